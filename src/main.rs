//! The `ffvk` command line.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use ffvk::gl::state::LightingMode;
use ffvk::images::compare::{self, Tolerance};
use ffvk::images::save_png;
use ffvk::scene::direct::is_gltf;
use ffvk::scene::render_scene;
use ffvk::vk::Validation;
use ffvk::{Renderer, RendererOptions};
use ffvk_cli::gltf_args::GltfArgs;
use ffvk_cli::regress;

#[derive(Parser)]
#[command(
    name = "ffvk",
    version,
    about = "The OpenGL 2.1 fixed-function lighting equation, verbatim, on Vulkan"
)]
struct Cli {
    /// Use the Vulkan device whose name contains this text (default: lavapipe).
    #[arg(long, global = true)]
    device: Option<String>,
    /// Load VK_LAYER_KHRONOS_validation when installed (warn when it is not).
    #[arg(long, global = true)]
    validate: bool,
    /// The host memory a scene's meshes may take, in MiB (the device holds as much again).
    #[arg(long, global = true, value_name = "MIB", default_value_t = ffvk::scene::DEFAULT_MESH_BYTES >> 20,
          value_parser = clap::value_parser!(u64).range(1..=1 << 24))]
    max_mesh_mib: u64,
    /// Let glTF buffer URIs reach files inside DIR too (by default only the glTF file's own
    /// folder); may be given more than once.
    #[arg(long, global = true, value_name = "DIR")]
    allow_root: Vec<PathBuf>,
    /// Run as a worker process of `render --jobs` (started by ffvk itself).
    #[arg(long, hide = true)]
    render_worker: bool,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Print the device, driver, versions and the limits that matter to ffvk.
    Info,
    /// Render the demo: the lit teapot panels and the three lighting modes.
    Demo {
        /// Output directory.
        #[arg(short, long, default_value = "out/demo")]
        out: PathBuf,
    },
    /// Benchmark the lighting modes, densities, sizes, lights and pipeline variants.
    Bench(ffvk_cli::bench::BenchArgs),
    /// Render scene files, glTF files (or directories of scene files) with one device;
    /// optionally check each image against references.
    Render {
        /// Scene files (.toml), glTF files (.gltf, .glb: drawn with the scene `ffvk scene`
        /// prints) or directories: their *.toml files below them, in path order, or where
        /// there is none their *.gltf and *.glb files (a folder of models is a suite too).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Output PNG when rendering one scene or glTF file in one mode; otherwise a folder
        /// (NAME.png each; a name ending in .png is refused). Without -o each image lands
        /// beside its scene or glTF file, as NAME.png.
        #[arg(short, long)]
        out: Option<PathBuf>,
        /// Override the scenes' lighting mode; a comma list renders each (NAME_MODE.png).
        #[arg(long, value_delimiter = ',')]
        lighting: Vec<LightingMode>,
        /// Override the image size, as WxH (the vertical field of view is kept).
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
        /// Draw the fragment mode forward (at every fragment), deferred (once per pixel,
        /// where a frame allows it) or auto (deferred where ffvk's fixed rule of vertices,
        /// pixels, lights and device type says it is faster): overrides the scenes'
        /// `[image] fragment_path`.
        #[arg(long, value_parser = ["forward", "deferred", "auto"])]
        fragment_path: Option<String>,
        /// Check each image against DIR/NAME.png and print a summary table; exit 1 on a
        /// difference past the tolerance or a missing reference.
        #[arg(long, value_name = "DIR")]
        check: Option<PathBuf>,
        /// Write missing or changed references into the --check directory (also FFVK_BLESS=1).
        #[arg(long, requires = "check")]
        bless: bool,
        /// Worker processes to render in (default: one per CPU). A worker that crashes costs
        /// only the scene it was rendering, which becomes an error row.
        #[arg(short, long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
        jobs: Option<u32>,
        /// Render only shard K of N: the scenes whose name (path below the folder given)
        /// hashes to K; the N shards together are the whole suite (see `ffvk results merge`).
        #[arg(long, value_name = "K/N")]
        partition: Option<regress::Partition>,
        /// Write the results as JUnit XML (one test case per scene and mode).
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Write the results as JSON (what `ffvk results merge` reads).
        #[arg(long, value_name = "FILE")]
        json: Option<PathBuf>,
        /// Write an HTML report into DIR (index.html): the failed, missing, errored and
        /// blessed images worst first, each with its reference, difference maps and figures.
        #[arg(long, value_name = "DIR", requires = "check")]
        report: Option<PathBuf>,
        /// Seconds one scene (all its modes) may take before its worker is killed and the
        /// scene reported as an error.
        #[arg(long, value_name = "SECONDS", default_value_t = 600.0, value_parser = parse_seconds)]
        timeout: f64,
        #[command(flatten)]
        tolerance: ToleranceArgs,
        #[command(flatten)]
        gltf: GltfArgs,
    },
    /// Results files of `render --json`: merge the shards of a partitioned run.
    Results {
        #[command(subcommand)]
        action: ResultsAction,
    },
    /// Print the scene TOML ffvk draws a glTF file with (camera, lights, glTF's meaning), as
    /// the start of a hand-tuned scene.
    Scene {
        /// A .gltf or .glb file.
        gltf: PathBuf,
        /// Write the scene here (its glTF path made relative to it) instead of to stdout.
        #[arg(short, long)]
        out: Option<PathBuf>,
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
        #[command(flatten)]
        choices: GltfArgs,
    },
    /// Compare two images: per-channel differences, share over a threshold, FLIP.
    Compare {
        expected: PathBuf,
        actual: PathBuf,
        /// Write a heat map of the differences (FLIP, magma) here.
        #[arg(long)]
        diff: Option<PathBuf>,
        #[command(flatten)]
        tolerance: ToleranceArgs,
    },
    /// Write the Utah teapot (Newell's patches) as a glTF file.
    Teapot {
        /// Tessellation level: each patch becomes LEVEL×LEVEL quads.
        #[arg(long, default_value_t = 8)]
        level: u32,
        #[arg(short, long, default_value = "assets/teapot.gltf")]
        out: PathBuf,
    },
    /// Print every term of the lighting equation at one pixel (CPU reference).
    Explain {
        /// A scene file (.toml) or a glTF file (.gltf, .glb), as `render` takes it.
        scene: PathBuf,
        /// The pixel, as X,Y from the top-left corner.
        #[arg(long, value_parser = parse_pixel)]
        pixel: (u32, u32),
        /// Explain the pixel as this lighting mode draws it (vertex, fragment or flat)
        /// instead of the scene's own mode.
        #[arg(long)]
        lighting: Option<LightingMode>,
        /// The image size, as WxH, as `render --size` sets it (the vertical field of view is
        /// kept): the pixel is in that image.
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
        #[command(flatten)]
        gltf: GltfArgs,
    },
}

#[derive(Subcommand)]
enum ResultsAction {
    /// Join the results files of every shard of one suite (each written by `render
    /// --partition K/N --json FILE`) into one summary, and optionally one JSON and one JUnit
    /// file; refuses shards of different suites, a shard given twice and missing shards.
    /// Exits as `render --check` does: 0 pass, 1 a difference or missing reference, 2 an error.
    Merge {
        /// The shards' results files.
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// Write the merged results as JSON.
        #[arg(long, value_name = "FILE")]
        json: Option<PathBuf>,
        /// Write the merged results as JUnit XML.
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Write the merged results as an HTML report into DIR.
        #[arg(long, value_name = "DIR")]
        report: Option<PathBuf>,
    },
    /// Write the HTML report of results files (one run's, or every shard's: they are merged
    /// first) into DIR. The image paths the files record are read as they were written
    /// (relative ones from the current folder). Exits as `render --check` does.
    Report {
        /// The results files (`render --json`).
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// The folder to write index.html, report.css and images/ into.
        #[arg(short, long, value_name = "DIR", required = true)]
        out: PathBuf,
    },
}

fn parse_seconds(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x > 0.0 && x <= 1e6 => Ok(x),
        _ => Err(format!(
            "{s:?}: expected a number of seconds, > 0 and at most 1000000"
        )),
    }
}

fn parse_pair(s: &str, sep: char, what: &str) -> Result<(u32, u32), String> {
    let parts: Vec<&str> = s.split(sep).collect();
    match parts.as_slice() {
        [a, b] => match (a.trim().parse(), b.trim().parse()) {
            (Ok(a), Ok(b)) => Ok((a, b)),
            _ => Err(format!("{s:?}: expected {what}")),
        },
        _ => Err(format!("{s:?}: expected {what}")),
    }
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = parse_pair(s, 'x', "WIDTHxHEIGHT, e.g. 512x512")?;
    if w == 0 || h == 0 || w > ffvk::scene::MAX_SIZE || h > ffvk::scene::MAX_SIZE {
        return Err(format!(
            "{s:?}: expected each side in 1..={}",
            ffvk::scene::MAX_SIZE
        ));
    }
    Ok((w, h))
}

fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    parse_pair(s, ',', "X,Y, e.g. 100,80")
}

fn limits(cli: &Cli) -> ffvk::scene::Limits {
    let mut limits = ffvk::scene::Limits::default();
    limits.asset_roots = cli.allow_root.clone();
    limits.mesh_bytes = cli.max_mesh_mib << 20;
    limits
}

fn options(cli: &Cli) -> RendererOptions {
    let env_validate = std::env::var_os("FFVK_VALIDATION").is_some_and(|v| v != "0");
    if (cli.validate || env_validate) && !ffvk::vk::instance::validation_layer_installed().unwrap_or(true) {
        eprintln!(
            "warning: {}; running without validation",
            ffvk::Error::NoValidationLayer
        );
    }
    let mut options = RendererOptions::default();
    options.device = cli.device.clone();
    options.validation = if cli.validate || env_validate {
        Validation::IfPresent
    } else {
        Validation::Off
    };
    options
}

/// The comparison tolerance (see the README's tolerance policy).
#[derive(clap::Args, Debug, Clone)]
struct ToleranceArgs {
    /// Per-channel difference (of 255) a pixel may have without counting as different.
    #[arg(long, default_value_t = 2)]
    threshold: u8,
    /// Largest share of pixels (0..1) allowed over the threshold.
    #[arg(long, default_value_t = 0.001)]
    max_share: f64,
    /// Largest mean FLIP error (0..1), counted at the pixels over the threshold.
    #[arg(long, default_value_t = 0.005)]
    max_flip: f32,
    /// Count FLIP at every pixel, so that a shift within the threshold can fail an image.
    #[arg(long)]
    flip_all_pixels: bool,
}

impl ToleranceArgs {
    fn tolerance(&self) -> Tolerance {
        let mut tolerance = Tolerance::default();
        tolerance.threshold = self.threshold;
        tolerance.max_share = self.max_share;
        tolerance.max_flip = self.max_flip;
        tolerance.flip_all_pixels = self.flip_all_pixels;
        tolerance
    }
}

fn run(cli: Cli) -> ffvk_cli::Result<ExitCode> {
    match &cli.command {
        Command::Info => {
            let renderer = Renderer::new(&options(&cli))?;
            let i = renderer.device_info();
            println!("device:                  {} ({})", i.name, i.device_type);
            println!("driver:                  {} ({})", i.driver_name, i.driver_info);
            println!("Vulkan API:              {}", i.api_version);
            println!(
                "vendor/device id:        {:#06x}/{:#06x}",
                i.vendor_id, i.device_id
            );
            println!("maxImageDimension2D:     {}", i.max_image_dimension_2d);
            println!("maxUniformBufferRange:   {}", i.max_uniform_buffer_range);
            println!(
                "minUniformBufferOffsetAlignment: {}",
                i.min_uniform_buffer_offset_alignment
            );
            println!("maxVertexOutputComponents: {}", i.max_vertex_output_components);
            println!(
                "timestamps:              {} (period {} ns)",
                i.timestamps_supported, i.timestamp_period_ns
            );
            println!("pipeline statistics:     {}", i.pipeline_statistics_query);
            println!("provoking vertex last:   {}", i.provoking_vertex_last);
            for (usage, chosen) in renderer.memory_choices() {
                let what = match chosen {
                    Some(c) => format!(
                        "type {} ({:?}), heap of {} MiB",
                        c.index,
                        c.flags,
                        c.heap_bytes >> 20
                    ),
                    None => "none acceptable".to_string(),
                };
                println!("memory for {:<16} {what}", format!("{usage:?}:"));
            }
            println!("GL_MAX_LIGHTS:           {}", ffvk::gl::state::MAX_LIGHTS);
            println!(
                "validation layer:        {}",
                if i.validation { "on" } else { "off" }
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::Demo { out } => ffvk_cli::demo::run(&options(&cli), out).map(|()| ExitCode::SUCCESS),
        Command::Bench(args) => {
            let program = std::env::current_exe().map_err(|source| ffvk_cli::Error::Read {
                path: "/proc/self/exe".into(),
                source,
            })?;
            ffvk_cli::bench::run(args, &options(&cli), &program).map(|()| ExitCode::SUCCESS)
        }
        Command::Render {
            scenes,
            out,
            lighting,
            size,
            fragment_path,
            check,
            bless,
            jobs,
            partition,
            junit,
            json,
            report,
            timeout,
            tolerance,
            gltf,
        } => {
            let files = regress::scene_files(scenes)?;
            let paths: Vec<PathBuf> = files.iter().map(|f| f.path.clone()).collect();
            gltf.check(&paths)?;
            let job = regress::Job {
                scenes: scenes.clone(),
                out_dir: out.clone(),
                modes: lighting.clone(),
                size: *size,
                fragment_path: fragment_path.as_deref().map(|p| match p {
                    "deferred" => ffvk::FragmentPath::Deferred,
                    "auto" => ffvk::FragmentPath::Auto,
                    _ => ffvk::FragmentPath::Forward,
                }),
                references: check.clone(),
                bless: *bless || regress::bless_from_env(),
                tolerance: tolerance.tolerance(),
                limits: limits(&cli),
                direct: gltf.options(),
                // Each worker sets its own, from its device.
                driver_family: None,
                partition: *partition,
            };
            if cli.render_worker {
                regress::pool::worker_main(&options(&cli), job)?;
                return Ok(ExitCode::SUCCESS);
            }
            for dir in scenes.iter().filter(|p| p.is_dir()) {
                let meshes = regress::folder_scenes(dir)?.meshes;
                if !meshes.is_empty() {
                    eprintln!(
                        "ffvk: note: {}: its .toml files are the scenes; its {} .gltf/.glb file(s) are \
                         left to them as meshes (give a glTF file by name to draw it directly)",
                        dir.display(),
                        meshes.len()
                    );
                }
            }
            let results_asked = check.is_some() || junit.is_some() || json.is_some() || partition.is_some();
            if files.len() == 1 && lighting.len() <= 1 && !results_asked && !scenes[0].is_dir() {
                return render_one(&cli, &files[0].path, out.as_ref(), &job);
            }
            // Several images (or a folder's): -o is their folder, never a file name.
            if let Some(out) = out
                .as_ref()
                .filter(|o| o.extension().is_some_and(|e| e.eq_ignore_ascii_case("png")))
            {
                return Err(ffvk_cli::Error::Path {
                    path: out.clone(),
                    problem:
                        "names a .png file, but this run writes a folder's images (several scenes, several \
                              lighting modes, results files or a folder given): expected a folder for -o",
                });
            }
            // Results files: not over a scene file, one of the run's images, each other, or
            // into the references.
            let outputs: Vec<(&'static str, &std::path::Path)> =
                [("--junit", junit), ("--json", json), ("--report", report)]
                    .into_iter()
                    .filter_map(|(flag, path)| path.as_deref().map(|p| (flag, p)))
                    .collect();
            let inputs: Vec<&std::path::Path> = scenes
                .iter()
                .map(PathBuf::as_path)
                .chain(files.iter().map(|f| f.path.as_path()))
                .collect();
            let references: Vec<&std::path::Path> = check.iter().map(PathBuf::as_path).collect();
            regress::refuse_overlaps(
                &outputs,
                &inputs,
                &regress::image_paths(&job, &files),
                &references,
            )?;
            if let (Some(dir), Some(refs)) = (report, check) {
                // Refused now rather than after the run.
                regress::report::claim(dir, &[refs.as_path()])?;
            }
            let worker = regress::pool::WorkerCommand {
                program: std::env::current_exe().map_err(|source| ffvk_cli::Error::Read {
                    path: "/proc/self/exe".into(),
                    source,
                })?,
                args: std::iter::once("--render-worker".into())
                    .chain(std::env::args_os().skip(1))
                    .collect(),
            };
            let results = regress::pool::run_suite(
                &job,
                &worker,
                &regress::pool::SuiteOptions {
                    jobs: jobs.map(|j| j as usize),
                    lp_num_threads: None,
                    timeout: std::time::Duration::from_secs_f64(*timeout),
                },
                &mut |m| match m {
                    regress::Message::Wrote { .. } => println!("{m}"),
                    _ => eprintln!("{m}"),
                },
            )?;
            let run = &results.runs[0].info;
            eprintln!(
                "ffvk: {} scene(s){} in {} worker process(es), LP_NUM_THREADS={} each, {:.1} s",
                run.scenes,
                run.partition
                    .map(|p| format!(" (shard {p} of a suite of {})", run.suite_scenes))
                    .unwrap_or_default(),
                run.jobs,
                run.lp_num_threads.as_deref().unwrap_or("unset"),
                run.seconds
            );
            let outputs = Outputs {
                json: json.as_deref(),
                junit: junit.as_deref(),
                report: report.as_deref(),
            };
            finish_results(&results, check.is_some(), &outputs)
        }
        Command::Results { action } => {
            let (files, outputs) = match action {
                ResultsAction::Merge {
                    files,
                    json,
                    junit,
                    report,
                } => (
                    files,
                    Outputs {
                        json: json.as_deref(),
                        junit: junit.as_deref(),
                        report: report.as_deref(),
                    },
                ),
                ResultsAction::Report { files, out } => (
                    files,
                    Outputs {
                        report: Some(out),
                        ..Outputs::default()
                    },
                ),
            };
            let parts = files
                .iter()
                .map(|f| Ok((f.clone(), regress::results::Results::read_json(f)?)))
                .collect::<ffvk_cli::Result<Vec<_>>>()?;
            // The merged files' own rule: not over an input, each other, or the references the
            // runs checked against.
            let written: Vec<(&'static str, &std::path::Path)> = [
                ("--junit", outputs.junit),
                ("--json", outputs.json),
                ("--report", outputs.report),
            ]
            .into_iter()
            .filter_map(|(flag, path)| path.map(|p| (flag, p)))
            .collect();
            let inputs: Vec<&std::path::Path> = files.iter().map(PathBuf::as_path).collect();
            let references: Vec<PathBuf> = parts
                .iter()
                .flat_map(|(_, r)| r.runs.iter().filter_map(|run| run.info.references.clone()))
                .collect();
            let references: Vec<&std::path::Path> = references.iter().map(PathBuf::as_path).collect();
            regress::refuse_overlaps(&written, &inputs, &[], &references)?;
            let merged = regress::results::Results::merge(parts)?;
            let checked = merged.runs.iter().any(|r| r.info.references.is_some());
            if let Some(dir) = outputs.report {
                let references: Vec<&std::path::Path> = merged
                    .runs
                    .iter()
                    .filter_map(|r| r.info.references.as_deref())
                    .collect();
                regress::report::claim(dir, &references)?;
            }
            finish_results(&merged, checked, &outputs)
        }
        Command::Compare {
            expected,
            actual,
            diff,
            tolerance,
        } => {
            let tolerance = tolerance.tolerance();
            tolerance.validate()?;
            if let Some(path) = diff {
                if ffvk::files::same_file(path, expected) || ffvk::files::same_file(path, actual) {
                    return Err(ffvk_cli::Error::OverwritesInput { path: path.clone() });
                }
            }
            let e = compare::load_image(expected)?;
            let a = compare::load_image(actual)?;
            let c = compare::compare(&e, &a, &tolerance).map_err(|source| ffvk_cli::Error::Compare {
                expected: expected.clone(),
                actual: actual.clone(),
                source,
            })?;
            println!("{}", c.summary());
            if let Some(path) = diff {
                save_png(&compare::heat_map(&e, &a, tolerance.threshold)?, path)?;
                println!("diff heat map: {}", path.display());
            }
            if c.passes(&tolerance) {
                println!(
                    "PASS (threshold {}/255, max share {}, max FLIP {})",
                    tolerance.threshold, tolerance.max_share, tolerance.max_flip
                );
                Ok(ExitCode::SUCCESS)
            } else {
                println!(
                    "FAIL (threshold {}/255, max share {}, max FLIP {})",
                    tolerance.threshold, tolerance.max_share, tolerance.max_flip
                );
                Ok(ExitCode::FAILURE)
            }
        }
        Command::Teapot { level, out } => {
            let mesh = ffvk::mesh::teapot::teapot(*level)?;
            ffvk::scene::gltf::write::write_gltf(&mesh, out).map_err(|source| ffvk_cli::Error::Write {
                path: out.clone(),
                source,
            })?;
            println!(
                "wrote {} ({} vertices, {} triangles)",
                out.display(),
                mesh.vertices.len(),
                mesh.triangle_count()
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::Scene {
            gltf,
            out,
            size,
            choices,
        } => write_scene(&cli, gltf, out.as_deref(), *size, choices),
        Command::Explain {
            scene,
            pixel,
            lighting,
            size,
            gltf,
        } => {
            gltf.check(std::slice::from_ref(scene))?;
            let scene = ffvk::scene::open(
                scene,
                *size,
                &limits(&cli),
                &gltf.options(),
                &mut print_note(scene),
            )?;
            let (x, y) = *pixel;
            if x >= scene.width || y >= scene.height {
                return Err(ffvk_cli::Error::PixelOutside {
                    path: scene.path.clone(),
                    pixel: (x, y),
                    size: (scene.width, scene.height),
                });
            }
            let mode = lighting.unwrap_or(scene.state.mode);
            match ffvk_cli::explain::explain(&scene, x, y, mode) {
                Some(text) => print!("{text}"),
                None => println!(
                    "pixel ({x}, {y}): no surface; the clear color {} shows",
                    scene.clear_color
                ),
            }
            // What the GPU drew there, to set beside the reference.
            let mut renderer = Renderer::new(&options(&cli))?;
            let image = render_scene(&mut renderer, &scene, Some(mode))?;
            println!(
                "ffvk on {} drew {:?}",
                renderer.device_info().name,
                image.get_pixel(x, y).0
            );
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// `ffvk scene`: the scene TOML for a glTF file, to stdout or a file.
fn write_scene(
    cli: &Cli,
    gltf: &std::path::Path,
    out: Option<&std::path::Path>,
    size: Option<(u32, u32)>,
    choices: &GltfArgs,
) -> ffvk_cli::Result<ExitCode> {
    if !is_gltf(gltf) {
        return Err(ffvk_cli::Error::Path {
            path: gltf.to_path_buf(),
            problem: "expected a .gltf or .glb file",
        });
    }
    choices.check(&[gltf.to_path_buf()])?;
    let mut options = choices.options();
    options.size = size;
    let reference = ffvk::scene::direct::relative_ref(gltf, out);
    let made = ffvk::scene::direct::from_gltf(gltf, &reference.to_string_lossy(), &limits(cli), &options)?;
    for w in &made.scene.warnings {
        eprintln!("warning: {w}");
    }
    match out {
        None => print!("{}", made.toml),
        Some(path) => {
            if ffvk::files::same_file(path, gltf) {
                return Err(ffvk_cli::Error::OverwritesInput {
                    path: path.to_path_buf(),
                });
            }
            ffvk::files::write_bytes(path, made.toml.as_bytes()).map_err(|source| {
                ffvk_cli::Error::Write {
                    path: path.to_path_buf(),
                    source,
                }
            })?;
            eprintln!("wrote {}", path.display());
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// Renders one scene in one mode in this process (no results asked for).
fn render_one(
    cli: &Cli,
    file: &std::path::Path,
    out: Option<&PathBuf>,
    job: &regress::Job,
) -> ffvk_cli::Result<ExitCode> {
    let path = out.cloned().unwrap_or_else(|| file.with_extension("png"));
    if ffvk::files::same_file(&path, file) {
        return Err(ffvk_cli::Error::OverwritesInput { path });
    }
    // As a worker of a suite renders it (pool::worker_main).
    let mut renderer_options = options(cli);
    renderer_options.specialize = ffvk::Specialize::Always;
    let mut renderer = Renderer::new(&renderer_options)?;
    let scene = ffvk::scene::open(file, job.size, &job.limits, &job.direct, &mut print_note(file))?;
    let image = ffvk::scene::render_scene_with(
        &mut renderer,
        &scene,
        job.modes.first().copied(),
        job.fragment_path,
    )?;
    save_png(&image, &path)?;
    println!("{} -> {}", file.display(), path.display());
    Ok(ExitCode::SUCCESS)
}

/// The files a run's results are written to.
#[derive(Default)]
struct Outputs<'a> {
    json: Option<&'a std::path::Path>,
    junit: Option<&'a std::path::Path>,
    /// The HTML report's folder.
    report: Option<&'a std::path::Path>,
}

/// Writes the results files asked for, prints the summary and exits as documented: 2 on an
/// error, else 1 on a difference or missing reference, else 0.
fn finish_results(
    results: &regress::results::Results,
    checked: bool,
    outputs: &Outputs,
) -> ffvk_cli::Result<ExitCode> {
    if let Some(path) = outputs.json {
        results.write_json(path)?;
        eprintln!("wrote {}", path.display());
    }
    if let Some(path) = outputs.junit {
        regress::junit::write(results, path)?;
        eprintln!("wrote {}", path.display());
    }
    if let Some(dir) = outputs.report {
        let written = regress::report::write(results, dir)?;
        for problem in &written.unreadable {
            eprintln!("ffvk: report: {problem}");
        }
        eprintln!(
            "wrote {} ({} image(s) to look at)",
            written.page.display(),
            written.entries
        );
    }
    let rows = results.rows();
    println!("{}", regress::summary(&rows, checked));
    Ok(ExitCode::from(results.counts().exit_code()))
}

/// Prints what opening the scene at `path` noted, as a suite's log does: a choice after the
/// file's path, a warning as it is.
fn print_note(path: &std::path::Path) -> impl FnMut(ffvk::scene::OpenNote) + '_ {
    move |note| match note {
        ffvk::scene::OpenNote::Chose { .. } => eprintln!("{}: {note}", path.display()),
        _ => eprintln!("{note}"),
    }
}

fn main() -> ExitCode {
    // Output piped into a reader that stops early (`ffvk compare … | head -1`) ends ffvk as it
    // ends other Unix tools, instead of a panic in println! on EPIPE (Rust ignores SIGPIPE).
    // SAFETY: called first, before any thread exists; SIG_DFL is a valid disposition.
    unsafe { libc::signal(libc::SIGPIPE, libc::SIG_DFL) };
    // A write past a file-size limit (ulimit -f, prlimit --fsize) fails with EFBIG, which the
    // writer turns into an error that removes its temporary file, instead of SIGXFSZ killing
    // the process with the temporary file left behind (worker processes inherit this).
    // SAFETY: as above; SIG_IGN is a valid disposition.
    unsafe { libc::signal(libc::SIGXFSZ, libc::SIG_IGN) };
    match run(Cli::parse()) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("ffvk: error: {e}");
            // 2, not 1: 1 means a comparison ran and found a difference.
            ExitCode::from(2)
        }
    }
}
