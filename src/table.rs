//! `Accept: text/csv`: the main table of an answer (RFC 4180, a header row of the JSON field
//! names, numbers as JSON writes them, empty cells for null), chosen by the `table` query
//! parameter. Built from the answer's own rows, so CSV and JSON never disagree.

use axum::extract::{FromRequestParts, Query};
use axum::http::request::Parts;
use axum::http::{header, HeaderMap, HeaderValue};
use axum::response::{IntoResponse, Response};
use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::error::ApiError;
use crate::extract::{without_prefix, ApiJson};

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

/// Whether the client asks for CSV: `text/csv` in `Accept` with a weight above that of any
/// JSON type it also names (no weight is 1).
fn wants_csv(headers: &HeaderMap) -> bool {
    let weight = |media: &str| -> f64 {
        headers
            .get_all(header::ACCEPT)
            .iter()
            .filter_map(|v| v.to_str().ok())
            .flat_map(|v| v.split(','))
            .filter_map(|item| {
                let mut parts = item.split(';').map(str::trim);
                let name = parts.next()?.to_ascii_lowercase();
                (name == media).then(|| {
                    parts
                        .find_map(|p| p.strip_prefix("q="))
                        .and_then(|q| q.parse::<f64>().ok())
                        .unwrap_or(1.0)
                })
            })
            .fold(0.0, f64::max)
    };
    let csv = weight("text/csv");
    csv > 0.0 && csv >= weight("application/json")
}

/// A route's query (`?table=`), naming its tables `Table` (the default is the main one).
pub trait TableQuery: DeserializeOwned + Send {
    /// The route's tables.
    type Table: Default;
    /// The table asked for, if any.
    fn table(self) -> Option<Self::Table>;
}

/// The table to answer with when the client asks for CSV (`None`: JSON). The query is read
/// whatever the client accepts: one that does not read is 422 naming `table`, the only
/// parameter (unknown ones are ignored).
#[derive(Debug)]
pub struct CsvTable<Q: TableQuery>(pub Option<Q::Table>);

impl<S: Send + Sync, Q: TableQuery> FromRequestParts<S> for CsvTable<Q> {
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
        Ok(Self(
            wants_csv(&parts.headers).then(|| query.table().unwrap_or_default()),
        ))
    }
}

/// A solve route's answer: JSON, or one of its tables as CSV.
#[derive(Debug)]
pub enum Answer<T> {
    /// `application/json`.
    Json(T),
    /// `text/csv`.
    Csv(Csv),
}

impl<T: Serialize> IntoResponse for Answer<T> {
    fn into_response(self) -> Response {
        match self {
            Self::Json(body) => ApiJson(body).into_response(),
            Self::Csv(csv) => csv.into_response(),
        }
    }
}
