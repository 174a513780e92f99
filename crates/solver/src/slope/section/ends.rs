//! Where a slip surface enters and leaves the ground (model §4.2).

use smallvec::{smallvec, SmallVec};

use super::model::Section;
use super::polyline::Polyline;
use super::shape::SlipShape;
use crate::slope::error::{SlopeError, SlopeParameter};

/// Relative tolerance on heights for "at the ground".
const ON_GROUND: f64 = 1e-9;

/// Relative distance of a crossing from a ground vertex that is rounding.
const VERTEX_ROUNDING: f64 = 1e-12;

/// Entry and exit of each mass a surface cuts out of the ground: a few, on the stack (a search
/// asks at every circle).
pub(super) type Pieces = SmallVec<[(f64, f64); 4]>;

/// The x of entry and exit (entry < exit) of the masses `shape` may cut out of `ground`, the
/// largest within the stated ground first (a polyline cuts one).
pub(super) fn ends(section: &Section, shape: &SlipShape) -> Result<Pieces, SlopeError> {
    let ground = &section.ground;
    // The masses are sized within the stated ground, unless it runs on level by definition.
    let span = (!section.is_level_beyond_ends()).then(|| ground.x_range());
    match shape {
        SlipShape::Circle { centre, radius } => circle_ends(ground, span, *centre, *radius),
        SlipShape::Polyline(line) => polyline_ends(ground, line).map(|e| smallvec![e]),
    }
}

/// The pairs of the arc's crossings of the ground that bound a part of it below the ground, the
/// largest mass within the section's x-range first (the area between the ground and the arc
/// over the stated ground; two reaching equally large is ambiguous: an error).
fn circle_ends(
    ground: &Polyline,
    span: Option<(f64, f64)>,
    centre: (f64, f64),
    radius: f64,
) -> Result<Pieces, SlopeError> {
    let (xc, yc) = centre;
    let (left, right) = (xc - radius, xc + radius);
    let arc = |x: f64| yc - (radius * radius - (x - xc).powi(2)).max(0.0).sqrt();
    let cuts = arc_cuts(ground, centre, radius);
    let depth = |x: f64| ground.y_at(x) - arc(x);
    let masses = cuts
        .windows(2)
        .filter(|w| {
            let m = 0.5 * (w[0] + w[1]);
            w[1] > w[0] && depth(m) > 0.0
        })
        .map(|w| {
            (
                w[0],
                w[1],
                mass_area(ground, span, centre, radius, (w[0], w[1])),
            )
        })
        .collect::<SmallVec<[_; 4]>>();
    let largest = masses.iter().map(|p| p.2).fold(f64::NEG_INFINITY, f64::max);
    let ties = masses
        .iter()
        .filter(|p| p.2 >= largest - 1e-9 * largest.abs().max(radius * radius))
        .count();
    if ties > 1 {
        return Err(SlopeError::NoSlipMass {
            parameter: SlopeParameter::CircleCentre,
            reason: format!(
                "the circle cuts the ground into {ties} masses of the same size: which one \
                 slides is ambiguous — move the centre, change the radius or choose one \
                 (circle.mass)"
            ),
        });
    }
    let mut pieces = masses;
    pieces.sort_by(|a, b| b.2.total_cmp(&a.2));
    let Some(&(entry, exit, _)) = pieces.first() else {
        return Err(SlopeError::NoSlipMass {
            parameter: SlopeParameter::CircleCentre,
            reason: format!(
                "the circle (centre ({xc}, {yc}), radius {radius}) does not pass below the ground: \
                 lower the centre or enlarge the radius"
            ),
        });
    };
    if entry == left || exit == right {
        return Err(SlopeError::NoSlipMass {
            parameter: SlopeParameter::CircleCentre,
            reason: format!(
                "the centre ({xc}, {yc}) lies below the ground at the height of the centre, so \
                 the lower half of the circle does not come back to the surface on both sides: \
                 raise the centre or shrink the radius"
            ),
        });
    }
    let snap = |x: f64| on_vertex(ground, x, &arc, radius);
    Ok(pieces
        .into_iter()
        .filter(|p| p.0 != left && p.1 != right)
        .map(|(a, b, _)| (snap(a), snap(b)))
        .collect())
}

/// The area between the ground and the arc over [a, b], clipped to `span` when given (the
/// ground straight on each piece, the arc integrated in closed form).
fn mass_area(
    ground: &Polyline,
    span: Option<(f64, f64)>,
    (xc, yc): (f64, f64),
    radius: f64,
    (a, b): (f64, f64),
) -> f64 {
    let (a, b) = span.map_or((a, b), |(first, last)| (a.max(first), b.min(last)));
    if b <= a {
        return 0.0;
    }
    // ∫ √(R² − u²) du.
    let root = |x: f64| {
        let u = (x - xc).clamp(-radius, radius);
        0.5 * (u * (radius * radius - u * u).max(0.0).sqrt()
            + radius * radius * (u / radius).asin())
    };
    let under_ground: f64 = ground
        .pieces(a, b)
        .map(|(x0, x1, m, c)| 0.5 * m * (x1 * x1 - x0 * x0) + c * (x1 - x0))
        .sum();
    under_ground - (yc * (b - a) - (root(b) - root(a)))
}

/// The ends of the circle's lower half and its crossings of the ground between them, sorted,
/// each once.
fn arc_cuts(ground: &Polyline, centre: (f64, f64), radius: f64) -> SmallVec<[f64; 10]> {
    let (xc, _) = centre;
    let (left, right) = (xc - radius, xc + radius);
    let mut cuts: SmallVec<[f64; 10]> = std::iter::once(left)
        .chain(
            ground
                .circle_crossings(centre, radius, left, right)
                .into_iter()
                .filter(|c| c.1)
                .map(|c| c.0),
        )
        .chain(std::iter::once(right))
        .collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    cuts
}

/// A crossing within rounding (1e-12 of the radius) of a ground vertex that the arc passes
/// through, moved onto that vertex: a circle placed through a toe (the simple form's lower end)
/// ends exactly there, not 1e-14 beside it.
fn on_vertex(ground: &Polyline, x: f64, arc: &impl Fn(f64) -> f64, radius: f64) -> f64 {
    let tolerance = VERTEX_ROUNDING * radius.max(x.abs());
    ground
        .points()
        .iter()
        .find(|v| (v.0 - x).abs() <= tolerance && (arc(v.0) - v.1).abs() <= tolerance)
        .map_or(x, |v| v.0)
}

/// The first and last crossings of the surface with the ground; the surface must start and end
/// at or above the ground and stay below it in between.
fn polyline_ends(ground: &Polyline, line: &Polyline) -> Result<(f64, f64), SlopeError> {
    let points = line.points();
    let (first, last) = (points[0], points[points.len() - 1]);
    let scale = points
        .iter()
        .chain(ground.points())
        .fold(1.0f64, |m, p| m.max(p.0.abs()).max(p.1.abs()));
    let tolerance = ON_GROUND * scale;
    let depth = |x: f64| ground.y_at(x) - line.y_at(x);
    let fail = |reason: String| {
        Err(SlopeError::NoSlipMass {
            parameter: SlopeParameter::Surface,
            reason,
        })
    };
    if points.len() < 2 {
        return fail("needs at least two points".to_owned());
    }
    for (name, p) in [("first", first), ("last", last)] {
        if depth(p.0) > tolerance {
            return fail(format!(
                "its {name} point ({}, {}) lies below the ground (at {}): start and end the \
                 surface at or above the ground",
                p.0,
                p.1,
                ground.y_at(p.0)
            ));
        }
    }
    let mut crossings = line.crossings(ground, first.0, last.0);
    for p in [first, last] {
        if depth(p.0).abs() <= tolerance {
            crossings.push(p.0);
        }
    }
    // Vertices of either line lying on the other are crossings the sign test above misses.
    for x in line.xs().chain(ground.xs()) {
        if x > first.0 && x < last.0 && depth(x).abs() <= tolerance {
            crossings.push(x);
        }
    }
    crossings.sort_by(f64::total_cmp);
    crossings.dedup();
    let (Some(&entry), Some(&exit)) = (crossings.first(), crossings.last()) else {
        return fail("it does not pass below the ground".to_owned());
    };
    if exit - entry <= tolerance {
        return fail("it does not pass below the ground".to_owned());
    }
    // Between entry and exit it must stay at or below the ground.
    let mut xs: Vec<f64> = line
        .xs()
        .chain(ground.xs())
        .filter(|&x| x > entry && x < exit)
        .collect();
    xs.extend(crossings.windows(2).map(|w| 0.5 * (w[0] + w[1])));
    if let Some(x) = xs.into_iter().find(|&x| depth(x) < -tolerance) {
        return fail(format!(
            "it rises above the ground at x = {x} between its entry (x = {entry}) and exit \
             (x = {exit}): one surface must bound one sliding mass"
        ));
    }
    Ok((entry, exit))
}
