//! The slices of an answer as a table: each slice's geometry and forces at the solution.

use serde::Serialize;
use thrustline_solver::slope::{SliceModel, SpencerSolution};
use utoipa::ToSchema;

/// Geometry and forces of one slice at the solution.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SliceDto {
    /// Slice number, 1 at the lower (toe) end of the slip surface.
    pub slice: usize,
    /// x of the slice's left side (the smaller x).
    pub x_left: f64,
    /// x of the slice's right side.
    pub x_right: f64,
    /// The soil at the base: the section's layer, numbered from 1 from the top down as the
    /// drawing's key names them (`section.layers[layer − 1]`; 1 for the simple slope).
    pub layer: usize,
    /// Inclination α of the base chord in degrees, positive where it rises towards the crest.
    pub base_inclination_deg: f64,
    /// Length of the base chord.
    pub base_length: f64,
    /// Height of the slice at its middle.
    pub height: f64,
    /// Weight W.
    pub weight: f64,
    /// Pore pressure u at the base middle (r_u·σ_v, or γ_w times the head of the piezometric
    /// line).
    pub pore_pressure: f64,
    /// Total normal force on the base.
    pub normal_force: f64,
    /// Effective normal force on the base (total minus u·l).
    pub effective_normal_force: f64,
    /// Mobilised shear force on the base.
    pub shear_force: f64,
    /// Total normal stress σ = N/l on the base.
    pub normal_stress: f64,
    /// Effective normal stress σ' = σ − u on the base.
    pub effective_normal_stress: f64,
    /// Available shear strength c' + σ'·tan φ' of the base.
    pub available_shear_strength: f64,
    /// Mobilised shear stress τ = (c' + σ'·tan φ')/F on the base.
    pub mobilised_shear_strength: f64,
    /// Resultant Q of the two inter-slice forces, positive along (cos θ, sin θ).
    pub interslice_resultant: f64,
    /// Inter-slice force Z on the crest-side boundary (compression positive; 0 at the exit),
    /// inclined at θ.
    pub interslice_force: f64,
    /// Its normal component E = Z·cos θ (horizontal, on the vertical boundary; compression
    /// positive).
    pub interslice_normal: f64,
    /// Its shear component X = Z·sin θ: the vertical force this slice passes to its crest-side
    /// neighbour (up positive; the slice itself takes −X). 0 in Bishop's forces of
    /// `moment_only`. Each slice balances W, the base's N and S, (E, X) of its toe-side
    /// boundary and −(E, X) of its own.
    pub interslice_shear: f64,
    /// The denominator m_α = cos(α−θ) + sin(α−θ)·tan φ'/F.
    pub m_alpha: f64,
}

/// Each slice's geometry and forces, numbered from 1 at the lower end, in the request's x.
pub fn slice_dtos(
    model: &SliceModel,
    solution: &SpencerSolution,
    to_x: &dyn Fn(f64) -> f64,
) -> Vec<SliceDto> {
    // θ of the answer; Bishop's horizontal forces under `moment_only`.
    let (sin_theta, cos_theta) = solution.theta_rad.unwrap_or(0.0).sin_cos();
    model
        .slices
        .iter()
        .zip(&solution.slice_forces)
        .enumerate()
        .map(|(i, (s, f))| {
            let (a, b) = (to_x(s.x_left), to_x(s.x_right));
            let normal_stress = f.normal_force / s.base_length;
            let effective_normal_stress = f.effective_normal_force / s.base_length;
            let available = f.available_shear_strength;
            SliceDto {
                slice: i + 1,
                x_left: a.min(b),
                x_right: a.max(b),
                layer: s.layer + 1,
                base_inclination_deg: s.base_inclination_rad().to_degrees(),
                base_length: s.base_length,
                height: s.height_middle,
                weight: f.weight,
                pore_pressure: f.pore_pressure,
                normal_force: f.normal_force,
                effective_normal_force: f.effective_normal_force,
                shear_force: f.shear_force,
                normal_stress,
                effective_normal_stress,
                available_shear_strength: available,
                mobilised_shear_strength: f.shear_force / s.base_length,
                interslice_resultant: f.interslice_resultant,
                interslice_force: f.interslice_force_right,
                interslice_normal: f.interslice_force_right * cos_theta,
                interslice_shear: f.interslice_force_right * sin_theta,
                m_alpha: f.m_alpha,
            }
        })
        .collect()
}
