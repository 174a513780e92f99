//! One-variable root finding and few-variable minimisation, shared by the solvers.
//!
//! - [`brent`]: Brent's method on a bracket (Spencer's F at fixed θ, the θ fallback, the
//!   minimum thickness).
//! - [`nelder_mead`]: the Nelder–Mead simplex (the refinement of the critical-circle search).

pub mod brent;
pub mod nelder_mead;

pub use brent::{brent, Root};
pub use nelder_mead::{nelder_mead, Minimum};
