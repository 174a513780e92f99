use std::num::NonZeroUsize;

use super::*;
use crate::reference::spencer_1967;
use crate::slope::{Embankment, SlipCircle, SlopeError, SlopeParameter};

/// Spencer (1967) example with the unit weight and the cohesion scaled.
fn spencer_example(n: usize, unit_weight: f64, cohesion_scale: f64) -> SlopeProblem {
    SlopeProblem::new(
        spencer_1967::embankment(),
        spencer_1967::circle(),
        NonZeroUsize::new(n).unwrap(),
        Soil::new(
            unit_weight,
            spencer_1967::COHESION_RATIO * unit_weight * spencer_1967::HEIGHT * cohesion_scale,
            spencer_1967::FRICTION_ANGLE_DEG,
            spencer_1967::PORE_PRESSURE_RATIO,
        )
        .unwrap(),
        Seismic::default(),
        Vec::new(),
    )
    .unwrap()
}

fn solve(p: &SlopeProblem) -> (f64, f64, SpencerSolution) {
    let s = solve_spencer(&p.model(), &SpencerSettings::default());
    assert_eq!(s.status, SpencerStatus::Converged);
    (
        s.factor_of_safety.unwrap(),
        s.theta_rad.unwrap().to_degrees(),
        s,
    )
}

#[test]
fn spencer_1967_example_converged() {
    // Spencer (1967) example, converged F = 1.0695, θ = 22.43° (model §2.3); ±2e-4, ±0.01°.
    for n in [500, 1000] {
        let (f, theta, _) = solve(&spencer_example(n, 10.0, 1.0));
        assert!((f - 1.0695).abs() < 2e-4, "N = {n}: F = {f}");
        assert!((theta - 22.43).abs() < 0.01, "N = {n}: θ = {theta}");
    }
}

#[test]
fn thesis_table_of_f_against_number_of_slices() {
    // Thesis §5.6, F and θ for N = 10 … 1000, printed to 5 and 3 decimals: half a unit in
    // the last printed digit.
    let table = [
        (10, 1.07188, 22.735),
        (20, 1.07068, 22.491),
        (50, 1.06974, 22.439),
        (100, 1.06958, 22.432),
        (200, 1.06954, 22.431),
        (500, 1.06952, 22.430),
        (1000, 1.06952, 22.430),
    ];
    for (n, f_ref, theta_ref) in table {
        let (f, theta, _) = solve(&spencer_example(n, 10.0, 1.0));
        assert!(
            (f - f_ref).abs() <= 5e-6,
            "N = {n}: F = {f}, thesis {f_ref}"
        );
        assert!(
            (theta - theta_ref).abs() <= 5e-4,
            "N = {n}: θ = {theta}, thesis {theta_ref}"
        );
    }
}

#[test]
fn bishop_simplified_for_the_spencer_circle() {
    // model §2.3: Bishop's simplified F for the same circle ≈ 1.040 (1.0397 to 4 decimals).
    let (_, _, s) = solve(&spencer_example(1000, 10.0, 1.0));
    let bishop = s.bishop_factor_of_safety.unwrap();
    assert!((bishop - 1.0397).abs() < 1e-4, "Bishop F = {bishop}");
}

#[test]
fn f_depends_on_cohesion_and_unit_weight_only_through_their_ratio() {
    // model §2.3: scaling c' and γ together leaves F and θ unchanged (1e-10: rounding).
    let (f1, t1, _) = solve(&spencer_example(200, 10.0, 1.0));
    for gamma in [1e-6, 1.0, 18.5, 1e6] {
        let (f, t, _) = solve(&spencer_example(200, gamma, 1.0));
        assert!((f - f1).abs() < 1e-10 * f1, "γ = {gamma}: {f} vs {f1}");
        assert!((t - t1).abs() < 1e-8, "γ = {gamma}: {t} vs {t1}");
    }
    // And doubling c' alone does change it (upwards).
    let (f2, _, _) = solve(&spencer_example(200, 10.0, 2.0));
    assert!(f2 > f1 + 0.01);
}

#[test]
fn f_converges_as_slices_are_added() {
    // Chords cut the arc with an error O(N⁻²); the slices that straddle the kinks of the
    // ground add a wobble of the same order. For this circle |F_N − F_4000|·N² stays below
    // 1 from N = 10 on (0.46 at N = 20, 0.67 at N = 320).
    let (converged, _, _) = solve(&spencer_example(4000, 10.0, 1.0));
    for n in [10, 20, 40, 80, 160, 320, 640] {
        let (f, _, _) = solve(&spencer_example(n, 10.0, 1.0));
        let error = (f - converged).abs();
        assert!(
            error * (n * n) as f64 <= 1.0,
            "N = {n}: F = {f}, error {error}"
        );
    }
}

#[test]
fn returned_forces_satisfy_both_equilibrium_equations() {
    // Independent check of the solution: resolve every slice's forces (W, N, S, Q) in x and
    // y, and sum the moments about the centre. 1e-9 of the total weight: rounding.
    let p = spencer_example(100, 10.0, 1.0);
    let (_, theta, s) = solve(&p);
    let theta = theta.to_radians();
    let total_weight: f64 = s.slice_forces.iter().map(|f| f.weight).sum();
    for (slice, forces) in p.geometry.slices.iter().zip(&s.slice_forces) {
        let (sin_a, cos_a) = slice.base_inclination_rad.sin_cos();
        // Normal N along (−sin α, cos α), shear S up the slope along (cos α, sin α).
        let fx = -forces.normal_force * sin_a
            + forces.shear_force * cos_a
            + forces.interslice_resultant * theta.cos();
        let fy = -forces.weight
            + forces.normal_force * cos_a
            + forces.shear_force * sin_a
            + forces.interslice_resultant * theta.sin();
        assert!(fx.abs() < 1e-9 * total_weight, "fx = {fx}");
        assert!(fy.abs() < 1e-9 * total_weight, "fy = {fy}");
    }
    let sum_q: f64 = s.slice_forces.iter().map(|f| f.interslice_resultant).sum();
    assert!(sum_q.abs() < 1e-9 * total_weight);
    // The inter-slice force dies out at the upper exit and the thrust line is inside the
    // mass over the bulk of the slices (Spencer 1973: near the lower third point).
    let last = s.slice_forces.last().unwrap();
    assert_eq!(last.interslice_force_right, 0.0);
    let inside = s.thrust_line.iter().filter(|t| t.is_inside_slice).count();
    assert!(
        inside * 10 >= s.thrust_line.len() * 9,
        "{inside} of {}",
        s.thrust_line.len()
    );
}

#[test]
fn thrust_line_near_lower_third_point() {
    // Spencer (1967): the line of thrust passes close to the lower third point of the
    // inter-slice boundaries. Check the middle half of the boundaries lies within the lower
    // 0.2–0.45 of the boundary height.
    let p = spencer_example(200, 10.0, 1.0);
    let (_, _, s) = solve(&p);
    let n = s.thrust_line.len();
    for t in &s.thrust_line[n / 4..3 * n / 4] {
        let slice = &p.geometry.slices[t.boundary - 1];
        let top = p.geometry.embankment.ground(t.x);
        let ratio = (t.y.unwrap() - slice.base_right_y) / (top - slice.base_right_y);
        assert!(
            (0.2..0.45).contains(&ratio),
            "boundary {}: {ratio}",
            t.boundary
        );
    }
}

#[test]
fn one_slice_is_solved_or_reported_honestly() {
    // N = 1: a single slice cannot satisfy both equations unless Q = 0; whatever the status,
    // a converged answer must satisfy the equations.
    let s = solve_spencer(
        &spencer_example(1, 10.0, 1.0).model(),
        &SpencerSettings::default(),
    );
    match s.status {
        SpencerStatus::Converged => assert!(s.residual.unwrap() < 1e-9),
        SpencerStatus::NoSolution | SpencerStatus::Unphysical => {
            assert!(s.factor_of_safety.is_none())
        }
        // φ' = 40° here: the moment-only answer is for φ' = 0 alone.
        SpencerStatus::MomentOnly => panic!("moment-only answer with friction"),
    }
}

#[test]
fn soil_without_strength_is_rejected() {
    assert!(matches!(
        Soil::new(10.0, 0.0, 0.0, 0.0),
        Err(SlopeError::OutOfRange {
            parameter: SlopeParameter::Cohesion,
            ..
        })
    ));
    assert!(Soil::new(10.0, 1.0, 90.0, 0.0).is_err());
    assert!(Soil::new(10.0, 1.0, 30.0, 1.5).is_err());
    assert!(Soil::new(-1.0, 1.0, 30.0, 0.0).is_err());
}

/// Issue #15's steep slope with r_u = 0.5: a 2:1e-9 (vertical) face 30.48 high, the circle
/// through the toe with centre (−62.509, 62.072) from it.
fn vertical_face_with_high_pore_pressure() -> SlopeProblem {
    SlopeProblem::new(
        Embankment::new(30.48, 1e-9).unwrap(),
        SlipCircle {
            x: -62.509252886075785,
            y: 62.071731840088276,
            lower_end_factor: 0.0,
        },
        std::num::NonZeroUsize::new(50).unwrap(),
        Soil::new(10.0, 18.58, 40.0, 0.5).unwrap(),
        Seismic::default(),
        Vec::new(),
    )
    .unwrap()
}

#[test]
fn a_root_held_up_by_tension_is_not_converged() {
    // The classic equations have a root F ≈ 2e-15 there with every slice in tension: reported
    // as unphysical, with no F.
    let s = solve_spencer(
        &vertical_face_with_high_pore_pressure().model(),
        &SpencerSettings::default(),
    );
    assert_eq!(
        s.status,
        SpencerStatus::Unphysical,
        "{:?}",
        s.factor_of_safety
    );
    assert!(s.factor_of_safety.is_none());
    assert!(s.unphysical_root.is_some_and(|f| f < 1e-3));
}

#[test]
fn dropping_friction_in_tension_gives_the_cohesive_answer() {
    // With the frictional term dropped where N' < 0 (c' kept), the mass is held by cohesion
    // (and friction where the base is in compression): a physical F, no frictional slice left
    // in tension. Dropping c' as well on those slices can only lower F.
    let model = vertical_face_with_high_pore_pressure().model();
    let settings = SpencerSettings {
        negative_effective_stress: NegativeEffectiveStress::DropFriction,
        ..SpencerSettings::default()
    };
    let s = solve_spencer(&model, &settings);
    let f = s.factor_of_safety.unwrap();
    assert!(f > 0.1 && f < 10.0, "F = {f}");
    assert!(!s.tension_dropped_slices.is_empty());
    for &i in &s.negative_effective_normal_slices {
        assert!(
            s.tension_dropped_slices.contains(&i),
            "slice {i} in tension with friction"
        );
    }
    let settings = SpencerSettings {
        negative_effective_stress: NegativeEffectiveStress::DropStrength,
        ..SpencerSettings::default()
    };
    let weaker = solve_spencer(&model, &settings);
    if let Some(g) = weaker.factor_of_safety {
        assert!(g <= f * (1.0 + 1e-9), "{g} > {f}");
    }
    // Spencer's own example keeps its published F under the default treatment.
    let classic = solve_spencer(
        &spencer_example(100, 10.0, 1.0).model(),
        &SpencerSettings::default(),
    );
    assert!((classic.factor_of_safety.unwrap() - 1.06958).abs() < 5e-6);
}

#[test]
fn the_effective_line_of_thrust_is_the_total_less_the_side_water() {
    // Dry (r_u = 0): no water on the boundaries, the two lines coincide. With r_u = 0.5 the
    // side water is ½·r_u·γ·h² at h/3 above the base (by hand at one boundary) and the effective
    // point balances the horizontal moments: Z cos θ·y = E'·y' + U·y_U.
    let dry = solve_spencer(
        &spencer_example(100, 10.0, 1.0).model(),
        &SpencerSettings::default(),
    );
    let mut wet_problem = spencer_example(100, 10.0, 1.0);
    wet_problem.soil = Soil::new(10.0, 6.096, 40.0, 0.0).unwrap();
    let dry_no_water = solve_spencer(&wet_problem.model(), &SpencerSettings::default());
    for (t, e) in dry_no_water
        .thrust_line
        .iter()
        .zip(&dry_no_water.effective_thrust_line)
    {
        let (a, b) = (t.y.unwrap(), e.y.unwrap());
        assert!((a - b).abs() <= 1e-12 * a.abs().max(1.0), "{a} vs {b}");
    }
    let p = spencer_example(100, 10.0, 1.0);
    let g = &p.geometry;
    let cos_t = dry.theta_rad.unwrap().cos();
    let i = 40;
    let (t, e) = (&dry.thrust_line[i], &dry.effective_thrust_line[i]);
    let slice = &g.slices[i];
    let h = g.embankment.ground(slice.x_right) - slice.base_right_y;
    let water = 0.5 * 0.5 * 10.0 * h * h;
    let y_water = slice.base_right_y + h / 3.0;
    let horizontal = t.force * cos_t - water;
    let by_hand = (t.force * cos_t * t.y.unwrap() - water * y_water) / horizontal;
    assert!((e.y.unwrap() - by_hand).abs() < 1e-9 * by_hand.abs().max(1.0));
}

/// The first crossing of a scan that evaluates all 49 samples, written out.
fn full_scan(e: &Equations, theta: f64, moment: bool) -> Option<(f64, f64, f64, f64)> {
    let (lo, hi) = e.admissible_f(theta)?;
    let residual = |f: f64| {
        let r = e.evaluate(f, theta);
        if moment {
            r.moment
        } else {
            r.force
        }
    };
    let ratio = (hi / lo).powf(1.0 / 48.0);
    let (mut a, mut fa) = (lo, residual(lo));
    for i in 1..=48 {
        let b = if i == 48 { hi } else { lo * ratio.powi(i) };
        let fb = residual(b);
        if fa.is_finite() && fb.is_finite() && fa < 0.0 && fb >= 0.0 {
            return Some((a, fa, b, fb));
        }
        (a, fa) = (b, fb);
    }
    None
}

#[test]
fn bounded_scan_finds_the_full_scans_crossing_bit_for_bit() {
    // Spencer's example with weak to strong soils and dry to saturated pore pressures, at θ
    // from −85° to 85°: crossings, curves that do not exist and curves with poles.
    let (mut cases, mut samples, mut crossings) = (0, 0, 0);
    for (c_scale, phi, ru) in [
        (1.0, 40.0, 0.5),
        (0.0, 40.0, 0.0),
        (3.0, 10.0, 0.9),
        (0.2, 5.0, 0.0),
    ] {
        let problem = SlopeProblem::new(
            spencer_1967::embankment(),
            spencer_1967::circle(),
            NonZeroUsize::new(50).unwrap(),
            Soil::new(20.0, c_scale * 0.02 * 20.0 * 10.0, phi, ru).unwrap(),
            Seismic::default(),
            Vec::new(),
        )
        .unwrap();
        let e = Equations::new(&problem.model());
        for k in -17..=17 {
            let theta = (5.0 * f64::from(k)).to_radians();
            for moment in [false, true] {
                let Some(range) = e.admissible_f(theta) else {
                    continue;
                };
                let mut scan = e.scan(theta, moment, range);
                let found = scan.first_crossing();
                crossings += usize::from(found.is_some());
                assert_eq!(
                    found,
                    full_scan(&e, theta, moment),
                    "θ = {}°, moment {moment}",
                    5 * k
                );
                cases += 1;
                samples += scan.evaluations;
            }
        }
    }
    // Both kinds of answer occur.
    assert!(
        cases > 200 && crossings > 20 && crossings < cases - 20,
        "{crossings}/{cases}"
    );
    // The bounds settle most stretches: far fewer samples than 49 a scan.
    assert!(samples < cases * 20, "{samples} samples for {cases} scans");
}

#[test]
fn what_drives_a_mass_is_summed_without_the_vector_of_terms_bit_for_bit() {
    // The check made while placing a search's surfaces, against the same sums over the
    // equations' slice terms: the same two numbers to the bit, with and without seismic
    // coefficients, and with known loads (which take the vector's path).
    let loads = vec![
        ExternalLoad {
            slice: 3,
            fx: 12.5,
            fy: -40.0,
            moment: 2.0,
            passive: false,
        },
        ExternalLoad {
            slice: 3,
            fx: -1.0,
            fy: -3.0,
            moment: 0.0,
            passive: true,
        },
    ];
    for (n, seismic, loads) in [
        (7, Seismic::default(), Vec::new()),
        (50, Seismic::default(), Vec::new()),
        (50, Seismic::new(0.15, -0.05).unwrap(), Vec::new()),
        (20, Seismic::new(0.1, 0.0).unwrap(), loads),
    ] {
        let p = spencer_example(n, 10.0, 1.0);
        let p = SlopeProblem::new(
            spencer_1967::embankment(),
            spencer_1967::circle(),
            NonZeroUsize::new(n).unwrap(),
            p.soil,
            seismic,
            loads,
        )
        .unwrap();
        let model = p.model();
        let (driving, size) = methods::model_moments(&model);
        let (expected_driving, expected_size) =
            methods::ordinary_moments(equations::Equations::slice_terms(&model).0);
        assert_eq!(driving.to_bits(), expected_driving.to_bits(), "n = {n}");
        assert_eq!(size.to_bits(), expected_size.to_bits(), "n = {n}");
        assert!(driving < 0.0 && methods::model_drives(&model));
    }
}

#[test]
fn a_neighbours_start_finds_the_same_roots_and_reports_bishop_settled() {
    // A 76° face 10 high (c' = 20, φ' = 30°; tests/http_honest.rs): near its critical circle
    // many circles have no Spencer root, and whether one has can turn on rounding. Over a field
    // of circles through the toe, started as in a search from a neighbour's F 3 % away
    // (Bishop's F, Spencer's start, settled from there) and without one: the same root to
    // rounding where there is one, and where there is none the same Bishop F, as reported.
    // (With Bishop's F settled only to a relative step of 1e-3, ~2e-7 from it, the search of
    // that test chose a circle on which Spencer's equations, solved alone, have no root.)
    let settings = SpencerSettings::default();
    let (mut solved, mut unsolved) = (0, 0);
    for i in 0..12 {
        for j in 0..12 {
            let Ok(problem) = SlopeProblem::new(
                Embankment::new(10.0, 2.5).unwrap(),
                SlipCircle {
                    x: -8.0 + 1.5 * f64::from(i),
                    y: 4.0 + 2.0 * f64::from(j),
                    lower_end_factor: 0.0,
                },
                NonZeroUsize::new(50).unwrap(),
                Soil::new(20.0, 20.0, 30.0, 0.0).unwrap(),
                Seismic::default(),
                Vec::new(),
            ) else {
                continue;
            };
            let equations = Equations::new(&problem.model());
            let alone = newton::solve_equations(&equations, &settings, None);
            let Some(bishop) = alone.bishop else {
                continue;
            };
            for near in [1.03 * bishop, 0.97 * bishop] {
                let started = newton::solve_equations(&equations, &settings, Some(near));
                match (alone.root, started.root) {
                    (Some((f, theta)), Some((f_near, theta_near))) => {
                        assert!(
                            (f_near - f).abs() <= 1e-13 * f
                                && (theta_near - theta).abs() <= 1e-11,
                            "({i}, {j}): ({f}, {theta}) alone, ({f_near}, {theta_near}) from {near}"
                        );
                        solved += 1;
                    }
                    (None, None) => {
                        let reported = started.bishop.unwrap();
                        assert!(
                            (reported - bishop).abs() <= 1e-14 * bishop,
                            "({i}, {j}): Bishop {bishop} alone, {reported} from {near}"
                        );
                        unsolved += 1;
                    }
                    (alone, started) => {
                        panic!("({i}, {j}): {alone:?} alone, {started:?} from {near}")
                    }
                }
            }
        }
    }
    assert!(
        solved > 100 && unsolved >= 6,
        "{solved} solved, {unsolved} unsolved"
    );
}
