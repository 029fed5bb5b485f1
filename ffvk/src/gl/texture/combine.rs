//! `GL_COMBINE` (GL 2.1 §3.8.13, table 3.24; ARB_texture_env_combine and _dot3): the texture
//! environment as a function of up to three arguments, each a source's color or alpha, or
//! one minus it, for RGB and alpha apart, scaled, then clamped to [0, 1]. The shaders' copy is
//! `glsl/texture.glsl`'s `combine`, the CPU reference's `reference::texture::combine`.

use super::MAX_TEXTURE_UNITS;

/// `GL_COMBINE_RGB` and `GL_COMBINE_ALPHA`: the function of the arguments Arg0, Arg1, Arg2.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum CombineFunc {
    /// `GL_REPLACE`: Arg0.
    Replace,
    /// `GL_MODULATE` (GL's default): Arg0 × Arg1.
    #[default]
    Modulate,
    /// `GL_ADD`: Arg0 + Arg1.
    Add,
    /// `GL_ADD_SIGNED`: Arg0 + Arg1 − 0.5.
    AddSigned,
    /// `GL_INTERPOLATE`: Arg0 × Arg2 + Arg1 × (1 − Arg2).
    Interpolate,
    /// `GL_SUBTRACT`: Arg0 − Arg1.
    Subtract,
    /// `GL_DOT3_RGB` (RGB only): 4 × ((Arg0_r − ½)(Arg1_r − ½) + (Arg0_g − ½)(Arg1_g − ½) +
    /// (Arg0_b − ½)(Arg1_b − ½)) in each of R, G and B.
    Dot3Rgb,
    /// `GL_DOT3_RGBA` (RGB only): `Dot3Rgb`'s value in alpha too; `GL_COMBINE_ALPHA` is then
    /// not used.
    Dot3Rgba,
}

impl CombineFunc {
    /// Every function, in the shaders' code order.
    pub const ALL: [CombineFunc; 8] = [
        CombineFunc::Replace,
        CombineFunc::Modulate,
        CombineFunc::Add,
        CombineFunc::AddSigned,
        CombineFunc::Interpolate,
        CombineFunc::Subtract,
        CombineFunc::Dot3Rgb,
        CombineFunc::Dot3Rgba,
    ];

    /// GL's name (`GL_MODULATE`, …).
    pub fn gl_name(self) -> &'static str {
        match self {
            CombineFunc::Replace => "GL_REPLACE",
            CombineFunc::Modulate => "GL_MODULATE",
            CombineFunc::Add => "GL_ADD",
            CombineFunc::AddSigned => "GL_ADD_SIGNED",
            CombineFunc::Interpolate => "GL_INTERPOLATE",
            CombineFunc::Subtract => "GL_SUBTRACT",
            CombineFunc::Dot3Rgb => "GL_DOT3_RGB",
            CombineFunc::Dot3Rgba => "GL_DOT3_RGBA",
        }
    }

    /// How many arguments the function reads (table 3.24): `GL_REPLACE` one, `GL_INTERPOLATE`
    /// three, the others two.
    pub fn arguments(self) -> usize {
        match self {
            CombineFunc::Replace => 1,
            CombineFunc::Interpolate => 3,
            _ => 2,
        }
    }

    /// The shaders' value (`COMBINE_*` in `glsl/texture.glsl`): the index in [`CombineFunc::ALL`].
    pub fn code(self) -> u32 {
        CombineFunc::ALL.iter().position(|&f| f == self).unwrap_or(0) as u32
    }

    /// Whether `GL_COMBINE_ALPHA` takes it (the dot products are RGB functions).
    pub fn is_alpha_function(self) -> bool {
        !matches!(self, CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba)
    }
}

/// `GL_SRCn_RGB` and `GL_SRCn_ALPHA`: where an argument comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum CombineSource {
    /// `GL_TEXTURE`: this unit's texel.
    Texture,
    /// `GL_CONSTANT`: the environment color C_c.
    Constant,
    /// `GL_PRIMARY_COLOR`: the fragment's primary color before texturing.
    PrimaryColor,
    /// `GL_PREVIOUS`: the previous unit's result; for the first unit, the primary color.
    Previous,
    /// `GL_TEXTUREn` (ARB_texture_env_crossbar, GL 1.4): unit n's texel, sampled with unit n's
    /// own coordinates and texture. A unit whose arguments read a unit that is not enabled with
    /// a complete texture passes the previous unit's color through, as the extension says (GL
    /// 2.1 leaves it undefined).
    TextureUnit(u8),
}

impl CombineSource {
    /// Every source, in the shaders' code order.
    pub const ALL: [CombineSource; 4] = [
        CombineSource::Texture,
        CombineSource::Constant,
        CombineSource::PrimaryColor,
        CombineSource::Previous,
    ];

    /// The shaders' value: the index in [`CombineSource::ALL`]; `GL_TEXTUREn` is
    /// `GL_TEXTURE`'s, with the unit in [`Combine::crossbar_code`].
    pub fn code(self) -> u32 {
        CombineSource::ALL.iter().position(|&s| s == self).unwrap_or(0) as u32
    }

    /// GL's name (`GL_PRIMARY_COLOR`, `GL_TEXTURE1`, …).
    pub fn gl_name(self) -> &'static str {
        const UNITS: [&str; MAX_TEXTURE_UNITS] = ["GL_TEXTURE0", "GL_TEXTURE1", "GL_TEXTURE2", "GL_TEXTURE3"];
        match self {
            CombineSource::Texture => "GL_TEXTURE",
            CombineSource::Constant => "GL_CONSTANT",
            CombineSource::PrimaryColor => "GL_PRIMARY_COLOR",
            CombineSource::Previous => "GL_PREVIOUS",
            CombineSource::TextureUnit(n) => UNITS.get(usize::from(n)).copied().unwrap_or("GL_TEXTUREn"),
        }
    }

    /// The unit a `GL_TEXTUREn` source reads.
    pub fn unit(self) -> Option<usize> {
        match self {
            CombineSource::TextureUnit(n) => Some(usize::from(n)),
            _ => None,
        }
    }
}

/// `GL_OPERANDn_RGB`: which of a source's values an RGB argument takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum RgbOperand {
    /// `GL_SRC_COLOR`: C_s.
    SrcColor,
    /// `GL_ONE_MINUS_SRC_COLOR`: 1 − C_s.
    OneMinusSrcColor,
    /// `GL_SRC_ALPHA`: A_s in each of R, G, B.
    SrcAlpha,
    /// `GL_ONE_MINUS_SRC_ALPHA`: 1 − A_s in each.
    OneMinusSrcAlpha,
}

impl RgbOperand {
    /// Every operand, in the shaders' code order.
    pub const ALL: [RgbOperand; 4] = [
        RgbOperand::SrcColor,
        RgbOperand::OneMinusSrcColor,
        RgbOperand::SrcAlpha,
        RgbOperand::OneMinusSrcAlpha,
    ];

    /// GL's name (`GL_SRC_COLOR`, …).
    pub fn gl_name(self) -> &'static str {
        match self {
            RgbOperand::SrcColor => "GL_SRC_COLOR",
            RgbOperand::OneMinusSrcColor => "GL_ONE_MINUS_SRC_COLOR",
            RgbOperand::SrcAlpha => "GL_SRC_ALPHA",
            RgbOperand::OneMinusSrcAlpha => "GL_ONE_MINUS_SRC_ALPHA",
        }
    }

    /// The shaders' value: the index in [`RgbOperand::ALL`].
    pub fn code(self) -> u32 {
        RgbOperand::ALL.iter().position(|&o| o == self).unwrap_or(0) as u32
    }
}

/// `GL_OPERANDn_ALPHA`: which of a source's values an alpha argument takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum AlphaOperand {
    /// `GL_SRC_ALPHA`: A_s.
    SrcAlpha,
    /// `GL_ONE_MINUS_SRC_ALPHA`: 1 − A_s.
    OneMinusSrcAlpha,
}

impl AlphaOperand {
    /// GL's name (`GL_SRC_ALPHA`, `GL_ONE_MINUS_SRC_ALPHA`).
    pub fn gl_name(self) -> &'static str {
        match self {
            AlphaOperand::SrcAlpha => "GL_SRC_ALPHA",
            AlphaOperand::OneMinusSrcAlpha => "GL_ONE_MINUS_SRC_ALPHA",
        }
    }
}

/// `GL_COMBINE`'s state (table 6.19, with GL's initial values in [`Combine::default`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Combine {
    /// `GL_COMBINE_RGB`; `GL_MODULATE` by default.
    pub rgb: CombineFunc,
    /// `GL_COMBINE_ALPHA`; `GL_MODULATE` by default; never a dot product.
    pub alpha: CombineFunc,
    /// `GL_SRC0_RGB` .. `GL_SRC2_RGB`: `GL_TEXTURE`, `GL_PREVIOUS`, `GL_CONSTANT` by default.
    pub rgb_sources: [CombineSource; 3],
    /// `GL_SRC0_ALPHA` .. `GL_SRC2_ALPHA`: the same defaults.
    pub alpha_sources: [CombineSource; 3],
    /// `GL_OPERAND0_RGB` .. `2`: `GL_SRC_COLOR`, `GL_SRC_COLOR`, `GL_SRC_ALPHA` by default.
    pub rgb_operands: [RgbOperand; 3],
    /// `GL_OPERAND0_ALPHA` .. `2`: `GL_SRC_ALPHA` each by default.
    pub alpha_operands: [AlphaOperand; 3],
    /// `GL_RGB_SCALE`: 1, 2 or 4; 1 by default.
    pub rgb_scale: f32,
    /// `GL_ALPHA_SCALE`: 1, 2 or 4; 1 by default.
    pub alpha_scale: f32,
}

impl Default for Combine {
    fn default() -> Self {
        use CombineSource::*;
        Combine {
            rgb: CombineFunc::Modulate,
            alpha: CombineFunc::Modulate,
            rgb_sources: [Texture, Previous, Constant],
            alpha_sources: [Texture, Previous, Constant],
            rgb_operands: [RgbOperand::SrcColor, RgbOperand::SrcColor, RgbOperand::SrcAlpha],
            alpha_operands: [AlphaOperand::SrcAlpha; 3],
            rgb_scale: 1.0,
            alpha_scale: 1.0,
        }
    }
}

/// A scale's 2-bit code: 0 for 1, 1 for 2, 2 for 4 (anything else is refused before).
fn scale_code(scale: f32) -> u32 {
    if scale == 4.0 {
        2
    } else if scale == 2.0 {
        1
    } else {
        0
    }
}

impl Combine {
    /// The state as the shaders read it (`SPEC_COMBINE`, the state block's `combine`): the RGB
    /// function in bits 0-2, the alpha function 3-5, the RGB sources 6-11 (2 bits each from
    /// Arg0), the alpha sources 12-17, the RGB operands 18-23, the alpha operands 24-26 (1 bit
    /// each: one minus), the RGB scale 27-28 and the alpha scale 29-30 (0: 1, 1: 2, 2: 4).
    pub fn code(&self) -> u32 {
        let mut bits = self.rgb.code() | self.alpha.code() << 3;
        for i in 0..3 {
            bits |= self.rgb_sources[i].code() << (6 + 2 * i);
            bits |= self.alpha_sources[i].code() << (12 + 2 * i);
            bits |= self.rgb_operands[i].code() << (18 + 2 * i);
            bits |= u32::from(self.alpha_operands[i] == AlphaOperand::OneMinusSrcAlpha) << (24 + i);
        }
        bits | scale_code(self.rgb_scale) << 27 | scale_code(self.alpha_scale) << 29
    }

    /// The `GL_TEXTUREn` sources as the shaders read them (`SPEC_CROSSBAR`, the unit block's
    /// `crossbar`): 3 bits per argument, the RGB arguments' from bit 0, the alpha arguments'
    /// from bit 9, each n + 1 for `GL_TEXTUREn` and 0 for any other source.
    pub fn crossbar_code(&self) -> u32 {
        let sources = self.rgb_sources.iter().chain(&self.alpha_sources);
        sources.enumerate().fold(0, |bits, (i, s)| {
            bits | s.unit().map_or(0, |n| n as u32 + 1) << (3 * i)
        })
    }

    /// The units whose texels the arguments the two functions read come from (`GL_TEXTUREn`
    /// sources), a bit each: a unit reads `GL_REPLACE`'s one argument, `GL_INTERPOLATE`'s
    /// three, two for the others, and no alpha argument under `GL_DOT3_RGBA`.
    pub fn units_read(&self) -> u32 {
        let alpha_args = if self.rgb == CombineFunc::Dot3Rgba {
            0
        } else {
            self.alpha.arguments()
        };
        let rgb = self.rgb_sources.iter().take(self.rgb.arguments());
        let alpha = self.alpha_sources.iter().take(alpha_args);
        rgb.chain(alpha)
            .filter_map(|s| s.unit())
            .fold(0, |mask, n| mask | 1 << n)
    }

    /// Whether GL would have accepted every value: an alpha function that is not a dot product,
    /// scales of 1, 2 or 4, `GL_TEXTUREn` sources of units that exist.
    pub fn is_valid(&self) -> bool {
        let scale = |s: f32| s == 1.0 || s == 2.0 || s == 4.0;
        let unit = |s: &CombineSource| s.unit().is_none_or(|n| n < MAX_TEXTURE_UNITS);
        self.alpha.is_alpha_function()
            && scale(self.rgb_scale)
            && scale(self.alpha_scale)
            && self.rgb_sources.iter().chain(&self.alpha_sources).all(unit)
    }
}
