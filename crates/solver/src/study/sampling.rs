//! Uncertain inputs and their samples: normal, lognormal (by the mean and standard deviation of
//! the variable itself), uniform and triangular distributions, truncated to [min, max] where
//! given; correlated through a Gaussian copula (the normal scores z = L·ε with L the Cholesky
//! factor of the correlation matrix); drawn by Monte Carlo or Latin hypercube sampling from a
//! seed (ChaCha8: the same seed gives the same samples on any machine).
//!
//! Each sample's value is F⁻¹(F(a) + Φ(z)·(F(b) − F(a))): the quantile of the truncated
//! distribution at the copula's uniform score.

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};

use super::normal;

/// A variable's distribution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Distribution {
    /// Normal with this mean and standard deviation (> 0).
    Normal {
        /// The mean.
        mean: f64,
        /// The standard deviation.
        std: f64,
    },
    /// Lognormal whose values have this mean (> 0) and standard deviation (> 0).
    Lognormal {
        /// The mean of the variable.
        mean: f64,
        /// The standard deviation of the variable.
        std: f64,
    },
    /// Uniform on [min, max].
    Uniform {
        /// Lower end.
        min: f64,
        /// Upper end (> min).
        max: f64,
    },
    /// Triangular on [min, max] with its mode between.
    Triangular {
        /// Lower end.
        min: f64,
        /// The mode, min ≤ mode ≤ max.
        mode: f64,
        /// Upper end (> min).
        max: f64,
    },
}

impl Distribution {
    /// F(x).
    pub fn cdf(&self, x: f64) -> f64 {
        match *self {
            Self::Normal { mean, std } => normal::cdf((x - mean) / std),
            Self::Lognormal { .. } if x <= 0.0 => 0.0,
            Self::Lognormal { .. } => {
                let (mu, sigma) = self.log_parameters();
                normal::cdf((x.ln() - mu) / sigma)
            }
            Self::Uniform { min, max } => ((x - min) / (max - min)).clamp(0.0, 1.0),
            Self::Triangular { min, mode, max } => {
                if x <= min {
                    0.0
                } else if x >= max {
                    1.0
                } else if x <= mode {
                    (x - min).powi(2) / ((max - min) * (mode - min))
                } else {
                    1.0 - (max - x).powi(2) / ((max - min) * (max - mode))
                }
            }
        }
    }

    /// F⁻¹(p), 0 ≤ p ≤ 1.
    pub fn quantile(&self, p: f64) -> f64 {
        match *self {
            Self::Normal { mean, std } => mean + std * normal::quantile(p),
            Self::Lognormal { .. } => {
                let (mu, sigma) = self.log_parameters();
                (mu + sigma * normal::quantile(p)).exp()
            }
            Self::Uniform { min, max } => min + p * (max - min),
            Self::Triangular { min, mode, max } => {
                let split = (mode - min) / (max - min);
                if p <= split {
                    min + (p * (max - min) * (mode - min)).sqrt()
                } else {
                    max - ((1.0 - p) * (max - min) * (max - mode)).sqrt()
                }
            }
        }
    }

    /// μ and σ of ln X for a lognormal X: σ² = ln(1 + V²), μ = ln(mean) − σ²/2.
    fn log_parameters(&self) -> (f64, f64) {
        match *self {
            Self::Lognormal { mean, std } => {
                let s2 = (1.0 + (std / mean).powi(2)).ln();
                (mean.ln() - 0.5 * s2, s2.sqrt())
            }
            _ => (0.0, 1.0),
        }
    }
}

/// An uncertain input: its distribution, truncated to [min, max] where given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Variable {
    /// The distribution.
    pub distribution: Distribution,
    /// Values below are not drawn.
    pub min: Option<f64>,
    /// Values above are not drawn.
    pub max: Option<f64>,
}

impl Variable {
    /// Whether [min, max] leaves the distribution any probability to sample.
    pub fn has_probability(&self) -> bool {
        let d = &self.distribution;
        let lo = self.min.map_or(0.0, |a| d.cdf(a));
        let hi = self.max.map_or(1.0, |b| d.cdf(b));
        hi.partial_cmp(&lo) == Some(std::cmp::Ordering::Greater)
    }

    /// The value at uniform score p: the truncated distribution's quantile.
    pub fn at(&self, p: f64) -> f64 {
        let d = &self.distribution;
        let lo = self.min.map_or(0.0, |a| d.cdf(a));
        let hi = self.max.map_or(1.0, |b| d.cdf(b));
        let x = d.quantile(lo + p * (hi - lo));
        // Rounding in the tails must not leave the interval.
        let x = self.min.map_or(x, |a| x.max(a));
        self.max.map_or(x, |b| x.min(b))
    }
}

/// How the uniform scores are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sampling {
    /// Independent uniform scores.
    MonteCarlo,
    /// One score in each of n equal strata per variable, the strata shuffled per variable.
    LatinHypercube,
}

/// Why a study cannot be sampled.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StudyError {
    /// The correlation matrix is not positive definite (no Gaussian copula has it).
    #[error("the correlation matrix is not positive definite (pivot {pivot} is {value:e})")]
    NotPositiveDefinite {
        /// The variable whose pivot failed.
        pivot: usize,
        /// The pivot's value.
        value: f64,
    },
    /// A truncation leaves no probability: [min, max] misses the distribution.
    #[error("variable {index}: min and max leave no probability to sample")]
    EmptyTruncation {
        /// The variable.
        index: usize,
    },
}

/// The lower-triangular Cholesky factor of the k × k correlation matrix `rho` (row-major).
pub fn cholesky(rho: &[f64], k: usize) -> Result<Vec<f64>, StudyError> {
    let mut l = vec![0.0; k * k];
    for i in 0..k {
        for j in 0..=i {
            let sum: f64 = (0..j).map(|m| l[i * k + m] * l[j * k + m]).sum();
            if i == j {
                let pivot = rho[i * k + i] - sum;
                if pivot <= 1e-12 {
                    return Err(StudyError::NotPositiveDefinite {
                        pivot: i,
                        value: pivot,
                    });
                }
                l[i * k + i] = pivot.sqrt();
            } else {
                l[i * k + j] = (rho[i * k + j] - sum) / l[j * k + j];
            }
        }
    }
    Ok(l)
}

/// `n` samples of `variables` (row-major, n × k) correlated by `rho` (k × k row-major, or
/// empty: independent), drawn by `sampling` from `seed`.
pub fn samples(
    variables: &[Variable],
    rho: &[f64],
    n: usize,
    sampling: Sampling,
    seed: u64,
) -> Result<Vec<f64>, StudyError> {
    let k = variables.len();
    if let Some(index) = variables.iter().position(|v| !v.has_probability()) {
        return Err(StudyError::EmptyTruncation { index });
    }
    let factor = if rho.is_empty() {
        None
    } else {
        Some(cholesky(rho, k)?)
    };
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    // Uniform scores in (0, 1), row-major.
    let mut u = vec![0.0; n * k];
    match sampling {
        Sampling::MonteCarlo => u.iter_mut().for_each(|x| *x = open_unit(&mut rng)),
        Sampling::LatinHypercube => {
            let mut strata: Vec<usize> = (0..n).collect();
            for j in 0..k {
                shuffle(&mut strata, &mut rng);
                for (i, &s) in strata.iter().enumerate() {
                    u[i * k + j] = (s as f64 + open_unit(&mut rng)) / n as f64;
                }
            }
        }
    }
    let mut z = vec![0.0; k];
    for row in u.chunks_mut(k.max(1)) {
        if let Some(l) = &factor {
            z.iter_mut()
                .zip(row.iter())
                .for_each(|(z, &p)| *z = normal::quantile(p));
            for i in (0..k).rev() {
                let correlated: f64 = (0..=i).map(|m| l[i * k + m] * z[m]).sum();
                row[i] = normal::cdf(correlated);
            }
        }
        for (x, v) in row.iter_mut().zip(variables) {
            *x = v.at(*x);
        }
    }
    Ok(u)
}

/// A uniform draw in the open interval (0, 1).
fn open_unit(rng: &mut ChaCha8Rng) -> f64 {
    loop {
        let x: f64 = rng.random();
        if x > 0.0 {
            return x;
        }
    }
}

/// Fisher–Yates.
fn shuffle(items: &mut [usize], rng: &mut ChaCha8Rng) {
    for i in (1..items.len()).rev() {
        let j = rng.random_range(0..=i);
        items.swap(i, j);
    }
}
