//! One linear programme on Clarabel: the general (assembly) form over all resultants, the chain
//! form over three redundants solved by constraint generation, and Clarabel's status named as a
//! [`SolverFailure`].

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus,
    SupportedConeT, ZeroConeT,
};

use super::chain_simplex::{ChainSimplex, MAX_SIMPLEX_ROWS};
use super::problem::LimitSettings;
use super::rows::Row;
use crate::arch::chain::ChainStatics;
use crate::arch::equilibrium::Equilibrium;
use crate::arch::mechanism::Resultant;
use crate::outcome::SolverFailure;

/// Outcome of one programme.
pub(super) struct Programme {
    pub status: SolverStatus,
    pub x: Vec<f64>,
    pub z: Vec<f64>,
    pub iterations: u32,
}

/// When Clarabel refines the solutions of its KKT systems iteratively.
///
/// Refinement makes each interior-point step dearer (a residual product and a further solve per
/// refinement step: a third of the time on a two-ring arch), and most programmes of assemblies
/// reach the tolerances without it; but some (the crushing planes' nearly parallel rows) end in
/// reduced accuracy. `OnRetry` solves without refinement first and again with it whenever that
/// ends short of `Solved`, so every answer meets the same tolerances on the same residuals.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Refinement {
    /// Refine from the start (the programmes of plain chains, answered as they always were).
    Always,
    /// Solve without refinement; with it only when that did not solve.
    OnRetry,
    /// Solve once without refinement (the state programme: its state is checked, and one
    /// short of `Solved` that passes the check is as good).
    Never,
}

/// How the interior-point method solves a programme: its settings and when it refines.
#[derive(Debug, Clone, Copy)]
pub(super) struct InteriorPoint<'a> {
    /// The interior-point settings (tolerances, iterations, the budget).
    pub settings: &'a LimitSettings,
    /// When the method refines the solutions of its KKT systems.
    pub refinement: Refinement,
}

/// One programme over the resultants r and one extra variable x (δ or λ):
/// min objective·x subject to H r + extra_equilibrium·x = b_eq, the limit rows (each with
/// `row_extra`·x added), and cap.0·x ≤ cap.1.
pub(super) struct ProgrammeSpec<'a> {
    pub extra_equilibrium: &'a [f64],
    pub b_eq: &'a [f64],
    pub row_extra: Option<f64>,
    pub cap: (f64, f64),
    pub objective: f64,
}

pub(super) fn solve_programme(
    eq: &Equilibrium,
    rows: &[Row],
    spec: &ProgrammeSpec,
    solve: InteriorPoint<'_>,
    abort: Option<&Arc<AtomicBool>>,
) -> Programme {
    let ProgrammeSpec {
        extra_equilibrium,
        b_eq,
        row_extra,
        cap,
        objective: objective_extra,
    } = *spec;
    let n = eq.columns + 1;
    let extra = eq.columns;
    let m_eq = eq.rows;
    let m = m_eq + rows.len() + 1;
    let (mut ti, mut tj, mut tv, mut b) = assemble(eq, rows, b_eq, 0.0);
    for (i, &v) in extra_equilibrium.iter().enumerate() {
        if v != 0.0 {
            ti.push(i);
            tj.push(extra);
            tv.push(v);
        }
    }
    for (r, row) in rows.iter().enumerate() {
        // Passive bounds are hard: a margin relaxes the yield limits only.
        if let (Some(coefficient), true) = (row_extra, relaxed(row)) {
            ti.push(m_eq + r);
            tj.push(extra);
            tv.push(coefficient);
        }
    }
    // Cap on the extra variable: cap.0·x_extra ≤ cap.1.
    ti.push(m - 1);
    tj.push(extra);
    tv.push(cap.0);
    b.push(cap.1);
    let mut c = vec![0.0; n];
    c[extra] = objective_extra;
    run_clarabel((m, n, m_eq), (ti, tj, tv), &b, &c, solve, abort)
}

/// The state programme over the resultants alone: min costs·r subject to H r = b_eq and the
/// limit rows with their right-hand sides raised by `shift` (the passive bounds stay as they
/// are). It picks one state among those a solved programme admits at its λ (or δ).
pub(super) fn solve_state_programme(
    eq: &Equilibrium,
    rows: &[Row],
    b_eq: &[f64],
    shift: f64,
    costs: &[f64],
    solve: InteriorPoint<'_>,
) -> Programme {
    let (n, m_eq) = (eq.columns, eq.rows);
    let m = m_eq + rows.len();
    let (ti, tj, tv, b) = assemble(eq, rows, b_eq, shift);
    run_clarabel((m, n, m_eq), (ti, tj, tv), &b, costs, solve, None)
}

/// The triplets of H with the limit rows below it (row m_eq + r for rows[r]), and b: `b_eq`
/// then each row's b, raised by `shift` (the passive bounds never).
fn assemble(
    eq: &Equilibrium,
    rows: &[Row],
    b_eq: &[f64],
    shift: f64,
) -> (Vec<usize>, Vec<usize>, Vec<f64>, Vec<f64>) {
    let capacity = eq.triplets.len() + eq.rows + 4 * rows.len() + 1;
    let (mut ti, mut tj, mut tv) = (
        Vec::with_capacity(capacity),
        Vec::with_capacity(capacity),
        Vec::with_capacity(capacity),
    );
    for &(i, j, v) in &eq.triplets {
        ti.push(i);
        tj.push(j);
        tv.push(v);
    }
    let mut b = Vec::with_capacity(b_eq.len() + rows.len() + 1);
    b.extend_from_slice(b_eq);
    for (r, row) in rows.iter().enumerate() {
        for &(j, v) in &row.entries[..row.len] {
            ti.push(eq.rows + r);
            tj.push(j);
            tv.push(v);
        }
        // Unraised rows keep their b bit for bit (−0.0 + 0.0 would be +0.0).
        let raise = relaxed(row) && shift != 0.0;
        b.push(if raise { row.b + shift } else { row.b });
    }
    (ti, tj, tv, b)
}

/// Whether a row is a yield limit a margin may relax (the passive bounds are hard).
fn relaxed(row: &Row) -> bool {
    row.tag.resultant != Resultant::Passive
}

/// Solves min c'x subject to A x + s = b (A: m × n from the triplets) with s in
/// {0}^m_eq × R₊^(m − m_eq); with [`Refinement::OnRetry`] first without iterative refinement
/// (the iterations of both attempts counted). Setting `abort` stops the interior-point method
/// at its next iteration (`CallbackTerminated`: the answer is no longer wanted).
fn run_clarabel(
    (m, n, m_eq): (usize, usize, usize),
    (ti, tj, tv): (Vec<usize>, Vec<usize>, Vec<f64>),
    b: &[f64],
    c: &[f64],
    solve: InteriorPoint<'_>,
    abort: Option<&Arc<AtomicBool>>,
) -> Programme {
    let InteriorPoint {
        settings,
        refinement,
    } = solve;
    let a = CscMatrix::new_from_triplets(m, n, ti, tj, tv);
    let once = |refine: bool| run_clarabel_once((m, m_eq), &a, b, c, settings, refine, abort);
    if refinement == Refinement::OnRetry {
        let quick = once(false);
        if matches!(
            quick.status,
            SolverStatus::Solved | SolverStatus::CallbackTerminated
        ) {
            return quick;
        }
        let mut refined = once(true);
        refined.iterations += quick.iterations;
        return refined;
    }
    once(refinement == Refinement::Always)
}

/// One attempt of [`run_clarabel`] (m rows, the first m_eq equalities), with iterative
/// refinement when `refine`.
fn run_clarabel_once(
    (m, m_eq): (usize, usize),
    a: &CscMatrix<f64>,
    b: &[f64],
    c: &[f64],
    settings: &LimitSettings,
    refine: bool,
    abort: Option<&Arc<AtomicBool>>,
) -> Programme {
    let n = a.n;
    let p = CscMatrix::zeros((n, n));
    let cones: [SupportedConeT<f64>; 2] = [ZeroConeT(m_eq), NonnegativeConeT(m - m_eq)];
    let tol = settings.tolerance;
    let clarabel_settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .max_iter(settings.max_iterations)
        // The budget's time, the one limit (Clarabel's default, none, without a deadline).
        .time_limit(
            settings
                .budget
                .remaining()
                .map_or(f64::INFINITY, |r| r.as_secs_f64()),
        )
        .tol_gap_abs(tol)
        .tol_gap_rel(tol)
        .tol_feas(tol)
        .tol_ktratio(tol.sqrt() * 1e-2)
        .iterative_refinement_enable(refine)
        .build()
        .expect("the settings are within Clarabel's ranges");
    let mut solver = match DefaultSolver::new(&p, c, a, b, &cones, clarabel_settings) {
        Ok(solver) => solver,
        Err(_) => {
            return Programme {
                status: SolverStatus::NumericalError,
                x: Vec::new(),
                z: Vec::new(),
                iterations: 0,
            }
        }
    };
    // Stopped at the next iteration when the twin programme no longer needs it, or when the
    // analysis' budget is spent (then as at a time limit).
    let abort = abort.map(Arc::clone);
    let budget = settings.budget.clone();
    solver.set_termination_callback(move |_| {
        abort.as_ref().is_some_and(|a| a.load(Ordering::Relaxed)) || budget.is_spent()
    });
    solver.solve();
    let solution = solver.solution;
    let status = match solution.status {
        SolverStatus::CallbackTerminated if settings.budget.is_spent() => SolverStatus::MaxTime,
        status => status,
    };
    Programme {
        status,
        x: solution.x,
        z: solution.z,
        iterations: solution.iterations,
    }
}

/// A programme of the chain formulation over (x₀, x₁, x₂, extra): each limit row a·r_k ≤ b
/// becomes (D_kᵀa)·x + extra_coefficient(a, k)·extra ≤ b − dead_factor·a·(D_k C_k), plus the
/// cap cap.0·extra ≤ cap.1; minimise objective·extra, as `solve` says.
///
/// Only a few rows are active at the optimum (the hinges), so the programme is solved by
/// constraint generation: start from the rows of about 32 evenly spread interfaces and the
/// crushing cuts (added where a previous solution went beyond the curve), solve,
/// add the violated rows that are local maxima of the violation along the chain, repeat until
/// no row is violated by more than the solver tolerance. The multipliers of rows never added
/// are zero, exactly as at the optimum of the full programme.
pub(super) fn solve_chain_programme(
    chain: &ChainStatics,
    rows: &[Row],
    dead_factor: f64,
    extra_coefficient: impl Fn(&[f64; 3], usize) -> f64,
    cap: (f64, f64),
    objective: f64,
    solve: InteriorPoint<'_>,
) -> Programme {
    let settings = solve.settings;
    const MAX_ROUNDS: usize = 40;
    const MAX_ADDED_PER_ROUND: usize = 256;
    let dense = on_redundants(chain, rows, dead_factor, extra_coefficient);
    let interfaces = chain.interfaces();
    let per_interface = rows.len() / interfaces.max(1);
    let mut selected = first_rows(rows, interfaces);
    let mut c = vec![0.0; 4];
    c[3] = objective;
    let lp = ChainLp {
        dense,
        cap,
        c,
        solve,
    };
    let mut iterations = 0;
    let mut rounds = Rounds {
        simplex: Some(ChainSimplex::new(objective, cap)),
        pushed: vec![false; rows.len()],
    };
    for _ in 0..MAX_ROUNDS {
        if settings.budget.is_spent() {
            return unanswered(SolverStatus::MaxTime, iterations);
        }
        let subset: Vec<usize> = (0..rows.len()).filter(|&i| selected[i]).collect();
        let mut programme = rounds.solve(&lp, &subset);
        iterations += programme.iterations;
        programme.iterations = iterations;
        if failure(programme.status).is_some() {
            return programme;
        }
        let mut added = violated_peaks(
            &lp.dense,
            &selected,
            &programme.x,
            per_interface,
            settings.tolerance,
        );
        if added.is_empty() {
            // A margin programme (minimising δ) whose dead load is carried is not read for a
            // mechanism: its vertex's multipliers serve.
            let read = objective < 0.0 || programme.x[3] > settings.margin_tolerance;
            if rounds.simplex.is_some() && read {
                // The simplex method's multipliers are a vertex of the optimal face (a
                // symmetric arch's five hinges come out as an asymmetric four): the interior-
                // point method on the rows that hold at the vertex gives the face's centre,
                // as the whole programme did.
                central_multipliers(&lp, &subset, &mut programme);
            }
            return on_every_row(programme, &subset, rows.len());
        }
        added.sort_by(|a, b| b.0.total_cmp(&a.0));
        for &(_, i) in added.iter().take(MAX_ADDED_PER_ROUND) {
            selected[i] = true;
        }
    }
    unanswered(SolverStatus::MaxIterations, iterations)
}

/// The chain programme written on the redundants, whose rows the rounds of constraint
/// generation solve subsets of.
struct ChainLp<'a> {
    /// Each limit row's coefficients on (x₀, x₁, x₂, extra) and right-hand side
    /// ([`on_redundants`]).
    dense: Vec<([f64; 4], f64)>,
    /// The cap on the extra variable: cap.0·extra ≤ cap.1.
    cap: (f64, f64),
    /// The objective's coefficients on (x₀, x₁, x₂, extra).
    c: Vec<f64>,
    /// How the interior-point method solves the rounds.
    solve: InteriorPoint<'a>,
}

/// The method that solves the rounds of constraint generation.
struct Rounds {
    /// The simplex method while the rows stay few and it solves; `None` from then on (the
    /// interior-point method).
    simplex: Option<ChainSimplex>,
    /// The rows given to the simplex method so far.
    pushed: Vec<bool>,
}

impl Rounds {
    /// The programme of `lp` on `subset` (and the cap, last): by the simplex method while the
    /// rows stay few, else, or from the round where it fails, by the interior-point method.
    fn solve(&mut self, lp: &ChainLp, subset: &[usize]) -> Programme {
        if subset.len() >= MAX_SIMPLEX_ROWS {
            self.simplex = None;
        }
        let pushed = &mut self.pushed;
        let by_simplex = self.simplex.as_mut().and_then(|simplex| {
            for &i in subset {
                if !std::mem::replace(&mut pushed[i], true) {
                    simplex.add(i, &lp.dense[i]);
                }
            }
            simplex_programme(simplex, subset, lp.dense.len())
        });
        if by_simplex.is_none() {
            self.simplex = None;
        }
        match by_simplex {
            Some(programme) => programme,
            None => clarabel_on(lp, subset),
        }
    }
}

/// The rows the constraint generation starts from: those of about 32 evenly spread interfaces
/// (the last among them) and the crushing cuts.
fn first_rows(rows: &[Row], interfaces: usize) -> Vec<bool> {
    let stride = (interfaces / 32).max(1);
    rows.iter()
        .map(|row| {
            let k = row.tag.interface;
            k % stride == 0 || k + 1 == interfaces || row.cut
        })
        .collect()
}

/// A programme without a solution, ended with `status` after `iterations`.
fn unanswered(status: SolverStatus, iterations: u32) -> Programme {
    Programme {
        status,
        x: Vec::new(),
        z: Vec::new(),
        iterations,
    }
}

/// `programme` (over `subset`, the cap last) with the multipliers of the full programme over
/// `rows` rows and the cap: zero on the rows never added.
fn on_every_row(mut programme: Programme, subset: &[usize], rows: usize) -> Programme {
    let mut z = vec![0.0; rows + 1];
    for (r, &i) in subset.iter().enumerate() {
        z[i] = programme.z[r];
    }
    z[rows] = programme.z[subset.len()];
    programme.z = z;
    programme
}

/// The rows not yet selected that `x` violates by more than `tolerance`, where the violation
/// peaks along the chain (no more than at the same row of either neighbouring interface), as
/// (violation, row).
fn violated_peaks(
    dense: &[([f64; 4], f64)],
    selected: &[bool],
    x: &[f64],
    per_interface: usize,
    tolerance: f64,
) -> Vec<(f64, usize)> {
    let violation = |i: usize| {
        let (a, rhs) = &dense[i];
        a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + a[3] * x[3] - rhs
    };
    (0..dense.len())
        .filter(|&i| !selected[i])
        .filter_map(|i| {
            let v = violation(i);
            let is_peak = [i.checked_sub(per_interface), Some(i + per_interface)]
                .into_iter()
                .flatten()
                .filter(|&j| j < dense.len())
                .all(|j| violation(j) <= v);
            (v > tolerance && is_peak).then_some((v, i))
        })
        .collect()
}

/// The chain programme `lp` on `subset` (and the cap, last) by the interior-point method.
fn clarabel_on(lp: &ChainLp, subset: &[usize]) -> Programme {
    let (dense, cap) = (&lp.dense, lp.cap);
    let m = subset.len() + 1;
    let (mut ti, mut tj, mut tv, mut b) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::with_capacity(m));
    for (r, &i) in subset.iter().enumerate() {
        let (coefficients, rhs) = &dense[i];
        for (j, &v) in coefficients.iter().enumerate() {
            if v != 0.0 {
                ti.push(r);
                tj.push(j);
                tv.push(v);
            }
        }
        b.push(*rhs);
    }
    ti.push(m - 1);
    tj.push(3);
    tv.push(cap.0);
    b.push(cap.1);
    run_clarabel((m, 4, 0), (ti, tj, tv), &b, &lp.c, lp.solve, None)
}

/// Replaces the multipliers of the simplex method's `programme` (over `subset` of `lp`'s rows,
/// the cap last) by the interior-point method's on the rows that hold at its vertex (within
/// 1e-9 of the largest right-hand side); kept as they are when that programme does not solve.
fn central_multipliers(lp: &ChainLp, subset: &[usize], programme: &mut Programme) {
    let (dense, cap) = (&lp.dense, lp.cap);
    let x = &programme.x;
    let scale = subset
        .iter()
        .map(|&i| dense[i].1.abs())
        .fold(cap.1.abs(), f64::max)
        .max(1.0);
    let holding: Vec<usize> = (0..subset.len())
        .filter(|&r| {
            let (a, b) = &dense[subset[r]];
            b - (a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + a[3] * x[3]) <= 1e-9 * scale
        })
        .collect();
    // Four rows or fewer hold: the vertex is not degenerate and its multipliers are the only
    // ones (four variables).
    if holding.len() <= 4 {
        return;
    }
    let rows: Vec<usize> = holding.iter().map(|&r| subset[r]).collect();
    let central = clarabel_on(lp, &rows);
    if central.status != SolverStatus::Solved {
        return;
    }
    let mut z = vec![0.0; subset.len() + 1];
    for (k, &r) in holding.iter().enumerate() {
        z[r] = central.z[k];
    }
    z[subset.len()] = central.z[rows.len()];
    programme.z = z;
    programme.iterations += central.iterations;
}

/// The simplex method's vertex as a programme over `subset` (multipliers in its order, the
/// cap's last); `None` when it failed.
fn simplex_programme(lp: &mut ChainSimplex, subset: &[usize], rows: usize) -> Option<Programme> {
    let vertex = lp.solve().ok()?;
    let mut position = vec![usize::MAX; rows];
    for (r, &i) in subset.iter().enumerate() {
        position[i] = r;
    }
    let mut z = vec![0.0; subset.len() + 1];
    for (j, origin) in lp.origin().iter().enumerate() {
        let at = origin.map_or(subset.len(), |i| position[i]);
        z[at] = vertex.multipliers[j];
    }
    Some(Programme {
        status: SolverStatus::Solved,
        x: vertex.y,
        z,
        iterations: u32::try_from(vertex.pivots).unwrap_or(u32::MAX),
    })
}

/// Each row written on the chain's three redundants and the extra variable: its coefficients
/// and its right-hand side less the dead load's part.
fn on_redundants(
    chain: &ChainStatics,
    rows: &[Row],
    dead_factor: f64,
    extra_coefficient: impl Fn(&[f64; 3], usize) -> f64,
) -> Vec<([f64; 4], f64)> {
    rows.iter()
        .map(|row| {
            let (k, a) = row.local();
            let affine = chain.affine(k);
            let (d, dead) = (affine.map, affine.dead);
            let coefficients = [
                a[0] * d[0][0] + a[1] * d[1][0] + a[2] * d[2][0],
                a[0] * d[0][1] + a[1] * d[1][1] + a[2] * d[2][1],
                a[0] * d[0][2] + a[1] * d[1][2] + a[2] * d[2][2],
                extra_coefficient(&a, k),
            ];
            (coefficients, row.b - dead_factor * dot(&a, &dead))
        })
        .collect()
}

pub(super) fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(super) fn failure(status: SolverStatus) -> Option<SolverFailure> {
    match status {
        SolverStatus::Solved => None,
        SolverStatus::AlmostSolved => Some(SolverFailure::ReducedAccuracy),
        SolverStatus::MaxIterations => Some(SolverFailure::MaxIterations),
        // Clarabel's time limit is the budget's remaining time: past it the budget is spent, and
        // the solution's stop says so (`Context::failed`).
        SolverStatus::MaxTime => Some(SolverFailure::Numerical),
        SolverStatus::PrimalInfeasible
        | SolverStatus::AlmostPrimalInfeasible
        | SolverStatus::DualInfeasible
        | SolverStatus::AlmostDualInfeasible => Some(SolverFailure::Infeasible),
        SolverStatus::Unsolved
        | SolverStatus::NumericalError
        | SolverStatus::InsufficientProgress
        | SolverStatus::CallbackTerminated => Some(SolverFailure::Numerical),
    }
}
