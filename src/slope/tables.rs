//! The Spencer answer's CSV tables (`POST /slope/spencer/csv?table=`): which tables there are
//! and their columns.

use serde::{Deserialize, Serialize};
use utoipa::{IntoParams, ToSchema};

use super::options::SlopeDetailDto;
use super::outputs::PointDto;
use super::response::{BoundaryThrustPointDto, SliceDto, SpencerResponse};
use crate::error::ApiError;
use crate::table::{csv, Csv, Row, TableQuery};

/// A table of a Spencer answer.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum SlopeTableDto {
    /// `slices`: one row per slice.
    #[default]
    Slices,
    /// `thrust_line`: one row per interior boundary.
    ThrustLine,
    /// `effective_thrust_line`.
    EffectiveThrustLine,
    /// `surface`: the slip surface's points.
    Surface,
    /// `grid` (with `search`): one row per centre, x fastest.
    Grid,
}

/// The query of the Spencer route.
#[derive(Debug, Clone, Copy, Deserialize, IntoParams)]
#[into_params(parameter_in = Query)]
pub struct SlopeTableQuery {
    /// The table to answer with (header row of the JSON field names; lengths, forces and
    /// stresses in the request's units, angles in degrees, empty cells for null). Defaults to
    /// `slices`.
    pub table: Option<SlopeTableDto>,
}

impl TableQuery for SlopeTableQuery {
    type Table = SlopeTableDto;
    fn table(self) -> Option<SlopeTableDto> {
        self.table
    }
}

impl Row for SliceDto {
    const COLUMNS: &'static [&'static str] = &[
        "slice",
        "x_left",
        "x_right",
        "layer",
        "base_inclination_deg",
        "base_length",
        "height",
        "weight",
        "pore_pressure",
        "normal_force",
        "effective_normal_force",
        "shear_force",
        "normal_stress",
        "effective_normal_stress",
        "available_shear_strength",
        "mobilised_shear_strength",
        "interslice_resultant",
        "interslice_force",
        "interslice_normal",
        "interslice_shear",
        "m_alpha",
    ];
}

impl Row for BoundaryThrustPointDto {
    const COLUMNS: &'static [&'static str] = &["boundary", "x", "y", "force", "inside_slice"];
}

impl Row for PointDto {
    const COLUMNS: &'static [&'static str] = &["x", "y"];
}

/// One centre of the search grid.
#[derive(Debug, Clone, Copy, Serialize)]
struct GridRow {
    x: f64,
    y: f64,
    x_absolute: f64,
    y_absolute: f64,
    factor_of_safety: Option<f64>,
}

impl Row for GridRow {
    const COLUMNS: &'static [&'static str] =
        &["x", "y", "x_absolute", "y_absolute", "factor_of_safety"];
}

/// The table of a Spencer answer.
pub fn slope_table(answer: &SpencerResponse, table: SlopeTableDto) -> Result<Csv, ApiError> {
    let detail = match table {
        SlopeTableDto::Slices => SlopeDetailDto::Slices,
        SlopeTableDto::ThrustLine => SlopeDetailDto::ThrustLine,
        SlopeTableDto::EffectiveThrustLine => SlopeDetailDto::EffectiveThrustLine,
        SlopeTableDto::Surface => SlopeDetailDto::Surface,
        SlopeTableDto::Grid => SlopeDetailDto::Grid,
    };
    if answer.omitted.contains(&detail) {
        return Err(ApiError::invalid(
            "table",
            "is a detail that include left out: add it to include, or leave include out",
        ));
    }
    match table {
        SlopeTableDto::Slices => csv(&answer.slices),
        SlopeTableDto::ThrustLine => csv(&answer.thrust_line),
        SlopeTableDto::EffectiveThrustLine => csv(&answer.effective_thrust_line),
        SlopeTableDto::Surface => csv(&answer.surface),
        SlopeTableDto::Grid => {
            let grid = answer.grid.as_ref().ok_or_else(|| {
                ApiError::invalid("table", "grid is the table of a search (give `search`)")
            })?;
            let rows: Vec<GridRow> = grid
                .factor_of_safety
                .iter()
                .enumerate()
                .flat_map(|(j, row)| {
                    row.iter().enumerate().map(move |(i, &f)| GridRow {
                        x: grid.xs[i],
                        y: grid.ys[j],
                        x_absolute: grid.x_absolute[i],
                        y_absolute: grid.y_absolute[j],
                        factor_of_safety: f,
                    })
                })
                .collect();
            csv(&rows)
        }
    }
}
