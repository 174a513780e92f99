//! Partial factors (EN 1997-1 Annex A; model §9.1): a design approach's factors on the soil's
//! strength and weight, on the loads by their action, and on the resistance; the section and
//! soil in design values, and the verdict on the factor of safety found with them.
//!
//! Design values: tan φ'/γ_φ and c'/γ_c (a soil with φ' = 0 is undrained: c_u/γ_cu), unit
//! weights ·γ_γ, unfavourable loads ·γ_G (permanent) or ·γ_Q (variable), favourable loads
//! ·1 (permanent) or ·0 (variable). DA2 factors the effect instead: F is found with variable
//! loads ·γ_Q/γ_G and permanent ones as they are, and the over-design factor is F/(γ_G·γ_R);
//! otherwise it is F/γ_R. Pore water, seismic coefficients and support capacities are taken
//! as given. Strength models (model §8): an undrained profile's s_u/γ_cu; a nonlinear
//! envelope's τ/γ_φ (M2 has γ_c = γ_φ, so its cohesive and frictional parts alike).

use super::error::{SlopeError, SlopeParameter};
use super::section::{LineLoad, SectionParts, Surcharge};
use super::spencer::Soil;
use super::strength::{Envelope, Strength};

/// An EN 1997-1 design approach, or factors of one's own.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Approach {
    /// DA1 combination 1: A1 + M1 + R1.
    Da1Combination1,
    /// DA1 combination 2: A2 + M2 + R1.
    Da1Combination2,
    /// DA2: A1 + M1 + R2, on the effect of the actions.
    Da2,
    /// DA3: A2 (the geotechnical actions) + M2 + R3.
    Da3,
    /// The factors given.
    Custom,
}

/// The partial factors (each > 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Factors {
    /// γ_φ, on tan φ'.
    pub friction: f64,
    /// γ_c, on c'.
    pub cohesion: f64,
    /// γ_cu, on c_u (a soil with φ' = 0).
    pub undrained: f64,
    /// γ_γ, on unit weights.
    pub unit_weight: f64,
    /// γ_G, on unfavourable permanent loads.
    pub permanent: f64,
    /// γ_Q, on unfavourable variable loads.
    pub variable: f64,
    /// γ_R, on the resistance.
    pub resistance: f64,
}

/// M1, A1, R1: every factor 1 (the characteristic values).
const UNITY: Factors = Factors {
    friction: 1.0,
    cohesion: 1.0,
    undrained: 1.0,
    unit_weight: 1.0,
    permanent: 1.0,
    variable: 1.0,
    resistance: 1.0,
};

/// How a load acts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Action {
    /// Variable (traffic, storage) rather than permanent.
    pub variable: bool,
    /// Favourable: it helps stability (then permanent ·1, variable ·0).
    pub favourable: bool,
}

/// What the design check found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Verdict {
    /// The check.
    pub design: Design,
    /// F on the design values.
    pub factor_of_safety: Option<f64>,
    /// F/γ_R (DA2: F/(γ_G·γ_R)); null without F.
    pub over_design_factor: Option<f64>,
    /// Whether the over-design factor is at least 1.
    pub verified: bool,
}

/// A design check: its approach and factors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Design {
    /// The approach.
    pub approach: Approach,
    /// Its factors.
    pub factors: Factors,
}

impl Design {
    /// An approach of EN 1997-1 Annex A with its factors (`Custom`: all 1).
    pub fn approach(approach: Approach) -> Self {
        let m2 = Factors {
            friction: 1.25,
            cohesion: 1.25,
            undrained: 1.4,
            ..UNITY
        };
        let factors = match approach {
            Approach::Da1Combination1 => Factors {
                permanent: 1.35,
                variable: 1.5,
                ..UNITY
            },
            Approach::Da1Combination2 | Approach::Da3 => Factors {
                variable: 1.3,
                ..m2
            },
            Approach::Da2 => Factors {
                permanent: 1.35,
                variable: 1.5,
                resistance: 1.1,
                ..UNITY
            },
            Approach::Custom => UNITY,
        };
        Self { approach, factors }
    }

    /// Factors of one's own, each finite and > 0 (at most 100).
    pub fn custom(factors: Factors) -> Result<Self, SlopeError> {
        let named = [
            ("friction", factors.friction),
            ("cohesion", factors.cohesion),
            ("undrained", factors.undrained),
            ("unit_weight", factors.unit_weight),
            ("permanent", factors.permanent),
            ("variable", factors.variable),
            ("resistance", factors.resistance),
        ];
        for (name, value) in named {
            if !(value.is_finite() && value > 0.0 && value <= 100.0) {
                return Err(SlopeError::OutOfRange {
                    parameter: SlopeParameter::DesignFactor { name },
                    value,
                    allowed: "a partial factor 0 < γ ≤ 100",
                });
            }
        }
        Ok(Self {
            approach: Approach::Custom,
            factors,
        })
    }

    /// The soil in design values.
    pub fn soil(&self, soil: Soil) -> Result<Soil, SlopeError> {
        let f = &self.factors;
        let undrained = soil.friction_angle_rad == 0.0;
        let cohesion = soil.cohesion / if undrained { f.undrained } else { f.cohesion };
        let tan_phi = soil.friction_angle_rad.tan() / f.friction;
        Soil::new(
            soil.unit_weight * f.unit_weight,
            cohesion,
            tan_phi.atan().to_degrees(),
            soil.pore_pressure_ratio(),
        )
    }

    /// A soil's total-stress (R) envelope of a rapid drawdown in design values: c_R/γ_c and
    /// tan φ_R/γ_φ, as its effective strength.
    pub fn total_stress_envelope(
        &self,
        r: crate::slope::section::drawdown::REnvelope,
    ) -> crate::slope::section::drawdown::REnvelope {
        let f = &self.factors;
        crate::slope::section::drawdown::REnvelope {
            cohesion: r.cohesion / f.cohesion,
            friction_angle_rad: (r.friction_angle_rad.tan() / f.friction).atan(),
        }
    }

    /// The factor on a load acting as `action`.
    pub fn load_factor(&self, action: Action) -> f64 {
        let f = &self.factors;
        match (action.favourable, action.variable, self.approach) {
            (true, false, _) => 1.0,
            (true, true, _) => 0.0,
            // DA2 factors the effect: the actions' ratio here, γ_G on the answer.
            (false, false, Approach::Da2) => 1.0,
            (false, true, Approach::Da2) => f.variable / f.permanent,
            (false, false, _) => f.permanent,
            (false, true, _) => f.variable,
        }
    }

    /// The section's parts in design values: every layer's soil, and each surcharge and line
    /// load by its action (`surcharges`, `line_loads`: one action per load, in order).
    pub fn section(
        &self,
        mut parts: SectionParts,
        surcharges: &[Action],
        line_loads: &[Action],
    ) -> Result<SectionParts, SlopeError> {
        let f = &self.factors;
        for layer in &mut parts.layers {
            match &layer.strength {
                Strength::MohrCoulomb => layer.soil = self.soil(layer.soil)?,
                Strength::Undrained(u) => {
                    layer.soil = Soil::weight_only(layer.soil.unit_weight * f.unit_weight)?;
                    layer.strength = Strength::Undrained(u.divided(f.undrained));
                }
                Strength::Envelope(e) => {
                    layer.soil = Soil::weight_only(layer.soil.unit_weight * f.unit_weight)?;
                    layer.strength =
                        Strength::Envelope(Envelope::Divided(Box::new(e.clone()), f.friction));
                }
            }
        }
        for (s, &action) in parts.surcharges.iter_mut().zip(surcharges) {
            let k = self.load_factor(action);
            *s = Surcharge {
                pressure: s.pressure * k,
                pressure_end: s.pressure_end * k,
                ..*s
            };
        }
        for (l, &action) in parts.line_loads.iter_mut().zip(line_loads) {
            let k = self.load_factor(action);
            *l = LineLoad {
                fx: l.fx * k,
                fy: l.fy * k,
                ..*l
            };
        }
        Ok(parts)
    }

    /// The verdict on F found with the design values.
    pub fn verdict(&self, factor_of_safety: Option<f64>) -> Verdict {
        let f = &self.factors;
        let divisor = match self.approach {
            Approach::Da2 => f.permanent * f.resistance,
            _ => f.resistance,
        };
        let over_design_factor = factor_of_safety.map(|v| v / divisor);
        Verdict {
            design: *self,
            factor_of_safety,
            over_design_factor,
            verified: over_design_factor.is_some_and(|v| v >= 1.0),
        }
    }
}
