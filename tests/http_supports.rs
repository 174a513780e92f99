//! `section.supports` over HTTP (model §7): each support's crossing, force and mode in the
//! answer, every method and the search honouring them, the drawing showing them, and bad
//! supports refused naming the field. The equations themselves are checked against the wedge's
//! closed form in the solver's tests (crates/solver/tests/supports.rs).
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

/// The 45° face of crates/solver/tests/supports.rs with a nail through its middle and the
/// planar surface at 30° from the toe.
fn nailed(application: &str) -> Value {
    json!({
        "section": {
            "ground": [[0, 0], [10, 0], [20, 10], [40, 10]],
            "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 5, "friction_angle_deg": 30}}],
            "supports": [{"kind": "soil_nail", "head": [15, 5], "end": [26.59110991546882, 1.8941738241592206],
                          "spacing": 1.5, "tensile_capacity": 150, "plate_capacity": 50,
                          "bond_strength": 20, "application": application}]
        },
        "surface": [[10, 0], [27.320508075688775, 10]],
        "slices": 40,
        "methods": ["morgenstern_price", "bishop", "janbu", "ordinary"],
        "include": []
    })
}

#[tokio::test]
async fn the_answer_lists_each_support_and_every_method_honours_it() {
    let server = Server::start().await;
    let (status, _, active) = server.post("/slope/spencer", &nailed("active")).await;
    assert_eq!(status, 200, "{active}");
    let (_, _, passive) = server.post("/slope/spencer", &nailed("passive")).await;
    let mut bare = nailed("active");
    bare["section"]["supports"] = json!([]);
    let (_, _, bare) = server.post("/slope/spencer", &bare).await;
    // Without supports the answer has no `supports` (as before the feature).
    assert!(bare.get("supports").is_none(), "{bare}");
    let support = &active["supports"][0];
    assert_eq!(support["support"], 1);
    assert_eq!(support["mode"], "stripping");
    assert_eq!(support["application"], "active");
    // The crossing on the plane y = (x − 10)·tan 30°, and the force (plate + bond × length
    // inside) ÷ spacing, measured here.
    let p = [
        support["crossing"][0].as_f64().unwrap(),
        support["crossing"][1].as_f64().unwrap(),
    ];
    assert!((p[1] - (p[0] - 10.0) * 30f64.to_radians().tan()).abs() < 1e-9);
    let inside = (p[0] - 15.0).hypot(p[1] - 5.0);
    let force = support["force"].as_f64().unwrap();
    assert!(
        (force - (50.0 + 20.0 * inside) / 1.5).abs() < 1e-9,
        "{force}"
    );
    // Every method gains from the nail, passive never more than active; on a plane Spencer's
    // force equation is Janbu's.
    let f = |v: &Value| v["factor_of_safety"].as_f64().unwrap();
    assert!(f(&bare) < f(&passive) && f(&passive) < f(&active));
    for method in ["morgenstern_price", "janbu", "ordinary"] {
        let m = |v: &Value| v["methods"][method]["factor_of_safety"].as_f64();
        if let (Some(b), Some(a), Some(p)) = (m(&bare), m(&active), m(&passive)) {
            assert!(b < a && b < p, "{method}: {b} {p} {a}");
        }
    }
    let janbu = active["methods"]["janbu"]["factor_of_safety"]
        .as_f64()
        .unwrap();
    assert!((janbu - f(&active)).abs() < 1e-9 * janbu);
}

#[tokio::test]
async fn a_search_gives_each_trial_surface_its_own_forces_and_the_drawing_shows_them() {
    let server = Server::start().await;
    let mut search = nailed("passive");
    search.as_object_mut().unwrap().remove("surface");
    search["search"] = json!({});
    search["slices"] = json!(30);
    let (status, _, answer) = server.post("/slope/spencer", &search).await;
    assert_eq!(status, 200, "{answer}");
    let mut bare = search.clone();
    bare["section"]["supports"] = json!([]);
    let (_, _, unreinforced) = server.post("/slope/spencer", &bare).await;
    let f = |v: &Value| v["factor_of_safety"].as_f64().unwrap();
    // The critical surface of the nailed slope is at least as safe as the bare one's.
    assert!(
        f(&answer) >= f(&unreinforced) - 1e-9,
        "{} {}",
        f(&answer),
        f(&unreinforced)
    );
    assert_eq!(answer["supports"].as_array().unwrap().len(), 1);
    // Drawn on the plane, which the nail crosses.
    let response = server
        .client
        .post(format!("{}/slope/spencer/svg", server.base))
        .json(&nailed("active"))
        .send()
        .await
        .unwrap();
    let svg = response.text().await.unwrap();
    roxmltree::Document::parse(&svg).unwrap();
    assert!(
        svg.contains("supports: ● where the surface crosses"),
        "no key entry"
    );
    assert!(svg.contains("stroke=\"#2e7d32\""), "no support drawn");
    // The support forces' arrowheads are green, not the live loads' blue ones.
    assert!(
        svg.contains("marker-end=\"url(#arrow-2e7d32)\""),
        "no green arrow"
    );
    assert!(
        svg.contains("<marker id=\"arrow-2e7d32\""),
        "no green arrowhead defined"
    );
}

#[tokio::test]
async fn bad_supports_are_refused_naming_the_field() {
    let server = Server::start().await;
    let with = |path: &str, value: Value| common::with(nailed("active"), path, value);
    for (body, field) in [
        (
            with("section.supports.0.spacing", json!(0)),
            "section.supports[0].spacing",
        ),
        (
            with("section.supports.0.tensile_capacity", json!(-1)),
            "section.supports[0].tensile_capacity",
        ),
        (
            with("section.supports.0.head", json!([50, 10])),
            "section.supports[0].head",
        ),
        (
            with("section.supports.0.end", json!([15, 5])),
            "section.supports[0].end",
        ),
        (
            with("section.supports.0.head", json!([15, 9])),
            "section.supports[0].head",
        ),
    ] {
        let (status, content_type, problem) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &problem, 422, field);
        assert_eq!(problem["field"], field, "{problem}");
    }
    // A tieback whose bond is longer than the tieback.
    let mut tieback = nailed("active");
    tieback["section"]["supports"][0] = json!({"kind": "grouted_tieback", "head": [15, 5], "end": [26, 2],
        "spacing": 2, "tensile_capacity": 400, "plate_capacity": 400, "bond_strength": 80,
        "bond_length": 50, "application": "active"});
    let (status, content_type, problem) = server.post("/slope/spencer", &tieback).await;
    assert_problem(
        status,
        &content_type,
        &problem,
        422,
        "section.supports[0].bond_length",
    );
    // An unknown kind, a field another kind has, no application.
    let mut unknown = nailed("active");
    unknown["section"]["supports"][0]["kind"] = json!("rock_bolt");
    let mut foreign = nailed("active");
    foreign["section"]["supports"][0]["bond_length"] = json!(3);
    let mut missing = nailed("active");
    missing["section"]["supports"][0]
        .as_object_mut()
        .unwrap()
        .remove("application");
    for body in [unknown, foreign, missing] {
        let (status, _, problem) = server.post("/slope/spencer", &body).await;
        assert_eq!(status, 422, "{problem}");
        assert!(
            problem["detail"].as_str().unwrap().contains("supports"),
            "{problem}"
        );
    }
    // More than 1000.
    let mut many = nailed("active");
    let one = many["section"]["supports"][0].clone();
    many["section"]["supports"] = Value::Array(vec![one; 1001]);
    let (status, content_type, problem) = server.post("/slope/spencer", &many).await;
    assert_problem(status, &content_type, &problem, 422, "section.supports");
}

#[tokio::test]
async fn the_numbers_docs_slopes_states_around_its_reinforcement_example() {
    // docs/slopes.md's example as written (its own numbers are checked by the example
    // runner); here the ones its prose gives beside it.
    let server = Server::start().await;
    let body = |supports: Value| {
        json!({"section": {"ground": [[0, 0], [10, 0], [20, 10], [40, 10]],
                           "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 5, "friction_angle_deg": 30}}],
                           "supports": supports},
               "surface": [[10, 0], [27.3205, 10]], "slices": 40, "include": []})
    };
    let nail = |application: &str| {
        json!([{"kind": "soil_nail", "head": [15, 5], "end": [26.6, 1.9], "spacing": 1.5,
                "tensile_capacity": 150, "plate_capacity": 50, "bond_strength": 20,
                "application": application}])
    };
    let f = |v: &Value| v["factor_of_safety"].as_f64().unwrap();
    let (_, _, bare) = server.post("/slope/spencer", &body(json!([]))).await;
    assert!((f(&bare) - 1.2732).abs() < 5e-5, "{}", f(&bare));
    let (_, _, passive) = server.post("/slope/spencer", &body(nail("passive"))).await;
    assert!((f(&passive) - 1.4800).abs() < 5e-5, "{}", f(&passive));
    // The nail's length inside the mass: 2.59.
    let p = &passive["supports"][0]["crossing"];
    let inside = (p[0].as_f64().unwrap() - 15.0).hypot(p[1].as_f64().unwrap() - 5.0);
    assert!((inside - 2.59).abs() < 5e-3, "{inside}");
}
