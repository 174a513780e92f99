//! The one shape every analysis the service answers takes (SPEC §12): a problem family is a
//! request type, a validation into what runs (`prepare`: the solver's model and plan, and the
//! request's studies), the analysis on the pool within the request's budget (`run`: the
//! solver's one `analyse`), and the answers built whole from what it found — the JSON answer,
//! the drawing, the CSV tables and the calculation report.
//!
//! The handlers here are generic over a [`Family`]: a family's folder writes its documented
//! route functions with [`route!`], and registers its routes, its OpenAPI paths and its ranges
//! once ([`Registration`], listed in `crate::routes`). The router, `/batch` (whose lines go
//! through the same routes), the OpenAPI document and its limits read that list. What a family
//! shares with the others stays shared: its solver errors become fields in `crate::fields`, its
//! warnings are codes of `crate::warning`.

use std::future::Future;
use std::sync::Arc;

use axum::http::HeaderMap;
use axum::response::{Html, IntoResponse, Response};
use axum::Router;
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::Value;

use crate::error::ApiError;
use crate::extract::{ApiJson, ApiJsonWithBody};
use crate::report::{without_nulls, Report, ReportTable};
use crate::state::AppState;
use crate::study::run::Tally;
use crate::table::{Csv, TableQuery};
use crate::warning::Warning;

/// A problem family: what its routes take, run and answer.
pub trait Family: Send + Sync + 'static {
    /// The request as clients send it (wire types only).
    type Request: DeserializeOwned + Serialize + Send + Sync + 'static;
    /// A validated request: what will run (the solver's model and plan, the studies).
    type Prepared: Send + 'static;
    /// What the analysis found: every answer of the family is built from it.
    type Solved: Send + 'static;
    /// The JSON answer.
    type Answer: Serialize + Send + 'static;
    /// The `?table=` query of the CSV twin.
    type Tables: TableQuery + 'static;

    /// The JSON route (`/slope/spencer`); the twins are `<route>/svg`, `/csv`, `/report`,
    /// `/stream`.
    const ROUTE: &'static str;
    /// Whether the JSON route streams progress lines when `Accept` names NDJSON (the families
    /// whose requests carry studies). Defaults to false.
    const STREAMS: bool = false;

    /// Validates `request` (`body`: the JSON it was read from): every 4xx of the input, and
    /// nothing computed.
    fn prepare(request: &Self::Request, body: &Value) -> Result<Self::Prepared, ApiError>;

    /// Runs the analysis (and the studies) on the pool within the request's budget; `tally`
    /// counts the studies' analyses as they finish.
    fn run(
        state: &AppState,
        prepared: Self::Prepared,
        tally: Arc<Tally>,
    ) -> impl Future<Output = Result<Self::Solved, ApiError>> + Send;

    /// The JSON answer, built whole.
    fn answer(request: &Self::Request, solved: &Self::Solved) -> Self::Answer;

    /// The drawing (SVG) of the answer.
    fn draw(request: &Self::Request, solved: &Self::Solved) -> Result<String, ApiError>;

    /// One table of the answer as CSV.
    fn table(
        answer: &Self::Answer,
        table: <Self::Tables as TableQuery>::Table,
    ) -> Result<Csv, ApiError>;

    /// What the calculation report prints beyond the request and the answer; `None` for a
    /// family without a report route. Defaults to none.
    fn report<'a>(
        _request: &Self::Request,
        _solved: &Self::Solved,
        _answer: &'a Self::Answer,
    ) -> Option<ReportParts<'a>> {
        None
    }
}

/// What a family's report prints of its answer: the headline, the drawing, the warnings and
/// the main tables.
pub struct ReportParts<'a> {
    /// The result in one line.
    pub headline: String,
    /// The drawing (SVG).
    pub drawing: String,
    /// The answer's warnings.
    pub warnings: &'a [Warning],
    /// The main tables.
    pub tables: Vec<ReportTable>,
    /// What the report is of, in words (`slope stability by Spencer's method`).
    pub subject: &'static str,
}

/// A family's routes and OpenAPI paths, registered once (`crate::routes::FAMILIES`).
#[derive(Clone, Copy)]
pub struct Registration {
    /// The JSON route, which a `/batch` line may name.
    pub route: &'static str,
    /// The family's routes (the JSON answer and its twins).
    pub routes: fn() -> Router<AppState>,
    /// The OpenAPI paths of those routes.
    pub openapi: fn() -> utoipa::openapi::OpenApi,
    /// The ranges its request's properties state (schema, property, limit), beside the shared
    /// table `crate::limits::schema::SCHEMA_LIMITS`: the document writes them, and the limits
    /// test checks that each lands on a property the document states (that the service refuses
    /// past one is checked for the cases that test lists). The families of Parts I–III keep
    /// theirs in the shared table.
    pub limits: &'static [(&'static str, &'static str, crate::limits::Limit)],
}

/// Validates and analyses a request ([`Family::prepare`], [`Family::run`]).
pub async fn solve<F: Family>(
    state: &AppState,
    request: &F::Request,
    body: &Value,
    tally: Arc<Tally>,
) -> Result<F::Solved, ApiError> {
    let prepared = F::prepare(request, body)?;
    F::run(state, prepared, tally).await
}

/// The JSON answer; streamed after progress lines when the family streams and `Accept` asks.
pub async fn json<F: Family>(
    state: AppState,
    headers: &HeaderMap,
    id: String,
    read: ApiJsonWithBody<F::Request>,
) -> Result<Response, ApiError> {
    if F::STREAMS && crate::study::stream::wants_stream(headers) {
        return stream::<F>(state, id, read);
    }
    let ApiJsonWithBody { request, body } = read;
    let solved = solve::<F>(&state, &request, &body, Arc::default()).await?;
    Ok(ApiJson(F::answer(&request, &solved)).into_response())
}

/// The answer streamed after its progress lines (model §9.4); the input is checked first, so a
/// request the route refuses is its 4xx, not a line.
pub fn stream<F: Family>(
    state: AppState,
    id: String,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<F::Request>,
) -> Result<Response, ApiError> {
    let prepared = F::prepare(&request, &body)?;
    let tally = Arc::new(Tally::default());
    let counted = tally.clone();
    Ok(crate::study::stream::ndjson(tally, id, async move {
        let solved = F::run(&state, prepared, counted).await?;
        serde_json::to_vec(&F::answer(&request, &solved))
            .map_err(|e| ApiError::Internal(e.to_string()))
    }))
}

/// The drawing of the answer.
pub async fn svg<F: Family>(
    state: &AppState,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<F::Request>,
) -> Result<crate::svg::Svg, ApiError> {
    let solved = solve::<F>(state, &request, &body, Arc::default()).await?;
    F::draw(&request, &solved).map(crate::svg::Svg)
}

/// One table of the answer as CSV.
pub async fn csv<F: Family>(
    state: &AppState,
    table: <F::Tables as TableQuery>::Table,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<F::Request>,
) -> Result<Csv, ApiError> {
    let solved = solve::<F>(state, &request, &body, Arc::default()).await?;
    F::table(&F::answer(&request, &solved), table)
}

/// The answer as a printable calculation report (one self-contained HTML page).
pub async fn report<F: Family>(
    state: &AppState,
    request_id: String,
    ApiJsonWithBody { request, body }: ApiJsonWithBody<F::Request>,
) -> Result<Html<String>, ApiError> {
    let solved = solve::<F>(state, &request, &body, Arc::default()).await?;
    let answer = F::answer(&request, &solved);
    let parts = F::report(&request, &solved, &answer).ok_or_else(|| {
        ApiError::Internal(format!(
            "{} has no report, yet its route was asked",
            F::ROUTE
        ))
    })?;
    let report = Report {
        route: F::ROUTE,
        headline: parts.headline,
        request_id,
        request: without_nulls(&serde_json::to_value(&request).unwrap_or_default()),
        answer: serde_json::to_value(&answer).unwrap_or_default(),
        warnings: parts.warnings,
        drawing: parts.drawing,
        tables: parts.tables,
    };
    Ok(report.html(parts.subject))
}

/// Declares a family's route handler, documented: its doc comment, then the kind of answer and
/// `name(Family, Request)`. `json` takes its own `#[utoipa::path(...)]` after the doc (a route's
/// examples are its own); the twins write theirs from `at "path", "tag"` (the same responses on
/// every family): `stream` (with its line type), `svg`, `report`, and `csv` (with its table
/// query). Each handler is one call of the generic one of its kind.
macro_rules! route {
    ($(#[$meta:meta])* json $name:ident($family:ty, $request:ty)) => {
        $(#[$meta])*
        pub async fn $name(
            axum::extract::State(state): axum::extract::State<$crate::state::AppState>,
            headers: axum::http::HeaderMap,
            $crate::headers::RequestId(id): $crate::headers::RequestId,
            read: $crate::extract::ApiJsonWithBody<$request>,
        ) -> Result<axum::response::Response, $crate::error::ApiError> {
            $crate::family::json::<$family>(state, &headers, id, read).await
        }
    };
    ($(#[$meta:meta])* stream $name:ident($family:ty, $request:ty, $line:ty) at $path:tt, $tag:tt) => {
        $crate::family::route! { @twin [$(#[$meta])*] $path, $tag, $request, [],
            (description = "Progress lines, then the answer (or its problem) as the last line", body = $line, content_type = "application/x-ndjson"),
            $name(
                $crate::headers::RequestId(id): $crate::headers::RequestId,
            ) -> axum::response::Response {
                |state, read| $crate::family::stream::<$family>(state, id, read)
            }
        }
    };
    ($(#[$meta:meta])* svg $name:ident($family:ty, $request:ty) at $path:tt, $tag:tt) => {
        $crate::family::route! { @twin [$(#[$meta])*] $path, $tag, $request, [],
            (description = "The drawing, 800 px wide", body = String, content_type = "image/svg+xml"),
            $name() -> $crate::svg::Svg {
                |state, read| $crate::family::svg::<$family>(&state, read).await
            }
        }
    };
    ($(#[$meta:meta])* csv $name:ident($family:ty, $request:ty, $query:ty) at $path:tt, $tag:tt) => {
        $crate::family::route! { @twin [$(#[$meta])*] $path, $tag, $request, [params($query),],
            (description = "The table (RFC 4180, UTF-8, a header row)", body = String, content_type = "text/csv"),
            $name(
                $crate::table::Table(table): $crate::table::Table<$query>,
            ) -> $crate::table::Csv {
                |state, read| $crate::family::csv::<$family>(&state, table, read).await
            }
        }
    };
    ($(#[$meta:meta])* report $name:ident($family:ty, $request:ty) at $path:tt, $tag:tt) => {
        $crate::family::route! { @twin [$(#[$meta])*] $path, $tag, $request, [],
            (description = "The report, one HTML page", body = String, content_type = "text/html"),
            $name(
                $crate::headers::RequestId(request_id): $crate::headers::RequestId,
            ) -> axum::response::Html<String> {
                |state, read| $crate::family::report::<$family>(&state, request_id, read).await
            }
        }
    };
    // A twin: the attribute every family's twin of a kind shares, and its handler.
    (@twin [$($meta:tt)*] $path:tt, $tag:tt, $request:ty, [$($params:tt)*], ($($ok:tt)*),
        $name:ident($($extra:tt)*) -> $answer:ty {
            |$state:ident, $read:ident| $call:expr
        }
    ) => {
        $($meta)*
        #[utoipa::path(
            post,
            path = $path,
            tag = $tag,
            request_body = $request,
            $($params)*
            responses(
                (status = 200, $($ok)*),
                $crate::error::ProblemResponses,
            )
        )]
        pub async fn $name(
            axum::extract::State($state): axum::extract::State<$crate::state::AppState>,
            $($extra)*
            $read: $crate::extract::ApiJsonWithBody<$request>,
        ) -> Result<$answer, $crate::error::ApiError> {
            $call
        }
    };
}
pub(crate) use route;
