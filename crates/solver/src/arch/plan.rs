//! What an arch analysis is asked to do and what it answers: the plan (which programme, how
//! friction is treated, the stages after it) and the outcome. [`super::analysis::analyse`] runs
//! a plan.

use super::equilibrium::LiveLoad;
use super::limit::non_associative::NonAssociative;
use super::limit::{ArchProblem, LimitSettings, LimitSolution, LimitStatus};
use super::rolling::RollingAxles;
use super::thrust_line::ThrustPoint;
use crate::budget::Stop;

/// Which of Livesley's programmes, and over which loads.
#[derive(Debug, Clone, PartialEq)]
pub enum Programme {
    /// The largest factor on the dead load that can be carried (λ₀, stopping at 1).
    DeadLoad,
    /// The factor on the problem's live loads at collapse.
    LiveLoad,
    /// The live-load factor at every stop of a rolling load (the live loads of stop i; an
    /// empty list: nothing on the structure there); the critical stop is answered.
    Rolling(Vec<Vec<LiveLoad>>),
}

/// How Coulomb friction is treated (Livesley §2.7–2.9).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Friction {
    /// The associative programme alone (or no friction at all).
    Associative,
    /// The associative answer, checked by the non-associative iteration when its mechanism
    /// slides (whether the factor may be an over-estimate).
    Checked,
    /// The non-associative iteration's own answer.
    NonAssociative,
}

/// Every option of an arch analysis, resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct ArchPlan {
    /// The programme.
    pub programme: Programme,
    /// The treatment of friction.
    pub friction: Friction,
    /// The interior-point settings (the budget given to the analysis replaces theirs).
    pub settings: LimitSettings,
    /// With [`Programme::Rolling`]: the critical position narrowed between the stops
    /// (`refine_critical`). Defaults to none.
    pub refine: Option<RefineCritical>,
    /// Where the rings lock (staggered rings that cannot slip): the same scene on one ring of
    /// the whole thickness, whose λ (associative) the answer is compared with
    /// ([`ArchOutcome::bonded_load_factor`]; with [`Programme::LiveLoad`] only). Defaults to
    /// none.
    pub bonded: Option<ArchProblem>,
}

impl ArchPlan {
    /// The programme alone: no refinement, no comparison.
    pub fn new(programme: Programme, friction: Friction, settings: LimitSettings) -> Self {
        Self {
            programme,
            friction,
            settings,
            refine: None,
            bonded: None,
        }
    }
}

/// A rolling load's critical position narrowed between the stops: a golden-section search for
/// the least λ between the critical stop's neighbours, to [`Self::TOLERANCE`] of the stops'
/// spacing.
#[derive(Debug, Clone, PartialEq)]
pub struct RefineCritical {
    /// The stops' positions (of the axles' reference point), at least two.
    pub positions: Vec<f64>,
    /// The axles, for the live loads at a position between the stops.
    pub axles: RollingAxles,
}

impl RefineCritical {
    /// The search narrows the critical position to this fraction of the stops' spacing.
    pub const TOLERANCE: f64 = 1e-3;
}

/// λ at each stop of a rolling load, and its critical stop.
#[derive(Debug, Clone, PartialEq)]
pub struct RollingCurve {
    /// λ at each stop; `None` where nothing stands on the structure or no finite λ collapses it.
    pub load_factors: Vec<Option<f64>>,
    /// The critical stop (least λ, the first of equal ones) and its λ; `None` when no stop has
    /// a λ or the sweep did not finish.
    pub critical: Option<(usize, f64)>,
    /// Wall time per stop over the whole sweep, in milliseconds (0 when it did not finish).
    pub time_per_stop_ms: f64,
    /// Wall time of the first loaded stop (a cold start) in milliseconds.
    pub first_stop_ms: f64,
    /// The critical position narrowed between the stops, when asked for
    /// ([`ArchPlan::refine`]).
    pub refined: Option<RefinedCritical>,
}

/// A critical position narrowed between the stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RefinedCritical {
    /// The position of least λ found.
    pub position: f64,
    /// λ there.
    pub load_factor: f64,
    /// Half the final bracket: how far the least λ may lie from `position` (λ unimodal there).
    pub error: f64,
    /// Live-load analyses the search ran.
    pub evaluations: usize,
}

/// How an arch analysis' answer stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArchStatus {
    /// The programme's own status.
    Limit(LimitStatus),
    /// [`Friction::NonAssociative`]: the iteration did not settle; no factor is answered.
    NotSettled,
}

/// What an arch analysis found.
#[derive(Debug, Clone)]
pub struct ArchOutcome {
    /// The problem answered: the plan's, or a rolling load's critical stop's.
    pub problem: ArchProblem,
    /// Its solution (for [`Friction::NonAssociative`], the iteration's); its `solve_time_secs`
    /// is the wall time of the whole analysis.
    pub solution: LimitSolution,
    /// How the answer stands.
    pub status: ArchStatus,
    /// How the analysis ended: [`Stop::Finished`], or the budget's reason.
    pub stop: Stop,
    /// The points of action at the interfaces of the state answered.
    pub thrust_line: Vec<ThrustPoint>,
    /// With a rolling load: λ at each stop.
    pub rolling: Option<RollingCurve>,
    /// With friction: the non-associative iteration, when it ran.
    pub friction: Option<NonAssociative>,
    /// With [`ArchPlan::bonded`]: the bonded single ring's λ (associative), when it has one.
    pub bonded_load_factor: Option<f64>,
}
