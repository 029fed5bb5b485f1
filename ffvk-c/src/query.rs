//! The queries an application makes of the lighting state: glGetLight, glGetMaterial,
//! glGetTexEnv and glGet{Boolean,Integer,Float}v, with GL 2.1's conversions (section 6.1.2):
//! booleans as 0 or 1, integers and enums as they are, floats rounded to the nearest integer,
//! colors mapped by [(2^32 - 1) c - 1] / 2, and anything non-zero as `GL_TRUE`.

use ffvk::gl::state::{
    Cap, ColorControl, ColorMaterialMode, Face, Light, Material, SpriteOrigin, MAX_LIGHTS,
};
use ffvk::gl::texture::{TexEnvMode, TexGenMode, MAX_TEXTURE_UNITS};

use crate::enums::*;
use crate::gl::{
    combine_argument, face, gl_enum, invalid_enum, light_index, raster_cap, source_enum, texgen_coord,
    with_context, Argument, FfvkContext, GlResult, ALPHA_OPERANDS, FUNCS, LIGHT_PNAMES, RGB_OPERANDS,
    TEXGEN_PNAMES, TEX_ENV_PNAMES,
};

mod raster;

/// A queried value before its conversion to the entry point's type.
enum Answer {
    Bool(bool),
    /// An enum or an integer.
    Int(i64),
    /// Several enums, integers or booleans (0 or 1).
    Ints(Vec<i64>),
    /// Floats that convert to integers by rounding.
    Floats(Vec<f32>),
    /// Color or normal components, which convert to integers by GL's linear mapping.
    Color(Vec<f32>),
}

impl Answer {
    fn floats(&self) -> Vec<f32> {
        match self {
            Answer::Bool(b) => vec![*b as u8 as f32],
            Answer::Int(i) => vec![*i as f32],
            Answer::Ints(v) => v.iter().map(|&i| i as f32).collect(),
            Answer::Floats(v) => v.clone(),
            Answer::Color(c) => c.clone(),
        }
    }
    fn ints(&self) -> Vec<i32> {
        // GL says "rounded to the nearest integer"; halves go away from zero, as Mesa's
        // IROUND takes them (2.5 is 3).
        let round = |v: f32| (v as f64).round().clamp(i32::MIN as f64, i32::MAX as f64) as i32;
        match self {
            Answer::Bool(b) => vec![*b as i32],
            // An unsigned value past i32's range (a stencil mask of all ones) is the nearest
            // representable one, as Mesa answers it.
            Answer::Int(i) => vec![(*i).clamp(i32::MIN.into(), i32::MAX.into()) as i32],
            Answer::Ints(v) => v.iter().map(|&i| i as i32).collect(),
            Answer::Floats(v) => v.iter().map(|&v| round(v)).collect(),
            Answer::Color(c) => c
                .iter()
                .map(|&c| {
                    ((4_294_967_295.0 * c as f64 - 1.0) / 2.0)
                        .round_ties_even()
                        .clamp(i32::MIN as f64, i32::MAX as f64) as i32
                })
                .collect(),
        }
    }
    fn bools(&self) -> Vec<u8> {
        match self {
            Answer::Bool(b) => vec![*b as u8],
            Answer::Int(i) => vec![(*i != 0) as u8],
            Answer::Ints(v) => v.iter().map(|&i| (i != 0) as u8).collect(),
            other => other.floats().iter().map(|&v| (v != 0.0) as u8).collect(),
        }
    }
}

pub(crate) fn is_enabled(c: &FfvkContext, cap: Cap) -> bool {
    let l = &c.gl.lighting;
    match cap {
        Cap::Lighting => l.lighting,
        Cap::Light(i) => l.lights[i].enabled,
        Cap::ColorMaterial => l.color_material.enabled,
        Cap::Normalize => l.normalize,
        Cap::RescaleNormal => l.rescale_normal,
        Cap::Texture2D => l.texture_units[c.gl.active_unit].enabled,
        Cap::TextureCubeMap => l.texture_units[c.gl.active_unit].cube_map,
        Cap::ColorSum => l.fragment.color_sum,
        Cap::AlphaTest => l.fragment.alpha_test.enabled,
        Cap::Fog => l.fragment.fog.enabled,
        Cap::ClipPlane(i) => l.clip.enabled.get(i).copied().unwrap_or(false),
        Cap::PointSprite => l.points.sprite,
        Cap::TextureGen(i) => l.texture_units[c.gl.active_unit]
            .texgen
            .get(i)
            .is_some_and(|g| g.enabled),
        other => c.gl.raster.enabled(other).unwrap_or(false),
    }
}

fn light_answer(f: &str, light: &Light, pname: u32) -> GlResult<Answer> {
    Ok(match pname {
        GL_AMBIENT => Answer::Color(light.ambient.to_array().to_vec()),
        GL_DIFFUSE => Answer::Color(light.diffuse.to_array().to_vec()),
        GL_SPECULAR => Answer::Color(light.specular.to_array().to_vec()),
        GL_POSITION => Answer::Floats(light.position.to_array().to_vec()),
        GL_SPOT_DIRECTION => Answer::Floats(light.spot_direction.to_array().to_vec()),
        GL_SPOT_EXPONENT => Answer::Floats(vec![light.spot_exponent]),
        GL_SPOT_CUTOFF => Answer::Floats(vec![light.spot_cutoff]),
        GL_CONSTANT_ATTENUATION => Answer::Floats(vec![light.constant_attenuation]),
        GL_LINEAR_ATTENUATION => Answer::Floats(vec![light.linear_attenuation]),
        GL_QUADRATIC_ATTENUATION => Answer::Floats(vec![light.quadratic_attenuation]),
        _ => return Err(invalid_enum(f, "pname", pname, LIGHT_PNAMES)),
    })
}

fn material_answer(f: &str, c: &FfvkContext, face_enum: u32, pname: u32) -> GlResult<Answer> {
    let (material, side): (&Material, usize) = match face(f, face_enum)? {
        Face::Front => (&c.gl.lighting.front, 0),
        Face::Back => (&c.gl.lighting.back, 1),
        Face::FrontAndBack => {
            return Err(invalid_enum(
                f,
                "face",
                face_enum,
                "GL_FRONT or GL_BACK (a query names one face)",
            ))
        }
    };
    Ok(match pname {
        GL_AMBIENT => Answer::Color(material.ambient.to_array().to_vec()),
        GL_DIFFUSE => Answer::Color(material.diffuse.to_array().to_vec()),
        GL_SPECULAR => Answer::Color(material.specular.to_array().to_vec()),
        GL_EMISSION => Answer::Color(material.emission.to_array().to_vec()),
        GL_SHININESS => Answer::Floats(vec![material.shininess]),
        GL_COLOR_INDEXES => Answer::Floats(c.color_indexes[side].to_vec()),
        _ => {
            return Err(invalid_enum(
                f,
                "pname",
                pname,
                "GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS or GL_COLOR_INDEXES",
            ))
        }
    })
}

fn tex_env_answer(f: &str, c: &FfvkContext, target: u32, pname: u32) -> GlResult<Answer> {
    if target == GL_POINT_SPRITE {
        return match pname {
            GL_COORD_REPLACE => Ok(Answer::Bool(
                c.gl.lighting.texture_units[c.gl.active_unit].coord_replace,
            )),
            _ => Err(invalid_enum(
                f,
                "pname",
                pname,
                "GL_COORD_REPLACE (target GL_POINT_SPRITE)",
            )),
        };
    }
    if target != GL_TEXTURE_ENV {
        return Err(invalid_enum(
            f,
            "target",
            target,
            "GL_TEXTURE_ENV or GL_POINT_SPRITE",
        ));
    }
    let unit = &c.gl.lighting.texture_units[c.gl.active_unit];
    let combine = &unit.combine;
    Ok(match pname {
        GL_TEXTURE_ENV_MODE => Answer::Int(match unit.env_mode {
            TexEnvMode::Replace => GL_REPLACE,
            TexEnvMode::Decal => GL_DECAL,
            TexEnvMode::Blend => GL_BLEND,
            TexEnvMode::Add => GL_ADD,
            TexEnvMode::Combine => GL_COMBINE,
            _ => GL_MODULATE,
        } as i64),
        GL_TEXTURE_ENV_COLOR => Answer::Color(unit.env_color.to_array().to_vec()),
        GL_COMBINE_RGB => Answer::Int(gl_enum(&FUNCS, combine.rgb).into()),
        GL_COMBINE_ALPHA => Answer::Int(gl_enum(&FUNCS, combine.alpha).into()),
        GL_RGB_SCALE => Answer::Floats(vec![combine.rgb_scale]),
        GL_ALPHA_SCALE => Answer::Floats(vec![combine.alpha_scale]),
        _ => Answer::Int(
            match combine_argument(pname) {
                Some((Argument::SourceRgb, n)) => source_enum(combine.rgb_sources[n]),
                Some((Argument::SourceAlpha, n)) => source_enum(combine.alpha_sources[n]),
                Some((Argument::OperandRgb, n)) => gl_enum(&RGB_OPERANDS, combine.rgb_operands[n]),
                Some((Argument::OperandAlpha, n)) => gl_enum(&ALPHA_OPERANDS, combine.alpha_operands[n]),
                None => return Err(invalid_enum(f, "pname", pname, TEX_ENV_PNAMES)),
            }
            .into(),
        ),
    })
}

/// glGetTexGen's answer: the mode as GL's enum, a plane's four values as stored (the eye plane
/// in eye space).
fn tex_gen_answer(f: &str, c: &FfvkContext, coord: u32, pname: u32) -> GlResult<Answer> {
    let gen = &c.gl.lighting.texture_units[c.gl.active_unit].texgen[texgen_coord(f, coord)?];
    Ok(match pname {
        GL_TEXTURE_GEN_MODE => Answer::Int(i64::from(match gen.mode {
            TexGenMode::ObjectLinear => GL_OBJECT_LINEAR,
            TexGenMode::SphereMap => GL_SPHERE_MAP,
            TexGenMode::ReflectionMap => GL_REFLECTION_MAP,
            TexGenMode::NormalMap => GL_NORMAL_MAP,
            _ => GL_EYE_LINEAR,
        })),
        GL_OBJECT_PLANE => Answer::Floats(gen.object_plane.to_array().to_vec()),
        GL_EYE_PLANE => Answer::Floats(gen.eye_plane.to_array().to_vec()),
        _ => return Err(invalid_enum(f, "pname", pname, TEXGEN_PNAMES)),
    })
}

fn face_enum(face: Face) -> u32 {
    match face {
        Face::Front => GL_FRONT,
        Face::Back => GL_BACK,
        Face::FrontAndBack => GL_FRONT_AND_BACK,
    }
}

/// glGet's answer for the lighting state's names.
fn get_answer(f: &str, c: &FfvkContext, pname: u32) -> GlResult<Answer> {
    let l = &c.gl.lighting;
    let cap = match pname {
        GL_LIGHTING => Some(Cap::Lighting),
        GL_COLOR_MATERIAL => Some(Cap::ColorMaterial),
        GL_NORMALIZE => Some(Cap::Normalize),
        GL_RESCALE_NORMAL => Some(Cap::RescaleNormal),
        GL_TEXTURE_2D => Some(Cap::Texture2D),
        GL_TEXTURE_CUBE_MAP => Some(Cap::TextureCubeMap),
        GL_COLOR_SUM => Some(Cap::ColorSum),
        GL_ALPHA_TEST => Some(Cap::AlphaTest),
        GL_FOG => Some(Cap::Fog),
        GL_POINT_SPRITE => Some(Cap::PointSprite),
        p if (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + 6).contains(&p) => {
            Some(Cap::ClipPlane((p - GL_CLIP_PLANE0) as usize))
        }
        p if (GL_TEXTURE_GEN_S..=GL_TEXTURE_GEN_Q).contains(&p) => {
            Some(Cap::TextureGen((p - GL_TEXTURE_GEN_S) as usize))
        }
        p if p >= GL_LIGHT0 && p < GL_LIGHT0 + MAX_LIGHTS as u32 => light_index(f, p).ok().map(Cap::Light),
        p => raster_cap(p),
    };
    if let Some(cap) = cap {
        return Ok(Answer::Bool(is_enabled(c, cap)));
    }
    if let Some(answer) = raster::answer(c, pname) {
        return Ok(answer);
    }
    Ok(match pname {
        GL_LIGHT_MODEL_AMBIENT => Answer::Color(l.model.ambient.to_array().to_vec()),
        GL_LIGHT_MODEL_LOCAL_VIEWER => Answer::Bool(l.model.local_viewer),
        GL_LIGHT_MODEL_TWO_SIDE => Answer::Bool(l.model.two_side),
        GL_LIGHT_MODEL_COLOR_CONTROL => Answer::Int(match l.model.color_control {
            ColorControl::SingleColor => GL_SINGLE_COLOR,
            ColorControl::SeparateSpecularColor => GL_SEPARATE_SPECULAR_COLOR,
        } as i64),
        GL_SHADE_MODEL => Answer::Int(c.shade_model as i64),
        GL_COLOR_MATERIAL_FACE => Answer::Int(face_enum(l.color_material.face) as i64),
        GL_COLOR_MATERIAL_PARAMETER => Answer::Int(match l.color_material.mode {
            ColorMaterialMode::Emission => GL_EMISSION,
            ColorMaterialMode::Ambient => GL_AMBIENT,
            ColorMaterialMode::Diffuse => GL_DIFFUSE,
            ColorMaterialMode::Specular => GL_SPECULAR,
            ColorMaterialMode::AmbientAndDiffuse => GL_AMBIENT_AND_DIFFUSE,
        } as i64),
        GL_CURRENT_COLOR => Answer::Color(l.current_color.to_array().to_vec()),
        GL_CURRENT_NORMAL => Answer::Color(l.current_normal.to_array().to_vec()),
        GL_CURRENT_SECONDARY_COLOR => Answer::Color(l.current_secondary_color.to_array().to_vec()),
        GL_ALPHA_TEST_FUNC => Answer::Int(i64::from(0x0200 + l.fragment.alpha_test.func.code())),
        GL_ALPHA_TEST_REF => Answer::Color(vec![l.fragment.alpha_test.reference]),
        GL_FOG_MODE => Answer::Int(i64::from(match l.fragment.fog.mode {
            ffvk::gl::state::FogMode::Linear => GL_LINEAR,
            ffvk::gl::state::FogMode::Exp => GL_EXP,
            _ => GL_EXP2,
        })),
        GL_FOG_DENSITY => Answer::Floats(vec![l.fragment.fog.density]),
        GL_FOG_START => Answer::Floats(vec![l.fragment.fog.start]),
        GL_FOG_END => Answer::Floats(vec![l.fragment.fog.end]),
        GL_FOG_COLOR => Answer::Color(l.fragment.fog.color.to_array().to_vec()),
        GL_FOG_COORD_SRC => Answer::Int(i64::from(match l.fragment.fog.source {
            ffvk::gl::state::FogSource::FogCoord => GL_FOG_COORD,
            _ => GL_FRAGMENT_DEPTH,
        })),
        GL_FOG_HINT => Answer::Int(i64::from(match l.fragment.fog.hint {
            ffvk::gl::state::FogHint::Fastest => GL_FASTEST,
            ffvk::gl::state::FogHint::Nicest => GL_NICEST,
            _ => GL_DONT_CARE,
        })),
        GL_CURRENT_FOG_COORD => Answer::Floats(vec![l.current_fog_coord]),
        GL_FOG_INDEX => Answer::Floats(vec![c.fog_index]),
        GL_POINT_SIZE_MIN => Answer::Floats(vec![l.points.size_min]),
        GL_POINT_SIZE_MAX => Answer::Floats(vec![l.points.size_max]),
        GL_POINT_FADE_THRESHOLD_SIZE => Answer::Floats(vec![l.points.fade_threshold]),
        GL_POINT_DISTANCE_ATTENUATION => Answer::Floats(l.points.distance_attenuation.to_array().to_vec()),
        GL_POINT_SPRITE_COORD_ORIGIN => Answer::Int(match l.points.sprite_origin {
            SpriteOrigin::LowerLeft => GL_LOWER_LEFT,
            _ => GL_UPPER_LEFT,
        } as i64),
        GL_MAX_CLIP_PLANES => Answer::Int(ffvk::gl::state::MAX_CLIP_PLANES as i64),
        GL_CURRENT_TEXTURE_COORDS => Answer::Floats(l.current_texcoords[c.gl.active_unit].to_array().to_vec()),
        GL_MAX_LIGHTS => Answer::Int(MAX_LIGHTS as i64),
        GL_ACTIVE_TEXTURE => Answer::Int(i64::from(GL_TEXTURE0) + c.gl.active_unit as i64),
        GL_MAX_TEXTURE_UNITS | GL_MAX_TEXTURE_COORDS => Answer::Int(MAX_TEXTURE_UNITS as i64),
        GL_MODELVIEW_MATRIX => Answer::Floats(c.gl.modelview.to_cols_array().to_vec()),
        GL_PROJECTION_MATRIX => Answer::Floats(c.projection.to_cols_array().to_vec()),
        GL_TEXTURE_MATRIX => Answer::Floats(l.texture_units[c.gl.active_unit].matrix.to_cols_array().to_vec()),
        _ => {
            return Err(invalid_enum(
                f,
                "pname",
                pname,
                "a state name: GL_LIGHTING, GL_LIGHTi, GL_COLOR_MATERIAL(_FACE, _PARAMETER), GL_NORMALIZE, GL_RESCALE_NORMAL, GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, GL_LIGHT_MODEL_*, GL_SHADE_MODEL, GL_CURRENT_COLOR, GL_CURRENT_NORMAL, GL_CURRENT_TEXTURE_COORDS, GL_CURRENT_SECONDARY_COLOR, GL_COLOR_SUM, GL_ALPHA_TEST(_FUNC, _REF), GL_FOG(_MODE, _DENSITY, _START, _END, _COLOR, _COORD_SRC, _HINT, _INDEX), GL_CURRENT_FOG_COORD, GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE, GL_POINT_DISTANCE_ATTENUATION, GL_POINT_SPRITE(_COORD_ORIGIN), GL_CLIP_PLANEi, GL_TEXTURE_GEN_S, _T, _R, _Q, GL_MAX_CLIP_PLANES, GL_MAX_LIGHTS, GL_ACTIVE_TEXTURE, GL_MAX_TEXTURE_UNITS, GL_MAX_TEXTURE_COORDS, GL_{MODELVIEW,PROJECTION,TEXTURE}_MATRIX or a raster state name (GL_POLYGON_MODE, GL_POLYGON_OFFSET_*, GL_EDGE_FLAG, GL_LINE_STIPPLE*, GL_POLYGON_STIPPLE, GL_STENCIL_*, GL_DEPTH_*, GL_COLOR_WRITEMASK, GL_BLEND*, GL_COLOR_LOGIC_OP, GL_LOGIC_OP_MODE, GL_CULL_FACE(_MODE), GL_FRONT_FACE, GL_POINT_SIZE, GL_LINE_WIDTH)",
            ))
        }
    })
}

/// Writes `values` to `out`, or GL_INVALID_VALUE for a null or misaligned `out`.
///
/// # Safety
///
/// `out` is null, misaligned or has room for `values.len()` values.
unsafe fn write<T: Copy>(f: &str, out: *mut T, values: &[T]) -> GlResult {
    // SAFETY: the caller's contract, passed on.
    unsafe { write_named(f, "params", out, values) }
}

/// [`write`] to an out-parameter named `name`.
///
/// # Safety
///
/// As [`write`].
unsafe fn write_named<T: Copy>(f: &str, name: &str, out: *mut T, values: &[T]) -> GlResult {
    if out.is_null() {
        return Err(crate::gl::GlError::null_out(f, name));
    }
    if crate::result::misaligned(out) {
        return Err(crate::gl::GlError::misaligned(f, name, out.cast_const()));
    }
    // SAFETY: the caller's contract: out has room for as many values as the name has.
    unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), out, values.len()) };
    Ok(())
}

fn light_query(f: &str, c: &FfvkContext, light: u32, pname: u32) -> GlResult<Answer> {
    let index = light_index(f, light)?;
    light_answer(f, &c.gl.lighting.lights[index], pname)
}

/// glGetLightfv: a light's parameter as stored: positions and spot directions in eye
/// space. Errors: `GL_INVALID_ENUM` for a light past `GL_MAX_LIGHTS` or an unknown
/// `pname`; `GL_INVALID_VALUE` for a null `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetLightfv(ctx: *mut FfvkContext, light: u32, pname: u32, params: *mut f32) {
    let f = "ffvkGetLightfv";
    with_context(ctx, f, |c| {
        let answer = light_query(f, c, light, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.floats()) }
    })
}

/// glGetLightiv: `ffvkGetLightfv` as integers (colors by GL's linear mapping, the rest
/// rounded).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetLightiv(ctx: *mut FfvkContext, light: u32, pname: u32, params: *mut i32) {
    let f = "ffvkGetLightiv";
    with_context(ctx, f, |c| {
        let answer = light_query(f, c, light, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.ints()) }
    })
}

/// glGetMaterialfv for `GL_FRONT` or `GL_BACK` (`GL_FRONT_AND_BACK` sets
/// `GL_INVALID_ENUM`, as in GL). Errors: `GL_INVALID_ENUM` for another face or `pname`
/// (`GL_AMBIENT_AND_DIFFUSE` is not a query); `GL_INVALID_VALUE` for a null `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetMaterialfv(ctx: *mut FfvkContext, face: u32, pname: u32, params: *mut f32) {
    let f = "ffvkGetMaterialfv";
    with_context(ctx, f, |c| {
        let answer = material_answer(f, c, face, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.floats()) }
    })
}

/// glGetMaterialiv: `ffvkGetMaterialfv` as integers.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetMaterialiv(ctx: *mut FfvkContext, face: u32, pname: u32, params: *mut i32) {
    let f = "ffvkGetMaterialiv";
    with_context(ctx, f, |c| {
        let answer = material_answer(f, c, face, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.ints()) }
    })
}

/// glGetTexEnvfv on `GL_TEXTURE_ENV`: the active unit's (`ffvkActiveTexture`)
/// `GL_TEXTURE_ENV_MODE`, `GL_TEXTURE_ENV_COLOR` or one of `GL_COMBINE`'s names
/// (`ffvkTexEnvfv`): its enum (a `GL_TEXTUREn` source as `GL_TEXTURE0 + n`), or the scale (1, 2
/// or 4); on `GL_POINT_SPRITE`, the active unit's `GL_COORD_REPLACE`. Errors:
/// `GL_INVALID_ENUM` for another target or `pname`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetTexEnvfv(ctx: *mut FfvkContext, target: u32, pname: u32, params: *mut f32) {
    let f = "ffvkGetTexEnvfv";
    with_context(ctx, f, |c| {
        let answer = tex_env_answer(f, c, target, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.floats()) }
    })
}

/// glGetTexEnviv: `ffvkGetTexEnvfv` as integers.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetTexEnviv(ctx: *mut FfvkContext, target: u32, pname: u32, params: *mut i32) {
    let f = "ffvkGetTexEnviv";
    with_context(ctx, f, |c| {
        let answer = tex_env_answer(f, c, target, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.ints()) }
    })
}

/// glGetTexGenfv: the active unit's coordinate `coord`'s (`GL_S`, `GL_T`, `GL_R`, `GL_Q`) `GL_TEXTURE_GEN_MODE`
/// (one value, the mode's enum), `GL_OBJECT_PLANE` or `GL_EYE_PLANE` (four values, as stored:
/// the eye plane in eye space, as `ffvkTexGenfv` transformed it) (GL 2.1 §2.11.4, §6.1.3).
/// Errors: `GL_INVALID_ENUM` for another `coord` or `pname`; `GL_INVALID_VALUE` for a null
/// `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (4 for a plane). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetTexGenfv(ctx: *mut FfvkContext, coord: u32, pname: u32, params: *mut f32) {
    let f = "ffvkGetTexGenfv";
    with_context(ctx, f, |c| {
        let answer = tex_gen_answer(f, c, coord, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.floats()) }
    })
}

/// glGetTexGeniv: `ffvkGetTexGenfv` as integers, a plane's values rounded to the nearest
/// integer (GL 2.1 §6.1.2).
///
/// # Safety
///
/// As `ffvkGetTexGenfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetTexGeniv(ctx: *mut FfvkContext, coord: u32, pname: u32, params: *mut i32) {
    let f = "ffvkGetTexGeniv";
    with_context(ctx, f, |c| {
        let answer = tex_gen_answer(f, c, coord, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.ints()) }
    })
}

/// glGetTexGendv: `ffvkGetTexGenfv` as doubles.
///
/// # Safety
///
/// As `ffvkGetTexGenfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetTexGendv(ctx: *mut FfvkContext, coord: u32, pname: u32, params: *mut f64) {
    let f = "ffvkGetTexGendv";
    with_context(ctx, f, |c| {
        let answer = tex_gen_answer(f, c, coord, pname)?;
        let values: Vec<f64> = answer.floats().into_iter().map(f64::from).collect();
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &values) }
    })
}

/// glGetFloatv for the names of the state ffvk keeps: `GL_LIGHTING`, `GL_LIGHTi`,
/// `GL_COLOR_MATERIAL`, `GL_COLOR_MATERIAL_FACE`, `GL_COLOR_MATERIAL_PARAMETER`,
/// `GL_NORMALIZE`, `GL_RESCALE_NORMAL`, `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP`,
/// `GL_LIGHT_MODEL_AMBIENT`,
/// `GL_LIGHT_MODEL_LOCAL_VIEWER`, `GL_LIGHT_MODEL_TWO_SIDE`, `GL_LIGHT_MODEL_COLOR_CONTROL`,
/// `GL_SHADE_MODEL`, `GL_CURRENT_COLOR`, `GL_CURRENT_NORMAL`, `GL_CURRENT_TEXTURE_COORDS`,
/// `GL_MAX_LIGHTS` (16) and the modelview, projection and texture matrices; the texture units:
/// `GL_ACTIVE_TEXTURE` (`GL_TEXTURE0` .. `GL_TEXTURE3`, `ffvkActiveTexture`),
/// `GL_MAX_TEXTURE_UNITS` and `GL_MAX_TEXTURE_COORDS` (4), and the active unit's
/// `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP`, `GL_TEXTURE_GEN_*`, `GL_CURRENT_TEXTURE_COORDS` and
/// `GL_TEXTURE_MATRIX`;
/// and the stages
/// around lighting: `GL_COLOR_SUM`, `GL_CURRENT_SECONDARY_COLOR`, `GL_FOG`, `GL_FOG_MODE`,
/// `GL_FOG_DENSITY`, `GL_FOG_START`, `GL_FOG_END`, `GL_FOG_COLOR`, `GL_FOG_INDEX`,
/// `GL_FOG_COORD_SRC`, `GL_FOG_HINT`, `GL_CURRENT_FOG_COORD`, `GL_ALPHA_TEST`,
/// `GL_ALPHA_TEST_FUNC`, `GL_ALPHA_TEST_REF`, `GL_CLIP_PLANEi` (enabled),
/// `GL_MAX_CLIP_PLANES` (6), `GL_TEXTURE_GEN_S`, `_T`, `_R`, `_Q` (enabled); and the points': `GL_POINT_SIZE_MIN`, `GL_POINT_SIZE_MAX`,
/// `GL_POINT_FADE_THRESHOLD_SIZE`, `GL_POINT_DISTANCE_ATTENUATION` (3 values),
/// `GL_POINT_SPRITE` and `GL_POINT_SPRITE_COORD_ORIGIN`; and the raster state's:
/// `GL_POLYGON_MODE` (front, back), `GL_POLYGON_OFFSET_FACTOR`, `GL_POLYGON_OFFSET_UNITS`,
/// `GL_POLYGON_OFFSET_FILL`, `_LINE`, `_POINT`, `GL_EDGE_FLAG`, `GL_LINE_STIPPLE`, `GL_POLYGON_STIPPLE`,
/// `GL_LINE_STIPPLE_PATTERN`, `GL_LINE_STIPPLE_REPEAT`, `GL_DEPTH_RANGE`, `GL_DEPTH_TEST`,
/// `GL_DEPTH_WRITEMASK`, `GL_DEPTH_FUNC`, `GL_STENCIL_TEST`, `GL_STENCIL_FUNC`, `GL_STENCIL_REF`
/// (clamped to [0, 255]), `GL_STENCIL_VALUE_MASK`, `GL_STENCIL_FAIL`,
/// `GL_STENCIL_PASS_DEPTH_FAIL`, `GL_STENCIL_PASS_DEPTH_PASS`, `GL_STENCIL_WRITEMASK`, their
/// `GL_STENCIL_BACK_*` forms, `GL_STENCIL_CLEAR_VALUE`, `GL_COLOR_WRITEMASK` (4 values),
/// `GL_BLEND`, `GL_BLEND_SRC_RGB` (`GL_BLEND_SRC`), `GL_BLEND_DST_RGB` (`GL_BLEND_DST`),
/// `GL_BLEND_SRC_ALPHA`, `GL_BLEND_DST_ALPHA`, `GL_BLEND_EQUATION_RGB`,
/// `GL_BLEND_EQUATION_ALPHA`, `GL_BLEND_COLOR`, `GL_COLOR_LOGIC_OP`, `GL_LOGIC_OP_MODE`,
/// `GL_CULL_FACE`, `GL_CULL_FACE_MODE`, `GL_FRONT_FACE`, `GL_POINT_SIZE` and `GL_LINE_WIDTH`.
/// Errors: `GL_INVALID_ENUM` for any other name (a layer answers the rest of GL's state
/// itself); `GL_INVALID_VALUE` for a null `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetFloatv(ctx: *mut FfvkContext, pname: u32, params: *mut f32) {
    let f = "ffvkGetFloatv";
    with_context(ctx, f, |c| {
        let answer = get_answer(f, c, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.floats()) }
    })
}

/// glGetIntegerv: `ffvkGetFloatv`'s names as integers.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetIntegerv(ctx: *mut FfvkContext, pname: u32, params: *mut i32) {
    let f = "ffvkGetIntegerv";
    with_context(ctx, f, |c| {
        let answer = get_answer(f, c, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.ints()) }
    })
}

/// glGetBooleanv: `ffvkGetFloatv`'s names as `GL_TRUE` (non-zero) or `GL_FALSE`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or has room
/// for as many values as the name has (16 for a matrix). Nothing is written when an error is
/// set.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetBooleanv(ctx: *mut FfvkContext, pname: u32, params: *mut u8) {
    let f = "ffvkGetBooleanv";
    with_context(ctx, f, |c| {
        let answer = get_answer(f, c, pname)?;
        // SAFETY: the caller's contract on params.
        unsafe { write(f, params, &answer.bools()) }
    })
}

/// glGetPolygonStipple: the polygon stipple's 128 bytes as `ffvkPolygonStipple` takes them
/// (GL's default pixel storage); all ones until set. Errors: `GL_INVALID_VALUE` for a null
/// `mask`. Nothing is written when an error is set.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `mask` is null or has room
/// for 128 bytes.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetPolygonStipple(ctx: *mut FfvkContext, mask: *mut u8) {
    let f = "ffvkGetPolygonStipple";
    with_context(ctx, f, |c| {
        let pattern = c.gl.raster.polygon_stipple_mask;
        // SAFETY: the caller's contract on mask.
        unsafe { write_named(f, "mask", mask, &pattern) }
    })
}

/// glGetClipPlane: the plane's equation as stored, in eye space (four doubles). Errors:
/// `GL_INVALID_ENUM` for another `plane`; `GL_INVALID_VALUE` for a null `equation`. Nothing is
/// written when an error is set.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `equation` is null or has room
/// for four doubles.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetClipPlane(ctx: *mut FfvkContext, plane: u32, equation: *mut f64) {
    let f = "ffvkGetClipPlane";
    with_context(ctx, f, |c| {
        let i = crate::gl::clip_plane_index(f, plane)?;
        let p = c.gl.lighting.clip.planes[i].as_dvec4().to_array();
        // SAFETY: the caller's contract on equation.
        unsafe { write_named(f, "equation", equation, &p) }
    })
}
