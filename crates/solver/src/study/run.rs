//! Running a study: each sample's analysis, in parallel on a pool of the study's own, within
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

/// Runs `evaluate` on each of `items` (a sample's row of values, a sensitivity's point): its
/// answers in the items' order. Stops early (with the budget's stop) when the budget is spent;
/// the answers of the items not run are then absent from the result.
pub fn run<T, A, E>(
    items: &[T],
    evaluate: E,
    budget: &Budget,
    progress: &dyn Progress,
) -> (Vec<A>, Result<(), Stop>)
where
    T: Sync,
    A: Send,
    E: Fn(&T) -> A + Sync,
{
    // A pool of its own: the study's items are not queued behind other work on the global
    // pool (another request's study), so its budget is seen as soon as it is spent.
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
        Ok(pool) => pool.install(|| run_here(items, &evaluate, budget, progress)),
        Err(_) => run_here(items, &evaluate, budget, progress),
    }
}

/// [`run`] on the current rayon pool.
fn run_here<T, A, E>(
    items: &[T],
    evaluate: &E,
    budget: &Budget,
    progress: &dyn Progress,
) -> (Vec<A>, Result<(), Stop>)
where
    T: Sync,
    A: Send,
    E: Fn(&T) -> A + Sync,
{
    let of = items.len();
    let done = AtomicUsize::new(0);
    let answers: Vec<Option<A>> = items
        .par_iter()
        .map(|item| {
            budget.check().ok()?;
            let answer = evaluate(item);
            let d = done.fetch_add(1, Ordering::Relaxed) + 1;
            progress.report(d, of);
            Some(answer)
        })
        .collect();
    // An item left out was left by the budget: the study stops with its reason.
    let stop = if answers.iter().all(Option::is_some) {
        Ok(())
    } else {
        Err(budget.check().err().unwrap_or(Stop::TimeLimit))
    };
    (answers.into_iter().flatten().collect(), stop)
}

/// The rows of `samples` (row-major, `k` values a row).
pub fn rows(samples: &[f64], k: usize) -> Vec<&[f64]> {
    samples.chunks(k.max(1)).collect()
}
