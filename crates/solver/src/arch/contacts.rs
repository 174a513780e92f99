//! Any assembly of polygonal blocks on fixed supports (model §5.4): the polygons are checked,
//! oriented counter-clockwise, and their contacts found where an edge of one block runs along
//! an edge of another block or of a support, in the opposite direction, over a positive length.
//! Each contact is a Livesley interface between its two ends (q and s there, t along it).
//!
//! Tolerance: points closer than [`CONTACT_TOLERANCE`] × the assembly's size count as the same
//! (edges on one line, overlaps of no length, shared corners), so coordinates rounded to about
//! seven significant digits still touch.

use super::error::{ArchError, ArchParameter};
use super::geometry::{Assembly, Block, Interface, InterfaceKind};
use crate::polygon::polygon_area_centroid;

/// Contact tolerance relative to the assembly's size.
pub const CONTACT_TOLERANCE: f64 = 1e-7;

/// Pairs of polygons whose boxes touch, at most.
const MAX_PAIRS: usize = 1_000_000;
/// Pairs of edges the contact search compares at most.
const MAX_EDGE_PAIRS: usize = 50_000_000;

type Point = (f64, f64);

fn cross(o: Point, a: Point, b: Point) -> f64 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

/// Which polygon: block `b` or support `s` (0-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Piece {
    Block(usize),
    Support(usize),
}

impl Piece {
    fn parameter(self) -> ArchParameter {
        match self {
            Self::Block(block) => ArchParameter::BlockPolygon { block },
            Self::Support(support) => ArchParameter::SupportPolygon { support },
        }
    }

    fn name(self) -> String {
        match self {
            Self::Block(b) => format!("block {}", b + 1),
            Self::Support(s) => format!("support {}", s + 1),
        }
    }
}

/// A checked polygon, counter-clockwise.
struct Polygon {
    piece: Piece,
    points: Vec<Point>,
    lo: Point,
    hi: Point,
}

impl Polygon {
    fn edges(&self) -> impl Iterator<Item = (Point, Point)> + '_ {
        let n = self.points.len();
        (0..n).map(move |i| (self.points[i], self.points[(i + 1) % n]))
    }

    /// Whether `p` lies inside, farther than `tolerance` from every edge.
    fn strictly_contains(&self, p: Point, tolerance: f64) -> bool {
        let mut inside = false;
        for (a, b) in self.edges() {
            if (a.1 > p.1) != (b.1 > p.1) && p.0 < a.0 + (b.0 - a.0) * (p.1 - a.1) / (b.1 - a.1) {
                inside = !inside;
            }
            if distance_to_segment(p, a, b) <= tolerance {
                return false;
            }
        }
        inside
    }
}

fn distance_to_segment(p: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let length2 = dx * dx + dy * dy;
    let t = if length2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// Whether segments ab and cd cross at a point inside both (not merely touching).
fn properly_cross(a: Point, b: Point, c: Point, d: Point, tolerance: f64) -> bool {
    let scale = |u: Point, v: Point| (v.0 - u.0).hypot(v.1 - u.1);
    let (d1, d2) = (cross(c, d, a) / scale(c, d), cross(c, d, b) / scale(c, d));
    let (d3, d4) = (cross(a, b, c) / scale(a, b), cross(a, b, d) / scale(a, b));
    let strictly =
        |x: f64, y: f64| (x > tolerance && y < -tolerance) || (x < -tolerance && y > tolerance);
    strictly(d1, d2) && strictly(d3, d4)
}

fn check_polygon(piece: Piece, given: &[Point], tolerance: f64) -> Result<Polygon, ArchError> {
    let parameter = piece.parameter();
    if given.len() < 3 {
        return Err(ArchError::geometry(
            parameter,
            format!("{} needs at least 3 corners", piece.name()),
        ));
    }
    if given.iter().any(|p| !(p.0.is_finite() && p.1.is_finite())) {
        return Err(ArchError::geometry(
            parameter,
            "corners must be finite numbers",
        ));
    }
    let n = given.len();
    for i in 0..n {
        let (a, b) = (given[i], given[(i + 1) % n]);
        if (b.0 - a.0).hypot(b.1 - a.1) <= tolerance {
            return Err(ArchError::geometry(
                parameter,
                format!(
                    "{} has an edge of no length (corners {} and {} coincide)",
                    piece.name(),
                    i + 1,
                    (i + 1) % n + 1
                ),
            ));
        }
    }
    check_not_self_intersecting(piece, given, tolerance)?;
    let (area, _) = polygon_area_centroid(given);
    let extent = given
        .iter()
        .flat_map(|p| given.iter().map(move |q| (p.0 - q.0).hypot(p.1 - q.1)))
        .fold(0.0, f64::max);
    if area.abs() <= 1e-12 * extent * extent {
        return Err(ArchError::geometry(
            parameter,
            format!("{} has no area", piece.name()),
        ));
    }
    // Clockwise polygons are turned round (the same block).
    let mut points = given.to_vec();
    if area < 0.0 {
        points.reverse();
    }
    let lo = points.iter().fold((f64::INFINITY, f64::INFINITY), |m, p| {
        (m.0.min(p.0), m.1.min(p.1))
    });
    let hi = points
        .iter()
        .fold((f64::NEG_INFINITY, f64::NEG_INFINITY), |m, p| {
            (m.0.max(p.0), m.1.max(p.1))
        });
    Ok(Polygon {
        piece,
        points,
        lo,
        hi,
    })
}

/// Rejects a polygon two of whose non-adjacent edges touch or cross.
fn check_not_self_intersecting(
    piece: Piece,
    given: &[Point],
    tolerance: f64,
) -> Result<(), ArchError> {
    let n = given.len();
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            let (a, b) = (given[i], given[(i + 1) % n]);
            let (c, d) = (given[j], given[(j + 1) % n]);
            let touching = distance_to_segment(a, c, d).min(distance_to_segment(b, c, d))
                <= tolerance
                || distance_to_segment(c, a, b).min(distance_to_segment(d, a, b)) <= tolerance;
            if touching || properly_cross(a, b, c, d, 0.0) {
                return Err(ArchError::geometry(
                    piece.parameter(),
                    format!(
                        "{} is self-intersecting: edges {} and {} meet",
                        piece.name(),
                        i + 1,
                        j + 1
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The contact of edge (a, b) of a counter-clockwise polygon with edge (c, d) of another, when
/// they run along one line in opposite directions and overlap: its two ends, along (a, b).
fn contact(a: Point, b: Point, c: Point, d: Point, tolerance: f64) -> Option<(Point, Point)> {
    let length = (b.0 - a.0).hypot(b.1 - a.1);
    let u = ((b.0 - a.0) / length, (b.1 - a.1) / length);
    let along = |p: Point| (p.0 - a.0) * u.0 + (p.1 - a.1) * u.1;
    let off = |p: Point| ((p.0 - a.0) * u.1 - (p.1 - a.1) * u.0).abs();
    if off(c) > tolerance || off(d) > tolerance || along(d) - along(c) >= 0.0 {
        return None;
    }
    let (t0, t1) = (along(d).max(0.0), along(c).min(length));
    (t1 - t0 > tolerance).then(|| {
        let at = |t: f64| (a.0 + t * u.0, a.1 + t * u.1);
        (at(t0), at(t1))
    })
}

/// Whether two edges lie along one line in the same direction and overlap (two pieces
/// covering the same ground).
fn same_way_overlap(a: Point, b: Point, c: Point, d: Point, tolerance: f64) -> bool {
    contact(a, b, d, c, tolerance).is_some()
}

fn boxes_meet(p: &Polygon, q: &Polygon, tolerance: f64) -> bool {
    p.lo.0 <= q.hi.0 + tolerance
        && q.lo.0 <= p.hi.0 + tolerance
        && p.lo.1 <= q.hi.1 + tolerance
        && q.lo.1 <= p.hi.1 + tolerance
}

/// Pairs of polygons (i < j, at least one a block) whose boxes touch, by sweeping the boxes
/// along x; bounded, so that no input makes the check run for minutes.
fn candidate_pairs(
    polygons: &[Polygon],
    n: usize,
    tolerance: f64,
) -> Result<Vec<(usize, usize)>, ArchError> {
    // Candidate pairs by sweeping the boxes along x.
    let mut order: Vec<usize> = (0..polygons.len()).collect();
    order.sort_by(|&i, &j| polygons[i].lo.0.total_cmp(&polygons[j].lo.0));
    let mut pairs = Vec::new();
    for (position, &i) in order.iter().enumerate() {
        for &j in &order[position + 1..] {
            if polygons[j].lo.0 > polygons[i].hi.0 + tolerance {
                break;
            }
            if (i < n || j < n) && boxes_meet(&polygons[i], &polygons[j], tolerance) {
                pairs.push((i.min(j), i.max(j)));
                if pairs.len() > MAX_PAIRS {
                    return Err(ArchError::geometry(
                        ArchParameter::Blocks,
                        format!(
                            "more than {MAX_PAIRS} pairs of polygons whose boxes touch: \
                             the polygons overlap, or there are too many"
                        ),
                    ));
                }
            }
        }
    }
    pairs.sort_unstable();
    // Edge pairs to compare: bounded, so that no input makes the check run for minutes.
    let work: usize = pairs
        .iter()
        .map(|&(i, j)| polygons[i].points.len() * polygons[j].points.len())
        .sum();
    if work > MAX_EDGE_PAIRS {
        return Err(ArchError::geometry(
            ArchParameter::Blocks,
            format!(
                "too many neighbouring edges to check for contacts ({work} pairs of edges in \
                 touching boxes; at most {MAX_EDGE_PAIRS}): use fewer corners or blocks"
            ),
        ));
    }
    Ok(pairs)
}

/// The contacts between polygons i and j (j ≥ n: a support), as interfaces; an error when the
/// two overlap.
fn contacts_between(
    polygons: &[Polygon],
    (i, j): (usize, usize),
    n: usize,
    tolerance: f64,
) -> Result<Vec<Interface>, ArchError> {
    let mut found = Vec::new();
    let (p, q) = (&polygons[i], &polygons[j]);
    let overlap = p.edges().any(|(a, b)| {
        q.edges().any(|(c, d)| {
            properly_cross(a, b, c, d, tolerance) || same_way_overlap(a, b, c, d, tolerance)
        })
    }) || q.points.iter().any(|&v| p.strictly_contains(v, tolerance))
        || p.points.iter().any(|&v| q.strictly_contains(v, tolerance));
    if overlap {
        return Err(ArchError::geometry(
            p.piece.parameter(),
            format!("{} and {} overlap", p.piece.name(), q.piece.name()),
        ));
    }
    for (a, b) in p.edges() {
        for (c, d) in q.edges() {
            let Some((start, end)) = contact(a, b, c, d, tolerance) else {
                continue;
            };
            let length = (end.0 - start.0).hypot(end.1 - start.1);
            let tangent = ((end.0 - start.0) / length, (end.1 - start.1) / length);
            // Out of p (counter-clockwise: the edge turned clockwise).
            let outward = (tangent.1, -tangent.0);
            let (normal, lower, upper) = if j < n {
                (outward, Some(i), Some(j))
            } else {
                // A support: the normal points into the block.
                ((-outward.0, -outward.1), None, Some(i))
            };
            found.push(Interface {
                intrados: start,
                extrados: end,
                normal,
                tangent,
                angle_deg: tangent.1.atan2(tangent.0).to_degrees(),
                lower,
                upper,
                kind: InterfaceKind::Joint,
            });
        }
    }
    Ok(found)
}

/// Every block touches something and is held, through contacts, by a support.
fn check_held(interfaces: &[Interface], n: usize) -> Result<(), ArchError> {
    // Every block touches something and is held, through contacts, by a support.
    let mut neighbours = vec![Vec::new(); n];
    let mut held = vec![false; n];
    let mut queue: Vec<usize> = Vec::new();
    for i in interfaces {
        match (i.lower, i.upper) {
            (Some(x), Some(y)) => {
                neighbours[x].push(y);
                neighbours[y].push(x);
            }
            (None, Some(b)) | (Some(b), None) => {
                if !held[b] {
                    held[b] = true;
                    queue.push(b);
                }
            }
            (None, None) => {}
        }
    }
    while let Some(b) = queue.pop() {
        for &other in &neighbours[b] {
            if !held[other] {
                held[other] = true;
                queue.push(other);
            }
        }
    }
    if let Some(b) = held.iter().position(|h| !h) {
        let touches = !neighbours[b].is_empty();
        let reason = if touches {
            format!(
                "block {} is not connected to any support through its contacts",
                b + 1
            )
        } else {
            format!("block {} touches no other block and no support", b + 1)
        };
        return Err(ArchError::geometry(
            ArchParameter::BlockPolygon { block: b },
            reason,
        ));
    }
    Ok(())
}

impl Assembly {
    /// An assembly of polygonal `blocks` resting on fixed `supports` (polygons too): polygons
    /// of three or more corners in either orientation (clockwise ones are turned round),
    /// convex or not, with no two overlapping. Every block must touch something and be
    /// connected to a support through contacts. Interfaces are numbered in the order the
    /// contacts are found: block by block, edge by edge.
    pub fn from_polygons(
        blocks: &[Vec<Point>],
        supports: &[Vec<Point>],
    ) -> Result<Self, ArchError> {
        if blocks.is_empty() {
            return Err(ArchError::geometry(
                ArchParameter::Blocks,
                "at least one block is needed",
            ));
        }
        if supports.is_empty() {
            return Err(ArchError::geometry(
                ArchParameter::Supports,
                "at least one support is needed: a structure with no support cannot stand",
            ));
        }
        let all = blocks.iter().chain(supports).flatten();
        let (lo, hi) = all.fold(
            (
                (f64::INFINITY, f64::INFINITY),
                (f64::NEG_INFINITY, f64::NEG_INFINITY),
            ),
            |(lo, hi), p| {
                (
                    (lo.0.min(p.0), lo.1.min(p.1)),
                    (hi.0.max(p.0), hi.1.max(p.1)),
                )
            },
        );
        let size = (hi.0 - lo.0).max(hi.1 - lo.1);
        let tolerance = CONTACT_TOLERANCE * if size.is_finite() { size } else { 0.0 };
        let mut polygons = Vec::with_capacity(blocks.len() + supports.len());
        for (b, given) in blocks.iter().enumerate() {
            polygons.push(check_polygon(Piece::Block(b), given, tolerance)?);
        }
        for (s, given) in supports.iter().enumerate() {
            polygons.push(check_polygon(Piece::Support(s), given, tolerance)?);
        }
        let n = blocks.len();
        let mut interfaces = Vec::new();
        let pairs = candidate_pairs(&polygons, n, tolerance)?;
        for &(i, j) in &pairs {
            interfaces.extend(contacts_between(&polygons, (i, j), n, tolerance)?);
        }
        check_held(&interfaces, n)?;
        let blocks = polygons[..n]
            .iter()
            .map(|p| {
                let (area, centroid) = polygon_area_centroid(&p.points);
                Block {
                    corners: p.points.clone(),
                    area: area.abs(),
                    centroid,
                }
            })
            .collect();
        Ok(Self { blocks, interfaces })
    }
}
