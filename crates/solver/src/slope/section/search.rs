//! The critical circle of a section (model §4.4): centres on a grid, several radii at each (a
//! range, tangents to given elevations, or chosen from the section), the least F over radii
//! mapped over the centres, then Nelder–Mead over (x_c, y_c, R) from the best few grid points.
//!
//! Given bounds are hard: the answer's centre lies inside them and a minimum on their edge is
//! reported as such. Automatic bounds cover toe, face and deep circles of the section and move
//! (at most `max_regrids` times) when the minimum lies on their edge. Circles that cut a mass
//! but have no solution are counted, and flagged when they lie next to the minimum.

use std::num::NonZeroUsize;

use rayon::prelude::*;

use super::model::Section;
use super::shape::SlipShape;
use super::trial::{trial, Outcome, TrialSetup};
use crate::budget::Budget;
use crate::numerics::{nelder_mead_to, Minimum};
use crate::slope::circles::{
    self, search, spaced, CentreGrid, CentreResult, CircleFamily, FactorGrid, Start, F_RESOLUTION,
};
use crate::slope::spencer::methods::{InterSliceFunction, Method};
use crate::slope::spencer::{Seismic, SpencerSettings};

/// The radii tried at each centre.
#[derive(Debug, Clone, PartialEq)]
pub enum Radii {
    /// `count` radii evenly from `min` to `max`.
    Range {
        /// Smallest radius.
        min: f64,
        /// Largest radius.
        max: f64,
        /// Number of radii (≥ 1).
        count: usize,
    },
    /// Circles tangent to each of these elevations (R = y_c − y), below the centre.
    Tangent(Vec<f64>),
    /// `count` radii from just cutting the ground to a depth of one section height below its
    /// lowest point (or down to the bedrock).
    Automatic {
        /// Number of radii (≥ 1).
        count: usize,
    },
}

/// The region of centres and the radii.
#[derive(Debug, Clone, PartialEq)]
pub struct CircleRegion {
    /// The grid of centres.
    pub centres: CentreGrid,
    /// Radii at each centre.
    pub radii: Radii,
}

/// Extent of the section's relief: (x_lo, x_hi, y_low, y_top), the x-range of the non-level
/// part of the ground (all of it when level).
fn relief(section: &Section) -> (f64, f64, f64, f64) {
    let p = section.ground.points();
    let sloping: Vec<f64> = p
        .windows(2)
        .filter(|w| w[0].1 != w[1].1)
        .flat_map(|w| [w[0].0, w[1].0])
        .collect();
    let (x_lo, x_hi) = if sloping.is_empty() {
        (p[0].0, p[p.len() - 1].0)
    } else {
        sloping
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            })
    };
    let (y_low, y_top) = p
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), q| {
            (a.min(q.1), b.max(q.1))
        });
    (x_lo, x_hi, y_low, y_top)
}

impl CircleRegion {
    /// Centres over the sloping part of the ground widened by half its size each way, from
    /// half-way up the relief to two sizes above its top; radii chosen per centre.
    pub fn automatic(section: &Section, nx: usize, ny: usize, nr: usize) -> Self {
        let (x_lo, x_hi, y_low, y_top) = relief(section);
        let size = (x_hi - x_lo).max(y_top - y_low).max(1e-6);
        Self {
            centres: CentreGrid {
                x_min: x_lo - 0.5 * size,
                x_max: x_hi + 0.5 * size,
                y_min: y_low + 0.5 * (y_top - y_low).max(0.1 * size),
                y_max: y_top + 2.0 * size,
                nx,
                ny,
            },
            radii: Radii::Automatic { count: nr },
        }
    }
}

/// Settings of the search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircleSearchSettings<'a> {
    /// Settings of each Spencer solution.
    pub spencer: SpencerSettings,
    /// Grid points the refinement starts from. Defaults to 3.
    pub starts: usize,
    /// Nelder–Mead evaluations per start. Defaults to 400.
    pub max_refine_evaluations: usize,
    /// Times automatic bounds may move. Defaults to 3.
    pub max_regrids: usize,
    /// Circles whose greatest depth below the ground is smaller are no candidates. Defaults
    /// to 0.
    pub min_depth: f64,
    /// Whether a circle that would cross the bedrock is no candidate (`false`: it follows the
    /// bedrock, a composite surface). Defaults to false.
    pub circles_only: bool,
    /// Whether a circle may enter or leave the ground beyond the section's x-range (the ground
    /// taken level there). Defaults to false: such a circle is no candidate.
    pub beyond_ground: bool,
    /// The method the circles are ranked by: Spencer's (`None`, the default) or another's,
    /// for its own critical circle.
    pub method: Option<(Method, &'a InterSliceFunction)>,
}

impl Default for CircleSearchSettings<'_> {
    fn default() -> Self {
        Self {
            spencer: SpencerSettings::default(),
            starts: 3,
            max_refine_evaluations: 400,
            max_regrids: 3,
            min_depth: 0.0,
            circles_only: false,
            beyond_ground: false,
            method: None,
        }
    }
}

/// What the search found: the critical circle as its centre and radius.
pub type CircleSearch = circles::CircleSearch<((f64, f64), f64)>;

struct Evaluator<'a> {
    section: &'a Section,
    mirror: Section,
    slices: NonZeroUsize,
    seismic: Seismic,
    spencer: SpencerSettings,
    budget: &'a Budget,
    /// Lowest y a circle may usefully reach (automatic radii).
    deep: f64,
    /// Shallower circles are no candidates.
    min_depth: f64,
    /// Circles that would cross the bedrock are no candidates.
    circles_only: bool,
    /// Circles beyond the section's x-range are candidates.
    beyond_ground: bool,
    /// The method the circles are ranked by (`None`: Spencer's).
    method: Option<(Method, &'a InterSliceFunction)>,
}

impl Evaluator<'_> {
    fn is_late(&self) -> bool {
        self.budget.is_spent()
    }

    /// The circle's outcome, Bishop's start looked for from `near` (a neighbour's F) first.
    fn factor(&self, centre: (f64, f64), radius: f64, near: Option<f64>) -> Outcome {
        let setup = TrialSetup {
            section: self.section,
            mirror: &self.mirror,
            slices: self.slices,
            seismic: self.seismic,
            spencer: &self.spencer,
            min_depth: self.min_depth,
            beyond_ground: self.beyond_ground,
            method: self.method,
        };
        trial(&setup, &SlipShape::Circle { centre, radius }, near, |cut| {
            self.circles_only && self.crosses_bedrock(cut, centre, radius)
        })
    }

    /// Whether the circle dips below the bedrock between its ends (its mass then follows the
    /// bedrock). Bedrock less arc is concave on each straight stretch of the bedrock (slope m),
    /// largest where the arc has its slope, x − x_c = m·R/√(1 + m²), or at the stretch's end.
    fn crosses_bedrock(&self, cut: &super::cut::Cut, centre: (f64, f64), radius: f64) -> bool {
        let frame = if cut.mirrored {
            &self.mirror
        } else {
            self.section
        };
        let Some(bedrock) = frame.bedrock.as_ref() else {
            return false;
        };
        let xc = if cut.mirrored { -centre.0 } else { centre.0 };
        let arc = |x: f64| centre.1 - (radius * radius - (x - xc).powi(2)).max(0.0).sqrt();
        let (a, b) = (cut.ends.0 .0, cut.ends.1 .0);
        let rounding = 1e-9 * radius;
        bedrock.pieces(a, b).any(|(x0, x1, m, _)| {
            let x = (xc + m * radius / m.hypot(1.0)).clamp(x0, x1);
            bedrock.y_at(x) - arc(x) > rounding
        })
    }

    fn radii(&self, radii: &Radii, (xc, yc): (f64, f64)) -> Vec<f64> {
        match radii {
            Radii::Range { min, max, count } => spaced(*min, *max, *count),
            Radii::Tangent(ys) => ys.iter().filter(|&&y| y < yc).map(|y| yc - y).collect(),
            Radii::Automatic { count } => {
                let ground = &self.section.ground;
                let p = ground.points();
                let span = (p[p.len() - 1].0 - p[0].0).max(1.0);
                let near = ground.distance_to(
                    (xc, yc),
                    p[0].0 - 10.0 * span,
                    p[p.len() - 1].0 + 10.0 * span,
                );
                let far = yc - self.deep;
                if far <= near {
                    return Vec::new();
                }
                let n = (*count).max(1);
                (1..=n)
                    .map(|k| near + (far - near) * k as f64 / n as f64)
                    .collect()
            }
        }
    }
}

impl Evaluator<'_> {
    /// The least F over the radii at each centre of the row at `y` along `xs`.
    fn row(&self, radii: &Radii, xs: &[f64], y: f64) -> Vec<CentreResult> {
        // Each circle's F starts the search for Bishop's F of the circle of the same radius
        // index at the next centre along the row (its nearest neighbour), or, before there is
        // one, of the next radius.
        let mut near: Vec<Option<f64>> = Vec::new();
        let mut last = None;
        xs.iter()
            .map(|&x| {
                let mut best: Option<(f64, f64)> = None;
                let mut unsolved = 0;
                let mut bishop: Option<f64> = None;
                for (k, r) in self.radii(radii, (x, y)).into_iter().enumerate() {
                    if self.is_late() {
                        break;
                    }
                    if near.len() <= k {
                        near.resize(k + 1, None);
                    }
                    let outcome = self.factor((x, y), r, near[k].or(last));
                    if let Ok(s) = &outcome {
                        (near[k], last) = (Some(s.factor_of_safety), Some(s.factor_of_safety));
                    }
                    match outcome.map(|s| s.factor_of_safety) {
                        Ok(f) if best.is_none_or(|b| f < b.0) => best = Some((f, r)),
                        Ok(_) | Err(None) => {}
                        Err(Some(b)) => {
                            unsolved += 1;
                            if let Some(b) = b {
                                bishop = Some(bishop.map_or(b, |l| l.min(b)));
                            }
                        }
                    }
                }
                CentreResult {
                    best,
                    unsolved,
                    bishop,
                }
            })
            .collect()
    }

    /// Nelder–Mead on (x, y, R) from each start (R, i, j) of the grid (`factors`), inside the
    /// region (`centres`) and its `radii`: each start's least F, its point and its evaluations.
    fn refine(
        &self,
        centres: &CentreGrid,
        radii: &Radii,
        starts: &[Start],
        factors: &FactorGrid,
        settings: &CircleSearchSettings<'_>,
    ) -> Vec<Minimum> {
        let (xs, ys) = (factors.xs.as_slice(), factors.ys.as_slice());
        let (dx, dy) = centres.cell();
        let inside = |v: &[f64]| {
            v[0] >= centres.x_min
                && v[0] <= centres.x_max
                && v[1] >= centres.y_min
                && v[1] <= centres.y_max
        };
        let radius_allowed = |v: &[f64]| match radii {
            Radii::Range { min, max, .. } => v[2] >= *min && v[2] <= *max,
            Radii::Tangent(ys) => {
                let below: Vec<f64> = ys.iter().copied().filter(|&y| y < v[1]).collect();
                let (lo, hi) = below
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| {
                        (a.min(y), b.max(y))
                    });
                !below.is_empty() && v[2] >= v[1] - hi && v[2] <= v[1] - lo
            }
            Radii::Automatic { .. } => v[2] > 0.0 && v[2] <= v[1] - self.deep,
        };
        starts
            .par_iter()
            .map(|&Start { radius: r, i, j }| {
                // The last F found starts the next circle's search for Bishop's F.
                let near = std::cell::Cell::new(None);
                let objective = |v: &[f64]| {
                    if self.is_late() || !inside(v) || !radius_allowed(v) {
                        return f64::INFINITY;
                    }
                    let outcome = self.factor((v[0], v[1]), v[2], near.get());
                    match outcome {
                        Ok(s) => {
                            near.set(Some(s.factor_of_safety));
                            s.factor_of_safety
                        }
                        Err(_) => f64::INFINITY,
                    }
                };
                let scale = dx.abs().max(dy.abs()).max(r);
                nelder_mead_to(
                    objective,
                    &[xs[i], ys[j], r],
                    &[0.5 * dx, 0.5 * dy, 0.05 * r],
                    1e-9 * scale,
                    F_RESOLUTION,
                    settings.max_refine_evaluations,
                )
            })
            .collect()
    }
}

impl<'a> Evaluator<'a> {
    /// The evaluator of circles of `section` within `budget`; automatic radii reach down to
    /// the bedrock's lowest point, or the relief's height below its foot.
    fn new(
        section: &'a Section,
        slices: NonZeroUsize,
        seismic: Seismic,
        settings: &CircleSearchSettings<'a>,
        budget: &'a Budget,
    ) -> Self {
        let (_, _, y_low, y_top) = relief(section);
        let deep = section
            .bedrock
            .as_ref()
            .map_or(y_low - (y_top - y_low).max(1e-6), |b| {
                b.points().iter().fold(f64::INFINITY, |m, p| m.min(p.1))
            });
        Evaluator {
            section,
            mirror: section.mirrored(),
            slices,
            seismic,
            spencer: settings.spencer,
            budget,
            deep,
            min_depth: settings.min_depth,
            circles_only: settings.circles_only,
            beyond_ground: settings.beyond_ground,
            method: settings.method,
        }
    }
}

/// Whether the best grid point (i, j) of an nx × ny grid lies on its edge, or the refined
/// centre `v` on the region's bounds (to 1e-6 of a cell).
fn is_on_edge(region: &CentreGrid, (bi, bj): (usize, usize), v: &[f64]) -> bool {
    let (dx, dy) = region.cell();
    let tolerance = 1e-6 * dx.abs().max(dy.abs());
    region.is_edge_point((bi, bj))
        || v[0] - region.x_min <= tolerance
        || region.x_max - v[0] <= tolerance
        || v[1] - region.y_min <= tolerance
        || region.y_max - v[1] <= tolerance
}

/// A section's circles: several radii at each centre (a range, tangents, or chosen from the
/// section), refined over (x, y, R).
struct SeveralRadii<'a> {
    evaluator: Evaluator<'a>,
    radii: &'a Radii,
    hard: bool,
    settings: &'a CircleSearchSettings<'a>,
}

impl CircleFamily for SeveralRadii<'_> {
    type Circle = ((f64, f64), f64);

    fn budget(&self) -> &Budget {
        self.evaluator.budget
    }

    fn starts(&self) -> usize {
        self.settings.starts
    }

    fn row(&self, xs: &[f64], y: f64) -> Vec<CentreResult> {
        self.evaluator.row(self.radii, xs, y)
    }

    fn grid_evaluations(&self, xs: &[f64], ys: &[f64]) -> usize {
        xs.iter()
            .flat_map(|&x| ys.iter().map(move |&y| (x, y)))
            .map(|c| self.evaluator.radii(self.radii, c).len())
            .sum::<usize>()
    }

    fn refine(&self, centres: &CentreGrid, starts: &[Start], factors: &FactorGrid) -> Vec<Minimum> {
        self.evaluator
            .refine(centres, self.radii, starts, factors, self.settings)
    }

    fn accepts(&self, refined: &Minimum, f0: f64) -> bool {
        refined.value.is_finite() && refined.value <= f0
    }

    fn grid_point(&self, factors: &FactorGrid, start: Start) -> Vec<f64> {
        vec![factors.xs[start.i], factors.ys[start.j], start.radius]
    }

    fn is_on_edge(&self, centres: &CentreGrid, point: (usize, usize), v: &[f64]) -> bool {
        is_on_edge(centres, point, v)
    }

    fn may_move(&self, regrids: usize) -> bool {
        !self.hard && regrids < self.settings.max_regrids
    }

    fn moved(&self, centres: &CentreGrid, v: &[f64]) -> CentreGrid {
        // Centre a region of the same size on the best point found.
        let (half_x, half_y) = (
            0.5 * (centres.x_max - centres.x_min),
            0.5 * (centres.y_max - centres.y_min),
        );
        CentreGrid {
            x_min: v[0] - half_x,
            x_max: v[0] + half_x,
            y_min: v[1] - half_y,
            y_max: v[1] + half_y,
            ..*centres
        }
    }

    fn circle(&self, v: &[f64]) -> ((f64, f64), f64) {
        ((v[0], v[1]), v[2])
    }
}

/// Searches the critical circle of `section` over `region`; `hard` bounds stay put, automatic
/// ones move when the minimum lies on their edge. No circle is evaluated once `budget` is spent;
/// the search's stop then says why.
pub fn search_circles(
    section: &Section,
    region: &CircleRegion,
    hard: bool,
    slices: NonZeroUsize,
    seismic: Seismic,
    settings: &CircleSearchSettings<'_>,
    budget: &Budget,
) -> CircleSearch {
    let family = SeveralRadii {
        evaluator: Evaluator::new(section, slices, seismic, settings, budget),
        radii: &region.radii,
        hard,
        settings,
    };
    search(&family, region.centres)
}
