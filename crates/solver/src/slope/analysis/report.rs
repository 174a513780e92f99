//! What a slope analysis produced: the surface answered, its solution and the extras the plan
//! asked for, how a search went (the simple slope's or a section's) and how a refinement went.

use super::methods::{Method, MethodFactors};
use super::surface::Analysed;
use crate::budget::Stop;
use crate::slope::refinement::RefinementStep;
use crate::slope::search::{FactorGrid, SearchSolution};
use crate::slope::section::search::CircleSearch;
use crate::slope::spencer::{FactorCurves, SpencerSolution};

/// How a search went.
#[derive(Debug, Clone, PartialEq)]
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
    /// Where the grid's (0, 0) lies in the caller's coordinates: the lower end of the simple
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
    /// How the non-circular stage ended: [`Stop::Finished`] (or no such stage), or what ended
    /// it first — its time budget, the solve's, its evaluation cap — when its answer is the best
    /// found so far.
    pub noncircular_stop: Stop,
    /// What the search could answer.
    pub candidates: super::search_plan::Candidates,
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
            noncircular_stop: Stop::Finished,
            candidates: super::search_plan::Candidates::default(),
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
            noncircular_stop: Stop::Finished,
            candidates: super::search_plan::Candidates::default(),
        }
    }
}

/// How a refinement went: the steps, and whether F settled within the tolerance.
#[derive(Debug, Clone, PartialEq)]
pub struct Refinement {
    /// The relative tolerance asked for.
    pub tolerance: f64,
    /// F at each slice count.
    pub steps: Vec<RefinementStep>,
    /// Whether the last doubling changed F by less than the tolerance.
    pub is_settled: bool,
}

/// A slope answered: the surface analysed (or found), its solution and the extras planned.
#[derive(Debug, Clone)]
pub struct SlopeAnswer {
    /// The slip surface analysed, at the slice count answered.
    pub problem: Analysed,
    /// Its solution (its status says whether Spencer's equations have a root there).
    pub solution: SpencerSolution,
    /// With a search: how it went.
    pub search: Option<SearchReport>,
    /// With curves planned: F_f(θ) and F_m(θ).
    pub curves: Option<FactorCurves>,
    /// With methods planned: their factors on the answered slices.
    pub methods: Option<MethodFactors>,
    /// With `per_method`: each method's own critical surface, in the plan's order.
    pub critical: Vec<(Method, OwnCritical)>,
    /// With a slice tolerance: the refinement.
    pub refinement: Option<Refinement>,
    /// The estimated discretisation error of F at the slices answered.
    pub accuracy: crate::slope::accuracy::Accuracy,
    /// With a design check: its verdict on F.
    pub design: Option<crate::slope::design::Verdict>,
}

/// A method's own critical surface (`per_method`): searched with its F, answered with it.
#[derive(Debug, Clone)]
pub struct MethodCritical {
    /// The surface, at the plan's slices.
    pub problem: Analysed,
    /// The method's F on it.
    pub factor_of_safety: f64,
    /// The search that found it.
    pub report: SearchReport,
}

/// A method's own search: its critical surface, or `None` when no circle of the search has an
/// F by that method.
pub type OwnCritical = Option<MethodCritical>;

/// Which stage of a slope plan a stop ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlopeStage {
    /// The circular search.
    Search,
    /// The slice refinement.
    Refinement,
}

/// How a slope analysis ended: an answer, or the stage that stopped without one and why.
#[derive(Debug, Clone)]
pub enum SlopeOutcome {
    /// The plan ran to its end.
    Answered(Box<SlopeAnswer>),
    /// A stage ended without an answer ([`Stop::TimeLimit`], [`Stop::Cancelled`] or
    /// [`Stop::NoCandidate`]).
    Stopped {
        /// The stage.
        stage: SlopeStage,
        /// Why.
        stop: Stop,
    },
}

impl SlopeOutcome {
    /// How it ended: [`Stop::Finished`] for an answer.
    pub fn stop(&self) -> Stop {
        match self {
            Self::Answered(_) => Stop::Finished,
            Self::Stopped { stop, .. } => *stop,
        }
    }
}
