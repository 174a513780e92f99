//! The `…/csv` routes: every table of every solve route is the JSON answer's array, cell for
//! cell — read here with a CSV reader written for the test, compared with the JSON answer of
//! the same request.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use common::{milankovitch, spencer_example, Server};
use serde_json::{json, Value};

/// The CSV's rows as cells (the tables hold numbers, booleans and snake_case names: no quoting).
fn cells(text: &str) -> Vec<Vec<String>> {
    assert!(!text.contains('"'), "unexpected quoting: {text}");
    text.lines()
        .map(|line| line.split(',').map(str::to_owned).collect())
        .collect()
}

/// A cell against the JSON value it stands for: numbers equal as f64 (both written shortest
/// round-trip), null as an empty cell, strings and booleans as written.
fn same(cell: &str, value: &Value) -> bool {
    match value {
        Value::Null => cell.is_empty(),
        Value::Number(n) => cell.parse::<f64>().ok() == n.as_f64(),
        Value::Bool(b) => cell == b.to_string(),
        Value::String(s) => cell == s,
        _ => false,
    }
}

/// The table `table` of `path` as CSV against `rows` of the JSON answer: the header is the rows'
/// keys, every cell its value. Returns the number of rows.
async fn check_table(
    server: &Server,
    path: &str,
    table: &str,
    body: &Value,
    rows: &[Value],
) -> usize {
    let (status, content_type, text) = server
        .post_accept(&format!("{path}/csv?table={table}"), "text/csv", body)
        .await;
    assert_eq!(status, 200, "{path} {table}: {text}");
    assert!(content_type.starts_with("text/csv"), "{content_type}");
    let cells = cells(&text);
    let (header, data) = cells.split_first().expect("a header row");
    assert_eq!(data.len(), rows.len(), "{path} {table}");
    for (row, json) in data.iter().zip(rows) {
        let object = json.as_object().unwrap();
        assert_eq!(header.len(), object.len(), "{path} {table}: {header:?}");
        for (name, cell) in header.iter().zip(row) {
            let value = object
                .get(name)
                .unwrap_or_else(|| panic!("{table}: no {name}"));
            assert!(
                same(cell, value),
                "{path} {table} {name}: {cell} vs {value}"
            );
        }
    }
    data.len()
}

fn array(value: &Value) -> Vec<Value> {
    value.as_array().cloned().unwrap_or_default()
}

#[tokio::test]
async fn arch_tables_are_the_json_answer() {
    let server = Server::start().await;
    let live = json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
        "loads": [{"block": 26, "fy": -1.0}]
    });
    let (status, _, answer) = server.post("/arch/live-load", &live).await;
    assert_eq!(status, 200);
    assert_eq!(
        check_table(
            &server,
            "/arch/live-load",
            "thrust_line",
            &live,
            &array(&answer["thrust_line"])
        )
        .await,
        101
    );
    assert_eq!(
        check_table(
            &server,
            "/arch/live-load",
            "hinges",
            &live,
            &array(&answer["hinges"])
        )
        .await,
        4
    );
    check_table(
        &server,
        "/arch/live-load",
        "active_constraints",
        &live,
        &array(&answer["active_constraints"]),
    )
    .await;
    assert_eq!(
        check_table(
            &server,
            "/arch/live-load",
            "reactions",
            &live,
            &array(&answer["reactions"])
        )
        .await,
        2
    );
    assert_eq!(
        check_table(
            &server,
            "/arch/live-load",
            "mechanism",
            &live,
            &array(&answer["mechanism"]["blocks"])
        )
        .await,
        100
    );

    // No table asked: the thrust line. A structure that stands has no hinges: the header alone.
    let stands = milankovitch(1.5);
    let (_, _, text) = server
        .post_accept("/arch/dead-load/csv", "*/*", &stands)
        .await;
    assert!(text.starts_with("interface,x,y,normal_force"), "{text}");
    assert_eq!(text.lines().count(), 1802);
    let (_, _, text) = server
        .post_accept("/arch/dead-load/csv?table=hinges", "text/csv", &stands)
        .await;
    assert_eq!(
        text.trim_end(),
        "interface,angle_deg,location,x,y,span_distance,span_fraction,rotation"
    );

    // Minimum thickness: its hinges.
    let minimum = json!({"geometry": {"kind": "circular", "radius": 10.0, "voussoirs": 40}});
    let (_, _, answer) = server.post("/arch/minimum-thickness", &minimum).await;
    assert!(
        check_table(
            &server,
            "/arch/minimum-thickness",
            "hinges",
            &minimum,
            &array(&answer["hinges"])
        )
        .await
            >= 4
    );
    check_table(
        &server,
        "/arch/minimum-thickness",
        "active_constraints",
        &minimum,
        &array(&answer["active_constraints"]),
    )
    .await;

    // Rolling stops, as (position, load_factor) rows of the JSON's two arrays.
    let rolling = json!({
        "geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 40},
        "fill": {"unit_weight": 1.8, "surface": 11.5},
        "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}], "x_start": -8.0, "x_end": 8.0, "positions": 5}
    });
    let (status, _, answer) = server.post("/arch/live-load", &rolling).await;
    assert_eq!(status, 200, "{answer}");
    let rows: Vec<Value> = array(&answer["rolling"]["positions"])
        .iter()
        .zip(array(&answer["rolling"]["load_factor"]))
        .map(|(p, f)| json!({"position": p, "load_factor": f}))
        .collect();
    assert_eq!(
        check_table(&server, "/arch/live-load", "rolling", &rolling, &rows).await,
        5
    );
}

#[tokio::test]
async fn slope_tables_are_the_json_answer() {
    let server = Server::start().await;
    let example = spencer_example();
    let (_, _, answer) = server.post("/slope/spencer", &example).await;
    assert_eq!(
        check_table(
            &server,
            "/slope/spencer",
            "slices",
            &example,
            &array(&answer["slices"])
        )
        .await,
        100
    );
    assert_eq!(
        check_table(
            &server,
            "/slope/spencer",
            "thrust_line",
            &example,
            &array(&answer["thrust_line"])
        )
        .await,
        99
    );
    check_table(
        &server,
        "/slope/spencer",
        "effective_thrust_line",
        &example,
        &array(&answer["effective_thrust_line"]),
    )
    .await;
    check_table(
        &server,
        "/slope/spencer",
        "surface",
        &example,
        &array(&answer["surface"]),
    )
    .await;

    let mut search = spencer_example();
    search.as_object_mut().unwrap().remove("circle");
    search["search"] = json!({"nx": 4, "ny": 3});
    search["slices"] = json!(20);
    let (status, _, answer) = server.post("/slope/spencer", &search).await;
    assert_eq!(status, 200, "{answer}");
    let grid = &answer["grid"];
    let mut rows = Vec::new();
    for j in 0..3 {
        for i in 0..4 {
            rows.push(json!({"x": grid["xs"][i], "y": grid["ys"][j],
                             "x_absolute": grid["x_absolute"][i], "y_absolute": grid["y_absolute"][j],
                             "factor_of_safety": grid["factor_of_safety"][j][i]}));
        }
    }
    assert_eq!(
        check_table(&server, "/slope/spencer", "grid", &search, &rows).await,
        12
    );
}

#[tokio::test]
async fn tables_are_asked_for_and_refused_clearly() {
    let server = Server::start().await;
    let example = spencer_example();
    // A JSON route answers JSON whatever the client accepts (one type per route for typed
    // clients), and a CSV route CSV: the route says what comes back, not Accept.
    for accept in ["text/csv", "application/json, text/csv;q=0.5", "*/*"] {
        let (status, content_type, text) = server
            .post_accept("/slope/spencer?table=slices", accept, &example)
            .await;
        assert_eq!(status, 200);
        assert!(
            content_type.starts_with("application/json"),
            "{accept}: {content_type}"
        );
        assert!(text.starts_with('{'), "{text}");
        let (status, content_type, text) = server
            .post_accept("/slope/spencer/csv", accept, &example)
            .await;
        assert_eq!(status, 200);
        assert_eq!(content_type, "text/csv; charset=utf-8; header=present");
        assert!(text.starts_with("slice,x_left,x_right,layer"), "{text}");
    }
    // A table the route does not have, or that the answer does not have.
    for (path, body) in [
        ("/slope/spencer/csv?table=hinges", example.clone()),
        ("/slope/spencer/csv?table=grid", example.clone()),
        ("/arch/dead-load/csv?table=rolling", milankovitch(1.5)),
        ("/arch/live-load/csv?table=rolling", {
            let mut live = milankovitch(1.5);
            live["loads"] = json!([{"block": 26, "fy": -1.0}]);
            live
        }),
        (
            "/arch/minimum-thickness/csv?table=thrust_line",
            milankovitch(1.5),
        ),
    ] {
        let (status, content_type, text) = server.post_accept(path, "text/csv", &body).await;
        assert_eq!(status, 422, "{path}: {text}");
        assert_eq!(content_type, "application/problem+json");
        let problem: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(problem["field"], "table", "{path}: {problem}");
        // The parameter is named once, not "table: table: …".
        let detail = problem["detail"].as_str().unwrap();
        assert!(!detail.contains("table: table"), "{path}: {detail}");
    }
    // A table that include left out is refused, not answered as a header alone.
    let mut lean = example.clone();
    lean["include"] = json!([]);
    let (status, _, text) = server
        .post_accept("/slope/spencer/csv?table=slices", "text/csv", &lean)
        .await;
    assert_eq!(status, 422, "{text}");
    assert!(text.contains("include left out"), "{text}");
}
