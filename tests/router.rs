//! The router built by `app(state)`, called in process with `oneshot` (no socket).

// Test scaffolding: a failed request should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use axum::body::Body;
use axum::http::{Request, StatusCode};
use http_body_util::BodyExt;
use tower::ServiceExt;

fn router() -> axum::Router {
    let settings = thrustline::Settings::default();
    thrustline::app(thrustline::AppState::new(&settings), &settings)
}

async fn call(request: Request<Body>) -> (StatusCode, String, serde_json::Value) {
    let response = router().oneshot(request).await.unwrap();
    let status = response.status();
    let content_type = response
        .headers()
        .get("content-type")
        .map(|v| v.to_str().unwrap().to_owned())
        .unwrap_or_default();
    let bytes = response.into_body().collect().await.unwrap().to_bytes();
    (
        status,
        content_type,
        serde_json::from_slice(&bytes).unwrap_or(serde_json::Value::Null),
    )
}

#[tokio::test]
async fn healthz_in_process() {
    let (status, _, body) = call(Request::get("/healthz").body(Body::empty()).unwrap()).await;
    assert_eq!(status, StatusCode::OK);
    assert_eq!(body["status"], "ok");
}

#[tokio::test]
async fn spencer_example_in_process() {
    // Thesis §5.6, N = 100: F = 1.06958 (half a unit in the last printed digit).
    let body = common::spencer_example();
    let request = Request::post("/slope/spencer")
        .header("content-type", "application/json")
        .body(Body::from(body.to_string()))
        .unwrap();
    let (status, content_type, body) = call(request).await;
    assert_eq!(status, StatusCode::OK);
    assert_eq!(content_type, "application/json");
    assert!((body["factor_of_safety"].as_f64().unwrap() - 1.06958).abs() <= 5e-6);
}

#[tokio::test]
async fn wrong_method_and_missing_route_in_process() {
    let (status, content_type, _) =
        call(Request::get("/nowhere").body(Body::empty()).unwrap()).await;
    assert_eq!(
        (status, content_type.as_str()),
        (StatusCode::NOT_FOUND, "application/problem+json")
    );
    let (status, content_type, body) =
        call(Request::get("/slope/spencer").body(Body::empty()).unwrap()).await;
    assert_eq!(
        (status, content_type.as_str()),
        (StatusCode::METHOD_NOT_ALLOWED, "application/problem+json")
    );
    assert!(body["detail"].as_str().unwrap().contains("GET"));
}
