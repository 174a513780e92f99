//! A basis of the simplex method of [`super`]: n rows held at equality and the inverse of
//! their matrix, kept by the product form at each pivot and by Sherman–Morrison when a column
//! changes, recomputed by Gauss–Jordan elimination with partial pivoting.

use super::lp::{axpy, dot, Lp, RowView};
use super::outcome::SimplexFailure;

/// Pivots between two recomputations of B⁻¹ from scratch.
pub const REFACTOR_EVERY: usize = 64;

/// A basis: the rows held at equality and the inverse of their matrix.
#[derive(Debug, Clone)]
pub struct Basis {
    pub(super) rows: Vec<usize>,
    /// Column-major n × n: column j is B⁻¹e_j (moving along −B⁻¹e_j releases row W_j only).
    inverse: Vec<f64>,
    pub(super) since_refactor: usize,
}

impl Basis {
    /// The basis of rows `rows` (n of them) of `lp`; fails when their matrix is singular.
    pub fn new(lp: &Lp, rows: Vec<usize>) -> Result<Self, SimplexFailure> {
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

    pub(super) fn column(&self, j: usize, n: usize) -> &[f64] {
        &self.inverse[j * n..(j + 1) * n]
    }

    /// Recomputes B⁻¹ by Gauss–Jordan elimination with partial pivoting.
    pub(super) fn refactor(&mut self, lp: &Lp) -> Result<(), SimplexFailure> {
        let n = lp.n;
        // [B | I] row-reduced to [I | B⁻¹], B row j = a_{W_j}; stored row-major, then
        // transposed into the column-major inverse.
        let width = 2 * n;
        let mut m = vec![0.0; n * width];
        for (j, &i) in self.rows.iter().enumerate() {
            lp.row(i).add_to(1.0, &mut m[j * width..j * width + n]);
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
    pub(super) fn pivot(&mut self, lp: &Lp, j: usize, entering: usize, w: &[f64]) {
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
    pub(super) fn vertex(&self, lp: &Lp) -> Vec<f64> {
        let n = lp.n;
        let mut y = vec![0.0; n];
        for (j, &i) in self.rows.iter().enumerate() {
            axpy(lp.b[i], self.column(j, n), &mut y);
        }
        y
    }

    /// z = B⁻ᵀ c for costs c.
    pub(super) fn multipliers(&self, n: usize, c: &[f64]) -> Vec<f64> {
        (0..n).map(|j| dot(self.column(j, n), c)).collect()
    }

    /// w = B⁻ᵀa for a row a of the programme (a = Σ w_j a_{W_j}).
    pub(super) fn weights(&self, n: usize, row: RowView) -> Vec<f64> {
        (0..n).map(|j| row.dot(self.column(j, n))).collect()
    }

    /// Follows a change of the programme's moving column (`change`: every row's normalised
    /// entry, new minus old; [`super::set_column`]): B' = B + u e_jᵀ with u the change on the basis
    /// rows, B'⁻¹ = B⁻¹ − g (e_jᵀB⁻¹)/(1 + g_j), g = B⁻¹u; refactored instead when that
    /// denominator nearly vanishes (an error if B' is singular).
    pub fn column_changed(&mut self, lp: &Lp, change: &[f64]) -> Result<(), SimplexFailure> {
        let (n, j) = (lp.n, lp.moving_column());
        let mut g = vec![0.0; n];
        for (k, &i) in self.rows.iter().enumerate() {
            if change[i] != 0.0 {
                axpy(change[i], self.column(k, n), &mut g);
            }
        }
        let denominator = 1.0 + g[j];
        if denominator.abs() < 1e-8 {
            return self.refactor(lp);
        }
        for k in 0..n {
            let factor = self.inverse[k * n + j] / denominator;
            if factor != 0.0 {
                let col = &mut self.inverse[k * n..(k + 1) * n];
                for (x, gi) in col.iter_mut().zip(&g) {
                    *x -= factor * gi;
                }
            }
        }
        self.since_refactor += 1;
        Ok(())
    }
}
