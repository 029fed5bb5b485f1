//! The report's HTML: templates filled with escaped text. No inline styles or scripts (see
//! the module above): sizes are `width`/`height` attributes, looks are classes of
//! `report.css`.

use super::{Entry, Shown, Slot};
use crate::regress::junit::escape;
use crate::regress::results::{Counts, Results, Run};
use crate::regress::{Row, Status};
use ffvk::images::compare::{channel_gain, Comparison, PixelDiff};

/// The page's style sheet, written beside it as `report.css`.
pub(super) const CSS: &str = include_str!("report.css");

/// The longest side, in CSS pixels, an entry's images are shown at.
const SHOWN_SIDE: u32 = 288;
/// The largest whole-number enlargement of small images.
const MAX_ZOOM: u32 = 8;

/// Text for HTML content and attribute values.
fn text(s: &str) -> String {
    escape(s, true)
}

/// The whole page.
pub(super) fn page(results: &Results, entries: &[Entry], passes: &[&Row]) -> String {
    let counts = results.counts();
    let attention = if entries.is_empty() {
        "<h2>Nothing to look at: no image failed, lacks its reference, errored or was blessed.</h2>"
            .to_string()
    } else {
        format!("<h2>{} image(s) to look at, worst first</h2>", entries.len())
    };
    let body: String = entries.iter().map(entry).collect();
    format!(
        r#"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="ffvk {version}">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src 'self'; style-src 'self'">
<title>ffvk report: {title}</title>
<link rel="stylesheet" href="report.css">
</head>
<body>
<header>
<h1>ffvk regression report</h1>
<p class="counts">{badges}</p>
{runs}
{tolerance}
</header>
<main>
{attention}
{body}
{passes}
</main>
</body>
</html>
"#,
        version = env!("CARGO_PKG_VERSION"),
        title = text(&counts.to_string()),
        badges = badges(&counts),
        runs = runs(&results.runs),
        tolerance = tolerances(&results.runs),
        passes = pass_list(passes),
    )
}

/// The counts, one badge each (zero counts of the rarer kinds left out).
fn badges(c: &Counts) -> String {
    let always = [
        (c.passed, "passed", "pass"),
        (c.failed, "failed", "fail"),
        (c.missing, "missing", "missing"),
        (c.errors, "error(s)", "error"),
        (c.blessed, "blessed", "blessed"),
    ];
    let mut out: Vec<String> = always
        .iter()
        .map(|(n, word, class)| {
            format!(r#"<span class="badge {class}" data-count="{class}">{n} {word}</span>"#)
        })
        .collect();
    if c.rendered > 0 {
        out.push(format!(
            r#"<span class="badge rendered" data-count="rendered">{} rendered, not checked</span>"#,
            c.rendered
        ));
    }
    format!("{} of {} image(s)", out.join(" "), c.images)
}

/// One table row per run (one per shard of a merged run): where and how it ran.
fn runs(runs: &[Run]) -> String {
    let rows: String = runs
        .iter()
        .map(|run| {
            let i = &run.info;
            let (device, driver) = match &i.device {
                Some(d) => (
                    format!("{} ({})", d.device, d.device_type),
                    format!("{} {} · Vulkan {}", d.driver, d.driver_info, d.api_version),
                ),
                None => ("no worker started".into(), "-".into()),
            };
            let shard = i.partition.map_or("whole suite".into(), |p| format!("shard {p}"));
            format!(
                "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{} × LP_NUM_THREADS={}</td><td>{} UTC</td><td>{:.1} s</td></tr>\n",
                text(&shard),
                text(&device),
                text(&driver),
                text(&i.hostname),
                i.scenes,
                i.jobs,
                text(i.lp_num_threads.as_deref().unwrap_or("unset")),
                text(&i.timestamp),
                i.seconds
            )
        })
        .collect();
    format!(
        r#"<table class="runs">
<tr><th>run</th><th>device</th><th>driver</th><th>host</th><th>scenes</th><th>workers</th><th>started</th><th>took</th></tr>
{rows}</table>"#
    )
}

/// The tolerances images were checked with (one line per distinct one) and the reference
/// folders.
fn tolerances(runs: &[Run]) -> String {
    let mut lines: Vec<String> = Vec::new();
    for run in runs {
        let t = &run.info.tolerance;
        let scope = if t.flip_all_pixels {
            "counted at every pixel"
        } else {
            "counted at the pixels over the threshold"
        };
        let refs = run
            .info
            .references
            .as_ref()
            .map_or("No references (not checked)".into(), |r| {
                format!("References: {}", r.display())
            });
        let line = format!(
            "Tolerance: a channel may differ by {}/255; at most {} % of the pixels may exceed that; mean FLIP at most {} ({scope}). {}{}.",
            t.threshold,
            percent(t.max_share),
            t.max_flip,
            refs,
            if run.info.bless { ", blessing" } else { "" }
        );
        if !lines.contains(&line) {
            lines.push(line);
        }
    }
    lines
        .iter()
        .map(|l| format!("<p class=\"tolerance\">{}</p>", text(l)))
        .collect::<Vec<_>>()
        .join("\n")
}

/// A share as a percentage with at most six decimals, trailing zeros dropped (0.007 →
/// "0.7", not "0.7000000000000001").
fn percent(share: f64) -> String {
    let text = format!("{:.6}", share * 100.0);
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The scale the images of an entry are shown at: whole-number enlargements of small images
/// (drawn pixelated, so that pixels stay pixels), reductions of large ones; the same for all
/// four so that they line up.
fn scale(entry: &Entry) -> f64 {
    let long = [&entry.reference, &entry.actual, &entry.channels, &entry.flip]
        .into_iter()
        .filter_map(|s| match s {
            Slot::Shown(s) => Some(s.width.max(s.height)),
            _ => None,
        })
        .max()
        .unwrap_or(SHOWN_SIDE);
    if long <= SHOWN_SIDE {
        f64::from((SHOWN_SIDE / long.max(1)).clamp(1, MAX_ZOOM))
    } else {
        f64::from(SHOWN_SIDE) / f64::from(long)
    }
}

/// An image at `scale`, linking to its full PNG.
fn img(shown: &Shown, scale: f64, alt: &str, class: &str) -> String {
    let (w, h) = (
        ((f64::from(shown.width) * scale).round() as u32).max(1),
        ((f64::from(shown.height) * scale).round() as u32).max(1),
    );
    let pixelated = if scale > 1.0 { " zoomed" } else { "" };
    format!(
        r#"<a class="{class}" href="{full}" title="{alt}: full image, {iw}×{ih}"><img class="picture{pixelated}" src="{src}" width="{w}" height="{h}" alt="{alt}" loading="lazy" data-kind="{kind}"></a>"#,
        full = text(&shown.full),
        src = text(&shown.src),
        iw = shown.width,
        ih = shown.height,
        alt = text(alt),
        kind = text(alt),
    )
}

/// What stands in a place without an image.
fn placeholder(slot: &Slot, absent: &str) -> String {
    let why = match slot {
        Slot::Unreadable(why) => why.as_str(),
        _ => absent,
    };
    format!(r#"<div class="none">{}</div>"#, text(why))
}

/// One figure: an image (or what stands for it) and its caption.
fn figure(class: &str, slot: &Slot, scale: f64, caption: &str, absent: &str) -> String {
    let inner = match slot {
        Slot::Shown(s) => img(s, scale, caption, "only"),
        other => placeholder(other, absent),
    };
    format!(
        r#"<figure class="slot {class}"><div class="stack">{inner}</div><figcaption>{}</figcaption></figure>"#,
        text(caption)
    )
}

/// The reference and actual places: with both images, each place holds both, stacked, and
/// the entry's toggle flips which one shows.
fn flippable(entry: &Entry, scale: f64, reference_caption: &str, actual_caption: &str) -> (String, bool) {
    match (&entry.reference, &entry.actual) {
        (Slot::Shown(r), Slot::Shown(a)) => {
            let place = |class: &str, first: (&Shown, &str), second: (&Shown, &str)| {
                format!(
                    r#"<figure class="slot {class}"><div class="stack">{}{}</div><figcaption><span class="a">{}</span><span class="b">{} (flipped)</span></figcaption></figure>"#,
                    img(first.0, scale, first.1, "a"),
                    img(second.0, scale, second.1, "b"),
                    text(first.1),
                    text(second.1),
                )
            };
            let both = place("reference", (r, reference_caption), (a, actual_caption))
                + &place("actual", (a, actual_caption), (r, reference_caption));
            (both, true)
        }
        _ => {
            let absent = match entry.row.status {
                Status::Missing => "no reference: rerun with --bless to make this image the reference",
                Status::Blessed => "no earlier reference: this image is the new one",
                _ => "no reference image",
            };
            let both = figure("reference", &entry.reference, scale, reference_caption, absent)
                + &figure(
                    "actual",
                    &entry.actual,
                    scale,
                    actual_caption,
                    "no image was written",
                );
            (both, false)
        }
    }
}

/// One image shown in full: heading, images, figures.
fn entry(entry: &Entry) -> String {
    let row = entry.row;
    let n = entry.number;
    let scale = scale(entry);
    let (reference_caption, actual_caption) = match row.status {
        Status::Blessed => ("previous reference", "actual (the new reference)"),
        _ => ("reference", "actual"),
    };
    let any_image = [&entry.reference, &entry.actual, &entry.channels, &entry.flip]
        .into_iter()
        .any(|s| !matches!(s, Slot::Absent));
    let (pair, flips) = flippable(entry, scale, reference_caption, actual_caption);
    let toggle = if flips {
        format!(
            r#"<input type="checkbox" class="flip" id="flip-{n}"><label class="flip-button" for="flip-{n}">Flip reference ⇄ actual</label>"#
        )
    } else {
        String::new()
    };
    let channels_caption = match &row.comparison {
        Some(c) => format!(
            "per-channel |actual − reference| ×{:.1}",
            channel_gain(c.max_diff.into_iter().max().unwrap_or(0))
        ),
        None => "per-channel |actual − reference|".to_string(),
    };
    let identical = match (row.status, &row.comparison) {
        (Status::Missing, _) => "no reference to compare with",
        (Status::Blessed, None) if matches!(entry.reference, Slot::Absent) => {
            "no earlier reference to compare with"
        }
        (_, None) => "not compared (see above)",
        (_, Some(_)) => "identical: no difference to map",
    };
    let channels = figure("channels", &entry.channels, scale, &channels_caption, identical);
    let flip = figure(
        "flip",
        &entry.flip,
        scale,
        "FLIP error (magma; red: over the threshold, rated dim)",
        identical,
    );
    // A scene that did not load has nothing to show but its message.
    let images = if any_image {
        format!("<div class=\"images\">{pair}{channels}{flip}</div>\n")
    } else {
        String::new()
    };
    let message = row
        .message
        .as_ref()
        .map(|m| format!("<p class=\"message\">{}</p>\n", text(m)))
        .unwrap_or_default();
    let mode = row.mode.as_deref().unwrap_or("-");
    format!(
        r##"<section class="entry {status}" id="e{n}" data-name="{name}" data-status="{status}">
<h3><span class="badge {status}">{word}</span> <a href="#e{n}">{name}</a> <span class="mode">{mode}</span></h3>
<p class="scene">scene {scene}</p>
{message}{toggle}
{images}{numbers}
</section>
"##,
        status = status_class(row.status),
        word = row.status.word(),
        name = text(&row.name),
        mode = text(mode),
        scene = text(&row.file.display().to_string()),
        numbers = numbers(row),
    )
}

/// The CSS class (and `data-status`) of a status.
fn status_class(status: Status) -> &'static str {
    match status {
        Status::Rendered => "rendered",
        Status::Pass => "pass",
        Status::Fail => "fail",
        Status::Missing => "missing",
        Status::Blessed => "blessed",
        Status::Error => "error",
    }
}

/// A pixel and its two values.
fn pixel(p: &PixelDiff) -> String {
    let rgba = |v: [u8; 4]| format!("({}, {}, {}, {})", v[0], v[1], v[2], v[3]);
    format!(
        "({}, {}): reference {}, actual {}",
        p.x,
        p.y,
        rgba(p.expected),
        rgba(p.actual)
    )
}

/// The figures of a comparison, one table row each (`data-figure` names them for tools).
fn numbers(row: &Row) -> String {
    let Some(c) = &row.comparison else {
        return format!(
            r#"<table class="numbers"><tr data-figure="seconds"><th>rendered in</th><td>{:.3} s</td></tr></table>"#,
            row.seconds
        );
    };
    let figures = comparison_figures(c);
    let rows: String = figures
        .iter()
        .chain(std::iter::once(&(
            "seconds",
            "rendered in".to_string(),
            format!("{:.3} s", row.seconds),
        )))
        .map(|(key, label, value)| {
            format!(
                "<tr data-figure=\"{key}\"><th>{}</th><td>{}</td></tr>",
                text(label),
                text(value)
            )
        })
        .collect();
    format!("<table class=\"numbers\">{rows}</table>")
}

/// (key, label, value) for each figure of a comparison.
fn comparison_figures(c: &Comparison) -> Vec<(&'static str, String, String)> {
    let d = c.max_diff;
    let flip = match c.flip_mean {
        Some(f) if c.flip_all_pixels => format!("{f:.5} (every pixel)"),
        Some(f) => format!("{f:.5} (pixels over the threshold)"),
        None => "not computed".into(),
    };
    let none = || "none".to_string();
    vec![
        ("size", "size".into(), format!("{}×{}", c.width, c.height)),
        (
            "max-diff",
            "max difference R, G, B, A".into(),
            format!("{}, {}, {}, {} (of 255)", d[0], d[1], d[2], d[3]),
        ),
        (
            "over",
            format!("over the threshold ({}/255)", c.threshold),
            format!("{} pixel(s), {:.4} %", c.over, c.share_over * 100.0),
        ),
        ("flip", "mean FLIP".into(), flip),
        (
            "first-over",
            "first pixel over the threshold".into(),
            match &c.first_over {
                Some(p) => pixel(p),
                // Results files of ffvk before the report do not record it.
                None if c.over > 0 => "not recorded".into(),
                None => none(),
            },
        ),
        (
            "worst",
            "largest difference".into(),
            c.worst.as_ref().map_or_else(none, pixel),
        ),
    ]
}

/// The images that passed (or were only rendered), collapsed.
fn pass_list(passes: &[&Row]) -> String {
    if passes.is_empty() {
        return String::new();
    }
    let rows: String = passes
        .iter()
        .map(|r| {
            let (diff, flip) = match &r.comparison {
                Some(c) if c.identical() => ("identical".to_string(), "-".to_string()),
                Some(c) => (
                    format!("{:?}", c.max_diff),
                    c.flip_mean.map_or("-".into(), |f| format!("{f:.5}")),
                ),
                None => ("-".into(), "-".into()),
            };
            format!(
                "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.3}</td></tr>\n",
                text(&r.name),
                text(r.mode.as_deref().unwrap_or("-")),
                r.status.word(),
                text(&diff),
                flip,
                r.seconds
            )
        })
        .collect();
    format!(
        r#"<details class="passes"><summary>{} image(s) passed or rendered</summary>
<table>
<tr><th>image</th><th>mode</th><th>status</th><th>max diff RGBA</th><th>FLIP</th><th>seconds</th></tr>
{rows}</table>
</details>"#,
        passes.len()
    )
}
