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

/// The largest number of variables a programme may have (B⁻¹ is dense: n² numbers).
pub const MAX_VARIABLES: usize = 1024;
/// Pivots between two recomputations of B⁻¹ from scratch.
pub const REFACTOR_EVERY: usize = 64;

/// Tolerances of the simplex method, on rows of unit Euclidean norm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimplexSettings {
    /// A row counts as violated when a_i·y − b_i exceeds this. Defaults to 1e-9.
    pub primal_tolerance: f64,
    /// A multiplier counts as negative below minus this (relative to |c|). Defaults to 1e-9.
    pub dual_tolerance: f64,
    /// Smallest pivot element accepted. Defaults to 1e-9.
    pub pivot_tolerance: f64,
    /// Largest number of pivots of one solve. Defaults to 10 000.
    pub max_pivots: usize,
}

impl Default for SimplexSettings {
    fn default() -> Self {
        Self {
            primal_tolerance: 1e-9,
            dual_tolerance: 1e-9,
            pivot_tolerance: 1e-9,
            max_pivots: 10_000,
        }
    }
}

/// A programme max c·y subject to A y ≤ b, rows stored densely and normalised to unit length.
#[derive(Debug, Clone)]
pub struct DenseLp {
    n: usize,
    /// Row-major m × n.
    a: Vec<f64>,
    b: Vec<f64>,
    c: Vec<f64>,
    /// The factor each row was divided by (its Euclidean norm).
    norms: Vec<f64>,
}

/// Why a solve did not end at an optimal vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SimplexFailure {
    /// A row cannot be met while the others are (the dual simplex found no pivot).
    Infeasible,
    /// The objective grows without bound along an edge.
    Unbounded,
    /// The basis is singular or became so; or the vertex failed its final check.
    Singular,
    /// The pivot limit was reached.
    MaxPivots,
}

/// A basis: the rows held at equality and the inverse of their matrix.
#[derive(Debug, Clone)]
pub struct Basis {
    rows: Vec<usize>,
    /// Column-major n × n: column j is B⁻¹e_j (moving along −B⁻¹e_j releases row W_j only).
    inverse: Vec<f64>,
    since_refactor: usize,
}

/// An optimal vertex.
#[derive(Debug, Clone, PartialEq)]
pub struct Vertex {
    /// The optimal y.
    pub y: Vec<f64>,
    /// The multiplier of every row of the programme (zero off the basis), for the rows as
    /// given (not normalised): c = Σ z_i a_i.
    pub multipliers: Vec<f64>,
    /// Pivots this solve took.
    pub pivots: usize,
}

impl DenseLp {
    /// A programme with n variables and objective c (max c·y), no rows yet.
    pub fn new(c: Vec<f64>) -> Self {
        Self {
            n: c.len(),
            a: Vec::new(),
            b: Vec::new(),
            c,
            norms: Vec::new(),
        }
    }

    /// Adds the row a·y ≤ b (a of length n); returns its index. A zero row is kept as 0 ≤ b.
    pub fn push_row(&mut self, a: &[f64], b: f64) -> usize {
        let norm = a.iter().map(|v| v * v).sum::<f64>().sqrt();
        let scale = if norm > 0.0 { 1.0 / norm } else { 1.0 };
        self.a.extend(a.iter().map(|v| v * scale));
        self.b.push(b * scale);
        self.norms.push(if norm > 0.0 { norm } else { 1.0 });
        self.b.len() - 1
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.b.len()
    }

    /// Number of variables.
    pub fn variables(&self) -> usize {
        self.n
    }

    fn row(&self, i: usize) -> &[f64] {
        &self.a[i * self.n..(i + 1) * self.n]
    }

    /// Entry j of row i as given (not normalised).
    pub fn entry(&self, i: usize, j: usize) -> f64 {
        self.a[i * self.n + j] * self.norms[i]
    }

    /// Sets column j of every row to `column[i]` (as given, not normalised), keeping each row's
    /// normalisation factor (so the other entries stay bit for bit), and updates `basis` to
    /// match (Sherman–Morrison; a basis it would make singular is refactored, and an error
    /// returned if that fails).
    pub fn set_column(
        &mut self,
        j: usize,
        column: &[f64],
        basis: Option<&mut Basis>,
    ) -> Result<(), SimplexFailure> {
        let n = self.n;
        let mut change = Vec::new();
        if let Some(basis) = &basis {
            change = basis
                .rows
                .iter()
                .map(|&i| column[i] / self.norms[i] - self.a[i * n + j])
                .collect();
        }
        for (i, &v) in column.iter().enumerate() {
            self.a[i * n + j] = v / self.norms[i];
        }
        let Some(basis) = basis else { return Ok(()) };
        // B' = B + u e_jᵀ (u = change on the basis rows): B'⁻¹ = B⁻¹ − g (e_jᵀB⁻¹)/(1 + g_j),
        // g = B⁻¹u.
        let mut g = vec![0.0; n];
        for (k, &u) in change.iter().enumerate() {
            if u != 0.0 {
                axpy(u, basis.column(k, n), &mut g);
            }
        }
        let denominator = 1.0 + g[j];
        if denominator.abs() < 1e-8 {
            return basis.refactor(self);
        }
        for k in 0..n {
            let factor = basis.inverse[k * n + j] / denominator;
            if factor != 0.0 {
                let col = &mut basis.inverse[k * n..(k + 1) * n];
                for (x, gi) in col.iter_mut().zip(&g) {
                    *x -= factor * gi;
                }
            }
        }
        basis.since_refactor += 1;
        Ok(())
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn axpy(alpha: f64, x: &[f64], y: &mut [f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi += alpha * xi;
    }
}

impl Basis {
    /// The basis of rows `rows` (n of them) of `lp`; fails when their matrix is singular.
    pub fn new(lp: &DenseLp, rows: Vec<usize>) -> Result<Self, SimplexFailure> {
        let n = lp.n;
        if rows.len() != n || rows.iter().any(|&i| i >= lp.rows()) {
            return Err(SimplexFailure::Singular);
        }
        let mut basis = Self {
            rows,
            inverse: vec![0.0; n * n],
            since_refactor: 0,
        };
        basis.refactor(lp)?;
        Ok(basis)
    }

    /// The rows held at equality.
    pub fn rows(&self) -> &[usize] {
        &self.rows
    }

    fn column(&self, j: usize, n: usize) -> &[f64] {
        &self.inverse[j * n..(j + 1) * n]
    }

    /// Recomputes B⁻¹ by Gauss–Jordan elimination with partial pivoting.
    fn refactor(&mut self, lp: &DenseLp) -> Result<(), SimplexFailure> {
        let n = lp.n;
        // [B | I] row-reduced to [I | B⁻¹], B row j = a_{W_j}; stored row-major, then
        // transposed into the column-major inverse.
        let width = 2 * n;
        let mut m = vec![0.0; n * width];
        for (j, &i) in self.rows.iter().enumerate() {
            m[j * width..j * width + n].copy_from_slice(lp.row(i));
            m[j * width + n + j] = 1.0;
        }
        for col in 0..n {
            let pivot = (col..n)
                .max_by(|&p, &q| {
                    m[p * width + col]
                        .abs()
                        .total_cmp(&m[q * width + col].abs())
                })
                .unwrap_or(col);
            let value = m[pivot * width + col];
            if value.is_nan() || value.abs() <= 1e-12 {
                return Err(SimplexFailure::Singular);
            }
            if pivot != col {
                for k in 0..width {
                    m.swap(pivot * width + k, col * width + k);
                }
            }
            let inv = 1.0 / value;
            for k in 0..width {
                m[col * width + k] *= inv;
            }
            let (before, rest) = m.split_at_mut(col * width);
            let (pivot_row, after) = rest.split_at_mut(width);
            for other in before
                .chunks_exact_mut(width)
                .chain(after.chunks_exact_mut(width))
            {
                let factor = other[col];
                if factor != 0.0 {
                    for (x, p) in other.iter_mut().zip(pivot_row.iter()) {
                        *x -= factor * p;
                    }
                }
            }
        }
        // Row r of the right half is row r of B⁻¹: entry (r, j) goes to column j.
        for r in 0..n {
            for j in 0..n {
                self.inverse[j * n + r] = m[r * width + n + j];
            }
        }
        self.since_refactor = 0;
        Ok(())
    }

    /// Replaces basis row j by row `entering` of `lp`, given w = B⁻ᵀ a_entering.
    fn pivot(&mut self, lp: &DenseLp, j: usize, entering: usize, w: &[f64]) {
        let n = lp.n;
        let pivot = w[j];
        let (before, rest) = self.inverse.split_at_mut(j * n);
        let (col_j, after) = rest.split_at_mut(n);
        for x in col_j.iter_mut() {
            *x /= pivot;
        }
        for (k, col) in before.chunks_exact_mut(n).enumerate().chain(
            after
                .chunks_exact_mut(n)
                .enumerate()
                .map(|(k, c)| (k + j + 1, c)),
        ) {
            if w[k] != 0.0 {
                axpy(-w[k], col_j, col);
            }
        }
        self.rows[j] = entering;
        self.since_refactor += 1;
    }

    /// y = B⁻¹ b_W.
    fn vertex(&self, lp: &DenseLp) -> Vec<f64> {
        let n = lp.n;
        let mut y = vec![0.0; n];
        for (j, &i) in self.rows.iter().enumerate() {
            axpy(lp.b[i], self.column(j, n), &mut y);
        }
        y
    }

    /// z = B⁻ᵀ c for costs c.
    fn multipliers(&self, n: usize, c: &[f64]) -> Vec<f64> {
        (0..n).map(|j| dot(self.column(j, n), c)).collect()
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
    lp: &DenseLp,
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
    // Phase 1's costs: z' = max(z, 0) at the starting basis (c' = Bᵀz').
    let z0 = basis.multipliers(n, &lp.c);
    let shifted: Vec<f64> = if z0.iter().all(|&z| z >= -dual_tol) {
        lp.c.clone()
    } else {
        let mut c = vec![0.0; n];
        for (j, &i) in basis.rows.iter().enumerate() {
            axpy(z0[j].max(0.0), lp.row(i), &mut c);
        }
        c
    };
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
            *s = lp.b[i] - dot(lp.row(i), &y);
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
            // The entering row: the most violated (Bland: the first violated).
            let violated = (0..m).filter(|&i| !in_basis[i] && slack[i] < -primal_tol);
            let entering = if bland {
                violated.into_iter().next()
            } else {
                violated.min_by(|&p, &q| slack[p].total_cmp(&slack[q]))
            };
            let Some(entering) = entering else {
                phase = Phase::Primal;
                (best, stalled, bland) = (f64::INFINITY, 0, false);
                continue;
            };
            let z = basis.multipliers(n, &shifted);
            let w = basis.multipliers(n, lp.row(entering));
            let j =
                dual_ratio(&z, &w, settings, dual_tol, bland).ok_or(SimplexFailure::Infeasible)?;
            in_basis[basis.rows[j]] = false;
            in_basis[entering] = true;
            basis.pivot(lp, j, entering, &w);
        } else {
            let z = basis.multipliers(n, &lp.c);
            let negative = (0..n).filter(|&j| z[j] < -dual_tol);
            let leaving = if bland {
                negative.min_by_key(|&j| basis.rows[j])
            } else {
                negative.min_by(|&p, &q| z[p].total_cmp(&z[q]))
            };
            let Some(j) = leaving else {
                return certify(lp, basis, settings, pivots);
            };
            // Along d = −B⁻¹e_j row W_j goes slack; a row with a·d > 0 tightens.
            let d: Vec<f64> = basis.column(j, n).iter().map(|v| -v).collect();
            let entering = primal_ratio(lp, &in_basis, &slack, &d, settings, bland)
                .ok_or(SimplexFailure::Unbounded)?;
            let w = basis.multipliers(n, lp.row(entering));
            if w[j].abs() < settings.pivot_tolerance {
                return Err(SimplexFailure::Singular);
            }
            in_basis[basis.rows[j]] = false;
            in_basis[entering] = true;
            basis.pivot(lp, j, entering, &w);
        }
        pivots += 1;
    }
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
    lp: &DenseLp,
    in_basis: &[bool],
    slack: &[f64],
    d: &[f64],
    settings: &SimplexSettings,
    bland: bool,
) -> Option<usize> {
    let rates: Vec<(usize, f64)> = (0..lp.rows())
        .filter(|&i| !in_basis[i])
        .map(|i| (i, dot(lp.row(i), d)))
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
    lp: &DenseLp,
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
            .map(|&i| (dot(lp.row(i), &y) - lp.b[i]).abs())
            .fold(0.0, f64::max);
        let mut c = vec![0.0; n];
        for (j, &i) in basis.rows.iter().enumerate() {
            axpy(z[j], lp.row(i), &mut c);
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
            .all(|i| dot(lp.row(i), &y) - lp.b[i] <= 2.0 * settings.primal_tolerance * scale_y);
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
