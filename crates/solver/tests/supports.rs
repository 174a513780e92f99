//! Reinforcement (model §7) on a planar slip surface, against the sliding wedge's two force
//! equations written out here: with every base at one inclination β, Spencer's force equation
//! sums to  F·(W sin β − T_s) = c·L + (W cos β + T_n) tan φ  for an active support and
//! F·W sin β = c·L + (W cos β + T_n) tan φ + T_s  for a passive one, whatever θ is (T_s: the
//! support force's component up the plane, T_n: its component pressing the plane). The force
//! T of each kind of support, and its governing mode, from model §7's formulas with the lengths
//! measured here.
// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::num::NonZeroUsize;

use thrustline_solver::slope::section::supports::{
    Anchorage, Application, Mode, Orientation, PileOrientation, Support, SupportKind,
};
use thrustline_solver::slope::section::{
    Layer, Polyline, Section, SectionParts, SectionProblem, SlipShape,
};
use thrustline_solver::slope::*;

const GAMMA: f64 = 20.0;
const COHESION: f64 = 5.0;
const PHI_DEG: f64 = 30.0;
const BETA_DEG: f64 = 30.0;

/// The ground: level at 0 to x = 10, a 45° face to (20, 10), level at 10 beyond.
fn ground() -> Vec<(f64, f64)> {
    vec![(0.0, 0.0), (10.0, 0.0), (20.0, 10.0), (40.0, 10.0)]
}

/// The plane from the toe (10, 0) at β to the crest level.
fn plane() -> ((f64, f64), (f64, f64)) {
    let top = (10.0 + 10.0 / BETA_DEG.to_radians().tan(), 10.0);
    ((10.0, 0.0), top)
}

fn section(supports: Vec<Support>) -> Section {
    Section::new(SectionParts {
        supports,
        ..section_parts()
    })
    .unwrap()
}

/// Spencer's F and the supports' forces on the plane.
fn solve(supports: Vec<Support>) -> (f64, Vec<thrustline_solver::slope::section::SupportForce>) {
    let (a, b) = plane();
    let problem = SectionProblem::new(
        section(supports),
        SlipShape::Polyline(Polyline::new(vec![a, b]).unwrap()),
        NonZeroUsize::new(40).unwrap(),
        Seismic::default(),
        None,
    )
    .unwrap();
    let solution = solve_spencer(problem.model(), &SpencerSettings::default());
    assert_eq!(solution.status, SpencerStatus::Converged);
    (solution.factor_of_safety.unwrap(), problem.supports())
}

/// The wedge's weight (shoelace over (10, 0), (20, 10), the plane's top) and the plane's length.
fn wedge() -> (f64, f64) {
    let (a, b) = plane();
    let c = (20.0, 10.0);
    let area = 0.5 * ((c.0 - a.0) * (b.1 - a.1) - (b.0 - a.0) * (c.1 - a.1)).abs();
    (GAMMA * area, (b.0 - a.0).hypot(b.1 - a.1))
}

/// F of the wedge with a force `t` per unit width along the unit vector `d`.
fn expected(t: f64, d: (f64, f64), application: Application) -> f64 {
    let (w, l) = wedge();
    let (s, c) = BETA_DEG.to_radians().sin_cos();
    let up = (c, s); // up the plane
    let pressing = (s, -c); // into the plane
    let t_s = t * (d.0 * up.0 + d.1 * up.1);
    let t_n = t * (d.0 * pressing.0 + d.1 * pressing.1);
    let tan_phi = PHI_DEG.to_radians().tan();
    let friction = COHESION * l + (w * c + t_n) * tan_phi;
    match application {
        Application::Active => friction / (w * s - t_s),
        Application::Passive => (friction + t_s) / (w * s),
    }
}

/// Where the segment from `head` to `end` crosses the plane, and the lengths before and after.
fn crossing(head: (f64, f64), end: (f64, f64)) -> ((f64, f64), f64, f64) {
    let tan_beta = BETA_DEG.to_radians().tan();
    // Plane: y = (x − 10)·tan β; segment: head + u·(end − head).
    let d = (end.0 - head.0, end.1 - head.1);
    let u = ((head.0 - 10.0) * tan_beta - head.1) / (d.1 - d.0 * tan_beta);
    let p = (head.0 + u * d.0, head.1 + u * d.1);
    let length = d.0.hypot(d.1);
    (p, u * length, (1.0 - u) * length)
}

fn unit(d: (f64, f64)) -> (f64, f64) {
    let n = d.0.hypot(d.1);
    (d.0 / n, d.1 / n)
}

/// A nail from the face's middle, 15° below horizontal, 12 long.
const HEAD: (f64, f64) = (15.0, 5.0);
fn nail_end() -> (f64, f64) {
    let (s, c) = (-15f64).to_radians().sin_cos();
    (HEAD.0 + 12.0 * c, HEAD.1 + 12.0 * s)
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * b.abs()
}

#[test]
fn the_unreinforced_wedge_is_the_two_force_equations() {
    let (f, forces) = solve(Vec::new());
    assert!(forces.is_empty());
    assert!(
        close(f, expected(0.0, (1.0, 0.0), Application::Active)),
        "{f}"
    );
}

#[test]
fn a_soil_nail_holds_by_each_of_its_modes_active_and_passive() {
    let end = nail_end();
    let (p, inside, beyond) = crossing(HEAD, end);
    let spacing = 1.5;
    let bond = 20.0;
    // (tensile, plate) making each of the three limits the least.
    for (tensile, plate, mode, t) in [
        (150.0, 50.0, Mode::Stripping, 50.0 + bond * inside),
        (40.0, 500.0, Mode::Tensile, 40.0),
        (1e6, 1e6, Mode::Pullout, bond * beyond),
    ] {
        for application in [Application::Active, Application::Passive] {
            let nail = Support {
                head: HEAD,
                end,
                spacing,
                kind: SupportKind::SoilNail {
                    tensile_capacity: tensile,
                    plate_capacity: plate,
                    bond_strength: bond,
                },
                application,
            };
            let (f, forces) = solve(vec![nail]);
            let force = forces[0];
            let crossed = force.crossing.unwrap();
            assert!((crossed.0 - p.0).abs() < 1e-9 && (crossed.1 - p.1).abs() < 1e-9);
            assert_eq!(force.mode, Some(mode));
            assert!(
                close(force.force, t / spacing),
                "{} vs {}",
                force.force,
                t / spacing
            );
            let d = unit((end.0 - HEAD.0, end.1 - HEAD.1));
            let want = expected(t / spacing, d, application);
            assert!(close(f, want), "{mode:?} {application:?}: {f} vs {want}");
        }
    }
    // Passive never gives more than active (Slide's and Duncan & Wright's observation): here
    // T_s > 0 and F > 1, so (R + T_s)/D < R/(D − T_s).
    let nail = |application| Support {
        head: HEAD,
        end,
        spacing,
        kind: SupportKind::SoilNail {
            tensile_capacity: 150.0,
            plate_capacity: 50.0,
            bond_strength: bond,
        },
        application,
    };
    let (active, _) = solve(vec![nail(Application::Active)]);
    let (passive, _) = solve(vec![nail(Application::Passive)]);
    let (bare, _) = solve(Vec::new());
    assert!(
        bare < passive && passive < active,
        "{bare} {passive} {active}"
    );
}

#[test]
fn anchors_and_tiebacks_hold_by_their_formulas() {
    let end = nail_end();
    let (_, inside, beyond) = crossing(HEAD, end);
    let d = unit((end.0 - HEAD.0, end.1 - HEAD.1));
    // End-anchored: min(tensile, plate), the plate here.
    let anchor = Support {
        head: HEAD,
        end,
        spacing: 2.0,
        kind: SupportKind::EndAnchored {
            tensile_capacity: 200.0,
            plate_capacity: 120.0,
        },
        application: Application::Active,
    };
    let (f, forces) = solve(vec![anchor]);
    assert_eq!(forces[0].mode, Some(Mode::Plate));
    assert!(close(forces[0].force, 60.0));
    assert!(close(f, expected(60.0, d, Application::Active)));
    // A tieback bonded over its last 4 (all beyond the surface: `beyond` > 4): pull-out of
    // bond × 4; bonded over its last beyond + 2 (2 of it inside the mass): the plate with
    // bond × 2 strips before the bond beyond pulls out.
    assert!(beyond > 4.0 && inside > 2.0, "{inside} {beyond}");
    for (bond_length, plate, mode, t) in [
        (4.0, 1e6, Mode::Pullout, 30.0 * 4.0),
        (beyond + 2.0, 10.0, Mode::Stripping, 10.0 + 30.0 * 2.0),
        (4.0, 10.0, Mode::Plate, 10.0),
    ] {
        let tieback = Support {
            head: HEAD,
            end,
            spacing: 2.0,
            kind: SupportKind::GroutedTieback {
                tensile_capacity: 1e6,
                plate_capacity: plate,
                bond_strength: 30.0,
                bond_length,
            },
            application: Application::Passive,
        };
        let (f, forces) = solve(vec![tieback]);
        assert_eq!(forces[0].mode, Some(mode), "{bond_length}");
        assert!(
            close(forces[0].force, t / 2.0),
            "{} vs {}",
            forces[0].force,
            t / 2.0
        );
        assert!(close(f, expected(t / 2.0, d, Application::Passive)));
    }
}

#[test]
fn geosynthetics_and_piles_act_in_their_directions() {
    // A horizontal geogrid from the face at y = 4 into the slope, 14 long.
    let head = (14.0, 4.0);
    let end = (28.0, 4.0);
    let (_, inside, beyond) = crossing(head, end);
    let (s, c) = BETA_DEG.to_radians().sin_cos();
    let along = (1.0, 0.0);
    let up = (c, s);
    let bisector = unit((along.0 + up.0, along.1 + up.1));
    // (anchorage, orientation, direction, tensile strength, force, mode); bond 5 per unit
    // length.
    let cases = [
        (
            Anchorage::None,
            Orientation::Parallel,
            along,
            1e6,
            5.0 * inside.min(beyond),
            Mode::Stripping,
        ),
        (
            Anchorage::SlopeFace,
            Orientation::Tangent,
            up,
            1e6,
            5.0 * beyond,
            Mode::Pullout,
        ),
        (
            Anchorage::EmbeddedEnd,
            Orientation::Bisector,
            bisector,
            1e6,
            5.0 * inside,
            Mode::Stripping,
        ),
        (
            Anchorage::BothEnds,
            Orientation::Parallel,
            along,
            40.0,
            40.0,
            Mode::Tensile,
        ),
        (
            Anchorage::None,
            Orientation::Tangent,
            up,
            10.0,
            10.0,
            Mode::Tensile,
        ),
    ];
    assert!(inside < beyond, "{inside} {beyond}");
    for (anchorage, orientation, d, tensile, t, mode) in cases {
        let grid = Support {
            head,
            end,
            spacing: 1.0,
            kind: SupportKind::Geosynthetic {
                tensile_strength: tensile,
                bond_strength: 5.0,
                anchorage,
                orientation,
            },
            application: Application::Passive,
        };
        let (f, forces) = solve(vec![grid]);
        assert_eq!(forces[0].mode, Some(mode), "{anchorage:?}");
        assert!(
            close(forces[0].force, t),
            "{anchorage:?}: {} vs {t}",
            forces[0].force
        );
        let got = forces[0].direction;
        assert!(
            (got.0 - d.0).abs() < 1e-12 && (got.1 - d.1).abs() < 1e-12,
            "{got:?} {d:?}"
        );
        assert!(
            close(f, expected(t, d, Application::Passive)),
            "{anchorage:?}"
        );
    }
    // A vertical pile through the wedge: its shear along the plane, or across the pile
    // (horizontal, against the sliding).
    for (orientation, d) in [
        (PileOrientation::ParallelToSurface, up),
        (PileOrientation::PerpendicularToPile, (1.0, 0.0)),
    ] {
        let pile = Support {
            head: (22.0, 10.0),
            end: (22.0, -5.0),
            spacing: 2.5,
            kind: SupportKind::Pile {
                shear_strength: 100.0,
                orientation,
            },
            application: Application::Active,
        };
        let (f, forces) = solve(vec![pile]);
        assert_eq!(forces[0].mode, Some(Mode::Shear));
        assert!(close(forces[0].force, 40.0));
        assert!(
            close(f, expected(40.0, d, Application::Active)),
            "{orientation:?}"
        );
    }
}

#[test]
fn a_support_the_surface_misses_carries_nothing_and_bad_supports_are_refused() {
    // A short nail that ends before the plane.
    let short = Support {
        head: HEAD,
        end: (16.0, 4.9),
        spacing: 1.0,
        kind: SupportKind::SoilNail {
            tensile_capacity: 100.0,
            plate_capacity: 100.0,
            bond_strength: 10.0,
        },
        application: Application::Active,
    };
    let (f, forces) = solve(vec![short]);
    assert_eq!(forces[0].crossing, None);
    assert_eq!(forces[0].force, 0.0);
    assert!(close(f, expected(0.0, (1.0, 0.0), Application::Active)));
    let refused = |s: Support| {
        Section::new(SectionParts {
            supports: vec![s],
            ..section_parts()
        })
        .unwrap_err()
        .to_string()
    };
    let nail = short;
    assert!(refused(Support {
        spacing: 0.0,
        ..nail
    })
    .contains("spacing"));
    assert!(refused(Support { end: HEAD, ..nail }).contains("end of support 1"));
    assert!(refused(Support {
        head: (50.0, 10.0),
        ..nail
    })
    .contains("outside the section"));
    assert!(refused(Support {
        head: (15.0, 9.0),
        ..nail
    })
    .contains("above the ground"));
    let negative = SupportKind::SoilNail {
        tensile_capacity: -1.0,
        plate_capacity: 1.0,
        bond_strength: 1.0,
    };
    assert!(refused(Support {
        kind: negative,
        ..nail
    })
    .contains("tensile_capacity"));
    let too_long = SupportKind::GroutedTieback {
        tensile_capacity: 1.0,
        plate_capacity: 1.0,
        bond_strength: 1.0,
        bond_length: 2.0,
    };
    assert!(refused(Support {
        kind: too_long,
        ..nail
    })
    .contains("bond_length"));
}

fn section_parts() -> SectionParts {
    SectionParts {
        ground: Polyline::new(ground()).unwrap(),
        layers: vec![Layer {
            top: None,
            soil: Soil::new(GAMMA, COHESION, PHI_DEG, 0.0).unwrap(),
            pore_pressure_ratio: None,
            strength: thrustline_solver::slope::strength::Strength::MohrCoulomb,
            piezometric_line: None,
        }],
        bedrock: None,
        piezometric_line: None,
        water_unit_weight: 9.81,
        surcharges: Vec::new(),
        line_loads: Vec::new(),
        tension_crack: None,
        supports: Vec::new(),
        water: Default::default(),
    }
}

#[test]
fn a_reinforced_section_and_its_mirror_image_have_the_same_answer() {
    let mirror = |p: (f64, f64)| (-p.0, p.1);
    let nail = Support {
        head: HEAD,
        end: nail_end(),
        spacing: 1.5,
        kind: SupportKind::SoilNail {
            tensile_capacity: 150.0,
            plate_capacity: 50.0,
            bond_strength: 20.0,
        },
        application: Application::Passive,
    };
    let (f, forces) = solve(vec![nail]);
    let mirrored_ground: Vec<(f64, f64)> = ground().into_iter().rev().map(mirror).collect();
    let (a, b) = plane();
    let problem = SectionProblem::new(
        Section::new(SectionParts {
            ground: Polyline::new(mirrored_ground).unwrap(),
            supports: vec![Support {
                head: mirror(nail.head),
                end: mirror(nail.end),
                ..nail
            }],
            ..section_parts()
        })
        .unwrap(),
        SlipShape::Polyline(Polyline::new(vec![mirror(b), mirror(a)]).unwrap()),
        NonZeroUsize::new(40).unwrap(),
        Seismic::default(),
        None,
    )
    .unwrap();
    assert!(problem.is_mirrored());
    let solution = solve_spencer(problem.model(), &SpencerSettings::default());
    let g = solution.factor_of_safety.unwrap();
    assert!((g - f).abs() <= 1e-12 * f, "{g} vs {f}");
    let (here, there) = (forces[0], problem.supports()[0]);
    let (p, q) = (here.crossing.unwrap(), there.crossing.unwrap());
    assert!(
        (q.0 + p.0).abs() < 1e-9 && (q.1 - p.1).abs() < 1e-9,
        "{p:?} {q:?}"
    );
    assert!((there.direction.0 + here.direction.0).abs() < 1e-12);
    assert_eq!(there.force, here.force);
}
