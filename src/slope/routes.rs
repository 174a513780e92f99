//! The Spencer routes: `POST /slope/spencer` and its `/svg`, `/stream`, `/csv` and `/report`
//! twins, each one call of the generic handlers of [`crate::family`] for [`Spencer`], and their
//! registration (routes and OpenAPI paths) for `crate::routes`.

use axum::routing::post;
use axum::Router;
use utoipa::OpenApi;

use super::family::Spencer;
use super::request::SpencerRequest;
use super::response::{SpencerResponse, SpencerStreamLine};
use super::tables::{SlopeTableDto, SlopeTableQuery};
use crate::error::ProblemResponses;
use crate::family::{route, Family, Registration};
use crate::state::AppState;

/// The family's registration.
pub const REGISTRATION: Registration = Registration {
    route: <Spencer as Family>::ROUTE,
    routes,
    openapi: Api::openapi,
    limits: &[],
};

/// The routes.
fn routes() -> Router<AppState> {
    Router::new()
        .route("/slope/spencer", post(spencer))
        .route("/slope/spencer/svg", post(spencer_svg))
        .route("/slope/spencer/stream", post(spencer_stream))
        .route("/slope/spencer/csv", post(spencer_csv))
        .route("/slope/spencer/report", post(spencer_report))
}

/// The routes' OpenAPI paths.
#[derive(OpenApi)]
#[openapi(
    paths(spencer, spencer_svg, spencer_stream, spencer_csv, spencer_report),
    components(schemas(SlopeTableDto))
)]
struct Api;

route! {
    /// Spencer's method for one slip surface, or the critical circle.
    ///
    /// F and θ satisfying force and moment equilibrium (Spencer 1967/1973), Bishop's F, the slices
    /// and the line of thrust. The ground is the simple `slope` with its `soil`, or any `section`
    /// (layers, bedrock, water, loads, tension crack); give exactly one of `circle` (relative to the
    /// lower end on the simple slope, or absolute: `centre` and `radius`), `surface` (any polyline)
    /// and `search` (the critical circle, with the F map). `converged: false` with a status when the equations have no
    /// solution; a search or refinement stopped at the time limit is 422 naming the field. A
    /// `probabilistic` or `sensitivity` study varies numbers of the request by their paths and
    /// answers the probability of failure or F at each value (docs/studies.md); with `Accept:
    /// application/x-ndjson` the answer streams after progress lines, as `/slope/spencer/stream`.
    #[utoipa::path(
        post,
        path = "/slope/spencer",
        tag = "slope",
        request_body(content = SpencerRequest, examples(
            ("spencer_1967" = (summary = "Spencer's (1967) example circle at 100 slices: F = 1.0696, θ = 22.43° (converged 1.0695, 22.43°)",
                value = json!({"slope": {"height": 30.48, "length": 60.96},
                               "circle": {"x": 9.63168, "y": 63.76416}, "slices": 100,
                               "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0,
                                        "pore_pressure_ratio": 0.5}}))),
            ("fredlund_krahn_1977" = (summary = "Fredlund & Krahn (1977) case 1, a section facing left, 100 slices: F = 2.0721 (published: Spencer 2.073, Bishop 2.080)",
                value = json!({"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
                                           "layers": [{"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]},
                               "circle": {"centre": [120, 90], "radius": 80}, "slices": 100,
                               "methods": ["morgenstern_price", "bishop", "janbu", "ordinary"]}))),
            ("layered_section" = (summary = "Layers, bedrock, a water table, a surcharge, a line load and a water-filled tension crack: F = 2.3131",
                value = json!({"section": {"ground": [[-20, 0], [0, 0], [20, 10], [40, 10]],
                                           "layers": [{"top": null, "soil": {"unit_weight": 19, "cohesion": 10, "friction_angle_deg": 28}},
                                                      {"top": [[-20, -3], [40, -3]], "soil": {"unit_weight": 20, "cohesion": 0, "friction_angle_deg": 35}}],
                                           "bedrock": [[-20, -12], [40, -12]],
                                           "piezometric_line": [[-20, 1], [10, 3], [40, 6]], "water_unit_weight": 9.81,
                                           "surcharges": [{"x_start": 25, "x_end": 35, "pressure": 20}],
                                           "line_loads": [{"x": 30, "fx": 0, "fy": -50}],
                                           "tension_crack": {"depth": 2.5, "water_depth": 2.5}},
                               "circle": {"centre": [12, 28], "radius": 26}, "slices": 100}))),
            ("polyline_surface" = (summary = "A non-circular slip surface through the same section as Fredlund & Krahn's: F = 2.4795",
                value = json!({"section": {"ground": [[0, 60], [60, 60], [140, 20], [180, 20]],
                                           "layers": [{"top": null, "soil": {"unit_weight": 120, "cohesion": 600, "friction_angle_deg": 20}}]},
                               "surface": [[40, 62], [70, 38], [130, 22], [165, 21]], "slices": 100}))),
            ("strength_and_water" = (summary = "A power-curve fill under an inclined water table with the phreatic-surface correction (h_u = cos²α): F = 1.5410",
                value = json!({"section": {"ground": [[-20, 0], [0, 0], [20, 10], [50, 10]],
                                           "layers": [{"top": null, "soil": {"unit_weight": 19,
                                               "strength": {"model": "power_curve", "a": 3, "b": 0.6, "c": 1}}}],
                                           "piezometric_line": {"points": [[-20, -2], [0, -0.5], [20, 5], [50, 6]], "hu": "auto"}},
                               "circle": {"centre": [12, 22], "radius": 26}, "slices": 60}))),
            ("rapid_drawdown" = (summary = "A 3H:1V upstream face drawn down from 18 to 2 m, its clay undrained (R envelope c_R = 15, φ_R = 15°), searched: F = 1.0261 (the pool up 2.1561)",
                value = json!({"section": {"ground": [[-20, 0], [0, 0], [60, 20], [75, 20]],
                                           "layers": [{"top": null, "soil": {"unit_weight": 20, "cohesion": 10, "friction_angle_deg": 25,
                                               "r_envelope": {"cohesion": 15, "friction_angle_deg": 15}}}],
                                           "drawdown": {"before": [[-20, 18], [54, 18], [75, 12]],
                                                        "after": [[-20, 2], [6, 2], [54, 18], [75, 12]]}},
                               "search": {}, "slices": 40}))),
            ("probabilistic_study" = (summary = "Spencer's critical circle with c′ normal and φ′ lognormal, correlated, in 2000 Latin-hypercube samples on the fixed circle: F = 1.0146, probability of failure 0.3785",
                value = json!({"slope": {"height": 30.48, "length": 60.96}, "search": {}, "slices": 50,
                               "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0,
                                        "pore_pressure_ratio": 0.5},
                               "probabilistic": {"samples": 2000, "sampling": "latin_hypercube", "seed": 7,
                                   "variables": [{"field": "soil.cohesion", "distribution": "normal", "std": 1.0, "min": 0},
                                                 {"field": "soil.friction_angle_deg", "distribution": "lognormal", "std": 2}],
                                   "correlations": [{"fields": ["soil.cohesion", "soil.friction_angle_deg"], "coefficient": -0.5}]}}))),
            ("critical_circle" = (summary = "The critical circle of Spencer's embankment (automatic search bounds): F = 1.0146",
                value = json!({"slope": {"height": 30.48, "length": 60.96}, "search": {}, "slices": 50,
                               "soil": {"unit_weight": 10.0, "cohesion": 6.096, "friction_angle_deg": 40.0,
                                        "pore_pressure_ratio": 0.5}})))
        )),
        responses(
            (status = 200, description = "Solved, or an honest `converged: false` (its tables as CSV: `/slope/spencer/csv`)", body = SpencerResponse),
            ProblemResponses,
        )
    )]
    json spencer(Spencer, SpencerRequest)
}

route! {
    /// Spencer's method with its studies' progress streamed (model §9.4).
    ///
    /// The same request and answer as `/slope/spencer` (which streams too when `Accept` names
    /// `application/x-ndjson`), as NDJSON: `{"progress": {"done": k, "of": n}}` lines at most
    /// every 100 ms while a `probabilistic` or `sensitivity` study runs, then the answer as the
    /// last line — or its problem (with `status`, `field` and `detail`) when the study stopped, e.g.
    /// at the time limit. Closing the connection cancels the work.
    stream spencer_stream(Spencer, SpencerRequest, SpencerStreamLine) at "/slope/spencer/stream", "slope"
}

route! {
    /// Spencer's method drawn: embankment, slip circle and centre, slices, line of thrust, and
    /// for a search the map of F over the centres.
    ///
    /// The same request and solve as `/slope/spencer`, answered as an SVG picture.
    svg spencer_svg(Spencer, SpencerRequest) at "/slope/spencer/svg", "slope"
}

route! {
    /// A table of the Spencer answer as CSV.
    ///
    /// The same request and solve as `/slope/spencer`; `table` chooses the table (a header row of
    /// the JSON field names, then one row per item): the slices, a line of thrust, the surface or
    /// a search's grid of F.
    csv spencer_csv(Spencer, SpencerRequest, SlopeTableQuery) at "/slope/spencer/csv", "slope"
}

route! {
    /// The Spencer answer as a printable calculation report.
    ///
    /// The same request and solve as `/slope/spencer`, answered as one self-contained HTML page
    /// (nothing fetched): the result and every scalar of the JSON answer, the warnings, the drawing,
    /// the slices (the first 200), the inputs as read, the service's version, the request id and
    /// the date. Print it, or save it with the calculation.
    report spencer_report(Spencer, SpencerRequest) at "/slope/spencer/report", "slope"
}
