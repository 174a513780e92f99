//! A section and its mirror image answer alike (SPEC §14): the same searched F (1e-9 relative;
//! in fact bit for bit, the circle search running in one frame for both), the mirrored critical
//! circle, with water lines, a rectangular pore-pressure grid (whose Delaunay triangulation is
//! not unique), supports, surcharges, line loads and a crack. (The non-circular stage still
//! runs in each section's own frame: docs/model.md §4.4.)
#![allow(clippy::unwrap_used)]

mod common;

use common::Server;
use serde_json::{json, Value};

/// A polyline [[x, y], ...] seen from behind: x → −x, left to right again.
fn line(points: &Value) -> Value {
    let mut out: Vec<Value> = points
        .as_array()
        .unwrap()
        .iter()
        .map(|p| json!([-p[0].as_f64().unwrap(), p[1]]))
        .collect();
    out.reverse();
    Value::Array(out)
}

/// The section seen from behind, written out field by field (not by the service's own mirror).
fn mirrored(section: &Value) -> Value {
    let mut s = section.clone();
    s["ground"] = line(&section["ground"]);
    for layer in s["layers"].as_array_mut().unwrap() {
        if !layer["top"].is_null() {
            layer["top"] = line(&layer["top"]);
        }
    }
    if let Some(p) = section.get("piezometric_line") {
        s["piezometric_line"] = line(p);
    }
    if let Some(grid) = section.get("pore_pressure_grid") {
        let points: Vec<Value> = grid["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| json!([-p[0].as_f64().unwrap(), p[1], p[2]]))
            .collect();
        s["pore_pressure_grid"] = json!({"points": points});
    }
    for support in s
        .get_mut("supports")
        .and_then(Value::as_array_mut)
        .into_iter()
        .flatten()
    {
        for end in ["head", "end"] {
            support[end][0] = json!(-support[end][0].as_f64().unwrap());
        }
    }
    for load in s
        .get_mut("surcharges")
        .and_then(Value::as_array_mut)
        .into_iter()
        .flatten()
    {
        let (a, b) = (
            load["x_start"].as_f64().unwrap(),
            load["x_end"].as_f64().unwrap(),
        );
        let (p, q) = (load["pressure"].clone(), load["pressure_end"].clone());
        *load = json!({"x_start": -b, "x_end": -a, "pressure": q, "pressure_end": p});
    }
    for load in s
        .get_mut("line_loads")
        .and_then(Value::as_array_mut)
        .into_iter()
        .flatten()
    {
        load["x"] = json!(-load["x"].as_f64().unwrap());
        load["fx"] = json!(-load["fx"].as_f64().unwrap());
    }
    s
}

fn sections() -> Vec<(&'static str, Value)> {
    let soil = |g: f64, c: f64, phi: f64| json!({"unit_weight": g, "cohesion": c, "friction_angle_deg": phi});
    let base = json!({"ground": [[-25, 0], [0, 0], [20, 10], [45, 10]],
        "layers": [{"top": null, "soil": soil(19.0, 8.0, 30.0)},
                   {"top": [[-25, -4], [45, -4]], "soil": soil(20.0, 2.0, 33.0)}]});
    let with = |key: &str, value: Value| {
        let mut s = base.clone();
        s[key] = value;
        s
    };
    // u = γ_w·(3 − y) below y = 3 on a 8 × 8 rectangular grid: cocircular in every cell.
    let grid: Vec<Value> = (0..8)
        .flat_map(|i| {
            (0..8).map(move |j| (-25.0 + 10.0 * f64::from(i), -30.0 + 6.0 * f64::from(j)))
        })
        .map(|(x, y)| json!([x, y, (9.81 * (3.0 - y)).max(0.0)]))
        .collect();
    let mut loaded = with(
        "surcharges",
        json!([{"x_start": 25, "x_end": 35, "pressure": 20, "pressure_end": 40}]),
    );
    loaded["line_loads"] = json!([{"x": 30, "fx": 5, "fy": -50}]);
    loaded["tension_crack"] = json!({"depth": 2.5, "water_depth": 2.5});
    vec![
        ("layered", base.clone()),
        (
            "water line",
            with("piezometric_line", json!([[-25, -1], [0, -1], [45, 6]])),
        ),
        (
            "pore-pressure grid",
            with("pore_pressure_grid", json!({"points": grid})),
        ),
        (
            "passive nail",
            with(
                "supports",
                json!([{"kind": "soil_nail", "head": [10, 5],
            "end": [22, 2], "spacing": 1.5, "tensile_capacity": 150, "plate_capacity": 50,
            "bond_strength": 20, "application": "passive"}]),
            ),
        ),
        ("loads and a crack", loaded),
    ]
}

async fn spencer(server: &Server, body: &Value) -> Value {
    let (status, _, answer) = server.post("/slope/spencer", body).await;
    assert_eq!(status, 200, "{answer}");
    answer
}

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[tokio::test]
async fn a_section_and_its_mirror_image_search_alike() {
    let server = Server::start().await;
    for (name, section) in sections() {
        for search in [json!({}), json!({"nx": 15, "ny": 12, "nr": 7})] {
            let body =
                |s: &Value| json!({"section": s, "search": search, "slices": 40, "include": []});
            let a = spencer(&server, &body(&section)).await;
            let b = spencer(&server, &body(&mirrored(&section))).await;
            let (f, g) = (
                number(&a["factor_of_safety"]),
                number(&b["factor_of_safety"]),
            );
            assert!((f - g).abs() <= 1e-9 * f, "{name} {search}: {f} vs {g}");
            let (sa, sb) = (
                a["surface"].as_array().unwrap(),
                b["surface"].as_array().unwrap(),
            );
            assert_eq!(sa.len(), sb.len(), "{name}");
            for (p, q) in sa.iter().zip(sb.iter().rev()) {
                let (p0, q0) = (number(&p["x"]), number(&q["x"]));
                assert!(
                    (p0 + q0).abs() <= 1e-9 * (1.0 + p0.abs()),
                    "{name}: {p} vs {q}"
                );
            }
            assert_eq!(
                a["search"]["evaluations"], b["search"]["evaluations"],
                "{name}"
            );
        }
    }
}

#[tokio::test]
async fn a_rectangular_grid_gives_the_same_pressures_seen_from_either_side() {
    // The critical circle across the grid, stated on the section and on its mirror image.
    let server = Server::start().await;
    let (_, section) = sections().swap_remove(2);
    let found = spencer(
        &server,
        &json!({"section": section, "search": {}, "slices": 37,
                                          "include": []}),
    )
    .await;
    let (x, y, r) = (
        number(&found["circle"]["centre"]["x"]),
        number(&found["circle"]["centre"]["y"]),
        number(&found["circle"]["radius"]),
    );
    let body = |s: &Value, x: f64| {
        json!({"section": s, "circle": {"centre": [x, y], "radius": r}, "slices": 37,
               "include": ["slices"]})
    };
    let a = spencer(&server, &body(&section, x)).await;
    let b = spencer(&server, &body(&mirrored(&section), -x)).await;
    let (sa, sb) = (
        a["slices"].as_array().unwrap(),
        b["slices"].as_array().unwrap(),
    );
    let wet = sa
        .iter()
        .filter(|s| number(&s["pore_pressure"]) > 0.0)
        .count();
    assert!(wet > 10, "{wet} bases under water");
    for (p, q) in sa.iter().zip(sb) {
        let (u, v) = (number(&p["pore_pressure"]), number(&q["pore_pressure"]));
        assert!(
            (u - v).abs() <= 1e-9 * (1.0 + u.abs()),
            "slice {}: {u} vs {v}",
            p["slice"]
        );
    }
    let (f, g) = (
        number(&a["factor_of_safety"]),
        number(&b["factor_of_safety"]),
    );
    assert!((f - g).abs() <= 1e-9 * f, "{f} vs {g}");
    assert!((f - number(&found["factor_of_safety"])).abs() <= 1e-9 * f);
}
