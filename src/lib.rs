//! thrustline, the HTTP service: limit analysis of masonry arches (Livesley 1978) and of
//! embankments by Spencer's method (1967/1973).
//!
//! This crate only translates: JSON request → validated solver input → solve on a bounded
//! blocking pool → JSON response, and solver or request errors → problem+json. The numerics live
//! in `thrustline-solver`.
//!
//! - [`app`] builds the router (used by `main` and by the tests with `oneshot`);
//! - [`serve`] runs it on a listener until the shutdown future completes.

pub mod arch;
pub mod config;
pub mod error;
pub mod health;
pub mod minimum_thickness;
pub mod openapi;
pub mod pool;
pub mod slope;
pub mod validation;

use std::future::Future;
use std::time::Duration;

use axum::extract::DefaultBodyLimit;
use axum::http::Request;
use axum::routing::{get, post};
use axum::Router;
use tower_http::trace::TraceLayer;
use utoipa::OpenApi;
use utoipa_swagger_ui::SwaggerUi;

pub use config::Settings;

/// What every handler shares.
#[derive(Debug, Clone)]
pub struct AppState {
    /// The bounded pool that runs solves.
    pub pool: pool::SolvePool,
    /// Time limit of one solve (the solvers' own limit: `spawn_blocking` cannot be cancelled).
    pub solve_time_limit: std::time::Duration,
}

impl AppState {
    /// State for the given settings.
    pub fn new(settings: &Settings) -> Self {
        Self {
            pool: pool::SolvePool::new(
                settings.max_running,
                settings.max_queued,
                settings.solve_timeout,
            ),
            solve_time_limit: settings.solve_timeout,
        }
    }

    /// The solvers' time limit in seconds.
    pub fn solve_time_limit_secs(&self) -> f64 {
        self.solve_time_limit.as_secs_f64()
    }
}

/// The service's router.
pub fn app(state: AppState, settings: &Settings) -> Router {
    let api = Router::new()
        .route("/healthz", get(health::healthz))
        .route("/slope/spencer", post(slope::spencer))
        .route("/arch/dead-load", post(arch::dead_load))
        .route("/arch/live-load", post(arch::live_load))
        .route(
            "/arch/minimum-thickness",
            post(minimum_thickness::minimum_thickness),
        )
        .with_state(state);
    Router::new()
        .merge(SwaggerUi::new("/docs").url("/openapi.json", openapi::ApiDoc::openapi()))
        .merge(api)
        .fallback(not_found)
        .layer(DefaultBodyLimit::max(settings.body_limit))
        .layer(
            TraceLayer::new_for_http()
                .make_span_with(|request: &Request<_>| {
                    tracing::info_span!("request", method = %request.method(), path = %request.uri().path())
                })
                .on_request(())
                .on_response(|response: &axum::http::Response<_>, latency: Duration, _span: &tracing::Span| {
                    tracing::info!(
                        status = response.status().as_u16(),
                        latency_ms = latency.as_secs_f64() * 1e3,
                        "response"
                    );
                })
                .on_failure(()),
        )
}

async fn not_found(uri: axum::http::Uri) -> error::ApiError {
    error::ApiError::BadRequest {
        status: axum::http::StatusCode::NOT_FOUND,
        detail: format!("no route for {}", uri.path()),
    }
}

/// Serves `app` on `listener` until `shutdown` completes, then finishes in-flight requests.
pub async fn serve(
    listener: tokio::net::TcpListener,
    settings: Settings,
    shutdown: impl Future<Output = ()> + Send + 'static,
) -> std::io::Result<()> {
    let state = AppState::new(&settings);
    axum::serve(listener, app(state, &settings))
        .with_graceful_shutdown(shutdown)
        .await
}
