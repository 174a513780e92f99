//! `POST /slope/spencer` with a `section`, an absolute circle or a polyline surface (model §4).

mod common;

use common::{assert_problem, spencer_example, with, Server};
use serde_json::{json, Value};

fn fredlund_krahn() -> Value {
    json!({
        "section": {
            "ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
            "layers": [{"top": null,
                        "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]
        },
        "circle": {"centre": [120, 90], "radius": 80},
        "slices": 200
    })
}

#[tokio::test]
async fn fredlund_krahn_case_1_over_http() {
    // model §4.5: Spencer 2.073 (their slices; ±0.002), Bishop for this circle 2.07563 by an
    // independent fine integration (see the solver's section tests).
    let server = Server::start().await;
    let (status, _, body) = server.post("/slope/spencer", &fredlund_krahn()).await;
    assert_eq!(status, 200, "{body}");
    let f = body["factor_of_safety"].as_f64().unwrap();
    assert!((f - 2.073).abs() < 2e-3, "F = {f}");
    let bishop = body["bishop_factor_of_safety"].as_f64().unwrap();
    assert!((bishop - 2.07563).abs() < 2e-4, "Bishop {bishop}");
    assert_eq!(body["radius"], 80.0);
    assert_eq!(body["circle"]["centre"]["x"], 120.0);
    // The slope faces left: the lower end is on the right, the slices run right to left.
    let lower = body["circle"]["lower_end"]["x"].as_f64().unwrap();
    assert!((lower - 158.7298).abs() < 1e-3, "lower end x {lower}");
    let slices = body["slices"].as_array().unwrap();
    assert!(slices[0]["x_left"].as_f64().unwrap() > slices[1]["x_left"].as_f64().unwrap());
    let surface = body["surface"].as_array().unwrap();
    assert!(surface
        .windows(2)
        .all(|w| w[1]["x"].as_f64() > w[0]["x"].as_f64()));
    // Stresses are the forces over the base length, and the mobilised strength is the
    // available one over F.
    for s in slices {
        let l = s["base_length"].as_f64().unwrap();
        let sigma = s["normal_stress"].as_f64().unwrap();
        let n = s["normal_force"].as_f64().unwrap();
        assert!(
            (sigma * l - n).abs() < 1e-9 * (1.0 + n.abs()),
            "σ·l {} vs N {n}",
            sigma * l
        );
        let available = s["available_shear_strength"].as_f64().unwrap();
        let mobilised = s["mobilised_shear_strength"].as_f64().unwrap();
        assert!((available / f - mobilised).abs() < 1e-9 * available);
    }
}

#[tokio::test]
async fn the_simple_slope_takes_an_absolute_circle_and_a_surface() {
    // Spencer's example circle given absolutely on the simple slope: the same slices as the
    // relative form, the same F to 1e-12.
    let server = Server::start().await;
    let mut body = spencer_example();
    let (_, _, relative) = server.post("/slope/spencer", &body).await;
    body["circle"] = json!({"centre": [9.63168, 63.76416], "radius": 9.63168f64.hypot(63.76416)});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let f = answer["factor_of_safety"].as_f64().unwrap();
    let g = relative["factor_of_safety"].as_f64().unwrap();
    assert!((f - g).abs() < 1e-12 * g, "absolute {f}, relative {g}");

    body["circle"] = Value::Null;
    body["surface"] = json!([[-5, 0], [10, -5], [50, 10], [70, 31]]);
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    assert!(answer["circle"].is_null() && answer["radius"].is_null());
    assert!(answer["bishop_factor_of_safety"].is_null());
    assert!(answer["factor_of_safety"].as_f64().unwrap() > 0.5);
}

#[tokio::test]
async fn the_simple_form_and_the_same_slope_as_a_section_agree_on_every_circle() {
    // model §6.3: the relative circle (X, Y, F_e) and the same circle given absolutely on the
    // slope written out as a section, centres in front of the toe included (the thesis'
    // geometry answered 0.9776 where the section had no solution): the same answer, to the
    // last digit JSON prints, or the same refusal.
    let server = Server::start().await;
    let soil = json!({"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 30});
    let section = json!({"ground": [[-100, 0], [0, 0], [20, 10], [200, 10]],
                         "layers": [{"top": null, "soil": soil}]});
    for (x, y, fe) in [
        (3.0, 20.0, 0.0),
        (0.0, 25.0, 0.0),
        (-1.0, 30.0, 0.0),
        (-2.0, 15.0, 0.0),
        (-8.0, 30.0, 0.0),
        (4.0, 18.0, 0.3),
        (-6.0, 10.0, 0.0),
    ] {
        let relative = json!({"slope": {"height": 10, "length": 20}, "soil": soil,
            "circle": {"x": x, "y": y, "lower_end_factor": fe}, "slices": 50});
        let centre = [-fe * 10.0 + 0.0 + x, y];
        let absolute = json!({"section": section, "slices": 50,
            "circle": {"centre": centre, "radius": f64::hypot(x, y)}});
        let (status_a, _, a) = server.post("/slope/spencer", &relative).await;
        let (status_b, _, b) = server.post("/slope/spencer", &absolute).await;
        assert_eq!(status_a, status_b, "({x}, {y}, {fe}): {a} vs {b}");
        assert_eq!(a["status"], b["status"], "({x}, {y}, {fe})");
        assert_eq!(
            a["factor_of_safety"], b["factor_of_safety"],
            "({x}, {y}, {fe})"
        );
        assert_eq!(a["theta_deg"], b["theta_deg"], "({x}, {y}, {fe})");
    }
}

#[tokio::test]
async fn section_errors_name_their_fields() {
    let server = Server::start().await;
    let cases: Vec<(Value, &str)> = vec![
        (
            with(
                fredlund_krahn(),
                "section.ground",
                json!([[0, 60], [60, 60], [60, 20]]),
            ),
            "section.ground[2]",
        ),
        (
            with(
                fredlund_krahn(),
                "section.layers.0.soil.friction_angle_deg",
                json!(95),
            ),
            "section.layers[0].soil.friction_angle_deg",
        ),
        (
            with(fredlund_krahn(), "section.layers.0.top", json!([[0, 1]])),
            "section.layers[0].top",
        ),
        (
            with(fredlund_krahn(), "section.water_unit_weight", json!(-1)),
            "section.water_unit_weight",
        ),
        (
            // Two hills, the circle's bottom over the valley between: two equal pieces.
            with(
                with(
                    fredlund_krahn(),
                    "section.ground",
                    json!([[-20, 0], [-10, 10], [0, -10], [10, 10], [20, 0]]),
                ),
                "circle",
                json!({"centre": [0, 30], "radius": 25}),
            ),
            "circle.centre",
        ),
        (
            with(
                fredlund_krahn(),
                "section.surcharges",
                json!([{"x_start": 300, "x_end": 310, "pressure": 1}]),
            ),
            "section.surcharges[0]",
        ),
        (
            with(
                fredlund_krahn(),
                "section.piezometric_line",
                json!([[-100, 10], [-50, 12]]),
            ),
            "section.piezometric_line",
        ),
        (
            with(
                fredlund_krahn(),
                "section.tension_crack",
                json!({"depth": 2, "water_depth": 3}),
            ),
            "section.tension_crack.water_depth",
        ),
        (
            with(
                fredlund_krahn(),
                "section.surcharges",
                json!([{"x_start": 5, "x_end": 1, "pressure": 1}]),
            ),
            "section.surcharges[0].x_end",
        ),
        (
            with(
                fredlund_krahn(),
                "circle",
                json!({"centre": [120, 200], "radius": 80}),
            ),
            "circle.centre",
        ),
        (
            with(fredlund_krahn(), "circle", json!({"centre": [120, 90]})),
            "circle.radius",
        ),
        (
            with(fredlund_krahn(), "circle", json!({"x": 1, "y": 50})),
            "circle",
        ),
        (
            with(fredlund_krahn(), "slope", json!({"height": 1, "length": 1})),
            "slope",
        ),
        (
            with(
                with(fredlund_krahn(), "circle", Value::Null),
                "surface",
                json!([[10, 50], [100, 10]]),
            ),
            "surface",
        ),
        (
            with(
                fredlund_krahn(),
                "external_loads",
                json!([{"slice": 1, "fy": -1}]),
            ),
            "external_loads",
        ),
        (
            with(
                with(
                    with(fredlund_krahn(), "circle", Value::Null),
                    "surface",
                    json!([[40, 62], [70, 38], [120, 21], [165, 21]]),
                ),
                "section.bedrock",
                json!([[0, 15], [100, 25], [180, 15]]),
            ),
            "surface[2]",
        ),
        (
            with(
                fredlund_krahn(),
                "section.layers",
                json!([
                    {"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}},
                    {"top": [[0, 30], [180, 30]], "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}},
                    {"top": [[0, 20], [100, 35], [180, 20]], "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}
                ]),
            ),
            "section.layers[2].top",
        ),
    ];
    for (body, field) in cases {
        let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
        assert_eq!(answer["field"], field, "{answer}");
    }
}

#[tokio::test]
async fn a_layered_section_with_water_loads_and_a_crack_is_drawn() {
    let server = Server::start().await;
    let body = json!({ "section": {
        "ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
        "layers": [
          {"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
          {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
        "bedrock": [[-20, -12], [40, -12]],
        "piezometric_line": [[-20, 1], [10, 3], [40, 6]],
        "surcharges": [{"x_start": 25, "x_end": 35, "pressure": 20}],
        "line_loads": [{"x": 30, "fx": 0, "fy": -50}],
        "tension_crack": {"depth": 2.5, "water_depth": 2.5} },
      "circle": {"centre": [12, 28], "radius": 26},
      "slices": 100 });
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["converged"], true);
    // The surface ends with the crack's vertical face: 2.5 deep at the crest (y = 10).
    let surface = answer["surface"].as_array().unwrap();
    let (a, b) = (&surface[surface.len() - 2], &surface[surface.len() - 1]);
    assert_eq!(a["x"], b["x"]);
    assert!((a["y"].as_f64().unwrap() - 7.5).abs() < 1e-9 && b["y"] == 10.0);
    let response = server
        .client
        .post(format!("{}/slope/spencer/svg", server.base))
        .json(&body)
        .send()
        .await
        .unwrap();
    assert_eq!(response.status(), 200);
    let svg = response.text().await.unwrap();
    // Each layer filled in its colour and named with its soil in the legend.
    for label in [
        "layer 1: γ = ",
        "layer 2: γ = ",
        "fill-opacity",
        "bedrock",
        "piezometric line",
        "one slip circle",
    ] {
        assert!(svg.contains(label), "no {label}");
    }
}

fn acads_1a() -> Value {
    json!({
        "section": {
            "ground": [[20, 25], [30, 25], [50, 35], [70, 35]],
            "layers": [{"top": null,
                        "soil": {"unit_weight": 20, "cohesion": 3, "friction_angle_deg": 19.6}}]
        },
        "search": {},
        "slices": 50
    })
}

#[tokio::test]
async fn acads_1a_critical_circle_over_http() {
    // model §4.5: Spencer ≈ 0.986 (Slide2), referee 1.00; see the solver's search test.
    let server = Server::start().await;
    let (status, _, body) = server.post("/slope/spencer", &acads_1a()).await;
    assert_eq!(status, 200, "{body}");
    let f = body["factor_of_safety"].as_f64().unwrap();
    assert!((f - 0.986).abs() < 5e-3, "F = {f}");
    assert_eq!(body["search"]["on_edge"], false);
    assert!(body["search"]["unsolved"].is_u64());
    // The grid is absolute: the critical centre lies within its columns and rows.
    let xs = body["grid"]["xs"].as_array().unwrap();
    let centre = body["circle"]["centre"]["x"].as_f64().unwrap();
    assert!(xs[0].as_f64().unwrap() < centre && centre < xs[xs.len() - 1].as_f64().unwrap());
}

#[tokio::test]
async fn section_search_bounds_are_hard_and_validated() {
    let server = Server::start().await;
    let body = with(
        acads_1a(),
        "search",
        json!({"x_min": 0, "x_max": 20, "y_min": 40, "y_max": 70, "nx": 11, "ny": 11,
               "tangent_elevations": [10, 15, 20, 25]}),
    );
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let x = answer["circle"]["centre"]["x"].as_f64().unwrap();
    assert!((0.0..=20.0).contains(&x), "centre x {x} outside the bounds");
    assert_eq!(answer["search"]["on_edge"], true);
    assert_eq!(answer["search"]["regrids"], 0);
    let warnings = answer["warnings"].to_string();
    assert!(
        warnings.contains("edge of the given search bounds"),
        "{warnings}"
    );

    let cases = [
        (
            with(acads_1a(), "search", json!({"lower_end_factor": 1})),
            "search.lower_end_factor",
        ),
        (
            with(acads_1a(), "search", json!({"radius_min": 5})),
            "search.radius_max",
        ),
        (
            with(
                acads_1a(),
                "search",
                json!({"radius_min": 5, "radius_max": 4}),
            ),
            "search.radius_max",
        ),
        (
            with(acads_1a(), "search", json!({"x_min": 10, "x_max": 5})),
            "search.x_max",
        ),
        (with(acads_1a(), "search", json!({"nr": 0})), "search.nr"),
        (
            with(
                acads_1a(),
                "search",
                json!({"tangent_elevations": [1, "a"]}),
            ),
            "search.tangent_elevations",
        ),
        (
            with(
                spencer_example(),
                "search",
                json!({"tangent_elevations": [1]}),
            ),
            "search.tangent_elevations",
        ),
    ];
    for (mut body, field) in cases {
        if field == "search.tangent_elevations" && body.get("circle").is_some() {
            body["circle"] = Value::Null;
        }
        let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
}

#[tokio::test]
async fn methods_side_by_side() {
    // Fredlund & Krahn case 1 at 1000 slices against the independent computations of the
    // solver's section tests: ordinary 1.92768, Bishop 2.07563, Janbu 1.87702, M–P (half-sine)
    // 2.07140 with λ = 0.32321; a triangle given as points is accepted and converges.
    let server = Server::start().await;
    let mut body = with(fredlund_krahn(), "slices", json!(1000));
    body["methods"] = json!(["morgenstern_price", "bishop", "janbu", "ordinary"]);
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let m = &answer["methods"];
    let f = |name: &str| m[name]["factor_of_safety"].as_f64().unwrap();
    assert!((f("ordinary") - 1.92768).abs() < 1e-4);
    assert!((f("bishop") - 2.07563).abs() < 1e-4);
    assert!((f("janbu") - 1.87702).abs() < 1e-4);
    assert!((f("morgenstern_price") - 2.07140).abs() < 1e-4);
    assert!((m["morgenstern_price"]["lambda"].as_f64().unwrap() - 0.32321).abs() < 1e-3);
    assert_eq!(m["bishop"]["converged"], true);

    body["methods"] = json!(["morgenstern_price"]);
    body["interslice_function"] = json!([[0, 0], [0.5, 1], [1, 0]]);
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let triangle = answer["methods"]["morgenstern_price"]["factor_of_safety"]
        .as_f64()
        .unwrap();
    assert!((triangle - 2.0714).abs() < 5e-3, "triangle {triangle}");
    assert!(answer["methods"].get("bishop").is_none());

    body["interslice_function"] = json!([[0, 0], [0, 1]]);
    let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
    assert_problem(
        status,
        &content_type,
        &answer,
        422,
        "interslice_function[1]",
    );
    body["interslice_function"] = Value::Null;
    body["methods"] = json!(["simplified"]);
    let (status, _, _) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 422);
}

#[tokio::test]
async fn a_noncircular_search_follows_a_weak_layer() {
    // See the solver's noncircular test: the polyline from the critical circle runs along the
    // thin weak layer at a much lower F; the path starts at the circle's polyline.
    let server = Server::start().await;
    let soil =
        |c: f64, phi: f64| json!({"unit_weight": 19, "cohesion": c, "friction_angle_deg": phi});
    let section = json!({
        "ground": [[0, 0], [20, 0], [40, 10], [80, 10]],
        "layers": [{"top": null, "soil": soil(10.0, 30.0)},
                   {"top": [[0, 1], [80, 1]], "soil": soil(1.0, 8.0)},
                   {"top": [[0, 0.5], [80, 0.5]], "soil": soil(10.0, 30.0)}]});
    let (status, _, circle) = server
        .post(
            "/slope/spencer",
            &json!({"section": section, "search": {}, "slices": 50}),
        )
        .await;
    assert_eq!(status, 200, "{circle}");
    let body = json!({"section": section, "search": {"shape": "noncircular"}, "slices": 50});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let (fc, f) = (
        circle["factor_of_safety"].as_f64().unwrap(),
        answer["factor_of_safety"].as_f64().unwrap(),
    );
    assert!(f < 0.9 * fc, "non-circular {f} vs circular {fc}");
    assert!(answer["circle"].is_null());
    assert!(answer["search"]["path"].as_array().unwrap().len() >= 2);
    let (status, content_type, answer) = server
        .post(
            "/slope/spencer",
            &json!({"section": section, "search": {"vertices": 8}}),
        )
        .await;
    assert_problem(status, &content_type, &answer, 422, "search.vertices");
}

#[tokio::test]
async fn slice_layers_count_from_one_like_every_other_index() {
    // Regression: `slices[].layer` counted from 0 where slices, blocks and interfaces count
    // from 1. Two layers, the lower from y = -3 down: slices whose base middle lies below -3
    // are in layer 2, the others in layer 1; the simple slope's are all in layer 1.
    let server = Server::start().await;
    let body = json!({"section": {"ground": [[-20, 0], [0, 0], [20, 10], [60, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                   {"top": [[-20, -3], [60, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}]},
        "circle": {"centre": [12, 28], "radius": 34}, "slices": 40, "include": ["slices"]});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let slices = answer["slices"].as_array().unwrap();
    let mut seen = [false; 2];
    for slice in slices {
        let (left, right) = (
            slice["x_left"].as_f64().unwrap(),
            slice["x_right"].as_f64().unwrap(),
        );
        let middle = 0.5 * (left + right);
        // The base middle's depth: the circle below the middle of the slice.
        let base = 28.0 - (34.0f64.powi(2) - (middle - 12.0).powi(2)).sqrt();
        let layer = slice["layer"].as_u64().unwrap();
        let expected = if base < -3.0 { 2 } else { 1 };
        assert_eq!(layer, expected, "{slice}");
        seen[(layer - 1) as usize] = true;
    }
    assert!(seen[0] && seen[1], "both layers cut: {seen:?}");
    let simple = json!({"slope": {"height": 30.48, "length": 60.96},
        "circle": {"x": 9.63168, "y": 63.76416}, "slices": 10, "include": ["slices"],
        "soil": {"unit_weight": 10, "cohesion": 6.096, "friction_angle_deg": 40}});
    let (_, _, answer) = server.post("/slope/spencer", &simple).await;
    assert!(answer["slices"]
        .as_array()
        .unwrap()
        .iter()
        .all(|s| s["layer"] == 1));
}
