//! The example runner: every `curl` example of README.md and docs/*.md is sent to a real server,
//! and every number shown with it is checked at the precision it is shown; so is every named
//! request example of the OpenAPI document whose summary states a factor.
//!
//! What counts as shown with an example: the fenced answer block that follows it (JSON: each
//! `"field": value`; CSV: each row shown), and in the prose between the example and the next
//! block or heading, each `` `"field": value` `` in backticks. A number shown with d decimals
//! must equal the answer rounded to d decimals; a field may occur several times in an answer
//! (hinges, constraints): one occurrence with that value suffices. Wall times are not checked.
// Test scaffolding: a malformed example should fail the test loudly.
#![allow(clippy::unwrap_used)]

mod common;

use std::path::{Path, PathBuf};

use common::Server;
use serde_json::Value;

/// Fields whose values are wall times: shown as examples, never checked.
const TIMES: [&str; 5] = [
    "time_ms",
    "solve_time_ms",
    "time_per_position_ms",
    "first_position_ms",
    "path_ms",
];

/// One curl example: where it is, what it sends, and what the page shows of its answer.
#[derive(Debug)]
struct Example {
    place: String,
    path: String,
    accept: Option<String>,
    /// The headers the example sends besides `accept` (`content-type` is JSON unless it says
    /// otherwise).
    headers: Vec<(String, String)>,
    body: String,
    /// The fenced block after it (its language and text), if any.
    answer: Option<(String, String)>,
    /// The prose after it (up to the next example or heading).
    prose: String,
}

fn documents() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![root.join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    files
}

/// The fenced blocks and the prose between them, in order: (language, text) or ("", prose).
fn pieces(text: &str) -> Vec<(Option<String>, String)> {
    let mut out = Vec::new();
    let mut prose = String::new();
    let mut lines = text.lines();
    while let Some(line) = lines.next() {
        if let Some(language) = line.strip_prefix("```") {
            out.push((None, std::mem::take(&mut prose)));
            let mut block = String::new();
            for inner in lines.by_ref() {
                if inner.starts_with("```") {
                    break;
                }
                block.push_str(inner);
                block.push('\n');
            }
            out.push((Some(language.trim().to_owned()), block));
        } else if line.starts_with('#') {
            // A heading ends what an example's prose can say about it.
            out.push((None, std::mem::take(&mut prose)));
        } else {
            prose.push_str(line);
            prose.push('\n');
        }
    }
    out.push((None, prose));
    out
}

fn examples(file: &Path) -> Vec<Example> {
    let text = std::fs::read_to_string(file).unwrap();
    let pieces = pieces(&text);
    let mut found = Vec::new();
    for (i, (language, block)) in pieces.iter().enumerate() {
        if language.as_deref() != Some("sh") || !block.contains("curl") {
            continue;
        }
        let command = block.replace("\\\n", " ");
        let Some(at) = command.find("localhost:8080") else {
            continue;
        };
        let path: String = command[at + "localhost:8080".len()..]
            .chars()
            .take_while(|c| !c.is_whitespace() && *c != '\'')
            .collect();
        let mut headers: Vec<(String, String)> = command
            .split("-H '")
            .skip(1)
            .filter_map(|h| h.split('\'').next())
            .filter_map(|h| h.split_once(": "))
            .map(|(name, value)| (name.to_ascii_lowercase(), value.to_owned()))
            .collect();
        let accept = headers
            .iter()
            .find(|(name, _)| name == "accept")
            .map(|(_, value)| value.clone());
        headers.retain(|(name, _)| name != "accept");
        if headers.iter().all(|(name, _)| name != "content-type") {
            headers.push(("content-type".to_owned(), "application/json".to_owned()));
        }
        let Some((start, flag)) = ["-d '", "--data-binary '"]
            .iter()
            .find_map(|flag| command.find(flag).map(|at| (at, flag.len())))
        else {
            continue;
        };
        let body = &command[start + flag..];
        let body = body[..body.rfind('\'').unwrap()].to_owned();
        // The prose and the answer block that follow, up to the next example.
        let mut prose = String::new();
        let mut answer = None;
        for (language, text) in &pieces[i + 1..] {
            match language.as_deref() {
                None => prose.push_str(text),
                Some("sh") => break,
                Some(language) if answer.is_none() => {
                    answer = Some((language.to_owned(), text.clone()));
                }
                Some(_) => break,
            }
        }
        found.push(Example {
            place: format!("{} ({})", file.display(), path),
            path,
            accept,
            headers,
            body,
            answer,
            prose,
        });
    }
    found
}

/// Each `"field": value` in `text` whose value is a number, a string, true, false or null.
fn shown_fields(text: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(start) = rest.find('"') {
        let after = &rest[start + 1..];
        let Some(end) = after.find('"') else { break };
        let key = &after[..end];
        let tail = after[end + 1..].trim_start();
        rest = &after[end + 1..];
        let Some(tail) = tail.strip_prefix(':') else {
            continue;
        };
        let tail = tail.trim_start();
        let value: String = if let Some(string) = tail.strip_prefix('"') {
            match string.find('"') {
                Some(close) => format!("\"{}\"", &string[..close]),
                None => continue,
            }
        } else {
            tail.chars()
                .take_while(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '+'))
                .collect()
        };
        let is_scalar = value.starts_with('"')
            || matches!(value.as_str(), "true" | "false" | "null")
            || value.parse::<f64>().is_ok();
        if !key.is_empty() && is_scalar {
            out.push((key.to_owned(), value));
        }
    }
    out
}

/// Each `` `"field": value` `` in backticks, alone, in the first paragraph of `prose` (the
/// sentence that says what the example answered; request options are written without quotes
/// round their names, or inside braces).
fn prose_fields(prose: &str) -> Vec<(String, String)> {
    let first = prose.trim_start().split("\n\n").next().unwrap_or_default();
    first
        .split('`')
        .skip(1)
        .step_by(2)
        .filter(|snippet| !snippet.contains(['{', '[', ',']))
        .flat_map(shown_fields)
        .collect()
}

/// Every value of `key` anywhere in `value`.
fn occurrences<'a>(value: &'a Value, key: &str, out: &mut Vec<&'a Value>) {
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                if k == key {
                    out.push(v);
                }
                occurrences(v, key, out);
            }
        }
        Value::Array(items) => items.iter().for_each(|v| occurrences(v, key, out)),
        _ => {}
    }
}

/// Whether `actual` is `shown` at the precision it is shown.
fn agrees(shown: &str, actual: &Value) -> bool {
    if let Ok(number) = shown.parse::<f64>() {
        let Some(actual) = actual.as_f64() else {
            return false;
        };
        if shown.contains(['e', 'E']) {
            return (actual - number).abs() <= 1e-12 * number.abs();
        }
        let decimals = shown.split('.').nth(1).map_or(0, str::len) as i32;
        let half_unit = 0.5 * 10f64.powi(-decimals);
        return (actual - number).abs() <= half_unit * (1.0 + 1e-9);
    }
    match shown {
        "true" => actual == &Value::Bool(true),
        "false" => actual == &Value::Bool(false),
        "null" => actual.is_null(),
        quoted => actual.as_str() == Some(quoted.trim_matches('"')),
    }
}

fn check_fields(
    place: &str,
    answer: &Value,
    shown: &[(String, String)],
    failures: &mut Vec<String>,
) {
    for (key, value) in shown {
        if TIMES.contains(&key.as_str()) {
            continue;
        }
        let mut found = Vec::new();
        occurrences(answer, key, &mut found);
        if !found.iter().any(|actual| agrees(value, actual)) {
            let actual: Vec<String> = found
                .iter()
                .filter(|v| !v.is_array() && !v.is_object())
                .take(3)
                .map(|v| v.to_string())
                .collect();
            failures.push(format!(
                "{place}: \"{key}\": {value} shown, answered {actual:?}"
            ));
        }
    }
}

/// The rows of a CSV answer block (up to a `...` line) against the CSV answered.
fn check_csv(place: &str, shown: &str, answered: &str, failures: &mut Vec<String>) {
    let rows: Vec<&str> = answered.lines().collect();
    for (i, line) in shown.lines().take_while(|l| l.trim() != "...").enumerate() {
        let Some(actual) = rows.get(i) else {
            failures.push(format!("{place}: CSV row {i} shown, not answered"));
            continue;
        };
        let cells: Vec<&str> = line.split(',').collect();
        let actual_cells: Vec<&str> = actual.split(',').collect();
        let same = cells.len() == actual_cells.len()
            && cells
                .iter()
                .zip(&actual_cells)
                .all(|(s, a)| match s.parse::<f64>() {
                    Ok(_) => a
                        .parse::<f64>()
                        .is_ok_and(|a| agrees(s, &serde_json::json!(a))),
                    Err(_) => s == a,
                });
        if !same {
            failures.push(format!(
                "{place}: CSV row {i}: shown {line:?}, answered {actual:?}"
            ));
        }
    }
}

async fn run(server: &Server, example: &Example) -> Result<(), Vec<String>> {
    let mut request = server
        .client
        .post(format!("{}{}", server.base, example.path))
        .body(example.body.clone());
    for (name, value) in &example.headers {
        request = request.header(name, value);
    }
    if let Some(accept) = &example.accept {
        request = request.header("accept", accept);
    }
    let response = request.send().await.unwrap();
    let content_type = response
        .headers()
        .get("content-type")
        .and_then(|v| v.to_str().ok())
        .unwrap_or_default()
        .to_owned();
    let text = response.text().await.unwrap();
    let mut failures = Vec::new();
    let place = &example.place;
    let route = example.path.split('?').next().unwrap_or_default();
    if route.ends_with("/report") && !content_type.starts_with("text/html") {
        failures.push(format!(
            "{place}: a report answered {content_type}: {text:.300}"
        ));
    }
    match &example.answer {
        Some((language, shown)) if language.is_empty() && route.ends_with("/csv") => {
            if !content_type.starts_with("text/csv") {
                failures.push(format!("{place}: a table answered {content_type}"));
            }
            check_csv(place, shown, &text, &mut failures);
        }
        Some((language, shown)) if language == "ndjson" => {
            // Line i shown against line i answered.
            let answered: Vec<Value> = text
                .lines()
                .map(|l| serde_json::from_str(l).unwrap_or(Value::Null))
                .collect();
            for (i, line) in shown.lines().enumerate() {
                match answered.get(i) {
                    Some(answer) => check_fields(place, answer, &shown_fields(line), &mut failures),
                    None => failures.push(format!("{place}: NDJSON line {i} shown, not answered")),
                }
            }
        }
        Some((language, shown)) if language == "json" => {
            let answer: Value = serde_json::from_str(&text)
                .unwrap_or_else(|e| panic!("{place}: not JSON ({e}): {text:.300}"));
            check_fields(place, &answer, &shown_fields(shown), &mut failures);
            check_fields(place, &answer, &prose_fields(&example.prose), &mut failures);
        }
        _ => {
            if let Ok(answer) = serde_json::from_str::<Value>(&text) {
                check_fields(place, &answer, &prose_fields(&example.prose), &mut failures);
            }
        }
    }
    if failures.is_empty() {
        Ok(())
    } else {
        Err(failures)
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_example_in_the_docs_answers_what_the_docs_show() {
    let server = Server::start().await;
    let mut failures = Vec::new();
    let mut count = 0;
    let mut checked = 0;
    for file in documents() {
        for example in examples(&file) {
            count += 1;
            checked += example
                .answer
                .as_ref()
                .map_or(0, |(_, text)| shown_fields(text).len())
                + prose_fields(&example.prose).len();
            if let Err(mut f) = run(&server, &example).await {
                failures.append(&mut f);
            }
        }
    }
    // The docs show at least a dozen examples and many more numbers: a runner that finds
    // nothing to check is broken, not green.
    assert!(count >= 12, "only {count} curl examples found");
    assert!(checked >= 40, "only {checked} shown values found");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// `F = 1.0696`, `θ = 22.43°`, `λ = 22.9969`, `λ₀ = 1` in an example's summary: the symbol, the
/// field it names, and the number.
fn summary_claims(summary: &str) -> Vec<(&'static str, String)> {
    let symbols = [
        ("λ₀ = ", "dead_load_factor"),
        ("λ = ", "load_factor"),
        ("F = ", "factor_of_safety"),
        ("θ = ", "theta_deg"),
    ];
    let mut out = Vec::new();
    for (symbol, field) in symbols {
        for (at, _) in summary.match_indices(symbol) {
            let number: String = summary[at + symbol.len()..]
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '.')
                .collect();
            let number = number.trim_end_matches('.').to_owned();
            if !number.is_empty() {
                out.push((field, number));
            }
        }
    }
    out
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_factor_in_an_openapi_example_summary_is_the_answer() {
    let server = Server::start().await;
    let document: Value = serde_json::from_str(include_str!("../openapi/openapi.json")).unwrap();
    let mut failures = Vec::new();
    let mut claims = 0;
    for (path, item) in document["paths"].as_object().unwrap() {
        let examples = &item["post"]["requestBody"]["content"]["application/json"]["examples"];
        let Some(examples) = examples.as_object() else {
            continue;
        };
        for (name, example) in examples {
            let summary = example["summary"].as_str().unwrap_or_default();
            let shown = summary_claims(summary);
            // The twins (/svg, /csv, /report) carry their JSON route's examples: checked there.
            let twin = ["/svg", "/csv", "/report"]
                .iter()
                .any(|s| path.ends_with(s));
            if shown.is_empty() || twin {
                continue;
            }
            let (status, _, answer) = server.post(path, &example["value"]).await;
            assert_eq!(status, 200, "{path} {name}: {answer}");
            for (field, number) in shown {
                claims += 1;
                let mut found = Vec::new();
                occurrences(&answer, field, &mut found);
                if !found.iter().any(|a| agrees(&number, a)) {
                    failures.push(format!("{path} {name}: {field} {number} in the summary"));
                }
            }
        }
    }
    assert!(
        claims >= 5,
        "only {claims} claims found in the example summaries"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_runner_reads_what_a_page_shows() {
    let shown = shown_fields(r#"{"factor_of_safety": 1.0695, "status": "solved", "x": [1, 2]}"#);
    assert_eq!(
        shown,
        [
            ("factor_of_safety".to_owned(), "1.0695".to_owned()),
            ("status".to_owned(), "\"solved\"".to_owned())
        ]
    );
    // Shown precision: 1.0695 stands for [1.06945, 1.06955].
    assert!(agrees("1.0695", &serde_json::json!(1.069524)));
    assert!(!agrees("1.0695", &serde_json::json!(1.06956)));
    assert!(agrees("6", &serde_json::json!(6)));
    assert!(!agrees("3.245", &serde_json::json!(1.5349)));
    assert_eq!(
        prose_fields("gives `\"load_factor\": 1.5349` and 3.245, `{\"fill\": 2}`\n\n`\"x\": 1`"),
        [("load_factor".to_owned(), "1.5349".to_owned())]
    );
    assert_eq!(
        summary_claims("A unit load (λ = 22.9969), F = 1.0696, θ = 22.43°"),
        [
            ("load_factor", "22.9969".to_owned()),
            ("factor_of_safety", "1.0696".to_owned()),
            ("theta_deg", "22.43".to_owned())
        ]
    );
}

#[test]
fn the_readme_counts_the_pages_examples() {
    // The README said "eight examples" after the page had grown a ninth.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let page = std::fs::read_to_string(root.join("src/page.html")).unwrap();
    let panels = page.matches(" title: \"").count();
    let words = [
        "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven",
        "twelve",
    ];
    let said = readme
        .split("solves and draws ")
        .nth(1)
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|word| words.iter().position(|w| *w == word))
        .map(|i| i + 1);
    assert!(panels >= 9, "{panels} panels found in the page");
    assert_eq!(
        said,
        Some(panels),
        "the README's count of the page's examples"
    );
}
