//! The texture units (GL 2.1 §2.7, §3.8.17; `GL_MAX_TEXTURE_UNITS` and `GL_MAX_TEXTURE_COORDS`
//! are 4): `ffvkActiveTexture`, which selects the unit glTexEnv, glTexGen, the texture matrix
//! and the `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP` and `GL_TEXTURE_GEN_*` enables act on and
//! queries answer for, and
//! `ffvkMultiTexCoord*`, each unit's current texture coordinates.
//!
//! There is no `ffvkClientActiveTexture`: the C API keeps no client array state for it to
//! select. A layer declares its arrays in an `FfvkVertexLayoutInfo`, where unit i's texture
//! coordinate array is a field of its own (`texcoord`, `texcoord1` .. `texcoord3`); its own
//! glClientActiveTexture only says which of those fields its next glTexCoordPointer fills.

use ffvk::gl::texture::MAX_TEXTURE_UNITS;
use ffvk::glam::Vec4;

use super::{invalid_enum, read_named, state_error, with_context, FfvkContext, GlResult};
use crate::enums::*;

/// What a unit parameter takes, for messages.
const UNITS: &str = "GL_TEXTURE0 .. GL_TEXTURE3 (GL_MAX_TEXTURE_UNITS is 4)";
const COORDS: &str = "GL_TEXTURE0 .. GL_TEXTURE3 (GL_MAX_TEXTURE_COORDS is 4)";

/// The unit `GL_TEXTUREi` names (i below 4), or `GL_INVALID_ENUM` naming `what` and what was
/// expected.
fn unit(function: &str, what: &str, texture: u32, expected: &str) -> GlResult<usize> {
    match texture.checked_sub(GL_TEXTURE0) {
        Some(i) if (i as usize) < MAX_TEXTURE_UNITS => Ok(i as usize),
        _ => Err(invalid_enum(function, what, texture, expected)),
    }
}

/// glActiveTexture: `GL_TEXTURE0` .. `GL_TEXTURE3` becomes the active unit (`GL_ACTIVE_TEXTURE`,
/// `GL_TEXTURE0` initially): the unit later `ffvkTexEnv*`, `ffvkTexGen*`,
/// `ffvkLoadTextureMatrix`, `GL_TEXTURE_2D`, `GL_TEXTURE_CUBE_MAP`, `GL_TEXTURE_GEN_*` and
/// `GL_COORD_REPLACE` act on,
/// and whose state `ffvkGetTexEnv*`, `ffvkGetTexGen*`, `ffvkIsEnabled` and
/// `GL_CURRENT_TEXTURE_COORDS` and `GL_TEXTURE_MATRIX` answer. Errors: `GL_INVALID_ENUM` for any
/// other value (`GL_TEXTURE4` and past: ffvk has four units, and no shader image units beyond
/// them), the active unit unchanged.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkActiveTexture(ctx: *mut FfvkContext, texture: u32) {
    const F: &str = "ffvkActiveTexture";
    with_context(ctx, F, |c| {
        let i = unit(F, "texture", texture, UNITS)?;
        c.gl.active_texture(i).map_err(|e| state_error(F, e))
    })
}

/// One glMultiTexCoord call: the target checked first, then the coordinates.
fn multi_tex_coord(ctx: *mut FfvkContext, f: &str, target: u32, coords: impl FnOnce() -> GlResult<Vec4>) {
    with_context(ctx, f, |c| {
        let i = unit(f, "target", target, COORDS)?;
        let v = coords()?;
        c.gl.multi_tex_coord(i, v).map_err(|e| state_error(f, e))
    })
}

/// glMultiTexCoord4f: unit `target`'s (`GL_TEXTURE0` .. `GL_TEXTURE3`) current texture
/// coordinates (s, t, r, q), whatever the active unit: every vertex's for that unit in a draw
/// whose layout has no texture coordinate array for it (`ffvkTexCoord4f` is
/// `ffvkMultiTexCoord4f(GL_TEXTURE0, …)`). Initially (0, 0, 0, 1) on every unit. Errors:
/// `GL_INVALID_ENUM` for another target (GL 2.1 §2.7 leaves an invalid coordinate set
/// undefined: ffvk refuses it); `GL_INVALID_VALUE` for a component that is not finite (ffvk's
/// choice). Nothing changes on an error.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkMultiTexCoord4f(
    ctx: *mut FfvkContext,
    target: u32,
    s: f32,
    t: f32,
    r: f32,
    q: f32,
) {
    multi_tex_coord(ctx, "ffvkMultiTexCoord4f", target, || Ok(Vec4::new(s, t, r, q)))
}

/// glMultiTexCoord2f: `ffvkMultiTexCoord4f` with r = 0 and q = 1.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkMultiTexCoord2f(ctx: *mut FfvkContext, target: u32, s: f32, t: f32) {
    multi_tex_coord(ctx, "ffvkMultiTexCoord2f", target, || {
        Ok(Vec4::new(s, t, 0.0, 1.0))
    })
}

/// glMultiTexCoord4fv: `ffvkMultiTexCoord4f` with (s, t, r, q) read from `v`. Errors as
/// `ffvkMultiTexCoord4f`, and `GL_INVALID_VALUE` for a null or misaligned `v` (checked after
/// the target).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `v` is null or points at four
/// floats.
#[no_mangle]
pub unsafe extern "C" fn ffvkMultiTexCoord4fv(ctx: *mut FfvkContext, target: u32, v: *const f32) {
    const F: &str = "ffvkMultiTexCoord4fv";
    multi_tex_coord(ctx, F, target, || {
        // SAFETY: the caller's contract: v is null, misaligned or points at four floats.
        let v = unsafe { read_named(F, "v", v, 4) }?;
        Ok(Vec4::new(v[0], v[1], v[2], v[3]))
    })
}
