//! The problem families the service answers, registered once each: the router mounts their
//! routes, `/batch` sends its lines through them and the OpenAPI document takes their paths.
//! Adding a family is its folder and one line here.

use axum::Router;

use crate::family::Registration;
use crate::limits::schema::SCHEMA_LIMITS;
use crate::limits::Limit;
use crate::state::AppState;
use crate::{arch, slope};

/// Every family, in the order the batch schema lists their routes.
pub const FAMILIES: [Registration; 4] = [
    slope::routes::REGISTRATION,
    arch::routes::DEAD_LOAD,
    arch::routes::LIVE_LOAD,
    arch::minimum_thickness::routes::REGISTRATION,
];

/// Every range the document states: the shared table and each family's own.
pub fn schema_limits() -> impl Iterator<Item = &'static (&'static str, &'static str, Limit)> {
    SCHEMA_LIMITS
        .iter()
        .chain(FAMILIES.iter().flat_map(|family| family.limits.iter()))
}

/// The JSON routes of the families, which a `/batch` line may name.
pub const BATCH_ROUTES: [&str; FAMILIES.len()] = {
    let mut routes = [""; FAMILIES.len()];
    let mut i = 0;
    while i < FAMILIES.len() {
        routes[i] = FAMILIES[i].route;
        i += 1;
    }
    routes
};

/// The solve routes: each family's JSON answer and its twins (also what a batch's lines are
/// sent through).
pub fn solve_routes() -> Router<AppState> {
    FAMILIES.iter().fold(Router::new(), |router, family| {
        router.merge((family.routes)())
    })
}
