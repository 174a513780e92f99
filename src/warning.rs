//! Warnings as data (SPEC §6.1): a `code` a dashboard can switch on, a `message` for people, and
//! the indices it speaks of as arrays (numbered from 1, as everywhere in the answers), never
//! packed into the message only.

use serde::Serialize;
use utoipa::ToSchema;

/// What an answer asks the engineer to look at before trusting it.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct Warning {
    /// What kind of warning.
    pub code: WarningCode,
    /// The warning in words.
    pub message: String,
    /// The slices it speaks of (from 1 at the toe end).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub slices: Vec<usize>,
    /// The inter-slice boundaries it speaks of (boundary i between slices i and i + 1).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub boundaries: Vec<usize>,
    /// The interfaces it speaks of (from 1).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub interfaces: Vec<usize>,
}

/// The kinds of warning.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum WarningCode {
    /// Spencer's equations have no root for the surface.
    NoSolution,
    /// φ' = 0 with no parallel inter-slice forces: F from moments alone.
    MomentOnly,
    /// The equations' root is not physical; no F is reported.
    Unphysical,
    /// m_α small at some slices: their base forces are sensitive to F.
    SmallMAlpha,
    /// Negative effective normal force (tension) at some bases.
    Tension,
    /// Spencer's F lies more than 15 % below Bishop's on the same circle.
    FarBelowBishop,
    /// The inter-slice forces are inclined more than 60° from the horizontal.
    SteepInterslice,
    /// Bases in tension had their strength dropped and the equations were solved again.
    TensionDropped,
    /// The line of thrust leaves the sliding mass at some boundaries.
    ThrustLineOutside,
    /// `slice_tolerance` was not reached before the slice limit.
    SliceToleranceNotReached,
    /// The critical centre lies on the edge of the search region.
    MinimumOnBound,
    /// A budget ended the non-circular search: its best so far.
    BudgetExhausted,
    /// Surfaces without a Spencer solution have a Bishop F below the minimum found.
    UnsolvedBelowMinimum,
    /// Surfaces next to the critical one have no Spencer solution.
    UnsolvedNearMinimum,
    /// The surface runs beyond the ground as stated (taken level there).
    BeyondGround,
    /// The searched surface reaches the end of the section as stated.
    MinimumAtSectionEnd,
    /// The circle cuts the ground into several masses: one is analysed.
    SeveralMasses,
    /// The non-associative friction iteration did not settle.
    NotSettled,
    /// Nonlinear strength envelopes did not reach a consistent state.
    StrengthNotConsistent,
    /// Bases lie outside the pore-pressure grid (u = 0 taken there).
    OutsidePorePressureGrid,
    /// Supports cross a tension crack's face but not the slip surface: they hold nothing.
    SupportCrossesCrack,
    /// Associative friction may over-estimate the collapse load.
    FrictionMayOverestimate,
    /// Samples of a study without an answer (counted apart: neither safe nor failed).
    SamplesUnsolved,
    /// Samples of a study whose values the route refuses (left out of its statistics).
    SamplesRefused,
    /// Rings that cannot slip lock: the answer is unbounded, or far above one ring's.
    RingsLocked,
    /// Rings slide on each other at collapse on friction alone: the mortar's cohesion is left
    /// out.
    RingsSlide,
}

impl Warning {
    /// A warning with no indices.
    pub fn new(code: WarningCode, message: impl Into<String>) -> Self {
        Self {
            code,
            message: message.into(),
            slices: Vec::new(),
            boundaries: Vec::new(),
            interfaces: Vec::new(),
        }
    }

    /// The same warning about `slices` (numbered from 1).
    pub fn slices(mut self, slices: Vec<usize>) -> Self {
        self.slices = slices;
        self
    }

    /// The same warning about `boundaries`.
    pub fn boundaries(mut self, boundaries: Vec<usize>) -> Self {
        self.boundaries = boundaries;
        self
    }

    /// The same warning about `interfaces` (numbered from 1).
    pub fn interfaces(mut self, interfaces: Vec<usize>) -> Self {
        self.interfaces = interfaces;
        self
    }
}

/// Indices from 0 as the answers number them, from 1.
pub fn one_based(indices: &[usize]) -> Vec<usize> {
    indices.iter().map(|i| i + 1).collect()
}

/// Numbers as a message lists them: "1, 2, 3".
pub fn listed(numbers: &[usize]) -> String {
    numbers
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}
