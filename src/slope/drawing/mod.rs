//! Drawing of a slope: the embankment, the slip circle and its centre, the slices, the line of
//! thrust, and for a search the map of F over the grid of centres with the critical centre.

mod ground;
mod map;
mod supports;
mod thrust;

mod scene;

use super::solved::SolvedSlope;
use crate::svg::Canvas;
use scene::{scene, Scene};

/// The drawing's title: which surface it shows (a search's critical one is a circle, or a
/// non-circular surface).
pub fn title(solved: &SolvedSlope) -> &'static str {
    match (solved.search.is_some(), solved.problem.circle().is_some()) {
        (true, true) => "Spencer's method: the critical slip circle",
        (true, false) => "Spencer's method: the critical slip surface",
        (false, true) => "Spencer's method: one slip circle",
        (false, false) => "Spencer's method: one slip surface",
    }
}

/// The drawing of a solved request (the analysed or critical surface) and its answer.
pub fn draw(solved: &SolvedSlope, title: &str) -> String {
    let scene = scene(&solved.problem);
    let frame = frame(&scene);
    let lower_end = solved.search.as_ref().map_or((0.0, 0.0), |s| s.origin);
    let extent = extent(solved, &scene, &frame, lower_end);
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
    factor_map(&mut canvas, solved, &scene, lower_end, visible);
    let size = frame.size;
    let mut legend = ground::ground(
        &mut canvas,
        &scene,
        &solved.problem,
        [frame.left, frame.right, frame.bottom],
        size,
    );
    thrust::surface(&mut canvas, &scene, solved, size, &mut legend);
    let supports = supports::supports(&mut canvas, &solved.problem, size);
    key(&mut canvas, solved, legend, supports);
    crate::svg::study::panels(&mut canvas, &solved.studies, "F");
    canvas.finish(title)
}

/// The picture's edges around the scene, and its size.
struct Frame {
    /// The scene's larger extent (at least 1e-9): what margins and marks scale with.
    size: f64,
    /// The picture's left edge, 0.3·size left of the scene.
    left: f64,
    /// Its right edge, 0.3·size right of the scene.
    right: f64,
    /// Its bottom, 0.2·size below the scene.
    bottom: f64,
    /// Its top, 0.2·size above the scene.
    top: f64,
}

/// The frame of the scene: its ground, slip surface and lines, with margins.
fn frame(scene: &Scene) -> Frame {
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
    Frame {
        size,
        left,
        right,
        bottom,
        top: y_hi + 0.2 * size,
    }
}

/// The points the canvas holds: the frame, the supports, the circle's centre, or the grid.
fn extent(
    solved: &SolvedSlope,
    scene: &Scene,
    frame: &Frame,
    lower_end: (f64, f64),
) -> Vec<(f64, f64)> {
    let Frame {
        size,
        left,
        right,
        bottom,
        top,
    } = *frame;
    let mut extent = vec![(left, bottom), (right, top)];
    extent.extend(supports::ends(&solved.problem));
    if let Some(c) = scene.circle {
        // The centre with room above it for its label and the map around it.
        extent.push((c.centre.0, c.centre.1 + 0.15 * size));
        extent.push((c.centre.0, (c.centre.1 - c.radius).max(bottom)));
    }
    let grid = solved.search.as_ref().map(|s| &s.grid);
    // A map larger than the scene is cut at the axes: the picture stays on the slope and the
    // critical centre. Without a critical circle the whole grid is shown.
    if let (Some(grid), None) = (grid, scene.circle) {
        extent.extend(grid.xs.iter().flat_map(|&x| {
            grid.ys
                .iter()
                .map(move |&y| (lower_end.0 + x, lower_end.1 + y))
        }));
    }
    extent
}

/// Draws a search's F map over the grid of centres, clear of the centre's label.
fn factor_map(
    canvas: &mut Canvas,
    solved: &SolvedSlope,
    scene: &Scene,
    lower_end: (f64, f64),
    visible: [f64; 4],
) {
    // The F map of a search; the key names the refined critical circle's F, which the grid's
    // least F bounds above.
    if let Some(grid) = solved.search.as_ref().map(|s| &s.grid) {
        let critical = match (solved.solution.factor_of_safety, scene.circle) {
            (Some(f), Some(c)) => format!(
                "; ● refined centre ({:.2}, {:.2}): F = {f:.4}",
                c.centre.0, c.centre.1
            ),
            _ => String::new(),
        };
        let reserved: Vec<[f64; 4]> = scene
            .circle
            .iter()
            .map(|c| thrust::centre_label_box(canvas, c.centre, c.radius))
            .collect();
        map::factor_map(canvas, grid, lower_end, visible, critical, &reserved);
    }
}

/// Draws the key: the line of thrust with F, the ground's `legend`, the supports, the design.
fn key(
    canvas: &mut Canvas,
    solved: &SolvedSlope,
    legend: Vec<(&'static str, String)>,
    supports: Option<String>,
) {
    canvas.key(
        &format!("— line of thrust. {}", caption(&solved.solution)),
        "#c62828",
        12.0,
        true,
    );
    for (colour, label) in legend {
        canvas.key(&format!("— {label}"), colour, 11.0, true);
    }
    if let Some(label) = supports {
        canvas.key(&format!("— {label}"), supports::COLOUR, 11.0, true);
    }
    if let Some(verdict) = &solved.design {
        canvas.key(&design_caption(verdict), "#37474f", 11.0, true);
    }
}

/// F and θ in the key, Bishop's F beside.
fn caption(solution: &thrustline_solver::slope::SpencerSolution) -> String {
    match (solution.factor_of_safety, solution.theta_rad) {
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
    }
}

/// A design check in the key: the approach, its factors, the over-design factor.
fn design_caption(verdict: &thrustline_solver::slope::design::Verdict) -> String {
    use thrustline_solver::slope::design::Approach;
    let f = &verdict.design.factors;
    let approach = match verdict.design.approach {
        Approach::Da1Combination1 => "EN 1997-1 DA1-1",
        Approach::Da1Combination2 => "EN 1997-1 DA1-2",
        Approach::Da2 => "EN 1997-1 DA2",
        Approach::Da3 => "EN 1997-1 DA3",
        Approach::Custom => "partial factors",
    };
    let odf = verdict.over_design_factor.map_or("none".to_owned(), |v| {
        format!(
            "{v:.3} ({})",
            if verdict.verified {
                "verified"
            } else {
                "not verified"
            }
        )
    });
    format!(
        "{approach}, on design values: γ_φ {} γ_c {} γ_cu {} γ_γ {} γ_G {} γ_Q {} γ_R {}; \
         over-design factor {odf}",
        f.friction, f.cohesion, f.undrained, f.unit_weight, f.permanent, f.variable, f.resistance
    )
}
