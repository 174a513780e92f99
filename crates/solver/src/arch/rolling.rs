//! A load rolled across a structure (SPEC §5.3): the live-load factor at each stop of a set of
//! live loads on the same blocks, limits and dead loads.
//!
//! Consecutive stops share everything but the live loads, so the dead load is checked once, at
//! the first loaded stop: its margin holds for every other stop, which solves the live-load
//! programme alone ([`solve_live_load_after`]; with crushing the dead load is checked again,
//! the cutting planes differing from stop to stop). Given that margin the stops are
//! independent programmes and are solved in parallel on the machine's cores; each answer is
//! the one a sequential sweep gives (the same programmes on the same data).

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use rayon::prelude::*;

use super::equilibrium::LiveLoad;
use super::error::ArchError;
use super::limit::{
    solve_live_load, solve_live_load_after, ArchProblem, LimitSettings, LimitSolution,
};

/// The solutions of a sweep, stop by stop.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// Each stop's solution; `None` where the stop has no live load, or where the time ran out
    /// before it was solved.
    pub stops: Vec<Option<LimitSolution>>,
    /// Wall time of the first loaded stop (the dead-load check included), in seconds.
    pub first_stop_secs: f64,
    /// Whether the time limit ran out before every stop was solved.
    pub out_of_time: bool,
}

/// Solves the live load `loads[i]` on `problem` at every stop i (an empty list: no load there,
/// no solve), within the settings' time limit for the whole sweep.
pub fn sweep_live_loads(
    problem: &ArchProblem,
    settings: &LimitSettings,
    loads: &[Vec<LiveLoad>],
) -> Result<Sweep, ArchError> {
    let start = Instant::now();
    let mut stops: Vec<Option<LimitSolution>> = vec![None; loads.len()];
    let Some(first) = loads.iter().position(|l| !l.is_empty()) else {
        return Ok(Sweep {
            stops,
            first_stop_secs: 0.0,
            out_of_time: false,
        });
    };
    let at = |i: usize| problem.clone().with_live_loads(loads[i].clone());
    let solution = solve_live_load(&at(first)?, settings)?;
    let first_stop_secs = start.elapsed().as_secs_f64();
    let known_margin = match solution.dead_load_carried {
        Some(true) => solution.dead_load_margin,
        _ => None,
    };
    stops[first] = Some(solution);
    let out_of_time = AtomicBool::new(false);
    let rest: Vec<(usize, Option<LimitSolution>)> = (first + 1..loads.len())
        .into_par_iter()
        .filter(|&i| !loads[i].is_empty())
        .map(|i| {
            if out_of_time.load(Ordering::Relaxed)
                || start.elapsed().as_secs_f64() > settings.time_limit_secs
            {
                out_of_time.store(true, Ordering::Relaxed);
                return Ok((i, None));
            }
            let problem = at(i)?;
            let solution = match known_margin {
                Some(margin) => solve_live_load_after(&problem, settings, margin)?,
                None => solve_live_load(&problem, settings)?,
            };
            Ok((i, Some(solution)))
        })
        .collect::<Result<_, ArchError>>()?;
    for (i, solution) in rest {
        stops[i] = solution;
    }
    Ok(Sweep {
        stops,
        first_stop_secs,
        out_of_time: out_of_time.into_inner(),
    })
}
