//! The methods beside Spencer's on nonlinear strength envelopes: each solved to the consistent
//! state of [`super::consistent`], reading each base's σ′ₙ from its own equations (Spencer's
//! own solution there is the parent module's).

use super::consistent::{consistent, is_nonlinear, Step};
use super::equations::Equations;
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
