//! Drawing of an arch: voussoirs, line of thrust, hinges with their angles, live loads as
//! arrows, and the collapse mechanism as the displaced blocks (dashed).

mod joints;
mod parts;
mod rolling;

use super::rolling::RollingOutDto;
use super::solved::SolvedArch;
use crate::svg::Canvas;
use parts::{Legend, MAX_HINGE_LABELS};

/// Assemblies of more blocks than this are drawn without the displaced blocks and the sliding
/// joints (both in the JSON; the key says so): each block is then a pixel or two wide, and
/// drawing them twice more doubled the picture (1.4 MB for eight rings of 1000).
const MECHANISM_DRAWN_UP_TO: usize = 1000;
/// The dead-load drawing's title: λ₀ and whether the arch stands.
pub fn dead_load_title(solved: &SolvedArch) -> String {
    match solved.solution.load_factor {
        Some(f) if f >= 1.0 => format!("Dead load: λ₀ = {f} (stands)"),
        Some(f) => format!("Dead load: λ₀ = {f} (collapses)"),
        None => "Dead load: no answer".to_owned(),
    }
}

/// The live-load drawing's title: λ, or why there is none.
pub fn live_load_title(solved: &SolvedArch) -> String {
    match (
        solved.solution.load_factor,
        solved.solution.dead_load_carried,
    ) {
        (Some(f), _) => format!("Live load: λ = {f:.4}"),
        (None, Some(false)) => "Live load: the dead load is not carried".to_owned(),
        (None, _) => "Live load: no collapse load".to_owned(),
    }
}

/// A dense chain's key entry: how many of its joints are drawn.
fn joints_key(canvas: &mut Canvas, assembly: &thrustline_solver::arch::Assembly) {
    if let Some((blocks, step)) = parts::joints_drawn(assembly) {
        canvas.key(
            &format!("| {blocks} voussoirs: one joint in {step} drawn"),
            "#8d6e63",
            11.0,
            false,
        );
    }
}

/// Every block's corners.
fn corners(assembly: &thrustline_solver::arch::Assembly) -> Vec<(f64, f64)> {
    assembly
        .blocks
        .iter()
        .flat_map(|b| b.corners.iter().copied())
        .collect()
}

/// The road's two ends.
type Road = [(f64, f64); 2];

/// The drawing of a minimum-thickness answer: the arch just too thin to stand, its voussoirs
/// and its collapse mechanism with the hinges labelled by angle (`mechanism` is that arch's),
/// or the arch alone when there is none.
pub fn minimum_thickness(
    assembly: &thrustline_solver::arch::Assembly,
    mechanism: Option<&thrustline_solver::arch::Mechanism>,
    curved: bool,
    (title, caption): (&str, &str),
) -> String {
    let corners = corners(assembly);
    let mut canvas = fitted(assembly, &[], &corners, (None, None));
    parts::blocks(&mut canvas, assembly, curved);
    if let Some(mechanism) = mechanism {
        if assembly.blocks.len() <= MECHANISM_DRAWN_UP_TO {
            parts::mechanism(&mut canvas, assembly, mechanism, curved);
        }
    }
    let count = parts::hinges_and_loads(&mut canvas, assembly, mechanism, &[]);
    canvas.key(caption, "#37474f", 12.0, true);
    if mechanism.is_some_and(|m| !m.hinges.is_empty()) {
        let hinges = match count > MAX_HINGE_LABELS {
            true => "● hinges of its collapse (unlabelled: too many)",
            false => "● hinges of its collapse",
        };
        canvas.key(hinges, "#1b5e20", 11.0, true);
        let drawn = assembly.blocks.len() <= MECHANISM_DRAWN_UP_TO;
        let mechanism = match drawn {
            true => "- - collapse mechanism",
            false => "collapse mechanism not drawn: too many blocks",
        };
        canvas.key(mechanism, "#546e7a", 11.0, false);
    }
    joints_key(&mut canvas, assembly);
    canvas.finish(title)
}

/// The canvas holding the blocks' corners, the road, the live loads' arrows (so that no arrow
/// runs into the key above the plot) and a rolling load's first and last stops (on the x axis
/// the curve under the bridge shares).
fn fitted(
    assembly: &thrustline_solver::arch::Assembly,
    loads: &[thrustline_solver::arch::LiveLoad],
    corners: &[(f64, f64)],
    (road, rolling): (Option<Road>, Option<&RollingOutDto>),
) -> Canvas {
    let tails = parts::load_arrows(assembly, loads)
        .into_iter()
        .map(|(from, _)| from);
    let y_low = corners.iter().fold(f64::INFINITY, |m, p| m.min(p.1));
    let stops = rolling.into_iter().flat_map(|r| {
        [r.positions.first(), r.positions.last()]
            .into_iter()
            .flatten()
            .map(move |&x| (x, y_low))
    });
    Canvas::fitting(
        corners
            .iter()
            .copied()
            .chain(road.into_iter().flatten())
            .chain(tails)
            .chain(stops),
    )
}

/// The drawing of a solved arch (with arcs for annular-sector voussoirs).
pub fn draw(solved: &SolvedArch, title: &str) -> String {
    let assembly = solved.input.problem.assembly();
    let loads = solved.input.problem.live_loads();
    let mechanism = solved.solution.mechanism.as_ref();
    let corners = corners(assembly);
    // With fill: the fill between the extrados and the road, over the span.
    let fill = solved.input.fill.as_ref();
    let (x_lo, x_hi) = corners
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    let road = fill.map(|(f, _, _)| [(x_hi, f.road), (x_lo, f.road)]);
    let mut canvas = fitted(assembly, loads, &corners, (road, solved.rolling.as_ref()));
    let mut legend: Legend = Vec::new();
    if let (Some(fill), Some(road)) = (fill, road) {
        parts::fill(&mut canvas, assembly, fill, road, &mut legend);
    }
    parts::blocks(&mut canvas, assembly, solved.input.is_curved);
    if let Some(mechanism) = mechanism {
        if assembly.blocks.len() <= MECHANISM_DRAWN_UP_TO {
            parts::mechanism(&mut canvas, assembly, mechanism, solved.input.is_curved);
        }
    }
    thrust_line(&mut canvas, solved);
    let hinge_count = parts::hinges_and_loads(&mut canvas, assembly, mechanism, loads);
    joints::passive(
        &mut canvas,
        &solved.input.problem,
        &solved.solution.passive,
        &mut legend,
    );
    joints::crushing(&mut canvas, assembly, mechanism, &mut legend);
    let dense = assembly.blocks.len() > MECHANISM_DRAWN_UP_TO;
    if !dense {
        joints::sliding(&mut canvas, assembly, mechanism, &mut legend);
    }
    complete_legend(&mut legend, solved, hinge_count, dense);
    for (colour, text) in &legend {
        canvas.key(text, colour, 11.0, false);
    }
    joints_key(&mut canvas, assembly);
    if let Some(curve) = &solved.rolling {
        rolling::rolling_curve(&mut canvas, curve);
    }
    crate::svg::study::panels(&mut canvas, &solved.studies, "λ");
    canvas.finish(title)
}

/// Draws the line of thrust: a chain's as a line, other assemblies' as points of action.
fn thrust_line(canvas: &mut Canvas, solved: &SolvedArch) {
    // A chain is drawn with its line of thrust; other assemblies block by block, with the
    // points of action at their contacts.
    let thrust: Vec<(f64, f64)> = solved
        .thrust_line
        .iter()
        .map(|t| t.point.unwrap_or((f64::NAN, f64::NAN)))
        .collect();
    if solved.input.problem.assembly().is_chain() {
        canvas.polyline(&thrust, "stroke=\"#c62828\" stroke-width=\"1.8\"");
    } else {
        canvas.dots(&thrust, 5.0, "#c62828");
    }
}

/// Adds the thrust line (first), hinges, mechanism (not drawn when `dense`) and loads to the key.
fn complete_legend(legend: &mut Legend, solved: &SolvedArch, hinge_count: usize, dense: bool) {
    let mechanism = solved.solution.mechanism.as_ref();
    if !solved.thrust_line.is_empty() {
        legend.insert(0, ("#c62828", "— line of thrust".into()));
    }
    if mechanism.is_some_and(|m| !m.hinges.is_empty()) {
        legend.push((
            "#1b5e20",
            if hinge_count > MAX_HINGE_LABELS {
                "● hinges (unlabelled: too many)"
            } else {
                "● hinges"
            }
            .into(),
        ));
    }
    if mechanism.is_some() {
        legend.push(match dense {
            true => (
                "#546e7a",
                "collapse mechanism and sliding joints not drawn: too many blocks".into(),
            ),
            false => ("#546e7a", "- - collapse mechanism".into()),
        });
    }
    if !solved.input.problem.live_loads().is_empty() {
        legend.push(("#1565c0", "→ live loads".into()));
    }
}
