//! The search stages of a slope analysis: the simple slope's critical circle, and a section's
//! critical circle followed by the non-circular stage when planned. Each answers the surface
//! found (rebuilt at the plan's slices) with its report, or the stop that left it without one.

use super::report::SearchReport;
use super::search_plan::{Candidates, Noncircular, SectionSearch};
use super::surface::Analysed;
use crate::budget::{Budget, Stop};
use crate::slope::search::{
    search_critical_circle, SearchGrid, SearchProblem, SearchSettings, SearchStatus,
};
use crate::slope::section::noncircular::{search_noncircular, NoncircularLimits};
use crate::slope::section::search::{search_circles, CircleSearchSettings};
use crate::slope::section::{Polyline, SectionProblem, SlipShape};
use crate::slope::spencer::methods::{InterSliceFunction, Method};
use crate::slope::spencer::{solve_spencer, SpencerSettings};
use crate::slope::{SlopeError, SlopeParameter};

/// With automatic search bounds, circles beyond this many times the embankment's larger
/// dimension are not candidates (a radius that dwarfs it is a plane, not a slip circle of it).
const MAX_RADIUS_OVER_SIZE: f64 = 50.0;

/// What a search stage gives: the surface found with its report, or why there is none.
pub(super) type Found = Result<(Analysed, SearchReport), Stop>;

/// The stop of a search that found nothing (or that the budget cut short): the budget's reason
/// when it is spent, else no candidate.
fn no_circle(budget: &Budget) -> Stop {
    budget.check().err().unwrap_or(Stop::NoCandidate)
}

/// The simple slope's critical circle over `grid` (`hard_bounds`: whether its bounds were
/// given, and stay put), ranked by Spencer's F or `method`'s.
pub(super) fn simple(
    problem: &SearchProblem,
    grid: SearchGrid,
    hard_bounds: bool,
    spencer: &SpencerSettings,
    candidates: Candidates,
    method: Option<(Method, &InterSliceFunction)>,
    budget: &Budget,
) -> Result<Found, SlopeError> {
    let size = problem.embankment.height().max(problem.embankment.length());
    let settings = SearchSettings {
        spencer: *spencer,
        hard_bounds,
        // Automatic bounds may move; not to circles that dwarf the embankment.
        max_radius: (!hard_bounds).then_some(MAX_RADIUS_OVER_SIZE * size),
        min_depth: candidates.min_depth,
        method,
        ..SearchSettings::default()
    };
    let found = search_critical_circle(problem, grid, &settings, budget);
    let circle = match (found.status, found.stop, found.circle) {
        (SearchStatus::Found, Stop::Finished, Some(circle)) => circle,
        _ => return Ok(Err(no_circle(budget))),
    };
    // The grid's circles start at the lower end of F_e as given (the refinement may move F_e
    // within lower_end_factor_max; the grid does not).
    let grid_lower_end = (
        -problem.lower_end_factor * problem.embankment.height() + 0.0,
        0.0,
    );
    let answered = problem.at(circle)?;
    let report = SearchReport {
        candidates,
        ..SearchReport::of_simple(&found, hard_bounds, grid_lower_end)
    };
    Ok(Ok((Analysed::Section(Box::new(answered)), report)))
}

/// A section's critical circle (ranked by Spencer's F or `method`'s), then the non-circular
/// stage from it when planned. A section whose ground rises to the left has its circles
/// searched seen from behind and the circle found turned back, so that a section and its mirror
/// image are searched in one frame and find the same circle, bit for bit (model §4.4): the
/// grid and the refinement's simplex are not symmetric in x. (The non-circular stage runs in
/// the section's own frame: seen from behind, its moves reach roots next to a pole of m_α on
/// some published sections that the rule for roots does not yet reject.)
pub(super) fn section(
    plan: &SectionSearch,
    spencer: &SpencerSettings,
    candidates: Candidates,
    method: Option<(Method, &InterSliceFunction)>,
    budget: &Budget,
) -> Result<Found, SlopeError> {
    let found = if plan.section.rises_to_the_left() {
        let seen = plan.mirrored();
        critical_circle(&seen, spencer, candidates, method, budget)?.map(|mut circle| {
            circle.centre.0 = -circle.centre.0;
            circle.report.grid = circle.report.grid.mirrored();
            circle
        })
    } else {
        critical_circle(plan, spencer, candidates, method, budget)?
    };
    let Circle {
        centre,
        radius,
        factor_of_safety,
        mut report,
    } = match found {
        Ok(circle) => circle,
        Err(stop) => return Ok(Err(stop)),
    };
    let shape = SlipShape::Circle { centre, radius };
    let mut problem =
        SectionProblem::new(plan.section.clone(), shape, plan.slices, plan.seismic, None)?;
    if let Some(noncircular) = plan.noncircular {
        let stage = NoncircularStage {
            plan,
            noncircular,
            spencer,
            candidates,
            circle_factor: factor_of_safety,
        };
        problem = stage.run(problem, &mut report, budget)?;
    }
    Ok(Ok((Analysed::Section(Box::new(problem)), report)))
}

/// A critical circle found, with the search's report.
struct Circle {
    centre: (f64, f64),
    radius: f64,
    /// Its F, the search's own at the plan's slices.
    factor_of_safety: Option<f64>,
    report: SearchReport,
}

/// A section's critical circle in its own frame.
fn critical_circle(
    plan: &SectionSearch,
    spencer: &SpencerSettings,
    candidates: Candidates,
    method: Option<(Method, &InterSliceFunction)>,
    budget: &Budget,
) -> Result<Result<Circle, Stop>, SlopeError> {
    let settings = CircleSearchSettings {
        spencer: *spencer,
        min_depth: candidates.min_depth,
        circles_only: candidates.circles_only,
        beyond_ground: candidates.beyond_ground,
        method,
        ..CircleSearchSettings::default()
    };
    let (section, region) = (&plan.section, &plan.region);
    let found = search_circles(
        section,
        region,
        plan.hard,
        plan.slices,
        plan.seismic,
        &settings,
        budget,
    );
    let (centre, radius) = match (found.status, found.stop, found.circle) {
        (SearchStatus::Found, Stop::Finished, Some(circle)) => circle,
        _ => return Ok(Err(no_circle(budget))),
    };
    let report = SearchReport {
        candidates,
        ..SearchReport::of_section(&found, plan.hard)
    };
    Ok(Ok(Circle {
        centre,
        radius,
        factor_of_safety: found.factor_of_safety,
        report,
    }))
}

/// The non-circular stage of a section's search, from its critical circle.
struct NoncircularStage<'a> {
    plan: &'a SectionSearch,
    noncircular: Noncircular,
    spencer: &'a SpencerSettings,
    candidates: Candidates,
    /// The circle's F, the search's own at the plan's slices.
    circle_factor: Option<f64>,
}

impl NoncircularStage<'_> {
    /// The polyline found from the circle's `problem` where its F is lower (never above the
    /// best circle: its resampling of the circle starts a little above it, and a short budget
    /// may end the stage there), else the circle; the stage's work added to `report`.
    fn run(
        &self,
        problem: SectionProblem,
        report: &mut SearchReport,
        budget: &Budget,
    ) -> Result<SectionProblem, SlopeError> {
        let (plan, candidates) = (self.plan, self.candidates);
        let stage_budget = budget.narrowed(self.noncircular.budget);
        let better = search_noncircular(
            problem.section(),
            &problem.surface(),
            NoncircularLimits {
                vertices: self.noncircular.vertices,
                max_evaluations: self.noncircular.max_evaluations,
                min_depth: candidates.min_depth,
                beyond_ground: candidates.beyond_ground,
            },
            plan.slices,
            plan.seismic,
            self.spencer,
            &stage_budget,
        );
        let Some(better) = better else {
            return Ok(problem);
        };
        let line = Polyline::new(better.surface.clone()).map_err(|e| SlopeError::Conflict {
            parameter: SlopeParameter::Search,
            reason: e.to_string(),
        })?;
        let polyline = SectionProblem::new(
            problem.section().clone(),
            SlipShape::Polyline(line),
            plan.slices,
            plan.seismic,
            None,
        )?;
        report.evaluations += better.evaluations;
        report.path = Some(better.path);
        report.path_ms = Some(better.path_ms);
        report.noncircular_stop = better.stop;
        let g = solve_spencer(polyline.model(), self.spencer).factor_of_safety;
        Ok(match (g, self.circle_factor) {
            (Some(g), Some(c)) if g < c => polyline,
            _ => problem,
        })
    }
}
