//! The layout rules of the code: no import cycle of any length, no function over 80 lines, and
//! every file short enough to read in one sitting (the service's at most 450 lines, the
//! solver's 600).
//!
//! A module's imports are the `use` paths that start with `crate::`, `super::` or `self::`,
//! resolved to the longest module prefix that is a file of the crate (an item re-exported by a
//! parent counts as an import of the parent: import it from where it is defined instead). Inline
//! `#[cfg(test)] mod tests` blocks, whose `super` is their own file, are left out.
#![allow(clippy::unwrap_used)]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Module path → file, for every `.rs` file under `root` (`lib.rs` is the crate root).
fn modules(root: &Path) -> BTreeMap<Vec<String>, PathBuf> {
    let mut found = BTreeMap::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let relative = path.strip_prefix(root).unwrap().with_extension("");
            let mut segments: Vec<String> = relative
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect();
            if matches!(
                segments.last().map(String::as_str),
                Some("mod" | "lib" | "main")
            ) {
                segments.pop();
            }
            if segments.is_empty() && path.file_name().is_some_and(|n| n == "main.rs") {
                continue; // the binary is a crate of its own
            }
            found.insert(segments, path);
        }
    }
    found
}

/// The `use` declarations of a source file, each flattened into full paths.
fn use_paths(source: &str) -> Vec<String> {
    let mut paths = Vec::new();
    let mut rest = source;
    while let Some(start) = rest.find("use ") {
        let at_line_start = rest[..start]
            .rsplit('\n')
            .next()
            .is_some_and(|line| matches!(line.trim(), "" | "pub" | "pub(crate)" | "pub(super)"));
        rest = &rest[start + 4..];
        if !at_line_start {
            continue;
        }
        let Some(end) = rest.find(';') else { break };
        let tree: String = rest[..end].chars().filter(|c| !c.is_whitespace()).collect();
        expand("", &tree, &mut paths);
        rest = &rest[end..];
    }
    paths
}

/// The paths written inline in a source file, outside its `use` declarations: every chain
/// `a::b::c` that does not continue another (`x::a::b` is read from `x`), in code only (comments,
/// strings and character literals left out). `super::helper()` in a function body is an import of
/// the parent as much as `use super::helper;` is.
fn inline_paths(source: &str) -> Vec<String> {
    let code = code_only(source);
    let chars: Vec<char> = code.chars().collect();
    let is_ident = |c: char| c.is_alphanumeric() || c == '_';
    let mut paths = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let starts_word = is_ident(chars[i])
            && !chars[i].is_ascii_digit()
            && (i == 0 || !is_ident(chars[i - 1]))
            && !(i >= 2 && chars[i - 1] == ':' && chars[i - 2] == ':');
        if !starts_word {
            i += 1;
            continue;
        }
        let mut end = i;
        let mut segments = Vec::new();
        loop {
            let from = end;
            while end < chars.len() && is_ident(chars[end]) {
                end += 1;
            }
            segments.push(chars[from..end].iter().collect::<String>());
            let continues = end + 2 < chars.len()
                && chars[end] == ':'
                && chars[end + 1] == ':'
                && is_ident(chars[end + 2]);
            if !continues {
                break;
            }
            end += 2;
        }
        if segments[0] == "use" {
            // A `use` declaration: read by `use_paths`; skip to its end.
            end = chars[end..]
                .iter()
                .position(|&c| c == ';')
                .map_or(chars.len(), |p| end + p);
        } else if segments.len() > 1 {
            paths.push(segments.join("::"));
        }
        i = end.max(i + 1);
    }
    paths
}

/// The source with comments, string literals and character literals blanked out (each replaced
/// by a space), so that only code is read for paths.
fn code_only(source: &str) -> String {
    let chars: Vec<char> = source.chars().collect();
    let mut out = String::with_capacity(source.len());
    let mut i = 0;
    while i < chars.len() {
        let next = chars.get(i + 1).copied();
        match (chars[i], next) {
            ('/', Some('/')) => {
                while i < chars.len() && chars[i] != '\n' {
                    i += 1;
                }
            }
            ('/', Some('*')) => {
                i += 2;
                while i + 1 < chars.len() && !(chars[i] == '*' && chars[i + 1] == '/') {
                    i += 1;
                }
                i += 2;
                out.push(' ');
            }
            ('r', Some('#' | '"'))
                if i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '_') =>
            {
                // A raw string r"…" or r#"…"#: skip to the same number of hashes after a quote.
                let mut j = i + 1;
                let mut hashes = 0;
                while j < chars.len() && chars[j] == '#' {
                    hashes += 1;
                    j += 1;
                }
                if chars.get(j) != Some(&'"') {
                    out.push(chars[i]);
                    i += 1;
                    continue;
                }
                j += 1;
                let closing: String = std::iter::once('"')
                    .chain(std::iter::repeat_n('#', hashes))
                    .collect();
                let rest: String = chars[j..].iter().collect();
                i = j + rest.find(&closing).map_or(rest.len(), |p| {
                    rest[..p].chars().count() + closing.chars().count()
                });
                out.push(' ');
            }
            ('"', _) => {
                i += 1;
                while i < chars.len() && chars[i] != '"' {
                    i += if chars[i] == '\\' { 2 } else { 1 };
                }
                i += 1;
                out.push(' ');
            }
            ('\'', Some('\\')) => {
                i += 2;
                while i < chars.len() && chars[i] != '\'' {
                    i += 1;
                }
                i += 1;
                out.push(' ');
            }
            ('\'', Some(_)) if chars.get(i + 2) == Some(&'\'') => {
                i += 3;
                out.push(' ');
            }
            (c, _) => {
                out.push(c);
                i += 1;
            }
        }
    }
    out
}

/// Expands `a::{b, c::{d, e}}` into `a::b`, `a::c::d`, `a::c::e`.
fn expand(prefix: &str, tree: &str, out: &mut Vec<String>) {
    let Some(open) = tree.find('{') else {
        out.push(format!("{prefix}{tree}"));
        return;
    };
    let head = format!("{prefix}{}", &tree[..open]);
    let inner = &tree[open + 1..tree.len() - 1];
    let (mut depth, mut from) = (0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                expand(&head, &inner[from..i], out);
                from = i + 1;
            }
            _ => {}
        }
    }
    if from < inner.len() {
        expand(&head, &inner[from..], out);
    }
}

/// The module a path names, from `module`; `None` for other crates.
fn resolve(
    module: &[String],
    path: &str,
    known: &BTreeMap<Vec<String>, PathBuf>,
) -> Option<Vec<String>> {
    let mut segments = path.split("::").map(str::to_owned);
    let first = segments.next()?;
    let mut base: Vec<String> = match first.as_str() {
        "crate" => Vec::new(),
        "self" => module.to_vec(),
        "super" => module[..module.len().saturating_sub(1)].to_vec(),
        // A path from a child module (`use child::Item;`).
        child if known.contains_key(&[module, &[child.to_owned()]].concat()) => {
            [module, &[child.to_owned()]].concat()
        }
        _ => return None,
    };
    let mut segments = segments.peekable();
    while segments.peek().is_some_and(|s| s == "super") {
        segments.next();
        base.pop();
    }
    for segment in segments {
        base.push(segment.split(" as ").next().unwrap_or(&segment).to_owned());
        if !known.contains_key(&base) {
            base.pop();
            break;
        }
    }
    Some(base)
}

/// Module → the other modules of its crate it imports from.
fn imports(root: &Path) -> BTreeMap<Vec<String>, BTreeSet<Vec<String>>> {
    let known = modules(root);
    known
        .iter()
        .map(|(module, file)| {
            let source = std::fs::read_to_string(file).unwrap();
            // Inline test modules come last; their `super` is the file itself.
            let source = source
                .split("#[cfg(test)]\nmod tests {")
                .next()
                .unwrap_or_default();
            let targets = use_paths(source)
                .iter()
                .chain(inline_paths(source).iter())
                .filter_map(|path| resolve(module, path, &known))
                .filter(|target| target != module)
                .collect();
            (module.clone(), targets)
        })
        .collect()
}

/// Every import cycle of any length: the strongly connected components of the import graph
/// with more than one module (Tarjan's algorithm), each listed by its modules.
fn import_cycles(root: &Path) -> Vec<String> {
    let graph = imports(root);
    let names: Vec<&Vec<String>> = graph.keys().collect();
    let index_of: BTreeMap<&Vec<String>, usize> =
        names.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let edges: Vec<Vec<usize>> = names
        .iter()
        .map(|n| {
            graph[*n]
                .iter()
                .filter_map(|t| index_of.get(t).copied())
                .collect()
        })
        .collect();
    let mut tarjan = Tarjan {
        edges: &edges,
        index: vec![None; names.len()],
        low: vec![0; names.len()],
        on_stack: vec![false; names.len()],
        stack: Vec::new(),
        next: 0,
        components: Vec::new(),
    };
    for v in 0..names.len() {
        if tarjan.index[v].is_none() {
            tarjan.visit(v);
        }
    }
    tarjan
        .components
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|mut c| {
            c.sort_unstable();
            c.iter()
                .map(|&i| names[i].join("::"))
                .collect::<Vec<_>>()
                .join(" -> ")
        })
        .collect()
}

struct Tarjan<'a> {
    edges: &'a [Vec<usize>],
    index: Vec<Option<usize>>,
    low: Vec<usize>,
    on_stack: Vec<bool>,
    stack: Vec<usize>,
    next: usize,
    components: Vec<Vec<usize>>,
}

impl Tarjan<'_> {
    fn visit(&mut self, v: usize) {
        self.index[v] = Some(self.next);
        self.low[v] = self.next;
        self.next += 1;
        self.stack.push(v);
        self.on_stack[v] = true;
        for &w in &self.edges[v] {
            match self.index[w] {
                None => {
                    self.visit(w);
                    self.low[v] = self.low[v].min(self.low[w]);
                }
                Some(iw) if self.on_stack[w] => self.low[v] = self.low[v].min(iw),
                Some(_) => {}
            }
        }
        if Some(self.low[v]) == self.index[v] {
            let mut component = Vec::new();
            while let Some(w) = self.stack.pop() {
                self.on_stack[w] = false;
                component.push(w);
                if w == v {
                    break;
                }
            }
            self.components.push(component);
        }
    }
}

/// Functions outside test code longer than `limit` lines: `fn` items found by their opening
/// line, measured to the closing brace at their own indentation.
fn long_functions(root: &Path, limit: usize) -> Vec<String> {
    let mut found = Vec::new();
    for file in modules(root).values() {
        let source = std::fs::read_to_string(file).unwrap();
        let source = source.split("#[cfg(test)]").next().unwrap_or_default();
        let lines: Vec<&str> = source.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            let trimmed = line.trim_start();
            let is_fn = [
                "fn ",
                "pub fn ",
                "pub(crate) fn ",
                "pub(super) fn ",
                "async fn ",
                "pub async fn ",
            ]
            .iter()
            .any(|p| trimmed.starts_with(p));
            if !is_fn || trimmed.ends_with(';') {
                continue;
            }
            let indent = line.len() - trimmed.len();
            let close = format!("{}}}", " ".repeat(indent));
            let Some(end) = lines[i + 1..].iter().position(|l| *l == close) else {
                continue;
            };
            if end + 2 > limit {
                found.push(format!("{}:{} ({} lines)", file.display(), i + 1, end + 2));
            }
        }
    }
    found
}

fn long_files(root: &Path, limit: usize) -> Vec<String> {
    modules(root)
        .values()
        .filter_map(|file| {
            let lines = std::fs::read_to_string(file).unwrap().lines().count();
            (lines > limit).then(|| format!("{} ({lines} lines)", file.display()))
        })
        .collect()
}

fn crate_root(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

#[test]
fn no_import_cycle_of_any_length() {
    for root in ["src", "crates/solver/src"] {
        let cycles = import_cycles(&crate_root(root));
        assert!(cycles.is_empty(), "{root}: import cycles: {cycles:?}");
    }
}

#[test]
fn no_function_over_eighty_lines() {
    for root in ["src", "crates/solver/src"] {
        let long = long_functions(&crate_root(root), 80);
        assert!(long.is_empty(), "{root}: functions over 80 lines: {long:?}");
    }
}

#[test]
fn files_are_short_enough_to_read_in_one_sitting() {
    let long = long_files(&crate_root("src"), 450);
    assert!(long.is_empty(), "service files over 450 lines: {long:?}");
    let long = long_files(&crate_root("crates/solver/src"), 600);
    assert!(long.is_empty(), "solver files over 600 lines: {long:?}");
}

#[test]
fn the_check_sees_a_circle_and_a_grouped_import() {
    // The checker itself: grouped imports expand, super:: resolves, a circle is found.
    let mut paths = Vec::new();
    expand("", "super::{a::B,c::{d::E,F}}", &mut paths);
    assert_eq!(paths, ["super::a::B", "super::c::d::E", "super::c::F"]);
    let dir = std::env::temp_dir().join(format!("thrustline-layout-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("a")).unwrap();
    std::fs::write(dir.join("lib.rs"), "mod a;\n").unwrap();
    std::fs::write(
        dir.join("a/mod.rs"),
        "mod b;\nmod c;\nmod d;\nmod e;\nuse b::X;\n",
    )
    .unwrap();
    std::fs::write(dir.join("a/b.rs"), "use super::Z;\npub struct X;\n").unwrap();
    std::fs::write(dir.join("a/c.rs"), "use super::d::Y;\npub struct Z;\n").unwrap();
    std::fs::write(dir.join("a/d.rs"), "use super::e::W;\npub struct Y;\n").unwrap();
    std::fs::write(dir.join("a/e.rs"), "use super::c::Z;\npub struct W;\n").unwrap();
    let cycles = import_cycles(&dir);
    std::fs::remove_dir_all(&dir).unwrap();
    // The pair, and a cycle of three that no pair check sees.
    assert_eq!(cycles.len(), 2, "{cycles:?}");
    assert!(cycles.contains(&"a -> a::b".to_owned()), "{cycles:?}");
    assert!(
        cycles.contains(&"a::c -> a::d -> a::e".to_owned()),
        "{cycles:?}"
    );
}

#[test]
fn the_check_reads_inline_paths_and_not_comments_or_strings() {
    // A cycle made only of inline paths (`super::x::f()` in a body, `crate::a::b::T` in a type)
    // is found; the same paths in a comment, a doc comment or a string are not read.
    let dir = std::env::temp_dir().join(format!("thrustline-inline-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("a")).unwrap();
    std::fs::write(dir.join("lib.rs"), "mod a;\nmod q;\n").unwrap();
    std::fs::write(dir.join("a/mod.rs"), "mod b;\nmod c;\nmod d;\n").unwrap();
    std::fs::write(
        dir.join("a/b.rs"),
        "pub fn f() -> u8 {\n    super::c::g()\n}\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("a/c.rs"),
        "pub fn g() -> u8 { 1 }\npub fn h(_: crate::a::b::T) {}\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("a/d.rs"),
        "//! See [`crate::q::Z`].\n// crate::q::f()\npub fn s() -> &'static str {\n    \
         let _c = '\"';\n    \"crate::q::f\"\n}\n/* super::super::q::x */\n",
    )
    .unwrap();
    std::fs::write(dir.join("q.rs"), "pub fn f() { crate::a::d::s(); }\n").unwrap();
    let cycles = import_cycles(&dir);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(cycles, ["a::b -> a::c"], "{cycles:?}");
}
