//! Filling the device-local buffers of meshes: directly where the host sees their memory
//! (lavapipe, integrated GPUs), else through a staging buffer and a copy on the renderer's
//! queue (a discrete GPU's VRAM).

use std::sync::Arc;

use ash::vk;

use crate::error::{vk_error, Result};
use crate::gl::texture::Level;
use crate::vk::objects::{CommandPool, Fence};
use crate::vk::{Buffer, Device, Image, MemoryUse};

/// How meshes reach device-local memory.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum Upload {
    /// Written by the host where the device-local memory is host-visible, else copied from a
    /// staging buffer.
    #[default]
    Auto,
    /// Always copied from a staging buffer by the GPU, even where the host could write the
    /// memory: what a discrete GPU does, on any device.
    Staging,
}

/// One buffer to create and fill.
pub(super) struct Part<'a> {
    /// What it is, for errors.
    pub what: &'static str,
    /// Its contents.
    pub bytes: &'a [u8],
    /// What it is used as (the copy's destination usage is added).
    pub usage: vk::BufferUsageFlags,
    /// The stages and accesses that read it after the upload.
    pub read_stage: vk::PipelineStageFlags2,
    pub read_access: vk::AccessFlags2,
}

/// The command buffer and fence of staging copies.
pub(super) struct Uploader {
    // Field order is drop order; both hold the device.
    commands: CommandPool,
    fence: Fence,
}

impl Uploader {
    pub(super) fn new(device: &Arc<Device>) -> Result<Self> {
        Ok(Uploader {
            commands: CommandPool::with_one_buffer(device, device.own()?.queue_family)?,
            fence: Fence::new(device)?,
        })
    }

    /// Device-local buffers holding `parts`, filled as `policy` says. Returns once the GPU
    /// has finished any copy.
    pub(super) fn upload(
        &mut self,
        device: &Arc<Device>,
        parts: &[Part],
        policy: Upload,
    ) -> Result<Vec<Buffer>> {
        let mut buffers = parts
            .iter()
            .map(|p| {
                let usage = p.usage | vk::BufferUsageFlags::TRANSFER_DST;
                Buffer::new(device, p.what, p.bytes.len() as u64, usage, MemoryUse::Gpu)
            })
            .collect::<Result<Vec<_>>>()?;
        if policy == Upload::Auto && buffers.iter().all(Buffer::is_mapped) {
            for (buffer, part) in buffers.iter_mut().zip(parts) {
                buffer.write(0, part.bytes)?;
            }
            return Ok(buffers);
        }
        let total: u64 = parts.iter().map(|p| p.bytes.len() as u64).sum();
        let mut staging = Buffer::new(
            device,
            "staging buffer",
            total,
            vk::BufferUsageFlags::TRANSFER_SRC,
            MemoryUse::Staging,
        )?;
        let mut offset = 0;
        let mut copies = Vec::with_capacity(parts.len());
        for (buffer, part) in buffers.iter().zip(parts) {
            if part.bytes.is_empty() {
                // A copy of zero bytes is invalid; an empty mesh draws nothing anyway.
                continue;
            }
            staging.write(offset, part.bytes)?;
            copies.push((buffer.raw(), offset, part.bytes.len() as u64));
            offset += part.bytes.len() as u64;
        }
        let (read_stage, read_access) = parts.iter().fold(
            (vk::PipelineStageFlags2::NONE, vk::AccessFlags2::NONE),
            |(s, a), p| (s | p.read_stage, a | p.read_access),
        );
        self.record(device, &staging, &copies, read_stage, read_access)?;
        self.submit_and_wait(device)?;
        Ok(buffers)
    }

    /// Fills every level of every layer of `image` (a color image with `TRANSFER_DST` and
    /// `SAMPLED` usage, as many levels as each of `layers` has and as many layers as `layers`)
    /// from `layers` through a staging buffer, and leaves it in `SHADER_READ_ONLY_OPTIMAL` for
    /// fragment shaders. Returns once the GPU has finished.
    pub(super) fn upload_image(
        &mut self,
        device: &Arc<Device>,
        image: &Image,
        layers: &[&[Level]],
    ) -> Result<()> {
        let all = || {
            layers
                .iter()
                .enumerate()
                .flat_map(|(l, levels)| levels.iter().enumerate().map(move |(i, v)| (l, i, v)))
        };
        let total: u64 = all().map(|(_, _, l)| l.rgba().len() as u64).sum();
        let mut staging = Buffer::new(
            device,
            "texture staging buffer",
            total,
            vk::BufferUsageFlags::TRANSFER_SRC,
            MemoryUse::Staging,
        )?;
        let mut regions = Vec::new();
        let mut offset = 0;
        for (layer, index, level) in all() {
            staging.write(offset, level.rgba())?;
            regions.push(
                vk::BufferImageCopy::default()
                    .buffer_offset(offset)
                    .image_subresource(vk::ImageSubresourceLayers {
                        aspect_mask: vk::ImageAspectFlags::COLOR,
                        mip_level: index as u32,
                        base_array_layer: layer as u32,
                        layer_count: 1,
                    })
                    .image_extent(vk::Extent3D {
                        width: level.width(),
                        height: level.height(),
                        depth: 1,
                    }),
            );
            offset += level.rgba().len() as u64;
        }
        let vkd = &device.raw;
        let range = vk::ImageSubresourceRange {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            base_mip_level: 0,
            level_count: image.levels(),
            base_array_layer: 0,
            layer_count: image.layers(),
        };
        // SAFETY: every upload waits for its fence, so the command buffer is not pending.
        let cmd = unsafe { self.commands.begin_one_time() }?;
        let to_transfer = [vk::ImageMemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::NONE)
            .dst_stage_mask(vk::PipelineStageFlags2::COPY)
            .dst_access_mask(vk::AccessFlags2::TRANSFER_WRITE)
            .old_layout(vk::ImageLayout::UNDEFINED)
            .new_layout(vk::ImageLayout::TRANSFER_DST_OPTIMAL)
            .image(image.raw())
            .subresource_range(range)];
        let to_sampled = [vk::ImageMemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::COPY)
            .src_access_mask(vk::AccessFlags2::TRANSFER_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags2::FRAGMENT_SHADER)
            .dst_access_mask(vk::AccessFlags2::SHADER_SAMPLED_READ)
            .old_layout(vk::ImageLayout::TRANSFER_DST_OPTIMAL)
            .new_layout(vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL)
            .image(image.raw())
            .subresource_range(range)];
        // SAFETY: recording outside any rendering pass; the image and staging buffer live
        // until the fence below is waited for; each region lies inside its level and the
        // staging buffer; the barriers cover every level.
        unsafe {
            vkd.cmd_pipeline_barrier2(
                cmd,
                &vk::DependencyInfo::default().image_memory_barriers(&to_transfer),
            );
            vkd.cmd_copy_buffer_to_image(
                cmd,
                staging.raw(),
                image.raw(),
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                &regions,
            );
            vkd.cmd_pipeline_barrier2(
                cmd,
                &vk::DependencyInfo::default().image_memory_barriers(&to_sampled),
            );
        }
        // SAFETY: recording is complete.
        unsafe { vkd.end_command_buffer(cmd) }.map_err(vk_error("vkEndCommandBuffer"))?;
        self.submit_and_wait(device)
    }

    fn record(
        &self,
        device: &Device,
        staging: &Buffer,
        copies: &[(vk::Buffer, u64, u64)],
        read_stage: vk::PipelineStageFlags2,
        read_access: vk::AccessFlags2,
    ) -> Result<()> {
        let vkd = &device.raw;
        // SAFETY: every upload waits for its fence, so the command buffer is not pending.
        let cmd = unsafe { self.commands.begin_one_time() }?;
        for &(dst, src_offset, size) in copies {
            let region = vk::BufferCopy {
                src_offset,
                dst_offset: 0,
                size,
            };
            // SAFETY: recording; both buffers are alive until the fence is waited for, the
            // region lies inside both and the destination allows transfers.
            unsafe { vkd.cmd_copy_buffer(cmd, staging.raw(), dst, &[region]) };
        }
        // The copies' writes become visible to the vertex input of every later submission on
        // this queue (barriers apply in submission order).
        let barrier = [vk::MemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::COPY)
            .src_access_mask(vk::AccessFlags2::TRANSFER_WRITE)
            .dst_stage_mask(read_stage)
            .dst_access_mask(read_access)];
        // SAFETY: recording, outside any rendering pass.
        unsafe { vkd.cmd_pipeline_barrier2(cmd, &vk::DependencyInfo::default().memory_barriers(&barrier)) };
        // SAFETY: recording is complete.
        unsafe { vkd.end_command_buffer(cmd) }.map_err(vk_error("vkEndCommandBuffer"))
    }

    fn submit_and_wait(&self, device: &Device) -> Result<()> {
        let vkd = &device.raw;
        let buffers = [self.commands.buffer()];
        let submit = vk::SubmitInfo::default().command_buffers(&buffers);
        let queue = device.own()?.queue;
        // SAFETY: the command buffer is recorded, the fence unsignaled; the renderer's queue
        // is used by one call at a time (uploads hold the uploader's lock, frames take the
        // renderer by &mut, and the two cannot overlap).
        let result = unsafe {
            vkd.queue_submit(queue, &[submit], self.fence.raw())
                .map_err(vk_error("vkQueueSubmit"))
                .and_then(|()| {
                    vkd.wait_for_fences(&[self.fence.raw()], true, u64::MAX)
                        .map_err(vk_error("vkWaitForFences"))
                })
        };
        if result.is_err() && device.wait_idle().is_err() {
            // The copy may still be pending and the fence in use: leave both alone (nothing
            // more can be submitted to a device that cannot even be waited for).
            return result;
        }
        // SAFETY: the fence is not in use by a pending submission (waited for above).
        let reset = unsafe { vkd.reset_fences(&[self.fence.raw()]) }.map_err(vk_error("vkResetFences"));
        result.and(reset)
    }
}
