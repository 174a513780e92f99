//! Friction and cohesion of their own (model §10): a block on its support slides at
//! λ = (μ·W + c·ℓ)/P, the statics written here; ring cohesion never lowers λ and a large one
//! gives the answer of rings that cannot slip (aligned rings; staggered ones lock outright);
//! bad interfaces are refused naming the field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, live_load_factor, Server};
use serde_json::{json, Value};

/// A unit block (W = γ·1 = 1) on a wide support, pushed sideways by P = 1 at y = 0.1: it
/// overturns about its corner at λ = W·0.5/(P·0.1) = 5, so sliding governs below that.
fn block(interfaces: Value) -> Value {
    json!({"geometry": {"kind": "assembly",
               "blocks": [{"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]}],
               "supports": [{"polygon": [[-2, -1], [3, -1], [3, 0], [-2, 0]]}]},
           "friction_coefficient": 0.8, "interfaces": interfaces,
           "loads": [{"block": 1, "fx": 1.0, "fy": 0.0, "x": 0.5, "y": 0.1}], "include": []})
}

#[tokio::test]
async fn a_block_slides_at_its_base_own_friction_and_cohesion() {
    let server = Server::start().await;
    // The arch's μ = 0.8 alone: λ = 0.8.
    let plain = live_load_factor(&server, &block(json!([]))).await;
    assert!((plain - 0.8).abs() < 1e-7, "{plain}");
    for (mu, c) in [(0.2, 0.0), (0.2, 0.3), (0.0, 0.4), (0.5, 1.2)] {
        let own = json!([{"blocks": [1, 0], "friction_coefficient": mu, "cohesion": c}]);
        let lambda = live_load_factor(&server, &block(own)).await;
        // Base length ℓ = 1, W = 1, P = 1.
        let expected = mu + c;
        assert!(
            (lambda - expected).abs() < 1e-7,
            "μ {mu}, c {c}: {lambda} against {expected}"
        );
    }
    // Cohesion alone on the arch's friction: λ = 0.8 + c.
    let cohesive = live_load_factor(
        &server,
        &block(json!([{"blocks": [0, 1], "cohesion": 0.5}])),
    )
    .await;
    assert!((cohesive - 1.3).abs() < 1e-7, "{cohesive}");
}

fn rings(ring_interface: Option<Value>, joints: &str) -> Value {
    let mut body = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.6,
                                       "voussoirs": 24, "rings": 2, "ring_joints": joints},
                          "friction_coefficient": 0.6,
                          "loads": [{"block": 8, "fy": -1.0}], "include": []});
    if let Some(r) = ring_interface {
        body["ring_interface"] = r;
    }
    body
}

/// λ, or 0 where the dead load is not carried (no live load is).
async fn carried(server: &Server, body: &Value) -> f64 {
    let (status, _, answer) = server.post("/arch/live-load", body).await;
    assert_eq!(status, 200, "{answer}");
    match answer["load_factor"].as_f64() {
        Some(lambda) => lambda,
        None => {
            assert_eq!(
                answer["solver"]["status"], "dead_load_not_carried",
                "{answer}"
            );
            0.0
        }
    }
}

#[tokio::test]
async fn ring_cohesion_never_lowers_lambda_and_a_large_one_bonds_the_rings() {
    let server = Server::start().await;
    let cohesive = |c: f64, joints: &str| {
        rings(
            Some(json!({"friction_coefficient": 0.2, "cohesion": c})),
            joints,
        )
    };
    for joints in ["staggered", "aligned"] {
        let mut last = 0.0;
        for c in [0.0, 0.3, 1.0, 3.0, 100.0, 1e4] {
            let lambda = carried(&server, &cohesive(c, joints)).await;
            assert!(
                lambda >= last * (1.0 - 1e-9),
                "{joints}, c {c}: {lambda} below {last}"
            );
            last = lambda;
        }
    }
    // Aligned rings with a large cohesion cannot slip: the answer of rings without ring
    // friction (they lock, each pair of ring blocks one voussoir).
    let bonded = live_load_factor(&server, &cohesive(1e4, "aligned")).await;
    let locked = live_load_factor(&server, &rings(None, "aligned")).await;
    assert!(
        (bonded - locked).abs() < 1e-8 * locked,
        "{bonded} against {locked}"
    );
    // Staggered rings that cannot slip lock outright (no mechanism crosses both rings): with
    // cohesion λ grows with it, without bound, and the cohesion-free answer is not carried.
    let (ten, thousand) = (
        live_load_factor(&server, &cohesive(10.0, "staggered")).await,
        live_load_factor(&server, &cohesive(1e4, "staggered")).await,
    );
    assert!(thousand > 50.0 * ten, "{ten} then {thousand}");
    // `ring_interface.friction_coefficient` is `ring_friction_coefficient`.
    let mut alias = rings(None, "aligned");
    alias["ring_friction_coefficient"] = json!(0.2);
    let (a, b) = (
        carried(&server, &alias).await,
        carried(&server, &cohesive(0.0, "aligned")).await,
    );
    assert!((a - b).abs() <= 1e-12 * a.max(1.0), "{a} against {b}");
}

#[tokio::test]
async fn bad_interfaces_are_refused_naming_the_field() {
    let server = Server::start().await;
    let cases = [
        (
            block(json!([{"blocks": [1, 0], "cohesion": -1.0}])),
            "interfaces[0].cohesion",
        ),
        (
            block(json!([{"blocks": [1, 0], "friction_coefficient": -0.1}])),
            "interfaces[0].friction_coefficient",
        ),
        (block(json!([{"blocks": [2, 0]}])), "interfaces[0].blocks"),
        (block(json!([{"blocks": [0, 0]}])), "interfaces[0].blocks"),
        (block(json!([{"blocks": [1, 1]}])), "interfaces[0].blocks"),
        (
            rings(Some(json!({"cohesion": 1.0})), "aligned"),
            "ring_interface.cohesion",
        ),
        (
            rings(
                Some(json!({"friction_coefficient": 0.2, "cohesion": -1.0})),
                "aligned",
            ),
            "ring_interface.cohesion",
        ),
        (
            {
                let mut b = rings(Some(json!({"friction_coefficient": 0.2})), "aligned");
                b["ring_friction_coefficient"] = json!(0.3);
                b
            },
            "ring_interface",
        ),
        (
            {
                let mut b = block(json!([]));
                b["ring_interface"] = json!({"friction_coefficient": 0.2});
                b
            },
            "ring_interface",
        ),
    ];
    for (body, field) in cases {
        let (status, content_type, problem) = server.post("/arch/live-load", &body).await;
        assert_problem(status, &content_type, &problem, 422, field);
    }
}

#[tokio::test]
async fn the_three_ring_arch_docs_arches_quotes() {
    // docs/arches.md, "Ring mortar": the example without cohesion (0.383) and without ring
    // friction (locked: unbounded, warned).
    let server = Server::start().await;
    let body = |ring: Option<Value>| {
        let mut b = json!({"geometry": {"kind": "profile", "shape": "segmental", "span": 6,
                "rise": 1.5, "thickness": 0.345, "voussoirs": 30, "rings": 3},
            "unit_weight": 20, "friction_coefficient": 0.6,
            "fill": {"unit_weight": 18, "surface": 2.2},
            "road_loads": [{"x": 1.5, "fy": -100, "length": 0.3}], "include": []});
        if let Some(r) = ring {
            b["ring_interface"] = r;
        }
        b
    };
    let codes = |answer: &Value| -> Vec<String> {
        answer["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w["code"].as_str().unwrap().to_owned())
            .collect()
    };
    let (status, _, slides) = server
        .post(
            "/arch/live-load",
            &body(Some(json!({"friction_coefficient": 0.5}))),
        )
        .await;
    assert_eq!(status, 200, "{slides}");
    let friction = slides["load_factor"].as_f64().unwrap();
    assert!((friction - 0.383).abs() < 5e-4, "{friction}");
    // Sliding between rings on friction alone is warned of, naming ring interfaces.
    assert!(
        codes(&slides).contains(&"rings_slide".to_owned()),
        "{slides}"
    );
    let (_, _, mortared) = server
        .post(
            "/arch/live-load",
            &body(Some(json!({"friction_coefficient": 0.5, "cohesion": 50}))),
        )
        .await;
    assert!(
        !codes(&mortared).contains(&"rings_slide".to_owned()),
        "{mortared}"
    );
    let (status, _, locked) = server.post("/arch/live-load", &body(None)).await;
    assert_eq!(status, 200);
    assert_eq!(locked["solver"]["status"], "unbounded", "{locked}");
    assert!(locked["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w["code"] == "rings_locked"));
}
