//! What a solve produced — the surface analysed, its solution and the extras asked for, and how
//! a search went (the simple slope's or a section's): what the response, the warnings and the
//! drawing read.

use thrustline_solver::slope::section::search::CircleSearch;
use thrustline_solver::slope::{
    FactorCurves, FactorGrid, RefinementStep, SearchSolution, SpencerSolution,
};

use super::analysed::Analysed;
use super::methods::MethodsDto;

/// How a search went.
#[derive(Debug, Clone)]
pub struct SearchReport {
    /// Circles evaluated.
    pub evaluations: usize,
    /// Times automatic bounds moved.
    pub regrids: usize,
    /// Whether the minimum lies on the edge of the region searched.
    pub is_on_edge: bool,
    /// Whether the bounds were given (and stayed put).
    pub hard: bool,
    /// F over the last grid of centres.
    pub grid: FactorGrid,
    /// Where the grid's (0, 0) lies in the request's coordinates: the lower end of the simple
    /// slope's circles, (0, 0) for a section (whose grid is absolute).
    pub origin: (f64, f64),
    /// Circles of the last grid that cut a mass but had no physical Spencer solution.
    pub unsolved: usize,
    /// The least Bishop F among them.
    pub unsolved_bishop_minimum: Option<f64>,
    /// Whether unsolved circles lie at or next to the grid centre of the minimum.
    pub unsolved_near_minimum: bool,
    /// A non-circular search's least F so far, the critical circle's polyline first, then each
    /// time a round lowered it.
    pub path: Option<Vec<f64>>,
    /// When each of `path` was reached, in milliseconds from the start of the polyline search.
    pub path_ms: Option<Vec<f64>>,
    /// Whether the time limit ended a non-circular search (its answer is the best so far).
    pub timed_out: bool,
}

impl SearchReport {
    /// The report of the simple slope's search with given (`hard`) or automatic bounds; the
    /// grid is relative to the lower end `lower_end` of its circles.
    pub fn of_simple(s: &SearchSolution, hard: bool, lower_end: (f64, f64)) -> Self {
        Self {
            evaluations: s.evaluations,
            regrids: s.regrids,
            is_on_edge: s.is_on_edge,
            hard,
            grid: s.grid.clone(),
            origin: lower_end,
            unsolved: s.unsolved,
            unsolved_bishop_minimum: s.unsolved_bishop_minimum,
            unsolved_near_minimum: s.unsolved_near_minimum,
            path: None,
            path_ms: None,
            timed_out: false,
        }
    }

    /// The report of a section's search with given (`hard`) or automatic bounds.
    pub fn of_section(s: &CircleSearch, hard: bool) -> Self {
        Self {
            evaluations: s.evaluations,
            regrids: s.regrids,
            is_on_edge: s.is_on_edge,
            hard,
            grid: s.grid.clone(),
            origin: (0.0, 0.0),
            unsolved: s.unsolved,
            unsolved_bishop_minimum: s.unsolved_bishop_minimum,
            unsolved_near_minimum: s.unsolved_near_minimum,
            path: None,
            path_ms: None,
            timed_out: false,
        }
    }
}

/// How a refinement went: the steps, and whether F settled within the tolerance.
#[derive(Debug, Clone)]
pub struct Refinement {
    /// The relative tolerance asked for.
    pub tolerance: f64,
    /// F at each slice count.
    pub steps: Vec<RefinementStep>,
    /// Whether the last doubling changed F by less than the tolerance.
    pub is_settled: bool,
}

/// A solved Spencer request: the circle analysed (or found), its solution and the extras asked
/// for.
#[derive(Debug, Clone)]
pub struct SolvedSlope {
    /// The slip surface analysed, at the slice count answered.
    pub problem: Analysed,
    /// Its solution.
    pub solution: SpencerSolution,
    /// With `search`: how the search went.
    pub search: Option<SearchReport>,
    /// With `curves`: F_f(θ) and F_m(θ).
    pub curves: Option<FactorCurves>,
    /// With `methods`: the other methods' answers.
    pub methods: Option<MethodsDto>,
    /// With `slice_tolerance`: the refinement.
    pub refinement: Option<Refinement>,
    /// Wall time of the solve in milliseconds.
    pub solve_time_ms: f64,
}
