//! Speed against accuracy, measured: the tables of docs/accuracy.md
//! section. Run with `cargo bench -p thrustline-solver --bench tables` (release build); each
//! time is the median of repeated runs on one thread.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;
use thrustline_solver::arch::*;
use thrustline_solver::budget::Budget;
use thrustline_solver::reference::{semicircle, spencer_1967};
use thrustline_solver::slope::*;

mod common;

/// Median wall time in milliseconds of `runs` calls, and the last value.
fn time<T>(runs: usize, f: impl FnMut() -> T) -> (f64, T) {
    let (secs, value) = common::median_secs(runs, f);
    (secs * 1e3, value)
}

fn runs_for(n: usize) -> usize {
    if n >= 5000 {
        5
    } else if n >= 1000 {
        11
    } else {
        31
    }
}

/// A unit downward load at polar angle 45° on the middle radius, on whichever block holds it.
fn quarter_load(arch: &CircularArch) -> Vec<LiveLoad> {
    let n = arch.voussoirs();
    let block = ((45.0 / 180.0) * n as f64).floor() as usize;
    let phi = 45f64.to_radians();
    vec![LiveLoad {
        block: block.min(n - 1),
        point: (10.0 * phi.cos(), 10.0 * phi.sin()),
        fx: 0.0,
        fy: -1.0,
        moment: 0.0,
    }]
}

fn minimum_thickness_ratio(n: usize) -> f64 {
    let r = solve_minimum_thickness(
        &semicircle(n, 10.0, 1.0),
        1.0,
        InterfaceLimits::heyman(),
        None,
        &MinimumThicknessSettings::default(),
    )
    .unwrap();
    match r.outcome {
        Ok(MinimumThicknessOutcome::Found { thickness, .. }) => thickness / 10.0,
        _ => f64::NAN,
    }
}

fn live_factor(n: usize, settings: &LimitSettings) -> f64 {
    let arch = semicircle(n, 10.0, 1.5);
    let p = ArchProblem::new(
        arch.assembly(),
        1.0,
        InterfaceLimits::heyman(),
        None,
        quarter_load(&arch),
    )
    .unwrap();
    solve_live_load(&p, settings).unwrap().load_factor.unwrap()
}

fn spencer(n: usize) -> f64 {
    solve_spencer(
        &spencer_1967::problem(n).model(),
        &SpencerSettings::default(),
    )
    .factor_of_safety
    .unwrap()
}

fn critical(grid_points: usize, refine: bool) -> f64 {
    let e = spencer_1967::embankment();
    let p = SearchProblem {
        embankment: e,
        slices: NonZeroUsize::new(50).unwrap(),
        soil: spencer_1967::soil(spencer_1967::UNIT_WEIGHT),
        seismic: Seismic::default(),
        lower_end_factor: 0.0,
        lower_end_factor_max: None,
    };
    let grid = SearchGrid {
        nx: grid_points,
        ny: grid_points,
        ..SearchGrid::automatic(&e, 0.0)
    };
    let settings = if refine {
        SearchSettings::default()
    } else {
        SearchSettings {
            starts: 0,
            max_regrids: 0,
            ..SearchSettings::default()
        }
    };
    search_critical_circle(&p, grid, &settings, &Budget::unlimited())
        .factor_of_safety
        .unwrap()
}

fn main() {
    // cargo bench passes --bench; nothing to parse.
    println!(
        "### Arch: minimum thickness of the semicircle (Heyman, curved voussoirs) against N\n"
    );
    println!("Reference: Milankovitch's d/R = 0.10748 (model §1.4); tolerance 1e-6·R.\n");
    println!("| N | d/R | error to 0.10748 | time |");
    println!("|---|---|---|---|");
    for n in [10, 30, 100, 300, 1000, 1800, 3000, 10000] {
        let (ms, ratio) = time(runs_for(n), || minimum_thickness_ratio(n));
        println!(
            "| {n} | {ratio:.6} | {:+.1e} | {ms:.2} ms |",
            ratio - 0.10748
        );
    }
    println!("\n### Arch: live-load factor against N (R = 10, D = 1.5, unit load at 45° on the middle radius)\n");
    let reference = live_factor(20000, &LimitSettings::default());
    println!("Reference: N = 20000, λ = {reference:.6}.\n");
    println!("| N | λ | relative error | time (chain) | time (assembly) |");
    println!("|---|---|---|---|---|");
    for n in [10, 100, 1800, 10000] {
        let (ms, lambda) = time(runs_for(n), || live_factor(n, &LimitSettings::default()));
        let assembly = LimitSettings {
            formulation: Formulation::Assembly,
            ..LimitSettings::default()
        };
        let (ms_assembly, _) = time(runs_for(n).min(5), || live_factor(n, &assembly));
        println!(
            "| {n} | {lambda:.6} | {:.1e} | {ms:.2} ms | {ms_assembly:.1} ms |",
            (lambda - reference).abs() / reference
        );
    }
    println!("\n### Arch: dead load against N (D = 1.0747, just too thin at N = 1800)\n");
    println!("| N | λ₀ | time (chain) | time (assembly) |");
    println!("|---|---|---|---|");
    for n in [10, 100, 1800, 10000] {
        let problem = ArchProblem::new(
            semicircle(n, 10.0, 1.0747).assembly(),
            1.0,
            InterfaceLimits::heyman(),
            None,
            vec![],
        )
        .unwrap();
        let (ms, s) = time(runs_for(n), || {
            solve_dead_load(&problem, &LimitSettings::default())
        });
        let assembly = LimitSettings {
            formulation: Formulation::Assembly,
            ..LimitSettings::default()
        };
        let (ms_assembly, _) = time(runs_for(n).min(5), || solve_dead_load(&problem, &assembly));
        println!(
            "| {n} | {} | {ms:.2} ms | {ms_assembly:.1} ms |",
            s.load_factor.unwrap()
        );
    }
    println!("\n### Solver tolerance against error in λ and time (live load, N = 1800)\n");
    let tight = live_factor(
        1800,
        &LimitSettings {
            tolerance: 1e-12,
            ..LimitSettings::default()
        },
    );
    println!("| tolerance | λ | relative error to tolerance 1e-12 | time |");
    println!("|---|---|---|---|");
    for tolerance in [1e-4, 1e-6, 1e-8, 1e-10] {
        let settings = LimitSettings {
            tolerance,
            ..LimitSettings::default()
        };
        let (ms, lambda) = time(11, || live_factor(1800, &settings));
        println!(
            "| {tolerance:.0e} | {lambda:.9} | {:.1e} | {ms:.2} ms |",
            (lambda - tight).abs() / tight
        );
    }
    println!("\n### Slope: Spencer's F against the number of slices (Spencer's 1967 example)\n");
    let converged = spencer(20000);
    println!("Reference: N = 20000, F = {converged:.7}.\n");
    println!("| slices | F | error | time |");
    println!("|---|---|---|---|");
    for n in [10, 20, 50, 100, 200, 500, 1000, 5000] {
        let (ms, f) = time(runs_for(n), || spencer(n));
        println!("| {n} | {f:.6} | {:+.1e} | {:.3} ms |", f - converged, ms);
    }
    println!(
        "\n### Slope: critical F against the search grid (Spencer's example soil, 50 slices)\n"
    );
    let best = critical(81, true);
    println!("Reference: 81 × 81 grid with refinement, F = {best:.6}.\n");
    println!("| grid | F (grid only) | error | time | F (grid + refinement) | error | time |");
    println!("|---|---|---|---|---|---|---|");
    for n in [5, 11, 21, 41, 81] {
        let (ms_grid, f_grid) = time(5, || critical(n, false));
        let (ms, f) = time(5, || critical(n, true));
        println!("| {n} × {n} | {f_grid:.6} | {:+.1e} | {ms_grid:.1} ms | {f:.6} | {:+.1e} | {ms:.1} ms |", f_grid - best, f - best);
    }
}
