//! Strength and water models (model §8) against identities derived by hand: a power curve
//! with b = 1 and a two-point shear–normal function are Mohr–Coulomb; an undrained profile is
//! the limit of thin sublayers of constant strength; a grid sampled from a water line's
//! hydrostatic field is that line; a layer's own line is the section's line for that soil;
//! h_u scales the head. Nonlinear answers carry each base's envelope strength at its own σ′ₙ.
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::slope::section::{
    Hu, Layer, Polyline, PoreGrid, Section, SectionParts, SectionProblem, SlipShape, Water,
    WaterLine,
};
use thrustline_solver::slope::spencer::methods::{
    bishop, janbu, morgenstern_price, ordinary, InterSliceFunction,
};
use thrustline_solver::slope::strength::{Envelope, HoekBrown, Reference, Strength, Undrained};
use thrustline_solver::slope::*;

const GROUND: [(f64, f64); 4] = [(-20.0, 0.0), (0.0, 0.0), (20.0, 10.0), (50.0, 10.0)];
const CIRCLE: ((f64, f64), f64) = ((12.0, 22.0), 26.0);

fn line(points: &[(f64, f64)]) -> Polyline {
    Polyline::new(points.to_vec()).unwrap()
}

fn layer(top: Option<Polyline>, soil: Soil, strength: Strength) -> Layer {
    Layer {
        top,
        soil,
        pore_pressure_ratio: None,
        strength,
        piezometric_line: None,
    }
}

fn parts(layers: Vec<Layer>, piezometric_line: Option<Polyline>, water: Water) -> SectionParts {
    SectionParts {
        ground: line(&GROUND),
        layers,
        bedrock: None,
        piezometric_line,
        water_unit_weight: 9.81,
        surcharges: Vec::new(),
        line_loads: Vec::new(),
        tension_crack: None,
        supports: Vec::new(),
        water,
    }
}

fn problem(parts: SectionParts) -> SectionProblem {
    on(
        parts,
        SlipShape::Circle {
            centre: CIRCLE.0,
            radius: CIRCLE.1,
        },
    )
}

/// `shape` on the section of `parts`; a polyline takes moments about the circle's centre.
fn on(parts: SectionParts, shape: SlipShape) -> SectionProblem {
    let centre = matches!(shape, SlipShape::Polyline(_)).then_some(CIRCLE.0);
    SectionProblem::new(
        Section::new(parts).unwrap(),
        shape,
        NonZeroUsize::new(60).unwrap(),
        Seismic::default(),
        centre,
    )
    .unwrap()
}

/// Below the ground everywhere (no ponded water, which a grid or a layer's line do not give).
fn water_table() -> Option<Polyline> {
    Some(line(&[
        (-20.0, -2.0),
        (0.0, -0.5),
        (20.0, 5.0),
        (50.0, 6.0),
    ]))
}

/// Spencer's F and θ and the four other methods' F.
fn factors(p: &SectionProblem) -> Vec<f64> {
    let model = p.model();
    let s = solve_spencer(model, &SpencerSettings::default());
    assert!(s.strength.settled, "{:?}", s.strength);
    let (f, theta) = (s.factor_of_safety.unwrap(), s.theta_rad.unwrap());
    vec![
        f,
        theta,
        bishop(model).factor_of_safety.unwrap(),
        janbu(model).factor_of_safety.unwrap(),
        ordinary(model).factor_of_safety.unwrap(),
        morgenstern_price(model, &InterSliceFunction::HalfSine, (f, theta.tan()))
            .factor_of_safety
            .unwrap(),
    ]
}

fn assert_close(a: &[f64], b: &[f64], tolerance: f64) {
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= tolerance * y.abs(), "{a:?} against {b:?}");
    }
}

fn mohr_coulomb(c: f64, phi: f64) -> Vec<f64> {
    let soil = Soil::new(19.0, c, phi, 0.0).unwrap();
    factors(&problem(parts(
        vec![layer(None, soil, Strength::MohrCoulomb)],
        water_table(),
        Water::default(),
    )))
}

fn with_envelope(envelope: Envelope) -> (SectionProblem, Vec<f64>) {
    let soil = Soil::weight_only(19.0).unwrap();
    let p = problem(parts(
        vec![layer(None, soil, Strength::Envelope(envelope))],
        water_table(),
        Water::default(),
    ));
    let f = factors(&p);
    (p, f)
}

#[test]
fn a_power_curve_with_b_one_is_mohr_coulomb_in_every_method() {
    // τ = a(σ′ + d) + c with a = tan 30°, a·d + c = 10: c′ = 10, φ′ = 30°.
    let a = 30f64.to_radians().tan();
    let (_, got) = with_envelope(Envelope::PowerCurve {
        a,
        b: 1.0,
        c: 4.0,
        d: 6.0 / a,
    });
    assert_close(&got, &mohr_coulomb(10.0, 30.0), 1e-9);
}

#[test]
fn a_two_point_shear_normal_function_is_mohr_coulomb() {
    let t = 25f64.to_radians().tan();
    let (_, got) = with_envelope(Envelope::ShearNormal(vec![
        (0.0, 8.0),
        (400.0, 8.0 + 400.0 * t),
    ]));
    assert_close(&got, &mohr_coulomb(8.0, 25.0), 1e-9);
}

/// Each base carries its envelope's strength at its own σ′ₙ.
fn assert_on_envelope(p: &SectionProblem, envelope: &Envelope) -> SpencerSolution {
    let s = solve_spencer(p.model(), &SpencerSettings::default());
    assert!(
        s.strength.settled && s.strength.rounds >= 2,
        "{:?}",
        s.strength
    );
    for (slice, forces) in p.model().slices.iter().zip(&s.slice_forces) {
        let sigma = forces.effective_normal_force / slice.base_length;
        let tau = envelope.shear(sigma).0;
        assert!(
            (forces.available_shear_strength - tau).abs() <= 1e-8 * tau.max(1.0),
            "σ′ {sigma}: {} against {tau}",
            forces.available_shear_strength
        );
    }
    s
}

#[test]
fn a_concave_power_curve_settles_on_its_envelope() {
    let envelope = Envelope::PowerCurve {
        a: 3.0,
        b: 0.6,
        c: 0.0,
        d: 0.0,
    };
    let (p, got) = with_envelope(envelope.clone());
    let s = assert_on_envelope(&p, &envelope);
    // Concave through the origin: τ(σ)/σ falls with σ, so each base's strength lies between
    // the secants from the origin to the largest and the smallest σ′ₙ; F lies between the
    // answers of those two Mohr–Coulomb soils (c′ = 0).
    let sigmas: Vec<f64> = p
        .model()
        .slices
        .iter()
        .zip(&s.slice_forces)
        .map(|(sl, f)| f.effective_normal_force / sl.base_length)
        .collect();
    let hi = sigmas.iter().copied().fold(0.0, f64::max);
    let lo = sigmas
        .iter()
        .copied()
        .filter(|&x| x > 1.0)
        .fold(f64::MAX, f64::min);
    let secant = |x: f64| (envelope.shear(x).0 / x).atan().to_degrees();
    let below = mohr_coulomb_dry(0.0, secant(hi));
    let above = mohr_coulomb_dry(0.0, secant(lo));
    assert!(
        below < got[0] && got[0] < above,
        "{below} < {} < {above}",
        got[0]
    );
}

fn mohr_coulomb_dry(c: f64, phi: f64) -> f64 {
    let soil = Soil::new(19.0, c, phi, 0.0).unwrap();
    solve_spencer(
        problem(parts(
            vec![layer(None, soil, Strength::MohrCoulomb)],
            water_table(),
            Water::default(),
        ))
        .model(),
        &SpencerSettings::default(),
    )
    .factor_of_safety
    .unwrap()
}

#[test]
fn hoek_brown_settles_on_its_envelope() {
    let envelope = Envelope::HoekBrown(HoekBrown::new(5_000.0, 30.0, 8.0, 0.5));
    let (p, got) = with_envelope(envelope.clone());
    assert_on_envelope(&p, &envelope);
    assert!(got[0] > 1.0 && got[0].is_finite());
}

/// The undrained profile of `reference` as `n` sublayers of constant strength (each its
/// profile's value at its middle), against the profile itself.
fn sublayers(reference: Reference, n: usize) -> (f64, f64) {
    let profile = Undrained {
        cohesion: 15.0,
        gradient: 3.0,
        reference,
        cohesion_max: None,
    };
    let soil = Soil::weight_only(18.0).unwrap();
    let exact = solve_spencer(
        problem(parts(
            vec![layer(None, soil, Strength::Undrained(profile))],
            None,
            Water::default(),
        ))
        .model(),
        &SpencerSettings::default(),
    )
    .factor_of_safety
    .unwrap();
    // Sublayers 20/n thick from y = 10 (the crest) down to y = −10, then the rest.
    let h = 20.0 / n as f64;
    let shifted = |depth: f64| -> Polyline {
        match reference {
            Reference::Datum(_) => line(&[(-20.0, 10.0 - depth), (50.0, 10.0 - depth)]),
            Reference::Ground => line(&GROUND.map(|(x, y)| (x, y - depth))),
        }
    };
    let layers: Vec<Layer> = (0..=n)
        .map(|k| {
            let depth = (k as f64 + 0.5) * h;
            let (y, g) = (10.0 - depth, 10.0);
            let c = profile.at(y, g);
            let top = (k > 0).then(|| shifted(k as f64 * h));
            let c = if k == n { profile.at(y - 1e3, g) } else { c };
            layer(
                top,
                Soil::new(18.0, c, 0.0, 0.0).unwrap(),
                Strength::MohrCoulomb,
            )
        })
        .collect();
    let stepped = solve_spencer(
        problem(parts(layers, None, Water::default())).model(),
        &SpencerSettings::default(),
    )
    .factor_of_safety
    .unwrap();
    (exact, stepped)
}

#[test]
fn an_undrained_profile_is_the_limit_of_thin_sublayers() {
    for reference in [Reference::Datum(10.0), Reference::Ground] {
        let (exact, coarse) = sublayers(reference, 10);
        let (_, fine) = sublayers(reference, 160);
        let (e_coarse, e_fine) = ((coarse - exact).abs(), (fine - exact).abs());
        assert!(
            e_fine < 2e-3 * exact,
            "{reference:?}: {fine} against {exact}"
        );
        assert!(
            e_fine < e_coarse / 4.0,
            "{reference:?}: {e_coarse} then {e_fine}"
        );
    }
}

#[test]
fn a_grid_sampled_from_a_level_water_line_is_that_line() {
    let level = 0.0;
    let table = Some(line(&[(-20.0, level), (50.0, level)]));
    let soil = Soil::new(19.0, 8.0, 30.0, 0.0).unwrap();
    // A polyline through the line's level at a vertex: the slices of both cases are the same
    // (a water line's crossings with the base are slice sides; a grid's are not).
    let surface = SlipShape::Polyline(line(&[
        (-4.0, 0.0),
        (4.0, -4.0),
        (22.0, -4.0),
        (30.0, level),
        (36.0, 10.5),
    ]));
    let by_line = factors(&on(
        parts(
            vec![layer(None, soil, Strength::MohrCoulomb)],
            table,
            Water::default(),
        ),
        surface.clone(),
    ));
    // Rows at the line and above it carry u = 0; below it u is linear in y, so every triangle
    // (between two rows) interpolates the line's field exactly.
    let mut points = Vec::new();
    for x in (-3..=6).map(|i| f64::from(i) * 10.0) {
        for y in [-30.0, -15.0, -5.0, level, 8.0, 14.0] {
            points.push((x, y, 9.81 * (level - y).max(0.0)));
        }
    }
    let grid = PoreGrid::new(points).unwrap();
    let by_grid = factors(&on(
        parts(
            vec![layer(None, soil, Strength::MohrCoulomb)],
            None,
            Water {
                grid: Some(grid),
                ..Water::default()
            },
        ),
        surface,
    ));
    assert_close(&by_grid, &by_line, 1e-9);
}

#[test]
fn a_layers_own_line_is_the_sections_line_for_that_soil() {
    let soil = Soil::new(19.0, 8.0, 30.0, 0.0).unwrap();
    let by_section = factors(&problem(parts(
        vec![layer(None, soil, Strength::MohrCoulomb)],
        water_table(),
        Water::default(),
    )));
    let mut own = layer(None, soil, Strength::MohrCoulomb);
    own.piezometric_line = Some(WaterLine {
        line: water_table().unwrap(),
        hu: Hu::Factor(1.0),
    });
    // The section's own line lies far below: the layer's line rules its soil.
    let by_layer = factors(&problem(parts(
        vec![own],
        Some(line(&[(-20.0, -50.0), (50.0, -50.0)])),
        Water::default(),
    )));
    assert_close(&by_layer, &by_section, 1e-12);
}

#[test]
fn hu_scales_the_head_and_auto_is_cos_squared_of_the_line() {
    let soil = Soil::new(19.0, 8.0, 30.0, 0.0).unwrap();
    // No pore pressure on the same slices: the soil's own r_u of 0 rules it.
    let mut dry_layer = layer(None, soil, Strength::MohrCoulomb);
    dry_layer.pore_pressure_ratio = Some(0.0);
    let dry = factors(&problem(parts(
        vec![dry_layer],
        water_table(),
        Water::default(),
    )));
    let none = factors(&problem(parts(
        vec![layer(None, soil, Strength::MohrCoulomb)],
        water_table(),
        Water {
            hu: Hu::Factor(0.0),
            grid: None,
        },
    )));
    assert_close(&none, &dry, 1e-12);
    // Auto: each base's u is cos²α·γ_w·(y_p − y), α the line's inclination above it.
    let p = problem(parts(
        vec![layer(None, soil, Strength::MohrCoulomb)],
        water_table(),
        Water {
            hu: Hu::Auto,
            grid: None,
        },
    ));
    for s in &p.model().slices {
        let (x, y) = s.base_middle;
        let (yp, slope) = if x <= 0.0 {
            (-2.0 + 0.075 * (x + 20.0), 0.075)
        } else if x <= 20.0 {
            (-0.5 + 0.275 * x, 0.275)
        } else {
            (5.0 + (x - 20.0) / 30.0, 1.0 / 30.0)
        };
        let expected = 9.81 * (yp - y).max(0.0) / (1.0 + slope * slope);
        assert!((s.pore_pressure - expected).abs() <= 1e-9 * expected.max(1.0));
    }
    // Less water than the full head, more than none.
    let f = factors(&p)[0];
    assert!(none[0] > f && f > mohr_coulomb(8.0, 30.0)[0]);
}

/// A planar wedge cut as one slice: the ends carry no inter-slice force, so force equilibrium
/// along the base gives F = τ(σ′ₙ)·l/(W sin α) with σ′ₙ = W cos α/l — for any envelope, once
/// the base's strength is its envelope's at that σ′ₙ.
#[test]
fn a_one_slice_wedge_has_the_closed_form_factor_on_any_envelope() {
    // Face (0, 0)–(20, 10), crest level; the plane from the toe to (30, 10).
    let ground = line(&[(-10.0, 0.0), (0.0, 0.0), (20.0, 10.0), (40.0, 10.0)]);
    let weight = 19.0 * 50.0;
    let (l, alpha) = (1000f64.sqrt(), (10.0f64 / 30.0).atan());
    let sigma = weight * alpha.cos() / l;
    for envelope in [
        Envelope::PowerCurve {
            a: 2.0,
            b: 0.6,
            c: 1.5,
            d: 0.0,
        },
        Envelope::HoekBrown(HoekBrown::new(2_000.0, 25.0, 10.0, 0.3)),
        Envelope::ShearNormal(vec![(0.0, 2.0), (10.0, 9.0), (40.0, 20.0)]),
    ] {
        let expected = envelope.shear(sigma).0 * l / (weight * alpha.sin());
        let mut p = parts(
            vec![layer(
                None,
                Soil::weight_only(19.0).unwrap(),
                Strength::Envelope(envelope.clone()),
            )],
            None,
            Water::default(),
        );
        p.ground = ground.clone();
        let problem = SectionProblem::new(
            Section::new(p).unwrap(),
            SlipShape::Polyline(line(&[(0.0, 0.0), (30.0, 10.0)])),
            NonZeroUsize::new(1).unwrap(),
            Seismic::default(),
            None,
        )
        .unwrap();
        assert_eq!(problem.model().slices.len(), 1);
        let f = janbu(problem.model()).factor_of_safety.unwrap();
        assert!(
            (f - expected).abs() <= 1e-9 * expected,
            "{f} against {expected}"
        );
    }
}
