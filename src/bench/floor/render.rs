//! The floor's renderer: one frame recorded anew, submitted and waited for, through one data
//! path. Every Vulkan object is ffvk's owned wrapper (or the floor's own [`super::pipelines`]
//! layout) and frees itself in `Drop`; the [`Context`] goes last.

use ash::vk;
use ffvk::vk::objects::{CommandPool, DescriptorPool, Fence};
use ffvk::vk::{Buffer, Image, MemoryUse, Validation};

use super::context::{failed, Context};
use super::pipelines::{pipelines, Kind, KindPipeline, COLOR_FORMAT, DEPTH_FORMAT};
use super::scene::{FloorScene, RECORD_BYTES};
use super::FloorPath;
use crate::bench::points::CLEAR;
use crate::{Error, Result};

/// A mesh's vertex and index buffers.
struct MeshBuffers {
    vertices: Buffer,
    indices: Buffer,
}

/// One scene's buffers and descriptor sets. Field order is drop order: the sets' pools before
/// the buffers they name.
struct Loaded {
    sets: Vec<(Kind, DescriptorPool)>,
    _frame_block: Buffer,
    /// Every record, 128 bytes apart: the instance attributes and the storage buffer.
    packed: Buffer,
    /// Every record at `aligned_stride`: the dynamic uniform buffer.
    aligned: Buffer,
    aligned_stride: u64,
    /// The records laid out `aligned_stride` apart, written whole each frame.
    aligned_bytes: Vec<u8>,
    /// One mesh, or one per draw (each its own buffers).
    meshes: Vec<MeshBuffers>,
    /// For a mesh each: every draw's mesh in one buffer pair (multi-draw's).
    packed_meshes: Option<MeshBuffers>,
    /// Each draw's place in the multi-draw's buffers.
    multi: Vec<vk::MultiDrawIndexedInfoEXT>,
    index_count: u32,
    scene: FloorScene,
}

/// What the floor made on its device: pipelines, target and, once loaded, a scene. Waits
/// for the device before it frees them.
struct Gpu {
    loaded: Option<Loaded>,
    commands: CommandPool,
    fence: Fence,
    color: Image,
    depth: Image,
    readback: Buffer,
    pipelines: Vec<KindPipeline>,
    size: u32,
    /// The device's handle, to wait for it in `Drop`.
    device: ash::Device,
}

impl Drop for Gpu {
    fn drop(&mut self) {
        // SAFETY: the device is alive (the context goes after this); waiting keeps the GPU off
        // what is dropped next.
        let _ = unsafe { self.device.device_wait_idle() };
    }
}

/// The floor: its device and what it made there.
pub(super) struct Floor {
    gpu: Gpu,
    // Last: everything above lives on its device.
    context: Context,
}

fn buffer(
    context: &Context,
    what: &'static str,
    bytes: &[u8],
    usage: vk::BufferUsageFlags,
) -> Result<Buffer> {
    let mut b = Buffer::new(
        context.ffvk()?,
        what,
        bytes.len() as u64,
        usage,
        MemoryUse::Uniforms,
    )?;
    b.write(0, bytes)?;
    Ok(b)
}

fn mesh_buffers(context: &Context, vertices: &[u8], indices: &[u8]) -> Result<MeshBuffers> {
    Ok(MeshBuffers {
        vertices: buffer(
            context,
            "floor vertices",
            vertices,
            vk::BufferUsageFlags::VERTEX_BUFFER,
        )?,
        indices: buffer(
            context,
            "floor indices",
            indices,
            vk::BufferUsageFlags::INDEX_BUFFER,
        )?,
    })
}

fn color_range(aspect: vk::ImageAspectFlags) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: aspect,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

impl Floor {
    /// The floor on the device named like `device` (lavapipe by default), drawing `size`².
    pub(super) fn new(device: Option<&str>, validation: Validation, size: u32) -> Result<Self> {
        let context = Context::new(device, validation)?;
        let owner = context.ffvk()?;
        let extent = vk::Extent2D {
            width: size,
            height: size,
        };
        let color = Image::new(
            owner,
            extent,
            COLOR_FORMAT,
            vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
            vk::ImageAspectFlags::COLOR,
        )?;
        let depth = Image::new(
            owner,
            extent,
            DEPTH_FORMAT,
            vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
            vk::ImageAspectFlags::DEPTH,
        )?;
        let readback = Buffer::new(
            owner,
            "floor readback",
            u64::from(size) * u64::from(size) * 4,
            vk::BufferUsageFlags::TRANSFER_DST,
            MemoryUse::Readback,
        )?;
        let pipelines = pipelines(owner, context.device()?, size, context.multi_draw.is_some())?;
        let gpu = Gpu {
            loaded: None,
            commands: CommandPool::with_one_buffer(owner, context.queue_family)?,
            fence: Fence::new(owner)?,
            color,
            depth,
            readback,
            pipelines,
            size,
            device: context.device()?.clone(),
        };
        let floor = Floor { gpu, context };
        floor.context.check_validation()?;
        Ok(floor)
    }

    /// Whether the device can draw through `path` (the storage path needs VK_EXT_multi_draw).
    pub(super) fn can(&self, path: FloorPath) -> bool {
        path != FloorPath::StorageDrawId || self.context.multi_draw.is_some()
    }

    /// Makes `scene` the one drawn: its meshes, records and descriptor sets.
    pub(super) fn load(&mut self, scene: FloorScene) -> Result<()> {
        self.gpu.loaded = None;
        let context = &self.context;
        let device = context.device()?;
        let mesh = &scene.mesh;
        let vertices: &[u8] = bytemuck::cast_slice(&mesh.vertices);
        let indices: &[u8] = bytemuck::cast_slice(&mesh.indices);
        let mesh_count = if scene.mesh_each { scene.draws } else { 1 };
        let meshes = (0..mesh_count)
            .map(|_| mesh_buffers(context, vertices, indices))
            .collect::<Result<Vec<_>>>()?;
        let index_count = mesh.indices.len() as u32;
        let vertex_count = mesh.vertices.len() as i32;
        let packed_meshes = if scene.mesh_each && context.multi_draw.is_some() {
            Some(mesh_buffers(
                context,
                &vertices.repeat(scene.draws as usize),
                &indices.repeat(scene.draws as usize),
            )?)
        } else {
            None
        };
        let multi = (0..scene.draws)
            .map(|i| {
                let each = if scene.mesh_each { i } else { 0 };
                vk::MultiDrawIndexedInfoEXT {
                    first_index: each * index_count,
                    index_count,
                    vertex_offset: each as i32 * vertex_count,
                }
            })
            .collect();

        let records: &[u8] = bytemuck::cast_slice(&scene.records);
        let usage = vk::BufferUsageFlags::VERTEX_BUFFER | vk::BufferUsageFlags::STORAGE_BUFFER;
        let packed = buffer(context, "floor records", records, usage)?;
        let align = context.limits.min_uniform_buffer_offset_alignment.max(1);
        let aligned_stride = RECORD_BYTES.div_ceil(align) * align;
        let mut aligned_bytes = vec![0u8; (aligned_stride * u64::from(scene.draws)) as usize];
        for (at, record) in aligned_bytes
            .chunks_mut(aligned_stride as usize)
            .zip(records.chunks(RECORD_BYTES as usize))
        {
            at[..record.len()].copy_from_slice(record);
        }
        let aligned = buffer(
            context,
            "floor aligned records",
            &aligned_bytes,
            vk::BufferUsageFlags::UNIFORM_BUFFER,
        )?;
        let frame_block = buffer(
            context,
            "floor frame block",
            bytemuck::bytes_of(&scene.block),
            vk::BufferUsageFlags::UNIFORM_BUFFER,
        )?;

        let mut sets = Vec::new();
        for p in &self.gpu.pipelines {
            let mut sizes = vec![vk::DescriptorPoolSize {
                ty: vk::DescriptorType::UNIFORM_BUFFER,
                descriptor_count: 1,
            }];
            sizes.extend(p.kind.record_descriptor().map(|ty| vk::DescriptorPoolSize {
                ty,
                descriptor_count: 1,
            }));
            let pool = DescriptorPool::with_one_set(context.ffvk()?, &sizes, &p.set_layout)?;
            let block_info = [vk::DescriptorBufferInfo {
                buffer: frame_block.raw(),
                offset: 0,
                range: vk::WHOLE_SIZE,
            }];
            let record_info = [match p.kind {
                Kind::Uniform => vk::DescriptorBufferInfo {
                    buffer: aligned.raw(),
                    offset: 0,
                    range: RECORD_BYTES,
                },
                _ => vk::DescriptorBufferInfo {
                    buffer: packed.raw(),
                    offset: 0,
                    range: vk::WHOLE_SIZE,
                },
            }];
            let mut writes = vec![vk::WriteDescriptorSet::default()
                .dst_set(pool.set())
                .dst_binding(0)
                .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                .buffer_info(&block_info)];
            if let Some(ty) = p.kind.record_descriptor() {
                writes.push(
                    vk::WriteDescriptorSet::default()
                        .dst_set(pool.set())
                        .dst_binding(1)
                        .descriptor_type(ty)
                        .buffer_info(&record_info),
                );
            }
            // SAFETY: the set is not in use by any pending command (the floor waits for each
            // frame); the buffers are alive and as large as the ranges.
            unsafe { device.update_descriptor_sets(&writes, &[]) };
            sets.push((p.kind, pool));
        }
        self.gpu.loaded = Some(Loaded {
            sets,
            _frame_block: frame_block,
            packed,
            aligned,
            aligned_stride,
            aligned_bytes,
            meshes,
            packed_meshes,
            multi,
            index_count,
            scene,
        });
        self.context.check_validation()
    }

    /// Draws the loaded scene's frame through `path`: writes the draws' records where the
    /// path reads them from a buffer, records the command buffer anew, submits it and waits
    /// for its fence. With `readback`, returns the image (RGBA, row 0 at the top).
    pub(super) fn frame(&mut self, path: FloorPath, readback: bool) -> Result<Option<Vec<u8>>> {
        let Some(loaded) = self.gpu.loaded.as_mut() else {
            return Err(Error::Bench("a floor frame before its scene".into()));
        };
        if path == FloorPath::StorageDrawId && self.context.multi_draw.is_none() {
            return Err(Error::Bench(format!("{} needs VK_EXT_multi_draw", path.name())));
        }
        if path == FloorPath::InstanceAttributesInstanced && loaded.scene.mesh_each {
            return Err(Error::Bench(format!("{} draws one mesh only", path.name())));
        }
        match path.kind() {
            Kind::Instance | Kind::Storage => loaded
                .packed
                .write(0, bytemuck::cast_slice(&loaded.scene.records))?,
            Kind::Uniform => loaded.aligned.write(0, &loaded.aligned_bytes)?,
            Kind::Push => {}
        }
        let device = self.context.device()?;
        // SAFETY: the last submission of the command buffer finished (its fence was waited for).
        let cb = unsafe { self.gpu.commands.begin_one_time() }?;
        let Some(pipeline) = self.gpu.pipelines.iter().find(|p| p.kind == path.kind()) else {
            return Err(Error::Bench(format!("no floor pipeline for {}", path.name())));
        };
        let Some((_, pool)) = loaded.sets.iter().find(|(k, _)| *k == path.kind()) else {
            return Err(Error::Bench(format!(
                "no floor descriptor set for {}",
                path.name()
            )));
        };
        let targets = (&self.gpu.color, &self.gpu.depth, self.gpu.size);
        // SAFETY: `cb` is recording; every handle recorded is alive until the fence below
        // signals, and the commands follow the pipeline's layout and vertex input.
        unsafe {
            begin_pass(device, cb, targets);
            let layout = pipeline.layout.raw();
            device.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, pipeline.pipeline.raw());
            let set = [pool.set()];
            if path.kind() != Kind::Uniform {
                device.cmd_bind_descriptor_sets(cb, vk::PipelineBindPoint::GRAPHICS, layout, 0, &set, &[]);
            }
            if path.kind() == Kind::Instance {
                device.cmd_bind_vertex_buffers(cb, 1, &[loaded.packed.raw()], &[0]);
            }
            let count = loaded.index_count;
            let bind_mesh = |m: &MeshBuffers| {
                device.cmd_bind_vertex_buffers(cb, 0, &[m.vertices.raw()], &[0]);
                device.cmd_bind_index_buffer(cb, m.indices.raw(), 0, vk::IndexType::UINT32);
            };
            let draws = loaded.scene.draws;
            match path {
                FloorPath::InstanceAttributesInstanced => {
                    bind_mesh(&loaded.meshes[0]);
                    device.cmd_draw_indexed(cb, count, draws, 0, 0, 0);
                }
                FloorPath::StorageDrawId => {
                    let (multi_draw, max) = self
                        .context
                        .multi_draw
                        .as_ref()
                        .ok_or_else(|| Error::Bench("VK_EXT_multi_draw is gone".into()))?;
                    bind_mesh(loaded.packed_meshes.as_ref().unwrap_or(&loaded.meshes[0]));
                    let draw_multi = multi_draw.fp().cmd_draw_multi_indexed_ext;
                    let stride = std::mem::size_of::<vk::MultiDrawIndexedInfoEXT>() as u32;
                    for (batch, infos) in loaded.multi.chunks((*max).max(1) as usize).enumerate() {
                        let first = batch as u32 * (*max).max(1);
                        // One instance per draw, the batch's first record as firstInstance
                        // (the shader adds gl_DrawID); a null vertex offset: each draw's own.
                        draw_multi(
                            cb,
                            infos.len() as u32,
                            infos.as_ptr(),
                            1,
                            first,
                            stride,
                            std::ptr::null(),
                        );
                    }
                }
                _ => {
                    for i in 0..draws {
                        let mesh = &loaded.meshes[if loaded.scene.mesh_each { i as usize } else { 0 }];
                        if i == 0 || loaded.scene.mesh_each {
                            bind_mesh(mesh);
                        }
                        match path.kind() {
                            Kind::Uniform => {
                                let offset = [(u64::from(i) * loaded.aligned_stride) as u32];
                                let point = vk::PipelineBindPoint::GRAPHICS;
                                device.cmd_bind_descriptor_sets(cb, point, layout, 0, &set, &offset);
                                device.cmd_draw_indexed(cb, count, 1, 0, 0, 0);
                            }
                            Kind::Push => {
                                let bytes = bytemuck::bytes_of(&loaded.scene.records[i as usize]);
                                device.cmd_push_constants(cb, layout, vk::ShaderStageFlags::VERTEX, 0, bytes);
                                device.cmd_draw_indexed(cb, count, 1, 0, 0, 0);
                            }
                            _ => device.cmd_draw_indexed(cb, count, 1, 0, 0, i),
                        }
                    }
                }
            }
            device.cmd_end_rendering(cb);
            if readback {
                copy_out(device, cb, &self.gpu.color, &self.gpu.readback, self.gpu.size);
            }
            device
                .end_command_buffer(cb)
                .map_err(failed("vkEndCommandBuffer"))?;
            let buffers = [cb];
            let submit = vk::SubmitInfo::default().command_buffers(&buffers);
            device
                .queue_submit(self.context.queue, &[submit], self.gpu.fence.raw())
                .map_err(failed("vkQueueSubmit"))?;
            device
                .wait_for_fences(&[self.gpu.fence.raw()], true, u64::MAX)
                .map_err(failed("vkWaitForFences"))?;
            device
                .reset_fences(&[self.gpu.fence.raw()])
                .map_err(failed("vkResetFences"))?;
        }
        self.context.check_validation()?;
        if !readback {
            return Ok(None);
        }
        let bytes = self
            .gpu
            .readback
            .bytes()
            .ok_or_else(|| Error::Bench("the floor's readback buffer is not mapped".into()))?;
        Ok(Some(bytes.to_vec()))
    }
}

impl Floor {
    /// Frees everything, the device last, and fails with the validation layer's messages of
    /// the teardown (objects left alive, for example).
    pub(super) fn close(self) -> Result<()> {
        let Floor { gpu, context } = self;
        drop(gpu);
        context.close()
    }
}

/// The attachments into their layouts, and the pass begun with both cleared.
///
/// # Safety
///
/// `cb` is recording, outside a pass; the images are alive and not in use.
unsafe fn begin_pass(
    device: &ash::Device,
    cb: vk::CommandBuffer,
    (color, depth, size): (&Image, &Image, u32),
) {
    let tests = vk::PipelineStageFlags::EARLY_FRAGMENT_TESTS | vk::PipelineStageFlags::LATE_FRAGMENT_TESTS;
    let barriers = [
        vk::ImageMemoryBarrier::default()
            .dst_access_mask(vk::AccessFlags::COLOR_ATTACHMENT_WRITE)
            .old_layout(vk::ImageLayout::UNDEFINED)
            .new_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .image(color.raw())
            .subresource_range(color_range(vk::ImageAspectFlags::COLOR)),
        vk::ImageMemoryBarrier::default()
            .dst_access_mask(
                vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_READ
                    | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            )
            .old_layout(vk::ImageLayout::UNDEFINED)
            .new_layout(vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL)
            .image(depth.raw())
            .subresource_range(color_range(vk::ImageAspectFlags::DEPTH)),
    ];
    let c = CLEAR;
    let color_attachment = [vk::RenderingAttachmentInfo::default()
        .image_view(color.view())
        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)
        .clear_value(vk::ClearValue {
            color: vk::ClearColorValue {
                float32: [c.x, c.y, c.z, c.w],
            },
        })];
    let depth_attachment = vk::RenderingAttachmentInfo::default()
        .image_view(depth.view())
        .image_layout(vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::DONT_CARE)
        .clear_value(vk::ClearValue {
            depth_stencil: vk::ClearDepthStencilValue {
                depth: 1.0,
                stencil: 0,
            },
        });
    let rendering = vk::RenderingInfo::default()
        .render_area(vk::Rect2D {
            offset: vk::Offset2D { x: 0, y: 0 },
            extent: vk::Extent2D {
                width: size,
                height: size,
            },
        })
        .layer_count(1)
        .color_attachments(&color_attachment)
        .depth_attachment(&depth_attachment);
    // SAFETY: the caller's contract; the barriers and attachments name live images.
    unsafe {
        device.cmd_pipeline_barrier(
            cb,
            vk::PipelineStageFlags::TOP_OF_PIPE,
            vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT | tests,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &barriers,
        );
        device.cmd_begin_rendering(cb, &rendering);
    }
}

/// The color image copied into `readback` for the host to read after the fence.
///
/// # Safety
///
/// `cb` is recording, after the pass that wrote `color`; both are alive and large enough.
unsafe fn copy_out(device: &ash::Device, cb: vk::CommandBuffer, color: &Image, readback: &Buffer, size: u32) {
    let to_transfer = vk::ImageMemoryBarrier::default()
        .src_access_mask(vk::AccessFlags::COLOR_ATTACHMENT_WRITE)
        .dst_access_mask(vk::AccessFlags::TRANSFER_READ)
        .old_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .new_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)
        .image(color.raw())
        .subresource_range(color_range(vk::ImageAspectFlags::COLOR));
    let region = vk::BufferImageCopy::default()
        .image_subresource(vk::ImageSubresourceLayers {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            mip_level: 0,
            base_array_layer: 0,
            layer_count: 1,
        })
        .image_extent(vk::Extent3D {
            width: size,
            height: size,
            depth: 1,
        });
    let to_host = vk::BufferMemoryBarrier::default()
        .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
        .dst_access_mask(vk::AccessFlags::HOST_READ)
        .buffer(readback.raw())
        .size(vk::WHOLE_SIZE);
    // SAFETY: the caller's contract.
    unsafe {
        device.cmd_pipeline_barrier(
            cb,
            vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            vk::PipelineStageFlags::TRANSFER,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[to_transfer],
        );
        device.cmd_copy_image_to_buffer(
            cb,
            color.raw(),
            vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            readback.raw(),
            &[region],
        );
        device.cmd_pipeline_barrier(
            cb,
            vk::PipelineStageFlags::TRANSFER,
            vk::PipelineStageFlags::HOST,
            vk::DependencyFlags::empty(),
            &[],
            &[to_host],
            &[],
        );
    }
}
