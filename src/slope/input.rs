//! The one validation of a Spencer request: JSON values → the solver's typed inputs. Every range
//! the API states is checked here (naming the field); what the solver's own constructors check
//! (a circle that cuts no slip mass, a soil without strength) comes back from them as a typed
//! parameter that [`crate::fields`] names.

use std::num::NonZeroUsize;

use thrustline_solver::slope::section::{Section, SectionProblem, SlipShape};
use thrustline_solver::slope::{
    Embankment, ExternalLoad, Seismic, SlipCircle, SlopeError, SlopeParameter, Soil,
};

use super::lines::polyline;
use super::methods::{interslice_function, methods_plan, MethodsAsked};
use super::request::{CircleDto, CompositeDto, MassDto, SearchDto, SpencerRequest};
use super::section::{search_region, section_from};
use super::simple_search::simple_search;
use super::strength::soil as soil_from;
use crate::error::ApiError;
use crate::limits::{
    CENTRE_HEIGHT, CIRCLE_MASS, FORCE, LENGTH, LOADS, LOWER_END_FACTOR, MAX_SLICES, MIN_DEPTH,
    RADIUS, SEISMIC_KH, SEISMIC_KV, SLICES,
};
use crate::validation::{count, count_within, finite, within};
use thrustline_solver::slope::analysis::{Analysed, Candidates, SectionSearch, SlopePlan, Target};
use thrustline_solver::slope::design::{Action, Design};

/// The ground and soil: a section, or the simple slope with its soil.
enum Ground {
    Simple(Embankment, Soil),
    Section(Box<Section>),
}

/// The validated parts of a request that do not depend on the slip surface (in design values
/// with a design check).
struct Parts {
    ground: Ground,
    design: Option<Design>,
    slices: NonZeroUsize,
    seismic: Seismic,
    external_loads: Vec<ExternalLoad>,
}

impl SpencerRequest {
    /// Validates the request into the analysis' plan.
    pub fn validate(&self) -> Result<SlopePlan, ApiError> {
        let parts = self.parts()?;
        let design = parts.design;
        let (slice_tolerance, relative_error) =
            super::checks::refinement(self, !parts.external_loads.is_empty())?;
        super::checks::one_surface(self)?;
        let mut candidates = Candidates::default();
        let target = if let Some(circle) = &self.circle {
            circle_target(circle, parts)?
        } else if let Some(points) = &self.surface {
            let line = polyline("surface", points)?;
            let centre = self
                .moment_centre
                .map(|c| {
                    finite("moment_centre", c[0])?;
                    finite("moment_centre", c[1]).map(|_| (c[0], c[1]))
                })
                .transpose()?;
            section_target(parts, SlipShape::Polyline(line), centre, (None, false))?
        } else if let Some(search) = &self.search {
            let (target, found) = search_target(search, parts)?;
            candidates = found;
            target
        } else {
            return Err(ApiError::invalid(
                "circle",
                "give a circle or a surface to analyse, or search ({} for automatic bounds) \
                 for the critical circle",
            ));
        };
        let (methods, per_method) = methods_plan(MethodsAsked {
            names: &self.methods,
            interslice_function: self.interslice_function.is_some(),
            per_method: self.search.as_ref().is_some_and(|s| s.per_method),
            classic: self.negative_effective_stress == Default::default(),
        })?;
        Ok(SlopePlan {
            target,
            per_method,
            slice_tolerance,
            relative_error,
            estimate_accuracy: true,
            max_slices: MAX_SLICES,
            curves: self.curves,
            methods,
            interslice_function: interslice_function(self.interslice_function.as_deref())?,
            negative_effective_stress: self.negative_effective_stress.into(),
            candidates,
            design,
        })
    }

    /// Validates everything but the slip surface.
    fn parts(&self) -> Result<Parts, ApiError> {
        let slices = count_within("slices", self.slices, SLICES)?;
        let design = self
            .design
            .as_ref()
            .map(super::design::design)
            .transpose()?;
        let ground = self.ground(design.as_ref())?;
        let seismic = match &self.seismic {
            Some(s) => Seismic::new(
                within("seismic.kh", s.kh, SEISMIC_KH)?,
                within("seismic.kv", s.kv, SEISMIC_KV)?,
            )?,
            None => Seismic::default(),
        };
        let external_loads = self.external_loads(&ground, design, slices)?;
        let slices = NonZeroUsize::new(slices)
            .ok_or_else(|| ApiError::invalid("slices", "must be at least 1"))?;
        Ok(Parts {
            ground,
            design,
            slices,
            seismic,
            external_loads,
        })
    }

    /// The ground and soil: a section, or the simple slope with its soil (in design values).
    fn ground(&self, design: Option<&Design>) -> Result<Ground, ApiError> {
        Ok(match (&self.section, &self.slope, &self.soil) {
            (Some(section), None, None) => {
                Ground::Section(Box::new(section_from(section, design)?))
            }
            (Some(_), _, _) => {
                return Err(ApiError::invalid(
                    if self.slope.is_some() {
                        "slope"
                    } else {
                        "soil"
                    },
                    "give either section, or slope and soil, not both",
                ))
            }
            (None, Some(slope), Some(soil)) => {
                let length = |field: &str, value: f64| within(field, value, LENGTH);
                let height = length("slope.height", slope.height)?;
                let slope_length = length("slope.length", slope.length)?;
                let soil = soil_from("soil", soil, soil.pore_pressure_ratio.unwrap_or(0.0))?;
                let soil = match design {
                    Some(d) => d.soil(soil)?,
                    None => soil,
                };
                Ground::Simple(Embankment::new(height, slope_length)?, soil)
            }
            (None, None, _) => {
                return Err(ApiError::invalid(
                    "slope",
                    "give the ground: slope and soil, or section",
                ))
            }
            (None, Some(_), None) => {
                return Err(ApiError::invalid("soil", "the slope needs its soil"))
            }
        })
    }

    /// The simple slope's per-slice loads, numbered within `slices` (in design values).
    fn external_loads(
        &self,
        ground: &Ground,
        design: Option<Design>,
        slices: usize,
    ) -> Result<Vec<ExternalLoad>, ApiError> {
        count_within("external_loads", self.external_loads.len(), LOADS)?;
        if matches!(ground, Ground::Section(_)) && !self.external_loads.is_empty() {
            return Err(ApiError::invalid(
                "external_loads",
                "are for the simple slope's slices: on a section use section.line_loads and \
                 section.surcharges",
            ));
        }
        self.external_loads
            .iter()
            .enumerate()
            .map(|(i, load)| {
                let field = |name: &str| format!("external_loads[{i}].{name}");
                // Per-slice loads are permanent and unfavourable in a design check.
                let k = design.map_or(1.0, |d| d.load_factor(Action::default()));
                let force = |name: &str, v: f64| within(&field(name), v, FORCE).map(|v| v * k);
                Ok(ExternalLoad {
                    slice: count(&field("slice"), load.slice, 1, slices)? - 1,
                    fx: force("fx", load.fx)?,
                    fy: force("fy", load.fy)?,
                    moment: force("moment", load.moment)?,
                    passive: false,
                })
            })
            .collect::<Result<Vec<_>, ApiError>>()
    }
}

/// A placed circle that cuts no mass names the relative centre the request gave.
fn relative_centre(error: SlopeError) -> ApiError {
    match error {
        SlopeError::NoSlipMass {
            parameter: SlopeParameter::CircleCentre,
            reason,
        } => ApiError::invalid(
            "circle.x, circle.y",
            format!("the centre (relative to the lower end) places no slip mass: {reason}"),
        ),
        other => other.into(),
    }
}

/// What a search may answer: `search.min_depth` (by default 2 % of `height`) and
/// `search.composite`.
fn search_candidates(search: &SearchDto, height: f64) -> Result<Candidates, ApiError> {
    let min_depth = match search.min_depth {
        Some(d) => within("search.min_depth", d, MIN_DEPTH)?,
        None => DEFAULT_MIN_DEPTH_OVER_HEIGHT * height,
    };
    Ok(Candidates {
        min_depth,
        circles_only: search.composite == CompositeDto::CirclesOnly,
        beyond_ground: search.beyond_ground,
    })
}

/// The default `search.min_depth` as a fraction of the height (model §6.4).
const DEFAULT_MIN_DEPTH_OVER_HEIGHT: f64 = 0.02;

/// A circle in either form: relative (the simple slope only) or absolute.
fn circle_target(circle: &CircleDto, parts: Parts) -> Result<Target, ApiError> {
    match (circle.x, circle.y, circle.centre, circle.radius) {
        (Some(x), Some(y), None, None) => match parts.ground {
            Ground::Simple(embankment, soil) => {
                let relative = SlipCircle {
                    x: finite("circle.x", x)?,
                    y: within("circle.y", y, CENTRE_HEIGHT)?,
                    lower_end_factor: within(
                        "circle.lower_end_factor",
                        circle.lower_end_factor.unwrap_or(0.0),
                        LOWER_END_FACTOR,
                    )?,
                };
                let problem = SectionProblem::new(
                    Section::simple(&embankment, soil)?,
                    relative.placed(embankment.height())?,
                    parts.slices,
                    parts.seismic,
                    None,
                )
                .map_err(relative_centre)?
                .with_slice_loads(parts.external_loads)?;
                Ok(Target::Surface(Analysed::Section(Box::new(problem))))
            }
            Ground::Section(_) => Err(ApiError::invalid(
                "circle",
                "on a section give the circle absolutely: centre [x, y] and radius",
            )),
        },
        (None, None, Some(centre), Some(radius)) if circle.lower_end_factor.is_none() => {
            let radius = within("circle.radius", radius, RADIUS)?;
            if !parts.external_loads.is_empty() {
                return Err(ApiError::invalid(
                    "external_loads",
                    "are for the relative circle's slices; with an absolute circle use a \
                     section's line_loads",
                ));
            }
            let shape = SlipShape::Circle {
                centre: (centre[0], centre[1]),
                radius,
            };
            let mass = match circle.mass {
                Some(MassDto::Index(k)) => Some(count_within("circle.mass", k, CIRCLE_MASS)? - 1),
                _ => None,
            };
            section_target(parts, shape, None, (mass, circle.beyond_ground))
        }
        (None, None, None, None) => Err(ApiError::invalid(
            "circle",
            "give x and y (relative to the lower end), or centre and radius (absolute)",
        )),
        (None, None, Some(_), None) => Err(ApiError::invalid(
            "circle.radius",
            "the absolute circle needs its radius",
        )),
        (None, None, None, Some(_)) => Err(ApiError::invalid(
            "circle.centre",
            "the absolute circle needs its centre [x, y]",
        )),
        (Some(_), None, ..) => Err(ApiError::invalid("circle.y", "the relative circle needs y")),
        (None, Some(_), ..) => Err(ApiError::invalid("circle.x", "the relative circle needs x")),
        _ => Err(ApiError::invalid(
            "circle",
            "give either x, y (and lower_end_factor) or centre and radius, not both",
        )),
    }
}

/// An absolute circle or a polyline on a section (the simple slope becomes the section
/// [(0, 0), (L, H)], continued level both ways, with its soil).
/// A circle's `mass` (from the left, from 0; `None`: the largest) is analysed. A surface that
/// leaves the section's x-range is refused naming `circle` or `surface`, unless `beyond_ground`
/// allows it (a circle's `beyond_ground`; a polyline's points are the user's own).
fn section_target(
    parts: Parts,
    shape: SlipShape,
    moment_centre: Option<(f64, f64)>,
    (mass, beyond_ground): (Option<usize>, bool),
) -> Result<Target, ApiError> {
    let field = match shape {
        SlipShape::Circle { .. } => "circle",
        SlipShape::Polyline(_) => "surface",
    };
    let section = match parts.ground {
        Ground::Section(section) => *section,
        Ground::Simple(embankment, soil) => Section::simple(&embankment, soil)?,
    };
    let problem = SectionProblem::new(section, shape, parts.slices, parts.seismic, moment_centre)?;
    let problem = match mass {
        Some(index) => problem.with_mass(index)?,
        None => problem,
    };
    if let (false, Some(((low, high), (first, last)))) = (beyond_ground, problem.beyond_ground()) {
        let circle = " (or circle.beyond_ground: true to take it as level there)";
        let allow = if field == "circle" { circle } else { "" };
        return Err(ApiError::invalid(
            field,
            format!(
                "the slip surface runs from x = {low:.4} to {high:.4}, beyond the section's \
                 ground (x = {first} … {last}): extend section.ground to where the surface \
                 ends{allow}"
            ),
        ));
    }
    Ok(Target::Surface(Analysed::Section(Box::new(problem))))
}

/// A search on the simple slope or a section, and what it may answer.
fn search_target(search: &SearchDto, parts: Parts) -> Result<(Target, Candidates), ApiError> {
    match parts.ground {
        Ground::Simple(embankment, soil) => {
            if !parts.external_loads.is_empty() {
                return Err(ApiError::invalid(
                    "external_loads",
                    "cannot be combined with search: loads are given per slice, and the slices \
                     change from circle to circle",
                ));
            }
            let target = simple_search(search, embankment, soil, parts.slices, parts.seismic)?;
            // The simple slope's ground runs on level both ways by definition.
            let candidates = Candidates {
                beyond_ground: true,
                ..search_candidates(search, embankment.height())?
            };
            Ok((target, candidates))
        }
        Ground::Section(section) => {
            let (low, top) = section
                .ground()
                .points()
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                    (a.min(p.1), b.max(p.1))
                });
            let candidates = search_candidates(search, top - low)?;
            let (region, hard, noncircular) = search_region(search, &section, parts.slices.get())?;
            let target = Target::SectionSearch(Box::new(SectionSearch {
                section: *section,
                region,
                hard,
                slices: parts.slices,
                seismic: parts.seismic,
                noncircular,
            }));
            Ok((target, candidates))
        }
    }
}
