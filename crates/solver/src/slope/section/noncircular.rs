//! The critical non-circular surface (model §4.4). Two starts: the critical circle's polyline
//! (`vertices` points at equal steps from entry to exit), and the best block surface along the
//! section's layer boundaries ([`blocks`]: a grid of x₁, x₂ on each, then Nelder–Mead), which
//! is where a thin weak layer's surface lies and where no polyline moved from a circle gets.
//! From the lower start first, then the other while time remains, the interior heights and the
//! entry and exit move to lower Spencer's F (Nelder–Mead, restarted from its own answer while
//! that still lowers F), under a time budget. Kinematically admissible: the base never bends
//! back upwards by more than `REVERSE_BEND_DEG` between segments (the surface is concave
//! upwards but for that), stays below the ground and above bedrock.

use std::cell::Cell;
use std::num::NonZeroUsize;
use std::time::Instant;

use super::blocks;
use super::model::Section;
use super::place::place;
use super::polyline::Polyline;
use super::shape::SlipShape;
use crate::budget::{Budget, Stop};
use crate::numerics::nelder_mead;
use crate::slope::spencer::{spencer_factor_outcome, FactorOutcome, Seismic, SpencerSettings};

/// A surface's points, left to right.
type Points = [(f64, f64)];

/// The most a segment may turn downwards from the one before it, in degrees.
const REVERSE_BEND_DEG: f64 = 10.0;

/// What the non-circular search found.
#[derive(Debug, Clone, PartialEq)]
pub struct NoncircularSearch {
    /// The surface, left to right.
    pub surface: Vec<(f64, f64)>,
    /// Its factor of safety.
    pub factor_of_safety: f64,
    /// The least F found so far, the critical circle's polyline first, then each time a round
    /// of the search lowered it.
    pub path: Vec<f64>,
    /// When each of `path` was reached, in milliseconds from the start of the search.
    pub path_ms: Vec<f64>,
    /// Surfaces evaluated.
    pub evaluations: usize,
    /// How the search ended: [`Stop::Finished`], or what ended it first (its time budget, the
    /// solve's, its evaluation cap), when the surface is the best found so far.
    pub stop: Stop,
}

/// Whether a surface (left to right) may slide: its interior points below the ground, above
/// bedrock, and concave upwards but for reverse bends of up to `REVERSE_BEND_DEG`.
fn admissible(section: &Section, points: &[(f64, f64)]) -> bool {
    // On the bedrock to rounding counts as on it (a composite start's vertices lie there).
    let rounding = points
        .iter()
        .fold(1.0f64, |m, p| m.max(p.0.abs()).max(p.1.abs()))
        * 1e-12;
    let inside = points.len() >= 2
        && points[1..points.len() - 1].iter().all(|&(x, y)| {
            y < section.ground.y_at(x)
                && section
                    .bedrock
                    .as_ref()
                    .is_none_or(|r| y >= r.y_at(x) - rounding)
        });
    let limit = REVERSE_BEND_DEG.to_radians();
    let angles: Vec<f64> = points
        .windows(2)
        .map(|w| (w[1].1 - w[0].1).atan2(w[1].0 - w[0].0))
        .collect();
    // Whichever way the slope faces, a bowl's segments steepen from left to right.
    inside && angles.windows(2).all(|w| w[1] >= w[0] - limit)
}

/// The surface of `v`: entry x, exit x, then the interior heights as depths below the ground at
/// `fractions` of the way from entry to exit (k/m as (k, m), which for the circle's equal steps
/// i/(n − 1) rounds as `(b − a)·i/(n − 1)` always has).
fn surface_of(section: &Section, fractions: &[(f64, f64)], v: &[f64]) -> Option<Vec<(f64, f64)>> {
    let (a, b) = (v[0], v[1]);
    if b <= a || b.is_nan() || a.is_nan() {
        return None;
    }
    let ground = &section.ground;
    // The ends sit just above the ground so that the surface crosses it there.
    let lift = 1e-6 * (b - a);
    let mut points = Vec::with_capacity(v.len());
    points.push((a, ground.y_at(a) + lift));
    for ((k, m), depth) in fractions.iter().zip(&v[2..]) {
        if *depth <= 0.0 {
            return None;
        }
        let x = a + (b - a) * k / m;
        points.push((x, ground.y_at(x) - depth));
    }
    points.push((b, ground.y_at(b) + lift));
    admissible(section, &points).then_some(points)
}

/// A surface's parameters for [`surface_of`]: its interior points' fractions of the way from
/// entry to exit, and entry, exit and their depths.
fn parameters(section: &Section, points: &[(f64, f64)]) -> (Vec<(f64, f64)>, Vec<f64>) {
    let (a, b) = (points[0].0, points[points.len() - 1].0);
    let inner = &points[1..points.len() - 1];
    let fractions = inner.iter().map(|p| (p.0 - a, b - a)).collect();
    let v = [a, b]
        .into_iter()
        .chain(
            inner
                .iter()
                .map(|p| (section.ground.y_at(p.0) - p.1).max(1e-6 * (b - a))),
        )
        .collect();
    (fractions, v)
}

/// `points` with points added in the middle of the longest segments until there are `n`.
fn refined(mut points: Vec<(f64, f64)>, n: usize) -> Vec<(f64, f64)> {
    while points.len() < n {
        let Some(i) = (1..points.len()).max_by(|&i, &j| {
            let length = |k: usize| points[k].0 - points[k - 1].0;
            length(i).total_cmp(&length(j))
        }) else {
            break;
        };
        let (p, q) = (points[i - 1], points[i]);
        points.insert(i, (0.5 * (p.0 + q.0), 0.5 * (p.1 + q.1)));
    }
    points
}

/// Rounds of Nelder–Mead on [`surface_of`]'s parameters from `v`, restarted while F still falls
/// by 0.1 %, telling `round` F after each: the best parameters, their F, and what ended the
/// rounds early (`stop`: [`Stop::Finished`] while the search may go on).
fn polish(
    factor: &dyn Fn(&[f64]) -> f64,
    mut v: Vec<f64>,
    mut best: f64,
    stop: &dyn Fn() -> Stop,
    round: &mut dyn FnMut(f64),
) -> (Vec<f64>, f64, Stop) {
    let n = v.len();
    let span = v[1] - v[0];
    let mut stopped = Stop::Finished;
    for _ in 0..8 {
        let depth = v[2..].iter().fold(0.0f64, |m, d| m.max(*d));
        let mut step = vec![0.05 * span, 0.05 * span];
        step.extend(std::iter::repeat_n(0.15 * depth.max(1e-3 * span), n - 2));
        let found = nelder_mead(factor, &v, &step, 1e-7 * span, 400 * n);
        if stopped.is_finished() {
            stopped = stop();
        }
        if found.value >= best || found.value.is_nan() {
            break;
        }
        let settled = found.value >= best * (1.0 - 1e-3);
        best = found.value;
        v = found.point;
        round(best);
        if settled || !stopped.is_finished() {
            break;
        }
    }
    (v, best, stopped)
}

/// The best admissible block surface ([`blocks`]): on every base, x₁ and x₂ over a grid of its
/// stretch below the ground with the rays at 45° ± φ/2 (the steeper, active, one under the
/// higher ground), then the best base's best block moved by Nelder–Mead in (x₁, x₂, both
/// angles).
fn best_block(section: &Section, trial: &dyn Fn(&Points) -> f64) -> Option<Vec<(f64, f64)>> {
    const GRID: usize = 12;
    let phi = section.layers[0].soil.friction_angle_rad;
    let (active, passive) = (
        std::f64::consts::FRAC_PI_4 + 0.5 * phi,
        std::f64::consts::FRAC_PI_4 - 0.5 * phi,
    );
    let angles = |x1: f64, x2: f64| {
        if section.ground.y_at(x1) >= section.ground.y_at(x2) {
            (active, passive)
        } else {
            (passive, active)
        }
    };
    let block = |base: &blocks::Base, p: [f64; 4]| {
        blocks::block(section, base, (p[0], p[1]), (p[2], p[3]))
            .filter(|points| admissible(section, points))
    };
    let mut best: Option<(usize, [f64; 4], f64)> = None;
    let bases = blocks::bases(section);
    for (k, base) in bases.iter().enumerate() {
        let at = |i: usize| base.from + (base.to - base.from) * i as f64 / GRID as f64;
        for i in 0..GRID {
            for j in i + 1..=GRID {
                let (x1, x2) = (at(i), at(j));
                let (l, r) = angles(x1, x2);
                let Some(points) = block(base, [x1, x2, l, r]) else {
                    continue;
                };
                let f = trial(&points);
                if best.is_none_or(|b| f < b.2) {
                    best = Some((k, [x1, x2, l, r], f));
                }
            }
        }
    }
    let (k, start, f) = best.filter(|b| b.2.is_finite())?;
    let base = &bases[k];
    let of = |p: &[f64]| block(base, [p[0], p[1], p[2], p[3]]);
    let span = base.to - base.from;
    let step = [0.5 * span / GRID as f64, 0.5 * span / GRID as f64, 0.1, 0.1];
    let found = nelder_mead(
        |p| of(p).map_or(f64::INFINITY, |points| trial(&points)),
        &start,
        &step,
        1e-7 * span,
        400,
    );
    of(if found.value < f {
        &found.point
    } else {
        &start
    })
}

/// A trial's F at `slices`, if four times as many give it again (to 1 %): a surface can have a
/// root at one slicing only, which an optimiser would happily exploit. Infinite otherwise.
fn confirmed_factor(
    section: &Section,
    mirror: &Section,
    shape: &SlipShape,
    slicing: Slicing,
    settings: &SpencerSettings,
) -> f64 {
    let Slicing {
        slices,
        seismic,
        min_depth,
        beyond_ground,
    } = slicing;
    let doubled = NonZeroUsize::new(4 * slices.get()).unwrap_or(slices);
    let at = |n: NonZeroUsize| -> Option<f64> {
        let cut = place(section, Some(mirror), shape, n, seismic, None).ok()?;
        // Shallower than `search.min_depth`, or beyond the section: not a candidate (as in
        // the circle stage).
        if cut.model.depth() < min_depth || !(beyond_ground || cut.within_ground(section, mirror)) {
            return None;
        }
        match spencer_factor_outcome(&cut.model, settings) {
            FactorOutcome::Solved(s) => Some(s.factor_of_safety),
            FactorOutcome::Unsolved { .. } | FactorOutcome::Undriven => None,
        }
    };
    match (at(slices), at(doubled)) {
        (Some(f), Some(g)) if (f - g).abs() <= 1e-2 * f => f,
        _ => f64::INFINITY,
    }
}

/// A polyline's parameters: the interior vertices' fractions along x, and the ends' x with
/// each vertex's depth below the ground.
type Parameters = (Vec<(f64, f64)>, Vec<f64>);

/// The surface `start` (left to right) as the search's parameters with `n` vertices: the
/// interior vertices' fractions along x, and the ends' x with each vertex's depth below the
/// ground.
fn resampled(section: &Section, start: &[(f64, f64)], n: usize) -> Option<Parameters> {
    let (a, b) = (start.first()?.0, start.last()?.0);
    let start_line = Polyline::new(start.to_vec()).ok()?;
    let fractions: Vec<(f64, f64)> = (1..n - 1).map(|i| (i as f64, (n - 1) as f64)).collect();
    let mut v = vec![a, b];
    for (k, m) in &fractions {
        let x = a + (b - a) * k / m;
        // On the bedrock where a composite start follows it (not a rounding below it).
        let y = section
            .bedrock
            .as_ref()
            .map_or(start_line.y_at(x), |r| start_line.y_at(x).max(r.y_at(x)));
        v.push((section.ground.y_at(x) - y).max(1e-6 * (b - a)));
    }
    Some((fractions, v))
}

/// A polyline's F, confirmed at four times the slices ([`confirmed_factor`]).
fn polyline_factor(
    section: &Section,
    mirror: &Section,
    points: Vec<(f64, f64)>,
    slicing: Slicing,
    settings: &SpencerSettings,
) -> f64 {
    let Ok(line) = Polyline::new(points) else {
        return f64::INFINITY;
    };
    let shape = SlipShape::Polyline(line);
    confirmed_factor(section, mirror, &shape, slicing, settings)
}

/// How a trial surface is cut and solved.
#[derive(Debug, Clone, Copy)]
struct Slicing {
    /// Its slices (confirmed at four times as many).
    slices: NonZeroUsize,
    /// The seismic loading.
    seismic: Seismic,
    /// The least depth of a candidate (`search.min_depth`; zero: any).
    min_depth: f64,
    /// Whether a candidate may end beyond the section's x-range.
    beyond_ground: bool,
}

/// How far a non-circular search goes and which surfaces it may answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NoncircularLimits {
    /// Points of the polyline moved (at least 3).
    pub vertices: usize,
    /// The most trial surfaces evaluated; none: as many as the budget allows.
    pub max_evaluations: Option<usize>,
    /// Surfaces shallower than this are no candidates (zero: any).
    pub min_depth: f64,
    /// Whether a surface may end beyond the section's x-range (otherwise no candidate).
    pub beyond_ground: bool,
}

/// Searches from `start` (a circle's polyline, left to right) with `limits.vertices` points,
/// and from the best block surface along the section's layer boundaries when that is lower.
/// Once `budget` is spent, or `limits.max_evaluations` trial surfaces were evaluated, every
/// trial fails, so that the optimisers stop with the best found so far (`stop` then says
/// which).
pub fn search_noncircular(
    section: &Section,
    start: &[(f64, f64)],
    limits: NoncircularLimits,
    slices: NonZeroUsize,
    seismic: Seismic,
    settings: &SpencerSettings,
    budget: &Budget,
) -> Option<NoncircularSearch> {
    // The start is solved as any answer is (with Spencer's own construction when Newton's
    // method fails: a composite circle's θ can lie beyond Newton's reach from θ = 0); trial
    // surfaces without a Newton solution are skipped rather than searched for one.
    let NoncircularLimits {
        vertices,
        max_evaluations,
        min_depth,
        beyond_ground,
    } = limits;
    let start_settings = *settings;
    let trials = Trials {
        section,
        mirror: section.mirrored(),
        slicing: Slicing {
            slices,
            seismic,
            min_depth,
            beyond_ground,
        },
        settings: SpencerSettings {
            fallback: false,
            ..*settings
        },
        budget,
        max_evaluations,
        evaluations: Cell::new(0),
    };
    // The start: the circle's surface resampled at the vertices.
    let n = vertices.max(3);
    let (fractions, v) = resampled(section, start, n)?;
    let began = Instant::now();
    // The start is evaluated whatever the time, so that a search out of time still answers.
    trials.evaluations.set(trials.evaluations.get() + 1);
    let first = surface_of(section, &fractions, &v).map_or(f64::INFINITY, |p| {
        let slicing = Slicing {
            min_depth: 0.0,
            ..trials.slicing
        };
        polyline_factor(section, &trials.mirror, p, slicing, &start_settings)
    });
    if !first.is_finite() {
        return None;
    }
    let mut starts = vec![Candidate {
        fractions,
        v,
        factor: first,
    }];
    starts.extend(block_start(&trials, n));
    let Polished {
        best,
        path,
        path_ms,
        stop,
    } = polished(&trials, starts, first, began);
    Some(NoncircularSearch {
        surface: surface_of(section, &best.fractions, &best.v)?,
        factor_of_safety: best.factor,
        path,
        path_ms,
        evaluations: trials.evaluations.get(),
        stop,
    })
}

/// The non-circular search's trial surfaces: how each is solved, and what ends the search.
struct Trials<'a> {
    /// The section.
    section: &'a Section,
    /// The section seen from behind ([`place`]'s mirror).
    mirror: Section,
    /// How a trial is cut.
    slicing: Slicing,
    /// Spencer's settings for a trial (without the fallback construction).
    settings: SpencerSettings,
    /// The search's budget.
    budget: &'a Budget,
    /// The most trial surfaces to evaluate, if capped.
    max_evaluations: Option<usize>,
    /// Surfaces evaluated so far.
    evaluations: Cell<usize>,
}

impl Trials<'_> {
    /// What ends the search: the budget, or a count of trial surfaces that gives the same
    /// answer whatever the machine ([`Stop::Finished`] while it may go on).
    #[inline]
    fn stop(&self) -> Stop {
        match self.budget.stop() {
            Stop::Finished
                if self
                    .max_evaluations
                    .is_some_and(|m| self.evaluations.get() >= m) =>
            {
                Stop::EvaluationCap
            }
            stop => stop,
        }
    }

    /// Whether the search must end.
    #[inline]
    fn late(&self) -> bool {
        !self.stop().is_finished()
    }

    /// A trial surface's F, confirmed ([`polyline_factor`]); past the end every trial fails,
    /// so that the optimisers stop.
    #[inline]
    fn trial(&self, points: &Points) -> f64 {
        if self.late() {
            f64::INFINITY
        } else {
            self.evaluations.set(self.evaluations.get() + 1);
            polyline_factor(
                self.section,
                &self.mirror,
                points.to_vec(),
                self.slicing,
                &self.settings,
            )
        }
    }

    /// The trial F of the surface of parameters `v` ([`surface_of`]); infinite where there is
    /// none.
    #[inline]
    fn factor(&self, fractions: &[(f64, f64)], v: &[f64]) -> f64 {
        surface_of(self.section, fractions, v).map_or(f64::INFINITY, |p| self.trial(&p))
    }
}

/// A surface the search moves: its parameters for [`surface_of`] and its F.
#[derive(Debug, Clone)]
struct Candidate {
    /// The interior vertices' fractions of the way from entry to exit.
    fractions: Vec<(f64, f64)>,
    /// Entry x, exit x, then the interior vertices' depths below the ground.
    v: Vec<f64>,
    /// Its factor of safety.
    factor: f64,
}

/// The best block surface ([`best_block`]) as a start with `n` vertices, when its F is finite.
fn block_start(trials: &Trials, n: usize) -> Option<Candidate> {
    let points = best_block(trials.section, &|p: &Points| trials.trial(p))?;
    // Its F as polished and answered: with the vertices it will be moved by.
    let (fractions, v) = parameters(trials.section, &refined(points, n));
    let factor = trials.factor(&fractions, &v);
    factor.is_finite().then_some(Candidate {
        fractions,
        v,
        factor,
    })
}

/// What polishing the starts found.
struct Polished {
    /// The best surface.
    best: Candidate,
    /// The least F so far, each time it fell ([`NoncircularSearch::path`]).
    path: Vec<f64>,
    /// When each of `path` was reached, in milliseconds from the start of the search.
    path_ms: Vec<f64>,
    /// What ended the search ([`Stop::Finished`]: nothing did).
    stop: Stop,
}

/// Each of `starts` polished ([`polish`]), the lower first, while the search may go on: the
/// best surface, the path of F from `first` (the circle's) with the times from `began`, and
/// what ended the search.
fn polished(trials: &Trials, mut starts: Vec<Candidate>, first: f64, began: Instant) -> Polished {
    // The lower start first: what the time budget leaves for the other is its bonus.
    starts.sort_by(|p, q| p.factor.total_cmp(&q.factor));
    let mut best = starts[0].clone();
    let mut path = vec![first];
    let mut path_ms = vec![0.0];
    let mut note = |f: f64| {
        if f < path[path.len() - 1] {
            path.push(f);
            path_ms.push(began.elapsed().as_secs_f64() * 1e3);
        }
    };
    note(best.factor);
    let mut stopped = Stop::Finished;
    for Candidate {
        fractions,
        v,
        factor,
    } in starts
    {
        if trials.late() {
            stopped = trials.stop();
            break;
        }
        let factor_of = |v: &[f64]| trials.factor(&fractions, v);
        let (v, g, stopped_here) = polish(&factor_of, v, factor, &|| trials.stop(), &mut note);
        if stopped.is_finished() {
            stopped = stopped_here;
        }
        if g < best.factor {
            best = Candidate {
                fractions,
                v,
                factor: g,
            };
        }
    }
    Polished {
        best,
        path,
        path_ms,
        stop: stopped,
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::slope::section::tests::slope_over_layer;

    #[test]
    fn block_starts_are_admissible_surfaces() {
        // A weak layer whose top rises to a ridge under the face: a base along it bends back
        // upwards by far more than 10°, so the block start must not follow it over the ridge.
        let section = slope_over_layer(
            &[
                (-20.0, 3.0),
                (2.0, 3.0),
                (8.0, 6.5),
                (14.0, 1.0),
                (40.0, 1.0),
            ],
            0.5,
            5.0,
        );
        let calls = std::cell::Cell::new(0);
        let trial = |points: &Points| {
            calls.set(calls.get() + 1);
            assert!(admissible(&section, points), "tried {points:?}");
            // Lower the longer the surface runs under the ground: it would follow the ridge.
            -(points[points.len() - 1].0 - points[0].0)
        };
        let points = best_block(&section, &trial).unwrap();
        assert!(admissible(&section, &points));
        assert!(calls.get() > 100);
    }
}
