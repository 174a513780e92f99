use std::num::NonZeroUsize;
use thrustline_solver::arch::*;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args[1].parse().unwrap();
    let d: f64 = args[2].parse().unwrap();
    let arch = CircularArch::new(
        10.0,
        d,
        NonZeroUsize::new(n).unwrap(),
        0.0,
        0.0,
        VoussoirShape::Curved,
    )
    .unwrap();
    let p = ArchProblem::new(
        arch.assembly(),
        1.0,
        InterfaceLimits::heyman(),
        None,
        vec![],
    )
    .unwrap();
    let s = solve_dead_load(&p, &LimitSettings::default());
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
    }
}
