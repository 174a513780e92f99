//! Minimum thickness of circular arches against Milankovitch (model §1.4) and against an
//! independent hand computation of the governing mechanism's virtual work.
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::f64::consts::PI;

use thrustline_solver::arch::*;
use thrustline_solver::reference::circular_arch;

fn minimum(arch: &CircularArch, friction: Option<f64>) -> MinimumThickness {
    solve_minimum_thickness(
        arch,
        1.0,
        InterfaceLimits::heyman(),
        friction,
        &MinimumThicknessSettings::default(),
    )
    .unwrap()
}

fn found(m: &MinimumThickness) -> (f64, f64, Mechanism) {
    match &m.outcome {
        Ok(MinimumThicknessOutcome::Found {
            thickness,
            thickness_below,
            mechanism,
        }) => (*thickness, *thickness_below, mechanism.clone().unwrap()),
        other => panic!("expected a minimum, got {other:?}"),
    }
}

#[test]
fn milankovitch_minimum_thickness_1800_voussoirs() {
    // model §1.4: the thesis brackets d/R between 0.10747 and 0.10748 at N = 1800 curved
    // voussoirs; the exact limit is 0.10748 (N → ∞: 0.1075) with rupture at 54.5° from the crown.
    let a = circular_arch(1800, 10.0, 1.0, 0.0, VoussoirShape::Curved);
    let m = minimum(&a, None);
    let (thickness, below, mechanism) = found(&m);
    let ratio = thickness / 10.0;
    assert!((0.10747..=0.10748).contains(&ratio), "d/R = {ratio}");
    // Tolerance 1e-6·R: the bracket is that narrow.
    assert!(thickness - below <= 1e-5 && below < thickness);
    assert!((ratio - 0.1075).abs() < 5e-5);
    let rupture = rupture_angle_deg(&a, &mechanism).unwrap();
    assert!((rupture - 54.5).abs() < 0.05, "rupture angle {rupture}");
    assert!(m.evaluations < 20, "{} evaluations", m.evaluations);
}

/// Hand computation for N = 4 curved voussoirs of a semicircle (R = 10): the symmetric
/// five-hinge mechanism has hinges at the extrados of the springing (A), the intrados at 45° (B)
/// and the extrados of the crown (C). Block 1 turns about A; block 2 about its instantaneous
/// centre, the intersection of line AB with the horizontal through C (C moves vertically by
/// symmetry). The weight does no work at the limit thickness: Σ area·ω·(x_G − x_centre) = 0.
fn four_voussoir_limit_by_hand() -> f64 {
    let r = 10.0f64;
    let work = |d: f64| {
        let (ri, re) = (r - d / 2.0, r + d / 2.0);
        let a = (re, 0.0);
        let b = (ri * (PI / 4.0).cos(), ri * (PI / 4.0).sin());
        let t = (re - a.1) / (b.1 - a.1);
        let centre = (a.0 + t * (b.0 - a.0), re);
        let rho = 2.0 / 3.0 * (re.powi(3) - ri.powi(3)) / (re * re - ri * ri) * (PI / 8.0).sin()
            / (PI / 8.0);
        let g0 = rho * (PI / 8.0).cos();
        let g1 = rho * (3.0 * PI / 8.0).cos();
        let w1 = (b.0 - a.0) / (b.0 - centre.0);
        (g0 - a.0) + w1 * (g1 - centre.0)
    };
    let (mut lo, mut hi) = (0.5, 2.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if work(mid) * work(lo) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

#[test]
fn four_voussoirs_match_the_hand_computed_mechanism() {
    let by_hand = four_voussoir_limit_by_hand(); // 1.0086149…
    let (thickness, below, mechanism) = found(&minimum(
        &circular_arch(4, 10.0, 1.0, 0.0, VoussoirShape::Curved),
        None,
    ));
    // The answer brackets the hand value within the tolerance 1e-6·R (1e-9 for rounding).
    assert!(
        below - 1e-9 <= by_hand && by_hand <= thickness + 1e-9,
        "{below} … {thickness} vs {by_hand}"
    );
    let hinges: Vec<usize> = mechanism.hinges.iter().map(|h| h.interface).collect();
    assert_eq!(hinges, [0, 1, 2, 3, 4]);
}

#[test]
fn three_or_fewer_voussoirs_have_no_finite_minimum() {
    // model §1.4: N = 1, 2, 3 stand however thin under symmetric dead load.
    for n in 1..=3 {
        assert_eq!(
            minimum(
                &circular_arch(n, 10.0, 1.0, 0.0, VoussoirShape::Curved),
                None
            )
            .outcome,
            Ok(MinimumThicknessOutcome::StandsHoweverThin),
            "N = {n}"
        );
    }
}

#[test]
fn friction_too_low_for_any_thickness() {
    // Springing joints of a semicircle are horizontal: μ = 0.2 is below the thrust ratio there
    // whatever the thickness.
    assert_eq!(
        minimum(
            &circular_arch(50, 10.0, 1.0, 0.0, VoussoirShape::Curved),
            Some(0.2)
        )
        .outcome,
        Ok(MinimumThicknessOutcome::NeverStands)
    );
    // A rough joint (μ = 0.5) does not change the hinging limit of 50 voussoirs.
    let (rough, _, _) = found(&minimum(
        &circular_arch(50, 10.0, 1.0, 0.0, VoussoirShape::Curved),
        Some(0.5),
    ));
    let (smooth, _, _) = found(&minimum(
        &circular_arch(50, 10.0, 1.0, 0.0, VoussoirShape::Curved),
        None,
    ));
    assert!((rough - smooth).abs() <= 1e-5, "{rough} vs {smooth}");
}

#[test]
fn flat_segmental_arch_needs_very_little_thickness() {
    // Issue 4: a segmental arch of half-embrace 30° (base angles 60°) needs about 0.0015·R.
    let (thickness, _, _) = found(&minimum(
        &circular_arch(200, 10.0, 1.0, 60.0, VoussoirShape::Curved),
        None,
    ));
    let ratio = thickness / 10.0;
    assert!((0.0014..0.0016).contains(&ratio), "d/R = {ratio}");
}

#[test]
fn horseshoe_arch_needs_more_than_the_semicircle() {
    let (horseshoe, _, mechanism) = found(&minimum(
        &circular_arch(100, 10.0, 1.0, -30.0, VoussoirShape::Curved),
        None,
    ));
    let (semicircle, _, _) = found(&minimum(
        &circular_arch(100, 10.0, 1.0, 0.0, VoussoirShape::Curved),
        None,
    ));
    assert!(horseshoe > 2.0 * semicircle, "{horseshoe} vs {semicircle}");
    // Still a symmetric five-hinge mechanism with hinges at both springings.
    assert_eq!(mechanism.hinges.len(), 5);
    assert_eq!(mechanism.hinges[0].interface, 0);
    assert_eq!(mechanism.hinges[4].interface, 100);
}

#[test]
fn a_search_past_its_time_limit_stops_and_says_so() {
    // The budget is the search's one limit: spent, no programme runs and the outcome is its stop.
    let settings = MinimumThicknessSettings {
        limit: thrustline_solver::arch::LimitSettings {
            budget: thrustline_solver::budget::Budget::with_time_limit(std::time::Duration::ZERO),
            ..Default::default()
        },
        ..MinimumThicknessSettings::default()
    };
    let m = solve_minimum_thickness(
        &circular_arch(100, 10.0, 1.0, 0.0, VoussoirShape::Curved),
        1.0,
        InterfaceLimits::heyman(),
        None,
        &settings,
    )
    .unwrap();
    assert_eq!(m.outcome, Err(thrustline_solver::budget::Stop::TimeLimit));
    assert_eq!(m.evaluations, 0);
}
