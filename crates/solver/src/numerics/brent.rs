//! Root finding in one variable on a bracket: Brent's method (Brent 1973, *Algorithms for
//! Minimization without Derivatives*, ch. 4), used by Spencer's method for F at fixed θ and for
//! θ itself when Newton's method has to fall back.

/// Outcome of [`brent`]: the root estimate and the evaluations spent.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    /// The estimate of the root.
    pub x: f64,
    /// Function evaluations used, including none for the two bracket ends passed in.
    pub evaluations: usize,
}

/// Finds a root of `f` in `[a, b]`, given `fa = f(a)` and `fb = f(b)` of opposite signs.
///
/// Stops when the bracket is narrower than `x_tolerance` (absolute) or after `max_evaluations`;
/// returns `None` when the ends do not bracket a sign change or `f` returns a non-finite value.
pub fn brent(
    mut f: impl FnMut(f64) -> f64,
    mut a: f64,
    mut b: f64,
    mut fa: f64,
    mut fb: f64,
    x_tolerance: f64,
    max_evaluations: usize,
) -> Option<Root> {
    if !(fa.is_finite() && fb.is_finite()) || fa * fb > 0.0 {
        return None;
    }
    if let Some(root) = root_at_an_end(a, b, fa, fb) {
        return Some(root);
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for evaluations in 1..=max_evaluations {
        if fb * fc > 0.0 {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * x_tolerance;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Some(Root {
                x: b,
                evaluations: evaluations - 1,
            });
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let (p, q) = interpolation_step(a, b, c, fa, fb, fc, m);
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
        if !fb.is_finite() {
            return None;
        }
    }
    None
}

/// The root when one end of the bracket is one already (`a` first), with no evaluation spent.
fn root_at_an_end(a: f64, b: f64, fa: f64, fb: f64) -> Option<Root> {
    if fa == 0.0 {
        return Some(Root {
            x: a,
            evaluations: 0,
        });
    }
    if fb == 0.0 {
        return Some(Root {
            x: b,
            evaluations: 0,
        });
    }
    None
}

/// The bracket's next step as p / q (p ≥ 0): inverse quadratic interpolation through a, b and
/// c, or the secant step when only two points differ (`m` half the bracket, from b to c).
#[inline]
fn interpolation_step(a: f64, b: f64, c: f64, fa: f64, fb: f64, fc: f64, m: f64) -> (f64, f64) {
    let s = fb / fa;
    let (mut p, mut q);
    if a == c {
        p = 2.0 * m * s;
        q = 1.0 - s;
    } else {
        let qa = fa / fc;
        let r = fb / fc;
        p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
    }
    if p > 0.0 {
        q = -q;
    } else {
        p = -p;
    }
    (p, q)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_root_of_two() {
        let f = |x: f64| x * x * x - 2.0;
        let root = brent(f, 0.0, 2.0, f(0.0), f(2.0), 1e-14, 100).unwrap();
        // 1e-13: tolerance asked for plus rounding.
        assert!((root.x - 2f64.cbrt()).abs() < 1e-13);
        assert!(root.evaluations < 20);
    }

    #[test]
    fn no_bracket_is_none() {
        assert!(brent(|x| x * x + 1.0, -1.0, 1.0, 2.0, 2.0, 1e-12, 50).is_none());
    }
}
