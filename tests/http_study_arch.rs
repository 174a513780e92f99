//! Studies on the live-load route (model §9.2–9.3): λ is homogeneous of degree −1 in the live
//! load (the programme scales it), so a load of uniform magnitude gives λ = λ₁/|P| with a
//! probability of failure and a mean known in closed form; an arch too thin to carry itself
//! fails without live load (λ = 0); studies stream; bad studies are refused naming the field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

fn arch(thickness: f64, fy: f64) -> Value {
    json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": thickness, "voussoirs": 20},
           "loads": [{"block": 6, "fy": fy}], "include": []})
}

fn num(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key} in {v}"))
}

async fn answer(server: &Server, body: &Value) -> Value {
    let (status, _, answer) = server.post("/arch/live-load", body).await;
    assert_eq!(status, 200, "{answer}");
    answer
}

#[tokio::test]
async fn a_load_of_uniform_magnitude_fails_as_its_closed_form_says() {
    let server = Server::start().await;
    let unit = num(&answer(&server, &arch(1.5, -1.0)).await, "load_factor");
    // |P| uniform on [0.5, 1.3]·λ₁: λ = λ₁/|P| < 1 where |P| > λ₁, PF = 0.3/0.8; the mean of
    // λ₁/|P| is ln(1.3/0.5)/0.8.
    let n = 6000;
    let mut body = arch(1.5, -unit);
    body["probabilistic"] = json!({"samples": n, "seed": 21, "variables": [{"field": "loads[0].fy",
        "distribution": "uniform", "min": -1.3 * unit, "max": -0.5 * unit}]});
    body["sensitivity"] = json!({"variables": [{"field": "loads[0].fy", "from": -2.0 * unit, "to": -0.5 * unit, "points": 4}]});
    let a = answer(&server, &body).await;
    assert!(
        (num(&a, "load_factor") - 1.0).abs() < 1e-7,
        "{}",
        a["load_factor"]
    );
    let p = &a["probabilistic"];
    assert_eq!(p["unsolved"], 0, "{p}");
    let pf = 0.375;
    let se = (pf * (1.0f64 - pf) / n as f64).sqrt();
    assert!(
        (num(p, "probability_of_failure") - pf).abs() < 4.0 * se,
        "{p}"
    );
    let mean = (1.3f64 / 0.5).ln() / 0.8;
    // Var of 1/U for U uniform on [a, b]: 1/(ab) − mean².
    let sd = (1.0 / (0.5 * 1.3) - mean * mean).sqrt();
    assert!(
        (num(p, "mean") - mean).abs() < 4.0 * sd / (n as f64).sqrt(),
        "{p} vs {mean}"
    );
    assert!((num(p, "std") - sd).abs() < 0.05 * sd, "{p} vs {sd}");
    for point in a["sensitivity"]["variables"][0]["points"]
        .as_array()
        .unwrap()
    {
        let expected = unit / num(point, "value").abs();
        assert!(
            (num(point, "factor") - expected).abs() < 1e-7 * expected,
            "{point}"
        );
    }
}

#[tokio::test]
async fn an_arch_too_thin_to_stand_fails_without_live_load() {
    let server = Server::start().await;
    let (status, _, least) = server
        .post(
            "/arch/minimum-thickness",
            &json!({"geometry": {"kind": "circular", "radius": 10.0,
            "thickness": 1.5, "voussoirs": 20}}),
        )
        .await;
    assert_eq!(status, 200, "{least}");
    let t_min = num(&least, "thickness");
    let mut body = arch(1.2, -1.0);
    let n = 2000;
    body["probabilistic"] = json!({"samples": n, "seed": 4, "variables": [{"field": "geometry.thickness",
        "distribution": "uniform", "min": t_min - 0.1, "max": t_min + 0.3}]});
    body["sensitivity"] = json!({"variables": [{"field": "geometry.thickness", "from": t_min - 0.05, "to": t_min + 0.05, "points": 2}]});
    let a = answer(&server, &body).await;
    let p = &a["probabilistic"];
    // A quarter of the samples cannot carry themselves: λ = 0, failed.
    let se = (0.25f64 * 0.75 / n as f64).sqrt();
    assert!(num(p, "probability_of_failure") >= 0.25 - 4.0 * se, "{p}");
    assert_eq!(num(&p["histogram"][0], "from"), 0.0, "{p}");
    let points = &a["sensitivity"]["variables"][0]["points"];
    assert_eq!(num(&points[0], "factor"), 0.0, "{points}");
    assert!(num(&points[1], "factor") > 0.0, "{points}");
}

#[tokio::test]
async fn an_arch_study_streams_and_refuses_what_an_arch_cannot_vary() {
    let server = Server::start().await;
    let mut body = arch(1.5, -10.0);
    body["unit_weight"] = json!(1.0);
    body["probabilistic"] = json!({"samples": 300, "variables": [{"field": "unit_weight",
        "distribution": "normal", "std": 0.1, "min": 0.5}]});
    let plain = answer(&server, &body).await;
    let response = server
        .client
        .post(format!("{}/arch/live-load/stream", server.base))
        .json(&body)
        .send()
        .await
        .unwrap();
    assert_eq!(Server::content_type(&response), "application/x-ndjson");
    let text = response.text().await.unwrap();
    let last: Value = serde_json::from_str(text.lines().last().unwrap()).unwrap();
    assert_eq!(
        last["probabilistic"]["mean"],
        plain["probabilistic"]["mean"]
    );
    assert_eq!(last["load_factor"], plain["load_factor"]);
    let cases = [
        (
            json!({"samples": 10, "surface": "search", "variables": [{"field": "unit_weight", "distribution": "normal", "std": 0.1}]}),
            "probabilistic.surface",
        ),
        (
            json!({"samples": 10, "variables": [{"field": "geometry.voussoirs", "distribution": "normal", "std": 1}]}),
            "probabilistic.variables[0].field",
        ),
        (
            json!({"samples": 10, "variables": [{"field": "loads[1].fy", "distribution": "normal", "std": 1}]}),
            "probabilistic.variables[0].field",
        ),
    ];
    for (study, field) in cases {
        let mut body = arch(1.5, -10.0);
        body["unit_weight"] = json!(1.0);
        body["probabilistic"] = study;
        let (status, content_type, problem) = server.post("/arch/live-load", &body).await;
        assert_problem(status, &content_type, &problem, 422, field);
    }
    let mut body = arch(1.5, -10.0);
    body["unit_weight"] = json!(1.0);
    body["design"] = json!({"factors": {"live": 1.5}});
    body["probabilistic"] = json!({"samples": 10, "variables": [{"field": "unit_weight", "distribution": "normal", "std": 0.1}]});
    let (status, content_type, problem) = server.post("/arch/live-load", &body).await;
    assert_problem(status, &content_type, &problem, 422, "probabilistic");
    // The dead-load route has no studies.
    let mut body = arch(1.5, -10.0);
    body.as_object_mut().unwrap().remove("loads");
    body["probabilistic"] = json!({"samples": 10, "variables": []});
    let (status, _, problem) = server.post("/arch/dead-load", &body).await;
    assert_eq!(status, 422, "{problem}");
}
