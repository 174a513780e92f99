//! A study as clients ask for it (model §9.2–9.3): `probabilistic` and `sensitivity` blocks
//! beside the analysis they vary. Their numbers are read and checked in [`super::plan`].

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// A probabilistic study: the analysis run on samples of uncertain inputs.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(examples(json!({"samples": 2000, "sampling": "latin_hypercube", "seed": 7, "surface": "fixed",
    "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 1.0, "min": 0},
                  {"field": "soil.friction_angle_deg", "distribution": "lognormal", "std": 3}],
    "correlations": [{"fields": ["soil.cohesion", "soil.friction_angle_deg"], "coefficient": -0.5}]})))]
pub struct ProbabilisticDto {
    /// Samples to analyse, 1 ≤ n ≤ 100,000 (defaults to 1000); with k variables,
    /// n·k ≤ 2,000,000.
    #[serde(default)]
    #[schema(examples(2000))]
    pub samples: Option<usize>,
    /// How the samples are drawn. Defaults to `monte_carlo`.
    #[serde(default)]
    pub sampling: Option<SamplingDto>,
    /// The seed of the random numbers: the same seed gives the same samples and the same
    /// answer. Defaults to 0.
    #[serde(default)]
    #[schema(examples(7))]
    pub seed: Option<u64>,
    /// Slopes: `fixed` analyses every sample on the deterministic answer's slip surface (the
    /// one given, or the critical one found); `search` runs the request's search again for
    /// every sample. Defaults to `fixed`. Arches: only `fixed` (the stated loads).
    #[serde(default)]
    pub surface: Option<StudySurfaceDto>,
    /// The uncertain inputs, 1 to 20.
    pub variables: Vec<VariableDto>,
    /// Correlation coefficients between pairs of variables (a Gaussian copula); pairs not
    /// given are independent. The matrix must be positive definite.
    #[serde(default)]
    pub correlations: Option<Vec<CorrelationDto>>,
    /// Bars of the answer's histogram, 1 ≤ bins ≤ 200. Defaults to 20.
    #[serde(default)]
    #[schema(examples(20))]
    pub histogram_bins: Option<usize>,
    /// Slopes: the method whose F each sample answers (it must be among `methods`); with
    /// `surface: search`, each sample searches that method's own critical circle. Defaults to
    /// `spencer`. Arches: leave it out.
    #[serde(default)]
    pub method: Option<StudyMethodDto>,
}

/// The method whose F a slope study's samples answer.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum StudyMethodDto {
    /// Spencer's (the headline).
    #[default]
    Spencer,
    /// Morgenstern–Price.
    MorgensternPrice,
    /// Bishop's simplified.
    Bishop,
    /// Janbu's simplified.
    Janbu,
    /// The ordinary method.
    Ordinary,
}

/// How a probabilistic study draws its samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum SamplingDto {
    /// Independent draws.
    MonteCarlo,
    /// One draw in each of n equal-probability strata per variable.
    LatinHypercube,
}

/// Which slip surface a slope study's samples are analysed on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum StudySurfaceDto {
    /// The deterministic answer's surface, for every sample.
    Fixed,
    /// Each sample's own critical surface (the request's search run again).
    Search,
}

/// An uncertain input.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct VariableDto {
    /// The path of a number in this request, e.g. `section.layers[0].soil.cohesion`: its value
    /// is the mean (`normal`, `lognormal`) or the mode (`triangular`).
    #[schema(examples("soil.cohesion"))]
    pub field: String,
    /// The distribution.
    pub distribution: DistributionDto,
    /// Standard deviation (> 0) of `normal` and `lognormal`; not for the others.
    #[serde(default)]
    #[schema(examples(1.0))]
    pub std: Option<f64>,
    /// Least value: the lower end of `uniform` and `triangular` (required), a truncation of
    /// the others.
    #[serde(default)]
    pub min: Option<f64>,
    /// Largest value: the upper end of `uniform` and `triangular` (required), a truncation of
    /// the others.
    #[serde(default)]
    pub max: Option<f64>,
}

/// A variable's distribution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum DistributionDto {
    /// Normal: mean the field's value, `std`.
    Normal,
    /// Lognormal: the variable's own mean (the field's value, > 0) and `std`.
    Lognormal,
    /// Uniform on [`min`, `max`] (the field's value is not used).
    Uniform,
    /// Triangular on [`min`, `max`] with its mode at the field's value.
    Triangular,
}

/// The correlation of two variables.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CorrelationDto {
    /// The two variables' fields.
    #[schema(value_type = Vec<String>, min_items = 2, max_items = 2)]
    pub fields: [String; 2],
    /// Their correlation coefficient, −1 < ρ < 1 (of the Gaussian copula's normal scores).
    #[schema(examples(-0.5))]
    pub coefficient: f64,
}

/// A sensitivity study: the analysis at evenly spaced values of each variable in turn, the
/// others at their values in the request.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(examples(json!({"variables": [{"field": "soil.cohesion", "from": 4, "to": 8, "points": 11}]})))]
pub struct SensitivityDto {
    /// The variables, 1 to 20.
    pub variables: Vec<SensitivityVariableDto>,
    /// Slopes: the method whose F each point answers, as `probabilistic.method`. Defaults to
    /// `spencer`.
    #[serde(default)]
    pub method: Option<StudyMethodDto>,
}

/// One variable of a sensitivity study.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SensitivityVariableDto {
    /// The path of a number in this request.
    #[schema(examples("soil.cohesion"))]
    pub field: String,
    /// The first value.
    #[schema(examples(4.0))]
    pub from: f64,
    /// The last value (≠ `from`).
    #[schema(examples(8.0))]
    pub to: f64,
    /// Values from `from` to `to`, evenly spaced, 2 ≤ points ≤ 101. Defaults to 11.
    #[serde(default)]
    #[schema(examples(11))]
    pub points: Option<usize>,
}
