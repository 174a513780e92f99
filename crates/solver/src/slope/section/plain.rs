//! The slices of the commonest scene: one Mohr–Coulomb soil under the ground, dry or with its
//! own r_u, and nothing else above the bases (no water line, grid or layer of its own). The
//! general slicer's arithmetic, operation for operation, without its reading of every line at
//! every side: the same slices bit for bit (tested against it), at a fraction of the cost of a
//! search's circles.

use super::column;
use super::model::Section;
use crate::slope::slices::BaseSlice;
use crate::slope::strength::Strength;

/// A plain section's soil: (γ, c′, tan φ′, r_u).
#[derive(Debug, Clone, Copy)]
pub(super) struct PlainSoil {
    gamma: f64,
    cohesion: f64,
    tan_phi: f64,
    ratio: Option<f64>,
}

impl PlainSoil {
    /// The soil when `section` is plain, with its level table built.
    pub fn of(section: &Section) -> Option<Self> {
        let [layer] = section.layers.as_slice() else {
            return None;
        };
        let plain = matches!(layer.strength, Strength::MohrCoulomb)
            && layer.piezometric_line.is_none()
            && section.piezometric_line.is_none()
            && section.water.grid.is_none()
            && !section.levels.is_empty();
        plain.then(|| Self {
            gamma: layer.soil.unit_weight,
            cohesion: layer.soil.cohesion,
            tan_phi: layer.soil.friction_angle_rad.tan(),
            ratio: layer.pore_pressure_ratio,
        })
    }

    /// The column over y under the ground at g: its weight and first moment ∫γ·y dy.
    #[inline]
    fn column(&self, g: f64, y: f64) -> (f64, f64) {
        if g > y {
            (self.gamma * (g - y), self.gamma * 0.5 * (g * g - y * y))
        } else {
            (0.0, 0.0)
        }
    }

    /// The pore water's force on a side from the base at b up to the ground at g, and its
    /// height ([`column::ratio_side_water`]; none without r_u or above the ground).
    fn side_water(&self, g: f64, b: f64) -> (f64, f64) {
        match self.ratio {
            Some(ratio) if g > b => column::ratio_side_water(ratio, self.gamma, (g, b)),
            _ => (0.0, b),
        }
    }
}

/// The slices between the sides `xs` (the base at side i from `base_at(i, x, g)`, the ground
/// at x being g; `points`, the ground's bends within the cut, sorted) and the base's end point
/// at each side (with room for one more).
pub(super) fn slices(
    section: &Section,
    soil: PlainSoil,
    xs: &[f64],
    base_at: impl Fn(usize, f64, f64) -> f64,
    points: &[f64],
) -> (Vec<BaseSlice>, Vec<(f64, f64)>) {
    let table = &section.levels;
    let mut cursor = 0;
    let mut inner_points = column::InnerPoints::default();
    let count = xs.len().saturating_sub(1);
    let (mut slices, mut surface) = super::buffers::vectors(xs.len());
    let mut gl = table.ground_at(xs[0], &mut cursor);
    let mut bl = base_at(0, xs[0], gl);
    surface.push((xs[0], bl));
    let mut column_left = soil.column(gl, bl);
    for i in 0..count {
        let (xl, xr) = (xs[i], xs[i + 1]);
        let gr = table.ground_at(xr, &mut cursor);
        let br = base_at(i + 1, xr, gr);
        let inner = inner_points.within(points, (xl, xr));
        let ((weight, moment), column_right, gm) = if inner.is_empty() {
            let piece = piece(soil, ((xl, bl, gl), (xr, br, gr)), column_left);
            (piece.0, piece.1, 0.5 * (gl + gr))
        } else {
            let width = xr - xl;
            let chord = |x: f64| bl + (br - bl) * (x - xl) / width;
            let (mut a, mut column_a) = ((xl, bl, gl), column_left);
            let (mut weight, mut moment) = (0.0, 0.0);
            for (k, &xb) in inner.iter().chain(std::iter::once(&xr)).enumerate() {
                let b = if k == inner.len() {
                    (xr, br, gr)
                } else {
                    (xb, chord(xb), table.ground_at(xb, &mut cursor))
                };
                let (integral, column_b) = piece(soil, (a, b), column_a);
                weight += integral.0;
                moment += integral.1;
                (a, column_a) = (b, column_b);
            }
            let xm = 0.5 * (xl + xr);
            ((weight, moment), column_a, table.ground_at(xm, &mut cursor))
        };
        slices.push(slice(
            soil,
            ((xl, bl), (xr, br), (gm, gr)),
            (weight, moment),
        ));
        surface.push((xr, br));
        (gl, bl, column_left) = (gr, br, column_right);
    }
    (slices, surface)
}

/// One straight piece from (x_a, y_a) to (x_b, y_b) on the base, the ground over its ends
/// given and the column over its start: its weight and first moment by Simpson's rule (exact
/// here), and the column over its end.
#[inline]
fn piece(
    soil: PlainSoil,
    ((xa, ya, ga), (xb, yb, gb)): ((f64, f64, f64), (f64, f64, f64)),
    column_a: (f64, f64),
) -> ((f64, f64), (f64, f64)) {
    let column_m = soil.column(0.5 * (ga + gb), 0.5 * (ya + yb));
    let column_b = soil.column(gb, yb);
    let sixth = (xb - xa) / 6.0;
    (
        (
            sixth * (column_a.0 + 4.0 * column_m.0 + column_b.0),
            sixth * (column_a.1 + 4.0 * column_m.1 + column_b.1),
        ),
        column_b,
    )
}

/// The slice on the base from (x_l, b_l) to (x_r, b_r), the ground over its middle and right
/// side given, and its weight and first moment.
fn slice(
    soil: PlainSoil,
    ((xl, bl), (xr, br), (gm, gr)): ((f64, f64), (f64, f64), (f64, f64)),
    (weight, moment): (f64, f64),
) -> BaseSlice {
    let width = xr - xl;
    let (xm, bm) = (0.5 * (xl + xr), 0.5 * (bl + br));
    let rise = br - bl;
    let base_length = (width * width + rise * rise).sqrt();
    let pore_pressure = soil.ratio.map_or(0.0, |r| r * soil.column(gm, bm).0);
    BaseSlice {
        x_left: xl,
        x_right: xr,
        base_left_y: bl,
        base_right_y: br,
        top_right_y: gr,
        base_sin_cos: (rise / base_length, width / base_length),
        base_length,
        base_middle: (xm, bm),
        height_middle: gm - bm,
        weight,
        centroid_y: if weight > 0.0 { moment / weight } else { bm },
        cohesion: soil.cohesion,
        tan_phi: soil.tan_phi,
        pore_pressure,
        layer: 0,
        side_water: soil.side_water(gr, br),
    }
}
