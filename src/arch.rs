//! `POST /arch/dead-load` and `POST /arch/live-load`: limit analysis of rigid-block arches
//! (Livesley 1978; SPEC §1, §3).
//!
//! Blocks and interfaces are numbered from 1 in requests and responses, in order of increasing
//! polar angle for circular arches (interface 1 at the right springing), as the thesis prints
//! them. Angles are polar angles in degrees (for block chains: the direction of the joint from
//! its intrados to its extrados end).

use std::num::NonZeroUsize;

use axum::extract::State;
use serde::{Deserialize, Deserializer, Serialize};
use thrustline_solver::arch::{
    solve_dead_load, solve_live_load, thrust_line, ArchError, ArchProblem, Assembly, Bound,
    CircularArch, Formulation, HingeSide, InterfaceLimits, LimitSettings, LimitSolution,
    LimitStatus, LiveLoad, Mechanism, Resultant, SolverFailure, VoussoirShape,
};
use utoipa::ToSchema;

use crate::error::{ApiError, ApiJson, ProblemResponses};
use crate::validation::{count, finite, number};
use crate::AppState;

/// Largest number of voussoirs (or blocks) a request may ask for.
pub const MAX_VOUSSOIRS: usize = 10_000;
/// Smallest radius, height or length accepted (any unit): the scale where f64 still has room.
pub const MIN_LENGTH: f64 = 1e-9;
/// Largest radius, height or length accepted.
pub const MAX_LENGTH: f64 = 1e9;
/// Largest unit weight or cohesion accepted (any unit).
pub const MAX_MAGNITUDE: f64 = 1e12;
/// Largest force, moment or interface limit accepted (any unit).
pub const MAX_FORCE: f64 = 1e30;
/// Largest number of live loads in one request.
pub const MAX_LOADS: usize = 10_000;

/// Shape of the voussoirs of a circular arch.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum VoussoirDto {
    /// Annular sectors (curved intrados and extrados; exact centroid).
    #[default]
    Curved,
    /// Straight intrados and extrados between the corners (polygon centroid).
    Quadrilateral,
}

/// The model of the limit-analysis programmes.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum FormulationDto {
    /// Three redundant forces of the chain, with constraint generation.
    #[default]
    Chain,
    /// Livesley's general assembly: three resultants per interface and equilibrium rows.
    Assembly,
}

impl FormulationDto {
    fn solver(self) -> Formulation {
        match self {
            Self::Chain => Formulation::Chain,
            Self::Assembly => Formulation::Assembly,
        }
    }

    fn name(self) -> &'static str {
        match self {
            Self::Chain => "chain",
            Self::Assembly => "assembly",
        }
    }
}

/// One block of an explicit chain.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct BlockCornersDto {
    /// Corners [x, y] in the order intrados-start, extrados-start, extrados-end, intrados-end;
    /// a block's start face is the previous block's end face.
    #[schema(schema_with = corners_schema)]
    pub corners: [[f64; 2]; 4],
}

/// Four [x, y] points.
fn corners_schema() -> utoipa::openapi::schema::Array {
    use utoipa::openapi::schema::{ArrayBuilder, ObjectBuilder, Type};
    let point = ArrayBuilder::new()
        .items(ObjectBuilder::new().schema_type(Type::Number))
        .min_items(Some(2))
        .max_items(Some(2));
    ArrayBuilder::new()
        .items(point)
        .min_items(Some(4))
        .max_items(Some(4))
        .description(Some(
            "Corners [x, y]: intrados-start, extrados-start, extrados-end, intrados-end",
        ))
        .examples([serde_json::json!([
            [9.5, 0.0],
            [10.5, 0.0],
            [10.5, 1.0],
            [9.5, 1.0]
        ])])
        .build()
}

/// The structure: the thesis' circular arch, or any chain of quadrilateral blocks.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum GeometryDto {
    /// Circular arch (SPEC §1.3): centre at the origin, from polar angle C (right springing) to
    /// 180° − B (left springing), N voussoirs of equal angle.
    Circular {
        /// Middle radius R, 1e-9 ≤ R ≤ 1e9.
        #[schema(minimum = 1e-9, maximum = 1e9, example = 10.0)]
        radius: f64,
        /// Voussoir thickness D, 0 < D < 2R.
        #[schema(exclusive_minimum = 0.0, example = 1.0748)]
        thickness: f64,
        /// Number of voussoirs N, 1 ≤ N ≤ 10000.
        #[schema(minimum = 1, maximum = 10000, example = 1800)]
        voussoirs: usize,
        /// Left base angle B in degrees, −90 < B < 90 (0: semicircle; > 0 segmental; < 0
        /// horseshoe). Defaults to 0.
        #[serde(default)]
        #[schema(exclusive_minimum = -90.0, exclusive_maximum = 90.0, example = 0.0)]
        left_base_angle_deg: f64,
        /// Right base angle C in degrees, −90 < C < 90. Defaults to 0.
        #[serde(default)]
        #[schema(exclusive_minimum = -90.0, exclusive_maximum = 90.0, example = 0.0)]
        right_base_angle_deg: f64,
        /// Voussoir shape. Defaults to `curved`.
        #[serde(default)]
        voussoir: VoussoirDto,
    },
    /// A chain of quadrilateral blocks; the first block's start face and the last block's end
    /// face rest on supports.
    Blocks {
        /// The blocks, 1 to 10000 of them, in order.
        #[schema(min_items = 1, max_items = 10000)]
        blocks: Vec<BlockCornersDto>,
    },
}

/// Limits on the interface resultants (absolute forces). A missing field takes Heyman's value
/// (q_min = s_min = 0, the rest unbounded); `null` means unbounded.
#[derive(Debug, Clone, Default, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct InterfaceLimitsDto {
    /// Lower limit of q, the normal force at the extrados end (≤ 0; 0 = no tension).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>, maximum = 0.0, example = 0.0)]
    pub q_min: Option<Option<f64>>,
    /// Upper limit of q (≥ 0; crushing).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>, minimum = 0.0)]
    pub q_max: Option<Option<f64>>,
    /// Lower limit of s, the normal force at the intrados end (≤ 0; 0 = no tension).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>, maximum = 0.0, example = 0.0)]
    pub s_min: Option<Option<f64>>,
    /// Upper limit of s (≥ 0; crushing).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>, minimum = 0.0)]
    pub s_max: Option<Option<f64>>,
    /// Lower limit of the shear t (≤ 0).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>, maximum = 0.0)]
    pub t_min: Option<Option<f64>>,
    /// Upper limit of the shear t (≥ 0).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>, minimum = 0.0)]
    pub t_max: Option<Option<f64>>,
}

/// Tells a field that is present (possibly `null`) from one that is absent.
fn present<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Option<Option<f64>>, D::Error> {
    Option::<f64>::deserialize(deserializer).map(Some)
}

/// A live load: a force and a moment on one block.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadDto {
    /// Block number (1-based).
    #[schema(minimum = 1, maximum = 10000, example = 5)]
    pub block: usize,
    /// x of the point of application. Defaults to the block centroid.
    #[serde(default)]
    pub x: Option<f64>,
    /// y of the point of application. Defaults to the block centroid.
    #[serde(default)]
    pub y: Option<f64>,
    /// Horizontal force component. Defaults to 0.
    #[serde(default)]
    pub fx: f64,
    /// Vertical force component (up positive). Defaults to 0.
    #[serde(default)]
    #[schema(example = -1.0)]
    pub fy: f64,
    /// Applied moment, counter-clockwise positive. Defaults to 0.
    #[serde(default)]
    pub moment: f64,
}

/// Livesley's dead-load problem: does the structure carry its own weight?
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(example = json!({
    "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0748, "voussoirs": 1800,
                 "left_base_angle_deg": 0.0, "right_base_angle_deg": 0.0, "voussoir": "curved"},
    "unit_weight": 1.0,
    "interface_limits": {"q_min": 0.0, "q_max": null, "s_min": 0.0, "s_max": null, "t_min": null, "t_max": null},
    "friction_coefficient": null
}))]
pub struct DeadLoadRequest {
    /// The structure.
    pub geometry: GeometryDto,
    /// Unit weight γ (> 0): block weight = γ·area. Defaults to 1.
    #[serde(default = "unit")]
    #[schema(exclusive_minimum = 0.0, maximum = 1e12, default = 1.0, example = 1.0)]
    pub unit_weight: f64,
    /// Limits on the interface resultants. Defaults to Heyman's (no tension, no crushing).
    #[serde(default)]
    pub interface_limits: InterfaceLimitsDto,
    /// Coulomb friction coefficient μ ≥ 0 at every interface; null = no sliding. Defaults to
    /// null.
    #[serde(default)]
    #[schema(minimum = 0.0, maximum = 1000000.0)]
    pub friction_coefficient: Option<f64>,
    /// Which model the programmes are written on: `chain` (three redundant forces, the default
    /// and fastest) or `assembly` (Livesley's general formulation, three unknowns per
    /// interface). Both give the same answer; the choice is for cross-checking.
    #[serde(default)]
    pub formulation: FormulationDto,
    /// Interior-point tolerance (relative gap and feasibility), 1e-12 ≤ tol ≤ 1e-4. Defaults to
    /// 1e-10, which gives λ to about 1e-11 relative; 1e-6 is faster and still right to 1e-7
    /// (see the README's accuracy tables).
    #[serde(default = "default_solver_tolerance")]
    #[schema(minimum = 1e-12, maximum = 1e-4, default = 1e-10)]
    pub solver_tolerance: f64,
}

/// Livesley's live-load problem: the factor on the live loads at collapse.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(example = json!({
    "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
    "unit_weight": 1.0,
    "loads": [{"block": 26, "fx": 0.0, "fy": -1.0, "moment": 0.0}]
}))]
pub struct LiveLoadRequest {
    /// The structure.
    pub geometry: GeometryDto,
    /// Unit weight γ (> 0). Defaults to 1.
    #[serde(default = "unit")]
    #[schema(exclusive_minimum = 0.0, maximum = 1e12, default = 1.0, example = 1.0)]
    pub unit_weight: f64,
    /// Limits on the interface resultants. Defaults to Heyman's.
    #[serde(default)]
    pub interface_limits: InterfaceLimitsDto,
    /// Coulomb friction coefficient μ ≥ 0; null = no sliding.
    #[serde(default)]
    #[schema(minimum = 0.0, maximum = 1000000.0)]
    pub friction_coefficient: Option<f64>,
    /// Which model the programmes are written on: `chain` (three redundant forces, the default
    /// and fastest) or `assembly` (Livesley's general formulation, three unknowns per
    /// interface). Both give the same answer; the choice is for cross-checking.
    #[serde(default)]
    pub formulation: FormulationDto,
    /// Interior-point tolerance (relative gap and feasibility), 1e-12 ≤ tol ≤ 1e-4. Defaults to
    /// 1e-10, which gives λ to about 1e-11 relative; 1e-6 is faster and still right to 1e-7
    /// (see the README's accuracy tables).
    #[serde(default = "default_solver_tolerance")]
    #[schema(minimum = 1e-12, maximum = 1e-4, default = 1e-10)]
    pub solver_tolerance: f64,
    /// The live loads (1 to 10000), multiplied together by the load factor.
    #[schema(min_items = 1, max_items = 10000)]
    pub loads: Vec<LoadDto>,
}

fn unit() -> f64 {
    1.0
}

fn default_solver_tolerance() -> f64 {
    1e-10
}

/// An active limit of the collapse mechanism.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ActiveConstraintDto {
    /// Interface number (1-based).
    pub interface: usize,
    /// The resultant: q, s (normal forces at the extrados/intrados ends), t (shear), u, v
    /// (friction: μ(q+s) ∓ t).
    #[schema(example = "s")]
    pub resultant: &'static str,
    /// Which limit: lower or upper.
    #[schema(example = "lower")]
    pub bound: &'static str,
    /// Polar angle of the interface in degrees.
    pub angle_deg: f64,
    /// Where the hinge forms, for q and s at their lower limits: q → intrados, s → extrados.
    #[schema(example = "extrados")]
    pub hinge: Option<&'static str>,
    /// The multiplier (plastic rate), with velocities normalised to a fastest corner speed of 1.
    pub multiplier: f64,
}

/// A hinge of the collapse mechanism.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HingeDto {
    /// Interface number (1-based).
    pub interface: usize,
    /// Polar angle of the interface in degrees.
    pub angle_deg: f64,
    /// intrados or extrados.
    pub location: &'static str,
    /// Rotation rate of the higher-numbered block relative to the lower one (counter-clockwise).
    pub rotation: f64,
}

/// Virtual velocity of one block in the mechanism.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct BlockVelocityDto {
    /// Block number (1-based).
    pub block: usize,
    /// Velocity of the centroid in x.
    pub u: f64,
    /// Velocity of the centroid in y.
    pub v: f64,
    /// Rotation rate (counter-clockwise).
    pub rotation: f64,
}

/// The collapse mechanism, normalised so that the fastest block corner moves at speed 1.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MechanismDto {
    /// Velocity of every block.
    pub blocks: Vec<BlockVelocityDto>,
}

/// The resultant at one interface.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct InterfaceThrustPointDto {
    /// Interface number (1-based).
    pub interface: usize,
    /// x of the point of action of the normal force; null where it vanishes.
    pub x: Option<f64>,
    /// y of the point of action; null where it vanishes.
    pub y: Option<f64>,
    /// Normal force q + s (compression positive).
    pub normal_force: f64,
    /// Shear force t.
    pub shear_force: f64,
    /// Distance of the point of action from the middle of the joint, towards the extrados.
    pub eccentricity: Option<f64>,
}

/// How the solve ended.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SolverDto {
    /// solved; unbounded (no finite live load causes collapse); dead_load_not_carried;
    /// reduced_accuracy, max_iterations, max_time, numerical_error, infeasible (the
    /// interior-point method stopped without an answer it can vouch for: no factor reported).
    #[schema(example = "solved")]
    pub status: &'static str,
    /// Interior-point iterations over all linear programmes.
    pub iterations: u32,
    /// Linear programmes solved.
    pub programmes: usize,
    /// Wall time of the solve in milliseconds.
    pub time_ms: f64,
    /// The formulation used: chain or assembly.
    #[schema(example = "chain")]
    pub formulation: &'static str,
    /// The interior-point tolerance used.
    pub tolerance: f64,
}

/// Everything common to the dead- and live-load answers.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ArchOutcomeDto {
    /// Whether the structure carries its own weight (λ₀ = 1); null if that could not be decided.
    pub stable: Option<bool>,
    /// Dead-load margin at full dead load, as a fraction of the total weight: negative is a
    /// reserve (every limit met with that much to spare), positive a shortfall.
    pub dead_load_margin: Option<f64>,
    /// The limits active in the collapse mechanism (empty when nothing collapses).
    pub active_constraints: Vec<ActiveConstraintDto>,
    /// The hinges of the mechanism.
    pub hinges: Vec<HingeDto>,
    /// Interfaces that slide in the mechanism.
    pub sliding_interfaces: Vec<usize>,
    /// Interfaces that crush in the mechanism.
    pub crushing_interfaces: Vec<usize>,
    /// The collapse mechanism; null when nothing collapses.
    pub mechanism: Option<MechanismDto>,
    /// True when the mechanism slides under Coulomb friction: the linear programme assumes an
    /// associated flow rule, so the load factor may over-estimate the true one (Livesley
    /// §2.7–2.9).
    pub friction_may_overestimate: bool,
    /// The line of thrust of the admissible state at the load factor (empty when there is none).
    pub thrust_line: Vec<InterfaceThrustPointDto>,
    /// How the solve ended.
    pub solver: SolverDto,
}

/// Answer to the dead-load problem.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct DeadLoadResponse {
    /// λ₀ ≤ 1, the largest fraction of the dead load that can be carried; null if the solver
    /// failed.
    #[schema(example = 1.0)]
    pub dead_load_factor: Option<f64>,
    /// Details.
    #[serde(flatten)]
    pub outcome: ArchOutcomeDto,
}

/// Answer to the live-load problem.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct LiveLoadResponse {
    /// λ, the factor on the live loads at collapse; null when the dead load is not carried, no
    /// finite factor causes collapse, or the solver failed.
    pub load_factor: Option<f64>,
    /// Details.
    #[serde(flatten)]
    pub outcome: ArchOutcomeDto,
}

/// Dead-load limit analysis (Livesley's λ₀).
#[utoipa::path(
    post,
    path = "/arch/dead-load",
    tag = "arch",
    request_body = DeadLoadRequest,
    responses(
        (status = 200, description = "The dead-load factor, mechanism and thrust line", body = DeadLoadResponse),
        ProblemResponses,
    )
)]
pub async fn dead_load(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<DeadLoadRequest>,
) -> Result<ApiJson<DeadLoadResponse>, ApiError> {
    Ok(ApiJson(solve_dead_load_request(&state, &request).await?.1))
}

/// Dead-load limit analysis drawn: voussoirs, thrust line, hinges, mechanism.
#[utoipa::path(
    post,
    path = "/arch/dead-load/svg",
    tag = "arch",
    request_body = DeadLoadRequest,
    responses(
        (status = 200, description = "The drawing, 800 px wide", body = String, content_type = "image/svg+xml"),
        ProblemResponses,
    )
)]
pub async fn dead_load_svg(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<DeadLoadRequest>,
) -> Result<Svg, ApiError> {
    let (problem, response) = solve_dead_load_request(&state, &request).await?;
    let title = match response.dead_load_factor {
        Some(f) => format!(
            "Dead load: λ₀ = {f}{}",
            if f >= 1.0 {
                " (stands)"
            } else {
                " (collapses)"
            }
        ),
        None => "Dead load: no answer".to_owned(),
    };
    Ok(Svg(crate::svg::arch::draw(
        problem.assembly(),
        is_curved(&request.geometry),
        &response.outcome,
        &[],
        &title,
    )))
}

async fn solve_dead_load_request(
    state: &AppState,
    request: &DeadLoadRequest,
) -> Result<(ArchProblem, DeadLoadResponse), ApiError> {
    let problem = build_problem(
        &request.geometry,
        request.unit_weight,
        &request.interface_limits,
        request.friction_coefficient,
        &[],
    )?;
    let settings = limit_settings(state, request.formulation, request.solver_tolerance)?;
    let ((problem, solution), elapsed) = state
        .pool
        .run(move || {
            let solution = solve_dead_load(&problem, &settings);
            (problem, solution)
        })
        .await?;
    tracing::info!(
        blocks = problem.assembly().blocks.len(),
        iterations = solution.iterations,
        solve_ms = elapsed.as_secs_f64() * 1e3,
        dead_load_factor = solution.load_factor,
        "dead load solved"
    );
    let response = DeadLoadResponse {
        dead_load_factor: solution.load_factor,
        outcome: outcome(
            &problem,
            &solution,
            request.formulation.name(),
            settings.tolerance,
        ),
    };
    Ok((problem, response))
}

/// Live-load limit analysis (Livesley's λ).
#[utoipa::path(
    post,
    path = "/arch/live-load",
    tag = "arch",
    request_body = LiveLoadRequest,
    responses(
        (status = 200, description = "The live-load factor, mechanism and thrust line; `stable: false` and `load_factor: null` when the dead load is not carried", body = LiveLoadResponse),
        ProblemResponses,
    )
)]
pub async fn live_load(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<LiveLoadRequest>,
) -> Result<ApiJson<LiveLoadResponse>, ApiError> {
    Ok(ApiJson(solve_live_load_request(&state, &request).await?.1))
}

/// Live-load limit analysis drawn: voussoirs, loads, thrust line, hinges, mechanism.
#[utoipa::path(
    post,
    path = "/arch/live-load/svg",
    tag = "arch",
    request_body = LiveLoadRequest,
    responses(
        (status = 200, description = "The drawing, 800 px wide", body = String, content_type = "image/svg+xml"),
        ProblemResponses,
    )
)]
pub async fn live_load_svg(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<LiveLoadRequest>,
) -> Result<Svg, ApiError> {
    let (problem, response) = solve_live_load_request(&state, &request).await?;
    let title = match (response.load_factor, response.outcome.stable) {
        (Some(f), _) => format!("Live load: λ = {f:.4}"),
        (None, Some(false)) => "Live load: the dead load is not carried".to_owned(),
        (None, _) => "Live load: no collapse load".to_owned(),
    };
    let curved = is_curved(&request.geometry);
    Ok(Svg(crate::svg::arch::draw(
        problem.assembly(),
        curved,
        &response.outcome,
        problem.live_loads(),
        &title,
    )))
}

async fn solve_live_load_request(
    state: &AppState,
    request: &LiveLoadRequest,
) -> Result<(ArchProblem, LiveLoadResponse), ApiError> {
    count("loads", request.loads.len(), 1, MAX_LOADS)?;
    let problem = build_problem(
        &request.geometry,
        request.unit_weight,
        &request.interface_limits,
        request.friction_coefficient,
        &request.loads,
    )?;
    let settings = limit_settings(state, request.formulation, request.solver_tolerance)?;
    let ((problem, solution), elapsed) = state
        .pool
        .run(move || {
            let solution = solve_live_load(&problem, &settings);
            (problem, solution)
        })
        .await?;
    let solution = solution.map_err(arch_error)?;
    tracing::info!(
        blocks = problem.assembly().blocks.len(),
        iterations = solution.iterations,
        solve_ms = elapsed.as_secs_f64() * 1e3,
        load_factor = solution.load_factor,
        "live load solved"
    );
    let response = LiveLoadResponse {
        load_factor: solution.load_factor,
        outcome: outcome(
            &problem,
            &solution,
            request.formulation.name(),
            settings.tolerance,
        ),
    };
    Ok((problem, response))
}

/// The solver settings a request asks for, within the service's time limit.
fn limit_settings(
    state: &AppState,
    formulation: FormulationDto,
    tolerance: f64,
) -> Result<LimitSettings, ApiError> {
    Ok(LimitSettings {
        time_limit_secs: state.solve_time_limit_secs(),
        formulation: formulation.solver(),
        tolerance: number("solver_tolerance", tolerance, 1e-12, false, 1e-4)?,
        ..LimitSettings::default()
    })
}

/// Whether the request's voussoirs are annular sectors (drawn with arcs).
fn is_curved(geometry: &GeometryDto) -> bool {
    matches!(
        geometry,
        GeometryDto::Circular {
            voussoir: VoussoirDto::Curved,
            ..
        }
    )
}

/// An `image/svg+xml` answer.
pub struct Svg(pub String);

impl axum::response::IntoResponse for Svg {
    fn into_response(self) -> axum::response::Response {
        (
            [(
                axum::http::header::CONTENT_TYPE,
                "image/svg+xml; charset=utf-8",
            )],
            self.0,
        )
            .into_response()
    }
}

/// Validates `interface_limits`: missing fields take Heyman's values, `null` is unbounded.
pub fn interface_limits(limits: &InterfaceLimitsDto) -> Result<InterfaceLimits, ApiError> {
    let heyman = InterfaceLimits::heyman();
    let limit = |field: &str, given: Option<Option<f64>>, default: Option<f64>, lower: bool| {
        let field = format!("interface_limits.{field}");
        match given.unwrap_or(default) {
            None => Ok(None),
            Some(v) if lower => number(&field, v, -MAX_FORCE, false, 0.0).map(Some),
            Some(v) => number(&field, v, 0.0, false, MAX_FORCE).map(Some),
        }
    };
    Ok(InterfaceLimits {
        q_min: limit("q_min", limits.q_min, heyman.q_min, true)?,
        q_max: limit("q_max", limits.q_max, heyman.q_max, false)?,
        s_min: limit("s_min", limits.s_min, heyman.s_min, true)?,
        s_max: limit("s_max", limits.s_max, heyman.s_max, false)?,
        t_min: limit("t_min", limits.t_min, heyman.t_min, true)?,
        t_max: limit("t_max", limits.t_max, heyman.t_max, false)?,
    })
}

/// Validates `friction_coefficient` (null: no sliding).
pub fn friction_coefficient(friction: Option<f64>) -> Result<Option<f64>, ApiError> {
    friction
        .map(|mu| number("friction_coefficient", mu, 0.0, false, 1e6))
        .transpose()
}

/// Validates the common part of an arch request and builds the solver's problem.
pub fn build_problem(
    geometry: &GeometryDto,
    unit_weight: f64,
    limits: &InterfaceLimitsDto,
    friction: Option<f64>,
    loads: &[LoadDto],
) -> Result<ArchProblem, ApiError> {
    let assembly = build_assembly(geometry)?;
    let unit_weight = number("unit_weight", unit_weight, 0.0, true, MAX_MAGNITUDE)?;
    let limits = interface_limits(limits)?;
    let friction = friction_coefficient(friction)?;
    let n = assembly.blocks.len();
    let live_loads = loads
        .iter()
        .enumerate()
        .map(|(i, load)| {
            let field = |name: &str| format!("loads[{i}].{name}");
            let block = count(&field("block"), load.block, 1, n)? - 1;
            let centroid = assembly.blocks[block].centroid;
            Ok(LiveLoad {
                block,
                point: (
                    load.x
                        .map(|x| finite(&field("x"), x))
                        .transpose()?
                        .unwrap_or(centroid.0),
                    load.y
                        .map(|y| finite(&field("y"), y))
                        .transpose()?
                        .unwrap_or(centroid.1),
                ),
                fx: number(&field("fx"), load.fx, -MAX_FORCE, false, MAX_FORCE)?,
                fy: number(&field("fy"), load.fy, -MAX_FORCE, false, MAX_FORCE)?,
                moment: number(&field("moment"), load.moment, -MAX_FORCE, false, MAX_FORCE)?,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    if !loads.is_empty()
        && live_loads
            .iter()
            .all(|l| l.fx == 0.0 && l.fy == 0.0 && l.moment == 0.0)
    {
        return Err(ApiError::invalid(
            "loads",
            "every load is zero: give at least one non-zero fx, fy or moment",
        ));
    }
    ArchProblem::new(assembly, unit_weight, limits, friction, live_loads).map_err(arch_error)
}

/// The circular arch of a request, if it is one (validated).
pub fn circular_arch(geometry: &GeometryDto) -> Result<Option<CircularArch>, ApiError> {
    let GeometryDto::Circular {
        radius,
        thickness,
        voussoirs,
        left_base_angle_deg,
        right_base_angle_deg,
        voussoir,
    } = geometry
    else {
        return Ok(None);
    };
    let radius = number("geometry.radius", *radius, MIN_LENGTH, false, MAX_LENGTH)?;
    let n = count("geometry.voussoirs", *voussoirs, 1, MAX_VOUSSOIRS)?;
    let left = number(
        "geometry.left_base_angle_deg",
        *left_base_angle_deg,
        -90.0,
        true,
        89.999_999,
    )?;
    let right = number(
        "geometry.right_base_angle_deg",
        *right_base_angle_deg,
        -90.0,
        true,
        89.999_999,
    )?;
    let shape = match voussoir {
        VoussoirDto::Curved => VoussoirShape::Curved,
        VoussoirDto::Quadrilateral => VoussoirShape::Quadrilateral,
    };
    let n = NonZeroUsize::new(n)
        .ok_or_else(|| ApiError::invalid("geometry.voussoirs", "must be at least 1"))?;
    // 0 < thickness < 2·radius is CircularArch::new's check.
    CircularArch::new(radius, *thickness, n, left, right, shape)
        .map(Some)
        .map_err(arch_error)
}

fn build_assembly(geometry: &GeometryDto) -> Result<Assembly, ApiError> {
    if let Some(arch) = circular_arch(geometry)? {
        return Ok(arch.assembly());
    }
    let GeometryDto::Blocks { blocks } = geometry else {
        return Err(ApiError::invalid(
            "geometry.kind",
            "must be circular or blocks",
        ));
    };
    count("geometry.blocks", blocks.len(), 1, MAX_VOUSSOIRS)?;
    for (b, block) in blocks.iter().enumerate() {
        for (c, [x, y]) in block.corners.iter().enumerate() {
            let field = format!("geometry.blocks[{b}].corners[{c}]");
            number(&field, *x, -MAX_LENGTH, false, MAX_LENGTH)?;
            number(&field, *y, -MAX_LENGTH, false, MAX_LENGTH)?;
        }
    }
    let corners: Vec<[(f64, f64); 4]> = blocks
        .iter()
        .map(|b| b.corners.map(|[x, y]| (x, y)))
        .collect();
    Assembly::from_quadrilaterals(&corners).map_err(arch_error)
}

/// The solver's refusals are the client's to fix: 422 naming the parameter.
pub fn arch_error(error: ArchError) -> ApiError {
    match error {
        ArchError::OutOfRange {
            parameter,
            value,
            allowed,
        } => ApiError::invalid(
            parameter,
            format!("{value} is out of range: allowed is {allowed}"),
        ),
        ArchError::InvalidGeometry { parameter, reason } => ApiError::invalid(parameter, reason),
    }
}

fn resultant_name(resultant: Resultant) -> &'static str {
    match resultant {
        Resultant::Q => "q",
        Resultant::S => "s",
        Resultant::T => "t",
        Resultant::U => "u",
        Resultant::V => "v",
    }
}

fn side_name(side: HingeSide) -> &'static str {
    match side {
        HingeSide::Intrados => "intrados",
        HingeSide::Extrados => "extrados",
    }
}

/// The status word of a solution, exhaustively.
pub fn status_name(status: LimitStatus) -> &'static str {
    match status {
        LimitStatus::Solved => "solved",
        LimitStatus::DeadLoadNotCarried => "dead_load_not_carried",
        LimitStatus::Unbounded => "unbounded",
        LimitStatus::SolverFailed(SolverFailure::ReducedAccuracy) => "reduced_accuracy",
        LimitStatus::SolverFailed(SolverFailure::MaxIterations) => "max_iterations",
        LimitStatus::SolverFailed(SolverFailure::MaxTime) => "max_time",
        LimitStatus::SolverFailed(SolverFailure::Numerical) => "numerical_error",
        LimitStatus::SolverFailed(SolverFailure::Infeasible) => "infeasible",
    }
}

/// Translates a solution into the response fields common to both problems.
pub fn outcome(
    problem: &ArchProblem,
    solution: &LimitSolution,
    formulation: &'static str,
    tolerance: f64,
) -> ArchOutcomeDto {
    let mechanism = solution.mechanism.as_ref();
    let one_based = |list: &[usize]| list.iter().map(|k| k + 1).collect::<Vec<_>>();
    ArchOutcomeDto {
        stable: solution.dead_load_carried,
        dead_load_margin: solution.dead_load_margin,
        active_constraints: mechanism.map(active_constraints).unwrap_or_default(),
        hinges: mechanism.map(hinges).unwrap_or_default(),
        sliding_interfaces: mechanism.map(|m| one_based(&m.sliding)).unwrap_or_default(),
        crushing_interfaces: mechanism
            .map(|m| one_based(&m.crushing))
            .unwrap_or_default(),
        mechanism: mechanism.map(|m| MechanismDto {
            blocks: m
                .velocities
                .iter()
                .enumerate()
                .map(|(b, v)| BlockVelocityDto {
                    block: b + 1,
                    u: v[0],
                    v: v[1],
                    rotation: v[2],
                })
                .collect(),
        }),
        friction_may_overestimate: mechanism.is_some_and(|m| m.involves_friction()),
        thrust_line: thrust_line(problem.assembly(), &solution.resultants)
            .into_iter()
            .map(|t| InterfaceThrustPointDto {
                interface: t.interface + 1,
                x: t.point.map(|p| p.0),
                y: t.point.map(|p| p.1),
                normal_force: t.normal_force,
                shear_force: t.shear_force,
                eccentricity: t.eccentricity,
            })
            .collect(),
        solver: SolverDto {
            status: status_name(solution.status),
            iterations: solution.iterations,
            programmes: solution.programmes,
            time_ms: solution.solve_time_secs * 1e3,
            formulation,
            tolerance,
        },
    }
}

/// The active limits of a mechanism, 1-based.
pub fn active_constraints(mechanism: &Mechanism) -> Vec<ActiveConstraintDto> {
    mechanism
        .active
        .iter()
        .map(|a| ActiveConstraintDto {
            interface: a.interface + 1,
            resultant: resultant_name(a.resultant),
            bound: match a.bound {
                Bound::Lower => "lower",
                Bound::Upper => "upper",
            },
            angle_deg: a.angle_deg,
            hinge: a.hinge.map(side_name),
            multiplier: a.multiplier,
        })
        .collect()
}

/// The hinges of a mechanism, 1-based.
pub fn hinges(mechanism: &Mechanism) -> Vec<HingeDto> {
    mechanism
        .hinges
        .iter()
        .map(|h| HingeDto {
            interface: h.interface + 1,
            angle_deg: h.angle_deg,
            location: side_name(h.side),
            rotation: h.rotation,
        })
        .collect()
}
