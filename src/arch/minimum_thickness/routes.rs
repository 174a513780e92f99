//! The minimum-thickness routes: `POST /arch/minimum-thickness` and its `/csv` and `/svg`
//! twins, each one call of the generic handlers of [`crate::family`], and their registration
//! for `crate::routes`.

use axum::routing::post;
use axum::Router;
use utoipa::OpenApi;

use super::super::tables::{MinimumThicknessTableDto, MinimumThicknessTableQuery};
use super::family::Thickness;
use super::{MinimumThicknessRequest, MinimumThicknessResponse};
use crate::error::ProblemResponses;
use crate::family::{route, Family, Registration};
use crate::state::AppState;

/// The family's registration.
pub const REGISTRATION: Registration = Registration {
    route: <Thickness as Family>::ROUTE,
    routes,
    openapi: Api::openapi,
    limits: &[],
};

/// The routes.
fn routes() -> Router<AppState> {
    Router::new()
        .route("/arch/minimum-thickness", post(minimum_thickness))
        .route("/arch/minimum-thickness/csv", post(minimum_thickness_csv))
        .route("/arch/minimum-thickness/svg", post(minimum_thickness_svg))
}

/// The routes' OpenAPI paths.
#[derive(OpenApi)]
#[openapi(
    paths(minimum_thickness, minimum_thickness_csv, minimum_thickness_svg),
    components(schemas(MinimumThicknessTableDto))
)]
struct Api;

route! {
    /// Minimum thickness of a circular arch under its own weight.
    ///
    /// The thinnest arch of the given shape, voussoirs and joint limits that carries its own weight
    /// (Milankovitch 1904; model §1.4): Brent's method on the dead-load margin, to `tolerance`·R.
    /// A given `thickness` D adds the geometric factor of safety D / D_min. A solve stopped at the time limit is 422 naming
    /// `tolerance`.
    #[utoipa::path(
        post,
        path = "/arch/minimum-thickness",
        tag = "arch",
        request_body(content = MinimumThicknessRequest, examples(
            ("milankovitch" = (summary = "Milankovitch's semicircle of 1800 voussoirs: d/R = 0.10748",
                value = json!({"geometry": {"kind": "circular", "radius": 10.0, "voussoirs": 1800}})))
        )),
        responses(
            (status = 200, description = "The minimum thickness, or the reason there is none (its tables as CSV: `/arch/minimum-thickness/csv`)", body = MinimumThicknessResponse),
            ProblemResponses,
        )
    )]
    json minimum_thickness(Thickness, MinimumThicknessRequest)
}

route! {
    /// A table of the minimum-thickness answer as CSV.
    ///
    /// The same request and search as `/arch/minimum-thickness`; `table` chooses the table (a
    /// header row of the JSON field names, then one row per item).
    csv minimum_thickness_csv(Thickness, MinimumThicknessRequest, MinimumThicknessTableQuery) at "/arch/minimum-thickness/csv", "arch"
}

route! {
    /// Minimum thickness drawn: the arch just too thin to stand, with its collapse mechanism.
    ///
    /// The same request and search as `/arch/minimum-thickness`, answered as an SVG picture: the
    /// arch at the thickest thickness that does not stand (the lower end of the final bracket),
    /// its voussoirs, the displaced blocks of its mechanism and the hinges labelled by angle and
    /// side, the minimum thickness in the title. Without a minimum, the arch as given and why.
    svg minimum_thickness_svg(Thickness, MinimumThicknessRequest) at "/arch/minimum-thickness/svg", "arch"
}
