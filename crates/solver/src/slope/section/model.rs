//! The data of a cross-section: its parts ([`Layer`], [`Surcharge`], [`LineLoad`],
//! [`TensionCrack`], all of them in [`SectionParts`]) and the validated [`Section`] with what is
//! found once when it is built — the bends of its lines, their [`LevelTable`], the ponded
//! stretches and a rapid drawdown's section before it ([`Drawdown`], with the soils'
//! [`REnvelope`]). The section's modules build, read and cut it; `Section::new` (in the parent
//! module) validates the parts and finds the bends.

use std::sync::Arc;

use super::polyline::Polyline;
use super::supports::Support;
use super::water::{Water, WaterLine};
use crate::slope::spencer::Soil;
use crate::slope::strength::{Envelope, Strength};

/// One soil layer: its top line (`None` for the first: the ground) and its soil.
#[derive(Debug, Clone, PartialEq)]
pub struct Layer {
    /// Top of the layer; `None` = the ground (the first layer only).
    pub top: Option<Polyline>,
    /// The soil (its own r_u is not used: see `pore_pressure_ratio`).
    pub soil: Soil,
    /// r_u of this soil; when given it sets the pore pressure at bases in this soil, in place
    /// of the piezometric line.
    pub pore_pressure_ratio: Option<f64>,
    /// The strength model (Mohr–Coulomb: the soil's c′ and φ′).
    pub strength: Strength,
    /// The layer's own piezometric line: the pore pressure at bases in this soil (unless it
    /// has its own r_u), in place of the grid and the section's line.
    pub piezometric_line: Option<WaterLine>,
}

/// A vertical pressure on the ground over [x_start, x_end], varying linearly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surcharge {
    /// Left end.
    pub x_start: f64,
    /// Right end (> x_start).
    pub x_end: f64,
    /// Pressure at x_start (downward, ≥ 0).
    pub pressure: f64,
    /// Pressure at x_end (downward, ≥ 0).
    pub pressure_end: f64,
}

/// A force on the ground point above x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineLoad {
    /// Where it acts (on the ground above x).
    pub x: f64,
    /// Horizontal component, positive towards +x.
    pub fx: f64,
    /// Vertical component, positive upwards.
    pub fy: f64,
}

/// A tension crack: the ground moved down by `depth`, with water `water_depth` deep in it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TensionCrack {
    /// Depth of the crack below the ground (> 0).
    pub depth: f64,
    /// Depth of water in the crack, measured up from its bottom (0 ≤ z_w ≤ depth).
    pub water_depth: f64,
}

/// A validated cross-section.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    pub(crate) ground: Polyline,
    pub(crate) layers: Vec<Layer>,
    pub(crate) bedrock: Option<Polyline>,
    pub(crate) piezometric_line: Option<Polyline>,
    pub(crate) water_unit_weight: f64,
    pub(crate) surcharges: Vec<Surcharge>,
    pub(crate) line_loads: Vec<LineLoad>,
    pub(crate) tension_crack: Option<TensionCrack>,
    pub(crate) supports: Vec<Support>,
    pub(crate) water: Water,
    /// Per layer, its nonlinear envelope (empty when none has one): what the slice models of
    /// this section carry.
    pub(super) envelopes: Option<Arc<[Option<Envelope>]>>,
    /// Where the lines above the bases bend or cross, sorted ([`super::bends::bends`]).
    pub(super) bends: Vec<f64>,
    /// The lines above the bases between the bends.
    pub(super) levels: LevelTable,
    /// The stretches of x (between bends, or beyond the last ones) where the piezometric line
    /// lies above the ground somewhere: ponded water. Sorted, merged.
    pub(super) ponded: Vec<(f64, f64)>,
    /// Whether the ground is level beyond its ends by definition (the simple embankment) rather
    /// than as stated only so far (a section's ground line).
    pub(super) level_beyond_ends: bool,
    /// Rapid drawdown: the section before it and the soils that do not drain (the piezometric
    /// line is the one after it).
    pub(super) drawdown: Option<Box<Drawdown>>,
    /// The other stage's water line of a drawdown: its crossings cut the slices too, so that
    /// both stages have the same slices.
    pub(super) other_water_line: Option<Polyline>,
}

/// Everything a [`Section`] is built from.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionParts {
    /// Ground line.
    pub ground: Polyline,
    /// Layers from the top down (at least one; the first one's top is the ground).
    pub layers: Vec<Layer>,
    /// Bedrock line: no slip surface passes below it.
    pub bedrock: Option<Polyline>,
    /// Piezometric line.
    pub piezometric_line: Option<Polyline>,
    /// γ_w (> 0).
    pub water_unit_weight: f64,
    /// Surcharges.
    pub surcharges: Vec<Surcharge>,
    /// Line loads.
    pub line_loads: Vec<LineLoad>,
    /// Tension crack.
    pub tension_crack: Option<TensionCrack>,
    /// Reinforcement (model §7).
    pub supports: Vec<Support>,
    /// h_u of the piezometric line and a pore-pressure grid (model §8).
    pub water: Water,
}

impl Section {
    /// Whether ponded water stands anywhere over [a, b].
    pub(crate) fn is_ponded_over(&self, a: f64, b: f64) -> bool {
        self.ponded.iter().any(|&(lo, hi)| lo < b && a < hi)
    }

    /// Whether the ground is level beyond its ends by definition (the simple embankment):
    /// a surface reaching beyond a section's stated ground deserves a warning, the simple
    /// embankment's does not.
    pub fn is_level_beyond_ends(&self) -> bool {
        self.level_beyond_ends
    }

    /// The ground line.
    pub fn ground(&self) -> &Polyline {
        &self.ground
    }

    /// The layers, top down.
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// The bedrock line.
    pub fn bedrock(&self) -> Option<&Polyline> {
        self.bedrock.as_ref()
    }

    /// The piezometric line.
    pub fn piezometric_line(&self) -> Option<&Polyline> {
        self.piezometric_line.as_ref()
    }

    /// The surcharges.
    pub fn surcharges(&self) -> &[Surcharge] {
        &self.surcharges
    }

    /// The line loads.
    pub fn line_loads(&self) -> &[LineLoad] {
        &self.line_loads
    }

    /// The tension crack.
    pub fn tension_crack(&self) -> Option<TensionCrack> {
        self.tension_crack
    }

    /// The supports.
    pub fn supports(&self) -> &[Support] {
        &self.supports
    }

    /// h_u of the piezometric line and the pore-pressure grid.
    pub fn water(&self) -> &Water {
        &self.water
    }

    /// Whether pore pressures come from more than the section's piezometric line at full head
    /// and the soils' r_u: a layer's own line, h_u or a grid.
    pub(crate) fn has_water_models(&self) -> bool {
        !self.water.is_plain() || self.layers.iter().any(|l| l.piezometric_line.is_some())
    }

    /// Where the ground, layer tops and water line bend or cross, and the surcharge edges,
    /// sorted: between two of these every line of the section is straight.
    pub fn bends(&self) -> &[f64] {
        &self.bends
    }
}

/// A soil's total-stress (R) envelope from consolidated-undrained tests: the line tangent to
/// the circles drawn with σ′_3c and (σ₁ − σ₃)_f.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct REnvelope {
    /// Its intercept c_R.
    pub cohesion: f64,
    /// Its slope φ_R in radians.
    pub friction_angle_rad: f64,
}

/// The pool before the drawdown and the soils that do not drain.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Drawdown {
    /// The section as it stood before: the same, with the water line before the drawdown.
    pub before: Section,
    /// Per layer, its R envelope; `None` where the soil drains freely.
    pub envelopes: Vec<Option<REnvelope>>,
}

/// Entries a [`LevelTable`] may hold (16 bytes each: 4 MiB). Sections of realistic size need a
/// few thousand; one of 50 zigzag layers crossing a zigzag ground would need a hundred
/// megabytes, and is read line by line instead.
const MAX_TABLE_ENTRIES: usize = 1 << 18;

/// The section's lines (layer tops, the ground for a layer without one, then the water line)
/// stretch by stretch between the bends, where each is straight: reading the levels at x is one
/// search for the stretch and a line per level. Empty (each line searched on its own) when it
/// would exceed [`MAX_TABLE_ENTRIES`].
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct LevelTable {
    /// Where each stretch starts: the bends (the first stretch, before them, starts at the first).
    starts: Vec<f64>,
    /// Per stretch and line: the level at the stretch's start and the slope.
    pub(super) rows: Vec<(f64, f64)>,
    /// Lines per stretch.
    pub(super) lines: usize,
}

impl LevelTable {
    /// The table of `section`'s lines over `bends` (sorted, at least one, every vertex of the
    /// lines among them: beyond the first and last the lines are level).
    pub fn new(section: &Section, bends: &[f64]) -> Self {
        let lines: Vec<Option<&Polyline>> = section
            .layers
            .iter()
            .map(|l| Some(l.top.as_ref().unwrap_or(&section.ground)))
            .chain(std::iter::once(section.piezometric_line.as_ref()))
            .collect();
        if (bends.len() + 1).saturating_mul(lines.len()) > MAX_TABLE_ENTRIES {
            return Self::default();
        }
        let y = |line: Option<&Polyline>, x: f64| line.map_or(f64::NAN, |l| l.y_at(x));
        let mut rows = Vec::with_capacity((bends.len() + 1) * lines.len());
        for j in 0..=bends.len() {
            for &line in &lines {
                rows.push(match (j.checked_sub(1), bends.get(j)) {
                    (Some(i), Some(&end)) => {
                        let (start, y0) = (bends[i], y(line, bends[i]));
                        (y0, (y(line, end) - y0) / (end - start))
                    }
                    (Some(i), None) => (y(line, bends[i]), 0.0),
                    (None, _) => (y(line, bends.first().copied().unwrap_or(0.0)), 0.0),
                });
            }
        }
        Self {
            starts: bends.to_vec(),
            rows,
            lines: lines.len(),
        }
    }

    /// Whether there is no table (the lines are read one by one).
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// The stretch holding x, looked for from `cursor` (the stretch of the last read, which it
    /// becomes) by walking, and x's distance from the stretch's start. The first start beyond
    /// x, as `partition_point(|&s| s <= x)` gives it (x is finite).
    pub(super) fn stretch(&self, x: f64, cursor: &mut usize) -> (usize, f64) {
        let starts = &self.starts;
        let mut j = (*cursor).min(starts.len());
        while j < starts.len() && starts[j] <= x {
            j += 1;
        }
        while j > 0 && starts[j - 1] > x {
            j -= 1;
        }
        *cursor = j;
        let dx = x - starts.get(j.saturating_sub(1)).copied().unwrap_or(x);
        (j, dx)
    }

    /// The ground's level at x, as [`Levels::read_from`](super::column::Levels::read_from)
    /// reads it (the same arithmetic); the table must not be empty.
    pub fn ground_at(&self, x: f64, cursor: &mut usize) -> f64 {
        let (j, dx) = self.stretch(x, cursor);
        let (y, slope) = self.rows[j * self.lines];
        y + slope * dx
    }
}
