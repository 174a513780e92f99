//! The solution of the two equations for (F, θ): damped Newton with analytic derivatives, and
//! Spencer's own construction (F_f and F_m crossing, found by Brent's method) when Newton fails.

use super::equations::{Equations, Residuals};
use super::physical::is_physical;
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

/// Which roots Newton's method may step to.
#[derive(Clone, Copy, PartialEq)]
enum Branch {
    /// Every m_α positive, |θ| ≤ 89° (the classic domain).
    Admissible,
    /// Any (F > 0, θ): the poles where an m_α vanishes may be crossed.
    Any,
}

/// Bishop's F as the start (looked for from `near`, a neighbouring surface's F, first), damped
/// Newton, and the bracketing fallback when Newton fails.
pub(super) fn solve_equations(
    equations: &Equations,
    settings: &SpencerSettings,
    near: Option<f64>,
) -> EquationsSolution {
    let mut evaluations = 0;
    let bishop = equations.f_at_theta_from(0.0, true, near, &mut evaluations);
    let start = (bishop.unwrap_or(1.0), 0.0);
    let mut iterations = 0;
    let mut used_fallback = false;
    let mut root = newton(
        equations,
        start,
        settings,
        Branch::Admissible,
        &mut iterations,
    );
    if root.is_none() && settings.fallback {
        used_fallback = true;
        root = fallback(equations, settings, &mut iterations);
        // With φ' = 0 the moment equation alone fixes F (SpencerStatus::MomentOnly): a root
        // past the poles would add only a θ.
        if root.is_none() && !equations.is_frictionless() {
            root = beyond_poles(equations, start.0, settings, &mut iterations);
        }
    }
    EquationsSolution {
        root,
        bishop,
        iterations,
        used_fallback,
    }
}

/// Newton iterations and step halvings per start of [`beyond_poles`].
const BEYOND_ITERATIONS: usize = 8;
const BEYOND_HALVINGS: usize = 6;

/// Starts of [`beyond_poles`]: θ from 0 outwards in steps of 15°.
const BEYOND_STARTS_DEG: [f64; 11] = [
    0.0, 15.0, -15.0, 30.0, -30.0, 45.0, -45.0, 60.0, -60.0, 75.0, -75.0,
];

/// A root past the poles, where the classic domain (every m_α > 0) has none.
///
/// The two equations are those of every slice's equilibrium, which hold whatever the sign of
/// m_α; m_α = 0 only makes one slice's Q formula singular (its two equations are then
/// dependent). With φ' near 0, F hardly depends on θ and the force equation finds its root at
/// an inclination where a steep base has cos(α − θ) < 0: no root has every m_α positive,
/// though many, past one pole or several, give the same F (Duncan & Wright's clay slope at
/// φ' = 0.5°: F = 1.1418–1.1420 on 27 of them). Programs that take the normal force from
/// vertical equilibrium (m_α = cos α + sin α·tan φ'/F) do not see these poles and report such
/// roots as converged.
///
/// A root is sound when it is physical as any root must be and every slice past its pole is
/// pressed onto its base ([`sound_root`]). Among sound roots, the one past the fewest
/// poles, then the one nearest to horizontal inter-slice forces, is the answer: θ is reported
/// in (−90°, 90°], the poles counted as the slices whose m_α has the minority sign (θ and
/// θ + 180° are the same line of action, with every Q and m_α of opposite sign).
fn beyond_poles(
    equations: &Equations,
    f_start: f64,
    settings: &SpencerSettings,
    iterations: &mut usize,
) -> Option<(f64, f64)> {
    let mut best: Option<(usize, f64, (f64, f64))> = None;
    for degrees in BEYOND_STARTS_DEG {
        let start = (f_start, degrees.to_radians());
        let Some((f, theta)) = newton(equations, start, settings, Branch::Any, iterations) else {
            continue;
        };
        let theta = normalised(theta);
        let Some(poles) = sound_root(equations, f, theta) else {
            continue;
        };
        let better = best.is_none_or(|(p, t, _)| (poles, theta.abs()) < (p, t));
        if better {
            best = Some((poles, theta.abs(), (f, theta)));
        }
    }
    best.map(|(_, _, root)| root)
}

/// θ moved by multiples of 180° into (−90°, 90°].
fn normalised(theta: f64) -> f64 {
    use std::f64::consts::{FRAC_PI_2, PI};
    let t = theta - PI * (theta / PI).round();
    if t <= -FRAC_PI_2 {
        t + PI
    } else {
        t
    }
}

/// The poles a root lies past (slices whose m_α has the minority sign), when it is sound:
/// physical ([`is_physical`]), and every slice past its pole pressed onto its base
/// (N' ≥ 0 to rounding: near a pole N' is unbounded, and a slice held up by tension there is
/// the pole's artefact, not a mechanism).
fn sound_root(equations: &Equations, f: f64, theta: f64) -> Option<usize> {
    if !is_physical(equations, f, theta) {
        return None;
    }
    let trig = theta.sin_cos();
    let (sin_t, cos_t) = trig;
    let negative_majority = equations.m_alpha_mostly_negative(f, theta);
    let rounding = 1e-9 * equations.force_scale;
    let mut poles = 0;
    for t in &equations.terms {
        let r = Equations::q(t, f, trig);
        if (r.m_alpha <= 0.0) == negative_majority {
            continue;
        }
        poles += 1;
        let effective = t.a_n - t.pore_force + r.q * (t.sin_alpha * cos_t - t.cos_alpha * sin_t);
        if effective < -rounding {
            return None;
        }
    }
    Some(poles)
}

/// Damped Newton on (F, θ); `None` unless it converges (on the admissible branch: with every
/// m_α positive).
fn newton(
    equations: &Equations,
    (mut f, mut theta): (f64, f64),
    settings: &SpencerSettings,
    branch: Branch,
    iterations: &mut usize,
) -> Option<(f64, f64)> {
    // The squared norm of the residuals: ordered as the norm (no hypot per evaluation; scaled
    // residuals whose squares overflow are as unusable as their norm would be).
    let merit = |r: &Residuals| r.force * r.force + r.moment * r.moment;
    let admissible = |r: &Residuals| branch == Branch::Any || r.min_m_alpha > 0.0;
    let BranchLimits {
        max_theta,
        max_iterations,
        max_halvings,
    } = BranchLimits::of(branch, settings);
    let mut r = equations.evaluate(f, theta);
    if !admissible(&r) || !merit(&r).is_finite() {
        return None;
    }
    for _ in 0..max_iterations {
        *iterations += 1;
        let (mut df, mut dtheta) = limited_step(&r, f)?;
        let current = merit(&r);
        // A step within the tolerance from a point whose residual is already that of a
        // solution: the step's end is the root (to the tolerance, and quadratically closer),
        // with no evaluation there to confirm what the step's size says (a confirmation at
        // rounding level is often rejected, then halved to nothing).
        let tiny =
            df.abs() <= settings.tolerance * f.max(1.0) && dtheta.abs() <= settings.tolerance;
        if tiny && current <= SOLVED_RESIDUAL * SOLVED_RESIDUAL {
            return Some((f + df, (theta + dtheta).clamp(-max_theta, max_theta)));
        }
        let mut accepted = None;
        for _ in 0..max_halvings {
            let (f_new, theta_new) = (f + df, (theta + dtheta).clamp(-max_theta, max_theta));
            // A step below rounding lands on the current point: every shorter one would be
            // evaluated there too, and rejected as it (the merit does not fall below itself).
            if f_new == f && theta_new == theta {
                break;
            }
            let r_new = equations.evaluate(f_new, theta_new);
            let m = merit(&r_new);
            if admissible(&r_new) && m.is_finite() && (m < current || m == 0.0) {
                accepted = Some((f_new, theta_new, r_new));
                break;
            }
            df *= 0.5;
            dtheta *= 0.5;
        }
        // No step lowers the residual: fine if it is already at rounding level (a start on the
        // root, as the fallback gives), a failure otherwise.
        let Some((f_new, theta_new, r_new)) = accepted else {
            return (current <= ROUNDING_RESIDUAL * ROUNDING_RESIDUAL).then_some((f, theta));
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
            return (merit(&r) <= SOLVED_RESIDUAL * SOLVED_RESIDUAL).then_some((f, theta));
        }
    }
    // Newton stalled short of the tolerance: accept only if the residual is at rounding level.
    (merit(&r) <= ROUNDING_RESIDUAL * ROUNDING_RESIDUAL).then_some((f, theta))
}

/// How far Newton's method may go on a branch.
struct BranchLimits {
    /// The largest |θ| a step may reach.
    max_theta: f64,
    /// Newton iterations at most.
    max_iterations: usize,
    /// Step halvings per iteration at most.
    max_halvings: usize,
}

impl BranchLimits {
    /// The limits on `branch`: past the poles Newton's method either settles quickly or
    /// wanders between them, so a start that does not settle is given up early, the next one
    /// tried.
    fn of(branch: Branch, settings: &SpencerSettings) -> Self {
        const MAX_THETA: f64 = 89.0 * std::f64::consts::PI / 180.0;
        let max_theta = match branch {
            Branch::Admissible => MAX_THETA,
            Branch::Any => f64::INFINITY,
        };
        let (max_iterations, max_halvings) = match branch {
            Branch::Admissible => (settings.max_iterations, 40),
            Branch::Any => (
                settings.max_iterations.min(BEYOND_ITERATIONS),
                BEYOND_HALVINGS,
            ),
        };
        Self {
            max_theta,
            max_iterations,
            max_halvings,
        }
    }
}

/// The Newton step (dF, dθ) from the residuals `r` at F = `f`, limited so that F stays positive
/// and θ moves by at most ~11°; `None` where the Jacobian is singular.
#[inline]
fn limited_step(r: &Residuals, f: f64) -> Option<(f64, f64)> {
    const MAX_THETA_STEP: f64 = 0.2; // rad
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
    Some((df, dtheta))
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
        newton(equations, guess, settings, Branch::Admissible, iterations)
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
