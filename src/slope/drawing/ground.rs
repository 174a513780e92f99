//! The ground of a slope drawing: the ground line continued level to the edges, each layer
//! in its colour, layer tops, bedrock and the water line, and the surcharges.

use thrustline_solver::slope::analysis::Analysed;

use super::super::fills::layer_fills;
use super::scene::Scene;
use crate::svg::Canvas;

/// The ground between `left` and `right` down to `bottom`; answers the key's entries.
pub fn ground(
    canvas: &mut Canvas,
    scene: &Scene,
    problem: &Analysed,
    [left, right, bottom]: [f64; 3],
    size: f64,
) -> Vec<(&'static str, String)> {
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
    let mut legend: Vec<(&'static str, String)> = Vec::new();
    layers(
        canvas,
        problem,
        left.min(first.0),
        right.max(last.0),
        bottom,
        &mut legend,
    );
    canvas.polyline(&outline, "stroke=\"#5d4037\" stroke-width=\"1.2\"");
    section_lines(canvas, scene, left, right, &mut legend);
    grid(canvas, scene, &mut legend);
    if !scene.loads.is_empty() {
        // Surcharges are drawn as boxes on the ground, line loads as their thin edge.
        legend.push(("#e65100", "surcharges and line loads".to_owned()));
    }
    loads(canvas, scene, size);
    legend
}

/// Draws each layer in its colour between `x_lo` and `x_hi` down to `bottom`, when named.
fn layers(
    canvas: &mut Canvas,
    problem: &Analysed,
    x_lo: f64,
    x_hi: f64,
    bottom: f64,
    legend: &mut Vec<(&'static str, String)>,
) {
    let Analysed::Section(p) = problem;
    {
        // Each layer in its colour, over the plain ground colour.
        let fills = layer_fills(p.section(), x_lo, x_hi, bottom);
        // One Mohr–Coulomb soil needs no key; other models, and a soil that does not drain in
        // a drawdown, are named.
        let named = p.section().layers().len() > 1
            || p.section().r_envelope(0).is_some()
            || p.section().layers().iter().any(|l| {
                !matches!(
                    l.strength,
                    thrustline_solver::slope::strength::Strength::MohrCoulomb
                )
            });
        for fill in fills.iter().filter(|_| named) {
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
}

/// Draws the layer tops, bedrock and the water line, continued level to `left` and `right`.
fn section_lines(
    canvas: &mut Canvas,
    scene: &Scene,
    left: f64,
    right: f64,
    legend: &mut Vec<(&'static str, String)>,
) {
    for (points, colour, label) in &scene.lines {
        let mut line = vec![(left.min(points[0].0), points[0].1)];
        line.extend(points.iter().copied());
        let end = points[points.len() - 1];
        line.push((right.max(end.0), end.1));
        let dash = if label.starts_with("piezometric line") {
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
}

/// Draws the surcharges as boxes `0.04·size` high on the ground, line loads as their edge.
fn loads(canvas: &mut Canvas, scene: &Scene, size: f64) {
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
}

/// A pore-pressure grid: its points and their hull, cut at the axes (a grid wider than the
/// scene does not move the picture).
fn grid(canvas: &mut Canvas, scene: &Scene, legend: &mut Vec<(&'static str, String)>) {
    if let Some((hull, points)) = &scene.grid {
        canvas.clip_begin();
        canvas.polyline(
            hull,
            "stroke=\"#0288d1\" stroke-width=\"0.8\" stroke-dasharray=\"2 3\"",
        );
        canvas.dots(points, 2.5, "#0288d1");
        canvas.clip_end();
        legend.push((
            "#0288d1",
            format!(
                "pore-pressure grid: {} points and their extent",
                points.len()
            ),
        ));
    }
}
