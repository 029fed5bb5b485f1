//! The commands about one scene: `ffvk scene` (the TOML a glTF file is drawn with),
//! `ffvk explain` (every term at one pixel) and `ffvk teapot`.

use std::path::PathBuf;
use std::process::ExitCode;

use ffvk::gl::state::LightingMode;
use ffvk::scene::direct::is_gltf;
use ffvk::scene::render_scene;
use ffvk::Renderer;
use ffvk_cli::gltf_args::GltfArgs;

use super::common::{expect_extension, parse_pixel, parse_size, print_note, Global};

/// `ffvk explain`'s options.
#[derive(clap::Args, Debug, Clone)]
pub(crate) struct ExplainArgs {
    /// A scene file (.toml) or a glTF file (.gltf, .glb), as `render` takes it.
    pub(crate) scene: PathBuf,
    /// The pixel, as X,Y from the top-left corner.
    #[arg(long, value_parser = parse_pixel, allow_hyphen_values = true)]
    pub(crate) pixel: (u32, u32),
    /// Explain the pixel as this lighting mode draws it (vertex, fragment or flat)
    /// instead of the scene's own mode.
    #[arg(long)]
    pub(crate) lighting: Option<LightingMode>,
    /// The image size, as WxH, as `render --size` sets it (the vertical field of view is
    /// kept): the pixel is in that image.
    #[arg(long, value_parser = parse_size, allow_hyphen_values = true)]
    pub(crate) size: Option<(u32, u32)>,
    #[command(flatten)]
    pub(crate) gltf: GltfArgs,
}

/// Prints every term of the equation at the pixel `args` names.
pub(crate) fn explain(global: &Global, args: &ExplainArgs) -> ffvk_cli::Result<ExitCode> {
    let ExplainArgs {
        scene,
        pixel,
        lighting,
        size,
        gltf,
    } = args;
    gltf.check(std::slice::from_ref(scene))?;
    let scene = ffvk::scene::open(
        scene,
        *size,
        &global.limits(),
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
        Some(text) => ffvk_cli::out!("{text}"),
        None => ffvk_cli::outln!(
            "pixel ({x}, {y}): no surface; the clear color {} shows",
            scene.clear_color
        ),
    }?;
    // What the GPU drew there, to set beside the reference.
    let mut renderer = Renderer::new(&global.options())?;
    let image = render_scene(&mut renderer, &scene, Some(mode))?;
    ffvk_cli::outln!(
        "ffvk on {} drew {:?}",
        renderer.device_info().name,
        image.get_pixel(x, y).0
    )?;
    Ok(ExitCode::SUCCESS)
}

/// Writes the Utah teapot at tessellation `level` to `out`.
pub(crate) fn teapot(level: &u32, out: &std::path::Path) -> ffvk_cli::Result<ExitCode> {
    expect_extension(
        out,
        "gltf",
        "ffvk teapot writes glTF (JSON, its buffer embedded): expected a .gltf path",
    )?;
    let mesh = ffvk::mesh::teapot::teapot(*level)?;
    ffvk::scene::gltf::write::write_gltf(&mesh, out).map_err(|source| ffvk_cli::Error::Write {
        path: out.to_path_buf(),
        source,
    })?;
    ffvk_cli::outln!(
        "wrote {} ({} vertices, {} triangles)",
        out.display(),
        mesh.vertices.len(),
        mesh.triangle_count()
    )?;
    Ok(ExitCode::SUCCESS)
}

pub(crate) fn write_scene(
    global: &Global,
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
    if let Some(path) = out {
        expect_extension(
            path,
            "toml",
            "ffvk scene writes scene TOML: expected a .toml path",
        )?;
    }
    choices.check(&[gltf.to_path_buf()])?;
    let mut options = choices.options();
    options.size = size;
    let reference = ffvk::scene::direct::relative_ref(gltf, out);
    let made =
        ffvk::scene::direct::from_gltf(gltf, &reference.to_string_lossy(), &global.limits(), &options)?;
    for w in &made.scene.warnings {
        ffvk_cli::errln!("warning: {w}");
    }
    match out {
        None => ffvk_cli::out!("{}", made.toml)?,
        Some(path) => {
            for input in ffvk::scene::inputs(gltf, &global.limits()) {
                if ffvk::files::same_file(path, &input) {
                    return Err(ffvk_cli::Error::OverwritesInput {
                        path: path.to_path_buf(),
                        input,
                    });
                }
            }
            ffvk::files::write_bytes(path, made.toml.as_bytes()).map_err(|source| {
                ffvk_cli::Error::Write {
                    path: path.to_path_buf(),
                    source,
                }
            })?;
            ffvk_cli::errln!("wrote {}", path.display());
        }
    }
    Ok(ExitCode::SUCCESS)
}
