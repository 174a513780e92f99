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

fn polar(centre: Point, r: f64, degrees: f64) -> Point {
    let a = degrees.to_radians();
    (centre.0 + r * a.cos(), centre.1 + r * a.sin())
}

/// The voussoirs of one span about `centre`: (polygon, ring) per block, ring by ring.
fn span_blocks(
    arch: &CircularArch,
    rings: usize,
    joints: RingJoints,
    centre: Point,
) -> Vec<(Vec<Point>, usize)> {
    let n = arch.voussoirs();
    let (r0, d) = (arch.radius() - 0.5 * arch.thickness(), arch.thickness());
    let half = |j: usize| {
        // The angle of half-voussoir step j (0..=2n).
        let whole = arch.interface_angle_deg(j / 2);
        if j.is_multiple_of(2) {
            whole
        } else {
            0.5 * (whole + arch.interface_angle_deg(j / 2 + 1))
        }
    };
    let mut out = Vec::new();
    for ring in 0..rings {
        let (inner, outer) = (
            r0 + d * ring as f64 / rings as f64,
            r0 + d * (ring + 1) as f64 / rings as f64,
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
            polygon.push(polar(centre, inner, half(w[0])));
            polygon.extend(steps.iter().map(|&j| polar(centre, outer, half(j))));
            polygon.extend(steps.iter().rev().map(|&j| polar(centre, inner, half(j))));
            polygon.pop();
            out.push((polygon, ring));
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

/// A joint along a radius of its span (between voussoirs, at a springing) runs from its
/// intrados end (nearer the span's centre) to its extrados end, and its angle is its polar
/// angle about that centre, as on a chain (model §1.3): contacts are found in either direction,
/// and a hinge's face and angle are read from this orientation. Other contacts (between rings,
/// under piers) keep theirs.
fn orient_radially(interface: &mut Interface, centres: &[Point], radius: f64) {
    let middle = (
        0.5 * (interface.intrados.0 + interface.extrados.0),
        0.5 * (interface.intrados.1 + interface.extrados.1),
    );
    let away = |c: &Point| ((middle.0 - c.0).hypot(middle.1 - c.1) - radius).abs();
    let Some(centre) = centres.iter().min_by(|a, b| away(a).total_cmp(&away(b))) else {
        return;
    };
    let (dx, dy) = (middle.0 - centre.0, middle.1 - centre.1);
    let distance = dx.hypot(dy);
    if distance == 0.0 {
        return;
    }
    let along = (interface.tangent.0 * dx + interface.tangent.1 * dy) / distance;
    // Radial to 1e-9 (a joint of the generator lies on its radius up to rounding).
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

/// The ranges of a bridge: 1 to 16 rings, 1 to 20 spans, piers wide enough that the springings
/// of two spans do not cross and no higher than 1000 times the extrados radius.
fn check_bridge(arch: &CircularArch, rings: usize, piers: &Piers) -> Result<(), ArchError> {
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
    let r_out = arch.radius() + 0.5 * arch.thickness();
    let (right, left) = (
        arch.interface_angle_deg(0),
        arch.interface_angle_deg(arch.voussoirs()),
    );
    let (c, b) = (right.to_radians(), (180.0 - left).to_radians());
    if piers.spans > 1 {
        // The extrados springings of the two spans on a pier must not cross.
        let least = arch.thickness() * (c.cos() + b.cos());
        let width_ok = piers.width.is_finite()
            && piers.width >= least.max(0.0) + CONTACT_TOLERANCE * r_out
            && piers.width <= 1e3 * r_out;
        if !width_ok {
            return Err(ArchError::range(
                ArchParameter::PierWidth,
                piers.width,
                format!("{least} < width ≤ 1000·(R + D/2) (the springings must not overlap)"),
            ));
        }
        if !(piers.height.is_finite() && piers.height > 0.0 && piers.height <= 1e3 * r_out) {
            return Err(ArchError::range(
                ArchParameter::PierHeight,
                piers.height,
                "0 < height ≤ 1000·(R + D/2)",
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
    check_bridge(arch, rings, &piers)?;
    let (r_in, r_out) = (
        arch.radius() - 0.5 * arch.thickness(),
        arch.radius() + 0.5 * arch.thickness(),
    );
    let (right, left) = (
        arch.interface_angle_deg(0),
        arch.interface_angle_deg(arch.voussoirs()),
    );
    let (c, b) = (right.to_radians(), (180.0 - left).to_radians());
    let pitch = r_in * c.cos() + piers.width + r_in * b.cos();
    let mut polygons = Vec::new();
    let mut ring_of = Vec::new();
    let mut extrados = Vec::new();
    for span in 0..piers.spans {
        let centre = (span as f64 * pitch, 0.0);
        for (polygon, ring) in span_blocks(arch, rings, joints, centre) {
            if ring + 1 == rings {
                // The corners on the outer circle, in order (a run: the polygon goes inner
                // start, outer corners, inner corners back).
                let on_outer = |p: &&Point| {
                    ((p.0 - centre.0).hypot(p.1 - centre.1) - r_out).abs() <= 1e-9 * r_out
                };
                extrados.push((
                    polygons.len(),
                    polygon.iter().filter(on_outer).copied().collect(),
                ));
            }
            polygons.push(polygon);
            ring_of.push(Some(ring));
        }
    }
    let depth = arch.thickness();
    let mut supports = Vec::new();
    // The abutments at the two ends: the last span's right springing, the first's left.
    let first = (0.0, 0.0);
    let last = ((piers.spans - 1) as f64 * pitch, 0.0);
    supports.push(abutment(
        polar(last, r_in, right),
        polar(last, r_out, right),
        (c.sin(), -c.cos()),
        depth,
    ));
    let away_left = (-(left.to_radians()).sin(), left.to_radians().cos());
    supports.push(abutment(
        polar(first, r_in, left),
        polar(first, r_out, left),
        away_left,
        depth,
    ));
    // Piers between spans i (right springing) and i + 1 (left springing), on the ground.
    for span in 0..piers.spans.saturating_sub(1) {
        let (a, z) = ((span as f64 * pitch, 0.0), ((span + 1) as f64 * pitch, 0.0));
        let (i_l, e_l) = (polar(a, r_in, right), polar(a, r_out, right));
        let (i_r, e_r) = (polar(z, r_in, left), polar(z, r_out, left));
        let bottom = i_l.1.min(i_r.1) - piers.height;
        extrados.push((polygons.len(), vec![e_r, e_l]));
        polygons.push(vec![(i_l.0, bottom), (i_r.0, bottom), i_r, e_r, e_l, i_l]);
        ring_of.push(None);
        let ground = piers.width.max(depth);
        supports.push(vec![
            (i_l.0, bottom - ground),
            (i_r.0, bottom - ground),
            (i_r.0, bottom),
            (i_l.0, bottom),
        ]);
    }
    let mut assembly = Assembly::from_polygons(&polygons, &supports)?;
    let centres: Vec<Point> = (0..piers.spans)
        .map(|span| (span as f64 * pitch, 0.0))
        .collect();
    for interface in &mut assembly.interfaces {
        if let (Some(x), Some(y)) = (interface.lower, interface.upper) {
            if let (Some(p), Some(q)) = (ring_of[x], ring_of[y]) {
                if p != q {
                    interface.kind = InterfaceKind::Ring;
                }
            }
        }
        orient_radially(interface, &centres, arch.radius());
    }
    Ok(Bridge {
        assembly,
        ring: ring_of,
        extrados,
    })
}
