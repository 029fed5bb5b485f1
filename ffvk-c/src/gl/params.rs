//! Each entry point's enums and values read as GL reads them: which names a parameter takes,
//! how many values it has, and the checks GL makes before anything changes.

use ffvk::gl::state::{
    Cap, ColorControl, ColorMaterialMode, Face, LightModelParam, LightParam, MaterialParam, TexEnvParam,
    MAX_LIGHTS,
};
use ffvk::gl::texture::TexEnvMode;
use ffvk::glam::{Mat4, Vec3};

use super::combine::{combine_param, is_combine_pname};
use super::{invalid_enum, read_named, state_error, FfvkContext, GlError, GlResult, Values};
use crate::enums::*;

/// How many values a glLight parameter has; `None` for an unknown one.
pub(crate) fn light_len(pname: u32) -> Option<usize> {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => Some(4),
        GL_SPOT_DIRECTION => Some(3),
        GL_SPOT_EXPONENT
        | GL_SPOT_CUTOFF
        | GL_CONSTANT_ATTENUATION
        | GL_LINEAR_ATTENUATION
        | GL_QUADRATIC_ATTENUATION => Some(1),
        _ => None,
    }
}

pub(crate) const LIGHT_PNAMES: &str = "GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION, GL_SPOT_EXPONENT, GL_SPOT_CUTOFF or GL_*_ATTENUATION";
pub(super) const LIGHT_SCALAR_PNAMES: &str =
    "a single-valued parameter: GL_SPOT_EXPONENT, GL_SPOT_CUTOFF or GL_*_ATTENUATION";

/// The light index of `GL_LIGHTi`, or GL_INVALID_ENUM.
pub(crate) fn light_index(function: &str, light: u32) -> GlResult<usize> {
    match light.checked_sub(GL_LIGHT0) {
        Some(i) if (i as usize) < MAX_LIGHTS => Ok(i as usize),
        _ => Err(invalid_enum(
            function,
            "light",
            light,
            "GL_LIGHT0 .. GL_LIGHT0 + 15 (GL_MAX_LIGHTS is 16)",
        )),
    }
}

/// Checks a glLight call's light and parameter name in GL's order: the light, then the name
/// (scalar entry points take single-valued names only).
pub(super) fn light_call(function: &str, light: u32, pname: u32, scalar: bool) -> GlResult<(usize, usize)> {
    let index = light_index(function, light)?;
    match light_len(pname) {
        Some(1) => Ok((index, 1)),
        Some(n) if !scalar => Ok((index, n)),
        Some(_) => Err(invalid_enum(function, "pname", pname, LIGHT_SCALAR_PNAMES)),
        None => Err(invalid_enum(function, "pname", pname, LIGHT_PNAMES)),
    }
}

pub(super) fn set_light(
    ctx: &mut FfvkContext,
    function: &str,
    index: usize,
    pname: u32,
    v: Values,
) -> GlResult {
    let param = match pname {
        GL_AMBIENT => LightParam::Ambient(v.color4()),
        GL_DIFFUSE => LightParam::Diffuse(v.color4()),
        GL_SPECULAR => LightParam::Specular(v.color4()),
        GL_POSITION => LightParam::Position(v.vec4()),
        GL_SPOT_DIRECTION => LightParam::SpotDirection(Vec3::new(v.plain(0), v.plain(1), v.plain(2))),
        GL_SPOT_EXPONENT => LightParam::SpotExponent(v.plain(0)),
        GL_SPOT_CUTOFF => LightParam::SpotCutoff(v.plain(0)),
        GL_CONSTANT_ATTENUATION => LightParam::ConstantAttenuation(v.plain(0)),
        GL_LINEAR_ATTENUATION => LightParam::LinearAttenuation(v.plain(0)),
        GL_QUADRATIC_ATTENUATION => LightParam::QuadraticAttenuation(v.plain(0)),
        _ => return Err(invalid_enum(function, "pname", pname, LIGHT_PNAMES)),
    };
    ctx.gl.light(index, param).map_err(|e| state_error(function, e))
}

/// The material face of glMaterial (`GL_FRONT`, `GL_BACK`, `GL_FRONT_AND_BACK`).
pub(crate) fn face(function: &str, face: u32) -> GlResult<Face> {
    match face {
        GL_FRONT => Ok(Face::Front),
        GL_BACK => Ok(Face::Back),
        GL_FRONT_AND_BACK => Ok(Face::FrontAndBack),
        _ => Err(invalid_enum(
            function,
            "face",
            face,
            "GL_FRONT, GL_BACK or GL_FRONT_AND_BACK",
        )),
    }
}

pub(crate) const MATERIAL_PNAMES: &str =
    "GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_AMBIENT_AND_DIFFUSE or GL_COLOR_INDEXES";

pub(super) fn material_len(pname: u32) -> Option<usize> {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => Some(4),
        GL_COLOR_INDEXES => Some(3),
        GL_SHININESS => Some(1),
        _ => None,
    }
}

pub(super) fn material_call(
    function: &str,
    face_enum: u32,
    pname: u32,
    scalar: bool,
) -> GlResult<(Face, usize)> {
    let face = face(function, face_enum)?;
    match material_len(pname) {
        Some(1) => Ok((face, 1)),
        Some(n) if !scalar => Ok((face, n)),
        Some(_) => Err(invalid_enum(
            function,
            "pname",
            pname,
            "GL_SHININESS (the one single-valued parameter)",
        )),
        None => Err(invalid_enum(function, "pname", pname, MATERIAL_PNAMES)),
    }
}

pub(super) fn set_material(
    ctx: &mut FfvkContext,
    function: &str,
    face: Face,
    pname: u32,
    v: Values,
) -> GlResult {
    let param = match pname {
        GL_AMBIENT => MaterialParam::Ambient(v.color4()),
        GL_DIFFUSE => MaterialParam::Diffuse(v.color4()),
        GL_SPECULAR => MaterialParam::Specular(v.color4()),
        GL_EMISSION => MaterialParam::Emission(v.color4()),
        GL_AMBIENT_AND_DIFFUSE => MaterialParam::AmbientAndDiffuse(v.color4()),
        GL_SHININESS => MaterialParam::Shininess(v.plain(0)),
        GL_COLOR_INDEXES => {
            v.finite(function, "GL_COLOR_INDEXES", "finite components", 3)?;
            let indexes = [v.plain(0), v.plain(1), v.plain(2)];
            if face.includes_front() {
                ctx.color_indexes[0] = indexes;
            }
            if face.includes_back() {
                ctx.color_indexes[1] = indexes;
            }
            return Ok(());
        }
        _ => return Err(invalid_enum(function, "pname", pname, MATERIAL_PNAMES)),
    };
    ctx.gl.material(face, param).map_err(|e| state_error(function, e))
}

pub(super) const LIGHT_MODEL_PNAMES: &str = "GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE or GL_LIGHT_MODEL_COLOR_CONTROL";

pub(super) fn light_model_len(function: &str, pname: u32, scalar: bool) -> GlResult<usize> {
    match pname {
        GL_LIGHT_MODEL_AMBIENT if !scalar => Ok(4),
        GL_LIGHT_MODEL_AMBIENT => Err(invalid_enum(
            function,
            "pname",
            pname,
            "a single-valued parameter: GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE or GL_LIGHT_MODEL_COLOR_CONTROL",
        )),
        GL_LIGHT_MODEL_LOCAL_VIEWER | GL_LIGHT_MODEL_TWO_SIDE | GL_LIGHT_MODEL_COLOR_CONTROL => Ok(1),
        _ => Err(invalid_enum(function, "pname", pname, LIGHT_MODEL_PNAMES)),
    }
}

pub(super) fn set_light_model(ctx: &mut FfvkContext, function: &str, pname: u32, v: Values) -> GlResult {
    let param = match pname {
        GL_LIGHT_MODEL_AMBIENT => LightModelParam::Ambient(v.color4()),
        GL_LIGHT_MODEL_LOCAL_VIEWER => {
            LightModelParam::LocalViewer(v.as_bool(function, "GL_LIGHT_MODEL_LOCAL_VIEWER")?)
        }
        GL_LIGHT_MODEL_TWO_SIDE => LightModelParam::TwoSide(v.as_bool(function, "GL_LIGHT_MODEL_TWO_SIDE")?),
        GL_LIGHT_MODEL_COLOR_CONTROL => match v.as_enum(
            function,
            "GL_LIGHT_MODEL_COLOR_CONTROL",
            "GL_SINGLE_COLOR or GL_SEPARATE_SPECULAR_COLOR",
        )? {
            GL_SINGLE_COLOR => LightModelParam::ColorControl(ColorControl::SingleColor),
            GL_SEPARATE_SPECULAR_COLOR => LightModelParam::ColorControl(ColorControl::SeparateSpecularColor),
            other => {
                return Err(invalid_enum(
                    function,
                    "GL_LIGHT_MODEL_COLOR_CONTROL value",
                    other,
                    "GL_SINGLE_COLOR or GL_SEPARATE_SPECULAR_COLOR",
                ))
            }
        },
        _ => return Err(invalid_enum(function, "pname", pname, LIGHT_MODEL_PNAMES)),
    };
    ctx.gl.light_model(param).map_err(|e| state_error(function, e))
}

const TEX_ENV_MODES: &str = "GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD or GL_COMBINE";
pub(crate) const TEX_ENV_PNAMES: &str = "GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR or a GL_COMBINE parameter: GL_COMBINE_RGB, GL_COMBINE_ALPHA, GL_SRC0_RGB .. GL_SRC2_RGB, GL_SRC0_ALPHA .. GL_SRC2_ALPHA, GL_OPERAND0_RGB .. GL_OPERAND2_RGB, GL_OPERAND0_ALPHA .. GL_OPERAND2_ALPHA, GL_RGB_SCALE or GL_ALPHA_SCALE";
const TEX_ENV_SCALAR_PNAMES: &str = "a single-valued parameter: GL_TEXTURE_ENV_MODE or a GL_COMBINE parameter (GL_COMBINE_RGB, GL_COMBINE_ALPHA, GL_SRCn_RGB, GL_SRCn_ALPHA, GL_OPERANDn_RGB, GL_OPERANDn_ALPHA, GL_RGB_SCALE or GL_ALPHA_SCALE)";

pub(super) fn tex_env_len(function: &str, target: u32, pname: u32, scalar: bool) -> GlResult<usize> {
    if target == GL_POINT_SPRITE {
        return match pname {
            GL_COORD_REPLACE => Ok(1),
            _ => Err(invalid_enum(
                function,
                "pname",
                pname,
                "GL_COORD_REPLACE (target GL_POINT_SPRITE)",
            )),
        };
    }
    if target != GL_TEXTURE_ENV {
        return Err(invalid_enum(
            function,
            "target",
            target,
            "GL_TEXTURE_ENV or GL_POINT_SPRITE",
        ));
    }
    match pname {
        GL_TEXTURE_ENV_MODE => Ok(1),
        p if is_combine_pname(p) => Ok(1),
        GL_TEXTURE_ENV_COLOR if !scalar => Ok(4),
        GL_TEXTURE_ENV_COLOR => Err(invalid_enum(function, "pname", pname, TEX_ENV_SCALAR_PNAMES)),
        _ => Err(invalid_enum(function, "pname", pname, TEX_ENV_PNAMES)),
    }
}

pub(super) fn set_tex_env(ctx: &mut FfvkContext, function: &str, pname: u32, v: Values) -> GlResult {
    if pname == GL_COORD_REPLACE {
        // GL_TRUE or GL_FALSE; another value is GL_INVALID_VALUE, as Mesa sets it.
        let value = v.plain(0);
        if value != 0.0 && value != 1.0 {
            return Err(GlError::invalid_value(
                function,
                format!("GL_COORD_REPLACE = {value} is not GL_TRUE (1) or GL_FALSE (0)"),
            ));
        }
        ctx.gl.coord_replace(value == 1.0);
        return Ok(());
    }
    let param = match pname {
        GL_TEXTURE_ENV_MODE => {
            TexEnvParam::Mode(match v.as_enum(function, "GL_TEXTURE_ENV_MODE", TEX_ENV_MODES)? {
                GL_MODULATE => TexEnvMode::Modulate,
                GL_REPLACE => TexEnvMode::Replace,
                GL_DECAL => TexEnvMode::Decal,
                GL_BLEND => TexEnvMode::Blend,
                GL_ADD => TexEnvMode::Add,
                GL_COMBINE => TexEnvMode::Combine,
                other => {
                    return Err(invalid_enum(
                        function,
                        "GL_TEXTURE_ENV_MODE value",
                        other,
                        TEX_ENV_MODES,
                    ))
                }
            })
        }
        p if is_combine_pname(p) => combine_param(function, p, v)?,
        _ => TexEnvParam::Color(v.color4()),
    };
    ctx.gl.tex_env(param).map_err(|e| state_error(function, e))
}

/// The capability of glEnable, glDisable and glIsEnabled.
pub(crate) fn cap(function: &str, cap: u32) -> GlResult<Cap> {
    if let Some(raster) = super::raster_cap(cap) {
        return Ok(raster);
    }
    match cap {
        GL_LIGHTING => Ok(Cap::Lighting),
        GL_COLOR_MATERIAL => Ok(Cap::ColorMaterial),
        GL_NORMALIZE => Ok(Cap::Normalize),
        GL_RESCALE_NORMAL => Ok(Cap::RescaleNormal),
        GL_TEXTURE_2D => Ok(Cap::Texture2D),
        GL_TEXTURE_CUBE_MAP => Ok(Cap::TextureCubeMap),
        GL_COLOR_SUM => Ok(Cap::ColorSum),
        GL_ALPHA_TEST => Ok(Cap::AlphaTest),
        GL_POINT_SPRITE => Ok(Cap::PointSprite),
        GL_FOG => Ok(Cap::Fog),
        p if (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + 6).contains(&p) => Ok(Cap::ClipPlane((p - GL_CLIP_PLANE0) as usize)),
        p if (GL_TEXTURE_GEN_S..=GL_TEXTURE_GEN_Q).contains(&p) => {
            Ok(Cap::TextureGen((p - GL_TEXTURE_GEN_S) as usize))
        }
        other => light_index(function, other).map(Cap::Light).map_err(|_| {
            invalid_enum(
                function,
                "cap",
                other,
                "GL_LIGHTING, GL_LIGHT0 .. GL_LIGHT0 + 15, GL_COLOR_MATERIAL, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, GL_COLOR_SUM, GL_FOG, GL_ALPHA_TEST, GL_POINT_SPRITE, GL_CLIP_PLANE0 .. GL_CLIP_PLANE0 + 5, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_LINE_STIPPLE, GL_POLYGON_STIPPLE, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP, GL_BLEND, GL_DEPTH_TEST or GL_CULL_FACE",
            )
        }),
    }
}

pub(super) fn color_material_mode(function: &str, mode: u32) -> GlResult<ColorMaterialMode> {
    match mode {
        GL_EMISSION => Ok(ColorMaterialMode::Emission),
        GL_AMBIENT => Ok(ColorMaterialMode::Ambient),
        GL_DIFFUSE => Ok(ColorMaterialMode::Diffuse),
        GL_SPECULAR => Ok(ColorMaterialMode::Specular),
        GL_AMBIENT_AND_DIFFUSE => Ok(ColorMaterialMode::AmbientAndDiffuse),
        _ => Err(invalid_enum(
            function,
            "mode",
            mode,
            "GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR or GL_AMBIENT_AND_DIFFUSE",
        )),
    }
}

pub(super) fn load_matrix(function: &str, m: *const f32) -> GlResult<Mat4> {
    // SAFETY: the caller's contract (ffvk.h): m is null or points at 16 floats.
    let values = unsafe { read_named(function, "m", m, 16) }?;
    let mut cols = [0.0f32; 16];
    cols.copy_from_slice(values);
    let matrix = Mat4::from_cols_array(&cols);
    if let Some(v) = cols.iter().find(|v| !v.is_finite()) {
        return Err(GlError {
            code: GL_INVALID_VALUE,
            message: format!("{function}: component {v} is not a finite number: expected 16 finite floats, column-major (GL_INVALID_VALUE)"),
        });
    }
    Ok(matrix)
}
