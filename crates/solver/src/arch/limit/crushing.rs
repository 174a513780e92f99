//! Livesley's two problems with crushing solved to the exact stress-block curve: Kelley's
//! cutting planes. The programme starts with the tangents of [`Crushing::tangent_points`]; at
//! every interface whose resultant lies beyond the curve |q − s| ≤ N·(1 − N/(σ_c·t)), the
//! tangent at its own N is added and the programme solved again, until every interface is
//! within 1e-9 of σ_c·t of the curve. Tangents lie outside the (convex) admissible set, so λ
//! falls monotonically to the exact value. Without crushing, one solve.

use super::problem::{ArchProblem, Crushing, LimitSettings, LimitSolution, LimitStatus};
use crate::arch::ArchError;
use crate::outcome::SolverFailure;

/// Rounds of cuts at most (each adds at most two rows per interface).
const MAX_ROUNDS: usize = 30;

/// How far beyond the curve a resultant may lie, as a fraction of σ_c·t.
const ON_CURVE: f64 = 1e-9;

/// Solves with `solve_once`, adding cuts until every joint lies on or inside the exact curve.
pub(super) fn refine(
    problem: &ArchProblem,
    settings: &LimitSettings,
    solve_once: impl Fn(&ArchProblem, &LimitSettings) -> Result<LimitSolution, ArchError>,
) -> Result<LimitSolution, ArchError> {
    // The cuts can make the programme nearly degenerate (tangents close together): where the
    // interior-point method stops short of the tolerance, it is asked again 100 times looser
    // (never looser than 1e-6, still λ to ~1e-7).
    let solve = |p: &ArchProblem| -> Result<LimitSolution, ArchError> {
        let first = solve_once(p, settings)?;
        let reduced = first.status == LimitStatus::SolverFailed(SolverFailure::ReducedAccuracy);
        if reduced && p.crushing().is_some() && settings.tolerance < 1e-6 {
            let looser = LimitSettings {
                tolerance: (settings.tolerance * 100.0).min(1e-6),
                ..*settings
            };
            return solve_once(p, &looser);
        }
        Ok(first)
    };
    let mut solution = solve(problem)?;
    let Some(crushing) = problem.crushing() else {
        return Ok(solution);
    };
    let mut current = problem.clone();
    let mut crushing: Crushing = crushing.clone();
    let mut iterations = solution.iterations;
    let mut programmes = solution.programmes;
    for _ in 0..MAX_ROUNDS {
        let cuts = violations(&current, &crushing, &solution);
        if cuts.is_empty() {
            break;
        }
        crushing.cuts.extend(cuts);
        current = current.with_crushing(crushing.clone())?;
        solution = solve(&current)?;
        iterations += solution.iterations;
        programmes += solution.programmes;
    }
    solution.iterations = iterations;
    solution.programmes = programmes;
    Ok(solution)
}

/// The tangents to add: (interface, N/(σ_c·t)) where the resultant lies beyond the curve.
fn violations(
    problem: &ArchProblem,
    crushing: &Crushing,
    solution: &LimitSolution,
) -> Vec<(usize, f64)> {
    let tangent_points = crushing.tangent_points();
    solution
        .resultants
        .iter()
        .enumerate()
        .filter_map(|(k, &[q, s, _])| {
            let capacity = crushing.strength * problem.assembly().interfaces[k].length();
            let n = ((q + s) / capacity).clamp(0.0, 1.0);
            let beyond = (q - s).abs() - (q + s) * (1.0 - n);
            // A tangent next to one already there adds nothing but degeneracy.
            let known = tangent_points
                .iter()
                .copied()
                .chain(crushing.cuts.iter().filter(|c| c.0 == k).map(|c| c.1))
                .any(|m| (m - n).abs() < 1e-9);
            (beyond > ON_CURVE * capacity && !known).then_some((k, n))
        })
        .collect()
}
