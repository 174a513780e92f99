//! One slope analysis: a [`SlopePlan`] (every option resolved into what will run) analysed
//! within a [`Budget`] into a [`SlopeOutcome`].
//!
//! What runs after what is written here once: the search for the critical circle (the simple
//! slope's or a section's), the non-circular stage that starts from the best circle, the
//! refinement of the slices, Spencer's curves and the methods side by side on the answered
//! slices. Studies, design checks and batches call [`analyse`] as the service does.

pub mod methods;
pub mod report;
mod search;
mod search_plan;
pub mod surface;

use std::num::NonZeroUsize;

use crate::budget::{Budget, Stop};
use crate::slope::accuracy::{estimate, to_accuracy, Accuracy, Recut};
use crate::slope::refinement::{refine_slices, RefinementSettings, RefinementStatus};
use crate::slope::search::{SearchGrid, SearchProblem};
use crate::slope::slices::{SliceModel, Sliced};
use crate::slope::spencer::methods::{method_factor, InterSliceFunction};
use crate::slope::spencer::{
    factor_curves_around, solve_spencer, with_strength_dropped, NegativeEffectiveStress,
    SpencerSettings, SpencerSolution,
};
use crate::slope::SlopeError;
pub use methods::{Method, MethodAnswer, MethodFactors};
pub use report::{
    MethodCritical, OwnCritical, Refinement, SearchReport, SlopeAnswer, SlopeOutcome, SlopeStage,
};
pub use search_plan::{Candidates, Noncircular, SectionSearch};
pub use surface::{Analysed, PlacedCircle};

/// What an analysis answers: one given surface, or the critical one of a search.
#[derive(Debug, Clone)]
pub enum Target {
    /// One slip surface.
    Surface(Analysed),
    /// The critical circle of the simple slope over a grid of centres (relative to the lower
    /// end); `hard_bounds`: the grid was given and stays put.
    SimpleSearch {
        /// Everything but the circle.
        problem: SearchProblem,
        /// The centres.
        grid: SearchGrid,
        /// Whether the bounds were given.
        hard_bounds: bool,
    },
    /// The critical circle of a section, then perhaps a non-circular surface.
    SectionSearch(Box<SectionSearch>),
}

/// The slices an accuracy asked for starts doubling from.
const ACCURACY_START_SLICES: usize = 25;

/// Every option of a slope analysis, resolved.
#[derive(Debug, Clone)]
pub struct SlopePlan {
    /// The surface, or the search.
    pub target: Target,
    /// With a tolerance: the slices are doubled from the target's until F settles within it.
    pub slice_tolerance: Option<f64>,
    /// With an accuracy: the answered surface is re-cut at the fewest slices (from 25,
    /// doubling) whose estimated discretisation error is at most this fraction of F.
    pub relative_error: Option<f64>,
    /// Whether to estimate the answer's discretisation error (re-cutting it at other slice
    /// counts); a study's samples skip it.
    pub estimate_accuracy: bool,
    /// The most slices a refinement may reach.
    pub max_slices: usize,
    /// Whether to compute Spencer's curves F_f(θ), F_m(θ) around the answer.
    pub curves: bool,
    /// The other methods to answer beside Spencer's.
    pub methods: Vec<Method>,
    /// With a search: whether each of `methods` is searched for its own critical circle too.
    pub per_method: bool,
    /// Morgenstern–Price's inter-slice function.
    pub interslice_function: InterSliceFunction,
    /// The treatment of tension at slice bases, in every method and every search.
    pub negative_effective_stress: NegativeEffectiveStress,
    /// What a search may answer.
    pub candidates: Candidates,
    /// A design check: the target is already in its design values; the answer gets the
    /// verdict.
    pub design: Option<crate::slope::design::Design>,
}

impl SlopePlan {
    /// A plan that answers `target` with Spencer's method alone.
    pub fn spencer(target: Target) -> Self {
        Self {
            target,
            slice_tolerance: None,
            relative_error: None,
            estimate_accuracy: true,
            max_slices: 10_000,
            curves: false,
            methods: Vec::new(),
            per_method: false,
            interslice_function: InterSliceFunction::HalfSine,
            negative_effective_stress: NegativeEffectiveStress::Keep,
            candidates: Candidates::default(),
            design: None,
        }
    }
}

/// Analyses `plan` within `budget`: the search (if any), the answered surface's solution
/// (refined if planned), then the curves and methods planned. `Err` only for input the solver
/// cannot accept; a stage stopped by the budget, or a search without a candidate, is an outcome.
pub fn analyse(plan: &SlopePlan, budget: &Budget) -> Result<SlopeOutcome, SlopeError> {
    let spencer = SpencerSettings {
        negative_effective_stress: plan.negative_effective_stress,
        ..SpencerSettings::default()
    };
    let (problem, search) = match searched(plan, &spencer, budget)? {
        Ok(searched) => searched,
        Err(stop) => return Ok(stopped(SlopeStage::Search, stop)),
    };
    // Spencer's critical surface as found, a candidate of every method's own search.
    let searched_surface = plan.per_method.then(|| problem.clone());
    let Answered {
        problem,
        solution,
        refinement,
        accuracy,
        recut,
    } = match at_slices(problem, plan, &spencer, budget)? {
        Ok(answered) => answered,
        Err(stop) => return Ok(stopped(SlopeStage::Refinement, stop)),
    };
    let curves = match (solution.theta_rad, plan.curves) {
        (Some(theta), true) => Some(factor_curves_around(&problem.model(), theta)),
        _ => None,
    };
    let methods = (!plan.methods.is_empty())
        .then(|| other_methods(plan, &spencer, &problem, &solution, recut, budget));
    let critical = match plan.per_method {
        true => match own_criticals(plan, &spencer, &searched_surface, budget)? {
            Ok(critical) => critical,
            Err(stop) => return Ok(stopped(SlopeStage::Search, stop)),
        },
        false => Vec::new(),
    };
    let design = plan.design.map(|d| d.verdict(solution.factor_of_safety));
    Ok(SlopeOutcome::Answered(Box::new(SlopeAnswer {
        problem,
        design,
        solution,
        search,
        curves,
        methods,
        critical,
        refinement,
        accuracy,
    })))
}

/// Each planned method's own critical circle: the plan's circle search (bounds, radii, slices,
/// candidates) with the method's F ranking the circles, without a non-circular stage; nothing
/// for a plan without a search. Spencer's critical circle (`spencers`) is a candidate too: a
/// method's critical F is never above its F there (a search stops within its resolution, and
/// the methods' landscapes differ). `Err(stop)` when the budget ended one of the searches.
fn own_criticals(
    plan: &SlopePlan,
    spencer: &SpencerSettings,
    spencers: &Option<Analysed>,
    budget: &Budget,
) -> Result<Result<Vec<(Method, OwnCritical)>, Stop>, SlopeError> {
    let spencers = spencers.as_ref().filter(|s| s.circle().is_some());
    let circles = match &plan.target {
        Target::SectionSearch(section) => Some(SectionSearch {
            noncircular: None,
            ..(**section).clone()
        }),
        _ => None,
    };
    let mut out = Vec::with_capacity(plan.methods.len());
    for &method in &plan.methods {
        let ranked = Some((method, &plan.interslice_function));
        let found = match (&plan.target, &circles) {
            (
                Target::SimpleSearch {
                    problem,
                    grid,
                    hard_bounds,
                },
                _,
            ) => search::simple(
                problem,
                *grid,
                *hard_bounds,
                spencer,
                plan.candidates,
                ranked,
                budget,
            )?,
            (_, Some(circles)) => {
                search::section(circles, spencer, plan.candidates, ranked, budget)?
            }
            _ => return Ok(Ok(Vec::new())),
        };
        let (own, report) = match found {
            Ok((problem, report)) => (Some(problem), Some(report)),
            Err(Stop::NoCandidate) => (None, None),
            Err(stop) => return Ok(Err(stop)),
        };
        let factor = |p: &Analysed| method_factor(&p.model(), method, &plan.interslice_function);
        let best = [own, spencers.cloned()]
            .into_iter()
            .flatten()
            .filter_map(|p| factor(&p).map(|f| (f, p)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        let critical = best
            .zip(report)
            .map(|((factor_of_safety, problem), report)| MethodCritical {
                problem,
                factor_of_safety,
                report,
            });
        out.push((method, critical));
    }
    Ok(Ok(out))
}

/// The surface to answer: the plan's own, or the one its search found with the search's
/// report; `Err(stop)` when the search found none or the budget ended it.
fn searched(
    plan: &SlopePlan,
    spencer: &SpencerSettings,
    budget: &Budget,
) -> Result<Result<(Analysed, Option<SearchReport>), Stop>, SlopeError> {
    Ok(match &plan.target {
        Target::Surface(problem) => Ok((problem.clone(), None)),
        Target::SimpleSearch {
            problem,
            grid,
            hard_bounds,
        } => search::simple(
            problem,
            *grid,
            *hard_bounds,
            spencer,
            plan.candidates,
            None,
            budget,
        )?
        .map(|(problem, report)| (problem, Some(report))),
        Target::SectionSearch(section) => {
            search::section(section, spencer, plan.candidates, None, budget)?
                .map(|(problem, report)| (problem, Some(report)))
        }
    })
}
/// The plan's other methods on the answered slices (strength dropped where Spencer's
/// `solution` drops it), with their accuracy estimated on `recut` as Spencer's was.
fn other_methods(
    plan: &SlopePlan,
    spencer: &SpencerSettings,
    problem: &Analysed,
    solution: &SpencerSolution,
    recut: Option<Recut>,
    budget: &Budget,
) -> MethodFactors {
    let model = with_strength_dropped(
        &problem.model(),
        &solution.tension_dropped_slices,
        plan.negative_effective_stress,
    );
    let mut found =
        methods::side_by_side(&plan.methods, &plan.interslice_function, &model, solution);
    // At other slice counts, strength is dropped where Spencer's state there drops it.
    let dropping = !solution.tension_dropped_slices.is_empty();
    let prepare = |m: &SliceModel| match dropping {
        true => {
            let at = solve_spencer(m, spencer);
            with_strength_dropped(
                m,
                &at.tension_dropped_slices,
                plan.negative_effective_stress,
            )
        }
        false => m.clone(),
    };
    methods::with_accuracy(
        &mut found,
        problem,
        &plan.interslice_function,
        &prepare,
        recut,
        budget,
    );
    found
}

/// The answered surface at the slices the plan asks for, with its solution and accuracy.
struct Answered {
    problem: Analysed,
    solution: SpencerSolution,
    refinement: Option<Refinement>,
    accuracy: Accuracy,
    /// The surface re-cut for the accuracy estimate, for the methods' estimates to share.
    recut: Option<Recut>,
}

/// The surface at its own slices, refined to a slice tolerance, or re-cut to an accuracy;
/// `Err(stop)` when the budget ended a refinement.
fn at_slices(
    problem: Analysed,
    plan: &SlopePlan,
    spencer: &SpencerSettings,
    budget: &Budget,
) -> Result<Result<Answered, Stop>, SlopeError> {
    if let Some(target) = plan.relative_error {
        let start = NonZeroUsize::new(ACCURACY_START_SLICES).unwrap_or(NonZeroUsize::MIN);
        if let Some(answered) = to_accuracy(&problem, start, target, spencer, budget)? {
            return Ok(Ok(Answered {
                problem: answered.problem,
                solution: answered.solution,
                refinement: None,
                accuracy: answered.accuracy,
                recut: None,
            }));
        }
        if let Err(stop) = budget.check() {
            return Ok(Err(stop));
        }
    }
    let (problem, solution, refinement) = match plan.slice_tolerance {
        None => {
            let solution = solve_spencer(&problem.model(), spencer);
            (problem, solution, None)
        }
        Some(tolerance) => {
            let settings = RefinementSettings {
                max_slices: plan.max_slices,
                spencer: *spencer,
                ..RefinementSettings::new(tolerance)
            };
            let refined = match refine_slices(problem, &settings, budget)? {
                Ok(refined) => refined,
                Err(stop) => return Ok(Err(stop)),
            };
            let is_settled = match refined.status {
                RefinementStatus::Settled => true,
                RefinementStatus::SliceLimit => false,
            };
            let refinement = Refinement {
                tolerance,
                steps: refined.steps,
                is_settled,
            };
            (refined.problem, refined.solution, Some(refinement))
        }
    };
    let (accuracy, recut) = match solution.factor_of_safety {
        Some(f) if plan.estimate_accuracy => {
            let recut = Recut::of(&problem, budget);
            let spencer_at = |m: &SliceModel| solve_spencer(m, spencer).factor_of_safety;
            (estimate(&recut, f, &spencer_at), Some(recut))
        }
        _ => (
            Accuracy {
                slices: problem.slice_count(),
                discretisation_error: None,
            },
            None,
        ),
    };
    Ok(Ok(Answered {
        problem,
        solution,
        refinement,
        accuracy,
        recut,
    }))
}

fn stopped(stage: SlopeStage, stop: Stop) -> SlopeOutcome {
    SlopeOutcome::Stopped { stage, stop }
}
