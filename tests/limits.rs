//! One table of limits for the schema and the checks (`src/limits.rs`): every entry lands on a
//! property of the document, no schema attribute states a limit of its own, and at the table's
//! bounds the server answers as the schema says — a value just inside is not refused for its
//! range, a value just outside is 422 naming the field.
// Test scaffolding: a malformed fixture should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::Server;
use serde_json::{json, Value};
use thrustline::limits::{Limit, Range};

#[test]
fn every_table_entry_names_a_property_of_the_document() {
    let missing = thrustline::openapi::limit_targets_missing();
    assert!(missing.is_empty(), "limits naming no property: {missing:?}");
    // And the document states each of them.
    let doc: Value = serde_json::from_str(&thrustline::openapi::openapi_json()).unwrap();
    for (schema, property, limit) in thrustline::routes::schema_limits() {
        let p = &doc["components"]["schemas"][schema]["properties"][property];
        let text = p.to_string();
        let stated = match limit {
            Limit::Number(_) | Limit::Integer(_) => text.contains("imum"),
            Limit::Items(_) => text.contains("maxItems"),
        };
        assert!(stated, "{schema}.{property} states no limit: {p}");
    }
}

#[test]
fn no_schema_attribute_states_a_limit_of_its_own() {
    // Limits live in the table; an attribute's literal would be a second source. Points
    // ([x, y]: exactly two items) are shapes, not limits.
    let mut found = Vec::new();
    let mut stack = vec![std::path::PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/src"
    ))];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            for (i, line) in text.lines().enumerate() {
                let attribute = line.trim_start().starts_with("#[schema(");
                let limit = [
                    "minimum =",
                    "maximum =",
                    "exclusive_minimum =",
                    "max_items =",
                ]
                .iter()
                .any(|k| line.contains(k));
                let point = line.contains("min_items = 2, max_items = 2");
                if attribute && limit && !point {
                    found.push(format!("{}:{}", path.display(), i + 1));
                }
            }
        }
    }
    assert!(found.is_empty(), "limits outside the table: {found:?}");
}

/// A value just outside `range` at each finite end, with the side it is on.
fn outside(range: Range) -> Vec<f64> {
    let nudge = |v: f64, up: bool| {
        let step = 1e-6 * v.abs().max(1.0);
        if up {
            v + step
        } else {
            v - step
        }
    };
    let mut values = Vec::new();
    if let Some(min) = range.min {
        values.push(if range.min_open {
            min
        } else {
            nudge(min, false)
        });
    }
    if let Some(max) = range.max {
        values.push(nudge(max, true));
    }
    values
}

/// Sets the value at a JSON pointer.
fn set(body: &mut Value, pointer: &str, value: Value) {
    *body.pointer_mut(pointer).unwrap() = value;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_server_refuses_what_the_schema_excludes_and_names_the_field() {
    let server = Server::start().await;
    let spencer = json!({"slope": {"height": 30.48, "length": 60.96},
        "circle": {"x": 9.63168, "y": 63.76416}, "slices": 20,
        "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0,
                 "pore_pressure_ratio": 0.5},
        "seismic": {"kh": 0.0, "kv": 0.0}, "include": []});
    let section = json!({"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
        "layers": [{"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}],
        "water_unit_weight": 62.4,
        "surcharges": [{"x_start": 10, "x_end": 20, "pressure": 5}],
        "tension_crack": {"depth": 5, "water_depth": 1}},
        "circle": {"centre": [120, 90], "radius": 80}, "slices": 20, "include": []});
    let arch = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
        "voussoirs": 20, "left_base_angle_deg": 0.0}, "loads": [{"block": 6, "fy": -1}], "unit_weight": 1.0,
        "friction_coefficient": 0.5, "include": []});
    let bridge = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0,
        "voussoirs": 40}, "fill": {"unit_weight": 1.8, "surface": 11.5,
        "dispersal_angle_deg": 30, "passive": {"friction_angle_deg": 30, "mobilisation": 0.5}},
        "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}], "include": []});
    // (schema, property) → (route, body, pointer, field the 422 names).
    let cases: &[(&str, &str, &str, &Value, &str, &str)] = &[
        (
            "SlopeDto",
            "height",
            "/slope/spencer",
            &spencer,
            "/slope/height",
            "slope.height",
        ),
        (
            "CircleDto",
            "y",
            "/slope/spencer",
            &spencer,
            "/circle/y",
            "circle.y",
        ),
        (
            "SoilDto",
            "friction_angle_deg",
            "/slope/spencer",
            &spencer,
            "/soil/friction_angle_deg",
            "soil.friction_angle_deg",
        ),
        (
            "SoilDto",
            "pore_pressure_ratio",
            "/slope/spencer",
            &spencer,
            "/soil/pore_pressure_ratio",
            "soil.pore_pressure_ratio",
        ),
        (
            "SoilDto",
            "cohesion",
            "/slope/spencer",
            &spencer,
            "/soil/cohesion",
            "soil.cohesion",
        ),
        (
            "SeismicDto",
            "kh",
            "/slope/spencer",
            &spencer,
            "/seismic/kh",
            "seismic.kh",
        ),
        (
            "SeismicDto",
            "kv",
            "/slope/spencer",
            &spencer,
            "/seismic/kv",
            "seismic.kv",
        ),
        (
            "CircleDto",
            "radius",
            "/slope/spencer",
            &section,
            "/circle/radius",
            "circle.radius",
        ),
        (
            "SectionDto",
            "water_unit_weight",
            "/slope/spencer",
            &section,
            "/section/water_unit_weight",
            "section.water_unit_weight",
        ),
        (
            "SurchargeDto",
            "pressure",
            "/slope/spencer",
            &section,
            "/section/surcharges/0/pressure",
            "section.surcharges[0].pressure",
        ),
        (
            "TensionCrackDto",
            "depth",
            "/slope/spencer",
            &section,
            "/section/tension_crack/depth",
            "section.tension_crack.depth",
        ),
        (
            "CircularGeometryDto",
            "radius",
            "/arch/live-load",
            &arch,
            "/geometry/radius",
            "geometry.radius",
        ),
        (
            "CircularGeometryDto",
            "voussoirs",
            "/arch/live-load",
            &arch,
            "/geometry/voussoirs",
            "geometry.voussoirs",
        ),
        (
            "CircularGeometryDto",
            "left_base_angle_deg",
            "/arch/live-load",
            &arch,
            "/geometry/left_base_angle_deg",
            "geometry.left_base_angle_deg",
        ),
        (
            "LiveLoadRequest",
            "unit_weight",
            "/arch/live-load",
            &arch,
            "/unit_weight",
            "unit_weight",
        ),
        (
            "LiveLoadRequest",
            "friction_coefficient",
            "/arch/live-load",
            &arch,
            "/friction_coefficient",
            "friction_coefficient",
        ),
        (
            "FillDto",
            "dispersal_angle_deg",
            "/arch/live-load",
            &bridge,
            "/fill/dispersal_angle_deg",
            "fill.dispersal_angle_deg",
        ),
        (
            "PassiveDto",
            "mobilisation",
            "/arch/live-load",
            &bridge,
            "/fill/passive/mobilisation",
            "fill.passive.mobilisation",
        ),
        (
            "RoadLoadDto",
            "length",
            "/arch/live-load",
            &bridge,
            "/road_loads/0/length",
            "road_loads[0].length",
        ),
    ];
    let mut checked = 0;
    for (schema, property, route, body, pointer, field) in cases {
        let limit = thrustline::routes::schema_limits()
            .find(|(s, p, _)| s == schema && p == property)
            .map(|e| e.2)
            .unwrap_or_else(|| panic!("{schema}.{property} is not in the table"));
        let values: Vec<Value> = match limit {
            Limit::Number(range) => outside(range).into_iter().map(|v| json!(v)).collect(),
            Limit::Integer(c) | Limit::Items(c) => {
                vec![json!(c.min.saturating_sub(1)), json!(c.max + 1)]
            }
        };
        for value in values {
            let mut sent = (*body).clone();
            set(&mut sent, pointer, value.clone());
            let (status, _, answer) = server.post(route, &sent).await;
            assert_eq!(status, 422, "{schema}.{property} = {value}: {answer}");
            assert_eq!(
                answer["field"], *field,
                "{schema}.{property} = {value}: {answer}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 30, "only {checked} boundary values checked");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn tiny_and_huge_polyline_steps_are_422_naming_the_point_never_500() {
    // Regression (a 500 from a panic in the solver): an x-step of 5e-324 in any polyline of a
    // section or in a surface, on the JSON route and the drawing's.
    let server = Server::start().await;
    let base = json!({"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                   {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
        "bedrock": [[-20, -12], [40, -12]],
        "piezometric_line": [[-20, 1], [10, 3], [40, 6]]},
        "circle": {"centre": [12, 28], "radius": 26}, "slices": 20, "include": []});
    let lines = [
        ("/section/ground", "section.ground"),
        ("/section/layers/1/top", "section.layers[1].top"),
        ("/section/bedrock", "section.bedrock"),
        ("/section/piezometric_line", "section.piezometric_line"),
    ];
    let mut checked = 0;
    for step in [5e-324, 1e-300, 1e-15] {
        for (pointer, field) in lines {
            for route in ["/slope/spencer", "/slope/spencer/svg"] {
                let mut body = base.clone();
                let first = body.pointer(pointer).unwrap()[0].clone();
                let (x, y) = (first[0].as_f64().unwrap(), first[1].as_f64().unwrap());
                let points = body.pointer_mut(pointer).unwrap().as_array_mut().unwrap();
                points.insert(1, json!([x + step, y + 1.0]));
                let (status, _, answer) = server.post(route, &body).await;
                assert_eq!(status, 422, "{field} step {step} on {route}: {answer}");
                assert_eq!(answer["field"], format!("{field}[1]"), "{answer}");
                checked += 1;
            }
        }
        // A polyline surface with the same fault.
        let mut body = base.clone();
        body.as_object_mut().unwrap().remove("circle");
        body["surface"] = json!([[5, 12], [5.0 + step, 8], [30, 4], [40, 12]]);
        let (status, _, answer) = server.post("/slope/spencer", &body).await;
        assert_eq!(status, 422, "surface step {step}: {answer}");
        assert_eq!(answer["field"], "surface[1]", "{answer}");
        checked += 1;
    }
    // Huge coordinates and steps: 422 beyond 1e9, an answer (200) within.
    for x in [1e9, 1.0000001e9, 1e300] {
        let mut body = base.clone();
        body["section"]["ground"][3] = json!([x, 10]);
        let (status, _, answer) = server.post("/slope/spencer", &body).await;
        assert!(
            status == 200 || status == 422,
            "ground to {x}: {status} {answer}"
        );
        assert_eq!(status == 422, x > 1e9, "ground to {x}: {answer}");
        checked += 1;
    }
    assert_eq!(checked, 3 * (4 * 2 + 1) + 3);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_key_given_twice_is_422_naming_it_not_the_last_value_winning() {
    // Regression: `"slices": 100, "slices": 5` was solved with 5 slices.
    let server = Server::start().await;
    let cases = [
        (
            "/slope/spencer",
            r#"{"slope": {"height": 30.48, "length": 60.96}, "circle": {"x": 9.63168, "y": 63.76416},
                "slices": 100, "slices": 5,
                "soil": {"unit_weight": 10, "cohesion": 6.096, "friction_angle_deg": 40}}"#,
            "slices",
        ),
        (
            "/arch/dead-load",
            r#"{"geometry": {"kind": "circular", "radius": 10, "thickness": 1.0747,
                "voussoirs": 1800, "voussoirs": 10}}"#,
            "geometry.voussoirs",
        ),
        (
            "/arch/live-load",
            r#"{"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": 20},
                "loads": [{"block": 6, "fy": -1, "fy": -100}]}"#,
            "loads[0].fy",
        ),
    ];
    for (route, body, field) in cases {
        let (status, _, answer) = server.post_raw(route, "application/json", body).await;
        assert_eq!(status, 422, "{route}: {answer}");
        assert_eq!(answer["field"], field, "{route}: {answer}");
        assert!(
            answer["detail"]
                .as_str()
                .unwrap()
                .contains("given more than once"),
            "{answer}"
        );
    }
}
