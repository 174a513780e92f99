//! A long study's answer as a stream (model §9.4): NDJSON lines `{"progress": {"done": k,
//! "of": n}}` at most every 100 ms while its analyses run, then the answer (or its problem) as
//! the last line. The work runs inside the stream: a client that goes away drops it, and the
//! pool's budget is cancelled with it.

use std::convert::Infallible;
use std::future::Future;
use std::pin::Pin;
use std::sync::Arc;
use std::time::Duration;

use axum::body::{Body, Bytes};
use axum::http::{header, HeaderMap, HeaderValue};
use axum::response::{IntoResponse, Response};
use futures_util::stream;
use serde::Serialize;
use serde_json::json;
use utoipa::ToSchema;

use super::run::Tally;
use crate::error::ApiError;

/// The media type of a batch and of a stream, in and out: one JSON value per line.
pub const NDJSON: &str = "application/x-ndjson";

/// A progress line.
#[derive(Debug, Serialize, ToSchema)]
pub struct ProgressLine {
    /// The analyses done of all.
    pub progress: ProgressDto,
}

/// The analyses of a request's studies done of all.
#[derive(Debug, Serialize, ToSchema)]
pub struct ProgressDto {
    /// Analyses done.
    pub done: usize,
    /// Analyses in all.
    pub of: usize,
}

/// The least time between two progress lines.
pub const PROGRESS_INTERVAL: Duration = Duration::from_millis(100);

/// Whether the client asks for a stream: `application/x-ndjson` among its `Accept` types.
pub fn wants_stream(headers: &HeaderMap) -> bool {
    headers
        .get_all(header::ACCEPT)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .flat_map(|v| v.split(','))
        .any(|item| {
            let mut parts = item.split(';').map(str::trim);
            let is_ndjson = parts.next().is_some_and(|t| t.eq_ignore_ascii_case(NDJSON));
            let refused = parts.any(|p| {
                p.strip_prefix("q=")
                    .and_then(|q| q.parse::<f64>().ok())
                    .is_some_and(|q| q <= 0.0)
            });
            is_ndjson && !refused
        })
}

/// The work a stream drives: the answer's JSON bytes, or its problem.
type Work = Pin<Box<dyn Future<Output = Result<Vec<u8>, ApiError>> + Send>>;

/// Where the stream is.
struct State {
    work: Option<Work>,
    tally: Arc<Tally>,
    last: (usize, usize),
    ticker: tokio::time::Interval,
    request_id: String,
}

/// Streams `work` (the answer's JSON bytes) with progress lines read from `tally`.
pub fn ndjson<F>(tally: Arc<Tally>, request_id: String, work: F) -> Response
where
    F: Future<Output = Result<Vec<u8>, ApiError>> + Send + 'static,
{
    let mut ticker = tokio::time::interval(PROGRESS_INTERVAL);
    ticker.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    let state = State {
        work: Some(Box::pin(work)),
        tally,
        last: (0, 0),
        ticker,
        request_id,
    };
    let lines = stream::unfold(state, |mut s| async move {
        let work = s.work.as_mut()?;
        loop {
            tokio::select! {
                done = work.as_mut() => {
                    s.work = None;
                    let mut line = match done {
                        Ok(answer) => answer,
                        Err(error) => problem(&error, &s.request_id),
                    };
                    line.push(b'\n');
                    return Some((Ok::<_, Infallible>(Bytes::from(line)), s));
                }
                _ = s.ticker.tick() => {
                    let now = s.tally.read();
                    if now != s.last && now.1 > 0 {
                        s.last = now;
                        let line = json!(ProgressLine { progress: ProgressDto { done: now.0, of: now.1 } });
                        return Some((Ok(Bytes::from(format!("{line}\n"))), s));
                    }
                }
            }
        }
    });
    let mut response = Body::from_stream(lines).into_response();
    response
        .headers_mut()
        .insert(header::CONTENT_TYPE, HeaderValue::from_static(NDJSON));
    response
}

/// The problem of `error` as one line's JSON, with the request's id as its instance.
fn problem(error: &ApiError, request_id: &str) -> Vec<u8> {
    let mut value: serde_json::Value =
        serde_json::from_str(error.problem_raw().get()).unwrap_or_default();
    if let Some(object) = value.as_object_mut() {
        object.insert("instance".to_owned(), json!(request_id));
    }
    serde_json::to_vec(&value).unwrap_or_default()
}
