//! Friction as it acts (model §5.5): Coulomb sliding without dilatancy, by the iterative linear
//! programmes of Gilbert, Casapulla & Ahmed (2006). The associative programme makes a sliding
//! joint open as it slides (normality on μ(q + s) ∓ t ≥ 0), which real joints do not; the
//! load factor may then over-estimate (Livesley 1978, §2.7–2.9).
//!
//! The paper's iteration: start from the normal forces N⁰ of the associative solution; at step
//! k solve the programme with each friction row replaced by the modified surface
//! |t| ≤ c + α·μ·N, whose intercept c = (1 − α)·μ·Ñ makes it pass through Coulomb's line at the
//! normal force Ñ the previous steps left (the shear is limited almost independently of the
//! normal force: its flow is sliding with a dilatancy of α·μ, nearly the corrected mechanism
//! of Livesley §2.7), with the paper's α = [`SLOPE`] (Ñ = N⁰ for the first step). Ñ for the
//! next step is the paper's relaxation between the last two steps' normal forces,
//! Ñ = N^(k−2) + β·(N^(k−1) − N^(k−2)), β = [`RELAXATION`].
//!
//! Where that stops without settling (its [`MAX_STEPS`], [`STALLED_STEPS`] without halving the
//! inconsistency, or a step that does not solve), the Anderson mixing ([`super::mixing`]) of
//! the last [`MEMORY`] steps' (Ñ, N), with the same β, takes over from its last state that
//! solved, for up to as many steps again: once a step's active set stops changing, the map
//! Ñ ↦ N is affine and the mixing lands on its fixed point instead of circling it. It forgets
//! its memory every [`RESTART`] steps that do not halve the inconsistency (a fit across active
//! sets misleads); a mixed step that does not solve is retried once by plain relaxation from
//! the last step that solved. [`Relaxation::Anderson`] runs the mixing from the first step;
//! by default it is the rescue, so that every answer the paper's procedure gives is the paper's.
//!
//! Settled when the solution's own normal forces carry its shear (|t| ≤ μ·N at every joint, to
//! 1e-7 of the total weight) and, at every joint at its capacity, equal the Ñ it was built from
//! (to 1e-7 W; the surface is Coulomb's there): that state is admissible for the associative
//! programme too, so its λ is no more than the associative one. Not settled after both phases:
//! the answer says so, with one exception: where no step's λ left the associative one (a
//! programme so degenerate that the interior-point method does not pin its normal forces down,
//! as a wall panel sliding on its bed joints at λ = μ), the associative state is itself a fixed
//! point — it carries its shear by its own normal forces and is optimal for the first step's
//! programme, whose λ is the same (to [`SAME_FACTOR`]) — and it answers with that step's
//! mechanism.
//!
//! A fixed point is a collapse state under friction that does not dilate, not necessarily the
//! lowest one: non-associative collapse loads are not unique (the normal forces of a joint that
//! slides are statically indeterminate).
//!
//! A live-load step is the live-load programme alone: the dead load was checked once, by the
//! associative solve, and a step's capacities are those of a collapse state. A state that
//! settles below zero live load says the dead load is not carried without dilatancy. Where the
//! associative programme finds no collapse up to its cap on λ, the iteration starts from the
//! state at the cap and its steps are solved to the cap too; a step at the cap whose normal
//! forces carry its shear (to 1e-7 of its largest normal force) settles it: no collapse without
//! dilatancy either.
//!
//! What the iteration settles, and where it does not (walls, panels, arches; two-ring arches
//! with ring friction), is measured in docs/accuracy.md ("Friction without dilatancy").

use super::mixing::{relaxed, Mixing};
use super::problem::{ArchProblem, LimitSettings, LimitSolution, LimitStatus, Relaxation};
use crate::arch::equilibrium::force_scale;
use crate::arch::mechanism::Mechanism;

/// Steps at most.
pub const MAX_STEPS: usize = 50;

/// Steps without halving the smallest inconsistency so far after which the iteration stops
/// (it wanders: the two-ring arches; or, λ never leaving the associative one, the normal forces
/// of a degenerate programme only jitter). Converging walls halve it every 2–4 steps.
pub const STALLED_STEPS: usize = 10;

/// Consistency tolerance as a fraction of the total weight.
const SETTLED: f64 = 1e-7;

/// Relative difference within which a step's λ counts as the associative one.
pub const SAME_FACTOR: f64 = 1e-8;

/// The paper's α: the modified surface keeps this fraction of the friction coefficient as its
/// slope.
pub const SLOPE: f64 = 0.01;

/// The paper's β: the weight of the last step's normal forces against the step's before; the
/// mixing's relaxation too.
pub const RELAXATION: f64 = 0.6;

/// Steps the Anderson mixing of Ñ remembers.
pub const MEMORY: usize = 3;

/// Steps without halving the inconsistency after which the mixing forgets its memory (a fit
/// over steps from another active set misleads; each third such step starts afresh).
pub const RESTART: usize = 3;

/// How the next step's Ñ is formed.
enum Next {
    /// The paper's relaxation between the last two steps' normal forces: the one before.
    Paper { previous: Vec<f64> },
    /// The Anderson mixing of the last steps (the rescue, or from the first step on request).
    Mixing(Mixing),
}

/// The outcome of the iteration.
#[derive(Debug, Clone, PartialEq)]
pub struct NonAssociative {
    /// The last step's solution (the answer when `settled`); its solver figures are that
    /// step's own, the whole iteration's are in `totals`.
    pub solution: LimitSolution,
    /// The associative solution the iteration started from.
    pub associative: LimitSolution,
    /// λ at each step (the first is the associative programme's).
    pub history: Vec<Option<f64>>,
    /// Whether it reached a state whose normal forces carry its shear.
    pub settled: bool,
    /// The corrected mechanism (Livesley §2.7): the first step's, where sliding joints open by
    /// only α·μ times their slip; `None` when nothing slid or there was no step.
    pub corrected: Option<Mechanism>,
    /// Interior-point iterations, programmes and wall time of the whole iteration (the
    /// associative solve included).
    pub totals: (u32, usize, f64),
    /// The steps of the paper's relaxation after which the Anderson mixing took over (it had
    /// stopped without settling; 0 with [`Relaxation::Anderson`]); `None` when it did not.
    pub mixed_from: Option<usize>,
}

fn normal_forces(solution: &LimitSolution) -> Vec<f64> {
    solution.resultants.iter().map(|r| r[0] + r[1]).collect()
}

/// The largest violation of Coulomb's |t| ≤ μN over the joints with friction, and the largest
/// change of normal force from `used` over the joints whose shear is at its capacity
/// (1 − α)μ·used + αμN (where the normal force matters; elsewhere the programme leaves it
/// free), both absolute.
fn inconsistency(
    problem: &ArchProblem,
    solution: &LimitSolution,
    used: &[f64],
    tolerance: f64,
) -> (f64, f64) {
    let mut shear: f64 = 0.0;
    let mut moved: f64 = 0.0;
    for (k, r) in solution.resultants.iter().enumerate() {
        let Some(mu) = problem.material(k).1 else {
            continue;
        };
        let n = r[0] + r[1];
        let before = used.get(k).copied().unwrap_or(0.0).max(0.0);
        let cohesive = problem.cohesive_capacity(k);
        shear = shear.max(r[2].abs() - mu * n.max(0.0) - cohesive);
        let capacity = (1.0 - SLOPE) * mu * before + SLOPE * mu * n.max(0.0) + cohesive;
        if r[2].abs() >= capacity - tolerance {
            moved = moved.max((n - before).abs());
        }
    }
    (shear, moved)
}

/// Runs the iteration on `problem`: `solve` (the dead- or live-load solve) for the associative
/// start, `step` for each step's programme (given the associative solution: a live-load step
/// need not check the dead load again). With `only_if_sliding`, an associative mechanism that
/// does not slide is answered as it is (settled: without sliding, dilatancy plays no part).
pub fn iterate<E>(
    problem: &ArchProblem,
    settings: &LimitSettings,
    only_if_sliding: bool,
    solve: impl Fn(&ArchProblem, &LimitSettings) -> Result<LimitSolution, E>,
    step: impl Fn(&ArchProblem, &LimitSettings, &LimitSolution) -> Result<LimitSolution, E>,
) -> Result<NonAssociative, E> {
    let start = std::time::Instant::now();
    let associative = solve(problem, settings)?;
    let sliding = associative
        .mechanism
        .as_ref()
        .is_some_and(|m| m.involves_friction());
    if let Some(answer) = unchanged(problem, &associative, only_if_sliding, sliding) {
        return Ok(answer);
    }
    // The programmes' own force scale W: the blocks' and the other dead loads' weight.
    let weight = force_scale(
        problem.assembly(),
        problem.unit_weight(),
        problem.dead_loads(),
    );
    let mut run = Run::new(&associative, settings.relaxation);
    let mut out_of_budget = false;
    let settled = loop {
        if let Err(stop) = settings.budget.check() {
            // The request's budget ended it: no answer the iteration can vouch for.
            run.last.stop = stop;
            run.last.load_factor = None;
            out_of_budget = true;
            break false;
        }
        // The paper's relaxation has had its steps without settling: the mixing takes over
        // from its last state that solved, once, with steps of its own.
        if run.is_stopped() && !run.take_over() {
            break false;
        }
        run.steps += 1;
        let solved = step(
            &problem.with_fixed_friction(&run.used, SLOPE),
            settings,
            &associative,
        )?;
        match run.record(problem, solved, weight) {
            After::Settled => break true,
            After::Continue => {}
            After::Stop => break false,
        }
    };
    let totals = (
        run.iterations,
        run.programmes,
        start.elapsed().as_secs_f64(),
    );
    let corrected = corrected(sliding, &run.first_mechanism);
    if !settled && !out_of_budget && never_left(&run.history) {
        // The associative state is a fixed point (module docs): it answers.
        let mut solution = associative.clone();
        solution.mechanism = run.first_mechanism;
        return Ok(NonAssociative {
            solution,
            associative,
            history: run.history,
            settled: true,
            corrected,
            totals,
            mixed_from: run.mixed_from,
        });
    }
    Ok(NonAssociative {
        solution: run.last,
        associative,
        history: run.history,
        settled,
        corrected,
        totals,
        mixed_from: run.mixed_from,
    })
}

/// The associative answer as it stands, when there is nothing to iterate: with
/// `only_if_sliding`, a mechanism that does not slide; no friction; or no state to start from
/// (where that answer is a collapse under less than the load — a dead load not carried —
/// friction that does not dilate can only do worse: that answer is settled too).
fn unchanged(
    problem: &ArchProblem,
    associative: &LimitSolution,
    only_if_sliding: bool,
    sliding: bool,
) -> Option<NonAssociative> {
    let single = (
        associative.iterations,
        associative.programmes,
        associative.solve_time_secs,
    );
    let answer = |settled| NonAssociative {
        solution: associative.clone(),
        associative: associative.clone(),
        history: vec![associative.load_factor],
        settled,
        corrected: None,
        totals: single,
        mixed_from: None,
    };
    if only_if_sliding && !sliding && associative.status == LimitStatus::Solved {
        return Some(answer(true));
    }
    // No collapse up to the cap: friction that does not dilate may still collapse it; the
    // iteration starts from the state at the cap (not for the check, which follows a sliding
    // mechanism, and there is none).
    let open = associative.status == LimitStatus::Unbounded && !only_if_sliding;
    if !problem.has_friction()
        || !(associative.status == LimitStatus::Solved || open)
        || associative.resultants.is_empty()
    {
        let settled = !problem.has_friction()
            || matches!(
                associative.status,
                LimitStatus::Solved | LimitStatus::DeadLoadNotCarried
            );
        return Some(answer(settled));
    }
    None
}

/// What a recorded step leaves the iteration to do.
enum After {
    /// The step's state is consistent: it answers.
    Settled,
    /// Another step.
    Continue,
    /// No step can follow (a mixed step failed with no solved state to fall back on).
    Stop,
}

/// The iteration's state between steps.
struct Run {
    /// The Ñ the next step is built from.
    used: Vec<f64>,
    /// How the Ñ after it is formed.
    next: Next,
    /// The step after which the mixing took over.
    mixed_from: Option<usize>,
    /// The last step that solved: the Ñ it was built from and its normal forces.
    good: Option<(Vec<f64>, Vec<f64>)>,
    /// The first step's mechanism (the corrected one).
    first_mechanism: Option<Mechanism>,
    /// The last step's solution.
    last: LimitSolution,
    /// Interior-point iterations and programmes so far.
    iterations: u32,
    programmes: usize,
    /// The smallest inconsistency so far in this phase, the steps since it last halved, and
    /// the phase's steps.
    best: f64,
    stalled: usize,
    steps: usize,
    /// λ at each step, the associative first.
    history: Vec<Option<f64>>,
}

impl Run {
    fn new(associative: &LimitSolution, relaxation: Relaxation) -> Self {
        let used = normal_forces(associative);
        let (next, mixed_from) = match relaxation {
            Relaxation::Paper => (
                Next::Paper {
                    previous: used.clone(),
                },
                None,
            ),
            Relaxation::Anderson => (Next::Mixing(Mixing::default()), Some(0)),
        };
        Self {
            used,
            next,
            mixed_from,
            good: None,
            first_mechanism: None,
            last: associative.clone(),
            iterations: associative.iterations,
            programmes: associative.programmes,
            best: f64::INFINITY,
            stalled: 0,
            steps: 0,
            history: vec![associative.load_factor],
        }
    }

    /// Whether this phase has had its steps, or stalled.
    fn is_stopped(&self) -> bool {
        self.steps >= MAX_STEPS || self.stalled >= STALLED_STEPS
    }

    /// The mixing takes over from the paper's relaxation, from its last state that solved;
    /// false when it cannot (the mixing stopped already, nothing solved, or no step left the
    /// associative λ).
    fn take_over(&mut self) -> bool {
        let Next::Paper { .. } = self.next else {
            return false;
        };
        let Some((x, n)) = self.good.take() else {
            return false;
        };
        if never_left(&self.history) {
            return false;
        }
        let mut mixing = Mixing::default();
        self.used = mixing.next(x, n, MEMORY, RELAXATION);
        self.next = Next::Mixing(mixing);
        self.mixed_from = Some(self.history.len() - 1);
        (self.best, self.stalled, self.steps) = (f64::INFINITY, 0, 0);
        true
    }

    /// Records a step's solution and forms the next Ñ.
    fn record(&mut self, problem: &ArchProblem, step: LimitSolution, weight: f64) -> After {
        self.iterations += step.iterations;
        self.programmes += step.programmes;
        self.history.push(step.load_factor);
        if self.history.len() == 2 {
            self.first_mechanism.clone_from(&step.mechanism);
        }
        let open = step.status == LimitStatus::Unbounded;
        if !(step.status == LimitStatus::Solved || open) || step.resultants.is_empty() {
            self.last = step;
            return self.failed_step();
        }
        let normal = normal_forces(&step);
        // A state at the cap carries forces far beyond the weight: its consistency is
        // measured against its own largest normal force.
        let tolerance = if open {
            SETTLED * normal.iter().copied().fold(weight, f64::max)
        } else {
            SETTLED * weight
        };
        let (shear, moved) = inconsistency(problem, &step, &self.used, tolerance);
        self.last = step;
        let worst = shear.max(moved);
        if worst <= tolerance {
            return After::Settled;
        }
        if worst <= 0.5 * self.best {
            (self.best, self.stalled) = (worst, 0);
        } else {
            self.stalled += 1;
        }
        self.good = Some((self.used.clone(), normal.clone()));
        let used = std::mem::take(&mut self.used);
        self.used = match &mut self.next {
            // The paper's: between the last two steps' normal forces.
            Next::Paper { previous } => {
                let relaxed = previous
                    .iter()
                    .zip(&normal)
                    .map(|(p, n)| p + RELAXATION * (n - p))
                    .collect();
                *previous = normal;
                relaxed
            }
            Next::Mixing(mixing) => {
                if self.stalled > 0 && self.stalled.is_multiple_of(RESTART) {
                    mixing.forget();
                }
                mixing.next(used, normal, MEMORY, RELAXATION)
            }
        };
        After::Continue
    }

    /// A step that did not solve: the paper's relaxation ends here (the mixing may take over);
    /// a mixed Ñ whose programme the solver cannot solve (reduced accuracy on a degenerate
    /// programme) is, once, forgotten for a plain relaxation from the last step that solved.
    fn failed_step(&mut self) -> After {
        match &mut self.next {
            Next::Paper { .. } => self.stalled = STALLED_STEPS,
            Next::Mixing(mixing) => {
                let Some((x, n)) = self.good.take() else {
                    return After::Stop;
                };
                mixing.forget();
                self.used = relaxed(&x, &n, RELAXATION);
                self.stalled += 1;
            }
        }
        After::Continue
    }
}

/// The corrected mechanism: the first step's, when the associative mechanism slid.
fn corrected(sliding: bool, first_mechanism: &Option<Mechanism>) -> Option<Mechanism> {
    first_mechanism.clone().filter(|_| sliding)
}

/// Whether every step solved, with the associative λ (the first entry) to [`SAME_FACTOR`].
fn never_left(history: &[Option<f64>]) -> bool {
    let Some(Some(a)) = history.first().copied() else {
        return false;
    };
    history.len() > 1
        && history[1..].iter().all(|l| {
            l.is_some_and(|l| (l - a).abs() <= SAME_FACTOR * a.abs().max(f64::MIN_POSITIVE))
        })
}

impl NonAssociative {
    /// Whether the associative answer over-estimates: its mechanism slides, and the iteration
    /// either found a lower λ (by more than 1e-6 relative) or did not settle.
    pub fn associative_may_overestimate(&self) -> bool {
        let slides = self
            .associative
            .mechanism
            .as_ref()
            .is_some_and(|m| m.involves_friction());
        let lower = match (self.associative.load_factor, self.solution.load_factor) {
            (Some(a), Some(b)) => b < a - 1e-6 * a.abs().max(1e-12),
            // Carried associatively, not without dilatancy.
            (Some(_), None) => self.solution.status == LimitStatus::DeadLoadNotCarried,
            _ => false,
        };
        slides && (!self.settled || lower)
    }
}
