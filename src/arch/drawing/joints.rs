//! Forces and joints drawn over an arch: passive pressure where mobilised, crushing joints as
//! bars, sliding joints with the slip of one block on the other.

use thrustline_solver::arch::{ArchProblem, Assembly, Interface, Mechanism};

use super::parts::Legend;
use crate::svg::Canvas;

/// Passive pressure where mobilised: horizontal arrows onto the extrados.
pub fn passive(canvas: &mut Canvas, problem: &ArchProblem, mobilised: &[f64], legend: &mut Legend) {
    let span = problem.assembly().length_scale();
    let strongest = mobilised.iter().fold(0.0f64, |m, p| m.max(*p));
    if strongest > 0.0 {
        for (force, &p) in problem.passive().iter().zip(mobilised) {
            if p <= 1e-6 * strongest {
                continue;
            }
            let length = 0.06 * span * p / strongest;
            let from = (force.point.0 - force.direction * length, force.point.1);
            canvas.arrow_in(from, force.point, "#6d4c41", 1.6);
        }
        legend.push(("#6d4c41", "→ passive pressure".into()));
    }
}

/// Crushing joints: a bar across the joint.
pub fn crushing(
    canvas: &mut Canvas,
    assembly: &Assembly,
    mechanism: Option<&Mechanism>,
    legend: &mut Legend,
) {
    if let Some(m) = mechanism.filter(|m| !m.crushing.is_empty()) {
        let bars: Vec<Vec<(f64, f64)>> = m
            .crushing
            .iter()
            .filter_map(|&k| assembly.interfaces.get(k))
            .map(|i| vec![i.intrados, i.extrados])
            .collect();
        canvas.path(
            &bars,
            false,
            "fill=\"none\" stroke=\"#ef6c00\" stroke-width=\"4\"",
        );
        legend.push(("#ef6c00", "▮ crushing".into()));
    }
}

/// Sliding joints with their slip arrows when at most this many.
const MAX_SLIP_ARROWS: usize = 40;

/// Sliding joints: the joint drawn along, with the slip of the block on the normal's side
/// relative to the other (of the block, on a support) as a short arrow at its middle.
pub fn sliding(
    canvas: &mut Canvas,
    assembly: &Assembly,
    mechanism: Option<&Mechanism>,
    legend: &mut Legend,
) {
    let span = assembly.length_scale();
    if let Some(m) = mechanism.filter(|m| !m.sliding.is_empty()) {
        let joints: Vec<&Interface> = m
            .sliding
            .iter()
            .filter_map(|&k| assembly.interfaces.get(k))
            .collect();
        let along: Vec<Vec<(f64, f64)>> = joints
            .iter()
            .map(|i| vec![i.intrados, i.extrados])
            .collect();
        canvas.path(
            &along,
            false,
            "fill=\"none\" stroke=\"#7b1fa2\" stroke-width=\"3\" stroke-dasharray=\"2 2\"",
        );
        // Beyond a few dozen the arrows would hide the arch: the joints alone, said in the key.
        if joints.len() > MAX_SLIP_ARROWS {
            legend.push((
                "#7b1fa2",
                "┊ sliding joints (slip arrows left out: too many)".into(),
            ));
            return;
        }
        for i in joints {
            {
                if let Some(slip) = slip(assembly, &m.velocities, i) {
                    let middle = (
                        0.5 * (i.intrados.0 + i.extrados.0),
                        0.5 * (i.intrados.1 + i.extrados.1),
                    );
                    let (t, n) = (
                        (slip * i.tangent.0, slip * i.tangent.1),
                        (-i.tangent.1, i.tangent.0),
                    );
                    let (half, head) = (0.04 * span, 0.015 * span);
                    let tip = (middle.0 + half * t.0, middle.1 + half * t.1);
                    let (a, b) = (
                        canvas.px((middle.0 - half * t.0, middle.1 - half * t.1)),
                        canvas.px(tip),
                    );
                    canvas.raw(&format!(
                        "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"#7b1fa2\" stroke-width=\"1.4\"/>",
                        a.0, a.1, b.0, b.1
                    ));
                    let back = (tip.0 - head * t.0, tip.1 - head * t.1);
                    canvas.polygon(
                        &[
                            tip,
                            (back.0 + 0.5 * head * n.0, back.1 + 0.5 * head * n.1),
                            (back.0 - 0.5 * head * n.0, back.1 - 0.5 * head * n.1),
                        ],
                        "fill=\"#7b1fa2\" stroke=\"none\"",
                    );
                }
            }
        }
        legend.push(("#7b1fa2", "┊ sliding joints (→ slip)".into()));
    }
}

/// The sign of the slip along interface `i` (along its tangent) of its `upper` block relative to
/// its `lower` one (on a support, of the block on it), at the joint's middle; `None` when the
/// two move alike there.
fn slip(assembly: &Assembly, velocities: &[[f64; 3]], i: &Interface) -> Option<f64> {
    let middle = (
        0.5 * (i.intrados.0 + i.extrados.0),
        0.5 * (i.intrados.1 + i.extrados.1),
    );
    let at = |block: Option<usize>| -> (f64, f64) {
        let Some(b) = block.and_then(|b| velocities.get(b).zip(assembly.blocks.get(b))) else {
            return (0.0, 0.0);
        };
        let ([u, v, w], g) = (b.0, b.1.centroid);
        (u - w * (middle.1 - g.1), v + w * (middle.0 - g.0))
    };
    // On a support (no upper block), the block's slip on it.
    let (a, b) = match i.upper {
        Some(_) => (at(i.lower), at(i.upper)),
        None => (at(i.upper), at(i.lower)),
    };
    let along = (b.0 - a.0) * i.tangent.0 + (b.1 - a.1) * i.tangent.1;
    let scale = a.0.hypot(a.1).max(b.0.hypot(b.1));
    (along.abs() > 1e-9 * scale && scale > 0.0).then(|| along.signum())
}
