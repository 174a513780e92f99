//! Spencer's method: the factor of safety F and the inclination θ of parallel inter-slice
//! forces that satisfy both force and moment equilibrium (Spencer 1967; moment equation of the
//! 1973 revision, about each base middle).
//!
//! # Equations (SPEC §2.2)
//! Slice i carries known forces (weight W, seismic k_h·W towards the toe and k_v·W downwards,
//! external F_x, F_y): A_n is their component normal to the base (pressing it), A_t their
//! component along the base in the driving sense. With the base shear mobilised as
//! S = (c'·l + (N − u·l)·tan φ')/F, the resultant Q of the two inter-slice forces, taken
//! positive along (cos θ, sin θ), is
//!
//! ```text
//!   Q = (A_t − [c'·l + (A_n − u·l)·tan φ'] / F) / (cos(α−θ) + sin(α−θ)·tan φ' / F)
//! ```
//!
//! and equilibrium needs Σ Q = 0 (forces; the Q are parallel) and
//! Σ Q·((x_b − x_c)·sin θ − (y_b − y_c)·cos θ) = Σ M (moments about the circle centre, which
//! the sum of the per-slice moment equations about the base middles (x_b, y_b) reduces to; M
//! are the moments of the known forces about the base middles). At θ = 0 the moment equation
//! alone is Bishop's simplified method.
//!
//! Vertical body forces (W, k_v·W) act on the vertical through the base middle, the usual
//! method-of-slices idealisation with which the thesis reproduces Spencer's numbers; the
//! horizontal seismic force acts at the height of the slice centroid.
//!
//! # Solution
//! Damped Newton on (F, θ) with analytic derivatives, step limits and a check that every
//! denominator m_α = cos(α−θ) + sin(α−θ)·tan φ'/F stays positive; if it fails, a bracketing
//! fallback: for each θ on a grid, F_f(θ) and F_m(θ) from the two equations separately, then
//! Brent's method on F_f − F_m (Spencer's own figure: the answer is where the curves cross).

use std::num::NonZeroUsize;

use super::geometry::{Embankment, SlipCircle, SlopeGeometry};
use super::{check_range, SlopeError};
use crate::roots::brent;

/// Denominators m_α below this are reported: the base normal force becomes unreliable there
/// (a common guard in slope programs; Duncan & Wright recommend 0.2).
pub const SMALL_DENOMINATOR: f64 = 0.2;

/// A scaled residual this small is rounding: the equations are solved.
const ROUNDING_RESIDUAL: f64 = 1e3 * f64::EPSILON;

/// The largest scaled residual (force / ΣW, moment / (ΣW·R)) accepted at convergence.
const SOLVED_RESIDUAL: f64 = 1e-9;

/// Range of admissible factors of safety searched by the bracketing steps.
const F_RANGE: (f64, f64) = (1e-6, 1e6);

/// Soil properties, common to all slices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Soil {
    unit_weight: f64,
    cohesion: f64,
    friction_angle_rad: f64,
    pore_pressure_ratio: f64,
}

impl Soil {
    /// Soil with unit weight γ > 0, cohesion c' ≥ 0, friction angle 0 ≤ φ' < 90° and pore
    /// pressure ratio 0 ≤ r_u ≤ 1; c' and φ' must not both be zero (a soil with no strength).
    pub fn new(
        unit_weight: f64,
        cohesion: f64,
        friction_angle_deg: f64,
        pore_pressure_ratio: f64,
    ) -> Result<Self, SlopeError> {
        let unit_weight = check_range(
            "soil.unit_weight",
            unit_weight,
            0.0,
            true,
            f64::MAX,
            "a finite number > 0",
        )?;
        let cohesion = check_range(
            "soil.cohesion",
            cohesion,
            0.0,
            false,
            f64::MAX,
            "a finite number ≥ 0",
        )?;
        let friction_angle_deg = check_range(
            "soil.friction_angle_deg",
            friction_angle_deg,
            0.0,
            false,
            89.9,
            "0 ≤ φ' ≤ 89.9 degrees",
        )?;
        let pore_pressure_ratio = check_range(
            "soil.pore_pressure_ratio",
            pore_pressure_ratio,
            0.0,
            false,
            1.0,
            "0 ≤ r_u ≤ 1",
        )?;
        if cohesion == 0.0 && friction_angle_deg == 0.0 {
            return Err(SlopeError::OutOfRange {
                parameter: "soil.cohesion",
                value: cohesion,
                allowed: "> 0 when soil.friction_angle_deg is 0 (a soil with neither cohesion nor friction has no strength)",
            });
        }
        Ok(Self {
            unit_weight,
            cohesion,
            friction_angle_rad: friction_angle_deg.to_radians(),
            pore_pressure_ratio,
        })
    }

    /// Unit weight γ.
    pub fn unit_weight(&self) -> f64 {
        self.unit_weight
    }
}

/// Pseudo-static seismic coefficients: k_h·W towards the toe and k_v·W downwards, at the slice
/// centroids.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Seismic {
    /// Horizontal coefficient k_h (≥ 0 acts towards the toe).
    pub kh: f64,
    /// Vertical coefficient k_v (positive downwards).
    pub kv: f64,
}

/// A known force on one slice, applied at the middle of its base (the thesis' F_x, F_y, M1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExternalLoad {
    /// Index of the slice, 0 at the lower end.
    pub slice: usize,
    /// Horizontal force, positive towards +x (the crest side).
    pub fx: f64,
    /// Vertical force, positive upwards.
    pub fy: f64,
    /// Moment of the load about the middle of the base, counter-clockwise positive.
    pub moment: f64,
}

/// One slip circle of one embankment with its soil and loads, ready to solve.
#[derive(Debug, Clone, PartialEq)]
pub struct SlopeProblem {
    /// Geometry of the embankment, the circle and the slices.
    pub geometry: SlopeGeometry,
    /// The soil.
    pub soil: Soil,
    /// Seismic coefficients (zero for a static analysis).
    pub seismic: Seismic,
    /// External loads on slices.
    pub external_loads: Vec<ExternalLoad>,
}

impl SlopeProblem {
    /// Builds the problem, validating the circle against the embankment and the loads against
    /// the slices.
    pub fn new(
        embankment: Embankment,
        circle: SlipCircle,
        slices: NonZeroUsize,
        soil: Soil,
        seismic: Seismic,
        external_loads: Vec<ExternalLoad>,
    ) -> Result<Self, SlopeError> {
        check_range(
            "seismic.kh",
            seismic.kh,
            -10.0,
            false,
            10.0,
            "-10 ≤ kh ≤ 10",
        )?;
        check_range(
            "seismic.kv",
            seismic.kv,
            -0.99,
            false,
            10.0,
            "-0.99 ≤ kv ≤ 10",
        )?;
        for load in &external_loads {
            if load.slice >= slices.get() {
                return Err(SlopeError::OutOfRange {
                    parameter: "external_loads.slice",
                    value: load.slice as f64,
                    allowed: "an index of an existing slice, 0 ≤ slice < slices",
                });
            }
            let finite = "a finite number";
            check_range(
                "external_loads.fx",
                load.fx,
                f64::MIN,
                false,
                f64::MAX,
                finite,
            )?;
            check_range(
                "external_loads.fy",
                load.fy,
                f64::MIN,
                false,
                f64::MAX,
                finite,
            )?;
            check_range(
                "external_loads.moment",
                load.moment,
                f64::MIN,
                false,
                f64::MAX,
                finite,
            )?;
        }
        let geometry = SlopeGeometry::new(embankment, circle, slices)?;
        Ok(Self {
            geometry,
            soil,
            seismic,
            external_loads,
        })
    }
}

/// Settings of the Spencer solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpencerSettings {
    /// Convergence tolerance on F (relative) and θ (radians). Defaults to 1e-12.
    pub tolerance: f64,
    /// Maximum Newton iterations before the bracketing fallback. Defaults to 50.
    pub max_iterations: usize,
}

impl Default for SpencerSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-12,
            max_iterations: 50,
        }
    }
}

/// How the solution of the two equations ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpencerStatus {
    /// Both equations are satisfied to the tolerance with every m_α positive.
    Converged,
    /// No (F, θ) with positive denominators satisfies both equations on the searched range
    /// (F in 1e-6…1e6, |θ| < 89°).
    NoSolution,
    /// φ' = 0 and no parallel inter-slice forces satisfy force equilibrium, but the moment
    /// equation alone fixes F: with φ' = 0 the base shear c'·l/F does not depend on the normal
    /// forces, so moment equilibrium about the centre gives F whatever the inter-slice forces
    /// (the classical φ = 0 analysis). F is reported, θ is not; per-slice forces are Bishop's
    /// (θ = 0) and there is no line of thrust.
    MomentOnly,
}

/// Forces on one slice at the solution.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SliceForces {
    /// Weight W = γ·area.
    pub weight: f64,
    /// Pore pressure u = r_u·γ·h at the base.
    pub pore_pressure: f64,
    /// Total normal force N on the base (effective plus pore force u·l).
    pub normal_force: f64,
    /// Effective normal force N' = N − u·l on the base.
    pub effective_normal_force: f64,
    /// Mobilised shear force S on the base, acting up the slope.
    pub shear_force: f64,
    /// Resultant Q of the two inter-slice forces, positive along (cos θ, sin θ).
    pub interslice_resultant: f64,
    /// Inter-slice force Z on the crest-side boundary of the slice (compression positive).
    pub interslice_force_right: f64,
    /// The denominator m_α = cos(α−θ) + sin(α−θ)·tan φ'/F.
    pub m_alpha: f64,
}

/// A point of the line of thrust on a boundary between two slices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThrustPoint {
    /// Index of the boundary: boundary i lies between slices i−1 and i.
    pub boundary: usize,
    /// x of the boundary.
    pub x: f64,
    /// Height of the point of action of the inter-slice force.
    pub y: f64,
    /// The inter-slice force (compression positive).
    pub force: f64,
    /// Whether the point lies between the base and the ground surface.
    pub is_inside_slice: bool,
}

/// What [`solve_spencer`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct SpencerSolution {
    /// How the solution ended.
    pub status: SpencerStatus,
    /// Spencer's factor of safety (only when converged).
    pub factor_of_safety: Option<f64>,
    /// Inclination θ of the inter-slice forces in radians (only when converged).
    pub theta_rad: Option<f64>,
    /// Bishop's simplified factor of safety (θ = 0, moment equation), when it has a root.
    pub bishop_factor_of_safety: Option<f64>,
    /// Newton iterations (plus fallback evaluations) spent.
    pub iterations: usize,
    /// Whether the bracketing fallback was needed.
    pub used_fallback: bool,
    /// Forces on every slice (zeros when not converged).
    pub slice_forces: Vec<SliceForces>,
    /// The line of thrust on the interior slice boundaries (empty when not converged).
    pub thrust_line: Vec<ThrustPoint>,
    /// Slices whose m_α is below [`SMALL_DENOMINATOR`] at the solution.
    pub small_m_alpha_slices: Vec<usize>,
    /// Slices whose effective normal force is negative at the solution.
    pub negative_effective_normal_slices: Vec<usize>,
    /// Largest scaled residual of the two equations at the solution (force / ΣW, moment /
    /// (ΣW·R)).
    pub residual: f64,
}

/// Per-slice constants of the equations, computed once.
#[derive(Debug, Clone, Copy)]
struct SliceTerms {
    alpha: f64,
    /// sin α and cos α, so that the angle differences need no trigonometry per evaluation.
    sin_alpha: f64,
    cos_alpha: f64,
    a_t: f64,
    a_n: f64,
    pore_force: f64,
    /// c'·l + (A_n − u·l)·tan φ': the resisting force at F = 1 without the Q term.
    resistance: f64,
    tan_phi: f64,
    /// Base middle relative to the circle centre.
    arm: (f64, f64),
    /// Moment of the known forces about the base middle.
    moment: f64,
}

/// Value and derivatives of the two scaled residuals.
struct Residuals {
    force: f64,
    moment: f64,
    d_force: (f64, f64),
    d_moment: (f64, f64),
    min_m_alpha: f64,
}

struct Equations {
    terms: Vec<SliceTerms>,
    force_scale: f64,
    moment_scale: f64,
    known_moment: f64,
}

impl Equations {
    fn new(problem: &SlopeProblem) -> Self {
        let g = &problem.geometry;
        let soil = &problem.soil;
        let tan_phi = soil.friction_angle_rad.tan();
        let mut total_weight = 0.0;
        let mut terms: Vec<SliceTerms> = g
            .slices
            .iter()
            .map(|s| {
                let weight = soil.unit_weight * s.area;
                total_weight += weight;
                let (sin_a, cos_a) = s.base_inclination_rad.sin_cos();
                let fx = -problem.seismic.kh * weight;
                let fy = -(1.0 + problem.seismic.kv) * weight;
                let pore_force =
                    soil.pore_pressure_ratio * soil.unit_weight * s.height_middle * s.base_length;
                let a_n = fx * sin_a - fy * cos_a;
                SliceTerms {
                    alpha: s.base_inclination_rad,
                    sin_alpha: sin_a,
                    cos_alpha: cos_a,
                    a_t: -fx * cos_a - fy * sin_a,
                    a_n,
                    pore_force,
                    resistance: soil.cohesion * s.base_length + (a_n - pore_force) * tan_phi,
                    tan_phi,
                    arm: (s.base_middle.0 - g.centre.0, s.base_middle.1 - g.centre.1),
                    // Horizontal seismic force at the centroid height: r × F = −dy·F_x.
                    moment: -(s.centroid.1 - s.base_middle.1) * fx,
                }
            })
            .collect();
        for load in &problem.external_loads {
            let t = &mut terms[load.slice];
            let (sin_a, cos_a) = t.alpha.sin_cos();
            let a_n = load.fx * sin_a - load.fy * cos_a;
            t.a_t += -load.fx * cos_a - load.fy * sin_a;
            t.a_n += a_n;
            t.resistance += a_n * tan_phi;
            t.moment += load.moment;
        }
        let known_moment = terms.iter().map(|t| t.moment).sum();
        let force_scale = total_weight.max(f64::MIN_POSITIVE);
        Self {
            terms,
            force_scale,
            moment_scale: force_scale * g.radius,
            known_moment,
        }
    }

    /// Whether φ' = 0 (then the moment equation alone fixes F).
    fn is_frictionless(&self) -> bool {
        self.terms.iter().all(|t| t.tan_phi == 0.0)
    }

    /// Q and its derivatives for one slice; `None` if m_α ≤ 0.
    fn q(t: &SliceTerms, f: f64, (sin_t, cos_t): (f64, f64)) -> (f64, f64, f64, f64) {
        // sin(α−θ) and cos(α−θ) from the stored sin α, cos α.
        let d = t.sin_alpha * cos_t - t.cos_alpha * sin_t;
        let c = t.cos_alpha * cos_t + t.sin_alpha * sin_t;
        let numerator = t.a_t - t.resistance / f;
        let m_alpha = c + d * t.tan_phi / f;
        let q = numerator / m_alpha;
        let dq_df =
            (t.resistance * m_alpha + numerator * d * t.tan_phi) / (f * f * m_alpha * m_alpha);
        let dq_dtheta = -numerator * (d - c * t.tan_phi / f) / (m_alpha * m_alpha);
        (q, dq_df, dq_dtheta, m_alpha)
    }

    fn evaluate(&self, f: f64, theta: f64) -> Residuals {
        let (sin_t, cos_t) = theta.sin_cos();
        let mut r = Residuals {
            force: 0.0,
            moment: -self.known_moment,
            d_force: (0.0, 0.0),
            d_moment: (0.0, 0.0),
            min_m_alpha: f64::INFINITY,
        };
        for t in &self.terms {
            let (q, dq_df, dq_dt, m_alpha) = Self::q(t, f, (sin_t, cos_t));
            let arm = t.arm.0 * sin_t - t.arm.1 * cos_t;
            let d_arm = t.arm.0 * cos_t + t.arm.1 * sin_t;
            r.force += q;
            r.moment += q * arm;
            r.d_force.0 += dq_df;
            r.d_force.1 += dq_dt;
            r.d_moment.0 += dq_df * arm;
            r.d_moment.1 += dq_dt * arm + q * d_arm;
            r.min_m_alpha = r.min_m_alpha.min(m_alpha);
        }
        let (fs, ms) = (self.force_scale, self.moment_scale);
        r.force /= fs;
        r.moment /= ms;
        r.d_force = (r.d_force.0 / fs, r.d_force.1 / fs);
        r.d_moment = (r.d_moment.0 / ms, r.d_moment.1 / ms);
        r
    }

    /// The interval of F on which every m_α(F, θ) is positive, clipped to [`F_RANGE`].
    fn admissible_f(&self, theta: f64) -> Option<(f64, f64)> {
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
    fn f_at_theta(&self, theta: f64, moment: bool, evaluations: &mut usize) -> Option<f64> {
        let (lo, hi) = self.admissible_f(theta)?;
        // Newton from F = 1 first (a handful of evaluations for ordinary slopes); the residual
        // must cross from negative to positive, as on the bracketed path below.
        let mut f = 1.0f64.clamp(lo, hi);
        for _ in 0..30 {
            let r = self.evaluate(f, theta);
            *evaluations += 1;
            let (value, slope) = if moment {
                (r.moment, r.d_moment.0)
            } else {
                (r.force, r.d_force.0)
            };
            if !(value.is_finite() && slope > 0.0) || r.min_m_alpha <= 0.0 {
                break;
            }
            let next = f - value / slope;
            if !(next > lo && next < hi) {
                break;
            }
            if (next - f).abs() <= 1e-14 * next {
                return Some(next);
            }
            f = next;
        }
        let residual = |f: f64| {
            let r = self.evaluate(f, theta);
            if moment {
                r.moment
            } else {
                r.force
            }
        };
        const SAMPLES: usize = 48;
        let ratio = (hi / lo).powf(1.0 / SAMPLES as f64);
        let (mut a, mut fa) = (lo, residual(lo));
        *evaluations += 1;
        for i in 1..=SAMPLES {
            let b = if i == SAMPLES {
                hi
            } else {
                lo * ratio.powi(i as i32)
            };
            let fb = residual(b);
            *evaluations += 1;
            if fa.is_finite() && fb.is_finite() && fa < 0.0 && fb >= 0.0 {
                let root = brent(residual, a, b, fa, fb, 1e-14 * b, 200)?;
                *evaluations += root.evaluations;
                return Some(root.x);
            }
            (a, fa) = (b, fb);
        }
        None
    }
}

/// Spencer's (F, θ in radians) alone, without the per-slice forces: what a search over circles
/// needs. `None` when the equations have no solution.
pub fn solve_spencer_factor(
    problem: &SlopeProblem,
    settings: &SpencerSettings,
) -> Option<(f64, f64)> {
    let equations = Equations::new(problem);
    let (solution, bishop, _, _) = solve_equations(&equations, settings);
    match (solution, bishop) {
        (Some(solution), _) => Some(solution),
        // φ' = 0: the moment equation alone is exact (see SpencerStatus::MomentOnly).
        (None, Some(f)) if equations.is_frictionless() => Some((f, f64::NAN)),
        (None, _) => None,
    }
}

/// Bishop's F as the start, damped Newton, and the bracketing fallback when Newton fails.
/// Returns (the solution, Bishop's F, iterations, whether the fallback was used).
fn solve_equations(
    equations: &Equations,
    settings: &SpencerSettings,
) -> (Option<(f64, f64)>, Option<f64>, usize, bool) {
    let mut evaluations = 0;
    let bishop = equations.f_at_theta(0.0, true, &mut evaluations);
    let start = (bishop.unwrap_or(1.0), 0.0);
    let mut iterations = 0;
    let mut used_fallback = false;
    let mut solution = newton(equations, start, settings, &mut iterations);
    if solution.is_none() {
        used_fallback = true;
        solution = fallback(equations, settings, &mut iterations);
    }
    (solution, bishop, iterations, used_fallback)
}

/// Solves Spencer's two equations for the slip circle of `problem`.
pub fn solve_spencer(problem: &SlopeProblem, settings: &SpencerSettings) -> SpencerSolution {
    let equations = Equations::new(problem);
    let (solution, bishop, iterations, used_fallback) = solve_equations(&equations, settings);
    match solution {
        Some((f, theta)) => describe(
            problem,
            &equations,
            f,
            theta,
            bishop,
            iterations,
            used_fallback,
        ),
        None if equations.is_frictionless() && bishop.is_some() => {
            let f = bishop.unwrap_or(f64::NAN);
            let mut s = describe(
                problem,
                &equations,
                f,
                0.0,
                bishop,
                iterations,
                used_fallback,
            );
            s.status = SpencerStatus::MomentOnly;
            s.theta_rad = None;
            s.thrust_line.clear();
            s
        }
        None => SpencerSolution {
            status: SpencerStatus::NoSolution,
            factor_of_safety: None,
            theta_rad: None,
            bishop_factor_of_safety: bishop,
            iterations,
            used_fallback,
            slice_forces: vec![SliceForces::default(); problem.geometry.slices.len()],
            thrust_line: Vec::new(),
            small_m_alpha_slices: Vec::new(),
            negative_effective_normal_slices: Vec::new(),
            residual: f64::NAN,
        },
    }
}

/// Spencer's figure: the factor of safety that satisfies the force equation alone, F_f(θ), and
/// the moment equation alone, F_m(θ), for each θ (radians); `None` where an equation has no
/// root with positive m_α. The curves cross at the answer.
pub fn factor_curves(
    problem: &SlopeProblem,
    thetas_rad: &[f64],
) -> Vec<(Option<f64>, Option<f64>)> {
    let equations = Equations::new(problem);
    let mut evaluations = 0;
    thetas_rad
        .iter()
        .map(|&theta| {
            (
                equations.f_at_theta(theta, false, &mut evaluations),
                equations.f_at_theta(theta, true, &mut evaluations),
            )
        })
        .collect()
}

/// Damped Newton on (F, θ); `None` unless it converges with every m_α positive.
fn newton(
    equations: &Equations,
    (mut f, mut theta): (f64, f64),
    settings: &SpencerSettings,
    iterations: &mut usize,
) -> Option<(f64, f64)> {
    const MAX_THETA_STEP: f64 = 0.2; // rad
    const MAX_THETA: f64 = 89.0 * std::f64::consts::PI / 180.0;
    let merit = |r: &Residuals| r.force.hypot(r.moment);
    let mut r = equations.evaluate(f, theta);
    if r.min_m_alpha <= 0.0 || !merit(&r).is_finite() {
        return None;
    }
    for _ in 0..settings.max_iterations {
        *iterations += 1;
        let det = r.d_force.0 * r.d_moment.1 - r.d_force.1 * r.d_moment.0;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let mut df = -(r.force * r.d_moment.1 - r.moment * r.d_force.1) / det;
        let mut dtheta = -(r.d_force.0 * r.moment - r.d_moment.0 * r.force) / det;
        // Step limits: F stays positive, θ moves by at most ~11° a step.
        let scale = (1.0f64)
            .min(0.5 * f / df.abs().max(f64::MIN_POSITIVE))
            .min(MAX_THETA_STEP / dtheta.abs().max(f64::MIN_POSITIVE));
        df *= scale;
        dtheta *= scale;
        let current = merit(&r);
        let mut accepted = None;
        for _ in 0..40 {
            let (f_new, theta_new) = (f + df, (theta + dtheta).clamp(-MAX_THETA, MAX_THETA));
            let r_new = equations.evaluate(f_new, theta_new);
            let m = merit(&r_new);
            if r_new.min_m_alpha > 0.0 && m.is_finite() && (m < current || m == 0.0) {
                accepted = Some((f_new, theta_new, r_new));
                break;
            }
            df *= 0.5;
            dtheta *= 0.5;
        }
        // No step lowers the residual: fine if it is already at rounding level (a start on the
        // root, as the fallback gives), a failure otherwise.
        let Some((f_new, theta_new, r_new)) = accepted else {
            return (current <= ROUNDING_RESIDUAL).then_some((f, theta));
        };
        let settled = (f_new - f).abs() <= settings.tolerance * f_new.max(1.0)
            && (theta_new - theta).abs() <= settings.tolerance;
        (f, theta, r) = (f_new, theta_new, r_new);
        if merit(&r) == 0.0 {
            return Some((f, theta));
        }
        if settled {
            // Small steps alone can mean a minimum of the residual that is not a root (the
            // line search shortens the steps there): only a vanishing residual is a solution.
            return (merit(&r) <= SOLVED_RESIDUAL).then_some((f, theta));
        }
    }
    // Newton stalled short of the tolerance: accept only if the residual is at rounding level.
    (merit(&r) <= ROUNDING_RESIDUAL).then_some((f, theta))
}

/// Spencer's own construction: F_f(θ) and F_m(θ) from the two equations separately, and
/// Brent's method on their difference where it changes sign, searching outwards from θ = 0 in
/// steps of 4° (roots nearest to horizontal inter-slice forces first). Each crossing is
/// polished by Newton; a crossing that is a jump of the difference (a pole of one of the
/// curves), not a root, fails to polish and the walk goes on.
fn fallback(
    equations: &Equations,
    settings: &SpencerSettings,
    iterations: &mut usize,
) -> Option<(f64, f64)> {
    const STEP_DEG: f64 = 4.0;
    const LIMIT_DEG: f64 = 88.0;
    let mut evaluations = 0;
    let difference = |theta: f64, evaluations: &mut usize| -> f64 {
        match (
            equations.f_at_theta(theta, false, evaluations),
            equations.f_at_theta(theta, true, evaluations),
        ) {
            (Some(ff), Some(fm)) => ff - fm,
            _ => f64::NAN,
        }
    };
    let origin = difference(0.0, &mut evaluations);
    // A bracket [a, b] of F_f − F_m: Brent, then Newton on both equations from there.
    let mut solve_in = |a: f64, fa: f64, b: f64, fb: f64, evaluations: &mut usize| {
        let root = brent(|t| difference(t, evaluations), a, b, fa, fb, 1e-13, 200)?;
        let guess = (equations.f_at_theta(root.x, false, evaluations)?, root.x);
        newton(equations, guess, settings, iterations)
    };
    // The last finite value on each side of 0.
    let (mut up, mut down) = ((0.0f64, origin), (0.0f64, origin));
    // Whether the edge after the last finite value was already probed, per side.
    let mut probed = [false, false];
    let steps = (LIMIT_DEG / STEP_DEG) as usize;
    for i in 1..=steps {
        for side in [1.0, -1.0] {
            let probed = &mut probed[usize::from(side < 0.0)];
            let theta = (side * STEP_DEG * i as f64).to_radians();
            let value = difference(theta, &mut evaluations);
            let last = if side > 0.0 { &mut up } else { &mut down };
            let (a, fa) = *last;
            if value.is_finite() && fa.is_finite() && value * fa <= 0.0 {
                if let Some(solution) = solve_in(a, fa, theta, value, &mut evaluations) {
                    *iterations += evaluations;
                    return Some(solution);
                }
            } else if !value.is_finite() && fa.is_finite() && !*probed {
                *probed = true;
                // The curves end between a and θ (an m_α reaches zero): a root can hide just
                // before that edge, so find the edge and look there.
                let (mut inside, mut outside) = (a, theta);
                let mut edge_value = fa;
                for _ in 0..40 {
                    let middle = 0.5 * (inside + outside);
                    let v = difference(middle, &mut evaluations);
                    if v.is_finite() {
                        (inside, edge_value) = (middle, v);
                    } else {
                        outside = middle;
                    }
                }
                if edge_value * fa <= 0.0 && inside != a {
                    if let Some(solution) = solve_in(a, fa, inside, edge_value, &mut evaluations) {
                        *iterations += evaluations;
                        return Some(solution);
                    }
                }
                // Carry on from the edge: a later finite stretch is compared with it.
                *last = (inside, edge_value);
            }
            if value.is_finite() {
                *last = (theta, value);
                *probed = false;
            }
        }
    }
    *iterations += evaluations;
    None
}

/// Forces, line of thrust and flags at the converged (F, θ).
fn describe(
    problem: &SlopeProblem,
    equations: &Equations,
    f: f64,
    theta: f64,
    bishop: Option<f64>,
    iterations: usize,
    used_fallback: bool,
) -> SpencerSolution {
    let g = &problem.geometry;
    let soil = &problem.soil;
    let residuals = equations.evaluate(f, theta);
    let (sin_t, cos_t) = theta.sin_cos();
    let mut slice_forces = Vec::with_capacity(g.slices.len());
    let mut thrust_line = Vec::with_capacity(g.slices.len().saturating_sub(1));
    let mut small_m_alpha_slices = Vec::new();
    let mut negative_effective_normal_slices = Vec::new();
    // Inter-slice force and the height of its point of action on the left boundary of the
    // current slice; the lower end carries none.
    let (mut z_left, mut y_left) = (0.0, g.lower_end.1);
    let n = g.slices.len();
    for (i, (slice, t)) in g.slices.iter().zip(&equations.terms).enumerate() {
        let (q, _, _, m_alpha) = Equations::q(t, f, (sin_t, cos_t));
        let weight = soil.unit_weight * slice.area;
        let pore_pressure = soil.pore_pressure_ratio * soil.unit_weight * slice.height_middle;
        // N = A_n + Q·sin(α−θ); S from the Mohr–Coulomb criterion with the factor F.
        let normal_force = t.a_n + q * (t.alpha - theta).sin();
        let effective_normal_force = normal_force - t.pore_force;
        let shear_force =
            (soil.cohesion * slice.base_length + effective_normal_force * t.tan_phi) / f;
        // Z_{i+1} = Z_i − Q_i: Q is the net push of the two neighbours along (cos θ, sin θ).
        let z_right = z_left - q;
        if m_alpha < SMALL_DENOMINATOR {
            small_m_alpha_slices.push(i);
        }
        if effective_normal_force < 0.0 {
            negative_effective_normal_slices.push(i);
        }
        slice_forces.push(SliceForces {
            weight,
            pore_pressure,
            normal_force,
            effective_normal_force,
            shear_force,
            interslice_resultant: q,
            interslice_force_right: if i + 1 == n { 0.0 } else { z_right },
            m_alpha,
        });
        if i + 1 < n {
            // Moments about the base middle (1973): left force +Z_i·(cos θ, sin θ) at
            // (x_left, y_left), right force −Z_{i+1}·(cos θ, sin θ) at (x_right, y_right), plus
            // the known moment, sum to zero.
            let (xb, yb) = slice.base_middle;
            let left = (slice.x_left - xb) * z_left * sin_t - (y_left - yb) * z_left * cos_t;
            let y_right = if z_right.abs() * cos_t.abs() > f64::MIN_POSITIVE {
                yb + ((slice.x_right - xb) * z_right * sin_t - left - t.moment) / (z_right * cos_t)
            } else {
                f64::NAN
            };
            let top = problem.geometry.embankment.ground(slice.x_right);
            thrust_line.push(ThrustPoint {
                boundary: i + 1,
                x: slice.x_right,
                y: y_right,
                force: z_right,
                is_inside_slice: y_right >= slice.base_right_y && y_right <= top,
            });
            (z_left, y_left) = (z_right, if y_right.is_finite() { y_right } else { yb });
        }
    }
    SpencerSolution {
        status: SpencerStatus::Converged,
        factor_of_safety: Some(f),
        theta_rad: Some(theta),
        bishop_factor_of_safety: bishop,
        iterations,
        used_fallback,
        slice_forces,
        thrust_line,
        small_m_alpha_slices,
        negative_effective_normal_slices,
        residual: residuals.force.abs().max(residuals.moment.abs()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Spencer (1967) example in the thesis' SI units: H = 100 ft, 2:1, c'/(γH) = 0.02, φ' = 40°,
    /// r_u = 0.5, centre X = 31.6 ft, Y = 209.2 ft from the toe.
    fn spencer_example(n: usize, unit_weight: f64, cohesion_scale: f64) -> SlopeProblem {
        let height = 30.48;
        SlopeProblem::new(
            Embankment::new(height, 60.96).unwrap(),
            SlipCircle {
                x: 9.63168,
                y: 63.76416,
                lower_end_factor: 0.0,
            },
            NonZeroUsize::new(n).unwrap(),
            Soil::new(
                unit_weight,
                0.02 * unit_weight * height * cohesion_scale,
                40.0,
                0.5,
            )
            .unwrap(),
            Seismic::default(),
            Vec::new(),
        )
        .unwrap()
    }

    fn solve(p: &SlopeProblem) -> (f64, f64, SpencerSolution) {
        let s = solve_spencer(p, &SpencerSettings::default());
        assert_eq!(s.status, SpencerStatus::Converged);
        (
            s.factor_of_safety.unwrap(),
            s.theta_rad.unwrap().to_degrees(),
            s,
        )
    }

    #[test]
    fn spencer_1967_example_converged() {
        // Spencer (1967) example, converged F = 1.0695, θ = 22.43° (SPEC §2.3); ±2e-4, ±0.01°.
        for n in [500, 1000] {
            let (f, theta, _) = solve(&spencer_example(n, 10.0, 1.0));
            assert!((f - 1.0695).abs() < 2e-4, "N = {n}: F = {f}");
            assert!((theta - 22.43).abs() < 0.01, "N = {n}: θ = {theta}");
        }
    }

    #[test]
    fn thesis_table_of_f_against_number_of_slices() {
        // Thesis §5.6, F and θ for N = 10 … 1000, printed to 5 and 3 decimals: half a unit in
        // the last printed digit.
        let table = [
            (10, 1.07188, 22.735),
            (20, 1.07068, 22.491),
            (50, 1.06974, 22.439),
            (100, 1.06958, 22.432),
            (200, 1.06954, 22.431),
            (500, 1.06952, 22.430),
            (1000, 1.06952, 22.430),
        ];
        for (n, f_ref, theta_ref) in table {
            let (f, theta, _) = solve(&spencer_example(n, 10.0, 1.0));
            assert!(
                (f - f_ref).abs() <= 5e-6,
                "N = {n}: F = {f}, thesis {f_ref}"
            );
            assert!(
                (theta - theta_ref).abs() <= 5e-4,
                "N = {n}: θ = {theta}, thesis {theta_ref}"
            );
        }
    }

    #[test]
    fn bishop_simplified_for_the_spencer_circle() {
        // SPEC §2.3: Bishop's simplified F for the same circle ≈ 1.040 (1.0397 to 4 decimals).
        let (_, _, s) = solve(&spencer_example(1000, 10.0, 1.0));
        let bishop = s.bishop_factor_of_safety.unwrap();
        assert!((bishop - 1.0397).abs() < 1e-4, "Bishop F = {bishop}");
    }

    #[test]
    fn f_depends_on_cohesion_and_unit_weight_only_through_their_ratio() {
        // SPEC §2.3: scaling c' and γ together leaves F and θ unchanged (1e-10: rounding).
        let (f1, t1, _) = solve(&spencer_example(200, 10.0, 1.0));
        for gamma in [1e-6, 1.0, 18.5, 1e6] {
            let (f, t, _) = solve(&spencer_example(200, gamma, 1.0));
            assert!((f - f1).abs() < 1e-10 * f1, "γ = {gamma}: {f} vs {f1}");
            assert!((t - t1).abs() < 1e-8, "γ = {gamma}: {t} vs {t1}");
        }
        // And doubling c' alone does change it (upwards).
        let (f2, _, _) = solve(&spencer_example(200, 10.0, 2.0));
        assert!(f2 > f1 + 0.01);
    }

    #[test]
    fn f_converges_as_slices_are_added() {
        // Chords cut the arc with an error O(N⁻²); the slices that straddle the kinks of the
        // ground add a wobble of the same order. For this circle |F_N − F_4000|·N² stays below
        // 1 from N = 10 on (0.46 at N = 20, 0.67 at N = 320).
        let (converged, _, _) = solve(&spencer_example(4000, 10.0, 1.0));
        for n in [10, 20, 40, 80, 160, 320, 640] {
            let (f, _, _) = solve(&spencer_example(n, 10.0, 1.0));
            let error = (f - converged).abs();
            assert!(
                error * (n * n) as f64 <= 1.0,
                "N = {n}: F = {f}, error {error}"
            );
        }
    }

    #[test]
    fn returned_forces_satisfy_both_equilibrium_equations() {
        // Independent check of the solution: resolve every slice's forces (W, N, S, Q) in x and
        // y, and sum the moments about the centre. 1e-9 of the total weight: rounding.
        let p = spencer_example(100, 10.0, 1.0);
        let (_, theta, s) = solve(&p);
        let theta = theta.to_radians();
        let total_weight: f64 = s.slice_forces.iter().map(|f| f.weight).sum();
        for (slice, forces) in p.geometry.slices.iter().zip(&s.slice_forces) {
            let (sin_a, cos_a) = slice.base_inclination_rad.sin_cos();
            // Normal N along (−sin α, cos α), shear S up the slope along (cos α, sin α).
            let fx = -forces.normal_force * sin_a
                + forces.shear_force * cos_a
                + forces.interslice_resultant * theta.cos();
            let fy = -forces.weight
                + forces.normal_force * cos_a
                + forces.shear_force * sin_a
                + forces.interslice_resultant * theta.sin();
            assert!(fx.abs() < 1e-9 * total_weight, "fx = {fx}");
            assert!(fy.abs() < 1e-9 * total_weight, "fy = {fy}");
        }
        let sum_q: f64 = s.slice_forces.iter().map(|f| f.interslice_resultant).sum();
        assert!(sum_q.abs() < 1e-9 * total_weight);
        // The inter-slice force dies out at the upper exit and the thrust line is inside the
        // mass over the bulk of the slices (Spencer 1973: near the lower third point).
        let last = s.slice_forces.last().unwrap();
        assert_eq!(last.interslice_force_right, 0.0);
        let inside = s.thrust_line.iter().filter(|t| t.is_inside_slice).count();
        assert!(
            inside * 10 >= s.thrust_line.len() * 9,
            "{inside} of {}",
            s.thrust_line.len()
        );
    }

    #[test]
    fn thrust_line_near_lower_third_point() {
        // Spencer (1967): the line of thrust passes close to the lower third point of the
        // inter-slice boundaries. Check the middle half of the boundaries lies within the lower
        // 0.2–0.45 of the boundary height.
        let p = spencer_example(200, 10.0, 1.0);
        let (_, _, s) = solve(&p);
        let n = s.thrust_line.len();
        for t in &s.thrust_line[n / 4..3 * n / 4] {
            let slice = &p.geometry.slices[t.boundary - 1];
            let top = p.geometry.embankment.ground(t.x);
            let ratio = (t.y - slice.base_right_y) / (top - slice.base_right_y);
            assert!(
                (0.2..0.45).contains(&ratio),
                "boundary {}: {ratio}",
                t.boundary
            );
        }
    }

    #[test]
    fn one_slice_is_solved_or_reported_honestly() {
        // N = 1: a single slice cannot satisfy both equations unless Q = 0; whatever the status,
        // a converged answer must satisfy the equations.
        let s = solve_spencer(&spencer_example(1, 10.0, 1.0), &SpencerSettings::default());
        match s.status {
            SpencerStatus::Converged => assert!(s.residual < 1e-9),
            SpencerStatus::NoSolution => assert!(s.factor_of_safety.is_none()),
            // φ' = 40° here: the moment-only answer is for φ' = 0 alone.
            SpencerStatus::MomentOnly => panic!("moment-only answer with friction"),
        }
    }

    #[test]
    fn soil_without_strength_is_rejected() {
        assert!(matches!(
            Soil::new(10.0, 0.0, 0.0, 0.0),
            Err(SlopeError::OutOfRange {
                parameter: "soil.cohesion",
                ..
            })
        ));
        assert!(Soil::new(10.0, 1.0, 90.0, 0.0).is_err());
        assert!(Soil::new(10.0, 1.0, 30.0, 1.5).is_err());
        assert!(Soil::new(-1.0, 1.0, 30.0, 0.0).is_err());
    }
}
