//! `null` for an optional request field means "the default", exactly as a missing field does:
//! clients generated from the OpenAPI document (pydantic, Jackson, System.Text.Json) send `null`
//! for the fields they leave unset. The interface limits keep SPEC §3's meaning, where `null`
//! is "unbounded" and a missing field Heyman's value.

use serde::{Deserialize, Deserializer};

/// A field whose `null` is its type's default.
pub fn or_default<'de, D, T>(deserializer: D) -> Result<T, D::Error>
where
    D: Deserializer<'de>,
    T: Default + Deserialize<'de>,
{
    Ok(Option::<T>::deserialize(deserializer)?.unwrap_or_default())
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
null_is!(
    /// Number of slices: `null` is 100.
    slices: usize = 100
);
null_is!(
    /// Grid points along one axis of a search: `null` is 21.
    grid_points: usize = 21
);

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
