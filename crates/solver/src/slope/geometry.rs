//! The embankment, the slip circle and the vertical slices it is cut into (model §2.1; the
//! thesis' "Geometry Configuration" script).
//!
//! The service analyses the simple embankment as a section ([`super::section::Section::simple`],
//! the circle placed by [`SlipCircle::placed`]): one engine for every slope. This module keeps
//! the thesis' own geometry as an independent check of that engine (the two agree to rounding
//! wherever the circle's mass starts at its lower end) and as the reference the published
//! tables are reproduced with.
//!
//! The slip circle passes through its lower end, which lies on the ground at `F_e·H` in front of
//! the toe; its centre is given relative to that lower end. The sliding mass is bounded by the
//! lower arc of the circle and the ground surface, between the lower end and the point where the
//! arc comes back to the surface (the upper exit). It is cut into N vertical slices of equal
//! width. Each slice is the polygon between its two vertical sides, the ground surface (with its
//! kinks at the toe and the crest) and the **chord** of the arc: the base is straight, its
//! inclination α is that of the chord, positive where the base rises towards the crest. This is
//! the idealisation with which the thesis reproduces Spencer's (1967) numbers digit for digit.

use super::error::{check_range, SlopeError, SlopeParameter};
use crate::polygon::polygon_area_centroid;

/// Relative tolerance on lengths used to tell a genuine exit point from the lower end itself.
const SAME_POINT: f64 = 1e-9;

/// The embankment: toe at the origin, slope face up to (length, height), level crest beyond.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Embankment {
    height: f64,
    length: f64,
}

impl Embankment {
    /// An embankment of the given height H and horizontal slope length L, both positive.
    pub fn new(height: f64, length: f64) -> Result<Self, SlopeError> {
        let allowed = "a finite number > 0";
        Ok(Self {
            height: check_range(SlopeParameter::Height, height, 0.0, true, f64::MAX, allowed)?,
            length: check_range(SlopeParameter::Length, length, 0.0, true, f64::MAX, allowed)?,
        })
    }

    /// Slope height H.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// Horizontal length L of the slope face.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Height of the ground surface at `x`.
    pub fn ground(&self, x: f64) -> f64 {
        if x <= 0.0 {
            0.0
        } else if x >= self.length {
            self.height
        } else {
            self.height * x / self.length
        }
    }

    /// The straight pieces of the ground surface as (x_start, x_end, slope, intercept).
    fn pieces(&self) -> [(f64, f64, f64, f64); 3] {
        [
            (f64::NEG_INFINITY, 0.0, 0.0, 0.0),
            (0.0, self.length, self.height / self.length, 0.0),
            (self.length, f64::INFINITY, 0.0, self.height),
        ]
    }
}

/// A trial slip circle in the thesis' variables.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipCircle {
    /// Horizontal distance X from the lower end of the slip surface to the centre.
    pub x: f64,
    /// Height Y of the centre above the lower end of the slip surface.
    pub y: f64,
    /// Lower-end position factor F_e: the lower end lies F_e·H in front of the toe (≥ 0).
    pub lower_end_factor: f64,
}

impl SlipCircle {
    /// Checks the thesis' variables: X finite, Y > 0 (the centre above the lower end), F_e ≥ 0.
    pub fn check(&self) -> Result<(), SlopeError> {
        check_range(
            SlopeParameter::CircleX,
            self.x,
            f64::MIN,
            false,
            f64::MAX,
            "a finite number",
        )?;
        check_range(
            SlopeParameter::CircleY,
            self.y,
            0.0,
            true,
            f64::MAX,
            "a finite number > 0 (the centre lies above the lower end)",
        )?;
        check_range(
            SlopeParameter::LowerEndFactor,
            self.lower_end_factor,
            0.0,
            false,
            f64::MAX,
            "a finite number ≥ 0",
        )?;
        Ok(())
    }

    /// The circle as a section's: centre (−F_e·H + X, Y), radius √(X² + Y²), after the checks
    /// of the thesis' variables (Y > 0, F_e ≥ 0, all finite).
    pub fn placed(&self, height: f64) -> Result<super::section::shape::SlipShape, SlopeError> {
        self.check()?;
        // `+ 0.0` turns −0.0 (F_e = 0) into 0.0.
        let through = -self.lower_end_factor * height + 0.0;
        Ok(super::section::shape::SlipShape::Circle {
            centre: (through + self.x, self.y),
            radius: self.x.hypot(self.y),
        })
    }
}

/// One vertical slice of the sliding mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slice {
    /// x of the left (toe-side) vertical side.
    pub x_left: f64,
    /// x of the right (crest-side) vertical side.
    pub x_right: f64,
    /// y of the base at the left side (a point of the circle).
    pub base_left_y: f64,
    /// y of the base at the right side (a point of the circle).
    pub base_right_y: f64,
    /// Inclination α of the base chord, positive where it rises towards the crest.
    pub base_inclination_rad: f64,
    /// Length l = b / cos α of the base chord.
    pub base_length: f64,
    /// Cross-section area of the slice polygon.
    pub area: f64,
    /// Centroid of the slice polygon.
    pub centroid: (f64, f64),
    /// Middle of the base chord, the point about which the 1973 moment equation is written.
    pub base_middle: (f64, f64),
    /// Height h of the slice at its middle, from the base chord to the ground surface.
    pub height_middle: f64,
}

impl Slice {
    /// Width b of the slice.
    pub fn width(&self) -> f64 {
        self.x_right - self.x_left
    }

    /// Ground level at the top of the left side.
    pub fn top_left_y(&self, embankment: &Embankment) -> f64 {
        embankment.ground(self.x_left)
    }
}

/// The slip circle placed on the embankment, and the slices cut from the sliding mass.
#[derive(Debug, Clone, PartialEq)]
pub struct SlopeGeometry {
    /// The embankment.
    pub embankment: Embankment,
    /// The circle as given.
    pub circle: SlipCircle,
    /// Centre of the circle in embankment coordinates.
    pub centre: (f64, f64),
    /// Radius of the circle.
    pub radius: f64,
    /// Lower end of the slip surface (on the ground, at or in front of the toe).
    pub lower_end: (f64, f64),
    /// Upper exit of the slip surface on the ground surface.
    pub upper_exit: (f64, f64),
    /// The slices, from the lower end to the upper exit.
    pub slices: Vec<Slice>,
}

impl SlopeGeometry {
    /// Places `circle` on `embankment` and cuts the sliding mass into `slices` slices.
    ///
    /// Fails with [`SlopeError::NoSlipMass`] when the circle does not enter the ground at its
    /// lower end, or does not come back to the surface on the lower half of the circle.
    pub fn new(
        embankment: Embankment,
        circle: SlipCircle,
        slices: std::num::NonZeroUsize,
    ) -> Result<Self, SlopeError> {
        let h = embankment.height;
        circle.check()?;
        // `+ 0.0` turns −0.0 (F_e = 0) into 0.0.
        let lower_end = (-circle.lower_end_factor * h + 0.0, 0.0);
        let centre = (lower_end.0 + circle.x, circle.y);
        let radius = circle.x.hypot(circle.y);

        // The arc must dip below the ground just after the lower end: compare the slope of the
        // arc there with the slope of the ground surface to its right.
        let arc_slope = -circle.x / circle.y;
        let ground_slope = if lower_end.0 < 0.0 {
            0.0
        } else {
            h / embankment.length
        };
        if arc_slope >= ground_slope {
            return Err(SlopeError::NoSlipMass {
                parameter: SlopeParameter::CircleX,
                reason: format!(
                    "the circle does not enter the ground at its lower end (its slope there is \
                     {arc_slope:.4}, the ground's {ground_slope:.4}); move the centre further \
                     towards the crest"
                ),
            });
        }
        let exit_x = upper_exit(&embankment, centre, radius, lower_end.0).ok_or_else(|| {
            SlopeError::NoSlipMass {
                parameter: SlopeParameter::CircleY,
                reason: format!(
                    "the lower half of the circle (radius {radius:.4}) does not come back to \
                     the ground surface; raise the centre or move it towards the toe"
                ),
            }
        })?;
        let upper_exit = (exit_x, embankment.ground(exit_x));
        let arc_y = |x: f64| centre.1 - (radius * radius - (x - centre.0).powi(2)).max(0.0).sqrt();

        let n = slices.get();
        let width = (exit_x - lower_end.0) / n as f64;
        let slices = (0..n)
            .map(|i| {
                let x_left = lower_end.0 + width * i as f64;
                let x_right = if i + 1 == n {
                    exit_x
                } else {
                    lower_end.0 + width * (i + 1) as f64
                };
                let base_left_y = if i == 0 { lower_end.1 } else { arc_y(x_left) };
                let base_right_y = if i + 1 == n {
                    upper_exit.1
                } else {
                    arc_y(x_right)
                };
                slice_polygon(&embankment, x_left, x_right, base_left_y, base_right_y)
            })
            .collect();
        Ok(Self {
            embankment,
            circle,
            centre,
            radius,
            lower_end,
            upper_exit,
            slices,
        })
    }
}

/// The smallest x beyond `x_start` where the lower arc of the circle meets the ground surface.
fn upper_exit(
    embankment: &Embankment,
    centre: (f64, f64),
    radius: f64,
    x_start: f64,
) -> Option<f64> {
    let (xc, yc) = centre;
    let tolerance = SAME_POINT * radius.max(embankment.height);
    embankment
        .pieces()
        .iter()
        .flat_map(|&(x0, x1, m, k)| {
            // (x − xc)² + (m x + k − yc)² = R²  →  a x² + b x + c = 0
            let d = k - yc;
            let a = 1.0 + m * m;
            let b = 2.0 * (m * d - xc);
            let c = xc * xc + d * d - radius * radius;
            let discriminant = b * b - 4.0 * a * c;
            // No crossing with this piece when the discriminant is negative.
            let roots = (discriminant >= 0.0).then(|| {
                let sq = discriminant.sqrt();
                [(-b - sq) / (2.0 * a), (-b + sq) / (2.0 * a)]
            });
            roots.into_iter().flatten().filter(move |&x| {
                x.is_finite()
                    && x >= x0 - tolerance
                    && x <= x1 + tolerance
                    && x > x_start + tolerance
                    && m * x + k <= yc
            })
        })
        .min_by(f64::total_cmp)
}

/// The slice between two verticals, under the ground surface and above the base chord.
fn slice_polygon(
    embankment: &Embankment,
    x_left: f64,
    x_right: f64,
    base_left_y: f64,
    base_right_y: f64,
) -> Slice {
    // Counter-clockwise: along the base, up the right side, back along the ground.
    let mut polygon = vec![
        (x_left, base_left_y),
        (x_right, base_right_y),
        (x_right, embankment.ground(x_right)),
    ];
    for kink in [embankment.length, 0.0] {
        if kink > x_left && kink < x_right {
            polygon.push((kink, embankment.ground(kink)));
        }
    }
    polygon.push((x_left, embankment.ground(x_left)));
    let (area, centroid) = polygon_area_centroid(&polygon);
    let width = x_right - x_left;
    let base_inclination_rad = (base_right_y - base_left_y).atan2(width);
    let x_middle = 0.5 * (x_left + x_right);
    let base_middle = (x_middle, 0.5 * (base_left_y + base_right_y));
    Slice {
        x_left,
        x_right,
        base_left_y,
        base_right_y,
        base_inclination_rad,
        base_length: width.hypot(base_right_y - base_left_y),
        area,
        centroid,
        base_middle,
        height_middle: embankment.ground(x_middle) - base_middle.1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::num::NonZeroUsize;

    fn spencer_example(n: usize) -> SlopeGeometry {
        crate::reference::spencer_1967::problem(n).geometry
    }

    #[test]
    fn spencer_example_radius_and_exit() {
        // Thesis Figure 5-8: R = 64.4875 m, slice width B = 6.48657 m at N = 10.
        let g = spencer_example(10);
        assert!((g.radius - 64.4875).abs() < 5e-5, "radius {}", g.radius);
        assert!((g.slices[0].width() - 6.48657).abs() < 5e-6);
        // Exit on the crest: (x − xc)² = R² − (H − Y)², by hand.
        let expected = 9.63168 + (g.radius.powi(2) - (30.48f64 - 63.76416).powi(2)).sqrt();
        assert!((g.upper_exit.0 - expected).abs() < 1e-9);
        assert_eq!(g.upper_exit.1, 30.48);
    }

    #[test]
    fn slice_areas_add_up_to_the_segment_area() {
        // Independent: the sliding mass area = area under the ground − area under the chords.
        // For a fine cut this tends to ∫ (ground − arc) dx, here by Simpson's rule.
        let g = spencer_example(2000);
        let total: f64 = g.slices.iter().map(|s| s.area).sum();
        let (xc, yc, r) = (g.centre.0, g.centre.1, g.radius);
        let f = |x: f64| g.embankment.ground(x) - (yc - (r * r - (x - xc).powi(2)).sqrt());
        let (a, b, m) = (g.lower_end.0, g.upper_exit.0, 20000);
        let h = (b - a) / m as f64;
        let mut simpson = f(a) + f(b);
        for i in 1..m {
            simpson += f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        simpson *= h / 3.0;
        // 1e-4 relative: chords cut off O(N⁻²) of the segment, Simpson misses the kinks.
        assert!(
            (total - simpson).abs() / simpson < 1e-4,
            "{total} vs {simpson}"
        );
    }

    #[test]
    fn circle_that_rises_out_of_the_ground_is_rejected() {
        let embankment = Embankment::new(10.0, 20.0).unwrap();
        // Lower end in front of the toe, centre behind it: the arc rises above level ground.
        let circle = SlipCircle {
            x: -1.0,
            y: 20.0,
            lower_end_factor: 0.5,
        };
        let err = SlopeGeometry::new(embankment, circle, NonZeroUsize::new(10).unwrap());
        assert!(matches!(
            err,
            Err(SlopeError::NoSlipMass {
                parameter: SlopeParameter::CircleX,
                ..
            })
        ));
    }

    #[test]
    fn circle_whose_centre_is_below_the_crest_and_never_exits_is_rejected() {
        let embankment = Embankment::new(10.0, 10.0).unwrap();
        // Small circle through the toe, centre at mid-height far inside: the lower half ends at
        // height 2 inside the slope face, below the surface.
        let circle = SlipCircle {
            x: 30.0,
            y: 2.0,
            lower_end_factor: 0.0,
        };
        let err = SlopeGeometry::new(embankment, circle, NonZeroUsize::new(10).unwrap());
        assert!(matches!(
            err,
            Err(SlopeError::NoSlipMass {
                parameter: SlopeParameter::CircleY,
                ..
            })
        ));
    }

    #[test]
    fn nonpositive_height_is_rejected() {
        assert!(Embankment::new(0.0, 1.0).is_err());
        assert!(Embankment::new(f64::NAN, 1.0).is_err());
        assert!(Embankment::new(1.0, f64::INFINITY).is_err());
    }
}
