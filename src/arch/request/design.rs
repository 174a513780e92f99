//! `design` on the live-load request: the partial factors of an arch assessment (wire types;
//! validated and applied by `arch::design`).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// Partial factors of an arch assessment (each 0 < γ ≤ 100; those left out are 1).
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ArchFactorsDto {
    /// γ_d, on the masonry's self weight (`unit_weight`). Defaults to 1.
    #[serde(default)]
    pub dead: Option<f64>,
    /// γ_f, on the fill's weight (`fill.unit_weight`). Defaults to 1.
    #[serde(default)]
    pub fill: Option<f64>,
    /// γ_l, on every live load (`loads`, `road_loads`, `rolling` axles). Defaults to 1.
    #[serde(default)]
    pub live: Option<f64>,
    /// γ_m, dividing the masonry's compressive strength. Defaults to 1.
    #[serde(default)]
    pub strength: Option<f64>,
}

/// A partial-factor check of an arch.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ArchDesignDto {
    /// The factors.
    pub factors: ArchFactorsDto,
}
