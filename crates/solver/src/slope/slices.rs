//! What the equilibrium equations see of a slip surface: the slices with their weights,
//! strengths, pore pressures and known loads, in the solver's frame (crest towards +x, the mass
//! sliding towards −x). Both the simple embankment of [`super::geometry`] and the sections of
//! [`super::section`] are cut into this one form, so every method works on both.

use std::borrow::Cow;
use std::num::NonZeroUsize;
use std::sync::Arc;

use super::strength::Envelope;

use super::error::{check_range, SlopeError, SlopeParameter};

/// One vertical slice: its geometry, weight, base strength and pore pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BaseSlice {
    /// x of the left (toe-side) vertical side.
    pub x_left: f64,
    /// x of the right (crest-side) vertical side.
    pub x_right: f64,
    /// y of the base at the left side.
    pub base_left_y: f64,
    /// y of the base at the right side.
    pub base_right_y: f64,
    /// Ground level at the right side.
    pub top_right_y: f64,
    /// sin α and cos α of the base's inclination α (see [`BaseSlice::base_inclination_rad`]).
    pub base_sin_cos: (f64, f64),
    /// Length of the base.
    pub base_length: f64,
    /// Middle of the base, the point about which the 1973 moment equation is written.
    pub base_middle: (f64, f64),
    /// Height of the slice at its middle, from the base to the ground.
    pub height_middle: f64,
    /// Weight W of the soil in the slice.
    pub weight: f64,
    /// Height of the centre of gravity of the soil (where a horizontal seismic force acts).
    pub centroid_y: f64,
    /// Effective cohesion c' at the base.
    pub cohesion: f64,
    /// tan φ' at the base.
    pub tan_phi: f64,
    /// Pore pressure u at the base middle.
    pub pore_pressure: f64,
    /// Index of the soil (layer) at the base; 0 for a single soil. Where the layer has a
    /// nonlinear envelope ([`SliceModel::envelopes`]), `cohesion` and `tan_phi` are its
    /// tangent at an estimate of the base's σ′ₙ, to be moved to its consistent state (model
    /// §8), unless the slice is among [`SliceModel::fixed`].
    pub layer: usize,
    /// The pore water's force on the right side (horizontal, ∫u dy from the base to the
    /// ground) and the height it acts at: what separates the total inter-slice force there
    /// from the effective one (Spencer 1973).
    pub side_water: (f64, f64),
}

impl BaseSlice {
    /// Width b of the slice.
    pub fn width(&self) -> f64 {
        self.x_right - self.x_left
    }

    /// Inclination α of the (straight) base, positive where it rises towards the crest.
    pub fn base_inclination_rad(&self) -> f64 {
        (self.base_right_y - self.base_left_y).atan2(self.width())
    }
}

/// The slices of one slip surface and everything else the equations need.
#[derive(Debug, Clone, PartialEq)]
pub struct SliceModel {
    /// The slices, from the toe end (lower end) to the crest end.
    pub slices: Vec<BaseSlice>,
    /// Seismic coefficients (on the soil weight).
    pub seismic: Seismic,
    /// Known forces on slices (moments about their base middles).
    pub loads: Vec<ExternalLoad>,
    /// The point Spencer's and Morgenstern–Price's moment equation is written about: a circle's
    /// centre, or a point above a polyline's middle. Where force equilibrium holds the point
    /// does not change their root; it is never the given moment centre, so that they do not
    /// depend on it (model §6.3).
    pub reference: (f64, f64),
    /// The centre of rotation the moment-only methods (Bishop's, the ordinary method) take
    /// moments about: a circle's centre, or the one given for a polyline; `None` otherwise.
    pub moment_centre: Option<(f64, f64)>,
    /// Whether the surface is a circle about `reference`: every base normal then passes through
    /// it, and with φ' = 0 the moment equation alone fixes F.
    pub circular: bool,
    /// A length of the size of the mass (the radius of a circle), to scale moment residuals.
    pub length_scale: f64,
    /// Per layer, its nonlinear strength envelope (`None` when no layer has one: nothing to
    /// share between threads).
    pub envelopes: Option<Arc<[Option<Envelope>]>>,
    /// Slices on a nonlinear envelope whose strength is fixed where it stands (dropped in
    /// tension), sorted.
    pub fixed: Vec<usize>,
}

impl SliceModel {
    /// The same slices with moments taken about `centre` (the moment-only methods).
    pub fn about(&self, centre: (f64, f64)) -> Self {
        Self {
            reference: centre,
            ..self.clone()
        }
    }

    /// The greatest vertical depth of the slip surface below the ground, at the slices'
    /// middles (what `search.min_depth` compares).
    pub fn depth(&self) -> f64 {
        self.slices
            .iter()
            .map(|s| s.height_middle)
            .fold(0.0, f64::max)
    }

    /// The nonlinear envelope of `layer`, if it has one.
    pub fn envelope(&self, layer: usize) -> Option<&Envelope> {
        self.envelopes.as_deref()?.get(layer)?.as_ref()
    }

    /// The envelope slice `i` moves along, if its strength is not fixed.
    pub fn moving_envelope(&self, i: usize) -> Option<&Envelope> {
        let slice = self.slices.get(i)?;
        let envelope = self.envelope(slice.layer)?;
        self.fixed.binary_search(&i).is_err().then_some(envelope)
    }

    /// The start of the slip surface (toe end).
    pub fn lower_end(&self) -> (f64, f64) {
        self.slices
            .first()
            .map_or((0.0, 0.0), |s| (s.x_left, s.base_left_y))
    }
}

/// A slip surface on a slope that the equations can be set up for, and re-cut into a
/// different number of slices.
pub trait Sliced: Sized {
    /// The slices and loads.
    fn model(&self) -> Cow<'_, SliceModel>;
    /// The number of slices.
    fn slice_count(&self) -> usize;
    /// The same surface cut into (about) `slices` slices.
    fn with_slices(&self, slices: NonZeroUsize) -> Result<Self, SlopeError>;
}

/// Pseudo-static seismic coefficients: k_h·W towards the toe and k_v·W downwards, at the slice
/// centroids.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Seismic {
    /// Horizontal coefficient k_h (≥ 0 acts towards the toe).
    pub kh: f64,
    /// Vertical coefficient k_v (positive downwards).
    pub kv: f64,
}

impl Seismic {
    /// Seismic coefficients −10 ≤ k_h ≤ 10 and −0.99 ≤ k_v ≤ 10 (k_v > −1 keeps gravity acting).
    pub fn new(kh: f64, kv: f64) -> Result<Self, SlopeError> {
        Ok(Self {
            kh: check_range(
                SlopeParameter::SeismicKh,
                kh,
                -10.0,
                false,
                10.0,
                "-10 ≤ kh ≤ 10",
            )?,
            kv: check_range(
                SlopeParameter::SeismicKv,
                kv,
                -0.99,
                false,
                10.0,
                "-0.99 ≤ kv ≤ 10",
            )?,
        })
    }
}

/// Checks loads given per slice against `slices` slices: each on an existing slice, with
/// finite components.
pub(crate) fn check_slice_loads(loads: &[ExternalLoad], slices: usize) -> Result<(), SlopeError> {
    for (index, load) in loads.iter().enumerate() {
        if load.slice >= slices {
            return Err(SlopeError::OutOfRange {
                parameter: SlopeParameter::ExternalLoadSlice { index },
                value: (load.slice + 1) as f64,
                allowed: "the number of an existing slice, 1 ≤ slice ≤ slices",
            });
        }
        for value in [load.fx, load.fy, load.moment] {
            let parameter = SlopeParameter::ExternalLoad { index };
            check_range(
                parameter,
                value,
                f64::MIN,
                false,
                f64::MAX,
                "a finite number",
            )?;
        }
    }
    Ok(())
}

/// A known force on one slice, applied at the middle of its base (the thesis' F_x, F_y, M1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExternalLoad {
    /// Index of the slice, 0 at the lower end.
    pub slice: usize,
    /// Horizontal force, positive towards +x (the crest side).
    pub fx: f64,
    /// Vertical force, positive upwards.
    pub fy: f64,
    /// Moment of the load about the middle of the base, counter-clockwise positive.
    pub moment: f64,
    /// Whether its component along the base is mobilised like strength (a passive support:
    /// added to the resisting force, divided by F) rather than known (reducing the driving
    /// force); its component across the base presses the base either way.
    pub passive: bool,
}
