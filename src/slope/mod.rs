//! `POST /slope/spencer`: Spencer's method for one slip circle or the critical one (SPEC §2, §3).
//!
//! [`request`] holds the types clients send, [`input`] validates them once into the solver's
//! inputs, the handlers here solve on the blocking pool, [`response`] builds the answer whole
//! and [`drawing`] the picture, both from the solver's results. Slices are numbered from 1 at
//! the lower end of the slip surface, as the thesis prints them.

pub mod analysed;
pub mod contours;
pub mod drawing;
pub mod fills;
pub mod input;
pub mod methods;
pub mod outputs;
pub mod report;
pub mod request;
pub mod response;
pub mod section;
pub mod tables;
pub mod warnings;

use std::time::{Duration, Instant};

use axum::extract::State;
use thrustline_solver::slope::{
    factor_curves_around, refine_slices, search_critical_circle, solve_spencer, RefinementSettings,
    RefinementStatus, SearchSettings, SearchStatus, Sliced, SlopeProblem, SolverFailure,
    SpencerSettings,
};

use crate::error::{ApiError, ApiJson, ProblemResponses};
use crate::limits::MAX_SLICES;
use crate::svg::Svg;
use crate::table::{Answer, CsvTable};
use crate::AppState;
use analysed::Analysed;
use input::{SectionSearch, SpencerInput, Target};
use report::SearchReport;
use report::{Refinement, SolvedSlope};
use request::SpencerRequest;
use response::SpencerResponse;
use tables::{slope_table, SlopeTableQuery};
use thrustline_solver::slope::section::noncircular::search_noncircular;
use thrustline_solver::slope::section::search::{search_circles, CircleSearchSettings};
use thrustline_solver::slope::section::{Polyline, SectionProblem, SlipShape};

/// Spencer's method for one slip surface, or the critical circle.
///
/// F and θ satisfying force and moment equilibrium (Spencer 1967/1973), Bishop's F, the slices
/// and the line of thrust. The ground is the simple `slope` with its `soil`, or any `section`
/// (layers, bedrock, water, loads, tension crack); give exactly one of `circle` (relative to the
/// lower end on the simple slope, or absolute: `centre` and `radius`), `surface` (any polyline)
/// and `search` (the critical circle, with the F map). `converged: false` with a status when the equations have no
/// solution; a search or refinement stopped at the time limit is 422 naming the field.
#[utoipa::path(
    post,
    path = "/slope/spencer",
    tag = "slope",
    request_body(content = SpencerRequest, examples(
        ("spencer_1967" = (summary = "Spencer's (1967) example circle: F = 1.0696, θ = 22.43° (SPEC §2.3)",
            value = json!({"slope": {"height": 30.48, "length": 60.96},
                           "circle": {"x": 9.63168, "y": 63.76416}, "slices": 100,
                           "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0,
                                    "pore_pressure_ratio": 0.5}}))),
        ("fredlund_krahn_1977" = (summary = "Fredlund & Krahn (1977) case 1, a section facing left: Spencer 2.073, Bishop 2.080 (SPEC §4.5)",
            value = json!({"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
                                       "layers": [{"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]},
                           "circle": {"centre": [120, 90], "radius": 80}, "slices": 100,
                           "methods": ["morgenstern_price", "bishop", "janbu", "ordinary"]}))),
        ("layered_section" = (summary = "Layers, bedrock, a water table, a surcharge, a line load and a water-filled tension crack (SPEC §4.1)",
            value = json!({"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
                                       "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                                                  {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
                                       "bedrock": [[-20, -12], [40, -12]],
                                       "piezometric_line": [[-20, 1], [10, 3], [40, 6]], "water_unit_weight": 9.81,
                                       "surcharges": [{"x_start": 25, "x_end": 35, "pressure": 20}],
                                       "line_loads": [{"x": 30, "fx": 0, "fy": -50}],
                                       "tension_crack": {"depth": 2.5, "water_depth": 2.5}},
                           "circle": {"centre": [12, 28], "radius": 26}, "slices": 100}))),
        ("polyline_surface" = (summary = "A non-circular slip surface through the same section as Fredlund & Krahn's",
            value = json!({"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
                                       "layers": [{"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]},
                           "surface": [[40, 62], [70, 38], [130, 22], [165, 21]], "slices": 100}))),
        ("critical_circle" = (summary = "The critical circle of the same embankment (automatic search bounds)",
            value = json!({"slope": {"height": 30.48, "length": 60.96}, "search": {}, "slices": 50,
                           "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0,
                                    "pore_pressure_ratio": 0.5}})))
    )),
    params(SlopeTableQuery),
    responses(
        (status = 200, description = "Solved, or an honest `converged: false`; with `Accept: text/csv`, the `table` asked for", content(
            (SpencerResponse = "application/json"),
            (String = "text/csv")
        )),
        ProblemResponses,
    )
)]
pub async fn spencer(
    State(state): State<AppState>,
    CsvTable(table): CsvTable<SlopeTableQuery>,
    ApiJson(request): ApiJson<SpencerRequest>,
) -> Result<Answer<SpencerResponse>, ApiError> {
    let solved = solve(&state, request.validate()?).await?;
    let answer = SpencerResponse::new(&solved).with_details(request.include.as_deref());
    if let Some(table) = table {
        return slope_table(&answer, table).map(Answer::Csv);
    }
    Ok(Answer::Json(answer))
}

/// Spencer's method drawn: embankment, slip circle and centre, slices, line of thrust, and
/// for a search the map of F over the centres.
///
/// The same request and solve as `/slope/spencer`, answered as an SVG picture.
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
) -> Result<Svg, ApiError> {
    let solved = solve(&state, request.validate()?).await?;
    let is_circle = solved.problem.circle().is_some();
    let title = match (solved.search.is_some(), is_circle) {
        (true, _) => "Spencer's method: the critical slip circle",
        (false, true) => "Spencer's method: one slip circle",
        (false, false) => "Spencer's method: one slip surface",
    };
    Ok(Svg(drawing::draw(&solved, title)))
}

async fn solve(state: &AppState, input: SpencerInput) -> Result<SolvedSlope, ApiError> {
    let time_limit = state.solve_time_limit;
    let ran = state
        .pool
        .run(move || solve_blocking(input, time_limit))
        .await?;
    let mut solved = ran.value.map_err(|e| state.pool.judge(e, ran.shared))?;
    solved.solve_time_ms = ran.elapsed.as_secs_f64() * 1e3;
    tracing::info!(
        slices = solved.problem.slice_count(),
        iterations = solved.solution.iterations,
        evaluations = solved.search.as_ref().map(|s| s.evaluations),
        solve_ms = solved.solve_time_ms,
        factor_of_safety = solved.solution.factor_of_safety,
        "spencer solved"
    );
    Ok(solved)
}

/// With automatic search bounds, circles beyond this many times the embankment's larger
/// dimension are not candidates.
const MAX_RADIUS_OVER_SIZE: f64 = 50.0;

/// Runs on the blocking pool: the search if asked, then the full solution of the circle (refined
/// if asked), then the curves if asked. A solver stopped by the time limit is the README's
/// outcome rule's 422 naming the field that sets the work ([`crate::pool::SolvePool::judge`] makes it 503
/// when other solves ran beside it).
fn solve_blocking(input: SpencerInput, time_limit: Duration) -> Result<SolvedSlope, ApiError> {
    let deadline = Instant::now() + time_limit;
    let over_time = |field: &str, advice| ApiError::OverTimeLimit {
        field: field.to_owned(),
        seconds: time_limit.as_secs_f64(),
        advice,
        busy: None,
    };
    let spencer = SpencerSettings {
        negative_effective_stress: input.negative_effective_stress,
        ..SpencerSettings::default()
    };
    let (problem, search) =
        match input.target {
            Target::Surface(problem) => (problem, None),
            Target::Search(grid, search_problem, hard_bounds) => {
                let size = search_problem
                    .embankment
                    .height()
                    .max(search_problem.embankment.length());
                let settings = SearchSettings {
                    time_limit: Some(time_limit),
                    spencer,
                    hard_bounds,
                    // Automatic bounds may move; not to circles that dwarf the embankment.
                    max_radius: (!hard_bounds).then_some(MAX_RADIUS_OVER_SIZE * size),
                    ..SearchSettings::default()
                };
                let found = search_critical_circle(&search_problem, grid, &settings);
                let circle = match (found.status, found.circle) {
                    (SearchStatus::Found, Some(circle)) => circle,
                    (SearchStatus::SolverFailed(SolverFailure::MaxTime), _) => {
                        return Err(over_time(
                            "search",
                            "use a smaller grid, fewer slices or no lower_end_factor_max",
                        ))
                    }
                    (
                        SearchStatus::Found
                        | SearchStatus::NoValidCircle
                        | SearchStatus::SolverFailed(_),
                        _,
                    ) => return Err(ApiError::invalid(
                        "search",
                        "no centre in the region searched gives a circle with a solution: widen \
                         or move the bounds (or leave them out for automatic ones)",
                    )),
                };
                // The grid's circles start at the lower end of F_e as given (the refinement may
                // move F_e within lower_end_factor_max; the grid does not).
                let grid_lower_end = (
                    -search_problem.lower_end_factor * search_problem.embankment.height() + 0.0,
                    0.0,
                );
                let problem = SlopeProblem::new(
                    search_problem.embankment,
                    circle,
                    search_problem.slices,
                    search_problem.soil,
                    search_problem.seismic,
                    Vec::new(),
                )?;
                (
                    Analysed::Simple(problem),
                    Some(SearchReport::of_simple(&found, hard_bounds, grid_lower_end)),
                )
            }
            Target::SectionSearch(search) => {
                let settings = CircleSearchSettings {
                    deadline: Some(deadline),
                    spencer,
                    ..CircleSearchSettings::default()
                };
                let SectionSearch {
                    section,
                    region,
                    hard,
                    slices,
                    seismic,
                    noncircular,
                } = *search;
                let found = search_circles(&section, region, hard, slices, seismic, &settings);
                let circle = match (found.status, found.circle) {
                    (SearchStatus::Found, Some(circle)) => circle,
                    (SearchStatus::SolverFailed(SolverFailure::MaxTime), _) => {
                        return Err(over_time(
                            "search",
                            "use a smaller grid, fewer radii or fewer slices",
                        ))
                    }
                    _ => return Err(ApiError::invalid(
                        "search",
                        "no circle in the region searched cuts a sliding mass with a solution: \
                         widen or move the bounds or the radii (or leave them out)",
                    )),
                };
                let shape = SlipShape::Circle {
                    centre: circle.0,
                    radius: circle.1,
                };
                let mut problem = SectionProblem::new(section, shape, slices, seismic, None)?;
                let mut report = SearchReport::of_section(&found, hard);
                if let Some(noncircular) = noncircular {
                    let budget = noncircular
                        .budget
                        .and_then(|b| std::time::Instant::now().checked_add(b))
                        .map_or(deadline, |end| end.min(deadline));
                    let better = search_noncircular(
                        problem.section(),
                        &problem.surface(),
                        noncircular.vertices,
                        slices,
                        seismic,
                        &spencer,
                        Some(budget),
                    );
                    if let Some(better) = better {
                        let line = Polyline::new(better.surface.clone())
                            .map_err(|e| ApiError::invalid("search", e.to_string()))?;
                        problem = SectionProblem::new(
                            problem.section().clone(),
                            SlipShape::Polyline(line),
                            slices,
                            seismic,
                            None,
                        )?;
                        report.evaluations += better.evaluations;
                        report.path = Some(better.path);
                        report.path_ms = Some(better.path_ms);
                        report.timed_out = better.timed_out;
                    }
                }
                (Analysed::Section(Box::new(problem)), Some(report))
            }
        };
    let (problem, solution, refinement) = match input.slice_tolerance {
        None => {
            let solution = solve_spencer(&problem.model(), &spencer);
            (problem, solution, None)
        }
        Some(tolerance) => {
            let settings = RefinementSettings {
                max_slices: MAX_SLICES,
                deadline: Some(deadline),
                spencer,
                ..RefinementSettings::new(tolerance)
            };
            let refined = refine_slices(problem, &settings)?;
            let is_settled = match refined.status {
                RefinementStatus::Settled => true,
                RefinementStatus::SliceLimit => false,
                RefinementStatus::SolverFailed(_) => {
                    return Err(over_time("slice_tolerance", "use a larger slice_tolerance"))
                }
            };
            let refinement = Refinement {
                tolerance,
                steps: refined.steps,
                is_settled,
            };
            (refined.problem, refined.solution, Some(refinement))
        }
    };
    let curves = match (solution.theta_rad, input.curves) {
        (Some(theta), true) => Some(factor_curves_around(&problem.model(), theta)),
        _ => None,
    };
    let methods = (!input.methods.is_empty()).then(|| {
        methods::methods(
            &input.methods,
            &input.interslice_function,
            &problem.model(),
            &solution,
        )
    });
    Ok(SolvedSlope {
        problem,
        solution,
        search,
        curves,
        methods,
        refinement,
        solve_time_ms: 0.0,
    })
}
