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
//! pipelines). With the `osmesa` feature, the same scenes go through Mesa's fixed-function
//! OpenGL too, in the same process and on the same rasterizer (llvmpipe), as the anchor.
//!
//! Outputs: `results.csv`, `results.json`, `summary.md` and PNG plots, in one directory.
//! Every result carries LP_NUM_THREADS, the device, the driver and the Mesa version.

use std::collections::hash_map::Entry;
use std::collections::{BTreeMap, HashMap};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::Instant;

use glam::{Mat4, Vec3, Vec4};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use serde::Serialize;

use crate::draw::pipeline::Specialize;
use crate::gl::state::{
    Cap, Face, GlState, LightModelParam, LightParam, LightingMode, LightingState, MaterialParam,
};
use crate::mesh::MeshData;
use crate::renderer::{Draw, Frame, FrameStats, Mesh, Renderer, RendererOptions};
use crate::tools::{Error, Result};

/// LP_NUM_THREADS when neither `--lp-threads` nor the environment sets it: the CPUs this
/// process may use (what lavapipe would pick itself), pinned so that it is recorded.
pub fn default_lp_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// `ffvk bench`'s options.
#[derive(Debug, Clone, clap::Args)]
pub struct BenchArgs {
    /// Output directory: results.csv, results.json, summary.md and the plots (PNG).
    #[arg(short, long, default_value = "out/bench")]
    pub out: PathBuf,
    /// A quick sweep: fewer and smaller points, fewer frames (about a minute on 2 cores).
    #[arg(long, conflicts_with = "full")]
    pub quick: bool,
    /// The full sweep: more densities, sizes and light counts, both pipeline variants
    /// everywhere, more frames (about 25 minutes on 2 cores). The default sweep takes
    /// about 4 minutes.
    #[arg(long)]
    pub full: bool,
    /// Warm-up frames per point (default: the sweep's).
    #[arg(long)]
    pub warmup: Option<u32>,
    /// Measured frames per point (default: the sweep's).
    #[arg(long)]
    pub frames: Option<u32>,
    /// Rasterizer threads for lavapipe and OSMesa (sets LP_NUM_THREADS before the Vulkan
    /// instance exists). Default: LP_NUM_THREADS if set, else the number of CPUs.
    #[arg(long)]
    pub lp_threads: Option<usize>,
    /// Leave out the OpenGL (OSMesa) anchor even when ffvk is built with `--features osmesa`.
    #[arg(long)]
    pub no_gl: bool,
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
pub fn run(args: &BenchArgs, options: &RendererOptions) -> Result<()> {
    let threads = match (args.lp_threads, std::env::var("LP_NUM_THREADS")) {
        (Some(n), _) => n.to_string(),
        (None, Ok(v)) if !v.trim().is_empty() => v,
        _ => default_lp_threads().to_string(),
    };
    // Before the first Vulkan instance (lavapipe) or OSMesa context (llvmpipe) reads it, while
    // this process has one thread.
    std::env::set_var("LP_NUM_THREADS", &threads);
    if args.malloc_no_trim && !keep_freed_memory() {
        return Err(Error::Bench(
            "--malloc-no-trim needs glibc's mallopt, which refused the settings".into(),
        ));
    }

    let mut config = if args.quick {
        SweepConfig::quick()
    } else if args.full {
        SweepConfig::full()
    } else {
        SweepConfig::standard()
    };
    if let Some(w) = args.warmup {
        config.warmup = w;
    }
    if let Some(f) = args.frames {
        config.frames = f;
    }
    config.gl &= !args.no_gl;
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
    print!("{}", markdown(&report));
    println!();
    println!(
        "{} points in {:.0} s; wrote {}",
        report.results.len(),
        started.elapsed().as_secs_f64(),
        written
            .iter()
            .map(|p| p.display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    );
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// What a sweep measures.

/// A sweep: which points, how many frames each.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepConfig {
    pub name: String,
    /// Unmeasured frames first (at least one: it compiles what the point needs).
    pub warmup: u32,
    /// Measured frames per point (at least one).
    pub frames: u32,
    /// Densities of the density sweep, as sphere stacks (slices = 2 × stacks;
    /// (2s + 1)(s + 1) vertices).
    pub stacks: Vec<u32>,
    /// Image sides of the size sweep (square images).
    pub sizes: Vec<u32>,
    /// Light counts of the light-count sweep (directional lights).
    pub light_counts: Vec<usize>,
    /// Light kinds of the light-kind sweep, each with an infinite and a local viewer.
    pub kinds: Vec<LightKind>,
    /// Lights in the light-kind sweep.
    pub kind_lights: usize,
    /// Directional lights in the density and size sweeps.
    pub base_lights: usize,
    /// The mesh of the light-count and light-kind sweeps.
    pub base_stacks: u32,
    /// The mesh of the size sweep: dense enough that per-vertex and per-fragment lighting
    /// cross over within its image sizes.
    pub size_stacks: u32,
    /// The image side of every sweep but the size sweep.
    pub base_size: u32,
    /// Run the density and size sweeps with the uber-shader too (the light sweeps always
    /// run both variants).
    pub variants_everywhere: bool,
    /// Draw the OpenGL anchor points (needs the `osmesa` feature; skipped without it).
    pub gl: bool,
    /// Whether the process keeps freed heap memory (`--malloc-no-trim`). [`run`] sets the
    /// allocator up, process-wide; [`run_sweep`] only records this.
    pub malloc_no_trim: bool,
}

impl SweepConfig {
    /// About a minute on 2 cores.
    pub fn quick() -> Self {
        SweepConfig {
            name: "quick".into(),
            warmup: 2,
            frames: 5,
            stacks: vec![8, 32, 128, 512, 768],
            sizes: vec![128, 256, 512, 1024],
            light_counts: vec![1, 4, 8],
            kinds: LightKind::ALL.to_vec(),
            kind_lights: 4,
            base_lights: 4,
            base_stacks: 128,
            size_stacks: 256,
            base_size: 512,
            variants_everywhere: false,
            gl: true,
            malloc_no_trim: false,
        }
    }

    /// The default: about 4 minutes on 2 cores, from 153 to 2.1 million vertices and from
    /// 64² to 2048².
    pub fn standard() -> Self {
        SweepConfig {
            name: "standard".into(),
            warmup: 3,
            frames: 11,
            stacks: vec![8, 16, 32, 64, 128, 256, 512, 768, 1024],
            sizes: vec![64, 128, 256, 512, 1024, 2048],
            light_counts: vec![1, 2, 4, 8, 16],
            base_stacks: 256,
            size_stacks: 512,
            ..SweepConfig::quick()
        }
    }

    /// More of everything: about 25 minutes on 2 cores.
    pub fn full() -> Self {
        SweepConfig {
            name: "full".into(),
            warmup: 4,
            frames: 17,
            stacks: vec![8, 16, 32, 64, 128, 256, 384, 512, 768, 1024],
            sizes: vec![64, 96, 128, 192, 256, 384, 512, 768, 1024, 1536, 2048],
            light_counts: vec![1, 2, 3, 4, 6, 8, 12, 16],
            variants_everywhere: true,
            ..SweepConfig::standard()
        }
    }

    /// A few tiny points, one or two frames each: proves the harness works (tests).
    pub fn tiny() -> Self {
        SweepConfig {
            name: "tiny".into(),
            warmup: 1,
            frames: 2,
            stacks: vec![4, 8],
            sizes: vec![16, 32],
            light_counts: vec![1, 2],
            kinds: vec![LightKind::Directional, LightKind::Spot],
            kind_lights: 2,
            base_lights: 1,
            base_stacks: 6,
            size_stacks: 5,
            base_size: 24,
            variants_everywhere: false,
            gl: true,
            malloc_no_trim: false,
        }
    }

    fn validate(&self) -> Result<()> {
        let bad = |what: String| Err(Error::Bench(what));
        if self.warmup == 0 || self.frames == 0 {
            return bad(format!(
                "warm-up {} and frames {}: expected at least 1 of each",
                self.warmup, self.frames
            ));
        }
        let max_lights = crate::gl::state::MAX_LIGHTS;
        if let Some(n) = self
            .light_counts
            .iter()
            .chain([&self.kind_lights, &self.base_lights])
            .find(|&&n| n == 0 || n > max_lights)
        {
            return bad(format!("{n} lights: expected 1..={max_lights}"));
        }
        if let Some(s) = self
            .sizes
            .iter()
            .chain([&self.base_size])
            .find(|&&s| s == 0 || s > crate::scene::MAX_SIZE)
        {
            return bad(format!("image size {s}: expected 1..={}", crate::scene::MAX_SIZE));
        }
        if let Some(s) = self
            .stacks
            .iter()
            .chain([&self.base_stacks, &self.size_stacks])
            .find(|&&s| !(2..=2048).contains(&s))
        {
            return bad(format!("{s} sphere stacks: expected 2..=2048"));
        }
        Ok(())
    }
}

/// Which sweep a point belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Group {
    Density,
    Size,
    Lights,
    Kind,
}

/// Who draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Engine {
    Ffvk,
    /// Mesa's fixed-function OpenGL through OSMesa.
    Gl,
}

/// Where the equation is evaluated, or nowhere.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BenchMode {
    Vertex,
    Fragment,
    Flat,
    /// The same geometry with lighting off: the vertex color passes through (the floor).
    Unlit,
}

impl BenchMode {
    pub const ALL: [BenchMode; 4] = [
        BenchMode::Vertex,
        BenchMode::Fragment,
        BenchMode::Flat,
        BenchMode::Unlit,
    ];

    pub fn name(self) -> &'static str {
        match self {
            BenchMode::Vertex => "vertex",
            BenchMode::Fragment => "fragment",
            BenchMode::Flat => "flat",
            BenchMode::Unlit => "unlit",
        }
    }

    fn lighting_mode(self) -> LightingMode {
        match self {
            BenchMode::Fragment => LightingMode::Fragment,
            BenchMode::Flat => LightingMode::Flat,
            BenchMode::Vertex | BenchMode::Unlit => LightingMode::Vertex,
        }
    }
}

/// Which pipelines drew the point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Variant {
    /// ffvk's pipelines specialized for the state ([`Specialize::Always`]).
    Specialized,
    /// ffvk's uber-shader ([`Specialize::Never`]).
    Uber,
    /// GL's own fixed-function pipeline.
    FixedFunction,
}

impl Variant {
    pub fn name(self) -> &'static str {
        match self {
            Variant::Specialized => "specialized",
            Variant::Uber => "uber",
            Variant::FixedFunction => "fixed_function",
        }
    }
}

/// The kind of every light of a point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LightKind {
    /// w = 0.
    Directional,
    /// w = 1, attenuated.
    Point,
    /// A point light with a 35° cone, exponent 8.
    Spot,
}

impl LightKind {
    pub const ALL: [LightKind; 3] = [LightKind::Directional, LightKind::Point, LightKind::Spot];

    pub fn name(self) -> &'static str {
        match self {
            LightKind::Directional => "directional",
            LightKind::Point => "point",
            LightKind::Spot => "spot",
        }
    }
}

/// One measured configuration.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Point {
    pub group: Group,
    pub engine: Engine,
    pub mode: BenchMode,
    pub variant: Variant,
    /// Sphere stacks (slices are twice as many).
    pub stacks: u32,
    pub vertices: u64,
    pub triangles: u64,
    pub width: u32,
    pub height: u32,
    pub pixels: u64,
    /// Enabled lights (0 when unlit).
    pub lights: usize,
    pub light_kind: LightKind,
    pub local_viewer: bool,
}

impl Point {
    fn label(&self) -> String {
        format!(
            "{:?} {} {} {} {}v {}x{} {}×{}{}",
            self.group,
            match self.engine {
                Engine::Ffvk => "ffvk",
                Engine::Gl => "GL",
            },
            self.mode.name(),
            self.variant.name(),
            self.vertices,
            self.width,
            self.height,
            self.lights,
            self.light_kind.name(),
            if self.local_viewer { " local" } else { "" }
        )
    }
}

/// Median, quartiles and extremes of a point's frames.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Spread {
    pub median: f64,
    pub min: f64,
    pub p25: f64,
    pub p75: f64,
    pub max: f64,
}

impl Spread {
    /// The spread of `samples` (linear interpolation between order statistics); `None`
    /// when there are none.
    pub fn of(samples: &[f64]) -> Option<Spread> {
        let mut s: Vec<f64> = samples.iter().copied().filter(|v| v.is_finite()).collect();
        if s.is_empty() {
            return None;
        }
        s.sort_by(f64::total_cmp);
        let at = |q: f64| {
            let pos = q * (s.len() - 1) as f64;
            let (lo, hi) = (pos.floor() as usize, pos.ceil() as usize);
            s[lo] + (s[hi] - s[lo]) * (pos - lo as f64)
        };
        Some(Spread {
            median: at(0.5),
            min: s[0],
            p25: at(0.25),
            p75: at(0.75),
            max: s[s.len() - 1],
        })
    }
}

/// What a point measured.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PointStats {
    pub warmup: u32,
    pub frames: u32,
    /// Host time of the first warm-up frame, ms: it includes creating the pipeline and
    /// lavapipe's lazy fragment-shader compile when the point is the first to need them.
    pub first_frame_ms: f64,
    /// Timestamps around the rendering pass (ffvk only), ms.
    pub gpu_ms: Option<Spread>,
    /// Host time per frame, ms: submit to fence for ffvk; draw calls to glFinish for GL.
    pub wall_ms: Spread,
    /// The figure the tables and plots use: `gpu_ms` for ffvk, `wall_ms` for GL (medians).
    pub time_ms: f64,
    /// Pipeline statistics of the last frame (ffvk only; the same every frame).
    pub vs_invocations: Option<u64>,
    pub fs_invocations: Option<u64>,
    pub clipping_primitives: Option<u64>,
}

/// The machine and driver, recorded with every result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchEnv {
    /// LP_NUM_THREADS as the drivers read it ("unset" when it was not set).
    pub lp_num_threads: String,
    pub device: String,
    pub driver: String,
    pub driver_info: String,
    pub mesa_version: String,
    pub vulkan_api: String,
    /// GL_RENDERER and GL_VERSION of the OSMesa anchor, when it ran.
    pub gl_renderer: Option<String>,
    pub gl_version: Option<String>,
    pub cpu: String,
    pub cpus: usize,
    pub ffvk_version: String,
    /// Whether ffvk was built with optimizations (benchmarks want `--release`).
    pub optimized_build: bool,
    pub validation: bool,
    /// /proc/loadavg's 1-minute load before and after the sweep: other work on the machine.
    pub load_before: Option<f64>,
    pub load_after: Option<f64>,
}

/// One row of the results: the point, its stats and the environment.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchResult {
    #[serde(flatten)]
    pub point: Point,
    #[serde(flatten)]
    pub stats: PointStats,
    pub lp_num_threads: String,
    pub device: String,
    pub driver_info: String,
    pub mesa_version: String,
}

/// ffvk against GL on one scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GlRatio {
    pub group: Group,
    pub mode: BenchMode,
    pub vertices: u64,
    pub pixels: u64,
    pub lights: usize,
    /// ffvk's host time per frame (submit to fence), specialized pipelines, ms.
    pub ffvk_wall_ms: f64,
    /// ffvk's timestamps, ms.
    pub ffvk_gpu_ms: Option<f64>,
    /// GL's host time per frame (draw to glFinish), ms.
    pub gl_wall_ms: f64,
    /// ffvk_wall_ms / gl_wall_ms: below 1, ffvk is faster.
    pub ratio: f64,
}

/// What the sweep shows, computed from its results.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// Vertices (at the base image size) where vertex and fragment mode cost the same.
    pub crossover_vertices: Option<f64>,
    /// Pixels (with the base mesh) where vertex and fragment mode cost the same.
    pub crossover_pixels: Option<f64>,
    /// Per mode: geometric mean over the light sweeps of uber time / specialized time.
    pub specialization_speedup: BTreeMap<String, f64>,
    /// What ffvk uses by default, after this measurement.
    pub default_specialize: String,
    pub gl_ratios: Vec<GlRatio>,
    /// Geometric mean of the vertex-mode ratios.
    pub gl_vertex_ratio_geomean: Option<f64>,
}

/// A whole run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchReport {
    pub env: BenchEnv,
    pub sweep: SweepConfig,
    pub results: Vec<BenchResult>,
    pub summary: Summary,
    /// What was left out and why (the GL anchor without the osmesa feature, GL points over
    /// GL_MAX_LIGHTS).
    pub notes: Vec<String>,
}

/// Tells glibc's allocator to keep freed memory: no trimming of the heaps (lavapipe draws on
/// its queue thread, whose arena glibc trims with madvise after every frame, so the next
/// frame faults its pages in again), and a large top pad. Returns whether glibc accepted.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn keep_freed_memory() -> bool {
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
fn keep_freed_memory() -> bool {
    false
}

// ---------------------------------------------------------------------------------------------
// The points of a sweep.

fn sphere_counts(stacks: u32) -> (u64, u64) {
    let (slices, stacks) = (2 * stacks as u64, stacks as u64);
    ((slices + 1) * (stacks + 1), slices * (2 * stacks - 2))
}

/// The points of `config`, in a stable order: density, size, lights, kind; GL after ffvk.
pub fn points(config: &SweepConfig) -> Vec<Point> {
    let mut out = Vec::new();
    let base = |group, engine, mode, variant| {
        let (vertices, triangles) = sphere_counts(config.base_stacks);
        Point {
            group,
            engine,
            mode,
            variant,
            stacks: config.base_stacks,
            vertices,
            triangles,
            width: config.base_size,
            height: config.base_size,
            pixels: config.base_size as u64 * config.base_size as u64,
            lights: if mode == BenchMode::Unlit {
                0
            } else {
                config.base_lights
            },
            light_kind: LightKind::Directional,
            local_viewer: false,
        }
    };
    let some_variants = |everywhere: bool| {
        if everywhere {
            vec![Variant::Specialized, Variant::Uber]
        } else {
            vec![Variant::Specialized]
        }
    };
    let gl_modes = [BenchMode::Vertex, BenchMode::Flat, BenchMode::Unlit];

    for &stacks in &config.stacks {
        let (vertices, triangles) = sphere_counts(stacks);
        for mode in BenchMode::ALL {
            for variant in some_variants(config.variants_everywhere) {
                out.push(Point {
                    stacks,
                    vertices,
                    triangles,
                    ..base(Group::Density, Engine::Ffvk, mode, variant)
                });
            }
        }
        if config.gl {
            for mode in gl_modes {
                out.push(Point {
                    stacks,
                    vertices,
                    triangles,
                    ..base(Group::Density, Engine::Gl, mode, Variant::FixedFunction)
                });
            }
        }
    }
    for &size in &config.sizes {
        let (vertices, triangles) = sphere_counts(config.size_stacks);
        let sized = |p: Point| Point {
            stacks: config.size_stacks,
            vertices,
            triangles,
            width: size,
            height: size,
            pixels: size as u64 * size as u64,
            ..p
        };
        for mode in BenchMode::ALL {
            for variant in some_variants(config.variants_everywhere) {
                out.push(sized(base(Group::Size, Engine::Ffvk, mode, variant)));
            }
        }
        if config.gl {
            for mode in gl_modes {
                out.push(sized(base(Group::Size, Engine::Gl, mode, Variant::FixedFunction)));
            }
        }
    }
    for &lights in &config.light_counts {
        for mode in [BenchMode::Vertex, BenchMode::Fragment] {
            for variant in [Variant::Specialized, Variant::Uber] {
                out.push(Point {
                    lights,
                    ..base(Group::Lights, Engine::Ffvk, mode, variant)
                });
            }
        }
        if config.gl {
            out.push(Point {
                lights,
                ..base(
                    Group::Lights,
                    Engine::Gl,
                    BenchMode::Vertex,
                    Variant::FixedFunction,
                )
            });
        }
    }
    for &kind in &config.kinds {
        for local_viewer in [false, true] {
            let with_kind = |p: Point| Point {
                lights: config.kind_lights,
                light_kind: kind,
                local_viewer,
                ..p
            };
            for mode in [BenchMode::Vertex, BenchMode::Fragment] {
                for variant in [Variant::Specialized, Variant::Uber] {
                    out.push(with_kind(base(Group::Kind, Engine::Ffvk, mode, variant)));
                }
            }
            if config.gl {
                out.push(with_kind(base(
                    Group::Kind,
                    Engine::Gl,
                    BenchMode::Vertex,
                    Variant::FixedFunction,
                )));
            }
        }
    }
    out
}

/// The lighting state of a point: `lights` lights of one kind around the view axis, white
/// light split between them, a shiny material on both faces.
pub fn point_state(point: &Point) -> Result<LightingState> {
    let mut gl = GlState::new();
    gl.lighting_mode(point.mode.lighting_mode());
    if point.mode == BenchMode::Unlit {
        return Ok(gl.lighting);
    }
    gl.enable(Cap::Lighting)?;
    gl.light_model(LightModelParam::LocalViewer(point.local_viewer))?;
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Diffuse(Vec4::new(0.8, 0.7, 0.6, 1.0)),
    )?;
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Specular(Vec4::new(0.6, 0.6, 0.6, 1.0)),
    )?;
    gl.material(Face::FrontAndBack, MaterialParam::Shininess(32.0))?;
    let n = point.lights.max(1);
    let share = 1.0 / n as f32;
    for i in 0..point.lights {
        let a = std::f32::consts::TAU * i as f32 / n as f32;
        let (s, c) = a.sin_cos();
        gl.enable(Cap::Light(i))?;
        gl.light(i, LightParam::Diffuse(Vec4::new(share, share, share, 1.0)))?;
        gl.light(i, LightParam::Specular(Vec4::new(share, share, share, 1.0)))?;
        // Eye space (the modelview is the identity here): the sphere's center is at z = -2.6.
        let local = Vec3::new(1.6 * c, 1.6 * s, -1.0);
        match point.light_kind {
            LightKind::Directional => {
                gl.light(i, LightParam::Position(Vec4::new(0.6 * c, 0.6 * s, 1.0, 0.0)))?;
            }
            LightKind::Point | LightKind::Spot => {
                gl.light(i, LightParam::Position(local.extend(1.0)))?;
                gl.light(i, LightParam::ConstantAttenuation(1.0))?;
                gl.light(i, LightParam::LinearAttenuation(0.05))?;
                gl.light(i, LightParam::QuadraticAttenuation(0.02))?;
            }
        }
        if point.light_kind == LightKind::Spot {
            gl.light(i, LightParam::SpotDirection(Vec3::new(0.0, 0.0, -2.6) - local))?;
            gl.light(i, LightParam::SpotCutoff(35.0))?;
            gl.light(i, LightParam::SpotExponent(8.0))?;
        }
    }
    Ok(gl.lighting)
}

/// The sphere's modelview and a GL projection for a square image.
fn matrices(point: &Point) -> (Mat4, Mat4) {
    let aspect = point.width as f32 / point.height as f32;
    (
        Mat4::from_translation(Vec3::new(0.0, 0.0, -2.6)),
        Mat4::perspective_rh_gl(45f32.to_radians(), aspect, 0.5, 10.0),
    )
}

const CLEAR: Vec4 = Vec4::new(0.1, 0.1, 0.12, 1.0);

// ---------------------------------------------------------------------------------------------
// Running.

/// The first number after "Mesa " in a driver or GL version string ("Mesa 22.3.6 (LLVM …)").
pub fn mesa_version(text: &str) -> Option<String> {
    let at = text.find("Mesa ")? + "Mesa ".len();
    let version: String = text[at..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.')
        .collect();
    (!version.is_empty()).then_some(version)
}

fn cpu_model() -> String {
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
    uploads: HashMap<Variant, Mesh>,
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
    ] {
        let r = Renderer::new(&RendererOptions {
            specialize,
            ..options.clone()
        })?;
        renderers.insert(variant, r);
    }
    let info = renderers[&Variant::Specialized].device_info().clone();

    let gl = GlAnchor::open(config.gl, &mut notes);
    let env = BenchEnv {
        lp_num_threads: lp_num_threads.clone(),
        device: info.name.clone(),
        driver: info.driver_name.clone(),
        driver_info: info.driver_info.clone(),
        mesa_version: mesa_version(&info.driver_info).unwrap_or_else(|| "not Mesa".into()),
        vulkan_api: info.api_version.clone(),
        gl_renderer: gl.as_ref().map(|g| g.renderer.clone()),
        gl_version: gl.as_ref().map(|g| g.version.clone()),
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
                let mesh = match cache.uploads.entry(point.variant) {
                    Entry::Occupied(e) => e.into_mut(),
                    Entry::Vacant(e) => e.insert(renderer.upload(data)?),
                };
                measure_ffvk(renderer, mesh, point, config)?
            }
            Engine::Gl => match &gl {
                Some(g) => g.measure(data, point, config)?,
                None => unreachable!("GL points are removed without the anchor"),
            },
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
    Ok(BenchReport {
        env: BenchEnv {
            load_after: load_average(),
            ..env
        },
        sweep: config.clone(),
        results,
        summary,
        notes,
    })
}

fn measure_ffvk(
    renderer: &mut Renderer,
    mesh: &Mesh,
    point: &Point,
    config: &SweepConfig,
) -> Result<PointStats> {
    let (modelview, projection) = matrices(point);
    let mut frame = Frame::new(point.width, point.height);
    frame.clear_color = CLEAR;
    frame.draws.push(Draw {
        mesh,
        modelview,
        projection,
        state: point_state(point)?,
    });
    let start = Instant::now();
    renderer.measure(&frame)?;
    let first_frame_ms = start.elapsed().as_secs_f64() * 1e3;
    for _ in 1..config.warmup {
        renderer.measure(&frame)?;
    }
    let samples = (0..config.frames)
        .map(|_| renderer.measure(&frame))
        .collect::<crate::Result<Vec<FrameStats>>>()?;
    let gpu: Vec<f64> = samples
        .iter()
        .filter_map(|s| s.gpu_ns)
        .map(|ns| ns / 1e6)
        .collect();
    let wall: Vec<f64> = samples.iter().map(|s| s.wall_ns / 1e6).collect();
    let gpu_ms = Spread::of(&gpu);
    let wall_ms = Spread::of(&wall).expect("at least one frame");
    let last = samples.last().and_then(|s| s.pipeline);
    Ok(PointStats {
        warmup: config.warmup,
        frames: config.frames,
        first_frame_ms,
        time_ms: gpu_ms.map_or(wall_ms.median, |g| g.median),
        gpu_ms,
        wall_ms,
        vs_invocations: last.map(|p| p.vertex_shader_invocations),
        fs_invocations: last.map(|p| p.fragment_shader_invocations),
        clipping_primitives: last.map(|p| p.clipping_primitives),
    })
}

/// Mesa's fixed-function GL, when ffvk is built with the `osmesa` feature.
struct GlAnchor {
    renderer: String,
    version: String,
    max_lights: usize,
}

impl GlAnchor {
    #[cfg(feature = "osmesa")]
    fn open(wanted: bool, notes: &mut Vec<String>) -> Option<GlAnchor> {
        if !wanted {
            notes.push("GL anchor not requested".into());
            return None;
        }
        match crate::tools::gl_reference::gl_info() {
            Ok(info) => Some(GlAnchor {
                renderer: info.renderer,
                version: info.version,
                max_lights: usize::try_from(info.max_lights).unwrap_or(0),
            }),
            Err(e) => {
                notes.push(format!("GL anchor left out: {e}"));
                None
            }
        }
    }

    #[cfg(not(feature = "osmesa"))]
    fn open(wanted: bool, notes: &mut Vec<String>) -> Option<GlAnchor> {
        if wanted {
            notes.push(
                "GL anchor left out: ffvk was built without the `osmesa` feature \
                 (cargo run --release --features osmesa -- bench)"
                    .into(),
            );
        }
        None
    }

    #[cfg(feature = "osmesa")]
    fn measure(&self, mesh: &MeshData, point: &Point, config: &SweepConfig) -> Result<PointStats> {
        use crate::tools::gl_reference::{time_frames, GlDraw, GlScene};
        let (modelview, projection) = matrices(point);
        let scene = GlScene {
            width: point.width,
            height: point.height,
            clear_color: CLEAR.to_array(),
            depth_test: true,
            draws: vec![GlDraw {
                mesh,
                modelview,
                projection,
                state: point_state(point)?,
            }],
        };
        let timing = time_frames(&scene, config.warmup, config.frames)?;
        let wall: Vec<f64> = timing.frame_ns.iter().map(|ns| ns / 1e6).collect();
        let wall_ms = Spread::of(&wall).expect("at least one frame");
        Ok(PointStats {
            warmup: config.warmup,
            frames: config.frames,
            first_frame_ms: timing.first_frame_ns / 1e6,
            gpu_ms: None,
            wall_ms,
            time_ms: wall_ms.median,
            vs_invocations: None,
            fs_invocations: None,
            clipping_primitives: None,
        })
    }

    #[cfg(not(feature = "osmesa"))]
    fn measure(&self, _mesh: &MeshData, _point: &Point, _config: &SweepConfig) -> Result<PointStats> {
        Err(Error::Bench("the GL anchor needs the osmesa feature".into()))
    }
}

// ---------------------------------------------------------------------------------------------
// What the results show.

/// (x, time) of one series, sorted by x.
fn series(
    results: &[BenchResult],
    keep: impl Fn(&Point) -> bool,
    x: impl Fn(&Point) -> f64,
) -> Vec<(f64, &BenchResult)> {
    let mut s: Vec<(f64, &BenchResult)> = results
        .iter()
        .filter(|r| keep(&r.point))
        .map(|r| (x(&r.point), r))
        .collect();
    s.sort_by(|a, b| a.0.total_cmp(&b.0));
    s
}

/// Where `a` and `b` (times at the same x values) cost the same: the first sign change of
/// ln a − ln b, interpolated in log-log. `None` when one stays below the other.
pub fn crossover(a: &[(f64, f64)], b: &[(f64, f64)]) -> Option<f64> {
    let mut d: Vec<(f64, f64)> = Vec::new();
    for &(x, ta) in a {
        if let Some(&(_, tb)) = b.iter().find(|(xb, _)| *xb == x) {
            if x > 0.0 && ta > 0.0 && tb > 0.0 {
                d.push((x.ln(), ta.ln() - tb.ln()));
            }
        }
    }
    d.windows(2).find_map(|w| {
        let ((x0, d0), (x1, d1)) = (w[0], w[1]);
        if d0 == 0.0 {
            return Some(x0.exp());
        }
        if (d0 < 0.0) != (d1 < 0.0) || d1 == 0.0 {
            let t = d0 / (d0 - d1);
            Some((x0 + t * (x1 - x0)).exp())
        } else {
            None
        }
    })
}

fn geomean(values: impl IntoIterator<Item = f64>) -> Option<f64> {
    let (sum, n) = values
        .into_iter()
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((0.0, 0usize), |(s, n), v| (s + v.ln(), n + 1));
    (n > 0).then(|| (sum / n as f64).exp())
}

fn times(s: &[(f64, &BenchResult)]) -> Vec<(f64, f64)> {
    s.iter().map(|(x, r)| (*x, r.stats.time_ms)).collect()
}

fn is(group: Group, engine: Engine, mode: BenchMode, variant: Variant) -> impl Fn(&Point) -> bool {
    move |p: &Point| p.group == group && p.engine == engine && p.mode == mode && p.variant == variant
}

/// The crossovers, the specialization speedups and the GL ratios of `results`.
pub fn summarize(results: &[BenchResult]) -> Summary {
    let spec = Variant::Specialized;
    let by_vertices = |mode| {
        times(&series(
            results,
            is(Group::Density, Engine::Ffvk, mode, spec),
            |p| p.vertices as f64,
        ))
    };
    let by_pixels = |mode| {
        times(&series(results, is(Group::Size, Engine::Ffvk, mode, spec), |p| {
            p.pixels as f64
        }))
    };
    let crossover_vertices = crossover(&by_vertices(BenchMode::Vertex), &by_vertices(BenchMode::Fragment));
    let crossover_pixels = crossover(&by_pixels(BenchMode::Vertex), &by_pixels(BenchMode::Fragment));

    // Uber / specialized over every point that ran both.
    let mut speedups: BTreeMap<String, Vec<f64>> = BTreeMap::new();
    for r in results.iter().filter(|r| r.point.variant == Variant::Uber) {
        let twin = results.iter().find(|s| {
            s.point
                == Point {
                    variant: Variant::Specialized,
                    ..r.point.clone()
                }
        });
        if let Some(s) = twin {
            speedups
                .entry(r.point.mode.name().to_string())
                .or_default()
                .push(r.stats.time_ms / s.stats.time_ms);
        }
    }
    let specialization_speedup: BTreeMap<String, f64> = speedups
        .into_iter()
        .filter_map(|(mode, v)| geomean(v).map(|g| (mode, g)))
        .collect();
    let default_specialize = match geomean(specialization_speedup.values().copied()) {
        Some(g) if g < 1.0 => format!(
            "{} (the uber-shader measured faster here: consider Specialize::Never)",
            Specialize::default().name()
        ),
        _ => format!("{} (specialized pipelines)", Specialize::default().name()),
    };

    let mut gl_ratios = Vec::new();
    for g in results.iter().filter(|r| r.point.engine == Engine::Gl) {
        let twin = results.iter().find(|s| {
            s.point
                == Point {
                    engine: Engine::Ffvk,
                    variant: spec,
                    ..g.point.clone()
                }
        });
        if let Some(f) = twin {
            gl_ratios.push(GlRatio {
                group: g.point.group,
                mode: g.point.mode,
                vertices: g.point.vertices,
                pixels: g.point.pixels,
                lights: g.point.lights,
                ffvk_wall_ms: f.stats.wall_ms.median,
                ffvk_gpu_ms: f.stats.gpu_ms.map(|s| s.median),
                gl_wall_ms: g.stats.wall_ms.median,
                ratio: f.stats.wall_ms.median / g.stats.wall_ms.median,
            });
        }
    }
    let gl_vertex_ratio_geomean = geomean(
        gl_ratios
            .iter()
            .filter(|r| r.mode == BenchMode::Vertex)
            .map(|r| r.ratio),
    );
    Summary {
        crossover_vertices,
        crossover_pixels,
        specialization_speedup,
        default_specialize,
        gl_ratios,
        gl_vertex_ratio_geomean,
    }
}

// ---------------------------------------------------------------------------------------------
// Outputs.

fn write_file(path: &Path, bytes: &[u8]) -> Result<()> {
    std::fs::write(path, bytes).map_err(|source| Error::Write {
        path: path.to_path_buf(),
        source,
    })
}

/// The CSV columns, in order.
pub const CSV_COLUMNS: [&str; 36] = [
    "group",
    "engine",
    "mode",
    "variant",
    "stacks",
    "vertices",
    "triangles",
    "width",
    "height",
    "pixels",
    "lights",
    "light_kind",
    "local_viewer",
    "warmup",
    "frames",
    "time_ms",
    "gpu_ms_median",
    "gpu_ms_min",
    "gpu_ms_p25",
    "gpu_ms_p75",
    "gpu_ms_max",
    "wall_ms_median",
    "wall_ms_min",
    "wall_ms_p25",
    "wall_ms_p75",
    "wall_ms_max",
    "first_frame_ms",
    "vs_invocations",
    "fs_invocations",
    "clipping_primitives",
    "lp_num_threads",
    "device",
    "driver_info",
    "mesa_version",
    "optimized_build",
    "malloc_no_trim",
];

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The results as CSV: a header of [`CSV_COLUMNS`] and one row per point.
pub fn csv(report: &BenchReport) -> String {
    let mut out = CSV_COLUMNS.join(",");
    out.push('\n');
    let num = |v: f64| format!("{v:.4}");
    let opt_spread = |s: Option<Spread>| match s {
        Some(s) => [s.median, s.min, s.p25, s.p75, s.max].map(num),
        None => std::array::from_fn(|_| String::new()),
    };
    let opt = |v: Option<u64>| v.map_or(String::new(), |v| v.to_string());
    for r in &report.results {
        let p = &r.point;
        let s = &r.stats;
        let w = s.wall_ms;
        let mut row: Vec<String> = vec![
            serde_name(&p.group),
            serde_name(&p.engine),
            p.mode.name().into(),
            p.variant.name().into(),
            p.stacks.to_string(),
            p.vertices.to_string(),
            p.triangles.to_string(),
            p.width.to_string(),
            p.height.to_string(),
            p.pixels.to_string(),
            p.lights.to_string(),
            p.light_kind.name().into(),
            p.local_viewer.to_string(),
            s.warmup.to_string(),
            s.frames.to_string(),
            num(s.time_ms),
        ];
        row.extend(opt_spread(s.gpu_ms));
        row.extend([w.median, w.min, w.p25, w.p75, w.max].map(num));
        row.extend([
            num(s.first_frame_ms),
            opt(s.vs_invocations),
            opt(s.fs_invocations),
            opt(s.clipping_primitives),
            r.lp_num_threads.clone(),
            r.device.clone(),
            r.driver_info.clone(),
            r.mesa_version.clone(),
            report.env.optimized_build.to_string(),
            report.sweep.malloc_no_trim.to_string(),
        ]);
        debug_assert_eq!(row.len(), CSV_COLUMNS.len());
        out.push_str(&row.iter().map(|f| csv_field(f)).collect::<Vec<_>>().join(","));
        out.push('\n');
    }
    out
}

/// The serde name of a unit enum variant ("density", "ffvk").
fn serde_name<T: Serialize>(value: &T) -> String {
    match serde_json::to_value(value) {
        Ok(serde_json::Value::String(s)) => s,
        _ => String::new(),
    }
}

/// Writes results.csv, results.json, summary.md and the plots into `dir` (created when
/// missing); returns the paths written.
pub fn write_outputs(report: &BenchReport, dir: &Path) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut written = Vec::new();
    let path = dir.join("results.csv");
    write_file(&path, csv(report).as_bytes())?;
    written.push(path);
    let path = dir.join("results.json");
    let json = serde_json::to_string_pretty(report).map_err(|source| Error::Json {
        path: path.clone(),
        source,
    })?;
    write_file(&path, json.as_bytes())?;
    written.push(path);
    let path = dir.join("summary.md");
    write_file(&path, markdown(report).as_bytes())?;
    written.push(path);
    written.extend(plots::write_all(report, dir)?);
    Ok(written)
}

/// "1 directional light", "4 directional lights".
fn lights_text(n: usize) -> String {
    format!("{n} directional light{}", if n == 1 { "" } else { "s" })
}

fn ms(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
}

/// "median (p25–p75)" of a result's main time.
fn cell(r: Option<&BenchResult>) -> String {
    match r {
        None => "–".into(),
        Some(r) => {
            let s = r.stats.gpu_ms.unwrap_or(r.stats.wall_ms);
            format!("{} ({}–{})", ms(r.stats.time_ms), ms(s.p25), ms(s.p75))
        }
    }
}

fn find(results: &[BenchResult], keep: impl Fn(&Point) -> bool) -> Option<&BenchResult> {
    results.iter().find(|r| keep(&r.point))
}

fn count(n: f64) -> String {
    if n >= 1e6 {
        format!("{:.2} M", n / 1e6)
    } else if n >= 1e3 {
        format!("{:.1} k", n / 1e3)
    } else {
        format!("{n:.0}")
    }
}

/// The tables of a run, as Markdown (written to summary.md and quoted in BENCHMARKS.md).
pub fn markdown(report: &BenchReport) -> String {
    let mut m = String::new();
    let e = &report.env;
    let c = &report.sweep;
    let res = &report.results;
    let spec = Variant::Specialized;
    let _ = writeln!(m, "### Environment\n");
    let _ = writeln!(m, "| | |\n| --- | --- |");
    let _ = writeln!(m, "| device | {} ({}) |", e.device, e.driver);
    let _ = writeln!(m, "| driver | {} — Mesa {} |", e.driver_info, e.mesa_version);
    if let (Some(r), Some(v)) = (&e.gl_renderer, &e.gl_version) {
        let _ = writeln!(m, "| GL anchor | {r}, GL {v} (OSMesa) |");
    }
    let _ = writeln!(m, "| LP_NUM_THREADS | {} |", e.lp_num_threads);
    let _ = writeln!(
        m,
        "| heap | {} |",
        if c.malloc_no_trim {
            "freed memory kept (--malloc-no-trim: glibc M_TRIM_THRESHOLD = max, M_TOP_PAD = 256 MiB)"
        } else {
            "glibc defaults (freed memory trimmed)"
        }
    );
    let _ = writeln!(m, "| CPU | {} ({} CPUs) |", e.cpu, e.cpus);
    let load = |l: Option<f64>| l.map_or("?".into(), |l| format!("{l:.2}"));
    let _ = writeln!(
        m,
        "| load average (1 min) | {} before, {} after |",
        load(e.load_before),
        load(e.load_after)
    );
    let _ = writeln!(
        m,
        "| sweep | {} — {} warm-up + {} measured frames per point; image {}² but in the size sweep; {} vertices in the size sweep, {} in the light sweeps |",
        c.name,
        c.warmup,
        c.frames,
        c.base_size,
        sphere_counts(c.size_stacks).0,
        sphere_counts(c.base_stacks).0
    );
    let _ = writeln!(
        m,
        "| build | ffvk {}, {}{} |",
        e.ffvk_version,
        if e.optimized_build {
            "optimized"
        } else {
            "debug (numbers not representative)"
        },
        if e.validation { ", validation layer on" } else { "" }
    );
    for n in &report.notes {
        let _ = writeln!(m, "| note | {n} |");
    }

    let _ = writeln!(
        m,
        "\nTimes are per frame in ms: the median, then the interquartile range; ffvk's from \
         timestamps around the rendering pass, GL's from the host clock around the draw and \
         glFinish.\n"
    );

    // Density.
    let has_gl = res.iter().any(|r| r.point.engine == Engine::Gl);
    let _ = writeln!(
        m,
        "### Time against vertex count ({}² image, {})\n",
        c.base_size,
        lights_text(c.base_lights)
    );
    let mut header =
        String::from("| vertices | triangles | vertex | fragment | flat | unlit | VS invocations (vertex) |");
    let mut rule = String::from("| ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    if has_gl {
        header.push_str(" GL smooth | GL flat | GL unlit | ffvk vertex ÷ GL |");
        rule.push_str(" ---: | ---: | ---: | ---: |");
    }
    let _ = writeln!(m, "{header}\n{rule}");
    for &stacks in &c.stacks {
        let at = |engine, mode, variant| {
            find(res, |p| {
                p.group == Group::Density
                    && p.stacks == stacks
                    && p.engine == engine
                    && p.mode == mode
                    && p.variant == variant
            })
        };
        let (v, t) = sphere_counts(stacks);
        let mut row = format!("| {} | {} |", count(v as f64), count(t as f64));
        for mode in BenchMode::ALL {
            let _ = write!(row, " {} |", cell(at(Engine::Ffvk, mode, spec)));
        }
        let vs = at(Engine::Ffvk, BenchMode::Vertex, spec)
            .and_then(|r| r.stats.vs_invocations)
            .map_or("–".into(), |n| count(n as f64));
        let _ = write!(row, " {vs} |");
        if has_gl {
            for mode in [BenchMode::Vertex, BenchMode::Flat, BenchMode::Unlit] {
                let _ = write!(row, " {} |", cell(at(Engine::Gl, mode, Variant::FixedFunction)));
            }
            let ratio = report
                .summary
                .gl_ratios
                .iter()
                .find(|r| r.group == Group::Density && r.mode == BenchMode::Vertex && r.vertices == v)
                .map_or("–".into(), |r| format!("{:.2}", r.ratio));
            let _ = write!(row, " {ratio} |");
        }
        let _ = writeln!(m, "{row}");
    }

    // Size.
    let _ = writeln!(
        m,
        "\n### Time against pixel count ({} vertices, {})\n",
        sphere_counts(c.size_stacks).0,
        lights_text(c.base_lights)
    );
    let _ = writeln!(
        m,
        "| image | pixels | vertex | fragment | flat | unlit | FS invocations (fragment) |\n| ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    );
    for &size in &c.sizes {
        let at = |mode| {
            find(res, |p| {
                p.group == Group::Size
                    && p.width == size
                    && p.engine == Engine::Ffvk
                    && p.mode == mode
                    && p.variant == spec
            })
        };
        let mut row = format!("| {size}² | {} |", count(size as f64 * size as f64));
        for mode in BenchMode::ALL {
            let _ = write!(row, " {} |", cell(at(mode)));
        }
        let fs = at(BenchMode::Fragment)
            .and_then(|r| r.stats.fs_invocations)
            .map_or("–".into(), |n| count(n as f64));
        let _ = writeln!(m, "{row} {fs} |");
    }

    // Lights.
    let _ = writeln!(
        m,
        "\n### Light count: specialized pipelines against the uber-shader ({} vertices, {}², directional lights)\n",
        sphere_counts(c.base_stacks).0,
        c.base_size
    );
    let mut header =
        String::from("| lights | vertex specialized | vertex uber | uber ÷ spec. | fragment specialized | fragment uber | uber ÷ spec. |");
    let mut rule = String::from("| ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    if has_gl {
        header.push_str(" GL smooth | ffvk vertex ÷ GL |");
        rule.push_str(" ---: | ---: |");
    }
    let _ = writeln!(m, "{header}\n{rule}");
    for &lights in &c.light_counts {
        let at = |engine, mode, variant| {
            find(res, |p| {
                p.group == Group::Lights
                    && p.lights == lights
                    && p.engine == engine
                    && p.mode == mode
                    && p.variant == variant
            })
        };
        let mut row = format!("| {lights} |");
        for mode in [BenchMode::Vertex, BenchMode::Fragment] {
            let (s, u) = (
                at(Engine::Ffvk, mode, spec),
                at(Engine::Ffvk, mode, Variant::Uber),
            );
            let ratio = match (s, u) {
                (Some(s), Some(u)) => format!("{:.2}", u.stats.time_ms / s.stats.time_ms),
                _ => "–".into(),
            };
            let _ = write!(row, " {} | {} | {ratio} |", cell(s), cell(u));
        }
        if has_gl {
            let g = at(Engine::Gl, BenchMode::Vertex, Variant::FixedFunction);
            let ratio = report
                .summary
                .gl_ratios
                .iter()
                .find(|r| r.group == Group::Lights && r.lights == lights)
                .map_or("–".into(), |r| format!("{:.2}", r.ratio));
            let _ = write!(row, " {} | {ratio} |", cell(g));
        }
        let _ = writeln!(m, "{row}");
    }

    // Kinds.
    let _ = writeln!(
        m,
        "\n### Light kind ({} lights of one kind, {} vertices, {}²)\n",
        c.kind_lights,
        sphere_counts(c.base_stacks).0,
        c.base_size
    );
    let mut header = String::from(
        "| lights | viewer | vertex specialized | vertex uber | fragment specialized | fragment uber |",
    );
    let mut rule = String::from("| --- | --- | ---: | ---: | ---: | ---: |");
    if has_gl {
        header.push_str(" GL smooth | ffvk vertex ÷ GL |");
        rule.push_str(" ---: | ---: |");
    }
    let _ = writeln!(m, "{header}\n{rule}");
    for &kind in &c.kinds {
        for local in [false, true] {
            let at = |engine, mode, variant| {
                find(res, |p| {
                    p.group == Group::Kind
                        && p.light_kind == kind
                        && p.local_viewer == local
                        && p.engine == engine
                        && p.mode == mode
                        && p.variant == variant
                })
            };
            let mut row = format!(
                "| {} | {} |",
                kind.name(),
                if local { "local" } else { "infinite" }
            );
            for mode in [BenchMode::Vertex, BenchMode::Fragment] {
                for variant in [spec, Variant::Uber] {
                    let _ = write!(row, " {} |", cell(at(Engine::Ffvk, mode, variant)));
                }
            }
            if has_gl {
                let g = at(Engine::Gl, BenchMode::Vertex, Variant::FixedFunction);
                let f = at(Engine::Ffvk, BenchMode::Vertex, spec);
                let ratio = match (f, g) {
                    (Some(f), Some(g)) => format!("{:.2}", f.stats.wall_ms.median / g.stats.wall_ms.median),
                    _ => "–".into(),
                };
                let _ = write!(row, " {} | {ratio} |", cell(g));
            }
            let _ = writeln!(m, "{row}");
        }
    }

    // Summary.
    let s = &report.summary;
    let _ = writeln!(m, "\n### Summary\n");
    let _ = writeln!(
        m,
        "- vertex and fragment mode cost the same at about {} ({}² image)",
        s.crossover_vertices
            .map_or("— (no crossing in this sweep)".into(), |v| format!(
                "{} vertices",
                count(v)
            )),
        c.base_size
    );
    let _ = writeln!(
        m,
        "- with {} vertices they cost the same at about {}",
        sphere_counts(c.size_stacks).0,
        s.crossover_pixels
            .map_or("— (no crossing in this sweep)".into(), |p| format!(
                "{} pixels ({:.0}²)",
                count(p),
                p.sqrt()
            ))
    );
    for (mode, g) in &s.specialization_speedup {
        let _ = writeln!(
            m,
            "- {mode} mode: the uber-shader takes {g:.2}× the time of specialized pipelines (geometric mean)"
        );
    }
    let _ = writeln!(m, "- ffvk's default: Specialize::{}", s.default_specialize);
    if let Some(g) = s.gl_vertex_ratio_geomean {
        let _ = writeln!(
            m,
            "- ffvk vertex mode ÷ Mesa's fixed-function GL (host time per frame, geometric mean over {} scenes): {g:.2}",
            s.gl_ratios.iter().filter(|r| r.mode == BenchMode::Vertex).count()
        );
    }
    m
}

// ---------------------------------------------------------------------------------------------
// Plots.

mod plots {
    use super::*;
    use plotters::coord::ranged1d::ValueFormatter;
    use plotters::coord::Shift;
    use plotters::prelude::*;
    use plotters::style::text_anchor::{HPos, Pos, VPos};

    /// Tick labels: "20 k", "1.5 M", "0.5", "12".
    fn axis_number(v: f64) -> String {
        let a = v.abs();
        if a >= 1e6 {
            format!("{} M", trim(v / 1e6))
        } else if a >= 1e4 {
            format!("{} k", trim(v / 1e3))
        } else {
            trim(v)
        }
    }

    fn trim(v: f64) -> String {
        let s = if v.abs() >= 100.0 || v.fract() == 0.0 {
            format!("{v:.0}")
        } else if v.abs() >= 1.0 {
            format!("{v:.1}")
        } else {
            format!("{v:.2}")
        };
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    }

    const WIDTH: u32 = 1000;
    const HEIGHT: u32 = 640;

    /// Registers Debian's DejaVu Sans as plotters' "sans-serif" (once per process).
    fn ensure_font() -> Result<()> {
        static FONT: OnceLock<std::result::Result<(), String>> = OnceLock::new();
        FONT.get_or_init(|| {
            let path = crate::tools::sheet::LABEL_FONT;
            let bytes = std::fs::read(path)
                .map_err(|e| format!("{path}: {e} (install the Debian package fonts-dejavu-core)"))?;
            // plotters keeps the font for the life of the process; it is loaded once.
            let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
            plotters::style::register_font("sans-serif", FontStyle::Normal, bytes)
                .map_err(|_| format!("{path}: not a usable TrueType font"))
        })
        .clone()
        .map_err(|message| Error::Font {
            path: crate::tools::sheet::LABEL_FONT.into(),
            message,
        })
    }

    fn color(mode: BenchMode) -> RGBColor {
        match mode {
            BenchMode::Vertex => RGBColor(31, 119, 180),
            BenchMode::Fragment => RGBColor(214, 39, 40),
            BenchMode::Flat => RGBColor(44, 160, 44),
            BenchMode::Unlit => RGBColor(127, 127, 127),
        }
    }

    /// One line of a plot.
    struct Line {
        label: String,
        color: RGBColor,
        dashed: bool,
        /// (x, median, low, high).
        points: Vec<(f64, f64, f64, f64)>,
    }

    /// The lines of one sweep against `x`: ffvk's specialized modes, then GL's.
    fn mode_lines(res: &[BenchResult], group: Group, x: fn(&Point) -> f64) -> Vec<Line> {
        let mut lines = Vec::new();
        for mode in BenchMode::ALL {
            let ser = series(res, is(group, Engine::Ffvk, mode, Variant::Specialized), x);
            lines.extend(line(format!("ffvk {}", mode.name()), color(mode), false, &ser));
        }
        for mode in [BenchMode::Vertex, BenchMode::Flat, BenchMode::Unlit] {
            let ser = series(res, is(group, Engine::Gl, mode, Variant::FixedFunction), x);
            let name = if mode == BenchMode::Vertex {
                "smooth"
            } else {
                mode.name()
            };
            lines.extend(line(format!("GL {name} (OSMesa)"), color(mode), true, &ser));
        }
        lines
    }

    fn line(label: String, color: RGBColor, dashed: bool, s: &[(f64, &BenchResult)]) -> Option<Line> {
        let points: Vec<(f64, f64, f64, f64)> = s
            .iter()
            .map(|(x, r)| {
                let sp = r.stats.gpu_ms.unwrap_or(r.stats.wall_ms);
                (*x, r.stats.time_ms, sp.min, sp.max)
            })
            .collect();
        (!points.is_empty()).then_some(Line {
            label,
            color,
            dashed,
            points,
        })
    }

    /// A log-log (or lin-log) chart of `lines` with min–max whiskers and vertical markers.
    fn chart(
        path: &Path,
        title: &str,
        x_label: &str,
        x_log: bool,
        lines: &[Line],
        markers: &[(f64, String)],
    ) -> Result<()> {
        let err = |message: String| Error::Plot {
            path: path.to_path_buf(),
            message,
        };
        let plot_err = |e: &dyn std::fmt::Display| err(e.to_string());
        let mut buffer = vec![0u8; (WIDTH * HEIGHT * 3) as usize];
        {
            let root = BitMapBackend::with_buffer(&mut buffer, (WIDTH, HEIGHT)).into_drawing_area();
            root.fill(&WHITE).map_err(|e| plot_err(&e))?;
            let all: Vec<&(f64, f64, f64, f64)> = lines.iter().flat_map(|l| &l.points).collect();
            if all.is_empty() {
                return Err(err("no points to plot".into()));
            }
            let (mut x0, mut x1) = (f64::MAX, f64::MIN);
            let (mut y0, mut y1) = (f64::MAX, f64::MIN);
            for &&(x, y, lo, hi) in &all {
                x0 = x0.min(x);
                x1 = x1.max(x);
                y0 = y0.min(lo.min(y));
                y1 = y1.max(hi.max(y));
            }
            let (y0, y1) = ((y0 * 0.8).max(1e-3), y1 * 1.25);
            // Crossover labels sit left of their line in the right half of the plot.
            let markers: Vec<(f64, String, bool)> = markers
                .iter()
                .map(|(x, t)| {
                    let f = if x_log {
                        (x.ln() - x0.ln()) / (x1.ln() - x0.ln()).max(1e-9)
                    } else {
                        (x - x0) / (x1 - x0).max(1e-9)
                    };
                    (*x, t.clone(), f > 0.5)
                })
                .collect();
            let markers = &markers[..];
            if x_log {
                let (x0, x1) = (x0 / 1.3, x1 * 1.3);
                let c = builder(&root, title)
                    .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
                    .map_err(|e| plot_err(&e))?;
                draw(c, x_label, lines, markers, (y0, y1)).map_err(|e| plot_err(&e))?;
            } else {
                // A linear x (light counts) gets a linear time axis from zero.
                let pad = ((x1 - x0) * 0.05).max(0.5);
                let c = builder(&root, title)
                    .build_cartesian_2d((x0 - pad)..(x1 + pad), 0.0..y1)
                    .map_err(|e| plot_err(&e))?;
                draw(c, x_label, lines, markers, (0.0, y1)).map_err(|e| plot_err(&e))?;
            }
            root.present().map_err(|e| plot_err(&e))?;
        }
        let rgb =
            image::RgbImage::from_raw(WIDTH, HEIGHT, buffer).ok_or_else(|| err("plot buffer size".into()))?;
        Ok(crate::images::save_png(
            &image::DynamicImage::ImageRgb8(rgb).to_rgba8(),
            path,
        )?)
    }

    type Chart<'a, X, Y> = ChartContext<'a, BitMapBackend<'a>, Cartesian2d<X, Y>>;
    type DrawResult<'a> =
        std::result::Result<(), DrawingAreaErrorKind<<BitMapBackend<'a> as DrawingBackend>::ErrorType>>;

    fn builder<'a, 'b>(
        root: &'a DrawingArea<BitMapBackend<'b>, Shift>,
        title: &str,
    ) -> ChartBuilder<'a, 'b, BitMapBackend<'b>> {
        let mut b = ChartBuilder::on(root);
        b.caption(title, ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(64);
        b
    }

    fn draw<'a, X, Y>(
        mut c: Chart<'a, X, Y>,
        x_label: &str,
        lines: &[Line],
        markers: &[(f64, String, bool)],
        (y0, y1): (f64, f64),
    ) -> DrawResult<'a>
    where
        X: Ranged<ValueType = f64> + ValueFormatter<f64>,
        Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
    {
        c.configure_mesh()
            .x_desc(x_label)
            .y_desc("time per frame, ms (median; whiskers: min–max)")
            .x_label_formatter(&|v| axis_number(*v))
            .y_label_formatter(&|v| axis_number(*v))
            .label_style(("sans-serif", 15))
            .axis_desc_style(("sans-serif", 16))
            .draw()?;
        for (x, text, left_of_line) in markers {
            let style = ShapeStyle::from(&BLACK.mix(0.6)).stroke_width(1);
            c.draw_series(DashedLineSeries::new(vec![(*x, y0), (*x, y1)], 6, 4, style))?;
            let anchor = if *left_of_line { HPos::Right } else { HPos::Left };
            let font = ("sans-serif", 15)
                .into_font()
                .color(&BLACK)
                .pos(Pos::new(anchor, VPos::Top));
            let text = if *left_of_line {
                format!("{text} ")
            } else {
                format!(" {text}")
            };
            c.draw_series(std::iter::once(Text::new(text, (*x, y1 / 1.1), font)))?;
        }
        for l in lines {
            let style = ShapeStyle::from(&l.color).stroke_width(2);
            let pts: Vec<(f64, f64)> = l.points.iter().map(|p| (p.0, p.1)).collect();
            let anno = if l.dashed {
                c.draw_series(DashedLineSeries::new(pts.clone(), 8, 5, style))?
            } else {
                c.draw_series(LineSeries::new(pts.clone(), style))?
            };
            let legend_color = l.color;
            let dashed = l.dashed;
            anno.label(l.label.clone()).legend(move |(x, y)| {
                let s = ShapeStyle::from(&legend_color).stroke_width(if dashed { 1 } else { 3 });
                PathElement::new(vec![(x, y), (x + 22, y)], s)
            });
            c.draw_series(
                pts.iter()
                    .map(|&(x, y)| Circle::new((x, y), 3, ShapeStyle::from(&l.color).filled())),
            )?;
            c.draw_series(l.points.iter().map(|&(x, _, lo, hi)| {
                PathElement::new(vec![(x, lo), (x, hi)], ShapeStyle::from(&l.color.mix(0.7)))
            }))?;
        }
        c.configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.4))
            .label_font(("sans-serif", 15))
            .draw()?;
        Ok(())
    }

    /// Writes every plot the report has data for; returns the paths.
    pub fn write_all(report: &BenchReport, dir: &Path) -> Result<Vec<PathBuf>> {
        ensure_font()?;
        let res = &report.results;
        let c = &report.sweep;
        let s = &report.summary;
        let spec = Variant::Specialized;
        let mut written = Vec::new();

        // Time against vertices, per mode (+ GL).
        let lines = mode_lines(res, Group::Density, |p| p.vertices as f64);
        if !lines.is_empty() {
            let markers: Vec<(f64, String)> = s
                .crossover_vertices
                .map(|v| (v, format!("vertex = fragment at {} vertices", count(v))))
                .into_iter()
                .collect();
            let path = dir.join("time_vs_vertices.png");
            chart(
                &path,
                &format!(
                    "Time against vertex count ({}² image, {})",
                    c.base_size,
                    lights_text(c.base_lights)
                ),
                "vertices (log)",
                true,
                &lines,
                &markers,
            )?;
            written.push(path);
        }

        // Time against pixels, per mode (+ GL).
        let lines = mode_lines(res, Group::Size, |p| p.pixels as f64);
        if !lines.is_empty() {
            let markers: Vec<(f64, String)> = s
                .crossover_pixels
                .map(|p| (p, format!("vertex = fragment at {} pixels", count(p))))
                .into_iter()
                .collect();
            let path = dir.join("time_vs_pixels.png");
            chart(
                &path,
                &format!(
                    "Time against pixel count ({} vertices, {})",
                    sphere_counts(c.size_stacks).0,
                    lights_text(c.base_lights)
                ),
                "pixels (log)",
                true,
                &lines,
                &markers,
            )?;
            written.push(path);
        }

        // Time against light count: specialized against uber (+ GL).
        let mut lines = Vec::new();
        for mode in [BenchMode::Vertex, BenchMode::Fragment] {
            for variant in [spec, Variant::Uber] {
                let ser = series(res, is(Group::Lights, Engine::Ffvk, mode, variant), |p| {
                    p.lights as f64
                });
                lines.extend(line(
                    format!("ffvk {} {}", mode.name(), variant.name()),
                    color(mode),
                    variant == Variant::Uber,
                    &ser,
                ));
            }
        }
        let ser = series(
            res,
            is(
                Group::Lights,
                Engine::Gl,
                BenchMode::Vertex,
                Variant::FixedFunction,
            ),
            |p| p.lights as f64,
        );
        lines.extend(line("GL smooth (OSMesa)".into(), RGBColor(0, 0, 0), true, &ser));
        if !lines.is_empty() {
            let path = dir.join("time_vs_lights.png");
            chart(
                &path,
                &format!(
                    "Time against light count: specialized and uber pipelines ({} vertices, {}²)",
                    sphere_counts(c.base_stacks).0,
                    c.base_size
                ),
                "directional lights",
                false,
                &lines,
                &[],
            )?;
            written.push(path);
        }
        Ok(written)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Made-up times that grow with vertices, pixels and lights, the uber-shader and GL slower;
    /// vertex and fragment mode cross in the density and the size sweep.
    fn fake_time(p: &Point) -> f64 {
        let lights = 1.0 + p.lights as f64;
        let (per_vertex, per_pixel) = match p.mode {
            BenchMode::Vertex => (4e-3 * lights, 2e-4),
            BenchMode::Fragment => (1e-4, 1e-3 * lights),
            BenchMode::Flat => (3e-4 * lights, 2e-4),
            BenchMode::Unlit => (1e-4, 2e-4),
        };
        let kind = match p.light_kind {
            LightKind::Directional => 1.0,
            LightKind::Point => 1.05,
            LightKind::Spot => 1.1,
        };
        let viewer = if p.local_viewer { 1.02 } else { 1.0 };
        let t = (0.05 + per_vertex * p.vertices as f64 + per_pixel * p.pixels as f64) * kind * viewer;
        match p.variant {
            Variant::Specialized => t,
            Variant::Uber => t * 1.25,
            Variant::FixedFunction => t * 1.5,
        }
    }

    /// A report of the tiny sweep with [`fake_time`]s: no device needed.
    pub(crate) fn synthetic_report() -> BenchReport {
        let sweep = SweepConfig::tiny();
        let env = BenchEnv {
            lp_num_threads: "2".into(),
            device: "llvmpipe (LLVM 15.0.6, 256 bits)".into(),
            driver: "llvmpipe".into(),
            driver_info: "Mesa 22.3.6 (LLVM 15.0.6)".into(),
            mesa_version: "22.3.6".into(),
            vulkan_api: "1.3.230".into(),
            gl_renderer: Some("llvmpipe (LLVM 15.0.6, 256 bits)".into()),
            gl_version: Some("2.1 Mesa 22.3.6".into()),
            cpu: "Some CPU".into(),
            cpus: 2,
            ffvk_version: "0.1.0".into(),
            optimized_build: true,
            validation: false,
            load_before: Some(0.5),
            load_after: None,
        };
        let results: Vec<BenchResult> = points(&sweep)
            .into_iter()
            .map(|point| {
                let t = fake_time(&point);
                let spread = Spread {
                    median: t,
                    min: t * 0.9,
                    p25: t * 0.95,
                    p75: t * 1.05,
                    max: t * 1.2,
                };
                let ffvk = point.engine == Engine::Ffvk;
                BenchResult {
                    stats: PointStats {
                        warmup: sweep.warmup,
                        frames: sweep.frames,
                        first_frame_ms: 10.0 * t,
                        gpu_ms: ffvk.then_some(spread),
                        wall_ms: Spread {
                            median: t * 1.1,
                            ..spread
                        },
                        time_ms: t,
                        vs_invocations: ffvk.then_some(point.vertices),
                        fs_invocations: ffvk.then_some(point.pixels / 2),
                        clipping_primitives: ffvk.then_some(point.triangles),
                    },
                    point,
                    lp_num_threads: env.lp_num_threads.clone(),
                    device: env.device.clone(),
                    driver_info: env.driver_info.clone(),
                    mesa_version: env.mesa_version.clone(),
                }
            })
            .collect();
        let summary = summarize(&results);
        BenchReport {
            env,
            sweep,
            results,
            summary,
            notes: vec!["a note".into()],
        }
    }

    /// summary.md of [`synthetic_report`], to the character.
    const SYNTHETIC_SUMMARY: &str = r#"### Environment

| | |
| --- | --- |
| device | llvmpipe (LLVM 15.0.6, 256 bits) (llvmpipe) |
| driver | Mesa 22.3.6 (LLVM 15.0.6) — Mesa 22.3.6 |
| GL anchor | llvmpipe (LLVM 15.0.6, 256 bits), GL 2.1 Mesa 22.3.6 (OSMesa) |
| LP_NUM_THREADS | 2 |
| heap | glibc defaults (freed memory trimmed) |
| CPU | Some CPU (2 CPUs) |
| load average (1 min) | 0.50 before, ? after |
| sweep | tiny — 1 warm-up + 2 measured frames per point; image 24² but in the size sweep; 66 vertices in the size sweep, 91 in the light sweeps |
| build | ffvk 0.1.0, optimized |
| note | a note |

Times are per frame in ms: the median, then the interquartile range; ffvk's from timestamps around the rendering pass, GL's from the host clock around the draw and glFinish.

### Time against vertex count (24² image, 1 directional light)

| vertices | triangles | vertex | fragment | flat | unlit | VS invocations (vertex) | GL smooth | GL flat | GL unlit | ffvk vertex ÷ GL |
| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| 45 | 48 | 0.53 (0.50–0.55) | 1.21 (1.15–1.27) | 0.19 (0.18–0.20) | 0.17 (0.16–0.18) | 45 | 0.79 (0.75–0.83) | 0.29 (0.27–0.30) | 0.25 (0.24–0.27) | 0.67 |
| 153 | 224 | 1.39 (1.32–1.46) | 1.22 (1.16–1.28) | 0.26 (0.24–0.27) | 0.18 (0.17–0.19) | 153 | 2.08 (1.98–2.19) | 0.39 (0.37–0.40) | 0.27 (0.26–0.28) | 0.67 |

### Time against pixel count (66 vertices, 1 directional light)

| image | pixels | vertex | fragment | flat | unlit | FS invocations (fragment) |
| ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| 16² | 256 | 0.63 (0.60–0.66) | 0.57 (0.54–0.60) | 0.14 (0.13–0.15) | 0.11 (0.10–0.11) | 128 |
| 32² | 1.0 k | 0.78 (0.74–0.82) | 2.10 (2.00–2.21) | 0.29 (0.28–0.31) | 0.26 (0.25–0.27) | 512 |

### Light count: specialized pipelines against the uber-shader (91 vertices, 24², directional lights)

| lights | vertex specialized | vertex uber | uber ÷ spec. | fragment specialized | fragment uber | uber ÷ spec. | GL smooth | ffvk vertex ÷ GL |
| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| 1 | 0.89 (0.85–0.94) | 1.12 (1.06–1.17) | 1.25 | 1.21 (1.15–1.27) | 1.51 (1.44–1.59) | 1.25 | 1.34 (1.27–1.41) | 0.67 |
| 2 | 1.26 (1.19–1.32) | 1.57 (1.49–1.65) | 1.25 | 1.79 (1.70–1.88) | 2.23 (2.12–2.35) | 1.25 | 1.89 (1.79–1.98) | 0.67 |

### Light kind (2 lights of one kind, 91 vertices, 24²)

| lights | viewer | vertex specialized | vertex uber | fragment specialized | fragment uber | GL smooth | ffvk vertex ÷ GL |
| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |
| directional | infinite | 1.26 (1.19–1.32) | 1.57 (1.49–1.65) | 1.79 (1.70–1.88) | 2.23 (2.12–2.35) | 1.89 (1.79–1.98) | 0.67 |
| directional | local | 1.28 (1.22–1.35) | 1.60 (1.52–1.68) | 1.82 (1.73–1.91) | 2.28 (2.16–2.39) | 1.92 (1.83–2.02) | 0.67 |
| spot | infinite | 1.38 (1.31–1.45) | 1.73 (1.64–1.82) | 1.97 (1.87–2.06) | 2.46 (2.33–2.58) | 2.07 (1.97–2.18) | 0.67 |
| spot | local | 1.41 (1.34–1.48) | 1.76 (1.68–1.85) | 2.01 (1.90–2.11) | 2.51 (2.38–2.63) | 2.12 (2.01–2.22) | 0.67 |

### Summary

- vertex and fragment mode cost the same at about 129 vertices (24² image)
- with 66 vertices they cost the same at about 291 pixels (17²)
- fragment mode: the uber-shader takes 1.25× the time of specialized pipelines (geometric mean)
- vertex mode: the uber-shader takes 1.25× the time of specialized pipelines (geometric mean)
- ffvk's default: Specialize::auto (specialized pipelines)
- ffvk vertex mode ÷ Mesa's fixed-function GL (host time per frame, geometric mean over 10 scenes): 0.67
"#;

    #[test]
    fn markdown_of_a_synthetic_report() {
        let m = markdown(&synthetic_report());
        for (line, (actual, expected)) in m.lines().zip(SYNTHETIC_SUMMARY.lines()).enumerate() {
            assert_eq!(actual, expected, "line {}", line + 1);
        }
        assert_eq!(m, SYNTHETIC_SUMMARY);
    }
}
