//! What every handler shares: the solve pool, the time limits, the counters and the token,
//! built once from the settings at start-up.

use crate::config::Settings;
use crate::{metrics, pool};

/// What every handler shares.
#[derive(Debug, Clone)]
pub struct AppState {
    /// The bounded pool that runs solves.
    pub pool: pool::SolvePool,
    /// Time limit of one solve (the solvers' own limit: `spawn_blocking` cannot be cancelled).
    pub solve_time_limit: std::time::Duration,
    /// Time limit of a whole batch.
    pub batch_time_limit: std::time::Duration,
    /// Counters for /metrics.
    pub metrics: std::sync::Arc<metrics::Metrics>,
    /// The bearer token every endpoint but /healthz requires, if any.
    pub token: Option<std::sync::Arc<str>>,
}

impl AppState {
    /// State for the given settings.
    pub fn new(settings: &Settings) -> Self {
        let metrics = std::sync::Arc::new(metrics::Metrics::default());
        Self {
            pool: pool::SolvePool::new(
                settings.max_running,
                settings.max_queued,
                settings.solve_memory_mib,
                // The solvers stop themselves at the solve timeout and answer; the pool's own
                // deadline, later, only catches what could not (waiting in the queue included).
                settings.solve_timeout * 2 + std::time::Duration::from_secs(1),
                metrics.clone(),
            ),
            solve_time_limit: settings.solve_timeout,
            batch_time_limit: settings.batch_timeout,
            metrics,
            token: settings.token.as_deref().map(std::sync::Arc::from),
        }
    }

    /// The solvers' time limit in seconds.
    pub fn solve_time_limit_secs(&self) -> f64 {
        self.solve_time_limit.as_secs_f64()
    }
}
