//! The operational routes: `GET /healthz` (the service is up and can take solves), `GET /metrics`
//! (the counters of `metrics` in Prometheus' text format) and the middleware that counts every
//! answered request.

use axum::extract::{MatchedPath, Request, State};
use axum::http::{header, HeaderValue, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::{Json, Router};
use serde::Serialize;
use utoipa::ToSchema;

use crate::state::AppState;

/// Liveness and readiness of the service.
#[derive(Debug, Serialize, ToSchema)]
pub struct Health {
    /// Always `"ok"` when the service answers.
    #[schema(examples("ok"))]
    pub status: &'static str,
    /// Version of the service.
    #[schema(examples("0.1.0"))]
    pub version: &'static str,
    /// Solves running right now.
    pub running_solves: usize,
    /// Solves waiting for a worker right now.
    pub queued_solves: usize,
}

/// Liveness and readiness probe.
///
/// Answers 200 while the service can take solves; needs no token even when one is set.
#[utoipa::path(
    get,
    path = "/healthz",
    tag = "service",
    security(()),
    responses((status = 200, description = "The service can serve", body = Health))
)]
pub async fn healthz(State(state): State<AppState>) -> (StatusCode, Json<Health>) {
    (
        StatusCode::OK,
        Json(Health {
            status: "ok",
            version: env!("CARGO_PKG_VERSION"),
            running_solves: state.pool.running(),
            queued_solves: state.pool.queue_depth(),
        }),
    )
}

/// Connections served beyond the connection cap, for `/healthz` alone: 1,024 silent sockets
/// locked every client out, the liveness probe included.
pub const RESERVED_CONNECTIONS: usize = 16;

/// What a connection beyond the cap is served: `/healthz`, and 503 with `Retry-After` for
/// every other request.
pub fn reserved_app(state: AppState) -> Router {
    Router::new()
        .route("/healthz", get(healthz))
        .fallback(at_connection_cap)
        .with_state(state)
}

async fn at_connection_cap() -> impl IntoResponse {
    let problem = serde_json::json!({
        "type": "about:blank",
        "title": "Service Unavailable",
        "status": 503,
        "detail": "the service is at its connection cap: retry, or reuse a connection",
        "code": "busy",
    });
    (
        StatusCode::SERVICE_UNAVAILABLE,
        [
            (header::CONTENT_TYPE, "application/problem+json"),
            (header::RETRY_AFTER, "1"),
            (header::CONNECTION, "close"),
        ],
        problem.to_string(),
    )
}

/// Counts every answered request under its route template (not the raw path: bounded labels).
pub async fn count_requests(
    State(state): State<AppState>,
    request: Request,
    next: Next,
) -> Response {
    let route = request
        .extensions()
        .get::<MatchedPath>()
        .map_or_else(|| "unmatched".to_owned(), |p| p.as_str().to_owned());
    let response = next.run(request).await;
    state
        .metrics
        .observe_request(&route, response.status().as_u16());
    response
}

/// Prometheus metrics of this instance.
///
/// Requests by route and status, the solve-time histogram, solves running and waiting, in the
/// Prometheus text format.
#[utoipa::path(
    get,
    path = "/metrics",
    tag = "service",
    responses(
        (status = 200, description = "Prometheus text exposition format 0.0.4", body = String, content_type = "text/plain"),
        (status = 401, description = "THRUSTLINE_TOKEN is set and the request has no `Authorization: Bearer` with it", body = crate::error::Problem, content_type = "application/problem+json"),
    )
)]
pub async fn metrics(State(state): State<AppState>) -> Response {
    let text = state
        .metrics
        .render(state.pool.running(), state.pool.queue_depth());
    let mut response = text.into_response();
    response.headers_mut().insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static("text/plain; version=0.0.4; charset=utf-8"),
    );
    response
}
