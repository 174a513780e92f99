//! Spencer's method as a [`Family`]: the request validated into its plan and studies, the
//! analysis and the studies on the pool, the answer with the details `include` keeps, the
//! drawing, the tables and the report.

use std::sync::Arc;

use serde_json::Value;

use super::drawing;
use super::request::SpencerRequest;
use super::response::SpencerResponse;
use super::solve::{prepare, run, Prepared};
use super::solved::SolvedSlope;
use super::tables::{slope_table, SlopeTableDto, SlopeTableQuery};
use crate::error::ApiError;
use crate::family::{Family, ReportParts};
use crate::report::table;
use crate::state::AppState;
use crate::study::run::Tally;
use crate::table::Csv;

/// `POST /slope/spencer` and its twins.
pub struct Spencer;

impl Family for Spencer {
    type Request = SpencerRequest;
    type Prepared = Prepared;
    type Solved = SolvedSlope;
    type Answer = SpencerResponse;
    type Tables = SlopeTableQuery;

    const ROUTE: &'static str = "/slope/spencer";
    const STREAMS: bool = true;

    fn prepare(request: &SpencerRequest, body: &Value) -> Result<Prepared, ApiError> {
        prepare(request, body)
    }

    async fn run(
        state: &AppState,
        prepared: Prepared,
        tally: Arc<Tally>,
    ) -> Result<SolvedSlope, ApiError> {
        run(state, prepared, tally).await
    }

    fn answer(request: &SpencerRequest, solved: &SolvedSlope) -> SpencerResponse {
        SpencerResponse::new(solved).with_details(request.include.as_deref())
    }

    fn draw(_request: &SpencerRequest, solved: &SolvedSlope) -> Result<String, ApiError> {
        Ok(drawing::draw(solved, drawing::title(solved)))
    }

    fn table(answer: &SpencerResponse, table: SlopeTableDto) -> Result<Csv, ApiError> {
        slope_table(answer, table)
    }

    fn report<'a>(
        _request: &SpencerRequest,
        solved: &SolvedSlope,
        answer: &'a SpencerResponse,
    ) -> Option<ReportParts<'a>> {
        let title = drawing::title(solved);
        let headline = match (answer.factor_of_safety, answer.theta_deg) {
            (Some(f), Some(theta)) => format!("{title}: F = {f:.4}, θ = {theta:.2}°"),
            (Some(f), None) => format!("{title}: F = {f:.4} (moment equation only)"),
            _ => format!("{title}: no factor of safety"),
        };
        Some(ReportParts {
            headline,
            drawing: drawing::draw(solved, title),
            warnings: &answer.warnings,
            tables: vec![table("Slices", &answer.slices)],
            subject: "slope stability by Spencer's method",
        })
    }
}
