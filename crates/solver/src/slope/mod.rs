//! Stability of embankments by Spencer's method (Spencer 1967, with the moment equation of the
//! 1973 revision), following the "Slope Stability" program of the thesis in the thesis.
//!
//! Coordinates: x to the right, y up, the toe of the embankment at the origin, ground level
//! y = 0 in front of the toe (x < 0), the slope face rising to the crest (L, H) and the crest at
//! y = H beyond it. The sliding mass moves towards the toe, that is towards −x. Moments are
//! counter-clockwise positive. Angles are carried in radians inside the crate (`_rad`).
//!
//! - [`geometry`]: the embankment, the slip circle and the vertical slices cut from it.
//! - [`spencer`]: the two equilibrium equations and their solution for (F, θ).
//! - [`refinement`]: F made independent of the slice count by doubling the slices.
//! - [`search`]: the critical slip circle over a grid of centres, refined.
//! - [`section`]: any cross-section, any slip surface, and their searches.
//! - [`analysis`]: one analysis of a plan within a budget — what runs after what.
//! - [`design`]: partial factors (EN 1997-1): the scene in design values and the verdict.

pub mod accuracy;
pub mod analysis;
pub mod circles;
pub mod design;
mod error;
pub mod geometry;
pub mod refinement;
pub mod search;
pub mod section;
pub mod slices;
mod spare;
pub mod spencer;
pub mod strength;

pub use crate::outcome::SolverFailure;
pub use error::{SlopeError, SlopeParameter, SupportField};
pub use geometry::{Embankment, Slice, SlipCircle, SlopeGeometry};
pub use refinement::{
    refine_slices, RefinedSolution, RefinementSettings, RefinementStatus, RefinementStep,
};
pub use search::{
    factor_of_safety, search_critical_circle, FactorGrid, SearchGrid, SearchProblem,
    SearchSettings, SearchSolution, SearchStatus,
};
pub use slices::{BaseSlice, SliceModel, Sliced};
pub use spencer::{
    factor_curves, factor_curves_around, solve_spencer, solve_spencer_factor,
    spencer_factor_outcome, spencer_factor_outcome_near, ExternalLoad, FactorCurves, FactorOutcome,
    Seismic, SliceForces, SlopeProblem, Soil, SpencerFactor, SpencerSettings, SpencerSolution,
    SpencerStatus, ThrustPoint,
};
