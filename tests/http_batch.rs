//! `POST /batch`: NDJSON lines answered in order, each exactly as its route answers the same
//! body alone (the times aside), each with its own status; the batch refused as a whole only
//! when it is not a batch; its time limit and a client that goes away stop its lines.
// Test helpers: a failed request or a malformed answer should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use std::time::Duration;

use common::{milankovitch, spencer_example, Server};
use serde_json::{json, Value};

/// POSTs `text` to /batch as `content_type`; the status, content type and body.
async fn send(server: &Server, content_type: &str, text: String) -> (u16, String, String) {
    let response = server
        .client
        .post(format!("{}/batch", server.base))
        .header("content-type", content_type)
        .header("x-request-id", "fleet-1")
        .body(text)
        .send()
        .await
        .unwrap();
    let status = response.status().as_u16();
    let content_type = Server::content_type(&response);
    (status, content_type, response.text().await.unwrap())
}

/// The batch's answer lines.
fn answers(text: &str) -> Vec<Value> {
    assert!(text.ends_with('\n'), "every answer line ends in a newline");
    text.lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// A copy without the wall times, which differ between two solves of the same request.
fn timeless(value: &Value) -> Value {
    match value {
        Value::Object(map) => Value::Object(
            map.iter()
                .filter(|(k, _)| !k.ends_with("time_ms") && !k.ends_with("_ms"))
                .map(|(k, v)| (k.clone(), timeless(v)))
                .collect(),
        ),
        Value::Array(items) => Value::Array(items.iter().map(timeless).collect()),
        other => other.clone(),
    }
}

fn line(route: &str, body: &Value) -> String {
    json!({"route": route, "body": body}).to_string()
}

/// An arch with Livesley's general formulation at N = 10,000: a few hundred milliseconds per
/// solve in a release build, seconds in a debug one.
fn slow_arch() -> Value {
    json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0747,
                        "voussoirs": 10_000},
           "formulation": "assembly"})
}

#[tokio::test]
async fn each_line_is_its_route_s_answer_in_order() {
    let server = Server::start().await;
    let quarter = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5,
                                      "voussoirs": 100},
                         "loads": [{"block": 26, "fy": -1.0}]});
    let minimum = json!({"geometry": {"kind": "circular", "radius": 10.0, "voussoirs": 200}});
    let bad_slices = common::with(spencer_example(), "slices", json!(0));
    let lines = [
        ("/slope/spencer", spencer_example()),
        ("/arch/dead-load", milankovitch(1.0747)),
        ("/arch/live-load", quarter),
        ("/arch/minimum-thickness", minimum),
        ("/slope/spencer", bad_slices),
        ("/arch/dead-load", milankovitch(1.5)),
    ];
    // Blank lines and CRLF line ends are allowed; blank lines are not counted.
    let text = lines
        .iter()
        .map(|(route, body)| line(route, body))
        .collect::<Vec<_>>()
        .join("\r\n\n");
    let (status, content_type, text) = send(&server, "application/x-ndjson", text).await;
    assert_eq!(status, 200, "{text}");
    assert_eq!(content_type, "application/x-ndjson");
    let answers = answers(&text);
    assert_eq!(answers.len(), lines.len());
    for (i, ((route, body), answer)) in lines.iter().zip(&answers).enumerate() {
        assert_eq!(answer["line"], i + 1);
        let (alone_status, _, alone) = server.post(route, body).await;
        assert_eq!(answer["status"], alone_status, "line {}", i + 1);
        if alone_status == 200 {
            assert_eq!(
                timeless(&answer["body"]),
                timeless(&alone),
                "line {}",
                i + 1
            );
        } else {
            // The same problem, with the batch's id and the line as its instance.
            assert_eq!(answer["body"]["detail"], alone["detail"]);
            assert_eq!(answer["body"]["code"], "out_of_range");
            assert_eq!(answer["body"]["instance"], format!("fleet-1:{}", i + 1));
        }
    }
    // The published numbers come through: Spencer's F (model §2.3), Milankovitch's hinges
    // (model §1.4), the quarter-span λ (docs/arches.md).
    assert!((answers[0]["body"]["factor_of_safety"].as_f64().unwrap() - 1.06958).abs() < 5e-6);
    assert_eq!(answers[1]["body"]["dead_load_factor"], 0.0);
    assert!((answers[2]["body"]["load_factor"].as_f64().unwrap() - 22.996889652).abs() < 1e-6);
}

#[tokio::test]
async fn bad_lines_are_answered_and_the_rest_go_on() {
    let server = Server::start().await;
    let good = line("/arch/dead-load", &milankovitch(1.5));
    let text = [
        "not json".to_owned(),
        json!({"route": "/arch/anything", "body": {}}).to_string(),
        json!({"route": "/arch/dead-load", "body": {}, "extra": 1}).to_string(),
        json!({"body": {}}).to_string(),
        json!({"route": "/arch/dead-load", "body": {"geometry": {"kind": "circular"}}}).to_string(),
        good,
    ]
    .join("\n");
    let (status, _, text) = send(&server, "application/jsonl", text).await;
    assert_eq!(status, 200, "{text}");
    let answers = answers(&text);
    let expected = [
        (400, "invalid_json", None),
        (422, "invalid_value", Some("route")),
        (422, "unknown_field", Some("extra")),
        (422, "missing_field", Some("route")),
        (422, "missing_field", Some("geometry.radius")),
    ];
    for (i, (status, code, named)) in expected.into_iter().enumerate() {
        let answer = &answers[i];
        assert_eq!(answer["status"], status, "line {}: {answer}", i + 1);
        assert_eq!(answer["body"]["code"], code, "line {}: {answer}", i + 1);
        assert_eq!(answer["body"]["instance"], format!("fleet-1:{}", i + 1));
        if let Some(name) = named {
            let detail = answer["body"]["detail"].as_str().unwrap();
            assert!(
                detail.contains(name.split('.').next_back().unwrap()),
                "line {}: {detail}",
                i + 1
            );
            assert_eq!(answer["body"]["field"], name, "line {}: {answer}", i + 1);
            assert!(!detail.contains(" at line "), "{detail}");
        }
    }
    assert_eq!(answers[5]["status"], 200);
    assert_eq!(answers[5]["body"]["dead_load_factor"], 1.0);
}

#[tokio::test]
async fn what_is_not_a_batch_is_refused_whole() {
    let server = Server::start().await;
    let one = line("/arch/dead-load", &milankovitch(1.5));
    let (status, content_type, text) = send(&server, "application/json", one.clone()).await;
    assert_eq!(
        (status, content_type.as_str()),
        (415, "application/problem+json"),
        "{text}"
    );
    assert!(text.contains("application/x-ndjson"), "{text}");
    for empty in ["", "\n\n  \n"] {
        let (status, _, text) = send(&server, "application/x-ndjson", empty.to_owned()).await;
        assert_eq!(status, 422, "{text}");
        let problem: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(problem["field"], "body");
    }
    // 10,001 lines (each small) are over the line limit, under the body limit.
    let many = vec!["{}"; 10_001].join("\n");
    let (status, _, text) = send(&server, "application/x-ndjson", many).await;
    assert_eq!(status, 422, "{text}");
    assert!(text.contains("1 to 10000 lines"), "{text}");
    let response = server
        .client
        .post(format!("{}/batch", server.base))
        .header("content-type", "application/x-ndjson")
        .body(vec![0xff_u8, 0xfe, b'\n'])
        .send()
        .await
        .unwrap();
    assert_eq!(response.status().as_u16(), 400);
}

#[tokio::test]
async fn the_batch_time_limit_answers_the_lines_left_503() {
    // One worker and a 200 ms batch: five solves of a few hundred milliseconds each (or more)
    // cannot all finish; those cut or not started are 503 over_time_limit, in order.
    let server = Server::start_with(thrustline::Settings {
        max_running: 1,
        batch_timeout: Duration::from_millis(200),
        ..Default::default()
    })
    .await;
    let text = vec![line("/arch/dead-load", &slow_arch()); 5].join("\n");
    let (status, _, text) = send(&server, "application/x-ndjson", text).await;
    assert_eq!(status, 200);
    let answers = answers(&text);
    assert_eq!(answers.len(), 5);
    let last = &answers[4];
    assert_eq!(last["status"], 503, "{last}");
    assert_eq!(last["body"]["code"], "over_time_limit");
    assert!(last["body"]["detail"]
        .as_str()
        .unwrap()
        .contains("THRUSTLINE_BATCH_TIMEOUT_SECS"));
    // Once a line is over the limit, every later one is too.
    let first_over = answers.iter().position(|a| a["status"] == 503).unwrap();
    assert!(answers[first_over..].iter().all(|a| a["status"] == 503));
    // Nothing is left running: the line cut at the limit was cancelled.
    assert_eq!(settled(&server).await, 0);
}

/// Solves running and waiting once they settle (the cancelled ones see their cancellation at
/// their next budget check), polled for up to 5 s.
async fn settled(server: &Server) -> u64 {
    let mut left = u64::MAX;
    for _ in 0..100 {
        left = server.solves_running().await;
        if left == 0 {
            break;
        }
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    left
}

#[tokio::test]
async fn a_client_that_goes_away_cancels_its_lines() {
    // 100 slow lines on one worker are tens of seconds of work: the pool must be empty within
    // seconds of the client dropping the answer after its first line.
    let server = Server::start_with(thrustline::Settings {
        max_running: 1,
        ..Default::default()
    })
    .await;
    let text = vec![line("/arch/dead-load", &slow_arch()); 100].join("\n");
    let mut response = server
        .client
        .post(format!("{}/batch", server.base))
        .header("content-type", "application/x-ndjson")
        .body(text)
        .send()
        .await
        .unwrap();
    let mut read = Vec::new();
    while !read.contains(&b'\n') {
        read.extend_from_slice(&response.chunk().await.unwrap().unwrap());
    }
    let end = read.iter().position(|&b| b == b'\n').unwrap();
    let first: Value = serde_json::from_slice(&read[..end]).unwrap();
    assert_eq!(first["line"], 1);
    assert_eq!(first["status"], 200);
    drop(response);
    let mut left = u64::MAX;
    for _ in 0..100 {
        left = server.solves_running().await;
        if left == 0 {
            break;
        }
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    assert_eq!(
        left, 0,
        "the batch's lines kept running after the client left"
    );
}
