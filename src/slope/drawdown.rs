//! `section.drawdown` and `soil.r_envelope` (model §8): a rapid drawdown's two water lines and
//! the soils that do not drain, read into the solver's [`Section::with_drawdown`].

use serde::Serialize;
use thrustline_solver::slope::design::Design;
use thrustline_solver::slope::section::drawdown::REnvelope;
use thrustline_solver::slope::section::Section;
use utoipa::ToSchema;

use super::lines::polyline;
use super::options::Coordinates;
use super::request::SectionDto;
use crate::error::ApiError;
use crate::limits::{FRICTION_ANGLE_DEG, STRESS};
use crate::validation::within;

/// The after-line a drawdown puts in place of `section.piezometric_line`, refusing both.
pub fn after_line(dto: &SectionDto) -> Result<Option<&[Coordinates]>, ApiError> {
    match (&dto.drawdown, &dto.piezometric_line) {
        (Some(_), Some(_)) => Err(ApiError::invalid(
            "section.piezometric_line",
            "is not given with section.drawdown, whose before and after lines are the water \
             lines of its two states",
        )),
        (Some(d), None) => Ok(Some(&d.after)),
        (None, _) => Ok(None),
    }
}

/// `section` with its drawdown, when the request states one (in a design check's values:
/// c_R/γ_c and tan φ_R/γ_φ); a soil's `r_envelope` without a drawdown is refused.
pub fn with_drawdown(
    section: Section,
    dto: &SectionDto,
    design: Option<&Design>,
) -> Result<Section, ApiError> {
    let mut envelopes = Vec::with_capacity(dto.layers.len());
    for (i, layer) in dto.layers.iter().enumerate() {
        let Some(r) = &layer.soil.r_envelope else {
            envelopes.push(None);
            continue;
        };
        let field = format!("section.layers[{i}].soil.r_envelope");
        if dto.drawdown.is_none() {
            return Err(ApiError::invalid(
                field,
                "is used in a rapid drawdown only: give section.drawdown",
            ));
        }
        let envelope = REnvelope {
            cohesion: within(&format!("{field}.cohesion"), r.cohesion, STRESS)?,
            friction_angle_rad: within(
                &format!("{field}.friction_angle_deg"),
                r.friction_angle_deg,
                FRICTION_ANGLE_DEG,
            )?
            .to_radians(),
        };
        envelopes.push(Some(match design {
            Some(d) => d.total_stress_envelope(envelope),
            None => envelope,
        }));
    }
    let Some(d) = &dto.drawdown else {
        return Ok(section);
    };
    let before = polyline("section.drawdown.before", &d.before)?;
    Ok(section.with_drawdown(before, envelopes)?)
}

/// What a rapid drawdown's stages gave on the answered surface (its F is the answer's).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct DrawdownOutDto {
    /// Stage 1: F before the drawdown, every soil drained; its bases' stresses are the
    /// consolidation stresses.
    pub before_factor_of_safety: f64,
    /// Stage 2: F after it, the bases in soils that do not drain at their undrained strength.
    pub undrained_factor_of_safety: f64,
    /// The stage whose F is the answer: 3 where a base's drained strength was the lower at
    /// stage 2 (that base then has its drained c′ and φ′), else 2.
    pub stage: u8,
    /// The slices whose base lies in a soil that does not drain, numbered as `slices[].slice`.
    pub undrained_slices: Vec<usize>,
    /// Those given their drained strength at stage 3.
    pub drained_slices: Vec<usize>,
}

/// The stages as the answer reports them, slices numbered as `slices[].slice` (from 1 at the
/// toe end).
pub fn drawdown_out(
    stages: &thrustline_solver::slope::section::drawdown::DrawdownStages,
) -> DrawdownOutDto {
    let numbered = |slices: &[usize]| slices.iter().map(|i| i + 1).collect();
    DrawdownOutDto {
        before_factor_of_safety: stages.before_factor,
        undrained_factor_of_safety: stages.undrained_factor,
        stage: if stages.drained_slices.is_empty() {
            2
        } else {
            3
        },
        undrained_slices: numbered(&stages.undrained_slices),
        drained_slices: numbered(&stages.drained_slices),
    }
}
