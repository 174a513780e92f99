//! The committed OpenAPI document must be what the code generates.
//! Regenerate with `cargo run -q -- openapi > openapi/openapi.json`.

#[test]
fn committed_openapi_is_current() {
    let generated = thrustline::openapi::openapi_json();
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/openapi/openapi.json");
    let committed = std::fs::read_to_string(path).unwrap_or_default();
    assert!(
        committed == generated,
        "openapi/openapi.json is stale: run `cargo run -q -- openapi > openapi/openapi.json`"
    );
}

#[test]
fn every_operation_documents_its_errors() {
    let doc: serde_json::Value =
        serde_json::from_str(&thrustline::openapi::openapi_json()).unwrap();
    for (path, item) in doc["paths"].as_object().unwrap() {
        if let Some(post) = item.get("post") {
            for code in ["200", "400", "413", "415", "422", "503"] {
                assert!(
                    post["responses"][code].is_object(),
                    "{path} does not document {code}"
                );
            }
            let problem = &post["responses"]["422"]["content"]["application/problem+json"];
            assert!(problem.is_object(), "{path}: 422 is not problem+json");
        }
    }
}

#[test]
fn every_reference_resolves() {
    let text = thrustline::openapi::openapi_json();
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    let schemas = doc["components"]["schemas"].as_object().unwrap();
    for piece in text.split("\"$ref\": \"#/components/schemas/").skip(1) {
        let name = &piece[..piece.find('"').unwrap()];
        assert!(schemas.contains_key(name), "dangling $ref to {name}");
    }
}
