//! One arch analysis: an [`ArchProblem`] and an [`ArchPlan`] (which programme, how friction is
//! treated) analysed within a [`Budget`] into an [`ArchOutcome`].
//!
//! What runs after what is written here once: the dead- or live-load programme, or a rolling
//! load's sweep and its critical stop; the non-associative iteration (all of it for
//! [`Friction::NonAssociative`], whose answer it then is; only as a check when the associative
//! mechanism slides, for [`Friction::Checked`]); the relief of a state squeezed by a
//! self-stress (associative answers only); the line of thrust of the state answered.

use std::time::Instant;

use super::equilibrium::LiveLoad;
use super::error::ArchError;
use super::limit::non_associative::NonAssociative;
use super::limit::{
    relieve_squeeze, solve_dead_load, solve_dead_load_non_associative, solve_live_load,
    solve_live_load_non_associative, ArchProblem, LimitSettings, LimitSolution, LimitStatus,
    StateOf,
};
use super::rolling::sweep_live_loads;
use super::thrust_line::{thrust_line, ThrustPoint};
use crate::budget::{Budget, Stop};
use crate::outcome::SolverFailure;

/// Which of Livesley's programmes, and over which loads.
#[derive(Debug, Clone, PartialEq)]
pub enum Programme {
    /// The largest factor on the dead load that can be carried (λ₀, stopping at 1).
    DeadLoad,
    /// The factor on the problem's live loads at collapse.
    LiveLoad,
    /// The live-load factor at every stop of a rolling load (the live loads of stop i; an
    /// empty list: nothing on the structure there); the critical stop is answered.
    Rolling(Vec<Vec<LiveLoad>>),
}

/// How Coulomb friction is treated (Livesley §2.7–2.9).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Friction {
    /// The associative programme alone (or no friction at all).
    Associative,
    /// The associative answer, checked by the non-associative iteration when its mechanism
    /// slides (whether the factor may be an over-estimate).
    Checked,
    /// The non-associative iteration's own answer.
    NonAssociative,
}

/// Every option of an arch analysis, resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct ArchPlan {
    /// The programme.
    pub programme: Programme,
    /// The treatment of friction.
    pub friction: Friction,
    /// The interior-point settings (their time limit is narrowed to the budget's).
    pub settings: LimitSettings,
}

/// λ at each stop of a rolling load, and its critical stop.
#[derive(Debug, Clone, PartialEq)]
pub struct RollingCurve {
    /// λ at each stop; `None` where nothing stands on the structure or no finite λ collapses it.
    pub load_factors: Vec<Option<f64>>,
    /// The critical stop (least λ, the first of equal ones) and its λ; `None` when no stop has
    /// a λ or the sweep did not finish.
    pub critical: Option<(usize, f64)>,
    /// Wall time per stop over the whole sweep, in milliseconds (0 when it did not finish).
    pub time_per_stop_ms: f64,
    /// Wall time of the first loaded stop (a cold start) in milliseconds.
    pub first_stop_ms: f64,
    /// The critical position narrowed between the stops, when asked for
    /// ([`super::refine::refine_critical`]).
    pub refined: Option<RefinedCritical>,
}

/// A critical position narrowed between the stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RefinedCritical {
    /// The position of least λ found.
    pub position: f64,
    /// λ there.
    pub load_factor: f64,
    /// Half the final bracket: how far the least λ may lie from `position` (λ unimodal there).
    pub error: f64,
    /// Live-load analyses the search ran.
    pub evaluations: usize,
}

/// How an arch analysis' answer stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArchStatus {
    /// The programme's own status.
    Limit(LimitStatus),
    /// [`Friction::NonAssociative`]: the iteration did not settle; no factor is answered.
    NotSettled,
}

/// What an arch analysis found.
#[derive(Debug, Clone)]
pub struct ArchOutcome {
    /// The problem answered: the plan's, or a rolling load's critical stop's.
    pub problem: ArchProblem,
    /// Its solution (for [`Friction::NonAssociative`], the iteration's); its `solve_time_secs`
    /// is the wall time of the whole analysis.
    pub solution: LimitSolution,
    /// How the answer stands.
    pub status: ArchStatus,
    /// How the analysis ended: [`Stop::Finished`], or the budget's reason.
    pub stop: Stop,
    /// The points of action at the interfaces of the state answered.
    pub thrust_line: Vec<ThrustPoint>,
    /// With a rolling load: λ at each stop.
    pub rolling: Option<RollingCurve>,
    /// With friction: the non-associative iteration, when it ran.
    pub friction: Option<NonAssociative>,
}

/// Analyses `problem` as `plan` says within `budget`. `Err` only for input the solver cannot
/// accept; the time limit is an outcome ([`ArchOutcome::stop`]).
pub fn analyse(
    problem: &ArchProblem,
    plan: &ArchPlan,
    budget: &Budget,
) -> Result<ArchOutcome, ArchError> {
    let start = Instant::now();
    // Every programme, cutting-plane round, friction step and rolling stop asks the budget.
    let settings = LimitSettings {
        budget: budget.clone(),
        ..plan.settings.clone()
    };
    let is_non_associative = plan.friction == Friction::NonAssociative;
    let (problem, mut solution, rolling, friction) = match &plan.programme {
        Programme::Rolling(stops) => {
            let (problem, solution, curve) = roll(problem, &settings, stops)?;
            // The friction check at the critical stop, when it slides.
            let check = (plan.friction != Friction::Associative
                && solution
                    .mechanism
                    .as_ref()
                    .is_some_and(|m| m.involves_friction()))
            .then(|| solve_live_load_non_associative(&problem, &settings, true))
            .and_then(Result::ok);
            (problem, solution, Some(curve), check)
        }
        Programme::DeadLoad | Programme::LiveLoad => {
            let (solution, friction) =
                solve_with_friction(problem, &plan.programme, plan.friction, &settings)?;
            (problem.clone(), solution, None, friction)
        }
    };
    if !is_non_associative {
        // A state squeezed by a self-stress (assemblies) is relieved; a non-associative answer
        // keeps its iteration's state.
        let of = match plan.programme {
            Programme::DeadLoad => StateOf::DeadLoad,
            Programme::LiveLoad | Programme::Rolling(_) => StateOf::LiveLoad,
        };
        relieve_squeeze(&problem, &settings, of, &mut solution);
    }
    let mut status = ArchStatus::Limit(solution.status);
    if is_non_associative && friction.as_ref().is_some_and(|f| !f.settled) {
        // No factor the iteration cannot vouch for; its steps are in `friction`.
        status = ArchStatus::NotSettled;
        solution.load_factor = None;
    }
    if solution.status == LimitStatus::Unbounded {
        // The state at the cap of λ (the non-associative iteration's start): not an answer.
        solution.resultants.clear();
    }
    // Stopped at the time limit: the answer's own programme, or the friction iteration (whose
    // check the answer would otherwise report as not settled).
    let out_of_time =
        |status: LimitStatus| status == LimitStatus::SolverFailed(SolverFailure::MaxTime);
    let stop = if out_of_time(solution.status)
        || friction
            .as_ref()
            .is_some_and(|f| out_of_time(f.solution.status))
    {
        budget.out_of_time()
    } else {
        Stop::Finished
    };
    let thrust_line = thrust_line(problem.assembly(), &solution.resultants);
    // The answer's time is the whole analysis': every programme, round, step and stop.
    solution.solve_time_secs = start.elapsed().as_secs_f64();
    Ok(ArchOutcome {
        problem,
        solution,
        status,
        stop,
        thrust_line,
        rolling,
        friction,
    })
}

/// One dead- or live-load solve; with friction other than associative, the non-associative
/// iteration too (all of it, or only when the associative mechanism slides).
fn solve_with_friction(
    problem: &ArchProblem,
    programme: &Programme,
    friction: Friction,
    settings: &LimitSettings,
) -> Result<(LimitSolution, Option<NonAssociative>), ArchError> {
    let is_dead = matches!(programme, Programme::DeadLoad);
    if friction == Friction::Associative || !problem.has_friction() {
        let solution = if is_dead {
            solve_dead_load(problem, settings)
        } else {
            solve_live_load(problem, settings)?
        };
        return Ok((solution, None));
    }
    let is_non_associative = friction == Friction::NonAssociative;
    let iteration = if is_dead {
        solve_dead_load_non_associative(problem, settings, !is_non_associative)
    } else {
        solve_live_load_non_associative(problem, settings, !is_non_associative)?
    };
    let mut solution = if is_non_associative {
        iteration.solution.clone()
    } else {
        iteration.associative.clone()
    };
    // The answer's solver figures count the whole iteration (the check included).
    (
        solution.iterations,
        solution.programmes,
        solution.solve_time_secs,
    ) = iteration.totals;
    Ok((solution, Some(iteration)))
}

/// Solves the live load at every stop; the critical stop's problem and solution with the
/// curve. Out of time, or with no stop that collapses, the first loaded stop's answer as the
/// sweep found it (out of time: with the time limit as its status).
fn roll(
    problem: &ArchProblem,
    settings: &LimitSettings,
    stops: &[Vec<LiveLoad>],
) -> Result<(ArchProblem, LimitSolution, RollingCurve), ArchError> {
    let start = Instant::now();
    let sweep = sweep_live_loads(problem, settings, stops)?;
    let load_factors = sweep
        .stops
        .iter()
        .map(|s| s.as_ref().and_then(|s| s.load_factor))
        .collect();
    let best = sweep.critical();
    let elapsed_ms = start.elapsed().as_secs_f64() * 1e3;
    let mut curve = RollingCurve {
        load_factors,
        critical: best,
        time_per_stop_ms: elapsed_ms / stops.len().max(1) as f64,
        first_stop_ms: sweep.first_stop_secs * 1e3,
        refined: None,
    };
    let mut solutions = sweep.stops;
    let critical = best
        .filter(|_| !sweep.out_of_time)
        .and_then(|(i, _)| solutions[i].take().map(|s| (i, s)));
    if let Some((i, solution)) = critical {
        let problem = problem.clone().with_live_loads(stops[i].clone())?;
        return Ok((problem, solution, curve));
    }
    let mut solution = solutions
        .into_iter()
        .flatten()
        .next()
        .map_or_else(|| solve_live_load(problem, settings), Ok)?;
    if sweep.out_of_time {
        // The sweep is not finished, and says so through the status.
        curve.critical = None;
        curve.time_per_stop_ms = 0.0;
        solution.status = LimitStatus::SolverFailed(SolverFailure::MaxTime);
    }
    Ok((problem.clone(), solution, curve))
}
