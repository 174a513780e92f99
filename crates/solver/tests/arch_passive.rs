//! Passive restraint of a fill (model §5.1, §5.6): its capacities against the closed form, the
//! whole bridge in equilibrium with the forces it mobilises, and the load factor never lowered.

// Fixtures: a failed construction should fail the test loudly.
#![allow(clippy::unwrap_used)]

use thrustline_solver::arch::fill::{
    fill_dead_loads, passive_forces, road_load, Extrados, ExtradosFaces, Fill, Passive,
    PassiveForce, RoadLoad,
};
use thrustline_solver::arch::*;
use thrustline_solver::reference::semicircle;

const ARC: Extrados = Extrados::Arc { centre: (0.0, 0.0) };

fn fill() -> Fill {
    Fill {
        unit_weight: 1.0,
        road: 11.5,
        dispersal_angle_deg: 30.0,
        layers: Vec::new(),
    }
}

/// A thin filled semicircle (R = 10, D = 1, N = 60) with a wheel at x = −4 and the given
/// passive restraint.
fn bridge(passive: Option<Passive>) -> (ArchProblem, Vec<PassiveForce>, Vec<LiveLoad>) {
    let arch = semicircle(60, 10.0, 1.0).assembly();
    let fill = fill();
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
    let forces = passive.map_or(Vec::new(), |p| {
        passive_forces(&arch, &ExtradosFaces::of_chain(&arch, ARC), &fill, &p)
    });
    let problem = ArchProblem::new(arch, 1.0, InterfaceLimits::heyman(), None, live.clone())
        .unwrap()
        .with_dead_loads(dead)
        .unwrap()
        .with_passive(forces.clone())
        .unwrap();
    (problem, forces, live)
}

fn lambda(problem: &ArchProblem) -> f64 {
    let s = solve_live_load(problem, &LimitSettings::default()).unwrap();
    assert_eq!(s.status, LimitStatus::Solved);
    s.load_factor.unwrap()
}

#[test]
fn capacities_follow_the_passive_pressure_on_a_vertical_face() {
    // One square block whose extrados (x = 0, from y = 0 to y = 1) faces a fill with its road at
    // y = 3: capacity m·K_p·γ·∫₀¹ (3 − y) dy = m·K_p·γ·2.5, at the centroid of the trapezoid
    // y = (3·1²/2 − 1/3)/2.5, pushing towards +x (the fill lies at x < 0).
    let block = [(1.0, 0.0), (0.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
    let a = Assembly::from_quadrilaterals(&[block]).unwrap();
    let fill = Fill {
        unit_weight: 18.0,
        road: 3.0,
        dispersal_angle_deg: 0.0,
        layers: Vec::new(),
    };
    let p = Passive {
        friction_angle_deg: 30.0,
        mobilisation: 0.5,
    };
    let kp = 3.0; // (1 + ½)/(1 − ½)
    let f = passive_forces(
        &a,
        &ExtradosFaces::of_chain(&a, Extrados::Straight),
        &fill,
        &p,
    );
    assert_eq!(f.len(), 1, "{f:?}");
    let expected = 0.5 * kp * 18.0 * 2.5;
    assert!((f[0].capacity - expected).abs() < 1e-9 * expected, "{f:?}");
    assert_eq!(f[0].direction, 1.0);
    let y = (1.5 - 1.0 / 3.0) / 2.5;
    assert!((f[0].point.1 - y).abs() < 1e-9 && f[0].point.0.abs() < 1e-12);
    // No mobilisation, no force; a road below the face, none either.
    let none = Passive {
        mobilisation: 0.0,
        ..p
    };
    assert!(passive_forces(
        &a,
        &ExtradosFaces::of_chain(&a, Extrados::Straight),
        &fill,
        &none
    )
    .is_empty());
    let low = Fill { road: -1.0, ..fill };
    assert!(passive_forces(
        &a,
        &ExtradosFaces::of_chain(&a, Extrados::Straight),
        &low,
        &p
    )
    .is_empty());
}

#[test]
fn the_semicircle_is_restrained_from_both_sides_by_equal_capacities() {
    // A symmetric arch and fill: the capacities mirror each other (1e-9), push inwards, and
    // those of the springing voussoirs are the largest (deepest, steepest extrados).
    let arch = semicircle(60, 10.0, 1.0).assembly();
    let p = Passive {
        friction_angle_deg: 30.0,
        mobilisation: 1.0,
    };
    let f = passive_forces(&arch, &ExtradosFaces::of_chain(&arch, ARC), &fill(), &p);
    let total = |dir: f64| -> f64 {
        f.iter()
            .filter(|x| x.direction == dir)
            .map(|x| x.capacity)
            .sum()
    };
    let (left, right) = (total(1.0), total(-1.0));
    assert!((left - right).abs() < 1e-9 * left, "{left} {right}");
    // The whole extrados from the springing (y = 0) to the crown (10.5) under a road at 11.5:
    // K_p·γ·∫₀^10.5 (11.5 − y) dy on each side.
    let expected = 3.0 * (11.5 * 10.5 - 10.5 * 10.5 / 2.0);
    assert!(
        (left - expected).abs() < 1e-6 * expected,
        "{left} vs {expected}"
    );
    for x in &f {
        assert_eq!(x.direction, -x.point.0.signum(), "{x:?}");
    }
}

#[test]
fn passive_restraint_never_lowers_the_load_factor_and_grows_with_mobilisation() {
    let (bare, _, _) = bridge(None);
    let lambda_bare = lambda(&bare);
    let mut previous = lambda_bare;
    for m in [0.0, 0.05, 0.2, 0.5, 1.0] {
        let (p, _, _) = bridge(Some(Passive {
            friction_angle_deg: 30.0,
            mobilisation: m,
        }));
        let l = lambda(&p);
        // 1e-7: the interior-point tolerance, relative.
        assert!(l >= previous * (1.0 - 1e-7), "m = {m}: {l} < {previous}");
        if m == 0.0 {
            assert!(
                (l - lambda_bare).abs() < 1e-7 * lambda_bare,
                "{l} {lambda_bare}"
            );
        }
        previous = l;
    }
    // Full passive resistance carries several times the bare fill's wheel load.
    assert!(previous > 1.5 * lambda_bare, "{previous} vs {lambda_bare}");
}

#[test]
fn the_bridge_is_in_equilibrium_with_the_passive_forces_it_mobilises() {
    // Whole-structure equilibrium computed here from the support resultants (q at the extrados
    // end, s at the intrados end, t along the joint), the block and fill weights, λ·P and the
    // mobilised passive forces at their points: forces and moment about the origin vanish
    // (1e-7 of the total weight), and 0 ≤ force ≤ capacity.
    let (problem, forces, live) = bridge(Some(Passive {
        friction_angle_deg: 30.0,
        mobilisation: 0.5,
    }));
    let s = solve_live_load(&problem, &LimitSettings::default()).unwrap();
    let lambda = s.load_factor.unwrap();
    let a = problem.assembly();
    let n = a.interfaces.len() - 1;
    let (mut fx, mut fy, mut m) = (0.0, 0.0, 0.0);
    let mut add = |p: (f64, f64), f: (f64, f64)| {
        fx += f.0;
        fy += f.1;
        m += p.0 * f.1 - p.1 * f.0;
    };
    for (k, sign) in [(0, 1.0), (n, -1.0)] {
        let i = a.interfaces[k];
        let [q, s_, t] = s.resultants[k];
        add(i.extrados, (sign * q * i.normal.0, sign * q * i.normal.1));
        add(i.intrados, (sign * s_ * i.normal.0, sign * s_ * i.normal.1));
        add(i.intrados, (sign * t * i.tangent.0, sign * t * i.tangent.1));
    }
    for b in &a.blocks {
        add(b.centroid, (0.0, -problem.unit_weight() * b.area));
    }
    for l in problem.dead_loads() {
        add(l.point, (l.fx, l.fy));
    }
    for l in &live {
        add(l.point, (lambda * l.fx, lambda * l.fy));
    }
    assert_eq!(s.passive.len(), forces.len());
    let mut mobilised = 0.0;
    for (f, &p) in forces.iter().zip(&s.passive) {
        assert!(
            p >= -1e-7 && p <= f.capacity * (1.0 + 1e-7) + 1e-9,
            "{p} {f:?}"
        );
        add(f.point, (f.direction * p, 0.0));
        mobilised += p;
    }
    assert!(
        mobilised > 0.0,
        "the sway mechanism mobilises passive pressure"
    );
    let w: f64 = a.total_area() + problem.dead_loads().iter().map(|l| -l.fy).sum::<f64>();
    for r in [fx, fy, m / 10.0] {
        assert!(r.abs() < 1e-7 * w, "residual {r} of {w}");
    }
}
