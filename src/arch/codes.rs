//! The coded strings of the arch answers as enums: which resultant a limit is on, which bound,
//! which side a hinge opens on.

use serde::Serialize;
use thrustline_solver::arch::{HingeSide, Resultant};
use utoipa::ToSchema;

/// A resultant of an interface.
#[derive(Debug, Clone, Copy, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ResultantDto {
    /// Normal force at the extrados end.
    Q,
    /// Normal force at the intrados end.
    S,
    /// Shear.
    T,
    /// μ(q + s) − t (friction).
    U,
    /// μ(q + s) + t (friction).
    V,
    /// Crushing: the moment–normal force limit of the rectangular stress block (`upper`: the
    /// resultant pressed to the extrados end, `lower`: to the intrados end).
    M,
    /// A passive force of the fill at its bound. Not an interface limit: the solver keeps it out
    /// of a mechanism's active limits, so answers do not contain it today.
    Passive,
}

impl From<Resultant> for ResultantDto {
    fn from(resultant: Resultant) -> Self {
        match resultant {
            Resultant::Q => Self::Q,
            Resultant::S => Self::S,
            Resultant::T => Self::T,
            Resultant::U => Self::U,
            Resultant::V => Self::V,
            Resultant::M => Self::M,
            Resultant::Passive => Self::Passive,
        }
    }
}

/// Which limit of a resultant.
#[derive(Debug, Clone, Copy, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum BoundDto {
    /// The lower limit (no tension, friction).
    Lower,
    /// The upper limit (crushing, shear capacity).
    Upper,
}

/// Where a hinge forms.
#[derive(Debug, Clone, Copy, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum HingeSideDto {
    /// At the intrados end of the joint.
    Intrados,
    /// At the extrados end of the joint.
    Extrados,
}

impl From<HingeSide> for HingeSideDto {
    fn from(side: HingeSide) -> Self {
        match side {
            HingeSide::Intrados => Self::Intrados,
            HingeSide::Extrados => Self::Extrados,
        }
    }
}
