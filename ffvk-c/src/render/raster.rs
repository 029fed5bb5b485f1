//! A draw's raster state as C passes it ([`FfvkRaster`]), GL's defaults for it, and its
//! conversion to ffvk's [`RasterState`] (which checks each value when the draw is staged:
//! [`RasterState::validate`]).

use ffvk::ash::vk;
use ffvk::{Blend, RasterState};

use super::{invalid, FfvkDrawInfo};
use crate::gl::FfvkContext;
use crate::result::{misaligned, FfvkResult};
use crate::vk_types::*;

/// `FfvkDrawInfo::raster_source`: the draw's raster state is its `raster` (the default).
pub const FFVK_RASTER_SOURCE_DRAW: u32 = 0;
/// `FfvkDrawInfo::raster_source`: the draw's raster state is the context's GL raster state at
/// `ffvkDraw` (`ffvkPolygonMode`, `ffvkStencilFunc`, `ffvkColorMask`, `ffvkEnable`, ...).
pub const FFVK_RASTER_SOURCE_CONTEXT: u32 = 1;

/// The raster state a draw is staged with: its `raster`, or the context's GL raster state now
/// (GL's rule: a draw takes the state in force when it is issued).
pub(crate) fn of_draw(
    function: &str,
    draw: &FfvkDrawInfo,
    ctx: &FfvkContext,
) -> Result<RasterState, FfvkResult> {
    match draw.raster_source {
        FFVK_RASTER_SOURCE_DRAW => Ok(raster(&draw.raster)),
        FFVK_RASTER_SOURCE_CONTEXT => context_raster(function, draw.mode, ctx),
        other => Err(invalid(format!(
            "{function}: raster_source {other} is not accepted: expected FFVK_RASTER_SOURCE_DRAW (0) or FFVK_RASTER_SOURCE_CONTEXT (1)"
        ))),
    }
}

/// The context's raster state for a draw of GL mode `mode`. GL stipples filled polygons only: a
/// draw of points or lines, or of polygons drawn as lines or points, needs no framebuffer
/// height for `GL_POLYGON_STIPPLE`; a fill does (`ffvkFramebufferHeight`).
fn context_raster(function: &str, mode: u32, ctx: &FfvkContext) -> Result<RasterState, FfvkResult> {
    use crate::enums::{GL_TRIANGLES, GL_TRIANGLES_ADJACENCY, GL_TRIANGLE_FAN, GL_TRIANGLE_STRIP};
    let state_error = |message: String| crate::result::fail(FfvkResult::FFVK_ERROR_STATE, message);
    match ctx.gl.raster_state() {
        Ok(raster) => Ok(raster),
        Err(ffvk::gl::state::StateError::NoFramebufferHeight) => {
            let mut unstippled = ctx.gl.raster;
            unstippled.polygon_stipple = false;
            let raster = unstippled
                .to_raster_state()
                .map_err(|e| state_error(format!("{function}: {e}")))?;
            let polygons = matches!(
                mode,
                GL_TRIANGLES | GL_TRIANGLE_STRIP | GL_TRIANGLE_FAN | GL_TRIANGLES_ADJACENCY
            );
            let modes = raster.polygon_mode;
            if polygons && (modes.front == vk::PolygonMode::FILL || modes.back == vk::PolygonMode::FILL) {
                Err(state_error(format!(
                    "{function}: GL_POLYGON_STIPPLE is enabled but the context has no framebuffer height: \
                     expected ffvkFramebufferHeight(ctx, height) first (GL counts the stipple's rows \
                     from the framebuffer's bottom)"
                )))
            } else {
                Ok(raster)
            }
        }
        Err(e) => Err(state_error(format!("{function}: {e}"))),
    }
}

/// A draw's fixed-function raster state (GL's glCullFace/glFrontFace, depth and blend state,
/// glPointSize, glLineWidth) in Vulkan's terms. `ffvkRasterDefaults` fills GL's initial
/// values; a zeroed struct is not GL's defaults (depth writes off, depth compare NEVER, sizes
/// 0, which draws refuse). `ffvkDraw` refuses (`FFVK_ERROR_INVALID_ARGUMENT`, naming the field
/// and value) any other value than these: `cull_mode` bits of `VK_CULL_MODE_FRONT_AND_BACK`,
/// `front_face` 0 or 1, `depth_compare` `VK_COMPARE_OP_NEVER` .. `ALWAYS` (0 .. 7), and while
/// blending, factors `VK_BLEND_FACTOR_ZERO` .. `SRC_ALPHA_SATURATE` (0 .. 14; no dual-source
/// factors) and equations `VK_BLEND_OP_ADD` .. `MAX` (0 .. 4).
///
/// It never changes size (`ffvkRasterDefaults` writes it whole, and it lies inside
/// `FfvkDrawInfo`): raster state added later becomes new fields at the end of `FfvkDrawInfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct FfvkRaster {
    /// `GL_CULL_FACE` with glCullFace: `VK_CULL_MODE_NONE` (GL's default) or a face.
    pub cull_mode: VkCullModeFlags,
    /// glFrontFace: `VK_FRONT_FACE_COUNTER_CLOCKWISE` is GL's `GL_CCW` (the default).
    pub front_face: VkFrontFace,
    /// `GL_DEPTH_TEST` (needs a depth format).
    pub depth_test: u8,
    /// glDepthMask (GL's default: true; only while the depth test is on).
    pub depth_write: u8,
    /// glDepthFunc (GL's default: `VK_COMPARE_OP_LESS`).
    pub depth_compare: VkCompareOp,
    /// `GL_BLEND`; the factors and equations below apply when it is non-zero.
    pub blend: u8,
    /// Source factor for RGB.
    pub src_color: VkBlendFactor,
    /// Destination factor for RGB.
    pub dst_color: VkBlendFactor,
    /// Equation for RGB.
    pub color_op: VkBlendOp,
    /// Source factor for alpha.
    pub src_alpha: VkBlendFactor,
    /// Destination factor for alpha.
    pub dst_alpha: VkBlendFactor,
    /// Equation for alpha.
    pub alpha_op: VkBlendOp,
    /// glPointSize, in pixels (1 by default; another size needs `FFVK_FEATURE_LARGE_POINTS`).
    pub point_size: f32,
    /// glLineWidth, in pixels (1 by default; another width needs `FFVK_FEATURE_WIDE_LINES`).
    pub line_width: f32,
}

fn raster(r: &FfvkRaster) -> RasterState {
    let mut state = RasterState::default()
        .with_depth_test(r.depth_test != 0)
        .with_point_size(r.point_size)
        .with_line_width(r.line_width);
    state.cull_mode = r.cull_mode;
    state.front_face = r.front_face;
    state.depth_write = r.depth_write != 0;
    state.depth_compare = r.depth_compare;
    state.blend = (r.blend != 0).then(|| {
        let mut b = Blend::new(r.src_color, r.dst_color, r.color_op);
        b.src_alpha = r.src_alpha;
        b.dst_alpha = r.dst_alpha;
        b.alpha_op = r.alpha_op;
        b
    });
    state
}

/// Fills `raster` with GL's initial raster state: no culling, `GL_CCW` front faces, depth
/// test off with writes on and `GL_LESS`, blending off (factors ONE, ZERO, ADD), point size
/// and line width 1.
///
/// # Safety
///
/// `raster` is null (ignored) or writable.
#[no_mangle]
pub unsafe extern "C" fn ffvkRasterDefaults(raster: *mut FfvkRaster) {
    if raster.is_null() || misaligned(raster) {
        return;
    }
    // SAFETY: checked non-null; the caller's contract makes it writable.
    unsafe { raster.write(raster_defaults()) };
}

/// GL's initial raster state (`ffvkRasterDefaults`): also the default of a draw's raster state.
pub(crate) fn raster_defaults() -> FfvkRaster {
    FfvkRaster {
        cull_mode: vk::CullModeFlags::NONE,
        front_face: vk::FrontFace::COUNTER_CLOCKWISE,
        depth_test: 0,
        depth_write: 1,
        depth_compare: vk::CompareOp::LESS,
        blend: 0,
        src_color: vk::BlendFactor::ONE,
        dst_color: vk::BlendFactor::ZERO,
        color_op: vk::BlendOp::ADD,
        src_alpha: vk::BlendFactor::ONE,
        dst_alpha: vk::BlendFactor::ZERO,
        alpha_op: vk::BlendOp::ADD,
        point_size: 1.0,
        line_width: 1.0,
    }
}
