//! Request fields read as generated clients write them. `null` for an optional field means "the
//! default", exactly as a missing field does: clients generated from the OpenAPI document
//! (pydantic, Jackson, System.Text.Json) send `null` for the fields they leave unset. The
//! interface limits keep model §3's meaning, where `null` is "unbounded" and a missing field
//! Heyman's value. An integer field takes `100.0` as 100: JSON Schema's `integer` is any number
//! with a zero fractional part, and some serialisers write whole numbers that way.

use serde::de::{Error, Unexpected, Visitor};
use serde::{Deserialize, Deserializer};

/// A non-negative integer, written `100` or `100.0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Integer(pub usize);

impl<'de> Deserialize<'de> for Integer {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct IntegerVisitor;
        impl Visitor<'_> for IntegerVisitor {
            type Value = Integer;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a non-negative integer")
            }

            fn visit_u64<E: Error>(self, v: u64) -> Result<Integer, E> {
                usize::try_from(v)
                    .map(Integer)
                    .map_err(|_| E::invalid_value(Unexpected::Unsigned(v), &self))
            }

            fn visit_i64<E: Error>(self, v: i64) -> Result<Integer, E> {
                usize::try_from(v)
                    .map(Integer)
                    .map_err(|_| E::invalid_value(Unexpected::Signed(v), &self))
            }

            fn visit_f64<E: Error>(self, v: f64) -> Result<Integer, E> {
                // Whole numbers up to 2^53 are exact in f64; beyond, they are not integers a
                // client meant.
                if v.fract() == 0.0 && (0.0..=9_007_199_254_740_992.0).contains(&v) {
                    Ok(Integer(v as usize))
                } else {
                    Err(E::invalid_value(Unexpected::Float(v), &self))
                }
            }
        }
        deserializer.deserialize_any(IntegerVisitor)
    }
}

/// A required integer field (`100` or `100.0`).
pub fn integer<'de, D: Deserializer<'de>>(deserializer: D) -> Result<usize, D::Error> {
    Integer::deserialize(deserializer).map(|i| i.0)
}

/// An integer field that defaults to 1 (`null` too).
pub fn integer_or_one<'de, D: Deserializer<'de>>(deserializer: D) -> Result<usize, D::Error> {
    Ok(Option::<Integer>::deserialize(deserializer)?.map_or(1, |i| i.0))
}

/// A field whose `null` is its type's default.
pub fn or_default<'de, D, T>(deserializer: D) -> Result<T, D::Error>
where
    D: Deserializer<'de>,
    T: Default + Deserialize<'de>,
{
    Ok(Option::<T>::deserialize(deserializer)?.unwrap_or_default())
}

/// A unit enum given by its name; `null` is its default. Read through a string, so that a number
/// in its place is a value of the wrong type (422 naming the field), not malformed JSON (400).
pub fn name_or_default<'de, D, T>(deserializer: D) -> Result<T, D::Error>
where
    D: Deserializer<'de>,
    T: Default + serde::de::DeserializeOwned,
{
    match Option::<String>::deserialize(deserializer)? {
        None => Ok(T::default()),
        Some(name) => T::deserialize(serde::de::IntoDeserializer::<D::Error>::into_deserializer(
            name,
        )),
    }
}

/// Declares `fn $name`, reading a field whose `null` is `$default`.
macro_rules! null_is {
    ($(#[$attr:meta])* $name:ident: $ty:ty = $default:expr) => {
        $(#[$attr])*
        pub fn $name<'de, D: Deserializer<'de>>(deserializer: D) -> Result<$ty, D::Error> {
            Ok(Option::<$ty>::deserialize(deserializer)?.unwrap_or($default))
        }
    };
}

null_is!(
    /// Unit weight: `null` is 1.
    unit_weight: f64 = 1.0
);
null_is!(
    /// Interior-point tolerance of the arch programmes: `null` is 1e-10.
    solver_tolerance: f64 = 1e-10
);
null_is!(
    /// Minimum-thickness tolerance: `null` is 1e-6.
    thickness_tolerance: f64 = 1e-6
);
/// Number of slices: `null` is 100.
pub fn slices<'de, D: Deserializer<'de>>(deserializer: D) -> Result<usize, D::Error> {
    Ok(Option::<Integer>::deserialize(deserializer)?.map_or(100, |i| i.0))
}

/// Grid points along one axis of a search: `null` is 21.
pub fn grid_points<'de, D: Deserializer<'de>>(deserializer: D) -> Result<usize, D::Error> {
    Ok(Option::<Integer>::deserialize(deserializer)?.map_or(21, |i| i.0))
}

#[cfg(test)]
mod tests {
    use serde::Deserialize;

    #[derive(Deserialize)]
    struct Fields {
        #[serde(default, deserialize_with = "super::or_default")]
        count: usize,
        #[serde(default = "one", deserialize_with = "super::unit_weight")]
        unit_weight: f64,
    }

    fn one() -> f64 {
        1.0
    }

    #[derive(Deserialize)]
    struct Count {
        #[serde(deserialize_with = "super::integer")]
        n: usize,
    }

    #[test]
    fn integers_may_be_written_with_a_zero_fraction_and_nothing_else() {
        for (text, n) in [
            (r#"{"n": 100}"#, 100),
            (r#"{"n": 100.0}"#, 100),
            (r#"{"n": 0}"#, 0),
        ] {
            assert_eq!(serde_json::from_str::<Count>(text).unwrap().n, n);
        }
        for text in [
            r#"{"n": 100.5}"#,
            r#"{"n": -1}"#,
            r#"{"n": -1.0}"#,
            r#"{"n": "7"}"#,
            r#"{"n": 1e300}"#,
        ] {
            let error = serde_json::from_str::<Count>(text)
                .err()
                .unwrap()
                .to_string();
            assert!(error.contains("a non-negative integer"), "{text}: {error}");
        }
    }

    #[test]
    fn null_and_missing_both_mean_the_default() {
        let null: Fields = serde_json::from_str(r#"{"count": null, "unit_weight": null}"#).unwrap();
        let missing: Fields = serde_json::from_str("{}").unwrap();
        for f in [null, missing] {
            assert_eq!((f.count, f.unit_weight), (0, 1.0));
        }
        let given: Fields = serde_json::from_str(r#"{"count": 3, "unit_weight": 2.5}"#).unwrap();
        assert_eq!((given.count, given.unit_weight), (3, 2.5));
    }
}
