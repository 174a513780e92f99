//! The one validation of a Spencer request: JSON values → the solver's typed inputs. Every range
//! the API states is checked here (naming the field); what the solver's own constructors check
//! (a circle that cuts no slip mass, a soil without strength) comes back from them as a typed
//! parameter that [`crate::fields`] names.

use std::num::NonZeroUsize;

use thrustline_solver::slope::{
    Embankment, ExternalLoad, SearchGrid, SearchProblem, Seismic, SlipCircle, SlopeProblem, Soil,
};

use super::request::{CircleDto, SearchDto, SpencerRequest};
use crate::error::ApiError;
use crate::limits::{
    MAX_EXTERNAL_LOADS, MAX_FORCE, MAX_GRID, MAX_GRID_SLICES, MAX_LENGTH, MAX_MAGNITUDE,
    MAX_SLICES, MIN_LENGTH, SLICE_TOLERANCE,
};
use crate::validation::{count, finite, number};

/// A validated Spencer request, ready for the solver.
#[derive(Debug, Clone)]
pub struct SpencerInput {
    /// One circle, or a search for the critical one.
    pub target: Target,
    /// With a slice tolerance: refine the slices until F settles within it.
    pub slice_tolerance: Option<f64>,
    /// Whether to compute Spencer's curves F_f(θ), F_m(θ).
    pub curves: bool,
}

/// One circle, or a search.
#[derive(Debug, Clone)]
pub enum Target {
    /// The circle to analyse.
    Circle(SlopeProblem),
    /// The grid to search and everything but the circle.
    Search(SearchGrid, SearchProblem),
}

/// The validated parts of a request that do not depend on the circle.
struct Parts {
    embankment: Embankment,
    slices: NonZeroUsize,
    soil: Soil,
    seismic: Seismic,
    external_loads: Vec<ExternalLoad>,
}

impl SpencerRequest {
    /// Validates the request into the solver's input.
    pub fn validate(&self) -> Result<SpencerInput, ApiError> {
        let parts = self.parts()?;
        let slice_tolerance = self
            .slice_tolerance
            .map(|t| {
                number(
                    "slice_tolerance",
                    t,
                    SLICE_TOLERANCE.0,
                    false,
                    SLICE_TOLERANCE.1,
                )
            })
            .transpose()?;
        if slice_tolerance.is_some() && !parts.external_loads.is_empty() {
            return Err(ApiError::invalid(
                "slice_tolerance",
                "cannot be combined with external_loads: loads are given per slice, and refining \
                 changes the slices",
            ));
        }
        let target = match (&self.circle, &self.search) {
            (Some(circle), None) => Target::Circle(SlopeProblem::new(
                parts.embankment,
                circle_from(circle),
                parts.slices,
                parts.soil,
                parts.seismic,
                parts.external_loads,
            )?),
            (None, Some(search)) => {
                if !parts.external_loads.is_empty() {
                    return Err(ApiError::invalid(
                        "external_loads",
                        "cannot be combined with search: loads are given per slice, and the \
                         slices change from circle to circle",
                    ));
                }
                search_from(search, &parts)?
            }
            (Some(_), Some(_)) => {
                return Err(ApiError::invalid(
                    "search",
                    "give either circle or search, not both",
                ))
            }
            (None, None) => {
                return Err(ApiError::invalid(
                    "circle",
                    "give a circle to analyse, or search ({} for automatic bounds) for the \
                     critical one",
                ))
            }
        };
        Ok(SpencerInput {
            target,
            slice_tolerance,
            curves: self.curves,
        })
    }

    /// Validates everything but the circle or search.
    fn parts(&self) -> Result<Parts, ApiError> {
        let length = |field: &str, value: f64| number(field, value, MIN_LENGTH, false, MAX_LENGTH);
        let height = length("slope.height", self.slope.height)?;
        let slope_length = length("slope.length", self.slope.length)?;
        let slices = count("slices", self.slices, 1, MAX_SLICES)?;
        let soil = &self.soil;
        number(
            "soil.unit_weight",
            soil.unit_weight,
            0.0,
            true,
            MAX_MAGNITUDE,
        )?;
        number("soil.cohesion", soil.cohesion, 0.0, false, MAX_MAGNITUDE)?;
        // The friction angle, the pore pressure ratio and the lower bounds are Soil::new's.
        let soil = Soil::new(
            soil.unit_weight,
            soil.cohesion,
            soil.friction_angle_deg,
            soil.pore_pressure_ratio,
        )?;
        let seismic = match &self.seismic {
            Some(s) => Seismic::new(s.kh, s.kv)?,
            None => Seismic::default(),
        };
        count(
            "external_loads",
            self.external_loads.len(),
            0,
            MAX_EXTERNAL_LOADS,
        )?;
        let external_loads = self
            .external_loads
            .iter()
            .enumerate()
            .map(|(i, load)| {
                let field = |name: &str| format!("external_loads[{i}].{name}");
                let force =
                    |name: &str, v: f64| number(&field(name), v, -MAX_FORCE, false, MAX_FORCE);
                Ok(ExternalLoad {
                    slice: count(&field("slice"), load.slice, 1, slices)? - 1,
                    fx: force("fx", load.fx)?,
                    fy: force("fy", load.fy)?,
                    moment: force("moment", load.moment)?,
                })
            })
            .collect::<Result<Vec<_>, ApiError>>()?;
        let embankment = Embankment::new(height, slope_length)?;
        let slices = NonZeroUsize::new(slices)
            .ok_or_else(|| ApiError::invalid("slices", "must be at least 1"))?;
        Ok(Parts {
            embankment,
            slices,
            soil,
            seismic,
            external_loads,
        })
    }
}

/// The circle as given: its ranges (finite X, Y > 0, F_e ≥ 0) are `SlopeGeometry::new`'s checks.
fn circle_from(circle: &CircleDto) -> SlipCircle {
    SlipCircle {
        x: circle.x,
        y: circle.y,
        lower_end_factor: circle.lower_end_factor,
    }
}

fn search_from(search: &SearchDto, parts: &Parts) -> Result<Target, ApiError> {
    let lower_end_factor = number(
        "search.lower_end_factor",
        search.lower_end_factor,
        0.0,
        false,
        100.0,
    )?;
    let lower_end_factor_max = search
        .lower_end_factor_max
        .map(|m| number("search.lower_end_factor_max", m, 0.0, true, 100.0))
        .transpose()?;
    let automatic = SearchGrid::automatic(&parts.embankment, lower_end_factor);
    let nx = count("search.nx", search.nx, 2, MAX_GRID)?;
    let ny = count("search.ny", search.ny, 2, MAX_GRID)?;
    let cost = nx * ny * parts.slices.get();
    if cost > MAX_GRID_SLICES {
        return Err(ApiError::invalid(
            "search",
            format!(
                "nx·ny·slices = {cost} is out of range: allowed is at most {MAX_GRID_SLICES} \
                 (fewer grid points or slices)"
            ),
        ));
    }
    let bound = |field: &str, value: Option<f64>, default: f64| {
        value.map_or(Ok(default), |v| finite(field, v))
    };
    let grid = SearchGrid {
        x_min: bound("search.x_min", search.x_min, automatic.x_min)?,
        x_max: bound("search.x_max", search.x_max, automatic.x_max)?,
        y_min: bound("search.y_min", search.y_min, automatic.y_min)?,
        y_max: bound("search.y_max", search.y_max, automatic.y_max)?,
        nx,
        ny,
    };
    if grid.x_max <= grid.x_min {
        return Err(ApiError::invalid(
            "search.x_max",
            "must be greater than search.x_min",
        ));
    }
    if grid.y_max <= grid.y_min {
        return Err(ApiError::invalid(
            "search.y_max",
            "must be greater than search.y_min",
        ));
    }
    if grid.y_max <= 0.0 {
        return Err(ApiError::invalid(
            "search.y_max",
            "must be > 0: centres lie above the lower end",
        ));
    }
    let problem = SearchProblem {
        embankment: parts.embankment,
        slices: parts.slices,
        soil: parts.soil,
        seismic: parts.seismic,
        lower_end_factor,
        lower_end_factor_max,
    };
    Ok(Target::Search(grid, problem))
}
