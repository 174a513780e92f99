//! The parts of the Spencer answer that its methods share with the headline: how a search went,
//! F over its grid of centres, Spencer's two curves, and the circle and points a surface is
//! stated by.

use serde::Serialize;
use thrustline_solver::slope::analysis::{Analysed, SearchReport};
use utoipa::ToSchema;

/// F over the grid of centres, for contour plots.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GridDto {
    /// Centre x of the grid columns (simple slope: from the lower end; section: absolute).
    pub xs: Vec<f64>,
    /// Centre y of the grid rows (simple slope: above the lower end; section: absolute).
    pub ys: Vec<f64>,
    /// `factor_of_safety[j][i]` at (xs[i], ys[j]), the least over the radii tried on a
    /// section; null where the centre gives no circle with a solution.
    pub factor_of_safety: Vec<Vec<Option<f64>>>,
    /// The columns' centre x in the request's coordinates (the simple slope: toe at the
    /// origin; a section: equal to `xs`).
    pub x_absolute: Vec<f64>,
    /// The rows' centre y in the request's coordinates.
    pub y_absolute: Vec<f64>,
}

/// How the search went.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SearchOutDto {
    /// Circles evaluated (grid and refinement).
    pub evaluations: usize,
    /// Times the grid moved because the minimum lay on its edge.
    pub regrids: usize,
    /// Whether the minimum still lies on the edge of the region searched.
    pub on_edge: bool,
    /// Circles of the last grid that cut a sliding mass but whose equations have no physical
    /// solution.
    pub unsolved: usize,
    /// The least Bishop F among those circles (null when none has one): when it is below the
    /// answer's F, the critical surface may hide among them (see `warnings`).
    #[schema(required = true)]
    pub unsolved_bishop_minimum: Option<f64>,
    /// Whether circles without a solution lie at or next to the grid centre of the minimum
    /// (the least F found may then not be the least F there is).
    pub unsolved_near_minimum: bool,
    /// The least depth below the ground a candidate surface had to reach (`search.min_depth`,
    /// by default 2 % of the height).
    pub min_depth: f64,
    /// Whether circles that would cross the bedrock were candidates (`follow_bedrock`) or not
    /// (`circles_only`).
    pub composite: super::options::CompositeDto,
    /// Whether surfaces could enter or leave the ground beyond the section's x-range
    /// (`search.beyond_ground`; always on the simple slope, whose ground runs on level).
    pub beyond_ground: bool,
    /// With `shape: noncircular`: whether a budget (`time_budget_ms`, `max_evaluations` or the
    /// time limit) ended the polyline search: its answer is the best found by then, never
    /// above the critical circle.
    pub budget_exhausted: bool,
    /// With `shape: noncircular`: the least F found so far, first on the critical circle's
    /// polyline, then each time a round of the polyline search lowered it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path: Option<Vec<f64>>,
    /// With `shape: noncircular`: when each F of `path` was reached, in milliseconds from the
    /// start of the polyline search (F against time: what a shorter `time_budget_ms` gives).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path_ms: Option<Vec<f64>>,
}

/// Spencer's figure: F from each equation alone against θ; they cross at the answer.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CurvesDto {
    /// Inclinations θ in degrees.
    pub theta_deg: Vec<f64>,
    /// F_f(θ), from force equilibrium; null where it has no root.
    pub force_factor: Vec<Option<f64>>,
    /// F_m(θ), from moment equilibrium; null where it has no root.
    pub moment_factor: Vec<Option<f64>>,
}

/// A point in the plane of the section.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PointDto {
    /// Horizontal coordinate (the simple slope: toe at 0, towards the crest positive; a
    /// section: its own coordinates).
    pub x: f64,
    /// Vertical coordinate (up positive).
    pub y: f64,
}

/// The slip circle as placed on the embankment.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CircleOutDto {
    /// Centre X measured from the lower end (as given).
    pub x: f64,
    /// Centre Y measured from the lower end (as given).
    pub y: f64,
    /// Radius.
    pub radius: f64,
    /// The centre in embankment coordinates (toe at the origin).
    pub centre: PointDto,
    /// Lower end of the slip surface.
    pub lower_end: PointDto,
    /// Upper exit of the slip surface on the ground.
    pub upper_exit: PointDto,
}

/// A point of the section.
pub(super) fn point((x, y): (f64, f64)) -> PointDto {
    PointDto { x, y }
}

/// The analysed circle, if the surface is one: its centre relative to the lower end, its ends.
pub(super) fn circle_out(problem: &Analysed) -> Option<CircleOutDto> {
    problem.circle().map(|c| CircleOutDto {
        x: c.centre.0 - c.lower_end.0,
        y: c.centre.1 - c.lower_end.1,
        radius: c.radius,
        centre: point(c.centre),
        lower_end: point(c.lower_end),
        upper_exit: point(c.upper_exit),
    })
}

/// How a search went, as answered.
pub(super) fn search_out(search: &SearchReport) -> SearchOutDto {
    SearchOutDto {
        evaluations: search.evaluations,
        regrids: search.regrids,
        on_edge: search.is_on_edge,
        unsolved: search.unsolved,
        unsolved_bishop_minimum: search.unsolved_bishop_minimum,
        unsolved_near_minimum: search.unsolved_near_minimum,
        min_depth: search.candidates.min_depth,
        composite: if search.candidates.circles_only {
            super::options::CompositeDto::CirclesOnly
        } else {
            super::options::CompositeDto::FollowBedrock
        },
        beyond_ground: search.candidates.beyond_ground,
        budget_exhausted: !search.noncircular_stop.is_finished(),
        path: search.path.clone(),
        path_ms: search.path_ms.clone(),
    }
}
