//! The service's error type and its problem+json form (RFC 9457).
//!
//! Every error a client can cause comes out as `application/problem+json` with a `detail` that
//! names the offending field and, where there is one, the allowed range. Server faults (a solver
//! panic, a lost worker) are logged once here and answered with a bare 500 that says nothing of
//! the internals.

use axum::extract::rejection::JsonRejection;
use axum::extract::FromRequest;
use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde::de::DeserializeOwned;
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

    /// The HTTP status of this error.
    pub fn status(&self) -> StatusCode {
        match self {
            Self::BadRequest { status, .. } => *status,
            Self::OverTimeLimit { busy: Some(_), .. } => StatusCode::SERVICE_UNAVAILABLE,
            Self::Invalid { .. } | Self::OverTimeLimit { .. } => StatusCode::UNPROCESSABLE_ENTITY,
            Self::Unauthorized => StatusCode::UNAUTHORIZED,
            Self::Overloaded { .. } => StatusCode::SERVICE_UNAVAILABLE,
            Self::TimedOut { .. } => StatusCode::SERVICE_UNAVAILABLE,
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
            detail,
            field,
        }
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        let status = self.status();
        if status.is_server_error()
            && !matches!(
                self,
                Self::Overloaded { .. } | Self::TimedOut { .. } | Self::OverTimeLimit { .. }
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

impl From<JsonRejection> for ApiError {
    fn from(rejection: JsonRejection) -> Self {
        let status = match &rejection {
            // Wrong types, missing or unknown fields: the body is JSON but not this request.
            JsonRejection::JsonDataError(_) => StatusCode::UNPROCESSABLE_ENTITY,
            JsonRejection::JsonSyntaxError(_) => StatusCode::BAD_REQUEST,
            JsonRejection::MissingJsonContentType(_) => StatusCode::UNSUPPORTED_MEDIA_TYPE,
            other => other.status(),
        };
        let detail = bounded(in_plain_words(&rejection.body_text()));
        let field = (status == StatusCode::UNPROCESSABLE_ENTITY)
            .then(|| data_error_field(&detail))
            .flatten();
        Self::BadRequest {
            status,
            detail,
            field,
        }
    }
}

/// The field path serde reports in a data error ("…target type: slope.foo: unknown field…").
/// A missing field, or a key given twice, is named by its full path ("…target type: slope:
/// missing field `height`…").
/// Paths a geometry object reports inside itself follow its own ("geometry: blocks[1].corners:
/// …"): they are joined.
fn data_error_field(detail: &str) -> Option<String> {
    let rest = detail.split_once("target type: ")?.1;
    let (segments, message) = path_segments(rest);
    let path = (!segments.is_empty()).then(|| segments.join("."));
    let missing = message
        .strip_prefix("missing field `")
        .or_else(|| message.strip_prefix(crate::json::DUPLICATE_KEY))
        .and_then(|name| name.split_once('`'))
        .map(|(name, _)| name);
    match (path, missing) {
        (Some(path), Some(name)) => Some(format!("{path}.{name}")),
        (None, Some(name)) => Some(name.to_owned()),
        (Some(path), None) => Some(path),
        (None, None) => None,
    }
}

/// The leading "path: " segments of serde's message (no spaces in a path), and the rest.
fn path_segments(message: &str) -> (Vec<&str>, &str) {
    let mut segments = Vec::new();
    let mut rest = message;
    while let Some((head, tail)) = rest.split_once(": ") {
        if head.is_empty() || head.contains(' ') || head.contains('`') {
            break;
        }
        segments.push(head);
        rest = tail;
    }
    (segments, rest)
}

/// The detail with nested paths joined: "…target type: geometry.blocks[1].corners: …".
fn joined_paths(detail: String) -> String {
    let Some((head, rest)) = detail.split_once("target type: ") else {
        return detail;
    };
    let (segments, message) = path_segments(rest);
    if segments.len() < 2 {
        return detail;
    }
    format!("{head}target type: {}: {message}", segments.join("."))
}

/// Longest `detail` echoed from a client's input, in characters.
const MAX_DETAIL: usize = 600;

/// The detail cut to [`MAX_DETAIL`] characters (it may quote a client's input, which can be
/// megabytes long).
fn bounded(detail: String) -> String {
    match detail.char_indices().nth(MAX_DETAIL) {
        Some((end, _)) => format!("{}… (cut)", &detail[..end]),
        None => detail,
    }
}

/// serde's words for the expected JSON, with Rust's type names replaced by JSON's.
fn in_plain_words(detail: &str) -> String {
    let mut text = detail
        .replace("expected f64", "expected a number")
        .replace("expected usize", "expected a non-negative integer")
        .replace(
            "expected variant identifier",
            "expected an object with `kind`",
        );
    // "expected struct FooDto", "expected internally tagged enum FooDto": an object.
    for kind in [
        "expected internally tagged enum ",
        "expected struct ",
        "expected enum ",
    ] {
        while let Some(start) = text.find(kind) {
            let name_start = start + kind.len();
            let name_end = text[name_start..]
                .find(|c: char| !c.is_alphanumeric() && c != '_')
                .map_or(text.len(), |i| name_start + i);
            text.replace_range(start..name_end, "expected an object");
        }
    }
    text
}

/// `axum::Json` whose rejections are problem+json, and which takes an object only where the
/// request type has one: serde reads a struct from a JSON array too (`"interface_limits":
/// [null, null]` as q_min = null, tension allowed), which changes the physics. The body is read
/// as JSON, deserialised with the path of any error, and compared with the request as it
/// serialises back: an array where the request has an object is 422 naming it.
#[derive(Debug)]
pub struct ApiJson<T>(pub T);

impl<T, S> FromRequest<S> for ApiJson<T>
where
    T: DeserializeOwned + Serialize,
    S: Send + Sync,
{
    type Rejection = ApiError;

    async fn from_request(request: axum::extract::Request, state: &S) -> Result<Self, ApiError> {
        // Read with every object's keys checked: a key given twice is 422 naming it.
        let axum::Json(crate::json::UniqueKeys(value)) =
            axum::Json::<crate::json::UniqueKeys>::from_request(request, state).await?;
        if !value.is_object() {
            return Err(ApiError::BadRequest {
                status: StatusCode::UNPROCESSABLE_ENTITY,
                detail: format!("body: expected a JSON object, found {}", json_kind(&value)),
                field: Some("body".to_owned()),
            });
        }
        let typed: T = serde_path_to_error::deserialize(&value).map_err(|e| {
            let detail = bounded(joined_paths(in_plain_words(&format!(
                "Failed to deserialize the JSON body into the target type: {e}"
            ))));
            let field = data_error_field(&detail);
            ApiError::BadRequest {
                status: StatusCode::UNPROCESSABLE_ENTITY,
                detail,
                field,
            }
        })?;
        if let Ok(back) = serde_json::to_value(&typed) {
            // The body itself is an object (checked above): the path is never empty.
            if let Some(field) = array_for_object(&value, &back, String::new()) {
                return Err(ApiError::BadRequest {
                    status: StatusCode::UNPROCESSABLE_ENTITY,
                    detail: format!("{field}: expected an object, found an array"),
                    field: Some(field),
                });
            }
        }
        Ok(Self(typed))
    }
}

/// A JSON value's kind in words ("null", "an array", …), for messages.
pub fn json_kind(value: &serde_json::Value) -> &'static str {
    use serde_json::Value;
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// The path of the first array in `input` where `typed` (the request serialised back) has an
/// object.
fn array_for_object(
    input: &serde_json::Value,
    typed: &serde_json::Value,
    path: String,
) -> Option<String> {
    use serde_json::Value;
    match (input, typed) {
        (Value::Array(_), Value::Object(_)) => Some(path),
        (Value::Object(given), Value::Object(back)) => given.iter().find_map(|(key, v)| {
            let inner = if path.is_empty() {
                key.clone()
            } else {
                format!("{path}.{key}")
            };
            back.get(key).and_then(|w| array_for_object(v, w, inner))
        }),
        (Value::Array(given), Value::Array(back)) => given
            .iter()
            .zip(back)
            .enumerate()
            .find_map(|(i, (v, w))| array_for_object(v, w, format!("{path}[{i}]"))),
        _ => None,
    }
}

impl<T: Serialize> IntoResponse for ApiJson<T> {
    fn into_response(self) -> Response {
        axum::Json(self.0).into_response()
    }
}
