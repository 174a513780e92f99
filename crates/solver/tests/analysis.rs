//! The composition of an analysis, tested where it lives: `slope::analysis::analyse` and
//! `arch::analysis::analyse` answer what their stages answer alone, run the stages a plan names
//! and no other, and say how they stopped when the budget ends them.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

use thrustline_solver::arch::analysis::{
    analyse as analyse_arch, ArchPlan, ArchStatus, Friction, Programme,
};
use thrustline_solver::arch::{
    solve_dead_load, solve_live_load, ArchProblem, InterfaceLimits, LimitSettings, LimitStatus,
    LiveLoad,
};
use thrustline_solver::budget::{Budget, Stop};
use thrustline_solver::reference::{milankovitch, semicircle, spencer_1967};
use thrustline_solver::slope::analysis::{
    analyse, Analysed, Method, SlopeOutcome, SlopePlan, SlopeStage, Target,
};
use thrustline_solver::slope::spencer::methods::bishop;
use thrustline_solver::slope::{
    solve_spencer, SearchGrid, SearchProblem, Seismic, SpencerSettings,
};

fn answered(outcome: SlopeOutcome) -> thrustline_solver::slope::analysis::SlopeAnswer {
    match outcome {
        SlopeOutcome::Answered(answer) => *answer,
        SlopeOutcome::Stopped { stage, stop } => panic!("{stage:?} stopped: {stop}"),
    }
}

fn spencer_search(grid: Option<SearchGrid>) -> Target {
    let problem = SearchProblem {
        embankment: spencer_1967::embankment(),
        slices: NonZeroUsize::new(30).unwrap(),
        soil: spencer_1967::soil(spencer_1967::UNIT_WEIGHT),
        seismic: Seismic::default(),
        lower_end_factor: 0.0,
        lower_end_factor_max: None,
    };
    let hard_bounds = grid.is_some();
    let grid = grid.unwrap_or_else(|| SearchGrid::automatic(&problem.embankment, 0.0));
    Target::SimpleSearch {
        problem,
        grid,
        hard_bounds,
    }
}

#[test]
fn one_circle_is_answered_as_spencers_method_answers_it() {
    // Spencer (1967) example at 100 slices: the analysis is the solve, bit for bit, and the
    // methods planned are the methods on the same slices.
    let problem = spencer_1967::section_problem(100);
    let alone = solve_spencer(problem.model(), &SpencerSettings::default());
    let mut plan = SlopePlan::spencer(Target::Surface(Analysed::Section(Box::new(
        problem.clone(),
    ))));
    plan.methods = vec![Method::Bishop];
    let answer = answered(analyse(&plan, &Budget::unlimited()).unwrap());
    assert_eq!(answer.solution, alone);
    let bishop_alone = bishop(problem.model());
    let found = answer.methods.unwrap().bishop.unwrap();
    assert_eq!(found.factor, bishop_alone);
    assert!(found.accuracy.is_some_and(|a| a.slices == 100));
    // Nothing else was planned, so nothing else ran.
    assert!(answer.search.is_none() && answer.curves.is_none() && answer.refinement.is_none());
    // Spencer (1967): F = 1.0695 converged; 100 slices lie within 5e-4 of it (the thesis'
    // table), θ = 22.43° within 0.05°.
    let f = answer.solution.factor_of_safety.unwrap();
    assert!((f - spencer_1967::FACTOR_OF_SAFETY).abs() < 5e-4, "F = {f}");
    let theta = answer.solution.theta_rad.unwrap().to_degrees();
    assert!(
        (theta - spencer_1967::THETA_DEG).abs() < 0.05,
        "θ = {theta}"
    );
}

#[test]
fn a_planned_refinement_reaches_the_converged_factor() {
    // Spencer (1967): F = 1.0695 as N → ∞; from 10 slices to 1e-6, within the published
    // rounding (5e-5).
    let mut plan = SlopePlan::spencer(Target::Surface(Analysed::Section(Box::new(
        spencer_1967::section_problem(10),
    ))));
    plan.slice_tolerance = Some(1e-6);
    let answer = answered(analyse(&plan, &Budget::unlimited()).unwrap());
    let refinement = answer.refinement.unwrap();
    assert!(refinement.is_settled);
    let f = answer.solution.factor_of_safety.unwrap();
    assert!((f - spencer_1967::FACTOR_OF_SAFETY).abs() < 5e-5, "F = {f}");
    assert_eq!(
        refinement.steps.last().unwrap().slices,
        answer.problem.slice_count_answered()
    );
}

/// The slice count of an answered surface, read through the public trait.
trait SliceCount {
    fn slice_count_answered(&self) -> usize;
}

impl SliceCount for Analysed {
    fn slice_count_answered(&self) -> usize {
        thrustline_solver::slope::Sliced::slice_count(self)
    }
}

#[test]
fn a_search_answers_a_circle_no_worse_than_the_published_one() {
    // The critical circle of Spencer's embankment is at most the example circle's F (the
    // example circle is one candidate; 1e-3: the search's own grid and 30 slices).
    let plan = SlopePlan::spencer(spencer_search(None));
    let answer = answered(analyse(&plan, &Budget::unlimited()).unwrap());
    let search = answer.search.unwrap();
    assert!(search.evaluations > 0);
    let f = answer.solution.factor_of_safety.unwrap();
    assert!(f <= spencer_1967::FACTOR_OF_SAFETY + 1e-3, "F = {f}");
}

#[test]
fn a_spent_or_cancelled_budget_stops_the_search_and_says_which() {
    let plan = SlopePlan::spencer(spencer_search(None));
    let spent = Budget::with_time_limit(Duration::ZERO);
    let outcome = analyse(&plan, &spent).unwrap();
    assert!(matches!(
        outcome,
        SlopeOutcome::Stopped {
            stage: SlopeStage::Search,
            stop: Stop::TimeLimit
        }
    ));
    let flag = Arc::new(AtomicBool::new(true));
    let cancelled = Budget::with_time_limit(Duration::from_secs(600)).cancelled_by(flag.clone());
    assert_eq!(analyse(&plan, &cancelled).unwrap().stop(), Stop::Cancelled);
    flag.store(false, Ordering::Relaxed);
    assert_eq!(analyse(&plan, &cancelled).unwrap().stop(), Stop::Finished);
}

#[test]
fn a_region_without_a_slip_circle_is_no_candidate() {
    // Centres far behind the crest and below it: every circle through the toe dives under the
    // embankment and exits nowhere on the ground, so no circle is a candidate.
    let grid = SearchGrid {
        x_min: 1000.0,
        x_max: 1010.0,
        y_min: 1.0,
        y_max: 2.0,
        nx: 3,
        ny: 3,
    };
    let plan = SlopePlan::spencer(spencer_search(Some(grid)));
    let outcome = analyse(&plan, &Budget::unlimited()).unwrap();
    assert_eq!(outcome.stop(), Stop::NoCandidate);
}

fn milankovitch_problem(thickness: f64, voussoirs: usize) -> ArchProblem {
    let arch = semicircle(voussoirs, milankovitch::RADIUS, thickness).assembly();
    ArchProblem::new(arch, 1.0, InterfaceLimits::heyman(), None, vec![]).unwrap()
}

fn plan(programme: Programme, friction: Friction) -> ArchPlan {
    ArchPlan::new(programme, friction, LimitSettings::default())
}

#[test]
fn milankovitch_semicircle_stands_at_1_0748_and_falls_at_1_0747() {
    // Milankovitch (1904): d/R = 0.10748 at N = 1800 curved voussoirs.
    let dead = plan(Programme::DeadLoad, Friction::Checked);
    for (thickness, factor) in [
        (milankovitch::THICKNESS_STANDS, 1.0),
        (milankovitch::THICKNESS_FALLS, 0.0),
    ] {
        let problem = milankovitch_problem(thickness, milankovitch::VOUSSOIRS);
        let outcome = analyse_arch(&problem, &dead, &Budget::unlimited()).unwrap();
        assert_eq!(outcome.stop, Stop::Finished);
        let lambda = outcome.solution.load_factor.unwrap();
        // 1e-6: the interior-point tolerance on a cone whose λ₀ is exactly 0 or 1.
        assert!(
            (lambda - factor).abs() < 1e-6,
            "D = {thickness}: λ₀ = {lambda}"
        );
        // The dead load alone answers the same λ₀.
        let alone = solve_dead_load(&problem, &LimitSettings::default());
        assert_eq!(outcome.solution.load_factor, alone.load_factor);
    }
}

fn unit_load(problem: &ArchProblem, block: usize) -> Vec<LiveLoad> {
    vec![LiveLoad {
        block,
        point: problem.assembly().blocks[block].centroid,
        fx: 0.0,
        fy: -1.0,
        moment: 0.0,
    }]
}

#[test]
fn a_rolling_load_answers_its_least_stop_as_that_stop_alone_answers() {
    // An independent sweep: each stop solved by itself; the analysis' critical stop is the
    // least of them (first of equal ones), its λ the same to 1e-9 relative (the interior-point
    // answers of one programme on the same data).
    let base = milankovitch_problem(1.5, 30);
    let blocks = [6, 8, 10, 13];
    let stops: Vec<Vec<LiveLoad>> = blocks.iter().map(|&b| unit_load(&base, b)).collect();
    let alone: Vec<f64> = stops
        .iter()
        .map(|loads| {
            let p = base.clone().with_live_loads(loads.clone()).unwrap();
            solve_live_load(&p, &LimitSettings::default())
                .unwrap()
                .load_factor
                .unwrap()
        })
        .collect();
    let (least_at, least) =
        alone.iter().enumerate().fold(
            (0, f64::INFINITY),
            |b, (i, &f)| if f < b.1 { (i, f) } else { b },
        );
    let rolling = plan(Programme::Rolling(stops.clone()), Friction::Checked);
    let outcome = analyse_arch(&base, &rolling, &Budget::unlimited()).unwrap();
    let curve = outcome.rolling.unwrap();
    let (at, lambda) = curve.critical.unwrap();
    assert_eq!(at, least_at);
    assert!(
        (lambda - least).abs() <= 1e-9 * least,
        "{lambda} vs {least}"
    );
    // The problem answered is the critical stop's: its live loads are that stop's.
    assert_eq!(outcome.problem.live_loads(), stops[least_at].as_slice());
    assert_eq!(outcome.status, ArchStatus::Limit(LimitStatus::Solved));
}

#[test]
fn the_bonded_comparison_is_the_bonded_problem_analysed_alone() {
    // A plan that names a bonded problem answers its own λ as without it, and beside it the λ
    // the bonded problem's live-load programme gives alone (the same programme on the same
    // data: equal to rounding, 1e-12 relative); a dead-load plan compares nothing.
    let base = milankovitch_problem(1.5, 30);
    let problem = base.clone().with_live_loads(unit_load(&base, 8)).unwrap();
    let thick = milankovitch_problem(2.0, 30);
    let bonded = thick.clone().with_live_loads(unit_load(&thick, 8)).unwrap();
    let alone = solve_live_load(&bonded, &LimitSettings::default())
        .unwrap()
        .load_factor
        .unwrap();
    let without = analyse_arch(
        &problem,
        &plan(Programme::LiveLoad, Friction::Checked),
        &Budget::unlimited(),
    )
    .unwrap();
    let with = ArchPlan {
        bonded: Some(bonded.clone()),
        ..plan(Programme::LiveLoad, Friction::Checked)
    };
    let outcome = analyse_arch(&problem, &with, &Budget::unlimited()).unwrap();
    assert_eq!(outcome.solution.load_factor, without.solution.load_factor);
    assert_eq!(without.bonded_load_factor, None);
    let compared = outcome.bonded_load_factor.unwrap();
    assert!(
        (compared - alone).abs() <= 1e-12 * alone,
        "{compared} vs {alone}"
    );
    let dead = ArchPlan {
        bonded: Some(bonded),
        ..plan(Programme::DeadLoad, Friction::Checked)
    };
    let outcome = analyse_arch(&problem, &dead, &Budget::unlimited()).unwrap();
    assert_eq!(outcome.bonded_load_factor, None);
}

/// Two leaves 0.5 × 2 under a 1 × 0.5 cap on a base, μ = 0.5, pushed sideways at the cap.
fn two_leaves_under_a_cap() -> ArchProblem {
    let wall = thrustline_solver::arch::Assembly::from_polygons(
        &[
            vec![(0.0, 0.0), (0.5, 0.0), (0.5, 2.0), (0.0, 2.0)],
            vec![(0.5, 0.0), (1.0, 0.0), (1.0, 2.0), (0.5, 2.0)],
            vec![(0.0, 2.0), (1.0, 2.0), (1.0, 2.5), (0.0, 2.5)],
        ],
        &[vec![(-2.0, -1.0), (3.0, -1.0), (3.0, 0.0), (-2.0, 0.0)]],
    )
    .unwrap();
    let load = LiveLoad {
        block: 2,
        point: (0.0, 2.5),
        fx: 1.0,
        fy: 0.0,
        moment: 0.0,
    };
    ArchProblem::new(wall, 1.0, InterfaceLimits::heyman(), Some(0.5), vec![load]).unwrap()
}

#[test]
fn non_associative_friction_answers_below_the_associative_factor() {
    // Two leaves under a cap (Gilbert, Casapulla & Ahmed 2006's kind of panel): the associative
    // programme over-estimates; the iteration's settled answer is lower, and `Checked` keeps
    // the associative factor while reporting the iteration.
    let problem = two_leaves_under_a_cap();
    let checked = analyse_arch(
        &problem,
        &plan(Programme::LiveLoad, Friction::Checked),
        &Budget::unlimited(),
    )
    .unwrap();
    let iterated = analyse_arch(
        &problem,
        &plan(Programme::LiveLoad, Friction::NonAssociative),
        &Budget::unlimited(),
    )
    .unwrap();
    let associative = solve_live_load(&problem, &LimitSettings::default()).unwrap();
    assert_eq!(checked.solution.load_factor, associative.load_factor);
    assert!(checked.friction.is_some());
    let (a, n) = (
        checked.solution.load_factor.unwrap(),
        iterated.solution.load_factor.unwrap(),
    );
    assert!(n < a - 1e-6, "non-associative {n} vs associative {a}");
    assert!(iterated.friction.unwrap().settled);
}

#[test]
fn a_spent_budget_stops_an_arch_at_the_time_limit() {
    let problem = milankovitch_problem(1.5, 100);
    let loads = (0..50).map(|b| unit_load(&problem, b)).collect();
    let rolling = plan(Programme::Rolling(loads), Friction::Checked);
    let spent = Budget::with_time_limit(Duration::ZERO);
    let outcome = analyse_arch(&problem, &rolling, &spent).unwrap();
    assert_eq!(outcome.stop, Stop::TimeLimit);
    assert!(outcome.rolling.unwrap().critical.is_none());
}

#[test]
fn a_spent_budget_stops_a_single_programme() {
    // One dead-load programme on Livesley's general formulation: the budget reaches into the
    // interior-point method (its time limit and its callback), not only between programmes.
    let problem = milankovitch_problem(milankovitch::THICKNESS_FALLS, 200);
    let mut dead = plan(Programme::DeadLoad, Friction::Associative);
    dead.settings.formulation = thrustline_solver::arch::Formulation::Assembly;
    let spent = Budget::with_time_limit(Duration::ZERO);
    let outcome = analyse_arch(&problem, &dead, &spent).unwrap();
    assert_eq!(outcome.stop, Stop::TimeLimit);
    assert_eq!(outcome.solution.load_factor, None);
}

#[test]
fn a_cancelled_budget_stops_a_running_programme() {
    // The flag raised from another thread while a long programme runs (N = 1800 on the general
    // formulation): the analysis answers `Cancelled`, not the programme's own answer.
    let problem = milankovitch_problem(milankovitch::THICKNESS_FALLS, milankovitch::VOUSSOIRS);
    let mut dead = plan(Programme::DeadLoad, Friction::Associative);
    dead.settings.formulation = thrustline_solver::arch::Formulation::Assembly;
    let flag = Arc::new(AtomicBool::new(false));
    let budget = Budget::with_time_limit(Duration::from_secs(600)).cancelled_by(flag.clone());
    let raise = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(5));
        flag.store(true, Ordering::Relaxed);
    });
    let outcome = analyse_arch(&problem, &dead, &budget).unwrap();
    raise.join().unwrap();
    assert_eq!(outcome.stop, Stop::Cancelled);
}

#[test]
fn the_answer_states_the_time_of_the_whole_analysis() {
    // Regression: the time was the last cutting-plane round's (5–30 times too small). A rolling
    // sweep of 12 stops: the time stated covers them all, so it lies between half the wall time
    // measured around the call and that wall time.
    let base = milankovitch_problem(1.5, 60);
    let stops: Vec<Vec<LiveLoad>> = (10..22).map(|b| unit_load(&base, b)).collect();
    let rolling = plan(Programme::Rolling(stops), Friction::Checked);
    let start = std::time::Instant::now();
    let outcome = analyse_arch(&base, &rolling, &Budget::unlimited()).unwrap();
    let around = start.elapsed().as_secs_f64();
    let stated = outcome.solution.solve_time_secs;
    assert!(
        stated <= around && stated >= 0.5 * around,
        "{stated} s of {around} s"
    );
}

#[test]
fn a_budget_spent_between_friction_steps_ends_the_iteration_unsettled() {
    // The two leaves under a cap take 28 steps to settle; the budget's flag raised during the
    // second step ends the iteration at the next one: not settled, no factor, and the stop
    // says the budget's reason (never the associative state answered as a fixed point).
    let problem = two_leaves_under_a_cap();
    let flag = Arc::new(AtomicBool::new(false));
    let settings = LimitSettings {
        formulation: thrustline_solver::arch::Formulation::Assembly,
        budget: Budget::unlimited().cancelled_by(flag.clone()),
        ..LimitSettings::default()
    };
    let steps = std::cell::Cell::new(0);
    let outcome = thrustline_solver::arch::non_associative::iterate(
        &problem,
        &settings,
        false,
        solve_live_load,
        |p, s, _| {
            steps.set(steps.get() + 1);
            if steps.get() == 2 {
                flag.store(true, Ordering::Relaxed);
            }
            solve_live_load(p, s)
        },
    )
    .unwrap();
    assert!(!outcome.settled);
    assert_eq!(steps.get(), 2, "no step after the budget was spent");
    assert_eq!(outcome.solution.load_factor, None);
    assert_eq!(outcome.solution.stop, Stop::Cancelled);
}
