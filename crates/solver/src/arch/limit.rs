//! The limit-analysis linear programmes of a rigid-block assembly (Livesley 1978, §2.3–2.6),
//! solved with Clarabel's interior-point method.
//!
//! # Formulations
//! An interior-point method needs a feasible set with an interior. The textbook dead-load
//! programme — maximise λ₀ with H r + λ₀ w = 0 and the yield limits — does not have one when the
//! structure is too thin (with Heyman's limits its feasible set is then the single point r = 0).
//! So the dead load is measured by a **margin** programme that is always well posed:
//!
//! ```text
//!   margin(λ) = min δ   subject to  H r + λ w = 0,
//!                                    every finite limit relaxed by δ·W  (r⁻ − δW ≤ r ≤ r⁺ + δW,
//!                                    friction rows μ(q+s) ∓ t ≥ −δW),  δ ≥ −1,
//! ```
//!
//! W being the total weight. margin(λ) ≤ 0 exactly when λ·w can be carried; it is convex and
//! piecewise linear in λ with margin(0) ≤ 0 (r = 0 is admissible when every limit admits zero
//! force). Hence λ₀ = 1 when margin(1) ≤ 0; with homogeneous limits (all finite limits zero:
//! Heyman's case, friction) the feasible set is a cone and λ₀ = 0 otherwise; in general λ₀ is the
//! root of margin(λ), found by Newton's method on the convex function (monotone from the right,
//! finite on a piecewise-linear function) with the slope dmargin/dλ = w·y from the multipliers.
//!
//! The live load is the textbook programme, max λ subject to H r + w + λ p = 0 and the limits,
//! solved once the dead load is known to be carried (then r is strictly admissible at λ = 0
//! unless the structure sits exactly at its limit). λ is capped to detect loads that cause no
//! collapse.
//!
//! # Multipliers
//! With Clarabel's convention (min c'x, Ax + s = b, s ∈ K; dual A'z + c = 0) the multipliers y of
//! the equilibrium rows satisfy Hᵀy = z_lower − z_upper: y are the block velocities (u, v, ω)
//! of the collapse mechanism and z the plastic multipliers of the limits, with the loads doing
//! positive work. See [`super::mechanism`].

use std::time::Instant;

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus,
    SupportedConeT, ZeroConeT,
};

use super::chain::ChainStatics;
use super::equilibrium::{
    assemble_equilibrium, force_scale, Equilibrium, LiveLoad, RESULTANTS_PER_INTERFACE,
};
use super::geometry::Assembly;
use super::mechanism::{read_mechanism, Bound, Mechanism, Resultant};
use super::ArchError;

/// Limits on the stress resultants of every interface (absolute forces; `None` = unbounded).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InterfaceLimits {
    /// Lower limit of q (0 = no tension at the extrados end).
    pub q_min: Option<f64>,
    /// Upper limit of q (crushing).
    pub q_max: Option<f64>,
    /// Lower limit of s (0 = no tension at the intrados end).
    pub s_min: Option<f64>,
    /// Upper limit of s (crushing).
    pub s_max: Option<f64>,
    /// Lower limit of the shear t.
    pub t_min: Option<f64>,
    /// Upper limit of the shear t.
    pub t_max: Option<f64>,
}

impl InterfaceLimits {
    /// Heyman's assumptions: no tension, infinite compressive strength, no sliding.
    pub fn heyman() -> Self {
        Self {
            q_min: Some(0.0),
            q_max: None,
            s_min: Some(0.0),
            s_max: None,
            t_min: None,
            t_max: None,
        }
    }

    fn bounds(&self) -> [(Resultant, Bound, Option<f64>); 6] {
        [
            (Resultant::Q, Bound::Lower, self.q_min),
            (Resultant::Q, Bound::Upper, self.q_max),
            (Resultant::S, Bound::Lower, self.s_min),
            (Resultant::S, Bound::Upper, self.s_max),
            (Resultant::T, Bound::Lower, self.t_min),
            (Resultant::T, Bound::Upper, self.t_max),
        ]
    }

    /// Whether every finite limit is zero: the admissible set is then a cone.
    pub fn is_homogeneous(&self) -> bool {
        self.bounds()
            .iter()
            .all(|(_, _, v)| v.unwrap_or(0.0) == 0.0)
    }
}

/// A rigid-block structure with its loads and limits, validated.
#[derive(Debug, Clone, PartialEq)]
pub struct ArchProblem {
    assembly: Assembly,
    unit_weight: f64,
    limits: InterfaceLimits,
    friction: Option<f64>,
    live_loads: Vec<LiveLoad>,
}

impl ArchProblem {
    /// Checks the numbers: unit weight > 0; each limit finite with min ≤ 0 ≤ max (the unloaded
    /// state must be admissible); friction coefficient finite ≥ 0; loads on existing blocks.
    pub fn new(
        assembly: Assembly,
        unit_weight: f64,
        limits: InterfaceLimits,
        friction: Option<f64>,
        live_loads: Vec<LiveLoad>,
    ) -> Result<Self, ArchError> {
        if !(unit_weight.is_finite() && unit_weight > 0.0) {
            return Err(ArchError::range(
                "unit_weight",
                unit_weight,
                "a finite number > 0",
            ));
        }
        let names = ["q_min", "q_max", "s_min", "s_max", "t_min", "t_max"];
        for ((_, bound, value), name) in limits.bounds().iter().zip(names) {
            if let Some(v) = *value {
                let ok = v.is_finite()
                    && match bound {
                        Bound::Lower => v <= 0.0,
                        Bound::Upper => v >= 0.0,
                    };
                if !ok {
                    let allowed = match bound {
                        Bound::Lower => "a finite number ≤ 0 or null (unbounded)",
                        Bound::Upper => "a finite number ≥ 0 or null (unbounded)",
                    };
                    return Err(ArchError::range(
                        format!("interface_limits.{name}"),
                        v,
                        allowed,
                    ));
                }
            }
        }
        if let Some(mu) = friction {
            if !(mu.is_finite() && mu >= 0.0) {
                return Err(ArchError::range(
                    "friction_coefficient",
                    mu,
                    "a finite number ≥ 0 or null (no sliding)",
                ));
            }
        }
        for (i, load) in live_loads.iter().enumerate() {
            if load.block >= assembly.blocks.len() {
                return Err(ArchError::range(
                    format!("loads[{i}].block"),
                    (load.block + 1) as f64,
                    format!("a block number 1 ≤ block ≤ {}", assembly.blocks.len()),
                ));
            }
            let values = [load.point.0, load.point.1, load.fx, load.fy, load.moment];
            if values.iter().any(|v| !v.is_finite()) {
                return Err(ArchError::range(
                    format!("loads[{i}]"),
                    f64::NAN,
                    "finite numbers",
                ));
            }
        }
        Ok(Self {
            assembly,
            unit_weight,
            limits,
            friction,
            live_loads,
        })
    }

    /// The blocks and interfaces.
    pub fn assembly(&self) -> &Assembly {
        &self.assembly
    }

    /// The unit weight γ.
    pub fn unit_weight(&self) -> f64 {
        self.unit_weight
    }

    /// The live loads.
    pub fn live_loads(&self) -> &[LiveLoad] {
        &self.live_loads
    }
}

/// Settings of the interior-point solves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitSettings {
    /// Clarabel's gap and feasibility tolerances (relative). Defaults to 1e-10.
    pub tolerance: f64,
    /// A dead-load margin at or below this (a fraction of the total weight) counts as carried.
    /// Defaults to 1e-9.
    pub margin_tolerance: f64,
    /// Interior-point iterations per programme. Defaults to 200.
    pub max_iterations: u32,
    /// Time limit of one programme in seconds. Defaults to 30.
    pub time_limit_secs: f64,
    /// Which model the programmes are written on. Defaults to [`Formulation::Chain`].
    pub formulation: Formulation,
}

/// The model of the limit-analysis programmes; both give the same answers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Formulation {
    /// Three redundant forces of the chain (four variables; see [`super::chain`]).
    #[default]
    Chain,
    /// Livesley's general assembly: three resultants per interface and the equilibrium rows.
    Assembly,
}

impl Default for LimitSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            margin_tolerance: 1e-9,
            max_iterations: 200,
            time_limit_secs: 30.0,
            formulation: Formulation::Chain,
        }
    }
}

/// How a limit analysis ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LimitStatus {
    /// The load factor was found.
    Solved,
    /// Live load only: the dead load is not carried, so there is no live-load factor.
    DeadLoadNotCarried,
    /// Live load only: no finite multiple of the live load causes collapse.
    Unbounded,
    /// The interior-point method stopped without an answer it can vouch for.
    SolverFailed(SolverFailure),
}

/// Why Clarabel stopped without a solution (its status, named).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SolverFailure {
    /// Reached only reduced accuracy.
    ReducedAccuracy,
    /// Iteration limit.
    MaxIterations,
    /// Time limit.
    MaxTime,
    /// Numerical error or lack of progress.
    Numerical,
    /// Reported the programme infeasible, which the formulations exclude.
    Infeasible,
}

/// What a limit analysis found.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitSolution {
    /// How it ended.
    pub status: LimitStatus,
    /// The dead-load factor λ₀ (dead load) or live-load factor λ (live load), when solved.
    pub load_factor: Option<f64>,
    /// Whether the dead load is carried (λ₀ = 1); `None` if that could not be decided.
    pub dead_load_carried: Option<bool>,
    /// Dead-load margin δ at full dead load, a fraction of the total weight: negative is a
    /// reserve (every limit is met with that much to spare), positive a shortfall.
    pub dead_load_margin: Option<f64>,
    /// Resultants (q, s, t) per interface in force units at the load factor (empty when there
    /// is no admissible state to show).
    pub resultants: Vec<[f64; 3]>,
    /// The collapse mechanism, when the structure is at its limit.
    pub mechanism: Option<Mechanism>,
    /// Interior-point iterations over all programmes.
    pub iterations: u32,
    /// Linear programmes solved.
    pub programmes: usize,
    /// Wall time of the solves in seconds.
    pub solve_time_secs: f64,
}

/// Which side of the bound a row is, and of which resultant, for reading multipliers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct RowTag {
    pub interface: usize,
    pub resultant: Resultant,
    pub bound: Bound,
}

/// An inequality row a·x ≤ b.
struct Row {
    entries: [(usize, f64); 3],
    len: usize,
    b: f64,
    tag: RowTag,
}

impl Row {
    /// The interface of the row and its coefficients on that interface's (q, s, t).
    fn local(&self) -> (usize, [f64; 3]) {
        let k = self.tag.interface;
        let mut a = [0.0; 3];
        for &(j, v) in &self.entries[..self.len] {
            a[j - RESULTANTS_PER_INTERFACE * k] += v;
        }
        (k, a)
    }
}

/// The yield rows of every interface, in scaled units (forces divided by the total weight).
fn limit_rows(problem: &ArchProblem, force_scale: f64) -> Vec<Row> {
    let w = force_scale;
    let mut rows = Vec::new();
    for k in 0..problem.assembly.interfaces.len() {
        let col = RESULTANTS_PER_INTERFACE * k;
        for (resultant, bound, value) in problem.limits.bounds() {
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
                tag: RowTag {
                    interface: k,
                    resultant,
                    bound,
                },
            });
        }
        if let Some(mu) = problem.friction {
            // u = μ(q + s) − t ≥ 0 and v = μ(q + s) + t ≥ 0 (Livesley §2.7), written −u ≤ 0 and
            // −v ≤ 0; only where friction is finite.
            for (resultant, t_sign) in [(Resultant::U, 1.0), (Resultant::V, -1.0)] {
                rows.push(Row {
                    entries: [(col, -mu), (col + 1, -mu), (col + 2, t_sign)],
                    len: 3,
                    b: 0.0,
                    tag: RowTag {
                        interface: k,
                        resultant,
                        bound: Bound::Lower,
                    },
                });
            }
        }
    }
    rows
}

/// Outcome of one programme.
struct Programme {
    status: SolverStatus,
    x: Vec<f64>,
    z: Vec<f64>,
    iterations: u32,
}

/// One programme over the resultants r and one extra variable x (δ or λ):
/// min objective·x subject to H r + extra_equilibrium·x = b_eq, the limit rows (each with
/// `row_extra`·x added), and cap.0·x ≤ cap.1.
struct ProgrammeSpec<'a> {
    extra_equilibrium: &'a [f64],
    b_eq: &'a [f64],
    row_extra: Option<f64>,
    cap: (f64, f64),
    objective: f64,
}

fn solve_programme(
    eq: &Equilibrium,
    rows: &[Row],
    spec: &ProgrammeSpec,
    settings: &LimitSettings,
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
    let mut ti = Vec::with_capacity(eq.triplets.len() + m_eq + 3 * rows.len() + 1);
    let mut tj = Vec::with_capacity(ti.capacity());
    let mut tv = Vec::with_capacity(ti.capacity());
    for &(i, j, v) in &eq.triplets {
        ti.push(i);
        tj.push(j);
        tv.push(v);
    }
    for (i, &v) in extra_equilibrium.iter().enumerate() {
        if v != 0.0 {
            ti.push(i);
            tj.push(extra);
            tv.push(v);
        }
    }
    let mut b = b_eq.to_vec();
    for (r, row) in rows.iter().enumerate() {
        for &(j, v) in &row.entries[..row.len] {
            ti.push(m_eq + r);
            tj.push(j);
            tv.push(v);
        }
        if let Some(coefficient) = row_extra {
            ti.push(m_eq + r);
            tj.push(extra);
            tv.push(coefficient);
        }
        b.push(row.b);
    }
    // Cap on the extra variable: cap.0·x_extra ≤ cap.1.
    ti.push(m - 1);
    tj.push(extra);
    tv.push(cap.0);
    b.push(cap.1);
    let mut c = vec![0.0; n];
    c[extra] = objective_extra;
    run_clarabel((m, n, m_eq), (ti, tj, tv), &b, &c, settings)
}

/// Solves min c'x subject to A x + s = b with s in {0}^m_eq × R₊^(m − m_eq).
fn run_clarabel(
    (m, n, m_eq): (usize, usize, usize),
    (ti, tj, tv): (Vec<usize>, Vec<usize>, Vec<f64>),
    b: &[f64],
    c: &[f64],
    settings: &LimitSettings,
) -> Programme {
    let a = CscMatrix::new_from_triplets(m, n, ti, tj, tv);
    let p = CscMatrix::zeros((n, n));
    let cones: [SupportedConeT<f64>; 2] = [ZeroConeT(m_eq), NonnegativeConeT(m - m_eq)];
    let tol = settings.tolerance;
    let clarabel_settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .max_iter(settings.max_iterations)
        .time_limit(settings.time_limit_secs)
        .tol_gap_abs(tol)
        .tol_gap_rel(tol)
        .tol_feas(tol)
        .tol_ktratio(tol.sqrt() * 1e-2)
        .build()
        .expect("the settings are within Clarabel's ranges");
    let mut solver = match DefaultSolver::new(&p, c, &a, b, &cones, clarabel_settings) {
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
    solver.solve();
    let solution = solver.solution;
    Programme {
        status: solution.status,
        x: solution.x,
        z: solution.z,
        iterations: solution.iterations,
    }
}

/// A programme of the chain formulation over (x₀, x₁, x₂, extra): each limit row a·r_k ≤ b
/// becomes (D_kᵀa)·x + extra_coefficient(a, k)·extra ≤ b − dead_factor·a·(D_k C_k), plus the
/// cap cap.0·extra ≤ cap.1; minimise objective·extra.
///
/// Only a few rows are active at the optimum (the hinges), so the programme is solved by
/// constraint generation: start from the rows of about 32 evenly spread interfaces, solve,
/// add the violated rows that are local maxima of the violation along the chain, repeat until
/// no row is violated by more than the solver tolerance. The multipliers of rows never added
/// are zero, exactly as at the optimum of the full programme.
fn solve_chain_programme(
    chain: &ChainStatics,
    rows: &[Row],
    dead_factor: f64,
    extra_coefficient: impl Fn(&[f64; 3], usize) -> f64,
    (cap, objective): ((f64, f64), f64),
    settings: &LimitSettings,
) -> Programme {
    const MAX_ROUNDS: usize = 40;
    const MAX_ADDED_PER_ROUND: usize = 256;
    let dense: Vec<([f64; 4], f64)> = rows
        .iter()
        .map(|row| {
            let (k, a) = row.local();
            let (d, dead, _) = chain.affine(k);
            let coefficients = [
                a[0] * d[0][0] + a[1] * d[1][0] + a[2] * d[2][0],
                a[0] * d[0][1] + a[1] * d[1][1] + a[2] * d[2][1],
                a[0] * d[0][2] + a[1] * d[1][2] + a[2] * d[2][2],
                extra_coefficient(&a, k),
            ];
            (coefficients, row.b - dead_factor * dot(&a, &dead))
        })
        .collect();
    let interfaces = chain.interfaces();
    let per_interface = rows.len() / interfaces.max(1);
    let stride = (interfaces / 32).max(1);
    let mut selected: Vec<bool> = rows
        .iter()
        .map(|row| row.tag.interface % stride == 0 || row.tag.interface + 1 == interfaces)
        .collect();
    let mut c = vec![0.0; 4];
    c[3] = objective;
    let mut iterations = 0;
    for _ in 0..MAX_ROUNDS {
        let subset: Vec<usize> = (0..rows.len()).filter(|&i| selected[i]).collect();
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
        let mut programme = run_clarabel((m, 4, 0), (ti, tj, tv), &b, &c, settings);
        iterations += programme.iterations;
        programme.iterations = iterations;
        if failure(programme.status).is_some() {
            return programme;
        }
        let x = &programme.x;
        let violation = |i: usize| {
            let (a, rhs) = &dense[i];
            a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + a[3] * x[3] - rhs
        };
        let tolerance = settings.tolerance;
        let mut added: Vec<(f64, usize)> = (0..rows.len())
            .filter(|&i| !selected[i])
            .filter_map(|i| {
                let v = violation(i);
                let is_peak = [i.checked_sub(per_interface), Some(i + per_interface)]
                    .into_iter()
                    .flatten()
                    .filter(|&j| j < rows.len())
                    .all(|j| violation(j) <= v);
                (v > tolerance && is_peak).then_some((v, i))
            })
            .collect();
        if added.is_empty() {
            // Multipliers of the full programme: zero on the rows never added.
            let mut z = vec![0.0; rows.len() + 1];
            for (r, &i) in subset.iter().enumerate() {
                z[i] = programme.z[r];
            }
            z[rows.len()] = programme.z[subset.len()];
            programme.z = z;
            return programme;
        }
        added.sort_by(|a, b| b.0.total_cmp(&a.0));
        for &(_, i) in added.iter().take(MAX_ADDED_PER_ROUND) {
            selected[i] = true;
        }
    }
    Programme {
        status: SolverStatus::MaxIterations,
        x: Vec::new(),
        z: Vec::new(),
        iterations,
    }
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Live loads are scaled to a unit largest component; λ above this counts as no collapse.
const LIVE_LOAD_CAP: f64 = 1e6;

fn failure(status: SolverStatus) -> Option<SolverFailure> {
    match status {
        SolverStatus::Solved => None,
        SolverStatus::AlmostSolved => Some(SolverFailure::ReducedAccuracy),
        SolverStatus::MaxIterations => Some(SolverFailure::MaxIterations),
        SolverStatus::MaxTime => Some(SolverFailure::MaxTime),
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

/// The answer of a solve, before the solve statistics are added.
struct Found {
    status: LimitStatus,
    load_factor: Option<f64>,
    dead_load_carried: Option<bool>,
    dead_load_margin: Option<f64>,
    resultants: Vec<[f64; 3]>,
    mechanism: Option<Mechanism>,
}

/// margin(λ) with its state and multipliers.
struct MarginEvaluation {
    lambda: f64,
    value: f64,
    programme: Programme,
}

/// The model the programmes are written on.
enum Model {
    /// Livesley's general assembly: all resultants and H r + λ₀w + λp = 0.
    Assembly(Equilibrium),
    /// The chain: three redundants, resultants affine in them.
    Chain(ChainStatics),
}

struct Context<'a> {
    problem: &'a ArchProblem,
    model: Model,
    rows: Vec<Row>,
    force_scale: f64,
    settings: &'a LimitSettings,
    iterations: u32,
    programmes: usize,
}

impl<'a> Context<'a> {
    fn new(problem: &'a ArchProblem, settings: &'a LimitSettings) -> Self {
        let (a, gamma, loads) = (&problem.assembly, problem.unit_weight, &problem.live_loads);
        let force_scale = force_scale(a, gamma);
        let model = match settings.formulation {
            Formulation::Chain => Model::Chain(ChainStatics::new(a, gamma, loads)),
            Formulation::Assembly => Model::Assembly(assemble_equilibrium(a, gamma, loads)),
        };
        let rows = limit_rows(problem, force_scale);
        Self {
            problem,
            model,
            rows,
            force_scale,
            settings,
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
    fn extra(&self) -> usize {
        match &self.model {
            Model::Assembly(eq) => eq.columns,
            Model::Chain(_) => 3,
        }
    }

    fn margin(&mut self, lambda: f64) -> Result<MarginEvaluation, SolverFailure> {
        let programme = match &self.model {
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
                solve_programme(eq, &self.rows, &spec, self.settings)
            }
            Model::Chain(chain) => solve_chain_programme(
                chain,
                &self.rows,
                lambda,
                |_, _| -1.0,
                ((-1.0, 1.0), 1.0),
                self.settings,
            ),
        };
        let programme = self.count(programme)?;
        let value = programme.x[self.extra()];
        Ok(MarginEvaluation {
            lambda,
            value,
            programme,
        })
    }

    /// The live-load programme: λ̂ = λ·scale with the live loads scaled to a unit largest
    /// component; returns the programme and the scale.
    fn live(&mut self) -> Result<(Programme, f64), SolverFailure> {
        let (programme, scale) = match &self.model {
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
                (solve_programme(eq, &self.rows, &spec, self.settings), scale)
            }
            Model::Chain(chain) => {
                let scale = chain.live_scale;
                let coefficient = |a: &[f64; 3], k: usize| dot(a, &chain.affine(k).2) / scale;
                let programme = solve_chain_programme(
                    chain,
                    &self.rows,
                    1.0,
                    coefficient,
                    ((1.0, LIVE_LOAD_CAP), -1.0),
                    self.settings,
                );
                (programme, scale)
            }
        };
        Ok((self.count(programme)?, scale))
    }

    /// Whether any live load is non-zero.
    fn has_live_load(&self) -> bool {
        match &self.model {
            Model::Assembly(eq) => eq.live.iter().any(|v| *v != 0.0),
            Model::Chain(chain) => chain.live_scale > 0.0,
        }
    }

    /// Slope dmargin/dλ at the multipliers of `evaluation`: minus the λ-derivative of the
    /// right-hand side, dotted with the multipliers (LP sensitivity).
    fn slope(&self, evaluation: &MarginEvaluation) -> f64 {
        let z = &evaluation.programme.z;
        match &self.model {
            Model::Assembly(eq) => eq.dead.iter().zip(z).map(|(w, y)| w * y).sum(),
            Model::Chain(chain) => self
                .rows
                .iter()
                .zip(z)
                .map(|(row, z)| {
                    let (k, a) = row.local();
                    z * dot(&a, &chain.affine(k).1)
                })
                .sum(),
        }
    }

    /// Resultants in force units from a programme's x at the given factors.
    fn resultants(&self, x: &[f64], dead_factor: f64, live_factor: f64) -> Vec<[f64; 3]> {
        let w = self.force_scale;
        match &self.model {
            Model::Assembly(eq) => x[..eq.columns]
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

    fn mechanism(&self, programme: &Programme) -> Option<Mechanism> {
        let tags: Vec<RowTag> = self.rows.iter().map(|r| r.tag).collect();
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

    fn finish(&self, found: Found, start: Instant) -> LimitSolution {
        let Found {
            status,
            load_factor,
            dead_load_carried,
            dead_load_margin,
            resultants,
            mechanism,
        } = found;
        LimitSolution {
            status,
            load_factor,
            dead_load_carried,
            dead_load_margin,
            resultants,
            mechanism,
            iterations: self.iterations,
            programmes: self.programmes,
            solve_time_secs: start.elapsed().as_secs_f64(),
        }
    }

    fn failed(&self, failure: SolverFailure, start: Instant) -> LimitSolution {
        self.finish(
            Found {
                status: LimitStatus::SolverFailed(failure),
                load_factor: None,
                dead_load_carried: None,
                dead_load_margin: None,
                resultants: Vec::new(),
                mechanism: None,
            },
            start,
        )
    }
}

/// The dead-load margin δ at full dead load (a fraction of the total weight; ≤ 0 when the weight
/// is carried), the collapse mechanism when δ > 0 and the interior-point iterations spent.
pub(crate) fn full_dead_load_margin(
    problem: &ArchProblem,
    settings: &LimitSettings,
) -> Result<(f64, Option<Mechanism>, u32), SolverFailure> {
    let mut cx = Context::new(problem, settings);
    let full = cx.margin(1.0)?;
    let mechanism = if full.value > settings.margin_tolerance {
        cx.mechanism(&full.programme)
    } else {
        None
    };
    Ok((full.value, mechanism, cx.iterations))
}

/// The dead-load factor λ₀ ≤ 1 (Livesley's dead-load problem) and, when the dead load is not
/// carried, the mechanism in which the structure collapses under it.
pub fn solve_dead_load(problem: &ArchProblem, settings: &LimitSettings) -> LimitSolution {
    let start = Instant::now();
    let mut cx = Context::new(problem, settings);
    let full = match cx.margin(1.0) {
        Ok(e) => e,
        Err(f) => return cx.failed(f, start),
    };
    let tol = settings.margin_tolerance;
    if full.value <= tol {
        let resultants = cx.resultants(&full.programme.x, 1.0, 0.0);
        return cx.finish(
            Found {
                status: LimitStatus::Solved,
                load_factor: Some(1.0),
                dead_load_carried: Some(true),
                dead_load_margin: Some(full.value),
                resultants,
                mechanism: None,
            },
            start,
        );
    }
    if problem.limits.is_homogeneous() {
        // A cone: if λ·w cannot be carried for λ = 1, it cannot for any λ > 0.
        let mechanism = cx.mechanism(&full.programme);
        return cx.finish(
            Found {
                status: LimitStatus::Solved,
                load_factor: Some(0.0),
                dead_load_carried: Some(false),
                dead_load_margin: Some(full.value),
                resultants: Vec::new(),
                mechanism,
            },
            start,
        );
    }
    // Newton from the right on the convex margin(λ), safeguarded by bisection on [lo, hi].
    let full_margin = full.value;
    let (mut lo, mut hi) = (0.0, full);
    let mut carried: Option<MarginEvaluation> = None;
    for _ in 0..60 {
        let slope = cx.slope(&hi);
        let newton = hi.lambda - hi.value / slope;
        let lambda = if slope > 0.0 && newton.is_finite() && newton > lo && newton < hi.lambda {
            newton
        } else {
            0.5 * (lo + hi.lambda)
        };
        let e = match cx.margin(lambda) {
            Ok(e) => e,
            Err(f) => return cx.failed(f, start),
        };
        if e.value <= tol {
            lo = lambda;
            let done = e.value >= -tol || hi.lambda - lo <= 1e-12;
            carried = Some(e);
            if done {
                break;
            }
        } else {
            hi = e;
        }
        if hi.lambda - lo <= 1e-12 {
            break;
        }
    }
    let resultants = carried
        .map(|e| cx.resultants(&e.programme.x, e.lambda, 0.0))
        .unwrap_or_default();
    let mechanism = cx.mechanism(&hi.programme);
    cx.finish(
        Found {
            status: LimitStatus::Solved,
            load_factor: Some(lo),
            dead_load_carried: Some(false),
            dead_load_margin: Some(full_margin),
            resultants,
            mechanism,
        },
        start,
    )
}

/// The live-load factor λ (Livesley's live-load problem), given that the dead load is carried.
pub fn solve_live_load(
    problem: &ArchProblem,
    settings: &LimitSettings,
) -> Result<LimitSolution, ArchError> {
    let start = Instant::now();
    let mut cx = Context::new(problem, settings);
    if !cx.has_live_load() {
        return Err(ArchError::range(
            "loads",
            0.0,
            "at least one load with a non-zero force or moment",
        ));
    }
    let full = match cx.margin(1.0) {
        Ok(e) => e,
        Err(f) => return Ok(cx.failed(f, start)),
    };
    if full.value > settings.margin_tolerance {
        let mechanism = cx.mechanism(&full.programme);
        return Ok(cx.finish(
            Found {
                status: LimitStatus::DeadLoadNotCarried,
                load_factor: None,
                dead_load_carried: Some(false),
                dead_load_margin: Some(full.value),
                resultants: Vec::new(),
                mechanism,
            },
            start,
        ));
    }
    let (programme, scale) = match cx.live() {
        Ok(p) => p,
        Err(f) => return Ok(cx.failed(f, start)),
    };
    let lambda_scaled = programme.x[cx.extra()];
    if lambda_scaled >= LIVE_LOAD_CAP * (1.0 - 1e-6) {
        return Ok(cx.finish(
            Found {
                status: LimitStatus::Unbounded,
                load_factor: None,
                dead_load_carried: Some(true),
                dead_load_margin: Some(full.value),
                resultants: Vec::new(),
                mechanism: None,
            },
            start,
        ));
    }
    let resultants = cx.resultants(&programme.x, 1.0, lambda_scaled / scale);
    let mechanism = cx.mechanism(&programme);
    Ok(cx.finish(
        Found {
            status: LimitStatus::Solved,
            load_factor: Some(lambda_scaled / scale),
            dead_load_carried: Some(true),
            dead_load_margin: Some(full.value),
            resultants,
            mechanism,
        },
        start,
    ))
}
