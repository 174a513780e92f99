//! Studies on the Spencer route (model §9.2–9.3): how a sample of the request is analysed.
//!
//! A sample is the request as JSON with the study's values written in: read as a request,
//! validated as one, and analysed without what only the deterministic answer reports (the
//! accuracy estimate, other methods, curves). With `surface: fixed` every sample keeps the
//! deterministic answer's surface at its slice count (so a sample at the stated values is that
//! answer); with `search` each sample runs the request's search and refinement again.

use serde_json::{json, Value};
use thrustline_solver::budget::Budget;
use thrustline_solver::slope::analysis::{analyse, Analysed, SlopeAnswer, SlopeOutcome};
use thrustline_solver::slope::section::SlipShape;
use thrustline_solver::slope::spencer::SpencerStatus;
use thrustline_solver::slope::Sliced;

use super::request::SpencerRequest;
use crate::error::ApiError;
use crate::study::run::{Sampled, StudyStop, Tally};
use crate::study::{Study, StudyAnswers};

/// The request's studies, checked against its `body` as sent (None without any).
pub fn plan(request: &SpencerRequest, body: &Value) -> Result<Option<Study>, ApiError> {
    crate::study::plan::<SpencerRequest>(
        body,
        (request.probabilistic.as_ref(), request.sensitivity.as_ref()),
        // `methods` and `curves` stay: a sample is validated as the request is (an
        // `interslice_function` needs Morgenstern–Price among the methods), then runs without them.
        (&["include"], request.design.is_some()),
    )
}

/// Runs the studies around `answer` (the deterministic one) within `budget`.
pub fn run(
    study: &Study,
    answer: &SlopeAnswer,
    budget: &Budget,
    tally: &Tally,
) -> Result<StudyAnswers, (&'static str, StudyStop)> {
    let fixed = study.probabilistic.as_ref().is_some_and(|p| p.fixed);
    let sampled = match fixed {
        true => with_fixed_surface(&study.base, answer),
        false => study.base.clone(),
    };
    crate::study::run(study, &sampled, evaluate, budget, tally)
}

/// `base` with the deterministic answer's surface fixed: the circle or polyline answered, at
/// its slice count, without a search or refinement.
pub fn with_fixed_surface(base: &Value, answer: &SlopeAnswer) -> Value {
    let mut fixed = base.clone();
    let Some(object) = fixed.as_object_mut() else {
        return fixed;
    };
    let Analysed::Section(section_problem) = &answer.problem;
    if object.get("search").is_some_and(|s| !s.is_null()) {
        for key in ["search", "circle", "surface", "moment_centre"] {
            object.remove(key);
        }
        match section_problem.shape() {
            SlipShape::Circle { centre, radius } => {
                object.insert(
                    "circle".to_owned(),
                    json!({"centre": [centre.0, centre.1], "radius": radius}),
                );
            }
            SlipShape::Polyline(line) => {
                let points: Vec<Value> = line.points().iter().map(|p| json!([p.0, p.1])).collect();
                object.insert("surface".to_owned(), Value::Array(points));
            }
        }
    }
    for key in ["slice_tolerance", "accuracy"] {
        object.remove(key);
    }
    object.insert("slices".to_owned(), json!(answer.problem.slice_count()));
    fixed
}

/// One sample: `request` read, validated and analysed; its F when Spencer's equations (or the
/// φ = 0 moment equation) answer it with the strengths settled.
pub fn evaluate(request: Value, budget: &Budget) -> Sampled {
    let typed: SpencerRequest = match serde_json::from_value(request) {
        Ok(typed) => typed,
        Err(e) => return Sampled::Refused(e.to_string()),
    };
    let mut plan = match typed.validate() {
        Ok(plan) => plan,
        Err(e) => return Sampled::Refused(e.to_string()),
    };
    plan.estimate_accuracy = false;
    plan.methods.clear();
    plan.curves = false;
    match analyse(&plan, budget) {
        Ok(SlopeOutcome::Answered(answer)) => {
            let s = &answer.solution;
            let answered = matches!(
                s.status,
                SpencerStatus::Converged | SpencerStatus::MomentOnly
            );
            match s.factor_of_safety {
                Some(f) if answered && s.strength.settled => Sampled::Solved(f),
                _ => Sampled::Unsolved,
            }
        }
        Ok(SlopeOutcome::Stopped { .. }) => Sampled::Unsolved,
        Err(e) => Sampled::Refused(e.to_string()),
    }
}
