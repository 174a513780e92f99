//! The methods side by side and polyline surfaces on sections (model §4.2–4.3), against
//! independent computations.

use std::num::NonZeroUsize;

use super::tests::{infinite_slope, line, one_soil, solve};
use super::*;
use crate::slope::spencer::methods::{
    bishop, janbu, morgenstern_price, ordinary, InterSliceFunction,
};
use crate::slope::spencer::Seismic;
use crate::slope::spencer::{solve_spencer, SpencerSettings};

#[test]
fn fredlund_krahn_case_1_by_every_method() {
    // Independent integration of the same circle (200,000 strips, weights at the strip
    // middles; Bishop's and Janbu's textbook fixed points): ordinary 1.92768, Bishop 2.07563,
    // Janbu simplified 1.87702. Published (their
    // slices): ordinary 1.928, Bishop 2.080, Spencer 2.073, Morgenstern–Price (half-sine) 2.076.
    let parts = one_soil(
        &[(0.0, 60.0), (60.0, 60.0), (140.0, 20.0), (180.0, 20.0)],
        120.0,
        600.0,
        20.0,
    );
    let circle = SlipShape::Circle {
        centre: (120.0, 90.0),
        radius: 80.0,
    };
    let (p, s) = solve(parts, circle, 1000);
    let model = p.model();
    let close = |name: &str, got: Option<f64>, want: f64, tolerance: f64| {
        let got = got.unwrap_or(f64::NAN);
        assert!((got - want).abs() < tolerance, "{name}: {got} vs {want}");
    };
    close("ordinary", ordinary(model).factor_of_safety, 1.92768, 1e-4);
    close("Bishop", bishop(model).factor_of_safety, 2.07563, 1e-4);
    close("Janbu", janbu(model).factor_of_safety, 1.87702, 1e-4);
    let spencer = (s.factor_of_safety.unwrap(), s.theta_rad.unwrap().tan());
    let mp = morgenstern_price(model, &InterSliceFunction::HalfSine, spencer);
    // An independent GLE iteration (Fredlund & Krahn's own scheme: X = λ·f·E by fixed point,
    // F_f and F_m crossed in λ; 4000 strips) gives F = 2.07140, λ = 0.32321 for the half-sine and
    // F = 2.07185, λ = 0.25762 for f ≡ 1; the published 2.076 is within their slicing.
    close("Morgenstern–Price", mp.factor_of_safety, 2.07140, 1e-4);
    close("Morgenstern–Price λ", mp.lambda, 0.32321, 1e-3);
    close(
        "Morgenstern–Price (published)",
        mp.factor_of_safety,
        2.076,
        5e-3,
    );
    close("Spencer λ by GLE", Some(spencer.1), 0.25762, 1e-4);
    // f ≡ 1 is Spencer: the same F and λ = tan θ to 1e-9.
    let constant = morgenstern_price(model, &InterSliceFunction::Constant, (spencer.0 * 1.1, 0.0));
    close("M–P constant F", constant.factor_of_safety, spencer.0, 1e-9);
    close("M–P constant λ", constant.lambda, spencer.1, 1e-9);
}

#[test]
fn a_polyline_on_a_circle_gives_the_circle() {
    // 2001 points on Fredlund & Krahn's circle (from just outside the ground at both ends):
    // the polyline's F tends to the circle's as the chords shorten (1e-6 at 1000 slices).
    let ground = [(0.0, 60.0), (60.0, 60.0), (140.0, 20.0), (180.0, 20.0)];
    let parts = one_soil(&ground, 120.0, 600.0, 20.0);
    let (centre, radius) = ((120.0, 90.0), 80.0);
    let (_, circle) = solve(parts.clone(), SlipShape::Circle { centre, radius }, 1000);
    let (a, b) = (45.0, 159.5);
    let points: Vec<(f64, f64)> = (0..=2000)
        .map(|k| {
            let x = a + (b - a) * f64::from(k) / 2000.0;
            (
                x,
                centre.1 - (radius * radius - (x - centre.0).powi(2)).sqrt(),
            )
        })
        .collect();
    let polyline = SlipShape::Polyline(line(&points));
    let (_, poly) = solve(parts, polyline, 1000);
    let (fc, fp) = (
        circle.factor_of_safety.unwrap(),
        poly.factor_of_safety.unwrap(),
    );
    assert!((fc - fp).abs() < 1e-5 * fc, "circle {fc}, polyline {fp}");
}

#[test]
fn every_method_on_a_dry_cohesionless_infinite_slope() {
    // c' = 0, dry: on a surface parallel to the face every slice has N = W cos β and the
    // inter-slice forces cancel, so every method gives tan φ'/tan β (to the ends' z/L).
    let (beta, phi) = (25.0f64, 33.0f64);
    let (ground, surface) = infinite_slope(beta, 2.0, 2000.0);
    let expected = phi.to_radians().tan() / beta.to_radians().tan();
    let problem = SectionProblem::new(
        Section::new(one_soil(&ground, 19.0, 0.0, phi)).unwrap(),
        SlipShape::Polyline(surface),
        NonZeroUsize::new(400).unwrap(),
        Seismic::default(),
        Some((1000.0, 5000.0)),
    )
    .unwrap();
    let model = problem.model();
    let s = solve_spencer(model, &SpencerSettings::default());
    let spencer = (s.factor_of_safety.unwrap(), s.theta_rad.unwrap().tan());
    let mp = morgenstern_price(model, &InterSliceFunction::HalfSine, spencer);
    for (name, f) in [
        ("Spencer", Some(spencer.0)),
        ("Morgenstern–Price", mp.factor_of_safety),
        ("Bishop", bishop(model).factor_of_safety),
        ("Janbu", janbu(model).factor_of_safety),
        ("ordinary", ordinary(model).factor_of_safety),
    ] {
        let f = f.unwrap_or(f64::NAN);
        assert!(
            (f - expected).abs() < 5e-3 * expected,
            "{name}: {f} vs {expected}"
        );
    }
}
