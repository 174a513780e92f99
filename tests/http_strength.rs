//! Strength and water models over HTTP (model §8): each answered slice's strength checked
//! against its model evaluated here, the identities the solver's tests prove (power curve with
//! b = 1 is Mohr–Coulomb), the grid's warning, h_u, design factors on s_u, searches on
//! nonlinear envelopes, and bad input refused naming its field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, with, Server};
use serde_json::{json, Value};

const GROUND: &str = "[[-20, 0], [0, 0], [20, 10], [50, 10]]";

fn section(soil: Value, extra: Value) -> Value {
    let mut section = json!({
        "ground": serde_json::from_str::<Value>(GROUND).unwrap(),
        "layers": [{"top": null, "soil": soil}],
    });
    for (k, v) in extra.as_object().unwrap() {
        section[k] = v.clone();
    }
    json!({
        "section": section,
        "circle": {"centre": [12, 22], "radius": 26},
        "slices": 60,
        "methods": ["bishop", "janbu", "ordinary", "morgenstern_price"],
    })
}

fn f(answer: &Value) -> f64 {
    answer["factor_of_safety"].as_f64().unwrap()
}

fn slices(answer: &Value) -> &Vec<Value> {
    answer["slices"].as_array().unwrap()
}

fn number(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap()
}

#[tokio::test]
async fn a_power_curve_with_b_one_answers_as_mohr_coulomb() {
    let server = Server::start().await;
    let a = 30f64.to_radians().tan();
    let curve = section(
        json!({"unit_weight": 19, "strength": {"model": "power_curve", "a": a, "b": 1, "c": 4, "d": 6.0 / a}}),
        json!({}),
    );
    let mc = section(
        json!({"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 30}),
        json!({}),
    );
    let (status, _, curve) = server.post("/slope/spencer", &curve).await;
    assert_eq!(status, 200, "{curve}");
    let (_, _, mc) = server.post("/slope/spencer", &mc).await;
    assert!((f(&curve) - f(&mc)).abs() < 1e-9 * f(&mc));
    for method in ["bishop", "janbu", "ordinary", "morgenstern_price"] {
        let (p, q) = (
            number(&curve["methods"][method], "factor_of_safety"),
            number(&mc["methods"][method], "factor_of_safety"),
        );
        assert!((p - q).abs() < 1e-9 * q, "{method}: {p} {q}");
    }
    // The rounds are reported for envelopes only.
    assert!(curve["strength_iterations"].as_u64().unwrap() >= 1);
    assert!(mc.get("strength_iterations").is_none(), "{mc}");
}

#[tokio::test]
async fn each_slice_carries_its_envelope_at_its_own_normal_stress() {
    let server = Server::start().await;
    let body = section(
        json!({"unit_weight": 19, "strength": {"model": "power_curve", "a": 3, "b": 0.6, "c": 1}}),
        json!({}),
    );
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["converged"], true);
    assert!(
        answer["strength_iterations"].as_u64().unwrap() >= 2,
        "{answer}"
    );
    for s in slices(&answer) {
        let sigma = number(s, "effective_normal_stress");
        let tau = 3.0 * sigma.max(0.0).powf(0.6) + 1.0;
        let got = number(s, "available_shear_strength");
        assert!(
            (got - tau).abs() < 1e-8 * tau,
            "σ′ {sigma}: {got} against {tau}"
        );
    }
}

#[tokio::test]
async fn undrained_strength_grows_with_depth_below_the_ground_or_a_datum() {
    let server = Server::start().await;
    let ground = section(
        json!({"unit_weight": 18, "strength": {"model": "undrained", "cohesion": 12, "gradient": 2.5, "reference": "ground"}}),
        json!({}),
    );
    let (status, _, answer) = server.post("/slope/spencer", &ground).await;
    assert_eq!(status, 200, "{answer}");
    for s in slices(&answer) {
        // φ = 0: the strength is s_u at the base middle, `height` below the ground.
        let expected = 12.0 + 2.5 * number(s, "height");
        assert!((number(s, "available_shear_strength") - expected).abs() < 1e-9 * expected);
    }
    let datum = section(
        json!({"unit_weight": 18, "strength": {"model": "undrained", "cohesion": 12, "gradient": 2.5, "datum": 4, "cohesion_max": 20}}),
        json!({}),
    );
    let (status, _, answer) = server.post("/slope/spencer", &datum).await;
    assert_eq!(status, 200, "{answer}");
    let mut capped = 0;
    for s in slices(&answer) {
        // The base middle's y from the ground at its x less its height.
        let x = 0.5 * (number(s, "x_left") + number(s, "x_right"));
        let ground = if x <= 0.0 {
            0.0
        } else if x <= 20.0 {
            x / 2.0
        } else {
            10.0
        };
        let y = ground - number(s, "height");
        let expected = (12.0 + 2.5 * (4.0 - y).max(0.0)).min(20.0);
        capped += usize::from(expected == 20.0);
        assert!((number(s, "available_shear_strength") - expected).abs() < 1e-9 * expected);
    }
    assert!(capped > 0, "the cap should bind somewhere: {answer}");
}

#[tokio::test]
async fn design_values_divide_undrained_strength_by_gamma_cu() {
    // φ = 0 on a circle: F is proportional to s_u, so DA1-2 (γ_cu 1.4, γ_γ 1) gives F/1.4.
    let server = Server::start().await;
    let body = section(
        json!({"unit_weight": 18, "strength": {"model": "undrained", "cohesion": 30, "gradient": 1, "reference": "ground"}}),
        json!({}),
    );
    let (_, _, plain) = server.post("/slope/spencer", &body).await;
    let mut designed = body.clone();
    designed["design"] = json!({"approach": "DA1-2"});
    let (status, _, answer) = server.post("/slope/spencer", &designed).await;
    assert_eq!(status, 200, "{answer}");
    let fd = answer["design"]["factor_of_safety"].as_f64().unwrap();
    assert!(
        (fd - f(&plain) / 1.4).abs() < 1e-9 * fd,
        "{fd} {}",
        f(&plain)
    );
}

#[tokio::test]
async fn hu_scales_each_bases_pore_pressure() {
    let server = Server::start().await;
    let soil = json!({"unit_weight": 19, "cohesion": 8, "friction_angle_deg": 30});
    let points = json!([[-20, -2], [0, -0.5], [20, 5], [50, 6]]);
    let full = section(soil.clone(), json!({"piezometric_line": points}));
    let half = section(
        soil.clone(),
        json!({"piezometric_line": {"points": points, "hu": 0.5}}),
    );
    let auto = section(
        soil,
        json!({"piezometric_line": {"points": points, "hu": "auto"}}),
    );
    let (_, _, full) = server.post("/slope/spencer", &full).await;
    let (status, _, half) = server.post("/slope/spencer", &half).await;
    assert_eq!(status, 200, "{half}");
    let (status, _, auto) = server.post("/slope/spencer", &auto).await;
    assert_eq!(status, 200, "{auto}");
    let mut wet = 0;
    for (p, q) in slices(&full).iter().zip(slices(&half)) {
        let (u, v) = (number(p, "pore_pressure"), number(q, "pore_pressure"));
        wet += usize::from(u > 0.0);
        assert!((v - 0.5 * u).abs() <= 1e-12 * u.max(1.0), "{u} {v}");
    }
    assert!(wet > 5, "{full}");
    // cos²α < 1 on the inclined line: less water than the full head.
    assert!(
        f(&full) < f(&auto) && f(&auto) < f(&half) + 1.0,
        "{} {}",
        f(&full),
        f(&auto)
    );
}

#[tokio::test]
async fn a_grid_that_misses_bases_says_so() {
    let server = Server::start().await;
    let soil = json!({"unit_weight": 19, "cohesion": 8, "friction_angle_deg": 30});
    // Over x ≤ 12 only: the bases beyond take u = 0, and are named.
    let grid = json!({"points": [[-25, -30, 300], [12, -30, 300], [-25, 12, 0], [12, 12, 0]]});
    let body = section(soil, json!({"pore_pressure_grid": grid}));
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let warning = common::warning(&answer, "outside_pore_pressure_grid");
    let named: Vec<u64> = warning["slices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect();
    for s in slices(&answer) {
        let middle = 0.5 * (number(s, "x_left") + number(s, "x_right"));
        let outside = named.contains(&s["slice"].as_u64().unwrap());
        assert_eq!(outside, middle > 12.0, "slice {}", s["slice"]);
        if outside {
            assert_eq!(number(s, "pore_pressure"), 0.0);
        } else {
            assert!(number(s, "pore_pressure") > 0.0);
        }
    }
}

#[tokio::test]
async fn a_search_on_hoek_brown_rock_settles() {
    let server = Server::start().await;
    let mut body = section(
        json!({"unit_weight": 25, "strength": {"model": "hoek_brown", "sigma_ci": 2000, "gsi": 30, "mi": 8, "disturbance": 0.5}}),
        json!({}),
    );
    body.as_object_mut().unwrap().remove("circle");
    body["search"] = json!({"nx": 8, "ny": 8, "nr": 6});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["converged"], true, "{answer}");
    assert!(f(&answer) > 1.0 && answer["strength_iterations"].as_u64().unwrap() >= 2);
}

#[tokio::test]
async fn bad_models_and_water_are_refused_naming_the_field() {
    let server = Server::start().await;
    let strength = |s: Value| section(json!({"unit_weight": 19, "strength": s}), json!({}));
    let cases: Vec<(Value, &str)> = vec![
        (
            strength(json!({"model": "power_curve", "a": 1, "b": 0})),
            "section.layers[0].soil.strength.b",
        ),
        (
            strength(json!({"model": "power_curve", "a": 1, "b": 1.5})),
            "section.layers[0].soil.strength.b",
        ),
        (
            strength(json!({"model": "power_curve", "a": 0, "b": 0.5})),
            "section.layers[0].soil.strength.a",
        ),
        (
            strength(json!({"model": "hoek_brown", "sigma_ci": 100, "gsi": 4, "mi": 10})),
            "section.layers[0].soil.strength.gsi",
        ),
        (
            strength(json!({"model": "hoek_brown", "sigma_ci": 100, "gsi": 101, "mi": 10})),
            "section.layers[0].soil.strength.gsi",
        ),
        (
            strength(json!({"model": "hoek_brown", "sigma_ci": 0, "gsi": 50, "mi": 10})),
            "section.layers[0].soil.strength.sigma_ci",
        ),
        (
            strength(json!({"model": "hoek_brown", "sigma_ci": 100, "gsi": 50, "mi": 0})),
            "section.layers[0].soil.strength.mi",
        ),
        (
            strength(
                json!({"model": "hoek_brown", "sigma_ci": 100, "gsi": 50, "mi": 10, "disturbance": 1.5}),
            ),
            "section.layers[0].soil.strength.disturbance",
        ),
        (
            strength(json!({"model": "shear_normal", "points": [[0, 1]]})),
            "section.layers[0].soil.strength.points",
        ),
        (
            strength(json!({"model": "shear_normal", "points": [[0, 1], [0, 2]]})),
            "section.layers[0].soil.strength.points[1]",
        ),
        (
            strength(json!({"model": "shear_normal", "points": [[0, 1], [10, -2]]})),
            "section.layers[0].soil.strength.points[1]",
        ),
        (
            strength(json!({"model": "undrained", "cohesion": 10, "gradient": 1})),
            "section.layers[0].soil.strength.datum",
        ),
        (
            strength(
                json!({"model": "undrained", "cohesion": 10, "gradient": 1, "datum": 0, "reference": "ground"}),
            ),
            "section.layers[0].soil.strength.reference",
        ),
        (
            strength(json!({"model": "undrained", "cohesion": 10, "cohesion_max": 5})),
            "section.layers[0].soil.strength.cohesion_max",
        ),
        (
            strength(json!({"model": "undrained", "cohesion": 0})),
            "section.layers[0].soil.strength.cohesion",
        ),
        (
            section(
                json!({"unit_weight": 19, "cohesion": 5, "strength": {"model": "undrained", "cohesion": 10}}),
                json!({}),
            ),
            "section.layers[0].soil.cohesion",
        ),
        (
            section(
                json!({"unit_weight": 19, "friction_angle_deg": 30}),
                json!({}),
            ),
            "section.layers[0].soil.cohesion",
        ),
        (
            section(
                json!({"unit_weight": 19, "cohesion": 5, "friction_angle_deg": 30}),
                json!({"piezometric_line": {"points": [[0, 1], [10, 2]], "hu": 1.5}}),
            ),
            "section.piezometric_line.hu",
        ),
        (
            section(
                json!({"unit_weight": 19, "cohesion": 5, "friction_angle_deg": 30}),
                json!({"pore_pressure_grid": {"points": [[0, 0, 1], [1, 1, 1]]}}),
            ),
            "section.pore_pressure_grid.points",
        ),
        (
            section(
                json!({"unit_weight": 19, "cohesion": 5, "friction_angle_deg": 30}),
                json!({"pore_pressure_grid": {"points": [[0, 0, 1], [1, 1, 1], [2, 2, 0]]}}),
            ),
            "section.pore_pressure_grid.points",
        ),
        (
            section(
                json!({"unit_weight": 19, "cohesion": 5, "friction_angle_deg": 30}),
                json!({"pore_pressure_grid": {"points": [[0, 0, 1], [1, 0, 1], [0, 0, 3], [0, 1, 0]]}}),
            ),
            "section.pore_pressure_grid.points[2]",
        ),
    ];
    for (body, field) in cases {
        let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
    // The simple slope takes no strength model; its soil still needs c′ and φ′.
    let simple = with(
        common::spencer_example(),
        "soil.strength",
        json!({"model": "undrained", "cohesion": 10}),
    );
    let (status, content_type, answer) = server.post("/slope/spencer", &simple).await;
    assert_problem(status, &content_type, &answer, 422, "soil.strength");
}

#[tokio::test]
async fn the_drawing_names_each_model_and_draws_each_water_source() {
    let server = Server::start().await;
    let body = json!({
        "section": {
            "ground": [[-20, 0], [0, 0], [20, 10], [50, 10]],
            "layers": [
                {"top": null, "soil": {"unit_weight": 19, "strength": {"model": "power_curve", "a": 3, "b": 0.6, "c": 1}}},
                {"top": [[-20, -3], [50, -3]],
                 "soil": {"unit_weight": 18, "strength": {"model": "undrained", "cohesion": 30, "gradient": 2, "datum": -3}},
                 "piezometric_line": {"points": [[-20, -1], [50, 2]], "hu": "auto"}}],
            "pore_pressure_grid": {"points": [[-25, -30, 100], [12, -30, 100], [-25, 12, 0], [12, 12, 0], [0, 0, 50]]}
        },
        "circle": {"centre": [12, 22], "radius": 26},
        "slices": 60
    });
    let (status, content_type, svg) = server
        .post_accept("/slope/spencer/svg", "image/svg+xml", &body)
        .await;
    assert_eq!(status, 200, "{svg}");
    assert!(content_type.starts_with("image/svg+xml"), "{content_type}");
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let texts = common::svg_texts(&doc);
    let keyed = |words: &str| texts.iter().any(|t| t.contains(words));
    for words in [
        "layer 1: γ = 19, τ = 3·(σ′ + 0)^0.6 + 1",
        "layer 2: γ = 18, undrained s_u = 30 + 2·depth below y = -3",
        "piezometric line of layer 2 (h_u = cos²α)",
        "pore-pressure grid: 5 points",
    ] {
        assert!(keyed(words), "{words} is not in the key: {texts:?}");
    }
    // The grid's points are drawn, each one a dot (a round-capped move) in the grid's colour,
    // and its hull as a closed outline.
    let dots = doc
        .descendants()
        .filter(|n| n.has_tag_name("path") && n.attribute("stroke") == Some("#0288d1"))
        .filter_map(|n| n.attribute("d"))
        .map(|d| d.matches('M').count())
        .sum::<usize>();
    assert_eq!(dots, 5, "{svg}");
    let hull = doc
        .descendants()
        .find(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some("#0288d1"))
        .and_then(|n| n.attribute("points"))
        .unwrap();
    let corners: Vec<&str> = hull.split_whitespace().collect();
    assert_eq!(corners.len(), 5, "four corners, closed: {hull}");
    assert_eq!(corners.first(), corners.last());
}
