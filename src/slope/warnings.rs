//! The warnings of a Spencer answer: what the engineer should look at before trusting F.

use thrustline_solver::slope::{SpencerSolution, SpencerStatus};

use super::solved::SolvedSlope;
use crate::limits::MAX_SLICES;
use crate::warning::{listed, one_based, Warning, WarningCode as Code};
use thrustline_solver::slope::analysis::{Analysed, SearchReport};

/// Every warning that applies to `solved`.
pub fn warnings(solved: &SolvedSlope) -> Vec<Warning> {
    let solution = &solved.solution;
    let mut warnings = Vec::new();
    warnings.extend(status_warning(solution));
    slice_warnings(solution, &mut warnings);
    warnings.extend(root_warnings(solution));
    if let Some(refinement) = solved.refinement.as_ref().filter(|r| !r.is_settled) {
        warnings.push(Warning::new(
            Code::SliceToleranceNotReached,
            format!(
                "slice_tolerance {} not reached before {MAX_SLICES} slices",
                refinement.tolerance
            ),
        ));
    }
    if let Some(search) = &solved.search {
        search_warnings(search, solution.factor_of_safety, &mut warnings);
    }
    if let Some(beyond) = beyond_the_ground(solved) {
        warnings.push(beyond);
    }
    warnings.extend(at_the_section_end(solved));
    warnings.extend(several_masses(solved));
    if !solution.strength.settled {
        warnings.push(Warning::new(
            Code::StrengthNotConsistent,
            format!(
                "the bases' strengths did not settle on their nonlinear envelopes in {} rounds: \
                 F is that of the last round, not a consistent state",
                solution.strength.rounds
            ),
        ));
    }
    warnings.extend(outside_the_grid(solved));
    warnings.extend(supports_in_the_crack(solved));
    warnings.extend(crate::study::warnings(
        solved.studies.probabilistic.as_ref(),
        solved.studies.sensitivity.as_ref(),
    ));
    warnings
}

/// The warning of an answer that did not converge plainly, if any.
fn status_warning(solution: &SpencerSolution) -> Option<Warning> {
    match solution.status {
        SpencerStatus::Converged => None,
        SpencerStatus::NoSolution => Some(Warning::new(
            Code::NoSolution,
            "Spencer's equations have no root for this surface (none with every m_α positive, \
             and none past the poles of m_α with the slices there pressed onto their bases); no \
             factor of safety is reported",
        )),
        SpencerStatus::MomentOnly => Some(Warning::new(
            Code::MomentOnly,
            "φ' = 0 and no parallel inter-slice forces satisfy force equilibrium: F is from \
             moment equilibrium alone (exact for a circle when φ' = 0); θ is undefined and the \
             slice forces are Bishop's (θ = 0)",
        )),
        SpencerStatus::Unphysical => Some(Warning::new(
            Code::Unphysical,
            format!(
                "the equilibrium equations have a root F = {:e} that is not physical (F outside \
             1e-6…1e6, a base pulled below the apex of its strength envelope: c'·l + N'·tan φ' \
             < 0, or the mass held up by tension at the base: Σ N'·tan φ' < 0); no factor \
             of safety is reported — negative_effective_stress: drop_friction solves such \
             surfaces without tension",
                solution.unphysical_root.unwrap_or(f64::NAN)
            ),
        )),
    }
}

/// Spencer's F this far below Bishop's on the same circle is the inter-slice forces' doing, not
/// the circle's: the answer says so (model §14).
pub const FAR_BELOW_BISHOP: f64 = 0.85;

/// Inter-slice forces inclined more than this from the horizontal (degrees) are rarely physical.
pub const STEEP_INTERSLICE_DEG: f64 = 60.0;

/// A root an engineer should look at twice: far below Bishop's F on the same circle, or with
/// inter-slice forces inclined steeply.
fn root_warnings(solution: &SpencerSolution) -> Vec<Warning> {
    let mut out = Vec::new();
    let Some(f) = solution.factor_of_safety else {
        return out;
    };
    let theta = solution.theta_rad.map(f64::to_degrees);
    let at = theta.map_or(String::new(), |t| format!(" (θ = {t:.1}°)"));
    if let Some(bishop) = solution
        .bishop_factor_of_safety
        .filter(|&b| f < FAR_BELOW_BISHOP * b)
    {
        out.push(Warning::new(
            Code::FarBelowBishop,
            format!(
                "Spencer's F = {f:.4} is {:.0} % below Bishop's F = {bishop:.4} on the same                  surface{at}: the difference is carried by the inter-slice forces, not by the                  surface; look at the bases in tension and the line of thrust (a tension crack,                  or negative_effective_stress: drop_friction, usually brings the two together)",
                100.0 * (1.0 - f / bishop)
            ),
        ));
    }
    if let Some(t) = theta.filter(|t| t.abs() > STEEP_INTERSLICE_DEG) {
        out.push(Warning::new(
            Code::SteepInterslice,
            format!(
                "the inter-slice forces are inclined at θ = {t:.1}°, steeper than                  {STEEP_INTERSLICE_DEG}°: forces this steep are rarely physical; compare                  methods.bishop and methods.morgenstern_price on the same surface"
            ),
        ));
    }
    out
}

/// Slices with small m_α, dropped or left tension; boundaries the line of thrust leaves the mass.
fn slice_warnings(solution: &SpencerSolution, warnings: &mut Vec<Warning>) {
    let at = |indices: &[usize], code: Code, words: &dyn Fn(&str) -> String| {
        let slices = one_based(indices);
        (!slices.is_empty()).then(|| Warning::new(code, words(&listed(&slices))).slices(slices))
    };
    let small = thrustline_solver::slope::spencer::SMALL_DENOMINATOR;
    warnings.extend(at(
        &solution.small_m_alpha_slices,
        Code::SmallMAlpha,
        &|list| format!("m_alpha < {small} at slices {list}: base forces there are sensitive to F"),
    ));
    warnings.extend(at(
        &solution.tension_dropped_slices,
        Code::TensionDropped,
        &|list| {
            format!(
                "bases in tension at slices {list}: their strength in tension was dropped \
             (negative_effective_stress) and the equations solved again"
            )
        },
    ));
    warnings.extend(at(
        &solution.negative_effective_normal_slices,
        Code::Tension,
        &|list| format!("negative effective normal force (tension) at slices {list}"),
    ));
    let outside: Vec<usize> = solution
        .thrust_line
        .iter()
        .filter(|t| !t.is_inside_slice)
        .map(|t| t.boundary)
        .collect();
    if !outside.is_empty() {
        let message = format!(
            "the line of thrust leaves the sliding mass at boundaries {}",
            listed(&outside)
        );
        warnings.push(Warning::new(Code::ThrustLineOutside, message).boundaries(outside));
    }
}

/// Bases whose pore pressure comes from the grid but lie outside it (u = 0 taken there).
fn outside_the_grid(solved: &SolvedSlope) -> Option<Warning> {
    let Analysed::Section(problem) = &solved.problem;
    let section = problem.section();
    let grid = section.water().grid.as_ref()?;
    let layers = section.layers();
    let outside: Vec<usize> = problem
        .model()
        .slices
        .iter()
        .enumerate()
        .filter(|(_, s)| {
            let layer = &layers[s.layer];
            layer.pore_pressure_ratio.is_none()
                && layer.piezometric_line.is_none()
                && grid
                    .pressure(problem.to_section_x(s.base_middle.0), s.base_middle.1)
                    .is_none()
        })
        .map(|(i, _)| i)
        .collect();
    let slices = one_based(&outside);
    (!slices.is_empty()).then(|| {
        Warning::new(
            Code::OutsidePorePressureGrid,
            format!(
                "the bases of slices {} lie outside section.pore_pressure_grid: u = 0 taken \
                 there — extend the grid over the sliding mass",
                listed(&slices)
            ),
        )
        .slices(slices)
    })
}

/// Supports that cross the tension crack's face but not the slip surface: they hold nothing,
/// which a drawing of a nail through the crack would not suggest.
fn supports_in_the_crack(solved: &SolvedSlope) -> Option<Warning> {
    let Analysed::Section(problem) = &solved.problem;
    let crossing: Vec<usize> = problem
        .supports()
        .iter()
        .enumerate()
        .filter(|(_, s)| s.crack_only)
        .map(|(i, _)| i + 1)
        .collect();
    (!crossing.is_empty()).then(|| {
        Warning::new(
            Code::SupportCrossesCrack,
            format!(
                "section.supports {} cross the tension crack's face but not the slip surface: \
                 the crack carries no force but its water, so they hold nothing here",
                listed(&crossing)
            ),
        )
    })
}

/// A surface that reaches beyond a section's ground as stated: the ground is taken level
/// there, which the section did not say.
fn beyond_the_ground(solved: &SolvedSlope) -> Option<Warning> {
    let Analysed::Section(problem) = &solved.problem;
    let ((low, high), (first, last)) = problem.beyond_ground()?;
    Some(Warning::new(
        Code::BeyondGround,
        format!(
            "the slip surface runs from x = {low:.4} to {high:.4}, beyond the ground as stated \
             (x = {first} … {last}): the ground is taken as level beyond its ends, as asked \
             (beyond_ground)"
        ),
    ))
}

/// A circle that cuts the ground into several masses that could slide: which one is analysed,
/// and the others (a lens that nothing drives is not named).
fn several_masses(solved: &SolvedSlope) -> Option<Warning> {
    let Analysed::Section(problem) = &solved.problem;
    let masses = problem.masses();
    if masses.len() < 2 {
        return None;
    }
    let ((a, _), (b, _)) = problem.ends();
    let entry = a.min(b);
    let analysed = masses
        .iter()
        .enumerate()
        .min_by(|x, y| (x.1 .0 - entry).abs().total_cmp(&(y.1 .0 - entry).abs()))
        .map_or(0, |(i, _)| i);
    let listed: Vec<String> = masses
        .iter()
        .enumerate()
        .filter(|(i, m)| *i != analysed && m.2)
        .map(|(i, m)| format!("{} (x = {:.4} … {:.4})", i + 1, m.0, m.1))
        .collect();
    if listed.is_empty() {
        return None;
    }
    let (x0, x1, _) = masses[analysed];
    Some(Warning::new(
        Code::SeveralMasses,
        format!(
            "the circle cuts {} masses out of the ground: mass {} (x = {x0:.4} … {x1:.4}) is \
             analysed, the largest within the section that something drives; the others that \
             could slide are {} — circle.mass: k (from the left) analyses another",
            masses.len(),
            analysed + 1,
            listed.join(", ")
        ),
    ))
}

/// A searched surface that ends where the stated section does: surfaces beyond it were no
/// candidates (`search.beyond_ground`), and the least F may lie among them.
fn at_the_section_end(solved: &SolvedSlope) -> Option<Warning> {
    let search = solved.search.as_ref()?;
    let Analysed::Section(problem) = &solved.problem;
    let section = problem.section();
    if search.candidates.beyond_ground || section.is_level_beyond_ends() {
        return None;
    }
    let (first, last) = section.ground().x_range();
    let ((a, _), (b, _)) = problem.ends();
    let near = 1e-6 * (last - first).abs().max(1.0);
    let end = [first, last]
        .into_iter()
        .find(|e| (a - e).abs() <= near || (b - e).abs() <= near)?;
    Some(Warning::new(
        Code::MinimumAtSectionEnd,
        format!(
            "the critical surface reaches the end of the section as stated (x = {end}): \
             surfaces beyond it were not candidates and the least F may lie among them — \
             extend section.ground where the ground goes on (or search.beyond_ground: true to \
             take it as level)"
        ),
    ))
}

/// What a search leaves unsure: a minimum on the edge, a non-circular stage out of time,
/// unsolved circles whose Bishop F lies below the answer or next to it.
fn search_warnings(
    search: &SearchReport,
    factor_of_safety: Option<f64>,
    warnings: &mut Vec<Warning>,
) {
    if search.is_on_edge && search.hard {
        warnings.push(Warning::new(
            Code::MinimumOnBound,
            "the critical centre lies on the edge of the given search bounds: F is the \
                     least inside them, the true minimum may lie outside",
        ));
    } else if search.is_on_edge {
        warnings.push(Warning::new(
            Code::MinimumOnBound,
            "the critical centre lies on the edge of the search region even after moving \
                     the grid: the true minimum may lie outside it",
        ));
    }
    if !search.noncircular_stop.is_finished() {
        warnings.push(Warning::new(
            Code::BudgetExhausted,
            "a budget ended the non-circular search (time_budget_ms, max_evaluations or the \
                 time limit): the surface is the best found so far, never above the critical \
                 circle, and a lower F may exist (fewer vertices or slices, or a larger budget)",
        ));
    }
    let below = search
        .unsolved_bishop_minimum
        .zip(factor_of_safety)
        .filter(|(b, f)| b < f);
    if let Some((bishop, f)) = below {
        let message = format!(
            "{} circles of the search have no physical Spencer solution, and Bishop's F on \
                 them goes down to {bishop:.4}, below the F found ({f:.4}): the critical F may \
                 be lower than reported (on those circles F_f(θ) and F_m(θ) do not cross, on the \
                 classic domain nor past the poles of m_α)",
            search.unsolved
        );
        warnings.push(Warning::new(Code::UnsolvedBelowMinimum, message));
    } else if search.unsolved_near_minimum {
        let message = format!(
            "circles next to the critical one have no Spencer solution ({} in the search): \
                 the least F may lie among them",
            search.unsolved
        );
        warnings.push(Warning::new(Code::UnsolvedNearMinimum, message));
    }
}
