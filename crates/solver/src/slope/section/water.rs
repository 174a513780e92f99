//! Pore water beyond one piezometric line (model §8): a layer's own line, the factor h_u on a
//! line's head (a number, or cos²α of the line's inclination above the point: the
//! phreatic-surface correction), and a grid of measured or computed pore pressures interpolated
//! linearly over its Delaunay triangulation (u = 0 outside its hull).

use std::sync::Arc;

use spade::{DelaunayTriangulation, FloatTriangulation, HasPosition, Point2, Triangulation};

use crate::slope::section::polyline::Polyline;

/// The factor on a piezometric line's head.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Hu {
    /// u = h_u·γ_w·(y_p − y).
    Factor(f64),
    /// h_u = cos²α, α the line's inclination above the point.
    Auto,
}

impl Default for Hu {
    fn default() -> Self {
        Self::Factor(1.0)
    }
}

impl Hu {
    /// h_u under `line` at x.
    pub fn at(self, line: &Polyline, x: f64) -> f64 {
        match self {
            Self::Factor(h) => h,
            Self::Auto => {
                let slope = line.slope_at(x);
                1.0 / (1.0 + slope * slope)
            }
        }
    }

    /// Whether the head counts in full everywhere (h_u = 1).
    pub fn is_full(self) -> bool {
        self == Self::Factor(1.0)
    }
}

/// A piezometric line with its h_u.
#[derive(Debug, Clone, PartialEq)]
pub struct WaterLine {
    /// The line.
    pub line: Polyline,
    /// h_u.
    pub hu: Hu,
}

impl WaterLine {
    /// The pore pressure at (x, y) for water of unit weight `gamma_w`.
    pub fn pressure(&self, gamma_w: f64, x: f64, y: f64) -> f64 {
        gamma_w * self.hu.at(&self.line, x) * (self.line.y_at(x) - y).max(0.0)
    }

    /// The line seen from behind (x → −x).
    pub fn mirrored(&self) -> Self {
        Self {
            line: self.line.mirrored(),
            hu: self.hu,
        }
    }
}

/// One point of a pore-pressure grid.
#[derive(Debug, Clone, Copy, PartialEq)]
struct GridPoint {
    position: Point2<f64>,
    u: f64,
    /// Its index in the points as given.
    index: usize,
}

impl HasPosition for GridPoint {
    type Scalar = f64;

    fn position(&self) -> Point2<f64> {
        self.position
    }
}

/// Why a grid cannot be triangulated.
#[derive(Debug, Clone, PartialEq)]
pub enum GridError {
    /// Fewer than three points.
    TooFew,
    /// Point `index` repeats an earlier one.
    Repeated {
        /// Index of the repeat.
        index: usize,
    },
    /// Every point lies on one line: no triangle.
    Collinear,
    /// The triangulation refused a point (a coordinate beyond its range).
    Refused {
        /// Index of the point.
        index: usize,
    },
}

/// Pore pressures at points, linear over their Delaunay triangulation.
///
/// Where the triangulation is not unique (four or more points on one circle: every cell of a
/// rectangular grid), one choice of diagonals would make the field, and every F on it, depend
/// on which way the section faces. The grid then also keeps the triangulation of its mirror
/// image (x → −x), and u is the mean of the two interpolants: the same for a section and its
/// mirror, bit for bit. Points are inserted in sorted order, so that the triangulation depends
/// on the points, not on the order they are listed in.
#[derive(Clone)]
pub struct PoreGrid {
    points: Arc<[(f64, f64, f64)]>,
    triangulation: Arc<DelaunayTriangulation<GridPoint>>,
    /// The triangulation of the points at −x, where it is not the mirror of `triangulation`.
    mirror: Option<Arc<DelaunayTriangulation<GridPoint>>>,
    /// −1 when the section is seen from behind (queries at −x).
    sign: f64,
}

impl std::fmt::Debug for PoreGrid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PoreGrid")
            .field("points", &self.points.len())
            .field("ambiguous", &self.mirror.is_some())
            .field("sign", &self.sign)
            .finish()
    }
}

impl PartialEq for PoreGrid {
    fn eq(&self, other: &Self) -> bool {
        self.points == other.points && self.sign == other.sign
    }
}

/// The Delaunay triangulation of `points` with x multiplied by `sign`, inserted in sorted order.
fn triangulate(
    points: &[(f64, f64, f64)],
    sign: f64,
) -> Result<DelaunayTriangulation<GridPoint>, GridError> {
    let mut vertices: Vec<GridPoint> = points
        .iter()
        .enumerate()
        .map(|(index, &(x, y, u))| GridPoint {
            position: Point2::new(sign * x, y),
            u,
            index,
        })
        .collect();
    vertices.sort_by(|a, b| {
        (a.position.x.total_cmp(&b.position.x)).then(a.position.y.total_cmp(&b.position.y))
    });
    let mut triangulation = DelaunayTriangulation::<GridPoint>::new();
    for v in vertices {
        let index = v.index;
        triangulation
            .insert(v)
            .map_err(|_| GridError::Refused { index })?;
    }
    Ok(triangulation)
}

/// The triangles of `triangulation` as sorted triples of the points' indices, sorted.
fn triangle_set(triangulation: &DelaunayTriangulation<GridPoint>) -> Vec<[usize; 3]> {
    let mut out: Vec<[usize; 3]> = triangulation
        .inner_faces()
        .map(|f| {
            let mut t = f.vertices().map(|v| v.data().index);
            t.sort_unstable();
            t
        })
        .collect();
    out.sort_unstable();
    out
}

impl PoreGrid {
    /// The grid through `points` (x, y, u): at least three, not all on one line, none
    /// repeated, every number finite (the caller checks ranges).
    pub fn new(points: Vec<(f64, f64, f64)>) -> Result<Self, GridError> {
        if points.len() < 3 {
            return Err(GridError::TooFew);
        }
        let mut seen: Vec<(f64, f64, usize)> = points
            .iter()
            .enumerate()
            .map(|(i, p)| (p.0, p.1, i))
            .collect();
        seen.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        if let Some(w) = seen
            .windows(2)
            .find(|w| w[0].0 == w[1].0 && w[0].1 == w[1].1)
        {
            return Err(GridError::Repeated {
                index: w[0].2.max(w[1].2),
            });
        }
        let triangulation = triangulate(&points, 1.0)?;
        if triangulation.num_inner_faces() == 0 {
            return Err(GridError::Collinear);
        }
        let mirror = triangulate(&points, -1.0)?;
        let mirror =
            (triangle_set(&mirror) != triangle_set(&triangulation)).then(|| Arc::new(mirror));
        Ok(Self {
            points: points.into(),
            triangulation: Arc::new(triangulation),
            mirror,
            sign: 1.0,
        })
    }

    /// The points as given (x, y, u).
    pub fn points(&self) -> &[(f64, f64, f64)] {
        &self.points
    }

    /// The triangles as index triples into [`PoreGrid::points`] (where the triangulation is
    /// not unique, one of its choices).
    pub fn triangles(&self) -> Vec<[usize; 3]> {
        self.triangulation
            .inner_faces()
            .map(|f| f.vertices().map(|v| v.data().index))
            .collect()
    }

    /// u at (x, y); `None` outside the grid's hull.
    pub fn pressure(&self, x: f64, y: f64) -> Option<f64> {
        let at = |t: &DelaunayTriangulation<GridPoint>, x: f64| {
            t.barycentric()
                .interpolate(|v| v.data().u, Point2::new(x, y))
        };
        let own = at(&self.triangulation, self.sign * x);
        let Some(mirror) = &self.mirror else {
            return own;
        };
        match (own, at(mirror, -self.sign * x)) {
            (Some(a), Some(b)) => Some(0.5 * (a + b)),
            (a, b) => a.or(b),
        }
    }

    /// The grid seen from behind (x → −x).
    pub fn mirrored(&self) -> Self {
        Self {
            sign: -self.sign,
            ..self.clone()
        }
    }
}

/// The water of a section beyond its piezometric line.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Water {
    /// h_u of the section's piezometric line.
    pub hu: Hu,
    /// A pore-pressure grid: u at bases in soils without their own r_u or line.
    pub grid: Option<PoreGrid>,
}

impl Water {
    /// Whether nothing beyond the section's line is given.
    pub fn is_plain(&self) -> bool {
        self.hu.is_full() && self.grid.is_none()
    }

    /// Seen from behind.
    pub fn mirrored(&self) -> Self {
        Self {
            hu: self.hu,
            grid: self.grid.as_ref().map(PoreGrid::mirrored),
        }
    }
}
