//! One trial surface of a search: placed, cut and solved as the searches rank them.

use std::num::NonZeroUsize;

use super::cut::{place_for_search, Cut};
use super::model::Section;
use super::shape::SlipShape;
use crate::slope::error::{SlopeError, SlopeParameter};
use crate::slope::spencer::{
    spencer_factor_outcome_near, FactorOutcome, Seismic, SpencerFactor, SpencerSettings,
};

/// A trial surface's F (and θ); `Err(None)` when it cuts no mass, `Err(Some(bishop))` when it
/// cuts one but has no solution (with Bishop's F there, if any).
pub type Outcome = Result<SpencerFactor, Option<Option<f64>>>;

/// Spencer's F (and θ) of one trial circle of a search on `section` (`mirror`: the section
/// seen from behind, built once per search), Bishop's start looked for from `near` first when
/// given (a neighbouring circle's F, [`spencer_factor_outcome_near`]); `Err(None)` when it
/// cuts no mass (or one shallower than `min_depth`), `Err(Some(bishop))` when it has no
/// solution.
pub fn circle_outcome(
    (section, mirror): (&Section, &Section),
    (centre, radius): ((f64, f64), f64),
    (slices, seismic): (NonZeroUsize, Seismic),
    (spencer, min_depth): (&SpencerSettings, f64),
    near: Option<f64>,
) -> Outcome {
    trial(
        (section, mirror),
        &SlipShape::Circle { centre, radius },
        (slices, seismic),
        (spencer, min_depth, near),
        |_| false,
    )
}

/// [`circle_outcome`] of any trial surface; `excluded(cut)`: whether the cut is no candidate.
pub(super) fn trial(
    (section, mirror): (&Section, &Section),
    shape: &SlipShape,
    (slices, seismic): (NonZeroUsize, Seismic),
    (spencer, min_depth, near): (&SpencerSettings, f64, Option<f64>),
    excluded: impl Fn(&Cut) -> bool,
) -> Outcome {
    let cut = place_for_search(section, mirror, shape, slices, seismic).map_err(|e| match e {
        // A drawdown stage without a solution: a mass that cannot be answered.
        SlopeError::NoSlipMass {
            parameter: SlopeParameter::Drawdown,
            ..
        } => Some(None),
        _ => None,
    })?;
    if cut.model.depth() < min_depth || excluded(&cut) {
        return Err(None);
    }
    let outcome = match spencer_factor_outcome_near(&cut.model, spencer, near) {
        FactorOutcome::Solved(s) => Ok(s),
        FactorOutcome::Unsolved { bishop } => Err(Some(bishop)),
        FactorOutcome::Undriven => Err(None),
    };
    super::buffers::give_back(cut.model.slices, cut.surface);
    outcome
}
