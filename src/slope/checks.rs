//! Rules of a Spencer request that join several fields: how the slices are refined, and which
//! one slip surface (or search) is asked for.

use super::request::SpencerRequest;
use crate::error::ApiError;
use crate::limits::{RELATIVE_ERROR, SLICE_TOLERANCE};
use crate::validation::within;

/// `slice_tolerance` and `accuracy.relative_error`: at most one, and neither with loads given
/// per slice (`per_slice_loads`), which fix the slices.
pub fn refinement(
    request: &SpencerRequest,
    per_slice_loads: bool,
) -> Result<(Option<f64>, Option<f64>), ApiError> {
    let slice_tolerance = request
        .slice_tolerance
        .map(|t| within("slice_tolerance", t, SLICE_TOLERANCE))
        .transpose()?;
    if slice_tolerance.is_some() && per_slice_loads {
        return Err(ApiError::invalid(
            "slice_tolerance",
            "cannot be combined with external_loads: loads are given per slice, and refining \
             changes the slices",
        ));
    }
    let relative_error = request
        .accuracy
        .as_ref()
        .map(|a| within("accuracy.relative_error", a.relative_error, RELATIVE_ERROR))
        .transpose()?;
    if relative_error.is_some() && slice_tolerance.is_some() {
        return Err(ApiError::invalid(
            "accuracy",
            "give one of slice_tolerance (a change of F between doublings) and \
             accuracy.relative_error (an estimated error), not both",
        ));
    }
    if relative_error.is_some() && per_slice_loads {
        return Err(ApiError::invalid(
            "accuracy",
            "cannot be combined with external_loads: loads are given per slice, and the \
             slices change",
        ));
    }
    Ok((slice_tolerance, relative_error))
}

/// At most one of `circle`, `surface` and `search`; `moment_centre` with a surface only.
pub fn one_surface(request: &SpencerRequest) -> Result<(), ApiError> {
    let given = [
        request.circle.is_some(),
        request.surface.is_some(),
        request.search.is_some(),
    ];
    if given.iter().filter(|g| **g).count() > 1 {
        return Err(ApiError::invalid(
            if request.search.is_some() {
                "search"
            } else {
                "surface"
            },
            "give one of circle, surface and search",
        ));
    }
    if request.moment_centre.is_some() && request.surface.is_none() {
        return Err(ApiError::invalid(
            "moment_centre",
            "is for a polyline surface only (a circle uses its centre)",
        ));
    }
    Ok(())
}
