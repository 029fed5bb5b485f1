//! The floor's pipelines: one per kind of vertex stage (where a draw's record comes from),
//! each with its descriptor set layout and pipeline layout. Nothing of ffvk's pipelines.

use std::io::Cursor;
use std::sync::Arc;

use ash::vk;
use ffvk::vk::objects::{DescriptorSetLayout, Pipeline, ShaderModule};
use ffvk::vk::Device;

use super::context::failed;
use super::scene::RECORD_BYTES;
use crate::{Error, Result};

/// The color and depth formats, ffvk's renderer's.
pub(super) const COLOR_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;
pub(super) const DEPTH_FORMAT: vk::Format = vk::Format::D32_SFLOAT;

/// Where the vertex stage reads a draw's record: one shader build each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// Per-instance vertex attributes (binding 1).
    Instance,
    /// A storage buffer indexed by `gl_DrawID` (plus the batch's first instance).
    Storage,
    /// A dynamic uniform buffer (set 0, binding 1).
    Uniform,
    /// Push constants.
    Push,
}

impl Kind {
    pub(super) const ALL: [Kind; 4] = [Kind::Instance, Kind::Storage, Kind::Uniform, Kind::Push];

    fn spirv(self) -> &'static [u8] {
        match self {
            Kind::Instance => include_bytes!(concat!(env!("OUT_DIR"), "/floor_instance.vert.spv")),
            Kind::Storage => include_bytes!(concat!(env!("OUT_DIR"), "/floor_storage.vert.spv")),
            Kind::Uniform => include_bytes!(concat!(env!("OUT_DIR"), "/floor_uniform.vert.spv")),
            Kind::Push => include_bytes!(concat!(env!("OUT_DIR"), "/floor_push.vert.spv")),
        }
    }

    /// Set 0's binding 1, the record's descriptor, where the kind has one.
    pub(super) fn record_descriptor(self) -> Option<vk::DescriptorType> {
        match self {
            Kind::Storage => Some(vk::DescriptorType::STORAGE_BUFFER),
            Kind::Uniform => Some(vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC),
            Kind::Instance | Kind::Push => None,
        }
    }
}

const FRAGMENT: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/floor.frag.spv"));

/// A pipeline layout, which ffvk's `PipelineLayout` makes without push constants.
pub(super) struct Layout {
    device: ash::Device,
    raw: vk::PipelineLayout,
    /// Keeps `device` alive while this layout lives (the `ash::Device` is a copy of its
    /// handle).
    _owner: Arc<Device>,
}

impl Layout {
    fn new(owner: &Arc<Device>, device: &ash::Device, set: &DescriptorSetLayout, push: bool) -> Result<Self> {
        let sets = [set.raw()];
        let ranges = [vk::PushConstantRange::default()
            .stage_flags(vk::ShaderStageFlags::VERTEX)
            .offset(0)
            .size(RECORD_BYTES as u32)];
        let mut info = vk::PipelineLayoutCreateInfo::default().set_layouts(&sets);
        if push {
            info = info.push_constant_ranges(&ranges);
        }
        // SAFETY: a valid create info on a live device; the set layout is alive.
        let raw = unsafe { device.create_pipeline_layout(&info, None) }
            .map_err(failed("vkCreatePipelineLayout"))?;
        Ok(Layout {
            device: device.clone(),
            raw,
            _owner: owner.clone(),
        })
    }

    pub(super) fn raw(&self) -> vk::PipelineLayout {
        self.raw
    }
}

impl Drop for Layout {
    fn drop(&mut self) {
        // SAFETY: created on this device (kept alive by `_owner`), destroyed once; no pending
        // command uses it (the floor waits for its fence before dropping anything).
        unsafe { self.device.destroy_pipeline_layout(self.raw, None) }
    }
}

/// One kind's pipeline and layouts. Field order is drop order.
pub(super) struct KindPipeline {
    pub(super) kind: Kind,
    pub(super) pipeline: Pipeline,
    pub(super) layout: Layout,
    pub(super) set_layout: DescriptorSetLayout,
}

fn module(device: &Arc<Device>, spirv: &[u8]) -> Result<ShaderModule> {
    let words = ash::util::read_spv(&mut Cursor::new(spirv))
        .map_err(|e| Error::Bench(format!("the floor's SPIR-V: {e}")))?;
    Ok(ShaderModule::new(device, &words)?)
}

/// Vertex bindings and attributes: position and normal from binding 0 (ffvk's `Vertex`,
/// 48 bytes), and for [`Kind::Instance`] the record's eight `vec4`s per instance from binding 1.
fn vertex_input(
    kind: Kind,
) -> (
    Vec<vk::VertexInputBindingDescription>,
    Vec<vk::VertexInputAttributeDescription>,
) {
    let stride = std::mem::size_of::<ffvk::mesh::Vertex>() as u32;
    let mut bindings = vec![vk::VertexInputBindingDescription {
        binding: 0,
        stride,
        input_rate: vk::VertexInputRate::VERTEX,
    }];
    let mut attributes = vec![
        vk::VertexInputAttributeDescription {
            location: 0,
            binding: 0,
            format: vk::Format::R32G32B32_SFLOAT,
            offset: 0,
        },
        vk::VertexInputAttributeDescription {
            location: 1,
            binding: 0,
            format: vk::Format::R32G32B32_SFLOAT,
            offset: 12,
        },
    ];
    if kind == Kind::Instance {
        bindings.push(vk::VertexInputBindingDescription {
            binding: 1,
            stride: RECORD_BYTES as u32,
            input_rate: vk::VertexInputRate::INSTANCE,
        });
        attributes.extend((0..8u32).map(|i| vk::VertexInputAttributeDescription {
            location: 2 + i,
            binding: 1,
            format: vk::Format::R32G32B32A32_SFLOAT,
            offset: 16 * i,
        }));
    }
    (bindings, attributes)
}

/// Every kind's pipeline for images of `size`², drawing into [`COLOR_FORMAT`] and
/// [`DEPTH_FORMAT`] with dynamic rendering: triangles, no culling, depth test LESS.
/// [`Kind::Storage`] only when `storage` (the device has `shaderDrawParameters`).
pub(super) fn pipelines(
    owner: &Arc<Device>,
    device: &ash::Device,
    size: u32,
    storage: bool,
) -> Result<Vec<KindPipeline>> {
    let fragment = module(owner, FRAGMENT)?;
    let mut out = Vec::new();
    for kind in Kind::ALL.into_iter().filter(|&k| storage || k != Kind::Storage) {
        let mut bindings = vec![vk::DescriptorSetLayoutBinding::default()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX)];
        if let Some(ty) = kind.record_descriptor() {
            bindings.push(
                vk::DescriptorSetLayoutBinding::default()
                    .binding(1)
                    .descriptor_type(ty)
                    .descriptor_count(1)
                    .stage_flags(vk::ShaderStageFlags::VERTEX),
            );
        }
        let set_layout = DescriptorSetLayout::new(owner, &bindings)?;
        let layout = Layout::new(owner, device, &set_layout, kind == Kind::Push)?;
        let vertex = module(owner, kind.spirv())?;
        let stages = [
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::VERTEX)
                .module(vertex.raw())
                .name(c"main"),
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::FRAGMENT)
                .module(fragment.raw())
                .name(c"main"),
        ];
        let (vertex_bindings, attributes) = vertex_input(kind);
        let input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&vertex_bindings)
            .vertex_attribute_descriptions(&attributes);
        let assembly = vk::PipelineInputAssemblyStateCreateInfo::default()
            .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let extent = vk::Extent2D {
            width: size,
            height: size,
        };
        let viewports = [vk::Viewport {
            x: 0.0,
            y: 0.0,
            width: size as f32,
            height: size as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        }];
        let scissors = [vk::Rect2D {
            offset: vk::Offset2D { x: 0, y: 0 },
            extent,
        }];
        let viewport = vk::PipelineViewportStateCreateInfo::default()
            .viewports(&viewports)
            .scissors(&scissors);
        let raster = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(vk::CullModeFlags::NONE)
            .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
            .line_width(1.0);
        let multisample = vk::PipelineMultisampleStateCreateInfo::default()
            .rasterization_samples(vk::SampleCountFlags::TYPE_1);
        let depth = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(true)
            .depth_write_enable(true)
            .depth_compare_op(vk::CompareOp::LESS);
        let blend_attachments = [vk::PipelineColorBlendAttachmentState::default().color_write_mask(
            vk::ColorComponentFlags::R
                | vk::ColorComponentFlags::G
                | vk::ColorComponentFlags::B
                | vk::ColorComponentFlags::A,
        )];
        let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend_attachments);
        let color_formats = [COLOR_FORMAT];
        let mut rendering = vk::PipelineRenderingCreateInfo::default()
            .color_attachment_formats(&color_formats)
            .depth_attachment_format(DEPTH_FORMAT);
        let info = vk::GraphicsPipelineCreateInfo::default()
            .stages(&stages)
            .vertex_input_state(&input)
            .input_assembly_state(&assembly)
            .viewport_state(&viewport)
            .rasterization_state(&raster)
            .multisample_state(&multisample)
            .depth_stencil_state(&depth)
            .color_blend_state(&blend)
            .layout(layout.raw())
            .push_next(&mut rendering);
        let pipeline = Pipeline::graphics(owner, vk::PipelineCache::null(), &info)?;
        out.push(KindPipeline {
            kind,
            pipeline,
            layout,
            set_layout,
        });
    }
    Ok(out)
}
