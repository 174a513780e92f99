//! `"search"` on the simple slope: the grid of centres relative to the lower end, validated
//! into the solver's simple search.

use std::num::NonZeroUsize;

use thrustline_solver::slope::analysis::Target;
use thrustline_solver::slope::{Embankment, SearchGrid, SearchProblem, Seismic, Soil};

use super::request::SearchDto;
use super::section::refuse_section_only;
use crate::error::ApiError;
use crate::limits::{GRID_POINTS, LOWER_END_FACTOR_MAX, MAX_GRID_SLICES, SEARCH_LOWER_END_FACTOR};
use crate::validation::{count_within, finite, within};

/// The simple slope's search of `search`, its bounds (automatic where left out) checked.
pub fn simple_search(
    search: &SearchDto,
    embankment: Embankment,
    soil: Soil,
    slices: NonZeroUsize,
    seismic: Seismic,
) -> Result<Target, ApiError> {
    refuse_section_only(search)?;
    let lower_end_factor = within(
        "search.lower_end_factor",
        search.lower_end_factor,
        SEARCH_LOWER_END_FACTOR,
    )?;
    let lower_end_factor_max = search
        .lower_end_factor_max
        .map(|m| within("search.lower_end_factor_max", m, LOWER_END_FACTOR_MAX))
        .transpose()?;
    let automatic = SearchGrid::automatic(&embankment, lower_end_factor);
    let nx = count_within("search.nx", search.nx, GRID_POINTS)?;
    let ny = count_within("search.ny", search.ny, GRID_POINTS)?;
    let cost = nx * ny * slices.get();
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
        embankment,
        slices,
        soil,
        seismic,
        lower_end_factor,
        lower_end_factor_max,
    };
    let hard = [search.x_min, search.x_max, search.y_min, search.y_max]
        .iter()
        .any(Option::is_some);
    Ok(Target::SimpleSearch {
        problem,
        grid,
        hard_bounds: hard,
    })
}
