//! Arches with fill, road loads and rolling axles over HTTP (model §5.1, §5.3).

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

fn geometry() -> Value {
    json!({"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100})
}

#[tokio::test]
async fn fill_carries_an_arch_that_stands_alone_no_more() {
    // R = 10, D = 1 (t/R = 0.1, below Milankovitch's 0.1075): the bare semicircle falls; with
    // 1.8 of fill to a road at 11.5 it stands and carries a road load. The fill's weight is
    // that of the columns over the extrados, 2·Re·y_r − π·Re²/2 times 1.8 (to the sampling).
    let server = Server::start().await;
    let (status, _, bare) = server
        .post("/arch/dead-load", &json!({"geometry": geometry()}))
        .await;
    assert_eq!(status, 200, "{bare}");
    assert_eq!(bare["stable"], false);
    let fill = json!({"unit_weight": 1.8, "surface": 11.5});
    let (status, _, filled) = server
        .post(
            "/arch/dead-load",
            &json!({"geometry": geometry(), "fill": fill}),
        )
        .await;
    assert_eq!(status, 200, "{filled}");
    assert_eq!(filled["stable"], true);
    let re: f64 = 10.5;
    let expected = 1.8 * (2.0 * re * 11.5 - std::f64::consts::PI * re * re / 2.0);
    let weight = filled["fill_weight"].as_f64().unwrap();
    assert!(
        (weight - expected).abs() < 1e-4 * expected,
        "{weight} vs {expected}"
    );
    let body = json!({"geometry": geometry(), "fill": fill,
                      "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}]});
    let (status, _, live) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{live}");
    assert!(live["load_factor"].as_f64().unwrap() > 0.0);
}

#[tokio::test]
async fn passive_restraint_raises_the_wheel_load_and_reports_what_it_mobilises() {
    // The filled bridge of the test above, its wheel at x = −4: with half the passive pressure
    // of a 30° fill the arch carries more (never less), each force stays within its capacity,
    // and the capacities on the two halves are equal (a symmetric arch and fill, 1e-9).
    let server = Server::start().await;
    let body = |passive: Value| {
        json!({"geometry": geometry(),
               "fill": {"unit_weight": 1.8, "surface": 11.5, "passive": passive},
               "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}]})
    };
    let (status, _, without) = server.post("/arch/live-load", &body(Value::Null)).await;
    assert_eq!(status, 200, "{without}");
    assert!(without.get("passive").is_none(), "{without}");
    let passive = json!({"friction_angle_deg": 30, "mobilisation": 0.5});
    let (status, _, with) = server.post("/arch/live-load", &body(passive)).await;
    assert_eq!(status, 200, "{with}");
    let (bare, restrained) = (
        without["load_factor"].as_f64().unwrap(),
        with["load_factor"].as_f64().unwrap(),
    );
    assert!(restrained > bare * 1.1, "{restrained} vs {bare}");
    assert_eq!(with["solver"]["formulation"], "assembly");
    let forces = with["passive"].as_array().unwrap();
    let mut sides = [0.0, 0.0];
    let mut mobilised = 0.0;
    for f in forces {
        let (capacity, force) = (
            f["capacity"].as_f64().unwrap(),
            f["force"].as_f64().unwrap(),
        );
        assert!(
            force >= -1e-6 && force <= capacity * (1.0 + 1e-6) + 1e-9,
            "{f}"
        );
        mobilised += force;
        sides[usize::from(f["direction"].as_f64().unwrap() > 0.0)] += capacity;
    }
    assert!(mobilised > 0.0);
    assert!((sides[0] - sides[1]).abs() < 1e-9 * sides[0], "{sides:?}");
}

#[tokio::test]
async fn a_rolling_axle_is_symmetric_and_its_worst_stop_is_the_worst_single_load() {
    let server = Server::start().await;
    let fill = json!({"unit_weight": 1.8, "surface": 11.5, "dispersal_angle_deg": 30.0});
    let body = json!({"geometry": geometry(), "fill": fill,
        "rolling": {"axles": [{"fy": -10.0, "length": 0.2}], "x_start": -8.0, "x_end": 8.0,
                    "positions": 17}});
    let (status, _, answer) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    let rolling = &answer["rolling"];
    let factors: Vec<f64> = rolling["load_factor"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(factors.len(), 17);
    // The arch, the fill and the axle are symmetric about x = 0: λ(x) = λ(−x).
    for i in 0..8 {
        let (a, b) = (factors[i], factors[16 - i]);
        assert!((a - b).abs() < 1e-6 * a, "stop {i}: {a} vs {b}");
    }
    // The critical stop is the least λ, and the answer is that stop's.
    let least = factors.iter().copied().fold(f64::INFINITY, f64::min);
    assert_eq!(rolling["critical_load_factor"].as_f64().unwrap(), least);
    assert_eq!(answer["load_factor"].as_f64().unwrap(), least);
    // The stops are 1 apart (−8 … 8 in 17): the least λ lies within half of that of the
    // critical stop (model §6.2).
    assert_eq!(rolling["critical_position_error"].as_f64().unwrap(), 0.5);
    // The same load as a road load at the critical stop gives the same λ.
    let x = rolling["critical_position"].as_f64().unwrap();
    let single = json!({"geometry": geometry(), "fill": fill,
                        "road_loads": [{"x": x, "fy": -10.0, "length": 0.2}]});
    let (_, _, one) = server.post("/arch/live-load", &single).await;
    let f = one["load_factor"].as_f64().unwrap();
    assert!((f - least).abs() < 1e-9 * least, "{f} vs {least}");
}

#[tokio::test]
async fn fill_and_road_errors_name_their_fields() {
    let server = Server::start().await;
    let cases = [
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": 1.8, "surface": 10.0}}),
            "fill.surface",
        ),
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": -1, "surface": 12.0}}),
            "fill.unit_weight",
        ),
        (
            json!({"geometry": geometry(),
                "fill": {"unit_weight": 1, "surface": 12.0, "dispersal_angle_deg": 70}}),
            "fill.dispersal_angle_deg",
        ),
        (
            json!({"geometry": geometry(),
                "fill": {"unit_weight": 1, "surface": 12.0,
                "passive": {"friction_angle_deg": 30, "mobilisation": -0.1}}}),
            "fill.passive.mobilisation",
        ),
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": 1, "surface": 12.0,
                "passive": {"friction_angle_deg": 75, "mobilisation": 0.5}}}),
            "fill.passive.friction_angle_deg",
        ),
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": 1, "surface": 12.0,
                "passive": {"friction_angle_deg": 30, "mobilisation": 1.5}}}),
            "fill.passive.mobilisation",
        ),
    ];
    for (body, field) in cases {
        let (status, content_type, answer) = server.post("/arch/dead-load", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
    let live = [
        (
            json!({"geometry": geometry(), "road_loads": [{"x": 0, "fy": -1}]}),
            "road_loads",
        ),
        (json!({"geometry": geometry()}), "loads"),
        // Beyond the arch (R + D/2 = 10.5): spread at 30° from the road at 12 it reaches the
        // springing level 6.9 short of x = 20, still beyond the arch; it used to be smeared
        // over the whole way to the arch's end and give a finite, meaningless λ.
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": 1, "surface": 12.0},
                "road_loads": [{"x": 20, "fy": -1}]}),
            "road_loads[0].x",
        ),
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": 1, "surface": 12.0},
                "road_loads": [{"x": 2, "fy": 0}]}),
            "road_loads",
        ),
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": 1, "surface": 12.0},
                "road_loads": [{"x": 0, "fy": -1}, {"x": 1e9, "fy": -1}]}),
            "road_loads[1].x",
        ),
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": 1, "surface": 12.0},
                "rolling": {"axles": [{"fy": -1}], "x_start": 20, "x_end": 30}}),
            "rolling.x_start",
        ),
        (
            json!({"geometry": geometry(), "fill": {"unit_weight": 1, "surface": 12.0},
                "rolling": {"axles": [{"fy": -1}], "x_start": 5, "x_end": 1}}),
            "rolling.x_end",
        ),
    ];
    for (body, field) in live {
        let (status, content_type, answer) = server.post("/arch/live-load", &body).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
}

#[tokio::test]
async fn crushing_lowers_lambda_and_names_its_hinges() {
    // The quarter-span load on R = 10, D = 1.5 (Heyman: λ = 22.9969). σ_c = 1e9 changes
    // nothing; σ_c = 100 lowers λ (13.93276 by the solver's crushing tests) with hinges where
    // the stress block reaches the faces.
    let server = Server::start().await;
    let body = |strength: Option<f64>| {
        let mut b = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
                                        "voussoirs": 100},
                           "loads": [{"block": 26, "fy": -1.0}]});
        if let Some(s) = strength {
            b["compressive_strength"] = json!(s);
        }
        b
    };
    let lambda = |v: &Value| v["load_factor"].as_f64().unwrap();
    let (_, _, heyman) = server.post("/arch/live-load", &body(None)).await;
    let (_, _, strong) = server.post("/arch/live-load", &body(Some(1e9))).await;
    assert!((lambda(&strong) - lambda(&heyman)).abs() < 1e-7 * lambda(&heyman));
    let (status, _, weak) = server.post("/arch/live-load", &body(Some(100.0))).await;
    assert_eq!(status, 200, "{weak}");
    assert!((lambda(&weak) - 13.93276).abs() < 1e-4, "{}", lambda(&weak));
    let crushed = weak["mechanism"]["crushing_interfaces"].as_array();
    let active = weak["active_constraints"].to_string();
    assert!(active.contains("\"m\""), "{active}");
    assert!(crushed.is_some_and(|c| !c.is_empty()) || active.contains("\"m\""));
    for (value, field) in [
        (json!(0), "compressive_strength"),
        (json!(-5), "compressive_strength"),
    ] {
        let mut b = body(None);
        b["compressive_strength"] = value;
        let (status, content_type, answer) = server.post("/arch/live-load", &b).await;
        assert_problem(status, &content_type, &answer, 422, field);
    }
    let mut b = body(Some(100.0));
    b["crushing_planes"] = json!(1);
    let (status, content_type, answer) = server.post("/arch/live-load", &b).await;
    assert_problem(status, &content_type, &answer, 422, "crushing_planes");
}

#[tokio::test]
async fn the_live_load_route_judges_the_dead_load_as_the_dead_load_route_does() {
    // With crushing, the live-load solve checks the dead load on its first cuts and again on
    // its final ones (not in between). Across the strength where a thin arch (R = 10, D = 1.2,
    // 40 quadrilateral voussoirs) stops carrying its own weight, between σ_c = 110 and 120 —
    // where the first, outer cuts still carry it and the exact curve does not — the live-load
    // route must say "dead load not carried" exactly where the dead-load route finds λ₀ < 1.
    let server = Server::start().await;
    let geometry = json!({"kind": "circular", "radius": 10.0, "thickness": 1.2, "voussoirs": 40,
                          "voussoir": "quadrilateral"});
    let mut verdicts = Vec::new();
    for strength in [100.0, 104.0, 108.0, 112.0, 116.0, 120.0, 130.0] {
        let dead = json!({"geometry": geometry, "compressive_strength": strength});
        let (status, _, dead) = server.post("/arch/dead-load", &dead).await;
        assert_eq!(status, 200, "{dead}");
        let live = json!({"geometry": geometry, "compressive_strength": strength,
                          "loads": [{"block": 10, "fy": -1.0}]});
        let (status, _, live) = server.post("/arch/live-load", &live).await;
        assert_eq!(status, 200, "{live}");
        let carried = dead["dead_load_factor"].as_f64().unwrap() >= 1.0 - 1e-9;
        assert_eq!(live["stable"], json!(carried), "σ_c = {strength}: {live}");
        assert_eq!(
            live["load_factor"].is_number(),
            carried,
            "σ_c = {strength}: {live}"
        );
        verdicts.push(carried);
    }
    // The range straddles the threshold.
    assert!(
        verdicts.contains(&true) && verdicts.contains(&false),
        "{verdicts:?}"
    );
}

#[tokio::test]
async fn refine_critical_narrows_the_critical_position_between_the_stops() {
    // SPEC §6.2: two axles over the filled arch of the README at 101 stops (spacing 0.22):
    // the critical stop's λ is 0.6413 at x = 0.54 (±0.11). With refine_critical the golden
    // section narrows it to 1e-3 of the spacing; checked against an independent fine sweep of
    // 441 stops (spacing 0.001) between the critical stop's neighbours.
    let server = Server::start().await;
    let axles = json!([{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}]);
    let body = |x_start: f64, x_end: f64, positions: usize, refine: bool| {
        json!({"geometry": geometry(), "fill": {"unit_weight": 1.8, "surface": 11.5},
               "rolling": {"axles": axles, "x_start": x_start, "x_end": x_end,
                           "positions": positions, "refine_critical": refine},
               "include": []})
    };
    let (status, _, coarse) = server
        .post("/arch/live-load", &body(-12.0, 10.0, 101, false))
        .await;
    assert_eq!(status, 200, "{coarse}");
    let stop = &coarse["rolling"];
    let (x_stop, lambda_stop) = (
        stop["critical_position"].as_f64().unwrap(),
        stop["critical_load_factor"].as_f64().unwrap(),
    );
    assert!(stop["refine_evaluations"].is_null());
    let (status, _, refined) = server
        .post("/arch/live-load", &body(-12.0, 10.0, 101, true))
        .await;
    assert_eq!(status, 200, "{refined}");
    let r = &refined["rolling"];
    let (x, lambda, error) = (
        r["critical_position"].as_f64().unwrap(),
        r["critical_load_factor"].as_f64().unwrap(),
        r["critical_position_error"].as_f64().unwrap(),
    );
    assert!(error <= 1e-3 * 0.22 + 1e-12, "error {error}");
    assert!(r["refine_evaluations"].as_u64().unwrap() >= 10);
    assert!(lambda <= lambda_stop, "{lambda} > {lambda_stop}");
    assert!((x - x_stop).abs() <= 0.22, "{x} vs {x_stop}");
    // The answer is the refined position's: its λ, and the stops' curve unchanged.
    assert_eq!(refined["load_factor"].as_f64().unwrap(), lambda);
    assert_eq!(r["load_factor"], stop["load_factor"]);
    // The fine sweep between the neighbours.
    let (status, _, fine) = server
        .post(
            "/arch/live-load",
            &body(x_stop - 0.22, x_stop + 0.22, 441, false),
        )
        .await;
    assert_eq!(status, 200, "{fine}");
    let f = &fine["rolling"];
    let (x_fine, lambda_fine) = (
        f["critical_position"].as_f64().unwrap(),
        f["critical_load_factor"].as_f64().unwrap(),
    );
    assert!(
        lambda <= lambda_fine + 1e-9,
        "refined {lambda} above the fine sweep's {lambda_fine}"
    );
    assert!(
        (lambda_fine - lambda) <= 1e-4 * lambda,
        "{lambda_fine} vs {lambda}"
    );
    assert!(
        (x - x_fine).abs() <= error + 0.001,
        "{x} vs the fine sweep's {x_fine}"
    );
    // One stop: nothing to narrow.
    let (_, _, one) = server
        .post("/arch/live-load", &body(0.5, 0.5, 1, true))
        .await;
    assert_eq!(
        one["rolling"]["critical_position_error"].as_f64(),
        Some(0.0)
    );
}
