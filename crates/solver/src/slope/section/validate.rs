//! The checks of a section's parts that depend on each other (polylines are valid by
//! construction): layers listed from the top down, ranges of r_u, γ_w, loads and the crack,
//! loads and lines over the ground, bedrock below it.

use super::model::SectionParts;
use crate::slope::error::{check_range, SlopeError, SlopeParameter};

/// Largest magnitude of a pressure, force or unit weight (as for the simple form).
pub(super) const MAX_MAGNITUDE: f64 = 1e12;

/// Checks `parts`; the first failure names its input.
pub(super) fn check(parts: &SectionParts) -> Result<(), SlopeError> {
    layers(parts)?;
    loads(parts)?;
    placement(parts)
}

/// The layers: at least one, tops given after the first, listed from the top down.
fn layers(parts: &SectionParts) -> Result<(), SlopeError> {
    if parts.layers.is_empty() {
        return Err(SlopeError::Conflict {
            parameter: SlopeParameter::Layer { index: 0 },
            reason: "a section needs at least one layer".to_owned(),
        });
    }
    for (index, layer) in parts.layers.iter().enumerate() {
        match (index, &layer.top) {
            (0, Some(_)) => {
                return Err(SlopeError::Conflict {
                    parameter: SlopeParameter::LayerTop { index },
                    reason: "the first layer's top is the ground: give null".to_owned(),
                })
            }
            (1.., None) => {
                return Err(SlopeError::Conflict {
                    parameter: SlopeParameter::LayerTop { index },
                    reason: "every layer after the first needs its top line".to_owned(),
                })
            }
            _ => {}
        }
        if let Some(ratio) = layer.pore_pressure_ratio {
            check_range(
                SlopeParameter::Layer { index },
                ratio,
                0.0,
                false,
                1.0,
                "0 ≤ pore_pressure_ratio ≤ 1",
            )?;
        }
    }
    // Listed top-down: a layer's top may meet the one above (the upper layer pinches out)
    // but not rise above it.
    for index in 2..parts.layers.len() {
        let (Some(upper), Some(top)) = (&parts.layers[index - 1].top, &parts.layers[index].top)
        else {
            continue;
        };
        let scale = upper
            .points()
            .iter()
            .chain(top.points())
            .fold(1.0f64, |m, p| m.max(p.1.abs()));
        let rise = upper
            .xs()
            .chain(top.xs())
            .map(|x| (x, top.y_at(x) - upper.y_at(x)))
            .find(|&(_, d)| d > 1e-9 * scale);
        if let Some((x, _)) = rise {
            return Err(SlopeError::Conflict {
                parameter: SlopeParameter::LayerTop { index },
                reason: format!(
                    "rises above the top of layer {} at x = {x}: layers are listed from the \
                     top down, and a top may meet the one above (that layer pinches out) but \
                     not cross it",
                    index
                ),
            });
        }
    }
    Ok(())
}

/// γ_w, the loads' and the crack's ranges.
fn loads(parts: &SectionParts) -> Result<(), SlopeError> {
    check_range(
        SlopeParameter::WaterUnitWeight,
        parts.water_unit_weight,
        0.0,
        true,
        MAX_MAGNITUDE,
        "a finite number > 0",
    )?;
    for (index, s) in parts.surcharges.iter().enumerate() {
        let parameter = SlopeParameter::Surcharge { index };
        let allowed = "pressures 0 ≤ p ≤ 1e12 and a finite x_start < x_end";
        for p in [s.pressure, s.pressure_end] {
            check_range(parameter, p, 0.0, false, MAX_MAGNITUDE, allowed)?;
        }
        if !(s.x_start.is_finite() && s.x_end.is_finite() && s.x_start < s.x_end) {
            return Err(SlopeError::OutOfRange {
                parameter,
                value: s.x_end,
                allowed,
            });
        }
    }
    for (index, l) in parts.line_loads.iter().enumerate() {
        for v in [l.x, l.fx, l.fy] {
            check_range(
                SlopeParameter::LineLoad { index },
                v,
                -MAX_MAGNITUDE,
                false,
                MAX_MAGNITUDE,
                "finite x, fx, fy with |value| ≤ 1e12",
            )?;
        }
    }
    if let Some(crack) = parts.tension_crack {
        let depth = check_range(
            SlopeParameter::TensionCrackDepth,
            crack.depth,
            0.0,
            true,
            1e9,
            "a finite depth > 0",
        )?;
        check_range(
            SlopeParameter::TensionCrackWater,
            crack.water_depth,
            0.0,
            false,
            depth,
            "0 ≤ water_depth ≤ depth",
        )?;
    }
    Ok(())
}

/// Loads and lines over the ground, bedrock below it.
fn placement(parts: &SectionParts) -> Result<(), SlopeError> {
    let (g0, g1) = parts.ground.x_range();
    for (index, s) in parts.surcharges.iter().enumerate() {
        if s.x_end < g0 || s.x_start > g1 {
            return Err(SlopeError::Conflict {
                parameter: SlopeParameter::Surcharge { index },
                reason: format!(
                    "lies outside the ground (which runs from x = {g0} to {g1}): a surcharge \
                     acts on the ground"
                ),
            });
        }
    }
    super::supports::check(&parts.supports, &parts.ground)?;
    if let Some(line) = &parts.piezometric_line {
        let p = line.points();
        if g1 > g0 && (p[p.len() - 1].0 < g0 || p[0].0 > g1) {
            return Err(SlopeError::Conflict {
                parameter: SlopeParameter::PiezometricLine,
                reason: format!(
                    "lies outside the section (the ground runs from x = {g0} to {g1}): give \
                     it over the section"
                ),
            });
        }
    }
    if let Some(bedrock) = &parts.bedrock {
        let above = bedrock
            .points()
            .iter()
            .map(|p| (p.0, p.1 - parts.ground.y_at(p.0)))
            .chain(
                parts
                    .ground
                    .points()
                    .iter()
                    .map(|p| (p.0, bedrock.y_at(p.0) - p.1)),
            )
            .find(|&(_, rise)| rise > 0.0);
        if let Some((x, _)) = above {
            return Err(SlopeError::Conflict {
                parameter: SlopeParameter::Bedrock,
                reason: format!("must not rise above the ground (it does at x = {x})"),
            });
        }
    }
    Ok(())
}
