//! The one validation of an arch request: JSON values → the solver's typed inputs. Every range
//! the API states is checked here (naming the field); what the solver's own constructors check
//! (thickness below twice the radius, shared faces of a chain, loads on existing blocks) comes
//! back from them as a typed parameter that [`crate::fields`] names.

use std::num::NonZeroUsize;

use thrustline_solver::arch::analysis::ArchPlan;
use thrustline_solver::arch::fill::{Extrados, ExtradosFaces, Fill, RoadLoad};
use thrustline_solver::arch::{
    ArchProblem, Assembly, CircularArch, Crushing, Formulation, LimitSettings, LiveLoad,
    VoussoirShape,
};

use super::assembly::Generated;
use super::fill::{fill_faces, fill_loads, FillDto, FillLoads, RoadLoadDto};
use super::geometry::{
    AssemblyGeometryDto, BlocksGeometryDto, CircularGeometryDto, GeometryDto, ProfileGeometryDto,
    VoussoirDto,
};
use super::material::material;
use super::plan::{plan, Problem};
use super::request::{
    ArchDetailDto, DeadLoadRequest, FrictionDto, LimitFields, LiveLoadRequest, LoadDto,
};
use super::rolling::RollingDto;
use crate::error::ApiError;
use crate::limits::{
    BASE_ANGLE_DEG, BLOCKS, COORDINATE, CRUSHING_PLANES, FORCE, LENGTH, LOADS, POSITIVE_STRESS,
    SOLVER_TOLERANCE, THICKNESS,
};
use crate::validation::{count, count_within, finite, within};

/// A validated dead- or live-load request: the structure the solver analyses and what the
/// answer needs of the request beside the solver's outcome. Its plan is the other half of what
/// validation gives ([`DeadLoadRequest::validate`]).
#[derive(Debug, Clone)]
pub struct ArchInput {
    /// The structure, its loads and limits.
    pub problem: ArchProblem,
    /// Whether the voussoirs are annular sectors (drawn with arcs).
    pub is_curved: bool,
    /// The fill's weight, when there is a fill.
    pub fill_weight: Option<f64>,
    /// A rolling load's stops (their loads are the plan's).
    pub rolling_positions: Option<Vec<f64>>,
    /// With `fill.passive`: whether passive restraint was asked for (its forces are the
    /// problem's).
    pub has_passive: bool,
    /// The fill, the faces it lies on and the road loads, for drawings.
    pub fill: Option<(Fill, ExtradosFaces, Vec<RoadLoad>)>,
    /// The details the answer carries (`include`; all when not given).
    pub include: Vec<ArchDetailDto>,
    /// A partial-factor check: the problem is in its design values.
    pub design: Option<super::design::ArchFactors>,
}

/// What a request adds to the blocks' own loads: fill, road loads, rolling axles.
#[derive(Debug, Clone, Copy, Default)]
struct Extras<'a> {
    fill: Option<&'a FillDto>,
    road_loads: &'a [RoadLoadDto],
    rolling: Option<&'a RollingDto>,
}

impl Extras<'_> {
    /// The field that needs an extrados to lie on, if any.
    fn needing_faces(&self) -> Option<&'static str> {
        if self.fill.is_some() {
            Some("fill")
        } else if self.rolling.is_some() {
            Some("rolling")
        } else {
            (!self.road_loads.is_empty()).then_some("road_loads")
        }
    }
}

impl DeadLoadRequest {
    /// Validates the request into the structure and the plan of its analysis.
    pub fn validate(&self) -> Result<(ArchInput, ArchPlan), ApiError> {
        let extras = Extras {
            fill: self.fill.as_ref(),
            ..Extras::default()
        };
        input(Problem::DeadLoad, self.limit_fields(), &[], extras)
    }
}

impl LiveLoadRequest {
    /// Validates the request into the structure and the plan of its analysis.
    pub fn validate(&self) -> Result<(ArchInput, ArchPlan), ApiError> {
        if let Some(design) = &self.design {
            // The design values, once; the input remembers the check for the answer.
            let factors = super::design::factors(design)?;
            let (mut input, plan) = super::design::in_design_values(self, &factors).validate()?;
            input.design = Some(factors);
            return Ok((input, plan));
        }
        count_within("loads", self.loads.len(), LOADS)?;
        if self.friction == FrictionDto::NonAssociative && self.rolling.is_some() {
            return Err(ApiError::invalid(
                "friction",
                "non_associative is not available with rolling (each stop would iterate): roll \
                 with the associative rule, then check the critical stop with loads",
            ));
        }
        if self.loads.is_empty() && self.road_loads.is_empty() && self.rolling.is_none() {
            return Err(ApiError::invalid(
                "loads",
                "give the live loads: loads on blocks, road_loads (with fill) or rolling",
            ));
        }
        if self.rolling.is_some() && !(self.loads.is_empty() && self.road_loads.is_empty()) {
            return Err(ApiError::invalid(
                "rolling",
                "rolls alone: give either rolling, or loads and road_loads",
            ));
        }
        let extras = Extras {
            fill: self.fill.as_ref(),
            road_loads: &self.road_loads,
            rolling: self.rolling.as_ref(),
        };
        input(Problem::LiveLoad, self.limit_fields(), &self.loads, extras)
    }
}

/// The structure of a request and the plan of its analysis: the programme (a rolling load's
/// stops), the treatment of friction, the settings, the critical position's refinement and the
/// bonded ring to compare with.
fn input(
    which: Problem,
    fields: LimitFields,
    loads: &[LoadDto],
    extras: Extras,
) -> Result<(ArchInput, ArchPlan), ApiError> {
    let material = material(fields.material)?;
    let (assembly, bridge_faces) = assembly(fields.geometry)?;
    let is_curved = matches!(fields.geometry, GeometryDto::Circular(c) if c.is_curved_single());
    let shape = if is_curved {
        Extrados::Arc { centre: (0.0, 0.0) }
    } else {
        Extrados::Straight
    };
    let faces = fill_faces(&assembly, bridge_faces, shape, extras.needing_faces())?;
    let filled = match &faces {
        Some(faces) => fill_loads(
            &assembly,
            faces,
            extras.fill,
            extras.road_loads,
            extras.rolling,
        )?,
        None => FillLoads::default(),
    };
    let live_loads = all_live_loads(&assembly, loads, &filled)?;
    let problem = ArchProblem::new(
        assembly,
        material.unit_weight,
        material.limits,
        material.friction,
        live_loads,
    )?
    .with_dead_loads(filled.dead.clone())?
    .with_passive(filled.passive.clone().unwrap_or_default())?;
    let problem = with_rings_and_crushing(problem, &fields)?;
    let settings = settings(&fields, &problem, filled.passive.is_some())?;
    let bonded = bonded(&fields, &problem, loads, extras);
    let (plan, rolling_positions) = plan(which, fields.friction, settings, filled.rolling, bonded);
    let input = ArchInput {
        design: None,
        problem,
        is_curved,
        fill_weight: extras.fill.map(|_| filled.weight),
        rolling_positions,
        has_passive: filled.passive.is_some(),
        fill: filled
            .fill
            .zip(faces)
            .map(|(f, faces)| (f, faces, filled.road)),
        include: include(fields.include),
    };
    Ok((input, plan))
}

/// The live loads the problem starts with: those on blocks and the road loads dispersed onto
/// the extrados; with a rolling load, its first loaded stop's (the sweep replaces them).
fn all_live_loads(
    assembly: &Assembly,
    loads: &[LoadDto],
    filled: &FillLoads,
) -> Result<Vec<LiveLoad>, ApiError> {
    let mut live_loads = live_loads(assembly, loads)?;
    let zero = |l: &LiveLoad| l.fx == 0.0 && l.fy == 0.0 && l.moment == 0.0;
    if live_loads.iter().all(zero) && !filled.live.is_empty() && filled.live.iter().all(zero) {
        return Err(ApiError::invalid(
            "road_loads",
            "every road load is zero: give a non-zero fy",
        ));
    }
    live_loads.extend(filled.live.iter().copied());
    if let Some(rolling) = &filled.rolling {
        if rolling.loads.iter().all(Vec::is_empty) {
            return Err(ApiError::invalid(
                "rolling.x_start",
                "the axles never stand on the arch between x_start and x_end",
            ));
        }
        live_loads = rolling
            .loads
            .iter()
            .find(|l| !l.is_empty())
            .cloned()
            .unwrap_or_default();
    }
    Ok(live_loads)
}

/// The programmes' settings: the formulation (the general assembly where passive forces or an
/// assembly that is not a chain need it), the tolerance, the friction relaxation.
fn settings(
    fields: &LimitFields,
    problem: &ArchProblem,
    has_passive: bool,
) -> Result<LimitSettings, ApiError> {
    // Passive forces are variables of their own: the general assembly carries them.
    // So do assemblies that are not chains: the answer names what was used.
    let formulation = if has_passive || !problem.assembly().is_chain() {
        Formulation::Assembly
    } else {
        fields.formulation.solver()
    };
    Ok(LimitSettings {
        formulation,
        tolerance: within(
            "solver_tolerance",
            fields.solver_tolerance,
            SOLVER_TOLERANCE,
        )?,
        relaxation: fields.friction_relaxation.solver(),
        ..LimitSettings::default()
    })
}

/// Where `problem`'s rings lock (staggered, no ring friction) on one span without a rolling
/// load: the same request on one ring of the whole thickness (None where it does not validate,
/// such as a load on a block of an outer ring).
fn bonded(
    fields: &LimitFields,
    problem: &ArchProblem,
    loads: &[LoadDto],
    extras: Extras,
) -> Option<ArchProblem> {
    let (rings, spans) = match fields.geometry {
        GeometryDto::Circular(c) => (c.rings, c.spans),
        GeometryDto::Profile(p) => (p.rings, p.spans),
        _ => return None,
    };
    let locked = rings > 1 && spans == 1 && problem.has_locked_rings();
    if !locked || extras.rolling.is_some() {
        return None;
    }
    let single = match fields.geometry {
        GeometryDto::Circular(circular) => GeometryDto::Circular(CircularGeometryDto {
            rings: 1,
            ..circular.clone()
        }),
        GeometryDto::Profile(profile) => GeometryDto::Profile(ProfileGeometryDto {
            rings: 1,
            ..profile.clone()
        }),
        _ => return None,
    };
    let fields = LimitFields {
        geometry: &single,
        ..*fields
    };
    input(Problem::LiveLoad, fields, loads, extras)
        .ok()
        .map(|(i, _)| i.problem)
}

/// The ring interfaces' limits and friction (arches of more than one ring) and crushing.
fn with_rings_and_crushing(
    problem: ArchProblem,
    fields: &LimitFields,
) -> Result<ArchProblem, ApiError> {
    let problem = super::interfaces::with_ring_and_own_interfaces(problem, fields)?;
    Ok(match fields.compressive_strength {
        None if fields.crushing_planes.is_some() => {
            return Err(ApiError::invalid(
                "crushing_planes",
                "is for compressive_strength: give that too, or leave crushing_planes out",
            ))
        }
        None => problem,
        Some(strength) => problem.with_crushing(Crushing {
            strength: within("compressive_strength", strength, POSITIVE_STRESS)?,
            planes: count_within(
                "crushing_planes",
                fields.crushing_planes.unwrap_or(4),
                CRUSHING_PLANES,
            )?,
            cuts: Vec::new(),
        })?,
    })
}

/// `include`: the details named (a repeated one counts once); all of them when not given.
fn include(given: Option<&[ArchDetailDto]>) -> Vec<ArchDetailDto> {
    ArchDetailDto::ALL
        .into_iter()
        .filter(|d| given.is_none_or(|g| g.contains(d)))
        .collect()
}

/// Validates a circular arch of the given thickness (against the radius it is
/// `CircularArch::new`'s check); rings and spans are the caller's.
pub fn circular_arch(
    fields: &CircularGeometryDto,
    thickness: f64,
) -> Result<CircularArch, ApiError> {
    let radius = within("geometry.radius", fields.radius, LENGTH)?;
    let n = count_within("geometry.voussoirs", fields.voussoirs, BLOCKS)?;
    let angle = |field: &str, value: f64| within(field, value, BASE_ANGLE_DEG);
    let left = angle("geometry.left_base_angle_deg", fields.left_base_angle_deg)?;
    let right = angle("geometry.right_base_angle_deg", fields.right_base_angle_deg)?;
    let shape = match fields.voussoir {
        VoussoirDto::Curved => VoussoirShape::Curved,
        VoussoirDto::Quadrilateral => VoussoirShape::Quadrilateral,
    };
    let n = NonZeroUsize::new(n)
        .ok_or_else(|| ApiError::invalid("geometry.voussoirs", "must be at least 1"))?;
    Ok(CircularArch::new(radius, thickness, n, left, right, shape)?)
}

/// A generated bridge's fill faces: (block, points along the face).
type Faces = Vec<(usize, Vec<(f64, f64)>)>;

/// The assembly of a geometry, and for a generated bridge the faces a fill lies on.
fn assembly(geometry: &GeometryDto) -> Result<(Assembly, Option<Faces>), ApiError> {
    match geometry {
        GeometryDto::Circular(circular) => {
            let thickness = circular.thickness.ok_or_else(|| {
                ApiError::invalid(
                    "geometry.thickness",
                    "is required here (0 < D < 2R); only the minimum-thickness route finds it",
                )
            })?;
            let arch = circular_arch(circular, thickness)?;
            let generated = Generated {
                rings: circular.rings,
                ring_joints: circular.ring_joints,
                spans: circular.spans,
                pier_width: circular.pier_width,
                pier_height: circular.pier_height,
            };
            if generated.is_plain() {
                Ok((arch.assembly(), None))
            } else {
                let bridge = super::assembly::generated(&arch, generated)?;
                Ok((bridge.assembly, Some(bridge.extrados)))
            }
        }
        GeometryDto::Blocks(BlocksGeometryDto { blocks, .. }) => {
            count_within("geometry.blocks", blocks.len(), BLOCKS)?;
            for (b, block) in blocks.iter().enumerate() {
                for (c, [x, y]) in block.corners.iter().enumerate() {
                    let field = format!("geometry.blocks[{b}].corners[{c}]");
                    within(&field, *x, COORDINATE)?;
                    within(&field, *y, COORDINATE)?;
                }
            }
            let corners: Vec<[(f64, f64); 4]> = blocks
                .iter()
                .map(|b| b.corners.map(|[x, y]| (x, y)))
                .collect();
            Ok((Assembly::from_quadrilaterals(&corners)?, None))
        }
        GeometryDto::Assembly(AssemblyGeometryDto {
            blocks, supports, ..
        }) => Ok((super::assembly::assembly(blocks, supports)?, None)),
        GeometryDto::Profile(profile) => {
            let thickness = profile.thickness.ok_or_else(|| {
                ApiError::invalid(
                    "geometry.thickness",
                    "is required here (0 < thickness < span); only the minimum-thickness route \
                     finds it",
                )
            })?;
            let thickness = within("geometry.thickness", thickness, THICKNESS)?;
            super::profile::profile_assembly(profile, thickness)
        }
    }
}

/// The live loads, 1-based blocks in, 0-based out; the point defaults to the block centroid.
fn live_loads(assembly: &Assembly, loads: &[LoadDto]) -> Result<Vec<LiveLoad>, ApiError> {
    let n = assembly.blocks.len();
    let live_loads = loads
        .iter()
        .enumerate()
        .map(|(i, load)| {
            let field = |name: &str| format!("loads[{i}].{name}");
            let block = count(&field("block"), load.block, 1, n)? - 1;
            let centroid = assembly.blocks[block].centroid;
            let coordinate = |name: &str, value: Option<f64>, default: f64| {
                value.map_or(Ok(default), |v| finite(&field(name), v))
            };
            let force = |name: &str, value: f64| within(&field(name), value, FORCE);
            Ok(LiveLoad {
                block,
                point: (
                    coordinate("x", load.x, centroid.0)?,
                    coordinate("y", load.y, centroid.1)?,
                ),
                fx: force("fx", load.fx)?,
                fy: force("fy", load.fy)?,
                moment: force("moment", load.moment)?,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    if !loads.is_empty()
        && live_loads
            .iter()
            .all(|l| l.fx == 0.0 && l.fy == 0.0 && l.moment == 0.0)
    {
        return Err(ApiError::invalid(
            "loads",
            "every load is zero: give at least one non-zero fx, fy or moment",
        ));
    }
    Ok(live_loads)
}
