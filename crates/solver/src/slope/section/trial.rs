//! One trial surface of a search: placed, cut and solved as the searches rank them.

use std::num::NonZeroUsize;

use super::cut::Cut;
use super::model::Section;
use super::place::place_for_search;
use super::shape::SlipShape;
use crate::slope::error::{SlopeError, SlopeParameter};
use crate::slope::spencer::methods::{method_factor, InterSliceFunction, Method};
use crate::slope::spencer::{
    drives_towards_toe, spencer_factor_outcome_near, FactorOutcome, Seismic, SpencerFactor,
    SpencerSettings,
};

/// A trial surface's F (and θ); `Err(None)` when it cuts no mass, `Err(Some(bishop))` when it
/// cuts one but has no solution (with Bishop's F there, if any).
pub type Outcome = Result<SpencerFactor, Option<Option<f64>>>;

/// What every trial surface of one search shares: the section it is placed on, how it is cut
/// into slices and how it is solved.
#[derive(Debug, Clone, Copy)]
pub struct TrialSetup<'a> {
    /// The section searched.
    pub section: &'a Section,
    /// The section seen from behind ([`Section::mirrored`]), built once per search.
    pub mirror: &'a Section,
    /// About how many slices each surface is cut into.
    pub slices: NonZeroUsize,
    /// The seismic coefficients.
    pub seismic: Seismic,
    /// How Spencer's equations are solved.
    pub spencer: &'a SpencerSettings,
    /// Masses shallower than this cut no mass (are no candidates).
    pub min_depth: f64,
    /// Whether a mass may enter or leave the ground beyond the section's x-range (the ground
    /// taken level there); otherwise such a surface is no candidate.
    pub beyond_ground: bool,
    /// The method that ranks the surfaces: Spencer's (`None`), or another for its own
    /// critical surface (with Morgenstern–Price's inter-slice function).
    pub method: Option<(Method, &'a InterSliceFunction)>,
}

/// Spencer's F (and θ) of the trial circle through `centre` of `radius` of a search
/// (`setup`), Bishop's start looked for from `near` first when given (a neighbouring circle's
/// F, [`spencer_factor_outcome_near`]); `Err(None)` when it cuts no mass (or one shallower
/// than `setup.min_depth`), `Err(Some(bishop))` when it has no solution.
pub fn circle_outcome(
    setup: &TrialSetup<'_>,
    centre: (f64, f64),
    radius: f64,
    near: Option<f64>,
) -> Outcome {
    trial(setup, &SlipShape::Circle { centre, radius }, near, |_| {
        false
    })
}

/// [`circle_outcome`] of any trial surface; `excluded(cut)`: whether the cut is no candidate.
pub(super) fn trial(
    setup: &TrialSetup<'_>,
    shape: &SlipShape,
    near: Option<f64>,
    excluded: impl Fn(&Cut) -> bool,
) -> Outcome {
    let TrialSetup {
        section,
        mirror,
        slices,
        seismic,
        spencer,
        min_depth,
        beyond_ground,
        method,
    } = *setup;
    let cut = place_for_search(section, mirror, shape, slices, seismic).map_err(|e| match e {
        // A drawdown stage without a solution: a mass that cannot be answered.
        SlopeError::NoSlipMass {
            parameter: SlopeParameter::Drawdown,
            ..
        } => Some(None),
        _ => None,
    })?;
    let outside = !beyond_ground && !cut.within_ground(section, mirror);
    if cut.model.depth() < min_depth || outside || excluded(&cut) {
        return Err(None);
    }
    let outcome = match method {
        None => match spencer_factor_outcome_near(&cut.model, spencer, near) {
            FactorOutcome::Solved(s) => Ok(s),
            FactorOutcome::Unsolved { bishop } => Err(Some(bishop)),
            FactorOutcome::Undriven => Err(None),
        },
        // Another method's F in the place of Spencer's (no θ); undriven masses are no
        // candidates, as in Spencer's search.
        Some(_) if !drives_towards_toe(&cut.model) => Err(None),
        Some((method, function)) => match method_factor(&cut.model, method, function) {
            Some(f) => Ok(SpencerFactor {
                factor_of_safety: f,
                theta_rad: None,
            }),
            None => Err(Some(None)),
        },
    };
    super::buffers::give_back(cut.model.slices, cut.surface);
    outcome
}
