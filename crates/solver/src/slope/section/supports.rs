//! Reinforcement (model §7): end-anchored bars, grouted tiebacks, soil nails, geosynthetics and
//! piles. Each support is a segment from its `head` (at the ground) to its `end` (in the ground);
//! where a slip surface crosses it at P the support holds the sliding mass with the force its
//! governing mode allows (per unit width: ÷ spacing), applied at P on the slice whose base
//! holds P — `active`, as a known force, or `passive`, its component along the base mobilised
//! like the soil's strength (divided by F; its component across the base presses the base,
//! as an active force's does: Duncan & Wright's Method B, Slide's passive support).

use crate::slope::error::{check_range, SlopeError, SlopeParameter, SupportField};
use crate::slope::slices::{BaseSlice, ExternalLoad};

use crate::slope::section::polyline::Polyline;

/// Largest capacity, strength or spacing accepted.
const MAX_MAGNITUDE: f64 = 1e12;

/// How a support's force enters the equilibrium equations.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Application {
    /// A known force (reduces the driving force).
    Active,
    /// Mobilised like strength (adds to the resisting force, divided by F).
    Passive,
}

/// Which ends of a geosynthetic are anchored (cannot pull out).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Anchorage {
    /// Neither: pull-out beyond the surface and stripping inside the mass both count.
    None,
    /// At the slope face (the head): no stripping.
    SlopeFace,
    /// At the embedded end: no pull-out.
    EmbeddedEnd,
    /// Both: the tensile strength alone.
    BothEnds,
}

/// The direction of a geosynthetic's force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Orientation {
    /// Along the reinforcement.
    Parallel,
    /// Along the slip surface at the crossing.
    Tangent,
    /// Halfway between the two.
    Bisector,
}

/// The direction of a pile's shear force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PileOrientation {
    /// Along the slip surface at the crossing, against the sliding.
    ParallelToSurface,
    /// Across the pile, against the sliding.
    PerpendicularToPile,
}

/// What a support is and what it can carry (forces per support; per unit width for a
/// geosynthetic; bond strengths per unit length of bond).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SupportKind {
    /// A bar anchored at its end: min(tensile, plate) once its end lies beyond the surface.
    EndAnchored {
        /// Tensile capacity.
        tensile_capacity: f64,
        /// Capacity of the head plate.
        plate_capacity: f64,
    },
    /// A tendon bonded over its last `bond_length` towards the end.
    GroutedTieback {
        /// Tensile capacity.
        tensile_capacity: f64,
        /// Capacity of the head plate.
        plate_capacity: f64,
        /// Bond strength per unit length.
        bond_strength: f64,
        /// Length of the bonded part (at the end).
        bond_length: f64,
    },
    /// A nail bonded over its whole length.
    SoilNail {
        /// Tensile capacity.
        tensile_capacity: f64,
        /// Capacity of the head plate.
        plate_capacity: f64,
        /// Bond strength per unit length.
        bond_strength: f64,
    },
    /// A geotextile or geogrid (per unit width already).
    Geosynthetic {
        /// Tensile strength per unit width.
        tensile_strength: f64,
        /// Bond strength per unit length (both faces).
        bond_strength: f64,
        /// Which ends cannot pull out.
        anchorage: Anchorage,
        /// The direction of its force.
        orientation: Orientation,
    },
    /// A pile or micro-pile: its shear strength across the slip surface.
    Pile {
        /// Shear strength.
        shear_strength: f64,
        /// The direction of its force.
        orientation: PileOrientation,
    },
}

/// One support.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Support {
    /// The head (at the ground).
    pub head: (f64, f64),
    /// The end (in the ground).
    pub end: (f64, f64),
    /// Out-of-plane spacing (1 for a geosynthetic).
    pub spacing: f64,
    /// What it is.
    pub kind: SupportKind,
    /// How its force enters the equations.
    pub application: Application,
}

/// What limits a support's force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// The tendon's or the geosynthetic's tensile capacity.
    Tensile,
    /// The head plate.
    Plate,
    /// Pull-out of the bond beyond the slip surface.
    Pullout,
    /// Stripping: the support pulls out of the sliding mass with its head.
    Stripping,
    /// A pile's shear strength.
    Shear,
}

/// A support against one slip surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SupportForce {
    /// Where the surface crosses it (solver frame), if it does.
    pub crossing: Option<(f64, f64)>,
    /// The force on the sliding mass per unit width (0 without a crossing).
    pub force: f64,
    /// Its direction (unit vector, solver frame).
    pub direction: (f64, f64),
    /// What limits it.
    pub mode: Option<Mode>,
    /// The slice it acts on (0 at the lower end).
    pub slice: Option<usize>,
    /// Whether it crosses a tension crack's face but not the slip surface: it then holds
    /// nothing (the crack carries no force but its water).
    pub crack_only: bool,
}

impl Support {
    /// The same support seen from behind (x → −x).
    pub(super) fn mirrored(&self) -> Self {
        Self {
            head: (-self.head.0, self.head.1),
            end: (-self.end.0, self.end.1),
            ..*self
        }
    }

    fn length(&self) -> f64 {
        (self.end.0 - self.head.0).hypot(self.end.1 - self.head.1)
    }

    /// The force per support and its mode, with `inside` of it in the sliding mass and
    /// `beyond` of it past the surface.
    pub fn capacity(&self, inside: f64, beyond: f64) -> (f64, Mode) {
        let candidates: Vec<(f64, Mode)> = match self.kind {
            SupportKind::EndAnchored {
                tensile_capacity,
                plate_capacity,
            } => vec![
                (tensile_capacity, Mode::Tensile),
                (plate_capacity, Mode::Plate),
            ],
            SupportKind::GroutedTieback {
                tensile_capacity,
                plate_capacity,
                bond_strength,
                bond_length,
            } => {
                let bonded_beyond = bond_length.min(beyond);
                let bonded_inside = (bond_length - beyond).max(0.0).min(inside);
                let held = if bonded_inside > 0.0 {
                    Mode::Stripping
                } else {
                    Mode::Plate
                };
                vec![
                    (tensile_capacity, Mode::Tensile),
                    (bond_strength * bonded_beyond, Mode::Pullout),
                    (plate_capacity + bond_strength * bonded_inside, held),
                ]
            }
            SupportKind::SoilNail {
                tensile_capacity,
                plate_capacity,
                bond_strength,
            } => vec![
                (tensile_capacity, Mode::Tensile),
                (bond_strength * beyond, Mode::Pullout),
                (plate_capacity + bond_strength * inside, Mode::Stripping),
            ],
            SupportKind::Geosynthetic {
                tensile_strength,
                bond_strength,
                anchorage,
                ..
            } => {
                let mut c = vec![(tensile_strength, Mode::Tensile)];
                if matches!(anchorage, Anchorage::None | Anchorage::SlopeFace) {
                    c.push((bond_strength * beyond, Mode::Pullout));
                }
                if matches!(anchorage, Anchorage::None | Anchorage::EmbeddedEnd) {
                    c.push((bond_strength * inside, Mode::Stripping));
                }
                c
            }
            SupportKind::Pile { shear_strength, .. } => vec![(shear_strength, Mode::Shear)],
        };
        // The least; on a tie the first listed (tensile before the others).
        candidates
            .into_iter()
            .fold(None, |best: Option<(f64, Mode)>, c| match best {
                Some(b) if b.0 <= c.0 => Some(b),
                _ => Some(c),
            })
            .unwrap_or((0.0, Mode::Tensile))
    }

    /// The direction of the force on the sliding mass, with `up_slope` the slip surface's unit
    /// tangent at the crossing pointing against the sliding (solver frame: towards +x).
    fn direction(&self, up_slope: (f64, f64)) -> (f64, f64) {
        let length = self.length();
        let along = (
            (self.end.0 - self.head.0) / length,
            (self.end.1 - self.head.1) / length,
        );
        let unit = |v: (f64, f64)| {
            let n = v.0.hypot(v.1);
            if n > 0.0 {
                (v.0 / n, v.1 / n)
            } else {
                up_slope
            }
        };
        match self.kind {
            SupportKind::Geosynthetic { orientation, .. } => match orientation {
                Orientation::Parallel => along,
                Orientation::Tangent => up_slope,
                Orientation::Bisector => unit((along.0 + up_slope.0, along.1 + up_slope.1)),
            },
            SupportKind::Pile { orientation, .. } => match orientation {
                PileOrientation::ParallelToSurface => up_slope,
                PileOrientation::PerpendicularToPile => {
                    let across = (-along.1, along.0);
                    if across.0 * up_slope.0 + across.1 * up_slope.1 >= 0.0 {
                        across
                    } else {
                        (-across.0, -across.1)
                    }
                }
            },
            _ => along,
        }
    }
}

/// Checks the supports against the section's ground: finite and within bounds, of non-zero
/// length, the end in the ground and the head at most rounding above it, within the ground's
/// x range; a tieback's bond no longer than the tieback.
pub(super) fn check(supports: &[Support], ground: &Polyline) -> Result<(), SlopeError> {
    let points = ground.points();
    let (g0, g1) = ground.x_range();
    let scale = points
        .iter()
        .fold(g1 - g0, |m, p| m.max(p.1.abs()))
        .max(f64::MIN_POSITIVE);
    for (index, s) in supports.iter().enumerate() {
        let at = |field| SlopeParameter::Support { index, field };
        for (field, point) in [(SupportField::Head, s.head), (SupportField::End, s.end)] {
            for v in [point.0, point.1] {
                check_range(
                    at(field),
                    v,
                    -1e9,
                    false,
                    1e9,
                    "finite coordinates, |x|, |y| ≤ 1e9",
                )?;
            }
            let outside = if point.0 < g0 || point.0 > g1 {
                Some(format!(
                    "lies outside the section (the ground runs from x = {g0} to {g1})"
                ))
            } else if point.1 > ground.y_at(point.0) + 1e-6 * scale {
                Some(format!(
                    "lies above the ground (at y = {} there): a support is in the ground, its \
                     head at the ground",
                    ground.y_at(point.0)
                ))
            } else {
                None
            };
            if let Some(reason) = outside {
                return Err(SlopeError::Conflict {
                    parameter: at(field),
                    reason: format!("({}, {}) {reason}", point.0, point.1),
                });
            }
        }
        if s.length() <= 1e-9 * scale {
            return Err(SlopeError::Conflict {
                parameter: at(SupportField::End),
                reason: "is the head: a support needs a length".to_owned(),
            });
        }
        check_range(
            at(SupportField::Spacing),
            s.spacing,
            0.0,
            true,
            MAX_MAGNITUDE,
            "0 < spacing ≤ 1e12",
        )?;
        check_kind(index, s)?;
    }
    Ok(())
}

/// Checks what support `index` can carry: capacities and strengths ≥ 0, a tieback's bond
/// within its length.
fn check_kind(index: usize, s: &Support) -> Result<(), SlopeError> {
    let at = |field| SlopeParameter::Support { index, field };
    let capacity =
        |field, v| check_range(at(field), v, 0.0, false, MAX_MAGNITUDE, "0 ≤ value ≤ 1e12");
    match s.kind {
        SupportKind::EndAnchored {
            tensile_capacity,
            plate_capacity,
        } => {
            capacity(SupportField::TensileCapacity, tensile_capacity)?;
            capacity(SupportField::PlateCapacity, plate_capacity)?;
        }
        SupportKind::GroutedTieback {
            tensile_capacity,
            plate_capacity,
            bond_strength,
            bond_length,
        } => {
            capacity(SupportField::TensileCapacity, tensile_capacity)?;
            capacity(SupportField::PlateCapacity, plate_capacity)?;
            capacity(SupportField::BondStrength, bond_strength)?;
            check_range(
                at(SupportField::BondLength),
                bond_length,
                0.0,
                true,
                s.length() * (1.0 + 1e-12),
                "0 < bond_length ≤ the tieback's length |end − head|",
            )?;
        }
        SupportKind::SoilNail {
            tensile_capacity,
            plate_capacity,
            bond_strength,
        } => {
            capacity(SupportField::TensileCapacity, tensile_capacity)?;
            capacity(SupportField::PlateCapacity, plate_capacity)?;
            capacity(SupportField::BondStrength, bond_strength)?;
        }
        SupportKind::Geosynthetic {
            tensile_strength,
            bond_strength,
            ..
        } => {
            capacity(SupportField::TensileStrength, tensile_strength)?;
            capacity(SupportField::BondStrength, bond_strength)?;
        }
        SupportKind::Pile { shear_strength, .. } => {
            capacity(SupportField::ShearStrength, shear_strength)?;
        }
    }
    Ok(())
}

/// Forces found in the solver's frame, in section coordinates (x → −x when it is mirrored).
pub(super) fn in_section(forces: &[SupportForce], mirrored: bool) -> Vec<SupportForce> {
    let flip = |v: (f64, f64)| if mirrored { (-v.0, v.1) } else { v };
    forces
        .iter()
        .map(|s| SupportForce {
            crossing: s.crossing.map(flip),
            direction: flip(s.direction),
            ..*s
        })
        .collect()
}

/// Where the segment a–b first crosses the polyline `surface` (from a): the point and the
/// index of the surface's segment.
fn first_crossing(
    (a, b): ((f64, f64), (f64, f64)),
    surface: &[(f64, f64)],
) -> Option<((f64, f64), usize)> {
    let d = (b.0 - a.0, b.1 - a.1);
    let mut best: Option<(f64, (f64, f64), usize)> = None;
    for (k, w) in surface.windows(2).enumerate() {
        let (p, q) = (w[0], w[1]);
        let e = (q.0 - p.0, q.1 - p.1);
        let denominator = d.0 * e.1 - d.1 * e.0;
        if denominator == 0.0 {
            continue;
        }
        let (rx, ry) = (p.0 - a.0, p.1 - a.1);
        let t = (rx * e.1 - ry * e.0) / denominator;
        let u = (rx * d.1 - ry * d.0) / denominator;
        if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) && best.is_none_or(|b| t < b.0) {
            best = Some((t, (a.0 + t * d.0, a.1 + t * d.1), k));
        }
    }
    best.map(|(_, point, k)| (point, k))
}

/// A segment: its two ends.
pub(super) type Segment = [(f64, f64); 2];

/// Each support against the slip surface as cut (`surface`: the bases' end points, toe end
/// first; solver frame, like `supports` and `slices`): its force and the loads it puts on the
/// slices (moments about their base middles). A tension crack's face (`crack`: its bottom and
/// top) is no part of it: the crack carries no force but its water, so a support that crosses
/// only the crack holds nothing, and says so (`crack_only`).
pub(super) fn forces(
    supports: &[Support],
    surface: &[(f64, f64)],
    crack: Option<Segment>,
    slices: &[BaseSlice],
) -> (Vec<SupportForce>, Vec<ExternalLoad>) {
    let mut out = Vec::with_capacity(supports.len());
    let mut loads = Vec::new();
    for s in supports {
        let Some((p, k)) = first_crossing((s.head, s.end), surface) else {
            out.push(SupportForce {
                crossing: None,
                force: 0.0,
                direction: (0.0, 0.0),
                mode: None,
                slice: None,
                crack_only: crack
                    .is_some_and(|face| first_crossing((s.head, s.end), &face).is_some()),
            });
            continue;
        };
        let inside = (p.0 - s.head.0).hypot(p.1 - s.head.1);
        let beyond = (s.end.0 - p.0).hypot(s.end.1 - p.1);
        let (per_support, mode) = s.capacity(inside, beyond);
        let force = per_support / s.spacing;
        // The surface's segment k: base k (toe end first, so it points up the slope).
        let (a, b) = (surface[k], surface[k + 1]);
        let length = (b.0 - a.0).hypot(b.1 - a.1).max(f64::MIN_POSITIVE);
        let up_slope = ((b.0 - a.0) / length, (b.1 - a.1) / length);
        let direction = s.direction(up_slope);
        let slice = k.min(slices.len().saturating_sub(1));
        if force > 0.0 {
            if let Some(base) = slices.get(slice) {
                let (fx, fy) = (force * direction.0, force * direction.1);
                let (xb, yb) = base.base_middle;
                loads.push(ExternalLoad {
                    slice,
                    fx,
                    fy,
                    moment: (p.0 - xb) * fy - (p.1 - yb) * fx,
                    passive: s.application == Application::Passive,
                });
            }
        }
        out.push(SupportForce {
            crossing: Some(p),
            force,
            direction,
            mode: Some(mode),
            slice: Some(slice),
            crack_only: false,
        });
    }
    (out, loads)
}
