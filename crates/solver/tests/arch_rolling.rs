//! A load rolled across an arch (model §5.3): the sweep answers each stop as a solve of that stop
//! alone does (the warm simplex method's λ against the interior-point solves), its critical stop
//! with the state a solve of that stop gives, and says when its time ran out.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use thrustline_solver::arch::*;
use thrustline_solver::reference::semicircle;

/// A unit load on the centroid of block `b`, or nothing (an empty stop) for `None`.
fn stop(arch: &Assembly, b: Option<usize>) -> Vec<LiveLoad> {
    b.map(|b| LiveLoad {
        block: b,
        point: arch.blocks[b].centroid,
        fx: 0.0,
        fy: -1.0,
        moment: 0.0,
    })
    .into_iter()
    .collect()
}

fn problem(arch: &Assembly, passive: bool) -> ArchProblem {
    let p = ArchProblem::new(arch.clone(), 1.0, InterfaceLimits::heyman(), None, vec![]).unwrap();
    if !passive {
        return p;
    }
    // A horizontal restraint on every voussoir of the left half, pushing right, up to 0.05.
    let forces = (0..arch.blocks.len() / 2)
        .map(|b| fill::PassiveForce {
            block: b,
            point: arch.blocks[b].centroid,
            direction: 1.0,
            capacity: 0.05,
        })
        .collect();
    p.with_passive(forces).unwrap()
}

#[test]
fn every_stop_is_answered_as_its_own_solve_answers_it() {
    let arch = semicircle(30, 10.0, 1.5).assembly();
    for passive in [false, true] {
        let p = problem(&arch, passive);
        let settings = LimitSettings::default();
        let blocks = [None, Some(2), Some(7), None, Some(12), Some(15), Some(22)];
        let loads: Vec<Vec<LiveLoad>> = blocks.iter().map(|&b| stop(&arch, b)).collect();
        let sweep = sweep_live_loads(&p, &settings, &loads).unwrap();
        let mut solved = 0;
        assert!(sweep.stop.is_finished());
        assert_eq!(sweep.stops.len(), blocks.len());
        for (i, b) in blocks.iter().enumerate() {
            let Some(b) = b else {
                assert!(sweep.stops[i].is_none(), "stop {i} has no load");
                continue;
            };
            let alone = solve_live_load(
                &p.clone().with_live_loads(stop(&arch, Some(*b))).unwrap(),
                &settings,
            )
            .unwrap();
            let swept = sweep.stops[i].as_ref().unwrap();
            assert_eq!(swept.status, alone.status, "stop {i} (passive {passive})");
            if let (Some(a), Some(s)) = (alone.load_factor, swept.load_factor) {
                // The stops after the first skip the dead-load programme; the live-load
                // programme is the same one, so λ agrees to the solver's tolerance.
                assert!(
                    (a - s).abs() <= 1e-8 * a,
                    "stop {i} (passive {passive}): {a} vs {s}"
                );
                assert!(a > 0.0 && a.is_finite());
                solved += 1;
            }
        }
        assert!(
            solved >= 4,
            "passive {passive}: {solved} stops with a factor"
        );
        // Every stop after the first was swept by the warm simplex method.
        assert_eq!(sweep.simplex_stops, 4, "passive {passive}");
    }
}

#[test]
fn a_fine_sweep_with_passive_restraint_is_warm_and_agrees_stop_by_stop() {
    // A unit load on every voussoir of a semicircle of 40, in turn; the left half restrained.
    let arch = semicircle(40, 10.0, 1.2).assembly();
    let p = problem(&arch, true);
    let settings = LimitSettings::default();
    let loads: Vec<Vec<LiveLoad>> = (0..40).map(|b| stop(&arch, Some(b))).collect();
    let sweep = sweep_live_loads(&p, &settings, &loads).unwrap();
    assert_eq!(sweep.simplex_stops, 39);
    // Warm starts show: a few pivots a stop (the first, cold, takes tens).
    let per_stop = sweep.pivots as f64 / 39.0;
    assert!(per_stop < 12.0, "{per_stop} pivots a stop");
    let mut least = (f64::INFINITY, 0);
    let mut compared = 0;
    for (b, swept) in sweep.stops.iter().enumerate() {
        let swept = swept.as_ref().unwrap();
        let alone = solve_live_load(
            &p.clone().with_live_loads(stop(&arch, Some(b))).unwrap(),
            &settings,
        )
        .unwrap();
        assert_eq!(swept.status, alone.status, "block {b}");
        let (Some(a), Some(s)) = (alone.load_factor, swept.load_factor) else {
            // No collapse under a load next to a springing: both say so (the status).
            continue;
        };
        // Two methods (a vertex of the chain's programme, an interior point of the general
        // formulation's) to the interior-point tolerance.
        assert!((a - s).abs() <= 1e-8 * a, "block {b}: {a} vs {s}");
        compared += 1;
        if s < least.0 {
            least = (s, b);
        }
    }
    assert!(compared >= 30, "{compared} stops collapse");
    // The critical stop carries its state: the interior-point solve of that stop alone.
    let critical = sweep.stops[least.1].as_ref().unwrap();
    let alone = solve_live_load(
        &p.clone()
            .with_live_loads(stop(&arch, Some(least.1)))
            .unwrap(),
        &settings,
    )
    .unwrap();
    assert_eq!(critical.load_factor, alone.load_factor);
    assert_eq!(critical.resultants.len(), arch.interfaces.len());
    assert!(critical.mechanism.is_some());
}

#[test]
fn a_warm_start_reaches_the_vertex_a_cold_start_does() {
    let arch = semicircle(30, 10.0, 1.5).assembly();
    let p = problem(&arch, true);
    let mut warm = WarmLiveLoad::new(&p).unwrap();
    let mut cold = WarmLiveLoad::new(&p).unwrap();
    for b in 3..27 {
        let w = warm.solve(&stop(&arch, Some(b))).unwrap();
        cold.forget();
        let c = cold.solve(&stop(&arch, Some(b))).unwrap();
        assert_eq!(w.warm, b > 3, "block {b}");
        assert!(!c.warm);
        // One optimum, reached along other paths (to the simplex tolerances, 1e-11 on rows).
        match (w.load_factor, c.load_factor) {
            (Some(w), Some(c)) => assert!((w - c).abs() <= 1e-10 * c, "block {b}: {w} vs {c}"),
            (w, c) => assert_eq!(w, c, "block {b}"),
        }
    }
}

#[test]
fn crushing_and_assemblies_are_swept_on_the_interior_point_method() {
    let arch = semicircle(20, 10.0, 1.5).assembly();
    let crushing = Crushing {
        strength: 200.0,
        planes: 4,
        cuts: Vec::new(),
    };
    let p = problem(&arch, true).with_crushing(crushing).unwrap();
    assert!(WarmLiveLoad::new(&p).is_none());
    let loads: Vec<Vec<LiveLoad>> = (4..8).map(|b| stop(&arch, Some(b))).collect();
    let sweep = sweep_live_loads(&p, &LimitSettings::default(), &loads).unwrap();
    assert_eq!(sweep.simplex_stops, 0);
    assert!(sweep
        .stops
        .iter()
        .all(|s| s.as_ref().unwrap().load_factor.is_some()));
}

#[test]
fn a_sweep_out_of_time_says_so_and_leaves_the_rest_unsolved() {
    let arch = semicircle(30, 10.0, 1.5).assembly();
    let p = problem(&arch, false);
    let settings = LimitSettings {
        budget: thrustline_solver::budget::Budget::with_time_limit(std::time::Duration::ZERO),
        ..LimitSettings::default()
    };
    let loads: Vec<Vec<LiveLoad>> = (5..12).map(|b| stop(&arch, Some(b))).collect();
    let sweep = sweep_live_loads(&p, &settings, &loads).unwrap();
    assert_eq!(sweep.stop, thrustline_solver::budget::Stop::TimeLimit);
    assert!(sweep.stops[0].is_some(), "the first stop is always tried");
    assert!(sweep.stops[1..].iter().all(Option::is_none));
}

#[test]
fn a_sweep_without_loads_solves_nothing() {
    let arch = semicircle(10, 10.0, 1.5).assembly();
    let sweep = sweep_live_loads(
        &problem(&arch, false),
        &LimitSettings::default(),
        &[Vec::new(), Vec::new()],
    )
    .unwrap();
    assert!(sweep.stop.is_finished());
    assert!(sweep.stops.iter().all(Option::is_none));
}
