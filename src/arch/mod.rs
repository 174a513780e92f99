//! `POST /arch/dead-load` and `POST /arch/live-load`: limit analysis of rigid-block arches
//! (Livesley 1978; SPEC §1, §3).
//!
//! Blocks and interfaces are numbered from 1 in requests and responses, in order of increasing
//! polar angle for circular arches (interface 1 at the right springing), as the thesis prints
//! them. Angles are polar angles in degrees (for block chains: the direction of the joint from
//! its intrados to its extrados end).

pub mod assembly;
pub mod codes;
pub mod drawing;
pub mod fill;
pub mod geometry;
pub mod input;
pub mod mechanism;
pub mod minimum_thickness;
pub mod request;
pub mod response;
pub mod tables;

use axum::extract::State;
use fill::{Rolling, RollingOutDto};
use thrustline_solver::arch::non_associative::NonAssociative;
use thrustline_solver::arch::{
    relieve_squeeze, solve_dead_load, solve_dead_load_non_associative, solve_live_load,
    solve_live_load_non_associative, sweep_live_loads, thrust_line, ArchError, LimitSolution,
    LimitStatus, SolverFailure, StateOf,
};

use crate::error::{ApiError, ApiJson, ProblemResponses};
use crate::svg::Svg;
use crate::table::{Answer, CsvTable};
use crate::AppState;
use input::ArchInput;
use request::{DeadLoadRequest, LiveLoadRequest};
use response::{ArchStatusDto, DeadLoadResponse, LiveLoadResponse, SolvedArch};
use tables::{arch_table, ArchTableQuery};

/// Dead-load limit analysis (Livesley's λ₀).
///
/// Whether the structure carries its own weight: λ₀ = 1 when it does, below 1 (0 under Heyman's
/// limits) when it does not, with the collapse mechanism, its hinges and the line of thrust.
/// Solver statuses other than `solved` carry no factor; a solve stopped at the time limit is
/// 422 naming `geometry`.
#[utoipa::path(
    post,
    path = "/arch/dead-load",
    tag = "arch",
    request_body(content = DeadLoadRequest, examples(
        ("milankovitch_stands" = (summary = "Milankovitch's semicircle, N = 1800, D = 1.0748: stands (SPEC §1.4)",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0748, "voussoirs": 1800}}))),
        ("milankovitch_falls" = (summary = "The same, D = 1.0747: five hinges (SPEC §1.4)",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0747, "voussoirs": 1800}})))
    )),
    params(ArchTableQuery),
    responses(
        (status = 200, description = "The dead-load factor, mechanism and thrust line; with `Accept: text/csv`, the `table` asked for", content(
            (DeadLoadResponse = "application/json"),
            (String = "text/csv")
        )),
        ProblemResponses,
    )
)]
pub async fn dead_load(
    State(state): State<AppState>,
    CsvTable(table): CsvTable<ArchTableQuery>,
    ApiJson(request): ApiJson<DeadLoadRequest>,
) -> Result<Answer<DeadLoadResponse>, ApiError> {
    let solved = solve(
        &state,
        Problem::DeadLoad,
        request.validate(state.solve_time_limit_secs())?,
    )
    .await?;
    let answer = DeadLoadResponse::new(&solved);
    if let Some(table) = table {
        return arch_table(&answer.outcome, None, table).map(Answer::Csv);
    }
    Ok(Answer::Json(answer))
}

/// Dead-load limit analysis drawn: voussoirs, thrust line, hinges, mechanism.
///
/// The same request and solve as `/arch/dead-load`, answered as an SVG picture.
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
    let solved = solve(
        &state,
        Problem::DeadLoad,
        request.validate(state.solve_time_limit_secs())?,
    )
    .await?;
    let title = match solved.solution.load_factor {
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
    Ok(Svg(drawing::draw(&solved, &title)))
}

/// Live-load limit analysis (Livesley's λ).
///
/// The factor on the live loads at collapse, given that the dead load is carried, with the
/// mechanism and the line of thrust; `load_factor: null` with `solver.status`
/// `dead_load_not_carried` or `unbounded` when there is none.
#[utoipa::path(
    post,
    path = "/arch/live-load",
    tag = "arch",
    request_body(content = LiveLoadRequest, examples(
        ("quarter_span_load" = (summary = "A unit load near the quarter span of a semicircle (λ = 22.9969)",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
                           "loads": [{"block": 26, "fy": -1.0}]}))),
        ("filled_bridge" = (summary = "A thin semicircle that stands only with its fill, a wheel on the road dispersed at 30°",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
                           "fill": {"unit_weight": 1.8, "surface": 11.5, "dispersal_angle_deg": 30.0},
                           "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}]}))),
        ("rolling_axles" = (summary = "Two axles rolled across the filled arch: λ at 101 stops, the critical one answered",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
                           "fill": {"unit_weight": 1.8, "surface": 11.5},
                           "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}],
                                       "x_start": -12.0, "x_end": 10.0, "positions": 101}})))
    )),
    params(ArchTableQuery),
    responses(
        (status = 200, description = "The live-load factor, mechanism and thrust line; `stable: false` and `load_factor: null` when the dead load is not carried; with `Accept: text/csv`, the `table` asked for", content(
            (LiveLoadResponse = "application/json"),
            (String = "text/csv")
        )),
        ProblemResponses,
    )
)]
pub async fn live_load(
    State(state): State<AppState>,
    CsvTable(table): CsvTable<ArchTableQuery>,
    ApiJson(request): ApiJson<LiveLoadRequest>,
) -> Result<Answer<LiveLoadResponse>, ApiError> {
    let solved = solve(
        &state,
        Problem::LiveLoad,
        request.validate(state.solve_time_limit_secs())?,
    )
    .await?;
    let answer = LiveLoadResponse::new(&solved);
    if let Some(table) = table {
        return arch_table(&answer.outcome, answer.rolling.as_ref(), table).map(Answer::Csv);
    }
    Ok(Answer::Json(answer))
}

/// Live-load limit analysis drawn: voussoirs, loads, thrust line, hinges, mechanism.
///
/// The same request and solve as `/arch/live-load`, answered as an SVG picture.
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
    let solved = solve(
        &state,
        Problem::LiveLoad,
        request.validate(state.solve_time_limit_secs())?,
    )
    .await?;
    let title = match (
        solved.solution.load_factor,
        solved.solution.dead_load_carried,
    ) {
        (Some(f), _) => format!("Live load: λ = {f:.4}"),
        (None, Some(false)) => "Live load: the dead load is not carried".to_owned(),
        (None, _) => "Live load: no collapse load".to_owned(),
    };
    Ok(Svg(drawing::draw(&solved, &title)))
}

/// Which of Livesley's two programmes.
#[derive(Debug, Clone, Copy)]
enum Problem {
    DeadLoad,
    LiveLoad,
}

/// Solves on the pool; the solver's time limit becomes the README's outcome rule's 422 (or 503
/// when other solves ran beside it).
async fn solve(state: &AppState, which: Problem, input: ArchInput) -> Result<SolvedArch, ApiError> {
    let ran = state
        .pool
        .run(move || {
            let mut input = input;
            let mut rolling = None;
            let (mut solution, friction) = match (which, input.rolling.take()) {
                (Problem::LiveLoad, Some(stops)) => match roll(&mut input, &stops) {
                    Ok((solution, curve)) => {
                        rolling = Some(curve);
                        // The friction check at the critical stop, when it slides.
                        let check = solution
                            .mechanism
                            .as_ref()
                            .is_some_and(|m| m.involves_friction())
                            .then(|| {
                                solve_live_load_non_associative(
                                    &input.problem,
                                    &input.settings,
                                    true,
                                )
                            })
                            .and_then(Result::ok);
                        (Ok(solution), check)
                    }
                    Err(e) => (Err(e), None),
                },
                _ => solve_with_friction(which, &input),
            };
            if let (Ok(solution), false) = (&mut solution, input.non_associative) {
                // A state squeezed by a self-stress (assemblies) is relieved (README,
                // Assemblies); a non-associative answer keeps its iteration's state.
                let of = match which {
                    Problem::DeadLoad => StateOf::DeadLoad,
                    Problem::LiveLoad => StateOf::LiveLoad,
                };
                relieve_squeeze(&input.problem, &input.settings, of, solution);
            }
            (input, solution, rolling, friction)
        })
        .await?;
    let (elapsed, shared) = (ran.elapsed, ran.shared);
    let (input, solution, rolling, friction) = ran.value;
    let mut solution = solution?;
    tracing::info!(
        problem = ?which,
        blocks = input.problem.assembly().blocks.len(),
        iterations = solution.iterations,
        solve_ms = elapsed.as_secs_f64() * 1e3,
        load_factor = solution.load_factor,
        "arch solved"
    );
    let mut status = ArchStatusDto::try_from(solution.status).map_err(|_| {
        let error = ApiError::OverTimeLimit {
            field: "geometry".to_owned(),
            seconds: state.solve_time_limit_secs(),
            advice: "use fewer blocks, the chain formulation or a larger solver_tolerance",
            busy: None,
        };
        state.pool.judge(error, shared)
    })?;
    if input.non_associative && friction.as_ref().is_some_and(|f| !f.settled) {
        // No factor the iteration cannot vouch for; its steps are in `non_associative`.
        status = ArchStatusDto::NotSettled;
        solution.load_factor = None;
    }
    if solution.status == LimitStatus::Unbounded {
        // The state at the cap of λ (the non-associative iteration's start): not an answer.
        solution.resultants.clear();
    }
    let thrust_line = thrust_line(input.problem.assembly(), &solution.resultants);
    Ok(SolvedArch {
        input,
        solution,
        status,
        thrust_line,
        rolling,
        friction,
    })
}

/// One dead- or live-load solve; with friction, the non-associative iteration too (all of it
/// for `friction: non_associative`, whose answer it then is; otherwise only when the
/// associative mechanism slides, for `friction_may_overestimate`).
fn solve_with_friction(
    which: Problem,
    input: &ArchInput,
) -> (Result<LimitSolution, ArchError>, Option<NonAssociative>) {
    let (problem, settings) = (&input.problem, &input.settings);
    let check_only = !input.non_associative;
    // The answer's solver figures count the whole iteration (the check included).
    let pick = |o: &NonAssociative| {
        let mut solution = if input.non_associative {
            o.solution.clone()
        } else {
            o.associative.clone()
        };
        (
            solution.iterations,
            solution.programmes,
            solution.solve_time_secs,
        ) = o.totals;
        solution
    };
    match (which, problem.has_friction()) {
        (Problem::DeadLoad, true) => {
            let o = solve_dead_load_non_associative(problem, settings, check_only);
            (Ok(pick(&o)), Some(o))
        }
        (Problem::DeadLoad, false) => (Ok(solve_dead_load(problem, settings)), None),
        (Problem::LiveLoad, true) => {
            match solve_live_load_non_associative(problem, settings, check_only) {
                Ok(o) => (Ok(pick(&o)), Some(o)),
                Err(e) => (Err(e), None),
            }
        }
        (Problem::LiveLoad, false) => (solve_live_load(problem, settings), None),
    }
}

/// Solves the live load at every stop of a rolling load; the input's problem becomes the
/// critical stop's, whose solution is returned with the curve. A stop whose solve fails
/// (time) fails the whole.
fn roll(
    input: &mut ArchInput,
    stops: &Rolling,
) -> Result<(LimitSolution, RollingOutDto), ArchError> {
    let start = std::time::Instant::now();
    let sweep = sweep_live_loads(&input.problem, &input.settings, &stops.loads)?;
    let factors: Vec<Option<f64>> = sweep
        .stops
        .iter()
        .map(|s| s.as_ref().and_then(|s| s.load_factor))
        .collect();
    let first_position_ms = sweep.first_stop_secs * 1e3;
    let best = sweep.critical();
    let elapsed_ms = start.elapsed().as_secs_f64() * 1e3;
    let mut curve = RollingOutDto {
        positions: stops.positions.clone(),
        load_factor: factors,
        critical_position: best.map(|(i, _)| stops.positions[i]),
        critical_load_factor: best.map(|(_, f)| f),
        time_per_position_ms: elapsed_ms / stops.positions.len().max(1) as f64,
        first_position_ms,
    };
    let mut solutions = sweep.stops;
    let critical = best
        .filter(|_| !sweep.out_of_time)
        .and_then(|(i, _)| solutions[i].take().map(|s| (i, s)));
    if let Some((i, solution)) = critical {
        input.problem = input
            .problem
            .clone()
            .with_live_loads(stops.loads[i].clone())?;
        return Ok((solution, curve));
    }
    // Out of time, or no stop collapses: the first loaded stop's answer (the input's problem)
    // as the sweep found it.
    let mut solution = solutions
        .into_iter()
        .flatten()
        .next()
        .map_or_else(|| solve_live_load(&input.problem, &input.settings), Ok)?;
    if sweep.out_of_time {
        // The sweep is not finished, and says so through the status.
        curve.critical_position = None;
        curve.critical_load_factor = None;
        curve.time_per_position_ms = 0.0;
        solution.status = LimitStatus::SolverFailed(SolverFailure::MaxTime);
    }
    Ok((solution, curve))
}
