//! `ffvk bench`: what the lighting equation costs on this machine's Vulkan driver.
//!
//! Every point of a sweep draws one lit UV sphere filling most of a square image (no culling,
//! depth test on: GL's defaults) and times it: warm-up frames first (pipeline creation, and
//! lavapipe compiles fragment code lazily at the first draw), then measured frames, each
//! with two timestamps around the rendering pass and a pipeline-statistics query
//! ([`Renderer::measure`]). A point reports the median and the spread of its frames.
//!
//! The sweeps vary one thing around a base point: mesh density (lighting mode × vertices),
//! image size (mode × pixels), light count and light kind (mode × specialized or uber
//! pipelines). The same scenes go through fixed-function OpenGL too, as the anchor: the GL
//! reference renderer (EGL, loaded at run time) on the GL device whose name matches the
//! Vulkan device's, so the same rasterizer in the same process (llvmpipe for lavapipe).
//! Without a GL driver, or without a matching device, the anchor is left out with a note.
//!
//! Outputs: `results.csv`, `results.json`, `summary.md` and PNG plots, in one directory.
//! Every result carries LP_NUM_THREADS, the device, the driver and the Mesa version.
//!
//! This module holds the arguments, the entry point and the loop over the points; `sweep`
//! says which points a sweep has, `measure` times one point and summarizes the results,
//! `report` writes the CSV, JSON and Markdown, and `plots` the PNG plots.

#![warn(missing_docs)]

mod draw_cost;
pub mod draws;
pub mod floor;
mod format;
mod measure;
mod plots;
mod points;
mod report;
mod stage_textures;
mod stages;
pub mod states;
mod suite;
mod sweep;
mod tables;
pub mod zink;

use std::collections::hash_map::Entry;
use std::collections::HashMap;
use std::path::PathBuf;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use serde::Serialize;

use crate::{Error, Result};
use ffvk::draw::pipeline::Specialize;
use ffvk::mesh::MeshData;
use ffvk::renderer::{Mesh, Renderer, RendererOptions};

pub use draw_cost::{measure_draw_cost, DrawCost, DRAWS};
pub use measure::{crossover, fit_line, summarize, Costs, GlRatio, PointStats, Spread, Summary};
pub use measure::{ffvk_frame, gl_scene};
pub use points::{point_state, points};
pub use report::{csv, markdown, write_outputs, CSV_COLUMNS};
pub use stage_textures::{StageTextures, UploadedTextures};
pub use suite::{generate_scenes, jobs_markdown, run_jobs_sweep, JobsPoint, SuiteConfig, SuiteReport};
pub use sweep::{BenchMode, Engine, Group, LightKind, Point, Stage, SweepConfig, Variant, MAX_DRAWS};

use measure::{measure_ffvk, GlAnchor};

/// LP_NUM_THREADS when neither `--lp-threads` nor the environment sets it: the CPUs this
/// process may use (what lavapipe would pick itself), pinned so that it is recorded.
pub fn default_lp_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// The most warm-up or measured frames per point `--warmup` and `--frames` take.
const MAX_FRAMES: i64 = 100_000;

/// `ffvk bench`'s options.
#[derive(Debug, Clone, clap::Args)]
pub struct BenchArgs {
    /// Output directory: results.csv, results.json, summary.md and the plots (PNG).
    #[arg(short, long, default_value = "out/bench")]
    pub out: PathBuf,
    /// Which sweep: `standard` (about 4 minutes on 2 cores), `quick` (about a minute),
    /// `full` (more of everything, about 25 minutes), `gpu` (16 draws per frame, frames
    /// timed in batches, images to 4096², up to 16 lights: for GPUs, where a standard frame
    /// is too short to show the lighting) or `auto`: `gpu` on a discrete, integrated or
    /// virtual GPU, else `standard`. `paths` (about 3 minutes on 2 cores): the fragment
    /// mode forward and deferred over mesh density, image size and lights, with what
    /// `FragmentPath::Auto` picks at each point. `draws` (about 2 minutes on 2 cores): the
    /// many-draws frames alone, with their anchors. `stages` (about 2 minutes on 2 cores):
    /// what fog, the alpha test, the color sum and clip planes cost in each lighting mode,
    /// specialized and uber, and GL's cost of each. `jobs` is another kind of sweep:
    /// regression-suite throughput (`ffvk render --check` of generated scenes) with 1, 2, …
    /// worker processes.
    #[arg(long, default_value = "auto", value_parser = ["auto", "quick", "standard", "full", "gpu", "paths", "draws", "stages", "jobs"])]
    pub sweep: String,
    /// `--sweep jobs`: scenes in the generated suite (128² each).
    #[arg(long, default_value_t = 200, value_parser = clap::value_parser!(u32).range(1..=100_000),
          allow_negative_numbers = true)]
    pub scenes: u32,
    /// `--sweep jobs`: the numbers of workers to time, comma-separated (default: 1, 2, the
    /// powers of two below the CPU count and the CPU count).
    #[arg(long, value_delimiter = ',', value_parser = clap::value_parser!(u32).range(1..=1024),
          allow_negative_numbers = true)]
    pub jobs: Vec<u32>,
    /// Same as `--sweep quick`.
    #[arg(long, conflicts_with_all = ["full", "sweep"])]
    pub quick: bool,
    /// Same as `--sweep full`.
    #[arg(long, conflicts_with = "sweep")]
    pub full: bool,
    /// Draws of the mesh per frame (default: the sweep's; 1 but in the gpu sweep).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_DRAWS)),
          allow_negative_numbers = true)]
    pub draws: Option<u32>,
    /// Warm-up frames per point (default: the sweep's).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_FRAMES),
          allow_negative_numbers = true)]
    pub warmup: Option<u32>,
    /// Measured frames per point (default: the sweep's); in the jobs sweep, runs per number
    /// of workers.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_FRAMES),
          allow_negative_numbers = true)]
    pub frames: Option<u32>,
    /// Rasterizer threads for lavapipe and llvmpipe's GL (sets LP_NUM_THREADS before the
    /// Vulkan instance exists). Default: LP_NUM_THREADS if set, else the number of CPUs.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024), allow_negative_numbers = true)]
    pub lp_threads: Option<u32>,
    /// Leave out the OpenGL anchor.
    #[arg(long)]
    pub no_gl: bool,
    /// Leave out the zink anchor (Mesa's GL on the same Vulkan driver, in a process of its
    /// own).
    #[arg(long)]
    pub no_zink: bool,
    /// Draw the zink anchor's points for a parent `ffvk bench` (a request on stdin, the
    /// answer on stdout): ffvk runs itself this way.
    #[arg(long, hide = true)]
    pub anchor_worker: bool,
    /// No progress bar.
    #[arg(long)]
    pub no_progress: bool,
    /// Keep freed heap memory in the process instead of returning it to the kernel after
    /// every frame (glibc's M_TRIM_THRESHOLD and M_TOP_PAD), for ffvk and GL alike: shows the
    /// frame time without the page faults of re-growing the heap (BENCHMARKS.md).
    #[arg(long)]
    pub malloc_no_trim: bool,
}

/// `ffvk bench`: pins LP_NUM_THREADS, runs the sweep with a progress bar, writes the outputs
/// and prints the summary.
///
/// Sets the process environment, so call it before any other thread exists (ffvk's CLI calls
/// it first thing); library users and tests call [`run_sweep`] and [`write_outputs`].
/// `program` is ffvk's own executable: the jobs sweep starts its workers from it.
pub fn run(args: &BenchArgs, options: &RendererOptions, program: &std::path::Path) -> Result<()> {
    if args.anchor_worker {
        // LP_NUM_THREADS and the GL driver's environment come from the parent.
        return zink::answer_request();
    }
    claim_out_dir(&args.out)?;
    if args.sweep == "jobs" {
        // Before LP_NUM_THREADS is pinned for this process: each number of workers gets its
        // own default unless --lp-threads fixes one for all.
        return run_jobs(args, options, program);
    }
    let threads = match (args.lp_threads, std::env::var("LP_NUM_THREADS")) {
        (Some(n), _) => n.to_string(),
        (None, Ok(v)) if !v.trim().is_empty() => v,
        _ => default_lp_threads().to_string(),
    };
    // Before the first Vulkan instance (lavapipe) or GL context (llvmpipe) reads it, while
    // this process has one thread.
    std::env::set_var("LP_NUM_THREADS", &threads);
    if args.malloc_no_trim && !keep_freed_memory() {
        return Err(Error::Bench(
            "--malloc-no-trim needs glibc's mallopt, which refused the settings".into(),
        ));
    }

    let name = match (args.quick, args.full) {
        (true, _) => "quick",
        (_, true) => "full",
        _ => args.sweep.as_str(),
    };
    let mut config = match name {
        "quick" => SweepConfig::quick(),
        "full" => SweepConfig::full(),
        "standard" => SweepConfig::standard(),
        "gpu" => SweepConfig::gpu(),
        "draws" => SweepConfig::draws_only(),
        "stages" => SweepConfig::stages_only(),
        "paths" => {
            let probe = Renderer::new(options)?;
            SweepConfig::paths(is_gpu(&probe.device_info().device_type))
        }
        _ => {
            // The device decides: a GPU gets the sweep that keeps it busy.
            let probe = Renderer::new(options)?;
            if is_gpu(&probe.device_info().device_type) {
                SweepConfig::gpu()
            } else {
                SweepConfig::standard()
            }
        }
    };
    if let Some(d) = args.draws {
        config.draws = d;
    }
    if let Some(w) = args.warmup {
        config.warmup = w;
    }
    if let Some(f) = args.frames {
        config.frames = f;
    }
    config.gl &= !args.no_gl;
    // Not where the sweep has no GL points and no draws sweep (the paths sweep).
    config.zink =
        (!args.no_zink && (config.gl || !config.draw_counts.is_empty())).then(|| program.to_path_buf());
    config.malloc_no_trim = args.malloc_no_trim;

    let progress = if args.no_progress {
        ProgressBar::hidden()
    } else {
        ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr())
    };
    let started = Instant::now();
    let report = run_sweep(&config, options, &progress)?;
    progress.finish_and_clear();
    let written = write_outputs(&report, &args.out)?;
    crate::out!("{}", markdown(&report))?;
    crate::outln!()?;
    crate::outln!(
        "{} points in {:.0} s; wrote {}",
        report.results.len(),
        started.elapsed().as_secs_f64(),
        written
            .iter()
            .map(|p| p.display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    )?;
    Ok(())
}

/// Makes `dir`, the folder a sweep's outputs go to, before anything is measured: a file there,
/// or a folder that cannot be made, is refused at once rather than after minutes of sweep.
fn claim_out_dir(dir: &std::path::Path) -> Result<()> {
    if dir.exists() && !dir.is_dir() {
        return Err(Error::Path {
            path: dir.to_path_buf(),
            problem: "is a file, but bench writes its results (CSV, JSON, Markdown, plots) into a \
                      folder: expected a folder for -o",
        });
    }
    std::fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: dir.to_path_buf(),
        source,
    })
}

/// `ffvk bench --sweep jobs`: writes the suite under `--out`, prints and writes the table.
fn run_jobs(args: &BenchArgs, options: &RendererOptions, program: &std::path::Path) -> Result<()> {
    let mut config = SuiteConfig::standard();
    config.scenes = args.scenes as usize;
    if !args.jobs.is_empty() {
        config.jobs = args.jobs.iter().map(|&j| j as usize).collect();
    }
    if let Some(f) = args.frames {
        config.runs = f as usize;
    }
    config.lp_num_threads = args.lp_threads.map(|t| t.to_string());
    let dir = args.out.join("jobs");
    let started = Instant::now();
    let report = run_jobs_sweep(&config, options, program, &dir, &mut |step| {
        if !args.no_progress {
            crate::errln!("{step}");
        }
    })?;
    crate::outln!("{}", jobs_markdown(&report))?;
    crate::outln!(
        "{:.0} s; wrote {} and {}",
        started.elapsed().as_secs_f64(),
        dir.join("jobs.md").display(),
        dir.join("jobs.json").display()
    )?;
    Ok(())
}

/// Whether a `VkPhysicalDeviceType` (as [`ffvk::vk::DeviceInfo::device_type`] spells it)
/// is a GPU: the `auto` sweep is then the `gpu` sweep.
pub fn is_gpu(device_type: &str) -> bool {
    matches!(device_type, "DISCRETE_GPU" | "INTEGRATED_GPU" | "VIRTUAL_GPU")
}

// ---------------------------------------------------------------------------------------------
// What a run records.

/// The machine and driver, recorded with every result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchEnv {
    /// LP_NUM_THREADS as the drivers read it ("unset" when it was not set).
    pub lp_num_threads: String,
    /// The Vulkan device's name.
    pub device: String,
    /// `VkPhysicalDeviceType` as ffvk's [`DeviceInfo`](ffvk::DeviceInfo) spells it (`CPU`).
    pub device_type: String,
    /// The Vulkan driver's name ("llvmpipe").
    pub driver: String,
    /// The Vulkan driver's version text.
    pub driver_info: String,
    /// The Mesa version in `driver_info`; empty for drivers that are not Mesa's.
    pub mesa_version: String,
    /// The device's Vulkan version.
    pub vulkan_api: String,
    /// GL_RENDERER of the GL anchor, when it ran.
    pub gl_renderer: Option<String>,
    /// GL_VERSION of the GL anchor, when it ran.
    pub gl_version: Option<String>,
    /// GL_RENDERER of the zink anchor, when it ran.
    pub zink_renderer: Option<String>,
    /// GL_VERSION of the zink anchor, when it ran.
    pub zink_version: Option<String>,
    /// The CPU's model name (/proc/cpuinfo).
    pub cpu: String,
    /// The CPUs this process may use.
    pub cpus: usize,
    /// ffvk's crate version.
    pub ffvk_version: String,
    /// Whether ffvk was built with optimizations (benchmarks want `--release`).
    pub optimized_build: bool,
    /// Whether the validation layer was on.
    pub validation: bool,
    /// /proc/loadavg's 1-minute load before the sweep: other work on the machine.
    pub load_before: Option<f64>,
    /// The same load after the sweep.
    pub load_after: Option<f64>,
}

/// One row of the results: the point, its stats and the environment.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchResult {
    #[serde(flatten)]
    /// What was drawn.
    pub point: Point,
    #[serde(flatten)]
    /// What it measured.
    pub stats: PointStats,
    /// LP_NUM_THREADS, as in [`BenchEnv`].
    pub lp_num_threads: String,
    /// The device, as in [`BenchEnv`].
    pub device: String,
    /// The driver's version text, as in [`BenchEnv`].
    pub driver_info: String,
    /// The Mesa version, as in [`BenchEnv`].
    pub mesa_version: String,
}

/// A whole run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchReport {
    /// The machine and the drivers.
    pub env: BenchEnv,
    /// The sweep that ran.
    pub sweep: SweepConfig,
    /// One result per point, in the order of [`points`].
    pub results: Vec<BenchResult>,
    /// What the results show.
    pub summary: Summary,
    /// The host cost of recording draws; `None` when it was not measured.
    pub draw_cost: Option<DrawCost>,
    /// The draws sweep: frames of many draws, each with its own material.
    pub draws: Vec<draws::DrawsResult>,
    /// The floor: the draws sweep's frames drawn by a plain Vulkan program, without ffvk.
    pub floor: Vec<floor::FloorResult>,
    /// Frames of several lighting states on both fragment paths (with the paths sweep).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub states: Vec<states::StatesResult>,
    /// What was left out and why (the GL anchor without a GL driver or a matching device, GL
    /// points over GL_MAX_LIGHTS).
    pub notes: Vec<String>,
}

/// Tells glibc's allocator to keep freed memory: no trimming of the heaps (lavapipe draws on
/// its queue thread, whose arena glibc trims with madvise after every frame, so the next
/// frame faults its pages in again), and a large top pad. Returns whether glibc accepted.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
pub(crate) fn keep_freed_memory() -> bool {
    use std::os::raw::c_int;
    extern "C" {
        fn mallopt(param: c_int, value: c_int) -> c_int;
    }
    const M_TRIM_THRESHOLD: c_int = -1;
    const M_TOP_PAD: c_int = -2;
    // SAFETY: mallopt only sets glibc allocator parameters (under the allocator's own lock);
    // both values are in range for their parameters.
    unsafe { mallopt(M_TRIM_THRESHOLD, c_int::MAX) == 1 && mallopt(M_TOP_PAD, 256 << 20) == 1 }
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
pub(crate) fn keep_freed_memory() -> bool {
    false
}

// ---------------------------------------------------------------------------------------------
// Running.

impl BenchEnv {
    /// Whether LP_NUM_THREADS means anything here: the Vulkan device is lavapipe or the GL
    /// anchor is llvmpipe (the two Mesa drivers that read it).
    pub fn uses_lp_threads(&self) -> bool {
        let llvmpipe = |s: &str| s.contains("llvmpipe");
        llvmpipe(&self.driver) || llvmpipe(&self.device) || self.gl_renderer.as_deref().is_some_and(llvmpipe)
    }
}

/// The first number after "Mesa " in a driver or GL version string ("Mesa 22.3.6 (LLVM …)").
pub fn mesa_version(text: &str) -> Option<String> {
    let at = text.find("Mesa ")? + "Mesa ".len();
    let version: String = text[at..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.')
        .collect();
    (!version.is_empty()).then_some(version)
}

pub(crate) fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into())
}

fn load_average() -> Option<f64> {
    std::fs::read_to_string("/proc/loadavg")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

/// Meshes of the current density: the host copy (for GL) and one upload per renderer.
struct MeshCache {
    stacks: u32,
    data: Option<MeshData>,
    uploads: HashMap<(Variant, sweep::Primitive), Mesh>,
}

/// Runs every point of `config`, drawing `progress` as it goes. `options` chooses the device
/// and validation; the specialization policy of each point is its variant's.
pub fn run_sweep(
    config: &SweepConfig,
    options: &RendererOptions,
    progress: &ProgressBar,
) -> Result<BenchReport> {
    config.validate()?;
    let load_before = load_average();
    let lp_num_threads = std::env::var("LP_NUM_THREADS").unwrap_or_else(|_| "unset".into());
    let mut notes = Vec::new();

    let mut renderers: HashMap<Variant, Renderer> = HashMap::new();
    for (variant, specialize) in [
        (Variant::Specialized, Specialize::Always),
        (Variant::Uber, Specialize::Never),
        (Variant::Deferred, Specialize::Always),
        (Variant::DeferredUber, Specialize::Never),
    ] {
        let mut variant_options = options.clone();
        variant_options.specialize = specialize;
        let r = Renderer::new(&variant_options)?;
        renderers.insert(variant, r);
    }
    let info = renderers[&Variant::Specialized].device_info().clone();

    let gl = GlAnchor::open(config.gl, &info.name, &mut notes);
    let env = BenchEnv {
        lp_num_threads: lp_num_threads.clone(),
        device: info.name.clone(),
        device_type: info.device_type.clone(),
        driver: info.driver_name.clone(),
        driver_info: info.driver_info.clone(),
        mesa_version: mesa_version(&info.driver_info).unwrap_or_default(),
        vulkan_api: info.api_version.clone(),
        gl_renderer: gl.as_ref().map(|g| g.renderer.clone()),
        gl_version: gl.as_ref().map(|g| g.version.clone()),
        zink_renderer: None,
        zink_version: None,
        cpu: cpu_model(),
        cpus: default_lp_threads(),
        ffvk_version: env!("CARGO_PKG_VERSION").to_string(),
        optimized_build: !cfg!(debug_assertions),
        validation: info.validation,
        load_before,
        load_after: None,
    };

    let mut all = points(config);
    if gl.is_none() {
        all.retain(|p| p.engine != Engine::Gl);
    }
    if let Some(g) = &gl {
        let before = all.len();
        all.retain(|p| p.engine != Engine::Gl || p.lights <= g.max_lights);
        if all.len() < before {
            notes.push(format!(
                "GL points with more than GL_MAX_LIGHTS = {} lights are left out",
                g.max_lights
            ));
        }
    }
    // One density at a time, so that only one set of meshes is alive (results keep the
    // order of `points`).
    let mut order: Vec<usize> = (0..all.len()).collect();
    order.sort_by_key(|&i| all[i].stacks);

    progress.set_length(all.len() as u64);
    progress.set_style(
        ProgressStyle::with_template("{bar:32.cyan/blue} {pos}/{len} {elapsed_precise} (eta {eta}) {msg}")
            .map_err(|e| Error::Bench(format!("progress bar template: {e}")))?,
    );
    let mut cache = MeshCache {
        stacks: 0,
        data: None,
        uploads: HashMap::new(),
    };
    let mut stats: Vec<Option<PointStats>> = vec![None; all.len()];
    for i in order {
        let point = &all[i];
        progress.set_message(point.label());
        if cache.stacks != point.stacks {
            cache.uploads.clear();
            cache.data = Some(MeshData::uv_sphere(2 * point.stacks, point.stacks));
            cache.stacks = point.stacks;
        }
        let data = cache.data.as_ref().expect("made above");
        let measured = match point.engine {
            Engine::Ffvk => {
                let renderer = renderers
                    .get_mut(&point.variant)
                    .expect("a renderer per ffvk variant");
                let mesh = match cache.uploads.entry((point.variant, point.primitive)) {
                    Entry::Occupied(e) => e.into_mut(),
                    Entry::Vacant(e) => e.insert(renderer.upload(&point.primitive.mesh(data))?),
                };
                measure_ffvk(renderer, mesh, point, config)?
            }
            Engine::Gl => match &gl {
                Some(g) => g.measure(&point.primitive.mesh(data), point, config)?,
                None => unreachable!("GL points are removed without the anchor"),
            },
            Engine::Zink => unreachable!("points() makes no zink points: its process draws them"),
        };
        stats[i] = Some(measured);
        progress.inc(1);
    }
    drop(cache);

    let results: Vec<BenchResult> = all
        .into_iter()
        .zip(stats)
        .map(|(point, stats)| BenchResult {
            point,
            stats: stats.expect("every point ran"),
            lp_num_threads: lp_num_threads.clone(),
            device: env.device.clone(),
            driver_info: env.driver_info.clone(),
            mesa_version: env.mesa_version.clone(),
        })
        .collect();
    let summary = summarize(&results);
    // A renderer of its own, so that the sweep's pipelines do not count as new keys (none
    // in a sweep that records no draws for it).
    let draw_cost = if config.record_draws > 0 {
        progress.set_message(format!(
            "recording cost ({} draws per frame)",
            config.record_draws
        ));
        let mut recorder_options = options.clone();
        recorder_options.specialize = Specialize::Always;
        let mut recorder = Renderer::new(&recorder_options)?;
        Some(measure_draw_cost(
            &mut recorder,
            options.device.as_deref(),
            config.record_draws,
            config.frames.clamp(1, 21),
            config.new_keys,
        )?)
    } else {
        None
    };
    // The draws sweep on a renderer of its own too: its thousands of states stay out of the
    // other measurements' pipelines and memory.
    let mut draws_renderer = Renderer::new(options)?;
    progress.set_length(
        progress.length().unwrap_or(0)
            + draws::DRAW_MODES.len() as u64
                * draws::DrawShape::ALL
                    .iter()
                    .map(|s| s.counts(&config.draw_counts).len() as u64)
                    .sum::<u64>()
                * (1 + u64::from(gl.is_some())),
    );
    let mut draws = draws::run_draws(config, &mut draws_renderer, gl.as_ref(), progress)?;
    // Frames of several lighting states, with the paths they compare.
    let states = match config.path_stacks.is_empty() {
        true => Vec::new(),
        false => states::run_states(config, &mut draws_renderer, progress)?,
    };
    drop(draws_renderer);
    // The floor on a device of its own, after the draws sweep.
    let floor = floor::run_floor(config, options, progress, &mut notes)?;
    let mut results = results;
    let mut env = env;
    if let Some(program) = &config.zink {
        progress.set_message("zink anchor (a process of its own)");
        let device = (info.name.as_str(), info.device_type.as_str());
        if let Some(zink) = zink::run_zink(program, config, device, &mut notes) {
            results.extend(zink.points.into_iter().map(|(point, stats)| BenchResult {
                point,
                stats,
                lp_num_threads: lp_num_threads.clone(),
                device: env.device.clone(),
                driver_info: env.driver_info.clone(),
                mesa_version: env.mesa_version.clone(),
            }));
            draws.extend(zink.draws);
            env.zink_renderer = Some(zink.renderer);
            env.zink_version = Some(zink.version);
        }
    }
    Ok(BenchReport {
        env: BenchEnv {
            load_after: load_average(),
            ..env
        },
        sweep: config.clone(),
        results,
        summary,
        draw_cost,
        draws,
        floor,
        states,
        notes,
    })
}
