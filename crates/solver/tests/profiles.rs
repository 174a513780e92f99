//! Arch profiles (model §10) against constructions written here independently: each shape's
//! joints at equal arc lengths from closed forms or a quadrature of this file's own, their
//! normals from the shape's slope, the springings and the crown.

use std::f64::consts::PI;
use std::num::NonZeroUsize;

use thrustline_solver::arch::profile::{pointed_rise, Profile, ProfileShape, Station};
use thrustline_solver::arch::{ArchError, CircularArch, VoussoirShape};

type Point = (f64, f64);

const SPAN: f64 = 10.0;
const H: f64 = 0.5 * SPAN;

fn stations(shape: ProfileShape, rise: f64, m: usize) -> Vec<Station> {
    Profile::new(&shape, SPAN, rise)
        .expect("a valid profile")
        .stations(m)
}

/// Every station equals the expected point and outward unit normal within `tol`.
fn assert_stations(got: &[Station], expected: &[(Point, Point)], tol: f64) {
    assert_eq!(got.len(), expected.len());
    for (k, (s, (p, n))) in got.iter().zip(expected).enumerate() {
        let dp = (s.point.0 - p.0).hypot(s.point.1 - p.1);
        let dn = (s.normal.0 - n.0).hypot(s.normal.1 - n.1);
        assert!(
            dp <= tol * SPAN && dn <= tol,
            "station {k}: {s:?} against {p:?}, {n:?} ({dp:e}, {dn:e})"
        );
    }
}

fn unit(v: Point) -> Point {
    let l = v.0.hypot(v.1);
    (v.0 / l, v.1 / l)
}

/// The root of an increasing `f` on [lo, hi] by bisection.
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// A circular arc about `c` of radius `r`, stations at equal angles from `from` to `to`.
fn arc_stations(c: Point, r: f64, from: f64, to: f64, m: usize) -> Vec<(Point, Point)> {
    (0..=m)
        .map(|k| {
            let a = from + (to - from) * k as f64 / m as f64;
            ((c.0 + r * a.cos(), c.1 + r * a.sin()), (a.cos(), a.sin()))
        })
        .collect()
}

#[test]
fn circles_have_joints_at_equal_angles() {
    let m = 24;
    assert_stations(
        &stations(ProfileShape::Semicircular, H, m),
        &arc_stations((0.0, 0.0), H, 0.0, PI, m),
        1e-12,
    );
    // Segmental: the circle through (±h, 0) and (0, r); its centre below the springings.
    let rise = 2.0;
    let radius = (H * H + rise * rise) / (2.0 * rise);
    let from = (H / radius).acos();
    assert!((radius * from.sin() - (radius - rise)).abs() < 1e-12);
    assert_stations(
        &stations(ProfileShape::Segmental, rise, m),
        &arc_stations((0.0, rise - radius), radius, from, PI - from, m),
        1e-12,
    );
}

#[test]
fn a_semicircular_profile_is_the_circular_arch_with_quadrilateral_voussoirs() {
    let (t, n) = (0.6, 30);
    let chain = Profile::new(&ProfileShape::Semicircular, SPAN, H)
        .and_then(|p| p.chain(t, n))
        .expect("a chain");
    let circle = CircularArch::new(
        H + 0.5 * t,
        t,
        NonZeroUsize::new(n).expect("n > 0"),
        0.0,
        0.0,
        VoussoirShape::Quadrilateral,
    )
    .expect("a circular arch")
    .assembly();
    for (a, b) in chain.blocks.iter().zip(&circle.blocks) {
        for (p, q) in a.corners.iter().zip(&b.corners) {
            assert!((p.0 - q.0).hypot(p.1 - q.1) < 1e-12 * SPAN, "{p:?} {q:?}");
        }
        assert!((a.area - b.area).abs() < 1e-12 * a.area);
    }
}

/// Simpson's rule with `n` (even) intervals.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let h = (b - a) / n as f64;
    let inner: f64 = (1..n)
        .map(|i| f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}

#[test]
fn an_ellipse_has_equal_arcs_by_an_independent_quadrature() {
    let (rise, m) = (3.0, 16);
    let speed = |t: f64| (H * t.sin()).hypot(rise * t.cos());
    let arc = |t: f64| simpson(speed, 0.0, t, 4000);
    let total = arc(PI);
    let expected: Vec<(Point, Point)> = (0..=m)
        .map(|k| {
            let target = total * k as f64 / m as f64;
            let t = bisect(|t| arc(t) - target, 0.0, PI);
            // Outward normal of (h cos t, r sin t): (r cos t, h sin t) normalised.
            (
                (H * t.cos(), rise * t.sin()),
                unit((rise * t.cos(), H * t.sin())),
            )
        })
        .collect();
    assert_stations(
        &stations(ProfileShape::Elliptical, rise, m),
        &expected,
        1e-9,
    );
}

#[test]
fn a_parabola_has_equal_arcs_by_its_closed_form() {
    let (rise, m) = (4.0, 20);
    let k = 2.0 * rise / (H * H);
    // Arc length from the crown to x of y = r(1 − x²/h²), whose slope is −k·x.
    let from_crown = |x: f64| 0.5 * x * (1.0 + k * k * x * x).sqrt() + (k * x).asinh() / (2.0 * k);
    let half = from_crown(H);
    let expected: Vec<(Point, Point)> = (0..=m)
        .map(|j| {
            let sigma = half - 2.0 * half * j as f64 / m as f64;
            let x = bisect(|x| from_crown(x) - sigma, -H, H);
            ((x, rise * (1.0 - x * x / (H * H))), unit((k * x, 1.0)))
        })
        .collect();
    assert_stations(
        &stations(ProfileShape::Parabolic, rise, m),
        &expected,
        1e-10,
    );
}

#[test]
fn a_catenary_has_equal_arcs_by_its_closed_form() {
    let (rise, m) = (6.0, 18);
    // a·(cosh(h/a) − 1) = r, decreasing in a.
    let a = bisect(|a| rise - a * ((H / a).cosh() - 1.0), 0.05, 1e3);
    let half = a * (H / a).sinh();
    let expected: Vec<(Point, Point)> = (0..=m)
        .map(|j| {
            let sigma = half - 2.0 * half * j as f64 / m as f64;
            let x = a * (sigma / a).asinh();
            let sh = (x / a).sinh();
            ((x, rise + a - a * (x / a).cosh()), unit((sh, 1.0)))
        })
        .collect();
    assert_stations(&stations(ProfileShape::Catenary, rise, m), &expected, 1e-10);
}

#[test]
fn a_three_centred_arch_is_two_haunch_arcs_tangent_to_a_crown_arc() {
    let (rise, rho, m) = (3.0, 1.5, 24);
    // The crown centre (0, y_c): |centres| = R_c − ρ with R_c = r − y_c, by bisection.
    let yc = bisect(
        |y| (H - rho).hypot(y) - (rise - y - rho),
        -1e6 * SPAN,
        rise - rho,
    );
    let big = rise - yc;
    let phi = (-yc).atan2(H - rho);
    let (l1, l2) = (rho * phi, big * (PI - 2.0 * phi));
    let total = 2.0 * l1 + l2;
    let expected: Vec<(Point, Point)> = (0..=m)
        .map(|k| {
            let s = total * k as f64 / m as f64;
            let (centre, radius, angle) = if s <= l1 {
                ((H - rho, 0.0), rho, s / rho)
            } else if s <= l1 + l2 {
                ((0.0, yc), big, phi + (s - l1) / big)
            } else {
                ((rho - H, 0.0), rho, PI - phi + (s - l1 - l2) / rho)
            };
            (
                (
                    centre.0 + radius * angle.cos(),
                    centre.1 + radius * angle.sin(),
                ),
                (angle.cos(), angle.sin()),
            )
        })
        .collect();
    let got = stations(ProfileShape::ThreeCentred { haunch_radius: rho }, rise, m);
    assert_stations(&got, &expected, 1e-10);
    // The crown at (0, r): m is even.
    let crown = got[m / 2];
    assert!((crown.point.0).abs() < 1e-12 && (crown.point.1 - rise).abs() < 1e-12);
}

#[test]
fn a_pointed_arch_meets_at_its_crown_with_a_vertical_joint() {
    // The equilateral arch: arcs of radius = span, rise = span·√3/2.
    let rise = pointed_rise(SPAN, SPAN);
    assert!((rise - SPAN * 3f64.sqrt() / 2.0).abs() < 1e-12);
    let m = 12;
    // Arcs about (h − ρ, 0) and (ρ − h, 0), each an angle β from the springing line.
    let beta = rise.atan2(SPAN - H);
    let mut expected = arc_stations((H - SPAN, 0.0), SPAN, 0.0, beta, m / 2);
    expected.pop();
    expected.push(((0.0, rise), (0.0, 1.0)));
    expected.extend(
        arc_stations((SPAN - H, 0.0), SPAN, PI - beta, PI, m / 2)
            .into_iter()
            .skip(1),
    );
    assert_stations(&stations(ProfileShape::Pointed, rise, m), &expected, 1e-12);
    assert!(matches!(
        Profile::new(&ProfileShape::Pointed, SPAN, H),
        Err(ArchError::OutOfRange { .. })
    ));
}

#[test]
fn measured_points_are_a_polyline_with_bisector_joints_at_vertices() {
    let points = vec![(-4.0, 0.0), (-3.0, 2.0), (0.0, 3.0), (3.0, 2.0), (4.0, 0.0)];
    let profile = Profile::new(&ProfileShape::Points(points), 0.0, 0.0).expect("a profile");
    assert_eq!((profile.span(), profile.rise()), (8.0, 3.0));
    let (a, b) = (5f64.sqrt(), 10f64.sqrt());
    assert!((profile.length() - 2.0 * (a + b)).abs() < 1e-12);
    // Four stations: the springings, the crown vertex (normal vertical), and the quarter
    // points, one on each side at a + b/2… along the segments.
    let got = profile.stations(4);
    let quarter = 0.5 * (a + b);
    // From (4, 0) along (−1, 2)/√5 for a, then along (−3, 1)/√10.
    let on_second = quarter - a;
    let p1 = (3.0 - 3.0 * on_second / b, 2.0 + on_second / b);
    let n1 = unit((1.0, 3.0));
    let expected = [
        ((4.0, 0.0), unit((2.0, 1.0))),
        (p1, n1),
        ((0.0, 3.0), (0.0, 1.0)),
        ((-p1.0, p1.1), (-n1.0, n1.1)),
        ((-4.0, 0.0), unit((-2.0, 1.0))),
    ];
    assert_stations(&got, &expected, 1e-12);
    // Segments of length 5 (3-4-5 triangles and a flat crown): with m = 4 every station is a
    // vertex, whose joint is the bisector of its two segments' normals.
    let flat = vec![(8.0, 0.0), (5.0, 4.0), (0.0, 4.0), (-5.0, 4.0), (-8.0, 0.0)];
    let flat = Profile::new(&ProfileShape::Points(flat), 0.0, 0.0).expect("a profile");
    let kink = unit((0.8 + 0.0, 0.6 + 1.0));
    let expected = [
        ((8.0, 0.0), (0.8, 0.6)),
        ((5.0, 4.0), kink),
        ((0.0, 4.0), (0.0, 1.0)),
        ((-5.0, 4.0), (-kink.0, kink.1)),
        ((-8.0, 0.0), (-0.8, 0.6)),
    ];
    assert_stations(&flat.stations(4), &expected, 1e-12);
}

#[test]
fn bad_profiles_are_refused_naming_what_is_wrong() {
    let refused = |shape: ProfileShape, rise: f64| Profile::new(&shape, SPAN, rise).is_err();
    assert!(refused(ProfileShape::Segmental, H));
    assert!(refused(ProfileShape::Segmental, 0.0));
    assert!(refused(ProfileShape::Semicircular, 4.0));
    assert!(refused(ProfileShape::Elliptical, -1.0));
    assert!(refused(ProfileShape::Parabolic, f64::NAN));
    assert!(refused(
        ProfileShape::ThreeCentred { haunch_radius: 3.0 },
        3.0
    ));
    assert!(refused(
        ProfileShape::ThreeCentred { haunch_radius: 1.0 },
        6.0
    ));
    assert!(refused(ProfileShape::Pointed, 4.9));
    let points = |p: Vec<Point>| Profile::new(&ProfileShape::Points(p), 0.0, 0.0).is_err();
    assert!(points(vec![(0.0, 0.0), (1.0, 1.0)]));
    assert!(points(vec![(0.0, 0.0), (1.0, 1.0), (1.0, 0.0)]));
    assert!(points(vec![
        (0.0, 0.0),
        (1.0, 1.0),
        (2.0, 0.5),
        (3.0, 1.0),
        (4.0, 0.0)
    ]));
    assert!(points(vec![(0.0, 0.0), (1.0, -1.0), (2.0, 0.0)]));
    assert!(points(vec![(0.0, 0.0), (1.0, f64::INFINITY), (2.0, 0.0)]));
    let profile = Profile::new(&ProfileShape::Parabolic, SPAN, 3.0).expect("a profile");
    assert!(profile.chain(SPAN, 10).is_err());
    assert!(profile.chain(0.0, 10).is_err());
    // A measured intrados turning sharply inwards (a concave corner at (±1, 0.5)): the joints
    // either side cross inside a thick arch.
    let sharp = vec![(-4.0, 0.0), (-1.0, 0.5), (0.0, 4.0), (1.0, 0.5), (4.0, 0.0)];
    let sharp = Profile::new(&ProfileShape::Points(sharp), 0.0, 0.0).expect("a profile");
    assert!(sharp.chain(3.0, 200).is_err());
}
