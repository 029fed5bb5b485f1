//! `ffvk render`: one scene or glTF file to a PNG, or a suite (folders, several modes,
//! references, results files) in worker processes.

use std::path::PathBuf;
use std::process::ExitCode;

use ffvk::gl::state::LightingMode;
use ffvk::images::save_png;
use ffvk::Renderer;
use ffvk_cli::gltf_args::GltfArgs;
use ffvk_cli::regress;

use super::common::{expect_extension, parse_seconds, parse_size, print_note, Global, ToleranceArgs};

/// `ffvk render`'s options.
#[derive(clap::Args, Debug, Clone)]
pub(crate) struct RenderArgs {
    /// Scene files (.toml), glTF files (.gltf, .glb: drawn with the scene `ffvk scene`
    /// prints) or directories: their *.toml files below them, in path order, or where
    /// there is none their *.gltf and *.glb files (a folder of models is a suite too).
    #[arg(required = true)]
    pub(crate) scenes: Vec<PathBuf>,
    /// Output PNG when rendering one scene or glTF file in one mode; otherwise a folder
    /// (NAME.png each; a name ending in .png is refused). Without -o each image lands
    /// beside its scene or glTF file, as NAME.png.
    #[arg(short, long)]
    pub(crate) out: Option<PathBuf>,
    /// Override the scenes' lighting mode; a comma list renders each (NAME_MODE.png).
    #[arg(long, value_delimiter = ',')]
    pub(crate) lighting: Vec<LightingMode>,
    /// Override the image size, as WxH (the vertical field of view is kept).
    #[arg(long, value_parser = parse_size, allow_hyphen_values = true)]
    pub(crate) size: Option<(u32, u32)>,
    /// Draw the fragment mode forward (at every fragment), deferred (once per pixel,
    /// where a frame allows it) or auto (deferred where ffvk's fixed rule of vertices,
    /// pixels, lights and device type says it is faster): overrides the scenes'
    /// `[image] fragment_path`.
    #[arg(long, value_parser = ["forward", "deferred", "auto"])]
    pub(crate) fragment_path: Option<String>,
    /// Check each image against DIR/NAME.png and print a summary table; exit 1 on a
    /// difference past the tolerance or a missing reference.
    #[arg(long, value_name = "DIR")]
    pub(crate) check: Option<PathBuf>,
    /// Write missing or changed references into the --check directory (also FFVK_BLESS=1).
    #[arg(long, requires = "check")]
    pub(crate) bless: bool,
    /// Worker processes to render in (default: one per CPU). A worker that crashes costs
    /// only the scene it was rendering, which becomes an error row.
    #[arg(short, long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024),
          allow_negative_numbers = true)]
    pub(crate) jobs: Option<u32>,
    /// Render only shard K of N: the scenes whose name (path below the folder given)
    /// hashes to K; the N shards together are the whole suite (see `ffvk results merge`).
    #[arg(long, value_name = "K/N", allow_hyphen_values = true)]
    pub(crate) partition: Option<regress::Partition>,
    /// Write the results as JUnit XML (one test case per scene and mode).
    #[arg(long, value_name = "FILE")]
    pub(crate) junit: Option<PathBuf>,
    /// Write the results as JSON (what `ffvk results merge` reads).
    #[arg(long, value_name = "FILE")]
    pub(crate) json: Option<PathBuf>,
    /// Write an HTML report into DIR (index.html): the failed, missing, errored and
    /// blessed images worst first, each with its reference, difference maps and figures.
    #[arg(long, value_name = "DIR", requires = "check")]
    pub(crate) report: Option<PathBuf>,
    /// Seconds one scene (all its modes) may take before its worker is killed and the
    /// scene reported as an error.
    #[arg(long, value_name = "SECONDS", default_value_t = 600.0, value_parser = parse_seconds,
          allow_negative_numbers = true)]
    pub(crate) timeout: f64,
    #[command(flatten)]
    pub(crate) tolerance: ToleranceArgs,
    #[command(flatten)]
    pub(crate) gltf: GltfArgs,
}

/// Renders what `args` asks for (see [`RenderArgs`]).
pub(crate) fn run(global: &Global, args: &RenderArgs) -> ffvk_cli::Result<ExitCode> {
    let RenderArgs {
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
    } = args;
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
        limits: global.limits(),
        direct: gltf.options(),
        // Each worker sets its own, from its device.
        driver_family: None,
        partition: *partition,
    };
    if global.render_worker {
        regress::note_inputs(&job, &files);
        regress::pool::worker_main(&global.options(), job)?;
        return Ok(ExitCode::SUCCESS);
    }
    for dir in scenes.iter().filter(|p| p.is_dir()) {
        let meshes = regress::folder_scenes(dir)?.meshes;
        if !meshes.is_empty() {
            ffvk_cli::errln!(
                "ffvk: note: {}: its .toml files are the scenes; its {} .gltf/.glb file(s) are \
                 left to them as meshes (give a glTF file by name to draw it directly)",
                dir.display(),
                meshes.len()
            );
        }
    }
    let results_asked = check.is_some() || junit.is_some() || json.is_some() || partition.is_some();
    if let Some((i, mode)) = lighting
        .iter()
        .enumerate()
        .find(|(i, m)| lighting[..*i].contains(m))
    {
        return Err(ffvk_cli::Error::Argument(format!(
            "--lighting names {} twice (at {} and {}): expected each mode once, as each writes its own image",
            mode.name(),
            lighting.iter().position(|m| m == mode).unwrap_or(0) + 1,
            i + 1
        )));
    }
    if files.len() == 1 && lighting.len() <= 1 && !results_asked && !scenes[0].is_dir() {
        let image = out.clone().unwrap_or_else(|| files[0].path.with_extension("png"));
        regress::refuse_writing_inputs(&job, &files, &[image.as_path()], false)?;
        return render_one(global, &files[0].path, out.as_ref(), &job);
    }
    // Several images (or a folder's): -o is their folder, never a file name.
    if let Some(out) = out
        .as_ref()
        .filter(|o| o.extension().is_some_and(|e| e.eq_ignore_ascii_case("png")))
    {
        return Err(ffvk_cli::Error::Path {
            path: out.clone(),
            problem: "names a .png file, but this run writes a folder's images (several scenes, several \
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
    let named: Vec<&std::path::Path> = outputs.iter().map(|(_, p)| *p).collect();
    regress::refuse_writing_inputs(&job, &files, &named, true)?;
    // The workers write the images without sweeping: this process knows every input.
    // One pass over each folder, however many images it gets.
    let mut folders: std::collections::BTreeMap<PathBuf, Vec<String>> = Default::default();
    for image in regress::image_paths(&job, &files) {
        if let (Some(dir), Some(name)) = (image.parent(), image.file_name()) {
            let dir = if dir.as_os_str().is_empty() {
                std::path::Path::new(".")
            } else {
                dir
            };
            folders
                .entry(dir.to_path_buf())
                .or_default()
                .push(name.to_string_lossy().into_owned());
        }
    }
    for (dir, names) in &folders {
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        ffvk::files::sweep_stale_temporaries(dir, &names);
    }
    regress::refuse_overlaps(
        &outputs,
        &inputs,
        &regress::image_paths(&job, &files),
        &references,
    )?;
    expect_results_names(json.as_deref(), junit.as_deref())?;
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
    let mut stdout_failed = None;
    let results = regress::pool::run_suite(
        &job,
        &worker,
        &regress::pool::SuiteOptions {
            jobs: jobs.map(|j| j as usize),
            lp_num_threads: None,
            timeout: std::time::Duration::from_secs_f64(*timeout),
        },
        &mut |m| match m {
            // The first failed write ends the run once the suite is done.
            regress::Message::Wrote { .. } => {
                if stdout_failed.is_none() {
                    stdout_failed = ffvk_cli::outln!("{m}").err();
                }
            }
            _ => ffvk_cli::errln!("{m}"),
        },
    )?;
    if let Some(e) = stdout_failed {
        return Err(e);
    }
    let run = &results.runs[0].info;
    ffvk_cli::errln!(
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

/// Renders one scene in one mode in this process (no results asked for).
fn render_one(
    global: &Global,
    file: &std::path::Path,
    out: Option<&PathBuf>,
    job: &regress::Job,
) -> ffvk_cli::Result<ExitCode> {
    if let Some(out) = out {
        expect_extension(
            out,
            "png",
            "ffvk render writes one scene's image in one mode here: expected a .png path (a folder \
             only for several images, modes or results files)",
        )?;
    }
    let path = out.cloned().unwrap_or_else(|| file.with_extension("png"));
    // As a worker of a suite renders it (pool::worker_main).
    let mut renderer_options = global.options();
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
    ffvk_cli::outln!("{} -> {}", file.display(), path.display())?;
    Ok(ExitCode::SUCCESS)
}

/// Refuses a `--json` path not named `.json` and a `--junit` path not named `.xml`.
pub(crate) fn expect_results_names(
    json: Option<&std::path::Path>,
    junit: Option<&std::path::Path>,
) -> ffvk_cli::Result<()> {
    if let Some(path) = json {
        expect_extension(
            path,
            "json",
            "--json writes the results as JSON: expected a .json path",
        )?;
    }
    if let Some(path) = junit {
        expect_extension(path, "xml", "--junit writes JUnit XML: expected a .xml path")?;
    }
    Ok(())
}

/// The files a run's results are written to.
#[derive(Default)]
pub(crate) struct Outputs<'a> {
    pub(crate) json: Option<&'a std::path::Path>,
    pub(crate) junit: Option<&'a std::path::Path>,
    /// The HTML report's folder.
    pub(crate) report: Option<&'a std::path::Path>,
}

/// Writes the results files asked for, prints the summary and exits as documented: 2 on an
/// error, else 1 on a difference or missing reference, else 0.
pub(crate) fn finish_results(
    results: &regress::results::Results,
    checked: bool,
    outputs: &Outputs,
) -> ffvk_cli::Result<ExitCode> {
    if let Some(path) = outputs.json {
        results.write_json(path)?;
        ffvk_cli::errln!("wrote {}", path.display());
    }
    if let Some(path) = outputs.junit {
        regress::junit::write(results, path)?;
        ffvk_cli::errln!("wrote {}", path.display());
    }
    if let Some(dir) = outputs.report {
        let written = regress::report::write(results, dir)?;
        for problem in &written.unreadable {
            ffvk_cli::errln!("ffvk: report: {problem}");
        }
        ffvk_cli::errln!(
            "wrote {} ({} image(s) to look at)",
            written.page.display(),
            written.entries
        );
    }
    let rows = results.rows();
    ffvk_cli::outln!("{}", regress::summary(&rows, checked))?;
    Ok(ExitCode::from(results.counts().exit_code()))
}
