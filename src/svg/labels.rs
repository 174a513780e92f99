//! Placement of labels beside points of a drawing, clear of each other and of what is drawn.

/// Labels placed one by one where they overlap nothing placed before them: other labels, the
/// obstacles given (dots, arrows) and the edges of the plot. Boxes are in pixels, estimated from
/// the text's length (0.6 em a character).
#[derive(Default)]
pub struct Labels {
    taken: Vec<[f64; 4]>,
}

impl Labels {
    /// Keeps labels off the pixel box [x0, y0, x1, y1].
    pub fn avoid(&mut self, b: [f64; 4]) {
        self.taken.push(b);
    }

    /// Keeps labels off the segment from `a` to `b` (pixels), padded by `pad`.
    pub fn avoid_segment(&mut self, a: (f64, f64), b: (f64, f64), pad: f64) {
        self.avoid([
            a.0.min(b.0) - pad,
            a.1.min(b.1) - pad,
            a.0.max(b.0) + pad,
            a.1.max(b.1) + pad,
        ]);
    }

    /// The top-left corner of a label of `chars` characters at `font` px beside the pixel point
    /// `p`: 8 px away in the first of 16 directions, turning both ways from `preferred`, whose
    /// box is free and inside `bounds`; the preferred place when none is. The box is then taken.
    pub fn place(
        &mut self,
        p: (f64, f64),
        preferred: (f64, f64),
        (chars, font): (usize, f64),
        bounds: [f64; 4],
    ) -> (f64, f64) {
        let (w, h) = (0.6 * font * chars as f64, font);
        let start = preferred.1.atan2(preferred.0);
        let box_at = |angle: f64| {
            let d = (angle.cos(), angle.sin());
            let reach = 8.0 + 0.5 * (d.0.abs() * w + d.1.abs() * h);
            let c = (p.0 + d.0 * reach, p.1 + d.1 * reach);
            [c.0 - w / 2.0, c.1 - h / 2.0, c.0 + w / 2.0, c.1 + h / 2.0]
        };
        let overlaps =
            |a: &[f64; 4], b: &[f64; 4]| a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
        let fits = |b: &[f64; 4]| {
            b[0] >= bounds[0] && b[1] >= bounds[1] && b[2] <= bounds[2] && b[3] <= bounds[3]
        };
        let step = std::f64::consts::PI / 8.0;
        let chosen = (0..16)
            .map(|k| {
                // 0, +1, −1, +2, −2, … steps from the preferred direction.
                let turn = if k % 2 == 1 {
                    ((k + 1) / 2) as f64
                } else {
                    -((k / 2) as f64)
                };
                box_at(start + turn * step)
            })
            .find(|b| fits(b) && !self.taken.iter().any(|t| overlaps(b, t)))
            .unwrap_or_else(|| box_at(start));
        self.taken.push(chosen);
        (chosen[0], chosen[1])
    }
}
