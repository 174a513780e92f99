//! The state of one limit analysis: the model the programmes are written on (assembly or chain),
//! its rows and scale, the margin and live-load programmes, and the reading of resultants and
//! mechanism from their solutions. [`super`] drives it.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;

use clarabel::solver::SolverStatus;

use super::problem::{ArchProblem, Formulation, LimitSettings, LimitSolution, LimitStatus};
use super::programme::{
    dot, failure, solve_chain_programme, solve_programme, solve_state_programme, InteriorPoint,
    Programme, ProgrammeSpec, Refinement,
};
use super::rows::{limit_rows, Row};
use super::squeeze::local_programme;
use crate::arch::chain::ChainStatics;
use crate::arch::equilibrium::{
    assemble_equilibrium, force_scale, Equilibrium, RESULTANTS_PER_INTERFACE,
};
use crate::arch::mechanism::{read_mechanism, Bound, LimitTag, Mechanism, Resultant};
use crate::budget::Stop;
use crate::outcome::SolverFailure;

/// Live loads are scaled to a unit largest component; λ above this counts as no collapse.
pub(super) const LIVE_LOAD_CAP: f64 = 1e6;

/// Whether a state programme's x satisfies H r = b_eq and the rows raised by `shift` to
/// [`STATE_CHECK`] (scaled units: a fraction of the total weight): a programme short of
/// `Solved` is accepted when its state passes.
fn state_holds(eq: &Equilibrium, rows: &[Row], x: &[f64], b_eq: &[f64], shift: f64) -> bool {
    if x.len() < eq.columns || x.iter().any(|v| !v.is_finite()) {
        return false;
    }
    let mut residual: Vec<f64> = b_eq.iter().map(|b| -b).collect();
    for &(i, j, v) in &eq.triplets {
        residual[i] += v * x[j];
    }
    let balanced = residual.iter().all(|r| r.abs() <= STATE_CHECK);
    let admissible = rows.iter().all(|row| {
        let lhs: f64 = row.entries[..row.len].iter().map(|&(j, v)| v * x[j]).sum();
        let raised = if row.tag.resultant == Resultant::Passive {
            0.0
        } else {
            shift
        };
        lhs <= row.b + raised + STATE_CHECK
    });
    balanced && admissible
}

/// The costs of the state programme: 1 on every normal force with a lower bound (a row
/// −q ≤ b or −s ≤ b of its own), 0 elsewhere.
fn normal_costs(rows: &[Row], columns: usize) -> Vec<f64> {
    let mut costs = vec![0.0; columns];
    for row in rows {
        let normal = matches!(row.tag.resultant, Resultant::Q | Resultant::S);
        if normal && row.tag.bound == Bound::Lower && row.len == 1 {
            costs[row.entries[0].0] = 1.0;
        }
    }
    costs
}

/// The largest residual [`state_holds`] accepts, in units of the total weight.
const STATE_CHECK: f64 = 1e-7;

/// Whether `problem` is written on the chain's three redundants: asked for, and a chain
/// (passive forces are variables of their own: only the general assembly has room for them,
/// and only a chain has the chain's three redundants).
pub fn on_chain(problem: &ArchProblem, settings: &LimitSettings) -> bool {
    let chain = problem.passive.is_empty() && problem.assembly.is_chain();
    settings.formulation == Formulation::Chain && chain
}

/// Whether a state programme ended with a state worth checking.
fn usable(status: SolverStatus) -> bool {
    matches!(status, SolverStatus::Solved | SolverStatus::AlmostSolved)
}

/// The answer of a solve, before the solve statistics are added.
pub(super) struct Found {
    pub status: LimitStatus,
    pub load_factor: Option<f64>,
    pub dead_load_carried: Option<bool>,
    pub dead_load_margin: Option<f64>,
    pub resultants: Vec<[f64; 3]>,
    pub passive: Vec<f64>,
    pub mechanism: Option<Mechanism>,
}

/// margin(λ) with its state and multipliers.
pub(super) struct MarginEvaluation {
    pub lambda: f64,
    pub value: f64,
    pub programme: Programme,
}

/// The model the programmes are written on.
enum Model {
    /// Livesley's general assembly: all resultants and H r + λ₀w + λp = 0.
    Assembly(Equilibrium),
    /// The chain: three redundants, resultants affine in them.
    Chain(ChainStatics),
}

pub(super) struct Context<'a> {
    problem: &'a ArchProblem,
    model: Model,
    rows: Vec<Row>,
    force_scale: f64,
    settings: &'a LimitSettings,
    refinement: Refinement,
    pub iterations: u32,
    pub programmes: usize,
}

impl<'a> Context<'a> {
    pub fn new(problem: &'a ArchProblem, settings: &'a LimitSettings) -> Self {
        let (a, gamma, loads) = (&problem.assembly, problem.unit_weight, &problem.live_loads);
        let dead = &problem.dead_loads;
        let force_scale = force_scale(a, gamma, dead);
        let chain = problem.passive.is_empty() && a.is_chain();
        let model = match on_chain(problem, settings) {
            true => Model::Chain(ChainStatics::new(a, gamma, dead, loads)),
            false => {
                let mut eq = assemble_equilibrium(a, gamma, dead, loads);
                eq.add_passive(a, &problem.passive);
                Model::Assembly(eq)
            }
        };
        let rows = limit_rows(problem, force_scale);
        // Plain chains (either formulation) are solved as they always were; the programmes of
        // assemblies, passive restraint and crushing refine only when they must.
        let refinement = if chain && problem.crushing.is_none() {
            Refinement::Always
        } else {
            Refinement::OnRetry
        };
        Self {
            problem,
            model,
            rows,
            force_scale,
            settings,
            refinement,
            iterations: 0,
            programmes: 0,
        }
    }

    fn count(&mut self, programme: Programme) -> Result<Programme, SolverFailure> {
        self.iterations += programme.iterations;
        self.programmes += 1;
        match failure(programme.status) {
            Some(f) => Err(f),
            None => Ok(programme),
        }
    }

    /// The index of the extra variable (δ or λ) in the programme's x.
    pub fn extra(&self) -> usize {
        match &self.model {
            Model::Assembly(eq) => eq.columns,
            Model::Chain(_) => 3,
        }
    }

    pub fn margin(&mut self, lambda: f64) -> Result<MarginEvaluation, SolverFailure> {
        let programme = self.margin_programme(lambda);
        self.margin_from(lambda, programme)
    }

    /// margin(λ) read from its programme (counted).
    fn margin_from(
        &mut self,
        lambda: f64,
        programme: Programme,
    ) -> Result<MarginEvaluation, SolverFailure> {
        let programme = self.count(programme)?;
        let value = programme.x[self.extra()];
        Ok(MarginEvaluation {
            lambda,
            value,
            programme,
        })
    }

    /// Whether the margin at full dead load and the live-load programme are worth solving side
    /// by side (on two threads) rather than one after the other: the general formulation's
    /// programmes of assemblies and passive restraint, milliseconds each. Plain chains and
    /// crushing (programmes of a fraction of a millisecond, cut after cut) stay sequential.
    pub fn solves_side_by_side(&self) -> bool {
        matches!(self.model, Model::Assembly(_)) && self.refinement == Refinement::OnRetry
    }

    /// margin(1) and the live-load programme solved at once on two threads (see
    /// [`Self::solves_side_by_side`]); both counted.
    pub fn margin_and_live(
        &mut self,
    ) -> (
        Result<MarginEvaluation, SolverFailure>,
        Result<(Programme, f64), SolverFailure>,
    ) {
        // A dead load not carried has no live-load factor: its programme is then stopped.
        let not_carried = Arc::new(AtomicBool::new(false));
        let margin_then_flag = || {
            let programme = self.margin_programme(1.0);
            let carried = programme.status == clarabel::solver::SolverStatus::Solved
                && programme.x[self.extra()] <= self.settings.margin_tolerance;
            not_carried.store(!carried, Ordering::Relaxed);
            programme
        };
        let (margin, (live, scale)) =
            rayon::join(margin_then_flag, || self.live_programme(Some(&not_carried)));
        let margin = self.margin_from(1.0, margin);
        let live = self.count(live).map(|p| (p, scale));
        (margin, live)
    }

    fn margin_programme(&self, lambda: f64) -> Programme {
        match &self.model {
            Model::Assembly(eq) => {
                let b_eq: Vec<f64> = eq.dead.iter().map(|w| -lambda * w).collect();
                let zeros = vec![0.0; eq.rows];
                let spec = ProgrammeSpec {
                    extra_equilibrium: &zeros,
                    b_eq: &b_eq,
                    row_extra: Some(-1.0),
                    cap: (-1.0, 1.0),
                    objective: 1.0,
                };
                solve_programme(eq, &self.rows, &spec, self.solve(), None)
            }
            Model::Chain(chain) => solve_chain_programme(
                chain,
                &self.rows,
                lambda,
                |_, _| -1.0,
                (-1.0, 1.0),
                1.0,
                self.solve(),
            ),
        }
    }

    /// The live-load programme: λ̂ = λ·scale with the live loads scaled to a unit largest
    /// component; returns the programme and the scale.
    pub fn live(&mut self) -> Result<(Programme, f64), SolverFailure> {
        let (programme, scale) = self.live_programme(None);
        Ok((self.count(programme)?, scale))
    }

    fn live_programme(&self, abort: Option<&Arc<AtomicBool>>) -> (Programme, f64) {
        match &self.model {
            Model::Assembly(eq) => {
                let scale = eq.live.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                let live: Vec<f64> = eq.live.iter().map(|p| p / scale).collect();
                let b_eq: Vec<f64> = eq.dead.iter().map(|w| -w).collect();
                let spec = ProgrammeSpec {
                    extra_equilibrium: &live,
                    b_eq: &b_eq,
                    row_extra: None,
                    cap: (1.0, LIVE_LOAD_CAP),
                    objective: -1.0,
                };
                let solve = self.solve();
                (solve_programme(eq, &self.rows, &spec, solve, abort), scale)
            }
            Model::Chain(chain) => {
                let scale = chain.live_scale;
                let coefficient = |a: &[f64; 3], k: usize| dot(a, &chain.affine(k).live) / scale;
                let programme = solve_chain_programme(
                    chain,
                    &self.rows,
                    1.0,
                    coefficient,
                    (1.0, LIVE_LOAD_CAP),
                    -1.0,
                    self.solve(),
                );
                (programme, scale)
            }
        }
    }

    /// The state of least normal force among those the limit rows admit at dead-load factor
    /// `dead_factor`, live-load factor `live_factor` and margin `margin` (the rows raised by
    /// it): min Σ(q + s) over the normal forces with a lower bound, by the state programme. The
    /// interior-point method needs an interior: the caller backs the factors (or the margin)
    /// off the optimum a little.
    /// Returns the resultants and passive forces in force units; `None` for a chain (three
    /// redundants: nothing to choose), or when the programme does not solve or its state fails
    /// the check (the caller keeps the state it has).
    pub fn least_normal_state(
        &mut self,
        dead_factor: f64,
        live_factor: f64,
        margin: f64,
    ) -> Option<(Vec<[f64; 3]>, Vec<f64>)> {
        let Model::Assembly(eq) = &self.model else {
            return None;
        };
        let b_eq = self.state_equations(eq, dead_factor, live_factor);
        let costs = normal_costs(&self.rows, eq.columns);
        let programme =
            solve_state_programme(eq, &self.rows, &b_eq, margin, &costs, self.solve_once());
        self.iterations += programme.iterations;
        self.programmes += 1;
        if !usable(programme.status) {
            return None;
        }
        self.checked_state(eq, &programme.x, &b_eq, margin, dead_factor, live_factor)
    }

    /// [`Self::least_normal_state`] changing only the resultants of `contacts`: every other
    /// contact keeps its force in `state` (resultants and passive forces in force units, at the
    /// same factors and margin), so the programme is as small as the squeeze (see
    /// [`super::squeeze`]). `None` as there, or when nothing is left to change.
    pub fn relieve_squeeze(
        &mut self,
        dead_factor: f64,
        live_factor: f64,
        margin: f64,
        resultants: &[[f64; 3]],
        passive: &[f64],
        contacts: &[usize],
    ) -> Option<(Vec<[f64; 3]>, Vec<f64>)> {
        let Model::Assembly(eq) = &self.model else {
            return None;
        };
        let w = self.force_scale;
        let mut x: Vec<f64> = resultants.iter().flatten().map(|v| v / w).collect();
        x.extend(passive.iter().map(|p| p / w));
        if x.len() != eq.columns || contacts.is_empty() {
            return None;
        }
        let b_eq = self.state_equations(eq, dead_factor, live_factor);
        let local = local_programme(eq, &self.rows, &x, &b_eq, margin, contacts);
        let costs = normal_costs(&local.rows, local.eq.columns);
        let programme = solve_state_programme(
            &local.eq,
            &local.rows,
            &local.b_eq,
            margin + local.excess,
            &costs,
            self.solve_once(),
        );
        self.iterations += programme.iterations;
        self.programmes += 1;
        if !usable(programme.status) || programme.x.len() < local.columns.len() {
            return None;
        }
        for (&j, &v) in local.columns.iter().zip(&programme.x) {
            x[j] = v;
        }
        let shift = margin + local.excess;
        self.checked_state(eq, &x, &b_eq, shift, dead_factor, live_factor)
    }

    /// The state x (scaled, every column) in force units, when it passes [`state_holds`]
    /// (equations H r = `b_eq`, the rows raised by `shift`), read at the given factors.
    fn checked_state(
        &self,
        eq: &Equilibrium,
        x: &[f64],
        b_eq: &[f64],
        shift: f64,
        dead_factor: f64,
        live_factor: f64,
    ) -> Option<(Vec<[f64; 3]>, Vec<f64>)> {
        state_holds(eq, &self.rows, x, b_eq, shift).then(|| {
            (
                self.resultants(x, dead_factor, live_factor),
                self.passive(x),
            )
        })
    }

    /// How the interior-point method solves this analysis' margin and live-load programmes.
    fn solve(&self) -> InteriorPoint<'a> {
        InteriorPoint {
            settings: self.settings,
            refinement: self.refinement,
        }
    }

    /// How it solves a state programme: once, without refinement.
    fn solve_once(&self) -> InteriorPoint<'a> {
        InteriorPoint {
            settings: self.settings,
            refinement: Refinement::Never,
        }
    }

    /// The right-hand sides of the equilibrium rows at the given factors.
    fn state_equations(&self, eq: &Equilibrium, dead_factor: f64, live_factor: f64) -> Vec<f64> {
        eq.dead
            .iter()
            .zip(&eq.live)
            .map(|(w, p)| -dead_factor * w - live_factor * p)
            .collect()
    }

    /// Whether any live load is non-zero.
    pub fn has_live_load(&self) -> bool {
        match &self.model {
            Model::Assembly(eq) => eq.live.iter().any(|v| *v != 0.0),
            Model::Chain(chain) => chain.live_scale > 0.0,
        }
    }

    /// Slope dmargin/dλ at the multipliers of `evaluation`: minus the λ-derivative of the
    /// right-hand side, dotted with the multipliers (LP sensitivity).
    pub fn slope(&self, evaluation: &MarginEvaluation) -> f64 {
        let z = &evaluation.programme.z;
        match &self.model {
            Model::Assembly(eq) => eq.dead.iter().zip(z).map(|(w, y)| w * y).sum(),
            Model::Chain(chain) => self
                .rows
                .iter()
                .zip(z)
                .map(|(row, z)| {
                    let (k, a) = row.local();
                    z * dot(&a, &chain.affine(k).dead)
                })
                .sum(),
        }
    }

    /// Resultants in force units from a programme's x at the given factors.
    pub fn resultants(&self, x: &[f64], dead_factor: f64, live_factor: f64) -> Vec<[f64; 3]> {
        let w = self.force_scale;
        match &self.model {
            Model::Assembly(eq) => x[..eq.resultant_columns]
                .chunks_exact(RESULTANTS_PER_INTERFACE)
                .map(|r| [r[0] * w, r[1] * w, r[2] * w])
                .collect(),
            Model::Chain(chain) => chain
                .resultants([x[0], x[1], x[2]], dead_factor, live_factor)
                .into_iter()
                .map(|r| [r[0] * w, r[1] * w, r[2] * w])
                .collect(),
        }
    }

    /// The passive forces in force units from a programme's x (empty without them).
    pub fn passive(&self, x: &[f64]) -> Vec<f64> {
        match &self.model {
            Model::Assembly(eq) if x.len() >= eq.columns => x[eq.resultant_columns..eq.columns]
                .iter()
                .map(|p| p * self.force_scale)
                .collect(),
            _ => Vec::new(),
        }
    }

    pub fn mechanism(&self, programme: &Programme) -> Option<Mechanism> {
        let tags: Vec<LimitTag> = self.rows.iter().map(|r| r.tag).collect();
        let assembly = &self.problem.assembly;
        match &self.model {
            Model::Assembly(eq) => read_mechanism(
                assembly,
                eq.length_scale,
                &programme.z[..eq.rows],
                &programme.z[eq.rows..eq.rows + self.rows.len()],
                &tags,
            ),
            Model::Chain(chain) => {
                // Deformation rates d_k = −Σ a·z over the rows of interface k (H ᵀy = −A ᵀz).
                let mut deformation = vec![[0.0; 3]; chain.interfaces()];
                for (row, z) in self.rows.iter().zip(&programme.z) {
                    let (k, a) = row.local();
                    for i in 0..3 {
                        deformation[k][i] -= a[i] * z;
                    }
                }
                let y = chain.block_velocities(&deformation);
                read_mechanism(
                    assembly,
                    assembly.length_scale(),
                    &y,
                    &programme.z[..self.rows.len()],
                    &tags,
                )
            }
        }
    }

    pub fn finish(&self, found: Found, start: Instant) -> LimitSolution {
        let Found {
            status,
            load_factor,
            dead_load_carried,
            dead_load_margin,
            resultants,
            passive,
            mechanism,
        } = found;
        LimitSolution {
            status,
            stop: Stop::Finished,
            load_factor,
            dead_load_carried,
            dead_load_margin,
            resultants,
            passive,
            mechanism,
            iterations: self.iterations,
            programmes: self.programmes,
            solve_time_secs: start.elapsed().as_secs_f64(),
        }
    }

    /// No answer: a programme failed, or the budget ended it (then its `stop` says why: a
    /// programme the budget interrupted reports a failure of its own).
    pub fn failed(&self, failure: SolverFailure, start: Instant) -> LimitSolution {
        let mut solution = self.finish(
            Found {
                status: LimitStatus::SolverFailed(failure),
                load_factor: None,
                dead_load_carried: None,
                dead_load_margin: None,
                resultants: Vec::new(),
                passive: Vec::new(),
                mechanism: None,
            },
            start,
        );
        solution.stop = self.settings.budget.stop();
        solution
    }
}
