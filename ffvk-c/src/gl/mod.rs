//! The context: GL's lighting state machine behind GL's own entry points, enums and errors.
//!
//! Each `ffvk*` state function is the GL function of the same name with the context first. A
//! call GL would refuse sets GL's error (first error sticks until `ffvkGetError` reads it, as
//! in GL) and changes nothing; its message, naming the parameter, the value and what was
//! expected, is `ffvkResultMessage()` on the calling thread.

//!
//! `params.rs` reads each entry point's enums and values as GL does; `entry.rs` holds the
//! entry points themselves.

use std::panic::{catch_unwind, AssertUnwindSafe};

use ffvk::gl::state::{GlState, LightingMode, StateError};
use ffvk::glam::{DVec4, Mat4, Vec4};

use crate::enums::*;
use crate::result::{fail, misaligned, panic_text, FfvkResult};

mod clip;
mod combine;
mod entry;
mod fog;
mod fragment;
mod params;
mod points;
mod raster;
mod texgen;
mod units;

pub use clip::*;
pub(crate) use combine::{
    argument as combine_argument, gl_enum, source_enum, Argument, ALPHA_OPERANDS, FUNCS, RGB_OPERANDS,
};
pub use entry::*;
pub use fog::*;
pub use fragment::*;
pub(crate) use params::{face, light_index, LIGHT_PNAMES, TEX_ENV_PNAMES};
pub use points::*;
pub use raster::*;
pub use texgen::*;
pub use units::*;

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
    /// `GL_FOG_INDEX`: kept for queries (color-index fog is not drawn).
    pub(crate) fog_index: f32,
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

    /// GL_INVALID_VALUE with `what` (the parameter, its value, what was expected).
    pub(crate) fn invalid_value(function: &str, what: String) -> GlError {
        GlError {
            code: GL_INVALID_VALUE,
            message: format!("{function}: {what} (GL_INVALID_VALUE)"),
        }
    }

    pub(crate) fn null_out(function: &str, name: &str) -> GlError {
        GlError {
            code: GL_INVALID_VALUE,
            message: format!(
                "{function}: {name} is a null pointer: expected room for the answer (GL_INVALID_VALUE)"
            ),
        }
    }
}

pub(crate) fn invalid_enum(function: &str, what: &str, value: u32, expected: &str) -> GlError {
    GlError {
        code: GL_INVALID_ENUM,
        message: format!(
            "{function}: {what} {} is not accepted: expected {expected} (GL_INVALID_ENUM)",
            enum_name(value)
        ),
    }
}

fn state_error(function: &str, e: StateError) -> GlError {
    let code = match e {
        StateError::LightIndex { .. } | StateError::NotAccepted { .. } => GL_INVALID_ENUM,
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
            fog_index: 0.0,
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

/// A parameter array as GL's `fv`, `iv` or `dv` entry point passes it.
#[derive(Clone, Copy)]
pub(crate) enum Values<'a> {
    F(&'a [f32]),
    I(&'a [i32]),
    D(&'a [f64]),
}

impl Values<'_> {
    /// The values as written (integers converted directly): positions, directions, scalars.
    fn plain(&self, i: usize) -> f32 {
        match self {
            Values::F(v) => v[i],
            Values::I(v) => v[i] as f32,
            Values::D(v) => v[i] as f32,
        }
    }
    /// The values as a color: integers map [-2^31, 2^31 - 1] onto [-1, 1] (GL 2.1 table 2.9:
    /// (2c + 1) / (2^32 - 1)).
    fn color(&self, i: usize) -> f32 {
        match self {
            Values::F(v) => v[i],
            Values::I(v) => ((2.0 * v[i] as f64 + 1.0) / 4_294_967_295.0) as f32,
            Values::D(v) => v[i] as f32,
        }
    }
    fn color4(&self) -> Vec4 {
        Vec4::new(self.color(0), self.color(1), self.color(2), self.color(3))
    }
    fn vec4(&self) -> Vec4 {
        Vec4::new(self.plain(0), self.plain(1), self.plain(2), self.plain(3))
    }
    /// Four values as doubles, each exactly as given (integers convert directly): a plane's
    /// coefficients, which ffvk's state takes in double precision as `glClipPlane` gives them.
    fn dvec4(&self) -> DVec4 {
        let d = |i: usize| match self {
            Values::F(v) => f64::from(v[i]),
            Values::I(v) => f64::from(v[i]),
            Values::D(v) => v[i],
        };
        DVec4::new(d(0), d(1), d(2), d(3))
    }
    /// The value read as an enum: a float or double is truncated to an integer first; one
    /// that is not finite is no enum and sets GL_INVALID_VALUE, as for every other parameter.
    fn as_enum(&self, function: &str, parameter: &'static str, valid: &'static str) -> GlResult<u32> {
        self.finite(function, parameter, valid, 1)?;
        Ok(match self {
            Values::F(v) => v[0] as i32 as u32,
            Values::I(v) => v[0] as u32,
            Values::D(v) => v[0] as i32 as u32,
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
            Values::D(v) => match v[..len].iter().find(|v| !v.is_finite()) {
                Some(&value) => Err(state_error(
                    function,
                    StateError::NotFinite {
                        parameter,
                        value: value as f32,
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
