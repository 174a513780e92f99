//! The solve routes, one registration per problem family: each family's JSON answer and its
//! `/svg`, `/csv`, `/stream` and `/report` twins. The router mounts them and `/batch` sends its
//! lines through them.

use axum::routing::post;
use axum::Router;

use crate::state::AppState;
use crate::{arch, slope};

/// The solve routes: each problem's JSON answer and its `/svg`, `/csv` and `/report` twins
/// (also what a batch's lines are sent through).
pub fn solve_routes() -> Router<AppState> {
    Router::new()
        .route("/slope/spencer", post(slope::spencer))
        .route("/slope/spencer/svg", post(slope::spencer_svg))
        .route("/slope/spencer/stream", post(slope::spencer_stream))
        .route("/slope/spencer/csv", post(slope::tables::spencer_csv))
        .route("/slope/spencer/report", post(slope::report::spencer_report))
        .route("/arch/dead-load", post(arch::dead_load))
        .route("/arch/dead-load/svg", post(arch::dead_load_svg))
        .route("/arch/dead-load/csv", post(arch::tables::dead_load_csv))
        .route(
            "/arch/dead-load/report",
            post(arch::report::dead_load_report),
        )
        .route("/arch/live-load", post(arch::live_load))
        .route("/arch/live-load/svg", post(arch::live_load_svg))
        .route("/arch/live-load/stream", post(arch::live_load_stream))
        .route("/arch/live-load/csv", post(arch::tables::live_load_csv))
        .route(
            "/arch/live-load/report",
            post(arch::report::live_load_report),
        )
        .route(
            "/arch/minimum-thickness",
            post(arch::minimum_thickness::minimum_thickness),
        )
        .route(
            "/arch/minimum-thickness/csv",
            post(arch::minimum_thickness::minimum_thickness_csv),
        )
        .route(
            "/arch/minimum-thickness/svg",
            post(arch::minimum_thickness::minimum_thickness_svg),
        )
}
