//! Limit analysis of arches, grouped by problem class, against the literature (model §1.4) and
//! against independent computations written here: block equilibrium summed by hand from the
//! returned resultants, and the virtual-work equation of the returned mechanism.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use thrustline_solver::arch::*;
use thrustline_solver::reference::{circular_arch, milankovitch, semicircle};

fn heyman(assembly: Assembly, loads: Vec<LiveLoad>) -> ArchProblem {
    ArchProblem::new(assembly, 1.0, InterfaceLimits::heyman(), None, loads).unwrap()
}

fn dead(problem: &ArchProblem) -> LimitSolution {
    let s = solve_dead_load(problem, &LimitSettings::default());
    assert_eq!(s.status, LimitStatus::Solved);
    s
}

fn live(problem: &ArchProblem) -> LimitSolution {
    let s = solve_live_load(problem, &LimitSettings::default()).unwrap();
    assert_eq!(s.status, LimitStatus::Solved);
    s
}

/// A downward unit point load at the centroid of block `b`.
fn point_load(assembly: &Assembly, b: usize, fy: f64) -> Vec<LiveLoad> {
    vec![LiveLoad {
        block: b,
        point: assembly.blocks[b].centroid,
        fx: 0.0,
        fy,
        moment: 0.0,
    }]
}

/// Independent equilibrium check: for every block, sum the interface forces (q at the extrados
/// end and s at the intrados end along the joint normal, t along the joint), the weight and the
/// loads, and their moments about the origin. Returns the largest residual relative to the
/// total weight (forces) and weight × span (moments).
fn equilibrium_residual(
    problem: &ArchProblem,
    r: &[[f64; 3]],
    dead_factor: f64,
    loads: &[LiveLoad],
    live_factor: f64,
) -> f64 {
    let a = problem.assembly();
    let n = a.blocks.len();
    let mut sums = vec![[0.0f64; 3]; n];
    let cross = |p: (f64, f64), f: (f64, f64)| p.0 * f.1 - p.1 * f.0;
    for (k, (i, &[q, s, t])) in a.interfaces.iter().zip(r).enumerate() {
        // The normal of joint k, pointing from block k−1 into block k, by hand.
        let tangent = (i.extrados.0 - i.intrados.0, i.extrados.1 - i.intrados.1);
        let len = tangent.0.hypot(tangent.1);
        let tau = (tangent.0 / len, tangent.1 / len);
        let mut nu = (-tau.1, tau.0);
        let into = if k < n {
            a.blocks[k].centroid
        } else {
            a.blocks[n - 1].centroid
        };
        let m = i.middle();
        let side = nu.0 * (into.0 - m.0) + nu.1 * (into.1 - m.1);
        if (k < n && side < 0.0) || (k == n && side > 0.0) {
            nu = (-nu.0, -nu.1);
        }
        let forces = [
            (i.extrados, (q * nu.0, q * nu.1)),
            (i.intrados, (s * nu.0, s * nu.1)),
            (i.intrados, (t * tau.0, t * tau.1)),
        ];
        for (block, sign) in [(k, 1.0), (k.wrapping_sub(1), -1.0)] {
            if block < n {
                for (p, f) in forces {
                    sums[block][0] += sign * f.0;
                    sums[block][1] += sign * f.1;
                    sums[block][2] += sign * cross(p, f);
                }
            }
        }
    }
    let gamma = problem.unit_weight();
    for (b, block) in a.blocks.iter().enumerate() {
        let w = dead_factor * gamma * block.area;
        sums[b][1] -= w;
        sums[b][2] += cross(block.centroid, (0.0, -w));
    }
    for l in loads {
        let f = (live_factor * l.fx, live_factor * l.fy);
        sums[l.block][0] += f.0;
        sums[l.block][1] += f.1;
        sums[l.block][2] += cross(l.point, f) + live_factor * l.moment;
    }
    let weight = gamma * a.total_area();
    let span = a.length_scale();
    sums.iter()
        .map(|s| {
            (s[0].abs() / weight)
                .max(s[1].abs() / weight)
                .max(s[2].abs() / (weight * span))
        })
        .fold(0.0, f64::max)
}

mod dead_load {
    use super::*;

    #[test]
    fn milankovitch_1800_voussoirs_thickness_1_0748_stands() {
        // model §1.4: N = 1800 curved voussoirs, R = 10, D = 1.0748: λ₀ = 1, no active limits.
        let arch = semicircle(
            milankovitch::VOUSSOIRS,
            milankovitch::RADIUS,
            milankovitch::THICKNESS_STANDS,
        );
        let p = heyman(arch.assembly(), vec![]);
        let s = dead(&p);
        assert_eq!(s.load_factor, Some(1.0));
        assert_eq!(s.dead_load_carried, Some(true));
        assert!(s.mechanism.is_none());
        // The returned state is the independent proof: in equilibrium (1e-9: interior-point
        // tolerance 1e-10 on scaled rows) and without tension.
        assert!(equilibrium_residual(&p, &s.resultants, 1.0, &[], 0.0) < 1e-9);
        let weight = p.assembly().total_area();
        assert!(s
            .resultants
            .iter()
            .all(|r| r[0] >= -1e-9 * weight && r[1] >= -1e-9 * weight));
    }

    #[test]
    fn milankovitch_1800_voussoirs_thickness_1_0747_collapses_in_five_hinges() {
        // model §1.4: D = 1.0747: λ₀ = 0 and the active limits are interface 1 s (0.0°, hinge at
        // the extrados), 356 q (35.5°, intrados), 901 s (90.0°, extrados), 1446 q (144.5°,
        // intrados), 1801 s (180.0°, extrados). Interfaces are 0-based here.
        let arch = semicircle(
            milankovitch::VOUSSOIRS,
            milankovitch::RADIUS,
            milankovitch::THICKNESS_FALLS,
        );
        let s = dead(&heyman(arch.assembly(), vec![]));
        assert_eq!(s.load_factor, Some(0.0));
        assert_eq!(s.dead_load_carried, Some(false));
        let m = s.mechanism.unwrap();
        let active: Vec<(usize, Resultant, Bound, Option<HingeSide>)> = m
            .active
            .iter()
            .map(|a| (a.interface + 1, a.resultant, a.bound, a.hinge))
            .collect();
        use Bound::Lower;
        use HingeSide::{Extrados, Intrados};
        assert_eq!(
            active,
            vec![
                (1, Resultant::S, Lower, Some(Extrados)),
                (356, Resultant::Q, Lower, Some(Intrados)),
                (901, Resultant::S, Lower, Some(Extrados)),
                (1446, Resultant::Q, Lower, Some(Intrados)),
                (1801, Resultant::S, Lower, Some(Extrados)),
            ]
        );
        let angles: Vec<f64> = m.active.iter().map(|a| a.angle_deg).collect();
        for (a, e) in angles.iter().zip([0.0, 35.5, 90.0, 144.5, 180.0]) {
            assert!((a - e).abs() < 1e-9, "{angles:?}");
        }
        // Five hinges leave two degrees of freedom: the mechanism is a combination of the two
        // four-hinge ones, so it need not be symmetric. Check it is a mechanism, by hand: the
        // blocks turn relative to each other only at the five hinges, the end blocks turn about
        // the extrados points of the springings (zero velocity there, to 1e-6), and the weight
        // does positive work.
        let hinge_interfaces = [0, 355, 900, 1445, 1800];
        for b in 1..1800 {
            let relative = m.velocities[b][2] - m.velocities[b - 1][2];
            if !hinge_interfaces.contains(&b) {
                assert!(
                    relative.abs() < 1e-6,
                    "block {b} turns relative to {}: {relative}",
                    b - 1
                );
            }
        }
        let a = arch.assembly();
        for (b, point) in [(0, (10.53735, 0.0)), (1799, (-10.53735, 0.0))] {
            let (v, g) = (m.velocities[b], a.blocks[b].centroid);
            let speed = (v[0] - v[2] * (point.1 - g.1)).hypot(v[1] + v[2] * (point.0 - g.0));
            assert!(
                speed < 1e-6,
                "block {b} moves at its springing hinge: {speed}"
            );
        }
        let work: f64 = a
            .blocks
            .iter()
            .zip(&m.velocities)
            .map(|(b, v)| -b.area * v[1])
            .sum();
        assert!(work > 0.0);
    }

    #[test]
    fn one_two_or_three_voussoirs_stand_however_thin() {
        // model §1.4: no mechanism can form under symmetric dead load with N ≤ 3.
        for n in 1..=3 {
            for d in [1e-3, 0.01, 0.1] {
                let arch = circular_arch(n, 1.0, d, 0.0, VoussoirShape::Curved);
                let s = dead(&heyman(arch.assembly(), vec![]));
                assert_eq!(s.load_factor, Some(1.0), "N = {n}, D = {d}");
            }
        }
        // …while four thin voussoirs do not.
        let s = dead(&heyman(
            circular_arch(4, 1.0, 0.01, 0.0, VoussoirShape::Curved).assembly(),
            vec![],
        ));
        assert_eq!(s.load_factor, Some(0.0));
    }

    #[test]
    fn shear_capacity_gives_a_fractional_dead_load_factor() {
        // Hand computation: a unit square block between two vertical walls. Normal forces on
        // vertical joints are horizontal, so the weight W = 1 can only be carried by the shear
        // of the two joints, |t| ≤ 0.25 each: λ₀ = 2·0.25/1 = 0.5 exactly.
        let block = [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)];
        let block = [block[0], block[1], block[2], block[3]];
        // Joints: start face (0,0)-(0,1), end face (1,0)-(1,1).
        let assembly = Assembly::from_quadrilaterals(&[block]).unwrap();
        let limits = InterfaceLimits {
            t_min: Some(-0.25),
            t_max: Some(0.25),
            ..InterfaceLimits::heyman()
        };
        let p = ArchProblem::new(assembly, 1.0, limits, None, vec![]).unwrap();
        let s = dead(&p);
        let lambda = s.load_factor.unwrap();
        // 1e-8: interior-point tolerance.
        assert!((lambda - 0.5).abs() < 1e-8, "λ₀ = {lambda}");
        assert_eq!(s.dead_load_carried, Some(false));
        assert!(equilibrium_residual(&p, &s.resultants, lambda, &[], 0.0) < 1e-8);
        let m = s.mechanism.unwrap();
        assert_eq!(m.sliding, vec![0, 1]);
    }

    #[test]
    fn friction_too_low_makes_the_springings_slide() {
        // A thick semicircle stands without sliding limits, but its springing joints are
        // horizontal: with μ below the thrust ratio H/V there they slide.
        let arch = circular_arch(20, 10.0, 3.0, 0.0, VoussoirShape::Curved);
        assert_eq!(
            dead(&heyman(arch.assembly(), vec![])).load_factor,
            Some(1.0)
        );
        let p = ArchProblem::new(
            arch.assembly(),
            1.0,
            InterfaceLimits::heyman(),
            Some(0.1),
            vec![],
        )
        .unwrap();
        let s = dead(&p);
        assert_eq!(s.load_factor, Some(0.0));
        let m = s.mechanism.unwrap();
        // Both springings slide (and, at μ = 0.1, two joints near 54° from the crown too).
        assert!(
            m.sliding.contains(&0) && m.sliding.contains(&20),
            "{:?}",
            m.sliding
        );
        assert!(m.involves_friction());
    }
}

mod live_load {
    use super::*;

    fn quarter_span(n: usize, thickness: f64) -> (ArchProblem, Vec<LiveLoad>) {
        let a = circular_arch(n, 10.0, thickness, 0.0, VoussoirShape::Curved).assembly();
        let loads = point_load(&a, n / 4, -1.0);
        (heyman(a, loads.clone()), loads)
    }

    #[test]
    fn point_load_near_quarter_span_makes_four_hinges() {
        let (p, loads) = quarter_span(100, 1.5);
        let s = live(&p);
        let lambda = s.load_factor.unwrap();
        let m = s.mechanism.clone().unwrap();
        assert_eq!(m.hinges.len(), 4, "{:?}", m.hinges);
        // Hinges alternate intrados/extrados, one under the load, both springings take part.
        let sides: Vec<HingeSide> = m.hinges.iter().map(|h| h.side).collect();
        assert_eq!(
            sides,
            [
                HingeSide::Intrados,
                HingeSide::Extrados,
                HingeSide::Intrados,
                HingeSide::Extrados
            ]
        );
        assert_eq!(m.hinges[3].interface, 100);
        // Lower bound: the returned state is admissible and in equilibrium at λ.
        assert!(equilibrium_residual(&p, &s.resultants, 1.0, &loads, lambda) < 1e-9);
        assert!(s.resultants.iter().all(|r| r[0] >= -1e-9 && r[1] >= -1e-9));
        // Upper bound: virtual work of the mechanism, by hand. With Heyman's limits the hinges
        // dissipate nothing, so λ·(p·V) + (w·V) = 0.
        let a = p.assembly();
        let dead_work: f64 = a
            .blocks
            .iter()
            .zip(&m.velocities)
            .map(|(b, v)| -b.area * v[1])
            .sum();
        let l = &loads[0];
        let v = m.velocities[l.block];
        let g = a.blocks[l.block].centroid;
        let velocity_at_load = (
            v[0] - v[2] * (l.point.1 - g.1),
            v[1] + v[2] * (l.point.0 - g.0),
        );
        let live_work = l.fx * velocity_at_load.0 + l.fy * velocity_at_load.1;
        let lambda_kinematic = -dead_work / live_work;
        // 1e-6: the mechanism comes from multipliers at interior-point accuracy.
        assert!(
            (lambda_kinematic - lambda).abs() < 1e-6 * lambda,
            "{lambda_kinematic} vs {lambda}"
        );
    }

    #[test]
    fn load_factor_scales_exactly_with_the_loads_and_not_with_units() {
        let (p, _) = quarter_span(60, 1.5);
        let base = live(&p).load_factor.unwrap();
        // Twice the load: half the factor. 1e-8 relative: interior-point tolerance.
        let a = p.assembly().clone();
        let doubled = heyman(a.clone(), point_load(&a, 15, -2.0));
        let lambda = live(&doubled).load_factor.unwrap();
        assert!(
            (2.0 * lambda - base).abs() < 1e-8 * base,
            "{lambda} vs {base}"
        );
        // γ × 10⁶ with loads × 10⁶ and γ × 10⁻⁶ with loads × 10⁻⁶: the same factor.
        for scale in [1e-6, 1e6] {
            let scaled = ArchProblem::new(
                a.clone(),
                scale,
                InterfaceLimits::heyman(),
                None,
                point_load(&a, 15, -scale),
            )
            .unwrap();
            let lambda = live(&scaled).load_factor.unwrap();
            assert!(
                (lambda - base).abs() < 1e-8 * base,
                "scale {scale}: {lambda} vs {base}"
            );
        }
        // Lengths × 1000 (weight grows as area, so loads × 10⁶): the same factor.
        let big = circular_arch(60, 10_000.0, 1_500.0, 0.0, VoussoirShape::Curved).assembly();
        let lambda = live(&heyman(big.clone(), point_load(&big, 15, -1e6)))
            .load_factor
            .unwrap();
        assert!((lambda - base).abs() < 1e-8 * base, "{lambda} vs {base}");
    }

    #[test]
    fn large_friction_coefficient_recovers_the_frictionless_answer() {
        let (p, loads) = quarter_span(40, 1.5);
        let frictionless = live(&p).load_factor.unwrap();
        let a = p.assembly().clone();
        let rough = ArchProblem::new(a, 1.0, InterfaceLimits::heyman(), Some(1e3), loads).unwrap();
        let s = live(&rough);
        assert!((s.load_factor.unwrap() - frictionless).abs() < 1e-7 * frictionless);
        assert!(!s.mechanism.unwrap().involves_friction());
    }

    #[test]
    fn quadrilateral_chain_reproduces_the_generator() {
        let arch = circular_arch(30, 10.0, 1.5, 0.0, VoussoirShape::Quadrilateral).assembly();
        let corners: Vec<[(f64, f64); 4]> = arch
            .blocks
            .iter()
            .map(|b| std::array::from_fn(|i| b.corners[i]))
            .collect();
        let chain = Assembly::from_quadrilaterals(&corners).unwrap();
        let a = live(&heyman(arch.clone(), point_load(&arch, 7, -1.0)))
            .load_factor
            .unwrap();
        let b = live(&heyman(chain.clone(), point_load(&chain, 7, -1.0)))
            .load_factor
            .unwrap();
        assert!((a - b).abs() < 1e-9 * a, "{a} vs {b}");
    }

    #[test]
    fn thin_arch_that_cannot_carry_its_weight_has_no_live_load_factor() {
        let (p, _) = quarter_span(100, 0.5);
        let s = solve_live_load(&p, &LimitSettings::default()).unwrap();
        assert_eq!(s.status, LimitStatus::DeadLoadNotCarried);
        assert_eq!(s.load_factor, None);
        assert!(s.mechanism.is_some());
    }

    #[test]
    fn two_voussoirs_cannot_form_a_mechanism() {
        // Two blocks have three joints: at most three hinges, a structure, not a mechanism.
        let a = circular_arch(2, 10.0, 0.5, 0.0, VoussoirShape::Curved).assembly();
        let s = solve_live_load(
            &heyman(a.clone(), point_load(&a, 0, -1.0)),
            &LimitSettings::default(),
        )
        .unwrap();
        assert_eq!(s.status, LimitStatus::Unbounded);
        assert_eq!(s.load_factor, None);
    }

    #[test]
    fn no_load_is_an_error() {
        let a = circular_arch(10, 10.0, 1.5, 0.0, VoussoirShape::Curved).assembly();
        assert!(solve_live_load(
            &heyman(a.clone(), point_load(&a, 0, 0.0)),
            &LimitSettings::default()
        )
        .is_err());
    }
}

mod formulations {
    //! The chain formulation (three redundants, constraint generation) and Livesley's general
    //! assembly formulation are two independent programmes: they must agree.
    use super::*;

    fn both<T>(run: impl Fn(&LimitSettings) -> T) -> (T, T) {
        let chain = LimitSettings {
            formulation: Formulation::Chain,
            ..LimitSettings::default()
        };
        let assembly = LimitSettings {
            formulation: Formulation::Assembly,
            ..LimitSettings::default()
        };
        (run(&chain), run(&assembly))
    }

    fn active(s: &LimitSolution) -> Vec<(usize, Resultant, Bound)> {
        s.mechanism
            .as_ref()
            .map(|m| {
                m.active
                    .iter()
                    .map(|a| (a.interface, a.resultant, a.bound))
                    .collect()
            })
            .unwrap_or_default()
    }

    #[test]
    fn dead_load_margins_and_mechanisms_agree() {
        for (n, d, mu) in [
            (1800, 1.0747, None),
            (1800, 1.0748, None),
            (40, 3.0, Some(0.1)),
            (7, 0.2, None),
        ] {
            let a = circular_arch(n, 10.0, d, 0.0, VoussoirShape::Curved).assembly();
            let p = ArchProblem::new(a, 1.0, InterfaceLimits::heyman(), mu, vec![]).unwrap();
            let (c, s) = both(|settings| solve_dead_load(&p, settings));
            assert_eq!(c.load_factor, s.load_factor, "N = {n}, D = {d}");
            // 1e-9 of the weight: the chain's simplex vertex against the interior-point
            // method's solution at tolerance 1e-10.
            let (mc, ms) = (c.dead_load_margin.unwrap(), s.dead_load_margin.unwrap());
            assert!((mc - ms).abs() < 1e-9, "N = {n}, D = {d}: {mc} vs {ms}");
            assert_eq!(active(&c), active(&s), "N = {n}, D = {d}");
        }
    }

    #[test]
    fn live_load_factors_agree() {
        for (n, mu, limits) in [
            (100, None, InterfaceLimits::heyman()),
            (1800, None, InterfaceLimits::heyman()),
            (30, Some(0.6), InterfaceLimits::heyman()),
            (
                30,
                None,
                InterfaceLimits {
                    q_max: Some(30.0),
                    s_max: Some(30.0),
                    ..InterfaceLimits::heyman()
                },
            ),
        ] {
            let a = circular_arch(n, 10.0, 1.5, 0.0, VoussoirShape::Quadrilateral).assembly();
            let loads = point_load(&a, n / 4, -1.0);
            let p = ArchProblem::new(a, 1.0, limits, mu, loads).unwrap();
            let (c, s) = both(|settings| solve_live_load(&p, settings).unwrap());
            let (lc, ls) = (c.load_factor.unwrap(), s.load_factor.unwrap());
            // 1e-7 relative: the chain's simplex vertex against an interior-point solution at
            // tolerance 1e-10.
            assert!((lc - ls).abs() < 1e-7 * ls, "N = {n}: {lc} vs {ls}");
            assert_eq!(active(&c), active(&s), "N = {n}");
        }
    }

    #[test]
    fn fractional_dead_load_factor_agrees() {
        // Finite crushing strength below what the weight needs: λ₀ < 1 by Newton on the margin.
        let a = circular_arch(24, 10.0, 1.5, 0.0, VoussoirShape::Curved).assembly();
        let limits = InterfaceLimits {
            q_max: Some(0.5),
            s_max: Some(0.5),
            ..InterfaceLimits::heyman()
        };
        let p = ArchProblem::new(a, 1.0, limits, None, vec![]).unwrap();
        let (c, s) = both(|settings| solve_dead_load(&p, settings));
        let (lc, ls) = (c.load_factor.unwrap(), s.load_factor.unwrap());
        assert!(lc > 0.0 && lc < 1.0, "{lc}");
        assert!((lc - ls).abs() < 1e-7, "{lc} vs {ls}");
        assert!(equilibrium_residual(&p, &c.resultants, lc, &[], 0.0) < 1e-9);
        let weight = p.assembly().total_area();
        assert!(c
            .resultants
            .iter()
            .all(|r| r[0] <= 0.5 + 1e-8 * weight && r[1] <= 0.5 + 1e-8 * weight));
        assert!(!c.mechanism.unwrap().crushing.is_empty());
    }

    /// A circular arch of its own base angles, R = 10.
    fn arch(n: usize, thickness: f64, left: f64, right: f64) -> Assembly {
        let n = std::num::NonZeroUsize::new(n).unwrap();
        CircularArch::new(10.0, thickness, n, left, right, VoussoirShape::Curved)
            .unwrap()
            .assembly()
    }

    // Random arches and loads (issue 45: the chain on the simplex method, the assembly on the
    // interior-point method).
    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        #[test]
        fn random_live_loads_agree(
            n in 4usize..160,
            thickness in 0.9f64..3.0,
            left in -10.0f64..40.0,
            right in -10.0f64..40.0,
            at in 0.0f64..1.0,
            angle in -60.0f64..60.0,
            friction in proptest::option::of(0.3f64..1.0),
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
            let p =
                ArchProblem::new(a, 1.0, InterfaceLimits::heyman(), friction, vec![load]).unwrap();
            let (chain, assembly) = both(|settings| solve_live_load(&p, settings).unwrap());
            proptest::prop_assert_eq!(chain.status, assembly.status);
            match (chain.load_factor, assembly.load_factor) {
                // 1e-7: a load at a springing reaches λ ~ 4e4, where the interior-point
                // method's 1e-10 on the scaled programme leaves 2e-8 of it.
                (Some(x), Some(y)) => {
                    proptest::prop_assert!((x - y).abs() <= 1e-7 * y, "λ {} against {}", x, y)
                }
                (x, y) => proptest::prop_assert_eq!(x, y),
            }
            if chain.load_factor.is_some() {
                proptest::prop_assert_eq!(active(&chain), active(&assembly));
            }
        }

        #[test]
        fn random_dead_loads_agree(
            n in 4usize..160,
            thickness in 0.6f64..1.6,
            left in -10.0f64..30.0,
            right in -10.0f64..30.0,
            friction in proptest::option::of(0.3f64..1.0),
        ) {
            let a = arch(n, thickness, left, right);
            let p = ArchProblem::new(a, 1.0, InterfaceLimits::heyman(), friction, vec![]).unwrap();
            let (chain, assembly) = both(|settings| solve_dead_load(&p, settings));
            proptest::prop_assert_eq!(chain.status, assembly.status);
            proptest::prop_assert_eq!(chain.dead_load_carried, assembly.dead_load_carried);
            let (x, y) = (chain.dead_load_margin.unwrap(), assembly.dead_load_margin.unwrap());
            proptest::prop_assert!((x - y).abs() <= 1e-8, "margin {} against {}", x, y);
            if chain.dead_load_carried == Some(false) {
                proptest::prop_assert_eq!(active(&chain), active(&assembly));
            }
        }
    }
}
