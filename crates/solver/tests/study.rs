//! Probabilistic sampling and statistics (model §9.2) against what must hold: sample moments
//! within their standard errors of the distributions' own, Latin hypercube strata filled once
//! each, truncation respected with the truncated normal's mean, correlations within their
//! standard error (and against an independent Box–Muller sampler written here), the probability
//! of failure of a linear answer within its binomial standard error of Φ((1 − mean)/std).
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::time::Duration;

use thrustline_solver::budget::Budget;
use thrustline_solver::study;
use thrustline_solver::study::normal;
use thrustline_solver::study::sampling::samples;
use thrustline_solver::study::{run, summarise, Distribution, Sampling, StudyError, Variable};

fn free(distribution: Distribution) -> Variable {
    Variable {
        distribution,
        min: None,
        max: None,
    }
}

fn moments(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    let mean = xs.iter().sum::<f64>() / n;
    let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, var.sqrt())
}

fn column(rows: &[f64], k: usize, j: usize) -> Vec<f64> {
    rows.chunks(k).map(|r| r[j]).collect()
}

#[test]
fn monte_carlo_moments_lie_within_their_standard_errors() {
    let n = 20_000;
    let vars = [
        free(Distribution::Normal {
            mean: 10.0,
            std: 2.0,
        }),
        free(Distribution::Lognormal {
            mean: 30.0,
            std: 3.0,
        }),
        free(Distribution::Uniform { min: 2.0, max: 5.0 }),
        free(Distribution::Triangular {
            min: 1.0,
            mode: 2.0,
            max: 6.0,
        }),
    ];
    let rows = samples(&vars, &[], n, Sampling::MonteCarlo, 7).unwrap();
    let expected = [
        (10.0, 2.0),
        (30.0, 3.0),
        (3.5, 3.0 / 12f64.sqrt()),
        // Triangular: (a + b + c)/3 and √((a² + b² + c² − ab − ac − bc)/18).
        (
            3.0,
            ((1.0f64 + 4.0 + 36.0 - 2.0 - 6.0 - 12.0) / 18.0).sqrt(),
        ),
    ];
    for (j, &(mean, std)) in expected.iter().enumerate() {
        let (m, s) = moments(&column(&rows, 4, j));
        let se = std / (n as f64).sqrt();
        assert!(
            (m - mean).abs() < 4.0 * se,
            "variable {j}: mean {m} against {mean}"
        );
        // The standard error of s is about σ/√(2n) (normal-like tails).
        assert!(
            (s - std).abs() < 6.0 * std / (2.0 * n as f64).sqrt(),
            "variable {j}: std {s} against {std}"
        );
    }
}

#[test]
fn latin_hypercube_fills_each_stratum_once() {
    let n = 500;
    let vars = [
        free(Distribution::Normal {
            mean: 0.0,
            std: 1.0,
        }),
        free(Distribution::Triangular {
            min: 0.0,
            mode: 1.0,
            max: 4.0,
        }),
    ];
    let rows = samples(&vars, &[], n, Sampling::LatinHypercube, 3).unwrap();
    for (j, v) in vars.iter().enumerate() {
        let mut strata: Vec<usize> = column(&rows, 2, j)
            .iter()
            .map(|&x| (v.distribution.cdf(x) * n as f64) as usize)
            .collect();
        strata.sort_unstable();
        assert_eq!(strata, (0..n).collect::<Vec<_>>(), "variable {j}");
    }
    // Stratified: the sample mean of the normal is far closer than Monte Carlo's 1/√n.
    let (m, _) = moments(&column(&rows, 2, 0));
    assert!(m.abs() < 0.01, "{m}");
}

#[test]
fn truncation_is_respected_and_gives_the_truncated_mean() {
    let n = 20_000;
    let v = Variable {
        distribution: Distribution::Normal {
            mean: 5.0,
            std: 2.0,
        },
        min: Some(4.0),
        max: Some(9.0),
    };
    let xs = samples(&[v], &[], n, Sampling::MonteCarlo, 11).unwrap();
    assert!(xs.iter().all(|&x| (4.0..=9.0).contains(&x)));
    // μ + σ(φ(α) − φ(β))/(Φ(β) − Φ(α)), α = (4 − 5)/2, β = (9 − 5)/2.
    let (a, b) = (-0.5, 2.0);
    let z = normal::cdf(b) - normal::cdf(a);
    let mean = 5.0 + 2.0 * (normal::pdf(a) - normal::pdf(b)) / z;
    let (m, s) = moments(&xs);
    assert!(
        (m - mean).abs() < 4.0 * s / (n as f64).sqrt(),
        "{m} against {mean}"
    );
}

/// Standard normal pairs by Box–Muller from an LCG, correlated by the 2 × 2 Cholesky factor
/// written out: an independent sampler.
fn box_muller_pairs(n: usize, rho: f64) -> Vec<(f64, f64)> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut uniform = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    };
    (0..n)
        .map(|_| {
            let (u1, u2) = (uniform(), uniform());
            let r = (-2.0 * u1.ln()).sqrt();
            let (z1, z2) = (
                r * (2.0 * std::f64::consts::PI * u2).cos(),
                r * (2.0 * std::f64::consts::PI * u2).sin(),
            );
            (z1, rho * z1 + (1.0 - rho * rho).sqrt() * z2)
        })
        .collect()
}

fn pearson(pairs: &[(f64, f64)]) -> f64 {
    let n = pairs.len() as f64;
    let (mx, my) = (
        pairs.iter().map(|p| p.0).sum::<f64>() / n,
        pairs.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxy: f64 = pairs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pairs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let syy: f64 = pairs.iter().map(|p| (p.1 - my).powi(2)).sum();
    sxy / (sxx * syy).sqrt()
}

#[test]
fn correlated_normals_have_the_asked_correlation() {
    let (n, rho) = (20_000, -0.5);
    let vars = [
        free(Distribution::Normal {
            mean: 10.0,
            std: 2.0,
        }),
        free(Distribution::Normal {
            mean: 30.0,
            std: 3.0,
        }),
    ];
    let rows = samples(&vars, &[1.0, rho, rho, 1.0], n, Sampling::MonteCarlo, 5).unwrap();
    let ours: Vec<(f64, f64)> = rows.chunks(2).map(|r| (r[0], r[1])).collect();
    let theirs = box_muller_pairs(n, rho);
    // The standard error of r is about (1 − ρ²)/√n.
    let se = (1.0 - rho * rho) / (n as f64).sqrt();
    let (r_ours, r_theirs) = (pearson(&ours), pearson(&theirs));
    assert!((r_ours - rho).abs() < 4.0 * se, "{r_ours}");
    assert!((r_theirs - rho).abs() < 4.0 * se, "{r_theirs}");
    assert!(
        (r_ours - r_theirs).abs() < 6.0 * se,
        "{r_ours} against {r_theirs}"
    );
    // Correlation keeps each variable's own distribution.
    let (m, s) = moments(&column(&rows, 2, 1));
    assert!(
        (m - 30.0).abs() < 4.0 * 3.0 / (n as f64).sqrt() && (s - 3.0).abs() < 0.1,
        "{m} {s}"
    );
}

#[test]
fn a_matrix_that_is_not_positive_definite_is_refused() {
    let v = free(Distribution::Normal {
        mean: 0.0,
        std: 1.0,
    });
    let rho = [1.0, 0.9, 0.9, 0.9, 1.0, -0.9, 0.9, -0.9, 1.0];
    let error = samples(&[v, v, v], &rho, 10, Sampling::MonteCarlo, 1).unwrap_err();
    assert!(
        matches!(error, StudyError::NotPositiveDefinite { pivot: 2, .. }),
        "{error:?}"
    );
    let empty = Variable {
        min: Some(100.0),
        max: Some(101.0),
        ..v
    };
    assert!(matches!(
        samples(&[empty], &[], 10, Sampling::MonteCarlo, 1),
        Err(StudyError::EmptyTruncation { index: 0 })
    ));
}

#[test]
fn the_same_seed_gives_the_same_samples() {
    let v = [free(Distribution::Lognormal {
        mean: 3.0,
        std: 1.0,
    })];
    let a = samples(&v, &[], 100, Sampling::LatinHypercube, 42).unwrap();
    let b = samples(&v, &[], 100, Sampling::LatinHypercube, 42).unwrap();
    let c = samples(&v, &[], 100, Sampling::LatinHypercube, 43).unwrap();
    assert_eq!(a, b);
    assert_ne!(a, c);
}

#[test]
fn a_linear_answer_fails_as_often_as_its_normal_says() {
    // F = 1.2 + 0.1·Z: PF = Φ(−2), mean 1.2, std 0.1, β = 2.
    let n = 40_000;
    let v = [free(Distribution::Normal {
        mean: 0.0,
        std: 1.0,
    })];
    let rows = samples(&v, &[], n, Sampling::MonteCarlo, 9).unwrap();
    let (answers, stop) = run(
        &study::run::rows(&rows, 1),
        |x: &&[f64]| Some(1.2 + 0.1 * x[0]),
        &Budget::unlimited(),
        &|_, _| {},
    );
    assert!(stop.is_ok());
    let s = summarise(&answers, 1.0, 20);
    let pf = normal::cdf(-2.0);
    let se = (pf * (1.0 - pf) / n as f64).sqrt();
    assert!(
        (s.probability_of_failure.unwrap() - pf).abs() < 4.0 * se,
        "{s:?}"
    );
    assert!((s.mean.unwrap() - 1.2).abs() < 4.0 * 0.1 / (n as f64).sqrt());
    assert!((s.reliability_index_normal.unwrap() - 2.0).abs() < 0.05);
    assert_eq!(s.histogram.iter().map(|b| b.count).sum::<usize>(), n);
    assert_eq!(s.histogram.len(), 20);
    assert_eq!(s.unsolved, 0);
    // The lognormal index by its formula, from the sample's own mean and std.
    let (m, sd) = (s.mean.unwrap(), s.std.unwrap());
    let v2 = (sd / m).powi(2);
    let beta = (m / (1.0 + v2).sqrt()).ln() / (1.0 + v2).ln().sqrt();
    assert!((s.reliability_index_lognormal.unwrap() - beta).abs() < 1e-12);
}

#[test]
fn unsolved_samples_are_neither_safe_nor_failed() {
    let answers = [Some(0.5), None, Some(1.5), None, Some(2.5)];
    let s = summarise(&answers, 1.0, 2);
    assert_eq!((s.samples, s.unsolved), (5, 2));
    assert_eq!(s.probability_of_failure, Some(1.0 / 3.0));
    assert_eq!(
        s.histogram.iter().map(|b| b.count).collect::<Vec<_>>(),
        [1, 2]
    );
}

#[test]
fn a_spent_budget_stops_the_study() {
    let v = [free(Distribution::Uniform { min: 0.0, max: 1.0 })];
    let rows = samples(&v, &[], 1000, Sampling::MonteCarlo, 1).unwrap();
    let budget = Budget::with_time_limit(Duration::from_millis(20));
    let (answers, stop) = run(
        &study::run::rows(&rows, 1),
        |x: &&[f64]| {
            std::thread::sleep(Duration::from_millis(2));
            Some(x[0])
        },
        &budget,
        &|_, _| {},
    );
    assert!(stop.is_err());
    assert!(answers.len() < 1000, "{}", answers.len());
}
