//! A study's drawing (model §9.4), read back from the SVG: the histogram's bars carry the
//! answer's counts, their heights follow the counts, bars below 1 are shaded as failures and
//! bars above are not, the threshold sits between the ticks where 1 lies; each sensitivity
//! variable has its own plot whose points are the answer's.
// Test helpers: a failed request or a malformed drawing should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::Server;
use serde_json::{json, Value};

const FAILED: &str = "#c62828";

fn study() -> Value {
    json!({"slope": {"height": 30.48, "length": 60.96}, "circle": {"x": 9.63168, "y": 63.76416}, "slices": 50,
        "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0, "pore_pressure_ratio": 0.5},
        "include": [],
        "probabilistic": {"samples": 1500, "seed": 5, "histogram_bins": 12,
            "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 2.5, "min": 0}]},
        "sensitivity": {"variables": [{"field": "soil.cohesion", "from": 3, "to": 9, "points": 5},
                                      {"field": "soil.pore_pressure_ratio", "from": 0.3, "to": 0.6, "points": 4}]}})
}

async fn post(server: &Server, path: &str, body: &Value) -> String {
    let response = server
        .client
        .post(format!("{}{path}", server.base))
        .json(body)
        .send()
        .await
        .unwrap();
    assert_eq!(response.status(), 200);
    response.text().await.unwrap()
}

fn number(node: roxmltree::Node, attribute: &str) -> f64 {
    node.attribute(attribute).unwrap().parse().unwrap()
}

#[tokio::test]
async fn a_study_is_drawn_with_its_histogram_and_sensitivity_plots() {
    let server = Server::start().await;
    let body = study();
    let answer: Value =
        serde_json::from_str(&post(&server, "/slope/spencer", &body).await).unwrap();
    let svg = post(&server, "/slope/spencer/svg", &body).await;
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let kind = |k: &str| {
        doc.descendants()
            .filter(|n| n.attribute("data-kind") == Some(k))
            .collect::<Vec<_>>()
    };
    let histogram = kind("histogram");
    assert_eq!(histogram.len(), 1);
    let bars: Vec<_> = histogram[0]
        .children()
        .filter(|n| n.attribute("data-count").is_some())
        .collect();
    let bins = answer["probabilistic"]["histogram"].as_array().unwrap();
    assert_eq!(bars.len(), bins.len());
    let most = bins
        .iter()
        .map(|b| b["count"].as_u64().unwrap())
        .max()
        .unwrap() as f64;
    let mut tallest = 0.0f64;
    let (mut failed_bars, mut safe_bars) = (0, 0);
    for (bar, bin) in bars.iter().zip(bins) {
        assert_eq!(number(*bar, "data-count"), bin["count"].as_f64().unwrap());
        assert_eq!(number(*bar, "data-from"), bin["from"].as_f64().unwrap());
        let rects: Vec<_> = bar.children().filter(|n| n.has_tag_name("rect")).collect();
        if bin["count"] == 0 {
            assert!(rects.is_empty());
            continue;
        }
        let height = number(rects[0], "height");
        if bin["count"].as_f64().unwrap() == most {
            tallest = height;
        }
        // Every piece of a bar is as tall as its count says.
        for r in &rects {
            assert!((number(*r, "height") - height).abs() < 0.01);
        }
        let colours: Vec<&str> = rects.iter().map(|r| r.attribute("fill").unwrap()).collect();
        let (from, to) = (bin["from"].as_f64().unwrap(), bin["to"].as_f64().unwrap());
        if to <= 1.0 {
            assert_eq!(colours, [FAILED], "{bin}");
            failed_bars += 1;
        } else if from >= 1.0 {
            assert!(!colours.contains(&FAILED), "{bin}");
            safe_bars += 1;
        } else {
            assert_eq!(colours.len(), 2, "a bar across 1 is split: {bin}");
        }
    }
    assert!(
        failed_bars > 0 && safe_bars > 0,
        "{failed_bars} {safe_bars}"
    );
    // Heights in proportion to counts: every bar's height per count is the tallest's.
    for (bar, bin) in bars.iter().zip(bins) {
        if let Some(r) = bar.children().find(|n| n.has_tag_name("rect")) {
            let expected = tallest * bin["count"].as_f64().unwrap() / most;
            assert!((number(r, "height") - expected).abs() < 0.02, "{bin}");
        }
    }
    // The threshold line lies between the ticks around 1, in proportion.
    let line = histogram[0]
        .descendants()
        .find(|n| n.has_tag_name("line") && n.attribute("stroke") == Some(FAILED))
        .unwrap();
    let ticks: Vec<(f64, f64)> = histogram[0]
        .descendants()
        .filter(|n| n.attribute("data-tick").is_some())
        .map(|n| (number(n, "data-tick"), number(n, "x")))
        .collect();
    assert!(ticks.len() >= 3, "{ticks:?}");
    let (a, b) = (ticks[0], ticks[ticks.len() - 1]);
    let at_one = a.1 + (1.0 - a.0) / (b.0 - a.0) * (b.1 - a.1);
    assert!(
        (number(line, "x1") - at_one).abs() < 0.05,
        "{} vs {at_one}",
        number(line, "x1")
    );
    // One plot per sensitivity variable, its points the answer's.
    let plots = kind("sensitivity");
    let curves = answer["sensitivity"]["variables"].as_array().unwrap();
    assert_eq!(plots.len(), curves.len());
    for (plot, curve) in plots.iter().zip(curves) {
        let dots: Vec<(f64, f64)> = plot
            .descendants()
            .filter(|n| n.attribute("data-value").is_some())
            .map(|n| (number(n, "data-value"), number(n, "data-factor")))
            .collect();
        let expected: Vec<(f64, f64)> = curve["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| (p["value"].as_f64().unwrap(), p["factor"].as_f64().unwrap()))
            .collect();
        assert_eq!(dots, expected);
        let field = curve["field"].as_str().unwrap();
        assert!(plot
            .descendants()
            .any(|n| n.text().is_some_and(|t| t.contains(field))));
    }
    // The panels lie below the picture and inside the drawing.
    let height: f64 = doc
        .root_element()
        .attribute("height")
        .unwrap()
        .parse()
        .unwrap();
    for dot in doc
        .descendants()
        .filter(|n| n.attribute("data-value").is_some())
    {
        assert!(number(dot, "cy") < height);
    }
}

#[tokio::test]
async fn an_arch_study_is_drawn_under_the_arch() {
    let server = Server::start().await;
    let body = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 20},
        "loads": [{"block": 6, "fy": -15.0}], "include": [],
        "probabilistic": {"samples": 400, "variables": [{"field": "loads[0].fy", "distribution": "uniform", "min": -25, "max": -10}]}});
    let svg = post(&server, "/arch/live-load/svg", &body).await;
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let histogram = doc
        .descendants()
        .find(|n| n.attribute("data-kind") == Some("histogram"))
        .unwrap();
    let counted: f64 = histogram
        .children()
        .filter_map(|n| n.attribute("data-count"))
        .map(|c| c.parse::<f64>().unwrap())
        .sum();
    assert_eq!(counted, 400.0);
    assert!(histogram
        .descendants()
        .any(|n| n.text().is_some_and(|t| t.contains("λ = 1"))));
}
