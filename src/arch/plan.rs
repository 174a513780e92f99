//! The plan of a validated dead- or live-load request: which programme (a rolling load's stops),
//! how friction is treated, the settings, the critical position's refinement and the bonded
//! ring to compare with — every option resolved once, for the solver's `analyse`.

use thrustline_solver::arch::analysis::{ArchPlan, Friction, Programme, RefineCritical};
use thrustline_solver::arch::{ArchProblem, LimitSettings};

use super::request::FrictionDto;
use super::rolling::Rolling;

/// Which of Livesley's two programmes a route asks for.
#[derive(Debug, Clone, Copy)]
pub enum Problem {
    /// `dead-load`: λ₀.
    DeadLoad,
    /// `live-load`: λ.
    LiveLoad,
}

/// The plan of a request of route `which`, and a rolling load's stops for the answer (their
/// loads go to the plan).
pub fn plan(
    which: Problem,
    friction: FrictionDto,
    settings: LimitSettings,
    rolling: Option<Rolling>,
    bonded: Option<ArchProblem>,
) -> (ArchPlan, Option<Vec<f64>>) {
    let friction = match friction {
        FrictionDto::NonAssociative => Friction::NonAssociative,
        FrictionDto::Associative => Friction::Checked,
    };
    let (programme, refine, rolling_positions) = match (which, rolling) {
        (Problem::DeadLoad, _) => (Programme::DeadLoad, None, None),
        (Problem::LiveLoad, None) => (Programme::LiveLoad, None, None),
        (Problem::LiveLoad, Some(rolling)) => {
            let refine = rolling
                .refine
                .filter(|_| rolling.positions.len() > 1)
                .map(|axles| RefineCritical {
                    positions: rolling.positions.clone(),
                    axles,
                });
            let stops = Programme::Rolling(rolling.loads);
            (stops, refine, Some(rolling.positions))
        }
    };
    let plan = ArchPlan {
        programme,
        friction,
        settings,
        refine,
        bonded,
    };
    (plan, rolling_positions)
}
