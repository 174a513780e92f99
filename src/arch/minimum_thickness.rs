//! `POST /arch/minimum-thickness`: the thinnest circular arch that carries its own weight
//! (SPEC §3; Milankovitch 1904). A dead-load request with circular geometry whose `thickness`
//! is ignored, plus an optional `tolerance` relative to the radius.

use axum::extract::State;
use serde::{Deserialize, Serialize};
use thrustline_solver::arch::{
    rupture_angle_deg, solve_minimum_thickness, CircularArch, LimitSettings, MinimumThickness,
    MinimumThicknessOutcome, MinimumThicknessSettings, SolverFailure,
};
use utoipa::ToSchema;

use super::input::{circular_arch, material, CircularFields};
use super::request::{arch_request, unit, InterfaceLimitsDto, MaterialFields, VoussoirDto};
use super::response::{active_constraints, hinges, ActiveConstraintDto, HingeDto};
use crate::error::{ApiError, ApiJson, ProblemResponses};
use crate::limits::{MAX_LENGTH, MIN_LENGTH, THICKNESS_TOLERANCE};
use crate::validation::number;
use crate::AppState;

/// The only geometry kind with a minimum thickness.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum CircularKind {
    /// The circular arch generator.
    Circular,
}

/// A circular arch whose thickness is to be found (SPEC §1.3).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CircularGeometryDto {
    /// Always `circular`.
    pub kind: CircularKind,
    /// Middle radius R, 1e-9 ≤ R ≤ 1e9.
    #[schema(minimum = 1e-9, maximum = 1e9, examples(10.0))]
    pub radius: f64,
    /// Ignored (accepted so that a dead-load request can be sent as it is).
    #[serde(default)]
    pub thickness: Option<f64>,
    /// Number of voussoirs N, 1 ≤ N ≤ 10000.
    #[schema(minimum = 1, maximum = 10000, examples(1800))]
    #[serde(deserialize_with = "crate::nullable::integer")]
    pub voussoirs: usize,
    /// Left base angle B in degrees, −90 < B < 90. Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(exclusive_minimum = -90.0, maximum = 89.999999)]
    pub left_base_angle_deg: f64,
    /// Right base angle C in degrees, −90 < C < 90. Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(exclusive_minimum = -90.0, maximum = 89.999999)]
    pub right_base_angle_deg: f64,
    /// Voussoir shape. Defaults to `curved`.
    #[serde(default, deserialize_with = "crate::nullable::name_or_default")]
    #[schema(nullable)]
    pub voussoir: VoussoirDto,
}

arch_request! {
    /// The minimum-thickness question for a circular arch.
    #[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
    #[serde(deny_unknown_fields)]
    #[schema(examples(json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 1800},
        "unit_weight": 1.0,
        "tolerance": 1e-6
    })))]
    pub struct MinimumThicknessRequest {
        /// The circular arch; its `thickness`, if given, is ignored.
        pub geometry: CircularGeometryDto,
        /// Accuracy of the thickness relative to the radius, 1e-9 ≤ tolerance ≤ 1e-2. Defaults
        /// to 1e-6.
        #[serde(default = "default_tolerance", deserialize_with = "crate::nullable::thickness_tolerance")]
        #[schema(nullable)]
        #[schema(minimum = 1e-9, maximum = 0.01, default = 1e-6)]
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
    /// thickness / radius.
    #[schema(examples(0.10747802))]
    #[schema(required = true)]
    pub thickness_to_radius: Option<f64>,
    /// The thickest thickness found not to carry it (the other end of the final bracket).
    #[schema(required = true)]
    pub thickness_below: Option<f64>,
    /// Angle from the crown of the intrados hinge of the mechanism at the limit, in degrees.
    #[schema(examples(54.5))]
    #[schema(required = true)]
    pub rupture_angle_deg: Option<f64>,
    /// Hinges of the mechanism at the limit.
    pub hinges: Vec<HingeDto>,
    /// Active limits of the mechanism at the limit.
    pub active_constraints: Vec<ActiveConstraintDto>,
    /// Dead-load programmes solved.
    pub evaluations: usize,
    /// Interior-point iterations over all of them.
    pub iterations: u32,
    /// Wall time of the search in milliseconds.
    pub solve_time_ms: f64,
    /// The outcome in words.
    pub detail: String,
}

/// Minimum thickness of a circular arch under its own weight.
///
/// The thinnest arch of the given shape, voussoirs and joint limits that carries its own weight
/// (Milankovitch 1904; SPEC §1.4): Brent's method on the dead-load margin, to `tolerance`·R.
/// The `thickness` of the geometry is ignored. A solve stopped at the time limit is 422 naming
/// `tolerance`.
#[utoipa::path(
    post,
    path = "/arch/minimum-thickness",
    tag = "arch",
    request_body(content = MinimumThicknessRequest, examples(
        ("milankovitch" = (summary = "Milankovitch's semicircle of 1800 voussoirs: d/R = 0.10748 (SPEC §1.4)",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "voussoirs": 1800}})))
    )),
    responses(
        (status = 200, description = "The minimum thickness, or the reason there is none", body = MinimumThicknessResponse),
        ProblemResponses,
    )
)]
pub async fn minimum_thickness(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<MinimumThicknessRequest>,
) -> Result<ApiJson<MinimumThicknessResponse>, ApiError> {
    let g = &request.geometry;
    // The thickness is ignored: any valid one serves as the template.
    let radius = number("geometry.radius", g.radius, MIN_LENGTH, false, MAX_LENGTH)?;
    let arch = circular_arch(CircularFields {
        radius,
        thickness: 0.1 * radius,
        voussoirs: g.voussoirs,
        left_base_angle_deg: g.left_base_angle_deg,
        right_base_angle_deg: g.right_base_angle_deg,
        voussoir: g.voussoir,
    })?;
    let material = material(request.material())?;
    if request.ring_friction_coefficient.is_some() {
        return Err(ApiError::invalid(
            "ring_friction_coefficient",
            "is for arches of more than one ring, which the minimum-thickness search does not \
             take: leave it out",
        ));
    }
    let (min, max) = THICKNESS_TOLERANCE;
    let settings = MinimumThicknessSettings {
        tolerance: number("tolerance", request.tolerance, min, false, max)?,
        limit: LimitSettings {
            time_limit_secs: state.solve_time_limit_secs(),
            ..LimitSettings::default()
        },
        time_limit: Some(state.solve_time_limit),
        ..MinimumThicknessSettings::default()
    };
    let (result, elapsed) = state
        .pool
        .run(move || {
            let result = solve_minimum_thickness(
                &arch,
                material.unit_weight,
                material.limits,
                material.friction,
                &settings,
            );
            (arch, result)
        })
        .await?;
    let (arch, result) = result;
    let result = result?;
    tracing::info!(
        evaluations = result.evaluations,
        solve_ms = elapsed.as_secs_f64() * 1e3,
        "minimum thickness solved"
    );
    if result.outcome == MinimumThicknessOutcome::SolverFailed(SolverFailure::MaxTime) {
        return Err(ApiError::OverTimeLimit {
            field: "tolerance".to_owned(),
            seconds: state.solve_time_limit_secs(),
            advice: "use a larger tolerance or fewer voussoirs",
        });
    }
    Ok(ApiJson(response(&arch, &result)))
}

/// The answer, built whole for each outcome.
fn response(arch: &CircularArch, result: &MinimumThickness) -> MinimumThicknessResponse {
    let radius = arch.radius();
    let none = MinimumThicknessResponse {
        outcome: MinimumThicknessOutcomeDto::SolverFailed,
        thickness: None,
        thickness_to_radius: None,
        thickness_below: None,
        rupture_angle_deg: None,
        hinges: Vec::new(),
        active_constraints: Vec::new(),
        evaluations: result.evaluations,
        iterations: result.iterations,
        solve_time_ms: result.solve_time_secs * 1e3,
        detail: String::new(),
    };
    match &result.outcome {
        MinimumThicknessOutcome::Found {
            thickness,
            thickness_below,
            mechanism,
        } => MinimumThicknessResponse {
            outcome: MinimumThicknessOutcomeDto::Found,
            thickness: Some(*thickness),
            thickness_to_radius: Some(thickness / radius),
            thickness_below: Some(*thickness_below),
            rupture_angle_deg: mechanism.as_ref().and_then(|m| rupture_angle_deg(arch, m)),
            // The mechanism is the collapse of the arch just too thin.
            hinges: match (mechanism, arch.with_thickness(*thickness_below)) {
                (Some(m), Ok(collapsing)) => hinges(&collapsing.assembly(), m),
                _ => Vec::new(),
            },
            active_constraints: mechanism
                .as_ref()
                .map(active_constraints)
                .unwrap_or_default(),
            detail: format!(
                "the arch carries its own weight from thickness {thickness} on; at {thickness_below} it collapses"
            ),
            ..none
        },
        MinimumThicknessOutcome::StandsHoweverThin => MinimumThicknessResponse {
            outcome: MinimumThicknessOutcomeDto::StandsHoweverThin,
            detail: format!(
                "no finite minimum: even thickness {} (1e-6·R) carries the dead load \
                 (with three or fewer voussoirs no mechanism can form under symmetric dead load)",
                1e-6 * radius
            ),
            ..none
        },
        MinimumThicknessOutcome::NeverStands => MinimumThicknessResponse {
            outcome: MinimumThicknessOutcomeDto::NeverStands,
            detail: "no thickness below 2·radius carries the dead load (with friction: the \
                     coefficient is too low for the joints at the springings)"
                .to_owned(),
            ..none
        },
        MinimumThicknessOutcome::SolverFailed(failure) => MinimumThicknessResponse {
            detail: format!(
                "a dead-load programme failed ({}); no thickness is reported",
                match failure {
                    SolverFailure::ReducedAccuracy => "reduced accuracy",
                    SolverFailure::MaxIterations => "iteration limit",
                    SolverFailure::MaxTime => "the solve time limit was reached",
                    SolverFailure::Numerical => "numerical error",
                    SolverFailure::Infeasible => "reported infeasible",
                }
            ),
            ..none
        },
    }
}
