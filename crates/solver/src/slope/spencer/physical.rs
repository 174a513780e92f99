//! Which roots of Spencer's two equations are physical: F within [`PHYSICAL_F`] (the bracketing
//! range of the solver) and a frictional resistance Σ N'·tan φ' that is not negative.

use super::equations::Equations;

/// The range of F a physical root lies in (the bracketing range of the solver).
pub const PHYSICAL_F: (f64, f64) = (1e-6, 1e6);

/// Whether a root is physical: F within [`PHYSICAL_F`] and Σ N'·tan φ' ≥ 0.
pub(super) fn is_physical(equations: &Equations, f: f64, theta: f64) -> bool {
    let (sin_t, cos_t) = theta.sin_cos();
    let friction: f64 = equations
        .terms
        .iter()
        .map(|t| {
            let q = Equations::q(t, f, (sin_t, cos_t)).q;
            // sin(α − θ) from the stored sin α, cos α.
            let normal = t.a_n + q * (t.sin_alpha * cos_t - t.cos_alpha * sin_t);
            (normal - t.pore_force) * t.tan_phi
        })
        .sum();
    (PHYSICAL_F.0..=PHYSICAL_F.1).contains(&f) && friction >= 0.0
}
