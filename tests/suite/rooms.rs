//! The house's rules about its own source (issue 39): no file under a `src/` over 800 lines
//! before its tests, and no module that imports a module that imports it back, directly or
//! around a longer circle. A parent's `pub use` of its own child's items is not counted (the
//! child is declared there; re-exporting keeps public paths).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The crates' source folders, as (folder, name for messages).
const ROOTS: [&str; 3] = ["ffvk/src", "src", "ffvk-c/src"];

fn repository() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// A file's text before its `#[cfg(test)]` module, comments dropped.
fn code_before_tests(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let code = text.split("\n#[cfg(test)]").next().unwrap_or("");
    code.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The module path of `file` below its crate's `root`: `gl/state` for `gl/state/mod.rs` or
/// `gl/state.rs`; empty for the crate root.
fn module_of(root: &Path, file: &Path) -> Vec<String> {
    let relative = file.strip_prefix(root).unwrap().with_extension("");
    let mut parts: Vec<String> = relative
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib" | "main")) {
        parts.pop();
    }
    parts
}

#[test]
fn no_source_file_is_over_800_lines_before_its_tests() {
    let mut long = Vec::new();
    for root in ROOTS {
        let mut files = Vec::new();
        rust_files(&repository().join(root), &mut files);
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap();
            let lines = text.split("\n#[cfg(test)]").next().unwrap_or("").lines().count();
            if lines > 800 {
                long.push(format!("{} ({lines} lines)", file.display()));
            }
        }
    }
    assert!(
        long.is_empty(),
        "files over 800 lines before their tests: {long:?}"
    );
}

#[test]
fn no_module_imports_a_module_that_imports_it_back() {
    for root in ROOTS {
        let root = repository().join(root);
        let mut files = Vec::new();
        rust_files(&root, &mut files);
        let modules: BTreeMap<Vec<String>, PathBuf> =
            files.iter().map(|f| (module_of(&root, f), f.clone())).collect();
        // Longest prefix of `path` that is a module of the crate.
        let resolve = |path: &[String]| -> Option<Vec<String>> {
            (1..=path.len())
                .rev()
                .map(|n| path[..n].to_vec())
                .find(|p| modules.contains_key(p))
        };
        let mut edges: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
        for (module, file) in &modules {
            let code = code_before_tests(file);
            let mut deps = BTreeSet::new();
            let is_path_char = |c: char| c.is_alphanumeric() || c == '_' || c == ':';
            for head in ["crate::", "super::", "self::"] {
                for (i, _) in code.match_indices(head) {
                    if code[..i].chars().last().is_some_and(is_path_char) {
                        continue;
                    }
                    let rest = &code[i..];
                    let end = rest.find(|c: char| !is_path_char(c)).unwrap_or(rest.len());
                    let segments: Vec<&str> = rest[..end].split("::").filter(|s| !s.is_empty()).collect();
                    let mut base: Vec<String> = match segments[0] {
                        "crate" => Vec::new(),
                        "self" => module.clone(),
                        // `super` of a directory module (mod.rs) and of a file module alike:
                        // the parent module.
                        _ => module[..module.len().saturating_sub(1)].to_vec(),
                    };
                    let mut tail = &segments[1..];
                    while tail.first() == Some(&"super") {
                        base.pop();
                        tail = &tail[1..];
                    }
                    // `use super::{a::X, b}`: each item of the group is a path of its own.
                    let mut paths = vec![tail.iter().map(|s| s.to_string()).collect::<Vec<_>>()];
                    if rest[end..].starts_with('{') {
                        let group = &rest[end + 1..rest[end..].find('}').map_or(end + 1, |e| end + e)];
                        for item in group.split(',') {
                            let mut p: Vec<String> = tail.iter().map(|s| s.to_string()).collect();
                            p.extend(
                                item.trim()
                                    .split("::")
                                    .filter(|s| !s.is_empty())
                                    .map(str::to_owned),
                            );
                            paths.push(p);
                        }
                    }
                    for tail in paths {
                        let mut path = base.clone();
                        path.extend(tail);
                        let Some(target) = resolve(&path) else { continue };
                        // A parent naming its own child (mod declarations, re-exports) is
                        // not an import back up.
                        let child_of_self = target.len() > module.len() && target.starts_with(module);
                        if target != *module && !child_of_self {
                            deps.insert(target);
                        }
                    }
                }
            }
            edges.insert(module.clone(), deps);
        }
        // Every circle: a module that reaches itself again.
        let mut circles = Vec::new();
        for start in edges.keys() {
            let mut stack = vec![(start.clone(), vec![start.clone()])];
            let mut seen = BTreeSet::new();
            while let Some((at, trail)) = stack.pop() {
                for next in edges.get(&at).into_iter().flatten() {
                    if next == start {
                        circles.push(trail.iter().map(|m| m.join("/")).collect::<Vec<_>>().join(" -> "));
                    } else if seen.insert(next.clone()) {
                        let mut t = trail.clone();
                        t.push(next.clone());
                        stack.push((next.clone(), t));
                    }
                }
            }
        }
        assert!(
            circles.is_empty(),
            "{}: import circles (each back to its start): {circles:#?}",
            root.display()
        );
    }
}
