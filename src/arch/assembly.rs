//! Assemblies in requests (model §5.4): polygons of blocks and supports, the ring and span
//! generators of circular arches, and their one validation into the solver's [`Assembly`].

use serde::{Deserialize, Serialize};
use thrustline_solver::arch::generators::{bridge, Bridge, Piers, RingJoints};
use thrustline_solver::arch::{ArchError, Assembly, CircularArch};
use utoipa::ToSchema;

use crate::error::ApiError;
use crate::limits::{BLOCKS, COORDINATE, POLYGON_CORNERS, RINGS, SPANS, SUPPORTS};
use crate::validation::{count_within, within};

/// Blocks a generated assembly may have (rings × spans × voussoirs, and piers).
const MAX_GENERATED_BLOCKS: usize = 20_000;

/// How the joints of neighbouring rings lie.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum RingJointsDto {
    /// Every other ring shifted by half a voussoir (brick bonding; its end blocks are half
    /// voussoirs).
    #[default]
    Staggered,
    /// All joints on the same radial lines.
    Aligned,
}

/// A polygon: a block or a support of an assembly.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(examples(json!({"polygon": [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]})))]
pub struct PolygonDto {
    /// Corners [x, y], 3 to 256, in either direction (clockwise ones are turned round);
    /// convex or not, not self-intersecting.
    pub polygon: Vec<[f64; 2]>,
}

fn polygons(field: &str, given: &[PolygonDto]) -> Result<Vec<Vec<(f64, f64)>>, ApiError> {
    given
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let field = format!("{field}[{i}].polygon");
            count_within(&field, p.polygon.len(), POLYGON_CORNERS)?;
            p.polygon
                .iter()
                .map(|&[x, y]| {
                    Ok((
                        within(&field, x, COORDINATE)?,
                        within(&field, y, COORDINATE)?,
                    ))
                })
                .collect()
        })
        .collect()
}

/// `geometry.kind = assembly`: the polygons checked, contacts found by the solver.
pub fn assembly(blocks: &[PolygonDto], supports: &[PolygonDto]) -> Result<Assembly, ApiError> {
    count_within("geometry.blocks", blocks.len(), BLOCKS)?;
    count_within("geometry.supports", supports.len(), SUPPORTS)?;
    let blocks = polygons("geometry.blocks", blocks)?;
    let supports = polygons("geometry.supports", supports)?;
    Ok(Assembly::from_polygons(&blocks, &supports)?)
}

/// The rings and spans of a circular arch as given.
#[derive(Debug, Clone, Copy)]
pub struct Generated {
    /// `rings`.
    pub rings: usize,
    /// `ring_joints`.
    pub ring_joints: RingJointsDto,
    /// `spans`.
    pub spans: usize,
    /// `pier_width`.
    pub pier_width: Option<f64>,
    /// `pier_height`.
    pub pier_height: Option<f64>,
}

impl Generated {
    /// Whether the arch is the plain one-ring, one-span chain.
    pub fn is_plain(&self) -> bool {
        self.rings == 1 && self.spans == 1
    }
}

/// A circular arch with rings or spans: the generated assembly.
pub fn generated(arch: &CircularArch, g: Generated) -> Result<Bridge, ApiError> {
    generated_by(arch.voussoirs(), g, |rings, joints, piers| {
        bridge(arch, rings, joints, piers)
    })
}

/// The rings and spans of `g` checked and built by `build` (rings, joints, piers), for an arch
/// of `voussoirs` voussoirs per ring.
pub fn generated_by(
    voussoirs: usize,
    g: Generated,
    build: impl FnOnce(usize, RingJoints, Piers) -> Result<Bridge, ArchError>,
) -> Result<Bridge, ApiError> {
    count_within("geometry.rings", g.rings, RINGS)?;
    count_within("geometry.spans", g.spans, SPANS)?;
    let per_span = voussoirs * g.rings + g.rings / 2;
    if per_span * g.spans > MAX_GENERATED_BLOCKS {
        return Err(ApiError::invalid(
            "geometry.voussoirs",
            format!(
                "{voussoirs} is too many for {} rings and {} spans: at most \
                 {MAX_GENERATED_BLOCKS} blocks in all",
                g.rings, g.spans
            ),
        ));
    }
    let piers = if g.spans > 1 {
        let required = |name: &str, v: Option<f64>| {
            v.ok_or_else(|| {
                ApiError::invalid(
                    format!("geometry.{name}"),
                    format!("is needed with spans > 1 (give geometry.{name})"),
                )
            })
        };
        Piers {
            spans: g.spans,
            width: required("pier_width", g.pier_width)?,
            height: required("pier_height", g.pier_height)?,
        }
    } else {
        if g.pier_width.is_some() || g.pier_height.is_some() {
            return Err(ApiError::invalid(
                "geometry.pier_width",
                "piers are for spans > 1: give spans, or leave the piers out",
            ));
        }
        Piers {
            spans: 1,
            width: 0.0,
            height: 0.0,
        }
    };
    let joints = match g.ring_joints {
        RingJointsDto::Staggered => RingJoints::Staggered,
        RingJointsDto::Aligned => RingJoints::Aligned,
    };
    Ok(build(g.rings, joints, piers)?)
}
