//! Crushing of the joints (model §5.2): the rectangular stress block, linearised.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use thrustline_solver::arch::*;
use thrustline_solver::reference::semicircle;

fn lambda(strength: Option<f64>, planes: usize, formulation: Formulation) -> f64 {
    let arch = semicircle(100, 10.0, 1.5).assembly();
    let load = LiveLoad {
        block: 25,
        point: arch.blocks[25].centroid,
        fx: 0.0,
        fy: -1.0,
        moment: 0.0,
    };
    let mut p = ArchProblem::new(arch, 1.0, InterfaceLimits::heyman(), None, vec![load]).unwrap();
    if let Some(strength) = strength {
        p = p
            .with_crushing(Crushing {
                strength,
                planes,
                cuts: Vec::new(),
            })
            .unwrap();
    }
    let settings = LimitSettings {
        formulation,
        ..LimitSettings::default()
    };
    let s = solve_live_load(&p, &settings).unwrap();
    assert_eq!(s.status, LimitStatus::Solved);
    s.load_factor.unwrap()
}

#[test]
fn infinite_strength_is_heyman_and_finite_strength_lowers_lambda_monotonically() {
    let heyman = lambda(None, 16, Formulation::Chain);
    assert!((heyman - 22.996889652022617).abs() < 1e-6, "{heyman}");
    let strong = lambda(Some(1e12), 16, Formulation::Chain);
    assert!(
        (strong - heyman).abs() < 1e-7 * heyman,
        "{strong} vs {heyman}"
    );
    // The thrust is of the order of the weight (~47): σ_c·t from 1500 down to 75 bites harder
    // (at σ_c = 20 the dead load itself crushes the arch).
    let mut previous = strong;
    for strength in [1000.0, 300.0, 120.0, 100.0, 80.0, 50.0] {
        let l = lambda(Some(strength), 16, Formulation::Chain);
        assert!(
            l <= previous * (1.0 + 1e-9),
            "σ_c = {strength}: {l} > {previous}"
        );
        previous = l;
    }
    assert!(
        previous < 0.2 * heyman,
        "crushing at σ_c = 50 should bite: {previous}"
    );
}

#[test]
fn both_formulations_agree_and_the_planes_converge() {
    let chain = lambda(Some(50.0), 16, Formulation::Chain);
    let assembly = lambda(Some(50.0), 16, Formulation::Assembly);
    assert!(
        (chain - assembly).abs() < 1e-7 * chain,
        "{chain} vs {assembly}"
    );
    // Cutting planes at each joint's own N take any start to the exact curve: 2, 16 and 64
    // initial planes give the same λ to 1e-6 (fixed tangents alone: 5.13 with 8, 3.91 with 256).
    for planes in [2, 64] {
        let other = lambda(Some(50.0), planes, Formulation::Chain);
        assert!(
            (other - chain).abs() < 1e-6 * chain,
            "{planes} planes: {other} vs {chain}"
        );
    }
    for strength in [80.0, 100.0, 120.0] {
        let (a, b) = (
            lambda(Some(strength), 2, Formulation::Chain),
            lambda(Some(strength), 32, Formulation::Chain),
        );
        assert!((a - b).abs() < 1e-6 * a, "σ_c = {strength}: {a} vs {b}");
    }
}

/// λ₀ of the semicircle R = 10, D = 1.5 (100 voussoirs), dead load only, at strength σ_c.
fn dead_load_factor(thickness: f64, strength: f64) -> f64 {
    let arch = semicircle(100, 10.0, thickness).assembly();
    let p = ArchProblem::new(arch, 1.0, InterfaceLimits::heyman(), None, Vec::new())
        .unwrap()
        .with_crushing(Crushing {
            strength,
            planes: 16,
            cuts: Vec::new(),
        })
        .unwrap();
    let s = solve_dead_load(&p, &LimitSettings::default());
    assert_eq!(s.status, LimitStatus::Solved);
    s.load_factor.unwrap()
}

#[test]
fn with_crushing_the_dead_load_factor_is_the_share_of_the_weight_carried() {
    // model §6.5. Equilibrium is linear in the loads and the crushing curve
    // |M| ≤ N·(t − N/σ_c)/2 is homogeneous in (N, M, σ_c): λ·w is carried at strength σ_c exactly
    // when w is carried at σ_c/λ. So below full weight λ₀ = σ_c/σ*, linear in σ_c, with σ* the
    // least strength that carries the whole weight — checked from both sides. (This used to
    // answer 0: the crushing rows were taken for a cone.)
    let at_20 = dead_load_factor(1.5, 20.0);
    assert!(at_20 > 0.05 && at_20 < 1.0, "{at_20}");
    let at_10 = dead_load_factor(1.5, 10.0);
    assert!((at_10 / at_20 - 0.5).abs() < 1e-6, "{at_10} vs {at_20}");
    let least = 20.0 / at_20;
    assert_eq!(dead_load_factor(1.5, least * 1.001), 1.0);
    let below = dead_load_factor(1.5, least * 0.999);
    assert!((below - 0.999).abs() < 1e-5, "{below}");
    // Too thin to stand as rigid blocks (D < 1.0748): nothing is carried, exactly.
    assert_eq!(dead_load_factor(1.0, 20.0), 0.0);
}
