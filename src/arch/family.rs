//! The dead- and live-load analyses as [`Family`]s: the request validated, analysed on the pool
//! (the live load with its studies), and the answers built from the solved arch — the JSON
//! answer, the drawing, the tables and the report.

use std::sync::Arc;

use serde_json::Value;

use super::drawing;
use super::input::ArchInput;
use super::request::{DeadLoadRequest, LiveLoadRequest};
use super::response::{ArchOutcomeDto, DeadLoadResponse, LiveLoadResponse};
use super::solve::solve;
use super::solved::SolvedArch;
use super::study::{prepare_live, run_live, PreparedLive};
use super::tables::{arch_table, rolling_table, ArchTableDto, ArchTableQuery};
use crate::error::ApiError;
use crate::family::{Family, ReportParts};
use crate::report::{table, ReportTable};
use crate::state::AppState;
use crate::study::run::Tally;
use crate::table::Csv;
use thrustline_solver::arch::analysis::ArchPlan;

/// `POST /arch/dead-load` and its twins: Livesley's λ₀.
pub struct DeadLoad;

/// `POST /arch/live-load` and its twins: Livesley's λ, with its studies.
pub struct LiveLoad;

/// The tables an arch report prints: hinges, reactions and the line of thrust.
fn report_tables(outcome: &ArchOutcomeDto) -> Vec<ReportTable> {
    vec![
        table("Hinges", &outcome.hinges),
        table("Reactions", &outcome.reactions),
        table("Line of thrust", &outcome.thrust_line),
    ]
}

impl Family for DeadLoad {
    type Request = DeadLoadRequest;
    type Prepared = (ArchInput, ArchPlan);
    type Solved = SolvedArch;
    type Answer = DeadLoadResponse;
    type Tables = ArchTableQuery;

    const ROUTE: &'static str = "/arch/dead-load";

    fn prepare(
        request: &DeadLoadRequest,
        _body: &Value,
    ) -> Result<(ArchInput, ArchPlan), ApiError> {
        request.validate()
    }

    async fn run(
        state: &AppState,
        (input, plan): (ArchInput, ArchPlan),
        _tally: Arc<Tally>,
    ) -> Result<SolvedArch, ApiError> {
        solve(state, input, plan).await
    }

    fn answer(_request: &DeadLoadRequest, solved: &SolvedArch) -> DeadLoadResponse {
        DeadLoadResponse::new(solved)
    }

    fn draw(_request: &DeadLoadRequest, solved: &SolvedArch) -> Result<String, ApiError> {
        Ok(drawing::draw(solved, &drawing::dead_load_title(solved)))
    }

    fn table(answer: &DeadLoadResponse, table: ArchTableDto) -> Result<Csv, ApiError> {
        arch_table(&answer.outcome, None, table)
    }

    fn report<'a>(
        _request: &DeadLoadRequest,
        solved: &SolvedArch,
        answer: &'a DeadLoadResponse,
    ) -> Option<ReportParts<'a>> {
        let headline = drawing::dead_load_title(solved);
        Some(ReportParts {
            drawing: drawing::draw(solved, &headline),
            headline,
            warnings: &answer.outcome.warnings,
            tables: report_tables(&answer.outcome),
            subject: "dead-load limit analysis of a rigid-block arch",
        })
    }
}

impl Family for LiveLoad {
    type Request = LiveLoadRequest;
    type Prepared = PreparedLive;
    type Solved = SolvedArch;
    type Answer = LiveLoadResponse;
    type Tables = ArchTableQuery;

    const ROUTE: &'static str = "/arch/live-load";
    const STREAMS: bool = true;

    fn prepare(request: &LiveLoadRequest, body: &Value) -> Result<PreparedLive, ApiError> {
        prepare_live(request, body)
    }

    async fn run(
        state: &AppState,
        prepared: PreparedLive,
        tally: Arc<Tally>,
    ) -> Result<SolvedArch, ApiError> {
        run_live(state, prepared, tally).await
    }

    fn answer(_request: &LiveLoadRequest, solved: &SolvedArch) -> LiveLoadResponse {
        LiveLoadResponse::new(solved)
    }

    fn draw(_request: &LiveLoadRequest, solved: &SolvedArch) -> Result<String, ApiError> {
        Ok(drawing::draw(solved, &drawing::live_load_title(solved)))
    }

    fn table(answer: &LiveLoadResponse, table: ArchTableDto) -> Result<Csv, ApiError> {
        arch_table(&answer.outcome, answer.rolling.as_ref(), table)
    }

    fn report<'a>(
        _request: &LiveLoadRequest,
        solved: &SolvedArch,
        answer: &'a LiveLoadResponse,
    ) -> Option<ReportParts<'a>> {
        let headline = drawing::live_load_title(solved);
        let mut tables = report_tables(&answer.outcome);
        if let Some(rolling) = &answer.rolling {
            tables.push(rolling_table(rolling));
        }
        Some(ReportParts {
            drawing: drawing::draw(solved, &headline),
            headline,
            warnings: &answer.outcome.warnings,
            tables,
            subject: "live-load limit analysis of a rigid-block arch",
        })
    }
}
