//! Drawing of a slope: the embankment, the slip circle and its centre, the slices, the line of
//! thrust, and for a search the map of F over the grid of centres with the critical centre.

use thrustline_solver::slope::SlopeProblem;

use super::{heat, Canvas};
use crate::slope::SpencerResponse;

/// The drawing of `problem` (the analysed or critical circle) and its answer.
pub fn draw(problem: &SlopeProblem, response: &SpencerResponse, title: &str) -> String {
    let g = &problem.geometry;
    let e = &g.embankment;
    let (h, l) = (e.height(), e.length());
    let left = g.lower_end.0.min(0.0) - 0.3 * (l + h);
    let right = g.upper_exit.0.max(l) + 0.3 * (l + h);
    let mut extent = vec![
        (left, -0.2 * h),
        (right, h * 1.2),
        g.centre,
        (g.centre.0, g.centre.1 - g.radius),
    ];
    let lower_end = g.lower_end;
    let grid_centres: Vec<(f64, f64)> = response
        .grid
        .as_ref()
        .map(|grid| {
            grid.xs
                .iter()
                .flat_map(|&x| {
                    grid.ys
                        .iter()
                        .map(move |&y| (lower_end.0 + x, lower_end.1 + y))
                })
                .collect()
        })
        .unwrap_or_default();
    extent.extend(grid_centres.iter().copied());
    let mut canvas = Canvas::fitting(extent);
    // The F map of a search: one cell per grid point, coloured from the least F (red) up.
    if let Some(grid) = &response.grid {
        let values: Vec<f64> = grid
            .factor_of_safety
            .iter()
            .flatten()
            .flatten()
            .copied()
            .collect();
        let (lo, hi) = values
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(*v), b.max(*v))
            });
        let cap = lo + (hi - lo).min(2.0 * lo.max(1e-9));
        let (dx, dy) = (cell(&grid.xs), cell(&grid.ys));
        for (j, row) in grid.factor_of_safety.iter().enumerate() {
            for (i, f) in row.iter().enumerate() {
                let Some(f) = f else { continue };
                let t = 1.0 - ((f - lo) / (cap - lo).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
                let (x, y) = (lower_end.0 + grid.xs[i], lower_end.1 + grid.ys[j]);
                let corners = [
                    (x - dx / 2.0, y - dy / 2.0),
                    (x + dx / 2.0, y - dy / 2.0),
                    (x + dx / 2.0, y + dy / 2.0),
                    (x - dx / 2.0, y + dy / 2.0),
                ];
                canvas.polygon(
                    &corners,
                    &format!("fill=\"{}\" fill-opacity=\"0.55\" stroke=\"none\"", heat(t)),
                );
            }
        }
        canvas.raw(&format!(
            "<text x=\"60\" y=\"44\" font-size=\"11\" font-family=\"sans-serif\" fill=\"#b71c1c\">F map over centres: red F = {lo:.3} … blue F ≥ {cap:.3}; blank: no valid circle</text>"
        ));
    }
    // The embankment.
    let ground = [
        (left, 0.0),
        (0.0, 0.0),
        (l, h),
        (right, h),
        (right, -0.2 * h),
        (left, -0.2 * h),
    ];
    canvas.polygon(
        &ground,
        "fill=\"#d7ccc8\" stroke=\"#5d4037\" stroke-width=\"1.2\"",
    );
    // The slices and the slip surface (their base chords).
    for s in &g.slices {
        canvas.polyline(
            &[(s.x_left, s.base_left_y), (s.x_left, e.ground(s.x_left))],
            "stroke=\"#8d6e63\" stroke-width=\"0.4\"",
        );
    }
    let base: Vec<(f64, f64)> = std::iter::once(g.lower_end)
        .chain(g.slices.iter().map(|s| (s.x_right, s.base_right_y)))
        .collect();
    canvas.polyline(&base, "stroke=\"#212121\" stroke-width=\"1.8\"");
    // The circle's centre and two radii to the ends of the slip surface.
    canvas.polyline(
        &[g.lower_end, g.centre, g.upper_exit],
        "stroke=\"#9e9e9e\" stroke-width=\"0.6\" stroke-dasharray=\"4 3\"",
    );
    canvas.dot(g.centre, 4.0, "fill=\"#212121\"");
    canvas.text(
        g.centre,
        (8.0, -6.0),
        &format!("centre, R = {:.3}", g.radius),
        "font-size=\"11\" font-family=\"sans-serif\" fill=\"#212121\"",
    );
    // The line of thrust on the slice boundaries.
    let thrust: Vec<(f64, f64)> = response
        .thrust_line
        .iter()
        .map(|t| (t.x, t.y.unwrap_or(f64::NAN)))
        .collect();
    canvas.polyline(&thrust, "stroke=\"#c62828\" stroke-width=\"1.6\"");
    let caption = match (response.factor_of_safety, response.theta_deg) {
        (Some(f), Some(t)) => format!(
            "F = {f:.4}, θ = {t:.2}° (Spencer); Bishop {:.4}",
            response.bishop_factor_of_safety.unwrap_or(f64::NAN)
        ),
        _ => "no solution for this circle".to_owned(),
    };
    canvas.raw(&format!(
        "<text x=\"60\" y=\"{}\" font-size=\"12\" font-family=\"sans-serif\" fill=\"#c62828\">— line of thrust. {}</text>",
        if response.grid.is_some() { 58 } else { 44 },
        super::escape(&caption)
    ));
    canvas.finish(title)
}

fn cell(values: &[f64]) -> f64 {
    if values.len() < 2 {
        1.0
    } else {
        (values[values.len() - 1] - values[0]) / (values.len() - 1) as f64
    }
}
