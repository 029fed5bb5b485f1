//! Regression runs: render many scenes, check each image against a directory of references,
//! bless new or changed references on request, and report the results as a table, JSON and
//! JUnit XML.
//!
//! One scene is rendered by [`render_file`], which never fails: a scene that cannot be loaded,
//! rendered or written becomes an error row. [`run`] renders a suite with one renderer in this
//! process; [`pool::run_pool`] spreads it over worker processes (`ffvk render --jobs N`), so
//! that a crash costs one scene; [`partition`] splits a suite into shards for several machines
//! and [`results`] merges what the shards wrote and writes it for CI systems.

#![warn(missing_docs)]

pub mod junit;
pub mod partition;
pub mod pool;
pub mod report;
pub mod results;
mod scenes;

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::{Deserialize, Serialize};

use crate::table::{Align, Table};
use crate::{Error, Result};
use ffvk::gl::state::LightingMode;
#[cfg(doc)]
use ffvk::images::compare::heat_map;
use ffvk::images::compare::{channel_map, compare, heat_map_with_flip, load_image, Comparison, Tolerance};
use ffvk::images::save_png;
use ffvk::scene::direct::DirectOptions;
use ffvk::scene::OpenNote;
use ffvk::scene::{Limits, Scene};
use ffvk::Renderer;

pub use partition::Partition;
pub use scenes::{folder_scenes, scene_files, FolderScenes, SceneFile};

/// The environment variable that blesses references (any value but "0").
pub const BLESS_VAR: &str = "FFVK_BLESS";

/// Whether FFVK_BLESS asks for blessing.
pub fn bless_from_env() -> bool {
    std::env::var_os(BLESS_VAR).is_some_and(|v| v != "0")
}

/// What to render and how to check it.
#[derive(Debug, Clone, Default)]
pub struct Job {
    /// Scene files (.toml), glTF files, or directories of them ([`folder_scenes`]).
    pub scenes: Vec<PathBuf>,
    /// The output directory; `None` writes next to each scene file. An image's name mirrors
    /// its scene's path relative to the directory given (`a/s.toml` → `a/s.png`); a scene
    /// given as a file is named by its stem.
    pub out_dir: Option<PathBuf>,
    /// Lighting modes to render each scene in; empty: the scene's own. With more than one,
    /// images are named NAME_MODE.png.
    pub modes: Vec<LightingMode>,
    /// Render at this size (width, height) instead of each scene's own.
    pub size: Option<(u32, u32)>,
    /// Draw the fragment mode on this path instead of each scene's own
    /// (`[image] fragment_path`).
    pub fragment_path: Option<ffvk::FragmentPath>,
    /// A directory of reference images (same names) to check against.
    pub references: Option<PathBuf>,
    /// Write the actual image as the reference when it is missing or differs.
    pub bless: bool,
    /// How far an image may differ from its reference and pass.
    pub tolerance: Tolerance,
    /// What each scene may make ffvk allocate.
    pub limits: Limits,
    /// How `.gltf`/`.glb` files among `scenes` are drawn.
    pub direct: DirectOptions,
    /// The renderer's driver family ([`driver_family`]): references in
    /// `references/FAMILY/` take precedence over the shared ones when they exist.
    pub driver_family: Option<String>,
    /// Render only this shard of the suite ([`Partition`]).
    pub partition: Option<Partition>,
}

/// The folder name of a device's driver family for per-driver references: the Vulkan driver
/// name, lower-case, anything but letters and digits turned into `-` (`llvmpipe` for
/// lavapipe, `nvidia`, `radv`, `intel-open-source-mesa-driver`).
pub fn driver_family(info: &ffvk::vk::DeviceInfo) -> String {
    let name: String = info
        .driver_name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect();
    let name = name.trim_matches('-');
    if name.is_empty() {
        "unknown".into()
    } else {
        name.into()
    }
}

/// The reference of image `name`: `refs/FAMILY/NAME.png` when the job has a driver family
/// and that file exists, else `refs/NAME.png`.
fn reference_path(refs: &Path, family: Option<&str>, name: &str) -> PathBuf {
    if let Some(family) = family {
        let own = refs.join(family).join(format!("{name}.png"));
        if own.exists() {
            return own;
        }
    }
    refs.join(format!("{name}.png"))
}

/// What happened to one image.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    /// Rendered; nothing to check against.
    Rendered,
    /// Within the tolerance of its reference.
    Pass,
    /// Beyond the tolerance of its reference (or of another size).
    Fail,
    /// No reference and no blessing: a failure.
    Missing,
    /// The reference was written (new) or replaced (changed) by blessing.
    Blessed,
    /// The scene could not be loaded, rendered or written, or its worker process crashed or
    /// ran out of time: the message says which.
    Error,
}

impl Status {
    /// Whether the image fails the run: it differs or has no reference.
    pub fn failed(self) -> bool {
        matches!(self, Status::Fail | Status::Missing)
    }

    /// How the summary table spells the status.
    pub fn word(self) -> &'static str {
        match self {
            Status::Rendered => "rendered",
            Status::Pass => "ok",
            Status::Fail => "FAILED",
            Status::Missing => "MISSING",
            Status::Blessed => "blessed",
            Status::Error => "ERROR",
        }
    }
}

/// One line of the summary: one scene in one lighting mode.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Row {
    /// The image's name: the scene's name, with `_MODE` when several modes were asked for.
    pub name: String,
    /// The scene's name ([`SceneFile::name`]).
    pub scene: String,
    /// The scene file.
    pub file: PathBuf,
    /// The scene's place in the whole suite (before partitioning): rows sort by it.
    pub index: usize,
    /// The lighting mode rendered (`vertex`, `fragment`, `flat`); `None` when the scene could
    /// not be loaded and no mode was asked for.
    pub mode: Option<String>,
    /// What happened.
    pub status: Status,
    /// Why the image could not be compared (a reference of another size) or rendered.
    pub message: Option<String>,
    /// The comparison with the reference, when there was one.
    pub comparison: Option<Comparison>,
    /// The image written, when one was.
    pub output: Option<PathBuf>,
    /// The FLIP heat map of the differences ([`heat_map`]), when the image is not identical
    /// to its reference.
    pub diff: Option<PathBuf>,
    /// The map of the per-channel differences ([`channel_map`]), when the image is not
    /// identical to its reference.
    #[serde(default)]
    pub channels: Option<PathBuf>,
    /// The reference that blessing replaced, kept beside the image so that what was accepted
    /// can be looked at.
    #[serde(default)]
    pub replaced: Option<PathBuf>,
    /// The reference checked against (or blessed), when there is a reference folder.
    pub reference: Option<PathBuf>,
    /// Seconds spent on this image (its share of loading the scene included).
    pub seconds: f64,
}

impl Row {
    /// A row for `file` in `mode`, before anything happened to it.
    fn new(file: &SceneFile, name: String, mode: Option<LightingMode>) -> Row {
        Row {
            name,
            scene: file.name.clone(),
            file: file.path.clone(),
            index: file.index,
            mode: mode.map(|m| m.name().to_owned()),
            status: Status::Rendered,
            message: None,
            comparison: None,
            output: None,
            diff: None,
            channels: None,
            replaced: None,
            reference: None,
            seconds: 0.0,
        }
    }

    /// The rows of a scene that failed as a whole (it did not load, or its worker crashed):
    /// one error row per mode asked for, or one for the scene's own mode.
    pub fn errors(job: &Job, file: &SceneFile, message: &str, seconds: f64) -> Vec<Row> {
        let modes = requested_modes(job);
        let share = seconds / modes.len() as f64;
        modes
            .iter()
            .map(|mode| {
                let mut row = Row::new(file, image_name(file, *mode, modes.len()), *mode);
                row.status = Status::Error;
                row.message = Some(message.to_owned());
                row.seconds = share;
                row
            })
            .collect()
    }

    /// What the row says beyond its status: the comparison, the problem or the error.
    pub fn detail(&self) -> String {
        match (&self.comparison, &self.message, self.status) {
            (_, Some(message), _) => message.clone(),
            (Some(c), None, _) => c.summary(),
            (None, None, Status::Missing) => "no reference".into(),
            (None, None, _) => String::new(),
        }
    }
}

/// The modes a job renders each scene in: those asked for, or the scene's own (`None`).
fn requested_modes(job: &Job) -> Vec<Option<LightingMode>> {
    if job.modes.is_empty() {
        vec![None]
    } else {
        job.modes.iter().copied().map(Some).collect()
    }
}

/// The name of `file`'s image in `mode`: the scene's name, with the mode when there are
/// several.
fn image_name(file: &SceneFile, mode: Option<LightingMode>, modes: usize) -> String {
    match mode {
        Some(m) if modes > 1 => format!("{}_{}", file.name, m.name()),
        _ => file.name.clone(),
    }
}

/// Every image `job` writes for `files` (in every mode asked for): what a results file may not
/// replace, and what may not land in the reference folder.
pub fn image_paths(job: &Job, files: &[SceneFile]) -> Vec<PathBuf> {
    let modes = requested_modes(job);
    files
        .iter()
        .flat_map(|file| {
            modes
                .iter()
                .map(|&mode| image_path(job, file, &image_name(file, mode, modes.len())))
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Notes every file each of `files` reads ([`ffvk::scene::inputs`]) as an input of this
/// process ([`ffvk::files::note_input`]): the parent before it checks its outputs, and each
/// worker before it draws, so that a worker's writes are checked against every scene's inputs,
/// not only those of the scenes it has read so far.
pub fn note_inputs(job: &Job, files: &[SceneFile]) {
    for file in files {
        for input in ffvk::scene::inputs(&file.path, &job.limits) {
            ffvk::files::note_input(&input);
        }
    }
}

/// Refuses a run that would write onto a file it reads, before anything is written: every
/// file each scene reads ([`ffvk::scene::inputs`]: the scene, its textures, glTF files,
/// buffers and images) is noted as an input ([`ffvk::files::note_input`]), then each image the
/// run writes, each reference it may bless and each of `outputs` (`-o`, `--json`, …) is
/// checked against them by file identity, after links. Each later write checks again.
/// `images`: whether the run writes its images where [`image_paths`] says (not a single
/// image at a path of its own, given among `outputs`).
pub fn refuse_writing_inputs(job: &Job, files: &[SceneFile], outputs: &[&Path], images: bool) -> Result<()> {
    note_inputs(job, files);
    let mut written: Vec<PathBuf> = outputs.iter().map(|p| p.to_path_buf()).collect();
    if images {
        written.extend(image_paths(job, files));
    }
    if let (Some(refs), true) = (&job.references, job.bless) {
        let modes = requested_modes(job);
        for file in files {
            for &mode in &modes {
                let name = image_name(file, mode, modes.len());
                written.push(reference_path(refs, job.driver_family.as_deref(), &name));
            }
        }
    }
    for path in written {
        if let Some(input) = ffvk::files::input_named(&path) {
            return Err(Error::OverwritesInput { path, input });
        }
    }
    Ok(())
}

/// Where the image named `name` of `file` goes: `--out`'s folder and the name, or beside the
/// scene file under its stem.
fn image_path(job: &Job, file: &SceneFile, name: &str) -> PathBuf {
    match &job.out_dir {
        Some(d) => d.join(format!("{name}.png")),
        None => {
            let stem = name.rsplit('/').next().unwrap_or(name);
            file.path
                .parent()
                .unwrap_or(Path::new("."))
                .join(format!("{stem}.png"))
        }
    }
}

/// The one rule for what a command writes: `outputs` (each with the option that names it) may
/// not name one file twice, replace one of `inputs` or one of the `images` the same run
/// writes, or lie inside one of `references`. Paths are compared after symbolic links, whether
/// they exist yet or not.
pub fn refuse_overlaps(
    outputs: &[(&'static str, &Path)],
    inputs: &[&Path],
    images: &[PathBuf],
    references: &[&Path],
) -> Result<()> {
    use ffvk::files::resolved;
    let resolved_outputs: Vec<PathBuf> = outputs.iter().map(|(_, p)| resolved(p)).collect();
    let inputs: Vec<PathBuf> = inputs.iter().map(|p| resolved(p)).collect();
    let images: std::collections::HashSet<PathBuf> = if outputs.is_empty() {
        Default::default()
    } else {
        images.iter().map(|p| resolved(p)).collect()
    };
    for (i, (&(first, path), at)) in outputs.iter().zip(&resolved_outputs).enumerate() {
        if let Some(j) = resolved_outputs[i + 1..].iter().position(|b| b == at) {
            return Err(Error::SameOutput {
                first,
                second: outputs[i + 1 + j].0,
                path: path.to_path_buf(),
            });
        }
        if let Some(j) = inputs.iter().position(|input| input == at) {
            return Err(Error::OverwritesInput {
                path: path.to_path_buf(),
                input: inputs[j].clone(),
            });
        }
        if images.contains(at) {
            return Err(Error::SameOutput {
                first,
                second: "the run's images",
                path: path.to_path_buf(),
            });
        }
        // The report's own files: a results file there would be replaced by the page.
        if let Some(&(report, dir)) = outputs.iter().find(|&&(flag, _)| flag == "--report") {
            if first != report && is_report_file(at, &resolved(dir)) {
                return Err(Error::SameOutput {
                    first,
                    second: "--report",
                    path: path.to_path_buf(),
                });
            }
        }
        if let Some(refs) = references.iter().find(|refs| ffvk::files::is_within(path, refs)) {
            return Err(Error::FileInReferences {
                output: path.to_path_buf(),
                references: refs.to_path_buf(),
                what: first,
            });
        }
    }
    Ok(())
}

/// Whether `file` (resolved) is one of the files or folders a report writes in `dir` (resolved).
fn is_report_file(file: &Path, dir: &Path) -> bool {
    file.strip_prefix(dir).is_ok_and(|rest| {
        rest.components()
            .next()
            .is_some_and(|first| report::OWN_NAMES.iter().any(|n| first.as_os_str() == *n))
    })
}

/// Refuses a job that would write into its references or over its own inputs: references
/// are only written by blessing, and only the references themselves. Each image the run
/// writes is checked, so a reference folder inside the output folder is caught too.
pub fn check_outputs(job: &Job, files: &[SceneFile]) -> Result<()> {
    let Some(refs) = &job.references else {
        return Ok(());
    };
    if refs.exists() && !refs.is_dir() {
        return Err(Error::Path {
            path: refs.clone(),
            problem: "is not a folder: --check expects a folder of reference images",
        });
    }
    let out_dirs: Vec<PathBuf> = match &job.out_dir {
        Some(d) => vec![d.clone()],
        None => files
            .iter()
            .map(|f| f.path.parent().unwrap_or(Path::new(".")).to_path_buf())
            .collect(),
    };
    for dir in out_dirs {
        if ffvk::files::is_within(&dir, refs) {
            return Err(Error::OutputInReferences {
                output: dir,
                references: refs.clone(),
            });
        }
    }
    // A reference folder inside the output folder: an image may still land in it.
    if let Some(image) = image_paths(job, files)
        .into_iter()
        .find(|image| ffvk::files::is_within(image, refs))
    {
        return Err(Error::FileInReferences {
            output: image,
            references: refs.clone(),
            what: "the run's images",
        });
    }
    Ok(())
}

/// What a regression run reports as it goes.
#[derive(Debug, Clone, Copy)]
pub enum Message<'a> {
    /// A scene's warning, once however many nodes repeat it, with how many times it came
    /// (for a terminal's stderr: it is not part of the results).
    Warning {
        /// The warning.
        text: &'a str,
        /// How many times the scene gave it.
        times: usize,
    },
    /// What ffvk chose for a glTF file drawn without a scene file (camera, lights), one line
    /// each.
    Chose {
        /// The glTF file.
        scene: &'a Path,
        /// The choice.
        text: &'a str,
    },
    /// A line a worker process wrote to stderr, or to stdout outside its protocol (for a
    /// terminal's stderr: it is not part of the results).
    Output {
        /// The line.
        text: &'a str,
    },
    /// An image was written.
    Wrote {
        /// The scene file.
        scene: &'a Path,
        /// The image.
        image: &'a Path,
    },
}

impl std::fmt::Display for Message<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Message::Warning { text, times } => write!(f, "{}", OpenNote::Warning { text, times: *times }),
            Message::Chose { scene, text } => write!(f, "{}: {text}", scene.display()),
            Message::Wrote { scene, image } => write!(f, "{} -> {}", scene.display(), image.display()),
            Message::Output { text } => write!(f, "{text}"),
        }
    }
}

/// [`ffvk::scene::open`], its notes as this module's [`Message`]s.
pub fn load_scene(
    path: &Path,
    size: Option<(u32, u32)>,
    limits: &Limits,
    direct: &DirectOptions,
    log: &mut dyn FnMut(Message),
) -> Result<Scene> {
    let scene = ffvk::scene::open(path, size, limits, direct, &mut |n| match n {
        OpenNote::Chose { text } => log(Message::Chose { scene: path, text }),
        // Named by its scene: in a folder run, warnings of many scenes interleave.
        OpenNote::Warning { text, times } => log(Message::Warning {
            text: &crate::named_by(path, text),
            times,
        }),
        _ => {}
    })?;
    Ok(scene)
}

/// The suite's scene files that `job` renders: every one, or those of its partition, after
/// refusing two scenes that would write one image and outputs that would land in the
/// reference folder.
pub fn job_files(job: &Job) -> Result<(Vec<SceneFile>, usize)> {
    job.tolerance.validate()?;
    let files = scene_files(&job.scenes)?;
    check_outputs(job, &files)?;
    let suite = files.len();
    let files = match job.partition {
        Some(p) => files.into_iter().filter(|f| p.contains(&f.name)).collect(),
        None => files,
    };
    Ok((files, suite))
}

/// Renders every scene of `job` (of its partition) in every mode with `renderer`, in this
/// process, checking and blessing as asked. A scene that cannot be loaded, rendered or
/// written is an error row and the run goes on; refuses, before rendering anything, a job
/// whose outputs would land in its reference folder or two scenes that would write one
/// image.
pub fn run(renderer: &mut Renderer, job: &Job, log: &mut dyn FnMut(Message)) -> Result<Vec<Row>> {
    let (files, _) = job_files(job)?;
    Ok(files
        .iter()
        .flat_map(|file| render_file(renderer, job, file, log))
        .collect())
}

/// Renders one scene of `job` in every mode asked for, checking and blessing as asked. Never
/// fails: what goes wrong is an error row (the scene's, when it does not load; the mode's,
/// when one image cannot be rendered or written).
pub fn render_file(
    renderer: &mut Renderer,
    job: &Job,
    file: &SceneFile,
    log: &mut dyn FnMut(Message),
) -> Vec<Row> {
    let started = Instant::now();
    let scene = match load_scene(&file.path, job.size, &job.limits, &job.direct, log) {
        Ok(scene) => scene,
        Err(e) => return Row::errors(job, file, &e.to_string(), started.elapsed().as_secs_f64()),
    };
    let modes = requested_modes(job);
    let load_share = started.elapsed().as_secs_f64() / modes.len() as f64;
    let mut rows = Vec::with_capacity(modes.len());
    for mode in &modes {
        let started = Instant::now();
        let name = image_name(file, *mode, modes.len());
        let mut row = Row::new(file, name, Some(mode.unwrap_or(scene.state.mode)));
        if let Err(e) = render_image(renderer, job, file, &scene, *mode, &mut row) {
            row.status = Status::Error;
            row.message = Some(e.to_string());
        }
        row.seconds = load_share + started.elapsed().as_secs_f64();
        if let Some(image) = &row.output {
            log(Message::Wrote {
                scene: &file.path,
                image,
            });
        }
        rows.push(row);
    }
    rows
}

/// Saves a run's image, map or replaced reference at `path`, checked at the moment of writing
/// against the reference folder (the check before the run cannot see a folder swapped for a
/// link while it runs): only blessing writes there, and only the references themselves.
fn save_outside_references(job: &Job, image: &image::RgbaImage, path: &Path) -> Result<()> {
    if let Some(refs) = &job.references {
        if ffvk::files::is_within(path, refs) {
            return Err(Error::FileInReferences {
                output: path.to_path_buf(),
                references: refs.clone(),
                what: "the run's images",
            });
        }
    }
    Ok(save_png(image, path)?)
}

/// Renders `scene` in `mode` into `row`'s image, then checks it against (or blesses) its
/// reference. The row keeps what happened before an error.
fn render_image(
    renderer: &mut Renderer,
    job: &Job,
    file: &SceneFile,
    scene: &Scene,
    mode: Option<LightingMode>,
    row: &mut Row,
) -> Result<()> {
    let image = ffvk::scene::render_scene_with(renderer, scene, mode, job.fragment_path)?;
    // Next to the scene file, an image is named by the file's stem.
    let output = image_path(job, file, &row.name);
    let dir = output.parent().unwrap_or(Path::new(".")).to_path_buf();
    let local = output
        .file_stem()
        .map_or_else(|| row.name.clone(), |s| s.to_string_lossy().into_owned());
    if ffvk::files::same_file(&output, &file.path) {
        return Err(Error::OverwritesInput {
            path: output,
            input: file.path.clone(),
        });
    }
    save_outside_references(job, &image, &output)?;
    row.output = Some(output.clone());
    let Some(refs) = &job.references else {
        return Ok(());
    };
    let reference = reference_path(refs, job.driver_family.as_deref(), &row.name);
    row.reference = Some(reference.clone());
    if reference.exists() && !reference.is_file() {
        // A pipe would block the worker until its timeout; a folder cannot be compared.
        return Err(Error::Path {
            path: reference,
            problem: "is not a regular file: expected a PNG reference (or no file, to bless one)",
        });
    }
    if !reference.exists() {
        row.status = if job.bless {
            Status::Blessed
        } else {
            Status::Missing
        };
    } else {
        let expected = load_image(&reference)?;
        match compare(&expected, &image, &job.tolerance) {
            Err(mismatch) if !job.bless => {
                row.status = Status::Fail;
                row.message = Some(format!(
                    "the reference {} is {}x{}, the image {} is {}x{}",
                    reference.display(),
                    mismatch.expected.0,
                    mismatch.expected.1,
                    output.display(),
                    mismatch.actual.0,
                    mismatch.actual.1
                ));
            }
            Err(_) => row.status = Status::Blessed,
            Ok(mut c) => {
                row.status = match (c.passes(&job.tolerance), job.bless && !c.identical()) {
                    (_, true) => Status::Blessed,
                    (true, false) => Status::Pass,
                    (false, false) => Status::Fail,
                };
                if !c.identical() {
                    let (map, flip) = heat_map_with_flip(&expected, &image, &job.tolerance)?;
                    // Where the share over the threshold decided, the map's FLIP values
                    // still give the figure the summary and the report show.
                    c.flip_mean.get_or_insert(flip);
                    let diff = dir.join(format!("{local}.diff.png"));
                    save_outside_references(job, &map, &diff)?;
                    row.diff = Some(diff);
                    let channels = dir.join(format!("{local}.channels.png"));
                    save_outside_references(job, &channel_map(&expected, &image)?, &channels)?;
                    row.channels = Some(channels);
                }
                row.comparison = Some(c);
            }
        }
        if row.status == Status::Blessed {
            let replaced = dir.join(format!("{local}.replaced.png"));
            save_outside_references(job, &expected, &replaced)?;
            row.replaced = Some(replaced);
        }
    }
    if row.status == Status::Blessed {
        save_png(&image, &reference)?;
    }
    Ok(())
}

/// The summary table: scene, status, max difference, share over the threshold, FLIP mean;
/// then the counts ([`results::Counts`]).
pub fn table(rows: &[Row]) -> String {
    let mut t = Table::new([
        ("scene", Align::Left),
        ("status", Align::Left),
        ("max diff RGBA", Align::Right),
        ("over %", Align::Right),
        ("FLIP", Align::Right),
    ]);
    for r in rows {
        let (diff, over, flip) = match &r.comparison {
            Some(c) => (
                format!("{:?}", c.max_diff),
                format!("{:.4}", c.share_over * 100.0),
                c.flip_mean.map_or("-".into(), |f| format!("{f:.5}")),
            ),
            None => ("-".into(), "-".into(), "-".into()),
        };
        t.row([r.name.clone(), r.status.word().into(), diff, over, flip]);
    }
    format!("{}{}", t.text(), results::Counts::of(rows))
}

/// What a run prints at its end: the summary table when images were checked (else the
/// counts), then a line for each failure and error with its figures or message and its
/// paths, and how to bless when something failed.
pub fn summary(rows: &[Row], checked: bool) -> String {
    let mut text = if checked {
        table(rows)
    } else {
        results::Counts::of(rows).to_string()
    };
    for r in rows
        .iter()
        .filter(|r| r.status.failed() || r.status == Status::Error)
    {
        let paths: Vec<String> = [("actual", &r.output), ("diff", &r.diff)]
            .into_iter()
            .filter_map(|(what, p)| p.as_ref().map(|p| format!("{what} {}", p.display())))
            .collect();
        text.push_str(&format!("\n{}: {}", r.name, r.detail()));
        if !paths.is_empty() {
            text.push_str(&format!("; {}", paths.join(", ")));
        }
    }
    if rows.iter().any(|r| r.status.failed()) {
        text.push_str(&format!(
            "\nto accept these images as the new references: rerun with --bless (or {BLESS_VAR}=1)"
        ));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    fn comparison(max_diff: [u8; 4], share_over: f64, flip_mean: f32) -> Comparison {
        let mut c = Comparison::default();
        c.width = 128;
        c.height = 128;
        c.max_diff = max_diff;
        c.over = (share_over * 128.0 * 128.0) as usize;
        c.share_over = share_over;
        c.flip_mean = Some(flip_mean);
        c.threshold = 1;
        c
    }

    #[test]
    fn the_summary_table() {
        let row = |name: &str, status, comparison| Row {
            name: name.into(),
            scene: name.into(),
            file: PathBuf::from(format!("{name}.toml")),
            index: 0,
            mode: Some("vertex".into()),
            status,
            comparison,
            output: Some(PathBuf::from(format!("out/{name}.png"))),
            diff: None,
            channels: None,
            replaced: None,
            message: None,
            reference: None,
            seconds: 0.0,
        };
        let same = comparison([0; 4], 0.0, 0.0);
        let different = comparison([255, 12, 3, 0], 0.0123, 0.04567);
        let rows = [
            row("a", Status::Rendered, None),
            row("spot_light_vertex", Status::Pass, Some(same)),
            row("b", Status::Fail, Some(different)),
            row("missing_one", Status::Missing, None),
            row("new", Status::Blessed, None),
            row("broken", Status::Error, None),
        ];
        let expected = "\
scene              status      max diff RGBA  over %     FLIP\n\
a                  rendered                -       -        -\n\
spot_light_vertex  ok           [0, 0, 0, 0]  0.0000  0.00000\n\
b                  FAILED    [255, 12, 3, 0]  1.2300  0.04567\n\
missing_one        MISSING                 -       -        -\n\
new                blessed                 -       -        -\n\
broken             ERROR                   -       -        -\n\
6 image(s): 1 passed, 1 failed, 1 missing, 1 blessed, 1 rendered, 1 error(s)";
        assert_eq!(table(&rows), expected);
    }
}
