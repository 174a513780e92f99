//! What a search may answer (model §6.4): `search.min_depth` (no sliver along a c' = 0 face)
//! and `search.composite` (circles only, or circles that follow the bedrock).

// Test scaffolding: a missing field should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

/// A dry c' = 0 face at 1 : 2 (β = 26.57°), 10 high, φ' = 35°.
fn cohesionless(search: Value) -> Value {
    json!({"section": {"ground": [[0, 0], [20, 0], [40, 10], [60, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}]},
        "search": search, "slices": 50})
}

/// The greatest slice height of an answer: its surface's depth below the ground (at the slices'
/// middles).
fn depth(answer: &Value) -> f64 {
    answer["slices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["height"].as_f64().unwrap())
        .fold(0.0, f64::max)
}

#[tokio::test]
async fn a_cohesionless_face_answers_a_mechanism_not_a_sliver() {
    let server = Server::start().await;
    // Without a least depth the critical surface is a sliver of the infinite slope, whose F is
    // tan φ'/tan β = tan 35°/0.5 (derived by hand: a dry c' = 0 slope parallel to its face).
    let (status, _, sliver) = server
        .post("/slope/spencer", &cohesionless(json!({"min_depth": 0})))
        .await;
    assert_eq!(status, 200, "{sliver}");
    let infinite_slope = 35f64.to_radians().tan() / 0.5;
    let f = sliver["factor_of_safety"].as_f64().unwrap();
    assert!((f - infinite_slope).abs() < 1e-9, "{f} vs {infinite_slope}");
    assert!(depth(&sliver) < 0.05, "{}", depth(&sliver));
    // The default least depth, 2 % of the height (0.2): a surface at least that deep, above
    // the sliver's F.
    let (_, _, default) = server
        .post("/slope/spencer", &cohesionless(json!({})))
        .await;
    assert_eq!(default["search"]["min_depth"], 0.2);
    assert!(depth(&default) >= 0.2, "{}", depth(&default));
    let g = default["factor_of_safety"].as_f64().unwrap();
    assert!(g > f + 1e-4, "{g} vs {f}");
    // The values docs/slopes.md shows.
    assert!((g - 1.4039).abs() < 5e-5, "{g}");
    // Deeper still when asked.
    let (_, _, deep) = server
        .post("/slope/spencer", &cohesionless(json!({"min_depth": 1.0})))
        .await;
    assert!(depth(&deep) >= 1.0, "{}", depth(&deep));
    let h = deep["factor_of_safety"].as_f64().unwrap();
    assert!(h >= g);
    assert!((h - 1.4191).abs() < 5e-5, "{h}");
}

#[tokio::test]
async fn circles_only_keeps_a_search_off_the_bedrock() {
    // A soft clay over bedrock that rises towards the crest: the deep circles cross it.
    let server = Server::start().await;
    let body = |composite: &str| {
        json!({"section": {"ground": [[0, 0], [20, 0], [40, 10], [60, 10]],
            "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 20, "friction_angle_deg": 5}}],
            "bedrock": [[0, -3], [60, 3]]},
            "search": {"composite": composite}, "slices": 50})
    };
    // How far the answer's circle dips below the bedrock along its surface (the bedrock line
    // written out here: y = −3 + x/10).
    let below = |answer: &Value| {
        let c = &answer["circle"];
        let (xc, yc, r) = (
            c["centre"]["x"].as_f64().unwrap(),
            c["centre"]["y"].as_f64().unwrap(),
            c["radius"].as_f64().unwrap(),
        );
        answer["surface"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                let x = p["x"].as_f64().unwrap();
                let arc = yc - (r * r - (x - xc).powi(2)).max(0.0).sqrt();
                (-3.0 + x / 10.0) - arc
            })
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (_, _, composite) = server.post("/slope/spencer", &body("follow_bedrock")).await;
    let (status, _, circle) = server.post("/slope/spencer", &body("circles_only")).await;
    assert_eq!(status, 200, "{circle}");
    assert_eq!(circle["search"]["composite"], "circles_only");
    assert!(below(&composite) > 0.01, "{}", below(&composite));
    assert!(below(&circle) < 1e-6, "{}", below(&circle));
    let (f, g) = (
        composite["factor_of_safety"].as_f64().unwrap(),
        circle["factor_of_safety"].as_f64().unwrap(),
    );
    assert!(g >= f, "circles only {g}, composite {f}");
}

#[tokio::test]
async fn candidate_options_are_validated() {
    let server = Server::start().await;
    for (search, field) in [
        (json!({"min_depth": -1}), "search.min_depth"),
        (json!({"min_depth": 2e9}), "search.min_depth"),
        (json!({"composite": "sometimes"}), "composite"),
    ] {
        let (status, content_type, body) =
            server.post("/slope/spencer", &cohesionless(search)).await;
        assert_problem(status, &content_type, &body, 422, field);
    }
}

#[tokio::test]
async fn a_search_stays_within_the_stated_section_unless_told_otherwise() {
    // The ground stops 1 m behind the crest; the critical circle would exit further back, where
    // the ground is only taken as level. The search stays within the section (SPEC §14) and
    // says that its minimum reaches the section's end; with `beyond_ground` it goes on, and the
    // answer warns. A fixed circle beyond the ground is refused unless it says the same. The
    // simple slope, level beyond its ends by definition, is never bounded.
    let server = Server::start().await;
    let soil = json!({"unit_weight": 20, "cohesion": 20, "friction_angle_deg": 25});
    let section = json!({"ground": [[10, 0], [20, 0], [40, 10], [41, 10]],
        "layers": [{"top": null, "soil": soil}]});
    let short = json!({"section": section, "search": {}, "slices": 50});
    let (status, _, within) = server.post("/slope/spencer", &short).await;
    assert_eq!(status, 200, "{within}");
    let exit = within["circle"]["upper_exit"]["x"].as_f64().unwrap();
    let entry = within["circle"]["lower_end"]["x"].as_f64().unwrap();
    assert!(
        entry >= 10.0 - 1e-7 && exit <= 41.0 + 1e-7,
        "{entry} … {exit}"
    );
    let codes = within["warnings"].to_string();
    assert!(codes.contains("minimum_at_section_end"), "{codes}");
    assert!(!codes.contains("beyond the ground"), "{codes}");
    assert_eq!(within["search"]["beyond_ground"], false);
    let mut beyond = short.clone();
    beyond["search"]["beyond_ground"] = json!(true);
    let (_, _, answer) = server.post("/slope/spencer", &beyond).await;
    let exit = answer["circle"]["upper_exit"]["x"].as_f64().unwrap();
    assert!(exit > 41.0, "{exit}");
    assert!(answer["warnings"]
        .to_string()
        .contains("beyond the ground as stated"));
    assert_eq!(answer["search"]["beyond_ground"], true);
    let f_beyond = answer["factor_of_safety"].as_f64().unwrap();
    let f_within = within["factor_of_safety"].as_f64().unwrap();
    assert!(f_beyond < f_within, "{f_beyond} vs {f_within}");
    // The circle found beyond the ground, stated as a fixed circle: refused, then answered
    // with the same F when it says beyond_ground.
    let circle = &answer["circle"];
    let mut fixed = json!({"section": section, "slices": 50, "circle": {
        "centre": [circle["centre"]["x"], circle["centre"]["y"]], "radius": circle["radius"]}});
    let (status, content_type, problem) = server.post("/slope/spencer", &fixed).await;
    assert_problem(status, &content_type, &problem, 422, "circle");
    assert!(problem["detail"]
        .as_str()
        .unwrap()
        .contains("extend section.ground"));
    fixed["circle"]["beyond_ground"] = json!(true);
    let (status, _, again) = server.post("/slope/spencer", &fixed).await;
    assert_eq!(status, 200, "{again}");
    let g = again["factor_of_safety"].as_f64().unwrap();
    assert!((g - f_beyond).abs() < 1e-9 * g, "{g} vs {f_beyond}");
    let simple = json!({"slope": {"height": 10, "length": 20}, "soil": soil, "search": {},
                        "slices": 50});
    let (_, _, answer) = server.post("/slope/spencer", &simple).await;
    assert!(!answer["warnings"].to_string().contains("beyond the ground"));
    assert!(!answer["warnings"].to_string().contains("section_end"));
    assert_eq!(answer["search"]["beyond_ground"], true);
    let mut refused = simple.clone();
    refused["search"]["beyond_ground"] = json!(true);
    let (status, content_type, problem) = server.post("/slope/spencer", &refused).await;
    assert_problem(status, &content_type, &problem, 422, "search.beyond_ground");
}

#[tokio::test]
async fn options_that_would_be_ignored_are_refused() {
    // Issue 38: Morgenstern–Price's inter-slice function without Morgenstern–Price, and a line
    // load beyond the ground as stated, used to be accepted and ignored.
    let server = Server::start().await;
    let soil = json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 30});
    let section = |x: f64| {
        json!({"ground": [[0, 0], [20, 0], [40, 10], [60, 10]],
               "layers": [{"top": null, "soil": soil}],
               "line_loads": [{"x": x, "fx": 0, "fy": -50}]})
    };
    let circle = json!({"centre": [30, 30], "radius": 31});
    let body = json!({"section": section(50.0), "circle": circle,
                      "interslice_function": [[0, 0], [0.5, 1], [1, 0]], "methods": ["bishop"]});
    let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &answer, 422, "interslice_function");
    let body = json!({"section": section(50.0), "circle": circle,
                      "interslice_function": [[0, 0], [0.5, 1], [1, 0]],
                      "methods": ["morgenstern_price"]});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let body = json!({"section": section(75.0), "circle": circle});
    let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
    assert_problem(
        status,
        &content_type,
        &answer,
        422,
        "section.line_loads[0].x",
    );
}

#[tokio::test]
async fn the_non_circular_stage_keeps_to_the_least_depth_too() {
    // model §6.4: the polyline stage moves from the best circle; on a c' = 0 face it would
    // slide towards the sliver of no depth. Its trial surfaces shallower than min_depth are not
    // candidates either: the answer is at least 1.0 deep, and never above the circle's F.
    let server = Server::start().await;
    let search = |min_depth: f64| json!({"shape": "noncircular", "min_depth": min_depth, "max_evaluations": 400});
    let (status, _, deep) = server
        .post("/slope/spencer", &cohesionless(search(1.0)))
        .await;
    assert_eq!(status, 200, "{deep}");
    assert!(depth(&deep) >= 1.0, "{}", depth(&deep));
    let f = deep["factor_of_safety"].as_f64().unwrap();
    let (_, _, circle) = server
        .post("/slope/spencer", &cohesionless(json!({"min_depth": 1.0})))
        .await;
    assert!(f <= circle["factor_of_safety"].as_f64().unwrap() + 1e-12);
    // Without a least depth the stage finds the infinite slope's sliver (tan φ'/tan β).
    let (_, _, shallow) = server
        .post("/slope/spencer", &cohesionless(search(0.0)))
        .await;
    let g = shallow["factor_of_safety"].as_f64().unwrap();
    assert!(g < f, "{g} vs {f}");
    assert!(g >= 35f64.to_radians().tan() / 0.5 - 1e-9, "{g}");
}
