//! `POST /arch/dead-load` and `POST /arch/live-load` over a real socket.

mod common;

use common::{assert_problem, milankovitch, with, Server};
use serde_json::{json, Value};

fn quarter_span_load() -> Value {
    json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
        "loads": [{"block": 26, "fx": 0.0, "fy": -1.0, "moment": 0.0}]
    })
}

#[tokio::test]
async fn milankovitch_thickness_1_0748_stands() {
    // model §1.4: λ₀ = 1 and no active constraints.
    let server = Server::start().await;
    let (status, _, body) = server.post("/arch/dead-load", &milankovitch(1.0748)).await;
    assert_eq!(status, 200, "{body}");
    assert_eq!(body["dead_load_factor"], 1.0);
    assert_eq!(body["stable"], true);
    assert_eq!(body["active_constraints"], json!([]));
    assert_eq!(body["mechanism"], Value::Null);
    assert_eq!(body["thrust_line"].as_array().unwrap().len(), 1801);
    assert_eq!(body["solver"]["status"], "solved");
}

#[tokio::test]
async fn milankovitch_thickness_1_0747_collapses_as_the_thesis_reports() {
    // model §1.4: interfaces 1 s 0.0° extrados, 356 q 35.5° intrados, 901 s 90.0° extrados,
    // 1446 q 144.5° intrados, 1801 s 180.0° extrados.
    let server = Server::start().await;
    let (status, _, body) = server.post("/arch/dead-load", &milankovitch(1.0747)).await;
    assert_eq!(status, 200, "{body}");
    assert_eq!(body["dead_load_factor"], 0.0);
    assert_eq!(body["stable"], false);
    let active: Vec<(u64, String, f64, String)> = body["active_constraints"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| {
            (
                a["interface"].as_u64().unwrap(),
                a["resultant"].as_str().unwrap().to_owned(),
                (a["angle_deg"].as_f64().unwrap() * 10.0).round() / 10.0,
                a["hinge"].as_str().unwrap().to_owned(),
            )
        })
        .collect();
    let expected = [
        (1, "s", 0.0, "extrados"),
        (356, "q", 35.5, "intrados"),
        (901, "s", 90.0, "extrados"),
        (1446, "q", 144.5, "intrados"),
        (1801, "s", 180.0, "extrados"),
    ];
    assert_eq!(active.len(), expected.len(), "{active:?}");
    for (got, want) in active.iter().zip(expected) {
        assert_eq!((got.0, got.1.as_str(), got.2, got.3.as_str()), want);
    }
    assert!(body["active_constraints"]
        .as_array()
        .unwrap()
        .iter()
        .all(|a| a["bound"] == "lower"));
    assert_eq!(body["hinges"].as_array().unwrap().len(), 5);
    assert_eq!(body["mechanism"]["blocks"].as_array().unwrap().len(), 1800);
}

#[tokio::test]
async fn live_load_near_quarter_span() {
    let server = Server::start().await;
    let (status, _, body) = server.post("/arch/live-load", &quarter_span_load()).await;
    assert_eq!(status, 200, "{body}");
    assert_eq!(body["stable"], true);
    let lambda = body["load_factor"].as_f64().unwrap();
    assert!(lambda > 0.0);
    assert_eq!(body["hinges"].as_array().unwrap().len(), 4);
    // Twice the load, half the factor (1e-8: interior-point tolerance).
    let doubled = with(
        quarter_span_load(),
        "loads",
        json!([{"block": 26, "fy": -2.0}]),
    );
    let (_, _, body) = server.post("/arch/live-load", &doubled).await;
    let half = body["load_factor"].as_f64().unwrap();
    assert!((2.0 * half - lambda).abs() < 1e-8 * lambda);
}

#[tokio::test]
async fn live_load_on_an_arch_that_cannot_stand_is_not_a_number() {
    // Issue 3: 200 with stable: false and load_factor: null.
    let server = Server::start().await;
    let body = with(quarter_span_load(), "geometry.thickness", json!(0.5));
    let (status, _, body) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{body}");
    assert_eq!(body["stable"], false);
    assert_eq!(body["load_factor"], Value::Null);
    assert_eq!(body["solver"]["status"], "dead_load_not_carried");
}

#[tokio::test]
async fn block_chain_input_matches_the_quadrilateral_generator() {
    let server = Server::start().await;
    let n = 16;
    let (r_in, r_out) = (9.25f64, 10.75f64);
    let corner = |r: f64, k: usize| {
        let phi = std::f64::consts::PI * k as f64 / n as f64;
        json!([r * phi.cos(), r * phi.sin()])
    };
    let blocks: Vec<Value> = (0..n)
        .map(|k| json!({"corners": [corner(r_in, k), corner(r_out, k), corner(r_out, k + 1), corner(r_in, k + 1)]}))
        .collect();
    let loads = json!([{"block": 4, "fy": -1.0}]);
    let chain = json!({"geometry": {"kind": "blocks", "blocks": blocks}, "loads": loads});
    let generated = json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": n, "voussoir": "quadrilateral"},
        "loads": loads
    });
    let (_, _, a) = server.post("/arch/live-load", &chain).await;
    let (_, _, b) = server.post("/arch/live-load", &generated).await;
    let (a, b) = (
        a["load_factor"].as_f64().unwrap(),
        b["load_factor"].as_f64().unwrap(),
    );
    assert!((a - b).abs() < 1e-8 * a, "{a} vs {b}");
}

#[tokio::test]
async fn bad_arch_inputs_are_422_naming_the_field() {
    let server = Server::start().await;
    let cases = [
        ("geometry.thickness", json!(20.0)),
        ("geometry.thickness", json!(-1.0)),
        ("geometry.radius", json!(0.0)),
        ("geometry.voussoirs", json!(0)),
        ("geometry.voussoirs", json!(10_001)),
        ("geometry.left_base_angle_deg", json!(90.0)),
        ("geometry.right_base_angle_deg", json!(-95.0)),
        ("unit_weight", json!(0.0)),
        ("interface_limits.q_min", json!(1.0)),
        ("interface_limits.s_max", json!(-1.0)),
        ("friction_coefficient", json!(-0.5)),
    ];
    for (field, value) in cases {
        let body = with(milankovitch(1.0748), field, value);
        let (status, content_type, body) = server.post("/arch/dead-load", &body).await;
        assert_problem(status, &content_type, &body, 422, field);
    }
    let cases = [
        ("loads", json!([])),
        ("loads", json!([{"block": 1, "fy": 0.0}])),
        ("loads[0].block", json!([{"block": 101, "fy": -1.0}])),
        ("loads[0].block", json!([{"block": 0, "fy": -1.0}])),
    ];
    for (field, loads) in cases {
        let body = with(quarter_span_load(), "loads", loads);
        let (status, content_type, body) = server.post("/arch/live-load", &body).await;
        assert_problem(status, &content_type, &body, 422, field);
    }
    // Blocks that do not share faces.
    let body = json!({"geometry": {"kind": "blocks", "blocks": [
        {"corners": [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]},
        {"corners": [[1.5, 0.0], [1.5, 1.0], [2.0, 1.0], [2.0, 0.0]]}]}});
    let (status, content_type, body) = server.post("/arch/dead-load", &body).await;
    assert_problem(
        status,
        &content_type,
        &body,
        422,
        "geometry.blocks[1].corners",
    );
    // Unknown geometry kind and unknown fields.
    let body = with(milankovitch(1.0748), "geometry.kind", json!("gothic"));
    let (status, content_type, _) = server.post("/arch/dead-load", &body).await;
    assert_eq!(
        (status, content_type.as_str()),
        (422, "application/problem+json")
    );
    let body = with(milankovitch(1.0748), "extra", json!(1));
    let (status, content_type, body) = server.post("/arch/dead-load", &body).await;
    assert_problem(status, &content_type, &body, 422, "extra");
}

#[tokio::test]
async fn minimum_thickness_of_milankovitch_semicircle() {
    // model §1.4: 0.10747 < d/R < 0.10748 at N = 1800, rupture 54.5° from the crown.
    let server = Server::start().await;
    let (status, _, body) = server
        .post("/arch/minimum-thickness", &milankovitch(1.0))
        .await;
    assert_eq!(status, 200, "{body}");
    assert_eq!(body["outcome"], "found");
    let ratio = body["thickness_to_radius"].as_f64().unwrap();
    assert!((0.10747..=0.10748).contains(&ratio), "{ratio}");
    assert!((body["rupture_angle_deg"].as_f64().unwrap() - 54.5).abs() < 0.05);
    assert_eq!(body["hinges"].as_array().unwrap().len(), 5);
    assert!(body["evaluations"].as_u64().unwrap() >= 2);
}

#[tokio::test]
async fn minimum_thickness_edges_and_bad_inputs() {
    let server = Server::start().await;
    let three = with(milankovitch(1.0), "geometry.voussoirs", json!(3));
    let (status, _, body) = server.post("/arch/minimum-thickness", &three).await;
    assert_eq!(status, 200);
    assert_eq!(body["outcome"], "stands_however_thin");
    assert_eq!(body["thickness"], Value::Null);

    let slippery = with(
        with(milankovitch(1.0), "geometry.voussoirs", json!(50)),
        "friction_coefficient",
        json!(0.2),
    );
    let (_, _, body) = server.post("/arch/minimum-thickness", &slippery).await;
    assert_eq!(body["outcome"], "never_stands");

    let mut tolerance = milankovitch(1.0);
    tolerance["tolerance"] = json!(0.5);
    let (status, content_type, body) = server.post("/arch/minimum-thickness", &tolerance).await;
    assert_problem(status, &content_type, &body, 422, "tolerance");

    let blocks = json!({"geometry": {"kind": "blocks", "blocks": [
        {"corners": [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]}]}});
    let (status, content_type, body) = server.post("/arch/minimum-thickness", &blocks).await;
    // Only circular and profile geometries have a minimum thickness: `blocks` is refused.
    assert_problem(status, &content_type, &body, 422, "geometry.kind");

    // A given thickness is checked as on the dead-load route (0 < D < 2R): it is the D of the
    // geometric factor of safety.
    let too_thick = with(milankovitch(1.0), "geometry.thickness", json!(50.0));
    let (status, content_type, body) = server.post("/arch/minimum-thickness", &too_thick).await;
    assert_problem(status, &content_type, &body, 422, "geometry.thickness");
    for (field, value) in [
        ("geometry.rings", json!(2)),
        ("geometry.spans", json!(2)),
        ("geometry.pier_width", json!(1.0)),
    ] {
        let bad = with(milankovitch(1.0), field, value);
        let (status, content_type, body) = server.post("/arch/minimum-thickness", &bad).await;
        assert_problem(status, &content_type, &body, 422, field);
    }
    // Without a thickness there is no geometric factor; nulls mean "not given".
    let mut bare = with(milankovitch(1.0), "geometry.voussoirs", json!(4));
    bare["geometry"]["thickness"] = Value::Null;
    bare["geometry"]["rings"] = Value::Null;
    let (status, _, body) = server.post("/arch/minimum-thickness", &bare).await;
    assert_eq!(status, 200, "{body}");
    assert_eq!(body["outcome"], "found");
    assert_eq!(body["geometric_factor_of_safety"], Value::Null);
}

/// Heyman's geometric factor of safety of Milankovitch's semicircle (N = 1800, d_min/R =
/// 0.10748, model §1.4) at D = 1.5, R = 10: 1.5 / 1.0748 = 1.39561 (5e-5 relative: the
/// published ratio has 5 digits).
#[tokio::test]
async fn geometric_factor_of_safety_is_thickness_over_minimum() {
    let server = Server::start().await;
    let (status, _, body) = server
        .post("/arch/minimum-thickness", &milankovitch(1.5))
        .await;
    assert_eq!(status, 200, "{body}");
    let factor = body["geometric_factor_of_safety"].as_f64().unwrap();
    let expected = 1.5 / 1.0748;
    assert!((factor - expected).abs() < 5e-5 * expected, "{factor}");
    let minimum = body["thickness"].as_f64().unwrap();
    assert!(
        (factor * minimum - 1.5).abs() < 1e-12,
        "{factor} × {minimum}"
    );
}

#[tokio::test]
async fn both_formulations_answer_alike_over_http() {
    let server = Server::start().await;
    let mut assembly = quarter_span_load();
    assembly["formulation"] = json!("assembly");
    let (_, _, chain) = server.post("/arch/live-load", &quarter_span_load()).await;
    let (status, _, general) = server.post("/arch/live-load", &assembly).await;
    assert_eq!(status, 200, "{general}");
    assert_eq!(chain["solver"]["formulation"], "chain");
    assert_eq!(general["solver"]["formulation"], "assembly");
    let (a, b) = (
        chain["load_factor"].as_f64().unwrap(),
        general["load_factor"].as_f64().unwrap(),
    );
    // 1e-7 relative: two interior-point solutions at tolerance 1e-10.
    assert!((a - b).abs() < 1e-7 * b, "{a} vs {b}");
    assert_eq!(
        chain["hinges"].as_array().unwrap().len(),
        general["hinges"].as_array().unwrap().len()
    );
}

#[tokio::test]
async fn solver_tolerance_is_a_documented_control() {
    let server = Server::start().await;
    let (_, _, tight) = server.post("/arch/live-load", &quarter_span_load()).await;
    let mut loose = quarter_span_load();
    loose["solver_tolerance"] = json!(1e-6);
    let (status, _, loose) = server.post("/arch/live-load", &loose).await;
    assert_eq!(status, 200, "{loose}");
    assert_eq!(tight["solver"]["tolerance"], 1e-10);
    assert_eq!(loose["solver"]["tolerance"], 1e-6);
    let (a, b) = (
        tight["load_factor"].as_f64().unwrap(),
        loose["load_factor"].as_f64().unwrap(),
    );
    // README table: tolerance 1e-6 is right to about 3e-8; allow 1e-6.
    assert!((a - b).abs() < 1e-6 * a, "{a} vs {b}");
    let mut bad = quarter_span_load();
    bad["solver_tolerance"] = json!(0.1);
    let (status, content_type, body) = server.post("/arch/live-load", &bad).await;
    assert_problem(status, &content_type, &body, 422, "solver_tolerance");
}

#[tokio::test]
async fn drawings_and_the_page() {
    let server = Server::start().await;
    let response = server
        .client
        .post(format!("{}/arch/live-load/svg", server.base))
        .json(&quarter_span_load())
        .send()
        .await
        .unwrap();
    assert_eq!(response.status().as_u16(), 200);
    assert!(response.headers()["content-type"]
        .to_str()
        .unwrap()
        .starts_with("image/svg+xml"));
    let svg = response.text().await.unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    // 100 voussoirs, a line of thrust, four hinges with their angles, the load as an arrow.
    assert_eq!(svg.matches("<polygon").count(), 100);
    assert!(svg.contains("stroke=\"#c62828\""));
    assert_eq!(svg.matches("<circle").count(), 4);
    assert!(svg.contains("18.0° intrados") && svg.contains("180.0° extrados"));
    assert!(svg.contains("marker-end=\"url(#arrow)\""));
    // Bad input to a drawing is the same problem+json as to the numbers.
    let bad = with(quarter_span_load(), "geometry.thickness", json!(-1.0));
    let (status, content_type, body) = server.post("/arch/live-load/svg", &bad).await;
    assert_problem(status, &content_type, &body, 422, "geometry.thickness");

    let (status, _, body) = server
        .post("/arch/dead-load/svg", &milankovitch(1.0747))
        .await;
    assert_eq!(status, 200);
    let svg = body.as_str().unwrap();
    assert!(svg.contains("λ₀ = 0") && svg.contains("35.5° intrados"));

    let response = server
        .client
        .get(format!("{}/", server.base))
        .send()
        .await
        .unwrap();
    assert!(response.headers()["content-type"]
        .to_str()
        .unwrap()
        .starts_with("text/html"));
    let page = response.text().await.unwrap();
    // The page builds its panels from a list: each example's route, and the drawings from the
    // /svg routes; nothing is loaded from elsewhere (the browser test solves and draws them).
    for needle in [
        "path: \"/arch/dead-load\"",
        "path: \"/arch/live-load\"",
        "path: \"/arch/minimum-thickness\"",
        "path: \"/slope/spencer\"",
        "/svg`",
    ] {
        assert!(page.contains(needle), "{needle}");
    }
    for external in ["src=\"http", "href=\"http", "@import", "fetch(\"http"] {
        assert!(!page.contains(external), "{external}");
    }
}

#[tokio::test]
async fn hinges_are_placed_and_reactions_carry_the_weight() {
    let server = Server::start().await;
    // Milankovitch 1.0747 (model §1.4): each hinge lies on the intrados (radius R − D/2) or the
    // extrados (R + D/2) at the polar angle of its joint.
    let (status, _, body) = server.post("/arch/dead-load", &milankovitch(1.0747)).await;
    assert_eq!(status, 200, "{body}");
    let hinges = body["hinges"].as_array().unwrap();
    assert_eq!(hinges.len(), 5);
    for h in hinges {
        let radius = match h["location"].as_str().unwrap() {
            "intrados" => 10.0 - 0.5 * 1.0747,
            _ => 10.0 + 0.5 * 1.0747,
        };
        let angle = h["angle_deg"].as_f64().unwrap().to_radians();
        let (x, y) = (h["x"].as_f64().unwrap(), h["y"].as_f64().unwrap());
        // 1e-9: the corner coordinates are computed the same way up to rounding.
        assert!((x - radius * angle.cos()).abs() < 1e-9 && (y - radius * angle.sin()).abs() < 1e-9);
    }
    // A thick semicircle (R = 10, D = 2, γ = 1.5) stands: its area is π·R·D, so the vertical
    // reactions carry 1.5·π·10·2 and the horizontal ones cancel; every joint's thrust lies
    // inside it (margin > 0).
    let body = serde_json::json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 2.0, "voussoirs": 90},
        "unit_weight": 1.5});
    let (status, _, body) = server.post("/arch/dead-load", &body).await;
    assert_eq!(status, 200, "{body}");
    let reactions = body["reactions"].as_array().unwrap();
    assert_eq!(reactions.len(), 2);
    assert_eq!(
        (
            reactions[0]["interface"].as_u64(),
            reactions[1]["interface"].as_u64()
        ),
        (Some(1), Some(91))
    );
    let weight = 1.5 * std::f64::consts::PI * 10.0 * 2.0;
    let sum = |key: &str| {
        reactions
            .iter()
            .map(|r| r[key].as_f64().unwrap())
            .sum::<f64>()
    };
    assert!(
        (sum("vertical") - weight).abs() < 1e-8 * weight,
        "{reactions:?}"
    );
    assert!(sum("horizontal").abs() < 1e-8 * weight);
    let margin = body["thrust_margin"].as_f64().unwrap();
    assert!(margin > 0.0 && margin <= 0.5, "{margin}");
    for point in body["thrust_line"].as_array().unwrap() {
        let ratio = point["eccentricity_ratio"].as_f64().unwrap();
        assert!(ratio.abs() <= 0.5 - margin + 1e-12);
        assert_eq!(
            point["in_middle_third"].as_bool().unwrap(),
            ratio.abs() <= 1.0 / 6.0
        );
    }
}

#[tokio::test]
async fn locked_rings_say_why_no_load_collapses_them() {
    // model §6.5: two rings that cannot slip on each other interlock at their staggered joints:
    // the answer is unbounded, where the same arch as one ring does not even carry its weight
    // (D = 1.0 < Milankovitch's 1.0748); the warning says why. With ring friction, none.
    let server = Server::start().await;
    let body = |rings: usize, ring_friction: Option<f64>| {
        let mut b = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0,
                                        "voussoirs": 40, "rings": rings},
                           "loads": [{"block": 10, "fy": -1}]});
        if let Some(mu) = ring_friction {
            b["ring_friction_coefficient"] = json!(mu);
        }
        b
    };
    let (_, _, locked) = server.post("/arch/live-load", &body(2, None)).await;
    assert_eq!(locked["solver"]["status"], "unbounded", "{locked}");
    assert!(locked["warnings"].to_string().contains("rings_locked"));
    let (_, _, single) = server.post("/arch/live-load", &body(1, None)).await;
    assert_eq!(single["solver"]["status"], "dead_load_not_carried");
    assert_eq!(single["warnings"], json!([]));
    let (_, _, sliding) = server.post("/arch/live-load", &body(2, Some(0.6))).await;
    assert!(!sliding["warnings"].to_string().contains("rings_locked"));
}

#[tokio::test]
async fn locked_rings_far_above_the_bonded_single_ring_say_so() {
    // SPEC §6.5: with crushing (σ_c = 50) two staggered rings that cannot slip carry a finite
    // load, but far above one ring of the whole thickness (λ = 3.9095 for R = 10, D = 1.5,
    // N = 100, a unit load on block 26): the warning gives both, the single ring's from its
    // own request. Aligned rings (that can open, not slip: below the single ring) and rings
    // that can slip: none.
    let server = Server::start().await;
    let body = |rings: usize, joints: &str, extra: Value| {
        let mut b = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
                                        "voussoirs": 100, "rings": rings, "ring_joints": joints},
                           "loads": [{"block": 26, "fy": -1}], "compressive_strength": 50,
                           "include": []});
        for (k, v) in extra.as_object().unwrap() {
            b[k] = v.clone();
        }
        b
    };
    let (_, _, single) = server
        .post("/arch/live-load", &body(1, "staggered", json!({})))
        .await;
    let single = single["load_factor"].as_f64().unwrap();
    assert!((single - 3.9095).abs() < 1e-4, "{single}");
    let (status, _, locked) = server
        .post("/arch/live-load", &body(2, "staggered", json!({})))
        .await;
    assert_eq!(status, 200, "{locked}");
    let lambda = locked["load_factor"].as_f64().unwrap();
    assert!(lambda > 1.25 * single, "{lambda} vs {single}");
    let warnings = locked["warnings"].to_string();
    assert!(warnings.contains("rings_locked"), "{warnings}");
    assert!(warnings.contains(&format!("{single:.6}")), "{warnings}");
    assert!(
        warnings.contains(&format!("{:.2} times", lambda / single)),
        "{warnings}"
    );
    for (joints, extra) in [
        ("aligned", json!({})),
        ("staggered", json!({"ring_friction_coefficient": 0.6})),
    ] {
        let (_, _, answer) = server
            .post("/arch/live-load", &body(2, joints, extra))
            .await;
        // (With ring friction and crushing the dead load is not even carried: no λ.)
        let lambda = answer["load_factor"].as_f64().unwrap_or(0.0);
        assert!(lambda <= 1.25 * single, "{joints}: {lambda}");
        assert!(
            !answer["warnings"].to_string().contains("rings_locked"),
            "{joints}"
        );
    }
}
