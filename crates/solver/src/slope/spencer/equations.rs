//! Spencer's two equations for one slip surface, their derivatives in (F, θ), and F from either
//! equation alone at a fixed θ (model §2.2; the equations are written out in [`super`]).

use std::cell::Cell;

use super::kernel::{resultant, Kernel, Lane, Sums};
use super::scan::Scan;
use crate::numerics::brent;
use crate::slope::slices::{BaseSlice, SliceModel};
use crate::slope::spare;

/// The relative Newton step after which a root started from a neighbour's F is taken (see
/// [`Equations::f_at_theta_from`]).
const STARTING_STEP: f64 = 1e-8;

/// Range of admissible factors of safety searched by the bracketing steps.
const F_RANGE: (f64, f64) = (1e-6, 1e6);

/// Per-slice constants of the equations, computed once.
#[derive(Debug, Clone, Copy)]
pub(super) struct SliceTerms {
    /// sin α and cos α, so that the angle differences need no trigonometry per evaluation.
    pub sin_alpha: f64,
    pub cos_alpha: f64,
    pub a_t: f64,
    pub a_n: f64,
    pub pore_force: f64,
    /// c'·l + (A_n − u·l)·tan φ': the resisting force at F = 1 without the Q term.
    pub resistance: f64,
    /// c'·l: the base's strength without normal stress.
    pub cohesion: f64,
    /// Whether a known force acts on this slice (`model.loads`).
    pub loaded: bool,
    pub tan_phi: f64,
    /// Base middle relative to the circle centre.
    pub arm: (f64, f64),
    /// Moment of the known forces about the base middle.
    pub moment: f64,
}

impl SliceTerms {
    /// One slice's constants before the known loads (`model.loads`) are added to them.
    #[inline]
    pub fn unloaded(model: &SliceModel, s: &BaseSlice) -> Self {
        let weight = s.weight;
        let tan_phi = s.tan_phi;
        let (sin_a, cos_a) = s.base_sin_cos;
        let fx = -model.seismic.kh * weight;
        let fy = -(1.0 + model.seismic.kv) * weight;
        let pore_force = s.pore_pressure * s.base_length;
        let a_n = fx * sin_a - fy * cos_a;
        SliceTerms {
            sin_alpha: sin_a,
            cos_alpha: cos_a,
            a_t: -fx * cos_a - fy * sin_a,
            a_n,
            pore_force,
            resistance: s.cohesion * s.base_length + (a_n - pore_force) * tan_phi,
            cohesion: s.cohesion * s.base_length,
            loaded: false,
            tan_phi,
            arm: (
                s.base_middle.0 - model.reference.0,
                s.base_middle.1 - model.reference.1,
            ),
            // Horizontal seismic force at the centroid height: r × F = −dy·F_x.
            moment: -(s.centroid_y - s.base_middle.1) * fx,
        }
    }
}

/// Value and derivatives of the two scaled residuals.
pub(super) struct Residuals {
    pub force: f64,
    pub moment: f64,
    pub d_force: (f64, f64),
    pub d_moment: (f64, f64),
    pub min_m_alpha: f64,
}

/// Q of one slice (model §2.2) and the denominator m_α.
#[derive(Debug, Clone, Copy)]
pub(super) struct SliceResultant {
    pub q: f64,
    pub m_alpha: f64,
}

pub(super) struct Equations {
    pub terms: Vec<SliceTerms>,
    pub force_scale: f64,
    pub moment_scale: f64,
    pub known_moment: f64,
    /// The terms as [`Equations::evaluate`] sums them.
    kernel: Kernel,
}

thread_local! {
    /// The terms of the last equations dropped on this thread ([`spare`]).
    static SPARE_TERMS: Cell<Vec<SliceTerms>> = const { Cell::new(Vec::new()) };
}

impl Drop for Equations {
    fn drop(&mut self) {
        spare::keep(&SPARE_TERMS, std::mem::take(&mut self.terms));
    }
}

impl Equations {
    pub fn new(model: &SliceModel) -> Self {
        let (terms, total_weight) = Self::slice_terms(model);
        let known_moment = terms.iter().map(|t| t.moment).sum();
        let force_scale = total_weight.max(f64::MIN_POSITIVE);
        let kernel = Kernel::new(terms.iter().map(|t| Lane {
            sin_alpha: t.sin_alpha,
            cos_alpha: t.cos_alpha,
            a_t: t.a_t,
            resistance: t.resistance,
            tan_phi: t.tan_phi,
            arm: t.arm,
        }));
        Self {
            terms,
            force_scale,
            moment_scale: force_scale * model.length_scale,
            known_moment,
            kernel,
        }
    }

    /// Each slice's constants with the known loads added, and the total weight: what the
    /// equations are built from (and all that whether anything drives the mass needs).
    pub fn slice_terms(model: &SliceModel) -> (Vec<SliceTerms>, f64) {
        let mut total_weight = 0.0;
        let mut terms = spare::take(&SPARE_TERMS);
        terms.extend(model.slices.iter().map(|s| {
            total_weight += s.weight;
            SliceTerms::unloaded(model, s)
        }));
        for load in &model.loads {
            let t = &mut terms[load.slice];
            let (sin_a, cos_a) = (t.sin_alpha, t.cos_alpha);
            let a_n = load.fx * sin_a - load.fy * cos_a;
            let a_t = -load.fx * cos_a - load.fy * sin_a;
            if load.passive {
                // Mobilised like strength: R/F gains −A_t/F (a force against the sliding has
                // A_t < 0).
                t.resistance -= a_t;
            } else {
                t.a_t += a_t;
            }
            t.a_n += a_n;
            t.resistance += a_n * t.tan_phi;
            t.moment += load.moment;
            t.loaded = true;
        }
        (terms, total_weight)
    }

    /// Whether φ' = 0 (then the moment equation alone fixes F).
    pub fn is_frictionless(&self) -> bool {
        self.terms.iter().all(|t| t.tan_phi == 0.0)
    }

    /// Q for one slice (m_α may be ≤ 0: the callers check it).
    pub fn q(t: &SliceTerms, f: f64, trig: (f64, f64)) -> SliceResultant {
        let [q, _, _, m_alpha] = resultant(
            (t.sin_alpha, t.cos_alpha),
            t.a_t,
            t.resistance,
            t.tan_phi,
            f,
            trig,
        );
        SliceResultant { q, m_alpha }
    }

    pub fn evaluate(&self, f: f64, theta: f64) -> Residuals {
        let Sums {
            force,
            moment,
            d_force,
            d_moment,
            min_m_alpha,
        } = self.kernel.sums(f, theta.sin_cos(), -self.known_moment);
        let (fs, ms) = (self.force_scale, self.moment_scale);
        Residuals {
            force: force / fs,
            moment: moment / ms,
            d_force: (d_force.0 / fs, d_force.1 / fs),
            d_moment: (d_moment.0 / ms, d_moment.1 / ms),
            min_m_alpha,
        }
    }

    /// One scaled residual at (F, θ), the force (`moment` false) or the moment equation's, its
    /// derivative in F and the least m_α: as [`Equations::evaluate`] gives them, bit for bit.
    pub fn evaluate_one(&self, f: f64, theta: f64, moment: bool) -> (f64, f64, f64) {
        let start = moment.then_some(-self.known_moment);
        let [value, slope, min_m_alpha] = self.kernel.one(f, theta.sin_cos(), start);
        let scale = if moment {
            self.moment_scale
        } else {
            self.force_scale
        };
        (value / scale, slope / scale, min_m_alpha)
    }

    /// Whether more than half of the m_α are ≤ 0 at (F, θ): past the poles, the same root
    /// with θ + 180° has every Q and m_α of opposite sign, and the minority are the slices
    /// past their pole.
    pub fn m_alpha_mostly_negative(&self, f: f64, theta: f64) -> bool {
        let trig = theta.sin_cos();
        let non_positive = self
            .terms
            .iter()
            .filter(|t| Self::q(t, f, trig).m_alpha <= 0.0)
            .count();
        2 * non_positive > self.terms.len()
    }

    /// The interval of F on which every m_α(F, θ) is positive, clipped to [`F_RANGE`].
    pub(super) fn admissible_f(&self, theta: f64) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = F_RANGE;
        let (sin_t, cos_t) = theta.sin_cos();
        for t in &self.terms {
            let d = t.sin_alpha * cos_t - t.cos_alpha * sin_t;
            let c = t.cos_alpha * cos_t + t.sin_alpha * sin_t;
            let dt = d * t.tan_phi;
            // m_α = c + dt/F > 0
            if c > 0.0 {
                if dt < 0.0 {
                    lo = lo.max(-dt / c);
                }
            } else if dt > 0.0 {
                hi = hi.min(dt / -c);
            } else {
                return None;
            }
        }
        // Stay clear of the pole itself.
        let (lo, hi) = (lo * (1.0 + 1e-9), hi * (1.0 - 1e-9));
        (lo < hi).then_some((lo, hi))
    }

    /// F solving the force (`moment = false`) or moment equation at fixed θ: the crossing from
    /// negative to positive residual (more driving than resisting as F grows).
    pub fn f_at_theta(&self, theta: f64, moment: bool, evaluations: &mut usize) -> Option<f64> {
        self.f_at_theta_from(theta, moment, None, evaluations)
    }

    /// [`Equations::f_at_theta`], Newton's method tried first from `start` (a neighbouring
    /// surface's F) when given: where it does not settle there, the search goes on as without
    /// it.
    pub fn f_at_theta_from(
        &self,
        theta: f64,
        moment: bool,
        start: Option<f64>,
        evaluations: &mut usize,
    ) -> Option<f64> {
        let (lo, hi) = self.admissible_f(theta)?;
        // From a neighbour's F, Newton's iterate after a step below STARTING_STEP is as close
        // as rounding (its error is of the order of the step squared): no step to confirm it.
        let from_start = start.and_then(|f| {
            self.newton_at_theta(theta, moment, (f, (lo, hi), STARTING_STEP), evaluations)
        });
        if let Some(f) = from_start {
            return Some(f);
        }
        // Newton from F = 1 first (a handful of evaluations for ordinary slopes); the residual
        // must cross from negative to positive, as on the bracketed path below.
        if let Some(f) = self.newton_at_theta(theta, moment, (1.0, (lo, hi), 1e-14), evaluations) {
            return Some(f);
        }
        let residual = |f: f64| self.evaluate_one(f, theta, moment).0;
        let mut scan = self.scan(theta, moment, (lo, hi));
        let crossing = scan.first_crossing();
        *evaluations += scan.evaluations;
        let (a, fa, b, fb) = crossing?;
        let root = brent(residual, a, b, fa, fb, 1e-14 * b, 200)?;
        *evaluations += root.evaluations;
        Some(root.x)
    }

    /// Newton's method on one equation at θ from `f` (clamped into the admissible `range`):
    /// the root where the residual crosses from negative to positive, the iterate after a step
    /// of at most `settle` (relative), or `None` where a step leaves the range, the slope is not
    /// positive or an m_α is not.
    fn newton_at_theta(
        &self,
        theta: f64,
        moment: bool,
        (f, (lo, hi), settle): (f64, (f64, f64), f64),
        evaluations: &mut usize,
    ) -> Option<f64> {
        let mut f = f.clamp(lo, hi);
        for _ in 0..30 {
            let (value, slope, min_m_alpha) = self.evaluate_one(f, theta, moment);
            *evaluations += 1;
            if !(value.is_finite() && slope > 0.0) || min_m_alpha <= 0.0 {
                return None;
            }
            let next = f - value / slope;
            if !(next > lo && next < hi) {
                return None;
            }
            if (next - f).abs() <= settle * next {
                return Some(next);
            }
            f = next;
        }
        None
    }

    /// The bounded scan of one equation's residual at θ over [lo, hi] (see [`Scan`]): the terms
    /// computed as [`Equations::evaluate`] computes them, so that the residuals agree bit for
    /// bit.
    pub(super) fn scan(
        &self,
        theta: f64,
        moment: bool,
        range: (f64, f64),
    ) -> Scan<impl FnMut(f64, &mut Vec<f64>) + '_> {
        let trig = theta.sin_cos();
        let (sin_t, cos_t) = trig;
        let terms_at = move |f: f64, out: &mut Vec<f64>| {
            out.extend(self.terms.iter().map(|t| {
                let q = Self::q(t, f, trig).q;
                if moment {
                    q * (t.arm.0 * sin_t - t.arm.1 * cos_t)
                } else {
                    q
                }
            }));
        };
        let (constant, scale) = if moment {
            (-self.known_moment, self.moment_scale)
        } else {
            (0.0, self.force_scale)
        };
        Scan::new(terms_at, constant, scale, range)
    }
}
