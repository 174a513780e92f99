//! Derivative-free minimisation in a few variables: the simplex method of Nelder & Mead (1965),
//! with the standard coefficients (reflection 1, expansion 2, contraction ½, shrink ½; Lagarias
//! et al. 1998 for their role). The critical-circle search uses it because F over the centres is
//! non-smooth and has shallow local minima.

/// Reflection coefficient ρ: the worst vertex is mirrored through the centroid of the others.
const REFLECTION: f64 = 1.0;
/// Expansion coefficient χ: a successful reflection is pushed this many times as far.
const EXPANSION: f64 = 2.0;
/// Contraction coefficient γ: a failed reflection is pulled back to this fraction.
const CONTRACTION: f64 = 0.5;
/// Shrink coefficient σ: every vertex moves this fraction of the way to the best one.
const SHRINK: f64 = 0.5;

/// The best point found by [`nelder_mead`].
#[derive(Debug, Clone, PartialEq)]
pub struct Minimum {
    /// The smallest value found.
    pub value: f64,
    /// Where it was found.
    pub point: Vec<f64>,
    /// Evaluations of the function spent.
    pub evaluations: usize,
}

/// Minimises `f` from the simplex of `start` and `start + step_i·e_i`; stops when the simplex is
/// smaller than `x_tolerance` (largest coordinate distance from the best vertex) or after about
/// `max_evaluations` evaluations.
pub fn nelder_mead(
    f: impl Fn(&[f64]) -> f64,
    start: &[f64],
    step: &[f64],
    x_tolerance: f64,
    max_evaluations: usize,
) -> Minimum {
    nelder_mead_to(f, start, step, x_tolerance, 0.0, max_evaluations)
}

/// [`nelder_mead`], stopping too when the values at the simplex's vertices differ by less than
/// `f_tolerance` times the best (relative): `f` is known to no better than that, so a smaller
/// simplex would only follow its rounding.
pub fn nelder_mead_to(
    f: impl Fn(&[f64]) -> f64,
    start: &[f64],
    step: &[f64],
    x_tolerance: f64,
    f_tolerance: f64,
    max_evaluations: usize,
) -> Minimum {
    let n = start.len();
    let mut simplex = initial_simplex(start, step);
    let mut values: Vec<f64> = simplex.iter().map(|p| f(p)).collect();
    let mut evaluations = n + 1;
    while evaluations < max_evaluations {
        sort_by_value(&mut simplex, &mut values);
        let size = size_about_best(&simplex);
        let spread = values[n] - values[0];
        if size <= x_tolerance || spread < f_tolerance * values[0].abs() {
            break;
        }
        let centroid = centroid_of_best(&simplex);
        let along = |t: f64| -> Vec<f64> {
            (0..n)
                .map(|d| centroid[d] + t * (simplex[n][d] - centroid[d]))
                .collect()
        };
        let reflected = along(-REFLECTION);
        let fr = f(&reflected);
        evaluations += 1;
        if fr < values[0] {
            let expanded = along(-REFLECTION * EXPANSION);
            let fe = f(&expanded);
            evaluations += 1;
            if fe < fr {
                simplex[n] = expanded;
                values[n] = fe;
            } else {
                simplex[n] = reflected;
                values[n] = fr;
            }
        } else if fr < values[n - 1] {
            simplex[n] = reflected;
            values[n] = fr;
        } else {
            let (contracted, fc) = if fr < values[n] {
                let c = along(-REFLECTION * CONTRACTION);
                let fc = f(&c);
                (c, fc)
            } else {
                let c = along(CONTRACTION);
                let fc = f(&c);
                (c, fc)
            };
            evaluations += 1;
            if fc < values[n].min(fr) {
                simplex[n] = contracted;
                values[n] = fc;
            } else {
                shrink(&mut simplex, &mut values, &f);
                evaluations += n;
            }
        }
    }
    let best = (0..=n)
        .min_by(|&a, &b| values[a].total_cmp(&values[b]))
        .unwrap_or(0);
    Minimum {
        value: values[best],
        point: simplex[best].clone(),
        evaluations,
    }
}

/// The simplex of `start` and `start + step_i·e_i`.
fn initial_simplex(start: &[f64], step: &[f64]) -> Vec<Vec<f64>> {
    let n = start.len();
    let mut simplex: Vec<Vec<f64>> = vec![start.to_vec()];
    for i in 0..n {
        let mut p = start.to_vec();
        p[i] += step[i];
        simplex.push(p);
    }
    simplex
}

/// Orders the vertices and their values from the best (smallest value) to the worst.
#[inline]
fn sort_by_value(simplex: &mut Vec<Vec<f64>>, values: &mut Vec<f64>) {
    let n = simplex.len() - 1;
    let mut order: Vec<usize> = (0..=n).collect();
    order.sort_by(|&a, &b| values[a].total_cmp(&values[b]));
    *simplex = order.iter().map(|&i| simplex[i].clone()).collect();
    *values = order.iter().map(|&i| values[i]).collect();
}

/// The simplex's size: the largest coordinate distance of a vertex from the best (the first).
#[inline]
fn size_about_best(simplex: &[Vec<f64>]) -> f64 {
    simplex[1..]
        .iter()
        .map(|p| {
            p.iter()
                .zip(&simplex[0])
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

/// The centroid of every vertex but the worst (the last).
#[inline]
fn centroid_of_best(simplex: &[Vec<f64>]) -> Vec<f64> {
    let n = simplex.len() - 1;
    (0..n)
        .map(|d| simplex[..n].iter().map(|p| p[d]).sum::<f64>() / n as f64)
        .collect()
}

/// Shrinks every vertex towards the best point (the first) and evaluates `f` at each moved one.
#[inline]
fn shrink(simplex: &mut [Vec<f64>], values: &mut [f64], f: &impl Fn(&[f64]) -> f64) {
    let best = simplex[0].clone();
    for (point, value) in simplex.iter_mut().zip(values.iter_mut()).skip(1) {
        for (x, b) in point.iter_mut().zip(&best) {
            *x = b + SHRINK * (*x - b);
        }
        *value = f(point);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nelder_mead_finds_the_minimum_of_a_quadratic() {
        // Minimum 0 at (1, −2), found to 1e-7 (the simplex tolerance is 1e-10).
        let f = |v: &[f64]| (v[0] - 1.0).powi(2) + 3.0 * (v[1] + 2.0).powi(2);
        let m = nelder_mead(f, &[0.0, 0.0], &[0.5, 0.5], 1e-10, 1000);
        assert!(
            m.value < 1e-15 && (m.point[0] - 1.0).abs() < 1e-7 && (m.point[1] + 2.0).abs() < 1e-7
        );
    }

    #[test]
    fn nelder_mead_stops_where_the_values_no_longer_differ() {
        // 1 + q(v): the vertices' values differ by less than 1e-10 (relative) once the simplex
        // is ~1e-5 across, long before it is 1e-12 across.
        let f = |v: &[f64]| 1.0 + (v[0] - 1.0).powi(2) + 3.0 * (v[1] + 2.0).powi(2);
        let by_x = nelder_mead(f, &[0.0, 0.0], &[0.5, 0.5], 1e-12, 5000);
        let by_f = nelder_mead_to(f, &[0.0, 0.0], &[0.5, 0.5], 1e-12, 1e-10, 5000);
        assert!(by_f.evaluations < by_x.evaluations, "{by_f:?} {by_x:?}");
        // Stopped within the tolerance of the minimum value 1.
        assert!(by_f.value - 1.0 <= 1e-10 && by_f.value >= 1.0);
        assert!((by_f.point[0] - 1.0).abs() < 1e-4 && (by_f.point[1] + 2.0).abs() < 1e-4);
        // A zero tolerance is `nelder_mead`.
        let zero = nelder_mead_to(f, &[0.0, 0.0], &[0.5, 0.5], 1e-12, 0.0, 5000);
        assert_eq!(zero, by_x);
    }
}
