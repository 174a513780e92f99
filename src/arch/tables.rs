//! The arch answers' CSV tables (`POST /arch/dead-load/csv`, `/arch/live-load/csv` and
//! `/arch/minimum-thickness/csv`, `?table=`): which tables there are and their columns.

use serde::{Deserialize, Serialize};
use utoipa::{IntoParams, ToSchema};

use super::mechanism::{ActiveConstraintDto, BlockVelocityDto, HingeDto};
use super::request::ArchDetailDto;
use super::response::{ArchOutcomeDto, InterfaceThrustPointDto, ReactionDto};
use super::rolling::RollingOutDto;
use crate::error::ApiError;
use crate::report::{table, ReportTable};
use crate::table::{csv, Csv, Row, TableQuery};

/// A table of a dead- or live-load answer.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ArchTableDto {
    /// `thrust_line`: one row per interface.
    #[default]
    ThrustLine,
    /// `hinges`.
    Hinges,
    /// `active_constraints`.
    ActiveConstraints,
    /// `reactions`: one row per support contact.
    Reactions,
    /// `mechanism`: one row per block (its velocity).
    Mechanism,
    /// `rolling`: λ at each stop (live load with `rolling` only).
    Rolling,
}

/// The query of a dead- or live-load route.
#[derive(Debug, Clone, Copy, Deserialize, IntoParams)]
#[into_params(parameter_in = Query)]
pub struct ArchTableQuery {
    /// The table to answer with (header row of the JSON field names; lengths, forces and
    /// moments in the request's units, angles in degrees, empty cells for null). Defaults to
    /// `thrust_line`.
    pub table: Option<ArchTableDto>,
}

impl TableQuery for ArchTableQuery {
    type Table = ArchTableDto;
    fn table(self) -> Option<ArchTableDto> {
        self.table
    }
}

/// A table of a minimum-thickness answer.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum MinimumThicknessTableDto {
    /// `hinges` of the mechanism at the limit.
    #[default]
    Hinges,
    /// `active_constraints` at the limit.
    ActiveConstraints,
}

/// The query of the minimum-thickness route.
#[derive(Debug, Clone, Copy, Deserialize, IntoParams)]
#[into_params(parameter_in = Query)]
pub struct MinimumThicknessTableQuery {
    /// The table to answer with (header row of the JSON field names). Defaults to `hinges`.
    pub table: Option<MinimumThicknessTableDto>,
}

impl TableQuery for MinimumThicknessTableQuery {
    type Table = MinimumThicknessTableDto;
    fn table(self) -> Option<MinimumThicknessTableDto> {
        self.table
    }
}

impl Row for InterfaceThrustPointDto {
    const COLUMNS: &'static [&'static str] = &[
        "interface",
        "x",
        "y",
        "normal_force",
        "shear_force",
        "eccentricity",
        "eccentricity_ratio",
        "in_middle_third",
    ];
}

impl Row for HingeDto {
    const COLUMNS: &'static [&'static str] = &[
        "interface",
        "angle_deg",
        "location",
        "x",
        "y",
        "span_distance",
        "span_fraction",
        "rotation",
    ];
}

impl Row for ActiveConstraintDto {
    const COLUMNS: &'static [&'static str] = &[
        "interface",
        "resultant",
        "bound",
        "angle_deg",
        "hinge",
        "multiplier",
    ];
}

impl Row for ReactionDto {
    const COLUMNS: &'static [&'static str] = &["interface", "horizontal", "vertical"];
}

impl Row for BlockVelocityDto {
    const COLUMNS: &'static [&'static str] = &["block", "u", "v", "rotation"];
}

/// One stop of a rolling load.
#[derive(Debug, Clone, Copy, Serialize)]
struct RollingRow {
    position: f64,
    load_factor: Option<f64>,
}

impl Row for RollingRow {
    const COLUMNS: &'static [&'static str] = &["position", "load_factor"];
}

/// λ at each stop of a rolling load.
fn rolling_rows(rolling: &RollingOutDto) -> Vec<RollingRow> {
    rolling
        .positions
        .iter()
        .zip(&rolling.load_factor)
        .map(|(&position, &load_factor)| RollingRow {
            position,
            load_factor,
        })
        .collect()
}

/// The rolling table of a report.
pub fn rolling_table(rolling: &RollingOutDto) -> ReportTable {
    table("λ at each stop of the rolling load", &rolling_rows(rolling))
}

/// The table of a dead- or live-load answer.
pub fn arch_table(
    outcome: &ArchOutcomeDto,
    rolling: Option<&RollingOutDto>,
    table: ArchTableDto,
) -> Result<Csv, ApiError> {
    let detail = match table {
        ArchTableDto::ThrustLine => Some(ArchDetailDto::ThrustLine),
        ArchTableDto::Hinges => Some(ArchDetailDto::Hinges),
        ArchTableDto::ActiveConstraints => Some(ArchDetailDto::ActiveConstraints),
        ArchTableDto::Reactions => Some(ArchDetailDto::Reactions),
        ArchTableDto::Mechanism => Some(ArchDetailDto::Mechanism),
        ArchTableDto::Rolling => None,
    };
    if detail.is_some_and(|d| outcome.omitted.contains(&d)) {
        return Err(ApiError::invalid(
            "table",
            "is a detail that include left out: add it to include, or leave include out",
        ));
    }
    match table {
        ArchTableDto::ThrustLine => csv(&outcome.thrust_line),
        ArchTableDto::Hinges => csv(&outcome.hinges),
        ArchTableDto::ActiveConstraints => csv(&outcome.active_constraints),
        ArchTableDto::Reactions => csv(&outcome.reactions),
        ArchTableDto::Mechanism => match &outcome.mechanism {
            Some(mechanism) => csv(&mechanism.blocks),
            None => csv::<BlockVelocityDto>(&[]),
        },
        ArchTableDto::Rolling => {
            let rolling = rolling.ok_or_else(|| {
                ApiError::invalid("table", "rolling is the table of a live load with rolling")
            })?;
            csv(&rolling_rows(rolling))
        }
    }
}
