//! Rapid drawdown through HTTP (model §8): identities that follow from the three stages — an R
//! envelope far above the drained strength leaves every base drained (stage 3 everywhere: the
//! drained answer with the line after), and with φ′ = 0 an R envelope of c_R = c′, φ_R = 0 gives
//! τ_ff = c′ (stage 2, the same answer) — a search whose circle answers alone as it did, the
//! drawdown below the pool up, and bad input refused naming the field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

/// An upstream face at 3H:1V from a level foundation to a crest at 20; the pool at 18 before,
/// at 2 after, the line then along the face. Neither line crosses the circle below the ground,
/// so the stages' slices are those of the plain sections.
fn section(soil: Value) -> Value {
    json!({
        "ground": [[-20, 0], [0, 0], [60, 20], [75, 20]],
        "layers": [{"top": null, "soil": soil}],
        "drawdown": {"before": [[-20, 18], [54, 18], [75, 12]],
                     "after": [[-20, 2], [6, 2], [54, 18], [75, 12]]}
    })
}

fn request(section: Value) -> Value {
    json!({"section": section, "circle": {"centre": [10, 45], "radius": 47.5}, "slices": 40})
}

/// The same section drained, with `line` as its piezometric line.
fn drained(soil: Value, line: &str) -> Value {
    let mut s = section(soil);
    let water = s["drawdown"][line].clone();
    s.as_object_mut().unwrap().remove("drawdown");
    s["piezometric_line"] = water;
    if let Some(soil) = s["layers"][0]["soil"].as_object_mut() {
        soil.remove("r_envelope");
    }
    request(s)
}

async fn answer(server: &Server, body: &Value) -> Value {
    let (status, _, answer) = server.post("/slope/spencer", body).await;
    assert_eq!(status, 200, "{answer}");
    answer
}

fn factor(answer: &Value) -> f64 {
    answer["factor_of_safety"]
        .as_f64()
        .unwrap_or_else(|| panic!("{answer}"))
}

#[tokio::test]
async fn an_r_envelope_above_the_drained_strength_leaves_the_drained_answer() {
    let server = Server::start().await;
    let soil = json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 25,
                      "r_envelope": {"cohesion": 1e6, "friction_angle_deg": 30}});
    let drawdown = answer(&server, &request(section(soil.clone()))).await;
    let after = factor(&answer(&server, &drained(soil.clone(), "after")).await);
    let before = factor(&answer(&server, &drained(soil, "before")).await);
    let stages = &drawdown["drawdown"];
    assert_eq!(stages["stage"], 3, "{stages}");
    assert_eq!(stages["drained_slices"], stages["undrained_slices"]);
    assert_eq!(stages["undrained_slices"].as_array().unwrap().len(), 40);
    assert!((factor(&drawdown) - after).abs() <= 1e-12 * after);
    assert!((stages["before_factor_of_safety"].as_f64().unwrap() - before).abs() <= 1e-12 * before);
    // The pool down costs the slope its support.
    assert!(after < before, "{after} vs {before}");
}

#[tokio::test]
async fn a_frictionless_soil_whose_r_envelope_is_its_cohesion_keeps_its_strength() {
    let server = Server::start().await;
    let soil = json!({"unit_weight": 20, "cohesion": 40, "friction_angle_deg": 0,
                      "r_envelope": {"cohesion": 40, "friction_angle_deg": 0}});
    let drawdown = answer(&server, &request(section(soil.clone()))).await;
    let after = factor(&answer(&server, &drained(soil, "after")).await);
    assert_eq!(drawdown["drawdown"]["stage"], 2);
    assert!(
        (factor(&drawdown) - after).abs() <= 1e-10 * after,
        "{} vs {after}",
        factor(&drawdown)
    );
    assert!(
        (drawdown["drawdown"]["undrained_factor_of_safety"]
            .as_f64()
            .unwrap()
            - after)
            .abs()
            <= 1e-10 * after
    );
}

#[tokio::test]
async fn a_search_answers_a_circle_that_answers_alone_as_it_did() {
    let server = Server::start().await;
    let soil = json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 25,
                      "r_envelope": {"cohesion": 15, "friction_angle_deg": 15}});
    let searched = answer(
        &server,
        &json!({"section": section(soil.clone()), "search": {}, "slices": 40}),
    )
    .await;
    let f = factor(&searched);
    let c = &searched["circle"];
    let alone = answer(
        &server,
        &json!({"section": section(soil.clone()), "slices": 40,
                "circle": {"centre": [c["centre"]["x"], c["centre"]["y"]], "radius": c["radius"]}}),
    )
    .await;
    assert!(
        (factor(&alone) - f).abs() <= 1e-9 * f,
        "{} vs {f}",
        factor(&alone)
    );
    assert_eq!(alone["drawdown"], searched["drawdown"]);
    // The fixed circle of the other tests is no more critical than the search's.
    let fixed = factor(&answer(&server, &request(section(soil.clone()))).await);
    assert!(f <= fixed + 1e-9, "{f} vs {fixed}");
    // The pool up, drained, was safer on the searched circle.
    let before = searched["drawdown"]["before_factor_of_safety"]
        .as_f64()
        .unwrap();
    assert!(f < before);
    // A slow drawdown (every soil drained, the line after) leaves the face safer (the docs'
    // example).
    let mut slow = section(soil.clone());
    slow["piezometric_line"] = slow["drawdown"]["after"].take();
    slow.as_object_mut().unwrap().remove("drawdown");
    slow["layers"][0]["soil"]
        .as_object_mut()
        .unwrap()
        .remove("r_envelope");
    let slow = factor(
        &answer(
            &server,
            &json!({"section": slow, "search": {}, "slices": 40}),
        )
        .await,
    );
    assert!(f < slow, "{f} vs {slow}");
}

#[tokio::test]
async fn bad_drawdowns_are_refused_naming_the_field() {
    let server = Server::start().await;
    let soil = json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 25,
                      "r_envelope": {"cohesion": 15, "friction_angle_deg": 15}});
    let plain = json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 25});
    let mut both = section(soil.clone());
    both["piezometric_line"] = json!([[-20, 5], [75, 5]]);
    let mut no_drawdown = section(soil.clone());
    no_drawdown.as_object_mut().unwrap().remove("drawdown");
    let mut ratio = section(soil.clone());
    ratio["layers"][0]["soil"]["pore_pressure_ratio"] = json!(0.2);
    let mut grid = section(soil.clone());
    grid["pore_pressure_grid"] = json!({"points": [[0, 0, 1], [10, 0, 1], [0, 10, 1]]});
    let mut model = section(json!({"unit_weight": 20, "r_envelope": {"cohesion": 15,
        "friction_angle_deg": 15}, "strength": {"model": "undrained", "cohesion": 20}}));
    model["layers"][0]["soil"]["strength"]["gradient"] = json!(0);
    let mut unordered = section(soil.clone());
    unordered["drawdown"]["before"] = json!([[10, 18], [0, 18]]);
    let envelope = |r: Value| {
        section(
            json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 25,
                       "r_envelope": r}),
        )
    };
    let cases: Vec<(Value, &str)> = vec![
        (request(both), "section.piezometric_line"),
        (request(no_drawdown), "section.layers[0].soil.r_envelope"),
        (request(section(plain)), "section.drawdown"),
        (request(ratio), "section.layers[0]"),
        (request(grid), "section.drawdown"),
        (request(model), "section.layers[0].soil.r_envelope"),
        (request(unordered), "section.drawdown.before"),
        (
            request(envelope(json!({"cohesion": -1, "friction_angle_deg": 15}))),
            "section.layers[0].soil.r_envelope.cohesion",
        ),
        (
            request(envelope(json!({"cohesion": 1, "friction_angle_deg": 90}))),
            "section.layers[0].soil.r_envelope.friction_angle_deg",
        ),
        (
            request(envelope(json!({"cohesion": 0, "friction_angle_deg": 0}))),
            "section.layers[0].soil.r_envelope",
        ),
        (
            json!({"slope": {"height": 10, "length": 20}, "soil": soil,
                   "circle": {"x": 5, "y": 20}}),
            "soil.r_envelope",
        ),
    ];
    for (body, field) in cases {
        let (status, content_type, problem) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &problem, 422, field);
    }
}

#[tokio::test]
async fn the_drawing_shows_both_water_lines_and_the_soil_that_does_not_drain() {
    let server = Server::start().await;
    let soil = json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 25,
                      "r_envelope": {"cohesion": 15, "friction_angle_deg": 15}});
    // One soil that does not drain is named in the key.
    let (_, _, one) = server
        .post_accept(
            "/slope/spencer/svg",
            "image/svg+xml",
            &request(section(soil.clone())),
        )
        .await;
    assert!(
        one.contains("undrained in the drawdown: R envelope c_R = 15"),
        "{one}"
    );
    // With a foundation that drains.
    let mut two = section(soil);
    two["layers"].as_array_mut().unwrap().push(json!({
        "top": [[-20, -1], [75, -1]],
        "soil": {"unit_weight": 21, "cohesion": 0, "friction_angle_deg": 36}}));
    let (status, content_type, svg) = server
        .post_accept("/slope/spencer/svg", "image/svg+xml", &request(two))
        .await;
    assert_eq!(status, 200, "{svg}");
    assert!(content_type.starts_with("image/svg+xml"), "{content_type}");
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let texts = common::svg_texts(&doc);
    for words in [
        "piezometric line before the drawdown",
        "piezometric line after the drawdown",
        "undrained in the drawdown: R envelope c_R = 15, φ_R = 15°",
    ] {
        assert!(
            texts.iter().any(|t| t.contains(words)),
            "{words} is not in the key: {texts:?}"
        );
    }
    // Both lines drawn dashed, each in its own colour.
    let dashed: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke-dasharray").is_some())
        .filter_map(|n| n.attribute("stroke"))
        .collect();
    assert!(
        dashed.contains(&"#80d8ff") && dashed.contains(&"#0277bd"),
        "{dashed:?}"
    );
}

#[tokio::test]
async fn a_design_check_factors_the_r_envelope_as_the_effective_strength() {
    let server = Server::start().await;
    // DA1-2's M2: tan φ/1.25, c/1.25, on c′, φ′ and on c_R, φ_R alike; γ_γ = 1.
    let soil = |c: f64, phi: f64, c_r: f64, phi_r: f64| {
        json!({"unit_weight": 20, "cohesion": c, "friction_angle_deg": phi,
               "r_envelope": {"cohesion": c_r, "friction_angle_deg": phi_r}})
    };
    let mut designed = request(section(soil(10.0, 25.0, 15.0, 15.0)));
    designed["design"] = json!({"approach": "DA1-2"});
    let designed = answer(&server, &designed).await;
    let reduced = |deg: f64| (deg.to_radians().tan() / 1.25).atan().to_degrees();
    let by_hand = answer(
        &server,
        &request(section(soil(
            10.0 / 1.25,
            reduced(25.0),
            15.0 / 1.25,
            reduced(15.0),
        ))),
    )
    .await;
    let f = factor(&by_hand);
    assert!(
        (designed["design"]["factor_of_safety"].as_f64().unwrap() - f).abs() <= 1e-9 * f,
        "{} vs {f}",
        designed["design"]
    );
    assert_eq!(designed["drawdown"], by_hand["drawdown"]);
}
