//! The `…/csv` routes: a table of an answer (RFC 4180, a header row of the JSON field names,
//! numbers as JSON writes them, empty cells for null), chosen by the `table` query parameter.
//! Built from the answer's own rows, so CSV and JSON never disagree. The JSON routes answer
//! JSON only, so that a typed client gets one type per route (SPEC §11).

use axum::extract::{FromRequestParts, Query};
use axum::http::request::Parts;
use axum::http::{header, HeaderValue};
use axum::response::{IntoResponse, Response};
use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::error::ApiError;
use crate::extract::without_prefix;

/// A row of a table: its serialised fields, in order, are the columns.
pub trait Row: Serialize {
    /// The header row (the field names, as serialised).
    const COLUMNS: &'static [&'static str];
}

/// A CSV answer.
#[derive(Debug)]
pub struct Csv(pub String);

impl IntoResponse for Csv {
    fn into_response(self) -> Response {
        (
            [(
                header::CONTENT_TYPE,
                HeaderValue::from_static("text/csv; charset=utf-8; header=present"),
            )],
            self.0,
        )
            .into_response()
    }
}

/// The rows as CSV, the header row first (also when there is no row).
pub fn csv<R: Row>(rows: &[R]) -> Result<Csv, ApiError> {
    let failed = |e: csv::Error| ApiError::Internal(format!("writing the CSV table: {e}"));
    let mut writer = csv::WriterBuilder::new()
        .has_headers(false)
        .from_writer(Vec::new());
    writer.write_record(R::COLUMNS).map_err(failed)?;
    for row in rows {
        writer.serialize(row).map_err(failed)?;
    }
    let bytes = writer
        .into_inner()
        .map_err(|e| ApiError::Internal(format!("writing the CSV table: {e}")))?;
    String::from_utf8(bytes)
        .map(Csv)
        .map_err(|e| ApiError::Internal(format!("the CSV table is not UTF-8: {e}")))
}

/// A route's query (`?table=`), naming its tables `Table` (the default is the main one).
pub trait TableQuery: DeserializeOwned + Send {
    /// The route's tables.
    type Table: Default;
    /// The table asked for, if any.
    fn table(self) -> Option<Self::Table>;
}

/// The table a CSV route answers with (`?table=`, the route's main table when it is left
/// out). A query that does not read is 422 naming `table`, the only parameter (unknown ones
/// are ignored).
#[derive(Debug)]
pub struct Table<Q: TableQuery>(pub Q::Table);

impl<S: Send + Sync, Q: TableQuery> FromRequestParts<S> for Table<Q> {
    type Rejection = ApiError;

    async fn from_request_parts(parts: &mut Parts, state: &S) -> Result<Self, ApiError> {
        let Query(query) =
            Query::<Q>::from_request_parts(parts, state)
                .await
                .map_err(|rejection| {
                    let detail = without_prefix(&rejection.body_text());
                    // serde names the parameter itself; the problem names it once.
                    let detail = detail.strip_prefix("table: ").unwrap_or(&detail);
                    ApiError::invalid("table", detail.to_owned())
                })?;
        Ok(Self(query.table().unwrap_or_default()))
    }
}
