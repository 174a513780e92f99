//! `section.supports` (model §7): reinforcement as clients state it, read into the solver's
//! supports, and each support's force against the answered surface.

use serde::{Deserialize, Serialize};
use thrustline_solver::slope::section::supports::{
    Anchorage, Application, Mode, Orientation, PileOrientation, Support, SupportKind,
};
use thrustline_solver::slope::section::SupportForce;
use utoipa::ToSchema;

use crate::error::ApiError;
use crate::limits::SLOPE_SUPPORTS;
use crate::validation::count_within;

/// How a support's force enters the equations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ApplicationDto {
    /// A known force on the sliding mass: it reduces the driving force (tensioned tiebacks,
    /// anchors: they act before the slope moves).
    Active,
    /// Mobilised like the soil's strength: its component along the slip surface adds to the
    /// resisting force and is divided by F (nails, geosynthetics: they act once it moves). Never
    /// gives a higher F than `active`.
    Passive,
}

/// Which ends of a geosynthetic cannot pull out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum AnchorageDto {
    /// Neither (pull-out beyond the surface and stripping inside the mass both limit it).
    #[default]
    None,
    /// Wrapped or fixed at the slope face (the head): no stripping.
    SlopeFace,
    /// Fixed at the embedded end: no pull-out.
    EmbeddedEnd,
    /// Both: its tensile strength alone.
    BothEnds,
}

/// The direction of a geosynthetic's force.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum GeosyntheticOrientationDto {
    /// Along the reinforcement.
    #[default]
    Parallel,
    /// Along the slip surface where it crosses.
    Tangent,
    /// Halfway between the two.
    Bisector,
}

/// The direction of a pile's shear force.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum PileOrientationDto {
    /// Along the slip surface where it crosses, against the sliding.
    #[default]
    ParallelToSurface,
    /// Across the pile, against the sliding.
    PerpendicularToPile,
}

/// One support: a segment from its `head` (at the ground) to its `end` (in the ground).
/// Capacities are forces per support (a geosynthetic's per unit width), divided by `spacing`
/// into forces per unit width of the section; bond strengths are forces per unit length.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SupportDto {
    /// A bar anchored at its end: min(tensile, plate) once its end lies beyond the slip surface.
    EndAnchored {
        /// The head, at the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        head: [f64; 2],
        /// The end, in the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        end: [f64; 2],
        /// Out-of-plane spacing (> 0).
        spacing: f64,
        /// Tensile capacity (≥ 0).
        tensile_capacity: f64,
        /// Capacity of the head plate (≥ 0).
        plate_capacity: f64,
        /// `active` or `passive`.
        application: ApplicationDto,
    },
    /// A tendon bonded over its last `bond_length` towards the end: min(tensile, bond × bonded
    /// length beyond the surface, plate + bond × bonded length inside the mass).
    GroutedTieback {
        /// The head, at the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        head: [f64; 2],
        /// The end, in the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        end: [f64; 2],
        /// Out-of-plane spacing (> 0).
        spacing: f64,
        /// Tensile capacity (≥ 0).
        tensile_capacity: f64,
        /// Capacity of the head plate (≥ 0).
        plate_capacity: f64,
        /// Bond strength per unit length (≥ 0).
        bond_strength: f64,
        /// Length of the bonded part at the end (0 < bond_length ≤ the tieback's length).
        bond_length: f64,
        /// `active` or `passive`.
        application: ApplicationDto,
    },
    /// A nail bonded over its whole length: min(tensile, bond × length beyond the surface,
    /// plate + bond × length inside the mass).
    SoilNail {
        /// The head, at the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        head: [f64; 2],
        /// The end, in the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        end: [f64; 2],
        /// Out-of-plane spacing (> 0).
        spacing: f64,
        /// Tensile capacity (≥ 0).
        tensile_capacity: f64,
        /// Capacity of the head plate (≥ 0).
        plate_capacity: f64,
        /// Bond strength per unit length (≥ 0).
        bond_strength: f64,
        /// `active` or `passive`.
        application: ApplicationDto,
    },
    /// A geotextile or geogrid, per unit width: min(tensile, bond × length beyond the surface
    /// unless the embedded end is anchored, bond × length inside unless the face is).
    Geosynthetic {
        /// The head, at the ground (the slope face).
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        head: [f64; 2],
        /// The end, in the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        end: [f64; 2],
        /// Tensile strength per unit width (≥ 0).
        tensile_strength: f64,
        /// Bond strength per unit length, both faces together (≥ 0).
        bond_strength: f64,
        /// Which ends cannot pull out. Defaults to `none`.
        #[serde(default)]
        anchorage: Option<AnchorageDto>,
        /// The direction of its force. Defaults to `parallel`.
        #[serde(default)]
        force_orientation: Option<GeosyntheticOrientationDto>,
        /// `active` or `passive`.
        application: ApplicationDto,
    },
    /// A pile or micro-pile: its shear strength where the slip surface crosses it.
    Pile {
        /// The head, at the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        head: [f64; 2],
        /// The toe, in the ground.
        #[schema(value_type = Vec<f64>, min_items = 2, max_items = 2)]
        end: [f64; 2],
        /// Out-of-plane spacing (> 0).
        spacing: f64,
        /// Shear strength (≥ 0).
        shear_strength: f64,
        /// The direction of its force. Defaults to `parallel_to_surface`.
        #[serde(default)]
        force_orientation: Option<PileOrientationDto>,
        /// `active` or `passive`.
        application: ApplicationDto,
    },
}

/// The solver's supports (the solver checks the values against the section and names the
/// field: `section.supports[i].…`).
pub fn supports(dtos: &[SupportDto]) -> Result<Vec<Support>, ApiError> {
    count_within("section.supports", dtos.len(), SLOPE_SUPPORTS)?;
    Ok(dtos.iter().map(support).collect())
}

fn support(dto: &SupportDto) -> Support {
    use SupportDto as D;
    let (head, end, spacing, application) = match *dto {
        D::EndAnchored {
            head,
            end,
            spacing,
            application,
            ..
        }
        | D::GroutedTieback {
            head,
            end,
            spacing,
            application,
            ..
        }
        | D::SoilNail {
            head,
            end,
            spacing,
            application,
            ..
        }
        | D::Pile {
            head,
            end,
            spacing,
            application,
            ..
        } => (head, end, spacing, application),
        D::Geosynthetic {
            head,
            end,
            application,
            ..
        } => (head, end, 1.0, application),
    };
    Support {
        head: (head[0], head[1]),
        end: (end[0], end[1]),
        spacing,
        kind: kind(dto),
        application: match application {
            ApplicationDto::Active => Application::Active,
            ApplicationDto::Passive => Application::Passive,
        },
    }
}

/// What a support is and can carry, as the solver takes it.
fn kind(dto: &SupportDto) -> SupportKind {
    match *dto {
        SupportDto::EndAnchored {
            tensile_capacity,
            plate_capacity,
            ..
        } => SupportKind::EndAnchored {
            tensile_capacity,
            plate_capacity,
        },
        SupportDto::GroutedTieback {
            tensile_capacity,
            plate_capacity,
            bond_strength,
            bond_length,
            ..
        } => SupportKind::GroutedTieback {
            tensile_capacity,
            plate_capacity,
            bond_strength,
            bond_length,
        },
        SupportDto::SoilNail {
            tensile_capacity,
            plate_capacity,
            bond_strength,
            ..
        } => SupportKind::SoilNail {
            tensile_capacity,
            plate_capacity,
            bond_strength,
        },
        SupportDto::Geosynthetic {
            tensile_strength,
            bond_strength,
            anchorage,
            force_orientation,
            ..
        } => SupportKind::Geosynthetic {
            tensile_strength,
            bond_strength,
            anchorage: match anchorage.unwrap_or_default() {
                AnchorageDto::None => Anchorage::None,
                AnchorageDto::SlopeFace => Anchorage::SlopeFace,
                AnchorageDto::EmbeddedEnd => Anchorage::EmbeddedEnd,
                AnchorageDto::BothEnds => Anchorage::BothEnds,
            },
            orientation: match force_orientation.unwrap_or_default() {
                GeosyntheticOrientationDto::Parallel => Orientation::Parallel,
                GeosyntheticOrientationDto::Tangent => Orientation::Tangent,
                GeosyntheticOrientationDto::Bisector => Orientation::Bisector,
            },
        },
        SupportDto::Pile {
            shear_strength,
            force_orientation,
            ..
        } => SupportKind::Pile {
            shear_strength,
            orientation: match force_orientation.unwrap_or_default() {
                PileOrientationDto::ParallelToSurface => PileOrientation::ParallelToSurface,
                PileOrientationDto::PerpendicularToPile => PileOrientation::PerpendicularToPile,
            },
        },
    }
}

/// What limits a support's force.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ModeDto {
    /// The tendon's or the geosynthetic's tensile capacity.
    Tensile,
    /// The head plate.
    Plate,
    /// Pull-out of the bond beyond the slip surface.
    Pullout,
    /// Stripping: the support pulls out of the sliding mass with its head.
    Stripping,
    /// A pile's shear strength.
    Shear,
}

/// One support against the answered slip surface.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SupportOutDto {
    /// The support (from 1, as listed in `section.supports`).
    pub support: usize,
    /// Where the slip surface crosses it (first from its head); null where it does not (then
    /// it carries nothing).
    #[schema(value_type = Option<Vec<f64>>)]
    pub crossing: Option<[f64; 2]>,
    /// The force it puts on the sliding mass, per unit width (÷ spacing): 0 where the surface
    /// misses it.
    pub force: f64,
    /// The force's direction (a unit vector; null where the surface misses it).
    #[schema(value_type = Option<Vec<f64>>)]
    pub direction: Option<[f64; 2]>,
    /// What limits the force; null where the surface misses it.
    pub mode: Option<ModeDto>,
    /// `active` or `passive`, as given.
    pub application: ApplicationDto,
}

/// Each support against the surface, in the section's order.
pub fn supports_out(forces: &[SupportForce], supports: &[Support]) -> Vec<SupportOutDto> {
    forces
        .iter()
        .zip(supports)
        .enumerate()
        .map(|(i, (f, s))| SupportOutDto {
            support: i + 1,
            crossing: f.crossing.map(|p| [p.0, p.1]),
            force: f.force,
            direction: f.crossing.map(|_| [f.direction.0, f.direction.1]),
            mode: f.mode.map(|m| match m {
                Mode::Tensile => ModeDto::Tensile,
                Mode::Plate => ModeDto::Plate,
                Mode::Pullout => ModeDto::Pullout,
                Mode::Stripping => ModeDto::Stripping,
                Mode::Shear => ModeDto::Shear,
            }),
            application: match s.application {
                Application::Active => ApplicationDto::Active,
                Application::Passive => ApplicationDto::Passive,
            },
        })
        .collect()
}
