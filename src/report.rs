//! The `…/report` routes: a self-contained printable HTML calculation report of a request
//! (SPEC §11) — what was asked (the inputs as the service read them), what was answered (the
//! headline, every scalar of the JSON answer, the main tables), the drawing, the warnings, the
//! version, the request id and the date. One file, nothing fetched: no script, no font, no
//! image from anywhere (the drawing is inline SVG), so it prints and archives as it is.

use std::fmt::Write as _;
use std::time::{SystemTime, UNIX_EPOCH};

use axum::response::Html;
use serde_json::Value;

use crate::svg::escape;
use crate::table::Row;
use crate::warning::Warning;

/// Rows a report prints of one table; the rest are counted and left to the `…/csv` route.
pub const MAX_REPORT_ROWS: usize = 200;

/// A table of the report: its columns and rows as text, and how many rows were left out.
#[derive(Debug)]
pub struct ReportTable {
    /// The table's heading.
    pub title: String,
    /// The header row (the JSON field names).
    pub columns: &'static [&'static str],
    /// The rows printed, cells as JSON writes them (empty for null).
    pub rows: Vec<Vec<String>>,
    /// Rows beyond [`MAX_REPORT_ROWS`], not printed.
    pub more: usize,
}

/// The first [`MAX_REPORT_ROWS`] rows of a table, numbers to [`TABLE_DIGITS`] significant
/// figures (the `…/csv` route has every digit).
pub fn table<R: Row>(title: &str, rows: &[R]) -> ReportTable {
    let printed = rows
        .iter()
        .take(MAX_REPORT_ROWS)
        .map(|row| {
            let value = serde_json::to_value(row).unwrap_or(Value::Null);
            R::COLUMNS
                .iter()
                .map(|&name| table_cell(value.get(name).unwrap_or(&Value::Null)))
                .collect()
        })
        .collect();
    ReportTable {
        title: title.to_owned(),
        columns: R::COLUMNS,
        rows: printed,
        more: rows.len().saturating_sub(MAX_REPORT_ROWS),
    }
}

/// A scalar as text: numbers as JSON writes them (every digit the answer has), null empty.
fn cell(value: &Value) -> String {
    match value {
        Value::Null => String::new(),
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Significant figures of the numbers in a report's tables (wide tables must fit a page).
pub const TABLE_DIGITS: usize = 6;

/// A table's cell: integers as they are, other numbers to [`TABLE_DIGITS`] significant figures.
fn table_cell(value: &Value) -> String {
    match value.as_f64() {
        Some(x) if value.is_f64() => significant(x, TABLE_DIGITS),
        _ => cell(value),
    }
}

/// `x` to `digits` significant figures, trailing zeros dropped; in exponent form outside
/// 1e-4 ≤ |x| < 1e6.
pub fn significant(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return if x == 0.0 {
            "0".to_owned()
        } else {
            x.to_string()
        };
    }
    let magnitude = x.abs().log10().floor();
    if !(-4.0..6.0).contains(&magnitude) {
        return format!("{:.*e}", digits - 1, x);
    }
    let decimals = (digits as f64 - 1.0 - magnitude).max(0.0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// What a report shows.
#[derive(Debug)]
pub struct Report<'a> {
    /// The route the same request answers as JSON (`/slope/spencer`, …).
    pub route: &'a str,
    /// The result in one line (also the drawing's title).
    pub headline: String,
    /// The request's id.
    pub request_id: String,
    /// The request as the service read it (defaults written out, nulls left out).
    pub request: Value,
    /// The JSON answer of the same request.
    pub answer: Value,
    /// The answer's warnings.
    pub warnings: &'a [Warning],
    /// The drawing (SVG).
    pub drawing: String,
    /// The main tables.
    pub tables: Vec<ReportTable>,
}

/// The answer's scalars by their dotted path, in alphabetical order: top-level numbers, strings
/// and booleans, those of objects up to two levels down (`accuracy.discretisation_error`,
/// `design.factors.friction`), and short lists of scalars; tables, nulls and the warnings
/// (printed on their own) are left out.
pub fn scalars(answer: &Value) -> Vec<(String, String)> {
    fn short_list(items: &[Value]) -> Option<String> {
        (!items.is_empty()
            && items.len() <= 8
            && items.iter().all(|v| !v.is_object() && !v.is_array()))
        .then(|| items.iter().map(cell).collect::<Vec<_>>().join(", "))
    }
    /// The scalars of `value` under `path`, objects `depth` levels deep at most.
    fn walk(path: String, value: &Value, depth: usize, out: &mut Vec<(String, String)>) {
        match value {
            Value::Null => {}
            Value::Array(items) => out.extend(short_list(items).map(|v| (path, v))),
            Value::Object(inner) if depth > 0 => {
                for (name, v) in inner {
                    let inner_path = if path.is_empty() {
                        name.clone()
                    } else {
                        format!("{path}.{name}")
                    };
                    walk(inner_path, v, depth - 1, out);
                }
            }
            Value::Object(_) => {}
            scalar => out.push((path, cell(scalar))),
        }
    }
    let mut out = Vec::new();
    let Some(object) = answer.as_object() else {
        return out;
    };
    // The answer's own fields, those of its blocks and of their blocks (a design check's
    // factors); the warnings are printed on their own.
    for (key, value) in object.iter().filter(|(k, _)| k.as_str() != "warnings") {
        walk(key.clone(), value, 2, &mut out);
    }
    out
}

/// A copy of the value without its nulls (the request as read writes every option left out).
pub fn without_nulls(value: &Value) -> Value {
    match value {
        Value::Object(map) => Value::Object(
            map.iter()
                .filter(|(_, v)| !v.is_null())
                .map(|(k, v)| (k.clone(), without_nulls(v)))
                .collect(),
        ),
        Value::Array(items) => Value::Array(items.iter().map(without_nulls).collect()),
        other => other.clone(),
    }
}

/// A UTC time as `YYYY-MM-DD hh:mm:ss UTC` (the proleptic Gregorian calendar; Hinnant's
/// days-to-civil algorithm).
pub fn utc_text(time: SystemTime) -> String {
    let seconds = time.duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, of_day) = (seconds / 86_400, seconds % 86_400);
    let z = days as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02} {:02}:{:02}:{:02} UTC",
        of_day / 3600,
        of_day % 3600 / 60,
        of_day % 60
    )
}

/// The page's style: A4 print, the drawing kept whole on a page, tables repeating their header.
const STYLE: &str = "body{font:11pt/1.4 system-ui,sans-serif;color:#111;max-width:60em;margin:1.5em auto;padding:0 1em}\
h1{font-size:1.5em;margin:0}h2{font-size:1.15em;border-bottom:1px solid #999;margin-top:1.4em}\
.headline{font-size:1.25em;font-weight:600}table{border-collapse:collapse;font-size:9pt}\
th,td{border:1px solid #bbb;padding:2px 6px;text-align:left}td.n{text-align:right;font-variant-numeric:tabular-nums}\
thead{display:table-header-group}pre{font-size:8.5pt;background:#f5f5f5;padding:.6em;white-space:pre-wrap;word-break:break-all}\
table.wide{font-size:7.5pt}svg{width:100%;height:auto}.drawing{break-inside:avoid}.warn li{margin:.2em 0}\
footer{margin-top:2em;font-size:8.5pt;color:#555}@page{size:A4;margin:14mm}\
@media print{body{margin:0;max-width:none}a{color:inherit}}";

impl Report<'_> {
    /// The whole page.
    pub fn html(&self, kind: &str) -> Html<String> {
        let mut page = String::with_capacity(self.drawing.len() + 16_384);
        let version = env!("CARGO_PKG_VERSION");
        let date = utc_text(SystemTime::now());
        // Writing to a String cannot fail.
        let _ = write!(
            page,
            "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
             <title>{title} — thrustline report {id}</title><style>{STYLE}</style></head><body>\
             <header><h1>Calculation report: {kind}</h1><table class=\"meta\">\
             <tr><th>Route</th><td>POST {route}</td></tr>\
             <tr><th>Service</th><td>thrustline {version}</td></tr>\
             <tr><th>Request id</th><td id=\"request-id\">{id}</td></tr>\
             <tr><th>Date</th><td id=\"date\">{date}</td></tr></table></header>\
             <h2>Result</h2><p class=\"headline\" id=\"headline\">{title}</p>",
            title = escape(&self.headline),
            kind = escape(kind),
            route = escape(self.route),
            id = escape(&self.request_id),
        );
        page.push_str(
            "<table id=\"results\"><thead><tr><th>Field</th><th>Value</th></tr></thead><tbody>",
        );
        for (name, value) in scalars(&self.answer) {
            let _ = write!(
                page,
                "<tr><th>{}</th><td class=\"n\">{}</td></tr>",
                escape(&name),
                escape(&value)
            );
        }
        page.push_str("</tbody></table><h2>Warnings</h2>");
        if self.warnings.is_empty() {
            page.push_str("<p id=\"warnings\">None.</p>");
        } else {
            page.push_str("<ul class=\"warn\" id=\"warnings\">");
            for w in self.warnings {
                let code = serde_json::to_value(w.code)
                    .map(|v| cell(&v))
                    .unwrap_or_default();
                let _ = write!(
                    page,
                    "<li><code>{}</code>: {}</li>",
                    escape(&code),
                    escape(&w.message)
                );
            }
            page.push_str("</ul>");
        }
        let _ = write!(
            page,
            "<section class=\"drawing\"><h2>Drawing</h2>{}</section>",
            self.drawing
        );
        for t in &self.tables {
            write_table(&mut page, t);
        }
        let request = serde_json::to_string_pretty(&self.request).unwrap_or_default();
        let _ = writeln!(
            page,
            "<h2>Inputs</h2><p>The request as the service read it, defaults written out \
             (POST it to {route} for the JSON answer).</p><pre id=\"inputs\">{}</pre>\
             <footer>thrustline {version}: limit analysis of rigid-block arches (Livesley 1978) \
             and embankments by Spencer's method (1967, 1973). The numbers are those of the JSON \
             answer of the same request; their accuracy and warnings are stated above.</footer>\
             </body></html>",
            escape(&request),
            route = escape(self.route),
        );
        Html(page)
    }
}

/// One table of the report, its header repeated on every printed page.
fn write_table(page: &mut String, t: &ReportTable) {
    let _ = write!(page, "<h2>{}</h2>", escape(&t.title));
    if t.rows.is_empty() {
        page.push_str("<p>No rows.</p>");
        return;
    }
    page.push_str("<table class=\"wide\"><thead><tr>");
    for c in t.columns {
        // Long field names may break after their underscores.
        let _ = write!(page, "<th>{}</th>", escape(c).replace('_', "_<wbr>"));
    }
    page.push_str("</tr></thead><tbody>");
    for row in &t.rows {
        page.push_str("<tr>");
        for c in row {
            let _ = write!(page, "<td class=\"n\">{}</td>", escape(c));
        }
        page.push_str("</tr>");
    }
    page.push_str("</tbody></table>");
    if t.more > 0 {
        let _ = write!(
            page,
            "<p>… and {} more rows (the whole table, every digit: the route's <code>/csv</code> \
             twin).</p>",
            t.more
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn dates_are_the_calendar_s() {
        // Checked against Python's datetime: 2000-02-29 is the leap day of a century year
        // divisible by 400, 2100 (divisible by 100 only) has none.
        let at = |s: u64| utc_text(UNIX_EPOCH + Duration::from_secs(s));
        assert_eq!(at(0), "1970-01-01 00:00:00 UTC");
        assert_eq!(at(951_782_400), "2000-02-29 00:00:00 UTC");
        assert_eq!(at(951_868_799), "2000-02-29 23:59:59 UTC");
        assert_eq!(at(1_795_707_044), "2026-11-26 15:30:44 UTC");
        assert_eq!(at(4_107_542_400), "2100-03-01 00:00:00 UTC");
    }

    #[test]
    fn table_numbers_keep_six_significant_figures() {
        assert_eq!(significant(1.0695758843216443, 6), "1.06958");
        assert_eq!(significant(-8.29847477394504, 6), "-8.29847");
        assert_eq!(significant(2321.1192504185237, 6), "2321.12");
        assert_eq!(significant(123456.7, 6), "123457");
        assert_eq!(significant(0.5, 6), "0.5");
        assert_eq!(significant(0.00005005724564236118, 6), "5.00572e-5");
        assert_eq!(significant(1.5e7, 6), "1.50000e7");
        assert_eq!(significant(0.0, 6), "0");
        assert_eq!(table_cell(&serde_json::json!(42)), "42");
        assert_eq!(table_cell(&serde_json::json!(null)), "");
    }

    #[test]
    fn text_is_escaped_and_scalars_flattened() {
        let answer = serde_json::json!({"f": 1.5, "none": null, "ok": true, "status": "converged",
            "accuracy": {"slices": 100, "e": 1e-7, "deep": {"x": 1, "deeper": {"y": 2}}}, "rows": [{"a": 1}],
            "omitted": ["slices", "grid"], "warnings": [{"code": "tension"}]});
        let expected = [
            ("accuracy.deep.x", "1"),
            ("accuracy.e", "1e-7"),
            ("accuracy.slices", "100"),
            ("f", "1.5"),
            ("ok", "true"),
            ("omitted", "slices, grid"),
            ("status", "converged"),
        ];
        let got = scalars(&answer);
        let got: Vec<(&str, &str)> = got.iter().map(|(k, v)| (k.as_str(), v.as_str())).collect();
        assert_eq!(got, expected);
    }
}
