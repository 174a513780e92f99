//! The critical non-circular surface (SPEC §4.4): from a circle (the critical one, say), a
//! polyline of `vertices` points at fixed fractions of the way from entry to exit, whose interior
//! heights and whose entry and exit move to lower Spencer's F (Nelder–Mead, restarted from its
//! own answer while that still lowers F), under a time budget. Kinematically admissible: the
//! base never bends back upwards by more than `REVERSE_BEND_DEG` between segments (the surface
//! is concave upwards but for that), stays below the ground and above bedrock.

use std::num::NonZeroUsize;
use std::time::Instant;

use super::cut::place;
use super::polyline::Polyline;
use super::{Section, SlipShape};
use crate::numerics::nelder_mead;
use crate::slope::spencer::{spencer_factor_outcome, FactorOutcome, Seismic, SpencerSettings};

/// The most a segment may turn downwards from the one before it, in degrees.
const REVERSE_BEND_DEG: f64 = 10.0;

/// What the non-circular search found.
#[derive(Debug, Clone, PartialEq)]
pub struct NoncircularSearch {
    /// The surface, left to right.
    pub surface: Vec<(f64, f64)>,
    /// Its factor of safety.
    pub factor_of_safety: f64,
    /// F after each round of the search, the start first.
    pub path: Vec<f64>,
    /// Surfaces evaluated.
    pub evaluations: usize,
    /// Whether the time budget ended the search.
    pub timed_out: bool,
}

/// The surface of `v`: entry x, exit x, then the interior heights as depths below the ground.
fn surface_of(section: &Section, v: &[f64]) -> Option<Vec<(f64, f64)>> {
    let (a, b) = (v[0], v[1]);
    if b <= a || b.is_nan() || a.is_nan() {
        return None;
    }
    let n = v.len();
    let ground = &section.ground;
    // The ends sit just above the ground so that the surface crosses it there.
    let lift = 1e-6 * (b - a);
    let mut points = Vec::with_capacity(n);
    points.push((a, ground.y_at(a) + lift));
    for (i, depth) in v[2..].iter().enumerate() {
        let x = a + (b - a) * (i + 1) as f64 / (n - 1) as f64;
        if *depth <= 0.0 {
            return None;
        }
        let y = ground.y_at(x) - depth;
        if section.bedrock.as_ref().is_some_and(|r| y < r.y_at(x)) {
            return None;
        }
        points.push((x, y));
    }
    points.push((b, ground.y_at(b) + lift));
    // Concave upwards but for small reverse bends.
    let limit = REVERSE_BEND_DEG.to_radians();
    let angles: Vec<f64> = points
        .windows(2)
        .map(|w| (w[1].1 - w[0].1).atan2(w[1].0 - w[0].0))
        .collect();
    // Whichever way the slope faces, a bowl's segments steepen from left to right.
    angles
        .windows(2)
        .all(|w| w[1] >= w[0] - limit)
        .then_some(points)
}

/// Searches from `start` (a circle's polyline, left to right) with `vertices` points.
pub fn search_noncircular(
    section: &Section,
    start: &[(f64, f64)],
    vertices: usize,
    slices: NonZeroUsize,
    seismic: Seismic,
    settings: &SpencerSettings,
    deadline: Option<Instant>,
) -> Option<NoncircularSearch> {
    let mirror = section.mirrored();
    // Trial surfaces without a Newton solution are skipped rather than searched for one.
    let settings = &SpencerSettings {
        fallback: false,
        ..*settings
    };
    let evaluations = std::cell::Cell::new(0usize);
    let late = || deadline.is_some_and(|d| Instant::now() >= d);
    // A trial's F at the search's slices, if four times as many give it again (to 1 %): a
    // surface can have a root at one slicing only, which an optimiser would happily exploit.
    let doubled = NonZeroUsize::new(4 * slices.get()).unwrap_or(slices);
    let factor = |v: &[f64]| -> f64 {
        if late() {
            return f64::INFINITY;
        }
        let Some(points) = surface_of(section, v) else {
            return f64::INFINITY;
        };
        let Ok(line) = Polyline::new(points) else {
            return f64::INFINITY;
        };
        evaluations.set(evaluations.get() + 1);
        let shape = SlipShape::Polyline(line);
        let at = |n: NonZeroUsize| -> Option<f64> {
            let cut = place(section, Some(&mirror), &shape, n, seismic, None).ok()?;
            match spencer_factor_outcome(&cut.model, settings) {
                FactorOutcome::Solved(s) => Some(s.factor_of_safety),
                FactorOutcome::Unsolved { .. } => None,
            }
        };
        match (at(slices), at(doubled)) {
            (Some(f), Some(g)) if (f - g).abs() <= 1e-2 * f => f,
            _ => f64::INFINITY,
        }
    };
    // The start: the circle's surface resampled at the vertices.
    let (a, b) = (start.first()?.0, start.last()?.0);
    let start_line = Polyline::new(start.to_vec()).ok()?;
    let n = vertices.max(3);
    let mut v = vec![a, b];
    for i in 1..n - 1 {
        let x = a + (b - a) * i as f64 / (n - 1) as f64;
        v.push((section.ground.y_at(x) - start_line.y_at(x)).max(1e-6 * (b - a)));
    }
    let mut best = factor(&v);
    if !best.is_finite() {
        return None;
    }
    let mut path = vec![best];
    let span = b - a;
    let mut timed_out = false;
    for _ in 0..8 {
        let depth = v[2..].iter().fold(0.0f64, |m, d| m.max(*d));
        let mut step = vec![0.05 * span, 0.05 * span];
        step.extend(std::iter::repeat_n(0.15 * depth.max(1e-3 * span), n - 2));
        let found = nelder_mead(factor, &v, &step, 1e-7 * span, 400 * n);
        if late() {
            timed_out = true;
        }
        if found.value >= best || found.value.is_nan() {
            break;
        }
        let settled = found.value >= best * (1.0 - 1e-3);
        best = found.value;
        v = found.point;
        path.push(best);
        if settled {
            break;
        }
        if timed_out {
            break;
        }
    }
    Some(NoncircularSearch {
        surface: surface_of(section, &v)?,
        factor_of_safety: best,
        path,
        evaluations: evaluations.get(),
        timed_out,
    })
}
