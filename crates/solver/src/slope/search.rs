//! The simple slope's critical circle (Spencer 1967, §5 of the thesis): the circles through
//! the lower end of their slip surface, one for each centre, searched by the one circle search
//! ([`super::circles`]); when the lower end is searched too, the refinement moves it with the
//! centre.
//!
//! Centres are measured from the lower end of the slip surface, as in [`super::geometry`].
//! Grid points whose circle cuts no slip mass, or whose equations have no solution, have no F.

use std::cell::Cell;
use std::num::NonZeroUsize;

use rayon::prelude::*;

use super::circles::{search, CentreGrid, CentreResult, CircleFamily, Start, F_RESOLUTION};
pub use super::circles::{CircleSearch, FactorGrid, SearchStatus};
use super::error::SlopeError;
use super::geometry::{Embankment, SlipCircle};
use crate::budget::{Budget, Stop};
use crate::numerics::{nelder_mead_to, Minimum};

use super::section::trial::{circle_outcome, TrialSetup};
use super::section::{check_circle, Section, SectionProblem, SlipShape};
use super::spencer::methods::{InterSliceFunction, Method};
use super::spencer::{Seismic, Soil, SpencerSettings};

/// The region of centres searched and the grid laid over it (centres from the lower end).
pub type SearchGrid = CentreGrid;

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
pub struct SearchSettings<'a> {
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
    /// The method the circles are ranked by: Spencer's (`None`, the default) or another's, for
    /// its own critical circle.
    pub method: Option<(Method, &'a InterSliceFunction)>,
}

impl Default for SearchSettings<'_> {
    fn default() -> Self {
        Self {
            spencer: SpencerSettings::default(),
            starts: 3,
            max_regrids: 4,
            max_refine_evaluations: 300,
            hard_bounds: false,
            max_radius: None,
            min_depth: 0.0,
            method: None,
        }
    }
}

/// The critical circle found.
pub type SearchSolution = CircleSearch<SlipCircle>;

/// Spencer's F for one circle, or `None` when the circle is invalid or has no solution.
pub fn factor_of_safety(
    problem: &SearchProblem,
    circle: SlipCircle,
    settings: &SpencerSettings,
) -> Option<f64> {
    let section = problem.section().ok()?;
    let mirror = section.mirrored();
    let trials = TrialSetup {
        section: &section,
        mirror: &mirror,
        slices: problem.slices,
        seismic: problem.seismic,
        spencer: settings,
        min_depth: 0.0,
        beyond_ground: true,
        method: None,
    };
    outcome(problem, &trials, circle, &Cell::new(None)).ok()
}

/// Spencer's F for one circle of `problem` tried as `trials` says (on the embankment as a
/// section and seen from behind, built once per search); `Err(None)` when it cuts no mass,
/// `Err(Some(bishop))` when it has no physical solution (with Bishop's F there, if any).
/// Bishop's F, Spencer's start, is looked for from `near` first, the last F found (a
/// neighbouring circle's), which a solved circle replaces.
fn outcome(
    problem: &SearchProblem,
    trials: &TrialSetup<'_>,
    circle: SlipCircle,
    near: &Cell<Option<f64>>,
) -> Result<f64, Option<Option<f64>>> {
    let Ok(SlipShape::Circle { centre, radius }) = circle.placed(problem.embankment.height())
    else {
        return Err(None);
    };
    // A circle beyond what a section takes cuts no mass of it.
    check_circle(centre, radius).map_err(|_| None::<Option<f64>>)?;
    circle_outcome(trials, centre, radius, near.get()).map(|s| {
        near.set(Some(s.factor_of_safety));
        s.factor_of_safety
    })
}

/// Whether the circle's radius is within the limit.
fn within_reach(circle: SlipCircle, max_radius: Option<f64>) -> bool {
    // (x² + y²) against m² rather than hypot: this is asked of every circle of a grid.
    max_radius.is_none_or(|m| circle.x * circle.x + circle.y * circle.y <= m * m)
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
    family: &ThroughLowerEnd,
    grid: &SearchGrid,
    factors: &FactorGrid,
    start: Start,
) -> Minimum {
    let ThroughLowerEnd {
        problem,
        ref trials,
        settings,
        budget,
    } = *family;
    let (i, j) = (start.i, start.j);
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
        outcome(problem, trials, circle_at(v), &near).unwrap_or(f64::INFINITY)
    };
    // Centres first, at the grid's lower-end factor…
    let start = [factors.xs[i], factors.ys[j]];
    let centres = nelder_mead_to(
        objective,
        &start,
        &[0.5 * dx, 0.5 * dy],
        1e-9 * scale,
        F_RESOLUTION,
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
                1e-9 * scale,
                F_RESOLUTION,
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

/// The simple slope's circles: through the lower end of their slip surface, one for each centre
/// (measured from there), the lower end moved by the refinement when it is searched too.
struct ThroughLowerEnd<'a> {
    problem: &'a SearchProblem,
    /// How each circle is tried: on the embankment as a section and seen from behind (built
    /// once), with the problem's slices and seismic coefficients and the settings' Spencer
    /// settings and least depth.
    trials: TrialSetup<'a>,
    settings: &'a SearchSettings<'a>,
    budget: &'a Budget,
}

impl CircleFamily for ThroughLowerEnd<'_> {
    type Circle = SlipCircle;

    fn budget(&self) -> &Budget {
        self.budget
    }

    fn starts(&self) -> usize {
        self.settings.starts
    }

    fn row(&self, xs: &[f64], y: f64) -> Vec<CentreResult> {
        // Each circle's F starts the next one's search for Bishop's F along the row.
        let near = Cell::new(None);
        xs.iter()
            .map(|&x| {
                if self.budget.is_spent() {
                    return CentreResult::default();
                }
                let circle = SlipCircle {
                    x,
                    y,
                    lower_end_factor: self.problem.lower_end_factor,
                };
                if !within_reach(circle, self.settings.max_radius) {
                    return CentreResult::default();
                }
                match outcome(self.problem, &self.trials, circle, &near) {
                    Ok(f) => CentreResult {
                        best: Some((f, 0.0)),
                        ..CentreResult::default()
                    },
                    Err(None) => CentreResult::default(),
                    Err(Some(bishop)) => CentreResult {
                        best: None,
                        unsolved: 1,
                        bishop,
                    },
                }
            })
            .collect()
    }

    fn grid_evaluations(&self, xs: &[f64], ys: &[f64]) -> usize {
        // Every centre counts, evaluated or not (the budget, the radius limit).
        xs.len() * ys.len()
    }

    fn refine(&self, grid: &SearchGrid, starts: &[Start], factors: &FactorGrid) -> Vec<Minimum> {
        starts
            .par_iter()
            .map(|&start| refine_from(self, grid, factors, start))
            .collect()
    }

    fn accepts(&self, refined: &Minimum, _f0: f64) -> bool {
        refined.value.is_finite()
    }

    fn grid_point(&self, factors: &FactorGrid, start: Start) -> Vec<f64> {
        vec![factors.xs[start.i], factors.ys[start.j]]
    }

    fn is_on_edge(&self, grid: &SearchGrid, (i, j): (usize, usize), v: &[f64]) -> bool {
        grid.is_edge_point((i, j)) || grid.is_outside(v)
    }

    fn may_move(&self, regrids: usize) -> bool {
        !self.settings.hard_bounds && regrids < self.settings.max_regrids
    }

    fn moved(&self, grid: &SearchGrid, v: &[f64]) -> SearchGrid {
        recentred(*grid, v)
    }

    fn circle(&self, v: &[f64]) -> SlipCircle {
        SlipCircle {
            x: v[0],
            y: v[1],
            lower_end_factor: v.get(2).copied().unwrap_or(self.problem.lower_end_factor),
        }
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
        centres: *grid,
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
    let family = ThroughLowerEnd {
        problem,
        trials: TrialSetup {
            section: &section,
            mirror: &mirror,
            slices: problem.slices,
            seismic: problem.seismic,
            spencer: &settings.spencer,
            min_depth: settings.min_depth,
            // The embankment's ground runs on level beyond what any circle reaches.
            beyond_ground: true,
            method: settings.method,
        },
        settings,
        budget,
    };
    search(&family, grid)
}
