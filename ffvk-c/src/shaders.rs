//! ffvk's shader library from C: the interface version and each file's text
//! (`ffvkShaderLibraryFile`), for a compiler's include callback or for inlining; `make install-c`
//! installs the same files beside `ffvk.h`, under `ffvk/`. The packers write what the library's
//! shaders read from a context's GL state: the state block (`ffvkPackStateBlock`), a draw's
//! own values (`ffvkPackDrawRecord`) and the specialization constants (`ffvkPackSpecKey`).

use std::ffi::{c_char, c_void, CStr};

use ffvk::gpu::layout::{DrawBlock, DrawRecord, SpecKey, StateBlock};
use ffvk::{PipelineConstants, Topology};

use crate::enums::{enum_name, GL_POINTS, GL_POLYGON};
use crate::gl::FfvkContext;
use crate::result::{check_ptr, fail, guard, FfvkResult};
use crate::vk_types::VkFormat;

/// The shader library's interface version (`FFVK_LIBRARY_VERSION` in `ffvk/state.glsl`): a
/// change of the state block, a function's inputs or outputs, a specialization constant or
/// what the caller defines is a new version.
#[no_mangle]
pub extern "C" fn ffvkShaderLibraryVersion() -> u32 {
    ffvk::shaders::LIBRARY_VERSION
}

/// Writes the text of the library file `name` (as a shader includes it: `"ffvk/lighting.glsl"`)
/// to `*source` and its length in bytes to `*length`. The text is ffvk's, valid for the life
/// of the process, and not NUL-terminated. `FFVK_ERROR_INVALID_ARGUMENT` for a null or
/// misaligned pointer and for a name the library does not have (the message lists its files);
/// `*source` is then null and `*length` 0.
///
/// # Safety
///
/// `name` is null or a NUL-terminated string; `source` and `length` are null or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkShaderLibraryFile(
    name: *const c_char,
    source: *mut *const c_char,
    length: *mut usize,
) -> FfvkResult {
    const F: &str = "ffvkShaderLibraryFile";
    guard(|| {
        if let Err(code) = check_ptr(F, "source", source, "where to write the file's text") {
            return code;
        }
        if let Err(code) = check_ptr(F, "length", length, "where to write the text's length") {
            return code;
        }
        // SAFETY: both checked non-null and aligned; the caller's contract makes them
        // writable. Cleared first, so that a caller reading them after an error reads nothing.
        unsafe {
            *source = std::ptr::null();
            *length = 0;
        }
        if name.is_null() {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{F}: name is a null pointer: expected a file's name, as \"ffvk/lighting.glsl\""),
            );
        }
        // SAFETY: the caller's contract: a NUL-terminated string.
        let given = unsafe { CStr::from_ptr(name) }.to_string_lossy();
        let Some(file) = ffvk::shaders::file(&given) else {
            let names: Vec<&str> = ffvk::shaders::FILES.iter().map(|f| f.name).collect();
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!(
                    "{F}: name {given:?}: the shader library has no such file (expected one of {})",
                    names.join(", ")
                ),
            );
        };
        // SAFETY: checked above; the text is static.
        unsafe {
            *source = file.source.as_ptr().cast();
            *length = file.source.len();
        }
        FfvkResult::FFVK_SUCCESS
    })
}

/// Checks `ctx` and `dst` (non-null, aligned for `T`) and that `size` holds `need` bytes; runs
/// `pack` on the context behind the panic barrier.
///
/// # Safety
///
/// `ctx` is null or a live context; `dst` is null or `size` writable bytes.
unsafe fn pack_into(
    function: &str,
    ctx: *const FfvkContext,
    (dst, size, need): (*mut u8, usize, usize),
    pack: impl FnOnce(&FfvkContext) -> Result<Vec<u8>, FfvkResult>,
) -> FfvkResult {
    guard(|| {
        if let Err(code) = check_ptr(function, "ctx", ctx, "a context from ffvkCreateContext") {
            return code;
        }
        if let Err(code) = check_ptr(
            function,
            "dst",
            dst.cast::<u32>(),
            "where to write the bytes, 4-byte aligned",
        ) {
            return code;
        }
        if size < need {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{function}: size {size}: expected at least {need} bytes"),
            );
        }
        // SAFETY: checked non-null and aligned; the caller's contract: a live context, used by
        // one thread at a time.
        let context = unsafe { &*ctx };
        match pack(context) {
            Ok(bytes) => {
                // SAFETY: `size` >= `need` == bytes.len() writable bytes at dst (the contract).
                unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), dst, bytes.len()) };
                FfvkResult::FFVK_SUCCESS
            }
            Err(code) => code,
        }
    })
}

/// Writes the shader library's state block (`FFVK_STATE_MEMBERS` in `ffvk/state.glsl`, std140)
/// for `ctx`'s state under its projection: 3,488 bytes at `dst`, 4-byte aligned. `size` is the
/// space at `dst`; less than the block is `FFVK_ERROR_INVALID_ARGUMENT`, as a state GL could not
/// draw (the message says why: a positional light with all-zero attenuation, ...).
///
/// # Safety
///
/// `ctx` is null or a live context; `dst` is null or `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn ffvkPackStateBlock(
    ctx: *const FfvkContext,
    dst: *mut c_void,
    size: usize,
) -> FfvkResult {
    const F: &str = "ffvkPackStateBlock";
    let need = std::mem::size_of::<StateBlock>();
    // SAFETY: passed on under the same contract.
    unsafe {
        pack_into(F, ctx, (dst.cast(), size, need), |c| {
            c.gl.lighting.check_drawable().map_err(|e| state_error(F, &e))?;
            Ok(bytemuck::bytes_of(&StateBlock::new(&c.gl.lighting, c.projection)).to_vec())
        })
    }
}

/// Writes a draw's own values for `ctx`'s state and modelview (its materials, current color,
/// normal matrix and the rescale factor: `DrawRecord`, 352 bytes) at `dst`, 4-byte aligned:
/// what `face_material` and `eye_normal` take, in the layout ffvk's own pipelines read. A
/// modelview that cannot be inverted while lighting is `FFVK_ERROR_INVALID_ARGUMENT`.
///
/// # Safety
///
/// `ctx` is null or a live context; `dst` is null or `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn ffvkPackDrawRecord(
    ctx: *const FfvkContext,
    dst: *mut c_void,
    size: usize,
) -> FfvkResult {
    const F: &str = "ffvkPackDrawRecord";
    let need = std::mem::size_of::<DrawRecord>();
    // SAFETY: passed on under the same contract.
    unsafe {
        pack_into(F, ctx, (dst.cast(), size, need), |c| {
            let block = DrawBlock::new(&c.gl.lighting, c.gl.modelview, c.projection)
                .map_err(|e| state_error(F, &e))?;
            Ok(bytemuck::bytes_of(&block.record).to_vec())
        })
    }
}

/// Writes the specialization constants of `ctx`'s state and modelview (`SpecKey`: constant i,
/// a 32-bit value, at byte 4i; 49 of them) at `dst`: the data of a `VkSpecializationInfo`
/// whose map entries take constant i to the caller's ID `FFVK_SPEC_BASE + i`.
///
/// # Safety
///
/// `ctx` is null or a live context; `dst` is null or `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn ffvkPackSpecKey(
    ctx: *const FfvkContext,
    dst: *mut c_void,
    size: usize,
) -> FfvkResult {
    const F: &str = "ffvkPackSpecKey";
    let need = std::mem::size_of::<SpecKey>();
    // SAFETY: passed on under the same contract.
    unsafe {
        pack_into(F, ctx, (dst.cast(), size, need), |c| {
            Ok(bytemuck::bytes_of(&SpecKey::for_draw(&c.gl.lighting, c.gl.modelview)).to_vec())
        })
    }
}

/// Writes the specialization constants of a pipeline of the caller's own that draws `mode`
/// (GL's primitive: `GL_POINTS` for any pipeline that rasterizes points, polygons in
/// `GL_POINT` mode included) into a color attachment of `colorFormat`, with a complete 2D
/// texture bound on the units `bound2d` names and a cube map on those `boundCube` names (a bit
/// per unit), under `ctx`'s state and modelview: `ffvkPackSpecKey`'s values with the
/// pipeline's own set as ffvk sets them in its own pipelines (the point constants from
/// `glPointSize` and `glPointParameter`, the target's alpha bits, the units sampled and
/// applied). Same layout and errors as `ffvkPackSpecKey`; a `mode` that is not one of GL's
/// ten primitive modes, or a bit of `bound2d` or `boundCube` past the last unit, is
/// `FFVK_ERROR_INVALID_ARGUMENT`.
///
/// # Safety
///
/// `ctx` is null or a live context; `dst` is null or `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn ffvkPackSpecKeyForPipeline(
    ctx: *const FfvkContext,
    mode: u32,
    color_format: VkFormat,
    bound2d: u32,
    bound_cube: u32,
    dst: *mut c_void,
    size: usize,
) -> FfvkResult {
    const F: &str = "ffvkPackSpecKeyForPipeline";
    let need = std::mem::size_of::<SpecKey>();
    // SAFETY: passed on under the same contract.
    unsafe {
        pack_into(F, ctx, (dst.cast(), size, need), |c| {
            let topology = match mode {
                GL_POINTS => Topology::PointList,
                m if m <= GL_POLYGON => Topology::TriangleList,
                other => {
                    return Err(fail(
                        FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                        format!(
                            "{F}: mode {} is not one of GL's ten primitive modes: expected GL_POINTS \
                             (0x0000) .. GL_POLYGON (0x0009)",
                            enum_name(other)
                        ),
                    ))
                }
            };
            let units = (1u32 << ffvk::gl::texture::MAX_TEXTURE_UNITS) - 1;
            for (name, bits) in [("bound2d", bound2d), ("boundCube", bound_cube)] {
                if bits & !units != 0 {
                    return Err(fail(
                        FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                        format!(
                            "{F}: {name} 0x{bits:x} names a unit past the last: expected a bit per unit, \
                             within 0x{units:x}"
                        ),
                    ));
                }
            }
            let mut pipeline = PipelineConstants::new(topology, color_format);
            pipeline.point_size = c.gl.raster.point_size;
            pipeline.bound_2d = bound2d;
            pipeline.bound_cube = bound_cube;
            let key = SpecKey::for_pipeline(&c.gl.lighting, c.gl.modelview, &pipeline);
            Ok(bytemuck::bytes_of(&key).to_vec())
        })
    }
}

/// Writes `source` with each `#include "ffvk/..."` replaced by the library file's text (each
/// file once; other `#include` lines left as they are), for a compiler without `#include`
/// (GLSL ES: `ffvk/es.glsl`). `source` is NUL-terminated; the result is written to `dst`, NUL
/// included, where `capacity` bytes fit it, and its length without the NUL to `*length` in any
/// case, so that a first call with `dst` null and `capacity` 0 asks for the size.
/// `FFVK_ERROR_INVALID_ARGUMENT` for a null `source` or `length`, an include the library does
/// not have (the message names its line and lists the files), a malformed `#include`, and a
/// `capacity` too small for the text and its NUL (nothing is then written to `dst`).
///
/// # Safety
///
/// `source` is null or a NUL-terminated string; `dst` is null or `capacity` writable bytes;
/// `length` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkShaderLibraryResolve(
    source: *const c_char,
    dst: *mut c_char,
    capacity: usize,
    length: *mut usize,
) -> FfvkResult {
    const F: &str = "ffvkShaderLibraryResolve";
    guard(|| {
        if let Err(code) = check_ptr(F, "length", length, "where to write the text's length") {
            return code;
        }
        // SAFETY: checked non-null and aligned; writable by the contract.
        unsafe { *length = 0 };
        if source.is_null() {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{F}: source is a null pointer: expected a shader's NUL-terminated text"),
            );
        }
        // SAFETY: the caller's contract: a NUL-terminated string.
        let text = unsafe { CStr::from_ptr(source) }.to_string_lossy();
        let resolved = match ffvk::shaders::resolve(&text) {
            Ok(resolved) => resolved,
            Err(e) => {
                return fail(
                    FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                    format!("{F}: source: {e}"),
                )
            }
        };
        // SAFETY: as above.
        unsafe { *length = resolved.len() };
        if dst.is_null() || capacity < resolved.len() + 1 {
            if dst.is_null() && capacity == 0 {
                return FfvkResult::FFVK_SUCCESS;
            }
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!(
                    "{F}: capacity {capacity}: the resolved text needs {} bytes with its NUL",
                    resolved.len() + 1
                ),
            );
        }
        // SAFETY: `capacity` >= len + 1 writable bytes at dst (the contract).
        unsafe {
            std::ptr::copy_nonoverlapping(resolved.as_ptr(), dst.cast::<u8>(), resolved.len());
            *dst.add(resolved.len()) = 0;
        }
        FfvkResult::FFVK_SUCCESS
    })
}

fn state_error(function: &str, e: &ffvk::gl::state::StateError) -> FfvkResult {
    fail(
        FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
        format!("{function}: {e}"),
    )
}
