//! The published problems the crate is checked against (model §1.4, §2.3), built in one place for
//! the tests, the benchmarks and the service's tests: Spencer's (1967) example embankment and
//! Milankovitch's (1904) semicircular arch. The reference *values* live next to the problems, with
//! their sources, so that a test names what it compares with.

use std::num::NonZeroUsize;

use crate::arch::{CircularArch, VoussoirShape};
use crate::slope::{Embankment, SlipCircle, SlopeProblem, Soil};

/// Spencer (1967), the example of his paper in the thesis' SI units: H = 100 ft, slope 2:1,
/// c'/(γH) = 0.02, φ' = 40°, r_u = 0.5, centre X = 31.6 ft, Y = 209.2 ft from the toe.
pub mod spencer_1967 {
    use super::*;

    /// Slope height H (30.48 m = 100 ft).
    pub const HEIGHT: f64 = 30.48;
    /// Horizontal length L of the face (2:1).
    pub const LENGTH: f64 = 60.96;
    /// Centre X from the toe (31.6 ft).
    pub const CENTRE_X: f64 = 9.63168;
    /// Centre Y above the toe (209.2 ft).
    pub const CENTRE_Y: f64 = 63.76416;
    /// c'/(γH).
    pub const COHESION_RATIO: f64 = 0.02;
    /// φ' in degrees.
    pub const FRICTION_ANGLE_DEG: f64 = 40.0;
    /// r_u.
    pub const PORE_PRESSURE_RATIO: f64 = 0.5;
    /// The unit weight the thesis and the service's examples use (F depends on c' and γ only
    /// through c'/(γH)).
    pub const UNIT_WEIGHT: f64 = 10.0;
    /// Radius of the circle (model §2.3).
    pub const RADIUS: f64 = 64.4875;
    /// Converged F as N → ∞ (the thesis: 1.06952 at N = 500 and 1000; Spencer printed 1.070).
    pub const FACTOR_OF_SAFETY: f64 = 1.0695;
    /// Converged θ in degrees.
    pub const THETA_DEG: f64 = 22.43;
    /// Bishop's simplified F for the same circle (model §2.3, ≈).
    pub const BISHOP_FACTOR_OF_SAFETY: f64 = 1.040;

    /// The embankment.
    pub fn embankment() -> Embankment {
        Embankment::new(HEIGHT, LENGTH).expect("Spencer's embankment is valid")
    }

    /// The slip circle through the toe.
    pub fn circle() -> SlipCircle {
        SlipCircle {
            x: CENTRE_X,
            y: CENTRE_Y,
            lower_end_factor: 0.0,
        }
    }

    /// The soil with unit weight `unit_weight` (c' = 0.02·γ·H).
    pub fn soil(unit_weight: f64) -> Soil {
        Soil::new(
            unit_weight,
            COHESION_RATIO * unit_weight * HEIGHT,
            FRICTION_ANGLE_DEG,
            PORE_PRESSURE_RATIO,
        )
        .expect("Spencer's soil is valid")
    }

    /// The example circle cut into `slices` slices, static, with γ = [`UNIT_WEIGHT`].
    /// The example circle on the embankment as a section, as the service analyses it.
    pub fn section_problem(slices: usize) -> crate::slope::section::SectionProblem {
        let placed = circle().placed(HEIGHT).expect("Spencer's circle is finite");
        let section = crate::slope::section::Section::simple(&embankment(), soil(UNIT_WEIGHT))
            .expect("Spencer's embankment is a section");
        crate::slope::section::SectionProblem::new(
            section,
            placed,
            NonZeroUsize::new(slices).expect("at least one slice"),
            Default::default(),
            None,
        )
        .expect("Spencer's circle cuts the embankment")
    }

    /// The example circle in the thesis' own geometry (kept as an independent check of the
    /// section engine).
    pub fn problem(slices: usize) -> SlopeProblem {
        SlopeProblem::new(
            embankment(),
            circle(),
            NonZeroUsize::new(slices).expect("at least one slice"),
            soil(UNIT_WEIGHT),
            Default::default(),
            Vec::new(),
        )
        .expect("Spencer's circle cuts the embankment")
    }
}

/// Milankovitch (1904): the minimum thickness of a semicircular arch under its own weight,
/// d_min/R = 0.10748 with the rupture at 54.48° from the crown; the thesis' N = 1800 case.
pub mod milankovitch {
    /// The thesis' radius.
    pub const RADIUS: f64 = 10.0;
    /// The thesis' number of curved voussoirs.
    pub const VOUSSOIRS: usize = 1800;
    /// Exact limit d/R.
    pub const THICKNESS_TO_RADIUS: f64 = 0.10748;
    /// Rupture angle from the crown in degrees.
    pub const RUPTURE_ANGLE_DEG: f64 = 54.48;
    /// With N = 1800 and R = 10 this thickness carries its weight (λ₀ = 1) …
    pub const THICKNESS_STANDS: f64 = 1.0748;
    /// … and this one does not (λ₀ = 0, five hinges).
    pub const THICKNESS_FALLS: f64 = 1.0747;
}

/// A circular arch of `n` voussoirs of the given shape, between equal base angles (0: the
/// semicircle).
pub fn circular_arch(
    n: usize,
    radius: f64,
    thickness: f64,
    base_angle_deg: f64,
    shape: VoussoirShape,
) -> CircularArch {
    CircularArch::new(
        radius,
        thickness,
        NonZeroUsize::new(n).expect("at least one voussoir"),
        base_angle_deg,
        base_angle_deg,
        shape,
    )
    .expect("a valid circular arch")
}

/// A semicircular arch of `n` curved voussoirs.
pub fn semicircle(n: usize, radius: f64, thickness: f64) -> CircularArch {
    circular_arch(n, radius, thickness, 0.0, VoussoirShape::Curved)
}
