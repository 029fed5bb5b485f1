//! `ffvk info`.

use std::process::ExitCode;

use ffvk::Renderer;

use super::common::Global;

/// Prints the device, driver, versions, limits and the memory each use gets.
pub(crate) fn run(global: &Global) -> ffvk_cli::Result<ExitCode> {
    let renderer = Renderer::new(&global.options())?;
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
