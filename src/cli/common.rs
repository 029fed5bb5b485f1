//! What every command shares: the global options (device, validation, limits), the parsers
//! of sizes, pixels and seconds, the comparison tolerance, and how a scene's notes print.

use std::path::PathBuf;

use ffvk::images::compare::Tolerance;
use ffvk::vk::Validation;
use ffvk::RendererOptions;

/// The options every command takes.
#[derive(clap::Args, Debug, Clone)]
pub(crate) struct Global {
    /// Use the Vulkan device whose name contains this text (default: lavapipe).
    #[arg(long, global = true)]
    pub(crate) device: Option<String>,
    /// Load VK_LAYER_KHRONOS_validation when installed (warn when it is not).
    #[arg(long, global = true)]
    pub(crate) validate: bool,
    /// The host memory a scene's meshes may take, in MiB (the device holds as much again).
    #[arg(long, global = true, value_name = "MIB", default_value_t = ffvk::scene::DEFAULT_MESH_BYTES >> 20,
          value_parser = parse_mib, allow_negative_numbers = true)]
    pub(crate) max_mesh_mib: u64,
    /// The host memory a scene's decoded textures may take, in MiB (RGBA8 with mipmaps,
    /// counted from each image's header before it is decoded).
    #[arg(long, global = true, value_name = "MIB", default_value_t = ffvk::scene::DEFAULT_TEXTURE_BYTES >> 20,
          value_parser = parse_mib, allow_negative_numbers = true)]
    pub(crate) max_texture_mib: u64,
    /// The host memory one glTF file's buffers may take, in MiB (files, data URIs, the GLB
    /// chunk and meshopt fallback buffers together).
    #[arg(long, global = true, value_name = "MIB", default_value_t = ffvk::scene::DEFAULT_BUFFER_BYTES >> 20,
          value_parser = parse_mib, allow_negative_numbers = true)]
    pub(crate) max_buffer_mib: u64,
    /// The mesh placements a scene may have, each counted by the nodes on its path.
    #[arg(long, global = true, value_name = "N", default_value_t = ffvk::scene::DEFAULT_PLACEMENTS,
          value_parser = parse_count, allow_negative_numbers = true)]
    pub(crate) max_placements: u64,
    /// Let glTF buffer URIs reach files inside DIR too (by default only the glTF file's own
    /// folder); may be given more than once.
    #[arg(long, global = true, value_name = "DIR")]
    pub(crate) allow_root: Vec<PathBuf>,
    /// Run as a worker process of `render --jobs` (started by ffvk itself).
    #[arg(long, hide = true)]
    pub(crate) render_worker: bool,
}

impl Global {
    /// The scene limits these options set.
    pub(crate) fn limits(&self) -> ffvk::scene::Limits {
        let mut limits = ffvk::scene::Limits::default();
        limits.asset_roots = self.allow_root.clone();
        limits.mesh_bytes = self.max_mesh_mib << 20;
        limits.texture_bytes = self.max_texture_mib << 20;
        limits.buffer_bytes = self.max_buffer_mib << 20;
        limits.placements = self.max_placements;
        limits
    }

    /// The renderer options these options set (validation also from FFVK_VALIDATION).
    pub(crate) fn options(&self) -> RendererOptions {
        let env_validate = std::env::var_os("FFVK_VALIDATION").is_some_and(|v| v != "0");
        if (self.validate || env_validate)
            && !ffvk::vk::instance::validation_layer_installed().unwrap_or(true)
        {
            ffvk_cli::errln!(
                "warning: {}; running without validation",
                ffvk::Error::NoValidationLayer
            );
        }
        let mut options = RendererOptions::default();
        options.device = self.device.clone();
        options.validation = if self.validate || env_validate {
            Validation::IfPresent
        } else {
            Validation::Off
        };
        options
    }
}

/// `--max-mesh-mib`, `--max-texture-mib`, `--max-buffer-mib`: a whole number of MiB, 1 to 2^24 (16 TiB).
fn parse_mib(s: &str) -> Result<u64, String> {
    const MAX: u64 = 1 << 24;
    match s.trim().parse::<u64>() {
        Ok(n) if (1..=MAX).contains(&n) => Ok(n),
        _ => Err(format!("{s:?}: expected a whole number of MiB in 1..={MAX}")),
    }
}

/// `--max-placements`: a whole number, 1 to 2^24 (each counted placement keeps a node's name,
/// about 60 bytes: 2^24 of them are about 1 GiB).
fn parse_count(s: &str) -> Result<u64, String> {
    const MAX: u64 = 1 << 24;
    match s.trim().parse::<u64>() {
        Ok(n) if (1..=MAX).contains(&n) => Ok(n),
        _ => Err(format!("{s:?}: expected a whole number in 1..={MAX}")),
    }
}

/// A share or a mean error: a number from 0 to 1.
fn parse_unit(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if (0.0..=1.0).contains(&x) => Ok(x),
        _ => Err(format!("{s:?}: expected a number from 0 to 1")),
    }
}

fn parse_share(s: &str) -> Result<f64, String> {
    parse_unit(s)
}

fn parse_flip(s: &str) -> Result<f32, String> {
    parse_unit(s).map(|x| x as f32)
}

/// Refuses an output path whose name does not end in `.EXTENSION` (in any case), so that a
/// file's name says what it holds: `problem` says what the command writes and what it
/// expected, e.g. "ffvk teapot writes glTF: expected a .gltf path".
pub(crate) fn expect_extension(
    path: &std::path::Path,
    extension: &str,
    problem: &'static str,
) -> ffvk_cli::Result<()> {
    if path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(extension))
    {
        Ok(())
    } else {
        Err(ffvk_cli::Error::Path {
            path: path.to_path_buf(),
            problem,
        })
    }
}

pub(crate) fn parse_seconds(s: &str) -> Result<f64, String> {
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

pub(crate) fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = parse_pair(s, 'x', "WIDTHxHEIGHT, e.g. 512x512")?;
    if w == 0 || h == 0 || w > ffvk::scene::MAX_SIZE || h > ffvk::scene::MAX_SIZE {
        return Err(format!(
            "{s:?}: expected each side in 1..={}",
            ffvk::scene::MAX_SIZE
        ));
    }
    Ok((w, h))
}

pub(crate) fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    parse_pair(s, ',', "X,Y, e.g. 100,80")
}

/// The comparison tolerance (see docs/regression.md, "Tolerance policy").
#[derive(clap::Args, Debug, Clone)]
pub(crate) struct ToleranceArgs {
    /// Per-channel difference (of 255) a pixel may have without counting as different.
    #[arg(long, default_value_t = 2, allow_negative_numbers = true)]
    pub(crate) threshold: u8,
    /// Largest share of pixels (0..1) allowed over the threshold.
    #[arg(long, default_value_t = 0.001, value_parser = parse_share, allow_negative_numbers = true)]
    pub(crate) max_share: f64,
    /// Largest mean FLIP error (0..1), counted at the pixels over the threshold.
    #[arg(long, default_value_t = 0.005, value_parser = parse_flip, allow_negative_numbers = true)]
    pub(crate) max_flip: f32,
    /// Count FLIP at every pixel, so that a shift within the threshold can fail an image.
    #[arg(long)]
    pub(crate) flip_all_pixels: bool,
}

impl ToleranceArgs {
    pub(crate) fn tolerance(&self) -> Tolerance {
        let mut tolerance = Tolerance::default();
        tolerance.threshold = self.threshold;
        tolerance.max_share = self.max_share;
        tolerance.max_flip = self.max_flip;
        tolerance.flip_all_pixels = self.flip_all_pixels;
        tolerance
    }
}

/// Prints what opening the scene at `path` noted, as a suite's log does: a choice after the
/// file's path, a warning as it is.
pub(crate) fn print_note(path: &std::path::Path) -> impl FnMut(ffvk::scene::OpenNote) + '_ {
    move |note| match note {
        ffvk::scene::OpenNote::Chose { .. } => ffvk_cli::errln!("{}: {note}", path.display()),
        ffvk::scene::OpenNote::Warning { text, times } => ffvk_cli::errln!(
            "{}",
            ffvk::scene::OpenNote::Warning {
                text: &ffvk_cli::named_by(path, text),
                times
            }
        ),
        _ => ffvk_cli::errln!("{note}"),
    }
}
