//! The live-load programme of a chain (with or without passive restraint), on the simplex
//! method and warm from one set of live loads to the next: the stops of a rolling load
//! (model §5.3).
//!
//! On a chain the resultants of interface k are (q, s, t)_k = D_k (x + C_k) (see
//! [`crate::arch::chain`]), C_k the wrench of every load on the blocks before k; a passive force
//! p_j (0 ≤ p_j ≤ capacity, horizontal, on block b_j) adds p_j·P_j to C_k for every k > b_j. So
//! the programme of one stop is, over y = (x, λ̂, p),
//!
//! ```text
//!   max λ̂  subject to  a·D_k (x + C_k^dead + λ̂ C_k^live/scale + Σ_{b_j<k} p_j P_j) ≤ b
//!                       for every yield row a·(q, s, t)_k ≤ b,   the passive bounds,
//!                       0 ≤ λ̂ ≤ cap,
//! ```
//!
//! with 4 + P variables — the interior-point solver's general formulation has 3 per interface
//! and the equilibrium rows, and no warm start. From stop to stop only the column of λ̂ changes
//! (C_k^live), so the optimal basis of one stop is a start for the next, a few pivots away.
//! λ̂ ≥ 0 is implied when the dead load is carried (λ̂ = 0 is then admissible); it is written
//! to give the first basis its row for λ̂.

use super::context::LIVE_LOAD_CAP;
use super::problem::ArchProblem;
use super::programme::dot;
use super::rows::{limit_rows, Row};
use crate::arch::chain::ChainStatics;
use crate::arch::equilibrium::{force_scale, LiveLoad};
use crate::arch::mechanism::Resultant;
use crate::numerics::simplex::{
    maximise, set_column, Basis, Lp, SimplexFailure, SimplexSettings, MAX_VARIABLES,
};

/// Index of λ̂ in y.
const LAMBDA: usize = 3;
/// The most passive forces swept this way. The first stop starts cold, O(P) pivots of O(P²)
/// each; above some 400 forces (N ≈ 400 voussoirs) that costs more than the interior-point
/// sweep (measured 2026-11-24: N = 300 0.44 s against 0.68 s, N = 500 1.6 s against 1.2 s).
const MAX_PASSIVE_FORCES: usize = 300;

/// A chain's live-load programme, kept (with its basis) from one set of live loads to the next.
pub struct WarmLiveLoad<'a> {
    problem: &'a ArchProblem,
    rows: Vec<Row>,
    lp: Lp,
    basis: Option<Basis>,
    settings: SimplexSettings,
}

/// The answer at one set of live loads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WarmStop {
    /// The live-load factor λ; `None` when no finite factor causes collapse (λ̂ at its cap).
    pub load_factor: Option<f64>,
    /// Pivots of the simplex method.
    pub pivots: usize,
    /// Whether the solve started from the previous stop's basis.
    pub warm: bool,
}

impl<'a> WarmLiveLoad<'a> {
    /// The programme of `problem`'s blocks, limits, dead loads and passive forces; `None` when it
    /// is not a chain, has crushing (cuts from stop to stop) or fixed shear capacities, or has
    /// more variables than the dense method takes.
    pub fn new(problem: &'a ArchProblem) -> Option<Self> {
        let assembly = &problem.assembly;
        let variables = 4 + problem.passive.len();
        let fits = assembly.is_chain()
            && problem.crushing.is_none()
            && problem.shear_capacities.is_none()
            && problem.passive.len() <= MAX_PASSIVE_FORCES
            && variables <= MAX_VARIABLES;
        if !fits {
            return None;
        }
        let scale = force_scale(assembly, problem.unit_weight, &problem.dead_loads);
        let statics = ChainStatics::new(assembly, problem.unit_weight, &problem.dead_loads, &[]);
        let rows = limit_rows(problem, scale);
        // P_j: the wrench of a unit passive force j.
        let passive: Vec<(usize, [f64; 3])> = problem
            .passive
            .iter()
            .map(|f| (f.block, statics.wrench(f.point, (f.direction, 0.0))))
            .collect();
        let mut objective = vec![0.0; variables];
        objective[LAMBDA] = 1.0;
        let mut lp = Lp::new(objective, LAMBDA);
        let mut a = vec![0.0; variables];
        for row in &rows {
            a.fill(0.0);
            if row.tag.resultant == Resultant::Passive {
                let j = row.tag.interface;
                a[4 + j] = row.entries[0].1;
                lp.push_row(&a, row.b);
                continue;
            }
            let (k, local) = row.local();
            let affine = statics.affine(k);
            // g = aᵀD_k: the row's coefficients on x, and on p_j through P_j.
            let g: [f64; 3] =
                std::array::from_fn(|i| (0..3).map(|r| local[r] * affine.map[r][i]).sum());
            a[..3].copy_from_slice(&g);
            for (j, (block, wrench)) in passive.iter().enumerate() {
                if *block < k {
                    a[4 + j] = dot(&g, wrench);
                }
            }
            lp.push_row(&a, row.b - dot(&local, &affine.dead));
        }
        a.fill(0.0);
        a[LAMBDA] = 1.0;
        lp.push_row(&a, LIVE_LOAD_CAP);
        a[LAMBDA] = -1.0;
        lp.push_row(&a, 0.0);
        Some(Self {
            problem,
            rows,
            lp,
            basis: None,
            settings: SimplexSettings::default(),
        })
    }

    /// The first basis: every passive force at zero, λ̂ = 0, and three yield rows independent
    /// in x (greedily, by Gram–Schmidt on their x-coefficients).
    fn cold_basis(&self) -> Result<Basis, SimplexFailure> {
        let mut chosen: Vec<usize> = Vec::new();
        let mut directions: Vec<[f64; 3]> = Vec::new();
        for (i, row) in self.rows.iter().enumerate() {
            if row.tag.resultant == Resultant::Passive {
                continue;
            }
            let mut v: [f64; 3] = std::array::from_fn(|c| self.lp.entry(i, c));
            let norm = dot(&v, &v).sqrt();
            for d in &directions {
                let along = dot(&v, d);
                for c in 0..3 {
                    v[c] -= along * d[c];
                }
            }
            let rest = dot(&v, &v).sqrt();
            if norm > 0.0 && rest > 0.3 * norm {
                directions.push(v.map(|c| c / rest));
                chosen.push(i);
                if chosen.len() == 3 {
                    break;
                }
            }
        }
        for (i, row) in self.rows.iter().enumerate() {
            let lower_passive = row.tag.resultant == Resultant::Passive && row.entries[0].1 < 0.0;
            if lower_passive {
                chosen.push(i);
            }
        }
        chosen.push(self.lp.rows() - 1);
        Basis::new(&self.lp, chosen)
    }

    /// λ for the live loads `loads` (which must not all be zero), from the last stop's basis
    /// when there is one; a failed warm start is retried cold.
    pub fn solve(&mut self, loads: &[LiveLoad]) -> Result<WarmStop, SimplexFailure> {
        let problem = self.problem;
        let statics = ChainStatics::new(
            &problem.assembly,
            problem.unit_weight,
            &problem.dead_loads,
            loads,
        );
        let scale = statics.live_scale;
        if scale.is_nan() || scale <= 0.0 {
            return Err(SimplexFailure::Singular);
        }
        let mut column = Vec::with_capacity(self.lp.rows());
        for row in &self.rows {
            column.push(if row.tag.resultant == Resultant::Passive {
                0.0
            } else {
                let (k, local) = row.local();
                dot(&local, &statics.affine(k).live) / scale
            });
        }
        column.extend([1.0, -1.0]);
        // Warm: the last basis with λ̂'s column changed; cold when there is none or it fails.
        let mut warm = None;
        if let Some(mut basis) = self.basis.take() {
            if set_column(&mut self.lp, &column, Some(&mut basis)).is_ok() {
                if let Ok(vertex) = maximise(&self.lp, &mut basis, &self.settings) {
                    warm = Some((vertex, basis));
                }
            }
        } else {
            set_column(&mut self.lp, &column, None)?;
        }
        let is_warm = warm.is_some();
        let (vertex, basis) = match warm {
            Some(found) => found,
            None => {
                let mut basis = self.cold_basis()?;
                (maximise(&self.lp, &mut basis, &self.settings)?, basis)
            }
        };
        self.basis = Some(basis);
        let lambda_scaled = vertex.y[LAMBDA];
        let load_factor =
            (lambda_scaled < LIVE_LOAD_CAP * (1.0 - 1e-6)).then(|| lambda_scaled / scale);
        Ok(WarmStop {
            load_factor,
            pivots: vertex.pivots,
            warm: is_warm,
        })
    }

    /// Forgets the basis: the next solve starts cold.
    pub fn forget(&mut self) {
        self.basis = None;
    }
}
