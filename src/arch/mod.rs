//! `POST /arch/dead-load` and `POST /arch/live-load`: limit analysis of rigid-block arches
//! (Livesley 1978; model §1, §3).
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
pub mod material;
pub mod mechanism;
pub mod minimum_thickness;
pub mod request;
pub mod response;
pub mod rolling;
pub mod tables;

use axum::extract::State;
use thrustline_solver::arch::analysis::{analyse, ArchOutcome, ArchPlan, Friction, Programme};
use thrustline_solver::arch::memory::{memory_bound, on_chain};
use thrustline_solver::arch::refine::refine_critical;
use thrustline_solver::arch::{ArchError, ArchProblem};
use thrustline_solver::budget::Budget;

use crate::error::{ApiError, ProblemResponses};
use crate::extract::ApiJson;
use crate::pool::Cost;
use crate::stop::Work;
use crate::svg::Svg;
use crate::table::{Answer, CsvTable};
use crate::AppState;
use input::ArchInput;
use request::{DeadLoadRequest, LiveLoadRequest};
use response::{ArchStatusDto, DeadLoadResponse, LiveLoadResponse, SolvedArch};
use rolling::Axles;
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
        ("milankovitch_stands" = (summary = "Milankovitch's semicircle, N = 1800, D = 1.0748: stands, λ₀ = 1",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0748, "voussoirs": 1800}}))),
        ("milankovitch_falls" = (summary = "The same, D = 1.0747: λ₀ = 0, five hinges",
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
        ("filled_bridge" = (summary = "A thin semicircle that stands only with its fill, a wheel on the road dispersed at 30°: λ = 1.5349",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
                           "fill": {"unit_weight": 1.8, "surface": 11.5, "dispersal_angle_deg": 30.0},
                           "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}]}))),
        ("rolling_axles" = (summary = "Two axles rolled across the filled arch: λ at 101 stops, the critical one answered (λ = 0.6413)",
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

/// Which of Livesley's two programmes a route asks for.
#[derive(Debug, Clone, Copy)]
enum Problem {
    DeadLoad,
    LiveLoad,
}

/// The plan of a validated request: the programme (a rolling load's stops for a live load that
/// rolls: moved out of the input, which keeps the positions; a thousand stops of a long chain's
/// loads are tens of MB) and the treatment of friction.
fn plan(which: Problem, input: &mut ArchInput) -> ArchPlan {
    let programme = match (which, input.rolling.as_mut()) {
        (Problem::DeadLoad, _) => Programme::DeadLoad,
        (Problem::LiveLoad, Some(rolling)) => {
            Programme::Rolling(std::mem::take(&mut rolling.loads))
        }
        (Problem::LiveLoad, None) => Programme::LiveLoad,
    };
    let friction = if input.non_associative {
        Friction::NonAssociative
    } else {
        Friction::Checked
    };
    ArchPlan {
        programme,
        friction,
        settings: input.settings.clone(),
    }
}

/// `refine_critical` narrows the critical position to this fraction of the stop spacing.
const REFINED_TO: f64 = 1e-3;

/// Chains of up to this many blocks, without a rolling load or the friction iteration, are
/// light (a few milliseconds: docs/performance.md).
const LIGHT_CHAIN_BLOCKS: usize = 1000;

/// What the analysis will take; 422 naming the geometry when its memory bound is over what one
/// solve may have (`THRUSTLINE_SOLVE_MEMORY_MIB`), with the most blocks that would fit.
fn cost(state: &AppState, input: &ArchInput, plan: &ArchPlan) -> Result<Cost, ApiError> {
    let problem = &input.problem;
    let memory = memory_bound(problem, plan);
    let limit = state.pool.memory_limit();
    if memory > limit {
        let blocks = problem.assembly().blocks.len();
        // The bound is linear in the blocks' interfaces: the share that fits.
        let fitting = (blocks as f64 * limit as f64 / memory as f64).floor();
        return Err(ApiError::invalid(
            "geometry",
            format!(
                "{blocks} blocks would take up to {} MiB to solve with these options, over the \
                 {} MiB one solve may take: use about {fitting} blocks or fewer (fewer \
                 voussoirs, rings or spans), or no crushing, rolling load or friction iteration",
                memory.div_ceil(1 << 20),
                limit >> 20,
            ),
        ));
    }
    let light = on_chain(problem, plan)
        && problem.assembly().blocks.len() <= LIGHT_CHAIN_BLOCKS
        && plan.friction != Friction::NonAssociative
        && !matches!(plan.programme, Programme::Rolling(_));
    Ok(Cost { light, memory })
}

/// Analyses the request on the pool within the solve time limit; a stop at the limit becomes
/// the outcome rule's 422 naming `geometry` (503 when other solves ran beside it).
async fn solve(
    state: &AppState,
    which: Problem,
    mut input: ArchInput,
) -> Result<SolvedArch, ApiError> {
    let plan = plan(which, &mut input);
    let cost = cost(state, &input, &plan)?;
    let problem = input.problem.clone();
    let extra = Extra {
        // With refine_critical: the axles and the stops, to search between them.
        refine: input.rolling.as_ref().and_then(|r| {
            let axles = r.refine.clone()?;
            (r.positions.len() > 1).then(|| (axles, r.positions.clone()))
        }),
        bonded: input.bonded.take(),
    };
    let ran = state
        .pool
        .run_budgeted(state.solve_time_limit, cost, move |budget| {
            run(&problem, &plan, extra, budget)
        })
        .await?;
    let (outcome, bonded_load_factor) = ran.value?;
    tracing::info!(
        problem = ?which,
        blocks = outcome.problem.assembly().blocks.len(),
        interfaces = outcome.problem.assembly().interfaces.len(),
        iterations = outcome.solution.iterations,
        solve_ms = ran.elapsed.as_secs_f64() * 1e3,
        load_factor = outcome.solution.load_factor,
        "arch solved"
    );
    let status = ArchStatusDto::try_from(outcome.status)
        .ok()
        .filter(|_| outcome.stop.is_finished());
    let Some(status) = status else {
        let work = Work {
            field: "geometry",
            advice: "use fewer blocks, the chain formulation or a larger solver_tolerance",
            no_candidate: "",
        };
        return Err(state.refuse(outcome.stop, work, ran.shared));
    };
    let mut solved = SolvedArch::new(input, outcome, status);
    solved.bonded_load_factor = bonded_load_factor;
    Ok(solved)
}

/// What a request adds to its plan's analysis.
struct Extra {
    /// `refine_critical`: the axles and the stops.
    refine: Option<(Axles, Vec<f64>)>,
    /// Locked rings: the bonded single ring.
    bonded: Option<ArchProblem>,
}

/// What runs on the pool: the plan's analysis; a rolling load's critical position narrowed
/// when asked; where the rings lock, the bonded single ring's λ (associative) to compare.
fn run(
    problem: &ArchProblem,
    plan: &ArchPlan,
    extra: Extra,
    budget: &Budget,
) -> Result<(ArchOutcome, Option<f64>), ArchError> {
    let mut outcome = analyse(problem, plan, budget)?;
    if let Some((axles, positions)) = extra.refine {
        let spacing =
            (positions[positions.len() - 1] - positions[0]).abs() / (positions.len() - 1) as f64;
        outcome = refine_critical(
            outcome,
            (problem, plan),
            &positions,
            REFINED_TO * spacing,
            &|x| axles.loads_at(x),
            budget,
        )?;
    }
    let compare = outcome.stop.is_finished()
        && outcome.solution.load_factor.is_some()
        && plan.programme == Programme::LiveLoad;
    let bonded = match extra.bonded.filter(|_| compare) {
        Some(bonded) => {
            let at = ArchPlan {
                friction: Friction::Associative,
                ..plan.clone()
            };
            let single = analyse(&bonded, &at, budget)?;
            single
                .stop
                .is_finished()
                .then_some(single.solution.load_factor)
                .flatten()
        }
        None => None,
    };
    Ok((outcome, bonded))
}
