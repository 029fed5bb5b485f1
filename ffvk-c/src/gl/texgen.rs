//! glTexGen: GL 2.1's texture coordinate generation (section 2.11.4) on a context. A
//! coordinate is generated while its `GL_TEXTURE_GEN_S` (`_T`, `_R`, `_Q`) is enabled
//! (`ffvkEnable`); glGetTexGen is in `query.rs`.

use ffvk::gl::texture::TexGenMode;

use super::{invalid_enum, read, state_error, with_context, FfvkContext, GlResult, Values};
use crate::enums::*;

pub(crate) const TEXGEN_PNAMES: &str = "GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE or GL_EYE_PLANE";

/// The coordinate `coord` names: 0 for `GL_S`, 1 `GL_T`, 2 `GL_R`, 3 `GL_Q`; GL_INVALID_ENUM
/// for another value.
pub(crate) fn texgen_coord(function: &str, coord: u32) -> GlResult<usize> {
    match coord {
        GL_S => Ok(0),
        GL_T => Ok(1),
        GL_R => Ok(2),
        GL_Q => Ok(3),
        _ => Err(invalid_enum(function, "coord", coord, "GL_S, GL_T, GL_R or GL_Q")),
    }
}

/// How many values `pname` takes; `scalar` for glTexGen{i,f,d}, whose one value is a mode
/// (§2.11.4: "In the first form of the command, param is a symbolic constant specifying a
/// single-valued texture generation parameter"): the planes are the vector forms' alone.
fn texgen_len(function: &str, pname: u32, scalar: bool) -> GlResult<usize> {
    match pname {
        GL_TEXTURE_GEN_MODE => Ok(1),
        GL_OBJECT_PLANE | GL_EYE_PLANE if !scalar => Ok(4),
        GL_OBJECT_PLANE | GL_EYE_PLANE => Err(invalid_enum(
            function,
            "pname",
            pname,
            "GL_TEXTURE_GEN_MODE (the single-valued parameter: a plane's four values take the vector forms)",
        )),
        _ => Err(invalid_enum(function, "pname", pname, TEXGEN_PNAMES)),
    }
}

/// The modes coordinate `coord` takes, in words: `GL_SPHERE_MAP` for S and T only,
/// `GL_REFLECTION_MAP` and `GL_NORMAL_MAP` for S, T and R (§2.11.4).
fn modes_for(coord: usize) -> &'static str {
    match coord {
        0 | 1 => "GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_REFLECTION_MAP or GL_NORMAL_MAP",
        2 => "GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_REFLECTION_MAP or GL_NORMAL_MAP (GL_SPHERE_MAP is for S and T only)",
        _ => "GL_OBJECT_LINEAR or GL_EYE_LINEAR (GL_SPHERE_MAP is for S and T only, GL_REFLECTION_MAP and GL_NORMAL_MAP for S, T and R)",
    }
}

/// The mode `GL_TEXTURE_GEN_MODE`'s value names for coordinate `coord`; GL_INVALID_ENUM for a
/// value that is no mode, or a mode the coordinate does not take.
fn texgen_mode(function: &str, coord: usize, value: u32) -> GlResult<TexGenMode> {
    let mode = match value {
        GL_OBJECT_LINEAR => Some(TexGenMode::ObjectLinear),
        GL_EYE_LINEAR => Some(TexGenMode::EyeLinear),
        GL_SPHERE_MAP => Some(TexGenMode::SphereMap),
        GL_REFLECTION_MAP => Some(TexGenMode::ReflectionMap),
        GL_NORMAL_MAP => Some(TexGenMode::NormalMap),
        _ => None,
    };
    mode.filter(|m| m.allowed_for(coord)).ok_or_else(|| {
        let what = ["GL_S", "GL_T", "GL_R", "GL_Q"][coord];
        invalid_enum(
            function,
            &format!("{what}'s GL_TEXTURE_GEN_MODE value"),
            value,
            modes_for(coord),
        )
    })
}

fn set_texgen(c: &mut FfvkContext, function: &str, coord: usize, pname: u32, v: Values) -> GlResult {
    let set = match pname {
        GL_TEXTURE_GEN_MODE => {
            let value = v.as_enum(function, "GL_TEXTURE_GEN_MODE", modes_for(coord))?;
            let mode = texgen_mode(function, coord, value)?;
            c.gl.tex_gen_mode(coord, mode)
        }
        GL_OBJECT_PLANE => c.gl.tex_gen_object_plane(coord, v.dvec4()),
        GL_EYE_PLANE => c.gl.tex_gen_eye_plane(coord, v.dvec4()),
        _ => return Err(invalid_enum(function, "pname", pname, TEXGEN_PNAMES)),
    };
    set.map_err(|e| state_error(function, e))
}

/// One glTexGen call: the coordinate and name checked in GL's order, then the values read.
fn texgen_entry<'a>(
    ctx: *mut FfvkContext,
    f: &str,
    (coord, pname, scalar): (u32, u32, bool),
    values: impl FnOnce(usize) -> GlResult<Values<'a>>,
) {
    with_context(ctx, f, |c| {
        let index = texgen_coord(f, coord)?;
        let len = texgen_len(f, pname, scalar)?;
        set_texgen(c, f, index, pname, values(len)?)
    })
}

/// glTexGeni: `GL_TEXTURE_GEN_MODE` of the active unit's (`ffvkActiveTexture`) coordinate
/// `coord` (`GL_S`, `GL_T`, `GL_R`, `GL_Q`):
/// `GL_OBJECT_LINEAR`, `GL_EYE_LINEAR` (the initial mode), `GL_SPHERE_MAP` (S and T only),
/// `GL_REFLECTION_MAP` or `GL_NORMAL_MAP` (S, T and R), used while the coordinate's
/// `GL_TEXTURE_GEN_S` (`_T`, `_R`, `_Q`) is enabled (GL 2.1 §2.11.4). Errors:
/// `GL_INVALID_ENUM` for another `coord`, another `pname` (`GL_OBJECT_PLANE` and
/// `GL_EYE_PLANE` included: their four values take the vector forms), a value that is no mode,
/// or a mode the coordinate does not take.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexGeni(ctx: *mut FfvkContext, coord: u32, pname: u32, param: i32) {
    let value = [param];
    texgen_entry(ctx, "ffvkTexGeni", (coord, pname, true), |_| {
        Ok(Values::I(&value))
    });
}

/// glTexGenf: `ffvkTexGeni` with the mode's value as a float (truncated to an integer, as GL
/// reads an enum given as a float; one that is not finite sets `GL_INVALID_VALUE`, ffvk's rule
/// for every non-finite value).
///
/// # Safety
///
/// As `ffvkTexGeni`.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexGenf(ctx: *mut FfvkContext, coord: u32, pname: u32, param: f32) {
    let value = [param];
    texgen_entry(ctx, "ffvkTexGenf", (coord, pname, true), |_| {
        Ok(Values::F(&value))
    });
}

/// glTexGend: `ffvkTexGenf` with a double.
///
/// # Safety
///
/// As `ffvkTexGeni`.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexGend(ctx: *mut FfvkContext, coord: u32, pname: u32, param: f64) {
    let value = [param];
    texgen_entry(ctx, "ffvkTexGend", (coord, pname, true), |_| {
        Ok(Values::D(&value))
    });
}

/// glTexGenfv: `ffvkTexGenf`'s `GL_TEXTURE_GEN_MODE`, and the coordinate's planes (p1, p2, p3,
/// p4): `GL_OBJECT_PLANE`, kept as given, and `GL_EYE_PLANE`, stored in eye space as
/// (p1 p2 p3 p4) M⁻¹ with M the context's modelview at this call (`ffvkLoadModelview`), as GL
/// does; later modelview changes do not move it. Errors: as `ffvkTexGeni`, and
/// `GL_INVALID_VALUE` for a null `params`, a plane value that is not finite, or (for the eye
/// plane) a singular modelview (ffvk's choices: GL leaves those undefined).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or points
/// at as many values as `pname` has (4 for a plane, 1 for the mode).
#[no_mangle]
pub unsafe extern "C" fn ffvkTexGenfv(ctx: *mut FfvkContext, coord: u32, pname: u32, params: *const f32) {
    let f = "ffvkTexGenfv";
    texgen_entry(ctx, f, (coord, pname, false), |n| {
        // SAFETY: the caller's contract on params.
        unsafe { read(f, params, n) }.map(Values::F)
    })
}

/// glTexGeniv: `ffvkTexGenfv` with integers, a plane's converted directly to floats.
///
/// # Safety
///
/// As `ffvkTexGenfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexGeniv(ctx: *mut FfvkContext, coord: u32, pname: u32, params: *const i32) {
    let f = "ffvkTexGeniv";
    texgen_entry(ctx, f, (coord, pname, false), |n| {
        // SAFETY: the caller's contract on params.
        unsafe { read(f, params, n) }.map(Values::I)
    })
}

/// glTexGendv: `ffvkTexGenfv` with doubles (a plane is stored as floats, the eye plane
/// transformed in double precision first).
///
/// # Safety
///
/// As `ffvkTexGenfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexGendv(ctx: *mut FfvkContext, coord: u32, pname: u32, params: *const f64) {
    let f = "ffvkTexGendv";
    texgen_entry(ctx, f, (coord, pname, false), |n| {
        // SAFETY: the caller's contract on params.
        unsafe { read(f, params, n) }.map(Values::D)
    })
}
