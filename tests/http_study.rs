//! Probabilistic and sensitivity studies over HTTP (model §9.2–9.3), checked against what must
//! hold analytically: on a fixed φ = 0 circle F = c·L·R/(γ·M) is linear in c and in 1/γ, so a
//! normal c gives a normal F with PF = Φ((1 − mean)/std), a lognormal c a lognormal F; the
//! correlation of c and γ is checked against a sampler written here; re-searching never fails
//! less often than the fixed surface; bad study input is refused naming its field.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{assert_problem, Server};
use serde_json::{json, Value};

/// Φ by Abramowitz & Stegun 7.1.26 (|error| < 1.5e-7), written here apart from the solver's.
fn phi(z: f64) -> f64 {
    let x = z.abs() / std::f64::consts::SQRT_2;
    let t = 1.0 / (1.0 + 0.327_591_1 * x);
    let poly = t
        * (0.254_829_592
            + t * (-0.284_496_736
                + t * (1.421_413_741 + t * (-1.453_152_027 + t * 1.061_405_429))));
    let erf = 1.0 - poly * (-x * x).exp();
    if z >= 0.0 {
        0.5 * (1.0 + erf)
    } else {
        0.5 * (1.0 - erf)
    }
}

/// A frictionless embankment on a fixed circle: F = c·L·R/(γ·M).
fn undrained(cohesion: f64, unit_weight: f64) -> Value {
    json!({
        "slope": {"height": 10, "length": 20},
        "circle": {"centre": [8, 18], "radius": 19},
        "slices": 100,
        "soil": {"unit_weight": unit_weight, "cohesion": cohesion, "friction_angle_deg": 0},
        "include": [],
    })
}

fn num(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key} in {v}"))
}

async fn answer(server: &Server, body: &Value) -> Value {
    let (status, _, answer) = server.post("/slope/spencer", body).await;
    assert_eq!(status, 200, "{answer}");
    answer
}

#[tokio::test]
async fn a_normal_cohesion_gives_the_normal_probability_of_failure() {
    let server = Server::start().await;
    let (c, sd) = (30.0, 6.0);
    let mut body = undrained(c, 18.0);
    // F is linear in c through 0: checked on the sensitivity study's points.
    body["sensitivity"] =
        json!({"variables": [{"field": "soil.cohesion", "from": 10, "to": 50, "points": 5}]});
    let n = 20_000;
    body["probabilistic"] = json!({"samples": n, "seed": 3,
        "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": sd}]});
    let a = answer(&server, &body).await;
    let f0 = num(&a, "factor_of_safety");
    let k = f0 / c;
    for p in a["sensitivity"]["variables"][0]["points"]
        .as_array()
        .unwrap()
    {
        let (x, f) = (num(p, "value"), num(p, "factor"));
        assert!((f - k * x).abs() < 1e-9 * f, "F({x}) = {f}, not {}", k * x);
    }
    let p = &a["probabilistic"];
    let (mean, std) = (k * c, k * sd);
    let pf = phi((1.0 - mean) / std);
    assert!(pf > 0.05 && pf < 0.5, "a probability worth sampling: {pf}");
    let se = (pf * (1.0 - pf) / n as f64).sqrt();
    assert!(
        (num(p, "probability_of_failure") - pf).abs() < 4.0 * se,
        "{p} vs {pf}"
    );
    assert!(
        (num(p, "mean") - mean).abs() < 4.0 * std / (n as f64).sqrt(),
        "{p}"
    );
    assert!(
        (num(p, "std") - std).abs() < 4.0 * std / (2.0 * n as f64).sqrt(),
        "{p}"
    );
    let reported_se = num(p, "probability_of_failure_standard_error");
    assert!((reported_se - se).abs() < 0.1 * se, "{reported_se} vs {se}");
    assert_eq!(p["samples"], n);
    assert_eq!(
        (p["unsolved"].as_u64(), p["refused"].as_u64()),
        (Some(0), Some(0))
    );
    let failed = p["failed"].as_u64().unwrap() as f64;
    assert!((failed / n as f64 - num(p, "probability_of_failure")).abs() < 1e-12);
    let counted: u64 = p["histogram"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["count"].as_u64().unwrap())
        .sum();
    assert_eq!(counted, n as u64);
    // β by its definition, from the answer's own mean and std.
    let beta = (num(p, "mean") - 1.0) / num(p, "std");
    assert!((num(p, "reliability_index_normal") - beta).abs() < 1e-12);
}

#[tokio::test]
async fn a_lognormal_cohesion_gives_the_lognormal_probability_of_failure() {
    let server = Server::start().await;
    let (c, sd) = (30.0, 9.0);
    let mut body = undrained(c, 18.0);
    let n = 20_000;
    body["probabilistic"] = json!({"samples": n, "seed": 11, "sampling": "latin_hypercube",
        "variables": [{"field": "soil.cohesion", "distribution": "lognormal", "std": sd}]});
    let a = answer(&server, &body).await;
    let k = num(&a, "factor_of_safety") / c;
    // ln F = ln k + ln c: normal with σ² = ln(1 + V²), μ = ln(k·mean) − σ²/2.
    let s2 = (1.0 + (sd / c).powi(2)).ln();
    let mu = (k * c).ln() - s2 / 2.0;
    let pf = phi(-mu / s2.sqrt());
    assert!(pf > 0.05 && pf < 0.5, "{pf}");
    let p = &a["probabilistic"];
    let se = (pf * (1.0 - pf) / n as f64).sqrt();
    assert!(
        (num(p, "probability_of_failure") - pf).abs() < 4.0 * se,
        "{p} vs {pf}"
    );
    // The lognormal index of a lognormal F is −Φ⁻¹(PF): μ/σ.
    assert!(
        (num(p, "reliability_index_lognormal") - mu / s2.sqrt()).abs() < 0.02,
        "{p}"
    );
    assert!((num(p, "mean") - k * c).abs() < 4.0 * k * sd / (n as f64).sqrt());
}

/// splitmix64: this test's own random numbers.
struct Mix(u64);

impl Mix {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64 + 0.5 / (1u64 << 53) as f64
    }

    /// Two independent standard normals (Box–Muller).
    fn normals(&mut self) -> (f64, f64) {
        let (u, v) = (self.unit(), self.unit());
        let r = (-2.0 * u.ln()).sqrt();
        let t = std::f64::consts::TAU * v;
        (r * t.cos(), r * t.sin())
    }
}

#[tokio::test]
async fn correlated_cohesion_and_weight_fail_as_an_independent_sampler_says() {
    // F = k·c/γ: a positive correlation of c and γ narrows F and lowers PF.
    let server = Server::start().await;
    let (c, sc, g, sg, rho) = (26.0, 5.0, 18.0, 2.5, 0.8);
    let mut body = undrained(c, g);
    let k = num(&answer(&server, &body).await, "factor_of_safety") * g / c;
    let n = 20_000;
    let variables = json!([
        {"field": "soil.cohesion", "distribution": "normal", "std": sc},
        {"field": "soil.unit_weight", "distribution": "normal", "std": sg}]);
    let mut pfs = Vec::new();
    for r in [0.0, rho] {
        body["probabilistic"] = json!({"samples": n, "seed": 5, "variables": variables,
            "correlations": [{"fields": ["soil.cohesion", "soil.unit_weight"], "coefficient": r}]});
        let a = answer(&server, &body).await;
        let p = num(&a["probabilistic"], "probability_of_failure");
        // The same study drawn here: z₂ = ρ·z₁ + √(1 − ρ²)·ε.
        let mut mix = Mix(0x5EED + (r * 10.0) as u64);
        let m = 400_000;
        let failed = (0..m)
            .filter(|_| {
                let (z1, e) = mix.normals();
                let z2 = r * z1 + (1.0 - r * r).sqrt() * e;
                k * (c + sc * z1) / (g + sg * z2) < 1.0
            })
            .count();
        let expected = failed as f64 / m as f64;
        let se = (expected * (1.0 - expected) * (1.0 / n as f64 + 1.0 / m as f64)).sqrt();
        assert!(
            (p - expected).abs() < 4.0 * se,
            "ρ = {r}: {p} vs {expected} ± {se}"
        );
        pfs.push(p);
    }
    assert!(
        pfs[0] - pfs[1] > 0.03,
        "the correlation matters here: {pfs:?}"
    );
}

#[tokio::test]
async fn searching_every_sample_fails_at_least_as_often_as_the_fixed_surface() {
    let server = Server::start().await;
    let mut body = json!({"slope": {"height": 10, "length": 20}, "search": {}, "slices": 40,
        "soil": {"unit_weight": 19, "cohesion": 5, "friction_angle_deg": 22}, "include": []});
    let n = 400;
    let mut pf = Vec::new();
    for surface in ["fixed", "search"] {
        body["probabilistic"] = json!({"samples": n, "seed": 2, "surface": surface,
            "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 2, "min": 0.5},
                          {"field": "soil.friction_angle_deg", "distribution": "normal", "std": 4, "min": 5}]});
        let a = answer(&server, &body).await;
        assert_eq!(a["probabilistic"]["surface"], surface);
        assert_eq!(a["probabilistic"]["unsolved"], 0, "{}", a["probabilistic"]);
        pf.push((
            num(&a["probabilistic"], "probability_of_failure"),
            num(&a["probabilistic"], "mean"),
        ));
    }
    // The same seed draws the same samples: each sample's own critical surface is no safer
    // than the fixed one, so the mean falls and PF rises (within rounding of the search).
    assert!(pf[1].0 >= pf[0].0, "{pf:?}");
    assert!(pf[1].1 <= pf[0].1 + 1e-6, "{pf:?}");
    assert!(pf[0].0 > 0.05, "{pf:?}");
}

#[tokio::test]
async fn a_sample_at_the_stated_values_is_the_deterministic_answer() {
    // A variable confined to its stated value: every fixed-surface sample is the answer itself,
    // for a circle found by a search and for a non-circular surface.
    let server = Server::start().await;
    let section = json!({"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
        "layers": [{"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]});
    let bodies = [
        json!({"slope": {"height": 10, "length": 20}, "search": {}, "slices": 40, "slice_tolerance": 1e-4,
               "soil": {"unit_weight": 19, "cohesion": 9, "friction_angle_deg": 22}}),
        json!({"section": section, "search": {"shape": "noncircular", "vertices": 8, "max_evaluations": 300},
               "slices": 40}),
    ];
    for (mut body, field, value) in [
        (bodies[0].clone(), "soil.cohesion", 9.0),
        (bodies[1].clone(), "section.layers[0].soil.cohesion", 600.0),
    ] {
        body["include"] = json!([]);
        body["probabilistic"] = json!({"samples": 8, "variables": [{"field": field,
            "distribution": "uniform", "min": value * (1.0 - 1e-12), "max": value * (1.0 + 1e-12)}]});
        body["sensitivity"] =
            json!({"variables": [{"field": field, "from": value, "to": 2.0 * value, "points": 2}]});
        let a = answer(&server, &body).await;
        let f0 = num(&a, "factor_of_safety");
        let p = &a["probabilistic"];
        assert!(
            (num(p, "mean") - f0).abs() < 1e-9 * f0,
            "{} vs {f0}",
            p["mean"]
        );
        assert!(num(p, "std") < 1e-9 * f0, "{p}");
        // The sensitivity study re-runs the search: at the stated value it is the answer.
        let at = num(&a["sensitivity"]["variables"][0]["points"][0], "factor");
        assert!((at - f0).abs() < 1e-12 * f0, "{at} vs {f0}");
    }
}

#[tokio::test]
async fn the_same_seed_gives_the_same_answer() {
    let server = Server::start().await;
    let mut body = undrained(30.0, 18.0);
    let study = |seed: u64| {
        json!({"samples": 500, "seed": seed, "sampling": "latin_hypercube",
        "variables": [{"field": "soil.cohesion", "distribution": "triangular", "min": 20, "max": 36},
                      {"field": "soil.unit_weight", "distribution": "uniform", "min": 17, "max": 19}]})
    };
    body["probabilistic"] = study(4);
    let a = answer(&server, &body).await["probabilistic"].clone();
    let b = answer(&server, &body).await["probabilistic"].clone();
    body["probabilistic"] = study(5);
    let c = answer(&server, &body).await["probabilistic"].clone();
    let strip = |mut v: Value| {
        v.as_object_mut().unwrap().remove("time_ms");
        v
    };
    assert_eq!(strip(a.clone()), strip(b));
    assert_ne!(strip(a.clone()), strip(c));
    // Triangular on [20, 36] with mode 30: mean (20 + 30 + 36)/3; F = k·c/γ with γ uniform.
    let k = num(
        &answer(&server, &undrained(30.0, 18.0)).await,
        "factor_of_safety",
    ) * 18.0
        / 30.0;
    let mean_inverse_weight = (19.0f64 / 17.0).ln() / 2.0;
    let expected = k * (20.0 + 30.0 + 36.0) / 3.0 * mean_inverse_weight;
    assert!(
        (num(&a, "mean") - expected).abs() < 2e-3 * expected,
        "{a} vs {expected}"
    );
}

#[tokio::test]
async fn samples_the_route_refuses_are_counted_and_named() {
    let server = Server::start().await;
    let mut body = undrained(4.0, 18.0);
    body["probabilistic"] = json!({"samples": 400, "seed": 1,
        "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 4}]});
    let a = answer(&server, &body).await;
    let p = &a["probabilistic"];
    let refused = p["refused"].as_u64().unwrap();
    // P(c < 0) = Φ(−1): about 63 of 400; a zero cohesion with φ' = 0 is refused too.
    assert!((40..90).contains(&refused), "{p}");
    let warning = common::warning(&a, "samples_refused");
    assert!(
        warning["message"]
            .as_str()
            .unwrap()
            .contains("soil.cohesion"),
        "{warning}"
    );
    let counted: u64 = p["histogram"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["count"].as_u64().unwrap())
        .sum();
    assert_eq!(counted + refused, 400);
}

#[tokio::test]
async fn bad_studies_are_refused_naming_the_field() {
    let server = Server::start().await;
    let variable = |v: Value| json!({"samples": 10, "variables": [v]});
    let normal = |field: &str| json!({"field": field, "distribution": "normal", "std": 1});
    let pair = json!([
        normal("soil.cohesion"),
        normal("soil.unit_weight"),
        normal("soil.friction_angle_deg")
    ]);
    let cases: Vec<(Value, &str)> = vec![
        (
            variable(normal("soil.nothing")),
            "probabilistic.variables[0].field",
        ),
        (
            variable(normal("soil.cohesion[2]")),
            "probabilistic.variables[0].field",
        ),
        (variable(normal("soil")), "probabilistic.variables[0].field"),
        (
            variable(normal("slices")),
            "probabilistic.variables[0].field",
        ),
        (
            variable(normal("so il")),
            "probabilistic.variables[0].field",
        ),
        (
            variable(normal("probabilistic.samples")),
            "probabilistic.variables[0].field",
        ),
        (
            variable(json!({"field": "soil.cohesion", "distribution": "normal", "std": 0})),
            "probabilistic.variables[0].std",
        ),
        (
            variable(json!({"field": "soil.cohesion", "distribution": "normal", "std": -1})),
            "probabilistic.variables[0].std",
        ),
        (
            variable(json!({"field": "soil.cohesion", "distribution": "normal"})),
            "probabilistic.variables[0].std",
        ),
        (
            variable(
                json!({"field": "soil.cohesion", "distribution": "uniform", "min": 5, "max": 5}),
            ),
            "probabilistic.variables[0].max",
        ),
        (
            variable(json!({"field": "soil.cohesion", "distribution": "uniform", "min": 5})),
            "probabilistic.variables[0].max",
        ),
        (
            variable(
                json!({"field": "soil.cohesion", "distribution": "uniform", "min": 1, "max": 9, "std": 1}),
            ),
            "probabilistic.variables[0].std",
        ),
        (
            variable(
                json!({"field": "soil.cohesion", "distribution": "triangular", "min": 40, "max": 50}),
            ),
            "probabilistic.variables[0].field",
        ),
        (
            variable(
                json!({"field": "circle.lower_end_factor", "distribution": "lognormal", "std": 1}),
            ),
            "probabilistic.variables[0].field",
        ),
        (
            variable(
                json!({"field": "soil.cohesion", "distribution": "normal", "std": 1, "min": 1000, "max": 2000}),
            ),
            "probabilistic.variables[0].min",
        ),
        (
            json!({"samples": 100_001, "variables": [normal("soil.cohesion")]}),
            "probabilistic.samples",
        ),
        (
            json!({"samples": 0, "variables": [normal("soil.cohesion")]}),
            "probabilistic.samples",
        ),
        (
            json!({"samples": 10, "variables": []}),
            "probabilistic.variables",
        ),
        (
            json!({"samples": 10, "histogram_bins": 0, "variables": [normal("soil.cohesion")]}),
            "probabilistic.histogram_bins",
        ),
        (
            json!({"samples": 10, "variables": [normal("soil.cohesion"), normal("soil.cohesion")]}),
            "probabilistic.variables[1].field",
        ),
        (
            json!({"samples": 10, "variables": pair, "correlations": [
            {"fields": ["soil.cohesion", "soil.unit_weight"], "coefficient": 0.9},
            {"fields": ["soil.cohesion", "soil.friction_angle_deg"], "coefficient": 0.9},
            {"fields": ["soil.unit_weight", "soil.friction_angle_deg"], "coefficient": -0.9}]}),
            "probabilistic.correlations",
        ),
        (
            json!({"samples": 10, "variables": pair, "correlations": [
            {"fields": ["soil.cohesion", "soil.unit_weight"], "coefficient": 1.0}]}),
            "probabilistic.correlations",
        ),
        (
            json!({"samples": 10, "variables": pair, "correlations": [
            {"fields": ["soil.cohesion", "soil.unit_weight"], "coefficient": 1.5}]}),
            "probabilistic.correlations[0].coefficient",
        ),
        (
            json!({"samples": 10, "variables": pair, "correlations": [
            {"fields": ["soil.cohesion", "slope.height"], "coefficient": 0.5}]}),
            "probabilistic.correlations[0].fields",
        ),
        (
            json!({"samples": 10, "variables": pair, "correlations": [
            {"fields": ["soil.cohesion", "soil.cohesion"], "coefficient": 0.5}]}),
            "probabilistic.correlations[0].fields",
        ),
        (
            json!({"samples": 10, "variables": pair, "correlations": [
            {"fields": ["soil.cohesion", "soil.unit_weight"], "coefficient": 0.0},
            {"fields": ["soil.unit_weight", "soil.cohesion"], "coefficient": 0.3}]}),
            "probabilistic.correlations[1].fields",
        ),
    ];
    for (study, field) in cases {
        let mut body = common::spencer_example();
        body["include"] = json!([]);
        body["probabilistic"] = study.clone();
        let (status, content_type, problem) = server.post("/slope/spencer", &body).await;
        assert_eq!(status, 422, "{study}: {}", problem["probabilistic"]);
        assert_problem(status, &content_type, &problem, 422, field);
        assert_eq!(problem["field"], field, "{problem}");
    }
    let mut body = common::spencer_example();
    body["probabilistic"] = variable(normal("soil.cohesion"));
    body["design"] = json!({"approach": "DA1-2"});
    let (status, content_type, problem) = server.post("/slope/spencer", &body).await;
    assert_problem(status, &content_type, &problem, 422, "probabilistic");
    let sensitivity_cases = [
        (
            json!({"variables": [{"field": "soil.cohesion", "from": 1, "to": 1}]}),
            "sensitivity.variables[0].to",
        ),
        (
            json!({"variables": [{"field": "soil.cohesion", "from": 1, "to": 2, "points": 1}]}),
            "sensitivity.variables[0].points",
        ),
        (
            json!({"variables": [{"field": "soil.cohesion", "from": 1, "to": 2, "points": 102}]}),
            "sensitivity.variables[0].points",
        ),
        (
            json!({"variables": [{"field": "circle.nothing", "from": 1, "to": 2}]}),
            "sensitivity.variables[0].field",
        ),
        (json!({"variables": []}), "sensitivity.variables"),
    ];
    for (study, field) in sensitivity_cases {
        let mut body = common::spencer_example();
        body["sensitivity"] = study;
        let (status, content_type, problem) = server.post("/slope/spencer", &body).await;
        assert_problem(status, &content_type, &problem, 422, field);
    }
}

#[tokio::test]
async fn a_study_over_its_time_limit_is_refused_naming_its_samples() {
    let server = Server::start_with(thrustline::Settings {
        solve_timeout: std::time::Duration::from_millis(300),
        ..thrustline::Settings::default()
    })
    .await;
    // One circle is a millisecond; 100,000 samples of it are seconds.
    let mut body = undrained(30.0, 18.0);
    body["probabilistic"] = json!({"samples": 100_000,
        "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 1, "min": 1}]});
    let started = std::time::Instant::now();
    let (status, content_type, problem) = server.post("/slope/spencer", &body).await;
    assert_problem(
        status,
        &content_type,
        &problem,
        422,
        "probabilistic.samples",
    );
    assert!(started.elapsed().as_secs_f64() < 5.0);
}

/// The NDJSON lines of a streamed answer.
async fn lines(server: &Server, path: &str, accept: &str, body: &Value) -> Vec<Value> {
    let response = server
        .client
        .post(format!("{}{path}", server.base))
        .header("accept", accept)
        .json(body)
        .send()
        .await
        .unwrap();
    assert_eq!(response.status(), 200);
    assert_eq!(Server::content_type(&response), "application/x-ndjson");
    let text = response.text().await.unwrap();
    text.lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

#[tokio::test]
async fn a_streamed_study_reports_progress_then_the_answer() {
    let server = Server::start().await;
    let mut body = json!({"slope": {"height": 10, "length": 20}, "search": {}, "slices": 40,
        "soil": {"unit_weight": 19, "cohesion": 5, "friction_angle_deg": 22}, "include": []});
    body["probabilistic"] = json!({"samples": 150, "surface": "search", "seed": 8,
        "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 1, "min": 0.5}]});
    let plain = answer(&server, &body).await;
    for (path, accept) in [
        ("/slope/spencer/stream", "*/*"),
        (
            "/slope/spencer",
            "application/json;q=0.5, application/x-ndjson",
        ),
    ] {
        let got = lines(&server, path, accept, &body).await;
        let (last, progress) = got.split_last().unwrap();
        assert!(!progress.is_empty(), "{path}: no progress line");
        let mut before = 0;
        for p in progress {
            let (done, of) = (
                p["progress"]["done"].as_u64().unwrap(),
                p["progress"]["of"].as_u64().unwrap(),
            );
            assert_eq!(of, 150);
            assert!(done >= before && done <= of, "{p}");
            before = done;
        }
        let strip = |v: &Value| {
            let mut v = v["probabilistic"].clone();
            v.as_object_mut().unwrap().remove("time_ms");
            v
        };
        assert_eq!(strip(last), strip(&plain), "{path}");
        assert_eq!(last["factor_of_safety"], plain["factor_of_safety"]);
    }
    // A request the route refuses is its 422, not a line of a stream.
    let mut bad = body.clone();
    bad["probabilistic"]["samples"] = json!(0);
    for path in ["/slope/spencer/stream", "/slope/spencer"] {
        let response = server
            .client
            .post(format!("{}{path}", server.base))
            .header("accept", "application/x-ndjson")
            .json(&bad)
            .send()
            .await
            .unwrap();
        assert_eq!(response.status(), 422, "{path}");
        assert_eq!(Server::content_type(&response), "application/problem+json");
    }
    // A study stopped at the time limit: its problem is the last line.
    let server = Server::start_with(thrustline::Settings {
        solve_timeout: std::time::Duration::from_millis(300),
        ..thrustline::Settings::default()
    })
    .await;
    body = undrained(30.0, 18.0);
    body["probabilistic"] = json!({"samples": 100_000,
        "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 1, "min": 1}]});
    let got = lines(
        &server,
        "/slope/spencer/stream",
        "application/x-ndjson",
        &body,
    )
    .await;
    let last = got.last().unwrap();
    assert_eq!(last["status"], 422, "{last}");
    assert_eq!(last["field"], "probabilistic.samples");
    assert!(last["instance"].is_string(), "{last}");
}

#[tokio::test]
async fn a_client_that_goes_away_cancels_its_study() {
    let server = Server::start().await;
    let mut body = json!({"slope": {"height": 10, "length": 20}, "search": {}, "slices": 60,
        "soil": {"unit_weight": 19, "cohesion": 5, "friction_angle_deg": 22}, "include": []});
    // Tens of seconds of searches.
    body["probabilistic"] = json!({"samples": 100_000, "surface": "search",
        "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 1, "min": 0.5}]});
    let mut response = server
        .client
        .post(format!("{}/slope/spencer/stream", server.base))
        .json(&body)
        .send()
        .await
        .unwrap();
    let mut read = Vec::new();
    while read.iter().filter(|&&b| b == b'\n').count() < 2 {
        read.extend_from_slice(&response.chunk().await.unwrap().unwrap());
    }
    assert_eq!(server.solves_running().await, 1);
    drop(response);
    let mut left = u64::MAX;
    for _ in 0..100 {
        left = server.solves_running().await;
        if left == 0 {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    assert_eq!(left, 0, "the study kept running after the client left");
}

#[tokio::test]
async fn samples_of_a_request_with_other_methods_are_analysed() {
    // The methods and Morgenstern–Price's inter-slice function stay in each sample (it is
    // validated as the request is, then runs Spencer's method alone): none is refused.
    let server = Server::start().await;
    let body = json!({"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
            "layers": [{"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]},
        "circle": {"centre": [120, 90], "radius": 80}, "slices": 50, "include": [], "curves": true,
        "methods": ["morgenstern_price"], "interslice_function": [[0, 0], [0.5, 1], [1, 0]],
        "probabilistic": {"samples": 50, "variables": [{"field": "section.layers[0].soil.cohesion",
            "distribution": "uniform", "min": 599.999999, "max": 600.000001}]}});
    let a = answer(&server, &body).await;
    let p = &a["probabilistic"];
    assert_eq!(
        (p["refused"].as_u64(), p["unsolved"].as_u64()),
        (Some(0), Some(0)),
        "{p}"
    );
    let f0 = num(&a, "factor_of_safety");
    assert!((num(p, "mean") - f0).abs() < 1e-6 * f0, "{p} vs {f0}");
}
