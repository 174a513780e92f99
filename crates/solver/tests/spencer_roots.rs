//! Where Spencer's equations have a root and where they provably have none, checked against a
//! computation of the two equations written here from the slices alone (model §2.2): for each
//! slice, with u = 1/F, Q = (A_t − R·u)/(cos(α−θ) + sin(α−θ)·tan φ'·u), and
//! Σ Q = 0, Σ Q·((x_b − x_c)·sin θ − (y_b − y_c)·cos θ) = 0 (no seismic force, no loads).
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::slope::section::Section;
use thrustline_solver::slope::section::{SectionProblem, SlipShape};
use thrustline_solver::slope::*;

/// One slice as the equations see it, from the slice data alone.
struct Term {
    sin_a: f64,
    cos_a: f64,
    /// Driving component of the weight along the base, W·sin α.
    driving: f64,
    /// Effective normal component of the weight, W·cos α − u·l.
    normal: f64,
    cohesion: f64,
    tan_phi: f64,
    arm: (f64, f64),
}

fn terms(model: &SliceModel) -> Vec<Term> {
    model
        .slices
        .iter()
        .map(|s| {
            let (sin_a, cos_a) = s.base_sin_cos;
            Term {
                sin_a,
                cos_a,
                driving: s.weight * sin_a,
                normal: s.weight * cos_a - s.pore_pressure * s.base_length,
                cohesion: s.cohesion * s.base_length,
                tan_phi: s.tan_phi,
                arm: (
                    s.base_middle.0 - model.reference.0,
                    s.base_middle.1 - model.reference.1,
                ),
            }
        })
        .collect()
}

/// Per slice at (F, θ): Q, m_α and N'.
fn slice_state(t: &Term, f: f64, theta: f64) -> (f64, f64, f64) {
    let (st, ct) = theta.sin_cos();
    let sin_d = t.sin_a * ct - t.cos_a * st;
    let cos_d = t.cos_a * ct + t.sin_a * st;
    let m_alpha = cos_d + sin_d * t.tan_phi / f;
    let resisting = t.cohesion + t.normal * t.tan_phi;
    let q = (t.driving - resisting / f) / m_alpha;
    (q, m_alpha, t.normal + q * sin_d)
}

/// The force and moment residuals, scaled by Σ W and Σ W·R.
fn residuals(terms: &[Term], weight: f64, radius: f64, f: f64, theta: f64) -> (f64, f64) {
    let (st, ct) = theta.sin_cos();
    let (mut force, mut moment) = (0.0, 0.0);
    for t in terms {
        let q = slice_state(t, f, theta).0;
        force += q;
        moment += q * (t.arm.0 * st - t.arm.1 * ct);
    }
    (force / weight, moment / (weight * radius))
}

fn section(ground: Vec<(f64, f64)>, soil: Soil) -> Section {
    Section::of_one_soil(ground, soil).unwrap()
}

fn circle(section: &Section, centre: (f64, f64), radius: f64) -> SectionProblem {
    SectionProblem::new(
        section.clone(),
        SlipShape::Circle { centre, radius },
        NonZeroUsize::new(50).unwrap(),
        Seismic::default(),
        None,
    )
    .unwrap()
}

/// Duncan & Wright's clay slope (H = 50 ft, face 40 ft wide, γ = 100 pcf,
/// c = 1000 psf) with φ' = 0.5°, and the critical toe circle of its φ' = 0 analysis.
fn clay_slope_circle() -> SectionProblem {
    let soil = Soil::new(100.0, 1000.0, 0.5, 0.0).unwrap();
    let ground = vec![(-200.0, 0.0), (0.0, 0.0), (40.0, 50.0), (300.0, 50.0)];
    circle(&section(ground, soil), (12.653, 71.805), 72.911)
}

#[test]
fn a_root_past_a_pole_of_m_alpha_is_found_where_the_classic_domain_has_none() {
    let problem = clay_slope_circle();
    let model = problem.model();
    let terms = terms(model);
    let weight: f64 = model.slices.iter().map(|s| s.weight).sum();
    let radius = 72.911;

    // First what must hold: on the classic domain (every m_α > 0, |θ| < 89°) F_f(θ) and F_m(θ)
    // never cross. Each is found here by bisection in F over the admissible interval at θ
    // steps of 0.5°; wherever both exist, F_f − F_m keeps one sign.
    let root_in = |theta: f64, moment: bool| -> Option<f64> {
        let value = |f: f64| {
            let (st, ct) = theta.sin_cos();
            terms.iter().fold(0.0, |s, t| {
                let q = slice_state(t, f, theta).0;
                s + if moment {
                    q * (t.arm.0 * st - t.arm.1 * ct)
                } else {
                    q
                }
            })
        };
        let admissible = |f: f64| terms.iter().all(|t| slice_state(t, f, theta).1 > 0.0);
        // Log-spaced samples 0.01 … 100: the first sign change inside the admissible set.
        let fs: Vec<f64> = (0..=400)
            .map(|i| 0.01 * 10f64.powf(i as f64 / 100.0))
            .collect();
        for w in fs.windows(2) {
            let (a, b) = (w[0], w[1]);
            if admissible(a) && admissible(b) && value(a) * value(b) <= 0.0 {
                let (mut lo, mut hi) = (a, b);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if value(lo) * value(mid) <= 0.0 {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                return Some(0.5 * (lo + hi));
            }
        }
        None
    };
    let signs: Vec<bool> = (-178..=178)
        .filter_map(|i| {
            let theta = (f64::from(i) * 0.5).to_radians();
            Some(root_in(theta, false)? > root_in(theta, true)?)
        })
        .collect();
    assert!(signs.len() > 50, "the curves exist over a range of θ");
    assert!(
        signs.iter().all(|&s| s == signs[0]),
        "the curves cross on the classic domain"
    );

    // The solver's answer: both equations hold (checked here), it lies past the pole of at
    // least one slice, and every slice past its pole is pressed onto its base.
    let s = solve_spencer(model, &SpencerSettings::default());
    assert_eq!(s.status, SpencerStatus::Converged);
    let (f, theta) = (s.factor_of_safety.unwrap(), s.theta_rad.unwrap());
    let (force, moment) = residuals(&terms, weight, radius, f, theta);
    assert!(
        force.abs() < 1e-9 && moment.abs() < 1e-9,
        "{force} {moment}"
    );
    let states: Vec<(f64, f64, f64)> = terms.iter().map(|t| slice_state(t, f, theta)).collect();
    let past = states.iter().filter(|s| s.1 <= 0.0).count();
    let minority_negative = 2 * past <= states.len();
    assert!(past > 0 && past < states.len(), "{past} slices past a pole");
    for (i, (_, m_alpha, effective)) in states.iter().enumerate() {
        if (*m_alpha <= 0.0) == minority_negative {
            assert!(*effective >= -1e-9 * weight, "slice {i}: N' = {effective}");
        }
    }
    // With φ' = 0.5° the frictional strength is a few per cent of c' at most, so F lies within
    // that of Bishop's F (the φ' → 0 limit of the moment equation): 1e-3 here.
    let bishop = s.bishop_factor_of_safety.unwrap();
    assert!((f / bishop - 1.0).abs() < 1e-3, "F = {f}, Bishop {bishop}");
    assert!(theta.abs() < 89f64.to_radians());
}

#[test]
fn a_circle_in_level_ground_provably_has_no_root() {
    // Symmetric about the centre's vertical: the weights drive no moment about the centre, so
    // no finite F meets moment equilibrium (F_m = ∞ for every θ). Such a circle is refused as a
    // slip surface (nothing drives it), and its slices, written out here (two mirror-image
    // slices of a lens), have no root: Undriven to a search, no solution to a single analysis.
    let soil = Soil::new(20.0, 10.0, 30.0, 0.0).unwrap();
    let ground = vec![(-50.0, 0.0), (50.0, 0.0)];
    let refused = SectionProblem::new(
        section(ground, soil),
        SlipShape::Circle {
            centre: (0.0, 5.0),
            radius: 8.0,
        },
        NonZeroUsize::new(50).unwrap(),
        Seismic::default(),
        None,
    );
    assert!(
        matches!(&refused, Err(SlopeError::NoSlipMass { reason, .. }) if reason.contains("nothing drives")),
        "{refused:?}"
    );
    let half_width = (8.0f64 * 8.0 - 5.0 * 5.0).sqrt();
    let slice = |sign: f64| {
        // From the centre's vertical out to the crossing: the chord from (0, −3) to (±w, 0).
        let (x0, x1) = if sign > 0.0 {
            (0.0, half_width)
        } else {
            (-half_width, 0.0)
        };
        let (y0, y1) = if sign > 0.0 { (-3.0, 0.0) } else { (0.0, -3.0) };
        let length = half_width.hypot(3.0);
        let weight = 20.0 * 0.5 * half_width * 3.0;
        BaseSlice {
            x_left: x0,
            x_right: x1,
            base_left_y: y0,
            base_right_y: y1,
            top_right_y: 0.0,
            base_sin_cos: ((y1 - y0) / length, half_width / length),
            base_length: length,
            base_middle: (0.5 * (x0 + x1), -1.5),
            height_middle: 1.5,
            weight,
            centroid_y: -1.0,
            cohesion: 10.0,
            tan_phi: 30f64.to_radians().tan(),
            pore_pressure: 0.0,
            layer: 0,
            side_water: (0.0, 0.0),
        }
    };
    let model = SliceModel {
        slices: vec![slice(-1.0), slice(1.0)],
        seismic: Seismic::default(),
        loads: Vec::new(),
        reference: (0.0, 5.0),
        moment_centre: Some((0.0, 5.0)),
        circular: true,
        length_scale: 8.0,
        envelopes: None,
        fixed: Vec::new(),
    };
    assert_eq!(
        spencer_factor_outcome(&model, &SpencerSettings::default()),
        FactorOutcome::Undriven
    );
    let s = solve_spencer(&model, &SpencerSettings::default());
    assert_eq!(s.status, SpencerStatus::NoSolution);
    assert!(s.factor_of_safety.is_none() && s.theta_rad.is_none());
}

#[test]
fn the_clay_slope_search_lands_within_the_friction_bound_of_the_undrained_answer() {
    // φ' = 0 gives F = 1.1233 (Duncan & Wright publish 1.124) on the critical toe circle. With
    // φ' = 0.5° the strength grows by at most σ'·tan φ' ≤ γ·H·tan 0.5° = 43.6 psf on c' = 1000
    // psf (4.4 %): the critical F lies in [1.1233, 1.1233·1.044]. Before the roots past the
    // poles were solved, the search answered 1.2252 (its deep circles had no classic root).
    let problem = |phi: f64| SearchProblem {
        embankment: Embankment::new(50.0, 40.0).unwrap(),
        slices: NonZeroUsize::new(50).unwrap(),
        soil: Soil::new(100.0, 1000.0, phi, 0.0).unwrap(),
        seismic: Seismic::default(),
        lower_end_factor: 0.0,
        lower_end_factor_max: None,
    };
    let search = |phi: f64| {
        let p = problem(phi);
        search_critical_circle(
            &p,
            SearchGrid::automatic(&p.embankment, 0.0),
            &SearchSettings::default(),
            &thrustline_solver::budget::Budget::unlimited(),
        )
        .factor_of_safety
        .unwrap()
    };
    let undrained = search(0.0);
    assert!((undrained - 1.124).abs() < 1e-3, "{undrained}");
    let f = search(0.5);
    assert!(
        f > undrained && f < undrained * (1.0 + 100.0 * 50.0 * 0.5f64.to_radians().tan() / 1000.0),
        "F = {f} against {undrained}"
    );
}
