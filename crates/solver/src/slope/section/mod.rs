//! Real cross-sections (model §4.1–4.2): a ground line facing either way, layers listed from the
//! top down, bedrock, a piezometric line (ponded water where it lies above the ground), per-soil
//! r_u, surcharges, line loads and a tension crack; slip surfaces that are absolute circles or
//! any polyline.
//!
//! [`SectionProblem::new`] validates the section, places the slip surface on it and cuts the
//! sliding mass into [`SliceModel`] slices in the solver's frame (crest towards +x: a section
//! whose crest lies to the left is mirrored, x → −x, and mirrored back for the answer).

mod bends;
mod blocks;
mod column;
mod cut;
pub mod drawdown;
mod ends;
#[cfg(test)]
mod level_tests;
#[cfg(test)]
mod method_tests;
pub mod noncircular;
mod plain;
pub mod polyline;
pub mod search;
mod simple;
mod slicing;
pub mod supports;
#[cfg(test)]
mod tests;
pub mod trial;
mod validate;
pub mod water;

use super::error::{check_range, SlopeError, SlopeParameter};
use std::borrow::Cow;
use std::num::NonZeroUsize;
use std::sync::Arc;

use super::slices::{SliceModel, Sliced};
use super::spencer::{ExternalLoad, Seismic, Soil};
pub use polyline::{Polyline, PolylineError};
pub use supports::{Support, SupportForce};
pub use water::{Hu, PoreGrid, Water, WaterLine};

use super::strength::{Envelope, Strength};

/// Largest magnitude of a pressure, force or unit weight (as for the simple form).
const MAX_MAGNITUDE: f64 = 1e12;

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
    envelopes: Option<Arc<[Option<Envelope>]>>,
    /// Where the lines above the bases bend or cross, sorted ([`bends::bends`]).
    bends: Vec<f64>,
    /// The lines above the bases between the bends.
    levels: column::LevelTable,
    /// The stretches of x (between bends, or beyond the last ones) where the piezometric line
    /// lies above the ground somewhere: ponded water. Sorted, merged.
    ponded: Vec<(f64, f64)>,
    /// Whether the ground is level beyond its ends by definition (the simple embankment) rather
    /// than as stated only so far (a section's ground line).
    level_beyond_ends: bool,
    /// Rapid drawdown: the section before it and the soils that do not drain (the piezometric
    /// line is the one after it).
    drawdown: Option<Box<drawdown::Drawdown>>,
    /// The other stage's water line of a drawdown: its crossings cut the slices too, so that
    /// both stages have the same slices.
    other_water_line: Option<Polyline>,
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
    /// Validates the parts that depend on each other (polylines are valid by construction).
    pub fn new(parts: SectionParts) -> Result<Self, SlopeError> {
        validate::check(&parts)?;
        Ok(Self {
            envelopes: envelopes(&parts.layers),
            ground: parts.ground,
            layers: parts.layers,
            bedrock: parts.bedrock,
            piezometric_line: parts.piezometric_line,
            water_unit_weight: parts.water_unit_weight,
            surcharges: parts.surcharges,
            line_loads: parts.line_loads,
            tension_crack: parts.tension_crack,
            supports: parts.supports,
            water: parts.water,
            bends: Vec::new(),
            levels: column::LevelTable::default(),
            ponded: Vec::new(),
            level_beyond_ends: false,
            drawdown: None,
            other_water_line: None,
        }
        .with_bends())
    }

    /// The section with its bends found.
    fn with_bends(mut self) -> Self {
        self.bends = bends::bends(&self);
        self.levels = column::LevelTable::new(&self, &self.bends);
        self.ponded = bends::ponded(&self);
        self
    }

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

/// Per layer, its nonlinear envelope; `None` when no layer has one.
fn envelopes(layers: &[Layer]) -> Option<Arc<[Option<Envelope>]>> {
    layers
        .iter()
        .any(|l| matches!(l.strength, Strength::Envelope(_)))
        .then(|| {
            layers
                .iter()
                .map(|l| match &l.strength {
                    Strength::Envelope(e) => Some(e.clone()),
                    _ => None,
                })
                .collect()
        })
}

/// A slip surface in the section's coordinates.
#[derive(Debug, Clone, PartialEq)]
pub enum SlipShape {
    /// A circle; the sliding mass lies above the arc between the two crossings of the ground
    /// that bound the deepest part of the arc.
    Circle {
        /// Centre.
        centre: (f64, f64),
        /// Radius (> 0).
        radius: f64,
    },
    /// A polyline whose first and last points lie at or above the ground.
    Polyline(Polyline),
}

impl SlipShape {
    fn mirrored(&self) -> Self {
        match self {
            Self::Circle { centre, radius } => Self::Circle {
                centre: (-centre.0, centre.1),
                radius: *radius,
            },
            Self::Polyline(line) => Self::Polyline(line.mirrored()),
        }
    }
}

/// One slip surface on one section, cut into slices, ready to solve.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionProblem {
    section: Section,
    shape: SlipShape,
    slices: NonZeroUsize,
    seismic: Seismic,
    moment_centre: Option<(f64, f64)>,
    cut: cut::Cut,
    /// Known forces given per slice (the thesis' F_x, F_y, M1), already in `cut.model.loads`.
    slice_loads: Vec<ExternalLoad>,
}

/// A circle a section takes: finite coordinates, |x|, |y| ≤ 1e9, and 0 < R ≤ 1e9.
pub(crate) fn check_circle(centre: (f64, f64), radius: f64) -> Result<(), SlopeError> {
    for v in [centre.0, centre.1] {
        check_range(
            SlopeParameter::CircleCentre,
            v,
            -1e9,
            false,
            1e9,
            "finite coordinates, |x|, |y| ≤ 1e9",
        )?;
    }
    check_range(
        SlopeParameter::CircleRadius,
        radius,
        0.0,
        true,
        1e9,
        "a finite radius, 0 < R ≤ 1e9",
    )?;
    Ok(())
}

impl SectionProblem {
    /// Places `shape` on `section` and cuts the sliding mass into about `slices` slices (more
    /// when the section has more pieces than that: each slice lies within one piece).
    pub fn new(
        section: Section,
        shape: SlipShape,
        slices: NonZeroUsize,
        seismic: Seismic,
        moment_centre: Option<(f64, f64)>,
    ) -> Result<Self, SlopeError> {
        Seismic::new(seismic.kh, seismic.kv)?;
        if let SlipShape::Circle { centre, radius } = &shape {
            check_circle(*centre, *radius)?;
        }
        if let Some(c) = moment_centre {
            for v in [c.0, c.1] {
                check_range(
                    SlopeParameter::MomentCentre,
                    v,
                    -1e9,
                    false,
                    1e9,
                    "finite coordinates, |x|, |y| ≤ 1e9",
                )?;
            }
        }
        if let (SlipShape::Polyline(line), Some(bedrock)) = (&shape, &section.bedrock) {
            let below = line
                .points()
                .iter()
                .enumerate()
                .find(|(_, p)| p.1 < bedrock.y_at(p.0) - 1e-9 * p.1.abs().max(1.0));
            if let Some((index, p)) = below {
                return Err(SlopeError::NoSlipMass {
                    parameter: SlopeParameter::SurfaceVertex { index },
                    reason: format!(
                        "vertex {index} ({}, {}) lies below the bedrock (at {}): a slip surface \
                         cannot pass through it",
                        p.0,
                        p.1,
                        bedrock.y_at(p.0)
                    ),
                });
            }
        }
        let cut = cut::place(&section, None, &shape, slices, seismic, moment_centre)?;
        Ok(Self {
            section,
            shape,
            slices,
            seismic,
            moment_centre,
            cut,
            slice_loads: Vec::new(),
        })
    }

    /// The same surface with known forces on given slices (the thesis' F_x, F_y and M1 at the
    /// base middle, slices counted from the lower end in the solver's frame). Such a problem
    /// cannot be re-cut into other slices (`with_slices` refuses it).
    pub fn with_slice_loads(mut self, loads: Vec<ExternalLoad>) -> Result<Self, SlopeError> {
        crate::slope::slices::check_slice_loads(&loads, self.cut.model.slices.len())?;
        self.cut.model.loads.extend(loads.iter().copied());
        self.slice_loads.extend(loads);
        Ok(self)
    }

    /// The section.
    pub fn section(&self) -> &Section {
        &self.section
    }

    /// The slip surface as given.
    pub fn shape(&self) -> &SlipShape {
        &self.shape
    }

    /// Whether the section's crest lies to the left: the solver's frame is then mirrored
    /// (x → −x) and the slices run from right to left.
    pub fn is_mirrored(&self) -> bool {
        self.cut.mirrored
    }

    /// A solver-frame x in section coordinates.
    pub fn to_section_x(&self, x: f64) -> f64 {
        if self.cut.mirrored {
            -x
        } else {
            x
        }
    }

    /// The slip surface as cut, left to right in section coordinates (a tension crack adds its
    /// vertical face at the upper end).
    pub fn surface(&self) -> Vec<(f64, f64)> {
        let mut points: Vec<(f64, f64)> = self
            .cut
            .surface
            .iter()
            .map(|&(x, y)| (self.to_section_x(x), y))
            .collect();
        if self.cut.mirrored {
            points.reverse();
        }
        points
    }

    /// Entry and exit of the slip surface on the ground (toe end, crest end), in section
    /// coordinates; with a tension crack the crest end is the top of the crack.
    pub fn ends(&self) -> ((f64, f64), (f64, f64)) {
        let (a, b) = self.cut.ends;
        ((self.to_section_x(a.0), a.1), (self.to_section_x(b.0), b.1))
    }

    /// The tension crack as cut: x, bottom and top, in section coordinates.
    pub fn crack(&self) -> Option<(f64, f64, f64)> {
        self.cut
            .crack
            .map(|(x, bottom, top)| (self.to_section_x(x), bottom, top))
    }

    /// The slices and loads in the solver's frame.
    pub fn model(&self) -> &SliceModel {
        &self.cut.model
    }

    /// What a rapid drawdown's stages gave on this surface.
    pub fn drawdown(&self) -> Option<&drawdown::DrawdownStages> {
        self.cut.drawdown.as_ref()
    }

    /// Each support against this surface, in section coordinates (as the section lists them).
    pub fn supports(&self) -> Vec<SupportForce> {
        supports::in_section(&self.cut.supports, self.cut.mirrored)
    }
}

impl Sliced for SectionProblem {
    fn model(&self) -> Cow<'_, SliceModel> {
        Cow::Borrowed(&self.cut.model)
    }

    fn slice_count(&self) -> usize {
        self.cut.model.slices.len()
    }

    fn with_slices(&self, slices: NonZeroUsize) -> Result<Self, SlopeError> {
        if !self.slice_loads.is_empty() {
            return Err(SlopeError::Conflict {
                parameter: SlopeParameter::ExternalLoads,
                reason: "loads are given per slice: the slices cannot change".to_owned(),
            });
        }
        Self::new(
            self.section.clone(),
            self.shape.clone(),
            slices,
            self.seismic,
            self.moment_centre,
        )
    }
}
