//! The arch whose minimum thickness is searched (`POST /arch/minimum-thickness`): a circular
//! arch, or an arch by its intrados profile, one ring and one span; its blocks at any thickness.

use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use thrustline_solver::arch::profile::{Profile, Station};
use thrustline_solver::arch::{ArchError, Assembly, CircularArch};
use utoipa::ToSchema;

use super::geometry::{variant, CircularGeometryDto, ProfileGeometryDto, VoussoirDto};
use super::input::circular_arch;
use crate::error::ApiError;
use crate::extract::json_kind;
use crate::limits::{BLOCKS, LENGTH};
use crate::validation::{count_within, within};

/// The arch of a minimum-thickness search, by `kind`: circular or a profile (one ring, one
/// span); its `thickness`, if given, is the D of the geometric factor of safety.
#[derive(Debug, Clone, Serialize, ToSchema)]
#[serde(untagged)]
#[schema(discriminator(property_name = "kind", mapping(
    ("circular" = "#/components/schemas/CircularGeometryDto"),
    ("profile" = "#/components/schemas/ProfileGeometryDto"),
)))]
pub enum ThinnestGeometryDto {
    /// `kind: circular`.
    Circular(CircularGeometryDto),
    /// `kind: profile`.
    Profile(ProfileGeometryDto),
}

impl<'de> Deserialize<'de> for ThinnestGeometryDto {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let value = Value::deserialize(deserializer)?;
        let expected = "expected one of `circular`, `profile`";
        match value.get("kind") {
            _ if !value.is_object() => Err(D::Error::custom(format!(
                "invalid type: {}, expected an object with `kind`",
                json_kind(&value)
            ))),
            None => Err(D::Error::missing_field("kind")),
            Some(Value::String(kind)) if kind == "circular" => variant(&value).map(Self::Circular),
            Some(Value::String(kind)) if kind == "profile" => variant(&value).map(Self::Profile),
            Some(Value::String(other)) => Err(D::Error::custom(format!(
                "kind: unknown variant `{other}`, {expected} (the minimum-thickness search takes \
                 one ring and one span)"
            ))),
            Some(other) => Err(D::Error::custom(format!(
                "kind: invalid type: {}, {expected}",
                json_kind(other)
            ))),
        }
    }
}

impl ThinnestGeometryDto {
    /// Whether the voussoirs are annular sectors (drawn with arcs).
    pub fn is_curved(&self) -> bool {
        matches!(self, Self::Circular(c) if c.voussoir == VoussoirDto::Curved)
    }

    /// The thickness given, if any.
    pub fn thickness(&self) -> Option<f64> {
        match self {
            Self::Circular(c) => c.thickness,
            Self::Profile(p) => p.thickness,
        }
    }
}

/// The arch of the search, validated: its shape without a thickness.
#[derive(Debug, Clone)]
pub enum Thinnest {
    /// A circular arch (its thickness is only a template).
    Circle(CircularArch),
    /// An intrados and its voussoirs.
    Profile {
        /// The intrados.
        profile: Profile,
        /// Its joints' stations, N + 1 of them.
        stations: Vec<Station>,
    },
}

impl Thinnest {
    /// The length the search's range and tolerance are relative to: the radius of a circle,
    /// half the span of a profile.
    pub fn scale(&self) -> f64 {
        match self {
            Self::Circle(arch) => arch.radius(),
            Self::Profile { profile, .. } => 0.5 * profile.span(),
        }
    }

    /// The blocks at thickness `d`.
    pub fn assembly(&self, d: f64) -> Result<Assembly, ArchError> {
        match self {
            Self::Circle(arch) => arch.with_thickness(d).map(|a| a.assembly()),
            Self::Profile { profile, stations } => profile.chain_on(stations, d),
        }
    }

    /// Voussoirs N.
    pub fn voussoirs(&self) -> usize {
        match self {
            Self::Circle(arch) => arch.voussoirs(),
            Self::Profile { stations, .. } => stations.len() - 1,
        }
    }

    /// The circular arch of thickness `d`, for a circle.
    pub fn circle(&self, d: f64) -> Option<CircularArch> {
        match self {
            Self::Circle(arch) => arch.with_thickness(d).ok(),
            Self::Profile { .. } => None,
        }
    }

    /// The span of a profile.
    pub fn span(&self) -> Option<f64> {
        match self {
            Self::Circle(_) => None,
            Self::Profile { profile, .. } => Some(profile.span()),
        }
    }
}

/// One ring and one span.
fn one_ring_one_span(
    rings: usize,
    spans: usize,
    pier_width: Option<f64>,
    pier_height: Option<f64>,
) -> Result<(), ApiError> {
    for (field, many) in [
        ("geometry.rings", rings != 1),
        ("geometry.spans", spans != 1),
        ("geometry.pier_width", pier_width.is_some()),
        ("geometry.pier_height", pier_height.is_some()),
    ] {
        if many {
            return Err(ApiError::invalid(
                field,
                "the minimum-thickness search takes one ring and one span: leave it out",
            ));
        }
    }
    Ok(())
}

/// The arch of the search and the thickness given (checked against the shape).
pub fn thinnest(geometry: &ThinnestGeometryDto) -> Result<(Thinnest, Option<f64>), ApiError> {
    match geometry {
        ThinnestGeometryDto::Circular(g) => {
            let radius = within("geometry.radius", g.radius, LENGTH)?;
            one_ring_one_span(g.rings, g.spans, g.pier_width, g.pier_height)?;
            // A given thickness is checked (0 < D < 2R) for the geometric factor; any valid
            // one serves as the template of the search.
            let given = g
                .thickness
                .map(|d| circular_arch(g, d).map(|_| d))
                .transpose()?;
            Ok((Thinnest::Circle(circular_arch(g, 0.1 * radius)?), given))
        }
        ThinnestGeometryDto::Profile(g) => {
            let profile = super::profile::profile(g)?;
            one_ring_one_span(g.rings, g.spans, g.pier_width, g.pier_height)?;
            let voussoirs = count_within("geometry.voussoirs", g.voussoirs, BLOCKS)?;
            if let Some(d) = g.thickness {
                profile.check_thickness(d)?;
            }
            let stations = profile.stations(voussoirs);
            Ok((Thinnest::Profile { profile, stations }, g.thickness))
        }
    }
}
