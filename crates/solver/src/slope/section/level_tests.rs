//! The section's lines as the slices read them: ponded stretches, the level table and the
//! reading of sections too large for one (against the polylines themselves).

use std::num::NonZeroUsize;

use super::column::Levels;
use super::model::LevelTable;
use super::tests::{line, one_soil};
use super::*;
use crate::slope::spencer::{solve_spencer, SpencerSettings};
use crate::slope::spencer::{Seismic, Soil};

#[test]
fn ponded_stretches_are_where_the_water_stands_above_the_ground() {
    // Slope (0, 10)–(20, 0), level beyond; water level at y = 4 in front, falling to 2 at
    // x = 40: above the ground from the water's crossing with the face (x = 12) onwards.
    let mut parts = one_soil(
        &[(-20.0, 10.0), (0.0, 10.0), (20.0, 0.0), (40.0, 0.0)],
        19.0,
        0.0,
        30.0,
    );
    parts.piezometric_line = Some(line(&[(-20.0, 4.0), (20.0, 4.0), (40.0, 2.0)]));
    let section = Section::new(parts.clone()).unwrap();
    // The crossing is a bend: the face is dry up to it, wet beyond.
    assert!(!section.is_ponded_over(11.0, 11.5));
    assert!(section.is_ponded_over(12.5, 13.0));
    assert!(section.is_ponded_over(30.0, 31.0));
    assert!(section.is_ponded_over(50.0, 60.0));
    assert!(!section.is_ponded_over(-15.0, -1.0));
    // Below the ground everywhere: nothing ponded.
    parts.piezometric_line = Some(line(&[(-20.0, -1.0), (40.0, -2.0)]));
    let dry = Section::new(parts).unwrap();
    assert!(!dry.is_ponded_over(-100.0, 100.0));
}

#[test]
fn levels_read_from_the_table_are_the_lines_heights() {
    let mut parts = one_soil(
        &[(-20.0, 10.0), (0.0, 10.0), (20.0, 0.0), (40.0, 0.0)],
        19.0,
        10.0,
        30.0,
    );
    let top = line(&[(-20.0, 2.0), (5.0, 3.0), (40.0, -4.0)]);
    parts.layers.push(Layer {
        top: Some(top.clone()),
        soil: Soil::new(20.0, 5.0, 25.0, 0.0).unwrap(),
        pore_pressure_ratio: None,
        strength: crate::slope::strength::Strength::MohrCoulomb,
        piezometric_line: None,
    });
    let water = line(&[(-20.0, 6.0), (30.0, 1.0)]);
    parts.piezometric_line = Some(water.clone());
    let section = Section::new(parts.clone()).unwrap();
    let mut levels = Levels::default();
    // Before, between and beyond every vertex and crossing.
    for k in 0..=140 {
        let x = -30.0 + 0.5 * f64::from(k);
        levels.read(&section, x);
        let expected = [parts.ground.y_at(x), top.y_at(x), water.y_at(x)];
        for (got, want) in levels.values().iter().zip(expected) {
            assert!((got - want).abs() <= 1e-12, "x = {x}: {got} against {want}");
        }
    }
    // Without a water line the last level is NaN.
    parts.piezometric_line = None;
    levels.read(&Section::new(parts).unwrap(), 3.0);
    assert!(levels.values()[2].is_nan());
}

/// The 3-layer section with a water table (the search of docs/performance.md), and the F of one circle on
/// it, its levels read from `section` as given.
fn layered_factor(section: Section, slices: usize) -> f64 {
    let problem = SectionProblem::new(
        section,
        SlipShape::Circle {
            centre: (5.0, 19.0),
            radius: 19.2,
        },
        NonZeroUsize::new(slices).unwrap(),
        Seismic::default(),
        None,
    )
    .unwrap();
    solve_spencer(problem.model(), &SpencerSettings::default())
        .factor_of_safety
        .unwrap()
}

fn three_layers() -> SectionParts {
    let mut parts = one_soil(
        &[(-20.0, 0.0), (0.0, 0.0), (20.0, 10.0), (40.0, 10.0)],
        19.0,
        10.0,
        28.0,
    );
    for (top, gamma, c, phi) in [
        (line(&[(-20.0, -3.0), (40.0, -3.0)]), 20.0, 0.0, 35.0),
        (line(&[(-20.0, -6.0), (40.0, -8.0)]), 21.0, 20.0, 25.0),
    ] {
        parts.layers.push(Layer {
            top: Some(top),
            soil: Soil::new(gamma, c, phi, 0.0).unwrap(),
            pore_pressure_ratio: None,
            strength: crate::slope::strength::Strength::MohrCoulomb,
            piezometric_line: None,
        });
    }
    parts.piezometric_line = Some(line(&[(-20.0, 1.0), (10.0, 3.0), (40.0, 6.0)]));
    parts
}

#[test]
fn levels_from_the_table_and_from_the_lines_give_one_factor() {
    let section = Section::new(three_layers()).unwrap();
    assert!(!section.levels.is_empty());
    let mut by_lines = section.clone();
    by_lines.levels = LevelTable::default();
    for slices in [7, 50, 200] {
        let (a, b) = (
            layered_factor(section.clone(), slices),
            layered_factor(by_lines.clone(), slices),
        );
        assert!(
            (a - b).abs() <= 1e-12 * a,
            "{slices} slices: {a} against {b}"
        );
    }
}

#[test]
fn a_section_too_large_for_a_table_reads_its_lines_one_by_one() {
    // 49 layer tops of 1000 vertices under a water line zigzagging across them: ~100,000 bends
    // × 51 lines would be 80 MB of table.
    let mut parts = one_soil(
        &[(-20.0, 0.0), (0.0, 0.0), (20.0, 10.0), (120.0, 10.0)],
        19.0,
        10.0,
        28.0,
    );
    for k in 0..49 {
        let depth = 1.0 + 0.2 * f64::from(k);
        let top: Vec<(f64, f64)> = (0..1000)
            .map(|i| {
                let wiggle = if i % 2 == 0 { 0.0 } else { 0.05 };
                (-20.0 + 0.14 * f64::from(i), -depth + wiggle)
            })
            .collect();
        parts.layers.push(Layer {
            top: Some(line(&top)),
            soil: Soil::new(20.0, 5.0, 30.0, 0.0).unwrap(),
            pore_pressure_ratio: None,
            strength: crate::slope::strength::Strength::MohrCoulomb,
            piezometric_line: None,
        });
    }
    let water: Vec<(f64, f64)> = (0..1000)
        .map(|i| {
            (
                -20.07 + 0.14 * f64::from(i),
                if i % 2 == 0 { 2.0 } else { -12.0 },
            )
        })
        .collect();
    parts.piezometric_line = Some(line(&water));
    let section = Section::new(parts.clone()).unwrap();
    assert!(section.levels.is_empty());
    let mut levels = Levels::default();
    for x in [-25.0, -3.3, 7.77, 50.0, 200.0] {
        levels.read(&section, x);
        assert_eq!(levels.values()[0], parts.ground.y_at(x));
        assert_eq!(levels.values()[50], line(&water).y_at(x));
    }
    let f = layered_factor(section, 50);
    assert!(f.is_finite() && f > 0.0, "F = {f}");
}

/// The column as the soil rule states it, with `f64::min`/`max` (what `column` computed before
/// it compared instead).
fn column_by_min_max(section: &Section, levels: &[f64], y: f64) -> (f64, f64) {
    let g = levels[0];
    let mut below = y;
    let (mut w, mut m) = (0.0, 0.0);
    for (layer, &top) in section.layers.iter().zip(levels).rev() {
        let upper = g.min(top);
        if upper > below {
            let gamma = layer.soil.unit_weight;
            w += gamma * (upper - below);
            m += gamma * 0.5 * (upper * upper - below * below);
        }
        below = below.max(top);
    }
    (w, m)
}

#[test]
fn the_column_by_comparisons_is_the_rule_with_min_and_max_bit_for_bit() {
    let section = Section::new(three_layers()).unwrap();
    // Levels above, at and below one another, signed zeros among them, and tops above the
    // ground (a layer cut off by it), for bases above, at and below every level.
    let values = [-7.5, -3.0, -0.0, 0.0, 1e-300, 2.25, 10.0];
    let mut compared = 0;
    for &g in &values {
        for &t1 in &values {
            for &t2 in &values {
                let levels = [g, t1, t2, f64::NAN];
                for &y in values.iter().chain(&[-20.0, 30.0]) {
                    let (w, m) = super::column::column(&section, &levels, y);
                    let (w0, m0) = column_by_min_max(&section, &levels, y);
                    assert_eq!(
                        (w.to_bits(), m.to_bits()),
                        (w0.to_bits(), m0.to_bits()),
                        "levels {levels:?}, y {y}"
                    );
                    compared += 1;
                }
            }
        }
    }
    assert_eq!(compared, 7 * 7 * 7 * 9);
}

#[test]
fn the_points_inside_each_slice_found_by_walking_are_those_a_search_finds() {
    use super::column::InnerPoints;
    let points = [-3.0, 0.0, 0.0, 1.5, 2.0, 7.25, 9.0];
    // Sides on points, between them, repeated (a slice of no width), beyond both ends.
    let sides = [
        -5.0, -3.0, -3.0, -1.0, 0.0, 0.5, 1.5, 1.75, 2.0, 7.0, 7.25, 9.0, 9.0, 12.0,
    ];
    let mut walk = InnerPoints::default();
    for w in sides.windows(2) {
        let (xl, xr) = (w[0], w[1]);
        let first = points.partition_point(|&p| p <= xl);
        let last = points.partition_point(|&p| p < xr);
        assert_eq!(
            walk.within(&points, (xl, xr)),
            &points[first..last.max(first)],
            "slice [{xl}, {xr}]"
        );
    }
    // No points: nothing inside any slice.
    let mut walk = InnerPoints::default();
    assert!(walk.within(&[], (0.0, 1.0)).is_empty());
}
