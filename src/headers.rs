//! Response headers every answer carries, and the bound on a client's request id.
//!
//! - `X-Content-Type-Options: nosniff` on every answer; `Cache-Control: no-store` on computed
//!   answers (POST); on the page (`/`, which has a token field) and `/docs`, a
//!   `Content-Security-Policy` that keeps everything on this origin and forbids framing.
//! - A client's `x-request-id` longer than [`MAX_REQUEST_ID`] bytes, or with characters other
//!   than visible ASCII, is replaced by one of the service's (it is echoed and logged).

use axum::extract::Request;
use axum::http::{header, HeaderValue, Method};
use axum::middleware::Next;
use axum::response::Response;

/// Longest client request id kept, in bytes.
pub const MAX_REQUEST_ID: usize = 128;

const PAGE_POLICY: &str = "default-src 'self'; script-src 'self' 'unsafe-inline'; \
     style-src 'self' 'unsafe-inline'; img-src 'self' blob: data:; connect-src 'self'; \
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
    }
    response
}
