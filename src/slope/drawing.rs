//! Drawing of a slope: the embankment, the slip circle and its centre, the slices, the line of
//! thrust, and for a search the map of F over the grid of centres with the critical centre.

use thrustline_solver::slope::Sliced;

use super::contours::{contour, refine};
use super::fills::{layer_fills, LAYER_COLOURS};
use super::report::SolvedSlope;
use crate::svg::{heat, Canvas};
use thrustline_solver::slope::analysis::{Analysed, PlacedCircle};

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
        // The centre with room above it for its label and the map around it.
        extent.push((c.centre.0, c.centre.1 + 0.15 * size));
        extent.push((c.centre.0, (c.centre.1 - c.radius).max(bottom)));
    }
    let lower_end = solved.search.as_ref().map_or((0.0, 0.0), |s| s.origin);
    // A map larger than the scene is cut at the axes: the picture stays on the slope and the
    // critical centre. Without a critical circle the whole grid is shown.
    if let (Some(grid), None) = (grid, scene.circle) {
        extent.extend(grid.xs.iter().flat_map(|&x| {
            grid.ys
                .iter()
                .map(move |&y| (lower_end.0 + x, lower_end.1 + y))
        }));
    }
    let visible = extent.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, p| [b[0].min(p.0), b[1].min(p.1), b[2].max(p.0), b[3].max(p.1)],
    );
    let mut canvas = Canvas::fitting(extent);
    // The F map of a search: one cell per grid point, coloured from the least F (red) up.
    if let Some(grid) = grid {
        canvas.clip_begin();
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
        // Contours F = F_min·(1.02, 1.05, 1.1, 1.2, 1.4, 1.7) on the grid refined 4 times per
        // cell (cubic), each labelled with its F at its rightmost point inside the grid (nested
        // contours spread their labels along x; the grid's edges crowd them).
        let absolute_xs: Vec<f64> = grid.xs.iter().map(|x| lower_end.0 + x).collect();
        let absolute_ys: Vec<f64> = grid.ys.iter().map(|y| lower_end.1 + y).collect();
        let (fine_xs, fine_ys, fine) = refine(&absolute_xs, &absolute_ys, &grid.factors, 4);
        let mut labelled = 0;
        for factor in [1.02, 1.05, 1.1, 1.2, 1.4, 1.7] {
            let level = lo * factor;
            let segments = contour(&fine_xs, &fine_ys, &fine, level);
            for segment in &segments {
                canvas.polyline(segment, "stroke=\"#4e342e\" stroke-width=\"0.8\"");
            }
            let (x_edge, y_edge) = (
                0.02 * (fine_xs[fine_xs.len() - 1] - fine_xs[0]).abs(),
                0.02 * (fine_ys[fine_ys.len() - 1] - fine_ys[0]).abs(),
            );
            // Inside the grid and inside the picture.
            let inside = |p: &(f64, f64)| {
                p.0 < fine_xs[fine_xs.len() - 1] - x_edge
                    && p.1 > fine_ys[0] + y_edge
                    && p.1 < fine_ys[fine_ys.len() - 1] - y_edge
                    && p.0 > visible[0]
                    && p.0 < visible[2] - 0.05 * (visible[2] - visible[0])
                    && p.1 > visible[1]
                    && p.1 < visible[3]
            };
            let top = segments
                .iter()
                .flatten()
                .copied()
                .filter(inside)
                .max_by(|a, b| a.0.total_cmp(&b.0));
            if let Some(top) = top {
                canvas.text(
                    top,
                    (3.0, -3.0),
                    &format!("{level:.3}"),
                    "font-size=\"9\" font-family=\"sans-serif\" fill=\"#4e342e\" stroke=\"#ffffff\" stroke-width=\"2\" paint-order=\"stroke\"",
                );
                labelled += 1;
            }
        }
        // The key names the refined critical circle's F, which the grid's least F bounds above.
        let critical = match (solution.factor_of_safety, scene.circle) {
            (Some(f), Some(c)) => format!(
                "; ● refined centre ({:.2}, {:.2}): F = {f:.4}",
                c.centre.0, c.centre.1
            ),
            _ => String::new(),
        };
        canvas.clip_end();
        canvas.key(
            &format!(
                "F over centres: red {lo:.3} (grid least) … blue ≥ {cap:.3}; {labelled} labelled \
                 contours{critical}"
            ),
            "#b71c1c",
            11.0,
            true,
        );
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
        let effective: Vec<(f64, f64)> = solution
            .effective_thrust_line
            .iter()
            .map(|t| match t.y {
                Some(y) if t.is_inside_slice => (solved.problem.request_x(t.x), y),
                _ => (f64::NAN, f64::NAN),
            })
            .collect();
        canvas.polyline(
            &effective,
            "stroke=\"#c62828\" stroke-width=\"1.2\" stroke-dasharray=\"5 3\"",
        );
        legend.push((
            "#c62828",
            "line of thrust of the effective forces (dashed; not drawn where it leaves its \
             slice)"
                .to_owned(),
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
    canvas.key(
        &format!("— line of thrust. {caption}"),
        "#c62828",
        12.0,
        true,
    );
    for (colour, label) in legend {
        canvas.key(&format!("— {label}"), colour, 11.0, true);
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
