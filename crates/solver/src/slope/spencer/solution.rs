//! The settings of a Spencer solution and what it returns: status, (F, θ), per-slice forces and
//! the line of thrust.

/// Settings of the Spencer solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpencerSettings {
    /// Convergence tolerance on F (relative) and θ (radians). Defaults to 1e-12.
    pub tolerance: f64,
    /// Maximum Newton iterations before the bracketing fallback. Defaults to 50.
    pub max_iterations: usize,
    /// What to do where the effective normal force on a base comes out negative. Defaults to
    /// [`NegativeEffectiveStress::Keep`].
    pub negative_effective_stress: NegativeEffectiveStress,
    /// Whether Spencer's own F_f/F_m construction is tried when Newton's method fails (slow
    /// where there is no solution; a search over many trial surfaces may go without it).
    /// Defaults to true.
    pub fallback: bool,
}

/// The treatment of a negative effective normal force N' on a slice base (tension, which soil
/// cannot carry).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NegativeEffectiveStress {
    /// The classic equations: N'·tan φ' enters the strength whatever its sign. Spencer's and
    /// the thesis' published numbers are these; a root where the frictional terms add up to a
    /// negative resistance is reported as [`SpencerStatus::Unphysical`], never as converged.
    #[default]
    Keep,
    /// No tension: on slices whose N' comes out negative the frictional term is dropped
    /// (c' kept) and the equations solved again, until no frictional slice is in tension.
    DropFriction,
    /// As `DropFriction`, with c' dropped as well on those slices (no strength in tension).
    DropStrength,
}

impl Default for SpencerSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-12,
            max_iterations: 50,
            negative_effective_stress: NegativeEffectiveStress::Keep,
            fallback: true,
        }
    }
}

/// How the solution of the two equations ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpencerStatus {
    /// Both equations are satisfied to the tolerance with every m_α positive.
    Converged,
    /// No (F, θ) satisfies both equations on the searched range (F in 1e-6…1e6): none with
    /// every denominator m_α positive (|θ| < 89°), and none found past the poles of m_α with
    /// every slice past its pole pressed onto its base.
    NoSolution,
    /// φ' = 0 and no parallel inter-slice forces satisfy force equilibrium, but the moment
    /// equation alone fixes F: with φ' = 0 the base shear c'·l/F does not depend on the normal
    /// forces, so moment equilibrium about the centre gives F whatever the inter-slice forces
    /// (the classical φ = 0 analysis). F is reported, θ is not; per-slice forces are Bishop's
    /// (θ = 0) and there is no line of thrust.
    MomentOnly,
    /// The equations have a root, but not a physical one: F outside 1e-6…1e6, a base pulled
    /// below the apex of its strength envelope (c'·l + N'·tan φ' < 0: a negative strength), or
    /// the frictional terms Σ N'·tan φ' adding up to a negative resistance (tension at the base
    /// carried by friction). No F is reported; `unphysical_root` holds the root for the record.
    Unphysical,
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
    /// The base's strength c + σ′ₙ·tan φ per unit length at the solution (on a nonlinear
    /// envelope, the envelope's at the base's σ′ₙ).
    pub available_shear_strength: f64,
}

/// A point of the line of thrust on a boundary between two slices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThrustPoint {
    /// Index of the boundary: boundary i lies between slices i−1 and i.
    pub boundary: usize,
    /// x of the boundary.
    pub x: f64,
    /// Height of the point of action of the inter-slice force; `None` where the force (or
    /// cos θ) vanishes and the point is undefined.
    pub y: Option<f64>,
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
    /// The line of thrust of the effective inter-slice forces: the total force less the pore
    /// water's push on the boundary (Spencer 1973); empty when not converged.
    pub effective_thrust_line: Vec<ThrustPoint>,
    /// Slices whose m_α is below [`SMALL_DENOMINATOR`] at the solution.
    pub small_m_alpha_slices: Vec<usize>,
    /// Slices whose effective normal force is negative at the solution.
    pub negative_effective_normal_slices: Vec<usize>,
    /// With [`SpencerStatus::Unphysical`]: the root that was rejected.
    pub unphysical_root: Option<f64>,
    /// Slices whose frictional strength (and with `DropStrength` cohesion) was dropped because
    /// their effective normal force came out negative.
    pub tension_dropped_slices: Vec<usize>,
    /// Largest scaled residual of the two equations at the solution (force / ΣW, moment /
    /// (ΣW·R)).
    /// `None` when there is no solution.
    pub residual: Option<f64>,
    /// How nonlinear strength envelopes reached their consistent state (rounds 0 without
    /// any).
    pub strength: crate::slope::strength::Consistency,
}
