//! The arch answers, built whole from the solver's results: serde enums for every coded string,
//! blocks and interfaces numbered from 1, angles in degrees.

use serde::Serialize;
use thrustline_solver::arch::{support_reactions, ThrustPoint};
use utoipa::ToSchema;

use super::fill::{passive_out, PassiveOutDto};
use super::mechanism::{
    active_constraints, hinges, ActiveConstraintDto, HingeDto, MechanismDto, NonAssociativeOutDto,
};
use super::request::{ArchDetailDto, FormulationDto};
use super::rolling::RollingOutDto;
use super::solved::{ArchStatusDto, SolvedArch};
use crate::warning::{one_based, Warning};

/// The resultant at one interface.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct InterfaceThrustPointDto {
    /// Interface number (1-based).
    pub interface: usize,
    /// x of the point of action of the normal force; null where it vanishes (at or below 1e-6
    /// of the largest normal force).
    #[schema(required = true)]
    pub x: Option<f64>,
    /// y of the point of action; null where it vanishes.
    #[schema(required = true)]
    pub y: Option<f64>,
    /// Normal force q + s (compression positive).
    pub normal_force: f64,
    /// Shear force t.
    pub shear_force: f64,
    /// Distance of the point of action from the middle of the joint, towards the extrados.
    #[schema(required = true)]
    pub eccentricity: Option<f64>,
    /// The eccentricity as a fraction of the joint's length, e/t in [−½, ½] (null where the
    /// normal force vanishes).
    #[schema(required = true)]
    pub eccentricity_ratio: Option<f64>,
    /// Whether the point of action lies in the middle third of the joint, |e/t| ≤ 1/6 (the
    /// whole joint in compression under a linear stress distribution).
    #[schema(required = true)]
    pub in_middle_third: Option<bool>,
}

/// The force a support exerts on the structure.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ReactionDto {
    /// The support's interface number (1-based): the first and the last interface.
    pub interface: usize,
    /// Horizontal component (+x).
    pub horizontal: f64,
    /// Vertical component (up positive).
    pub vertical: f64,
}

/// How the solve ended.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SolverDto {
    /// solved; unbounded (no finite live load causes collapse); dead_load_not_carried;
    /// reduced_accuracy, max_iterations, numerical_error, infeasible (the interior-point method
    /// stopped without an answer it can vouch for: no factor reported).
    pub status: ArchStatusDto,
    /// Iterations over all linear programmes: interior-point iterations, and simplex pivots
    /// on a chain.
    pub iterations: u32,
    /// Linear programmes solved.
    pub programmes: usize,
    /// Wall time of the whole solve in milliseconds: every programme, cutting-plane round,
    /// friction step and rolling stop.
    pub time_ms: f64,
    /// The formulation used: chain or assembly.
    pub formulation: FormulationDto,
    /// The interior-point tolerance used.
    pub tolerance: f64,
}

/// Everything common to the dead- and live-load answers.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ArchOutcomeDto {
    /// Whether the structure carries its own weight (λ₀ = 1); null if that could not be decided.
    #[schema(required = true)]
    pub stable: Option<bool>,
    /// Dead-load margin at full dead load, as a fraction of the total weight: negative is a
    /// reserve (every limit met with that much to spare), positive a shortfall.
    #[schema(required = true)]
    pub dead_load_margin: Option<f64>,
    /// The limits active in the collapse mechanism (empty when nothing collapses).
    pub active_constraints: Vec<ActiveConstraintDto>,
    /// The hinges of the mechanism.
    pub hinges: Vec<HingeDto>,
    /// Interfaces that slide in the mechanism.
    pub sliding_interfaces: Vec<usize>,
    /// Interfaces that crush in the mechanism.
    pub crushing_interfaces: Vec<usize>,
    /// The collapse mechanism; null when nothing collapses.
    #[schema(required = true)]
    pub mechanism: Option<MechanismDto>,
    /// True only when the associative answer is shown to over-estimate: its mechanism slides,
    /// and friction without dilatancy (the non-associative iteration, run for the check)
    /// carries less, or does not settle (Livesley §2.7–2.9). See `non_associative`.
    pub friction_may_overestimate: bool,
    /// With friction, when the iteration ran (`friction: non_associative`, or an associative
    /// mechanism that slides): its steps, whether it settled, the corrected mechanism.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub non_associative: Option<NonAssociativeOutDto>,
    /// The line of thrust of the admissible state at the load factor (empty when there is none).
    /// On the general formulation (assemblies, rings, passive restraint), where the
    /// interior-point state carries a self-stress (a contact above 10 times all the loads), the
    /// state of least normal force among those the answer admits (docs/arches.md, Assemblies).
    pub thrust_line: Vec<InterfaceThrustPointDto>,
    /// The smallest distance from the line of thrust to the nearer face of its joint, as a
    /// fraction of the joint's length (½ − |e/t|, minimised over the joints): 0 where it
    /// touches a face (a hinge), ½ when it runs through every joint's middle; null without a
    /// line of thrust.
    #[schema(required = true)]
    pub thrust_margin: Option<f64>,
    /// The reactions of the supports in the state of `thrust_line`, one per support contact
    /// (empty when there is none).
    pub reactions: Vec<ReactionDto>,
    /// How the solve ended.
    pub solver: SolverDto,
    /// What to look at before trusting the answer: `rings_locked` (rings that cannot slip on
    /// each other lock their staggered joints: unbounded, or far above one ring of the whole
    /// thickness), `friction_may_overestimate` (with the sliding interfaces), `not_settled`.
    pub warnings: Vec<Warning>,
    /// The details `include` left out (returned empty, `mechanism` null); empty by default.
    pub omitted: Vec<ArchDetailDto>,
}

/// Answer to the dead-load problem.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct DeadLoadResponse {
    /// λ₀ ≤ 1, the largest fraction of the dead load that can be carried; null if the solver
    /// failed.
    #[schema(examples(1.0))]
    #[schema(required = true)]
    pub dead_load_factor: Option<f64>,
    /// With `fill`: its weight (the columns between the extrados and the road).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fill_weight: Option<f64>,
    /// With `fill.passive`: each passive force's capacity and the force mobilised.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub passive: Option<Vec<PassiveOutDto>>,
    /// Details.
    #[serde(flatten)]
    pub outcome: ArchOutcomeDto,
}

/// Answer to the live-load problem.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct LiveLoadResponse {
    /// λ, the factor on the live loads at collapse; null when the dead load is not carried, no
    /// finite factor causes collapse, or the solver failed.
    #[schema(required = true)]
    pub load_factor: Option<f64>,
    /// With `fill`: its weight (the columns between the extrados and the road).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fill_weight: Option<f64>,
    /// With `fill.passive`: each passive force's capacity and the force mobilised.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub passive: Option<Vec<PassiveOutDto>>,
    /// With `rolling`: λ at each stop; the rest of the answer is the critical stop's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rolling: Option<RollingOutDto>,
    /// With `design`: the factors applied, the adequacy factor (λ on the design values) and
    /// whether it is at least 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub design: Option<super::design::ArchDesignOutDto>,
    /// With `probabilistic`: the study's probability of failure (λ < 1), statistics and
    /// histogram.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub probabilistic: Option<crate::study::response::ProbabilisticOutDto>,
    /// With `sensitivity`: λ at each value of each variable.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sensitivity: Option<crate::study::response::SensitivityOutDto>,
    /// Details.
    #[serde(flatten)]
    pub outcome: ArchOutcomeDto,
}

impl DeadLoadResponse {
    /// The answer to a solved dead-load request.
    pub fn new(solved: &SolvedArch) -> Self {
        Self {
            dead_load_factor: solved.solution.load_factor,
            fill_weight: solved.input.fill_weight,
            passive: passive(solved),
            outcome: ArchOutcomeDto::new(solved),
        }
    }
}

impl LiveLoadResponse {
    /// The answer to a solved live-load request.
    pub fn new(solved: &SolvedArch) -> Self {
        Self {
            load_factor: solved.solution.load_factor,
            fill_weight: solved.input.fill_weight,
            passive: passive(solved),
            rolling: solved.rolling.clone(),
            design: solved
                .input
                .design
                .map(|f| super::design::verdict(f, solved.solution.load_factor)),
            probabilistic: solved
                .studies
                .probabilistic
                .as_ref()
                .map(|(p, _)| p.clone()),
            sensitivity: solved.studies.sensitivity.clone(),
            outcome: ArchOutcomeDto::new(solved),
        }
    }
}

/// The passive forces of a solved request with `fill.passive`.
fn passive(solved: &SolvedArch) -> Option<Vec<PassiveOutDto>> {
    let forces = solved.input.problem.passive();
    solved
        .input
        .has_passive
        .then(|| passive_out(forces, &solved.solution.passive))
}

impl ArchOutcomeDto {
    fn new(solved: &SolvedArch) -> Self {
        let solution = &solved.solution;
        let included = |detail| solved.input.include.contains(&detail);
        let omitted: Vec<ArchDetailDto> = ArchDetailDto::ALL
            .into_iter()
            .filter(|&d| !included(d))
            .collect();
        let mechanism = solution.mechanism.as_ref();
        let detail = |d| mechanism.filter(|_| included(d));
        let thrust_line: &[_] = if included(ArchDetailDto::ThrustLine) {
            &solved.thrust_line
        } else {
            &[]
        };
        let warnings = super::warnings::warnings(solved);
        Self {
            warnings,
            stable: solution.dead_load_carried,
            dead_load_margin: solution.dead_load_margin,
            active_constraints: detail(ArchDetailDto::ActiveConstraints)
                .map(active_constraints)
                .unwrap_or_default(),
            hinges: detail(ArchDetailDto::Hinges)
                .map(|m| hinges(solved.input.problem.assembly(), m))
                .unwrap_or_default(),
            sliding_interfaces: mechanism.map(|m| one_based(&m.sliding)).unwrap_or_default(),
            crushing_interfaces: mechanism
                .map(|m| one_based(&m.crushing))
                .unwrap_or_default(),
            mechanism: detail(ArchDetailDto::Mechanism).map(MechanismDto::new),
            friction_may_overestimate: !solved.is_non_associative
                && solved
                    .friction
                    .as_ref()
                    .is_some_and(|f| f.associative_may_overestimate()),
            non_associative: solved.friction.as_ref().and_then(|f| {
                (solved.is_non_associative || f.history.len() > 1)
                    .then(|| NonAssociativeOutDto::new(f, included(ArchDetailDto::Mechanism)))
            }),
            thrust_line: thrust_points(thrust_line),
            thrust_margin: solved
                .thrust_line
                .iter()
                .filter_map(|t| t.eccentricity_ratio)
                .map(|r| 0.5 - r.abs())
                .reduce(f64::min),
            reactions: reactions(solved, included(ArchDetailDto::Reactions)),
            solver: SolverDto {
                status: solved.status,
                iterations: solution.iterations,
                programmes: solution.programmes,
                time_ms: solution.solve_time_secs * 1e3,
                formulation: solved.settings.formulation.into(),
                tolerance: solved.settings.tolerance,
            },
            omitted,
        }
    }
}

/// The answer's points of action, interfaces numbered from 1.
fn thrust_points(thrust_line: &[ThrustPoint]) -> Vec<InterfaceThrustPointDto> {
    thrust_line
        .iter()
        .map(|t| InterfaceThrustPointDto {
            interface: t.interface + 1,
            x: t.point.map(|p| p.0),
            y: t.point.map(|p| p.1),
            normal_force: t.normal_force,
            shear_force: t.shear_force,
            eccentricity: t.eccentricity,
            eccentricity_ratio: t.eccentricity_ratio,
            in_middle_third: t.is_in_middle_third(),
        })
        .collect()
}

/// The supports' reactions, when `included` and the assembly has them (else none).
fn reactions(solved: &SolvedArch, included: bool) -> Vec<ReactionDto> {
    let solution = &solved.solution;
    support_reactions(solved.input.problem.assembly(), &solution.resultants)
        .filter(|_| included)
        .map(|pair| {
            pair.iter()
                .map(|r| ReactionDto {
                    interface: r.interface + 1,
                    horizontal: r.horizontal,
                    vertical: r.vertical,
                })
                .collect()
        })
        .unwrap_or_default()
}

/// A line of `/arch/live-load/stream`: progress, then the answer or its problem.
#[derive(Debug, Serialize, ToSchema)]
#[serde(untagged)]
pub enum LiveLoadStreamLine {
    /// How far the studies have come.
    Progress(crate::study::stream::ProgressLine),
    /// The answer, the last line.
    Answer(Box<LiveLoadResponse>),
    /// The problem of a study stopped after the stream began, the last line.
    Problem(crate::error::Problem),
}
