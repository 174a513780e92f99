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

#[test]
fn points_are_pairs_and_codes_are_enums() {
    // Issue 39: `[x, y]` had no length in the schema (`[1]` type-checked in a generated
    // client); warnings' and problems' codes are enums a client can switch on.
    let doc: serde_json::Value =
        serde_json::from_str(&thrustline::openapi::openapi_json()).unwrap();
    let schemas = &doc["components"]["schemas"];
    for (schema, property) in [
        ("SectionDto", "ground"),
        ("SectionDto", "bedrock"),
        ("WaterLineDto", "points"),
        ("LayerDto", "top"),
        ("SpencerRequest", "surface"),
        ("SpencerRequest", "interslice_function"),
        ("PolygonDto", "polygon"),
    ] {
        let pair = &schemas[schema]["properties"][property]["items"];
        assert_eq!(pair["minItems"], 2, "{schema}.{property}: {pair}");
        assert_eq!(pair["maxItems"], 2, "{schema}.{property}: {pair}");
    }
    // A piezometric line given as its points alone is a list of pairs; a grid's are triples.
    let line = &schemas["PiezometricLineDto"]["oneOf"][0]["items"];
    assert_eq!(
        (&line["minItems"], &line["maxItems"]),
        (&2.into(), &2.into()),
        "{line}"
    );
    let grid = &schemas["PoreGridDto"]["properties"]["points"]["items"];
    assert_eq!(
        (&grid["minItems"], &grid["maxItems"]),
        (&3.into(), &3.into()),
        "{grid}"
    );
    // The search's map of F is a matrix, not points.
    let map = &schemas["GridDto"]["properties"]["factor_of_safety"]["items"];
    assert!(map["maxItems"].is_null(), "{map}");
    let codes = |name: &str| -> Vec<String> {
        schemas[name]["enum"]
            .as_array()
            .unwrap_or_else(|| panic!("{name}: {}", schemas[name]))
            .iter()
            .map(|c| c.as_str().unwrap().to_owned())
            .collect()
    };
    let warnings = codes("WarningCode");
    for code in [
        "tension",
        "thrust_line_outside",
        "unsolved_below_minimum",
        "minimum_on_bound",
        "budget_exhausted",
        "not_settled",
        "friction_may_overestimate",
        "rings_locked",
        "strength_not_consistent",
        "outside_pore_pressure_grid",
        "support_crosses_crack",
    ] {
        assert!(warnings.contains(&code.to_owned()), "{code}: {warnings:?}");
    }
    let problems = codes("ProblemCode");
    for code in [
        "invalid_json",
        "duplicate_key",
        "unknown_field",
        "missing_field",
        "out_of_range",
        "invalid_value",
        "unstateable",
        "over_time_limit",
        "busy",
        "too_large",
        "unauthorized",
        "not_found",
    ] {
        assert!(problems.contains(&code.to_owned()), "{code}: {problems:?}");
    }
}

#[test]
fn no_property_declares_a_default_and_every_option_states_its_own() {
    // Issue 39: openapi-typescript (7.x, by default) makes a property with a `default` required
    // in the type of a component schema, so the README's own bodies, which leave options out,
    // failed `tsc --strict`. Defaults are stated in the descriptions instead ("Defaults to …"),
    // where people read them; the service applies them.
    let text = thrustline::openapi::openapi_json();
    assert!(
        !text.contains("\"default\":"),
        "a schema declares a default"
    );
    let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    let schemas = &doc["components"]["schemas"];
    for (schema, property, default) in [
        ("SpencerRequest", "slices", "100"),
        ("SearchDto", "nx", "21"),
        ("SectionDto", "water_unit_weight", "9.81"),
        ("DeadLoadRequest", "unit_weight", "1"),
        ("DeadLoadRequest", "solver_tolerance", "1e-10"),
        ("FillDto", "dispersal_angle_deg", "30"),
        ("RollingDto", "positions", "101"),
        ("CircularGeometryDto", "rings", "1"),
        ("MinimumThicknessRequest", "tolerance", "1e-6"),
    ] {
        let description = schemas[schema]["properties"][property]["description"]
            .as_str()
            .unwrap_or_default()
            .replace('\n', " ");
        assert!(
            description.contains(&format!("Defaults to {default}")),
            "{schema}.{property}: {description:?}"
        );
        let required = schemas[schema]["required"].as_array();
        assert!(
            required.is_none_or(|r| !r.iter().any(|n| n == property)),
            "{schema}.{property} is required"
        );
    }
}
