//! Recording draws: what one lit draw binds and issues inside a rendering pass.

use ash::vk;

/// One indexed draw of a lit mesh: its pipeline, the per-draw uniform block (a dynamic offset
/// into descriptor set 0) and the vertex and index buffers.
#[derive(Debug, Clone, Copy)]
pub struct IndexedDraw {
    /// A pipeline of [`super::pipeline::Pipelines`].
    pub pipeline: vk::Pipeline,
    /// The pipeline layout it was created with.
    pub layout: vk::PipelineLayout,
    /// Descriptor set 0: binding 0 is the uniform block (`UNIFORM_BUFFER_DYNAMIC`).
    pub set: vk::DescriptorSet,
    /// Offset of this draw's [`crate::gpu::layout::DrawBlock`] in the uniform buffer, a
    /// multiple of `minUniformBufferOffsetAlignment`.
    pub uniform_offset: u32,
    /// Interleaved [`crate::mesh::Vertex`] data at offset 0, bound to binding 0.
    pub vertices: vk::Buffer,
    /// `u32` indices at offset 0.
    pub indices: vk::Buffer,
    /// How many indices to draw (three per triangle).
    pub index_count: u32,
}

/// Binds `draw`'s pipeline, uniform block and buffers into `cmd` and draws it.
///
/// # Safety
///
/// `cmd` is a command buffer of `device` in the recording state, inside a dynamic rendering
/// pass whose formats match the pipeline's; every handle in `draw` belongs to `device` and
/// stays alive until the command buffer has finished executing.
pub(crate) unsafe fn record_indexed(device: &ash::Device, cmd: vk::CommandBuffer, draw: &IndexedDraw) {
    // SAFETY (each call below): the caller's contract above; the bind point is graphics and
    // set 0 is the only set of the layout, with one dynamic offset.
    unsafe { device.cmd_bind_pipeline(cmd, vk::PipelineBindPoint::GRAPHICS, draw.pipeline) };
    // SAFETY: as above.
    unsafe {
        device.cmd_bind_descriptor_sets(
            cmd,
            vk::PipelineBindPoint::GRAPHICS,
            draw.layout,
            0,
            &[draw.set],
            &[draw.uniform_offset],
        )
    };
    // SAFETY: as above; binding 0 is the pipeline's only vertex binding.
    unsafe { device.cmd_bind_vertex_buffers(cmd, 0, &[draw.vertices], &[0]) };
    // SAFETY: as above.
    unsafe { device.cmd_bind_index_buffer(cmd, draw.indices, 0, vk::IndexType::UINT32) };
    // SAFETY: as above; the renderer checked every index against the vertex count at upload.
    unsafe { device.cmd_draw_indexed(cmd, draw.index_count, 1, 0, 0, 0) };
}
