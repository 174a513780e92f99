//! The slip surface of a slope drawing: the slices, the surface, a circle's centre and radii,
//! and the lines of thrust (total, and effective where pore water moves it).

use thrustline_solver::slope::analysis::PlacedCircle;
use thrustline_solver::slope::ThrustPoint;

use super::super::solved::SolvedSlope;
use super::scene::Scene;
use crate::svg::Canvas;

/// The slices, the surface, the centre and the lines of thrust; the key's entries go to
/// `legend`.
pub fn surface(
    canvas: &mut Canvas,
    scene: &Scene,
    solved: &SolvedSlope,
    size: f64,
    legend: &mut Vec<(&'static str, String)>,
) {
    let solution = &solved.solution;
    // The slices and the slip surface.
    for side in &scene.sides {
        canvas.polyline(side, "stroke=\"#8d6e63\" stroke-width=\"0.4\"");
    }
    canvas.polyline(&scene.surface, "stroke=\"#212121\" stroke-width=\"1.8\"");
    circle(canvas, scene);
    // The line of thrust on the slice boundaries, broken where a point leaves its slice (an
    // inter-slice force near zero puts it anywhere): those points are marked with a ring.
    canvas.polyline(
        &drawn(solved, &solution.thrust_line),
        "stroke=\"#c62828\" stroke-width=\"1.6\"",
    );
    outside_marks(canvas, solved, legend);
    // Pore water moves the effective line off the total one by more than rounding.
    let has_water = solution
        .thrust_line
        .iter()
        .zip(&solution.effective_thrust_line)
        .any(|(t, e)| match (t.y, e.y) {
            (Some(a), Some(b)) => (a - b).abs() > 1e-9 * size,
            (a, b) => a.is_some() != b.is_some(),
        });
    if has_water {
        // Broken where it leaves its slice, like the total one.
        canvas.polyline(
            &drawn(solved, &solution.effective_thrust_line),
            "stroke=\"#c62828\" stroke-width=\"1.2\" stroke-dasharray=\"5 3\"",
        );
        legend.push((
            "#c62828",
            "line of thrust of the effective forces (dashed; not drawn where it leaves its \
             slice)"
                .to_owned(),
        ));
    }
}

/// Draws a circle's centre, labelled with its radius, and two radii to the surface's ends.
fn circle(canvas: &mut Canvas, scene: &Scene) {
    if let Some(PlacedCircle {
        centre,
        radius,
        lower_end,
        upper_exit,
    }) = scene.circle
    {
        canvas.polyline(
            &[lower_end, centre, upper_exit],
            "stroke=\"#9e9e9e\" stroke-width=\"0.6\" stroke-dasharray=\"4 3\"",
        );
        canvas.dot(centre, 4.0, "fill=\"#212121\"");
        canvas.text(
            centre,
            CENTRE_LABEL_OFFSET,
            &centre_label(radius),
            "font-size=\"11\" font-family=\"sans-serif\" fill=\"#212121\"",
        );
    }
}

/// A line of thrust in the request's coordinates, broken (NaN) where a point leaves its slice.
fn drawn(solved: &SolvedSlope, line: &[ThrustPoint]) -> Vec<(f64, f64)> {
    line.iter()
        .map(|t| match t.y {
            Some(y) if t.is_inside_slice => (solved.problem.request_x(t.x), y),
            _ => (f64::NAN, f64::NAN),
        })
        .collect()
}

/// Rings the boundaries where the line of thrust leaves its slice, at the ground, and keys them.
fn outside_marks(
    canvas: &mut Canvas,
    solved: &SolvedSlope,
    legend: &mut Vec<(&'static str, String)>,
) {
    let solution = &solved.solution;
    let outside = solution
        .thrust_line
        .iter()
        .filter(|t| !t.is_inside_slice)
        .count();
    if outside > 0 {
        for t in solution.thrust_line.iter().filter(|t| !t.is_inside_slice) {
            // At the ground on that boundary: where the line would leave the mass.
            let x = solved.problem.request_x(t.x);
            canvas.dot(
                (x, solved.problem.ground_y(t.x)),
                3.0,
                "fill=\"none\" stroke=\"#c62828\" stroke-width=\"1\"",
            );
        }
        legend.push((
            "#c62828",
            format!("○ {outside} boundaries where the line of thrust leaves its slice (not drawn)"),
        ));
    }
}

/// Where the centre's label starts, from the centre (pixels).
const CENTRE_LABEL_OFFSET: (f64, f64) = (8.0, -6.0);

/// The label of a circle's centre.
fn centre_label(radius: f64) -> String {
    format!("centre, R = {radius:.3}")
}

/// The pixel box of the centre's dot and label (11 px, 0.6 em a character, padded by 1 px),
/// for the map's contour labels to keep clear of.
pub fn centre_label_box(canvas: &Canvas, centre: (f64, f64), radius: f64) -> [f64; 4] {
    let (x, y) = canvas.px(centre);
    let chars = centre_label(radius).chars().count() as f64;
    [
        x - 5.0,
        y + CENTRE_LABEL_OFFSET.1 - 11.0 - 1.0,
        x + CENTRE_LABEL_OFFSET.0 + 0.6 * 11.0 * chars + 1.0,
        y + 5.0,
    ]
}
