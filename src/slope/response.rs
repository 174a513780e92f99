//! The Spencer answer, built whole from the solver's results: slices numbered from 1 at the
//! lower end of the slip surface, angles in degrees.

use serde::Serialize;
use thrustline_solver::slope::analysis::{Analysed, Refinement, SearchReport};
use thrustline_solver::slope::{Sliced, SpencerSolution, SpencerStatus, ThrustPoint};

use super::methods::MethodsDto;
use super::options::{AccuracyOutDto, SlopeDetailDto};
use super::outputs::{
    circle_out, point, search_out, CircleOutDto, CurvesDto, GridDto, PointDto, SearchOutDto,
};
use super::slices::slice_dtos;
pub use super::slices::SliceDto;
use super::solved::SolvedSlope;
use super::warnings::warnings;
use crate::warning::Warning;

use utoipa::ToSchema;

/// A point of the line of thrust on an inter-slice boundary (Spencer 1973).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct BoundaryThrustPointDto {
    /// Boundary number: boundary i lies between slices i and i+1.
    pub boundary: usize,
    /// x of the boundary.
    pub x: f64,
    /// Height of the point of action; null where the inter-slice force vanishes.
    #[schema(required = true)]
    pub y: Option<f64>,
    /// Inter-slice force (compression positive).
    pub force: f64,
    /// Whether the point lies between the slip surface and the ground surface.
    pub inside_slice: bool,
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
    /// The equations have a root, but F is outside 1e-6…1e6 or the frictional terms add up to
    /// a negative resistance (the mass held up by tension at the base): no F is reported.
    /// `negative_effective_stress: drop_friction` answers such surfaces.
    Unphysical,
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
    #[schema(examples(1.06958))]
    #[schema(required = true)]
    pub factor_of_safety: Option<f64>,
    /// Inclination θ of the parallel inter-slice forces in degrees; null when not converged.
    #[schema(examples(22.432))]
    #[schema(required = true)]
    pub theta_deg: Option<f64>,
    /// Bishop's simplified factor of safety (θ = 0, moment equation); null when it has no root.
    #[schema(examples(1.0397))]
    #[schema(required = true)]
    pub bishop_factor_of_safety: Option<f64>,
    /// Radius of the slip circle; null for a polyline surface.
    #[schema(examples(64.4875))]
    #[schema(required = true)]
    pub radius: Option<f64>,
    /// The slip circle on the ground; null for a polyline surface.
    #[schema(required = true)]
    pub circle: Option<CircleOutDto>,
    /// The slip surface as cut: the slice bases' end points, left to right (a tension crack
    /// adds the top of its vertical face).
    pub surface: Vec<PointDto>,
    /// Number of slices used.
    pub slice_count: usize,
    /// Per-slice geometry and forces (empty when not converged).
    pub slices: Vec<SliceDto>,
    /// The resisting total: Σ (c' + σ'·tan φ')·l, the shear strength available along the slip
    /// surface; null without slice forces.
    #[schema(required = true)]
    pub total_shear_strength: Option<f64>,
    /// The driving total: Σ S, the shear mobilised along the slip surface (total_shear_strength
    /// / F); null without slice forces.
    #[schema(required = true)]
    pub total_mobilised_shear: Option<f64>,
    /// Line of thrust on the interior slice boundaries (empty when not converged).
    pub thrust_line: Vec<BoundaryThrustPointDto>,
    /// Line of thrust of the effective inter-slice forces (the total less the pore water's
    /// push on each boundary, Spencer 1973); `force` is the effective force's magnitude.
    pub effective_thrust_line: Vec<BoundaryThrustPointDto>,
    /// Newton iterations (plus fallback evaluations).
    pub iterations: usize,
    /// Rounds of solving until every base's strength sat on its nonlinear envelope at its own
    /// σ′ₙ (model §8); absent without such an envelope.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub strength_iterations: Option<usize>,
    /// Largest scaled residual of the two equations (force/ΣW, moment/(ΣW·R)).
    #[schema(required = true)]
    pub residual: Option<f64>,
    /// Things the engineer should look at, each with a `code`, a `message` and the slices or
    /// boundaries it speaks of: small m_α, tension at the base, a thrust line outside the mass,
    /// no solution, a search's doubts.
    pub warnings: Vec<Warning>,
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
    /// With `methods`: each method's F for the same slices.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub methods: Option<MethodsDto>,
    /// The accuracy of F: the slices answered and the estimated discretisation error
    /// |F(n) − F(∞)|/F (from F at n, 2n and 4n slices; null where it cannot be estimated).
    pub accuracy: AccuracyOutDto,
    /// With `slice_tolerance`: F at each number of slices tried, the last one answered.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slice_refinement: Option<Vec<SliceRefinementDto>>,
    /// The details `include` left out (returned empty, `grid` absent); empty by default.
    pub omitted: Vec<SlopeDetailDto>,
    /// With `section.supports`: each support against the answered slip surface (where it
    /// crosses, its force per unit width, what limits it).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub supports: Vec<super::supports::SupportOutDto>,
    /// With `design`: the partial factors applied, F on the design values, the over-design
    /// factor and whether it is verified.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub design: Option<super::design::DesignOutDto>,
    /// With `section.drawdown`: F of each stage on the answered surface, the stage answered,
    /// and the slices in soils that do not drain.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drawdown: Option<super::drawdown::DrawdownOutDto>,
    /// With `probabilistic`: the study's probability of failure, statistics and histogram.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub probabilistic: Option<crate::study::response::ProbabilisticOutDto>,
    /// With `sensitivity`: F at each value of each variable.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sensitivity: Option<crate::study::response::SensitivityOutDto>,
}

/// One step of the slice refinement.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SliceRefinementDto {
    /// Number of slices.
    pub slices: usize,
    /// F with that many slices; null where the equations had no solution.
    #[schema(required = true)]
    pub factor_of_safety: Option<f64>,
}

impl SpencerResponse {
    /// The answer with only the details of `include` (all when `None`); the totals and every
    /// headline figure stay.
    pub fn with_details(mut self, include: Option<&[SlopeDetailDto]>) -> Self {
        let Some(include) = include else {
            return self;
        };
        for detail in SlopeDetailDto::ALL {
            if include.contains(&detail) {
                continue;
            }
            match detail {
                SlopeDetailDto::Slices => self.slices = Vec::new(),
                SlopeDetailDto::Surface => self.surface = Vec::new(),
                SlopeDetailDto::ThrustLine => self.thrust_line = Vec::new(),
                SlopeDetailDto::EffectiveThrustLine => self.effective_thrust_line = Vec::new(),
                SlopeDetailDto::Grid => self.grid = None,
            }
            self.omitted.push(detail);
        }
        self
    }

    /// The answer to a solved request.
    pub fn new(solved: &SolvedSlope) -> Self {
        let (problem, solution) = (&solved.problem, &solved.solution);
        let (converged, status, has_forces) = status_of(solution);
        let warnings = warnings(solved);
        let model = problem.model();
        let to_x = |x: f64| problem.request_x(x);
        let slices = if has_forces {
            slice_dtos(&model, solution, &to_x)
        } else {
            Vec::new()
        };
        let (total_shear_strength, total_mobilised_shear) = shear_totals(&slices);
        let circle = circle_out(problem);
        let surface = problem.surface();
        let Analysed::Section(section) = problem;
        SpencerResponse {
            converged,
            status,
            factor_of_safety: solution.factor_of_safety,
            theta_deg: solution.theta_rad.map(f64::to_degrees),
            bishop_factor_of_safety: solution.bishop_factor_of_safety,
            radius: circle.as_ref().map(|c| c.radius),
            circle,
            surface: surface.into_iter().map(point).collect(),
            slice_count: model.slices.len(),
            slices,
            total_shear_strength,
            total_mobilised_shear,
            thrust_line: thrust_points(problem, &solution.thrust_line),
            effective_thrust_line: thrust_points(problem, &solution.effective_thrust_line),
            iterations: solution.iterations,
            strength_iterations: (solution.strength.rounds > 0).then_some(solution.strength.rounds),
            residual: solution.residual,
            warnings,
            solve_time_ms: solved.solve_time_ms,
            search: solved.search.as_ref().map(search_out),
            grid: solved.search.as_ref().map(grid_out),
            methods: solved
                .methods
                .as_ref()
                .map(|m| MethodsDto::new(m, &solved.critical)),
            curves: solved.curves.as_ref().map(|c| CurvesDto {
                theta_deg: c.theta_deg.clone(),
                force_factor: c.force_factor.clone(),
                moment_factor: c.moment_factor.clone(),
            }),
            accuracy: AccuracyOutDto {
                slices: solved.accuracy.slices,
                discretisation_error: solved.accuracy.discretisation_error,
            },
            slice_refinement: solved.refinement.as_ref().map(refinement_out),
            omitted: Vec::new(),
            supports: super::supports::supports_out(
                &section.supports(),
                section.section().supports(),
            ),
            design: solved.design.as_ref().map(super::design::design_out),
            drawdown: section.drawdown().map(super::drawdown::drawdown_out),
            probabilistic: solved
                .studies
                .probabilistic
                .as_ref()
                .map(|(p, _)| p.clone()),
            sensitivity: solved.studies.sensitivity.clone(),
        }
    }
}

/// A line of thrust as answered, in the request's x.
fn thrust_points(problem: &Analysed, points: &[ThrustPoint]) -> Vec<BoundaryThrustPointDto> {
    points
        .iter()
        .map(|t| BoundaryThrustPointDto {
            boundary: t.boundary,
            x: problem.request_x(t.x),
            y: t.y,
            force: t.force,
            inside_slice: t.is_inside_slice,
        })
        .collect()
}

/// A search's grid of F, relative to the lower end and absolute.
fn grid_out(search: &SearchReport) -> GridDto {
    GridDto {
        xs: search.grid.xs.clone(),
        ys: search.grid.ys.clone(),
        factor_of_safety: search.grid.factors.clone(),
        x_absolute: search.grid.xs.iter().map(|x| x + search.origin.0).collect(),
        y_absolute: search.grid.ys.iter().map(|y| y + search.origin.1).collect(),
    }
}

/// The slice refinement's steps: F at each number of slices tried.
fn refinement_out(refinement: &Refinement) -> Vec<SliceRefinementDto> {
    refinement
        .steps
        .iter()
        .map(|s| SliceRefinementDto {
            slices: s.slices,
            factor_of_safety: s.factor_of_safety,
        })
        .collect()
}

/// The slices' available and mobilised shear forces summed (none without slices).
fn shear_totals(slices: &[SliceDto]) -> (Option<f64>, Option<f64>) {
    let totals =
        |f: fn(&SliceDto) -> f64| (!slices.is_empty()).then(|| slices.iter().map(f).sum::<f64>());
    (
        totals(|s| s.available_shear_strength * s.base_length),
        totals(|s| s.shear_force),
    )
}

/// Whether the answer converged, its status, and whether it has slice forces: converged only
/// where every nonlinear strength settled on its envelope.
fn status_of(solution: &SpencerSolution) -> (bool, SpencerStatusDto, bool) {
    match solution.status {
        SpencerStatus::Converged => (solution.strength.settled, SpencerStatusDto::Converged, true),
        SpencerStatus::NoSolution => (false, SpencerStatusDto::NoSolution, false),
        SpencerStatus::MomentOnly => (false, SpencerStatusDto::MomentOnly, true),
        SpencerStatus::Unphysical => (false, SpencerStatusDto::Unphysical, false),
    }
}

/// A line of `/slope/spencer/stream`: progress, then the answer or its problem.
#[derive(Debug, Serialize, ToSchema)]
#[serde(untagged)]
pub enum SpencerStreamLine {
    /// How far the studies have come.
    Progress(crate::study::stream::ProgressLine),
    /// The answer, the last line.
    Answer(Box<SpencerResponse>),
    /// The problem of a study stopped after the stream began, the last line.
    Problem(crate::error::Problem),
}
