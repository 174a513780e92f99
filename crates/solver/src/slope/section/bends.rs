//! What a section's lines give once, for every cut of it: where they bend or cross (the
//! slices' weights and loads are integrated piecewise between these) and where water stands
//! above the ground.

use super::model::Section;
use super::polyline::Polyline;

/// Where the lines above the bases bend or cross (ground, layer tops, the water line, surcharge
/// edges), over the whole section, sorted: the slice weights and loads are integrated piecewise
/// between these, exactly. Computed once per section.
pub(super) fn bends(section: &Section) -> Vec<f64> {
    let lines: Vec<&Polyline> = std::iter::once(&section.ground)
        .chain(section.layers.iter().filter_map(|l| l.top.as_ref()))
        .chain(section.piezometric_line.as_ref())
        .collect();
    let mut xs: Vec<f64> = lines.iter().flat_map(|l| l.xs()).collect();
    xs.extend(section.surcharges.iter().flat_map(|s| [s.x_start, s.x_end]));
    // A layer's own water line bends its pore pressures (not the levels): its vertices.
    xs.extend(
        section
            .layers
            .iter()
            .filter_map(|l| l.piezometric_line.as_ref())
            .flat_map(|w| w.line.xs()),
    );
    // Beyond every vertex the lines run level: no crossing lies outside their range.
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let (lo, hi) = (lo - 1.0, hi + 1.0);
    for (i, line) in lines.iter().enumerate() {
        for other in &lines[i + 1..] {
            xs.extend(line.crossings(other, lo, hi));
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    xs
}

/// The stretches of x where the piezometric line lies above the ground somewhere (ponded
/// water), merged. Between the bends both lines are straight, beyond them level: the water
/// stands above the ground on a stretch only if it does at one of its ends.
pub(super) fn ponded(section: &Section) -> Vec<(f64, f64)> {
    let mut ponded: Vec<(f64, f64)> = Vec::new();
    let Some(line) = &section.piezometric_line else {
        return ponded;
    };
    let above = |x: f64| line.y_at(x) > section.ground.y_at(x);
    let ends = std::iter::once(f64::NEG_INFINITY)
        .chain(section.bends.iter().copied())
        .chain(std::iter::once(f64::INFINITY));
    for (a, b) in ends.clone().zip(ends.skip(1)) {
        if !((a.is_finite() && above(a)) || (b.is_finite() && above(b))) {
            continue;
        }
        match ponded.last_mut() {
            Some(last) if last.1 == a => last.1 = b,
            _ => ponded.push((a, b)),
        }
    }
    ponded
}
