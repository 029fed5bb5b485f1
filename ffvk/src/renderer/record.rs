//! Recording a submission: a frame's rendering pass, once or repeated for measurement, with
//! the queries a measurement asks for and the copy a readback needs.

use ash::vk;

use super::attachments::{
    area_and_viewport, attachment_barriers, color_attachment, depth_attachment, stencil_attachment,
};
use super::deferred::{record_deferred, DeferredPass};
use super::{subresource, Draw, Frame, Pass, Recording, Renderer, Targets};
use crate::draw::lighting::{DrawValues, Lighting, LitDraw, Staged, VertexLayout};
use crate::draw::pipeline::{Attribute, VertexInput};
use crate::draw::record::Geometry;
use crate::error::{vk_error, Error, Result};
use crate::gl::state::FixedFunctionState;
use crate::gpu::layout::same_block_state;
use crate::vk::objects::QueryPool;

impl Renderer {
    /// Records the submission `pass` describes; returns the host time the first pass's draws
    /// took to record, in nanoseconds (the repeats only bind again what it wrote).
    pub(super) fn record(
        &mut self,
        frame: &Frame,
        pass: Pass,
        lits: &[LitDraw],
        staged: &[Staged],
        deferred: Option<&DeferredPass>,
    ) -> Result<f64> {
        let vkd = &self.device.raw;
        // Borrowed as a field (not through self.targets()): the draws below take the lighting
        // mutably at the same time.
        let targets = self.targets.as_ref().ok_or(Error::Internal(
            "a frame was recorded before its targets were made",
        ))?;
        // SAFETY: the previous submission was waited for.
        let cmd = unsafe { self.commands.begin_one_time() }?;
        // A pool where the device has it and the pass asks for it.
        let wanted = |pool: &Option<QueryPool>, on: bool| pool.as_ref().filter(|_| on).map(QueryPool::raw);
        let timestamps = wanted(&self.queries.timestamps, pass.timestamps);
        let statistics = wanted(&self.queries.statistics, pass.statistics);
        if let Some(pool) = timestamps {
            // SAFETY: recording outside any rendering pass; the pool has two queries per
            // repeat and one more (Queries::ensure_timestamps), reset before they are written.
            // On lavapipe a timestamp after any stage but TOP_OF_PIPE flushes the work before
            // it, and its value is taken when the next flush runs: the barrier right after
            // this one, before the pass starts.
            unsafe {
                vkd.cmd_reset_query_pool(cmd, pool, 0, 2 * pass.repeat + 1);
                vkd.cmd_write_timestamp2(cmd, vk::PipelineStageFlags2::ALL_COMMANDS, pool, 0);
            }
        }
        if let Some(pool) = statistics {
            // SAFETY: outside any rendering pass; the pool has one query.
            unsafe { vkd.cmd_reset_query_pool(cmd, pool, 0, 1) };
        }
        // The draws' uniforms were written once, before recording; every pass binds them.
        let mut record_ns = 0.0;
        // The next timestamp's query: a deferred frame writes one between its passes too.
        let mut query = 1;
        for i in 0..pass.repeat {
            let ns = match deferred {
                // SAFETY: the command buffer is recording, outside any pass; every handle
                // belongs to this device and outlives the submission (the renderer waits for
                // it); the deferred pass was made for these targets and staged draws; the
                // query was reset with query 0.
                Some(d) => unsafe {
                    let between = timestamps.map(|pool| (pool, query));
                    query += u32::from(between.is_some());
                    record_deferred(
                        &self.lighting,
                        frame,
                        (lits, staged),
                        targets,
                        d,
                        cmd,
                        (statistics, between),
                    )
                },
                // SAFETY: as above.
                None => unsafe {
                    record_pass(&self.lighting, frame, (lits, staged), targets, cmd, statistics)
                },
            }?;
            if i == 0 {
                record_ns = ns;
            }
            if let Some(pool) = timestamps {
                // After every command of the pass has completed (on lavapipe: a flush that
                // waits for the rasterizer threads).
                // SAFETY: as above; the query was reset with query 0.
                unsafe { vkd.cmd_write_timestamp2(cmd, vk::PipelineStageFlags2::ALL_COMMANDS, pool, query) };
                query += 1;
            }
        }
        if pass.readback {
            // SAFETY: as above; the last pass left the color image in COLOR_ATTACHMENT_OPTIMAL.
            unsafe { record_readback(vkd, targets, cmd) };
        }
        // SAFETY: as above; recording is complete.
        unsafe { vkd.end_command_buffer(cmd) }.map_err(vk_error("vkEndCommandBuffer"))?;
        Ok(record_ns)
    }
}

/// Records one frame's rendering pass: the attachments' layouts, the clears and the draws,
/// inside the statistics query when there is one; the draws are `lits`, staged as `staged`,
/// recorded as one run. Returns the host time their recording took.
///
/// # Safety
///
/// `cmd` is a command buffer of the lighting's device in the recording state, outside any pass; every handle
/// belongs to that device and stays alive until the submission has finished; the lighting's
/// frame slot 0 was begun after the last frame's fence.
unsafe fn record_pass(
    lighting: &Lighting,
    frame: &Frame,
    (lits, staged): (&[LitDraw], &[Staged]),
    targets: &Targets,
    cmd: vk::CommandBuffer,
    statistics: Option<vk::QueryPool>,
) -> Result<f64> {
    let vkd = &lighting.device().raw;
    let extent = targets.extent;
    let to_attachment = attachment_barriers(targets);
    let color_attachments = [color_attachment(targets, frame)];
    let depth_attachment = depth_attachment(targets, vk::AttachmentStoreOp::DONT_CARE);
    let stencil_attachment = stencil_attachment(targets, frame);
    let (area, viewport) = area_and_viewport(extent);
    let mut rendering = vk::RenderingInfo::default()
        .render_area(area)
        .layer_count(1)
        .color_attachments(&color_attachments)
        .depth_attachment(&depth_attachment);
    if let Some(stencil) = &stencil_attachment {
        rendering = rendering.stencil_attachment(stencil);
    }

    // SAFETY: recording into a command buffer in the recording state; every handle belongs
    // to this device and outlives the submission (render waits for it). The same holds for
    // the next blocks of this function.
    unsafe {
        vkd.cmd_pipeline_barrier2(
            cmd,
            &vk::DependencyInfo::default().image_memory_barriers(&to_attachment),
        )
    };
    if let Some(pool) = statistics {
        // SAFETY: as above; the query was reset before this, outside the pass.
        unsafe { vkd.cmd_begin_query(cmd, pool, 0, vk::QueryControlFlags::empty()) };
    }
    // SAFETY: as above; the attachments are in the layouts the barrier set.
    unsafe { vkd.cmd_begin_rendering(cmd, &rendering) };
    // SAFETY: as above; viewport and scissor are dynamic in every pipeline.
    unsafe {
        vkd.cmd_set_viewport(cmd, 0, &[viewport]);
        vkd.cmd_set_scissor(cmd, 0, &[area]);
    }
    let draws_start = std::time::Instant::now();
    // Recording below is safe: inside the rendering pass begun above, whose formats are the
    // Target::OFFSCREEN the lighting was made for, viewport and scissor set; the mesh buffers
    // outlive the submission; slot 0 was begun after the last frame's fence. The draws are one
    // run: nothing else is recorded between them.
    // glDepthRange is the viewport's depth: the draws go in runs of one range, the viewport
    // set before each run whose range is not the last one set.
    let mut at = 0;
    let mut range_set = [viewport.min_depth, viewport.max_depth];
    while at < lits.len() {
        let range = |i: usize| frame.draws.get(i).map(Draw::clamped_depth_range);
        let here = range(at);
        let end = (at..lits.len()).find(|&i| range(i) != here).unwrap_or(lits.len());
        if let Some([near, far]) = here.filter(|&r| r != range_set) {
            range_set = [near, far];
            let v = vk::Viewport {
                min_depth: near,
                max_depth: far,
                ..viewport
            };
            // SAFETY: as above; the viewport is dynamic in every pipeline.
            unsafe { vkd.cmd_set_viewport(cmd, 0, &[v]) };
        }
        let (staged, lits) = (&staged[at..end], &lits[at..end]);
        // SAFETY: as above; staged[i] was staged for lits[i] in this frame's slot.
        unsafe {
            match frame.recording {
                Recording::Run => lighting.record_staged_run(cmd, staged, lits),
                Recording::DrawByDraw => lighting.record_staged_draw_by_draw(cmd, staged, lits),
            }
        };
        at = end;
    }
    let record_ns = draws_start.elapsed().as_nanos() as f64;
    // SAFETY: as above; the pass begun above ends here.
    unsafe { vkd.cmd_end_rendering(cmd) };
    if let Some(pool) = statistics {
        // SAFETY: as above; ends the query begun before the pass.
        unsafe { vkd.cmd_end_query(cmd, pool, 0) };
    }
    Ok(record_ns)
}

/// Records the copy of the color image into the readback buffer, visible to the host after
/// the fence.
///
/// # Safety
///
/// As [`record_pass`]; the color image is in `COLOR_ATTACHMENT_OPTIMAL` after a pass.
unsafe fn record_readback(vkd: &ash::Device, targets: &Targets, cmd: vk::CommandBuffer) {
    let extent = targets.extent;
    let color_range = subresource(vk::ImageAspectFlags::COLOR);
    let to_transfer = [vk::ImageMemoryBarrier2::default()
        .src_stage_mask(vk::PipelineStageFlags2::COLOR_ATTACHMENT_OUTPUT)
        .src_access_mask(vk::AccessFlags2::COLOR_ATTACHMENT_WRITE)
        .dst_stage_mask(vk::PipelineStageFlags2::COPY)
        .dst_access_mask(vk::AccessFlags2::TRANSFER_READ)
        .old_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .new_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)
        .image(targets.color.raw())
        .subresource_range(color_range)];
    let region = vk::BufferImageCopy {
        buffer_offset: 0,
        buffer_row_length: 0,
        buffer_image_height: 0,
        image_subresource: vk::ImageSubresourceLayers {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            mip_level: 0,
            base_array_layer: 0,
            layer_count: 1,
        },
        image_offset: vk::Offset3D { x: 0, y: 0, z: 0 },
        image_extent: vk::Extent3D {
            width: extent.width,
            height: extent.height,
            depth: 1,
        },
    };
    let to_host = [vk::BufferMemoryBarrier2::default()
        .src_stage_mask(vk::PipelineStageFlags2::COPY)
        .src_access_mask(vk::AccessFlags2::TRANSFER_WRITE)
        .dst_stage_mask(vk::PipelineStageFlags2::HOST)
        .dst_access_mask(vk::AccessFlags2::HOST_READ)
        .buffer(targets.readback.raw())
        .offset(0)
        .size(vk::WHOLE_SIZE)];
    // SAFETY: the function's contract; moves the color image to TRANSFER_SRC_OPTIMAL after the pass.
    unsafe {
        vkd.cmd_pipeline_barrier2(
            cmd,
            &vk::DependencyInfo::default().image_memory_barriers(&to_transfer),
        )
    };
    // SAFETY: as above; the image is in TRANSFER_SRC_OPTIMAL and the readback buffer holds
    // width * height * 4 bytes.
    unsafe {
        vkd.cmd_copy_image_to_buffer(
            cmd,
            targets.color.raw(),
            vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            targets.readback.raw(),
            &[region],
        )
    };
    // SAFETY: as above; makes the copy visible to the host read after the fence.
    unsafe {
        vkd.cmd_pipeline_barrier2(
            cmd,
            &vk::DependencyInfo::default().buffer_memory_barriers(&to_host),
        )
    };
}

/// The lit draws of `frame`: each mesh's vertices and indices, the frame's raster state with
/// the draw's culling, its texture when it samples one. A draw whose state differs from the
/// draw before's only in its own values (materials, current color) borrows that draw's state
/// and carries its values, as an embedder's run does: its state is compared here once, and
/// staging and pipeline lookup take it as the same.
/// `layouts` holds the vertex layout of each value of a draw's [`Draw::mesh_texcoords`] and
/// [`Draw::second_texcoords`] ([`mesh_texcoord_index`]), `None` for the interleaved layout
/// alone.
pub(super) fn lit_draws<'f>(frame: &'f Frame, layouts: &TexcoordLayouts) -> Vec<LitDraw<'f>> {
    let mut shared: Option<&'f FixedFunctionState> = None;
    frame
        .draws
        .iter()
        .map(|draw| {
            let own = &draw.state;
            let state = match shared {
                Some(s)
                    if (s.mode, s.rescale_normal) == (own.mode, own.rescale_normal)
                        && same_block_state(s, own) =>
                {
                    s
                }
                _ => own,
            };
            shared = Some(state);
            let mesh = draw.mesh;
            let geometry = Geometry::indexed(mesh.indices.raw(), vk::IndexType::UINT32, mesh.index_count)
                .with_topology(draw.topology);
            let index = mesh_texcoord_index(draw);
            // The second set's binding where the layout reads it (the frame was checked: the
            // mesh then has one).
            let bound = if index >> 3 != 0 { 2 } else { 1 };
            let buffers: &[(vk::Buffer, u64)] = &mesh.vertex_bindings[..bound];
            LitDraw::new(state, draw.modelview, draw.projection, buffers, geometry)
                .with_layout(layouts[index])
                .with_values(Some(DrawValues::of(own)))
                .with_raster(draw.raster(frame))
                .with_textures(std::array::from_fn(|i| {
                    draw.textures[i].filter(|t| t.is_complete()).map(|t| &t.binding)
                }))
                .with_cube_maps(std::array::from_fn(|i| {
                    draw.cube_maps[i].filter(|t| t.is_complete()).map(|t| &t.binding)
                }))
        })
        .collect()
}

/// The vertex layouts of [`lit_draws`], by [`mesh_texcoord_index`].
pub(super) type TexcoordLayouts = [Option<VertexLayout>; 64];

/// The index of a draw's texture coordinate arrays among the layouts [`lit_draws`] takes: bits
/// 0-2 the units 1-3 reading the mesh's first set ([`Draw::mesh_texcoords`]' bits 1-3), bits
/// 3-5 those reading its second set ([`Draw::second_texcoords`]' bits 1-3), which a unit in
/// both reads.
pub(super) fn mesh_texcoord_index(draw: &Draw) -> usize {
    let second = (draw.second_texcoords >> 1) & 7;
    let first = (draw.mesh_texcoords >> 1) & 7 & !second;
    (first | second << 3) as usize
}

impl Renderer {
    /// The vertex layouts `frame`'s draws need for their texture coordinate arrays (added to
    /// the lighting on first use), by [`mesh_texcoord_index`]: the interleaved layout with the
    /// mesh's texture coordinates on those units too, and with the second set in a binding of
    /// its own (binding 1, two floats a vertex) on the units that read it.
    pub(super) fn texcoord_layouts(&mut self, frame: &Frame) -> Result<TexcoordLayouts> {
        let mut layouts = [None; 64];
        for draw in &frame.draws {
            let index = mesh_texcoord_index(draw);
            if index == 0 || layouts[index].is_some() {
                continue;
            }
            let mut base = VertexInput::interleaved();
            let second = Attribute::new(1, 0, vk::Format::R32G32_SFLOAT);
            if index >> 3 != 0 {
                base.bindings.push(vk::VertexInputBindingDescription {
                    binding: 1,
                    stride: std::mem::size_of::<[f32; 2]>() as u32,
                    input_rate: vk::VertexInputRate::VERTEX,
                });
            }
            let units = std::array::from_fn(|i| {
                if index & 8 << i != 0 {
                    Some(second)
                } else {
                    base.texcoord.filter(|_| index & 1 << i != 0)
                }
            });
            layouts[index] = Some(self.lighting.vertex_layout(base.with_unit_texcoords(units))?);
        }
        Ok(layouts)
    }
}
