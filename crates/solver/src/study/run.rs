//! Running a study: each sample's analysis, in parallel across the worker's threads, within
//! the solver's one budget (a sample not started when time runs out or the client goes is not
//! run, and the study says it stopped), with progress reported as samples finish.

use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use crate::budget::{Budget, Stop};

/// Progress of a study: samples done of all.
pub trait Progress: Sync {
    /// `done` of `of` samples are answered.
    fn report(&self, done: usize, of: usize);
}

impl<F: Fn(usize, usize) + Sync> Progress for F {
    fn report(&self, done: usize, of: usize) {
        self(done, of)
    }
}

/// Runs `evaluate` on each row of `samples` (row-major, `k` values a row): its answer, `None`
/// where it has none. Stops early (with the budget's stop) when the budget is spent; the
/// answers of the rows not run are then absent from the result.
pub fn run<E>(
    samples: &[f64],
    k: usize,
    evaluate: E,
    budget: &Budget,
    progress: &dyn Progress,
) -> (Vec<Option<f64>>, Result<(), Stop>)
where
    E: Fn(&[f64]) -> Option<f64> + Sync,
{
    let rows: Vec<&[f64]> = samples.chunks(k.max(1)).collect();
    let of = rows.len();
    let done = AtomicUsize::new(0);
    let answers: Vec<Option<Option<f64>>> = rows
        .par_iter()
        .map(|row| {
            budget.check().ok()?;
            let answer = evaluate(row);
            let d = done.fetch_add(1, Ordering::Relaxed) + 1;
            progress.report(d, of);
            Some(answer)
        })
        .collect();
    let stop = if answers.iter().all(Option::is_some) {
        Ok(())
    } else {
        budget.check().and(Err(budget.out_of_time()))
    };
    (answers.into_iter().flatten().collect(), stop)
}
