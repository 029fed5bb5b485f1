//! The regression report: a static HTML page (`index.html`, `report.css` and `images/` in one
//! folder) that shows a checked run for triage. At the top the counts, devices and tolerances;
//! then every image that failed, lacks its reference, errored or was blessed, worst first,
//! with its reference, actual image, per-channel difference map and FLIP map side by side and
//! its figures; passes collapsed in a list.
//!
//! The folder is self-contained (the images it shows are copied into it) and the page needs
//! neither a server, the network nor scripts: the reference/actual toggle is a checkbox and
//! CSS, and the styles live in their own file, so the page also works under the
//! content-security policies CI servers put on artifacts (Jenkins forbids inline styles and
//! scripts); the page's own policy allows images and styles from its folder only. Images larger than [`THUMBNAIL_SIDE`] are shown as thumbnails linking to the
//! full PNG.

mod page;

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use super::results::Results;
use super::{Row, Status};
use crate::{Error, Result};
use ffvk::images::load_image;
use ffvk::images::thumbnail::{thumbnail, Reduce};

/// Images whose longer side exceeds this are shown through a thumbnail of this size (more
/// than twice the largest size the page shows them at, for high-density screens).
pub const THUMBNAIL_SIDE: u32 = 640;

/// The file that marks a folder as a report, so that a later report may replace its images
/// (and a folder that is not one is never emptied).
const MARKER: &str = ".ffvk-report";

/// What [`write`] wrote.
#[derive(Debug, Clone)]
pub struct Written {
    /// The page.
    pub page: PathBuf,
    /// Images shown in full (failed, missing, errored and blessed).
    pub entries: usize,
    /// Image files the rows name that could not be shown, with why (the page says so in
    /// their place).
    pub unreadable: Vec<String>,
}

/// One image of an entry, as the page shows it.
#[derive(Debug, Clone)]
struct Shown {
    /// The full PNG, relative to the page.
    full: String,
    /// What the page shows: the full PNG or its thumbnail, relative to the page.
    src: String,
    /// The image's size.
    width: u32,
    height: u32,
}

/// The four places of an entry, in the order the page shows them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Kind {
    Reference,
    Actual,
    Channels,
    Flip,
}

impl Kind {
    fn file_stem(self) -> &'static str {
        match self {
            Kind::Reference => "reference",
            Kind::Actual => "actual",
            Kind::Channels => "channels",
            Kind::Flip => "flip",
        }
    }

    /// How thumbnails keep what matters: pictures are averaged, difference maps keep their
    /// largest values so that a single differing pixel still shows.
    fn reduce(self) -> Reduce {
        match self {
            Kind::Reference | Kind::Actual => Reduce::Mean,
            Kind::Channels | Kind::Flip => Reduce::Max,
        }
    }
}

/// One place of an entry: the image, or why there is none.
#[derive(Debug, Clone)]
enum Slot {
    Shown(Shown),
    /// The row names no such image (no reference yet, identical images, an error).
    Absent,
    /// The row names the file, but it cannot be read.
    Unreadable(String),
}

/// One image the page shows in full.
#[derive(Debug, Clone)]
struct Entry<'a> {
    row: &'a Row,
    /// Its place in the page (and its images' file names): 1, 2, …
    number: usize,
    reference: Slot,
    actual: Slot,
    channels: Slot,
    flip: Slot,
}

/// Writes the report of `results` into `dir`: `dir/index.html`, `dir/report.css` and
/// `dir/images/`. `dir` must be new, empty or an earlier report (whose images are replaced);
/// it may not lie inside a reference folder. Image files the rows name but that cannot be read
/// are reported in [`Written::unreadable`] and in the page, not as an error.
pub fn write(results: &Results, dir: &Path) -> Result<Written> {
    let references: Vec<&Path> = results
        .runs
        .iter()
        .filter_map(|r| r.info.references.as_deref())
        .collect();
    claim(dir, &references)?;
    let rows = results.rows();
    // The images are copied into a folder of their own and swapped in at the end, so that
    // an earlier report stays whole until this one is.
    let final_images = dir.join("images");
    for row in &rows {
        let paths = [
            &row.output,
            &row.reference,
            &row.diff,
            &row.channels,
            &row.replaced,
        ];
        if let Some(path) = paths
            .into_iter()
            .flatten()
            .find(|p| ffvk::files::is_within(p, &final_images))
        {
            return Err(Error::Path {
                path: path.clone(),
                problem: "lies in the report's images/ folder, which each report replaces: expected the run's images outside the report folder",
            });
        }
    }
    let images = dir.join(".images.new");
    remove_folder(&images)?;
    std::fs::create_dir_all(&images).map_err(|source| Error::Write {
        path: images.clone(),
        source,
    })?;
    // A fault while the images are staged (a full disk in the middle of a copy) leaves no
    // part-written folder behind: the earlier report's images/ are untouched.
    let staged = stage_entries(&rows, &images).inspect_err(|_| {
        let _ = remove_folder(&images);
    });
    let (entries, unreadable) = staged?;
    let passes: Vec<&Row> = rows.iter().filter(|r| !needs_attention(r)).collect();
    let html = page::page(results, &entries, &passes);
    let css = own_file(dir, "report.css").inspect_err(|_| {
        let _ = remove_folder(&images);
    })?;
    crate::write_file(&css, page::CSS.as_bytes()).inspect_err(|_| {
        let _ = remove_folder(&images);
    })?;
    let old = dir.join(".images.old");
    remove_folder(&old)?;
    let moved = |from: &Path, to: &Path| {
        std::fs::rename(from, to).map_err(|source| Error::Write {
            path: to.to_path_buf(),
            source,
        })
    };
    if final_images.exists() {
        moved(&final_images, &old)?;
    }
    // Past this point a fault puts the earlier report's images back, so that its page and
    // its images still go together.
    let restore = || {
        let _ = remove_folder(&images);
        let _ = remove_folder(&final_images);
        if old.exists() {
            let _ = std::fs::rename(&old, &final_images);
        }
    };
    moved(&images, &final_images).inspect_err(|_| restore())?;
    let index = own_file(dir, "index.html").inspect_err(|_| restore())?;
    crate::write_file(&index, html.as_bytes()).inspect_err(|_| restore())?;
    remove_folder(&old)?;
    Ok(Written {
        page: index,
        entries: entries.len(),
        unreadable,
    })
}

/// Copies the images of every row that needs attention into `images` and makes the page's
/// entries, worst first; also the messages of the images that could not be read.
fn stage_entries<'a>(rows: &'a [Row], images: &Path) -> Result<(Vec<Entry<'a>>, Vec<String>)> {
    let mut attention: Vec<&Row> = rows.iter().filter(|r| needs_attention(r)).collect();
    attention.sort_by(|a, b| worse_first(a, b));
    let mut unreadable = Vec::new();
    let mut shown = HashMap::new();
    let mut entries = Vec::with_capacity(attention.len());
    for (i, row) in attention.into_iter().enumerate() {
        let number = i + 1;
        let mut slot = |kind: Kind, source: Option<&PathBuf>| match source {
            None => Ok(Slot::Absent),
            Some(path) => show(path, kind, number, images, &mut shown).or_else(|e| match e {
                Unshown::Unreadable(why) => {
                    unreadable.push(why.clone());
                    Ok(Slot::Unreadable(why))
                }
                Unshown::Fatal(e) => Err(e),
            }),
        };
        // Blessing replaced the reference: the one it replaced is what the image differed
        // from.
        let reference = match row.status {
            Status::Blessed => row.replaced.as_ref(),
            Status::Missing => None,
            // An error may come before the reference was looked at, or without one.
            Status::Error => row.reference.as_ref().filter(|p| p.is_file()),
            _ => row.reference.as_ref(),
        };
        entries.push(Entry {
            row,
            number,
            reference: slot(Kind::Reference, reference)?,
            actual: slot(Kind::Actual, row.output.as_ref())?,
            channels: slot(Kind::Channels, row.channels.as_ref())?,
            flip: slot(Kind::Flip, row.diff.as_ref())?,
        });
    }
    Ok((entries, unreadable))
}

/// Whether a row is shown in full: it failed, lacks its reference, errored or was blessed.
fn needs_attention(row: &Row) -> bool {
    matches!(
        row.status,
        Status::Fail | Status::Missing | Status::Error | Status::Blessed
    )
}

/// The page's order, worst first: errors, then failures, then missing references, then
/// blessings. Failures and blessings are ordered by mean FLIP, then share over the threshold,
/// then largest difference, each larger first; a failure of another size (nothing compared)
/// comes before every compared one, a blessing of a new reference (nothing compared) after
/// every changed one. Ties keep suite order.
fn worse_first(a: &Row, b: &Row) -> std::cmp::Ordering {
    let rank = |r: &Row| match r.status {
        Status::Error => 0,
        Status::Fail => 1,
        Status::Missing => 2,
        _ => 3,
    };
    let figures = |r: &Row| match &r.comparison {
        Some(c) => (
            f64::from(c.flip_mean.unwrap_or(f32::INFINITY)),
            c.share_over,
            f64::from(c.max_diff.into_iter().max().unwrap_or(0)),
        ),
        None if r.status == Status::Fail => (f64::INFINITY, f64::INFINITY, f64::INFINITY),
        None => (-1.0, -1.0, -1.0),
    };
    let (fa, fb) = (figures(a), figures(b));
    rank(a)
        .cmp(&rank(b))
        .then(fb.0.total_cmp(&fa.0))
        .then(fb.1.total_cmp(&fa.1))
        .then(fb.2.total_cmp(&fa.2))
        .then(a.index.cmp(&b.index))
}

/// Why an image could not be shown: a file the run named that is gone or broken (shown in
/// its place), or the report's own folder failing (an error).
enum Unshown {
    Unreadable(String),
    Fatal(Error),
}

/// Copies `source` into the report's `images/` as NUMBER-KIND.png (a hard link when the
/// file system allows), with a thumbnail when it is large. A file shown before as the same
/// kind (one reference behind many failing rows) is shown from its first copy: `shown` holds
/// those, so that a long report neither copies it again nor links it past the file system's
/// link limit.
fn show(
    source: &Path,
    kind: Kind,
    number: usize,
    images: &Path,
    shown: &mut HashMap<(PathBuf, Kind), Shown>,
) -> std::result::Result<Slot, Unshown> {
    let unreadable = |e: &dyn std::fmt::Display| {
        Unshown::Unreadable(format!("{}: cannot read the image: {e}", source.display()))
    };
    // The file itself: a hard link to a symbolic link would be the link, which may point
    // outside the folder or nowhere.
    let real = std::fs::canonicalize(source).map_err(|e| unreadable(&e))?;
    if !real.is_file() {
        return Err(unreadable(&"not a file"));
    }
    if let Some(earlier) = shown.get(&(real.clone(), kind)) {
        return Ok(Slot::Shown(earlier.clone()));
    }
    let (width, height) = image::image_dimensions(&real).map_err(|e| unreadable(&e))?;
    let name = format!("{number}-{}.png", kind.file_stem());
    let target = images.join(&name);
    if std::fs::hard_link(&real, &target).is_err() {
        std::fs::copy(&real, &target).map_err(|e| {
            Unshown::Fatal(Error::Write {
                path: target.clone(),
                source: e,
            })
        })?;
    }
    let mut src = format!("images/{name}");
    if width.max(height) > THUMBNAIL_SIDE {
        let image = load_image(&real).map_err(|e| unreadable(&e))?;
        if let Some(small) = thumbnail(&image, THUMBNAIL_SIDE, kind.reduce()) {
            let name = format!("{number}-{}.thumb.png", kind.file_stem());
            ffvk::images::save_png(&small, &images.join(&name)).map_err(|e| Unshown::Fatal(e.into()))?;
            src = format!("images/{name}");
        }
    }
    let this = Shown {
        full: format!("images/{name}"),
        src,
        width,
        height,
    };
    shown.insert((real, kind), this.clone());
    Ok(Slot::Shown(this))
}

/// Claims `dir` for a report before anything is written (`render --report` calls it before
/// rendering, so that a folder it would refuse is refused at once): refuses a folder inside a
/// reference folder or holding one, and a non-empty folder that no report wrote; creates the
/// folder and its marker. Nothing in it is removed.
pub fn claim(given: &Path, references: &[&Path]) -> Result<()> {
    // The folder the path will name (`new/../rep` is `rep`, `link/..` the link's target's
    // parent), so that what is in it is judged, not what the spelling suggests.
    let dir = &ffvk::files::resolved(given);
    for refs in references {
        if ffvk::files::is_within(dir, refs) || ffvk::files::is_within(refs, dir) {
            return Err(Error::ReportInReferences {
                report: given.to_path_buf(),
                references: refs.to_path_buf(),
            });
        }
    }
    // The folders a report replaces whole: nothing the run reads may be in them.
    for own in ["images", ".images.new", ".images.old"] {
        if let Some(input) = ffvk::files::input_within(&dir.join(own)) {
            return Err(Error::FolderHoldsInput {
                folder: given.join(own),
                input,
            });
        }
    }
    if dir.exists() {
        if !dir.is_dir() {
            return Err(Error::Path {
                path: given.to_path_buf(),
                problem: "is not a folder: expected a folder to write the report into",
            });
        }
        let read = |source| Error::Read {
            path: given.to_path_buf(),
            source,
        };
        let empty = std::fs::read_dir(dir).map_err(read)?.next().is_none();
        // The marker itself, not what a link there points at: a link proves no report.
        let marked = std::fs::symlink_metadata(dir.join(MARKER)).is_ok_and(|m| m.file_type().is_file());
        if !empty && !marked {
            return Err(Error::Path {
                path: given.to_path_buf(),
                problem: "is not empty and holds no earlier ffvk report: expected a new or empty folder, or one a report wrote (its images are replaced)",
            });
        }
    }
    std::fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: given.to_path_buf(),
        source,
    })?;
    crate::write_file(
        &own_file(dir, MARKER)?,
        b"An ffvk regression report: each report written here replaces images/ and index.html.\n",
    )
}

/// The names a report writes in its folder: no other output of a run may take them.
pub const OWN_NAMES: [&str; 6] = [
    "index.html",
    "report.css",
    MARKER,
    "images",
    ".images.new",
    ".images.old",
];

/// `dir/name`, one of the report's own files, made safe to write: a symbolic link there
/// (which would carry the page or the style sheet to wherever it points, a scene file
/// perhaps) is removed, so the report writes a file of its own in its place.
fn own_file(dir: &Path, name: &str) -> Result<PathBuf> {
    let path = dir.join(name);
    if std::fs::symlink_metadata(&path).is_ok_and(|m| m.file_type().is_symlink()) {
        std::fs::remove_file(&path).map_err(|source| Error::Write {
            path: path.clone(),
            source,
        })?;
        eprintln!(
            "ffvk: note: {}: was a symbolic link; replaced by the report's own file (the file it pointed at is untouched)",
            path.display()
        );
    }
    Ok(path)
}

/// Removes a folder of the report's own making, if it is there.
fn remove_folder(path: &Path) -> Result<()> {
    match std::fs::remove_dir_all(path) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
        Err(source) => Err(Error::Write {
            path: path.to_path_buf(),
            source,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::regress::results::RunInfo;
    use ffvk::images::compare::{Comparison, Tolerance};

    fn row(name: &str, index: usize, status: Status, figures: Option<(f32, f64, u8)>) -> Row {
        let file = crate::regress::SceneFile {
            index,
            path: format!("{name}.toml").into(),
            name: name.into(),
        };
        let mut row = Row::new(&file, name.into(), Some(ffvk::gl::state::LightingMode::Vertex));
        row.status = status;
        row.comparison = figures.map(|(flip, share, max)| {
            let mut c = Comparison::default();
            c.width = 8;
            c.height = 8;
            c.max_diff = [max, 0, 0, 0];
            c.over = (share * 64.0) as usize;
            c.share_over = share;
            c.flip_mean = Some(flip);
            c.threshold = 2;
            c
        });
        row
    }

    #[test]
    fn entries_come_worst_first_by_status_then_flip_then_share_then_difference() {
        let rows = [
            row("large_share_small_flip", 0, Status::Fail, Some((0.10, 1.0, 255))),
            row("new_reference", 1, Status::Blessed, None),
            row("changed_reference", 2, Status::Blessed, Some((0.2, 0.1, 40))),
            row("no_reference", 3, Status::Missing, None),
            row("large_flip", 4, Status::Fail, Some((0.60, 0.001, 10))),
            row("another_size", 5, Status::Fail, None),
            row("crashed", 6, Status::Error, None),
            row("same_flip_larger_share", 7, Status::Fail, Some((0.10, 1.0, 255))),
            row("same_flip_smaller_share", 8, Status::Fail, Some((0.10, 0.5, 255))),
            row("passed", 9, Status::Pass, Some((0.0, 0.0, 1))),
        ];
        let mut order: Vec<&Row> = rows.iter().filter(|r| needs_attention(r)).collect();
        order.sort_by(|a, b| worse_first(a, b));
        let names: Vec<&str> = order.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "crashed",
                "another_size",
                "large_flip",
                // Equal figures keep suite order.
                "large_share_small_flip",
                "same_flip_larger_share",
                "same_flip_smaller_share",
                "no_reference",
                "changed_reference",
                "new_reference",
            ]
        );
    }

    #[test]
    fn names_and_messages_are_escaped_in_the_page() {
        let mut bad = row("a<b>&\"c'", 0, Status::Error, None);
        bad.message = Some("<script>alert(1)</script>\nline 2".into());
        let results = Results::single(
            RunInfo {
                ffvk: "test".into(),
                device: None,
                jobs: 1,
                lp_num_threads: None,
                partition: None,
                suite_scenes: 1,
                scenes: 1,
                modes: vec![],
                references: Some("refs<1>".into()),
                bless: false,
                tolerance: Tolerance::default(),
                timestamp: "2026-11-23T00:00:00".into(),
                hostname: "<host>".into(),
                seconds: 0.0,
            },
            vec![bad],
        );
        let rows = results.rows();
        let entries = [Entry {
            row: &rows[0],
            number: 1,
            reference: Slot::Absent,
            actual: Slot::Unreadable("out/<x>.png: cannot read the image".into()),
            channels: Slot::Absent,
            flip: Slot::Absent,
        }];
        let html = page::page(&results, &entries, &[]);
        for raw in ["<script>", "a<b>", "<host>", "refs<1>", "out/<x>.png"] {
            assert!(!html.contains(raw), "{raw} is not escaped");
        }
        for escaped in [
            "data-name=\"a&lt;b&gt;&amp;&quot;c&apos;\"",
            "&lt;script&gt;alert(1)&lt;/script&gt;&#10;line 2",
            "&lt;host&gt;",
            "out/&lt;x&gt;.png: cannot read the image",
        ] {
            assert!(html.contains(escaped), "no {escaped}");
        }
    }
}
