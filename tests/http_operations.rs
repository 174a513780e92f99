//! Operations over a real socket: bearer token, CORS, metrics, request ids, overload.

mod common;

use common::{spencer_example, Server};
use serde_json::json;

/// An arch solved with Livesley's general formulation (slower than the chain).
fn assembly_arch(voussoirs: usize) -> serde_json::Value {
    json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0747,
                        "voussoirs": voussoirs},
           "formulation": "assembly"})
}

fn slow_arch() -> serde_json::Value {
    // Livesley's general formulation at N = 10000: a few hundred milliseconds per solve.
    assembly_arch(10_000)
}

#[tokio::test]
async fn bearer_token_guards_everything_but_healthz() {
    let server = Server::start_with(thrustline::Settings {
        token: Some("s3cret".to_owned()),
        ..Default::default()
    })
    .await;
    let (status, content_type, body) = server.post("/slope/spencer", &spencer_example()).await;
    assert_eq!(
        (status, content_type.as_str()),
        (401, "application/problem+json"),
        "{body}"
    );
    for path in ["/metrics", "/openapi.json"] {
        assert_eq!(server.get(path).await.0, 401, "{path}");
    }
    assert_eq!(server.get("/healthz").await.0, 200);
    let url = format!("{}/slope/spencer", server.base);
    let wrong = server
        .client
        .post(&url)
        .bearer_auth("s3creT")
        .json(&spencer_example())
        .send()
        .await
        .unwrap();
    assert_eq!(wrong.status().as_u16(), 401);
    assert_eq!(wrong.headers()["www-authenticate"], "Bearer");
    let right = server
        .client
        .post(&url)
        .bearer_auth("s3cret")
        .json(&spencer_example())
        .send()
        .await
        .unwrap();
    assert_eq!(right.status().as_u16(), 200);
    // The refusals are counted, by the route they were refused on.
    let metrics = server
        .client
        .get(format!("{}/metrics", server.base))
        .bearer_auth("s3cret")
        .send()
        .await
        .unwrap()
        .text()
        .await
        .unwrap();
    for line in [
        "thrustline_requests_total{route=\"/slope/spencer\",status=\"401\"} 2",
        "thrustline_requests_total{route=\"/openapi.json\",status=\"401\"} 1",
        "thrustline_requests_total{route=\"/slope/spencer\",status=\"200\"} 1",
    ] {
        assert!(metrics.contains(line), "{line} in {metrics}");
    }
}

#[tokio::test]
async fn cors_only_when_configured() {
    let closed = Server::start().await;
    let response = closed
        .client
        .get(format!("{}/healthz", closed.base))
        .header("origin", "https://dash.example")
        .send()
        .await
        .unwrap();
    assert!(response
        .headers()
        .get("access-control-allow-origin")
        .is_none());
    let open = Server::start_with(thrustline::Settings {
        cors_origins: vec!["https://dash.example".to_owned()],
        ..Default::default()
    })
    .await;
    let response = open
        .client
        .get(format!("{}/healthz", open.base))
        .header("origin", "https://dash.example")
        .send()
        .await
        .unwrap();
    assert_eq!(
        response.headers()["access-control-allow-origin"],
        "https://dash.example"
    );
    // Issue 39: the dashboard can read Retry-After and the request id.
    let exposed = response.headers()["access-control-expose-headers"]
        .to_str()
        .unwrap()
        .to_ascii_lowercase();
    assert!(
        exposed.contains("retry-after") && exposed.contains("x-request-id"),
        "{exposed}"
    );
    // A preflight allows sending its own request id, and is cached for 10 minutes.
    let preflight = open
        .client
        .request(
            reqwest::Method::OPTIONS,
            format!("{}/slope/spencer", open.base),
        )
        .header("origin", "https://dash.example")
        .header("access-control-request-method", "POST")
        .header(
            "access-control-request-headers",
            "content-type, x-request-id",
        )
        .send()
        .await
        .unwrap();
    assert!(preflight.status().is_success(), "{}", preflight.status());
    let allowed = preflight.headers()["access-control-allow-headers"]
        .to_str()
        .unwrap()
        .to_ascii_lowercase();
    assert!(
        allowed.contains("x-request-id") && allowed.contains("content-type"),
        "{allowed}"
    );
    assert_eq!(preflight.headers()["access-control-max-age"], "600");
}

#[tokio::test]
async fn metrics_count_requests_and_solves_and_ids_are_returned() {
    let server = Server::start().await;
    server.post("/slope/spencer", &spencer_example()).await;
    let mut bad = spencer_example();
    bad["slices"] = json!(0);
    server.post("/slope/spencer", &bad).await;
    // Unknown paths, the document and the docs are counted too (unknown paths under one label).
    server.get("/nowhere").await;
    server.get("/elsewhere").await;
    server.get("/openapi.json").await;
    server.get("/docs/missing.js").await;
    let response = server
        .client
        .get(format!("{}/metrics", server.base))
        .send()
        .await
        .unwrap();
    assert!(response.headers()["content-type"]
        .to_str()
        .unwrap()
        .starts_with("text/plain"));
    assert!(response.headers().get("x-request-id").is_some());
    let text = response.text().await.unwrap();
    assert!(
        text.contains("thrustline_requests_total{route=\"/slope/spencer\",status=\"200\"} 1"),
        "{text}"
    );
    assert!(
        text.contains("thrustline_requests_total{route=\"/slope/spencer\",status=\"422\"} 1"),
        "{text}"
    );
    assert!(
        text.contains("thrustline_requests_total{route=\"unmatched\",status=\"404\"} 2"),
        "{text}"
    );
    assert!(
        text.contains("thrustline_requests_total{route=\"/openapi.json\",status=\"200\"} 1"),
        "{text}"
    );
    assert!(text.contains("status=\"404\"} 1"), "{text}");
    assert!(text.contains("thrustline_solve_seconds_count 1"), "{text}");
    assert!(text.contains("thrustline_solve_queue_depth 0"), "{text}");
}

#[tokio::test]
async fn overload_is_503_with_retry_after_not_a_queue() {
    let server = Server::start_with(thrustline::Settings {
        max_running: 1,
        max_queued: 0,
        ..Default::default()
    })
    .await;
    let url = format!("{}/arch/dead-load", server.base);
    let send = || server.client.post(&url).json(&slow_arch()).send();
    let (a, b) = tokio::join!(send(), send());
    let (a, b) = (a.unwrap(), b.unwrap());
    let mut statuses = [a.status().as_u16(), b.status().as_u16()];
    statuses.sort_unstable();
    assert_eq!(statuses, [200, 503]);
    let rejected = if a.status() == 503 { a } else { b };
    assert_eq!(rejected.headers()["retry-after"], "1");
    assert_eq!(
        rejected.headers()["content-type"],
        "application/problem+json"
    );
    let problem: serde_json::Value = rejected.json().await.unwrap();
    assert_eq!(problem["code"], "busy", "{problem}");
}

#[tokio::test]
async fn a_search_over_its_time_limit_is_422() {
    let server = Server::start_with(thrustline::Settings {
        solve_timeout: std::time::Duration::from_millis(1),
        ..Default::default()
    })
    .await;
    let mut body = spencer_example();
    body.as_object_mut().unwrap().remove("circle");
    body["search"] = json!({"nx": 101, "ny": 101});
    body["slices"] = json!(500);
    let (status, content_type, body) = server.post("/slope/spencer", &body).await;
    assert_eq!(
        (status, content_type.as_str()),
        (422, "application/problem+json"),
        "{body}"
    );
    assert!(body["detail"].as_str().unwrap().contains("did not finish"));
    assert_eq!(body["code"], "over_time_limit", "{body}");
}

#[tokio::test]
async fn every_solver_stopped_by_the_time_limit_is_the_same_422() {
    // The README's outcome rule: a solver that stops itself at the solve time limit answers 422
    // naming the field that sets the work, never a 200 without a number.
    let server = Server::start_with(thrustline::Settings {
        solve_timeout: std::time::Duration::from_micros(200),
        ..Default::default()
    })
    .await;
    // A layered section with water, loads and a crack: its slices cost several times the
    // simple slope's, so its doublings outlast the 200 µs limit on any machine (the whole
    // refinement of the simple slope to 5,120 slices now takes 1–2 ms).
    let refine = json!({"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
        "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                   {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
        "bedrock": [[-20, -12], [40, -12]],
        "piezometric_line": [[-20, 1], [10, 3], [40, 6]],
        "surcharges": [{"x_start": 25, "x_end": 35, "pressure": 20}],
        "line_loads": [{"x": 30, "fx": 0, "fy": -50}],
        "tension_crack": {"depth": 2.5, "water_depth": 2.5}},
        "circle": {"centre": [12, 28], "radius": 26}, "slices": 10, "slice_tolerance": 1e-9});
    let minimum = json!({"geometry": {"kind": "circular", "radius": 10.0, "voussoirs": 10000},
                         "tolerance": 1e-9});
    for (path, body, field) in [
        ("/arch/dead-load", assembly_arch(1000), "geometry"),
        ("/arch/minimum-thickness", minimum, "tolerance"),
        ("/slope/spencer", refine, "slice_tolerance"),
    ] {
        let (status, content_type, body) = server.post(path, &body).await;
        assert_eq!(
            (status, content_type.as_str()),
            (422, "application/problem+json"),
            "{path}: {body}"
        );
        assert_eq!(body["field"], field, "{path}: {body}");
        assert!(
            body["detail"]
                .as_str()
                .unwrap()
                .contains("solve time limit"),
            "{path}: {body}"
        );
    }
}

#[tokio::test]
async fn graceful_shutdown_finishes_the_request_in_flight() {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    let (stop, stopped) = tokio::sync::oneshot::channel::<()>();
    let server = tokio::spawn(thrustline::serve(
        listener,
        thrustline::Settings::default(),
        async {
            let _ = stopped.await;
        },
    ));
    let client = reqwest::Client::new();
    let url = format!("http://{addr}/arch/dead-load");
    let request = tokio::spawn(async move { client.post(&url).json(&slow_arch()).send().await });
    tokio::time::sleep(std::time::Duration::from_millis(150)).await;
    stop.send(()).unwrap();
    let response = request.await.unwrap().unwrap();
    assert_eq!(response.status().as_u16(), 200);
    let body: serde_json::Value = response.json().await.unwrap();
    assert_eq!(body["dead_load_factor"], 0.0);
    // The server has stopped: the task ends and new connections are refused.
    tokio::time::timeout(std::time::Duration::from_secs(10), server)
        .await
        .unwrap()
        .unwrap()
        .unwrap();
    assert!(reqwest::get(format!("http://{addr}/healthz"))
        .await
        .is_err());
}

#[tokio::test]
async fn a_client_holding_a_partial_request_does_not_stop_the_shutdown() {
    // Issue 18, item 1: `printf 'GET /'` on a kept-open socket used to keep the process up.
    use std::io::Write;
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    let (stop, stopped) = tokio::sync::oneshot::channel::<()>();
    let settings = thrustline::Settings {
        drain_timeout: std::time::Duration::from_millis(300),
        ..Default::default()
    };
    let server = tokio::spawn(thrustline::serve(listener, settings, async {
        let _ = stopped.await;
    }));
    let mut socket = std::net::TcpStream::connect(addr).unwrap();
    socket.write_all(b"GET /").unwrap();
    tokio::time::sleep(std::time::Duration::from_millis(100)).await;
    stop.send(()).unwrap();
    tokio::time::timeout(std::time::Duration::from_secs(5), server)
        .await
        .expect("the server stops within the drain time")
        .unwrap()
        .unwrap();
    drop(socket);
}

#[tokio::test]
async fn answers_carry_safe_headers_and_bounded_ids() {
    // Issue 18, items 6–8: nosniff everywhere, no-store on computed answers, a policy on the
    // page; a 100 KB request id is replaced, not echoed; a 1 MB unknown key is not echoed whole;
    // the scheme of the token is case-insensitive.
    let server = Server::start_with(thrustline::Settings {
        token: Some("s3cret".to_owned()),
        ..Default::default()
    })
    .await;
    let url = format!("{}/slope/spencer", server.base);
    let answer = server
        .client
        .post(&url)
        .header("authorization", "bearer s3cret")
        .header("x-request-id", "x".repeat(100_000))
        .json(&spencer_example())
        .send()
        .await
        .unwrap();
    assert_eq!(answer.status().as_u16(), 200);
    let headers = answer.headers();
    assert_eq!(headers["x-content-type-options"], "nosniff");
    assert_eq!(headers["cache-control"], "no-store");
    assert!(headers["x-request-id"].len() <= 128);
    let page = server
        .client
        .get(format!("{}/", server.base))
        .send()
        .await
        .unwrap();
    let policy = page.headers()["content-security-policy"].to_str().unwrap();
    assert!(policy.contains("frame-ancestors 'none'"), "{policy}");
    let mut body = spencer_example();
    body["x".repeat(1_000_000)] = json!(1);
    let answer = server
        .client
        .post(&url)
        .header("authorization", "Bearer s3cret")
        .json(&body)
        .send()
        .await
        .unwrap();
    assert_eq!(answer.status().as_u16(), 422);
    assert!(answer.text().await.unwrap().len() < 10_000);
}

#[tokio::test]
async fn arrays_are_not_read_as_objects() {
    // Issue 18, item 4: `"interface_limits": [null, null]` was read as q_min = null (tension
    // allowed) and answered `stable: true` for an arch that falls; any object given as an
    // array is now 422 naming it.
    let server = Server::start().await;
    let arch = json!({"kind": "circular", "radius": 10, "thickness": 0.5, "voussoirs": 100});
    let cases = [
        (
            "/arch/dead-load",
            json!({"geometry": arch, "interface_limits": [null, null]}),
            "interface_limits",
        ),
        (
            "/arch/dead-load",
            json!({"geometry": ["circular", 10, 0.5, 100]}),
            "geometry",
        ),
        (
            "/arch/live-load",
            json!({"geometry": arch, "loads": [[5, null, null, 0, -1]]}),
            "loads[0]",
        ),
        (
            "/slope/spencer",
            json!({"slope": [10, 20], "soil": {"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 30}, "circle": {"x": 5, "y": 20}}),
            "slope",
        ),
        ("/arch/dead-load", json!([{"kind": "circular"}]), "body"),
        // Not an object at all: the body is at fault, and says so.
        ("/arch/dead-load", json!(null), "body"),
        ("/slope/spencer", json!(5), "body"),
        ("/arch/minimum-thickness", json!("geometry"), "body"),
    ];
    for (path, body, field) in cases {
        let (status, content_type, answer) = server.post(path, &body).await;
        common::assert_problem(status, &content_type, &answer, 422, field);
    }
    // The same limits as an object are fine.
    let (status, _, answer) = server
        .post(
            "/arch/dead-load",
            &json!({"geometry": arch, "interface_limits": {}}),
        )
        .await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["stable"], false);
}

#[tokio::test]
async fn slow_and_idle_clients_are_cut_off() {
    // Issue 18, item 2: a client that never finishes its request head, or stays idle on a
    // kept-alive connection, is disconnected after the header timeout; a body that never
    // arrives is refused after the body timeout; connections beyond the cap are closed at once.
    use std::io::{Read, Write};
    let settings = thrustline::Settings {
        header_timeout: std::time::Duration::from_millis(300),
        body_timeout: std::time::Duration::from_millis(300),
        ..Default::default()
    };
    let server = Server::start_with(settings).await;
    let addr = server.base.trim_start_matches("http://").to_owned();
    let closed_within = |mut socket: std::net::TcpStream, seconds: u64| {
        socket
            .set_read_timeout(Some(std::time::Duration::from_secs(seconds)))
            .unwrap();
        let mut buffer = Vec::new();
        // A closed connection ends the read (Ok); a timeout is an error.
        socket.read_to_end(&mut buffer).is_ok()
    };
    let partial_head = tokio::task::spawn_blocking({
        let addr = addr.clone();
        move || {
            let mut socket = std::net::TcpStream::connect(addr).unwrap();
            socket
                .write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\n")
                .unwrap();
            closed_within(socket, 5)
        }
    });
    assert!(
        partial_head.await.unwrap(),
        "a partial head keeps its connection"
    );
    let idle = tokio::task::spawn_blocking({
        let addr = addr.clone();
        move || {
            let socket = std::net::TcpStream::connect(addr).unwrap();
            closed_within(socket, 5)
        }
    });
    assert!(idle.await.unwrap(), "an idle connection stays open");
    let slow_body = tokio::task::spawn_blocking({
        let addr = addr.clone();
        move || {
            let mut socket = std::net::TcpStream::connect(addr).unwrap();
            socket
                .write_all(
                    b"POST /slope/spencer HTTP/1.1\r\nHost: x\r\ncontent-type: application/json\r\ncontent-length: 100\r\n\r\n{",
                )
                .unwrap();
            socket
                .set_read_timeout(Some(std::time::Duration::from_secs(5)))
                .unwrap();
            let mut answer = [0u8; 12];
            socket.read_exact(&mut answer).map(|()| answer.to_vec())
        }
    });
    let answer = slow_body.await.unwrap().expect("an answer before 5 s");
    assert!(
        answer.starts_with(b"HTTP/1.1 4"),
        "{}",
        String::from_utf8_lossy(&answer)
    );
    // The cap: four idle connections held; beyond them a reserve of 16 connections answers
    // /healthz (issue 38, O3: 1,024 silent sockets locked out the liveness probe) and 503 to
    // anything else; with the reserve held too, the next connection is closed at once (long
    // before the header timeout of this second server).
    let server = Server::start_with(thrustline::Settings {
        header_timeout: std::time::Duration::from_secs(20),
        max_connections: 4,
        ..Default::default()
    })
    .await;
    let addr = server.base.trim_start_matches("http://").to_owned();
    let held: Vec<_> = (0..4)
        .map(|_| std::net::TcpStream::connect(&addr).unwrap())
        .collect();
    std::thread::sleep(std::time::Duration::from_millis(100));
    let ask = |request: &'static [u8]| {
        let addr = addr.clone();
        tokio::task::spawn_blocking(move || {
            let mut socket = std::net::TcpStream::connect(addr).unwrap();
            socket.write_all(request).unwrap();
            socket
                .set_read_timeout(Some(std::time::Duration::from_secs(5)))
                .unwrap();
            let mut answer = String::new();
            socket.read_to_string(&mut answer).map(|_| answer)
        })
    };
    let health = ask(b"GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n");
    let health = health.await.unwrap().expect("an answer and a close");
    assert!(health.starts_with("HTTP/1.1 200"), "{health}");
    assert!(health.contains(r#""status":"ok""#), "{health}");
    let solve = ask(b"POST /slope/spencer HTTP/1.1\r\nHost: x\r\ncontent-length: 2\r\n\r\n{}");
    let solve = solve.await.unwrap().expect("an answer and a close");
    assert!(solve.starts_with("HTTP/1.1 503"), "{solve}");
    assert!(
        solve.to_ascii_lowercase().contains("retry-after: 1"),
        "{solve}"
    );
    assert!(solve.contains("connection cap"), "{solve}");
    let reserve: Vec<_> = (0..thrustline::health::RESERVED_CONNECTIONS)
        .map(|_| std::net::TcpStream::connect(&addr).unwrap())
        .collect();
    std::thread::sleep(std::time::Duration::from_millis(100));
    let started = std::time::Instant::now();
    let next = tokio::task::spawn_blocking({
        let addr = addr.clone();
        move || closed_within(std::net::TcpStream::connect(addr).unwrap(), 5)
    });
    assert!(
        next.await.unwrap(),
        "the connection beyond the reserve was kept"
    );
    // Closed at once (the reserve's header timeout is 250 ms, the server's 20 s).
    assert!(started.elapsed() < std::time::Duration::from_millis(200));
    drop((held, reserve));
}

#[tokio::test]
async fn a_body_trickled_byte_by_byte_is_cut_off_at_the_body_deadline() {
    // Issue 38, O1: the body timeout was per chunk, so a body sent one byte every 100 ms was
    // never cut off. The whole body must arrive within the limit (300 ms here).
    use std::io::{Read, Write};
    let server = Server::start_with(thrustline::Settings {
        body_timeout: std::time::Duration::from_millis(300),
        ..Default::default()
    })
    .await;
    let addr = server.base.trim_start_matches("http://").to_owned();
    let trickled = tokio::task::spawn_blocking(move || {
        let mut socket = std::net::TcpStream::connect(addr).unwrap();
        socket
            .write_all(
                b"POST /slope/spencer HTTP/1.1\r\nHost: x\r\ncontent-type: application/json\r\n\
                  content-length: 100\r\n\r\n",
            )
            .unwrap();
        let started = std::time::Instant::now();
        socket.set_nonblocking(true).unwrap();
        let mut answer = Vec::new();
        // One byte every 50 ms, for up to 5 s, until the server answers.
        for _ in 0..100 {
            let mut buffer = [0u8; 1024];
            match socket.read(&mut buffer) {
                Ok(n) if n > 0 => {
                    answer.extend_from_slice(&buffer[..n]);
                    break;
                }
                _ => {}
            }
            if socket.write_all(b" ").is_err() {
                break;
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        (
            String::from_utf8_lossy(&answer).into_owned(),
            started.elapsed(),
        )
    });
    let (answer, took) = trickled.await.unwrap();
    assert!(
        answer.starts_with("HTTP/1.1 4"),
        "{answer:?} after {took:?}"
    );
    assert!(answer.contains("not sent within 0.3 s"), "{answer}");
    assert!(took < std::time::Duration::from_secs(2), "{took:?}");
}

#[tokio::test]
async fn compressed_and_oversized_bodies_are_refused_before_they_are_read() {
    // Issue 18, item 10: a gzip body was 400 (415 is right); `Expect: 100-continue` with an
    // over-limit Content-Length got `100 Continue` before its 413.
    use std::io::{Read, Write};
    let server = Server::start().await;
    let answer = server
        .client
        .post(format!("{}/slope/spencer", server.base))
        .header("content-type", "application/json")
        .header("content-encoding", "gzip")
        .body(vec![0x1f, 0x8b, 0x08, 0x00])
        .send()
        .await
        .unwrap();
    assert_eq!(answer.status().as_u16(), 415);
    let addr = server.base.trim_start_matches("http://").to_owned();
    let first_line = tokio::task::spawn_blocking(move || {
        let mut socket = std::net::TcpStream::connect(addr).unwrap();
        socket
            .write_all(
                b"POST /slope/spencer HTTP/1.1\r\nHost: x\r\ncontent-type: application/json\r\n\
                  content-length: 999999999\r\nexpect: 100-continue\r\n\r\n",
            )
            .unwrap();
        socket
            .set_read_timeout(Some(std::time::Duration::from_secs(5)))
            .unwrap();
        let mut answer = [0u8; 12];
        socket.read_exact(&mut answer).unwrap();
        String::from_utf8_lossy(&answer).into_owned()
    })
    .await
    .unwrap();
    assert_eq!(first_line, "HTTP/1.1 413");
}

#[tokio::test]
async fn answers_are_compressed_as_the_client_accepts() {
    // Issue 39: a 3.26 MB JSON answer would be 0.84 MB gzipped. Answers of 1 KiB or more are
    // compressed by Accept-Encoding (gzip, br, zstd), smaller ones and clients that accept none
    // are not; the gzipped answer is the same JSON.
    use std::io::{Read, Write};
    let server = Server::start().await;
    let addr = server.base.trim_start_matches("http://").to_owned();
    let body = spencer_example().to_string();
    let ask = |encoding: &'static str, body: String| {
        let addr = addr.clone();
        tokio::task::spawn_blocking(move || {
            let mut socket = std::net::TcpStream::connect(addr).unwrap();
            write!(
                socket,
                "POST /slope/spencer HTTP/1.1\r\nHost: x\r\ncontent-type: application/json\r\n\
                 accept-encoding: {encoding}\r\nconnection: close\r\ncontent-length: {}\r\n\r\n{body}",
                body.len()
            )
            .unwrap();
            let mut answer = Vec::new();
            socket.read_to_end(&mut answer).unwrap();
            let split = answer.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
            let head = String::from_utf8_lossy(&answer[..split]).to_ascii_lowercase();
            (head, answer[split + 4..].to_vec())
        })
    };
    let (plain_head, plain) = ask("identity", body.clone()).await.unwrap();
    assert!(!plain_head.contains("content-encoding"), "{plain_head}");
    let plain: serde_json::Value = serde_json::from_slice(&dechunk(&plain_head, &plain)).unwrap();
    assert!(plain.to_string().len() > 1024);
    for encoding in ["gzip", "br", "zstd"] {
        let (head, compressed) = ask(encoding, body.clone()).await.unwrap();
        assert!(
            head.contains(&format!("content-encoding: {encoding}")),
            "{encoding}: {head}"
        );
        let compressed = dechunk(&head, &compressed);
        assert!(compressed.len() < plain.to_string().len() / 2, "{encoding}");
        if encoding == "gzip" {
            let mut json = Vec::new();
            flate2::read::GzDecoder::new(&compressed[..])
                .read_to_end(&mut json)
                .unwrap();
            let json: serde_json::Value = serde_json::from_slice(&json).unwrap();
            // The same answer but for its wall times.
            assert_eq!(json["factor_of_safety"], plain["factor_of_safety"]);
            assert_eq!(json["slices"], plain["slices"]);
        }
    }
    // A small answer (/healthz) is left as it is.
    let health = tokio::task::spawn_blocking({
        let addr = addr.clone();
        move || {
            let mut socket = std::net::TcpStream::connect(addr).unwrap();
            socket
                .write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\naccept-encoding: gzip\r\nconnection: close\r\n\r\n")
                .unwrap();
            let mut answer = String::new();
            socket.read_to_string(&mut answer).unwrap();
            answer.to_ascii_lowercase()
        }
    })
    .await
    .unwrap();
    assert!(health.starts_with("http/1.1 200") && !health.contains("content-encoding"));
}

/// A body as sent: chunked transfer coding removed when the head says so.
fn dechunk(head: &str, body: &[u8]) -> Vec<u8> {
    if !head.contains("transfer-encoding: chunked") {
        return body.to_vec();
    }
    let mut out = Vec::new();
    let mut rest = body;
    loop {
        let line = rest
            .windows(2)
            .position(|w| w == b"\r\n")
            .expect("a chunk size line");
        let size = usize::from_str_radix(
            std::str::from_utf8(&rest[..line]).expect("ASCII").trim(),
            16,
        )
        .expect("a hexadecimal chunk size");
        if size == 0 {
            return out;
        }
        out.extend_from_slice(&rest[line + 2..line + 2 + size]);
        rest = &rest[line + 2 + size + 2..];
    }
}
