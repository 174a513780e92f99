//! The answer's own accuracy (model §6.2): an estimate of |F(n) − F(∞)|/F for the surface
//! answered, from F at three slice counts a doubling apart.
//!
//! With the differences d₁ = F(n) − F(2n) and d₂ = F(2n) − F(4n), and r = d₁/d₂ the observed
//! ratio: when the sequence converges monotonically (d₁, d₂ of one sign, |d₂| < |d₁|) the
//! remaining error of F(n) is the geometric tail d₁·(1 + 1/r + 1/r² + …) = d₁·r/(r − 1), which
//! holds in the asymptotic regime (r = 4 for Spencer's 1/N² convergence) and before it (r ≈ 2
//! at 10–20 slices, where a two-point Richardson estimate with the asymptotic order
//! under-estimates tenfold). r is taken within [1.1, 4]: at least 1.1 (a tail of at most
//! 11 d₁), at most Spencer's asymptotic 4 (a larger ratio is a difference that cancelled by
//! chance). Otherwise (the differences change sign or grow: a slicing that moves a kink of the
//! ground within a slice from one count to the next, F swinging about its limit) the estimate
//! is F(n)'s distance from F(4n) and half the last swing, |F(n) − F(4n)| + |d₂|/2 (|d₁| + |d₂|
//! before: ten times the true error of the ordinary method's F at 20 slices on Spencer's 1967
//! example, where F(n) swung close to its limit by chance). Above 2,500
//! slices the three counts are n/4, n/2 and n, and the error of F(n) is the tail after d₂,
//! max(|d₂|, |d₁|/r)/(r − 1).
//!
//! Measured against 10,000 slices on circles and polylines, simple slopes and layered sections
//! with water and a crack (crates/solver/tests/accuracy.rs), for Spencer's F and for each
//! method's beside it: the true error is at most twice the estimate (+1e-9), and at least a
//! tenth of it wherever it exceeds 1e-7.

use std::num::NonZeroUsize;

use super::error::SlopeError;
use super::slices::{SliceModel, Sliced};
use super::spencer::{solve_spencer, SpencerSettings};
use crate::budget::Budget;

/// Most slices an estimate reaches for (the largest count a request may ask for).
pub const MAX_SLICES: usize = 10_000;

/// The least observed ratio of successive differences the tail is summed with.
const LEAST_RATIO: f64 = 1.1;

/// The largest: Spencer's F on chords converges as 1/N², a difference falling fourfold a
/// doubling. A larger observed ratio is a difference that cancelled by chance (where a kink of
/// the ground falls inside a slice moves F by ~1e-8 from one count to the next), not faster
/// convergence.
const FASTEST_RATIO: f64 = 4.0;

/// The accuracy of an answered F.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accuracy {
    /// The slices of the answer.
    pub slices: usize,
    /// The estimated |F(n) − F(∞)|/F; `None` where it cannot be estimated (the equations have
    /// no solution at another slice count, loads given per slice fix the slices, or the budget
    /// ran out).
    pub discretisation_error: Option<f64>,
}

/// The estimate of |F(n) − F(∞)| from F at three counts a doubling apart (`coarse` true: F(n),
/// F(2n), F(4n) with n answered; false: F(n/4), F(n/2), F(n) with n answered).
pub fn tail(levels: [f64; 3], coarse: bool) -> f64 {
    let (d1, d2) = (levels[0] - levels[1], levels[1] - levels[2]);
    let monotone = d1 * d2 > 0.0 && d2.abs() < d1.abs();
    if !monotone {
        return if coarse {
            (levels[0] - levels[2]).abs() + d2.abs() / 2.0
        } else {
            d2.abs() + d1.abs() / FASTEST_RATIO
        };
    }
    let r = (d1 / d2).clamp(LEAST_RATIO, FASTEST_RATIO);
    if coarse {
        d1.abs() * r / (r - 1.0)
    } else {
        d2.abs().max(d1.abs() / r) / (r - 1.0)
    }
}

/// The accuracy of `f`, Spencer's F of `problem` at its slices: F at two more counts a doubling
/// apart (up when 4n ≤ [`MAX_SLICES`], else down), within `budget`.
pub fn accuracy_of<P: Sliced>(
    problem: &P,
    f: f64,
    settings: &SpencerSettings,
    budget: &Budget,
) -> Accuracy {
    accuracy_with(
        problem,
        f,
        &|model| solve_spencer(model, settings).factor_of_safety,
        budget,
    )
}

/// The accuracy of `f`, the F that `factor` gives `problem` at its slices (any method of
/// slices: their F on chords converge alike), as [`accuracy_of`] estimates Spencer's.
pub fn accuracy_with<P: Sliced>(
    problem: &P,
    f: f64,
    factor: &dyn Fn(&SliceModel) -> Option<f64>,
    budget: &Budget,
) -> Accuracy {
    estimate(&Recut::of(problem, budget), f, factor)
}

/// A surface re-cut at the two other counts an estimate needs, once for every F estimated on it.
pub struct Recut {
    /// The answered surface's slices.
    slices: usize,
    /// Whether the other counts are 2n and 4n (else n/4 and n/2).
    coarse: bool,
    /// The models at the other counts; `None` where a cut failed or the budget was spent.
    models: Option<[SliceModel; 2]>,
}

impl Recut {
    /// `problem` at two more counts a doubling apart (up when 4n ≤ [`MAX_SLICES`], else
    /// down), within `budget`.
    pub fn of<P: Sliced>(problem: &P, budget: &Budget) -> Self {
        let n = problem.slice_count();
        let coarse = 4 * n <= MAX_SLICES;
        let counts = if coarse {
            [2 * n, 4 * n]
        } else {
            [n / 4, n / 2]
        };
        let at = |count: usize| -> Option<SliceModel> {
            if budget.is_spent() {
                return None;
            }
            let cut = problem.with_slices(NonZeroUsize::new(count)?).ok()?;
            Some(cut.model().into_owned())
        };
        let models = (|| Some([at(counts[0])?, at(counts[1])?]))();
        Self {
            slices: n,
            coarse,
            models,
        }
    }
}

/// The accuracy of `f` (the answered surface's F by `factor`) from `factor` on the re-cuts.
pub fn estimate(recut: &Recut, f: f64, factor: &dyn Fn(&SliceModel) -> Option<f64>) -> Accuracy {
    let estimate = recut.models.as_ref().and_then(|[first, second]| {
        let (a, b) = (factor(first)?, factor(second)?);
        let levels = if recut.coarse { [f, a, b] } else { [a, b, f] };
        Some(tail(levels, recut.coarse) / f.abs())
    });
    Accuracy {
        slices: recut.slices,
        discretisation_error: estimate.filter(|e| e.is_finite()),
    }
}

/// The surface re-cut at the fewest slices (from `start`, doubling, at most [`MAX_SLICES`])
/// whose estimated error is at most `relative_error`, with its solution and accuracy; the
/// finest count reached when none is (its accuracy says how far it got).
pub fn to_accuracy<P: Sliced>(
    problem: &P,
    start: NonZeroUsize,
    relative_error: f64,
    settings: &SpencerSettings,
    budget: &Budget,
) -> Result<Option<Answered<P>>, SlopeError> {
    // F at each count tried: each doubling reuses the two counts above the last.
    let mut factors: Vec<(usize, Option<f64>)> = Vec::new();
    let factor_at = |count: usize, factors: &mut Vec<(usize, Option<f64>)>| {
        if let Some(&(_, f)) = factors.iter().find(|(c, _)| *c == count) {
            return Ok(f);
        }
        let slices = NonZeroUsize::new(count).unwrap_or(NonZeroUsize::MIN);
        let f = solve_spencer(&problem.with_slices(slices)?.model(), settings).factor_of_safety;
        factors.push((count, f));
        Ok::<_, SlopeError>(f)
    };
    let mut n = start.get().clamp(1, MAX_SLICES / 4);
    let mut best: Option<(usize, f64)> = None;
    loop {
        if budget.is_spent() {
            break;
        }
        let levels = [
            factor_at(n, &mut factors)?,
            factor_at(2 * n, &mut factors)?,
            factor_at(4 * n, &mut factors)?,
        ];
        if let [Some(a), Some(b), Some(c)] = levels {
            let e = tail([a, b, c], true) / a.abs();
            if e.is_finite() {
                best = Some((n, e));
                if e <= relative_error {
                    break;
                }
            }
        }
        if 8 * n > MAX_SLICES {
            break;
        }
        n *= 2;
    }
    let Some((n, e)) = best else {
        return Ok(None);
    };
    let problem = problem.with_slices(NonZeroUsize::new(n).unwrap_or(NonZeroUsize::MIN))?;
    let solution = solve_spencer(&problem.model(), settings);
    Ok(Some(Answered {
        accuracy: Accuracy {
            slices: problem.slice_count(),
            discretisation_error: Some(e),
        },
        problem,
        solution,
    }))
}

/// A surface answered at the slices an accuracy asked for.
#[derive(Debug, Clone)]
pub struct Answered<P> {
    /// The surface at those slices.
    pub problem: P,
    /// Its solution.
    pub solution: super::spencer::SpencerSolution,
    /// Its accuracy.
    pub accuracy: Accuracy,
}
