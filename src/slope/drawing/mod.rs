//! Drawing of a slope: the embankment, the slip circle and its centre, the slices, the line of
//! thrust, and for a search the map of F over the grid of centres with the critical centre.

mod ground;
mod map;
mod supports;
mod thrust;

use thrustline_solver::slope::Sliced;

use super::fills::LAYER_COLOURS;
use super::solved::SolvedSlope;
use crate::svg::Canvas;
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
    /// A pore-pressure grid: its hull (closed) and its points.
    grid: Option<(Points, Points)>,
}

/// Points in the request's coordinates.
type Points = Vec<(f64, f64)>;

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
        Analysed::Section(p) => {
            let section = p.section();
            let lines = section_lines(section);
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
                grid: section.water().grid.as_ref().map(|g| {
                    let points: Vec<(f64, f64)> = g.points().iter().map(|p| (p.0, p.1)).collect();
                    (hull(&points), points)
                }),
            }
        }
    }
}

/// The section's lines: layer tops, bedrock, the water lines.
fn section_lines(section: &thrustline_solver::slope::section::Section) -> Vec<Line> {
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
    if let Some(before) = section.drawdown_before() {
        let label = "piezometric line before the drawdown".to_owned();
        lines.push((before.points().to_vec(), "#80d8ff", label));
    }
    if let Some(w) = section.piezometric_line() {
        let after = match section.drawdown_before() {
            Some(_) => " after the drawdown",
            None => "",
        };
        let label = format!("piezometric line{after}{}", hu(section.water().hu));
        lines.push((w.points().to_vec(), "#0277bd", label));
    }
    for (i, layer) in section.layers().iter().enumerate() {
        if let Some(w) = &layer.piezometric_line {
            let label = format!("piezometric line of layer {}{}", i + 1, hu(w.hu));
            lines.push((w.line.points().to_vec(), "#01579b", label));
        }
    }
    lines
}

/// A line's h_u as its key names it (nothing for the full head).
fn hu(hu: thrustline_solver::slope::section::Hu) -> String {
    use thrustline_solver::slope::section::Hu;
    match hu {
        Hu::Factor(1.0) => String::new(),
        Hu::Factor(h) => format!(" (h_u = {h})"),
        Hu::Auto => " (h_u = cos²α)".to_owned(),
    }
}

/// The convex hull of `points`, closed (Andrew's monotone chain).
fn hull(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut p = points.to_vec();
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let mut chain: Vec<(f64, f64)> = Vec::with_capacity(2 * p.len() + 1);
    for pass in [p.clone(), p.into_iter().rev().collect()] {
        let start = chain.len();
        for q in pass {
            while chain.len() >= start + 2
                && cross(chain[chain.len() - 2], chain[chain.len() - 1], q) <= 0.0
            {
                chain.pop();
            }
            chain.push(q);
        }
        chain.pop();
    }
    if let Some(&first) = chain.first() {
        chain.push(first);
    }
    chain
}

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
    extent.extend(supports::ends(&solved.problem));
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
    // The F map of a search; the key names the refined critical circle's F, which the grid's
    // least F bounds above.
    if let Some(grid) = grid {
        let critical = match (solution.factor_of_safety, scene.circle) {
            (Some(f), Some(c)) => format!(
                "; ● refined centre ({:.2}, {:.2}): F = {f:.4}",
                c.centre.0, c.centre.1
            ),
            _ => String::new(),
        };
        let reserved: Vec<[f64; 4]> = scene
            .circle
            .iter()
            .map(|c| thrust::centre_label_box(&canvas, c.centre, c.radius))
            .collect();
        map::factor_map(&mut canvas, grid, (lower_end, visible), critical, &reserved);
    }
    let mut legend = ground::ground(
        &mut canvas,
        &scene,
        &solved.problem,
        [left, right, bottom],
        size,
    );
    thrust::surface(&mut canvas, &scene, solved, size, &mut legend);
    let supports = supports::supports(&mut canvas, &solved.problem, size);
    canvas.key(
        &format!("— line of thrust. {}", caption(solution)),
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
    crate::svg::study::panels(&mut canvas, &solved.studies, "F");
    canvas.finish(title)
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
