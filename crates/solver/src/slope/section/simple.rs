//! Sections built from other sections or from the simple embankment.

use super::model::{Drawdown, Layer, LevelTable, LineLoad, Section, SectionParts, Surcharge};
use super::polyline::Polyline;
use super::water::Water;
use crate::slope::error::{SlopeError, SlopeParameter};
use crate::slope::spencer::Soil;
use crate::slope::strength::Strength;

impl Section {
    /// The simple embankment as a section: the ground (0, 0)–(L, H), continued level both ways,
    /// one soil with its r_u (the service's simple form and its search are this section).
    pub fn simple(embankment: &crate::slope::Embankment, soil: Soil) -> Result<Self, SlopeError> {
        let ground = Polyline::new(vec![(0.0, 0.0), (embankment.length(), embankment.height())])
            .map_err(|e| SlopeError::NoSlipMass {
                parameter: SlopeParameter::Height,
                reason: e.to_string(),
            })?;
        let section = Self::new(one_soil(ground, soil, Some(soil.pore_pressure_ratio())))?;
        Ok(Self {
            level_beyond_ends: true,
            ..section
        })
    }

    /// A section of one soil under `ground` (no water, loads or crack): the commonest scene,
    /// and the fixtures' (water's unit weight 9.81).
    pub fn of_one_soil(ground: Vec<(f64, f64)>, soil: Soil) -> Result<Self, SlopeError> {
        let ground = Polyline::new(ground).map_err(|e| SlopeError::NoSlipMass {
            parameter: SlopeParameter::Surface,
            reason: e.to_string(),
        })?;
        Self::new(one_soil(ground, soil, None))
    }

    /// Whether the ground rises towards the left: its left end higher than its right, or, with
    /// both ends level, more of its relief (the area above its lowest point) left of its
    /// middle. Exactly one of a section and its mirror image rises to the left, unless the
    /// ground is symmetric; a search runs in the frame where it does not, so that a section and
    /// its mirror image are searched alike (model §14).
    pub fn rises_to_the_left(&self) -> bool {
        let p = self.ground.points();
        let (first, last) = (p[0], p[p.len() - 1]);
        if first.1 != last.1 {
            return first.1 > last.1;
        }
        let low = p.iter().fold(f64::INFINITY, |m, q| m.min(q.1));
        let (mut area, mut moment) = (0.0, 0.0);
        for w in p.windows(2) {
            let ((x0, y0), (x1, y1)) = (w[0], w[1]);
            let (h0, h1) = (y0 - low, y1 - low);
            area += 0.5 * (h0 + h1) * (x1 - x0);
            moment += (x1 - x0) / 6.0 * (x0 * (2.0 * h0 + h1) + x1 * (h0 + 2.0 * h1));
        }
        area > 0.0 && moment < 0.5 * (first.0 + last.0) * area
    }

    /// The section seen from behind (x → −x).
    pub(crate) fn mirrored(&self) -> Self {
        let line = |l: &Option<Polyline>| l.as_ref().map(Polyline::mirrored);
        Self {
            ground: self.ground.mirrored(),
            layers: self
                .layers
                .iter()
                .map(|l| Layer {
                    top: line(&l.top),
                    piezometric_line: l.piezometric_line.as_ref().map(|w| w.mirrored()),
                    ..l.clone()
                })
                .collect(),
            bedrock: line(&self.bedrock),
            piezometric_line: line(&self.piezometric_line),
            water_unit_weight: self.water_unit_weight,
            surcharges: self
                .surcharges
                .iter()
                .map(|s| Surcharge {
                    x_start: -s.x_end,
                    x_end: -s.x_start,
                    pressure: s.pressure_end,
                    pressure_end: s.pressure,
                })
                .collect(),
            supports: self.supports.iter().map(|s| s.mirrored()).collect(),
            line_loads: self
                .line_loads
                .iter()
                .map(|l| LineLoad {
                    x: -l.x,
                    fx: -l.fx,
                    fy: l.fy,
                })
                .collect(),
            tension_crack: self.tension_crack,
            water: self.water.mirrored(),
            envelopes: self.envelopes.clone(),
            bends: Vec::new(),
            levels: LevelTable::default(),
            ponded: Vec::new(),
            level_beyond_ends: self.level_beyond_ends,
            drawdown: self.drawdown.as_ref().map(|d| {
                Box::new(Drawdown {
                    before: d.before.mirrored(),
                    envelopes: d.envelopes.clone(),
                })
            }),
            other_water_line: line(&self.other_water_line),
        }
        .with_bends()
    }
}

/// The parts of a section of one soil under `ground`, with its own r_u when given.
fn one_soil(ground: Polyline, soil: Soil, pore_pressure_ratio: Option<f64>) -> SectionParts {
    SectionParts {
        ground,
        layers: vec![Layer {
            top: None,
            soil,
            pore_pressure_ratio,
            strength: Strength::MohrCoulomb,
            piezometric_line: None,
        }],
        bedrock: None,
        piezometric_line: None,
        water_unit_weight: 9.81,
        surcharges: Vec::new(),
        line_loads: Vec::new(),
        tension_crack: None,
        supports: Vec::new(),
        water: Water::default(),
    }
}
