//! The data of a limit analysis: the structure with its loads and yield limits, the settings of
//! the interior-point solves, and the plain solution they return (Livesley 1978, §2.3).

use crate::arch::equilibrium::LiveLoad;
use crate::arch::error::{ArchError, ArchParameter};
use crate::arch::fill::PassiveForce;
use crate::arch::geometry::{Assembly, InterfaceKind};
use crate::arch::mechanism::{Bound, Mechanism, Resultant};
use crate::budget::{Budget, Stop};
use crate::outcome::SolverFailure;

/// Limits on the stress resultants of every interface (absolute forces; `None` = unbounded).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InterfaceLimits {
    /// Lower limit of q (0 = no tension at the extrados end).
    pub q_min: Option<f64>,
    /// Upper limit of q (crushing).
    pub q_max: Option<f64>,
    /// Lower limit of s (0 = no tension at the intrados end).
    pub s_min: Option<f64>,
    /// Upper limit of s (crushing).
    pub s_max: Option<f64>,
    /// Lower limit of the shear t.
    pub t_min: Option<f64>,
    /// Upper limit of the shear t.
    pub t_max: Option<f64>,
}

impl InterfaceLimits {
    /// Heyman's assumptions: no tension, infinite compressive strength, no sliding.
    pub fn heyman() -> Self {
        Self {
            q_min: Some(0.0),
            q_max: None,
            s_min: Some(0.0),
            s_max: None,
            t_min: None,
            t_max: None,
        }
    }

    pub(super) fn bounds(&self) -> [(Resultant, Bound, Option<f64>); 6] {
        [
            (Resultant::Q, Bound::Lower, self.q_min),
            (Resultant::Q, Bound::Upper, self.q_max),
            (Resultant::S, Bound::Lower, self.s_min),
            (Resultant::S, Bound::Upper, self.s_max),
            (Resultant::T, Bound::Lower, self.t_min),
            (Resultant::T, Bound::Upper, self.t_max),
        ]
    }

    /// Whether every finite limit is zero: the admissible set is then a cone.
    pub fn is_homogeneous(&self) -> bool {
        self.bounds()
            .iter()
            .all(|(_, _, v)| v.unwrap_or(0.0) == 0.0)
    }
}

/// A rigid-block structure with its loads and limits, validated.
#[derive(Debug, Clone, PartialEq)]
pub struct ArchProblem {
    pub(super) assembly: Assembly,
    pub(super) unit_weight: f64,
    pub(super) limits: InterfaceLimits,
    pub(super) friction: Option<f64>,
    pub(super) live_loads: Vec<LiveLoad>,
    pub(super) dead_loads: Vec<LiveLoad>,
    pub(super) crushing: Option<Crushing>,
    pub(super) passive: Vec<PassiveForce>,
    /// Limits and friction of the ring interfaces of a multi-ring arch, when they differ.
    pub(super) ring: Option<(InterfaceLimits, Option<f64>)>,
    /// Cohesion c of the ring interfaces: shear capacity μ·N + c·ℓ (model §10).
    pub(super) ring_cohesion: f64,
    /// Friction and cohesion of single interfaces, by interface (sorted, each once): they
    /// replace the problem's (or the rings') friction and cohesion there.
    pub(super) own: Vec<(usize, Option<f64>, f64)>,
    /// Shear capacities |t| ≤ c_k + `friction_slope`·μ_k·N in place of the friction rows (a
    /// step of the non-associative iteration), per interface; only where it has friction.
    pub(super) shear_capacities: Option<Vec<f64>>,
    /// With `shear_capacities`: the fraction α of the friction coefficient kept as the slope
    /// of the modified surface |t| ≤ c_k + α·μ_k·N.
    pub(super) friction_slope: f64,
}

/// Crushing of the joints (model §5.2): a joint of thickness t carries N = q + s ≤ σ_c·t and a
/// moment about its middle |M| ≤ N·(t − N/σ_c)/2 (the rectangular stress block), linearised by
/// the tangents to that parabola at `planes` values of N/(σ_c·t) spaced as
/// ½(1 − cos(πk/(planes − 1))) — denser at both ends, where the curve bends; the first tangent
/// (N = 0) is Heyman's no-tension limit, the last (N = σ_c·t) bounds N. Tangents lie outside the
/// parabola, so λ tends to the exact value from above as the planes increase.
#[derive(Debug, Clone, PartialEq)]
pub struct Crushing {
    /// Compressive strength σ_c (force per unit area per unit depth).
    pub strength: f64,
    /// Number of tangent planes (≥ 2).
    pub planes: usize,
    /// More tangents (interface, n), added where a solution went beyond the exact curve.
    pub cuts: Vec<(usize, f64)>,
}

impl Crushing {
    /// The tangent points n_k = N/(σ_c·t).
    pub fn tangent_points(&self) -> Vec<f64> {
        let k_max = (self.planes.max(2) - 1) as f64;
        (0..self.planes.max(2))
            .map(|k| 0.5 * (1.0 - (std::f64::consts::PI * k as f64 / k_max).cos()))
            .collect()
    }
}

impl ArchProblem {
    /// Checks the numbers: unit weight > 0; each limit finite with min ≤ 0 ≤ max (the unloaded
    /// state must be admissible); friction coefficient finite ≥ 0; loads on existing blocks.
    pub fn new(
        assembly: Assembly,
        unit_weight: f64,
        limits: InterfaceLimits,
        friction: Option<f64>,
        live_loads: Vec<LiveLoad>,
    ) -> Result<Self, ArchError> {
        if !(unit_weight.is_finite() && unit_weight > 0.0) {
            return Err(ArchError::range(
                ArchParameter::UnitWeight,
                unit_weight,
                "a finite number > 0",
            ));
        }
        for &(resultant, bound, value) in &limits.bounds() {
            if let Some(v) = value {
                let ok = v.is_finite()
                    && match bound {
                        Bound::Lower => v <= 0.0,
                        Bound::Upper => v >= 0.0,
                    };
                if !ok {
                    let allowed = match bound {
                        Bound::Lower => "a finite number ≤ 0 or null (unbounded)",
                        Bound::Upper => "a finite number ≥ 0 or null (unbounded)",
                    };
                    return Err(ArchError::range(
                        ArchParameter::InterfaceLimit { resultant, bound },
                        v,
                        allowed,
                    ));
                }
            }
        }
        check_friction(friction)?;
        for (i, load) in live_loads.iter().enumerate() {
            if load.block >= assembly.blocks.len() {
                return Err(ArchError::range(
                    ArchParameter::LoadBlock { index: i },
                    (load.block + 1) as f64,
                    format!("a block number 1 ≤ block ≤ {}", assembly.blocks.len()),
                ));
            }
            let values = [load.point.0, load.point.1, load.fx, load.fy, load.moment];
            if let Some(&value) = values.iter().find(|v| !v.is_finite()) {
                return Err(ArchError::range(
                    ArchParameter::Load { index: i },
                    value,
                    "finite numbers",
                ));
            }
        }
        Ok(Self {
            assembly,
            unit_weight,
            limits,
            friction,
            live_loads,
            dead_loads: Vec::new(),
            crushing: None,
            passive: Vec::new(),
            ring: None,
            ring_cohesion: 0.0,
            own: Vec::new(),
            shear_capacities: None,
            friction_slope: 0.0,
        })
    }

    /// The same problem with crushing of the joints.
    pub fn with_crushing(mut self, crushing: Crushing) -> Result<Self, ArchError> {
        if !(crushing.strength.is_finite() && crushing.strength > 0.0) {
            return Err(ArchError::range(
                ArchParameter::CompressiveStrength,
                crushing.strength,
                "a finite number > 0",
            ));
        }
        if !(2..=256).contains(&crushing.planes) {
            return Err(ArchError::range(
                ArchParameter::CrushingPlanes,
                crushing.planes as f64,
                "an integer 2 ≤ planes ≤ 256",
            ));
        }
        self.crushing = Some(crushing);
        Ok(self)
    }

    /// The same problem with passive restraint of a fill: horizontal forces 0 ≤ p ≤ capacity on
    /// the voussoirs, new variables of the programmes (which are then written on the general
    /// assembly: each force enters one block's equilibrium).
    pub fn with_passive(mut self, passive: Vec<PassiveForce>) -> Result<Self, ArchError> {
        for force in &passive {
            let values = [force.point.0, force.point.1, force.capacity];
            let ok = force.block < self.assembly.blocks.len()
                && values.iter().all(|v| v.is_finite())
                && force.capacity >= 0.0
                && force.direction.abs() == 1.0;
            if !ok {
                return Err(ArchError::range(
                    ArchParameter::Passive,
                    force.capacity,
                    "finite passive capacities ≥ 0 on existing blocks, direction ±1",
                ));
            }
        }
        self.passive = passive;
        Ok(self)
    }

    /// The same problem with other limits and friction on the interfaces of
    /// [`InterfaceKind::Ring`] (between the rings of a multi-ring arch); checked as the
    /// problem's own.
    pub fn with_ring_interfaces(
        mut self,
        limits: InterfaceLimits,
        friction: Option<f64>,
    ) -> Result<Self, ArchError> {
        let check = Self::new(
            self.assembly.clone(),
            self.unit_weight,
            limits,
            friction,
            Vec::new(),
        )?;
        self.ring = Some((check.limits, check.friction));
        Ok(self)
    }

    /// The same problem with cohesion `cohesion` (≥ 0) on the ring interfaces: their shear
    /// capacity is μ·N + c·ℓ (with μ = 0, c·ℓ alone).
    pub fn with_ring_cohesion(mut self, cohesion: f64) -> Result<Self, ArchError> {
        check_cohesion(cohesion)?;
        self.ring_cohesion = cohesion;
        Ok(self)
    }

    /// The same problem with interface `k`'s own friction coefficient (`None`: no sliding)
    /// and cohesion (≥ 0), in place of the problem's or the rings'.
    pub fn with_interface(
        mut self,
        k: usize,
        friction: Option<f64>,
        cohesion: f64,
    ) -> Result<Self, ArchError> {
        check_cohesion(cohesion)?;
        check_friction(friction)?;
        if k >= self.assembly.interfaces.len() {
            return Err(ArchError::range(
                ArchParameter::Blocks,
                k as f64,
                "an interface of the assembly",
            ));
        }
        match self.own.binary_search_by_key(&k, |o| o.0) {
            Ok(i) => self.own[i] = (k, friction, cohesion),
            Err(i) => self.own.insert(i, (k, friction, cohesion)),
        }
        Ok(self)
    }

    /// The limits and friction of interface `k`.
    pub(crate) fn material(&self, k: usize) -> (InterfaceLimits, Option<f64>) {
        let (limits, friction) = match (self.assembly.interfaces[k].kind, self.ring) {
            (InterfaceKind::Ring, Some(ring)) => ring,
            _ => (self.limits, self.friction),
        };
        match self.own(k) {
            Some((mu, _)) => (limits, mu),
            None => (limits, friction),
        }
    }

    /// The friction coefficient of interface `k` (`None`: no sliding).
    pub fn friction_of(&self, k: usize) -> Option<f64> {
        self.material(k).1
    }

    /// Interface `k`'s own friction and cohesion, if it has them.
    fn own(&self, k: usize) -> Option<(Option<f64>, f64)> {
        if self.own.is_empty() {
            return None;
        }
        self.own
            .binary_search_by_key(&k, |o| o.0)
            .ok()
            .map(|i| (self.own[i].1, self.own[i].2))
    }

    /// The cohesive shear capacity c·ℓ of interface `k` (0 without cohesion).
    pub fn cohesive_capacity(&self, k: usize) -> f64 {
        let cohesion = match self.own(k) {
            Some((_, c)) => c,
            None if self.assembly.interfaces[k].kind == InterfaceKind::Ring => self.ring_cohesion,
            None => 0.0,
        };
        if cohesion == 0.0 {
            0.0
        } else {
            cohesion * self.assembly.interfaces[k].length()
        }
    }

    /// Whether any interface has cohesion.
    fn has_cohesion(&self) -> bool {
        self.ring_cohesion > 0.0 || self.own.iter().any(|o| o.2 > 0.0)
    }

    /// Whether every finite limit of every interface is zero (the admissible set a cone).
    pub(crate) fn is_homogeneous(&self) -> bool {
        // Crushing (a finite strength) bounds the resultants by the strength, not by the
        // loads: what a load carries, twice the load may not (model §6.5).
        self.limits.is_homogeneous()
            && self.ring.is_none_or(|(l, _)| l.is_homogeneous())
            && self.shear_capacities.is_none()
            && self.crushing.is_none()
            && !self.has_cohesion()
    }

    /// Whether the rings of a multi-ring arch cannot slip on each other (their interfaces have
    /// no friction coefficient, their own or the arch's): staggered joints then lock.
    pub fn has_locked_rings(&self) -> bool {
        let has_rings = self
            .assembly
            .interfaces
            .iter()
            .any(|i| i.kind == crate::arch::geometry::InterfaceKind::Ring);
        let ring_locked = self.ring.map_or(self.friction, |(_, mu)| mu).is_none();
        // Every ring interface slides where its own friction says so.
        has_rings
            && self.assembly.interfaces.iter().enumerate().any(|(k, i)| {
                i.kind == crate::arch::geometry::InterfaceKind::Ring
                    && self.own(k).map_or(ring_locked, |(mu, _)| mu.is_none())
            })
    }

    /// Whether any interface has Coulomb friction.
    pub fn has_friction(&self) -> bool {
        self.friction.is_some()
            || self.ring.is_some_and(|(_, mu)| mu.is_some())
            || self.own.iter().any(|o| o.1.is_some())
    }

    /// The same problem with the friction rows of every interface that has friction replaced
    /// by the modified surface |t_k| ≤ (1 − slope)·μ_k·normal[k] + slope·μ_k·N_k (through
    /// Coulomb's line at N_k = normal[k]; its flow dilates by slope·μ_k only, none at 0);
    /// `normal` holds one normal force per interface (negative taken as 0).
    pub(crate) fn with_fixed_friction(&self, normal: &[f64], slope: f64) -> Self {
        let mut fixed = self.clone();
        let capacities = (0..self.assembly.interfaces.len())
            .map(|k| {
                let mu = self.material(k).1.unwrap_or(0.0);
                (1.0 - slope) * mu * normal.get(k).copied().unwrap_or(0.0).max(0.0)
                    + self.cohesive_capacity(k)
            })
            .collect();
        fixed.shear_capacities = Some(capacities);
        fixed.friction_slope = slope;
        fixed
    }

    /// The passive forces the fill can exert.
    pub fn passive(&self) -> &[PassiveForce] {
        &self.passive
    }

    /// The crushing of the joints, if any.
    pub fn crushing(&self) -> Option<&Crushing> {
        self.crushing.as_ref()
    }

    /// The same problem with other dead loads on the blocks (a fill's weight, say), carried
    /// with the blocks' own weight and scaled with it by the dead-load factor.
    pub fn with_dead_loads(mut self, dead_loads: Vec<LiveLoad>) -> Result<Self, ArchError> {
        for (i, load) in dead_loads.iter().enumerate() {
            let values = [load.point.0, load.point.1, load.fx, load.fy, load.moment];
            if load.block >= self.assembly.blocks.len() || values.iter().any(|v| !v.is_finite()) {
                return Err(ArchError::range(
                    ArchParameter::Load { index: i },
                    load.fy,
                    "finite dead loads on existing blocks",
                ));
            }
        }
        self.dead_loads = dead_loads;
        Ok(self)
    }

    /// The dead loads other than the blocks' own weight.
    pub fn dead_loads(&self) -> &[LiveLoad] {
        &self.dead_loads
    }

    /// The same problem with other live loads.
    pub fn with_live_loads(mut self, live_loads: Vec<LiveLoad>) -> Result<Self, ArchError> {
        let check = Self::new(
            self.assembly.clone(),
            self.unit_weight,
            self.limits,
            self.friction,
            live_loads,
        )?;
        self.live_loads = check.live_loads;
        Ok(self)
    }

    /// The blocks and interfaces.
    pub fn assembly(&self) -> &Assembly {
        &self.assembly
    }

    /// The unit weight γ.
    pub fn unit_weight(&self) -> f64 {
        self.unit_weight
    }

    /// The live loads.
    pub fn live_loads(&self) -> &[LiveLoad] {
        &self.live_loads
    }
}

/// Settings of the interior-point solves.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitSettings {
    /// Clarabel's gap and feasibility tolerances (relative). Defaults to 1e-10.
    pub tolerance: f64,
    /// A dead-load margin at or below this (a fraction of the total weight) counts as carried.
    /// Defaults to 1e-9.
    pub margin_tolerance: f64,
    /// Interior-point iterations per programme. Defaults to 200.
    pub max_iterations: u32,
    /// Which model the programmes are written on. Defaults to [`Formulation::Chain`].
    pub formulation: Formulation,
    /// How the non-associative iteration forms each step's normal forces. Defaults to
    /// [`Relaxation::Paper`].
    pub relaxation: Relaxation,
    /// The whole analysis' budget, the one limit on its time: every programme stops at its
    /// deadline or when it is cancelled (at the next interior-point iteration). Defaults to
    /// unlimited.
    pub budget: Budget,
}

/// How the non-associative iteration (see [`super::non_associative`]) forms the normal forces
/// Ñ each step's shear capacities are built from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Relaxation {
    /// Gilbert, Casapulla & Ahmed's relaxation between the last two steps' normal forces;
    /// where it stops without settling, the Anderson mixing takes over.
    #[default]
    Paper,
    /// The Anderson mixing of the last steps from the first step on: the same fixed points in
    /// fewer programmes.
    Anderson,
}

/// The model of the limit-analysis programmes; both give the same answers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Formulation {
    /// Three redundant forces of the chain (four variables; see [`super::chain`]).
    #[default]
    Chain,
    /// Livesley's general assembly: three resultants per interface and the equilibrium rows.
    Assembly,
}

impl Default for LimitSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            margin_tolerance: 1e-9,
            max_iterations: 200,
            formulation: Formulation::Chain,
            relaxation: Relaxation::Paper,
            budget: Budget::unlimited(),
        }
    }
}

/// How a limit analysis ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LimitStatus {
    /// The load factor was found.
    Solved,
    /// Live load only: the dead load is not carried, so there is no live-load factor.
    DeadLoadNotCarried,
    /// Live load only: no finite multiple of the live load causes collapse.
    Unbounded,
    /// The interior-point method stopped without an answer it can vouch for.
    SolverFailed(SolverFailure),
}

/// What a limit analysis found.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitSolution {
    /// What the programmes answered; meaningful only where `stop` is [`Stop::Finished`].
    pub status: LimitStatus,
    /// How it ended: [`Stop::Finished`], or the budget's reason when the budget ended a
    /// programme (then nothing is answered: no factor, no state).
    pub stop: Stop,
    /// The dead-load factor λ₀ (dead load) or live-load factor λ (live load), when solved.
    pub load_factor: Option<f64>,
    /// Whether the dead load is carried (λ₀ = 1); `None` if that could not be decided.
    pub dead_load_carried: Option<bool>,
    /// Dead-load margin δ at full dead load, a fraction of the total weight: negative is a
    /// reserve (every limit is met with that much to spare), positive a shortfall.
    pub dead_load_margin: Option<f64>,
    /// Resultants (q, s, t) per interface in force units at the load factor (empty when there
    /// is no admissible state to show). For [`LimitStatus::Unbounded`], the state at the cap of
    /// the live-load factor: no collapse below it (a state to start from, not to show).
    pub resultants: Vec<[f64; 3]>,
    /// The collapse mechanism, when the structure is at its limit.
    pub mechanism: Option<Mechanism>,
    /// Iterations over all programmes: interior-point iterations, and simplex pivots on a
    /// chain.
    pub iterations: u32,
    /// Linear programmes solved.
    pub programmes: usize,
    /// The passive force mobilised on each of the problem's [`PassiveForce`]s, in force units
    /// (empty without passive restraint or without an admissible state).
    pub passive: Vec<f64>,
    /// Wall time of the solves in seconds.
    pub solve_time_secs: f64,
}

/// A cohesion: finite, ≥ 0.
fn check_cohesion(cohesion: f64) -> Result<(), ArchError> {
    if cohesion.is_finite() && cohesion >= 0.0 {
        Ok(())
    } else {
        Err(ArchError::range(
            ArchParameter::Cohesion,
            cohesion,
            "a finite number ≥ 0",
        ))
    }
}

/// A friction coefficient: finite, ≥ 0, or `None` (no sliding).
fn check_friction(friction: Option<f64>) -> Result<(), ArchError> {
    match friction {
        Some(mu) if !(mu.is_finite() && mu >= 0.0) => Err(ArchError::range(
            ArchParameter::FrictionCoefficient,
            mu,
            "a finite number ≥ 0 or null (no sliding)",
        )),
        _ => Ok(()),
    }
}
