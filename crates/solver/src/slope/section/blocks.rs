//! Slip surfaces along the section's layer boundaries ("block" surfaces, as SLOPE/W and Slide2
//! offer for weak layers): a base that follows a layer top (or bedrock) a hair above or below
//! it between x₁ and x₂, and at each end a straight ray rising to the ground. A thin weak seam
//! is where the critical surface runs, and no circle, nor a polyline moved from one, finds a
//! seam a few centimetres thick; a base laid along it does.

use super::model::Section;
use super::polyline::Polyline;

/// How far above or below a boundary a base runs, relative to the section's size: inside the
/// layer on that side however thin the layer, yet the same line to any measurement.
const HAIR: f64 = 1e-6;

/// A line a base may follow: a boundary moved a hair up or down, with the stretch of x over
/// which it lies below the ground.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Base {
    pub line: Polyline,
    pub from: f64,
    pub to: f64,
    /// The section's extent, within which the end rays must reach the ground.
    pub extent: (f64, f64),
}

/// The section's extent: from the leftmost to the rightmost point of its ground, layer tops
/// and bedrock.
fn extent(section: &Section) -> (f64, f64) {
    let lines = std::iter::once(&section.ground)
        .chain(section.layers.iter().filter_map(|l| l.top.as_ref()))
        .chain(section.bedrock.as_ref());
    lines.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), l| {
        let p = l.points();
        (lo.min(p[0].0), hi.max(p[p.len() - 1].0))
    })
}

/// The lines bases may follow: every layer top a hair above and a hair below, bedrock a hair
/// above; each where it lies below the ground by more than a thousandth of the section's
/// height (the longest such stretch).
pub(super) fn bases(section: &Section) -> Vec<Base> {
    let (lo, hi) = extent(section);
    if hi <= lo {
        return Vec::new();
    }
    let ground = &section.ground;
    let (low, high) = ground
        .points()
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p.1), h.max(p.1))
        });
    let height = high - low;
    let scale = (hi - lo).max(height);
    let hair = HAIR * scale;
    let deep = 1e-3 * height.max(1e-3 * scale);
    let tops = section.layers.iter().filter_map(|l| l.top.as_ref());
    let boundaries = tops
        .flat_map(|t| [(t, hair), (t, -hair)])
        .chain(section.bedrock.as_ref().map(|r| (r, hair)));
    let mut out = Vec::new();
    for (line, shift) in boundaries {
        let mut xs: Vec<f64> = std::iter::once(lo)
            .chain(line.xs().chain(ground.xs()).filter(|&x| x > lo && x < hi))
            .chain(std::iter::once(hi))
            .collect();
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        let mut points: Vec<(f64, f64)> = line
            .xs()
            .filter(|&x| x > lo && x < hi)
            .chain([lo, hi])
            .map(|x| (x, line.y_at(x) + shift))
            .collect();
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        points.dedup_by(|a, b| a.0 == b.0);
        let Ok(moved) = Polyline::new(points) else {
            continue;
        };
        if let Some((from, to)) = below_ground(ground, &moved, &xs, deep) {
            out.push(Base {
                line: moved,
                from,
                to,
                extent: (lo, hi),
            });
        }
    }
    out
}

/// The longest stretch of `xs` (refined at the crossings) over which `line` lies more than
/// `deep` below the ground.
fn below_ground(ground: &Polyline, line: &Polyline, xs: &[f64], deep: f64) -> Option<(f64, f64)> {
    let depth = |x: f64| ground.y_at(x) - line.y_at(x) - deep;
    let mut best: Option<(f64, f64)> = None;
    let mut start: Option<f64> = None;
    let consider = |a: f64, b: f64, best: &mut Option<(f64, f64)>| {
        if b > a && best.is_none_or(|(p, q)| b - a > q - p) {
            *best = Some((a, b));
        }
    };
    for w in xs.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (da, db) = (depth(a), depth(b));
        // Between vertices both lines are straight: depth is linear.
        let cross = || a + (b - a) * da / (da - db);
        match (start, da > 0.0, db > 0.0) {
            (None, true, _) => start = Some(a),
            (None, false, true) => start = Some(cross()),
            _ => {}
        }
        if let (Some(s), false) = (start, db > 0.0) {
            let end = if da > 0.0 { cross() } else { a };
            consider(s, end, &mut best);
            start = None;
        }
    }
    if let Some(s) = start {
        consider(s, xs[xs.len() - 1], &mut best);
    }
    best
}

/// Where a ray from `(x0, y0)` rising at `angle` (radians above horizontal) towards `towards`
/// (−1 left, +1 right) meets the ground, if it does within `[lo, hi]`.
fn ray_to_ground(
    ground: &Polyline,
    (x0, y0): (f64, f64),
    angle: f64,
    towards: f64,
    (lo, hi): (f64, f64),
) -> Option<f64> {
    let rise = angle.tan();
    // Height of the ground above the ray, as a function of the distance d from x0.
    let gap = |d: f64| ground.y_at(x0 + towards * d) - (y0 + rise * d);
    let mut stops: Vec<f64> = ground
        .xs()
        .map(|x| (x - x0) * towards)
        .filter(|&d| d > 0.0)
        .collect();
    let reach = if towards < 0.0 { x0 - lo } else { hi - x0 };
    stops.push(reach.max(0.0));
    stops.sort_by(f64::total_cmp);
    let mut d0 = 0.0;
    let mut g0 = gap(0.0);
    for d1 in stops {
        if d1 <= d0 {
            continue;
        }
        let g1 = gap(d1);
        if g1 <= 0.0 {
            let d = d0 + (d1 - d0) * g0 / (g0 - g1);
            return Some(x0 + towards * d);
        }
        d0 = d1;
        g0 = g1;
    }
    None
}

/// The block surface on `base` from `x1` to `x2` (within its stretch below the ground), its
/// left ray rising at `left` and its right one at `right` (radians above horizontal), left to
/// right; its ends a hair above the ground.
pub(super) fn block(
    section: &Section,
    base: &Base,
    (x1, x2): (f64, f64),
    (left, right): (f64, f64),
) -> Option<Vec<(f64, f64)>> {
    let limit = 89f64.to_radians();
    if !(base.from <= x1 && x1 < x2 && x2 <= base.to)
        || !(0.0 < left && left < limit && 0.0 < right && right < limit)
    {
        return None;
    }
    let ground = &section.ground;
    let span = base.extent;
    let (y1, y2) = (base.line.y_at(x1), base.line.y_at(x2));
    let a = ray_to_ground(ground, (x1, y1), left, -1.0, span)?;
    let b = ray_to_ground(ground, (x2, y2), right, 1.0, span)?;
    let lift = HAIR * (b - a);
    let mut points = vec![(a, ground.y_at(a) + lift)];
    let gap = 1e-9 * (b - a);
    if x1 - a > gap {
        points.push((x1, y1));
    }
    points.extend(
        base.line
            .points()
            .iter()
            .filter(|p| p.0 > x1 + gap && p.0 < x2 - gap),
    );
    if b - x2 > gap {
        points.push((x2, y2));
    }
    points.push((b, ground.y_at(b) + lift));
    Some(points)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::slope::section::tests::slope_over_layer;

    /// A 1:2 slope from (0, 10) down to (20, 0), level either side, with a thin layer whose top
    /// runs 4 m below the crest and meets the face at x = 8.
    fn seam() -> Section {
        slope_over_layer(&[(-20.0, 6.0), (40.0, 6.0)], 1.0, 10.0)
    }

    #[test]
    fn a_ray_meets_the_ground_where_the_lines_cross() {
        // From (5, 2) at 45° to the left: the face y = 10 − x/2 and y = 2 + (5 − x) meet at
        // x = −6 → beyond the crest, on the level y = 10: 2 + (5 − x) = 10 → x = −3.
        let s = seam();
        let x = ray_to_ground(
            &s.ground,
            (5.0, 2.0),
            std::f64::consts::FRAC_PI_4,
            -1.0,
            (-20.0, 40.0),
        );
        assert!((x.unwrap() + 3.0).abs() < 1e-12);
        // To the right at 30°: 2 + (x − 5)·tan 30° = 10 − x/2 → x = 5 + 5.5/(tan 30° + ½)… on the face.
        let t = 30f64.to_radians().tan();
        let expected = (8.0 + 5.0 * t) / (t + 0.5);
        let x = ray_to_ground(
            &s.ground,
            (5.0, 2.0),
            30f64.to_radians(),
            1.0,
            (-20.0, 40.0),
        );
        assert!((x.unwrap() - expected).abs() < 1e-12, "{x:?} vs {expected}");
        // A ray that stays under the ground to the section's end finds nothing.
        assert!(ray_to_ground(&s.ground, (30.0, -5.0), 1e-3, 1.0, (-20.0, 40.0)).is_none());
    }

    #[test]
    fn bases_follow_each_boundary_where_it_lies_under_the_ground() {
        let s = seam();
        let bases = bases(&s);
        // The seam's top, a hair above and below; no bedrock.
        assert_eq!(bases.len(), 2);
        for base in &bases {
            // y = 6 lies under the ground from the section's left end to the face at x = 8,
            // less the thousandth of the height (10 m) kept clear: 8 − 2·0.01.
            assert_eq!(base.from, -20.0);
            assert!((base.to - (8.0 - 0.02)).abs() < 1e-3, "{}", base.to);
            assert!((base.line.y_at(3.0) - 6.0).abs() < 1e-4);
        }
        assert!(bases[0].line.y_at(0.0) > 6.0 && bases[1].line.y_at(0.0) < 6.0);
    }

    #[test]
    fn a_block_runs_along_its_base_between_two_rays() {
        let s = seam();
        let base = &bases(&s)[1];
        let (left, right) = (60f64.to_radians(), 30f64.to_radians());
        let points = block(&s, base, (-4.0, 6.0), (left, right)).unwrap();
        assert_eq!(points.len(), 4);
        let (a, b) = (points[0], points[3]);
        // Ends on the ground (a hair above), corners on the base.
        assert!((a.1 - s.ground.y_at(a.0)).abs() < 1e-4 && a.1 >= s.ground.y_at(a.0));
        assert!((b.1 - s.ground.y_at(b.0)).abs() < 1e-4 && b.1 >= s.ground.y_at(b.0));
        assert_eq!((points[1].0, points[2].0), (-4.0, 6.0));
        // The rays rise at their angles: 4 m up from y = 6 at 60° is 4/tan 60° to the left.
        assert!((a.0 - (-4.0 - 4.0 / left.tan())).abs() < 1e-4, "{a:?}");
        // Outside the base's stretch, or with an angle out of (0°, 89°), there is no block.
        assert!(block(&s, base, (-4.0, 9.0), (left, right)).is_none());
        assert!(block(&s, base, (-4.0, 6.0), (0.0, right)).is_none());
        assert!(block(&s, base, (6.0, -4.0), (left, right)).is_none());
    }
}
