//! The masonry of an arch request: unit weight, interface limits and friction (of every joint,
//! and of the ring interfaces), validated into the solver's [`InterfaceLimits`].

use thrustline_solver::arch::InterfaceLimits;

use super::request::{InterfaceLimitsDto, MaterialFields};
use crate::error::ApiError;
use crate::limits::{FRICTION, LOWER_LIMIT, UNIT_WEIGHT, UPPER_LIMIT};
use crate::validation::within;

/// The material part of every arch request, validated.
#[derive(Debug, Clone, Copy)]
pub struct Material {
    /// Unit weight γ.
    pub unit_weight: f64,
    /// Limits on the interface resultants.
    pub limits: InterfaceLimits,
    /// Coulomb friction coefficient; `None` = no sliding.
    pub friction: Option<f64>,
}

/// Validates the unit weight, `interface_limits` (missing fields take Heyman's values, `null`
/// is unbounded) and `friction_coefficient` (null: no sliding).
pub fn material(fields: MaterialFields) -> Result<Material, ApiError> {
    let unit_weight = within("unit_weight", fields.unit_weight, UNIT_WEIGHT)?;
    Ok(Material {
        unit_weight,
        limits: limits("interface_limits", fields.interface_limits)?,
        friction: friction("friction_coefficient", fields.friction_coefficient)?,
    })
}

/// `ring_interface_limits` and `ring_friction_coefficient`, validated like their one-ring twins.
pub fn ring_material(fields: MaterialFields) -> Result<(InterfaceLimits, Option<f64>), ApiError> {
    Ok((
        limits("ring_interface_limits", fields.ring_interface_limits)?,
        friction(
            "ring_friction_coefficient",
            fields.ring_friction_coefficient,
        )?,
    ))
}

/// Interface limits: missing fields take Heyman's values, `null` is unbounded.
fn limits(name: &str, given: &InterfaceLimitsDto) -> Result<InterfaceLimits, ApiError> {
    let heyman = InterfaceLimits::heyman();
    let limit = |field: &str, given: Option<Option<f64>>, default: Option<f64>, lower: bool| {
        let field = format!("{name}.{field}");
        match given.unwrap_or(default) {
            None => Ok(None),
            Some(v) if lower => within(&field, v, LOWER_LIMIT).map(Some),
            Some(v) => within(&field, v, UPPER_LIMIT).map(Some),
        }
    };
    Ok(InterfaceLimits {
        q_min: limit("q_min", given.q_min, heyman.q_min, true)?,
        q_max: limit("q_max", given.q_max, heyman.q_max, false)?,
        s_min: limit("s_min", given.s_min, heyman.s_min, true)?,
        s_max: limit("s_max", given.s_max, heyman.s_max, false)?,
        t_min: limit("t_min", given.t_min, heyman.t_min, true)?,
        t_max: limit("t_max", given.t_max, heyman.t_max, false)?,
    })
}

/// A friction coefficient: null is no sliding.
fn friction(field: &str, mu: Option<f64>) -> Result<Option<f64>, ApiError> {
    mu.map(|mu| within(field, mu, FRICTION)).transpose()
}
