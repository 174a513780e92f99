//! Assemblies engineers describe by a few numbers (model §5.4): multi-ring circular arches and
//! circular spans on piers, built as polygons and handed to [`Assembly::from_polygons`], which
//! finds their contacts.
//!
//! Rings split the thickness D equally (ring 1 the innermost). With staggered joints every
//! other ring is shifted by half a voussoir (its first and last blocks are half voussoirs), and
//! every block's intrados and extrados run through the corners at each half-voussoir angle, so
//! that the faces of neighbouring rings meet edge to edge; with aligned joints the voussoirs
//! are the quadrilaterals of the one-ring generator cut into rings. Voussoirs are polygons
//! (straight faces between their corners), as `"voussoir": "quadrilateral"`.

use super::contacts::CONTACT_TOLERANCE;
use super::error::{ArchError, ArchParameter};
use super::geometry::{Assembly, CircularArch, Interface, InterfaceKind};
use super::profile::{Profile, Station};

type Point = (f64, f64);

/// How the joints of neighbouring rings lie.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RingJoints {
    /// Every other ring shifted by half a voussoir (brick bonding).
    #[default]
    Staggered,
    /// All joints on the same radial lines.
    Aligned,
}

/// Spans on piers: the arch repeated `spans` times, each neighbouring pair sharing a pier
/// `width` wide (between the two intrados springing points) and `height` tall below the lower
/// springing, standing on the ground (a support).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piers {
    /// Number of spans (≥ 1).
    pub spans: usize,
    /// Pier width between the intrados springings of its two spans.
    pub width: f64,
    /// Pier height below its lower springing.
    pub height: f64,
}

/// A multi-ring, multi-span assembly with the ring of each block (0 = innermost) and the span
/// of each block (piers: `None`).
#[derive(Debug, Clone, PartialEq)]
pub struct Bridge {
    /// The blocks and their contacts (ring interfaces of [`InterfaceKind::Ring`]).
    pub assembly: Assembly,
    /// The ring of each block (`None` for piers).
    pub ring: Vec<Option<usize>>,
    /// The faces a fill lies on, as (block, points along the face): the outer ring's extrados
    /// of each span and the top of each pier between them.
    pub extrados: Vec<(usize, Vec<Point>)>,
}

/// What the generator needs of one span: its voussoirs, thickness and the corner at each
/// half-voussoir step j (0..=2N, from the right springing) and depth along the joint (0 at the
/// intrados), in the span's own frame.
trait SpanShape {
    fn voussoirs(&self) -> usize;
    fn thickness(&self) -> f64;
    fn corner(&self, j: usize, depth: f64) -> Point;
    /// The joint's unit direction at step j, from the intrados out.
    fn normal(&self, j: usize) -> Point;
    /// A length for the ranges: the extrados radius of a circle, half the span plus the
    /// thickness of a profile.
    fn scale(&self) -> f64;
}

/// A circular arch: corners on circles about the origin, joints radial.
struct Circle<'a> {
    arch: &'a CircularArch,
    inner: f64,
}

impl Circle<'_> {
    /// The polar angle of half-voussoir step j (0..=2N).
    fn half(&self, j: usize) -> f64 {
        let whole = self.arch.interface_angle_deg(j / 2);
        if j.is_multiple_of(2) {
            whole
        } else {
            0.5 * (whole + self.arch.interface_angle_deg(j / 2 + 1))
        }
    }
}

impl SpanShape for Circle<'_> {
    fn voussoirs(&self) -> usize {
        self.arch.voussoirs()
    }
    fn thickness(&self) -> f64 {
        self.arch.thickness()
    }
    fn corner(&self, j: usize, depth: f64) -> Point {
        let a = self.half(j).to_radians();
        let r = self.inner + depth;
        (r * a.cos(), r * a.sin())
    }
    fn normal(&self, j: usize) -> Point {
        let a = self.half(j).to_radians();
        (a.cos(), a.sin())
    }
    fn scale(&self) -> f64 {
        self.arch.radius() + 0.5 * self.arch.thickness()
    }
}

/// A profile's stations at every half voussoir.
struct Stations {
    stations: Vec<Station>,
    thickness: f64,
    scale: f64,
}

impl SpanShape for Stations {
    fn voussoirs(&self) -> usize {
        (self.stations.len() - 1) / 2
    }
    fn thickness(&self) -> f64 {
        self.thickness
    }
    fn corner(&self, j: usize, depth: f64) -> Point {
        self.stations[j].at(depth)
    }
    fn normal(&self, j: usize) -> Point {
        self.stations[j].normal
    }
    fn scale(&self) -> f64 {
        self.scale
    }
}

/// One generated voussoir: its polygon (in the span's frame), ring, and the half-voussoir
/// steps of its start and end joints.
struct Voussoir {
    polygon: Vec<Point>,
    ring: usize,
    joints: [usize; 2],
}

/// The voussoirs of one span, ring by ring.
fn span_blocks(shape: &impl SpanShape, rings: usize, joints: RingJoints) -> Vec<Voussoir> {
    let n = shape.voussoirs();
    let d = shape.thickness();
    let mut out = Vec::new();
    for ring in 0..rings {
        let (inner, outer) = (
            d * ring as f64 / rings as f64,
            d * (ring + 1) as f64 / rings as f64,
        );
        // Block boundaries as half-steps.
        let shifted = joints == RingJoints::Staggered && ring % 2 == 1;
        let mut cuts: Vec<usize> = if shifted {
            std::iter::once(0)
                .chain((0..n).map(|k| 2 * k + 1))
                .chain(std::iter::once(2 * n))
                .collect()
        } else {
            (0..=n).map(|k| 2 * k).collect()
        };
        cuts.dedup();
        for w in cuts.windows(2) {
            let steps: Vec<usize> = match joints {
                RingJoints::Staggered => (w[0]..=w[1]).collect(),
                RingJoints::Aligned => vec![w[0], w[1]],
            };
            let mut polygon: Vec<Point> = Vec::with_capacity(2 * steps.len());
            polygon.push(shape.corner(w[0], inner));
            polygon.extend(steps.iter().map(|&j| shape.corner(j, outer)));
            polygon.extend(steps.iter().rev().map(|&j| shape.corner(j, inner)));
            polygon.pop();
            out.push(Voussoir {
                polygon,
                ring,
                joints: [w[0], w[1]],
            });
        }
    }
    out
}

/// The support under a springing face from `intrados` to `extrados`, extending `depth` along
/// `away` (the direction out of the arch).
fn abutment(intrados: Point, extrados: Point, away: Point, depth: f64) -> Vec<Point> {
    vec![
        intrados,
        extrados,
        (extrados.0 + depth * away.0, extrados.1 + depth * away.1),
        (intrados.0 + depth * away.0, intrados.1 + depth * away.1),
    ]
}

/// A joint of the generator (between voussoirs of a ring, at a springing) runs from its
/// intrados end to its extrados end along the joint's direction, and its angle is that
/// direction's polar angle, as on a chain (model §1.3): contacts are found in either direction,
/// and a hinge's face and angle are read from this orientation. Other contacts (between rings,
/// under piers) keep theirs.
fn orient(interface: &mut Interface, direction: Point) {
    let along = interface.tangent.0 * direction.0 + interface.tangent.1 * direction.1;
    // Along the joint to 1e-9 (a contact found on a joint lies on it up to rounding).
    if along.abs() < 1.0 - 1e-9 {
        return;
    }
    if along < 0.0 {
        std::mem::swap(&mut interface.intrados, &mut interface.extrados);
        interface.tangent = (-interface.tangent.0, -interface.tangent.1);
    }
    let mut angle_deg = interface.tangent.1.atan2(interface.tangent.0).to_degrees();
    if angle_deg <= -90.0 {
        angle_deg += 360.0;
    }
    interface.angle_deg = angle_deg;
}

/// The half-voussoir step of the joint an interface lies on: the step two voussoirs of one
/// ring share, or a voussoir's springing step against a support or a pier (the one nearer the
/// contact when the voussoir spans the arch).
fn joint_step(
    interface: &Interface,
    voussoirs: &[Option<(usize, &Voussoir)>],
    springing: impl Fn(usize, usize) -> Point,
    last: usize,
) -> Option<(usize, usize)> {
    let of = |b: Option<usize>| b.and_then(|b| voussoirs[b]);
    match (of(interface.lower), of(interface.upper)) {
        (Some((span_a, a)), Some((span_b, b))) => {
            let same = span_a == span_b && a.ring == b.ring;
            let shared = a.joints.iter().find(|j| b.joints.contains(j));
            shared.filter(|_| same).map(|&j| (span_a, j))
        }
        (Some((span, v)), None) | (None, Some((span, v))) => {
            let middle = interface.middle();
            let away = |j: usize| {
                let p = springing(span, j);
                (p.0 - middle.0).hypot(p.1 - middle.1)
            };
            v.joints
                .iter()
                .copied()
                .filter(|&j| j == 0 || j == last)
                .min_by(|&a, &b| away(a).total_cmp(&away(b)))
                .map(|j| (span, j))
        }
        (None, None) => None,
    }
}

/// The ranges of a bridge: 1 to 16 rings, 1 to 20 spans, piers wide enough that the springings
/// of two spans do not cross and no higher than 1000 times the shape's scale.
fn check_bridge(shape: &impl SpanShape, rings: usize, piers: &Piers) -> Result<(), ArchError> {
    if !(1..=16).contains(&rings) {
        return Err(ArchError::range(
            ArchParameter::Rings,
            rings as f64,
            "an integer 1 ≤ rings ≤ 16",
        ));
    }
    if !(1..=20).contains(&piers.spans) {
        return Err(ArchError::range(
            ArchParameter::Spans,
            piers.spans as f64,
            "an integer 1 ≤ spans ≤ 20",
        ));
    }
    let (n, d, scale) = (shape.voussoirs(), shape.thickness(), shape.scale());
    if piers.spans > 1 {
        // The extrados springings of the two spans on a pier must not cross: each leans out
        // over the pier by its joint's horizontal extent.
        let least = (shape.corner(0, d).0 - shape.corner(0, 0.0).0)
            + (shape.corner(2 * n, 0.0).0 - shape.corner(2 * n, d).0);
        let width_ok = piers.width.is_finite()
            && piers.width >= least.max(0.0) + CONTACT_TOLERANCE * scale
            && piers.width <= 1e3 * scale;
        if !width_ok {
            return Err(ArchError::range(
                ArchParameter::PierWidth,
                piers.width,
                format!(
                    "{least} < width ≤ {} (the springings must not overlap)",
                    1e3 * scale
                ),
            ));
        }
        if !(piers.height.is_finite() && piers.height > 0.0 && piers.height <= 1e3 * scale) {
            return Err(ArchError::range(
                ArchParameter::PierHeight,
                piers.height,
                format!("0 < height ≤ {}", 1e3 * scale),
            ));
        }
    }
    Ok(())
}

/// A circular arch of `rings` rings (1 to 16) and `piers.spans` spans (1 to 20).
pub fn bridge(
    arch: &CircularArch,
    rings: usize,
    joints: RingJoints,
    piers: Piers,
) -> Result<Bridge, ArchError> {
    let shape = Circle {
        arch,
        inner: arch.radius() - 0.5 * arch.thickness(),
    };
    build(&shape, rings, joints, piers)
}

/// An arch of `profile`'s intrados, `thickness` thick, of `voussoirs` voussoirs per ring,
/// `rings` rings (1 to 16) and `piers.spans` spans (1 to 20).
pub fn profile_bridge(
    profile: &Profile,
    thickness: f64,
    voussoirs: usize,
    rings: usize,
    joints: RingJoints,
    piers: Piers,
) -> Result<Bridge, ArchError> {
    profile.check_thickness(thickness)?;
    let shape = Stations {
        stations: profile.stations(2 * voussoirs.max(1)),
        thickness,
        scale: 0.5 * profile.span() + thickness,
    };
    build(&shape, rings, joints, piers)
}

fn build(
    shape: &impl SpanShape,
    rings: usize,
    joints: RingJoints,
    piers: Piers,
) -> Result<Bridge, ArchError> {
    check_bridge(shape, rings, &piers)?;
    let (n, depth) = (shape.voussoirs(), shape.thickness());
    let last = 2 * n;
    let pitch = pitch(shape, &piers);
    let at = |span: usize, j: usize, d: f64| {
        let p = shape.corner(j, d);
        (span as f64 * pitch + p.0, 0.0 + p.1)
    };
    let voussoirs = span_blocks(shape, rings, joints);
    let mut polygons = Vec::new();
    let mut generated: Vec<Option<(usize, &Voussoir)>> = Vec::new();
    let mut extrados = Vec::new();
    for span in 0..piers.spans {
        let shift = span as f64 * pitch;
        for v in &voussoirs {
            let polygon: Vec<Point> = v.polygon.iter().map(|p| (shift + p.0, 0.0 + p.1)).collect();
            if v.ring + 1 == rings {
                // The outer corners follow the first: the polygon goes inner start, outer
                // corners, inner corners back.
                let outer = polygon.len().div_ceil(2);
                extrados.push((polygons.len(), polygon[1..=outer].to_vec()));
            }
            polygons.push(polygon);
            generated.push(Some((span, v)));
        }
    }
    let mut supports = end_abutments(shape, &at, piers.spans);
    // Piers between spans i (right springing) and i + 1 (left springing), on the ground.
    for span in 0..piers.spans.saturating_sub(1) {
        let (i_l, e_l) = (at(span, 0, 0.0), at(span, 0, depth));
        let (i_r, e_r) = (at(span + 1, last, 0.0), at(span + 1, last, depth));
        let bottom = i_l.1.min(i_r.1) - piers.height;
        extrados.push((polygons.len(), vec![e_r, e_l]));
        polygons.push(vec![(i_l.0, bottom), (i_r.0, bottom), i_r, e_r, e_l, i_l]);
        generated.push(None);
        let ground = piers.width.max(depth);
        supports.push(vec![
            (i_l.0, bottom - ground),
            (i_r.0, bottom - ground),
            (i_r.0, bottom),
            (i_l.0, bottom),
        ]);
    }
    let mut assembly = Assembly::from_polygons(&polygons, &supports)?;
    classify_interfaces(&mut assembly.interfaces, &generated, shape, &at);
    Ok(Bridge {
        assembly,
        ring: generated.iter().map(|g| g.map(|(_, v)| v.ring)).collect(),
        extrados,
    })
}

/// The abutments at the two ends: the last span's right springing, the first's left, extending
/// back along the arch's direction there (`at` places a corner of a span in the bridge's frame).
fn end_abutments(
    shape: &impl SpanShape,
    at: &impl Fn(usize, usize, f64) -> Point,
    spans: usize,
) -> Vec<Vec<Point>> {
    let (n, depth) = (shape.voussoirs(), shape.thickness());
    let last = 2 * n;
    let mut supports = Vec::new();
    let (right, left) = (shape.normal(0), shape.normal(last));
    supports.push(abutment(
        at(spans - 1, 0, 0.0),
        at(spans - 1, 0, depth),
        (right.1, -right.0),
        depth,
    ));
    supports.push(abutment(
        at(0, last, 0.0),
        at(0, last, depth),
        (-left.1, left.0),
        depth,
    ));
    supports
}

/// Marks the contacts between rings as ring interfaces and orients every joint of the
/// generator along its direction (`at` places a corner of a span in the bridge's frame).
fn classify_interfaces(
    interfaces: &mut [Interface],
    generated: &[Option<(usize, &Voussoir)>],
    shape: &impl SpanShape,
    at: &impl Fn(usize, usize, f64) -> Point,
) {
    let last = 2 * shape.voussoirs();
    for interface in interfaces {
        if let (Some(Some((_, a))), Some(Some((_, b)))) = (
            interface.lower.map(|x| generated[x]),
            interface.upper.map(|y| generated[y]),
        ) {
            if a.ring != b.ring {
                interface.kind = InterfaceKind::Ring;
            }
        }
        if let Some((_, j)) = joint_step(interface, generated, |s, j| at(s, j, 0.0), last) {
            orient(interface, shape.normal(j));
        }
    }
}

/// The distance between neighbouring spans' frames: the span between the intrados springings
/// and the pier's width.
fn pitch(shape: &impl SpanShape, piers: &Piers) -> f64 {
    let last = 2 * shape.voussoirs();
    shape.corner(0, 0.0).0 + piers.width - shape.corner(last, 0.0).0
}
