//! Friction and cohesion where they differ from the arch's (model §10): the ring interfaces of
//! a multi-ring arch (`ring_interface`, their mortar's cohesion) and single interfaces named
//! by the blocks they join (`interfaces`: a wall's base, a ring's joint).

use thrustline_solver::arch::{ArchProblem, InterfaceKind};

use super::request::interfaces::{InterfaceDto, RingInterfaceDto};
use super::request::LimitFields;
use crate::error::ApiError;
use crate::limits::{FRICTION, INTERFACE_OVERRIDES, STRESS};
use crate::validation::{count, count_within, within};

/// The ring interfaces' friction from `ring_friction_coefficient` or `ring_interface`, and
/// the cohesion of `ring_interface`: (μ, c) when `ring_interface` is given.
pub fn ring_interface(
    given: Option<&RingInterfaceDto>,
    ring_friction_coefficient: Option<f64>,
) -> Result<Option<(Option<f64>, f64)>, ApiError> {
    let Some(ring) = given else {
        return Ok(None);
    };
    if ring_friction_coefficient.is_some() {
        return Err(ApiError::invalid(
            "ring_interface",
            "replaces ring_friction_coefficient: give the coefficient in ring_interface only",
        ));
    }
    let mu = ring
        .friction_coefficient
        .map(|mu| within("ring_interface.friction_coefficient", mu, FRICTION))
        .transpose()?;
    let cohesion = within(
        "ring_interface.cohesion",
        ring.cohesion.unwrap_or(0.0),
        STRESS,
    )?;
    if cohesion > 0.0 && mu.is_none() {
        return Err(ApiError::invalid(
            "ring_interface.cohesion",
            "needs ring_interface.friction_coefficient (0 for cohesion alone): without one the \
             rings cannot slip and cohesion has nothing to do",
        ));
    }
    Ok(Some((mu, cohesion)))
}

/// `problem` with each interface of `interfaces` given its own friction and cohesion.
pub fn with_interfaces(
    mut problem: ArchProblem,
    interfaces: &[InterfaceDto],
) -> Result<ArchProblem, ApiError> {
    count_within("interfaces", interfaces.len(), INTERFACE_OVERRIDES)?;
    let n = problem.assembly().blocks.len();
    for (i, given) in interfaces.iter().enumerate() {
        let field = |name: &str| format!("interfaces[{i}].{name}");
        // One block and another or a support (0), in either order.
        let [a, b] = given.blocks;
        count(&field("blocks"), a.max(b), 1, n)?;
        let (a, b) = (a.max(b) - 1, a.min(b).checked_sub(1));
        let mu = given
            .friction_coefficient
            .map(|mu| within(&field("friction_coefficient"), mu, FRICTION))
            .transpose()?;
        let cohesion = within(&field("cohesion"), given.cohesion.unwrap_or(0.0), STRESS)?;
        let joins = |lower: Option<usize>, upper: Option<usize>| {
            (lower == Some(a) && upper == b) || (upper == Some(a) && lower == b)
        };
        let found: Vec<usize> = problem
            .assembly()
            .interfaces
            .iter()
            .enumerate()
            .filter(|(_, face)| joins(face.lower, face.upper))
            .map(|(k, _)| k)
            .collect();
        if found.is_empty() {
            return Err(ApiError::invalid(
                field("blocks"),
                format!(
                    "blocks {} and {} do not touch: name two blocks that share an interface \
                     (0 for a support)",
                    given.blocks[0], given.blocks[1]
                ),
            ));
        }
        for k in found {
            let friction = mu.or(problem.friction_of(k));
            problem = problem.with_interface(k, friction, cohesion)?;
        }
    }
    Ok(problem)
}

/// The ring interfaces' limits, friction and cohesion (arches of more than one ring; refused
/// on one ring), then each interface of `interfaces` with its own friction and cohesion.
pub fn with_ring_and_own_interfaces(
    problem: ArchProblem,
    fields: &LimitFields,
) -> Result<ArchProblem, ApiError> {
    let has_rings = problem
        .assembly()
        .interfaces
        .iter()
        .any(|i| i.kind == InterfaceKind::Ring);
    // Checked whether or not there are rings: an out-of-range value is an error either way.
    let (ring_limits, mut ring_friction) = super::material::ring_material(fields.material)?;
    let ring_interface = ring_interface(
        fields.ring_interface,
        fields.material.ring_friction_coefficient,
    )?;
    if let Some((mu, _)) = ring_interface {
        ring_friction = mu;
    }
    let problem = if has_rings {
        let problem = problem.with_ring_interfaces(ring_limits, ring_friction)?;
        match ring_interface {
            Some((_, cohesion)) => problem.with_ring_cohesion(cohesion)?,
            None => problem,
        }
    } else if let Some(field) = [
        (
            "ring_friction_coefficient",
            fields.material.ring_friction_coefficient.is_some(),
        ),
        ("ring_interface", fields.ring_interface.is_some()),
    ]
    .iter()
    .find_map(|(f, given)| given.then_some(*f))
    {
        return Err(ApiError::invalid(
            field,
            "is for arches of more than one ring (geometry.rings > 1): leave it out",
        ));
    } else {
        problem
    };
    let problem = with_interfaces(problem, fields.interfaces)?;
    Ok(problem)
}
