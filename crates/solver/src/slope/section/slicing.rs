//! The slices between given sides: each one's weight and its centroid's height integrated
//! exactly, piece by piece between the points where a line above the base bends (Simpson's
//! rule is exact for the linear thickness and the quadratic ∫y of a straight piece), its soil,
//! pore pressure and side water, and the ponded water pressing on its top.
//!
//! The lines are read once per side: the column over a side serves the slices on both of it.

use super::column::{column, ground, pore_pressure, side_water, soil_at, water, Levels};
use super::Section;
use crate::slope::slices::BaseSlice;

/// The slices of one cut.
pub(super) struct Slicing {
    pub slices: Vec<BaseSlice>,
    /// The base's height at each side.
    pub base_ys: Vec<f64>,
    /// Per slice, the ponded water's force on its top: (f_x, f_y, moment about the base
    /// middle).
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
}

/// The slices between the sides `xs`; `base_at(i, x, g)` is the base's height at side i (at x,
/// where the ground is at g). `points`: the section's bends within the cut, sorted.
pub(super) fn slice_all(
    section: &Section,
    xs: &[f64],
    base_at: impl Fn(usize, f64, f64) -> f64,
    points: &[f64],
    tolerance: f64,
) -> Slicing {
    let tan_phi: Vec<f64> = section
        .layers
        .iter()
        .map(|l| l.soil.friction_angle_rad.tan())
        .collect();
    let count = xs.len().saturating_sub(1);
    let mut out = Slicing {
        slices: Vec::with_capacity(count),
        base_ys: Vec::with_capacity(xs.len()),
        ponded: Vec::with_capacity(count),
    };
    let mut s = Scratch::default();
    s.left.read(section, xs[0]);
    let mut bl = base_at(0, xs[0], ground(s.left.values()));
    out.base_ys.push(bl);
    let mut column_left = column(section, s.left.values(), bl);
    for i in 0..count {
        let (xl, xr) = (xs[i], xs[i + 1]);
        s.right.read(section, xr);
        let br = base_at(i + 1, xr, ground(s.right.values()));
        let (slice, column_right, ponded) = slice(
            section,
            ((xl, bl), (xr, br)),
            column_left,
            points,
            (tolerance, &tan_phi),
            &mut s,
        );
        out.slices.push(slice);
        out.base_ys.push(br);
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
}

/// One straight piece [x_a, x_b] of a slice, the levels at its ends given and the base chord
/// from y_a to y_b under it. Leaves the levels half-way in `middle`.
fn piece(
    section: &Section,
    ((xa, ya), (xb, yb)): ((f64, f64), (f64, f64)),
    (a, b): (&[f64], &[f64]),
    column_a: (f64, f64),
    ponded: bool,
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
    // Ponded water: pressure γ_w·d normal to the ground, d linear along the piece.
    let wet = ponded.then(|| {
        let (ga, gb) = (ground(a), ground(b));
        let (da, db) = ((water(a) - ga).max(0.0), (water(b) - gb).max(0.0));
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
    }
}

/// The slice from ((x_l, b_l), (x_r, b_r)) on its base, the levels at its sides read into
/// `s.left` and `s.right` and the column over its left side given: the slice, the column over
/// its right side, and the ponded water on it.
fn slice(
    section: &Section,
    ((xl, bl), (xr, br)): ((f64, f64), (f64, f64)),
    column_left: (f64, f64),
    points: &[f64],
    (tolerance, tan_phi): (f64, &[f64]),
    s: &mut Scratch,
) -> (BaseSlice, (f64, f64), (f64, f64, f64)) {
    let width = xr - xl;
    let (xm, bm) = (0.5 * (xl + xr), 0.5 * (bl + br));
    let ponded = section.piezometric_line.is_some() && section.is_ponded_over(xl, xr);
    let first = points.partition_point(|&p| p <= xl);
    let last = points.partition_point(|&p| p < xr);
    let inner = &points[first..last.max(first)];
    let (mut weight, mut moment) = (0.0, 0.0);
    let mut water_force = (0.0, 0.0, 0.0);
    let mut add = |piece: Piece| {
        weight += piece.integral.0;
        moment += piece.integral.1;
        if let Some((fx, fy, x, y)) = piece.wet {
            water_force.0 += fx;
            water_force.1 += fy;
            water_force.2 += (x - xm) * fy - (y - bm) * fx;
        }
        piece.column_b
    };
    let column_right = if inner.is_empty() {
        // One piece; the levels half-way are those over the base middle.
        add(piece(
            section,
            ((xl, bl), (xr, br)),
            (s.left.values(), s.right.values()),
            column_left,
            ponded,
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
                s.b.read(section, xb);
                chord(xb)
            };
            let column_b = add(piece(
                section,
                ((xa, ya), (xb, yb)),
                (s.a.values(), s.b.values()),
                column_a,
                ponded,
                &mut s.middle,
            ));
            (xa, ya, column_a) = (xb, yb, column_b);
            std::mem::swap(&mut s.a, &mut s.b);
        }
        s.middle.read(section, xm);
        column_a
    };
    let levels = s.middle.values();
    let layer = soil_at(section, levels, bm + tolerance);
    let rise = br - bl;
    let base_length = (width * width + rise * rise).sqrt();
    let soil = &section.layers[layer].soil;
    let slice = BaseSlice {
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
        cohesion: soil.cohesion,
        tan_phi: tan_phi[layer],
        pore_pressure: pore_pressure(section, levels, layer, bm),
        layer,
        side_water: side_water(section, s.right.values(), br),
    };
    (slice, column_right, water_force)
}
