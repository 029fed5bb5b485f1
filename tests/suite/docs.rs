//! The documentation holds together (issue 52): the README is a front page that leads into
//! the guides under `docs/`, so every relative link among them must lead somewhere, every
//! Rust snippet in them must stay compiled, and CI must keep running the README's test command.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn repository() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The Markdown a reader walks: the front page, the changelog, the benchmark report and the
/// guides (not the generated summaries under `docs/bench/`).
fn documents() -> Vec<PathBuf> {
    let root = repository();
    let mut files = vec![
        root.join("README.md"),
        root.join("CHANGELOG.md"),
        root.join("BENCHMARKS.md"),
    ];
    let mut guides: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "md"))
        .collect();
    guides.sort();
    assert!(!guides.is_empty(), "docs/ should hold the guides");
    files.extend(guides);
    files
}

/// The lines outside fenced code blocks, with their 1-based numbers.
fn prose(text: &str) -> Vec<(usize, &str)> {
    let mut fenced = false;
    let mut lines = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if !fenced {
            lines.push((i + 1, line));
        }
    }
    lines
}

/// `[text](target)` becomes `text`, and code spans lose their backticks: what GitHub keeps of
/// a heading before it makes the anchor.
fn heading_text(heading: &str) -> String {
    let mut out = String::new();
    let mut rest = heading;
    while let Some(open) = rest.find('[') {
        let Some(close) = rest[open..].find("](").map(|c| open + c) else {
            break;
        };
        let Some(end) = rest[close..].find(')').map(|e| close + e) else {
            break;
        };
        out.push_str(&rest[..open]);
        out.push_str(&rest[open + 1..close]);
        rest = &rest[end + 1..];
    }
    out.push_str(rest);
    out.replace('`', "")
}

/// GitHub's anchor for a heading: lowercase, letters, digits, '-' and '_' kept, each space a
/// '-', every other character dropped.
fn slug(heading: &str) -> String {
    heading_text(heading)
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            '-' | '_' => Some(c),
            c if c.is_alphanumeric() => Some(c),
            _ => None,
        })
        .collect()
}

/// The anchors of a document's headings; a repeated one gets GitHub's `-1`, `-2`, ...
fn anchors(text: &str) -> BTreeSet<String> {
    let mut seen = BTreeSet::new();
    for (_, line) in prose(text) {
        let hashes = line.chars().take_while(|&c| c == '#').count();
        if !(1..=6).contains(&hashes) || !line[hashes..].starts_with(' ') {
            continue;
        }
        let base = slug(&line[hashes..]);
        let mut anchor = base.clone();
        let mut n = 0;
        while seen.contains(&anchor) {
            n += 1;
            anchor = format!("{base}-{n}");
        }
        seen.insert(anchor);
    }
    seen
}

/// Every `[text](target)` and `![alt](target)` outside code, as (line, target).
fn links(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (number, line) in prose(text) {
        // Code spans may show link syntax without being links.
        let outside_code: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
        let mut rest = outside_code.as_str();
        while let Some(at) = rest.find("](") {
            let after = &rest[at + 2..];
            let Some(end) = after.find(')') else { break };
            let target = after[..end].split_whitespace().next().unwrap_or("").to_owned();
            found.push((number, target));
            rest = &after[end..];
        }
    }
    found
}

/// What is wrong with each relative link of `file`: a file that does not exist, or an anchor
/// that no heading of its target makes.
fn broken_links(file: &Path, text: &str) -> Vec<String> {
    let mut broken = Vec::new();
    for (line, target) in links(text) {
        if target.is_empty() || target.contains("://") || target.starts_with("mailto:") {
            continue;
        }
        let (path, anchor) = match target.split_once('#') {
            Some((path, anchor)) => (path, Some(anchor)),
            None => (target.as_str(), None),
        };
        let linked = if path.is_empty() {
            file.to_path_buf()
        } else {
            file.parent().unwrap().join(path)
        };
        let at = format!("{}:{line}: ({target})", file.display());
        if !linked.exists() {
            broken.push(format!("{at}: no file {}", linked.display()));
            continue;
        }
        let Some(anchor) = anchor else { continue };
        if linked.extension().is_none_or(|e| e != "md") {
            broken.push(format!("{at}: an anchor into a file that is not Markdown"));
            continue;
        }
        let headings = anchors(&std::fs::read_to_string(&linked).unwrap());
        if !headings.contains(anchor) {
            broken.push(format!(
                "{at}: no heading of {} makes #{anchor}",
                linked.display()
            ));
        }
    }
    broken
}

#[test]
fn github_makes_the_anchors_the_docs_link_to() {
    assert_eq!(
        slug(" Lighting variants: Phong's specular, soft spot edges, glTF's falloff"),
        "lighting-variants-phongs-specular-soft-spot-edges-gltfs-falloff"
    );
    assert_eq!(
        slug(" Which fragment path wins (`FragmentPath::Auto`)"),
        "which-fragment-path-wins-fragmentpathauto"
    );
    assert_eq!(
        slug(" After texturing: color sum, fog, alpha test; user clip planes"),
        "after-texturing-color-sum-fog-alpha-test-user-clip-planes"
    );
    assert_eq!(
        slug(" glTF's meaning: `gltf_defaults = true`"),
        "gltfs-meaning-gltf_defaults--true"
    );
    assert_eq!(slug(" See [the guide](docs/x.md)"), "see-the-guide");
    let repeated = anchors("# A\n\n## A\n\n```sh\n# A\n```\n");
    assert_eq!(repeated, BTreeSet::from(["a".to_owned(), "a-1".to_owned()]));
}

#[test]
fn every_relative_link_in_the_docs_leads_to_a_file_and_a_heading_that_exist() {
    let mut broken = Vec::new();
    let mut count = 0;
    for file in documents() {
        let text = std::fs::read_to_string(&file).unwrap();
        count += links(&text).len();
        broken.extend(broken_links(&file, &text));
    }
    assert!(count > 50, "only {count} links found: the link reader is broken");
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

#[test]
fn a_link_to_a_missing_file_or_heading_is_found() {
    let readme = repository().join("README.md");
    let text = "[ok](docs/regression.md#files-are-never-damaged) [gone](docs/nowhere.md) \
                [renamed](docs/regression.md#tolerances) [here](#ffvk) `[code](not/a/link.md)`";
    let broken = broken_links(&readme, text);
    assert_eq!(broken.len(), 2, "{broken:#?}");
    assert!(
        broken[0].contains("no file") && broken[0].contains("nowhere.md"),
        "{}",
        broken[0]
    );
    assert!(broken[1].contains("#tolerances"), "{}", broken[1]);
}

/// The README is the front page: what ffvk is, the two commands, the ways in and links. The
/// rest lives in the guides; a README that grows past this bound is taking them back in.
#[test]
fn the_readme_stays_a_front_page_of_at_most_320_lines() {
    let readme = std::fs::read_to_string(repository().join("README.md")).unwrap();
    let lines = readme.lines().count();
    assert!(
        lines <= 320,
        "README.md has {lines} lines: move sections into a guide under docs/"
    );
}

/// rustdoc compiles only what `ffvk/src/lib.rs` includes under `cfg(doctest)`: a snippet in a
/// file left out would silently stop compiling.
#[test]
fn every_markdown_file_with_a_rust_snippet_is_compiled_as_a_doctest() {
    let root = repository();
    let lib = std::fs::read_to_string(root.join("ffvk/src/lib.rs")).unwrap();
    for file in documents() {
        let text = std::fs::read_to_string(&file).unwrap();
        if !text.lines().any(|line| line.trim_start().starts_with("```rust")) {
            continue;
        }
        let relative = file
            .strip_prefix(&root)
            .unwrap()
            .to_str()
            .unwrap()
            .replace('\\', "/");
        let include = format!("include_str!(\"../../{relative}\")");
        assert!(
            lib.contains(&include),
            "{relative} has Rust snippets: ffvk/src/lib.rs should have {include}"
        );
    }
}

/// CI runs exactly the README's test command, so the README's promise is what CI checks.
#[test]
fn ci_runs_the_readmes_test_command() {
    let root = repository();
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let test = "make test   # runs the whole test suite with the Vulkan validation layer on";
    let demo = "make demo   # renders the demo into out/demo/ (contact_sheet.png and one PNG per panel)";
    assert!(
        readme.contains(test) && readme.contains(demo),
        "README.md should show its two commands"
    );
    let ci = std::fs::read_to_string(root.join(".ci/run")).unwrap();
    assert!(
        ci.lines().any(|line| line.trim() == "make test"),
        ".ci/run should run `make test`"
    );
}
