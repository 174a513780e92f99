//! Pore water beyond one piezometric line (model §8): a line with its factor h_u (the section's
//! or a layer's own) and a pore-pressure grid, read into the solver's [`WaterLine`] and
//! [`PoreGrid`].

use serde::{Deserialize, Serialize};
use thrustline_solver::slope::section::water::GridError;
use thrustline_solver::slope::section::{Hu, PoreGrid, WaterLine};
use utoipa::ToSchema;

use super::lines::polyline;
use super::request::Coordinates;
use crate::error::ApiError;
use crate::limits::{COORDINATE, HEAD_FACTOR, PORE_GRID_POINTS, SIGNED_STRESS};
use crate::validation::{count_within, within};

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

/// The line at `field` as the solver takes it.
pub fn water_line(field: &str, dto: &PiezometricLineDto) -> Result<WaterLine, ApiError> {
    let (points, hu, at) = match dto {
        PiezometricLineDto::Points(p) => (p, None, field.to_owned()),
        PiezometricLineDto::Line(l) => (&l.points, l.hu, format!("{field}.points")),
    };
    let hu = match hu {
        None => Hu::Factor(1.0),
        Some(HuDto::Auto(AutoDto::Auto)) => Hu::Auto,
        Some(HuDto::Factor(h)) => Hu::Factor(within(&format!("{field}.hu"), h, HEAD_FACTOR)?),
    };
    Ok(WaterLine {
        line: polyline(&at, points)?,
        hu,
    })
}

/// The grid at `section.pore_pressure_grid` as the solver takes it.
pub fn pore_grid(dto: &PoreGridDto) -> Result<PoreGrid, ApiError> {
    let field = "section.pore_pressure_grid.points";
    count_within(field, dto.points.len(), PORE_GRID_POINTS)?;
    let mut points = Vec::with_capacity(dto.points.len());
    for (i, p) in dto.points.iter().enumerate() {
        let at = format!("{field}[{i}]");
        points.push((
            within(&at, p[0], COORDINATE)?,
            within(&at, p[1], COORDINATE)?,
            within(&at, p[2], SIGNED_STRESS)?,
        ));
    }
    PoreGrid::new(points).map_err(|e| match e {
        GridError::TooFew => ApiError::invalid(field, "needs at least 3 points"),
        GridError::Repeated { index } => ApiError::invalid(
            format!("{field}[{index}]"),
            "repeats an earlier point's x and y",
        ),
        GridError::Collinear => ApiError::invalid(
            field,
            "every point lies on one line: no triangle to interpolate over",
        ),
        GridError::Refused { index } => ApiError::invalid(
            format!("{field}[{index}]"),
            "cannot be triangulated (a coordinate beyond the range the triangulation takes)",
        ),
    })
}
