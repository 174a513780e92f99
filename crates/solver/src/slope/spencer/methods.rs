//! The methods engineers compare with Spencer's (model §4.3), on the same slices: the ordinary
//! method (Fellenius), Bishop's simplified, Janbu's simplified (uncorrected) and
//! Morgenstern–Price with any inter-slice function.
//!
//! # Morgenstern–Price
//! The inter-slice force on boundary j is E_j·(1, λ·f_j) (E horizontal, compression positive;
//! f the inter-slice function at the boundary's x). Each slice's normal and tangential
//! equilibrium with S = (c'l + (N − ul) tan φ')/F gives E across it:
//!
//! ```text
//!   E_{i+1}·D_{i+1} = c'l + (A_n − ul) tan φ' − F·A_t + E_i·D_i,
//!   D_j = F·(cos α + λ f_j sin α) − tan φ'·(λ f_j cos α − sin α)     (α of slice i),
//! ```
//!
//! from E_0 = 0; force equilibrium needs E_n = 0, moment equilibrium the same equation as
//! Spencer's, Σ b_i × Q_i = Σ M_i with Q_i = E_i g_i − E_{i+1} g_{i+1} (the sum of the slices'
//! moments about their base middles). With f ≡ 1 these are Spencer's equations (λ = tan θ).
//! D_j > 0 plays the part of m_α > 0. Solved by damped Newton on (F, λ) from Spencer's answer.

use super::equations::{Equations, SliceTerms};
use super::nonlinear::{effective_normals, method};
use super::physical::strength_holds;
use crate::slope::slices::SliceModel;

/// A method of slices beside Spencer's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Morgenstern–Price: X = λ·f(x)·E, force and moment equilibrium.
    MorgensternPrice,
    /// Bishop's simplified: moments about the centre, horizontal inter-slice forces.
    Bishop,
    /// Janbu's simplified (uncorrected): horizontal force equilibrium.
    Janbu,
    /// The ordinary method (Fellenius): no inter-slice forces, moments about the centre.
    Ordinary,
}

/// The inter-slice function of Morgenstern–Price.
#[derive(Debug, Clone, PartialEq)]
pub enum InterSliceFunction {
    /// f = sin(π·ξ), ξ = (x − x_l)/(x_r − x_l) along the mass.
    HalfSine,
    /// f ≡ 1 (Spencer's parallel forces).
    Constant,
    /// f(ξ) by linear interpolation between points (ξ, f), ξ in [0, 1] increasing.
    Points(Vec<(f64, f64)>),
}

impl InterSliceFunction {
    fn at(&self, xi: f64) -> f64 {
        match self {
            Self::HalfSine => (std::f64::consts::PI * xi).sin(),
            Self::Constant => 1.0,
            Self::Points(points) => {
                let i = points.partition_point(|p| p.0 < xi);
                match (i.checked_sub(1).map(|k| points[k]), points.get(i)) {
                    (Some(a), Some(b)) if b.0 > a.0 => a.1 + (b.1 - a.1) * (xi - a.0) / (b.0 - a.0),
                    (_, Some(b)) => b.1,
                    (Some(a), None) => a.1,
                    (None, None) => 0.0,
                }
            }
        }
    }
}

/// F of one method; `None` when its equation has no root (or, for the moment methods, when the
/// surface has no centre of rotation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MethodFactor {
    /// The factor of safety.
    pub factor_of_safety: Option<f64>,
    /// Morgenstern–Price's λ.
    pub lambda: Option<f64>,
    /// Newton iterations (Morgenstern–Price).
    pub iterations: usize,
}

impl MethodFactor {
    fn plain(f: Option<f64>) -> Self {
        Self {
            factor_of_safety: f,
            lambda: None,
            iterations: 0,
        }
    }
}

/// The ordinary method (Fellenius): N = the known forces' normal component, moments about the
/// centre. `None` without a centre of rotation or when nothing drives the mass.
pub fn ordinary(model: &SliceModel) -> MethodFactor {
    MethodFactor::plain(method(model, |m, normals| {
        let f = ordinary_factor(m).factor_of_safety?;
        let n = match normals {
            true => Equations::new(m)
                .terms
                .iter()
                .map(|t| t.a_n - t.pore_force)
                .collect(),
            false => Vec::new(),
        };
        Some((f, n))
    }))
}

/// [`ordinary`] with each base's strength as it stands.
fn ordinary_factor(model: &SliceModel) -> MethodFactor {
    let Some(centre) = model.moment_centre else {
        return MethodFactor::plain(None);
    };
    let equations = Equations::new(&model.about(centre));
    let (driving, _) = ordinary_moments(equations.terms.iter().copied());
    let resisting: f64 = equations
        .terms
        .iter()
        .map(|t| t.resistance * (t.arm.0 * t.sin_alpha - t.arm.1 * t.cos_alpha))
        .sum();
    let f = -resisting / driving;
    MethodFactor::plain((driving < 0.0 && f.is_finite() && f > 0.0).then_some(f))
}

/// The moment of the known forces about the reference (negative: towards the toe), with the
/// known normal force on each base, and the sum of the terms' sizes (for rounding).
pub(super) fn ordinary_moments(terms: impl IntoIterator<Item = SliceTerms>) -> (f64, f64) {
    let (mut driving, mut size) = (0.0, 0.0);
    for t in terms {
        let (s, c) = (t.sin_alpha, t.cos_alpha);
        // The known force K from its components along and across the base.
        let kx = -t.a_t * c + t.a_n * s;
        let ky = -t.a_t * s - t.a_n * c;
        let (dx, dy) = t.arm;
        let term = dx * ky - dy * kx + t.moment + t.a_n * (dx * c + dy * s);
        driving += term;
        size += term.abs();
    }
    (driving, size)
}

/// Whether the known forces drive the mass towards the toe about the reference (a circle's
/// centre): a moment beyond rounding (1e-12 of its terms' sizes).
pub(super) fn drives(terms: &[SliceTerms]) -> bool {
    is_driving(ordinary_moments(terms.iter().copied()))
}

/// [`drives`] of `model`'s slice terms, the known loads added ([`Equations::slice_terms`]).
pub(super) fn model_drives(model: &SliceModel) -> bool {
    is_driving(model_moments(model))
}

/// [`ordinary_moments`] of `model`'s slice terms, bit for bit; without known loads each
/// slice's terms are made and summed as they come, with no vector of them.
pub(super) fn model_moments(model: &SliceModel) -> (f64, f64) {
    if model.loads.is_empty() {
        ordinary_moments(model.slices.iter().map(|s| SliceTerms::unloaded(model, s)))
    } else {
        ordinary_moments(Equations::slice_terms(model).0)
    }
}

/// A driving moment beyond rounding (1e-12 of its terms' sizes).
fn is_driving((driving, size): (f64, f64)) -> bool {
    driving < -1e-12 * size
}

/// Bishop's simplified method: the moment equation with horizontal inter-slice forces.
pub fn bishop(model: &SliceModel) -> MethodFactor {
    MethodFactor::plain(method(model, |m, normals| {
        let f = bishop_factor(m)?;
        Some((
            f,
            if normals {
                effective_normals(m, f, 0.0)
            } else {
                Vec::new()
            },
        ))
    }))
}

/// Bishop's F about the model's centre of rotation, `None` without one or without a root.
pub(super) fn bishop_factor(model: &SliceModel) -> Option<f64> {
    let centre = model.moment_centre?;
    let mut evaluations = 0;
    if centre == model.reference {
        return Equations::new(model).f_at_theta(0.0, true, &mut evaluations);
    }
    Equations::new(&model.about(centre)).f_at_theta(0.0, true, &mut evaluations)
}

/// Janbu's simplified method (uncorrected): force equilibrium with horizontal inter-slice
/// forces.
pub fn janbu(model: &SliceModel) -> MethodFactor {
    MethodFactor::plain(method(model, |m, normals| {
        let mut evaluations = 0;
        let f = Equations::new(m).f_at_theta(0.0, false, &mut evaluations)?;
        Some((
            f,
            if normals {
                effective_normals(m, f, 0.0)
            } else {
                Vec::new()
            },
        ))
    }))
}

/// Scaled residuals (E_n/ΣW, moment/(ΣW·L)) of Morgenstern–Price at (F, λ); `None` where a D
/// is not positive.
fn mp_residuals(
    equations: &Equations,
    f_values: &[f64],
    (f, lambda): (f64, f64),
) -> Option<(f64, f64)> {
    let mut e = 0.0;
    let mut moment = -equations.known_moment;
    for (i, t) in equations.terms.iter().enumerate() {
        let d = |fj: f64| {
            f * (t.cos_alpha + lambda * fj * t.sin_alpha)
                - t.tan_phi * (lambda * fj * t.cos_alpha - t.sin_alpha)
        };
        let (d_left, d_right) = (d(f_values[i]), d(f_values[i + 1]));
        if !(d_right > 0.0 && d_left > 0.0) {
            return None;
        }
        let e_next = (t.resistance - f * t.a_t + e * d_left) / d_right;
        let qx = e - e_next;
        let qy = lambda * (f_values[i] * e - f_values[i + 1] * e_next);
        moment += t.arm.0 * qy - t.arm.1 * qx;
        e = e_next;
    }
    let r = (e / equations.force_scale, moment / equations.moment_scale);
    (r.0.is_finite() && r.1.is_finite()).then_some(r)
}

/// Morgenstern–Price with `function`, by damped Newton on (F, λ) from `start` (Spencer's F and
/// tan θ, say); on nonlinear envelopes, at their consistent state.
pub fn morgenstern_price(
    model: &SliceModel,
    function: &InterSliceFunction,
    start: (f64, f64),
) -> MethodFactor {
    let mut iterations = 0;
    let solved = method(model, |m, normals| {
        let answer = mp_linear(m, function, start);
        iterations += answer.iterations;
        let (f, lambda) = (answer.factor_of_safety?, answer.lambda?);
        let n = match normals {
            true => mp_normals(m, function, (f, lambda)),
            false => Vec::new(),
        };
        Some(((f, lambda), n))
    });
    MethodFactor {
        factor_of_safety: solved.map(|s| s.0),
        lambda: solved.map(|s| s.1),
        iterations,
    }
}

/// The inter-slice function at each slice boundary of `model`; `None` without slices.
fn boundary_values(model: &SliceModel, function: &InterSliceFunction) -> Option<Vec<f64>> {
    let n = model.slices.len();
    let (x0, x1) = (model.slices.first()?.x_left, model.slices.last()?.x_right);
    Some(
        (0..=n)
            .map(|j| {
                let x = if j == n { x1 } else { model.slices[j].x_left };
                function.at((x - x0) / (x1 - x0))
            })
            .collect(),
    )
}

/// Each slice's N′ under Morgenstern–Price's forces at (F, λ): N = A_n + Q_x·sin α − Q_y·cos α.
fn mp_normals(
    model: &SliceModel,
    function: &InterSliceFunction,
    (f, lambda): (f64, f64),
) -> Vec<f64> {
    let equations = Equations::new(model);
    match boundary_values(model, function) {
        Some(f_values) => mp_effective_normals(&equations, &f_values, (f, lambda)),
        None => Vec::new(),
    }
}

/// [`mp_normals`] from the equations and the inter-slice function at the boundaries.
fn mp_effective_normals(
    equations: &Equations,
    f_values: &[f64],
    (f, lambda): (f64, f64),
) -> Vec<f64> {
    let mut e = 0.0;
    let mut out = Vec::with_capacity(equations.terms.len());
    for (i, t) in equations.terms.iter().enumerate() {
        let d = |fj: f64| {
            f * (t.cos_alpha + lambda * fj * t.sin_alpha)
                - t.tan_phi * (lambda * fj * t.cos_alpha - t.sin_alpha)
        };
        let e_next = (t.resistance - f * t.a_t + e * d(f_values[i])) / d(f_values[i + 1]);
        let qx = e - e_next;
        let qy = lambda * (f_values[i] * e - f_values[i + 1] * e_next);
        out.push(t.a_n + qx * t.sin_alpha - qy * t.cos_alpha - t.pore_force);
        e = e_next;
    }
    out
}

/// [`morgenstern_price`] with each base's strength as it stands.
fn mp_linear(model: &SliceModel, function: &InterSliceFunction, start: (f64, f64)) -> MethodFactor {
    const SOLVED: f64 = 1e-11;
    let equations = Equations::new(model);
    let Some(f_values) = boundary_values(model, function) else {
        return MethodFactor::plain(None);
    };
    let merit = |r: (f64, f64)| r.0.hypot(r.1);
    let mut x = start;
    let mut iterations = 0;
    let Some(mut r) = mp_residuals(&equations, &f_values, x) else {
        return MethodFactor::plain(None);
    };
    for _ in 0..60 {
        if merit(r) <= SOLVED {
            break;
        }
        iterations += 1;
        // Central differences: the residuals are smooth where every D is positive.
        let (hf, hl) = (1e-7 * x.0, 1e-7 * x.1.abs().max(1e-3));
        let diff = |dx: (f64, f64)| {
            let plus = mp_residuals(&equations, &f_values, (x.0 + dx.0, x.1 + dx.1))?;
            let minus = mp_residuals(&equations, &f_values, (x.0 - dx.0, x.1 - dx.1))?;
            let h = if dx.0 != 0.0 { dx.0 } else { dx.1 };
            Some((
                (plus.0 - minus.0) / (2.0 * h),
                (plus.1 - minus.1) / (2.0 * h),
            ))
        };
        let (Some(d_f), Some(d_l)) = (diff((hf, 0.0)), diff((0.0, hl))) else {
            break;
        };
        let det = d_f.0 * d_l.1 - d_l.0 * d_f.1;
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let mut step = (
            -(r.0 * d_l.1 - r.1 * d_l.0) / det,
            -(d_f.0 * r.1 - d_f.1 * r.0) / det,
        );
        // F stays positive; λ moves by at most 0.5 a step.
        let scale = 1.0f64
            .min(0.5 * x.0 / step.0.abs().max(f64::MIN_POSITIVE))
            .min(0.5 / step.1.abs().max(f64::MIN_POSITIVE));
        step = (step.0 * scale, step.1 * scale);
        let mut accepted = None;
        for _ in 0..40 {
            let next = (x.0 + step.0, x.1 + step.1);
            if let Some(rn) = mp_residuals(&equations, &f_values, next) {
                if merit(rn) < merit(r) {
                    accepted = Some((next, rn));
                    break;
                }
            }
            step = (0.5 * step.0, 0.5 * step.1);
        }
        let Some((next, rn)) = accepted else { break };
        (x, r) = (next, rn);
    }
    // The same rule for roots as Spencer's (model §2.2): no base below its envelope's apex.
    let solved = merit(r) <= SOLVED
        && strength_holds(
            &equations,
            mp_effective_normals(&equations, &f_values, x).into_iter(),
        );
    MethodFactor {
        factor_of_safety: solved.then_some(x.0),
        lambda: solved.then_some(x.1),
        iterations,
    }
}

/// The F of `method` alone on `model`, as a search for the method's own critical surface ranks
/// it; Morgenstern–Price from Bishop's F with λ = 0, then from (1, 0).
pub fn method_factor(
    model: &SliceModel,
    method: Method,
    function: &InterSliceFunction,
) -> Option<f64> {
    match method {
        Method::Bishop => bishop(model).factor_of_safety,
        Method::Janbu => janbu(model).factor_of_safety,
        Method::Ordinary => ordinary(model).factor_of_safety,
        Method::MorgensternPrice => {
            let starts = [
                bishop(model).factor_of_safety.map(|f| (f, 0.0)),
                Some((1.0, 0.0)),
            ];
            starts
                .into_iter()
                .flatten()
                .find_map(|start| morgenstern_price(model, function, start).factor_of_safety)
        }
    }
}
