//! `geometry.kind = profile` (model §10): the intrados validated once into the solver's
//! [`Profile`], and its blocks: the one-ring chain, or the generated rings and spans.

use thrustline_solver::arch::generators::profile_bridge;
use thrustline_solver::arch::profile::{pointed_rise, Profile, ProfileShape};
use thrustline_solver::arch::Assembly;

use super::assembly::{generated_by, Generated};
use super::geometry::{ProfileGeometryDto, ProfileShapeDto};
use crate::error::ApiError;
use crate::limits::{BLOCKS, COORDINATE, INTRADOS_POINTS, LENGTH, RISE_PER_SPAN};
use crate::validation::{count_within, within};

/// A generated bridge's fill faces: (block, points along the face).
type Faces = Vec<(usize, Vec<(f64, f64)>)>;

/// A field given to a shape that does not take it.
fn not_for(field: &str, shape: &str) -> ApiError {
    ApiError::invalid(
        format!("geometry.{field}"),
        format!("is for shape {shape}: leave it out"),
    )
}

fn required(field: &str, value: Option<f64>, what: &str) -> Result<f64, ApiError> {
    value.ok_or_else(|| {
        ApiError::invalid(format!("geometry.{field}"), format!("is required {what}"))
    })
}

/// A rise (or a pointed arch's radius) within 1e-3·span … 100·span.
fn per_span(field: &str, value: f64, span: f64) -> Result<f64, ApiError> {
    let field = format!("geometry.{field}");
    let value = crate::validation::finite(&field, value)?;
    if RISE_PER_SPAN.contains(value / span) {
        Ok(value)
    } else {
        Err(ApiError::invalid(
            field,
            format!(
                "{value} is out of range: allowed is {} ≤ value ≤ {} (1e-3·span to 100·span)",
                1e-3 * span,
                100.0 * span
            ),
        ))
    }
}

/// The intrados of a profile geometry, every field checked and named.
pub fn profile(dto: &ProfileGeometryDto) -> Result<Profile, ApiError> {
    use ProfileShapeDto as S;
    if dto.radius.is_some() && dto.shape != S::Pointed {
        return Err(not_for("radius", "pointed"));
    }
    if dto.haunch_radius.is_some() && dto.shape != S::ThreeCentred {
        return Err(not_for("haunch_radius", "three_centred"));
    }
    if dto.shape == S::Points {
        return measured(dto);
    }
    if dto.intrados.is_some() {
        return Err(not_for("intrados", "points"));
    }
    let span = within(
        "geometry.span",
        required("span", dto.span, "(the intrados' span)")?,
        LENGTH,
    )?;
    let shape = shape(dto)?;
    let rise = rise(dto, span)?;
    Ok(Profile::new(&shape, span, rise)?)
}

/// The intrados of a measured profile (shape points): its points, checked and named.
fn measured(dto: &ProfileGeometryDto) -> Result<Profile, ApiError> {
    for field in ["span", "rise"] {
        let given = if field == "span" { dto.span } else { dto.rise };
        if given.is_some() {
            return Err(ApiError::invalid(
                format!("geometry.{field}"),
                "comes from the points with shape points: leave it out",
            ));
        }
    }
    let points = dto
        .intrados
        .as_deref()
        .ok_or_else(|| ApiError::invalid("geometry.intrados", "is required with shape points"))?;
    count_within("geometry.intrados", points.len(), INTRADOS_POINTS)?;
    let points = points
        .iter()
        .enumerate()
        .map(|(i, &[x, y])| {
            let field = format!("geometry.intrados[{i}]");
            Ok((
                within(&field, x, COORDINATE)?,
                within(&field, y, COORDINATE)?,
            ))
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    Ok(Profile::new(&ProfileShape::Points(points), 0.0, 0.0)?)
}

/// The solver's shape for a formula-given profile (not shape points).
fn shape(dto: &ProfileGeometryDto) -> Result<ProfileShape, ApiError> {
    use ProfileShapeDto as S;
    Ok(match dto.shape {
        S::Segmental => ProfileShape::Segmental,
        S::Semicircular => ProfileShape::Semicircular,
        S::Elliptical => ProfileShape::Elliptical,
        S::Parabolic => ProfileShape::Parabolic,
        S::Catenary => ProfileShape::Catenary,
        S::Pointed => ProfileShape::Pointed,
        S::ThreeCentred => ProfileShape::ThreeCentred {
            haunch_radius: crate::validation::finite(
                "geometry.haunch_radius",
                required(
                    "haunch_radius",
                    dto.haunch_radius,
                    "with shape three_centred",
                )?,
            )?,
        },
        S::Points => unreachable!("measured profiles return above"),
    })
}

/// The intrados' rise above its springings, given or (pointed arch) from its radius.
fn rise(dto: &ProfileGeometryDto, span: f64) -> Result<f64, ApiError> {
    use ProfileShapeDto as S;
    Ok(match (dto.shape, dto.rise, dto.radius) {
        (S::Semicircular, None, _) => 0.5 * span,
        (S::Pointed, Some(_), Some(_)) => {
            return Err(ApiError::invalid(
                "geometry.radius",
                "give either rise or radius for a pointed arch, not both",
            ))
        }
        (S::Pointed, None, Some(radius)) => {
            let radius = per_span("radius", radius, span)?;
            if radius <= 0.5 * span {
                return Err(ApiError::invalid(
                    "geometry.radius",
                    format!(
                        "{radius} is out of range: allowed is radius > span/2 = {}",
                        0.5 * span
                    ),
                ));
            }
            pointed_rise(span, radius)
        }
        (_, rise, _) => per_span(
            "rise",
            required("rise", rise, "(the intrados' crown above its springings)")?,
            span,
        )?,
    })
}

/// The blocks of a profile geometry of `thickness`, and for generated rings or spans the
/// faces a fill lies on.
pub fn profile_assembly(
    dto: &ProfileGeometryDto,
    thickness: f64,
) -> Result<(Assembly, Option<Faces>), ApiError> {
    let profile = profile(dto)?;
    let n = count_within("geometry.voussoirs", dto.voussoirs, BLOCKS)?;
    let g = Generated {
        rings: dto.rings,
        ring_joints: dto.ring_joints,
        spans: dto.spans,
        pier_width: dto.pier_width,
        pier_height: dto.pier_height,
    };
    if g.is_plain() {
        if g.pier_width.is_some() || g.pier_height.is_some() {
            return Err(ApiError::invalid(
                "geometry.pier_width",
                "piers are for spans > 1: give spans, or leave the piers out",
            ));
        }
        return Ok((profile.chain(thickness, n)?, None));
    }
    let bridge = generated_by(n, g, |rings, joints, piers| {
        profile_bridge(&profile, thickness, n, rings, joints, piers)
    })?;
    Ok((bridge.assembly, Some(bridge.extrados)))
}
