//! Blocks and interfaces of a rigid-block assembly, and the two ways to make one: the circular
//! arch of the thesis' "Arch Stability" program (model §1.3) and an explicit chain of
//! quadrilaterals given by their corners.
//!
//! Circular arch: centre at the origin, middle radius R, thickness D (intrados R − D/2, extrados
//! R + D/2), from polar angle C (right springing) to 180° − B (left springing), N voussoirs of
//! equal angle, numbered in order of increasing polar angle. Curved voussoirs are annular
//! sectors (exact centroid); quadrilateral voussoirs have straight sides (polygon centroid).

use std::num::NonZeroUsize;

use super::error::{ArchError, ArchParameter};
use crate::polygon::polygon_area_centroid;

/// Relative tolerance for "the same point" when checking that chain blocks share faces.
const SHARED_FACE_TOLERANCE: f64 = 1e-9;

/// One rigid block.
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    /// Corners of the polygon. A chain's blocks have four: intrados-start, extrados-start,
    /// extrados-end, intrados-end; an assembly's block any number, counter-clockwise.
    pub corners: Vec<(f64, f64)>,
    /// Cross-section area (per unit depth).
    pub area: f64,
    /// Centroid.
    pub centroid: (f64, f64),
}

/// A straight contact between two blocks, or between a block and a support.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interface {
    /// Intrados end P_s, where the resultant s acts.
    pub intrados: (f64, f64),
    /// Extrados end P_q, where the resultant q acts.
    pub extrados: (f64, f64),
    /// Unit normal, pointing into the higher-numbered block.
    pub normal: (f64, f64),
    /// Unit tangent from the intrados to the extrados end.
    pub tangent: (f64, f64),
    /// Direction of the joint in degrees (its polar angle, for a circular arch).
    pub angle_deg: f64,
    /// The block the normal points out of (`None`: a support).
    pub lower: Option<usize>,
    /// The block the normal points into (`None`: a support). The resultant acts on it as
    /// (q + s)·ν + t·τ, and oppositely on `lower`.
    pub upper: Option<usize>,
    /// What kind of contact this is (its limits and friction may differ).
    pub kind: InterfaceKind,
}

/// Kinds of interfaces whose limits and friction may be given apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum InterfaceKind {
    /// A joint between voussoirs, or any contact of an assembly (the problem's limits).
    #[default]
    Joint,
    /// The interface between two rings of a multi-ring arch.
    Ring,
}

impl Interface {
    /// Length of the joint.
    pub fn length(&self) -> f64 {
        (self.extrados.0 - self.intrados.0).hypot(self.extrados.1 - self.intrados.1)
    }

    /// Middle of the joint.
    pub fn middle(&self) -> (f64, f64) {
        (
            0.5 * (self.intrados.0 + self.extrados.0),
            0.5 * (self.intrados.1 + self.extrados.1),
        )
    }
}

/// Rigid blocks and the interfaces between them and the supports. In a chain, block b lies
/// between interfaces b and b+1 and the first and last interfaces are supports; an assembly's
/// interfaces name their blocks (`lower`, `upper`).
#[derive(Debug, Clone, PartialEq)]
pub struct Assembly {
    /// The blocks.
    pub blocks: Vec<Block>,
    /// The interfaces.
    pub interfaces: Vec<Interface>,
}

/// Shape of the voussoirs of a circular arch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VoussoirShape {
    /// Annular sectors: curved intrados and extrados.
    Curved,
    /// Straight intrados and extrados between the corners.
    Quadrilateral,
}

/// The thesis' circular arch, validated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularArch {
    radius: f64,
    thickness: f64,
    voussoirs: NonZeroUsize,
    left_base_angle_deg: f64,
    right_base_angle_deg: f64,
    shape: VoussoirShape,
}

impl CircularArch {
    /// A circular arch of middle radius R > 0 and thickness 0 < D < 2R, with N voussoirs
    /// between base angles −90° < B, C < 90° (0 for a semicircle, positive for segmental,
    /// negative for horseshoe).
    pub fn new(
        radius: f64,
        thickness: f64,
        voussoirs: NonZeroUsize,
        left_base_angle_deg: f64,
        right_base_angle_deg: f64,
        shape: VoussoirShape,
    ) -> Result<Self, ArchError> {
        if !(radius.is_finite() && radius > 0.0) {
            return Err(ArchError::range(
                ArchParameter::Radius,
                radius,
                "a finite number > 0",
            ));
        }
        if !(thickness.is_finite() && thickness > 0.0 && thickness < 2.0 * radius) {
            return Err(ArchError::range(
                ArchParameter::Thickness,
                thickness,
                format!("0 < thickness < 2·radius = {}", 2.0 * radius),
            ));
        }
        for (name, angle) in [
            (ArchParameter::LeftBaseAngle, left_base_angle_deg),
            (ArchParameter::RightBaseAngle, right_base_angle_deg),
        ] {
            if !(angle.is_finite() && angle > -90.0 && angle < 90.0) {
                return Err(ArchError::range(name, angle, "-90 < angle < 90 degrees"));
            }
        }
        Ok(Self {
            radius,
            thickness,
            voussoirs,
            left_base_angle_deg,
            right_base_angle_deg,
            shape,
        })
    }

    /// Middle radius R.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Voussoir thickness D.
    pub fn thickness(&self) -> f64 {
        self.thickness
    }

    /// Number of voussoirs N.
    pub fn voussoirs(&self) -> usize {
        self.voussoirs.get()
    }

    /// The same arch with another thickness (checked again).
    pub fn with_thickness(&self, thickness: f64) -> Result<Self, ArchError> {
        Self::new(
            self.radius,
            thickness,
            self.voussoirs,
            self.left_base_angle_deg,
            self.right_base_angle_deg,
            self.shape,
        )
    }

    /// Polar angle of interface k (0-based) in degrees: C + k·(180° − B − C)/N.
    pub fn interface_angle_deg(&self, k: usize) -> f64 {
        let span = 180.0 - self.left_base_angle_deg - self.right_base_angle_deg;
        self.right_base_angle_deg + span * k as f64 / self.voussoirs.get() as f64
    }

    /// The blocks and interfaces of the arch.
    pub fn assembly(&self) -> Assembly {
        let n = self.voussoirs.get();
        let (inner, outer) = (
            self.radius - 0.5 * self.thickness,
            self.radius + 0.5 * self.thickness,
        );
        let angles: Vec<f64> = (0..=n)
            .map(|k| self.interface_angle_deg(k).to_radians())
            .collect();
        let point = |r: f64, phi: f64| (r * phi.cos(), r * phi.sin());
        let blocks = angles
            .windows(2)
            .map(|w| {
                let corners = [
                    point(inner, w[0]),
                    point(outer, w[0]),
                    point(outer, w[1]),
                    point(inner, w[1]),
                ];
                let (area, centroid) = match self.shape {
                    VoussoirShape::Quadrilateral => polygon_area_centroid(&corners),
                    VoussoirShape::Curved => {
                        // Annular sector of half-angle a: area a·(Re² − Ri²), centroid on the
                        // bisector at (2/3)·(Re³ − Ri³)/(Re² − Ri²)·sin a / a.
                        let half = 0.5 * (w[1] - w[0]);
                        let area = half * (outer * outer - inner * inner);
                        let rho = 2.0 / 3.0 * (outer.powi(3) - inner.powi(3))
                            / (outer * outer - inner * inner)
                            * sinc(half);
                        (area, point(rho, 0.5 * (w[0] + w[1])))
                    }
                };
                Block {
                    corners: corners.to_vec(),
                    area,
                    centroid,
                }
            })
            .collect();
        let interfaces = angles
            .iter()
            .enumerate()
            .map(|(k, &phi)| {
                let (c, s) = (phi.cos(), phi.sin());
                Interface {
                    intrados: point(inner, phi),
                    extrados: point(outer, phi),
                    // Towards increasing polar angle, where the higher-numbered block lies.
                    normal: (-s, c),
                    tangent: (c, s),
                    angle_deg: self.interface_angle_deg(k),
                    lower: k.checked_sub(1),
                    upper: (k < n).then_some(k),
                    kind: InterfaceKind::Joint,
                }
            })
            .collect();
        Assembly { blocks, interfaces }
    }
}

/// sin x / x, exact to rounding also for tiny x.
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

/// The N + 1 interfaces of a chain of blocks: each block's start face, and the last block's
/// end face; normals into the higher-numbered block.
fn chain_interfaces(blocks: &[Block], scale: f64) -> Result<Vec<Interface>, ArchError> {
    let n = blocks.len();
    let mut interfaces = Vec::with_capacity(n + 1);
    for k in 0..=n {
        let (intrados, extrados) = if k < n {
            (blocks[k].corners[0], blocks[k].corners[1])
        } else {
            (blocks[n - 1].corners[3], blocks[n - 1].corners[2])
        };
        let length = (extrados.0 - intrados.0).hypot(extrados.1 - intrados.1);
        let has_length = length > 1e-12 * scale;
        if !has_length {
            return Err(ArchError::geometry(
                ArchParameter::BlockCorners {
                    block: k.min(n - 1),
                },
                format!("interface {} has zero length", k + 1),
            ));
        }
        let tangent = (
            (extrados.0 - intrados.0) / length,
            (extrados.1 - intrados.1) / length,
        );
        let mut normal = (-tangent.1, tangent.0);
        let middle = (
            0.5 * (intrados.0 + extrados.0),
            0.5 * (intrados.1 + extrados.1),
        );
        // Point the normal into the higher-numbered block (out of the lower one at the end).
        let towards = if k < n {
            (
                blocks[k].centroid.0 - middle.0,
                blocks[k].centroid.1 - middle.1,
            )
        } else {
            (
                middle.0 - blocks[n - 1].centroid.0,
                middle.1 - blocks[n - 1].centroid.1,
            )
        };
        if normal.0 * towards.0 + normal.1 * towards.1 < 0.0 {
            normal = (-normal.0, -normal.1);
        }
        let mut angle_deg = tangent.1.atan2(tangent.0).to_degrees();
        if angle_deg <= -90.0 {
            angle_deg += 360.0;
        }
        interfaces.push(Interface {
            intrados,
            extrados,
            normal,
            tangent,
            angle_deg,
            lower: k.checked_sub(1),
            upper: (k < n).then_some(k),
            kind: InterfaceKind::Joint,
        });
    }
    Ok(interfaces)
}

impl Assembly {
    /// A chain of quadrilateral blocks given by their corners (intrados-start, extrados-start,
    /// extrados-end, intrados-end); consecutive blocks must share a face.
    pub fn from_quadrilaterals(corners: &[[(f64, f64); 4]]) -> Result<Self, ArchError> {
        if corners.is_empty() {
            return Err(ArchError::geometry(
                ArchParameter::Blocks,
                "at least one block is needed",
            ));
        }
        let scale = corners
            .iter()
            .flatten()
            .map(|&(x, y)| x.abs().max(y.abs()))
            .fold(0.0, f64::max);
        for (b, block) in corners.iter().enumerate() {
            for (c, &(x, y)) in block.iter().enumerate() {
                if !(x.is_finite() && y.is_finite()) {
                    return Err(ArchError::geometry(
                        ArchParameter::BlockCorner {
                            block: b,
                            corner: c,
                        },
                        "corners must be finite numbers",
                    ));
                }
            }
        }
        let tolerance = SHARED_FACE_TOLERANCE * scale.max(f64::MIN_POSITIVE);
        let mut blocks = Vec::with_capacity(corners.len());
        for (b, c) in corners.iter().enumerate() {
            let (signed_area, centroid) = polygon_area_centroid(c);
            let extent = c
                .iter()
                .flat_map(|p| c.iter().map(move |q| (p.0 - q.0).hypot(p.1 - q.1)))
                .fold(0.0, f64::max);
            let has_area = signed_area.abs() > 1e-12 * extent * extent;
            if !has_area || is_self_intersecting(c) {
                return Err(ArchError::geometry(
                    ArchParameter::BlockCorners { block: b },
                    "the block is degenerate or self-intersecting (corners must be intrados-start, \
                     extrados-start, extrados-end, intrados-end)",
                ));
            }
            if b > 0 {
                let previous = &corners[b - 1];
                let same = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).hypot(p.1 - q.1) <= tolerance;
                if !(same(previous[3], c[0]) && same(previous[2], c[1])) {
                    return Err(ArchError::geometry(
                        ArchParameter::BlockCorners { block: b },
                        format!(
                            "block {} does not share its start face with the end face of block {b}: \
                             its intrados-start and extrados-start must equal the previous block's \
                             intrados-end and extrados-end",
                            b + 1
                        ),
                    ));
                }
            }
            blocks.push(Block {
                corners: c.to_vec(),
                area: signed_area.abs(),
                centroid,
            });
        }
        let interfaces = chain_interfaces(&blocks, scale)?;
        Ok(Self { blocks, interfaces })
    }

    /// Whether the assembly is a chain: interface k between blocks k−1 and k, the first and
    /// last on supports (what the chain formulation needs).
    pub fn is_chain(&self) -> bool {
        let n = self.blocks.len();
        self.interfaces.len() == n + 1
            && self
                .interfaces
                .iter()
                .enumerate()
                .all(|(k, i)| i.lower == k.checked_sub(1) && i.upper == (k < n).then_some(k))
    }

    /// Total area of the blocks.
    pub fn total_area(&self) -> f64 {
        self.blocks.iter().map(|b| b.area).sum()
    }

    /// A length that measures the size of the assembly: the largest extent of its corners.
    pub fn length_scale(&self) -> f64 {
        let (mut lo, mut hi) = (
            (f64::INFINITY, f64::INFINITY),
            (f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for &(x, y) in self.blocks.iter().flat_map(|b| b.corners.iter()) {
            lo = (lo.0.min(x), lo.1.min(y));
            hi = (hi.0.max(x), hi.1.max(y));
        }
        (hi.0 - lo.0).max(hi.1 - lo.1).max(f64::MIN_POSITIVE)
    }
}

/// Whether two opposite edges of a quadrilateral cross.
fn is_self_intersecting(c: &[(f64, f64); 4]) -> bool {
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let segments_cross = |p1, p2, p3, p4| {
        let d1 = cross(p3, p4, p1);
        let d2 = cross(p3, p4, p2);
        let d3 = cross(p1, p2, p3);
        let d4 = cross(p1, p2, p4);
        d1 * d2 < 0.0 && d3 * d4 < 0.0
    };
    segments_cross(c[0], c[1], c[2], c[3]) || segments_cross(c[1], c[2], c[3], c[0])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn semicircle(n: usize, shape: VoussoirShape) -> CircularArch {
        crate::reference::circular_arch(n, 10.0, 1.0, 0.0, shape)
    }

    #[test]
    fn curved_voussoirs_add_up_to_the_half_annulus() {
        // Half annulus: area π(Re² − Ri²)/2, centroid at 4(Re³ − Ri³)/(3π(Re² − Ri²)) on the
        // axis (the textbook formula); 1e-12 relative: rounding.
        let a = semicircle(7, VoussoirShape::Curved).assembly();
        let (ri, re) = (9.5f64, 10.5f64);
        let area: f64 = a.blocks.iter().map(|b| b.area).sum();
        let expected = std::f64::consts::PI * (re * re - ri * ri) / 2.0;
        assert!((area - expected).abs() < 1e-12 * expected);
        let y: f64 = a.blocks.iter().map(|b| b.area * b.centroid.1).sum::<f64>() / area;
        let y_expected =
            4.0 * (re.powi(3) - ri.powi(3)) / (3.0 * std::f64::consts::PI * (re * re - ri * ri));
        assert!((y - y_expected).abs() < 1e-12 * y_expected);
    }

    #[test]
    fn numbering_starts_at_the_right_springing() {
        let arch = CircularArch::new(
            10.0,
            1.0,
            NonZeroUsize::new(4).unwrap(),
            10.0,
            20.0,
            VoussoirShape::Curved,
        )
        .unwrap();
        assert_eq!(arch.interface_angle_deg(0), 20.0);
        assert_eq!(arch.interface_angle_deg(4), 170.0);
        let a = arch.assembly();
        assert!(a.blocks[0].centroid.0 > 0.0 && a.blocks[3].centroid.0 < 0.0);
        // Normals point into the higher-numbered block.
        for (k, i) in a.interfaces.iter().enumerate().take(4) {
            let g = a.blocks[k].centroid;
            let m = i.middle();
            assert!(i.normal.0 * (g.0 - m.0) + i.normal.1 * (g.1 - m.1) > 0.0);
        }
    }

    #[test]
    fn quadrilateral_chain_matches_the_generator() {
        let arch = semicircle(12, VoussoirShape::Quadrilateral).assembly();
        let corners: Vec<[(f64, f64); 4]> = arch
            .blocks
            .iter()
            .map(|b| std::array::from_fn(|i| b.corners[i]))
            .collect();
        let chain = Assembly::from_quadrilaterals(&corners).unwrap();
        for (a, b) in arch.blocks.iter().zip(&chain.blocks) {
            assert!((a.area - b.area).abs() < 1e-12 * a.area);
            assert!(
                (a.centroid.0 - b.centroid.0).abs() < 1e-12
                    && (a.centroid.1 - b.centroid.1).abs() < 1e-12
            );
        }
        for (a, b) in arch.interfaces.iter().zip(&chain.interfaces) {
            assert!(
                (a.normal.0 - b.normal.0).abs() < 1e-12 && (a.normal.1 - b.normal.1).abs() < 1e-12
            );
            assert!(
                (a.angle_deg - b.angle_deg).abs() < 1e-9,
                "{} {}",
                a.angle_deg,
                b.angle_deg
            );
        }
    }

    #[test]
    fn chain_blocks_that_do_not_touch_are_rejected() {
        let a = [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)];
        let b = [(1.1, 0.0), (1.1, 1.0), (2.0, 1.0), (2.0, 0.0)];
        let err = Assembly::from_quadrilaterals(&[a, b]).unwrap_err();
        assert!(matches!(
            err,
            ArchError::InvalidGeometry {
                parameter: ArchParameter::BlockCorners { block: 1 },
                ..
            }
        ));
        let bowtie = [(0.0, 0.0), (1.0, 1.0), (0.0, 1.0), (1.0, 0.0)];
        assert!(Assembly::from_quadrilaterals(&[bowtie]).is_err());
        let flat = [(0.0, 0.0), (0.0, 0.0), (1.0, 0.0), (1.0, 0.0)];
        assert!(Assembly::from_quadrilaterals(&[flat]).is_err());
    }

    #[test]
    fn thickness_and_angles_are_checked() {
        let n = NonZeroUsize::new(3).unwrap();
        assert!(CircularArch::new(1.0, 2.0, n, 0.0, 0.0, VoussoirShape::Curved).is_err());
        assert!(CircularArch::new(1.0, 0.0, n, 0.0, 0.0, VoussoirShape::Curved).is_err());
        assert!(CircularArch::new(1.0, 0.1, n, 90.0, 0.0, VoussoirShape::Curved).is_err());
        assert!(CircularArch::new(1.0, 0.1, n, -89.0, -89.0, VoussoirShape::Curved).is_ok());
        assert!(CircularArch::new(f64::NAN, 0.1, n, 0.0, 0.0, VoussoirShape::Curved).is_err());
    }
}
