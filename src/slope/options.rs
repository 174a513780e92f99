//! Small option types of a Spencer request: the accuracy asked for, and whether a search may
//! answer composite surfaces.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

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
