//! The scan behind [`Equations::f_at_theta`] when Newton fails: the first sign change (negative
//! to non-negative) of one equation's residual over log-spaced factors, without evaluating every
//! sample where none can be.
//!
//! At fixed θ every slice term of either residual is monotone in F on the admissible interval:
//! Q = (a_t − R/F) / (c + D/F) is, in u = 1/F, a Möbius map (a_t − R·u) / (c + D·u) with
//! dQ/du = −(R·c + D·a_t) / (c + D·u)², of one sign while the denominator m_α stays positive;
//! the moment terms are Q times an arm fixed by θ. So over samples i..j the residual lies
//! between Σ min and Σ max of the terms at i and j, and a stretch whose bounds keep one sign
//! (clear of rounding) has that sign at every sample in it. The samples, the crossing found and
//! the values handed to Brent's method are those of a full scan, bit for bit.

/// Log-spaced samples over the admissible interval (49 values, both ends included).
pub(super) const SAMPLES: usize = 48;

/// Bounds closer to zero than this fraction of the terms' size are rounding: look closer.
const ROUNDING_MARGIN: f64 = 1e-10;

/// The sign of a sample: negative, non-negative, or not a number.
#[derive(Clone, Copy, PartialEq)]
enum Sign {
    Negative,
    NonNegative,
    Undefined,
}

fn sign_of(value: f64) -> Sign {
    if !value.is_finite() {
        Sign::Undefined
    } else if value < 0.0 {
        Sign::Negative
    } else {
        Sign::NonNegative
    }
}

/// The residual of one equation at fixed θ, term by term, over the sample grid: the residual
/// at F is (constant + Σ terms(F)) / scale, the terms summed as the kernel sums them.
pub(super) struct Scan<T: FnMut(f64, &mut Vec<f64>)> {
    terms_at: T,
    constant: f64,
    scale: f64,
    lo: f64,
    hi: f64,
    ratio: f64,
    terms: Vec<Option<Vec<f64>>>,
    /// Samples evaluated.
    pub evaluations: usize,
}

impl<T: FnMut(f64, &mut Vec<f64>)> Scan<T> {
    /// `terms_at(F, out)` pushes the terms at F onto `out`, each monotone in F on [lo, hi].
    pub fn new(terms_at: T, constant: f64, scale: f64, (lo, hi): (f64, f64)) -> Self {
        Self {
            terms_at,
            constant,
            scale,
            lo,
            hi,
            ratio: (hi / lo).powf(1.0 / SAMPLES as f64),
            terms: vec![None; SAMPLES + 1],
            evaluations: 0,
        }
    }

    /// F at sample i, as the full scan places it.
    pub fn factor(&self, i: usize) -> f64 {
        match i {
            0 => self.lo,
            SAMPLES => self.hi,
            _ => self.lo * self.ratio.powi(i as i32),
        }
    }

    /// The terms at sample i.
    fn terms(&mut self, i: usize) -> &[f64] {
        if self.terms[i].is_none() {
            let mut values = Vec::new();
            let f = self.factor(i);
            (self.terms_at)(f, &mut values);
            self.terms[i] = Some(values);
            self.evaluations += 1;
        }
        self.terms[i].as_deref().unwrap_or(&[])
    }

    /// The residual at sample i, summed as the kernel sums it.
    pub fn value(&mut self, i: usize) -> f64 {
        let constant = self.constant;
        super::kernel::sum_as_lanes(constant, self.terms(i)) / self.scale
    }

    /// The signs of samples i..=j when the bounds settle them, `None` when they do not.
    fn uniform_sign(&mut self, i: usize, j: usize) -> Option<Sign> {
        let constant = self.constant;
        self.terms(i);
        self.terms(j);
        let (Some(a), Some(b)) = (&self.terms[i], &self.terms[j]) else {
            return None;
        };
        let (mut lower, mut upper, mut size) = (constant, constant, constant.abs());
        for (&x, &y) in a.iter().zip(b) {
            lower += x.min(y);
            upper += x.max(y);
            size += x.abs().max(y.abs());
        }
        let margin = ROUNDING_MARGIN * size;
        if !(lower.is_finite() && upper.is_finite() && size.is_finite()) {
            None
        } else if lower > margin {
            Some(Sign::NonNegative)
        } else if upper < -margin {
            Some(Sign::Negative)
        } else {
            None
        }
    }

    /// The first pair of neighbouring samples (a, f(a), b, f(b)) with f(a) < 0 ≤ f(b), both
    /// finite: stretches are settled by their bounds or halved, left to right.
    pub fn first_crossing(&mut self) -> Option<(f64, f64, f64, f64)> {
        let mut previous = sign_of(self.value(0));
        // Stretches still to settle, the leftmost on top.
        let mut stack = vec![(0, SAMPLES)];
        while let Some((i, j)) = stack.pop() {
            if j - i > 1 {
                if let Some(sign) = self.uniform_sign(i, j) {
                    // Every sample in i..=j has this sign (sample i's is `previous`): no
                    // crossing inside.
                    previous = sign;
                    continue;
                }
                let m = (i + j) / 2;
                stack.push((m, j));
                stack.push((i, m));
                continue;
            }
            let sign = sign_of(self.value(j));
            if previous == Sign::Negative && sign == Sign::NonNegative {
                return Some(self.pair(j));
            }
            previous = sign;
        }
        None
    }

    /// Samples k − 1 and k with their residuals.
    fn pair(&mut self, k: usize) -> (f64, f64, f64, f64) {
        let (fa, fb) = (self.value(k - 1), self.value(k));
        (self.factor(k - 1), fa, self.factor(k), fb)
    }
}
