//! Rapid drawdown (model §8) against constructions written here: the K_c = 1 envelope from
//! circles drawn tangent to the R envelope, the interpolation in K_c from the consolidation
//! Mohr circle, and the three stages staged by hand with Spencer's method on the two plain
//! sections (the pool up, the pool down).
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::slope::section::drawdown::{
    isotropic_envelope, undrained_strength, REnvelope,
};
use thrustline_solver::slope::section::{
    Layer, Polyline, Section, SectionParts, SectionProblem, SlipShape, Water,
};
use thrustline_solver::slope::spencer::{solve_spencer, SpencerSettings};
use thrustline_solver::slope::strength::Strength;
use thrustline_solver::slope::*;

fn line(points: &[(f64, f64)]) -> Polyline {
    Polyline::new(points.to_vec()).unwrap()
}

/// τ_ff of isotropic consolidation at σ′_3c: the circle from σ′_3c whose diameter reaches the
/// R envelope (found by bisection on the radius: the distance from its centre to the line
/// equals its radius), then the shear on the plane at 45° + φ′/2 to the major principal
/// plane, r·cos φ′.
fn tangent_circle_strength(r: REnvelope, phi: f64, sigma3: f64) -> f64 {
    let (c_r, phi_r) = (r.cohesion, r.friction_angle_rad);
    // Distance from (σ₃ + ρ, 0) to τ = c_R + σ·tan φ_R, less ρ: positive while ρ is short.
    let gap = |rho: f64| (c_r + (sigma3 + rho) * phi_r.tan()) * phi_r.cos() - rho;
    let (mut lo, mut hi) = (0.0, 1.0);
    while gap(hi) > 0.0 {
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if gap(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi) * phi.cos()
}

#[test]
fn the_isotropic_envelope_is_the_circles_tangent_to_the_r_envelope() {
    for (c_r, phi_r_deg) in [
        (0.0, 15.0),
        (15.0, 15.0),
        (40.0, 0.0),
        (5.0, 30.0),
        (1.0, 60.0),
    ] {
        let r = REnvelope {
            cohesion: c_r,
            friction_angle_rad: f64::to_radians(phi_r_deg),
        };
        for phi_deg in [0.0, 20.0, 35.0] {
            let phi = f64::to_radians(phi_deg);
            let (d, tan_psi) = isotropic_envelope(r, phi);
            for sigma in [0.0, 10.0, 137.5, 2000.0] {
                let expected = tangent_circle_strength(r, phi, sigma);
                let got = d + sigma * tan_psi;
                assert!(
                    (got - expected).abs() <= 1e-10 * expected.max(1.0),
                    "c_R {c_r}, φ_R {phi_r_deg}, φ′ {phi_deg}, σ {sigma}: {got} vs {expected}"
                );
                // K_c = 1 (no shear at consolidation) is this envelope itself, where both
                // envelopes' σ′_3c are positive.
                let c = 10.0;
                if sigma > c * phi.cos() && sigma > 0.0 {
                    let tau = undrained_strength((sigma, 0.0), (c, phi), r);
                    assert!(
                        (tau - expected).abs() <= 1e-9 * expected,
                        "{tau} vs {expected}"
                    );
                }
            }
        }
    }
}

/// K_c = σ′_1c/σ′_3c of the circle through (σ, τ) on the plane at 45° + φ′/2 to the major
/// principal plane: that point lies at the angle where the effective envelope would touch, so
/// τ = q·cos φ′ and σ = p − q·sin φ′.
fn consolidation_ratio(sigma: f64, tau: f64, phi: f64) -> f64 {
    let q = tau / phi.cos();
    let p = sigma + q * phi.sin();
    (p + q) / (p - q)
}

#[test]
fn the_undrained_strength_is_linear_in_the_consolidation_ratio_between_the_envelopes() {
    let r = REnvelope {
        cohesion: 12.0,
        friction_angle_rad: f64::to_radians(16.0),
    };
    let (c, phi) = (8.0, f64::to_radians(30.0));
    for sigma in [50.0, 120.0, 400.0] {
        let (d, tan_psi) = isotropic_envelope(r, phi);
        let isotropic = d + sigma * tan_psi;
        let drained = c + sigma * phi.tan();
        let k_f = consolidation_ratio(sigma, drained, phi);
        for fraction in [0.0, 0.25, 0.5, 0.9, 1.0] {
            let tau = fraction * drained;
            let k = consolidation_ratio(sigma, tau, phi);
            let expected = ((k_f - k) * isotropic + (k - 1.0) * drained) / (k_f - 1.0);
            let got = undrained_strength((sigma, tau), (c, phi), r);
            assert!(
                (got - expected).abs() <= 1e-9 * expected,
                "σ {sigma}, τ {tau}: {got} vs {expected}"
            );
        }
        // Sheared beyond failure at consolidation (F < 1 before the drawdown): K_c = K_f.
        let beyond = undrained_strength((sigma, 1.5 * drained), (c, phi), r);
        assert!((beyond - drained).abs() <= 1e-9 * drained);
    }
    // Where a σ′_3c is negative (large cohesion, low σ′): the lower envelope.
    let sigma = 2.0;
    let (d, tan_psi) = isotropic_envelope(r, phi);
    let lower = (d + sigma * tan_psi).min(c + sigma * phi.tan());
    assert_eq!(undrained_strength((sigma, 5.0), (c, phi), r), lower);
    assert_eq!(undrained_strength((-3.0, 5.0), (c, phi), r), d.min(c));
}

const GROUND: [(f64, f64); 4] = [(-20.0, 0.0), (0.0, 0.0), (60.0, 20.0), (75.0, 20.0)];
/// The pool up at 18, the phreatic line falling through the embankment.
const BEFORE: [(f64, f64); 3] = [(-20.0, 18.0), (54.0, 18.0), (75.0, 12.0)];
/// The pool down at 2, the line along the face (what was the pool above it has gone).
const AFTER: [(f64, f64); 4] = [(-20.0, 2.0), (6.0, 2.0), (54.0, 18.0), (75.0, 12.0)];
const CLAY: (f64, f64, f64) = (20.0, 10.0, 25.0);
const SAND: (f64, f64, f64) = (21.0, 0.0, 36.0);

fn parts(water: &[(f64, f64)]) -> SectionParts {
    let layer = |top: Option<Polyline>, (gamma, c, phi): (f64, f64, f64)| Layer {
        top,
        soil: Soil::new(gamma, c, phi, 0.0).unwrap(),
        pore_pressure_ratio: None,
        strength: Strength::MohrCoulomb,
        piezometric_line: None,
    };
    SectionParts {
        ground: line(&GROUND),
        layers: vec![
            layer(None, CLAY),
            layer(Some(line(&[(-20.0, -1.0), (75.0, -1.0)])), SAND),
        ],
        bedrock: None,
        piezometric_line: Some(line(water)),
        water_unit_weight: 9.81,
        surcharges: Vec::new(),
        line_loads: Vec::new(),
        tension_crack: None,
        supports: Vec::new(),
        water: Water::default(),
    }
}

fn section(water: &[(f64, f64)]) -> Section {
    Section::new(parts(water)).unwrap()
}

fn on(section: Section) -> SectionProblem {
    SectionProblem::new(
        section,
        SlipShape::Circle {
            centre: (10.0, 45.0),
            radius: 47.5,
        },
        NonZeroUsize::new(40).unwrap(),
        Seismic::default(),
        None,
    )
    .unwrap()
}

fn spencer(model: &SliceModel) -> (f64, Vec<f64>) {
    let s = solve_spencer(model, &SpencerSettings::default());
    let normals = s
        .slice_forces
        .iter()
        .map(|f| f.effective_normal_force)
        .collect();
    (s.factor_of_safety.unwrap(), normals)
}

#[test]
fn the_three_stages_are_those_staged_by_hand() {
    // Neither water line crosses this circle below the ground, so the plain sections' slices
    // are the drawdown's.
    let r = REnvelope {
        cohesion: 6.0,
        friction_angle_rad: f64::to_radians(14.0),
    };
    let drawdown = section(&AFTER)
        .with_drawdown(line(&BEFORE), vec![Some(r), None])
        .unwrap();
    let problem = on(drawdown);
    let stages = problem.drawdown().unwrap().clone();

    // Stage 1: the pool up, drained.
    let before = on(section(&BEFORE));
    let (f1, normals) = spencer(before.model());
    assert!((stages.before_factor - f1).abs() <= 1e-12 * f1);
    // Stage 2: the clay's bases at τ_ff of their consolidation, φ = 0.
    let mut after = on(section(&AFTER)).model().clone();
    assert_eq!(after.slices.len(), before.model().slices.len());
    let phi = CLAY.2.to_radians();
    let mut clay = Vec::new();
    for (i, s) in after.slices.iter_mut().enumerate() {
        if s.layer != 0 {
            continue;
        }
        let sigma = normals[i] / s.base_length;
        let tau = (CLAY.1 + sigma.max(0.0) * phi.tan()) / f1;
        let (d, tan_psi) = isotropic_envelope(r, phi);
        let isotropic = d + sigma * tan_psi;
        let drained = CLAY.1 + sigma * phi.tan();
        let k = consolidation_ratio(sigma, tau, phi);
        let k_f = consolidation_ratio(sigma, drained, phi);
        // A negative σ′_3c (either circle's p − q; K then negative or infinite): the lower.
        let minor = |t: f64| sigma + t * phi.tan() - t / phi.cos();
        s.cohesion = if minor(tau) <= 0.0 || minor(drained) <= 0.0 {
            isotropic.min(drained)
        } else {
            ((k_f - k) * isotropic + (k - 1.0) * drained) / (k_f - 1.0)
        };
        s.tan_phi = 0.0;
        clay.push(i);
    }
    assert!(
        !clay.is_empty() && clay.len() < after.slices.len(),
        "both soils are cut"
    );
    assert_eq!(stages.undrained_slices, clay);
    let (f2, normals) = spencer(&after);
    assert!(
        (stages.undrained_factor - f2).abs() <= 1e-9 * f2,
        "{} vs {f2}",
        stages.undrained_factor
    );
    // Stage 3: the drained strength where it is the lower.
    let mut drained = Vec::new();
    for &i in &clay {
        let s = &mut after.slices[i];
        let strength = CLAY.1 + (normals[i] / s.base_length).max(0.0) * phi.tan();
        if strength < s.cohesion {
            (s.cohesion, s.tan_phi) = (CLAY.1, phi.tan());
            drained.push(i);
        }
    }
    assert_eq!(stages.drained_slices, drained);
    let (f3, _) = spencer(&after);
    let (answer, _) = spencer(problem.model());
    assert!((answer - f3).abs() <= 1e-9 * f3, "{answer} vs {f3}");
    // The drawdown costs the slope: below both the pool up and the undrained stage.
    assert!(answer < f1 && answer <= f2 + 1e-12);
}

#[test]
fn a_drawdown_is_refused_where_its_pore_pressures_would_come_from_elsewhere() {
    let r = Some(REnvelope {
        cohesion: 1.0,
        friction_angle_rad: 0.2,
    });
    let no_soil = section(&AFTER).with_drawdown(line(&BEFORE), vec![None, None]);
    assert!(matches!(
        no_soil,
        Err(SlopeError::Conflict {
            parameter: SlopeParameter::Drawdown,
            ..
        })
    ));
    let steep = section(&AFTER).with_drawdown(
        line(&BEFORE),
        vec![
            Some(REnvelope {
                cohesion: 1.0,
                friction_angle_rad: 1.6,
            }),
            None,
        ],
    );
    assert!(matches!(
        steep,
        Err(SlopeError::OutOfRange {
            parameter: SlopeParameter::REnvelope { index: 0 },
            ..
        })
    ));
    let dry = Section::new(SectionParts {
        piezometric_line: None,
        ..parts(&AFTER)
    })
    .unwrap();
    assert!(dry.with_drawdown(line(&BEFORE), vec![r, None]).is_err());
}
