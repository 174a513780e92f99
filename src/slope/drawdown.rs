//! `section.drawdown` and `soil.r_envelope` (model §8): a rapid drawdown's two water lines and
//! the soils that do not drain, read into the solver's [`Section::with_drawdown`].

use serde::{Deserialize, Serialize};
use thrustline_solver::slope::design::Design;
use thrustline_solver::slope::section::drawdown::REnvelope;
use thrustline_solver::slope::section::Section;
use utoipa::ToSchema;

use super::lines::polyline;
use super::request::{Coordinates, SectionDto};
use crate::error::ApiError;
use crate::limits::{FRICTION_ANGLE_DEG, STRESS};
use crate::validation::within;

/// A rapid drawdown (Duncan, Wright & Wong 1990, three stages): the water lines before and after
/// it, in place of `piezometric_line`. Soils with an `r_envelope` do not drain: after the
/// drawdown they have the undrained strength of their consolidation before it; the others drain
/// freely.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct DrawdownDto {
    /// The piezometric line before the drawdown (the pool up), 1 to 1000 points.
    #[schema(value_type = Vec<Vec<f64>>)]
    pub before: Vec<Coordinates>,
    /// The piezometric line after it (the pool down), 1 to 1000 points.
    #[schema(value_type = Vec<Vec<f64>>)]
    pub after: Vec<Coordinates>,
}

/// A soil's total-stress (R) envelope from consolidated-undrained triaxial tests: the line
/// tangent to the circles drawn with the effective consolidation pressure σ′_3c and the
/// principal stress difference at failure.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct REnvelopeDto {
    /// Its intercept c_R, 0 ≤ c_R ≤ 1e12.
    #[schema(examples(5.0))]
    pub cohesion: f64,
    /// Its slope φ_R in degrees, 0 ≤ φ_R ≤ 89.9.
    #[schema(examples(15.0))]
    pub friction_angle_deg: f64,
}

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
