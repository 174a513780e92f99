//! Where the solver's inputs live in a request: the one place where a solver error, which names
//! a typed parameter, becomes a 422 naming a JSON field path. Array indices in paths are 0-based
//! (JSON), block, interface, slice and load *numbers* in messages 1-based (as the API numbers
//! them).

use thrustline_solver::arch::{ArchError, ArchParameter, Bound, Resultant};
use thrustline_solver::slope::{SlopeError, SlopeParameter};

use crate::error::ApiError;

/// The request field of an arch parameter.
pub fn arch_field(parameter: ArchParameter) -> String {
    match parameter {
        ArchParameter::Radius => "geometry.radius".to_owned(),
        ArchParameter::Thickness => "geometry.thickness".to_owned(),
        ArchParameter::LeftBaseAngle => "geometry.left_base_angle_deg".to_owned(),
        ArchParameter::RightBaseAngle => "geometry.right_base_angle_deg".to_owned(),
        ArchParameter::Blocks => "geometry.blocks".to_owned(),
        ArchParameter::BlockCorners { block } => format!("geometry.blocks[{block}].corners"),
        ArchParameter::BlockCorner { block, corner } => {
            format!("geometry.blocks[{block}].corners[{corner}]")
        }
        ArchParameter::BlockPolygon { block } => format!("geometry.blocks[{block}].polygon"),
        ArchParameter::Supports => "geometry.supports".to_owned(),
        ArchParameter::SupportPolygon { support } => {
            format!("geometry.supports[{support}].polygon")
        }
        ArchParameter::Span => "geometry.span".to_owned(),
        ArchParameter::Rise => "geometry.rise".to_owned(),
        ArchParameter::HaunchRadius => "geometry.haunch_radius".to_owned(),
        ArchParameter::Intrados => "geometry.intrados".to_owned(),
        ArchParameter::Rings => "geometry.rings".to_owned(),
        ArchParameter::Spans => "geometry.spans".to_owned(),
        ArchParameter::PierWidth => "geometry.pier_width".to_owned(),
        ArchParameter::PierHeight => "geometry.pier_height".to_owned(),
        ArchParameter::UnitWeight => "unit_weight".to_owned(),
        ArchParameter::InterfaceLimit { resultant, bound } => {
            let resultant = match resultant {
                Resultant::Q => "q",
                Resultant::S => "s",
                Resultant::T | Resultant::U | Resultant::V => "t",
                Resultant::M => "compressive_strength",
                Resultant::Passive => "passive",
            };
            let bound = match bound {
                Bound::Lower => "min",
                Bound::Upper => "max",
            };
            format!("interface_limits.{resultant}_{bound}")
        }
        ArchParameter::FrictionCoefficient => "friction_coefficient".to_owned(),
        ArchParameter::Cohesion => "ring_interface.cohesion".to_owned(),
        ArchParameter::CompressiveStrength => "compressive_strength".to_owned(),
        ArchParameter::CrushingPlanes => "crushing_planes".to_owned(),
        ArchParameter::Loads => "loads".to_owned(),
        ArchParameter::Load { index } => format!("loads[{index}]"),
        ArchParameter::LoadBlock { index } => format!("loads[{index}].block"),
        ArchParameter::Passive => "fill.passive".to_owned(),
    }
}

/// The request field of a slope parameter (the simple form: `slope`, `circle`, `soil`).
pub fn slope_field(parameter: SlopeParameter) -> String {
    match parameter {
        SlopeParameter::Height => "slope.height".to_owned(),
        SlopeParameter::Length => "slope.length".to_owned(),
        SlopeParameter::CircleX => "circle.x".to_owned(),
        SlopeParameter::CircleY => "circle.y".to_owned(),
        SlopeParameter::LowerEndFactor => "circle.lower_end_factor".to_owned(),
        SlopeParameter::UnitWeight => "soil.unit_weight".to_owned(),
        SlopeParameter::Cohesion => "soil.cohesion".to_owned(),
        SlopeParameter::FrictionAngle => "soil.friction_angle_deg".to_owned(),
        SlopeParameter::PorePressureRatio => "soil.pore_pressure_ratio".to_owned(),
        SlopeParameter::SeismicKh => "seismic.kh".to_owned(),
        SlopeParameter::SeismicKv => "seismic.kv".to_owned(),
        SlopeParameter::ExternalLoads => "external_loads".to_owned(),
        SlopeParameter::ExternalLoadSlice { index } => format!("external_loads[{index}].slice"),
        SlopeParameter::ExternalLoad { index } => format!("external_loads[{index}]"),
        SlopeParameter::Ground => "section.ground".to_owned(),
        SlopeParameter::Layer { index } => format!("section.layers[{index}]"),
        SlopeParameter::LayerTop { index } => format!("section.layers[{index}].top"),
        SlopeParameter::Bedrock => "section.bedrock".to_owned(),
        SlopeParameter::PiezometricLine => "section.piezometric_line".to_owned(),
        SlopeParameter::Drawdown => "section.drawdown".to_owned(),
        SlopeParameter::REnvelope { index } => {
            format!("section.layers[{index}].soil.r_envelope")
        }
        SlopeParameter::WaterUnitWeight => "section.water_unit_weight".to_owned(),
        SlopeParameter::Surcharge { index } => format!("section.surcharges[{index}]"),
        SlopeParameter::LineLoad { index } => format!("section.line_loads[{index}]"),
        SlopeParameter::TensionCrackDepth => "section.tension_crack.depth".to_owned(),
        SlopeParameter::TensionCrackWater => "section.tension_crack.water_depth".to_owned(),
        SlopeParameter::CircleCentre => "circle.centre".to_owned(),
        SlopeParameter::CircleMass => "circle.mass".to_owned(),
        SlopeParameter::CircleRadius => "circle.radius".to_owned(),
        SlopeParameter::Surface => "surface".to_owned(),
        SlopeParameter::SurfaceVertex { index } => format!("surface[{index}]"),
        SlopeParameter::MomentCentre => "moment_centre".to_owned(),
        SlopeParameter::Search => "search".to_owned(),
        SlopeParameter::DesignFactor { name } => format!("design.factors.{name}"),
        SlopeParameter::Support { index, field } => {
            format!("section.supports[{index}].{}", field.name())
        }
    }
}

/// The arch solver's refusals are the client's to fix: 422 naming the field.
impl From<ArchError> for ApiError {
    fn from(error: ArchError) -> Self {
        match error {
            ArchError::OutOfRange {
                parameter,
                value,
                allowed,
            } => ApiError::invalid(
                arch_field(parameter),
                format!("{value} is out of range: allowed is {allowed}"),
            ),
            ArchError::InvalidGeometry { parameter, reason } => {
                ApiError::invalid(arch_field(parameter), reason)
            }
        }
    }
}

/// The slope solver's refusals are the client's to fix: 422 naming the field.
impl From<SlopeError> for ApiError {
    fn from(error: SlopeError) -> Self {
        match error {
            SlopeError::OutOfRange {
                parameter,
                value,
                allowed,
            } => ApiError::invalid(
                slope_field(parameter),
                format!("{value} is out of range: allowed is {allowed}"),
            ),
            SlopeError::NoSlipMass { parameter, reason } => ApiError::invalid(
                slope_field(parameter),
                format!("the slip surface cuts no sliding mass from the ground: {reason}"),
            ),
            SlopeError::Conflict { parameter, reason } => {
                ApiError::invalid(slope_field(parameter), reason)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_interface_limit_has_its_own_field() {
        let field =
            |resultant, bound| arch_field(ArchParameter::InterfaceLimit { resultant, bound });
        assert_eq!(field(Resultant::Q, Bound::Lower), "interface_limits.q_min");
        assert_eq!(field(Resultant::S, Bound::Upper), "interface_limits.s_max");
        assert_eq!(field(Resultant::T, Bound::Lower), "interface_limits.t_min");
    }

    #[test]
    fn indices_in_paths_are_those_of_the_json_arrays() {
        let corner = ArchParameter::BlockCorner {
            block: 0,
            corner: 3,
        };
        assert_eq!(arch_field(corner), "geometry.blocks[0].corners[3]");
        let slice = SlopeParameter::ExternalLoadSlice { index: 2 };
        assert_eq!(slope_field(slice), "external_loads[2].slice");
    }
}
