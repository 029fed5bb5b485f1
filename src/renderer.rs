//! The offscreen render path: one device, many frames, many scenes.

use std::sync::Arc;

use ash::vk;
use glam::{Mat4, Vec4};
use image::RgbaImage;

use crate::error::{vk_error, Error, Result};
use crate::gl::state::LightingState;
use crate::layout::DrawBlock;
use crate::mesh::MeshData;
use crate::pipeline::{Pipelines, COLOR_FORMAT, DEPTH_FORMAT};
use crate::vk::{Buffer, Device, DeviceInfo, Image, Instance, Validation, ValidationSink};

/// How to open a renderer.
#[derive(Debug, Clone, Default)]
pub struct RendererOptions {
    /// A substring of the device name; `None` picks lavapipe ("llvmpipe") when present.
    pub device: Option<String>,
    pub validation: Validation,
}

/// A mesh uploaded to the renderer's device. Draw it only with the renderer that made it.
pub struct Mesh {
    vertices: Buffer,
    indices: Buffer,
    index_count: u32,
    vertex_count: u32,
}

impl Mesh {
    pub fn index_count(&self) -> u32 {
        self.index_count
    }
    pub fn vertex_count(&self) -> u32 {
        self.vertex_count
    }
}

/// One draw: a mesh, its matrices (GL conventions) and the lighting state it captures.
#[derive(Clone, Copy)]
pub struct Draw<'a> {
    pub mesh: &'a Mesh,
    /// Object to eye space. Eye space: viewer at the origin looking down -z, y up.
    pub modelview: Mat4,
    /// GL projection (clip z in [-w, w]); ffvk converts it to Vulkan's clip space.
    pub projection: Mat4,
    pub state: LightingState,
}

/// One image: its size, clear color, depth test and draws, in order.
#[derive(Clone)]
pub struct Frame<'a> {
    pub width: u32,
    pub height: u32,
    pub clear_color: Vec4,
    /// GL_DEPTH_TEST with LESS against a depth buffer cleared to 1.
    pub depth_test: bool,
    pub draws: Vec<Draw<'a>>,
}

impl<'a> Frame<'a> {
    pub fn new(width: u32, height: u32) -> Self {
        Frame {
            width,
            height,
            clear_color: Vec4::new(0.0, 0.0, 0.0, 1.0),
            depth_test: true,
            draws: Vec::new(),
        }
    }
}

/// The render target of one size, reused while the size stays the same.
struct Targets {
    extent: vk::Extent2D,
    color: Image,
    depth: Image,
    readback: Buffer,
}

/// Draws frames offscreen and returns them as images. Owns its device; meshes hold it too.
pub struct Renderer {
    // Field order is drop order: everything below is freed before `device`'s last Arc.
    targets: Option<Targets>,
    uniforms: Option<Buffer>,
    pipelines: Pipelines,
    descriptor_pool: vk::DescriptorPool,
    descriptor_set: vk::DescriptorSet,
    command_pool: vk::CommandPool,
    command_buffer: vk::CommandBuffer,
    fence: vk::Fence,
    uniform_stride: u64,
    device: Arc<Device>,
}

impl Renderer {
    pub fn new(options: &RendererOptions) -> Result<Self> {
        let instance = Instance::new(options.validation)?;
        let device = Device::new(instance, options.device.as_deref())?;
        let pipelines = Pipelines::new(&device)?;
        let vkd = &device.raw;

        let align = device.limits.min_uniform_buffer_offset_alignment.max(16);
        let uniform_stride = (std::mem::size_of::<DrawBlock>() as u64).div_ceil(align) * align;

        let mut renderer = Renderer {
            targets: None,
            uniforms: None,
            pipelines,
            descriptor_pool: vk::DescriptorPool::null(),
            descriptor_set: vk::DescriptorSet::null(),
            command_pool: vk::CommandPool::null(),
            command_buffer: vk::CommandBuffer::null(),
            fence: vk::Fence::null(),
            uniform_stride,
            device: device.clone(),
        };
        let pool_sizes = [vk::DescriptorPoolSize {
            ty: vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
            descriptor_count: 1,
        }];
        let info = vk::DescriptorPoolCreateInfo::default()
            .max_sets(1)
            .pool_sizes(&pool_sizes);
        // SAFETY (this block and the three below): valid create infos on a live device;
        // each handle is stored in `renderer` immediately so Drop frees it on a later error.
        renderer.descriptor_pool =
            unsafe { vkd.create_descriptor_pool(&info, None) }.map_err(vk_error("vkCreateDescriptorPool"))?;
        let layouts = [renderer.pipelines.set_layout];
        let info = vk::DescriptorSetAllocateInfo::default()
            .descriptor_pool(renderer.descriptor_pool)
            .set_layouts(&layouts);
        // SAFETY: see above.
        renderer.descriptor_set =
            unsafe { vkd.allocate_descriptor_sets(&info) }.map_err(vk_error("vkAllocateDescriptorSets"))?[0];
        let info = vk::CommandPoolCreateInfo::default()
            .queue_family_index(device.queue_family)
            .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
        // SAFETY: see above.
        renderer.command_pool =
            unsafe { vkd.create_command_pool(&info, None) }.map_err(vk_error("vkCreateCommandPool"))?;
        let info = vk::CommandBufferAllocateInfo::default()
            .command_pool(renderer.command_pool)
            .level(vk::CommandBufferLevel::PRIMARY)
            .command_buffer_count(1);
        // SAFETY: see above.
        renderer.command_buffer =
            unsafe { vkd.allocate_command_buffers(&info) }.map_err(vk_error("vkAllocateCommandBuffers"))?[0];
        // SAFETY: see above.
        renderer.fence = unsafe { vkd.create_fence(&vk::FenceCreateInfo::default(), None) }
            .map_err(vk_error("vkCreateFence"))?;
        renderer.check_validation()?;
        Ok(renderer)
    }

    pub fn device_info(&self) -> &DeviceInfo {
        self.device.info()
    }

    /// The validation messages of this renderer's instance. Messages reported while the
    /// device is destroyed arrive after the renderer is dropped; keep a clone to read them.
    pub fn validation_sink(&self) -> ValidationSink {
        self.device.instance.validation_sink()
    }

    fn check_validation(&self) -> Result<()> {
        let errors = self.validation_sink().take_errors();
        if errors.is_empty() {
            Ok(())
        } else {
            Err(Error::Validation(errors))
        }
    }

    /// Uploads a triangle list. Fails when an index is past the vertices or the index count
    /// is not a multiple of three.
    pub fn upload(&self, mesh: &MeshData) -> Result<Mesh> {
        if mesh.indices.len() % 3 != 0 {
            return Err(Error::Mesh(format!(
                "{} indices is not a whole number of triangles: expected a multiple of 3",
                mesh.indices.len()
            )));
        }
        let count = mesh.vertices.len();
        if let Some((at, &bad)) = mesh
            .indices
            .iter()
            .enumerate()
            .find(|(_, &i)| i as usize >= count)
        {
            return Err(Error::Mesh(format!(
                "index {at} is {bad}: expected a vertex index below {count} (the vertex count)"
            )));
        }
        let vertex_bytes: &[u8] = bytemuck::cast_slice(&mesh.vertices);
        let index_bytes: &[u8] = bytemuck::cast_slice(&mesh.indices);
        let mut vertices = Buffer::new(
            &self.device,
            vertex_bytes.len() as u64,
            vk::BufferUsageFlags::VERTEX_BUFFER,
        )?;
        vertices.write(0, vertex_bytes);
        let mut indices = Buffer::new(
            &self.device,
            index_bytes.len() as u64,
            vk::BufferUsageFlags::INDEX_BUFFER,
        )?;
        indices.write(0, index_bytes);
        Ok(Mesh {
            vertices,
            indices,
            index_count: mesh.indices.len() as u32,
            vertex_count: count as u32,
        })
    }

    fn ensure_targets(&mut self, width: u32, height: u32) -> Result<()> {
        let max = self.device.limits.max_image_dimension2_d;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(Error::InvalidSize { width, height, max });
        }
        let extent = vk::Extent2D { width, height };
        if self.targets.as_ref().is_some_and(|t| t.extent == extent) {
            return Ok(());
        }
        self.targets = None;
        let color = Image::new(
            &self.device,
            extent,
            COLOR_FORMAT,
            vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
            vk::ImageAspectFlags::COLOR,
        )?;
        let depth = Image::new(
            &self.device,
            extent,
            DEPTH_FORMAT,
            vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
            vk::ImageAspectFlags::DEPTH,
        )?;
        let readback = Buffer::new(
            &self.device,
            width as u64 * height as u64 * 4,
            vk::BufferUsageFlags::TRANSFER_DST,
        )?;
        self.targets = Some(Targets {
            extent,
            color,
            depth,
            readback,
        });
        Ok(())
    }

    /// Makes the uniform buffer hold `draws` blocks and points the descriptor at it.
    fn ensure_uniforms(&mut self, draws: usize) -> Result<()> {
        let needed = self.uniform_stride * draws.max(1) as u64;
        if self.uniforms.as_ref().is_some_and(|u| u.size() >= needed) {
            return Ok(());
        }
        // Grow geometrically so scenes with more draws don't reallocate every frame.
        let size = needed.max(self.uniforms.as_ref().map_or(0, |u| u.size() * 2));
        let buffer = Buffer::new(&self.device, size, vk::BufferUsageFlags::UNIFORM_BUFFER)?;
        let info = [vk::DescriptorBufferInfo {
            buffer: buffer.raw,
            offset: 0,
            range: std::mem::size_of::<DrawBlock>() as u64,
        }];
        let write = vk::WriteDescriptorSet::default()
            .dst_set(self.descriptor_set)
            .dst_binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC)
            .buffer_info(&info);
        // SAFETY: no command buffer using the set is pending (render waits for its fence).
        unsafe { self.device.raw.update_descriptor_sets(&[write], &[]) };
        self.uniforms = Some(buffer);
        Ok(())
    }

    /// Draws `frame` and returns its pixels, row 0 at the top of the view.
    pub fn render(&mut self, frame: &Frame) -> Result<RgbaImage> {
        self.ensure_targets(frame.width, frame.height)?;
        self.ensure_uniforms(frame.draws.len())?;
        let blocks = frame
            .draws
            .iter()
            .map(|d| DrawBlock::new(&d.state, d.modelview, d.projection))
            .collect::<Result<Vec<_>, _>>()?;
        let uniforms = self.uniforms.as_mut().expect("ensure_uniforms made it");
        for (i, block) in blocks.iter().enumerate() {
            uniforms.write(i as u64 * self.uniform_stride, bytemuck::bytes_of(block));
        }

        self.record(frame)?;
        self.submit_and_wait()?;
        self.check_validation()?;

        let targets = self.targets.as_ref().expect("ensure_targets made them");
        let len = (frame.width * frame.height * 4) as usize;
        let pixels = targets.readback.bytes()[..len].to_vec();
        Ok(RgbaImage::from_raw(frame.width, frame.height, pixels)
            .expect("readback holds width*height*4 bytes"))
    }

    fn record(&self, frame: &Frame) -> Result<()> {
        let vkd = &self.device.raw;
        let cmd = self.command_buffer;
        let targets = self.targets.as_ref().expect("ensure_targets made them");
        let extent = targets.extent;

        let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
        // SAFETY: the command buffer is not pending (the previous submit was waited for);
        // the pool allows individual resets.
        unsafe {
            vkd.reset_command_buffer(cmd, vk::CommandBufferResetFlags::empty())
                .map_err(vk_error("vkResetCommandBuffer"))?;
            vkd.begin_command_buffer(cmd, &begin)
                .map_err(vk_error("vkBeginCommandBuffer"))?;
        }

        let color_range = subresource(vk::ImageAspectFlags::COLOR);
        let depth_range = subresource(vk::ImageAspectFlags::DEPTH);
        let to_attachment = [
            vk::ImageMemoryBarrier2::default()
                .src_stage_mask(vk::PipelineStageFlags2::TRANSFER)
                .src_access_mask(vk::AccessFlags2::TRANSFER_READ)
                .dst_stage_mask(vk::PipelineStageFlags2::COLOR_ATTACHMENT_OUTPUT)
                .dst_access_mask(vk::AccessFlags2::COLOR_ATTACHMENT_WRITE)
                .old_layout(vk::ImageLayout::UNDEFINED)
                .new_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                .image(targets.color.raw)
                .subresource_range(color_range),
            vk::ImageMemoryBarrier2::default()
                .src_stage_mask(vk::PipelineStageFlags2::LATE_FRAGMENT_TESTS)
                .src_access_mask(vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_WRITE)
                .dst_stage_mask(
                    vk::PipelineStageFlags2::EARLY_FRAGMENT_TESTS
                        | vk::PipelineStageFlags2::LATE_FRAGMENT_TESTS,
                )
                .dst_access_mask(
                    vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_READ
                        | vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_WRITE,
                )
                .old_layout(vk::ImageLayout::UNDEFINED)
                .new_layout(vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL)
                .image(targets.depth.raw)
                .subresource_range(depth_range),
        ];
        let c = frame.clear_color;
        let color_attachments = [vk::RenderingAttachmentInfo::default()
            .image_view(targets.color.view)
            .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::STORE)
            .clear_value(vk::ClearValue {
                color: vk::ClearColorValue {
                    float32: [c.x, c.y, c.z, c.w],
                },
            })];
        let depth_attachment = vk::RenderingAttachmentInfo::default()
            .image_view(targets.depth.view)
            .image_layout(vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::DONT_CARE)
            .clear_value(vk::ClearValue {
                depth_stencil: vk::ClearDepthStencilValue {
                    depth: 1.0,
                    stencil: 0,
                },
            });
        let area = vk::Rect2D {
            offset: vk::Offset2D { x: 0, y: 0 },
            extent,
        };
        let rendering = vk::RenderingInfo::default()
            .render_area(area)
            .layer_count(1)
            .color_attachments(&color_attachments)
            .depth_attachment(&depth_attachment);
        let viewport = vk::Viewport {
            x: 0.0,
            y: 0.0,
            width: extent.width as f32,
            height: extent.height as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        };

        // SAFETY: recording into a command buffer in the recording state; every handle
        // belongs to this device and outlives the submission (render waits for it).
        unsafe {
            vkd.cmd_pipeline_barrier2(
                cmd,
                &vk::DependencyInfo::default().image_memory_barriers(&to_attachment),
            );
            vkd.cmd_begin_rendering(cmd, &rendering);
            vkd.cmd_set_viewport(cmd, 0, &[viewport]);
            vkd.cmd_set_scissor(cmd, 0, &[area]);
            vkd.cmd_set_depth_test_enable(cmd, frame.depth_test);
            vkd.cmd_set_depth_write_enable(cmd, frame.depth_test);
            for (i, draw) in frame.draws.iter().enumerate() {
                vkd.cmd_bind_pipeline(
                    cmd,
                    vk::PipelineBindPoint::GRAPHICS,
                    self.pipelines.get(draw.state.mode),
                );
                let offset = (i as u64 * self.uniform_stride) as u32;
                vkd.cmd_bind_descriptor_sets(
                    cmd,
                    vk::PipelineBindPoint::GRAPHICS,
                    self.pipelines.layout,
                    0,
                    &[self.descriptor_set],
                    &[offset],
                );
                vkd.cmd_bind_vertex_buffers(cmd, 0, &[draw.mesh.vertices.raw], &[0]);
                vkd.cmd_bind_index_buffer(cmd, draw.mesh.indices.raw, 0, vk::IndexType::UINT32);
                vkd.cmd_draw_indexed(cmd, draw.mesh.index_count, 1, 0, 0, 0);
            }
            vkd.cmd_end_rendering(cmd);
        }

        let to_transfer = [vk::ImageMemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::COLOR_ATTACHMENT_OUTPUT)
            .src_access_mask(vk::AccessFlags2::COLOR_ATTACHMENT_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags2::COPY)
            .dst_access_mask(vk::AccessFlags2::TRANSFER_READ)
            .old_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .new_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)
            .image(targets.color.raw)
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
            .buffer(targets.readback.raw)
            .offset(0)
            .size(vk::WHOLE_SIZE)];
        // SAFETY: as above; the image is in TRANSFER_SRC_OPTIMAL after the barrier.
        unsafe {
            vkd.cmd_pipeline_barrier2(
                cmd,
                &vk::DependencyInfo::default().image_memory_barriers(&to_transfer),
            );
            vkd.cmd_copy_image_to_buffer(
                cmd,
                targets.color.raw,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                targets.readback.raw,
                &[region],
            );
            vkd.cmd_pipeline_barrier2(
                cmd,
                &vk::DependencyInfo::default().buffer_memory_barriers(&to_host),
            );
            vkd.end_command_buffer(cmd)
                .map_err(vk_error("vkEndCommandBuffer"))?;
        }
        Ok(())
    }

    fn submit_and_wait(&self) -> Result<()> {
        let vkd = &self.device.raw;
        let buffers = [self.command_buffer];
        let submit = vk::SubmitInfo::default().command_buffers(&buffers);
        // SAFETY: the command buffer is fully recorded; the fence is unsignaled (reset after
        // every wait); &self plus the renderer's exclusive ownership of the queue serialize
        // queue access.
        unsafe {
            vkd.queue_submit(self.device.queue, &[submit], self.fence)
                .map_err(vk_error("vkQueueSubmit"))?;
            vkd.wait_for_fences(&[self.fence], true, u64::MAX)
                .map_err(vk_error("vkWaitForFences"))?;
            vkd.reset_fences(&[self.fence])
                .map_err(vk_error("vkResetFences"))?;
        }
        Ok(())
    }
}

fn subresource(aspect: vk::ImageAspectFlags) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: aspect,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

impl Drop for Renderer {
    fn drop(&mut self) {
        let _ = self.device.wait_idle();
        let vkd = &self.device.raw;
        // SAFETY: the device is idle, so nothing these handles own is in use; freeing the
        // pools frees the command buffer and the descriptor set with them.
        unsafe {
            vkd.destroy_fence(self.fence, None);
            vkd.destroy_command_pool(self.command_pool, None);
            vkd.destroy_descriptor_pool(self.descriptor_pool, None);
        }
    }
}
