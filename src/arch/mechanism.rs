//! The collapse mechanism in answers: its active limits, hinges (placed along the span) and
//! block velocities, and the friction check that corrects it (Livesley 1978 §2.7–2.9;
//! Gilbert, Casapulla & Ahmed 2006).

use serde::Serialize;
use thrustline_solver::arch::non_associative::NonAssociative;
use thrustline_solver::arch::{Assembly, Bound, HingeSide, Mechanism};
use utoipa::ToSchema;

use super::codes::{BoundDto, HingeSideDto, ResultantDto};

/// An active limit of the collapse mechanism.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ActiveConstraintDto {
    /// Interface number (1-based).
    pub interface: usize,
    /// The resultant: q, s (normal forces at the extrados/intrados ends), t (shear), u, v
    /// (friction: μ(q+s) ∓ t).
    pub resultant: ResultantDto,
    /// Which limit: lower or upper.
    pub bound: BoundDto,
    /// Polar angle of the interface in degrees.
    pub angle_deg: f64,
    /// Where the hinge forms, for q and s at their lower limits: q → intrados, s → extrados.
    #[schema(required = true)]
    pub hinge: Option<HingeSideDto>,
    /// The multiplier (plastic rate), with velocities normalised to a fastest corner speed of 1.
    pub multiplier: f64,
}

/// A hinge of the collapse mechanism.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HingeDto {
    /// Interface number (1-based).
    pub interface: usize,
    /// Polar angle of the interface in degrees.
    pub angle_deg: f64,
    /// intrados or extrados.
    pub location: HingeSideDto,
    /// x of the hinge (the intrados or extrados end of the joint).
    pub x: f64,
    /// y of the hinge.
    pub y: f64,
    /// Horizontal distance of the hinge from the left end of the span: a chain's left
    /// springing at the intrados (the clear span), an assembly's leftmost corner.
    pub span_distance: f64,
    /// `span_distance` as a fraction of the span (0 at the left end, 1 at the right).
    pub span_fraction: f64,
    /// Rotation rate of the higher-numbered block relative to the lower one (counter-clockwise).
    pub rotation: f64,
}

/// Virtual velocity of one block in the mechanism.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct BlockVelocityDto {
    /// Block number (1-based).
    pub block: usize,
    /// Velocity of the centroid in x.
    pub u: f64,
    /// Velocity of the centroid in y.
    pub v: f64,
    /// Rotation rate (counter-clockwise).
    pub rotation: f64,
}

/// The collapse mechanism, normalised so that the fastest block corner moves at speed 1.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MechanismDto {
    /// Velocity of every block.
    pub blocks: Vec<BlockVelocityDto>,
}

impl MechanismDto {
    /// The mechanism as answered (blocks numbered from 1).
    pub fn new(m: &Mechanism) -> Self {
        Self {
            blocks: m
                .velocities
                .iter()
                .enumerate()
                .map(|(b, v)| BlockVelocityDto {
                    block: b + 1,
                    u: v[0],
                    v: v[1],
                    rotation: v[2],
                })
                .collect(),
        }
    }
}

/// Friction without dilatancy: the iteration of Gilbert, Casapulla & Ahmed (2006).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct NonAssociativeOutDto {
    /// The associative programme's factor the iteration started from.
    #[schema(required = true)]
    pub associative_load_factor: Option<f64>,
    /// The factor the iteration settled on; null when it did not settle, settled below zero
    /// live load (the dead load is then not carried without dilatancy: `solver.status` is
    /// `dead_load_not_carried`, the negative λ the last of `load_factors`), or settled with no
    /// collapse up to the cap (`solver.status` `unbounded`, every step null).
    #[schema(required = true)]
    pub load_factor: Option<f64>,
    /// λ at each step: the associative programme's, then each programme with the friction
    /// rows replaced by Gilbert, Casapulla & Ahmed's modified surface |t| ≤ (1 − α)·μ·Ñ +
    /// α·μ·N (α = 0.01), Ñ the normal forces of the last two steps relaxed (β = 0.6) — or,
    /// after `mixing_from_step`, the Anderson mixing of the last steps. Null for a step whose
    /// programme did not solve.
    pub load_factors: Vec<Option<f64>>,
    /// The paper's relaxation stopped without settling after this many steps (50, 10 without
    /// halving its inconsistency, or a step that did not solve), and the Anderson mixing of the
    /// last three steps' normal forces took over from its last solved state, for up to as many
    /// steps again; 0 with `friction_relaxation: anderson` (the mixing from the first step);
    /// null when the paper's relaxation settled (or when nothing was iterated).
    #[schema(required = true)]
    pub mixing_from_step: Option<usize>,
    /// Whether it reached a state whose own normal forces carry its shear, |t| ≤ μ·N at every
    /// joint (to 1e-7 of the weight; of its largest normal force for a state at the cap of λ,
    /// when nothing collapses), with the normal forces no longer moving — or, when no
    /// step left the associative λ (to 1e-8), the associative state, which is then such a
    /// state. Each phase (the paper's relaxation, then the mixing) stops after 50 steps, or
    /// after 10 that did not halve its inconsistency.
    pub settled: bool,
    /// The corrected mechanism (Livesley §2.7), the first step's: sliding joints slide and
    /// open by only α·μ = 1 % of Coulomb's dilatancy; null when nothing slides, or when
    /// `include` leaves out `mechanism`.
    #[schema(required = true)]
    pub corrected_mechanism: Option<MechanismDto>,
}

impl NonAssociativeOutDto {
    /// The answer's account of the iteration (the corrected mechanism only with `mechanism`).
    pub fn new(outcome: &NonAssociative, mechanism: bool) -> Self {
        Self {
            associative_load_factor: outcome.associative.load_factor,
            load_factor: outcome
                .settled
                .then_some(outcome.solution.load_factor)
                .flatten(),
            load_factors: outcome.history.clone(),
            mixing_from_step: outcome.mixed_from,
            settled: outcome.settled,
            corrected_mechanism: outcome
                .corrected
                .as_ref()
                .filter(|_| mechanism)
                .map(MechanismDto::new),
        }
    }
}

/// The active limits of a mechanism, 1-based.
pub fn active_constraints(mechanism: &Mechanism) -> Vec<ActiveConstraintDto> {
    mechanism
        .active
        .iter()
        .map(|a| ActiveConstraintDto {
            interface: a.interface + 1,
            resultant: a.resultant.into(),
            bound: match a.bound {
                Bound::Lower => BoundDto::Lower,
                Bound::Upper => BoundDto::Upper,
            },
            angle_deg: a.angle_deg,
            hinge: a.hinge.map(HingeSideDto::from),
            multiplier: a.multiplier,
        })
        .collect()
}

/// The hinges of a mechanism, 1-based, placed on the joints of `assembly`.
pub fn hinges(assembly: &Assembly, mechanism: &Mechanism) -> Vec<HingeDto> {
    let (left, right) = span(assembly);
    let width = (right - left).max(f64::MIN_POSITIVE);
    mechanism
        .hinges
        .iter()
        .map(|h| {
            let interface = &assembly.interfaces[h.interface];
            let (x, y) = match h.side {
                HingeSide::Intrados => interface.intrados,
                HingeSide::Extrados => interface.extrados,
            };
            HingeDto {
                interface: h.interface + 1,
                angle_deg: h.angle_deg,
                location: h.side.into(),
                x,
                y,
                span_distance: x - left,
                span_fraction: (x - left) / width,
                rotation: h.rotation,
            }
        })
        .collect()
}

/// The ends of the span in x: a chain's springings at the intrados (the clear span), an
/// assembly's extreme corners.
fn span(assembly: &Assembly) -> (f64, f64) {
    let springings = (assembly.is_chain())
        .then(|| {
            let first = assembly.interfaces.first()?.intrados.0;
            let last = assembly.interfaces.last()?.intrados.0;
            Some((first.min(last), first.max(last)))
        })
        .flatten();
    springings.unwrap_or_else(|| {
        assembly
            .blocks
            .iter()
            .flat_map(|b| b.corners.iter())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &(x, _)| {
                (lo.min(x), hi.max(x))
            })
    })
}
