//! The `ffvk` command line.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use ffvk::gl::state::LightingMode;
use ffvk::images::save_png;
use ffvk::scene::{render_scene, Scene};
use ffvk::vk::Validation;
use ffvk::{Renderer, RendererOptions};

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
    /// Render scene files (or directories of them) with one device.
    Render {
        /// Scene files (.toml) or directories whose *.toml files are rendered in name order.
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Output PNG when rendering one scene; with several, a directory (NAME.png each).
        #[arg(short, long)]
        out: Option<PathBuf>,
        /// Override the scenes' lighting mode.
        #[arg(long)]
        lighting: Option<LightingMode>,
        /// Override the image size, as WxH (the vertical field of view is kept).
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
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
        scene: PathBuf,
        /// The pixel, as X,Y from the top-left corner.
        #[arg(long, value_parser = parse_pixel)]
        pixel: (u32, u32),
        #[arg(long)]
        lighting: Option<LightingMode>,
        #[arg(long, value_parser = parse_size)]
        size: Option<(u32, u32)>,
    },
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

/// The scene files named on the command line, directories expanded.
fn scene_files(inputs: &[PathBuf]) -> ffvk::Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for input in inputs {
        if input.is_dir() {
            let entries = std::fs::read_dir(input).map_err(|e| ffvk::Error::Input {
                path: input.clone(),
                message: e.to_string(),
            })?;
            let mut found: Vec<PathBuf> = entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .collect();
            found.sort();
            if found.is_empty() {
                return Err(ffvk::Error::Input {
                    path: input.clone(),
                    message: "no .toml scene files in this directory".into(),
                });
            }
            files.extend(found);
        } else {
            files.push(input.clone());
        }
    }
    Ok(files)
}

fn load_scene(path: &std::path::Path, size: Option<(u32, u32)>) -> ffvk::Result<Scene> {
    let mut scene = Scene::load(path)?;
    for w in &scene.warnings {
        eprintln!("warning: {w}");
    }
    if let Some((w, h)) = size {
        scene.set_size(w, h);
    }
    Ok(scene)
}

fn options(cli: &Cli) -> RendererOptions {
    let env_validate = std::env::var_os("FFVK_VALIDATION").is_some_and(|v| v != "0");
    RendererOptions {
        device: cli.device.clone(),
        validation: if cli.validate || env_validate {
            Validation::IfPresent
        } else {
            Validation::Off
        },
    }
}

fn run(cli: Cli) -> ffvk::Result<()> {
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
            println!("GL_MAX_LIGHTS:           {}", ffvk::gl::state::MAX_LIGHTS);
            println!(
                "validation layer:        {}",
                if i.validation { "on" } else { "off" }
            );
            Ok(())
        }
        Command::Demo { out } => ffvk::demo::run(&options(&cli), out),
        Command::Render {
            scenes,
            out,
            lighting,
            size,
        } => {
            let files = scene_files(scenes)?;
            let single = files.len() == 1 && !scenes[0].is_dir();
            let mut renderer = Renderer::new(&options(&cli))?;
            for file in &files {
                let scene = load_scene(file, *size)?;
                let image = render_scene(&mut renderer, &scene, *lighting)?;
                let stem = file
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                let path = match (single, out) {
                    (true, Some(out)) => out.clone(),
                    (false, Some(dir)) => dir.join(format!("{stem}.png")),
                    (_, None) => file.with_extension("png"),
                };
                save_png(&image, &path)?;
                println!("{} -> {}", file.display(), path.display());
            }
            Ok(())
        }
        Command::Teapot { level, out } => {
            let mesh = ffvk::teapot::teapot(*level).map_err(ffvk::Error::Mesh)?;
            ffvk::teapot::write_gltf(&mesh, out).map_err(|e| ffvk::Error::Output {
                path: out.clone(),
                message: e.to_string(),
            })?;
            println!(
                "wrote {} ({} vertices, {} triangles)",
                out.display(),
                mesh.vertices.len(),
                mesh.triangle_count()
            );
            Ok(())
        }
        Command::Explain {
            scene,
            pixel,
            lighting,
            size,
        } => {
            let scene = load_scene(scene, *size)?;
            let (x, y) = *pixel;
            if x >= scene.width || y >= scene.height {
                return Err(ffvk::Error::Input {
                    path: scene.path.clone(),
                    message: format!(
                        "--pixel {x},{y} is outside the {}x{} image: expected x < {} and y < {}",
                        scene.width, scene.height, scene.width, scene.height
                    ),
                });
            }
            let mode = lighting.unwrap_or(scene.state.mode);
            match ffvk::explain::explain(&scene, x, y, mode) {
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
            Ok(())
        }
    }
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("ffvk: error: {e}");
            ExitCode::FAILURE
        }
    }
}
