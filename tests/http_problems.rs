//! Errors are data (SPEC §6.1): every problem+json answer carries a `code` a program can switch
//! on, `instance` = the request id it was answered with, and a `detail` in the project's words
//! (no framework prefix such as "Failed to deserialize the JSON body into the target type").

// Test scaffolding: a failed request should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{spencer_example, Server};
use serde_json::{json, Value};

/// Sends `body` (raw) to `path` with a request id; returns the status and the problem.
async fn problem(
    server: &Server,
    (method, path): (reqwest::Method, &str),
    (content_type, body): (&str, String),
    id: &str,
) -> (u16, Value) {
    let response = server
        .client
        .request(method, format!("{}{path}", server.base))
        .header("content-type", content_type)
        .header("x-request-id", id)
        .body(body)
        .send()
        .await
        .unwrap();
    let status = response.status().as_u16();
    assert_eq!(response.headers()["x-request-id"], id);
    assert_eq!(
        response.headers()["content-type"],
        "application/problem+json"
    );
    (status, response.json().await.unwrap())
}

/// A code, the route and body that cause it, and the status it comes with.
type Case<'a> = (&'a str, (reqwest::Method, &'a str), (&'a str, String), u16);

#[tokio::test]
async fn every_problem_has_a_code_and_the_request_id() {
    let server = Server::start_with(thrustline::Settings {
        body_limit: 100_000,
        ..Default::default()
    })
    .await;
    let post = reqwest::Method::POST;
    let json = "application/json";
    let with = |path: &str, value: Value| {
        let mut body = spencer_example();
        *body.pointer_mut(path).unwrap() = value;
        body.to_string()
    };
    let mut unknown = spencer_example();
    unknown["slope"]["x"] = json!(3);
    let mut missing = spencer_example();
    missing["slope"].as_object_mut().unwrap().remove("height");
    let cases: Vec<Case> = vec![
        (
            "invalid_json",
            (post.clone(), "/slope/spencer"),
            (json, "{bad".into()),
            400,
        ),
        (
            "duplicate_key",
            (post.clone(), "/slope/spencer"),
            (json, r#"{"slices": 100, "slices": 5}"#.into()),
            422,
        ),
        (
            "unknown_field",
            (post.clone(), "/slope/spencer"),
            (json, unknown.to_string()),
            422,
        ),
        (
            "missing_field",
            (post.clone(), "/slope/spencer"),
            (json, missing.to_string()),
            422,
        ),
        (
            "out_of_range",
            (post.clone(), "/slope/spencer"),
            (json, with("/slices", json!(0))),
            422,
        ),
        (
            "invalid_value",
            (post.clone(), "/slope/spencer"),
            (json, with("/slices", json!("many"))),
            422,
        ),
        (
            // Both in range, together no circle through the slope.
            "unstateable",
            (post.clone(), "/slope/spencer"),
            (json, with("/circle", json!({"x": 500.0, "y": 1.0}))),
            422,
        ),
        (
            "too_large",
            (post.clone(), "/slope/spencer"),
            (json, format!("{{\"pad\": \"{}\"}}", "x".repeat(200_000))),
            413,
        ),
        (
            "unsupported_media_type",
            (post.clone(), "/slope/spencer"),
            ("text/plain", spencer_example().to_string()),
            415,
        ),
        (
            "not_found",
            (post.clone(), "/nowhere"),
            (json, "{}".into()),
            404,
        ),
        (
            "method_not_allowed",
            (reqwest::Method::GET, "/slope/spencer"),
            (json, String::new()),
            405,
        ),
    ];
    for (i, (code, route, body, status)) in cases.into_iter().enumerate() {
        let id = format!("case-{i}");
        let (answered, problem) = problem(&server, route, body, &id).await;
        assert_eq!(answered, status, "{code}: {problem}");
        assert_eq!(problem["code"], code, "{problem}");
        assert_eq!(problem["instance"], id.as_str(), "{problem}");
        assert_eq!(problem["status"], status, "{problem}");
        let detail = problem["detail"].as_str().unwrap();
        assert!(!detail.contains("Failed to"), "{code}: {detail}");
        assert!(!detail.contains("target type"), "{code}: {detail}");
    }
    // Without an id of its own the request gets one, and the problem carries it.
    let response = server
        .client
        .post(format!("{}/slope/spencer", server.base))
        .json(&json!({"slope": {"height": 1.0}}))
        .send()
        .await
        .unwrap();
    let id = response.headers()["x-request-id"]
        .to_str()
        .unwrap()
        .to_owned();
    let problem: Value = response.json().await.unwrap();
    assert_eq!(problem["instance"], id.as_str());
}

#[tokio::test]
async fn an_unauthorized_request_has_its_code() {
    let server = Server::start_with(thrustline::Settings {
        token: Some("secret".to_owned()),
        ..Default::default()
    })
    .await;
    let (status, problem) = problem(
        &server,
        (reqwest::Method::POST, "/slope/spencer"),
        ("application/json", spencer_example().to_string()),
        "no-token",
    )
    .await;
    assert_eq!(status, 401);
    assert_eq!(problem["code"], "unauthorized");
    assert_eq!(problem["instance"], "no-token");
}
