//! The 3-layer section search of docs/performance.md (50 × 50 centres × 10 radii, 50 slices)
//! timed on the solver alone, for profiling: `cargo run --release -p thrustline-solver
//! --example section_search [repeats]`.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;
use std::time::Instant;

use thrustline_solver::budget::Budget;
use thrustline_solver::slope::section::search::{
    search_circles, CircleRegion, CircleSearchSettings,
};
use thrustline_solver::slope::section::{Layer, Polyline, Section, SectionParts};
use thrustline_solver::slope::{Seismic, Soil};

fn line(points: &[(f64, f64)]) -> Polyline {
    Polyline::new(points.to_vec()).unwrap()
}

fn layer(top: Option<Polyline>, gamma: f64, c: f64, phi: f64) -> Layer {
    Layer {
        top,
        soil: Soil::new(gamma, c, phi, 0.0).unwrap(),
        pore_pressure_ratio: None,
        strength: thrustline_solver::slope::strength::Strength::MohrCoulomb,
        piezometric_line: None,
    }
}

fn main() {
    let repeats: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5);
    let section = Section::new(SectionParts {
        ground: line(&[(-20.0, 0.0), (0.0, 0.0), (20.0, 10.0), (40.0, 10.0)]),
        layers: vec![
            layer(None, 19.0, 10.0, 28.0),
            layer(Some(line(&[(-20.0, -3.0), (40.0, -3.0)])), 20.0, 0.0, 35.0),
            layer(Some(line(&[(-20.0, -6.0), (40.0, -8.0)])), 21.0, 20.0, 25.0),
        ],
        bedrock: None,
        piezometric_line: Some(line(&[(-20.0, 1.0), (10.0, 3.0), (40.0, 6.0)])),
        water_unit_weight: 9.81,
        surcharges: Vec::new(),
        line_loads: Vec::new(),
        tension_crack: None,
        supports: Vec::new(),
        water: Default::default(),
    })
    .unwrap();
    for _ in 0..repeats {
        let start = Instant::now();
        let found = search_circles(
            &section,
            &CircleRegion::automatic(&section, 50, 50, 10),
            false,
            NonZeroUsize::new(50).unwrap(),
            Seismic::default(),
            &CircleSearchSettings::default(),
            &Budget::unlimited(),
        );
        println!(
            "{:.1} ms  F = {:?}  circle {:?}  evaluations {}  unsolved {}  regrids {}",
            start.elapsed().as_secs_f64() * 1e3,
            found.factor_of_safety,
            found.circle,
            found.evaluations,
            found.unsolved,
            found.regrids
        );
    }
}
