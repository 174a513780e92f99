//! `POST /arch/minimum-thickness`: the thinnest arch of a shape that carries its own weight
//! (model §3; Milankovitch 1904). A dead-load request with circular or profile geometry whose
//! `thickness` is optional (given, the answer adds the geometric factor of safety), plus an
//! optional `tolerance` relative to the radius (half the span of a profile).

use serde::{Deserialize, Serialize};
use thrustline_solver::arch::{
    rupture_angle_deg, solve_minimum_thickness_of, LimitSettings, Mechanism, MinimumThickness,
    MinimumThicknessOutcome, MinimumThicknessSettings, SolverFailure,
};
use utoipa::ToSchema;

use super::material::{material, ring_material, Material};
use super::mechanism::{active_constraints, hinges, ActiveConstraintDto, HingeDto};
use super::request::{arch_request, unit, InterfaceLimitsDto, MaterialFields};
use super::thinnest::{thinnest, Thinnest, ThinnestGeometryDto};
use crate::error::ApiError;
use crate::limits::THICKNESS_TOLERANCE;
use crate::pool::Cost;
use crate::state::AppState;
use crate::stop::Work;
use crate::validation::within;
use thrustline_solver::arch::memory::chain_memory_bound;

pub mod family;
pub mod routes;

arch_request! {
    /// The minimum-thickness question for a circular arch or a profile.
    #[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
    #[serde(deny_unknown_fields)]
    #[schema(examples(json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 1800},
        "unit_weight": 1.0,
        "tolerance": 1e-6
    })))]
    pub struct MinimumThicknessRequest {
        /// The arch, circular or a profile (one ring, one span); its `thickness`, if given, is
        /// the D of the geometric factor of safety.
        pub geometry: ThinnestGeometryDto,
        /// Accuracy of the thickness relative to the radius (half the span of a profile),
        /// 1e-9 ≤ tolerance ≤ 1e-2. Defaults to 1e-6.
        #[serde(default = "default_tolerance", deserialize_with = "crate::nullable::thickness_tolerance")]
        #[schema(nullable)]
        pub tolerance: f64,
    }
}

fn default_tolerance() -> f64 {
    1e-6
}

/// What the search found.
#[derive(Debug, Clone, Copy, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum MinimumThicknessOutcomeDto {
    /// The minimum thickness was found.
    Found,
    /// No finite minimum: even 1e-6·R stands (e.g. N ≤ 3).
    StandsHoweverThin,
    /// No thickness below 2R carries the weight (e.g. friction too low).
    NeverStands,
    /// A dead-load programme failed without an answer it can vouch for.
    SolverFailed,
}

/// The minimum thickness, or why there is none.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MinimumThicknessResponse {
    /// found; stands_however_thin (no finite minimum: even 1e-6·R stands, e.g. N ≤ 3);
    /// never_stands (no thickness below 2R carries the weight, e.g. friction too low);
    /// solver_failed.
    pub outcome: MinimumThicknessOutcomeDto,
    /// The thinnest thickness found to carry the dead load (within `tolerance`·R of the limit,
    /// on the safe side); null unless found.
    #[schema(examples(1.0747802))]
    #[schema(required = true)]
    pub thickness: Option<f64>,
    /// thickness / radius (circular arches).
    #[schema(examples(0.10747802))]
    #[schema(required = true)]
    pub thickness_to_radius: Option<f64>,
    /// thickness / span of the intrados (profiles).
    #[schema(required = true)]
    pub thickness_to_span: Option<f64>,
    /// The thickest thickness found not to carry it (the other end of the final bracket).
    #[schema(required = true)]
    pub thickness_below: Option<f64>,
    /// With `geometry.thickness` D given: Heyman's geometric factor of safety D / D_min (> 1:
    /// the given arch is that many times thicker than the thinnest that stands); null without
    /// a thickness or a minimum.
    #[schema(examples(1.5))]
    #[schema(required = true)]
    pub geometric_factor_of_safety: Option<f64>,
    /// Angle from the crown of the intrados hinge of the mechanism at the limit, in degrees
    /// (circular arches).
    #[schema(examples(54.5))]
    #[schema(required = true)]
    pub rupture_angle_deg: Option<f64>,
    /// Hinges of the mechanism at the limit.
    pub hinges: Vec<HingeDto>,
    /// Active limits of the mechanism at the limit.
    pub active_constraints: Vec<ActiveConstraintDto>,
    /// Dead-load programmes solved.
    pub evaluations: usize,
    /// Iterations over all of them (interior-point iterations; simplex pivots on a chain).
    pub iterations: u32,
    /// Wall time of the search in milliseconds.
    pub solve_time_ms: f64,
    /// The outcome in words.
    pub detail: String,
}

/// A validated minimum-thickness request: the arch whose shape is searched, its material, the
/// search's settings and the thickness given (for the geometric factor of safety).
pub struct Planned {
    /// The arch whose shape is searched.
    pub shape: Thinnest,
    /// Its material.
    pub material: Material,
    /// The search's settings.
    pub settings: MinimumThicknessSettings,
    /// The thickness given, for the geometric factor of safety.
    pub given: Option<f64>,
}

/// Validates the request once: one ring and one span, the material, the tolerance.
pub fn plan(request: &MinimumThicknessRequest) -> Result<Planned, ApiError> {
    let (shape, given) = thinnest(&request.geometry)?;
    let material = material(request.material())?;
    // One ring: the ring fields have nothing to act on, but a value out of range is still an
    // error, as on the other routes.
    ring_material(request.material())?;
    if request.ring_friction_coefficient.is_some() {
        return Err(ApiError::invalid(
            "ring_friction_coefficient",
            "is for arches of more than one ring, which the minimum-thickness search does not \
             take: leave it out",
        ));
    }
    let settings = MinimumThicknessSettings {
        tolerance: within("tolerance", request.tolerance, THICKNESS_TOLERANCE)?,
        ..MinimumThicknessSettings::default()
    };
    Ok(Planned {
        shape,
        material,
        settings,
        given,
    })
}

/// The search on the pool within the request's budget (every dead-load programme asks it); a
/// search stopped by it is the outcome rule's 422 naming `tolerance` (503 beside other solves).
pub async fn solve(
    state: &AppState,
    planned: Planned,
) -> Result<(Thinnest, MinimumThickness), ApiError> {
    let Planned {
        shape,
        material,
        settings,
        ..
    } = planned;
    // A search of dead-load programmes on the chain formulation.
    let cost = Cost {
        light: false,
        memory: chain_memory_bound(shape.voussoirs()),
    };
    let ran = state
        .pool
        .run_budgeted(state.solve_time_limit, cost, move |budget| {
            let settings = MinimumThicknessSettings {
                limit: LimitSettings {
                    budget: budget.clone(),
                    ..settings.limit.clone()
                },
                ..settings
            };
            let result = solve_minimum_thickness_of(
                &|d| shape.assembly(d),
                shape.scale(),
                material.unit_weight,
                material.limits,
                material.friction,
                &settings,
            );
            (shape, result)
        })
        .await?;
    let (shape, result) = ran.value;
    let result = result?;
    tracing::info!(
        evaluations = result.evaluations,
        solve_ms = ran.elapsed.as_secs_f64() * 1e3,
        "minimum thickness solved"
    );
    if let Err(stop) = result.outcome {
        let work = Work {
            field: "tolerance",
            advice: "use a larger tolerance or fewer voussoirs",
            no_candidate: "",
        };
        return Err(state.refuse(stop, work, ran.shared));
    }
    Ok((shape, result))
}

/// The answer, built whole for each outcome.
pub fn response(
    shape: &Thinnest,
    result: &MinimumThickness,
    given: Option<f64>,
) -> MinimumThicknessResponse {
    let scale = shape.scale();
    let (least, most) = match shape {
        Thinnest::Circle(_) => ("1e-6·R", "2·radius"),
        Thinnest::Profile { .. } => ("1e-6·span/2", "the span"),
    };
    let none = without_thickness(result);
    // A search the budget ended is refused before it is answered ([`solve`]).
    let Ok(outcome) = &result.outcome else {
        return MinimumThicknessResponse {
            detail: "the search was stopped before it ended; no thickness is reported".to_owned(),
            ..none
        };
    };
    match outcome {
        MinimumThicknessOutcome::Found {
            thickness,
            thickness_below,
            mechanism,
        } => found(
            shape,
            *thickness,
            *thickness_below,
            mechanism.as_ref(),
            given,
            none,
        ),
        MinimumThicknessOutcome::StandsHoweverThin => MinimumThicknessResponse {
            outcome: MinimumThicknessOutcomeDto::StandsHoweverThin,
            detail: format!(
                "no finite minimum: even thickness {} ({least}) carries the dead load ({})",
                1e-6 * scale,
                if shape.voussoirs() <= 3 {
                    "with three or fewer voussoirs no mechanism can form under symmetric dead load"
                } else {
                    "no mechanism of these voussoirs forms under their own weight: base angles \
                     or joints that leave no room for four hinges"
                }
            ),
            ..none
        },
        MinimumThicknessOutcome::NeverStands => MinimumThicknessResponse {
            outcome: MinimumThicknessOutcomeDto::NeverStands,
            detail: format!(
                "no thickness below {most} carries the dead load (with friction: the \
                 coefficient is too low for the joints at the springings)"
            ),
            ..none
        },
        MinimumThicknessOutcome::SolverFailed(failure) => MinimumThicknessResponse {
            detail: format!(
                "a dead-load programme failed ({}); no thickness is reported",
                match failure {
                    SolverFailure::ReducedAccuracy => "reduced accuracy",
                    SolverFailure::MaxIterations => "iteration limit",
                    SolverFailure::Numerical => "numerical error",
                    SolverFailure::Infeasible => "reported infeasible",
                }
            ),
            ..none
        },
    }
}

/// The answer when the minimum was found: `thickness` stands, `thickness_below` (the other end of
/// the final bracket) collapses with `mechanism`; `given`, the thickness of the request.
fn found(
    shape: &Thinnest,
    thickness: f64,
    thickness_below: f64,
    mechanism: Option<&Mechanism>,
    given: Option<f64>,
    none: MinimumThicknessResponse,
) -> MinimumThicknessResponse {
    MinimumThicknessResponse {
    outcome: MinimumThicknessOutcomeDto::Found,
    thickness: Some(thickness),
    thickness_to_radius: shape.circle(thickness).map(|a| thickness / a.radius()),
    thickness_to_span: shape.span().map(|span| thickness / span),
    thickness_below: Some(thickness_below),
    geometric_factor_of_safety: given.map(|d| d / thickness),
    rupture_angle_deg: match (mechanism, shape.circle(thickness_below)) {
        (Some(m), Some(arch)) => rupture_angle_deg(&arch, m),
        _ => None,
    },
    // The mechanism is the collapse of the arch just too thin.
    hinges: match (mechanism, shape.assembly(thickness_below)) {
        (Some(m), Ok(collapsing)) => hinges(&collapsing, m),
        _ => Vec::new(),
    },
    active_constraints: mechanism.map(active_constraints).unwrap_or_default(),
    detail: format!(
        "the arch carries its own weight from thickness {thickness} on; at {thickness_below} it collapses"
    ),
    ..none
}
}

/// The answer without a thickness: the search's cost, every result empty (each outcome fills in
/// what it has).
fn without_thickness(result: &MinimumThickness) -> MinimumThicknessResponse {
    MinimumThicknessResponse {
        outcome: MinimumThicknessOutcomeDto::SolverFailed,
        thickness: None,
        thickness_to_radius: None,
        thickness_to_span: None,
        thickness_below: None,
        geometric_factor_of_safety: None,
        rupture_angle_deg: None,
        hinges: Vec::new(),
        active_constraints: Vec::new(),
        evaluations: result.evaluations,
        iterations: result.iterations,
        solve_time_ms: result.solve_time_secs * 1e3,
        detail: String::new(),
    }
}
