//! `"methods"`: the factors of safety of the methods engineers compare with Spencer's, on the
//! same slices (model §4.3).

use serde::{Deserialize, Serialize};
use thrustline_solver::slope::analysis::{Method, MethodAnswer, MethodFactors, OwnCritical};
use thrustline_solver::slope::spencer::methods::InterSliceFunction;
use utoipa::ToSchema;

use super::options::AccuracyOutDto;
use super::outputs::{circle_out, search_out, CircleOutDto, SearchOutDto};
use crate::error::ApiError;
use crate::limits::INTERSLICE_POINTS;
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
    /// The accuracy of its F as the headline's (from its F at two more slice counts); null when
    /// not converged.
    #[schema(required = true)]
    pub accuracy: Option<AccuracyOutDto>,
    /// With `search.per_method`: the method's own critical circle, searched with its F.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical: Option<MethodCriticalDto>,
}

/// A method's own critical circle (`search.per_method`): the search's centres, radii and
/// candidates, the circles ranked by the method's F.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MethodCriticalDto {
    /// Whether a circle of the search has an F by the method.
    pub converged: bool,
    /// The method's least F over the search; null when no circle has one.
    #[schema(required = true)]
    pub factor_of_safety: Option<f64>,
    /// Its critical circle; null when none.
    #[schema(required = true)]
    pub circle: Option<CircleOutDto>,
    /// How its search went; null when it found no circle.
    #[schema(required = true)]
    pub search: Option<SearchOutDto>,
}

impl MethodCriticalDto {
    fn new(critical: &OwnCritical) -> Self {
        Self {
            converged: critical.is_some(),
            factor_of_safety: critical.as_ref().map(|c| c.factor_of_safety),
            circle: critical.as_ref().and_then(|c| circle_out(&c.problem)),
            search: critical.as_ref().map(|c| search_out(&c.report)),
        }
    }
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
    if !(INTERSLICE_POINTS.min..=INTERSLICE_POINTS.max).contains(&points.len()) {
        return Err(ApiError::invalid(
            "interslice_function",
            format!(
                "{} points: allowed is {} to {} points [ξ, f]",
                points.len(),
                INTERSLICE_POINTS.min,
                INTERSLICE_POINTS.max
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

/// What a request asks of the methods.
#[derive(Debug, Clone, Copy)]
pub struct MethodsAsked<'a> {
    /// `methods`.
    pub names: &'a [MethodName],
    /// Whether `interslice_function` is given.
    pub interslice_function: bool,
    /// `search.per_method`.
    pub per_method: bool,
    /// Whether `negative_effective_stress` is `keep` (the classic equations).
    pub classic: bool,
}

/// `methods` and `search.per_method` as planned: the methods in order (repeats next to each
/// other dropped), and whether each is searched for its own critical circle.
pub fn methods_plan(asked: MethodsAsked<'_>) -> Result<(Vec<Method>, bool), ApiError> {
    let mut methods = asked.names.to_vec();
    methods.dedup();
    if asked.interslice_function && !methods.contains(&MethodName::MorgensternPrice) {
        return Err(ApiError::invalid(
            "interslice_function",
            "is Morgenstern–Price's: add \"morgenstern_price\" to methods, or leave it out",
        ));
    }
    let per_method = asked.per_method;
    if per_method && methods.is_empty() {
        return Err(ApiError::invalid(
            "search.per_method",
            "names no method to search: list them in methods (bishop, janbu, ordinary, \
             morgenstern_price)",
        ));
    }
    if per_method && !asked.classic {
        return Err(ApiError::invalid(
            "search.per_method",
            "searches each method on its classic equations: it does not combine with \
             negative_effective_stress other than keep",
        ));
    }
    Ok((methods.into_iter().map(Into::into).collect(), per_method))
}

impl From<MethodName> for Method {
    fn from(name: MethodName) -> Self {
        match name {
            MethodName::MorgensternPrice => Self::MorgensternPrice,
            MethodName::Bishop => Self::Bishop,
            MethodName::Janbu => Self::Janbu,
            MethodName::Ordinary => Self::Ordinary,
        }
    }
}

impl MethodDto {
    fn new(answer: &MethodAnswer, critical: Option<&OwnCritical>) -> Self {
        let m = &answer.factor;
        Self {
            converged: m.factor_of_safety.is_some(),
            factor_of_safety: m.factor_of_safety,
            lambda: m.lambda,
            accuracy: answer.accuracy.map(|a| AccuracyOutDto {
                slices: a.slices,
                discretisation_error: a.discretisation_error,
            }),
            critical: critical.map(MethodCriticalDto::new),
        }
    }
}

impl MethodsDto {
    /// The methods' answers as the API states them, each with its own critical circle when
    /// `critical` has one for it.
    pub fn new(found: &MethodFactors, critical: &[(Method, OwnCritical)]) -> Self {
        let of = |method: Method| critical.iter().find(|(m, _)| *m == method).map(|(_, c)| c);
        let dto = |method: Method| found.of(method).map(|a| MethodDto::new(a, of(method)));
        Self {
            morgenstern_price: dto(Method::MorgensternPrice),
            bishop: dto(Method::Bishop),
            janbu: dto(Method::Janbu),
            ordinary: dto(Method::Ordinary),
        }
    }
}
