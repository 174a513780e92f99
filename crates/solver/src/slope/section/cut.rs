//! The sliding mass of a section cut into vertical slices, in the solver's frame (crest towards
//! +x). Slice sides fall where the base changes: the surface's vertices and its crossings with
//! layer tops, the water line and bedrock, and the bedrock's kinks where the base follows it;
//! between those the slices are of equal width. Above the base, the weights and loads are
//! integrated exactly, piece by piece between the kinks and crossings of the ground, the layer
//! tops, the water line and the surcharge edges, so a section cut like the simple embankment
//! (one soil, no water) gets the simple embankment's slices.

use std::num::NonZeroUsize;

use super::polyline::Polyline;
use super::{Section, SlipShape};
use crate::slope::error::{SlopeError, SlopeParameter};
use crate::slope::slices::{BaseSlice, SliceModel};
use crate::slope::spencer::{ExternalLoad, Seismic};

/// Relative distance below which two cuts are one.
const SAME_CUT: f64 = 1e-9;

/// A cut sliding mass.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Cut {
    pub model: SliceModel,
    /// The slip surface as cut (the bases' end points), toe end first, solver frame.
    pub surface: Vec<(f64, f64)>,
    /// Toe end and crest end (top of the crack if there is one), solver frame.
    pub ends: ((f64, f64), (f64, f64)),
    /// The tension crack: x, bottom, top (solver frame).
    pub crack: Option<(f64, f64, f64)>,
    /// Whether the solver frame is the section mirrored.
    pub mirrored: bool,
}

/// y of the slip surface (before bedrock) at x.
fn shape_y(shape: &SlipShape, x: f64) -> f64 {
    match shape {
        SlipShape::Circle { centre, radius } => {
            centre.1 - (radius * radius - (x - centre.0).powi(2)).max(0.0).sqrt()
        }
        SlipShape::Polyline(line) => line.y_at(x),
    }
}

/// x where the slip surface meets `line` within (a, b).
fn shape_crossings(shape: &SlipShape, line: &Polyline, a: f64, b: f64) -> Vec<f64> {
    match shape {
        SlipShape::Circle { centre, radius } => line
            .circle_crossings(*centre, *radius, a, b)
            .into_iter()
            .filter(|c| c.1)
            .map(|c| c.0)
            .collect(),
        SlipShape::Polyline(surface) => surface.crossings(line, a, b),
    }
}

impl Cut {
    pub fn new(
        section: &Section,
        shape: &SlipShape,
        (entry, exit): (f64, f64),
        slices: NonZeroUsize,
        seismic: Seismic,
        moment_centre: Option<(f64, f64)>,
        mirrored: bool,
    ) -> Result<Self, SlopeError> {
        let ground = &section.ground;
        let base = |x: f64| {
            let y = shape_y(shape, x);
            section.bedrock.as_ref().map_or(y, |b| y.max(b.y_at(x)))
        };
        let scale = (exit - entry).max(ground.y_at(entry).abs()).max(1e-9);
        let tolerance = SAME_CUT * scale;
        let (xa, mut xb) = (entry, exit);
        let mut crack = None;
        if let Some(c) = section.tension_crack {
            let crack_line = Polyline::new(
                ground
                    .points()
                    .iter()
                    .map(|p| (p.0, p.1 - c.depth))
                    .collect(),
            )
            .map_err(|_| SlopeError::Conflict {
                parameter: SlopeParameter::TensionCrackDepth,
                reason: "the crack line is not a valid line".to_owned(),
            })?;
            let mut candidates = shape_crossings(shape, &crack_line, xa, xb);
            if let Some(b) = &section.bedrock {
                candidates.extend(b.crossings(&crack_line, xa, xb));
            }
            let last = candidates
                .into_iter()
                .filter(|&x| {
                    x > xa + tolerance
                        && x < xb - tolerance
                        && (base(x) - crack_line.y_at(x)).abs() <= 1e-7 * scale
                })
                .max_by(f64::total_cmp);
            let Some(x) = last else {
                return Err(SlopeError::NoSlipMass {
                    parameter: SlopeParameter::TensionCrackDepth,
                    reason: format!(
                        "the slip surface never lies deeper than the crack ({} below the \
                         ground): the whole mass would be inside the crack",
                        c.depth
                    ),
                });
            };
            xb = x;
            crack = Some((x, crack_line.y_at(x), ground.y_at(x)));
        }
        let cuts = base_cuts(section, shape, xa, xb, tolerance);
        let points = top_points(section, xa, xb, tolerance);
        let boundaries = allocate(&cuts, slices.get());
        let last = boundaries.len() - 1;
        let base_at = |i: usize, x: f64| {
            if i == 0 {
                ground.y_at(x)
            } else if i == last {
                crack.map_or(ground.y_at(x), |c| c.1)
            } else {
                base(x).min(ground.y_at(x))
            }
        };
        let base_ys: Vec<f64> = boundaries
            .iter()
            .enumerate()
            .map(|(i, &x)| base_at(i, x))
            .collect();
        let slices: Vec<BaseSlice> = (0..last)
            .map(|i| {
                slice(
                    section,
                    (boundaries[i], boundaries[i + 1]),
                    (base_ys[i], base_ys[i + 1]),
                    &points,
                    tolerance,
                )
            })
            .collect();
        let loads = loads(section, &slices, &points, crack);
        let surface: Vec<(f64, f64)> = boundaries
            .iter()
            .copied()
            .zip(base_ys.iter().copied())
            .chain(crack.map(|c| (c.0, c.2)))
            .collect();
        let (reference, has_moment_centre) = match (shape, moment_centre) {
            (SlipShape::Circle { centre, .. }, _) => (*centre, true),
            (SlipShape::Polyline(_), Some(centre)) => (centre, true),
            (SlipShape::Polyline(_), None) => {
                let top = ground.y_at(xa).max(ground.y_at(xb));
                ((0.5 * (xa + xb), top + 0.5 * (xb - xa)), false)
            }
        };
        let length_scale = surface
            .iter()
            .map(|p| (p.0 - reference.0).hypot(p.1 - reference.1))
            .fold(0.0f64, f64::max)
            .max(f64::MIN_POSITIVE);
        Ok(Self {
            model: SliceModel {
                slices,
                seismic,
                loads,
                reference,
                has_moment_centre,
                length_scale,
            },
            ends: (
                (xa, ground.y_at(xa)),
                (xb, crack.map_or(ground.y_at(xb), |c| c.2)),
            ),
            surface,
            crack,
            mirrored,
        })
    }
}

/// Sorted x in (a, b) closer than `tolerance` merged, with a and b at the ends.
fn sorted_between(xs: Vec<f64>, a: f64, b: f64, tolerance: f64) -> Vec<f64> {
    let mut cuts: Vec<f64> = std::iter::once(a)
        .chain(
            xs.into_iter()
                .filter(|&x| x > a + tolerance && x < b - tolerance),
        )
        .chain(std::iter::once(b))
        .collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|next, kept| *next - *kept <= tolerance);
    if let Some(end) = cuts.last_mut() {
        *end = b;
    }
    cuts
}

/// Where a slice side must fall, so that each base is straight, in one soil and on one side of
/// the water line: the surface's vertices, its crossings with layer tops, bedrock and the
/// piezometric line, and the bedrock's kinks and crossings where the base follows it.
fn base_cuts(section: &Section, shape: &SlipShape, a: f64, b: f64, tolerance: f64) -> Vec<f64> {
    let tops = section.layers.iter().filter_map(|l| l.top.as_ref());
    let lines: Vec<&Polyline> = tops
        .chain(section.bedrock.as_ref())
        .chain(section.piezometric_line.as_ref())
        .collect();
    let mut xs: Vec<f64> = Vec::new();
    if let SlipShape::Polyline(line) = shape {
        xs.extend(line.xs());
    }
    for line in &lines {
        xs.extend(shape_crossings(shape, line, a, b));
    }
    if let Some(bedrock) = &section.bedrock {
        let on_bedrock = |x: f64| bedrock.y_at(x) >= shape_y(shape, x) - tolerance;
        xs.extend(bedrock.xs().filter(|&x| on_bedrock(x)));
        for line in &lines {
            xs.extend(
                bedrock
                    .crossings(line, a, b)
                    .into_iter()
                    .filter(|&x| on_bedrock(x)),
            );
        }
    }
    sorted_between(xs, a, b, tolerance)
}

/// Where the lines above the base bend or cross (ground, layer tops, the water line, surcharge
/// edges): the slice weights and loads are integrated piecewise between these, exactly.
fn top_points(section: &Section, a: f64, b: f64, tolerance: f64) -> Vec<f64> {
    let lines: Vec<&Polyline> = std::iter::once(&section.ground)
        .chain(section.layers.iter().filter_map(|l| l.top.as_ref()))
        .chain(section.piezometric_line.as_ref())
        .collect();
    let mut xs: Vec<f64> = lines.iter().flat_map(|l| l.xs()).collect();
    xs.extend(section.surcharges.iter().flat_map(|s| [s.x_start, s.x_end]));
    for (i, line) in lines.iter().enumerate() {
        for other in &lines[i + 1..] {
            xs.extend(line.crossings(other, a, b));
        }
    }
    sorted_between(xs, a, b, tolerance)
}

/// The pieces of [xl, xr] between the top points.
fn pieces(points: &[f64], xl: f64, xr: f64) -> Vec<(f64, f64)> {
    let inner = points.iter().copied().filter(|&x| x > xl && x < xr);
    let xs: Vec<f64> = std::iter::once(xl)
        .chain(inner)
        .chain(std::iter::once(xr))
        .collect();
    xs.windows(2).map(|w| (w[0], w[1])).collect()
}

/// Slice sides: every cut, and between cuts slices of about the width (b − a)/n; at least one
/// slice between two cuts, so there may be more than n.
fn allocate(cuts: &[f64], n: usize) -> Vec<f64> {
    let span = cuts[cuts.len() - 1] - cuts[0];
    let width = span / n as f64;
    let lengths: Vec<f64> = cuts.windows(2).map(|w| w[1] - w[0]).collect();
    let mut counts: Vec<usize> = lengths
        .iter()
        .map(|&l| ((l / width).floor() as usize).max(1))
        .collect();
    let mut total: usize = counts.iter().sum();
    // Hand out what is left to the pieces whose slices are widest.
    while total < n {
        let widest = (0..counts.len()).max_by(|&i, &j| {
            (lengths[i] / counts[i] as f64).total_cmp(&(lengths[j] / counts[j] as f64))
        });
        let Some(i) = widest else { break };
        counts[i] += 1;
        total += 1;
    }
    let mut sides = Vec::with_capacity(total + 1);
    for (w, &count) in cuts.windows(2).zip(&counts) {
        for k in 0..count {
            sides.push(w[0] + (w[1] - w[0]) * k as f64 / count as f64);
        }
    }
    sides.push(cuts[cuts.len() - 1]);
    sides
}

/// The slice between x_l and x_r with its base from (x_l, b_l) to (x_r, b_r).
fn slice(
    section: &Section,
    (xl, xr): (f64, f64),
    (bl, br): (f64, f64),
    points: &[f64],
    tolerance: f64,
) -> BaseSlice {
    let ground = &section.ground;
    let width = xr - xl;
    let xm = 0.5 * (xl + xr);
    let bm = 0.5 * (bl + br);
    let layers = &section.layers;
    let chord = |x: f64| bl + (br - bl) * (x - xl) / width;
    // Thickness of each layer at x over the base b, and ∫y over it, by the soil rule: layer k
    // holds the points at or below its top and above every later layer's top.
    let column = |x: f64| column(section, x, chord(x));
    let (mut weight, mut moment) = (0.0, 0.0);
    // Between the top points every line is straight: Simpson's rule is exact for the linear
    // thickness and the quadratic ∫y of each piece.
    let first = points.partition_point(|&p| p <= xl);
    let last = points.partition_point(|&p| p < xr);
    let inner = points[first..last.max(first)].iter().copied();
    let mut a = xl;
    let mut ca = column(a);
    for b in inner.chain(std::iter::once(xr)) {
        let (cm, cb) = (column(0.5 * (a + b)), column(b));
        weight += (b - a) / 6.0 * (ca.0 + 4.0 * cm.0 + cb.0);
        moment += (b - a) / 6.0 * (ca.1 + 4.0 * cm.1 + cb.1);
        (a, ca) = (b, cb);
    }
    let probe = bm + tolerance;
    let g_m = ground.y_at(xm);
    let layer = soil_at(section, xm, probe);
    let soil = &layers[layer].soil;
    let pore_pressure = match (layers[layer].pore_pressure_ratio, &section.piezometric_line) {
        (Some(ratio), _) => {
            // σ_v: the weight of the column above the base middle.
            ratio * column(xm).0
        }
        (None, Some(line)) => section.water_unit_weight * (line.y_at(xm) - bm).max(0.0),
        (None, None) => 0.0,
    };
    BaseSlice {
        x_left: xl,
        x_right: xr,
        base_left_y: bl,
        base_right_y: br,
        top_right_y: ground.y_at(xr),
        base_inclination_rad: (br - bl).atan2(width),
        base_length: width.hypot(br - bl),
        base_middle: (xm, bm),
        height_middle: g_m - bm,
        weight,
        centroid_y: if weight > 0.0 { moment / weight } else { bm },
        cohesion: soil.cohesion,
        tan_phi: soil.friction_angle_rad.tan(),
        pore_pressure,
        layer,
        side_water: side_water(section, xr, br),
    }
}

/// The weight of the column over y at x and its first moment ∫γ·y dy, by the soil rule: layer k
/// holds the points at or below its top and above every later layer's top.
fn column(section: &Section, x: f64, y: f64) -> (f64, f64) {
    let g = section.ground.y_at(x);
    let mut below = y;
    let (mut w, mut m) = (0.0, 0.0);
    for layer in section.layers.iter().rev() {
        let top = layer.top.as_ref().map_or(g, |t| t.y_at(x));
        let upper = g.min(top);
        if upper > below {
            let gamma = layer.soil.unit_weight;
            w += gamma * (upper - below);
            m += gamma * 0.5 * (upper * upper - below * below);
        }
        below = below.max(top);
    }
    (w, m)
}

/// The layer whose soil is at (x, y): the last one whose top is at or above y (the first at
/// the ground).
fn soil_at(section: &Section, x: f64, y: f64) -> usize {
    let g = section.ground.y_at(x);
    let layers = &section.layers;
    (0..layers.len())
        .rev()
        .find(|&k| layers[k].top.as_ref().map_or(g, |t| t.y_at(x)) >= y)
        .unwrap_or(0)
}

/// The pore water's force on the vertical through x from the base at y = b up to the ground,
/// and its height: ∫u dy by Simpson's rule on 8 panels (exact under a water line; the r_u
/// pressures of layered soils are piecewise linear, to ~1e-4 there).
fn side_water(section: &Section, x: f64, b: f64) -> (f64, f64) {
    let g = section.ground.y_at(x);
    if g <= b {
        return (0.0, b);
    }
    let layers = &section.layers;
    if layers.iter().all(|l| l.pore_pressure_ratio.is_none()) {
        // Water line only (or none): u = γ_w·(y_p − y) below it, closed form.
        let Some(line) = &section.piezometric_line else {
            return (0.0, b);
        };
        let yp = line.y_at(x);
        let top = yp.min(g);
        if top <= b {
            return (0.0, b);
        }
        let gw = section.water_unit_weight;
        // ∫_b^top γ_w (y_p − y) dy and its moment ∫ γ_w (y_p − y)·y dy.
        let force = gw * ((yp - b).powi(2) - (yp - top).powi(2)) / 2.0;
        let moment = gw * (yp * (top * top - b * b) / 2.0 - (top.powi(3) - b.powi(3)) / 3.0);
        return if force > 0.0 {
            (force, moment / force)
        } else {
            (0.0, b)
        };
    }
    let u = |y: f64| -> f64 {
        match (
            layers[soil_at(section, x, y)].pore_pressure_ratio,
            &section.piezometric_line,
        ) {
            (Some(ratio), _) => ratio * column(section, x, y).0,
            (None, Some(line)) => section.water_unit_weight * (line.y_at(x) - y).max(0.0),
            (None, None) => 0.0,
        }
    };
    const PANELS: usize = 8;
    let h = (g - b) / PANELS as f64;
    let (mut force, mut moment) = (0.0, 0.0);
    for i in 0..=PANELS {
        let y = b + h * i as f64;
        let w = if i == 0 || i == PANELS {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        let p = u(y);
        force += w * p;
        moment += w * p * y;
    }
    force *= h / 3.0;
    moment *= h / 3.0;
    if force > 0.0 {
        (force, moment / force)
    } else {
        (0.0, b)
    }
}

/// The known forces on the slices: ponded water, surcharges, line loads and the water in the
/// crack, one load per slice that carries any (moments about the base middle).
fn loads(
    section: &Section,
    slices: &[BaseSlice],
    points: &[f64],
    crack: Option<(f64, f64, f64)>,
) -> Vec<ExternalLoad> {
    let ground = &section.ground;
    let mut totals = vec![(0.0, 0.0, 0.0); slices.len()];
    // A force (fx, fy) at (x, y) on slice i.
    let mut add = |i: usize, (x, y): (f64, f64), (fx, fy): (f64, f64), s: &BaseSlice| {
        let (xb, yb) = s.base_middle;
        let t: &mut (f64, f64, f64) = &mut totals[i];
        t.0 += fx;
        t.1 += fy;
        t.2 += (x - xb) * fy - (y - yb) * fx;
    };
    for (i, s) in slices.iter().enumerate() {
        let (xl, xr) = (s.x_left, s.x_right);
        if let Some(line) = &section.piezometric_line {
            // Ponded water: pressure γ_w·d normal to the ground, d linear on each piece.
            for (a, b) in pieces(points, xl, xr) {
                let (ga, gb) = (ground.y_at(a), ground.y_at(b));
                let (da, db) = ((line.y_at(a) - ga).max(0.0), (line.y_at(b) - gb).max(0.0));
                if da + db > 0.0 {
                    let p = section.water_unit_weight * (b - a) * 0.5 * (da + db);
                    let x = a + (b - a) * (da + 2.0 * db) / (3.0 * (da + db));
                    let slope = (gb - ga) / (b - a);
                    add(i, (x, ground.y_at(x)), (slope * p, -p), s);
                }
            }
        }
        for sc in &section.surcharges {
            let (a, b) = (xl.max(sc.x_start), xr.min(sc.x_end));
            if b <= a {
                continue;
            }
            let q = |x: f64| {
                sc.pressure
                    + (sc.pressure_end - sc.pressure) * (x - sc.x_start) / (sc.x_end - sc.x_start)
            };
            let (qa, qb) = (q(a), q(b));
            if qa + qb > 0.0 {
                let p = (b - a) * 0.5 * (qa + qb);
                let x = a + (b - a) * (qa + 2.0 * qb) / (3.0 * (qa + qb));
                add(i, (x, ground.y_at(x)), (0.0, -p), s);
            }
        }
        let is_last = i + 1 == slices.len();
        for l in &section.line_loads {
            if l.x >= xl && (l.x < xr || (is_last && l.x <= xr)) {
                add(i, (l.x, ground.y_at(l.x)), (l.fx, l.fy), s);
            }
        }
        if let (true, Some(c), Some((_, bottom, _))) = (is_last, section.tension_crack, crack) {
            // ½·γ_w·z_w² towards the toe, z_w/3 above the crack bottom.
            let p = 0.5 * section.water_unit_weight * c.water_depth * c.water_depth;
            if p > 0.0 {
                add(i, (xr, bottom + c.water_depth / 3.0), (-p, 0.0), s);
            }
        }
    }
    totals
        .into_iter()
        .enumerate()
        .filter(|(_, t)| *t != (0.0, 0.0, 0.0))
        .map(|(slice, (fx, fy, moment))| ExternalLoad {
            slice,
            fx,
            fy,
            moment,
        })
        .collect()
}
