//! `soil.strength` (model §8): the strength models clients state, read into the solver's
//! [`Strength`]. Nonlinear envelopes are solved to their consistent state by the solver.

use thrustline_solver::slope::strength::{Envelope, HoekBrown, Reference, Strength, Undrained};
use thrustline_solver::slope::Soil;

use super::request::soil::{DepthReferenceDto, StrengthDto};
use super::request::SoilDto;
use crate::error::ApiError;
use crate::limits::{
    COORDINATE, DISTURBANCE, ENVELOPE_POINTS, FRICTION_ANGLE_DEG, GSI, HOEK_BROWN_MI,
    POSITIVE_STRESS, POWER_EXPONENT, SIGNED_STRESS, STRESS, UNIT_WEIGHT,
};
use crate::svg::shown;
use crate::validation::{count_within, within};

/// A Mohr–Coulomb soil at `prefix` (`soil`: the simple slope, which takes no strength model);
/// r_u is the caller's.
pub fn soil(prefix: &str, dto: &SoilDto, ratio: f64) -> Result<Soil, ApiError> {
    if dto.r_envelope.is_some() {
        return Err(ApiError::invalid(
            format!("{prefix}.r_envelope"),
            "is for a section's layers with section.drawdown: give the slope as a section",
        ));
    }
    if dto.strength.is_some() {
        return Err(ApiError::invalid(
            format!("{prefix}.strength"),
            "is for a section's layers: give the slope as a section (its ground and one layer) \
             to use a strength model",
        ));
    }
    mohr_coulomb(prefix, dto, ratio)
}

/// A layer's soil at `prefix` (`section.layers[i].soil`) and its strength model: `cohesion`
/// and `friction_angle_deg`, or `strength` (then neither of them).
pub fn layer_soil(prefix: &str, dto: &SoilDto) -> Result<(Soil, Strength), ApiError> {
    let Some(model) = &dto.strength else {
        return Ok((mohr_coulomb(prefix, dto, 0.0)?, Strength::MohrCoulomb));
    };
    for (name, given) in [
        ("cohesion", dto.cohesion.is_some()),
        ("friction_angle_deg", dto.friction_angle_deg.is_some()),
    ] {
        if given {
            return Err(ApiError::invalid(
                format!("{prefix}.{name}"),
                "is not used with strength: state the strength in the model alone",
            ));
        }
    }
    let weight = within(
        &format!("{prefix}.unit_weight"),
        dto.unit_weight,
        UNIT_WEIGHT,
    )?;
    Ok((
        Soil::weight_only(weight)?,
        strength(&format!("{prefix}.strength"), model)?,
    ))
}

/// c′ and φ′ at `prefix`, both required.
fn mohr_coulomb(prefix: &str, dto: &SoilDto, ratio: f64) -> Result<Soil, ApiError> {
    let field = |name: &str| format!("{prefix}.{name}");
    within(&field("unit_weight"), dto.unit_weight, UNIT_WEIGHT)?;
    let required = |name: &str, value: Option<f64>| {
        value.ok_or_else(|| {
            ApiError::invalid(
                field(name),
                "is required (or give strength, a strength model, in a section's layer)",
            )
        })
    };
    let cohesion = within(
        &field("cohesion"),
        required("cohesion", dto.cohesion)?,
        STRESS,
    )?;
    let friction = within(
        &field("friction_angle_deg"),
        required("friction_angle_deg", dto.friction_angle_deg)?,
        FRICTION_ANGLE_DEG,
    )?;
    // A soil without strength is Soil::new's check; its errors name `soil.*`, re-rooted here
    // at the prefix.
    Soil::new(dto.unit_weight, cohesion, friction, ratio).map_err(|e| match ApiError::from(e) {
        ApiError::Invalid { field, detail } => ApiError::Invalid {
            field: field.replacen("soil", prefix, 1),
            detail,
        },
        other => other,
    })
}

/// The model at `prefix` (`section.layers[i].soil.strength`) as the solver takes it.
pub fn strength(prefix: &str, dto: &StrengthDto) -> Result<Strength, ApiError> {
    let field = |name: &str| format!("{prefix}.{name}");
    Ok(match dto {
        StrengthDto::Undrained { .. } => Strength::Undrained(undrained(prefix, dto)?),
        StrengthDto::PowerCurve { a, b, c, d } => {
            let a = within(&field("a"), *a, STRESS)?;
            let b = within(&field("b"), *b, POWER_EXPONENT)?;
            let c = within(&field("c"), c.unwrap_or(0.0), STRESS)?;
            let d = within(&field("d"), d.unwrap_or(0.0), SIGNED_STRESS)?;
            if a == 0.0 && c == 0.0 {
                return Err(ApiError::invalid(
                    field("a"),
                    "0 is out of range: allowed is a > 0 when c is 0 (a soil without strength)",
                ));
            }
            Strength::Envelope(Envelope::PowerCurve { a, b, c, d })
        }
        StrengthDto::HoekBrown {
            sigma_ci,
            gsi,
            mi,
            disturbance,
        } => Strength::Envelope(Envelope::HoekBrown(HoekBrown::new(
            within(&field("sigma_ci"), *sigma_ci, POSITIVE_STRESS)?,
            within(&field("gsi"), *gsi, GSI)?,
            within(&field("mi"), *mi, HOEK_BROWN_MI)?,
            within(
                &field("disturbance"),
                disturbance.unwrap_or(0.0),
                DISTURBANCE,
            )?,
        ))),
        StrengthDto::ShearNormal { points: given } => {
            count_within(&field("points"), given.len(), ENVELOPE_POINTS)?;
            let mut points: Vec<(f64, f64)> = Vec::with_capacity(given.len());
            for (i, p) in given.iter().enumerate() {
                let at = format!("{prefix}.points[{i}]");
                let sigma = within(&at, p[0], SIGNED_STRESS)?;
                let tau = within(&at, p[1], STRESS)?;
                if points.last().is_some_and(|q| sigma <= q.0) {
                    return Err(ApiError::invalid(
                        at,
                        "σ′ₙ must increase strictly from point to point",
                    ));
                }
                points.push((sigma, tau));
            }
            if points.iter().all(|p| p.1 == 0.0) {
                return Err(ApiError::invalid(
                    field("points"),
                    "every τ is 0: a soil without strength",
                ));
            }
            Strength::Envelope(Envelope::ShearNormal(points))
        }
    })
}

/// An undrained profile: a datum or the ground, a cap not below s_u0, some strength.
fn undrained(prefix: &str, dto: &StrengthDto) -> Result<Undrained, ApiError> {
    let StrengthDto::Undrained {
        cohesion,
        gradient,
        datum,
        reference,
        cohesion_max,
    } = dto
    else {
        return Err(ApiError::invalid(prefix, "is not an undrained profile"));
    };
    let field = |name: &str| format!("{prefix}.{name}");
    let cohesion = within(&field("cohesion"), *cohesion, STRESS)?;
    let gradient = within(&field("gradient"), gradient.unwrap_or(0.0), STRESS)?;
    let reference = match (*datum, *reference) {
        (Some(_), Some(_)) => {
            return Err(ApiError::invalid(
                field("reference"),
                "give either datum (a level) or reference: ground, not both",
            ))
        }
        (Some(datum), None) => Reference::Datum(within(&field("datum"), datum, COORDINATE)?),
        (None, Some(DepthReferenceDto::Ground)) => Reference::Ground,
        (None, None) if gradient == 0.0 => Reference::Ground,
        (None, None) => {
            return Err(ApiError::invalid(
                field("datum"),
                "is required with a gradient: the level depth is measured from (or give \
                 reference: ground)",
            ))
        }
    };
    let cohesion_max = cohesion_max
        .map(|m| within(&field("cohesion_max"), m, STRESS))
        .transpose()?;
    if let Some(max) = cohesion_max {
        if max < cohesion {
            return Err(ApiError::invalid(
                field("cohesion_max"),
                format!("{max} is out of range: allowed is cohesion_max ≥ cohesion ({cohesion})"),
            ));
        }
    }
    if cohesion == 0.0 && (gradient == 0.0 || cohesion_max == Some(0.0)) {
        return Err(ApiError::invalid(
            field("cohesion"),
            "0 is out of range: allowed is > 0 when the gradient is 0 (a soil without strength)",
        ));
    }
    Ok(Undrained {
        cohesion,
        gradient,
        reference,
        cohesion_max,
    })
}

/// A layer's strength as a drawing's key names it.
pub fn describe(layer: &thrustline_solver::slope::section::Layer) -> String {
    match &layer.strength {
        Strength::MohrCoulomb => format!(
            "c′ = {}, φ′ = {}°",
            shown(layer.soil.cohesion()),
            shown(layer.soil.friction_angle_deg())
        ),
        Strength::Undrained(u) => {
            let from = match u.reference {
                Reference::Datum(y) => format!("below y = {}", shown(y)),
                Reference::Ground => "below the ground".to_owned(),
            };
            let cap = u
                .cohesion_max
                .map_or(String::new(), |c| format!(", at most {}", shown(c)));
            format!(
                "undrained s_u = {} + {}·depth {from}{cap}",
                shown(u.cohesion),
                shown(u.gradient)
            )
        }
        Strength::Envelope(e) => envelope(e),
    }
}

/// A nonlinear envelope in words.
fn envelope(e: &Envelope) -> String {
    match e {
        Envelope::PowerCurve { a, b, c, d } => format!(
            "τ = {}·(σ′ + {})^{} + {}",
            shown(*a),
            shown(*d),
            shown(*b),
            shown(*c)
        ),
        Envelope::HoekBrown(h) => format!(
            "Hoek–Brown σ_ci = {}, m_b = {:.4}, s = {:.3e}, a = {:.4}",
            h.sigma_ci, h.mb, h.s, h.a
        ),
        Envelope::ShearNormal(points) => {
            format!("shear–normal function of {} points", points.len())
        }
        Envelope::Divided(inner, factor) => {
            format!("{} (÷ {})", envelope(inner), shown(*factor))
        }
    }
}
