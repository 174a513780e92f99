//! The floor the chain programmes are measured against (issue 45): building a semicircular
//! chain's statics and one O(N) pass (every interface's resultants from three known
//! redundants), beside the dead- and live-load solves of the same chain, as ratios. Run with
//! `cargo bench -p thrustline-solver --bench chain_floor` (release build); each time is the
//! median of repeated runs on one thread, in microseconds.
#![allow(clippy::unwrap_used)]

use thrustline_solver::arch::chain::ChainStatics;
use thrustline_solver::arch::*;
use thrustline_solver::reference::semicircle;

mod common;

/// Median wall time in microseconds of `runs` calls, and the last value.
fn time<T>(runs: usize, f: impl FnMut() -> T) -> (f64, T) {
    let (secs, value) = common::median_secs(runs, f);
    (secs * 1e6, value)
}

fn main() {
    println!("| N | build + one pass | dead load | ratio | live load | ratio |");
    println!("|---|---|---|---|---|---|");
    for n in [100, 1800, 10_000] {
        let runs = if n >= 10_000 { 11 } else { 51 };
        // D = 1.5: stands; a unit load at a quarter of the span.
        let arch = semicircle(n, 10.0, 1.5);
        let load = vec![LiveLoad {
            block: n / 4,
            point: arch.assembly().blocks[n / 4].centroid,
            fx: 0.0,
            fy: -1.0,
            moment: 0.0,
        }];
        let (floor, _) = time(runs, || {
            let assembly = arch.assembly();
            let chain = ChainStatics::new(&assembly, 1.0, &[], &load);
            chain.resultants([1.0, 0.0, 0.0], 1.0, 0.0).len()
        });
        let settings = LimitSettings::default();
        let (dead, d) = time(runs, || {
            let problem = ArchProblem::new(
                arch.assembly(),
                1.0,
                InterfaceLimits::heyman(),
                None,
                vec![],
            )
            .unwrap();
            solve_dead_load(&problem, &settings)
        });
        let (live, l) = time(runs, || {
            let problem = ArchProblem::new(
                arch.assembly(),
                1.0,
                InterfaceLimits::heyman(),
                None,
                load.clone(),
            )
            .unwrap();
            solve_live_load(&problem, &settings).unwrap()
        });
        assert!(d.dead_load_carried == Some(true) && l.load_factor.is_some());
        println!(
            "| {n} | {floor:.1} µs | {dead:.1} µs | {:.1}× | {live:.1} µs | {:.1}× |",
            dead / floor,
            live / floor
        );
    }
}
