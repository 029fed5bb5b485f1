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

use std::path::{Path, PathBuf};

use super::results::Results;
use super::{Row, Status};
use crate::images::load_image;
use crate::images::thumbnail::{thumbnail, Reduce};
use crate::tools::{Error, Result};

/// Images whose longer side exceeds this are shown through a thumbnail of this size (twice
/// the largest size the page shows them at, for high-density screens).
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
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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
    prepare(results, dir)?;
    let rows = results.rows();
    let mut attention: Vec<&Row> = rows.iter().filter(|r| needs_attention(r)).collect();
    attention.sort_by(|a, b| {
        severity(a)
            .total_cmp(&severity(b))
            .reverse()
            .then(a.index.cmp(&b.index))
    });
    let images = dir.join("images");
    let mut unreadable = Vec::new();
    let mut entries = Vec::with_capacity(attention.len());
    for (i, row) in attention.into_iter().enumerate() {
        let number = i + 1;
        let mut slot = |kind: Kind, source: Option<&PathBuf>| match source {
            None => Ok(Slot::Absent),
            Some(path) => show(path, kind, number, &images).or_else(|e| match e {
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
    let passes: Vec<&Row> = rows.iter().filter(|r| !needs_attention(r)).collect();
    let html = page::page(results, &entries, &passes);
    crate::tools::write_file(&dir.join("report.css"), page::CSS.as_bytes())?;
    let index = dir.join("index.html");
    crate::tools::write_file(&index, html.as_bytes())?;
    Ok(Written {
        page: index,
        entries: entries.len(),
        unreadable,
    })
}

/// Whether a row is shown in full: it failed, lacks its reference, errored or was blessed.
fn needs_attention(row: &Row) -> bool {
    matches!(
        row.status,
        Status::Fail | Status::Missing | Status::Error | Status::Blessed
    )
}

/// How bad a row is, for the order of the page (larger first): errors, then failures by
/// their mean FLIP, share over the threshold and largest difference (a size mismatch first of
/// all), then missing references, then blessings by the same figures.
fn severity(row: &Row) -> f64 {
    let figures = |row: &Row| match &row.comparison {
        // FLIP and share are in [0, 1], the difference in [0, 255]: FLIP decides first.
        Some(c) => {
            let max = c.max_diff.iter().copied().max().unwrap_or(0);
            f64::from(c.flip_mean.unwrap_or(1.0)) * 0.5 + c.share_over * 0.25 + f64::from(max) / 255.0 * 0.2
        }
        None => 1.0,
    };
    match row.status {
        Status::Error => 4.0,
        Status::Fail => 2.0 + figures(row),
        Status::Missing => 1.5,
        Status::Blessed => figures(row),
        _ => 0.0,
    }
}

/// Why an image could not be shown: a file the run named that is gone or broken (shown in
/// its place), or the report's own folder failing (an error).
enum Unshown {
    Unreadable(String),
    Fatal(Error),
}

/// Copies `source` into the report's `images/` as NUMBER-KIND.png (a hard link when the
/// file system allows), with a thumbnail when it is large.
fn show(source: &Path, kind: Kind, number: usize, images: &Path) -> std::result::Result<Slot, Unshown> {
    let (width, height) = image::image_dimensions(source)
        .map_err(|e| Unshown::Unreadable(format!("{}: cannot read the image: {e}", source.display())))?;
    let name = format!("{number}-{}.png", kind.file_stem());
    let target = images.join(&name);
    if std::fs::hard_link(source, &target).is_err() {
        std::fs::copy(source, &target).map_err(|e| {
            Unshown::Fatal(Error::Write {
                path: target.clone(),
                source: e,
            })
        })?;
    }
    let mut src = format!("images/{name}");
    if width.max(height) > THUMBNAIL_SIDE {
        let image = load_image(source).map_err(|e| Unshown::Unreadable(e.to_string()))?;
        if let Some(small) = thumbnail(&image, THUMBNAIL_SIDE, kind.reduce()) {
            let name = format!("{number}-{}.thumb.png", kind.file_stem());
            crate::images::save_png(&small, &images.join(&name)).map_err(|e| Unshown::Fatal(e.into()))?;
            src = format!("images/{name}");
        }
    }
    Ok(Slot::Shown(Shown {
        full: format!("images/{name}"),
        src,
        width,
        height,
    }))
}

/// Makes `dir` ready for a report: refuses a folder inside a reference folder and a
/// non-empty folder that no report wrote; empties an earlier report's images.
fn prepare(results: &Results, dir: &Path) -> Result<()> {
    for run in &results.runs {
        if let Some(refs) = &run.info.references {
            if crate::files::is_within(dir, refs) {
                return Err(Error::OutputInReferences {
                    output: dir.to_path_buf(),
                    references: refs.clone(),
                });
            }
        }
    }
    if dir.exists() {
        if !dir.is_dir() {
            return Err(Error::Path {
                path: dir.to_path_buf(),
                problem: "is not a folder: --report expects a folder to write the report into",
            });
        }
        let read = |source| Error::Read {
            path: dir.to_path_buf(),
            source,
        };
        let empty = std::fs::read_dir(dir).map_err(read)?.next().is_none();
        if !empty && !dir.join(MARKER).is_file() {
            return Err(Error::Path {
                path: dir.to_path_buf(),
                problem: "is not empty and holds no earlier ffvk report: expected a new or empty folder, or one a report wrote (its images are replaced)",
            });
        }
    }
    let images = dir.join("images");
    if images.exists() {
        std::fs::remove_dir_all(&images).map_err(|source| Error::Write {
            path: images.clone(),
            source,
        })?;
    }
    std::fs::create_dir_all(&images).map_err(|source| Error::Write {
        path: images.clone(),
        source,
    })?;
    crate::tools::write_file(
        &dir.join(MARKER),
        b"An ffvk regression report: each report written here replaces images/ and index.html.\n",
    )
}
