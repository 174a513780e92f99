//! What a study's answers add up to: the share that failed (F below the threshold), the mean
//! and standard deviation of the solved ones, both reliability indices and a histogram. Samples
//! without a solution are counted apart: neither safe nor failed.

/// One bar of the histogram: answers in [from, to) (the last bar includes its upper end).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bin {
    /// Lower edge.
    pub from: f64,
    /// Upper edge.
    pub to: f64,
    /// Answers in it.
    pub count: usize,
}

/// The statistics of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// Samples analysed.
    pub samples: usize,
    /// Samples without a solution.
    pub unsolved: usize,
    /// The share of solved samples below the threshold; `None` when none solved.
    pub probability_of_failure: Option<f64>,
    /// Mean of the solved answers.
    pub mean: Option<f64>,
    /// Standard deviation (n − 1) of the solved answers.
    pub std: Option<f64>,
    /// (mean − threshold)/std.
    pub reliability_index_normal: Option<f64>,
    /// ln(mean/√(1 + V²))/√(ln(1 + V²)), V = std/mean (threshold 1).
    pub reliability_index_lognormal: Option<f64>,
    /// `bins` equal bars between the least and the greatest answer.
    pub histogram: Vec<Bin>,
}

/// The statistics of `answers` (None: unsolved) against failure below `threshold`, with a
/// histogram of `bins` bars.
pub fn summarise(answers: &[Option<f64>], threshold: f64, bins: usize) -> Summary {
    let solved: Vec<f64> = answers.iter().flatten().copied().collect();
    let n = solved.len();
    let mean = (n > 0).then(|| solved.iter().sum::<f64>() / n as f64);
    let std = mean
        .filter(|_| n > 1)
        .map(|m| (solved.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt());
    let failed = solved.iter().filter(|&&x| x < threshold).count();
    let normal = match (mean, std) {
        (Some(m), Some(s)) if s > 0.0 => Some((m - threshold) / s),
        _ => None,
    };
    let lognormal = match (mean, std) {
        (Some(m), Some(s)) if s > 0.0 && m > 0.0 => {
            let v2 = (s / m).powi(2);
            Some((m / (1.0 + v2).sqrt() / threshold).ln() / (1.0 + v2).ln().sqrt())
        }
        _ => None,
    };
    Summary {
        samples: answers.len(),
        unsolved: answers.len() - n,
        probability_of_failure: (n > 0).then(|| failed as f64 / n as f64),
        mean,
        std,
        reliability_index_normal: normal,
        reliability_index_lognormal: lognormal,
        histogram: histogram(&solved, bins),
    }
}

/// `bins` equal bars over the range of `values` (one bar when they are all equal).
fn histogram(values: &[f64], bins: usize) -> Vec<Bin> {
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    if values.is_empty() || bins == 0 {
        return Vec::new();
    }
    let bins = if hi > lo { bins } else { 1 };
    let width = (hi - lo) / bins as f64;
    let mut out: Vec<Bin> = (0..bins)
        .map(|i| Bin {
            from: lo + width * i as f64,
            to: if i + 1 == bins {
                hi
            } else {
                lo + width * (i + 1) as f64
            },
            count: 0,
        })
        .collect();
    for &x in values {
        let i = if width > 0.0 {
            (((x - lo) / width) as usize).min(bins - 1)
        } else {
            0
        };
        out[i].count += 1;
    }
    out
}
