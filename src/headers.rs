//! Response headers every answer carries, and the bound on a client's request id.
//!
//! - `X-Content-Type-Options: nosniff` on every answer; `Cache-Control: no-store` on computed
//!   answers (POST); on the page (`/`, which has a token field) and `/docs`, a
//!   `Content-Security-Policy` that keeps everything on this origin and forbids framing.
//! - A client's `x-request-id` longer than [`MAX_REQUEST_ID`] bytes, or with characters other
//!   than visible ASCII, is replaced by one of the service's (it is echoed and logged).

use axum::body::Body;
use axum::extract::{FromRequestParts, Request};
use axum::http::request::Parts;
use axum::http::{header, HeaderValue, Method, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

use crate::error::ApiError;

/// Longest client request id kept, in bytes.
pub const MAX_REQUEST_ID: usize = 128;

const PAGE_POLICY: &str = "default-src 'self'; script-src 'self' 'unsafe-inline'; \
     style-src 'self' 'unsafe-inline'; img-src 'self' blob: data:; connect-src 'self'; \
     frame-ancestors 'none'; base-uri 'none'; form-action 'none'";

/// A calculation report runs no script and fetches nothing: inline style only.
const REPORT_POLICY: &str = "default-src 'none'; style-src 'unsafe-inline'; \
     frame-ancestors 'none'; base-uri 'none'; form-action 'none'";

/// Drops an over-long or unprintable `x-request-id`, so that a fresh one is made.
pub async fn bound_request_id(mut request: Request, next: Next) -> Response {
    let keep = request.headers().get("x-request-id").is_none_or(|v| {
        v.len() <= MAX_REQUEST_ID && v.as_bytes().iter().all(|b| (0x21..=0x7e).contains(b))
    });
    if !keep {
        request.headers_mut().remove("x-request-id");
    }
    next.run(request).await
}

/// Refuses, before any of the body is read, what the service cannot take: a compressed body
/// (415: it reads JSON as sent, no `Content-Encoding`), and a `Content-Length` over the body
/// limit (413 — also before `Expect: 100-continue` is answered with 100).
pub async fn refuse_early(
    axum::extract::State(body_limit): axum::extract::State<usize>,
    request: Request,
    next: Next,
) -> Response {
    let headers = request.headers();
    let encoded = headers
        .get(header::CONTENT_ENCODING)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| !v.trim().eq_ignore_ascii_case("identity"));
    if encoded {
        return ApiError::BadRequest {
            status: StatusCode::UNSUPPORTED_MEDIA_TYPE,
            detail: "compressed request bodies are not accepted: send the JSON as it is \
                     (no Content-Encoding)"
                .to_owned(),
            field: None,
        }
        .into_response();
    }
    let length = headers
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.trim().parse::<u64>().ok());
    if length.is_some_and(|n| n > body_limit as u64) {
        return ApiError::BadRequest {
            status: StatusCode::PAYLOAD_TOO_LARGE,
            detail: format!("the body is larger than the limit of {body_limit} bytes"),
            field: None,
        }
        .into_response();
    }
    next.run(request).await
}

/// Adds the security and caching headers.
pub async fn security_headers(request: Request, next: Next) -> Response {
    let computed = request.method() == Method::POST;
    let path = request.uri().path().to_owned();
    let mut response = next.run(request).await;
    let headers = response.headers_mut();
    headers.insert(
        header::X_CONTENT_TYPE_OPTIONS,
        HeaderValue::from_static("nosniff"),
    );
    if computed {
        headers.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    }
    if path == "/" || path == "/docs" || path.starts_with("/docs/") {
        headers.insert(
            header::CONTENT_SECURITY_POLICY,
            HeaderValue::from_static(PAGE_POLICY),
        );
        headers.insert(header::X_FRAME_OPTIONS, HeaderValue::from_static("DENY"));
    } else if path.ends_with("/report") {
        // A report runs nothing and loads nothing: its style is inline, its drawing inline SVG.
        headers.insert(
            header::CONTENT_SECURITY_POLICY,
            HeaderValue::from_static(REPORT_POLICY),
        );
        headers.insert(header::X_FRAME_OPTIONS, HeaderValue::from_static("DENY"));
    }
    response
}

/// Problem bodies carry the request's id as `instance` (SPEC §6.1): the id the response is
/// answered with, so that a client can quote it and an operator find the request in the log.
pub async fn problem_instance(request: Request, next: Next) -> Response {
    let response = next.run(request).await;
    let is_problem = response
        .headers()
        .get(header::CONTENT_TYPE)
        .is_some_and(|v| v.as_bytes() == crate::error::PROBLEM_JSON.as_bytes());
    let id = response
        .headers()
        .get("x-request-id")
        .and_then(|v| v.to_str().ok())
        .map(str::to_owned);
    let Some(id) = id.filter(|_| is_problem) else {
        return response;
    };
    let (mut parts, body) = response.into_parts();
    // Problem bodies are small (their detail is cut at 600 characters).
    let Ok(bytes) = axum::body::to_bytes(body, 1 << 20).await else {
        return Response::from_parts(parts, Body::empty());
    };
    let mut problem: serde_json::Value = match serde_json::from_slice(&bytes) {
        Ok(value) => value,
        Err(_) => return Response::from_parts(parts, Body::from(bytes)),
    };
    if let Some(object) = problem.as_object_mut() {
        object.insert("instance".to_owned(), serde_json::Value::String(id));
    }
    let body = serde_json::to_vec(&problem).unwrap_or_else(|_| bytes.to_vec());
    parts.headers.remove(header::CONTENT_LENGTH);
    Response::from_parts(parts, Body::from(body))
}

/// The request's id (`x-request-id`, set or kept by the service before any handler runs).
#[derive(Debug)]
pub struct RequestId(pub String);

impl<S: Send + Sync> FromRequestParts<S> for RequestId {
    type Rejection = std::convert::Infallible;

    async fn from_request_parts(parts: &mut Parts, _: &S) -> Result<Self, Self::Rejection> {
        let id = parts
            .headers
            .get("x-request-id")
            .and_then(|v| v.to_str().ok())
            .unwrap_or("-");
        Ok(Self(id.to_owned()))
    }
}
