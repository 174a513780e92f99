//! The minimum thickness of a circular arch: the smallest voussoir thickness D for which the arch
//! carries its own weight (λ₀ = 1) — Milankovitch's (1904) question, asked of the rigid-block
//! model for any base angles, voussoir count, voussoir shape, limits and friction.
//!
//! # Method
//! The dead-load margin δ(D) of [`super::limit`] (the least relaxation of the limits, a fraction
//! of the weight, under which the weight is carried) is continuous in D and changes sign at the
//! minimum thickness: the root is bracketed by geometric steps from D = R/10 and then found by
//! Brent's method on δ(D) itself — a continuous margin, not a yes/no test, so that the bracket
//! shrinks superlinearly instead of by halves. The answer is the upper end of the final bracket:
//! the thinnest arch known to stand, within `tolerance`·R of the limit.

use std::time::Instant;

use super::error::ArchError;
use super::geometry::{Assembly, CircularArch};
use super::limit::full_dead_load_margin;
use super::limit::problem::{ArchProblem, InterfaceLimits, LimitSettings};
use super::mechanism::{HingeSide, Mechanism};
use crate::budget::Stop;
use crate::numerics::brent;
use crate::outcome::SolverFailure;

/// Settings of the search.
#[derive(Debug, Clone, PartialEq)]
pub struct MinimumThicknessSettings {
    /// Accuracy of the thickness relative to the radius. Defaults to 1e-6.
    pub tolerance: f64,
    /// Settings of each dead-load programme.
    pub limit: LimitSettings,
    /// Largest number of dead-load evaluations. Defaults to 100.
    pub max_evaluations: usize,
}

impl Default for MinimumThicknessSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-6,
            limit: LimitSettings::default(),
            max_evaluations: 100,
        }
    }
}

/// What the search found.
#[derive(Debug, Clone, PartialEq)]
pub enum MinimumThicknessOutcome {
    /// The minimum thickness, with the mechanism of an arch just thinner than it.
    Found {
        /// Thinnest thickness known to carry the dead load.
        thickness: f64,
        /// The thickest thickness known not to (the other end of the final bracket).
        thickness_below: f64,
        /// Collapse mechanism at `thickness_below`.
        mechanism: Option<Mechanism>,
    },
    /// Even a thickness of 1e-6·R carries the dead load: there is no finite minimum (for
    /// example N ≤ 3 voussoirs under symmetric dead load).
    StandsHoweverThin,
    /// No thickness below 2R carries the dead load (for example friction too low).
    NeverStands,
    /// A dead-load programme failed.
    SolverFailed(SolverFailure),
}

/// The answer with its cost.
#[derive(Debug, Clone, PartialEq)]
pub struct MinimumThickness {
    /// What was found, or the budget's stop (`settings.limit.budget`) when it ended the search
    /// first.
    pub outcome: Result<MinimumThicknessOutcome, Stop>,
    /// Dead-load programmes solved.
    pub evaluations: usize,
    /// Iterations over all of them (interior-point iterations; simplex pivots on a chain).
    pub iterations: u32,
    /// Wall time in seconds.
    pub solve_time_secs: f64,
}

/// Why one evaluation of δ(D) ended the search.
enum Halt {
    /// The arch at that thickness cannot be built.
    Input(ArchError),
    /// Its dead-load programme failed.
    Failed(SolverFailure),
    /// The budget is spent.
    Stopped(Stop),
}

/// One evaluation: the thickness, its margin and the mechanism when it collapses.
struct Evaluation {
    thickness: f64,
    margin: f64,
    mechanism: Option<Mechanism>,
}

/// The blocks of an arch of a given thickness.
pub type ArchOfThickness<'a> = &'a dyn Fn(f64) -> Result<Assembly, ArchError>;

/// δ(D) for the arch, counting the programmes.
struct MarginOfThickness<'a> {
    arch: ArchOfThickness<'a>,
    unit_weight: f64,
    limits: InterfaceLimits,
    friction: Option<f64>,
    settings: &'a LimitSettings,
    evaluations: usize,
    iterations: u32,
}

impl MarginOfThickness<'_> {
    fn at(&mut self, thickness: f64) -> Result<Evaluation, Halt> {
        let budget = &self.settings.budget;
        budget.check().map_err(Halt::Stopped)?;
        let assembly = (self.arch)(thickness).map_err(Halt::Input)?;
        let problem = ArchProblem::new(
            assembly,
            self.unit_weight,
            self.limits,
            self.friction,
            Vec::new(),
        )
        .map_err(Halt::Input)?;
        self.evaluations += 1;
        // A programme the budget interrupted fails: the budget's stop, not the failure.
        let full =
            full_dead_load_margin(&problem, self.settings).map_err(|failure| {
                match budget.check() {
                    Err(stop) => Halt::Stopped(stop),
                    Ok(()) => Halt::Failed(failure),
                }
            })?;
        self.iterations += full.iterations;
        Ok(Evaluation {
            thickness,
            margin: full.margin,
            mechanism: full.mechanism,
        })
    }
}

/// Searches the minimum thickness of `arch` (its own thickness is only the shape template).
pub fn solve_minimum_thickness(
    arch: &CircularArch,
    unit_weight: f64,
    limits: InterfaceLimits,
    friction: Option<f64>,
    settings: &MinimumThicknessSettings,
) -> Result<MinimumThickness, ArchError> {
    let of_thickness = |d: f64| arch.with_thickness(d).map(|a| a.assembly());
    solve_minimum_thickness_of(
        &of_thickness,
        arch.radius(),
        unit_weight,
        limits,
        friction,
        settings,
    )
}

/// Searches the minimum thickness of the arch whose blocks at thickness D are `arch(D)`, on
/// 1e-6·`scale` < D < 2·`scale` (the radius of a circle, half the span of a profile), to
/// `settings.tolerance`·`scale`.
pub fn solve_minimum_thickness_of(
    arch: ArchOfThickness,
    scale: f64,
    unit_weight: f64,
    limits: InterfaceLimits,
    friction: Option<f64>,
    settings: &MinimumThicknessSettings,
) -> Result<MinimumThickness, ArchError> {
    let start = Instant::now();
    let mut delta = MarginOfThickness {
        arch,
        unit_weight,
        limits,
        friction,
        settings: &settings.limit,
        evaluations: 0,
        iterations: 0,
    };
    let outcome = match search(&mut delta, scale, settings) {
        Ok(outcome) => Ok(outcome),
        Err(Halt::Failed(failure)) => Ok(MinimumThicknessOutcome::SolverFailed(failure)),
        Err(Halt::Stopped(stop)) => Err(stop),
        Err(Halt::Input(error)) => return Err(error),
    };
    Ok(MinimumThickness {
        outcome,
        evaluations: delta.evaluations,
        iterations: delta.iterations,
        solve_time_secs: start.elapsed().as_secs_f64(),
    })
}

/// The bracket, then the root: the outcome of the search.
fn search(
    delta: &mut MarginOfThickness,
    radius: f64,
    settings: &MinimumThicknessSettings,
) -> Result<MinimumThicknessOutcome, Halt> {
    match bracket(delta, radius, settings)? {
        Bracket::Found(ends) => {
            let (below, above) = *ends;
            narrow(delta, radius, settings, below, above)
        }
        Bracket::StandsHoweverThin => Ok(MinimumThicknessOutcome::StandsHoweverThin),
        Bracket::NeverStands => Ok(MinimumThicknessOutcome::NeverStands),
    }
}

/// Where the geometric steps from D = R/10 end.
enum Bracket {
    /// An arch that falls (δ > tol) and a thicker one that stands (δ ≤ tol) (boxed: each
    /// evaluation holds a mechanism).
    Found(Box<(Evaluation, Evaluation)>),
    /// Even the thinnest arch stands.
    StandsHoweverThin,
    /// Even the thickest arch falls.
    NeverStands,
}

/// Brackets the minimum by geometric steps from D = R/10: halving while it stands, × 1.6 while
/// it falls.
fn bracket(
    delta: &mut MarginOfThickness,
    radius: f64,
    settings: &MinimumThicknessSettings,
) -> Result<Bracket, Halt> {
    let tol = settings.limit.margin_tolerance;
    let stands = |e: &Evaluation| e.margin <= tol;
    let thinnest = 1e-6 * radius;
    let thickest = 2.0 * radius * (1.0 - 1e-9);
    // Bracket: `below` falls (δ > tol), `above` stands (δ ≤ tol).
    let first = delta.at(0.1 * radius)?;
    let (below, above) = if stands(&first) {
        let mut above = first;
        loop {
            if above.thickness <= thinnest {
                return Ok(Bracket::StandsHoweverThin);
            }
            let e = delta.at((0.5 * above.thickness).max(thinnest))?;
            if !stands(&e) {
                break (e, above);
            }
            above = e;
        }
    } else {
        let mut below = first;
        loop {
            if below.thickness >= thickest {
                return Ok(Bracket::NeverStands);
            }
            let e = delta.at((1.6 * below.thickness).min(thickest))?;
            if stands(&e) {
                break (below, e);
            }
            below = e;
        }
    };
    Ok(Bracket::Found(Box::new((below, above))))
}

/// Brent's method on δ(D) − tol from the bracket (`below` falls, `above` stands), keeping the
/// bracket's ends, closed by bisection to `settings.tolerance`·R.
fn narrow(
    delta: &mut MarginOfThickness,
    radius: f64,
    settings: &MinimumThicknessSettings,
    mut below: Evaluation,
    mut above: Evaluation,
) -> Result<MinimumThicknessOutcome, Halt> {
    let tol = settings.limit.margin_tolerance;
    let stands = |e: &Evaluation| e.margin <= tol;
    let x_tolerance = settings.tolerance * radius;
    let mut stop = None;
    let (a, b, fa, fb) = (
        below.thickness,
        above.thickness,
        below.margin - tol,
        above.margin - tol,
    );
    let budget = settings.max_evaluations.saturating_sub(delta.evaluations);
    let _ = brent(
        |x| {
            if stop.is_some() {
                return f64::NAN;
            }
            match delta.at(x) {
                Ok(e) => {
                    let value = e.margin - tol;
                    if value > 0.0 {
                        if e.thickness > below.thickness {
                            below = e;
                        }
                    } else if e.thickness < above.thickness {
                        above = e;
                    }
                    value
                }
                Err(s) => {
                    stop = Some(s);
                    f64::NAN
                }
            }
        },
        a,
        b,
        fa,
        fb,
        // Brent stops on its own bracket; aim a little tighter so ours closes too.
        0.5 * x_tolerance,
        budget,
    );
    if let Some(s) = stop {
        return Err(s);
    }
    // Close our bracket by bisection if Brent's last steps all fell on one side.
    while above.thickness - below.thickness > x_tolerance
        && delta.evaluations < settings.max_evaluations
    {
        let e = delta.at(0.5 * (below.thickness + above.thickness))?;
        if stands(&e) {
            above = e;
        } else {
            below = e;
        }
    }
    Ok(MinimumThicknessOutcome::Found {
        thickness: above.thickness,
        thickness_below: below.thickness,
        mechanism: below.mechanism,
    })
}

/// The rupture angle of a mechanism: the angle from the crown (the middle of the arch) of its
/// intrados hinge on the right half, in degrees.
pub fn rupture_angle_deg(arch: &CircularArch, mechanism: &Mechanism) -> Option<f64> {
    let crown = 0.5 * (arch.interface_angle_deg(0) + arch.interface_angle_deg(arch.voussoirs()));
    mechanism
        .hinges
        .iter()
        .filter(|h| h.side == HingeSide::Intrados && h.angle_deg <= crown)
        .map(|h| crown - h.angle_deg)
        .fold(None, |best: Option<f64>, a| {
            Some(best.map_or(a, |b| b.min(a)))
        })
}
