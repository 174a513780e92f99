//! Every hinge's angle and face read back from the geometry, on every generator (one ring or
//! several, one span or several on piers): the hinge's point lies on a radius of its span at
//! the polar angle it states, at the intrados or the extrados its face names (a hinge at the end
//! of a contact between two rings states that contact's direction, along the arc).
//! Regression: with `spans` 2 or 3, every hinge's `angle_deg` was off by −180° and intrados and
//! extrados were swapped (the same joint at (8.797, 2.858) was "18.0°, intrados" with one span
//! and "−162.0°, extrados" with two).
#![allow(clippy::unwrap_used)]

mod common;

use common::Server;
use serde_json::json;

const RADIUS: f64 = 10.0;
const THICKNESS: f64 = 1.5;
const PIER_WIDTH: f64 = 4.0;

/// The polar angle in degrees of `(x, y)` about `centre`, in (−90°, 270°] as the answers give it.
fn polar_deg((x, y): (f64, f64), centre: f64) -> f64 {
    let mut angle = y.atan2(x - centre).to_degrees();
    if angle <= -90.0 {
        angle += 360.0;
    }
    angle
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_hinge_states_the_angle_and_face_its_point_has() {
    let server = Server::start().await;
    let (r_in, r_out) = (RADIUS - 0.5 * THICKNESS, RADIUS + 0.5 * THICKNESS);
    // Semicircles side by side: span k's centre at k·(2·r_in + pier width).
    let pitch = 2.0 * r_in + PIER_WIDTH;
    let mut hinges_checked = 0;
    for spans in [1, 2, 3] {
        for rings in [1, 2] {
            let mut geometry = json!({"kind": "circular", "radius": RADIUS,
                "thickness": THICKNESS, "voussoirs": 20, "rings": rings, "spans": spans});
            if spans > 1 {
                geometry["pier_width"] = json!(PIER_WIDTH);
                geometry["pier_height"] = json!(6.0);
            }
            let mut body = json!({"geometry": geometry,
                "loads": [{"block": 6, "fy": -1}], "include": ["hinges"]});
            if rings > 1 {
                // Rings that can slide on each other form hinges (locked ones carry any load).
                body["ring_friction_coefficient"] = json!(0.6);
            }
            let (status, _, answer) = server.post("/arch/live-load", &body).await;
            assert_eq!(status, 200, "{answer}");
            let hinges = answer["hinges"].as_array().unwrap();
            assert!(!hinges.is_empty(), "spans {spans}, rings {rings}: {answer}");
            for hinge in hinges {
                let point = (hinge["x"].as_f64().unwrap(), hinge["y"].as_f64().unwrap());
                // Its span: the centre whose distance lies within the ring.
                let centre = (0..spans)
                    .map(|k| k as f64 * pitch)
                    .min_by(|a, b| {
                        let off = |c: f64| ((point.0 - c).hypot(point.1) - RADIUS).abs();
                        off(*a).total_cmp(&off(*b))
                    })
                    .unwrap();
                let distance = (point.0 - centre).hypot(point.1);
                let angle = hinge["angle_deg"].as_f64().unwrap();
                let expected = polar_deg(point, centre);
                let inner_boundary = (distance - r_in).abs() > 1e-9 * RADIUS
                    && (distance - r_out).abs() > 1e-9 * RADIUS;
                // 1e-6°: a radial joint's angle is its own direction, the point one of its
                // ends. Between two rings a hinge may also lie at an end of a ring contact, a
                // chord of the arc over half a voussoir (9°/2 here): its direction is the polar
                // angle ± 90°, turned by half that chord's angle (2.25°) towards its other end.
                let within = |a: f64, b: f64, tolerance: f64| {
                    let d = (a - b).rem_euclid(360.0);
                    d.min(360.0 - d) <= tolerance
                };
                let radial = within(angle, expected, 1e-6);
                let half_chord = 0.5 * 180.0 / (2.0 * 20.0) + 1e-6;
                let tangential = within(angle, expected + 90.0, half_chord)
                    || within(angle, expected - 90.0, half_chord);
                assert!(
                    radial || (inner_boundary && tangential),
                    "spans {spans}, rings {rings}: {hinge} at polar angle {expected}"
                );
                // On a ring boundary; with one ring, the intrados is r_in and the extrados r_out.
                let boundaries: Vec<f64> = (0..=rings)
                    .map(|k| r_in + THICKNESS * k as f64 / rings as f64)
                    .collect();
                assert!(
                    boundaries
                        .iter()
                        .any(|r| (distance - r).abs() < 1e-9 * RADIUS),
                    "{hinge}: {distance} from its centre"
                );
                if rings == 1 {
                    let face = if (distance - r_in).abs() < 1e-9 * RADIUS {
                        "intrados"
                    } else {
                        assert!((distance - r_out).abs() < 1e-9 * RADIUS);
                        "extrados"
                    };
                    assert_eq!(hinge["location"], face, "spans {spans}: {hinge}");
                }
                hinges_checked += 1;
            }
        }
    }
    assert!(hinges_checked >= 20, "only {hinges_checked} hinges checked");
}
