//! The consistent state (model §8) of a slip surface with nonlinear envelopes: solve with each base's
//! tangent, read each base's σ′ₙ = N′/l, move the tangents there, solve again — until the
//! strength each base carries is its envelope's at its own σ′ₙ (within 1e-10 of the largest
//! base strength).
//!
//! At that state the linearised equations are the nonlinear ones: any tangent slope gives the
//! same answer, only the path to it changes.

use crate::slope::slices::SliceModel;
use crate::slope::strength::Consistency;

/// Rounds of solving at most; a state not settled by then is answered as such.
pub const MAX_ROUNDS: usize = 60;

/// How far apart the strength a base carries and its envelope's may be, relative to the largest
/// base strength, for the state to count as consistent.
const SETTLED: f64 = 1e-10;

/// What one solve of the linearised surface gives.
pub enum Step<T> {
    /// An answer and each slice's effective normal force N′: go on.
    Next(T, Vec<f64>),
    /// An answer to stop at (no solution: nothing to move the tangents to).
    Done(T),
}

/// Whether any base of `model` carries a nonlinear envelope.
pub fn is_nonlinear(model: &SliceModel) -> bool {
    model.envelopes.is_some() && (0..model.slices.len()).any(|i| model.moving_envelope(i).is_some())
}

/// Solves `model` to its consistent state with `solve`; the answer of the last round and how
/// it was reached. A model without nonlinear bases is solved once.
pub fn consistent<T>(
    model: &SliceModel,
    mut solve: impl FnMut(&SliceModel) -> Step<T>,
) -> (T, Consistency, SliceModel) {
    let mut current = model.clone();
    let mut rounds = 0;
    loop {
        rounds += 1;
        let (answer, normals) = match solve(&current) {
            // Nothing to settle: the answer (no solution) says what happened.
            Step::Done(answer) => {
                let settled = true;
                return (answer, Consistency { rounds, settled }, current);
            }
            Step::Next(answer, normals) => (answer, normals),
        };
        let (mut worst, mut scale) = (0.0f64, 0.0f64);
        for (i, (slice, &normal)) in current.slices.iter_mut().zip(&normals).enumerate() {
            let Some(envelope) = model.moving_envelope(i) else {
                continue;
            };
            let sigma = normal / slice.base_length;
            let (tau, _) = envelope.shear(sigma);
            let carried = slice.cohesion + sigma * slice.tan_phi;
            worst = worst.max((tau - carried).abs());
            scale = scale.max(tau.abs()).max(carried.abs());
            (slice.cohesion, slice.tan_phi) = envelope.tangent(sigma);
        }
        let settled = worst <= SETTLED * scale.max(f64::MIN_POSITIVE) || !worst.is_finite();
        if settled || rounds >= MAX_ROUNDS {
            let settled = settled && worst.is_finite();
            return (answer, Consistency { rounds, settled }, current);
        }
    }
}
