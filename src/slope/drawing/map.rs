//! The map of F over a search's centres: one cell per grid point coloured from the least F
//! (red) up, and labelled contours on the grid refined four times per cell.

use thrustline_solver::slope::search::FactorGrid;

use super::super::contours::{contour, refine};
use crate::svg::{heat, Canvas};

/// The map of `grid` (relative to `lower_end`), clipped to the plot; `visible` is the picture's
/// extent [x_lo, y_lo, x_hi, y_hi], `critical` the key's note on the refined critical circle.
pub fn factor_map(
    canvas: &mut Canvas,
    grid: &FactorGrid,
    lower_end: (f64, f64),
    visible: [f64; 4],
    critical: String,
    reserved: &[[f64; 4]],
) {
    canvas.clip_begin();
    let values: Vec<f64> = grid.factors.iter().flatten().flatten().copied().collect();
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    let cap = lo + (hi - lo).min(2.0 * lo.max(1e-9));
    cells(canvas, grid, lower_end, lo, cap);
    let labelled = contours(canvas, grid, lower_end, visible, lo, reserved);
    canvas.clip_end();
    canvas.key(
        &format!(
            "F over centres: red {lo:.3} (grid least) … blue ≥ {cap:.3}; {labelled} labelled \
             contours{critical}"
        ),
        "#b71c1c",
        11.0,
        true,
    );
}

/// Draws one cell per grid point (relative to `lower_end`), coloured from `lo` (red) to `cap`.
fn cells(canvas: &mut Canvas, grid: &FactorGrid, lower_end: (f64, f64), lo: f64, cap: f64) {
    let (dx, dy) = (cell(&grid.xs), cell(&grid.ys));
    for (j, row) in grid.factors.iter().enumerate() {
        for (i, f) in row.iter().enumerate() {
            let Some(f) = f else { continue };
            let t = 1.0 - ((f - lo) / (cap - lo).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
            let (x, y) = (lower_end.0 + grid.xs[i], lower_end.1 + grid.ys[j]);
            let corners = [
                (x - dx / 2.0, y - dy / 2.0),
                (x + dx / 2.0, y - dy / 2.0),
                (x + dx / 2.0, y + dy / 2.0),
                (x - dx / 2.0, y + dy / 2.0),
            ];
            canvas.polygon(
                &corners,
                &format!("fill=\"{}\" fill-opacity=\"0.55\" stroke=\"none\"", heat(t)),
            );
        }
    }
}

/// Draws the contours of F above the least `lo`, labelled clear of `reserved`; counts the labels.
fn contours(
    canvas: &mut Canvas,
    grid: &FactorGrid,
    lower_end: (f64, f64),
    visible: [f64; 4],
    lo: f64,
    reserved: &[[f64; 4]],
) -> usize {
    // Contours F = F_min·(1.02, 1.05, 1.1, 1.2, 1.4, 1.7) on the grid refined 4 times per
    // cell (cubic), each labelled with its F at its rightmost point inside the grid (nested
    // contours spread their labels along x; the grid's edges crowd them).
    let absolute_xs: Vec<f64> = grid.xs.iter().map(|x| lower_end.0 + x).collect();
    let absolute_ys: Vec<f64> = grid.ys.iter().map(|y| lower_end.1 + y).collect();
    let (fine_xs, fine_ys, fine) = refine(&absolute_xs, &absolute_ys, &grid.factors, 4);
    let mut labelled = 0;
    // Labels drawn later (the critical centre's) are kept clear too.
    let mut placed: Vec<[f64; 4]> = reserved.to_vec();
    for factor in [1.02, 1.05, 1.1, 1.2, 1.4, 1.7] {
        let level = lo * factor;
        let segments = contour(&fine_xs, &fine_ys, &fine, level);
        for segment in &segments {
            canvas.polyline(segment, "stroke=\"#4e342e\" stroke-width=\"0.8\"");
        }
        let (x_edge, y_edge) = (
            0.02 * (fine_xs[fine_xs.len() - 1] - fine_xs[0]).abs(),
            0.02 * (fine_ys[fine_ys.len() - 1] - fine_ys[0]).abs(),
        );
        // Inside the grid and inside the picture.
        let inside = |p: &(f64, f64)| {
            p.0 < fine_xs[fine_xs.len() - 1] - x_edge
                && p.1 > fine_ys[0] + y_edge
                && p.1 < fine_ys[fine_ys.len() - 1] - y_edge
                && p.0 > visible[0]
                && p.0 < visible[2] - 0.05 * (visible[2] - visible[0])
                && p.1 > visible[1]
                && p.1 < visible[3]
        };
        // The rightmost point whose label overlaps no label placed before it.
        let text = format!("{level:.3}");
        let mut points: Vec<(f64, f64)> =
            segments.iter().flatten().copied().filter(inside).collect();
        points.sort_by(|a, b| b.0.total_cmp(&a.0));
        let top = points.into_iter().find_map(|p| {
            let b = label_box(canvas.px(p), text.chars().count());
            (!placed.iter().any(|q| overlaps(&b, q))).then(|| {
                placed.push(b);
                p
            })
        });
        if let Some(top) = top {
            canvas.text(
                top,
                (3.0, -3.0),
                &text,
                "font-size=\"9\" font-family=\"sans-serif\" fill=\"#4e342e\" stroke=\"#ffffff\" stroke-width=\"2\" paint-order=\"stroke\"",
            );
            labelled += 1;
        }
    }
    labelled
}

fn cell(values: &[f64]) -> f64 {
    if values.len() < 2 {
        1.0
    } else {
        (values[values.len() - 1] - values[0]) / (values.len() - 1) as f64
    }
}

/// The pixel box of a contour label of `chars` characters at 9 px, 3 px right of and 3 px above
/// the point `p` (its baseline), padded by 1 px.
fn label_box(p: (f64, f64), chars: usize) -> [f64; 4] {
    let (x, y) = (p.0 + 3.0, p.1 - 3.0);
    [
        x - 1.0,
        y - 9.0 - 1.0,
        x + 0.6 * 9.0 * chars as f64 + 1.0,
        y + 1.0,
    ]
}

/// Whether two boxes overlap.
fn overlaps(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}
