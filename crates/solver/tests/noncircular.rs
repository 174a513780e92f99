//! The non-circular search on a slope over a thin weak layer (model §4.4).
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::budget::Budget;
use thrustline_solver::slope::section::noncircular::{search_noncircular, NoncircularLimits};
use thrustline_solver::slope::section::search::{
    search_circles, CircleRegion, CircleSearchSettings,
};
use thrustline_solver::slope::section::*;
use thrustline_solver::slope::{Seismic, Soil, SpencerSettings};

fn weak_layer_section() -> Section {
    let line = |p: &[(f64, f64)]| Polyline::new(p.to_vec()).unwrap();
    let soil = |c: f64, phi: f64| Soil::new(19.0, c, phi, 0.0).unwrap();
    Section::new(SectionParts {
        ground: line(&[(0.0, 0.0), (20.0, 0.0), (40.0, 10.0), (80.0, 10.0)]),
        layers: vec![
            Layer {
                top: None,
                soil: soil(10.0, 30.0),
                pore_pressure_ratio: None,
                strength: thrustline_solver::slope::strength::Strength::MohrCoulomb,
                piezometric_line: None,
            },
            Layer {
                top: Some(line(&[(0.0, 1.0), (80.0, 1.0)])),
                soil: soil(1.0, 8.0),
                pore_pressure_ratio: None,
                strength: thrustline_solver::slope::strength::Strength::MohrCoulomb,
                piezometric_line: None,
            },
            Layer {
                top: Some(line(&[(0.0, 0.5), (80.0, 0.5)])),
                soil: soil(10.0, 30.0),
                pore_pressure_ratio: None,
                strength: thrustline_solver::slope::strength::Strength::MohrCoulomb,
                piezometric_line: None,
            },
        ],
        bedrock: None,
        piezometric_line: None,
        water_unit_weight: 9.81,
        surcharges: Vec::new(),
        line_loads: Vec::new(),
        tension_crack: None,
        supports: Vec::new(),
        water: Default::default(),
    })
    .unwrap()
}

#[test]
fn a_weak_layer_draws_the_critical_surface_along_it() {
    // The best circle cannot follow a thin weak layer (c' = 1, φ' = 8° between y = 0.5 and 1,
    // stronger soil above and below); the polyline search from it can, and must find a much
    // lower F — re-solved independently at 200 slices with the full solver, the same F to 1 %.
    let section = weak_layer_section();
    let slices = NonZeroUsize::new(50).unwrap();
    let circle = search_circles(
        &section,
        &CircleRegion::automatic(&section, 21, 21, 10),
        false,
        slices,
        Seismic::default(),
        &CircleSearchSettings::default(),
        &Budget::unlimited(),
    );
    let f_circle = circle.factor_of_safety.unwrap();
    let ((xc, yc), r) = circle.circle.unwrap();
    let start = SectionProblem::new(
        section.clone(),
        SlipShape::Circle {
            centre: (xc, yc),
            radius: r,
        },
        NonZeroUsize::new(200).unwrap(),
        Seismic::default(),
        None,
    )
    .unwrap()
    .surface();
    let found = search_noncircular(
        &section,
        &start,
        NoncircularLimits {
            vertices: 12,
            max_evaluations: None,
            min_depth: 0.0,
            beyond_ground: false,
        },
        slices,
        Seismic::default(),
        &SpencerSettings::default(),
        &Budget::unlimited(),
    )
    .unwrap();
    let f = found.factor_of_safety;
    assert!(f < 0.9 * f_circle, "non-circular {f} vs circle {f_circle}");
    assert!(found.path.windows(2).all(|w| w[1] <= w[0]));
    let in_layer = found
        .surface
        .iter()
        .filter(|p| (0.4..=1.1).contains(&p.1))
        .count();
    assert!(in_layer >= 3, "{:?}", found.surface);
    let check = SectionProblem::new(
        section,
        SlipShape::Polyline(Polyline::new(found.surface.clone()).unwrap()),
        NonZeroUsize::new(200).unwrap(),
        Seismic::default(),
        None,
    )
    .unwrap();
    let again = thrustline_solver::slope::solve_spencer(check.model(), &SpencerSettings::default());
    let g = again.factor_of_safety.unwrap();
    assert!((g - f).abs() < 1e-2 * f, "{g} vs {f}");
}
