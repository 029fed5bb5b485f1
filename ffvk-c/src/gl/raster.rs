//! GL's raster state on a context (GL 2.1 §3.3-3.5, §4.1, §4.2.2): glPolygonMode,
//! glPolygonOffset, glLineStipple, glPointSize, glLineWidth, glCullFace, glFrontFace,
//! glEdgeFlag and their caps. A draw takes them with `FfvkDrawInfo::raster_source`
//! `FFVK_RASTER_SOURCE_CONTEXT`; the per-fragment operations are in `fragment.rs`.

use ffvk::gl::state::{Cap, Face, FrontFace, GlEnum, PolygonMode};

use super::{face, invalid_enum, state_error, with_context, FfvkContext, GlResult};
use crate::enums::*;

/// The raster state's caps of glEnable, glDisable, glIsEnabled and glGet; `None` for another.
pub(crate) fn raster_cap(cap: u32) -> Option<Cap> {
    Some(match cap {
        GL_POLYGON_OFFSET_FILL => Cap::PolygonOffsetFill,
        GL_POLYGON_OFFSET_LINE => Cap::PolygonOffsetLine,
        GL_POLYGON_OFFSET_POINT => Cap::PolygonOffsetPoint,
        GL_LINE_STIPPLE => Cap::LineStipple,
        GL_POLYGON_STIPPLE => Cap::PolygonStipple,
        GL_STENCIL_TEST => Cap::StencilTest,
        GL_COLOR_LOGIC_OP => Cap::ColorLogicOp,
        GL_BLEND => Cap::Blend,
        GL_DEPTH_TEST => Cap::DepthTest,
        GL_CULL_FACE => Cap::CullFace,
        _ => return None,
    })
}

/// `value` as the GL enum `T`, or GL_INVALID_ENUM naming parameter `what` and `T`'s values.
pub(crate) fn gl_enum<T: GlEnum>(function: &str, what: &str, value: u32) -> GlResult<T> {
    T::from_gl(value).ok_or_else(|| invalid_enum(function, what, value, T::EXPECTED))
}

/// glPolygonMode: how `face`'s polygons (`GL_FRONT`, `GL_BACK`, `GL_FRONT_AND_BACK`) are
/// rasterized: `GL_POINT`, `GL_LINE` or `GL_FILL`. Errors: `GL_INVALID_ENUM` for another face or
/// mode.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkPolygonMode(ctx: *mut FfvkContext, face_enum: u32, mode: u32) {
    const F: &str = "ffvkPolygonMode";
    with_context(ctx, F, |c| {
        let face = face(F, face_enum)?;
        let mode: PolygonMode = gl_enum(F, "mode", mode)?;
        c.gl.polygon_mode(face, mode);
        Ok(())
    })
}

/// glPolygonOffset: the slope factor and constant of the offset enabled by
/// `GL_POLYGON_OFFSET_FILL`, `_LINE` and `_POINT`. Errors: `GL_INVALID_VALUE` for a value that
/// is not finite (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkPolygonOffset(ctx: *mut FfvkContext, factor: f32, units: f32) {
    const F: &str = "ffvkPolygonOffset";
    with_context(ctx, F, |c| {
        c.gl.polygon_offset(factor, units).map_err(|e| state_error(F, e))
    })
}

/// glLineStipple: the repeat factor (clamped to [1, 256] as GL clamps it) and the 16-bit
/// pattern used while `GL_LINE_STIPPLE` is enabled. Never an error.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkLineStipple(ctx: *mut FfvkContext, factor: i32, pattern: u16) {
    with_context(ctx, "ffvkLineStipple", |c| {
        c.gl.line_stipple(factor, pattern);
        Ok(())
    })
}

/// glPointSize: the size of points, in pixels. Errors: `GL_INVALID_VALUE` for a size at or below
/// 0, or not finite (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkPointSize(ctx: *mut FfvkContext, size: f32) {
    const F: &str = "ffvkPointSize";
    with_context(ctx, F, |c| c.gl.point_size(size).map_err(|e| state_error(F, e)))
}

/// glLineWidth: the width of lines, in pixels. Errors: `GL_INVALID_VALUE` for a width at or
/// below 0, or not finite (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkLineWidth(ctx: *mut FfvkContext, width: f32) {
    const F: &str = "ffvkLineWidth";
    with_context(ctx, F, |c| c.gl.line_width(width).map_err(|e| state_error(F, e)))
}

/// glCullFace: the faces culled while `GL_CULL_FACE` is enabled: `GL_FRONT`, `GL_BACK` (the
/// default) or `GL_FRONT_AND_BACK`. Errors: `GL_INVALID_ENUM` for another mode.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkCullFace(ctx: *mut FfvkContext, mode: u32) {
    const F: &str = "ffvkCullFace";
    with_context(ctx, F, |c| {
        let face = match mode {
            GL_FRONT => Face::Front,
            GL_BACK => Face::Back,
            GL_FRONT_AND_BACK => Face::FrontAndBack,
            other => {
                return Err(invalid_enum(
                    F,
                    "mode",
                    other,
                    "GL_FRONT, GL_BACK or GL_FRONT_AND_BACK",
                ))
            }
        };
        c.gl.cull_face(face);
        Ok(())
    })
}

/// glFrontFace: the winding of front-facing polygons, `GL_CW` or `GL_CCW` (the default).
/// Errors: `GL_INVALID_ENUM` for another mode.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkFrontFace(ctx: *mut FfvkContext, mode: u32) {
    const F: &str = "ffvkFrontFace";
    with_context(ctx, F, |c| {
        let winding: FrontFace = gl_enum(F, "mode", mode)?;
        c.gl.front_face(winding);
        Ok(())
    })
}

/// glPolygonStipple: the 32 × 32 pattern `GL_POLYGON_STIPPLE` applies to filled polygons, 128
/// bytes as GL unpacks them with the default pixel storage: rows of 4 bytes from the bottom row
/// up, the most significant bit of each byte leftmost (`GL_UNPACK_LSB_FIRST` false). A draw with
/// the stipple on needs the framebuffer's height (`ffvkFramebufferHeight`). Errors:
/// `GL_INVALID_VALUE` for a null `mask`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `mask` is null or points at
/// 128 bytes.
#[no_mangle]
pub unsafe extern "C" fn ffvkPolygonStipple(ctx: *mut FfvkContext, mask: *const u8) {
    const F: &str = "ffvkPolygonStipple";
    with_context(ctx, F, |c| {
        // SAFETY: the caller's contract on mask.
        let bytes = unsafe { super::read_named(F, "mask", mask, 128) }?;
        let mut pattern = [0u8; 128];
        pattern.copy_from_slice(bytes);
        c.gl.polygon_stipple(&pattern);
        Ok(())
    })
}

/// The height in pixels of the framebuffer the context's draws render into (ffvk's call: a GL
/// context knows its window's): GL counts `GL_POLYGON_STIPPLE`'s rows from the framebuffer's
/// bottom, so a draw with the stipple on needs it (`FFVK_ERROR_STATE` at `ffvkDraw` otherwise).
/// Call it when the framebuffer is made or resized. Errors: `GL_INVALID_VALUE` for 0.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkFramebufferHeight(ctx: *mut FfvkContext, height: u32) {
    const F: &str = "ffvkFramebufferHeight";
    with_context(ctx, F, |c| {
        c.gl.framebuffer_height(height).map_err(|e| state_error(F, e))
    })
}

/// glEdgeFlag: the current edge flag (non-zero is `GL_TRUE`), kept for `GL_EDGE_FLAG` queries:
/// a draw's flags are in its indices (`ffvkEdgeFlaggedIndices` takes each vertex's). Never an
/// error.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkEdgeFlag(ctx: *mut FfvkContext, flag: u8) {
    with_context(ctx, "ffvkEdgeFlag", |c| {
        c.gl.edge_flag(flag != 0);
        Ok(())
    })
}
