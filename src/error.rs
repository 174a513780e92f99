//! The service's error type and its problem+json form (RFC 9457).
//!
//! Every error a client can cause comes out as `application/problem+json` with a `detail` that
//! names the offending field and, where there is one, the allowed range. Server faults (a solver
//! panic, a lost worker) are logged once here and answered with a bare 500 that says nothing of
//! the internals.

use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde::Serialize;
use utoipa::ToSchema;

/// Media type of error bodies.
pub const PROBLEM_JSON: &str = "application/problem+json";

/// An RFC 9457 problem details body.
#[derive(Debug, Serialize, ToSchema)]
pub struct Problem {
    /// A URI reference that identifies the problem type (`about:blank` for the plain HTTP meaning).
    #[schema(examples("about:blank"))]
    pub r#type: String,
    /// Short summary of the problem type.
    #[schema(examples("Unprocessable Content"))]
    pub title: String,
    /// The HTTP status code.
    #[schema(examples(422))]
    pub status: u16,
    /// What went wrong, naming the offending field and the allowed range.
    #[schema(examples("slices = 0 is out of range: an integer 1 ≤ slices ≤ 10000"))]
    pub detail: String,
    /// The offending field as a dotted path into the request body, when there is one.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(examples("slices"))]
    pub field: Option<String>,
    /// What kind of problem, for programs (the `detail` is for people).
    pub code: ProblemCode,
    /// The request's id (`x-request-id`), to find it in the service's log.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(examples("18c1f0a2b3d-42"))]
    pub instance: Option<String>,
}

/// The kind of a problem (SPEC §6.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ProblemCode {
    /// The body is not JSON.
    InvalidJson,
    /// An object has a key twice.
    DuplicateKey,
    /// A field the request type does not have.
    UnknownField,
    /// A required field is missing.
    MissingField,
    /// A value outside its stated range.
    OutOfRange,
    /// A value of the wrong type or not among the allowed ones.
    InvalidValue,
    /// Values each in range that together state no scene the service can build (a load on a
    /// block that does not exist, a circle that misses the slope, a geometry that does not
    /// close) or that the service will not take on (too much memory).
    Unstateable,
    /// The analysis asks for more work than one solve may do.
    OverTimeLimit,
    /// The service is busy: retry after `Retry-After`.
    Busy,
    /// The body is larger than the limit.
    TooLarge,
    /// The body is not `application/json` (or is compressed).
    UnsupportedMediaType,
    /// A bearer token is required.
    Unauthorized,
    /// No such route.
    NotFound,
    /// The route does not take this method.
    MethodNotAllowed,
    /// A fault of the server.
    Internal,
}

/// The error answers every solving endpoint documents (problem+json bodies).
#[derive(utoipa::IntoResponses)]
pub enum ProblemResponses {
    /// The body is not JSON.
    #[response(status = 400, content_type = "application/problem+json")]
    BadRequest(Problem),
    /// THRUSTLINE_TOKEN is set and the request has no `Authorization: Bearer` with it.
    #[response(status = 401, content_type = "application/problem+json")]
    Unauthorized(Problem),
    /// The body is larger than the limit.
    #[response(status = 413, content_type = "application/problem+json")]
    PayloadTooLarge(Problem),
    /// The content type is not application/json.
    #[response(status = 415, content_type = "application/problem+json")]
    UnsupportedMediaType(Problem),
    /// A field is missing, unknown or out of range, or the geometry is invalid; the detail and
    /// the `field` member name it.
    #[response(status = 422, content_type = "application/problem+json")]
    Unprocessable(Problem),
    /// At capacity, or the calculation ran out of time: retry after the Retry-After seconds.
    #[response(
        status = 503,
        content_type = "application/problem+json",
        headers(("Retry-After" = u32, description = "Seconds to wait before retrying"))
    )]
    Unavailable(Problem),
}

/// Everything a handler can fail with.
#[derive(Debug, thiserror::Error)]
pub enum ApiError {
    /// The body is not JSON, or not the JSON of this request type.
    #[error("{detail}")]
    BadRequest {
        /// Status to answer with (400, 404, 405, 413, 415 or 422).
        status: StatusCode,
        /// The message for the client.
        detail: String,
        /// The field serde named, for a body that is JSON but not this request.
        field: Option<String>,
    },
    /// The request is well-formed but a value is out of range or inconsistent.
    #[error("{field}: {detail}")]
    Invalid {
        /// Dotted path of the field at fault.
        field: String,
        /// What is wrong with it and what is allowed.
        detail: String,
    },
    /// The bearer token is missing or wrong.
    #[error("missing or invalid bearer token")]
    Unauthorized,
    /// The solve queue is full; try again later.
    #[error("the service is at capacity: {queued} solves are waiting")]
    Overloaded {
        /// Solves already waiting.
        queued: usize,
        /// Seconds until a worker is likely free (the `Retry-After`).
        retry_after: u64,
    },
    /// The solve did not finish within the request's time limit.
    #[error("the calculation did not finish within {seconds} s")]
    TimedOut {
        /// The limit that was exceeded.
        seconds: f64,
        /// Seconds until a worker is likely free (the `Retry-After`).
        retry_after: u64,
    },
    /// The solver stopped itself at the solve time limit. Alone on the pool: the request asks
    /// for more work than one solve may do (422, a limit of the request like the body size);
    /// with other solves beside it (`busy`: the `Retry-After`), 503.
    #[error("{field}: the calculation did not finish within the solve time limit of {seconds} s{}: {advice}", busy.map_or(String::new(), |s| format!(" while the service was busy (retry after {s} s)")))]
    OverTimeLimit {
        /// The field that sets the amount of work.
        field: String,
        /// The solve time limit.
        seconds: f64,
        /// What to change.
        advice: &'static str,
        /// Seconds until a retry is likely to run alone, when other solves ran beside it.
        busy: Option<u64>,
    },
    /// A batch's time limit ran out before a line was answered (503: send the lines left
    /// again).
    #[error("the batch's time limit of {seconds} s (THRUSTLINE_BATCH_TIMEOUT_SECS) ran out before this line was answered: send the lines left in a batch of their own")]
    BatchOverTime {
        /// The batch's time limit.
        seconds: f64,
    },
    /// A fault of the server (a panic in a solve, a lost worker).
    #[error("internal error: {0}")]
    Internal(String),
}

impl ApiError {
    /// A validation failure of `field`.
    pub fn invalid(field: impl Into<String>, detail: impl Into<String>) -> Self {
        Self::Invalid {
            field: field.into(),
            detail: detail.into(),
        }
    }

    /// The problem body as raw JSON (for answers that embed it, like a batch's lines).
    pub fn problem_raw(&self) -> Box<serde_json::value::RawValue> {
        serde_json::value::to_raw_value(&self.problem())
            .unwrap_or_else(|_| serde_json::value::RawValue::NULL.to_owned())
    }

    /// The HTTP status of this error.
    pub fn status(&self) -> StatusCode {
        match self {
            Self::BadRequest { status, .. } => *status,
            Self::OverTimeLimit { busy: Some(_), .. } => StatusCode::SERVICE_UNAVAILABLE,
            Self::Invalid { .. } | Self::OverTimeLimit { .. } => StatusCode::UNPROCESSABLE_ENTITY,
            Self::Unauthorized => StatusCode::UNAUTHORIZED,
            Self::Overloaded { .. } => StatusCode::SERVICE_UNAVAILABLE,
            Self::TimedOut { .. } | Self::BatchOverTime { .. } => StatusCode::SERVICE_UNAVAILABLE,
            Self::Internal(_) => StatusCode::INTERNAL_SERVER_ERROR,
        }
    }

    fn problem(&self) -> Problem {
        let status = self.status();
        let (detail, field) = match self {
            Self::BadRequest { detail, field, .. } => (detail.clone(), field.clone()),
            Self::Invalid { field, detail } => (format!("{field}: {detail}"), Some(field.clone())),
            Self::OverTimeLimit { field, .. } => (self.to_string(), Some(field.clone())),
            Self::Internal(_) => (
                "the server failed to complete the calculation".to_owned(),
                None,
            ),
            other => (other.to_string(), None),
        };
        Problem {
            r#type: "about:blank".to_owned(),
            title: status.canonical_reason().unwrap_or("Error").to_owned(),
            status: status.as_u16(),
            code: self.code(&detail),
            detail,
            field,
            instance: None,
        }
    }

    /// The problem's code; `detail` as answered.
    fn code(&self, detail: &str) -> ProblemCode {
        match self {
            Self::BadRequest { status, .. } => match *status {
                StatusCode::BAD_REQUEST => ProblemCode::InvalidJson,
                StatusCode::PAYLOAD_TOO_LARGE => ProblemCode::TooLarge,
                StatusCode::UNSUPPORTED_MEDIA_TYPE => ProblemCode::UnsupportedMediaType,
                StatusCode::NOT_FOUND => ProblemCode::NotFound,
                StatusCode::METHOD_NOT_ALLOWED => ProblemCode::MethodNotAllowed,
                _ if detail.contains(crate::json::DUPLICATE_KEY) => ProblemCode::DuplicateKey,
                _ if detail.contains("unknown field") => ProblemCode::UnknownField,
                _ if detail.contains("missing field") => ProblemCode::MissingField,
                _ => ProblemCode::InvalidValue,
            },
            // The validation helpers state a range as "… is out of range: allowed is …".
            Self::Invalid { detail, .. } if detail.contains("out of range") => {
                ProblemCode::OutOfRange
            }
            Self::Invalid { .. } => ProblemCode::Unstateable,
            Self::Unauthorized => ProblemCode::Unauthorized,
            Self::Overloaded { .. }
            | Self::TimedOut { .. }
            | Self::OverTimeLimit { busy: Some(_), .. } => ProblemCode::Busy,
            Self::OverTimeLimit { busy: None, .. } | Self::BatchOverTime { .. } => {
                ProblemCode::OverTimeLimit
            }
            Self::Internal(_) => ProblemCode::Internal,
        }
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        let status = self.status();
        if status.is_server_error()
            && !matches!(
                self,
                Self::Overloaded { .. }
                    | Self::TimedOut { .. }
                    | Self::OverTimeLimit { .. }
                    | Self::BatchOverTime { .. }
            )
        {
            // The one place a 5xx is logged; the client gets no internals.
            tracing::error!(error = %self, "request failed");
        }
        let body = serde_json::to_vec(&self.problem()).unwrap_or_default();
        let mut response = (status, body).into_response();
        let headers = response.headers_mut();
        headers.insert(header::CONTENT_TYPE, HeaderValue::from_static(PROBLEM_JSON));
        if let Self::Overloaded { retry_after, .. }
        | Self::TimedOut { retry_after, .. }
        | Self::OverTimeLimit {
            busy: Some(retry_after),
            ..
        } = self
        {
            headers.insert(header::RETRY_AFTER, HeaderValue::from(retry_after.max(1)));
        }
        if matches!(self, Self::Unauthorized) {
            headers.insert(header::WWW_AUTHENTICATE, HeaderValue::from_static("Bearer"));
        }
        response
    }
}
