//! Range checks applied to a request once, at the edge, before anything reaches the solver.
//! Each failure names the field by its dotted path in the body and states the allowed range.

use crate::error::ApiError;
use crate::limits::{Count, Range};

/// A finite number in `[min, max]`; `min_open` excludes `min` itself.
pub fn number(
    field: &str,
    value: f64,
    min: f64,
    min_open: bool,
    max: f64,
) -> Result<f64, ApiError> {
    let above = if min_open { value > min } else { value >= min };
    if value.is_finite() && above && value <= max {
        return Ok(value);
    }
    let lower = match (min_open, min == f64::MIN) {
        (_, true) => String::new(),
        (true, false) => format!("{} < ", readable(min)),
        (false, false) => format!("{} ≤ ", readable(min)),
    };
    let upper = if max == f64::MAX {
        String::new()
    } else {
        format!(" ≤ {}", readable(max))
    };
    Err(ApiError::invalid(
        field,
        format!(
            "{} is out of range: allowed is a finite number {lower}{field}{upper}",
            readable(value)
        ),
    ))
}

/// A number as a person reads it: plain when moderate, in e-notation when very large or small.
pub fn readable(value: f64) -> String {
    let magnitude = value.abs();
    if value.is_finite() && value != 0.0 && !(1e-4..1e6).contains(&magnitude) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// A finite number in `range` (a range of [`crate::limits`], as the schema states it).
pub fn within(field: &str, value: f64, range: Range) -> Result<f64, ApiError> {
    number(
        field,
        value,
        range.min.unwrap_or(f64::MIN),
        range.min_open,
        range.max.unwrap_or(f64::MAX),
    )
}

/// An integer, or a list's length, in `range`.
pub fn count_within(field: &str, value: usize, range: Count) -> Result<usize, ApiError> {
    count(field, value, range.min, range.max)
}

/// Any finite number.
pub fn finite(field: &str, value: f64) -> Result<f64, ApiError> {
    number(field, value, f64::MIN, false, f64::MAX)
}

/// An integer count in `[min, max]`.
pub fn count(field: &str, value: usize, min: usize, max: usize) -> Result<usize, ApiError> {
    if (min..=max).contains(&value) {
        Ok(value)
    } else {
        Err(ApiError::invalid(
            field,
            format!("{value} is out of range: allowed is an integer {min} ≤ {field} ≤ {max}"),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_field_and_the_range() {
        let err = number("slope.height", -1.0, 0.0, true, f64::MAX).unwrap_err();
        assert_eq!(
            err.to_string(),
            "slope.height: -1 is out of range: allowed is a finite number 0 < slope.height"
        );
        let err = count("slices", 0, 1, 10_000).unwrap_err();
        assert_eq!(
            err.to_string(),
            "slices: 0 is out of range: allowed is an integer 1 ≤ slices ≤ 10000"
        );
        assert!(finite("x", f64::NAN).is_err());
        let err = number("soil.unit_weight", 3.4e38, 0.0, true, 1e12).unwrap_err();
        assert_eq!(
            err.to_string(),
            "soil.unit_weight: 3.4e38 is out of range: allowed is a finite number 0 < soil.unit_weight ≤ 1e12"
        );
        assert!(finite("x", f64::INFINITY).is_err());
    }
}
