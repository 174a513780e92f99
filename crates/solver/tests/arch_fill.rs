//! Fill over an arch (model §5.1, §5.6) against analytic values and the plain live load.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use thrustline_solver::arch::fill::{
    fill_dead_loads, road_load, Extrados, ExtradosFaces, Fill, RoadLoad,
};
use thrustline_solver::arch::*;
use thrustline_solver::reference::semicircle;

const ARC: Extrados = Extrados::Arc { centre: (0.0, 0.0) };

fn settings() -> LimitSettings {
    LimitSettings::default()
}

#[test]
fn the_fill_weighs_what_lies_between_the_extrados_and_the_road() {
    // Semicircle R = 10, D = 1.5 (extrados 10.75), road at 12: the fill over the span is
    // 2·Re·y_r − π·Re²/2 (the rectangle minus the half disc), 18 kN/m³.
    let arch = semicircle(100, 10.0, 1.5).assembly();
    let fill = Fill {
        unit_weight: 18.0,
        road: 12.0,
        dispersal_angle_deg: 30.0,
        layers: Vec::new(),
    };
    let loads = fill_dead_loads(&ExtradosFaces::of_chain(&arch, ARC), &fill);
    let total: f64 = loads.iter().map(|l| -l.fy).sum();
    let re: f64 = 10.75;
    let expected = 18.0 * (2.0 * re * 12.0 - std::f64::consts::PI * re * re / 2.0);
    assert!(
        (total - expected).abs() < 1e-5 * expected,
        "{total} vs {expected}"
    );
    // Each load sits on its voussoir's extrados.
    for l in &loads {
        assert!(
            (l.point.0.hypot(l.point.1) - re).abs() < 1e-4,
            "{:?}",
            l.point
        );
    }
}

#[test]
fn the_supports_carry_the_arch_the_fill_and_the_live_load() {
    // At collapse under the live load, the two vertical reactions add up to the blocks'
    // weight, the fill's and λ·P (to 1e-9 of the total).
    let arch = semicircle(60, 10.0, 1.5).assembly();
    let fill = Fill {
        unit_weight: 1.0,
        road: 11.5,
        dispersal_angle_deg: 30.0,
        layers: Vec::new(),
    };
    let dead = fill_dead_loads(&ExtradosFaces::of_chain(&arch, ARC), &fill);
    let live = road_load(
        &ExtradosFaces::of_chain(&arch, ARC),
        &fill,
        RoadLoad {
            x: -4.0,
            fy: -1.0,
            length: 0.3,
        },
    );
    let spread: f64 = live.iter().map(|l| l.fy).sum();
    assert!(
        (spread + 1.0).abs() < 1e-12,
        "the dispersed load adds up to {spread}"
    );
    let problem = ArchProblem::new(arch.clone(), 1.0, InterfaceLimits::heyman(), None, live)
        .unwrap()
        .with_dead_loads(dead.clone())
        .unwrap();
    let s = solve_live_load(&problem, &settings()).unwrap();
    assert_eq!(s.status, LimitStatus::Solved);
    let lambda = s.load_factor.unwrap();
    let reactions = support_reactions(&arch, &s.resultants).unwrap();
    let w_blocks = arch.total_area();
    let w_fill: f64 = dead.iter().map(|l| -l.fy).sum();
    let vertical: f64 = reactions.iter().map(|r| r.vertical).sum::<f64>();
    let expected = w_blocks + w_fill + lambda;
    assert!(
        (vertical.abs() - expected).abs() < 1e-9 * expected,
        "{vertical} vs {expected}"
    );
}

#[test]
fn weightless_fill_without_dispersal_is_the_plain_live_load_on_the_extrados() {
    // model §5.6: the same λ as a point load at (x, √(Re² − x²)) on the voussoir under it.
    let arch = semicircle(100, 10.0, 1.5).assembly();
    let fill = Fill {
        unit_weight: 0.0,
        road: 12.0,
        dispersal_angle_deg: 0.0,
        layers: Vec::new(),
    };
    let x: f64 = -4.3;
    let loads = road_load(
        &ExtradosFaces::of_chain(&arch, ARC),
        &fill,
        RoadLoad {
            x,
            fy: -1.0,
            length: 0.0,
        },
    );
    assert_eq!(loads.len(), 1);
    let re: f64 = 10.75;
    let point = (x, (re * re - x * x).sqrt());
    assert!((loads[0].point.1 - point.1).abs() < 1e-4);
    let by_fill = ArchProblem::new(
        arch.clone(),
        1.0,
        InterfaceLimits::heyman(),
        None,
        loads.clone(),
    )
    .unwrap()
    .with_dead_loads(fill_dead_loads(&ExtradosFaces::of_chain(&arch, ARC), &fill))
    .unwrap();
    let plain = ArchProblem::new(
        arch.clone(),
        1.0,
        InterfaceLimits::heyman(),
        None,
        vec![LiveLoad {
            block: loads[0].block,
            point,
            fx: 0.0,
            fy: -1.0,
            moment: 0.0,
        }],
    )
    .unwrap();
    let a = solve_live_load(&by_fill, &settings())
        .unwrap()
        .load_factor
        .unwrap();
    let b = solve_live_load(&plain, &settings())
        .unwrap()
        .load_factor
        .unwrap();
    assert!((a - b).abs() < 1e-4 * b, "{a} vs {b}");
    // The voussoir is the one whose extrados spans x.
    let c = &arch.blocks[loads[0].block].corners;
    let (lo, hi) = (c[1].0.min(c[2].0), c[1].0.max(c[2].0));
    assert!(lo <= x && x <= hi);
}

#[test]
fn dispersal_spreads_the_load_over_the_width_the_angle_gives() {
    // Road 2 above a flat-ish crown: a patch 0.3 wide at x = 0 spreads over about
    // 0.3 + 2·(road − y_e)·tan 30°; the shares are proportional to the overlaps.
    let arch = semicircle(200, 10.0, 1.0).assembly();
    let fill = Fill {
        unit_weight: 0.0,
        road: 12.5,
        dispersal_angle_deg: 30.0,
        layers: Vec::new(),
    };
    let loads = road_load(
        &ExtradosFaces::of_chain(&arch, ARC),
        &fill,
        RoadLoad {
            x: 0.0,
            fy: -10.0,
            length: 0.3,
        },
    );
    let xs: Vec<f64> = loads.iter().map(|l| l.point.0).collect();
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    // Depth of fill at the crown 2.0 (extrados 10.5): half-width ≥ 0.15 + 2·tan 30°.
    let half = 0.15 + 2.0 * 30f64.to_radians().tan();
    assert!(
        hi > 0.8 * half && -lo > 0.8 * half && hi < 1.1 * half,
        "{lo} … {hi}"
    );
    let total: f64 = loads.iter().map(|l| l.fy).sum();
    assert!((total + 10.0).abs() < 1e-12);
}

#[test]
fn a_road_load_beyond_the_springing_puts_only_its_share_on_the_arch() {
    // Semicircle R = 10, D = 1 (extrados 10.5), road at 11.5, dispersal 30°, a point load at
    // x = −12 (1.5 beyond the left springing). Its left line meets no arch; its right line
    // y = 11.5 − √3·(x + 12) meets the extrados y = √(10.5² − x²) at x_c (bisection here). The
    // load spreads uniformly over [−12, x_c]; the arch carries the part over [−10.5, x_c]:
    // (x_c + 10.5)/(x_c + 12) of it (1e-6: the extrados is sampled; measured 2e-8).
    let arch = semicircle(100, 10.0, 1.0).assembly();
    let fill = Fill {
        unit_weight: 1.0,
        road: 11.5,
        dispersal_angle_deg: 30.0,
        layers: Vec::new(),
    };
    let line = |x: f64| 11.5 - 3f64.sqrt() * (x + 12.0) - (10.5f64 * 10.5 - x * x).max(0.0).sqrt();
    let (mut a, mut b) = (-10.5, 0.0);
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        if line(m) > 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    let xc = 0.5 * (a + b);
    let share = (xc + 10.5) / (xc + 12.0);
    let loads = road_load(
        &ExtradosFaces::of_chain(&arch, ARC),
        &fill,
        RoadLoad {
            x: -12.0,
            fy: -1.0,
            length: 0.0,
        },
    );
    let carried: f64 = loads.iter().map(|l| -l.fy).sum();
    assert!(
        (carried - share).abs() < 1e-6,
        "{carried} vs {share} (x_c = {xc})"
    );
    assert!(loads.iter().all(|l| l.point.0 <= xc + 0.5), "{loads:?}");
}
