//! Input the arch solver cannot accept, naming the offending input by what it is.

use super::resultant::{Bound, Resultant};

/// An input of the arch solver, named by what it is (the service maps it to its request field).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArchParameter {
    /// The middle radius of a circular arch.
    Radius,
    /// The voussoir thickness of a circular arch.
    Thickness,
    /// The left base angle of a circular arch.
    LeftBaseAngle,
    /// The right base angle of a circular arch.
    RightBaseAngle,
    /// The list of blocks of a chain.
    Blocks,
    /// The corners of block `block` (0-based) of a chain.
    BlockCorners {
        /// Index of the block.
        block: usize,
    },
    /// Corner `corner` of block `block` (both 0-based).
    BlockCorner {
        /// Index of the block.
        block: usize,
        /// Index of the corner.
        corner: usize,
    },
    /// The polygon of block `block` (0-based) of an assembly.
    BlockPolygon {
        /// Index of the block.
        block: usize,
    },
    /// The supports of an assembly.
    Supports,
    /// The polygon of support `support` (0-based) of an assembly.
    SupportPolygon {
        /// Index of the support.
        support: usize,
    },
    /// The span of a profile.
    Span,
    /// The rise of a profile.
    Rise,
    /// The haunch radius of a three-centred profile.
    HaunchRadius,
    /// The points of a measured intrados.
    Intrados,
    /// The number of rings of a circular arch.
    Rings,
    /// The number of spans.
    Spans,
    /// The width of the piers.
    PierWidth,
    /// The height of the piers.
    PierHeight,
    /// The unit weight.
    UnitWeight,
    /// One limit of the interface resultants.
    InterfaceLimit {
        /// Of which resultant (q, s or t).
        resultant: Resultant,
        /// Which of its limits.
        bound: Bound,
    },
    /// The friction coefficient.
    FrictionCoefficient,
    /// A cohesion.
    Cohesion,
    /// The compressive strength of the joints.
    CompressiveStrength,
    /// The number of crushing planes.
    CrushingPlanes,
    /// The live loads as a whole.
    Loads,
    /// Live load `index` (0-based).
    Load {
        /// Index of the load.
        index: usize,
    },
    /// The passive restraint of a fill.
    Passive,
    /// The block of live load `index` (0-based).
    LoadBlock {
        /// Index of the load.
        index: usize,
    },
}

impl std::fmt::Display for ArchParameter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Radius => write!(f, "radius"),
            Self::Thickness => write!(f, "thickness"),
            Self::LeftBaseAngle => write!(f, "left base angle"),
            Self::RightBaseAngle => write!(f, "right base angle"),
            Self::Blocks => write!(f, "blocks"),
            Self::BlockCorners { block } => write!(f, "corners of block {}", block + 1),
            Self::BlockCorner { block, corner } => {
                write!(f, "corner {} of block {}", corner + 1, block + 1)
            }
            Self::BlockPolygon { block } => write!(f, "polygon of block {}", block + 1),
            Self::Supports => write!(f, "supports"),
            Self::SupportPolygon { support } => write!(f, "polygon of support {}", support + 1),
            Self::Span => write!(f, "span"),
            Self::Rise => write!(f, "rise"),
            Self::HaunchRadius => write!(f, "haunch radius"),
            Self::Intrados => write!(f, "intrados"),
            Self::Rings => write!(f, "rings"),
            Self::Spans => write!(f, "spans"),
            Self::PierWidth => write!(f, "pier width"),
            Self::PierHeight => write!(f, "pier height"),
            Self::UnitWeight => write!(f, "unit weight"),
            Self::InterfaceLimit { resultant, bound } => {
                write!(f, "{bound:?} limit of {resultant:?}")
            }
            Self::FrictionCoefficient => write!(f, "friction coefficient"),
            Self::Cohesion => write!(f, "cohesion"),
            Self::CompressiveStrength => write!(f, "compressive strength"),
            Self::CrushingPlanes => write!(f, "crushing planes"),
            Self::Loads => write!(f, "loads"),
            Self::Load { index } => write!(f, "load {}", index + 1),
            Self::LoadBlock { index } => write!(f, "block of load {}", index + 1),
            Self::Passive => write!(f, "passive restraint"),
        }
    }
}

/// Input the arch solver cannot accept; `parameter` names the offending input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ArchError {
    /// A number is outside its allowed range.
    #[error("{parameter}: {value} is out of range: allowed is {allowed}")]
    OutOfRange {
        /// The input at fault.
        parameter: ArchParameter,
        /// The rejected value.
        value: f64,
        /// The allowed range in words.
        allowed: String,
    },
    /// The blocks do not form a valid assembly.
    #[error("{parameter}: {reason}")]
    InvalidGeometry {
        /// The input at fault.
        parameter: ArchParameter,
        /// What is wrong.
        reason: String,
    },
}

impl ArchError {
    pub(crate) fn range(parameter: ArchParameter, value: f64, allowed: impl Into<String>) -> Self {
        Self::OutOfRange {
            parameter,
            value,
            allowed: allowed.into(),
        }
    }

    pub(crate) fn geometry(parameter: ArchParameter, reason: impl Into<String>) -> Self {
        Self::InvalidGeometry {
            parameter,
            reason: reason.into(),
        }
    }
}
