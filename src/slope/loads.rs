//! The loads on a section's ground as clients state them: surcharges and line loads, with
//! their action for a design check.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// A vertical pressure on the ground over [x_start, x_end], downward.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SurchargeDto {
    /// Left end.
    pub x_start: f64,
    /// Right end (> x_start).
    pub x_end: f64,
    /// Pressure at x_start, 0 ≤ p ≤ 1e12.
    pub pressure: f64,
    /// Pressure at x_end (linear in between). Defaults to `pressure`.
    #[serde(default)]
    pub pressure_end: Option<f64>,
    /// For a design check: `permanent` or `variable`. Defaults to `permanent`.
    #[serde(default)]
    pub action: Option<super::design::ActionDto>,
    /// For a design check: whether it helps stability. Defaults to false.
    #[serde(default)]
    pub favourable: Option<bool>,
}

/// A force on the ground point above x.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LineLoadDto {
    /// Where it acts.
    pub x: f64,
    /// Horizontal component, positive towards +x. Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub fx: f64,
    /// Vertical component, positive upwards (a weight is negative). Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub fy: f64,
    /// For a design check: `permanent` or `variable`. Defaults to `permanent`.
    #[serde(default)]
    pub action: Option<super::design::ActionDto>,
    /// For a design check: whether it helps stability. Defaults to false.
    #[serde(default)]
    pub favourable: Option<bool>,
}
