//! The layers of an arch drawing, each drawn on the canvas in turn: the fill and its road
//! loads, the blocks, the collapse mechanism, the hinges and live loads, passive pressure and
//! crushing joints.

use thrustline_solver::arch::fill::{ExtradosFaces, ExtradosProfile, Fill, RoadLoad};
use thrustline_solver::arch::{Assembly, HingeSide, LiveLoad, Mechanism};

use crate::svg::{escape, shown, Canvas, Labels};

/// The key's entries: colour and text.
pub type Legend = Vec<(&'static str, std::borrow::Cow<'static, str>)>;

/// Chains of more blocks than this are drawn as one outline.
const MERGED_ABOVE: usize = 200;
/// Hinges are labelled with their angle when there are at most this many.
pub const MAX_HINGE_LABELS: usize = 8;

/// Points along a voussoir's outline: straight sides, or arcs about the origin when `curved`.
fn outline(corners: &[(f64, f64)], curved: bool) -> Vec<(f64, f64)> {
    if !curved || corners.len() != 4 {
        return corners.to_vec();
    }
    // Intrados-start → extrados-start (straight), along the extrados, extrados-end →
    // intrados-end (straight), back along the intrados.
    let arc = |a: (f64, f64), b: (f64, f64)| -> Vec<(f64, f64)> {
        let (ra, ta) = (a.0.hypot(a.1), a.1.atan2(a.0));
        let mut tb = b.1.atan2(b.0);
        while tb - ta > std::f64::consts::PI {
            tb -= 2.0 * std::f64::consts::PI;
        }
        while ta - tb > std::f64::consts::PI {
            tb += 2.0 * std::f64::consts::PI;
        }
        (0..=6)
            .map(|i| {
                let t = ta + (tb - ta) * f64::from(i) / 6.0;
                (ra * t.cos(), ra * t.sin())
            })
            .collect()
    };
    let mut points = vec![corners[0]];
    points.extend(arc(corners[1], corners[2]));
    points.extend(arc(corners[3], corners[0]));
    points
}

/// The fill between the extrados and the road, and each road load's patch and dispersal.
pub fn fill(
    canvas: &mut Canvas,
    assembly: &Assembly,
    (f, faces, road_loads): &(Fill, ExtradosFaces, Vec<RoadLoad>),
    road: [(f64, f64); 2],
    legend: &mut Legend,
) {
    let chain = assembly.is_chain();
    let profile = ExtradosProfile::new(faces);
    // A chain's extrados from the right springing to the left (block order), a bridge's
    // upper envelope from the left; closed along the road.
    let mut outline: Vec<(f64, f64)> = if chain {
        assembly
            .blocks
            .iter()
            .flat_map(|b| [b.corners[1], b.corners[2]])
            .collect()
    } else {
        profile.envelope().iter().rev().copied().collect()
    };
    outline.insert(0, road[0]);
    outline.push(road[1]);
    canvas.polygon(&outline, "fill=\"#f3ead7\" stroke=\"none\"");
    canvas.polyline(&road, "stroke=\"#616161\" stroke-width=\"2.5\"");
    legend.push(("#a1887f", "▬ fill and road".into()));
    // Layers, highest first, each the fill below its level drawn over the one above, darker
    // the lower it lies (no stroke: the clipped outline runs twice along the level).
    const SHADES: [(&str, &str); 4] = [
        ("#e6d5b3", "#8d6e63"),
        ("#d6bf95", "#795548"),
        ("#c4a77a", "#6d4c41"),
        ("#b08f62", "#5d4037"),
    ];
    for (i, layer) in f.layers.iter().rev().enumerate() {
        let part = clip_below(&outline, layer.below);
        if part.len() < 3 {
            continue;
        }
        let (shade, key) = SHADES[i.min(SHADES.len() - 1)];
        canvas.polygon(
            &part,
            &format!("fill=\"{shade}\" stroke=\"none\" data-kind=\"fill-layer\""),
        );
        legend.push((
            key,
            format!(
                "▬ fill γ = {} below y = {}",
                shown(layer.unit_weight),
                shown(layer.below)
            )
            .into(),
        ));
    }
    // Road loads: the patch on the road and its dispersal lines down to the extrados.
    // A line that passes over the arch is cut where the road ends (the bridge's edge).
    let (x_lo, x_hi) = (road[0].0.min(road[1].0), road[0].0.max(road[1].0));
    let within = |from: (f64, f64), to: (f64, f64)| {
        let x = to.0.clamp(x_lo, x_hi);
        if to.0 == from.0 || x == to.0 {
            to
        } else {
            (x, from.1 + (to.1 - from.1) * (x - from.0) / (to.0 - from.0))
        }
    };
    for load in road_loads {
        let (a, b) = (load.x - 0.5 * load.length, load.x + 0.5 * load.length);
        let ends = profile.dispersal_ends(f, *load);
        let ends = [within((a, f.road), ends[0]), within((b, f.road), ends[1])];
        let fan = "stroke=\"#1565c0\" stroke-width=\"0.9\" stroke-dasharray=\"3 2\"";
        canvas.polyline(&[(a, f.road), ends[0]], fan);
        canvas.polyline(&[(b, f.road), ends[1]], fan);
        canvas.polyline(
            &[(a, f.road), (b, f.road)],
            "stroke=\"#1565c0\" stroke-width=\"4\"",
        );
    }
    if !road_loads.is_empty() {
        legend.push(("#1565c0", "- - dispersal".into()));
    }
}

/// The part of a polygon at or below level `y` (Sutherland–Hodgman against one half-plane).
fn clip_below(polygon: &[(f64, f64)], y: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(polygon.len() + 2);
    for (i, &p) in polygon.iter().enumerate() {
        let q = polygon[(i + 1) % polygon.len()];
        let (p_in, q_in) = (p.1 <= y, q.1 <= y);
        if p_in {
            out.push(p);
        }
        if p_in != q_in {
            let t = (y - p.1) / (q.1 - p.1);
            out.push((p.0 + t * (q.0 - p.0), y));
        }
    }
    out
}

/// For a chain drawn as one outline: its blocks and the step between the joints drawn (the key
/// says so, lest 1800 voussoirs look like ten).
pub fn joints_drawn(assembly: &Assembly) -> Option<(usize, usize)> {
    let n = assembly.blocks.len();
    (assembly.is_chain() && n > MERGED_ABOVE).then_some((n, (n / 10).max(1)))
}

/// The blocks: one by one, or a long chain as one outline with every tenth joint marked.
pub fn blocks(canvas: &mut Canvas, assembly: &Assembly, curved: bool) {
    let chain = assembly.is_chain();
    let outlines: Vec<Vec<(f64, f64)>> = assembly
        .blocks
        .iter()
        .map(|b| outline(&b.corners, curved))
        .collect();
    let thin = if assembly.blocks.len() > 200 {
        "0.2"
    } else {
        "0.8"
    };
    if chain && assembly.blocks.len() > MERGED_ABOVE {
        // Blocks too small to see one by one: the ring as one outline (extrados out, intrados
        // back), with every tenth joint marked.
        let mut ring: Vec<(f64, f64)> = assembly
            .blocks
            .iter()
            .flat_map(|b| [b.corners[1], b.corners[2]])
            .collect();
        ring.extend(
            assembly
                .blocks
                .iter()
                .rev()
                .flat_map(|b| [b.corners[3], b.corners[0]]),
        );
        canvas.polygon(
            &ring,
            "fill=\"#e8dcc8\" stroke=\"#8d6e63\" stroke-width=\"0.8\"",
        );
        let step = joints_drawn(assembly).map_or(1, |(_, step)| step);
        for i in assembly.interfaces.iter().step_by(step) {
            canvas.polyline(
                &[i.intrados, i.extrados],
                "stroke=\"#8d6e63\" stroke-width=\"0.5\"",
            );
        }
    } else if assembly.blocks.len() > MERGED_ABOVE {
        // Rings and spans of many blocks: every block still drawn, in one path.
        canvas.path(
            &outlines,
            true,
            &format!("fill=\"#e8dcc8\" stroke=\"#8d6e63\" stroke-width=\"{thin}\""),
        );
    } else {
        for o in &outlines {
            canvas.polygon(
                o,
                &format!("fill=\"#e8dcc8\" stroke=\"#8d6e63\" stroke-width=\"{thin}\""),
            );
        }
    }
}

/// The collapse mechanism: blocks displaced by 8 % of the span at the fastest corner; each
/// block dashed when there are few, the displaced intrados and extrados when there are many.
pub fn mechanism(canvas: &mut Canvas, assembly: &Assembly, mechanism: &Mechanism, curved: bool) {
    let (chain, span) = (assembly.is_chain(), assembly.length_scale());
    let delta = 0.08 * span;
    let displaced: Vec<Vec<(f64, f64)>> = assembly
        .blocks
        .iter()
        .zip(&mechanism.velocities)
        .map(|(block, &[u, v, rotation])| {
            let g = block.centroid;
            let corners = if chain && assembly.blocks.len() > 60 {
                block.corners.to_vec()
            } else {
                outline(&block.corners, curved)
            };
            corners
                .into_iter()
                .map(|(x, y)| {
                    (
                        x + delta * (u - rotation * (y - g.1)),
                        y + delta * (v + rotation * (x - g.0)),
                    )
                })
                .collect()
        })
        .collect();
    let style = "fill=\"none\" stroke=\"#546e7a\" stroke-width=\"0.9\" stroke-dasharray=\"4 3\"";
    if chain && assembly.blocks.len() > 60 {
        let intrados: Vec<(f64, f64)> = displaced.iter().flat_map(|c| [c[0], c[3]]).collect();
        let extrados: Vec<(f64, f64)> = displaced.iter().flat_map(|c| [c[1], c[2]]).collect();
        canvas.polyline(&intrados, style);
        canvas.polyline(&extrados, style);
    } else if assembly.blocks.len() > MERGED_ABOVE {
        canvas.path(&displaced, true, style);
    } else {
        for d in &displaced {
            canvas.polygon(d, style);
        }
    }
}

/// The live loads as arrows (tail, head): ending at their point, 12 % of the span long for the
/// largest. The picture holds their tails, so that none runs into the key above it.
pub fn load_arrows(assembly: &Assembly, loads: &[LiveLoad]) -> Vec<((f64, f64), (f64, f64))> {
    let span = assembly.length_scale();
    let largest = loads.iter().map(|l| l.fx.hypot(l.fy)).fold(0.0, f64::max);
    loads
        .iter()
        .filter_map(|load| {
            let magnitude = load.fx.hypot(load.fy);
            if magnitude == 0.0 || largest == 0.0 {
                return None;
            }
            let length = 0.12 * span * magnitude / largest;
            let from = (
                load.point.0 - length * load.fx / magnitude,
                load.point.1 - length * load.fy / magnitude,
            );
            Some((from, load.point))
        })
        .collect()
}

/// Hinges at the intrados or extrados end of their interface and the live loads as arrows; the
/// hinges' labels (polar angle and side) placed clear of the dots, the arrows and each other.
/// Answers how many hinges there are (their labels are left out beyond [`MAX_HINGE_LABELS`]).
pub fn hinges_and_loads(
    canvas: &mut Canvas,
    assembly: &Assembly,
    mechanism: Option<&Mechanism>,
    loads: &[LiveLoad],
) -> usize {
    let mut hinge_labels = Vec::new();
    let mut labels = Labels::default();
    let hinges = mechanism.map(|m| m.hinges.as_slice()).unwrap_or_default();
    // Many hinges (a multi-ring mechanism) are drawn as one path of dots.
    let many = hinges.len() > MAX_HINGE_LABELS;
    let mut dots = Vec::new();
    for hinge in hinges {
        let Some(interface) = assembly.interfaces.get(hinge.interface) else {
            continue;
        };
        let (point, outward, location) = match hinge.side {
            HingeSide::Intrados => (interface.intrados, -1.0, "intrados"),
            HingeSide::Extrados => (interface.extrados, 1.0, "extrados"),
        };
        if many {
            dots.push(point);
            continue;
        }
        canvas.dot(
            point,
            5.0,
            "fill=\"#1b5e20\" stroke=\"white\" stroke-width=\"1.5\"",
        );
        let p = canvas.px(point);
        labels.avoid([p.0 - 6.0, p.1 - 6.0, p.0 + 6.0, p.1 + 6.0]);
        // Away from the arch: outwards at the extrados, inwards at the intrados (pixels, y down).
        let direction = (
            outward * interface.tangent.0,
            -outward * interface.tangent.1,
        );
        hinge_labels.push((p, direction, format!("{:.1}° {location}", hinge.angle_deg)));
    }
    canvas.dots(&dots, 8.0, "#1b5e20");
    for (from, to) in load_arrows(assembly, loads) {
        canvas.arrow(from, to, "stroke=\"#1565c0\" stroke-width=\"2\"");
        labels.avoid_segment(canvas.px(from), canvas.px(to), 6.0);
    }
    let area = canvas.plot_area();
    // Many hinges would bury the drawing in labels: their angles are in the JSON; the key
    // says so.
    let hinge_count = hinge_labels.len() + dots.len();
    for (p, direction, text) in hinge_labels {
        let (x, y) = labels.place(p, direction, (text.chars().count(), 11.0), area);
        canvas.raw(&format!(
            "<text x=\"{x:.2}\" y=\"{:.2}\" font-size=\"11\" fill=\"#1b5e20\" font-family=\"sans-serif\">{}</text>",
            y + 9.0,
            escape(&text)
        ));
    }
    hinge_count
}
