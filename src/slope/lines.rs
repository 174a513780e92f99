//! Polylines as clients state them: points [x, y] read into the solver's [`Polyline`], each
//! failure naming its field.

use thrustline_solver::slope::section::Polyline;

use super::options::Coordinates;
use crate::error::ApiError;
use crate::limits::{MAX_POLYLINE_POINTS, POLYLINE_POINTS};
use crate::validation::count_within;

/// A polyline from its points, at `field`.
pub fn polyline(field: &str, points: &[Coordinates]) -> Result<Polyline, ApiError> {
    count_within(field, points.len(), POLYLINE_POINTS).map_err(|_| {
        ApiError::invalid(
            field,
            format!(
                "{} points is out of range: allowed is 1 to {MAX_POLYLINE_POINTS} points [x, y]",
                points.len()
            ),
        )
    })?;
    Polyline::from_input(points.iter().map(|p| (p[0], p[1])).collect()).map_err(|e| {
        use thrustline_solver::slope::section::PolylineError;
        let at = match e {
            PolylineError::Empty => field.to_owned(),
            PolylineError::NotFinite { index }
            | PolylineError::NotIncreasing { index }
            | PolylineError::TooClose { index } => {
                format!("{field}[{index}]")
            }
        };
        ApiError::invalid(at, e.to_string())
    })
}
