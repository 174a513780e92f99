//! `POST /slope/spencer`: Spencer's method for one slip circle (SPEC §2, §3).
//!
//! Translates the JSON request into the solver's types (validating every number once), runs the
//! solve on the blocking pool, and translates the solution back. Slices are numbered from 1 at
//! the lower end of the slip surface, as the thesis prints them.

use std::num::NonZeroUsize;

use axum::extract::State;
use serde::{Deserialize, Serialize};
use thrustline_solver::slope::{
    solve_spencer, Embankment, ExternalLoad, Seismic, SlipCircle, SlopeError, SlopeProblem, Soil,
    SpencerSettings, SpencerSolution, SpencerStatus,
};
use utoipa::ToSchema;

use crate::error::{ApiError, ApiJson, Problem};
use crate::validation::{count, finite, number};
use crate::AppState;

/// Largest number of slices a request may ask for.
pub const MAX_SLICES: usize = 10_000;
/// Largest number of external loads in one request.
pub const MAX_EXTERNAL_LOADS: usize = 10_000;

/// The embankment: toe at the origin, slope face up to (length, height), level crest beyond.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SlopeDto {
    /// Slope height H (> 0).
    #[schema(exclusive_minimum = 0.0, example = 30.48)]
    pub height: f64,
    /// Horizontal length L of the slope face (> 0); the slope is H:L.
    #[schema(exclusive_minimum = 0.0, example = 60.96)]
    pub length: f64,
}

/// A trial slip circle, its centre measured from the lower end of the slip surface.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CircleDto {
    /// Horizontal distance X from the lower end to the centre (towards the crest positive).
    #[schema(example = 9.63168)]
    pub x: f64,
    /// Height Y of the centre above the lower end (> 0).
    #[schema(exclusive_minimum = 0.0, example = 63.76416)]
    pub y: f64,
    /// Lower-end position factor F_e ≥ 0: the lower end lies F_e·H in front of the toe.
    #[serde(default)]
    #[schema(minimum = 0.0, example = 0.0)]
    pub lower_end_factor: f64,
}

/// Soil properties, the same in every slice.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SoilDto {
    /// Unit weight γ (> 0).
    #[schema(exclusive_minimum = 0.0, example = 10.0)]
    pub unit_weight: f64,
    /// Effective cohesion c' (≥ 0; > 0 when the friction angle is 0).
    #[schema(minimum = 0.0, example = 6.096)]
    pub cohesion: f64,
    /// Effective friction angle φ' in degrees, 0 ≤ φ' ≤ 89.9.
    #[schema(minimum = 0.0, maximum = 89.9, example = 40.0)]
    pub friction_angle_deg: f64,
    /// Pore pressure ratio r_u = u/(γh), 0 ≤ r_u ≤ 1.
    #[serde(default)]
    #[schema(minimum = 0.0, maximum = 1.0, example = 0.5)]
    pub pore_pressure_ratio: f64,
}

/// Pseudo-static seismic coefficients, applied at the slice centroids.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SeismicDto {
    /// Horizontal coefficient: k_h·W acts towards the toe. −10 ≤ k_h ≤ 10.
    #[serde(default)]
    #[schema(minimum = -10.0, maximum = 10.0, example = 0.1)]
    pub kh: f64,
    /// Vertical coefficient: k_v·W acts downwards. −0.99 ≤ k_v ≤ 10.
    #[serde(default)]
    #[schema(minimum = -0.99, maximum = 10.0, example = 0.0)]
    pub kv: f64,
}

/// A known load on one slice, applied at the middle of its base (the thesis' F_x, F_y, M1).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ExternalLoadDto {
    /// Slice number, 1 at the lower end of the slip surface.
    #[schema(minimum = 1, maximum = 10000, example = 3)]
    pub slice: usize,
    /// Horizontal force, positive towards the crest (+x).
    #[serde(default)]
    pub fx: f64,
    /// Vertical force, positive upwards.
    #[serde(default)]
    pub fy: f64,
    /// Moment about the middle of the slice base, counter-clockwise positive.
    #[serde(default)]
    pub moment: f64,
}

/// A Spencer analysis of one slip circle.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(example = json!({
    "slope": {"height": 30.48, "length": 60.96},
    "circle": {"x": 9.63168, "y": 63.76416, "lower_end_factor": 0.0},
    "slices": 100,
    "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0, "pore_pressure_ratio": 0.5}
}))]
pub struct SpencerRequest {
    /// The embankment.
    pub slope: SlopeDto,
    /// The slip circle.
    pub circle: CircleDto,
    /// Number of vertical slices of equal width, 1 ≤ N ≤ 10000. Defaults to 100.
    #[serde(default = "default_slices")]
    #[schema(minimum = 1, maximum = 10000, default = 100, example = 100)]
    pub slices: usize,
    /// The soil.
    pub soil: SoilDto,
    /// Optional pseudo-static seismic load.
    #[serde(default)]
    pub seismic: Option<SeismicDto>,
    /// Optional known loads on slices.
    #[serde(default)]
    #[schema(max_items = 10000)]
    pub external_loads: Vec<ExternalLoadDto>,
}

fn default_slices() -> usize {
    100
}

/// A point in the plane of the section.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PointDto {
    /// Horizontal coordinate (toe at 0, towards the crest positive).
    pub x: f64,
    /// Vertical coordinate (toe at 0, up positive).
    pub y: f64,
}

/// Geometry and forces of one slice at the solution.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SliceDto {
    /// Slice number, 1 at the lower end.
    pub slice: usize,
    /// x of the toe-side vertical.
    pub x_left: f64,
    /// x of the crest-side vertical.
    pub x_right: f64,
    /// Inclination α of the base chord in degrees, positive where it rises towards the crest.
    pub base_inclination_deg: f64,
    /// Length of the base chord.
    pub base_length: f64,
    /// Height of the slice at its middle.
    pub height: f64,
    /// Weight W.
    pub weight: f64,
    /// Pore pressure u = r_u·γ·h at the base.
    pub pore_pressure: f64,
    /// Total normal force on the base.
    pub normal_force: f64,
    /// Effective normal force on the base (total minus u·l).
    pub effective_normal_force: f64,
    /// Mobilised shear force on the base.
    pub shear_force: f64,
    /// Resultant Q of the two inter-slice forces, positive along (cos θ, sin θ).
    pub interslice_resultant: f64,
    /// Inter-slice force on the crest-side boundary (compression positive; 0 at the exit).
    pub interslice_force: f64,
    /// The denominator m_α = cos(α−θ) + sin(α−θ)·tan φ'/F.
    pub m_alpha: f64,
}

/// A point of the line of thrust on an inter-slice boundary (Spencer 1973).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ThrustPointDto {
    /// Boundary number: boundary i lies between slices i and i+1.
    pub boundary: usize,
    /// x of the boundary.
    pub x: f64,
    /// Height of the point of action; null where the inter-slice force vanishes.
    pub y: Option<f64>,
    /// Inter-slice force (compression positive).
    pub force: f64,
    /// Whether the point lies between the slip surface and the ground surface.
    pub inside_slice: bool,
}

/// The slip circle as placed on the embankment.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CircleOutDto {
    /// Centre X measured from the lower end (as given).
    pub x: f64,
    /// Centre Y measured from the lower end (as given).
    pub y: f64,
    /// Radius.
    pub radius: f64,
    /// The centre in embankment coordinates (toe at the origin).
    pub centre: PointDto,
    /// Lower end of the slip surface.
    pub lower_end: PointDto,
    /// Upper exit of the slip surface on the ground.
    pub upper_exit: PointDto,
}

/// How the solution of Spencer's equations ended.
#[derive(Debug, Clone, Copy, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum SpencerStatusDto {
    /// Both equations are satisfied with every m_α positive.
    Converged,
    /// No (F, θ) with positive denominators satisfies both equations (F in 1e-6…1e6,
    /// |θ| < 89°); no factor of safety is reported.
    NoSolution,
}

/// Spencer's factor of safety, the inter-slice inclination and everything behind them.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SpencerResponse {
    /// Whether both equilibrium equations were solved.
    pub converged: bool,
    /// How the solution ended.
    pub status: SpencerStatusDto,
    /// Spencer's factor of safety F; null when not converged.
    #[schema(example = 1.06958)]
    pub factor_of_safety: Option<f64>,
    /// Inclination θ of the parallel inter-slice forces in degrees; null when not converged.
    #[schema(example = 22.432)]
    pub theta_deg: Option<f64>,
    /// Bishop's simplified factor of safety (θ = 0, moment equation); null when it has no root.
    #[schema(example = 1.0397)]
    pub bishop_factor_of_safety: Option<f64>,
    /// Radius of the slip circle.
    #[schema(example = 64.4875)]
    pub radius: f64,
    /// The slip circle on the embankment.
    pub circle: CircleOutDto,
    /// Number of slices used.
    pub slice_count: usize,
    /// Per-slice geometry and forces (empty when not converged).
    pub slices: Vec<SliceDto>,
    /// Line of thrust on the interior slice boundaries (empty when not converged).
    pub thrust_line: Vec<ThrustPointDto>,
    /// Newton iterations (plus fallback evaluations).
    pub iterations: usize,
    /// Largest scaled residual of the two equations (force/ΣW, moment/(ΣW·R)).
    pub residual: Option<f64>,
    /// Things the engineer should look at: small m_α, tension at the base, a thrust line
    /// outside the mass, no solution.
    pub warnings: Vec<String>,
    /// Wall time of the solve in milliseconds.
    pub solve_time_ms: f64,
}

/// Spencer's method for one slip circle.
#[utoipa::path(
    post,
    path = "/slope/spencer",
    tag = "slope",
    request_body = SpencerRequest,
    responses(
        (status = 200, description = "Solved, or an honest `converged: false`", body = SpencerResponse),
        (status = 400, description = "Body is not JSON", body = Problem, content_type = "application/problem+json"),
        (status = 413, description = "Body too large", body = Problem, content_type = "application/problem+json"),
        (status = 415, description = "Content type is not application/json", body = Problem, content_type = "application/problem+json"),
        (status = 422, description = "A field is missing, unknown or out of range, or the circle cuts no slip mass", body = Problem, content_type = "application/problem+json"),
        (status = 503, description = "At capacity or out of time; retry later", body = Problem, content_type = "application/problem+json"),
    )
)]
pub async fn spencer(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<SpencerRequest>,
) -> Result<ApiJson<SpencerResponse>, ApiError> {
    let problem = problem_from(&request)?;
    let (solution, elapsed) = state
        .pool
        .run(move || {
            let solution = solve_spencer(&problem, &SpencerSettings::default());
            (problem, solution)
        })
        .await?;
    let (problem, solution) = solution;
    tracing::info!(
        slices = problem.geometry.slices.len(),
        iterations = solution.iterations,
        solve_ms = elapsed.as_secs_f64() * 1e3,
        factor_of_safety = solution.factor_of_safety,
        "spencer solved"
    );
    Ok(ApiJson(response_from(
        &problem,
        &solution,
        elapsed.as_secs_f64() * 1e3,
    )))
}

/// Validates the request and builds the solver's problem.
fn problem_from(request: &SpencerRequest) -> Result<SlopeProblem, ApiError> {
    let height = number("slope.height", request.slope.height, 0.0, true, f64::MAX)?;
    let length = number("slope.length", request.slope.length, 0.0, true, f64::MAX)?;
    let slices = count("slices", request.slices, 1, MAX_SLICES)?;
    let circle = &request.circle;
    let circle = SlipCircle {
        x: finite("circle.x", circle.x)?,
        y: number("circle.y", circle.y, 0.0, true, f64::MAX)?,
        lower_end_factor: number(
            "circle.lower_end_factor",
            circle.lower_end_factor,
            0.0,
            false,
            f64::MAX,
        )?,
    };
    let soil = &request.soil;
    number("soil.unit_weight", soil.unit_weight, 0.0, true, f64::MAX)?;
    number("soil.cohesion", soil.cohesion, 0.0, false, f64::MAX)?;
    number(
        "soil.friction_angle_deg",
        soil.friction_angle_deg,
        0.0,
        false,
        89.9,
    )?;
    number(
        "soil.pore_pressure_ratio",
        soil.pore_pressure_ratio,
        0.0,
        false,
        1.0,
    )?;
    let soil = Soil::new(
        soil.unit_weight,
        soil.cohesion,
        soil.friction_angle_deg,
        soil.pore_pressure_ratio,
    )
    .map_err(slope_error)?;
    let seismic = match &request.seismic {
        Some(s) => Seismic {
            kh: number("seismic.kh", s.kh, -10.0, false, 10.0)?,
            kv: number("seismic.kv", s.kv, -0.99, false, 10.0)?,
        },
        None => Seismic::default(),
    };
    count(
        "external_loads",
        request.external_loads.len(),
        0,
        MAX_EXTERNAL_LOADS,
    )?;
    let external_loads = request
        .external_loads
        .iter()
        .enumerate()
        .map(|(i, load)| {
            let field = |name: &str| format!("external_loads[{i}].{name}");
            count(&field("slice"), load.slice, 1, slices)?;
            Ok(ExternalLoad {
                slice: load.slice - 1,
                fx: finite(&field("fx"), load.fx)?,
                fy: finite(&field("fy"), load.fy)?,
                moment: finite(&field("moment"), load.moment)?,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    let embankment = Embankment::new(height, length).map_err(slope_error)?;
    let slices = NonZeroUsize::new(slices)
        .ok_or_else(|| ApiError::invalid("slices", "must be at least 1"))?;
    SlopeProblem::new(embankment, circle, slices, soil, seismic, external_loads)
        .map_err(slope_error)
}

/// The solver's refusals are the client's to fix: 422 naming the parameter.
fn slope_error(error: SlopeError) -> ApiError {
    match error {
        SlopeError::OutOfRange {
            parameter,
            value,
            allowed,
        } => ApiError::invalid(
            parameter,
            format!("{value} is out of range: allowed is {allowed}"),
        ),
        SlopeError::NoSlipMass { parameter, reason } => ApiError::invalid(
            parameter,
            format!("the circle cuts no slip mass from the slope: {reason}"),
        ),
    }
}

fn finite_or_none(value: f64) -> Option<f64> {
    value.is_finite().then_some(value)
}

fn response_from(
    problem: &SlopeProblem,
    solution: &SpencerSolution,
    solve_time_ms: f64,
) -> SpencerResponse {
    let g = &problem.geometry;
    let converged = match solution.status {
        SpencerStatus::Converged => true,
        SpencerStatus::NoSolution => false,
    };
    let status = match solution.status {
        SpencerStatus::Converged => SpencerStatusDto::Converged,
        SpencerStatus::NoSolution => SpencerStatusDto::NoSolution,
    };
    let mut warnings = Vec::new();
    if !converged {
        warnings.push(
            "no (F, θ) with positive m_α satisfies both equilibrium equations for this circle; \
             no factor of safety is reported"
                .to_owned(),
        );
    }
    let one_based = |list: &[usize]| {
        list.iter()
            .map(|i| (i + 1).to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    if !solution.small_m_alpha_slices.is_empty() {
        warnings.push(format!(
            "m_alpha < {} at slices {}: base forces there are sensitive to F",
            thrustline_solver::slope::spencer::SMALL_DENOMINATOR,
            one_based(&solution.small_m_alpha_slices)
        ));
    }
    if !solution.negative_effective_normal_slices.is_empty() {
        warnings.push(format!(
            "negative effective normal force (tension) at slices {}",
            one_based(&solution.negative_effective_normal_slices)
        ));
    }
    let outside: Vec<usize> = solution
        .thrust_line
        .iter()
        .filter(|t| !t.is_inside_slice)
        .map(|t| t.boundary)
        .collect();
    if !outside.is_empty() {
        warnings.push(format!(
            "the line of thrust leaves the sliding mass at boundaries {}",
            outside
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    let slices = if converged {
        g.slices
            .iter()
            .zip(&solution.slice_forces)
            .enumerate()
            .map(|(i, (s, f))| SliceDto {
                slice: i + 1,
                x_left: s.x_left,
                x_right: s.x_right,
                base_inclination_deg: s.base_inclination_rad.to_degrees(),
                base_length: s.base_length,
                height: s.height_middle,
                weight: f.weight,
                pore_pressure: f.pore_pressure,
                normal_force: f.normal_force,
                effective_normal_force: f.effective_normal_force,
                shear_force: f.shear_force,
                interslice_resultant: f.interslice_resultant,
                interslice_force: f.interslice_force_right,
                m_alpha: f.m_alpha,
            })
            .collect()
    } else {
        Vec::new()
    };
    let point = |(x, y): (f64, f64)| PointDto { x, y };
    SpencerResponse {
        converged,
        status,
        factor_of_safety: solution.factor_of_safety,
        theta_deg: solution.theta_rad.map(f64::to_degrees),
        bishop_factor_of_safety: solution.bishop_factor_of_safety,
        radius: g.radius,
        circle: CircleOutDto {
            x: g.centre.0 - g.lower_end.0,
            y: g.centre.1 - g.lower_end.1,
            radius: g.radius,
            centre: point(g.centre),
            lower_end: point(g.lower_end),
            upper_exit: point(g.upper_exit),
        },
        slice_count: g.slices.len(),
        slices,
        thrust_line: solution
            .thrust_line
            .iter()
            .map(|t| ThrustPointDto {
                boundary: t.boundary,
                x: t.x,
                y: finite_or_none(t.y),
                force: t.force,
                inside_slice: t.is_inside_slice,
            })
            .collect(),
        iterations: solution.iterations,
        residual: finite_or_none(solution.residual),
        warnings,
        solve_time_ms,
    }
}
