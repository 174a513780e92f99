//! Named vehicles and the strip width (model §10): each named vehicle rolls as its explicit
//! axles (EN 1991-2 LM1 tandem: 2 × 300 kN 1.2 m apart on 0.4 m; LM2: 400 kN on 0.35 m), the
//! width divides every axle (λ is homogeneous of degree −1 in the live load, so λ scales with
//! the width), a partial-factor check factors a named vehicle as its axles; bad vehicles are
//! refused naming the field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

fn body(rolling: Value) -> Value {
    let mut rolling = rolling;
    rolling["x_start"] = json!(-8.0);
    rolling["x_end"] = json!(8.0);
    rolling["positions"] = json!(9);
    json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.2, "voussoirs": 60},
           "unit_weight": 20.0, "fill": {"unit_weight": 18.0, "surface": 11.5},
           "rolling": rolling, "include": []})
}

async fn curve(server: &Server, body: &Value) -> Vec<f64> {
    let (status, _, answer) = server.post("/arch/live-load", body).await;
    assert_eq!(status, 200, "{answer}");
    answer["rolling"]["load_factor"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap_or_else(|| panic!("{answer}")))
        .collect()
}

fn axles(list: &[(f64, f64, f64)]) -> Value {
    json!(list
        .iter()
        .map(|(offset, fy, length)| json!({"offset": offset, "fy": fy, "length": length}))
        .collect::<Vec<_>>())
}

#[tokio::test]
async fn a_named_vehicle_rolls_as_its_axles_divided_by_the_width() {
    let server = Server::start().await;
    // 300 / 2.5 = 120 and 400 / 2 = 200 exactly: the curves agree bit for bit.
    let tandem = curve(
        &server,
        &body(json!({"vehicle": "en1991_lm1_tandem", "width": 2.5})),
    )
    .await;
    let explicit = curve(
        &server,
        &body(json!({"axles": axles(&[(-0.6, -120.0, 0.4), (0.6, -120.0, 0.4)])})),
    )
    .await;
    assert_eq!(tandem, explicit);
    let lm2 = curve(
        &server,
        &body(json!({"vehicle": "en1991_lm2", "width": 2.0})),
    )
    .await;
    let one = curve(
        &server,
        &body(json!({"axles": axles(&[(0.0, -200.0, 0.35)])})),
    )
    .await;
    assert_eq!(lm2, one);
    // The vehicle as an object of axles is the same as `axles`.
    let as_vehicle = curve(
        &server,
        &body(json!({"vehicle": {"axles": axles(&[(0.0, -200.0, 0.35)])}})),
    )
    .await;
    assert_eq!(as_vehicle, one);
}

#[tokio::test]
async fn lambda_scales_with_the_strip_width() {
    let server = Server::start().await;
    let narrow = curve(&server, &body(json!({"vehicle": "en1991_lm2"}))).await;
    let wide = curve(
        &server,
        &body(json!({"vehicle": "en1991_lm2", "width": 3.0})),
    )
    .await;
    for (a, b) in narrow.iter().zip(&wide) {
        assert!((b - 3.0 * a).abs() < 1e-7 * b, "{a} × 3 against {b}");
    }
}

#[tokio::test]
async fn a_design_check_factors_a_named_vehicle_as_its_axles() {
    let server = Server::start().await;
    let design = json!({"factors": {"dead": 1.35, "fill": 1.35, "live": 1.5, "strength": 1.0}});
    let mut named = body(json!({"vehicle": "en1991_lm2"}));
    named["design"] = design.clone();
    let mut explicit = body(json!({"axles": axles(&[(0.0, -400.0, 0.35)])}));
    explicit["design"] = design;
    let (a, b) = (
        curve(&server, &named).await,
        curve(&server, &explicit).await,
    );
    assert_eq!(a, b);
    let plain = curve(&server, &body(json!({"vehicle": "en1991_lm2"}))).await;
    assert!(
        a.iter().zip(&plain).all(|(d, p)| d < p),
        "{a:?} against {plain:?}"
    );
}

#[tokio::test]
async fn bad_vehicles_are_refused_naming_the_field() {
    let server = Server::start().await;
    let cases = [
        (json!({"vehicle": "hb_45"}), "rolling.vehicle"),
        (json!({"vehicle": 5}), "rolling.vehicle"),
        (json!({"vehicle": {"axles": []}}), "rolling.vehicle.axles"),
        (
            json!({"vehicle": {"axles": [{"fy": "heavy"}]}}),
            "rolling.vehicle",
        ),
        (
            json!({"vehicle": "en1991_lm2", "axles": axles(&[(0.0, -1.0, 0.0)])}),
            "rolling.vehicle",
        ),
        (json!({}), "rolling.axles"),
        (json!({"axles": []}), "rolling.axles"),
        (
            json!({"vehicle": "en1991_lm2", "width": 0.0}),
            "rolling.width",
        ),
        (
            json!({"vehicle": "en1991_lm2", "width": -2.0}),
            "rolling.width",
        ),
    ];
    for (rolling, field) in cases {
        let (status, content_type, problem) = server.post("/arch/live-load", &body(rolling)).await;
        assert_problem(status, &content_type, &problem, 422, field);
    }
}
