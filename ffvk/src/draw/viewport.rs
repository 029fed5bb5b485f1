//! GL's viewport, depth range and scissor box (`glViewport`, `glDepthRange`, `glScissor`) as
//! the Vulkan viewport and scissor that reproduce GL's window coordinates with ffvk's
//! pipelines: [`gl_viewport`] and [`gl_scissor`].
//!
//! ffvk's vertex shaders turn GL's clip coordinates into Vulkan's with
//! [`VK_FROM_GL_CLIP`](crate::gpu::layout::VK_FROM_GL_CLIP): y negated, z taken from
//! [−w, w] to [0, w]. GL counts window rows from the bottom of the window, Vulkan from the
//! top. For GL's viewport (x, y, w, h), depth range (n, f) and a target H pixels high, a
//! vertex at GL's normalized device coordinates (x_d, y_d, z_d) lands in GL at
//!
//! - column x + (x_d + 1) w / 2,
//! - row y + (y_d + 1) h / 2 from the bottom, which is row H − y − (y_d + 1) h / 2 from the top,
//! - depth n + (f − n) (z_d + 1) / 2,
//!
//! and in Vulkan, whose normalized device coordinates after the shader are
//! (x_d, −y_d, (z_d + 1) / 2), for a viewport (v_x, v_y, v_w, v_h, min, max), at column
//! v_x + (x_d + 1) v_w / 2, row v_y + (1 − y_d) v_h / 2 from the top and depth
//! min + (max − min) (z_d + 1) / 2. The two agree for every vertex when
//!
//! v_x = x, v_y = H − y − h, v_w = w, v_h = h (positive: no flip), min = n, max = f.
//!
//! The scissor box is the same rectangle of pixels counted from the other side: GL's rows
//! y .. y + h from the bottom are rows H − y − h .. H − y from the top.

use ash::vk;

/// A value [`gl_viewport`] or [`gl_scissor`] cannot turn into Vulkan's.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ViewportError {
    /// A negative width or height: GL's `GL_INVALID_VALUE`, which leaves GL's viewport or
    /// scissor box as it was.
    #[error(
        "{field} is {value}: expected 0 or more (a negative {field} is GL_INVALID_VALUE in {gl_function})"
    )]
    Negative {
        /// `glViewport` or `glScissor`.
        gl_function: &'static str,
        /// `width` or `height`.
        field: &'static str,
        /// The value given.
        value: i32,
    },
    /// A viewport of width or height 0: GL draws nothing through it, but Vulkan has no empty
    /// viewport (`VkViewport::width` must be positive and `height` not 0).
    #[error("{field} is 0: expected at least 1 (GL draws nothing through an empty viewport, but a VkViewport cannot be empty: skip the draws instead)")]
    Empty {
        /// `width` or `height`.
        field: &'static str,
    },
    /// A depth range value that is NaN (GL clamps the others to [0, 1]).
    #[error("depth_range [{near}, {far}] holds NaN: expected glDepthRange's near and far values (clamped to [0, 1] as GL clamps them)")]
    DepthRange {
        /// glDepthRange's `nearVal`.
        near: f32,
        /// glDepthRange's `farVal`.
        far: f32,
    },
    /// A target side past what a Vulkan offset (an `int32_t`) can count.
    #[error("target {field} is {value}: expected at most {max} (Vulkan's offsets are int32_t)", max = i32::MAX)]
    Target {
        /// `width` or `height`.
        field: &'static str,
        /// The value given.
        value: u32,
    },
}

fn side(gl_function: &'static str, field: &'static str, value: i32) -> Result<i64, ViewportError> {
    if value < 0 {
        return Err(ViewportError::Negative {
            gl_function,
            field,
            value,
        });
    }
    Ok(i64::from(value))
}

fn target_side(field: &'static str, value: u32) -> Result<i64, ViewportError> {
    if value > i32::MAX as u32 {
        return Err(ViewportError::Target { field, value });
    }
    Ok(i64::from(value))
}

/// The Vulkan viewport that puts ffvk's draws where GL's `glViewport(x, y, width, height)`
/// and `glDepthRange(depth_range[0], depth_range[1])` put them, in a target (the color
/// attachment) `target_height` pixels high: `x`, `width` and `height` unchanged,
/// `y = target_height − y − height` (GL counts rows from the bottom, Vulkan from the top; the
/// height stays positive, since ffvk's shaders flip y themselves), and the depth range as
/// `minDepth`/`maxDepth`, clamped to [0, 1] as GL clamps it (near may exceed far, as in GL).
/// See the module documentation for the derivation.
///
/// GL clamps the width and height to `GL_MAX_VIEWPORT_DIMS`; clamp them to the device's
/// `maxViewportDimensions` first in the same way, and keep the viewport within its
/// `viewportBoundsRange`. Errors: a negative width or height ([`ViewportError::Negative`],
/// GL's `GL_INVALID_VALUE`), a width or height of 0 ([`ViewportError::Empty`]: GL draws
/// nothing, so skip the draws), a NaN depth value, a target taller than `i32::MAX`.
///
/// ```
/// use ffvk::ash::vk;
///
/// // glViewport(0, 0, 320, 240) in the lower left of a 640 × 480 window: Vulkan's rows
/// // 240 .. 480 from the top.
/// let v = ffvk::gl_viewport(0, 0, 320, 240, 480, [0.0, 1.0]).unwrap();
/// assert_eq!((v.x, v.y, v.width, v.height), (0.0, 240.0, 320.0, 240.0));
/// assert_eq!((v.min_depth, v.max_depth), (0.0, 1.0));
/// // glDepthRange(0.5, 2.0): GL clamps far to 1.
/// let v = ffvk::gl_viewport(0, 0, 640, 480, 480, [0.5, 2.0]).unwrap();
/// assert_eq!((v.y, v.min_depth, v.max_depth), (0.0, 0.5, 1.0));
/// // glViewport with a negative width is GL_INVALID_VALUE.
/// let e = ffvk::gl_viewport(0, 0, -1, 240, 480, [0.0, 1.0]).unwrap_err();
/// assert!(e.to_string().contains("width is -1: expected 0 or more"));
/// ```
pub fn gl_viewport(
    x: i32,
    y: i32,
    width: i32,
    height: i32,
    target_height: u32,
    depth_range: [f32; 2],
) -> Result<vk::Viewport, ViewportError> {
    let w = side("glViewport", "width", width)?;
    let h = side("glViewport", "height", height)?;
    for (field, value) in [("width", w), ("height", h)] {
        if value == 0 {
            return Err(ViewportError::Empty { field });
        }
    }
    let [near, far] = depth_range;
    if near.is_nan() || far.is_nan() {
        return Err(ViewportError::DepthRange { near, far });
    }
    let target = target_side("height", target_height)?;
    let top = target - i64::from(y) - h;
    Ok(vk::Viewport {
        x: x as f32,
        y: top as f32,
        width: w as f32,
        height: h as f32,
        min_depth: near.clamp(0.0, 1.0),
        max_depth: far.clamp(0.0, 1.0),
    })
}

/// The Vulkan scissor rectangle that keeps the pixels GL's `glScissor(x, y, width, height)`
/// keeps (with `GL_SCISSOR_TEST` on), in a target (the color attachment) of `target` pixels:
/// GL's rows y .. y + height from the bottom are rows `target.height − y − height` ..
/// `target.height − y` from the top. The box is clipped to the target, as GL's window clips
/// it, so the rectangle is always one Vulkan accepts (offsets from 0, no overflow); a box
/// wholly outside the target, or of width or height 0, becomes an empty rectangle, which
/// draws nothing, as in GL. With the scissor test off, GL's box is the whole target:
/// `gl_scissor(0, 0, width, height, target)`.
///
/// Errors: a negative width or height ([`ViewportError::Negative`], GL's
/// `GL_INVALID_VALUE`), a target side past `i32::MAX`.
///
/// ```
/// use ffvk::ash::vk;
///
/// let target = vk::Extent2D { width: 640, height: 480 };
/// // glScissor(10, 20, 100, 50): rows 20 .. 70 from the bottom are 410 .. 460 from the top.
/// let s = ffvk::gl_scissor(10, 20, 100, 50, target).unwrap();
/// assert_eq!((s.offset.x, s.offset.y, s.extent.width, s.extent.height), (10, 410, 100, 50));
/// // A box reaching past the window's left and top edges is clipped to it.
/// let s = ffvk::gl_scissor(-10, 460, 100, 50, target).unwrap();
/// assert_eq!((s.offset.x, s.offset.y, s.extent.width, s.extent.height), (0, 0, 90, 20));
/// ```
pub fn gl_scissor(
    x: i32,
    y: i32,
    width: i32,
    height: i32,
    target: vk::Extent2D,
) -> Result<vk::Rect2D, ViewportError> {
    let w = side("glScissor", "width", width)?;
    let h = side("glScissor", "height", height)?;
    let target_w = target_side("width", target.width)?;
    let target_h = target_side("height", target.height)?;
    // GL's box in GL's window coordinates (rows from the bottom), clipped to the target.
    let left = i64::from(x).clamp(0, target_w);
    let right = (i64::from(x) + w).clamp(left, target_w);
    let bottom = i64::from(y).clamp(0, target_h);
    let top = (i64::from(y) + h).clamp(bottom, target_h);
    // Each value lies in 0 ..= i32::MAX (the target sides were checked), so the casts are exact.
    Ok(vk::Rect2D {
        offset: vk::Offset2D {
            x: left as i32,
            y: (target_h - top) as i32,
        },
        extent: vk::Extent2D {
            width: (right - left) as u32,
            height: (top - bottom) as u32,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(s: vk::Rect2D) -> (i32, i32, u32, u32) {
        (s.offset.x, s.offset.y, s.extent.width, s.extent.height)
    }

    #[test]
    fn a_viewport_of_the_whole_target_is_the_whole_target_unflipped() {
        let v = gl_viewport(0, 0, 64, 48, 48, [0.0, 1.0]).unwrap();
        assert_eq!((v.x, v.y, v.width, v.height), (0.0, 0.0, 64.0, 48.0));
    }

    #[test]
    fn a_viewport_reaching_past_the_top_starts_above_the_target() {
        // glViewport(48, 30, 20, 30) on a 48-row target: GL's rows 30 .. 60, Vulkan's -12 .. 18.
        let v = gl_viewport(48, 30, 20, 30, 48, [0.0, 1.0]).unwrap();
        assert_eq!((v.x, v.y, v.width, v.height), (48.0, -12.0, 20.0, 30.0));
    }

    #[test]
    fn a_reversed_depth_range_stays_reversed_and_infinities_clamp() {
        let v = gl_viewport(0, 0, 1, 1, 1, [1.0, 0.0]).unwrap();
        assert_eq!((v.min_depth, v.max_depth), (1.0, 0.0));
        let v = gl_viewport(0, 0, 1, 1, 1, [f32::NEG_INFINITY, f32::INFINITY]).unwrap();
        assert_eq!((v.min_depth, v.max_depth), (0.0, 1.0));
    }

    #[test]
    fn a_negative_or_empty_viewport_or_a_nan_depth_is_an_error_naming_the_value() {
        let says = |r: Result<vk::Viewport, ViewportError>, words: &str| {
            let text = r.unwrap_err().to_string();
            assert!(text.contains(words), "{text:?} does not say {words:?}");
        };
        says(
            gl_viewport(0, 0, 4, -3, 8, [0.0, 1.0]),
            "height is -3: expected 0 or more",
        );
        says(
            gl_viewport(0, 0, 0, 3, 8, [0.0, 1.0]),
            "width is 0: expected at least 1",
        );
        says(
            gl_viewport(0, 0, 4, 3, 8, [f32::NAN, 1.0]),
            "depth_range [NaN, 1] holds NaN",
        );
        says(
            gl_viewport(0, 0, 4, 3, u32::MAX, [0.0, 1.0]),
            "target height is 4294967295",
        );
    }

    #[test]
    fn a_scissor_box_is_clipped_to_the_target_and_may_be_empty() {
        let target = vk::Extent2D {
            width: 64,
            height: 48,
        };
        assert_eq!(rect(gl_scissor(0, 0, 64, 48, target).unwrap()), (0, 0, 64, 48));
        // Past the right and the bottom edges.
        assert_eq!(rect(gl_scissor(50, -5, 30, 12, target).unwrap()), (50, 41, 14, 7));
        // Wholly outside, and of width 0.
        assert_eq!(rect(gl_scissor(70, 0, 10, 10, target).unwrap()).2, 0);
        assert_eq!(rect(gl_scissor(0, 60, 10, 10, target).unwrap()).3, 0);
        assert_eq!(rect(gl_scissor(5, 5, 0, 10, target).unwrap()).2, 0);
        // The far ends of i32 neither overflow nor leave the target.
        assert_eq!(
            rect(gl_scissor(i32::MIN, i32::MIN, i32::MAX, i32::MAX, target).unwrap()),
            (0, 48, 0, 0)
        );
        assert_eq!(
            rect(gl_scissor(i32::MAX, i32::MAX, i32::MAX, i32::MAX, target).unwrap()),
            (64, 0, 0, 0)
        );
        let e = gl_scissor(0, 0, -1, 1, target).unwrap_err().to_string();
        assert!(e.contains("GL_INVALID_VALUE in glScissor"), "{e}");
    }
}
