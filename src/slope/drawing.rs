//! Drawing of a slope: the embankment, the slip circle and its centre, the slices, the line of
//! thrust, and for a search the map of F over the grid of centres with the critical centre.

use thrustline_solver::slope::Sliced;

use super::analysed::{Analysed, PlacedCircle};
use super::fills::{layer_fills, LAYER_COLOURS};
use super::report::SolvedSlope;
use crate::svg::{escape, heat, Canvas};

/// What is drawn of the ground, in the request's coordinates.
struct Scene {
    /// The ground line (continued level to the edges of the picture).
    ground: Vec<(f64, f64)>,
    /// Layer tops, bedrock and the water line.
    lines: Vec<Line>,
    /// The slip surface.
    surface: Vec<(f64, f64)>,
    /// The slice sides, base to ground.
    sides: Vec<[(f64, f64); 2]>,
    /// The circle, if the surface is one.
    circle: Option<PlacedCircle>,
    /// Surcharges as (x_start, x_end) and line loads' x.
    loads: Vec<(f64, f64)>,
}

/// A line of the section: points, colour, label (empty: not in the legend).
type Line = (Vec<(f64, f64)>, &'static str, String);

fn scene(problem: &Analysed) -> Scene {
    let model = problem.model();
    let sides: Vec<[(f64, f64); 2]> = model
        .slices
        .iter()
        .skip(1)
        .map(|s| {
            let x = problem.request_x(s.x_left);
            [(x, s.base_left_y), (x, problem.ground_y(s.x_left))]
        })
        .collect();
    match problem {
        Analysed::Simple(p) => {
            let e = &p.geometry.embankment;
            Scene {
                ground: vec![(0.0, 0.0), (e.length(), e.height())],
                lines: Vec::new(),
                surface: problem.surface(),
                sides,
                circle: problem.circle(),
                loads: Vec::new(),
            }
        }
        Analysed::Section(p) => {
            let section = p.section();
            let mut lines = Vec::new();
            for (i, layer) in section.layers().iter().enumerate().skip(1) {
                if let Some(top) = &layer.top {
                    lines.push((
                        top.points().to_vec(),
                        LAYER_COLOURS[i % LAYER_COLOURS.len()],
                        // In the legend as the layer's fill.
                        String::new(),
                    ));
                }
            }
            if let Some(b) = section.bedrock() {
                lines.push((b.points().to_vec(), "#424242", "bedrock".to_owned()));
            }
            if let Some(w) = section.piezometric_line() {
                lines.push((
                    w.points().to_vec(),
                    "#0277bd",
                    "piezometric line".to_owned(),
                ));
            }
            let loads = section
                .surcharges()
                .iter()
                .map(|s| (s.x_start, s.x_end))
                .chain(section.line_loads().iter().map(|l| (l.x, l.x)))
                .collect();
            Scene {
                ground: section.ground().points().to_vec(),
                lines,
                surface: p.surface(),
                sides,
                circle: problem.circle(),
                loads,
            }
        }
    }
}

/// The drawing of a solved request (the analysed or critical surface) and its answer.
pub fn draw(solved: &SolvedSlope, title: &str) -> String {
    let scene = scene(&solved.problem);
    let solution = &solved.solution;
    let grid = solved.search.as_ref().map(|s| &s.grid);
    let ys = || {
        scene
            .ground
            .iter()
            .chain(&scene.surface)
            .chain(scene.lines.iter().flat_map(|l| &l.0))
            .map(|p| p.1)
    };
    let (y_lo, y_hi) = ys().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
        (a.min(y), b.max(y))
    });
    let xs = || scene.ground.iter().chain(&scene.surface).map(|p| p.0);
    let (x_lo, x_hi) = xs().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    });
    let size = (x_hi - x_lo).max(y_hi - y_lo).max(1e-9);
    let (left, right) = (x_lo - 0.3 * size, x_hi + 0.3 * size);
    let bottom = y_lo - 0.2 * size;
    let mut extent = vec![(left, bottom), (right, y_hi + 0.2 * size)];
    if let Some(c) = scene.circle {
        extent.push(c.centre);
        extent.push((c.centre.0, (c.centre.1 - c.radius).max(bottom)));
    }
    let lower_end = solved.search.as_ref().map_or((0.0, 0.0), |s| s.origin);
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
    // The ground, continued level to the edges.
    let first = scene.ground[0];
    let last = scene.ground[scene.ground.len() - 1];
    let mut ground: Vec<(f64, f64)> = vec![(left.min(first.0), first.1)];
    ground.extend(scene.ground.iter().copied());
    ground.push((right.max(last.0), last.1));
    let outline = ground.clone();
    ground.push((right.max(last.0), bottom));
    ground.push((left.min(first.0), bottom));
    canvas.polygon(&ground, "fill=\"#d7ccc8\" stroke=\"none\"");
    let mut legend: Vec<(&str, String)> = Vec::new();
    if let Analysed::Section(p) = &solved.problem {
        // Each layer in its colour, over the plain ground colour.
        let fills = layer_fills(p.section(), left.min(first.0), right.max(last.0), bottom);
        for fill in fills.iter().filter(|_| p.section().layers().len() > 1) {
            canvas.polygon(
                &fill.polygon,
                &format!(
                    "fill=\"{}\" fill-opacity=\"0.18\" stroke=\"none\"",
                    fill.colour
                ),
            );
            legend.push((fill.colour, fill.label.clone()));
        }
    }
    canvas.polyline(&outline, "stroke=\"#5d4037\" stroke-width=\"1.2\"");
    for (points, colour, label) in &scene.lines {
        let mut line = vec![(left.min(points[0].0), points[0].1)];
        line.extend(points.iter().copied());
        let end = points[points.len() - 1];
        line.push((right.max(end.0), end.1));
        let dash = if label == "piezometric line" {
            " stroke-dasharray=\"6 3\""
        } else {
            ""
        };
        canvas.polyline(
            &line,
            &format!("stroke=\"{colour}\" stroke-width=\"1.2\"{dash}"),
        );
        if !label.is_empty() {
            legend.push((*colour, label.clone()));
        }
    }
    for (a, b) in &scene.loads {
        let y = |x: f64| {
            let i = scene.ground.partition_point(|p| p.0 < x);
            match (
                i.checked_sub(1).map(|k| scene.ground[k]),
                scene.ground.get(i),
            ) {
                (Some(p), Some(q)) => p.1 + (q.1 - p.1) * (x - p.0) / (q.0 - p.0),
                (None, Some(q)) => q.1,
                (Some(p), None) => p.1,
                (None, None) => 0.0,
            }
        };
        let h = 0.04 * size;
        canvas.polyline(
            &[
                (*a, y(*a) + h),
                (*a, y(*a)),
                (*b, y(*b)),
                (*b, y(*b) + h),
                (*a, y(*a) + h),
            ],
            "stroke=\"#e65100\" stroke-width=\"1.2\"",
        );
    }
    // The slices and the slip surface.
    for side in &scene.sides {
        canvas.polyline(side, "stroke=\"#8d6e63\" stroke-width=\"0.4\"");
    }
    canvas.polyline(&scene.surface, "stroke=\"#212121\" stroke-width=\"1.8\"");
    // The circle's centre and two radii to the ends of the slip surface.
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
            (8.0, -6.0),
            &format!("centre, R = {radius:.3}"),
            "font-size=\"11\" font-family=\"sans-serif\" fill=\"#212121\"",
        );
    }
    // The line of thrust on the slice boundaries, broken where a point leaves its slice (an
    // inter-slice force near zero puts it anywhere): those points are marked with a ring.
    let thrust: Vec<(f64, f64)> = solution
        .thrust_line
        .iter()
        .map(|t| match t.y {
            Some(y) if t.is_inside_slice => (solved.problem.request_x(t.x), y),
            _ => (f64::NAN, f64::NAN),
        })
        .collect();
    canvas.polyline(&thrust, "stroke=\"#c62828\" stroke-width=\"1.6\"");
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
    let has_water = solution
        .thrust_line
        .iter()
        .zip(&solution.effective_thrust_line)
        .any(|(t, e)| t.y != e.y);
    if has_water {
        let effective: Vec<(f64, f64)> = solution
            .effective_thrust_line
            .iter()
            .map(|t| (solved.problem.request_x(t.x), t.y.unwrap_or(f64::NAN)))
            .collect();
        canvas.polyline(
            &effective,
            "stroke=\"#c62828\" stroke-width=\"1.2\" stroke-dasharray=\"5 3\"",
        );
        legend.push((
            "#c62828",
            "line of thrust of the effective forces (dashed)".to_owned(),
        ));
    }
    let caption = match (solution.factor_of_safety, solution.theta_rad) {
        (Some(f), Some(theta)) => {
            let bishop = solution
                .bishop_factor_of_safety
                .filter(|b| b.is_finite())
                .map_or(String::new(), |b| format!("; Bishop {b:.4}"));
            format!(
                "F = {f:.4}, θ = {:.2}° (Spencer){bishop}",
                theta.to_degrees()
            )
        }
        _ => "no solution for this slip surface".to_owned(),
    };
    let mut y = if grid.is_some() { 58 } else { 44 };
    canvas.raw(&format!(
        "<text x=\"60\" y=\"{y}\" font-size=\"12\" font-family=\"sans-serif\" fill=\"#c62828\">— line of thrust. {}</text>",
        escape(&caption)
    ));
    for (colour, label) in legend {
        y += 14;
        canvas.raw(&format!(
            "<text x=\"60\" y=\"{y}\" font-size=\"11\" font-family=\"sans-serif\" fill=\"{colour}\">— {}</text>",
            escape(&label)
        ));
    }
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
