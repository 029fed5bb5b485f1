//! The caller's vertex layouts ([`VertexInput`], [`Attribute`]): where each of GL's arrays
//! lives, in which format, and how the pipelines read it, the arrays a layout lacks taking
//! GL's current values from the draw's record.

use ash::vk;

use crate::error::{LightingError, Result};
use crate::gl::state::Face;
use crate::gl::texture::MAX_TEXTURE_UNITS;
use crate::gpu::layout::{DrawRecord, RECORD_FIRST_LOCATION, RECORD_LOCATIONS};
use crate::mesh::Vertex;
use crate::vk::Device;

/// Where one vertex attribute comes from: a binding of [`VertexInput::bindings`], the byte
/// offset in its element and the format (one of those the attribute accepts:
/// [`VertexInput::validate`]).
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

/// One material parameter a layout may give per vertex ([`VertexInput::with_material`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum MaterialArray {
    /// `GL_AMBIENT`, RGBA.
    Ambient,
    /// `GL_DIFFUSE`, RGBA.
    Diffuse,
    /// `GL_SPECULAR`, RGBA.
    Specular,
    /// `GL_EMISSION`, RGBA.
    Emission,
    /// `GL_SHININESS`, one value.
    Shininess,
}

impl MaterialArray {
    /// The five, in table 2.10's order.
    pub const ALL: [MaterialArray; 5] = [
        MaterialArray::Ambient,
        MaterialArray::Diffuse,
        MaterialArray::Specular,
        MaterialArray::Emission,
        MaterialArray::Shininess,
    ];

    /// GL's name of the parameter.
    pub fn gl_name(self) -> &'static str {
        match self {
            MaterialArray::Ambient => "GL_AMBIENT",
            MaterialArray::Diffuse => "GL_DIFFUSE",
            MaterialArray::Specular => "GL_SPECULAR",
            MaterialArray::Emission => "GL_EMISSION",
            MaterialArray::Shininess => "GL_SHININESS",
        }
    }
}

/// A layout's per-vertex material arrays of one face, by [`MaterialArray`] in table 2.10's
/// order; `None`: the draw's material for every vertex.
pub type FaceArrays = [Option<Attribute>; 5];

/// The caller's vertex layout: its buffer bindings and where each of GL's arrays lives. The
/// shaders read position at location 0, normal at 1, color at 2 and texture coordinates at 3;
/// where a layout has no array for the normal, the color or the texture coordinates, every
/// vertex takes GL's current value ([`DrawValues`](crate::DrawValues)), which the pipeline
/// reads from the draw's record. One [`Lighting`](crate::Lighting) draws with any number of
/// layouts ([`Lighting::vertex_layout`](crate::Lighting::vertex_layout)).
///
/// ```
/// use ffvk::ash::vk;
/// use ffvk::{Attribute, VertexInput};
///
/// // Positions in their own buffer; normals as bytes (glNormalPointer(GL_BYTE), padded to
/// // four) and RGBA8 colors interleaved in a second one.
/// let binding = |binding, stride| vk::VertexInputBindingDescription {
///     binding,
///     stride,
///     input_rate: vk::VertexInputRate::VERTEX,
/// };
/// let input = VertexInput::new(
///     vec![binding(0, 12), binding(1, 8)],
///     Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
///     Attribute::new(1, 0, vk::Format::R8G8B8A8_SNORM),
/// )
/// .with_color(Some(Attribute::new(1, 4, vk::Format::R8G8B8A8_UNORM)));
/// assert!(input.texcoord.is_none());
/// assert!(input.validate().is_ok());
/// ```
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct VertexInput {
    /// The vertex buffer bindings, in the order draws pass their buffers.
    pub bindings: Vec<vk::VertexInputBindingDescription>,
    /// Object-space position (`glVertexPointer`): 2 to 4 components, missing ones read as
    /// GL reads them (z = 0, w = 1).
    pub position: Attribute,
    /// Object-space normal (`glNormalPointer`); `None`: GL's current normal for every vertex.
    pub normal: Option<Attribute>,
    /// Per-vertex color (`glColorPointer`); `None`: GL's current color for every vertex.
    pub color: Option<Attribute>,
    /// Unit 0's texture coordinates (`glTexCoordPointer`, 1 to 4 components, missing ones
    /// read as t = r = 0, q = 1), read by draws sampling unit 0; `None`: GL's current texture
    /// coordinates of unit 0.
    pub texcoord: Option<Attribute>,
    /// Units 1-3's texture coordinates (`glClientActiveTexture(GL_TEXTUREi)`, then
    /// `glTexCoordPointer`), as `texcoord`; `None`: the unit's current coordinates
    /// (`glMultiTexCoord`).
    pub unit_texcoords: [Option<Attribute>; MAX_TEXTURE_UNITS - 1],
    /// Secondary colors (`glSecondaryColorPointer`: three components; a fourth is ignored),
    /// summed with lighting off under `GL_COLOR_SUM`; `None`: GL's current secondary color.
    pub secondary_color: Option<Attribute>,
    /// Fog coordinates (`glFogCoordPointer`, one float), read with `GL_FOG_COORD_SRC`
    /// `GL_FOG_COORD`; `None`: GL's current fog coordinate.
    pub fog_coord: Option<Attribute>,
    /// Per-vertex front material parameters (Mesa's material attributes: `glMaterial` between
    /// `glBegin` and `glEnd`), each taking the place of the draw's own for that parameter.
    pub front_materials: FaceArrays,
    /// Per-vertex back material parameters, as `front_materials` (read with two-sided
    /// lighting only).
    pub back_materials: FaceArrays,
}

impl PartialEq for VertexInput {
    /// The same bindings (number, stride, rate, in order) and the same attributes.
    fn eq(&self, other: &Self) -> bool {
        // Every field by name: a field added to the layout fails to compile here until it is
        // compared too.
        let VertexInput {
            bindings,
            position,
            normal,
            color,
            texcoord,
            unit_texcoords,
            secondary_color,
            fog_coord,
            front_materials,
            back_materials,
        } = self;
        let binding = |b: &vk::VertexInputBindingDescription| (b.binding, b.stride, b.input_rate);
        bindings
            .iter()
            .map(binding)
            .eq(other.bindings.iter().map(binding))
            && (*position, *normal, *color, *texcoord)
                == (other.position, other.normal, other.color, other.texcoord)
            && (*secondary_color, *fog_coord) == (other.secondary_color, other.fog_coord)
            && *unit_texcoords == other.unit_texcoords
            && (*front_materials, *back_materials) == (other.front_materials, other.back_materials)
    }
}

impl Eq for VertexInput {}

/// Which of GL's arrays an attribute is: what formats it takes and how they convert.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Position,
    Normal,
    Color,
    TexCoord,
    MaterialColor,
    Shininess,
}

/// How one format is read: its size in bytes, its components, and for GL's normalized arrays
/// (normals, colors) given as SNORM, the bits of each component (GL 2.1 converts those as
/// (2c + 1) / (2^b − 1), not as Vulkan's SNORM does: ffvk fetches the SSCALED format and
/// converts in the shader).
#[derive(Debug, Clone, Copy)]
struct Read {
    size: u32,
    components: u32,
    gl_snorm_bits: u32,
    /// The format the pipeline fetches (the SSCALED twin of a GL-converted SNORM format).
    fetch: vk::Format,
}

use vk::Format as F;

/// The formats of 32-bit floats, 1 to 4 components.
const FLOATS: [(vk::Format, u32); 4] = [
    (F::R32_SFLOAT, 1),
    (F::R32G32_SFLOAT, 2),
    (F::R32G32B32_SFLOAT, 3),
    (F::R32G32B32A32_SFLOAT, 4),
];
/// 16-bit integers read as their values (`GL_SHORT` positions and texture coordinates).
const SHORTS: [(vk::Format, u32); 4] = [
    (F::R16_SSCALED, 1),
    (F::R16G16_SSCALED, 2),
    (F::R16G16B16_SSCALED, 3),
    (F::R16G16B16A16_SSCALED, 4),
];
/// Signed normalized integers GL converts itself: (format, SSCALED twin, bits, components).
const GL_SNORM: [(vk::Format, vk::Format, u32, u32); 4] = [
    (F::R8G8B8_SNORM, F::R8G8B8_SSCALED, 8, 3),
    (F::R8G8B8A8_SNORM, F::R8G8B8A8_SSCALED, 8, 4),
    (F::R16G16B16_SNORM, F::R16G16B16_SSCALED, 16, 3),
    (F::R16G16B16A16_SNORM, F::R16G16B16A16_SSCALED, 16, 4),
];
/// Unsigned normalized integers: Vulkan's c / (2^b − 1) is GL's.
const UNORM: [(vk::Format, u32); 4] = [
    (F::R8G8B8_UNORM, 3),
    (F::R8G8B8A8_UNORM, 4),
    (F::R16G16B16_UNORM, 3),
    (F::R16G16B16A16_UNORM, 4),
];
/// Formats earlier versions accepted for every attribute, read as Vulkan reads them (kept for
/// positions and texture coordinates, where GL has no normalized arrays).
const VULKAN_READ: [(vk::Format, u32); 4] = [
    (F::R16G16B16A16_SFLOAT, 4),
    (F::R16G16B16A16_UNORM, 4),
    (F::R8G8B8A8_UNORM, 4),
    (F::B8G8R8A8_UNORM, 4),
];

/// The size in bytes of a format this module knows.
fn size_of(format: vk::Format) -> u32 {
    match format {
        F::R32_SFLOAT => 4,
        F::R32G32_SFLOAT => 8,
        F::R32G32B32_SFLOAT => 12,
        F::R32G32B32A32_SFLOAT => 16,
        F::R16_SSCALED => 2,
        F::R16G16_SSCALED => 4,
        F::R16G16B16_SSCALED | F::R16G16B16_SNORM | F::R16G16B16_UNORM => 6,
        F::R16G16B16A16_SSCALED | F::R16G16B16A16_SNORM | F::R16G16B16A16_UNORM | F::R16G16B16A16_SFLOAT => 8,
        F::R8G8B8_SNORM | F::R8G8B8_UNORM => 3,
        _ => 4,
    }
}

impl Kind {
    /// How this kind of attribute reads `format`, or `None` when it does not take it.
    fn read(self, format: vk::Format) -> Option<Read> {
        let plain = |components| Read {
            size: size_of(format),
            components,
            gl_snorm_bits: 0,
            fetch: format,
        };
        let among =
            |list: &[(vk::Format, u32)]| list.iter().find(|(f, _)| *f == format).map(|&(_, c)| plain(c));
        let gl_snorm = || {
            GL_SNORM
                .iter()
                .find(|s| s.0 == format)
                .map(|&(_, fetch, bits, components)| Read {
                    size: size_of(format),
                    components,
                    gl_snorm_bits: bits,
                    fetch,
                })
        };
        match self {
            // glVertexPointer: 2 to 4 floats or shorts.
            Kind::Position => among(&FLOATS[1..])
                .or_else(|| among(&SHORTS[1..]))
                .or_else(|| among(&VULKAN_READ)),
            // glTexCoordPointer: 1 to 4 floats or shorts.
            Kind::TexCoord => among(&FLOATS)
                .or_else(|| among(&SHORTS))
                .or_else(|| among(&VULKAN_READ)),
            // glNormalPointer: 3 floats, bytes or shorts (bytes and shorts also padded to 4).
            Kind::Normal => among(&FLOATS[2..]).or_else(gl_snorm),
            // glColorPointer: 3 or 4 floats, bytes, unsigned bytes, shorts, unsigned shorts.
            Kind::Color => among(&FLOATS[2..])
                .or_else(gl_snorm)
                .or_else(|| among(&UNORM))
                .or_else(|| among(&[(F::B8G8R8A8_UNORM, 4)])),
            Kind::MaterialColor => among(&FLOATS[3..]),
            Kind::Shininess => among(&FLOATS[..1]),
        }
    }

    /// The formats this kind takes, as Vulkan's C API names them, for messages.
    fn accepted(self) -> String {
        let all = [
            &FLOATS[..],
            &SHORTS[..],
            &UNORM[..],
            &VULKAN_READ[..],
            &GL_SNORM.map(|s| (s.0, s.3))[..],
        ];
        let mut names: Vec<String> = Vec::new();
        for list in all {
            for &(format, _) in list {
                let name = format!("VK_FORMAT_{format:?}");
                if self.read(format).is_some() && !names.contains(&name) {
                    names.push(name);
                }
            }
        }
        names.join(", ")
    }
}

/// What one location of a pipeline reads: the caller's array, or the record at a byte offset.
enum Source {
    Array(Attribute, Read),
    Record(u32, vk::Format),
}

/// The record's byte offset of a field, as a `u32`.
macro_rules! record_offset {
    ($field:ident) => {
        std::mem::offset_of!(DrawRecord, $field) as u32
    };
}

/// The most vertex bindings a layout may have (Vulkan's devices allow 16 to 32, and ffvk's
/// per-draw record takes one more): a caller's count past it is refused before it is read.
pub const MAX_VERTEX_BINDINGS: u32 = 32;

impl VertexInput {
    /// A layout of these `bindings` with position and normal where the attributes say, no
    /// color array (GL's current color), no texture coordinates (GL's current ones) and no
    /// material arrays; the `with_*` methods set the others.
    pub fn new(
        bindings: Vec<vk::VertexInputBindingDescription>,
        position: Attribute,
        normal: Attribute,
    ) -> Self {
        VertexInput {
            bindings,
            position,
            normal: Some(normal),
            color: None,
            texcoord: None,
            unit_texcoords: [None; MAX_TEXTURE_UNITS - 1],
            secondary_color: None,
            fog_coord: None,
            front_materials: [None; 5],
            back_materials: [None; 5],
        }
    }

    /// This layout with a normal array (`glNormalPointer`) at `normal`; `None`: GL's current
    /// normal for every vertex.
    #[must_use]
    pub fn with_normal(mut self, normal: Option<Attribute>) -> Self {
        self.normal = normal;
        self
    }

    /// This layout with a per-vertex color array (`glColorPointer`) at `color`; `None`: GL's
    /// current color for every vertex.
    #[must_use]
    pub fn with_color(mut self, color: Option<Attribute>) -> Self {
        self.color = color;
        self
    }

    /// This layout with texture coordinates (`glTexCoordPointer`) at `texcoord`; `None`:
    /// GL's current texture coordinates for every vertex.
    #[must_use]
    pub fn with_texcoord(mut self, texcoord: Option<Attribute>) -> Self {
        self.texcoord = texcoord;
        self
    }

    /// This layout with units 1-3's texture coordinate arrays (`None`: a unit's current
    /// coordinates for every vertex).
    #[must_use]
    pub fn with_unit_texcoords(mut self, texcoords: [Option<Attribute>; MAX_TEXTURE_UNITS - 1]) -> Self {
        self.unit_texcoords = texcoords;
        self
    }

    /// This layout with a secondary color array (`glSecondaryColorPointer`) at `secondary`;
    /// `None`: GL's current secondary color for every vertex.
    #[must_use]
    pub fn with_secondary_color(mut self, secondary: Option<Attribute>) -> Self {
        self.secondary_color = secondary;
        self
    }

    /// This layout with a fog coordinate array (`glFogCoordPointer`, `R32_SFLOAT`) at `fog`;
    /// `None`: GL's current fog coordinate for every vertex.
    #[must_use]
    pub fn with_fog_coord(mut self, fog: Option<Attribute>) -> Self {
        self.fog_coord = fog;
        self
    }

    /// This layout with material parameter `which` of `face` (`Front`, `Back` or
    /// `FrontAndBack`) given per vertex at `attribute` (RGBA as `R32G32B32A32_SFLOAT`,
    /// shininess as `R32_SFLOAT`); `None`: the draw's own. Drawn in the vertex and flat modes
    /// (the fragment mode refuses such a layout: its materials are the draw's).
    #[must_use]
    pub fn with_material(mut self, face: Face, which: MaterialArray, attribute: Option<Attribute>) -> Self {
        let i = which as usize;
        if face != Face::Back {
            self.front_materials[i] = attribute;
        }
        if face != Face::Front {
            self.back_materials[i] = attribute;
        }
        self
    }

    /// [`Vertex`] interleaved in binding 0: position, normal and color as floats, and texture
    /// coordinates (s, t).
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
            position: attribute(std::mem::offset_of!(Vertex, position), F::R32G32B32_SFLOAT),
            normal: Some(attribute(
                std::mem::offset_of!(Vertex, normal),
                F::R32G32B32_SFLOAT,
            )),
            color: Some(attribute(
                std::mem::offset_of!(Vertex, color),
                F::R32G32B32A32_SFLOAT,
            )),
            texcoord: Some(attribute(
                std::mem::offset_of!(Vertex, texcoord),
                F::R32G32_SFLOAT,
            )),
            unit_texcoords: [None; MAX_TEXTURE_UNITS - 1],
            secondary_color: None,
            fog_coord: None,
            front_materials: [None; 5],
            back_materials: [None; 5],
        }
    }

    /// Whether any material parameter comes from an array.
    pub fn has_material_arrays(&self) -> bool {
        self.front_materials
            .iter()
            .chain(&self.back_materials)
            .any(Option::is_some)
    }

    /// Whether positions may have w ≠ 1 (four components).
    pub(crate) fn positions_have_w(&self) -> bool {
        Kind::Position
            .read(self.position.format)
            .is_none_or(|r| r.components == 4)
    }

    /// Every attribute the layout has, with its name for messages and its kind.
    fn named(&self) -> Vec<(String, Kind, Attribute)> {
        let mut out = vec![("position".to_owned(), Kind::Position, self.position)];
        for (name, kind, a) in [
            ("normal", Kind::Normal, self.normal),
            ("color", Kind::Color, self.color),
            ("texcoord", Kind::TexCoord, self.texcoord),
            ("secondary color", Kind::Color, self.secondary_color),
            ("fog coordinate", Kind::Shininess, self.fog_coord),
        ] {
            if let Some(a) = a {
                out.push((name.to_owned(), kind, a));
            }
        }
        for (i, a) in self.unit_texcoords.iter().enumerate() {
            if let Some(a) = a {
                out.push((format!("unit {} texcoord", i + 1), Kind::TexCoord, *a));
            }
        }
        for (face, arrays) in [("front", &self.front_materials), ("back", &self.back_materials)] {
            for (which, a) in MaterialArray::ALL.iter().zip(arrays) {
                if let Some(a) = a {
                    let kind = if *which == MaterialArray::Shininess {
                        Kind::Shininess
                    } else {
                        Kind::MaterialColor
                    };
                    out.push((format!("{face} {} material", which.gl_name()), kind, *a));
                }
            }
        }
        out
    }

    /// Checks bindings and attributes; errors name the attribute and the value: at most
    /// [`MAX_VERTEX_BINDINGS`] bindings, each once and per vertex; each attribute on one of
    /// them, within one element (offset + size <= stride, or any offset with stride 0, which
    /// reads one element for every vertex), in a format it takes:
    ///
    /// - position (`glVertexPointer`): `R32G32[B32[A32]]_SFLOAT`, `R16G16[B16[A16]]_SSCALED`
    ///   (GL's `GL_SHORT`);
    /// - normal (`glNormalPointer`): `R32G32B32[A32]_SFLOAT`, `R8G8B8[A8]_SNORM` (`GL_BYTE`),
    ///   `R16G16B16[A16]_SNORM` (`GL_SHORT`), the fourth component ignored;
    /// - color (`glColorPointer`): 3 or 4 components as `SFLOAT` (32-bit), `SNORM` or `UNORM`
    ///   (8 or 16 bits: `GL_BYTE`, `GL_UNSIGNED_BYTE`, `GL_SHORT`, `GL_UNSIGNED_SHORT`), and
    ///   `B8G8R8A8_UNORM` (`GL_BGRA`);
    /// - texture coordinates (`glTexCoordPointer`): 1 to 4 components as `R32_SFLOAT`.. or
    ///   `R16_SSCALED`..;
    /// - material arrays: `R32G32B32A32_SFLOAT`, shininess `R32_SFLOAT`.
    ///
    /// Positions and texture coordinates also take `R16G16B16A16_SFLOAT`, `R16G16B16A16_UNORM`,
    /// `R8G8B8A8_UNORM` and `B8G8R8A8_UNORM`, read as Vulkan reads them. Signed normalized
    /// normals and colors are converted as GL 2.1 converts them (table 2.9: (2c + 1) / (2^b −
    /// 1), so that no byte is exactly 0), not as Vulkan's SNORM (max(c / (2^(b−1) − 1), −1)).
    /// GL's `GL_INT`, `GL_UNSIGNED_INT` and `GL_DOUBLE` arrays have no Vulkan vertex format
    /// that reads them as GL does: they are refused (convert them to floats first).
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
        for (name, kind, a) in self.named() {
            let Some(binding) = self.bindings.iter().find(|b| b.binding == a.binding) else {
                return Err(LightingError::UnknownBinding {
                    attribute: name,
                    binding: a.binding,
                    available: self.bindings.iter().map(|b| b.binding).collect(),
                }
                .into());
            };
            let Some(read) = kind.read(a.format) else {
                return Err(LightingError::AttributeFormat {
                    attribute: name,
                    format: a.format,
                    expected: kind.accepted(),
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
            if a.offset.checked_add(read.size).is_none_or(|end| end > limit) {
                return Err(LightingError::AttributeOffset {
                    attribute: name,
                    offset: a.offset,
                    format: a.format,
                    size: read.size,
                    binding: a.binding,
                    stride: binding.stride,
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
    /// (per instance, `record_stride` bytes apart: a draw's `firstInstance` picks its record).
    pub fn binding_descriptions(&self, record_stride: u32) -> Vec<vk::VertexInputBindingDescription> {
        let mut out = self.bindings.clone();
        out.push(vk::VertexInputBindingDescription {
            binding: self.record_binding(),
            stride: record_stride,
            input_rate: vk::VertexInputRate::INSTANCE,
        });
        out
    }

    /// Checks that `device` can take this layout with the record beside it: bindings, strides,
    /// offsets and locations within its limits, every format (as ffvk fetches it) readable from
    /// vertex buffers.
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
        for (name, kind, a) in self.named() {
            if a.offset > limits.max_vertex_input_attribute_offset {
                return Err(LightingError::VertexLimit {
                    what: format!("the offset of the {name} attribute"),
                    value: a.offset,
                    limit: "maxVertexInputAttributeOffset",
                    max: limits.max_vertex_input_attribute_offset,
                }
                .into());
            }
            let Some(read) = kind.read(a.format) else { continue };
            let buffer = device.format_properties(read.fetch).buffer_features;
            if !buffer.contains(vk::FormatFeatureFlags::VERTEX_BUFFER) {
                return Err(LightingError::VertexFormatUnsupported {
                    attribute: name,
                    format: a.format,
                    fetched: read.fetch,
                }
                .into());
            }
        }
        // The record's locations, then the secondary color's and the fog coordinate's.
        let locations = RECORD_FIRST_LOCATION + RECORD_LOCATIONS + 2;
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

    /// What each location reads, in location order: the caller's arrays, or for those the
    /// layout lacks, the record's current values and materials (locations 1-3, 11-20); the
    /// record's modelview and normal matrix at 4-10. Location 3 only for textured pipelines.
    fn sources(&self, textured: bool) -> Vec<(u32, Source)> {
        // A format validate() did not pass is fetched as given (a pipeline is made only for a
        // validated layout).
        let array = |kind: Kind, a: Attribute| {
            let read = kind.read(a.format).unwrap_or(Read {
                size: 0,
                components: 4,
                gl_snorm_bits: 0,
                fetch: a.format,
            });
            Source::Array(a, read)
        };
        let or_record = |kind, a: Option<Attribute>, offset, format| match a {
            Some(a) => array(kind, a),
            None => Source::Record(offset, format),
        };
        let vec4 = F::R32G32B32A32_SFLOAT;
        let mut out = vec![
            (0, array(Kind::Position, self.position)),
            (
                1,
                or_record(
                    Kind::Normal,
                    self.normal,
                    record_offset!(current_normal),
                    F::R32G32B32_SFLOAT,
                ),
            ),
            (
                2,
                or_record(Kind::Color, self.color, record_offset!(current_color), vec4),
            ),
        ];
        if textured {
            out.push((
                3,
                or_record(
                    Kind::TexCoord,
                    self.texcoord,
                    record_offset!(current_texcoord),
                    vec4,
                ),
            ));
        }
        // The modelview's four columns and the normal matrix's three.
        for i in 0..7 {
            out.push((4 + i, Source::Record(16 * i, vec4)));
        }
        let materials = record_offset!(front);
        for (face, arrays) in [&self.front_materials, &self.back_materials]
            .into_iter()
            .enumerate()
        {
            let face = face as u32;
            for (i, a) in arrays[..4].iter().enumerate() {
                let offset = materials + 64 * face + 16 * i as u32;
                out.push((
                    11 + 4 * face + i as u32,
                    or_record(Kind::MaterialColor, *a, offset, vec4),
                ));
            }
            // The shininesses are the normal matrix's first two columns' w.
            let offset = record_offset!(normal_matrix) + 16 * face + 12;
            out.push((
                19 + face,
                or_record(Kind::Shininess, arrays[4], offset, F::R32_SFLOAT),
            ));
        }
        let current = record_offset!(current_secondary_color);
        out.push((21, or_record(Kind::Color, self.secondary_color, current, vec4)));
        // The current fog coordinate is the current normal's w.
        let current = record_offset!(current_normal) + 12;
        out.push((
            22,
            or_record(Kind::Shininess, self.fog_coord, current, F::R32_SFLOAT),
        ));
        if textured {
            let current = record_offset!(current_unit_texcoords);
            for (i, a) in self.unit_texcoords.iter().enumerate() {
                let offset = current + 16 * i as u32;
                out.push((23 + i as u32, or_record(Kind::TexCoord, *a, offset, vec4)));
            }
        }
        out
    }

    /// The attribute descriptions ffvk's pipelines of this layout use (`textured`: with
    /// location 3): the caller's arrays, and at [`VertexInput::record_binding`] the draw
    /// record's fields, GL's current values among them for the arrays the layout lacks.
    pub fn attributes(&self, textured: bool) -> Vec<vk::VertexInputAttributeDescription> {
        let record = self.record_binding();
        self.sources(textured)
            .into_iter()
            .map(|(location, source)| match source {
                Source::Array(a, Read { fetch, .. }) => vk::VertexInputAttributeDescription {
                    location,
                    binding: a.binding,
                    format: fetch,
                    offset: a.offset,
                },
                Source::Record(offset, format) => vk::VertexInputAttributeDescription {
                    location,
                    binding: record,
                    format,
                    offset,
                },
            })
            .collect()
    }

    /// `SPEC_GL_SNORM` for this layout: a byte per converted attribute (the normal's, the
    /// color's, the secondary color's), b in bits 0-4 and bit 7 when the array has a fourth
    /// component.
    pub(crate) fn gl_snorm_code(&self) -> i32 {
        let code = |kind: Kind, a: Option<Attribute>| {
            a.and_then(|a| kind.read(a.format))
                .filter(|r| r.gl_snorm_bits != 0)
                .map_or(0, |r| r.gl_snorm_bits | if r.components == 4 { 0x80 } else { 0 })
        };
        (code(Kind::Normal, self.normal)
            | code(Kind::Color, self.color) << 8
            | code(Kind::Color, self.secondary_color) << 16) as i32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Where each location of a pipeline reads: (binding, offset, format).
    fn reads(input: &VertexInput, textured: bool) -> Vec<(u32, u32, u32, vk::Format)> {
        input
            .attributes(textured)
            .iter()
            .map(|a| (a.location, a.binding, a.offset, a.format))
            .collect()
    }

    #[test]
    fn the_record_locations_read_the_record_fields_the_shaders_name() {
        let input = VertexInput::interleaved();
        let record = input.record_binding();
        let all = reads(&input, true);
        let at = |location: u32| all.iter().find(|r| r.0 == location).copied();
        let vec4 = F::R32G32B32A32_SFLOAT;
        for column in 0..4 {
            assert_eq!(at(4 + column), Some((4 + column, record, 16 * column, vec4)), "M");
        }
        let nm = std::mem::offset_of!(DrawRecord, normal_matrix) as u32;
        for column in 0..3 {
            assert_eq!(at(8 + column), Some((8 + column, record, nm + 16 * column, vec4)));
        }
        let (front, back) = (
            std::mem::offset_of!(DrawRecord, front) as u32,
            std::mem::offset_of!(DrawRecord, back) as u32,
        );
        for i in 0..4 {
            assert_eq!(at(11 + i), Some((11 + i, record, front + 16 * i, vec4)));
            assert_eq!(at(15 + i), Some((15 + i, record, back + 16 * i, vec4)));
        }
        // The shininesses: the w of the normal matrix's first two columns.
        assert_eq!(at(19), Some((19, record, nm + 12, F::R32_SFLOAT)));
        assert_eq!(at(20), Some((20, record, nm + 28, F::R32_SFLOAT)));
        // Units 1-3's current coordinates, one vec4 each after the secondary color.
        let units = std::mem::offset_of!(DrawRecord, current_unit_texcoords) as u32;
        for i in 0..3 {
            assert_eq!(at(23 + i), Some((23 + i, record, units + 16 * i, vec4)));
        }
        assert_eq!(
            all.len(),
            26,
            "locations 0-25, every unit's texture coordinates included"
        );
    }

    #[test]
    fn arrays_a_layout_lacks_are_read_from_the_records_current_values() {
        let binding = vk::VertexInputBindingDescription {
            binding: 0,
            stride: 12,
            input_rate: vk::VertexInputRate::VERTEX,
        };
        let input = VertexInput::new(
            vec![binding],
            Attribute::new(0, 0, F::R32G32B32_SFLOAT),
            Attribute::new(0, 0, F::R32G32B32_SFLOAT),
        )
        .with_normal(None);
        assert!(input.validate().is_ok());
        let record = input.record_binding();
        assert_eq!(record, 1);
        let all = reads(&input, true);
        let offset = |f: usize| f as u32;
        assert!(all.contains(&(
            1,
            record,
            offset(std::mem::offset_of!(DrawRecord, current_normal)),
            F::R32G32B32_SFLOAT
        )));
        assert!(all.contains(&(
            2,
            record,
            offset(std::mem::offset_of!(DrawRecord, current_color)),
            F::R32G32B32A32_SFLOAT
        )));
        assert!(all.contains(&(
            3,
            record,
            offset(std::mem::offset_of!(DrawRecord, current_texcoord)),
            F::R32G32B32A32_SFLOAT
        )));
        // Untextured pipelines read no texture coordinates.
        assert!(reads(&input, false).iter().all(|r| r.0 != 3));
    }

    #[test]
    fn a_material_array_replaces_the_records_parameter_for_its_faces_only() {
        let binding = vk::VertexInputBindingDescription {
            binding: 0,
            stride: 32,
            input_rate: vk::VertexInputRate::VERTEX,
        };
        let input = VertexInput::new(
            vec![binding],
            Attribute::new(0, 0, F::R32G32B32_SFLOAT),
            Attribute::new(0, 12, F::R32G32B32_SFLOAT),
        )
        .with_material(
            Face::Front,
            MaterialArray::Diffuse,
            Some(Attribute::new(0, 16, F::R32G32B32A32_SFLOAT)),
        )
        .with_material(
            Face::FrontAndBack,
            MaterialArray::Shininess,
            Some(Attribute::new(0, 28, F::R32_SFLOAT)),
        );
        assert!(input.validate().is_ok());
        assert!(input.has_material_arrays());
        let all = reads(&input, false);
        assert!(
            all.contains(&(12, 0, 16, F::R32G32B32A32_SFLOAT)),
            "front diffuse"
        );
        let back_diffuse = std::mem::offset_of!(DrawRecord, back) as u32 + 16;
        assert!(
            all.contains(&(16, 1, back_diffuse, F::R32G32B32A32_SFLOAT)),
            "back diffuse"
        );
        assert!(all.contains(&(19, 0, 28, F::R32_SFLOAT)) && all.contains(&(20, 0, 28, F::R32_SFLOAT)));
    }

    #[test]
    fn signed_normalized_normals_and_colors_are_fetched_scaled_and_converted_as_gl_does() {
        let binding = vk::VertexInputBindingDescription {
            binding: 0,
            stride: 20,
            input_rate: vk::VertexInputRate::VERTEX,
        };
        let input = VertexInput::new(
            vec![binding],
            Attribute::new(0, 0, F::R32G32B32_SFLOAT),
            Attribute::new(0, 12, F::R8G8B8_SNORM),
        )
        .with_color(Some(Attribute::new(0, 16, F::R8G8B8A8_SNORM)));
        assert!(input.validate().is_ok());
        let all = reads(&input, false);
        assert!(all.contains(&(1, 0, 12, F::R8G8B8_SSCALED)));
        assert!(all.contains(&(2, 0, 16, F::R8G8B8A8_SSCALED)));
        // 8 bits each; the color's alpha is the array's too.
        assert_eq!(input.gl_snorm_code(), 8 | (8 | 0x80) << 8);
        let shorts = input
            .clone()
            .with_normal(Some(Attribute::new(0, 16, F::R16G16B16_SNORM)));
        assert!(shorts.validate().is_err(), "6 bytes at 16 end past the stride 20");
        let floats = VertexInput::interleaved();
        assert_eq!(floats.gl_snorm_code(), 0);
    }

    #[test]
    fn a_format_an_array_does_not_take_is_refused_naming_the_attribute_and_the_formats_it_takes() {
        let mut input = VertexInput::interleaved();
        input.normal = Some(Attribute::new(0, 12, F::R32G32_SFLOAT));
        let e = input.validate().unwrap_err().to_string();
        assert!(
            e.contains("the normal attribute has format VK_FORMAT_R32G32_SFLOAT")
                && e.contains("VK_FORMAT_R8G8B8_SNORM")
                && e.contains("VK_FORMAT_R16G16B16A16_SNORM"),
            "{e}"
        );
        let mut input = VertexInput::interleaved();
        input.color = Some(Attribute::new(0, 24, F::R32G32B32A32_UINT));
        let e = input.validate().unwrap_err().to_string();
        assert!(
            e.contains("the color attribute") && e.contains("VK_FORMAT_R8G8B8_UNORM"),
            "{e}"
        );
    }
}
