//! How much an analysis may spend, and how it stopped (argmin's `Executor` and
//! `TerminationReason` are the model).
//!
//! A [`Budget`] is a whole-solve deadline plus a cancellation flag that the caller may raise
//! from another thread (a client that went away, a process that drains). Every loop of an
//! analysis asks [`Budget::check`] between its steps; nothing keeps its own clock. A [`Stop`]
//! says how an analysis ended; the service derives its status codes from it in one place.

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A whole-solve deadline and a cancellation flag. Cloning shares the flag.
#[derive(Debug, Clone, Default)]
pub struct Budget {
    deadline: Option<Instant>,
    cancelled: Option<Arc<AtomicBool>>,
}

impl Budget {
    /// No deadline, no cancellation.
    pub fn unlimited() -> Self {
        Self::default()
    }

    /// Ends `limit` from now.
    pub fn with_time_limit(limit: Duration) -> Self {
        Self {
            deadline: Instant::now().checked_add(limit),
            cancelled: None,
        }
    }

    /// Ends at `deadline`.
    pub fn until(deadline: Instant) -> Self {
        Self {
            deadline: Some(deadline),
            cancelled: None,
        }
    }

    /// The same budget, also ended when `flag` is raised.
    pub fn cancelled_by(mut self, flag: Arc<AtomicBool>) -> Self {
        self.cancelled = Some(flag);
        self
    }

    /// The same budget (and flag), ending no later than `limit` from now.
    pub fn narrowed(&self, limit: Option<Duration>) -> Self {
        let end = limit.and_then(|l| Instant::now().checked_add(l));
        let deadline = match (self.deadline, end) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        Self {
            deadline,
            cancelled: self.cancelled.clone(),
        }
    }

    /// The deadline, if any.
    pub fn deadline(&self) -> Option<Instant> {
        self.deadline
    }

    /// Time left before the deadline (zero once past it); `None` without a deadline.
    pub fn remaining(&self) -> Option<Duration> {
        self.deadline
            .map(|d| d.saturating_duration_since(Instant::now()))
    }

    /// Whether the flag was raised.
    pub fn is_cancelled(&self) -> bool {
        self.cancelled
            .as_ref()
            .is_some_and(|f| f.load(Ordering::Relaxed))
    }

    /// `Err` with the reason once the budget is spent: cancellation first, then the deadline.
    pub fn check(&self) -> Result<(), Stop> {
        if self.is_cancelled() {
            Err(Stop::Cancelled)
        } else if self.deadline.is_some_and(|d| Instant::now() >= d) {
            Err(Stop::TimeLimit)
        } else {
            Ok(())
        }
    }

    /// How the budget stands: [`Stop::Finished`] while it lasts, else why it is spent
    /// ([`Stop::Cancelled`] first, then [`Stop::TimeLimit`]). A loop that ended early reports
    /// this as its stop.
    pub fn stop(&self) -> Stop {
        self.check().err().unwrap_or(Stop::Finished)
    }

    /// Whether the budget is spent.
    pub fn is_spent(&self) -> bool {
        self.check().is_err()
    }
}

impl PartialEq for Budget {
    /// The same deadline and the same flag (or none).
    fn eq(&self, other: &Self) -> bool {
        let same_flag = match (&self.cancelled, &other.cancelled) {
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            (None, None) => true,
            _ => false,
        };
        self.deadline == other.deadline && same_flag
    }
}

/// How an analysis ended. The answer's own status (a circle without a root, an arch that does
/// not carry its weight) is part of a finished answer, not a stop.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// It ran its whole plan.
    Finished,
    /// The budget's deadline passed first.
    TimeLimit,
    /// The budget's flag was raised (the client went away, the process drains).
    Cancelled,
    /// A search found no candidate with a solution in the region it was given.
    NoCandidate,
    /// A search's own cap on the trial surfaces it may evaluate was reached (a count that
    /// gives the same answer on every machine); it answers the best found so far.
    EvaluationCap,
}

impl Stop {
    /// Whether the plan ran to its end.
    pub fn is_finished(self) -> bool {
        self == Self::Finished
    }

    /// Whether the budget ended it (deadline or cancellation).
    pub fn is_budget(self) -> bool {
        matches!(self, Self::TimeLimit | Self::Cancelled)
    }
}

impl fmt::Display for Stop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Finished => "finished",
            Self::TimeLimit => "stopped at the time limit",
            Self::Cancelled => "cancelled",
            Self::NoCandidate => "no candidate with a solution",
            Self::EvaluationCap => "stopped at its evaluation cap",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_budget_says_why_it_is_spent() {
        assert_eq!(Budget::unlimited().check(), Ok(()));
        assert_eq!(
            Budget::with_time_limit(Duration::ZERO).check(),
            Err(Stop::TimeLimit)
        );
        let flag = Arc::new(AtomicBool::new(false));
        let budget = Budget::with_time_limit(Duration::from_secs(60)).cancelled_by(flag.clone());
        assert_eq!(budget.check(), Ok(()));
        flag.store(true, Ordering::Relaxed);
        // A clone shares the flag; cancellation is reported before the deadline.
        assert_eq!(budget.clone().check(), Err(Stop::Cancelled));
    }

    #[test]
    fn narrowing_keeps_the_earlier_end_and_the_flag() {
        let wide = Budget::with_time_limit(Duration::from_secs(3600));
        let narrow = wide.narrowed(Some(Duration::ZERO));
        assert_eq!(narrow.check(), Err(Stop::TimeLimit));
        let same = wide.narrowed(Some(Duration::from_secs(7200)));
        assert_eq!(same.deadline(), wide.deadline());
        assert!(Budget::unlimited().narrowed(None).deadline().is_none());
        assert!(wide
            .remaining()
            .is_some_and(|r| r > Duration::from_secs(3500)));
    }
}
