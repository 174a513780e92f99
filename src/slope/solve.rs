//! The Spencer routes' one pipeline: a validated plan → the analysis on the pool within the
//! request's budget → the solved slope every answer (JSON, CSV, SVG, report) is built from; a
//! stage that stopped without an answer becomes the 422 naming the field that sets its work.

use thrustline_solver::slope::analysis::{analyse, SlopeOutcome, SlopePlan, SlopeStage, Target};
use thrustline_solver::slope::Sliced;

use std::sync::Arc;

use super::request::SpencerRequest;
use super::solved::SolvedSlope;
use super::study;
use crate::error::ApiError;
use crate::pool::Cost;
use crate::state::AppState;
use crate::stop::Work;
use crate::study::run::Tally;

/// A request read into what runs: the analysis' plan and its studies.
pub struct Prepared {
    plan: SlopePlan,
    studies: Option<crate::study::Study>,
}

/// Validates the request and its studies (its `body` as sent): every 4xx of the input.
pub fn prepare(request: &SpencerRequest, body: &serde_json::Value) -> Result<Prepared, ApiError> {
    Ok(Prepared {
        plan: request.validate()?,
        studies: study::plan(request, body)?,
    })
}

/// Validates the request (its `body` as sent) and analyses it ([`prepare`], [`run`]).
pub async fn solve(
    state: &AppState,
    request: &SpencerRequest,
    body: &serde_json::Value,
    tally: Arc<Tally>,
) -> Result<SolvedSlope, ApiError> {
    run(state, prepare(request, body)?, tally).await
}

/// Analyses the plan on the pool within the solve time limit, then its studies within the same
/// budget; a stage that stopped without an answer becomes the outcome rule's 422 naming the
/// field that sets the work (503 when other solves ran beside it, [`AppState::refuse`]).
/// `tally` counts the studies' analyses as they finish.
pub async fn run(
    state: &AppState,
    Prepared { plan, studies }: Prepared,
    tally: Arc<Tally>,
) -> Result<SolvedSlope, ApiError> {
    tally.expect(studies.as_ref().map_or(0, crate::study::analyses));
    let is_simple_search = matches!(plan.target, Target::SimpleSearch { .. });
    let by_accuracy = plan.relative_error.is_some();
    // One surface at a stated slice count is milliseconds; searches and accuracy targets run
    // in the heavy lane. Neither takes much memory (slices are capped at 10,000).
    let cost = match (&plan.target, by_accuracy, &studies) {
        (Target::Surface(_), false, None) => Cost::LIGHT,
        _ => Cost::HEAVY,
    };
    let ran = state
        .pool
        .run_budgeted(state.solve_time_limit, cost, move |budget| {
            let outcome = analyse(&plan, budget)?;
            let studied = match (&outcome, &studies) {
                (SlopeOutcome::Answered(answer), Some(s)) => {
                    Some(study::run(s, answer, budget, &tally))
                }
                _ => None,
            };
            Ok::<_, thrustline_solver::slope::SlopeError>((outcome, studied))
        })
        .await?;
    let (outcome, studied) = ran.value?;
    let advice = "use fewer samples or points, surface: fixed, or a smaller search";
    let studies = studied
        .transpose()
        .map_err(|stopped| crate::study::refusal(state, stopped, advice, ran.shared))?;
    let answer = match outcome {
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
        studies: studies.unwrap_or_default(),
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
