//! The envelopes against the formulas evaluated here on their own.

use super::{Envelope, HoekBrown, Reference, Undrained};

#[test]
fn power_curve_with_b_one_is_mohr_coulomb() {
    // τ = a(σ + d) + c: c′ = a·d + c, tan φ′ = a.
    let e = Envelope::PowerCurve {
        a: 0.6,
        b: 1.0,
        c: 4.0,
        d: 5.0,
    };
    for sigma in [0.0, 1.0, 37.5, 1e4] {
        let (tau, slope) = e.shear(sigma);
        assert!((tau - (0.6 * 5.0 + 4.0 + 0.6 * sigma)).abs() <= 1e-12 * tau.max(1.0));
        assert_eq!(slope, 0.6);
        let (c, t) = e.tangent(sigma);
        assert!((c - 7.0).abs() < 1e-12 && (t - 0.6).abs() < 1e-15);
    }
    // Below σ = −d the strength is c alone.
    assert_eq!(e.shear(-6.0), (4.0, 0.0));
}

#[test]
fn power_curve_slope_is_the_derivative() {
    let e = Envelope::PowerCurve {
        a: 2.5,
        b: 0.7,
        c: 1.0,
        d: 0.0,
    };
    for sigma in [0.5, 10.0, 300.0] {
        let h = 1e-6 * sigma;
        let numeric = (e.shear(sigma + h).0 - e.shear(sigma - h).0) / (2.0 * h);
        assert!((e.shear(sigma).1 - numeric).abs() < 1e-7 * numeric);
        assert!((e.shear(sigma).0 - (2.5 * sigma.powf(0.7) + 1.0)).abs() < 1e-12 * sigma);
    }
    // Near σ = 0 the tangent is flattened to tan 80°, and still passes through the envelope.
    let (c, t) = e.tangent(1e-9);
    assert!((t - 80f64.to_radians().tan()).abs() < 1e-12);
    assert!((c + t * 1e-9 - e.shear(1e-9).0).abs() < 1e-12);
}

#[test]
fn two_point_shear_normal_is_mohr_coulomb_on_its_line() {
    // Through (0, 10) and (100, 10 + 100·tan 30°): c′ = 10, φ′ = 30°.
    let t = 30f64.to_radians().tan();
    let e = Envelope::ShearNormal(vec![(0.0, 10.0), (100.0, 10.0 + 100.0 * t)]);
    for sigma in [-5.0, 0.0, 50.0, 250.0] {
        let (tau, slope) = e.shear(sigma);
        assert!(
            (tau - (10.0 + sigma * t)).abs() < 1e-12 * tau.max(1.0),
            "{sigma}"
        );
        assert!((slope - t).abs() < 1e-15);
    }
    // Never below zero.
    assert_eq!(e.shear(-1e3), (0.0, 0.0));
}

#[test]
fn shear_normal_interpolates_between_points() {
    let e = Envelope::ShearNormal(vec![(0.0, 0.0), (50.0, 40.0), (200.0, 100.0)]);
    assert_eq!(e.shear(25.0), (20.0, 0.8));
    assert_eq!(e.shear(50.0), (40.0, 0.4));
    assert_eq!(e.shear(125.0), (70.0, 0.4));
    assert_eq!(e.shear(300.0), (140.0, 0.4));
}

/// σ₁ from the criterion, then σₙ and τ from Balmer's formulas, written out here.
fn by_hand(sigma_ci: f64, gsi: f64, mi: f64, d: f64, sigma3: f64) -> (f64, f64) {
    let mb = mi * ((gsi - 100.0) / (28.0 - 14.0 * d)).exp();
    let s = ((gsi - 100.0) / (9.0 - 3.0 * d)).exp();
    let a = 0.5 + ((-gsi / 15.0).exp() - (-20.0f64 / 3.0).exp()) / 6.0;
    let sigma1 = sigma3 + sigma_ci * (mb * sigma3 / sigma_ci + s).powf(a);
    let k = 1.0 + a * mb * (mb * sigma3 / sigma_ci + s).powf(a - 1.0);
    let normal = (sigma1 + sigma3) / 2.0 - (sigma1 - sigma3) / 2.0 * (k - 1.0) / (k + 1.0);
    let tau = (sigma1 - sigma3) * k.sqrt() / (k + 1.0);
    (normal, tau)
}

#[test]
fn hoek_brown_equals_the_criterion_by_hand() {
    for &(sigma_ci, gsi, mi, d) in &[
        (30_000.0, 45.0, 10.0, 0.0),
        (100_000.0, 70.0, 25.0, 0.7),
        (5_000.0, 20.0, 7.0, 1.0),
        (80_000.0, 100.0, 12.0, 0.0),
    ] {
        let hb = HoekBrown::new(sigma_ci, gsi, mi, d);
        for sigma3 in [0.0, 10.0, 250.0, 2_000.0] {
            let (normal, tau) = by_hand(sigma_ci, gsi, mi, d, sigma3);
            let (got, slope) = Envelope::HoekBrown(hb).shear(normal);
            assert!(
                (got - tau).abs() <= 1e-9 * tau,
                "σci {sigma_ci} GSI {gsi}: τ {got} against {tau}"
            );
            // The slope is the envelope's: a central difference along it.
            let h = 1e-5 * normal.abs().max(1.0);
            let numeric = (hb.shear(normal + h).0 - hb.shear(normal - h).0) / (2.0 * h);
            assert!(
                (slope - numeric).abs() <= 1e-5 * numeric,
                "{slope} {numeric}"
            );
        }
        // No strength at or below the tensile strength −s·σci/mb.
        assert_eq!(hb.shear(hb.tensile_strength() - 1.0), (0.0, 0.0));
    }
}

#[test]
fn undrained_grows_with_depth_and_caps() {
    let u = Undrained {
        cohesion: 10.0,
        gradient: 2.0,
        reference: Reference::Datum(5.0),
        cohesion_max: Some(30.0),
    };
    assert_eq!(u.at(8.0, 20.0), 10.0);
    assert_eq!(u.at(0.0, 20.0), 20.0);
    assert_eq!(u.at(-20.0, 20.0), 30.0);
    let g = Undrained {
        reference: Reference::Ground,
        cohesion_max: None,
        ..u
    };
    assert_eq!(g.at(12.0, 20.0), 26.0);
    assert_eq!(g.divided(2.0).at(12.0, 20.0), 13.0);
}
