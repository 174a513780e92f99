//! The layers of a section as filled areas for the drawing: layer k holds the ground at or
//! below its top and above the next layer's top (model §4.1's soil rule; validation keeps each
//! top at or below the one before it, so the next top bounds every later one).

use thrustline_solver::slope::section::{Polyline, Section};

/// Fill colours of the layers, top down (repeated beyond six).
pub const LAYER_COLOURS: [&str; 6] = [
    "#6d4c41", "#1565c0", "#2e7d32", "#6a1b9a", "#ef6c00", "#00838f",
];

/// One layer's area: the outline (upper edge left to right, lower edge back), its colour and
/// its legend entry.
pub struct Fill {
    pub polygon: Vec<(f64, f64)>,
    pub colour: &'static str,
    pub label: String,
}

/// The layers of `section` between x = left and right, down to y = bottom; layers with no
/// area there are left out.
pub fn layer_fills(section: &Section, left: f64, right: f64, bottom: f64) -> Vec<Fill> {
    let ground = section.ground();
    let tops: Vec<&Polyline> = std::iter::once(ground)
        .chain(
            section
                .layers()
                .iter()
                .skip(1)
                .filter_map(|l| l.top.as_ref()),
        )
        .collect();
    // Every line is straight between the section's bends: the edges are exact through these x.
    let mut xs: Vec<f64> = vec![left, right];
    xs.extend(section.bends().iter().filter(|&&x| x > left && x < right));
    xs.sort_by(f64::total_cmp);
    let mut fills = Vec::new();
    for (k, layer) in section.layers().iter().enumerate() {
        let upper = |x: f64| tops[k].y_at(x).min(ground.y_at(x));
        let lower = |x: f64| {
            let floor = tops.get(k + 1).map_or(bottom, |t| t.y_at(x).max(bottom));
            floor.min(upper(x))
        };
        let area: f64 = xs
            .windows(2)
            .map(|w| {
                let h = |x: f64| upper(x) - lower(x);
                0.5 * (w[1] - w[0]) * (h(w[0]) + h(w[1]))
            })
            .sum();
        if area <= 0.0 {
            continue;
        }
        let mut polygon: Vec<(f64, f64)> = xs.iter().map(|&x| (x, upper(x))).collect();
        polygon.extend(xs.iter().rev().map(|&x| (x, lower(x))));
        fills.push(Fill {
            polygon,
            colour: LAYER_COLOURS[k % LAYER_COLOURS.len()],
            label: format!(
                "layer {}: γ = {}, {}{}",
                k + 1,
                crate::svg::shown(layer.soil.unit_weight()),
                super::strength::describe(layer),
                section.r_envelope(k).map_or(String::new(), |r| format!(
                    "; undrained in the drawdown: R envelope c_R = {}, φ_R = {}°",
                    crate::svg::shown(r.cohesion),
                    crate::svg::shown(r.friction_angle_rad.to_degrees())
                ))
            ),
        });
    }
    fills
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use thrustline_solver::slope::section::{Layer, SectionParts};
    use thrustline_solver::slope::Soil;

    use super::*;

    fn line(points: &[(f64, f64)]) -> Polyline {
        Polyline::new(points.to_vec()).unwrap()
    }

    fn layer(top: Option<Polyline>) -> Layer {
        Layer {
            top,
            soil: Soil::new(20.0, 5.0, 30.0, 0.0).unwrap(),
            pore_pressure_ratio: None,
            strength: thrustline_solver::slope::strength::Strength::MohrCoulomb,
            piezometric_line: None,
        }
    }

    /// Shoelace area of a simple polygon.
    fn area(p: &[(f64, f64)]) -> f64 {
        let n = p.len();
        0.5 * (0..n)
            .map(|i| p[i].0 * p[(i + 1) % n].1 - p[(i + 1) % n].0 * p[i].1)
            .sum::<f64>()
            .abs()
    }

    #[test]
    fn layers_tile_the_ground_and_each_has_its_area_by_hand() {
        // Ground 0 → 10 over x = 0…20 (level beyond), a level top at y = 4 and a top sloping
        // from −2 to 2 that meets it nowhere; bottom −10, from x = −10 to 30.
        let parts = SectionParts {
            ground: line(&[(0.0, 0.0), (20.0, 10.0)]),
            layers: vec![
                layer(None),
                layer(Some(line(&[(-10.0, 4.0), (30.0, 4.0)]))),
                layer(Some(line(&[(-10.0, -2.0), (30.0, 2.0)]))),
            ],
            bedrock: None,
            piezometric_line: None,
            water_unit_weight: 9.81,
            surcharges: Vec::new(),
            line_loads: Vec::new(),
            tension_crack: None,
            supports: Vec::new(),
            water: Default::default(),
        };
        let section = Section::new(parts).unwrap();
        let fills = layer_fills(&section, -10.0, 30.0, -10.0);
        assert_eq!(fills.len(), 3);
        // Ground above y = 4: from x = 8 (where the ground reaches 4) to 30, under the ground:
        // triangle 8…20 of height 6 (36) plus 20…30 at 6 (60).
        assert!((area(&fills[0].polygon) - 96.0).abs() < 1e-9);
        // Between the sloping top (y = −2 + 0.1(x + 10)) and min(ground, 4): the whole strip
        // less the first layer, computed from the total below the ground.
        // Below the ground over −10…30 down to −10: 10·10 (x < 0) + 20·(10 + 5) + 10·20.
        let total = 100.0 + 300.0 + 200.0;
        let sum: f64 = fills.iter().map(|f| area(&f.polygon)).sum();
        assert!((sum - total).abs() < 1e-9, "{sum}");
        // The last layer: below the sloping top, above −10: mean height 10 over 40.
        assert!((area(&fills[2].polygon) - 400.0).abs() < 1e-9);
        assert!(fills[1].label.starts_with("layer 2: γ = 20"));
    }
}
