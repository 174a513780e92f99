//! One programme of an arch analysis: the dead- or live-load programme, or a rolling load's
//! sweep and its critical stop; the non-associative iteration (all of it for
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
use super::plan::{ArchOutcome, ArchPlan, ArchStatus, Friction, Programme, RollingCurve};
use super::rolling::sweep_live_loads;
use super::thrust_line::thrust_line;
use crate::budget::{Budget, Stop};

/// Analyses `problem` under the plan's programme and friction within `budget` (its other
/// stages are [`super::analysis::analyse`]'s). `Err` only for input the solver cannot accept;
/// the time limit is an outcome ([`ArchOutcome::stop`]).
pub fn analyse_programme(
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
    // Stopped by the budget: the answer's own programme (or sweep), or the friction iteration
    // (whose check the answer would otherwise report as not settled).
    let stop = match (solution.stop, friction.as_ref().map(|f| f.solution.stop)) {
        (Stop::Finished, Some(stop)) => stop,
        (stop, _) => stop,
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
        bonded_load_factor: None,
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
/// sweep found it (out of time: with the sweep's stop).
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
        .filter(|_| sweep.stop.is_finished())
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
    if !sweep.stop.is_finished() {
        // The sweep is not finished, and says so through its stop.
        curve.critical = None;
        curve.time_per_stop_ms = 0.0;
        solution.stop = sweep.stop;
    }
    Ok((problem.clone(), solution, curve))
}
