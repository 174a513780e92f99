//! The accuracy every slope answer states, and the accuracy a request may ask for instead of a
//! slice count (model §6.2).
// Test scaffolding: a missing field should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, spencer_example, with, Server};
use serde_json::json;

#[tokio::test]
async fn every_answer_states_its_discretisation_error() {
    // Spencer's example at 100 slices: F(100) − F(∞) = +5.3e-5 of F (docs/accuracy.md's table
    // against 20,000 slices); the stated error must hold it within the contract's bounds.
    let server = Server::start().await;
    let (status, _, answer) = server.post("/slope/spencer", &spencer_example()).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["accuracy"]["slices"], 100);
    let e = answer["accuracy"]["discretisation_error"].as_f64().unwrap();
    let truth = 5.3e-5 / 1.0695;
    assert!(truth <= 2.0 * e && truth >= e / 10.0, "stated {e}");
    // A search states it for the answered circle.
    let search = with(spencer_example(), "search", json!({}));
    let mut search = search;
    search["circle"] = serde_json::Value::Null;
    let (_, _, answer) = server.post("/slope/spencer", &search).await;
    assert!(answer["accuracy"]["discretisation_error"].as_f64().unwrap() > 0.0);
}

#[tokio::test]
async fn an_accuracy_is_asked_for_instead_of_a_slice_count() {
    let server = Server::start().await;
    for target in [1e-3, 1e-5] {
        let body = with(
            spencer_example(),
            "accuracy",
            json!({"relative_error": target}),
        );
        let (status, _, answer) = server.post("/slope/spencer", &body).await;
        assert_eq!(status, 200, "{answer}");
        let e = answer["accuracy"]["discretisation_error"].as_f64().unwrap();
        assert!(e <= target, "{target}: {e}");
        let slices = answer["accuracy"]["slices"].as_u64().unwrap();
        assert_eq!(answer["slice_count"], slices);
        // Converged F = 1.0695 (Spencer 1967; the thesis 1.06952): within twice the target.
        let f = answer["factor_of_safety"].as_f64().unwrap();
        assert!(
            (f - 1.069_522).abs() <= 2.0 * target * f + 1e-6,
            "{target}: F = {f}"
        );
    }
}

#[tokio::test]
async fn accuracy_requests_are_validated() {
    let server = Server::start().await;
    for (body, field) in [
        (
            with(
                spencer_example(),
                "accuracy",
                json!({"relative_error": 0.5}),
            ),
            "accuracy.relative_error",
        ),
        (
            with(
                spencer_example(),
                "accuracy",
                json!({"relative_error": 1e-9}),
            ),
            "accuracy.relative_error",
        ),
        (
            with(spencer_example(), "accuracy", json!({})),
            "relative_error",
        ),
        (
            with(
                with(
                    spencer_example(),
                    "accuracy",
                    json!({"relative_error": 1e-4}),
                ),
                "slice_tolerance",
                json!(1e-4),
            ),
            "accuracy",
        ),
    ] {
        let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
}
