//! `design` on the live-load route (model §9.1): partial factors on the self weight, the fill's
//! weight, the live loads and the masonry's strength. The request is read in design values
//! once — self weight ·γ_d, fill ·γ_f, every live load (on blocks, on the road, rolled) ·γ_l,
//! σ_c/γ_m — and λ on that scene is the adequacy factor: the factor on the factored live load
//! at collapse, verified when at least 1.

use serde::Serialize;
use utoipa::ToSchema;

use super::request::design::ArchDesignDto;
use super::request::LiveLoadRequest;
use crate::error::ApiError;

/// The factors applied (all given).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, ToSchema)]
pub struct ArchFactors {
    /// γ_d.
    pub dead: f64,
    /// γ_f.
    pub fill: f64,
    /// γ_l.
    pub live: f64,
    /// γ_m.
    pub strength: f64,
}

/// The check's verdict.
#[derive(Debug, Clone, Copy, Serialize, ToSchema)]
pub struct ArchDesignOutDto {
    /// The factors applied.
    pub factors: ArchFactors,
    /// λ on the design values: the factor on the factored live load at collapse; null where
    /// there is none (the dead load in design values is not carried, or nothing collapses).
    pub adequacy_factor: Option<f64>,
    /// Whether the adequacy factor is at least 1.
    pub verified: bool,
}

/// The factors of a check, each finite and 0 < γ ≤ 100.
pub fn factors(dto: &ArchDesignDto) -> Result<ArchFactors, ApiError> {
    let f = dto.factors;
    let one = |name: &str, v: Option<f64>| {
        let v = v.unwrap_or(1.0);
        if v.is_finite() && v > 0.0 && v <= 100.0 {
            Ok(v)
        } else {
            Err(ApiError::invalid(
                format!("design.factors.{name}"),
                format!("{v} is out of range: allowed is a partial factor 0 < γ ≤ 100"),
            ))
        }
    };
    Ok(ArchFactors {
        dead: one("dead", f.dead)?,
        fill: one("fill", f.fill)?,
        live: one("live", f.live)?,
        strength: one("strength", f.strength)?,
    })
}

/// The request in design values (without its check).
pub fn in_design_values(request: &LiveLoadRequest, f: &ArchFactors) -> LiveLoadRequest {
    let mut r = request.clone();
    r.design = None;
    r.unit_weight *= f.dead;
    r.compressive_strength = r.compressive_strength.map(|s| s / f.strength);
    // The mortar's cohesion is a strength too.
    if let Some(ring) = r.ring_interface.as_mut() {
        ring.cohesion = ring.cohesion.map(|c| c / f.strength);
    }
    for interface in r.interfaces.iter_mut().flatten() {
        interface.cohesion = interface.cohesion.map(|c| c / f.strength);
    }
    if let Some(fill) = r.fill.as_mut() {
        fill.unit_weight *= f.fill;
        for layer in fill.layers.iter_mut().flatten() {
            layer.unit_weight *= f.fill;
        }
    }
    for load in &mut r.loads {
        load.fx *= f.live;
        load.fy *= f.live;
        load.moment *= f.live;
    }
    for load in &mut r.road_loads {
        load.fy *= f.live;
    }
    if let Some(rolling) = r.rolling.as_mut() {
        // A named vehicle is factored as its axles.
        if let Some(super::rolling::VehicleDto::Named(name)) = rolling.vehicle {
            rolling.vehicle = Some(super::rolling::VehicleDto::Axles(
                super::rolling::VehicleAxlesDto {
                    axles: name.axles(),
                },
            ));
        }
        let vehicle = match rolling.vehicle.as_mut() {
            Some(super::rolling::VehicleDto::Axles(v)) => v.axles.as_mut_slice(),
            _ => &mut [],
        };
        for axle in rolling.axles.iter_mut().flatten().chain(vehicle) {
            axle.fy *= f.live;
        }
    }
    r
}

/// The verdict on λ found in design values.
pub fn verdict(factors: ArchFactors, load_factor: Option<f64>) -> ArchDesignOutDto {
    ArchDesignOutDto {
        factors,
        adequacy_factor: load_factor,
        verified: load_factor.is_some_and(|l| l >= 1.0),
    }
}
