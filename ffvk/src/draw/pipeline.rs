//! Shader modules and the graphics pipelines: one per lighting mode, specialization key and
//! [`RasterState`], for one target and vertex layout, created on first use through a
//! pipeline cache (the caller's or ffvk's own).

use std::collections::HashMap;
use std::sync::Arc;

use ash::vk;

use crate::draw::formats;
use crate::draw::record::Topology;
use crate::error::{Error, LightingError, Result};
use crate::gl::state::{FixedFunctionState, LightingMode, SpriteOrigin};
use crate::gpu::layout::{SpecConstant, SpecKey, SPEC_CONSTANT_COUNT};
use crate::gpu::shaders;
use crate::vk::objects::{DescriptorSetLayout, Pipeline, PipelineCache, PipelineLayout, ShaderModule};
use crate::vk::Device;

pub use super::raster::{
    Blend, BlendColor, LineStipple, Pixels, PolygonModes, PolygonOffset, RasterState, Stencil, StencilFace,
};
pub use super::stipple::PolygonStipple;
pub use super::target::{Target, COLOR_FORMAT, DEPTH_FORMAT};
pub use super::variants::{
    edges_variant_name, one_color, variant_name, variant_name_staged, SMALL_DRAW_VERTICES,
};
pub use super::vertex_input::{Attribute, FaceArrays, MaterialArray, VertexInput, MAX_VERTEX_BINDINGS};

/// The specialization map of every pipeline: each constant is an `int` at offset
/// 4 × constant_id of the key; a stage that does not use a constant ignores its entry.
pub(crate) fn spec_entries() -> [vk::SpecializationMapEntry; SPEC_CONSTANT_COUNT] {
    SpecConstant::ALL.map(|c| vk::SpecializationMapEntry {
        constant_id: c.id(),
        offset: c.id() * 4,
        size: 4,
    })
}

/// What a points pipeline is made for beyond its size (GL 2.1 §3.3): the attenuation, the
/// clamp and the sprite, as the bits of the constants `SPEC_POINT_ATTENUATION` ..
/// `SPEC_POINT_SPRITE`. Every other pipeline has [`PointKey::OFF`], whatever the state's points
/// say, so that point parameters never split the pipelines of triangles and lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) struct PointKey {
    /// `SPEC_POINT_ATTENUATION` .. `SPEC_POINT_SPRITE`, in `constant_id` order.
    values: [i32; 7],
}

impl PointKey {
    /// The constants' "off" values (the GLSL's defaults).
    pub(crate) const OFF: PointKey = PointKey {
        values: [0, 0x3f80_0000, 0, 0, 0, 0x7f7f_ffff, 0],
    };

    /// Whether the shader may write a size other than the draw's `glPointSize`: attenuated
    /// points whose `GL_POINT_SIZE_MAX` lets them grow past one pixel, or a
    /// `GL_POINT_SIZE_MIN` above one pixel.
    fn varies_the_size(&self) -> bool {
        let float = |i: usize| f32::from_bits(self.values[i] as u32);
        (self.values[0] != 0 && float(5) > 1.0) || float(4) > 1.0
    }

    /// The key of a draw of `topology` under `state` sampling the texture units `units` (a bit
    /// each): `GL_COORD_REPLACE` counts for those units only.
    pub(crate) fn of(state: &FixedFunctionState, topology: Topology, units: u32) -> PointKey {
        if topology != Topology::PointList {
            return PointKey::OFF;
        }
        let p = &state.points;
        let bits = |v: f32| v.to_bits() as i32;
        let attenuated = p.attenuated();
        let abc = if attenuated {
            p.distance_attenuation.to_array()
        } else {
            [1.0, 0.0, 0.0]
        };
        // GL_COORD_REPLACE: unit 0's in bit 1, unit i's in bit 2 + i (texture.glsl, sprite_or).
        let replace = state
            .texture_units
            .iter()
            .enumerate()
            .filter(|&(i, u)| p.sprite && u.coord_replace && units & 1 << i != 0)
            .fold(0, |bits, (i, _)| bits | if i == 0 { 2 } else { 4 << i });
        let sprite = p.sprite as i32 | replace | ((p.sprite_origin == SpriteOrigin::LowerLeft) as i32) << 2;
        PointKey {
            values: [
                attenuated as i32,
                bits(abc[0]),
                bits(abc[1]),
                bits(abc[2]),
                bits(p.size_min),
                bits(p.size_max),
                sprite,
            ],
        }
    }
}

/// `key` with the pipeline's own constants set: the topology's (points or not), the point
/// size (a float constant, passed to every pipeline, the uber-shader's too) and the other
/// point constants ([`PointKey`]).
pub(crate) fn with_assembly(key: SpecKey, points: bool, point_size: f32, point: PointKey) -> SpecKey {
    let mut spec = key;
    spec.values[SpecConstant::Points as usize] = points as i32;
    spec.values[SpecConstant::PointSize as usize] = point_size.to_bits() as i32;
    let first = SpecConstant::PointAttenuation as usize;
    spec.values[first..first + point.values.len()].copy_from_slice(&point.values);
    spec
}

/// `key` with the constants of the vertex layout and the target set: the layout's GL
/// conversions (`SPEC_GL_SNORM`), the record stride on `device` (`SPEC_RECORD_VEC4S`) and the
/// color attachment's alpha precision (`SPEC_ALPHA_BITS`), in every pipeline.
pub(crate) fn with_layout(key: SpecKey, gl_snorm: i32, color_format: vk::Format, device: &Device) -> SpecKey {
    let mut spec = key;
    spec.values[SpecConstant::GlSnorm as usize] = gl_snorm;
    spec.values[SpecConstant::RecordVec4s as usize] = (record_stride_on(device) / 16) as i32;
    spec.values[SpecConstant::AlphaBits as usize] = super::formats::unorm_alpha_bits(color_format) as i32;
    spec
}

/// Bytes between draw records in ffvk's record buffers on `device`.
pub(crate) fn record_stride_on(device: &Device) -> u32 {
    crate::gpu::layout::record_stride(device.limits.min_uniform_buffer_offset_alignment) as u32
}

/// A shader module from embedded SPIR-V bytes, its descriptor set moved to `set`.
pub(crate) fn shader_module(
    device: &Arc<Device>,
    name: &str,
    bytes: &[u8],
    set: u32,
) -> Result<ShaderModule> {
    let mut words = ash::util::read_spv(&mut std::io::Cursor::new(bytes))
        .map_err(|e| Error::MissingFeature(format!("valid SPIR-V in {name}: {e}")))?;
    set_descriptor_set(&mut words, set);
    ShaderModule::new(device, &words)
}

/// Adds `set` to every `OpDecorate … DescriptorSet n` of a SPIR-V module: the GLSL declares
/// its uniform block in set 0 and the texture in set 1, and callers choose where the block
/// goes (the texture follows it). A module cut short ends the walk where its last whole
/// instruction ends.
pub fn set_descriptor_set(words: &mut [u32], set: u32) {
    const OP_DECORATE: u32 = 71;
    const DESCRIPTOR_SET: u32 = 34;
    // The header is 5 words; each instruction starts with (word count << 16) | opcode.
    let mut at = 5;
    while let Some(&first) = words.get(at) {
        let count = (first >> 16) as usize;
        let Some(instruction) = words.get_mut(at..at + count).filter(|_| count > 0) else {
            break;
        };
        if let [op, _target, DESCRIPTOR_SET, n] = instruction {
            if *op & 0xffff == OP_DECORATE {
                *n = n.wrapping_add(set);
            }
        }
        at += count;
    }
}

/// Which pipelines draws use: variants specialized for their lighting state, or the
/// uber-shader that branches on the uniforms. `ffvk bench` measures both (BENCHMARKS.md):
/// on lavapipe specialized pipelines are faster in every mode, so they are the default.
///
/// A "lighting state" here is its specialization key ([`SpecKey`]): the switches and the kinds
/// of the enabled lights, never materials, colors, matrices or light values, so frames of
/// thousands of differently-lit draws use a handful of pipelines. Neither kind of pipeline
/// makes lavapipe 22.3 compile a shader variant per draw (it would for an `if` or a loop bound
/// on uniform values alone: BENCHMARKS.md, "Many draws").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
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
    pub const ALL: &'static [Specialize] = &[Specialize::Auto, Specialize::Always, Specialize::Never];

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
    type Err = crate::error::UnknownName;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Specialize::ALL
            .iter()
            .copied()
            .find(|v| v.name() == s)
            .ok_or_else(|| crate::error::UnknownName::new("specialization", s, "auto, always or never"))
    }
}

/// What every pipeline of one [`Pipelines`] shares.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct PipelineConfig {
    /// The attachments' formats and samples.
    pub target: Target,
    /// The vertex layout.
    pub vertex_input: VertexInput,
    /// The descriptor set index of the uniform block (lower sets are left empty).
    pub set_index: u32,
    /// The caller's pipeline cache; `None` makes one of ffvk's own.
    pub cache: Option<vk::PipelineCache>,
}

with_fields!(PipelineConfig {
    /// Sets [`set_index`](PipelineConfig::set_index).
    with_set_index => set_index: u32,
    /// Sets [`cache`](PipelineConfig::cache).
    with_cache => cache: Option<vk::PipelineCache>,
});

impl PipelineConfig {
    /// Pipelines for `target` and `vertex_input`, the uniform block at set 0, ffvk's own cache.
    pub fn new(target: Target, vertex_input: VertexInput) -> Self {
        PipelineConfig {
            target,
            vertex_input,
            set_index: 0,
            cache: None,
        }
    }

    /// ffvk's offscreen renderer: [`Target::OFFSCREEN`], [`VertexInput::interleaved`], set 0.
    pub fn offscreen() -> Self {
        PipelineConfig {
            target: Target::OFFSCREEN,
            vertex_input: VertexInput::interleaved(),
            set_index: 0,
            cache: None,
        }
    }
}

/// The states every ffvk pipeline takes as dynamic state, all core in Vulkan 1.3: the
/// viewport and scissor (the caller's), and the raster state a draw sets when it is recorded
/// (`DynamicRaster`): culling, front face, the depth test, the stencil test (its enable, ops,
/// masks and reference), the depth bias (its enable and values), line width and blend
/// constants. The rest of [`RasterState`] keys the pipeline.
pub const DYNAMIC_RASTER: [vk::DynamicState; 16] = [
    vk::DynamicState::VIEWPORT,
    vk::DynamicState::SCISSOR,
    vk::DynamicState::CULL_MODE,
    vk::DynamicState::FRONT_FACE,
    vk::DynamicState::DEPTH_TEST_ENABLE,
    vk::DynamicState::DEPTH_WRITE_ENABLE,
    vk::DynamicState::DEPTH_COMPARE_OP,
    vk::DynamicState::DEPTH_BIAS_ENABLE,
    vk::DynamicState::DEPTH_BIAS,
    vk::DynamicState::STENCIL_TEST_ENABLE,
    vk::DynamicState::STENCIL_OP,
    vk::DynamicState::STENCIL_COMPARE_MASK,
    vk::DynamicState::STENCIL_WRITE_MASK,
    vk::DynamicState::STENCIL_REFERENCE,
    vk::DynamicState::LINE_WIDTH,
    vk::DynamicState::BLEND_CONSTANTS,
];

/// What a pipeline is found by.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct PipelineKey {
    /// The vertex layout's number ([`Pipelines::add_layout`]).
    layout: u32,
    mode: LightingMode,
    spec: SpecKey,
    raster: RasterState,
    /// The texture units it samples and applies (`SPEC_TEXTURE_UNITS`); 0 untextured.
    units: u32,
    /// A small draw of the fragment mode (always false in the other modes).
    small: bool,
    /// The primitives its vertices make.
    topology: Topology,
    /// Primitive restart (strips and fans only).
    restart: bool,
    /// The deferred path's G-buffer pass (fragment mode only): four color attachments
    /// ([`GBUFFER_FORMATS`]) instead of the target's one.
    gbuffer: bool,
    /// Renders into the stencil form of the target ([`Target::with_stencil`]): the
    /// Renderer's frames that test the stencil buffer.
    stencil_target: bool,
    /// The draw has user clip planes: the `_clipped` build.
    clipped: bool,
    /// The draw is fogged: the `_fog` build.
    fogged: bool,
    /// The point constants ([`PointKey::OFF`] but for points).
    points: PointKey,
}

/// The G-buffer's attachments, in `fragment.frag`'s output order under `GBUFFER`: the surface
/// (the draw's record index + 1 with the facing in bit 31, the normal's direction
/// octahedron-encoded in two 16-bit SNORM values, its length as a 32-bit float, the fragment's
/// depth as a 32-bit float, from which the lighting pass rebuilds the eye-space position) and
/// the primary color as four 16-bit floats, which color material and unlit draws read. 24
/// bytes a pixel.
pub const GBUFFER_FORMATS: [vk::Format; 2] = [vk::Format::R32G32B32A32_UINT, vk::Format::R32G32_UINT];

/// The descriptor layouts, pipeline layout, cache and the pipelines made so far.
pub struct Pipelines {
    // Field order is drop order: pipelines before the layouts and cache they were made with.
    pipelines: HashMap<PipelineKey, Pipeline>,
    /// The cache pipelines are made through: the caller's, or `own_cache`'s.
    cache: vk::PipelineCache,
    /// ffvk's own cache when the caller passes none; held to be freed with the pipelines.
    _own_cache: Option<PipelineCache>,
    layout: PipelineLayout,
    set_layout: DescriptorSetLayout,
    /// The texture's set, right after `set_layout`'s.
    texture_set_layout: DescriptorSetLayout,
    /// The draw records' set as the fragment mode's fragment stage reads them, after the
    /// texture's.
    record_set_layout: DescriptorSetLayout,
    /// Empty layouts for the sets below `set_index`.
    _lower_sets: Vec<DescriptorSetLayout>,
    config: PipelineConfig,
    /// The vertex layouts, by number: `config.vertex_input` first.
    layouts: Vec<VertexInput>,
    /// The device blends into the target's color format (`COLOR_ATTACHMENT_BLEND`).
    blendable: bool,
    device: Arc<Device>,
}

impl Pipelines {
    /// The layouts and a cache; pipelines are created by [`Pipelines::get`].
    pub fn new(device: &Arc<Device>, config: PipelineConfig) -> Result<Self> {
        config.target.validate()?;
        config.vertex_input.validate()?;
        let blendable = config.target.check_device(device)?;
        config.vertex_input.check_limits(device)?;
        let layouts = vec![config.vertex_input.clone()];
        let bindings = [vk::DescriptorSetLayoutBinding::default()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT)];
        let set_layout = DescriptorSetLayout::new(device, &bindings)?;
        let lower_sets = (0..config.set_index)
            .map(|_| DescriptorSetLayout::new(device, &[]))
            .collect::<Result<Vec<_>>>()?;
        let texture_set_layout = super::texture::set_layout(device)?;
        let record_bindings = [vk::DescriptorSetLayoutBinding::default()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
        let record_set_layout = DescriptorSetLayout::new(device, &record_bindings)?;
        let mut set_layouts: Vec<&DescriptorSetLayout> = lower_sets.iter().collect();
        set_layouts.push(&set_layout);
        set_layouts.push(&texture_set_layout);
        set_layouts.push(&record_set_layout);
        let layout = PipelineLayout::new(device, &set_layouts)?;
        let (cache, own_cache) = match config.cache {
            Some(caller) => (caller, None),
            None => {
                let own = PipelineCache::new(device)?;
                (own.raw(), Some(own))
            }
        };
        Ok(Pipelines {
            pipelines: HashMap::new(),
            cache,
            _own_cache: own_cache,
            layout,
            set_layout,
            texture_set_layout,
            record_set_layout,
            _lower_sets: lower_sets,
            config,
            layouts,
            blendable,
            device: device.clone(),
        })
    }

    /// The layout of the uniform block's descriptor set (binding 0: the draw's block, at a
    /// dynamic offset).
    pub fn set_layout(&self) -> &DescriptorSetLayout {
        &self.set_layout
    }

    /// The layout of a texture's descriptor set (binding 0: a combined image sampler), at the
    /// set after the uniform block's.
    pub fn texture_set_layout(&self) -> &DescriptorSetLayout {
        &self.texture_set_layout
    }

    /// The layout of a record chunk's descriptor set (binding 0: the draw's record, at a
    /// dynamic offset, read by the fragment mode's fragment stage), two sets after the state
    /// block's.
    pub fn record_set_layout(&self) -> &DescriptorSetLayout {
        &self.record_set_layout
    }

    /// The pipeline layout every pipeline uses.
    pub fn layout(&self) -> vk::PipelineLayout {
        self.layout.raw()
    }

    /// What the pipelines share.
    pub fn config(&self) -> &PipelineConfig {
        &self.config
    }

    /// Adds a vertex layout pipelines can be made for, checked as [`Pipelines::new`] checks
    /// the first, and returns its number (0 is the config's); a layout equal to one added
    /// before gets that one's number.
    pub fn add_layout(&mut self, input: VertexInput) -> Result<u32> {
        if let Some(at) = self.layouts.iter().position(|l| *l == input) {
            return Ok(at as u32);
        }
        input.validate()?;
        input.check_limits(&self.device)?;
        self.layouts.push(input);
        Ok(self.layouts.len() as u32 - 1)
    }

    /// Vertex layout number `layout` (0: the config's).
    pub fn vertex_layout(&self, layout: u32) -> Option<&VertexInput> {
        self.layouts.get(layout as usize)
    }

    /// The pipeline of `mode` specialized by `key` ([`SpecKey::UBER`]: the uber-shader) with
    /// `raster`, textured or not, for small draws or not ([`SMALL_DRAW_VERTICES`]; only the
    /// fragment mode tells them apart), created on first use.
    pub fn get(
        &mut self,
        mode: LightingMode,
        key: SpecKey,
        raster: RasterState,
        (textured, small): (bool, bool),
        (topology, restart): (Topology, bool),
    ) -> Result<vk::Pipeline> {
        // Textured: unit 0, sampled and applied.
        let units = if textured { 0x11 } else { 0 };
        self.get_for(
            0,
            (mode, key, raster),
            (units, small),
            (topology, restart),
            (false, false, false, false),
            PointKey::of(&FixedFunctionState::default(), topology, units),
        )
    }

    /// The pipeline cache pipelines are made through.
    pub(crate) fn cache(&self) -> vk::PipelineCache {
        self.cache
    }

    /// [`Pipelines::get`], or (`gbuffer`) the deferred path's G-buffer pipeline of a fragment
    /// mode draw.
    pub(crate) fn get_for(
        &mut self,
        layout: u32,
        (mode, key, raster): (LightingMode, SpecKey, RasterState),
        (units, small): (u32, bool),
        (topology, restart): (Topology, bool),
        (gbuffer, clipped, fogged, stencil_target): (bool, bool, bool, bool),
        points: PointKey,
    ) -> Result<vk::Pipeline> {
        let gbuffer = gbuffer && mode == LightingMode::Fragment;
        let k = PipelineKey {
            layout,
            mode,
            spec: key,
            raster,
            units,
            small: small && mode == LightingMode::Fragment && !gbuffer,
            topology,
            restart,
            gbuffer,
            stencil_target,
            clipped: clipped && !gbuffer,
            fogged: fogged && !gbuffer,
            points,
        };
        if let Some(pipeline) = self.pipelines.get(&k) {
            return Ok(pipeline.raw());
        }
        let pipeline = self.create(k)?;
        let raw = pipeline.raw();
        self.pipelines.insert(k, pipeline);
        Ok(raw)
    }

    /// Checks a draw's whole raster state against the device and target
    /// ([`RasterState::check_device`]): pipelines are made for its keyed part only.
    pub(crate) fn check_raster(
        &self,
        raster: &RasterState,
        (stencil_target, gbuffer): (bool, bool),
    ) -> Result<()> {
        raster
            .check_device(
                &self.device,
                self.config.target,
                (stencil_target, gbuffer, self.blendable),
            )
            .map(|_| ())
    }

    /// Whether the pipeline [`Pipelines::get`] would return for these (and vertex layout
    /// `layout`) exists already.
    pub(crate) fn contains(
        &self,
        layout: u32,
        mode: LightingMode,
        key: SpecKey,
        raster: RasterState,
        (units, small): (u32, bool),
        (topology, restart, points, stencil_target): (Topology, bool, PointKey, bool),
    ) -> bool {
        self.pipelines.contains_key(&PipelineKey {
            layout,
            mode,
            spec: key,
            raster,
            units,
            small: small && mode == LightingMode::Fragment,
            topology,
            restart,
            gbuffer: false,
            stencil_target,
            clipped: key != SpecKey::UBER && key.get(SpecConstant::ClipPlanes) != 0,
            fogged: key != SpecKey::UBER && key.get(SpecConstant::FogMode) > 0,
            points,
        })
    }

    /// How many pipelines exist, and how many of them are specialized.
    pub fn counts(&self) -> (usize, usize) {
        let specialized = self.pipelines.keys().filter(|k| k.spec != SpecKey::UBER).count();
        (self.pipelines.len(), specialized)
    }

    fn create(&self, k: PipelineKey) -> Result<Pipeline> {
        let device = &self.device;
        let config = &self.config;
        let input = self.layouts.get(k.layout as usize).ok_or(Error::Internal(
            "a pipeline key names a vertex layout that was never added",
        ))?;
        if k.mode == LightingMode::Flat && !device.info.provoking_vertex_last {
            return Err(Error::NotEnabled {
                feature: "provokingVertexLast of VK_EXT_provoking_vertex",
                flag: "provoking_vertex_last",
                needed_for: "the flat mode needs (each triangle takes its last vertex's color, as in GL)",
            });
        }
        let (depth_format, mode) = k.raster.check_device(
            device,
            config.target,
            (k.stencil_target, k.gbuffer, self.blendable),
        )?;
        if k.clipped && !device.info.clip_distance {
            return Err(Error::NotEnabled {
                feature: "shaderClipDistance",
                flag: "clip_distance",
                needed_for: "GL's user clip planes (glClipPlane) need",
            });
        }
        if k.mode == LightingMode::Fragment && input.has_material_arrays() {
            let arrays = input.front_materials.iter().map(|a| ("front", a));
            let arrays = arrays.chain(input.back_materials.iter().map(|a| ("back", a)));
            let first = arrays
                .zip(MaterialArray::ALL.iter().cycle())
                .find(|((_, a), _)| a.is_some())
                .map(|((face, _), which)| format!("{face} {} material", which.gl_name()))
                .unwrap_or_default();
            return Err(LightingError::MaterialArraysInFragmentMode { attribute: first }.into());
        }
        if k.points.varies_the_size() && !device.info.large_points {
            return Err(Error::NotEnabled {
                feature: "largePoints",
                flag: "large_points",
                needed_for: "points that may grow past one pixel (GL_POINT_DISTANCE_ATTENUATION with \
                             GL_POINT_SIZE_MAX above 1, or GL_POINT_SIZE_MIN above 1) need",
            });
        }
        if k.restart && !k.topology.restartable() {
            return Err(LightingError::RestartOnList {
                topology: k.topology.gl_name(),
            }
            .into());
        }
        if k.topology == Topology::EdgeFlaggedTriangles && !device.info.geometry_shader {
            return Err(Error::NotEnabled {
                feature: "geometryShader",
                flag: "geometry_shader",
                needed_for: "GL's edge flags (GL_TRIANGLES_ADJACENCY, a triangle list with adjacency) need",
            });
        }
        // Polygons drawn as lines or points with their edge flags: the `_edges` build, whose
        // geometry stage marks the boundary edges. Filled, the adjacency is ignored.
        let edges = k.topology == Topology::EdgeFlaggedTriangles && mode != vk::PolygonMode::FILL;
        let name = if k.gbuffer {
            "fragment_gbuffer".to_owned()
        } else if edges {
            edges_variant_name(k.mode, (k.units != 0, k.small), (k.fogged, k.clipped))
        } else {
            variant_name_staged(k.mode, k.spec, (k.units != 0, k.small), (k.fogged, k.clipped))
        };
        let name = name.as_str();
        let variant = shaders::variant(name)
            .ok_or_else(|| Error::MissingFeature(format!("the embedded shader variant {name}")))?;
        let vert = shader_module(device, name, variant.vertex, config.set_index)?;
        let frag = shader_module(device, name, variant.fragment, config.set_index)?;
        let geom = match variant.geometry {
            Some(spirv) => Some(shader_module(device, name, spirv, config.set_index)?),
            None => None,
        };
        let entries = spec_entries();
        // Points and polygons drawn as points take GL's point size (§3.5.4: their vertices are
        // rasterized as points).
        let spec = with_assembly(
            k.spec,
            k.topology == Topology::PointList || mode == vk::PolygonMode::POINT,
            k.raster.point_size.0,
            k.points,
        );
        let mut spec = with_layout(spec, input.gl_snorm_code(), config.target.color_format, device);
        spec.values[SpecConstant::TextureUnits as usize] = k.units as i32;
        let specialization = vk::SpecializationInfo::default()
            .map_entries(&entries)
            .data(bytemuck::bytes_of(&spec));
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
        // The uber-shader's key leaves every lighting constant at its default (-1).
        stages[0] = stages[0].specialization_info(&specialization);
        let stipple = k.raster.polygon_stipple;
        let (entries, data) =
            super::stipple::fragment_specialization(&entries, bytemuck::bytes_of(&spec), stipple);
        let fragment_specialization = vk::SpecializationInfo::default()
            .map_entries(&entries)
            .data(&data);
        stages[1] = stages[1].specialization_info(&fragment_specialization);
        let mut stages = stages.to_vec();
        // edges.geom's one constant: whether GL_CW is the front face.
        let front_cw = i32::from(k.raster.front_face == vk::FrontFace::CLOCKWISE);
        let geometry_entries = [vk::SpecializationMapEntry::default()
            .constant_id(0)
            .offset(0)
            .size(4)];
        let geometry_specialization = vk::SpecializationInfo::default()
            .map_entries(&geometry_entries)
            .data(bytemuck::bytes_of(&front_cw));
        if let Some(geom) = &geom {
            stages.push(
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::GEOMETRY)
                    .module(geom.raw())
                    .name(c"main")
                    .specialization_info(&geometry_specialization),
            );
        }
        let attributes = input.attributes(k.units != 0);
        let bindings = input.binding_descriptions(record_stride_on(device));
        let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&bindings)
            .vertex_attribute_descriptions(&attributes);
        let input_assembly = vk::PipelineInputAssemblyStateCreateInfo::default()
            .topology(k.topology.vk())
            .primitive_restart_enable(k.restart);
        let viewport = vk::PipelineViewportStateCreateInfo::default()
            .viewport_count(1)
            .scissor_count(1);
        // GL's flat shading takes the last vertex of each triangle. Only flat pipelines ask
        // for it: the other modes interpolate, and a caller's device may lack the feature.
        let mut provoking = vk::PipelineRasterizationProvokingVertexStateCreateInfoEXT::default()
            .provoking_vertex_mode(vk::ProvokingVertexModeEXT::LAST_VERTEX);
        // After the y flip of VK_FROM_GL_CLIP a GL-CCW triangle has positive area in Vulkan's
        // formula, so Vulkan's COUNTER_CLOCKWISE matches GL's FrontFace(CCW).
        // Keys come from RasterState::face_passes: one polygon mode for both faces, and an
        // offset only where the pass's mode is offset.
        let mut rasterization = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(mode)
            .cull_mode(k.raster.cull_mode)
            .front_face(k.raster.front_face)
            .line_width(k.raster.line_width.0);
        if k.mode == LightingMode::Flat {
            rasterization = rasterization.push_next(&mut provoking);
        }
        // GL's aliased lines are its diamond-exit lines (§3.4.1): Vulkan's Bresenham lines,
        // where the device has them, for line primitives and polygon outlines alike (the
        // default lines of some drivers are rectangles, two pixels wide on a diagonal).
        // Stippled, bit (c / factor) mod 16 of the pattern draws fragment c.
        let draws_lines =
            k.topology.is_lines() || (k.topology.is_triangles() && mode == vk::PolygonMode::LINE);
        let mut lines = vk::PipelineRasterizationLineStateCreateInfoEXT::default();
        if draws_lines && device.info.stippled_lines {
            lines = lines.line_rasterization_mode(vk::LineRasterizationModeEXT::BRESENHAM);
            if let Some(l) = k.raster.line_stipple {
                lines = lines
                    .stippled_line_enable(true)
                    .line_stipple_factor(l.factor)
                    .line_stipple_pattern(l.pattern);
            }
            rasterization = rasterization.push_next(&mut lines);
        }
        let multisample =
            vk::PipelineMultisampleStateCreateInfo::default().rasterization_samples(config.target.samples);
        // The depth and stencil tests are dynamic state (DYNAMIC_RASTER).
        let depth = vk::PipelineDepthStencilStateCreateInfo::default();
        let mut blend_attachment =
            vk::PipelineColorBlendAttachmentState::default().color_write_mask(k.raster.color_mask);
        if let Some(b) = k.raster.blend {
            blend_attachment = blend_attachment
                .blend_enable(true)
                .src_color_blend_factor(b.src_color)
                .dst_color_blend_factor(b.dst_color)
                .color_blend_op(b.color_op)
                .src_alpha_blend_factor(b.src_alpha)
                .dst_alpha_blend_factor(b.dst_alpha)
                .alpha_blend_op(b.alpha_op);
        }
        // The G-buffer's four attachments take the values as they are.
        let plain =
            vk::PipelineColorBlendAttachmentState::default().color_write_mask(vk::ColorComponentFlags::RGBA);
        let blend_attachments = if k.gbuffer {
            vec![plain; GBUFFER_FORMATS.len()]
        } else {
            vec![blend_attachment]
        };
        let mut blend = vk::PipelineColorBlendStateCreateInfo::default()
            .attachments(&blend_attachments)
            .blend_constants(k.raster.blend_color.0);
        if let Some(op) = k.raster.logic_op.filter(|_| !k.gbuffer) {
            blend = blend.logic_op_enable(true).logic_op(op);
        }
        let dynamic_states = DYNAMIC_RASTER;
        let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
        let color_formats = if k.gbuffer {
            GBUFFER_FORMATS.to_vec()
        } else {
            vec![config.target.color_format]
        };
        let mut rendering = vk::PipelineRenderingCreateInfo::default()
            .color_attachment_formats(&color_formats)
            .depth_attachment_format(depth_format);
        if formats::has_stencil(depth_format) {
            rendering = rendering.stencil_attachment_format(depth_format);
        }
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
        Pipeline::graphics(device, self.cache, &info)
    }
}
