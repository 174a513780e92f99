//! `design` (model §9.1): each EN 1997-1 approach equals the same request with its inputs
//! factored by hand here (F to 1e-9), DA2 factoring the effect, favourable loads as stated, a
//! search searching on the design values; bad checks refused naming the field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

/// A two-soil section (a frictional fill over a clay with φ = 0) with a permanent surcharge, a
/// variable line load and a favourable variable one at the toe, and its soils and loads with
/// the factors applied by hand: (γ_φ, γ_c, γ_cu, γ_γ) on the soils, `k_g`, `k_q` on the
/// unfavourable permanent and variable loads, favourable variable loads left out.
fn section(factors: Option<(f64, f64, f64, f64)>, k_g: f64, k_q: f64, tagged: bool) -> Value {
    let (phi, c, cu, gamma) = factors.unwrap_or((1.0, 1.0, 1.0, 1.0));
    let phi_d = |deg: f64| (deg.to_radians().tan() / phi).atan().to_degrees();
    let mut surcharge = json!({"x_start": 24, "x_end": 34, "pressure": 15.0 * k_g});
    let mut traffic = json!({"x": 30, "fx": 0, "fy": -40.0 * k_q});
    let mut toe = json!({"x": 6, "fx": 0, "fy": if tagged { -30.0 } else { 0.0 }});
    if tagged {
        surcharge["action"] = json!("permanent");
        traffic["action"] = json!("variable");
        toe["action"] = json!("variable");
        toe["favourable"] = json!(true);
    }
    json!({
        "ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
        "layers": [
            {"top": null, "soil": {"unit_weight": 19.0 * gamma, "cohesion": 8.0 / c, "friction_angle_deg": phi_d(30.0)}},
            {"top": [[-20, -0.5], [0, -0.5], [20, 0.5], [40, 0.5]],
             "soil": {"unit_weight": 17.0 * gamma, "cohesion": 45.0 / cu, "friction_angle_deg": 0}}
        ],
        "surcharges": [surcharge],
        "line_loads": [traffic, toe]
    })
}

fn request(section: Value, design: Option<Value>) -> Value {
    let mut body = json!({"section": section, "circle": {"centre": [12, 28], "radius": 28.5},
                          "slices": 60, "include": []});
    if let Some(d) = design {
        body["design"] = d;
    }
    body
}

fn f(v: &Value) -> f64 {
    v["factor_of_safety"].as_f64().unwrap()
}

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() <= 1e-9 * b.abs(), "{what}: {a} vs {b}");
}

#[tokio::test]
async fn each_approach_is_its_inputs_factored_by_hand() {
    let server = Server::start().await;
    let (status, _, plain) = server
        .post(
            "/slope/spencer",
            &request(section(None, 1.0, 1.0, true), None),
        )
        .await;
    assert_eq!(status, 200, "{plain}");
    assert!(
        plain.get("design").is_none(),
        "no design block without a check"
    );
    let m2 = Some((1.25, 1.25, 1.4, 1.0));
    // (approach, soil factors, load factors on the hand request, γ_R, γ_G·γ_R for DA2)
    for (approach, soils, k_g, k_q, divisor) in [
        ("DA1-1", None, 1.35, 1.5, 1.0),
        ("DA1-2", m2, 1.0, 1.3, 1.0),
        ("DA2", None, 1.0, 1.5 / 1.35, 1.35 * 1.1),
        ("DA3", m2, 1.0, 1.3, 1.0),
    ] {
        let designed = request(
            section(None, 1.0, 1.0, true),
            Some(json!({"approach": approach})),
        );
        let (status, _, answer) = server.post("/slope/spencer", &designed).await;
        assert_eq!(status, 200, "{approach}: {answer}");
        let by_hand = request(section(soils, k_g, k_q, false), None);
        let (_, _, hand) = server.post("/slope/spencer", &by_hand).await;
        close(f(&answer), f(&hand), approach);
        let design = &answer["design"];
        assert_eq!(design["approach"], approach);
        close(
            design["factor_of_safety"].as_f64().unwrap(),
            f(&hand),
            approach,
        );
        let odf = design["over_design_factor"].as_f64().unwrap();
        close(odf, f(&hand) / divisor, approach);
        assert_eq!(design["verified"], odf >= 1.0);
    }
}

#[tokio::test]
async fn own_factors_and_favourable_loads_are_applied_as_stated() {
    let server = Server::start().await;
    let factors = json!({"friction": 1.2, "cohesion": 1.5, "undrained": 1.6, "unit_weight": 1.1,
                         "permanent": 1.2, "variable": 1.4, "resistance": 1.15});
    let (_, _, answer) = server
        .post(
            "/slope/spencer",
            &request(
                section(None, 1.0, 1.0, true),
                Some(json!({"factors": factors})),
            ),
        )
        .await;
    let (_, _, hand) = server
        .post(
            "/slope/spencer",
            &request(section(Some((1.2, 1.5, 1.6, 1.1)), 1.2, 1.4, false), None),
        )
        .await;
    close(f(&answer), f(&hand), "custom");
    assert_eq!(answer["design"]["approach"], "custom");
    close(
        answer["design"]["over_design_factor"].as_f64().unwrap(),
        f(&hand) / 1.15,
        "custom ODF",
    );
    // Factors left out are 1: with only γ_R given, F is the characteristic one (the favourable
    // variable load still left out, as in any check).
    let (_, _, only_r) = server
        .post(
            "/slope/spencer",
            &request(
                section(None, 1.0, 1.0, true),
                Some(json!({"factors": {"resistance": 1.25}})),
            ),
        )
        .await;
    let (_, _, plain) = server
        .post(
            "/slope/spencer",
            &request(section(None, 1.0, 1.0, false), None),
        )
        .await;
    close(f(&only_r), f(&plain), "unit factors");
    // A favourable permanent load keeps its value (·1) under DA1-1's γ_G = 1.35.
    let mut favourable = request(
        section(None, 1.0, 1.0, true),
        Some(json!({"approach": "DA1-1"})),
    );
    favourable["section"]["surcharges"][0]["favourable"] = json!(true);
    let (_, _, answer) = server.post("/slope/spencer", &favourable).await;
    let (_, _, hand) = server
        .post(
            "/slope/spencer",
            &request(section(None, 1.0, 1.5, false), None),
        )
        .await;
    close(f(&answer), f(&hand), "favourable permanent");
}

#[tokio::test]
async fn a_search_searches_on_the_design_values() {
    let server = Server::start().await;
    let search = |s: Value, design: Option<Value>| {
        let mut body =
            json!({"section": s, "search": {"nx": 7, "ny": 7}, "slices": 30, "include": []});
        if let Some(d) = design {
            body["design"] = d;
        }
        body
    };
    let (status, _, designed) = server
        .post(
            "/slope/spencer",
            &search(
                section(None, 1.0, 1.0, true),
                Some(json!({"approach": "DA1-2"})),
            ),
        )
        .await;
    assert_eq!(status, 200, "{designed}");
    let (_, _, hand) = server
        .post(
            "/slope/spencer",
            &search(section(Some((1.25, 1.25, 1.4, 1.0)), 1.0, 1.3, false), None),
        )
        .await;
    close(f(&designed), f(&hand), "DA1-2 search");
    // The simple form too: its soil in design values.
    let simple = |soil: Value, design: Option<Value>| {
        let mut body = json!({"slope": {"height": 10, "length": 20}, "soil": soil,
                              "search": {}, "slices": 30, "include": []});
        if let Some(d) = design {
            body["design"] = d;
        }
        body
    };
    let phi_d = (30f64.to_radians().tan() / 1.25).atan().to_degrees();
    let (_, _, designed) = server
        .post(
            "/slope/spencer",
            &simple(
                json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 30}),
                Some(json!({"approach": "DA3"})),
            ),
        )
        .await;
    let (_, _, hand) = server
        .post(
            "/slope/spencer",
            &simple(
                json!({"unit_weight": 20, "cohesion": 8, "friction_angle_deg": phi_d}),
                None,
            ),
        )
        .await;
    close(f(&designed), f(&hand), "DA3 simple search");
}

#[tokio::test]
async fn bad_checks_are_refused_naming_the_field() {
    let server = Server::start().await;
    let base = || request(section(None, 1.0, 1.0, true), None);
    for (design, field) in [
        (
            json!({"factors": {"friction": 0}}),
            "design.factors.friction",
        ),
        (
            json!({"factors": {"resistance": -1.1}}),
            "design.factors.resistance",
        ),
        (
            json!({"factors": {"variable": 1000}}),
            "design.factors.variable",
        ),
        (json!({}), "design"),
        (
            json!({"approach": "DA1-1", "factors": {"friction": 1.2}}),
            "design.factors",
        ),
    ] {
        let mut body = base();
        body["design"] = design;
        let (status, content_type, problem) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &problem, 422, field);
        assert_eq!(problem["field"], field, "{problem}");
    }
    // An unknown approach, an unknown factor, an action on something that is not a load.
    let mut unknown = base();
    unknown["design"] = json!({"approach": "DA4"});
    let mut factor = base();
    factor["design"] = json!({"factors": {"gamma_m": 1.2}});
    let mut not_a_load = base();
    not_a_load["section"]["layers"][0]["soil"]["action"] = json!("variable");
    for body in [unknown, factor, not_a_load] {
        let (status, _, problem) = server.post("/slope/spencer", &body).await;
        assert_eq!(status, 422, "{problem}");
    }
}

#[tokio::test]
async fn the_characteristic_factor_docs_slopes_states_for_its_design_example() {
    // docs/slopes.md's design examples (their numbers are checked by the example runner)
    // without a check: the characteristic F its prose gives, 1.6858.
    let server = Server::start().await;
    let body = json!({
        "section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
                    "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 8, "friction_angle_deg": 30}}],
                    "surcharges": [{"x_start": 20, "x_end": 30, "pressure": 20},
                                   {"x_start": 20, "x_end": 30, "pressure": 10, "action": "variable"}]},
        "search": {}, "slices": 50, "include": []});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    assert!((f(&answer) - 1.6858).abs() < 5e-5, "{}", f(&answer));
}

#[tokio::test]
async fn the_drawing_and_the_report_show_the_approach_and_its_factors() {
    let server = Server::start().await;
    let body = request(
        section(None, 1.0, 1.0, true),
        Some(json!({"approach": "DA2"})),
    );
    let (_, _, answer) = server.post("/slope/spencer", &body).await;
    let odf = answer["design"]["over_design_factor"].as_f64().unwrap();
    let text = |path: &'static str| {
        let server = &server;
        let body = body.clone();
        async move {
            server
                .client
                .post(format!("{}{path}", server.base))
                .json(&body)
                .send()
                .await
                .unwrap()
                .text()
                .await
                .unwrap()
        }
    };
    let svg = text("/slope/spencer/svg").await;
    roxmltree::Document::parse(&svg).unwrap();
    assert!(
        svg.contains(
            "EN 1997-1 DA2, on design values: γ_φ 1 γ_c 1 γ_cu 1 γ_γ 1 γ_G 1.35 γ_Q 1.5 γ_R 1.1"
        ),
        "no design key"
    );
    assert!(svg.contains(&format!("over-design factor {odf:.3}")));
    let page = text("/slope/spencer/report").await;
    for (field, value) in [
        ("design.approach", "DA2".to_owned()),
        ("design.factors.permanent", "1.35".to_owned()),
        ("design.factors.resistance", "1.1".to_owned()),
        ("design.over_design_factor", odf.to_string()),
    ] {
        let row = format!("<tr><th>{field}</th><td class=\"n\">{value}</td></tr>");
        assert!(page.contains(&row), "the report lacks {row}");
    }
}

/// A filled bridge with crushing and a road load, its inputs factored by hand: (γ_d, γ_f, γ_l,
/// γ_m).
fn bridge(factors: (f64, f64, f64, f64), design: Option<Value>) -> Value {
    let (dead, fill, live, strength) = factors;
    let mut body = json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 60},
        "unit_weight": 2.0 * dead,
        "compressive_strength": 2000.0 / strength,
        "fill": {"unit_weight": 1.8 * fill, "surface": 11.5},
        "road_loads": [{"x": -4.0, "fy": -10.0 * live, "length": 0.3}],
        "include": []
    });
    if let Some(d) = design {
        body["design"] = d;
    }
    body
}

#[tokio::test]
async fn an_arch_s_adequacy_is_the_hand_factored_request_s_load_factor() {
    let server = Server::start().await;
    let (status, _, plain) = server
        .post("/arch/live-load", &bridge((1.0, 1.0, 1.0, 1.0), None))
        .await;
    assert_eq!(status, 200, "{plain}");
    assert!(plain.get("design").is_none());
    let mut answered = 0;
    for factors in [
        (1.2, 1.2, 1.5, 1.0),
        (1.0, 1.0, 1.0, 2.0),
        (1.35, 1.1, 1.7, 1.2),
        (1.0, 1.0, 0.05, 1.0),
    ] {
        let design = json!({"factors": {"dead": factors.0, "fill": factors.1,
                                        "live": factors.2, "strength": factors.3}});
        let (status, _, answer) = server
            .post(
                "/arch/live-load",
                &bridge((1.0, 1.0, 1.0, 1.0), Some(design)),
            )
            .await;
        assert_eq!(status, 200, "{answer}");
        let (_, _, hand) = server.post("/arch/live-load", &bridge(factors, None)).await;
        // λ of the hand-factored request, or none where its dead load is not carried (the
        // strength halved): the adequacy is the same, and not verified without one.
        let lambda = hand["load_factor"].as_f64();
        let adequacy = answer["design"]["adequacy_factor"].as_f64();
        match (adequacy, lambda) {
            (Some(a), Some(l)) => {
                close(a, l, &format!("{factors:?}"));
                close(answer["load_factor"].as_f64().unwrap(), l, "λ");
                answered += 1;
            }
            (None, None) => assert_eq!(hand["stable"], answer["stable"]),
            other => panic!("{factors:?}: {other:?}"),
        }
        assert_eq!(
            answer["design"]["verified"],
            lambda.is_some_and(|l| l >= 1.0)
        );
        assert_eq!(answer["design"]["factors"]["live"], factors.2);
    }
    assert!(answered >= 3, "only {answered} cases with a λ");
    // The live-load factor alone divides λ exactly (λ is linear in the live load).
    let (_, _, live) = server
        .post(
            "/arch/live-load",
            &bridge(
                (1.0, 1.0, 1.0, 1.0),
                Some(json!({"factors": {"live": 2.0}})),
            ),
        )
        .await;
    close(
        live["design"]["adequacy_factor"].as_f64().unwrap(),
        plain["load_factor"].as_f64().unwrap() / 2.0,
        "γ_l = 2",
    );
    for (factors, field) in [
        (json!({"dead": 0}), "design.factors.dead"),
        (json!({"strength": -1}), "design.factors.strength"),
        (json!({"live": 101}), "design.factors.live"),
    ] {
        let body = bridge((1.0, 1.0, 1.0, 1.0), Some(json!({"factors": factors})));
        let (status, content_type, problem) = server.post("/arch/live-load", &body).await;
        assert_problem(status, &content_type, &problem, 422, field);
    }
    let body = bridge(
        (1.0, 1.0, 1.0, 1.0),
        Some(json!({"factors": {"wind": 1.2}})),
    );
    let (status, _, _) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 422);
}

#[tokio::test]
async fn the_unfactored_lambda_docs_arches_states_for_its_assessment_example() {
    // docs/arches.md's assessment example without its check: λ = 1.3761 as its prose says.
    let server = Server::start().await;
    let body = json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
        "unit_weight": 2.0, "compressive_strength": 2000,
        "fill": {"unit_weight": 1.8, "surface": 11.5},
        "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}], "include": []});
    let (_, _, answer) = server.post("/arch/live-load", &body).await;
    let lambda = answer["load_factor"].as_f64().unwrap();
    assert!((lambda - 1.3761).abs() < 5e-5, "{lambda}");
}
