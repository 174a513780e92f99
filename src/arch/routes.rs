//! The dead- and live-load routes: `POST /arch/dead-load` and `/arch/live-load` with their
//! `/svg`, `/csv`, `/report` (and for the live load `/stream`) twins, each one call of the
//! generic handlers of [`crate::family`], and their registrations for `crate::routes`.

use axum::routing::post;
use axum::Router;
use utoipa::OpenApi;

use super::family::{DeadLoad, LiveLoad};
use super::request::{DeadLoadRequest, LiveLoadRequest};
use super::response::{DeadLoadResponse, LiveLoadResponse, LiveLoadStreamLine};
use super::tables::{ArchTableDto, ArchTableQuery};
use crate::error::ProblemResponses;
use crate::family::{route, Family, Registration};
use crate::state::AppState;

/// The dead load's registration.
pub const DEAD_LOAD: Registration = Registration {
    route: <DeadLoad as Family>::ROUTE,
    routes: dead_load_routes,
    openapi: DeadLoadApi::openapi,
    limits: &[],
};

/// The live load's registration.
pub const LIVE_LOAD: Registration = Registration {
    route: <LiveLoad as Family>::ROUTE,
    routes: live_load_routes,
    openapi: LiveLoadApi::openapi,
    limits: &[],
};

/// The dead load's routes.
fn dead_load_routes() -> Router<AppState> {
    Router::new()
        .route("/arch/dead-load", post(dead_load))
        .route("/arch/dead-load/svg", post(dead_load_svg))
        .route("/arch/dead-load/csv", post(dead_load_csv))
        .route("/arch/dead-load/report", post(dead_load_report))
}

/// The live load's routes.
fn live_load_routes() -> Router<AppState> {
    Router::new()
        .route("/arch/live-load", post(live_load))
        .route("/arch/live-load/svg", post(live_load_svg))
        .route("/arch/live-load/stream", post(live_load_stream))
        .route("/arch/live-load/csv", post(live_load_csv))
        .route("/arch/live-load/report", post(live_load_report))
}

/// The dead load's OpenAPI paths.
#[derive(OpenApi)]
#[openapi(
    paths(dead_load, dead_load_svg, dead_load_csv, dead_load_report),
    components(schemas(ArchTableDto))
)]
struct DeadLoadApi;

/// The live load's OpenAPI paths.
#[derive(OpenApi)]
#[openapi(paths(
    live_load,
    live_load_svg,
    live_load_stream,
    live_load_csv,
    live_load_report
))]
struct LiveLoadApi;

route! {
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
    json dead_load(DeadLoad, DeadLoadRequest)
}

route! {
    /// Dead-load limit analysis drawn: voussoirs, thrust line, hinges, mechanism.
    ///
    /// The same request and solve as `/arch/dead-load`, answered as an SVG picture.
    svg dead_load_svg(DeadLoad, DeadLoadRequest) at "/arch/dead-load/svg", "arch"
}

route! {
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
    json live_load(LiveLoad, LiveLoadRequest)
}

route! {
    /// Live-load limit analysis with its studies' progress streamed (model §9.4).
    ///
    /// The same request and answer as `/arch/live-load` (which streams too when `Accept` names
    /// `application/x-ndjson`), as NDJSON: `{"progress": {"done": k, "of": n}}` lines at most
    /// every 100 ms while a `probabilistic` or `sensitivity` study runs, then the answer as the
    /// last line — or its problem when the study stopped. Closing the connection cancels the work.
    stream live_load_stream(LiveLoad, LiveLoadRequest, LiveLoadStreamLine) at "/arch/live-load/stream", "arch"
}

route! {
    /// Live-load limit analysis drawn: voussoirs, loads, thrust line, hinges, mechanism.
    ///
    /// The same request and solve as `/arch/live-load`, answered as an SVG picture.
    svg live_load_svg(LiveLoad, LiveLoadRequest) at "/arch/live-load/svg", "arch"
}

route! {
    /// A table of the dead-load answer as CSV.
    ///
    /// The same request and solve as `/arch/dead-load`; `table` chooses the table (a header row of
    /// the JSON field names, then one row per item).
    csv dead_load_csv(DeadLoad, DeadLoadRequest, ArchTableQuery) at "/arch/dead-load/csv", "arch"
}

route! {
    /// A table of the live-load answer as CSV.
    ///
    /// The same request and solve as `/arch/live-load`; `table` chooses the table (a header row of
    /// the JSON field names, then one row per item); `rolling` is λ at each stop of a rolling load.
    csv live_load_csv(LiveLoad, LiveLoadRequest, ArchTableQuery) at "/arch/live-load/csv", "arch"
}

route! {
    /// The dead-load answer as a printable calculation report.
    ///
    /// The same request and solve as `/arch/dead-load`, answered as one self-contained HTML page
    /// (nothing fetched): the result and every scalar of the JSON answer, the warnings, the drawing,
    /// the hinges, reactions and line of thrust (the first 200 rows), the inputs as read, the
    /// service's version, the request id and the date.
    report dead_load_report(DeadLoad, DeadLoadRequest) at "/arch/dead-load/report", "arch"
}

route! {
    /// The live-load answer as a printable calculation report.
    ///
    /// The same request and solve as `/arch/live-load`, answered as one self-contained HTML page
    /// (nothing fetched): the result and every scalar of the JSON answer, the warnings, the drawing,
    /// the hinges, reactions and line of thrust (the first 200 rows), λ at each stop of a rolling
    /// load, the inputs as read, the service's version, the request id and the date.
    report live_load_report(LiveLoad, LiveLoadRequest) at "/arch/live-load/report", "arch"
}
