//! What a search stage of a slope analysis is asked: a section's search ([`SectionSearch`],
//! with its non-circular stage [`Noncircular`]) and the surfaces a search may answer
//! ([`Candidates`]).

use std::num::NonZeroUsize;
use std::time::Duration;

use crate::slope::section::search::CircleRegion;
use crate::slope::section::Section;
use crate::slope::spencer::Seismic;

/// A search for the critical circle of a section.
#[derive(Debug, Clone)]
pub struct SectionSearch {
    /// The section.
    pub section: Section,
    /// The centres and radii.
    pub region: CircleRegion,
    /// Whether the bounds were given (they then stay put).
    pub hard: bool,
    /// Slices per surface.
    pub slices: NonZeroUsize,
    /// Seismic coefficients.
    pub seismic: Seismic,
    /// With a non-circular stage: its polyline.
    pub noncircular: Option<Noncircular>,
}

impl SectionSearch {
    /// The search of the section seen from behind (x → −x).
    pub(super) fn mirrored(&self) -> Self {
        Self {
            section: self.section.mirrored(),
            region: CircleRegion {
                centres: self.region.centres.mirrored(),
                radii: self.region.radii.clone(),
            },
            ..self.clone()
        }
    }
}

/// The non-circular stage: a polyline of `vertices` points, moved from the best circle's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Noncircular {
    /// Vertices of the polyline.
    pub vertices: usize,
    /// The most the stage may spend (within the analysis' own budget).
    pub budget: Option<Duration>,
    /// The most trial surfaces the stage may evaluate: a budget that gives the same answer on
    /// any machine.
    pub max_evaluations: Option<usize>,
}

/// The surfaces a search may answer (model §6.4).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Candidates {
    /// Surfaces whose greatest depth below the ground is smaller are not candidates.
    pub min_depth: f64,
    /// Whether a circle that would cross the bedrock is not a candidate (otherwise it follows
    /// the bedrock: a composite surface).
    pub circles_only: bool,
    /// Whether a surface may enter or leave the ground beyond the section's x-range (the
    /// ground taken level there); otherwise it is no candidate. The simple slope's ground runs
    /// on level by definition.
    pub beyond_ground: bool,
}
