//! The data of one Spencer analysis: the soil, the seismic coefficients, known loads on slices,
//! and the slip circle cut into slices on the embankment — validated on construction.

use std::num::NonZeroUsize;

use crate::slope::error::{check_range, SlopeError, SlopeParameter};
use std::borrow::Cow;

use crate::slope::geometry::{Embankment, SlipCircle, SlopeGeometry};
use crate::slope::slices::{BaseSlice, SliceModel, Sliced};
pub use crate::slope::slices::{ExternalLoad, Seismic};

/// Soil properties, common to all slices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Soil {
    pub(crate) unit_weight: f64,
    pub(crate) cohesion: f64,
    pub(crate) friction_angle_rad: f64,
    pub(super) pore_pressure_ratio: f64,
}

impl Soil {
    /// Soil with unit weight γ > 0, cohesion c' ≥ 0, friction angle 0 ≤ φ' < 90° and pore
    /// pressure ratio 0 ≤ r_u ≤ 1; c' and φ' must not both be zero (a soil with no strength).
    pub fn new(
        unit_weight: f64,
        cohesion: f64,
        friction_angle_deg: f64,
        pore_pressure_ratio: f64,
    ) -> Result<Self, SlopeError> {
        let unit_weight = checked_unit_weight(unit_weight)?;
        let cohesion = check_range(
            SlopeParameter::Cohesion,
            cohesion,
            0.0,
            false,
            f64::MAX,
            "a finite number ≥ 0",
        )?;
        let friction_angle_deg = check_range(
            SlopeParameter::FrictionAngle,
            friction_angle_deg,
            0.0,
            false,
            89.9,
            "0 ≤ φ' ≤ 89.9 degrees",
        )?;
        let pore_pressure_ratio = check_range(
            SlopeParameter::PorePressureRatio,
            pore_pressure_ratio,
            0.0,
            false,
            1.0,
            "0 ≤ r_u ≤ 1",
        )?;
        if cohesion == 0.0 && friction_angle_deg == 0.0 {
            return Err(SlopeError::OutOfRange {
                parameter: SlopeParameter::Cohesion,
                value: cohesion,
                allowed: "> 0 when soil.friction_angle_deg is 0 (a soil with neither cohesion nor friction has no strength)",
            });
        }
        Ok(Self {
            unit_weight,
            cohesion,
            friction_angle_rad: friction_angle_deg.to_radians(),
            pore_pressure_ratio,
        })
    }

    /// A soil whose strength is given by a model of its own (model §8): its weight alone,
    /// γ > 0 (c′ = 0, φ′ = 0, r_u = 0 are not used).
    pub fn weight_only(unit_weight: f64) -> Result<Self, SlopeError> {
        Ok(Self {
            unit_weight: checked_unit_weight(unit_weight)?,
            cohesion: 0.0,
            friction_angle_rad: 0.0,
            pore_pressure_ratio: 0.0,
        })
    }

    /// Unit weight γ.
    pub fn unit_weight(&self) -> f64 {
        self.unit_weight
    }

    /// Effective cohesion c'.
    pub fn cohesion(&self) -> f64 {
        self.cohesion
    }

    /// Effective friction angle φ' in degrees.
    pub fn friction_angle_deg(&self) -> f64 {
        self.friction_angle_rad.to_degrees()
    }

    /// Pore pressure ratio r_u.
    pub fn pore_pressure_ratio(&self) -> f64 {
        self.pore_pressure_ratio
    }
}

/// A unit weight γ > 0, finite.
fn checked_unit_weight(unit_weight: f64) -> Result<f64, SlopeError> {
    check_range(
        SlopeParameter::UnitWeight,
        unit_weight,
        0.0,
        true,
        f64::MAX,
        "a finite number > 0",
    )
}

/// One slip circle of one embankment with its soil and loads, ready to solve.
#[derive(Debug, Clone, PartialEq)]
pub struct SlopeProblem {
    /// Geometry of the embankment, the circle and the slices.
    pub geometry: SlopeGeometry,
    /// The soil.
    pub soil: Soil,
    /// Seismic coefficients (zero for a static analysis).
    pub seismic: Seismic,
    /// External loads on slices.
    pub external_loads: Vec<ExternalLoad>,
}

impl SlopeProblem {
    /// Builds the problem, validating the circle against the embankment and the loads against
    /// the slices.
    pub fn new(
        embankment: Embankment,
        circle: SlipCircle,
        slices: NonZeroUsize,
        soil: Soil,
        seismic: Seismic,
        external_loads: Vec<ExternalLoad>,
    ) -> Result<Self, SlopeError> {
        Seismic::new(seismic.kh, seismic.kv)?;
        crate::slope::slices::check_slice_loads(&external_loads, slices.get())?;
        let geometry = SlopeGeometry::new(embankment, circle, slices)?;
        Ok(Self {
            geometry,
            soil,
            seismic,
            external_loads,
        })
    }

    /// The slices as the equations see them: W = γ·area, u = r_u·γ·h at the base middle, the
    /// moments about the circle's centre.
    pub fn model(&self) -> SliceModel {
        let g = &self.geometry;
        let soil = &self.soil;
        let tan_phi = soil.friction_angle_rad.tan();
        let slices = g
            .slices
            .iter()
            .map(|s| BaseSlice {
                x_left: s.x_left,
                x_right: s.x_right,
                base_left_y: s.base_left_y,
                base_right_y: s.base_right_y,
                top_right_y: g.embankment.ground(s.x_right),
                base_sin_cos: s.base_inclination_rad.sin_cos(),
                base_length: s.base_length,
                base_middle: s.base_middle,
                height_middle: s.height_middle,
                weight: soil.unit_weight * s.area,
                centroid_y: s.centroid.1,
                cohesion: soil.cohesion,
                tan_phi,
                pore_pressure: soil.pore_pressure_ratio * soil.unit_weight * s.height_middle,
                layer: 0,
                side_water: {
                    // u = r_u·γ·(ground − y): ½·r_u·γ·h² at h/3 above the base.
                    let h = (g.embankment.ground(s.x_right) - s.base_right_y).max(0.0);
                    (
                        0.5 * soil.pore_pressure_ratio * soil.unit_weight * h * h,
                        s.base_right_y + h / 3.0,
                    )
                },
            })
            .collect();
        SliceModel {
            slices,
            seismic: self.seismic,
            loads: self.external_loads.clone(),
            reference: g.centre,
            moment_centre: Some(g.centre),
            circular: true,
            length_scale: g.radius,
            envelopes: None,
            fixed: Vec::new(),
        }
    }

    /// The same problem cut into `slices` slices (external loads are given per slice, so a
    /// problem with them cannot be re-cut: it is refused).
    pub fn with_slices(&self, slices: NonZeroUsize) -> Result<Self, SlopeError> {
        if !self.external_loads.is_empty() {
            return Err(SlopeError::Conflict {
                parameter: SlopeParameter::ExternalLoads,
                reason: "loads are given per slice: the slices cannot change".to_owned(),
            });
        }
        Self::new(
            self.geometry.embankment,
            self.geometry.circle,
            slices,
            self.soil,
            self.seismic,
            Vec::new(),
        )
    }
}

impl Sliced for SlopeProblem {
    fn model(&self) -> Cow<'_, SliceModel> {
        Cow::Owned(SlopeProblem::model(self))
    }

    fn slice_count(&self) -> usize {
        self.geometry.slices.len()
    }

    fn with_slices(&self, slices: NonZeroUsize) -> Result<Self, SlopeError> {
        SlopeProblem::with_slices(self, slices)
    }
}
