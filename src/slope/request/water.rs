//! The water of a Spencer request as clients send it: piezometric lines with their factor h_u,
//! a pore-pressure grid and a rapid drawdown's two lines (wire types; validated by
//! `slope::water` and `slope::drawdown`).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::slope::options::Coordinates;

/// `auto`: h_u = cos²α, α the line's inclination above the point (the phreatic-surface
/// correction for flow parallel to the line).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum AutoDto {
    /// cos²α.
    Auto,
}

/// The factor h_u on a line's head: a number 0 ≤ h_u ≤ 1, or `auto`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize, ToSchema)]
#[serde(untagged)]
pub enum HuDto {
    /// u = h_u·γ_w·(y_line − y).
    Factor(f64),
    /// cos²α.
    Auto(AutoDto),
}

/// A piezometric line with its h_u.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct WaterLineDto {
    /// 1 to 1000 points, x strictly increasing.
    #[schema(value_type = Vec<Vec<f64>>)]
    pub points: Vec<Coordinates>,
    /// h_u: a number 0 ≤ h_u ≤ 1 or `auto` (cos²α). Defaults to 1.
    #[serde(default)]
    pub hu: Option<HuDto>,
}

/// A piezometric line: its points, or `{points, hu}`.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(untagged)]
pub enum PiezometricLineDto {
    /// Points [x, y], x strictly increasing; h_u = 1.
    #[schema(value_type = Vec<Vec<f64>>)]
    Points(Vec<Coordinates>),
    /// Points with h_u.
    Line(WaterLineDto),
}

/// Pore pressures at points, interpolated linearly over their Delaunay triangulation (u = 0
/// outside its hull, with the warning `outside_pore_pressure_grid`).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PoreGridDto {
    /// 3 to 10,000 points [x, y, u] (u < 0: suction), not all on one line, none repeated.
    #[schema(value_type = Vec<Vec<f64>>)]
    pub points: Vec<[f64; 3]>,
}

/// A rapid drawdown (Duncan, Wright & Wong 1990, three stages): the water lines before and after
/// it, in place of `piezometric_line`. Soils with an `r_envelope` do not drain: after the
/// drawdown they have the undrained strength of their consolidation before it; the others drain
/// freely.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct DrawdownDto {
    /// The piezometric line before the drawdown (the pool up), 1 to 1000 points.
    #[schema(value_type = Vec<Vec<f64>>)]
    pub before: Vec<Coordinates>,
    /// The piezometric line after it (the pool down), 1 to 1000 points.
    #[schema(value_type = Vec<Vec<f64>>)]
    pub after: Vec<Coordinates>,
}
