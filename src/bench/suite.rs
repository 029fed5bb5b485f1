//! `ffvk bench --sweep jobs`: how regression runs scale with worker processes.
//!
//! Generates a suite of small scenes (200 at 128² by default: spheres, teapots and planes in
//! all three lighting modes, one to three lights, point, directional and spot, the material
//! presets), blesses their references once (the warm-up run, which also fills the file cache),
//! then times `ffvk render --check` of the whole suite with each number of workers, the runs
//! of the different numbers interleaved so that drift on the machine spreads over all of them.
//! A run is timed end to end as a user sees it: workers started, pipelines compiled, scenes
//! loaded, rendered, written, compared. Every measured run must pass (the images are
//! identical whatever the number of workers), else the bench fails.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Duration;

use serde::Serialize;

use super::{cpu_model, mesa_version};
use crate::regress::pool::{run_suite, SuiteOptions, WorkerCommand};
use crate::regress::{self, Job};
use crate::{Error, Result};
use ffvk::gl::presets::PRESET_NAMES;
use ffvk::images::compare::Tolerance;
use ffvk::vk::Validation;
use ffvk::RendererOptions;

/// What the jobs sweep does.
#[derive(Debug, Clone)]
pub struct SuiteConfig {
    /// Scenes in the generated suite.
    pub scenes: usize,
    /// Their width and height.
    pub size: u32,
    /// The numbers of workers to time.
    pub jobs: Vec<usize>,
    /// Timed runs per number of workers.
    pub runs: usize,
    /// LP_NUM_THREADS per worker for every run; `None`: the default for each number of
    /// workers ([`crate::regress::pool::default_lp_threads`]).
    pub lp_num_threads: Option<String>,
}

impl SuiteConfig {
    /// 200 scenes at 128², 1 and 2 workers and every power of two up to the CPUs (and the
    /// CPUs themselves), 5 runs each.
    pub fn standard() -> SuiteConfig {
        let cpus = crate::regress::pool::default_jobs();
        let mut jobs = vec![1];
        let mut j = 2;
        while j < cpus {
            jobs.push(j);
            j *= 2;
        }
        if cpus > 1 {
            jobs.push(cpus);
        }
        SuiteConfig {
            scenes: 200,
            size: 128,
            jobs,
            runs: 5,
            lp_num_threads: None,
        }
    }
}

/// One number of workers, timed.
#[derive(Debug, Clone, Serialize)]
pub struct JobsPoint {
    /// Worker processes.
    pub jobs: usize,
    /// LP_NUM_THREADS in each.
    pub lp_num_threads: String,
    /// Images per run (scenes × modes).
    pub images: usize,
    /// Wall-clock seconds of each run, in the order run.
    pub seconds: Vec<f64>,
    /// Their median.
    pub median_seconds: f64,
    /// Images per second at the median.
    pub images_per_second: f64,
    /// Images per second relative to the first number of workers (1).
    pub speedup: f64,
}

/// The sweep's results with the machine they came from.
#[derive(Debug, Clone, Serialize)]
pub struct SuiteReport {
    /// The device, driver and Vulkan version, as the workers reported them.
    pub device: Option<regress::results::DeviceSummary>,
    /// The Mesa version in the driver's text, when it is Mesa.
    pub mesa_version: Option<String>,
    /// The CPU model.
    pub cpu: String,
    /// The CPUs this process may use.
    pub cpus: usize,
    /// Whether ffvk was built with optimizations.
    pub optimized_build: bool,
    /// Scenes in the suite.
    pub scenes: usize,
    /// Their size.
    pub size: u32,
    /// Each number of workers.
    pub points: Vec<JobsPoint>,
}

/// Writes `count` scene files of `size`² into `dir` (`scene_000.toml`, …), the same ones
/// every time: shapes, modes, lights and materials vary with the index.
pub fn generate_scenes(dir: &Path, count: usize, size: u32) -> Result<Vec<PathBuf>> {
    let mut written = Vec::with_capacity(count);
    for i in 0..count {
        let path = dir.join(format!("scene_{i:03}.toml"));
        let text = scene_text(i, size);
        crate::write_file(&path, text.as_bytes())?;
        written.push(path);
    }
    Ok(written)
}

/// Scene `i` of the generated suite.
fn scene_text(i: usize, size: u32) -> String {
    // A small generator (xorshift64*) seeded by the index: the same scene for the same index.
    let mut state = (i as u64 + 1).wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = move || {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    };
    let mode = ["vertex", "fragment", "flat"][i % 3];
    // The shapes at their default tessellation (the plane in 16 × 16 cells, so that
    // per-vertex lighting has vertices to work with).
    let (shape, level, distance) = [("sphere", 32, 3.0), ("teapot", 12, 3.4), ("plane", 16, 2.6)][i / 3 % 3];
    let preset = PRESET_NAMES[i % PRESET_NAMES.len()];
    let angle = next() * std::f64::consts::TAU;
    let mut t = String::new();
    let _ = writeln!(t, "# Generated by ffvk bench --sweep jobs: scene {i}.");
    let _ = writeln!(
        t,
        "[image]\nsize = [{size}, {size}]\nclear_color = [{:.2}, {:.2}, {:.2}]\nlighting_mode = \"{mode}\"",
        next() * 0.2,
        next() * 0.2,
        next() * 0.2
    );
    let _ = writeln!(
        t,
        "[camera]\neye = [{:.3}, {:.3}, {:.3}]\ntarget = [0.0, 0.0, 0.0]\nfovy = 40",
        distance * angle.sin(),
        0.5 + next(),
        distance * angle.cos()
    );
    let _ = writeln!(
        t,
        "[light_model]\nambient = [0.1, 0.1, 0.1]\nlocal_viewer = {}",
        i.is_multiple_of(2)
    );
    for _ in 0..1 + i % 3 {
        let kind = (next() * 3.0) as u32;
        let w = if kind == 0 { 0.0 } else { 1.0 };
        let _ = writeln!(
            t,
            "[[lights]]\nposition = [{:.3}, {:.3}, {:.3}, {w:.1}]\ndiffuse = [{:.2}, {:.2}, {:.2}]\nspecular = [1.0, 1.0, 1.0]",
            next() * 4.0 - 2.0,
            1.0 + next() * 2.0,
            next() * 4.0 - 2.0,
            0.4 + next() * 0.8,
            0.4 + next() * 0.8,
            0.4 + next() * 0.8
        );
        if kind == 2 {
            let _ = writeln!(
                t,
                "spot_direction = [0.0, -1.0, 0.0]\nspot_cutoff = {:.1}\nspot_exponent = {:.1}",
                30.0 + next() * 50.0,
                next() * 20.0
            );
        }
    }
    let _ = writeln!(t, "[material]\npreset = \"{preset}\"");
    let _ = writeln!(t, "[[meshes]]\nbuiltin = \"{shape}\"\nlevel = {level}");
    t
}

/// Runs the jobs sweep in `dir` (scenes, references and images under it) with `program` as
/// the workers' program, and writes `jobs.json` and `jobs.md` there.
pub fn run_jobs_sweep(
    config: &SuiteConfig,
    options: &RendererOptions,
    program: &Path,
    dir: &Path,
    progress: &mut dyn FnMut(&str),
) -> Result<SuiteReport> {
    if config.jobs.is_empty() || config.runs == 0 || config.scenes == 0 {
        return Err(Error::Bench(
            "the jobs sweep needs at least one scene, one number of workers and one run".into(),
        ));
    }
    let scenes = dir.join("scenes");
    let refs = dir.join("references");
    let images = dir.join("images");
    generate_scenes(&scenes, config.scenes, config.size)?;
    let job = |bless: bool| Job {
        scenes: vec![scenes.clone()],
        out_dir: Some(images.clone()),
        references: Some(refs.clone()),
        bless,
        tolerance: Tolerance::EXACT,
        ..Job::default()
    };
    // The workers parse the same job from these arguments.
    let worker = |bless: bool| {
        let mut args: Vec<std::ffi::OsString> = Vec::new();
        if let Some(d) = &options.device {
            args.extend(["--device".into(), d.into()]);
        }
        if options.validation != Validation::Off {
            args.push("--validate".into());
        }
        args.extend([
            "--render-worker".into(),
            "render".into(),
            scenes.clone().into(),
            "--out".into(),
            images.clone().into(),
            "--check".into(),
            refs.clone().into(),
            "--threshold".into(),
            "0".into(),
            "--max-share".into(),
            "0".into(),
            "--max-flip".into(),
            "0".into(),
        ]);
        if bless {
            args.push("--bless".into());
        }
        WorkerCommand {
            program: program.to_path_buf(),
            args,
        }
    };
    let timeout = Duration::from_secs(600);
    let suite_options = |jobs: usize| SuiteOptions {
        jobs: Some(jobs),
        lp_num_threads: config.lp_num_threads.clone(),
        timeout,
    };
    let max_jobs = config.jobs.iter().copied().max().unwrap_or(1);
    progress("warm-up: blessing the references");
    let warm = run_suite(&job(true), &worker(true), &suite_options(max_jobs), &mut |_| {})?;
    let device = warm.runs[0].info.device.clone();
    let mut points: Vec<JobsPoint> = config
        .jobs
        .iter()
        .map(|&jobs| JobsPoint {
            jobs,
            lp_num_threads: String::new(),
            images: 0,
            seconds: Vec::new(),
            median_seconds: 0.0,
            images_per_second: 0.0,
            speedup: 0.0,
        })
        .collect();
    for run in 0..config.runs {
        for point in &mut points {
            progress(&format!(
                "run {}/{}: {} worker(s)",
                run + 1,
                config.runs,
                point.jobs
            ));
            let results = run_suite(
                &job(false),
                &worker(false),
                &suite_options(point.jobs),
                &mut |_| {},
            )?;
            let counts = results.counts();
            if counts.passed != counts.images {
                return Err(Error::Bench(format!(
                    "with {} worker(s), not every image matched the references blessed in the warm-up \
                     ({counts}): images must not depend on the number of workers",
                    point.jobs
                )));
            }
            let info = &results.runs[0].info;
            point.lp_num_threads = info.lp_num_threads.clone().unwrap_or_default();
            point.images = counts.images;
            point.seconds.push(info.seconds);
        }
    }
    for point in &mut points {
        point.median_seconds = super::Spread::of(&point.seconds).map_or(f64::NAN, |s| s.median);
        point.images_per_second = point.images as f64 / point.median_seconds;
    }
    let base = points[0].images_per_second;
    for point in &mut points {
        point.speedup = point.images_per_second / base;
    }
    let report = SuiteReport {
        mesa_version: device.as_ref().and_then(|d| mesa_version(&d.driver_info)),
        device,
        cpu: cpu_model(),
        cpus: crate::regress::pool::default_jobs(),
        optimized_build: !cfg!(debug_assertions),
        scenes: config.scenes,
        size: config.size,
        points,
    };
    let json = serde_json::to_string_pretty(&report).map_err(|source| Error::Json {
        path: dir.join("jobs.json"),
        source,
    })?;
    for (name, text) in [("jobs.json", json), ("jobs.md", jobs_markdown(&report))] {
        let path = dir.join(name);
        crate::write_file(&path, text.as_bytes())?;
    }
    Ok(report)
}

/// The sweep as Markdown: the machine, then one row per number of workers.
pub fn jobs_markdown(report: &SuiteReport) -> String {
    let mut t = super::super::table::Table::new([
        ("workers", super::super::table::Align::Right),
        ("LP_NUM_THREADS", super::super::table::Align::Right),
        ("images", super::super::table::Align::Right),
        ("median s", super::super::table::Align::Right),
        ("min–max s", super::super::table::Align::Right),
        ("images/s", super::super::table::Align::Right),
        ("× 1 worker", super::super::table::Align::Right),
    ]);
    for p in &report.points {
        let (min, max) = super::Spread::of(&p.seconds).map_or((f64::NAN, f64::NAN), |s| (s.min, s.max));
        t.row([
            p.jobs.to_string(),
            p.lp_num_threads.clone(),
            p.images.to_string(),
            format!("{:.2}", p.median_seconds),
            format!("{min:.2}–{max:.2}"),
            format!("{:.1}", p.images_per_second),
            format!("{:.2}", p.speedup),
        ]);
    }
    let device = report.device.as_ref().map_or("no worker started".into(), |d| {
        format!(
            "{} ({}, {}), Vulkan {}",
            d.device, d.driver, d.driver_info, d.api_version
        )
    });
    format!(
        "Regression suite: {} generated scenes at {}², `ffvk render --check` end to end, median of {} runs\n\
         Device: {device}; Mesa {}; CPU: {} ({} CPUs); {} build\n\n{}",
        report.scenes,
        report.size,
        report.points.first().map_or(0, |p| p.seconds.len()),
        report.mesa_version.as_deref().unwrap_or("-"),
        report.cpu,
        report.cpus,
        if report.optimized_build {
            "release"
        } else {
            "debug"
        },
        t.markdown()
    )
}
