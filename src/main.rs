//! The `ffvk` command line: parses the arguments and dispatches each command to its module
//! under `cli/`.

mod cli;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use cli::common::Global;

#[derive(Parser)]
#[command(
    name = "ffvk",
    version,
    about = "The OpenGL 2.1 fixed-function lighting equation, verbatim, on Vulkan"
)]
struct Cli {
    #[command(flatten)]
    global: Global,
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
    Render(cli::render::RenderArgs),
    /// Results files of `render --json`: merge the shards of a partitioned run.
    Results {
        #[command(subcommand)]
        action: cli::results::ResultsAction,
    },
    /// Print the scene TOML ffvk draws a glTF file with (camera, lights, glTF's meaning), as
    /// the start of a hand-tuned scene.
    Scene {
        /// A .gltf or .glb file.
        gltf: PathBuf,
        /// Write the scene here (its glTF path made relative to it) instead of to stdout.
        #[arg(short, long)]
        out: Option<PathBuf>,
        #[arg(long, value_parser = cli::common::parse_size, allow_hyphen_values = true)]
        size: Option<(u32, u32)>,
        #[command(flatten)]
        choices: ffvk_cli::gltf_args::GltfArgs,
    },
    /// Compare two images: per-channel differences, share over a threshold, FLIP.
    Compare(cli::compare::CompareArgs),
    /// Write the Utah teapot (Newell's patches) as a glTF file.
    Teapot {
        /// Tessellation level: each patch becomes LEVEL×LEVEL quads.
        #[arg(long, default_value_t = 8, allow_negative_numbers = true,
              value_parser = clap::value_parser!(u32).range(1..=i64::from(ffvk::mesh::teapot::MAX_LEVEL)))]
        level: u32,
        #[arg(short, long, default_value = "assets/teapot.gltf")]
        out: PathBuf,
    },
    /// Print every term of the lighting equation at one pixel (CPU reference).
    Explain(cli::scene::ExplainArgs),
}

/// Runs the command `cli` names.
fn run(cli: Cli) -> ffvk_cli::Result<ExitCode> {
    let global = &cli.global;
    let done = |r: ffvk_cli::Result<()>| r.map(|()| ExitCode::SUCCESS);
    match &cli.command {
        Command::Info => cli::info::run(global),
        Command::Demo { out } => done(ffvk_cli::demo::run(&global.options(), out)),
        Command::Bench(args) => {
            let program = std::env::current_exe().map_err(|source| ffvk_cli::Error::Read {
                path: "/proc/self/exe".into(),
                source,
            })?;
            done(ffvk_cli::bench::run(args, &global.options(), &program))
        }
        Command::Render(args) => cli::render::run(global, args),
        Command::Results { action } => cli::results::run(action),
        Command::Scene {
            gltf,
            out,
            size,
            choices,
        } => cli::scene::write_scene(global, gltf, out.as_deref(), *size, choices),
        Command::Compare(args) => cli::compare::run(args),
        Command::Teapot { level, out } => cli::scene::teapot(level, out),
        Command::Explain(args) => cli::scene::explain(global, args),
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
    // Nothing ffvk writes lands on a file it read (a scene's texture, a glTF buffer, a
    // reference), however the output is spelled; an interrupted write leaves no temporary file.
    ffvk::files::protect_inputs(true);
    ffvk::files::remove_temporaries_on_signals();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        // --help, --version and usage errors, as clap prints them; a failed write of them (a
        // full stdout) is an error too, not a silent success.
        Err(e) => {
            use std::io::Write;
            let printed = e.print().and_then(|()| std::io::stdout().flush());
            return match printed {
                Ok(()) => ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2)),
                Err(io) => {
                    ffvk_cli::errln!("ffvk: error: stdout: {io}");
                    ExitCode::from(2)
                }
            };
        }
    };
    // Stale temporary files are swept where every input of the run is known: here, or in the
    // parent of a suite's workers (which know only their own scenes').
    ffvk::files::sweep_on_write(!cli.global.render_worker);
    match run(cli) {
        Ok(code) => code,
        Err(e) => {
            ffvk_cli::errln!("ffvk: error: {e}");
            // 2, not 1: 1 means a comparison ran and found a difference.
            ExitCode::from(2)
        }
    }
}
