//! Numerical stability at the extremes of every input (issue 6): each either gives the right
//! answer or an honest status. The "Extremes" list of docs/accuracy.md names these tests.
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::arch::*;
use thrustline_solver::reference::{semicircle, spencer_1967};
use thrustline_solver::slope::*;

fn dead_factor(arch: &CircularArch, unit_weight: f64, friction: Option<f64>) -> f64 {
    let p = ArchProblem::new(
        arch.assembly(),
        unit_weight,
        InterfaceLimits::heyman(),
        friction,
        vec![],
    )
    .unwrap();
    let s = solve_dead_load(&p, &LimitSettings::default());
    assert_eq!(s.status, LimitStatus::Solved);
    s.load_factor.unwrap()
}

#[test]
fn voussoir_counts_from_1_to_10000() {
    // A thick arch (D = 0.5R) stands for every N; a thin one (D = 0.05R) stands only for
    // N ≤ 3 (model §1.4).
    for n in [1, 2, 3, 4, 10, 100, 1000, 10_000] {
        assert_eq!(
            dead_factor(&semicircle(n, 10.0, 5.0), 1.0, None),
            1.0,
            "thick, N = {n}"
        );
        let thin = dead_factor(&semicircle(n, 10.0, 0.5), 1.0, None);
        assert_eq!(thin, if n <= 3 { 1.0 } else { 0.0 }, "thin, N = {n}");
    }
}

#[test]
fn thickness_within_a_millionth_of_the_limit_on_both_sides() {
    // The limit to 1e-9·R, then 1e-6·R either side of the bracket: decided correctly.
    let arch = semicircle(1800, 10.0, 1.0);
    let settings = MinimumThicknessSettings {
        tolerance: 1e-9,
        ..MinimumThicknessSettings::default()
    };
    let m =
        solve_minimum_thickness(&arch, 1.0, InterfaceLimits::heyman(), None, &settings).unwrap();
    let Ok(MinimumThicknessOutcome::Found {
        thickness,
        thickness_below,
        ..
    }) = m.outcome
    else {
        panic!("{:?}", m.outcome)
    };
    assert!(thickness - thickness_below <= 1e-8);
    assert_eq!(
        dead_factor(&arch.with_thickness(thickness + 1e-5).unwrap(), 1.0, None),
        1.0
    );
    assert_eq!(
        dead_factor(
            &arch.with_thickness(thickness_below - 1e-5).unwrap(),
            1.0,
            None
        ),
        0.0
    );
}

#[test]
fn unit_scales_from_a_millionth_to_a_million() {
    // λ of a quarter-span point load is dimensionless: lengths × s, unit weight × g and the
    // load × g·s² leave it unchanged (1e-7 relative: interior-point tolerance).
    let live = |s: f64, g: f64| {
        let arch = semicircle(60, 10.0 * s, 1.5 * s).assembly();
        let load = LiveLoad {
            block: 15,
            point: arch.blocks[15].centroid,
            fx: 0.0,
            fy: -g * s * s,
            moment: 0.0,
        };
        let p = ArchProblem::new(arch, g, InterfaceLimits::heyman(), None, vec![load]).unwrap();
        solve_live_load(&p, &LimitSettings::default())
            .unwrap()
            .load_factor
            .unwrap()
    };
    let base = live(1.0, 1.0);
    for s in [1e-6, 1e-3, 1e3, 1e6] {
        for g in [1e-6, 1.0, 1e6] {
            let lambda = live(s, g);
            assert!(
                (lambda - base).abs() < 1e-7 * base,
                "s = {s}, γ = {g}: {lambda} vs {base}"
            );
        }
    }
}

#[test]
fn friction_zero_and_a_thousand() {
    // μ = 0: joints carry no shear and the semicircle's horizontal springing joints cannot
    // take its thrust; μ = 1000 changes nothing against no sliding at all.
    let arch = semicircle(20, 10.0, 3.0);
    assert_eq!(dead_factor(&arch, 1.0, Some(0.0)), 0.0);
    assert_eq!(
        dead_factor(&arch, 1.0, Some(1e3)),
        dead_factor(&arch, 1.0, None)
    );
}

fn spencer(n: usize, phi: f64, ru: f64) -> SpencerSolution {
    // Spencer's (1967) circle with other φ' and r_u.
    let p = SlopeProblem::new(
        spencer_1967::embankment(),
        spencer_1967::circle(),
        NonZeroUsize::new(n).unwrap(),
        Soil::new(10.0, 6.096, phi, ru).unwrap(),
        Seismic::default(),
        Vec::new(),
    )
    .unwrap();
    solve_spencer(&p.model(), &SpencerSettings::default())
}

#[test]
fn slices_from_1_to_5000() {
    // N = 1: no solution (a single slice cannot meet both equations) — said, not invented.
    let one = spencer(1, 40.0, 0.5);
    match one.status {
        SpencerStatus::Converged => assert!(one.residual.unwrap() < 1e-9),
        SpencerStatus::NoSolution | SpencerStatus::Unphysical => {
            assert!(one.factor_of_safety.is_none())
        }
        SpencerStatus::MomentOnly => panic!("moment-only answer with friction"),
    }
    // N = 2, 3: whatever comes is a solution of the equations.
    for n in [2, 3] {
        let s = spencer(n, 40.0, 0.5);
        if s.status == SpencerStatus::Converged {
            assert!(s.residual.unwrap() < 1e-9, "N = {n}");
        }
    }
    // N = 5000: the converged F = 1.0695224 (Spencer's example) to 1e-7.
    let f = spencer(5000, 40.0, 0.5).factor_of_safety.unwrap();
    assert!((f - 1.0695224).abs() < 1e-7, "{f}");
}

#[test]
fn friction_angle_zero_and_near_ninety_and_full_pore_pressure() {
    // φ' = 0: the moment equation alone fixes F (θ drops out for a circle); F > 0.
    let s = spencer(100, 0.0, 0.0);
    assert_eq!(s.status, SpencerStatus::Converged);
    let f0 = s.factor_of_safety.unwrap();
    assert!(f0 > 0.0 && f0 < 1.0, "{f0}");
    // φ' = 89.9°: tan φ' ≈ 573, F is large and finite, and the equations hold.
    let s = spencer(100, 89.9, 0.0);
    assert_eq!(s.status, SpencerStatus::Converged);
    assert!(s.factor_of_safety.unwrap() > 100.0 && s.residual.unwrap() < 1e-9);
    // r_u from 0 to 1: F decreases; at r_u = 1 it still solves or says why not. At r_u = 1
    // the pore force u·l = W/cos α exceeds W·cos α on every inclined base: N' < 0 there, and
    // with c'/(γH) = 0.02 the steep bases fall below their envelope's apex (model §2.2).
    let mut previous = f64::INFINITY;
    for ru in [0.0, 0.25, 0.5, 0.75, 1.0] {
        let s = spencer(100, 40.0, ru);
        if let Some(f) = s.factor_of_safety {
            assert!(f < previous, "r_u = {ru}: {f}");
            previous = f;
        } else {
            assert!(ru > 0.9, "r_u = {ru}: {:?}", s.status);
            assert!(
                matches!(
                    s.status,
                    SpencerStatus::NoSolution | SpencerStatus::Unphysical
                ),
                "{:?}",
                s.status
            );
        }
    }
}
