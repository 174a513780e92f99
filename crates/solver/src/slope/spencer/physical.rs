//! Which roots of Spencer's two equations are physical: F within [`PHYSICAL_F`] (the bracketing
//! range of the solver), no base below the apex of its strength envelope, and a frictional
//! resistance Σ N'·tan φ' that is not negative.

use super::equations::Equations;

/// The range of F a physical root lies in (the bracketing range of the solver).
pub const PHYSICAL_F: (f64, f64) = (1e-6, 1e6);

/// Whether a root is physical: F within [`PHYSICAL_F`], Σ N'·tan φ' ≥ 0, and every base's
/// available strength c'·l + N'·tan φ' not negative: a normal stress below the apex of the
/// Mohr–Coulomb envelope, σ' < −c'/tan φ', would give the base a negative strength (the soil
/// has parted there). Near a pole of m_α, where a slice's base reaction at the mobilised
/// friction is nearly parallel to the inter-slice forces, the base normal force grows without
/// bound, of either sign: such roots fail here. A slice that carries a known force of its own
/// (a line load, a support, the water in a crack) is left out of the per-base test: the slices
/// cannot spread such a force, and as they get thinner its reaction concentrates on the one
/// base under it whatever the root (the water in a crack pulls the crack's foot open at any
/// F); the sum still counts it.
pub(super) fn is_physical(equations: &Equations, f: f64, theta: f64) -> bool {
    let (sin_t, cos_t) = theta.sin_cos();
    let normals = equations.terms.iter().map(|t| {
        let q = Equations::q(t, f, (sin_t, cos_t)).q;
        // sin(α − θ) from the stored sin α, cos α.
        t.a_n + q * (t.sin_alpha * cos_t - t.cos_alpha * sin_t) - t.pore_force
    });
    (PHYSICAL_F.0..=PHYSICAL_F.1).contains(&f) && strength_holds(equations, normals)
}

/// The strength part of [`is_physical`] for any method's effective normal forces N' (one a
/// slice, in order): every base not loaded by a known force of its own at or above its
/// envelope's apex, and Σ N'·tan φ' ≥ 0.
pub(super) fn strength_holds(equations: &Equations, normals: impl Iterator<Item = f64>) -> bool {
    let rounding = 1e-9 * equations.force_scale;
    let mut friction = 0.0;
    for (t, normal) in equations.terms.iter().zip(normals) {
        let frictional = normal * t.tan_phi;
        if !t.loaded && t.cohesion + frictional < -rounding {
            return false;
        }
        friction += frictional;
    }
    friction >= 0.0
}
