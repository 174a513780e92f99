//! The validation of a `section` (model §4.1) into the solver's [`Section`], and of a `surface`:
//! every point and number checked, each failure naming its field path.

use std::time::Duration;

use thrustline_solver::slope::analysis::Noncircular;
use thrustline_solver::slope::circles::CentreGrid;
use thrustline_solver::slope::section::search::{CircleRegion, Radii};
use thrustline_solver::slope::section::{
    Layer, LineLoad, Polyline, Section, SectionParts, Surcharge, TensionCrack,
};

use super::design::action;
use super::lines::polyline;
use super::request::{Coordinates, SearchDto, SearchShapeDto, SectionDto};
use super::strength::layer_soil;
use super::water::{pore_grid, water_line};
use crate::error::ApiError;
use crate::limits::{
    COORDINATE, CRACK_DEPTH, DEFAULT_WATER_UNIT_WEIGHT, EVALUATIONS, GRID_POINTS, LAYERS,
    LINE_LOAD, MAX_GRID_SLICES, PORE_PRESSURE_RATIO, RADII, RADIUS, SECTION_LOADS, STRESS,
    TIME_BUDGET_MS, UNIT_WEIGHT, VERTICES,
};
use crate::validation::{count_within, number, within};
use thrustline_solver::slope::design::Design;
use thrustline_solver::slope::section::{Hu, Water};

/// Radii per centre when none are given.
const DEFAULT_RADII: usize = 10;

/// A search on the simple slope: the options only a section's search has are refused, each
/// naming its field (none is silently ignored).
pub fn refuse_section_only(search: &SearchDto) -> Result<(), ApiError> {
    if search.beyond_ground {
        return Err(ApiError::invalid(
            "search.beyond_ground",
            "is for a search over a section; the simple slope's ground runs on level both ways \
             by definition",
        ));
    }
    let section_only = [
        ("search.radius_min", search.radius_min.is_some()),
        ("search.radius_max", search.radius_max.is_some()),
        ("search.nr", search.nr.is_some()),
        (
            "search.tangent_elevations",
            search.tangent_elevations.is_some(),
        ),
    ];
    if let Some((field, _)) = section_only.iter().find(|f| f.1) {
        return Err(ApiError::invalid(
            *field,
            "is for a search over a section; on the simple slope the radius follows from the \
             centre and the lower end",
        ));
    }
    let noncircular = [
        (
            "search.shape",
            search.shape == Some(SearchShapeDto::Noncircular),
        ),
        ("search.vertices", search.vertices.is_some()),
        ("search.time_budget_ms", search.time_budget_ms.is_some()),
        ("search.max_evaluations", search.max_evaluations.is_some()),
    ];
    if let Some((field, _)) = noncircular.iter().find(|f| f.1) {
        return Err(ApiError::invalid(
            *field,
            "is for a search over a section: give the slope as a section (its ground and one \
             layer) to search for a non-circular surface",
        ));
    }
    Ok(())
}

/// The region of a search over a section, whether its bounds were given (hard), and a
/// non-circular search's polyline.
pub fn search_region(
    search: &SearchDto,
    section: &Section,
    slices: usize,
) -> Result<(CircleRegion, bool, Option<Noncircular>), ApiError> {
    let noncircular = noncircular(search)?;
    if search.lower_end_factor != 0.0 || search.lower_end_factor_max.is_some() {
        return Err(ApiError::invalid(
            "search.lower_end_factor",
            "is for the simple slope; on a section the circles' ends follow from the centre \
             and radius",
        ));
    }
    let nx = count_within("search.nx", search.nx, GRID_POINTS)?;
    let ny = count_within("search.ny", search.ny, GRID_POINTS)?;
    let nr = count_within("search.nr", search.nr.unwrap_or(DEFAULT_RADII), RADII)?;
    let coordinate =
        |field: &str, v: Option<f64>| v.map(|v| within(field, v, COORDINATE)).transpose();
    let radii = radii(search, nr)?;
    let per_centre = match &radii {
        Radii::Tangent(ys) => ys.len(),
        Radii::Range { count, .. } | Radii::Automatic { count } => *count,
    };
    let cost = nx * ny * per_centre * slices;
    if cost > MAX_GRID_SLICES {
        return Err(ApiError::invalid(
            "search",
            format!(
                "nx·ny·radii·slices = {cost} is out of range: allowed is at most \
                 {MAX_GRID_SLICES} (fewer grid points, radii or slices)"
            ),
        ));
    }
    let automatic = CircleRegion::automatic(section, nx, ny, per_centre);
    let bounds = [
        coordinate("search.x_min", search.x_min)?,
        coordinate("search.x_max", search.x_max)?,
        coordinate("search.y_min", search.y_min)?,
        coordinate("search.y_max", search.y_max)?,
    ];
    let hard = bounds.iter().any(Option::is_some);
    let around = automatic.centres;
    let centres = CentreGrid {
        x_min: bounds[0].unwrap_or(around.x_min),
        x_max: bounds[1].unwrap_or(around.x_max),
        y_min: bounds[2].unwrap_or(around.y_min),
        y_max: bounds[3].unwrap_or(around.y_max),
        nx,
        ny,
    };
    if centres.x_max <= centres.x_min {
        return Err(ApiError::invalid(
            "search.x_max",
            format!("must be greater than search.x_min ({})", centres.x_min),
        ));
    }
    if centres.y_max <= centres.y_min {
        return Err(ApiError::invalid(
            "search.y_max",
            format!("must be greater than search.y_min ({})", centres.y_min),
        ));
    }
    let region = CircleRegion { centres, radii };
    Ok((region, hard, noncircular))
}

/// The non-circular stage of a search, when its shape asks for one.
fn noncircular(search: &SearchDto) -> Result<Option<Noncircular>, ApiError> {
    Ok(match search.shape.unwrap_or_default() {
        SearchShapeDto::Circular if search.vertices.is_some() => {
            return Err(ApiError::invalid(
                "search.vertices",
                "is for shape: noncircular",
            ))
        }
        SearchShapeDto::Circular if search.time_budget_ms.is_some() => {
            return Err(ApiError::invalid(
                "search.time_budget_ms",
                "is for shape: noncircular",
            ))
        }
        SearchShapeDto::Circular if search.max_evaluations.is_some() => {
            return Err(ApiError::invalid(
                "search.max_evaluations",
                "is for shape: noncircular",
            ))
        }
        SearchShapeDto::Circular => None,
        SearchShapeDto::Noncircular => Some(Noncircular {
            max_evaluations: search
                .max_evaluations
                .map(|n| count_within("search.max_evaluations", n, EVALUATIONS))
                .transpose()?,
            vertices: count_within("search.vertices", search.vertices.unwrap_or(12), VERTICES)?,
            budget: search
                .time_budget_ms
                .map(|t| within("search.time_budget_ms", t, TIME_BUDGET_MS))
                .transpose()?
                .map(|t| Duration::from_secs_f64(t / 1e3)),
        }),
    })
}

/// The radii at each centre: automatic, a range, or tangent to given elevations.
fn radii(search: &SearchDto, nr: usize) -> Result<Radii, ApiError> {
    let radius = |field: &str, v: Option<f64>| v.map(|v| within(field, v, RADIUS)).transpose();
    Ok(
        match (
            radius("search.radius_min", search.radius_min)?,
            radius("search.radius_max", search.radius_max)?,
            &search.tangent_elevations,
        ) {
            (None, None, None) => Radii::Automatic { count: nr },
            (Some(min), Some(max), None) if max >= min => Radii::Range {
                min,
                max,
                count: nr,
            },
            (Some(_), Some(_), None) => {
                return Err(ApiError::invalid(
                    "search.radius_max",
                    "must be at least search.radius_min",
                ))
            }
            (None, None, Some(ys)) => {
                count_within("search.tangent_elevations", ys.len(), RADII)?;
                for (i, &y) in ys.iter().enumerate() {
                    within(&format!("search.tangent_elevations[{i}]"), y, COORDINATE)?;
                }
                Radii::Tangent(ys.clone())
            }
            (_, _, Some(_)) => {
                return Err(ApiError::invalid(
                    "search.tangent_elevations",
                    "give either tangent_elevations or radius_min and radius_max",
                ))
            }
            (Some(_), None, None) => {
                return Err(ApiError::invalid(
                    "search.radius_max",
                    "give it with radius_min",
                ))
            }
            (None, Some(_), None) => {
                return Err(ApiError::invalid(
                    "search.radius_min",
                    "give it with radius_max",
                ))
            }
        },
    )
}

/// The section as the solver takes it.
pub fn section_from(dto: &SectionDto, design: Option<&Design>) -> Result<Section, ApiError> {
    let ground = polyline("section.ground", &dto.ground)?;
    let layers = layers(dto)?;
    let line = |field: &str, points: &Option<Vec<Coordinates>>| {
        points.as_ref().map(|p| polyline(field, p)).transpose()
    };
    let (piezometric_line, hu) = match (&dto.piezometric_line, super::drawdown::after_line(dto)?) {
        (_, Some(after)) => (
            Some(polyline("section.drawdown.after", after)?),
            Hu::default(),
        ),
        (Some(w), None) => {
            let w = water_line("section.piezometric_line", w)?;
            (Some(w.line), w.hu)
        }
        (None, None) => (None, Hu::default()),
    };
    let water_unit_weight = within(
        "section.water_unit_weight",
        dto.water_unit_weight.unwrap_or(DEFAULT_WATER_UNIT_WEIGHT),
        UNIT_WEIGHT,
    )?;
    count_within("section.surcharges", dto.surcharges.len(), SECTION_LOADS)?;
    count_within("section.line_loads", dto.line_loads.len(), SECTION_LOADS)?;
    let surcharges = surcharges(dto)?;
    let line_loads = dto
        .line_loads
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let field = |name: &str| format!("section.line_loads[{i}].{name}");
            Ok(LineLoad {
                x: within(&field("x"), l.x, COORDINATE)?,
                fx: within(&field("fx"), l.fx, LINE_LOAD)?,
                fy: within(&field("fy"), l.fy, LINE_LOAD)?,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()?;
    on_the_ground(&ground, &line_loads)?;
    let tension_crack = dto
        .tension_crack
        .as_ref()
        .map(|c| {
            let depth = within("section.tension_crack.depth", c.depth, CRACK_DEPTH)?;
            let water_depth = number(
                "section.tension_crack.water_depth",
                c.water_depth,
                0.0,
                false,
                depth,
            )?;
            Ok::<_, ApiError>(TensionCrack { depth, water_depth })
        })
        .transpose()?;
    let parts = SectionParts {
        ground,
        layers,
        bedrock: line("section.bedrock", &dto.bedrock)?,
        piezometric_line,
        water_unit_weight,
        surcharges,
        line_loads,
        tension_crack,
        supports: super::supports::supports(&dto.supports)?,
        water: Water {
            hu,
            grid: dto.pore_pressure_grid.as_ref().map(pore_grid).transpose()?,
        },
    };
    // The design values, once: soils and loads by their actions.
    let parts = match design {
        Some(design) => in_design_values(parts, dto, design)?,
        None => parts,
    };
    super::drawdown::with_drawdown(Section::new(parts)?, dto, design)
}

/// The layers, each with its soil, strength model and own water line.
fn layers(dto: &SectionDto) -> Result<Vec<Layer>, ApiError> {
    count_within("section.layers", dto.layers.len(), LAYERS)?;
    dto.layers
        .iter()
        .enumerate()
        .map(|(i, layer)| {
            let prefix = format!("section.layers[{i}]");
            let ratio = layer
                .soil
                .pore_pressure_ratio
                .map(|r| {
                    within(
                        &format!("{prefix}.soil.pore_pressure_ratio"),
                        r,
                        PORE_PRESSURE_RATIO,
                    )
                })
                .transpose()?;
            let (soil, strength) = layer_soil(&format!("{prefix}.soil"), &layer.soil)?;
            Ok(Layer {
                top: layer
                    .top
                    .as_ref()
                    .map(|t| polyline(&format!("{prefix}.top"), t))
                    .transpose()?,
                soil,
                pore_pressure_ratio: ratio,
                strength,
                piezometric_line: layer
                    .piezometric_line
                    .as_ref()
                    .map(|w| water_line(&format!("{prefix}.piezometric_line"), w))
                    .transpose()?,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()
}

/// The section's parts in a design check's values (each load by its action).
fn in_design_values(
    parts: SectionParts,
    dto: &SectionDto,
    design: &Design,
) -> Result<SectionParts, ApiError> {
    let surcharges: Vec<_> = dto
        .surcharges
        .iter()
        .map(|s| action(s.action, s.favourable))
        .collect();
    let line_loads: Vec<_> = dto
        .line_loads
        .iter()
        .map(|l| action(l.action, l.favourable))
        .collect();
    Ok(design.section(parts, &surcharges, &line_loads)?)
}

/// The surcharges on a section's ground, each over x_start < x_end.
fn surcharges(dto: &SectionDto) -> Result<Vec<Surcharge>, ApiError> {
    dto.surcharges
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let field = |name: &str| format!("section.surcharges[{i}].{name}");
            let x_start = within(&field("x_start"), s.x_start, COORDINATE)?;
            let x_end = within(&field("x_end"), s.x_end, COORDINATE)?;
            if x_end <= x_start {
                return Err(ApiError::invalid(
                    field("x_end"),
                    "must be greater than x_start",
                ));
            }
            let pressure = within(&field("pressure"), s.pressure, STRESS)?;
            let pressure_end = s
                .pressure_end
                .map(|p| within(&field("pressure_end"), p, STRESS))
                .transpose()?
                .unwrap_or(pressure);
            Ok(Surcharge {
                x_start,
                x_end,
                pressure,
                pressure_end,
            })
        })
        .collect::<Result<Vec<_>, ApiError>>()
}

/// A line load beyond the ground as stated would act on its level continuation, which the
/// section does not describe: refused rather than placed there silently.
fn on_the_ground(ground: &Polyline, line_loads: &[LineLoad]) -> Result<(), ApiError> {
    let (first, last) = ground.x_range();
    match line_loads
        .iter()
        .enumerate()
        .find(|(_, l)| l.x < first || l.x > last)
    {
        Some((i, l)) => Err(ApiError::invalid(
            format!("section.line_loads[{i}].x"),
            format!(
                "{} lies beyond the ground (x = {first} … {last}): extend section.ground to \
                 where the load stands",
                l.x
            ),
        )),
        None => Ok(()),
    }
}
