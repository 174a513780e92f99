//! The limit-analysis linear programmes of a rigid-block assembly (Livesley 1978, §2.3–2.6),
//! solved with Clarabel's interior-point method.
//!
//! # Formulations
//! An interior-point method needs a feasible set with an interior. The textbook dead-load
//! programme — maximise λ₀ with H r + λ₀ w = 0 and the yield limits — does not have one when the
//! structure is too thin (with Heyman's limits its feasible set is then the single point r = 0).
//! So the dead load is measured by a **margin** programme that is always well posed:
//!
//! ```text
//!   margin(λ) = min δ   subject to  H r + λ w = 0,
//!                                    every finite limit relaxed by δ·W  (r⁻ − δW ≤ r ≤ r⁺ + δW,
//!                                    friction rows μ(q+s) ∓ t ≥ −δW),  δ ≥ −1,
//! ```
//!
//! W being the total weight. margin(λ) ≤ 0 exactly when λ·w can be carried; it is convex and
//! piecewise linear in λ with margin(0) ≤ 0 (r = 0 is admissible when every limit admits zero
//! force). Hence λ₀ = 1 when margin(1) ≤ 0; with homogeneous limits (all finite limits zero:
//! Heyman's case, friction) the feasible set is a cone and λ₀ = 0 otherwise; in general λ₀ is the
//! root of margin(λ), found by Newton's method on the convex function (monotone from the right,
//! finite on a piecewise-linear function) with the slope dmargin/dλ = w·y from the multipliers.
//!
//! The live load is the textbook programme, max λ subject to H r + w + λ p = 0 and the limits,
//! solved once the dead load is known to be carried (then r is strictly admissible at λ = 0
//! unless the structure sits exactly at its limit). λ is capped to detect loads that cause no
//! collapse.
//!
//! # Multipliers
//! With Clarabel's convention (min c'x, Ax + s = b, s ∈ K; dual A'z + c = 0) the multipliers y of
//! the equilibrium rows satisfy Hᵀy = z_lower − z_upper: y are the block velocities (u, v, ω)
//! of the collapse mechanism and z the plastic multipliers of the limits, with the loads doing
//! positive work. See [`super::mechanism`].

mod chain_simplex;
mod context;
mod mixing;
pub(crate) mod problem;
mod programme;
mod rows;

use std::convert::Infallible;
use std::time::Instant;

use super::error::{ArchError, ArchParameter};
use super::mechanism::Mechanism;
use crate::outcome::SolverFailure;
use context::{Context, Found, MarginEvaluation, LIVE_LOAD_CAP};
use programme::Programme;

mod crushing;
pub mod non_associative;
mod squeeze;
mod state;
mod warm;

pub use context::on_chain;
pub use problem::{
    ArchProblem, Crushing, Formulation, InterfaceLimits, LimitSettings, LimitSolution, LimitStatus,
    Relaxation,
};
pub use state::{is_squeezed, relieve_squeeze, show_least_normal_state, StateOf};
pub use warm::{WarmLiveLoad, WarmStop};

/// The dead-load margin at full dead load, for the minimum-thickness search.
pub(crate) struct FullDeadLoadMargin {
    /// δ, a fraction of the total weight; ≤ 0 when the weight is carried.
    pub margin: f64,
    /// The collapse mechanism when δ > 0.
    pub mechanism: Option<Mechanism>,
    /// Iterations spent (interior-point iterations; simplex pivots on a chain).
    pub iterations: u32,
}

/// The dead-load margin δ at full dead load with its mechanism.
pub(crate) fn full_dead_load_margin(
    problem: &ArchProblem,
    settings: &LimitSettings,
) -> Result<FullDeadLoadMargin, SolverFailure> {
    let mut cx = Context::new(problem, settings);
    let full = cx.margin(1.0)?;
    let mechanism = if full.value > settings.margin_tolerance {
        cx.mechanism(&full.programme)
    } else {
        None
    };
    Ok(FullDeadLoadMargin {
        margin: full.value,
        mechanism,
        iterations: cx.iterations,
    })
}

/// One dead-load solve with the crushing planes as they are.
fn solve_dead_load_once(problem: &ArchProblem, settings: &LimitSettings) -> LimitSolution {
    let start = Instant::now();
    let mut cx = Context::new(problem, settings);
    let full = match cx.margin(1.0) {
        Ok(e) => e,
        Err(f) => return cx.failed(f, start),
    };
    let tol = settings.margin_tolerance;
    if full.value <= tol {
        let resultants = cx.resultants(&full.programme.x, 1.0, 0.0);
        return cx.finish(
            Found {
                status: LimitStatus::Solved,
                load_factor: Some(1.0),
                dead_load_carried: Some(true),
                dead_load_margin: Some(full.value),
                resultants,
                passive: cx.passive(&full.programme.x),
                mechanism: None,
            },
            start,
        );
    }
    if problem.passive.is_empty()
        && (problem.is_homogeneous() || rigid_cannot_carry(problem, settings))
    {
        // A cone: if λ·w cannot be carried for λ = 1, it cannot for any λ > 0 (passive
        // capacities are fixed forces, not scaled with λ: with them it is not a cone). A
        // finite strength only shrinks what the rigid blocks admit: where they cannot carry
        // the weight, nothing is carried with crushing either.
        let mechanism = cx.mechanism(&full.programme);
        return cx.finish(
            Found {
                status: LimitStatus::Solved,
                load_factor: Some(0.0),
                dead_load_carried: Some(false),
                dead_load_margin: Some(full.value),
                resultants: Vec::new(),
                passive: Vec::new(),
                mechanism,
            },
            start,
        );
    }
    let full_margin = full.value;
    let DeadLoadRoot { lo, hi, carried } = match dead_load_root(&mut cx, full, tol) {
        Ok(root) => root,
        Err(f) => return cx.failed(f, start),
    };
    let (resultants, passive) = carried
        .map(|e| {
            let x = &e.programme.x;
            (cx.resultants(x, e.lambda, 0.0), cx.passive(x))
        })
        .unwrap_or_default();
    let mechanism = cx.mechanism(&hi.programme);
    cx.finish(
        Found {
            status: LimitStatus::Solved,
            load_factor: Some(lo),
            dead_load_carried: Some(false),
            dead_load_margin: Some(full_margin),
            resultants,
            passive,
            mechanism,
        },
        start,
    )
}

/// Where the search for the root of margin(λ) ended.
struct DeadLoadRoot {
    /// The largest λ found carried.
    lo: f64,
    /// The evaluation at the least λ found not carried.
    hi: MarginEvaluation,
    /// The evaluation at `lo`, when one was made.
    carried: Option<MarginEvaluation>,
}

/// Newton from the right on the convex margin(λ), safeguarded by bisection on [lo, hi], from
/// the margin at full dead load (not carried).
fn dead_load_root(
    cx: &mut Context<'_>,
    full: MarginEvaluation,
    tol: f64,
) -> Result<DeadLoadRoot, SolverFailure> {
    let (mut lo, mut hi) = (0.0, full);
    let mut carried: Option<MarginEvaluation> = None;
    for _ in 0..60 {
        let slope = cx.slope(&hi);
        let newton = hi.lambda - hi.value / slope;
        let lambda = if slope > 0.0 && newton.is_finite() && newton > lo && newton < hi.lambda {
            newton
        } else {
            0.5 * (lo + hi.lambda)
        };
        let e = cx.margin(lambda)?;
        if e.value <= tol {
            lo = lambda;
            let done = e.value >= -tol || hi.lambda - lo <= 1e-12;
            carried = Some(e);
            if done {
                break;
            }
        } else {
            hi = e;
        }
        if hi.lambda - lo <= 1e-12 {
            break;
        }
    }
    Ok(DeadLoadRoot { lo, hi, carried })
}

/// Whether the same blocks without crushing, a cone, cannot carry their full dead load.
fn rigid_cannot_carry(problem: &ArchProblem, settings: &LimitSettings) -> bool {
    if problem.crushing.is_none() {
        return false;
    }
    let rigid = ArchProblem {
        crushing: None,
        ..problem.clone()
    };
    rigid.is_homogeneous()
        && Context::new(&rigid, settings)
            .margin(1.0)
            .is_ok_and(|e| e.value > settings.margin_tolerance)
}

/// One live-load solve with the crushing planes as they are.
fn solve_live_load_once(
    problem: &ArchProblem,
    settings: &LimitSettings,
    known_margin: Option<f64>,
) -> Result<LimitSolution, ArchError> {
    let start = Instant::now();
    let mut cx = Context::new(problem, settings);
    if !cx.has_live_load() {
        return Err(ArchError::range(
            ArchParameter::Loads,
            0.0,
            "at least one load with a non-zero force or moment",
        ));
    }
    // The live programme when it was solved beside the dead-load margin.
    let mut solved_beside = None;
    let margin = match known_margin {
        Some(margin) => margin,
        None => {
            let full = if cx.solves_side_by_side() {
                let (full, live) = cx.margin_and_live();
                solved_beside = Some(live);
                full
            } else {
                cx.margin(1.0)
            };
            let full = match full {
                Ok(e) => e,
                Err(f) => return Ok(cx.failed(f, start)),
            };
            if full.value > settings.margin_tolerance {
                let mechanism = cx.mechanism(&full.programme);
                return Ok(cx.finish(
                    Found {
                        status: LimitStatus::DeadLoadNotCarried,
                        load_factor: None,
                        dead_load_carried: Some(false),
                        dead_load_margin: Some(full.value),
                        resultants: Vec::new(),
                        passive: Vec::new(),
                        mechanism,
                    },
                    start,
                ));
            }
            full.value
        }
    };
    let (programme, scale) = match solved_beside.unwrap_or_else(|| cx.live()) {
        Ok(p) => p,
        Err(f) => return Ok(cx.failed(f, start)),
    };
    Ok(live_load_found(&cx, &programme, scale, margin, start))
}

/// The live-load solution read from the live programme's solution (`scale` the live loads'
/// scale), with the dead-load `margin`.
fn live_load_found(
    cx: &Context<'_>,
    programme: &Programme,
    scale: f64,
    margin: f64,
    start: Instant,
) -> LimitSolution {
    let lambda_scaled = programme.x[cx.extra()];
    if lambda_scaled >= LIVE_LOAD_CAP * (1.0 - 1e-6) {
        // No collapse up to the cap; the state there is kept for the non-associative
        // iteration, which starts from it (the service shows none).
        let resultants = cx.resultants(&programme.x, 1.0, lambda_scaled / scale);
        return cx.finish(
            Found {
                status: LimitStatus::Unbounded,
                load_factor: None,
                dead_load_carried: Some(true),
                dead_load_margin: Some(margin),
                resultants,
                passive: Vec::new(),
                mechanism: None,
            },
            start,
        );
    }
    let resultants = cx.resultants(&programme.x, 1.0, lambda_scaled / scale);
    let passive = cx.passive(&programme.x);
    let mechanism = cx.mechanism(programme);
    cx.finish(
        Found {
            status: LimitStatus::Solved,
            load_factor: Some(lambda_scaled / scale),
            dead_load_carried: Some(true),
            dead_load_margin: Some(margin),
            resultants,
            passive,
            mechanism,
        },
        start,
    )
}

/// The dead-load factor λ₀ ≤ 1 (Livesley's dead-load problem) and, when the dead load is not
/// carried, the mechanism in which the structure collapses under it.
pub fn solve_dead_load(problem: &ArchProblem, settings: &LimitSettings) -> LimitSolution {
    crushing::refine(problem, settings, |p, s| Ok(solve_dead_load_once(p, s)))
        .unwrap_or_else(|_| solve_dead_load_once(problem, settings))
}

/// The live-load factor λ (Livesley's live-load problem), given that the dead load is carried.
pub fn solve_live_load(
    problem: &ArchProblem,
    settings: &LimitSettings,
) -> Result<LimitSolution, ArchError> {
    crushing::refine_live(problem, settings, None, solve_live_load_once, final_margin)
}

/// The dead-load margin of `problem` and the interior-point iterations it took (`None` when
/// the programme failed), for [`crushing::refine_live`].
fn final_margin(problem: &ArchProblem, settings: &LimitSettings) -> Option<(f64, u32)> {
    full_dead_load_margin(problem, settings)
        .ok()
        .map(|m| (m.margin, m.iterations))
}

/// Livesley's dead-load problem with friction that does not dilate (model §5.5): see
/// [`non_associative`]; with `only_if_sliding` the iteration runs only when the associative
/// mechanism slides.
pub fn solve_dead_load_non_associative(
    problem: &ArchProblem,
    settings: &LimitSettings,
    only_if_sliding: bool,
) -> non_associative::NonAssociative {
    let solve = |p: &ArchProblem, s: &LimitSettings| -> Result<LimitSolution, Infallible> {
        Ok(solve_dead_load(p, s))
    };
    let step = |p: &ArchProblem, s: &LimitSettings, _: &LimitSolution| solve(p, s);
    match non_associative::iterate(problem, settings, only_if_sliding, solve, step) {
        Ok(outcome) => outcome,
        Err(never) => match never {},
    }
}

/// Livesley's live-load problem with friction that does not dilate (model §5.5): see
/// [`non_associative`]; `only_if_sliding` as for the dead load.
pub fn solve_live_load_non_associative(
    problem: &ArchProblem,
    settings: &LimitSettings,
    only_if_sliding: bool,
) -> Result<non_associative::NonAssociative, ArchError> {
    // The dead load is checked once, by the associative solve: a step's capacities are those
    // of a collapse state, not of the structure under its dead load alone.
    let step = |p: &ArchProblem, s: &LimitSettings, associative: &LimitSolution| {
        let margin = associative.dead_load_margin.unwrap_or(f64::INFINITY);
        solve_live_load_after(p, s, margin)
    };
    let mut outcome =
        non_associative::iterate(problem, settings, only_if_sliding, solve_live_load, step)?;
    let solution = &mut outcome.solution;
    if outcome.settled && solution.load_factor.is_some_and(|l| l < 0.0) {
        // A collapse state below zero live load: without dilatancy the dead load alone is not
        // carried (the steps, the negative λ among them, stay in the history).
        solution.status = LimitStatus::DeadLoadNotCarried;
        solution.load_factor = None;
        solution.dead_load_carried = Some(false);
    }
    Ok(outcome)
}

/// [`solve_live_load`] for a structure whose dead load is known to be carried with margin
/// `dead_load_margin` (≤ the margin tolerance): an earlier solve of the same blocks, limits and
/// dead loads — the previous stop of a rolling load, where only the live loads move. Skips the
/// dead-load programme, half the work of each stop. With crushing the dead load is checked
/// again (the cutting planes differ from stop to stop).
pub fn solve_live_load_after(
    problem: &ArchProblem,
    settings: &LimitSettings,
    dead_load_margin: f64,
) -> Result<LimitSolution, ArchError> {
    let carried = dead_load_margin <= settings.margin_tolerance;
    let known = (carried && problem.crushing.is_none()).then_some(dead_load_margin);
    crushing::refine_live(problem, settings, known, solve_live_load_once, final_margin)
}
