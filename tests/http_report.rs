//! The `…/report` routes: one self-contained HTML page per request whose numbers are the JSON
//! answer's, with the drawing (parsed as XML here), the warnings by code, the inputs as read,
//! the version, the request id and the date; nothing fetched, nothing run.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{milankovitch, spencer_example, Server};
use serde_json::{json, Value};

/// POSTs `body` to `path` with a request id; the status, headers and text.
async fn report(
    server: &Server,
    path: &str,
    id: &str,
    body: &Value,
) -> (u16, reqwest::header::HeaderMap, String) {
    let response = server
        .client
        .post(format!("{}{path}", server.base))
        .header("x-request-id", id)
        .json(body)
        .send()
        .await
        .unwrap();
    let status = response.status().as_u16();
    let headers = response.headers().clone();
    (status, headers, response.text().await.unwrap())
}

/// The text between `start` (after it) and the next `end`.
fn between<'a>(text: &'a str, start: &str, end: &str) -> &'a str {
    let from = text
        .find(start)
        .unwrap_or_else(|| panic!("no {start:?} in the report"))
        + start.len();
    let to = text[from..].find(end).unwrap() + from;
    &text[from..to]
}

/// The results table's value for `field`.
fn result(page: &str, field: &str) -> String {
    between(
        page,
        &format!("<tr><th>{field}</th><td class=\"n\">"),
        "</td>",
    )
    .to_owned()
}

/// What every report must be: HTML with the report's policy, self-contained, its drawing an
/// SVG that parses, the id and a UTC date of this year.
fn check_page(headers: &reqwest::header::HeaderMap, page: &str, id: &str) {
    assert_eq!(headers["content-type"], "text/html; charset=utf-8");
    let policy = headers["content-security-policy"].to_str().unwrap();
    assert!(policy.starts_with("default-src 'none'"), "{policy}");
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert!(page.trim_end().ends_with("</html>"));
    // Nothing fetched, nothing run.
    for absent in ["<script", "<link", "src=", "href=", "@import"] {
        assert!(!page.contains(absent), "the report contains {absent}");
    }
    // The drawing's markers refer to the page itself (`url(#arrow)`), nothing else does.
    assert!(page
        .match_indices("url(")
        .all(|(i, _)| page[i..].starts_with("url(#")));
    let svg = format!("<svg{}</svg>", between(page, "<svg", "</svg>"));
    roxmltree::Document::parse(&svg).unwrap();
    assert_eq!(between(page, "<td id=\"request-id\">", "</td>"), id);
    let date = between(page, "<td id=\"date\">", "</td>");
    assert!(
        date.starts_with("20") && date.ends_with(" UTC") && date.len() == 23,
        "{date}"
    );
    assert!(page.contains(&format!("thrustline {}", env!("CARGO_PKG_VERSION"))));
}

#[tokio::test]
async fn the_spencer_report_is_the_answer_printed() {
    let server = Server::start().await;
    let body = spencer_example();
    let (status, _, answer) = server.post("/slope/spencer", &body).await;
    assert_eq!(status, 200);
    let (status, headers, page) = report(&server, "/slope/spencer/report", "calc-17", &body).await;
    assert_eq!(status, 200, "{page}");
    check_page(&headers, &page, "calc-17");
    // Spencer (1967) at 100 slices: F = 1.0696, θ = 22.43° (model §2.3), every digit of the
    // JSON answer in the results.
    assert_eq!(
        between(&page, "id=\"headline\">", "</p>"),
        "Spencer&#39;s method: one slip circle: F = 1.0696, θ = 22.43°"
    );
    for field in ["factor_of_safety", "theta_deg", "bishop_factor_of_safety"] {
        let printed: f64 = result(&page, field).parse().unwrap();
        assert_eq!(Some(printed), answer[field].as_f64(), "{field}");
    }
    assert_eq!(result(&page, "accuracy.slices"), "100");
    // The warnings by code, as many as the answer has.
    let warnings = answer["warnings"].as_array().unwrap();
    assert!(!warnings.is_empty());
    for w in warnings {
        let code = w["code"].as_str().unwrap();
        assert!(
            page.contains(&format!("<li><code>{code}</code>: ")),
            "{code}"
        );
    }
    // All 100 slices, every cell the JSON answer's to six significant figures.
    let slices = between(&page, "<h2>Slices</h2>", "</table>");
    let rows: Vec<Vec<&str>> = slices
        .split("<tr>")
        .skip(2) // before the header, the header
        .map(|row| {
            row.split("<td class=\"n\">")
                .skip(1)
                .map(|c| c.split("</td>").next().unwrap())
                .collect()
        })
        .collect();
    assert_eq!(rows.len(), 100);
    let columns = [
        "slice",
        "x_left",
        "x_right",
        "layer",
        "base_inclination_deg",
        "base_length",
        "height",
        "weight",
    ];
    for (row, json) in rows.iter().zip(answer["slices"].as_array().unwrap()) {
        for (cell, name) in row.iter().zip(columns) {
            let (shown, exact) = (cell.parse::<f64>().unwrap(), json[name].as_f64().unwrap());
            assert!(
                (shown - exact).abs() <= 5e-6 * exact.abs() + 1e-12,
                "{name}: {cell} vs {exact}"
            );
        }
    }
    // The inputs as read: the cohesion given, and a default written out (the method's θ guess
    // is not; the slice count is).
    let inputs = between(&page, "<pre id=\"inputs\">", "</pre>");
    let read: Value = serde_json::from_str(&inputs.replace("&quot;", "\"")).unwrap();
    assert_eq!(read["soil"]["cohesion"], body["soil"]["cohesion"]);
    assert_eq!(read["slices"], 100);
}

#[tokio::test]
async fn arch_reports_print_the_factor_hinges_and_stops() {
    let server = Server::start().await;
    // Milankovitch, N = 1800, D = 1.0747 collapses with five hinges (model §1.4), and has no
    // line of thrust.
    let (status, headers, page) = report(
        &server,
        "/arch/dead-load/report",
        "m-1",
        &milankovitch(1.0747),
    )
    .await;
    assert_eq!(status, 200, "{page}");
    check_page(&headers, &page, "m-1");
    assert_eq!(
        between(&page, "id=\"headline\">", "</p>"),
        "Dead load: λ₀ = 0 (collapses)"
    );
    assert_eq!(result(&page, "dead_load_factor"), "0.0");
    assert_eq!(
        between(&page, "<h2>Line of thrust</h2>", "</p>"),
        "<p>No rows."
    );
    let hinges = between(&page, "<h2>Hinges</h2>", "</table>");
    for interface in [1, 356, 901, 1446, 1801] {
        assert!(
            hinges.contains(&format!("<tr><td class=\"n\">{interface}</td>")),
            "{interface}"
        );
    }
    // D = 1.5 stands; its line of thrust has 1801 rows, of which the report prints 200 and
    // counts the rest.
    let (status, _, page) =
        report(&server, "/arch/dead-load/report", "m-2", &milankovitch(1.5)).await;
    assert_eq!(status, 200, "{page}");
    assert_eq!(
        between(&page, "id=\"headline\">", "</p>"),
        "Dead load: λ₀ = 1 (stands)"
    );
    let thrust = between(&page, "<h2>Line of thrust</h2>", "</table>");
    assert_eq!(thrust.matches("<tr><td").count(), 200);
    assert!(
        page.contains("… and 1601 more rows"),
        "the thrust line is cut"
    );
    // A live load near the quarter span: λ = 22.9969 (docs/arches.md); two axles rolled over a
    // filled arch: λ at 101 stops, the critical 0.6413 (the route's OpenAPI example).
    let quarter = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
                         "loads": [{"block": 26, "fy": -1.0}]});
    let (status, headers, page) = report(&server, "/arch/live-load/report", "q", &quarter).await;
    assert_eq!(status, 200, "{page}");
    check_page(&headers, &page, "q");
    assert_eq!(
        between(&page, "id=\"headline\">", "</p>"),
        "Live load: λ = 22.9969"
    );
    let rolling = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
                         "fill": {"unit_weight": 1.8, "surface": 11.5},
                         "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}],
                                     "x_start": -12.0, "x_end": 10.0, "positions": 101}});
    let (status, _, page) = report(&server, "/arch/live-load/report", "r", &rolling).await;
    assert_eq!(status, 200, "{page}");
    assert_eq!(
        between(&page, "id=\"headline\">", "</p>"),
        "Live load: λ = 0.6413"
    );
    let stops = between(
        &page,
        "<h2>λ at each stop of the rolling load</h2>",
        "</table>",
    );
    assert_eq!(stops.matches("<tr><td").count(), 101);
}

#[tokio::test]
async fn reports_escape_what_clients_send_and_refuse_bad_requests() {
    let server = Server::start().await;
    // A request id with markup is printed as text.
    let (status, _, page) = report(
        &server,
        "/slope/spencer/report",
        "<b>x</b>",
        &spencer_example(),
    )
    .await;
    assert_eq!(status, 200);
    assert!(page.contains("&lt;b&gt;x&lt;/b&gt;"));
    assert!(!page.contains("<b>x</b>"));
    // A bad request is the same problem as on the JSON route.
    let bad = common::with(spencer_example(), "slices", json!(0));
    let (status, content_type, problem) = server.post("/slope/spencer/report", &bad).await;
    common::assert_problem(status, &content_type, &problem, 422, "slices");
    let (status, content_type, problem) = server
        .post(
            "/arch/dead-load/report",
            &json!({"geometry": {"kind": "circular"}}),
        )
        .await;
    assert_eq!(status, 422, "{problem}");
    assert_eq!(content_type, "application/problem+json");
}
