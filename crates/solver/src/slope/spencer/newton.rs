//! The solution of the two equations for (F, θ): damped Newton with analytic derivatives, and
//! Spencer's own construction (F_f and F_m crossing, found by Brent's method) when Newton fails.

use super::equations::{Equations, Residuals};
use super::solution::SpencerSettings;
use crate::numerics::brent;

/// A scaled residual this small is rounding: the equations are solved.
const ROUNDING_RESIDUAL: f64 = 1e3 * f64::EPSILON;

/// The largest scaled residual (force / ΣW, moment / (ΣW·R)) accepted at convergence.
const SOLVED_RESIDUAL: f64 = 1e-9;

/// What [`solve_equations`] found.
pub(super) struct EquationsSolution {
    /// (F, θ) solving both equations.
    pub root: Option<(f64, f64)>,
    /// Bishop's F (θ = 0, moment equation), when it has a root.
    pub bishop: Option<f64>,
    /// Newton iterations plus fallback evaluations.
    pub iterations: usize,
    /// Whether the bracketing fallback was needed.
    pub used_fallback: bool,
}

/// Bishop's F as the start, damped Newton, and the bracketing fallback when Newton fails.
pub(super) fn solve_equations(
    equations: &Equations,
    settings: &SpencerSettings,
) -> EquationsSolution {
    let mut evaluations = 0;
    let bishop = equations.f_at_theta(0.0, true, &mut evaluations);
    let start = (bishop.unwrap_or(1.0), 0.0);
    let mut iterations = 0;
    let mut used_fallback = false;
    let mut root = newton(equations, start, settings, &mut iterations);
    if root.is_none() && settings.fallback {
        used_fallback = true;
        root = fallback(equations, settings, &mut iterations);
    }
    EquationsSolution {
        root,
        bishop,
        iterations,
        used_fallback,
    }
}

/// Damped Newton on (F, θ); `None` unless it converges with every m_α positive.
fn newton(
    equations: &Equations,
    (mut f, mut theta): (f64, f64),
    settings: &SpencerSettings,
    iterations: &mut usize,
) -> Option<(f64, f64)> {
    const MAX_THETA_STEP: f64 = 0.2; // rad
    const MAX_THETA: f64 = 89.0 * std::f64::consts::PI / 180.0;
    let merit = |r: &Residuals| r.force.hypot(r.moment);
    let mut r = equations.evaluate(f, theta);
    if r.min_m_alpha <= 0.0 || !merit(&r).is_finite() {
        return None;
    }
    for _ in 0..settings.max_iterations {
        *iterations += 1;
        let det = r.d_force.0 * r.d_moment.1 - r.d_force.1 * r.d_moment.0;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let mut df = -(r.force * r.d_moment.1 - r.moment * r.d_force.1) / det;
        let mut dtheta = -(r.d_force.0 * r.moment - r.d_moment.0 * r.force) / det;
        // Step limits: F stays positive, θ moves by at most ~11° a step.
        let scale = (1.0f64)
            .min(0.5 * f / df.abs().max(f64::MIN_POSITIVE))
            .min(MAX_THETA_STEP / dtheta.abs().max(f64::MIN_POSITIVE));
        df *= scale;
        dtheta *= scale;
        let current = merit(&r);
        let mut accepted = None;
        for _ in 0..40 {
            let (f_new, theta_new) = (f + df, (theta + dtheta).clamp(-MAX_THETA, MAX_THETA));
            // A step below rounding lands on the current point: every shorter one would be
            // evaluated there too, and rejected as it (the merit does not fall below itself).
            if f_new == f && theta_new == theta {
                break;
            }
            let r_new = equations.evaluate(f_new, theta_new);
            let m = merit(&r_new);
            if r_new.min_m_alpha > 0.0 && m.is_finite() && (m < current || m == 0.0) {
                accepted = Some((f_new, theta_new, r_new));
                break;
            }
            df *= 0.5;
            dtheta *= 0.5;
        }
        // No step lowers the residual: fine if it is already at rounding level (a start on the
        // root, as the fallback gives), a failure otherwise.
        let Some((f_new, theta_new, r_new)) = accepted else {
            return (current <= ROUNDING_RESIDUAL).then_some((f, theta));
        };
        let settled = (f_new - f).abs() <= settings.tolerance * f_new.max(1.0)
            && (theta_new - theta).abs() <= settings.tolerance;
        (f, theta, r) = (f_new, theta_new, r_new);
        if merit(&r) == 0.0 {
            return Some((f, theta));
        }
        if settled {
            // Small steps alone can mean a minimum of the residual that is not a root (the
            // line search shortens the steps there): only a vanishing residual is a solution.
            return (merit(&r) <= SOLVED_RESIDUAL).then_some((f, theta));
        }
    }
    // Newton stalled short of the tolerance: accept only if the residual is at rounding level.
    (merit(&r) <= ROUNDING_RESIDUAL).then_some((f, theta))
}

/// Spencer's own construction: F_f(θ) and F_m(θ) from the two equations separately, and
/// Brent's method on their difference where it changes sign, searching outwards from θ = 0 in
/// steps of 4° (roots nearest to horizontal inter-slice forces first). Each crossing is
/// polished by Newton; a crossing that is a jump of the difference (a pole of one of the
/// curves), not a root, fails to polish and the walk goes on.
fn fallback(
    equations: &Equations,
    settings: &SpencerSettings,
    iterations: &mut usize,
) -> Option<(f64, f64)> {
    const STEP_DEG: f64 = 4.0;
    const LIMIT_DEG: f64 = 88.0;
    let mut evaluations = 0;
    // F_m is not looked for where F_f has no value: the difference is undefined either way.
    let difference = |theta: f64, evaluations: &mut usize| -> f64 {
        equations
            .f_at_theta(theta, false, evaluations)
            .and_then(|ff| Some(ff - equations.f_at_theta(theta, true, evaluations)?))
            .unwrap_or(f64::NAN)
    };
    let origin = difference(0.0, &mut evaluations);
    // A bracket [a, b] of F_f − F_m: Brent, then Newton on both equations from there.
    let mut solve_in = |a: f64, fa: f64, b: f64, fb: f64, evaluations: &mut usize| {
        let root = brent(|t| difference(t, evaluations), a, b, fa, fb, 1e-13, 200)?;
        let guess = (equations.f_at_theta(root.x, false, evaluations)?, root.x);
        newton(equations, guess, settings, iterations)
    };
    // The last finite value on each side of 0.
    let (mut up, mut down) = ((0.0f64, origin), (0.0f64, origin));
    // Whether the edge after the last finite value was already probed, per side.
    let mut probed = [false, false];
    let steps = (LIMIT_DEG / STEP_DEG) as usize;
    for i in 1..=steps {
        for side in [1.0, -1.0] {
            let probed = &mut probed[usize::from(side < 0.0)];
            let theta = (side * STEP_DEG * i as f64).to_radians();
            let value = difference(theta, &mut evaluations);
            let last = if side > 0.0 { &mut up } else { &mut down };
            let (a, fa) = *last;
            if value.is_finite() && fa.is_finite() && value * fa <= 0.0 {
                if let Some(solution) = solve_in(a, fa, theta, value, &mut evaluations) {
                    *iterations += evaluations;
                    return Some(solution);
                }
            } else if !value.is_finite() && fa.is_finite() && !*probed {
                *probed = true;
                // The curves end between a and θ (an m_α reaches zero): a root can hide just
                // before that edge, so find the edge and look there.
                let (mut inside, mut outside) = (a, theta);
                let mut edge_value = fa;
                // 24 halvings place the edge within 4°/2²⁴ ≈ 2e-7°.
                for _ in 0..24 {
                    let middle = 0.5 * (inside + outside);
                    let v = difference(middle, &mut evaluations);
                    if v.is_finite() {
                        (inside, edge_value) = (middle, v);
                    } else {
                        outside = middle;
                    }
                }
                if edge_value * fa <= 0.0 && inside != a {
                    if let Some(solution) = solve_in(a, fa, inside, edge_value, &mut evaluations) {
                        *iterations += evaluations;
                        return Some(solution);
                    }
                }
                // Carry on from the edge: a later finite stretch is compared with it.
                *last = (inside, edge_value);
            }
            if value.is_finite() {
                *last = (theta, value);
                *probed = false;
            }
        }
    }
    *iterations += evaluations;
    None
}
