//! The Spencer request as clients send it (serde + OpenAPI types). [`super::input`] turns it
//! into the solver's validated inputs; nothing else reads it.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

pub use super::loads::{LineLoadDto, SurchargeDto};
pub use super::options::{AccuracyDto, CompositeDto, Coordinates, SlopeDetailDto};

mod search;
pub mod soil;
pub mod water;

pub use search::{SearchDto, SearchShapeDto};

/// The embankment: toe at the origin, slope face up to (length, height), level crest beyond.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SlopeDto {
    /// Slope height H, 1e-9 ≤ H ≤ 1e9.
    #[schema(examples(30.48))]
    pub height: f64,
    /// Horizontal length L of the slope face, 1e-9 ≤ L ≤ 1e9; the slope is H:L.
    #[schema(examples(60.96))]
    pub length: f64,
}

/// A trial slip circle: either relative to the lower end of the slip surface (`x`, `y`,
/// `lower_end_factor`; the simple `slope` only) or absolute (`centre`, `radius`; any section,
/// and the simple `slope` in its own coordinates, toe at the origin).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CircleDto {
    /// Relative form: horizontal distance X from the lower end to the centre (towards the crest
    /// positive).
    #[serde(default)]
    #[schema(examples(9.63168))]
    pub x: Option<f64>,
    /// Relative form: height Y of the centre above the lower end (> 0).
    #[serde(default)]
    #[schema(examples(63.76416))]
    pub y: Option<f64>,
    /// Relative form: lower-end position factor F_e ≥ 0: the lower end lies F_e·H in front of
    /// the toe. Defaults to 0.
    #[serde(default)]
    #[schema(examples(0.0))]
    pub lower_end_factor: Option<f64>,
    /// Absolute form: the centre [x, y] in the section's coordinates.
    #[serde(default)]
    #[schema(value_type = Option<Vec<f64>>, min_items = 2, max_items = 2)]
    pub centre: Option<[f64; 2]>,
    /// Absolute form: the radius, 0 < R ≤ 1e9. The sliding mass lies above the arc between
    /// the two crossings of the ground that bound the deepest part of the arc.
    #[serde(default)]
    #[schema(examples(80.0))]
    pub radius: Option<f64>,
    /// On a section, a circle that cuts the ground more than twice: which mass is analysed —
    /// `"largest"` (the largest within the section that something drives; the default) or k,
    /// the k-th mass from the left (from 1).
    #[serde(default)]
    pub mass: Option<MassDto>,
    /// On a section: whether the circle may enter or leave the ground beyond the section's
    /// x-range, the ground taken as level there (answered with the `beyond_ground` warning).
    /// Defaults to false: such a circle is refused (422), extend `section.ground` instead.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub beyond_ground: bool,
}

/// Soil properties, the same in every slice.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SoilDto {
    /// Unit weight γ, 0 < γ ≤ 1e12.
    #[schema(examples(10.0))]
    pub unit_weight: f64,
    /// Effective cohesion c', 0 ≤ c' ≤ 1e12 (> 0 when the friction angle is 0). Required
    /// unless `strength` is given (then not allowed).
    #[serde(default)]
    #[schema(examples(6.096))]
    pub cohesion: Option<f64>,
    /// Effective friction angle φ' in degrees, 0 ≤ φ' ≤ 89.9. Required unless `strength` is
    /// given (then not allowed).
    #[serde(default)]
    #[schema(examples(40.0))]
    pub friction_angle_deg: Option<f64>,
    /// A strength model instead of `cohesion` and `friction_angle_deg` (model §8): undrained
    /// strength with depth, a power curve, Hoek–Brown or a shear–normal function. In a
    /// section's layers only.
    #[serde(default)]
    pub strength: Option<soil::StrengthDto>,
    /// Pore pressure ratio r_u = u/σ_v (σ_v = W/b, γh in one soil), 0 ≤ r_u ≤ 1. Defaults to
    /// 0 for `soil`; in a section's layer, when given it sets the pore pressure at bases in
    /// this soil in place of the piezometric line.
    #[serde(default)]
    #[schema(examples(0.5))]
    pub pore_pressure_ratio: Option<f64>,
    /// In a section's layer with `section.drawdown`: the soil does not drain during the
    /// drawdown, and this is its total-stress (R) envelope.
    #[serde(default)]
    pub r_envelope: Option<soil::REnvelopeDto>,
}

/// Pseudo-static seismic coefficients, applied at the slice centroids.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SeismicDto {
    /// Horizontal coefficient: k_h·W acts towards the toe. −10 ≤ k_h ≤ 10.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(examples(0.1))]
    pub kh: f64,
    /// Vertical coefficient: k_v·W acts downwards. −0.99 ≤ k_v ≤ 10.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(examples(0.0))]
    pub kv: f64,
}

/// A known load on one slice, applied at the middle of its base (the thesis' F_x, F_y, M1).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ExternalLoadDto {
    /// Slice number, 1 at the lower end of the slip surface.
    #[schema(examples(3))]
    #[serde(deserialize_with = "crate::nullable::integer")]
    pub slice: usize,
    /// Horizontal force, positive towards the crest (+x).
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub fx: f64,
    /// Vertical force, positive upwards.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub fy: f64,
    /// Moment about the middle of the slice base, counter-clockwise positive.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub moment: f64,
}

/// A Spencer analysis of one slip circle.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(examples(json!({
    "slope": {"height": 30.48, "length": 60.96},
    "circle": {"x": 9.63168, "y": 63.76416, "lower_end_factor": 0.0},
    "slices": 100,
    "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0, "pore_pressure_ratio": 0.5}
})))]
pub struct SpencerRequest {
    /// The simple embankment (with `soil`); or give `section`.
    #[serde(default)]
    pub slope: Option<SlopeDto>,
    /// Any cross-section: ground, layers, water, bedrock, loads, tension crack (instead of
    /// `slope` and `soil`).
    #[serde(default)]
    pub section: Option<SectionDto>,
    /// The slip circle to analyse (give this, `surface` or `search`).
    #[serde(default)]
    pub circle: Option<CircleDto>,
    /// Any slip surface: a polyline [[x, y], ...] running left to right, its first and last
    /// points at or above the ground (the surface starts and ends where it crosses the ground).
    #[serde(default)]
    #[schema(value_type = Option<Vec<Vec<f64>>>)]
    pub surface: Option<Vec<[f64; 2]>>,
    /// The centre [x, y] about which the moment-only methods (Bishop's, the ordinary method) take
    /// moments for a `surface`; without it they are not reported for a surface (a circle uses its
    /// centre). Spencer's, Morgenstern–Price's and Janbu's answers never depend on it.
    #[serde(default)]
    #[schema(value_type = Option<Vec<f64>>, min_items = 2, max_items = 2)]
    pub moment_centre: Option<[f64; 2]>,
    /// Search for the critical circle instead (`{}` for automatic bounds).
    #[serde(default)]
    pub search: Option<SearchDto>,
    /// Other methods to report beside Spencer's, for the same slices: `morgenstern_price`,
    /// `bishop`, `janbu`, `ordinary` (answered in `methods`).
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub methods: Vec<super::methods::MethodName>,
    /// Morgenstern–Price's inter-slice function as points [ξ, f], ξ from 0 (toe end) to 1
    /// (crest end); defaults to the half-sine sin(π·ξ).
    #[serde(default)]
    #[schema(value_type = Option<Vec<Vec<f64>>>)]
    pub interslice_function: Option<Vec<[f64; 2]>>,
    /// Where a slice base comes out in tension (negative effective normal force): `keep` the
    /// classic equations (the default: Spencer's and the thesis' published numbers; a root
    /// held up by net tension is answered `unphysical`, never converged), `drop_friction`
    /// (no tension: the frictional term is dropped on those slices, c' kept, and the equations
    /// solved again, as Slide2 and SLOPE/W do) or `drop_strength` (c' dropped too). The
    /// `methods` answer on the slices the headline dropped.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub negative_effective_stress: NegativeEffectiveStressDto,
    /// The details to answer with, of `surface`, `slices`, `thrust_line`,
    /// `effective_thrust_line`, `grid`. Those left out come back empty (`grid` absent) and are
    /// listed in `omitted`; F, θ, the totals and the other fields are always there. Defaults to
    /// all of them. Drawings ignore it.
    #[serde(default)]
    pub include: Option<Vec<SlopeDetailDto>>,
    /// A partial-factor check (EN 1997-1): `{"approach": "DA1-2"}` or `{"factors": {...}}`.
    /// The analysis (and a search) runs on the design values; the answer adds `design` with the
    /// over-design factor and whether it is verified.
    #[serde(default)]
    pub design: Option<super::design::DesignDto>,
    /// Also return Spencer's curves F_f(θ) and F_m(θ) around the solution. Defaults to false.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub curves: bool,
    /// Accuracy control: when given (1e-9 … 0.1), the slices are doubled from `slices` until F
    /// changes by less than this fraction (at most 10000 slices); `slice_refinement` lists the
    /// steps. Defaults to none: exactly `slices` slices. 1e-4 suits ordinary slopes.
    #[serde(default)]
    #[schema(examples(1e-4))]
    pub slice_tolerance: Option<f64>,
    /// The accuracy asked for instead of a slice count: `{"relative_error": 1e-4}` (1e-7 …
    /// 0.1) re-cuts the answered surface at the fewest slices (from 25, doubling, at most
    /// 10000) whose estimated discretisation error is at most that fraction of F; the answer's
    /// `accuracy` says what was used.
    #[serde(default)]
    pub accuracy: Option<AccuracyDto>,
    /// Number of vertical slices of equal width, 1 ≤ N ≤ 10000. Defaults to 100.
    #[serde(
        default = "default_slices",
        deserialize_with = "crate::nullable::slices"
    )]
    #[schema(nullable)]
    #[schema(examples(100))]
    pub slices: usize,
    /// The soil of the simple `slope`.
    #[serde(default)]
    pub soil: Option<SoilDto>,
    /// Optional pseudo-static seismic load.
    #[serde(default)]
    pub seismic: Option<SeismicDto>,
    /// Optional known loads on slices.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub external_loads: Vec<ExternalLoadDto>,
    /// A probabilistic study of this analysis (model §9.2): numbers of this request as
    /// variables, the analysis run on each sample, the probability of failure (F < 1).
    #[serde(default)]
    pub probabilistic: Option<crate::study::request::ProbabilisticDto>,
    /// A sensitivity study (model §9.3): the analysis at evenly spaced values of each variable.
    #[serde(default)]
    pub sensitivity: Option<crate::study::request::SensitivityDto>,
}

fn default_slices() -> usize {
    100
}

/// A cross-section (model §4.1). Polylines run left to right with strictly increasing x and are
/// continued horizontally beyond their ends; the section may face either way.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SectionDto {
    /// The ground surface, 1 to 1000 points.
    #[schema(value_type = Vec<Vec<f64>>)]
    pub ground: Vec<Coordinates>,
    /// Soil layers from the top down (1 to 50): the soil at a point is that of the last layer
    /// whose top is at or above it. The first layer's top is the ground (`null`).
    pub layers: Vec<LayerDto>,
    /// A hard stratum: slip surfaces do not pass below it (a circle that would, follows it).
    #[serde(default)]
    #[schema(value_type = Option<Vec<Vec<f64>>>)]
    pub bedrock: Option<Vec<Coordinates>>,
    /// The piezometric line: u = h_u·γ_w·(y_line − y) below it; where it lies above the ground
    /// the water is ponded and presses on the ground. Its points (1 to 1000), or `{points,
    /// hu}` with h_u a number 0–1 or `auto` (cos²α of the line's inclination).
    #[serde(default)]
    pub piezometric_line: Option<water::PiezometricLineDto>,
    /// Pore pressures at points [x, y, u], linear over their Delaunay triangulation: u at bases
    /// in soils without their own r_u or piezometric line (in place of the section's line,
    /// which still sets ponded water). Outside the grid u = 0, with a warning.
    #[serde(default)]
    pub pore_pressure_grid: Option<water::PoreGridDto>,
    /// A rapid drawdown (model §8): the water lines before and after it, in place of
    /// `piezometric_line`; soils with an `r_envelope` do not drain.
    #[serde(default)]
    pub drawdown: Option<water::DrawdownDto>,
    /// Unit weight of water γ_w, in the units of the soils' unit weights. Defaults to 9.81
    /// (kN/m³); give 62.4 for pcf.
    #[serde(default)]
    #[schema(examples(9.81))]
    pub water_unit_weight: Option<f64>,
    /// Vertical pressures on the ground.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub surcharges: Vec<SurchargeDto>,
    /// Forces on ground points.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub line_loads: Vec<LineLoadDto>,
    /// A tension crack at the upper end of the slip surface.
    #[serde(default)]
    pub tension_crack: Option<TensionCrackDto>,
    /// Reinforcement (up to 1000): end-anchored bars, grouted tiebacks, soil nails,
    /// geosynthetics and piles; each holds the sliding mass where the slip surface crosses it.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub supports: Vec<super::supports::SupportDto>,
}

/// One soil layer.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LayerDto {
    /// The top of the layer; `null` for the first (the ground), required for the others.
    #[serde(default)]
    #[schema(value_type = Option<Vec<Vec<f64>>>)]
    pub top: Option<Vec<Coordinates>>,
    /// The layer's soil.
    pub soil: SoilDto,
    /// The layer's own piezometric line: the pore pressure at bases in this soil (unless it has
    /// its own r_u), in place of the grid and the section's line. Points, or `{points, hu}`.
    #[serde(default)]
    pub piezometric_line: Option<water::PiezometricLineDto>,
}

/// A tension crack: where the slip surface rises through the ground moved down by `depth`, it
/// stops and a vertical crack rises to the ground.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct TensionCrackDto {
    /// Depth below the ground, > 0.
    pub depth: f64,
    /// Water in the crack, measured up from its bottom, 0 ≤ z_w ≤ depth: ½·γ_w·z_w² pushes the
    /// mass towards the toe at z_w/3 above the bottom. Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub water_depth: f64,
}

/// The treatment of tension at slice bases.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum NegativeEffectiveStressDto {
    /// The classic equations (the published numbers); net tension makes a root unphysical.
    #[default]
    Keep,
    /// No tension: the frictional term dropped where N' < 0, c' kept.
    DropFriction,
    /// No strength in tension: c' dropped as well.
    DropStrength,
}

impl From<NegativeEffectiveStressDto>
    for thrustline_solver::slope::spencer::NegativeEffectiveStress
{
    fn from(dto: NegativeEffectiveStressDto) -> Self {
        match dto {
            NegativeEffectiveStressDto::Keep => Self::Keep,
            NegativeEffectiveStressDto::DropFriction => Self::DropFriction,
            NegativeEffectiveStressDto::DropStrength => Self::DropStrength,
        }
    }
}

/// Which of the masses a circle cuts out of the ground is analysed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(untagged)]
pub enum MassDto {
    /// `"largest"`: the largest within the section that something drives.
    Largest(LargestDto),
    /// The k-th mass from the left, from 1.
    Index(usize),
}

/// The largest mass.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum LargestDto {
    /// The largest within the section that something drives.
    Largest,
}

impl<'de> Deserialize<'de> for MassDto {
    /// `"largest"` or a whole number, with words that say so otherwise.
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let value = serde_json::Value::deserialize(d)?;
        match (&value, value.as_u64()) {
            (serde_json::Value::String(s), _) if s == "largest" => {
                Ok(Self::Largest(LargestDto::Largest))
            }
            (_, Some(k)) => Ok(Self::Index(usize::try_from(k).unwrap_or(usize::MAX))),
            _ => Err(serde::de::Error::custom(format!(
                "{value} is not a mass: give \"largest\" or k, the k-th mass from the left \
                 (1 ≤ k ≤ 1000)"
            ))),
        }
    }
}
