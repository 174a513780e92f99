//! Every drawing is well-formed XML (an attribute written twice, for one, makes browsers show
//! nothing): the Part II scenes and arches on both sides of N = 60, parsed with an XML parser.

// Test scaffolding: a failed request should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::Server;
use serde_json::{json, Value};

async fn svg(server: &Server, path: &str, body: &Value) -> String {
    let response = server
        .client
        .post(format!("{}{path}", server.base))
        .json(body)
        .send()
        .await
        .unwrap();
    assert_eq!(response.status(), 200, "{path} {body}");
    response.text().await.unwrap()
}

fn assert_well_formed(text: &str, what: &str) {
    let document = roxmltree::Document::parse(text)
        .unwrap_or_else(|e| panic!("{what}: not well-formed XML: {e}"));
    assert_eq!(document.root_element().tag_name().name(), "svg", "{what}");
}

#[tokio::test]
async fn every_drawing_parses_as_xml() {
    let server = Server::start().await;
    let arch =
        |n: usize| json!({"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": n});
    for n in [1, 60, 61, 1800, 10000] {
        let body = json!({"geometry": arch(n), "loads": [{"block": n / 4 + 1, "fy": -1.0}]});
        let live = svg(&server, "/arch/live-load/svg", &body).await;
        assert_well_formed(&live, &format!("live N = {n}"));
        let body = json!({"geometry": arch(n)});
        let dead = svg(&server, "/arch/dead-load/svg", &body).await;
        assert_well_formed(&dead, &format!("dead N = {n}"));
        // Issue 19: the N = 1800 drawing was 607 KB; blocks too small to see are one outline
        // and sub-pixel detail is left out.
        for (what, text) in [("live", &live), ("dead", &dead)] {
            assert!(text.len() < 150_000, "{what} N = {n}: {} bytes", text.len());
        }
    }
    let rings = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
                                    "voussoirs": 30, "rings": 2, "spans": 2,
                                    "pier_width": 4.0, "pier_height": 5.0},
                       "loads": [{"block": 8, "fy": -1.0}]});
    assert_well_formed(
        &svg(&server, "/arch/live-load/svg", &rings).await,
        "two rings on two spans",
    );
    let filled = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
        "fill": {"unit_weight": 1.8, "surface": 11.5},
        "rolling": {"axles": [{"fy": -10.0}], "x_start": -8.0, "x_end": 8.0, "positions": 5},
        "compressive_strength": 200.0});
    assert_well_formed(
        &svg(&server, "/arch/live-load/svg", &filled).await,
        "fill, rolling, crushing",
    );
    let section = json!({
        "ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                   {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
        "bedrock": [[-20, -12], [40, -12]],
        "piezometric_line": [[-20, 1], [10, 3], [40, 6]],
        "surcharges": [{"x_start": 25, "x_end": 35, "pressure": 20}],
        "line_loads": [{"x": 30, "fx": 0, "fy": -50}],
        "tension_crack": {"depth": 2.5, "water_depth": 2.5}});
    let bodies = [
        json!({"section": section, "circle": {"centre": [12, 28], "radius": 26}, "slices": 100}),
        json!({"section": section, "surface": [[2, 1.1], [10, -2], [26, 7], [30, 10.5]], "slices": 50}),
        json!({"section": section, "search": {"nx": 8, "ny": 8, "nr": 4}, "slices": 30}),
        json!({"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
                           "layers": [{"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]},
               "circle": {"centre": [120, 90], "radius": 80}, "slices": 100}),
    ];
    for (i, body) in bodies.iter().enumerate() {
        assert_well_formed(
            &svg(&server, "/slope/spencer/svg", body).await,
            &format!("section {i}"),
        );
    }
}

#[tokio::test]
async fn hinge_labels_overlap_no_dot_no_arrow_and_no_other_label() {
    // The README's live-load arch and a thinner one with loads near two hinges: every hinge
    // label's box (0.6 em a character, 11 px text) clear of every hinge dot, of the load arrows
    // and of the other labels, and inside the drawing.
    let server = Server::start().await;
    for body in [
        json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
               "loads": [{"block": 26, "fy": -1.0}]}),
        json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 40},
               "loads": [{"block": 8, "fy": -1.0}, {"block": 30, "fy": -0.5}]}),
    ] {
        let text = svg(&server, "/arch/live-load/svg", &body).await;
        let document = roxmltree::Document::parse(&text).unwrap();
        let number = |n: roxmltree::Node, a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
        let green = |n: &roxmltree::Node| n.attribute("fill") == Some("#1b5e20");
        let dots: Vec<(f64, f64)> = document
            .descendants()
            .filter(|n| n.has_tag_name("circle") && green(n))
            .map(|n| (number(n, "cx"), number(n, "cy")))
            .collect();
        let labels: Vec<[f64; 4]> = document
            .descendants()
            .filter(|n| n.has_tag_name("text") && green(n) && n.text().unwrap().contains('°'))
            .map(|n| {
                let (x, y) = (number(n, "x"), number(n, "y"));
                let w = 0.6 * 11.0 * n.text().unwrap().chars().count() as f64;
                [x, y - 9.0, x + w, y + 2.0]
            })
            .collect();
        let arrows: Vec<[f64; 4]> = document
            .descendants()
            .filter(|n| n.has_tag_name("line") && n.attribute("marker-end").is_some())
            .map(|n| {
                let (x1, y1, x2, y2) = (
                    number(n, "x1"),
                    number(n, "y1"),
                    number(n, "x2"),
                    number(n, "y2"),
                );
                [x1.min(x2), y1.min(y2), x1.max(x2), y1.max(y2)]
            })
            .collect();
        assert!(
            dots.len() >= 4 && labels.len() == dots.len(),
            "{} dots, {} labels",
            dots.len(),
            labels.len()
        );
        let overlaps =
            |a: &[f64; 4], b: &[f64; 4]| a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
        for (i, l) in labels.iter().enumerate() {
            assert!(l[0] >= 60.0 && l[2] <= 800.0, "label {i} outside: {l:?}");
            for d in &dots {
                assert!(
                    !overlaps(l, &[d.0 - 5.0, d.1 - 5.0, d.0 + 5.0, d.1 + 5.0]),
                    "label {i} on a dot {d:?}"
                );
            }
            for a in &arrows {
                assert!(!overlaps(l, a), "label {i} on an arrow {a:?}");
            }
            for m in &labels[i + 1..] {
                assert!(!overlaps(l, m), "labels {l:?} and {m:?} overlap");
            }
        }
    }
}

#[tokio::test]
async fn the_effective_line_of_thrust_is_drawn_only_inside_its_slices() {
    // With r_u = 0.5 the effective inter-slice force nearly vanishes near the crest, and its
    // line of thrust there falls far below the slip surface (9 of 99 boundaries, flagged
    // `inside_slice: false`): the dashed line leaves those points out.
    let server = Server::start().await;
    let body = json!({"slope": {"height": 30.48, "length": 60.96}, "search": {},
                      "soil": {"unit_weight": 10, "cohesion": 6.096, "friction_angle_deg": 40,
                               "pore_pressure_ratio": 0.5}});
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200, "{answer}");
    let line = answer["effective_thrust_line"].as_array().unwrap();
    let inside = line
        .iter()
        .filter(|t| t["inside_slice"] == true && t["y"].is_number())
        .count();
    assert!(inside < line.len(), "the case must have points outside");
    let drawing = svg(&server, "/slope/spencer/svg", &body).await;
    let drawn: usize = drawing
        .lines()
        .filter(|l| l.starts_with("<polyline") && l.contains("stroke-dasharray=\"5 3\""))
        .map(|l| {
            let points = l
                .split("points=\"")
                .nth(1)
                .unwrap()
                .split('"')
                .next()
                .unwrap();
            points.split_whitespace().count()
        })
        .sum();
    assert_eq!(drawn, inside);
}

/// The number in `translate(0 S)` of the group holding the plot.
/// The plot's clip rectangle [x0, y0, x1, y1] in pixels (before the plot's shift).
fn plot_rect(document: &roxmltree::Document) -> [f64; 4] {
    let rect = document
        .descendants()
        .find(|n| n.has_tag_name("clipPath"))
        .and_then(|c| c.children().find(|n| n.has_tag_name("rect")))
        .unwrap();
    let number = |a: &str| rect.attribute(a).unwrap().parse::<f64>().unwrap();
    let (x0, y0) = (number("x"), number("y"));
    [x0, y0, x0 + number("width"), y0 + number("height")]
}

/// The root's data-frame: x0, top, y1 and the scale of the plot.
fn data_frame(document: &roxmltree::Document) -> Vec<f64> {
    document
        .root_element()
        .attribute("data-frame")
        .unwrap()
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect()
}

/// The hinge dots of an arch drawing mapped back to coordinates through the root's data-frame
/// ("x0 top y1 scale"; dots are drawn inside the plot's group, so its shift is added), and the
/// scale.
fn hinge_dots(document: &roxmltree::Document) -> (Vec<(f64, f64)>, f64) {
    let frame = data_frame(document);
    let [x0, top, y1, scale] = frame[..] else {
        panic!("{frame:?}")
    };
    let shift = plot_shift(document);
    let dots = document
        .descendants()
        .filter(|n| n.has_tag_name("circle") && n.attribute("fill") == Some("#1b5e20"))
        .map(|n| {
            let (cx, cy): (f64, f64) = (
                n.attribute("cx").unwrap().parse().unwrap(),
                n.attribute("cy").unwrap().parse().unwrap(),
            );
            (x0 + (cx - 60.0) / scale, y1 - (cy + shift - top) / scale)
        })
        .collect();
    (dots, scale)
}

fn plot_shift(document: &roxmltree::Document) -> f64 {
    let group = document
        .root_element()
        .children()
        .find(|n| n.has_tag_name("g") && n.attribute("transform").is_some())
        .unwrap();
    let transform = group.attribute("transform").unwrap();
    transform
        .trim_start_matches("translate(0 ")
        .trim_end_matches(')')
        .parse()
        .unwrap()
}

#[tokio::test]
async fn the_key_lies_above_the_plot_and_a_search_map_is_cut_at_the_axes() {
    // Issue 19: the key's lines ran down over the top of the plot, and the F map of a search
    // filled most of the picture. Every key line must lie above the plot's top edge (the
    // clip rectangle's top, moved down with the plot); the map is drawn inside the clip
    // group, and what is labelled of it (contour levels, the critical centre) lies inside
    // the clip rectangle.
    let server = Server::start().await;
    let simple = json!({"slope": {"height": 30.48, "length": 60.96}, "search": {}, "slices": 50,
                        "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0,
                                 "pore_pressure_ratio": 0.5}});
    let acads = json!({"section": {"ground": [[20, 25], [30, 25], [50, 35], [70, 35]],
                                   "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 3,
                                                                     "friction_angle_deg": 19.6}}]},
                       "search": {}, "slices": 50});
    for (what, body, key_lines) in [("simple, r_u", &simple, 4), ("ACADS 1(a), dry", &acads, 3)] {
        let text = svg(&server, "/slope/spencer/svg", body).await;
        let document = roxmltree::Document::parse(&text).unwrap();
        let number = |n: roxmltree::Node, a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
        let shift = plot_shift(&document);
        let [x0, y0, x1, y1] = plot_rect(&document);
        // Key lines: texts outside the plot's group below the title row.
        let key: Vec<(f64, String)> = document
            .root_element()
            .children()
            .filter(|n| n.has_tag_name("text") && number(*n, "y") > 30.0)
            .map(|n| (number(n, "y"), n.text().unwrap().to_owned()))
            .collect();
        let rows: std::collections::BTreeSet<i64> = key.iter().map(|k| k.0 as i64).collect();
        assert_eq!(rows.len(), key_lines, "{what}: key {key:?}");
        for (y, line) in &key {
            assert!(
                *y <= y0 + shift - 6.0,
                "{what}: '{line}' at {y} runs into the plot (top {})",
                y0 + shift
            );
        }
        // A dry section has no separate effective line of thrust in its key.
        let effective = key.iter().any(|k| k.1.contains("effective"));
        assert_eq!(effective, what.contains("r_u"), "{what}: {key:?}");
        let clipped = document
            .descendants()
            .find(|n| n.attribute("clip-path") == Some("url(#plot)"))
            .unwrap();
        let cells = clipped
            .children()
            .filter(|n| n.has_tag_name("polygon"))
            .count();
        assert!(cells > 100, "{what}: {cells} map cells in the clip group");
        let inside = |x: f64, y: f64| x >= x0 && x <= x1 && y >= y0 && y <= y1;
        let labels: Vec<(f64, f64)> = clipped
            .children()
            .filter(|n| n.has_tag_name("text"))
            .map(|n| (number(n, "x"), number(n, "y")))
            .collect();
        assert!(labels.len() >= 3, "{what}: {} contour labels", labels.len());
        for (x, y) in labels {
            assert!(
                inside(x, y),
                "{what}: contour label at ({x}, {y}) outside the plot"
            );
        }
        let centre = document
            .descendants()
            .find(|n| n.has_tag_name("circle") && n.attribute("r") == Some("4"))
            .unwrap();
        assert!(
            inside(number(centre, "cx"), number(centre, "cy")),
            "{what}: centre outside"
        );
    }
}

#[tokio::test]
async fn the_data_frame_maps_pixels_back_to_coordinates() {
    // The page places a live load where the arch is clicked from the root's data-frame
    // ("x0 top y1 scale"): each hinge dot, mapped back, must land on that hinge's x and y in
    // the JSON answer (to the 0.01 px the drawing rounds to).
    let server = Server::start().await;
    let body = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
                      "loads": [{"block": 26, "fy": -1.0}]});
    let (status, _, answer) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    let text = svg(&server, "/arch/live-load/svg", &body).await;
    let document = roxmltree::Document::parse(&text).unwrap();
    let (dots, scale) = hinge_dots(&document);
    let hinges = answer["hinges"].as_array().unwrap();
    assert_eq!(dots.len(), hinges.len());
    let tolerance = 0.011 / scale;
    for h in hinges {
        let (x, y) = (h["x"].as_f64().unwrap(), h["y"].as_f64().unwrap());
        assert!(
            dots.iter()
                .any(|d| (d.0 - x).abs() <= tolerance && (d.1 - y).abs() <= tolerance),
            "hinge ({x}, {y}) not among {dots:?}"
        );
    }
}

#[tokio::test]
async fn sliding_joints_are_drawn_with_the_direction_of_slip() {
    // Issue 17: a wall panel's top block pushed to the right at its top-left corner slides on
    // the block below at μ·W = 0.3 (μ = 0.3). The drawing marks each sliding joint (purple,
    // dashed) and the slip of the upper block relative to the lower one: to the right.
    let server = Server::start().await;
    let body = json!({"geometry": {"kind": "assembly",
        "blocks": [{"polygon": [[-1, 0], [1, 0], [1, 1], [-1, 1]]},
                   {"polygon": [[-0.5, 1], [0.5, 1], [0.5, 2], [-0.5, 2]]}],
        "supports": [{"polygon": [[-3, -1], [3, -1], [3, 0], [-3, 0]]}]},
        "friction_coefficient": 0.3,
        "loads": [{"block": 2, "x": -0.5, "y": 2, "fx": 1}]});
    let (status, _, answer) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    let sliding = answer["sliding_interfaces"].as_array().unwrap().len();
    assert!(sliding >= 1, "{answer}");
    let text = svg(&server, "/arch/live-load/svg", &body).await;
    let document = roxmltree::Document::parse(&text).unwrap();
    let purple = |n: &roxmltree::Node| n.attribute("stroke") == Some("#7b1fa2");
    // The joints in one path, a subpath each.
    let joints: usize = document
        .descendants()
        .filter(|n| n.has_tag_name("path") && purple(n))
        .map(|n| n.attribute("d").unwrap().matches('M').count())
        .sum();
    assert_eq!(joints, sliding);
    let arrows: Vec<f64> = document
        .descendants()
        .filter(|n| n.has_tag_name("line") && purple(n))
        .map(|n| {
            let x = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
            x("x2") - x("x1")
        })
        .collect();
    assert!(
        !arrows.is_empty() && arrows.iter().all(|dx| *dx > 0.0),
        "{arrows:?}"
    );
    assert!(text.contains("sliding joints"));
    // Without friction nothing slides and nothing is drawn in that colour.
    let mut tipping = body.clone();
    tipping["friction_coefficient"] = Value::Null;
    let text = svg(&server, "/arch/live-load/svg", &tipping).await;
    assert!(!text.contains("#7b1fa2"));
}

#[tokio::test]
async fn multi_ring_drawings_stay_small_and_draw_every_block() {
    // Issue 38: multi-ring SVGs reached 1.1 MB (four rings of 300) from a 97-byte request, an
    // element per block, per displaced block, per hinge and per slip arrow. Dense assemblies
    // are drawn as one path per layer: every block still there (one subpath each), at most
    // 300 KB for hundreds of blocks; beyond 1000 blocks the displaced blocks and the sliding
    // joints are left out and the key says so.
    let server = Server::start().await;
    for (rings, voussoirs) in [(3, 300), (4, 300), (8, 100)] {
        let body = json!({
            "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
                         "voussoirs": voussoirs, "rings": rings},
            "ring_friction_coefficient": 0.6, "loads": [{"block": 26, "fy": -1.0}]});
        let text = svg(&server, "/arch/live-load/svg", &body).await;
        let what = format!("{rings} rings of {voussoirs}");
        assert_well_formed(&text, &what);
        assert!(text.len() <= 300_000, "{what}: {} bytes", text.len());
        let document = roxmltree::Document::parse(&text).unwrap();
        let blocks = document
            .descendants()
            .find(|n| n.tag_name().name() == "path" && n.attribute("fill") == Some("#e8dcc8"))
            .unwrap_or_else(|| panic!("{what}: no path of blocks"));
        let subpaths = blocks.attribute("d").unwrap().matches('M').count();
        // Each ring's voussoirs, and the half voussoirs that start every other ring.
        let expected = rings * voussoirs + rings / 2;
        assert_eq!(subpaths, expected, "{what}");
        let stated = text.contains("not drawn: too many blocks");
        assert_eq!(stated, expected > 1000, "{what}");
    }
}

#[tokio::test]
async fn drawn_loads_are_in_the_key() {
    // Issue 46: a surcharge was drawn but missing from the key. The key is the text above the
    // plot: each item's text in the colour of what it names.
    let server = Server::start().await;
    let section = |surcharges: Value| {
        json!({"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
                           "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}}],
                           "surcharges": surcharges},
               "circle": {"centre": [12, 28], "radius": 26}, "slices": 40})
    };
    let loaded = svg(
        &server,
        "/slope/spencer/svg",
        &section(json!([{"x_start": 25, "x_end": 35, "pressure": 20}])),
    )
    .await;
    let document = roxmltree::Document::parse(&loaded).unwrap();
    let key = document
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .find(|n| {
            n.text()
                .is_some_and(|t| t.contains("surcharges and line loads"))
        })
        .expect("the surcharge's key item");
    assert_eq!(
        key.attribute("fill"),
        Some("#e65100"),
        "the key item's colour"
    );
    assert!(loaded.contains("stroke=\"#e65100\""), "the surcharge drawn");
    // Without loads, no such key item.
    let bare = svg(&server, "/slope/spencer/svg", &section(json!([]))).await;
    assert!(!bare.contains("surcharges and line loads"));
}

#[tokio::test]
async fn a_dense_chain_says_how_many_of_its_joints_are_drawn() {
    // Issue 46: N = 1800 voussoirs were drawn with 11 joints and nothing said so: it looked
    // like a 10-voussoir arch.
    let server = Server::start().await;
    let body = |n: usize| json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": n}});
    let dense = svg(&server, "/arch/dead-load/svg", &body(1800)).await;
    let document = roxmltree::Document::parse(&dense).unwrap();
    assert!(
        document
            .descendants()
            .any(|n| n.text() == Some("| 1800 voussoirs: one joint in 180 drawn")),
        "no key item for the joints drawn"
    );
    // 11 joints are drawn (0, 180, …, 1800), as the key says.
    let joints = dense
        .matches("stroke=\"#8d6e63\" stroke-width=\"0.5\"")
        .count();
    assert_eq!(joints, 11);
    // Up to 200 voussoirs every joint is drawn and nothing needs saying.
    let every = svg(&server, "/arch/dead-load/svg", &body(200)).await;
    assert!(!every.contains("one joint in"));
}

#[tokio::test]
async fn passive_pressure_and_live_loads_have_arrowheads_of_their_own() {
    // Issue 46: passive-pressure arrows carried the blue live-load arrowhead, so two different
    // forces looked alike. Each kind now has its colour, its head included.
    let server = Server::start().await;
    let body = json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
        "fill": {"unit_weight": 1.8, "surface": 11.5,
                 "passive": {"friction_angle_deg": 30, "mobilisation": 0.5}},
        "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}]});
    let drawn = svg(&server, "/arch/live-load/svg", &body).await;
    let document = roxmltree::Document::parse(&drawn).unwrap();
    let heads = |marker: &str| {
        document
            .descendants()
            .filter(|n| n.attribute("marker-end") == Some(marker))
            .map(|n| n.attribute("stroke").unwrap_or_default().to_owned())
            .collect::<Vec<_>>()
    };
    let passive = heads("url(#arrow-6d4c41)");
    let live = heads("url(#arrow)");
    assert!(!passive.is_empty(), "no passive arrow with its own head");
    assert!(passive.iter().all(|s| s == "#6d4c41"), "{passive:?}");
    assert!(
        !live.is_empty() && live.iter().all(|s| s == "#1565c0"),
        "{live:?}"
    );
    // The brown head is defined in brown.
    let marker = document
        .descendants()
        .find(|n| n.attribute("id") == Some("arrow-6d4c41"))
        .expect("the passive arrowhead");
    let fill = marker
        .descendants()
        .find_map(|n| n.attribute("fill"))
        .unwrap_or_default();
    assert_eq!(fill, "#6d4c41");
}

#[tokio::test]
async fn load_arrows_stay_inside_the_plot_clear_of_the_key() {
    // Issue 46: a load at the crown drew its arrow from above the picture's extent (the
    // blocks' bounding box), up into the key. Every live-load arrow must lie within the plot
    // (the clip rectangle, moved down with the plot), below the key's last line.
    let server = Server::start().await;
    for (what, body) in [
        (
            "crown, downwards",
            json!({"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": 40},
                                    "loads": [{"block": 20, "fy": -1}, {"block": 21, "fx": 0.3, "fy": -0.2}]}),
        ),
        (
            "springing, sideways",
            json!({"geometry": {"kind": "circular", "radius": 10, "thickness": 1.5, "voussoirs": 40},
                                       "loads": [{"block": 1, "fx": 2, "fy": 0}]}),
        ),
    ] {
        let text = svg(&server, "/arch/live-load/svg", &body).await;
        let document = roxmltree::Document::parse(&text).unwrap();
        let number = |n: roxmltree::Node, a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
        let shift = plot_shift(&document);
        let [x0, y0, x1, y1] = plot_rect(&document);
        let key_bottom = document
            .root_element()
            .children()
            .filter(|n| n.has_tag_name("text") && number(*n, "y") > 30.0)
            .map(|n| number(n, "y"))
            .fold(0.0, f64::max);
        let arrows: Vec<roxmltree::Node> = document
            .descendants()
            .filter(|n| n.has_tag_name("line") && n.attribute("stroke") == Some("#1565c0"))
            .collect();
        assert!(!arrows.is_empty(), "{what}: no arrow drawn");
        for arrow in arrows {
            for (x, y) in [("x1", "y1"), ("x2", "y2")] {
                let (px, py) = (number(arrow, x), number(arrow, y) + shift);
                assert!(
                    px >= x0 - 0.5
                        && px <= x1 + 0.5
                        && py >= y0 + shift - 0.5
                        && py <= y1 + shift + 0.5,
                    "{what}: arrow end ({px}, {py}) outside the plot [{x0}, {}]–[{x1}, {}]",
                    y0 + shift,
                    y1 + shift
                );
                assert!(
                    py > key_bottom,
                    "{what}: arrow end at {py} in the key (last line {key_bottom})"
                );
            }
        }
    }
}

#[tokio::test]
async fn contour_labels_overlap_neither_each_other_nor_the_centre_label() {
    // Issue 46: nested contours of a search's F map could put their labels on top of each
    // other. Each label's box (0.6 em a character at 9 px, from its baseline up) must be clear
    // of every other label's.
    let server = Server::start().await;
    let bodies = [
        json!({"slope": {"height": 30.48, "length": 60.96}, "search": {"nx": 31, "ny": 31}, "slices": 50,
               "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0, "pore_pressure_ratio": 0.5}}),
        json!({"section": {"ground": [[20, 25], [30, 25], [50, 35], [70, 35]],
                           "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 3, "friction_angle_deg": 19.6}}]},
               "search": {}, "slices": 50}),
        json!({"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
                           "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                                      {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
                           "piezometric_line": [[-20, 1], [10, 3], [40, 6]]},
               "search": {"nx": 25, "ny": 25, "nr": 8}, "slices": 40}),
    ];
    for body in &bodies {
        let text = svg(&server, "/slope/spencer/svg", body).await;
        let document = roxmltree::Document::parse(&text).unwrap();
        let number = |n: roxmltree::Node, a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
        let boxes: Vec<[f64; 4]> = document
            .descendants()
            .filter(|n| n.has_tag_name("text") && n.attribute("font-size") == Some("9"))
            .map(|n| {
                let (x, y) = (number(n, "x"), number(n, "y"));
                let w = 0.6 * 9.0 * n.text().unwrap().chars().count() as f64;
                [x, y - 9.0, x + w, y]
            })
            .collect();
        assert!(boxes.len() >= 3, "{} labels: {body}", boxes.len());
        // Nor the critical centre's label ("centre, R = …", 11 px), drawn after the map.
        let centre = document
            .descendants()
            .find(|n| n.text().is_some_and(|t| t.starts_with("centre, R =")))
            .unwrap();
        let (x, y) = (number(centre, "x"), number(centre, "y"));
        let w = 0.6 * 11.0 * centre.text().unwrap().chars().count() as f64;
        let centre_box = [x, y - 11.0, x + w, y];
        for a in &boxes {
            let overlap = a[0] < centre_box[2]
                && centre_box[0] < a[2]
                && a[1] < centre_box[3]
                && centre_box[1] < a[3];
            assert!(
                !overlap,
                "a contour label at {a:?} overlaps the centre's {centre_box:?}: {body}"
            );
        }
        for (i, a) in boxes.iter().enumerate() {
            for b in &boxes[i + 1..] {
                let overlap = a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
                assert!(!overlap, "labels at {a:?} and {b:?} overlap: {body}");
            }
        }
    }
}

#[tokio::test]
async fn the_rolling_curve_shares_the_bridge_axis_and_has_ticks() {
    // Each stop's point lies under its x on the bridge's axis (the root's data-frame maps x to
    // pixels), the band's x ticks are the bridge's, and λ is labelled; stops beyond the arch
    // widen the picture so that they stay on it.
    let server = Server::start().await;
    let body = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 60},
        "fill": {"unit_weight": 1.8, "surface": 11.5},
        "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}],
                    "x_start": -14.0, "x_end": 12.0, "positions": 27}, "include": []});
    let (status, _, answer) = server.post("/arch/live-load", &body).await;
    assert_eq!(status, 200, "{answer}");
    let text = svg(&server, "/arch/live-load/svg", &body).await;
    let doc = roxmltree::Document::parse(&text).unwrap();
    let frame = data_frame(&doc);
    let (x0, scale) = (frame[0], frame[3]);
    let to_px = |x: f64| 60.0 + (x - x0) * scale;
    let band = doc
        .descendants()
        .find(|n| n.attribute("data-kind") == Some("rolling"))
        .unwrap();
    let line = band
        .children()
        .find(|n| n.has_tag_name("polyline"))
        .unwrap();
    let xs: Vec<f64> = line
        .attribute("points")
        .unwrap()
        .split(' ')
        .map(|p| p.split(',').next().unwrap().parse().unwrap())
        .collect();
    let stops: Vec<f64> = answer["rolling"]["positions"]
        .as_array()
        .unwrap()
        .iter()
        .zip(answer["rolling"]["load_factor"].as_array().unwrap())
        .filter(|(_, l)| !l.is_null())
        .map(|(x, _)| x.as_f64().unwrap())
        .collect();
    assert_eq!(xs.len(), stops.len());
    for (px, x) in xs.iter().zip(&stops) {
        assert!(
            (px - to_px(*x)).abs() < 0.01,
            "stop {x}: {px} vs {}",
            to_px(*x)
        );
    }
    let [left, _, right, _] = plot_rect(&doc);
    assert!(
        xs.iter().all(|&px| px >= left - 0.01 && px <= right + 0.01),
        "{xs:?} in {left}..{right}"
    );
    let ticks: Vec<(f64, f64)> = band
        .descendants()
        .filter(|n| n.attribute("data-tick").is_some())
        .map(|n| {
            let x: f64 = n.attribute("data-tick").unwrap().parse().unwrap();
            (x, n.attribute("x").unwrap().parse().unwrap())
        })
        .collect();
    assert!(ticks.len() >= 3, "{ticks:?}");
    for (x, px) in &ticks {
        assert!((px - to_px(*x)).abs() < 0.01, "tick {x}");
    }
    // The bridge's own axis labels the same x values.
    let labels: Vec<String> = ticks.iter().map(|(x, _)| format!("{x}")).collect();
    for label in &labels {
        assert!(
            doc.descendants()
                .filter(|n| n.attribute("data-tick").is_none())
                .any(|n| n.text() == Some(label.as_str())),
            "{label}"
        );
    }
    assert!(
        band.descendants()
            .filter(|n| n.attribute("data-lambda").is_some())
            .count()
            >= 2
    );
}

#[tokio::test]
async fn the_minimum_thickness_drawing_marks_its_hinges() {
    // /arch/minimum-thickness/svg draws the arch just too thin with its collapse: a dot on each
    // hinge of the JSON answer (mapped back through the data-frame) labelled with its angle and
    // side, and the minimum thickness in the title.
    let server = Server::start().await;
    let body = json!({"geometry": {"kind": "circular", "radius": 10.0, "voussoirs": 40}});
    let (status, _, answer) = server.post("/arch/minimum-thickness", &body).await;
    assert_eq!(status, 200, "{answer}");
    let text = svg(&server, "/arch/minimum-thickness/svg", &body).await;
    let document = roxmltree::Document::parse(&text).unwrap();
    let (dots, scale) = hinge_dots(&document);
    let hinges = answer["hinges"].as_array().unwrap();
    assert_eq!(hinges.len(), 5, "{answer}");
    assert_eq!(dots.len(), hinges.len());
    let tolerance = 0.011 / scale;
    let texts: Vec<&str> = document.descendants().filter_map(|n| n.text()).collect();
    for h in hinges {
        let (x, y) = (h["x"].as_f64().unwrap(), h["y"].as_f64().unwrap());
        assert!(
            dots.iter()
                .any(|d| (d.0 - x).abs() <= tolerance && (d.1 - y).abs() <= tolerance),
            "hinge ({x}, {y}) not among {dots:?}"
        );
        let label = format!(
            "{:.1}° {}",
            h["angle_deg"].as_f64().unwrap(),
            h["location"].as_str().unwrap()
        );
        assert!(texts.contains(&label.as_str()), "{label}");
    }
    let thickness = answer["thickness"].as_f64().unwrap();
    let title = format!("Minimum thickness: D = {thickness:.6}");
    assert!(texts.iter().any(|t| t.starts_with(&title)), "{title}");
    // A dense chain's mechanism is not drawn, and the key says so.
    let dense = json!({"geometry": {"kind": "circular", "radius": 10.0, "voussoirs": 1800}});
    let text = svg(&server, "/arch/minimum-thickness/svg", &dense).await;
    assert!(text.contains("collapse mechanism not drawn: too many blocks"));
    assert!(!text.contains("- - collapse mechanism"));
    // Without a minimum the arch is drawn as given, the reason in the key.
    let three =
        json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 3}});
    let text = svg(&server, "/arch/minimum-thickness/svg", &three).await;
    assert!(text.contains("Minimum thickness: none found"), "{text}");
}

#[tokio::test]
async fn a_layer_key_shows_its_angle_as_given() {
    // 30° came back as 29.999999999999996° (degrees → radians → degrees) in a section's key.
    let server = Server::start().await;
    let body = json!({"section": {"ground": [[0, 0], [10, 0], [30, 10], [50, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 30}},
                   {"top": [[0, -2], [50, -2]], "soil": {"unit_weight": 20, "cohesion": 5, "friction_angle_deg": 35}}]},
        "circle": {"centre": [20, 25], "radius": 25}, "slices": 30});
    let (status, _, svg) = server
        .post_accept("/slope/spencer/svg", "image/svg+xml", &body)
        .await;
    assert_eq!(status, 200, "{svg}");
    assert!(svg.contains("layer 1: γ = 20, c′ = 10, φ′ = 30°"), "{svg}");
    assert!(svg.contains("layer 2: γ = 20, c′ = 5, φ′ = 35°"), "{svg}");
    assert!(!svg.contains("29.99999"), "{svg}");
}
