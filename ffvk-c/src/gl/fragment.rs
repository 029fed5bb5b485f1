//! GL's per-fragment operations on a context (GL 2.1 §4.1, §4.2.2): the stencil and depth
//! tests, blending, the logic op, the color and depth masks, glDepthRange and glClearStencil.
//! A draw takes them with `FfvkDrawInfo::raster_source` `FFVK_RASTER_SOURCE_CONTEXT`.

use ffvk::gl::state::{BlendEquation, BlendFactor, CompareFunc, Face, LogicOp, StencilOp};
use ffvk::glam::Vec4;

use super::raster::gl_enum;
use super::{face, state_error, with_context, FfvkContext, GlResult};

/// glStencilFuncSeparate's checks: the face, then the function.
fn stencil_func_call(
    ctx: *mut FfvkContext,
    f: &str,
    face: impl FnOnce() -> GlResult<Face>,
    (func, reference, mask): (u32, i32, u32),
) {
    with_context(ctx, f, |c| {
        let face = face()?;
        let func: CompareFunc = gl_enum(f, "func", func)?;
        c.gl.stencil_func_separate(face, func, reference, mask);
        Ok(())
    })
}

/// glStencilFunc: both faces' stencil test: `func` (`GL_NEVER` .. `GL_ALWAYS`), the reference
/// `ref` (kept as given; clamped to [0, 255], ffvk's 8 stencil bits, when tested and queried)
/// and the mask both are ANDed with. Errors: `GL_INVALID_ENUM` for another func.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkStencilFunc(ctx: *mut FfvkContext, func: u32, reference: i32, mask: u32) {
    stencil_func_call(
        ctx,
        "ffvkStencilFunc",
        || Ok(Face::FrontAndBack),
        (func, reference, mask),
    )
}

/// glStencilFuncSeparate: `ffvkStencilFunc` for `face` (`GL_FRONT`, `GL_BACK` or
/// `GL_FRONT_AND_BACK`). Errors: `GL_INVALID_ENUM` for another face or func.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkStencilFuncSeparate(
    ctx: *mut FfvkContext,
    face_enum: u32,
    func: u32,
    reference: i32,
    mask: u32,
) {
    const F: &str = "ffvkStencilFuncSeparate";
    stencil_func_call(ctx, F, || face(F, face_enum), (func, reference, mask))
}

/// glStencilOpSeparate's checks: the face, then each action in order.
fn stencil_op_call(
    ctx: *mut FfvkContext,
    f: &str,
    face: impl FnOnce() -> GlResult<Face>,
    (sfail, dpfail, dppass): (u32, u32, u32),
) {
    with_context(ctx, f, |c| {
        let face = face()?;
        let sfail: StencilOp = gl_enum(f, "sfail", sfail)?;
        let dpfail: StencilOp = gl_enum(f, "dpfail", dpfail)?;
        let dppass: StencilOp = gl_enum(f, "dppass", dppass)?;
        c.gl.stencil_op_separate(face, sfail, dpfail, dppass);
        Ok(())
    })
}

/// glStencilOp: both faces' actions when the stencil test fails (`sfail`), when it passes and
/// the depth test fails (`dpfail`) and when both pass (`dppass`): `GL_KEEP`, `GL_ZERO`,
/// `GL_REPLACE`, `GL_INCR`, `GL_DECR`, `GL_INVERT`, `GL_INCR_WRAP` or `GL_DECR_WRAP`. Errors:
/// `GL_INVALID_ENUM` for another action.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkStencilOp(ctx: *mut FfvkContext, sfail: u32, dpfail: u32, dppass: u32) {
    stencil_op_call(
        ctx,
        "ffvkStencilOp",
        || Ok(Face::FrontAndBack),
        (sfail, dpfail, dppass),
    )
}

/// glStencilOpSeparate: `ffvkStencilOp` for `face`. Errors: `GL_INVALID_ENUM` for another face
/// or action.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkStencilOpSeparate(
    ctx: *mut FfvkContext,
    face_enum: u32,
    sfail: u32,
    dpfail: u32,
    dppass: u32,
) {
    const F: &str = "ffvkStencilOpSeparate";
    stencil_op_call(ctx, F, || face(F, face_enum), (sfail, dpfail, dppass))
}

/// glStencilMask: the stencil bits both faces' fragments may write. Never an error.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkStencilMask(ctx: *mut FfvkContext, mask: u32) {
    with_context(ctx, "ffvkStencilMask", |c| {
        c.gl.stencil_mask(mask);
        Ok(())
    })
}

/// glStencilMaskSeparate: `ffvkStencilMask` for `face`. Errors: `GL_INVALID_ENUM` for another
/// face.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkStencilMaskSeparate(ctx: *mut FfvkContext, face_enum: u32, mask: u32) {
    const F: &str = "ffvkStencilMaskSeparate";
    with_context(ctx, F, |c| {
        let face = face(F, face_enum)?;
        c.gl.stencil_mask_separate(face, mask);
        Ok(())
    })
}

/// glClearStencil: the value a stencil clear writes, kept as given for
/// `GL_STENCIL_CLEAR_VALUE` (the caller clears its own attachments). Never an error.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkClearStencil(ctx: *mut FfvkContext, s: i32) {
    with_context(ctx, "ffvkClearStencil", |c| {
        c.gl.clear_stencil(s);
        Ok(())
    })
}

/// glColorMask: which channels fragments write (non-zero is `GL_TRUE`). Never an error.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkColorMask(ctx: *mut FfvkContext, red: u8, green: u8, blue: u8, alpha: u8) {
    with_context(ctx, "ffvkColorMask", |c| {
        c.gl.color_mask(red != 0, green != 0, blue != 0, alpha != 0);
        Ok(())
    })
}

/// glDepthMask: whether fragments write depth while the depth test is on (non-zero is
/// `GL_TRUE`). Never an error.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkDepthMask(ctx: *mut FfvkContext, flag: u8) {
    with_context(ctx, "ffvkDepthMask", |c| {
        c.gl.depth_mask(flag != 0);
        Ok(())
    })
}

/// glDepthFunc: the depth test's function, `GL_NEVER` .. `GL_ALWAYS` (`GL_LESS` by default).
/// Errors: `GL_INVALID_ENUM` for another func.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkDepthFunc(ctx: *mut FfvkContext, func: u32) {
    const F: &str = "ffvkDepthFunc";
    with_context(ctx, F, |c| {
        let func: CompareFunc = gl_enum(F, "func", func)?;
        c.gl.depth_func(func);
        Ok(())
    })
}

/// glDepthRange: near and far, each clamped to [0, 1] as GL clamps them, kept for
/// `GL_DEPTH_RANGE` queries (a draw's depth range is its viewport's: pass them to
/// `ffvkViewport`). Errors: `GL_INVALID_VALUE` for a NaN (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkDepthRange(ctx: *mut FfvkContext, near: f64, far: f64) {
    const F: &str = "ffvkDepthRange";
    with_context(ctx, F, |c| {
        c.gl.depth_range(near, far).map_err(|e| state_error(F, e))
    })
}

/// glBlendFuncSeparate's checks: the four factors in order, then the state's (a destination
/// `GL_SRC_ALPHA_SATURATE`).
fn blend_func_call(ctx: *mut FfvkContext, f: &str, names: [&str; 4], factors: [u32; 4]) {
    with_context(ctx, f, |c| {
        let mut parsed = [BlendFactor::Zero; 4];
        for ((slot, name), value) in parsed.iter_mut().zip(names).zip(factors) {
            *slot = gl_enum(f, name, value)?;
        }
        let [src_rgb, dst_rgb, src_alpha, dst_alpha] = parsed;
        c.gl.blend_func_separate((src_rgb, dst_rgb), (src_alpha, dst_alpha))
            .map_err(|e| state_error(f, e))
    })
}

/// glBlendFunc: the source and destination factors of color and alpha while `GL_BLEND` is
/// enabled (GL 2.1 table 4.2: `GL_ZERO`, `GL_ONE`, the `SRC`, `DST` and `CONSTANT` color and
/// alpha factors and their `ONE_MINUS` forms, and, as a source only, `GL_SRC_ALPHA_SATURATE`).
/// Errors: `GL_INVALID_ENUM` for another factor.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkBlendFunc(ctx: *mut FfvkContext, sfactor: u32, dfactor: u32) {
    blend_func_call(
        ctx,
        "ffvkBlendFunc",
        ["sfactor", "dfactor", "sfactor", "dfactor"],
        [sfactor, dfactor, sfactor, dfactor],
    )
}

/// glBlendFuncSeparate: `ffvkBlendFunc` with color's and alpha's factors apart. Errors:
/// `GL_INVALID_ENUM` for another factor.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkBlendFuncSeparate(
    ctx: *mut FfvkContext,
    src_rgb: u32,
    dst_rgb: u32,
    src_alpha: u32,
    dst_alpha: u32,
) {
    blend_func_call(
        ctx,
        "ffvkBlendFuncSeparate",
        ["sfactorRGB", "dfactorRGB", "sfactorAlpha", "dfactorAlpha"],
        [src_rgb, dst_rgb, src_alpha, dst_alpha],
    )
}

/// glBlendEquation: color's and alpha's equation, `GL_FUNC_ADD` (the default),
/// `GL_FUNC_SUBTRACT`, `GL_FUNC_REVERSE_SUBTRACT`, `GL_MIN` or `GL_MAX`. Errors:
/// `GL_INVALID_ENUM` for another mode.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkBlendEquation(ctx: *mut FfvkContext, mode: u32) {
    const F: &str = "ffvkBlendEquation";
    with_context(ctx, F, |c| {
        let equation: BlendEquation = gl_enum(F, "mode", mode)?;
        c.gl.blend_equation(equation);
        Ok(())
    })
}

/// glBlendEquationSeparate: `ffvkBlendEquation` with color's and alpha's apart. Errors:
/// `GL_INVALID_ENUM` for another mode.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkBlendEquationSeparate(ctx: *mut FfvkContext, mode_rgb: u32, mode_alpha: u32) {
    const F: &str = "ffvkBlendEquationSeparate";
    with_context(ctx, F, |c| {
        let rgb: BlendEquation = gl_enum(F, "modeRGB", mode_rgb)?;
        let alpha: BlendEquation = gl_enum(F, "modeAlpha", mode_alpha)?;
        c.gl.blend_equation_separate(rgb, alpha);
        Ok(())
    })
}

/// glBlendColor: the constant the `GL_CONSTANT_*` factors read, each component clamped to
/// [0, 1] as GL 2.1 clamps it. Errors: `GL_INVALID_VALUE` for a component that is not finite
/// (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkBlendColor(ctx: *mut FfvkContext, red: f32, green: f32, blue: f32, alpha: f32) {
    const F: &str = "ffvkBlendColor";
    with_context(ctx, F, |c| {
        c.gl.blend_color(Vec4::new(red, green, blue, alpha))
            .map_err(|e| state_error(F, e))
    })
}

/// glLogicOp: the op used while `GL_COLOR_LOGIC_OP` is enabled, `GL_CLEAR` .. `GL_SET`
/// (`GL_COPY` by default). Errors: `GL_INVALID_ENUM` for another op.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkLogicOp(ctx: *mut FfvkContext, opcode: u32) {
    const F: &str = "ffvkLogicOp";
    with_context(ctx, F, |c| {
        let op: LogicOp = gl_enum(F, "opcode", opcode)?;
        c.gl.logic_op(op);
        Ok(())
    })
}
