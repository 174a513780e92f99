//! A real server on 127.0.0.1:0 for the HTTP tests, and the model's example requests.
#![allow(dead_code)]
// Test scaffolding: a failed bind or request should fail the test loudly.
#![allow(clippy::unwrap_used)]

use serde_json::{json, Value};

/// A running server; it stops when the test's runtime ends.
pub struct Server {
    pub base: String,
    pub client: reqwest::Client,
}

impl Server {
    pub async fn start() -> Self {
        Self::start_with(thrustline::Settings::default()).await
    }

    pub async fn start_with(mut settings: thrustline::Settings) -> Self {
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
        settings.addr = listener.local_addr().unwrap();
        let base = format!("http://{}", settings.addr);
        tokio::spawn(thrustline::serve(
            listener,
            settings,
            std::future::pending(),
        ));
        Self {
            base,
            client: reqwest::Client::new(),
        }
    }

    /// POSTs `body` to `path`; returns the status, the content type and the JSON body. Every
    /// searched Spencer answer of the suite is checked on the way (SPEC §14): its surface,
    /// stated as a fixed surface, gives the same status and F.
    pub async fn post(&self, path: &str, body: &Value) -> (u16, String, Value) {
        let answer = self.post_once(path, body).await;
        if path == "/slope/spencer" && answer.0 == 200 {
            self.assert_fixed_resolve(body, &answer.2).await;
        }
        answer
    }

    async fn post_once(&self, path: &str, body: &Value) -> (u16, String, Value) {
        let response = self
            .client
            .post(format!("{}{path}", self.base))
            .json(body)
            .send()
            .await
            .unwrap();
        Self::parts(response).await
    }

    /// A searched answer's critical circle re-solved as a fixed circle, at the request's
    /// slices, without the studies: the same status and F (1e-9 relative).
    async fn assert_fixed_resolve(&self, body: &Value, answer: &Value) {
        // At the request's own slices: a refined answer's count is not one a request states.
        let searched = body.get("search").is_some_and(|s| !s.is_null())
            && ["external_loads", "slice_tolerance", "accuracy"]
                .iter()
                .all(|k| body.get(*k).is_none_or(Value::is_null));
        let Some(f) = answer["factor_of_safety"].as_f64().filter(|_| searched) else {
            return;
        };
        let mut fixed = body.clone();
        let object = fixed.as_object_mut().unwrap();
        let beyond = body["search"]["beyond_ground"] == true || body.get("slope").is_some();
        for key in ["search", "probabilistic", "sensitivity"] {
            object.remove(key);
        }
        object.insert("include".into(), json!([]));
        // Circles only: a polyline answer's surface as cut carries a crack's vertical face.
        let Some(radius) = answer["circle"].get("radius") else {
            return;
        };
        let centre = &answer["circle"]["centre"];
        let mut circle = json!({"centre": [centre["x"], centre["y"]], "radius": radius});
        if beyond && body.get("section").is_some() {
            circle["beyond_ground"] = json!(true);
        }
        object.insert("circle".into(), circle);
        let (status, _, again) = self.post_once("/slope/spencer", &fixed).await;
        assert_eq!(status, 200, "the searched surface re-solved: {again}");
        assert_eq!(again["status"], answer["status"], "re-solved: {again}");
        let g = again["factor_of_safety"].as_f64().unwrap();
        assert!((g - f).abs() <= 1e-9 * f, "searched F {f}, re-solved {g}");
    }

    pub async fn post_raw(
        &self,
        path: &str,
        content_type: &str,
        body: &str,
    ) -> (u16, String, Value) {
        let response = self
            .client
            .post(format!("{}{path}", self.base))
            .header("content-type", content_type)
            .body(body.to_owned())
            .send()
            .await
            .unwrap();
        Self::parts(response).await
    }

    /// POSTs `body` to `path` asking for `accept`; returns the status, content type and text.
    pub async fn post_accept(
        &self,
        path: &str,
        accept: &str,
        body: &Value,
    ) -> (u16, String, String) {
        let response = self
            .client
            .post(format!("{}{path}", self.base))
            .header("accept", accept)
            .json(body)
            .send()
            .await
            .unwrap();
        let status = response.status().as_u16();
        let content_type = Self::content_type(&response);
        (status, content_type, response.text().await.unwrap())
    }

    pub async fn get(&self, path: &str) -> (u16, String, Value) {
        let response = self
            .client
            .get(format!("{}{path}", self.base))
            .send()
            .await
            .unwrap();
        Self::parts(response).await
    }

    pub fn content_type(response: &reqwest::Response) -> String {
        response
            .headers()
            .get("content-type")
            .map(|v| v.to_str().unwrap().to_owned())
            .unwrap_or_default()
    }

    /// Solves running and waiting, from /metrics.
    pub async fn solves_running(&self) -> u64 {
        let text = self
            .client
            .get(format!("{}/metrics", self.base))
            .send()
            .await
            .unwrap()
            .text()
            .await
            .unwrap();
        [
            "thrustline_solves_running ",
            "thrustline_solve_queue_depth ",
        ]
        .iter()
        .map(|name| {
            text.lines()
                .find_map(|l| l.strip_prefix(name))
                .unwrap()
                .trim()
                .parse::<u64>()
                .unwrap()
        })
        .sum()
    }

    async fn parts(response: reqwest::Response) -> (u16, String, Value) {
        let status = response.status().as_u16();
        let content_type = Self::content_type(&response);
        let text = response.text().await.unwrap();
        let body = serde_json::from_str(&text).unwrap_or(Value::String(text));
        (status, content_type, body)
    }
}

/// Spencer (1967) example, model §3, from the solver's reference problem.
pub fn spencer_example() -> Value {
    use thrustline_solver::reference::spencer_1967 as s;
    json!({
        "slope": { "height": s::HEIGHT, "length": s::LENGTH },
        "circle": { "x": s::CENTRE_X, "y": s::CENTRE_Y, "lower_end_factor": 0.0 },
        "slices": 100,
        "soil": { "unit_weight": s::UNIT_WEIGHT,
                  "cohesion": s::COHESION_RATIO * s::UNIT_WEIGHT * s::HEIGHT,
                  "friction_angle_deg": s::FRICTION_ANGLE_DEG,
                  "pore_pressure_ratio": s::PORE_PRESSURE_RATIO }
    })
}

/// Milankovitch's semicircle of model §1.4 (N = 1800, R = 10) with the given thickness, every
/// field spelled out as model §3 prints the request.
pub fn milankovitch(thickness: f64) -> Value {
    use thrustline_solver::reference::milankovitch as m;
    json!({
        "geometry": {"kind": "circular", "radius": m::RADIUS, "thickness": thickness,
                     "voussoirs": m::VOUSSOIRS, "left_base_angle_deg": 0.0,
                     "right_base_angle_deg": 0.0, "voussoir": "curved"},
        "unit_weight": 1.0,
        "interface_limits": {"q_min": 0.0, "q_max": null, "s_min": 0.0, "s_max": null,
                             "t_min": null, "t_max": null},
        "friction_coefficient": null
    })
}

/// Sets `body[path] = value` for a dotted path (creating nothing: the path must exist).
pub fn with(mut body: Value, path: &str, value: Value) -> Value {
    let mut target = &mut body;
    let parts: Vec<&str> = path.split('.').collect();
    for part in &parts[..parts.len() - 1] {
        target = match part.parse::<usize>() {
            Ok(index) if target.is_array() => &mut target[index],
            _ => &mut target[*part],
        };
    }
    target[parts[parts.len() - 1]] = value;
    body
}

/// λ of a live-load request that must answer 200 with a factor.
pub async fn live_load_factor(server: &Server, body: &Value) -> f64 {
    let (status, _, answer) = server.post("/arch/live-load", body).await;
    assert_eq!(status, 200, "{answer}");
    answer["load_factor"]
        .as_f64()
        .unwrap_or_else(|| panic!("{answer}"))
}

/// Asserts an RFC 9457 problem whose detail names `field`.
pub fn assert_problem(
    status: u16,
    content_type: &str,
    body: &Value,
    expected_status: u16,
    field: &str,
) {
    assert_eq!(status, expected_status, "{body}");
    assert_eq!(content_type, "application/problem+json", "{body}");
    assert_eq!(body["status"], expected_status, "{body}");
    let detail = body["detail"].as_str().unwrap();
    assert!(
        detail.contains(field),
        "detail {detail:?} does not name {field}"
    );
}

/// The texts of a drawing (its title, key and labels).
/// The answer's warning of `code`; the test fails, showing the warnings, when there is none.
pub fn warning<'a>(answer: &'a Value, code: &str) -> &'a Value {
    answer["warnings"]
        .as_array()
        .and_then(|w| w.iter().find(|w| w["code"] == code))
        .unwrap_or_else(|| panic!("no warning {code}: {}", answer["warnings"]))
}

pub fn svg_texts<'a>(doc: &'a roxmltree::Document) -> Vec<&'a str> {
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .collect()
}
