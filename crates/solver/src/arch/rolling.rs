//! A load rolled across a structure (model §5.3): the live-load factor at each stop of a set of
//! live loads on the same blocks, limits and dead loads.
//!
//! Consecutive stops share everything but the live loads, so the dead load is checked once, at
//! the first loaded stop: its margin holds for every other stop, which solves the live-load
//! programme alone ([`solve_live_load_after`]; with crushing the dead load is checked again,
//! the cutting planes differing from stop to stop). Given that margin the stops are
//! independent programmes and are solved in parallel on the machine's cores; each answer is
//! the one a sequential sweep gives (the same programmes on the same data).
//!
//! A chain of blocks without crushing, with or without passive restraint (whose interior-point
//! programmes are the general formulation's, milliseconds each), is swept instead by the
//! simplex method warm from stop to stop ([`WarmLiveLoad`]): the optimal basis of one stop
//! starts the next, a few pivots away. Its λ are exact vertices; the stops within 1e-6 of the
//! least λ — the ones that can be critical — are then solved again on the interior-point
//! method, so that the critical stop, its λ and its state are the ones a solve of that stop
//! alone gives. A stop the simplex method cannot certify is solved on the interior-point
//! method too.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::Instant;

use rayon::prelude::*;

use super::equilibrium::LiveLoad;
use super::error::ArchError;
use super::fill::{road_load_on, ExtradosProfile, Fill, RoadLoad};
use super::limit::{
    solve_live_load, solve_live_load_after, ArchProblem, LimitSettings, LimitSolution, LimitStatus,
    WarmLiveLoad,
};
use crate::budget::Stop;

/// One axle of a rolling load, relative to the set's reference point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axle {
    /// Position relative to the reference point.
    pub offset: f64,
    /// Vertical force (up positive), per unit width of the strip analysed.
    pub fy: f64,
    /// Length of its patch on the road (≥ 0).
    pub length: f64,
}

/// A set of axles on the road, dispersed through the fill onto the extrados: the live loads
/// with the set's reference point at any x (a rolling load's stops, and the positions between
/// them that [`super::refine`] tries).
#[derive(Debug, Clone, PartialEq)]
pub struct RollingAxles {
    /// The extrados the loads land on.
    pub profile: ExtradosProfile,
    /// The fill that disperses them.
    pub carrier: Fill,
    /// The axles.
    pub axles: Vec<Axle>,
}

impl RollingAxles {
    /// The live loads with the reference point at x.
    pub fn loads_at(&self, x: f64) -> Vec<LiveLoad> {
        self.axles
            .iter()
            .flat_map(|axle| {
                let load = RoadLoad {
                    x: x + axle.offset,
                    fy: axle.fy,
                    length: axle.length,
                };
                road_load_on(&self.profile, &self.carrier, load)
            })
            .collect()
    }
}

/// The solutions of a sweep, stop by stop.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// Each stop's solution; `None` where the stop has no live load, or where the time ran out
    /// before it was solved. Only the first loaded stop and the critical stop carry their
    /// state (resultants, mechanism, passive forces); the others their status, λ and dead-load
    /// margin.
    pub stops: Vec<Option<LimitSolution>>,
    /// Stops answered by the warm simplex method (the rest: the interior-point method).
    pub simplex_stops: usize,
    /// Pivots of the simplex method over the sweep.
    pub pivots: usize,
    /// Wall time of the first loaded stop (the dead-load check included), in seconds.
    pub first_stop_secs: f64,
    /// How the sweep ended: [`Stop::Finished`], or the budget's reason when it ended the sweep
    /// before every stop was solved.
    pub stop: Stop,
}

impl Sweep {
    /// The critical stop, the one of least λ (the first of equal ones): its index and λ.
    pub fn critical(&self) -> Option<(usize, f64)> {
        least_stop(&self.stops)
    }
}

/// How a sweep ended: `skipped` (the stop that made it skip the stops left), else the stop of a
/// stop's own programme that the budget ended (its λ is not an answer, so neither is the
/// sweep's least).
fn swept_stop(skipped: Stop, stops: &[Option<LimitSolution>]) -> Stop {
    if !skipped.is_finished() {
        return skipped;
    }
    stops
        .iter()
        .flatten()
        .map(|s| s.stop)
        .find(|s| !s.is_finished())
        .unwrap_or(Stop::Finished)
}

/// The stop with the least λ (the first of equal ones) and that λ.
fn least_stop(stops: &[Option<LimitSolution>]) -> Option<(usize, f64)> {
    stops
        .iter()
        .enumerate()
        .filter_map(|(i, s)| s.as_ref().and_then(|s| s.load_factor).map(|f| (i, f)))
        .fold(None, |best, (i, f)| match best {
            Some((_, b)) if b <= f => best,
            _ => Some((i, f)),
        })
}

/// `solution` without its state (resultants, mechanism, passive forces); the whole of it kept
/// in `least` when it is the least stop so far (least λ, then the first of equal ones).
fn keep_if_least(
    least: &Mutex<Option<(usize, LimitSolution)>>,
    i: usize,
    mut solution: LimitSolution,
) -> LimitSolution {
    let bare = LimitSolution {
        status: solution.status,
        stop: solution.stop,
        load_factor: solution.load_factor,
        dead_load_carried: solution.dead_load_carried,
        dead_load_margin: solution.dead_load_margin,
        resultants: Vec::new(),
        mechanism: None,
        iterations: solution.iterations,
        programmes: solution.programmes,
        passive: Vec::new(),
        solve_time_secs: solution.solve_time_secs,
    };
    if let Some(f) = solution.load_factor {
        let mut least = least.lock().unwrap_or_else(|e| e.into_inner());
        let better = match least
            .as_ref()
            .and_then(|(j, s)| s.load_factor.map(|g| (*j, g)))
        {
            Some((j, g)) => f < g || (f == g && i < j),
            None => true,
        };
        if better {
            *least = Some((i, std::mem::replace(&mut solution, bare)));
            return solution;
        }
    }
    bare
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
            stop: Stop::Finished,
            simplex_stops: 0,
            pivots: 0,
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
    let warm = known_margin.and_then(|margin| WarmLiveLoad::new(problem).map(|w| (w, margin)));
    if let Some((warm, margin)) = warm {
        return sweep_warm(problem, settings, loads, first, stops, warm, margin).map(|mut s| {
            s.first_stop_secs = first_stop_secs;
            s
        });
    }
    // Raised by the first stop that finds the budget spent, so that the others skip at once.
    let stopped = AtomicBool::new(false);
    // Only the least stop's state is answered: the others keep their λ alone (a thousand
    // states of a long chain took 270 MB).
    let least = Mutex::new(None);
    let rest: Vec<(usize, Option<LimitSolution>)> = (first + 1..loads.len())
        .into_par_iter()
        .filter(|&i| !loads[i].is_empty())
        .map(|i| {
            if stopped.load(Ordering::Relaxed) || settings.budget.is_spent() {
                stopped.store(true, Ordering::Relaxed);
                return Ok((i, None));
            }
            let problem = at(i)?;
            let solution = match known_margin {
                Some(margin) => solve_live_load_after(&problem, settings, margin)?,
                None => solve_live_load(&problem, settings)?,
            };
            Ok((i, Some(keep_if_least(&least, i, solution))))
        })
        .collect::<Result<_, ArchError>>()?;
    for (i, solution) in rest {
        stops[i] = solution;
    }
    if let Some((i, solution)) = least.into_inner().unwrap_or_else(|e| e.into_inner()) {
        stops[i] = Some(solution);
    }
    let stop = if stopped.into_inner() {
        settings.budget.stop()
    } else {
        Stop::Finished
    };
    Ok(Sweep {
        stop: swept_stop(stop, &stops),
        stops,
        first_stop_secs,
        simplex_stops: 0,
        pivots: 0,
    })
}

/// The stops after `first` by the warm simplex method, one after the other; then the stops
/// that can be critical (and any the method could not certify) on the interior-point method.
fn sweep_warm(
    problem: &ArchProblem,
    settings: &LimitSettings,
    loads: &[Vec<LiveLoad>],
    first: usize,
    mut stops: Vec<Option<LimitSolution>>,
    mut warm: WarmLiveLoad,
    margin: f64,
) -> Result<Sweep, ArchError> {
    let scene = WarmScene {
        problem,
        settings,
        loads,
        margin,
    };
    let WarmPass {
        simplex_stops,
        pivots,
        stop,
        mut again,
    } = warm_pass(&scene, first, &mut stops, &mut warm);
    again.extend(near_least(&stops, first));
    if !stop.is_finished() {
        // Unfinished: the answer is the first stop's (see the analysis), nothing to confirm.
        again.clear();
    }
    let resolved: Vec<(usize, LimitSolution)> = again
        .into_par_iter()
        .map(|i| Ok((i, scene.solve(i)?)))
        .collect::<Result<_, ArchError>>()?;
    for (i, solution) in resolved {
        stops[i] = Some(solution);
    }
    // Should the interior-point λ of those stops differ from the simplex's by more than 1e-6
    // after all, the least stop (the first of equal ones) might be one without its state:
    // solve it too, until the least has one.
    while let Some((i, _)) = least_stop(&stops).filter(|_| stop.is_finished()) {
        if stops[i].as_ref().is_some_and(|s| !s.resultants.is_empty()) {
            break;
        }
        stops[i] = Some(scene.solve(i)?);
    }
    let stop = swept_stop(stop, &stops);
    Ok(Sweep {
        stops,
        first_stop_secs: 0.0,
        stop,
        simplex_stops,
        pivots,
    })
}

/// What every stop of a warm sweep shares.
struct WarmScene<'a> {
    /// The problem without its live loads.
    problem: &'a ArchProblem,
    /// The interior-point settings (and the sweep's budget).
    settings: &'a LimitSettings,
    /// Each stop's live loads.
    loads: &'a [Vec<LiveLoad>],
    /// The dead load's margin, checked at the first loaded stop.
    margin: f64,
}

impl WarmScene<'_> {
    /// Stop `i` on the interior-point method, given the dead load's margin.
    fn solve(&self, i: usize) -> Result<LimitSolution, ArchError> {
        let at = self
            .problem
            .clone()
            .with_live_loads(self.loads[i].clone())?;
        solve_live_load_after(&at, self.settings, self.margin)
    }
}

/// What the warm simplex method's pass over the stops left.
struct WarmPass {
    /// Stops it answered.
    simplex_stops: usize,
    /// Its pivots.
    pivots: usize,
    /// [`Stop::Finished`], or the budget's stop that ended the pass.
    stop: Stop,
    /// The stops it could not certify, for the interior-point method.
    again: Vec<usize>,
}

/// The stops after `first` by the warm simplex method, one after the other, into `stops`,
/// until the budget ends the pass.
fn warm_pass(
    scene: &WarmScene,
    first: usize,
    stops: &mut [Option<LimitSolution>],
    warm: &mut WarmLiveLoad,
) -> WarmPass {
    let (loads, margin) = (scene.loads, scene.margin);
    let mut pass = WarmPass {
        simplex_stops: 0,
        pivots: 0,
        stop: Stop::Finished,
        again: Vec::new(),
    };
    for i in first + 1..loads.len() {
        if loads[i].is_empty() {
            continue;
        }
        if let Err(spent) = scene.settings.budget.check() {
            pass.stop = spent;
            break;
        }
        let begun = Instant::now();
        match warm.solve(&loads[i]) {
            Ok(answer) => {
                pass.simplex_stops += 1;
                pass.pivots += answer.pivots;
                stops[i] = Some(LimitSolution {
                    status: match answer.load_factor {
                        Some(_) => LimitStatus::Solved,
                        None => LimitStatus::Unbounded,
                    },
                    stop: Stop::Finished,
                    load_factor: answer.load_factor,
                    dead_load_carried: Some(true),
                    dead_load_margin: Some(margin),
                    resultants: Vec::new(),
                    mechanism: None,
                    iterations: 0,
                    programmes: 0,
                    passive: Vec::new(),
                    solve_time_secs: begun.elapsed().as_secs_f64(),
                });
            }
            Err(_) => {
                warm.forget();
                pass.again.push(i);
            }
        }
    }
    pass
}

/// The stops after `first` that can be critical: within 1e-6 of the least λ found by the
/// simplex method (the interior-point λ agree with it to the solver's tolerance, far below
/// that).
fn near_least(stops: &[Option<LimitSolution>], first: usize) -> Vec<usize> {
    let least = (first + 1..stops.len())
        .filter_map(|i| stops[i].as_ref().and_then(|s| s.load_factor))
        .fold(f64::INFINITY, f64::min);
    (first + 1..stops.len())
        .filter(|&i| {
            stops[i]
                .as_ref()
                .and_then(|s| s.load_factor)
                .is_some_and(|f| f <= least + 1e-6 * least.abs())
        })
        .collect()
}
