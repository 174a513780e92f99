//! `GET /`: a single static page (embedded in the binary; no build step, nothing fetched from
//! the internet) with the nine examples of the model pre-filled, their numbers and drawings side by
//! side.

use axum::response::Html;

/// The page.
pub async fn index() -> Html<&'static str> {
    Html(include_str!("page.html"))
}
