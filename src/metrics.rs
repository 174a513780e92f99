//! The counters behind `GET /metrics` (served by `health`): requests by route and status, the
//! solve-time histogram and the solve pool's load, rendered in the Prometheus text exposition
//! format 0.0.4. Kept in process, no global registry: the `Metrics` value lives in the
//! application state.

use std::collections::BTreeMap;
use std::fmt::Write;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::Duration;

/// Upper bounds of the solve-time histogram buckets, in seconds.
const BUCKETS: [f64; 12] = [
    0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 5.0,
];

/// Counters of one running service.
#[derive(Debug, Default)]
pub struct Metrics {
    requests: Mutex<BTreeMap<(String, u16), u64>>,
    solve_buckets: [AtomicU64; BUCKETS.len()],
    solve_count: AtomicU64,
    solve_micros: AtomicU64,
    /// Recent solve time: an exponentially weighted mean (weight ⅕ on the newest), f64 bits.
    recent_solve_seconds: AtomicU64,
}

impl Metrics {
    /// Counts one answered request.
    pub fn observe_request(&self, route: &str, status: u16) {
        if let Ok(mut requests) = self.requests.lock() {
            *requests.entry((route.to_owned(), status)).or_default() += 1;
        }
    }

    /// Records the wall time of one solve.
    pub fn observe_solve(&self, elapsed: Duration) {
        let seconds = elapsed.as_secs_f64();
        for (bucket, bound) in self.solve_buckets.iter().zip(BUCKETS) {
            if seconds <= bound {
                bucket.fetch_add(1, Ordering::Relaxed);
            }
        }
        self.solve_count.fetch_add(1, Ordering::Relaxed);
        let micros = u64::try_from(elapsed.as_micros()).unwrap_or(u64::MAX);
        self.solve_micros.fetch_add(micros, Ordering::Relaxed);
        // OK to ignore: the closure always returns Some, so the update cannot fail.
        let _ =
            self.recent_solve_seconds
                .fetch_update(Ordering::Relaxed, Ordering::Relaxed, |bits| {
                    let old = f64::from_bits(bits);
                    let new = if old > 0.0 {
                        0.8 * old + 0.2 * seconds
                    } else {
                        seconds
                    };
                    Some(new.to_bits())
                });
    }

    /// The recent mean wall time of a solve in seconds (0 before the first).
    pub fn recent_solve_seconds(&self) -> f64 {
        f64::from_bits(self.recent_solve_seconds.load(Ordering::Relaxed))
    }

    /// The exposition text, with the pool's current load.
    pub fn render(&self, running: usize, queued: usize) -> String {
        let mut out = String::new();
        // OK to ignore: writing to a String cannot fail.
        let _ = self.write(&mut out, running, queued);
        out
    }

    fn write(&self, out: &mut String, running: usize, queued: usize) -> std::fmt::Result {
        writeln!(
            out,
            "# HELP thrustline_requests_total Requests answered, by route and status."
        )?;
        writeln!(out, "# TYPE thrustline_requests_total counter")?;
        if let Ok(requests) = self.requests.lock() {
            for ((route, status), count) in requests.iter() {
                writeln!(
                    out,
                    "thrustline_requests_total{{route=\"{route}\",status=\"{status}\"}} {count}"
                )?;
            }
        }
        writeln!(
            out,
            "# HELP thrustline_solve_seconds Wall time of solves on the blocking pool."
        )?;
        writeln!(out, "# TYPE thrustline_solve_seconds histogram")?;
        for (bucket, bound) in self.solve_buckets.iter().zip(BUCKETS) {
            writeln!(
                out,
                "thrustline_solve_seconds_bucket{{le=\"{bound}\"}} {}",
                bucket.load(Ordering::Relaxed)
            )?;
        }
        let count = self.solve_count.load(Ordering::Relaxed);
        writeln!(
            out,
            "thrustline_solve_seconds_bucket{{le=\"+Inf\"}} {count}"
        )?;
        let sum = self.solve_micros.load(Ordering::Relaxed) as f64 * 1e-6;
        writeln!(out, "thrustline_solve_seconds_sum {sum}")?;
        writeln!(out, "thrustline_solve_seconds_count {count}")?;
        writeln!(out, "# HELP thrustline_solves_running Solves running now.")?;
        writeln!(out, "# TYPE thrustline_solves_running gauge")?;
        writeln!(out, "thrustline_solves_running {running}")?;
        writeln!(
            out,
            "# HELP thrustline_solve_queue_depth Solves waiting for a worker now."
        )?;
        writeln!(out, "# TYPE thrustline_solve_queue_depth gauge")?;
        writeln!(out, "thrustline_solve_queue_depth {queued}")
    }
}
