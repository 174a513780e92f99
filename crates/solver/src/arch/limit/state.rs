//! The state shown with an answer of the general (assembly) model.
//!
//! λ and the mechanism are certified by the programme's optimum, but its state need not be
//! unique: where contacts of unlimited shear (supports that cannot slide, joints without
//! friction) close a loop with a contact in compression, a self-stress squeezes the blocks of
//! the loop together without limit — two blocks side by side on a support, the inner and outer
//! ring of an arch at a springing. The interior-point method then ends on a state with normal
//! forces of 1e5 times the weight (measured on wall panels and two-ring arches). Such a state
//! ([`is_squeezed`]) is replaced by the one of least normal force, Σ(q + s) over the normal
//! forces that have a lower bound, among those the limits admit at the answer's factors: a
//! second programme over the resultants alone (see
//! [`super::context::Context::least_normal_state`]), written a hair inside the optimum
//! ([`STATE_BACKOFF`]), where it has an interior. It costs about as much as the first, so it
//! runs only where the state is squeezed.
//!
//! What that state keeps is what the answer needs: a squeeze that gives a sliding contact the
//! normal force its friction needs at collapse stays (bounded by the loads), and a contact
//! that cannot slide may carry shear with no normal force (its limits allow it). Chains are
//! left alone (three redundants, answered as they always were); so are crushing (the crushing
//! curve bounds the normal forces, and its cutting planes belong to the refined problem) and
//! answers without a state.

use std::time::Instant;

use super::context::Context;
use super::problem::{ArchProblem, LimitSettings, LimitSolution, LimitStatus};
use crate::arch::equilibrium::force_scale;

/// How far inside the optimum the state is taken, relative to the factor (or margin): the
/// reactions then carry the loads to 1e-7 of the live load, and the limits hold to the
/// solver's tolerance (a shift of the limits instead put normal forces of −1e-8·W and points
/// of action beyond the faces of lightly loaded contacts into the answer).
const STATE_BACKOFF: f64 = 1e-7;

/// A state is squeezed when a contact carries more than this many times all the loads
/// together. Measured on 23 requests (walls, panels, rings, spans, fill, passive restraint):
/// states without a self-stress 0.39–1.06, the interior-point states with one 137–21,000.
const SQUEEZED: f64 = 10.0;

/// Whether `solution`'s state carries a self-stress worth removing: a contact's force
/// (|q| + |s| + |t|) above [`SQUEEZED`] times the loads the answer carries (the dead weight
/// at its factor, the live loads at theirs, the passive capacities). The interior-point
/// method ends far out along an unbounded self-stress (1e2 to 1e5 times the loads), so a
/// squeeze smaller than that is one the limits bound, and the state is shown as it is.
pub fn is_squeezed(problem: &ArchProblem, solution: &LimitSolution, programme: StateOf) -> bool {
    let Some(factor) = solution.load_factor else {
        return false;
    };
    let dead = force_scale(&problem.assembly, problem.unit_weight, &problem.dead_loads);
    let live: f64 = problem.live_loads.iter().map(|l| l.fx.hypot(l.fy)).sum();
    let passive: f64 = problem.passive.iter().map(|p| p.capacity).sum();
    let loads = match programme {
        DeadLoad => factor * dead,
        LiveLoad => dead + factor.abs() * live,
    } + passive;
    let largest = solution
        .resultants
        .iter()
        .map(|r| r[0].abs() + r[1].abs() + r[2].abs())
        .fold(0.0, f64::max);
    largest > SQUEEZED * loads
}

/// Which of Livesley's programmes an answer is of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StateOf {
    /// The dead-load factor λ₀ (the state at λ₀ and, when carried, at the answer's margin).
    DeadLoad,
    /// The live-load factor λ at full dead load.
    LiveLoad,
}

/// Replaces `solution`'s resultants and passive forces by the state of least normal force at
/// its factors, and adds the programme to its solver figures. Returns whether it did: an answer
/// without a state, a chain, crushing, or a state programme that fails keeps its state.
pub fn show_least_normal_state(
    problem: &ArchProblem,
    settings: &LimitSettings,
    programme: StateOf,
    solution: &mut LimitSolution,
) -> bool {
    if solution.status != LimitStatus::Solved
        || solution.resultants.is_empty()
        || problem.crushing.is_some()
    {
        return false;
    }
    let Some(factor) = solution.load_factor else {
        return false;
    };
    // The states at the optimum lie on the boundary of the admissible set; the programme is
    // written a hair inside it, where it has an interior: the factor backed off by
    // STATE_BACKOFF (its loads are then carried with the limits to spare), or a carried dead
    // load's margin δ < 0 taken as δ·(1 − STATE_BACKOFF). The limits hold as they are.
    let inside = 1.0 - STATE_BACKOFF;
    let (dead, live, margin) = match programme {
        // A carried dead load is shown at its margin (the state farthest inside the limits);
        // otherwise at λ₀, on the limits.
        DeadLoad if solution.dead_load_carried == Some(true) => {
            let margin = solution.dead_load_margin.unwrap_or(0.0).min(0.0);
            (factor, 0.0, margin * inside)
        }
        DeadLoad => (factor * inside, 0.0, 0.0),
        LiveLoad => (1.0, factor * inside, 0.0),
    };
    let start = Instant::now();
    let mut cx = Context::new(problem, settings);
    let state = cx.least_normal_state(dead, live, margin);
    solution.iterations += cx.iterations;
    solution.programmes += cx.programmes;
    solution.solve_time_secs += start.elapsed().as_secs_f64();
    let Some((resultants, passive)) = state else {
        return false;
    };
    solution.resultants = resultants;
    solution.passive = passive;
    true
}

use StateOf::{DeadLoad, LiveLoad};
