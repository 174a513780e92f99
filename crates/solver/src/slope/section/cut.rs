//! The sliding mass of a section cut into vertical slices, in the solver's frame (crest towards
//! +x). Slice sides fall where the base changes: the surface's vertices and its crossings with
//! layer tops, the water line and bedrock, and the bedrock's kinks where the base follows it;
//! between those the slices are of equal width. Above the base, the weights and loads are
//! integrated exactly, piece by piece between the kinks and crossings of the ground, the layer
//! tops, the water line and the surcharge edges, so a section cut like the simple embankment
//! (one soil, no water) gets the simple embankment's slices.

use std::num::NonZeroUsize;

use super::column::{column, ground, pore_pressure, side_water, soil_at, Levels};
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

/// Places `shape` on `section` and cuts it, in the solver's frame: mirrored (with `mirror`, the
/// section seen from behind, when the caller has it) when the crest lies to the left.
pub(super) fn place(
    section: &Section,
    mirror: Option<&Section>,
    shape: &SlipShape,
    slices: NonZeroUsize,
    seismic: Seismic,
    moment_centre: Option<(f64, f64)>,
) -> Result<Cut, SlopeError> {
    let (entry, exit) = super::ends::ends(&section.ground, shape)?;
    let ground = &section.ground;
    let rises_left = ground.y_at(entry) > ground.y_at(exit)
        || (ground.y_at(entry) == ground.y_at(exit) && {
            let p = ground.points();
            p[0].1 > p[p.len() - 1].1
        });
    if rises_left {
        let owned;
        let mirrored = match mirror {
            Some(m) => m,
            None => {
                owned = section.mirrored();
                &owned
            }
        };
        let centre = moment_centre.map(|c| (-c.0, c.1));
        Cut::new(
            mirrored,
            &shape.mirrored(),
            (-exit, -entry),
            slices,
            seismic,
            centre,
            true,
        )
    } else {
        Cut::new(
            section,
            shape,
            (entry, exit),
            slices,
            seismic,
            moment_centre,
            false,
        )
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
        let slices = slice_all(section, &boundaries, &base_ys, &points, tolerance);
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
            .map(|p| {
                let (dx, dy) = (p.0 - reference.0, p.1 - reference.1);
                (dx * dx + dy * dy).sqrt()
            })
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

/// Where the lines above the bases bend or cross (ground, layer tops, the water line, surcharge
/// edges), over the whole section, sorted: the slice weights and loads are integrated piecewise
/// between these, exactly. Computed once per section.
pub(super) fn bends(section: &Section) -> Vec<f64> {
    let lines: Vec<&Polyline> = std::iter::once(&section.ground)
        .chain(section.layers.iter().filter_map(|l| l.top.as_ref()))
        .chain(section.piezometric_line.as_ref())
        .collect();
    let mut xs: Vec<f64> = lines.iter().flat_map(|l| l.xs()).collect();
    xs.extend(section.surcharges.iter().flat_map(|s| [s.x_start, s.x_end]));
    // Beyond every vertex the lines run level: no crossing lies outside their range.
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let (lo, hi) = (lo - 1.0, hi + 1.0);
    for (i, line) in lines.iter().enumerate() {
        for other in &lines[i + 1..] {
            xs.extend(line.crossings(other, lo, hi));
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    xs
}

/// The stretches of x where the piezometric line lies above the ground somewhere (ponded
/// water), merged. Between the bends both lines are straight, beyond them level: the water
/// stands above the ground on a stretch only if it does at one of its ends.
pub(super) fn ponded(section: &Section) -> Vec<(f64, f64)> {
    let mut ponded: Vec<(f64, f64)> = Vec::new();
    let Some(line) = &section.piezometric_line else {
        return ponded;
    };
    let above = |x: f64| line.y_at(x) > section.ground.y_at(x);
    let ends = std::iter::once(f64::NEG_INFINITY)
        .chain(section.bends.iter().copied())
        .chain(std::iter::once(f64::INFINITY));
    for (a, b) in ends.clone().zip(ends.skip(1)) {
        if !((a.is_finite() && above(a)) || (b.is_finite() && above(b))) {
            continue;
        }
        match ponded.last_mut() {
            Some(last) if last.1 == a => last.1 = b,
            _ => ponded.push((a, b)),
        }
    }
    ponded
}

/// The bends of the section within (a, b), with a and b at the ends.
fn top_points(section: &Section, a: f64, b: f64, tolerance: f64) -> Vec<f64> {
    let first = section.bends.partition_point(|&x| x <= a + tolerance);
    let last = section.bends.partition_point(|&x| x < b - tolerance);
    sorted_between(
        section.bends[first..last.max(first)].to_vec(),
        a,
        b,
        tolerance,
    )
}

/// The pieces of [xl, xr] between the top points.
fn pieces(points: &[f64], xl: f64, xr: f64) -> impl Iterator<Item = (f64, f64)> + '_ {
    // The points are sorted: those strictly inside are one run.
    let first = points.partition_point(|&x| x <= xl);
    let last = points.partition_point(|&x| x < xr).max(first);
    let xs = std::iter::once(xl)
        .chain(points[first..last].iter().copied())
        .chain(std::iter::once(xr));
    xs.clone().zip(xs.skip(1))
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

/// The slices between the sides `xs` over the bases through `bs`: the lines are read once at
/// each side (and at the top points inside a slice, where one bends).
fn slice_all(
    section: &Section,
    xs: &[f64],
    bs: &[f64],
    points: &[f64],
    tolerance: f64,
) -> Vec<BaseSlice> {
    let tan_phi: Vec<f64> = section
        .layers
        .iter()
        .map(|l| l.soil.friction_angle_rad.tan())
        .collect();
    let mut scratch = Scratch::default();
    let (mut left, mut right) = (Levels::default(), Levels::default());
    left.read(section, xs[0]);
    let mut slices = Vec::with_capacity(xs.len().saturating_sub(1));
    for i in 0..xs.len().saturating_sub(1) {
        right.read(section, xs[i + 1]);
        slices.push(slice(
            section,
            (xs[i], xs[i + 1]),
            (bs[i], bs[i + 1]),
            (&left, &right),
            points,
            (tolerance, &tan_phi),
            &mut scratch,
        ));
        std::mem::swap(&mut left, &mut right);
    }
    slices
}

/// Buffers reused from slice to slice.
#[derive(Default)]
struct Scratch {
    /// Levels at the ends of the current piece and half-way.
    a: Levels,
    b: Levels,
    middle: Levels,
}

/// The slice between x_l and x_r with its base from (x_l, b_l) to (x_r, b_r), the levels at
/// its sides read.
fn slice(
    section: &Section,
    (xl, xr): (f64, f64),
    (bl, br): (f64, f64),
    (left, right): (&Levels, &Levels),
    points: &[f64],
    (tolerance, tan_phi): (f64, &[f64]),
    scratch: &mut Scratch,
) -> BaseSlice {
    let width = xr - xl;
    let xm = 0.5 * (xl + xr);
    let bm = 0.5 * (bl + br);
    let chord = |x: f64| bl + (br - bl) * (x - xl) / width;
    // Between the top points every line is straight: Simpson's rule is exact for the linear
    // thickness and the quadratic ∫y of each piece.
    let first = points.partition_point(|&p| p <= xl);
    let last = points.partition_point(|&p| p < xr);
    let inner = &points[first..last.max(first)];
    let (mut weight, mut moment) = (0.0, 0.0);
    let Scratch { a, b, middle } = scratch;
    let mut xa = xl;
    a.clone_from(left);
    for (k, &xb) in inner.iter().chain(std::iter::once(&xr)).enumerate() {
        if k == inner.len() {
            b.clone_from(right);
        } else {
            b.read(section, xb);
        }
        middle.midway(a.values(), b.values());
        let ca = column(section, a.values(), chord(xa));
        let cm = column(section, middle.values(), chord(0.5 * (xa + xb)));
        let cb = column(section, b.values(), chord(xb));
        weight += (xb - xa) / 6.0 * (ca.0 + 4.0 * cm.0 + cb.0);
        moment += (xb - xa) / 6.0 * (ca.1 + 4.0 * cm.1 + cb.1);
        xa = xb;
        std::mem::swap(a, b);
    }
    // The levels over the base middle: with no bend inside, the single piece's half-way levels
    // the loop left in `middle`; else read there.
    if !inner.is_empty() {
        middle.read(section, xm);
    }
    let levels = middle.values();
    let layer = soil_at(section, levels, bm + tolerance);
    let rise = br - bl;
    let base_length = (width * width + rise * rise).sqrt();
    let soil = &section.layers[layer].soil;
    BaseSlice {
        x_left: xl,
        x_right: xr,
        base_left_y: bl,
        base_right_y: br,
        top_right_y: ground(right.values()),
        base_sin_cos: (rise / base_length, width / base_length),
        base_length,
        base_middle: (xm, bm),
        height_middle: ground(levels) - bm,
        weight,
        centroid_y: if weight > 0.0 { moment / weight } else { bm },
        cohesion: soil.cohesion,
        tan_phi: tan_phi[layer],
        pore_pressure: pore_pressure(section, levels, layer, bm),
        layer,
        side_water: side_water(section, right.values(), br),
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
        let wet = section.piezometric_line.as_ref();
        if let Some(line) = wet.filter(|_| section.is_ponded_over(xl, xr)) {
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
