//! The critical slip circle: the circle of least Spencer factor of safety (Spencer 1967, §5 of
//! the thesis). A grid over centres — Spencer's own scheme, which also gives the contour map —
//! followed by a derivative-free local refinement (Nelder & Mead 1965) from the best few grid
//! points, since F over centres is non-smooth and full of shallow local minima (the thesis found
//! fmincon trapped in them). When the best centre lies on the edge of the grid, the grid is
//! moved there and the search repeated.
//!
//! Centres are measured from the lower end of the slip surface, as in [`super::geometry`].
//! Grid points whose circle cuts no slip mass, or whose equations have no solution, have no F.

use std::cell::Cell;
use std::num::NonZeroUsize;

use rayon::prelude::*;

use super::error::SlopeError;
use super::geometry::{Embankment, SlipCircle};
use crate::budget::{Budget, Stop};
use crate::numerics::{nelder_mead_to, Minimum};

use super::section::trial::circle_outcome;
use super::section::{check_circle, Section, SectionProblem, SlipShape};
use super::spencer::{Seismic, Soil, SpencerSettings};

/// The region of centres searched and the grid laid over it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearchGrid {
    /// Smallest centre X (from the lower end).
    pub x_min: f64,
    /// Largest centre X.
    pub x_max: f64,
    /// Smallest centre Y (above the lower end).
    pub y_min: f64,
    /// Largest centre Y.
    pub y_max: f64,
    /// Grid points along X (≥ 2).
    pub nx: usize,
    /// Grid points along Y (≥ 2).
    pub ny: usize,
}

impl SearchGrid {
    /// Bounds that hold the critical circle of ordinary embankments: around the perpendicular
    /// bisector of the slope face, on its uphill side, from half the height to well above the
    /// crest; 21 × 21 points. A minimum on the edge moves the grid anyway.
    pub fn automatic(embankment: &Embankment, lower_end_factor: f64) -> Self {
        let (h, l) = (embankment.height(), embankment.length());
        let face = h.hypot(l);
        let lower_end = lower_end_factor * h;
        Self {
            x_min: lower_end + 0.5 * l - face,
            x_max: lower_end + 0.5 * l + 0.75 * face,
            y_min: 0.5 * h,
            y_max: h + 2.0 * face,
            nx: 21,
            ny: 21,
        }
    }

    fn xs(&self) -> Vec<f64> {
        spaced(self.x_min, self.x_max, self.nx)
    }

    fn ys(&self) -> Vec<f64> {
        spaced(self.y_min, self.y_max, self.ny)
    }

    fn cell(&self) -> (f64, f64) {
        (
            (self.x_max - self.x_min) / (self.nx - 1) as f64,
            (self.y_max - self.y_min) / (self.ny - 1) as f64,
        )
    }
}

/// `n` values evenly from `a` to `b` (just `a` when n < 2).
pub(crate) fn spaced(a: f64, b: f64, n: usize) -> Vec<f64> {
    if n < 2 {
        return vec![a];
    }
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
        .collect()
}

/// Everything about the embankment except the circle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearchProblem {
    /// The embankment.
    pub embankment: Embankment,
    /// Slices per circle.
    pub slices: NonZeroUsize,
    /// The soil.
    pub soil: Soil,
    /// Seismic coefficients.
    pub seismic: Seismic,
    /// Lower-end factor F_e of the circles (the start of the search when it is searched too).
    pub lower_end_factor: f64,
    /// When set, F_e is searched as well in the refinement, within [0, this].
    pub lower_end_factor_max: Option<f64>,
}

impl SearchProblem {
    /// The problem of one circle of the search: the embankment as a section
    /// ([`Section::simple`]), the circle through (−F_e·H, 0) with its centre (X, Y) from there
    /// (no external loads: the slices move).
    pub fn at(&self, circle: SlipCircle) -> Result<SectionProblem, SlopeError> {
        self.on(&self.section()?, circle)
    }

    /// The embankment as a section, built once for a search's circles.
    pub fn section(&self) -> Result<Section, SlopeError> {
        Section::simple(&self.embankment, self.soil)
    }

    /// One circle's problem on `section` ([`SearchProblem::section`]).
    fn on(&self, section: &Section, circle: SlipCircle) -> Result<SectionProblem, SlopeError> {
        SectionProblem::new(
            section.clone(),
            circle.placed(self.embankment.height())?,
            self.slices,
            self.seismic,
            None,
        )
    }
}

/// Settings of the search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SearchSettings {
    /// Settings of each Spencer solution.
    pub spencer: SpencerSettings,
    /// Grid points the local refinement starts from (0: the best grid point is the answer).
    /// Defaults to 3.
    pub starts: usize,
    /// Times the grid may move when the minimum lies on its edge. Defaults to 4.
    pub max_regrids: usize,
    /// Nelder–Mead evaluations per start. Defaults to 300.
    pub max_refine_evaluations: usize,
    /// Whether the grid's bounds were given: they then stay put (no regrids) and the refined
    /// centre stays inside them. Defaults to false.
    pub hard_bounds: bool,
    /// Circles larger than this are no candidates (a radius that dwarfs the embankment is a
    /// plane, not a slip circle of it). Defaults to none.
    pub max_radius: Option<f64>,
    /// Circles whose greatest depth below the ground is smaller are no candidates (a sliver
    /// along a c' = 0 face is not the mechanism an engineer checks). Defaults to 0.
    pub min_depth: f64,
}

impl Default for SearchSettings {
    fn default() -> Self {
        Self {
            spencer: SpencerSettings::default(),
            starts: 3,
            max_regrids: 4,
            max_refine_evaluations: 300,
            hard_bounds: false,
            max_radius: None,
            min_depth: 0.0,
        }
    }
}

/// F over the grid of centres, for contour plots.
#[derive(Debug, Clone, PartialEq)]
pub struct FactorGrid {
    /// Centre X of the columns.
    pub xs: Vec<f64>,
    /// Centre Y of the rows.
    pub ys: Vec<f64>,
    /// F at (xs[i], ys[j]) in `factors[j][i]`; `None` where the centre gives no valid circle.
    pub factors: Vec<Vec<Option<f64>>>,
}

/// What a search found (how it ended is its [`Stop`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SearchStatus {
    /// The critical circle was found.
    Found,
    /// No centre of the region gives a circle with a solution.
    NoValidCircle,
}

/// The critical circle found.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchSolution {
    /// What the search found.
    pub status: SearchStatus,
    /// How it ended: [`Stop::Finished`], or the budget's reason when the budget cut it short
    /// (its answer is then not to be trusted).
    pub stop: Stop,
    /// The critical circle; `None` when no grid point gives a valid circle.
    pub circle: Option<SlipCircle>,
    /// Its factor of safety.
    pub factor_of_safety: Option<f64>,
    /// The last grid evaluated (the one around the critical circle).
    pub grid: FactorGrid,
    /// Spencer solutions computed (grid and refinement).
    pub evaluations: usize,
    /// Times the grid was moved because the minimum lay on its edge.
    pub regrids: usize,
    /// Whether the minimum still lies on the edge of the last grid (the true minimum may lie
    /// outside the region searched).
    pub is_on_edge: bool,
    /// Grid circles of the last grid that cut a mass but have no physical Spencer solution.
    pub unsolved: usize,
    /// The least Bishop F among those (an indication of what they would give).
    pub unsolved_bishop_minimum: Option<f64>,
    /// Whether such circles lie at or next to the grid point of the minimum.
    pub unsolved_near_minimum: bool,
}

/// Spencer's F for one circle, or `None` when the circle is invalid or has no solution.
pub fn factor_of_safety(
    problem: &SearchProblem,
    circle: SlipCircle,
    settings: &SpencerSettings,
) -> Option<f64> {
    let section = problem.section().ok()?;
    let frames = (&section, &section.mirrored());
    outcome(problem, frames, circle, (settings, 0.0), &Cell::new(None)).ok()
}

/// Spencer's F for one circle on `section` (`mirror`: the section seen from behind, built
/// once per search); `Err(None)` when it cuts no mass, `Err(Some(bishop))` when it has no
/// physical solution (with Bishop's F there, if any). Bishop's F, Spencer's start, is looked
/// for from `near` first, the last F found (a neighbouring circle's), which a solved circle
/// replaces.
fn outcome(
    problem: &SearchProblem,
    frames: (&Section, &Section),
    circle: SlipCircle,
    (settings, min_depth): (&SpencerSettings, f64),
    near: &Cell<Option<f64>>,
) -> Result<f64, Option<Option<f64>>> {
    let Ok(SlipShape::Circle { centre, radius }) = circle.placed(problem.embankment.height())
    else {
        return Err(None);
    };
    // A circle beyond what a section takes cuts no mass of it.
    check_circle(centre, radius).map_err(|_| None::<Option<f64>>)?;
    circle_outcome(
        frames,
        (centre, radius),
        (problem.slices, problem.seismic),
        (settings, min_depth),
        near.get(),
    )
    .map(|s| {
        near.set(Some(s.factor_of_safety));
        s.factor_of_safety
    })
}

/// The relative spread of F over the refinement's simplex below which it stops: what F is
/// computed to (the equations solved to rounding, 1e-16 relative, and the conditioning of a
/// circle's root on top), so a smaller simplex would only follow F's rounding.
pub(crate) const F_RESOLUTION: f64 = 1e-13;

/// Whether the circle's radius is within the limit.
fn within_reach(circle: SlipCircle, max_radius: Option<f64>) -> bool {
    // (x² + y²) against m² rather than hypot: this is asked of every circle of a grid.
    max_radius.is_none_or(|m| circle.x * circle.x + circle.y * circle.y <= m * m)
}

/// F over the grid, and the outcome of each point: `Err(Some(bishop))` where unsolved.
type Outcomes = Vec<Vec<Result<f64, Option<Option<f64>>>>>;

fn evaluate_grid(
    problem: &SearchProblem,
    frames: (&Section, &Section),
    grid: &SearchGrid,
    settings: &SearchSettings,
    budget: &Budget,
) -> (FactorGrid, Outcomes) {
    let (xs, ys) = (grid.xs(), grid.ys());
    let outcomes: Outcomes = ys
        .par_iter()
        .map(|&y| {
            // Each circle's F starts the next one's search for Bishop's F along the row.
            let near = Cell::new(None);
            xs.iter()
                .map(|&x| {
                    if budget.is_spent() {
                        return Err(None);
                    }
                    let circle = SlipCircle {
                        x,
                        y,
                        lower_end_factor: problem.lower_end_factor,
                    };
                    if !within_reach(circle, settings.max_radius) {
                        return Err(None);
                    }
                    outcome(
                        problem,
                        frames,
                        circle,
                        (&settings.spencer, settings.min_depth),
                        &near,
                    )
                })
                .collect()
        })
        .collect();
    let factors = outcomes
        .iter()
        .map(|row| row.iter().map(|o| o.as_ref().ok().copied()).collect())
        .collect();
    (FactorGrid { xs, ys, factors }, outcomes)
}

/// Unsolved circles of a grid: how many, the least Bishop F among them, and whether any lies
/// at or next to grid point (i, j).
pub(crate) fn unsolved_summary(
    outcomes: &Outcomes,
    (i, j): (usize, usize),
) -> (usize, Option<f64>, bool) {
    let mut count = 0;
    let mut least: Option<f64> = None;
    for row in outcomes {
        for o in row {
            if let Err(Some(bishop)) = o {
                count += 1;
                if let Some(b) = bishop {
                    least = Some(least.map_or(*b, |l: f64| l.min(*b)));
                }
            }
        }
    }
    let near = (j.saturating_sub(1)..=(j + 1).min(outcomes.len().saturating_sub(1))).any(|jj| {
        let row = &outcomes[jj];
        (i.saturating_sub(1)..=(i + 1).min(row.len().saturating_sub(1)))
            .any(|ii| matches!(row[ii], Err(Some(_))))
    });
    (count, least, near)
}

/// The grid points that have an F, least F first: (F, i, j).
fn ranked(factors: &FactorGrid) -> Vec<(f64, usize, usize)> {
    let mut points: Vec<(f64, usize, usize)> = factors
        .factors
        .iter()
        .enumerate()
        .flat_map(|(j, row)| {
            row.iter()
                .enumerate()
                .filter_map(move |(i, f)| f.map(|f| (f, i, j)))
        })
        .collect();
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    points
}

/// A grid of the same size centred on the centre `v` (kept above the lower end).
fn recentred(grid: SearchGrid, v: &[f64]) -> SearchGrid {
    let (half_x, half_y) = (
        0.5 * (grid.x_max - grid.x_min),
        0.5 * (grid.y_max - grid.y_min),
    );
    let y_centre = v[1].max(half_y * 0.1 + f64::MIN_POSITIVE);
    SearchGrid {
        x_min: v[0] - half_x,
        x_max: v[0] + half_x,
        y_min: (y_centre - half_y).max(1e-6 * half_y),
        y_max: y_centre + half_y,
        ..grid
    }
}

/// Nelder–Mead from grid point (i, j): the centre at the grid's lower-end factor, then, when it
/// is searched too, the lower end with it.
fn refine_from(
    problem: &SearchProblem,
    frames: (&Section, &Section),
    grid: &SearchGrid,
    factors: &FactorGrid,
    (i, j): (usize, usize),
    settings: &SearchSettings,
    budget: &Budget,
) -> Minimum {
    let (dx, dy) = grid.cell();
    let scale = dx.abs().max(dy.abs());
    let circle_at = |v: &[f64]| SlipCircle {
        x: v[0],
        y: v[1],
        lower_end_factor: v.get(2).copied().unwrap_or(problem.lower_end_factor),
    };
    // The last F found starts the next circle's search for Bishop's F.
    let near = Cell::new(None);
    let objective = |v: &[f64]| {
        if budget.is_spent() {
            return f64::INFINITY;
        }
        let outside =
            v[0] < grid.x_min || v[0] > grid.x_max || v[1] < grid.y_min || v[1] > grid.y_max;
        if settings.hard_bounds && outside {
            return f64::INFINITY;
        }
        if let (Some(max), Some(&f_e)) = (problem.lower_end_factor_max, v.get(2)) {
            if !(0.0..=max).contains(&f_e) {
                return f64::INFINITY;
            }
        }
        if !within_reach(circle_at(v), settings.max_radius) {
            return f64::INFINITY;
        }
        outcome(
            problem,
            frames,
            circle_at(v),
            (&settings.spencer, settings.min_depth),
            &near,
        )
        .unwrap_or(f64::INFINITY)
    };
    // Centres first, at the grid's lower-end factor…
    let start = [factors.xs[i], factors.ys[j]];
    let centres = nelder_mead_to(
        objective,
        &start,
        &[0.5 * dx, 0.5 * dy],
        (1e-9 * scale, F_RESOLUTION),
        settings.max_refine_evaluations,
    );
    // …then, when it is searched too, the lower end with them, from there: never
    // worse than the first refinement, whose point starts the simplex.
    match problem.lower_end_factor_max {
        Some(max) if centres.value.is_finite() => {
            let v = &centres.point;
            let start = [v[0], v[1], problem.lower_end_factor.clamp(0.0, max)];
            let step = [0.25 * dx, 0.25 * dy, 0.1 * max];
            let with_lower_end = nelder_mead_to(
                objective,
                &start,
                &step,
                (1e-9 * scale, F_RESOLUTION),
                settings.max_refine_evaluations,
            );
            Minimum {
                evaluations: centres.evaluations + with_lower_end.evaluations,
                ..with_lower_end
            }
        }
        _ => centres,
    }
}

/// A search that had no circle to evaluate.
fn without_circles(grid: &SearchGrid) -> SearchSolution {
    SearchSolution {
        status: SearchStatus::NoValidCircle,
        stop: Stop::Finished,
        circle: None,
        factor_of_safety: None,
        grid: FactorGrid {
            xs: grid.xs(),
            ys: grid.ys(),
            factors: vec![vec![None; grid.nx]; grid.ny],
        },
        evaluations: 0,
        regrids: 0,
        is_on_edge: false,
        unsolved: 0,
        unsolved_bishop_minimum: None,
        unsolved_near_minimum: false,
    }
}

/// Searches the critical circle over `grid` (moving it when the minimum is on its edge), within
/// `budget`: circles not evaluated by its end count as invalid and the stop says so.
pub fn search_critical_circle(
    problem: &SearchProblem,
    grid: SearchGrid,
    settings: &SearchSettings,
    budget: &Budget,
) -> SearchSolution {
    // The embankment and soil are valid by construction: a section that cannot be built has no
    // circle to offer.
    let Ok(section) = problem.section() else {
        return without_circles(&grid);
    };
    let mirror = section.mirrored();
    let frames = (&section, &mirror);
    let mut grid = grid;
    let mut evaluations = 0;
    let mut regrids = 0;
    loop {
        let (factors, outcomes) = evaluate_grid(problem, frames, &grid, settings, budget);
        evaluations += grid.nx * grid.ny;
        let points = ranked(&factors);
        let Some(&(_, bi, bj)) = points.first() else {
            let (unsolved, unsolved_bishop_minimum, _) = unsolved_summary(&outcomes, (0, 0));
            return SearchSolution {
                status: SearchStatus::NoValidCircle,
                stop: budget.stop(),
                circle: None,
                factor_of_safety: None,
                grid: factors,
                evaluations,
                regrids,
                is_on_edge: false,
                unsolved,
                unsolved_bishop_minimum,
                unsolved_near_minimum: false,
            };
        };
        // Refine from the best few grid points that are not neighbours of each other.
        let mut starts: Vec<(usize, usize)> = Vec::new();
        for &(_, i, j) in &points {
            if starts.len() >= settings.starts {
                break;
            }
            if starts
                .iter()
                .all(|&(a, b)| a.abs_diff(i) > 1 || b.abs_diff(j) > 1)
            {
                starts.push((i, j));
            }
        }
        let refined: Vec<Minimum> = starts
            .par_iter()
            .map(|&start| refine_from(problem, frames, &grid, &factors, start, settings, budget))
            .collect();
        evaluations += refined.iter().map(|r| r.evaluations).sum::<usize>();
        let best = refined
            .into_iter()
            .filter(|r| r.value.is_finite())
            .min_by(|a, b| a.value.total_cmp(&b.value));
        let (f, v) = match best {
            Some(m) => (m.value, m.point),
            None => {
                let f = points[0].0;
                (f, vec![factors.xs[bi], factors.ys[bj]])
            }
        };
        let on_edge = bi == 0 || bj == 0 || bi + 1 == grid.nx || bj + 1 == grid.ny;
        let outside =
            v[0] < grid.x_min || v[0] > grid.x_max || v[1] < grid.y_min || v[1] > grid.y_max;
        let circle = SlipCircle {
            x: v[0],
            y: v[1],
            lower_end_factor: v.get(2).copied().unwrap_or(problem.lower_end_factor),
        };
        if (on_edge || outside)
            && !settings.hard_bounds
            && regrids < settings.max_regrids
            && !budget.is_spent()
        {
            grid = recentred(grid, &v);
            regrids += 1;
            continue;
        }
        let (unsolved, unsolved_bishop_minimum, unsolved_near_minimum) =
            unsolved_summary(&outcomes, (bi, bj));
        return SearchSolution {
            status: SearchStatus::Found,
            stop: budget.stop(),
            circle: Some(circle),
            factor_of_safety: Some(f),
            grid: factors,
            evaluations,
            regrids,
            is_on_edge: on_edge || outside,
            unsolved,
            unsolved_bishop_minimum,
            unsolved_near_minimum,
        };
    }
}
