//! The generalised Hoek–Brown criterion (Hoek, Carranza-Torres & Corkum 2002) and the shear
//! strength on a plane under a given normal stress, from its Mohr envelope (Balmer 1952).
//!
//! σ₁′ = σ₃′ + σ_ci·(m_b·σ₃′/σ_ci + s)^a with m_b = m_i·e^((GSI−100)/(28−14D)),
//! s = e^((GSI−100)/(9−3D)), a = ½ + (e^(−GSI/15) − e^(−20/3))/6. On the envelope, with
//! k = dσ₁′/dσ₃′ = 1 + a·m_b·(m_b·σ₃′/σ_ci + s)^(a−1):
//!
//! ```text
//!   σ′ₙ = (σ₁′+σ₃′)/2 − (σ₁′−σ₃′)/2 · (k−1)/(k+1),   τ = (σ₁′−σ₃′)·√k/(k+1),
//! ```
//!
//! and the envelope's slope there is tan φᵢ = (k−1)/(2√k) (the instantaneous friction angle,
//! sin φᵢ = (k−1)/(k+1)). τ at a given σ′ₙ: σ₃′ from σ′ₙ(σ₃′) = σ′ₙ by Brent's method on
//! [σ_t, σ′ₙ] (σ′ₙ lies between σ₃′ and σ₁′); below the tensile strength σ_t = −s·σ_ci/m_b
//! there is none.

use crate::numerics::brent;

/// The criterion's constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoekBrown {
    /// Uniaxial compressive strength of the intact rock σ_ci (> 0).
    pub sigma_ci: f64,
    /// m_b.
    pub mb: f64,
    /// s.
    pub s: f64,
    /// a.
    pub a: f64,
}

impl HoekBrown {
    /// The constants from σ_ci, GSI (5–100), m_i (> 0) and the disturbance D (0–1).
    pub fn new(sigma_ci: f64, gsi: f64, mi: f64, disturbance: f64) -> Self {
        Self {
            sigma_ci,
            mb: mi * ((gsi - 100.0) / (28.0 - 14.0 * disturbance)).exp(),
            s: ((gsi - 100.0) / (9.0 - 3.0 * disturbance)).exp(),
            a: 0.5 + ((-gsi / 15.0).exp() - (-20.0f64 / 3.0).exp()) / 6.0,
        }
    }

    /// The tensile strength σ_t = −s·σ_ci/m_b (≤ 0).
    pub fn tensile_strength(&self) -> f64 {
        -self.s * self.sigma_ci / self.mb
    }

    /// (σ′ₙ, τ, tan φᵢ) on the envelope where the minor principal stress is σ₃′ (> σ_t).
    pub fn on_envelope(&self, sigma3: f64) -> (f64, f64, f64) {
        let base = (self.mb * sigma3 / self.sigma_ci + self.s).max(0.0);
        let sigma1 = sigma3 + self.sigma_ci * base.powf(self.a);
        let k = 1.0 + self.a * self.mb * base.powf(self.a - 1.0);
        let diff = sigma1 - sigma3;
        let normal = 0.5 * (sigma1 + sigma3) - 0.5 * diff * (k - 1.0) / (k + 1.0);
        let tau = diff * k.sqrt() / (k + 1.0);
        (normal, tau, (k - 1.0) / (2.0 * k.sqrt()))
    }

    /// τ and dτ/dσ′ₙ at σ′ₙ = `sigma` (0 at or below the tensile strength).
    pub fn shear(&self, sigma: f64) -> (f64, f64) {
        let t = self.tensile_strength();
        if sigma <= t || !sigma.is_finite() {
            return (0.0, 0.0);
        }
        let g = |s3: f64| {
            if s3 <= t {
                t - sigma
            } else {
                self.on_envelope(s3).0 - sigma
            }
        };
        let tolerance = 1e-15 * sigma.abs().max(self.sigma_ci);
        let (lo, hi) = (t, sigma);
        let Some(root) = brent(g, lo, hi, t - sigma, g(hi), tolerance, 200) else {
            return (0.0, 0.0);
        };
        if root.x <= t {
            return (0.0, 0.0);
        }
        let (_, tau, slope) = self.on_envelope(root.x);
        (tau, slope)
    }
}
