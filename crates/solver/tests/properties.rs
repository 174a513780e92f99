//! Invariants that hold for all inputs, checked on random ones (proptest).
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use proptest::prelude::*;
use thrustline_solver::arch::*;
use thrustline_solver::slope::*;

fn spencer_f(
    scale: f64,
    ratio: f64,
    c_ratio: f64,
    phi: f64,
    ru: f64,
    x: f64,
    y: f64,
) -> Option<f64> {
    let gamma = 10.0;
    let h = 10.0 * scale;
    let p = SlopeProblem::new(
        Embankment::new(h, h * ratio).ok()?,
        SlipCircle {
            x: x * h,
            y: y * h,
            lower_end_factor: 0.0,
        },
        NonZeroUsize::new(40).unwrap(),
        Soil::new(gamma, c_ratio * gamma * h, phi, ru).ok()?,
        Seismic::default(),
        Vec::new(),
    )
    .ok()?;
    solve_spencer(&p.model(), &SpencerSettings::default()).factor_of_safety
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// F depends on the geometry only through its shape and on c' only through c'/(γH):
    /// scaling every length by s (and c' with H) leaves F unchanged (1e-8 relative: the
    /// Newton tolerance and rounding across 12 orders of magnitude).
    #[test]
    fn spencer_factor_is_scale_invariant(
        scale in prop::sample::select(vec![1e-6, 1e-3, 1e3, 1e6]),
        ratio in 0.5f64..4.0,
        c_ratio in 0.01f64..0.2,
        phi in 0.0f64..45.0,
        ru in 0.0f64..0.6,
        x in 0.0f64..1.5,
        y in 1.0f64..3.0,
    ) {
        let base = spencer_f(1.0, ratio, c_ratio, phi, ru, x, y);
        let scaled = spencer_f(scale, ratio, c_ratio, phi, ru, x, y);
        match (base, scaled) {
            (Some(a), Some(b)) => prop_assert!((a - b).abs() <= 1e-8 * a, "{} vs {}", a, b),
            (None, None) => {}
            (a, b) => prop_assert!(false, "one solved, the other not: {:?} {:?}", a, b),
        }
    }

    /// Mirror symmetry: swapping the base angles mirrors the arch, which changes nothing in
    /// the dead-load margin (1e-9 of the weight: interior-point tolerance), and the chain and
    /// assembly formulations agree on it.
    #[test]
    fn dead_load_margin_is_mirror_symmetric_and_formulation_independent(
        n in 4usize..40,
        thickness in 0.3f64..2.5,
        left in -30.0f64..60.0,
        right in -30.0f64..60.0,
    ) {
        let margin = |b: f64, c: f64, formulation: Formulation| {
            let arch = CircularArch::new(10.0, thickness, NonZeroUsize::new(n).unwrap(), b, c, VoussoirShape::Curved).unwrap();
            let p = ArchProblem::new(arch.assembly(), 1.0, InterfaceLimits::heyman(), None, vec![]).unwrap();
            let settings = LimitSettings { formulation, ..LimitSettings::default() };
            solve_dead_load(&p, &settings).dead_load_margin.unwrap()
        };
        let a = margin(left, right, Formulation::Chain);
        let mirrored = margin(right, left, Formulation::Chain);
        let general = margin(left, right, Formulation::Assembly);
        prop_assert!((a - mirrored).abs() < 1e-9, "{} vs mirrored {}", a, mirrored);
        prop_assert!((a - general).abs() < 1e-9, "{} vs assembly {}", a, general);
    }
}
