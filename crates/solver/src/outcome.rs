//! How a programme that reached no answer it can vouch for failed: one vocabulary for every
//! solver of the crate (Clarabel's `SolverStatus` is the model). Each solution carries its own
//! status enum for the outcomes that belong to its problem (a dead load not carried, a circle
//! with no solution, an arch that stands however thin) and wraps a [`SolverFailure`] for the
//! rest; not converging is an outcome, never an `Err`. A solve the budget ended is not a
//! failure: its [`crate::budget::Stop`] says so, the one way to stop in the crate.

/// Why a programme stopped without an answer (Clarabel's status, named; the iteration limit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SolverFailure {
    /// Reached only reduced accuracy.
    ReducedAccuracy,
    /// Iteration limit.
    MaxIterations,
    /// Numerical error or lack of progress.
    Numerical,
    /// Reported the programme infeasible, which the formulations exclude.
    Infeasible,
}
