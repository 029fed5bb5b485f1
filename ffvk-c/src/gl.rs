//! The context: GL's lighting state machine behind GL's own entry points, enums and errors.
//!
//! Each `ffvk*` state function is the GL function of the same name with the context first. A
//! call GL would refuse sets GL's error (first error sticks until `ffvkGetError` reads it, as
//! in GL) and changes nothing; its message, naming the parameter, the value and what was
//! expected, is `ffvkResultMessage()` on the calling thread.

use std::panic::{catch_unwind, AssertUnwindSafe};

use ffvk::gl::state::{
    Cap, ColorControl, ColorMaterialMode, Face, GlState, LightModelParam, LightParam, LightingMode,
    MaterialParam, ShadeModel, StateError, TexEnvParam, MAX_LIGHTS,
};
use ffvk::gl::texture::TexEnvMode;
use ffvk::glam::{Mat4, Vec3, Vec4};

use crate::enums::*;
use crate::result::{fail, misaligned, panic_text, FfvkResult};

/// GL's lighting state, its matrices and its error flag: what an application's GL calls set.
/// Made by `ffvkCreateContext`, freed by `ffvkDestroyContext`. One thread at a time may call
/// into a context (GL's rule for a current context); different contexts are independent.
pub struct FfvkContext {
    pub(crate) gl: GlState,
    pub(crate) projection: Mat4,
    /// GL's error flag: the first error since the last `ffvkGetError`.
    error: u32,
    pub(crate) shade_model: u32,
    pub(crate) per_fragment: bool,
    /// `GL_COLOR_INDEXES` of the front and back material: kept for queries (color-index
    /// lighting is not drawn).
    pub(crate) color_indexes: [[f32; 3]; 2],
}

/// A GL error with its message.
pub(crate) struct GlError {
    code: u32,
    message: String,
}

pub(crate) type GlResult<T = ()> = Result<T, GlError>;

impl GlError {
    /// GL_INVALID_VALUE for a pointer parameter that is not aligned for its values.
    pub(crate) fn misaligned<T>(function: &str, name: &str, ptr: *const T) -> GlError {
        GlError {
            code: GL_INVALID_VALUE,
            message: format!(
                "{function}: {name} {ptr:p} is not aligned to {} bytes: expected a pointer to its values (GL_INVALID_VALUE)",
                std::mem::align_of::<T>()
            ),
        }
    }

    pub(crate) fn null_out(function: &str) -> GlError {
        GlError {
            code: GL_INVALID_VALUE,
            message: format!(
                "{function}: params is a null pointer: expected room for the answer (GL_INVALID_VALUE)"
            ),
        }
    }
}

pub(crate) fn invalid_enum(function: &str, what: &str, value: u32, expected: &str) -> GlError {
    GlError {
        code: GL_INVALID_ENUM,
        message: format!(
            "{function}: {what} 0x{value:04X} is not accepted: expected {expected} (GL_INVALID_ENUM)"
        ),
    }
}

fn state_error(function: &str, e: StateError) -> GlError {
    let code = match e {
        StateError::LightIndex { .. } => GL_INVALID_ENUM,
        _ => GL_INVALID_VALUE,
    };
    let name = if code == GL_INVALID_ENUM {
        "GL_INVALID_ENUM"
    } else {
        "GL_INVALID_VALUE"
    };
    GlError {
        code,
        message: format!("{function}: {e} ({name})"),
    }
}

fn null_params(function: &str, name: &str, len: usize) -> GlError {
    GlError {
        code: GL_INVALID_VALUE,
        message: format!(
            "{function}: {name} is a null pointer: expected the parameter's {len} value(s) (GL_INVALID_VALUE)"
        ),
    }
}

impl FfvkContext {
    fn new() -> Self {
        FfvkContext {
            gl: GlState::new(),
            projection: Mat4::IDENTITY,
            error: GL_NO_ERROR,
            shade_model: GL_SMOOTH,
            per_fragment: false,
            color_indexes: [[0.0, 1.0, 1.0]; 2],
        }
    }

    /// GL's rule: the first error since the last `ffvkGetError` is kept, later ones are
    /// dropped. The thread's message follows the kept error, so that `ffvkResultMessage`
    /// describes what `ffvkGetError` will return.
    fn record(&mut self, e: GlError) {
        if self.error == GL_NO_ERROR {
            self.error = e.code;
            fail(FfvkResult::FFVK_SUCCESS, e.message);
        }
    }

    /// glGetError: the flag, then cleared.
    pub(crate) fn take_error(&mut self) -> u32 {
        std::mem::replace(&mut self.error, GL_NO_ERROR)
    }

    fn update_mode(&mut self) {
        let mode = if self.shade_model == GL_FLAT {
            LightingMode::Flat
        } else if self.per_fragment {
            LightingMode::Fragment
        } else {
            LightingMode::Vertex
        };
        self.gl.lighting_mode(mode);
    }
}

/// Runs a state entry point on `ctx`: nothing for a null context (GL without a current
/// context), GL's error for a refused call, `GL_OUT_OF_MEMORY` for a panic (GL's error after
/// which the state is undefined).
pub(crate) fn with_context<T: Default>(
    ctx: *mut FfvkContext,
    function: &str,
    f: impl FnOnce(&mut FfvkContext) -> GlResult<T>,
) -> T {
    if misaligned(ctx) {
        fail(
            FfvkResult::FFVK_SUCCESS,
            format!(
                "{function}: the context {ctx:p} is not aligned: expected a context from ffvkCreateContext"
            ),
        );
        return T::default();
    }
    // SAFETY: the caller's contract (ffvk.h): ctx is null or a live context from
    // ffvkCreateContext used by one thread at a time.
    let Some(context) = (unsafe { ctx.as_mut() }) else {
        fail(
            FfvkResult::FFVK_SUCCESS,
            format!("{function}: the context is a null pointer"),
        );
        return T::default();
    };
    match catch_unwind(AssertUnwindSafe(|| f(&mut *context))) {
        Ok(Ok(value)) => value,
        Ok(Err(e)) => {
            context.record(e);
            T::default()
        }
        Err(payload) => {
            context.record(GlError {
                code: GL_OUT_OF_MEMORY,
                message: format!(
                    "{function}: internal error (a panic inside ffvk): {}",
                    panic_text(&payload)
                ),
            });
            T::default()
        }
    }
}

/// A parameter array as GL's `fv` or `iv` entry point passes it.
#[derive(Clone, Copy)]
pub(crate) enum Values<'a> {
    F(&'a [f32]),
    I(&'a [i32]),
}

impl Values<'_> {
    /// The values as written (integers converted directly): positions, directions, scalars.
    fn plain(&self, i: usize) -> f32 {
        match self {
            Values::F(v) => v[i],
            Values::I(v) => v[i] as f32,
        }
    }
    /// The values as a color: integers map [-2^31, 2^31 - 1] onto [-1, 1] (GL 2.1 table 2.9:
    /// (2c + 1) / (2^32 - 1)).
    fn color(&self, i: usize) -> f32 {
        match self {
            Values::F(v) => v[i],
            Values::I(v) => ((2.0 * v[i] as f64 + 1.0) / 4_294_967_295.0) as f32,
        }
    }
    fn color4(&self) -> Vec4 {
        Vec4::new(self.color(0), self.color(1), self.color(2), self.color(3))
    }
    fn vec4(&self) -> Vec4 {
        Vec4::new(self.plain(0), self.plain(1), self.plain(2), self.plain(3))
    }
    /// The value read as an enum: a float is truncated to an integer first; one that is not
    /// finite is no enum and sets GL_INVALID_VALUE, as for every other parameter.
    fn as_enum(&self, function: &str, parameter: &'static str, valid: &'static str) -> GlResult<u32> {
        self.finite(function, parameter, valid, 1)?;
        Ok(match self {
            Values::F(v) => v[0] as i32 as u32,
            Values::I(v) => v[0] as u32,
        })
    }
    /// The value read as a boolean (non-zero is true); GL_INVALID_VALUE for a float that is
    /// not finite (NaN is not "non-zero").
    fn as_bool(&self, function: &str, parameter: &'static str) -> GlResult<bool> {
        self.finite(function, parameter, "a finite number (non-zero is GL_TRUE)", 1)?;
        Ok(self.plain(0) != 0.0)
    }
    /// GL_INVALID_VALUE for the first of `len` float values that is not finite, for the
    /// parameters ffvk's state does not check itself.
    fn finite(&self, function: &str, parameter: &'static str, valid: &'static str, len: usize) -> GlResult {
        match self {
            Values::F(v) => match v[..len].iter().find(|v| !v.is_finite()) {
                Some(&value) => Err(state_error(
                    function,
                    StateError::NotFinite {
                        parameter,
                        value,
                        valid,
                    },
                )),
                None => Ok(()),
            },
            Values::I(_) => Ok(()),
        }
    }
}

/// Reads `len` values of an `fv`/`iv` entry point, or GL_INVALID_VALUE for a null or
/// misaligned pointer.
///
/// # Safety
///
/// `params` is null, misaligned or points at `len` readable values of `T`.
unsafe fn read<'a, T>(function: &str, params: *const T, len: usize) -> GlResult<&'a [T]> {
    // SAFETY: the caller's contract.
    unsafe { read_named(function, "params", params, len) }
}

/// `read` for a pointer parameter named `name`.
///
/// # Safety
///
/// As `read`.
unsafe fn read_named<'a, T>(function: &str, name: &str, ptr: *const T, len: usize) -> GlResult<&'a [T]> {
    if ptr.is_null() {
        return Err(null_params(function, name, len));
    }
    if misaligned(ptr) {
        return Err(GlError::misaligned(function, name, ptr));
    }
    // SAFETY: the caller's contract: `len` values are readable at a non-null, aligned ptr.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

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
const LIGHT_SCALAR_PNAMES: &str =
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
fn light_call(function: &str, light: u32, pname: u32, scalar: bool) -> GlResult<(usize, usize)> {
    let index = light_index(function, light)?;
    match light_len(pname) {
        Some(1) => Ok((index, 1)),
        Some(n) if !scalar => Ok((index, n)),
        Some(_) => Err(invalid_enum(function, "pname", pname, LIGHT_SCALAR_PNAMES)),
        None => Err(invalid_enum(function, "pname", pname, LIGHT_PNAMES)),
    }
}

fn set_light(ctx: &mut FfvkContext, function: &str, index: usize, pname: u32, v: Values) -> GlResult {
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

fn material_len(pname: u32) -> Option<usize> {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => Some(4),
        GL_COLOR_INDEXES => Some(3),
        GL_SHININESS => Some(1),
        _ => None,
    }
}

fn material_call(function: &str, face_enum: u32, pname: u32, scalar: bool) -> GlResult<(Face, usize)> {
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

fn set_material(ctx: &mut FfvkContext, function: &str, face: Face, pname: u32, v: Values) -> GlResult {
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

const LIGHT_MODEL_PNAMES: &str = "GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE or GL_LIGHT_MODEL_COLOR_CONTROL";

fn light_model_len(function: &str, pname: u32, scalar: bool) -> GlResult<usize> {
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

fn set_light_model(ctx: &mut FfvkContext, function: &str, pname: u32, v: Values) -> GlResult {
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

fn tex_env_len(function: &str, target: u32, pname: u32, scalar: bool) -> GlResult<usize> {
    if target != GL_TEXTURE_ENV {
        return Err(invalid_enum(function, "target", target, "GL_TEXTURE_ENV"));
    }
    match pname {
        GL_TEXTURE_ENV_MODE => Ok(1),
        GL_TEXTURE_ENV_COLOR if !scalar => Ok(4),
        GL_TEXTURE_ENV_COLOR => Err(invalid_enum(
            function,
            "pname",
            pname,
            "GL_TEXTURE_ENV_MODE (the single-valued parameter)",
        )),
        _ => Err(invalid_enum(
            function,
            "pname",
            pname,
            "GL_TEXTURE_ENV_MODE or GL_TEXTURE_ENV_COLOR",
        )),
    }
}

fn set_tex_env(ctx: &mut FfvkContext, function: &str, pname: u32, v: Values) -> GlResult {
    let param = match pname {
        GL_TEXTURE_ENV_MODE => TexEnvParam::Mode(
            match v.as_enum(
                function,
                "GL_TEXTURE_ENV_MODE",
                "GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND or GL_ADD",
            )? {
                GL_MODULATE => TexEnvMode::Modulate,
                GL_REPLACE => TexEnvMode::Replace,
                GL_DECAL => TexEnvMode::Decal,
                GL_BLEND => TexEnvMode::Blend,
                GL_ADD => TexEnvMode::Add,
                other => return Err(invalid_enum(
                    function,
                    "GL_TEXTURE_ENV_MODE value",
                    other,
                    "GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND or GL_ADD (GL_COMBINE is not drawn by ffvk)",
                )),
            },
        ),
        _ => TexEnvParam::Color(v.color4()),
    };
    ctx.gl.tex_env(param).map_err(|e| state_error(function, e))
}

/// The capability of glEnable, glDisable and glIsEnabled.
pub(crate) fn cap(function: &str, cap: u32) -> GlResult<Cap> {
    match cap {
        GL_LIGHTING => Ok(Cap::Lighting),
        GL_COLOR_MATERIAL => Ok(Cap::ColorMaterial),
        GL_NORMALIZE => Ok(Cap::Normalize),
        GL_RESCALE_NORMAL => Ok(Cap::RescaleNormal),
        GL_TEXTURE_2D => Ok(Cap::Texture2D),
        other => light_index(function, other).map(Cap::Light).map_err(|_| {
            invalid_enum(
                function,
                "cap",
                other,
                "GL_LIGHTING, GL_LIGHT0 .. GL_LIGHT0 + 15, GL_COLOR_MATERIAL, GL_NORMALIZE, GL_RESCALE_NORMAL or GL_TEXTURE_2D",
            )
        }),
    }
}

fn color_material_mode(function: &str, mode: u32) -> GlResult<ColorMaterialMode> {
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

fn load_matrix(function: &str, m: *const f32) -> GlResult<Mat4> {
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
/// `GL_RESCALE_NORMAL`, `GL_TEXTURE_2D`. Sets `GL_INVALID_ENUM` for any other cap (a layer
/// keeps the rest of GL's capabilities itself). Enabling `GL_COLOR_MATERIAL` writes the
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

/// glTexEnvfv on `GL_TEXTURE_ENV`: `GL_TEXTURE_ENV_MODE` (`GL_MODULATE`, `GL_REPLACE`,
/// `GL_DECAL`, `GL_BLEND`, `GL_ADD`) or `GL_TEXTURE_ENV_COLOR` (4 values, clamped to [0, 1]).
/// Errors: `GL_INVALID_ENUM` for another target, `pname` or mode (`GL_COMBINE` included: ffvk
/// does not draw it); `GL_INVALID_VALUE` for a value that is not finite or a null `params`.
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

/// glTexEnvf: `GL_TEXTURE_ENV_MODE` only (`GL_TEXTURE_ENV_COLOR` sets `GL_INVALID_ENUM`).
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

/// The current texture matrix (the `GL_TEXTURE` stack's top). Errors as `ffvkLoadModelview`.
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
