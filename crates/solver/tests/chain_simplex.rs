//! The chain programmes on the simplex method (issue 45) against Livesley's general assembly
//! formulation on the interior-point method, an independent programme: on random arches and
//! loads, the same λ (1e-7 relative) and dead-load margin (1e-8 of the weight) and the same
//! active constraints.
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use proptest::prelude::*;
use thrustline_solver::arch::*;

fn arch(n: usize, thickness: f64, left: f64, right: f64) -> Assembly {
    CircularArch::new(
        10.0,
        thickness,
        NonZeroUsize::new(n).unwrap(),
        left,
        right,
        VoussoirShape::Curved,
    )
    .unwrap()
    .assembly()
}

fn active(s: &LimitSolution) -> Vec<(usize, Resultant, Bound)> {
    let mut a: Vec<_> = s
        .mechanism
        .as_ref()
        .map(|m| {
            m.active
                .iter()
                .map(|a| (a.interface, a.resultant, a.bound))
                .collect()
        })
        .unwrap_or_default();
    a.sort_by_key(|x| format!("{x:?}"));
    a
}

fn solve(problem: &ArchProblem, formulation: Formulation) -> LimitSolution {
    let settings = LimitSettings {
        formulation,
        ..LimitSettings::default()
    };
    solve_live_load(problem, &settings).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn the_simplex_chain_answers_as_the_assembly_programme(
        n in 4usize..160,
        thickness in 0.9f64..3.0,
        left in -10.0f64..40.0,
        right in -10.0f64..40.0,
        at in 0.0f64..1.0,
        angle in -60.0f64..60.0,
        friction in prop::option::of(0.3f64..1.0),
    ) {
        let a = arch(n, thickness, left, right);
        let block = ((at * n as f64) as usize).min(n - 1);
        let (s, c) = angle.to_radians().sin_cos();
        let load = LiveLoad {
            block,
            point: a.blocks[block].centroid,
            fx: s,
            fy: -c,
            moment: 0.0,
        };
        let problem =
            ArchProblem::new(a, 1.0, InterfaceLimits::heyman(), friction, vec![load]).unwrap();
        let chain = solve(&problem, Formulation::Chain);
        let assembly = solve(&problem, Formulation::Assembly);
        prop_assert_eq!(chain.status, assembly.status);
        match (chain.load_factor, assembly.load_factor) {
            // 1e-7: a load at a springing reaches λ ~ 4e4, where the interior-point method's
            // 1e-10 on the scaled programme leaves 2e-8 of it (the simplex vertex is exact).
            (Some(x), Some(y)) => prop_assert!((x - y).abs() <= 1e-7 * y, "λ {} against {}", x, y),
            (x, y) => prop_assert_eq!(x, y),
        }
        if chain.load_factor.is_some() {
            prop_assert_eq!(active(&chain), active(&assembly));
        }
    }

    #[test]
    fn the_simplex_dead_load_answers_as_the_assembly_programme(
        n in 4usize..160,
        thickness in 0.6f64..1.6,
        left in -10.0f64..30.0,
        right in -10.0f64..30.0,
        friction in prop::option::of(0.3f64..1.0),
    ) {
        let a = arch(n, thickness, left, right);
        let problem =
            ArchProblem::new(a, 1.0, InterfaceLimits::heyman(), friction, vec![]).unwrap();
        let run = |formulation| {
            let settings = LimitSettings { formulation, ..LimitSettings::default() };
            solve_dead_load(&problem, &settings)
        };
        let (chain, assembly) = (run(Formulation::Chain), run(Formulation::Assembly));
        prop_assert_eq!(chain.status, assembly.status);
        prop_assert_eq!(chain.dead_load_carried, assembly.dead_load_carried);
        let (x, y) = (chain.dead_load_margin.unwrap(), assembly.dead_load_margin.unwrap());
        prop_assert!((x - y).abs() <= 1e-8, "margin {} against {}", x, y);
        if chain.dead_load_carried == Some(false) {
            prop_assert_eq!(active(&chain), active(&assembly));
        }
    }
}
