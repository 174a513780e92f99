//! F independent of the number of slices: the slices are doubled from the requested count until
//! F changes by less than a relative tolerance (the accuracy control of the service; the
//! F-against-N table of docs/accuracy.md shows the error falling as 1/N², so each doubling cuts
//! it about fourfold).

use std::num::NonZeroUsize;

use super::error::SlopeError;
use super::slices::Sliced;
use super::spencer::{solve_spencer, SpencerSettings, SpencerSolution};
use crate::budget::{Budget, Stop};

/// Settings of a slice refinement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RefinementSettings {
    /// Relative change of F between two doublings that counts as settled.
    pub tolerance: f64,
    /// No more slices than this. Defaults to 10000.
    pub max_slices: usize,
    /// Settings of each Spencer solution.
    pub spencer: SpencerSettings,
}

impl RefinementSettings {
    /// Refinement to `tolerance` with the other settings at their defaults.
    pub fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            max_slices: 10_000,
            spencer: SpencerSettings::default(),
        }
    }
}

/// F at one slice count.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RefinementStep {
    /// Number of slices.
    pub slices: usize,
    /// F with that many slices; `None` where the equations had no solution.
    pub factor_of_safety: Option<f64>,
}

/// How a refinement ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RefinementStatus {
    /// The last doubling changed F by less than the tolerance.
    Settled,
    /// The slice limit was reached first.
    SliceLimit,
}

/// The finest problem solved, its solution and the steps that led there.
#[derive(Debug, Clone, PartialEq)]
pub struct RefinedSolution<P> {
    /// How it ended.
    pub status: RefinementStatus,
    /// The problem at the last slice count.
    pub problem: P,
    /// Its solution.
    pub solution: SpencerSolution,
    /// F at each slice count tried, the last one answered.
    pub steps: Vec<RefinementStep>,
}

/// Solves `problem`, then doubles its slices until F settles within the tolerance; no doubling
/// starts once `budget` is spent, and the refinement then answers the budget's stop instead.
pub fn refine_slices<P: Sliced>(
    problem: P,
    settings: &RefinementSettings,
    budget: &Budget,
) -> Result<Result<RefinedSolution<P>, Stop>, SlopeError> {
    let mut solution = solve_spencer(&problem.model(), &settings.spencer);
    let mut problem = problem;
    let mut steps = vec![RefinementStep {
        slices: problem.slice_count(),
        factor_of_safety: solution.factor_of_safety,
    }];
    let status = loop {
        let doubled =
            NonZeroUsize::new(2 * problem.slice_count()).filter(|n| n.get() <= settings.max_slices);
        let Some(doubled) = doubled else {
            break RefinementStatus::SliceLimit;
        };
        if let Err(stop) = budget.check() {
            return Ok(Err(stop));
        }
        let finer = problem.with_slices(doubled)?;
        let finer_solution = solve_spencer(&finer.model(), &settings.spencer);
        let doubled = NonZeroUsize::new(finer.slice_count()).unwrap_or(doubled);
        steps.push(RefinementStep {
            slices: doubled.get(),
            factor_of_safety: finer_solution.factor_of_safety,
        });
        let settled = match (solution.factor_of_safety, finer_solution.factor_of_safety) {
            (Some(a), Some(b)) => (a - b).abs() <= settings.tolerance * b,
            _ => false,
        };
        (problem, solution) = (finer, finer_solution);
        if settled {
            break RefinementStatus::Settled;
        }
    };
    Ok(Ok(RefinedSolution {
        status,
        problem,
        solution,
        steps,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::spencer_1967;

    #[test]
    fn spencer_example_refined_from_ten_slices_reaches_the_converged_f() {
        // Spencer (1967) example: converged F = 1.0695 (model §2.3). From 10 slices (F = 1.07188
        // in the thesis' table) the doublings settle to 1e-5; the answer is within 5e-5 of the
        // published four digits (their rounding).
        let settings = RefinementSettings::new(1e-5);
        let refined = refine_slices(spencer_1967::problem(10), &settings, &Budget::unlimited())
            .unwrap()
            .unwrap();
        assert_eq!(refined.status, RefinementStatus::Settled);
        let f = refined.solution.factor_of_safety.unwrap();
        assert!((f - spencer_1967::FACTOR_OF_SAFETY).abs() < 5e-5, "F = {f}");
        // Each step doubles the slices, and the last two agree to the tolerance.
        let steps = &refined.steps;
        assert!(steps.windows(2).all(|w| w[1].slices == 2 * w[0].slices));
        let (a, b) = (
            steps[steps.len() - 2].factor_of_safety.unwrap(),
            steps[steps.len() - 1].factor_of_safety.unwrap(),
        );
        assert!((a - b).abs() <= 1e-5 * b);
        assert_eq!(
            refined.problem.geometry.slices.len(),
            steps[steps.len() - 1].slices
        );
    }

    #[test]
    fn the_slice_limit_and_the_deadline_end_a_refinement_honestly() {
        // A tolerance no doubling can meet stops at the slice limit, not in a loop.
        let settings = RefinementSettings {
            max_slices: 80,
            ..RefinementSettings::new(1e-15)
        };
        let refined = refine_slices(spencer_1967::problem(10), &settings, &Budget::unlimited())
            .unwrap()
            .unwrap();
        assert_eq!(refined.status, RefinementStatus::SliceLimit);
        assert_eq!(refined.steps.len(), 4); // 10, 20, 40, 80

        // A spent budget stops before the first doubling.
        let spent = Budget::with_time_limit(std::time::Duration::ZERO);
        let settings = RefinementSettings::new(1e-15);
        let refined = refine_slices(spencer_1967::problem(10), &settings, &spent).unwrap();
        assert!(matches!(refined, Err(Stop::TimeLimit)));
    }

    #[test]
    fn a_problem_with_external_loads_is_not_re_cut() {
        let mut problem = spencer_1967::problem(10);
        problem.external_loads.push(crate::slope::ExternalLoad {
            slice: 0,
            fx: 0.0,
            fy: -1.0,
            moment: 0.0,
            passive: false,
        });
        assert!(refine_slices(
            problem,
            &RefinementSettings::new(1e-4),
            &Budget::unlimited()
        )
        .is_err());
    }
}
