//! A study drawn under its analysis (model §9.4): the histogram of the answers with the share
//! below 1 shaded as failures and the threshold marked, and one small plot per sensitivity
//! variable (the answer against the value, 1 dashed). Each panel is a band of its own under the
//! picture, with its own axes and ticks; the `data-*` attributes let a reader (and the tests)
//! take the numbers back.

use super::numbers::{escape, nice_step, tick};
use super::{Canvas, WIDTH};
use crate::study::response::{ProbabilisticOutDto, SensitivityCurveDto};
use crate::study::StudyAnswers;

/// The colour of failed answers, and of the threshold.
pub const FAILED: &str = "#c62828";
/// The colour of answers at or above 1.
pub const SAFE: &str = "#90a4ae";
/// Left and right ends of a panel's plot (pixels).
const LEFT: f64 = 70.0;
const RIGHT: f64 = WIDTH - 40.0;

/// Draws the studies of `answers` in bands under the picture; `what` names the answer (F, λ).
pub fn panels(canvas: &mut Canvas, answers: &StudyAnswers, what: &str) {
    if let Some((p, _)) = &answers.probabilistic {
        histogram(canvas, p, what);
    }
    if let Some(s) = &answers.sensitivity {
        for curve in &s.variables {
            sensitivity(canvas, curve, what);
        }
    }
}

/// Ticks from `lo` to `hi`: about five at 1, 2 or 5 times a power of ten.
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let step = nice_step((hi - lo) / 5.0);
    // A tick at an end stays (0.6/0.1 is 5.999…).
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// A panel's frame, its x ticks and its title; returns the panel's top (pixels).
fn frame(
    canvas: &mut Canvas,
    height: f64,
    title: &str,
    x: (f64, f64),
    kind: &str,
) -> (f64, String) {
    let top = canvas.band_below(height + 56.0) + 22.0;
    let mut svg = format!(
        "<g data-kind=\"{kind}\" font-size=\"11\" font-family=\"sans-serif\">\
         <text x=\"{LEFT}\" y=\"{:.2}\" fill=\"#222\">{}</text>\
         <rect x=\"{LEFT}\" y=\"{top:.2}\" width=\"{:.2}\" height=\"{height}\" fill=\"none\" stroke=\"#999\"/>",
        top - 7.0,
        escape(title),
        RIGHT - LEFT,
    );
    let span = (x.1 - x.0).max(1e-300);
    for t in ticks(x.0, x.1) {
        let px = LEFT + (t - x.0) / span * (RIGHT - LEFT);
        svg.push_str(&format!(
            "<line x1=\"{px:.2}\" y1=\"{b:.2}\" x2=\"{px:.2}\" y2=\"{:.2}\" stroke=\"#999\"/>\
             <text x=\"{px:.2}\" y=\"{:.2}\" text-anchor=\"middle\" fill=\"#333\" data-tick=\"{t}\">{}</text>",
            top + height + 4.0,
            top + height + 16.0,
            tick(t),
            b = top + height,
        ));
    }
    (top, svg)
}

/// The histogram: bars by count, the part of each bar below 1 shaded as failures.
fn histogram(canvas: &mut Canvas, p: &ProbabilisticOutDto, what: &str) {
    let (Some(first), Some(last)) = (p.histogram.first(), p.histogram.last()) else {
        return;
    };
    let lo = first.from.min(1.0);
    let hi = last.to.max(1.0);
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        (lo - 0.5, hi + 0.5)
    };
    let height = 140.0;
    let pf = p.probability_of_failure.map_or("none".to_owned(), |pf| {
        let se = p.probability_of_failure_standard_error.unwrap_or(0.0);
        format!("{pf:.4} ± {se:.4}")
    });
    let title = format!(
        "{} samples ({:?}, seed {}): {what} < 1 in {} — probability of failure {pf}; {what} against count",
        p.samples, p.sampling, p.seed, p.failed
    )
    .replace("MonteCarlo", "Monte Carlo")
    .replace("LatinHypercube", "Latin hypercube");
    let (top, mut svg) = frame(canvas, height, &title, (lo, hi), "histogram");
    let most = p
        .histogram
        .iter()
        .map(|b| b.count)
        .max()
        .unwrap_or(0)
        .max(1) as f64;
    svg.push_str(&format!(
        "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\" fill=\"#333\">{most}</text>\
         <text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\" fill=\"#333\">0</text>",
        LEFT - 4.0,
        top + 8.0 + 4.0,
        LEFT - 4.0,
        top + height + 4.0
    ));
    let x = |v: f64| LEFT + (v - lo) / (hi - lo) * (RIGHT - LEFT);
    for bin in &p.histogram {
        let h = bin.count as f64 / most * (height - 8.0);
        let y = top + height - h;
        let (a, b) = (x(bin.from), x(bin.to));
        // The share of the bar below 1, taking the answers as spread evenly over it.
        let cut = x(1.0).clamp(a, b);
        svg.push_str(&format!(
            "<g data-from=\"{}\" data-to=\"{}\" data-count=\"{}\">",
            bin.from, bin.to, bin.count
        ));
        for (from, to, colour) in [(a, cut, FAILED), (cut, b, SAFE)] {
            if to - from > 1e-9 && bin.count > 0 {
                svg.push_str(&format!(
                    "<rect x=\"{from:.2}\" y=\"{y:.2}\" width=\"{:.2}\" height=\"{h:.2}\" fill=\"{colour}\"/>",
                    to - from
                ));
            }
        }
        svg.push_str("</g>");
    }
    let one = x(1.0);
    svg.push_str(&format!(
        "<line x1=\"{one:.2}\" y1=\"{top:.2}\" x2=\"{one:.2}\" y2=\"{:.2}\" stroke=\"{FAILED}\" stroke-dasharray=\"4 3\"/>\
         <text x=\"{:.2}\" y=\"{:.2}\" fill=\"{FAILED}\">{what} = 1</text>",
        top + height,
        one + 4.0,
        top + 12.0
    ));
    if let (Some(m), Some(s)) = (p.mean, p.std) {
        svg.push_str(&format!(
            "<text x=\"{RIGHT}\" y=\"{:.2}\" text-anchor=\"end\" fill=\"#333\">mean {m:.4}, std {s:.4}, β {}</text>",
            top + 12.0,
            p.reliability_index_normal
                .map_or("—".to_owned(), |b| format!("{b:.3}"))
        ));
    }
    svg.push_str("</g>");
    canvas.raw(&svg);
}

/// One sensitivity variable: the answer against its value, 1 dashed where it is in range.
fn sensitivity(canvas: &mut Canvas, curve: &SensitivityCurveDto, what: &str) {
    let points: Vec<(f64, f64)> = curve
        .points
        .iter()
        .filter_map(|p| p.factor.map(|f| (p.value, f)))
        .collect();
    let (Some(first), Some(last)) = (curve.points.first(), curve.points.last()) else {
        return;
    };
    let (x0, x1) = (first.value.min(last.value), first.value.max(last.value));
    let (f0, f1) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.1), b.max(p.1))
        });
    let (least, most) = (f0, f1);
    let (f0, f1) = match (f0.is_finite(), f1 > f0) {
        (false, _) => (0.0, 2.0),
        (true, true) => (f0 - 0.05 * (f1 - f0), f1 + 0.05 * (f1 - f0)),
        (true, false) => (f0 - 0.5, f0 + 0.5),
    };
    let height = 100.0;
    let range = match least.is_finite() {
        true => format!("{what} from {least:.4} to {most:.4}"),
        false => "no answer".to_owned(),
    };
    let title = format!("sensitivity: {what} against {} ({range})", curve.field);
    let (top, mut svg) = frame(canvas, height, &title, (x0, x1), "sensitivity");
    let px = |(v, f): (f64, f64)| {
        let u = if x1 > x0 { (v - x0) / (x1 - x0) } else { 0.5 };
        (
            LEFT + u * (RIGHT - LEFT),
            top + height - (f - f0) / (f1 - f0) * height,
        )
    };
    for t in ticks(f0, f1) {
        let (_, y) = px((x0, t));
        svg.push_str(&format!(
            "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\" fill=\"#333\" data-tick=\"{t}\">{}</text>",
            LEFT - 4.0,
            y + 4.0,
            tick(t)
        ));
    }
    if (f0..=f1).contains(&1.0) {
        let (_, y) = px((x0, 1.0));
        svg.push_str(&format!(
            "<line x1=\"{LEFT}\" y1=\"{y:.2}\" x2=\"{RIGHT}\" y2=\"{y:.2}\" stroke=\"{FAILED}\" stroke-dasharray=\"4 3\"/>"
        ));
    }
    let path: Vec<String> = points
        .iter()
        .map(|&p| {
            let (x, y) = px(p);
            format!("{x:.2},{y:.2}")
        })
        .collect();
    svg.push_str(&format!(
        "<polyline points=\"{}\" fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.6\"/>",
        path.join(" ")
    ));
    for &p in &points {
        let (x, y) = px(p);
        svg.push_str(&format!(
            "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"2.5\" fill=\"#1565c0\" data-value=\"{}\" data-factor=\"{}\"/>",
            p.0, p.1
        ));
    }
    svg.push_str("</g>");
    canvas.raw(&svg);
}
