//! Pore water beyond one piezometric line (model §8): a line with its factor h_u (the section's
//! or a layer's own) and a pore-pressure grid, read into the solver's [`WaterLine`] and
//! [`PoreGrid`].

use thrustline_solver::slope::section::water::GridError;
use thrustline_solver::slope::section::{Hu, PoreGrid, WaterLine};

use super::lines::polyline;
use super::request::water::{AutoDto, HuDto, PiezometricLineDto, PoreGridDto};
use crate::error::ApiError;
use crate::limits::{COORDINATE, HEAD_FACTOR, PORE_GRID_POINTS, SIGNED_STRESS};
use crate::validation::{count_within, within};

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
