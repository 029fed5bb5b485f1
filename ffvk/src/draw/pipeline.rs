//! Shader modules and the graphics pipelines: one per lighting mode, specialization key and
//! [`RasterState`], for one target and vertex layout, created on first use through a
//! pipeline cache (the caller's or ffvk's own).

use std::collections::HashMap;
use std::sync::Arc;

use ash::vk;

use crate::draw::record::Topology;
use crate::error::{Error, LightingError, Result};
use crate::gl::state::LightingMode;
use crate::gpu::layout::{
    DrawRecord, SpecConstant, SpecKey, RECORD_FIRST_LOCATION, RECORD_LOCATIONS, SPEC_CONSTANT_COUNT,
};
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

/// Draws of fewer indices (or, not indexed, vertices) than this are small: in the fragment mode
/// they pass their materials from the vertex stage as flat varyings (the `fragment_small`
/// variants), so that consecutive small draws bind nothing of their own; larger draws read them
/// from their record as a uniform block bound per draw. On lavapipe a flat varying costs its
/// triangle setup per triangle (about 70 ns for the materials) and a draw's own block about
/// 5 µs: the two meet near 80 triangles.
pub const SMALL_DRAW_VERTICES: u32 = 256;

/// The name of the shader variant a mode's pipeline specialized by `key` uses: the mode's
/// name, with `_small` for a small draw of the fragment mode ([`SMALL_DRAW_VERTICES`]), with
/// `_one_color` when [`one_color`] holds for a per-vertex mode, with `_current_color` when the
/// mesh has no color array (`color_array` false), and with `_textured` when the draw samples
/// a texture.
pub fn variant_name(
    mode: LightingMode,
    key: SpecKey,
    color_array: bool,
    textured: bool,
    small: bool,
) -> String {
    let one = one_color(key) && mode != LightingMode::Fragment;
    format!(
        "{}{}{}{}{}",
        mode.name(),
        if small && mode == LightingMode::Fragment {
            "_small"
        } else {
            ""
        },
        if one { "_one_color" } else { "" },
        if color_array { "" } else { "_current_color" },
        if textured { "_textured" } else { "" },
    )
}

/// A shader module from embedded SPIR-V bytes, its descriptor set moved to `set`.
fn shader_module(device: &Arc<Device>, name: &str, bytes: &[u8], set: u32) -> Result<ShaderModule> {
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

/// The caller's attachments, which every pipeline renders into (dynamic rendering).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Target {
    /// The one color attachment's format.
    pub color_format: vk::Format,
    /// The depth attachment's format; `UNDEFINED` for none (then no draw may test depth).
    pub depth_format: vk::Format,
    /// Samples per pixel of both attachments.
    pub samples: vk::SampleCountFlags,
}

impl Target {
    /// A target of one sample per pixel with these attachment formats (`depth_format`
    /// `UNDEFINED` for no depth attachment); set [`samples`](Target::samples) for more.
    pub fn new(color_format: vk::Format, depth_format: vk::Format) -> Self {
        Target {
            color_format,
            depth_format,
            samples: vk::SampleCountFlags::TYPE_1,
        }
    }

    /// ffvk's offscreen target: [`COLOR_FORMAT`], [`DEPTH_FORMAT`], one sample.
    pub const OFFSCREEN: Target = Target {
        color_format: COLOR_FORMAT,
        depth_format: DEPTH_FORMAT,
        samples: vk::SampleCountFlags::TYPE_1,
    };
}

/// Where one vertex attribute comes from: a binding of [`VertexInput::bindings`], the byte
/// offset in its element and the format (any format the shader can read as floats).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Attribute {
    /// The vertex buffer binding it is read from.
    pub binding: u32,
    /// Byte offset within one element of that binding.
    pub offset: u32,
    /// The attribute's format, e.g. `R32G32B32_SFLOAT` or `R8G8B8A8_UNORM`.
    pub format: vk::Format,
}

/// The caller's vertex layout: its buffer bindings and where each GL attribute lives. The
/// shaders read position at location 0, normal at 1, color at 2 and texture coordinates at 3.
///
/// ```
/// use ffvk::ash::vk;
/// use ffvk::{Attribute, VertexInput};
///
/// // Positions in their own buffer; normals and RGBA8 colors interleaved in a second one.
/// let binding = |binding, stride| vk::VertexInputBindingDescription {
///     binding,
///     stride,
///     input_rate: vk::VertexInputRate::VERTEX,
/// };
/// let input = VertexInput::new(
///     vec![binding(0, 12), binding(1, 16)],
///     Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
///     Attribute::new(1, 0, vk::Format::R32G32B32_SFLOAT),
/// )
/// .with_color(Some(Attribute::new(1, 12, vk::Format::R8G8B8A8_UNORM)));
/// assert!(input.texcoord.is_none());
/// ```
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct VertexInput {
    /// The vertex buffer bindings, in the order draws pass their buffers.
    pub bindings: Vec<vk::VertexInputBindingDescription>,
    /// Object-space position (`glVertexPointer`); missing components read as (x, y, 0, 1).
    pub position: Attribute,
    /// Object-space normal (`glNormalPointer`).
    pub normal: Attribute,
    /// Per-vertex color (`glColorPointer`); `None`: every vertex takes GL's current color
    /// ([`LightingState::current_color`](crate::gl::state::LightingState::current_color)).
    pub color: Option<Attribute>,
    /// Texture coordinates (s, t) (`glTexCoordPointer` with size 2), read at location 3 by
    /// textured draws, which fail without it ([`LightingError::NoTexcoord`]).
    pub texcoord: Option<Attribute>,
}

/// Formats whose components a shader reads as floats: what the attributes may use.
const FLOAT_FORMATS: &[vk::Format] = &[
    vk::Format::R32G32_SFLOAT,
    vk::Format::R32G32B32_SFLOAT,
    vk::Format::R32G32B32A32_SFLOAT,
    vk::Format::R16G16B16A16_SFLOAT,
    vk::Format::R16G16B16A16_SNORM,
    vk::Format::R16G16B16A16_UNORM,
    vk::Format::R8G8B8A8_SNORM,
    vk::Format::R8G8B8A8_UNORM,
    vk::Format::B8G8R8A8_UNORM,
    vk::Format::A2B10G10R10_SNORM_PACK32,
];

impl Attribute {
    /// The attribute at byte `offset` of each element of vertex binding `binding`, in
    /// `format`.
    pub fn new(binding: u32, offset: u32, format: vk::Format) -> Self {
        Attribute {
            binding,
            offset,
            format,
        }
    }
}

impl VertexInput {
    /// A layout of these `bindings` with position and normal where the attributes say, no
    /// color array (GL's current color) and no texture coordinates; set
    /// [`color`](VertexInput::color) and [`texcoord`](VertexInput::texcoord) for those, or use
    /// [`with_color`](VertexInput::with_color) and [`with_texcoord`](VertexInput::with_texcoord).
    pub fn new(
        bindings: Vec<vk::VertexInputBindingDescription>,
        position: Attribute,
        normal: Attribute,
    ) -> Self {
        VertexInput {
            bindings,
            position,
            normal,
            color: None,
            texcoord: None,
        }
    }

    /// This layout with a per-vertex color array (`glColorPointer`) at `color`; `None`: GL's
    /// current color for every vertex.
    #[must_use]
    pub fn with_color(mut self, color: Option<Attribute>) -> Self {
        self.color = color;
        self
    }

    /// This layout with texture coordinates (`glTexCoordPointer`) at `texcoord`; `None`: none
    /// (textured draws then fail with [`LightingError::NoTexcoord`]).
    #[must_use]
    pub fn with_texcoord(mut self, texcoord: Option<Attribute>) -> Self {
        self.texcoord = texcoord;
        self
    }

    /// [`Vertex`] interleaved in binding 0: position, normal and color as floats.
    pub fn interleaved() -> Self {
        let attribute = |offset: usize, format| Attribute {
            binding: 0,
            offset: offset as u32,
            format,
        };
        VertexInput {
            bindings: vec![vk::VertexInputBindingDescription {
                binding: 0,
                stride: std::mem::size_of::<Vertex>() as u32,
                input_rate: vk::VertexInputRate::VERTEX,
            }],
            position: attribute(
                std::mem::offset_of!(Vertex, position),
                vk::Format::R32G32B32_SFLOAT,
            ),
            normal: attribute(std::mem::offset_of!(Vertex, normal), vk::Format::R32G32B32_SFLOAT),
            color: Some(attribute(
                std::mem::offset_of!(Vertex, color),
                vk::Format::R32G32B32A32_SFLOAT,
            )),
            texcoord: Some(attribute(
                std::mem::offset_of!(Vertex, texcoord),
                vk::Format::R32G32_SFLOAT,
            )),
        }
    }

    /// Checks bindings and attributes; errors name the attribute and the value.
    pub fn validate(&self) -> Result<()> {
        for (i, b) in self.bindings.iter().enumerate() {
            if self.bindings[..i].iter().any(|o| o.binding == b.binding) {
                return Err(LightingError::DuplicateBinding { binding: b.binding }.into());
            }
            if b.input_rate != vk::VertexInputRate::VERTEX {
                return Err(LightingError::InputRate {
                    binding: b.binding,
                    rate: b.input_rate,
                }
                .into());
            }
        }
        let named = [
            ("position", Some(self.position)),
            ("normal", Some(self.normal)),
            ("color", self.color),
            ("texcoord", self.texcoord),
        ];
        for (name, attribute) in named {
            let Some(a) = attribute else { continue };
            if !self.bindings.iter().any(|b| b.binding == a.binding) {
                return Err(LightingError::UnknownBinding {
                    attribute: name,
                    binding: a.binding,
                    available: self.bindings.iter().map(|b| b.binding).collect(),
                }
                .into());
            }
            if !FLOAT_FORMATS.contains(&a.format) {
                return Err(LightingError::AttributeFormat {
                    attribute: name,
                    format: a.format,
                }
                .into());
            }
        }
        Ok(())
    }

    /// The binding ffvk reads its per-draw records from: the lowest binding number the
    /// caller's layout leaves free.
    pub fn record_binding(&self) -> u32 {
        (0..)
            .find(|n| self.bindings.iter().all(|b| b.binding != *n))
            .unwrap_or(0)
    }

    /// The binding descriptions the pipelines use: the caller's and the per-draw record's
    /// (per instance: a draw's `firstInstance` picks its record).
    fn binding_descriptions(&self) -> Vec<vk::VertexInputBindingDescription> {
        let mut out = self.bindings.clone();
        out.push(vk::VertexInputBindingDescription {
            binding: self.record_binding(),
            stride: std::mem::size_of::<DrawRecord>() as u32,
            input_rate: vk::VertexInputRate::INSTANCE,
        });
        out
    }

    /// Checks that `device` can take this layout with the record beside it.
    fn check_limits(&self, device: &Device) -> Result<()> {
        let limits = &device.limits;
        let highest = self.bindings.iter().map(|b| b.binding).max().unwrap_or(0);
        let bindings = highest.max(self.record_binding()).saturating_add(1);
        if bindings > limits.max_vertex_input_bindings {
            return Err(LightingError::VertexInputLimit {
                what: "bindings",
                needed: bindings,
                limit: "maxVertexInputBindings",
                max: limits.max_vertex_input_bindings,
            }
            .into());
        }
        let locations = RECORD_FIRST_LOCATION + RECORD_LOCATIONS;
        if locations > limits.max_vertex_input_attributes {
            return Err(LightingError::VertexInputLimit {
                what: "attribute locations",
                needed: locations,
                limit: "maxVertexInputAttributes",
                max: limits.max_vertex_input_attributes,
            }
            .into());
        }
        Ok(())
    }

    /// The attribute descriptions the pipelines use: locations 0, 1, (with a color array) 2
    /// and (textured) 3, then the record's, 4 to 19.
    fn attributes(&self, textured: bool) -> Vec<vk::VertexInputAttributeDescription> {
        let described = |location, a: Attribute| vk::VertexInputAttributeDescription {
            location,
            binding: a.binding,
            format: a.format,
            offset: a.offset,
        };
        let mut out = vec![described(0, self.position), described(1, self.normal)];
        if let Some(color) = self.color {
            out.push(described(2, color));
        }
        if let (true, Some(texcoord)) = (textured, self.texcoord) {
            out.push(described(3, texcoord));
        }
        let binding = self.record_binding();
        out.extend(
            (0..RECORD_LOCATIONS).map(|i| vk::VertexInputAttributeDescription {
                location: RECORD_FIRST_LOCATION + i,
                binding,
                format: vk::Format::R32G32B32A32_SFLOAT,
                offset: 16 * i,
            }),
        );
        out
    }
}

/// A blend equation (`glBlendFuncSeparate`, `glBlendEquationSeparate`) in Vulkan's terms.
///
/// ```
/// use ffvk::ash::vk::{BlendFactor, BlendOp};
/// use ffvk::{Blend, RasterState};
///
/// // glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)
/// let over = RasterState::default().with_blend(Some(Blend::ALPHA));
/// assert_eq!(over.blend, Some(Blend::new(BlendFactor::SRC_ALPHA, BlendFactor::ONE_MINUS_SRC_ALPHA, BlendOp::ADD)));
/// // glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE): add color, keep alpha
/// let add = Blend::separate(
///     (BlendFactor::ONE, BlendFactor::ONE, BlendOp::ADD),
///     (BlendFactor::ZERO, BlendFactor::ONE, BlendOp::ADD),
/// );
/// assert_eq!((add.src_alpha, add.dst_color), (BlendFactor::ZERO, BlendFactor::ONE));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct Blend {
    /// Source factor for RGB.
    pub src_color: vk::BlendFactor,
    /// Destination factor for RGB.
    pub dst_color: vk::BlendFactor,
    /// Equation for RGB.
    pub color_op: vk::BlendOp,
    /// Source factor for alpha.
    pub src_alpha: vk::BlendFactor,
    /// Destination factor for alpha.
    pub dst_alpha: vk::BlendFactor,
    /// Equation for alpha.
    pub alpha_op: vk::BlendOp,
}

impl Blend {
    /// `glBlendFunc(src, dst)` with `glBlendEquation(op)`: the same factors and equation for
    /// color and alpha.
    pub const fn new(src: vk::BlendFactor, dst: vk::BlendFactor, op: vk::BlendOp) -> Self {
        Blend {
            src_color: src,
            dst_color: dst,
            color_op: op,
            src_alpha: src,
            dst_alpha: dst,
            alpha_op: op,
        }
    }

    /// `glBlendFuncSeparate(src_color, dst_color, src_alpha, dst_alpha)` with
    /// `glBlendEquationSeparate(color_op, alpha_op)`.
    pub const fn separate(
        (src_color, dst_color, color_op): (vk::BlendFactor, vk::BlendFactor, vk::BlendOp),
        (src_alpha, dst_alpha, alpha_op): (vk::BlendFactor, vk::BlendFactor, vk::BlendOp),
    ) -> Self {
        Blend {
            src_color,
            dst_color,
            color_op,
            src_alpha,
            dst_alpha,
            alpha_op,
        }
    }

    /// `glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)`, `GL_FUNC_ADD`: the usual
    /// transparency.
    pub const ALPHA: Blend = Blend::new(
        vk::BlendFactor::SRC_ALPHA,
        vk::BlendFactor::ONE_MINUS_SRC_ALPHA,
        vk::BlendOp::ADD,
    );
}

/// The fixed-function state GL keeps beside lighting that Vulkan bakes into a pipeline: part
/// of each draw, and of the key its pipeline is found by. `Default` is GL's initial state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct RasterState {
    /// `GL_CULL_FACE` with `glCullFace`: `NONE` (GL's default: culling disabled).
    pub cull_mode: vk::CullModeFlags,
    /// `glFrontFace`: `COUNTER_CLOCKWISE` is GL's CCW (the default; ffvk's clip-space flip
    /// keeps GL's winding).
    pub front_face: vk::FrontFace,
    /// `GL_DEPTH_TEST`; off by default, as in GL. Needs a depth format in the [`Target`].
    pub depth_test: bool,
    /// `glDepthMask`; on by default. Only written while the depth test is on, as in GL.
    pub depth_write: bool,
    /// `glDepthFunc`; `LESS` by default.
    pub depth_compare: vk::CompareOp,
    /// `GL_BLEND`; `None` (disabled) by default.
    pub blend: Option<Blend>,
    /// `glPointSize`: 1 by default; another size needs the device's `largePoints` and must lie
    /// in its `pointSizeRange`.
    pub point_size: Pixels,
    /// `glLineWidth`: 1 by default; another width needs the device's `wideLines` and must lie
    /// in its `lineWidthRange`.
    pub line_width: Pixels,
}

/// A size in pixels (a point size, a line width), compared and hashed by its bits so that a
/// raster state can key a pipeline.
#[derive(Debug, Clone, Copy)]
pub struct Pixels(pub f32);

impl PartialEq for Pixels {
    fn eq(&self, other: &Self) -> bool {
        self.0.to_bits() == other.0.to_bits()
    }
}

impl Eq for Pixels {}

impl std::hash::Hash for Pixels {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.0.to_bits().hash(state);
    }
}

impl Default for RasterState {
    fn default() -> Self {
        RasterState {
            cull_mode: vk::CullModeFlags::NONE,
            front_face: vk::FrontFace::COUNTER_CLOCKWISE,
            depth_test: false,
            depth_write: true,
            depth_compare: vk::CompareOp::LESS,
            blend: None,
            point_size: Pixels(1.0),
            line_width: Pixels(1.0),
        }
    }
}

impl RasterState {
    /// Sets [`point_size`](RasterState::point_size) (`glPointSize`).
    #[must_use]
    pub fn with_point_size(mut self, size: f32) -> Self {
        self.point_size = Pixels(size);
        self
    }

    /// Sets [`line_width`](RasterState::line_width) (`glLineWidth`).
    #[must_use]
    pub fn with_line_width(mut self, width: f32) -> Self {
        self.line_width = Pixels(width);
        self
    }
}

with_fields!(RasterState {
    /// Sets [`cull_mode`](RasterState::cull_mode) (`glCullFace` with `GL_CULL_FACE` on).
    with_cull_mode => cull_mode: vk::CullModeFlags,
    /// Sets [`front_face`](RasterState::front_face) (`glFrontFace`).
    with_front_face => front_face: vk::FrontFace,
    /// Sets [`depth_test`](RasterState::depth_test) (`GL_DEPTH_TEST`).
    with_depth_test => depth_test: bool,
    /// Sets [`depth_write`](RasterState::depth_write) (`glDepthMask`).
    with_depth_write => depth_write: bool,
    /// Sets [`depth_compare`](RasterState::depth_compare) (`glDepthFunc`).
    with_depth_compare => depth_compare: vk::CompareOp,
    /// Sets [`blend`](RasterState::blend) (`GL_BLEND` and `glBlendFuncSeparate`).
    with_blend => blend: Option<Blend>,
});

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

/// What a pipeline is found by.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct PipelineKey {
    mode: LightingMode,
    spec: SpecKey,
    raster: RasterState,
    textured: bool,
    /// A small draw of the fragment mode (always false in the other modes).
    small: bool,
    /// The primitives its vertices make.
    topology: Topology,
    /// Primitive restart (strips and fans only).
    restart: bool,
}

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
    device: Arc<Device>,
}

impl Pipelines {
    /// The layouts and a cache; pipelines are created by [`Pipelines::get`].
    pub fn new(device: &Arc<Device>, config: PipelineConfig) -> Result<Self> {
        config.vertex_input.validate()?;
        config.vertex_input.check_limits(device)?;
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
        let k = PipelineKey {
            mode,
            spec: key,
            raster,
            textured,
            small: small && mode == LightingMode::Fragment,
            topology,
            restart,
        };
        if let Some(pipeline) = self.pipelines.get(&k) {
            return Ok(pipeline.raw());
        }
        let pipeline = self.create(k)?;
        let raw = pipeline.raw();
        self.pipelines.insert(k, pipeline);
        Ok(raw)
    }

    /// Whether the pipeline [`Pipelines::get`] would return for these exists already.
    pub fn contains(
        &self,
        mode: LightingMode,
        key: SpecKey,
        raster: RasterState,
        (textured, small): (bool, bool),
        (topology, restart): (Topology, bool),
    ) -> bool {
        self.pipelines.contains_key(&PipelineKey {
            mode,
            spec: key,
            raster,
            textured,
            small: small && mode == LightingMode::Fragment,
            topology,
            restart,
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
        if k.mode == LightingMode::Flat && !device.info.provoking_vertex_last {
            return Err(Error::NotEnabled {
                feature: "provokingVertexLast of VK_EXT_provoking_vertex",
                flag: "provoking_vertex_last",
                needed_for: "the flat mode needs (each triangle takes its last vertex's color, as in GL)",
            });
        }
        if k.raster.depth_test && config.target.depth_format == vk::Format::UNDEFINED {
            return Err(LightingError::NoDepthAttachment.into());
        }
        if k.textured && config.vertex_input.texcoord.is_none() {
            return Err(LightingError::NoTexcoord.into());
        }
        for (what, Pixels(size), enabled, range, feature, flag) in [
            (
                "point size",
                k.raster.point_size,
                device.info.large_points,
                device.info.point_size_range,
                "largePoints",
                "large_points",
            ),
            (
                "line width",
                k.raster.line_width,
                device.info.wide_lines,
                device.info.line_width_range,
                "wideLines",
                "wide_lines",
            ),
        ] {
            if !(size > 0.0 && size.is_finite()) {
                return Err(LightingError::RasterSize {
                    what,
                    size: size.to_string(),
                    expected: "a finite size above 0 (GL_INVALID_VALUE in GL)".to_owned(),
                }
                .into());
            }
            if size != 1.0 && !enabled {
                return Err(Error::NotEnabled {
                    feature,
                    flag,
                    needed_for: if what == "point size" {
                        "a point size other than 1 needs"
                    } else {
                        "a line width other than 1 needs"
                    },
                });
            }
            if !(range[0]..=range[1]).contains(&size) {
                return Err(LightingError::RasterSize {
                    what,
                    size: size.to_string(),
                    expected: format!("{} to {}, the device's range", range[0], range[1]),
                }
                .into());
            }
        }
        if k.restart && !k.topology.restartable() {
            return Err(LightingError::RestartOnList {
                topology: k.topology.gl_name(),
            }
            .into());
        }
        let name = variant_name(
            k.mode,
            k.spec,
            config.vertex_input.color.is_some(),
            k.textured,
            k.small,
        );
        let name = name.as_str();
        let variant = shaders::variant(name)
            .ok_or_else(|| Error::MissingFeature(format!("the embedded shader variant {name}")))?;
        let vert = shader_module(device, name, variant.vertex, config.set_index)?;
        let frag = shader_module(device, name, variant.fragment, config.set_index)?;
        // Every constant is an `int` at offset 4 * constant_id of the key; a stage that does
        // not use a constant ignores its entry.
        let entries: [vk::SpecializationMapEntry; SPEC_CONSTANT_COUNT] =
            SpecConstant::ALL.map(|c| vk::SpecializationMapEntry {
                constant_id: c.id(),
                offset: c.id() * 4,
                size: 4,
            });
        // The topology's constants are the pipeline's, not the state's; the point size (a
        // float constant) is passed to every pipeline, the uber-shader's too.
        let mut spec = k.spec;
        spec.values[SpecConstant::Points as usize] = (k.topology == Topology::PointList) as i32;
        spec.values[SpecConstant::PointSize as usize] = k.raster.point_size.0.to_bits() as i32;
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
        for stage in &mut stages {
            *stage = stage.specialization_info(&specialization);
        }
        let attributes = config.vertex_input.attributes(k.textured);
        let bindings = config.vertex_input.binding_descriptions();
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
        let mut rasterization = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(k.raster.cull_mode)
            .front_face(k.raster.front_face)
            .line_width(k.raster.line_width.0);
        if k.mode == LightingMode::Flat {
            rasterization = rasterization.push_next(&mut provoking);
        }
        let multisample =
            vk::PipelineMultisampleStateCreateInfo::default().rasterization_samples(config.target.samples);
        let depth = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(k.raster.depth_test)
            .depth_write_enable(k.raster.depth_test && k.raster.depth_write)
            .depth_compare_op(k.raster.depth_compare);
        let mut blend_attachment =
            vk::PipelineColorBlendAttachmentState::default().color_write_mask(vk::ColorComponentFlags::RGBA);
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
        let blend_attachments = [blend_attachment];
        let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend_attachments);
        let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
        let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
        let color_formats = [config.target.color_format];
        let mut rendering = vk::PipelineRenderingCreateInfo::default()
            .color_attachment_formats(&color_formats)
            .depth_attachment_format(config.target.depth_format);
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
