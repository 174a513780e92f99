//! Spencer's method: the factor of safety F and the inclination θ of parallel inter-slice
//! forces that satisfy both force and moment equilibrium (Spencer 1967; moment equation of the
//! 1973 revision, about each base middle).
//!
//! # Equations (model §2.2)
//! Slice i carries known forces (weight W, seismic k_h·W towards the toe and k_v·W downwards,
//! external F_x, F_y): A_n is their component normal to the base (pressing it), A_t their
//! component along the base in the driving sense. With the base shear mobilised as
//! S = (c'·l + (N − u·l)·tan φ')/F, the resultant Q of the two inter-slice forces, taken
//! positive along (cos θ, sin θ), is
//!
//! ```text
//!   Q = (A_t − [c'·l + (A_n − u·l)·tan φ'] / F) / (cos(α−θ) + sin(α−θ)·tan φ' / F)
//! ```
//!
//! and equilibrium needs Σ Q = 0 (forces; the Q are parallel) and
//! Σ Q·((x_b − x_c)·sin θ − (y_b − y_c)·cos θ) = Σ M (moments about the circle centre, which
//! the sum of the per-slice moment equations about the base middles (x_b, y_b) reduces to; M
//! are the moments of the known forces about the base middles). At θ = 0 the moment equation
//! alone is Bishop's simplified method.
//!
//! Vertical body forces (W, k_v·W) act on the vertical through the base middle, the usual
//! method-of-slices idealisation with which the thesis reproduces Spencer's numbers; the
//! horizontal seismic force acts at the height of the slice centroid.
//!
//! # Solution
//! Damped Newton on (F, θ) with analytic derivatives, step limits and a check that every
//! denominator m_α = cos(α−θ) + sin(α−θ)·tan φ'/F stays positive; if it fails, a bracketing
//! fallback: for each θ on a grid, F_f(θ) and F_m(θ) from the two equations separately, then
//! Brent's method on F_f − F_m (Spencer's own figure: the answer is where the curves cross).
//! Where no root has every m_α positive, Newton's method past the poles of m_α (see
//! `newton::beyond_poles` for which of those roots is sound and which is answered).

mod consistent;
mod describe;
mod equations;
mod kernel;
pub mod methods;
mod newton;
mod nonlinear;
mod physical;
mod problem;
mod scan;
mod solution;
#[cfg(test)]
mod tests;

use consistent::{consistent, is_nonlinear, Step};
use describe::describe;
use equations::Equations;
use newton::solve_equations;
use nonlinear::effective_normals;
use physical::is_physical;

use crate::slope::slices::SliceModel;

pub use describe::SMALL_DENOMINATOR;
pub use physical::PHYSICAL_F;
pub use problem::{ExternalLoad, Seismic, SlopeProblem, Soil};
pub use solution::{
    NegativeEffectiveStress, SliceForces, SpencerSettings, SpencerSolution, SpencerStatus,
    ThrustPoint,
};

/// Spencer's F for one slip surface without the per-slice forces: what a search needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpencerFactor {
    /// The factor of safety.
    pub factor_of_safety: f64,
    /// θ in radians; `None` when φ' = 0 and F is from moment equilibrium alone
    /// ([`SpencerStatus::MomentOnly`]).
    pub theta_rad: Option<f64>,
}

/// Spencer's (F, θ) alone, without the per-slice forces: what a search over circles needs.
/// `None` when the equations have no physical solution.
pub fn solve_spencer_factor(
    model: &SliceModel,
    settings: &SpencerSettings,
) -> Option<SpencerFactor> {
    match spencer_factor_outcome(model, settings) {
        FactorOutcome::Solved(s) => Some(s),
        FactorOutcome::Unsolved { .. } | FactorOutcome::Undriven => None,
    }
}

/// Spencer's F for a search, or why not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FactorOutcome {
    /// Solved.
    Solved(SpencerFactor),
    /// No physical solution; Bishop's F for the same surface when it has one (an indication
    /// of what the surface would give, for the search's report).
    Unsolved {
        /// Bishop's simplified F (circles, or a given moment centre).
        bishop: Option<f64>,
    },
    /// A circle whose known forces drive no rotation towards the toe (a lens of level ground
    /// symmetric about the centre's vertical, say): nothing to hold, no F. Not a candidate of a
    /// search, and not counted as unsolved.
    Undriven,
}

/// Spencer's F for a search, or Bishop's F as an indication where Spencer's has no solution;
/// on nonlinear envelopes, at their consistent state.
pub fn spencer_factor_outcome(model: &SliceModel, settings: &SpencerSettings) -> FactorOutcome {
    consistent_factor_outcome(model, settings, None)
}

/// [`spencer_factor_outcome`] of a search's trial surface next to one whose F `near` is known:
/// Bishop's F, which starts Newton's method on both equations, is looked for from there first
/// (from F = 1 as without a neighbour where it does not settle). Bishop's equation has one
/// root where the classic domain's m_α are positive on an ordinary surface, so the start is
/// the same to rounding, in fewer iterations; Spencer's root is then the one found without
/// a neighbour. (Starting Spencer's own iterations at a neighbour's (F, θ) is cheaper still,
/// but finds other roots of the two equations where they have several.)
pub fn spencer_factor_outcome_near(
    model: &SliceModel,
    settings: &SpencerSettings,
    near: Option<f64>,
) -> FactorOutcome {
    consistent_factor_outcome(model, settings, near)
}

/// [`spencer_factor_outcome_near`] with each base's strength as it stands.
fn linear_factor_outcome(
    model: &SliceModel,
    settings: &SpencerSettings,
    near: Option<f64>,
) -> FactorOutcome {
    if settings.negative_effective_stress != NegativeEffectiveStress::Keep {
        if !drives_towards_toe(model) {
            return FactorOutcome::Undriven;
        }
        let s = solve_tension(model, settings);
        return match s.factor_of_safety {
            Some(f) => FactorOutcome::Solved(SpencerFactor {
                factor_of_safety: f,
                theta_rad: s.theta_rad,
            }),
            None => FactorOutcome::Unsolved {
                bishop: s.bishop_factor_of_safety,
            },
        };
    }
    let equations = Equations::new(model);
    if model.circular && !methods::drives(&equations.terms) {
        return FactorOutcome::Undriven;
    }
    // φ' = 0 on a circle: the moment equation about the centre alone fixes F whatever the
    // inter-slice forces (the base normals pass through the centre, the shear is c'l/F), so
    // Bishop's F is Spencer's; no need to look for θ.
    if equations.is_frictionless() && model.circular {
        let mut evaluations = 0;
        return match equations.f_at_theta_from(0.0, true, near, &mut evaluations) {
            Some(f) => FactorOutcome::Solved(SpencerFactor {
                factor_of_safety: f,
                theta_rad: None,
            }),
            None => FactorOutcome::Unsolved { bishop: None },
        };
    }
    let mut solved = solve_equations(&equations, settings, near);
    solved.bishop = reported_bishop(model, solved.bishop);
    match (solved.root, solved.bishop) {
        (Some((f, theta)), _) if is_physical(&equations, f, theta) => {
            FactorOutcome::Solved(SpencerFactor {
                factor_of_safety: f,
                theta_rad: Some(theta),
            })
        }
        // φ' = 0: the moment equation alone is exact (see SpencerStatus::MomentOnly).
        (None, Some(f)) if equations.is_frictionless() && model.circular => {
            FactorOutcome::Solved(SpencerFactor {
                factor_of_safety: f,
                theta_rad: None,
            })
        }
        (_, bishop) => FactorOutcome::Unsolved { bishop },
    }
}

/// Whether anything drives the mass towards the toe: always for a polyline; for a circle, the
/// known forces' moment about its centre (a lens of level ground symmetric about the centre's
/// vertical has none, and nothing to hold).
pub fn drives_towards_toe(model: &SliceModel) -> bool {
    !model.circular || methods::model_drives(model)
}

/// Bishop's F as reported: a moment equation about the centre of rotation, meaningless without
/// one. `about_reference` is Bishop's F about the model's reference (Spencer's start), which is
/// that centre for a circle.
fn reported_bishop(model: &SliceModel, about_reference: Option<f64>) -> Option<f64> {
    match model.moment_centre {
        Some(centre) if centre == model.reference => about_reference,
        Some(_) => methods::bishop_factor(model),
        None => None,
    }
}

/// Solves Spencer's two equations for the slip surface of `model`, with the treatment of
/// negative effective stress of `settings`; on nonlinear envelopes, to their consistent state.
pub fn solve_spencer(model: &SliceModel, settings: &SpencerSettings) -> SpencerSolution {
    if !is_nonlinear(model) {
        return solve_tension(model, settings);
    }
    solve_consistent(model, settings).0
}

/// Spencer's equations with the treatment of tension of `settings`, each base's strength as
/// it stands.
fn solve_tension(model: &SliceModel, settings: &SpencerSettings) -> SpencerSolution {
    let mut solution = solve_classic(model, settings);
    if settings.negative_effective_stress == NegativeEffectiveStress::Keep {
        return solution;
    }
    let drop_cohesion = settings.negative_effective_stress == NegativeEffectiveStress::DropStrength;
    let mut current = model.clone();
    let mut dropped: Vec<usize> = Vec::new();
    // Drop the strength of slices in tension until none with friction is left in tension
    // (each round drops at least one more slice, so at most N rounds; 50 in practice).
    for _ in 0..50 {
        let newly: Vec<usize> = solution
            .negative_effective_normal_slices
            .iter()
            .copied()
            .filter(|&i| {
                current.slices[i].tan_phi > 0.0
                    || (drop_cohesion && current.slices[i].cohesion > 0.0)
            })
            .collect();
        if newly.is_empty() || solution.status == SpencerStatus::NoSolution {
            break;
        }
        current = with_strength_dropped(&current, &newly, settings.negative_effective_stress);
        dropped.extend(newly);
        solution = solve_classic(&current, settings);
    }
    dropped.sort_unstable();
    solution.tension_dropped_slices = dropped;
    solution
}

/// `model` with the strength of `slices` dropped as `treatment` says: the friction (and with
/// [`NegativeEffectiveStress::DropStrength`] the cohesion); unchanged with `Keep`. The methods
/// side by side answer on the slices Spencer's answer dropped, so that one treatment of
/// tension holds for the headline and every method (model §6.3).
pub fn with_strength_dropped(
    model: &SliceModel,
    slices: &[usize],
    treatment: NegativeEffectiveStress,
) -> SliceModel {
    let mut out = model.clone();
    if treatment == NegativeEffectiveStress::Keep {
        return out;
    }
    for &i in slices {
        let moving = model.moving_envelope(i).map(|e| e.shear(0.0).0);
        let Some(slice) = out.slices.get_mut(i) else {
            continue;
        };
        if let Some(strength) = moving {
            // Its envelope's strength without normal stress, fixed.
            slice.cohesion = strength;
            out.fixed.push(i);
        }
        slice.tan_phi = 0.0;
        if treatment == NegativeEffectiveStress::DropStrength {
            slice.cohesion = 0.0;
        }
    }
    out.fixed.sort_unstable();
    out.fixed.dedup();
    out
}

/// `model` with each base's strength fixed where it stands (nothing left to move).
fn fixed(mut model: SliceModel) -> SliceModel {
    model.envelopes = None;
    model.fixed.clear();
    model
}

/// Spencer's solution at the consistent state of a model with nonlinear bases, and the model
/// with each base's tangent there (the callers solve a model without any directly).
fn solve_consistent(
    model: &SliceModel,
    settings: &SpencerSettings,
) -> (SpencerSolution, SliceModel) {
    let (mut solution, consistency, current) = consistent(model, |m| {
        let s = solve_tension(m, settings);
        if s.factor_of_safety.is_some() {
            let normals = s
                .slice_forces
                .iter()
                .map(|f| f.effective_normal_force)
                .collect();
            Step::Next(s, normals)
        } else {
            Step::Done(s)
        }
    });
    solution.strength = consistency;
    (solution, fixed(current))
}

/// Spencer's F for a search at the consistent state; a state that does not settle is unsolved.
/// `near`: a neighbouring surface's F, to start Bishop's F from (linear envelopes only).
fn consistent_factor_outcome(
    model: &SliceModel,
    settings: &SpencerSettings,
    near: Option<f64>,
) -> FactorOutcome {
    if !is_nonlinear(model) {
        return linear_factor_outcome(model, settings, near);
    }
    let (outcome, consistency, _) =
        consistent(model, |m| match linear_factor_outcome(m, settings, None) {
            FactorOutcome::Solved(s) => {
                let theta = s.theta_rad.unwrap_or(0.0);
                let normals = effective_normals(m, s.factor_of_safety, theta);
                Step::Next(FactorOutcome::Solved(s), normals)
            }
            other => Step::Done(other),
        });
    match outcome {
        FactorOutcome::Solved(_) if !consistency.settled => {
            FactorOutcome::Unsolved { bishop: None }
        }
        other => other,
    }
}

/// The classic equations, with the physical check.
fn solve_classic(model: &SliceModel, settings: &SpencerSettings) -> SpencerSolution {
    let equations = Equations::new(model);
    let mut solved = solve_equations(&equations, settings, None);
    solved.bishop = reported_bishop(model, solved.bishop);
    match (solved.root, solved.bishop) {
        (Some((f, theta)), _) if !is_physical(&equations, f, theta) => {
            // Described, so that the slices in tension are known; F and θ withheld.
            let s = describe(model, &equations, f, theta, &solved);
            SpencerSolution {
                status: SpencerStatus::Unphysical,
                factor_of_safety: None,
                theta_rad: None,
                unphysical_root: Some(f),
                thrust_line: Vec::new(),
                effective_thrust_line: Vec::new(),
                ..s
            }
        }
        (Some((f, theta)), _) => describe(model, &equations, f, theta, &solved),
        (None, Some(bishop)) if equations.is_frictionless() && model.circular => {
            let mut s = describe(model, &equations, bishop, 0.0, &solved);
            s.status = SpencerStatus::MomentOnly;
            s.theta_rad = None;
            s.thrust_line.clear();
            s.effective_thrust_line.clear();
            s
        }
        (None, _) => no_solution(model, &solved),
    }
}

fn no_solution(model: &SliceModel, solved: &newton::EquationsSolution) -> SpencerSolution {
    SpencerSolution {
        status: SpencerStatus::NoSolution,
        factor_of_safety: None,
        theta_rad: None,
        bishop_factor_of_safety: solved.bishop,
        iterations: solved.iterations,
        used_fallback: solved.used_fallback,
        slice_forces: vec![SliceForces::default(); model.slices.len()],
        thrust_line: Vec::new(),
        effective_thrust_line: Vec::new(),
        small_m_alpha_slices: Vec::new(),
        negative_effective_normal_slices: Vec::new(),
        unphysical_root: None,
        tension_dropped_slices: Vec::new(),
        residual: None,
        strength: Default::default(),
    }
}

/// Spencer's figure: F_f(θ) from the force equation alone and F_m(θ) from the moment equation
/// alone, against θ; they cross at the answer.
#[derive(Debug, Clone, PartialEq)]
pub struct FactorCurves {
    /// Inclinations θ in degrees.
    pub theta_deg: Vec<f64>,
    /// F_f(θ); `None` where the force equation has no root with positive m_α.
    pub force_factor: Vec<Option<f64>>,
    /// F_m(θ); `None` where the moment equation has no root with positive m_α.
    pub moment_factor: Vec<Option<f64>>,
}

/// Half-width of the θ range of [`factor_curves_around`], in whole degrees.
const CURVE_HALF_WIDTH_DEG: i32 = 30;

/// F_f(θ) and F_m(θ) at whole degrees from θ* − 30° to θ* + 30° (θ* rounded), within |θ| < 89°;
/// on nonlinear envelopes, with each base's tangent at its consistent state (where the curves
/// cross at the answer).
pub fn factor_curves_around(model: &SliceModel, theta_rad: f64) -> FactorCurves {
    if is_nonlinear(model) {
        let (_, consistent) = solve_consistent(model, &SpencerSettings::default());
        return factor_curves_around(&consistent, theta_rad);
    }
    let centre = theta_rad.to_degrees().round();
    let theta_deg: Vec<f64> = (-CURVE_HALF_WIDTH_DEG..=CURVE_HALF_WIDTH_DEG)
        .map(|i| centre + f64::from(i))
        .filter(|t| t.abs() < 89.0)
        .collect();
    factor_curves(model, theta_deg)
}

/// F_f(θ) and F_m(θ) at the given θ in degrees.
pub fn factor_curves(model: &SliceModel, theta_deg: Vec<f64>) -> FactorCurves {
    let equations = Equations::new(model);
    let mut evaluations = 0;
    let (force_factor, moment_factor) = theta_deg
        .iter()
        .map(|t| {
            let theta = t.to_radians();
            (
                equations.f_at_theta(theta, false, &mut evaluations),
                equations.f_at_theta(theta, true, &mut evaluations),
            )
        })
        .unzip();
    FactorCurves {
        theta_deg,
        force_factor,
        moment_factor,
    }
}
