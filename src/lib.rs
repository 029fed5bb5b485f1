//! `ffvk-cli`: the tools behind the `ffvk` command line (`src/main.rs`), built on the `ffvk`
//! library: the benchmark, the demo, the per-pixel explanation, regression runs and their
//! report, contact sheets and the tables they print, and the GL reference (fixed-function
//! OpenGL through EGL). They print, read arguments and set environment variables; the library
//! does none of that. A library target of its own so that the test suite can reach them.

pub mod bench;
pub mod console;
pub mod demo;
pub mod explain;
pub mod gl_reference;
pub mod gltf_args;
pub mod regress;
pub mod sheet;
pub mod table;

use std::path::PathBuf;

/// Why a tool failed: an error of one of the layers below it, or of the tool itself.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The renderer, the device or the GL state.
    #[error(transparent)]
    Core(#[from] ffvk::Error),

    /// A PNG that could not be read or written.
    #[error(transparent)]
    Image(#[from] ffvk::images::ImageError),

    /// Two images of different sizes.
    #[error(transparent)]
    Size(#[from] ffvk::images::compare::SizeMismatch),

    /// A scene file (or its glTF) that could not be loaded. Boxed: scene errors are large.
    #[error(transparent)]
    Scene(Box<ffvk::scene::SceneError>),

    /// A file or folder that could not be read.
    #[error("cannot read {}: {source}", .path.display())]
    Read { path: PathBuf, source: std::io::Error },

    /// A file that could not be written.
    #[error("cannot write {}: {source}", .path.display())]
    Write { path: PathBuf, source: std::io::Error },

    /// Standard output that could not take what was printed (a full disk, a closed
    /// descriptor): see [`console`].
    #[error("stdout: {0}")]
    Stdout(std::io::Error),

    /// A benchmark report that could not be serialized.
    #[error("cannot write {}: {source}", .path.display())]
    Json {
        path: PathBuf,
        source: serde_json::Error,
    },

    /// A plot that could not be drawn (plotters reports its errors as text).
    #[error("cannot draw the plot {}: {message}", .path.display())]
    Plot { path: PathBuf, message: String },

    /// Two images given for comparison that differ in size.
    #[error("{} and {}: {source}", .expected.display(), .actual.display())]
    Compare {
        expected: PathBuf,
        actual: PathBuf,
        source: ffvk::images::compare::SizeMismatch,
    },

    /// A pixel asked for outside the scene's image.
    #[error(
        "{}: --pixel {},{} is outside the {}x{} image: expected x < {} and y < {}",
        .path.display(), .pixel.0, .pixel.1, .size.0, .size.1, .size.0, .size.1
    )]
    PixelOutside {
        path: PathBuf,
        pixel: (u32, u32),
        size: (u32, u32),
    },

    /// Two scenes of one run would write the same image.
    #[error("{} and {} would both write the image {name}.png: expected scene names that differ (in a folder run, images mirror the scenes' paths below the folder)", .first.display(), .second.display())]
    NameClash {
        name: String,
        first: PathBuf,
        second: PathBuf,
    },

    /// Outputs would be written into the reference folder.
    #[error("the output folder {} is, or lies inside, the reference folder {}: references are read-only unless blessed; expected --out outside it", .output.display(), .references.display())]
    OutputInReferences { output: PathBuf, references: PathBuf },

    /// A report folder that is, lies inside or holds a reference folder.
    #[error("the report folder {} is, lies inside or holds the reference folder {}: references are read-only unless blessed; expected a report folder apart from them", .report.display(), .references.display())]
    ReportInReferences { report: PathBuf, references: PathBuf },

    /// An output file would land in the reference folder: a run's image (a reference folder
    /// nested inside the output folder), `--json`, `--junit`.
    #[error("{} lies inside the reference folder {}: references are read-only unless blessed; expected {what} outside it", .output.display(), .references.display())]
    FileInReferences {
        /// The file that would be written.
        output: PathBuf,
        /// The reference folder.
        references: PathBuf,
        /// What it is (`the run's images`, `--json`, …).
        what: &'static str,
    },

    /// Two outputs of one command name the same file.
    #[error("{first} and {second} both name {}: expected a file for each", .path.display())]
    SameOutput {
        /// The first option.
        first: &'static str,
        /// The second option.
        second: &'static str,
        /// The file.
        path: PathBuf,
    },

    /// An output would replace one of the command's own inputs (the same file after links,
    /// however either is spelled). Nothing was written.
    #[error("{}: is {}, a file this run reads: refused, nothing written; expected an output path that is not one of the run's inputs", .path.display(), .input.display())]
    OverwritesInput {
        /// The output as given.
        path: PathBuf,
        /// The input it would replace, as read.
        input: PathBuf,
    },

    /// A folder a command replaces whole (a report's `images/`) holds one of its inputs.
    #[error("{}: holds {}, a file this run reads, and the report replaces this folder whole: refused, nothing written; expected a report folder apart from the run's inputs", .folder.display(), .input.display())]
    FolderHoldsInput {
        /// The folder.
        folder: PathBuf,
        /// The input inside it.
        input: PathBuf,
    },

    /// A tolerance out of its range.
    #[error(transparent)]
    Tolerance(#[from] ffvk::images::compare::ToleranceError),

    /// A path argument that names the wrong kind of thing.
    #[error("{}: {problem}", .path.display())]
    Path { path: PathBuf, problem: &'static str },

    /// A command-line option's value that is wrong only with the others (clap checks each
    /// alone): the option, its value and what was expected.
    #[error("{0}")]
    Argument(String),

    /// The embedded label font could not be used (a build defect).
    #[error("cannot draw labels: {message}")]
    Font { message: String },

    /// A benchmark that cannot run as asked.
    #[error("benchmark: {0}")]
    Bench(String),

    /// Results files that cannot be read or merged.
    #[error(transparent)]
    Merge(#[from] regress::results::MergeError),

    /// A regression run's worker processes that could not start or be talked to.
    #[error(transparent)]
    Worker(#[from] regress::pool::WorkerError),

    /// The GL reference renderer (fixed-function OpenGL through EGL): no GL driver, or a
    /// render that failed. Its messages start with "no GL driver:" or "GL reference:".
    #[error(transparent)]
    Gl(#[from] gl_reference::GlError),
}

impl From<ffvk::scene::SceneError> for Error {
    fn from(e: ffvk::scene::SceneError) -> Self {
        Error::Scene(Box::new(e))
    }
}

impl From<ffvk::error::MeshError> for Error {
    fn from(e: ffvk::error::MeshError) -> Self {
        Error::Core(e.into())
    }
}

impl From<ffvk::gl::state::StateError> for Error {
    fn from(e: ffvk::gl::state::StateError) -> Self {
        Error::Core(e.into())
    }
}

/// Writes `bytes` to `path` atomically ([`ffvk::files::write_bytes`]), the error naming the
/// path.
pub(crate) fn write_file(path: &std::path::Path, bytes: &[u8]) -> Result<()> {
    ffvk::files::write_bytes(path, bytes).map_err(|source| Error::Write {
        path: path.to_path_buf(),
        source,
    })
}

/// `text` named by the file it is about, as a warning of one scene among many is printed:
/// `PATH: text`, unless it names the file already.
pub fn named_by(path: &std::path::Path, text: &str) -> String {
    let name = path.display().to_string();
    if text.starts_with(&name) {
        text.to_owned()
    } else {
        format!("{name}: {text}")
    }
}

/// Result with the tools' [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;
