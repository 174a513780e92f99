//! Arches by their intrados (model §10) over HTTP: a profile's λ equals that of the same blocks
//! stated as a `blocks` chain, built here from each shape's closed form; rings and spans of a
//! profile; bad profiles are refused naming the field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, live_load_factor, Server};
use serde_json::{json, Value};

type Point = (f64, f64);

const SPAN: f64 = 10.0;
const H: f64 = 0.5 * SPAN;
const T: f64 = 0.5;

fn unit(v: Point) -> Point {
    let l = v.0.hypot(v.1);
    (v.0 / l, v.1 / l)
}

/// The root of an increasing `f` on [lo, hi] by bisection.
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// A chain of quadrilaterals from joints (intrados point, outward unit normal), `t` thick.
fn chain(joints: &[(Point, Point)], t: f64) -> Value {
    let at = |(p, n): (Point, Point), d: f64| json!([p.0 + d * n.0, p.1 + d * n.1]);
    let blocks: Vec<Value> = joints
        .windows(2)
        .map(|w| json!({"corners": [at(w[0], 0.0), at(w[0], t), at(w[1], t), at(w[1], 0.0)]}))
        .collect();
    json!({"kind": "blocks", "blocks": blocks})
}

/// Joints of y = r(1 − x²/h²) at equal arc lengths from the right springing (closed form).
fn parabola(rise: f64, n: usize) -> Vec<(Point, Point)> {
    let k = 2.0 * rise / (H * H);
    let from_crown = |x: f64| 0.5 * x * (1.0 + k * k * x * x).sqrt() + (k * x).asinh() / (2.0 * k);
    let half = from_crown(H);
    (0..=n)
        .map(|j| {
            let sigma = half - 2.0 * half * j as f64 / n as f64;
            let x = bisect(|x| from_crown(x) - sigma, -H, H);
            ((x, rise * (1.0 - x * x / (H * H))), unit((k * x, 1.0)))
        })
        .collect()
}

/// Joints of the catenary through (±h, 0) and (0, r) at equal arc lengths.
fn catenary(rise: f64, n: usize) -> Vec<(Point, Point)> {
    let a = bisect(|a| rise - a * ((H / a).cosh() - 1.0), 0.05, 1e3);
    let half = a * (H / a).sinh();
    (0..=n)
        .map(|j| {
            let x = a * ((half - 2.0 * half * j as f64 / n as f64) / a).asinh();
            (
                (x, rise + a - a * (x / a).cosh()),
                unit(((x / a).sinh(), 1.0)),
            )
        })
        .collect()
}

/// Joints of the segmental arc through (±h, 0) and (0, r): equal angles about its centre.
fn segmental(rise: f64, n: usize) -> Vec<(Point, Point)> {
    let radius = (H * H + rise * rise) / (2.0 * rise);
    let from = (H / radius).acos();
    (0..=n)
        .map(|k| {
            let a = from + (std::f64::consts::PI - 2.0 * from) * k as f64 / n as f64;
            let n = (a.cos(), a.sin());
            ((radius * n.0, rise - radius + radius * n.1), n)
        })
        .collect()
}

fn live(geometry: Value, block: usize) -> Value {
    json!({"geometry": geometry, "loads": [{"block": block, "fy": -10.0}], "include": []})
}

#[tokio::test]
async fn a_profile_carries_what_its_blocks_stated_as_a_chain_carry() {
    let server = Server::start().await;
    let n = 24;
    let cases = [
        ("parabolic", 3.0, parabola(3.0, n)),
        ("catenary", 4.0, catenary(4.0, n)),
        ("segmental", 2.5, segmental(2.5, n)),
    ];
    for (shape, rise, joints) in cases {
        let profile = json!({"kind": "profile", "shape": shape, "span": SPAN, "rise": rise,
                             "thickness": T, "voussoirs": n});
        let by_profile = live_load_factor(&server, &live(profile, 7)).await;
        let by_blocks = live_load_factor(&server, &live(chain(&joints, T), 7)).await;
        assert!(
            (by_profile - by_blocks).abs() <= 1e-8 * by_blocks,
            "{shape}: {by_profile} against {by_blocks}"
        );
    }
    // Measured points: a polyline of 3-4-5 segments and a flat crown, two voussoirs to a
    // segment: a joint at each vertex (the bisector of its segments' normals) and one at each
    // segment's middle (its normal).
    let points = json!([[-8, 0], [-5, 4], [0, 4], [5, 4], [8, 0]]);
    let kink = unit((0.8, 1.6));
    let joints = [
        ((8.0, 0.0), (0.8, 0.6)),
        ((6.5, 2.0), (0.8, 0.6)),
        ((5.0, 4.0), kink),
        ((2.5, 4.0), (0.0, 1.0)),
        ((0.0, 4.0), (0.0, 1.0)),
        ((-2.5, 4.0), (0.0, 1.0)),
        ((-5.0, 4.0), (-kink.0, kink.1)),
        ((-6.5, 2.0), (-0.8, 0.6)),
        ((-8.0, 0.0), (-0.8, 0.6)),
    ];
    let measured = json!({"kind": "profile", "shape": "points", "intrados": points,
                          "thickness": 2.0, "voussoirs": 8});
    let by_profile = live_load_factor(&server, &live(measured, 3)).await;
    let by_blocks = live_load_factor(&server, &live(chain(&joints, 2.0), 3)).await;
    assert!(
        (by_profile - by_blocks).abs() <= 1e-9 * by_blocks,
        "{by_profile} against {by_blocks}"
    );
}

#[tokio::test]
async fn a_semicircular_profile_is_the_circular_arch_on_rings_and_spans_too() {
    let server = Server::start().await;
    let extra = [
        json!({"rings": 2}),
        json!({"spans": 3, "pier_width": 3.0, "pier_height": 3.0}),
    ];
    for more in extra {
        let mut profile = json!({"kind": "profile", "shape": "semicircular", "span": SPAN,
                                 "thickness": 1.0, "voussoirs": 20});
        let mut circle =
            json!({"kind": "circular", "radius": H + 0.5, "thickness": 1.0, "voussoirs": 20});
        for (k, v) in more.as_object().unwrap() {
            profile[k] = v.clone();
            circle[k] = v.clone();
        }
        let body = |g: Value| {
            json!({"geometry": g, "ring_friction_coefficient": more.get("rings").map(|_| 0.6),
                   "loads": [{"block": 6, "fy": -10.0}], "include": []})
        };
        let (a, b) = (
            live_load_factor(&server, &body(profile)).await,
            live_load_factor(&server, &body(circle)).await,
        );
        assert!((a - b).abs() <= 1e-9 * b, "{more}: {a} against {b}");
    }
}

#[tokio::test]
async fn locked_rings_of_a_profile_are_warned_of() {
    let server = Server::start().await;
    let geometry = json!({"kind": "profile", "shape": "segmental", "span": SPAN, "rise": 3.0,
                          "thickness": 0.8, "voussoirs": 20, "rings": 2});
    let (status, _, answer) = server.post("/arch/live-load", &live(geometry, 6)).await;
    assert_eq!(status, 200, "{answer}");
    let codes: Vec<&str> = answer["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|w| w["code"].as_str())
        .collect();
    assert!(codes.contains(&"rings_locked"), "{answer}");
}

#[tokio::test]
async fn bad_profiles_are_refused_naming_the_field() {
    let server = Server::start().await;
    let base = json!({"kind": "profile", "shape": "segmental", "span": SPAN, "rise": 2.0,
                      "thickness": T, "voussoirs": 10});
    let cases: Vec<(Value, &str)> = vec![
        (json!({"rise": 0.0}), "geometry.rise"),
        (json!({"rise": -1.0}), "geometry.rise"),
        (json!({"rise": 5.0}), "geometry.rise"),
        (json!({"rise": 1e-5}), "geometry.rise"),
        (json!({"rise": null}), "geometry.rise"),
        (json!({"span": 0.0}), "geometry.span"),
        (json!({"span": null}), "geometry.span"),
        (json!({"thickness": 10.0}), "geometry.thickness"),
        (json!({"thickness": null}), "geometry.thickness"),
        (json!({"voussoirs": 0}), "geometry.voussoirs"),
        (json!({"shape": "gothic"}), "geometry.shape"),
        (json!({"radius": 8.0}), "geometry.radius"),
        (json!({"haunch_radius": 1.0}), "geometry.haunch_radius"),
        (
            json!({"intrados": [[0, 0], [1, 1], [2, 0]]}),
            "geometry.intrados",
        ),
        (
            json!({"shape": "semicircular", "rise": 4.0}),
            "geometry.rise",
        ),
        (json!({"shape": "pointed", "rise": 4.0}), "geometry.rise"),
        (
            json!({"shape": "pointed", "rise": null, "radius": 4.0}),
            "geometry.radius",
        ),
        (
            json!({"shape": "pointed", "rise": 6.0, "radius": 8.0}),
            "geometry.radius",
        ),
        (json!({"shape": "three_centred"}), "geometry.haunch_radius"),
        (
            json!({"shape": "three_centred", "haunch_radius": 2.0}),
            "geometry.haunch_radius",
        ),
        (
            json!({"shape": "three_centred", "haunch_radius": -1.0}),
            "geometry.haunch_radius",
        ),
        (
            json!({"shape": "three_centred", "rise": 6.0, "haunch_radius": 1.0}),
            "geometry.rise",
        ),
        (
            json!({"shape": "points", "span": null, "rise": null}),
            "geometry.intrados",
        ),
        (
            json!({"shape": "points", "rise": null, "intrados": [[0, 0], [1, 1], [2, 0]]}),
            "geometry.span",
        ),
        (
            json!({"shape": "points", "span": null, "rise": null, "intrados": [[0, 0], [2, 0]]}),
            "geometry.intrados",
        ),
        (
            json!({"shape": "points", "span": null, "rise": null,
                "intrados": [[0, 0], [1, 1], [2, 0.5], [3, 1], [4, 0]]}),
            "geometry.intrados",
        ),
        (
            json!({"shape": "points", "span": null, "rise": null,
                "intrados": [[0, 0], [1, 1], [1, 0]]}),
            "geometry.intrados",
        ),
        (
            json!({"shape": "points", "span": null, "rise": null,
                "intrados": [[0, 0], [1, 2e9], [2, 0]]}),
            "geometry.intrados[1]",
        ),
        (json!({"spans": 2}), "geometry.pier_width"),
        (json!({"pier_width": 1.0}), "geometry.pier_width"),
        (json!({"rings": 17}), "geometry.rings"),
    ];
    for (change, field) in cases {
        let mut geometry = base.clone();
        for (k, v) in change.as_object().unwrap() {
            if v.is_null() {
                geometry.as_object_mut().unwrap().remove(k);
            } else {
                geometry[k] = v.clone();
            }
        }
        let (status, content_type, body) = server.post("/arch/live-load", &live(geometry, 3)).await;
        assert_problem(status, &content_type, &body, 422, field);
    }
}

async fn thinnest(server: &Server, geometry: Value) -> Value {
    let (status, _, answer) = server
        .post("/arch/minimum-thickness", &json!({"geometry": geometry}))
        .await;
    assert_eq!(status, 200, "{answer}");
    answer
}

fn num(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key} in {v}"))
}

#[tokio::test]
async fn a_semicircular_profile_is_as_thin_as_the_circle_of_the_same_ratio() {
    // The circle route's D/R is scale-free (k = 0.1075 for many voussoirs); a semicircular
    // intrados of radius h is the circle of middle radius h + t/2, so t = h·k/(1 − k/2).
    let server = Server::start().await;
    let n = 60;
    let circle = thinnest(
        &server,
        json!({"kind": "circular", "radius": 1.0, "voussoirs": n, "voussoir": "quadrilateral"}),
    )
    .await;
    let k = num(&circle, "thickness_to_radius");
    let profile = thinnest(
        &server,
        json!({"kind": "profile", "shape": "semicircular", "span": SPAN, "voussoirs": n}),
    )
    .await;
    let t = num(&profile, "thickness");
    let expected = H * k / (1.0 - 0.5 * k);
    assert!((t - expected).abs() < 1e-5 * t, "{t} against {expected}");
    assert!((num(&profile, "thickness_to_span") - t / SPAN).abs() < 1e-15);
    assert!(profile["thickness_to_radius"].is_null() && profile["rupture_angle_deg"].is_null());
    assert_eq!(profile["hinges"].as_array().unwrap().len(), 5, "{profile}");
}

#[tokio::test]
async fn a_catenary_is_a_small_fraction_of_the_semicircle_thick() {
    // Expected before computing: the catenary is the funicular of a load uniform along its
    // length, and a strip offset along the normals weighs γ·t per unit length of its middle
    // line. The thrust line of N voussoirs then departs from the axis by the chord error of
    // the voussoirs, O((L/N)²·κ), and by what the strip's thickness adds, which vanishes
    // with t: the minimum thickness falls towards 0 like 1/N², far below the semicircle's
    // t/R = 0.1075 of the same span and rise.
    let server = Server::start().await;
    let at = |shape: &str, n: usize| json!({"kind": "profile", "shape": shape, "span": SPAN, "rise": H, "voussoirs": n});
    let semicircle = num(
        &thinnest(&server, at("semicircular", 20)).await,
        "thickness",
    );
    let coarse = num(&thinnest(&server, at("catenary", 20)).await, "thickness");
    let fine = num(&thinnest(&server, at("catenary", 100)).await, "thickness");
    assert!(coarse < 0.01 * semicircle, "{coarse} against {semicircle}");
    // 1/N² predicts a 25-fold fall from 20 to 100 voussoirs.
    assert!(
        fine < coarse / 10.0 && fine > coarse / 60.0,
        "{coarse} then {fine}"
    );
    // A parabola of the same rise is the funicular of a load uniform along the span, not the
    // arch's own weight: it needs a thickness of its own, between the two.
    let parabola = num(&thinnest(&server, at("parabolic", 100)).await, "thickness");
    assert!(
        parabola > 100.0 * fine && parabola < semicircle,
        "{parabola}"
    );
}

#[tokio::test]
async fn the_minimum_thickness_search_takes_one_ring_of_a_profile() {
    let server = Server::start().await;
    let base = json!({"kind": "profile", "shape": "parabolic", "span": SPAN, "rise": 3.0,
                      "voussoirs": 20});
    for (change, field) in [
        (json!({"rings": 2}), "geometry.rings"),
        (json!({"spans": 2}), "geometry.spans"),
        (json!({"thickness": 12.0}), "geometry.thickness"),
        (json!({"rise": 0.0}), "geometry.rise"),
        (json!({"kind": "blocks"}), "kind"),
    ] {
        let mut geometry = base.clone();
        for (k, v) in change.as_object().unwrap() {
            geometry[k] = v.clone();
        }
        let (status, content_type, body) = server
            .post("/arch/minimum-thickness", &json!({"geometry": geometry}))
            .await;
        assert_problem(status, &content_type, &body, 422, field);
    }
    // A given thickness gives the geometric factor of safety.
    let mut given = base.clone();
    given["thickness"] = json!(0.5);
    let answer = thinnest(&server, given).await;
    let factor = num(&answer, "geometric_factor_of_safety");
    assert!((factor - 0.5 / num(&answer, "thickness")).abs() < 1e-12);
}

#[tokio::test]
async fn the_minimum_thicknesses_docs_arches_quotes() {
    // docs/arches.md, "Arches as they are built": the semicircle's and the parabola's minimum
    // beside the catenary's example (span 10, rise 5, 100 voussoirs), to the digits shown.
    let server = Server::start().await;
    for (shape, shown) in [("semicircular", 0.5678), ("parabolic", 0.1403)] {
        let answer = thinnest(
            &server,
            json!({"kind": "profile", "shape": shape, "span": 10, "rise": 5, "voussoirs": 100}),
        )
        .await;
        let t = num(&answer, "thickness");
        assert!((t - shown).abs() < 5e-5, "{shape}: {t} shown as {shown}");
    }
}
