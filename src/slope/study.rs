//! Studies on the Spencer route (model §9.2–9.3): how a sample of the request is analysed.
//!
//! A sample is the request as JSON with the study's values written in: read as a request,
//! validated as one, and analysed without what only the deterministic answer reports (the
//! accuracy estimate, other methods, curves). With `surface: fixed` every sample keeps the
//! deterministic answer's surface at its slice count (so a sample at the stated values is that
//! answer); with `search` each sample runs the request's search and refinement again.

use serde_json::{json, Value};
use thrustline_solver::budget::Budget;
use thrustline_solver::slope::analysis::{
    analyse, Analysed, Method, SlopeAnswer, SlopeOutcome, Target,
};
use thrustline_solver::slope::section::SlipShape;
use thrustline_solver::slope::spencer::SpencerStatus;
use thrustline_solver::slope::Sliced;

use super::methods::MethodName;
use super::request::{NegativeEffectiveStressDto, SpencerRequest};
use crate::error::ApiError;
use crate::study::request::{StudyMethodDto, StudySurfaceDto};
use crate::study::run::{Sampled, StudyStop, Tally};
use crate::study::{Study, StudyAnswers};

/// The method of slices a study's method names (`None`: Spencer's, the headline).
fn method_of(method: StudyMethodDto) -> Option<MethodName> {
    match method {
        StudyMethodDto::Spencer => None,
        StudyMethodDto::MorgensternPrice => Some(MethodName::MorgensternPrice),
        StudyMethodDto::Bishop => Some(MethodName::Bishop),
        StudyMethodDto::Janbu => Some(MethodName::Janbu),
        StudyMethodDto::Ordinary => Some(MethodName::Ordinary),
    }
}

/// A study's method other than Spencer's must be among `methods` (so that the deterministic
/// answer has its F as well), and searched on the classic equations when samples search.
fn check_methods(request: &SpencerRequest) -> Result<(), ApiError> {
    let probabilistic = request.probabilistic.as_ref();
    let searches = probabilistic.is_some_and(|p| p.surface == Some(StudySurfaceDto::Search));
    let asked = [
        (
            "probabilistic.method",
            probabilistic.and_then(|p| p.method),
            searches,
        ),
        (
            "sensitivity.method",
            request.sensitivity.as_ref().and_then(|s| s.method),
            request.search.is_some(),
        ),
    ];
    for (field, method, searching) in asked {
        let Some(name) = method.and_then(method_of) else {
            continue;
        };
        if !request.methods.contains(&name) {
            return Err(ApiError::invalid(
                field,
                "names a method that is not among methods: add it there, so that the \
                 deterministic answer has its F too",
            ));
        }
        if searching && request.negative_effective_stress != NegativeEffectiveStressDto::Keep {
            return Err(ApiError::invalid(
                field,
                "searches each sample for the method's own circle on its classic equations: it \
                 does not combine with negative_effective_stress other than keep",
            ));
        }
    }
    Ok(())
}

/// The request's studies, checked against its `body` as sent (None without any).
pub fn plan(request: &SpencerRequest, body: &Value) -> Result<Option<Study>, ApiError> {
    check_methods(request)?;
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
    let sampled = match &study.probabilistic {
        Some(p) if p.fixed => with_fixed_surface(&study.base, answer, p.method),
        _ => study.base.clone(),
    };
    crate::study::run(study, &sampled, evaluate, budget, tally)
}

/// `base` with the deterministic answer's surface fixed: the circle or polyline answered (for
/// a study of another method, that method's own critical circle when the answer searched it),
/// at its slice count, without a search or refinement.
pub fn with_fixed_surface(base: &Value, answer: &SlopeAnswer, method: StudyMethodDto) -> Value {
    let mut fixed = base.clone();
    let Some(object) = fixed.as_object_mut() else {
        return fixed;
    };
    let own = method_of(method).and_then(|name| {
        let method = Method::from(name);
        answer
            .critical
            .iter()
            .find(|(m, _)| *m == method)?
            .1
            .as_ref()
    });
    let problem = own.map_or(&answer.problem, |c| &c.problem);
    let Analysed::Section(section_problem) = problem;
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

/// One sample: `request` read, validated and analysed; its F by `method` — Spencer's when his
/// equations (or the φ = 0 moment equation) answer it with the strengths settled; another's on
/// the surface given, or on its own critical circle when the sample searches.
pub fn evaluate(request: Value, method: StudyMethodDto, budget: &Budget) -> Sampled {
    let typed: SpencerRequest = match serde_json::from_value(request) {
        Ok(typed) => typed,
        Err(e) => return Sampled::Refused(e.to_string()),
    };
    let mut plan = match typed.validate() {
        Ok(plan) => plan,
        Err(e) => return Sampled::Refused(e.to_string()),
    };
    plan.estimate_accuracy = false;
    plan.curves = false;
    let other = method_of(method).map(Method::from);
    let searches = !matches!(plan.target, Target::Surface(_));
    plan.methods = other.into_iter().collect();
    plan.per_method = other.is_some() && searches;
    let answer = match analyse(&plan, budget) {
        Ok(SlopeOutcome::Answered(answer)) => answer,
        Ok(SlopeOutcome::Stopped { .. }) => return Sampled::Unsolved,
        Err(e) => return Sampled::Refused(e.to_string()),
    };
    let f = match other {
        None => {
            let s = &answer.solution;
            let answered = matches!(
                s.status,
                SpencerStatus::Converged | SpencerStatus::MomentOnly
            );
            s.factor_of_safety
                .filter(|_| answered && s.strength.settled)
        }
        Some(m) if searches => answer
            .critical
            .iter()
            .find(|(c, _)| *c == m)
            .and_then(|(_, c)| c.as_ref().map(|c| c.factor_of_safety)),
        Some(m) => answer
            .methods
            .as_ref()
            .and_then(|found| found.of(m))
            .and_then(|a| a.factor.factor_of_safety),
    };
    f.map_or(Sampled::Unsolved, Sampled::Solved)
}
