//! Everything behind a converged (F, θ): the forces on every slice, the line of thrust (moments
//! about each base middle, Spencer 1973) and the flags an engineer should look at.

use super::equations::{Equations, SliceResultant, SliceTerms};
use super::newton::EquationsSolution;
use super::solution::{SliceForces, SpencerSolution, SpencerStatus, ThrustPoint};
use crate::slope::slices::{BaseSlice, SliceModel};

/// Denominators m_α below this are reported: the base normal force becomes unreliable there
/// (a common guard in slope programs; Duncan & Wright recommend 0.2).
pub const SMALL_DENOMINATOR: f64 = 0.2;

/// Forces, line of thrust and flags at the converged (F, θ).
pub(super) fn describe(
    model: &SliceModel,
    equations: &Equations,
    f: f64,
    theta: f64,
    solved: &EquationsSolution,
) -> SpencerSolution {
    let slices = &model.slices;
    let residuals = equations.evaluate(f, theta);
    let (sin_t, cos_t) = theta.sin_cos();
    let mut slice_forces = Vec::with_capacity(slices.len());
    let mut thrust_line = Vec::with_capacity(slices.len().saturating_sub(1));
    let mut effective_thrust_line = Vec::with_capacity(slices.len().saturating_sub(1));
    let mut small_m_alpha_slices = Vec::new();
    let mut negative_effective_normal_slices = Vec::new();
    // Inter-slice force and the height of its point of action on the left boundary of the
    // current slice; the lower end carries none.
    let (mut z_left, mut y_left) = (0.0, model.lower_end().1);
    let n = slices.len();
    // Past the poles ([`super::newton`]) m_α may be negative on some slices, or on most (the
    // same root with θ + 180°): the slices flagged are those whose m_α, taken with the sign
    // of the majority, is small or negative.
    let sign = majority_sign(equations, f, theta);
    for (i, (slice, t)) in slices.iter().zip(&equations.terms).enumerate() {
        let SliceResultant { q, m_alpha, .. } = Equations::q(t, f, (sin_t, cos_t));
        // Z_{i+1} = Z_i − Q_i: Q is the net push of the two neighbours along (cos θ, sin θ).
        let z_right = z_left - q;
        let right = if i + 1 == n { 0.0 } else { z_right };
        let forces = forces_on_slice(slice, t, q, m_alpha, f, theta, right);
        if sign * m_alpha < SMALL_DENOMINATOR {
            small_m_alpha_slices.push(i);
        }
        if forces.effective_normal_force < 0.0 {
            negative_effective_normal_slices.push(i);
        }
        slice_forces.push(forces);
        if i + 1 < n {
            let (total, effective) = boundary_thrust(
                slice,
                t.moment,
                (z_left, y_left),
                z_right,
                (sin_t, cos_t),
                i,
            );
            (z_left, y_left) = (z_right, total.y.unwrap_or(slice.base_middle.1));
            thrust_line.push(total);
            effective_thrust_line.push(effective);
        }
    }
    SpencerSolution {
        status: SpencerStatus::Converged,
        factor_of_safety: Some(f),
        theta_rad: Some(theta),
        bishop_factor_of_safety: solved.bishop,
        iterations: solved.iterations,
        used_fallback: solved.used_fallback,
        slice_forces,
        thrust_line,
        effective_thrust_line,
        small_m_alpha_slices,
        negative_effective_normal_slices,
        unphysical_root: None,
        tension_dropped_slices: Vec::new(),
        strength: Default::default(),
        residual: Some(residuals.force.abs().max(residuals.moment.abs())).filter(|r| r.is_finite()),
    }
}

/// The sign of m_α on most slices: past the poles ([`super::newton`]) m_α may be negative on
/// some slices, or on most (the same root with θ + 180°).
fn majority_sign(equations: &Equations, f: f64, theta: f64) -> f64 {
    if equations.m_alpha_mostly_negative(f, theta) {
        -1.0
    } else {
        1.0
    }
}

/// The forces on one slice at (F, θ), its inter-slice resultant Q and m_α given, with the
/// inter-slice force `interslice_force_right` on its right side as reported.
#[inline]
fn forces_on_slice(
    slice: &BaseSlice,
    t: &SliceTerms,
    q: f64,
    m_alpha: f64,
    f: f64,
    theta: f64,
    interslice_force_right: f64,
) -> SliceForces {
    let weight = slice.weight;
    let pore_pressure = slice.pore_pressure;
    // N = A_n + Q·sin(α−θ); S from the Mohr–Coulomb criterion with the factor F.
    let normal_force = t.a_n + q * (slice.base_inclination_rad() - theta).sin();
    let effective_normal_force = normal_force - t.pore_force;
    let shear_force = (slice.cohesion * slice.base_length + effective_normal_force * t.tan_phi) / f;
    SliceForces {
        weight,
        pore_pressure,
        normal_force,
        effective_normal_force,
        shear_force,
        interslice_resultant: q,
        interslice_force_right,
        m_alpha,
        available_shear_strength: slice.cohesion
            + effective_normal_force / slice.base_length * t.tan_phi,
    }
}

/// The line of thrust on the right boundary of slice `i` (total and effective), from moments
/// about its base middle (1973): the left force +Z_i·(cos θ, sin θ) at (x_left, y_left), the
/// right force −Z_{i+1}·(cos θ, sin θ) at (x_right, y_right) and the known moment sum to zero.
fn boundary_thrust(
    slice: &BaseSlice,
    known_moment: f64,
    (z_left, y_left): (f64, f64),
    z_right: f64,
    (sin_t, cos_t): (f64, f64),
    i: usize,
) -> (ThrustPoint, ThrustPoint) {
    let (xb, yb) = slice.base_middle;
    let left = (slice.x_left - xb) * z_left * sin_t - (y_left - yb) * z_left * cos_t;
    let y_right = (z_right.abs() * cos_t.abs() > f64::MIN_POSITIVE)
        .then(|| {
            yb + ((slice.x_right - xb) * z_right * sin_t - left - known_moment) / (z_right * cos_t)
        })
        .filter(|y| y.is_finite());
    let top = slice.top_right_y;
    let total = ThrustPoint {
        boundary: i + 1,
        x: slice.x_right,
        y: y_right,
        force: z_right,
        is_inside_slice: y_right.is_some_and(|y| y >= slice.base_right_y && y <= top),
    };
    // Effective: the horizontal component less the side water U at y_U, same vertical
    // component; its point from the moments of the horizontal components.
    let (water, y_water) = slice.side_water;
    let horizontal = z_right * cos_t - water;
    let y_effective = y_right
        .map(|y| (z_right * cos_t * y - water * y_water) / horizontal)
        .filter(|y| y.is_finite() && horizontal.abs() > f64::MIN_POSITIVE);
    let effective = ThrustPoint {
        boundary: i + 1,
        x: slice.x_right,
        y: y_effective,
        force: horizontal.hypot(z_right * sin_t),
        is_inside_slice: y_effective.is_some_and(|y| y >= slice.base_right_y && y <= top),
    };
    (total, effective)
}
