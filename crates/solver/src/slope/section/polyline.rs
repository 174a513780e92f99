//! Polylines of a cross-section (ground, layer tops, bedrock, water line, slip surfaces): points
//! with strictly increasing x, continued horizontally beyond their ends.

/// A circle's crossings of a line, (x, whether the line lies at or below the centre there):
/// a handful, kept on the stack (a search asks for them at every circle).
pub type Crossings = smallvec::SmallVec<[(f64, bool); 8]>;

/// A polyline with strictly increasing x and at least one point.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline {
    points: Vec<(f64, f64)>,
    /// Slope of each segment, so that reading y needs no division.
    slopes: Vec<f64>,
}

/// Why a list of points is not a polyline.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PolylineError {
    /// No points.
    Empty,
    /// Point `index` is not finite or beyond the allowed magnitude.
    NotFinite {
        /// 0-based index of the point.
        index: usize,
    },
    /// Point `index` does not lie to the right of the one before it.
    NotIncreasing {
        /// 0-based index of the point.
        index: usize,
    },
    /// Point `index` lies too close to the one before it for its slope to be computed
    /// (closer than [`MIN_STEP`] of the line's extent).
    TooClose {
        /// 0-based index of the point.
        index: usize,
    },
}

impl std::fmt::Display for PolylineError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Empty => write!(f, "needs at least one point"),
            Self::NotFinite { index } => {
                write!(f, "point {index} must be finite, |x|, |y| ≤ 1e9")
            }
            Self::TooClose { index } => write!(
                f,
                "point {index} lies closer than 1e-9 of the line's extent to point {} in x: \
                 merge the two points or move them apart",
                index.saturating_sub(1)
            ),
            Self::NotIncreasing { index } => write!(
                f,
                "point {index} must lie to the right of point {}: x strictly increasing",
                index.saturating_sub(1)
            ),
        }
    }
}

/// Largest coordinate accepted, as elsewhere in the service.
const MAX_COORDINATE: f64 = 1e9;

/// Least x-step between consecutive points, relative to the line's extent (at least 1): a step
/// of 5e-324 makes a slope of 1e300 or an infinite one, and every height along it meaningless.
pub const MIN_STEP: f64 = 1e-9;

impl Polyline {
    /// The polyline through `points`, which must run left to right.
    pub fn new(points: Vec<(f64, f64)>) -> Result<Self, PolylineError> {
        if points.is_empty() {
            return Err(PolylineError::Empty);
        }
        for (index, &(x, y)) in points.iter().enumerate() {
            if !(x.is_finite() && y.is_finite())
                || x.abs() > MAX_COORDINATE
                || y.abs() > MAX_COORDINATE
            {
                return Err(PolylineError::NotFinite { index });
            }
            if index > 0 && x <= points[index - 1].0 {
                return Err(PolylineError::NotIncreasing { index });
            }
        }
        Ok(Self::through(points))
    }

    /// The polyline through `points` given as input: as [`Polyline::new`], and no x-step below
    /// [`MIN_STEP`] of the line's extent (a step of 5e-324 makes every height along it
    /// meaningless). Lines the solver builds itself (cut surfaces, whose slice sides may lie
    /// closer) are made with [`Polyline::new`].
    pub fn from_input(points: Vec<(f64, f64)>) -> Result<Self, PolylineError> {
        let extent = points
            .iter()
            .fold(1.0f64, |m, p| m.max(p.0.abs()).max(p.1.abs()));
        let close = (1..points.len()).find(|&i| {
            let step = points[i].0 - points[i - 1].0;
            step > 0.0 && step < MIN_STEP * extent
        });
        let line = Self::new(points)?;
        match close {
            Some(index) => Err(PolylineError::TooClose { index }),
            None => Ok(line),
        }
    }

    /// The polyline through points known to run left to right.
    fn through(points: Vec<(f64, f64)>) -> Self {
        let slopes = points
            .windows(2)
            .map(|w| (w[1].1 - w[0].1) / (w[1].0 - w[0].0))
            .collect();
        Self { points, slopes }
    }

    /// The points.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }

    /// The x of its first and last points: the range it is stated over.
    pub fn x_range(&self) -> (f64, f64) {
        (self.points[0].0, self.points[self.points.len() - 1].0)
    }

    /// The same line seen from behind (x → −x): for sections facing left.
    pub fn mirrored(&self) -> Self {
        Self::through(self.points.iter().rev().map(|&(x, y)| (-x, y)).collect())
    }

    /// y at `x`, continued horizontally beyond the ends.
    pub fn y_at(&self, x: f64) -> f64 {
        let p = &self.points;
        let last = p.len() - 1;
        if x <= p[0].0 || last == 0 {
            return p[0].1;
        }
        if x >= p[last].0 {
            return p[last].1;
        }
        // The segment [p[i-1], p[i]] with p[i-1].x < x ≤ p[i].x (an x that is NaN finds none:
        // the first segment, whose height is then NaN too, never an index out of bounds).
        let i = p.partition_point(|q| q.0 < x).max(1);
        let (x0, y0) = p[i - 1];
        y0 + self.slopes[i - 1] * (x - x0)
    }

    /// dy/dx at `x` (0 beyond the ends; at a vertex, the piece to its left).
    pub fn slope_at(&self, x: f64) -> f64 {
        let p = &self.points;
        let last = p.len() - 1;
        if last == 0 || !(x > p[0].0 && x <= p[last].0) {
            return 0.0;
        }
        self.slopes[p.partition_point(|q| q.0 < x).max(1) - 1]
    }

    /// x of the vertices.
    pub fn xs(&self) -> impl Iterator<Item = f64> + '_ {
        self.points.iter().map(|p| p.0)
    }

    /// The straight pieces over [x_min, x_max] as (x0, x1, slope, intercept), the horizontal
    /// continuations included.
    pub fn pieces(
        &self,
        x_min: f64,
        x_max: f64,
    ) -> impl Iterator<Item = (f64, f64, f64, f64)> + '_ {
        // The vertices strictly inside, sorted: no two cuts coincide unless x_min = x_max.
        let cuts = std::iter::once(x_min)
            .chain(
                self.points
                    .iter()
                    .map(|p| p.0)
                    .filter(move |&x| x > x_min && x < x_max),
            )
            .chain(std::iter::once(x_max));
        cuts.clone()
            .zip(cuts.skip(1))
            .filter(|(x0, x1)| x1 > x0)
            .map(|(x0, x1)| {
                let (y0, y1) = (self.y_at(x0), self.y_at(x1));
                let m = (y1 - y0) / (x1 - x0);
                (x0, x1, m, y0 - m * x0)
            })
    }

    /// The least distance from `point` to the line over [x_min, x_max].
    pub fn distance_to(&self, point: (f64, f64), x_min: f64, x_max: f64) -> f64 {
        self.pieces(x_min, x_max)
            .map(|(x0, x1, m, k)| {
                let (a, b) = ((x0, m * x0 + k), (x1, m * x1 + k));
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let t = (((point.0 - a.0) * dx + (point.1 - a.1) * dy) / (dx * dx + dy * dy))
                    .clamp(0.0, 1.0);
                (a.0 + t * dx - point.0).hypot(a.1 + t * dy - point.1)
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// x where this line and `other` cross (or touch) within (x_min, x_max).
    pub fn crossings(&self, other: &Polyline, x_min: f64, x_max: f64) -> Vec<f64> {
        let mut cuts: Vec<f64> = std::iter::once(x_min)
            .chain(
                self.xs()
                    .chain(other.xs())
                    .filter(|&x| x > x_min && x < x_max),
            )
            .chain(std::iter::once(x_max))
            .collect();
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        let d = |x: f64| self.y_at(x) - other.y_at(x);
        cuts.windows(2)
            .filter_map(|w| {
                let (d0, d1) = (d(w[0]), d(w[1]));
                // Both lines are straight between the cuts: the difference is linear.
                (d0 * d1 < 0.0).then(|| w[0] + (w[1] - w[0]) * d0 / (d0 - d1))
            })
            .collect()
    }

    /// x where the lower or upper half of the circle meets this line within [x_min, x_max]:
    /// (x, whether the crossing point lies on the lower half).
    pub fn circle_crossings(
        &self,
        centre: (f64, f64),
        radius: f64,
        x_min: f64,
        x_max: f64,
    ) -> Crossings {
        let (xc, yc) = centre;
        let mut found = Crossings::new();
        for (x0, x1, m, k) in self.pieces(x_min, x_max) {
            // (x − xc)² + (m x + k − yc)² = R²  →  a x² + b x + c = 0
            let d = k - yc;
            let a = 1.0 + m * m;
            let b = 2.0 * (m * d - xc);
            let c = xc * xc + d * d - radius * radius;
            let discriminant = b * b - 4.0 * a * c;
            if discriminant < 0.0 {
                continue;
            }
            let sq = discriminant.sqrt();
            // The numerically stable pair of roots.
            let q = -0.5 * (b + b.signum() * sq);
            let mut roots = [q / a, if q != 0.0 { c / q } else { q / a }];
            roots.sort_by(f64::total_cmp);
            for x in roots {
                if x.is_finite() && x >= x0 && x <= x1 {
                    found.push((x, m * x + k <= yc));
                }
            }
        }
        found.sort_by(|a, b| a.0.total_cmp(&b.0));
        found.dedup_by(|a, b| a.0 == b.0);
        found
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_and_horizontal_continuation() {
        let line = Polyline::new(vec![(0.0, 0.0), (10.0, 5.0), (20.0, 5.0)]).unwrap();
        assert_eq!(line.y_at(-5.0), 0.0);
        assert_eq!(line.y_at(4.0), 2.0);
        assert_eq!(line.y_at(10.0), 5.0);
        assert_eq!(line.y_at(30.0), 5.0);
        assert_eq!(line.mirrored().y_at(-4.0), 2.0);
    }

    #[test]
    fn bad_points_are_named() {
        assert_eq!(Polyline::new(vec![]), Err(PolylineError::Empty));
        assert_eq!(
            Polyline::new(vec![(0.0, 0.0), (0.0, 1.0)]),
            Err(PolylineError::NotIncreasing { index: 1 })
        );
        assert_eq!(
            Polyline::new(vec![(0.0, f64::NAN)]),
            Err(PolylineError::NotFinite { index: 0 })
        );
    }

    #[test]
    fn crossings_of_lines_and_circles_by_hand() {
        let ground = Polyline::new(vec![(0.0, 0.0), (10.0, 10.0)]).unwrap();
        let level = Polyline::new(vec![(0.0, 4.0)]).unwrap();
        assert_eq!(ground.crossings(&level, -100.0, 100.0), vec![4.0]);
        // Circle of radius 5 about (0, 5) meets the level line y = 0 (the ground's left
        // continuation) at x = 0 (tangent) and the line y = x at (0, 0) and (5, 5).
        let crossings = ground.circle_crossings((0.0, 5.0), 5.0, -100.0, 100.0);
        let xs: Vec<f64> = crossings.iter().map(|c| c.0).collect();
        assert!(xs.iter().any(|x| x.abs() < 1e-12));
        assert!(xs.iter().any(|x| (x - 5.0).abs() < 1e-12));
    }

    #[test]
    fn a_step_too_small_for_a_slope_is_refused_as_input_and_never_panics() {
        // Regression (a 500): an x-step of 5e-324 made an infinite slope, a NaN height, and an
        // index out of bounds in y_at.
        for step in [5e-324, 1e-300, 1e-12] {
            let points = vec![(0.0, 0.0), (step, 1.0), (20.0, 10.0)];
            assert_eq!(
                Polyline::from_input(points.clone()),
                Err(PolylineError::TooClose { index: 1 }),
                "step {step}"
            );
            // Built by the solver itself it stands, and any height along it is answered.
            let line = Polyline::new(points).unwrap();
            for x in [-1.0, 0.0, step, 1.0, f64::NAN, 25.0] {
                let _ = line.y_at(x);
            }
        }
        // A step of 1e-7 in a line 20 long is above 1e-9 of its extent (2e-8): accepted.
        assert!(Polyline::from_input(vec![(0.0, 0.0), (1e-7, 0.0), (20.0, 10.0)]).is_ok());
        // One point: every height is its height, a NaN x included.
        let point = Polyline::new(vec![(3.0, 4.0)]).unwrap();
        assert_eq!(point.y_at(f64::NAN), 4.0);
    }
}
