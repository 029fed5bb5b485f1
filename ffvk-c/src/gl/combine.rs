//! glTexEnv's `GL_COMBINE` parameters (GL 2.1 §3.8.13, table 3.24; ARB_texture_env_combine,
//! _dot3 and _crossbar) of the active texture unit: which names there are, the values each
//! takes and GL's errors. `ffvkTexEnv*` (`entry.rs`) set them through `params.rs`,
//! `ffvkGetTexEnv*` (`query.rs`) answer them.

use ffvk::gl::state::TexEnvParam;
use ffvk::gl::texture::{AlphaOperand, CombineFunc, CombineSource, RgbOperand, MAX_TEXTURE_UNITS};

use super::{invalid_enum, GlResult, Values};
use crate::enums::*;

/// `GL_TEXTURE0` .. `GL_TEXTURE31`: the enums a `GL_TEXTUREn` source may be spelled with; those
/// of a unit at or past `GL_MAX_TEXTURE_UNITS` (4) are refused.
const TEXTURE_UNIT_ENUMS: std::ops::Range<u32> = GL_TEXTURE0..GL_TEXTURE0 + 32;

/// `GL_COMBINE_RGB` and `GL_COMBINE_ALPHA`'s values (the dot products for RGB only).
pub(crate) const FUNCS: [(u32, CombineFunc); 8] = [
    (GL_REPLACE, CombineFunc::Replace),
    (GL_MODULATE, CombineFunc::Modulate),
    (GL_ADD, CombineFunc::Add),
    (GL_ADD_SIGNED, CombineFunc::AddSigned),
    (GL_INTERPOLATE, CombineFunc::Interpolate),
    (GL_SUBTRACT, CombineFunc::Subtract),
    (GL_DOT3_RGB, CombineFunc::Dot3Rgb),
    (GL_DOT3_RGBA, CombineFunc::Dot3Rgba),
];

/// `GL_SRCn_RGB` and `GL_SRCn_ALPHA`'s values besides `GL_TEXTUREn` ([`source_enum`]).
pub(crate) const SOURCES: [(u32, CombineSource); 4] = [
    (GL_TEXTURE, CombineSource::Texture),
    (GL_CONSTANT, CombineSource::Constant),
    (GL_PRIMARY_COLOR, CombineSource::PrimaryColor),
    (GL_PREVIOUS, CombineSource::Previous),
];

/// `GL_OPERANDn_RGB`'s values.
pub(crate) const RGB_OPERANDS: [(u32, RgbOperand); 4] = [
    (GL_SRC_COLOR, RgbOperand::SrcColor),
    (GL_ONE_MINUS_SRC_COLOR, RgbOperand::OneMinusSrcColor),
    (GL_SRC_ALPHA, RgbOperand::SrcAlpha),
    (GL_ONE_MINUS_SRC_ALPHA, RgbOperand::OneMinusSrcAlpha),
];

/// `GL_OPERANDn_ALPHA`'s values.
pub(crate) const ALPHA_OPERANDS: [(u32, AlphaOperand); 2] = [
    (GL_SRC_ALPHA, AlphaOperand::SrcAlpha),
    (GL_ONE_MINUS_SRC_ALPHA, AlphaOperand::OneMinusSrcAlpha),
];

/// The GL enum of a `GL_SRCn_RGB` or `GL_SRCn_ALPHA` value: `GL_TEXTURE0 + n` for unit n's
/// texel, else its entry in [`SOURCES`].
pub(crate) fn source_enum(source: CombineSource) -> u32 {
    match source {
        CombineSource::TextureUnit(n) => GL_TEXTURE0 + u32::from(n),
        other => gl_enum(&SOURCES, other),
    }
}

/// The GL enum of `value` in `table` (every value of ffvk's has one).
pub(crate) fn gl_enum<T: Copy + PartialEq>(table: &[(u32, T)], value: T) -> u32 {
    table.iter().find(|&&(_, v)| v == value).map_or(0, |&(e, _)| e)
}

fn from_gl<T: Copy>(table: &[(u32, T)], value: u32) -> Option<T> {
    table.iter().find(|&&(e, _)| e == value).map(|&(_, v)| v)
}

/// Which of an argument's parameters a name is.
#[derive(Clone, Copy)]
pub(crate) enum Argument {
    SourceRgb,
    SourceAlpha,
    OperandRgb,
    OperandAlpha,
}

/// The parameter and the argument n (0, 1, 2) of `GL_SRCn_RGB`, `GL_SRCn_ALPHA`,
/// `GL_OPERANDn_RGB` or `GL_OPERANDn_ALPHA`; `None` for another name.
pub(crate) fn argument(pname: u32) -> Option<(Argument, usize)> {
    let (which, first) = match pname {
        GL_SRC0_RGB..=GL_SRC2_RGB => (Argument::SourceRgb, GL_SRC0_RGB),
        GL_SRC0_ALPHA..=GL_SRC2_ALPHA => (Argument::SourceAlpha, GL_SRC0_ALPHA),
        GL_OPERAND0_RGB..=GL_OPERAND2_RGB => (Argument::OperandRgb, GL_OPERAND0_RGB),
        GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA => (Argument::OperandAlpha, GL_OPERAND0_ALPHA),
        _ => return None,
    };
    Some((which, (pname - first) as usize))
}

/// Whether `pname` is one of `GL_COMBINE`'s names (each has one value).
pub(crate) fn is_combine_pname(pname: u32) -> bool {
    matches!(
        pname,
        GL_COMBINE_RGB | GL_COMBINE_ALPHA | GL_RGB_SCALE | GL_ALPHA_SCALE
    ) || argument(pname).is_some()
}

/// `pname`'s GL name (`GL_SRC1_ALPHA`), for messages.
fn pname_name(pname: u32) -> &'static str {
    gl_enums()
        .iter()
        .find(|&&(_, v)| v == pname)
        .map_or("pname", |&(name, _)| name)
}

/// The glTexEnv parameter `pname` (one of [`is_combine_pname`]'s) sets to the value `v`;
/// GL_INVALID_ENUM for a value the name does not take. The state refuses a dot product as
/// the alpha function and a scale other than 1, 2 or 4.
pub(super) fn combine_param(function: &str, pname: u32, v: Values) -> GlResult<TexEnvParam> {
    const FUNC_NAMES: &str = "GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB or GL_DOT3_RGBA (GL_DOT3_* for GL_COMBINE_RGB only)";
    const SOURCE_NAMES: &str =
        "GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS or GL_TEXTURE0 .. GL_TEXTURE3 (another unit's texel)";
    const RGB_OPERAND_NAMES: &str =
        "GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA or GL_ONE_MINUS_SRC_ALPHA";
    const ALPHA_OPERAND_NAMES: &str =
        "GL_SRC_ALPHA or GL_ONE_MINUS_SRC_ALPHA (an alpha argument takes no color)";
    match pname {
        GL_RGB_SCALE => return Ok(TexEnvParam::RgbScale(v.plain(0))),
        GL_ALPHA_SCALE => return Ok(TexEnvParam::AlphaScale(v.plain(0))),
        _ => {}
    }
    let name = pname_name(pname);
    let expected = match argument(pname) {
        None => FUNC_NAMES,
        Some((Argument::SourceRgb | Argument::SourceAlpha, _)) => SOURCE_NAMES,
        Some((Argument::OperandRgb, _)) => RGB_OPERAND_NAMES,
        Some((Argument::OperandAlpha, _)) => ALPHA_OPERAND_NAMES,
    };
    let value = v.as_enum(function, name, expected)?;
    let refused = |expected: &str| invalid_enum(function, &format!("{name} value"), value, expected);
    let param = match argument(pname) {
        None => {
            let f = from_gl(&FUNCS, value).ok_or_else(|| refused(expected))?;
            if pname == GL_COMBINE_RGB {
                TexEnvParam::CombineRgb(f)
            } else {
                TexEnvParam::CombineAlpha(f)
            }
        }
        Some((which @ (Argument::SourceRgb | Argument::SourceAlpha), n)) => {
            let s = match from_gl(&SOURCES, value) {
                Some(s) => s,
                None if TEXTURE_UNIT_ENUMS.contains(&value) => {
                    let unit = value - GL_TEXTURE0;
                    if unit as usize >= MAX_TEXTURE_UNITS {
                        return Err(refused(
                            "GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS or GL_TEXTURE0 .. GL_TEXTURE3 (a GL_TEXTUREn source names a unit below GL_MAX_TEXTURE_UNITS, 4)",
                        ));
                    }
                    CombineSource::TextureUnit(unit as u8)
                }
                None => return Err(refused(expected)),
            };
            match which {
                Argument::SourceRgb => TexEnvParam::SourceRgb(n, s),
                _ => TexEnvParam::SourceAlpha(n, s),
            }
        }
        Some((Argument::OperandRgb, n)) => {
            TexEnvParam::OperandRgb(n, from_gl(&RGB_OPERANDS, value).ok_or_else(|| refused(expected))?)
        }
        Some((Argument::OperandAlpha, n)) => TexEnvParam::OperandAlpha(
            n,
            from_gl(&ALPHA_OPERANDS, value).ok_or_else(|| refused(expected))?,
        ),
    };
    Ok(param)
}
