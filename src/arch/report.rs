//! `POST /arch/dead-load/report` and `/arch/live-load/report`: the arch answers as printable
//! HTML calculation reports.

use axum::extract::State;

use super::drawing;
use super::request::{DeadLoadRequest, LiveLoadRequest};
use super::response::{ArchOutcomeDto, DeadLoadResponse, LiveLoadResponse};
use super::solve::{solve, Problem};
use crate::error::{ApiError, ProblemResponses};
use crate::extract::{ApiJson, ApiJsonWithBody};
use crate::headers::RequestId;
use crate::report::{table, without_nulls, Report, ReportTable};
use crate::state::AppState;
use axum::response::Html;

/// The tables an arch report prints: hinges, reactions and the line of thrust.
fn tables(outcome: &ArchOutcomeDto) -> Vec<ReportTable> {
    vec![
        table("Hinges", &outcome.hinges),
        table("Reactions", &outcome.reactions),
        table("Line of thrust", &outcome.thrust_line),
    ]
}

/// The dead-load answer as a printable calculation report.
///
/// The same request and solve as `/arch/dead-load`, answered as one self-contained HTML page
/// (nothing fetched): the result and every scalar of the JSON answer, the warnings, the drawing,
/// the hinges, reactions and line of thrust (the first 200 rows), the inputs as read, the
/// service's version, the request id and the date.
#[utoipa::path(
    post,
    path = "/arch/dead-load/report",
    tag = "arch",
    request_body = DeadLoadRequest,
    responses(
        (status = 200, description = "The report, one HTML page", body = String, content_type = "text/html"),
        ProblemResponses,
    )
)]
pub async fn dead_load_report(
    State(state): State<AppState>,
    RequestId(request_id): RequestId,
    ApiJson(request): ApiJson<DeadLoadRequest>,
) -> Result<Html<String>, ApiError> {
    let input = request.validate(state.solve_time_limit_secs())?;
    let solved = solve(&state, Problem::DeadLoad, input).await?;
    let answer = DeadLoadResponse::new(&solved);
    let headline = drawing::dead_load_title(&solved);
    let report = Report {
        route: "/arch/dead-load",
        request_id,
        request: without_nulls(&serde_json::to_value(&request).unwrap_or_default()),
        answer: serde_json::to_value(&answer).unwrap_or_default(),
        warnings: &answer.outcome.warnings,
        drawing: drawing::draw(&solved, &headline),
        tables: tables(&answer.outcome),
        headline,
    };
    Ok(report.html("dead-load limit analysis of a rigid-block arch"))
}

/// The live-load answer as a printable calculation report.
///
/// The same request and solve as `/arch/live-load`, answered as one self-contained HTML page
/// (nothing fetched): the result and every scalar of the JSON answer, the warnings, the drawing,
/// the hinges, reactions and line of thrust (the first 200 rows), λ at each stop of a rolling
/// load, the inputs as read, the service's version, the request id and the date.
#[utoipa::path(
    post,
    path = "/arch/live-load/report",
    tag = "arch",
    request_body = LiveLoadRequest,
    responses(
        (status = 200, description = "The report, one HTML page", body = String, content_type = "text/html"),
        ProblemResponses,
    )
)]
pub async fn live_load_report(
    State(state): State<AppState>,
    RequestId(request_id): RequestId,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<LiveLoadRequest>,
) -> Result<Html<String>, ApiError> {
    let solved = super::study::solve_live(&state, (&request, &body), Default::default()).await?;
    let answer = LiveLoadResponse::new(&solved);
    let headline = drawing::live_load_title(&solved);
    let mut tables = tables(&answer.outcome);
    if let Some(rolling) = &answer.rolling {
        tables.push(super::tables::rolling_table(rolling));
    }
    let report = Report {
        route: "/arch/live-load",
        request_id,
        request: without_nulls(&serde_json::to_value(&request).unwrap_or_default()),
        answer: serde_json::to_value(&answer).unwrap_or_default(),
        warnings: &answer.outcome.warnings,
        drawing: drawing::draw(&solved, &headline),
        tables,
        headline,
    };
    Ok(report.html("live-load limit analysis of a rigid-block arch"))
}
