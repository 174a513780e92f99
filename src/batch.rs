//! `POST /batch`: a fleet of bridges or slopes in one call (SPEC §11). NDJSON in — one
//! `{"route": "/slope/spencer", "body": {...}}` per line — and NDJSON out: one
//! `{"line": 1, "status": 200, "body": {...}}` per line, in the same order, each streamed as
//! soon as it and every line before it are answered. Each line goes through the same route as
//! a request of its own (validation, pool, solve time limit), so its body is exactly the
//! route's answer or problem; the batch as a whole is bounded by its line count, the body limit
//! and `THRUSTLINE_BATCH_TIMEOUT_SECS`, and a client that goes away cancels the lines running.

use std::convert::Infallible;

use axum::body::{Body, Bytes};
use axum::extract::State;
use axum::http::{header, HeaderMap, HeaderValue, Request, StatusCode};
use axum::response::{IntoResponse, Response};
use futures_util::stream::{self, StreamExt};
use serde::{Deserialize, Serialize};
use serde_json::value::RawValue;
use tokio::time::Instant;
use tower::ServiceExt;
use utoipa::ToSchema;

use crate::error::{ApiError, ProblemResponses, PROBLEM_JSON};
use crate::headers::RequestId;
use crate::limits::MAX_BATCH_LINES;
use crate::state::AppState;
use crate::study::stream::NDJSON;

/// A route a batch line may name: the JSON route of a registered family
/// (`crate::routes::FAMILIES`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(transparent)]
pub struct BatchRoute(&'static str);

impl BatchRoute {
    fn path(self) -> &'static str {
        self.0
    }
}

impl<'de> Deserialize<'de> for BatchRoute {
    /// One of the families' routes; any other string is serde's unknown variant, naming them.
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let name = std::borrow::Cow::<str>::deserialize(deserializer)?;
        crate::routes::BATCH_ROUTES
            .iter()
            .find(|route| **route == name)
            .map(|route| Self(route))
            .ok_or_else(|| serde::de::Error::unknown_variant(&name, &crate::routes::BATCH_ROUTES))
    }
}

impl utoipa::PartialSchema for BatchRoute {
    fn schema() -> utoipa::openapi::RefOr<utoipa::openapi::schema::Schema> {
        use utoipa::openapi::schema::{ObjectBuilder, Type};
        ObjectBuilder::new()
            .schema_type(Type::String)
            .description(Some(
                "The routes a batch line may name: the JSON solve routes.",
            ))
            .enum_values(Some(crate::routes::BATCH_ROUTES))
            .into()
    }
}

impl ToSchema for BatchRoute {}

/// One line of a batch: a route and the body a request to it would have.
#[derive(Debug, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct BatchLine {
    /// The route to answer the line as.
    pub route: BatchRoute,
    /// The request body, as the route takes it.
    #[schema(value_type = std::collections::HashMap<String, serde_json::Value>)]
    pub body: Box<RawValue>,
}

/// One line of a batch's answer.
#[derive(Debug, Serialize, ToSchema)]
pub struct BatchAnswer {
    /// The line it answers (from 1; blank lines are not counted).
    pub line: usize,
    /// The HTTP status the route answered the line with.
    pub status: u16,
    /// The route's answer (2xx) or its problem (4xx, 5xx; `instance` is the batch's request id
    /// and the line: `id:line`).
    #[schema(value_type = std::collections::HashMap<String, serde_json::Value>)]
    pub body: Box<RawValue>,
}

/// Answers a fleet of requests, one per NDJSON line, as NDJSON in the same order.
///
/// Each line is `{"route": "/slope/spencer" | "/arch/dead-load" | "/arch/live-load" |
/// "/arch/minimum-thickness", "body": {...}}` and is answered as a request of its own to that
/// route would be: `{"line": n, "status": 200, "body": {...}}`, or the status and problem of a
/// line that is refused (a line that is not such an object is 400 or 422; other lines go on).
/// Lines run beside each other on the solve pool; answers stream in order as they finish.
/// Lines not answered within the batch's time limit (`THRUSTLINE_BATCH_TIMEOUT_SECS`) are 503
/// `over_time_limit`. At most 10,000 lines, within the body limit.
#[utoipa::path(
    post,
    path = "/batch",
    tag = "service",
    request_body(content = BatchLine, content_type = "application/x-ndjson",
        description = "One `BatchLine` per line (NDJSON); blank lines are skipped"),
    responses(
        (status = 200, description = "One `BatchAnswer` per line, in order (NDJSON, streamed)", body = BatchAnswer, content_type = "application/x-ndjson"),
        ProblemResponses,
    )
)]
pub async fn batch(
    State(state): State<AppState>,
    RequestId(id): RequestId,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, ApiError> {
    let lines = read_lines(&headers, &body)?;
    let deadline = Instant::now() + state.batch_time_limit;
    let router = crate::routes::solve_routes().with_state(state.clone());
    let running = state.pool.max_running();
    let limit_secs = state.batch_time_limit.as_secs_f64();
    let answers = stream::iter(lines.into_iter().enumerate())
        .map(move |(i, line)| {
            let (router, id) = (router.clone(), id.clone());
            async move { answer_line(router, &id, i + 1, line, deadline, limit_secs).await }
        })
        .buffered(running)
        .map(Ok::<_, Infallible>);
    Ok((
        [(header::CONTENT_TYPE, HeaderValue::from_static(NDJSON))],
        Body::from_stream(answers),
    )
        .into_response())
}

/// The body's lines, each read as a [`BatchLine`] or the problem it is; the batch itself is
/// refused (415, 400, 422) when it is not NDJSON, not UTF-8, empty or too long.
fn read_lines(
    headers: &HeaderMap,
    body: &Bytes,
) -> Result<Vec<Result<BatchLine, ApiError>>, ApiError> {
    let media = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.split(';').next())
        .map(|v| v.trim().to_ascii_lowercase());
    if !matches!(media.as_deref(), Some(NDJSON | "application/jsonl")) {
        return Err(ApiError::BadRequest {
            status: StatusCode::UNSUPPORTED_MEDIA_TYPE,
            detail: format!(
                "a batch is NDJSON: send it with content-type {NDJSON} (one JSON object per line)"
            ),
            field: None,
        });
    }
    let text = std::str::from_utf8(body).map_err(|e| ApiError::BadRequest {
        status: StatusCode::BAD_REQUEST,
        detail: format!("the batch is not UTF-8 (at byte {})", e.valid_up_to()),
        field: None,
    })?;
    let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    if lines.is_empty() || lines.len() > MAX_BATCH_LINES {
        return Err(ApiError::invalid(
            "body",
            format!(
                "has {} lines: a batch has 1 to {MAX_BATCH_LINES} lines",
                lines.len()
            ),
        ));
    }
    Ok(lines.into_iter().map(read_line).collect())
}

/// A line as a [`BatchLine`], or its problem (400 when it is not JSON, 422 when it is not a
/// batch line), naming the field at fault.
fn read_line(line: &str) -> Result<BatchLine, ApiError> {
    let mut reader = serde_json::Deserializer::from_str(line);
    serde_path_to_error::deserialize(&mut reader).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        let syntax = inner.is_syntax() || inner.is_eof();
        let text = inner.to_string();
        // serde_json ends its messages with where it was: one line has no line to name.
        let text = match text.rfind(" at line ") {
            Some(at) => text[..at].to_owned(),
            None => text,
        };
        let quoted = |prefix: &str| {
            let rest = text.split(prefix).nth(1)?;
            Some(rest.split('`').next()?.to_owned())
        };
        let field = if syntax {
            None
        } else if path != "." {
            Some(path)
        } else {
            quoted("unknown field `").or_else(|| quoted("missing field `"))
        };
        ApiError::BadRequest {
            status: if syntax {
                StatusCode::BAD_REQUEST
            } else {
                StatusCode::UNPROCESSABLE_ENTITY
            },
            detail: format!("the line is not a batch line {{\"route\", \"body\"}}: {text}"),
            field,
        }
    })
}

/// One line answered: sent through the route's own handler unless the batch's time is up.
async fn answer_line(
    router: axum::Router,
    id: &str,
    number: usize,
    line: Result<BatchLine, ApiError>,
    deadline: Instant,
    limit_secs: f64,
) -> Bytes {
    let instance = format!("{id}:{number}");
    let over = || ApiError::BatchOverTime {
        seconds: limit_secs,
    };
    let response = match line {
        Err(problem) => problem.into_response(),
        Ok(_) if Instant::now() >= deadline => over().into_response(),
        Ok(line) => {
            let request = Request::post(line.route.path())
                .header(header::CONTENT_TYPE, "application/json")
                .header("x-request-id", instance.as_str())
                .body(Body::from(line.body.get().to_owned()));
            match request {
                Ok(request) => {
                    match tokio::time::timeout_at(deadline, router.oneshot(request)).await {
                        Ok(Ok(response)) => response,
                        Err(_) => over().into_response(),
                    }
                }
                Err(e) => {
                    ApiError::Internal(format!("a batch line's request: {e}")).into_response()
                }
            }
        }
    };
    encode(number, &instance, response).await
}

/// A route's response as one NDJSON answer line; a problem gets the line's `instance`.
async fn encode(number: usize, instance: &str, response: Response) -> Bytes {
    let mut status = response.status().as_u16();
    let is_problem = response
        .headers()
        .get(header::CONTENT_TYPE)
        .is_some_and(|v| v.as_bytes() == PROBLEM_JSON.as_bytes());
    let bytes = axum::body::to_bytes(response.into_body(), usize::MAX)
        .await
        .unwrap_or_default();
    let mut body: Box<RawValue> = match serde_json::from_slice::<Box<RawValue>>(&bytes) {
        Ok(raw) => raw,
        // A bare 500 has no body: the line says so.
        Err(_) => {
            let fault = ApiError::Internal("a batch line answered no JSON".to_owned());
            tracing::error!(error = %fault, "batch line failed");
            status = fault.status().as_u16();
            fault.problem_raw()
        }
    };
    if is_problem {
        if let Ok(mut problem) = serde_json::from_str::<serde_json::Value>(body.get()) {
            problem["instance"] = serde_json::Value::from(instance);
            if let Ok(raw) = serde_json::value::to_raw_value(&problem) {
                body = raw;
            }
        }
    }
    let answer = BatchAnswer {
        line: number,
        status,
        body,
    };
    let mut out = serde_json::to_vec(&answer).unwrap_or_default();
    out.push(b'\n');
    Bytes::from(out)
}
