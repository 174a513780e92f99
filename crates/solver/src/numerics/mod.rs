//! One-variable root finding, few-variable minimisation and small linear programmes, shared by
//! the solvers.
//!
//! - [`brent`]: Brent's method on a bracket (Spencer's F at fixed θ, the θ fallback, the
//!   minimum thickness).
//! - [`nelder_mead`]: the Nelder–Mead simplex (the refinement of the critical-circle search).
//! - [`simplex`]: Dantzig's simplex method for small dense linear programmes, warm-started
//!   from a basis (the stops of a rolling load on a chain with passive restraint).

pub mod brent;
pub mod nelder_mead;
pub mod simplex;

pub use brent::{brent, Root};
pub use nelder_mead::{nelder_mead, nelder_mead_to, Minimum};
