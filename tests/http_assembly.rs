//! Assemblies, multi-ring arches and spans on piers over HTTP (model §5.4, §5.6).

// Test scaffolding: a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

fn circular(extra: Value) -> Value {
    let mut g = json!({"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 40});
    for (k, v) in extra.as_object().unwrap() {
        g[k] = v.clone();
    }
    g
}

#[tokio::test]
async fn a_wall_panel_tips_or_slides_at_the_hand_computed_push() {
    // A 2 × 1 block on the ground with a 1 × 1 block centred on it, pushed at the top-left
    // corner: the top block tips at P = W_top/2 = 0.5 (γ = 1, P = 1), or slides first at
    // μ·W_top = 0.3 with μ = 0.3. Contacts are reported with the blocks they join.
    let server = Server::start().await;
    let geometry = json!({"kind": "assembly",
        "blocks": [{"polygon": [[-1, 0], [1, 0], [1, 1], [-1, 1]]},
                   {"polygon": [[-0.5, 1], [0.5, 1], [0.5, 2], [-0.5, 2]]}],
        "supports": [{"polygon": [[-3, -1], [3, -1], [3, 0], [-3, 0]]}]});
    let body = json!({"geometry": geometry, "loads": [{"block": 2, "x": -0.5, "y": 2, "fx": 1}]});
    let (status, _, tipping) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{tipping}");
    let lambda = tipping["load_factor"].as_f64().unwrap();
    assert!((lambda - 0.5).abs() < 1e-8, "{lambda}");
    assert_eq!(tipping["solver"]["formulation"], "assembly");
    assert_eq!(tipping["thrust_line"].as_array().unwrap().len(), 2);
    let mut sliding = body.clone();
    sliding["friction_coefficient"] = json!(0.3);
    let (status, _, sliding) = server.post("/arch/live-load", &sliding).await;
    assert_eq!(status, 200, "{sliding}");
    let lambda = sliding["load_factor"].as_f64().unwrap();
    assert!((lambda - 0.3).abs() < 1e-8, "{lambda}");
    assert!(!sliding["sliding_interfaces"].as_array().unwrap().is_empty());
    // The drawing of an assembly is well-formed SVG.
    let svg = server
        .client
        .post(format!("{}/arch/live-load/svg", server.base))
        .json(&body)
        .send()
        .await
        .unwrap()
        .text()
        .await
        .unwrap();
    assert!(roxmltree::Document::parse(&svg).is_ok(), "{svg}");
}

#[tokio::test]
async fn two_rings_stand_where_one_ring_of_their_thickness_falls() {
    // t/R = 0.10 < Milankovitch's 0.1075: one ring falls; two staggered rings that cannot slide
    // on each other stand; frictionless ring interfaces let each thin ring fall alone.
    let server = Server::start().await;
    let dead = |body: Value| {
        let server = &server;
        async move {
            let (status, _, answer) = server.post("/arch/dead-load", &body).await;
            assert_eq!(status, 200, "{answer}");
            answer["stable"].as_bool().unwrap()
        }
    };
    assert!(!dead(json!({"geometry": circular(json!({}))})).await);
    assert!(dead(json!({"geometry": circular(json!({"rings": 2}))})).await);
    assert!(
        !dead(json!({"geometry": circular(json!({"rings": 2})), "ring_friction_coefficient": 0}))
            .await
    );
    // Aligned joints with bonded rings are the one ring again.
    let bonded = json!({"geometry": circular(json!({"rings": 2, "ring_joints": "aligned"})),
                        "ring_interface_limits": {"q_min": null, "s_min": null}});
    assert!(!dead(bonded).await);
}

#[tokio::test]
async fn three_spans_on_piers_carry_a_load_on_the_first_span() {
    let server = Server::start().await;
    let body = json!({"geometry": circular(json!({"thickness": 1.5, "voussoirs": 30, "spans": 3,
                                                  "pier_width": 4, "pier_height": 6})),
                      "loads": [{"block": 8, "fy": -1}]});
    let (status, _, answer) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    assert!(answer["load_factor"].as_f64().unwrap() > 0.0);
    // Reactions: two abutments and two pier footings, carrying the weight and the load.
    let reactions = answer["reactions"].as_array().unwrap();
    assert_eq!(reactions.len(), 4, "{reactions:?}");
}

#[tokio::test]
async fn bad_assemblies_name_their_field() {
    let server = Server::start().await;
    let square = |x: f64, y: f64| json!({"polygon": [[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]]});
    let ground = json!([{"polygon": [[-5, -1], [5, -1], [5, 0], [-5, 0]]}]);
    let cases = [
        (
            json!({"kind": "assembly", "blocks": [square(0.0, 0.0), square(0.5, 0.0)], "supports": ground}),
            "geometry.blocks[0].polygon",
        ),
        (
            json!({"kind": "assembly", "blocks": [square(0.0, 0.0), square(0.0, 3.0)], "supports": ground}),
            "geometry.blocks[1].polygon",
        ),
        (
            json!({"kind": "assembly", "blocks": [square(0.0, 0.0)], "supports": []}),
            "geometry.supports",
        ),
        (
            json!({"kind": "assembly", "blocks": [{"polygon": [[0, 0], [1, 0]]}], "supports": ground}),
            "geometry.blocks[0].polygon",
        ),
        (circular(json!({"rings": 17})), "geometry.rings"),
        (circular(json!({"spans": 2})), "geometry.pier_width"),
        (
            circular(json!({"spans": 2, "pier_width": 1.0, "pier_height": 3})),
            "geometry.pier_width",
        ),
        (
            circular(json!({"spans": 2, "pier_width": 4.0, "pier_height": -3})),
            "geometry.pier_height",
        ),
    ];
    for (geometry, field) in cases {
        let (status, content_type, answer) = server
            .post("/arch/dead-load", &json!({"geometry": geometry}))
            .await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
    let (status, content_type, answer) = server
        .post(
            "/arch/dead-load",
            &json!({"geometry": circular(json!({})), "ring_friction_coefficient": 0.5}),
        )
        .await;
    assert_problem(
        status,
        &content_type,
        &answer,
        422,
        "ring_friction_coefficient",
    );
    // Ring limits out of range are an error even on one ring, where they do not apply
    // (schemathesis sent t_min = 9e307 with one ring, and it was answered 200).
    for rings in [1, 2] {
        let body = json!({"geometry": circular(json!({"rings": rings})),
            "ring_interface_limits": {"t_min": 9.27e307}});
        let (status, content_type, answer) = server.post("/arch/dead-load/svg", &body).await;
        assert_problem(
            status,
            &content_type,
            &answer,
            422,
            "ring_interface_limits.t_min",
        );
    }
    // So on the minimum-thickness route, which takes one ring (schemathesis sent q_min = 5e-324
    // there, and it was answered 200).
    let body = json!({"geometry": {"kind": "circular", "radius": 10, "voussoirs": 10},
        "ring_interface_limits": {"q_min": 5e-324}});
    let (status, content_type, answer) = server.post("/arch/minimum-thickness", &body).await;
    assert_problem(
        status,
        &content_type,
        &answer,
        422,
        "ring_interface_limits.q_min",
    );
    // The road of a fill must clear the outer ring's crown (R + D/2 = 11 here).
    let (status, content_type, answer) = server
        .post(
            "/arch/dead-load",
            &json!({"geometry": circular(json!({"rings": 2})), "fill": {"unit_weight": 1, "surface": 10.5}}),
        )
        .await;
    assert_problem(status, &content_type, &answer, 422, "fill.surface");
}

#[tokio::test]
async fn friction_is_checked_without_dilatancy_and_the_flag_only_rises_when_it_matters() {
    let server = Server::start().await;
    // An arch that slides at a joint and a springing: the check finds the same λ, so the flag
    // that used to cry wolf stays down, and the corrected mechanism is answered.
    let arch = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 2.0, "voussoirs": 20},
                      "friction_coefficient": 0.4, "loads": [{"block": 6, "fy": -1}]});
    let (status, _, answer) = server.post("/arch/live-load", &arch).await;
    assert_eq!(status, 200, "{answer}");
    assert!(!answer["sliding_interfaces"].as_array().unwrap().is_empty());
    assert_eq!(answer["friction_may_overestimate"], false);
    let check = &answer["non_associative"];
    assert_eq!(check["settled"], true, "{check}");
    assert!(check["corrected_mechanism"].is_object());
    // Issue 39: `include: []` leaves out every optional block, the nested mechanism too.
    let mut lean = arch.clone();
    lean["include"] = json!([]);
    let (_, _, lean) = server.post("/arch/live-load", &lean).await;
    assert_eq!(lean["non_associative"]["settled"], true, "{lean}");
    assert!(
        lean["non_associative"]["corrected_mechanism"].is_null(),
        "{lean}"
    );
    assert!(lean["mechanism"].is_null());
    // Two leaves under a cap: the associative 0.25 over-estimates; non_associative answers less.
    let wall = json!({"geometry": {"kind": "assembly",
        "blocks": [{"polygon": [[0, 0], [0.5, 0], [0.5, 2], [0, 2]]},
                   {"polygon": [[0.5, 0], [1, 0], [1, 2], [0.5, 2]]},
                   {"polygon": [[0, 2], [1, 2], [1, 2.5], [0, 2.5]]}],
        "supports": [{"polygon": [[-2, -1], [3, -1], [3, 0], [-2, 0]]}]},
        "friction_coefficient": 0.5, "loads": [{"block": 3, "x": 0, "y": 2.5, "fx": 1}]});
    let (status, _, associative) = server.post("/arch/live-load", &wall).await;
    assert_eq!(status, 200, "{associative}");
    assert_eq!(associative["friction_may_overestimate"], true);
    // The same as a warning (SPEC §6.1), with the sliding interfaces the answer lists.
    let warning = common::warning(&associative, "friction_may_overestimate").clone();
    assert_eq!(warning["interfaces"], associative["sliding_interfaces"]);
    let assoc = associative["load_factor"].as_f64().unwrap();
    let mut body = wall.clone();
    body["friction"] = json!("non_associative");
    let (status, _, answer) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    let na = answer["load_factor"].as_f64().unwrap();
    assert!(na < assoc, "{na} vs {assoc}");
    assert_eq!(answer["non_associative"]["settled"], true);
    assert_eq!(
        answer["non_associative"]["load_factor"].as_f64().unwrap(),
        na
    );
    assert_eq!(answer["friction_may_overestimate"], false);
    assert!(!answer["warnings"]
        .to_string()
        .contains("friction_may_overestimate"));
    assert!(answer["non_associative"]["mixing_from_step"].is_null());
    // Leaves 0.3 × 1 under a 0.6 × 0.5 cap, μ = 0.9: the paper's relaxation oscillates for
    // its 50 steps; the mixing settles it on the state worked out by hand in the solver's
    // tests: the right leaf and the cap overturn, the left leaf pressing with
    // N = 0.3μ/(1 + μ²), 1.5λ = 0.045 + 0.09 + 0.3μN.
    let mut leaves = body.clone();
    leaves["geometry"]["blocks"] = json!([{"polygon": [[0, 0], [0.3, 0], [0.3, 1], [0, 1]]},
                                          {"polygon": [[0.3, 0], [0.6, 0], [0.6, 1], [0.3, 1]]},
                                          {"polygon": [[0, 1], [0.6, 1], [0.6, 1.5], [0, 1.5]]}]);
    leaves["friction_coefficient"] = json!(0.9);
    leaves["loads"] = json!([{"block": 3, "x": 0, "y": 1.5, "fx": 1}]);
    let (status, _, answer) = server.post("/arch/live-load", &leaves).await;
    assert_eq!(status, 200, "{answer}");
    let check = &answer["non_associative"];
    assert_eq!(check["settled"], true, "{check}");
    assert_eq!(check["mixing_from_step"], 50, "{check}");
    let n = 0.3 * 0.9 / (1.0 + 0.81);
    let by_hand = (0.045 + 0.09 + 0.3 * 0.9 * n) / 1.5;
    let na = answer["load_factor"].as_f64().unwrap();
    assert!((na - by_hand).abs() < 1e-6, "{na} vs {by_hand}");
    assert_eq!(answer["solver"]["status"], "solved");
    // `friction_relaxation: anderson`: the mixing from the first step, the same λ (to the
    // consistency tolerance) in fewer programmes; an unknown relaxation is a 422 naming it.
    let mut mixed = leaves.clone();
    mixed["friction_relaxation"] = json!("anderson");
    let (status, _, fast) = server.post("/arch/live-load", &mixed).await;
    assert_eq!(status, 200, "{fast}");
    assert_eq!(fast["non_associative"]["mixing_from_step"], 0, "{fast}");
    assert!((fast["load_factor"].as_f64().unwrap() - by_hand).abs() < 1e-6);
    let (slow, quick) = (
        answer["solver"]["programmes"].as_u64().unwrap(),
        fast["solver"]["programmes"].as_u64().unwrap(),
    );
    assert!(quick <= 12 && quick < slow, "{quick} vs {slow}");
    mixed["friction_relaxation"] = json!("aitken");
    let (status, content_type, problem) = server.post("/arch/live-load", &mixed).await;
    assert_problem(status, &content_type, &problem, 422, "friction_relaxation");
}

#[tokio::test]
async fn a_very_high_friction_coefficient_is_no_sliding() {
    // Issue 18, item 5: μ up to the documented 1e6 answers like no sliding at all (was
    // `reduced_accuracy` and no factor from μ ≈ 8000 on). 1e-7: the solver tolerance.
    let server = Server::start().await;
    let body = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
                      "loads": [{"block": 26, "fy": -1}]});
    let (status, _, bare) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{bare}");
    let reference = bare["load_factor"].as_f64().unwrap();
    for mu in [8000.0, 1e5, 1e6] {
        let mut with = body.clone();
        with["friction_coefficient"] = json!(mu);
        let (status, _, answer) = server.post("/arch/live-load", &with).await;
        assert_eq!(status, 200, "{answer}");
        assert_eq!(answer["solver"]["status"], "solved", "μ = {mu}: {answer}");
        let lambda = answer["load_factor"].as_f64().unwrap();
        assert!(
            (lambda - reference).abs() < 1e-7 * reference,
            "μ = {mu}: {lambda} vs {reference}"
        );
        assert_eq!(answer["friction_may_overestimate"], false);
    }
}

#[tokio::test]
async fn a_live_load_on_rings_whose_dead_load_falls_has_no_factor_and_the_dead_load_margin() {
    // Two frictionless rings of 0.3 each fall under their own weight. The live-load route
    // solves the dead-load margin beside the live-load programme (assemblies are solved side
    // by side) and must answer as the dead-load route, which solves the margin alone: no
    // factor, the same margin and the same collapse mechanism.
    let server = Server::start().await;
    let geometry = circular(json!({"thickness": 0.6, "rings": 2}));
    let dead = json!({"geometry": geometry, "ring_friction_coefficient": 0.0});
    let (status, _, falls) = server.post("/arch/dead-load", &dead).await;
    assert_eq!(status, 200, "{falls}");
    assert_eq!(falls["stable"], false);
    let mut live = dead.clone();
    live["loads"] = json!([{"block": 10, "fy": -1}]);
    let (status, _, answer) = server.post("/arch/live-load", &live).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["solver"]["status"], "dead_load_not_carried");
    assert!(answer["load_factor"].is_null());
    assert_eq!(answer["stable"], false);
    let margin = answer["dead_load_margin"].as_f64().unwrap();
    assert!(margin > 1e-3, "{margin}");
    assert!((margin - falls["dead_load_margin"].as_f64().unwrap()).abs() <= 1e-12);
    assert_eq!(answer["hinges"], falls["hinges"]);
    assert!(!answer["hinges"].as_array().unwrap().is_empty());
}

#[tokio::test]
async fn no_collapse_under_a_load_near_a_springing_is_settled_without_dilatancy_too() {
    // A load on the second voussoir of 27 (joints within 14° of horizontal, μ = 0.4: the load
    // goes into the springing inside the friction cone): no collapse at any factor, either
    // way. The iteration starts from the state at the cap and settles there (it used to answer
    // `not_settled` with no step); that state is not shown.
    let server = Server::start().await;
    let mut body = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 27},
                          "friction_coefficient": 0.4, "loads": [{"block": 2, "fy": -1}]});
    let (status, _, associative) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{associative}");
    assert_eq!(associative["solver"]["status"], "unbounded");
    body["friction"] = json!("non_associative");
    let (status, _, answer) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["solver"]["status"], "unbounded", "{answer}");
    assert!(answer["load_factor"].is_null());
    let steps = &answer["non_associative"];
    assert_eq!(steps["settled"], true, "{steps}");
    let factors = steps["load_factors"].as_array().unwrap();
    assert!(
        factors.len() >= 2 && factors.iter().all(|f| f.is_null()),
        "{steps}"
    );
    for shown in [&associative, &answer] {
        assert_eq!(shown["thrust_line"], json!([]), "{shown}");
        assert_eq!(shown["reactions"], json!([]), "{shown}");
    }
}

/// The reactions of an answer as (interface, horizontal, vertical).
fn reactions(answer: &Value) -> Vec<(u64, f64, f64)> {
    answer["reactions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            let f = |k: &str| r[k].as_f64().unwrap();
            (
                r["interface"].as_u64().unwrap(),
                f("horizontal"),
                f("vertical"),
            )
        })
        .collect()
}

#[tokio::test]
async fn the_state_shown_is_the_least_squeezed_one() {
    // Two unit blocks side by side on ground that cannot slide, pushed at the top-left corner:
    // the pair overturns at λ = 2, and its one state of least normal force (worked out in
    // crates/solver/tests/arch_state.rs) has the ground's reactions (−0.5, 0) under the left
    // block and (−1.5, 2) under the right one. Any other state squeezes the pair between the
    // two bases' shear (the interior-point state did, by 5e5).
    let server = Server::start().await;
    let geometry = json!({"kind": "assembly",
        "blocks": [{"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]},
                   {"polygon": [[1, 0], [2, 0], [2, 1], [1, 1]]}],
        "supports": [{"polygon": [[-1, -1], [3, -1], [3, 0], [-1, 0]]}]});
    let body = json!({"geometry": geometry, "loads": [{"block": 1, "x": 0, "y": 1, "fx": 1}]});
    let (status, _, answer) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    assert!((answer["load_factor"].as_f64().unwrap() - 2.0).abs() < 1e-8);
    let mut found = reactions(&answer);
    found.sort_by(|a, b| b.1.total_cmp(&a.1));
    let expected = [(-0.5, 0.0), (-1.5, 2.0)];
    for ((_, h, v), (eh, ev)) in found.iter().zip(expected) {
        assert!((h - eh).abs() < 1e-6 && (v - ev).abs() < 1e-6, "{answer}");
    }
    assert_eq!(answer["solver"]["programmes"], 3, "{answer}");

    // Two staggered rings (R 10, D 1.5, 20 voussoirs): the first blocks of the two rings at a
    // springing can be squeezed together against the support without limit (the contact
    // between them runs down to it), and the interior-point state showed reactions of ±6.7e5
    // there, cancelling but for the thrust. Under the dead load, with rings that cannot slide
    // on each other, nothing needs a squeeze: both rings push each springing outwards. Under a
    // point load with ring μ = 0.6 the associative collapse state needs some (it gives the
    // sliding ring contact at the springing its normal force), a bounded one: no reaction
    // comes near the weight. Both: Σ horizontal = 0, Σ vertical = W (+ λ).
    let rings =
        json!({"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 20, "rings": 2});
    let (status, _, dead) = server
        .post("/arch/dead-load", &json!({"geometry": rings}))
        .await;
    assert_eq!(status, 200, "{dead}");
    let weight: f64 = reactions(&dead).iter().map(|r| r.2).sum();
    assert!(
        (weight - 15.0 * std::f64::consts::PI).abs() < 0.01 * weight,
        "{dead}"
    );
    let line = dead["thrust_line"].as_array().unwrap();
    for (k, h, _) in reactions(&dead) {
        // The side of the contact from its point of action: the supports push the left
        // springing's contacts rightwards, the right's leftwards.
        let x = line[k as usize - 1]["x"].as_f64().unwrap();
        assert!(h * x < 0.0, "interface {k}: {dead}");
    }
    let body = json!({"geometry": rings, "ring_friction_coefficient": 0.6,
                      "loads": [{"block": 6, "fy": -1}]});
    let (status, _, live) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{live}");
    let lambda = live["load_factor"].as_f64().unwrap();
    for (shown, total) in [(&dead, weight), (&live, weight + lambda)] {
        let found = reactions(shown);
        assert_eq!(found.len(), 4, "{shown}");
        let horizontal: f64 = found.iter().map(|r| r.1).sum();
        let vertical: f64 = found.iter().map(|r| r.2).sum();
        assert!(horizontal.abs() < 1e-6 * weight, "{shown}");
        assert!((vertical - total).abs() < 1e-6 * weight, "{shown}");
        assert!(found.iter().all(|r| r.1.abs() < weight), "{shown}");
    }
}
