//! `"methods"`: the factors of safety of the methods engineers compare with Spencer's, on the
//! same slices (SPEC §4.3).

use serde::{Deserialize, Serialize};
use thrustline_solver::slope::spencer::methods::{
    bishop, janbu, morgenstern_price, ordinary, InterSliceFunction, MethodFactor,
};
use thrustline_solver::slope::{SliceModel, SpencerSolution};
use utoipa::ToSchema;

use crate::error::ApiError;
use crate::validation::number;

/// A method of slices.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum MethodName {
    /// Morgenstern–Price: X = λ·f(x)·E, force and moment equilibrium.
    MorgensternPrice,
    /// Bishop's simplified: moments about the centre, horizontal inter-slice forces.
    Bishop,
    /// Janbu's simplified (uncorrected): horizontal force equilibrium, horizontal inter-slice
    /// forces.
    Janbu,
    /// The ordinary method (Fellenius): no inter-slice forces, moments about the centre.
    Ordinary,
}

/// One method's answer.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MethodDto {
    /// Whether its equations have a root (and, for moment methods, a centre to take moments
    /// about: a circle's, or `moment_centre`).
    pub converged: bool,
    /// The factor of safety; null when not converged.
    #[schema(required = true)]
    pub factor_of_safety: Option<f64>,
    /// Morgenstern–Price's λ (X/E = λ·f), when converged; absent for the other methods.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda: Option<f64>,
}

/// The methods asked for, each present only when asked.
#[derive(Debug, Clone, Default, Serialize, ToSchema)]
pub struct MethodsDto {
    /// Morgenstern–Price with the half-sine function (or `interslice_function`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub morgenstern_price: Option<MethodDto>,
    /// Bishop's simplified method.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bishop: Option<MethodDto>,
    /// Janbu's simplified method (uncorrected).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub janbu: Option<MethodDto>,
    /// The ordinary method.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ordinary: Option<MethodDto>,
}

/// The inter-slice function from its points [ξ, f] (ξ from 0 at the toe end to 1 at the crest
/// end, increasing; f ≥ 0); the half-sine when none are given.
pub fn interslice_function(points: Option<&[[f64; 2]]>) -> Result<InterSliceFunction, ApiError> {
    let Some(points) = points else {
        return Ok(InterSliceFunction::HalfSine);
    };
    if points.len() < 2 || points.len() > 1000 {
        return Err(ApiError::invalid(
            "interslice_function",
            format!(
                "{} points: allowed is 2 to 1000 points [ξ, f]",
                points.len()
            ),
        ));
    }
    for (i, p) in points.iter().enumerate() {
        let field = format!("interslice_function[{i}]");
        number(&field, p[0], 0.0, false, 1.0)?;
        number(&field, p[1], 0.0, false, 1e6)?;
        if i > 0 && p[0] <= points[i - 1][0] {
            return Err(ApiError::invalid(
                field,
                "ξ must increase from point to point",
            ));
        }
    }
    Ok(InterSliceFunction::Points(
        points.iter().map(|p| (p[0], p[1])).collect(),
    ))
}

/// Each method asked for on the slices of the answer; Morgenstern–Price starts from Spencer's
/// (F, tan θ), or Bishop's F with λ = 0.
pub fn methods(
    names: &[MethodName],
    function: &InterSliceFunction,
    model: &SliceModel,
    spencer: &SpencerSolution,
) -> MethodsDto {
    let dto = |m: MethodFactor| MethodDto {
        converged: m.factor_of_safety.is_some(),
        factor_of_safety: m.factor_of_safety,
        lambda: m.lambda,
    };
    let mut out = MethodsDto::default();
    for name in names {
        match name {
            MethodName::MorgensternPrice => {
                let starts = [
                    spencer
                        .factor_of_safety
                        .zip(spencer.theta_rad.map(f64::tan)),
                    spencer.bishop_factor_of_safety.map(|f| (f, 0.0)),
                    Some((1.0, 0.0)),
                ];
                let found = starts
                    .into_iter()
                    .flatten()
                    .map(|start| morgenstern_price(model, function, start))
                    .find(|m| m.factor_of_safety.is_some());
                out.morgenstern_price = Some(dto(found.unwrap_or(MethodFactor {
                    factor_of_safety: None,
                    lambda: None,
                    iterations: 0,
                })));
            }
            MethodName::Bishop => out.bishop = Some(dto(bishop(model))),
            MethodName::Janbu => out.janbu = Some(dto(janbu(model))),
            MethodName::Ordinary => out.ordinary = Some(dto(ordinary(model))),
        }
    }
    out
}
