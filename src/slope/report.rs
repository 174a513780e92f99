//! `POST /slope/spencer/report`: the Spencer answer as a printable HTML calculation report.

use axum::extract::State;

use super::drawing;
use super::request::SpencerRequest;
use super::response::SpencerResponse;
use super::solve::solve;
use crate::error::{ApiError, ProblemResponses};
use crate::extract::ApiJsonWithBody;
use crate::headers::RequestId;
use crate::report::{table, without_nulls, Report};
use crate::state::AppState;
use axum::response::Html;

/// The Spencer answer as a printable calculation report.
///
/// The same request and solve as `/slope/spencer`, answered as one self-contained HTML page
/// (nothing fetched): the result and every scalar of the JSON answer, the warnings, the drawing,
/// the slices (the first 200), the inputs as read, the service's version, the request id and
/// the date. Print it, or save it with the calculation.
#[utoipa::path(
    post,
    path = "/slope/spencer/report",
    tag = "slope",
    request_body = SpencerRequest,
    responses(
        (status = 200, description = "The report, one HTML page", body = String, content_type = "text/html"),
        ProblemResponses,
    )
)]
pub async fn spencer_report(
    State(state): State<AppState>,
    RequestId(request_id): RequestId,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<SpencerRequest>,
) -> Result<Html<String>, ApiError> {
    let solved = solve(&state, (&request, &body), Default::default()).await?;
    let answer = SpencerResponse::new(&solved).with_details(request.include.as_deref());
    let title = drawing::title(&solved);
    let headline = match (answer.factor_of_safety, answer.theta_deg) {
        (Some(f), Some(theta)) => format!("{title}: F = {f:.4}, θ = {theta:.2}°"),
        (Some(f), None) => format!("{title}: F = {f:.4} (moment equation only)"),
        _ => format!("{title}: no factor of safety"),
    };
    let report = Report {
        route: "/slope/spencer",
        headline,
        request_id,
        request: without_nulls(&serde_json::to_value(&request).unwrap_or_default()),
        answer: serde_json::to_value(&answer).unwrap_or_default(),
        warnings: &answer.warnings,
        drawing: drawing::draw(&solved, title),
        tables: vec![table("Slices", &answer.slices)],
    };
    Ok(report.html("slope stability by Spencer's method"))
}
