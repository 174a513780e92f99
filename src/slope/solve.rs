//! The Spencer routes' one pipeline: a validated plan → the analysis on the pool within the
//! request's budget → the solved slope every answer (JSON, CSV, SVG, report) is built from; a
//! stage that stopped without an answer becomes the 422 naming the field that sets its work.

use thrustline_solver::slope::analysis::{analyse, SlopeOutcome, SlopePlan, SlopeStage, Target};
use thrustline_solver::slope::Sliced;

use super::solved::SolvedSlope;
use crate::error::ApiError;
use crate::pool::Cost;
use crate::stop::Work;
use crate::AppState;

/// Analyses the plan on the pool within the solve time limit; a stage that stopped without an
/// answer becomes the outcome rule's 422 naming the field that sets the work (503 when other
/// solves ran beside it, [`AppState::refuse`]).
pub async fn solve(state: &AppState, plan: SlopePlan) -> Result<SolvedSlope, ApiError> {
    let is_simple_search = matches!(plan.target, Target::SimpleSearch { .. });
    let by_accuracy = plan.relative_error.is_some();
    // One surface at a stated slice count is milliseconds; searches and accuracy targets run
    // in the heavy lane. Neither takes much memory (slices are capped at 10,000).
    let cost = match (&plan.target, by_accuracy) {
        (Target::Surface(_), false) => Cost::LIGHT,
        _ => Cost::HEAVY,
    };
    let ran = state
        .pool
        .run_budgeted(state.solve_time_limit, cost, move |budget| {
            analyse(&plan, budget)
        })
        .await?;
    let answer = match ran.value? {
        SlopeOutcome::Answered(answer) => *answer,
        SlopeOutcome::Stopped { stage, stop } => {
            let work = match stage {
                SlopeStage::Search if is_simple_search => Work {
                    field: "search",
                    advice: "use a smaller grid, fewer slices or no lower_end_factor_max",
                    no_candidate: "no centre in the region searched gives a circle with a \
                                   solution: widen or move the bounds (or leave them out for \
                                   automatic ones)",
                },
                SlopeStage::Search => Work {
                    field: "search",
                    advice: "use a smaller grid, fewer radii or fewer slices",
                    no_candidate: "no circle in the region searched cuts a sliding mass with a \
                                   solution: widen or move the bounds or the radii (or leave \
                                   them out)",
                },
                SlopeStage::Refinement if by_accuracy => Work {
                    field: "accuracy.relative_error",
                    advice: "ask for a larger relative_error",
                    no_candidate: "",
                },
                SlopeStage::Refinement => Work {
                    field: "slice_tolerance",
                    advice: "use a larger slice_tolerance",
                    no_candidate: "",
                },
            };
            return Err(state.refuse(stop, work, ran.shared));
        }
    };
    let solved = SolvedSlope {
        answer,
        solve_time_ms: ran.elapsed.as_secs_f64() * 1e3,
    };
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
