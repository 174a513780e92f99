//! A vertical through the section: the heights of its lines there (the levels) and what the
//! soil rule makes of them — the weight of the column above a point, the soil at a point, the
//! pore water's force on the vertical.
//!
//! Levels are read once per slice side; between the points where a line bends or two lines
//! cross every line is straight, so the levels half-way are the mean of the levels at the ends.

use super::model::Section;

/// The bends of a cut that lie inside each of its slices, found by walking (the slices come left
/// to right): for sides x_l ≤ x_r, the points p with x_l < p < x_r, the same as
/// `partition_point` finds them, without a search per slice.
#[derive(Debug, Default)]
pub(super) struct InnerPoints {
    /// Points at or left of the last x_l, and left of the last x_r.
    first: usize,
    last: usize,
}

impl InnerPoints {
    /// The points (sorted) strictly between `xl` and `xr`; `xl` and `xr` never less than at
    /// the last call.
    pub fn within<'a>(&mut self, points: &'a [f64], (xl, xr): (f64, f64)) -> &'a [f64] {
        while self.first < points.len() && points[self.first] <= xl {
            self.first += 1;
        }
        while self.last < points.len() && points[self.last] < xr {
            self.last += 1;
        }
        &points[self.first..self.last.max(self.first)]
    }
}

/// The heights of the section's lines at one x, in a reusable buffer: index k < L is the top of
/// layer k (the ground for k = 0), index L the piezometric line (NaN without one).
#[derive(Debug, Default)]
pub(super) struct Levels(Vec<f64>);

/// `clone_from` copies into the buffer it has (a derived one would allocate a new one each
/// time: the slicer copies levels at every bend inside a slice).
impl Clone for Levels {
    fn clone(&self) -> Self {
        Self(self.0.clone())
    }

    fn clone_from(&mut self, source: &Self) {
        self.0.clone_from(&source.0);
    }
}

impl Levels {
    /// Reads the section's lines at x.
    #[cfg(test)]
    pub fn read(&mut self, section: &Section, x: f64) {
        self.read_from(section, x, &mut 0);
    }

    /// [`Levels::read`] for reads that move along x by small steps: the table's stretch is
    /// looked for from `cursor` (the stretch of the last read, which it becomes) by walking,
    /// where a search would start from scratch. The same stretch, so the same levels.
    pub fn read_from(&mut self, section: &Section, x: f64, cursor: &mut usize) {
        let table = &section.levels;
        if table.is_empty() {
            self.read_lines(section, x);
            return;
        }
        let (j, dx) = table.stretch(x, cursor);
        let rows = &table.rows[j * table.lines..(j + 1) * table.lines];
        // The buffer keeps its length from read to read: `resize` is called only when it
        // differs (the call, not inlined, costs more than the check on this per-side path).
        if self.0.len() != rows.len() {
            self.0.resize(rows.len(), 0.0);
        }
        for (level, &(y, slope)) in self.0.iter_mut().zip(rows) {
            *level = y + slope * dx;
        }
    }

    /// Reads each line at x on its own (sections too large for a
    /// [`LevelTable`](super::model::LevelTable)).
    fn read_lines(&mut self, section: &Section, x: f64) {
        self.0.clear();
        let g = section.ground.y_at(x);
        self.0.extend(
            section
                .layers
                .iter()
                .map(|l| l.top.as_ref().map_or(g, |t| t.y_at(x))),
        );
        self.0.push(
            section
                .piezometric_line
                .as_ref()
                .map_or(f64::NAN, |l| l.y_at(x)),
        );
    }

    /// The levels half-way between `a` and `b` on a stretch where every line is straight.
    pub fn midway(&mut self, a: &[f64], b: &[f64]) {
        self.0.clear();
        self.0.extend(a.iter().zip(b).map(|(p, q)| 0.5 * (p + q)));
    }

    /// The values, as [`Levels::read`] left them.
    pub fn values(&self) -> &[f64] {
        &self.0
    }
}

/// The ground at these levels.
pub(super) fn ground(levels: &[f64]) -> f64 {
    levels[0]
}

/// The piezometric line at these levels (NaN without one).
pub(super) fn water(levels: &[f64]) -> f64 {
    levels[levels.len() - 1]
}

/// The weight of the column over y and its first moment ∫γ·y dy, by the soil rule: layer k
/// holds the points at or below its top and above every later layer's top.
///
/// The smaller and larger of two levels are taken by comparison, not `f64::min`/`max` (whose
/// handling of NaN costs several instructions in this, the slicer's innermost loop): the levels
/// and y are finite, and where the two differ only in the sign of a zero, the weight and moment
/// are the same either way (a zero enters only as `upper − below` with `upper > below`, or
/// squared).
pub(super) fn column(section: &Section, levels: &[f64], y: f64) -> (f64, f64) {
    let g = ground(levels);
    let mut below = y;
    let (mut w, mut m) = (0.0, 0.0);
    for (layer, &top) in section.layers.iter().zip(levels).rev() {
        let upper = if top < g { top } else { g };
        if upper > below {
            let gamma = layer.soil.unit_weight;
            w += gamma * (upper - below);
            m += gamma * 0.5 * (upper * upper - below * below);
        }
        below = if top > below { top } else { below };
    }
    (w, m)
}

/// The layer whose soil is at height y: the last one whose top is at or above y (the first at
/// the ground).
pub(super) fn soil_at(section: &Section, levels: &[f64], y: f64) -> usize {
    (0..section.layers.len())
        .rev()
        .find(|&k| levels[k] >= y)
        .unwrap_or(0)
}

/// The pore pressure at (x, y) in `layer`: r_u times the column's weight where the soil has its
/// own r_u; else from the layer's own piezometric line; else from the grid (0 outside it); else
/// h_u·γ_w times the depth below the section's piezometric line; else none.
pub(super) fn pore_pressure(
    section: &Section,
    levels: &[f64],
    layer: usize,
    (x, y): (f64, f64),
) -> f64 {
    let own = &section.layers[layer];
    if let Some(ratio) = own.pore_pressure_ratio {
        return ratio * column(section, levels, y).0;
    }
    let gw = section.water_unit_weight;
    if let Some(line) = &own.piezometric_line {
        return line.pressure(gw, x, y);
    }
    if let Some(grid) = &section.water.grid {
        return grid.pressure(x, y).unwrap_or(0.0);
    }
    match &section.piezometric_line {
        Some(line) => gw * section.water.hu.at(line, x) * (water(levels) - y).max(0.0),
        None => 0.0,
    }
}

/// The side water of one soil with its own r_u, from the base at b up to the ground at g
/// (above it): u = r_u·γ·(g − y), so ½·r_u·γ·h² at h/3 above the base.
pub(super) fn ratio_side_water(ratio: f64, gamma: f64, (g, b): (f64, f64)) -> (f64, f64) {
    let h = g - b;
    let force = 0.5 * ratio * gamma * h * h;
    if force > 0.0 {
        (force, b + h / 3.0)
    } else {
        (0.0, b)
    }
}

/// Whether every pore pressure comes from the section's piezometric line alone (or there is
/// none): no grid, no layer with its own r_u or water line. [`side_water`] is then in closed
/// form; a slicer asks once per cut.
pub(super) fn water_from_line_alone(section: &Section) -> bool {
    section.water.grid.is_none()
        && section
            .layers
            .iter()
            .all(|l| l.pore_pressure_ratio.is_none() && l.piezometric_line.is_none())
}

/// The pore water's force on the vertical at x from the base at y = b up to the ground, and its
/// height: closed form under a water line, else ∫u dy by Simpson's rule on 8 panels (the r_u
/// pressures of layered soils are piecewise linear, to ~1e-4 there; a grid's are linear in
/// each triangle). `line_alone`: [`water_from_line_alone`] of the section.
pub(super) fn side_water(
    section: &Section,
    levels: &[f64],
    (x, b): (f64, f64),
    line_alone: bool,
) -> (f64, f64) {
    let g = ground(levels);
    if g <= b {
        return (0.0, b);
    }
    let layers = &section.layers;
    if line_alone {
        let Some(line) = &section.piezometric_line else {
            return (0.0, b);
        };
        let yp = water(levels);
        let top = yp.min(g);
        if top <= b {
            return (0.0, b);
        }
        let gw = section.water_unit_weight * section.water.hu.at(line, x);
        // ∫_b^top γ_w (y_p − y) dy and its moment ∫ γ_w (y_p − y)·y dy.
        let force = gw * ((yp - b).powi(2) - (yp - top).powi(2)) / 2.0;
        let moment = gw * (yp * (top * top - b * b) / 2.0 - (top.powi(3) - b.powi(3)) / 3.0);
        return if force > 0.0 {
            (force, moment / force)
        } else {
            (0.0, b)
        };
    }
    if let ([layer], None) = (layers.as_slice(), &section.water.grid) {
        if let (Some(ratio), None) = (layer.pore_pressure_ratio, &layer.piezometric_line) {
            return ratio_side_water(ratio, layer.soil.unit_weight, (g, b));
        }
    }
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
        let p = pore_pressure(section, levels, soil_at(section, levels, y), (x, y));
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
