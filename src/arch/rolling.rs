//! Rolling axles (model §5.3): the request, its stops' live loads (the axles dispersed through
//! the fill onto the extrados, bounded in number), the axles for a position between the stops
//! (`refine_critical`), and the answer's curve.

use serde::{Deserialize, Serialize};
use thrustline_solver::arch::analysis::RollingCurve;
use thrustline_solver::arch::fill::{ExtradosProfile, Fill};
use thrustline_solver::arch::rolling::{Axle, RollingAxles};
use thrustline_solver::arch::LiveLoad;
use utoipa::ToSchema;

use crate::error::ApiError;
use crate::limits::{
    AXLES, COORDINATE, FORCE, MAX_LENGTH, PATCH_LENGTH, POSITIVE_LENGTH, ROLLING_POSITIONS,
};
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
    /// The axles (1 to 20), offsets from the reference point; or give `vehicle`.
    #[serde(default)]
    pub axles: Option<Vec<AxleDto>>,
    /// A named vehicle (EN 1991-2's load models, in kN and m) or `{"axles": [...]}`, instead
    /// of `axles`.
    #[serde(default)]
    #[schema(nullable)]
    pub vehicle: Option<VehicleDto>,
    /// The width of the strip analysed, > 0: every axle load is divided by it (an axle's
    /// load spread across the strip the arch is analysed for). Defaults to 1.
    #[serde(default)]
    #[schema(nullable, examples(2.5))]
    pub width: Option<f64>,
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

/// A vehicle of an assessment code (model §10), in kN and metres, its reference point at the
/// middle of its axles.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, ToSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum VehicleNameDto {
    /// EN 1991-2 load model 1's tandem: two axles 1.2 m apart, 300 kN each, contact length
    /// 0.4 m.
    En1991Lm1Tandem,
    /// EN 1991-2 load model 2: one axle of 400 kN, contact length 0.35 m.
    En1991Lm2,
}

impl VehicleNameDto {
    /// The vehicle's axles: (offset, fy, contact length).
    pub fn axles(self) -> Vec<AxleDto> {
        let axle = |offset: f64, fy: f64, length: f64| AxleDto { offset, fy, length };
        match self {
            Self::En1991Lm1Tandem => vec![axle(-0.6, -300.0, 0.4), axle(0.6, -300.0, 0.4)],
            Self::En1991Lm2 => vec![axle(0.0, -400.0, 0.35)],
        }
    }
}

/// Axles given as a vehicle.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct VehicleAxlesDto {
    /// The axles (1 to 20).
    pub axles: Vec<AxleDto>,
}

/// A vehicle: a code's by name, or axles.
#[derive(Debug, Clone, Serialize, ToSchema)]
#[serde(untagged)]
pub enum VehicleDto {
    /// By name.
    Named(VehicleNameDto),
    /// By its axles.
    Axles(VehicleAxlesDto),
}

impl<'de> Deserialize<'de> for VehicleDto {
    /// A name or an object of axles, each read with its own errors (an unknown name lists
    /// the names).
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        use serde::de::Error as _;
        let value = serde_json::Value::deserialize(deserializer)?;
        match &value {
            serde_json::Value::String(_) => VehicleNameDto::deserialize(value)
                .map(Self::Named)
                .map_err(D::Error::custom),
            serde_json::Value::Object(_) => super::geometry::variant(&value).map(Self::Axles),
            other => Err(D::Error::custom(format!(
                "invalid type: {}, expected a vehicle's name or {{\"axles\": [...]}}",
                crate::extract::json_kind(other)
            ))),
        }
    }
}

impl RollingDto {
    /// The axles rolled and the field they came from: `axles`, or the vehicle's.
    pub fn given_axles(&self) -> Result<(Vec<AxleDto>, &'static str), ApiError> {
        match (&self.vehicle, &self.axles) {
            (Some(_), Some(_)) => Err(ApiError::invalid(
                "rolling.vehicle",
                "give either vehicle or axles, not both",
            )),
            (None, None) => Err(ApiError::invalid(
                "rolling.axles",
                "give the axles (1 to 20), or a vehicle",
            )),
            (None, Some(axles)) => Ok((axles.clone(), "rolling.axles")),
            (Some(VehicleDto::Named(name)), _) => Ok((name.axles(), "rolling.vehicle")),
            (Some(VehicleDto::Axles(v)), _) => Ok((v.axles.clone(), "rolling.vehicle.axles")),
        }
    }
}

/// A validated rolling load: the live loads at each stop.
#[derive(Debug, Clone)]
pub struct Rolling {
    /// The stops.
    pub positions: Vec<f64>,
    /// The live loads at each stop.
    pub loads: Vec<Vec<LiveLoad>>,
    /// The axles on the arch, for a position between the stops; with `refine_critical`.
    pub refine: Option<RollingAxles>,
}

/// The most loads a rolling load's stops may put on the voussoirs together (48 MB).
const MAX_ROLLING_LOADS: usize = 1_000_000;

pub fn rolling_loads(
    profile: &ExtradosProfile,
    carrier: &Fill,
    dto: &RollingDto,
) -> Result<Rolling, ApiError> {
    let (given, field) = dto.given_axles()?;
    count_within(field, given.len(), AXLES)?;
    let width = within("rolling.width", dto.width.unwrap_or(1.0), POSITIVE_LENGTH)?;
    let x_start = within("rolling.x_start", dto.x_start, COORDINATE)?;
    let x_end = number("rolling.x_end", dto.x_end, x_start, false, MAX_LENGTH)?;
    let n = count_within(
        "rolling.positions",
        dto.positions.unwrap_or(101),
        ROLLING_POSITIONS,
    )?;
    let axles = given
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let field = |name: &str| format!("{field}[{i}].{name}");
            Ok(Axle {
                offset: within(&field("offset"), a.offset, COORDINATE)?,
                fy: within(&field("fy"), a.fy, FORCE)? / width,
                length: within(&field("length"), a.length, PATCH_LENGTH)?,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    if axles.iter().all(|a| a.fy == 0.0) {
        return Err(ApiError::invalid(field, "every axle load is zero"));
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
    let axles = RollingAxles {
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
