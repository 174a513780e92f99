//! What a slope drawing shows of the ground, in the request's coordinates: the ground line,
//! the section's lines, the slip surface and its slices, loads and a pore-pressure grid.

use thrustline_solver::slope::analysis::{Analysed, PlacedCircle};
use thrustline_solver::slope::Sliced;

use super::super::fills::LAYER_COLOURS;

/// What is drawn of the ground, in the request's coordinates.
pub struct Scene {
    /// The ground line (continued level to the edges of the picture).
    pub ground: Vec<(f64, f64)>,
    /// Layer tops, bedrock and the water line.
    pub lines: Vec<Line>,
    /// The slip surface.
    pub surface: Vec<(f64, f64)>,
    /// The slice sides, base to ground.
    pub sides: Vec<[(f64, f64); 2]>,
    /// The circle, if the surface is one.
    pub circle: Option<PlacedCircle>,
    /// Surcharges as (x_start, x_end) and line loads' x.
    pub loads: Vec<(f64, f64)>,
    /// A pore-pressure grid: its hull (closed) and its points.
    pub grid: Option<(Points, Points)>,
}

/// Points in the request's coordinates.
pub type Points = Vec<(f64, f64)>;

/// A line of the section: points, colour, label (empty: not in the legend).
pub type Line = (Vec<(f64, f64)>, &'static str, String);

/// The scene of an analysed surface.
pub fn scene(problem: &Analysed) -> Scene {
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
