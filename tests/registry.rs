//! The families' registry and the places that still list the routes by hand: every registered
//! family's route is served, is a route a `/batch` line may name, has its paths in the OpenAPI
//! document, and is named in the README, docs/api.md, the `/batch` description of the document
//! and the TypeScript client check of `.ci/run` — so that a family added to
//! `thrustline::routes::FAMILIES` fails here until those lists say so too.

// Test scaffolding: a failed read should fail the test loudly.
#![allow(clippy::unwrap_used)]

use std::path::Path;

use serde_json::Value;
use thrustline::routes::{BATCH_ROUTES, FAMILIES};

fn read(relative: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)).unwrap()
}

#[test]
fn every_family_is_in_the_document_and_a_batch_route() {
    let doc: Value = serde_json::from_str(&thrustline::openapi::openapi_json()).unwrap();
    let batch_routes = &doc["components"]["schemas"]["BatchRoute"]["enum"];
    assert_eq!(FAMILIES.len(), BATCH_ROUTES.len());
    for family in FAMILIES {
        let route = family.route;
        assert!(
            doc["paths"][route]["post"].is_object(),
            "{route}: no POST in the document"
        );
        assert!(
            batch_routes.as_array().unwrap().iter().any(|r| r == route),
            "{route}: not a batch route in the document"
        );
        // The family's own document holds its paths and nothing of another family.
        let own = serde_json::to_value((family.openapi)()).unwrap();
        let paths = own["paths"].as_object().unwrap();
        assert!(paths.contains_key(route), "{route}: not in its own paths");
        assert!(
            paths.keys().all(|p| p.starts_with(route)),
            "{route}: its document has {:?}",
            paths.keys().collect::<Vec<_>>()
        );
    }
}

#[test]
fn the_hand_written_route_lists_name_every_family() {
    let doc: Value = serde_json::from_str(&thrustline::openapi::openapi_json()).unwrap();
    let batch = doc["paths"]["/batch"]["post"]["description"]
        .as_str()
        .unwrap()
        .to_owned();
    let lists = [
        ("README.md", read("README.md")),
        ("docs/api.md", read("docs/api.md")),
        ("the /batch description", batch),
        (".ci/ts_examples.py", read(".ci/ts_examples.py")),
    ];
    for route in BATCH_ROUTES {
        for (place, text) in &lists {
            assert!(
                text.contains(&format!("`POST {route}`"))
                    || text.contains(&format!("`{route}`"))
                    || text.contains(&format!("\"{route}\"")),
                "{place} does not name {route}"
            );
        }
    }
}
