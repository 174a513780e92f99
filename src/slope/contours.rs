//! Contours of the F map of a search: the grid of centres refined by cubic interpolation (so
//! that a 21 × 21 grid gives smooth lines), then marching squares.

/// The grid refined `k` times per cell: Catmull–Rom across each cell from its 4 × 4
/// neighbourhood (ends repeated), bilinear where a neighbour is missing, none where a corner is.
pub fn refine(
    xs: &[f64],
    ys: &[f64],
    f: &[Vec<Option<f64>>],
    k: usize,
) -> (Vec<f64>, Vec<f64>, Vec<Vec<Option<f64>>>) {
    let k = k.max(1);
    let fine = |v: &[f64]| -> Vec<f64> {
        let mut out: Vec<f64> = v
            .windows(2)
            .flat_map(|w| (0..k).map(move |m| w[0] + (w[1] - w[0]) * m as f64 / k as f64))
            .collect();
        out.extend(v.last());
        out
    };
    let (fx, fy) = (fine(xs), fine(ys));
    let (nx, ny) = (xs.len(), ys.len());
    let at = |j: isize, i: isize| -> Option<f64> {
        let j = j.clamp(0, ny as isize - 1) as usize;
        let i = i.clamp(0, nx as isize - 1) as usize;
        f.get(j)?.get(i).copied().flatten()
    };
    let values = (0..fy.len())
        .map(|jj| {
            (0..fx.len())
                .map(|ii| {
                    let (j, s) = ((jj / k).min(ny.saturating_sub(2)), jj as f64 / k as f64);
                    let (i, r) = ((ii / k).min(nx.saturating_sub(2)), ii as f64 / k as f64);
                    let (t, u) = (s - j as f64, r - i as f64);
                    let (j, i) = (j as isize, i as isize);
                    let corners = [at(j, i)?, at(j, i + 1)?, at(j + 1, i)?, at(j + 1, i + 1)?];
                    let cubic = (-1..=2)
                        .map(|dj| {
                            let row = (-1..=2)
                                .map(|di| at(j + dj, i + di))
                                .collect::<Option<Vec<f64>>>()?;
                            Some(catmull_rom(&row, u))
                        })
                        .collect::<Option<Vec<f64>>>()
                        .map(|column| catmull_rom(&column, t));
                    Some(cubic.unwrap_or_else(|| {
                        let bottom = corners[0] + (corners[1] - corners[0]) * u;
                        let top = corners[2] + (corners[3] - corners[2]) * u;
                        bottom + (top - bottom) * t
                    }))
                })
                .collect()
        })
        .collect();
    (fx, fy, values)
}

/// The Catmull–Rom cubic through p[1] (t = 0) and p[2] (t = 1).
fn catmull_rom(p: &[f64], t: f64) -> f64 {
    0.5 * (2.0 * p[1]
        + (p[2] - p[0]) * t
        + (2.0 * p[0] - 5.0 * p[1] + 4.0 * p[2] - p[3]) * t * t
        + (3.0 * p[1] - p[0] - 3.0 * p[2] + p[3]) * t * t * t)
}

/// The segments of the contour `level` of the values `f[j][i]` at (xs[i], ys[j]) (marching
/// squares; cells with a missing corner are skipped).
pub fn contour(xs: &[f64], ys: &[f64], f: &[Vec<Option<f64>>], level: f64) -> Vec<[(f64, f64); 2]> {
    let mut segments = Vec::new();
    for j in 0..ys.len().saturating_sub(1) {
        for i in 0..xs.len().saturating_sub(1) {
            let corners = [
                ((xs[i], ys[j]), f[j][i]),
                ((xs[i + 1], ys[j]), f[j][i + 1]),
                ((xs[i + 1], ys[j + 1]), f[j + 1][i + 1]),
                ((xs[i], ys[j + 1]), f[j + 1][i]),
            ];
            let Some(values) = corners.iter().map(|c| c.1).collect::<Option<Vec<f64>>>() else {
                continue;
            };
            // Crossing points on the four edges, in order.
            let mut crossings = Vec::with_capacity(4);
            for k in 0..4 {
                let (a, b) = (k, (k + 1) % 4);
                let (va, vb) = (values[a] - level, values[b] - level);
                if (va < 0.0) != (vb < 0.0) {
                    let t = va / (va - vb);
                    let (pa, pb) = (corners[a].0, corners[b].0);
                    crossings.push((pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1)));
                }
            }
            // Two crossings: one segment; four (a saddle): two, pairing neighbours.
            for pair in crossings.chunks_exact(2) {
                segments.push([pair[0], pair[1]]);
            }
        }
    }
    segments
}

#[cfg(test)]
mod tests {
    use super::{contour, refine};

    #[test]
    fn contour_of_a_cone_is_a_ring_at_the_right_radius() {
        // f = distance from the origin on a 41 × 41 grid: the level-1 contour lies on the unit
        // circle up to the linear interpolation error (h²/8 with h = 0.1: 2e-3).
        let axis: Vec<f64> = (0..41).map(|i| -2.0 + 0.1 * f64::from(i)).collect();
        let f: Vec<Vec<Option<f64>>> = axis
            .iter()
            .map(|&y| axis.iter().map(|&x| Some(x.hypot(y))).collect())
            .collect();
        let segments = contour(&axis, &axis, &f, 1.0);
        assert!(segments.len() > 40);
        for [a, b] in segments {
            for p in [a, b] {
                assert!((p.0.hypot(p.1) - 1.0).abs() < 5e-3, "{p:?}");
            }
        }
    }

    #[test]
    fn refinement_reproduces_a_smooth_field_and_keeps_holes() {
        // f = x² + y² on a coarse 9 × 9 grid over [−2, 2]²: the cubic refinement at 4 per cell
        // is within 1e-12 of the field where it is quadratic along each axis (Catmull–Rom is
        // exact for quadratics inside, h²/4-ish at the repeated ends), and cells with a missing
        // corner stay missing.
        let axis: Vec<f64> = (0..9).map(|i| -2.0 + 0.5 * f64::from(i)).collect();
        let mut f: Vec<Vec<Option<f64>>> = axis
            .iter()
            .map(|&y| axis.iter().map(|&x| Some(x * x + y * y)).collect())
            .collect();
        let (fx, fy, g) = refine(&axis, &axis, &f, 4);
        assert_eq!((fx.len(), fy.len()), (33, 33));
        for (jj, &y) in fy.iter().enumerate() {
            for (ii, &x) in fx.iter().enumerate() {
                let inner = (-1.5..=1.5).contains(&x) && (-1.5..=1.5).contains(&y);
                if inner {
                    let v = g[jj][ii].unwrap();
                    assert!((v - (x * x + y * y)).abs() < 1e-12, "({x}, {y}): {v}");
                }
            }
        }
        f[4][4] = None;
        let (_, _, g) = refine(&axis, &axis, &f, 4);
        assert!(g[16][16].is_none() && g[14][14].is_none() && g[18][18].is_none());
        assert!(g[8][8].is_some());
    }
}
