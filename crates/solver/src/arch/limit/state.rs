//! The state shown with an answer of the general (assembly) model.
//!
//! λ and the mechanism are certified by the programme's optimum, but its state need not be
//! unique: where contacts of unlimited shear (supports that cannot slide, joints without
//! friction) close a loop with a contact in compression, a self-stress squeezes the blocks of
//! the loop together without limit — two blocks side by side on a support, the inner and outer
//! ring of an arch at a springing. The interior-point method then ends on a state with normal
//! forces of 1e5 times the weight (measured on wall panels and two-ring arches). Such a state
//! ([`is_squeezed`]) is relieved ([`relieve_squeeze`]): first on the contacts that carry more
//! than the loads, every other contact held ([`super::squeeze`]: a programme as small as the
//! squeeze); where that is not enough, replaced by the whole structure's state of least normal
//! force, Σ(q + s) over the normal forces that have a lower bound, among those the limits admit
//! at the answer's factors ([`show_least_normal_state`]: a second programme over the
//! resultants alone, written a hair inside the optimum, [`STATE_BACKOFF`], where it has an
//! interior; it costs about as much as the first). States that are not squeezed run neither.
//!
//! What that state keeps is what the answer needs: a squeeze that gives a sliding contact the
//! normal force its friction needs at collapse stays (bounded by the loads), and a contact
//! that cannot slide may carry shear with no normal force (its limits allow it). Chains are
//! left alone (three redundants, answered as they always were); so are crushing (the crushing
//! curve bounds the normal forces, and its cutting planes belong to the refined problem) and
//! answers without a state.

use std::time::Instant;

use super::context::{on_chain, Context};
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
    largest_force(&solution.resultants) > SQUEEZED * carried_loads(problem, factor, programme)
}

/// The loads an answer carries: the dead weight at its factor (dead load) or whole (live
/// load) with the live loads at theirs, and the passive capacities.
fn carried_loads(problem: &ArchProblem, factor: f64, programme: StateOf) -> f64 {
    let dead = force_scale(&problem.assembly, problem.unit_weight, &problem.dead_loads);
    let live: f64 = problem.live_loads.iter().map(|l| l.fx.hypot(l.fy)).sum();
    let passive: f64 = problem.passive.iter().map(|p| p.capacity).sum();
    let loads = match programme {
        DeadLoad => factor * dead,
        LiveLoad => dead + factor.abs() * live,
    } + passive;
    loads.max(f64::MIN_POSITIVE)
}

/// The force at a contact, |q| + |s| + |t|.
fn force(r: &[f64; 3]) -> f64 {
    r[0].abs() + r[1].abs() + r[2].abs()
}

/// The largest [`force`] of a state.
fn largest_force(resultants: &[[f64; 3]]) -> f64 {
    resultants.iter().map(force).fold(0.0, f64::max)
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
/// its factors (the whole structure's programme), and adds the programme to its solver
/// figures. Returns whether it did: an answer without a state, a chain, crushing, or a state
/// programme that fails keeps its state.
pub fn show_least_normal_state(
    problem: &ArchProblem,
    settings: &LimitSettings,
    programme: StateOf,
    solution: &mut LimitSolution,
) -> bool {
    let Some(at) = state_at(problem, settings, solution, programme) else {
        return false;
    };
    let start = Instant::now();
    let mut cx = Context::new(problem, settings);
    let state = least_inside(&mut cx, at);
    replace(solution, &cx, start, state)
}

/// Relieves a squeezed state ([`is_squeezed`]): first on the contacts that carry more than the
/// loads, every other contact held (a programme as small as the squeeze, at the answer's own
/// factors: see [`super::squeeze`]); where that leaves it squeezed or does not solve, the state
/// of least normal force of the whole structure ([`show_least_normal_state`]). Returns whether
/// the state was replaced; a state that is not squeezed is left as it is.
pub fn relieve_squeeze(
    problem: &ArchProblem,
    settings: &LimitSettings,
    programme: StateOf,
    solution: &mut LimitSolution,
) -> bool {
    let Some(at) = state_at(problem, settings, solution, programme) else {
        return false;
    };
    let loads = carried_loads(problem, at.factor, programme);
    if largest_force(&solution.resultants) <= SQUEEZED * loads {
        return false;
    }
    let contacts: Vec<usize> = (solution.resultants.iter().enumerate())
        .filter(|(_, r)| force(r) > loads)
        .map(|(k, _)| k)
        .collect();
    let start = Instant::now();
    let mut cx = Context::new(problem, settings);
    // A carried dead load's margin backed off as for the whole programme (the contacts' rows
    // at the margin leave no interior). A squeeze over most contacts is the whole programme
    // at the optimum, which has none either.
    let (dead, live, margin) = at.factors();
    let local = 2 * contacts.len() <= solution.resultants.len();
    let state = local
        .then(|| {
            let (resultants, passive) = (&solution.resultants, &solution.passive);
            cx.relieve_squeeze(
                dead,
                live,
                margin * inside(),
                resultants,
                passive,
                &contacts,
            )
        })
        .flatten()
        .filter(|(r, _)| largest_force(r) <= SQUEEZED * loads)
        .or_else(|| least_inside(&mut cx, at));
    replace(solution, &cx, start, state)
}

/// The factors and margin of an answer's state.
#[derive(Clone, Copy)]
struct StateAt {
    programme: StateOf,
    factor: f64,
    /// A carried dead load's margin δ ≤ 0 (the state farthest inside the limits); otherwise
    /// None (the state at λ₀ or λ, on the limits).
    margin: Option<f64>,
}

impl StateAt {
    /// (dead-load factor, live-load factor, margin).
    fn factors(self) -> (f64, f64, f64) {
        match (self.programme, self.margin) {
            (DeadLoad, margin) => (self.factor, 0.0, margin.unwrap_or(0.0)),
            (LiveLoad, _) => (1.0, self.factor, 0.0),
        }
    }
}

/// Where `solution`'s state lies; None for an answer without one, a chain's (three
/// redundants) and crushing (the curve bounds the normal forces, and its cutting planes
/// belong to the refined problem).
fn state_at(
    problem: &ArchProblem,
    settings: &LimitSettings,
    solution: &LimitSolution,
    programme: StateOf,
) -> Option<StateAt> {
    let has_state = solution.status == LimitStatus::Solved && !solution.resultants.is_empty();
    if !has_state || problem.crushing.is_some() || on_chain(problem, settings) {
        return None;
    }
    let carried = programme == DeadLoad && solution.dead_load_carried == Some(true);
    Some(StateAt {
        programme,
        factor: solution.load_factor?,
        margin: carried.then(|| solution.dead_load_margin.unwrap_or(0.0).min(0.0)),
    })
}

/// The whole structure's least state. The states at the optimum lie on the boundary of the
/// admissible set; the programme is written a hair inside, where it has an interior: the
/// factor backed off by [`STATE_BACKOFF`] (its loads are then carried with the limits to
/// spare), or a carried dead load's margin δ < 0 taken as δ·(1 − STATE_BACKOFF). The limits
/// hold as they are.
fn least_inside(cx: &mut Context, at: StateAt) -> Option<(Vec<[f64; 3]>, Vec<f64>)> {
    let inside = inside();
    let (dead, live, margin) = at.factors();
    match (at.programme, at.margin) {
        (DeadLoad, Some(_)) => cx.least_normal_state(dead, live, margin * inside),
        (DeadLoad, None) => cx.least_normal_state(dead * inside, live, margin),
        (LiveLoad, _) => cx.least_normal_state(dead, live * inside, margin),
    }
}

/// 1 − [`STATE_BACKOFF`].
fn inside() -> f64 {
    1.0 - STATE_BACKOFF
}

/// Puts `state` (if any) into `solution` with the solver figures of `cx` since `start`.
fn replace(
    solution: &mut LimitSolution,
    cx: &Context,
    start: Instant,
    state: Option<(Vec<[f64; 3]>, Vec<f64>)>,
) -> bool {
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
