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
#[derive(Clone)]
pub struct PoreGrid {
    points: Arc<[(f64, f64, f64)]>,
    triangulation: Arc<DelaunayTriangulation<GridPoint>>,
    /// −1 when the section is seen from behind (queries at −x).
    sign: f64,
}

impl std::fmt::Debug for PoreGrid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PoreGrid")
            .field("points", &self.points.len())
            .field("sign", &self.sign)
            .finish()
    }
}

impl PartialEq for PoreGrid {
    fn eq(&self, other: &Self) -> bool {
        self.points == other.points && self.sign == other.sign
    }
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
        let vertices: Vec<GridPoint> = points
            .iter()
            .map(|&(x, y, u)| GridPoint {
                position: Point2::new(x, y),
                u,
            })
            .collect();
        let mut triangulation = DelaunayTriangulation::<GridPoint>::new();
        for (index, v) in vertices.into_iter().enumerate() {
            triangulation
                .insert(v)
                .map_err(|_| GridError::Refused { index })?;
        }
        if triangulation.num_inner_faces() == 0 {
            return Err(GridError::Collinear);
        }
        Ok(Self {
            points: points.into(),
            triangulation: Arc::new(triangulation),
            sign: 1.0,
        })
    }

    /// The points as given (x, y, u).
    pub fn points(&self) -> &[(f64, f64, f64)] {
        &self.points
    }

    /// The triangles as index triples into [`PoreGrid::points`].
    pub fn triangles(&self) -> Vec<[usize; 3]> {
        self.triangulation
            .inner_faces()
            .map(|f| f.vertices().map(|v| v.fix().index()))
            .collect()
    }

    /// u at (x, y); `None` outside the grid's hull.
    pub fn pressure(&self, x: f64, y: f64) -> Option<f64> {
        self.triangulation
            .barycentric()
            .interpolate(|v| v.data().u, Point2::new(self.sign * x, y))
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
