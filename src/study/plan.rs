//! A study's blocks read once into what runs: each variable's path checked against the request
//! (it must lead to a real number the route reads), its distribution's numbers in range, the
//! correlation matrix positive definite, the sizes within the limits. Every refusal names its
//! field (`probabilistic.variables[1].std`).

use serde::de::DeserializeOwned;
use serde_json::Value;
use thrustline_solver::study::sampling::cholesky;
use thrustline_solver::study::{Distribution, Sampling, Variable};

use super::paths::JsonPath;
use super::request::{
    DistributionDto, ProbabilisticDto, SamplingDto, SensitivityDto, StudyMethodDto,
    StudySurfaceDto, VariableDto,
};
use crate::error::ApiError;
use crate::limits::{
    Range, CORRELATION, HISTOGRAM_BINS, MAX_STUDY_VALUES, SENSITIVITY_POINTS, STUDY_SAMPLES,
    STUDY_VARIABLES,
};
use crate::validation::{count_within, finite, within};

/// Samples of a study that does not say.
pub const DEFAULT_SAMPLES: usize = 1000;
/// Bars of a histogram that does not say.
pub const DEFAULT_BINS: usize = 20;
/// Values of a sensitivity variable that does not say.
pub const DEFAULT_POINTS: usize = 11;

/// A probabilistic study, resolved.
#[derive(Debug, Clone)]
pub struct ProbabilisticPlan {
    /// Where each variable's value is written.
    pub paths: Vec<JsonPath>,
    /// The variables.
    pub variables: Vec<Variable>,
    /// The correlation matrix (k × k, row-major), empty when independent.
    pub rho: Vec<f64>,
    /// Samples.
    pub samples: usize,
    /// How they are drawn.
    pub sampling: Sampling,
    /// The seed.
    pub seed: u64,
    /// Whether every sample keeps the deterministic answer's surface.
    pub fixed: bool,
    /// Bars of the histogram.
    pub bins: usize,
    /// The method whose F the samples answer.
    pub method: StudyMethodDto,
}

/// A sensitivity study, resolved: each variable's path and values.
#[derive(Debug, Clone)]
pub struct SensitivityPlan {
    /// Per variable: where it is written, and its values.
    pub variables: Vec<(JsonPath, Vec<f64>)>,
    /// The method whose F the points answer.
    pub method: StudyMethodDto,
}

/// Reads `dto` against `request` (the route's request `R` as JSON).
pub fn probabilistic<R: DeserializeOwned>(
    dto: &ProbabilisticDto,
    request: &Value,
) -> Result<ProbabilisticPlan, ApiError> {
    const AT: &str = "probabilistic";
    let k = count_within(
        &format!("{AT}.variables"),
        dto.variables.len(),
        STUDY_VARIABLES,
    )?;
    let samples = count_within(
        &format!("{AT}.samples"),
        dto.samples.unwrap_or(DEFAULT_SAMPLES),
        STUDY_SAMPLES,
    )?;
    if samples * k > MAX_STUDY_VALUES {
        return Err(ApiError::invalid(
            format!("{AT}.samples"),
            format!(
                "{samples} samples of {k} variables are {} values: at most {MAX_STUDY_VALUES} \
                 (fewer samples or variables)",
                samples * k
            ),
        ));
    }
    let bins = count_within(
        &format!("{AT}.histogram_bins"),
        dto.histogram_bins.unwrap_or(DEFAULT_BINS),
        HISTOGRAM_BINS,
    )?;
    let mut paths: Vec<JsonPath> = Vec::with_capacity(k);
    let mut variables = Vec::with_capacity(k);
    for (i, v) in dto.variables.iter().enumerate() {
        let at = format!("{AT}.variables[{i}]");
        let (path, value) = resolve::<R>(&format!("{at}.field"), &v.field, request)?;
        if paths.iter().any(|p| p.text == path.text) {
            return Err(ApiError::invalid(
                format!("{at}.field"),
                format!("\"{}\" is already a variable", path.text),
            ));
        }
        variables.push(variable(&at, v, value)?);
        paths.push(path);
    }
    let rho = correlations(dto, &paths)?;
    Ok(ProbabilisticPlan {
        paths,
        variables,
        rho,
        samples,
        sampling: match dto.sampling.unwrap_or(SamplingDto::MonteCarlo) {
            SamplingDto::MonteCarlo => Sampling::MonteCarlo,
            SamplingDto::LatinHypercube => Sampling::LatinHypercube,
        },
        seed: dto.seed.unwrap_or(0),
        fixed: dto.surface.unwrap_or(StudySurfaceDto::Fixed) == StudySurfaceDto::Fixed,
        bins,
        method: dto.method.unwrap_or_default(),
    })
}

/// Reads `dto` against `request` (the route's request `R` as JSON).
pub fn sensitivity<R: DeserializeOwned>(
    dto: &SensitivityDto,
    request: &Value,
) -> Result<SensitivityPlan, ApiError> {
    const AT: &str = "sensitivity";
    count_within(
        &format!("{AT}.variables"),
        dto.variables.len(),
        STUDY_VARIABLES,
    )?;
    let mut variables: Vec<(JsonPath, Vec<f64>)> = Vec::new();
    for (i, v) in dto.variables.iter().enumerate() {
        let at = format!("{AT}.variables[{i}]");
        let (path, _) = resolve::<R>(&format!("{at}.field"), &v.field, request)?;
        if variables.iter().any(|(p, _)| p.text == path.text) {
            return Err(ApiError::invalid(
                format!("{at}.field"),
                format!("\"{}\" is already a variable", path.text),
            ));
        }
        let from = finite(&format!("{at}.from"), v.from)?;
        let to = finite(&format!("{at}.to"), v.to)?;
        if from == to {
            return Err(ApiError::invalid(
                format!("{at}.to"),
                "must differ from `from`",
            ));
        }
        let n = count_within(
            &format!("{at}.points"),
            v.points.unwrap_or(DEFAULT_POINTS),
            SENSITIVITY_POINTS,
        )?;
        let values = (0..n).map(|j| evenly(from, to, j, n)).collect();
        variables.push((path, values));
    }
    Ok(SensitivityPlan {
        variables,
        method: dto.method.unwrap_or_default(),
    })
}

/// The j-th of n values from `from` to `to`, to 12 significant digits (0.3 + 0.1 is 0.4 here,
/// as the engineer wrote it, not 0.39999999999999997).
fn evenly(from: f64, to: f64, j: usize, n: usize) -> f64 {
    let x = from + (to - from) * j as f64 / (n - 1) as f64;
    format!("{x:.11e}").parse().unwrap_or(x)
}

/// The path `text` (the value of `field`) and the number it leads to in `request`, which must
/// be a real number of the route's request `R` (writing any finite value there still reads).
fn resolve<R: DeserializeOwned>(
    field: &str,
    text: &str,
    request: &Value,
) -> Result<(JsonPath, f64), ApiError> {
    let path = JsonPath::parse(text).map_err(|detail| ApiError::invalid(field, detail))?;
    if path.starts_with("probabilistic") || path.starts_with("sensitivity") {
        return Err(ApiError::invalid(
            field,
            "a study varies the analysis, not itself: name a number of the analysis",
        ));
    }
    let Some(found) = path.get(request) else {
        return Err(ApiError::invalid(
            field,
            format!(
                "\"{text}\" names nothing in this request: give the number there first (its \
                 value is the variable's mean)"
            ),
        ));
    };
    let Some(value) = found.as_f64() else {
        return Err(ApiError::invalid(
            field,
            format!(
                "\"{text}\" is {}, not a number",
                crate::extract::json_kind(found)
            ),
        ));
    };
    let mut probe = request.clone();
    let read = path.set(&mut probe, value + 0.5) && serde_json::from_value::<R>(probe).is_ok();
    if !read {
        return Err(ApiError::invalid(
            field,
            format!("\"{text}\" is a whole number (a count or an index): it cannot vary"),
        ));
    }
    Ok((path, value))
}

/// A variable's distribution with `value` as its mean (or mode), checked.
fn variable(at: &str, v: &VariableDto, value: f64) -> Result<Variable, ApiError> {
    let min = v.min.map(|x| finite(&format!("{at}.min"), x)).transpose()?;
    let max = v.max.map(|x| finite(&format!("{at}.max"), x)).transpose()?;
    if let (Some(a), Some(b)) = (min, max) {
        if a >= b {
            return Err(ApiError::invalid(
                format!("{at}.max"),
                format!("must be greater than min ({a})"),
            ));
        }
    }
    let distribution = distribution(at, v, value, min, max)?;
    let variable = Variable {
        distribution,
        min,
        max,
    };
    if !variable.has_probability() {
        return Err(ApiError::invalid(
            format!("{at}.min"),
            "min and max leave the distribution no probability to sample",
        ));
    }
    Ok(variable)
}

/// A variable's distribution with `value` as its mean (or mode) between `min` and `max`.
fn distribution(
    at: &str,
    v: &VariableDto,
    value: f64,
    min: Option<f64>,
    max: Option<f64>,
) -> Result<Distribution, ApiError> {
    Ok(match v.distribution {
        DistributionDto::Normal => Distribution::Normal {
            mean: value,
            std: std_dev(at, v)?,
        },
        DistributionDto::Lognormal => {
            if value <= 0.0 {
                return Err(ApiError::invalid(
                    format!("{at}.field"),
                    format!("is {value}: a lognormal variable's mean must be positive"),
                ));
            }
            Distribution::Lognormal {
                mean: value,
                std: std_dev(at, v)?,
            }
        }
        DistributionDto::Uniform => {
            no_std(at, v)?;
            let (min, max) = ends(at, min, max)?;
            Distribution::Uniform { min, max }
        }
        DistributionDto::Triangular => {
            no_std(at, v)?;
            let (min, max) = ends(at, min, max)?;
            if !(min..=max).contains(&value) {
                return Err(ApiError::invalid(
                    format!("{at}.field"),
                    format!("is {value}: a triangular variable's mode lies in [min, max]"),
                ));
            }
            Distribution::Triangular {
                min,
                mode: value,
                max,
            }
        }
    })
}

/// A normal or lognormal variable's standard deviation, required and positive.
fn std_dev(at: &str, v: &VariableDto) -> Result<f64, ApiError> {
    let s = v.std.ok_or_else(|| {
        ApiError::invalid(format!("{at}.std"), "is required for this distribution")
    })?;
    within(&format!("{at}.std"), s, Range::greater_than(0.0))
}

/// A uniform or triangular variable's ends, both required.
fn ends(at: &str, min: Option<f64>, max: Option<f64>) -> Result<(f64, f64), ApiError> {
    match (min, max) {
        (Some(a), Some(b)) => Ok((a, b)),
        _ => Err(ApiError::invalid(
            format!("{at}.{}", if min.is_none() { "min" } else { "max" }),
            "is required for this distribution (its end)",
        )),
    }
}

/// A uniform or triangular variable takes no standard deviation.
fn no_std(at: &str, v: &VariableDto) -> Result<(), ApiError> {
    match v.std {
        Some(_) => Err(ApiError::invalid(
            format!("{at}.std"),
            "is for normal and lognormal: min and max set this distribution",
        )),
        None => Ok(()),
    }
}

/// The correlation matrix of `dto`'s pairs (empty without any), positive definite.
fn correlations(dto: &ProbabilisticDto, paths: &[JsonPath]) -> Result<Vec<f64>, ApiError> {
    let pairs = dto.correlations.as_deref().unwrap_or_default();
    if pairs.is_empty() {
        return Ok(Vec::new());
    }
    let k = paths.len();
    let mut rho = vec![0.0; k * k];
    (0..k).for_each(|i| rho[i * k + i] = 1.0);
    let mut given: Vec<(usize, usize)> = Vec::with_capacity(pairs.len());
    for (n, pair) in pairs.iter().enumerate() {
        let at = format!("probabilistic.correlations[{n}]");
        let index = |name: &str| {
            paths.iter().position(|p| p.text == name).ok_or_else(|| {
                ApiError::invalid(
                    format!("{at}.fields"),
                    format!("\"{name}\" is not one of the variables' fields"),
                )
            })
        };
        let (i, j) = (index(&pair.fields[0])?, index(&pair.fields[1])?);
        if i == j {
            return Err(ApiError::invalid(
                format!("{at}.fields"),
                "names one variable twice: a correlation is between two",
            ));
        }
        if given.contains(&(i.min(j), i.max(j))) {
            return Err(ApiError::invalid(
                format!("{at}.fields"),
                "this pair's correlation is already given",
            ));
        }
        let c = within(&format!("{at}.coefficient"), pair.coefficient, CORRELATION)?;
        given.push((i.min(j), i.max(j)));
        rho[i * k + j] = c;
        rho[j * k + i] = c;
    }
    cholesky(&rho, k)
        .map_err(|e| ApiError::invalid("probabilistic.correlations", e.to_string()))?;
    Ok(rho)
}
