//! The Spencer request as clients send it (serde + OpenAPI types). [`super::input`] turns it
//! into the solver's validated inputs; nothing else reads it.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// The embankment: toe at the origin, slope face up to (length, height), level crest beyond.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SlopeDto {
    /// Slope height H, 1e-9 ≤ H ≤ 1e9.
    #[schema(minimum = 1e-9, maximum = 1e9, examples(30.48))]
    pub height: f64,
    /// Horizontal length L of the slope face, 1e-9 ≤ L ≤ 1e9; the slope is H:L.
    #[schema(minimum = 1e-9, maximum = 1e9, examples(60.96))]
    pub length: f64,
}

/// A trial slip circle, its centre measured from the lower end of the slip surface.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CircleDto {
    /// Horizontal distance X from the lower end to the centre (towards the crest positive).
    #[schema(examples(9.63168))]
    pub x: f64,
    /// Height Y of the centre above the lower end (> 0).
    #[schema(exclusive_minimum = 0.0, examples(63.76416))]
    pub y: f64,
    /// Lower-end position factor F_e ≥ 0: the lower end lies F_e·H in front of the toe.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(minimum = 0.0, examples(0.0))]
    pub lower_end_factor: f64,
}

/// Soil properties, the same in every slice.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SoilDto {
    /// Unit weight γ, 0 < γ ≤ 1e12.
    #[schema(exclusive_minimum = 0.0, maximum = 1e12, examples(10.0))]
    pub unit_weight: f64,
    /// Effective cohesion c', 0 ≤ c' ≤ 1e12 (> 0 when the friction angle is 0).
    #[schema(minimum = 0.0, maximum = 1e12, examples(6.096))]
    pub cohesion: f64,
    /// Effective friction angle φ' in degrees, 0 ≤ φ' ≤ 89.9.
    #[schema(minimum = 0.0, maximum = 89.9, examples(40.0))]
    pub friction_angle_deg: f64,
    /// Pore pressure ratio r_u = u/(γh), 0 ≤ r_u ≤ 1.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(minimum = 0.0, maximum = 1.0, examples(0.5))]
    pub pore_pressure_ratio: f64,
}

/// Pseudo-static seismic coefficients, applied at the slice centroids.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SeismicDto {
    /// Horizontal coefficient: k_h·W acts towards the toe. −10 ≤ k_h ≤ 10.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(minimum = -10.0, maximum = 10.0, examples(0.1))]
    pub kh: f64,
    /// Vertical coefficient: k_v·W acts downwards. −0.99 ≤ k_v ≤ 10.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(minimum = -0.99, maximum = 10.0, examples(0.0))]
    pub kv: f64,
}

/// A known load on one slice, applied at the middle of its base (the thesis' F_x, F_y, M1).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ExternalLoadDto {
    /// Slice number, 1 at the lower end of the slip surface.
    #[schema(minimum = 1, maximum = 10000, examples(3))]
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
    /// The embankment.
    pub slope: SlopeDto,
    /// The slip circle to analyse (give this or `search`).
    #[serde(default)]
    pub circle: Option<CircleDto>,
    /// Search for the critical circle instead (`{}` for automatic bounds).
    #[serde(default)]
    pub search: Option<SearchDto>,
    /// Also return Spencer's curves F_f(θ) and F_m(θ) around the solution. Defaults to false.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub curves: bool,
    /// Accuracy control: when given (1e-9 … 0.1), the slices are doubled from `slices` until F
    /// changes by less than this fraction (at most 10000 slices); `slice_refinement` lists the
    /// steps. Defaults to none: exactly `slices` slices. 1e-4 suits ordinary slopes.
    #[serde(default)]
    #[schema(minimum = 1e-9, maximum = 0.1, examples(1e-4))]
    pub slice_tolerance: Option<f64>,
    /// Number of vertical slices of equal width, 1 ≤ N ≤ 10000. Defaults to 100.
    #[serde(
        default = "default_slices",
        deserialize_with = "crate::nullable::slices"
    )]
    #[schema(nullable)]
    #[schema(minimum = 1, maximum = 10000, default = 100, examples(100))]
    pub slices: usize,
    /// The soil.
    pub soil: SoilDto,
    /// Optional pseudo-static seismic load.
    #[serde(default)]
    pub seismic: Option<SeismicDto>,
    /// Optional known loads on slices.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(max_items = 10000)]
    pub external_loads: Vec<ExternalLoadDto>,
}

fn default_slices() -> usize {
    100
}

/// A search for the critical circle: a grid over centres, refined by Nelder–Mead; bounds left
/// out are chosen automatically around the perpendicular bisector of the slope.
#[derive(Debug, Clone, Default, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SearchDto {
    /// Smallest centre X (from the lower end). Automatic when missing.
    pub x_min: Option<f64>,
    /// Largest centre X. Automatic when missing.
    pub x_max: Option<f64>,
    /// Smallest centre Y (above the lower end). Automatic when missing.
    pub y_min: Option<f64>,
    /// Largest centre Y. Automatic when missing.
    pub y_max: Option<f64>,
    /// Grid points along X, 2 ≤ nx ≤ 101. Defaults to 21.
    #[serde(
        default = "default_grid",
        deserialize_with = "crate::nullable::grid_points"
    )]
    #[schema(nullable)]
    #[schema(minimum = 2, maximum = 101, default = 21)]
    pub nx: usize,
    /// Grid points along Y, 2 ≤ ny ≤ 101. Defaults to 21.
    #[serde(
        default = "default_grid",
        deserialize_with = "crate::nullable::grid_points"
    )]
    #[schema(nullable)]
    #[schema(minimum = 2, maximum = 101, default = 21)]
    pub ny: usize,
    /// Lower-end position factor F_e of the circles, 0 ≤ F_e ≤ 100. Defaults to 0 (toe).
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(minimum = 0.0, maximum = 100.0)]
    pub lower_end_factor: f64,
    /// When given, F_e is searched too, within [0, this], in the refinement.
    #[serde(default)]
    #[schema(exclusive_minimum = 0.0, maximum = 100.0)]
    pub lower_end_factor_max: Option<f64>,
}

fn default_grid() -> usize {
    21
}
