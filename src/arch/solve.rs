//! The arch routes' one pipeline: a validated request and its plan (the programme, the
//! treatment of friction, the stages after it) → what it will cost → the analysis on the pool
//! within the request's budget → the solved arch every answer (JSON, CSV, SVG, report) is built
//! from.

use thrustline_solver::arch::analysis::{analyse, ArchPlan, Friction, Programme};
use thrustline_solver::arch::memory::{memory_bound, on_chain};
use thrustline_solver::arch::ArchError;
use thrustline_solver::budget::Budget;

use super::input::ArchInput;
use super::solved::{ArchStatusDto, SolvedArch};
use crate::error::ApiError;
use crate::pool::Cost;
use crate::state::AppState;
use crate::stop::Work;
use crate::study::run::StudyStop;
use crate::study::StudyAnswers;

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

/// A request's studies, run after its analysis within the same budget (the route builds it:
/// the studies know how to analyse a sample of their route).
pub type StudyJob =
    Box<dyn FnOnce(&Budget) -> Result<StudyAnswers, (&'static str, StudyStop)> + Send>;

/// Analyses the request on the pool within the solve time limit; a stop at the limit becomes
/// the outcome rule's 422 naming `geometry` (503 when other solves ran beside it).
pub async fn solve(
    state: &AppState,
    input: ArchInput,
    plan: ArchPlan,
) -> Result<SolvedArch, ApiError> {
    solve_studied(state, input, plan, None).await
}

/// [`solve`], then the request's studies (`job`) within the same budget; a study stopped is
/// the outcome rule's 422 naming the field that sets its work.
pub async fn solve_studied(
    state: &AppState,
    input: ArchInput,
    plan: ArchPlan,
    job: Option<StudyJob>,
) -> Result<SolvedArch, ApiError> {
    let mut cost = cost(state, &input, &plan)?;
    cost.light &= job.is_none();
    let problem = input.problem.clone();
    // What the answer names of the plan, kept before the plan goes to the pool.
    let (is_dead_load, friction, settings) = (
        plan.programme == Programme::DeadLoad,
        plan.friction,
        plan.settings.clone(),
    );
    let ran = state
        .pool
        .run_budgeted(state.solve_time_limit, cost, move |budget| {
            let outcome = analyse(&problem, &plan, budget)?;
            let studied = match job {
                Some(job) if outcome.stop.is_finished() => Some(job(budget)),
                _ => None,
            };
            Ok::<_, ArchError>((outcome, studied))
        })
        .await?;
    let (outcome, studied) = ran.value?;
    let advice = "use fewer samples or points, or fewer blocks or stops";
    let studies = studied
        .transpose()
        .map_err(|stopped| crate::study::refusal(state, stopped, advice, ran.shared))?
        .unwrap_or_default();
    tracing::info!(
        dead_load = is_dead_load,
        blocks = outcome.problem.assembly().blocks.len(),
        interfaces = outcome.problem.assembly().interfaces.len(),
        iterations = outcome.solution.iterations,
        solve_ms = ran.elapsed.as_secs_f64() * 1e3,
        load_factor = outcome.solution.load_factor,
        "arch solved"
    );
    let status = Some(ArchStatusDto::from(outcome.status)).filter(|_| outcome.stop.is_finished());
    let Some(status) = status else {
        let work = Work {
            field: "geometry",
            advice: "use fewer blocks, the chain formulation or a larger solver_tolerance",
            no_candidate: "",
        };
        return Err(state.refuse(outcome.stop, work, ran.shared));
    };
    let mut solved = SolvedArch::new(input, outcome, status, friction, settings);
    solved.studies = studies;
    Ok(solved)
}
