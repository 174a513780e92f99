//! `"search"`: how the critical circle (and a non-circular surface) is looked for.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::super::options::CompositeDto;

/// A search for the critical circle: a grid over centres, refined by Nelder–Mead. On the simple
/// slope, centres are measured from the lower end and bounds left out are chosen around the
/// perpendicular bisector of the face. On a section, bounds are absolute and hard (the answer's
/// centre lies inside them), several radii are tried at each centre (`radius_min`…`radius_max`
/// in `nr` steps, or `tangent_elevations`, or chosen from the section), and bounds left out
/// cover toe, face and deep circles (moved when the minimum lies on their edge).
#[derive(Debug, Clone, Default, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SearchDto {
    /// Smallest centre x (simple slope: from the lower end; section: absolute). Automatic
    /// when missing.
    pub x_min: Option<f64>,
    /// Largest centre x. Automatic when missing.
    pub x_max: Option<f64>,
    /// Smallest centre y (simple slope: above the lower end; section: absolute). Automatic
    /// when missing.
    pub y_min: Option<f64>,
    /// Largest centre y. Automatic when missing.
    pub y_max: Option<f64>,
    /// Section only: the smallest radius tried at each centre (with `radius_max`).
    #[serde(default)]
    pub radius_min: Option<f64>,
    /// Section only: the largest radius tried at each centre.
    #[serde(default)]
    pub radius_max: Option<f64>,
    /// Section only: radii per centre, 1 ≤ nr ≤ 101. Defaults to 10.
    #[serde(default)]
    pub nr: Option<usize>,
    /// Section only: `noncircular` continues from the critical circle with a polyline whose
    /// vertices move to lower F (`vertices` of them; kinematically admissible, within the time
    /// limit). Defaults to `circular`.
    #[serde(default)]
    pub shape: Option<SearchShapeDto>,
    /// Section only, with `shape: noncircular`: vertices of the polyline, 4 ≤ n ≤ 40. Defaults
    /// to 12.
    #[serde(default)]
    pub vertices: Option<usize>,
    /// Section only, with `shape: noncircular`: the most the polyline search may spend after
    /// the critical circle is found, in milliseconds (0 < t ≤ 600000; the request's time limit
    /// still applies). When it ends the search, the answer is its best surface so far and a
    /// warning says so. Defaults to the time limit.
    #[serde(default)]
    pub time_budget_ms: Option<f64>,
    /// Section only, with `shape: noncircular`: the most trial surfaces the polyline search may
    /// evaluate, 1 ≤ n ≤ 1000000: a budget that gives the same answer on any machine (the time
    /// limits still apply). `search.budget_exhausted` says when a budget ended the search.
    #[serde(default)]
    pub max_evaluations: Option<usize>,
    /// Section only: circles tangent to these elevations (R = y_c − y) instead of a radius
    /// range; at most 101.
    #[serde(default)]
    pub tangent_elevations: Option<Vec<f64>>,
    /// Grid points along X, 2 ≤ nx ≤ 101. Defaults to 21.
    #[serde(
        default = "default_grid",
        deserialize_with = "crate::nullable::grid_points"
    )]
    #[schema(nullable)]
    pub nx: usize,
    /// Grid points along Y, 2 ≤ ny ≤ 101. Defaults to 21.
    #[serde(
        default = "default_grid",
        deserialize_with = "crate::nullable::grid_points"
    )]
    #[schema(nullable)]
    pub ny: usize,
    /// Simple slope only: lower-end position factor F_e of the circles, 0 ≤ F_e ≤ 100.
    /// Defaults to 0 (toe).
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub lower_end_factor: f64,
    /// Simple slope only: when given, F_e is searched too, within [0, this], in the
    /// refinement.
    #[serde(default)]
    pub lower_end_factor_max: Option<f64>,
    /// Surfaces whose greatest depth below the ground is smaller are not candidates (a sliver
    /// along a c' = 0 face is not the mechanism checked). 0 ≤ d ≤ 1e9; defaults to 2 % of the
    /// height (the ground's range of y on a section, H on the simple slope).
    #[serde(default)]
    pub min_depth: Option<f64>,
    /// With bedrock: `follow_bedrock` (a circle that would cross it follows it, a composite
    /// surface; the default) or `circles_only` (such a circle is not a candidate).
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub composite: CompositeDto,
    /// With `methods`: each of them is searched for its own critical circle too (the same
    /// centres, radii and candidates, the circles ranked by that method's F; circles only),
    /// answered as `methods.<name>.critical`. The headline stays Spencer's. Defaults to false.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub per_method: bool,
    /// Section only: whether surfaces may enter or leave the ground beyond the section's
    /// x-range, the ground taken as level there (the answer then warns `beyond_ground`).
    /// Defaults to false: the search stays within the section as stated.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub beyond_ground: bool,
}

fn default_grid() -> usize {
    21
}

/// The shape of the surfaces a search looks among.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum SearchShapeDto {
    /// Circles.
    #[default]
    Circular,
    /// The critical circle, then a polyline whose vertices move to lower F.
    Noncircular,
}
