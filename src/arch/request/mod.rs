//! The arch requests as clients send them (serde + OpenAPI types). [`super::input`] turns them
//! into the solver's validated inputs; nothing else reads them.
//!
//! The three arch routes share the material and the solver controls: `arch_request!`
//! declares them once.

use serde::{Deserialize, Deserializer, Serialize};
use thrustline_solver::arch::{Formulation, Relaxation};
use utoipa::ToSchema;

use super::geometry::GeometryDto;

pub mod design;
pub mod interfaces;

/// The model of the limit-analysis programmes.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum FormulationDto {
    /// Three redundant forces of the chain, with constraint generation.
    #[default]
    Chain,
    /// Livesley's general assembly: three resultants per interface and equilibrium rows.
    Assembly,
}

impl FormulationDto {
    /// The solver's formulation.
    pub fn solver(self) -> Formulation {
        match self {
            Self::Chain => Formulation::Chain,
            Self::Assembly => Formulation::Assembly,
        }
    }
}

/// How Coulomb friction acts at sliding joints.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum FrictionDto {
    /// The associated flow rule of the linear programme (sliding joints dilate); where the
    /// mechanism slides, the non-associative check runs too and sets
    /// `friction_may_overestimate`.
    #[default]
    Associative,
    /// No dilatancy: the iteration of Gilbert, Casapulla & Ahmed (2006) gives the answer.
    NonAssociative,
}

/// How the non-associative iteration forms each step's normal forces.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum FrictionRelaxationDto {
    /// Gilbert, Casapulla & Ahmed's relaxation between the last two steps' normal forces
    /// (β = 0.6); where it stops without settling, the Anderson mixing takes over.
    #[default]
    Paper,
    /// The Anderson mixing of the last three steps from the first step on: the same fixed
    /// points (λ to 1e-6 on the 108 requests of `bench/na_walls.py`) in fewer programmes
    /// (median 10 against 27 there).
    Anderson,
}

impl FrictionRelaxationDto {
    /// The solver's relaxation.
    pub fn solver(self) -> Relaxation {
        match self {
            Self::Paper => Relaxation::Paper,
            Self::Anderson => Relaxation::Anderson,
        }
    }
}

/// A detail of a dead- or live-load answer that `include` can leave out.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ArchDetailDto {
    /// `thrust_line` (one point per interface).
    ThrustLine,
    /// `mechanism` (one velocity per block).
    Mechanism,
    /// `active_constraints`.
    ActiveConstraints,
    /// `hinges`.
    Hinges,
    /// `reactions`.
    Reactions,
}

impl ArchDetailDto {
    /// Every detail, in the order of the answer.
    pub const ALL: [Self; 5] = [
        Self::ActiveConstraints,
        Self::Hinges,
        Self::Mechanism,
        Self::ThrustLine,
        Self::Reactions,
    ];
}

/// Limits on the interface resultants (absolute forces). A missing field takes Heyman's value
/// (q_min = s_min = 0, the rest unbounded); `null` means unbounded.
#[derive(Debug, Clone, Default, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct InterfaceLimitsDto {
    /// Lower limit of q, the normal force at the extrados end (≤ 0; 0 = no tension).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>, examples(0.0))]
    pub q_min: Option<Option<f64>>,
    /// Upper limit of q (≥ 0; crushing).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>)]
    pub q_max: Option<Option<f64>>,
    /// Lower limit of s, the normal force at the intrados end (≤ 0; 0 = no tension).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>, examples(0.0))]
    pub s_min: Option<Option<f64>>,
    /// Upper limit of s (≥ 0; crushing).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>)]
    pub s_max: Option<Option<f64>>,
    /// Lower limit of the shear t (≤ 0).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>)]
    pub t_min: Option<Option<f64>>,
    /// Upper limit of the shear t (≥ 0).
    #[serde(default, deserialize_with = "present")]
    #[schema(value_type = Option<f64>)]
    pub t_max: Option<Option<f64>>,
}

/// Tells a field that is present (possibly `null`) from one that is absent.
fn present<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Option<Option<f64>>, D::Error> {
    Option::<f64>::deserialize(deserializer).map(Some)
}

/// A live load: a force and a moment on one block.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadDto {
    /// Block number (1-based).
    #[schema(examples(5))]
    #[serde(deserialize_with = "crate::nullable::integer")]
    pub block: usize,
    /// x of the point of application. Defaults to the block centroid.
    #[serde(default)]
    pub x: Option<f64>,
    /// y of the point of application. Defaults to the block centroid.
    #[serde(default)]
    pub y: Option<f64>,
    /// Horizontal force component. Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub fx: f64,
    /// Vertical force component (up positive). Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(examples(-1.0))]
    pub fy: f64,
    /// Applied moment, counter-clockwise positive. Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub moment: f64,
}

/// The material every arch request shares, borrowed from it for validation.
#[derive(Debug, Clone, Copy)]
pub struct MaterialFields<'a> {
    /// `unit_weight`.
    pub unit_weight: f64,
    /// `interface_limits`.
    pub interface_limits: &'a InterfaceLimitsDto,
    /// `friction_coefficient`.
    pub friction_coefficient: Option<f64>,
    /// `ring_interface_limits`.
    pub ring_interface_limits: &'a InterfaceLimitsDto,
    /// `ring_friction_coefficient`.
    pub ring_friction_coefficient: Option<f64>,
}

/// What the dead- and live-load requests share, borrowed from them for validation.
#[derive(Debug, Clone, Copy)]
pub struct LimitFields<'a> {
    /// `geometry`.
    pub geometry: &'a GeometryDto,
    /// `formulation`.
    pub formulation: FormulationDto,
    /// `solver_tolerance`.
    pub solver_tolerance: f64,
    /// `compressive_strength`.
    pub compressive_strength: Option<f64>,
    /// `crushing_planes`.
    pub crushing_planes: Option<usize>,
    /// `friction`.
    pub friction: FrictionDto,
    /// `friction_relaxation`.
    pub friction_relaxation: FrictionRelaxationDto,
    /// `include`: the details to answer with; `None` is all of them.
    pub include: Option<&'a [ArchDetailDto]>,
    /// `ring_interface`.
    pub ring_interface: Option<&'a interfaces::RingInterfaceDto>,
    /// `interfaces`.
    pub interfaces: &'a [interfaces::InterfaceDto],
    /// The material.
    pub material: MaterialFields<'a>,
}

/// Declares an arch request: the route's own fields, then the material every arch route shares
/// (unit weight, interface limits, friction), documented once, with `material()` to borrow it.
macro_rules! arch_request {
    ($(#[$attr:meta])* pub struct $name:ident { $($(#[$field_attr:meta])* pub $field:ident: $ty:ty,)* }) => {
        $(#[$attr])*
        pub struct $name {
            $($(#[$field_attr])* pub $field: $ty,)*
            /// Unit weight γ (> 0): block weight = γ·area. Defaults to 1.
            #[serde(default = "unit", deserialize_with = "crate::nullable::unit_weight")]
            #[schema(nullable)]
            #[schema(examples(1.0))]
            pub unit_weight: f64,
            /// Limits on the interface resultants. Defaults to Heyman's (no tension, no
            /// crushing).
            #[serde(default, deserialize_with = "crate::nullable::or_default")]
            #[schema(nullable)]
            pub interface_limits: InterfaceLimitsDto,
            /// Coulomb friction coefficient μ ≥ 0 at every interface; null = no sliding.
            /// Defaults to null.
            #[serde(default)]
            pub friction_coefficient: Option<f64>,
            /// Multi-ring arches: friction coefficient μ ≥ 0 between the rings; null = no
            /// sliding between them. Defaults to null.
            #[serde(default)]
            pub ring_friction_coefficient: Option<f64>,
            /// Multi-ring arches: limits on the resultants between the rings (as
            /// `interface_limits`; `{"q_min": null, "s_min": null}` bonds the rings). Defaults
            /// to Heyman's.
            #[serde(default, deserialize_with = "crate::nullable::or_default")]
            #[schema(nullable)]
            pub ring_interface_limits: InterfaceLimitsDto,
        }

        impl $name {
            /// The material fields of the request.
            pub fn material(&self) -> MaterialFields<'_> {
                MaterialFields {
                    unit_weight: self.unit_weight,
                    interface_limits: &self.interface_limits,
                    friction_coefficient: self.friction_coefficient,
                    ring_interface_limits: &self.ring_interface_limits,
                    ring_friction_coefficient: self.ring_friction_coefficient,
                }
            }
        }
    };
}
pub(crate) use arch_request;

/// Declares a limit-analysis request (dead or live load): the structure and the solver controls,
/// then the route's own fields, then the material ([`arch_request!`]), with `limit_fields()`.
macro_rules! limit_request {
    ($(#[$attr:meta])* pub struct $name:ident { $($(#[$field_attr:meta])* pub $field:ident: $ty:ty,)* }) => {
        arch_request! {
            $(#[$attr])*
            pub struct $name {
                /// The structure.
                pub geometry: GeometryDto,
                /// Which model the programmes are written on: `chain` (three redundant forces,
                /// the default and fastest) or `assembly` (Livesley's general formulation, three
                /// unknowns per interface). Both give the same answer; the choice is for
                /// cross-checking.
                #[serde(default, deserialize_with = "crate::nullable::name_or_default")]
                #[schema(nullable)]
                pub formulation: FormulationDto,
                /// Interior-point tolerance (relative gap and feasibility), 1e-12 ≤ tol ≤ 1e-4.
                /// Defaults to 1e-10, which gives λ to about 1e-11 relative; 1e-6 is faster and
                /// still right to 1e-7 (see the accuracy tables of docs/accuracy.md).
                #[serde(default = "default_solver_tolerance", deserialize_with = "crate::nullable::solver_tolerance")]
                #[schema(nullable)]
                pub solver_tolerance: f64,
                /// Compressive strength σ_c of the masonry (force per unit area, per unit
                /// depth), 0 < σ_c ≤ 1e12: a joint of thickness t carries N ≤ σ_c·t and
                /// |M| ≤ N·(t − N/σ_c)/2 about its middle (the rectangular stress block).
                /// Solved to that exact curve by cutting planes. Defaults to none (no crushing).
                #[serde(default)]
                #[schema(examples(5000.0))]
                pub compressive_strength: Option<f64>,
                /// With `compressive_strength`: the tangent planes the first programme starts
                /// from, 2 ≤ planes ≤ 256 (more are added at each joint's own N until the exact
                /// curve is met, so the answer does not depend on them). Defaults to 4.
                #[serde(default)]
                pub crushing_planes: Option<usize>,
                /// With friction: `associative` (the linear programme's flow rule, the default)
                /// or `non_associative` (sliding without dilatancy, by iterated programmes).
                #[serde(default, deserialize_with = "crate::nullable::name_or_default")]
                #[schema(nullable)]
                pub friction: FrictionDto,
                /// With friction, when the non-associative iteration runs: `paper` (the
                /// default: Gilbert, Casapulla & Ahmed's relaxation, the Anderson mixing only
                /// where it stops without settling) or `anderson` (the mixing from the first
                /// step: the same fixed points in fewer programmes).
                #[serde(default, deserialize_with = "crate::nullable::name_or_default")]
                #[schema(nullable)]
                pub friction_relaxation: FrictionRelaxationDto,
                /// The details to answer with, of `thrust_line`, `mechanism`,
                /// `active_constraints`, `hinges`, `reactions` (a client that needs only λ
                /// need not take 10,000 thrust-line points). Those left out come back empty
                /// (`mechanism` null) and are listed in `omitted`; factors, statuses, margins
                /// and the other fields are always there. Defaults to all of them. Drawings
                /// ignore it.
                #[serde(default)]
                pub include: Option<Vec<ArchDetailDto>>,
                /// Multi-ring arches: the interfaces between the rings, their friction and
                /// the cohesion of their mortar (shear capacity μ·N + c·ℓ). Replaces
                /// `ring_friction_coefficient`. Defaults to none (no sliding between rings).
                #[serde(default)]
                #[schema(nullable)]
                pub ring_interface: Option<$crate::arch::request::interfaces::RingInterfaceDto>,
                /// Interfaces with friction and cohesion of their own (a wall's base, one
                /// joint), named by the blocks they join; 0 to 10000 of them. Defaults to
                /// none.
                #[serde(default)]
                pub interfaces: Option<Vec<$crate::arch::request::interfaces::InterfaceDto>>,
                $($(#[$field_attr])* pub $field: $ty,)*
            }
        }

        impl $name {
            /// The fields every limit-analysis request shares.
            pub fn limit_fields(&self) -> LimitFields<'_> {
                LimitFields {
                    geometry: &self.geometry,
                    formulation: self.formulation,
                    solver_tolerance: self.solver_tolerance,
                    compressive_strength: self.compressive_strength,
                    crushing_planes: self.crushing_planes,
                    friction: self.friction,
                    friction_relaxation: self.friction_relaxation,
                    include: self.include.as_deref(),
                    ring_interface: self.ring_interface.as_ref(),
                    interfaces: self.interfaces.as_deref().unwrap_or_default(),
                    material: self.material(),
                }
            }
        }
    };
}

limit_request! {
    /// Livesley's dead-load problem: does the structure carry its own weight?
    #[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
    #[serde(deny_unknown_fields)]
    #[schema(examples(json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0748, "voussoirs": 1800,
                     "left_base_angle_deg": 0.0, "right_base_angle_deg": 0.0, "voussoir": "curved"},
        "unit_weight": 1.0,
        "interface_limits": {"q_min": 0.0, "q_max": null, "s_min": 0.0, "s_max": null, "t_min": null, "t_max": null},
        "friction_coefficient": null
    })))]
    pub struct DeadLoadRequest {
        /// Fill over the arch up to a road: its weight joins the dead load. On circular arches
        /// (any rings and spans: the outer ring's extrados and the pier tops carry it) and
        /// block chains.
        #[serde(default)]
        pub fill: Option<super::fill::FillDto>,
    }
}

limit_request! {
    /// Livesley's live-load problem: the factor on the live loads at collapse.
    #[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
    #[serde(deny_unknown_fields)]
    #[schema(examples(json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
        "unit_weight": 1.0,
        "loads": [{"block": 26, "fx": 0.0, "fy": -1.0, "moment": 0.0}]
    })))]
    pub struct LiveLoadRequest {
        /// Live loads on blocks (up to 10000), multiplied together by the load factor; give
        /// these, `road_loads` or `rolling`.
        #[serde(default, deserialize_with = "crate::nullable::or_default")]
        #[schema(nullable)]
        pub loads: Vec<LoadDto>,
        /// Fill over the arch up to a road: its weight joins the dead load, and it spreads
        /// road loads. On circular arches (any rings and spans: the outer ring's extrados and
        /// the pier tops carry it) and block chains.
        #[serde(default)]
        pub fill: Option<super::fill::FillDto>,
        /// Live loads on the road (with `fill`), dispersed through the fill to the extrados.
        #[serde(default, deserialize_with = "crate::nullable::or_default")]
        #[schema(nullable)]
        pub road_loads: Vec<super::fill::RoadLoadDto>,
        /// A set of axles rolled across (on the road with `fill`, else on the extrados): the
        /// load factor at each stop in `rolling`, the answer at the critical stop.
        #[serde(default)]
        pub rolling: Option<super::rolling::RollingDto>,
        /// A partial-factor assessment: `{"factors": {"dead", "fill", "live", "strength"}}`.
        /// The analysis runs on the design values; the answer adds `design` with the adequacy
        /// factor (λ on the factored live load) and whether it is at least 1.
        #[serde(default)]
        pub design: Option<design::ArchDesignDto>,
        /// A probabilistic study of this analysis (model §9.2): numbers of this request as
        /// variables, the analysis run on each sample, the probability of failure (λ < 1).
        #[serde(default)]
        pub probabilistic: Option<crate::study::request::ProbabilisticDto>,
        /// A sensitivity study (model §9.3): λ at evenly spaced values of each variable.
        #[serde(default)]
        pub sensitivity: Option<crate::study::request::SensitivityDto>,
    }
}

/// The default unit weight.
pub(crate) fn unit() -> f64 {
    1.0
}

fn default_solver_tolerance() -> f64 {
    1e-10
}

/// How the answer names the formulation the solver used.
impl From<thrustline_solver::arch::Formulation> for FormulationDto {
    fn from(formulation: thrustline_solver::arch::Formulation) -> Self {
        match formulation {
            thrustline_solver::arch::Formulation::Chain => Self::Chain,
            thrustline_solver::arch::Formulation::Assembly => Self::Assembly,
        }
    }
}
