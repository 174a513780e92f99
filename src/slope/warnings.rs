//! The warnings of a Spencer answer: what the engineer should look at before trusting F.

use thrustline_solver::slope::SpencerStatus;

use super::report::SolvedSlope;
use crate::limits::MAX_SLICES;
use thrustline_solver::slope::analysis::{Analysed, SearchReport};

/// Every warning that applies to `solved`, in words.
pub fn warnings(solved: &SolvedSlope) -> Vec<String> {
    let solution = &solved.solution;
    let mut warnings = Vec::new();
    match solution.status {
        SpencerStatus::Converged => {}
        SpencerStatus::NoSolution => warnings.push(
            "Spencer's equations have no root for this surface (none with every m_α positive, \
             and none past the poles of m_α with the slices there pressed onto their bases); no \
             factor of safety is reported"
                .to_owned(),
        ),
        SpencerStatus::MomentOnly => warnings.push(
            "φ' = 0 and no parallel inter-slice forces satisfy force equilibrium: F is from \
             moment equilibrium alone (exact for a circle when φ' = 0); θ is undefined and the \
             slice forces are Bishop's (θ = 0)"
                .to_owned(),
        ),
        SpencerStatus::Unphysical => warnings.push(format!(
            "the equilibrium equations have a root F = {:e} that is not physical (F outside \
             1e-6…1e6, or the mass held up by tension at the base: Σ N'·tan φ' < 0); no factor \
             of safety is reported — negative_effective_stress: drop_friction solves such \
             surfaces without tension",
            solution.unphysical_root.unwrap_or(f64::NAN)
        )),
    }
    let one_based = |list: &[usize]| {
        list.iter()
            .map(|i| (i + 1).to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    if !solution.small_m_alpha_slices.is_empty() {
        warnings.push(format!(
            "m_alpha < {} at slices {}: base forces there are sensitive to F",
            thrustline_solver::slope::spencer::SMALL_DENOMINATOR,
            one_based(&solution.small_m_alpha_slices)
        ));
    }
    if !solution.tension_dropped_slices.is_empty() {
        warnings.push(format!(
            "bases in tension at slices {}: their strength in tension was dropped \
             (negative_effective_stress) and the equations solved again",
            one_based(&solution.tension_dropped_slices)
        ));
    }
    if !solution.negative_effective_normal_slices.is_empty() {
        warnings.push(format!(
            "negative effective normal force (tension) at slices {}",
            one_based(&solution.negative_effective_normal_slices)
        ));
    }
    let outside: Vec<usize> = solution
        .thrust_line
        .iter()
        .filter(|t| !t.is_inside_slice)
        .map(|t| t.boundary)
        .collect();
    if !outside.is_empty() {
        warnings.push(format!(
            "the line of thrust leaves the sliding mass at boundaries {}",
            outside
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    if let Some(refinement) = solved.refinement.as_ref().filter(|r| !r.is_settled) {
        warnings.push(format!(
            "slice_tolerance {} not reached before {MAX_SLICES} slices",
            refinement.tolerance
        ));
    }
    if let Some(search) = &solved.search {
        search_warnings(search, solution.factor_of_safety, &mut warnings);
    }
    if let Some(beyond) = beyond_the_ground(solved) {
        warnings.push(beyond);
    }
    warnings
}

/// A surface that reaches beyond a section's ground as stated: the ground is taken level
/// there, which the section did not say.
fn beyond_the_ground(solved: &SolvedSlope) -> Option<String> {
    let Analysed::Section(problem) = &solved.problem;
    let section = problem.section();
    if section.is_level_beyond_ends() {
        return None;
    }
    let points = section.ground().points();
    let (first, last) = (points[0].0, points[points.len() - 1].0);
    // In section coordinates already.
    let (low, high) = problem
        .surface()
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    let rounding = 1e-9 * (last - first).abs().max(1.0);
    (low < first - rounding || high > last + rounding).then(|| {
        format!(
            "the slip surface runs from x = {low:.4} to {high:.4}, beyond the ground as stated \
             (x = {first} … {last}): the ground is taken as level beyond its ends — extend \
             section.ground if it is not"
        )
    })
}

/// What a search leaves unsure: a minimum on the edge, a non-circular stage out of time,
/// unsolved circles whose Bishop F lies below the answer or next to it.
fn search_warnings(
    search: &SearchReport,
    factor_of_safety: Option<f64>,
    warnings: &mut Vec<String>,
) {
    if search.is_on_edge && search.hard {
        warnings.push(
            "the critical centre lies on the edge of the given search bounds: F is the \
                     least inside them, the true minimum may lie outside"
                .to_owned(),
        );
    } else if search.is_on_edge {
        warnings.push(
            "the critical centre lies on the edge of the search region even after moving \
                     the grid: the true minimum may lie outside it"
                .to_owned(),
        );
    }
    if search.timed_out {
        warnings.push(
            "a budget ended the non-circular search (time_budget_ms, max_evaluations or the \
                 time limit): the surface is the best found so far, never above the critical \
                 circle, and a lower F may exist (fewer vertices or slices, or a larger budget)"
                .to_owned(),
        );
    }
    let below = search
        .unsolved_bishop_minimum
        .zip(factor_of_safety)
        .filter(|(b, f)| b < f);
    if let Some((bishop, f)) = below {
        warnings.push(format!(
            "{} circles of the search have no physical Spencer solution, and Bishop's F on \
                 them goes down to {bishop:.4}, below the F found ({f:.4}): the critical F may \
                 be lower than reported (on those circles F_f(θ) and F_m(θ) do not cross, on the \
                 classic domain nor past the poles of m_α)",
            search.unsolved
        ));
    } else if search.unsolved_near_minimum {
        warnings.push(format!(
            "circles next to the critical one have no Spencer solution ({} in the search): \
                 the least F may lie among them",
            search.unsolved
        ));
    }
}
