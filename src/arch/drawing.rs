//! Drawing of an arch: voussoirs, line of thrust, hinges with their angles, live loads as
//! arrows, and the collapse mechanism as the displaced blocks (dashed).

use thrustline_solver::arch::fill::ExtradosProfile;
use thrustline_solver::arch::HingeSide;

use super::fill::RollingOutDto;
use super::response::SolvedArch;
use crate::svg::{escape, Canvas, Labels, WIDTH};

/// Chains of more blocks than this are drawn as one outline.
const MERGED_ABOVE: usize = 200;
/// Hinges are labelled with their angle when there are at most this many.
const MAX_HINGE_LABELS: usize = 8;

/// Points along a voussoir's outline: straight sides, or arcs about the origin when `curved`.
fn outline(corners: &[(f64, f64)], curved: bool) -> Vec<(f64, f64)> {
    if !curved || corners.len() != 4 {
        return corners.to_vec();
    }
    // Intrados-start → extrados-start (straight), along the extrados, extrados-end →
    // intrados-end (straight), back along the intrados.
    let arc = |a: (f64, f64), b: (f64, f64)| -> Vec<(f64, f64)> {
        let (ra, ta) = (a.0.hypot(a.1), a.1.atan2(a.0));
        let mut tb = b.1.atan2(b.0);
        while tb - ta > std::f64::consts::PI {
            tb -= 2.0 * std::f64::consts::PI;
        }
        while ta - tb > std::f64::consts::PI {
            tb += 2.0 * std::f64::consts::PI;
        }
        (0..=6)
            .map(|i| {
                let t = ta + (tb - ta) * f64::from(i) / 6.0;
                (ra * t.cos(), ra * t.sin())
            })
            .collect()
    };
    let mut points = vec![corners[0]];
    points.extend(arc(corners[1], corners[2]));
    points.extend(arc(corners[3], corners[0]));
    points
}

/// The drawing of a solved arch (with arcs for annular-sector voussoirs).
pub fn draw(solved: &SolvedArch, title: &str) -> String {
    let assembly = solved.input.problem.assembly();
    let curved = solved.input.is_curved;
    let loads = solved.input.problem.live_loads();
    let mechanism = solved.solution.mechanism.as_ref();
    // A chain is drawn with its line of thrust and, when long, its displaced faces; other
    // assemblies block by block, with the points of action at their contacts.
    let chain = assembly.is_chain();
    let corners: Vec<(f64, f64)> = assembly
        .blocks
        .iter()
        .flat_map(|b| b.corners.iter().copied())
        .collect();
    // With fill: the fill between the extrados and the road, over the span.
    let fill = solved.input.fill.as_ref();
    let (x_lo, x_hi) = corners
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    let road = fill.map(|(f, _, _)| [(x_hi, f.road), (x_lo, f.road)]);
    let mut canvas = Canvas::fitting(corners.iter().copied().chain(road.into_iter().flatten()));
    let span = assembly.length_scale();
    let mut legend: Vec<(&str, &str)> = Vec::new();
    if let (Some((f, faces, road_loads)), Some(road)) = (fill, road) {
        let profile = ExtradosProfile::new(faces);
        // A chain's extrados from the right springing to the left (block order), a bridge's
        // upper envelope from the left; closed along the road.
        let mut outline: Vec<(f64, f64)> = if chain {
            assembly
                .blocks
                .iter()
                .flat_map(|b| [b.corners[1], b.corners[2]])
                .collect()
        } else {
            profile.envelope().iter().rev().copied().collect()
        };
        outline.insert(0, road[0]);
        outline.push(road[1]);
        canvas.polygon(&outline, "fill=\"#f3ead7\" stroke=\"none\"");
        canvas.polyline(&road, "stroke=\"#616161\" stroke-width=\"2.5\"");
        legend.push(("#a1887f", "▬ fill and road"));
        // Road loads: the patch on the road and its dispersal lines down to the extrados.
        for load in road_loads {
            let ends = profile.dispersal_ends(f, *load);
            let (a, b) = (load.x - 0.5 * load.length, load.x + 0.5 * load.length);
            let fan = "stroke=\"#1565c0\" stroke-width=\"0.9\" stroke-dasharray=\"3 2\"";
            canvas.polyline(&[(a, f.road), ends[0]], fan);
            canvas.polyline(&[(b, f.road), ends[1]], fan);
            canvas.polyline(
                &[(a, f.road), (b, f.road)],
                "stroke=\"#1565c0\" stroke-width=\"4\"",
            );
        }
        if !road_loads.is_empty() {
            legend.push(("#1565c0", "- - dispersal"));
        }
    }
    let outlines: Vec<Vec<(f64, f64)>> = assembly
        .blocks
        .iter()
        .map(|b| outline(&b.corners, curved))
        .collect();
    let thin = if assembly.blocks.len() > 200 {
        "0.2"
    } else {
        "0.8"
    };
    if chain && assembly.blocks.len() > MERGED_ABOVE {
        // Blocks too small to see one by one: the ring as one outline (extrados out, intrados
        // back), with every tenth joint marked.
        let mut ring: Vec<(f64, f64)> = assembly
            .blocks
            .iter()
            .flat_map(|b| [b.corners[1], b.corners[2]])
            .collect();
        ring.extend(
            assembly
                .blocks
                .iter()
                .rev()
                .flat_map(|b| [b.corners[3], b.corners[0]]),
        );
        canvas.polygon(
            &ring,
            "fill=\"#e8dcc8\" stroke=\"#8d6e63\" stroke-width=\"0.8\"",
        );
        let step = assembly.blocks.len() / 10;
        for i in assembly.interfaces.iter().step_by(step.max(1)) {
            canvas.polyline(
                &[i.intrados, i.extrados],
                "stroke=\"#8d6e63\" stroke-width=\"0.5\"",
            );
        }
    } else {
        for o in &outlines {
            canvas.polygon(
                o,
                &format!("fill=\"#e8dcc8\" stroke=\"#8d6e63\" stroke-width=\"{thin}\""),
            );
        }
    }
    // The collapse mechanism: blocks displaced by 8 % of the span at the fastest corner; each
    // block dashed when there are few, the displaced intrados and extrados when there are many.
    if let Some(mechanism) = mechanism {
        let delta = 0.08 * span;
        let displaced: Vec<Vec<(f64, f64)>> = assembly
            .blocks
            .iter()
            .zip(&mechanism.velocities)
            .map(|(block, &[u, v, rotation])| {
                let g = block.centroid;
                let corners = if chain && assembly.blocks.len() > 60 {
                    block.corners.to_vec()
                } else {
                    outline(&block.corners, curved)
                };
                corners
                    .into_iter()
                    .map(|(x, y)| {
                        (
                            x + delta * (u - rotation * (y - g.1)),
                            y + delta * (v + rotation * (x - g.0)),
                        )
                    })
                    .collect()
            })
            .collect();
        let style =
            "fill=\"none\" stroke=\"#546e7a\" stroke-width=\"0.9\" stroke-dasharray=\"4 3\"";
        if chain && assembly.blocks.len() > 60 {
            let intrados: Vec<(f64, f64)> = displaced.iter().flat_map(|c| [c[0], c[3]]).collect();
            let extrados: Vec<(f64, f64)> = displaced.iter().flat_map(|c| [c[1], c[2]]).collect();
            canvas.polyline(&intrados, style);
            canvas.polyline(&extrados, style);
        } else {
            for d in &displaced {
                canvas.polygon(d, style);
            }
        }
    }
    // The line of thrust through the points of action at the interfaces.
    let thrust: Vec<(f64, f64)> = solved
        .thrust_line
        .iter()
        .map(|t| t.point.unwrap_or((f64::NAN, f64::NAN)))
        .collect();
    if chain {
        canvas.polyline(&thrust, "stroke=\"#c62828\" stroke-width=\"1.8\"");
    } else {
        for point in thrust.iter().filter(|p| p.0.is_finite()) {
            canvas.dot(*point, 2.5, "fill=\"#c62828\"");
        }
    }
    // Hinges at the intrados or extrados end of their interface; their labels (polar angle and
    // side) are placed after the loads, clear of the dots, the arrows and each other.
    let mut hinge_labels = Vec::new();
    let mut labels = Labels::default();
    for hinge in mechanism.map(|m| m.hinges.as_slice()).unwrap_or_default() {
        let Some(interface) = assembly.interfaces.get(hinge.interface) else {
            continue;
        };
        let (point, outward, location) = match hinge.side {
            HingeSide::Intrados => (interface.intrados, -1.0, "intrados"),
            HingeSide::Extrados => (interface.extrados, 1.0, "extrados"),
        };
        canvas.dot(
            point,
            5.0,
            "fill=\"#1b5e20\" stroke=\"white\" stroke-width=\"1.5\"",
        );
        let p = canvas.px(point);
        labels.avoid([p.0 - 6.0, p.1 - 6.0, p.0 + 6.0, p.1 + 6.0]);
        // Away from the arch: outwards at the extrados, inwards at the intrados (pixels, y down).
        let direction = (
            outward * interface.tangent.0,
            -outward * interface.tangent.1,
        );
        hinge_labels.push((p, direction, format!("{:.1}° {location}", hinge.angle_deg)));
    }
    // Live loads: arrows ending at their point, 12 % of the span long.
    let largest = loads.iter().map(|l| l.fx.hypot(l.fy)).fold(0.0, f64::max);
    for load in loads {
        let magnitude = load.fx.hypot(load.fy);
        if magnitude == 0.0 || largest == 0.0 {
            continue;
        }
        let length = 0.12 * span * magnitude / largest;
        let from = (
            load.point.0 - length * load.fx / magnitude,
            load.point.1 - length * load.fy / magnitude,
        );
        canvas.arrow(from, load.point, "stroke=\"#1565c0\" stroke-width=\"2\"");
        labels.avoid_segment(canvas.px(from), canvas.px(load.point), 6.0);
    }
    let area = canvas.plot_area();
    // Many hinges (a multi-ring mechanism) would bury the drawing in labels: their angles are
    // in the JSON; the key says how many.
    let hinge_count = hinge_labels.len();
    if hinge_count > MAX_HINGE_LABELS {
        hinge_labels.clear();
    }
    for (p, direction, text) in hinge_labels {
        let (x, y) = labels.place(p, direction, (text.chars().count(), 11.0), area);
        canvas.raw(&format!(
            "<text x=\"{x:.2}\" y=\"{:.2}\" font-size=\"11\" fill=\"#1b5e20\" font-family=\"sans-serif\">{}</text>",
            y + 9.0,
            escape(&text)
        ));
    }
    // Passive pressure where mobilised: horizontal arrows onto the extrados.
    let problem = &solved.input.problem;
    let mobilised = &solved.solution.passive;
    let strongest = mobilised.iter().fold(0.0f64, |m, p| m.max(*p));
    if strongest > 0.0 {
        for (force, &p) in problem.passive().iter().zip(mobilised) {
            if p <= 1e-6 * strongest {
                continue;
            }
            let length = 0.06 * span * p / strongest;
            let from = (force.point.0 - force.direction * length, force.point.1);
            canvas.arrow(from, force.point, "stroke=\"#6d4c41\" stroke-width=\"1.6\"");
        }
        legend.push(("#6d4c41", "→ passive pressure"));
    }
    // Crushing joints: a bar across the joint.
    if let Some(m) = mechanism.filter(|m| !m.crushing.is_empty()) {
        for &k in &m.crushing {
            if let Some(i) = assembly.interfaces.get(k) {
                canvas.polyline(
                    &[i.intrados, i.extrados],
                    "stroke=\"#ef6c00\" stroke-width=\"4\"",
                );
            }
        }
        legend.push(("#ef6c00", "▮ crushing"));
    }
    // Sliding joints: the joint drawn along, with the slip of the block on the normal's side
    // relative to the other (of the block, on a support) as a short arrow at its middle.
    if let Some(m) = mechanism.filter(|m| !m.sliding.is_empty()) {
        for &k in &m.sliding {
            if let Some(i) = assembly.interfaces.get(k) {
                canvas.polyline(
                    &[i.intrados, i.extrados],
                    "stroke=\"#7b1fa2\" stroke-width=\"3\" stroke-dasharray=\"2 2\"",
                );
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
        legend.push(("#7b1fa2", "┊ sliding joints (→ slip)"));
    }
    if !solved.thrust_line.is_empty() {
        legend.insert(0, ("#c62828", "— line of thrust"));
    }
    if mechanism.is_some_and(|m| !m.hinges.is_empty()) {
        legend.push((
            "#1b5e20",
            if hinge_count > MAX_HINGE_LABELS {
                "● hinges (unlabelled: too many)"
            } else {
                "● hinges"
            },
        ));
    }
    if mechanism.is_some() {
        legend.push(("#546e7a", "- - collapse mechanism"));
    }
    if !loads.is_empty() {
        legend.push(("#1565c0", "→ live loads"));
    }
    for (colour, text) in &legend {
        canvas.key(text, colour, 11.0, false);
    }
    if let Some(curve) = &solved.rolling {
        rolling_curve(&mut canvas, curve);
    }
    canvas.finish(title)
}

/// λ against the position of a rolling load, in a band under the arch, the critical stop
/// marked.
fn rolling_curve(canvas: &mut Canvas, curve: &RollingOutDto) {
    let points: Vec<(f64, f64)> = curve
        .positions
        .iter()
        .zip(&curve.load_factor)
        .filter_map(|(&x, l)| l.map(|l| (x, l)))
        .collect();
    if points.is_empty() {
        return;
    }
    let (height, left, right) = (150.0, 60.0, WIDTH - 60.0);
    let top = canvas.band_below(height + 40.0) + 20.0;
    let (x0, x1) = (
        curve.positions[0],
        curve.positions[curve.positions.len() - 1],
    );
    let l1 = points.iter().fold(0.0f64, |m, p| m.max(p.1)) * 1.05;
    let px = |(x, l): (f64, f64)| {
        let u = if x1 > x0 { (x - x0) / (x1 - x0) } else { 0.5 };
        let v = if l1 > 0.0 { l / l1 } else { 0.0 };
        (left + u * (right - left), top + height - v * height)
    };
    let path: Vec<String> = points
        .iter()
        .map(|&p| {
            let (x, y) = px(p);
            format!("{x:.2},{y:.2}")
        })
        .collect();
    let mut svg = format!(
        "<g font-size=\"11\" font-family=\"sans-serif\"><rect x=\"{left}\" y=\"{top:.2}\" width=\"{:.2}\" height=\"{height}\" fill=\"none\" stroke=\"#999\"/>\
         <polyline points=\"{}\" fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.6\"/>\
         <text x=\"{left}\" y=\"{:.2}\" fill=\"#333\">rolling load: λ against position (x from {} to {}; top of the box λ = {:.3})</text>",
        right - left,
        path.join(" "),
        top - 6.0,
        x0,
        x1,
        l1
    );
    if let (Some(x), Some(l)) = (curve.critical_position, curve.critical_load_factor) {
        let (cx, cy) = px((x, l));
        svg.push_str(&format!(
            "<circle cx=\"{cx:.2}\" cy=\"{cy:.2}\" r=\"4\" fill=\"#c62828\"/>\
             <text x=\"{:.2}\" y=\"{:.2}\" fill=\"#c62828\">critical: x = {x:.3}, λ = {l:.4}</text>",
            cx + 6.0,
            cy + 14.0
        ));
    }
    svg.push_str("</g>");
    canvas.raw(&svg);
}

/// The sign of the slip along interface `i` (along its tangent) of its `upper` block relative to
/// its `lower` one (on a support, of the block on it), at the joint's middle; `None` when the
/// two move alike there.
fn slip(
    assembly: &thrustline_solver::arch::Assembly,
    velocities: &[[f64; 3]],
    i: &thrustline_solver::arch::Interface,
) -> Option<f64> {
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
