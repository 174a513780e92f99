//! The engineering outputs of #12 checked against statics computed here: hinge positions along
//! the span, each slice's equilibrium with its inter-slice components, the resisting and
//! driving totals, and the search grid placed in the request's coordinates.

mod common;

use common::{milankovitch, spencer_example, with, Server};
use serde_json::{json, Value};

fn number(value: &Value) -> f64 {
    value
        .as_f64()
        .unwrap_or_else(|| panic!("not a number: {value}"))
}

/// Milankovitch's D = 1.0747 semicircle (R = 10, N = 1800) collapses in five hinges. The clear
/// span runs between the intrados springings, x = ∓r_i with r_i = R − D/2; a hinge at polar
/// angle θ lies at r·cos θ (r = r_i at the intrados, R + D/2 at the extrados), so its distance
/// from the left end is r·cos θ + r_i and its fraction of the span (r·cos θ + r_i) / 2r_i.
#[tokio::test]
async fn hinges_are_placed_along_the_clear_span() {
    let server = Server::start().await;
    let (status, _, body) = server.post("/arch/dead-load", &milankovitch(1.0747)).await;
    assert_eq!(status, 200, "{body}");
    let (radius, thickness) = (10.0_f64, 1.0747_f64);
    let inner = radius - thickness / 2.0;
    let hinges = body["hinges"].as_array().unwrap();
    assert_eq!(hinges.len(), 5);
    for hinge in hinges {
        let theta = number(&hinge["angle_deg"]).to_radians();
        let r = match hinge["location"].as_str().unwrap() {
            "intrados" => inner,
            _ => radius + thickness / 2.0,
        };
        let distance = r * theta.cos() + inner;
        assert!(
            (number(&hinge["span_distance"]) - distance).abs() < 1e-9,
            "{hinge}"
        );
        let fraction = distance / (2.0 * inner);
        assert!(
            (number(&hinge["span_fraction"]) - fraction).abs() < 1e-10,
            "{hinge}"
        );
    }
    // The crown hinge (interface 901, 90°) sits at mid-span.
    let crown = hinges.iter().find(|h| h["interface"] == 901).unwrap();
    assert!((number(&crown["span_fraction"]) - 0.5).abs() < 1e-12);
}

/// Spencer's example (r_u = 0.5, no loads): every slice is in equilibrium under its weight W,
/// the base's total normal force N along the inward normal (−sin α, cos α), the mobilised shear
/// S up the base (cos α, sin α), and the inter-slice components: (E, X) from the toe-side
/// neighbour, −(E, X) of its own crest-side boundary. Checked to 1e-9·W in both directions —
/// equilibrium the solver's equations never state in these terms.
#[tokio::test]
async fn every_slice_balances_with_its_interslice_components() {
    let server = Server::start().await;
    let (status, _, body) = server.post("/slope/spencer", &spencer_example()).await;
    assert_eq!(status, 200, "{body}");
    let theta = number(&body["theta_deg"]).to_radians();
    let slices = body["slices"].as_array().unwrap();
    let total_weight: f64 = slices.iter().map(|s| number(&s["weight"])).sum();
    let (mut e_toe, mut x_toe) = (0.0, 0.0);
    for slice in slices {
        let alpha = number(&slice["base_inclination_deg"]).to_radians();
        let (n, s, w) = (
            number(&slice["normal_force"]),
            number(&slice["shear_force"]),
            number(&slice["weight"]),
        );
        let (e, x) = (
            number(&slice["interslice_normal"]),
            number(&slice["interslice_shear"]),
        );
        let z = number(&slice["interslice_force"]);
        assert!((e.hypot(x) - z.abs()).abs() < 1e-9 * total_weight);
        // Along (cos θ, sin θ), whichever its sign.
        assert!((x * theta.cos() - e * theta.sin()).abs() < 1e-9 * total_weight);
        assert!((e * theta.cos() + x * theta.sin() - z).abs() < 1e-9 * total_weight);
        let horizontal = -n * alpha.sin() + s * alpha.cos() + e_toe - e;
        let vertical = n * alpha.cos() + s * alpha.sin() - w + x_toe - x;
        assert!(
            horizontal.abs() < 1e-9 * total_weight,
            "{slice}: {horizontal}"
        );
        assert!(vertical.abs() < 1e-9 * total_weight, "{slice}: {vertical}");
        (e_toe, x_toe) = (e, x);
    }
    // The last boundary is the exit: no force there.
    assert!(e_toe.abs() < 1e-9 * total_weight && x_toe.abs() < 1e-9 * total_weight);

    // Resisting and driving totals, summed here from the slices; their ratio is F.
    let strength: f64 = slices
        .iter()
        .map(|s| number(&s["available_shear_strength"]) * number(&s["base_length"]))
        .sum();
    let mobilised: f64 = slices.iter().map(|s| number(&s["shear_force"])).sum();
    assert!((number(&body["total_shear_strength"]) - strength).abs() < 1e-9 * strength);
    assert!((number(&body["total_mobilised_shear"]) - mobilised).abs() < 1e-9 * mobilised);
    let f = number(&body["factor_of_safety"]);
    assert!(
        (strength / mobilised - f).abs() < 1e-9 * f,
        "{strength} / {mobilised} vs {f}"
    );
}

/// The search grid of the simple slope is relative to the lower end of its circles; placed in
/// the request's coordinates (toe at the origin) it must be where the circle placement puts
/// the same relative centre: a relative circle request at a grid point answers with
/// `circle.centre` at that point's absolute coordinates. Lower end 0.5·H before the toe.
#[tokio::test]
async fn the_search_grid_is_given_in_absolute_coordinates() {
    let server = Server::start().await;
    let mut search = spencer_example();
    search.as_object_mut().unwrap().remove("circle");
    search["search"] = json!({"nx": 5, "ny": 4, "lower_end_factor": 0.5});
    search["slices"] = json!(20);
    let (status, _, body) = server.post("/slope/spencer", &search).await;
    assert_eq!(status, 200, "{body}");
    let grid = &body["grid"];
    let (xs, ys) = (
        grid["xs"].as_array().unwrap(),
        grid["ys"].as_array().unwrap(),
    );
    assert_eq!(grid["x_absolute"].as_array().unwrap().len(), xs.len());
    // Every grid point with a factor (a circle that cuts a mass), at most five of them.
    let solved: Vec<(usize, usize)> = (0..ys.len())
        .flat_map(|j| (0..xs.len()).map(move |i| (i, j)))
        .filter(|&(i, j)| grid["factor_of_safety"][j][i].is_number())
        .step_by(3)
        .take(5)
        .collect();
    assert!(solved.len() >= 3, "{grid}");
    for (i, j) in solved {
        let (x, y) = (number(&xs[i]), number(&ys[j]));
        let circle = with(
            with(
                spencer_example(),
                "circle",
                json!({"x": x, "y": y, "lower_end_factor": 0.5}),
            ),
            "slices",
            json!(20),
        );
        let (status, _, placed) = server.post("/slope/spencer", &circle).await;
        assert_eq!(status, 200, "{placed}");
        let centre = &placed["circle"]["centre"];
        assert!((number(&grid["x_absolute"][i]) - number(&centre["x"])).abs() < 1e-9);
        assert!((number(&grid["y_absolute"][j]) - number(&centre["y"])).abs() < 1e-9);
    }
}

/// `include` keeps only the details named: the others come back empty (the mechanism null),
/// listed in `omitted`; the factor and everything else is the full answer's. At N = 10,000 the
/// answer without details is a few hundred bytes instead of megabytes.
#[tokio::test]
async fn include_leaves_out_the_details_not_named() {
    let server = Server::start().await;
    let full_request = json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 10_000},
        "loads": [{"block": 2_500, "fy": -1.0}]
    });
    let (status, _, full) = server.post("/arch/live-load", &full_request).await;
    assert_eq!(status, 200, "{full}");
    assert_eq!(full["omitted"], json!([]));
    assert_eq!(full["thrust_line"].as_array().unwrap().len(), 10_001);

    let (status, _, bare) = server
        .post(
            "/arch/live-load",
            &with(full_request.clone(), "include", json!([])),
        )
        .await;
    assert_eq!(status, 200, "{bare}");
    assert_eq!(bare["load_factor"], full["load_factor"]);
    assert_eq!(bare["stable"], full["stable"]);
    assert_eq!(bare["thrust_margin"], full["thrust_margin"]);
    assert_eq!(bare["sliding_interfaces"], full["sliding_interfaces"]);
    for empty in ["thrust_line", "hinges", "active_constraints", "reactions"] {
        assert_eq!(bare[empty], json!([]), "{empty}");
    }
    assert_eq!(bare["mechanism"], Value::Null);
    assert_eq!(
        bare["omitted"],
        json!([
            "active_constraints",
            "hinges",
            "mechanism",
            "thrust_line",
            "reactions"
        ])
    );
    let (bare_size, full_size) = (bare.to_string().len(), full.to_string().len());
    assert!(
        bare_size < 2_000 && full_size > 1_000_000,
        "{bare_size} vs {full_size}"
    );

    // One detail named (twice: it counts once), null meaning all.
    let (_, _, hinges) = server
        .post(
            "/arch/live-load",
            &with(full_request.clone(), "include", json!(["hinges", "hinges"])),
        )
        .await;
    assert_eq!(hinges["hinges"].as_array().unwrap().len(), 4);
    assert_eq!(hinges["hinges"], full["hinges"]);
    assert_eq!(hinges["thrust_line"], json!([]));
    let (_, _, all) = server
        .post(
            "/arch/live-load",
            &with(full_request, "include", Value::Null),
        )
        .await;
    assert_eq!(all["omitted"], json!([]));
    assert_eq!(all["hinges"], full["hinges"]);

    // The slope: the totals and F stay, the slices go.
    let (_, _, slope_full) = server.post("/slope/spencer", &spencer_example()).await;
    let (status, _, slope) = server
        .post(
            "/slope/spencer",
            &with(spencer_example(), "include", json!(["thrust_line"])),
        )
        .await;
    assert_eq!(status, 200, "{slope}");
    assert_eq!(slope["factor_of_safety"], slope_full["factor_of_safety"]);
    assert_eq!(
        slope["total_shear_strength"],
        slope_full["total_shear_strength"]
    );
    assert_eq!(slope["thrust_line"], slope_full["thrust_line"]);
    assert_eq!(slope["slices"], json!([]));
    assert_eq!(
        slope["omitted"],
        json!(["surface", "slices", "effective_thrust_line", "grid"])
    );
    let (status, _, body) = server
        .post(
            "/slope/spencer",
            &with(spencer_example(), "include", json!(["everything"])),
        )
        .await;
    assert_eq!(status, 422, "{body}");
    assert_eq!(body["field"], "include[0]");
}
