//! Rapid drawdown (model §8): the three stages of Duncan, Wright & Wong (1990), as the US Army
//! Corps' slope manual (EM 1110-2-1902, App. G) and Duncan, Wright & Brandon (2014, ch. 9)
//! give them, on one slip surface.
//!
//! 1. Before the drawdown (the pool up, every soil drained, c′ and φ′): Spencer's solution
//!    gives each base its consolidation stresses, σ′_fc = N′/l and τ_fc = (c′ + σ′_fc·tan φ′)/F.
//! 2. After it (the pool down): a base in a soil that does not drain (one with an R envelope)
//!    has the undrained strength τ_ff of those stresses, with φ = 0. τ_ff lies between two
//!    envelopes of τ_ff against σ′_fc — isotropic consolidation (K_c = 1), from the R envelope,
//!    and consolidation at failure (K_c = K_f), the effective envelope — interpolated linearly
//!    in the base's consolidation ratio K_c = σ′_1c/σ′_3c. Where either envelope's σ′_3c would
//!    be negative, the lower of the two.
//! 3. Where a base's drained strength c′ + σ′·tan φ′ at stage 2's σ′ is the lower, the base
//!    takes its drained c′ and φ′, and F is computed again.
//!
//! The slices of both stages are the same: each stage's slices are also cut where the other
//! stage's water line crosses the surface.

pub use super::model::REnvelope;
use super::model::{Drawdown, Layer, Section};
use super::polyline::Polyline;
use crate::slope::error::{check_range, SlopeError, SlopeParameter};
use crate::slope::slices::SliceModel;
use crate::slope::spencer::{solve_spencer, SpencerSettings};
use crate::slope::strength::Strength;

impl Drawdown {
    /// The R envelope of layer `layer`'s soil; `None` where it drains freely.
    fn envelope(&self, layer: usize) -> Option<REnvelope> {
        self.envelopes.get(layer).copied().flatten()
    }
}

/// What the stages gave on one surface.
#[derive(Debug, Clone, PartialEq)]
pub struct DrawdownStages {
    /// Stage 1's F, the pool up (the consolidation stresses are its).
    pub before_factor: f64,
    /// Stage 2's F, with the undrained strengths.
    pub undrained_factor: f64,
    /// The bases in soils that do not drain.
    pub undrained_slices: Vec<usize>,
    /// Those whose drained strength was the lower at stage 2 (stage 3 gave them c′ and φ′;
    /// empty when stage 3 did not run).
    pub drained_slices: Vec<usize>,
}

impl Section {
    /// The section with a rapid drawdown from the water line `before` to its piezometric line
    /// (the line after), `envelopes` giving per layer the R envelope of a soil that does not
    /// drain (`None`: it drains freely). Pore pressures come from the two lines alone: r_u,
    /// a layer's own line, a grid and nonlinear envelopes are refused beside a drawdown, and a
    /// soil that does not drain needs c′ and φ′.
    pub fn with_drawdown(
        mut self,
        before: Polyline,
        envelopes: Vec<Option<REnvelope>>,
    ) -> Result<Self, SlopeError> {
        let Some(after) = self.piezometric_line.clone() else {
            return conflict(
                SlopeParameter::Drawdown,
                "a drawdown needs the water line after it",
            );
        };
        if envelopes.len() != self.layers.len() || envelopes.iter().all(Option::is_none) {
            return conflict(
                SlopeParameter::Drawdown,
                "no soil has an r_envelope: without a soil that does not drain, a drawdown is \
                 the drained analysis with the line after it as the piezometric line",
            );
        }
        if self.water.grid.is_some() {
            return conflict(
                SlopeParameter::Drawdown,
                "a pore-pressure grid describes one state: the drawdown's pore pressures come \
                 from its two lines",
            );
        }
        check_drawdown_layers(&self.layers, &envelopes)?;
        if self.envelopes.is_some() {
            return conflict(
                SlopeParameter::Drawdown,
                "nonlinear strength envelopes are not combined with a drawdown",
            );
        }
        let mut stage = self.clone();
        stage.piezometric_line = Some(before.clone());
        stage.other_water_line = Some(after);
        self.other_water_line = Some(before);
        self.drawdown = Some(Box::new(Drawdown {
            before: stage.with_bends(),
            envelopes,
        }));
        Ok(self)
    }

    /// The R envelope of layer `index`'s soil, when it does not drain in a drawdown.
    pub fn r_envelope(&self, index: usize) -> Option<REnvelope> {
        self.drawdown.as_ref().and_then(|d| d.envelope(index))
    }

    /// The water line before the drawdown, if there is one.
    pub fn drawdown_before(&self) -> Option<&Polyline> {
        self.drawdown
            .as_ref()
            .and_then(|d| d.before.piezometric_line.as_ref())
    }
}

/// The error of a drawdown that conflicts with the rest of the section.
fn conflict<T>(parameter: SlopeParameter, reason: &str) -> Result<T, SlopeError> {
    Err(SlopeError::Conflict {
        parameter,
        reason: reason.to_owned(),
    })
}

/// Checks the layers beside a drawdown: pore pressures from its two lines alone, and a soil that
/// does not drain (its R envelope in `envelopes`) with c′ and φ′ and a valid R envelope.
fn check_drawdown_layers(
    layers: &[Layer],
    envelopes: &[Option<REnvelope>],
) -> Result<(), SlopeError> {
    for (index, (layer, envelope)) in layers.iter().zip(envelopes).enumerate() {
        if layer.pore_pressure_ratio.is_some() || layer.piezometric_line.is_some() {
            return conflict(
                SlopeParameter::Layer { index },
                "a drawdown's pore pressures come from its two lines: give no r_u or own \
                 piezometric line",
            );
        }
        let Some(r) = envelope else { continue };
        if !matches!(layer.strength, Strength::MohrCoulomb) {
            return conflict(
                SlopeParameter::REnvelope { index },
                "a soil that does not drain needs its effective c′ and φ′ (cohesion and \
                 friction_angle_deg), not a strength model",
            );
        }
        check_range(
            SlopeParameter::REnvelope { index },
            r.cohesion,
            0.0,
            false,
            super::validate::MAX_MAGNITUDE,
            "0 ≤ c_R ≤ 1e12",
        )?;
        check_range(
            SlopeParameter::REnvelope { index },
            r.friction_angle_rad,
            0.0,
            false,
            89.9f64.to_radians(),
            "0 ≤ φ_R ≤ 89.9°",
        )?;
        if r.cohesion == 0.0 && r.friction_angle_rad == 0.0 {
            return conflict(
                SlopeParameter::REnvelope { index },
                "c_R = 0 with φ_R = 0 is a soil without undrained strength",
            );
        }
    }
    Ok(())
}

/// The K_c = 1 envelope of τ_ff against σ′_fc from the R envelope: a circle of isotropic
/// consolidation σ′_3c = σ′_fc whose diameter (σ₁ − σ₃)_f reaches the R envelope has radius
/// r = (c_R·cos φ_R + σ′_3c·sin φ_R)/(1 − sin φ_R); the failure plane (at 45° + φ′/2 to the
/// major principal plane) carries τ_ff = r·cos φ′. Returns (d, tan ψ).
pub fn isotropic_envelope(r: REnvelope, friction_angle_rad: f64) -> (f64, f64) {
    let (sin_r, cos_r) = r.friction_angle_rad.sin_cos();
    let cos_phi = friction_angle_rad.cos();
    (
        r.cohesion * cos_r * cos_phi / (1.0 - sin_r),
        sin_r * cos_phi / (1.0 - sin_r),
    )
}

/// The undrained strength τ_ff of a base consolidated under (σ′_fc, τ_fc), with effective
/// c′ and φ′ (radians) and its R envelope.
pub fn undrained_strength(
    (sigma, tau): (f64, f64),
    (cohesion, friction_angle_rad): (f64, f64),
    r: REnvelope,
) -> f64 {
    let sigma = sigma.max(0.0);
    let (s, c) = friction_angle_rad.sin_cos();
    let (d, tan_psi) = isotropic_envelope(r, friction_angle_rad);
    let isotropic = d + sigma * tan_psi;
    let at_failure = cohesion + sigma * friction_angle_rad.tan();
    // σ′_3c of the base's consolidation, and of consolidation at failure (K_c = K_f).
    let minor = sigma + tau * (s - 1.0) / c;
    let minor_at_failure = (sigma - cohesion * c) * (1.0 - s) / (c * c);
    let lower = isotropic.min(at_failure);
    if minor <= 0.0 || minor_at_failure <= 0.0 {
        return lower;
    }
    let k = (sigma + tau * (1.0 + s) / c) / minor;
    let k_f = (sigma + cohesion * c) * (1.0 + s) / ((sigma - cohesion * c) * (1.0 - s));
    if !(k_f > 1.0 && k.is_finite()) {
        return lower;
    }
    let k = k.clamp(1.0, k_f);
    // ((K_f − K)·τ₁ + (K − 1)·τ_f)/(K_f − 1), written so that equal envelopes give their value.
    isotropic + (k - 1.0) / (k_f - 1.0) * (at_failure - isotropic)
}

/// F and each base's effective normal force of `model` by Spencer's method, or why not.
fn solved(model: &SliceModel, stage: &str) -> Result<(f64, Vec<f64>), SlopeError> {
    let s = solve_spencer(model, &SpencerSettings::default());
    match s.factor_of_safety {
        Some(f) => Ok((
            f,
            s.slice_forces
                .iter()
                .map(|f| f.effective_normal_force)
                .collect(),
        )),
        None => Err(SlopeError::NoSlipMass {
            parameter: SlopeParameter::Drawdown,
            reason: format!(
                "{stage}: Spencer's equations have no solution on this surface ({:?})",
                s.status
            ),
        }),
    }
}

/// Runs the stages on `after`, the surface's slices after the drawdown (drained strengths),
/// with `before` the same slices before it: `after` is left with the strengths of the last
/// stage, whose F is the answer.
pub(super) fn stages(
    drawdown: &Drawdown,
    before: &SliceModel,
    after: &mut SliceModel,
) -> Result<DrawdownStages, SlopeError> {
    let same = before.slices.len() == after.slices.len()
        && before
            .slices
            .iter()
            .zip(&after.slices)
            .all(|(a, b)| a.x_left == b.x_left && a.x_right == b.x_right);
    if !same {
        return Err(SlopeError::NoSlipMass {
            parameter: SlopeParameter::Drawdown,
            reason: "the slices before and after the drawdown differ".to_owned(),
        });
    }
    // The same slices in the same soils: each base's drained c′ and tan φ′ are the ones it
    // had before the drawdown.
    let (before_factor, normals) = solved(before, "before the drawdown (stage 1)")?;
    let mut undrained_slices = Vec::new();
    for (i, (slice, consolidated)) in after.slices.iter_mut().zip(&before.slices).enumerate() {
        let Some(r) = drawdown.envelope(slice.layer) else {
            continue;
        };
        let sigma = normals[i] / consolidated.base_length;
        let (c, tan_phi) = (consolidated.cohesion, consolidated.tan_phi);
        let tau = (c + sigma.max(0.0) * tan_phi) / before_factor;
        slice.cohesion = undrained_strength((sigma, tau), (c, tan_phi.atan()), r);
        slice.tan_phi = 0.0;
        undrained_slices.push(i);
    }
    let (undrained_factor, normals) = solved(after, "after the drawdown (stage 2)")?;
    let mut drained_slices = Vec::new();
    for &i in &undrained_slices {
        let slice = &mut after.slices[i];
        let (c, tan_phi) = (before.slices[i].cohesion, before.slices[i].tan_phi);
        let sigma = (normals[i] / slice.base_length).max(0.0);
        // Lower beyond rounding: equal strengths keep the undrained one.
        if c + sigma * tan_phi < slice.cohesion * (1.0 - 1e-12) {
            (slice.cohesion, slice.tan_phi) = (c, tan_phi);
            drained_slices.push(i);
        }
    }
    Ok(DrawdownStages {
        before_factor,
        undrained_factor,
        undrained_slices,
        drained_slices,
    })
}
