//! The slices between given sides: each one's weight and its centroid's height integrated
//! exactly, piece by piece between the points where a line above the base bends (Simpson's
//! rule is exact for the linear thickness and the quadratic ∫y of a straight piece), its soil,
//! pore pressure and side water, and the ponded water pressing on its top.
//!
//! The lines are read once per side: the column over a side serves the slices on both of it.

use super::buffers::vectors;
use super::column::{
    column, ground, pore_pressure, side_water, soil_at, water, water_from_line_alone, InnerPoints,
    Levels,
};
use super::model::Section;
use super::plain::PlainSoil;
use crate::slope::slices::BaseSlice;
use crate::slope::strength::Strength;

/// The slices of one cut.
pub(super) struct Slicing {
    pub slices: Vec<BaseSlice>,
    /// The base's end points (x, y) at each side, with room for one more (a crack's top).
    pub surface: Vec<(f64, f64)>,
    /// Per slice, the ponded water's force on its top: (f_x, f_y, moment about the base
    /// middle); empty when no water can stand on any (a plain section).
    pub ponded: Vec<(f64, f64, f64)>,
}

/// Buffers reused from slice to slice.
#[derive(Default)]
struct Scratch {
    left: Levels,
    right: Levels,
    /// Levels at the ends of a piece inside a slice, and half-way along a piece.
    a: Levels,
    b: Levels,
    middle: Levels,
    /// The level table's stretch of the last read (the reads move along x).
    cursor: usize,
    /// tan φ′ per layer.
    tan_phi: Vec<f64>,
    /// [`water_from_line_alone`] of the section being cut.
    line_water: bool,
    /// The cut's bends inside the slice at hand.
    inner: InnerPoints,
}

/// The level of still water standing over the whole top of the mass between a and b, when it
/// does: a piezometric line at or above the ground all along, pore pressures from it alone (no
/// r_u) and no tension crack. The slices are then written relative to the hydrostatic field
/// of that level (its lowest over the mass): the field's pressures on a slice's top, base and
/// sides add up to the buoyancy γ_w·A through the centroid (Archimedes), so each slice carries
/// its buoyancy and only the pressures in excess of the field — heads relative to the water
/// surface, γ_w·(y_p − y_w) on its top and base — and the inter-slice forces are those beyond
/// the field's. A submerged slope is then its buoyant twin at any head, with no large
/// pressures cancelling (a head of 1e8 lost F before).
pub(super) fn still_water_level(section: &Section, a: f64, b: f64) -> Option<f64> {
    let line = section.piezometric_line.as_ref()?;
    if section.tension_crack.is_some()
        || section.has_water_models()
        || section
            .layers
            .iter()
            .any(|l| l.pore_pressure_ratio.is_some())
    {
        return None;
    }
    let inside = |x: f64| x > a && x < b;
    let xs = || {
        [a, b]
            .into_iter()
            .chain(line.xs().filter(move |&x| inside(x)))
            .chain(section.ground.xs().filter(move |&x| inside(x)))
    };
    // Both lines are straight between these x: the water is above the ground all along if it
    // is at each of them.
    let standing = xs().all(|x| line.y_at(x) >= section.ground.y_at(x));
    standing.then(|| xs().map(|x| line.y_at(x)).fold(f64::INFINITY, f64::min))
}

/// The pore pressure at the base middle (levels, layer, height) and the pore water's force on
/// the right side (at `xr`, its base at `br`) and its height; relative to still water at its level, the
/// pressures in excess of the still water's: γ_w times the head above that level.
fn base_water(
    section: &Section,
    still: Option<f64>,
    levels: &[f64],
    layer: usize,
    (xm, bm): (f64, f64),
    s: &Scratch,
    (xr, br): (f64, f64),
) -> (f64, (f64, f64)) {
    let right = s.right.values();
    match still {
        Some(level) => {
            let excess =
                |levels: &[f64]| section.water_unit_weight * (water(levels) - level).max(0.0);
            let g = ground(right);
            (
                excess(levels),
                ((g - br).max(0.0) * excess(right), 0.5 * (g + br)),
            )
        }
        None => (
            pore_pressure(section, levels, layer, (xm, bm)),
            side_water(section, right, (xr, br), s.line_water),
        ),
    }
}

/// The slices between the sides `xs`; `base_at(i, x, g)` is the base's height at side i (at x,
/// where the ground is at g). `points`: the section's bends within the cut, sorted. With
/// `still`, the level of [`still_water_level`], the slices are written relative to its
/// hydrostatic field. A plain section ([`PlainSoil`]) is sliced by [`super::plain::slices`],
/// the same arithmetic without the reads of every line.
pub(super) fn slice_all(
    section: &Section,
    xs: &[f64],
    base_at: impl Fn(usize, f64, f64) -> f64,
    points: &[f64],
    tolerance: f64,
    still: Option<f64>,
) -> Slicing {
    if let (Some(soil), None) = (PlainSoil::of(section), still) {
        let (slices, surface) = super::plain::slices(section, soil, xs, base_at, points);
        return Slicing {
            slices,
            surface,
            ponded: Vec::new(),
        };
    }
    // The buffers live with the thread: a search cuts thousands of surfaces on each.
    SCRATCH.with(|cell| match cell.try_borrow_mut() {
        Ok(mut s) => slice_with(section, xs, base_at, points, tolerance, still, &mut s),
        Err(_) => slice_with(
            section,
            xs,
            base_at,
            points,
            tolerance,
            still,
            &mut Scratch::default(),
        ),
    })
}

thread_local! {
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::new(Scratch::default());
}

/// [`slice_all`] with its buffers given.
fn slice_with(
    section: &Section,
    xs: &[f64],
    base_at: impl Fn(usize, f64, f64) -> f64,
    points: &[f64],
    tolerance: f64,
    still: Option<f64>,
    s: &mut Scratch,
) -> Slicing {
    s.line_water = water_from_line_alone(section);
    s.tan_phi.clear();
    s.tan_phi.extend(
        section
            .layers
            .iter()
            .map(|l| l.soil.friction_angle_rad.tan()),
    );
    let count = xs.len().saturating_sub(1);
    let (slices, surface) = vectors(xs.len());
    let mut out = Slicing {
        slices,
        surface,
        ponded: Vec::with_capacity(count),
    };
    s.cursor = 0;
    s.inner = InnerPoints::default();
    s.left.read_from(section, xs[0], &mut s.cursor);
    let mut bl = base_at(0, xs[0], ground(s.left.values()));
    out.surface.push((xs[0], bl));
    let mut column_left = column(section, s.left.values(), bl);
    for i in 0..count {
        let (xl, xr) = (xs[i], xs[i + 1]);
        s.right.read_from(section, xr, &mut s.cursor);
        let br = base_at(i + 1, xr, ground(s.right.values()));
        let (slice, column_right, ponded) = slice(
            section,
            ((xl, bl), (xr, br)),
            column_left,
            points,
            tolerance,
            still,
            s,
        );
        out.slices.push(slice);
        out.surface.push((xr, br));
        out.ponded.push(ponded);
        std::mem::swap(&mut s.left, &mut s.right);
        (bl, column_left) = (br, column_right);
    }
    out
}

/// What one straight piece of a slice gives.
struct Piece {
    /// The column (weight, first moment) at its right end.
    column_b: (f64, f64),
    /// Its weight and first moment ∫γ·y.
    integral: (f64, f64),
    /// The ponded water on its top: (f_x, f_y, x, y).
    wet: Option<(f64, f64, f64, f64)>,
    /// Relative to still water: the buoyancy of the piece and the x of its centroid.
    buoyancy: Option<(f64, f64)>,
}

/// One straight piece [x_a, x_b] of a slice, the levels at its ends given and the base chord
/// from y_a to y_b under it. Leaves the levels half-way in `middle`.
fn piece(
    section: &Section,
    ((xa, ya), (xb, yb)): ((f64, f64), (f64, f64)),
    (a, b): (&[f64], &[f64]),
    column_a: (f64, f64),
    ponded: bool,
    still: Option<f64>,
    middle: &mut Levels,
) -> Piece {
    middle.midway(a, b);
    let column_m = column(section, middle.values(), 0.5 * (ya + yb));
    let column_b = column(section, b, yb);
    let sixth = (xb - xa) / 6.0;
    let integral = (
        sixth * (column_a.0 + 4.0 * column_m.0 + column_b.0),
        sixth * (column_a.1 + 4.0 * column_m.1 + column_b.1),
    );
    let (ga, gb) = (ground(a), ground(b));
    // Ponded water: pressure γ_w·d normal to the ground, d linear along the piece; relative to
    // still water at y_w, d = y_p − y_w, and the piece is buoyed up by γ_w times its area.
    let buoyancy = still.map(|_| {
        let (ha, hb) = (ga - ya, gb - yb);
        let area = 0.5 * (xb - xa) * (ha + hb);
        let x = match ha + hb > 0.0 {
            true => xa + (xb - xa) * (ha + 2.0 * hb) / (3.0 * (ha + hb)),
            false => 0.5 * (xa + xb),
        };
        (section.water_unit_weight * area, x)
    });
    let wet = (ponded || still.is_some()).then(|| {
        let depth = |levels: &[f64], g: f64| match still {
            Some(level) => (water(levels) - level).max(0.0),
            None => (water(levels) - g).max(0.0),
        };
        let (da, db) = (depth(a, ga), depth(b, gb));
        (da + db > 0.0).then(|| {
            let p = section.water_unit_weight * (xb - xa) * 0.5 * (da + db);
            let t = (da + 2.0 * db) / (3.0 * (da + db));
            let slope = (gb - ga) / (xb - xa);
            (slope * p, -p, xa + (xb - xa) * t, ga + (gb - ga) * t)
        })
    });
    Piece {
        column_b,
        integral,
        wet: wet.flatten(),
        buoyancy,
    }
}

/// What the pieces of a slice add up to.
struct Totals {
    /// The base middle, about which the water's moment is taken.
    middle: (f64, f64),
    /// The weight.
    weight: f64,
    /// The weight's first moment ∫γ·y.
    moment: f64,
    /// The ponded water on the top (with the buoyancy relative to still water): (f_x, f_y,
    /// moment about the base middle).
    water_force: (f64, f64, f64),
}

impl Totals {
    /// Nothing yet, moments about `middle`.
    #[inline]
    fn about(middle: (f64, f64)) -> Self {
        Self {
            middle,
            weight: 0.0,
            moment: 0.0,
            water_force: (0.0, 0.0, 0.0),
        }
    }

    /// Adds `piece`; returns the column at its right end.
    #[inline]
    fn add(&mut self, piece: Piece) -> (f64, f64) {
        let (xm, bm) = self.middle;
        self.weight += piece.integral.0;
        self.moment += piece.integral.1;
        let water_force = &mut self.water_force;
        if let Some((fx, fy, x, y)) = piece.wet {
            water_force.0 += fx;
            water_force.1 += fy;
            water_force.2 += (x - xm) * fy - (y - bm) * fx;
        }
        if let Some((up, x)) = piece.buoyancy {
            water_force.1 += up;
            water_force.2 += (x - xm) * up;
        }
        piece.column_b
    }
}

/// The slice from ((x_l, b_l), (x_r, b_r)) on its base, the levels at its sides read into
/// `s.left` and `s.right` (and tan φ′ per layer into `s.tan_phi`) and the column over its left
/// side given: the slice, the column over its right side, and the ponded water on it.
fn slice(
    section: &Section,
    ((xl, bl), (xr, br)): ((f64, f64), (f64, f64)),
    column_left: (f64, f64),
    points: &[f64],
    tolerance: f64,
    still: Option<f64>,
    s: &mut Scratch,
) -> (BaseSlice, (f64, f64), (f64, f64, f64)) {
    let width = xr - xl;
    let (xm, bm) = (0.5 * (xl + xr), 0.5 * (bl + br));
    let ponded = section.piezometric_line.is_some() && section.is_ponded_over(xl, xr);
    let inner = s.inner.within(points, (xl, xr));
    let mut totals = Totals::about((xm, bm));
    let column_right = if inner.is_empty() {
        // One piece; the levels half-way are those over the base middle.
        totals.add(piece(
            section,
            ((xl, bl), (xr, br)),
            (s.left.values(), s.right.values()),
            column_left,
            ponded,
            still,
            &mut s.middle,
        ))
    } else {
        let chord = |x: f64| bl + (br - bl) * (x - xl) / width;
        let (mut xa, mut ya, mut column_a) = (xl, bl, column_left);
        s.a.clone_from(&s.left);
        for (k, &xb) in inner.iter().chain(std::iter::once(&xr)).enumerate() {
            let yb = if k == inner.len() {
                s.b.clone_from(&s.right);
                br
            } else {
                s.b.read_from(section, xb, &mut s.cursor);
                chord(xb)
            };
            let column_b = totals.add(piece(
                section,
                ((xa, ya), (xb, yb)),
                (s.a.values(), s.b.values()),
                column_a,
                ponded,
                still,
                &mut s.middle,
            ));
            (xa, ya, column_a) = (xb, yb, column_b);
            std::mem::swap(&mut s.a, &mut s.b);
        }
        s.middle.read_from(section, xm, &mut s.cursor);
        column_a
    };
    let layer = soil_at(section, s.middle.values(), bm + tolerance);
    let slice = base_slice(
        section,
        s,
        ((xl, bl), (xr, br)),
        &totals,
        layer,
        s.tan_phi[layer],
        still,
    );
    (slice, column_right, totals.water_force)
}

/// The slice from ((x_l, b_l), (x_r, b_r)) on its base in `layer` (its soil's tan φ′ given),
/// its pieces' `totals` added up and the levels over its base middle and sides in `s`.
#[inline]
fn base_slice(
    section: &Section,
    s: &Scratch,
    ((xl, bl), (xr, br)): ((f64, f64), (f64, f64)),
    totals: &Totals,
    layer: usize,
    tan_phi: f64,
    still: Option<f64>,
) -> BaseSlice {
    let width = xr - xl;
    let (xm, bm) = totals.middle;
    let (weight, moment) = (totals.weight, totals.moment);
    let levels = s.middle.values();
    let rise = br - bl;
    let base_length = (width * width + rise * rise).sqrt();
    let (pore_pressure, side_water) =
        base_water(section, still, levels, layer, (xm, bm), s, (xr, br));
    let (cohesion, tan_phi) = strength(section, layer, tan_phi, (bm, ground(levels)), || {
        (weight / width * (width / base_length).powi(2) - pore_pressure).max(0.0)
    });
    BaseSlice {
        x_left: xl,
        x_right: xr,
        base_left_y: bl,
        base_right_y: br,
        top_right_y: ground(s.right.values()),
        base_sin_cos: (rise / base_length, width / base_length),
        base_length,
        base_middle: (xm, bm),
        height_middle: ground(levels) - bm,
        weight,
        centroid_y: if weight > 0.0 { moment / weight } else { bm },
        cohesion,
        tan_phi,
        pore_pressure,
        layer,
        side_water,
    }
}

/// The base's (c, tan φ) in `layer` (its soil's tan φ′ given) at height y under the
/// ground at g: the soil's c′ and φ′, the undrained strength there with φ = 0, or the tangent
/// to a nonlinear envelope at the estimate `sigma()` of σ′ₙ (W·cos²α/b − u).
#[inline]
fn strength(
    section: &Section,
    layer: usize,
    tan_phi: f64,
    (y, g): (f64, f64),
    sigma: impl Fn() -> f64,
) -> (f64, f64) {
    let l = &section.layers[layer];
    match &l.strength {
        Strength::MohrCoulomb => (l.soil.cohesion, tan_phi),
        Strength::Undrained(u) => (u.at(y, g), 0.0),
        Strength::Envelope(e) => e.tangent(sigma()),
    }
}

#[cfg(test)]
mod tests {
    use super::super::plain;
    use super::*;
    use crate::slope::spencer::Soil;

    /// The plain slicer is the general one's arithmetic: the same slices, bit for bit, on
    /// grounds with bends and surcharge edges inside slices, a crack at the upper end, dry and
    /// with r_u, for shallow and deep circles.
    #[test]
    fn the_plain_slicer_gives_the_general_slicers_slices_bit_for_bit() {
        let ground = vec![
            (-20.0, 0.0),
            (0.0, 0.0),
            (10.0, 5.0),
            (13.3, 5.0),
            (30.0, 12.7),
            (60.0, 12.7),
        ];
        let mut sections = Vec::new();
        for ratio in [0.0, 0.35] {
            let soil = Soil::new(19.5, 8.0, 31.0, ratio).unwrap();
            sections.push(Section::of_one_soil(ground.clone(), soil).unwrap());
            let embankment = crate::slope::Embankment::new(7.5, 15.0).unwrap();
            sections.push(Section::simple(&embankment, soil).unwrap());
        }
        let mut compared = 0;
        for section in &sections {
            let soil = PlainSoil::of(section).unwrap();
            let bends: Vec<f64> = section.ground.xs().collect();
            for (centre, radius) in [
                ((12.0, 30.0), 29.0),
                ((8.0, 18.0), 18.5),
                ((25.0, 40.0), 36.0),
            ] {
                let base =
                    |x: f64| centre.1 - (radius * radius - (x - centre.0).powi(2)).max(0.0).sqrt();
                let (xa, xb) = (centre.0 - 0.9 * radius, centre.0 + 0.9 * radius);
                for count in [3, 17, 50] {
                    let xs: Vec<f64> = (0..=count)
                        .map(|i| xa + (xb - xa) * i as f64 / count as f64)
                        .collect();
                    // The last side as a tension crack's bottom leaves, 1.5 below the ground.
                    let base_at = |i: usize, x: f64, g: f64| match i {
                        0 => g,
                        i if i == count => g - 1.5,
                        _ => base(x).min(g),
                    };
                    // Surcharge edges split slices where the ground is straight.
                    let mut points: Vec<f64> = bends
                        .iter()
                        .copied()
                        .chain([4.4, 21.7])
                        .filter(|&x| x > xa && x < xb)
                        .collect();
                    points.sort_by(f64::total_cmp);
                    let general = slice_with(
                        section,
                        &xs,
                        base_at,
                        &points,
                        1e-9,
                        None,
                        &mut Scratch::default(),
                    );
                    let (slices, surface) = plain::slices(section, soil, &xs, base_at, &points);
                    assert_eq!(slices, general.slices);
                    assert_eq!(surface, general.surface);
                    assert!(general.ponded.iter().all(|&p| p == (0.0, 0.0, 0.0)));
                    let sliced = slice_all(section, &xs, base_at, &points, 1e-9, None);
                    assert_eq!(sliced.slices, general.slices);
                    assert!(sliced.ponded.is_empty());
                    compared += slices.len();
                }
            }
        }
        assert!(compared > 500, "{compared}");
    }

    #[test]
    fn a_section_with_water_or_layers_is_not_plain() {
        let soil = Soil::new(19.5, 8.0, 31.0, 0.0).unwrap();
        let ground = vec![(0.0, 0.0), (10.0, 5.0), (30.0, 5.0)];
        let plain = Section::of_one_soil(ground.clone(), soil).unwrap();
        assert!(PlainSoil::of(&plain).is_some());
        let mut wet = plain.clone();
        wet.piezometric_line =
            Some(super::super::Polyline::new(vec![(0.0, 0.0), (30.0, 3.0)]).unwrap());
        assert!(PlainSoil::of(&wet).is_none());
        let mut layered = plain.clone();
        layered.layers.push(layered.layers[0].clone());
        assert!(PlainSoil::of(&layered).is_none());
    }
}
