//! `GET /healthz`: the service is up and can take solves.

use axum::extract::State;
use axum::http::{header, StatusCode};
use axum::response::IntoResponse;
use axum::routing::get;
use axum::{Json, Router};
use serde::Serialize;
use utoipa::ToSchema;

use crate::AppState;

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
