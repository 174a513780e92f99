//! The drawing surface of the `/svg` routes (`image/svg+xml`), built as plain strings: a
//! [`Canvas`] maps the section's coordinates (y up, any unit) onto an 800-pixel-wide picture with
//! axes and a scale bar; `arch::drawing` and `slope::drawing` draw on it from the solvers' own
//! results, and [`Svg`] answers with the picture.

use std::fmt::Write;

mod labels;
mod numbers;
pub mod study;

use numbers::nice_step;
pub use numbers::{escape, heat, shown, tick};

pub use labels::Labels;

/// An `image/svg+xml` answer.
pub struct Svg(pub String);

impl axum::response::IntoResponse for Svg {
    fn into_response(self) -> axum::response::Response {
        (
            [(
                axum::http::header::CONTENT_TYPE,
                "image/svg+xml; charset=utf-8",
            )],
            self.0,
        )
            .into_response()
    }
}

/// Width of every drawing in pixels.
pub const WIDTH: f64 = 800.0;
const MARGIN: f64 = 60.0;
/// Points closer than this many pixels to the last one drawn are left out of a line.
const DETAIL: f64 = 0.75;

/// A picture of the region [x0, x1] × [y0, y1] of the section, y up, under a title and a key.
pub struct Canvas {
    x0: f64,
    y1: f64,
    scale: f64,
    height: f64,
    /// The plot inside the axes in pixels [x0, y0, x1, y1]: what [`Canvas::clip_begin`] keeps.
    plot: [f64; 4],
    body: String,
    /// The scale bar, drawn in the title's row.
    scale_bar: String,
    /// Items of the key: (text, colour, font size, whether it starts a new line).
    key: Vec<(String, String, f64, bool)>,
    /// Arrowheads in colours of their own ([`Canvas::arrow_in`]), as `#rrggbb`.
    heads: std::collections::BTreeSet<String>,
    /// The x of the axes' ticks, for a band under the picture to share them.
    x_ticks: Vec<f64>,
}

/// Baseline of the key's first line, and the distance between its lines (pixels).
const KEY_TOP: f64 = 44.0;
const KEY_LINE: f64 = 14.0;

impl Canvas {
    /// A canvas showing the bounding box of `points`, padded by 5 %.
    pub fn fitting(points: impl IntoIterator<Item = (f64, f64)>) -> Self {
        let (mut x0, mut y0, mut x1, mut y1) = (
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        );
        for (x, y) in points {
            if x.is_finite() && y.is_finite() {
                x0 = x0.min(x);
                x1 = x1.max(x);
                y0 = y0.min(y);
                y1 = y1.max(y);
            }
        }
        let has_width = x0 < x1;
        if !has_width {
            (x0, x1) = (x0.min(0.0) - 1.0, x1.max(0.0) + 1.0);
        }
        let has_height = y0 < y1;
        if !has_height {
            (y0, y1) = (y0.min(0.0) - 1.0, y1.max(0.0) + 1.0);
        }
        let pad = 0.05 * (x1 - x0).max(y1 - y0);
        let (x0, x1, y0, y1) = (x0 - pad, x1 + pad, y0 - pad, y1 + pad);
        let scale = (WIDTH - 2.0 * MARGIN) / (x1 - x0);
        let height = ((y1 - y0) * scale + 2.0 * MARGIN).clamp(200.0, 2000.0);
        let mut canvas = Self {
            x0,
            y1,
            scale,
            height,
            plot: [0.0; 4],
            body: String::new(),
            scale_bar: String::new(),
            key: Vec::new(),
            heads: std::collections::BTreeSet::new(),
            x_ticks: Vec::new(),
        };
        let (a, b) = (canvas.px((x0, y1)), canvas.px((x1, y0)));
        canvas.plot = [a.0, a.1, b.0, b.1];
        canvas.axes(x0, x1, y0, y1);
        canvas
    }

    /// Pixel coordinates of a point of the section.
    pub fn px(&self, (x, y): (f64, f64)) -> (f64, f64) {
        (
            MARGIN + (x - self.x0) * self.scale,
            MARGIN + (self.y1 - y) * self.scale,
        )
    }

    /// Adds a band of `extra` pixels below the picture; returns the band's top (pixels).
    pub fn band_below(&mut self, extra: f64) -> f64 {
        let top = self.height;
        self.height += extra;
        top
    }

    /// The plot inside the axes, in pixels [x0, y0, x1, y1]: where labels may go.
    pub fn plot_area(&self) -> [f64; 4] {
        [
            MARGIN + 2.0,
            MARGIN,
            WIDTH - 4.0,
            self.height - MARGIN - 2.0,
        ]
    }

    /// The x of the axes' ticks and the left and right ends of the plot in pixels: a band under
    /// the picture on the same x axis.
    pub fn x_axis(&self) -> (&[f64], f64, f64) {
        (&self.x_ticks, self.plot[0], self.plot[2])
    }

    /// A length of the section in pixels.
    pub fn length(&self, l: f64) -> f64 {
        l * self.scale
    }

    /// Everything drawn until [`Canvas::clip_end`] is cut at the axes (a map larger than the
    /// scene).
    pub fn clip_begin(&mut self) {
        self.raw("<g clip-path=\"url(#plot)\">");
    }

    /// Ends what [`Canvas::clip_begin`] started.
    pub fn clip_end(&mut self) {
        self.raw("</g>");
    }

    /// An item of the key above the plot, after the previous one on its line (or on a new line
    /// when `new_line` or when the line is full); the plot moves down to make room.
    pub fn key(&mut self, text: &str, colour: &str, font_size: f64, new_line: bool) {
        self.key
            .push((text.to_owned(), colour.to_owned(), font_size, new_line));
    }

    /// Appends raw SVG.
    pub fn raw(&mut self, svg: &str) {
        self.body.push_str(svg);
        self.body.push('\n');
    }

    /// A closed polygon (points closer than [`DETAIL`] pixels to the last one drawn left out).
    pub fn polygon(&mut self, points: &[(f64, f64)], style: &str) {
        let mut d = String::new();
        let mut last: Option<(f64, f64)> = None;
        for (i, &p) in points.iter().enumerate() {
            let (x, y) = self.px(p);
            let end = i + 1 == points.len();
            if last.is_some_and(|l| (l.0 - x).hypot(l.1 - y) < DETAIL) && !end {
                continue;
            }
            last = Some((x, y));
            let _ = write!(d, "{x:.2},{y:.2} ");
        }
        self.raw(&format!("<polygon points=\"{}\" {style}/>", d.trim_end()));
    }

    /// An open polyline; non-finite points break it (points closer than [`DETAIL`] pixels to
    /// the last one drawn left out, the ends kept).
    pub fn polyline(&mut self, points: &[(f64, f64)], style: &str) {
        let mut runs: Vec<String> = vec![String::new()];
        let mut last: Option<(f64, f64)> = None;
        for (i, &p) in points.iter().enumerate() {
            if p.0.is_finite() && p.1.is_finite() {
                let (x, y) = self.px(p);
                let next_breaks = points
                    .get(i + 1)
                    .is_none_or(|q| !(q.0.is_finite() && q.1.is_finite()));
                if last.is_some_and(|l| (l.0 - x).hypot(l.1 - y) < DETAIL) && !next_breaks {
                    continue;
                }
                last = Some((x, y));
                let _ = write!(runs.last_mut().expect("never empty"), "{x:.2},{y:.2} ");
            } else if !runs.last().is_some_and(String::is_empty) {
                runs.push(String::new());
                last = None;
            }
        }
        // Unfilled unless the style says otherwise: an attribute written twice makes the whole
        // picture invalid XML (browsers then show nothing).
        let fill = if style.contains("fill=") {
            ""
        } else {
            "fill=\"none\" "
        };
        for run in runs.into_iter().filter(|r| r.contains(' ')) {
            self.raw(&format!(
                "<polyline points=\"{}\" {fill}{style}/>",
                run.trim_end()
            ));
        }
    }

    /// Many shapes in one `<path>` (`closed`: each closed), in pixels to 0.1 with points within
    /// [`DETAIL`] of the last drawn or on the line to the next left out: what dense drawings
    /// use instead of an element per block (a multi-ring arch drew 1.1 MB).
    pub fn path(&mut self, shapes: &[Vec<(f64, f64)>], closed: bool, style: &str) {
        let mut d = String::new();
        for shape in shapes {
            let px: Vec<(f64, f64)> = shape.iter().map(|&p| self.px(p)).collect();
            if px.len() < 2 || px.iter().any(|p| !(p.0.is_finite() && p.1.is_finite())) {
                continue;
            }
            let mut last = px[0];
            let _ = write!(d, "M{:.1} {:.1}", last.0, last.1);
            for (i, &p) in px.iter().enumerate().skip(1) {
                let next = px.get(i + 1).copied();
                let near = (p.0 - last.0).hypot(p.1 - last.1) < DETAIL;
                // Off the chord from the last point drawn to the next by less than 0.2 px.
                let on_chord = next.is_some_and(|n| {
                    let (cx, cy) = (n.0 - last.0, n.1 - last.1);
                    let cross = (p.0 - last.0) * cy - (p.1 - last.1) * cx;
                    cross.abs() < 0.2 * cx.hypot(cy)
                });
                if next.is_some() && (near || on_chord) {
                    continue;
                }
                last = p;
                let _ = write!(d, "L{:.1} {:.1}", p.0, p.1);
            }
            if closed {
                d.push('Z');
            }
        }
        if !d.is_empty() {
            self.raw(&format!("<path d=\"{d}\" {style}/>"));
        }
    }

    /// Many dots of `diameter` pixels in one `<path>` (round caps on zero-length strokes).
    pub fn dots(&mut self, points: &[(f64, f64)], diameter: f64, colour: &str) {
        let mut d = String::new();
        for &p in points.iter().filter(|p| p.0.is_finite() && p.1.is_finite()) {
            let (x, y) = self.px(p);
            let _ = write!(d, "M{x:.1} {y:.1}h0");
        }
        if !d.is_empty() {
            self.raw(&format!(
                "<path d=\"{d}\" stroke=\"{colour}\" stroke-width=\"{diameter}\" stroke-linecap=\"round\"/>"
            ));
        }
    }

    /// A dot of `radius` pixels.
    pub fn dot(&mut self, p: (f64, f64), radius: f64, style: &str) {
        let (x, y) = self.px(p);
        self.raw(&format!(
            "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"{radius}\" {style}/>"
        ));
    }

    /// Text at a point, offset in pixels.
    pub fn text(&mut self, p: (f64, f64), offset: (f64, f64), text: &str, style: &str) {
        let (x, y) = self.px(p);
        self.raw(&format!(
            "<text x=\"{:.2}\" y=\"{:.2}\" {style}>{}</text>",
            x + offset.0,
            y + offset.1,
            escape(text)
        ));
    }

    /// An arrow from `from` to `to` in `colour` (`#rrggbb`), its head in the same colour: a
    /// force of its own kind, told apart from the live loads' blue arrows.
    pub fn arrow_in(&mut self, from: (f64, f64), to: (f64, f64), colour: &str, width: f64) {
        let id = colour.trim_start_matches('#').to_owned();
        let (a, b) = (self.px(from), self.px(to));
        self.raw(&format!(
            "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" marker-end=\"url(#arrow-{id})\" stroke=\"{colour}\" stroke-width=\"{width}\"/>",
            a.0, a.1, b.0, b.1
        ));
        self.heads.insert(colour.to_owned());
    }

    /// An arrow from `from` to `to` (section coordinates).
    pub fn arrow(&mut self, from: (f64, f64), to: (f64, f64), style: &str) {
        let (a, b) = (self.px(from), self.px(to));
        self.raw(&format!(
            "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" marker-end=\"url(#arrow)\" {style}/>",
            a.0, a.1, b.0, b.1
        ));
    }

    fn axes(&mut self, x0: f64, x1: f64, y0: f64, y1: f64) {
        let step = nice_step((x1 - x0).max(y1 - y0) / 8.0);
        let style = "stroke=\"#bbb\" stroke-width=\"0.5\"";
        let label = "font-size=\"10\" fill=\"#666\" font-family=\"sans-serif\"";
        let (left, bottom) = (x0, y0);
        let mut x = (x0 / step).ceil() * step;
        while x <= x1 {
            self.x_ticks.push(x);
            let (px, py) = self.px((x, bottom));
            self.raw(&format!(
                "<line x1=\"{px:.2}\" y1=\"{py:.2}\" x2=\"{px:.2}\" y2=\"{:.2}\" {style}/>",
                py + 5.0
            ));
            self.raw(&format!(
                "<text x=\"{px:.2}\" y=\"{:.2}\" text-anchor=\"middle\" {label}>{}</text>",
                py + 17.0,
                tick(x)
            ));
            x += step;
        }
        let mut y = (y0 / step).ceil() * step;
        while y <= y1 {
            let (px, py) = self.px((left, y));
            self.raw(&format!(
                "<line x1=\"{:.2}\" y1=\"{py:.2}\" x2=\"{px:.2}\" y2=\"{py:.2}\" {style}/>",
                px - 5.0
            ));
            self.raw(&format!(
                "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\" {label}>{}</text>",
                px - 8.0,
                py + 3.0,
                tick(y)
            ));
            y += step;
        }
        let (ax, ay) = self.px((left, bottom));
        let (bx, _) = self.px((x1, bottom));
        let (_, cy) = self.px((left, y1));
        self.raw(&format!("<polyline points=\"{ax:.2},{cy:.2} {ax:.2},{ay:.2} {bx:.2},{ay:.2}\" fill=\"none\" stroke=\"#888\"/>"));
        // Scale bar: one step, top right.
        let bar = self.length(step);
        let (sx, sy) = (WIDTH - MARGIN - bar, MARGIN - 30.0);
        self.scale_bar = format!(
            "<line x1=\"{sx:.2}\" y1=\"{sy:.2}\" x2=\"{:.2}\" y2=\"{sy:.2}\" stroke=\"#333\" stroke-width=\"3\"/>\
             <text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"middle\" {label}>{} (scale)</text>",
            sx + bar,
            sx + bar / 2.0,
            sy - 6.0,
            tick(step)
        );
    }

    /// The key laid out in lines from [`KEY_TOP`] down: the SVG and the pixels the plot must
    /// move down by (none for one line, as the plot's top margin holds it).
    fn key_lines(&self) -> (String, f64) {
        let (mut x, mut y) = (MARGIN, KEY_TOP);
        let mut svg = String::new();
        for (i, (text, colour, size, new_line)) in self.key.iter().enumerate() {
            let width = 0.6 * size * text.chars().count() as f64;
            if i > 0 && (*new_line || x + width > WIDTH - 10.0) {
                (x, y) = (MARGIN, y + KEY_LINE);
            }
            let _ = writeln!(
                svg,
                "<text x=\"{x:.0}\" y=\"{y:.0}\" font-size=\"{size}\" font-family=\"sans-serif\" fill=\"{colour}\">{}</text>",
                escape(text)
            );
            x += width + 18.0;
        }
        (svg, y - KEY_TOP)
    }

    /// The finished document, with a title, the scale bar and the key above the plot. The root's
    /// `data-frame` = "x0 top y1 scale" maps pixels back to the section (the page's clicks):
    /// x = x0 + (px − 60)/scale, y = y1 − (py − top)/scale.
    pub fn finish(self, title: &str) -> String {
        let (key, shift) = self.key_lines();
        let [px0, py0, px1, py1] = self.plot;
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h:.0}\" viewBox=\"0 0 {w} {h:.0}\" \
             data-frame=\"{x0} {top} {y1} {scale}\">\n\
             <defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#1565c0\"/></marker>{heads}\
             <clipPath id=\"plot\"><rect x=\"{px0:.2}\" y=\"{py0:.2}\" width=\"{pw:.2}\" height=\"{ph:.2}\"/></clipPath></defs>\n\
             <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n\
             <text x=\"{m}\" y=\"22\" font-size=\"15\" font-family=\"sans-serif\" fill=\"#222\">{t}</text>\n{bar}\n{key}\
             <g transform=\"translate(0 {shift:.0})\">\n{b}</g>\n</svg>\n",
            heads = self
                .heads
                .iter()
                .map(|c| format!(
                    "<marker id=\"arrow-{}\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"{c}\"/></marker>",
                    c.trim_start_matches('#')
                ))
                .collect::<String>(),
            w = WIDTH,
            h = self.height + shift,
            x0 = self.x0,
            top = MARGIN + shift,
            y1 = self.y1,
            scale = self.scale,
            m = MARGIN,
            t = escape(title),
            bar = self.scale_bar,
            pw = px1 - px0,
            ph = py1 - py0,
            b = self.body
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn canvas_maps_y_up_and_fits_the_width() {
        let c = Canvas::fitting([(0.0, 0.0), (10.0, 5.0)]);
        let (a, b) = (c.px((0.0, 0.0)), c.px((10.0, 5.0)));
        assert!(b.0 > a.0 && b.1 < a.1);
        assert!(a.0 >= MARGIN && b.0 <= WIDTH - MARGIN);
    }
}
