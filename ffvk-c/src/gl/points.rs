//! glPointParameter: GL 2.1's point parameters (section 3.3, ARB_point_parameters and the
//! sprite origin of GL 2.0) on a context. The point size itself is the draw's
//! (`FfvkRaster::point_size`); `GL_POINT_SPRITE` is a cap and `GL_COORD_REPLACE` a glTexEnv
//! parameter of target `GL_POINT_SPRITE`.

use ffvk::gl::state::{PointParam, SpriteOrigin};
use ffvk::glam::Vec3;

use super::{invalid_enum, read, state_error, with_context, FfvkContext, GlResult, Values};
use crate::enums::*;

const POINT_PNAMES: &str = "GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE, \
GL_POINT_SPRITE_COORD_ORIGIN or (the vector forms) GL_POINT_DISTANCE_ATTENUATION";

/// How many values `pname` takes; `scalar` for glPointParameterf/i, which cannot set the
/// attenuation.
fn point_len(function: &str, pname: u32, scalar: bool) -> GlResult<usize> {
    match pname {
        GL_POINT_SIZE_MIN
        | GL_POINT_SIZE_MAX
        | GL_POINT_FADE_THRESHOLD_SIZE
        | GL_POINT_SPRITE_COORD_ORIGIN => Ok(1),
        GL_POINT_DISTANCE_ATTENUATION if !scalar => Ok(3),
        _ => Err(invalid_enum(function, "pname", pname, POINT_PNAMES)),
    }
}

fn set_point(c: &mut FfvkContext, function: &str, pname: u32, v: Values) -> GlResult {
    let param = match pname {
        GL_POINT_SIZE_MIN => PointParam::SizeMin(v.plain(0)),
        GL_POINT_SIZE_MAX => PointParam::SizeMax(v.plain(0)),
        GL_POINT_FADE_THRESHOLD_SIZE => PointParam::FadeThresholdSize(v.plain(0)),
        GL_POINT_DISTANCE_ATTENUATION => {
            PointParam::DistanceAttenuation(Vec3::new(v.plain(0), v.plain(1), v.plain(2)))
        }
        GL_POINT_SPRITE_COORD_ORIGIN => PointParam::SpriteCoordOrigin(
            match v.as_enum(
                function,
                "GL_POINT_SPRITE_COORD_ORIGIN",
                "GL_UPPER_LEFT or GL_LOWER_LEFT",
            )? {
                GL_UPPER_LEFT => SpriteOrigin::UpperLeft,
                GL_LOWER_LEFT => SpriteOrigin::LowerLeft,
                other => {
                    return Err(invalid_enum(
                        function,
                        "GL_POINT_SPRITE_COORD_ORIGIN",
                        other,
                        "GL_UPPER_LEFT or GL_LOWER_LEFT",
                    ))
                }
            },
        ),
        _ => return Err(invalid_enum(function, "pname", pname, POINT_PNAMES)),
    };
    c.gl.point_parameter(param).map_err(|e| state_error(function, e))
}

fn point_entry<'a>(
    ctx: *mut FfvkContext,
    f: &str,
    (pname, scalar): (u32, bool),
    values: impl FnOnce(usize) -> GlResult<Values<'a>>,
) {
    with_context(ctx, f, |c| {
        let len = point_len(f, pname, scalar)?;
        set_point(c, f, pname, values(len)?)
    })
}

/// glPointParameterf: `GL_POINT_SIZE_MIN`, `GL_POINT_SIZE_MAX`, `GL_POINT_FADE_THRESHOLD_SIZE`
/// (each ≥ 0) or `GL_POINT_SPRITE_COORD_ORIGIN` (`GL_UPPER_LEFT`, `GL_LOWER_LEFT`). A draw of
/// points takes its size from `FfvkRaster::point_size`, times √(1 / (a + b d + c d²)) at the
/// eye distance d where the attenuation is not (1, 0, 0), clamped to [min, max], and rounded
/// to whole pixels unless `GL_POINT_SPRITE` is enabled. Errors: `GL_INVALID_ENUM` for another
/// `pname` (`GL_POINT_DISTANCE_ATTENUATION` included: it has three values) or origin;
/// `GL_INVALID_VALUE` for a negative size or threshold or a value that is not finite.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkPointParameterf(ctx: *mut FfvkContext, pname: u32, param: f32) {
    let value = [param];
    point_entry(ctx, "ffvkPointParameterf", (pname, true), |_| {
        Ok(Values::F(&value))
    });
}

/// glPointParameteri: `ffvkPointParameterf` with an integer.
///
/// # Safety
///
/// As `ffvkPointParameterf`.
#[no_mangle]
pub unsafe extern "C" fn ffvkPointParameteri(ctx: *mut FfvkContext, pname: u32, param: i32) {
    let value = [param];
    point_entry(ctx, "ffvkPointParameteri", (pname, true), |_| {
        Ok(Values::I(&value))
    });
}

/// glPointParameterfv: `ffvkPointParameterf`'s names, and `GL_POINT_DISTANCE_ATTENUATION`
/// (a, b, c). `GL_INVALID_VALUE` also for a null `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or points
/// at as many values as `pname` has.
#[no_mangle]
pub unsafe extern "C" fn ffvkPointParameterfv(ctx: *mut FfvkContext, pname: u32, params: *const f32) {
    let f = "ffvkPointParameterfv";
    point_entry(ctx, f, (pname, false), |n| {
        // SAFETY: the caller's contract on params.
        unsafe { read(f, params, n) }.map(Values::F)
    })
}

/// glPointParameteriv: `ffvkPointParameterfv` with integers.
///
/// # Safety
///
/// As `ffvkPointParameterfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkPointParameteriv(ctx: *mut FfvkContext, pname: u32, params: *const i32) {
    let f = "ffvkPointParameteriv";
    point_entry(ctx, f, (pname, false), |n| {
        // SAFETY: the caller's contract on params.
        unsafe { read(f, params, n) }.map(Values::I)
    })
}
