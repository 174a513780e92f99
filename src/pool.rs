//! The bounded pool that runs solves off the async workers.
//!
//! A solve takes an admission permit (solves running plus waiting, bounded: beyond it the
//! request is answered 503 with `Retry-After` instead of queueing without end), then a worker
//! permit (solves running at once), and runs in tokio's blocking pool inside the request's
//! tracing span. Solves run in two lanes by their [`Cost`]: light ones (a single surface, a
//! small chain) have workers of their own, so they are not queued behind searches and
//! multi-ring arches; heavy ones also reserve the memory their solver may take from a
//! process-wide amount (`THRUSTLINE_SOLVE_MEMORY_MIB`) and wait while it is taken.
//! `spawn_blocking` cannot be cancelled from outside, so a solve stops itself: it runs with a
//! budget ([`SolvePool::run_budgeted`]) whose deadline is the solve time limit and whose flag is
//! raised when the request's future is dropped (a client gone, the drain over); the pool's own
//! deadline only stops the client from waiting past it.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use thrustline_solver::budget::Budget;
use tokio::sync::Semaphore;

use crate::error::ApiError;
use crate::metrics::Metrics;

/// The most memory a light solve may take: more makes it heavy.
const LIGHT_MEMORY: usize = 16 << 20;

/// What a solve is expected to take: whether its work is small (a single surface, a chain of
/// modest size) and an upper bound on its memory in bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cost {
    /// Expected to finish in milliseconds.
    pub light: bool,
    /// An upper bound on the memory it takes, in bytes.
    pub memory: usize,
}

impl Cost {
    /// A solve of milliseconds and little memory.
    pub const LIGHT: Self = Self {
        light: true,
        memory: 0,
    };
    /// A solve that may run long but takes little memory (a search).
    pub const HEAVY: Self = Self {
        light: false,
        memory: 0,
    };
}

/// Workers and admission of one lane.
#[derive(Debug, Clone)]
struct Lane {
    running: Arc<Semaphore>,
    admitted: Arc<Semaphore>,
}

impl Lane {
    fn new(max_running: usize, max_queued: usize) -> Self {
        Self {
            running: Arc::new(Semaphore::new(max_running)),
            admitted: Arc::new(Semaphore::new(max_running + max_queued)),
        }
    }
}

/// Limits of the solve pool.
#[derive(Debug, Clone)]
pub struct SolvePool {
    heavy: Lane,
    light: Lane,
    /// Mebibytes the heavy solves running may reserve together.
    memory: Arc<Semaphore>,
    memory_mib: u32,
    max_running: usize,
    max_queued: usize,
    deadline: Duration,
    metrics: Arc<Metrics>,
    /// Solves started since the pool was made.
    started: Arc<AtomicU64>,
}

/// A solve's value, the time it ran, and whether another solve ran at any moment beside it
/// (then its time limit was shared with other work: see [`SolvePool::judge`]).
#[derive(Debug)]
pub struct Ran<T> {
    pub value: T,
    pub elapsed: Duration,
    pub shared: bool,
}

impl SolvePool {
    /// A pool running at most `max_running` solves at once in each lane with at most
    /// `max_queued` waiting in each, the heavy ones within `memory_mib` mebibytes together; a
    /// solve that has not answered within `deadline` is answered 503.
    pub fn new(
        max_running: usize,
        max_queued: usize,
        memory_mib: u32,
        deadline: Duration,
        metrics: Arc<Metrics>,
    ) -> Self {
        let max_running = max_running.max(1);
        let memory_mib = memory_mib.max(1);
        Self {
            heavy: Lane::new(max_running, max_queued),
            light: Lane::new(max_running, max_queued),
            memory: Arc::new(Semaphore::new(memory_mib as usize)),
            memory_mib,
            max_running,
            max_queued,
            deadline,
            metrics,
            started: Arc::default(),
        }
    }

    /// The most memory one solve may take, in bytes: the whole of what heavy solves share.
    pub fn memory_limit(&self) -> usize {
        (self.memory_mib as usize) << 20
    }

    /// Solves that run at once in each lane.
    pub fn max_running(&self) -> usize {
        self.max_running
    }

    /// Solves admitted but waiting for a worker right now.
    pub fn queue_depth(&self) -> usize {
        [&self.heavy, &self.light]
            .iter()
            .map(|lane| {
                let admitted =
                    self.max_running + self.max_queued - lane.admitted.available_permits();
                admitted.saturating_sub(self.max_running - lane.running.available_permits())
            })
            .sum()
    }

    /// Solves running right now.
    pub fn running(&self) -> usize {
        2 * self.max_running
            - self.heavy.running.available_permits()
            - self.light.running.available_permits()
    }

    /// Seconds until a worker is likely free for a new solve: the solves ahead of it (running
    /// and waiting) times the recent solve time, shared by the workers; at least 1, at most the
    /// deadline.
    pub fn retry_after_secs(&self) -> u64 {
        let ahead = (self.running() + self.queue_depth()) as f64;
        let wait = ahead * self.metrics.recent_solve_seconds() / self.max_running as f64;
        let most = self.deadline.as_secs_f64().ceil().max(1.0);
        // A float in [1, most]: the cast cannot overflow.
        wait.ceil().clamp(1.0, most) as u64
    }

    /// Runs `solve` on the blocking pool, in the lane its `cost` says, and returns its value
    /// with the time it took and whether it ran alone. A cost over [`SolvePool::memory_limit`]
    /// waits for the whole of it (the handlers refuse such requests first).
    pub async fn run<T, F>(&self, cost: Cost, solve: F) -> Result<Ran<T>, ApiError>
    where
        T: Send + 'static,
        F: FnOnce() -> T + Send + 'static,
    {
        let light = cost.light && cost.memory <= LIGHT_MEMORY;
        let lane = if light { &self.light } else { &self.heavy };
        let _admission =
            lane.admitted
                .clone()
                .try_acquire_owned()
                .map_err(|_| ApiError::Overloaded {
                    queued: self.max_queued,
                    retry_after: self.retry_after_secs(),
                })?;
        let closed = |_| ApiError::Internal("solve pool closed".to_owned());
        // The deadline covers the wait for memory and a worker as well as the solve.
        let work = async {
            let memory = match light {
                true => None,
                false => {
                    let mib = cost
                        .memory
                        .div_ceil(1 << 20)
                        .clamp(1, self.memory_mib as usize);
                    // At most memory_mib: fits in u32.
                    let mib = u32::try_from(mib).unwrap_or(self.memory_mib);
                    Some(
                        self.memory
                            .clone()
                            .acquire_many_owned(mib)
                            .await
                            .map_err(closed)?,
                    )
                }
            };
            let running = lane.running.clone().acquire_owned().await.map_err(closed)?;
            let span = tracing::Span::current();
            let pool = self.clone();
            let task = tokio::task::spawn_blocking(move || {
                let _entered = span.enter();
                let before = (pool.running(), pool.started.fetch_add(1, Ordering::Relaxed));
                let start = Instant::now();
                let value = solve();
                let elapsed = start.elapsed();
                // Others running when it began or ended, or begun and ended within it.
                let shared = before.0 > 1
                    || pool.running() > 1
                    || pool.started.load(Ordering::Relaxed) > before.1 + 1;
                drop((running, memory));
                Ran {
                    value,
                    elapsed,
                    shared,
                }
            });
            task.await.map_err(|join_error| {
                ApiError::Internal(format!("solve task failed: {join_error}"))
            })
        };
        match tokio::time::timeout(self.deadline, work).await {
            Ok(Ok(ran)) => {
                self.metrics.observe_solve(ran.elapsed);
                Ok(ran)
            }
            Ok(Err(error)) => Err(error),
            Err(_) => Err(ApiError::TimedOut {
                seconds: self.deadline.as_secs_f64(),
                retry_after: self.retry_after_secs(),
            }),
        }
    }

    /// Runs `solve` as [`SolvePool::run`] does, with a [`Budget`] of `time_limit` from the moment
    /// it starts running, cancelled when this future is dropped: a client that goes away (its
    /// request future dropped by the server) or the pool's own deadline stops every loop that
    /// asks the budget.
    pub async fn run_budgeted<T, F>(
        &self,
        time_limit: Duration,
        cost: Cost,
        solve: F,
    ) -> Result<Ran<T>, ApiError>
    where
        T: Send + 'static,
        F: FnOnce(&Budget) -> T + Send + 'static,
    {
        let cancelled = Arc::new(AtomicBool::new(false));
        let _cancel_on_drop = CancelOnDrop(cancelled.clone());
        self.run(cost, move || {
            let budget = Budget::with_time_limit(time_limit).cancelled_by(cancelled);
            solve(&budget)
        })
        .await
    }

    /// The outcome rule for a solver stopped at its time limit (docs/api.md): alone on the pool it
    /// is the request's size (the 422 naming the field that sets the work); beside other solves
    /// it may be the load (the same request can finish on an idle service), so it is the
    /// service's condition: 503 with `Retry-After`, the field still named.
    pub fn judge(&self, error: ApiError, shared: bool) -> ApiError {
        match error {
            ApiError::OverTimeLimit {
                field,
                seconds,
                advice,
                busy: None,
            } if shared => ApiError::OverTimeLimit {
                field,
                seconds,
                advice,
                busy: Some(self.retry_after_secs()),
            },
            other => other,
        }
    }
}

/// Raises its flag when dropped: the request's work is no longer wanted.
struct CancelOnDrop(Arc<AtomicBool>);

impl Drop for CancelOnDrop {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn the_deadline_covers_the_wait_for_a_worker() {
        // One worker, busy for 600 ms; the next solve waits for it and is answered 503 at the
        // 150 ms deadline, not after the first one finishes (regression: the wait was outside).
        let pool = SolvePool::new(1, 4, 64, Duration::from_millis(150), Arc::default());
        let busy = pool.clone();
        let first = tokio::spawn(async move {
            busy.run(Cost::HEAVY, || {
                std::thread::sleep(Duration::from_millis(600))
            })
            .await
        });
        tokio::time::sleep(Duration::from_millis(50)).await;
        let started = Instant::now();
        let second = pool.run(Cost::HEAVY, || ()).await;
        assert!(
            matches!(second, Err(ApiError::TimedOut { .. })),
            "{second:?}"
        );
        assert!(started.elapsed() < Duration::from_millis(450));
        // The first one, over its deadline too, is also a time-out.
        assert!(matches!(first.await, Ok(Err(ApiError::TimedOut { .. }))));
    }

    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn retry_after_is_the_work_ahead() {
        // Solves have taken 2 s lately; one worker busy and two waiting: a fourth is refused,
        // told to come back when the three ahead of it are done, 3 × 2 s on one worker.
        let metrics = Arc::new(Metrics::default());
        metrics.observe_solve(Duration::from_secs(2));
        let pool = SolvePool::new(1, 2, 64, Duration::from_secs(60), metrics);
        assert_eq!(pool.retry_after_secs(), 1, "nothing ahead: at least 1 s");
        let go = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let mut busy = Vec::new();
        for _ in 0..3 {
            let (pool, go) = (pool.clone(), go.clone());
            busy.push(tokio::spawn(async move {
                pool.run(Cost::HEAVY, move || {
                    while !go.load(std::sync::atomic::Ordering::Relaxed) {
                        std::thread::sleep(Duration::from_millis(5));
                    }
                })
                .await
            }));
        }
        tokio::time::sleep(Duration::from_millis(100)).await;
        match pool.run(Cost::HEAVY, || ()).await {
            Err(ApiError::Overloaded { retry_after, .. }) => assert_eq!(retry_after, 6),
            other => panic!("{other:?}"),
        }
        go.store(true, std::sync::atomic::Ordering::Relaxed);
        for task in busy {
            let _ = task.await;
        }
    }

    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn a_solve_knows_whether_it_ran_alone() {
        let pool = SolvePool::new(2, 4, 64, Duration::from_secs(10), Arc::default());
        assert!(!pool.run(Cost::HEAVY, || ()).await.unwrap().shared);
        // A long solve with a short one started and finished inside it: both shared.
        let long = {
            let pool = pool.clone();
            tokio::spawn(async move {
                pool.run(Cost::HEAVY, || {
                    std::thread::sleep(Duration::from_millis(300))
                })
                .await
            })
        };
        tokio::time::sleep(Duration::from_millis(50)).await;
        let short = pool.run(Cost::HEAVY, || ()).await.unwrap();
        assert!(short.shared);
        assert!(long.await.unwrap().unwrap().shared);
        assert!(
            !pool.run(Cost::HEAVY, || ()).await.unwrap().shared,
            "alone again"
        );
    }

    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn a_request_dropped_mid_solve_cancels_its_budget() {
        // A solve that loops until its budget is spent (60 s of time limit); the request's
        // future is dropped after 100 ms, as the server drops it when the client goes away.
        // The loop must see the cancellation at once, not at its time limit.
        let pool = SolvePool::new(1, 2, 64, Duration::from_secs(120), Arc::default());
        let (sender, receiver) = std::sync::mpsc::channel();
        let dropped_at = Instant::now();
        let run = pool.run_budgeted(Duration::from_secs(60), Cost::HEAVY, move |budget| {
            while !budget.is_spent() {
                std::thread::sleep(Duration::from_millis(1));
            }
            sender.send((budget.check(), Instant::now())).ok();
        });
        assert!(tokio::time::timeout(Duration::from_millis(100), run)
            .await
            .is_err());
        let (stop, at) = tokio::task::spawn_blocking(move || {
            receiver.recv_timeout(Duration::from_secs(10)).unwrap()
        })
        .await
        .unwrap();
        assert_eq!(stop, Err(thrustline_solver::budget::Stop::Cancelled));
        // 2 s: the loop's own step is 1 ms; anything near the 60 s limit is a failure.
        assert!(at.duration_since(dropped_at) < Duration::from_secs(2));
    }

    #[test]
    fn a_time_limit_hit_beside_other_solves_is_503_with_retry_after() {
        use axum::response::IntoResponse;
        let pool = SolvePool::new(1, 2, 64, Duration::from_secs(60), Arc::default());
        let hit = || ApiError::OverTimeLimit {
            field: "search".to_owned(),
            seconds: 30.0,
            advice: "use a coarser grid",
            busy: None,
        };
        let alone = pool.judge(hit(), false).into_response();
        assert_eq!(alone.status(), 422);
        assert!(alone.headers().get("retry-after").is_none());
        let busy = pool.judge(hit(), true);
        assert!(
            busy.to_string().contains("while the service was busy"),
            "{busy}"
        );
        assert!(busy.to_string().starts_with("search: "));
        let busy = busy.into_response();
        assert_eq!(busy.status(), 503);
        assert_eq!(busy.headers()["retry-after"], "1");
        // Other errors pass through unchanged.
        let other = pool.judge(ApiError::invalid("slices", "too many"), true);
        assert_eq!(other.into_response().status(), 422);
    }
}
