//! An intrados as a sequence of smooth pieces, traversed from the right springing to the left
//! (the order of a circular arch's increasing polar angle), and the points at equal arc lengths
//! along it with their outward normals.
//!
//! Arc lengths are integrated by composite 8-point Gauss–Legendre quadrature on panels fine
//! enough for the piece (more panels for a flat ellipse, whose speed turns sharply at its
//! springings), and inverted by Newton's method kept inside the panel that holds the length.

type Point = (f64, f64);

/// One smooth piece of an intrados, by a parameter u from 0 to 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Piece {
    /// A circular arc about `centre`, counter-clockwise from polar angle `from` to `to`
    /// (radians).
    Arc {
        centre: Point,
        radius: f64,
        from: f64,
        to: f64,
    },
    /// The upper half ellipse (a·cos θ, b·sin θ), θ from 0 to π.
    Ellipse { a: f64, b: f64 },
    /// y = r·(1 − (x/h)²), x from h to −h.
    Parabola { h: f64, r: f64 },
    /// y = r + a − a·cosh(x/a), x from h to −h.
    Catenary { h: f64, r: f64, a: f64 },
    /// A straight segment from `from` to `to`.
    Segment { from: Point, to: Point },
}

impl Piece {
    /// The point at parameter u.
    pub(super) fn point(&self, u: f64) -> Point {
        match *self {
            Self::Arc {
                centre,
                radius,
                from,
                to,
            } => {
                let phi = from + (to - from) * u;
                (centre.0 + radius * phi.cos(), centre.1 + radius * phi.sin())
            }
            Self::Ellipse { a, b } => {
                let theta = std::f64::consts::PI * u;
                (a * theta.cos(), b * theta.sin())
            }
            Self::Parabola { h, r } => {
                let x = h * (1.0 - 2.0 * u);
                (x, r * (1.0 - (x / h) * (x / h)))
            }
            Self::Catenary { h, r, a } => {
                let x = h * (1.0 - 2.0 * u);
                (x, r + a - a * (x / a).cosh())
            }
            Self::Segment { from, to } => {
                (from.0 + (to.0 - from.0) * u, from.1 + (to.1 - from.1) * u)
            }
        }
    }

    /// dp/du at parameter u.
    fn derivative(&self, u: f64) -> Point {
        match *self {
            Self::Arc {
                radius, from, to, ..
            } => {
                let phi = from + (to - from) * u;
                let rate = radius * (to - from);
                (-rate * phi.sin(), rate * phi.cos())
            }
            Self::Ellipse { a, b } => {
                let pi = std::f64::consts::PI;
                let theta = pi * u;
                (-a * pi * theta.sin(), b * pi * theta.cos())
            }
            Self::Parabola { h, r } => {
                let x = h * (1.0 - 2.0 * u);
                // dy/dx = −2·r·x/h², dx/du = −2h.
                (-2.0 * h, 4.0 * r * x / h)
            }
            Self::Catenary { h, a, .. } => {
                let x = h * (1.0 - 2.0 * u);
                (-2.0 * h, 2.0 * h * (x / a).sinh())
            }
            Self::Segment { from, to } => (to.0 - from.0, to.1 - from.1),
        }
    }

    /// The unit tangent at u, in the direction of travel.
    pub(super) fn tangent(&self, u: f64) -> Point {
        let (dx, dy) = self.derivative(u);
        let speed = dx.hypot(dy);
        (dx / speed, dy / speed)
    }

    fn speed(&self, u: f64) -> f64 {
        let (dx, dy) = self.derivative(u);
        dx.hypot(dy)
    }

    /// Panels for the quadrature: 32, more where the speed turns sharply (a flat ellipse turns
    /// within b/a of its springings).
    fn panels(&self) -> usize {
        match *self {
            Self::Ellipse { a, b } => {
                let ratio = (a.max(b) / a.min(b)).min(1e4);
                (32.0 * ratio).ceil().clamp(32.0, 40_000.0) as usize
            }
            Self::Segment { .. } => 1,
            _ => 32,
        }
    }
}

/// Nodes and weights of 8-point Gauss–Legendre quadrature on [−1, 1].
const GAUSS_8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// ∫ speed du from `a` to `b` by one 8-point rule.
fn length_between(piece: &Piece, a: f64, b: f64) -> f64 {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    GAUSS_8
        .iter()
        .map(|&(x, w)| w * piece.speed(mid + half * x))
        .sum::<f64>()
        * half
}

/// A piece with the arc length at each of its panel ends.
#[derive(Debug, Clone)]
struct Measured {
    piece: Piece,
    /// Arc length from the piece's start to each panel end (panels + 1 values, from 0).
    lengths: Vec<f64>,
}

impl Measured {
    fn new(piece: Piece) -> Self {
        let panels = piece.panels();
        let mut lengths = Vec::with_capacity(panels + 1);
        lengths.push(0.0);
        let mut total = 0.0;
        for p in 0..panels {
            let (a, b) = (p as f64 / panels as f64, (p + 1) as f64 / panels as f64);
            total += length_between(&piece, a, b);
            lengths.push(total);
        }
        Self { piece, lengths }
    }

    fn length(&self) -> f64 {
        self.lengths.last().copied().unwrap_or(0.0)
    }

    /// The parameter at arc length `s` (0 ≤ s ≤ length) from the piece's start.
    fn parameter_at(&self, s: f64) -> f64 {
        let panels = self.lengths.len() - 1;
        // The panel holding s.
        let p = self
            .lengths
            .partition_point(|&l| l <= s)
            .saturating_sub(1)
            .min(panels - 1);
        let (mut lo, mut hi) = (p as f64 / panels as f64, (p + 1) as f64 / panels as f64);
        let start = lo;
        let target = s - self.lengths[p];
        let mut u =
            lo + (hi - lo) * (target / (self.lengths[p + 1] - self.lengths[p])).clamp(0.0, 1.0);
        for _ in 0..60 {
            let g = length_between(&self.piece, start, u) - target;
            if g > 0.0 {
                hi = u;
            } else {
                lo = u;
            }
            let step = g / self.piece.speed(u);
            if step.abs() <= 1e-16 || hi - lo <= 1e-16 {
                break;
            }
            let next = u - step;
            u = if next >= lo && next <= hi && step.is_finite() {
                next
            } else {
                0.5 * (lo + hi)
            };
        }
        u
    }
}

/// A point of the intrados with its unit outward normal (towards the extrados).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Station {
    /// The point on the intrados.
    pub point: Point,
    /// The unit normal pointing out of the arch (the joint's direction).
    pub normal: Point,
}

impl Station {
    /// The point at `depth` along the normal.
    pub fn at(&self, depth: f64) -> Point {
        (
            self.point.0 + depth * self.normal.0,
            self.point.1 + depth * self.normal.1,
        )
    }
}

/// The outward normal of a unit tangent travelled right to left over an arch.
fn outward(tangent: Point) -> Point {
    (tangent.1, -tangent.0)
}

/// The intrados: its pieces, measured.
#[derive(Debug, Clone)]
pub(super) struct Curve {
    pieces: Vec<Measured>,
}

impl Curve {
    pub(super) fn new(pieces: Vec<Piece>) -> Self {
        Self {
            pieces: pieces.into_iter().map(Measured::new).collect(),
        }
    }

    /// The whole arc length.
    pub(super) fn length(&self) -> f64 {
        self.pieces.iter().map(Measured::length).sum()
    }

    /// The `m` + 1 stations at arc lengths k·L/m, k = 0..=m. A station on a corner between two
    /// pieces (a pointed arch's crown, a vertex of measured points) takes the bisector of their
    /// normals.
    pub(super) fn stations(&self, m: usize) -> Vec<Station> {
        let total = self.length();
        let corner = 1e-12 * total;
        // Arc length at the start of each piece.
        let mut starts = Vec::with_capacity(self.pieces.len());
        let mut s = 0.0;
        for piece in &self.pieces {
            starts.push(s);
            s += piece.length();
        }
        let station = |piece: &Piece, u: f64| Station {
            point: piece.point(u),
            normal: outward(piece.tangent(u)),
        };
        let (first, last) = (&self.pieces[0], &self.pieces[self.pieces.len() - 1]);
        (0..=m)
            .map(|k| {
                if k == 0 {
                    return station(&first.piece, 0.0);
                }
                if k == m {
                    return station(&last.piece, 1.0);
                }
                let target = total * k as f64 / m as f64;
                let i = starts
                    .partition_point(|&start| start <= target)
                    .saturating_sub(1);
                let local = (target - starts[i]).clamp(0.0, self.pieces[i].length());
                // A corner between pieces j − 1 and j, if the station is on one.
                let corner = if local <= corner && i > 0 {
                    Some(i)
                } else if self.pieces[i].length() - local <= corner && i + 1 < self.pieces.len() {
                    Some(i + 1)
                } else {
                    None
                };
                match corner {
                    None => station(&self.pieces[i].piece, self.pieces[i].parameter_at(local)),
                    Some(j) => {
                        let (before, after) = (&self.pieces[j - 1].piece, &self.pieces[j].piece);
                        let (a, b) = (outward(before.tangent(1.0)), outward(after.tangent(0.0)));
                        let (x, y) = (a.0 + b.0, a.1 + b.1);
                        let norm = x.hypot(y);
                        Station {
                            point: after.point(0.0),
                            normal: (x / norm, y / norm),
                        }
                    }
                }
            })
            .collect()
    }
}
