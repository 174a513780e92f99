//! A dense simplex method for small linear programmes in inequality form,
//!
//! ```text
//!   maximise c·y  subject to  a_i·y ≤ b_i  (i = 1 … m),   y ∈ ℝⁿ,
//! ```
//!
//! that starts from any basis — n linearly independent rows held at equality — and can change
//! one column of A between solves while keeping its basis: a warm start, which an interior-point
//! method cannot take. A sequence of nearby programmes (the stops of a rolling load) then costs a
//! few pivots each.
//!
//! At a basis W (rows a_W, B = a_W as an n × n matrix) the vertex is y = B⁻¹ b_W and the
//! multipliers z = B⁻ᵀ c; it is optimal when every row holds (a_i·y ≤ b_i) and z ≥ 0
//! (c = Σ z_j a_{W_j}). From a basis that is neither primal nor dual feasible the method runs in
//! two phases: the costs are first shifted (c' = c + Bᵀs, s ≥ 0, so that z' = z + s ≥ 0) and the
//! **dual simplex** (Lemke 1954) restores primal feasibility keeping z' ≥ 0; then with the true
//! costs the **primal simplex** (Dantzig) restores z ≥ 0 keeping feasibility. Both use Harris's
//! two-pass ratio test, and fall back to Bland's smallest-index rule after a run of pivots that
//! made no progress (degenerate vertices are the rule in limit analysis: a hinge makes several
//! rows active at once).
//!
//! B⁻¹ is kept explicitly (n ≤ [`MAX_VARIABLES`]), updated by the product form at each pivot and
//! by Sherman–Morrison when a column of A changes, recomputed by Gauss–Jordan elimination with
//! partial pivoting every [`REFACTOR_EVERY`] pivots. Before an answer is returned the vertex and
//! the multipliers are checked against their defining equations (residuals, not the inverse), so
//! a drifted inverse cannot pass: the answer is certified or the solve says it failed.
//!
//! # Reference
//! Chvátal, *Linear Programming* (1983), ch. 7–10 (revised, dual and bounded simplex);
//! Harris, *Pivot selection methods of the Devex LP code*, Math. Programming 5 (1973) 1–28;
//! Koberstein, *The dual simplex method, techniques for a fast and stable implementation*,
//! PhD thesis, Paderborn (2005), §3 (cost shifting).

mod basis;
mod lp;
mod outcome;

pub use basis::{Basis, REFACTOR_EVERY};
pub use lp::Lp;
pub use outcome::{SimplexFailure, Vertex};

use lp::dot;

/// The largest number of variables a programme may have (B⁻¹ is dense: n² numbers).
pub const MAX_VARIABLES: usize = 1024;

/// Tolerances of the simplex method, on rows of unit Euclidean norm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimplexSettings {
    /// A row counts as violated when a_i·y − b_i exceeds this. Defaults to 1e-11 (a looser
    /// tolerance lets the vertex stand that far outside a row, which moves an ill-conditioned
    /// optimum by more than the interior-point solver's 1e-10).
    pub primal_tolerance: f64,
    /// A multiplier counts as negative below minus this (relative to |c|). Defaults to 1e-11.
    pub dual_tolerance: f64,
    /// Smallest pivot element accepted. Defaults to 1e-9.
    pub pivot_tolerance: f64,
    /// Largest number of pivots of one solve. Defaults to 10 000.
    pub max_pivots: usize,
}

impl Default for SimplexSettings {
    fn default() -> Self {
        Self {
            primal_tolerance: 1e-11,
            dual_tolerance: 1e-11,
            pivot_tolerance: 1e-9,
            max_pivots: 10_000,
        }
    }
}

/// Sets the moving column of `lp` to `column` (one entry per row, as given) and brings `basis`,
/// if any, up to date with it.
pub fn set_column(
    lp: &mut Lp,
    column: &[f64],
    basis: Option<&mut Basis>,
) -> Result<(), SimplexFailure> {
    let change = lp.set_column(column);
    match basis {
        Some(basis) => basis.column_changed(lp, &change),
        None => Ok(()),
    }
}

/// Which phase a solve is in.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    /// Dual simplex on shifted costs, until every row holds.
    Dual,
    /// Primal simplex on the true costs, until every multiplier is ≥ 0.
    Primal,
}

/// Maximises `lp` from `basis` (which it leaves at the optimal basis, or wherever it stopped).
pub fn maximise(
    lp: &Lp,
    basis: &mut Basis,
    settings: &SimplexSettings,
) -> Result<Vertex, SimplexFailure> {
    let n = lp.n;
    let m = lp.rows();
    let scale_c = lp.c.iter().fold(0.0f64, |s, v| s.max(v.abs())).max(1e-300);
    let dual_tol = settings.dual_tolerance * scale_c;
    let primal_tol = settings.primal_tolerance;
    let mut in_basis = vec![false; m];
    for &i in &basis.rows {
        in_basis[i] = true;
    }
    let shifted = shifted_costs(lp, basis, dual_tol);
    let mut phase = Phase::Dual;
    let (mut best, mut stalled, mut bland) = (f64::INFINITY, 0usize, false);
    let mut pivots = 0;
    let mut slack = vec![0.0; m];
    loop {
        if basis.since_refactor >= REFACTOR_EVERY {
            basis.refactor(lp)?;
        }
        let y = basis.vertex(lp);
        for (i, s) in slack.iter_mut().enumerate() {
            *s = lp.b[i] - lp.row(i).dot(&y);
        }
        // Progress: the dual simplex lowers the dual objective b_W·z' = c'·y, the primal
        // simplex raises c·y; neither may stall for long without Bland's rule taking over.
        let measure = match phase {
            Phase::Dual => dot(&shifted, &y),
            Phase::Primal => -dot(&lp.c, &y),
        };
        if measure < best - 1e-14 * best.abs().max(1.0) {
            (best, stalled) = (measure, 0);
        } else {
            stalled += 1;
            bland |= stalled > 2 * n + 10;
        }
        if pivots >= settings.max_pivots {
            return Err(SimplexFailure::MaxPivots);
        }
        if phase == Phase::Dual {
            let Some(entering) = violated_row(&in_basis, &slack, primal_tol, bland) else {
                phase = Phase::Primal;
                (best, stalled, bland) = (f64::INFINITY, 0, false);
                continue;
            };
            let z = basis.multipliers(n, &shifted);
            let w = basis.weights(n, lp.row(entering));
            let j =
                dual_ratio(&z, &w, settings, dual_tol, bland).ok_or(SimplexFailure::Infeasible)?;
            exchange(lp, basis, &mut in_basis, j, entering, &w);
        } else {
            let z = basis.multipliers(n, &lp.c);
            let Some(j) = negative_multiplier(&z, basis, dual_tol, bland) else {
                return certify(lp, basis, settings, pivots);
            };
            // Along d = −B⁻¹e_j row W_j goes slack; a row with a·d > 0 tightens.
            let d: Vec<f64> = basis.column(j, n).iter().map(|v| -v).collect();
            let entering = primal_ratio(lp, &in_basis, &slack, &d, settings, bland)
                .ok_or(SimplexFailure::Unbounded)?;
            let w = basis.weights(n, lp.row(entering));
            if w[j].abs() < settings.pivot_tolerance {
                return Err(SimplexFailure::Singular);
            }
            exchange(lp, basis, &mut in_basis, j, entering, &w);
        }
        pivots += 1;
    }
}

/// Phase 1's costs: z' = max(z, 0) at the starting basis (c' = Bᵀz'), the true costs when
/// every multiplier is ≥ 0 there already.
fn shifted_costs(lp: &Lp, basis: &Basis, dual_tol: f64) -> Vec<f64> {
    let n = lp.n;
    let z0 = basis.multipliers(n, &lp.c);
    if z0.iter().all(|&z| z >= -dual_tol) {
        lp.c.clone()
    } else {
        let mut c = vec![0.0; n];
        for (j, &i) in basis.rows.iter().enumerate() {
            lp.row(i).add_to(z0[j].max(0.0), &mut c);
        }
        c
    }
}

/// The dual simplex's entering row: the most violated row out of the basis (Bland: the first
/// violated), `None` when every row holds.
#[inline]
fn violated_row(in_basis: &[bool], slack: &[f64], primal_tol: f64, bland: bool) -> Option<usize> {
    let violated = (0..slack.len()).filter(|&i| !in_basis[i] && slack[i] < -primal_tol);
    if bland {
        violated.into_iter().next()
    } else {
        violated.min_by(|&p, &q| slack[p].total_cmp(&slack[q]))
    }
}

/// The primal simplex's leaving position: the most negative multiplier (Bland: the one of the
/// smallest row), `None` when every multiplier is ≥ 0.
#[inline]
fn negative_multiplier(z: &[f64], basis: &Basis, dual_tol: f64, bland: bool) -> Option<usize> {
    let negative = (0..z.len()).filter(|&j| z[j] < -dual_tol);
    if bland {
        negative.min_by_key(|&j| basis.rows[j])
    } else {
        negative.min_by(|&p, &q| z[p].total_cmp(&z[q]))
    }
}

/// Row `entering` replaces the basis row at position `j` (`w` its weights B⁻ᵀa).
#[inline]
fn exchange(
    lp: &Lp,
    basis: &mut Basis,
    in_basis: &mut [bool],
    j: usize,
    entering: usize,
    w: &[f64],
) {
    in_basis[basis.rows[j]] = false;
    in_basis[entering] = true;
    basis.pivot(lp, j, entering, w);
}

/// The dual ratio test: the basis row j to leave when a row with w = B⁻ᵀa enters, keeping the
/// multipliers z − θw ≥ 0 (Harris: the largest |w_j| among the near-minimal ratios).
fn dual_ratio(
    z: &[f64],
    w: &[f64],
    settings: &SimplexSettings,
    dual_tol: f64,
    bland: bool,
) -> Option<usize> {
    let candidates = || (0..w.len()).filter(|&j| w[j] > settings.pivot_tolerance);
    let bound = candidates()
        .map(|j| (z[j].max(0.0) + dual_tol) / w[j])
        .fold(f64::INFINITY, f64::min);
    if !bound.is_finite() {
        return None;
    }
    let near = candidates().filter(|&j| z[j].max(0.0) / w[j] <= bound);
    if bland {
        near.min_by(|&p, &q| (z[p].max(0.0) / w[p]).total_cmp(&(z[q].max(0.0) / w[q])))
    } else {
        near.max_by(|&p, &q| w[p].total_cmp(&w[q]))
    }
}

/// The primal ratio test along d: the row that blocks first (Harris: the largest a·d among
/// the near-first).
fn primal_ratio(
    lp: &Lp,
    in_basis: &[bool],
    slack: &[f64],
    d: &[f64],
    settings: &SimplexSettings,
    bland: bool,
) -> Option<usize> {
    let rates: Vec<(usize, f64)> = (0..lp.rows())
        .filter(|&i| !in_basis[i])
        .map(|i| (i, lp.row(i).dot(d)))
        .filter(|&(_, s)| s > settings.pivot_tolerance)
        .collect();
    let bound = rates
        .iter()
        .map(|&(i, s)| (slack[i].max(0.0) + settings.primal_tolerance) / s)
        .fold(f64::INFINITY, f64::min);
    if !bound.is_finite() {
        return None;
    }
    let near = rates
        .iter()
        .filter(|&&(i, s)| slack[i].max(0.0) / s <= bound);
    if bland {
        near.map(|&(i, _)| i).next()
    } else {
        near.max_by(|p, q| p.1.total_cmp(&q.1)).map(|&(i, _)| i)
    }
}

/// Checks the final basis against its equations — B y = b_W, Bᵀz = c, every row met, z ≥ 0 —
/// refactoring once if the inverse has drifted, and returns the vertex.
fn certify(
    lp: &Lp,
    basis: &mut Basis,
    settings: &SimplexSettings,
    pivots: usize,
) -> Result<Vertex, SimplexFailure> {
    let n = lp.n;
    let scale_c = lp.c.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    for attempt in 0..2 {
        let y = basis.vertex(lp);
        let z = basis.multipliers(n, &lp.c);
        let scale_y = y.iter().fold(1.0f64, |s, v| s.max(v.abs()));
        let scale_z = z.iter().fold(scale_c, |s, v| s.max(v.abs()));
        let vertex_residual = basis
            .rows
            .iter()
            .map(|&i| (lp.row(i).dot(&y) - lp.b[i]).abs())
            .fold(0.0, f64::max);
        let mut c = vec![0.0; n];
        for (j, &i) in basis.rows.iter().enumerate() {
            lp.row(i).add_to(z[j], &mut c);
        }
        let dual_residual = c
            .iter()
            .zip(&lp.c)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        let exact = vertex_residual <= 1e-11 * scale_y && dual_residual <= 1e-11 * scale_z;
        if !exact {
            if attempt == 0 {
                basis.refactor(lp)?;
                continue;
            }
            return Err(SimplexFailure::Singular);
        }
        let feasible = (0..lp.rows())
            .all(|i| lp.row(i).dot(&y) - lp.b[i] <= 2.0 * settings.primal_tolerance * scale_y);
        let optimal = z
            .iter()
            .all(|&v| v >= -2.0 * settings.dual_tolerance * scale_c);
        if !(feasible && optimal) {
            return Err(SimplexFailure::Singular);
        }
        let mut multipliers = vec![0.0; lp.rows()];
        for (j, &i) in basis.rows.iter().enumerate() {
            multipliers[i] = z[j] / lp.norms[i];
        }
        return Ok(Vertex {
            y,
            multipliers,
            pivots,
        });
    }
    Err(SimplexFailure::Singular)
}
