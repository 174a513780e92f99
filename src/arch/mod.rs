//! `POST /arch/dead-load` and `POST /arch/live-load`: limit analysis of rigid-block arches
//! (Livesley 1978; model §1, §3).
//!
//! Blocks and interfaces are numbered from 1 in requests and responses, in order of increasing
//! polar angle for circular arches (interface 1 at the right springing), as the thesis prints
//! them. Angles are polar angles in degrees (for block chains: the direction of the joint from
//! its intrados to its extrados end).

pub mod assembly;
pub mod codes;
pub mod design;
pub mod drawing;
pub mod fill;
pub mod geometry;
pub mod input;
pub mod interfaces;
pub mod material;
pub mod mechanism;
pub mod minimum_thickness;
pub mod profile;
pub mod report;
pub mod request;
pub mod response;
pub mod rolling;
pub mod solve;
pub mod solved;
pub mod study;
pub mod tables;
pub mod thinnest;
pub mod warnings;

use std::sync::Arc;

use axum::extract::State;
use axum::http::HeaderMap;
use axum::response::{IntoResponse, Response};
use serde_json::Value;

use crate::error::{ApiError, ProblemResponses};
use crate::extract::{ApiJson, ApiJsonWithBody};
use crate::headers::RequestId;
use crate::state::AppState;
use crate::study::run::Tally;
use crate::svg::Svg;
use request::{DeadLoadRequest, LiveLoadRequest};
use response::{DeadLoadResponse, LiveLoadResponse};
use solve::{solve, Problem};

/// Dead-load limit analysis (Livesley's λ₀).
///
/// Whether the structure carries its own weight: λ₀ = 1 when it does, below 1 (0 under Heyman's
/// limits) when it does not, with the collapse mechanism, its hinges and the line of thrust.
/// Solver statuses other than `solved` carry no factor; a solve stopped at the time limit is
/// 422 naming `geometry`.
#[utoipa::path(
    post,
    path = "/arch/dead-load",
    tag = "arch",
    request_body(content = DeadLoadRequest, examples(
        ("milankovitch_stands" = (summary = "Milankovitch's semicircle, N = 1800, D = 1.0748: stands, λ₀ = 1",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0748, "voussoirs": 1800}}))),
        ("milankovitch_falls" = (summary = "The same, D = 1.0747: λ₀ = 0, five hinges",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0747, "voussoirs": 1800}})))
    )),
    responses(
        (status = 200, description = "The dead-load factor, mechanism and thrust line (its tables as CSV: `/arch/dead-load/csv`)", body = DeadLoadResponse),
        ProblemResponses,
    )
)]
pub async fn dead_load(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<DeadLoadRequest>,
) -> Result<ApiJson<DeadLoadResponse>, ApiError> {
    let solved = solve(
        &state,
        Problem::DeadLoad,
        request.validate(state.solve_time_limit_secs())?,
    )
    .await?;
    Ok(ApiJson(DeadLoadResponse::new(&solved)))
}

/// Dead-load limit analysis drawn: voussoirs, thrust line, hinges, mechanism.
///
/// The same request and solve as `/arch/dead-load`, answered as an SVG picture.
#[utoipa::path(
    post,
    path = "/arch/dead-load/svg",
    tag = "arch",
    request_body = DeadLoadRequest,
    responses(
        (status = 200, description = "The drawing, 800 px wide", body = String, content_type = "image/svg+xml"),
        ProblemResponses,
    )
)]
pub async fn dead_load_svg(
    State(state): State<AppState>,
    ApiJson(request): ApiJson<DeadLoadRequest>,
) -> Result<Svg, ApiError> {
    let solved = solve(
        &state,
        Problem::DeadLoad,
        request.validate(state.solve_time_limit_secs())?,
    )
    .await?;
    Ok(Svg(drawing::draw(
        &solved,
        &drawing::dead_load_title(&solved),
    )))
}

/// Live-load limit analysis (Livesley's λ).
///
/// The factor on the live loads at collapse, given that the dead load is carried, with the
/// mechanism and the line of thrust; `load_factor: null` with `solver.status`
/// `dead_load_not_carried` or `unbounded` when there is none.
#[utoipa::path(
    post,
    path = "/arch/live-load",
    tag = "arch",
    request_body(content = LiveLoadRequest, examples(
        ("quarter_span_load" = (summary = "A unit load near the quarter span of a semicircle (λ = 22.9969)",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.5, "voussoirs": 100},
                           "loads": [{"block": 26, "fy": -1.0}]}))),
        ("filled_bridge" = (summary = "A thin semicircle that stands only with its fill, a wheel on the road dispersed at 30°: λ = 1.5349",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
                           "fill": {"unit_weight": 1.8, "surface": 11.5, "dispersal_angle_deg": 30.0},
                           "road_loads": [{"x": -4.0, "fy": -10.0, "length": 0.3}]}))),
        ("rolling_axles" = (summary = "Two axles rolled across the filled arch: λ at 101 stops, the critical one answered (λ = 0.6413)",
            value = json!({"geometry": {"kind": "circular", "radius": 10.0, "thickness": 1.0, "voussoirs": 100},
                           "fill": {"unit_weight": 1.8, "surface": 11.5},
                           "rolling": {"axles": [{"offset": 0.0, "fy": -10.0}, {"offset": 1.8, "fy": -10.0}],
                                       "x_start": -12.0, "x_end": 10.0, "positions": 101}}))),
        ("profile_vehicle" = (summary = "An elliptical arch with masonry backing under EN 1991-2's load model 1 tandem on a 3 m strip: λ = 0.9422",
            value = json!({"geometry": {"kind": "profile", "shape": "elliptical", "span": 8.0, "rise": 2.5, "thickness": 0.75, "voussoirs": 40},
                           "unit_weight": 20.0,
                           "fill": {"unit_weight": 18.0, "surface": 3.6, "layers": [{"below": 1.5, "unit_weight": 22.0}]},
                           "rolling": {"vehicle": "en1991_lm1_tandem", "width": 3.0, "x_start": -4.0, "x_end": 4.0, "positions": 41}})))
    )),
    responses(
        (status = 200, description = "The live-load factor, mechanism and thrust line; `stable: false` and `load_factor: null` when the dead load is not carried (its tables as CSV: `/arch/live-load/csv`)", body = LiveLoadResponse),
        ProblemResponses,
    )
)]
pub async fn live_load(
    State(state): State<AppState>,
    headers: HeaderMap,
    RequestId(id): RequestId,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<LiveLoadRequest>,
) -> Result<Response, ApiError> {
    if crate::study::stream::wants_stream(&headers) {
        return live_load_streamed(state, id, request, body);
    }
    let solved = study::solve_live(&state, (&request, &body), Default::default()).await?;
    Ok(ApiJson(LiveLoadResponse::new(&solved)).into_response())
}

/// Live-load limit analysis with its studies' progress streamed (model §9.4).
///
/// The same request and answer as `/arch/live-load` (which streams too when `Accept` names
/// `application/x-ndjson`), as NDJSON: `{"progress": {"done": k, "of": n}}` lines at most
/// every 100 ms while a `probabilistic` or `sensitivity` study runs, then the answer as the
/// last line — or its problem when the study stopped. Closing the connection cancels the work.
#[utoipa::path(
    post,
    path = "/arch/live-load/stream",
    tag = "arch",
    request_body = LiveLoadRequest,
    responses(
        (status = 200, description = "Progress lines, then the answer (or its problem) as the last line", body = response::LiveLoadStreamLine, content_type = "application/x-ndjson"),
        ProblemResponses,
    )
)]
pub async fn live_load_stream(
    State(state): State<AppState>,
    RequestId(id): RequestId,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<LiveLoadRequest>,
) -> Result<Response, ApiError> {
    live_load_streamed(state, id, request, body)
}

/// The answer to `request` streamed after its progress lines; the input is checked first, so
/// a request the route refuses is its 4xx, not a line.
fn live_load_streamed(
    state: AppState,
    id: String,
    request: LiveLoadRequest,
    body: Value,
) -> Result<Response, ApiError> {
    let prepared = study::prepare_live(&state, (&request, &body))?;
    let tally = Arc::new(Tally::default());
    let counted = tally.clone();
    Ok(crate::study::stream::ndjson(tally, id, async move {
        let solved = study::run_live(&state, prepared, counted).await?;
        serde_json::to_vec(&LiveLoadResponse::new(&solved))
            .map_err(|e| ApiError::Internal(e.to_string()))
    }))
}

/// Live-load limit analysis drawn: voussoirs, loads, thrust line, hinges, mechanism.
///
/// The same request and solve as `/arch/live-load`, answered as an SVG picture.
#[utoipa::path(
    post,
    path = "/arch/live-load/svg",
    tag = "arch",
    request_body = LiveLoadRequest,
    responses(
        (status = 200, description = "The drawing, 800 px wide", body = String, content_type = "image/svg+xml"),
        ProblemResponses,
    )
)]
pub async fn live_load_svg(
    State(state): State<AppState>,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<LiveLoadRequest>,
) -> Result<Svg, ApiError> {
    let solved = study::solve_live(&state, (&request, &body), Default::default()).await?;
    Ok(Svg(drawing::draw(
        &solved,
        &drawing::live_load_title(&solved),
    )))
}
