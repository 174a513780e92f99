//! The sliding mass of a section cut into vertical slices, in the solver's frame (crest towards
//! +x). Slice sides fall where the base changes: the surface's vertices and its crossings with
//! layer tops, the water line and bedrock, and the bedrock's kinks where the base follows it;
//! between those the slices are of equal width. Above the base, the weights and loads are
//! integrated exactly, piece by piece between the kinks and crossings of the ground, the layer
//! tops, the water line and the surcharge edges, so a section cut like the simple embankment
//! (one soil, no water) gets the simple embankment's slices.

use std::num::NonZeroUsize;

use smallvec::SmallVec;

use super::model::Section;
use super::polyline::Polyline;
use super::shape::SlipShape;
use super::slicing::{slice_all, still_water_level, Slicing};
use crate::slope::error::{SlopeError, SlopeParameter};
use crate::slope::slices::{BaseSlice, SliceModel};
use crate::slope::spare;
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
    /// Each support of the section against this surface (solver frame).
    pub supports: Vec<super::supports::SupportForce>,
    /// With a rapid drawdown: what its stages gave (the model has the last stage's strengths).
    pub drawdown: Option<super::drawdown::DrawdownStages>,
}

impl Cut {
    /// Whether the mass enters and leaves the ground within the section's x-range, to rounding
    /// (`section` and `mirror`, the section seen from behind: the frames a cut may be in).
    pub fn within_ground(&self, section: &Section, mirror: &Section) -> bool {
        let frame = if self.mirrored { mirror } else { section };
        let (first, last) = frame.ground.x_range();
        let rounding = 1e-9 * (last - first).abs().max(1.0);
        self.ends.0 .0 >= first - rounding && self.ends.1 .0 <= last + rounding
    }
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
    let mut xs = Vec::new();
    add_shape_crossings(shape, line, (a, b), &mut xs);
    xs
}

/// [`shape_crossings`] added to `xs`.
fn add_shape_crossings(
    shape: &SlipShape,
    line: &Polyline,
    (a, b): (f64, f64),
    xs: &mut impl Extend<f64>,
) {
    match shape {
        SlipShape::Circle { centre, radius } => xs.extend(
            line.circle_crossings(*centre, *radius, a, b)
                .into_iter()
                .filter(|c| c.1)
                .map(|c| c.0),
        ),
        SlipShape::Polyline(surface) => xs.extend(surface.crossings(line, a, b)),
    }
}

impl Cut {
    /// The cut of `shape` between `entry` and `exit`; with a rapid drawdown, its stages run on
    /// it (the same surface cut before the drawdown gives the consolidation stresses).
    pub fn new(
        section: &Section,
        shape: &SlipShape,
        ends: (f64, f64),
        slices: NonZeroUsize,
        seismic: Seismic,
        moment_centre: Option<(f64, f64)>,
        mirrored: bool,
    ) -> Result<Self, SlopeError> {
        // The surface cut in a state of the section (a drawdown's stage before, or now).
        let cut_in = |state: &Section| {
            Self::one_state(state, shape, ends, slices, seismic, moment_centre, mirrored)
        };
        let mut cut = cut_in(section)?;
        if let Some(d) = &section.drawdown {
            let before = cut_in(&d.before)?;
            cut.drawdown = Some(super::drawdown::stages(d, &before.model, &mut cut.model)?);
        }
        Ok(cut)
    }

    /// The cut of `shape` on `section` as it stands (one water state).
    fn one_state(
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
        let crack = match section.tension_crack {
            Some(c) => Some(crack_at(section, shape, c.depth, (xa, xb), &base, scale)?),
            None => None,
        };
        if let Some(c) = crack {
            xb = c.0;
        }
        let cuts = base_cuts(section, shape, xa, xb, tolerance);
        let points = top_points(section, xa, xb, tolerance);
        let boundaries = allocate(&cuts, slices.get());
        let base_at = side_base(&base, crack, boundaries.len() - 1);
        let Slicing {
            slices,
            mut surface,
            ponded,
        } = slice_all(
            section,
            &boundaries,
            base_at,
            &points,
            tolerance,
            still_water_level(section, xa, xb),
        );
        spare::keep(&SPARE_SIDES, boundaries);
        let (loads, supports) = forces_on(section, &slices, ponded, crack, &mut surface);
        let (reference, moment_centre, circular) =
            reference(shape, ground, (xa, xb), moment_centre);
        let length_scale = farthest(&surface, reference);
        let model = SliceModel {
            slices,
            seismic,
            loads,
            reference,
            moment_centre,
            circular,
            length_scale,
            envelopes: section.envelopes.clone(),
            fixed: Vec::new(),
        };
        Ok(Self {
            model,
            ends: (
                (xa, ground.y_at(xa)),
                (xb, crack.map_or(ground.y_at(xb), |c| c.2)),
            ),
            surface,
            crack,
            mirrored,
            supports,
            drawdown: None,
        })
    }
}

/// The base's height at side `i` of the sides 0..=`last` (at x, under the ground at `ground_y`):
/// the ground at the first, the crack's bottom (or the ground) at the last, between them the
/// base (`base`, the slip surface on bedrock) but never above the ground.
fn side_base<'a>(
    base: &'a impl Fn(f64) -> f64,
    crack: Option<(f64, f64, f64)>,
    last: usize,
) -> impl Fn(usize, f64, f64) -> f64 + 'a {
    move |i: usize, x: f64, ground_y: f64| {
        if i == 0 {
            ground_y
        } else if i == last {
            crack.map_or(ground_y, |c| c.1)
        } else {
            base(x).min(ground_y)
        }
    }
}

/// The known forces on the slices ([`loads`]) with the supports' crossing the bases, and the
/// supports' forces; the crack's top is then added to `surface` (the base's end points).
fn forces_on(
    section: &Section,
    slices: &[BaseSlice],
    ponded: Vec<(f64, f64, f64)>,
    crack: Option<(f64, f64, f64)>,
    surface: &mut Vec<(f64, f64)>,
) -> (Vec<ExternalLoad>, Vec<super::supports::SupportForce>) {
    let mut loads = loads(section, slices, ponded, crack);
    // Supports cross the bases only: the crack carries no force but its water.
    let face = crack.map(|c| [(c.0, c.1), (c.0, c.2)]);
    let (supports, support_loads) =
        super::supports::forces(&section.supports, surface, face, slices);
    surface.extend(crack.map(|c| (c.0, c.2)));
    loads.extend(support_loads);
    (loads, supports)
}

/// The point the moment equation is written about, the moment centre reported and whether
/// the surface is a circle: a circle's centre; for a polyline between xa and xb, a point half
/// its width above the higher end (and the moment centre given, if any).
fn reference(
    shape: &SlipShape,
    ground: &Polyline,
    (xa, xb): (f64, f64),
    moment_centre: Option<(f64, f64)>,
) -> ((f64, f64), Option<(f64, f64)>, bool) {
    match shape {
        SlipShape::Circle { centre, .. } => (*centre, Some(*centre), true),
        SlipShape::Polyline(_) => {
            let top = ground.y_at(xa).max(ground.y_at(xb));
            (
                (0.5 * (xa + xb), top + 0.5 * (xb - xa)),
                moment_centre,
                false,
            )
        }
    }
}

/// The largest distance from `reference` to a point of `surface` (at least the least positive
/// number): the moment equation's length scale.
fn farthest(surface: &[(f64, f64)], reference: (f64, f64)) -> f64 {
    surface
        .iter()
        .map(|p| {
            let (dx, dy) = (p.0 - reference.0, p.1 - reference.1);
            (dx * dx + dy * dy).sqrt()
        })
        .fold(0.0f64, f64::max)
        .max(f64::MIN_POSITIVE)
}

/// Where the slip surface rises through the tension crack's line (the ground `depth` lower) at
/// its upper end: (x, y of the crack bottom, y of the ground).
fn crack_at(
    section: &Section,
    shape: &SlipShape,
    depth: f64,
    (xa, xb): (f64, f64),
    base: &dyn Fn(f64) -> f64,
    scale: f64,
) -> Result<(f64, f64, f64), SlopeError> {
    let ground = &section.ground;
    let tolerance = SAME_CUT * scale;
    let crack_line = Polyline::new(ground.points().iter().map(|p| (p.0, p.1 - depth)).collect())
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
                depth
            ),
        });
    };
    Ok((x, crack_line.y_at(x), ground.y_at(x)))
}

/// Sorted x in (a, b) closer than `tolerance` merged, with a and b at the ends. (Values equal
/// under `total_cmp` are the same bits: the order they come in does not matter.)
fn sorted_between(mut cuts: Sides, a: f64, b: f64, tolerance: f64) -> Sides {
    cuts.retain(|x| *x > a + tolerance && *x < b - tolerance);
    cuts.extend([a, b]);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|next, kept| *next - *kept <= tolerance);
    if let Some(end) = cuts.last_mut() {
        *end = b;
    }
    cuts
}

/// Places along a cut where slice sides must fall: a few for a circle through a simple
/// section, kept on the stack (a search cuts thousands of surfaces).
type Sides = SmallVec<[f64; 16]>;

/// Where a slice side must fall, so that each base is straight, in one soil and on one side of
/// each water line: the surface's vertices, its crossings with layer tops, bedrock and the
/// piezometric lines (the section's and the layers' own), and the bedrock's kinks and crossings
/// where the base follows it.
fn base_cuts(section: &Section, shape: &SlipShape, a: f64, b: f64, tolerance: f64) -> Sides {
    let tops = section.layers.iter().filter_map(|l| l.top.as_ref());
    let own = section
        .layers
        .iter()
        .filter_map(|l| l.piezometric_line.as_ref().map(|w| &w.line));
    let lines = || {
        tops.clone()
            .chain(section.bedrock.as_ref())
            .chain(section.piezometric_line.as_ref())
            .chain(section.other_water_line.as_ref())
            .chain(own.clone())
    };
    let mut xs = Sides::new();
    if let SlipShape::Polyline(line) = shape {
        xs.extend(line.xs());
    }
    for line in lines() {
        add_shape_crossings(shape, line, (a, b), &mut xs);
    }
    if let Some(bedrock) = &section.bedrock {
        let on_bedrock = |x: f64| bedrock.y_at(x) >= shape_y(shape, x) - tolerance;
        xs.extend(bedrock.xs().filter(|&x| on_bedrock(x)));
        for line in lines() {
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

/// The bends of the section within (a, b), with a and b at the ends.
fn top_points(section: &Section, a: f64, b: f64, tolerance: f64) -> Sides {
    let first = section.bends.partition_point(|&x| x <= a + tolerance);
    let last = section.bends.partition_point(|&x| x < b - tolerance);
    let inner = &section.bends[first..last.max(first)];
    sorted_between(Sides::from_slice(inner), a, b, tolerance)
}

thread_local! {
    /// The last cut's slice sides ([`spare`]).
    static SPARE_SIDES: std::cell::Cell<Vec<f64>> = const { std::cell::Cell::new(Vec::new()) };
}

/// Slice sides: every cut, and between cuts slices of about the width (b − a)/n; at least one
/// slice between two cuts, so there may be more than n.
fn allocate(cuts: &[f64], n: usize) -> Vec<f64> {
    let span = cuts[cuts.len() - 1] - cuts[0];
    let width = span / n as f64;
    let length = |i: usize| cuts[i + 1] - cuts[i];
    let mut counts: SmallVec<[usize; 16]> = (0..cuts.len() - 1)
        .map(|i| ((length(i) / width).floor() as usize).max(1))
        .collect();
    let mut total: usize = counts.iter().sum();
    // Hand out what is left to the pieces whose slices are widest.
    while total < n {
        let widest = (0..counts.len()).max_by(|&i, &j| {
            (length(i) / counts[i] as f64).total_cmp(&(length(j) / counts[j] as f64))
        });
        let Some(i) = widest else { break };
        counts[i] += 1;
        total += 1;
    }
    let mut sides = spare::take(&SPARE_SIDES);
    sides.reserve(total + 1);
    for (w, &count) in cuts.windows(2).zip(&counts) {
        sides.extend((0..count).map(|k| w[0] + (w[1] - w[0]) * k as f64 / count as f64));
    }
    sides.push(cuts[cuts.len() - 1]);
    sides
}

/// The known forces on the slices: ponded water (as sliced; none when `ponded` is empty),
/// surcharges, line loads and the water in the crack, one load per slice that carries any
/// (moments about the base middle).
fn loads(
    section: &Section,
    slices: &[BaseSlice],
    ponded: Vec<(f64, f64, f64)>,
    crack: Option<(f64, f64, f64)>,
) -> Vec<ExternalLoad> {
    let ground = &section.ground;
    let unloaded = section.surcharges.is_empty()
        && section.line_loads.is_empty()
        && section.tension_crack.is_none();
    if unloaded && ponded.is_empty() {
        return Vec::new();
    }
    let mut totals = if ponded.is_empty() {
        vec![(0.0, 0.0, 0.0); slices.len()]
    } else {
        ponded
    };
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
            passive: false,
        })
        .collect()
}
