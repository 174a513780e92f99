//! A rolling load's critical position narrowed between the stops (SPEC §6.2): the least λ lies
//! between the critical stop's neighbours; a golden-section search over that bracket, one
//! live-load analysis per position, narrows it to a given fraction of the stop spacing.

use super::error::ArchError;
use super::limit::ArchProblem;
use super::plan::{ArchOutcome, ArchPlan, Friction, Programme, RefineCritical, RefinedCritical};
use super::stage::analyse_programme;
use crate::budget::Budget;

/// 1/φ, the golden section.
const GOLDEN: f64 = 0.618_033_988_749_894_8;

/// `outcome` (a finished rolling sweep over the stops at `refine.positions`) with its critical
/// stop narrowed to [`RefineCritical::TOLERANCE`] of the stops' spacing: a golden-section search
/// for the least λ between the critical stop's neighbours, the live loads at a position from
/// the axles. Where a position gives a lower λ than the stop, the answer is that position's
/// (its problem, state and mechanism, friction treated as `plan` says); the curve keeps the
/// stops' λ. Unchanged when there is no critical stop, the sweep did not finish, or the budget
/// ends the search (then the stop's answer stands, with the stops' half spacing as its error).
pub fn refine_critical(
    mut outcome: ArchOutcome,
    problem: &ArchProblem,
    plan: &ArchPlan,
    refine: &RefineCritical,
    budget: &Budget,
) -> Result<ArchOutcome, ArchError> {
    let start = std::time::Instant::now();
    let positions = &refine.positions;
    if positions.len() < 2 {
        return Ok(outcome);
    }
    let Some(curve) = outcome.rolling.as_mut() else {
        return Ok(outcome);
    };
    let Some((i, stop_lambda)) = curve.critical.filter(|_| outcome.stop.is_finished()) else {
        return Ok(outcome);
    };
    let Some(refined) = narrowed(problem, plan, refine, budget, i, stop_lambda)? else {
        return Ok(outcome);
    };
    if refined.position != positions[i] {
        // The answer at the refined position, friction treated as the plan says.
        let Some(answer) = answer_at(problem, plan, refine, refined.position, budget)? else {
            return Ok(outcome);
        };
        let (curve, swept) = (outcome.rolling.take(), outcome.solution.solve_time_secs);
        outcome = ArchOutcome {
            rolling: curve,
            ..answer
        };
        outcome.solution.solve_time_secs = swept;
    }
    // The whole solve's time: the sweep's and the search's.
    outcome.solution.solve_time_secs += start.elapsed().as_secs_f64();
    if let Some(curve) = outcome.rolling.as_mut() {
        curve.refined = Some(refined);
    }
    Ok(outcome)
}

/// The golden-section search between the neighbours of the critical stop `i` (of λ
/// `stop_lambda`) to [`RefineCritical::TOLERANCE`] of the stops' spacing, one associative
/// live-load analysis per position; `None` when the budget ended one of them.
fn narrowed(
    problem: &ArchProblem,
    plan: &ArchPlan,
    refine: &RefineCritical,
    budget: &Budget,
    i: usize,
    stop_lambda: f64,
) -> Result<Option<RefinedCritical>, ArchError> {
    let positions = &refine.positions;
    let spacing =
        (positions[positions.len() - 1] - positions[0]).abs() / (positions.len() - 1) as f64;
    let tolerance = RefineCritical::TOLERANCE * spacing;
    let (a, b) = (
        positions[i.saturating_sub(1)],
        positions[(i + 1).min(positions.len() - 1)],
    );
    let associative = ArchPlan::new(
        Programme::LiveLoad,
        Friction::Associative,
        plan.settings.clone(),
    );
    let mut evaluations = 0;
    let mut lambda = |x: f64| -> Result<Option<f64>, ArchError> {
        let loads = refine.axles.loads_at(x);
        if loads.is_empty() {
            return Ok(Some(f64::INFINITY));
        }
        evaluations += 1;
        let at = analyse_programme(
            &problem.clone().with_live_loads(loads)?,
            &associative,
            budget,
        )?;
        Ok(at
            .stop
            .is_finished()
            .then(|| at.solution.load_factor.unwrap_or(f64::INFINITY)))
    };
    let Some((best, (a, b))) = golden((a, b), (positions[i], stop_lambda), tolerance, &mut lambda)?
    else {
        return Ok(None);
    };
    Ok(Some(RefinedCritical {
        position: best.0,
        load_factor: best.1,
        error: 0.5 * (b - a),
        evaluations,
    }))
}

/// The live-load answer with `refine`'s axles at `x` (their reference point), friction treated
/// as `plan` says; `None` when the budget ended it.
fn answer_at(
    problem: &ArchProblem,
    plan: &ArchPlan,
    refine: &RefineCritical,
    x: f64,
    budget: &Budget,
) -> Result<Option<ArchOutcome>, ArchError> {
    let at = ArchPlan::new(Programme::LiveLoad, plan.friction, plan.settings.clone());
    let answer = analyse_programme(
        &problem.clone().with_live_loads(refine.axles.loads_at(x))?,
        &at,
        budget,
    )?;
    Ok(answer.stop.is_finished().then_some(answer))
}

/// λ at a position: `None` when the budget ended its analysis.
type Lambda<'a> = dyn FnMut(f64) -> Result<Option<f64>, ArchError> + 'a;

/// The least point (x, λ) seen and the final bracket.
type Found = ((f64, f64), (f64, f64));

/// The golden-section search for the least of `f` over [a, b] until the bracket is at most
/// 2·`tolerance` wide: the least point seen (`best` to start with) and the final bracket;
/// `None` when an evaluation was cut short.
fn golden(
    (mut a, mut b): (f64, f64),
    mut best: (f64, f64),
    tolerance: f64,
    f: &mut Lambda<'_>,
) -> Result<Option<Found>, ArchError> {
    let (mut c, mut d) = (b - GOLDEN * (b - a), a + GOLDEN * (b - a));
    let (Some(mut fc), Some(mut fd)) = (f(c)?, f(d)?) else {
        return Ok(None);
    };
    loop {
        for (x, value) in [(c, fc), (d, fd)] {
            if value < best.1 {
                best = (x, value);
            }
        }
        if b - a <= 2.0 * tolerance {
            return Ok(Some((best, (a, b))));
        }
        if fc <= fd {
            (b, d, fd) = (d, c, fc);
            c = b - GOLDEN * (b - a);
            let Some(value) = f(c)? else {
                return Ok(None);
            };
            fc = value;
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + GOLDEN * (b - a);
            let Some(value) = f(d)? else {
                return Ok(None);
            };
            fd = value;
        }
    }
}
