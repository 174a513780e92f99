//! A solved arch request: the validated input, what the analysis found and its status as the
//! answer names it. The JSON answer, the tables, the drawing and the report are built from it.

use serde::Serialize;
use thrustline_solver::arch::analysis::{ArchOutcome, ArchStatus, Friction};
use thrustline_solver::arch::non_associative::NonAssociative;
use thrustline_solver::arch::{
    LimitSettings, LimitSolution, LimitStatus, SolverFailure, ThrustPoint,
};
use utoipa::ToSchema;

use super::input::ArchInput;
use super::rolling::RollingOutDto;

/// How an arch solve ended.
#[derive(Debug, Clone, Copy, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ArchStatusDto {
    /// The load factor was found.
    Solved,
    /// No finite live load causes collapse.
    Unbounded,
    /// The dead load is not carried, so there is no live-load factor.
    DeadLoadNotCarried,
    /// The interior-point method reached only reduced accuracy: no factor reported.
    ReducedAccuracy,
    /// The interior-point method reached its iteration limit: no factor reported.
    MaxIterations,
    /// The interior-point method failed numerically: no factor reported.
    NumericalError,
    /// The interior-point method reported the programme infeasible (which the formulations
    /// exclude): no factor reported.
    Infeasible,
    /// `friction: non_associative`: the iteration did not settle in its steps: no factor (λ at
    /// each step is in `non_associative.load_factors`).
    NotSettled,
}

impl From<ArchStatus> for ArchStatusDto {
    /// The status of a finished analysis (one the budget stopped is not answered: the service
    /// refuses it, 422 or 503).
    fn from(status: ArchStatus) -> Self {
        let status = match status {
            ArchStatus::NotSettled => return Self::NotSettled,
            ArchStatus::Limit(status) => status,
        };
        match status {
            LimitStatus::Solved => Self::Solved,
            LimitStatus::DeadLoadNotCarried => Self::DeadLoadNotCarried,
            LimitStatus::Unbounded => Self::Unbounded,
            LimitStatus::SolverFailed(failure) => match failure {
                SolverFailure::ReducedAccuracy => Self::ReducedAccuracy,
                SolverFailure::MaxIterations => Self::MaxIterations,
                SolverFailure::Numerical => Self::NumericalError,
                SolverFailure::Infeasible => Self::Infeasible,
            },
        }
    }
}

/// A solved arch request: its input, the solution, its status and the line of thrust.
pub struct SolvedArch {
    /// The validated request.
    pub input: ArchInput,
    /// What the solver found.
    pub solution: LimitSolution,
    /// Its status, the time limit excluded.
    pub status: ArchStatusDto,
    /// The points of action at the interfaces.
    pub thrust_line: Vec<ThrustPoint>,
    /// With `rolling`: λ at each stop.
    pub rolling: Option<RollingOutDto>,
    /// With friction: the non-associative iteration, when it ran.
    pub friction: Option<NonAssociative>,
    /// Where the rings lock: the bonded single ring's λ.
    pub bonded_load_factor: Option<f64>,
    /// What the request's studies answered (nothing without studies).
    pub studies: crate::study::StudyAnswers,
    /// Whether the plan answered by the non-associative iteration (`friction:
    /// non_associative`).
    pub is_non_associative: bool,
    /// The programmes' settings (the formulation and tolerance the answer names).
    pub settings: LimitSettings,
}

impl SolvedArch {
    /// The answer to `input` from the analysis' `outcome` with its `status`, under the plan's
    /// treatment of `friction` and `settings`; the problem shown is the one answered (a rolling
    /// load's critical stop).
    pub fn new(
        mut input: ArchInput,
        outcome: ArchOutcome,
        status: ArchStatusDto,
        friction: Friction,
        settings: LimitSettings,
    ) -> Self {
        let rolling = outcome
            .rolling
            .as_ref()
            .zip(input.rolling_positions.take())
            .map(|(curve, positions)| RollingOutDto::new(curve, positions));
        input.problem = outcome.problem;
        Self {
            input,
            solution: outcome.solution,
            status,
            thrust_line: outcome.thrust_line,
            rolling,
            friction: outcome.friction,
            bonded_load_factor: outcome.bonded_load_factor,
            studies: Default::default(),
            is_non_associative: friction == Friction::NonAssociative,
            settings,
        }
    }
}
