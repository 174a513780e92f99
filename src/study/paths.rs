//! Paths to numbers in a request: `section.layers[0].soil.cohesion` — object keys joined by
//! dots, array items by `[i]` — read from and written into the request as JSON.

use serde_json::{Number, Value};

/// One step of a path.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Step {
    /// An object's key.
    Key(String),
    /// An array's item.
    Index(usize),
}

/// A parsed path into a request.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct JsonPath {
    /// The path as written.
    pub text: String,
    steps: Vec<Step>,
}

/// Longest path accepted, in characters.
pub const MAX_PATH_CHARS: usize = 200;

impl JsonPath {
    /// Parses `text`; `Err` says what is wrong with it.
    pub fn parse(text: &str) -> Result<Self, String> {
        if text.is_empty() || text.chars().count() > MAX_PATH_CHARS {
            return Err(format!(
                "a path is 1 to {MAX_PATH_CHARS} characters, like \"section.layers[0].soil.cohesion\""
            ));
        }
        let mut steps = Vec::new();
        for part in text.split('.') {
            let (key, mut rest) = part.split_at(part.find('[').unwrap_or(part.len()));
            if key.is_empty() || !key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                return Err(format!(
                    "\"{part}\" is not a key: keys are letters, digits and _, items [i]"
                ));
            }
            steps.push(Step::Key(key.to_owned()));
            while !rest.is_empty() {
                let index = rest
                    .strip_prefix('[')
                    .and_then(|r| r.split_once(']'))
                    .and_then(|(i, r)| Some((i.parse::<usize>().ok()?, r)));
                let Some((i, r)) = index else {
                    return Err(format!("\"{part}\": an item is [i], i a whole number"));
                };
                steps.push(Step::Index(i));
                rest = r;
            }
        }
        Ok(Self {
            text: text.to_owned(),
            steps,
        })
    }

    /// Whether the path starts with the key `key`.
    pub fn starts_with(&self, key: &str) -> bool {
        matches!(self.steps.first(), Some(Step::Key(k)) if k == key)
    }

    /// The value the path leads to in `root`, if any.
    pub fn get<'a>(&self, root: &'a Value) -> Option<&'a Value> {
        self.steps.iter().try_fold(root, |v, step| match step {
            Step::Key(k) => v.get(k),
            Step::Index(i) => v.get(*i),
        })
    }

    /// Writes `value` where the path leads in `root` (which must hold a value there).
    pub fn set(&self, root: &mut Value, value: f64) -> bool {
        let slot = self.steps.iter().try_fold(root, |v, step| match step {
            Step::Key(k) => v.get_mut(k),
            Step::Index(i) => v.get_mut(*i),
        });
        match (slot, Number::from_f64(value)) {
            (Some(slot), Some(number)) => {
                *slot = Value::Number(number);
                true
            }
            _ => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn paths_read_and_write_numbers() {
        let mut v = json!({"section": {"layers": [{"soil": {"cohesion": 5}}, {"x": [[1, 2]]}]}});
        let p = JsonPath::parse("section.layers[0].soil.cohesion").unwrap();
        assert_eq!(p.get(&v), Some(&json!(5)));
        assert!(p.set(&mut v, 7.5));
        assert_eq!(p.get(&v), Some(&json!(7.5)));
        let q = JsonPath::parse("section.layers[1].x[0][1]").unwrap();
        assert_eq!(q.get(&v), Some(&json!(2)));
        assert!(JsonPath::parse("section.layers[9].x")
            .unwrap()
            .get(&v)
            .is_none());
        assert!(!JsonPath::parse("nowhere").unwrap().set(&mut v, 1.0));
    }

    #[test]
    fn malformed_paths_are_refused() {
        for bad in [
            "", "a..b", ".a", "a[", "a[x]", "a[-1]", "a]", "[0]", "a b", "a[1]b",
        ] {
            assert!(JsonPath::parse(bad).is_err(), "{bad}");
        }
        assert!(JsonPath::parse(&"a".repeat(MAX_PATH_CHARS + 1)).is_err());
    }
}
