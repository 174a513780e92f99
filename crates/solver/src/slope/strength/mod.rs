//! Strength models beyond Mohr–Coulomb (model §8): undrained strength that varies with depth,
//! and envelopes whose shear strength is a nonlinear function of the effective normal stress
//! (a power curve, Hoek–Brown, a piecewise-linear shear–normal function).
//!
//! Undrained strength depends on where a base lies only: it is written into the base's
//! cohesion when the slices are cut. A nonlinear envelope depends on the base's σ′ₙ, which
//! depends on F: each base carries the tangent to its envelope (c_t, tan φ_t) at an estimate of
//! σ′ₙ, and Spencer's method and the others solve, reads each base's σ′ₙ, moves the tangents there and solves
//! again until the strength every base carries is its envelope's at its own σ′ₙ.

mod hoek_brown;

pub use hoek_brown::HoekBrown;

/// The steepest tangent a base carries: tan 80°. Where an envelope is steeper (a power curve
/// with b < 1 or Hoek–Brown near their tensile ends) the tangent is flattened; the strength at
/// the linearisation point is still the envelope's, so the consistent state does not change.
const MAX_TANGENT: f64 = 5.671_281_819_617_709;

/// How the consistent state was reached.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Consistency {
    /// Rounds of solving (0 when nothing is nonlinear: one solve, nothing to settle).
    pub rounds: usize,
    /// Whether the strengths settled on their envelopes (always, when nothing is nonlinear).
    pub settled: bool,
}

impl Default for Consistency {
    fn default() -> Self {
        Self {
            rounds: 0,
            settled: true,
        }
    }
}

/// A base's soil strength model (Mohr–Coulomb when none is given: the soil's c′ and φ′).
#[derive(Debug, Clone, PartialEq)]
pub enum Strength {
    /// c′ and φ′ of the soil.
    MohrCoulomb,
    /// Undrained strength that grows with depth; φ = 0.
    Undrained(Undrained),
    /// A nonlinear envelope τ(σ′ₙ).
    Envelope(Envelope),
}

/// Where the depth of an undrained profile is measured from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reference {
    /// Below a level y_d: s_u = s_u0 + k·max(0, y_d − y).
    Datum(f64),
    /// Below the ground at the base's x.
    Ground,
}

/// s_u = s_u0 + k·depth, capped at `cohesion_max` when given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Undrained {
    /// s_u0 at the reference (≥ 0).
    pub cohesion: f64,
    /// k, the increase per unit depth (≥ 0).
    pub gradient: f64,
    /// What the depth is measured from.
    pub reference: Reference,
    /// The cap, when given.
    pub cohesion_max: Option<f64>,
}

impl Undrained {
    /// s_u at height y where the ground is at `ground`.
    pub fn at(&self, y: f64, ground: f64) -> f64 {
        let depth = match self.reference {
            Reference::Datum(datum) => datum - y,
            Reference::Ground => ground - y,
        };
        let s = self.cohesion + self.gradient * depth.max(0.0);
        self.cohesion_max.map_or(s, |cap| s.min(cap))
    }

    /// The profile with every strength divided by `factor` (a design value).
    pub fn divided(self, factor: f64) -> Self {
        Self {
            cohesion: self.cohesion / factor,
            gradient: self.gradient / factor,
            cohesion_max: self.cohesion_max.map(|c| c / factor),
            ..self
        }
    }
}

/// A nonlinear strength envelope.
#[derive(Debug, Clone, PartialEq)]
pub enum Envelope {
    /// τ = a·(σ′ₙ + d)^b + c; τ = c where σ′ₙ + d ≤ 0.
    PowerCurve {
        /// a ≥ 0.
        a: f64,
        /// 0 < b ≤ 1.
        b: f64,
        /// c ≥ 0.
        c: f64,
        /// d (a shift of the normal stress).
        d: f64,
    },
    /// The generalised Hoek–Brown criterion.
    HoekBrown(HoekBrown),
    /// Straight between points (σ′ₙ, τ) of increasing σ′ₙ, continued along the first and last
    /// pieces, never below τ = 0.
    ShearNormal(Vec<(f64, f64)>),
    /// Another envelope with its strength divided by a factor (a design value).
    Divided(Box<Envelope>, f64),
}

impl Envelope {
    /// τ and dτ/dσ′ₙ at σ′ₙ = `sigma`.
    pub fn shear(&self, sigma: f64) -> (f64, f64) {
        match self {
            Self::PowerCurve { a, b, c, d } => {
                let s = sigma + d;
                if s <= 0.0 {
                    (*c, 0.0)
                } else {
                    let p = s.powf(*b);
                    (a * p + c, a * b * p / s)
                }
            }
            Self::HoekBrown(hb) => hb.shear(sigma),
            Self::ShearNormal(points) => shear_normal(points, sigma),
            Self::Divided(envelope, factor) => {
                let (tau, slope) = envelope.shear(sigma);
                (tau / factor, slope / factor)
            }
        }
    }

    /// The tangent (c_t, tan φ_t) at σ′ₙ = `sigma`, its slope within 0 ≤ tan φ_t ≤ tan 80°.
    pub fn tangent(&self, sigma: f64) -> (f64, f64) {
        let (tau, slope) = self.shear(sigma);
        let tan_phi = slope.clamp(0.0, MAX_TANGENT);
        (tau - tan_phi * sigma, tan_phi)
    }
}

/// The piecewise-linear envelope through `points` (at least two, σ increasing) at σ.
fn shear_normal(points: &[(f64, f64)], sigma: f64) -> (f64, f64) {
    let n = points.len();
    if n < 2 {
        return (points.first().map_or(0.0, |p| p.1.max(0.0)), 0.0);
    }
    let i = points.partition_point(|p| p.0 <= sigma).clamp(1, n - 1);
    let ((x0, y0), (x1, y1)) = (points[i - 1], points[i]);
    let slope = (y1 - y0) / (x1 - x0);
    let tau = y0 + slope * (sigma - x0);
    if tau < 0.0 {
        (0.0, 0.0)
    } else {
        (tau, slope)
    }
}

#[cfg(test)]
mod tests;
