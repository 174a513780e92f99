//! Fill and road loads (model §5.1), with the rolling axles of [`super::rolling`]: the request
//! types and their one validation into the solver's dead and live loads.

use serde::{Deserialize, Serialize};
use thrustline_solver::arch::fill::{
    fill_dead_loads, passive_forces, road_load_on, Extrados, ExtradosFaces, ExtradosProfile, Fill,
    FillLayer, Passive, PassiveForce, RoadLoad,
};
use thrustline_solver::arch::{Assembly, LiveLoad};
use utoipa::ToSchema;

use super::rolling::{rolling_loads, Rolling, RollingDto};
use crate::error::ApiError;
use crate::limits::{
    COORDINATE, FILL_ANGLE_DEG, FILL_LAYERS, FORCE, LOADS, MOBILISATION, PATCH_LENGTH,
    UNIT_WEIGHT_OR_ZERO,
};
use crate::validation::{count_within, within};

/// Fill over the arch up to a road.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FillDto {
    /// Unit weight of the fill, 0 ≤ γ_f ≤ 1e12 (0: a weightless fill that only spreads road
    /// loads).
    #[schema(examples(18.0))]
    pub unit_weight: f64,
    /// The road level (absolute y), above the crown's extrados. The fill's weight on each
    /// voussoir is the column between its extrados and the road.
    #[schema(examples(11.0))]
    pub surface: f64,
    /// Dispersal angle of road loads from the vertical, 0 ≤ δ ≤ 60 degrees. Defaults to 30.
    #[serde(default)]
    #[schema(examples(30.0))]
    pub dispersal_angle_deg: Option<f64>,
    /// Passive restraint: where the arch sways into the fill, horizontal pressure on the
    /// extrados of up to `mobilisation`·K_p·σ_v. Without it the fill gives no horizontal
    /// pressure (conservative). Solved on the general assembly formulation.
    #[serde(default)]
    #[schema(nullable)]
    pub passive: Option<PassiveDto>,
    /// Denser layers below given levels (masonry backing at the haunches, a denser lower
    /// fill), 1 to 20 of them at distinct levels below the road: below each `below` (down to
    /// the next lower layer's) the column weighs that layer's unit weight, above the highest
    /// the fill's. The weights, the passive pressure's σ_v and the drawing follow them.
    #[serde(default)]
    #[schema(nullable)]
    pub layers: Option<Vec<FillLayerDto>>,
}

/// A layer of the fill below a level (model §10).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FillLayerDto {
    /// The layer's top (absolute y), below the road.
    #[schema(examples(2.0))]
    pub below: f64,
    /// Its unit weight, 0 ≤ γ ≤ 1e12.
    #[schema(examples(22.0))]
    pub unit_weight: f64,
}

/// Passive restraint of the fill (model §5.1).
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PassiveDto {
    /// Friction angle φ of the fill, 0 ≤ φ ≤ 60 degrees: K_p = (1 + sin φ)/(1 − sin φ).
    #[schema(examples(30.0))]
    pub friction_angle_deg: f64,
    /// Fraction of the full passive pressure that may be mobilised, 0 ≤ m ≤ 1.
    #[schema(examples(0.5))]
    pub mobilisation: f64,
}

/// A passive force of the fill on one voussoir: its capacity and what the answer mobilises.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PassiveOutDto {
    /// The voussoir (1-based).
    pub block: usize,
    /// Point of application on the extrados (the centroid of the largest pressure).
    pub x: f64,
    /// Its y.
    pub y: f64,
    /// +1: pushes the voussoir towards +x; −1: towards −x.
    pub direction: f64,
    /// The largest force: ∫ mobilisation·K_p·γ_f·(road − y)·|dy| over the extrados.
    pub capacity: f64,
    /// The force in the answer's admissible state, 0 ≤ force ≤ capacity; null without one.
    #[schema(required = true)]
    pub force: Option<f64>,
}

/// The passive forces of an answer: capacities with the mobilised forces (null without a
/// state).
pub fn passive_out(forces: &[PassiveForce], mobilised: &[f64]) -> Vec<PassiveOutDto> {
    forces
        .iter()
        .enumerate()
        .map(|(i, f)| PassiveOutDto {
            block: f.block + 1,
            x: f.point.0,
            y: f.point.1,
            direction: f.direction,
            capacity: f.capacity,
            force: mobilised.get(i).copied(),
        })
        .collect()
}

/// A load on the road: `fy` spread over a patch `length` wide centred at `x`, dispersed through
/// the fill to the extrados.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RoadLoadDto {
    /// Centre of the patch.
    #[schema(examples(3.2))]
    pub x: f64,
    /// Vertical force (up positive: a wheel is negative).
    #[schema(examples(-100.0))]
    pub fy: f64,
    /// Width of the patch, ≥ 0. Defaults to 0 (a line load on the road).
    #[serde(default, deserialize_with = "crate::nullable::or_default")]
    #[schema(nullable)]
    #[schema(examples(0.3))]
    pub length: f64,
}

/// Everything the fill gives a problem: its dead loads, the road loads as live loads, a
/// rolling load's stops, and the fill's total weight.
#[derive(Debug, Clone, Default)]
pub struct FillLoads {
    /// The fill's weight on the voussoirs.
    pub dead: Vec<LiveLoad>,
    /// The road loads dispersed to the voussoirs.
    pub live: Vec<LiveLoad>,
    /// A rolling load.
    pub rolling: Option<Rolling>,
    /// The fill's weight (0 without fill).
    pub weight: f64,
    /// With `fill.passive`: the horizontal forces the fill can exert.
    pub passive: Option<Vec<PassiveForce>>,
    /// The fill, validated (for drawings).
    pub fill: Option<Fill>,
    /// The road loads, validated (for drawings).
    pub road: Vec<RoadLoad>,
}

/// A generated bridge's outer faces: (block, polyline along its face).
pub type BridgeFaces = Vec<(usize, Vec<(f64, f64)>)>;

/// What a fill lies on: a chain's extrados, a generated bridge's outer faces (`bridge_faces`);
/// a general assembly has no single extrados. Sampled only when `needs` names the field (fill,
/// rolling or road loads) that needs it.
pub fn fill_faces(
    assembly: &Assembly,
    bridge_faces: Option<BridgeFaces>,
    shape: Extrados,
    needs: Option<&'static str>,
) -> Result<Option<ExtradosFaces>, ApiError> {
    Ok(match (needs, bridge_faces) {
        (None, _) => None,
        (Some(_), Some(faces)) => Some(ExtradosFaces::of_faces(faces)),
        (Some(_), None) if assembly.is_chain() => Some(ExtradosFaces::of_chain(assembly, shape)),
        (Some(field), None) => {
            return Err(ApiError::invalid(
                field,
                "fill, road loads and rolling loads are for circular arches (any rings and \
                 spans) and block chains: a general assembly has no single extrados (put loads \
                 on its blocks with loads)",
            ))
        }
    })
}

/// The fill's and the road's loads on `assembly`, lying on `faces`. Nothing to do for a
/// request without fill, road loads or rolling.
pub fn fill_loads(
    assembly: &Assembly,
    faces: &ExtradosFaces,
    fill: Option<&FillDto>,
    road_loads: &[RoadLoadDto],
    rolling: Option<&RollingDto>,
) -> Result<FillLoads, ApiError> {
    if fill.is_none() && road_loads.is_empty() && rolling.is_none() {
        return Ok(FillLoads::default());
    }
    let top = faces.top();
    let dto_passive = fill.and_then(|f| f.passive.as_ref());
    let fill = fill.map(|dto| fill_from(dto, top)).transpose()?;
    if fill.is_none() && !road_loads.is_empty() {
        return Err(ApiError::invalid(
            "road_loads",
            "need a fill to stand on (give fill, or put the loads on blocks with loads)",
        ));
    }
    count_within("road_loads", road_loads.len(), LOADS)?;
    // Without fill, axles stand on the extrados: a weightless "fill" at the crown with no
    // dispersal puts each on the voussoir under it.
    let carrier = fill.clone().unwrap_or(Fill {
        unit_weight: 0.0,
        road: top,
        dispersal_angle_deg: 0.0,
        layers: Vec::new(),
    });
    // The extrados sampled once for the road loads and the rolling stops.
    let profile =
        (!road_loads.is_empty() || rolling.is_some()).then(|| ExtradosProfile::new(faces));
    let (live, road) = road_loads_on(road_loads, profile.as_ref(), &carrier)?;
    let rolling = rolling
        .zip(profile.as_ref())
        .map(|(r, profile)| rolling_loads(profile, &carrier, r))
        .transpose()?;
    let dead = fill
        .as_ref()
        .map_or(Vec::new(), |f| fill_dead_loads(faces, f));
    let passive = passive_from(assembly, faces, fill.as_ref(), dto_passive)?;
    Ok(FillLoads {
        weight: dead.iter().map(|l| -l.fy).sum(),
        dead,
        live,
        rolling,
        passive,
        fill,
        road,
    })
}

/// The road loads validated, and the live loads they give through `carrier` onto `profile`.
fn road_loads_on(
    road_loads: &[RoadLoadDto],
    profile: Option<&ExtradosProfile>,
    carrier: &Fill,
) -> Result<(Vec<LiveLoad>, Vec<RoadLoad>), ApiError> {
    let mut live = Vec::new();
    let mut road = Vec::with_capacity(road_loads.len());
    for (i, load) in road_loads.iter().enumerate() {
        let field = |name: &str| format!("road_loads[{i}].{name}");
        let load = RoadLoad {
            x: within(&field("x"), load.x, COORDINATE)?,
            fy: within(&field("fy"), load.fy, FORCE)?,
            length: within(&field("length"), load.length, PATCH_LENGTH)?,
        };
        // Road loads made the profile.
        let Some(profile) = profile else { break };
        let dispersed = road_load_on(profile, carrier, load);
        if dispersed.is_empty() {
            let span = profile.x_range();
            return Err(ApiError::invalid(
                field("x"),
                format!(
                    "{} puts the load beyond the arch: spread down through the fill it reaches \
                     the abutment, not the extrados (the arch spans x = {:.6} … {:.6})",
                    load.x, span.0, span.1
                ),
            ));
        }
        live.extend(dispersed);
        road.push(load);
    }
    Ok((live, road))
}

/// With a fill and `fill.passive`: the horizontal forces the fill can exert, validated.
fn passive_from(
    assembly: &Assembly,
    faces: &ExtradosFaces,
    fill: Option<&Fill>,
    dto_passive: Option<&PassiveDto>,
) -> Result<Option<Vec<PassiveForce>>, ApiError> {
    Ok(match (fill, dto_passive) {
        (Some(fill), Some(p)) => {
            let passive = Passive {
                friction_angle_deg: within(
                    "fill.passive.friction_angle_deg",
                    p.friction_angle_deg,
                    FILL_ANGLE_DEG,
                )?,
                mobilisation: within("fill.passive.mobilisation", p.mobilisation, MOBILISATION)?,
            };
            Some(passive_forces(assembly, faces, fill, &passive))
        }
        _ => None,
    })
}

/// The fill of a request, its road above the crown's extrados at `top`.
fn fill_from(dto: &FillDto, top: f64) -> Result<Fill, ApiError> {
    let unit_weight = within("fill.unit_weight", dto.unit_weight, UNIT_WEIGHT_OR_ZERO)?;
    let surface = within("fill.surface", dto.surface, COORDINATE)?;
    if surface <= top {
        return Err(ApiError::invalid(
            "fill.surface",
            format!(
                "{surface} is out of range: the road must lie above the crown's extrados \
                 (y = {top})"
            ),
        ));
    }
    let angle = dto.dispersal_angle_deg.unwrap_or(30.0);
    Ok(Fill {
        unit_weight,
        road: surface,
        dispersal_angle_deg: within("fill.dispersal_angle_deg", angle, FILL_ANGLE_DEG)?,
        layers: fill_layers(dto.layers.as_deref(), surface)?,
    })
}

/// The fill's layers, lowest first: each below the road, at distinct levels.
fn fill_layers(given: Option<&[FillLayerDto]>, road: f64) -> Result<Vec<FillLayer>, ApiError> {
    let Some(given) = given else {
        return Ok(Vec::new());
    };
    count_within("fill.layers", given.len(), FILL_LAYERS)?;
    let mut layers = given
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let field = |name: &str| format!("fill.layers[{i}].{name}");
            let below = within(&field("below"), l.below, COORDINATE)?;
            if below >= road {
                return Err(ApiError::invalid(
                    field("below"),
                    format!(
                        "{below} is out of range: a layer lies below the road (fill.surface = \
                         {road})"
                    ),
                ));
            }
            Ok(FillLayer {
                below,
                unit_weight: within(&field("unit_weight"), l.unit_weight, UNIT_WEIGHT_OR_ZERO)?,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    layers.sort_by(|a, b| a.below.total_cmp(&b.below));
    if let Some(w) = layers.windows(2).find(|w| w[0].below == w[1].below) {
        let i = given
            .iter()
            .rposition(|l| l.below == w[0].below)
            .unwrap_or(0);
        return Err(ApiError::invalid(
            format!("fill.layers[{i}].below"),
            format!(
                "{} is given twice: each layer has a level of its own",
                w[0].below
            ),
        ));
    }
    Ok(layers)
}
