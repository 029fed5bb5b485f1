//! A texture's base internal format (GL 2.1 table 3.15, `glTexImage2D`'s `internalformat`):
//! which of a texel's R, G, B and A the image holds, and so what the texture environment
//! reads of it (table 3.22: a luminance light map leaves the fragment's alpha alone, an alpha
//! texture its color). ffvk's images stay RGBA8 in memory; the format picks the components as
//! GL's conversion from RGBA pixels does (luminance and intensity from R, alpha from A).

use glam::DVec4;

/// `GL_RGBA`, `GL_RGB`, `GL_ALPHA`, `GL_LUMINANCE`, `GL_LUMINANCE_ALPHA` or `GL_INTENSITY`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum BaseFormat {
    /// `GL_RGBA` (the default): (R, G, B, A).
    #[default]
    Rgba,
    /// `GL_RGB`: (R, G, B), alpha 1; the environment keeps the fragment's alpha.
    Rgb,
    /// `GL_ALPHA`: A alone, color 0; the environment keeps the fragment's color.
    Alpha,
    /// `GL_LUMINANCE`: L = R in each of R, G and B, alpha 1 (a light map).
    Luminance,
    /// `GL_LUMINANCE_ALPHA`: L = R in each of R, G and B, and A.
    LuminanceAlpha,
    /// `GL_INTENSITY`: I = R in each of R, G, B and A.
    Intensity,
}

impl BaseFormat {
    /// Every format, in the shaders' code order.
    pub const ALL: [BaseFormat; 6] = [
        BaseFormat::Rgba,
        BaseFormat::Rgb,
        BaseFormat::Alpha,
        BaseFormat::Luminance,
        BaseFormat::LuminanceAlpha,
        BaseFormat::Intensity,
    ];

    /// The shaders' value (`FORMAT_*` in `glsl/texture.glsl`): the index in [`BaseFormat::ALL`].
    pub fn code(self) -> u32 {
        BaseFormat::ALL.iter().position(|&f| f == self).unwrap_or(0) as u32
    }

    /// GL's name.
    pub fn gl_name(self) -> &'static str {
        match self {
            BaseFormat::Rgba => "GL_RGBA",
            BaseFormat::Rgb => "GL_RGB",
            BaseFormat::Alpha => "GL_ALPHA",
            BaseFormat::Luminance => "GL_LUMINANCE",
            BaseFormat::LuminanceAlpha => "GL_LUMINANCE_ALPHA",
            BaseFormat::Intensity => "GL_INTENSITY",
        }
    }

    /// Lowercase name (`rgba`, `rgb`, `alpha`, `luminance`, `luminance_alpha`, `intensity`).
    pub fn name(self) -> &'static str {
        match self {
            BaseFormat::Rgba => "rgba",
            BaseFormat::Rgb => "rgb",
            BaseFormat::Alpha => "alpha",
            BaseFormat::Luminance => "luminance",
            BaseFormat::LuminanceAlpha => "luminance_alpha",
            BaseFormat::Intensity => "intensity",
        }
    }

    /// Whether the format has color (all but `GL_ALPHA`): else the environment keeps C_p.
    pub fn has_color(self) -> bool {
        self != BaseFormat::Alpha
    }

    /// Whether the format has alpha (`GL_ALPHA`, `GL_LUMINANCE_ALPHA`, `GL_RGBA`,
    /// `GL_INTENSITY`): else the environment keeps A_p.
    pub fn has_alpha(self) -> bool {
        matches!(
            self,
            BaseFormat::Alpha | BaseFormat::LuminanceAlpha | BaseFormat::Rgba | BaseFormat::Intensity
        )
    }

    /// The texel (C_s, A_s) an RGBA8 texel filtered to `rgba` is in this format (table 3.15's
    /// components, table 3.22's C_s and A_s; a component the format lacks reads as GL's
    /// texture sampling gives it: color 0 for alpha, alpha 1 for color formats).
    pub fn texel(self, rgba: DVec4) -> DVec4 {
        let (r, a) = (rgba.x, rgba.w);
        match self {
            BaseFormat::Rgba => rgba,
            BaseFormat::Rgb => rgba.truncate().extend(1.0),
            BaseFormat::Alpha => DVec4::new(0.0, 0.0, 0.0, a),
            BaseFormat::Luminance => DVec4::new(r, r, r, 1.0),
            BaseFormat::LuminanceAlpha => DVec4::new(r, r, r, a),
            BaseFormat::Intensity => DVec4::splat(r),
        }
    }
}

impl std::str::FromStr for BaseFormat {
    type Err = super::super::errors::UnknownName;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        BaseFormat::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                super::super::errors::UnknownName::new(
                    "texture base format",
                    s,
                    "rgba, rgb, alpha, luminance, luminance_alpha or intensity",
                )
            })
    }
}
