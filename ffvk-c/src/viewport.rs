//! GL's viewport, depth range and scissor box as the Vulkan viewport and scissor the caller
//! sets before a scope (`ffvkViewport`, `ffvkScissor`): `ffvk::gl_viewport` and
//! `ffvk::gl_scissor` behind C.

use ffvk::ash::vk;

use crate::result::{check_ptr, fail, guard, FfvkResult};
use crate::vk_types::*;

/// Writes to `*viewport` the `VkViewport` that puts ffvk's draws where GL's
/// `glViewport(x, y, width, height)` and `glDepthRange(near_val, far_val)` put them, in a
/// color attachment `target_height` pixels high. Set it with `vkCmdSetViewport` between
/// scopes, as GL's state changes. GL counts window rows from the bottom and Vulkan from the
/// top: the result is `x`, `target_height - y - height`, `width`, `height` (positive: ffvk's
/// shaders turn GL's clip space into Vulkan's themselves, so there is no negative-height flip)
/// and depths `near_val`, `far_val`, clamped to [0, 1] as GL clamps them (near may exceed
/// far, as in GL). A layer clamps `width` and `height` to the device's
/// `maxViewportDimensions` first, as GL clamps them to `GL_MAX_VIEWPORT_DIMS`.
///
/// Errors (`FFVK_ERROR_INVALID_ARGUMENT`, `*viewport` unchanged): a null or misaligned
/// `viewport`; a negative `width` or `height` (GL's `GL_INVALID_VALUE`, which keeps the old
/// viewport); a `width` or `height` of 0 (GL draws nothing through an empty viewport, but a
/// `VkViewport` cannot be empty: skip the draws instead); a NaN depth; a `target_height` past
/// `INT32_MAX`.
///
/// # Safety
///
/// `viewport` is null or writable.
#[no_mangle]
#[allow(clippy::too_many_arguments)] // glViewport's four, the target's height, glDepthRange's two, the result
pub unsafe extern "C" fn ffvkViewport(
    x: i32,
    y: i32,
    width: i32,
    height: i32,
    target_height: u32,
    near_val: f64,
    far_val: f64,
    viewport: *mut VkViewport,
) -> FfvkResult {
    const F: &str = "ffvkViewport";
    guard(|| {
        if let Err(code) = check_ptr(F, "viewport", viewport, "where to write the VkViewport") {
            return code;
        }
        // GL clamps the depth range to [0, 1]; a value beyond f32's range clamps as its
        // infinity does, and NaN stays NaN (refused).
        let depth_range = [near_val as f32, far_val as f32];
        match ffvk::gl_viewport(x, y, width, height, target_height, depth_range) {
            Ok(v) => {
                // SAFETY: checked non-null and aligned; writable by the caller's contract.
                unsafe { viewport.write(v) };
                FfvkResult::FFVK_SUCCESS
            }
            Err(e) => fail(FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, format!("{F}: {e}")),
        }
    })
}

/// Writes to `*scissor` the `VkRect2D` that keeps the pixels GL's
/// `glScissor(x, y, width, height)` keeps, in a color attachment of `target_width` x
/// `target_height` pixels: GL's rows `y` .. `y + height` from the bottom are rows
/// `target_height - y - height` .. `target_height - y` from the top. The box is clipped to the
/// target as GL's window clips it, so the result is always a rectangle Vulkan accepts
/// (offsets from 0, no overflow); a box outside the target or of width or height 0 is an empty
/// rectangle, which draws nothing, as in GL. While `GL_SCISSOR_TEST` is off, GL's box is the
/// whole target: pass 0, 0, `target_width`, `target_height`.
///
/// Errors (`FFVK_ERROR_INVALID_ARGUMENT`, `*scissor` unchanged): a null or misaligned
/// `scissor`; a negative `width` or `height` (GL's `GL_INVALID_VALUE`); a target side past
/// `INT32_MAX`.
///
/// # Safety
///
/// `scissor` is null or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkScissor(
    x: i32,
    y: i32,
    width: i32,
    height: i32,
    target_width: u32,
    target_height: u32,
    scissor: *mut VkRect2D,
) -> FfvkResult {
    const F: &str = "ffvkScissor";
    guard(|| {
        if let Err(code) = check_ptr(F, "scissor", scissor, "where to write the VkRect2D") {
            return code;
        }
        let target = vk::Extent2D {
            width: target_width,
            height: target_height,
        };
        match ffvk::gl_scissor(x, y, width, height, target) {
            Ok(rect) => {
                // SAFETY: checked non-null and aligned; writable by the caller's contract.
                unsafe { scissor.write(rect) };
                FfvkResult::FFVK_SUCCESS
            }
            Err(e) => fail(FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, format!("{F}: {e}")),
        }
    })
}
