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

/// POSTs `body` in process and returns the status and the JSON answer without its timings.
async fn post(path: &str, body: &serde_json::Value) -> (StatusCode, serde_json::Value) {
    let request = Request::post(path)
        .header("content-type", "application/json")
        .body(Body::from(body.to_string()))
        .unwrap();
    let (status, _, mut answer) = call(request).await;
    strip_timings(&mut answer);
    (status, answer)
}

fn strip_timings(value: &mut serde_json::Value) {
    match value {
        serde_json::Value::Object(map) => {
            map.retain(|k, _| k != "time_ms" && k != "solve_time_ms");
            map.values_mut().for_each(strip_timings);
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(strip_timings),
        _ => {}
    }
}

#[tokio::test]
async fn null_for_an_optional_field_means_its_default_on_every_route() {
    // What pydantic's model_dump() sends for unset fields: every optional field null. The answer
    // must be the one for the body without them (interface limits excepted: there null is
    // "unbounded", model §3).
    use serde_json::json;
    let arch = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
                                   "voussoirs": 40}});
    let arch_nulls = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
                                         "voussoirs": 40, "left_base_angle_deg": null,
                                         "right_base_angle_deg": null, "voussoir": null,
                                         "rings": null, "ring_joints": null, "spans": null,
                                         "pier_width": null, "pier_height": null},
                            "unit_weight": null, "interface_limits": null,
                            "friction_coefficient": null, "formulation": null,
                            "solver_tolerance": null});
    let mut live = arch.clone();
    live["loads"] = json!([{"block": 11, "fy": -1.0}]);
    let mut live_nulls = arch_nulls.clone();
    live_nulls["loads"] =
        json!([{"block": 11, "x": null, "y": null, "fx": null, "fy": -1.0, "moment": null}]);
    let mut minimum = arch.clone();
    minimum["geometry"]["voussoirs"] = json!(12);
    minimum["geometry"]
        .as_object_mut()
        .unwrap()
        .remove("thickness");
    let mut minimum_nulls = arch_nulls.clone();
    minimum_nulls["geometry"]["voussoirs"] = json!(12);
    minimum_nulls["geometry"]["thickness"] = json!(null);
    let minimum_nulls = json!({"geometry": minimum_nulls["geometry"], "unit_weight": null,
                               "interface_limits": null, "friction_coefficient": null,
                               "tolerance": null});
    let mut slope = common::spencer_example();
    slope["soil"]
        .as_object_mut()
        .unwrap()
        .remove("pore_pressure_ratio");
    let mut slope_nulls = slope.clone();
    for field in [
        "search",
        "curves",
        "slice_tolerance",
        "seismic",
        "external_loads",
    ] {
        slope_nulls[field] = json!(null);
    }
    slope_nulls["circle"]["lower_end_factor"] = json!(null);
    slope_nulls["soil"]["pore_pressure_ratio"] = json!(null);
    slope_nulls["slices"] = json!(null);
    let mut search = common::spencer_example();
    search.as_object_mut().unwrap().remove("circle");
    search["search"] = json!({"nx": 5, "ny": 5});
    search["slices"] = json!(20);
    let mut search_nulls = search.clone();
    search_nulls["search"] = json!({"x_min": null, "x_max": null, "y_min": null, "y_max": null,
                                    "nx": 5, "ny": 5, "lower_end_factor": null,
                                    "lower_end_factor_max": null});
    search_nulls["circle"] = json!(null);
    for (path, plain, nulls) in [
        ("/arch/dead-load", &arch, &arch_nulls),
        ("/arch/live-load", &live, &live_nulls),
        ("/arch/minimum-thickness", &minimum, &minimum_nulls),
        ("/slope/spencer", &slope, &slope_nulls),
        ("/slope/spencer", &search, &search_nulls),
    ] {
        let (status, expected) = post(path, plain).await;
        assert_eq!(status, StatusCode::OK, "{path}: {expected}");
        let (status, answer) = post(path, nulls).await;
        assert_eq!(status, StatusCode::OK, "{path}: {answer}");
        assert!(answer == expected, "{path}: the answers differ");
    }
}

#[tokio::test]
async fn what_generated_clients_send_is_read_as_they_mean_it() {
    use serde_json::json;
    // Whole numbers written as 100.0 are integers (JSON Schema's `integer` includes them).
    let arch = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
                                   "voussoirs": 40}});
    let mut as_float = arch.clone();
    as_float["geometry"]["voussoirs"] = json!(40.0);
    let (status, expected) = post("/arch/dead-load", &arch).await;
    assert_eq!(status, StatusCode::OK);
    let (status, answer) = post("/arch/dead-load", &as_float).await;
    assert_eq!(status, StatusCode::OK, "{answer}");
    assert!(answer == expected);
    let mut slope = common::spencer_example();
    slope["slices"] = json!(100.0);
    let (status, answer) = post("/slope/spencer", &slope).await;
    assert_eq!(status, StatusCode::OK, "{answer}");
    assert_eq!(answer["slice_count"], 100);
    // Wrong types are 422 in JSON's words, naming the full path; never Rust's type names.
    let mut wrong = common::spencer_example();
    wrong["slices"] = json!(100.5);
    let mut formulation = arch.clone();
    formulation["formulation"] = json!(5);
    let mut limits = arch.clone();
    limits["interface_limits"] = json!(5);
    let mut unit_weight = arch.clone();
    unit_weight["unit_weight"] = json!(true);
    let mut missing = common::spencer_example();
    missing["slope"] = json!({"length": 2.0});
    for (path, body, field) in [
        ("/slope/spencer", wrong, "slices"),
        ("/arch/dead-load", formulation, "formulation"),
        ("/arch/dead-load", limits, "interface_limits"),
        ("/arch/dead-load", unit_weight, "unit_weight"),
        ("/slope/spencer", missing, "slope.height"),
        ("/arch/dead-load", json!({}), "geometry"),
    ] {
        let (status, answer) = post(path, &body).await;
        assert_eq!(status, StatusCode::UNPROCESSABLE_ENTITY, "{answer}");
        assert_eq!(answer["field"], field, "{answer}");
        let detail = answer["detail"].as_str().unwrap();
        for rust in ["f64", "usize", "struct ", "Dto", "enum "] {
            assert!(!detail.contains(rust), "{detail}");
        }
    }
}

#[tokio::test]
async fn every_named_request_example_of_the_spec_is_answered() {
    // The examples clients see in /docs and generated code must work as they are.
    let doc: serde_json::Value =
        serde_json::from_str(&thrustline::openapi::openapi_json()).unwrap();
    let mut tried = 0;
    for (path, item) in doc["paths"].as_object().unwrap() {
        let Some(examples) =
            item["post"]["requestBody"]["content"]["application/json"]["examples"].as_object()
        else {
            continue;
        };
        for (name, example) in examples {
            let request = Request::post(path.as_str())
                .header("content-type", "application/json")
                .body(Body::from(example["value"].to_string()))
                .unwrap();
            let response = router().oneshot(request).await.unwrap();
            assert_eq!(response.status(), StatusCode::OK, "{path} {name}");
            tried += 1;
        }
    }
    assert!(tried >= 11, "{tried}");
}
