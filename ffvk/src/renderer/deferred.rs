//! The fragment mode's deferred path ([`FragmentPath::Deferred`]): a G-buffer pass writes
//! what the equation needs at each pixel (the draws through the `fragment_gbuffer` shaders),
//! then a lighting pass (`deferred.frag`, the same `lighting.glsl`) evaluates it once per
//! pixel. The forward path evaluates it for every fragment of every triangle, which on
//! lavapipe means every 4×4 block a triangle touches (BENCHMARKS.md).
//!
//! A frame takes this path only where it gives the forward path's image: every draw in the
//! fragment mode, none blended or textured, with no fog, alpha test or clip plane, and their
//! records in one chunk of the frame slot (the lighting pass reads them by index); any other
//! frame is drawn forward. Its draws may be under up to [`MAX_DEFERRED_STATES`](super::MAX_DEFERRED_STATES) lighting
//! states (a state: a [`StateKey`], its lights, model and projection, with affine modelviews
//! or not): the lighting pass draws one full-screen triangle per state, specialized for it and
//! reading its state block, scissored to the window rectangle its draws' meshes project to;
//! a table of each record's state (binding 6) lets it leave the other states' pixels alone.
//! The G-buffer takes 24 bytes a pixel beside the depth buffer: the draw's record and facing,
//! the normal octahedron-encoded with its length, the depth (the lighting pass rebuilds the
//! eye-space position from it through the projection's inverse) and the color in 16-bit
//! floats (`glsl/gbuffer.glsl`).

use std::collections::HashMap;
use std::sync::Arc;

use ash::vk;

use super::attachments::{area_and_viewport, attachment_barriers, color_attachment, depth_attachment};
use super::frame::Frame;
use super::states::States;
use super::subresource;
use crate::draw::lighting::{Lighting, Staged};
use crate::draw::pipeline::{
    shader_module, spec_entries, with_assembly, with_layout, COLOR_FORMAT, DEPTH_FORMAT, GBUFFER_FORMATS,
};
use crate::error::{Error, Result};
use crate::gpu::layout::{SpecConstant, SpecKey, VK_FROM_GL_CLIP};
use crate::gpu::shaders;
use crate::vk::objects::{
    BufferView, DescriptorPool, DescriptorSetLayout, Pipeline, PipelineLayout, Sampler,
};
use crate::vk::{Buffer, Device, Image, MemoryUse};

/// The lighting pass's push constants: `Pass` in deferred.frag.
#[repr(C)]
#[derive(Debug, Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub(super) struct PassConstants {
    /// The inverse of the state's projection in Vulkan's clip space.
    eye_from_clip: [f32; 16],
    /// 1 / the extent.
    pixel_size: [f32; 2],
    /// The state's index: the pass lights the pixels whose record is of this state.
    state: u32,
    pad: u32,
}

const PUSH_CONSTANTS: [vk::PushConstantRange; 1] = [vk::PushConstantRange {
    stage_flags: vk::ShaderStageFlags::FRAGMENT,
    offset: 0,
    size: std::mem::size_of::<PassConstants>() as u32,
}];

/// Bytes of G-buffer per pixel ([`GBUFFER_FORMATS`]).
pub const GBUFFER_BYTES_PER_PIXEL: u64 = 24;

/// The G-buffer of one size and the descriptor set that names it.
struct GBuffer {
    extent: vk::Extent2D,
    // Field order is drop order: the set's pool before the images it names.
    descriptors: DescriptorPool,
    images: Vec<Image>,
    /// The view of the record buffer and the state table the set names now.
    records: Option<BufferView>,
    table: vk::Buffer,
}

/// The deferred path's objects: made on the first deferred frame, kept with the renderer.
pub(super) struct Deferred {
    // Field order is drop order: pipelines and the G-buffer before the layouts they use.
    /// By specialization key and whether the pass counts its evaluations.
    pipelines: HashMap<(SpecKey, bool), Pipeline>,
    gbuffer: Option<GBuffer>,
    /// The lighting pass's count of the pixels it lit (`deferred_counted`).
    counter: Buffer,
    /// Each record's state, by record index (`record_state` in deferred.frag), written per frame.
    table: Buffer,
    layout: PipelineLayout,
    set_layout: DescriptorSetLayout,
    sampler: Sampler,
    device: Arc<Device>,
}

/// One lighting state's part of the lighting pass.
pub(super) struct StatePass {
    pub(super) pipeline: vk::Pipeline,
    /// The state block's set and dynamic offset.
    pub(super) state: (vk::DescriptorSet, u32),
    pub(super) push: PassConstants,
    /// The window rectangle its draws' pixels lie in.
    pub(super) scissor: vk::Rect2D,
}

/// What a deferred frame's recording needs.
pub(super) struct DeferredPass {
    pub(super) images: [vk::Image; GBUFFER_FORMATS.len()],
    pub(super) views: [vk::ImageView; GBUFFER_FORMATS.len()],
    /// Whether the lighting pass reads the color (color material, or lighting off); else the
    /// G-buffer pass's color attachment is left out (a null view: its writes are dropped).
    pub(super) color: bool,
    /// Per lighting state with pixels on screen, in the order of their first draws.
    pub(super) states: Vec<StatePass>,
    pub(super) layout: vk::PipelineLayout,
    pub(super) set: vk::DescriptorSet,
    /// The evaluation counter, when the pass counts (it is zeroed before the pass).
    pub(super) counter: Option<vk::Buffer>,
}

/// The buffer of the staged draws' records, where the lighting pass can read them: all in one
/// buffer (it binds one), the last within the device's `maxTexelBufferElements` (it fetches
/// them as texels).
pub(super) fn readable_records(staged: &[Staged], device: &Device) -> Option<vk::Buffer> {
    let first = staged.first()?.record_buffer();
    let texels_per_record = u64::from(crate::draw::pipeline::record_stride_on(device) / 16);
    let last = staged.iter().map(Staged::record_index).max()?;
    let texels = (u64::from(last) + 1) * texels_per_record;
    (texels <= u64::from(device.limits.max_texel_buffer_elements)
        && staged.iter().all(|s| s.record_buffer() == first))
    .then_some(first)
}

impl Deferred {
    pub(super) fn new(device: &Arc<Device>) -> Result<Self> {
        let binding = |binding, ty| {
            vk::DescriptorSetLayoutBinding::default()
                .binding(binding)
                .descriptor_type(ty)
                .descriptor_count(1)
                .stage_flags(vk::ShaderStageFlags::FRAGMENT)
        };
        let (image, texels, storage) = (
            vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
            vk::DescriptorType::UNIFORM_TEXEL_BUFFER,
            vk::DescriptorType::STORAGE_BUFFER,
        );
        // The G-buffer, the frame's records, the evaluation counter, the records' states.
        let bindings = [
            binding(0, image),
            binding(1, image),
            binding(4, texels),
            binding(5, storage),
            binding(6, storage),
        ];
        let set_layout = DescriptorSetLayout::new(device, &bindings)?;
        // The lighting pass reads texels where they are (texelFetch): no filtering.
        let sampler = Sampler::new(
            device,
            &vk::SamplerCreateInfo::default()
                .mag_filter(vk::Filter::NEAREST)
                .min_filter(vk::Filter::NEAREST)
                .address_mode_u(vk::SamplerAddressMode::CLAMP_TO_EDGE)
                .address_mode_v(vk::SamplerAddressMode::CLAMP_TO_EDGE)
                .address_mode_w(vk::SamplerAddressMode::CLAMP_TO_EDGE),
        )?;
        // Set 0 stays empty until the first pipeline: its layout is the lighting's state
        // block layout, which `pass` is given.
        let empty = DescriptorSetLayout::new(device, &[])?;
        let layout = PipelineLayout::with_push_constants(device, &[&empty, &set_layout], &PUSH_CONSTANTS)?;
        let counter = Buffer::new(
            device,
            "deferred evaluation counter",
            4,
            vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::TRANSFER_DST,
            MemoryUse::Readback,
        )?;
        let table = state_table(device, 1024)?;
        Ok(Deferred {
            pipelines: HashMap::new(),
            gbuffer: None,
            counter,
            table,
            layout,
            set_layout,
            sampler,
            device: device.clone(),
        })
    }

    /// Makes the pipeline layout on the lighting's state block layout (once).
    fn ensure_layout(&mut self, lighting: &Lighting) -> Result<()> {
        if self.pipelines.is_empty() {
            self.layout = PipelineLayout::with_push_constants(
                &self.device,
                &[lighting.state_set_layout(), &self.set_layout],
                &PUSH_CONSTANTS,
            )?;
        }
        Ok(())
    }

    /// The G-buffer for `extent` (made anew when the size changes), checked against the
    /// device's heap first.
    fn ensure_gbuffer(&mut self, extent: vk::Extent2D, records: vk::Buffer) -> Result<()> {
        if self.gbuffer.as_ref().is_none_or(|g| g.extent != extent) {
            self.gbuffer = None;
            let needed = extent.width as u64 * extent.height as u64 * GBUFFER_BYTES_PER_PIXEL;
            // Half the largest device-local heap at most: the targets and meshes need the rest.
            let memory = &self.device.memory;
            let heap = memory.memory_heaps[..memory.memory_heap_count as usize]
                .iter()
                .filter(|h| h.flags.contains(vk::MemoryHeapFlags::DEVICE_LOCAL))
                .map(|h| h.size)
                .max()
                .unwrap_or(0);
            if needed > heap / 2 {
                return Err(Error::TooLarge {
                    what: "the deferred path's G-buffer",
                    bytes: needed,
                    limit: heap / 2,
                    limit_name: "half the largest device-local memory heap",
                });
            }
            let images = GBUFFER_FORMATS
                .iter()
                .map(|&format| {
                    Image::new(
                        &self.device,
                        extent,
                        format,
                        vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::SAMPLED,
                        vk::ImageAspectFlags::COLOR,
                    )
                })
                .collect::<Result<Vec<_>>>()?;
            let sizes = [
                vk::DescriptorPoolSize {
                    ty: vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
                    descriptor_count: GBUFFER_FORMATS.len() as u32,
                },
                vk::DescriptorPoolSize {
                    ty: vk::DescriptorType::UNIFORM_TEXEL_BUFFER,
                    descriptor_count: 1,
                },
                vk::DescriptorPoolSize {
                    ty: vk::DescriptorType::STORAGE_BUFFER,
                    descriptor_count: 2,
                },
            ];
            let descriptors = DescriptorPool::with_one_set(&self.device, &sizes, &self.set_layout)?;
            let infos: Vec<[vk::DescriptorImageInfo; 1]> = images
                .iter()
                .map(|i| {
                    [vk::DescriptorImageInfo {
                        sampler: self.sampler.raw(),
                        image_view: i.view(),
                        image_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
                    }]
                })
                .collect();
            let writes: Vec<vk::WriteDescriptorSet> = infos
                .iter()
                .enumerate()
                .map(|(binding, info)| {
                    vk::WriteDescriptorSet::default()
                        .dst_set(descriptors.set())
                        .dst_binding(binding as u32)
                        .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
                        .image_info(info)
                })
                .collect();
            let counter = [vk::DescriptorBufferInfo {
                buffer: self.counter.raw(),
                offset: 0,
                range: vk::WHOLE_SIZE,
            }];
            let mut writes = writes;
            writes.push(
                vk::WriteDescriptorSet::default()
                    .dst_set(descriptors.set())
                    .dst_binding(5)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .buffer_info(&counter),
            );
            // SAFETY: the set, views, sampler and counter are this device's and alive; no
            // submitted work uses the new set.
            unsafe { self.device.raw.update_descriptor_sets(&writes, &[]) };
            self.gbuffer = Some(GBuffer {
                extent,
                descriptors,
                images,
                records: None,
                table: vk::Buffer::null(),
            });
        }
        let gbuffer = self
            .gbuffer
            .as_mut()
            .ok_or(Error::Internal("no G-buffer after it was made"))?;
        // The records through a view made each frame: the ring may have dropped last frame's
        // chunk and made another, which may reuse its handle.
        let view = BufferView::new(&self.device, records, vk::Format::R32G32B32A32_SFLOAT)?;
        let views = [view.raw()];
        let mut writes = vec![vk::WriteDescriptorSet::default()
            .dst_set(gbuffer.descriptors.set())
            .dst_binding(4)
            .descriptor_type(vk::DescriptorType::UNIFORM_TEXEL_BUFFER)
            .texel_buffer_view(&views)];
        let table = [vk::DescriptorBufferInfo {
            buffer: self.table.raw(),
            offset: 0,
            range: vk::WHOLE_SIZE,
        }];
        // The table is this path's own: a new one is made before the old one is dropped, so
        // its handle names it.
        if gbuffer.table != self.table.raw() {
            writes.push(
                vk::WriteDescriptorSet::default()
                    .dst_set(gbuffer.descriptors.set())
                    .dst_binding(6)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .buffer_info(&table),
            );
            gbuffer.table = self.table.raw();
        }
        // SAFETY: the renderer waited for the last submission, the only user of the set (and
        // of the view it named, dropped below); the records are the lighting's and the table
        // this path's, and both outlive this frame's submission.
        unsafe { self.device.raw.update_descriptor_sets(&writes, &[]) };
        gbuffer.records = Some(view);
        Ok(())
    }

    /// The lighting pass's pipeline for `key`.
    fn pipeline(&mut self, key: SpecKey, counted: bool, cache: vk::PipelineCache) -> Result<vk::Pipeline> {
        if let Some(p) = self.pipelines.get(&(key, counted)) {
            return Ok(p.raw());
        }
        let name = if counted { "deferred_counted" } else { "deferred" };
        let variant = shaders::variant(name)
            .ok_or_else(|| Error::MissingFeature(format!("the embedded shader variant {name}")))?;
        let vert = shader_module(&self.device, name, variant.vertex, 0)?;
        let frag = shader_module(&self.device, name, variant.fragment, 0)?;
        let entries = spec_entries();
        let spec = with_layout(
            with_assembly(key, false, 1.0, crate::draw::pipeline::PointKey::OFF),
            0,
            COLOR_FORMAT,
            &self.device,
        );
        let specialization = vk::SpecializationInfo::default()
            .map_entries(&entries)
            .data(bytemuck::bytes_of(&spec));
        let stages = [
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::VERTEX)
                .module(vert.raw())
                .name(c"main")
                .specialization_info(&specialization),
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::FRAGMENT)
                .module(frag.raw())
                .name(c"main")
                .specialization_info(&specialization),
        ];
        let vertex_input = vk::PipelineVertexInputStateCreateInfo::default();
        let input_assembly = vk::PipelineInputAssemblyStateCreateInfo::default()
            .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let viewport = vk::PipelineViewportStateCreateInfo::default()
            .viewport_count(1)
            .scissor_count(1);
        let rasterization = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(vk::CullModeFlags::NONE)
            .line_width(1.0);
        let multisample = vk::PipelineMultisampleStateCreateInfo::default()
            .rasterization_samples(vk::SampleCountFlags::TYPE_1);
        // The triangle lies at depth 1: it passes GREATER where a draw left a nearer depth, so
        // that blocks of background are culled before the equation runs (and not counted).
        let depth = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(true)
            .depth_write_enable(false)
            .depth_compare_op(vk::CompareOp::GREATER);
        let attachments =
            [vk::PipelineColorBlendAttachmentState::default()
                .color_write_mask(vk::ColorComponentFlags::RGBA)];
        let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&attachments);
        let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
        let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
        let color_formats = [COLOR_FORMAT];
        let mut rendering = vk::PipelineRenderingCreateInfo::default()
            .color_attachment_formats(&color_formats)
            .depth_attachment_format(DEPTH_FORMAT);
        let info = vk::GraphicsPipelineCreateInfo::default()
            .stages(&stages)
            .vertex_input_state(&vertex_input)
            .input_assembly_state(&input_assembly)
            .viewport_state(&viewport)
            .rasterization_state(&rasterization)
            .multisample_state(&multisample)
            .depth_stencil_state(&depth)
            .color_blend_state(&blend)
            .dynamic_state(&dynamic)
            .layout(self.layout.raw())
            .push_next(&mut rendering);
        let pipeline = Pipeline::graphics(&self.device, cache, &info)?;
        let raw = pipeline.raw();
        self.pipelines.insert((key, counted), pipeline);
        Ok(raw)
    }

    /// Everything a deferred frame records with, on targets of `extent`: a lighting pass per
    /// state of `states` (the frame's), its draws staged as `staged` with their records in
    /// `records` (their one buffer).
    pub(super) fn pass(
        &mut self,
        lighting: &Lighting,
        (frame, extent): (&Frame, vk::Extent2D),
        (states, records): (&States, vk::Buffer),
        staged: &[Staged],
        counted: bool,
    ) -> Result<DeferredPass> {
        self.ensure_layout(lighting)?;
        self.write_table(states, staged)?;
        self.ensure_gbuffer(extent, records)?;
        let mut passes = Vec::with_capacity(states.len());
        let mut color = false;
        let scissors = states.scissors(frame, extent);
        for (index, (&(key, first), scissor)) in states.first().iter().zip(scissors).enumerate() {
            let Some(scissor) = scissor else {
                continue;
            };
            let (draw, staged) = frame
                .draws
                .get(first)
                .zip(staged.get(first))
                .ok_or(Error::Internal("a deferred state's first draw is not staged"))?;
            // The inverse in double precision: the projection may be near singular in z.
            let clip = (VK_FROM_GL_CLIP * draw.projection).as_dmat4();
            let push = PassConstants {
                eye_from_clip: clip.inverse().as_mat4().to_cols_array(),
                pixel_size: [1.0 / extent.width as f32, 1.0 / extent.height as f32],
                state: index as u32,
                pad: 0,
            };
            // The uber-shader's -1 reads the block: the color may be needed.
            color |= key.get(SpecConstant::ColorMaterial) != 0 || key.get(SpecConstant::Lighting) != 1;
            passes.push(StatePass {
                pipeline: self.pipeline(key, counted, lighting.pipeline_cache())?,
                state: staged.state_binding(),
                push,
                scissor,
            });
        }
        let gbuffer = self
            .gbuffer
            .as_ref()
            .ok_or(Error::Internal("no G-buffer after it was made"))?;
        let raw = |i: usize| gbuffer.images[i].raw();
        let view = |i: usize| gbuffer.images[i].view();
        Ok(DeferredPass {
            images: [raw(0), raw(1)],
            views: [view(0), view(1)],
            color,
            states: passes,
            layout: self.layout.raw(),
            set: gbuffer.descriptors.set(),
            counter: counted.then(|| self.counter.raw()),
        })
    }

    /// Writes each staged draw's state into the table at its record's index (a larger table
    /// first, where the records reach past this one).
    fn write_table(&mut self, states: &States, staged: &[Staged]) -> Result<()> {
        let most = staged.iter().map(Staged::record_index).max().unwrap_or(0) as usize;
        let mut table = vec![0u32; most + 1];
        for (s, &state) in staged.iter().zip(states.of_draw()) {
            table[s.record_index() as usize] = state;
        }
        let bytes: &[u8] = bytemuck::cast_slice(&table);
        if (bytes.len() as u64) > self.table.size() {
            // The set names the old table until ensure_gbuffer writes the new one; the
            // renderer waited for the last submission, the only one that read it.
            self.table = state_table(&self.device, table.len().next_power_of_two())?;
        }
        self.table.write(0, bytes)
    }

    /// The last counted lighting pass's evaluations (after its fence).
    pub(super) fn evaluations(&self) -> Option<u64> {
        let bytes = self.counter.bytes()?;
        Some(u32::from_le_bytes(bytes.get(..4)?.try_into().ok()?) as u64)
    }
}

/// A table of `entries` records' states, written by the host each frame.
fn state_table(device: &Arc<Device>, entries: usize) -> Result<Buffer> {
    Buffer::new(
        device,
        "deferred state table",
        (entries * 4) as u64,
        vk::BufferUsageFlags::STORAGE_BUFFER,
        MemoryUse::Uniforms,
    )
}

/// The G-buffer images' barrier from `old` to `new`.
pub(super) fn gbuffer_barriers(
    pass: &DeferredPass,
    (src_stage, src_access, old): (vk::PipelineStageFlags2, vk::AccessFlags2, vk::ImageLayout),
    (dst_stage, dst_access, new): (vk::PipelineStageFlags2, vk::AccessFlags2, vk::ImageLayout),
) -> [vk::ImageMemoryBarrier2<'static>; GBUFFER_FORMATS.len()] {
    pass.images.map(|image| {
        vk::ImageMemoryBarrier2::default()
            .src_stage_mask(src_stage)
            .src_access_mask(src_access)
            .dst_stage_mask(dst_stage)
            .dst_access_mask(dst_access)
            .old_layout(old)
            .new_layout(new)
            .image(image)
            .subresource_range(subresource(vk::ImageAspectFlags::COLOR))
    })
}

/// Records one deferred frame: the G-buffer pass (the draws, with depth), then the lighting
/// pass over the whole target, inside the statistics query when there is one (the lighting
/// pass alone: its fragment invocations are the equation's evaluations), with a timestamp
/// between the two where `timestamp` names one. Returns the host time the draws took to
/// record.
///
/// # Safety
///
/// As `record::record_pass`; `pass` was made for these targets' extent and these staged draws,
/// which were staged for the G-buffer pass.
pub(super) unsafe fn record_deferred(
    lighting: &Lighting,
    frame: &Frame,
    (lits, staged): (&[crate::draw::lighting::LitDraw], &[Staged]),
    targets: &super::Targets,
    pass: &DeferredPass,
    cmd: vk::CommandBuffer,
    (statistics, timestamp): (Option<vk::QueryPool>, Option<(vk::QueryPool, u32)>),
) -> Result<f64> {
    let vkd = &lighting.device().raw;
    let (area, viewport) = area_and_viewport(targets.extent);
    let color_stage = vk::PipelineStageFlags2::COLOR_ATTACHMENT_OUTPUT;
    let color_write = vk::AccessFlags2::COLOR_ATTACHMENT_WRITE;
    let tests = vk::PipelineStageFlags2::EARLY_FRAGMENT_TESTS | vk::PipelineStageFlags2::LATE_FRAGMENT_TESTS;
    let sampled = (
        vk::PipelineStageFlags2::FRAGMENT_SHADER,
        vk::AccessFlags2::SHADER_SAMPLED_READ,
    );
    // The G-buffer after the last frame's lighting pass read it; the depth and the color
    // image as the forward pass takes them.
    let mut to_attachments: Vec<vk::ImageMemoryBarrier2> = gbuffer_barriers(
        pass,
        (
            sampled.0 | color_stage,
            sampled.1 | color_write,
            vk::ImageLayout::UNDEFINED,
        ),
        (
            color_stage,
            color_write,
            vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
        ),
    )
    .to_vec();
    to_attachments.extend(attachment_barriers(targets));
    // Nothing drawn: a record index of 0 (the lighting pass leaves such pixels alone).
    // The color attachment only where the lighting pass reads it.
    let mut views = pass.views;
    if !pass.color {
        views[1] = vk::ImageView::null();
    }
    let gbuffer_attachments = views.map(|view| {
        vk::RenderingAttachmentInfo::default()
            .image_view(view)
            .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::STORE)
            .clear_value(vk::ClearValue {
                color: vk::ClearColorValue { uint32: [0; 4] },
            })
    });
    // Kept: the lighting pass tests against it.
    let depth_attachment = depth_attachment(targets, vk::AttachmentStoreOp::STORE);
    let gbuffer_pass = vk::RenderingInfo::default()
        .render_area(area)
        .layer_count(1)
        .color_attachments(&gbuffer_attachments)
        .depth_attachment(&depth_attachment);
    let mut to_sampled = gbuffer_barriers(
        pass,
        (
            color_stage,
            color_write,
            vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
        ),
        (sampled.0, sampled.1, vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL),
    )
    .to_vec();
    to_sampled.push(
        vk::ImageMemoryBarrier2::default()
            .src_stage_mask(tests)
            .src_access_mask(vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_WRITE)
            .dst_stage_mask(tests)
            .dst_access_mask(vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_READ)
            .old_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
            .new_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
            .image(targets.depth.raw())
            .subresource_range(subresource(vk::ImageAspectFlags::DEPTH)),
    );
    let color_attachments = [color_attachment(targets, frame)];
    // The G-buffer pass's depth, read by the lighting pass's depth test.
    let depth_read = vk::RenderingAttachmentInfo::default()
        .image_view(targets.depth.view())
        .image_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::LOAD)
        .store_op(vk::AttachmentStoreOp::DONT_CARE);
    let lighting_pass = vk::RenderingInfo::default()
        .render_area(area)
        .layer_count(1)
        .color_attachments(&color_attachments)
        .depth_attachment(&depth_read);

    // SAFETY: the function's contract: cmd records outside any pass; every handle belongs to
    // this device and outlives the submission. The same holds for each block below.
    unsafe {
        vkd.cmd_pipeline_barrier2(
            cmd,
            &vk::DependencyInfo::default().image_memory_barriers(&to_attachments),
        );
        vkd.cmd_begin_rendering(cmd, &gbuffer_pass);
        vkd.cmd_set_viewport(cmd, 0, &[viewport]);
        vkd.cmd_set_scissor(cmd, 0, &[area]);
    }
    let draws_start = std::time::Instant::now();
    // SAFETY: as above, inside the G-buffer pass whose formats the staged G-buffer pipelines
    // were made for; staged[i] was staged for lits[i] in this frame's slot.
    unsafe { lighting.record_staged_run(cmd, staged, lits) };
    let record_ns = draws_start.elapsed().as_nanos() as f64;
    // SAFETY: as above; the G-buffer becomes the lighting pass's input. The timestamp's query
    // was reset; on lavapipe its value is taken at the barrier after it, which waits for the
    // G-buffer pass's rendering (record.rs).
    unsafe {
        vkd.cmd_end_rendering(cmd);
        if let Some((pool, query)) = timestamp {
            vkd.cmd_write_timestamp2(cmd, vk::PipelineStageFlags2::ALL_COMMANDS, pool, query);
        }
        vkd.cmd_pipeline_barrier2(
            cmd,
            &vk::DependencyInfo::default().image_memory_barriers(&to_sampled),
        );
    }
    if let Some(counter) = pass.counter {
        let to_shader = [vk::BufferMemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::CLEAR)
            .src_access_mask(vk::AccessFlags2::TRANSFER_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags2::FRAGMENT_SHADER)
            .dst_access_mask(vk::AccessFlags2::SHADER_STORAGE_READ | vk::AccessFlags2::SHADER_STORAGE_WRITE)
            .buffer(counter)
            .offset(0)
            .size(vk::WHOLE_SIZE)];
        // SAFETY: as above, outside any pass; the counter is the deferred path's, 4 bytes.
        unsafe {
            vkd.cmd_fill_buffer(cmd, counter, 0, vk::WHOLE_SIZE, 0);
            vkd.cmd_pipeline_barrier2(
                cmd,
                &vk::DependencyInfo::default().buffer_memory_barriers(&to_shader),
            );
        }
    }
    if let Some(pool) = statistics {
        // SAFETY: as above; the query was reset before the pass, outside it.
        unsafe { vkd.cmd_begin_query(cmd, pool, 0, vk::QueryControlFlags::empty()) };
    }
    // SAFETY: as above; the lighting pass's pipelines, layout and sets are the deferred
    // path's, each state block's set and offset its draws' own.
    unsafe {
        vkd.cmd_begin_rendering(cmd, &lighting_pass);
        vkd.cmd_set_viewport(cmd, 0, &[viewport]);
        let mut bound = vk::Pipeline::null();
        for state in &pass.states {
            vkd.cmd_set_scissor(cmd, 0, &[state.scissor]);
            if state.pipeline != bound {
                vkd.cmd_bind_pipeline(cmd, vk::PipelineBindPoint::GRAPHICS, state.pipeline);
                bound = state.pipeline;
            }
            vkd.cmd_bind_descriptor_sets(
                cmd,
                vk::PipelineBindPoint::GRAPHICS,
                pass.layout,
                0,
                &[state.state.0, pass.set],
                &[state.state.1],
            );
            vkd.cmd_push_constants(
                cmd,
                pass.layout,
                vk::ShaderStageFlags::FRAGMENT,
                0,
                bytemuck::bytes_of(&state.push),
            );
            vkd.cmd_draw(cmd, 3, 1, 0, 0);
        }
        vkd.cmd_end_rendering(cmd);
    }
    if let Some(pool) = statistics {
        // SAFETY: as above; ends the query begun before the lighting pass.
        unsafe { vkd.cmd_end_query(cmd, pool, 0) };
    }
    if let Some(counter) = pass.counter {
        let to_host = [vk::BufferMemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::FRAGMENT_SHADER)
            .src_access_mask(vk::AccessFlags2::SHADER_STORAGE_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags2::HOST)
            .dst_access_mask(vk::AccessFlags2::HOST_READ)
            .buffer(counter)
            .offset(0)
            .size(vk::WHOLE_SIZE)];
        // SAFETY: as above; the count is read after the fence.
        unsafe {
            vkd.cmd_pipeline_barrier2(
                cmd,
                &vk::DependencyInfo::default().buffer_memory_barriers(&to_host),
            )
        };
    }
    Ok(record_ns)
}
