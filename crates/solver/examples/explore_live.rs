use std::num::NonZeroUsize;
use thrustline_solver::arch::*;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args[1].parse().unwrap();
    let d: f64 = args[2].parse().unwrap();
    let mu: Option<f64> = args.get(3).map(|s| s.parse().unwrap());
    let arch = CircularArch::new(
        10.0,
        d,
        NonZeroUsize::new(n).unwrap(),
        0.0,
        0.0,
        VoussoirShape::Curved,
    )
    .unwrap();
    let a = arch.assembly();
    let b = n / 4; // quarter span (right half)
    let g = a.blocks[b].centroid;
    let loads = vec![LiveLoad {
        block: b,
        point: g,
        fx: 0.0,
        fy: -1.0,
        moment: 0.0,
    }];
    let p = ArchProblem::new(a, 1.0, InterfaceLimits::heyman(), mu, loads).unwrap();
    let s = solve_live_load(&p, &LimitSettings::default()).unwrap();
    println!(
        "{:?} lf={:?} margin={:?} it={} t={:.4}",
        s.status, s.load_factor, s.dead_load_margin, s.iterations, s.solve_time_secs
    );
    if let Some(m) = &s.mechanism {
        for a in &m.active {
            println!(
                "  {} {:?} {:?} {:.2} {:?} {:.4e}",
                a.interface + 1,
                a.resultant,
                a.bound,
                a.angle_deg,
                a.hinge,
                a.multiplier
            );
        }
        println!("sliding {:?}", m.sliding);
    }
}
