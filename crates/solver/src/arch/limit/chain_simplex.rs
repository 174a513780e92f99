//! A chain programme over (x₀, x₁, x₂, extra) on the dense simplex method (issue 45): four
//! variables, so a vertex costs a few pivots of O(rows) each, where the interior-point method
//! pays its 20–80 iterations whatever the size. Rows arrive round by round (the constraint
//! generation of [`super::programme::solve_chain_programme`]); the basis of one round starts
//! the next, whose new rows only the dual simplex has to restore.
//!
//! The vertex and its multipliers are certified by the simplex method itself (residuals of
//! their defining equations); any failure hands the programme back to the interior-point
//! solver.

use crate::numerics::simplex::{maximise, Basis, Lp, SimplexFailure, SimplexSettings, Vertex};

/// The most rows a programme is taken on this way: beyond, its pivots (O(rows) each) cost more
/// than the interior-point method's iterations.
pub(super) const MAX_SIMPLEX_ROWS: usize = 3000;

/// The chain programme's rows so far, their basis and which row of the caller each holds.
pub(super) struct ChainSimplex {
    lp: Lp,
    basis: Option<Basis>,
    /// The caller's row index of each programme row (`None`: the cap).
    origin: Vec<Option<usize>>,
    settings: SimplexSettings,
}

impl ChainSimplex {
    /// Minimises `objective`·extra subject to `cap.0`·extra ≤ `cap.1` and the rows added.
    pub(super) fn new(objective: f64, cap: (f64, f64)) -> Self {
        let mut lp = Lp::new(vec![0.0, 0.0, 0.0, -objective], 3);
        lp.push_row(&[0.0, 0.0, 0.0, cap.0], cap.1);
        Self {
            lp,
            basis: None,
            origin: vec![None],
            settings: SimplexSettings {
                max_pivots: 2000,
                ..SimplexSettings::default()
            },
        }
    }

    /// Adds the caller's row `i`: coefficients on (x, extra) and right-hand side.
    pub(super) fn add(&mut self, i: usize, (a, b): &([f64; 4], f64)) {
        self.lp.push_row(a, *b);
        self.origin.push(Some(i));
    }

    /// The caller's row of each programme row (`None`: the cap).
    pub(super) fn origin(&self) -> &[Option<usize>] {
        &self.origin
    }

    /// A first basis: the cap and three rows independent in x (greedily, by Gram–Schmidt on
    /// their x-coefficients).
    fn cold_basis(&self) -> Result<Basis, SimplexFailure> {
        let mut chosen = vec![0];
        let mut directions: Vec<[f64; 3]> = Vec::new();
        for i in 1..self.lp.rows() {
            let mut v: [f64; 3] = std::array::from_fn(|c| self.lp.entry(i, c));
            let norm = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            for d in &directions {
                let along = v[0] * d[0] + v[1] * d[1] + v[2] * d[2];
                for c in 0..3 {
                    v[c] -= along * d[c];
                }
            }
            let rest = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            if norm > 0.0 && rest > 0.3 * norm {
                directions.push(v.map(|c| c / rest));
                chosen.push(i);
                if chosen.len() == 4 {
                    break;
                }
            }
        }
        Basis::new(&self.lp, chosen)
    }

    /// The optimal vertex of the rows so far: from the last basis, or cold when there is none
    /// or the warm start fails.
    pub(super) fn solve(&mut self) -> Result<Vertex, SimplexFailure> {
        if let Some(mut basis) = self.basis.take() {
            if let Ok(vertex) = maximise(&self.lp, &mut basis, &self.settings) {
                self.basis = Some(basis);
                return Ok(vertex);
            }
        }
        let mut basis = self.cold_basis()?;
        let vertex = maximise(&self.lp, &mut basis, &self.settings)?;
        self.basis = Some(basis);
        Ok(vertex)
    }
}
