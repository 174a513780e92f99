//! `design` (model §9.1): a partial-factor check as clients state it (an EN 1997-1 design
//! approach, or factors of one's own), the loads' actions, and the verdict in the answer. The
//! design values themselves are the solver's ([`thrustline_solver::slope::design`]), applied
//! once as the request is read.

use serde::{Deserialize, Serialize};
use thrustline_solver::slope::design::{Action, Approach, Design, Factors, Verdict};
use utoipa::ToSchema;

use crate::error::ApiError;

/// An EN 1997-1 design approach (Annex A's factor sets).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
pub enum ApproachDto {
    /// DA1 combination 1: A1 (γ_G 1.35, γ_Q 1.5), M1 (all 1), R1 (γ_R 1).
    #[serde(rename = "DA1-1")]
    Da1Combination1,
    /// DA1 combination 2: A2 (γ_G 1, γ_Q 1.3), M2 (γ_φ 1.25 on tan φ', γ_c 1.25, γ_cu 1.4,
    /// γ_γ 1), R1.
    #[serde(rename = "DA1-2")]
    Da1Combination2,
    /// DA2: A1, M1, R2 (γ_R 1.1), on the effect of the actions: F with variable loads
    /// ·γ_Q/γ_G, checked as F/(γ_G·γ_R) ≥ 1.
    #[serde(rename = "DA2")]
    Da2,
    /// DA3: A2 (on the loads, taken as geotechnical actions), M2, R3 (γ_R 1).
    #[serde(rename = "DA3")]
    Da3,
    /// The factors given in `design.factors`.
    #[serde(rename = "custom")]
    Custom,
}

/// Partial factors of one's own (each 0 < γ ≤ 100; those left out are 1).
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FactorsDto {
    /// γ_φ, dividing tan φ'. Defaults to 1.
    #[serde(default)]
    pub friction: Option<f64>,
    /// γ_c, dividing c'. Defaults to 1.
    #[serde(default)]
    pub cohesion: Option<f64>,
    /// γ_cu, dividing the cohesion of a soil with φ' = 0 (undrained). Defaults to 1.
    #[serde(default)]
    pub undrained: Option<f64>,
    /// γ_γ, multiplying unit weights. Defaults to 1.
    #[serde(default)]
    pub unit_weight: Option<f64>,
    /// γ_G, multiplying unfavourable permanent loads. Defaults to 1.
    #[serde(default)]
    pub permanent: Option<f64>,
    /// γ_Q, multiplying unfavourable variable loads. Defaults to 1.
    #[serde(default)]
    pub variable: Option<f64>,
    /// γ_R, dividing the resistance (the over-design factor is F/γ_R). Defaults to 1.
    #[serde(default)]
    pub resistance: Option<f64>,
}

/// A design check: give `approach` or `factors`.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct DesignDto {
    /// An EN 1997-1 design approach.
    #[serde(default)]
    pub approach: Option<ApproachDto>,
    /// Factors of one's own (instead of an approach).
    #[serde(default)]
    pub factors: Option<FactorsDto>,
}

/// How a load acts (for a design check; ignored without one).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ActionDto {
    /// Permanent (a structure, stored fill that stays).
    #[default]
    Permanent,
    /// Variable (traffic, storage).
    Variable,
}

/// A load's action in the solver's terms.
pub fn action(kind: Option<ActionDto>, favourable: Option<bool>) -> Action {
    Action {
        variable: kind == Some(ActionDto::Variable),
        favourable: favourable.unwrap_or(false),
    }
}

/// The solver's design check of the request's `design`.
pub fn design(dto: &DesignDto) -> Result<Design, ApiError> {
    match (dto.approach, dto.factors) {
        (Some(ApproachDto::Custom), None) | (None, None) => Err(ApiError::invalid(
            "design",
            "give an approach (DA1-1, DA1-2, DA2, DA3) or factors",
        )),
        (Some(ApproachDto::Custom) | None, Some(f)) => {
            let one = |v: Option<f64>| v.unwrap_or(1.0);
            Ok(Design::custom(Factors {
                friction: one(f.friction),
                cohesion: one(f.cohesion),
                undrained: one(f.undrained),
                unit_weight: one(f.unit_weight),
                permanent: one(f.permanent),
                variable: one(f.variable),
                resistance: one(f.resistance),
            })?)
        }
        (Some(_), Some(_)) => Err(ApiError::invalid(
            "design.factors",
            "give an approach or factors, not both (an approach has its own factors)",
        )),
        (Some(approach), None) => Ok(Design::approach(match approach {
            ApproachDto::Da1Combination1 => Approach::Da1Combination1,
            ApproachDto::Da1Combination2 => Approach::Da1Combination2,
            ApproachDto::Da2 => Approach::Da2,
            _ => Approach::Da3,
        })),
    }
}

/// The partial factors applied.
#[derive(Debug, Clone, Copy, Serialize, ToSchema)]
pub struct FactorsOutDto {
    /// γ_φ.
    pub friction: f64,
    /// γ_c.
    pub cohesion: f64,
    /// γ_cu.
    pub undrained: f64,
    /// γ_γ.
    pub unit_weight: f64,
    /// γ_G.
    pub permanent: f64,
    /// γ_Q.
    pub variable: f64,
    /// γ_R.
    pub resistance: f64,
}

/// The design check's verdict.
#[derive(Debug, Clone, Copy, Serialize, ToSchema)]
pub struct DesignOutDto {
    /// The approach (`custom` for factors of one's own).
    pub approach: ApproachDto,
    /// The factors applied.
    pub factors: FactorsOutDto,
    /// F on the design values (the answer's `factor_of_safety`).
    pub factor_of_safety: Option<f64>,
    /// F/γ_R (DA2: F/(γ_G·γ_R)); null without F.
    pub over_design_factor: Option<f64>,
    /// Whether the over-design factor is at least 1.
    pub verified: bool,
}

/// The verdict as answered.
pub fn design_out(verdict: &Verdict) -> DesignOutDto {
    let design = &verdict.design;
    let f = &design.factors;
    DesignOutDto {
        approach: match design.approach {
            Approach::Da1Combination1 => ApproachDto::Da1Combination1,
            Approach::Da1Combination2 => ApproachDto::Da1Combination2,
            Approach::Da2 => ApproachDto::Da2,
            Approach::Da3 => ApproachDto::Da3,
            Approach::Custom => ApproachDto::Custom,
        },
        factors: FactorsOutDto {
            friction: f.friction,
            cohesion: f.cohesion,
            undrained: f.undrained,
            unit_weight: f.unit_weight,
            permanent: f.permanent,
            variable: f.variable,
            resistance: f.resistance,
        },
        factor_of_safety: verdict.factor_of_safety,
        over_design_factor: verdict.over_design_factor,
        verified: verdict.verified,
    }
}
