//! The arithmetic of one slice's inter-slice resultant Q (model §2.2), and the slice sums of
//! both residuals computed a block of slices at a time.
//!
//! The per-slice work is one division (1/m_α; 1/F is common to all slices); done one slice
//! after the other it is bound by the divider. Stored column-wise in blocks of [`LANES`], the
//! compiler computes a block's slices side by side in vector registers — compiled twice, for
//! the baseline and for the machine's widest vectors (AVX2 where there is one, chosen at run
//! time by `pulp`). Each lane keeps its own partial sums (lane k adds slices k, k + 4, k + 8, …
//! in order), added as (s₀ + s₁) + (s₂ + s₃) at the end: no sum waits for the one before it,
//! as adding the slices one after the other in a single sum did (−5 % of a simple search's
//! time). IEEE arithmetic is exact per lane (and never contracted into fused multiply-adds), so
//! the residuals are bit for bit the same on any machine, and those of the written-out order
//! of the tests; against one sum slice after slice they differ at rounding (a few units in the
//! last place of the sums).

use std::cell::Cell;

use crate::slope::spare;

/// Slices per block.
const LANES: usize = 4;

/// Q of one slice with its derivatives in F and θ, and the denominator m_α (may be ≤ 0: the
/// callers check it). `(sin_t, cos_t)` of θ; sin(α−θ) and cos(α−θ) from the stored sin α,
/// cos α, so that no trigonometry is needed per evaluation.
#[inline(always)]
pub(super) fn resultant(
    (sin_alpha, cos_alpha): (f64, f64),
    a_t: f64,
    resistance: f64,
    tan_phi: f64,
    f: f64,
    (sin_t, cos_t): (f64, f64),
) -> [f64; 4] {
    let d = sin_alpha * cos_t - cos_alpha * sin_t;
    let c = cos_alpha * cos_t + sin_alpha * sin_t;
    // One division per slice: 1/F is the same for every slice (computed once per block
    // loop), 1/m_α serves Q and both derivatives.
    let inverse_f = 1.0 / f;
    let mobilised_tan = tan_phi * inverse_f;
    let numerator = a_t - resistance * inverse_f;
    let m_alpha = c + d * mobilised_tan;
    let inverse_m = 1.0 / m_alpha;
    let q = numerator * inverse_m;
    let inverse_m2 = inverse_m * inverse_m;
    let dq_df =
        (resistance * m_alpha + numerator * d * tan_phi) * (inverse_f * inverse_f) * inverse_m2;
    let dq_dtheta = -numerator * (d - c * mobilised_tan) * inverse_m2;
    [q, dq_df, dq_dtheta, m_alpha]
}

/// One slice's constants as the kernel needs them.
#[derive(Debug, Clone, Copy)]
pub(super) struct Lane {
    pub sin_alpha: f64,
    pub cos_alpha: f64,
    pub a_t: f64,
    pub resistance: f64,
    pub tan_phi: f64,
    /// Base middle relative to the moment centre.
    pub arm: (f64, f64),
}

/// [`LANES`] slices, column by column (a short last block is padded with slices that carry
/// nothing and are left out of the sums).
#[derive(Debug, Clone, Copy, Default)]
struct Block {
    sin_alpha: [f64; LANES],
    cos_alpha: [f64; LANES],
    a_t: [f64; LANES],
    resistance: [f64; LANES],
    tan_phi: [f64; LANES],
    arm_x: [f64; LANES],
    arm_y: [f64; LANES],
}

impl Block {
    /// [`resultant`] of lane k.
    #[inline(always)]
    fn resultant(&self, k: usize, f: f64, trig: (f64, f64)) -> [f64; 4] {
        resultant(
            (self.sin_alpha[k], self.cos_alpha[k]),
            self.a_t[k],
            self.resistance[k],
            self.tan_phi[k],
            f,
            trig,
        )
    }

    /// Lane k's moment arm for inter-slice forces at θ: (x_b − x_c)·sin θ − (y_b − y_c)·cos θ.
    #[inline(always)]
    fn arm(&self, k: usize, (sin_t, cos_t): (f64, f64)) -> f64 {
        self.arm_x[k] * sin_t - self.arm_y[k] * cos_t
    }
}

/// The slice sums of the two residuals and their derivatives, unscaled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Sums {
    pub force: f64,
    pub moment: f64,
    pub d_force: (f64, f64),
    pub d_moment: (f64, f64),
    pub min_m_alpha: f64,
}

/// Every slice's constants in blocks.
#[derive(Debug, Clone)]
pub(super) struct Kernel {
    blocks: Vec<Block>,
    slices: usize,
    /// The machine's vector instructions.
    arch: pulp::Arch,
}

thread_local! {
    /// The blocks of the last kernel dropped on this thread ([`spare`]).
    static SPARE_BLOCKS: Cell<Vec<Block>> = const { Cell::new(Vec::new()) };
}

impl Drop for Kernel {
    fn drop(&mut self) {
        spare::keep(&SPARE_BLOCKS, std::mem::take(&mut self.blocks));
    }
}

impl Kernel {
    pub fn new(lanes: impl ExactSizeIterator<Item = Lane>) -> Self {
        let slices = lanes.len();
        let mut blocks = spare::take(&SPARE_BLOCKS);
        blocks.resize(
            slices.div_ceil(LANES),
            Block {
                // Padding: m_α = 1, Q = 0.
                cos_alpha: [1.0; LANES],
                ..Block::default()
            },
        );
        for (i, lane) in lanes.enumerate() {
            let (b, k) = (&mut blocks[i / LANES], i % LANES);
            b.sin_alpha[k] = lane.sin_alpha;
            b.cos_alpha[k] = lane.cos_alpha;
            b.a_t[k] = lane.a_t;
            b.resistance[k] = lane.resistance;
            b.tan_phi[k] = lane.tan_phi;
            b.arm_x[k] = lane.arm.0;
            b.arm_y[k] = lane.arm.1;
        }
        Self {
            blocks,
            slices,
            arch: pulp::Arch::new(),
        }
    }

    /// Σ Q, `moment_start` + Σ Q·arm, their derivatives in (F, θ) and the least m_α, at F
    /// and θ given by `(sin θ, cos θ)`: the slices added in order.
    pub fn sums(&self, f: f64, trig: (f64, f64), moment_start: f64) -> Sums {
        self.arch.dispatch(Both(At {
            kernel: self,
            f,
            trig,
            moment_start: Some(moment_start),
        }))
    }

    /// One equation of [`Kernel::sums`], bit for bit: Σ Q (`moment_start` `None`) or
    /// `moment_start` + Σ Q·arm, its derivative in F and the least m_α, without the work of
    /// the other equation and of the derivatives in θ.
    pub fn one(&self, f: f64, trig: (f64, f64), moment_start: Option<f64>) -> [f64; 3] {
        self.arch.dispatch(One(At {
            kernel: self,
            f,
            trig,
            moment_start,
        }))
    }

    /// [`Kernel::sums`], compiled into each caller (the dispatch's vector variants).
    #[inline(always)]
    fn sums_here(&self, f: f64, (sin_t, cos_t): (f64, f64), moment_start: f64) -> Sums {
        let mut force = [0.0; LANES];
        let mut moment = [0.0; LANES];
        let mut d_force = ([0.0; LANES], [0.0; LANES]);
        let mut d_moment = ([0.0; LANES], [0.0; LANES]);
        let mut min_m_alpha = f64::INFINITY;
        for (i, b) in self.blocks.iter().enumerate() {
            // Side by side: each lane's terms.
            let mut q = [0.0; LANES];
            let mut dq_df = [0.0; LANES];
            let mut dq_dt = [0.0; LANES];
            let mut m_alpha = [0.0; LANES];
            let mut arm = [0.0; LANES];
            let mut d_arm = [0.0; LANES];
            for k in 0..LANES {
                [q[k], dq_df[k], dq_dt[k], m_alpha[k]] = b.resultant(k, f, (sin_t, cos_t));
                arm[k] = b.arm(k, (sin_t, cos_t));
                d_arm[k] = b.arm_x[k] * cos_t + b.arm_y[k] * sin_t;
            }
            // Each into its lane's sums (a short last block's padding left out).
            let used = LANES.min(self.slices - i * LANES);
            each_lane(used, |k| {
                force[k] += q[k];
                moment[k] += q[k] * arm[k];
                d_force.0[k] += dq_df[k];
                d_force.1[k] += dq_dt[k];
                d_moment.0[k] += dq_df[k] * arm[k];
                d_moment.1[k] += dq_dt[k] * arm[k] + q[k] * d_arm[k];
            });
            least(&mut min_m_alpha, &m_alpha, used);
        }
        Sums {
            force: total(&force),
            moment: moment_start + total(&moment),
            d_force: (total(&d_force.0), total(&d_force.1)),
            d_moment: (total(&d_moment.0), total(&d_moment.1)),
            min_m_alpha,
        }
    }

    /// [`Kernel::one`], compiled into each caller: the same lanes' sums as
    /// [`Kernel::sums_here`].
    #[inline(always)]
    fn one_here(&self, f: f64, (sin_t, cos_t): (f64, f64), moment_start: Option<f64>) -> [f64; 3] {
        let (mut value, mut slope) = ([0.0; LANES], [0.0; LANES]);
        let mut min_m_alpha = f64::INFINITY;
        for (i, b) in self.blocks.iter().enumerate() {
            let mut q = [0.0; LANES];
            let mut dq_df = [0.0; LANES];
            let mut m_alpha = [0.0; LANES];
            let mut arm = [0.0; LANES];
            for k in 0..LANES {
                [q[k], dq_df[k], _, m_alpha[k]] = b.resultant(k, f, (sin_t, cos_t));
                arm[k] = b.arm(k, (sin_t, cos_t));
            }
            let used = LANES.min(self.slices - i * LANES);
            if moment_start.is_some() {
                each_lane(used, |k| {
                    value[k] += q[k] * arm[k];
                    slope[k] += dq_df[k] * arm[k];
                });
            } else {
                each_lane(used, |k| {
                    value[k] += q[k];
                    slope[k] += dq_df[k];
                });
            }
            least(&mut min_m_alpha, &m_alpha, used);
        }
        [
            moment_start.unwrap_or(0.0) + total(&value),
            total(&slope),
            min_m_alpha,
        ]
    }
}

/// `add(k)` for the first `used` lanes: a whole block with a trip count the compiler knows (one
/// vector step), a short last block lane by lane.
#[inline(always)]
fn each_lane(used: usize, mut add: impl FnMut(usize)) {
    if used == LANES {
        for k in 0..LANES {
            add(k);
        }
    } else {
        for k in 0..used {
            add(k);
        }
    }
}

/// The least m_α so far and that of the first `used` lanes, by comparison: `f64::min`'s handling
/// of NaN cost 2 % of a simple search. Both keep the least so far past a NaN; they can differ
/// only in a zero's sign, which no caller sees (they ask whether the least is positive).
#[inline(always)]
fn least(least: &mut f64, m_alpha: &[f64; LANES], used: usize) {
    for &m in m_alpha.iter().take(used) {
        if m < *least {
            *least = m;
        }
    }
}

/// The lanes' partial sums added: (s₀ + s₁) + (s₂ + s₃).
#[inline(always)]
fn total(sums: &[f64; LANES]) -> f64 {
    (sums[0] + sums[1]) + (sums[2] + sums[3])
}

/// `start` plus the slices' `terms` added as the kernel adds them (slice i into lane i mod
/// [`LANES`], then the lanes): one equation's sum over terms computed elsewhere, bit for bit
/// the kernel's.
pub(super) fn sum_as_lanes(start: f64, terms: &[f64]) -> f64 {
    let mut sums = [0.0; LANES];
    for (i, &t) in terms.iter().enumerate() {
        sums[i % LANES] += t;
    }
    start + total(&sums)
}

/// The kernel at (F, θ), for [`pulp::Arch::dispatch`], which compiles what it is given once
/// per instruction set (every step inlined into each, so that each is vectorised for its own).
struct At<'a> {
    kernel: &'a Kernel,
    f: f64,
    trig: (f64, f64),
    moment_start: Option<f64>,
}

/// [`Kernel::sums`] at a point.
struct Both<'a>(At<'a>);

/// [`Kernel::one`] at a point.
struct One<'a>(At<'a>);

impl pulp::WithSimd for Both<'_> {
    type Output = Sums;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) -> Sums {
        let At {
            kernel,
            f,
            trig,
            moment_start,
        } = self.0;
        kernel.sums_here(f, trig, moment_start.unwrap_or(0.0))
    }
}

impl pulp::WithSimd for One<'_> {
    type Output = [f64; 3];

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) -> [f64; 3] {
        let At {
            kernel,
            f,
            trig,
            moment_start,
        } = self.0;
        kernel.one_here(f, trig, moment_start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sums as the kernel orders them — slice i into partial sum i mod 4, the four added as
    /// (s₀ + s₁) + (s₂ + s₃) — the arithmetic written out as model §2.2 gives it with 1/F and
    /// 1/m_α multiplied in as the kernel does.
    fn one_by_one(lanes: &[Lane], f: f64, theta: f64, start: f64) -> Sums {
        sums_written_out(lanes, f, theta, start, (false, true))
    }

    /// The sums written out: with a division for each quotient (`divided`) or as the kernel
    /// orders it, and in four partial sums (`lanewise`) or one sum slice after slice.
    fn sums_written_out(
        lanes: &[Lane],
        f: f64,
        theta: f64,
        start: f64,
        (divided, lanewise): (bool, bool),
    ) -> Sums {
        let (sin_t, cos_t) = theta.sin_cos();
        // Per partial sum: force, moment, d_force (F, θ), d_moment (F, θ).
        let mut partial = [[0.0f64; 6]; 4];
        let mut min_m_alpha = f64::INFINITY;
        for (i, l) in lanes.iter().enumerate() {
            let d = l.sin_alpha * cos_t - l.cos_alpha * sin_t;
            let c = l.cos_alpha * cos_t + l.sin_alpha * sin_t;
            let (q, dq_df, dq_dt, m) = if divided {
                let num = l.a_t - l.resistance / f;
                let m = c + d * l.tan_phi / f;
                let q = num / m;
                let dq_df = (l.resistance * m + num * d * l.tan_phi) / (f * f * m * m);
                let dq_dt = -num * (d - c * l.tan_phi / f) / (m * m);
                (q, dq_df, dq_dt, m)
            } else {
                let (inv_f, tan_f) = (1.0 / f, l.tan_phi * (1.0 / f));
                let num = l.a_t - l.resistance * inv_f;
                let m = c + d * tan_f;
                let inv_m = 1.0 / m;
                let q = num * inv_m;
                let dq_df =
                    (l.resistance * m + num * d * l.tan_phi) * (inv_f * inv_f) * (inv_m * inv_m);
                let dq_dt = -num * (d - c * tan_f) * (inv_m * inv_m);
                (q, dq_df, dq_dt, m)
            };
            let arm = l.arm.0 * sin_t - l.arm.1 * cos_t;
            let d_arm = l.arm.0 * cos_t + l.arm.1 * sin_t;
            let terms = [
                q,
                q * arm,
                dq_df,
                dq_dt,
                dq_df * arm,
                dq_dt * arm + q * d_arm,
            ];
            let sums = &mut partial[if lanewise { i % 4 } else { 0 }];
            for (sum, term) in sums.iter_mut().zip(terms) {
                *sum += term;
            }
            min_m_alpha = min_m_alpha.min(m);
        }
        let total = |j: usize| (partial[0][j] + partial[1][j]) + (partial[2][j] + partial[3][j]);
        Sums {
            force: total(0),
            moment: start + total(1),
            d_force: (total(2), total(3)),
            d_moment: (total(4), total(5)),
            min_m_alpha,
        }
    }

    #[test]
    fn the_least_m_alpha_passes_a_nan_as_f64_min_does() {
        // A slice whose m_α is not a number (its tan φ′ NaN), first, inside a block and last:
        // the least of the others, as `f64::min` gives it, on both paths.
        for nan_at in [0, 2, 4] {
            let lanes: Vec<Lane> = (0..5)
                .map(|i| Lane {
                    sin_alpha: (0.1 * i as f64).sin(),
                    cos_alpha: (0.1 * i as f64).cos(),
                    a_t: 1.0,
                    resistance: 1.0,
                    tan_phi: if i == nan_at { f64::NAN } else { 0.2 },
                    arm: (1.0, -3.0),
                })
                .collect();
            let kernel = Kernel::new(lanes.iter().copied());
            let expected = one_by_one(&lanes, 1.2, 0.3, 0.0).min_m_alpha;
            assert!(expected.is_finite());
            assert_eq!(
                kernel.sums(1.2, 0.3f64.sin_cos(), 0.0).min_m_alpha,
                expected
            );
            assert_eq!(kernel.one(1.2, 0.3f64.sin_cos(), None)[2], expected);
        }
    }

    #[test]
    fn blocks_sum_bit_for_bit_as_written_out() {
        // Every count of slices around the block size, the padding included.
        for n in 1..=13 {
            let lanes: Vec<Lane> = (0..n)
                .map(|i| {
                    let alpha = -0.6 + 1.4 * i as f64 / n as f64;
                    Lane {
                        sin_alpha: alpha.sin(),
                        cos_alpha: alpha.cos(),
                        a_t: 3.0 + (i as f64 * 0.7).sin(),
                        resistance: 1.0 + 0.3 * i as f64,
                        tan_phi: 0.1 * (i % 5) as f64,
                        arm: (-5.0 + i as f64, -9.0 + 0.1 * i as f64),
                    }
                })
                .collect();
            let kernel = Kernel::new(lanes.iter().copied());
            for (f, theta) in [(1.3f64, 0.2f64), (0.7, -0.4), (2.9, 0.0)] {
                let expected = one_by_one(&lanes, f, theta, -0.25);
                // The quotients multiplied in and summed in four parts are the divided ones
                // summed slice after slice, to rounding.
                let divided = sums_written_out(&lanes, f, theta, -0.25, (true, false));
                let close = |a: f64, b: f64| (a - b).abs() <= 1e-13 * (1.0 + b.abs());
                assert!(
                    close(expected.force, divided.force)
                        && close(expected.moment, divided.moment)
                        && close(expected.d_force.0, divided.d_force.0)
                        && close(expected.d_force.1, divided.d_force.1)
                        && close(expected.d_moment.0, divided.d_moment.0)
                        && close(expected.d_moment.1, divided.d_moment.1)
                        && close(expected.min_m_alpha, divided.min_m_alpha),
                    "n = {n}: {expected:?} against {divided:?}"
                );
                assert_eq!(
                    kernel.sums(f, theta.sin_cos(), -0.25),
                    expected,
                    "n = {n}, F = {f}, θ = {theta}"
                );
                assert_eq!(
                    kernel.one(f, theta.sin_cos(), None),
                    [expected.force, expected.d_force.0, expected.min_m_alpha]
                );
                assert_eq!(
                    kernel.one(f, theta.sin_cos(), Some(-0.25)),
                    [expected.moment, expected.d_moment.0, expected.min_m_alpha]
                );
            }
        }
    }
}
