//! glClipPlane: GL 2.1's user clip planes (section 2.12) on a context.

use ffvk::glam::DVec4;

use super::{invalid_enum, read_named, state_error, with_context, FfvkContext, GlResult};
use crate::enums::*;

/// The plane index of `GL_CLIP_PLANEi`, i in 0..6.
pub(crate) fn clip_plane_index(function: &str, plane: u32) -> GlResult<usize> {
    plane
        .checked_sub(GL_CLIP_PLANE0)
        .filter(|&i| (i as usize) < ffvk::gl::state::MAX_CLIP_PLANES)
        .map(|i| i as usize)
        .ok_or_else(|| invalid_enum(function, "plane", plane, "GL_CLIP_PLANE0 .. GL_CLIP_PLANE0 + 5"))
}

/// glClipPlane: the plane's equation (four doubles, in object coordinates), stored in eye
/// space by the inverse of the context's modelview now (GL 2.1 §2.12); enable it with
/// `ffvkEnable(ctx, GL_CLIP_PLANEi)`. Drawing with a plane enabled needs
/// `FFVK_FEATURE_CLIP_DISTANCE`. `plane` is GL's enum, `GL_CLIP_PLANE0` + i (i < 6), not the
/// index. Errors: `GL_INVALID_ENUM` for another `plane`;
/// `GL_INVALID_VALUE` for a null `equation`, a value that is not finite, or a singular
/// modelview (ffvk's choices: GL leaves those undefined).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `equation` is null or points
/// at four doubles.
#[no_mangle]
pub unsafe extern "C" fn ffvkClipPlane(ctx: *mut FfvkContext, plane: u32, equation: *const f64) {
    const F: &str = "ffvkClipPlane";
    with_context(ctx, F, |c| {
        let i = clip_plane_index(F, plane)?;
        // SAFETY: the caller's contract on equation.
        let e = unsafe { read_named(F, "equation", equation, 4) }?;
        c.gl.clip_plane(i, DVec4::new(e[0], e[1], e[2], e[3]))
            .map_err(|e| state_error(F, e))
    })
}
