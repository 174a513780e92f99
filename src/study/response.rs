//! A study's answer as clients read it, beside the analysis it varied.

use serde::Serialize;
use utoipa::ToSchema;

use super::request::{SamplingDto, StudyMethodDto, StudySurfaceDto};

/// What a probabilistic study found. Failure is an answer below 1 (F for slopes, λ for
/// arches); samples without an answer are counted apart, neither safe nor failed.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct ProbabilisticOutDto {
    /// Samples analysed.
    pub samples: usize,
    /// How they were drawn.
    pub sampling: SamplingDto,
    /// The seed they were drawn from.
    pub seed: u64,
    /// The surface each sample was analysed on (arches: `fixed`).
    pub surface: StudySurfaceDto,
    /// The method whose F the samples answered, when not Spencer's (`method`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub method: Option<StudyMethodDto>,
    /// The share of answered samples below 1; null when none was answered.
    pub probability_of_failure: Option<f64>,
    /// Its standard error √(p(1 − p)/n) as Monte Carlo sampling gives it (Latin hypercube
    /// sampling is usually closer); null when none was answered.
    pub probability_of_failure_standard_error: Option<f64>,
    /// Answered samples below 1.
    pub failed: usize,
    /// Mean of the answers.
    pub mean: Option<f64>,
    /// Standard deviation of the answers (n − 1).
    pub std: Option<f64>,
    /// (mean − 1)/std.
    pub reliability_index_normal: Option<f64>,
    /// ln(mean/√(1 + V²))/√(ln(1 + V²)), V = std/mean.
    pub reliability_index_lognormal: Option<f64>,
    /// Equal bars between the least and the greatest answer.
    pub histogram: Vec<BinDto>,
    /// Samples the analysis gave no answer for (no root, not settled, no candidate surface).
    pub unsolved: usize,
    /// Samples whose values the route refuses (e.g. a negative cohesion): truncate the
    /// variable with `min`/`max`.
    pub refused: usize,
    /// Wall time of the samples in milliseconds.
    pub time_ms: f64,
}

/// One bar of a histogram: answers in [from, to) (the last bar includes `to`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, ToSchema)]
pub struct BinDto {
    /// Lower edge.
    pub from: f64,
    /// Upper edge.
    pub to: f64,
    /// Answers in it.
    pub count: usize,
}

/// What a sensitivity study found.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct SensitivityOutDto {
    /// The method whose F the points answered, when not Spencer's (`method`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub method: Option<StudyMethodDto>,
    /// Per variable, its values and the answers there.
    pub variables: Vec<SensitivityCurveDto>,
    /// Wall time of the study in milliseconds.
    pub time_ms: f64,
}

/// One variable of a sensitivity study.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct SensitivityCurveDto {
    /// The variable's field.
    pub field: String,
    /// The analysis at each value, the other inputs as stated.
    pub points: Vec<SensitivityPointDto>,
}

/// The analysis at one value.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct SensitivityPointDto {
    /// The variable's value.
    pub value: f64,
    /// The answer there (F for slopes, λ for arches); null when there is none.
    pub factor: Option<f64>,
    /// Why the route refuses this value, when it does (the answer is then null).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
}
