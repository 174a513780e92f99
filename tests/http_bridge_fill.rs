//! Fill, road loads, passive restraint and rolling axles on multi-ring arches and spans on piers
//! (model §5.1–5.4): the fill lies on the outer ring's extrados and on the pier tops.

// Test scaffolding: a failed request should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

fn circular(extra: Value) -> Value {
    let mut g = json!({"kind": "circular", "radius": 10.0, "thickness": 1.2, "voussoirs": 24,
                       "voussoir": "quadrilateral"});
    for (k, v) in extra.as_object().unwrap() {
        g[k] = v.clone();
    }
    g
}

fn factor(answer: &Value) -> f64 {
    answer["load_factor"].as_f64().unwrap()
}

#[tokio::test]
async fn two_bonded_rings_under_fill_are_one_ring_of_their_thickness() {
    // Aligned joints, ring interfaces that can neither open nor slide: the two rings are the
    // one-ring arch of quadrilateral voussoirs of the total thickness, whose extrados (the
    // chords between the outer corners) is the outer ring's. Same fill, same road load, same
    // passive restraint: the same λ (the chain and the general formulation, to 1e-6).
    let server = Server::start().await;
    let fill = json!({"unit_weight": 1.8, "surface": 12.0, "dispersal_angle_deg": 30,
                      "passive": {"friction_angle_deg": 30, "mobilisation": 0.3}});
    let road = json!([{"x": -4.0, "fy": -10.0, "length": 0.5}]);
    let one = json!({"geometry": circular(json!({})), "fill": fill, "road_loads": road});
    let two = json!({"geometry": circular(json!({"rings": 2, "ring_joints": "aligned"})),
                     "ring_interface_limits": {"q_min": null, "s_min": null},
                     "fill": fill, "road_loads": road});
    let (status, _, a) = server.post("/arch/live-load", &one).await;
    assert_eq!(status, 200, "{a}");
    let (status, _, b) = server.post("/arch/live-load", &two).await;
    assert_eq!(status, 200, "{b}");
    let (la, lb) = (factor(&a), factor(&b));
    assert!(
        la > 0.0 && (la - lb).abs() <= 1e-6 * la,
        "one ring {la}, two rings {lb}"
    );
    let (wa, wb) = (
        a["fill_weight"].as_f64().unwrap(),
        b["fill_weight"].as_f64().unwrap(),
    );
    assert!((wa - wb).abs() <= 1e-9 * wa, "fill weights {wa} and {wb}");
}

#[tokio::test]
async fn the_fill_of_two_spans_weighs_what_lies_over_their_rings_and_the_pier() {
    // Two semicircular spans of two staggered rings on a pier 4 wide: the outer ring's
    // extrados is the polygon through the 2N + 1 half-steps on the outer circle (the outer
    // ring is the shifted one), so the fill over a span is y_r·2R_o − N·R_o²·sin(π/(2N)) (2N
    // triangles of the inscribed half-polygon), and over the pier y_r times its top's width,
    // pitch − 2R_o with pitch = 2R_i + width.
    let server = Server::start().await;
    let (n, r, d, width, road, gamma) = (24.0, 10.0, 1.2, 4.0, 12.5, 1.8);
    let geometry =
        circular(json!({"rings": 2, "spans": 2, "pier_width": width, "pier_height": 4.0}));
    let body = json!({"geometry": geometry, "fill": {"unit_weight": gamma, "surface": road}});
    let (status, _, answer) = server.post("/arch/dead-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    let (r_out, r_in): (f64, f64) = (r + d / 2.0, r - d / 2.0);
    let under = n * r_out * r_out * (std::f64::consts::PI / (2.0 * n)).sin();
    let pitch = 2.0 * r_in + width;
    let expected = gamma * (2.0 * (road * 2.0 * r_out - under) + road * (pitch - 2.0 * r_out));
    let weight = answer["fill_weight"].as_f64().unwrap();
    assert!(
        (weight - expected).abs() <= 1e-9 * expected,
        "fill weight {weight}, expected {expected}"
    );
    assert_eq!(answer["stable"], true, "{answer}");
}

#[tokio::test]
async fn axles_roll_over_a_two_ring_arch_symmetrically_and_passive_restraint_helps() {
    // A symmetric two-ring arch (aligned joints: the rings may part, not slide) and one axle
    // rolled over stops symmetric about the crown: λ(x) = λ(−x). Passive restraint never
    // lowers λ. (Staggered rings that cannot slide on each other form no mechanism at all.)
    let server = Server::start().await;
    let geometry = circular(
        json!({"rings": 2, "ring_joints": "aligned", "thickness": 1.0,
                                   "voussoirs": 16}),
    );
    let rolling = json!({"axles": [{"fy": -10.0}], "x_start": -6.0, "x_end": 6.0, "positions": 7});
    let body = json!({"geometry": geometry, "fill": {"unit_weight": 1.8, "surface": 12.0},
                      "rolling": rolling});
    let (status, _, plain) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{plain}");
    let curve: Vec<f64> = plain["rolling"]["load_factor"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_f64().unwrap())
        .collect();
    assert_eq!(curve.len(), 7);
    for k in 0..3 {
        let (a, b) = (curve[k], curve[6 - k]);
        assert!(
            (a - b).abs() <= 1e-5 * a.abs().max(b.abs()),
            "stops {k}: {a} against {b}"
        );
    }
    let mut restrained = body.clone();
    restrained["fill"]["passive"] = json!({"friction_angle_deg": 30, "mobilisation": 0.5});
    let (status, _, restrained) = server.post("/arch/live-load", &restrained).await;
    assert_eq!(status, 200, "{restrained}");
    let (free, held) = (factor(&plain), factor(&restrained));
    assert!(
        held >= free * (1.0 - 1e-7),
        "passive {held} < without {free}"
    );
}

#[tokio::test]
async fn a_general_assembly_still_has_no_fill() {
    let server = Server::start().await;
    let geometry = json!({"kind": "assembly",
        "blocks": [{"polygon": [[-1, 0], [1, 0], [1, 1], [-1, 1]]}],
        "supports": [{"polygon": [[-3, -1], [3, -1], [3, 0], [-3, 0]]}]});
    for (extra, field) in [
        (json!({"fill": {"unit_weight": 1, "surface": 3}}), "fill"),
        (
            json!({"rolling": {"axles": [{"fy": -1}], "x_start": 0, "x_end": 0}}),
            "rolling",
        ),
        (json!({"road_loads": [{"x": 0, "fy": -1}]}), "road_loads"),
    ] {
        let mut body = json!({"geometry": geometry, "loads": [{"block": 1, "fx": 1}]});
        for (k, v) in extra.as_object().unwrap() {
            body[k] = v.clone();
        }
        let (status, content_type, answer) = server.post("/arch/live-load", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
}
