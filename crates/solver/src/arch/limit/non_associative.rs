//! Friction as it acts (SPEC §5.5): Coulomb sliding without dilatancy, by the iterative linear
//! programmes of Gilbert, Casapulla & Ahmed (2006). The associative programme makes a sliding
//! joint open as it slides (normality on μ(q + s) ∓ t ≥ 0), which real joints do not; the
//! load factor may then over-estimate (Livesley 1978, §2.7–2.9).
//!
//! The iteration: start from the normal forces N⁰ of the associative solution; at step k solve
//! the programme with the friction rows replaced by fixed capacities |t| ≤ μ·N^(k−1) (shear
//! then limited independently of the normal force: its flow is pure sliding, the corrected
//! mechanism of Livesley §2.7); the normal forces N of that solution are the next step's,
//! N^k = N, as SPEC §5.5 states the procedure (shear capacities from the previous step's normal
//! forces). Relaxing them, N^k = N^(k−1) + ½·(N − N^(k−1)), was this module's first choice: it
//! creeps to the same fixed point by half a step at a time, and settled fewer cases (nine walls
//! of two leaves under a cap: 8–22 steps unrelaxed against 23–51, λ equal to 3e-6, two more
//! settled, none fewer). Stop when the solution's own normal forces
//! carry its shear (|t| ≤ μ·N at every joint, to 1e-7 of the total weight) and no longer move
//! (|N − N^(k−1)| ≤ 1e-7 W): that state is admissible for the associative programme too, so
//! its λ is no more than the associative one. Not settled after [`MAX_STEPS`]: say so.
//!
//! A single step cannot lower λ below the associative answer when started from its normal
//! forces (the associative optimum stays feasible), so the iteration's first λ is ≥ it.

use super::problem::{ArchProblem, LimitSettings, LimitSolution, LimitStatus};
use crate::arch::equilibrium::force_scale;
use crate::arch::mechanism::Mechanism;

/// Steps at most.
pub const MAX_STEPS: usize = 50;

/// Consistency tolerance as a fraction of the total weight.
const SETTLED: f64 = 1e-7;

/// The outcome of the iteration.
#[derive(Debug, Clone, PartialEq)]
pub struct NonAssociative {
    /// The last step's solution (the answer when `settled`); its solver figures are that
    /// step's own, the whole iteration's are in `totals`.
    pub solution: LimitSolution,
    /// The associative solution the iteration started from.
    pub associative: LimitSolution,
    /// λ at each step (the first is the associative programme's).
    pub history: Vec<Option<f64>>,
    /// Whether it reached a state whose normal forces carry its shear.
    pub settled: bool,
    /// The corrected mechanism (Livesley §2.7): the first step's, where sliding joints slide
    /// without opening; `None` when nothing slid or there was no step.
    pub corrected: Option<Mechanism>,
    /// Interior-point iterations, programmes and wall time of the whole iteration (the
    /// associative solve included).
    pub totals: (u32, usize, f64),
}

fn normal_forces(solution: &LimitSolution) -> Vec<f64> {
    solution.resultants.iter().map(|r| r[0] + r[1]).collect()
}

/// The largest violation of Coulomb's |t| ≤ μN over the joints with friction, and the largest
/// change of normal force from `used` over the joints whose shear is at its capacity (where
/// the normal force matters; elsewhere the programme leaves it free), both absolute.
fn inconsistency(
    problem: &ArchProblem,
    solution: &LimitSolution,
    used: &[f64],
    tolerance: f64,
) -> (f64, f64) {
    let mut shear: f64 = 0.0;
    let mut moved: f64 = 0.0;
    for (k, r) in solution.resultants.iter().enumerate() {
        let Some(mu) = problem.material(k).1 else {
            continue;
        };
        let n = r[0] + r[1];
        let before = used.get(k).copied().unwrap_or(0.0).max(0.0);
        shear = shear.max(r[2].abs() - mu * n.max(0.0));
        if r[2].abs() >= mu * before - tolerance {
            moved = moved.max((n - before).abs());
        }
    }
    (shear, moved)
}

/// Runs the iteration with `solve` (the dead- or live-load solve) on `problem`.
/// With `only_if_sliding`, an associative mechanism that does not slide is answered as it is
/// (settled: without sliding, dilatancy plays no part).
pub fn iterate<E>(
    problem: &ArchProblem,
    settings: &LimitSettings,
    only_if_sliding: bool,
    solve: impl Fn(&ArchProblem, &LimitSettings) -> Result<LimitSolution, E>,
) -> Result<NonAssociative, E> {
    let start = std::time::Instant::now();
    let associative = solve(problem, settings)?;
    let single = (
        associative.iterations,
        associative.programmes,
        associative.solve_time_secs,
    );
    let mut history = vec![associative.load_factor];
    let sliding = associative
        .mechanism
        .as_ref()
        .is_some_and(|m| m.involves_friction());
    if only_if_sliding && !sliding && associative.status == LimitStatus::Solved {
        return Ok(NonAssociative {
            solution: associative.clone(),
            associative,
            history,
            settled: true,
            corrected: None,
            totals: single,
        });
    }
    if !problem.has_friction()
        || associative.status != LimitStatus::Solved
        || associative.resultants.is_empty()
    {
        // Nothing slides, or no state to start from: the associative answer stands as it is.
        // Where it is a collapse under less than the load (a dead load not carried), friction
        // that does not dilate can only do worse: that answer is settled too.
        let settled = !problem.has_friction()
            || matches!(
                associative.status,
                LimitStatus::Solved | LimitStatus::DeadLoadNotCarried
            );
        return Ok(NonAssociative {
            solution: associative.clone(),
            associative,
            history,
            settled,
            corrected: None,
            totals: single,
        });
    }
    // The programmes' own force scale W: the blocks' and the other dead loads' weight.
    let weight = force_scale(
        problem.assembly(),
        problem.unit_weight(),
        problem.dead_loads(),
    );
    let tolerance = SETTLED * weight;
    let mut used = normal_forces(&associative);
    let mut corrected = None;
    let mut last = associative.clone();
    let (mut iterations, mut programmes) = (last.iterations, last.programmes);
    for _ in 0..MAX_STEPS {
        let step = solve(&problem.with_fixed_friction(&used), settings)?;
        iterations += step.iterations;
        programmes += step.programmes;
        history.push(step.load_factor);
        if history.len() == 2 && sliding {
            corrected.clone_from(&step.mechanism);
        }
        if step.status != LimitStatus::Solved || step.resultants.is_empty() {
            last = step;
            break;
        }
        let (shear, moved) = inconsistency(problem, &step, &used, tolerance);
        let normal = normal_forces(&step);
        last = step;
        if shear <= tolerance && moved <= tolerance {
            return Ok(NonAssociative {
                solution: last,
                associative,
                history,
                settled: true,
                corrected,
                totals: (iterations, programmes, start.elapsed().as_secs_f64()),
            });
        }
        used = normal;
    }
    Ok(NonAssociative {
        solution: last,
        associative,
        history,
        settled: false,
        corrected,
        totals: (iterations, programmes, start.elapsed().as_secs_f64()),
    })
}

impl NonAssociative {
    /// Whether the associative answer over-estimates: its mechanism slides, and the iteration
    /// either found a lower λ (by more than 1e-6 relative) or did not settle.
    pub fn associative_may_overestimate(&self) -> bool {
        let slides = self
            .associative
            .mechanism
            .as_ref()
            .is_some_and(|m| m.involves_friction());
        let lower = match (self.associative.load_factor, self.solution.load_factor) {
            (Some(a), Some(b)) => b < a - 1e-6 * a.abs().max(1e-12),
            _ => false,
        };
        slides && (!self.settled || lower)
    }
}
