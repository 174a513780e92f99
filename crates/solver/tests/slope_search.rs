//! The critical slip circle and the loads of Spencer's method, against Spencer's example, closed
//! forms (the infinite slope) and Taylor's (1937) stability numbers.
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::budget::Budget;
use thrustline_solver::reference::spencer_1967;
use thrustline_solver::slope::*;

fn problem(height: f64, length: f64, soil: Soil, slices: usize) -> SearchProblem {
    SearchProblem {
        embankment: Embankment::new(height, length).unwrap(),
        slices: NonZeroUsize::new(slices).unwrap(),
        soil,
        seismic: Seismic::default(),
        lower_end_factor: 0.0,
        lower_end_factor_max: None,
    }
}

fn spencer_soil() -> Soil {
    spencer_1967::soil(spencer_1967::UNIT_WEIGHT)
}

fn circle(x: f64, y: f64) -> SlipCircle {
    SlipCircle {
        x,
        y,
        lower_end_factor: 0.0,
    }
}

#[test]
fn spencer_example_circle_lies_in_the_valley_of_the_contour_map() {
    // model §2.3: contours roughly elliptical, the critical centre near the perpendicular bisector
    // of the slope on its uphill side; Spencer's circle (X = 31.6 ft, Y = 209.2 ft) near it.
    let p = problem(
        spencer_1967::HEIGHT,
        spencer_1967::LENGTH,
        spencer_soil(),
        50,
    );
    let grid = SearchGrid {
        x_min: -30.0,
        x_max: 40.0,
        y_min: 30.0,
        y_max: 130.0,
        nx: 36,
        ny: 51,
    };
    let s = search_critical_circle(&p, grid, &SearchSettings::default(), &Budget::unlimited());
    let f_min = s.factor_of_safety.unwrap();
    let critical = s.circle.unwrap();
    assert!(!s.is_on_edge);
    let spencer =
        factor_of_safety(&p, spencer_1967::circle(), &SpencerSettings::default()).unwrap();
    // Spencer's circle is within 6 % of the minimum: in the valley, not on its flanks.
    assert!(
        spencer >= f_min && spencer - f_min < 0.06 * f_min,
        "{spencer} vs {f_min}"
    );
    // The critical centre lies within 15 % of the face length of the perpendicular bisector.
    let (h, l) = (spencer_1967::HEIGHT, spencer_1967::LENGTH);
    let face = h.hypot(l);
    let d = (critical.x - l / 2.0, critical.y - h / 2.0);
    let distance = (d.0 * l / face + d.1 * h / face).abs();
    assert!(
        distance < 0.15 * face,
        "{critical:?} is {distance} from the bisector"
    );
    // Every grid value is at least the refined minimum (1e-12: rounding).
    let grid_min = s
        .grid
        .factors
        .iter()
        .flatten()
        .flatten()
        .fold(f64::INFINITY, |m, f| m.min(*f));
    assert!(f_min <= grid_min + 1e-12);
}

#[test]
fn taylor_stability_numbers_for_toe_circles() {
    // Taylor (1937), φ = 0: c/(γ·H·F) at the critical toe circle is 0.181 at β = 53°, 0.191 at
    // 60° and 0.219 at 75°. His numbers have three digits from the friction-circle method:
    // 1 % relative.
    for (beta, taylor) in [(53.0f64, 0.181), (60.0, 0.191), (75.0, 0.219)] {
        let (h, c, gamma) = (10.0, 20.0, 10.0);
        let p = problem(
            h,
            h / beta.to_radians().tan(),
            Soil::new(gamma, c, 0.0, 0.0).unwrap(),
            100,
        );
        let grid = SearchGrid {
            nx: 41,
            ny: 41,
            ..SearchGrid::automatic(&p.embankment, 0.0)
        };
        let f = search_critical_circle(&p, grid, &SearchSettings::default(), &Budget::unlimited())
            .factor_of_safety
            .unwrap();
        let number = c / (gamma * h * f);
        assert!(
            (number - taylor).abs() < 0.01 * taylor,
            "β = {beta}°: {number} vs {taylor}"
        );
    }
}

#[test]
fn cohesionless_shallow_circle_tends_to_the_infinite_slope() {
    // c' = 0, dry: a shallow slide parallel to the face has F = tan φ'/tan β. A circle through
    // the toe and the crest corner with its centre far out on the perpendicular bisector is such
    // a slide; 1 % at a centre 100 face lengths away.
    let (h, l) = (10.0f64, 20.0f64);
    let soil = Soil::new(18.0, 0.0, 30.0, 0.0).unwrap();
    let p = problem(h, l, soil, 200);
    let infinite = 30f64.to_radians().tan() / (h / l);
    let face = h.hypot(l);
    let far = 100.0 * face;
    let centre = (l / 2.0 - far * h / face, h / 2.0 + far * l / face);
    let f = factor_of_safety(&p, circle(centre.0, centre.1), &SpencerSettings::default()).unwrap();
    assert!((f / infinite - 1.0).abs() < 0.01, "{f} vs {infinite}");
    // No circle does better than the infinite slope (0.5 %: slices and chords).
    let s = search_critical_circle(
        &p,
        SearchGrid::automatic(&p.embankment, 0.0),
        &SearchSettings::default(),
        &Budget::unlimited(),
    );
    assert!(
        s.factor_of_safety.unwrap() >= 0.995 * infinite,
        "{:?}",
        s.factor_of_safety
    );
}

fn spencer_example(seismic: Seismic, loads: Vec<ExternalLoad>) -> SlopeProblem {
    SlopeProblem::new(
        spencer_1967::embankment(),
        spencer_1967::circle(),
        NonZeroUsize::new(100).unwrap(),
        spencer_soil(),
        seismic,
        loads,
    )
    .unwrap()
}

fn f_of(p: &SlopeProblem) -> f64 {
    solve_spencer(&p.model(), &SpencerSettings::default())
        .factor_of_safety
        .unwrap()
}

#[test]
fn seismic_load_lowers_the_factor_of_safety() {
    let static_f = f_of(&spencer_example(Seismic::default(), vec![]));
    // k_h = 0 is the static answer (exactly: the same arithmetic).
    assert_eq!(
        f_of(&spencer_example(Seismic { kh: 0.0, kv: 0.0 }, vec![])),
        static_f
    );
    let mut previous = static_f;
    for kh in [0.05, 0.1, 0.2] {
        let f = f_of(&spencer_example(Seismic { kh, kv: 0.0 }, vec![]));
        assert!(f < previous, "k_h = {kh}: {f} ≥ {previous}");
        previous = f;
    }
}

#[test]
fn self_equilibrated_loads_change_nothing_and_a_surcharge_lowers_f() {
    let base = f_of(&spencer_example(Seismic::default(), vec![]));
    // A force and its opposite on the same slice: nothing changes (1e-12: rounding).
    let pair = |slice, fx, fy, moment| {
        vec![
            ExternalLoad {
                slice,
                fx,
                fy,
                moment,
                passive: false,
            },
            ExternalLoad {
                slice,
                fx: -fx,
                fy: -fy,
                moment: -moment,
                passive: false,
            },
        ]
    };
    let f = f_of(&spencer_example(
        Seismic::default(),
        pair(40, 150.0, -300.0, 75.0),
    ));
    assert!((f - base).abs() < 1e-12, "{f} vs {base}");
    // A downward load on the upper slices (where the base is steep) drives the slide.
    let surcharge: Vec<ExternalLoad> = (80..100)
        .map(|slice| ExternalLoad {
            slice,
            fx: 0.0,
            fy: -200.0,
            moment: 0.0,
            passive: false,
        })
        .collect();
    assert!(f_of(&spencer_example(Seismic::default(), surcharge)) < base);
}

#[test]
fn force_and_moment_curves_cross_at_the_answer() {
    // Spencer (1967), Fig. 3: F_f(θ) and F_m(θ) meet at (θ*, F*); 1e-9: root-finding tolerance.
    let p = spencer_example(Seismic::default(), vec![]);
    let s = solve_spencer(&p.model(), &SpencerSettings::default());
    let (f, theta) = (s.factor_of_safety.unwrap(), s.theta_rad.unwrap());
    let curves = factor_curves(&p.model(), vec![theta.to_degrees(), 0.0]);
    let (ff, fm) = (curves.force_factor[0], curves.moment_factor[0]);
    assert!((ff.unwrap() - f).abs() < 1e-9 && (fm.unwrap() - f).abs() < 1e-9);
    // At θ = 0 the moment curve is Bishop's simplified F.
    assert!((curves.moment_factor[1].unwrap() - s.bishop_factor_of_safety.unwrap()).abs() < 1e-12);
}

#[test]
fn searching_the_lower_end_too_never_does_worse() {
    let toe = problem(10.0, 10.0, Soil::new(18.0, 5.0, 20.0, 0.0).unwrap(), 50);
    let free = SearchProblem {
        lower_end_factor_max: Some(1.0),
        ..toe
    };
    let grid = SearchGrid::automatic(&toe.embankment, 0.0);
    let a = search_critical_circle(&toe, grid, &SearchSettings::default(), &Budget::unlimited());
    let b = search_critical_circle(
        &free,
        grid,
        &SearchSettings::default(),
        &Budget::unlimited(),
    );
    assert!(b.factor_of_safety.unwrap() <= a.factor_of_safety.unwrap() + 1e-12);
    let f_e = b.circle.unwrap().lower_end_factor;
    assert!((0.0..=1.0).contains(&f_e));
}

#[test]
fn a_search_past_its_time_limit_says_so() {
    let p = problem(
        spencer_1967::HEIGHT,
        spencer_1967::LENGTH,
        spencer_soil(),
        50,
    );
    let spent = Budget::with_time_limit(std::time::Duration::ZERO);
    let settings = SearchSettings::default();
    let s = search_critical_circle(
        &p,
        SearchGrid::automatic(&p.embankment, 0.0),
        &settings,
        &spent,
    );
    assert_eq!(s.status, SearchStatus::NoValidCircle);
    assert_eq!(s.stop, thrustline_solver::budget::Stop::TimeLimit);
    assert!(s.grid.factors.iter().flatten().all(Option::is_none));
}

#[test]
fn undrained_circle_without_parallel_forces_reports_the_moment_f() {
    // φ' = 0, centre straight above the toe: F_f(θ) > F_m for every θ (no Spencer solution),
    // but moment equilibrium alone fixes F. Independent check: with φ' = 0, F = Σ c'·l·d /
    // Σ W·(x_c − x_b)… computed here from the slices: resisting moment of c'·l at the chord
    // distance d over the driving moment of the weights about the centre (1e-9 relative).
    let (h, c, gamma) = (10.0, 19.497667133576616, 10.0);
    let p = SlopeProblem::new(
        Embankment::new(h, 13.44183509448031).unwrap(),
        SlipCircle {
            x: 0.0,
            y: 11.50844243885352,
            lower_end_factor: 0.0,
        },
        NonZeroUsize::new(40).unwrap(),
        Soil::new(gamma, c, 0.0, 0.0).unwrap(),
        Seismic::default(),
        Vec::new(),
    )
    .unwrap();
    let s = solve_spencer(&p.model(), &SpencerSettings::default());
    assert_eq!(s.status, SpencerStatus::MomentOnly);
    assert!(s.theta_rad.is_none() && s.thrust_line.is_empty());
    let g = &p.geometry;
    let (mut resisting, mut driving) = (0.0, 0.0);
    for slice in &g.slices {
        let (xb, yb) = slice.base_middle;
        let (dx, dy) = (xb - g.centre.0, yb - g.centre.1);
        // Shear c·l along the chord (up the slope) about the centre, and the weight through
        // the base middle.
        let (sin_a, cos_a) = slice.base_inclination_rad.sin_cos();
        resisting += c * slice.base_length * (dx * sin_a - dy * cos_a);
        driving += gamma * slice.area * dx;
    }
    let by_hand = resisting / driving;
    let f = s.factor_of_safety.unwrap();
    assert!((f - by_hand).abs() < 1e-9 * by_hand, "{f} vs {by_hand}");
}

#[test]
fn a_neighbours_start_finds_the_same_root() {
    // A search starts each circle's Bishop F (Spencer's start) from a neighbour's F: the root
    // must be the one found without it, to rounding (1e-13; the equations are solved to
    // 1e-12 in the step, quadratically closer in F), whatever the neighbour's F — near
    // (±3 %), far (×0.5, ×2) or absurd (1e-5, 1e5: outside the admissible range, clamped).
    // Spencer's embankment, and the 10 × 10 slope of
    // `searching_the_lower_end_too_never_does_worse`, where circles have a second root with
    // every m_α positive that Newton's method reaches from a neighbour's (F, θ) (next to a
    // pole, θ = −53.5°, one base in tension: an artefact).
    let spencer = problem(
        spencer_1967::HEIGHT,
        spencer_1967::LENGTH,
        spencer_soil(),
        50,
    );
    let steep = problem(10.0, 10.0, Soil::new(18.0, 5.0, 20.0, 0.0).unwrap(), 50);
    let settings = SpencerSettings::default();
    let mut compared = 0;
    for (p, scale) in [(spencer, 1.0), (steep, 10.0 / spencer_1967::HEIGHT)] {
        for (i, j) in (0..9).flat_map(|i| (0..9).map(move |j| (i, j))) {
            let c = circle(
                scale * (-20.0 + 7.0 * f64::from(i)),
                scale * (40.0 + 15.0 * f64::from(j)),
            );
            let Ok(at) = p.at(c) else { continue };
            let alone = spencer_factor_outcome(at.model(), &settings);
            let FactorOutcome::Solved(alone) = alone else {
                continue;
            };
            let f = alone.factor_of_safety;
            for near in [f * 1.03, f * 0.97, f * 0.5, f * 2.0, 1e-5, 1e5] {
                match spencer_factor_outcome_near(at.model(), &settings, Some(near)) {
                    FactorOutcome::Solved(s) => {
                        assert!(
                            (s.factor_of_safety - f).abs() <= 1e-13 * f,
                            "{c:?} from {near}: {} against {f}",
                            s.factor_of_safety
                        );
                        compared += 1;
                    }
                    other => panic!("{c:?} from {near}: {other:?} against {f}"),
                }
            }
        }
    }
    // Most of the 2 × 81 centres give circles with a solution.
    assert!(compared >= 6 * 120, "{compared}");
}
