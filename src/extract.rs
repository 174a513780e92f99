//! The request body as the handlers take it: [`ApiJson`], JSON whose objects have no key twice,
//! read into the request type with the path of any error, its rejections problem+json in the
//! project's words (no framework prefix, Rust's type names as JSON's).

use axum::extract::rejection::JsonRejection;
use axum::extract::FromRequest;
use axum::http::StatusCode;
use axum::response::{IntoResponse, Response};
use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::error::ApiError;

impl From<JsonRejection> for ApiError {
    fn from(rejection: JsonRejection) -> Self {
        let status = match &rejection {
            // Wrong types, missing or unknown fields: the body is JSON but not this request.
            JsonRejection::JsonDataError(_) => StatusCode::UNPROCESSABLE_ENTITY,
            JsonRejection::JsonSyntaxError(_) => StatusCode::BAD_REQUEST,
            JsonRejection::MissingJsonContentType(_) => StatusCode::UNSUPPORTED_MEDIA_TYPE,
            other => other.status(),
        };
        let detail = bounded(joined_paths(without_prefix(&in_plain_words(
            &rejection.body_text(),
        ))));
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

/// The field path serde reports in a data error ("slope.foo: unknown field…"). A missing field,
/// or a key given twice, is named by its full path ("slope: missing field `height`…").
/// Paths a geometry object reports inside itself follow its own ("geometry: blocks[1].corners:
/// …"): they are joined.
fn data_error_field(detail: &str) -> Option<String> {
    let (segments, message) = path_segments(detail);
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

/// serde's message with nested paths joined: "geometry.blocks[1].corners: …".
fn joined_paths(message: String) -> String {
    let (segments, rest) = path_segments(&message);
    if segments.len() < 2 {
        return message;
    }
    format!("{}: {rest}", segments.join("."))
}

/// axum's words before serde's message, and the project's for them (none: the message names
/// the field itself).
const FRAMEWORK_PREFIXES: [(&str, &str); 3] = [
    (
        "Failed to deserialize the JSON body into the target type: ",
        "",
    ),
    (
        "Failed to parse the request body as JSON: ",
        "the body is not JSON: ",
    ),
    (
        "Failed to buffer the request body: ",
        "the body could not be read: ",
    ),
];

/// A rejection's text in the project's words: the framework's prefix replaced.
pub fn without_prefix(text: &str) -> String {
    FRAMEWORK_PREFIXES
        .iter()
        .find_map(|(theirs, ours)| {
            text.strip_prefix(theirs)
                .map(|rest| format!("{ours}{rest}"))
        })
        .unwrap_or_else(|| text.to_owned())
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
        Ok(Self(read(request, state).await?.0))
    }
}

/// [`ApiJson`] that keeps the body as the client wrote it beside the request read from it: a
/// study's variables are paths into what the client wrote (a field left out and the same
/// field given as null may mean different things, so the request serialised back will not do).
#[derive(Debug)]
pub struct ApiJsonWithBody<T> {
    /// The request.
    pub request: T,
    /// The body as sent (an object).
    pub body: serde_json::Value,
}

impl<T, S> FromRequest<S> for ApiJsonWithBody<T>
where
    T: DeserializeOwned + Serialize,
    S: Send + Sync,
{
    type Rejection = ApiError;

    async fn from_request(request: axum::extract::Request, state: &S) -> Result<Self, ApiError> {
        let (request, body) = read(request, state).await?;
        Ok(Self { request, body })
    }
}

/// The body read as [`ApiJson`] reads it, with the JSON it was read from.
async fn read<T, S>(
    request: axum::extract::Request,
    state: &S,
) -> Result<(T, serde_json::Value), ApiError>
where
    T: DeserializeOwned + Serialize,
    S: Send + Sync,
{
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
        let detail = bounded(joined_paths(in_plain_words(&e.to_string())));
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
    Ok((typed, value))
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
