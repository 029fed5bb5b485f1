//! Regression runs: render many scenes with one device, check each image against a directory
//! of references, bless new or changed references on request, and summarize in a table.

#![warn(missing_docs)]

use std::path::{Path, PathBuf};

use crate::gl::state::LightingMode;
use crate::images::compare::{compare, heat_map, load_image, Comparison, Tolerance};
use crate::images::save_png;
use crate::scene::{render_scene, Scene};
use crate::tools::table::{Align, Table};
use crate::tools::{Error, Result};
use crate::Renderer;

/// The environment variable that blesses references (any value but "0").
pub const BLESS_VAR: &str = "FFVK_BLESS";

/// Whether FFVK_BLESS asks for blessing.
pub fn bless_from_env() -> bool {
    std::env::var_os(BLESS_VAR).is_some_and(|v| v != "0")
}

/// What to render and how to check it.
#[derive(Debug, Clone, Default)]
pub struct Job {
    /// Scene files, or directories of them (*.toml, in name order).
    pub scenes: Vec<PathBuf>,
    /// The output directory (NAME.png each); `None` writes next to each scene file.
    pub out_dir: Option<PathBuf>,
    /// Lighting modes to render each scene in; empty: the scene's own. With more than one,
    /// images are named NAME_MODE.png.
    pub modes: Vec<LightingMode>,
    /// Render at this size (width, height) instead of each scene's own.
    pub size: Option<(u32, u32)>,
    /// A directory of reference images (same names) to check against.
    pub references: Option<PathBuf>,
    /// Write the actual image as the reference when it is missing or differs.
    pub bless: bool,
    /// How far an image may differ from its reference and pass.
    pub tolerance: Tolerance,
}

/// What happened to one image.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Rendered; nothing to check against.
    Rendered,
    /// Within the tolerance of its reference.
    Pass,
    /// Beyond the tolerance of its reference.
    Fail,
    /// No reference and no blessing: a failure.
    Missing,
    /// The reference was written (new) or replaced (changed) by blessing.
    Blessed,
}

impl Status {
    /// Whether the image fails the run: it differs or has no reference.
    pub fn failed(self) -> bool {
        matches!(self, Status::Fail | Status::Missing)
    }
}

/// One line of the summary.
#[derive(Debug, Clone)]
pub struct Row {
    /// The image's name: the scene file's stem, with the mode when there are several.
    pub name: String,
    /// What happened.
    pub status: Status,
    /// The comparison with the reference, when there was one.
    pub comparison: Option<Comparison>,
    /// The image written.
    pub output: PathBuf,
    /// The heat map of the differences, when the image is not identical to its reference.
    pub diff: Option<PathBuf>,
}

/// Expands directories into their *.toml files, in name order.
pub fn scene_files(inputs: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for input in inputs {
        if input.is_dir() {
            let entries = std::fs::read_dir(input).map_err(|source| Error::Read {
                path: input.clone(),
                source,
            })?;
            let mut found: Vec<PathBuf> = entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .collect();
            found.sort();
            if found.is_empty() {
                return Err(Error::Path {
                    path: input.clone(),
                    problem: "no .toml scene files in this directory",
                });
            }
            files.extend(found);
        } else {
            files.push(input.clone());
        }
    }
    Ok(files)
}

/// Loads a scene, resized when asked; warnings go to `log`.
pub fn load_scene(path: &Path, size: Option<(u32, u32)>, log: &mut dyn FnMut(&str)) -> Result<Scene> {
    let mut scene = Scene::load(path)?;
    for w in &scene.warnings {
        log(&format!("warning: {w}"));
    }
    if let Some((w, h)) = size {
        scene.set_size(w, h);
    }
    Ok(scene)
}

/// Renders every scene of `job` in every mode, checking and blessing as asked. Errors stop
/// the run (a scene that cannot load is not a difference); differences are rows.
pub fn run(renderer: &mut Renderer, job: &Job, log: &mut dyn FnMut(&str)) -> Result<Vec<Row>> {
    let files = scene_files(&job.scenes)?;
    let mut rows = Vec::new();
    for file in &files {
        let scene = load_scene(file, job.size, log)?;
        let stem = file
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let modes: Vec<Option<LightingMode>> = if job.modes.is_empty() {
            vec![None]
        } else {
            job.modes.iter().copied().map(Some).collect()
        };
        for mode in &modes {
            let name = match mode {
                Some(m) if modes.len() > 1 => format!("{stem}_{}", m.name()),
                _ => stem.clone(),
            };
            let image = render_scene(renderer, &scene, *mode)?;
            let dir = job
                .out_dir
                .clone()
                .unwrap_or_else(|| file.parent().unwrap_or(Path::new(".")).to_path_buf());
            let output = dir.join(format!("{name}.png"));
            save_png(&image, &output)?;
            let mut row = Row {
                name: name.clone(),
                status: Status::Rendered,
                comparison: None,
                output: output.clone(),
                diff: None,
            };
            if let Some(refs) = &job.references {
                let reference = refs.join(format!("{name}.png"));
                if !reference.exists() {
                    row.status = if job.bless {
                        Status::Blessed
                    } else {
                        Status::Missing
                    };
                } else {
                    let expected = load_image(&reference)?;
                    let c = compare(&expected, &image, job.tolerance.threshold)?;
                    row.status = match (c.passes(&job.tolerance), job.bless && !c.identical()) {
                        (_, true) => Status::Blessed,
                        (true, false) => Status::Pass,
                        (false, false) => Status::Fail,
                    };
                    if !c.identical() {
                        let diff = dir.join(format!("{name}.diff.png"));
                        save_png(&heat_map(&expected, &image, job.tolerance.threshold)?, &diff)?;
                        row.diff = Some(diff);
                    }
                    row.comparison = Some(c);
                }
                if row.status == Status::Blessed {
                    save_png(&image, &reference)?;
                }
            }
            log(&format!("{} -> {}", file.display(), output.display()));
            rows.push(row);
        }
    }
    Ok(rows)
}

/// The summary table: scene, status, max difference, share over the threshold, FLIP mean;
/// then the count of images and of failures.
pub fn table(rows: &[Row]) -> String {
    let mut t = Table::new([
        ("scene", Align::Left),
        ("status", Align::Left),
        ("max diff RGBA", Align::Right),
        ("over %", Align::Right),
        ("FLIP", Align::Right),
    ]);
    for r in rows {
        let status = match r.status {
            Status::Rendered => "rendered",
            Status::Pass => "ok",
            Status::Fail => "FAILED",
            Status::Missing => "MISSING",
            Status::Blessed => "blessed",
        };
        let (diff, over, flip) = match &r.comparison {
            Some(c) => (
                format!("{:?}", c.max_diff),
                format!("{:.4}", c.share_over * 100.0),
                format!("{:.5}", c.flip_mean),
            ),
            None => ("-".into(), "-".into(), "-".into()),
        };
        t.row([r.name.clone(), status.into(), diff, over, flip]);
    }
    let failed = rows.iter().filter(|r| r.status.failed()).count();
    format!("{}{} image(s), {} failed", t.text(), rows.len(), failed)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn comparison(max_diff: [u8; 4], share_over: f64, flip_mean: f32) -> Comparison {
        Comparison {
            width: 128,
            height: 128,
            max_diff,
            over: (share_over * 128.0 * 128.0) as usize,
            share_over,
            flip_mean,
            worst: None,
            threshold: 1,
        }
    }

    #[test]
    fn the_summary_table() {
        let row = |name: &str, status, comparison| Row {
            name: name.into(),
            status,
            comparison,
            output: PathBuf::from(format!("out/{name}.png")),
            diff: None,
        };
        let same = comparison([0; 4], 0.0, 0.0);
        let different = comparison([255, 12, 3, 0], 0.0123, 0.04567);
        let rows = [
            row("a", Status::Rendered, None),
            row("spot_light_vertex", Status::Pass, Some(same)),
            row("b", Status::Fail, Some(different)),
            row("missing_one", Status::Missing, None),
            row("new", Status::Blessed, None),
        ];
        let expected = "\
scene              status      max diff RGBA  over %     FLIP\n\
a                  rendered                -       -        -\n\
spot_light_vertex  ok           [0, 0, 0, 0]  0.0000  0.00000\n\
b                  FAILED    [255, 12, 3, 0]  1.2300  0.04567\n\
missing_one        MISSING                 -       -        -\n\
new                blessed                 -       -        -\n\
5 image(s), 2 failed";
        assert_eq!(table(&rows), expected);
    }
}
