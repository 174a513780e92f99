//! The collapse mechanism, read from the multipliers of the limit-analysis programme
//! (Livesley 1978, §2.4: the multipliers of the equilibrium rows are the block velocities, those
//! of the active limits the hinge rotations, sliding and crushing rates).
//!
//! Velocities are normalised so that the fastest corner of any block moves at speed 1; the
//! multipliers are scaled with them. A limit counts as active when its multiplier is at least
//! [`ACTIVE_FRACTION`] of the largest one: an interior-point method ends with multipliers of
//! order μ/slack on inactive limits, many orders below the active ones.

use super::geometry::Assembly;
pub use super::resultant::{Bound, Resultant};

/// Multipliers below this fraction of the largest are treated as inactive.
pub const ACTIVE_FRACTION: f64 = 1e-3;

/// Which limit a row of the programme is: the bound of one resultant of one interface. The
/// mechanism is read from the multipliers of the rows through these tags.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct LimitTag {
    pub interface: usize,
    pub resultant: Resultant,
    pub bound: Bound,
}

/// Where a hinge forms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HingeSide {
    /// At the intrados end (the joint opens at the extrados: q at its lower limit).
    Intrados,
    /// At the extrados end (the joint opens at the intrados: s at its lower limit).
    Extrados,
}

/// A limit that is active in the mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ActiveConstraint {
    /// Interface index (0-based).
    pub interface: usize,
    /// The resultant.
    pub resultant: Resultant,
    /// The limit.
    pub bound: Bound,
    /// Direction of the interface in degrees (its polar angle for a circular arch).
    pub angle_deg: f64,
    /// The hinge this limit makes, for the lower limits of q and s.
    pub hinge: Option<HingeSide>,
    /// The multiplier (plastic rate), at the velocity normalisation.
    pub multiplier: f64,
}

/// A hinge of the mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hinge {
    /// Interface index (0-based).
    pub interface: usize,
    /// Direction of the interface in degrees.
    pub angle_deg: f64,
    /// Where the hinge is.
    pub side: HingeSide,
    /// Rotation rate of the higher-numbered block relative to the lower (counter-clockwise).
    pub rotation: f64,
}

/// A collapse mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Mechanism {
    /// Velocity (u, v, ω) of every block: translation of its centroid and rotation rate.
    pub velocities: Vec<[f64; 3]>,
    /// The active limits.
    pub active: Vec<ActiveConstraint>,
    /// The hinges.
    pub hinges: Vec<Hinge>,
    /// Interfaces that slide (t, u or v at a limit).
    pub sliding: Vec<usize>,
    /// Interfaces that crush (q or s at its upper limit).
    pub crushing: Vec<usize>,
}

impl Mechanism {
    /// Whether friction takes part: the associated flow rule then dilates the sliding joints,
    /// and the computed load factor may over-estimate the true one (Livesley §2.7–2.9).
    pub fn involves_friction(&self) -> bool {
        self.active
            .iter()
            .any(|a| matches!(a.resultant, Resultant::U | Resultant::V))
    }
}

/// Builds the mechanism from the multipliers `y` of the equilibrium rows and `z` of the limit
/// rows; `None` when every multiplier vanishes (nothing to show).
pub(crate) fn read_mechanism(
    assembly: &Assembly,
    length_scale: f64,
    y: &[f64],
    z: &[f64],
    tags: &[LimitTag],
) -> Option<Mechanism> {
    // Moment rows were divided by L: their multiplier is ω·L.
    let raw: Vec<[f64; 3]> = y
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2] / length_scale])
        .collect();
    let speed = fastest_corner(assembly, &raw);
    if !(speed > 0.0 && speed.is_finite()) {
        return None;
    }
    let velocities: Vec<[f64; 3]> = raw
        .iter()
        .map(|v| [v[0] / speed, v[1] / speed, v[2] / speed])
        .collect();
    let largest = tags
        .iter()
        .zip(z)
        .filter(|(tag, _)| tag.resultant != Resultant::Passive)
        .fold(0.0f64, |m, (_, v)| m.max(*v));
    let mut active = Vec::new();
    let mut hinges = Vec::new();
    let mut sliding = Vec::new();
    let mut crushing = Vec::new();
    for (tag, &multiplier) in tags.iter().zip(z) {
        if !(largest > 0.0 && multiplier >= ACTIVE_FRACTION * largest)
            || tag.resultant == Resultant::Passive
        {
            continue;
        }
        let k = tag.interface;
        let angle_deg = assembly.interfaces[k].angle_deg;
        let hinge = hinge_of(tag);
        if let Some(side) = hinge {
            push_hinge(&mut hinges, assembly, &velocities, k, side);
        }
        match (tag.resultant, tag.bound) {
            (Resultant::T | Resultant::U | Resultant::V, _) => sliding.push(k),
            (Resultant::Q | Resultant::S, Bound::Upper) | (Resultant::M, _) => crushing.push(k),
            _ => {}
        }
        active.push(ActiveConstraint {
            interface: k,
            resultant: tag.resultant,
            bound: tag.bound,
            angle_deg,
            hinge,
            multiplier: multiplier / speed,
        });
    }
    sliding.dedup();
    crushing.dedup();
    Some(Mechanism {
        velocities,
        active,
        hinges,
        sliding,
        crushing,
    })
}

/// The speed of the fastest corner of any block under the velocities `raw`.
fn fastest_corner(assembly: &Assembly, raw: &[[f64; 3]]) -> f64 {
    assembly
        .blocks
        .iter()
        .zip(raw)
        .flat_map(|(block, v)| {
            block.corners.iter().map(move |c| {
                let (dx, dy) = (c.0 - block.centroid.0, c.1 - block.centroid.1);
                (v[0] - v[2] * dy).hypot(v[1] + v[2] * dx)
            })
        })
        .fold(0.0, f64::max)
}

/// The hinge an active limit makes: the lower limits of q and s, either limit of m.
fn hinge_of(tag: &LimitTag) -> Option<HingeSide> {
    match (tag.resultant, tag.bound) {
        (Resultant::Q, Bound::Lower) => Some(HingeSide::Intrados),
        (Resultant::S, Bound::Lower) => Some(HingeSide::Extrados),
        (Resultant::M, Bound::Upper) => Some(HingeSide::Extrados),
        (Resultant::M, Bound::Lower) => Some(HingeSide::Intrados),
        _ => None,
    }
}

/// Adds the hinge at `side` of interface `k`, unless it is already there, with the relative
/// rotation of its two blocks.
fn push_hinge(
    hinges: &mut Vec<Hinge>,
    assembly: &Assembly,
    velocities: &[[f64; 3]],
    k: usize,
    side: HingeSide,
) {
    let angle_deg = assembly.interfaces[k].angle_deg;
    let rotation = |b: Option<usize>| b.map_or(0.0, |b| velocities[b][2]);
    let (higher, lower) = (assembly.interfaces[k].upper, assembly.interfaces[k].lower);
    if !hinges
        .iter()
        .any(|h: &Hinge| h.interface == k && h.side == side)
    {
        hinges.push(Hinge {
            interface: k,
            angle_deg,
            side,
            rotation: rotation(higher) - rotation(lower),
        });
    }
}
