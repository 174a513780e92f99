//! Fill over an arch (model §5.1): its dead weight as a vertical load on each voussoir's extrados
//! (the column of fill between the extrados and the road), and loads on the road dispersed
//! through the fill down to the extrados.
//!
//! Each voussoir's extrados is sampled (an arc for curved voussoirs of a circular arch, the
//! straight face otherwise) and the columns integrated over the samples by the trapezoidal
//! rule, which for 64 samples per voussoir is exact to ~1e-5 of the column on the coarsest
//! arches and far better on fine ones.

use super::equilibrium::LiveLoad;
pub use super::equilibrium::PassiveForce;
use super::geometry::Assembly;

/// Samples of each voussoir's extrados.
const SAMPLES: usize = 64;

/// The shape of the extrados faces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Extrados {
    /// Straight faces between the extrados corners.
    Straight,
    /// Arcs about `centre` (curved voussoirs of a circular arch).
    Arc {
        /// Centre of the arcs.
        centre: (f64, f64),
    },
}

/// The fill: unit weight, road level, the dispersal angle of road loads and denser layers
/// below given levels (backing).
#[derive(Debug, Clone, PartialEq)]
pub struct Fill {
    /// Unit weight of the fill (≥ 0).
    pub unit_weight: f64,
    /// The road level (absolute y), above the crown's extrados.
    pub road: f64,
    /// Dispersal angle of road loads from the vertical, in degrees (0 ≤ δ ≤ 60).
    pub dispersal_angle_deg: f64,
    /// Layers by level, lowest first (distinct levels below the road): below each one's level
    /// and above the next lower one's, the fill weighs that layer's unit weight (model §10).
    pub layers: Vec<FillLayer>,
}

/// A layer of the fill: below `below` (down to the next lower layer) it weighs `unit_weight`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FillLayer {
    /// The layer's top level (absolute y).
    pub below: f64,
    /// Its unit weight (≥ 0).
    pub unit_weight: f64,
}

impl Fill {
    /// The weight of the column of fill from level y up to the road, per unit horizontal length:
    /// ∫ γ(η) dη over y < η < road.
    pub fn column(&self, y: f64) -> f64 {
        let mut weight = 0.0;
        let mut floor = y;
        for layer in &self.layers {
            let top = layer.below.min(self.road);
            if top > floor {
                weight += layer.unit_weight * (top - floor);
                floor = top;
            }
        }
        weight + self.unit_weight * (self.road - floor).max(0.0)
    }

    /// The levels where the column's unit weight changes, strictly between `a` and `b`.
    fn levels_between(&self, a: f64, b: f64) -> impl Iterator<Item = f64> + '_ {
        let (lo, hi) = (a.min(b), a.max(b));
        self.layers
            .iter()
            .map(|l| l.below)
            .filter(move |&y| y > lo && y < hi)
    }

    /// A piece of a face from `p` to `q` cut where it crosses a layer's level (the column is
    /// linear between the cuts), as the points along it.
    fn cut(&self, p: (f64, f64), q: (f64, f64)) -> Vec<(f64, f64)> {
        let mut ts: Vec<f64> = self
            .levels_between(p.1, q.1)
            .map(|y| (y - p.1) / (q.1 - p.1))
            .collect();
        ts.sort_by(f64::total_cmp);
        let mut points = vec![p];
        points.extend(
            ts.into_iter()
                .map(|t| (p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1))),
        );
        points.push(q);
        points
    }
}

/// A load on the road: `fy` (up positive) spread over a patch `length` wide centred at `x`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadLoad {
    /// Centre of the patch.
    pub x: f64,
    /// Vertical force (up positive).
    pub fy: f64,
    /// Width of the patch (≥ 0).
    pub length: f64,
}

/// The extrados of block `b`, sampled from its start corner to its end corner.
fn extrados_points(assembly: &Assembly, b: usize, shape: Extrados) -> Vec<(f64, f64)> {
    let c = &assembly.blocks[b].corners;
    let (start, end) = (c[1], c[2]);
    (0..=SAMPLES)
        .map(|k| {
            let t = k as f64 / SAMPLES as f64;
            match shape {
                Extrados::Straight => (
                    start.0 + t * (end.0 - start.0),
                    start.1 + t * (end.1 - start.1),
                ),
                Extrados::Arc { centre } => {
                    let r = (start.0 - centre.0).hypot(start.1 - centre.1);
                    let a0 = (start.1 - centre.1).atan2(start.0 - centre.0);
                    let mut a1 = (end.1 - centre.1).atan2(end.0 - centre.0);
                    // The short way round.
                    while a1 - a0 > std::f64::consts::PI {
                        a1 -= 2.0 * std::f64::consts::PI;
                    }
                    while a0 - a1 > std::f64::consts::PI {
                        a1 += 2.0 * std::f64::consts::PI;
                    }
                    let a = a0 + t * (a1 - a0);
                    (centre.0 + r * a.cos(), centre.1 + r * a.sin())
                }
            }
        })
        .collect()
}

/// y of the extrados polyline `points` at x (`None` outside its x-range).
fn y_at(points: &[(f64, f64)], x: f64) -> Option<f64> {
    points.windows(2).find_map(|w| {
        let (lo, hi) = (w[0].0.min(w[1].0), w[0].0.max(w[1].0));
        (x >= lo && x <= hi).then(|| {
            if hi > lo {
                w[0].1 + (w[1].1 - w[0].1) * (x - w[0].0) / (w[1].0 - w[0].0)
            } else {
                w[0].1.max(w[1].1)
            }
        })
    })
}

/// The faces the fill lies on, each with its block, sampled: a chain's extrados, or the outer
/// faces of a generated bridge (its outer ring and pier tops).
#[derive(Debug, Clone, PartialEq)]
pub struct ExtradosFaces {
    faces: Vec<(usize, Vec<(f64, f64)>)>,
}

impl ExtradosFaces {
    /// A chain's extrados: each block's face from its corner 1 to its corner 2, straight or an
    /// arc, [`SAMPLES`] pieces.
    pub fn of_chain(assembly: &Assembly, shape: Extrados) -> Self {
        Self {
            faces: (0..assembly.blocks.len())
                .map(|b| (b, extrados_points(assembly, b, shape)))
                .collect(),
        }
    }

    /// Faces given as (block, polyline along the face): each straight piece cut into equal
    /// parts, [`SAMPLES`] in all per face at least one per piece (the columns are linear on
    /// each part, but where the road crosses the face).
    pub fn of_faces(faces: Vec<(usize, Vec<(f64, f64)>)>) -> Self {
        let faces = faces
            .into_iter()
            .filter(|(_, points)| points.len() >= 2)
            .map(|(b, points)| {
                let parts = SAMPLES.div_ceil(points.len() - 1).max(1);
                let mut sampled = vec![points[0]];
                for w in points.windows(2) {
                    sampled.extend((1..=parts).map(|k| {
                        let t = k as f64 / parts as f64;
                        (
                            w[0].0 + t * (w[1].0 - w[0].0),
                            w[0].1 + t * (w[1].1 - w[0].1),
                        )
                    }));
                }
                (b, sampled)
            })
            .collect();
        Self { faces }
    }

    /// The highest point of the faces (the crown's, for an arch).
    pub fn top(&self) -> f64 {
        self.faces
            .iter()
            .flat_map(|f| &f.1)
            .fold(f64::NEG_INFINITY, |m, p| m.max(p.1))
    }

    /// The faces: (block, points along the face).
    pub fn faces(&self) -> &[(usize, Vec<(f64, f64)>)] {
        &self.faces
    }
}

/// The fill's weight on each voussoir: a vertical load at the column's centroid x, on the
/// extrados. Blocks with no fill above them carry none.
pub fn fill_dead_loads(faces: &ExtradosFaces, fill: &Fill) -> Vec<LiveLoad> {
    if !fill.layers.is_empty() {
        return layered_dead_loads(faces, fill);
    }
    if fill.unit_weight == 0.0 {
        return Vec::new();
    }
    faces
        .faces
        .iter()
        .filter_map(|(b, points)| {
            let (mut area, mut moment) = (0.0, 0.0);
            for w in points.windows(2) {
                let (h0, h1) = ((fill.road - w[0].1).max(0.0), (fill.road - w[1].1).max(0.0));
                let dx = (w[1].0 - w[0].0).abs();
                let a = 0.5 * (h0 + h1) * dx;
                let x = if h0 + h1 > 0.0 {
                    // The trapezoid's centroid, measured from w[0] towards w[1].
                    w[0].0 + (w[1].0 - w[0].0) * (h0 + 2.0 * h1) / (3.0 * (h0 + h1))
                } else {
                    0.5 * (w[0].0 + w[1].0)
                };
                area += a;
                moment += a * x;
            }
            (area > 0.0).then(|| {
                let x = moment / area;
                LiveLoad {
                    block: *b,
                    point: (x, y_at(points, x).unwrap_or(points[points.len() / 2].1)),
                    fx: 0.0,
                    fy: -fill.unit_weight * area,
                    moment: 0.0,
                }
            })
        })
        .collect()
}

/// [`fill_dead_loads`] with layers: each sampled piece cut where it crosses a layer's level,
/// the column's weight linear in x on each part (exact for straight faces).
fn layered_dead_loads(faces: &ExtradosFaces, fill: &Fill) -> Vec<LiveLoad> {
    faces
        .faces
        .iter()
        .filter_map(|(b, points)| {
            let (mut force, mut moment) = (0.0, 0.0);
            for w in points.windows(2) {
                for p in fill.cut(w[0], w[1]).windows(2) {
                    let (w0, w1) = (fill.column(p[0].1), fill.column(p[1].1));
                    let f = 0.5 * (w0 + w1) * (p[1].0 - p[0].0).abs();
                    let x = if w0 + w1 > 0.0 {
                        p[0].0 + (p[1].0 - p[0].0) * (w0 + 2.0 * w1) / (3.0 * (w0 + w1))
                    } else {
                        0.5 * (p[0].0 + p[1].0)
                    };
                    force += f;
                    moment += f * x;
                }
            }
            (force > 0.0).then(|| {
                let x = moment / force;
                LiveLoad {
                    block: *b,
                    point: (x, y_at(points, x).unwrap_or(points[points.len() / 2].1)),
                    fx: 0.0,
                    fy: -force,
                    moment: 0.0,
                }
            })
        })
        .collect()
}

/// The extrados of every voussoir, sampled once: what dispersing road loads needs.
#[derive(Debug, Clone, PartialEq)]
pub struct ExtradosProfile {
    /// (block, points) of each face.
    blocks: Vec<(usize, Vec<(f64, f64)>)>,
    /// Each block's x-range.
    ranges: Vec<(f64, f64)>,
    /// The upper envelope as a polyline sorted by x.
    envelope: Vec<(f64, f64)>,
}

impl ExtradosProfile {
    /// Samples the extrados of `assembly`.
    pub fn new(faces: &ExtradosFaces) -> Self {
        let blocks = faces.faces.clone();
        let ranges = blocks
            .iter()
            .map(|(_, p)| {
                p.iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, c), q| {
                        (a.min(q.0), c.max(q.0))
                    })
            })
            .collect();
        let mut envelope: Vec<(f64, f64)> = blocks.iter().flat_map(|f| &f.1).copied().collect();
        envelope.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.total_cmp(&a.1)));
        envelope.dedup_by(|next, kept| next.0 == kept.0);
        Self {
            blocks,
            ranges,
            envelope,
        }
    }

    /// The upper envelope of the faces, sorted by x (for drawings).
    pub fn envelope(&self) -> &[(f64, f64)] {
        &self.envelope
    }

    /// The extrados' height at x (its upper envelope); −∞ outside the arch.
    fn surface(&self, x: f64) -> f64 {
        let e = &self.envelope;
        if e.is_empty() || x < e[0].0 || x > e[e.len() - 1].0 {
            return f64::NEG_INFINITY;
        }
        let i = e.partition_point(|p| p.0 < x);
        if i == 0 {
            return e[0].1;
        }
        let (a, b) = (e[i - 1], e[i.min(e.len() - 1)]);
        if b.0 > a.0 {
            a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
        } else {
            a.1.max(b.1)
        }
    }
}

/// A road load dispersed through the fill: from each end of the patch a line runs down at the
/// dispersal angle, outward, to the extrados; between the two points the load is a uniform
/// pressure per horizontal length, shared among the voussoirs by horizontal overlap (what
/// falls beyond the arch goes to the abutments). A point load (no width left) goes to the
/// voussoir under it.
pub fn road_load(faces: &ExtradosFaces, fill: &Fill, load: RoadLoad) -> Vec<LiveLoad> {
    road_load_on(&ExtradosProfile::new(faces), fill, load)
}

impl ExtradosProfile {
    /// The x range of the extrados.
    pub fn x_range(&self) -> (f64, f64) {
        self.ranges
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
                (a.min(r.0), b.max(r.1))
            })
    }

    /// Where a line from (x0, road) going down and outward (`side` −1: left, +1: right) at the
    /// dispersal angle first meets the extrados: the first x beyond x0 with
    /// (road − y_e(x))·tan δ ≤ |x − x0|, found by scanning towards the arch's far end and
    /// bisecting. Beyond the springings y_e is the springing's level: a line starting beyond
    /// the arch and going away from it ends at x0, one starting beyond it and going towards it
    /// may reach that level before the arch (and ends there), one that passes over the whole
    /// arch ends where it reaches the far springing's level (beyond the arch; what falls there
    /// goes to the abutment).
    fn meet(&self, fill: &Fill, x0: f64, side: f64) -> f64 {
        const STEPS: usize = 256;
        let tan = fill.dispersal_angle_deg.to_radians().tan();
        if tan == 0.0 {
            return x0;
        }
        let (x_lo, x_hi) = self.x_range();
        // Above the line at x: positive while the line has not yet reached the extrados; beyond
        // the arch, the level of the springing on that side (a line from a load beyond the
        // arch that reaches that level first ends there, on the abutment).
        let above = |x: f64| {
            let y = self.surface(x.clamp(x_lo, x_hi));
            if y.is_finite() {
                (fill.road - y) * tan - (x - x0).abs()
            } else {
                f64::INFINITY
            }
        };
        let far = if side < 0.0 { x_lo } else { x_hi };
        if (far - x0) * side <= 0.0 {
            return x0;
        }
        let step = (far - x0) / STEPS as f64;
        let mut previous = x0;
        for k in 1..=STEPS {
            let x = x0 + step * k as f64;
            if above(x) <= 0.0 {
                // Bisect on [previous, x], where the line crosses the extrados (or enters
                // the arch already below its extrados: then at the springing).
                let (mut a, mut b) = (previous, x);
                for _ in 0..60 {
                    let m = 0.5 * (a + b);
                    if above(m) > 0.0 {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                return 0.5 * (a + b);
            }
            previous = x;
        }
        // Over the whole arch without meeting it: on to the springing's level, beyond the arch.
        let y_far = self.surface(far);
        let y_far = if y_far.is_finite() { y_far } else { fill.road };
        x0 + side * ((fill.road - y_far) * tan).max((far - x0).abs())
    }

    /// The two points where a road load's dispersal lines meet the extrados (for drawings);
    /// a line that passes over the arch ends on its own way down, at the far springing's
    /// level beyond the arch (a load beyond the arch going away from it: at the road).
    pub fn dispersal_ends(&self, fill: &Fill, load: RoadLoad) -> [(f64, f64); 2] {
        let tan = fill.dispersal_angle_deg.to_radians().tan();
        [(-1.0, -0.5), (1.0, 0.5)].map(|(side, half)| {
            let x0 = load.x + half * load.length;
            let x = self.meet(fill, x0, side);
            let y = self.surface(x);
            let y = if y.is_finite() {
                y
            } else if tan > 0.0 {
                fill.road - (x - x0).abs() / tan
            } else {
                fill.road
            };
            (x, y)
        })
    }
}

/// [`road_load`] on an extrados sampled once (for many loads, as a rolling sweep has).
pub fn road_load_on(profile: &ExtradosProfile, fill: &Fill, load: RoadLoad) -> Vec<LiveLoad> {
    let blocks = &profile.blocks;
    let surface = |x: f64| profile.surface(x);
    let (x_lo, x_hi) = profile.x_range();
    let left = profile.meet(fill, load.x - 0.5 * load.length, -1.0);
    let right = profile.meet(fill, load.x + 0.5 * load.length, 1.0);
    let width = right - left;
    let mut out = Vec::new();
    for (k, (b, points)) in blocks.iter().enumerate() {
        let (b, (lo, hi)) = (*b, profile.ranges[k]);
        if width <= 1e-12 * (x_hi - x_lo).max(1.0) {
            // A point load on the voussoir under it (the first one whose extrados spans x).
            if left >= lo && left <= hi && out.is_empty() {
                out.push(LiveLoad {
                    block: b,
                    point: (left, y_at(points, left).unwrap_or_else(|| surface(left))),
                    fx: 0.0,
                    fy: load.fy,
                    moment: 0.0,
                });
            }
            continue;
        }
        let (a, c) = (left.max(lo), right.min(hi));
        if c > a {
            let x = 0.5 * (a + c);
            out.push(LiveLoad {
                block: b,
                point: (x, y_at(points, x).unwrap_or_else(|| surface(x))),
                fx: 0.0,
                fy: load.fy * (c - a) / width,
                moment: 0.0,
            });
        }
    }
    out
}

/// Passive restraint of the fill (model §5.1): where the arch sways into the fill, a horizontal
/// pressure on the extrados of up to `mobilisation`·K_p·σ_v, K_p = (1 + sin φ)/(1 − sin φ) and
/// σ_v = γ_f·(road − y) the fill's vertical stress (with layers, the column's weight above y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Passive {
    /// Friction angle φ of the fill, in degrees (0 ≤ φ < 90).
    pub friction_angle_deg: f64,
    /// Fraction of the full passive pressure that may be mobilised (0 ≤ m ≤ 1).
    pub mobilisation: f64,
}

impl Passive {
    /// Rankine's passive coefficient K_p = (1 + sin φ)/(1 − sin φ).
    pub fn coefficient(&self) -> f64 {
        let s = self.friction_angle_deg.to_radians().sin();
        (1.0 + s) / (1.0 - s)
    }
}

/// The passive forces the fill can exert on each voussoir: the extrados is sampled as for the
/// fill's weight; each piece facing the fill sideways contributes m·K_p·σ_v·|Δy| (trapezoidal
/// rule) towards the arch. A voussoir whose extrados faces both ways (at the crown) gets one
/// force per direction. Pieces above the road carry nothing.
pub fn passive_forces(
    assembly: &Assembly,
    faces: &ExtradosFaces,
    fill: &Fill,
    passive: &Passive,
) -> Vec<PassiveForce> {
    let layered = !fill.layers.is_empty();
    let scale =
        passive.mobilisation * passive.coefficient() * if layered { 1.0 } else { fill.unit_weight };
    let heaviest = fill
        .layers
        .iter()
        .map(|l| l.unit_weight)
        .fold(fill.unit_weight, f64::max);
    if scale <= 0.0 || heaviest <= 0.0 {
        return Vec::new();
    }
    // σ_v: the column above the point (with layers), or γ_f·(road − y).
    let stress = |y: f64| {
        if layered {
            scale * fill.column(y)
        } else {
            scale * (fill.road - y).max(0.0)
        }
    };
    let mut out = Vec::new();
    for (b, points) in &faces.faces {
        let (b, block) = (*b, &assembly.blocks[*b]);
        // (force, Σ force·x, Σ force·y) per direction: index 0 towards −x, 1 towards +x.
        let mut sums = [[0.0f64; 3]; 2];
        let mut add = |a: (f64, f64), c: (f64, f64)| {
            let (dx, dy) = (c.0 - a.0, c.1 - a.1);
            let middle = (0.5 * (a.0 + c.0), 0.5 * (a.1 + c.1));
            // The normal of the piece pointing out of the block (into the fill).
            let mut normal = (-dy, dx);
            let away = (middle.0 - block.centroid.0, middle.1 - block.centroid.1);
            if normal.0 * away.0 + normal.1 * away.1 < 0.0 {
                normal = (dy, -dx);
            }
            let (s0, s1) = (stress(a.1), stress(c.1));
            let force = 0.5 * (s0 + s1) * dy.abs();
            if normal.0 == 0.0 || force <= 0.0 {
                return;
            }
            // Centroid of the trapezoidal load along the piece.
            let t = (s0 + 2.0 * s1) / (3.0 * (s0 + s1));
            let at = (a.0 + t * dx, a.1 + t * dy);
            let side = usize::from(normal.0 < 0.0);
            sums[side][0] += force;
            sums[side][1] += force * at.0;
            sums[side][2] += force * at.1;
        };
        for w in points.windows(2) {
            if layered {
                // Cut where the piece crosses a layer's level: σ_v is linear between.
                fill.cut(w[0], w[1])
                    .windows(2)
                    .for_each(|p| add(p[0], p[1]));
            } else {
                add(w[0], w[1]);
            }
        }
        for (side, s) in sums.iter().enumerate() {
            if s[0] > 0.0 {
                out.push(PassiveForce {
                    block: b,
                    point: (s[1] / s[0], s[2] / s[0]),
                    direction: if side == 1 { 1.0 } else { -1.0 },
                    capacity: s[0],
                });
            }
        }
    }
    out
}
