//! Stability of embankments by Spencer's method (Spencer 1967, with the moment equation of the
//! 1973 revision), following the "Slope Stability" program of the thesis in `shared/seed`.
//!
//! Coordinates: x to the right, y up, the toe of the embankment at the origin, ground level
//! y = 0 in front of the toe (x < 0), the slope face rising to the crest (L, H) and the crest at
//! y = H beyond it. The sliding mass moves towards the toe, that is towards −x. Moments are
//! counter-clockwise positive. Angles are carried in radians inside the crate (`_rad`).
//!
//! - [`geometry`]: the embankment, the slip circle and the vertical slices cut from it.
//! - [`spencer`]: the two equilibrium equations and their solution for (F, θ).
//! - [`search`]: the critical slip circle over a grid of centres, refined.

pub mod geometry;
pub mod search;
pub mod spencer;

pub use geometry::{Embankment, Slice, SlipCircle, SlopeGeometry};
pub use search::{
    factor_of_safety, search_critical_circle, FactorGrid, SearchGrid, SearchProblem,
    SearchSettings, SearchSolution,
};
pub use spencer::{
    factor_curves, solve_spencer, solve_spencer_factor, ExternalLoad, Seismic, SliceForces,
    SlopeProblem, Soil, SpencerSettings, SpencerSolution, SpencerStatus, ThrustPoint,
};

/// Input the slope solver cannot accept; `parameter` names the offending input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SlopeError {
    /// A number is outside its allowed range.
    #[error("{parameter} = {value} is out of range: {allowed}")]
    OutOfRange {
        /// Name of the input, as the service spells it (`slope.height`, `soil.cohesion`, …).
        parameter: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range in words.
        allowed: &'static str,
    },
    /// The slip circle does not cut a sliding mass out of the embankment.
    #[error("{parameter}: {reason}")]
    NoSlipMass {
        /// Name of the input that has to change.
        parameter: &'static str,
        /// What is wrong with the circle.
        reason: String,
    },
}

/// Checks that `value` is finite and lies in `[min, max]` (`min_open` makes the lower end open).
pub(crate) fn check_range(
    parameter: &'static str,
    value: f64,
    min: f64,
    min_open: bool,
    max: f64,
    allowed: &'static str,
) -> Result<f64, SlopeError> {
    let above_min = if min_open { value > min } else { value >= min };
    if value.is_finite() && above_min && value <= max {
        Ok(value)
    } else {
        Err(SlopeError::OutOfRange {
            parameter,
            value,
            allowed,
        })
    }
}
