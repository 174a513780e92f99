//! A slip surface as given, in the section's coordinates: a circle or a polyline.

use super::polyline::Polyline;

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
    /// The surface seen from behind (x → −x).
    pub fn mirrored(&self) -> Self {
        match self {
            Self::Circle { centre, radius } => Self::Circle {
                centre: (-centre.0, centre.1),
                radius: *radius,
            },
            Self::Polyline(line) => Self::Polyline(line.mirrored()),
        }
    }
}
