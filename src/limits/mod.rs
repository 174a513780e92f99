//! The service's limits on the size and magnitude of a request, in one place. They keep every
//! calculation within f64's room and within the solve time limit. [`schema::SCHEMA_LIMITS`] is the
//! table the OpenAPI document is written from ([`schema`]); the checks read the same constants.

pub mod schema;

/// Largest number of voussoirs (or blocks) a request may ask for.
pub const MAX_VOUSSOIRS: usize = 10_000;
/// Smallest radius, height or length accepted (any unit): the scale where f64 still has room.
pub const MIN_LENGTH: f64 = 1e-9;
/// Largest radius, height, length or coordinate accepted.
pub const MAX_LENGTH: f64 = 1e9;
/// Largest unit weight or cohesion accepted (any unit).
pub const MAX_MAGNITUDE: f64 = 1e12;
/// Largest force, moment or interface limit accepted (any unit).
pub const MAX_FORCE: f64 = 1e30;
/// Largest number of live loads in one request.
pub const MAX_LOADS: usize = 10_000;
/// Largest base angle of a circular arch in degrees (strictly below 90°, where the springing
/// joint would be vertical).
pub const MAX_BASE_ANGLE_DEG: f64 = 89.999_999;
/// Largest Coulomb friction coefficient.
pub const MAX_FRICTION_COEFFICIENT: f64 = 1e6;
/// Largest number of slices a request may ask for.
pub const MAX_SLICES: usize = 10_000;
/// Largest number of grid points along one axis of a search.
pub const MAX_GRID: usize = 101;
/// Largest nx·ny·slices of a search (its cost).
pub const MAX_GRID_SLICES: usize = 10_000_000;

/// Most points in one polyline of a section (ground, layer top, bedrock, water line, surface).
pub const MAX_POLYLINE_POINTS: usize = 1000;
/// Most layers in a section.
pub const MAX_LAYERS: usize = 50;
/// Most surcharges, and most line loads, in a section.
pub const MAX_SECTION_LOADS: usize = 1000;
/// Most supports in a section.
pub const MAX_SUPPORTS: usize = 1000;
/// Most lines in one `POST /batch`.
pub const MAX_BATCH_LINES: usize = 10_000;
/// The unit weight of water when none is given (kN/m³).
pub const DEFAULT_WATER_UNIT_WEIGHT: f64 = 9.81;

/// The allowed range of a number: from `min` (excluded when `min_open`) to `max`, either end
/// absent when unbounded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// The least value, if any.
    pub min: Option<f64>,
    /// Whether `min` itself is excluded.
    pub min_open: bool,
    /// The largest value, if any.
    pub max: Option<f64>,
}

impl Range {
    /// min ≤ value ≤ max.
    pub const fn closed(min: f64, max: f64) -> Self {
        Self {
            min: Some(min),
            min_open: false,
            max: Some(max),
        }
    }

    /// min < value ≤ max.
    pub const fn above(min: f64, max: f64) -> Self {
        Self {
            min: Some(min),
            min_open: true,
            max: Some(max),
        }
    }

    /// min < value, no upper end.
    pub const fn greater_than(min: f64) -> Self {
        Self {
            min: Some(min),
            min_open: true,
            max: None,
        }
    }

    /// min ≤ value, no upper end.
    pub const fn at_least(min: f64) -> Self {
        Self {
            min: Some(min),
            min_open: false,
            max: None,
        }
    }

    /// Whether `value` is finite and in the range.
    pub fn contains(&self, value: f64) -> bool {
        let above = match (self.min, self.min_open) {
            (None, _) => true,
            (Some(min), true) => value > min,
            (Some(min), false) => value >= min,
        };
        value.is_finite() && above && self.max.is_none_or(|max| value <= max)
    }
}

/// The allowed range of an integer, or of the number of items of a list.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Count {
    /// The least.
    pub min: usize,
    /// The most.
    pub max: usize,
}

impl Count {
    /// min ≤ n ≤ max.
    pub const fn new(min: usize, max: usize) -> Self {
        Self { min, max }
    }
}

/// What a schema property is limited by.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Limit {
    /// A number's range.
    Number(Range),
    /// An integer's range.
    Integer(Count),
    /// A list's number of items.
    Items(Count),
}

/// A radius, height or length.
pub const LENGTH: Range = Range::closed(MIN_LENGTH, MAX_LENGTH);
/// A thickness or other size that must be positive.
pub const POSITIVE_LENGTH: Range = Range::above(0.0, MAX_LENGTH);
/// An arch's thickness (below its diameter, checked against the radius by the solver).
pub const THICKNESS: Range = Range::above(0.0, 2.0 * MAX_LENGTH);
/// A coordinate.
pub const COORDINATE: Range = Range::closed(-MAX_LENGTH, MAX_LENGTH);
/// A unit weight.
pub const UNIT_WEIGHT: Range = Range::above(0.0, MAX_MAGNITUDE);
/// A unit weight that may be zero (a weightless fill).
pub const UNIT_WEIGHT_OR_ZERO: Range = Range::closed(0.0, MAX_MAGNITUDE);
/// A cohesion, pressure or strength that may be zero.
pub const STRESS: Range = Range::closed(0.0, MAX_MAGNITUDE);
/// A strength that must be positive.
pub const POSITIVE_STRESS: Range = Range::above(0.0, MAX_MAGNITUDE);
/// A force or moment.
pub const FORCE: Range = Range::closed(-MAX_FORCE, MAX_FORCE);
/// A line load's force on a section.
pub const LINE_LOAD: Range = Range::closed(-MAX_MAGNITUDE, MAX_MAGNITUDE);
/// A soil's friction angle in degrees.
pub const FRICTION_ANGLE_DEG: Range = Range::closed(0.0, 89.9);
/// A pore-pressure ratio r_u.
pub const PORE_PRESSURE_RATIO: Range = Range::closed(0.0, 1.0);
/// The horizontal seismic coefficient.
pub const SEISMIC_KH: Range = Range::closed(-10.0, 10.0);
/// The vertical seismic coefficient (above −1: gravity keeps acting).
pub const SEISMIC_KV: Range = Range::closed(-0.99, 10.0);
/// A circular arch's base angle in degrees.
pub const BASE_ANGLE_DEG: Range = Range::above(-90.0, MAX_BASE_ANGLE_DEG);
/// A Coulomb friction coefficient.
pub const FRICTION: Range = Range::closed(0.0, MAX_FRICTION_COEFFICIENT);
/// The interior-point tolerance of the arch programmes.
pub const SOLVER_TOLERANCE: Range = Range::closed(1e-12, 1e-4);
/// The minimum-thickness tolerance, relative to the radius.
pub const THICKNESS_TOLERANCE: Range = Range::closed(1e-9, 1e-2);
/// The accuracy a slope request may ask for (the estimate's floor: a kink of the ground moving
/// within a slice changes F by ~1e-8 from one slice count to the next).
pub const RELATIVE_ERROR: Range = Range::closed(1e-7, 0.1);
/// The relative slice tolerance of the slice refinement.
pub const SLICE_TOLERANCE: Range = Range::closed(1e-9, 0.1);
/// A lower limit of an interface resultant (a tensile strength: ≤ 0).
pub const LOWER_LIMIT: Range = Range::closed(-MAX_FORCE, 0.0);
/// An upper limit of an interface resultant (≥ 0).
pub const UPPER_LIMIT: Range = Range::closed(0.0, MAX_FORCE);
/// The fill's dispersal angle, and the passive restraint's friction angle, in degrees.
pub const FILL_ANGLE_DEG: Range = Range::closed(0.0, 60.0);
/// The share of the passive pressure mobilised.
pub const MOBILISATION: Range = Range::closed(0.0, 1.0);
/// A lower-end factor F_e of the simple slope's circles.
pub const LOWER_END_FACTOR: Range = Range::at_least(0.0);
/// The lower-end factor a search starts from.
pub const SEARCH_LOWER_END_FACTOR: Range = Range::closed(0.0, 100.0);
/// The largest lower-end factor a search may move to.
pub const LOWER_END_FACTOR_MAX: Range = Range::above(0.0, 100.0);
/// A non-circular search's time budget in milliseconds.
pub const TIME_BUDGET_MS: Range = Range::above(0.0, 6e5);
/// A circle's radius on a section.
pub const RADIUS: Range = Range::above(0.0, MAX_LENGTH);
/// A circle's centre height above its lower end (the simple slope's relative circle).
pub const CENTRE_HEIGHT: Range = Range::greater_than(0.0);
/// The length of a road load's patch or an axle's contact.
pub const PATCH_LENGTH: Range = Range::closed(0.0, MAX_LENGTH);
/// The least depth of a search's candidate surfaces below the ground.
pub const MIN_DEPTH: Range = Range::closed(0.0, MAX_LENGTH);
/// A tension crack's depth.
pub const CRACK_DEPTH: Range = Range::above(0.0, MAX_LENGTH);
/// The water in a tension crack (at most its depth, checked beside).
pub const CRACK_WATER_DEPTH: Range = Range::closed(0.0, MAX_LENGTH);

/// A Hoek–Brown geological strength index.
pub const GSI: Range = Range::closed(5.0, 100.0);
/// A Hoek–Brown m_i of intact rock.
pub const HOEK_BROWN_MI: Range = Range::above(0.0, 100.0);
/// A Hoek–Brown disturbance factor D.
pub const DISTURBANCE: Range = Range::closed(0.0, 1.0);
/// A power curve's exponent b (concave or straight).
pub const POWER_EXPONENT: Range = Range::above(0.0, 1.0);
/// A shift of normal stress, a normal stress on an envelope, or a pore pressure of a grid
/// (negative: suction).
pub const SIGNED_STRESS: Range = Range::closed(-MAX_MAGNITUDE, MAX_MAGNITUDE);
/// The factor h_u on a piezometric line's head.
pub const HEAD_FACTOR: Range = Range::closed(0.0, 1.0);

/// Slices of a slip surface.
pub const SLICES: Count = Count::new(1, MAX_SLICES);

/// `circle.mass` as an index: the k-th mass from the left a circle cuts out of the ground.
pub const CIRCLE_MASS: Count = Count::new(1, 1000);
/// Voussoirs of a circular arch, blocks of a chain or an assembly.
pub const BLOCKS: Count = Count::new(1, MAX_VOUSSOIRS);
/// Rings of a circular arch.
pub const RINGS: Count = Count::new(1, 16);
/// Spans of a circular arch on piers.
pub const SPANS: Count = Count::new(1, 20);
/// Planes of the crushing curve a programme starts from.
pub const CRUSHING_PLANES: Count = Count::new(2, 256);
/// Stops of a rolling load.
pub const ROLLING_POSITIONS: Count = Count::new(1, 1001);
/// Axles of a rolling load.
pub const AXLES: Count = Count::new(1, 20);
/// Grid points along one axis of a search.
pub const GRID_POINTS: Count = Count::new(2, MAX_GRID);
/// Radii per centre of a section's search.
pub const RADII: Count = Count::new(1, MAX_GRID);
/// Vertices of a non-circular search's polyline.
pub const VERTICES: Count = Count::new(4, 40);
/// Trial surfaces a non-circular search may evaluate.
pub const EVALUATIONS: Count = Count::new(1, 1_000_000);
/// Points of a polyline of a section or a slip surface.
pub const POLYLINE_POINTS: Count = Count::new(1, MAX_POLYLINE_POINTS);
/// Points of a shear–normal strength envelope.
pub const ENVELOPE_POINTS: Count = Count::new(2, 1000);
/// Points of a pore-pressure grid.
pub const PORE_GRID_POINTS: Count = Count::new(3, 10_000);
/// Layers of a section.
pub const LAYERS: Count = Count::new(1, MAX_LAYERS);
/// Surcharges, and line loads, of a section.
pub const SECTION_LOADS: Count = Count::new(0, MAX_SECTION_LOADS);
/// Supports (reinforcement) in a slope section.
pub const SLOPE_SUPPORTS: Count = Count::new(0, MAX_SUPPORTS);
/// Live loads on blocks, road loads, external loads on slices.
pub const LOADS: Count = Count::new(0, MAX_LOADS);
/// Corners of an assembly's polygon.
pub const POLYGON_CORNERS: Count = Count::new(3, 256);
/// Interfaces given friction and cohesion of their own.
pub const INTERFACE_OVERRIDES: Count = Count::new(0, MAX_LOADS);
/// Layers of an arch's fill.
pub const FILL_LAYERS: Count = Count::new(1, 20);
/// Points of a measured intrados.
pub const INTRADOS_POINTS: Count = Count::new(3, MAX_VOUSSOIRS);
/// A profile's rise, or a pointed arch's radius, as a multiple of its span.
pub const RISE_PER_SPAN: Range = Range::closed(1e-3, 100.0);
/// Supports of an assembly.
pub const SUPPORTS: Count = Count::new(1, 1000);
/// Points of a Morgenstern–Price inter-slice function.
pub const INTERSLICE_POINTS: Count = Count::new(2, 1000);
/// Methods answered beside Spencer's.
pub const METHODS: Count = Count::new(0, 4);

/// Most samples of a probabilistic study (each one analysis: the time limit bounds the study).
pub const MAX_STUDY_SAMPLES: usize = 100_000;
/// Most sampled values of a study (samples × variables): its memory, 16 MB of f64.
pub const MAX_STUDY_VALUES: usize = 2_000_000;
/// Samples of a probabilistic study.
pub const STUDY_SAMPLES: Count = Count::new(1, MAX_STUDY_SAMPLES);
/// Variables of a study.
pub const STUDY_VARIABLES: Count = Count::new(1, 20);
/// Bars of a study's histogram.
pub const HISTOGRAM_BINS: Count = Count::new(1, 200);
/// Values of one sensitivity variable.
pub const SENSITIVITY_POINTS: Count = Count::new(2, 101);
/// A correlation coefficient between two variables (±1 makes the matrix singular: refused as
/// not positive definite).
pub const CORRELATION: Range = Range::closed(-1.0, 1.0);
