//! `GET /healthz`: the service is up and can take solves.

use axum::extract::State;
use axum::http::StatusCode;
use axum::Json;
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
