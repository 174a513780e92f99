//! The rules of the methods side by side (model §6.3): Spencer, Morgenstern–Price and Janbu
//! never depend on the moment centre (only Bishop's and the ordinary method take moments about
//! it), and the treatment of tension holds for the headline and every method answered.
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::budget::Budget;
use thrustline_solver::slope::analysis::{analyse, Analysed, Method, SlopeOutcome, SlopePlan};
use thrustline_solver::slope::analysis::{SlopeAnswer, Target};
use thrustline_solver::slope::section::{Polyline, Section};
use thrustline_solver::slope::section::{SectionProblem, SlipShape};
use thrustline_solver::slope::spencer::methods::{janbu, morgenstern_price, InterSliceFunction};
use thrustline_solver::slope::spencer::NegativeEffectiveStress;
use thrustline_solver::slope::*;

/// Fredlund & Krahn's (1977) section and a polyline through it (the API's `polyline_surface`
/// example: F = 2.4795).
fn polyline_problem(moment_centre: Option<(f64, f64)>) -> SectionProblem {
    let soil = Soil::new(120.0, 600.0, 20.0, 0.0).unwrap();
    let ground = vec![(0.0, 60.0), (60.0, 60.0), (140.0, 20.0), (180.0, 20.0)];
    let section = Section::of_one_soil(ground, soil).unwrap();
    let surface = vec![(40.0, 62.0), (70.0, 38.0), (130.0, 22.0), (165.0, 21.0)];
    SectionProblem::new(
        section,
        SlipShape::Polyline(Polyline::new(surface).unwrap()),
        NonZeroUsize::new(100).unwrap(),
        Seismic::default(),
        moment_centre,
    )
    .unwrap()
}

fn answer(problem: SectionProblem, treatment: NegativeEffectiveStress) -> SlopeAnswer {
    let plan = SlopePlan {
        methods: vec![
            Method::MorgensternPrice,
            Method::Bishop,
            Method::Janbu,
            Method::Ordinary,
        ],
        negative_effective_stress: treatment,
        ..SlopePlan::spencer(Target::Surface(Analysed::Section(Box::new(problem))))
    };
    match analyse(&plan, &Budget::unlimited()).unwrap() {
        SlopeOutcome::Answered(answer) => *answer,
        SlopeOutcome::Stopped { stage, stop } => panic!("{stage:?}: {stop}"),
    }
}

#[test]
fn spencer_morgenstern_price_and_janbu_do_not_depend_on_the_moment_centre() {
    let free = answer(polyline_problem(None), NegativeEffectiveStress::Keep);
    let f = free.solution.factor_of_safety.unwrap();
    assert!((f - 2.4795).abs() < 5e-5, "{f}");
    assert!(free.solution.bishop_factor_of_safety.is_none());
    let free_methods = free.methods.unwrap();
    // A centre at a vertex of the surface, one above it and one far away: the same roots, bit
    // for bit (the moment equation is never written about the given centre).
    for centre in [(70.0, 38.0), (110.0, 90.0), (-500.0, 900.0)] {
        let with = answer(
            polyline_problem(Some(centre)),
            NegativeEffectiveStress::Keep,
        );
        assert_eq!(with.solution.factor_of_safety, Some(f), "{centre:?}");
        assert_eq!(with.solution.theta_rad, free.solution.theta_rad);
        let methods = with.methods.unwrap();
        assert_eq!(methods.morgenstern_price, free_methods.morgenstern_price);
        assert_eq!(methods.janbu, free_methods.janbu);
        // Bishop's F is about the centre: the headline and the method agree.
        assert_eq!(
            methods.bishop.unwrap().factor.factor_of_safety,
            with.solution.bishop_factor_of_safety
        );
    }
    // Bishop's F does depend on it (two centres, two moment equations).
    let bishop = |c| {
        answer(polyline_problem(Some(c)), NegativeEffectiveStress::Keep)
            .solution
            .bishop_factor_of_safety
            .unwrap()
    };
    assert!((bishop((110.0, 90.0)) - bishop((-500.0, 900.0))).abs() > 1e-3);
}

#[test]
fn the_treatment_of_tension_holds_for_every_method() {
    // With the friction dropped where Spencer's answer puts a base in tension, each method
    // answers on those slices: here written out by hand (tan φ' = 0 on them) and solved alone.
    for treatment in [
        NegativeEffectiveStress::DropFriction,
        NegativeEffectiveStress::DropStrength,
    ] {
        let problem = polyline_problem(Some((110.0, 90.0)));
        let answered = answer(problem.clone(), treatment);
        let dropped = &answered.solution.tension_dropped_slices;
        assert!(!dropped.is_empty(), "the surface has bases in tension");
        let mut model = problem.model().clone();
        for &i in dropped {
            model.slices[i].tan_phi = 0.0;
            if treatment == NegativeEffectiveStress::DropStrength {
                model.slices[i].cohesion = 0.0;
            }
        }
        let methods = answered.methods.unwrap();
        assert_eq!(
            methods.bishop.unwrap().factor.factor_of_safety,
            answered.solution.bishop_factor_of_safety
        );
        assert_eq!(methods.janbu.unwrap().factor, janbu(&model));
        let spencer = (
            answered.solution.factor_of_safety.unwrap(),
            answered.solution.theta_rad.unwrap().tan(),
        );
        let mp = morgenstern_price(&model, &InterSliceFunction::HalfSine, spencer);
        assert_eq!(methods.morgenstern_price.unwrap().factor, mp);
        // And they differ from the classic equations' methods (the treatment took effect).
        let keep = answer(problem, NegativeEffectiveStress::Keep)
            .methods
            .unwrap();
        assert_ne!(keep.janbu.unwrap().factor, methods.janbu.unwrap().factor);
    }
}
