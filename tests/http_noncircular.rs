//! Non-circular surfaces and searches against published benchmark problems (model §4.2, §4.4).
//!
//! The problems: Yamagami & Ueta's (1988) homogeneous slope, the layered slope of Zolfaghari et
//! al. (2005) with a weak third layer, and Cheng et al.'s (2007) two variants with a thin weak
//! seam. Published minima: Greco (1996) 1.327, Cheng et al. (2007) 1.325, Li et al. (2010)
//! 1.327 for the first; Cheng 1.101 / Li 1.113; Cheng 1.349 / Li 1.335; Cheng 1.184 / Li 1.197.
//! Geometry and the published critical surfaces as tabulated in McMaster's slope stability case
//! study (Karchewski; Frankis), from the papers' figures and tables.

#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

fn soil(phi: f64, c: f64, gamma: f64) -> Value {
    json!({"unit_weight": gamma, "cohesion": c, "friction_angle_deg": phi})
}

/// A section from layer tops listed top-down, each with its soil (φ', c', γ); the first top
/// is the ground.
fn section(layers: &[((f64, f64, f64), Value)]) -> Value {
    let listed: Vec<Value> = layers
        .iter()
        .enumerate()
        .map(|(i, ((phi, c, gamma), top))| {
            let top = if i == 0 { Value::Null } else { top.clone() };
            json!({"top": top, "soil": soil(*phi, *c, *gamma)})
        })
        .collect();
    json!({"ground": layers[0].1, "layers": listed})
}

fn yamagami_ueta() -> Value {
    section(&[(
        (10.0, 9.8, 17.64),
        json!([[0, 5], [5, 5], [15, 10], [25, 10]]),
    )])
}

/// Zolfaghari et al.'s slope (`thin`: false) or Cheng et al.'s thin-seam variant (`thin`: true,
/// their example 4: the weak layer 5 cm thick, outcropping at the toe).
fn layered(thin: bool) -> Value {
    let (ground, weak) = if thin {
        (
            json!([
                [10, 50],
                [15, 50],
                [19, 48],
                [31.9, 41.55],
                [32, 41.5],
                [35, 41.5]
            ]),
            json!([[10, 46.25], [31.9, 41.55], [32, 41.5], [35, 41.5]]),
        )
    } else {
        (
            json!([
                [10, 50],
                [15, 50],
                [19, 48],
                [30.5, 42.25],
                [32, 41.5],
                [35, 41.5]
            ]),
            json!([[10, 46.7], [30.5, 42.25], [32, 41.5], [35, 41.5]]),
        )
    };
    let layers = [
        ((20.0, 15.0, 19.0), ground),
        (
            (21.0, 17.0, 19.0),
            json!([[10, 48.5], [19, 48], [32, 41.5], [35, 41.5]]),
        ),
        ((10.0, 5.0, 19.0), weak),
        (
            (28.0, 35.0, 19.0),
            json!([[10, 46.2], [32, 41.5], [35, 41.5]]),
        ),
    ];
    section(&layers)
}

/// Cheng et al.'s example 3: a weak layer 1 m thick under the crest and face.
fn weak_layer() -> Value {
    let ground = json!([
        [10, 50],
        [15, 50],
        [19, 48],
        [25, 45],
        [27, 44],
        [32, 41.5],
        [40, 41.5]
    ]);
    let layers = [
        ((20.0, 15.0, 19.0), ground),
        (
            (21.0, 17.0, 19.0),
            json!([[10, 48.1], [19, 48], [32, 41.5], [40, 41.5]]),
        ),
        (
            (10.0, 5.0, 19.0),
            json!([[10, 45], [25, 45], [32, 41.5], [40, 41.5]]),
        ),
        (
            (28.0, 35.0, 19.0),
            json!([[10, 44], [27, 44], [32, 41.5], [40, 41.5]]),
        ),
    ];
    section(&layers)
}

async fn search(server: &Server, section: &Value) -> Value {
    let body = json!({"section": section, "search": {"shape": "noncircular"}, "slices": 50});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    answer
}

/// The search's F lies within the published minima, widened by 1 % below (a better optimum
/// than the papers' is possible; a much lower one would be an error) and 0.5 % above (the
/// issue's "within 0.5 % of the converged minimum"); its path falls and its clock runs.
fn assert_reaches(answer: &Value, published: &[f64]) {
    let f = answer["factor_of_safety"].as_f64().unwrap();
    let low = published.iter().cloned().fold(f64::INFINITY, f64::min);
    let high = published.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    assert!(
        f >= 0.99 * low && f <= 1.005 * high,
        "F = {f}, published {published:?}"
    );
    let path: Vec<f64> = answer["search"]["path"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let ms: Vec<f64> = answer["search"]["path_ms"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(path.len(), ms.len());
    assert!(path.windows(2).all(|w| w[1] < w[0]), "{path:?}");
    assert!(ms.windows(2).all(|w| w[1] >= w[0]), "{ms:?}");
    assert_eq!(*path.last().unwrap(), f);
}

#[tokio::test]
async fn the_homogeneous_slope_reaches_the_published_minimum() {
    let server = Server::start().await;
    let answer = search(&server, &yamagami_ueta()).await;
    assert_reaches(&answer, &[1.325, 1.327]);
}

#[tokio::test]
async fn a_weak_layer_reaches_the_published_minimum() {
    let server = Server::start().await;
    assert_reaches(&search(&server, &layered(false)).await, &[1.101, 1.113]);
    assert_reaches(&search(&server, &weak_layer()).await, &[1.335, 1.349]);
}

#[tokio::test]
async fn a_thin_seam_is_found() {
    // The critical circle here is 1.98, and a polyline moved from it stalls near 1.48: only a
    // surface laid along the 5 cm seam reaches the published 1.184 / 1.197.
    let server = Server::start().await;
    let answer = search(&server, &layered(true)).await;
    assert_reaches(&answer, &[1.184, 1.197]);
    let seam = answer["slices"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["layer"] == 3) // section.layers[2], numbered from 1
        .count();
    assert!(seam > 25, "{seam} of 50 slices in the seam");
}

/// Published critical surfaces (digitised from the papers' figures): Cheng et al.'s for
/// Yamagami & Ueta's slope (F 1.325) and for the thin seam (1.184), Li et al.'s for the weak
/// layer (1.335).
fn published_surfaces() -> [(Value, Value, f64); 3] {
    [
        (
            yamagami_ueta(),
            json!([
                [4.5258, 5.0],
                [5.0971, 4.6882],
                [5.6684, 4.3765],
                [6.1165, 4.2235],
                [6.5646, 4.0706],
                [6.8895, 4.0235],
                [7.2143, 3.9765],
                [7.7969, 3.9412],
                [8.3794, 3.9059],
                [8.9619, 3.9529],
                [9.5444, 4.0],
                [10.2054, 4.1412],
                [10.8663, 4.2824],
                [11.4712, 4.4824],
                [12.0762, 4.6824],
                [12.6139, 4.9412],
                [13.1516, 5.2],
                [13.5101, 5.4706],
                [13.8686, 5.7412],
                [14.227, 6.0],
                [14.5855, 6.2588],
                [15.0112, 6.6353],
                [15.4369, 7.0118],
                [15.8738, 7.3529],
                [16.3107, 7.6941],
                [16.8484, 8.2706],
                [17.3861, 8.8471],
                [17.655, 9.1765],
                [17.9238, 9.5059],
                [18.1591, 9.7529],
                [18.3943, 10.0]
            ]),
            1.325,
        ),
        (
            layered(true),
            json!([
                [12.0749, 50.0],
                [12.6225, 49.2217],
                [13.17, 48.4434],
                [13.7176, 47.6652],
                [14.2651, 46.8869],
                [14.7454, 46.2528],
                [15.2257, 45.6187],
                [15.7061, 44.9846],
                [16.4102, 44.8352],
                [17.1144, 44.6858],
                [17.8186, 44.5365],
                [18.5227, 44.3871],
                [19.2269, 44.2377],
                [19.9311, 44.0883],
                [20.6353, 43.939],
                [21.3394, 43.7896],
                [22.0436, 43.6402],
                [22.7478, 43.4908],
                [23.4519, 43.3415],
                [24.1561, 43.1921],
                [24.8603, 43.0427],
                [25.5645, 42.8934],
                [26.2686, 42.744],
                [26.9728, 42.5946],
                [27.677, 42.4452],
                [28.3812, 42.2959],
                [29.0853, 42.1465],
                [29.7895, 41.9971],
                [30.4937, 41.8477],
                [31.1978, 41.6984],
                [31.9, 42.0]
            ]),
            1.184,
        ),
        (
            weak_layer(),
            json!([
                [12.58, 50.0],
                [12.87, 49.59],
                [13.16, 49.18],
                [13.45, 48.77],
                [13.7433, 48.37],
                [14.0367, 47.97],
                [14.33, 47.57],
                [14.68, 47.1167],
                [15.03, 46.6633],
                [15.38, 46.21],
                [15.74, 45.8067],
                [16.1, 45.4033],
                [16.46, 45.0],
                [16.93, 44.79],
                [17.4, 44.58],
                [17.86, 44.435],
                [18.32, 44.29],
                [18.81, 44.19],
                [19.3, 44.09],
                [19.88, 44.055],
                [20.46, 44.02],
                [20.92, 44.015],
                [21.38, 44.01],
                [22.1733, 44.0067],
                [22.9667, 44.0033],
                [23.76, 44.0],
                [24.35, 44.0033],
                [24.94, 44.0067],
                [25.53, 44.01],
                [26.225, 44.025],
                [26.92, 44.04]
            ]),
            1.335,
        ),
    ]
}

#[tokio::test]
async fn published_critical_surfaces_give_their_published_factors() {
    // Their F came from each paper's own slicing and method (Spencer or Morgenstern–Price) on
    // these surfaces, which are read off figures to about a centimetre: within 2 %. Measured:
    // 1.3301, 1.2003, 1.3349 (200 slices).
    let server = Server::start().await;
    for (section, surface, published) in published_surfaces() {
        let body = json!({"section": section, "surface": surface, "slices": 200});
        let (status, _, answer) = server.post("/slope/spencer", &body).await;
        assert_eq!(status, 200, "{answer}");
        let f = answer["factor_of_safety"].as_f64().unwrap();
        assert!(
            (f / published - 1.0).abs() < 0.02,
            "F = {f}, published {published}"
        );
        assert_eq!(answer["status"], "converged");
    }
}

#[tokio::test]
async fn a_time_budget_bounds_the_polyline_search() {
    let server = Server::start().await;
    let section = layered(true);
    let body = json!({"section": section, "slices": 50,
                      "search": {"shape": "noncircular", "time_budget_ms": 1}});
    let (status, _, hurried) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{hurried}");
    let warned = hurried["warnings"].as_array().unwrap().iter().any(|w| {
        w["code"] == "budget_exhausted"
            && w["message"]
                .as_str()
                .unwrap()
                .contains("a budget ended the non-circular search")
    });
    assert!(warned, "{}", hurried["warnings"]);
    let f = hurried["factor_of_safety"].as_f64().unwrap();
    assert!(f > 1.3, "F = {f}: 1 ms does not reach the seam");
    // Bad budgets, and a budget for a circular search.
    for (budget, shape) in [
        (json!(0), "noncircular"),
        (json!(6e5 + 1.0), "noncircular"),
        (json!(-5), "noncircular"),
        (json!(100), "circular"),
    ] {
        let body =
            json!({"section": section, "search": {"shape": shape, "time_budget_ms": budget}});
        let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &answer, 422, "search.time_budget_ms");
    }
}

#[tokio::test]
async fn the_simple_slope_refuses_a_noncircular_search_instead_of_ignoring_it() {
    // It used to answer the critical circle as if the shape had not been asked for.
    let server = Server::start().await;
    let simple = json!({"slope": {"height": 10, "length": 20},
                        "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 30}});
    for (search, field) in [
        (json!({"shape": "noncircular"}), "search.shape"),
        (json!({"vertices": 8}), "search.vertices"),
        (json!({"time_budget_ms": 50}), "search.time_budget_ms"),
    ] {
        let mut body = simple.clone();
        body["search"] = search;
        let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
    let mut body = simple;
    body["search"] = json!({"shape": "circular"});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
}

#[tokio::test]
async fn the_polyline_stage_always_runs_and_never_answers_above_the_circle() {
    // model §6.4. A soft clay over bedrock rising towards the crest: the critical circle follows
    // the bedrock (composite). The polyline stage starts from it all the same (it used to skip
    // without a word), and whatever its budget the answer is never above the circle.
    let server = Server::start().await;
    let section = json!({"ground": [[0, 0], [20, 0], [40, 10], [60, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 20, "friction_angle_deg": 5}}],
        "bedrock": [[0, -3], [60, 3]]});
    let circle = server
        .post(
            "/slope/spencer",
            &json!({"section": section, "search": {}, "slices": 50}),
        )
        .await
        .2["factor_of_safety"]
        .as_f64()
        .unwrap();
    for search in [
        json!({"shape": "noncircular"}),
        json!({"shape": "noncircular", "max_evaluations": 5}),
        json!({"shape": "noncircular", "time_budget_ms": 0.01}),
    ] {
        let body = json!({"section": section, "search": search, "slices": 50});
        let (status, _, answer) = server.post("/slope/spencer", &body).await;
        assert_eq!(status, 200, "{answer}");
        assert!(answer["search"]["path"]
            .as_array()
            .is_some_and(|p| !p.is_empty()));
        let f = answer["factor_of_safety"].as_f64().unwrap();
        assert!(f <= circle, "{search}: {f} above the circle's {circle}");
    }
}

#[tokio::test]
async fn an_evaluation_budget_gives_the_same_answer_every_time() {
    let server = Server::start().await;
    let body = json!({"section": layered(true), "slices": 50,
                      "search": {"shape": "noncircular", "max_evaluations": 150}});
    let (_, _, first) = server.post("/slope/spencer", &body).await;
    let (_, _, second) = server.post("/slope/spencer", &body).await;
    assert_eq!(first["search"]["budget_exhausted"], true);
    assert_eq!(first["factor_of_safety"], second["factor_of_safety"]);
    assert_eq!(first["surface"], second["surface"]);
    assert_eq!(
        first["search"]["evaluations"],
        second["search"]["evaluations"]
    );
    // Unbounded, the same search goes further (or as far) and says no budget ended it.
    let body = json!({"section": layered(true), "slices": 50, "search": {"shape": "noncircular"}});
    let (_, _, free) = server.post("/slope/spencer", &body).await;
    assert_eq!(free["search"]["budget_exhausted"], false);
    assert!(
        free["factor_of_safety"].as_f64().unwrap() <= first["factor_of_safety"].as_f64().unwrap()
    );
    // A budget of evaluations is for the polyline stage only, and counted from 1.
    for (search, field) in [
        (json!({"max_evaluations": 10}), "search.max_evaluations"),
        (
            json!({"shape": "noncircular", "max_evaluations": 0}),
            "search.max_evaluations",
        ),
    ] {
        let body = json!({"section": layered(true), "slices": 50, "search": search});
        let (status, content_type, answer) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
}

#[tokio::test]
async fn the_drawing_of_a_non_circular_answer_is_titled_by_its_surface() {
    // Issue 46: a non-circular search's answer was titled "the critical slip circle".
    let server = Server::start().await;
    let body =
        json!({"section": yamagami_ueta(), "search": {"shape": "noncircular"}, "slices": 50});
    let (_, _, svg) = server
        .post_accept("/slope/spencer/svg", "image/svg+xml", &body)
        .await;
    let document = roxmltree::Document::parse(&svg).unwrap();
    let title = document
        .descendants()
        .find(|n| n.has_tag_name("text"))
        .and_then(|n| n.text())
        .unwrap()
        .to_owned();
    let (_, _, answer) = server.post("/slope/spencer", &body).await;
    let circular = answer["circle"].is_object();
    let expected = if circular {
        "Spencer's method: the critical slip circle"
    } else {
        "Spencer's method: the critical slip surface"
    };
    assert_eq!(title, expected);
    assert!(
        !circular,
        "the published non-circular minimum is below the circle's"
    );
}
