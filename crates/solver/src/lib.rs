//! Numerics of thrustline: limit analysis of rigid-block structures (Livesley 1978) and
//! embankment stability by Spencer's method (1967, revised 1973).
//!
//! The crate is pure numerics — no HTTP, no async, no JSON. Each problem follows the same
//! layering: an immutable problem description (validated on construction), a settings struct
//! with documented defaults, one `solve_*` call, and a plain solution struct that carries a
//! status. Not converging is an outcome reported in the solution, not an error; `Err` is kept
//! for input the solver cannot accept.
//!
//! - [`slope`]: Spencer's method for one slip circle (model §2).
#![warn(missing_docs)]

pub mod arch;
pub mod budget;
pub mod numerics;
pub mod outcome;
mod polygon;
pub mod reference;
pub mod slope;
pub mod study;
