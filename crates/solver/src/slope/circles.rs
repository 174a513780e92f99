//! The one circle search (model §4.4; Spencer 1967, §5 of the thesis): a grid over centres —
//! Spencer's own scheme, which also gives the contour map — then a derivative-free refinement
//! (Nelder & Mead 1965) from the best few grid points that are not neighbours, since F over
//! centres is non-smooth and full of shallow local minima (the thesis found fmincon trapped in
//! them); when the minimum lies on the edge of the grid and the bounds may move, the grid is
//! moved there and the search repeated.
//!
//! Two families of circles share it ([`CircleFamily`]): the simple slope's circles through the
//! lower end of their slip surface, one per centre ([`super::search`]), and a section's circles
//! of several radii at each centre ([`super::section::search`]). The grid, the ranking, the
//! starts, the moves, the counts of unsolved circles and the answer are written here once; how a
//! centre's circles are evaluated and refined is the family's.

use rayon::prelude::*;

use crate::budget::{Budget, Stop};
use crate::numerics::Minimum;

/// The relative spread of F over the refinement's simplex below which it stops: what F is
/// computed to (the equations solved to rounding, 1e-16 relative, and the conditioning of a
/// circle's root on top), so a smaller simplex would only follow F's rounding.
pub(crate) const F_RESOLUTION: f64 = 1e-13;

/// The grid of centres searched: a rectangle and the points laid over it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentreGrid {
    /// Smallest centre x.
    pub x_min: f64,
    /// Largest centre x.
    pub x_max: f64,
    /// Smallest centre y.
    pub y_min: f64,
    /// Largest centre y.
    pub y_max: f64,
    /// Grid points along x (≥ 2).
    pub nx: usize,
    /// Grid points along y (≥ 2).
    pub ny: usize,
}

impl CentreGrid {
    /// The grid seen from behind (x → −x).
    pub fn mirrored(&self) -> Self {
        Self {
            x_min: -self.x_max,
            x_max: -self.x_min,
            ..*self
        }
    }

    /// The centres' x, evenly from `x_min` to `x_max`.
    pub fn xs(&self) -> Vec<f64> {
        spaced(self.x_min, self.x_max, self.nx)
    }

    /// The centres' y, evenly from `y_min` to `y_max`.
    pub fn ys(&self) -> Vec<f64> {
        spaced(self.y_min, self.y_max, self.ny)
    }

    /// The spacing of the centres along x and y.
    pub fn cell(&self) -> (f64, f64) {
        (
            (self.x_max - self.x_min) / (self.nx.max(2) - 1) as f64,
            (self.y_max - self.y_min) / (self.ny.max(2) - 1) as f64,
        )
    }

    /// Whether the centre `v` lies outside the rectangle.
    pub fn is_outside(&self, v: &[f64]) -> bool {
        v[0] < self.x_min || v[0] > self.x_max || v[1] < self.y_min || v[1] > self.y_max
    }

    /// Whether grid point (i, j) lies on the grid's edge.
    pub fn is_edge_point(&self, (i, j): (usize, usize)) -> bool {
        i == 0 || j == 0 || i + 1 == self.nx || j + 1 == self.ny
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

/// F over the grid of centres, for contour plots.
#[derive(Debug, Clone, PartialEq)]
pub struct FactorGrid {
    /// Centre x of the columns.
    pub xs: Vec<f64>,
    /// Centre y of the rows.
    pub ys: Vec<f64>,
    /// F at (xs[i], ys[j]) in `factors[j][i]`; `None` where the centre gives no valid circle.
    pub factors: Vec<Vec<Option<f64>>>,
}

impl FactorGrid {
    /// The grid seen from behind (x → −x): columns in increasing x again.
    pub fn mirrored(&self) -> Self {
        Self {
            xs: self.xs.iter().rev().map(|x| -x).collect(),
            ys: self.ys.clone(),
            factors: self
                .factors
                .iter()
                .map(|row| row.iter().rev().copied().collect())
                .collect(),
        }
    }
}

/// What a search found (how it ended is its [`Stop`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SearchStatus {
    /// The critical circle was found.
    Found,
    /// No centre of the region gives a circle with a solution.
    NoValidCircle,
}

/// What a circle search found, whichever the family of its circles.
#[derive(Debug, Clone, PartialEq)]
pub struct CircleSearch<C> {
    /// What it found.
    pub status: SearchStatus,
    /// How it ended: [`Stop::Finished`], or the budget's reason when the budget cut it short
    /// (its answer is then not to be trusted).
    pub stop: Stop,
    /// The critical circle; `None` when no centre gives a circle with a solution.
    pub circle: Option<C>,
    /// Its factor of safety.
    pub factor_of_safety: Option<f64>,
    /// The least F at each centre of the last grid.
    pub grid: FactorGrid,
    /// The last grid of centres.
    pub centres: CentreGrid,
    /// Circles evaluated (grid and refinement).
    pub evaluations: usize,
    /// Times the grid moved because the minimum lay on its edge.
    pub regrids: usize,
    /// Whether the minimum lies on the edge of the last grid (the true minimum may lie outside
    /// the region searched).
    pub is_on_edge: bool,
    /// Circles of the last grid that cut a sliding mass but have no physical solution.
    pub unsolved: usize,
    /// The least Bishop F among them (an indication of what they would give).
    pub unsolved_bishop_minimum: Option<f64>,
    /// Whether such circles lie at or next to the grid point of the minimum.
    pub unsolved_near_minimum: bool,
}

/// The circles of one centre: the least F there and its radius (0 where the family has one
/// circle a centre), how many cut a mass without a solution, and the least Bishop F of those.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct CentreResult {
    /// The least F and its radius.
    pub best: Option<(f64, f64)>,
    /// Circles without a solution.
    pub unsolved: usize,
    /// Their least Bishop F.
    pub bishop: Option<f64>,
}

/// A grid point the refinement starts from: its best radius and its indices (i along x, j
/// along y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Start {
    /// The radius of the centre's least F (0 where the family has one circle a centre).
    pub radius: f64,
    /// Index along x.
    pub i: usize,
    /// Index along y.
    pub j: usize,
}

/// A family of circles: how the circles of a centre are evaluated and refined, and what its
/// grid may do.
pub(crate) trait CircleFamily: Sync {
    /// The circle the search answers.
    type Circle;

    /// The budget every circle asks.
    fn budget(&self) -> &Budget;

    /// Grid points the refinement starts from.
    fn starts(&self) -> usize;

    /// The centres of one row of the grid (at `y`, along `xs`), in order.
    fn row(&self, xs: &[f64], y: f64) -> Vec<CentreResult>;

    /// The circles a grid counts as evaluated.
    fn grid_evaluations(&self, xs: &[f64], ys: &[f64]) -> usize;

    /// The refinement from each start over the grid `centres` (F at its points in `factors`).
    fn refine(&self, centres: &CentreGrid, starts: &[Start], factors: &FactorGrid) -> Vec<Minimum>;

    /// Whether a refined minimum may answer, against the grid's least F `f0`.
    fn accepts(&self, refined: &Minimum, f0: f64) -> bool;

    /// The search's point of grid point `start` (what a refinement's point is).
    fn grid_point(&self, factors: &FactorGrid, start: Start) -> Vec<f64>;

    /// Whether the minimum — grid point `point` (i, j), refined point `v` — lies on the grid's
    /// edge.
    fn is_on_edge(&self, centres: &CentreGrid, point: (usize, usize), v: &[f64]) -> bool;

    /// Whether the grid may move a `regrids`-th time.
    fn may_move(&self, regrids: usize) -> bool;

    /// The grid moved to the point `v`.
    fn moved(&self, centres: &CentreGrid, v: &[f64]) -> CentreGrid;

    /// The circle of a point of the search.
    fn circle(&self, v: &[f64]) -> Self::Circle;
}

/// Searches the critical circle of `family` from the grid `centres` (moving it when the minimum
/// is on its edge and the family allows), within the family's budget: circles not evaluated
/// by its end count as invalid and the answer's stop says so.
pub(crate) fn search<F: CircleFamily>(family: &F, centres: CentreGrid) -> CircleSearch<F::Circle> {
    let budget = family.budget();
    let mut centres = centres;
    let mut evaluations = 0;
    let mut regrids = 0;
    loop {
        let (xs, ys) = (centres.xs(), centres.ys());
        let results: Vec<Vec<CentreResult>> = ys.par_iter().map(|&y| family.row(&xs, y)).collect();
        evaluations += family.grid_evaluations(&xs, &ys);
        let summary = summarise(&results, xs, ys);
        let Some(&(f0, r0, bi, bj)) = summary.points.first() else {
            return CircleSearch {
                status: SearchStatus::NoValidCircle,
                stop: budget.stop(),
                circle: None,
                factor_of_safety: None,
                grid: summary.grid,
                centres,
                evaluations,
                regrids,
                is_on_edge: false,
                unsolved: summary.unsolved,
                unsolved_bishop_minimum: summary.unsolved_bishop_minimum,
                unsolved_near_minimum: false,
            };
        };
        let starts = distinct_starts(&summary.points, family.starts());
        let refined = family.refine(&centres, &starts, &summary.grid);
        evaluations += refined.iter().map(|r| r.evaluations).sum::<usize>();
        let best = Start {
            radius: r0,
            i: bi,
            j: bj,
        };
        let (f, v) = refined
            .into_iter()
            .filter(|r| family.accepts(r, f0))
            .min_by(|a, b| a.value.total_cmp(&b.value))
            .map_or_else(
                || (f0, family.grid_point(&summary.grid, best)),
                |r| (r.value, r.point),
            );
        let on_edge = family.is_on_edge(&centres, (bi, bj), &v);
        if on_edge && family.may_move(regrids) && !budget.is_spent() {
            centres = family.moved(&centres, &v);
            regrids += 1;
            continue;
        }
        return CircleSearch {
            status: SearchStatus::Found,
            stop: budget.stop(),
            circle: Some(family.circle(&v)),
            factor_of_safety: Some(f),
            unsolved_near_minimum: is_unsolved_near(&results, (bi, bj)),
            grid: summary.grid,
            centres,
            evaluations,
            regrids,
            is_on_edge: on_edge,
            unsolved: summary.unsolved,
            unsolved_bishop_minimum: summary.unsolved_bishop_minimum,
        };
    }
}

/// A grid's results summed up.
struct GridSummary {
    /// F over the centres.
    grid: FactorGrid,
    /// Circles that cut a mass without a solution.
    unsolved: usize,
    /// The least Bishop F among them.
    unsolved_bishop_minimum: Option<f64>,
    /// The centres that have an F, least first (the first of equal ones): (F, R, i, j).
    points: Vec<(f64, f64, usize, usize)>,
}

/// A grid's results summed up: F over the centres, the unsolved circles, the least Bishop F
/// among them, and the centres that have an F, least first.
fn summarise(results: &[Vec<CentreResult>], xs: Vec<f64>, ys: Vec<f64>) -> GridSummary {
    let unsolved: usize = results.iter().flatten().map(|r| r.unsolved).sum();
    let unsolved_bishop_minimum = results
        .iter()
        .flatten()
        .filter_map(|r| r.bishop)
        .reduce(f64::min);
    let grid = FactorGrid {
        xs,
        ys,
        factors: results
            .iter()
            .map(|row| row.iter().map(|r| r.best.map(|b| b.0)).collect())
            .collect(),
    };
    let mut points: Vec<(f64, f64, usize, usize)> = results
        .iter()
        .enumerate()
        .flat_map(|(j, row)| {
            row.iter()
                .enumerate()
                .filter_map(move |(i, r)| r.best.map(|(f, radius)| (f, radius, i, j)))
        })
        .collect();
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    GridSummary {
        grid,
        unsolved,
        unsolved_bishop_minimum,
        points,
    }
}

/// Whether unsolved circles lie at grid point (i, j) or next to it.
fn is_unsolved_near(results: &[Vec<CentreResult>], (i, j): (usize, usize)) -> bool {
    let rows = j.saturating_sub(1)..=(j + 1).min(results.len().saturating_sub(1));
    rows.into_iter().any(|jj| {
        let row = &results[jj];
        (i.saturating_sub(1)..=(i + 1).min(row.len().saturating_sub(1)))
            .any(|ii| row[ii].unsolved > 0)
    })
}

/// Up to `count` grid points from `points` (sorted by F), no two of them neighbours.
fn distinct_starts(points: &[(f64, f64, usize, usize)], count: usize) -> Vec<Start> {
    let mut starts: Vec<Start> = Vec::new();
    for &(_, radius, i, j) in points {
        if starts.len() >= count {
            break;
        }
        if starts
            .iter()
            .all(|s| s.i.abs_diff(i) > 1 || s.j.abs_diff(j) > 1)
        {
            starts.push(Start { radius, i, j });
        }
    }
    starts
}
