//! Any block assembly and the generators built on it (model §5.4, §5.6): polygons against the
//! chain they describe, multi-ring arches against one ring, a wall panel against the hand
//! calculation, and the geometry errors.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::arch::generators::{bridge, Piers, RingJoints};
use thrustline_solver::arch::*;

fn arch(n: usize, thickness: f64) -> CircularArch {
    CircularArch::new(
        10.0,
        thickness,
        NonZeroUsize::new(n).unwrap(),
        0.0,
        0.0,
        VoussoirShape::Quadrilateral,
    )
    .unwrap()
}

fn one_span() -> Piers {
    Piers {
        spans: 1,
        width: 0.0,
        height: 0.0,
    }
}

fn heyman(assembly: Assembly, loads: Vec<LiveLoad>) -> ArchProblem {
    ArchProblem::new(assembly, 1.0, InterfaceLimits::heyman(), None, loads).unwrap()
}

fn dead_factor(problem: &ArchProblem) -> f64 {
    let s = solve_dead_load(problem, &LimitSettings::default());
    assert_eq!(s.status, LimitStatus::Solved);
    s.load_factor.unwrap()
}

fn live_factor(problem: &ArchProblem) -> f64 {
    let s = solve_live_load(problem, &LimitSettings::default()).unwrap();
    assert_eq!(s.status, LimitStatus::Solved, "{s:?}");
    s.load_factor.unwrap()
}

fn bonded() -> InterfaceLimits {
    InterfaceLimits {
        q_min: None,
        s_min: None,
        ..InterfaceLimits::heyman()
    }
}

#[test]
fn a_circular_arch_given_as_polygons_is_the_circular_generator() {
    // One aligned ring = the quadrilateral voussoirs of the generator with two abutments: the
    // same λ (1e-9 relative) and the same hinge points (1e-9 of R), found on the general
    // formulation from contacts the assembly detected itself.
    let generator = arch(24, 1.5);
    let chain = generator.assembly();
    let polygons = bridge(&generator, 1, RingJoints::Aligned, one_span()).unwrap();
    let assembly = polygons.assembly;
    assert!(!assembly.is_chain(), "solved on the general formulation");
    assert_eq!(assembly.blocks.len(), 24);
    assert_eq!(
        assembly.interfaces.len(),
        25,
        "23 joints and two springings"
    );
    let load = |a: &Assembly| {
        vec![LiveLoad {
            block: 6,
            point: a.blocks[6].centroid,
            fx: 0.0,
            fy: -1.0,
            moment: 0.0,
        }]
    };
    let (p, q) = (
        heyman(chain.clone(), load(&chain)),
        heyman(assembly.clone(), load(&assembly)),
    );
    let (a, b) = (live_factor(&p), live_factor(&q));
    assert!((a - b).abs() < 1e-9 * a, "{a} vs {b}");
    let hinge_points = |problem: &ArchProblem| {
        let s = solve_live_load(problem, &LimitSettings::default()).unwrap();
        let mut points: Vec<(f64, f64)> = s
            .mechanism
            .unwrap()
            .hinges
            .iter()
            .map(|h| {
                let i = problem.assembly().interfaces[h.interface];
                match h.side {
                    HingeSide::Intrados => i.intrados,
                    HingeSide::Extrados => i.extrados,
                }
            })
            .collect();
        points.sort_by(|u, v| u.0.total_cmp(&v.0));
        points
    };
    let (hp, hq) = (hinge_points(&p), hinge_points(&q));
    assert_eq!(hp.len(), 4);
    assert_eq!(hp.len(), hq.len());
    for (u, v) in hp.iter().zip(&hq) {
        assert!((u.0 - v.0).abs() < 1e-9 * 10.0 && (u.1 - v.1).abs() < 1e-9 * 10.0);
    }
}

#[test]
fn two_bonded_rings_with_aligned_joints_are_one_ring_of_the_whole_thickness() {
    // model §5.6: ring interfaces that can neither open nor slide make each radial pair of
    // voussoirs one block: λ equals the one-ring arch's (1e-8: interior-point tolerance).
    let generator = arch(20, 1.5);
    let one = heyman(generator.assembly(), vec![]);
    let two = bridge(&generator, 2, RingJoints::Aligned, one_span()).unwrap();
    assert_eq!(two.assembly.blocks.len(), 40);
    let rings = two
        .assembly
        .interfaces
        .iter()
        .filter(|i| i.kind == InterfaceKind::Ring)
        .count();
    assert_eq!(rings, 20);
    // A load on the outer ring over the sixth voussoir, and on the one ring at the same point.
    let point = two.assembly.blocks[20 + 5].centroid;
    let load = |block: usize| LiveLoad {
        block,
        point,
        fx: 0.0,
        fy: -1.0,
        moment: 0.0,
    };
    let one = one.with_live_loads(vec![load(5)]).unwrap();
    let two = heyman(two.assembly, vec![load(25)])
        .with_ring_interfaces(bonded(), None)
        .unwrap();
    let (a, b) = (live_factor(&one), live_factor(&two));
    assert!((a - b).abs() < 1e-8 * a, "{a} vs {b}");
}

#[test]
fn staggered_rings_lock_together_and_frictionless_rings_act_alone() {
    // R = 10, total D = 1.0 (t/R = 0.10, below Milankovitch's 0.1075): one ring of the whole
    // thickness falls under its own weight. Two staggered rings that cannot slide on each other
    // stand (no hinge can form without slip along the ring interface, model §5.6). With
    // frictionless ring interfaces each ring of t/R ≈ 0.05 acts alone, and falls.
    let generator = arch(40, 1.0);
    assert!(dead_factor(&heyman(generator.assembly(), vec![])) < 1.0);
    let two = bridge(&generator, 2, RingJoints::Staggered, one_span()).unwrap();
    assert_eq!(
        two.assembly.blocks.len(),
        81,
        "40 voussoirs and 41 shifted ones"
    );
    let locked = heyman(two.assembly.clone(), vec![])
        .with_ring_interfaces(InterfaceLimits::heyman(), None)
        .unwrap();
    assert_eq!(dead_factor(&locked), 1.0);
    let frictionless = heyman(two.assembly, vec![])
        .with_ring_interfaces(InterfaceLimits::heyman(), Some(0.0))
        .unwrap();
    assert!(dead_factor(&frictionless) < 1.0);
}

#[test]
fn a_wall_panel_overturns_at_the_hand_computed_load() {
    // A block 2 wide and 1 tall on the ground, a block 1 × 1 centred on it; a horizontal push
    // at the top-left corner of the top block (γ = 1). The top block tips about its right
    // bottom corner when P·1 = W_top·½ → P = 0.5; the whole wall would need P·2 = 3·1 → 1.5.
    // With friction μ = 0.3 the top block slides first, at P = μ·W_top = 0.3.
    let blocks = vec![
        vec![(-1.0, 0.0), (1.0, 0.0), (1.0, 1.0), (-1.0, 1.0)],
        // Clockwise, on purpose: turned round.
        vec![(-0.5, 1.0), (-0.5, 2.0), (0.5, 2.0), (0.5, 1.0)],
    ];
    let ground = vec![vec![(-3.0, -1.0), (3.0, -1.0), (3.0, 0.0), (-3.0, 0.0)]];
    let wall = Assembly::from_polygons(&blocks, &ground).unwrap();
    assert_eq!(wall.interfaces.len(), 2);
    let push = vec![LiveLoad {
        block: 1,
        point: (-0.5, 2.0),
        fx: 1.0,
        fy: 0.0,
        moment: 0.0,
    }];
    let tipping = heyman(wall.clone(), push.clone());
    assert!((live_factor(&tipping) - 0.5).abs() < 1e-8);
    let sliding = ArchProblem::new(wall, 1.0, InterfaceLimits::heyman(), Some(0.3), push).unwrap();
    assert!((live_factor(&sliding) - 0.3).abs() < 1e-8);
}

#[test]
fn spans_on_piers_stand_and_a_pier_too_narrow_is_refused() {
    // Three semicircular spans on two piers: each span thick enough to stand alone stands on
    // the piers too (the piers carry the two thrusts, which balance under dead load).
    let generator = arch(30, 1.5);
    let piers = Piers {
        spans: 3,
        width: 4.0,
        height: 6.0,
    };
    let b = bridge(&generator, 1, RingJoints::Aligned, piers).unwrap();
    assert_eq!(b.assembly.blocks.len(), 3 * 30 + 2);
    let p = heyman(b.assembly, vec![]);
    assert_eq!(dead_factor(&p), 1.0);
    let narrow = Piers {
        width: 2.5,
        ..piers
    };
    assert!(matches!(
        bridge(&generator, 1, RingJoints::Aligned, narrow),
        Err(ArchError::OutOfRange {
            parameter: ArchParameter::PierWidth,
            ..
        })
    ));
}

#[test]
fn bad_assemblies_are_refused_naming_the_block() {
    let square = |x: f64, y: f64| vec![(x, y), (x + 1.0, y), (x + 1.0, y + 1.0), (x, y + 1.0)];
    let ground = vec![vec![(-5.0, -1.0), (5.0, -1.0), (5.0, 0.0), (-5.0, 0.0)]];
    let named = |r: Result<Assembly, ArchError>| match r {
        Err(ArchError::InvalidGeometry { parameter, reason }) => (parameter, reason),
        other => panic!("{other:?}"),
    };
    // Overlapping.
    let (p, reason) = named(Assembly::from_polygons(
        &[square(0.0, 0.0), square(0.5, 0.0)],
        &ground,
    ));
    assert_eq!(p, ArchParameter::BlockPolygon { block: 0 });
    assert!(reason.contains("overlap"), "{reason}");
    // Touching nothing.
    let (p, reason) = named(Assembly::from_polygons(
        &[square(0.0, 0.0), square(0.0, 3.0)],
        &ground,
    ));
    assert_eq!(p, ArchParameter::BlockPolygon { block: 1 });
    assert!(reason.contains("touches no"), "{reason}");
    // No support.
    assert!(matches!(
        Assembly::from_polygons(&[square(0.0, 0.0)], &[]),
        Err(ArchError::InvalidGeometry {
            parameter: ArchParameter::Supports,
            ..
        })
    ));
    // Degenerate and self-intersecting.
    let (p, _) = named(Assembly::from_polygons(
        &[vec![(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]],
        &ground,
    ));
    assert_eq!(p, ArchParameter::BlockPolygon { block: 0 });
    let bowtie = vec![(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)];
    let (_, reason) = named(Assembly::from_polygons(&[bowtie], &ground));
    assert!(reason.contains("self-intersecting"), "{reason}");
    // A non-convex block (an L) standing on the ground is fine.
    let l = vec![
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 2.0),
        (0.0, 2.0),
    ];
    let a = Assembly::from_polygons(&[l], &ground).unwrap();
    assert_eq!(a.interfaces.len(), 1);
    assert!((a.blocks[0].area - 3.0).abs() < 1e-12);
}
