//! `POST /slope/spencer`: Spencer's method for one slip circle (SPEC §2, §3).
//!
//! Translates the JSON request into the solver's types (validating every number once), runs the
//! solve on the blocking pool, and translates the solution back. Slices are numbered from 1 at
//! the lower end of the slip surface, as the thesis prints them.

use std::num::NonZeroUsize;

use axum::extract::State;
use serde::{Deserialize, Serialize};
use thrustline_solver::slope::{
    factor_curves, search_critical_circle, solve_spencer, Embankment, ExternalLoad, SearchGrid,
    SearchProblem, SearchSettings, SearchSolution, Seismic, SlipCircle, SlopeError, SlopeProblem,
    Soil, SpencerSettings, SpencerSolution, SpencerStatus,
};
use utoipa::ToSchema;

use crate::arch::{MAX_FORCE, MAX_LENGTH, MAX_MAGNITUDE, MIN_LENGTH};
use crate::error::{ApiError, ApiJson, ProblemResponses};
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
    /// Slope height H, 1e-9 ≤ H ≤ 1e9.
    #[schema(minimum = 1e-9, maximum = 1e9, example = 30.48)]
    pub height: f64,
    /// Horizontal length L of the slope face, 1e-9 ≤ L ≤ 1e9; the slope is H:L.
    #[schema(minimum = 1e-9, maximum = 1e9, example = 60.96)]
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
    /// Unit weight γ, 0 < γ ≤ 1e12.
    #[schema(exclusive_minimum = 0.0, maximum = 1e12, example = 10.0)]
    pub unit_weight: f64,
    /// Effective cohesion c', 0 ≤ c' ≤ 1e12 (> 0 when the friction angle is 0).
    #[schema(minimum = 0.0, maximum = 1e12, example = 6.096)]
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
    /// The slip circle to analyse (give this or `search`).
    #[serde(default)]
    pub circle: Option<CircleDto>,
    /// Search for the critical circle instead (`{}` for automatic bounds).
    #[serde(default)]
    pub search: Option<SearchDto>,
    /// Also return Spencer's curves F_f(θ) and F_m(θ) around the solution. Defaults to false.
    #[serde(default)]
    pub curves: bool,
    /// Accuracy control: when given (1e-9 … 0.1), the slices are doubled from `slices` until F
    /// changes by less than this fraction (at most 10000 slices); `slice_refinement` lists the
    /// steps. Defaults to none: exactly `slices` slices. 1e-4 suits ordinary slopes.
    #[serde(default)]
    #[schema(minimum = 1e-9, maximum = 0.1, example = 1e-4)]
    pub slice_tolerance: Option<f64>,
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

/// Largest number of grid points along one axis of a search.
pub const MAX_GRID: usize = 101;
/// Largest nx·ny·slices of a search (its cost).
pub const MAX_GRID_SLICES: usize = 10_000_000;

/// A search for the critical circle: a grid over centres, refined by Nelder–Mead; bounds left
/// out are chosen automatically around the perpendicular bisector of the slope.
#[derive(Debug, Clone, Default, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SearchDto {
    /// Smallest centre X (from the lower end). Automatic when missing.
    pub x_min: Option<f64>,
    /// Largest centre X. Automatic when missing.
    pub x_max: Option<f64>,
    /// Smallest centre Y (above the lower end). Automatic when missing.
    pub y_min: Option<f64>,
    /// Largest centre Y. Automatic when missing.
    pub y_max: Option<f64>,
    /// Grid points along X, 2 ≤ nx ≤ 101. Defaults to 21.
    #[serde(default = "default_grid")]
    #[schema(minimum = 2, maximum = 101, default = 21)]
    pub nx: usize,
    /// Grid points along Y, 2 ≤ ny ≤ 101. Defaults to 21.
    #[serde(default = "default_grid")]
    #[schema(minimum = 2, maximum = 101, default = 21)]
    pub ny: usize,
    /// Lower-end position factor F_e of the circles, 0 ≤ F_e ≤ 100. Defaults to 0 (toe).
    #[serde(default)]
    #[schema(minimum = 0.0, maximum = 100.0)]
    pub lower_end_factor: f64,
    /// When given, F_e is searched too, within [0, this], in the refinement.
    #[serde(default)]
    #[schema(exclusive_minimum = 0.0, maximum = 100.0)]
    pub lower_end_factor_max: Option<f64>,
}

fn default_grid() -> usize {
    21
}

/// F over the grid of centres, for contour plots.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GridDto {
    /// Centre X of the grid columns (from the lower end).
    pub xs: Vec<f64>,
    /// Centre Y of the grid rows.
    pub ys: Vec<f64>,
    /// `factor_of_safety[j][i]` at (xs[i], ys[j]); null where the centre gives no valid circle.
    pub factor_of_safety: Vec<Vec<Option<f64>>>,
}

/// How the search went.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SearchOutDto {
    /// Circles evaluated (grid and refinement).
    pub evaluations: usize,
    /// Times the grid moved because the minimum lay on its edge.
    pub regrids: usize,
    /// Whether the minimum still lies on the edge of the region searched.
    pub on_edge: bool,
}

/// Spencer's figure: F from each equation alone against θ; they cross at the answer.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CurvesDto {
    /// Inclinations θ in degrees.
    pub theta_deg: Vec<f64>,
    /// F_f(θ), from force equilibrium; null where it has no root.
    pub force_factor: Vec<Option<f64>>,
    /// F_m(θ), from moment equilibrium; null where it has no root.
    pub moment_factor: Vec<Option<f64>>,
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
pub struct BoundaryThrustPointDto {
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
    /// φ' = 0: no parallel inter-slice forces meet force equilibrium, but moment equilibrium
    /// alone fixes F exactly for a circle (the base shear c'·l/F does not depend on the normal
    /// forces): F is reported, θ and the line of thrust are not; slice forces are Bishop's.
    MomentOnly,
}

/// Spencer's factor of safety, the inter-slice inclination and everything behind them.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SpencerResponse {
    /// Whether both equilibrium equations were solved (false with `status: moment_only`, which
    /// still reports F).
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
    pub thrust_line: Vec<BoundaryThrustPointDto>,
    /// Newton iterations (plus fallback evaluations).
    pub iterations: usize,
    /// Largest scaled residual of the two equations (force/ΣW, moment/(ΣW·R)).
    pub residual: Option<f64>,
    /// Things the engineer should look at: small m_α, tension at the base, a thrust line
    /// outside the mass, no solution.
    pub warnings: Vec<String>,
    /// Wall time of the solve in milliseconds.
    pub solve_time_ms: f64,
    /// With `search`: how the search went.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub search: Option<SearchOutDto>,
    /// With `search`: F over the last grid of centres.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grid: Option<GridDto>,
    /// With `curves: true`: F_f(θ) and F_m(θ).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curves: Option<CurvesDto>,
    /// With `slice_tolerance`: F at each number of slices tried, the last one answered.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slice_refinement: Option<Vec<SliceRefinementDto>>,
}

/// One step of the slice refinement.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SliceRefinementDto {
    /// Number of slices.
    pub slices: usize,
    /// F with that many slices; null where the equations had no solution.
    pub factor_of_safety: Option<f64>,
}

/// Spencer's method for one slip circle.
#[utoipa::path(
    post,
    path = "/slope/spencer",
    tag = "slope",
    request_body = SpencerRequest,
    responses(
        (status = 200, description = "Solved, or an honest `converged: false`", body = SpencerResponse),
        ProblemResponses,
    )
)]
pub async fn spencer(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<SpencerRequest>,
) -> Result<ApiJson<SpencerResponse>, ApiError> {
    Ok(ApiJson(solve_request(&state, request).await?.1))
}

/// Spencer's method drawn: embankment, slip circle and centre, slices, line of thrust, and
/// for a search the map of F over the centres.
#[utoipa::path(
    post,
    path = "/slope/spencer/svg",
    tag = "slope",
    request_body = SpencerRequest,
    responses(
        (status = 200, description = "The drawing, 800 px wide", body = String, content_type = "image/svg+xml"),
        ProblemResponses,
    )
)]
pub async fn spencer_svg(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<SpencerRequest>,
) -> Result<crate::arch::Svg, ApiError> {
    let searched = request.search.is_some();
    let (problem, response) = solve_request(&state, request).await?;
    let title = if searched {
        "Spencer's method: the critical slip circle"
    } else {
        "Spencer's method: one slip circle"
    };
    Ok(crate::arch::Svg(crate::svg::slope::draw(
        &problem, &response, title,
    )))
}

async fn solve_request(
    state: &AppState,
    request: SpencerRequest,
) -> Result<(SlopeProblem, SpencerResponse), ApiError> {
    let parts = parts_from(&request)?;
    let request_tolerance = parts.slice_tolerance.unwrap_or(0.0);
    let time_limit = state.solve_time_limit;
    let curves = request.curves;
    let target = match (&request.circle, &request.search) {
        (Some(circle), None) => Target::Circle(circle_from(circle)?),
        (None, Some(search)) => {
            if !request.external_loads.is_empty() {
                return Err(ApiError::invalid(
                    "external_loads",
                    "cannot be combined with search: loads are given per slice, and the slices \
                     change from circle to circle",
                ));
            }
            Target::Search(search_from(search, &parts)?)
        }
        (Some(_), Some(_)) => {
            return Err(ApiError::invalid(
                "search",
                "give either circle or search, not both",
            ))
        }
        (None, None) => return Err(ApiError::invalid(
            "circle",
            "give a circle to analyse, or search ({} for automatic bounds) for the critical one",
        )),
    };
    let (solved, elapsed) = state
        .pool
        .run(move || solve_target(parts, target, curves, time_limit))
        .await?;
    let (problem, solution, search, curves, refinement) = solved?;
    tracing::info!(
        slices = problem.geometry.slices.len(),
        iterations = solution.iterations,
        evaluations = search.as_ref().map(|s| s.evaluations),
        solve_ms = elapsed.as_secs_f64() * 1e3,
        factor_of_safety = solution.factor_of_safety,
        "spencer solved"
    );
    let mut response = response_from(&problem, &solution, elapsed.as_secs_f64() * 1e3);
    response.curves = curves;
    if let Some(refinement) = refinement {
        if !refinement.settled {
            response.warnings.push(format!(
                "slice_tolerance {request_tolerance} not reached before {MAX_SLICES} slices"
            ));
        }
        response.slice_refinement = Some(refinement.steps);
    }
    if let Some(search) = search {
        if search.is_on_edge {
            response.warnings.push(
                "the critical centre lies on the edge of the search region even after moving the \
                 grid: the true minimum may lie outside it"
                    .to_owned(),
            );
        }
        response.search = Some(SearchOutDto {
            evaluations: search.evaluations,
            regrids: search.regrids,
            on_edge: search.is_on_edge,
        });
        response.grid = Some(GridDto {
            xs: search.grid.xs,
            ys: search.grid.ys,
            factor_of_safety: search.grid.factors,
        });
    }
    Ok((problem, response))
}

/// The validated parts of a request that do not depend on the circle.
struct Parts {
    embankment: Embankment,
    slices: NonZeroUsize,
    slice_tolerance: Option<f64>,
    soil: Soil,
    seismic: Seismic,
    external_loads: Vec<ExternalLoad>,
}

impl Parts {
    /// Twice `current` slices, if that stays within the limit.
    fn slices_doubled(&self, current: usize) -> Option<NonZeroUsize> {
        NonZeroUsize::new(2 * current).filter(|n| n.get() <= MAX_SLICES)
    }
}

/// One circle, or a search.
enum Target {
    Circle(SlipCircle),
    Search((SearchGrid, SearchProblem)),
}

type Solved = (
    SlopeProblem,
    SpencerSolution,
    Option<SearchSolution>,
    Option<CurvesDto>,
    Option<SliceRefinement>,
);

/// The steps of a slice refinement and whether F settled within the tolerance.
struct SliceRefinement {
    steps: Vec<SliceRefinementDto>,
    settled: bool,
}

/// Runs on the blocking pool: the search if asked, then the full solution of the circle.
fn solve_target(
    parts: Parts,
    target: Target,
    curves: bool,
    time_limit: std::time::Duration,
) -> Result<Solved, ApiError> {
    let settings = SpencerSettings::default();
    let started = std::time::Instant::now();
    let (circle, search) = match target {
        Target::Circle(circle) => (circle, None),
        Target::Search((grid, problem)) => {
            let settings = SearchSettings {
                time_limit: Some(time_limit),
                ..SearchSettings::default()
            };
            let found = search_critical_circle(&problem, grid, &settings);
            if found.timed_out {
                // The request asks for more work than one solve may take: the client's to change.
                return Err(ApiError::invalid(
                    "search",
                    format!(
                        "the search did not finish within the solve time limit of {} s: use a \
                         smaller grid, fewer slices or no lower_end_factor_max",
                        time_limit.as_secs_f64()
                    ),
                ));
            }
            let circle = found.circle.ok_or_else(|| {
                ApiError::invalid(
                    "search",
                    "no centre in the region searched gives a circle with a solution: widen or \
                     move the bounds (or leave them out for automatic ones)",
                )
            })?;
            (circle, Some(found))
        }
    };
    let build = |slices: NonZeroUsize| {
        SlopeProblem::new(
            parts.embankment,
            circle,
            slices,
            parts.soil,
            parts.seismic,
            parts.external_loads.clone(),
        )
        .map_err(slope_error)
    };
    let mut problem = build(parts.slices)?;
    let mut solution = solve_spencer(&problem, &settings);
    let mut refinement = None;
    if let Some(tolerance) = parts.slice_tolerance {
        // Double the slices until F changes by less than the tolerance (relative).
        let mut steps = vec![SliceRefinementDto {
            slices: parts.slices.get(),
            factor_of_safety: solution.factor_of_safety,
        }];
        let mut settled = false;
        while let Some(doubled) = parts.slices_doubled(problem.geometry.slices.len()) {
            if started.elapsed() > time_limit {
                return Err(ApiError::invalid(
                    "slice_tolerance",
                    format!(
                        "the refinement did not settle within the solve time limit of {} s: use \
                         a larger slice_tolerance",
                        time_limit.as_secs_f64()
                    ),
                ));
            }
            let finer = build(doubled)?;
            let finer_solution = solve_spencer(&finer, &settings);
            steps.push(SliceRefinementDto {
                slices: doubled.get(),
                factor_of_safety: finer_solution.factor_of_safety,
            });
            settled = match (solution.factor_of_safety, finer_solution.factor_of_safety) {
                (Some(a), Some(b)) => (a - b).abs() <= tolerance * b,
                _ => false,
            };
            (problem, solution) = (finer, finer_solution);
            if settled {
                break;
            }
        }
        refinement = Some(SliceRefinement { steps, settled });
    }
    let curves = match (solution.theta_rad, curves) {
        (Some(theta), true) => Some(curves_around(&problem, theta)),
        _ => None,
    };
    Ok((problem, solution, search, curves, refinement))
}

/// F_f(θ) and F_m(θ) from θ* − 30° to θ* + 30° in steps of 1°.
fn curves_around(problem: &SlopeProblem, theta: f64) -> CurvesDto {
    let centre = theta.to_degrees().round();
    let theta_deg: Vec<f64> = (-30..=30)
        .map(|i| centre + f64::from(i))
        .filter(|t| t.abs() < 89.0)
        .collect();
    let radians: Vec<f64> = theta_deg.iter().map(|t| t.to_radians()).collect();
    let (force_factor, moment_factor) = factor_curves(problem, &radians).into_iter().unzip();
    CurvesDto {
        theta_deg,
        force_factor,
        moment_factor,
    }
}

fn circle_from(circle: &CircleDto) -> Result<SlipCircle, ApiError> {
    Ok(SlipCircle {
        x: finite("circle.x", circle.x)?,
        y: number("circle.y", circle.y, 0.0, true, f64::MAX)?,
        lower_end_factor: number(
            "circle.lower_end_factor",
            circle.lower_end_factor,
            0.0,
            false,
            f64::MAX,
        )?,
    })
}

fn search_from(search: &SearchDto, parts: &Parts) -> Result<(SearchGrid, SearchProblem), ApiError> {
    let lower_end_factor = number(
        "search.lower_end_factor",
        search.lower_end_factor,
        0.0,
        false,
        100.0,
    )?;
    let lower_end_factor_max = search
        .lower_end_factor_max
        .map(|m| number("search.lower_end_factor_max", m, 0.0, true, 100.0))
        .transpose()?;
    let automatic = SearchGrid::automatic(&parts.embankment, lower_end_factor);
    let nx = count("search.nx", search.nx, 2, MAX_GRID)?;
    let ny = count("search.ny", search.ny, 2, MAX_GRID)?;
    let cost = nx * ny * parts.slices.get();
    if cost > MAX_GRID_SLICES {
        return Err(ApiError::invalid(
            "search",
            format!(
                "nx·ny·slices = {cost} is out of range: allowed is at most {MAX_GRID_SLICES} \
                 (fewer grid points or slices)"
            ),
        ));
    }
    let bound = |field: &str, value: Option<f64>, default: f64| {
        value.map_or(Ok(default), |v| finite(field, v))
    };
    let grid = SearchGrid {
        x_min: bound("search.x_min", search.x_min, automatic.x_min)?,
        x_max: bound("search.x_max", search.x_max, automatic.x_max)?,
        y_min: bound("search.y_min", search.y_min, automatic.y_min)?,
        y_max: bound("search.y_max", search.y_max, automatic.y_max)?,
        nx,
        ny,
    };
    if grid.x_max <= grid.x_min {
        return Err(ApiError::invalid(
            "search.x_max",
            "must be greater than search.x_min",
        ));
    }
    if grid.y_max <= grid.y_min {
        return Err(ApiError::invalid(
            "search.y_max",
            "must be greater than search.y_min",
        ));
    }
    if grid.y_max <= 0.0 {
        return Err(ApiError::invalid(
            "search.y_max",
            "must be > 0: centres lie above the lower end",
        ));
    }
    let problem = SearchProblem {
        embankment: parts.embankment,
        slices: parts.slices,
        soil: parts.soil,
        seismic: parts.seismic,
        lower_end_factor,
        lower_end_factor_max,
    };
    Ok((grid, problem))
}

/// Validates everything but the circle or search.
fn parts_from(request: &SpencerRequest) -> Result<Parts, ApiError> {
    let height = number(
        "slope.height",
        request.slope.height,
        MIN_LENGTH,
        false,
        MAX_LENGTH,
    )?;
    let length = number(
        "slope.length",
        request.slope.length,
        MIN_LENGTH,
        false,
        MAX_LENGTH,
    )?;
    let slices = count("slices", request.slices, 1, MAX_SLICES)?;
    let soil = &request.soil;
    number(
        "soil.unit_weight",
        soil.unit_weight,
        0.0,
        true,
        MAX_MAGNITUDE,
    )?;
    number("soil.cohesion", soil.cohesion, 0.0, false, MAX_MAGNITUDE)?;
    // The friction angle, the pore pressure ratio and the lower bounds are Soil::new's checks.
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
                fx: number(&field("fx"), load.fx, -MAX_FORCE, false, MAX_FORCE)?,
                fy: number(&field("fy"), load.fy, -MAX_FORCE, false, MAX_FORCE)?,
                moment: number(&field("moment"), load.moment, -MAX_FORCE, false, MAX_FORCE)?,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    let embankment = Embankment::new(height, length).map_err(slope_error)?;
    let slices = NonZeroUsize::new(slices)
        .ok_or_else(|| ApiError::invalid("slices", "must be at least 1"))?;
    let slice_tolerance = request
        .slice_tolerance
        .map(|t| number("slice_tolerance", t, 1e-9, false, 0.1))
        .transpose()?;
    if slice_tolerance.is_some() && !external_loads.is_empty() {
        return Err(ApiError::invalid(
            "slice_tolerance",
            "cannot be combined with external_loads: loads are given per slice, and refining \
             changes the slices",
        ));
    }
    Ok(Parts {
        embankment,
        slices,
        slice_tolerance,
        soil,
        seismic,
        external_loads,
    })
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
    let (converged, status, has_forces) = match solution.status {
        SpencerStatus::Converged => (true, SpencerStatusDto::Converged, true),
        SpencerStatus::NoSolution => (false, SpencerStatusDto::NoSolution, false),
        SpencerStatus::MomentOnly => (false, SpencerStatusDto::MomentOnly, true),
    };
    let mut warnings = Vec::new();
    match solution.status {
        SpencerStatus::Converged => {}
        SpencerStatus::NoSolution => warnings.push(
            "no (F, θ) with positive m_α satisfies both equilibrium equations for this circle; \
             no factor of safety is reported"
                .to_owned(),
        ),
        SpencerStatus::MomentOnly => warnings.push(
            "φ' = 0 and no parallel inter-slice forces satisfy force equilibrium: F is from \
             moment equilibrium alone (exact for a circle when φ' = 0); θ is undefined and the \
             slice forces are Bishop's (θ = 0)"
                .to_owned(),
        ),
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
    let slices = if has_forces {
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
            .map(|t| BoundaryThrustPointDto {
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
        search: None,
        grid: None,
        curves: None,
        slice_refinement: None,
    }
}
