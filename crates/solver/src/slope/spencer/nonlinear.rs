//! Spencer's method and the methods beside it on nonlinear strength envelopes: each solved to
//! the consistent state of [`super::consistent`], reading each base's σ′ₙ from
//! its own equations.

use super::consistent::{consistent, is_nonlinear, Step};
use super::equations::Equations;
use super::{
    linear_factor_outcome, solve_tension, FactorOutcome, SpencerSettings, SpencerSolution,
};
use crate::slope::slices::SliceModel;

/// Each slice's effective normal force N′ = A_n + Q·sin(α − θ) − u·l at (F, θ) with parallel
/// inter-slice forces (Spencer's; θ = 0 for Bishop's and Janbu's).
pub(super) fn effective_normals(model: &SliceModel, f: f64, theta: f64) -> Vec<f64> {
    let equations = Equations::new(model);
    let (sin_t, cos_t) = theta.sin_cos();
    equations
        .terms
        .iter()
        .map(|t| {
            let q = Equations::q(t, f, (sin_t, cos_t)).q;
            t.a_n + q * (t.sin_alpha * cos_t - t.cos_alpha * sin_t) - t.pore_force
        })
        .collect()
}

/// `model` with each base's strength fixed where it stands (nothing left to move).
fn fixed(mut model: SliceModel) -> SliceModel {
    model.envelopes = None;
    model.fixed.clear();
    model
}

/// Spencer's solution at the consistent state of a model with nonlinear bases, and the model
/// with each base's tangent there (the callers solve a model without any directly).
pub(super) fn solve(
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
pub(super) fn factor_outcome(
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

/// One of the methods beside Spencer's at the consistent state: `solve(model, normals)` gives
/// F (and what else the method reports) with each slice's N′ when `normals` asks for them, or
/// `None`; `None` too when the state does not settle.
pub(super) fn method<T>(
    model: &SliceModel,
    mut solve: impl FnMut(&SliceModel, bool) -> Option<(T, Vec<f64>)>,
) -> Option<T> {
    if !is_nonlinear(model) {
        return solve(model, false).map(|(answer, _)| answer);
    }
    let (answer, consistency, _) = consistent(model, |m| match solve(m, true) {
        Some((answer, normals)) => Step::Next(Some(answer), normals),
        None => Step::Done(None),
    });
    answer.filter(|_| consistency.settled)
}
