//! Drawing of an arch: voussoirs, line of thrust, hinges with their angles, live loads as
//! arrows, and the collapse mechanism as the displaced blocks (dashed).

use thrustline_solver::arch::HingeSide;

use super::response::SolvedArch;
use crate::svg::Canvas;

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
    let corners = assembly
        .blocks
        .iter()
        .flat_map(|b| b.corners.iter().copied());
    let mut canvas = Canvas::fitting(corners);
    let span = assembly.length_scale();
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
    for o in &outlines {
        canvas.polygon(
            o,
            &format!("fill=\"#e8dcc8\" stroke=\"#8d6e63\" stroke-width=\"{thin}\""),
        );
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
    // Hinges at the intrados or extrados end of their interface, with their polar angle.
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
        let offset = (
            outward * 14.0 * interface.tangent.0,
            -outward * 14.0 * interface.tangent.1,
        );
        canvas.text(
            point,
            offset,
            &format!("{:.1}° {location}", hinge.angle_deg),
            "font-size=\"11\" fill=\"#1b5e20\" font-family=\"sans-serif\" text-anchor=\"middle\"",
        );
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
    }
    canvas.raw(
        "<g font-size=\"11\" font-family=\"sans-serif\"><text x=\"60\" y=\"44\" fill=\"#c62828\">— line of thrust</text>\
         <text x=\"180\" y=\"44\" fill=\"#1b5e20\">● hinges</text>\
         <text x=\"260\" y=\"44\" fill=\"#546e7a\">- - collapse mechanism</text>\
         <text x=\"420\" y=\"44\" fill=\"#1565c0\">→ live loads</text></g>",
    );
    canvas.finish(title)
}
