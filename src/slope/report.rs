//! How a search went, from the simple slope's search or a section's: what the response and the
//! drawing read of it.

use thrustline_solver::slope::section::search::CircleSearch;
use thrustline_solver::slope::{FactorGrid, SearchSolution};

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
    /// Whether the grid's coordinates are absolute (a section) rather than from the lower end.
    pub absolute: bool,
    /// Circles that cut a mass but had no solution (sections; the simple search does not
    /// tell them from circles that cut none).
    pub unsolved: Option<usize>,
    /// Whether unsolved circles lie at or next to the grid centre of the minimum.
    pub unsolved_near_minimum: bool,
}

impl From<&SearchSolution> for SearchReport {
    fn from(s: &SearchSolution) -> Self {
        Self {
            evaluations: s.evaluations,
            regrids: s.regrids,
            is_on_edge: s.is_on_edge,
            hard: false,
            grid: s.grid.clone(),
            absolute: false,
            unsolved: None,
            unsolved_near_minimum: false,
        }
    }
}

impl SearchReport {
    /// The report of a section's search with given (`hard`) or automatic bounds.
    pub fn of_section(s: &CircleSearch, hard: bool) -> Self {
        Self {
            evaluations: s.evaluations,
            regrids: s.regrids,
            is_on_edge: s.is_on_edge,
            hard,
            grid: s.grid.clone(),
            absolute: true,
            unsolved: Some(s.unsolved),
            unsolved_near_minimum: s.unsolved_near_minimum,
        }
    }
}
