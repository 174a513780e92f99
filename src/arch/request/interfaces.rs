//! The interfaces of an arch request that differ from the arch's: the ring interfaces of a
//! multi-ring arch and single interfaces named by the blocks they join (wire types; validated
//! by `arch::interfaces`).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// The interfaces between the rings of a multi-ring arch.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RingInterfaceDto {
    /// Friction coefficient μ ≥ 0 between the rings (as `ring_friction_coefficient`, which
    /// it replaces); null or left out: no sliding.
    #[serde(default)]
    #[schema(examples(0.6))]
    pub friction_coefficient: Option<f64>,
    /// Cohesion c ≥ 0 of the mortar between the rings, a force per unit length of interface:
    /// the shear capacity of an interface of length ℓ is μ·N + c·ℓ. Needs a friction
    /// coefficient (0 for cohesion alone). Defaults to 0.
    #[serde(default)]
    #[schema(examples(50.0))]
    pub cohesion: Option<f64>,
}

/// One interface with friction and cohesion of its own.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct InterfaceDto {
    /// The two blocks it joins, 1-based; 0 for a support (`[3, 0]`: block 3 on its
    /// supports). Every contact between them takes these values.
    #[schema(examples(json!([3, 0])))]
    pub blocks: [usize; 2],
    /// Its friction coefficient μ ≥ 0. Left out: the arch's (or the rings').
    #[serde(default)]
    pub friction_coefficient: Option<f64>,
    /// Its cohesion c ≥ 0 (shear capacity μ·N + c·ℓ). Defaults to 0.
    #[serde(default)]
    pub cohesion: Option<f64>,
}
