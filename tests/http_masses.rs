//! A circle that cuts the ground more than twice (SPEC §14): the largest mass within the section
//! is analysed by default, `circle.mass` chooses another, and the answer names the others
//! (`several_masses`).
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

/// A valley between two faces; the circle (25, 20), R 19 dips below both faces but not below
/// the valley floor.
const GROUND: [(f64, f64); 6] = [
    (0.0, 10.0),
    (10.0, 10.0),
    (20.0, 0.0),
    (30.0, 0.0),
    (40.0, 8.0),
    (60.0, 8.0),
];
const CENTRE: (f64, f64) = (25.0, 20.0);
const RADIUS: f64 = 19.0;

fn body(mass: Option<Value>) -> Value {
    let mut circle = json!({"centre": [CENTRE.0, CENTRE.1], "radius": RADIUS});
    if let Some(m) = mass {
        circle["mass"] = m;
    }
    json!({"section": {"ground": GROUND, "layers": [{"top": null,
        "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 25}}]},
        "circle": circle, "slices": 30, "include": []})
}

fn ground(x: f64) -> f64 {
    let w = GROUND.windows(2).find(|w| x <= w[1].0).unwrap();
    w[0].1 + (w[1].1 - w[0].1) * (x - w[0].0) / (w[1].0 - w[0].0)
}

fn arc(x: f64) -> f64 {
    CENTRE.1 - (RADIUS * RADIUS - (x - CENTRE.0).powi(2)).max(0.0).sqrt()
}

/// The masses found independently: where ground − arc changes sign (bisection on a fine scan),
/// and each mass's area by the trapezoidal rule.
fn masses() -> Vec<(f64, f64, f64)> {
    let depth = |x: f64| ground(x) - arc(x);
    let n = 60_000;
    let xs: Vec<f64> = (0..=n)
        .map(|i| CENTRE.0 - RADIUS + 2.0 * RADIUS * f64::from(i) / f64::from(n))
        .collect();
    let mut crossings = Vec::new();
    for w in xs.windows(2) {
        if (depth(w[0]) > 0.0) != (depth(w[1]) > 0.0) {
            let (mut a, mut b) = (w[0], w[1]);
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if (depth(m) > 0.0) == (depth(a) > 0.0) {
                    a = m;
                } else {
                    b = m;
                }
            }
            crossings.push(0.5 * (a + b));
        }
    }
    crossings
        .chunks(2)
        .map(|c| {
            let (a, b) = (c[0], c[1]);
            let steps = 20_000;
            let h = (b - a) / f64::from(steps);
            let area: f64 = (0..steps)
                .map(|i| {
                    let x = a + h * f64::from(i);
                    0.5 * h * (depth(x).max(0.0) + depth(x + h).max(0.0))
                })
                .sum();
            (a, b, area)
        })
        .collect()
}

fn ends(answer: &Value) -> (f64, f64) {
    let c = &answer["circle"];
    let (a, b) = (
        c["lower_end"]["x"].as_f64().unwrap(),
        c["upper_exit"]["x"].as_f64().unwrap(),
    );
    (a.min(b), a.max(b))
}

#[tokio::test]
async fn the_largest_mass_is_analysed_and_the_others_named() {
    let found = masses();
    assert_eq!(found.len(), 2, "{found:?}");
    let largest = if found[0].2 > found[1].2 { 0 } else { 1 };
    let server = Server::start().await;
    for mass in [None, Some(json!("largest"))] {
        let (status, _, answer) = server.post("/slope/spencer", &body(mass)).await;
        assert_eq!(status, 200, "{answer}");
        let (a, b) = ends(&answer);
        let (x0, x1, _) = found[largest];
        assert!(
            (a - x0).abs() < 1e-6 && (b - x1).abs() < 1e-6,
            "{a} … {b} vs {x0} … {x1}"
        );
        let warning = common::warning(&answer, "several_masses");
        let message = warning["message"].as_str().unwrap();
        let other = found[1 - largest];
        assert!(
            message.contains(&format!("{:.4} … {:.4}", other.0, other.1)),
            "{message}"
        );
    }
    // The other mass, chosen.
    let k = 2 - largest;
    let (status, _, answer) = server.post("/slope/spencer", &body(Some(json!(k)))).await;
    assert_eq!(status, 200, "{answer}");
    let (a, b) = ends(&answer);
    let (x0, x1, _) = found[1 - largest];
    assert!(
        (a - x0).abs() < 1e-6 && (b - x1).abs() < 1e-6,
        "{a} … {b} vs {x0} … {x1}"
    );
    // No third mass, masses count from 1, and a mass is "largest" or a whole number.
    for k in [
        json!(0),
        json!(3),
        json!(-1),
        json!(1.5),
        json!("smallest"),
        json!(1e9),
    ] {
        let (status, content_type, problem) = server.post("/slope/spencer", &body(Some(k))).await;
        assert_problem(status, &content_type, &problem, 422, "circle.mass");
    }
}

#[tokio::test]
async fn one_mass_has_no_warning() {
    let server = Server::start().await;
    let mut one = body(None);
    one["circle"]["radius"] = json!(17);
    one["circle"]["centre"] = json!([15, 20]);
    let (status, _, answer) = server.post("/slope/spencer", &one).await;
    assert_eq!(status, 200, "{answer}");
    assert!(!answer["warnings"].to_string().contains("several_masses"));
}
