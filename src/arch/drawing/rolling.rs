//! The rolling-load curve drawn under a bridge: λ against the position of the load, the
//! critical stop marked.

use crate::arch::rolling::RollingOutDto;
use crate::svg::{Canvas, WIDTH};

/// λ against the position of a rolling load, in a band under the arch, the critical stop
/// marked.
pub fn rolling_curve(canvas: &mut Canvas, curve: &RollingOutDto) {
    let points: Vec<(f64, f64)> = curve
        .positions
        .iter()
        .zip(&curve.load_factor)
        .filter_map(|(&x, l)| l.map(|l| (x, l)))
        .collect();
    if points.is_empty() {
        return;
    }
    let (height, left, right) = (150.0, 60.0, WIDTH - 60.0);
    let top = canvas.band_below(height + 40.0) + 20.0;
    let (x0, x1) = (
        curve.positions[0],
        curve.positions[curve.positions.len() - 1],
    );
    let l1 = points.iter().fold(0.0f64, |m, p| m.max(p.1)) * 1.05;
    let px = |(x, l): (f64, f64)| {
        let u = if x1 > x0 { (x - x0) / (x1 - x0) } else { 0.5 };
        let v = if l1 > 0.0 { l / l1 } else { 0.0 };
        (left + u * (right - left), top + height - v * height)
    };
    let path: Vec<String> = points
        .iter()
        .map(|&p| {
            let (x, y) = px(p);
            format!("{x:.2},{y:.2}")
        })
        .collect();
    let mut svg = format!(
        "<g font-size=\"11\" font-family=\"sans-serif\"><rect x=\"{left}\" y=\"{top:.2}\" width=\"{:.2}\" height=\"{height}\" fill=\"none\" stroke=\"#999\"/>\
         <polyline points=\"{}\" fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.6\"/>\
         <text x=\"{left}\" y=\"{:.2}\" fill=\"#333\">rolling load: λ against position (x from {} to {}; top of the box λ = {:.3})</text>",
        right - left,
        path.join(" "),
        top - 6.0,
        x0,
        x1,
        l1
    );
    if let (Some(x), Some(l)) = (curve.critical_position, curve.critical_load_factor) {
        let (cx, cy) = px((x, l));
        svg.push_str(&format!(
            "<circle cx=\"{cx:.2}\" cy=\"{cy:.2}\" r=\"4\" fill=\"#c62828\"/>\
             <text x=\"{:.2}\" y=\"{:.2}\" fill=\"#c62828\">critical: x = {x:.3}, λ = {l:.4}</text>",
            cx + 6.0,
            cy + 14.0
        ));
    }
    svg.push_str("</g>");
    canvas.raw(&svg);
}
