//! The yield rows of the programmes: each finite limit r⁻ ≤ r ≤ r⁺ of an interface resultant as
//! an inequality a·x ≤ b, Livesley's friction rows μ(q + s) ∓ t ≥ 0 (§2.7) where friction is
//! finite, and the bounds 0 ≤ p ≤ capacity of a fill's passive forces (their tag's `interface`
//! is the force's index). Forces are scaled by the total weight.

use super::problem::{ArchProblem, InterfaceLimits};
use crate::arch::equilibrium::RESULTANTS_PER_INTERFACE;
use crate::arch::mechanism::{Bound, LimitTag, Resultant};

/// An inequality row a·x ≤ b.
pub(super) struct Row {
    pub entries: [(usize, f64); 3],
    pub len: usize,
    pub b: f64,
    pub tag: LimitTag,
    /// A crushing cut (a tangent added where a solution went beyond the curve): the chain
    /// programmes start with these rows, where the next solution is expected to bear.
    pub cut: bool,
}

impl Row {
    /// The interface of the row and its coefficients on that interface's (q, s, t).
    pub fn local(&self) -> (usize, [f64; 3]) {
        let k = self.tag.interface;
        let mut a = [0.0; 3];
        for &(j, v) in &self.entries[..self.len] {
            a[j - RESULTANTS_PER_INTERFACE * k] += v;
        }
        (k, a)
    }
}

/// The yield rows of every interface, in scaled units (forces divided by the total weight).
pub(super) fn limit_rows(problem: &ArchProblem, force_scale: f64) -> Vec<Row> {
    let w = force_scale;
    let mut rows = Vec::new();
    // The starting tangents are the same at every interface.
    let tangent_points = problem
        .crushing
        .as_ref()
        .map_or(Vec::new(), |c| c.tangent_points());
    for k in 0..problem.assembly.interfaces.len() {
        let col = RESULTANTS_PER_INTERFACE * k;
        let (limits, friction) = problem.material(k);
        for (resultant, bound, value) in limits.bounds() {
            let Some(value) = value else { continue };
            let offset = match resultant {
                Resultant::Q => 0,
                Resultant::S => 1,
                _ => 2,
            };
            // Lower: −r ≤ −r⁻; upper: r ≤ r⁺.
            let sign = match bound {
                Bound::Lower => -1.0,
                Bound::Upper => 1.0,
            };
            rows.push(Row {
                entries: [(col + offset, sign), (col, 0.0), (col, 0.0)],
                len: 1,
                b: sign * value / w,
                tag: LimitTag {
                    interface: k,
                    resultant,
                    bound,
                },
                cut: false,
            });
        }
        crushing_rows(problem, k, &limits, &tangent_points, w, &mut rows);
        friction_rows(problem, k, friction, w, &mut rows);
    }
    let first_passive = RESULTANTS_PER_INTERFACE * problem.assembly.interfaces.len();
    for (j, force) in problem.passive.iter().enumerate() {
        // 0 ≤ p ≤ capacity: −p ≤ 0 and p ≤ capacity/W.
        for (bound, sign, b) in [
            (Bound::Lower, -1.0, 0.0),
            (Bound::Upper, 1.0, force.capacity / w),
        ] {
            rows.push(Row {
                entries: [(first_passive + j, sign), (0, 0.0), (0, 0.0)],
                len: 1,
                b,
                tag: LimitTag {
                    interface: j,
                    resultant: Resultant::Passive,
                    bound,
                },
                cut: false,
            });
        }
    }
    rows
}

/// The crushing rows of interface `k` (model §5.2): the starting tangents and the cuts added
/// at it, both signs of the moment.
fn crushing_rows(
    problem: &ArchProblem,
    k: usize,
    limits: &InterfaceLimits,
    tangent_points: &[f64],
    w: f64,
    rows: &mut Vec<Row>,
) {
    let Some(crushing) = &problem.crushing else {
        return;
    };
    let col = RESULTANTS_PER_INTERFACE * k;
    let no_tension =
        limits.q_min.is_some_and(|v| v >= 0.0) && limits.s_min.is_some_and(|v| v >= 0.0);
    // ±(q − s) ≤ (1 − 2n)(q + s) + n²·σ_c·t: the tangent at n = N/(σ_c t) to
    // |q − s| ≤ (q + s)(1 − (q + s)/(σ_c t)), i.e. |M| ≤ N(t − N/σ_c)/2.
    let t = problem.assembly.interfaces[k].length();
    let cuts = crushing
        .cuts
        .iter()
        .filter(|c| c.0 == k)
        .map(|c| (c.1, true));
    let planes = tangent_points.iter().map(|&n| (n, false));
    for (n, cut) in planes.chain(cuts) {
        let b = n * n * crushing.strength * t / w;
        // A plane this far out (in units of the whole dead weight) never binds; left
        // out, it cannot spoil the programme's scaling (σ_c → ∞ is Heyman's n = 0).
        if n > 0.0 && b > 1e4 {
            continue;
        }
        // The tangent at N = 0 is q ≥ 0 and s ≥ 0: left out when those limits are
        // there already (a duplicate row makes the programme degenerate).
        if n == 0.0 && no_tension {
            continue;
        }
        for (bound, sign) in [(Bound::Upper, 1.0), (Bound::Lower, -1.0)] {
            rows.push(Row {
                entries: [
                    (col, sign - (1.0 - 2.0 * n)),
                    (col + 1, -sign - (1.0 - 2.0 * n)),
                    (col, 0.0),
                ],
                len: 2,
                b,
                tag: LimitTag {
                    interface: k,
                    resultant: Resultant::M,
                    bound,
                },
                cut,
            });
        }
    }
}

/// The friction rows of interface `k`: Coulomb's (Livesley §2.7) where friction is finite, or
/// a non-associative step's fixed capacities.
fn friction_rows(
    problem: &ArchProblem,
    k: usize,
    friction: Option<f64>,
    w: f64,
    rows: &mut Vec<Row>,
) {
    let col = RESULTANTS_PER_INTERFACE * k;
    if let (Some(mu), Some(capacities)) = (friction, &problem.shear_capacities) {
        // Fixed capacities (non-associative step): t ≤ c + αμ(q + s) (tagged U: sliding
        // towards +τ) and −t ≤ c + αμ(q + s) (V).
        // Divided by αμ when that exceeds 1, as the Coulomb rows are by μ.
        let a = problem.friction_slope * mu;
        let scale = 1.0 / a.max(1.0);
        let c = capacities.get(k).copied().unwrap_or(0.0) / w * scale;
        for (resultant, sign) in [(Resultant::U, 1.0), (Resultant::V, -1.0)] {
            rows.push(Row {
                entries: [
                    (col + 2, sign * scale),
                    (col, -a * scale),
                    (col + 1, -a * scale),
                ],
                len: if a > 0.0 { 3 } else { 1 },
                b: c,
                tag: LimitTag {
                    interface: k,
                    resultant,
                    bound: Bound::Lower,
                },
                cut: false,
            });
        }
    } else if let Some(mu) = friction {
        // u = μ(q + s) − t ≥ 0 and v = μ(q + s) + t ≥ 0 (Livesley §2.7), written −u ≤ 0 and
        // −v ≤ 0 (≤ c·ℓ with cohesion); only where friction is finite. Divided by μ when μ > 1, so that a large μ
        // does not make the row (and the programme) badly scaled.
        let scale = 1.0 / mu.max(1.0);
        for (resultant, t_sign) in [(Resultant::U, 1.0), (Resultant::V, -1.0)] {
            rows.push(Row {
                entries: [
                    (col, -mu * scale),
                    (col + 1, -mu * scale),
                    (col + 2, t_sign * scale),
                ],
                len: 3,
                // Cohesion: |t| ≤ μ(q + s) + c·ℓ.
                b: problem.cohesive_capacity(k) / w * scale,
                tag: LimitTag {
                    interface: k,
                    resultant,
                    bound: Bound::Lower,
                },
                cut: false,
            });
        }
    }
}
