//! The state shown with an answer of the general model: the state of least normal force among
//! those the answer admits, against states worked out by hand where it is unique, and against
//! the chain's state where the collapse state is statically determinate.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::arch::generators::{bridge, Piers, RingJoints};
use thrustline_solver::arch::*;

/// Two unit blocks side by side on the ground (γ = 1: weight 1 each), block 0 on [0, 1],
/// block 1 on [1, 2]; the supports cannot slide (no friction coefficient). Interfaces: the
/// joint at x = 1 and the two bases.
fn two_blocks(loads: Vec<LiveLoad>) -> ArchProblem {
    let blocks = vec![
        vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
        vec![(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)],
    ];
    let ground = vec![vec![(-1.0, -1.0), (3.0, -1.0), (3.0, 0.0), (-1.0, 0.0)]];
    let assembly = Assembly::from_polygons(&blocks, &ground).unwrap();
    assert_eq!(assembly.interfaces.len(), 3);
    ArchProblem::new(assembly, 1.0, InterfaceLimits::heyman(), None, loads).unwrap()
}

/// R 10, D 1.5, 20 quadrilateral voussoirs.
fn twenty_voussoirs() -> CircularArch {
    CircularArch::new(
        10.0,
        1.5,
        NonZeroUsize::new(20).unwrap(),
        0.0,
        0.0,
        VoussoirShape::Quadrilateral,
    )
    .unwrap()
}

fn settings() -> LimitSettings {
    LimitSettings {
        formulation: Formulation::Assembly,
        ..LimitSettings::default()
    }
}

/// The joint between the two blocks (the interface whose points lie on x = 1 at two heights).
fn joint(problem: &ArchProblem) -> usize {
    let interfaces = &problem.assembly().interfaces;
    let k = interfaces
        .iter()
        .position(|i| (i.intrados.1 - i.extrados.1).abs() > 0.5)
        .unwrap();
    assert!((interfaces[k].intrados.0 - 1.0).abs() < 1e-12);
    k
}

/// The reactions keyed by the side of the support contact: (left block's, right block's).
fn reactions(problem: &ArchProblem, r: &[[f64; 3]]) -> (SupportReaction, SupportReaction) {
    let all = support_reactions(problem.assembly(), r).unwrap();
    assert_eq!(all.len(), 2);
    let middle = |s: &SupportReaction| {
        let i = &problem.assembly().interfaces[s.interface];
        0.5 * (i.intrados.0 + i.extrados.0)
    };
    if middle(&all[0]) < middle(&all[1]) {
        (all[0], all[1])
    } else {
        (all[1], all[0])
    }
}

#[test]
fn two_blocks_pushed_over_together_show_the_one_least_squeezed_state() {
    // A push λ at the top-left corner of block 0. The joint cannot slide and the ground cannot
    // either, so neither block tips alone (tipping about its own corner slides the joint): the
    // pair overturns about (2, 0) when λ·1 = 1·1.5 + 1·0.5 → λ = 2.
    //
    // At λ = 2 the base of block 0 lifts (no normal force), its shear is free. Block 0: the joint
    // pushes back with N at height y, the ground with shear T at y = 0, the joint's shear carries
    // the weight: N = 2 + T, and moments about (1, y): −2(1 − y) + 0.5 + yT = 0 → y = 1.5/N.
    // y ≤ 1 makes N ≥ 1.5: the least normal force is N = 1.5 at the joint's top end, with
    // T = −0.5; block 1 stands on its corner (2, 0) with N = 2 and shear −1.5. Unique: any
    // other admissible state squeezes the pair (N > 1.5 at the joint, balanced by the two
    // bases' shear), and the interior-point state squeezes it by ~1e5.
    let push = LiveLoad {
        block: 0,
        point: (0.0, 1.0),
        fx: 1.0,
        fy: 0.0,
        moment: 0.0,
    };
    let problem = two_blocks(vec![push]);
    let mut solution = solve_live_load(&problem, &settings()).unwrap();
    assert_eq!(solution.status, LimitStatus::Solved);
    assert!((solution.load_factor.unwrap() - 2.0).abs() < 1e-8);
    // The interior-point state carries the squeeze far out (measured 5e5 against loads of 4);
    // the least state does not.
    assert!(is_squeezed(&problem, &solution, StateOf::LiveLoad));
    let programmes = solution.programmes;
    assert!(show_least_normal_state(
        &problem,
        &settings(),
        StateOf::LiveLoad,
        &mut solution
    ));
    assert_eq!(solution.programmes, programmes + 1);
    assert!(!is_squeezed(&problem, &solution, StateOf::LiveLoad));
    let (left, right) = reactions(&problem, &solution.resultants);
    // Reactions are the forces of the supports on the blocks.
    assert!((left.horizontal + 0.5).abs() < 1e-6, "{left:?}");
    assert!(left.vertical.abs() < 1e-6, "{left:?}");
    assert!((right.horizontal + 1.5).abs() < 1e-6, "{right:?}");
    assert!((right.vertical - 2.0).abs() < 1e-6, "{right:?}");
    let line = thrust_line(problem.assembly(), &solution.resultants);
    let k = joint(&problem);
    assert!((line[k].normal_force - 1.5).abs() < 1e-6, "{:?}", line[k]);
    let (x, y) = line[k].point.unwrap();
    assert!(
        (x - 1.0).abs() < 1e-9 && (y - 1.0).abs() < 1e-6,
        "{:?}",
        line[k]
    );
    // The base of block 0 has no normal force: no point of action is shown for it.
    let base = left.interface;
    assert!(
        line[base].normal_force.abs() < 1e-6 && line[base].point.is_none(),
        "{:?}",
        line[base]
    );
}

#[test]
fn two_blocks_under_their_weight_show_the_least_squeezed_state_at_the_margin() {
    // Dead load only. The margin programme raises every limit by δ·W: every contact end's
    // force ≥ m = −δ·W. Block 0 (weight 1 at x = 0.5): the joint pushes it left with N at
    // height y (ends: N − Ny below, Ny above), the ground carries 1 at x_b and a shear N;
    // moments about (x_b, 0): x_b − 0.5 + N·y = 0. The ends' forces ≥ m: x_b ≥ m, N·y ≥ m,
    // so m ≤ x_b = 0.5 − N·y ≤ 0.5 − m → m ≤ 0.25 (δ = −0.125 with W = 2), reached with
    // N·y = 0.25 and the joint's lower end N − 0.25 ≥ 0.25. The least normal force at that
    // margin is then N = 0.5 exactly, at mid-height, and each base carries a shear of 0.5.
    let problem = two_blocks(Vec::new());
    let mut solution = solve_dead_load(&problem, &settings());
    assert_eq!(solution.dead_load_carried, Some(true));
    assert!((solution.dead_load_margin.unwrap() + 0.125).abs() < 1e-8);
    assert!(show_least_normal_state(
        &problem,
        &settings(),
        StateOf::DeadLoad,
        &mut solution
    ));
    let (left, right) = reactions(&problem, &solution.resultants);
    assert!((left.horizontal - 0.5).abs() < 1e-6, "{left:?}");
    assert!((right.horizontal + 0.5).abs() < 1e-6, "{right:?}");
    assert!((left.vertical + right.vertical - 2.0).abs() < 1e-8);
    let line = thrust_line(problem.assembly(), &solution.resultants);
    let k = joint(&problem);
    assert!((line[k].normal_force - 0.5).abs() < 1e-6, "{:?}", line[k]);
    assert!(
        (line[k].point.unwrap().1 - 0.5).abs() < 1e-6,
        "{:?}",
        line[k]
    );
}

#[test]
fn a_one_ring_arch_shows_the_chains_collapse_state_and_a_chain_keeps_its_own() {
    // At collapse a one-ring arch under a point load is statically determinate (four hinges):
    // the state of the general model is the chain's, whatever state the programme picks. The
    // chain's own state is never replaced (three redundants, nothing to choose).
    let arch = twenty_voussoirs();
    let load = LiveLoad {
        block: 5,
        point: arch.assembly().blocks[5].centroid,
        fx: 0.0,
        fy: -1.0,
        moment: 0.0,
    };
    let problem = ArchProblem::new(
        arch.assembly(),
        1.0,
        InterfaceLimits::heyman(),
        None,
        vec![load],
    )
    .unwrap();
    let mut chain = solve_live_load(&problem, &LimitSettings::default()).unwrap();
    let before = chain.resultants.clone();
    assert!(!show_least_normal_state(
        &problem,
        &LimitSettings::default(),
        StateOf::LiveLoad,
        &mut chain
    ));
    assert_eq!(chain.resultants, before);
    assert!(!is_squeezed(&problem, &chain, StateOf::LiveLoad));
    let mut general = solve_live_load(&problem, &settings()).unwrap();
    let lambda = chain.load_factor.unwrap();
    assert!((general.load_factor.unwrap() - lambda).abs() < 1e-8 * lambda);
    assert!(show_least_normal_state(
        &problem,
        &settings(),
        StateOf::LiveLoad,
        &mut general
    ));
    let weight = problem
        .assembly()
        .blocks
        .iter()
        .map(|b| b.area)
        .sum::<f64>();
    for (a, b) in chain.resultants.iter().zip(&general.resultants) {
        for i in 0..3 {
            assert!((a[i] - b[i]).abs() < 1e-6 * weight, "{a:?} against {b:?}");
        }
    }
}

#[test]
fn a_squeeze_at_the_springings_of_two_rings_is_relieved_there() {
    // Two staggered rings (R 10, D 1.5, 20 voussoirs, ring μ 0.6), a unit load on block 6:
    // the interior-point state squeezes the first blocks of the two rings against each support
    // (1e5 times the loads). The squeeze is relieved on the few contacts that carry it, in one
    // small programme; the state is then checked here on its own: the whole in equilibrium
    // (the reactions carry W + λ and push no net horizontal force), every contact within its
    // limits (q, s ≥ 0; |t| ≤ μ(q + s) on the ring interfaces).
    let generator = twenty_voussoirs();
    let piers = Piers {
        spans: 1,
        width: 0.0,
        height: 0.0,
    };
    let rings = bridge(&generator, 2, RingJoints::Staggered, piers).unwrap();
    let block = &rings.assembly.blocks[5];
    let load = LiveLoad {
        block: 5,
        point: block.centroid,
        fx: 0.0,
        fy: -1.0,
        moment: 0.0,
    };
    let problem = ArchProblem::new(
        rings.assembly.clone(),
        1.0,
        InterfaceLimits::heyman(),
        None,
        vec![load],
    )
    .unwrap()
    .with_ring_interfaces(InterfaceLimits::heyman(), Some(0.6))
    .unwrap();
    let mut solution = solve_live_load(&problem, &settings()).unwrap();
    let lambda = solution.load_factor.unwrap();
    assert!(is_squeezed(&problem, &solution, StateOf::LiveLoad));
    let programmes = solution.programmes;
    assert!(relieve_squeeze(
        &problem,
        &settings(),
        StateOf::LiveLoad,
        &mut solution
    ));
    assert_eq!(
        solution.programmes,
        programmes + 1,
        "the local programme alone"
    );
    assert!(!is_squeezed(&problem, &solution, StateOf::LiveLoad));
    assert_eq!(solution.load_factor, Some(lambda));
    let weight: f64 = problem.assembly().blocks.iter().map(|b| b.area).sum();
    let reactions = support_reactions(problem.assembly(), &solution.resultants).unwrap();
    let horizontal: f64 = reactions.iter().map(|r| r.horizontal).sum();
    let vertical: f64 = reactions.iter().map(|r| r.vertical).sum();
    assert!(horizontal.abs() < 1e-6 * weight, "{reactions:?}");
    assert!(
        (vertical - weight - lambda).abs() < 1e-6 * weight,
        "{reactions:?}"
    );
    let tolerance = 1e-7 * weight;
    for (interface, r) in problem
        .assembly()
        .interfaces
        .iter()
        .zip(&solution.resultants)
    {
        assert!(r[0] >= -tolerance && r[1] >= -tolerance, "{r:?}");
        if interface.kind == InterfaceKind::Ring {
            assert!(r[2].abs() <= 0.6 * (r[0] + r[1]) + tolerance, "{r:?}");
        }
    }
}
