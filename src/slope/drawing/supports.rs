//! The supports of a slope drawing: each as the segment from its head to its end, and where the
//! slip surface crosses it, the crossing and the force it puts on the sliding mass (an arrow
//! scaled to the largest force, labelled with its value per unit width).

use thrustline_solver::slope::analysis::Analysed;

use crate::svg::Canvas;

/// The supports' colour.
pub const COLOUR: &str = "#2e7d32";
/// Most force labels drawn (a dense pattern keeps its arrows, not its labels).
const MAX_LABELS: usize = 40;

/// The supports' heads and ends (the drawing's extent includes them).
pub fn ends(problem: &Analysed) -> Vec<(f64, f64)> {
    let Analysed::Section(p) = problem;
    p.section()
        .supports()
        .iter()
        .flat_map(|s| [s.head, s.end])
        .collect()
}

/// Draws the supports; answers the key's entry when there are any.
pub fn supports(canvas: &mut Canvas, problem: &Analysed, size: f64) -> Option<String> {
    let Analysed::Section(p) = problem;
    let given = p.section().supports();
    if given.is_empty() {
        return None;
    }
    let forces = p.supports();
    let segments: Vec<Vec<(f64, f64)>> = given.iter().map(|s| vec![s.head, s.end]).collect();
    canvas.path(
        &segments,
        false,
        &format!("stroke=\"{COLOUR}\" stroke-width=\"2\" fill=\"none\""),
    );
    let largest = forces.iter().map(|f| f.force).fold(0.0, f64::max);
    let crossed: Vec<_> = forces.iter().filter(|f| f.crossing.is_some()).collect();
    for (k, f) in crossed.iter().enumerate() {
        let Some(at) = f.crossing else { continue };
        canvas.dot(at, 3.0, &format!("fill=\"{COLOUR}\""));
        if f.force > 0.0 && largest > 0.0 {
            let length = 0.12 * size * f.force / largest;
            let tip = (at.0 + length * f.direction.0, at.1 + length * f.direction.1);
            canvas.arrow_in(at, tip, COLOUR, 1.6);
            if k < MAX_LABELS {
                canvas.text(
                    tip,
                    (4.0, -4.0),
                    &format!("{:.4}", f.force),
                    &format!("font-size=\"10\" fill=\"{COLOUR}\" font-family=\"sans-serif\""),
                );
            }
        }
    }
    let missed = forces.len() - crossed.len();
    let missed = if missed > 0 {
        format!("; {missed} not crossed by the surface")
    } else {
        String::new()
    };
    let labels = if crossed.len() > MAX_LABELS {
        format!(" (the first {MAX_LABELS} labelled)")
    } else {
        String::new()
    };
    Some(format!(
        "supports: ● where the surface crosses, → force per unit width{labels}{missed}"
    ))
}
