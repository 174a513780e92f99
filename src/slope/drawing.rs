//! Drawing of a slope: the embankment, the slip circle and its centre, the slices, the line of
//! thrust, and for a search the map of F over the grid of centres with the critical centre.

use super::response::SolvedSlope;
use crate::svg::{escape, heat, Canvas};

/// The drawing of a solved request (the analysed or critical circle) and its answer.
pub fn draw(solved: &SolvedSlope, title: &str) -> String {
    let g = &solved.problem.geometry;
    let solution = &solved.solution;
    let grid = solved.search.as_ref().map(|s| &s.grid);
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
    let grid_centres: Vec<(f64, f64)> = grid
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
    if let Some(grid) = grid {
        let values: Vec<f64> = grid.factors.iter().flatten().flatten().copied().collect();
        let (lo, hi) = values
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(*v), b.max(*v))
            });
        let cap = lo + (hi - lo).min(2.0 * lo.max(1e-9));
        let (dx, dy) = (cell(&grid.xs), cell(&grid.ys));
        for (j, row) in grid.factors.iter().enumerate() {
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
        // Contours F = F_min·(1.02, 1.05, 1.1, 1.2, 1.4, 1.7), by marching squares.
        let absolute_xs: Vec<f64> = grid.xs.iter().map(|x| lower_end.0 + x).collect();
        let absolute_ys: Vec<f64> = grid.ys.iter().map(|y| lower_end.1 + y).collect();
        for factor in [1.02, 1.05, 1.1, 1.2, 1.4, 1.7] {
            let level = lo * factor;
            for segment in contour(&absolute_xs, &absolute_ys, &grid.factors, level) {
                canvas.polyline(&segment, "stroke=\"#4e342e\" stroke-width=\"0.8\"");
            }
        }
        canvas.raw(&format!(
            "<text x=\"60\" y=\"44\" font-size=\"11\" font-family=\"sans-serif\" fill=\"#b71c1c\">F over centres: red {lo:.3} … blue ≥ {cap:.3}; contours F_min × 1.02 … 1.7; blank: no valid circle</text>"
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
    let thrust: Vec<(f64, f64)> = solution
        .thrust_line
        .iter()
        .map(|t| (t.x, t.y.unwrap_or(f64::NAN)))
        .collect();
    canvas.polyline(&thrust, "stroke=\"#c62828\" stroke-width=\"1.6\"");
    let caption = match (solution.factor_of_safety, solution.theta_rad) {
        (Some(f), Some(theta)) => format!(
            "F = {f:.4}, θ = {:.2}° (Spencer); Bishop {:.4}",
            theta.to_degrees(),
            solution.bishop_factor_of_safety.unwrap_or(f64::NAN)
        ),
        _ => "no solution for this circle".to_owned(),
    };
    canvas.raw(&format!(
        "<text x=\"60\" y=\"{}\" font-size=\"12\" font-family=\"sans-serif\" fill=\"#c62828\">— line of thrust. {}</text>",
        if grid.is_some() { 58 } else { 44 },
        escape(&caption)
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

/// The segments of the contour `level` of the values `f[j][i]` at (xs[i], ys[j]) (marching
/// squares; cells with a missing corner are skipped).
pub fn contour(xs: &[f64], ys: &[f64], f: &[Vec<Option<f64>>], level: f64) -> Vec<[(f64, f64); 2]> {
    let mut segments = Vec::new();
    for j in 0..ys.len().saturating_sub(1) {
        for i in 0..xs.len().saturating_sub(1) {
            let corners = [
                ((xs[i], ys[j]), f[j][i]),
                ((xs[i + 1], ys[j]), f[j][i + 1]),
                ((xs[i + 1], ys[j + 1]), f[j + 1][i + 1]),
                ((xs[i], ys[j + 1]), f[j + 1][i]),
            ];
            let Some(values) = corners.iter().map(|c| c.1).collect::<Option<Vec<f64>>>() else {
                continue;
            };
            // Crossing points on the four edges, in order.
            let mut crossings = Vec::with_capacity(4);
            for k in 0..4 {
                let (a, b) = (k, (k + 1) % 4);
                let (va, vb) = (values[a] - level, values[b] - level);
                if (va < 0.0) != (vb < 0.0) {
                    let t = va / (va - vb);
                    let (pa, pb) = (corners[a].0, corners[b].0);
                    crossings.push((pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1)));
                }
            }
            // Two crossings: one segment; four (a saddle): two, pairing neighbours.
            for pair in crossings.chunks_exact(2) {
                segments.push([pair[0], pair[1]]);
            }
        }
    }
    segments
}

#[cfg(test)]
mod tests {
    use super::contour;

    #[test]
    fn contour_of_a_cone_is_a_ring_at_the_right_radius() {
        // f = distance from the origin on a 41 × 41 grid: the level-1 contour lies on the unit
        // circle up to the linear interpolation error (h²/8 with h = 0.1: 2e-3).
        let axis: Vec<f64> = (0..41).map(|i| -2.0 + 0.1 * f64::from(i)).collect();
        let f: Vec<Vec<Option<f64>>> = axis
            .iter()
            .map(|&y| axis.iter().map(|&x| Some(x.hypot(y))).collect())
            .collect();
        let segments = contour(&axis, &axis, &f, 1.0);
        assert!(segments.len() > 40);
        for [a, b] in segments {
            for p in [a, b] {
                assert!((p.0.hypot(p.1) - 1.0).abs() < 5e-3, "{p:?}");
            }
        }
    }
}
