//! Running a study on the pool: each sample (or sensitivity value) written into a copy of the
//! request as JSON and analysed by the route's own `evaluate`, in parallel, within the request's
//! one budget; the answers added up into the study's answer.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use serde_json::Value;
use thrustline_solver::budget::{Budget, Stop};
use thrustline_solver::study::{self, summarise, Progress, StudyError};

use super::plan::{ProbabilisticPlan, SensitivityPlan};
use super::request::{SamplingDto, StudyMethodDto, StudySurfaceDto};
use super::response::{
    BinDto, ProbabilisticOutDto, SensitivityCurveDto, SensitivityOutDto, SensitivityPointDto,
};

/// How far a request's studies have come: analyses done of all, read by a stream of progress
/// lines while they run.
#[derive(Debug, Default)]
pub struct Tally {
    done: AtomicUsize,
    of: AtomicUsize,
}

impl Tally {
    /// Sets how many analyses the studies will run.
    pub fn expect(&self, of: usize) {
        self.of.store(of, Ordering::Relaxed);
    }

    /// One more analysis done.
    pub fn count(&self) {
        self.done.fetch_add(1, Ordering::Relaxed);
    }

    /// (done, of).
    pub fn read(&self) -> (usize, usize) {
        (
            self.done.load(Ordering::Relaxed),
            self.of.load(Ordering::Relaxed),
        )
    }
}

/// One sample's answer.
#[derive(Debug, Clone, PartialEq)]
pub enum Sampled {
    /// The analysis answered (F, λ).
    Solved(f64),
    /// The analysis has no answer.
    Unsolved,
    /// The route refuses the sample's values: why.
    Refused(String),
}

/// Why a study ended without its answer.
#[derive(Debug, Clone, PartialEq)]
pub enum StudyStop {
    /// The budget ran out, or the client went.
    Stopped(Stop),
    /// The samples could not be drawn (the plan checks this first).
    Sampling(StudyError),
}

/// Runs `plan` on `base` (the request as JSON, its surface fixed when the plan says).
pub fn probabilistic<E>(
    plan: &ProbabilisticPlan,
    base: &Value,
    evaluate: E,
    budget: &Budget,
    progress: &dyn Progress,
) -> Result<(ProbabilisticOutDto, Option<String>), StudyStop>
where
    E: Fn(Value, &Budget) -> Sampled + Sync,
{
    let start = Instant::now();
    let k = plan.variables.len();
    let values = study::sampling::samples(
        &plan.variables,
        &plan.rho,
        plan.samples,
        plan.sampling,
        plan.seed,
    )
    .map_err(StudyStop::Sampling)?;
    let rows = study::run::rows(&values, k);
    let (answers, stop) = study::run(
        &rows,
        |row: &&[f64]| {
            let mut request = base.clone();
            for (path, &x) in plan.paths.iter().zip(row.iter()) {
                path.set(&mut request, x);
            }
            evaluate(request, budget)
        },
        budget,
        progress,
    );
    stop.map_err(StudyStop::Stopped)?;
    let first_refusal = answers.iter().find_map(|a| match a {
        Sampled::Refused(why) => Some(why.clone()),
        _ => None,
    });
    let out = probabilistic_out(plan, &answers, start);
    Ok((out, first_refusal))
}

/// The answer of a probabilistic study from its samples' `answers` (started at `start`).
fn probabilistic_out(
    plan: &ProbabilisticPlan,
    answers: &[Sampled],
    start: Instant,
) -> ProbabilisticOutDto {
    let solved: Vec<Option<f64>> = answers
        .iter()
        .filter(|a| !matches!(a, Sampled::Refused(_)))
        .map(|a| match a {
            Sampled::Solved(f) => Some(*f),
            _ => None,
        })
        .collect();
    let s = summarise(&solved, 1.0, plan.bins);
    let answered = s.samples - s.unsolved;
    ProbabilisticOutDto {
        samples: answers.len(),
        sampling: match plan.sampling {
            study::Sampling::MonteCarlo => SamplingDto::MonteCarlo,
            study::Sampling::LatinHypercube => SamplingDto::LatinHypercube,
        },
        seed: plan.seed,
        surface: match plan.fixed {
            true => StudySurfaceDto::Fixed,
            false => StudySurfaceDto::Search,
        },
        method: (plan.method != StudyMethodDto::Spencer).then_some(plan.method),
        probability_of_failure: s.probability_of_failure,
        probability_of_failure_standard_error: s
            .probability_of_failure
            .map(|p| (p * (1.0 - p) / answered as f64).sqrt()),
        failed: solved.iter().flatten().filter(|&&f| f < 1.0).count(),
        mean: s.mean,
        std: s.std,
        reliability_index_normal: s.reliability_index_normal,
        reliability_index_lognormal: s.reliability_index_lognormal,
        histogram: s
            .histogram
            .iter()
            .map(|b| BinDto {
                from: b.from,
                to: b.to,
                count: b.count,
            })
            .collect(),
        unsolved: s.unsolved,
        refused: answers.len() - s.samples,
        time_ms: start.elapsed().as_secs_f64() * 1e3,
    }
}

/// Runs `plan` on `base` (the request as JSON, as stated).
pub fn sensitivity<E>(
    plan: &SensitivityPlan,
    base: &Value,
    evaluate: E,
    budget: &Budget,
    progress: &dyn Progress,
) -> Result<SensitivityOutDto, Stop>
where
    E: Fn(Value, &Budget) -> Sampled + Sync,
{
    let start = Instant::now();
    let points: Vec<(usize, f64)> = plan
        .variables
        .iter()
        .enumerate()
        .flat_map(|(i, (_, values))| values.iter().map(move |&x| (i, x)))
        .collect();
    let (answers, stop) = study::run(
        &points,
        |&(i, x): &(usize, f64)| {
            let mut request = base.clone();
            plan.variables[i].0.set(&mut request, x);
            evaluate(request, budget)
        },
        budget,
        progress,
    );
    stop?;
    let mut answers = answers.into_iter();
    let variables = plan
        .variables
        .iter()
        .map(|(path, values)| SensitivityCurveDto {
            field: path.text.clone(),
            points: values
                .iter()
                .zip(answers.by_ref())
                .map(|(&value, answer)| {
                    let (factor, refused) = match answer {
                        Sampled::Solved(f) => (Some(f), None),
                        Sampled::Unsolved => (None, None),
                        Sampled::Refused(why) => (None, Some(why)),
                    };
                    SensitivityPointDto {
                        value,
                        factor,
                        refused,
                    }
                })
                .collect(),
        })
        .collect();
    Ok(SensitivityOutDto {
        method: (plan.method != StudyMethodDto::Spencer).then_some(plan.method),
        variables,
        time_ms: start.elapsed().as_secs_f64() * 1e3,
    })
}
