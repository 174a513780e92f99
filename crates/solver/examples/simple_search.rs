//! The simple embankment's 50 × 50 search of docs/performance.md (Spencer's example with
//! r_u = 0.5, 50 slices, automatic bounds, min_depth 2 % of H) timed on the solver alone:
//! `cargo run --release -p thrustline-solver --example simple_search [repeats]`.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;
use std::time::Instant;

use thrustline_solver::budget::Budget;
use thrustline_solver::slope::search::{
    search_critical_circle, SearchGrid, SearchProblem, SearchSettings,
};
use thrustline_solver::slope::{Embankment, Seismic, Soil};

fn main() {
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5);
    let embankment = Embankment::new(30.48, 60.96).unwrap();
    let problem = SearchProblem {
        embankment,
        slices: NonZeroUsize::new(50).unwrap(),
        soil: Soil::new(10.0, 6.096, 40.0, 0.5).unwrap(),
        seismic: Seismic::default(),
        lower_end_factor: 0.0,
        lower_end_factor_max: None,
    };
    let grid = SearchGrid {
        nx: 50,
        ny: 50,
        ..SearchGrid::automatic(&embankment, 0.0)
    };
    let size = embankment.height().max(embankment.length());
    let settings = SearchSettings {
        max_radius: Some(50.0 * size),
        min_depth: 0.02 * embankment.height(),
        ..SearchSettings::default()
    };
    for _ in 0..repeats {
        let start = Instant::now();
        let found = search_critical_circle(&problem, grid, &settings, &Budget::unlimited());
        println!(
            "{:.2} ms  F = {:?}  circle {:?}  evaluations {}  unsolved {}  regrids {}",
            start.elapsed().as_secs_f64() * 1e3,
            found.factor_of_safety,
            found.circle.map(|c| (c.x, c.y)),
            found.evaluations,
            found.unsolved,
            found.regrids
        );
    }
}
