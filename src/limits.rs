//! The service's limits on the size and magnitude of a request, in one place. They keep every
//! calculation within f64's room and within the solve time limit; the OpenAPI schema states the
//! same numbers.

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
/// Range of the interior-point tolerance of the arch programmes.
pub const SOLVER_TOLERANCE: (f64, f64) = (1e-12, 1e-4);
/// Range of the minimum-thickness tolerance (relative to the radius).
pub const THICKNESS_TOLERANCE: (f64, f64) = (1e-9, 1e-2);
/// Largest number of slices a request may ask for.
pub const MAX_SLICES: usize = 10_000;
/// Largest number of external loads in one request.
pub const MAX_EXTERNAL_LOADS: usize = 10_000;
/// Largest number of grid points along one axis of a search.
pub const MAX_GRID: usize = 101;
/// Largest nx·ny·slices of a search (its cost).
pub const MAX_GRID_SLICES: usize = 10_000_000;
/// Range of the relative slice tolerance of the slice refinement.
pub const SLICE_TOLERANCE: (f64, f64) = (1e-9, 0.1);

/// Most points in one polyline of a section (ground, layer top, bedrock, water line, surface).
pub const MAX_POLYLINE_POINTS: usize = 1000;
/// Most layers in a section.
pub const MAX_LAYERS: usize = 50;
/// Most surcharges, and most line loads, in a section.
pub const MAX_SECTION_LOADS: usize = 1000;
/// The unit weight of water when none is given (kN/m³).
pub const DEFAULT_WATER_UNIT_WEIGHT: f64 = 9.81;
