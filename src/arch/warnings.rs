//! The warnings of an arch answer: what the engineer should look at before trusting λ.

use super::solved::{ArchStatusDto, SolvedArch};
use thrustline_solver::arch::InterfaceKind;

use crate::warning::{one_based, Warning, WarningCode};

/// Locked rings whose λ exceeds the bonded single ring's by more than this factor are warned
/// of (`rings_locked`): beyond a quarter more, the locking rather than the masonry carries the
/// load (aligned rings bonded give the single ring's λ to 1e-8).
const FAR_ABOVE_BONDED: f64 = 1.25;

/// What to look at before trusting the answer: `rings_locked` where locked rings answer
/// unbounded, or far above the bonded single ring; `rings_slide` where the mechanism slides
/// between rings that have no cohesion; `friction_may_overestimate` and
/// `not_settled` from the friction check.
pub fn warnings(solved: &SolvedArch) -> Vec<Warning> {
    let mut warnings = Vec::new();
    let advice = "the mortar between real rings shears — give ring_interface (its friction \
                  coefficient and the mortar's cohesion) for the ring joints";
    if solved.input.problem.has_locked_rings() && solved.status == ArchStatusDto::Unbounded {
        warnings.push(Warning::new(
            WarningCode::RingsLocked,
            format!(
                "the rings cannot slip on each other (no ring_friction_coefficient), so their \
                 staggered joints lock and no finite load forms a mechanism; {advice}"
            ),
        ));
    }
    let locked = solved.bonded_load_factor.zip(solved.solution.load_factor);
    if let Some((bonded, lambda)) = locked.filter(|(b, l)| *l > FAR_ABOVE_BONDED * b) {
        warnings.push(Warning::new(
            WarningCode::RingsLocked,
            format!(
                "λ = {lambda:.6} is {:.2} times the {bonded:.6} of one ring of the whole \
                 thickness: the rings cannot slip on each other (no \
                 ring_friction_coefficient), so their staggered joints lock and hinges cannot \
                 cross them; {advice}",
                lambda / bonded
            ),
        ));
    }
    if let Some(sliding) = rings_sliding_without_cohesion(solved) {
        warnings.push(
            Warning::new(
                WarningCode::RingsSlide,
                "the rings slide on each other at collapse on friction alone: the joints between \
                 real rings are mortared, and their cohesion (ring_interface.cohesion) raises λ \
                 where it holds — this answer leaves it out (conservative)",
            )
            .interfaces(one_based(&sliding)),
        );
    }
    let friction = solved.friction.as_ref();
    if !solved.is_non_associative && friction.is_some_and(|f| f.associative_may_overestimate()) {
        let sliding = solved
            .solution
            .mechanism
            .as_ref()
            .map(|m| m.sliding.clone());
        warnings.push(
            Warning::new(
                WarningCode::FrictionMayOverestimate,
                "the mechanism slides, and without dilatancy the joints may not hold the \
                 associative answer's state: λ may be over-estimated (friction: \
                 non_associative answers without that assumption)",
            )
            .interfaces(one_based(&sliding.unwrap_or_default())),
        );
    }
    if solved.status == ArchStatusDto::NotSettled {
        warnings.push(Warning::new(
            WarningCode::NotSettled,
            "the non-associative friction iteration did not settle: no λ it can vouch for \
             (its steps are in non_associative)",
        ));
    }
    warnings.extend(crate::study::warnings(
        solved.studies.probabilistic.as_ref(),
        solved.studies.sensitivity.as_ref(),
    ));
    warnings
}

/// The ring interfaces the collapse mechanism slides along that have no cohesion, if any.
fn rings_sliding_without_cohesion(solved: &SolvedArch) -> Option<Vec<usize>> {
    let problem = &solved.input.problem;
    let interfaces = &problem.assembly().interfaces;
    let sliding: Vec<usize> = solved
        .solution
        .mechanism
        .as_ref()?
        .sliding
        .iter()
        .copied()
        .filter(|&k| {
            interfaces[k].kind == InterfaceKind::Ring && problem.cohesive_capacity(k) == 0.0
        })
        .collect();
    (!sliding.is_empty()).then_some(sliding)
}
