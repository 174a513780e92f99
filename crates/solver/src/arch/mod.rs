//! Limit analysis of structures formed from rigid blocks (Livesley 1978), with the circular
//! arch of the thesis' "Arch Stability" program as the main generator.
//!
//! Conventions, fixed here once for the whole module:
//! - Blocks are numbered 0..n in the crate (the service prints 1..n); interface k separates
//!   block k−1 and block k, interface 0 and interface n are the supports (springings).
//! - Each interface runs from its **intrados** point P_s to its **extrados** point P_q. Its
//!   stress resultants are Livesley's r = (q, s, t): q and s are compressive normal forces at
//!   P_q and P_s, t the shear along P_s→P_q. The unit normal ν points into the higher-numbered
//!   block; the resultant acts on that block as (q + s)·ν + t·τ and on the lower one oppositely.
//! - Equilibrium of block b is written for forces in x, y and the moment about its centroid,
//!   counter-clockwise positive: H r + λ_dead·w + λ·p = 0 with w, p the applied loads.
//!
//! - [`analysis`]: one analysis of a plan within a budget — what runs after what; [`plan`] its
//!   plan and outcome, `stage` the plan's programme.
//! - [`geometry`]: blocks, interfaces, the circular arch generator and block chains.
//! - [`equilibrium`]: the sparse equilibrium matrix H and the load vectors.
//! - [`limit`]: the linear programmes (dead load, live load) solved with Clarabel.
//! - [`mechanism`]: the collapse mechanism read from the multipliers.
//! - [`memory`]: the memory an analysis may take, bounded before it runs.
//! - [`minimum_thickness`]: the thinnest circular arch that carries its own weight.
//! - [`profile`]: arches by their intrados (segmental … catenary, measured points).
//! - [`rolling`]: the live-load factor at each stop of a rolling load.
//! - [`refine`]: a rolling load's critical position narrowed between the stops.
//! - [`thrust_line`]: the points of action of the interface resultants.

pub mod analysis;
pub mod chain;
pub mod contacts;
pub mod equilibrium;
mod error;
pub mod fill;
pub mod generators;
pub mod geometry;
pub mod limit;
pub mod mechanism;
pub mod memory;
pub mod minimum_thickness;
pub mod plan;
pub mod profile;
pub mod refine;
pub mod resultant;
pub mod rolling;
mod stage;
pub mod thrust_line;

pub use crate::outcome::SolverFailure;
pub use equilibrium::LiveLoad;
pub use error::{ArchError, ArchParameter};
pub use geometry::{Assembly, Block, CircularArch, Interface, InterfaceKind, VoussoirShape};
pub use limit::{is_squeezed, relieve_squeeze, show_least_normal_state, StateOf};
pub use limit::{
    non_associative, solve_dead_load, solve_dead_load_non_associative, solve_live_load,
    solve_live_load_after, solve_live_load_non_associative, ArchProblem, Crushing, Formulation,
    InterfaceLimits, LimitSettings, LimitSolution, LimitStatus, Relaxation, WarmLiveLoad, WarmStop,
};
pub use mechanism::{ActiveConstraint, Bound, Hinge, HingeSide, Mechanism, Resultant};
pub use minimum_thickness::{
    rupture_angle_deg, solve_minimum_thickness, solve_minimum_thickness_of, MinimumThickness,
    MinimumThicknessOutcome, MinimumThicknessSettings,
};
pub use rolling::{sweep_live_loads, Sweep};
pub use thrust_line::{support_reactions, thrust_line, SupportReaction, ThrustPoint};
