//! Studies (model §9.2–9.4): a probabilistic or sensitivity study varies numbers of the request
//! it rides on, addressed by their JSON paths, so every numeric field is a variable without
//! per-field code. [`request`] holds the blocks clients send, [`plan`] checks them against the
//! request once, [`run`] writes each sample into a copy of the request and has the route
//! analyse it (the solver's study draws the samples and adds up the answers), and
//! [`response`] is the answer. Each route says how one of its samples is analysed.

pub mod paths;
pub mod plan;
pub mod request;
pub mod response;
pub mod run;
pub mod stream;

use serde::de::DeserializeOwned;
use serde_json::Value;
use thrustline_solver::budget::Budget;

use crate::error::ApiError;
use crate::state::AppState;
use crate::stop::Work;
use crate::warning::{Warning, WarningCode};
use plan::{ProbabilisticPlan, SensitivityPlan};
use request::{ProbabilisticDto, SensitivityDto, StudyMethodDto};
use response::{ProbabilisticOutDto, SensitivityOutDto};
use run::{Sampled, StudyStop, Tally};

/// The studies a request asks for, checked.
#[derive(Debug, Clone)]
pub struct Study {
    /// The request as JSON without its studies and what samples do not report.
    pub base: Value,
    /// The probabilistic study.
    pub probabilistic: Option<ProbabilisticPlan>,
    /// The sensitivity study.
    pub sensitivity: Option<SensitivityPlan>,
}

/// What a request's studies answered.
#[derive(Debug, Clone, Default)]
pub struct StudyAnswers {
    /// The probabilistic study, and the first refusal of a sample's values if any.
    pub probabilistic: Option<(ProbabilisticOutDto, Option<String>)>,
    /// The sensitivity study.
    pub sensitivity: Option<SensitivityOutDto>,
}

/// The studies of a request of the route's type `R`, checked against `body` (the request as the
/// client wrote it); None without any. `unsampled` are the request's keys samples leave out
/// (what only the deterministic answer reports); `design` whether the request is a design check
/// (which a probabilistic study refuses).
pub fn plan<R: DeserializeOwned>(
    body: &Value,
    studies: (Option<&ProbabilisticDto>, Option<&SensitivityDto>),
    (unsampled, design): (&[&str], bool),
) -> Result<Option<Study>, ApiError> {
    let (probabilistic, sensitivity) = studies;
    if probabilistic.is_none() && sensitivity.is_none() {
        return Ok(None);
    }
    if probabilistic.is_some() && design {
        return Err(ApiError::invalid(
            "probabilistic",
            "samples characteristic values: leave out design (partial factors and a \
             probability of failure answer the same question twice)",
        ));
    }
    let mut base = body.clone();
    if let Some(object) = base.as_object_mut() {
        for key in ["probabilistic", "sensitivity"].iter().chain(unsampled) {
            object.remove(*key);
        }
    }
    let probabilistic = probabilistic
        .map(|dto| plan::probabilistic::<R>(dto, &base))
        .transpose()?;
    let sensitivity = sensitivity
        .map(|dto| plan::sensitivity::<R>(dto, &base))
        .transpose()?;
    Ok(Some(Study {
        base,
        probabilistic,
        sensitivity,
    }))
}

/// Analyses the studies will run.
pub fn analyses(study: &Study) -> usize {
    let samples = study.probabilistic.as_ref().map_or(0, |p| p.samples);
    let points = study
        .sensitivity
        .as_ref()
        .map_or(0, |s| s.variables.iter().map(|(_, v)| v.len()).sum());
    samples + points
}

/// Runs the studies within `budget`, each sample analysed by `evaluate` (with the study's
/// method); the probabilistic
/// samples start from `sampled` (the base, its surface fixed where the plan says). A study that
/// did not finish is the field that sets its work, and why.
pub fn run<E>(
    study: &Study,
    sampled: &Value,
    evaluate: E,
    budget: &Budget,
    tally: &Tally,
) -> Result<StudyAnswers, (&'static str, StudyStop)>
where
    E: Fn(Value, StudyMethodDto, &Budget) -> Sampled + Sync,
{
    let progress = |_: usize, _: usize| tally.count();
    let probabilistic = match &study.probabilistic {
        Some(p) => Some(
            run::probabilistic(
                p,
                sampled,
                |v, b| evaluate(v, p.method, b),
                budget,
                &progress,
            )
            .map_err(|stop| ("probabilistic.samples", stop))?,
        ),
        None => None,
    };
    let sensitivity = match &study.sensitivity {
        Some(s) => Some(
            run::sensitivity(
                s,
                &study.base,
                |v, b| evaluate(v, s.method, b),
                budget,
                &progress,
            )
            .map_err(|stop| ("sensitivity.variables", StudyStop::Stopped(stop)))?,
        ),
        None => None,
    };
    Ok(StudyAnswers {
        probabilistic,
        sensitivity,
    })
}

/// A study that did not finish, as the client is told: the budget's end is the outcome rule's
/// 422 naming the field that sets its work, with `advice` (503 when other solves shared the
/// machine, [`AppState::refuse`]); samples that could not be drawn are 422 naming it.
pub fn refusal(
    state: &AppState,
    (field, stop): (&'static str, StudyStop),
    advice: &'static str,
    shared: bool,
) -> ApiError {
    match stop {
        StudyStop::Stopped(stop) => {
            let work = Work {
                field,
                advice,
                no_candidate: "",
            };
            state.refuse(stop, work, shared)
        }
        StudyStop::Sampling(e) => ApiError::invalid(field, e.to_string()),
    }
}

/// What a study's answer asks the engineer to look at: samples or values without an answer,
/// and values the route refuses (with the first refusal's words).
pub fn warnings(
    probabilistic: Option<&(ProbabilisticOutDto, Option<String>)>,
    sensitivity: Option<&SensitivityOutDto>,
) -> Vec<Warning> {
    let mut out = Vec::new();
    if let Some((p, refusal)) = probabilistic {
        if p.unsolved > 0 {
            out.push(Warning::new(
                WarningCode::SamplesUnsolved,
                format!(
                    "{} of {} samples have no answer (the analysis' status says why when each \
                     is sent alone): they are neither safe nor failed, and the probability of \
                     failure is of the {} answered",
                    p.unsolved,
                    p.samples,
                    p.samples - p.unsolved - p.refused
                ),
            ));
        }
        if let (true, Some(why)) = (p.refused > 0, refusal) {
            out.push(Warning::new(
                WarningCode::SamplesRefused,
                format!(
                    "{} of {} samples have values the route refuses and are left out of the \
                     statistics (the first: {why}): truncate the variables with min and max",
                    p.refused, p.samples
                ),
            ));
        }
    }
    if let Some(s) = sensitivity {
        let points = s.variables.iter().flat_map(|v| &v.points);
        let (unsolved, refused) = points.fold((0, 0), |(u, r), p| match (&p.factor, &p.refused) {
            (None, Some(_)) => (u, r + 1),
            (None, None) => (u + 1, r),
            _ => (u, r),
        });
        if unsolved > 0 {
            out.push(Warning::new(
                WarningCode::SamplesUnsolved,
                format!("{unsolved} values of the sensitivity study have no answer"),
            ));
        }
        if refused > 0 {
            out.push(Warning::new(
                WarningCode::SamplesRefused,
                format!(
                    "{refused} values of the sensitivity study are refused by the route (each \
                     point says why)"
                ),
            ));
        }
    }
    out
}
