//! Shader modules and the graphics pipelines: one per lighting mode and specialization key,
//! created on first use through a pipeline cache.

use std::collections::HashMap;
use std::sync::Arc;

use ash::vk;

use crate::error::{Error, Result};
use crate::gl::state::LightingMode;
use crate::gpu::layout::{SpecConstant, SpecKey, SPEC_CONSTANT_COUNT};
use crate::gpu::shaders;
use crate::mesh::Vertex;
use crate::vk::objects::{DescriptorSetLayout, Pipeline, PipelineCache, PipelineLayout, ShaderModule};
use crate::vk::Device;

/// The color image's format: 8 bits per channel, linear UNORM (no sRGB encoding), so a
/// color component c in [0, 1] is stored as c × 255, as in a default GL framebuffer.
pub const COLOR_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;
/// The depth buffer's format: 32-bit float, cleared to 1 and tested with LESS.
pub const DEPTH_FORMAT: vk::Format = vk::Format::D32_SFLOAT;

/// Whether a pipeline specialized by `key` needs only the front primary color between the
/// per-vertex stages: unlit, or one-sided with a single color (the back colors then equal the
/// front ones and the secondary color is (0, 0, 0, 1)). Fewer vertex outputs make lavapipe's
/// vertex pipeline cheaper (BENCHMARKS.md); the uber-shader always passes all four colors.
pub fn one_color(key: SpecKey) -> bool {
    key != SpecKey::UBER
        && (key.get(SpecConstant::Lighting) == 0
            || (key.get(SpecConstant::TwoSide) == 0 && key.get(SpecConstant::SeparateSpecular) == 0))
}

/// The name of the shader variant a mode's pipeline specialized by `key` uses: the mode's
/// name, with `_one_color` when [`one_color`] holds for a per-vertex mode, and with
/// `_current_color` when the mesh has no color array (`color_array` false).
pub fn variant_name(mode: LightingMode, key: SpecKey, color_array: bool) -> &'static str {
    match (mode, one_color(key), color_array) {
        (LightingMode::Vertex, false, true) => "vertex",
        (LightingMode::Vertex, true, true) => "vertex_one_color",
        (LightingMode::Fragment, _, true) => "fragment",
        (LightingMode::Flat, false, true) => "flat",
        (LightingMode::Flat, true, true) => "flat_one_color",
        (LightingMode::Vertex, false, false) => "vertex_current_color",
        (LightingMode::Vertex, true, false) => "vertex_one_color_current_color",
        (LightingMode::Fragment, _, false) => "fragment_current_color",
        (LightingMode::Flat, false, false) => "flat_current_color",
        (LightingMode::Flat, true, false) => "flat_one_color_current_color",
    }
}

/// A shader module from embedded SPIR-V bytes.
fn shader_module(device: &Arc<Device>, name: &str, bytes: &[u8]) -> Result<ShaderModule> {
    let words = ash::util::read_spv(&mut std::io::Cursor::new(bytes))
        .map_err(|e| Error::MissingFeature(format!("valid SPIR-V in {name}: {e}")))?;
    ShaderModule::new(device, &words)
}

/// Which pipelines draws use: variants specialized for their lighting state, or the
/// uber-shader that branches on the uniforms. `ffvk bench` measures both (BENCHMARKS.md):
/// on lavapipe specialized pipelines are faster in every mode, so they are the default.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Specialize {
    /// Specialized pipelines, one per lighting state (compiled on its first draw), up to
    /// [`MAX_AUTO_VARIANTS`] of them; states first seen after that use the uber-shader.
    /// A state keeps the pipeline it got, so frames of one state stay byte-identical.
    #[default]
    Auto,
    /// Every draw uses the pipeline specialized for its state, without a limit.
    Always,
    /// Every draw uses the uber-shader of its mode.
    Never,
}

/// How many specialized pipelines [`Specialize::Auto`] creates before new states fall back
/// to the uber-shader (bounding compile time and memory for programs that churn states).
pub const MAX_AUTO_VARIANTS: usize = 64;

impl Specialize {
    /// Every policy, in declaration order.
    pub const ALL: [Specialize; 3] = [Specialize::Auto, Specialize::Always, Specialize::Never];

    /// Lowercase name (`auto`, `always`, `never`), the one [`str::parse`] accepts.
    pub fn name(self) -> &'static str {
        match self {
            Specialize::Auto => "auto",
            Specialize::Always => "always",
            Specialize::Never => "never",
        }
    }
}

impl std::str::FromStr for Specialize {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Specialize::ALL
            .into_iter()
            .find(|v| v.name() == s)
            .ok_or_else(|| format!("unknown specialization {s:?}: expected auto, always or never"))
    }
}

/// The descriptor layout, pipeline layout, cache and the pipelines made so far.
pub struct Pipelines {
    // Field order is drop order: pipelines before the layouts and cache they were made with.
    pipelines: HashMap<(LightingMode, SpecKey), Pipeline>,
    cache: PipelineCache,
    layout: PipelineLayout,
    set_layout: DescriptorSetLayout,
    device: Arc<Device>,
}

impl Pipelines {
    /// The layouts and an empty cache; pipelines are created by [`Pipelines::get`].
    pub fn new(device: &Arc<Device>) -> Result<Self> {
        let bindings = [vk::DescriptorSetLayoutBinding::default()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT)];
        let set_layout = DescriptorSetLayout::new(device, &bindings)?;
        let layout = PipelineLayout::new(device, &set_layout)?;
        let cache = PipelineCache::new(device)?;
        Ok(Pipelines {
            pipelines: HashMap::new(),
            cache,
            layout,
            set_layout,
            device: device.clone(),
        })
    }

    /// The layout of descriptor set 0 (binding 0: the draw's uniform block, dynamic offset).
    pub fn set_layout(&self) -> &DescriptorSetLayout {
        &self.set_layout
    }

    /// The pipeline layout every pipeline uses.
    pub fn layout(&self) -> vk::PipelineLayout {
        self.layout.raw()
    }

    /// The pipeline of `mode` specialized by `key` ([`SpecKey::UBER`]: the uber-shader),
    /// created on first use.
    pub fn get(&mut self, mode: LightingMode, key: SpecKey) -> Result<vk::Pipeline> {
        if let Some(pipeline) = self.pipelines.get(&(mode, key)) {
            return Ok(pipeline.raw());
        }
        let pipeline = self.create(mode, key)?;
        let raw = pipeline.raw();
        self.pipelines.insert((mode, key), pipeline);
        Ok(raw)
    }

    /// Whether the pipeline of `mode` and `key` exists already.
    pub fn contains(&self, mode: LightingMode, key: SpecKey) -> bool {
        self.pipelines.contains_key(&(mode, key))
    }

    /// How many pipelines exist, and how many of them are specialized.
    pub fn counts(&self) -> (usize, usize) {
        let specialized = self.pipelines.keys().filter(|(_, k)| *k != SpecKey::UBER).count();
        (self.pipelines.len(), specialized)
    }

    fn create(&self, mode: LightingMode, key: SpecKey) -> Result<Pipeline> {
        let device = &self.device;
        let name = variant_name(mode, key, true);
        let variant = shaders::variant(name)
            .ok_or_else(|| Error::MissingFeature(format!("the embedded shader variant {name}")))?;
        let vert = shader_module(device, name, variant.vertex)?;
        let frag = shader_module(device, name, variant.fragment)?;
        // Every constant is an `int` at offset 4 * constant_id of the key; a stage that does
        // not use a constant ignores its entry.
        let entries: [vk::SpecializationMapEntry; SPEC_CONSTANT_COUNT] =
            SpecConstant::ALL.map(|c| vk::SpecializationMapEntry {
                constant_id: c.id(),
                offset: c.id() * 4,
                size: 4,
            });
        let specialization = vk::SpecializationInfo::default()
            .map_entries(&entries)
            .data(bytemuck::bytes_of(&key));
        let mut stages = [
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::VERTEX)
                .module(vert.raw())
                .name(c"main"),
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::FRAGMENT)
                .module(frag.raw())
                .name(c"main"),
        ];
        // The uber-shader is the modules as compiled, every constant at its default.
        if key != SpecKey::UBER {
            for stage in &mut stages {
                *stage = stage.specialization_info(&specialization);
            }
        }
        let vertex_bindings = [vk::VertexInputBindingDescription {
            binding: 0,
            stride: std::mem::size_of::<Vertex>() as u32,
            input_rate: vk::VertexInputRate::VERTEX,
        }];
        let attribute = |location, format, offset: usize| vk::VertexInputAttributeDescription {
            location,
            binding: 0,
            format,
            offset: offset as u32,
        };
        let vertex_attributes = [
            attribute(
                0,
                vk::Format::R32G32B32_SFLOAT,
                std::mem::offset_of!(Vertex, position),
            ),
            attribute(
                1,
                vk::Format::R32G32B32_SFLOAT,
                std::mem::offset_of!(Vertex, normal),
            ),
            attribute(
                2,
                vk::Format::R32G32B32A32_SFLOAT,
                std::mem::offset_of!(Vertex, color),
            ),
        ];
        let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&vertex_bindings)
            .vertex_attribute_descriptions(&vertex_attributes);
        let input_assembly = vk::PipelineInputAssemblyStateCreateInfo::default()
            .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let viewport = vk::PipelineViewportStateCreateInfo::default()
            .viewport_count(1)
            .scissor_count(1);
        // GL's flat shading takes the last vertex of each triangle.
        let mut provoking = vk::PipelineRasterizationProvokingVertexStateCreateInfoEXT::default()
            .provoking_vertex_mode(vk::ProvokingVertexModeEXT::LAST_VERTEX);
        // GL defaults: no culling; counter-clockwise front faces. After the y flip of
        // VK_FROM_GL_CLIP a GL-CCW triangle has positive area in Vulkan's formula, so
        // Vulkan's COUNTER_CLOCKWISE matches GL's FrontFace(CCW).
        let rasterization = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(vk::CullModeFlags::NONE)
            .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
            .line_width(1.0)
            .push_next(&mut provoking);
        let multisample = vk::PipelineMultisampleStateCreateInfo::default()
            .rasterization_samples(vk::SampleCountFlags::TYPE_1);
        let depth = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(true)
            .depth_write_enable(true)
            .depth_compare_op(vk::CompareOp::LESS);
        let blend_attachments = [vk::PipelineColorBlendAttachmentState::default()
            .blend_enable(false)
            .color_write_mask(vk::ColorComponentFlags::RGBA)];
        let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend_attachments);
        let dynamic_states = [
            vk::DynamicState::VIEWPORT,
            vk::DynamicState::SCISSOR,
            vk::DynamicState::DEPTH_TEST_ENABLE,
            vk::DynamicState::DEPTH_WRITE_ENABLE,
        ];
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
        Pipeline::graphics(device, &self.cache, &info)
    }
}
