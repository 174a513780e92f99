//! Livesley's two problems with crushing solved to the exact stress-block curve: Kelley's
//! cutting planes. The programme starts with the tangents of [`Crushing::tangent_points`]; at
//! every interface whose resultant lies beyond the curve |q − s| ≤ N·(1 − N/(σ_c·t)), the
//! tangent at its own N is added and the programme solved again, until every interface is
//! within 1e-9 of σ_c·t of the curve. Tangents lie outside the (convex) admissible set, so λ
//! falls monotonically to the exact value. Without crushing, one solve.

use super::problem::{ArchProblem, Crushing, LimitSettings, LimitSolution, LimitStatus};
use crate::arch::error::ArchError;
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
    let solve = |p: &ArchProblem| retrying(p, settings, |s| solve_once(p, s));
    let first = solve(problem)?;
    Ok(rounds(problem, first, solve)?.solution)
}

/// The end of the rounds of cuts.
struct Rounds {
    /// The last round's solution, its iterations and programmes the sum of all rounds'.
    solution: LimitSolution,
    /// The problem with every cut added.
    problem: ArchProblem,
    /// Rounds after the first.
    count: usize,
}

/// From the first round's `solution`, adds the cuts where joints lie beyond the curve and
/// solves again with `solve`, until none does.
fn rounds(
    problem: &ArchProblem,
    first: LimitSolution,
    solve: impl Fn(&ArchProblem) -> Result<LimitSolution, ArchError>,
) -> Result<Rounds, ArchError> {
    let mut solution = first;
    let mut current = problem.clone();
    let Some(crushing) = problem.crushing() else {
        return Ok(Rounds {
            solution,
            problem: current,
            count: 0,
        });
    };
    let mut crushing: Crushing = crushing.clone();
    let (mut iterations, mut programmes) = (solution.iterations, solution.programmes);
    let mut count = 0;
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
        count += 1;
    }
    solution.iterations = iterations;
    solution.programmes = programmes;
    Ok(Rounds {
        solution,
        problem: current,
        count,
    })
}

/// [`refine`] for the live-load problem, whose solve (`solve_once`) checks first that the dead
/// load is carried unless told its margin: the check is made in the first round and once more
/// on the final cuts (`final_margin`: the margin and the interior-point iterations), not in the
/// rounds between — they change only the rows of the live programme, whose λ does not depend
/// on the check. A dead load the final cuts cannot carry is answered by the full solve.
pub(super) fn refine_live(
    problem: &ArchProblem,
    settings: &LimitSettings,
    known_margin: Option<f64>,
    solve_once: impl Fn(&ArchProblem, &LimitSettings, Option<f64>) -> Result<LimitSolution, ArchError>,
    final_margin: impl Fn(&ArchProblem, &LimitSettings) -> Option<(f64, u32)>,
) -> Result<LimitSolution, ArchError> {
    let solve =
        |p: &ArchProblem, known: Option<f64>| retrying(p, settings, |s| solve_once(p, s, known));
    let first = solve(problem, known_margin)?;
    let carried = first
        .dead_load_margin
        .filter(|m| first.status == LimitStatus::Solved && *m <= settings.margin_tolerance);
    let (Some(first_margin), Some(_)) = (carried, problem.crushing()) else {
        return Ok(first);
    };
    let Rounds {
        mut solution,
        problem: last,
        count,
    } = rounds(problem, first, |p| solve(p, Some(first_margin)))?;
    if count > 0 {
        let (iterations, programmes) = (solution.iterations, solution.programmes);
        match final_margin(&last, settings) {
            Some((margin, its)) if margin <= settings.margin_tolerance => {
                solution.dead_load_margin = Some(margin);
                solution.iterations = iterations + its;
                solution.programmes = programmes + 1;
            }
            _ => {
                solution = solve(&last, None)?;
                solution.iterations += iterations;
                solution.programmes += programmes;
            }
        }
    }
    Ok(solution)
}

/// `solve` with `settings`; the cuts can make the programme nearly degenerate (tangents close
/// together): where the interior-point method stops short of the tolerance, it is asked again
/// 100 times looser (never looser than 1e-6, still λ to ~1e-7).
fn retrying(
    problem: &ArchProblem,
    settings: &LimitSettings,
    solve: impl Fn(&LimitSettings) -> Result<LimitSolution, ArchError>,
) -> Result<LimitSolution, ArchError> {
    let first = solve(settings)?;
    let reduced = first.status == LimitStatus::SolverFailed(SolverFailure::ReducedAccuracy);
    if reduced && problem.crushing().is_some() && settings.tolerance < 1e-6 {
        let looser = LimitSettings {
            tolerance: (settings.tolerance * 100.0).min(1e-6),
            ..settings.clone()
        };
        return solve(&looser);
    }
    Ok(first)
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
