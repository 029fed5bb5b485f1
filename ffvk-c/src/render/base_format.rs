//! A texture's base internal format as C gives it: GL's enum (`glTexImage2D`'s
//! `internalformat`, GL 2.1 table 3.15), for `ffvkCreateTextureWithFormat` and
//! `ffvkCreateCubeMapWithFormat`.

use ffvk::gl::texture::BaseFormat;

use super::invalid;
use crate::enums::*;
use crate::result::FfvkResult;

/// The six base internal formats with their enums, in the order messages list them.
const BASE: [(&str, u32, BaseFormat); 6] = [
    ("GL_ALPHA", GL_ALPHA, BaseFormat::Alpha),
    ("GL_LUMINANCE", GL_LUMINANCE, BaseFormat::Luminance),
    (
        "GL_LUMINANCE_ALPHA",
        GL_LUMINANCE_ALPHA,
        BaseFormat::LuminanceAlpha,
    ),
    ("GL_INTENSITY", GL_INTENSITY, BaseFormat::Intensity),
    ("GL_RGB", GL_RGB, BaseFormat::Rgb),
    ("GL_RGBA", GL_RGBA, BaseFormat::Rgba),
];

/// What else `glTexImage2D` takes as `internalformat` in GL 2.1, so that a message can name
/// the base format meant: the sized formats of table 3.16 and EXT_texture_sRGB's, as
/// `<GL/gl.h>` spells them (the view's `VkFormat` gives the texel's bits and its sRGB decode;
/// the base format says which components the texture has).
const SIZED: [(&str, u32, BaseFormat); 40] = [
    ("GL_ALPHA4", 0x803B, BaseFormat::Alpha),
    ("GL_ALPHA8", 0x803C, BaseFormat::Alpha),
    ("GL_ALPHA12", 0x803D, BaseFormat::Alpha),
    ("GL_ALPHA16", 0x803E, BaseFormat::Alpha),
    ("GL_LUMINANCE4", 0x803F, BaseFormat::Luminance),
    ("GL_LUMINANCE8", 0x8040, BaseFormat::Luminance),
    ("GL_LUMINANCE12", 0x8041, BaseFormat::Luminance),
    ("GL_LUMINANCE16", 0x8042, BaseFormat::Luminance),
    ("GL_LUMINANCE4_ALPHA4", 0x8043, BaseFormat::LuminanceAlpha),
    ("GL_LUMINANCE6_ALPHA2", 0x8044, BaseFormat::LuminanceAlpha),
    ("GL_LUMINANCE8_ALPHA8", 0x8045, BaseFormat::LuminanceAlpha),
    ("GL_LUMINANCE12_ALPHA4", 0x8046, BaseFormat::LuminanceAlpha),
    ("GL_LUMINANCE12_ALPHA12", 0x8047, BaseFormat::LuminanceAlpha),
    ("GL_LUMINANCE16_ALPHA16", 0x8048, BaseFormat::LuminanceAlpha),
    ("GL_INTENSITY4", 0x804A, BaseFormat::Intensity),
    ("GL_INTENSITY8", 0x804B, BaseFormat::Intensity),
    ("GL_INTENSITY12", 0x804C, BaseFormat::Intensity),
    ("GL_INTENSITY16", 0x804D, BaseFormat::Intensity),
    ("GL_R3_G3_B2", 0x2A10, BaseFormat::Rgb),
    ("GL_RGB4", 0x804F, BaseFormat::Rgb),
    ("GL_RGB5", 0x8050, BaseFormat::Rgb),
    ("GL_RGB8", 0x8051, BaseFormat::Rgb),
    ("GL_RGB10", 0x8052, BaseFormat::Rgb),
    ("GL_RGB12", 0x8053, BaseFormat::Rgb),
    ("GL_RGB16", 0x8054, BaseFormat::Rgb),
    ("GL_RGBA2", 0x8055, BaseFormat::Rgba),
    ("GL_RGBA4", 0x8056, BaseFormat::Rgba),
    ("GL_RGB5_A1", 0x8057, BaseFormat::Rgba),
    ("GL_RGBA8", 0x8058, BaseFormat::Rgba),
    ("GL_RGB10_A2", 0x8059, BaseFormat::Rgba),
    ("GL_RGBA12", 0x805A, BaseFormat::Rgba),
    ("GL_RGBA16", 0x805B, BaseFormat::Rgba),
    ("GL_SRGB", 0x8C40, BaseFormat::Rgb),
    ("GL_SRGB8", 0x8C41, BaseFormat::Rgb),
    ("GL_SRGB_ALPHA", 0x8C42, BaseFormat::Rgba),
    ("GL_SRGB8_ALPHA8", 0x8C43, BaseFormat::Rgba),
    ("GL_SLUMINANCE_ALPHA", 0x8C44, BaseFormat::LuminanceAlpha),
    ("GL_SLUMINANCE8_ALPHA8", 0x8C45, BaseFormat::LuminanceAlpha),
    ("GL_SLUMINANCE", 0x8C46, BaseFormat::Luminance),
    ("GL_SLUMINANCE8", 0x8C47, BaseFormat::Luminance),
];

/// The base format `internalformat` names, or `FFVK_ERROR_INVALID_ARGUMENT` naming `function`,
/// the parameter, the value (by its GL name where it has one) and the six accepted; a sized
/// format, an sRGB one or GL 1.0's component count (1 to 4) is refused saying which base
/// format to give instead.
pub(super) fn base_format(function: &str, internalformat: u32) -> Result<BaseFormat, FfvkResult> {
    if let Some(&(_, _, format)) = BASE.iter().find(|(_, v, _)| *v == internalformat) {
        return Ok(format);
    }
    let name = |format: BaseFormat| {
        BASE.iter()
            .find(|(_, _, f)| *f == format)
            .map_or("GL_RGBA", |(n, _, _)| *n)
    };
    let sized = SIZED.iter().find(|(_, v, _)| *v == internalformat);
    let counts = [
        BaseFormat::Luminance,
        BaseFormat::LuminanceAlpha,
        BaseFormat::Rgb,
        BaseFormat::Rgba,
    ];
    let (given, hint) = match (sized, internalformat) {
        (Some(&(sized, value, format)), _) => (
            format!("{sized} (0x{value:04X})"),
            format!(
                " ({sized} is a sized or sRGB internal format: give its base format, {}; the view's VkFormat gives the texel's bits and sRGB decode)",
                name(format)
            ),
        ),
        (None, n @ 1..=4) => (
            n.to_string(),
            format!(
                " ({n} is GL 1.0's component count: give its base format, {})",
                name(counts[n as usize - 1])
            ),
        ),
        (None, other) => (enum_name(other), String::new()),
    };
    let names: Vec<&str> = BASE.iter().map(|(n, _, _)| *n).collect();
    Err(invalid(format!(
        "{function}: internalformat {given} is not a base internal format: expected {} or {} (GL 2.1 table 3.15){hint}",
        names[..names.len() - 1].join(", "),
        names[names.len() - 1]
    )))
}
