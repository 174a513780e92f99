//! Studies on the live-load route (model §9.2–9.3): how a sample of the request is analysed.
//!
//! A sample is the request as JSON with the study's values written in, read and validated as a
//! request and analysed as the route's plan says (a rolling load at every stop; the critical
//! position's refinement is the deterministic answer's alone). Its answer is λ; an arch whose
//! dead load is not carried fails without any live load (λ = 0), and one that no finite live
//! load collapses has no λ (counted unsolved, neither safe nor failed).

use std::sync::Arc;

use serde_json::Value;
use thrustline_solver::arch::analysis::{analyse, ArchPlan, ArchStatus};
use thrustline_solver::arch::LimitStatus;
use thrustline_solver::budget::Budget;

use super::input::ArchInput;
use super::request::LiveLoadRequest;
use super::solve::{solve_studied, StudyJob};
use super::solved::SolvedArch;
use crate::error::ApiError;
use crate::state::AppState;
use crate::study::request::StudySurfaceDto;
use crate::study::run::{Sampled, Tally};
use crate::study::Study;

/// A live-load request read into what runs: its input and its studies.
pub struct PreparedLive {
    input: ArchInput,
    plan: ArchPlan,
    study: Option<Study>,
}

/// Validates a live-load request and its studies (its `body` as sent): every 4xx of the input.
pub fn prepare_live(request: &LiveLoadRequest, body: &Value) -> Result<PreparedLive, ApiError> {
    let (input, analysis) = request.validate()?;
    Ok(PreparedLive {
        input,
        plan: analysis,
        study: plan(request, body)?,
    })
}

/// Solves a prepared request and its studies on the pool within one budget; `tally` counts the
/// studies' analyses as they finish.
pub async fn run_live(
    state: &AppState,
    prepared: PreparedLive,
    tally: Arc<Tally>,
) -> Result<SolvedArch, ApiError> {
    let PreparedLive { input, plan, study } = prepared;
    let job = study.map(|study| {
        tally.expect(crate::study::analyses(&study));
        job(study, tally)
    });
    solve_studied(state, input, plan, job).await
}

/// The request's studies, checked against its `body` as sent (None without any).
pub fn plan(request: &LiveLoadRequest, body: &Value) -> Result<Option<Study>, ApiError> {
    let methods = [
        (
            "probabilistic.method",
            request.probabilistic.as_ref().and_then(|p| p.method),
        ),
        (
            "sensitivity.method",
            request.sensitivity.as_ref().and_then(|s| s.method),
        ),
    ];
    if let Some((field, _)) = methods.iter().find(|(_, m)| m.is_some()) {
        return Err(ApiError::invalid(
            *field,
            "is for slopes: an arch study answers its load factor λ",
        ));
    }
    if let Some(p) = &request.probabilistic {
        if p.surface == Some(StudySurfaceDto::Search) {
            return Err(ApiError::invalid(
                "probabilistic.surface",
                "an arch has no surface to search: leave it out (each sample is analysed under \
                 the stated loads)",
            ));
        }
    }
    crate::study::plan::<LiveLoadRequest>(
        body,
        (request.probabilistic.as_ref(), request.sensitivity.as_ref()),
        (&["include"], request.design.is_some()),
    )
}

/// The studies as the job the route's solve runs after its analysis.
fn job(study: Study, tally: Arc<Tally>) -> StudyJob {
    Box::new(move |budget: &Budget| {
        // An arch has one answer, λ: `method` is refused when the study is planned.
        let evaluate = |request: Value, _, budget: &Budget| evaluate(request, budget);
        crate::study::run(&study, &study.base, evaluate, budget, &tally)
    })
}

/// One sample: `request` read, validated and analysed; its λ.
pub fn evaluate(request: Value, budget: &Budget) -> Sampled {
    let typed: LiveLoadRequest = match serde_json::from_value(request) {
        Ok(typed) => typed,
        Err(e) => return Sampled::Refused(e.to_string()),
    };
    let (input, plan) = match typed.validate() {
        Ok(input) => input,
        Err(e) => return Sampled::Refused(e.to_string()),
    };
    // A sample is the plan's programme alone: the refinement of the critical position and the
    // bonded-ring comparison are the deterministic answer's.
    let plan = ArchPlan {
        refine: None,
        bonded: None,
        ..plan
    };
    match analyse(&input.problem, &plan, budget) {
        Ok(outcome) if outcome.stop.is_finished() => match outcome.status {
            ArchStatus::Limit(LimitStatus::Solved) => outcome
                .solution
                .load_factor
                .map_or(Sampled::Unsolved, Sampled::Solved),
            ArchStatus::Limit(LimitStatus::DeadLoadNotCarried) => Sampled::Solved(0.0),
            _ => Sampled::Unsolved,
        },
        Ok(_) => Sampled::Unsolved,
        Err(e) => Sampled::Refused(e.to_string()),
    }
}
