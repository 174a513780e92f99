//! Input the slope solver cannot accept, naming the offending input by what it is, and the range
//! check the constructors share.

/// An input of the slope solver, named by what it is (the service maps it to its request field).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlopeParameter {
    /// Slope height H.
    Height,
    /// Slope length L.
    Length,
    /// Centre X of the circle (from the lower end).
    CircleX,
    /// Centre Y of the circle (above the lower end).
    CircleY,
    /// Lower-end position factor F_e.
    LowerEndFactor,
    /// Unit weight γ of the soil.
    UnitWeight,
    /// Effective cohesion c'.
    Cohesion,
    /// Effective friction angle φ'.
    FrictionAngle,
    /// Pore pressure ratio r_u.
    PorePressureRatio,
    /// Horizontal seismic coefficient.
    SeismicKh,
    /// Vertical seismic coefficient.
    SeismicKv,
    /// The external loads as a whole.
    ExternalLoads,
    /// The slice of external load `index` (0-based).
    ExternalLoadSlice {
        /// Index of the load.
        index: usize,
    },
    /// The forces of external load `index` (0-based).
    ExternalLoad {
        /// Index of the load.
        index: usize,
    },
    /// The ground line of a section.
    Ground,
    /// Layer `index` of a section as a whole (0-based).
    Layer {
        /// Index of the layer.
        index: usize,
    },
    /// The top line of layer `index` (0-based).
    LayerTop {
        /// Index of the layer.
        index: usize,
    },
    /// The bedrock line.
    Bedrock,
    /// The piezometric line.
    PiezometricLine,
    /// A rapid drawdown as a whole.
    Drawdown,
    /// The R envelope of layer `index`'s soil (0-based).
    REnvelope {
        /// Index of the layer.
        index: usize,
    },
    /// The unit weight of water.
    WaterUnitWeight,
    /// Surcharge `index` (0-based).
    Surcharge {
        /// Index of the surcharge.
        index: usize,
    },
    /// Line load `index` (0-based).
    LineLoad {
        /// Index of the line load.
        index: usize,
    },
    /// The tension crack's depth.
    TensionCrackDepth,
    /// The tension crack's water depth.
    TensionCrackWater,
    /// The centre of an absolute circle.
    CircleCentre,
    /// Which of the masses a circle cuts is analysed.
    CircleMass,
    /// The radius of an absolute circle.
    CircleRadius,
    /// A polyline slip surface.
    Surface,
    /// Vertex `index` of a polyline slip surface (0-based).
    SurfaceVertex {
        /// Index of the vertex.
        index: usize,
    },
    /// The centre about which moment-only methods take moments.
    MomentCentre,
    /// A search (what it found could not be analysed).
    Search,
    /// A partial factor of a design check (its name as requests spell it).
    DesignFactor {
        /// The factor's name.
        name: &'static str,
    },
    /// A field of support `index` (0-based).
    Support {
        /// Index of the support.
        index: usize,
        /// The field.
        field: SupportField,
    },
}

/// A field of a support (model §7).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SupportField {
    /// Its head.
    Head,
    /// Its end.
    End,
    /// Its out-of-plane spacing.
    Spacing,
    /// A tendon's tensile capacity.
    TensileCapacity,
    /// A head plate's capacity.
    PlateCapacity,
    /// A bond strength.
    BondStrength,
    /// A tieback's bonded length.
    BondLength,
    /// A geosynthetic's tensile strength.
    TensileStrength,
    /// A pile's shear strength.
    ShearStrength,
}

impl SupportField {
    /// The field's name (as requests spell it).
    pub fn name(self) -> &'static str {
        match self {
            Self::Head => "head",
            Self::End => "end",
            Self::Spacing => "spacing",
            Self::TensileCapacity => "tensile_capacity",
            Self::PlateCapacity => "plate_capacity",
            Self::BondStrength => "bond_strength",
            Self::BondLength => "bond_length",
            Self::TensileStrength => "tensile_strength",
            Self::ShearStrength => "shear_strength",
        }
    }
}

impl std::fmt::Display for SlopeParameter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Height => write!(f, "slope height"),
            Self::Length => write!(f, "slope length"),
            Self::CircleX => write!(f, "circle centre X"),
            Self::CircleY => write!(f, "circle centre Y"),
            Self::LowerEndFactor => write!(f, "lower-end factor"),
            Self::UnitWeight => write!(f, "unit weight"),
            Self::Cohesion => write!(f, "cohesion"),
            Self::FrictionAngle => write!(f, "friction angle"),
            Self::PorePressureRatio => write!(f, "pore pressure ratio"),
            Self::SeismicKh => write!(f, "seismic kh"),
            Self::SeismicKv => write!(f, "seismic kv"),
            Self::ExternalLoads => write!(f, "external loads"),
            Self::ExternalLoadSlice { index } => write!(f, "slice of external load {}", index + 1),
            Self::ExternalLoad { index } => write!(f, "external load {}", index + 1),
            Self::Ground => write!(f, "ground"),
            Self::Layer { index } => write!(f, "layer {}", index + 1),
            Self::LayerTop { index } => write!(f, "top of layer {}", index + 1),
            Self::Bedrock => write!(f, "bedrock"),
            Self::PiezometricLine => write!(f, "piezometric line"),
            Self::Drawdown => write!(f, "drawdown"),
            Self::REnvelope { index } => write!(f, "R envelope of layer {index}"),
            Self::WaterUnitWeight => write!(f, "water unit weight"),
            Self::Surcharge { index } => write!(f, "surcharge {}", index + 1),
            Self::LineLoad { index } => write!(f, "line load {}", index + 1),
            Self::TensionCrackDepth => write!(f, "tension crack depth"),
            Self::TensionCrackWater => write!(f, "tension crack water depth"),
            Self::CircleCentre => write!(f, "circle centre"),
            Self::CircleMass => write!(f, "circle mass"),
            Self::CircleRadius => write!(f, "circle radius"),
            Self::Surface => write!(f, "slip surface"),
            Self::SurfaceVertex { index } => write!(f, "slip surface vertex {index}"),
            Self::DesignFactor { name } => write!(f, "partial factor {name}"),
            Self::Support { index, field } => {
                write!(f, "{} of support {}", field.name(), index + 1)
            }
            Self::MomentCentre => write!(f, "moment centre"),
            Self::Search => write!(f, "search"),
        }
    }
}

/// Input the slope solver cannot accept; `parameter` names the offending input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SlopeError {
    /// A number is outside its allowed range.
    #[error("{parameter}: {value} is out of range: allowed is {allowed}")]
    OutOfRange {
        /// The input at fault.
        parameter: SlopeParameter,
        /// The rejected value.
        value: f64,
        /// The allowed range in words.
        allowed: &'static str,
    },
    /// The slip circle does not cut a sliding mass out of the embankment.
    #[error("{parameter}: {reason}")]
    NoSlipMass {
        /// The input that has to change.
        parameter: SlopeParameter,
        /// What is wrong with the circle.
        reason: String,
    },
    /// Two inputs cannot be used together.
    #[error("{parameter}: {reason}")]
    Conflict {
        /// The input that has to change.
        parameter: SlopeParameter,
        /// Why.
        reason: String,
    },
}

/// Checks that `value` is finite and lies in `[min, max]` (`min_open` makes the lower end open).
pub(crate) fn check_range(
    parameter: SlopeParameter,
    value: f64,
    min: f64,
    min_open: bool,
    max: f64,
    allowed: &'static str,
) -> Result<f64, SlopeError> {
    let above_min = if min_open { value > min } else { value >= min };
    if value.is_finite() && above_min && value <= max {
        Ok(value)
    } else {
        Err(SlopeError::OutOfRange {
            parameter,
            value,
            allowed,
        })
    }
}
