//! `POST /slope/spencer` over a real socket.

mod common;

use common::{assert_problem, spencer_example, with, Server};
use serde_json::json;

#[tokio::test]
async fn spencer_example_over_http() {
    let server = Server::start().await;
    let (status, content_type, body) = server.post("/slope/spencer", &spencer_example()).await;
    assert_eq!(status, 200, "{body}");
    assert_eq!(content_type, "application/json");
    // Thesis §5.6 at N = 100: F = 1.06958, θ = 22.432 (half a unit in the last printed digit).
    let f = body["factor_of_safety"].as_f64().unwrap();
    let theta = body["theta_deg"].as_f64().unwrap();
    assert!((f - 1.06958).abs() <= 5e-6, "F = {f}");
    assert!((theta - 22.432).abs() <= 5e-4, "θ = {theta}");
    assert_eq!(body["converged"], true);
    assert_eq!(body["status"], "converged");
    // model §2.3: radius 64.4875, upper exit x ≈ 64.87, Bishop ≈ 1.040.
    assert!((body["radius"].as_f64().unwrap() - 64.4875).abs() < 5e-5);
    assert!((body["circle"]["upper_exit"]["x"].as_f64().unwrap() - 64.87).abs() < 5e-3);
    assert!((body["bishop_factor_of_safety"].as_f64().unwrap() - 1.040).abs() < 5e-4);
    assert_eq!(body["slices"].as_array().unwrap().len(), 100);
    assert_eq!(body["thrust_line"].as_array().unwrap().len(), 99);
    assert_eq!(body["slices"][0]["slice"], 1);
    assert!(body["iterations"].as_u64().unwrap() >= 1);
}

#[tokio::test]
async fn converged_spencer_example_at_1000_slices() {
    // model §2.3: F = 1.0695 ± 2e-4 and θ = 22.43° ± 0.01°.
    let server = Server::start().await;
    let body = with(spencer_example(), "slices", json!(1000));
    let (status, _, body) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200);
    assert!((body["factor_of_safety"].as_f64().unwrap() - 1.0695).abs() < 2e-4);
    assert!((body["theta_deg"].as_f64().unwrap() - 22.43).abs() < 0.01);
}

#[tokio::test]
async fn out_of_range_numbers_are_422_naming_the_field() {
    let server = Server::start().await;
    let cases = [
        ("slope.height", json!(-30.48)),
        ("slope.height", json!(0.0)),
        ("slope.length", json!(0)),
        ("slices", json!(0)),
        ("slices", json!(1_000_000)),
        ("circle.y", json!(-5.0)),
        ("circle.lower_end_factor", json!(-1.0)),
        ("soil.unit_weight", json!(0.0)),
        ("soil.cohesion", json!(-1.0)),
        ("soil.friction_angle_deg", json!(90.0)),
        ("soil.pore_pressure_ratio", json!(1.5)),
    ];
    for (field, value) in cases {
        let body = with(spencer_example(), field, value.clone());
        let (status, content_type, body) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &body, 422, field);
        assert_eq!(body["field"], field, "{value}");
    }
}

#[tokio::test]
async fn seismic_out_of_range_is_422_with_a_circle_and_with_a_search() {
    // The range is the solver's (Seismic::new); a search must not swallow it as "no valid
    // circle".
    let server = Server::start().await;
    let mut circle = spencer_example();
    circle["seismic"] = json!({"kh": 11.0});
    let mut search = circle.clone();
    search.as_object_mut().unwrap().remove("circle");
    search["search"] = json!({});
    let mut vertical = circle.clone();
    vertical["seismic"] = json!({"kv": -1.0});
    for (body, field) in [
        (circle, "seismic.kh"),
        (search, "seismic.kh"),
        (vertical, "seismic.kv"),
    ] {
        let (status, content_type, body) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &body, 422, field);
        assert_eq!(body["field"], field);
    }
}

#[tokio::test]
async fn soil_with_no_strength_is_422() {
    let server = Server::start().await;
    let body = with(spencer_example(), "soil.cohesion", json!(0.0));
    let body = with(body, "soil.friction_angle_deg", json!(0.0));
    let (status, content_type, body) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &body, 422, "soil.cohesion");
}

#[tokio::test]
async fn circle_that_misses_the_slope_is_422() {
    let server = Server::start().await;
    // Centre behind the lower end, in front of the toe: the arc rises out of level ground.
    let body = with(
        spencer_example(),
        "circle",
        json!({"x": -5.0, "y": 40.0, "lower_end_factor": 0.5}),
    );
    let (status, content_type, body) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &body, 422, "circle.x");
    // Centre so low that the lower half of the circle never comes back to the surface.
    let body = with(spencer_example(), "circle", json!({"x": 90.0, "y": 5.0}));
    let (status, content_type, body) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &body, 422, "circle.y");
}

#[tokio::test]
async fn external_load_on_a_missing_slice_is_422() {
    let server = Server::start().await;
    let body = with(spencer_example(), "slices", json!(10));
    let mut body = body;
    body["external_loads"] = json!([{"slice": 11, "fx": 0.0, "fy": -1.0, "moment": 0.0}]);
    let (status, content_type, body) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &body, 422, "external_loads[0].slice");
}

#[tokio::test]
async fn unknown_and_missing_fields_and_bad_json() {
    let server = Server::start().await;
    let body = with(spencer_example(), "slope.foo", json!(1));
    let (status, content_type, body) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &body, 422, "slope.foo");
    assert_eq!(body["field"], "slope.foo");

    let mut body = spencer_example();
    body.as_object_mut().unwrap().remove("soil");
    let (status, content_type, body) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &body, 422, "soil");

    let body = with(spencer_example(), "slices", json!("many"));
    let (status, content_type, body) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &body, 422, "slices");

    let (status, content_type, body) = server
        .post_raw("/slope/spencer", "application/json", "{\"slope\"")
        .await;
    assert_eq!(status, 400);
    assert_eq!(content_type, "application/problem+json");
    assert!(body["detail"].as_str().unwrap().contains("JSON"));

    let (status, content_type, _) = server.post_raw("/slope/spencer", "text/plain", "{}").await;
    assert_eq!(status, 415);
    assert_eq!(content_type, "application/problem+json");

    // A number too large for f64 is not Infinity: it is rejected by the parser.
    let text = spencer_example().to_string().replace("30.48", "1e999");
    let (status, content_type, _) = server
        .post_raw("/slope/spencer", "application/json", &text)
        .await;
    assert!(status == 400 || status == 422, "{status}");
    assert_eq!(content_type, "application/problem+json");
}

#[tokio::test]
async fn oversized_body_is_413() {
    let server = Server::start_with(thrustline::Settings {
        body_limit: 1024,
        ..Default::default()
    })
    .await;
    let mut body = spencer_example();
    body["external_loads"] = json!(vec![json!({"slice": 1, "fx": 0.0}); 200]);
    let (status, content_type, _) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 413);
    assert_eq!(content_type, "application/problem+json");
}

#[tokio::test]
async fn healthz_openapi_docs_and_unknown_routes() {
    let server = Server::start().await;
    let (status, _, body) = server.get("/healthz").await;
    assert_eq!(status, 200);
    assert_eq!(body["status"], "ok");
    let (status, _, body) = server.get("/openapi.json").await;
    assert_eq!(status, 200);
    assert_eq!(body["openapi"], "3.1.0");
    assert!(body["paths"]["/slope/spencer"]["post"].is_object());
    let (status, _, body) = server.get("/docs/").await;
    assert_eq!(status, 200);
    assert!(body.as_str().unwrap().contains("swagger"), "{body}");
    let (status, content_type, _) = server.get("/nowhere").await;
    assert_eq!(status, 404);
    assert_eq!(content_type, "application/problem+json");
    // A missing asset of the documentation UI: the same problem, not an empty 404.
    let (status, content_type, body) = server.get("/docs/missing.js").await;
    assert_eq!(status, 404);
    assert_eq!(content_type, "application/problem+json");
    assert_eq!(body["detail"], "no route for /docs/missing.js");
    let (status, content_type, _) = server.get("/docs/swagger-ui.css").await;
    assert_eq!(status, 200);
    assert!(content_type.starts_with("text/css"), "{content_type}");
}

#[tokio::test]
async fn critical_circle_search_with_automatic_bounds() {
    let server = Server::start().await;
    let mut body = spencer_example();
    body.as_object_mut().unwrap().remove("circle");
    body["search"] = json!({});
    body["slices"] = json!(50);
    let (status, _, body) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{body}");
    let critical = body["factor_of_safety"].as_f64().unwrap();
    // The critical circle is no safer than Spencer's own circle (F = 1.0697 at 50 slices).
    assert!(critical <= 1.0698, "{critical}");
    assert!(body["circle"]["radius"].as_f64().unwrap() > 0.0);
    let grid = &body["grid"];
    assert_eq!(grid["xs"].as_array().unwrap().len(), 21);
    assert_eq!(grid["ys"].as_array().unwrap().len(), 21);
    let rows = grid["factor_of_safety"].as_array().unwrap();
    assert_eq!(rows.len(), 21);
    // Some centres give no valid circle (null), the rest are at least the critical F.
    let values: Vec<&serde_json::Value> = rows.iter().flat_map(|r| r.as_array().unwrap()).collect();
    assert!(values.iter().any(|v| v.is_null()));
    assert!(values
        .iter()
        .filter_map(|v| v.as_f64())
        .all(|f| f >= critical - 1e-12));
    assert!(body["search"]["evaluations"].as_u64().unwrap() >= 441);
}

#[tokio::test]
async fn explicit_search_bounds_and_curves() {
    let server = Server::start().await;
    let mut body = spencer_example();
    body.as_object_mut().unwrap().remove("circle");
    body["search"] =
        json!({"x_min": -20.0, "x_max": 30.0, "y_min": 40.0, "y_max": 120.0, "nx": 11, "ny": 9});
    body["curves"] = json!(true);
    body["slices"] = json!(30);
    let (status, _, body) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{body}");
    assert_eq!(body["grid"]["xs"].as_array().unwrap().len(), 11);
    assert_eq!(body["grid"]["ys"].as_array().unwrap().len(), 9);
    let curves = &body["curves"];
    let thetas = curves["theta_deg"].as_array().unwrap();
    assert_eq!(
        thetas.len(),
        curves["force_factor"].as_array().unwrap().len()
    );
    // The curves cross near θ*: F_f − F_m changes sign within the 1° steps around it.
    let theta = body["theta_deg"].as_f64().unwrap();
    let i = thetas
        .iter()
        .position(|t| t.as_f64().unwrap() >= theta)
        .unwrap();
    let d = |k: usize| {
        curves["force_factor"][k].as_f64().unwrap() - curves["moment_factor"][k].as_f64().unwrap()
    };
    assert!(d(i - 1) * d(i) <= 0.0);
}

#[tokio::test]
async fn circle_and_search_are_exclusive_and_search_is_validated() {
    let server = Server::start().await;
    let mut both = spencer_example();
    both["search"] = json!({});
    let (status, content_type, body) = server.post("/slope/spencer", &both).await;
    assert_problem(status, &content_type, &body, 422, "search");

    let mut neither = spencer_example();
    neither.as_object_mut().unwrap().remove("circle");
    let (status, content_type, body) = server.post("/slope/spencer", &neither).await;
    assert_problem(status, &content_type, &body, 422, "circle");

    for (search, field, slices) in [
        (json!({"nx": 1}), "search.nx", 10),
        (json!({"ny": 500}), "search.ny", 10),
        (json!({"x_min": 10.0, "x_max": 5.0}), "search.x_max", 10),
        (json!({"nx": 101, "ny": 101}), "search", 1000),
        (
            json!({"lower_end_factor": -1.0}),
            "search.lower_end_factor",
            10,
        ),
        // Centres so far behind the lower end that no circle cuts a slip mass.
        (
            json!({"x_min": -2e3, "x_max": -1e3, "y_min": 1.0, "y_max": 2.0, "nx": 3, "ny": 3}),
            "search",
            10,
        ),
    ] {
        let mut body = neither.clone();
        body["search"] = search;
        body["slices"] = json!(slices);
        let (status, content_type, body) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &body, 422, field);
    }

    let mut loads = neither.clone();
    loads["search"] = json!({});
    loads["external_loads"] = json!([{"slice": 1, "fy": -1.0}]);
    let (status, content_type, body) = server.post("/slope/spencer", &loads).await;
    assert_problem(status, &content_type, &body, 422, "external_loads");
}

#[tokio::test]
async fn slice_tolerance_refines_until_f_settles() {
    let server = Server::start().await;
    let mut body = with(spencer_example(), "slices", json!(10));
    body["slice_tolerance"] = json!(1e-4);
    let (status, _, body) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{body}");
    let steps = body["slice_refinement"].as_array().unwrap();
    assert!(steps.len() >= 2);
    assert_eq!(steps[0]["slices"], 10);
    let last: Vec<f64> = steps
        .iter()
        .rev()
        .take(2)
        .map(|s| s["factor_of_safety"].as_f64().unwrap())
        .collect();
    assert!((last[0] - last[1]).abs() <= 1e-4 * last[0]);
    // Right to 1e-4 against the converged F = 1.0695224 (Spencer's example).
    let f = body["factor_of_safety"].as_f64().unwrap();
    assert!((f - 1.0695224).abs() < 1e-4 * f, "{f}");
    assert_eq!(body["slice_count"], steps.last().unwrap()["slices"]);

    let mut bad = spencer_example();
    bad["slice_tolerance"] = json!(0.5);
    let (status, content_type, body) = server.post("/slope/spencer", &bad).await;
    assert_problem(status, &content_type, &body, 422, "slice_tolerance");
}

#[tokio::test]
async fn slope_drawing_with_the_f_map() {
    let server = Server::start().await;
    let mut body = spencer_example();
    body.as_object_mut().unwrap().remove("circle");
    body["search"] = json!({"nx": 6, "ny": 5});
    body["slices"] = json!(20);
    let response = server
        .client
        .post(format!("{}/slope/spencer/svg", server.base))
        .json(&body)
        .send()
        .await
        .unwrap();
    assert_eq!(response.status().as_u16(), 200);
    let svg = response.text().await.unwrap();
    assert!(svg.contains("the critical slip circle") && svg.contains("F over centres"));
    // The embankment and at most 6 × 5 map cells; 20 slice sides; the centre dot.
    let polygons = svg.matches("<polygon").count();
    assert!((2..=31).contains(&polygons), "{polygons}");
    assert_eq!(svg.matches("<circle").count(), 1);
    // The key names the refined critical circle's F (the JSON answer's, to 4 decimals), which
    // is no more than the grid's least; each contour drawn is labelled.
    let (_, _, answer) = server.post("/slope/spencer", &body).await;
    let f = answer["factor_of_safety"].as_f64().unwrap();
    assert!(svg.contains(&format!("F = {f:.4}")), "{f}");
    let key = svg.split("F over centres: red ").nth(1).unwrap();
    let least: f64 = key.split(' ').next().unwrap().parse().unwrap();
    assert!(
        f <= least + 5e-4,
        "refined {f} above the grid's least {least}"
    );
    let contours: usize = key
        .split(';')
        .nth(1)
        .unwrap()
        .trim()
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let labels = svg.matches("font-size=\"9\"").count();
    assert_eq!(labels, contours, "one label per contour");
}
