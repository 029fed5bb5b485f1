//! The context's `extern "C"` entry points: GL's lighting functions with the context first.

use std::panic::catch_unwind;

use ffvk::gl::state::ShadeModel;
use ffvk::glam::{Vec3, Vec4};

use super::params::*;
use super::{invalid_enum, read, state_error, with_context, FfvkContext, GlResult, Values};
use crate::enums::*;
use crate::result::{fail, FfvkResult};

// ---------------------------------------------------------------------------------------
// The entry points.

/// Creates a context in GL's initial state (table 2.10 and friends): lighting off, every
/// light at its default, identity matrices, `GL_SMOOTH`, no error. Returns null only when
/// memory runs out (see `ffvkResultMessage`). Free it with `ffvkDestroyContext`.
#[no_mangle]
pub extern "C" fn ffvkCreateContext() -> *mut FfvkContext {
    catch_unwind(|| Box::into_raw(Box::new(FfvkContext::new()))).unwrap_or_else(|_| {
        fail(
            FfvkResult::FFVK_ERROR_OUT_OF_MEMORY,
            "ffvkCreateContext: out of memory",
        );
        std::ptr::null_mut()
    })
}

/// Frees a context from `ffvkCreateContext`; null is ignored. A renderer that recorded draws
/// from it no longer needs it once `ffvkEndDraws` returned.
///
/// # Safety
///
/// `ctx` is null or a context from `ffvkCreateContext` not yet destroyed, and no other
/// thread uses it.
#[no_mangle]
pub unsafe extern "C" fn ffvkDestroyContext(ctx: *mut FfvkContext) {
    // SAFETY: the caller's contract: made by this API, destroyed once.
    unsafe { crate::result::free(ctx) }
}

/// glGetError: the first error recorded since the last call (GL's first error sticks; later
/// ones are dropped), then `GL_NO_ERROR` until the next. A null context gives `GL_NO_ERROR`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkGetError(ctx: *mut FfvkContext) -> u32 {
    with_context(ctx, "ffvkGetError", |c| Ok(c.take_error()))
}

/// glEnable for `GL_LIGHTING`, `GL_LIGHTi` (i < 16), `GL_COLOR_MATERIAL`, `GL_NORMALIZE`,
/// `GL_RESCALE_NORMAL`, `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP`, `GL_COLOR_SUM`, `GL_FOG`,
/// `GL_ALPHA_TEST`, `GL_CLIP_PLANEi` (i < 6), `GL_POINT_SPRITE`, `GL_TEXTURE_GEN_S`, `_T`, `_R`,
/// `_Q` (the coordinate generated as `ffvkTexGeni` says, GL 2.1 §2.11.4; `GL_TEXTURE_2D`,
/// `GL_TEXTURE_CUBE_MAP` and `GL_TEXTURE_GEN_*` are the active unit's, `ffvkActiveTexture`;
/// with `GL_TEXTURE_CUBE_MAP` on, the unit samples the draw's cube map for it, `FfvkDrawInfo::
/// cube_map`, and not its 2D texture, GL 2.1 §3.8.15), and the raster state's
/// `GL_POLYGON_OFFSET_FILL`, `GL_POLYGON_OFFSET_LINE`, `GL_POLYGON_OFFSET_POINT`,
/// `GL_LINE_STIPPLE`, `GL_POLYGON_STIPPLE`, `GL_STENCIL_TEST`,
/// `GL_COLOR_LOGIC_OP`, `GL_BLEND`, `GL_DEPTH_TEST` and `GL_CULL_FACE` (which a draw takes with
/// `FFVK_RASTER_SOURCE_CONTEXT`). Sets `GL_INVALID_ENUM` for any other cap (a layer keeps the
/// rest of GL's capabilities itself). Enabling `GL_COLOR_MATERIAL` writes the
/// current color into the tracked material parameters, as GL does.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkEnable(ctx: *mut FfvkContext, cap_enum: u32) {
    with_context(ctx, "ffvkEnable", |c| {
        let cap = cap("ffvkEnable", cap_enum)?;
        c.gl.enable(cap).map_err(|e| state_error("ffvkEnable", e))
    })
}

/// glDisable for the caps of `ffvkEnable`; `GL_INVALID_ENUM` for any other.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkDisable(ctx: *mut FfvkContext, cap_enum: u32) {
    with_context(ctx, "ffvkDisable", |c| {
        let cap = cap("ffvkDisable", cap_enum)?;
        c.gl.disable(cap).map_err(|e| state_error("ffvkDisable", e))
    })
}

/// glIsEnabled for the caps of `ffvkEnable`: `GL_TRUE` or `GL_FALSE`; `GL_INVALID_ENUM`
/// (and `GL_FALSE`) for any other.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkIsEnabled(ctx: *mut FfvkContext, cap_enum: u32) -> u8 {
    with_context(ctx, "ffvkIsEnabled", |c| {
        let cap = cap("ffvkIsEnabled", cap_enum)?;
        Ok(crate::query::is_enabled(c, cap) as u8)
    })
}

/// One glLight call: the light and name checked in GL's order, then the values read.
fn light_entry<'a>(
    ctx: *mut FfvkContext,
    f: &str,
    (light, pname, scalar): (u32, u32, bool),
    values: impl FnOnce(usize) -> GlResult<Values<'a>>,
) {
    with_context(ctx, f, |c| {
        let (index, len) = light_call(f, light, pname, scalar)?;
        set_light(c, f, index, pname, values(len)?)
    })
}

/// glLightfv: one parameter of `GL_LIGHTi`. `GL_POSITION` is transformed by the context's
/// modelview (`ffvkLoadModelview`) and `GL_SPOT_DIRECTION` by its upper 3x3 at this call,
/// and stored in eye space, as GL does. Errors: `GL_INVALID_ENUM` for a light past
/// `GL_MAX_LIGHTS` (16) or an unknown `pname`; `GL_INVALID_VALUE` for a spot exponent
/// outside [0, 128], a cutoff outside [0, 90] and not 180, a negative attenuation, a value
/// that is not finite (ffvk's choice where GL leaves it unspecified) or a null `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or points
/// at as many values as `pname` has (4, 3 for `GL_SPOT_DIRECTION`, 1).
#[no_mangle]
pub unsafe extern "C" fn ffvkLightfv(ctx: *mut FfvkContext, light: u32, pname: u32, params: *const f32) {
    let f = "ffvkLightfv";
    light_entry(ctx, f, (light, pname, false), |n| {
        // SAFETY: the caller\'s contract on params.
        unsafe { read(f, params, n) }.map(Values::F)
    })
}

/// glLightiv: `ffvkLightfv` with integers; colors map [-2^31, 2^31 - 1] onto [-1, 1]
/// (GL 2.1 table 2.9), other values convert directly.
///
/// # Safety
///
/// As `ffvkLightfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkLightiv(ctx: *mut FfvkContext, light: u32, pname: u32, params: *const i32) {
    let f = "ffvkLightiv";
    light_entry(ctx, f, (light, pname, false), |n| {
        // SAFETY: the caller\'s contract on params.
        unsafe { read(f, params, n) }.map(Values::I)
    })
}

/// glLightf: the single-valued parameters only (`GL_SPOT_EXPONENT`, `GL_SPOT_CUTOFF`,
/// `GL_*_ATTENUATION`); any other `pname` sets `GL_INVALID_ENUM`. Errors as `ffvkLightfv`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkLightf(ctx: *mut FfvkContext, light: u32, pname: u32, param: f32) {
    let values = [param];
    light_entry(ctx, "ffvkLightf", (light, pname, true), |_| {
        Ok(Values::F(&values))
    })
}

/// glLighti: `ffvkLightf` with an integer.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkLighti(ctx: *mut FfvkContext, light: u32, pname: u32, param: i32) {
    let values = [param];
    light_entry(ctx, "ffvkLighti", (light, pname, true), |_| {
        Ok(Values::I(&values))
    })
}

/// One glMaterial call: the face and name checked in GL's order, then the values read.
fn material_entry<'a>(
    ctx: *mut FfvkContext,
    f: &str,
    (face_enum, pname, scalar): (u32, u32, bool),
    values: impl FnOnce(usize) -> GlResult<Values<'a>>,
) {
    with_context(ctx, f, |c| {
        let (face, len) = material_call(f, face_enum, pname, scalar)?;
        set_material(c, f, face, pname, values(len)?)
    })
}

/// glMaterialfv on `GL_FRONT`, `GL_BACK` or `GL_FRONT_AND_BACK`. While `GL_COLOR_MATERIAL`
/// is enabled the parameters it makes track the current color keep tracking it (GL 2.1
/// section 2.14.3): the call leaves them at the current color and sets the rest.
/// `GL_COLOR_INDEXES` is stored for queries only (color-index lighting is not drawn).
/// Errors: `GL_INVALID_ENUM` for another face or `pname`; `GL_INVALID_VALUE` for a shininess
/// outside [0, 128], a value that is not finite or a null `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or points
/// at as many values as `pname` has (4, 3 for `GL_COLOR_INDEXES`, 1 for `GL_SHININESS`).
#[no_mangle]
pub unsafe extern "C" fn ffvkMaterialfv(ctx: *mut FfvkContext, face: u32, pname: u32, params: *const f32) {
    let f = "ffvkMaterialfv";
    material_entry(ctx, f, (face, pname, false), |n| {
        // SAFETY: the caller\'s contract on params.
        unsafe { read(f, params, n) }.map(Values::F)
    })
}

/// glMaterialiv: `ffvkMaterialfv` with integers (colors as GL 2.1 table 2.9 maps them).
///
/// # Safety
///
/// As `ffvkMaterialfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkMaterialiv(ctx: *mut FfvkContext, face: u32, pname: u32, params: *const i32) {
    let f = "ffvkMaterialiv";
    material_entry(ctx, f, (face, pname, false), |n| {
        // SAFETY: the caller\'s contract on params.
        unsafe { read(f, params, n) }.map(Values::I)
    })
}

/// glMaterialf: `GL_SHININESS` only; any other `pname` sets `GL_INVALID_ENUM`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkMaterialf(ctx: *mut FfvkContext, face: u32, pname: u32, param: f32) {
    let values = [param];
    material_entry(ctx, "ffvkMaterialf", (face, pname, true), |_| {
        Ok(Values::F(&values))
    })
}

/// glMateriali: `ffvkMaterialf` with an integer.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkMateriali(ctx: *mut FfvkContext, face: u32, pname: u32, param: i32) {
    let values = [param];
    material_entry(ctx, "ffvkMateriali", (face, pname, true), |_| {
        Ok(Values::I(&values))
    })
}

/// One glLightModel call.
fn light_model_entry<'a>(
    ctx: *mut FfvkContext,
    f: &str,
    (pname, scalar): (u32, bool),
    values: impl FnOnce(usize) -> GlResult<Values<'a>>,
) {
    with_context(ctx, f, |c| {
        let len = light_model_len(f, pname, scalar)?;
        set_light_model(c, f, pname, values(len)?)
    })
}

/// glLightModelfv: `GL_LIGHT_MODEL_AMBIENT` (4 values), `GL_LIGHT_MODEL_LOCAL_VIEWER` and
/// `GL_LIGHT_MODEL_TWO_SIDE` (non-zero is true), `GL_LIGHT_MODEL_COLOR_CONTROL`
/// (`GL_SINGLE_COLOR` or `GL_SEPARATE_SPECULAR_COLOR`). Errors: `GL_INVALID_ENUM` for another
/// `pname` or color control; `GL_INVALID_VALUE` for a value that is not finite or a null
/// `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or points
/// at as many values as `pname` has.
#[no_mangle]
pub unsafe extern "C" fn ffvkLightModelfv(ctx: *mut FfvkContext, pname: u32, params: *const f32) {
    let f = "ffvkLightModelfv";
    light_model_entry(ctx, f, (pname, false), |n| {
        // SAFETY: the caller\'s contract on params.
        unsafe { read(f, params, n) }.map(Values::F)
    })
}

/// glLightModeliv: `ffvkLightModelfv` with integers.
///
/// # Safety
///
/// As `ffvkLightModelfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkLightModeliv(ctx: *mut FfvkContext, pname: u32, params: *const i32) {
    let f = "ffvkLightModeliv";
    light_model_entry(ctx, f, (pname, false), |n| {
        // SAFETY: the caller\'s contract on params.
        unsafe { read(f, params, n) }.map(Values::I)
    })
}

/// glLightModelf: the single-valued parameters (not `GL_LIGHT_MODEL_AMBIENT`, which sets
/// `GL_INVALID_ENUM` here).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkLightModelf(ctx: *mut FfvkContext, pname: u32, param: f32) {
    let values = [param];
    light_model_entry(ctx, "ffvkLightModelf", (pname, true), |_| Ok(Values::F(&values)))
}

/// glLightModeli: `ffvkLightModelf` with an integer.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkLightModeli(ctx: *mut FfvkContext, pname: u32, param: i32) {
    let values = [param];
    light_model_entry(ctx, "ffvkLightModeli", (pname, true), |_| Ok(Values::I(&values)))
}

/// One glTexEnv call.
fn tex_env_entry<'a>(
    ctx: *mut FfvkContext,
    f: &str,
    (target, pname, scalar): (u32, u32, bool),
    values: impl FnOnce(usize) -> GlResult<Values<'a>>,
) {
    with_context(ctx, f, |c| {
        let len = tex_env_len(f, target, pname, scalar)?;
        set_tex_env(c, f, pname, values(len)?)
    })
}

/// glTexEnvfv on `GL_TEXTURE_ENV`, for the active unit (`ffvkActiveTexture`):
/// `GL_TEXTURE_ENV_MODE` (`GL_MODULATE`, `GL_REPLACE`, `GL_DECAL`, `GL_BLEND`, `GL_ADD`,
/// `GL_COMBINE`), `GL_TEXTURE_ENV_COLOR` (4 values, clamped to [0, 1]), or one of
/// `GL_COMBINE`'s (GL 2.1 §3.8.13, table 3.24): `GL_COMBINE_RGB` and `GL_COMBINE_ALPHA`
/// (`GL_REPLACE`, `GL_MODULATE`, `GL_ADD`, `GL_ADD_SIGNED`, `GL_INTERPOLATE`, `GL_SUBTRACT`,
/// and for RGB `GL_DOT3_RGB`, `GL_DOT3_RGBA`), `GL_SRC0_RGB` .. `GL_SRC2_RGB` and
/// `GL_SRC0_ALPHA` .. `GL_SRC2_ALPHA` (`GL_TEXTURE`, `GL_CONSTANT`, `GL_PRIMARY_COLOR`,
/// `GL_PREVIOUS`, and `GL_TEXTURE0` .. `GL_TEXTURE3`: unit n's texel, sampled with unit n's
/// texture and coordinates, ARB_texture_env_crossbar; a unit that is not enabled with a
/// texture passes the previous color on), `GL_OPERAND0_RGB` .. `GL_OPERAND2_RGB`
/// (`GL_SRC_COLOR`, `GL_ONE_MINUS_SRC_COLOR`, `GL_SRC_ALPHA`, `GL_ONE_MINUS_SRC_ALPHA`),
/// `GL_OPERAND0_ALPHA` .. `GL_OPERAND2_ALPHA` (`GL_SRC_ALPHA`, `GL_ONE_MINUS_SRC_ALPHA`),
/// `GL_RGB_SCALE` and `GL_ALPHA_SCALE` (1, 2 or 4); on `GL_POINT_SPRITE`: `GL_COORD_REPLACE`
/// (zero is `GL_FALSE`, anything else `GL_TRUE`). Errors: `GL_INVALID_ENUM` for another
/// target, `pname` or value (a dot product for `GL_COMBINE_ALPHA`, a color operand for an alpha
/// argument, a `GL_TEXTUREn` source past the four units: `GL_TEXTURE4` and on, as Mesa refuses
/// one past its own); `GL_INVALID_VALUE` for a scale other than 1, 2 or 4, a value that is not
/// finite or a null `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or points
/// at as many values as `pname` has.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexEnvfv(ctx: *mut FfvkContext, target: u32, pname: u32, params: *const f32) {
    let f = "ffvkTexEnvfv";
    tex_env_entry(ctx, f, (target, pname, false), |n| {
        // SAFETY: the caller\'s contract on params.
        unsafe { read(f, params, n) }.map(Values::F)
    })
}

/// glTexEnviv: `ffvkTexEnvfv` with integers.
///
/// # Safety
///
/// As `ffvkTexEnvfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexEnviv(ctx: *mut FfvkContext, target: u32, pname: u32, params: *const i32) {
    let f = "ffvkTexEnviv";
    tex_env_entry(ctx, f, (target, pname, false), |n| {
        // SAFETY: the caller\'s contract on params.
        unsafe { read(f, params, n) }.map(Values::I)
    })
}

/// glTexEnvf: a single-valued name, `GL_TEXTURE_ENV_MODE` or one of `GL_COMBINE`'s, as
/// `ffvkTexEnvfv` takes it (an enum given as a float is truncated); `GL_TEXTURE_ENV_COLOR`
/// sets `GL_INVALID_ENUM`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexEnvf(ctx: *mut FfvkContext, target: u32, pname: u32, param: f32) {
    let values = [param];
    tex_env_entry(ctx, "ffvkTexEnvf", (target, pname, true), |_| {
        Ok(Values::F(&values))
    })
}

/// glTexEnvi: `ffvkTexEnvf` with an integer.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexEnvi(ctx: *mut FfvkContext, target: u32, pname: u32, param: i32) {
    let values = [param];
    tex_env_entry(ctx, "ffvkTexEnvi", (target, pname, true), |_| {
        Ok(Values::I(&values))
    })
}

/// glColorMaterial: which face(s) and parameter(s) track the current color while
/// `GL_COLOR_MATERIAL` is enabled (and, enabled, writes the current color into them now).
/// Errors: `GL_INVALID_ENUM` for another face or mode.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkColorMaterial(ctx: *mut FfvkContext, face_enum: u32, mode: u32) {
    let f = "ffvkColorMaterial";
    with_context(ctx, f, |c| {
        let face = face(f, face_enum)?;
        let mode = color_material_mode(f, mode)?;
        c.gl.color_material(face, mode);
        Ok(())
    })
}

/// glNormal3f: the current normal, every vertex's normal in a draw whose layout has no normal
/// array. Not normalized (GL normalizes only under `GL_NORMALIZE`); `GL_INVALID_VALUE` for a
/// component that is not finite (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkNormal3f(ctx: *mut FfvkContext, x: f32, y: f32, z: f32) {
    const F: &str = "ffvkNormal3f";
    with_context(ctx, F, |c| {
        c.gl.normal(Vec3::new(x, y, z)).map_err(|e| state_error(F, e))
    })
}

/// glNormal3b: `ffvkNormal3f` with each byte c converted as GL 2.1 converts signed bytes,
/// (2c + 1)/255.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkNormal3b(ctx: *mut FfvkContext, x: i8, y: i8, z: i8) {
    const F: &str = "ffvkNormal3b";
    let convert = |c: i8| (2.0 * f32::from(c) + 1.0) / 255.0;
    with_context(ctx, F, |c| {
        c.gl.normal(Vec3::new(convert(x), convert(y), convert(z)))
            .map_err(|e| state_error(F, e))
    })
}

/// glTexCoord4f: unit 0's current texture coordinates (`ffvkMultiTexCoord4f(GL_TEXTURE0, …)`,
/// whatever the active unit), every vertex's in a textured draw whose layout has no texture
/// coordinate array; `GL_INVALID_VALUE` for a component that is not finite (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexCoord4f(ctx: *mut FfvkContext, s: f32, t: f32, r: f32, q: f32) {
    const F: &str = "ffvkTexCoord4f";
    with_context(ctx, F, |c| {
        c.gl.tex_coord(Vec4::new(s, t, r, q))
            .map_err(|e| state_error(F, e))
    })
}

/// glTexCoord2f: `ffvkTexCoord4f` with r = 0 and q = 1.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkTexCoord2f(ctx: *mut FfvkContext, s: f32, t: f32) {
    const F: &str = "ffvkTexCoord2f";
    with_context(ctx, F, |c| {
        c.gl.tex_coord(Vec4::new(s, t, 0.0, 1.0))
            .map_err(|e| state_error(F, e))
    })
}

/// glAlphaFunc: the alpha test's function (`GL_NEVER` .. `GL_ALWAYS`; another value sets
/// `GL_INVALID_ENUM`) and reference, clamped to [0, 1] as GL clamps it (a NaN reference sets
/// `GL_INVALID_VALUE`: ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkAlphaFunc(ctx: *mut FfvkContext, func: u32, reference: f32) {
    const F: &str = "ffvkAlphaFunc";
    with_context(ctx, F, |c| {
        let Some(&compare) = func
            .checked_sub(GL_NEVER)
            .and_then(|i| ffvk::gl::state::CompareFunc::ALL.get(i as usize))
        else {
            return Err(invalid_enum(
                F,
                "func",
                func,
                "GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL or GL_ALWAYS",
            ));
        };
        c.gl.alpha_func(compare, reference).map_err(|e| state_error(F, e))
    })
}

/// glSecondaryColor3f: the current secondary color (r, g, b, 1), every vertex's in a draw
/// whose layout has no secondary color array, summed with lighting off under `GL_COLOR_SUM`;
/// `GL_INVALID_VALUE` for a component that is not finite (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkSecondaryColor3f(ctx: *mut FfvkContext, r: f32, g: f32, b: f32) {
    const F: &str = "ffvkSecondaryColor3f";
    with_context(ctx, F, |c| {
        c.gl.secondary_color(Vec3::new(r, g, b))
            .map_err(|e| state_error(F, e))
    })
}

fn color(ctx: *mut FfvkContext, f: &str, rgba: Vec4) {
    with_context(ctx, f, |c| c.gl.color(rgba).map_err(|e| state_error(f, e)))
}

/// glColor4f: the current color, the color of every vertex of a draw without a color array,
/// and (with `GL_COLOR_MATERIAL`) of the tracked material parameters. Unclamped, as in GL;
/// `GL_INVALID_VALUE` for a component that is not finite (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkColor4f(ctx: *mut FfvkContext, r: f32, g: f32, b: f32, a: f32) {
    color(ctx, "ffvkColor4f", Vec4::new(r, g, b, a))
}

/// glColor3f: `ffvkColor4f` with alpha 1.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkColor3f(ctx: *mut FfvkContext, r: f32, g: f32, b: f32) {
    color(ctx, "ffvkColor3f", Vec4::new(r, g, b, 1.0))
}

/// glColor4ub: each component c becomes c / 255.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkColor4ub(ctx: *mut FfvkContext, r: u8, g: u8, b: u8, a: u8) {
    let c = |v: u8| v as f32 / 255.0;
    color(ctx, "ffvkColor4ub", Vec4::new(c(r), c(g), c(b), c(a)))
}

/// glColor3ub: `ffvkColor4ub` with alpha 255.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkColor3ub(ctx: *mut FfvkContext, r: u8, g: u8, b: u8) {
    let c = |v: u8| v as f32 / 255.0;
    color(ctx, "ffvkColor3ub", Vec4::new(c(r), c(g), c(b), 1.0))
}

/// glShadeModel: `GL_FLAT` draws in ffvk's flat mode (each primitive its provoking vertex's
/// color), `GL_SMOOTH` per vertex, or per fragment after `ffvkPerFragmentLighting`. Errors:
/// `GL_INVALID_ENUM` for another mode.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkShadeModel(ctx: *mut FfvkContext, mode: u32) {
    let f = "ffvkShadeModel";
    with_context(ctx, f, |c| {
        let model = match mode {
            GL_FLAT => ShadeModel::Flat,
            GL_SMOOTH => ShadeModel::Smooth,
            other => return Err(invalid_enum(f, "mode", other, "GL_FLAT or GL_SMOOTH")),
        };
        c.gl.shade_model(model);
        c.shade_model = mode;
        c.update_mode();
        Ok(())
    })
}

/// ffvk's extension: with `GL_SMOOTH`, evaluate the equation per fragment (Phong's
/// interpolation) instead of per vertex. `GL_FLAT` still draws flat. Off initially.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkPerFragmentLighting(ctx: *mut FfvkContext, enabled: u8) {
    with_context(ctx, "ffvkPerFragmentLighting", |c| {
        c.per_fragment = enabled != 0;
        c.update_mode();
        Ok(())
    })
}

/// The current modelview matrix (16 floats, column-major, as glLoadMatrixf): the layer sets
/// it whenever its modelview changes. Light positions and spot directions given later are
/// transformed by it, and draws use it. `GL_INVALID_VALUE` (matrix kept) for a null pointer
/// or a component that is not finite.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `m` is null or points at 16
/// floats.
#[no_mangle]
pub unsafe extern "C" fn ffvkLoadModelview(ctx: *mut FfvkContext, m: *const f32) {
    let f = "ffvkLoadModelview";
    with_context(ctx, f, |c| {
        let matrix = load_matrix(f, m)?;
        c.gl.load_modelview(matrix).map_err(|e| state_error(f, e))
    })
}

/// The current projection matrix (16 floats, column-major, GL's clip space with z in
/// [-w, w]): draws use it. Errors as `ffvkLoadModelview`.
///
/// # Safety
///
/// As `ffvkLoadModelview`.
#[no_mangle]
pub unsafe extern "C" fn ffvkLoadProjection(ctx: *mut FfvkContext, m: *const f32) {
    let f = "ffvkLoadProjection";
    with_context(ctx, f, |c| {
        c.projection = load_matrix(f, m)?;
        Ok(())
    })
}

/// The active unit's current texture matrix (its `GL_TEXTURE` stack's top; `ffvkActiveTexture`
/// selects the unit). Errors as `ffvkLoadModelview`.
///
/// # Safety
///
/// As `ffvkLoadModelview`.
#[no_mangle]
pub unsafe extern "C" fn ffvkLoadTextureMatrix(ctx: *mut FfvkContext, m: *const f32) {
    let f = "ffvkLoadTextureMatrix";
    with_context(ctx, f, |c| {
        let matrix = load_matrix(f, m)?;
        c.gl.load_texture_matrix(matrix).map_err(|e| state_error(f, e))
    })
}
