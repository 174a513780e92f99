//! Limit analysis of structures formed from rigid blocks (Livesley 1978), with the circular
//! arch of the thesis' "Arch Stability" program as the main generator.
//!
//! Conventions, fixed here once for the whole module:
//! - Blocks are numbered 0..n in the crate (the service prints 1..n); interface k separates
//!   block k−1 and block k, interface 0 and interface n are the supports (springings).
//! - Each interface runs from its **intrados** point P_s to its **extrados** point P_q. Its
//!   stress resultants are Livesley's r = (q, s, t): q and s are compressive normal forces at
//!   P_q and P_s, t the shear along P_s→P_q. The unit normal ν points into the higher-numbered
//!   block; the resultant acts on that block as (q + s)·ν + t·τ and on the lower one oppositely.
//! - Equilibrium of block b is written for forces in x, y and the moment about its centroid,
//!   counter-clockwise positive: H r + λ_dead·w + λ·p = 0 with w, p the applied loads.
//!
//! - [`geometry`]: blocks, interfaces, the circular arch generator and block chains.
//! - [`equilibrium`]: the sparse equilibrium matrix H and the load vectors.
//! - [`limit`]: the linear programmes (dead load, live load) solved with Clarabel.
//! - [`mechanism`]: the collapse mechanism read from the multipliers.
//! - [`minimum_thickness`]: the thinnest circular arch that carries its own weight.
//! - [`thrust_line`]: the points of action of the interface resultants.

pub mod chain;
pub mod equilibrium;
pub mod geometry;
pub mod limit;
pub mod mechanism;
pub mod minimum_thickness;
pub mod thrust_line;

pub use crate::outcome::SolverFailure;
pub use equilibrium::LiveLoad;
pub use geometry::{Assembly, Block, CircularArch, Interface, VoussoirShape};
pub use limit::{
    solve_dead_load, solve_live_load, ArchProblem, Formulation, InterfaceLimits, LimitSettings,
    LimitSolution, LimitStatus,
};
pub use mechanism::{ActiveConstraint, Bound, Hinge, HingeSide, Mechanism, Resultant};
pub use minimum_thickness::{
    rupture_angle_deg, solve_minimum_thickness, MinimumThickness, MinimumThicknessOutcome,
    MinimumThicknessSettings,
};
pub use thrust_line::{thrust_line, ThrustPoint};

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
    /// The live loads as a whole.
    Loads,
    /// Live load `index` (0-based).
    Load {
        /// Index of the load.
        index: usize,
    },
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
            Self::UnitWeight => write!(f, "unit weight"),
            Self::InterfaceLimit { resultant, bound } => {
                write!(f, "{bound:?} limit of {resultant:?}")
            }
            Self::FrictionCoefficient => write!(f, "friction coefficient"),
            Self::Loads => write!(f, "loads"),
            Self::Load { index } => write!(f, "load {}", index + 1),
            Self::LoadBlock { index } => write!(f, "block of load {}", index + 1),
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
