//! glFog, glFogCoord and glHint: GL 2.1's fog (section 3.10) on a context.

use ffvk::gl::state::{FogHint, FogMode, FogParam, FogSource};

use super::{invalid_enum, read, state_error, with_context, FfvkContext, GlResult, Values};
use crate::enums::*;

const FOG_PNAMES: &str =
    "GL_FOG_MODE, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_COORD_SRC or (the vector forms) GL_FOG_COLOR";

/// How many values `pname` takes; `scalar` for glFogf/glFogi, which cannot set the color.
fn fog_len(function: &str, pname: u32, scalar: bool) -> GlResult<usize> {
    match pname {
        GL_FOG_MODE | GL_FOG_DENSITY | GL_FOG_START | GL_FOG_END | GL_FOG_COORD_SRC | GL_FOG_INDEX => Ok(1),
        GL_FOG_COLOR if !scalar => Ok(4),
        _ => Err(invalid_enum(function, "pname", pname, FOG_PNAMES)),
    }
}

fn set_fog(c: &mut FfvkContext, function: &str, pname: u32, v: Values) -> GlResult {
    let param = match pname {
        GL_FOG_MODE => FogParam::Mode(
            match v.as_enum(function, "GL_FOG_MODE", "GL_LINEAR, GL_EXP or GL_EXP2")? {
                GL_LINEAR => FogMode::Linear,
                GL_EXP => FogMode::Exp,
                GL_EXP2 => FogMode::Exp2,
                other => {
                    return Err(invalid_enum(
                        function,
                        "GL_FOG_MODE",
                        other,
                        "GL_LINEAR, GL_EXP or GL_EXP2",
                    ))
                }
            },
        ),
        GL_FOG_DENSITY => FogParam::Density(v.plain(0)),
        GL_FOG_START => FogParam::Start(v.plain(0)),
        GL_FOG_END => FogParam::End(v.plain(0)),
        GL_FOG_COLOR => FogParam::Color(v.color4()),
        // Color-index fog: GL takes it, and it changes nothing in RGBA, the only mode ffvk draws.
        GL_FOG_INDEX => {
            v.finite(function, "GL_FOG_INDEX", "a finite number", 1)?;
            c.fog_index = v.plain(0);
            return Ok(());
        }
        GL_FOG_COORD_SRC => FogParam::CoordSrc(
            match v.as_enum(function, "GL_FOG_COORD_SRC", "GL_FOG_COORD or GL_FRAGMENT_DEPTH")? {
                GL_FOG_COORD => FogSource::FogCoord,
                GL_FRAGMENT_DEPTH => FogSource::FragmentDepth,
                other => {
                    return Err(invalid_enum(
                        function,
                        "GL_FOG_COORD_SRC",
                        other,
                        "GL_FOG_COORD or GL_FRAGMENT_DEPTH",
                    ))
                }
            },
        ),
        _ => return Err(invalid_enum(function, "pname", pname, FOG_PNAMES)),
    };
    c.gl.fog(param).map_err(|e| state_error(function, e))
}

fn fog_entry<'a>(
    ctx: *mut FfvkContext,
    f: &str,
    (pname, scalar): (u32, bool),
    values: impl FnOnce(usize) -> GlResult<Values<'a>>,
) {
    with_context(ctx, f, |c| {
        let len = fog_len(f, pname, scalar)?;
        set_fog(c, f, pname, values(len)?)
    })
}

/// glFogf: `GL_FOG_MODE` (`GL_LINEAR`, `GL_EXP`, `GL_EXP2`), `GL_FOG_DENSITY` (≥ 0),
/// `GL_FOG_START`, `GL_FOG_END`, `GL_FOG_COORD_SRC` (`GL_FOG_COORD`, `GL_FRAGMENT_DEPTH`) or
/// `GL_FOG_INDEX` (color-index fog: kept for queries, drawing nothing in RGBA). A mode given as
/// a float that is not finite is `GL_INVALID_VALUE` (ffvk's rule for every non-finite value,
/// where GL would say `GL_INVALID_ENUM`). Errors: `GL_INVALID_ENUM` for another `pname` (`GL_FOG_COLOR` included: it has four values)
/// or mode; `GL_INVALID_VALUE` for a negative density or a value that is not finite.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkFogf(ctx: *mut FfvkContext, pname: u32, param: f32) {
    let value = [param];
    fog_entry(ctx, "ffvkFogf", (pname, true), |_| Ok(Values::F(&value)));
}

/// glFogi: `ffvkFogf` with an integer.
///
/// # Safety
///
/// As `ffvkFogf`.
#[no_mangle]
pub unsafe extern "C" fn ffvkFogi(ctx: *mut FfvkContext, pname: u32, param: i32) {
    let value = [param];
    fog_entry(ctx, "ffvkFogi", (pname, true), |_| Ok(Values::I(&value)));
}

/// glFogfv: `ffvkFogf`'s names, and `GL_FOG_COLOR` (4 values, clamped to [0, 1]).
/// `GL_INVALID_VALUE` also for a null `params`.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time; `params` is null or points
/// at as many values as `pname` has.
#[no_mangle]
pub unsafe extern "C" fn ffvkFogfv(ctx: *mut FfvkContext, pname: u32, params: *const f32) {
    let f = "ffvkFogfv";
    fog_entry(ctx, f, (pname, false), |n| {
        // SAFETY: the caller's contract on params.
        unsafe { read(f, params, n) }.map(Values::F)
    })
}

/// glFogiv: `ffvkFogfv` with integers (the color's map [-2^31, 2^31 - 1] onto [-1, 1], as GL
/// maps integer colors).
///
/// # Safety
///
/// As `ffvkFogfv`.
#[no_mangle]
pub unsafe extern "C" fn ffvkFogiv(ctx: *mut FfvkContext, pname: u32, params: *const i32) {
    let f = "ffvkFogiv";
    fog_entry(ctx, f, (pname, false), |n| {
        // SAFETY: the caller's contract on params.
        unsafe { read(f, params, n) }.map(Values::I)
    })
}

/// glFogCoordf: the current fog coordinate, every vertex's in draws whose layout has no fog
/// coordinate array (read with `GL_FOG_COORD_SRC` `GL_FOG_COORD`); `GL_INVALID_VALUE` for a
/// value that is not finite (ffvk's choice).
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkFogCoordf(ctx: *mut FfvkContext, coord: f32) {
    const F: &str = "ffvkFogCoordf";
    with_context(ctx, F, |c| c.gl.fog_coord(coord).map_err(|e| state_error(F, e)))
}

/// glHint: `GL_FOG_HINT` `GL_FASTEST` fogs per vertex, `GL_DONT_CARE` and `GL_NICEST` per
/// fragment; GL's other hint targets are accepted and change nothing ffvk draws. Errors:
/// `GL_INVALID_ENUM` for a target or mode GL does not name.
///
/// # Safety
///
/// `ctx` is null or a live context used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkHint(ctx: *mut FfvkContext, target: u32, mode: u32) {
    const F: &str = "ffvkHint";
    with_context(ctx, F, |c| {
        let hint = match mode {
            GL_DONT_CARE => FogHint::DontCare,
            GL_FASTEST => FogHint::Fastest,
            GL_NICEST => FogHint::Nicest,
            other => {
                return Err(invalid_enum(
                    F,
                    "mode",
                    other,
                    "GL_DONT_CARE, GL_FASTEST or GL_NICEST",
                ))
            }
        };
        match target {
            GL_FOG_HINT => c.gl.fog_hint(hint),
            GL_PERSPECTIVE_CORRECTION_HINT
            | GL_POINT_SMOOTH_HINT
            | GL_LINE_SMOOTH_HINT
            | GL_POLYGON_SMOOTH_HINT
            | GL_GENERATE_MIPMAP_HINT
            | GL_TEXTURE_COMPRESSION_HINT
            | GL_FRAGMENT_SHADER_DERIVATIVE_HINT => {}
            other => {
                return Err(invalid_enum(
                    F,
                    "target",
                    other,
                    "GL_FOG_HINT or another of GL 2.1's hint targets",
                ))
            }
        }
        Ok(())
    })
}
