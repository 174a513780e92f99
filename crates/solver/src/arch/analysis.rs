//! One arch analysis: an [`ArchProblem`] and an [`ArchPlan`] analysed within a [`Budget`] into an
//! [`ArchOutcome`]. What runs after what is written here once: the plan's programme
//! ([`super::stage`]: the dead or live load, a rolling load's sweep, friction, the relief of a
//! squeezed state, the line of thrust), then a rolling load's critical position narrowed between
//! the stops ([`super::refine`]), then, where the rings lock, the bonded single ring's λ to
//! compare with.

use super::error::ArchError;
use super::limit::ArchProblem;
pub use super::plan::{
    ArchOutcome, ArchPlan, ArchStatus, Friction, Programme, RefineCritical, RefinedCritical,
    RollingCurve,
};
use super::refine::refine_critical;
use super::stage::analyse_programme;
use crate::budget::Budget;

/// Analyses `problem` as `plan` says within `budget`, every stage of the plan. `Err` only for
/// input the solver cannot accept; the time limit is an outcome ([`ArchOutcome::stop`]).
pub fn analyse(
    problem: &ArchProblem,
    plan: &ArchPlan,
    budget: &Budget,
) -> Result<ArchOutcome, ArchError> {
    let mut outcome = analyse_programme(problem, plan, budget)?;
    if let (Some(refine), Programme::Rolling(_)) = (&plan.refine, &plan.programme) {
        outcome = refine_critical(outcome, problem, plan, refine, budget)?;
    }
    let compare = outcome.stop.is_finished()
        && outcome.solution.load_factor.is_some()
        && plan.programme == Programme::LiveLoad;
    if let Some(bonded) = plan.bonded.as_ref().filter(|_| compare) {
        outcome.bonded_load_factor = bonded_load_factor(bonded, plan, budget)?;
    }
    Ok(outcome)
}

/// The bonded single ring's λ under the plan's programme with the associative rule; `None` when
/// the budget ended it or it has none.
fn bonded_load_factor(
    bonded: &ArchProblem,
    plan: &ArchPlan,
    budget: &Budget,
) -> Result<Option<f64>, ArchError> {
    let at = ArchPlan::new(
        plan.programme.clone(),
        Friction::Associative,
        plan.settings.clone(),
    );
    let single = analyse_programme(bonded, &at, budget)?;
    Ok(single
        .stop
        .is_finished()
        .then_some(single.solution.load_factor)
        .flatten())
}
