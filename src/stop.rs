//! How an analysis that stopped without an answer is told to the client: the one rule from the
//! solver's [`Stop`] to a status code, for every route.

use thrustline_solver::budget::Stop;

use crate::error::ApiError;
use crate::state::AppState;

/// What a stopped analysis tells the client: the field that sets the work, what to change when
/// the budget ended it, and what to change when a search found no candidate.
#[derive(Debug, Clone, Copy)]
pub struct Work {
    /// Dotted path of the field that sets the amount of work.
    pub field: &'static str,
    /// What to change when the time limit ended the analysis.
    pub advice: &'static str,
    /// What to change when a search found no candidate (unused where there is no search).
    pub no_candidate: &'static str,
}

impl AppState {
    /// The budget's end is 422 naming `work.field` when the solve ran alone on the pool, 503
    /// beside other solves ([`crate::pool::SolvePool::judge`]); a search without a candidate is
    /// 422 naming the field.
    pub fn refuse(&self, stop: Stop, work: Work, shared: bool) -> ApiError {
        let over_time = || ApiError::OverTimeLimit {
            field: work.field.to_owned(),
            seconds: self.solve_time_limit_secs(),
            advice: work.advice,
            busy: None,
        };
        match stop {
            // An evaluation cap is a search's own, which answers its best so far: it never
            // reaches here, and is told as the work being too large if it did.
            Stop::TimeLimit | Stop::Cancelled | Stop::EvaluationCap => {
                self.pool.judge(over_time(), shared)
            }
            Stop::NoCandidate => ApiError::invalid(work.field, work.no_candidate),
            Stop::Finished => ApiError::Internal("an analysis finished without an answer".into()),
        }
    }
}
