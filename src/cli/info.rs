//! `ffvk info`.

use std::process::ExitCode;

use ffvk::Renderer;

use super::common::Global;

/// Prints the device, driver, versions, limits and the memory each use gets.
pub(crate) fn run(global: &Global) -> ffvk_cli::Result<ExitCode> {
    let renderer = Renderer::new(&global.options())?;
    let i = renderer.device_info();
    ffvk_cli::outln!("device:                  {} ({})", i.name, i.device_type)?;
    ffvk_cli::outln!("driver:                  {} ({})", i.driver_name, i.driver_info)?;
    ffvk_cli::outln!("Vulkan API:              {}", i.api_version)?;
    ffvk_cli::outln!(
        "vendor/device id:        {:#06x}/{:#06x}",
        i.vendor_id,
        i.device_id
    )?;
    ffvk_cli::outln!("maxImageDimension2D:     {}", i.max_image_dimension_2d)?;
    ffvk_cli::outln!("maxUniformBufferRange:   {}", i.max_uniform_buffer_range)?;
    ffvk_cli::outln!(
        "minUniformBufferOffsetAlignment: {}",
        i.min_uniform_buffer_offset_alignment
    )?;
    ffvk_cli::outln!("maxVertexOutputComponents: {}", i.max_vertex_output_components)?;
    ffvk_cli::outln!(
        "timestamps:              {} (period {} ns)",
        i.timestamps_supported,
        i.timestamp_period_ns
    )?;
    ffvk_cli::outln!("pipeline statistics:     {}", i.pipeline_statistics_query)?;
    ffvk_cli::outln!("provoking vertex last:   {}", i.provoking_vertex_last)?;
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
        ffvk_cli::outln!("memory for {:<16} {what}", format!("{usage:?}:"))?;
    }
    ffvk_cli::outln!("GL_MAX_LIGHTS:           {}", ffvk::gl::state::MAX_LIGHTS)?;
    ffvk_cli::outln!(
        "validation layer:        {}",
        if i.validation { "on" } else { "off" }
    )?;
    Ok(ExitCode::SUCCESS)
}
