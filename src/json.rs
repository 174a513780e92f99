//! A request body read as JSON with every object's keys checked: a key given twice is an
//! error naming it, where `serde_json::Value` would silently keep the last value
//! (`"slices": 100, "slices": 5` solved with 5 slices).

use std::collections::HashSet;
use std::fmt;

use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Number, Value};

/// The marker that starts the message of a duplicate key, which the error mapping recognises.
pub const DUPLICATE_KEY: &str = "duplicate key `";

/// A JSON value whose objects have no key twice.
#[derive(Debug, Clone, PartialEq)]
pub struct UniqueKeys(pub Value);

impl<'de> Deserialize<'de> for UniqueKeys {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer
            .deserialize_any(UniqueKeysVisitor)
            .map(UniqueKeys)
    }
}

struct UniqueKeysVisitor;

impl<'de> Visitor<'de> for UniqueKeysVisitor {
    type Value = Value;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("any JSON value")
    }

    fn visit_bool<E>(self, v: bool) -> Result<Value, E> {
        Ok(Value::Bool(v))
    }

    fn visit_i64<E>(self, v: i64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }

    fn visit_u64<E>(self, v: u64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }

    fn visit_f64<E>(self, v: f64) -> Result<Value, E> {
        // JSON text has no NaN or infinity: a finite f64 always makes a number.
        Ok(Number::from_f64(v).map_or(Value::Null, Value::Number))
    }

    fn visit_str<E>(self, v: &str) -> Result<Value, E> {
        Ok(Value::String(v.to_owned()))
    }

    fn visit_string<E>(self, v: String) -> Result<Value, E> {
        Ok(Value::String(v))
    }

    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_none<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_some<D: Deserializer<'de>>(self, deserializer: D) -> Result<Value, D::Error> {
        UniqueKeys::deserialize(deserializer).map(|u| u.0)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut items = Vec::with_capacity(seq.size_hint().unwrap_or(0).min(4096));
        while let Some(UniqueKeys(item)) = seq.next_element()? {
            items.push(item);
        }
        Ok(Value::Array(items))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut object = Map::new();
        let mut seen = HashSet::new();
        while let Some(key) = map.next_key::<String>()? {
            if !seen.insert(key.clone()) {
                return Err(de::Error::custom(format!(
                    "{DUPLICATE_KEY}{key}`: given more than once (one value per key)"
                )));
            }
            let UniqueKeys(value) = map.next_value()?;
            object.insert(key, value);
        }
        Ok(Value::Object(object))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    #[test]
    fn a_key_given_twice_is_refused_and_named() {
        let error = serde_json::from_str::<UniqueKeys>(r#"{"slices": 100, "slices": 5}"#)
            .unwrap_err()
            .to_string();
        assert!(error.starts_with("duplicate key `slices`"), "{error}");
        let nested = r#"{"geometry": {"radius": 10, "voussoirs": 1800, "voussoirs": 10}}"#;
        let error = serde_json::from_str::<UniqueKeys>(nested)
            .unwrap_err()
            .to_string();
        assert!(error.contains("duplicate key `voussoirs`"), "{error}");
        // Inside arrays too.
        let listed = r#"{"loads": [{"block": 1, "fy": -1, "fy": 2}]}"#;
        assert!(serde_json::from_str::<UniqueKeys>(listed).is_err());
    }

    #[test]
    fn every_other_value_reads_as_serde_json_reads_it() {
        let text =
            r#"{"a": [1, -2, 3.5, 1e300, true, null, "x", {"b": {}}], "c": 18446744073709551615}"#;
        let ours = serde_json::from_str::<UniqueKeys>(text).unwrap().0;
        let theirs: Value = serde_json::from_str(text).unwrap();
        assert_eq!(ours, theirs);
    }
}
