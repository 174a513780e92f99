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

use crate::warning::{Warning, WarningCode};
use response::{ProbabilisticOutDto, SensitivityOutDto};

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
                    "{} of {} samples have no answer (no root, strengths not settled, or no \
                     candidate surface): they are neither safe nor failed, and the probability \
                     of failure is of the {} answered",
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
