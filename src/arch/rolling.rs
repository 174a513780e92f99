//! Rolling axles (model §5.3): the request, its stops' live loads (the axles dispersed through
//! the fill onto the extrados, bounded in number), the axles for a position between the stops
//! (`refine_critical`), and the answer's curve.

use serde::{Deserialize, Serialize};
use thrustline_solver::arch::analysis::RollingCurve;
use thrustline_solver::arch::fill::{road_load_on, ExtradosProfile, Fill, RoadLoad};
use thrustline_solver::arch::LiveLoad;
use utoipa::ToSchema;

use crate::error::ApiError;
use crate::limits::{AXLES, COORDINATE, FORCE, MAX_LENGTH, PATCH_LENGTH, ROLLING_POSITIONS};
use crate::validation::{count_within, number, within};

/// One axle of a rolling load.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct AxleDto {
    /// Position relative to the axle set's reference point.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub offset: f64,
    /// Vertical force (up positive).
    #[schema(examples(-100.0))]
    pub fy: f64,
    /// Width of the wheel's patch on the road, ≥ 0. Defaults to 0.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub length: f64,
}

/// A set of axles rolled across the arch: the live-load factor at each stop, the critical stop.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RollingDto {
    /// The axles (1 to 20).
    pub axles: Vec<AxleDto>,
    /// First position of the reference point.
    pub x_start: f64,
    /// Last position (≥ x_start).
    pub x_end: f64,
    /// Stops, evenly from x_start to x_end, 1 ≤ positions ≤ 1001. Defaults to 101.
    #[serde(default)]
    pub positions: Option<usize>,
    /// Narrow the critical position between the critical stop's neighbours (golden section)
    /// to 1e-3 of the stop spacing, and answer there. Defaults to false.
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    pub refine_critical: bool,
}

/// A validated rolling load: the live loads at each stop.
#[derive(Debug, Clone)]
pub struct Rolling {
    /// The stops.
    pub positions: Vec<f64>,
    /// The live loads at each stop.
    pub loads: Vec<Vec<LiveLoad>>,
    /// The axles on the arch, for a position between the stops; with `refine_critical`.
    pub refine: Option<Axles>,
}

/// The axles (offset, load, patch length) dispersed through the fill onto the extrados.
#[derive(Debug, Clone)]
pub struct Axles {
    profile: ExtradosProfile,
    carrier: Fill,
    axles: Vec<(f64, f64, f64)>,
}

impl Axles {
    /// The live loads with the reference point at x.
    pub fn loads_at(&self, x: f64) -> Vec<LiveLoad> {
        self.axles
            .iter()
            .flat_map(|&(offset, fy, length)| {
                let load = RoadLoad {
                    x: x + offset,
                    fy,
                    length,
                };
                road_load_on(&self.profile, &self.carrier, load)
            })
            .collect()
    }
}

/// The most loads a rolling load's stops may put on the voussoirs together (48 MB).
const MAX_ROLLING_LOADS: usize = 1_000_000;

pub fn rolling_loads(
    profile: &ExtradosProfile,
    carrier: &Fill,
    dto: &RollingDto,
) -> Result<Rolling, ApiError> {
    count_within("rolling.axles", dto.axles.len(), AXLES)?;
    let x_start = within("rolling.x_start", dto.x_start, COORDINATE)?;
    let x_end = number("rolling.x_end", dto.x_end, x_start, false, MAX_LENGTH)?;
    let n = count_within(
        "rolling.positions",
        dto.positions.unwrap_or(101),
        ROLLING_POSITIONS,
    )?;
    let axles = dto
        .axles
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let field = |name: &str| format!("rolling.axles[{i}].{name}");
            Ok((
                within(&field("offset"), a.offset, COORDINATE)?,
                within(&field("fy"), a.fy, FORCE)?,
                within(&field("length"), a.length, PATCH_LENGTH)?,
            ))
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    if axles.iter().all(|a| a.1 == 0.0) {
        return Err(ApiError::invalid(
            "rolling.axles",
            "every axle load is zero",
        ));
    }
    let positions: Vec<f64> = (0..n)
        .map(|i| {
            if n == 1 {
                x_start
            } else {
                x_start + (x_end - x_start) * i as f64 / (n - 1) as f64
            }
        })
        .collect();
    // Every stop's loads are held for the sweep: bounded as they are made (a 400-byte request
    // of 1001 stops of 20 axles spread over 10,000 voussoirs made 9 GB of them).
    let axles = Axles {
        profile: profile.clone(),
        carrier: carrier.clone(),
        axles,
    };
    let mut loads = Vec::with_capacity(n);
    let mut total = 0usize;
    for &x in &positions {
        let stop = axles.loads_at(x);
        total += stop.len();
        if total > MAX_ROLLING_LOADS {
            return Err(ApiError::invalid(
                "rolling.positions",
                format!(
                    "the stops put more than {MAX_ROLLING_LOADS} loads on the voussoirs (each \
                     axle spread over the voussoirs under it, at every stop; {total} by stop {} \
                     of {n}): use fewer positions, voussoirs or axles, or less dispersal",
                    loads.len() + 1
                ),
            ));
        }
        loads.push(stop);
    }
    let refine = dto.refine_critical.then_some(axles);
    Ok(Rolling {
        positions,
        loads,
        refine,
    })
}

/// A rolling load's answer: λ at each stop and the critical stop.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct RollingOutDto {
    /// The stops of the reference point.
    pub positions: Vec<f64>,
    /// λ at each stop; null where no axle stands on the arch or no finite λ causes collapse.
    pub load_factor: Vec<Option<f64>>,
    /// The critical stop (least λ); null when no stop has a λ.
    #[schema(required = true)]
    pub critical_position: Option<f64>,
    /// λ there.
    #[schema(required = true)]
    pub critical_load_factor: Option<f64>,
    /// How far the true critical position may lie from `critical_position`: half the spacing
    /// of the stops (the least λ lies between the critical stop's neighbours), or with
    /// `refine_critical` half the final bracket of the golden-section search (at most 1e-3 of
    /// the spacing); null when there is no critical stop, 0 with a single stop.
    #[schema(required = true)]
    pub critical_position_error: Option<f64>,
    /// With `refine_critical`: the live-load analyses the search ran (null without, or when
    /// the time limit ended it and the stop's answer stands).
    #[schema(required = true)]
    pub refine_evaluations: Option<usize>,
    /// Wall time per stop in milliseconds, over the whole sweep. Only the live loads move, so
    /// the first stop's dead-load check serves every later stop (which then solve one
    /// programme, not two; with crushing each stop checks again).
    pub time_per_position_ms: f64,
    /// Wall time of the first loaded stop in milliseconds: a cold start, dead-load check
    /// included, to compare with `time_per_position_ms`.
    pub first_position_ms: f64,
}

impl RollingOutDto {
    /// The curve of a sweep over the stops at `positions`.
    pub fn new(curve: &RollingCurve, positions: Vec<f64>) -> Self {
        let spacing = match positions.as_slice() {
            [first, .., last] => (last - first).abs() / (positions.len() - 1) as f64,
            _ => 0.0,
        };
        let refined = curve.refined;
        Self {
            critical_position_error: match refined {
                Some(r) => Some(r.error),
                None => curve.critical.map(|_| 0.5 * spacing),
            },
            critical_position: match refined {
                Some(r) => Some(r.position),
                None => curve.critical.map(|(i, _)| positions[i]),
            },
            critical_load_factor: match refined {
                Some(r) => Some(r.load_factor),
                None => curve.critical.map(|(_, f)| f),
            },
            refine_evaluations: refined.map(|r| r.evaluations),
            positions,
            load_factor: curve.load_factors.clone(),
            time_per_position_ms: curve.time_per_stop_ms,
            first_position_ms: curve.first_stop_ms,
        }
    }
}
