//! Anderson mixing (Anderson 1965; Walker & Ni 2011) of a fixed-point map x ↦ g(x): the next
//! x combines the last few steps so that their residuals f = g(x) − x cancel as far as a least-
//! squares fit of their differences allows,
//!
//! ```text
//!   γ = argmin ‖f_k − ΔF γ‖,   x_{k+1} = x_k + β f_k − (ΔX + β ΔF) γ,
//! ```
//!
//! ΔX, ΔF the differences of the remembered x and f. With no memory this is plain relaxation
//! x + β(g(x) − x). Where g is affine (a programme whose active set no longer changes) the
//! residuals of m + 1 steps span its error and the mixing lands on the fixed point instead of
//! approaching it geometrically.

/// The remembered steps: each x the map was evaluated at, and g(x).
#[derive(Debug, Default, Clone)]
pub(crate) struct Mixing {
    inputs: Vec<Vec<f64>>,
    outputs: Vec<Vec<f64>>,
}

/// Tikhonov weight on the fit's normal equations, relative to each column's squared norm:
/// nearly parallel residual differences (a step that barely moved) then give a small γ, not a
/// huge one.
const REGULARISATION: f64 = 1e-10;

impl Mixing {
    /// Forgets every step (a restart: the next x is plain relaxation of the next step).
    pub(crate) fn forget(&mut self) {
        self.inputs.clear();
        self.outputs.clear();
    }

    /// Remembers that the map took `input` to `output` and returns the next x, mixing at most
    /// `memory` differences with relaxation `beta`, clamped to ≥ 0 (normal forces).
    pub(crate) fn next(
        &mut self,
        input: Vec<f64>,
        output: Vec<f64>,
        memory: usize,
        beta: f64,
    ) -> Vec<f64> {
        self.inputs.push(input);
        self.outputs.push(output);
        let keep = memory + 1;
        if self.inputs.len() > keep {
            let drop = self.inputs.len() - keep;
            self.inputs.drain(..drop);
            self.outputs.drain(..drop);
        }
        let residuals: Vec<Vec<f64>> = self
            .inputs
            .iter()
            .zip(&self.outputs)
            .map(|(x, g)| g.iter().zip(x).map(|(g, x)| g - x).collect())
            .collect();
        let k = residuals.len() - 1;
        let dx: Vec<Vec<f64>> = self
            .inputs
            .windows(2)
            .map(|w| difference(&w[1], &w[0]))
            .collect();
        let df: Vec<Vec<f64>> = residuals
            .windows(2)
            .map(|w| difference(&w[1], &w[0]))
            .collect();
        let gamma = least_squares(&df, &residuals[k]);
        (0..residuals[k].len())
            .map(|n| {
                let mixed = self.inputs[k][n] + beta * residuals[k][n]
                    - gamma
                        .iter()
                        .enumerate()
                        .map(|(i, g)| (dx[i][n] + beta * df[i][n]) * g)
                        .sum::<f64>();
                mixed.max(0.0)
            })
            .collect()
    }
}

/// Plain relaxation x + β(g − x), clamped to ≥ 0: what [`Mixing::next`] gives with no memory.
pub(crate) fn relaxed(input: &[f64], output: &[f64], beta: f64) -> Vec<f64> {
    input
        .iter()
        .zip(output)
        .map(|(x, g)| (x + beta * (g - x)).max(0.0))
        .collect()
}

fn difference(a: &[f64], b: &[f64]) -> Vec<f64> {
    a.iter().zip(b).map(|(a, b)| a - b).collect()
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| a * b).sum()
}

/// γ minimising ‖f − Σ γ_i columns_i‖ by the (regularised) normal equations, solved by
/// Gaussian elimination with partial pivoting (a handful of columns).
fn least_squares(columns: &[Vec<f64>], f: &[f64]) -> Vec<f64> {
    let m = columns.len();
    let mut a: Vec<Vec<f64>> = (0..m)
        .map(|i| {
            let mut row: Vec<f64> = (0..m).map(|j| dot(&columns[i], &columns[j])).collect();
            row[i] += REGULARISATION * row[i] + f64::MIN_POSITIVE;
            row.push(dot(&columns[i], f));
            row
        })
        .collect();
    for c in 0..m {
        let pivot = (c..m)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        a.swap(c, pivot);
        let (upper, lower) = a.split_at_mut(c + 1);
        let pivot = &upper[c];
        for row in lower {
            let q = row[c] / pivot[c];
            for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                *x -= q * p;
            }
        }
    }
    let mut gamma = vec![0.0; m];
    for c in (0..m).rev() {
        let tail: f64 = (c + 1..m).map(|j| a[c][j] * gamma[j]).sum();
        let g = (a[c][m] - tail) / a[c][c];
        gamma[c] = if g.is_finite() { g } else { 0.0 };
    }
    gamma
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_affine_map_is_solved_once_the_memory_spans_it() {
        // g(x) = A x + b with A = [[0.9, 0.3], [−0.2, 0.8]] (spectral radius ≈ 0.87: plain
        // relaxation crawls); fixed point x* = (I − A)⁻¹ b, by hand: (I − A) = [[0.1, −0.3],
        // [0.2, 0.2]], det 0.08, b = (0.5, 1) → x* = (0.2·0.5 + 0.3·1, −0.2·0.5 + 0.1·1)/0.08
        // = (5, 0).
        let g = |x: &[f64]| {
            vec![
                0.9 * x[0] + 0.3 * x[1] + 0.5,
                -0.2 * x[0] + 0.8 * x[1] + 1.0,
            ]
        };
        let mut mixing = Mixing::default();
        let mut x = vec![1.0, 1.0];
        for _ in 0..4 {
            let gx = g(&x);
            x = mixing.next(x, gx, 2, 0.6);
        }
        // Two differences span the plane: from the third step on, the mixing is exact.
        assert!((x[0] - 5.0).abs() < 1e-9 && x[1].abs() < 1e-9, "{x:?}");
    }

    #[test]
    fn without_memory_it_is_plain_relaxation_and_stays_non_negative() {
        let mut mixing = Mixing::default();
        let x = mixing.next(vec![1.0, 2.0], vec![3.0, -8.0], 0, 0.5);
        // 1 + 0.5·2 = 2; 2 + 0.5·(−10) = −3 → clamped to 0.
        assert_eq!(x, vec![2.0, 0.0]);
        mixing.forget();
        let x = mixing.next(vec![0.0], vec![1.0], 3, 0.6);
        assert_eq!(x, vec![0.6]);
        assert_eq!(relaxed(&[1.0, 2.0], &[3.0, -8.0], 0.5), vec![2.0, 0.0]);
    }
}
