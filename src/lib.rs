//! thrustline, the HTTP service: limit analysis of masonry arches (Livesley 1978) and of
//! embankments by Spencer's method (1967/1973).
//!
//! This crate only translates: JSON request → validated solver input → solve on a bounded
//! blocking pool → JSON response, and solver or request errors → problem+json. The numerics live
//! in `thrustline-solver`.
//!
//! - [`arch`] and [`slope`]: one folder per problem, following the pipeline — `request` (what
//!   clients send) → `input` (the one validation, into the solver's typed inputs) → the solve on
//!   the [`pool`] → `response` (built whole) and `drawing`;
//! - [`limits`] (every size and magnitude limit), [`fields`] (solver parameter → JSON field),
//!   [`error`] (problem+json; the outcome rule of docs/api.md: a solver stopped at the time limit
//!   is 422 naming the field that sets the work when it ran alone, 503 when other solves ran
//!   beside it; capacity and the pool deadline are 503);
//! - [`app`] builds the router (used by `main` and by the tests with `oneshot`);
//! - [`serve`] runs it on a listener until the shutdown future completes.

pub mod arch;
pub mod auth;
pub mod batch;
pub mod body;
pub mod config;
pub mod error;
pub mod extract;
pub mod family;
pub mod fields;
pub mod headers;
pub mod health;
pub mod json;
pub mod limits;
pub mod metrics;
pub mod nullable;
pub mod openapi;
pub mod page;
pub mod pool;
pub mod report;
pub mod routes;
pub mod slope;
pub mod state;
pub mod stop;
pub mod study;
pub mod svg;
pub mod table;
pub mod validation;
pub mod warning;

use std::future::Future;
use std::time::Duration;

use axum::extract::DefaultBodyLimit;
use axum::http::{header, HeaderName, HeaderValue, Method, Request};
use axum::response::IntoResponse;
use axum::routing::{get, post};
use axum::Router;
use tower_http::catch_panic::CatchPanicLayer;
use tower_http::compression::predicate::{NotForContentType, Predicate, SizeAbove};
use tower_http::compression::CompressionLayer;
use tower_http::cors::{AllowOrigin, CorsLayer};
use tower_http::request_id::{
    MakeRequestId, PropagateRequestIdLayer, RequestId, SetRequestIdLayer,
};
use tower_http::trace::TraceLayer;
use utoipa_swagger_ui::SwaggerUi;

pub use config::Settings;
pub use state::AppState;

/// The service's router.
pub fn app(state: AppState, settings: &Settings) -> Router {
    let api = Router::new()
        .route("/", get(page::index))
        .route("/healthz", get(health::healthz))
        .route("/metrics", get(health::metrics))
        .route("/batch", post(batch::batch))
        .merge(routes::solve_routes())
        .with_state(state.clone());
    let request_id = HeaderName::from_static("x-request-id");
    let router = Router::new()
        .merge(
            Router::from(SwaggerUi::new("/docs").url("/openapi.json", openapi::document()))
                .layer(axum::middleware::from_fn(docs_not_found)),
        )
        .merge(api)
        .fallback(not_found)
        .method_not_allowed_fallback(method_not_allowed)
        .layer(axum::middleware::from_fn_with_state(
            state.clone(),
            auth::require_token,
        ))
        // Outside the token check: 401s, unknown paths, the document and the docs count too.
        .layer(axum::middleware::from_fn_with_state(
            state,
            health::count_requests,
        ))
        .layer(DefaultBodyLimit::max(settings.body_limit))
        .layer(axum::middleware::from_fn_with_state(
            settings.body_limit,
            headers::refuse_early,
        ))
        .layer(axum::middleware::from_fn_with_state(
            settings.body_timeout,
            body::body_deadline,
        ))
        .layer(CatchPanicLayer::custom(|_| {
            error::ApiError::Internal("a handler panicked".to_owned()).into_response()
        }))
        .layer(
            TraceLayer::new_for_http()
                .make_span_with(|request: &Request<_>| {
                    let id = request
                        .headers()
                        .get("x-request-id")
                        .and_then(|v| v.to_str().ok())
                        .unwrap_or("-");
                    tracing::info_span!("request", id, method = %request.method(), path = %request.uri().path())
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
        .layer(axum::middleware::from_fn(headers::security_headers))
        .layer(PropagateRequestIdLayer::new(request_id.clone()))
        // Outside the propagation: it reads the id the response carries.
        .layer(axum::middleware::from_fn(headers::problem_instance))
        .layer(SetRequestIdLayer::new(request_id, SequentialRequestId::default()))
        .layer(axum::middleware::from_fn(headers::bound_request_id));
    // gzip, Brotli or zstd as the client accepts, for answers of 1 KiB or more (a 3.26 MB search
    // answer is 0.84 MB gzipped); not for raster images (there are none) or event streams.
    let compression = CompressionLayer::new().compress_when(
        SizeAbove::new(1024)
            .and(NotForContentType::GRPC)
            .and(NotForContentType::IMAGES)
            .and(NotForContentType::SSE)
            // A batch's lines stream as they finish: a compressor would hold them back.
            .and(NotForContentType::const_new(study::stream::NDJSON)),
    );
    let router = router.layer(compression);
    match cors(&settings.cors_origins) {
        Some(cors) => router.layer(cors),
        None => router,
    }
}

/// CORS for the configured origins (`*` for any); `None` when none are configured.
fn cors(origins: &[String]) -> Option<CorsLayer> {
    if origins.is_empty() {
        return None;
    }
    let allow = if origins.iter().any(|o| o == "*") {
        AllowOrigin::any()
    } else {
        AllowOrigin::list(origins.iter().filter_map(|o| HeaderValue::from_str(o).ok()))
    };
    // A dashboard reads Retry-After and the request id, sends its own id, and pays one
    // preflight per 10 minutes, not one per request.
    let request_id = HeaderName::from_static("x-request-id");
    Some(
        CorsLayer::new()
            .allow_origin(allow)
            .allow_methods([Method::GET, Method::POST])
            .allow_headers([
                header::CONTENT_TYPE,
                header::AUTHORIZATION,
                header::ACCEPT,
                request_id.clone(),
            ])
            .expose_headers([header::RETRY_AFTER, request_id])
            .max_age(Duration::from_secs(600)),
    )
}

/// Request ids `<process start in ms>-<counter>`: unique within an instance and across
/// restarts, without a random source.
#[derive(Debug, Clone)]
struct SequentialRequestId {
    prefix: u128,
    next: std::sync::Arc<std::sync::atomic::AtomicU64>,
}

impl Default for SequentialRequestId {
    fn default() -> Self {
        let prefix = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_millis());
        Self {
            prefix,
            next: std::sync::Arc::default(),
        }
    }
}

impl MakeRequestId for SequentialRequestId {
    fn make_request_id<B>(&mut self, _request: &Request<B>) -> Option<RequestId> {
        let n = self.next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        HeaderValue::from_str(&format!("{}-{n}", self.prefix))
            .ok()
            .map(RequestId::new)
    }
}

async fn method_not_allowed(method: Method, uri: axum::http::Uri) -> error::ApiError {
    error::ApiError::BadRequest {
        status: axum::http::StatusCode::METHOD_NOT_ALLOWED,
        detail: format!("{method} is not allowed on {}", uri.path()),
        field: None,
    }
}

async fn not_found(uri: axum::http::Uri) -> error::ApiError {
    error::ApiError::BadRequest {
        status: axum::http::StatusCode::NOT_FOUND,
        detail: format!("no route for {}", uri.path()),
        field: None,
    }
}

/// The documentation UI answers a missing asset (`/docs/<missing>`) with an empty 404: the same
/// problem+json as any unknown path instead.
async fn docs_not_found(
    request: axum::extract::Request,
    next: axum::middleware::Next,
) -> axum::response::Response {
    let uri = request.uri().clone();
    let response = next.run(request).await;
    if response.status() == axum::http::StatusCode::NOT_FOUND
        && !response.headers().contains_key(header::CONTENT_TYPE)
    {
        return not_found(uri).await.into_response();
    }
    response
}

/// Serves `app` on `listener` until `shutdown` completes, then finishes in-flight requests.
pub async fn serve(
    listener: tokio::net::TcpListener,
    settings: Settings,
    shutdown: impl Future<Output = ()> + Send + 'static,
) -> std::io::Result<()> {
    let state = AppState::new(&settings);
    let reserved = health::reserved_app(state.clone());
    let app = app(state, &settings);
    // HTTP/1.1 with a timer: a client must send a request's head within `header_timeout` of
    // the connection becoming ready for it (so idle keep-alive connections close too).
    let mut http = hyper::server::conn::http1::Builder::new();
    http.timer(hyper_util::rt::TokioTimer::new())
        .header_read_timeout(settings.header_timeout);
    // Beyond the cap: one request, its head within 250 ms (a probe's comes at once; silent
    // sockets that reach the reserve leave it quickly).
    let mut http_reserved = http.clone();
    http_reserved
        .header_read_timeout(Duration::from_millis(250))
        .keep_alive(false);
    let graceful = hyper_util::server::graceful::GracefulShutdown::new();
    let connections = std::sync::Arc::new(tokio::sync::Semaphore::new(settings.max_connections));
    let reserve = std::sync::Arc::new(tokio::sync::Semaphore::new(health::RESERVED_CONNECTIONS));
    let mut shutdown = std::pin::pin!(shutdown);
    loop {
        let (stream, _) = tokio::select! {
            accepted = listener.accept() => match accepted {
                Ok(accepted) => accepted,
                Err(error) => {
                    // Out of file descriptors and the like: wait, do not spin.
                    tracing::warn!(%error, "accept failed");
                    tokio::time::sleep(Duration::from_millis(50)).await;
                    continue;
                }
            },
            () = &mut shutdown => break,
        };
        // Over the connection cap: /healthz on a reserved connection, else closed at once (the
        // client may retry).
        let (permit, service, http) = match connections.clone().try_acquire_owned() {
            Ok(permit) => (permit, app.clone(), &http),
            Err(_) => match reserve.clone().try_acquire_owned() {
                Ok(permit) => (permit, reserved.clone(), &http_reserved),
                Err(_) => {
                    tracing::warn!("connection refused: at the connection cap");
                    continue;
                }
            },
        };
        let service = hyper_util::service::TowerToHyperService::new(service);
        // No upgrades (no websockets here): a plain connection, which the drain can close.
        let connection = http.serve_connection(hyper_util::rt::TokioIo::new(stream), service);
        let connection = graceful.watch(connection);
        tokio::spawn(async move {
            let _ = connection.await;
            drop(permit);
        });
    }
    drop(listener);
    // The drain after the shutdown signal is bounded: a client that never finishes its request
    // does not keep the process up (the orchestrator would kill it anyway).
    tokio::select! {
        () = graceful.shutdown() => {}
        () = tokio::time::sleep(settings.drain_timeout) => {
            tracing::warn!(
                seconds = settings.drain_timeout.as_secs_f64(),
                "connections still open after the drain time; stopping"
            );
        }
    }
    Ok(())
}
