//! Fill layers (model §10, masonry backing at the haunches): the fill's weight equals the
//! integral of the layered column written here, a layer of the fill's own weight changes
//! nothing, heavier backing carries more; bad layers are refused naming the field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

/// A segmental arch of straight-faced voussoirs (a profile), 4 m span, 1 m rise, 0.4 m thick.
fn geometry() -> Value {
    json!({"kind": "profile", "shape": "segmental", "span": 4.0, "rise": 1.0, "thickness": 0.4,
           "voussoirs": 12})
}

const ROAD: f64 = 2.0;
const FILL: f64 = 18.0;

/// The column of fill from y to the road: `layers` as (below, γ), any order.
fn column(y: f64, layers: &[(f64, f64)]) -> f64 {
    let mut sorted = layers.to_vec();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
    // Integrate γ(η) over y < η < road by the layer whose band holds each η: the least level
    // above η, else the fill.
    let gamma = |eta: f64| sorted.iter().find(|l| l.0 > eta).map_or(FILL, |l| l.1);
    let n = 2000;
    let h = (ROAD - y).max(0.0) / n as f64;
    (0..n).map(|i| gamma(y + (i as f64 + 0.5) * h) * h).sum()
}

/// The extrados of the arch's voussoirs: the segmental intrados' joints at equal angles,
/// offset by the thickness along the radius.
fn extrados() -> Vec<(f64, f64)> {
    let (h, r, t, n) = (2.0f64, 1.0f64, 0.4f64, 12);
    let radius = (h * h + r * r) / (2.0 * r);
    let from = (h / radius).acos();
    (0..=n)
        .map(|k| {
            let a = from + (std::f64::consts::PI - 2.0 * from) * k as f64 / n as f64;
            ((radius + t) * a.cos(), r - radius + (radius + t) * a.sin())
        })
        .collect()
}

/// ∫ column over the extrados' straight faces, by the midpoint rule on fine steps.
fn weight(layers: &[(f64, f64)]) -> f64 {
    extrados()
        .windows(2)
        .map(|w| {
            let steps = 400;
            (0..steps)
                .map(|i| {
                    let t = (i as f64 + 0.5) / steps as f64;
                    let y = w[0].1 + t * (w[1].1 - w[0].1);
                    column(y, layers) * (w[1].0 - w[0].0).abs() / steps as f64
                })
                .sum::<f64>()
        })
        .sum()
}

fn body(layers: &[(f64, f64)]) -> Value {
    let layers: Vec<Value> = layers
        .iter()
        .map(|(below, g)| json!({"below": below, "unit_weight": g}))
        .collect();
    let mut fill = json!({"unit_weight": FILL, "surface": ROAD});
    if !layers.is_empty() {
        fill["layers"] = json!(layers);
    }
    json!({"geometry": geometry(), "unit_weight": 20.0, "fill": fill,
           "road_loads": [{"x": 0.8, "fy": -10.0}], "include": []})
}

async fn answer(server: &Server, body: &Value) -> Value {
    let (status, _, answer) = server.post("/arch/live-load", body).await;
    assert_eq!(status, 200, "{answer}");
    answer
}

#[tokio::test]
async fn the_fill_weighs_its_layered_columns() {
    let server = Server::start().await;
    // Backing of 22 below y = 1.0 (across the haunches' extrados) and 24 below y = 0.6.
    let layers = [(1.0, 22.0), (0.6, 24.0)];
    let a = answer(&server, &body(&layers)).await;
    let expected = weight(&layers);
    let got = a["fill_weight"].as_f64().unwrap();
    // The midpoint sums here are exact to ~1e-7 of the weight (the column kinks at the levels).
    assert!(
        (got - expected).abs() < 1e-6 * expected,
        "{got} against {expected}"
    );
    let plain = answer(&server, &body(&[])).await;
    let without = plain["fill_weight"].as_f64().unwrap();
    assert!((without - weight(&[])).abs() < 1e-6 * without);
    assert!(got > without);
    // Heavier haunches hold the arch down where a load near the quarter point lifts it.
    let (with_backing, bare) = (
        a["load_factor"].as_f64().unwrap(),
        plain["load_factor"].as_f64().unwrap(),
    );
    assert!(with_backing > bare, "{with_backing} against {bare}");
}

#[tokio::test]
async fn a_layer_of_the_fills_own_weight_changes_nothing() {
    let server = Server::start().await;
    let plain = answer(&server, &body(&[])).await;
    let same = answer(&server, &body(&[(1.1, FILL), (0.5, FILL)])).await;
    for key in ["fill_weight", "load_factor"] {
        let (a, b) = (plain[key].as_f64().unwrap(), same[key].as_f64().unwrap());
        assert!((a - b).abs() < 1e-10 * a, "{key}: {a} against {b}");
    }
    // Passive restraint reads the layered column too: the same capacities.
    let passive = json!({"friction_angle_deg": 30.0, "mobilisation": 0.5});
    let mut p1 = body(&[]);
    p1["fill"]["passive"] = passive.clone();
    let mut p2 = body(&[(1.1, FILL)]);
    p2["fill"]["passive"] = passive;
    let (a, b) = (answer(&server, &p1).await, answer(&server, &p2).await);
    let capacities = |v: &Value| -> Vec<f64> {
        v["passive"]
            .as_array()
            .unwrap_or_else(|| panic!("{v}"))
            .iter()
            .map(|p| p["capacity"].as_f64().unwrap())
            .collect()
    };
    let (ca, cb) = (capacities(&a), capacities(&b));
    assert_eq!(ca.len(), cb.len());
    assert!(!ca.is_empty());
    for (x, y) in ca.iter().zip(&cb) {
        assert!((x - y).abs() <= 1e-9 * x.abs().max(1.0), "{x} against {y}");
    }
}

#[tokio::test]
async fn bad_fill_layers_are_refused_naming_the_field() {
    let server = Server::start().await;
    let cases: Vec<(Value, &str)> = vec![
        (
            json!([{"below": 2.5, "unit_weight": 22.0}]),
            "fill.layers[0].below",
        ),
        (
            json!([{"below": 1.0, "unit_weight": -1.0}]),
            "fill.layers[0].unit_weight",
        ),
        (
            json!([{"below": 1.0, "unit_weight": 22.0}, {"below": 1.0, "unit_weight": 24.0}]),
            "fill.layers[1].below",
        ),
        (json!([]), "fill.layers"),
        (json!([{"below": 1.0}]), "fill.layers"),
    ];
    for (layers, field) in cases {
        let mut b = body(&[]);
        b["fill"]["layers"] = layers;
        let (status, content_type, problem) = server.post("/arch/live-load", &b).await;
        assert_problem(status, &content_type, &problem, 422, field);
    }
}

#[tokio::test]
async fn the_drawing_shows_each_layer_in_the_key() {
    let server = Server::start().await;
    let (status, _, svg) = server
        .post_accept(
            "/arch/live-load/svg",
            "image/svg+xml",
            &body(&[(1.0, 22.0), (0.6, 24.0)]),
        )
        .await;
    assert_eq!(status, 200, "{svg}");
    assert_eq!(svg.matches("data-kind=\"fill-layer\"").count(), 2, "{svg}");
    for key in ["fill γ = 22 below y = 1<", "fill γ = 24 below y = 0.6<"] {
        assert!(svg.contains(key), "{key} not in the key");
    }
}

/// The points of every polyline whose style contains `style`, in pixels.
fn polylines(svg: &str, style: &str) -> Vec<Vec<(f64, f64)>> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .filter(|n| {
            let attrs: String = n
                .attributes()
                .map(|a| format!("{}=\"{}\" ", a.name(), a.value()))
                .collect();
            attrs.contains(style)
        })
        .map(|n| {
            n.attribute("points")
                .unwrap()
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect()
}

#[tokio::test]
async fn a_dispersal_line_over_a_steep_arch_runs_down_and_stops_at_the_bridges_edge() {
    // A pointed arch steeper than the 30° fan: the line from the patch's right end passes over
    // the arch without meeting its extrados. It is drawn going down, cut at the road's end (it
    // was drawn level along the road past the picture's edge).
    let server = Server::start().await;
    let body = json!({"geometry": {"kind": "profile", "shape": "pointed", "span": 8, "radius": 8,
                                   "thickness": 0.6, "voussoirs": 40},
                      "unit_weight": 20, "fill": {"unit_weight": 18, "surface": 7.8},
                      "road_loads": [{"x": 2, "fy": -200, "length": 0.4}]});
    let (status, _, svg) = server
        .post_accept("/arch/live-load/svg", "image/svg+xml", &body)
        .await;
    assert_eq!(status, 200, "{svg}");
    let road = polylines(&svg, "stroke=\"#616161\" stroke-width=\"2.5\"");
    assert_eq!(road.len(), 1, "{svg}");
    let (lo, hi) = road[0]
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    let fans = polylines(&svg, "stroke-dasharray=\"3 2\"");
    assert_eq!(fans.len(), 2, "{svg}");
    for fan in fans {
        let (top, end) = (fan[0], fan[fan.len() - 1]);
        assert!(end.1 > top.1 + 10.0, "a fan line runs down: {fan:?}");
        assert!(
            end.0 >= lo - 0.01 && end.0 <= hi + 0.01,
            "{fan:?} within {lo} … {hi}"
        );
    }
}
