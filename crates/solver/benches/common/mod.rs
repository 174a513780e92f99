//! What the benchmarks share: the median wall time of repeated runs.

use std::time::Instant;

/// Median wall time in seconds of `runs` calls of `f`, and the last value.
pub fn median_secs<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut times = Vec::with_capacity(runs);
    let mut value = None;
    for _ in 0..runs {
        let start = Instant::now();
        value = Some(f());
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    let value = value.expect("at least one run");
    (times[runs / 2], value)
}
