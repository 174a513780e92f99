//! One slip surface on one section: placed, cut into slices, ready to solve.

use std::borrow::Cow;
use std::num::NonZeroUsize;

use super::{cut, Polyline, Section};
use crate::slope::error::{check_range, SlopeError, SlopeParameter};
use crate::slope::slices::{SliceModel, Sliced};
use crate::slope::spencer::{ExternalLoad, Seismic};

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
    pub(super) fn mirrored(&self) -> Self {
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
                *radius,
                0.0,
                true,
                1e9,
                "a finite radius, 0 < R ≤ 1e9",
            )?;
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
        let slices = self.cut.model.slices.len();
        for (index, load) in loads.iter().enumerate() {
            if load.slice >= slices {
                return Err(SlopeError::OutOfRange {
                    parameter: SlopeParameter::ExternalLoadSlice { index },
                    value: (load.slice + 1) as f64,
                    allowed: "the number of an existing slice, 1 ≤ slice ≤ slices",
                });
            }
            for value in [load.fx, load.fy, load.moment] {
                let parameter = SlopeParameter::ExternalLoad { index };
                check_range(
                    parameter,
                    value,
                    f64::MIN,
                    false,
                    f64::MAX,
                    "a finite number",
                )?;
            }
        }
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
