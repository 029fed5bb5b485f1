//! GL 2.1's one texture unit (sections 3.8 and 3.13): the texture image with its parameters,
//! and the texture environment that combines a texel with the lit primary color before the
//! secondary color is added (section 3.9, color sum).
//!
//! What a draw captures splits as in GL: [`TextureUnit`] (`GL_TEXTURE_2D` enabled, the
//! environment, the texture matrix) is part of [`FixedFunctionState`](super::state::FixedFunctionState);
//! the texture object ([`TextureImage`] and [`Sampling`]) is bound per draw.

use glam::{Mat4, Vec4};

use super::errors::StateError;

mod combine;
mod cube;
mod format;
mod texgen;
pub use combine::{AlphaOperand, Combine, CombineFunc, CombineSource, RgbOperand};
pub use cube::{cube_face, CubeFace, CubeImage};
pub use format::BaseFormat;
pub use texgen::{TexCoordGen, TexGenMode};

/// `GL_MAX_TEXTURE_UNITS` (and `GL_MAX_TEXTURE_COORDS`): the texture units a draw applies, in
/// order, each to the previous one's color (§3.8.16). Four, as ANGLE's GLES 1 renderer has; each
/// more costs every textured pipeline a varying, a vertex attribute location and a descriptor.
pub const MAX_TEXTURE_UNITS: usize = 4;

/// `GL_TEXTURE_ENV_MODE` (table 3.22): how the texel C_s, A_s combines with the incoming
/// fragment color C_f, A_f (the lit primary color).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum TexEnvMode {
    /// `GL_MODULATE` (GL's default): C_v = C_f C_s, A_v = A_f A_s.
    #[default]
    Modulate,
    /// `GL_REPLACE`: C_v = C_s, A_v = A_s.
    Replace,
    /// `GL_DECAL`: C_v = C_f (1 − A_s) + C_s A_s, A_v = A_f.
    Decal,
    /// `GL_BLEND`: C_v = C_f (1 − C_s) + C_c C_s, A_v = A_f A_s, C_c the environment color.
    Blend,
    /// `GL_ADD`: C_v = C_f + C_s (clamped to [0, 1]), A_v = A_f A_s.
    Add,
    /// `GL_COMBINE` (§3.8.13): the function [`TextureUnit::combine`] says. Not in
    /// [`TexEnvMode::ALL`], which lists table 3.22's five.
    Combine,
}

impl TexEnvMode {
    /// Every mode, in the order of table 3.22's columns as ffvk lists them.
    pub const ALL: &'static [TexEnvMode] = &[
        TexEnvMode::Modulate,
        TexEnvMode::Replace,
        TexEnvMode::Decal,
        TexEnvMode::Blend,
        TexEnvMode::Add,
    ];

    /// Lowercase name (`modulate`, `replace`, `decal`, `blend`, `add`), the one scene files use.
    pub fn name(self) -> &'static str {
        match self {
            TexEnvMode::Modulate => "modulate",
            TexEnvMode::Replace => "replace",
            TexEnvMode::Decal => "decal",
            TexEnvMode::Blend => "blend",
            TexEnvMode::Add => "add",
            TexEnvMode::Combine => "combine",
        }
    }

    /// The value the shaders' `tex_env_mode` and `SPEC_TEX_ENV` take (`TEV_*` in
    /// `glsl/texture.glsl`).
    pub fn code(self) -> u32 {
        self as u32
    }
}

impl std::str::FromStr for TexEnvMode {
    type Err = super::errors::UnknownName;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        TexEnvMode::ALL
            .iter()
            .copied()
            .find(|m| m.name() == s)
            .ok_or_else(|| {
                super::errors::UnknownName::new(
                    "texture environment",
                    s,
                    "modulate, replace, decal, blend or add",
                )
            })
    }
}

/// The texture unit's state besides the bound texture.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct TextureUnit {
    /// `GL_TEXTURE_2D` (glEnable); off by default. On, with a complete texture bound, every
    /// fragment is textured; on without one (GL's texture object 0 has no image) it is as if
    /// texturing were off (section 3.8.10).
    pub enabled: bool,
    /// `GL_TEXTURE_CUBE_MAP` (glEnable); off by default. It takes precedence over
    /// `GL_TEXTURE_2D` (§3.8.16): on, the unit samples its cube map, and with no complete cube
    /// map bound it textures nothing, whatever its 2D texture.
    pub cube_map: bool,
    /// `GL_TEXTURE_ENV_MODE`; [`TexEnvMode::Modulate`] by default.
    pub env_mode: TexEnvMode,
    /// C_c, `GL_TEXTURE_ENV_COLOR`; (0, 0, 0, 0) by default. Clamped to [0, 1] when set, as GL
    /// does; only [`TexEnvMode::Blend`] reads it.
    pub env_color: Vec4,
    /// The `GL_TEXTURE` matrix: (s, t, 0, 1) is multiplied by it, then s and t are divided by
    /// q per fragment (section 2.11.4). Identity by default.
    pub matrix: Mat4,
    /// `GL_COORD_REPLACE` (glTexEnv with target `GL_POINT_SPRITE`); off by default. On, a point
    /// sprite's fragments take the sprite's (s, t, 0, 1) as this unit's texture coordinates.
    pub coord_replace: bool,
    /// `GL_COMBINE`'s functions, sources, operands and scales, which only
    /// [`TexEnvMode::Combine`] reads.
    pub combine: Combine,
    /// Texture coordinate generation for S, T, R and Q (§2.11.4), before the texture matrix.
    pub texgen: [TexCoordGen; 4],
}

impl Default for TextureUnit {
    fn default() -> Self {
        TextureUnit {
            enabled: false,
            cube_map: false,
            env_mode: TexEnvMode::Modulate,
            env_color: Vec4::ZERO,
            matrix: Mat4::IDENTITY,
            coord_replace: false,
            combine: Combine::default(),
            texgen: [0, 1, 2, 3].map(TexCoordGen::initial),
        }
    }
}

impl TextureUnit {
    /// Whether one of the unit's targets is enabled (`GL_TEXTURE_2D` or `GL_TEXTURE_CUBE_MAP`):
    /// only then do its environment and texgen count.
    pub fn is_enabled(&self) -> bool {
        self.enabled || self.cube_map
    }

    /// Each coordinate's generation as the shaders read it (`SPEC_TEXGEN`, the state block's
    /// `texgen`): [`TexCoordGen::code`] of S in bits 0-2, T in 3-5, R in 6-8, Q in 9-11.
    pub fn texgen_code(&self) -> u32 {
        self.texgen
            .iter()
            .enumerate()
            .fold(0, |bits, (i, g)| bits | g.code() << (3 * i))
    }

    /// Checks that the environment color is in [0, 1] and the matrix finite (state built field
    /// by field rather than through [`GlState`](super::state::GlState)'s setters).
    pub fn validate(&self) -> Result<(), StateError> {
        for v in self.env_color.to_array() {
            if !v.is_finite() {
                return Err(StateError::NotFinite {
                    parameter: "GL_TEXTURE_ENV_COLOR",
                    value: v,
                    valid: "components in [0, 1]",
                });
            }
            if !(0.0..=1.0).contains(&v) {
                return Err(StateError::OutOfRange {
                    parameter: "GL_TEXTURE_ENV_COLOR",
                    value: v,
                    valid: "components in [0, 1] (glTexEnv clamps them)",
                });
            }
        }
        if !self.combine.is_valid() {
            return Err(StateError::NotAccepted {
                parameter: "GL_COMBINE_ALPHA, GL_RGB_SCALE or GL_ALPHA_SCALE",
                value: self.combine.alpha.gl_name(),
                valid: "an alpha function other than GL_DOT3_RGB(A), and scales of 1, 2 or 4",
            });
        }
        for (i, g) in self.texgen.iter().enumerate() {
            if !g.mode.allowed_for(i) {
                return Err(StateError::NotAccepted {
                    parameter: "GL_TEXTURE_GEN_MODE",
                    value: g.mode.gl_name(),
                    valid: "GL_OBJECT_LINEAR, GL_EYE_LINEAR or (S, T) GL_SPHERE_MAP, (S, T, R) GL_REFLECTION_MAP or GL_NORMAL_MAP",
                });
            }
            let planes = [g.object_plane.to_array(), g.eye_plane.to_array()];
            if let Some(&v) = planes.iter().flatten().find(|v| !v.is_finite()) {
                return Err(StateError::NotFinite {
                    parameter: "GL_OBJECT_PLANE or GL_EYE_PLANE",
                    value: v,
                    valid: "finite components",
                });
            }
        }
        if let Some(&v) = self.matrix.to_cols_array().iter().find(|v| !v.is_finite()) {
            return Err(StateError::NotFinite {
                parameter: "GL_TEXTURE matrix",
                value: v,
                valid: "finite components",
            });
        }
        Ok(())
    }
}

/// `GL_TEXTURE_MAG_FILTER`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum MagFilter {
    /// `GL_NEAREST`: the texel whose square holds (u, v).
    Nearest,
    /// `GL_LINEAR` (GL's default): the 2×2 texels around (u, v), weighted.
    #[default]
    Linear,
}

/// `GL_TEXTURE_MIN_FILTER`: the filter within a level and, for the `*_MIPMAP_*` ones, how
/// levels are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum MinFilter {
    /// `GL_NEAREST`, level 0 only.
    Nearest,
    /// `GL_LINEAR`, level 0 only.
    Linear,
    /// `GL_NEAREST_MIPMAP_NEAREST`.
    NearestMipmapNearest,
    /// `GL_LINEAR_MIPMAP_NEAREST`.
    LinearMipmapNearest,
    /// `GL_NEAREST_MIPMAP_LINEAR` (GL's default, which needs mipmaps: a texture without them
    /// is incomplete under it and textures nothing).
    #[default]
    NearestMipmapLinear,
    /// `GL_LINEAR_MIPMAP_LINEAR` (trilinear).
    LinearMipmapLinear,
}

impl MinFilter {
    /// Every filter.
    pub const ALL: [MinFilter; 6] = [
        MinFilter::Nearest,
        MinFilter::Linear,
        MinFilter::NearestMipmapNearest,
        MinFilter::LinearMipmapNearest,
        MinFilter::NearestMipmapLinear,
        MinFilter::LinearMipmapLinear,
    ];

    /// Lowercase name as scene files write it (`nearest_mipmap_linear`, …).
    pub fn name(self) -> &'static str {
        match self {
            MinFilter::Nearest => "nearest",
            MinFilter::Linear => "linear",
            MinFilter::NearestMipmapNearest => "nearest_mipmap_nearest",
            MinFilter::LinearMipmapNearest => "linear_mipmap_nearest",
            MinFilter::NearestMipmapLinear => "nearest_mipmap_linear",
            MinFilter::LinearMipmapLinear => "linear_mipmap_linear",
        }
    }

    /// Whether it reads levels past 0 (and so needs a complete mipmap chain).
    pub fn uses_mipmaps(self) -> bool {
        !matches!(self, MinFilter::Nearest | MinFilter::Linear)
    }

    /// The filter within one level: linear or nearest.
    pub fn within_level(self) -> MagFilter {
        match self {
            MinFilter::Nearest | MinFilter::NearestMipmapNearest | MinFilter::NearestMipmapLinear => {
                MagFilter::Nearest
            }
            _ => MagFilter::Linear,
        }
    }

    /// Whether the two nearest levels are blended (`*_MIPMAP_LINEAR`).
    pub fn between_levels_linear(self) -> bool {
        matches!(
            self,
            MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear
        )
    }
}

impl MagFilter {
    /// Lowercase name as scene files write it.
    pub fn name(self) -> &'static str {
        match self {
            MagFilter::Nearest => "nearest",
            MagFilter::Linear => "linear",
        }
    }
}

/// `GL_TEXTURE_WRAP_S` / `GL_TEXTURE_WRAP_T`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Wrap {
    /// `GL_REPEAT` (GL's default): the fractional part.
    #[default]
    Repeat,
    /// `GL_CLAMP_TO_EDGE`: never past the edge texels' centers.
    ClampToEdge,
    /// `GL_MIRRORED_REPEAT`: every other repeat mirrored.
    MirroredRepeat,
}

impl Wrap {
    /// Every mode.
    pub const ALL: &'static [Wrap] = &[Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat];

    /// Lowercase name as scene files write it.
    pub fn name(self) -> &'static str {
        match self {
            Wrap::Repeat => "repeat",
            Wrap::ClampToEdge => "clamp_to_edge",
            Wrap::MirroredRepeat => "mirrored_repeat",
        }
    }
}

/// A texture object's sampling parameters (glTexParameter), GL's defaults by `Default`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub struct Sampling {
    /// `GL_TEXTURE_MIN_FILTER`; default `GL_NEAREST_MIPMAP_LINEAR`.
    pub min_filter: MinFilter,
    /// `GL_TEXTURE_MAG_FILTER`; default `GL_LINEAR`.
    pub mag_filter: MagFilter,
    /// `GL_TEXTURE_WRAP_S`; default `GL_REPEAT`.
    pub wrap_s: Wrap,
    /// `GL_TEXTURE_WRAP_T`; default `GL_REPEAT`.
    pub wrap_t: Wrap,
}

with_fields!(Sampling {
    /// Sets [`min_filter`](Sampling::min_filter) (`GL_TEXTURE_MIN_FILTER`).
    with_min_filter => min_filter: MinFilter,
    /// Sets [`mag_filter`](Sampling::mag_filter) (`GL_TEXTURE_MAG_FILTER`).
    with_mag_filter => mag_filter: MagFilter,
    /// Sets [`wrap_s`](Sampling::wrap_s) (`GL_TEXTURE_WRAP_S`).
    with_wrap_s => wrap_s: Wrap,
    /// Sets [`wrap_t`](Sampling::wrap_t) (`GL_TEXTURE_WRAP_T`).
    with_wrap_t => wrap_t: Wrap,
});

impl Sampling {
    /// Whether a texture sampled this way is complete (section 3.8.10): its min filter reads
    /// no mipmaps, or the texture `has_mipmaps`. An incomplete texture textures nothing.
    pub fn is_complete(&self, has_mipmaps: bool) -> bool {
        !self.min_filter.uses_mipmaps() || has_mipmaps
    }

    /// Nearest filtering without mipmaps and repeat: every texel reaches the screen unblended
    /// (what the exact tests use).
    pub const NEAREST: Sampling = Sampling {
        min_filter: MinFilter::Nearest,
        mag_filter: MagFilter::Nearest,
        wrap_s: Wrap::Repeat,
        wrap_t: Wrap::Repeat,
    };
}

/// Why a texture image cannot be made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum TextureError {
    /// A side of 0 or past the largest texture ffvk takes.
    #[error("texture size {width}x{height} is invalid: expected each side in 1..={max}")]
    Size {
        /// Width in texels.
        width: u32,
        /// Height in texels.
        height: u32,
        /// [`MAX_TEXTURE_SIZE`].
        max: u32,
    },
    /// The byte count is not width × height × 4.
    #[error("{bytes} bytes of RGBA8 for a {width}x{height} texture: expected {expected}")]
    Bytes {
        /// Bytes given.
        bytes: usize,
        /// Width in texels.
        width: u32,
        /// Height in texels.
        height: u32,
        /// width × height × 4.
        expected: usize,
    },
    /// A cube map face whose sides differ (§3.8.1: cube faces are square).
    #[error("cube map face {face} is {width}x{height}: expected a square face")]
    CubeFaceNotSquare {
        /// The face's target name.
        face: &'static str,
        /// Its width in texels.
        width: u32,
        /// Its height in texels.
        height: u32,
    },
    /// A cube map face whose size, levels or sRGB flag differ from the first face's (GL's cube
    /// completeness, §3.8.10).
    #[error("cube map face {face} is {size} texels a side with {levels} levels: expected {}x{} with {} levels and the first face's sRGB flag, as GL_TEXTURE_CUBE_MAP_POSITIVE_X", .expected.0, .expected.0, .expected.1)]
    CubeFacesDiffer {
        /// The face's target name.
        face: &'static str,
        /// Its side in texels.
        size: u32,
        /// Its levels.
        levels: usize,
        /// The first face's side and levels.
        expected: (u32, usize),
    },
    /// [`TextureImage::from_levels`] was given no level.
    #[error("a texture image without levels: expected level 0 at least")]
    NoLevels,
    /// [`TextureImage::from_levels`] was given more levels than the chain down to 1×1 has.
    #[error("{levels} texture levels: expected at most {max}, the chain down to 1x1")]
    TooManyLevels {
        /// Levels given.
        levels: usize,
        /// The levels of the complete chain.
        max: usize,
    },
    /// A level of [`TextureImage::from_levels`] that is not half the level above.
    #[error("texture level {level} is {width}x{height}: expected {}x{}, half the level above (rounded down, at least 1)", .expected.0, .expected.1)]
    LevelSize {
        /// The level's number (1 for the first below level 0).
        level: usize,
        /// Its width in texels.
        width: u32,
        /// Its height in texels.
        height: u32,
        /// The width and height it must have.
        expected: (u32, u32),
    },
}

/// The largest texture side ffvk takes (GL 2.1 asks for at least 64; Vulkan 1.3 devices
/// offer at least 4096 for sampled images).
pub const MAX_TEXTURE_SIZE: u32 = 4096;

/// One level of an RGBA8 texture: rows in upload order, so row 0 is t = 0 (GL's
/// glTexImage2D convention; an image file's first row, usually its top, lands at t = 0, as
/// glTF's texture coordinates expect).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Level {
    // Private: `rgba` holds exactly width × height × 4 bytes, which every reader relies on.
    width: u32,
    height: u32,
    rgba: Vec<u8>,
}

impl Level {
    /// A level of `width` × `height` RGBA8 texels (`rgba` holds width × height × 4 bytes,
    /// R, G, B, A, rows in upload order), each side in 1..=[`MAX_TEXTURE_SIZE`].
    pub fn new(width: u32, height: u32, rgba: Vec<u8>) -> Result<Self, TextureError> {
        if width == 0 || height == 0 || width > MAX_TEXTURE_SIZE || height > MAX_TEXTURE_SIZE {
            return Err(TextureError::Size {
                width,
                height,
                max: MAX_TEXTURE_SIZE,
            });
        }
        let expected = width as usize * height as usize * 4;
        if rgba.len() != expected {
            return Err(TextureError::Bytes {
                bytes: rgba.len(),
                width,
                height,
                expected,
            });
        }
        Ok(Level { width, height, rgba })
    }

    /// Width in texels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in texels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The texels: width × height × 4 bytes, R, G, B, A, rows in upload order.
    pub fn rgba(&self) -> &[u8] {
        &self.rgba
    }

    /// The texel at (i, j) (column, row), as 0..=255 per channel.
    ///
    /// # Panics
    ///
    /// When `i >= width` or `j >= height`, as indexing a slice out of range does.
    pub fn texel(&self, i: u32, j: u32) -> [u8; 4] {
        let at = (j as usize * self.width as usize + i as usize) * 4;
        [
            self.rgba[at],
            self.rgba[at + 1],
            self.rgba[at + 2],
            self.rgba[at + 3],
        ]
    }
}

/// A 2D texture's image: `GL_RGBA8` (or `GL_SRGB8_ALPHA8` when `srgb`), level 0 and, when
/// generated, its mipmaps.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct TextureImage {
    // Private: never empty, and each level halves the one above (see `from_levels`).
    levels: Vec<Level>,
    /// GL 2.1's `GL_SRGB8_ALPHA8`: texels are decoded from sRGB to linear when sampled (alpha
    /// stays linear). Off by default, as a legacy program's `GL_RGBA8`: a texel then reaches a
    /// UNORM framebuffer unchanged under full white light.
    pub srgb: bool,
    /// The base internal format (`glTexImage2D`'s `internalformat`): which components the
    /// texture has, read from the RGBA8 texels as GL converts RGBA pixels (luminance and
    /// intensity from R, alpha from A). `GL_RGBA` by default.
    pub base_format: BaseFormat,
}

impl TextureImage {
    /// One level of RGBA8 texels, `width` × `height`, rows in upload order.
    pub fn new(width: u32, height: u32, rgba: Vec<u8>) -> Result<Self, TextureError> {
        Ok(TextureImage {
            levels: vec![Level::new(width, height, rgba)?],
            srgb: false,
            base_format: BaseFormat::Rgba,
        })
    }

    /// The caller's own levels, as successive `glTexImage2D` calls for levels 0, 1, …: each
    /// level's sides are half the level above's (rounded down, never below 1), and there are
    /// at most as many levels as the chain down to 1×1 has. A complete chain makes the
    /// texture complete for a min filter that reads mipmaps ([`TextureImage::has_mipmaps`]).
    pub fn from_levels(levels: Vec<Level>) -> Result<Self, TextureError> {
        let Some(first) = levels.first() else {
            return Err(TextureError::NoLevels);
        };
        let max = mip_count(first.width, first.height) as usize;
        if levels.len() > max {
            return Err(TextureError::TooManyLevels {
                levels: levels.len(),
                max,
            });
        }
        for (i, pair) in levels.windows(2).enumerate() {
            let (above, level) = (&pair[0], &pair[1]);
            let expected = ((above.width / 2).max(1), (above.height / 2).max(1));
            if (level.width, level.height) != expected {
                return Err(TextureError::LevelSize {
                    level: i + 1,
                    width: level.width,
                    height: level.height,
                    expected,
                });
            }
        }
        Ok(TextureImage {
            levels,
            srgb: false,
            base_format: BaseFormat::Rgba,
        })
    }

    /// Level 0 first; either one level or more, down to the whole chain to 1×1.
    pub fn levels(&self) -> &[Level] {
        &self.levels
    }

    /// A `cells` × `cells` checkerboard of `size`² texels, alternating `a` (at texel (0, 0))
    /// and `b`.
    pub fn checker(size: u32, cells: u32, a: [u8; 4], b: [u8; 4]) -> Result<Self, TextureError> {
        let cell = (size / cells.max(1)).max(1);
        let mut rgba = Vec::with_capacity(size as usize * size as usize * 4);
        for j in 0..size {
            for i in 0..size {
                rgba.extend_from_slice(if (i / cell + j / cell).is_multiple_of(2) {
                    &a
                } else {
                    &b
                });
            }
        }
        TextureImage::new(size, size, rgba)
    }

    /// A particle for point sprites: a `size`² (at least 4) white disc, opaque to 0.77 of its
    /// radius r and fading to alpha 0 at the rim (alpha min(1, 2.5 (1 − r²))), on texels of
    /// alpha 0 outside it.
    pub fn disc(size: u32) -> Result<Self, TextureError> {
        let size = size.max(4);
        let mut rgba = Vec::with_capacity(size as usize * size as usize * 4);
        for j in 0..size {
            for i in 0..size {
                let p = glam::Vec2::new(i as f32 + 0.5, j as f32 + 0.5) / size as f32 * 2.0 - glam::Vec2::ONE;
                let alpha = (2.5 * (1.0 - p.length_squared())).clamp(0.0, 1.0);
                rgba.extend_from_slice(&[255, 255, 255, (alpha * 255.0).round() as u8]);
            }
        }
        TextureImage::new(size, size, rgba)
    }

    /// Foliage for the alpha test: a `size`² texture (at least 8) of five leaves, opaque greens
    /// whose shade runs along each leaf, on texels of alpha 0. Each leaf is the intersection of
    /// two discs (a lens), so its outline is crisp: with `GL_ALPHA_TEST` `GL_GREATER` 0.5 and
    /// linear filtering the cut follows the lens's edge.
    pub fn leaves(size: u32) -> Result<Self, TextureError> {
        // Centre (x, y), direction of the leaf's axis (radians), half-length: in texture units.
        const LEAVES: [(f32, f32, f32, f32); 5] = [
            (0.30, 0.30, 0.6, 0.22),
            (0.70, 0.28, 2.3, 0.20),
            (0.50, 0.55, 1.5, 0.26),
            (0.25, 0.75, 2.6, 0.18),
            (0.75, 0.75, 0.9, 0.21),
        ];
        let size = size.max(8);
        let mut rgba = Vec::with_capacity(size as usize * size as usize * 4);
        for j in 0..size {
            for i in 0..size {
                let p = glam::Vec2::new(i as f32 + 0.5, j as f32 + 0.5) / size as f32;
                let mut texel = [0u8, 0, 0, 0];
                for (k, &(x, y, angle, half)) in LEAVES.iter().enumerate() {
                    let axis = glam::Vec2::from_angle(angle);
                    let d = p - glam::Vec2::new(x, y);
                    let (along, across) = (d.dot(axis), d.perp_dot(axis));
                    // A lens of half-length `half` and half-width half / 2.5: the points within
                    // radius r of two centres on the normal, each r - half / 2.5 away.
                    let w = half / 2.5;
                    let r = (half * half + w * w) / (2.0 * w);
                    let inside = (along * along + (across - (r - w)).powi(2)) <= r * r
                        && (along * along + (across + (r - w)).powi(2)) <= r * r;
                    if inside {
                        let shade = 0.55 + 0.45 * (0.5 + along / (2.0 * half)).clamp(0.0, 1.0);
                        let g = (shade * (200.0 - 12.0 * k as f32)) as u8;
                        texel = [(g as f32 * 0.35) as u8, g, (g as f32 * 0.2) as u8, 255];
                    }
                }
                rgba.extend_from_slice(&texel);
            }
        }
        TextureImage::new(size, size, rgba)
    }

    /// A light map for a second texture unit: a `size`² (at least 4) opaque RGB texture of
    /// dim ambient light (0.2) with two soft pools, a warm one (1, 0.8, 0.55) around
    /// (0.3, 0.35) and a cool one (0.45, 0.6, 1) around (0.72, 0.7) in (s, t), each falling off
    /// as (1 − d²/r²)² to its radius r (0.38, 0.3); the sum clamped to 1.
    pub fn lightmap(size: u32) -> Result<Self, TextureError> {
        const POOLS: [([f32; 2], f32, [f32; 3]); 2] = [
            ([0.3, 0.35], 0.38, [1.0, 0.8, 0.55]),
            ([0.72, 0.7], 0.3, [0.45, 0.6, 1.0]),
        ];
        let size = size.max(4);
        let mut rgba = Vec::with_capacity(size as usize * size as usize * 4);
        for j in 0..size {
            for i in 0..size {
                let p = glam::Vec2::new(i as f32 + 0.5, j as f32 + 0.5) / size as f32;
                let mut light = glam::Vec3::splat(0.2);
                for (centre, radius, color) in POOLS {
                    let falloff = (1.0 - p.distance_squared(centre.into()) / (radius * radius)).max(0.0);
                    light += glam::Vec3::from(color) * falloff * falloff;
                }
                let [r, g, b] = light
                    .min(glam::Vec3::ONE)
                    .to_array()
                    .map(|c| (c * 255.0).round() as u8);
                rgba.extend_from_slice(&[r, g, b, 255]);
            }
        }
        TextureImage::new(size, size, rgba)
    }

    /// Level 0's width.
    pub fn width(&self) -> u32 {
        self.levels.first().map_or(0, |l| l.width)
    }

    /// Level 0's height.
    pub fn height(&self) -> u32 {
        self.levels.first().map_or(0, |l| l.height)
    }

    /// Whether the levels run down to 1×1 (a complete mipmap chain).
    pub fn has_mipmaps(&self) -> bool {
        self.levels.len() == mip_count(self.width(), self.height()) as usize
    }

    /// GL_GENERATE_MIPMAP's result, computed here so every device samples the same levels:
    /// each level halves each side (rounding down, never below 1), and each texel is the
    /// rounded mean of the 2×2 texels it covers (1×2 or 2×1 where the level above is one
    /// texel wide or high; odd sides drop their last row or column, as a box filter of GL's
    /// floor(size / 2) rule). The channels are averaged as stored, sRGB or not.
    pub fn with_mipmaps(mut self) -> Self {
        self.make_mipmaps();
        self
    }

    /// This image with base internal format `format` (`GL_LUMINANCE` for a light map, …).
    #[must_use]
    pub fn with_base_format(mut self, format: BaseFormat) -> Self {
        self.base_format = format;
        self
    }

    fn make_mipmaps(&mut self) {
        self.levels.truncate(1);
        while let Some(above) = self.levels.last().filter(|l| l.width > 1 || l.height > 1) {
            let (w, h) = ((above.width / 2).max(1), (above.height / 2).max(1));
            let (sx, sy) = (
                if above.width > 1 { 2 } else { 1 },
                if above.height > 1 { 2 } else { 1 },
            );
            let mut rgba = Vec::with_capacity(w as usize * h as usize * 4);
            for j in 0..h {
                for i in 0..w {
                    for c in 0..4 {
                        let mut sum = 0u32;
                        for dy in 0..sy {
                            for dx in 0..sx {
                                sum += u32::from(above.texel(i * sx + dx, j * sy + dy)[c]);
                            }
                        }
                        let n = sx * sy;
                        rgba.push(((sum + n / 2) / n) as u8);
                    }
                }
            }
            self.levels.push(Level {
                width: w,
                height: h,
                rgba,
            });
        }
    }
}

/// The number of levels of a complete mipmap chain for a `width` × `height` level 0.
pub fn mip_count(width: u32, height: u32) -> u32 {
    32 - width.max(height).max(1).leading_zeros()
}

/// The units a draw samples and the units it applies (§3.8.16), a bit per unit each. `bound`
/// has a bit per unit with a complete 2D texture, `bound_cube` one per unit with a complete
/// cube map. A unit with `GL_TEXTURE_CUBE_MAP` on samples its cube map, or nothing without one
/// (the cube map's precedence); else, with `GL_TEXTURE_2D` on, its 2D texture. A sampled unit
/// is applied where every `GL_TEXTUREn` source its `GL_COMBINE` reads names a sampled unit (a
/// unit that reads another unit's missing texel passes the color through, as
/// ARB_texture_env_crossbar says). Returns (sampled, applied, the sampled units that sample a
/// cube map).
pub fn units_applied(
    units: &[TextureUnit; MAX_TEXTURE_UNITS],
    bound: u32,
    bound_cube: u32,
) -> (u32, u32, u32) {
    let bit = |i: usize| 1u32 << i;
    let cube = (0..MAX_TEXTURE_UNITS)
        .filter(|&i| units[i].cube_map && bound_cube & bit(i) != 0)
        .fold(0, |mask, i| mask | bit(i));
    let flat = (0..MAX_TEXTURE_UNITS)
        .filter(|&i| !units[i].cube_map && units[i].enabled && bound & bit(i) != 0)
        .fold(0, |mask, i| mask | bit(i));
    let sampled = cube | flat;
    let applied = (0..MAX_TEXTURE_UNITS)
        .filter(|&i| sampled & 1 << i != 0)
        .filter(|&i| {
            units[i].env_mode != TexEnvMode::Combine || units[i].combine.units_read() & !sampled == 0
        })
        .fold(0, |mask, i| mask | 1 << i);
    (sampled, applied, cube)
}

/// Whether texturing applies to a draw (section 3.8.10): `GL_TEXTURE_2D` enabled and a bound
/// texture that is complete for its min filter (mipmaps present when the filter reads them).
pub fn texturing_applies(unit: &TextureUnit, bound: Option<(&TextureImage, &Sampling)>) -> bool {
    unit.enabled && bound.is_some_and(|(image, sampling)| sampling.is_complete(image.has_mipmaps()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_callers_own_levels_make_a_texture_when_each_halves_the_one_above() {
        let chain = TextureImage::checker(8, 2, [255; 4], [0, 0, 0, 255])
            .unwrap()
            .with_mipmaps();
        let own = TextureImage::from_levels(chain.levels().to_vec()).unwrap();
        assert_eq!(own, chain);
        assert!(own.has_mipmaps());
        // Levels 0 and 1 only: a texture, incomplete for a mipmap filter, as in GL.
        let partial = TextureImage::from_levels(chain.levels()[..2].to_vec()).unwrap();
        assert!(!partial.has_mipmaps());
        assert_eq!((partial.width(), partial.height()), (8, 8));
    }

    #[test]
    fn levels_that_do_not_halve_or_outnumber_the_chain_are_refused() {
        let level = |w: u32, h: u32| Level::new(w, h, vec![0; (w * h * 4) as usize]).unwrap();
        assert_eq!(TextureImage::from_levels(vec![]), Err(TextureError::NoLevels));
        assert_eq!(
            TextureImage::from_levels(vec![level(8, 4), level(4, 4)]),
            Err(TextureError::LevelSize {
                level: 1,
                width: 4,
                height: 4,
                expected: (4, 2)
            })
        );
        // 5×3 halves to 2×1, then 1×1; a fourth level is one too many.
        let chain = vec![level(5, 3), level(2, 1), level(1, 1), level(1, 1)];
        assert_eq!(
            TextureImage::from_levels(chain),
            Err(TextureError::TooManyLevels { levels: 4, max: 3 })
        );
        assert_eq!(
            Level::new(2, 2, vec![0; 15]),
            Err(TextureError::Bytes {
                bytes: 15,
                width: 2,
                height: 2,
                expected: 16
            })
        );
        assert!(matches!(Level::new(0, 2, vec![]), Err(TextureError::Size { .. })));
    }

    #[test]
    fn a_complete_chain_halves_down_to_one_texel() {
        assert_eq!(mip_count(1, 1), 1);
        assert_eq!(mip_count(8, 2), 4);
        assert_eq!(mip_count(5, 3), 3);
        let image = TextureImage::checker(8, 2, [255; 4], [0, 0, 0, 255])
            .unwrap()
            .with_mipmaps();
        let sizes: Vec<_> = image.levels.iter().map(|l| (l.width, l.height)).collect();
        assert_eq!(sizes, [(8, 8), (4, 4), (2, 2), (1, 1)]);
        assert!(image.has_mipmaps());
        // 2 cells of 4: level 2 is the cells themselves, level 3 their rounded mean.
        assert_eq!(image.levels[2].texel(0, 0), [255; 4]);
        assert_eq!(image.levels[2].texel(1, 0), [0, 0, 0, 255]);
        assert_eq!(image.levels[3].texel(0, 0), [128, 128, 128, 255]);
    }

    #[test]
    fn the_light_map_is_opaque_dim_between_its_pools_and_warm_and_cool_at_them() {
        let image = TextureImage::lightmap(64).unwrap();
        assert_eq!((image.width(), image.height()), (64, 64));
        let level = &image.levels()[0];
        assert!(level.rgba().chunks(4).all(|t| t[3] == 255));
        // A corner far from both pools: the ambient 0.2 alone.
        assert_eq!(level.texel(63, 0), [51, 51, 51, 255]);
        // Near the warm pool's centre (0.3, 0.35): about 0.2 + (1, 0.8, 0.55), clamped; near
        // the cool one's (0.72, 0.7), outside the warm one: about 0.2 + (0.45, 0.6, 1).
        let [r, g, b, _] = level.texel(19, 22);
        assert!(r == 255 && g > 240 && b > 180 && b < 200, "{:?}", [r, g, b]);
        let [r, g, b, _] = level.texel(46, 45);
        assert!(r < 180 && g > 190 && b == 255, "{:?}", [r, g, b]);
        assert!(TextureImage::lightmap(1).is_ok_and(|i| i.width() == 4));
    }

    #[test]
    fn a_one_texel_wide_level_averages_pairs() {
        let image = TextureImage::new(
            1,
            4,
            [0, 10, 20, 30].iter().flat_map(|&v| [v, v, v, 255]).collect(),
        )
        .unwrap()
        .with_mipmaps();
        assert_eq!(image.levels[1].texel(0, 0)[0], 5);
        assert_eq!(image.levels[1].texel(0, 1)[0], 25);
        assert_eq!(image.levels[2].texel(0, 0)[0], 15);
    }

    #[test]
    fn texturing_needs_a_texture_complete_for_its_min_filter() {
        let unit = TextureUnit {
            enabled: true,
            ..TextureUnit::default()
        };
        let image = TextureImage::checker(4, 2, [255; 4], [0; 4]).unwrap();
        // GL's default min filter reads mipmaps: without them the texture is incomplete.
        assert!(!texturing_applies(&unit, Some((&image, &Sampling::default()))));
        assert!(texturing_applies(&unit, Some((&image, &Sampling::NEAREST))));
        assert!(texturing_applies(
            &unit,
            Some((&image.clone().with_mipmaps(), &Sampling::default()))
        ));
        assert!(!texturing_applies(&unit, None));
        assert!(!texturing_applies(
            &TextureUnit::default(),
            Some((&image, &Sampling::NEAREST))
        ));
    }

    #[test]
    fn bad_sizes_and_byte_counts_are_errors_naming_the_values() {
        let e = TextureImage::new(0, 4, vec![]).unwrap_err().to_string();
        assert!(e.contains("0x4") && e.contains("4096"), "{e}");
        let e = TextureImage::new(2, 2, vec![0; 15]).unwrap_err().to_string();
        assert!(e.contains("15 bytes") && e.contains("expected 16"), "{e}");
        let bad = TextureUnit {
            env_color: Vec4::new(0.0, 2.0, 0.0, 0.0),
            ..TextureUnit::default()
        };
        assert!(bad
            .validate()
            .unwrap_err()
            .to_string()
            .contains("GL_TEXTURE_ENV_COLOR = 2"));
    }
}
