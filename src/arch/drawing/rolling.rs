//! The rolling-load curve drawn under a bridge: λ against the position of the load on the
//! bridge's own x axis (the same scale and ticks), the critical stop marked.

use crate::arch::rolling::RollingOutDto;
use crate::svg::Canvas;

/// λ against the position of a rolling load, in a band under the arch on its x axis, with
/// ticks of x (the bridge's) and of λ, the critical stop marked.
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
    let height = 150.0;
    let (ticks, left, right) = canvas.x_axis();
    let ticks = ticks.to_vec();
    let top = canvas.band_below(height + 40.0) + 20.0;
    // Stops where an axle barely stands on the arch can have λ hundreds of times the least:
    // the band shows up to ten times the critical λ, the rest on its top edge.
    let most = points.iter().fold(0.0f64, |m, p| m.max(p.1));
    let cap = match curve.critical_load_factor {
        Some(c) if c > 0.0 && most > 10.0 * c => Some(10.0 * c),
        _ => None,
    };
    let l1 = cap.unwrap_or(most) * 1.05;
    let x_px = |x: f64| canvas.px((x, 0.0)).0;
    let px = |(x, l): (f64, f64)| {
        let v = if l1 > 0.0 { l.min(l1) / l1 } else { 0.0 };
        (x_px(x), top + height - v * height)
    };
    let path: Vec<String> = points
        .iter()
        .map(|&p| {
            let (x, y) = px(p);
            format!("{x:.2},{y:.2}")
        })
        .collect();
    let mut svg = format!(
        "<g data-kind=\"rolling\" font-size=\"11\" font-family=\"sans-serif\"><rect x=\"{left:.2}\" y=\"{top:.2}\" width=\"{:.2}\" height=\"{height}\" fill=\"none\" stroke=\"#999\"/>\
         <polyline points=\"{}\" fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.6\"/>\
         <text x=\"{left:.2}\" y=\"{:.2}\" fill=\"#333\">rolling load: λ against the position of the load (x as the bridge's, above){}</text>",
        right - left,
        path.join(" "),
        top - 6.0,
        cap.map_or(String::new(), |c| format!("; λ above {c:.3} on the top edge")),
    );
    for x in ticks {
        let p = x_px(x);
        svg.push_str(&format!(
            "<line x1=\"{p:.2}\" y1=\"{b:.2}\" x2=\"{p:.2}\" y2=\"{:.2}\" stroke=\"#999\"/>\
             <text x=\"{p:.2}\" y=\"{:.2}\" text-anchor=\"middle\" fill=\"#666\" font-size=\"10\" data-tick=\"{x}\">{}</text>",
            top + height + 5.0,
            top + height + 17.0,
            crate::svg::tick(x),
            b = top + height,
        ));
    }
    for l in [0.0, l1 / 1.05 / 2.0, l1 / 1.05] {
        let (_, y) = px((0.0, l));
        svg.push_str(&format!(
            "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\" fill=\"#666\" font-size=\"10\" data-lambda=\"{l}\">{l:.3}</text>",
            left - 4.0,
            y + 3.0
        ));
    }
    if let (Some(x), Some(l)) = (curve.critical_position, curve.critical_load_factor) {
        let (cx, cy) = px((x, l));
        svg.push_str(&format!(
            "<circle cx=\"{cx:.2}\" cy=\"{cy:.2}\" r=\"4\" fill=\"#c62828\"/>\
             <text x=\"{:.2}\" y=\"{:.2}\" fill=\"#c62828\">critical: x = {x:.3}, λ = {l:.4}</text>",
            cx + 6.0,
            cy - 8.0
        ));
    }
    svg.push_str("</g>");
    canvas.raw(&svg);
}
