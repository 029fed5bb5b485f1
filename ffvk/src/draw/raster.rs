//! The fixed-function raster state a draw asks for: culling, depth, blending, point size and
//! line width ([`RasterState`], [`Blend`]), part of each pipeline's key.

use ash::vk;

#[cfg(doc)]
use super::target::Target;

/// A blend equation (`glBlendFuncSeparate`, `glBlendEquationSeparate`) in Vulkan's terms.
///
/// ```
/// use ffvk::ash::vk::{BlendFactor, BlendOp};
/// use ffvk::{Blend, RasterState};
///
/// // glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)
/// let over = RasterState::default().with_blend(Some(Blend::ALPHA));
/// assert_eq!(over.blend, Some(Blend::new(BlendFactor::SRC_ALPHA, BlendFactor::ONE_MINUS_SRC_ALPHA, BlendOp::ADD)));
/// // glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE): add color, keep alpha
/// let add = Blend::separate(
///     (BlendFactor::ONE, BlendFactor::ONE, BlendOp::ADD),
///     (BlendFactor::ZERO, BlendFactor::ONE, BlendOp::ADD),
/// );
/// assert_eq!((add.src_alpha, add.dst_color), (BlendFactor::ZERO, BlendFactor::ONE));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct Blend {
    /// Source factor for RGB.
    pub src_color: vk::BlendFactor,
    /// Destination factor for RGB.
    pub dst_color: vk::BlendFactor,
    /// Equation for RGB.
    pub color_op: vk::BlendOp,
    /// Source factor for alpha.
    pub src_alpha: vk::BlendFactor,
    /// Destination factor for alpha.
    pub dst_alpha: vk::BlendFactor,
    /// Equation for alpha.
    pub alpha_op: vk::BlendOp,
}

impl Blend {
    /// `glBlendFunc(src, dst)` with `glBlendEquation(op)`: the same factors and equation for
    /// color and alpha.
    pub const fn new(src: vk::BlendFactor, dst: vk::BlendFactor, op: vk::BlendOp) -> Self {
        Blend {
            src_color: src,
            dst_color: dst,
            color_op: op,
            src_alpha: src,
            dst_alpha: dst,
            alpha_op: op,
        }
    }

    /// `glBlendFuncSeparate(src_color, dst_color, src_alpha, dst_alpha)` with
    /// `glBlendEquationSeparate(color_op, alpha_op)`.
    pub const fn separate(
        (src_color, dst_color, color_op): (vk::BlendFactor, vk::BlendFactor, vk::BlendOp),
        (src_alpha, dst_alpha, alpha_op): (vk::BlendFactor, vk::BlendFactor, vk::BlendOp),
    ) -> Self {
        Blend {
            src_color,
            dst_color,
            color_op,
            src_alpha,
            dst_alpha,
            alpha_op,
        }
    }

    /// `glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)`, `GL_FUNC_ADD`: the usual
    /// transparency.
    pub const ALPHA: Blend = Blend::new(
        vk::BlendFactor::SRC_ALPHA,
        vk::BlendFactor::ONE_MINUS_SRC_ALPHA,
        vk::BlendOp::ADD,
    );
}

/// The fixed-function state GL keeps beside lighting that Vulkan bakes into a pipeline: part
/// of each draw, and of the key its pipeline is found by. `Default` is GL's initial state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct RasterState {
    /// `GL_CULL_FACE` with `glCullFace`: `NONE` (GL's default: culling disabled).
    pub cull_mode: vk::CullModeFlags,
    /// `glFrontFace`: `COUNTER_CLOCKWISE` is GL's CCW (the default; ffvk's clip-space flip
    /// keeps GL's winding).
    pub front_face: vk::FrontFace,
    /// `GL_DEPTH_TEST`; off by default, as in GL. Needs a depth format in the [`Target`].
    pub depth_test: bool,
    /// `glDepthMask`; on by default. Only written while the depth test is on, as in GL.
    pub depth_write: bool,
    /// `glDepthFunc`; `LESS` by default.
    pub depth_compare: vk::CompareOp,
    /// `GL_BLEND`; `None` (disabled) by default.
    pub blend: Option<Blend>,
    /// `glPointSize`: 1 by default; another size needs the device's `largePoints` and must lie
    /// in its `pointSizeRange`.
    pub point_size: Pixels,
    /// `glLineWidth`: 1 by default; another width needs the device's `wideLines` and must lie
    /// in its `lineWidthRange`.
    pub line_width: Pixels,
}

/// A size in pixels (a point size, a line width), compared and hashed by its bits so that a
/// raster state can key a pipeline.
#[derive(Debug, Clone, Copy)]
pub struct Pixels(pub f32);

impl PartialEq for Pixels {
    fn eq(&self, other: &Self) -> bool {
        self.0.to_bits() == other.0.to_bits()
    }
}

impl Eq for Pixels {}

impl std::hash::Hash for Pixels {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.0.to_bits().hash(state);
    }
}

impl Default for RasterState {
    fn default() -> Self {
        RasterState {
            cull_mode: vk::CullModeFlags::NONE,
            front_face: vk::FrontFace::COUNTER_CLOCKWISE,
            depth_test: false,
            depth_write: true,
            depth_compare: vk::CompareOp::LESS,
            blend: None,
            point_size: Pixels(1.0),
            line_width: Pixels(1.0),
        }
    }
}

impl RasterState {
    /// Sets [`point_size`](RasterState::point_size) (`glPointSize`).
    #[must_use]
    pub fn with_point_size(mut self, size: f32) -> Self {
        self.point_size = Pixels(size);
        self
    }

    /// Sets [`line_width`](RasterState::line_width) (`glLineWidth`).
    #[must_use]
    pub fn with_line_width(mut self, width: f32) -> Self {
        self.line_width = Pixels(width);
        self
    }
}

with_fields!(RasterState {
    /// Sets [`cull_mode`](RasterState::cull_mode) (`glCullFace` with `GL_CULL_FACE` on).
    with_cull_mode => cull_mode: vk::CullModeFlags,
    /// Sets [`front_face`](RasterState::front_face) (`glFrontFace`).
    with_front_face => front_face: vk::FrontFace,
    /// Sets [`depth_test`](RasterState::depth_test) (`GL_DEPTH_TEST`).
    with_depth_test => depth_test: bool,
    /// Sets [`depth_write`](RasterState::depth_write) (`glDepthMask`).
    with_depth_write => depth_write: bool,
    /// Sets [`depth_compare`](RasterState::depth_compare) (`glDepthFunc`).
    with_depth_compare => depth_compare: vk::CompareOp,
    /// Sets [`blend`](RasterState::blend) (`GL_BLEND` and `glBlendFuncSeparate`).
    with_blend => blend: Option<Blend>,
});
