//! Arches by their intrados profile (model §10): segmental, semicircular, elliptical,
//! three-centred, pointed, parabolic and catenary arches of a given span and rise, or any
//! measured intrados through points.
//!
//! Frame: the intrados springings at (±span/2, 0), the crown at (0, rise); a measured profile
//! keeps its own coordinates. Joints are normal to the intrados at equal arc lengths along it,
//! the extrados lies at the thickness along those normals, and the blocks are the
//! quadrilaterals between consecutive joints, numbered from the right springing (as a circular
//! arch's increasing polar angle).

mod curve;

use std::f64::consts::PI;

pub use curve::Station;
use curve::{Curve, Piece};

use super::error::{ArchError, ArchParameter};
use super::geometry::Assembly;
use crate::numerics::brent;

type Point = (f64, f64);

/// The shape of an intrados.
#[derive(Debug, Clone, PartialEq)]
pub enum ProfileShape {
    /// A circular arc through both springings and the crown, rise < span/2.
    Segmental,
    /// A half circle, rise = span/2.
    Semicircular,
    /// The half ellipse of semi-axes span/2 and rise.
    Elliptical,
    /// Haunch arcs of `haunch_radius` centred on the springing line, tangent to a crown arc
    /// centred on the vertical through the crown (0 < haunch radius < rise < span/2).
    ThreeCentred {
        /// The haunch arcs' radius.
        haunch_radius: f64,
    },
    /// Two arcs centred on the springing line, each through its springing and the crown
    /// (rise > span/2).
    Pointed,
    /// y = rise·(1 − (2x/span)²).
    Parabolic,
    /// The catenary through both springings and the crown.
    Catenary,
    /// A measured intrados: a polyline through the points, rising to one crown.
    Points(Vec<Point>),
}

/// An intrados, measured along its length.
#[derive(Debug, Clone)]
pub struct Profile {
    curve: Curve,
    span: f64,
    rise: f64,
}

/// The rise of a pointed arch of arcs of `radius` (> span/2): √(radius·span − span²/4).
pub fn pointed_rise(span: f64, radius: f64) -> f64 {
    (radius * span - 0.25 * span * span).sqrt()
}

fn check_rise(rise: f64, ok: bool, allowed: &str) -> Result<(), ArchError> {
    if ok && rise.is_finite() && rise > 0.0 {
        Ok(())
    } else {
        Err(ArchError::range(ArchParameter::Rise, rise, allowed))
    }
}

impl Profile {
    /// The intrados of `shape` with span `span` and rise `rise` (a measured profile takes
    /// both from its points; the two numbers are then ignored).
    pub fn new(shape: &ProfileShape, span: f64, rise: f64) -> Result<Self, ArchError> {
        if let ProfileShape::Points(points) = shape {
            return Self::measured(points);
        }
        if !(span.is_finite() && span > 0.0) {
            return Err(ArchError::range(
                ArchParameter::Span,
                span,
                "a finite number > 0",
            ));
        }
        let h = 0.5 * span;
        let pieces = match *shape {
            ProfileShape::Segmental => {
                check_rise(rise, rise < h, "0 < rise < span/2 (span/2 is semicircular)")?;
                let radius = (h * h + rise * rise) / (2.0 * rise);
                let from = (radius - rise).atan2(h);
                vec![Piece::Arc {
                    centre: (0.0, rise - radius),
                    radius,
                    from,
                    to: PI - from,
                }]
            }
            ProfileShape::Semicircular => {
                let same = (rise - h).abs() <= 1e-9 * h;
                check_rise(rise, same, "rise = span/2 for a semicircle")?;
                vec![Piece::Arc {
                    centre: (0.0, 0.0),
                    radius: h,
                    from: 0.0,
                    to: PI,
                }]
            }
            ProfileShape::Elliptical => {
                check_rise(rise, true, "rise > 0")?;
                vec![Piece::Ellipse { a: h, b: rise }]
            }
            ProfileShape::Parabolic => {
                check_rise(rise, true, "rise > 0")?;
                vec![Piece::Parabola { h, r: rise }]
            }
            ProfileShape::Catenary => {
                check_rise(rise, true, "rise > 0")?;
                vec![Piece::Catenary {
                    h,
                    r: rise,
                    a: catenary_parameter(h, rise)?,
                }]
            }
            ProfileShape::ThreeCentred { haunch_radius } => three_centred(h, rise, haunch_radius)?,
            ProfileShape::Pointed => {
                check_rise(rise, rise > h, "rise > span/2 (radius > span/2)")?;
                let radius = (h * h + rise * rise) / span;
                let crown = rise.atan2(radius - h);
                vec![
                    Piece::Arc {
                        centre: (h - radius, 0.0),
                        radius,
                        from: 0.0,
                        to: crown,
                    },
                    Piece::Arc {
                        centre: (radius - h, 0.0),
                        radius,
                        from: PI - crown,
                        to: PI,
                    },
                ]
            }
            ProfileShape::Points(_) => unreachable!("measured profiles return above"),
        };
        Ok(Self {
            curve: Curve::new(pieces),
            span,
            rise,
        })
    }

    /// A measured intrados: 3 or more finite points, x strictly monotone, y rising to one crown
    /// and falling after it. Traversed from the larger x (the right springing).
    fn measured(points: &[Point]) -> Result<Self, ArchError> {
        let bad = |reason: String| Err(ArchError::geometry(ArchParameter::Intrados, reason));
        if points.len() < 3 {
            return bad(format!("{} points: give at least 3", points.len()));
        }
        if let Some(i) = points
            .iter()
            .position(|p| !(p.0.is_finite() && p.1.is_finite()))
        {
            return bad(format!("point {i} is not finite"));
        }
        let mut points = points.to_vec();
        if points[0].0 < points[points.len() - 1].0 {
            points.reverse();
        }
        if let Some(i) = points.windows(2).position(|w| w[1].0 >= w[0].0) {
            return bad(format!(
                "x must run one way along the points (strictly increasing or decreasing): \
                 {:?} then {:?}",
                points[i],
                points[i + 1]
            ));
        }
        let top = points.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        let crown = points.iter().position(|p| p.1 == top).unwrap_or(0);
        let rises = points[..=crown].windows(2).all(|w| w[1].1 >= w[0].1);
        let falls = points[crown..].windows(2).all(|w| w[1].1 <= w[0].1);
        let springing = points[0].1.max(points[points.len() - 1].1);
        if !(rises && falls) || top <= springing {
            return bad(
                "the points must rise to a single crown above both springings and fall after it"
                    .into(),
            );
        }
        let span = points[0].0 - points[points.len() - 1].0;
        let pieces = points
            .windows(2)
            .map(|w| Piece::Segment {
                from: w[0],
                to: w[1],
            })
            .collect();
        Ok(Self {
            curve: Curve::new(pieces),
            span,
            rise: top - springing,
        })
    }

    /// The span (horizontal distance between the intrados springings).
    pub fn span(&self) -> f64 {
        self.span
    }

    /// The rise of the crown above the springings (the higher one of a measured profile).
    pub fn rise(&self) -> f64 {
        self.rise
    }

    /// The intrados' arc length.
    pub fn length(&self) -> f64 {
        self.curve.length()
    }

    /// The `m` + 1 points at equal arc lengths from the right springing, with their outward
    /// normals.
    pub fn stations(&self, m: usize) -> Vec<Station> {
        self.curve.stations(m.max(1))
    }

    /// The one-ring chain of `voussoirs` blocks of thickness `thickness` (0 < thickness <
    /// span).
    pub fn chain(&self, thickness: f64, voussoirs: usize) -> Result<Assembly, ArchError> {
        self.chain_on(&self.stations(voussoirs), thickness)
    }

    /// [`Profile::chain`] on this profile's `stations` computed once (a minimum-thickness
    /// search builds the chain at many thicknesses).
    pub fn chain_on(&self, stations: &[Station], thickness: f64) -> Result<Assembly, ArchError> {
        self.check_thickness(thickness)?;
        let corners: Vec<[Point; 4]> = stations
            .windows(2)
            .map(|w| {
                [
                    w[0].point,
                    w[0].at(thickness),
                    w[1].at(thickness),
                    w[1].point,
                ]
            })
            .collect();
        Assembly::from_quadrilaterals(&corners).map_err(|_| {
            ArchError::geometry(
                ArchParameter::Intrados,
                "neighbouring joints cross inside the thickness: the intrados turns too sharply \
                 for this thickness (give more points, fewer voussoirs or a thinner arch)",
            )
        })
    }

    /// 0 < thickness < span.
    pub fn check_thickness(&self, thickness: f64) -> Result<(), ArchError> {
        if thickness.is_finite() && thickness > 0.0 && thickness < self.span {
            Ok(())
        } else {
            Err(ArchError::range(
                ArchParameter::Thickness,
                thickness,
                format!("0 < thickness < span = {}", self.span),
            ))
        }
    }
}

/// The parameter a of the catenary y = r + a − a·cosh(x/a) through (±h, 0): a·(cosh(h/a) − 1)
/// = r, solved for v = h/a from (cosh v − 1)/v = r/h (increasing in v from 0).
fn catenary_parameter(h: f64, r: f64) -> Result<f64, ArchError> {
    let ratio = r / h;
    // cosh v − 1 = 2·sinh²(v/2), exact also for small v.
    let g = |v: f64| 2.0 * (0.5 * v).sinh().powi(2) / v - ratio;
    let hi = 700.0;
    let lo = 1e-300_f64.max(ratio.min(1.0) * 1e-3);
    let (glo, ghi) = (g(lo), g(hi));
    let root = brent(g, lo, hi, glo, ghi, 1e-17, 400);
    match root {
        Some(root) if root.x > 0.0 => Ok(h / root.x),
        _ => Err(ArchError::range(
            ArchParameter::Rise,
            r,
            "a rise the catenary can reach: 1e-3·span ≤ rise ≤ 100·span",
        )),
    }
}

/// Haunch arcs of radius ρ about (±(h − ρ), 0) tangent inside a crown arc about (0, y_c) of
/// radius R_c = r − y_c: R_c − ρ = |centres|, so y_c = ((h − ρ)² − (r − ρ)²) / (2(ρ − r)).
fn three_centred(h: f64, rise: f64, rho: f64) -> Result<Vec<Piece>, ArchError> {
    check_rise(rise, rise < h, "0 < rise < span/2 for a three-centred arch")?;
    if !(rho.is_finite() && rho > 0.0 && rho < rise) {
        return Err(ArchError::range(
            ArchParameter::HaunchRadius,
            rho,
            format!("0 < haunch_radius < rise = {rise} (a larger one leaves no crown arc)"),
        ));
    }
    let yc = ((h - rho).powi(2) - (rise - rho).powi(2)) / (2.0 * (rho - rise));
    let crown_radius = rise - yc;
    // The tangent points lie on the line from the crown centre through each haunch centre.
    let phi = (-yc).atan2(h - rho);
    Ok(vec![
        Piece::Arc {
            centre: (h - rho, 0.0),
            radius: rho,
            from: 0.0,
            to: phi,
        },
        Piece::Arc {
            centre: (0.0, yc),
            radius: crown_radius,
            from: phi,
            to: PI - phi,
        },
        Piece::Arc {
            centre: (rho - h, 0.0),
            radius: rho,
            from: PI - phi,
            to: PI,
        },
    ])
}
