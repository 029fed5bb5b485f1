//! What the pipelines draw into and read from: the caller's attachments ([`Target`]) and
//! vertex layout ([`VertexInput`], [`Attribute`]), checked against the device.

use ash::vk;

use super::formats;
use crate::error::{LightingError, Result};
use crate::gpu::layout::{DrawRecord, RECORD_FIRST_LOCATION, RECORD_LOCATIONS};
use crate::mesh::Vertex;
use crate::vk::Device;

/// The color image's format: 8 bits per channel, linear UNORM (no sRGB encoding), so a
/// color component c in [0, 1] is stored as c × 255, as in a default GL framebuffer.
pub const COLOR_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;
/// The depth buffer's format: 32-bit float, cleared to 1 and tested with LESS.
pub const DEPTH_FORMAT: vk::Format = vk::Format::D32_SFLOAT;

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

/// Formats whose components a shader reads as floats: what the attributes may use, with
/// their sizes in bytes.
const FLOAT_FORMATS: &[(vk::Format, u32)] = &[
    (vk::Format::R32G32_SFLOAT, 8),
    (vk::Format::R32G32B32_SFLOAT, 12),
    (vk::Format::R32G32B32A32_SFLOAT, 16),
    (vk::Format::R16G16B16A16_SFLOAT, 8),
    (vk::Format::R16G16B16A16_SNORM, 8),
    (vk::Format::R16G16B16A16_UNORM, 8),
    (vk::Format::R8G8B8A8_SNORM, 4),
    (vk::Format::R8G8B8A8_UNORM, 4),
    (vk::Format::B8G8R8A8_UNORM, 4),
    (vk::Format::A2B10G10R10_SNORM_PACK32, 4),
];

/// The most vertex bindings a layout may have (Vulkan's devices allow 16 to 32, and ffvk's
/// per-draw record takes one more): a caller's count past it is refused before it is read.
pub const MAX_VERTEX_BINDINGS: u32 = 32;

impl Target {
    /// Checks the values themselves, before any device is asked: the color format is one the
    /// shaders write as floats, the depth format is `UNDEFINED` or a depth format, and the
    /// samples are one `VkSampleCountFlagBits` bit. Errors name the field and its value.
    pub fn validate(&self) -> std::result::Result<(), LightingError> {
        if !formats::is_float_color(self.color_format) {
            return Err(LightingError::ColorFormat {
                format: self.color_format,
            });
        }
        if self.depth_format != vk::Format::UNDEFINED && !formats::is_depth(self.depth_format) {
            return Err(LightingError::DepthFormat {
                format: self.depth_format,
            });
        }
        if !formats::is_sample_count(self.samples) {
            return Err(LightingError::Samples {
                samples: self.samples,
            });
        }
        Ok(())
    }

    /// Checks that `device` can render into the target: the color format has
    /// `COLOR_ATTACHMENT`, the depth format `DEPTH_STENCIL_ATTACHMENT`, and the samples are
    /// among the device's framebuffer sample counts for each attachment. Returns whether the
    /// color format can be blended into (`COLOR_ATTACHMENT_BLEND`). Call after
    /// [`Target::validate`]: only known formats are asked about.
    pub(super) fn check_device(&self, device: &Device) -> Result<bool> {
        let features = |format| {
            let p = device.format_properties(format);
            p.optimal_tiling_features | p.linear_tiling_features
        };
        let color = features(self.color_format);
        if !color.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT) {
            return Err(LightingError::FormatUnsupported {
                field: "color_format",
                format: self.color_format,
                feature: "COLOR_ATTACHMENT",
            }
            .into());
        }
        let limits = &device.limits;
        let mut counts = vec![(
            "color attachment",
            limits.framebuffer_color_sample_counts,
            "framebufferColorSampleCounts",
        )];
        if self.depth_format != vk::Format::UNDEFINED {
            if !features(self.depth_format).contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT) {
                return Err(LightingError::FormatUnsupported {
                    field: "depth_format",
                    format: self.depth_format,
                    feature: "DEPTH_STENCIL_ATTACHMENT",
                }
                .into());
            }
            counts.push((
                "depth attachment",
                limits.framebuffer_depth_sample_counts,
                "framebufferDepthSampleCounts",
            ));
            if formats::has_stencil(self.depth_format) {
                counts.push((
                    "stencil of the depth attachment",
                    limits.framebuffer_stencil_sample_counts,
                    "framebufferStencilSampleCounts",
                ));
            }
        }
        for (attachment, supported, limit) in counts {
            if !supported.contains(self.samples) {
                return Err(LightingError::SamplesUnsupported {
                    samples: self.samples.as_raw(),
                    attachment,
                    supported: formats::sample_counts(supported),
                    limit,
                }
                .into());
            }
        }
        Ok(color.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT_BLEND))
    }
}

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

    /// Checks bindings and attributes; errors name the attribute and the value: at most
    /// [`MAX_VERTEX_BINDINGS`] bindings, each once and per vertex; each attribute on one of
    /// them, in a format the shaders read as floats, within one element (offset + size <=
    /// stride).
    pub fn validate(&self) -> Result<()> {
        if self.bindings.len() > MAX_VERTEX_BINDINGS as usize {
            return Err(LightingError::TooManyBindings {
                count: self.bindings.len(),
                max: MAX_VERTEX_BINDINGS,
            }
            .into());
        }
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
        for (name, _, attribute) in self.named() {
            let Some(a) = attribute else { continue };
            let Some(binding) = self.bindings.iter().find(|b| b.binding == a.binding) else {
                return Err(LightingError::UnknownBinding {
                    attribute: name,
                    binding: a.binding,
                    available: self.bindings.iter().map(|b| b.binding).collect(),
                }
                .into());
            };
            let Some(&(_, size)) = FLOAT_FORMATS.iter().find(|(f, _)| *f == a.format) else {
                return Err(LightingError::AttributeFormat {
                    attribute: name,
                    format: a.format,
                }
                .into());
            };
            // Stride 0 reads one element for every vertex (a constant attribute, as GL's
            // current values are): the offset then only has to leave room for it.
            let limit = if binding.stride == 0 {
                u32::MAX
            } else {
                binding.stride
            };
            if a.offset.checked_add(size).is_none_or(|end| end > limit) {
                return Err(LightingError::AttributeOffset {
                    attribute: name,
                    offset: a.offset,
                    format: a.format,
                    size,
                    binding: a.binding,
                    stride: binding.stride,
                }
                .into());
            }
        }
        Ok(())
    }

    /// The attributes the layout has, by GL's name, with the name of their format field.
    fn named(&self) -> [(&'static str, &'static str, Option<Attribute>); 4] {
        [
            ("position", "position.format", Some(self.position)),
            ("normal", "normal.format", Some(self.normal)),
            ("color", "color.format", self.color),
            ("texcoord", "texcoord.format", self.texcoord),
        ]
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
    pub(super) fn binding_descriptions(&self) -> Vec<vk::VertexInputBindingDescription> {
        let mut out = self.bindings.clone();
        out.push(vk::VertexInputBindingDescription {
            binding: self.record_binding(),
            stride: std::mem::size_of::<DrawRecord>() as u32,
            input_rate: vk::VertexInputRate::INSTANCE,
        });
        out
    }

    /// Checks that `device` can take this layout with the record beside it.
    pub(super) fn check_limits(&self, device: &Device) -> Result<()> {
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
        for b in &self.bindings {
            if b.stride > limits.max_vertex_input_binding_stride {
                return Err(LightingError::VertexLimit {
                    what: format!("the stride of binding {}", b.binding),
                    value: b.stride,
                    limit: "maxVertexInputBindingStride",
                    max: limits.max_vertex_input_binding_stride,
                }
                .into());
            }
        }
        for (name, field, attribute) in self.named() {
            let Some(a) = attribute else { continue };
            if a.offset > limits.max_vertex_input_attribute_offset {
                return Err(LightingError::VertexLimit {
                    what: format!("the offset of the {name} attribute"),
                    value: a.offset,
                    limit: "maxVertexInputAttributeOffset",
                    max: limits.max_vertex_input_attribute_offset,
                }
                .into());
            }
            let buffer = device.format_properties(a.format).buffer_features;
            if !buffer.contains(vk::FormatFeatureFlags::VERTEX_BUFFER) {
                return Err(LightingError::FormatUnsupported {
                    field,
                    format: a.format,
                    feature: "VERTEX_BUFFER",
                }
                .into());
            }
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
    pub(super) fn attributes(&self, textured: bool) -> Vec<vk::VertexInputAttributeDescription> {
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
