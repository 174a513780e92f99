//! The slip surface an analysis answers, on a section (the simple embankment is one,
//! [`crate::slope::section::Section::simple`]); what an answer and its drawing read of it, in
//! the caller's coordinates.

use std::borrow::Cow;
use std::num::NonZeroUsize;

use crate::slope::section::{SectionProblem, SlipShape};
use crate::slope::slices::{SliceModel, Sliced};
use crate::slope::SlopeError;

/// One slip surface on a section (the simple slope as one, its relative circle placed).
#[derive(Debug, Clone)]
pub enum Analysed {
    /// A section with a circle or a polyline.
    Section(Box<SectionProblem>),
}

/// A circle placed on the ground, in the request's coordinates.
#[derive(Debug, Clone, Copy)]
pub struct PlacedCircle {
    /// The centre.
    pub centre: (f64, f64),
    /// The radius.
    pub radius: f64,
    /// The lower (toe) end of the slip surface.
    pub lower_end: (f64, f64),
    /// The upper (crest) end of the slip surface.
    pub upper_exit: (f64, f64),
}

impl Analysed {
    /// A solver-frame x in the request's coordinates.
    pub fn request_x(&self, x: f64) -> f64 {
        match self {
            Self::Section(p) => p.to_section_x(x),
        }
    }

    /// The circle, when the surface is one.
    pub fn circle(&self) -> Option<PlacedCircle> {
        match self {
            Self::Section(p) => match p.shape() {
                SlipShape::Circle { centre, radius } => {
                    let (lower_end, upper_exit) = p.ends();
                    Some(PlacedCircle {
                        centre: *centre,
                        radius: *radius,
                        lower_end,
                        upper_exit,
                    })
                }
                SlipShape::Polyline(_) => None,
            },
        }
    }

    /// The slip surface as cut, left to right (the slice bases' end points).
    pub fn surface(&self) -> Vec<(f64, f64)> {
        match self {
            Self::Section(p) => p.surface(),
        }
    }

    /// Ground level above a solver-frame x.
    pub fn ground_y(&self, x: f64) -> f64 {
        match self {
            Self::Section(p) => p.section().ground().y_at(self.request_x(x)),
        }
    }
}

impl Sliced for Analysed {
    fn model(&self) -> Cow<'_, SliceModel> {
        match self {
            Self::Section(p) => Cow::Borrowed(p.model()),
        }
    }

    fn slice_count(&self) -> usize {
        match self {
            Self::Section(p) => Sliced::slice_count(p.as_ref()),
        }
    }

    fn with_slices(&self, slices: NonZeroUsize) -> Result<Self, SlopeError> {
        Ok(match self {
            Self::Section(p) => Self::Section(Box::new(p.with_slices(slices)?)),
        })
    }
}
