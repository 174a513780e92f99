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
mod buffers;
mod column;
mod cut;
pub mod drawdown;
mod ends;
#[cfg(test)]
mod level_tests;
#[cfg(test)]
mod method_tests;
mod model;
pub mod noncircular;
mod place;
mod plain;
pub mod polyline;
pub mod search;
pub(super) mod shape;
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
use super::spencer::{ExternalLoad, Seismic};
use model::LevelTable;
pub use model::{Layer, LineLoad, Section, SectionParts, Surcharge, TensionCrack};
pub use polyline::{Polyline, PolylineError};
pub use shape::SlipShape;
pub use supports::{Support, SupportForce};
pub use water::{Hu, PoreGrid, Water, WaterLine};

use super::strength::{Envelope, Strength};

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
            levels: LevelTable::default(),
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
        self.levels = LevelTable::new(&self, &self.bends);
        self.ponded = bends::ponded(&self);
        self
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
    /// Which mass of a circle is analysed, from the left from 0 (`None`: the largest driven).
    mass: Option<usize>,
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
        let cut = place::place(&section, None, &shape, slices, seismic, moment_centre)?;
        Ok(Self {
            section,
            shape,
            slices,
            seismic,
            moment_centre,
            cut,
            slice_loads: Vec::new(),
            mass: None,
        })
    }

    /// The same circle with its `index`-th mass analysed (from the left, from 0) instead of the
    /// largest.
    pub fn with_mass(mut self, index: usize) -> Result<Self, SlopeError> {
        self.cut = place::place_mass(&self.section, &self.shape, self.slices, self.seismic, index)?;
        self.mass = Some(index);
        Ok(self)
    }

    /// Every mass the surface cuts out of the ground, left to right, in section coordinates:
    /// entry and exit x, and whether something drives it towards its toe (a lens under level
    /// ground, symmetric about the centre's vertical, cannot slide). One for a polyline.
    pub fn masses(&self) -> Vec<(f64, f64, bool)> {
        let mut out: Vec<(f64, f64)> = ends::ends(&self.section, &self.shape)
            .map(|p| p.into_iter().collect())
            .unwrap_or_default();
        out.sort_by(|a, b| a.0.total_cmp(&b.0));
        let driven = |i: usize| {
            let cut = place::place_mass(&self.section, &self.shape, self.slices, self.seismic, i);
            cut.is_ok()
        };
        match out.len() {
            0 | 1 => out.into_iter().map(|(a, b)| (a, b, true)).collect(),
            _ => out
                .into_iter()
                .enumerate()
                .map(|(i, (a, b))| (a, b, driven(i)))
                .collect(),
        }
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

    /// Where the slip surface runs beyond the section's ground as stated, `(low, high)` its
    /// x-range against the ground's `(first, last)`: `None` when it stays within (to rounding),
    /// or on the simple embankment, whose ground runs on level by definition.
    pub fn beyond_ground(&self) -> Option<((f64, f64), (f64, f64))> {
        let section = self.section();
        if section.is_level_beyond_ends() {
            return None;
        }
        let (first, last) = section.ground().x_range();
        let (low, high) = self
            .surface()
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.0), b.max(p.0))
            });
        let rounding = 1e-9 * (last - first).abs().max(1.0);
        (low < first - rounding || high > last + rounding).then_some(((low, high), (first, last)))
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
        let problem = Self::new(
            self.section.clone(),
            self.shape.clone(),
            slices,
            self.seismic,
            self.moment_centre,
        )?;
        match self.mass {
            Some(index) => problem.with_mass(index),
            None => Ok(problem),
        }
    }
}
