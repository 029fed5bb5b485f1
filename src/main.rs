//! The `ffvk` command line.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
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
