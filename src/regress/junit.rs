//! Results as JUnit XML, the format CI systems show (Jenkins, GitLab, GitHub Actions'
//! reporters, Buildkite, Azure Pipelines).
//!
//! There is no single JUnit standard; the file is valid against both schemas that tools
//! validate against: Jenkins' `junit-4.xsd` (from Jenkins' dtkit JUnit model) and the stricter
//! Apache Ant schema published by Windy Road (`JUnit.xsd`), which requires `timestamp`,
//! `hostname`, `properties`, `system-out` and `system-err` on every `testsuite`, `package` and
//! `id` on suites inside `testsuites`, and at most one `failure` or `error` per `testcase`. The
//! test suite validates written files against both with `xmllint`.
//!
//! Layout: one `testsuite` per run (per shard once merged), one `testcase` per scene and mode:
//! `classname` is the scene's name (its path below the folder given), `name` the lighting mode.
//! A difference or a missing reference is a `failure` (message: the figures; text: the paths),
//! anything else that went wrong an `error`; passes, renders without a check and blessed images
//! are empty test cases. `testsuites` has no attributes (Ant's schema allows none); each
//! `testsuite` has the counts and the time. The suite's properties record the device, driver, jobs,
//! LP_NUM_THREADS, partition and tolerance; its `system-out` is the summary table.

use std::fmt::Write as _;
use std::path::Path;

use super::results::{Results, Run};
use super::{Row, Status};

/// The JUnit XML of `results`.
pub fn junit(results: &Results) -> String {
    let mut x = Xml::default();
    x.text.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    // No attributes on testsuites: Ant's schema allows none; the totals are the suites'.
    x.open("testsuites", &[]);
    for (id, run) in results.runs.iter().enumerate() {
        suite(&mut x, id, run);
    }
    x.close("testsuites");
    x.text
}

/// One run as a `testsuite`.
fn suite(x: &mut Xml, id: usize, run: &Run) {
    let info = &run.info;
    let counts = super::results::Counts::of(&run.rows);
    let name = match info.partition {
        Some(p) => format!("ffvk render (shard {p})"),
        None => "ffvk render".into(),
    };
    x.open(
        "testsuite",
        &[
            ("name", name),
            ("package", "ffvk".into()),
            ("id", id.to_string()),
            ("timestamp", info.timestamp.clone()),
            ("hostname", info.hostname.clone()),
            ("tests", run.rows.len().to_string()),
            ("failures", (counts.failed + counts.missing).to_string()),
            ("errors", counts.errors.to_string()),
            ("time", seconds(info.seconds)),
        ],
    );
    x.open("properties", &[]);
    let mut properties = vec![("ffvk", info.ffvk.clone())];
    if let Some(d) = &info.device {
        properties.extend([
            ("device", d.device.clone()),
            ("device_type", d.device_type.clone()),
            ("driver", d.driver.clone()),
            ("driver_info", d.driver_info.clone()),
            ("vulkan", d.api_version.clone()),
        ]);
    }
    properties.push(("jobs", info.jobs.to_string()));
    if let Some(t) = &info.lp_num_threads {
        properties.push(("LP_NUM_THREADS", t.clone()));
    }
    if let Some(p) = info.partition {
        properties.push(("partition", p.to_string()));
    }
    properties.push(("suite_scenes", info.suite_scenes.to_string()));
    properties.push(("scenes", info.scenes.to_string()));
    if let Some(r) = &info.references {
        properties.push(("references", r.display().to_string()));
    }
    let t = &info.tolerance;
    properties.push((
        "tolerance",
        format!(
            "threshold {}, max share {}, max FLIP {}{}",
            t.threshold,
            t.max_share,
            t.max_flip,
            if t.flip_all_pixels {
                ", FLIP over all pixels"
            } else {
                ""
            }
        ),
    ));
    for (name, value) in properties {
        x.empty("property", &[("name", name.into()), ("value", value)]);
    }
    x.close("properties");
    for row in &run.rows {
        case(x, row);
    }
    x.leaf("system-out", &format!("{}\n", super::table(&run.rows)));
    x.leaf("system-err", "");
    x.close("testsuite");
}

/// One row as a `testcase`.
fn case(x: &mut Xml, row: &Row) {
    let attributes = [
        ("name", row.mode.clone().unwrap_or_else(|| "scene".into())),
        ("classname", row.scene.clone()),
        ("time", seconds(row.seconds)),
    ];
    let (element, kind) = match row.status {
        Status::Fail if row.comparison.is_some() => ("failure", "image-difference"),
        Status::Fail => ("failure", "image-size"),
        Status::Missing => ("failure", "missing-reference"),
        Status::Error => ("error", "error"),
        Status::Pass | Status::Rendered | Status::Blessed => {
            x.empty("testcase", &attributes);
            return;
        }
    };
    x.open("testcase", &attributes);
    let mut paths = format!("scene: {}\n", row.file.display());
    for (what, path) in [
        ("actual", &row.output),
        ("reference", &row.reference),
        ("diff", &row.diff),
    ] {
        if let Some(p) = path {
            let _ = writeln!(paths, "{what}: {}", p.display());
        }
    }
    let message = match row.detail() {
        d if d.is_empty() => row.status.word().to_owned(),
        d => d,
    };
    x.open_with_text(
        element,
        &[("message", message.clone()), ("type", kind.into())],
        &format!("{message}\n{paths}"),
    );
    x.close(element);
    x.close("testcase");
}

/// Seconds with millisecond precision, as `xs:decimal`.
fn seconds(s: f64) -> String {
    format!("{:.3}", if s.is_finite() { s.max(0.0) } else { 0.0 })
}

/// A tiny indenting XML writer: elements, attributes and text, escaped.
#[derive(Default)]
struct Xml {
    text: String,
    depth: usize,
}

impl Xml {
    fn start(&mut self, name: &str, attributes: &[(&str, String)]) {
        self.text.push_str(&"  ".repeat(self.depth));
        self.text.push('<');
        self.text.push_str(name);
        for (key, value) in attributes {
            let _ = write!(self.text, " {key}=\"{}\"", escape(value, true));
        }
    }

    /// `<name …>` and a new line; the next elements are indented one more.
    fn open(&mut self, name: &str, attributes: &[(&str, String)]) {
        self.start(name, attributes);
        self.text.push_str(">\n");
        self.depth += 1;
    }

    /// `<name …>text` with the text escaped; `close` ends it.
    fn open_with_text(&mut self, name: &str, attributes: &[(&str, String)], text: &str) {
        self.start(name, attributes);
        self.text.push('>');
        self.text.push_str(&escape(text, false));
        self.depth += 1;
        // The closing tag follows the text on its own line.
        self.text.push('\n');
    }

    /// `<name …/>`.
    fn empty(&mut self, name: &str, attributes: &[(&str, String)]) {
        self.start(name, attributes);
        self.text.push_str("/>\n");
    }

    /// `<name>text</name>`.
    fn leaf(&mut self, name: &str, text: &str) {
        self.start(name, &[]);
        let _ = writeln!(self.text, ">{}</{name}>", escape(text, false));
    }

    fn close(&mut self, name: &str) {
        self.depth -= 1;
        let _ = writeln!(self.text, "{}</{name}>", "  ".repeat(self.depth));
    }
}

/// `s` as XML 1.0 character data or (`attribute`) an attribute value: markup characters
/// escaped; in attribute values, line breaks and tabs as character references (a parser would
/// fold them into spaces); the control characters XML 1.0 cannot carry at all replaced by
/// U+FFFD. (As attribute values, the result is also valid HTML text and attribute values:
/// the regression report uses it.)
pub(super) fn escape(s: &str, attribute: bool) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' if attribute => out.push_str("&#10;"),
            '\t' if attribute => out.push_str("&#9;"),
            '\n' | '\t' => out.push(c),
            '\r' => out.push_str("&#13;"),
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

/// Writes the JUnit XML of `results` to `path`, atomically.
pub fn write(results: &Results, path: &Path) -> crate::Result<()> {
    let text = junit(results);
    crate::write_file(path, text.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped_and_control_characters_replaced() {
        assert_eq!(
            escape("a<b>&\"c\" 'd'\n\u{1}", true),
            "a&lt;b&gt;&amp;&quot;c&quot; &apos;d&apos;&#10;\u{FFFD}"
        );
        assert_eq!(escape("x\ny\tz\r", false), "x\ny\tz&#13;");
    }

    #[test]
    fn seconds_are_decimals() {
        assert_eq!(seconds(1.23456), "1.235");
        assert_eq!(seconds(f64::NAN), "0.000");
        assert_eq!(seconds(-1.0), "0.000");
    }
}
