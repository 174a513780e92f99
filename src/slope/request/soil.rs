//! A soil's strength beyond Mohr–Coulomb as clients send it: the strength models and the
//! total-stress envelope of a soil that does not drain (wire types; validated by
//! `slope::strength` and `slope::drawdown`).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// What an undrained profile's depth is measured from, when not from a `datum`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum DepthReferenceDto {
    /// The ground above the point.
    Ground,
}

/// A soil's strength model (instead of `cohesion` and `friction_angle_deg`).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(tag = "model", rename_all = "snake_case", deny_unknown_fields)]
pub enum StrengthDto {
    /// Undrained strength s_u = cohesion + gradient·depth (φ = 0), capped at `cohesion_max`.
    Undrained {
        /// s_u at the datum (or at the ground), 0 ≤ s_u0 ≤ 1e12.
        #[schema(examples(20.0))]
        cohesion: f64,
        /// Increase per unit depth, 0 ≤ k ≤ 1e12. Defaults to 0 (constant s_u).
        #[serde(default)]
        #[schema(examples(1.5))]
        gradient: Option<f64>,
        /// Depth is measured below this level y (above it s_u = s_u0), |y| ≤ 1e9. Give this or
        /// `reference`.
        #[serde(default)]
        datum: Option<f64>,
        /// `ground`: depth is measured below the ground at the point's x. Give this or `datum`.
        #[serde(default)]
        reference: Option<DepthReferenceDto>,
        /// The largest s_u (≥ `cohesion`, ≤ 1e12), when given.
        #[serde(default)]
        cohesion_max: Option<f64>,
    },
    /// A power curve τ = a·(σ′ₙ + d)^b + c (τ = c where σ′ₙ + d ≤ 0); b = 1 is Mohr–Coulomb.
    PowerCurve {
        /// a, 0 ≤ a ≤ 1e12 (in the units that make τ a stress).
        #[schema(examples(2.5))]
        a: f64,
        /// b, 0 < b ≤ 1.
        #[schema(examples(0.75))]
        b: f64,
        /// c, a stress, 0 ≤ c ≤ 1e12. Defaults to 0.
        #[serde(default)]
        c: Option<f64>,
        /// d, a stress added to σ′ₙ, |d| ≤ 1e12. Defaults to 0.
        #[serde(default)]
        d: Option<f64>,
    },
    /// The generalised Hoek–Brown criterion (Hoek, Carranza-Torres & Corkum 2002); the shear
    /// strength at a base is the criterion's Mohr envelope at its σ′ₙ (Balmer 1952).
    HoekBrown {
        /// Uniaxial compressive strength of the intact rock, 0 < σ_ci ≤ 1e12.
        #[schema(examples(30000.0))]
        sigma_ci: f64,
        /// Geological strength index, 5 ≤ GSI ≤ 100.
        #[schema(examples(45.0))]
        gsi: f64,
        /// m_i of the intact rock, 0 < m_i ≤ 100.
        #[schema(examples(10.0))]
        mi: f64,
        /// Disturbance factor D, 0 ≤ D ≤ 1. Defaults to 0.
        #[serde(default)]
        disturbance: Option<f64>,
    },
    /// A piecewise-linear envelope through [σ′ₙ, τ] points (σ′ₙ strictly increasing, τ ≥ 0),
    /// continued along its first and last pieces, never below τ = 0.
    ShearNormal {
        /// 2 to 1000 points [σ′ₙ, τ].
        #[schema(value_type = Vec<Vec<f64>>)]
        points: Vec<[f64; 2]>,
    },
}

/// A soil's total-stress (R) envelope from consolidated-undrained triaxial tests: the line
/// tangent to the circles drawn with the effective consolidation pressure σ′_3c and the
/// principal stress difference at failure.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct REnvelopeDto {
    /// Its intercept c_R, 0 ≤ c_R ≤ 1e12.
    #[schema(examples(5.0))]
    pub cohesion: f64,
    /// Its slope φ_R in degrees, 0 ≤ φ_R ≤ 89.9.
    #[schema(examples(15.0))]
    pub friction_angle_deg: f64,
}
