//! The collapse mechanism in answers: block velocities, and the friction check that corrects
//! it (Livesley 1978 §2.7–2.9; Gilbert, Casapulla & Ahmed 2006).

use serde::Serialize;
use thrustline_solver::arch::non_associative::NonAssociative;
use thrustline_solver::arch::Mechanism;
use utoipa::ToSchema;

/// Virtual velocity of one block in the mechanism.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct BlockVelocityDto {
    /// Block number (1-based).
    pub block: usize,
    /// Velocity of the centroid in x.
    pub u: f64,
    /// Velocity of the centroid in y.
    pub v: f64,
    /// Rotation rate (counter-clockwise).
    pub rotation: f64,
}

/// The collapse mechanism, normalised so that the fastest block corner moves at speed 1.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MechanismDto {
    /// Velocity of every block.
    pub blocks: Vec<BlockVelocityDto>,
}

impl MechanismDto {
    /// The mechanism as answered (blocks numbered from 1).
    pub fn new(m: &Mechanism) -> Self {
        Self {
            blocks: m
                .velocities
                .iter()
                .enumerate()
                .map(|(b, v)| BlockVelocityDto {
                    block: b + 1,
                    u: v[0],
                    v: v[1],
                    rotation: v[2],
                })
                .collect(),
        }
    }
}

/// Friction without dilatancy: the iteration of Gilbert, Casapulla & Ahmed (2006).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct NonAssociativeOutDto {
    /// The associative programme's factor the iteration started from.
    #[schema(required = true)]
    pub associative_load_factor: Option<f64>,
    /// The factor the iteration settled on; null when it did not settle.
    #[schema(required = true)]
    pub load_factor: Option<f64>,
    /// λ at each step: the associative programme's, then each programme with the shear
    /// capacities μ·N fixed from the previous (relaxed) normal forces.
    pub load_factors: Vec<Option<f64>>,
    /// Whether it reached a state whose own normal forces carry its shear, |t| ≤ μ·N at every
    /// joint (to 1e-7 of the weight), with the normal forces no longer moving.
    pub settled: bool,
    /// The corrected mechanism (Livesley §2.7): sliding joints slide without opening; null
    /// when nothing slides.
    #[schema(required = true)]
    pub corrected_mechanism: Option<MechanismDto>,
}

impl NonAssociativeOutDto {
    /// The answer's account of the iteration.
    pub fn new(outcome: &NonAssociative) -> Self {
        Self {
            associative_load_factor: outcome.associative.load_factor,
            load_factor: outcome
                .settled
                .then_some(outcome.solution.load_factor)
                .flatten(),
            load_factors: outcome.history.clone(),
            settled: outcome.settled,
            corrected_mechanism: outcome.corrected.as_ref().map(MechanismDto::new),
        }
    }
}
