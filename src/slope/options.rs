//! Small types of a Spencer request and answer: a point, the details an answer may leave out,
//! the accuracy asked for and answered, and whether a search may answer composite surfaces.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// A point [x, y] of a polyline, in the section's coordinates (y up).
pub type Coordinates = [f64; 2];

/// A detail of the answer that `include` can leave out.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum SlopeDetailDto {
    /// `slices`.
    Slices,
    /// `surface`.
    Surface,
    /// `thrust_line`.
    ThrustLine,
    /// `effective_thrust_line`.
    EffectiveThrustLine,
    /// `grid` (with `search`).
    Grid,
}

impl SlopeDetailDto {
    /// Every detail, in the order of the answer.
    pub const ALL: [Self; 5] = [
        Self::Surface,
        Self::Slices,
        Self::ThrustLine,
        Self::EffectiveThrustLine,
        Self::Grid,
    ];
}

/// The accuracy a request asks for.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct AccuracyDto {
    /// The largest estimated |F(n) − F(∞)|/F accepted, 1e-7 ≤ e ≤ 0.1.
    pub relative_error: f64,
}

/// Whether a circular search may answer composite surfaces (circles that follow the bedrock).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum CompositeDto {
    /// A circle that would cross the bedrock follows it (the default).
    #[default]
    FollowBedrock,
    /// A circle that would cross the bedrock is not a candidate.
    CirclesOnly,
}

/// The accuracy of an answered F (model §6.2).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct AccuracyOutDto {
    /// The slices of the answer.
    pub slices: usize,
    /// The estimated |F(n) − F(∞)|/F: the true error (against 10,000 slices) is at most twice
    /// it (+1e-9) and, where above 1e-7, at least a tenth of it. Null where F at other slice
    /// counts cannot be had (no solution there, loads given per slice, or no time left).
    #[schema(required = true)]
    pub discretisation_error: Option<f64>,
}
