//! Each method its own critical surface (SPEC §14): `search.per_method` searches every method
//! of `methods` over the same centres, radii and candidates, ranked by that method's F, answered
//! as `methods.<name>.critical` beside the headline's Spencer search.
#![allow(clippy::unwrap_used)]

mod common;

use common::Server;
use serde_json::{json, Value};

const METHODS: [&str; 4] = ["bishop", "ordinary", "janbu", "morgenstern_price"];

/// ACADS 1(a) (Giam & Donald 1989; model §4.5).
fn acads_1a() -> Value {
    json!({"section": {"ground": [[20, 25], [30, 25], [50, 35], [70, 35]],
        "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 3, "friction_angle_deg": 19.6}}]},
        "search": {"per_method": true}, "slices": 50, "methods": METHODS, "include": []})
}

async fn spencer(server: &Server, body: &Value) -> Value {
    let (status, _, answer) = server.post("/slope/spencer", body).await;
    assert_eq!(status, 200, "{answer}");
    answer
}

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Each method's critical circle re-solved as a fixed circle gives its F; no method's critical
/// F lies above its F on Spencer's critical circle (a search over circles that include it);
/// the headline is the plain search's, bit for bit.
async fn assert_own_minima(server: &Server, body: &Value) -> Value {
    let answer = spencer(server, body).await;
    let mut plain = body.clone();
    plain["search"]["per_method"] = json!(false);
    let without = spencer(server, &plain).await;
    assert_eq!(answer["factor_of_safety"], without["factor_of_safety"]);
    assert_eq!(answer["circle"], without["circle"]);
    for method in body["methods"].as_array().unwrap() {
        let name = method.as_str().unwrap();
        let on_spencers = number(&answer["methods"][name]["factor_of_safety"]);
        assert!(without["methods"][name]["critical"].is_null(), "{name}");
        let critical = &answer["methods"][name]["critical"];
        assert_eq!(critical["converged"], true, "{name}: {critical}");
        let own = number(&critical["factor_of_safety"]);
        assert!(
            own <= on_spencers * (1.0 + 1e-6),
            "{name}: {own} > {on_spencers}"
        );
        let circle = &critical["circle"];
        let mut fixed = body.clone();
        fixed["search"] = Value::Null;
        fixed["methods"] = json!([name]);
        fixed["circle"] = json!({"centre": [number(&circle["centre"]["x"]), number(&circle["centre"]["y"])],
                                 "radius": number(&circle["radius"])});
        if body.get("slope").is_some() {
            // The simple slope's circle: its centre from the lower end, F_e as searched.
            fixed["circle"] = json!({"x": number(&circle["x"]), "y": number(&circle["y"]),
                                     "lower_end_factor": 0});
        }
        let again = spencer(server, &fixed).await;
        let f = number(&again["methods"][name]["factor_of_safety"]);
        assert!(
            (f - own).abs() < 1e-9 * own,
            "{name}: fixed {f}, searched {own}"
        );
        assert!(
            number(&critical["search"]["evaluations"]) > 100.0,
            "{name}: {critical}"
        );
    }
    answer
}

#[tokio::test]
async fn each_method_searches_its_own_critical_circle() {
    let server = Server::start().await;
    let answer = assert_own_minima(&server, &acads_1a()).await;
    // Slide2's verification manual, problem 1: Bishop's critical circle 0.987 (the study's
    // referee 1.00); Morgenstern–Price (GLE, half-sine) 0.986.
    let bishop = number(&answer["methods"]["bishop"]["critical"]["factor_of_safety"]);
    assert!((bishop - 0.987).abs() < 0.005 * 0.987, "Bishop {bishop}");
    let mp = number(&answer["methods"]["morgenstern_price"]["critical"]["factor_of_safety"]);
    assert!((mp - 0.986).abs() < 0.005 * 0.986, "M–P {mp}");
    // The methods without moment equilibrium go lower, on circles of their own: Janbu's and
    // the ordinary method's critical circles are not Spencer's.
    for name in ["janbu", "ordinary"] {
        let own = number(&answer["methods"][name]["critical"]["factor_of_safety"]);
        let on_spencers = number(&answer["methods"][name]["factor_of_safety"]);
        assert!(own < on_spencers - 1e-3, "{name}: {own} vs {on_spencers}");
    }
}

#[tokio::test]
async fn with_no_friction_every_method_finds_spencers_minimum() {
    // φ′ = 0: Spencer's, Bishop's and the ordinary method's F are one function of the circle
    // (tests/http_roots.rs), so their searches rank every circle alike and find one minimum.
    let server = Server::start().await;
    let body = json!({"section": {"ground": [[0, 0], [10, 0], [30, 10], [60, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 18, "cohesion": 25, "friction_angle_deg": 0}}]},
        "search": {"per_method": true}, "slices": 40, "methods": ["bishop", "ordinary"],
        "include": []});
    let answer = assert_own_minima(&server, &body).await;
    let f = number(&answer["factor_of_safety"]);
    for name in ["bishop", "ordinary"] {
        let own = number(&answer["methods"][name]["critical"]["factor_of_safety"]);
        assert!((own - f).abs() < 1e-9 * f, "{name}: {own} vs Spencer {f}");
    }
}

#[tokio::test]
async fn the_simple_slope_searches_each_method_too() {
    let server = Server::start().await;
    let body = json!({"slope": {"height": 10, "length": 20},
        "soil": {"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 30, "pore_pressure_ratio": 0.3},
        "search": {"per_method": true}, "slices": 40, "methods": ["bishop", "janbu"], "include": []});
    assert_own_minima(&server, &body).await;
}

#[tokio::test]
async fn per_method_needs_methods_and_the_classic_equations() {
    let server = Server::start().await;
    let mut none = acads_1a();
    none["methods"] = json!([]);
    let mut dropped = acads_1a();
    dropped["negative_effective_stress"] = json!("drop_friction");
    for (body, words) in [(none, "names no method"), (dropped, "classic equations")] {
        let (status, _, problem) = server.post("/slope/spencer", &body).await;
        assert_eq!(status, 422, "{problem}");
        assert_eq!(problem["field"], "search.per_method", "{problem}");
        assert!(
            problem["detail"].as_str().unwrap().contains(words),
            "{problem}"
        );
    }
}

/// Low (1989), Slide2's verification problem 23, as the XSLOPE corpus rebuilt it: a 2:1 fill
/// 8 m high (γ 20, c′ 95, φ′ 15°) on 4 m of clay (s_u 15) over 4 m whose s_u grows from 15 by
/// 3.75 kPa/m, on a rigid base. Published Bishop minima 1.14 (Low), 1.17 (Kim), 1.192 (Slide2);
/// ordinary 1.36 (Low), 1.370 (Slide2). Spencer's equations have no physical root on the deep
/// circles Bishop prefers (SPEC §14), so Spencer's minimum lies higher and says so.
#[tokio::test]
async fn an_embankment_on_clay_stronger_with_depth_has_bishops_published_minimum() {
    let server = Server::start().await;
    let body = json!({"section": {"ground": [[-20, 8], [10, 8], [26, 16], [60, 16]],
        "layers": [
            {"top": null, "soil": {"unit_weight": 20, "cohesion": 95, "friction_angle_deg": 15}},
            {"top": [[-20, 8], [60, 8]], "soil": {"unit_weight": 20, "cohesion": 15, "friction_angle_deg": 0}},
            {"top": [[-20, 4], [60, 4]], "soil": {"unit_weight": 20,
                "strength": {"model": "undrained", "cohesion": 15, "gradient": 3.75, "datum": 4}}}],
        "bedrock": [[-20, 0], [60, 0]]},
        "search": {"per_method": true}, "slices": 50, "methods": ["bishop", "ordinary"],
        "include": []});
    let answer = assert_own_minima(&server, &body).await;
    let bishop = number(&answer["methods"]["bishop"]["critical"]["factor_of_safety"]);
    assert!((1.14..=1.192).contains(&bishop), "Bishop {bishop}");
    let ordinary = number(&answer["methods"]["ordinary"]["critical"]["factor_of_safety"]);
    assert!(
        (ordinary - 1.365).abs() < 0.01 * 1.365,
        "ordinary {ordinary}"
    );
    let spencer = number(&answer["factor_of_safety"]);
    assert!(spencer > bishop * 1.1, "Spencer {spencer}");
    let codes = answer["warnings"].to_string();
    assert!(codes.contains("unsolved_below_minimum"), "{codes}");
}

/// ACADS 1(a) with a study of `method`: a sensitivity study whose first point is the stated
/// cohesion, and a probabilistic one of vanishing spread.
fn studied(method: &str, surface: &str) -> Value {
    let mut body = acads_1a();
    body["methods"] = json!(["bishop", "janbu"]);
    body["sensitivity"] = json!({"method": method, "variables": [
        {"field": "section.layers[0].soil.cohesion", "from": 3, "to": 4, "points": 2}]});
    body["probabilistic"] = json!({"method": method, "samples": 4, "seed": 1, "surface": surface,
        "variables": [{"field": "section.layers[0].soil.cohesion", "distribution": "normal",
                       "std": 1e-12}]});
    body
}

#[tokio::test]
async fn studies_on_a_chosen_method_equal_that_method_at_zero_spread() {
    let server = Server::start().await;
    for (method, surface) in [
        ("bishop", "fixed"),
        ("bishop", "search"),
        ("janbu", "search"),
    ] {
        let answer = spencer(&server, &studied(method, surface)).await;
        // The deterministic F of the method: on its own critical circle (per_method), which a
        // fixed-surface study keeps and a searching one finds again.
        let own = number(&answer["methods"][method]["critical"]["factor_of_safety"]);
        let p = &answer["probabilistic"];
        assert_eq!(p["method"], method, "{p}");
        let mean = number(&p["mean"]);
        assert!(
            (mean - own).abs() < 1e-9 * own,
            "{method} {surface}: mean {mean} vs {own}"
        );
        let s = &answer["sensitivity"];
        assert_eq!(s["method"], method, "{s}");
        let first = number(&s["variables"][0]["points"][0]["factor"]);
        assert!(
            (first - own).abs() < 1e-9 * own,
            "{method}: {first} vs {own}"
        );
    }
    // Spencer's (the default) as before: no method echoed, the headline F.
    let mut plain = studied("spencer", "fixed");
    plain["probabilistic"]
        .as_object_mut()
        .unwrap()
        .remove("method");
    let answer = spencer(&server, &plain).await;
    assert!(answer["probabilistic"].get("method").is_none());
    let f = number(&answer["factor_of_safety"]);
    let mean = number(&answer["probabilistic"]["mean"]);
    assert!((mean - f).abs() < 1e-9 * f, "{mean} vs {f}");
}

#[tokio::test]
async fn a_study_method_must_be_among_the_methods() {
    let server = Server::start().await;
    let mut body = studied("ordinary", "fixed");
    body["sensitivity"]["method"] = json!("spencer");
    let (status, _, problem) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 422, "{problem}");
    assert_eq!(problem["field"], "probabilistic.method", "{problem}");
    let arch = json!({"geometry": {"kind": "circular", "radius": 10, "thickness": 1, "voussoirs": 20},
        "loads": [{"block": 6, "fy": -1}], "include": [],
        "sensitivity": {"method": "bishop", "variables": [{"field": "loads[0].fy", "from": -2, "to": -1}]}});
    let (status, _, problem) = server.post("/arch/live-load", &arch).await;
    assert_eq!(status, 422, "{problem}");
    assert_eq!(problem["field"], "sensitivity.method", "{problem}");
}

/// Li & Lumb (1987), Slide2's problem 36: a 1:1 face, c′ 18, φ′ 30°, r_u 0.2; published Bishop
/// 1.334 (Hassan & Wolff) and 1.340 (Slide2). And Baker (2001), problem 43, with the dry crack
/// of the Rankine depth that its steep cohesive face has: both methods solve (docs/slopes.md).
#[tokio::test]
async fn steep_faces_give_the_published_bishop_minimum_and_solve_with_their_crack() {
    let server = Server::start().await;
    let li_lumb = json!({"section": {"ground": [[0, 5], [5, 5], [15, 15], [20, 15]],
        "layers": [{"top": null, "soil": {"unit_weight": 18, "cohesion": 18,
            "friction_angle_deg": 30, "pore_pressure_ratio": 0.2}}]},
        "search": {"per_method": true}, "slices": 50, "methods": ["bishop"], "include": []});
    let answer = assert_own_minima(&server, &li_lumb).await;
    let bishop = number(&answer["methods"]["bishop"]["critical"]["factor_of_safety"]);
    assert!((1.334 * 0.995..=1.340).contains(&bishop), "Bishop {bishop}");
    let cracked = json!({"section": {"ground": [[-10, 0], [0, 0], [3, 10], [20, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 30, "friction_angle_deg": 30}}],
        "tension_crack": {"depth": 5.2, "water_depth": 0}},
        "search": {"per_method": true}, "slices": 50, "methods": ["bishop"], "include": []});
    let answer = spencer(&server, &cracked).await;
    assert!(
        (number(&answer["factor_of_safety"]) - 1.1661).abs() < 5e-5,
        "{answer}"
    );
    let bishop = number(&answer["methods"]["bishop"]["critical"]["factor_of_safety"]);
    assert!((bishop - 1.1752).abs() < 5e-5, "{bishop}");
    assert_eq!(answer["search"]["unsolved"], 0, "{}", answer["search"]);
}
