//! The fixed-function raster state a draw asks for: culling, depth, blending, point size and
//! line width ([`RasterState`], [`Blend`]), part of each pipeline's key.

use ash::vk;

use super::stipple::PolygonStipple;
use crate::error::LightingError;

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
    /// `glPolygonOffset` with the modes it is enabled for: `None` (all three off) by
    /// default. Polygons only: lines and points drawn as such are never offset.
    pub polygon_offset: Option<PolygonOffset>,
    /// `glColorMask`: the channels written, all four by default (`VK_COLOR_COMPONENT_R_BIT` ..
    /// `A_BIT`). A masked channel keeps what the image held; tests still run.
    pub color_mask: vk::ColorComponentFlags,
    /// `glBlendColor`: the constant the `CONSTANT_*` blend factors read, (0, 0, 0, 0) by
    /// default, each in [0, 1] (GL clamps it there).
    pub blend_color: BlendColor,
    /// `glPolygonMode`: how front- and back-facing polygons are rasterized, `FILL` for both
    /// by default. `LINE` and `POINT` need the device's `fillModeNonSolid`. Where the two
    /// differ, ffvk draws the polygons twice, once with the back faces culled in the front
    /// mode and once with the front faces culled in the back mode: each polygon is drawn once,
    /// in its face's mode, but overlapping polygons of one draw may reach the framebuffer in
    /// another order than GL's (seen only where they blend or tie in depth).
    pub polygon_mode: PolygonModes,
    /// `GL_STENCIL_TEST` with `glStencilFuncSeparate`, `glStencilOpSeparate` and
    /// `glStencilMaskSeparate`: `None` (off) by default. Needs a depth format with stencil in
    /// the [`Target`].
    pub stencil: Option<Stencil>,
    /// `GL_COLOR_LOGIC_OP` with `glLogicOp`: `None` (off) by default. Needs the device's
    /// `logicOp` and a UNORM color format; replaces blending while on, as in GL.
    pub logic_op: Option<vk::LogicOp>,
    /// `GL_LINE_STIPPLE` with `glLineStipple`: `None` (off) by default. Needs
    /// `VK_EXT_line_rasterization`'s stippled Bresenham lines.
    pub line_stipple: Option<LineStipple>,
    /// `GL_POLYGON_STIPPLE` with `glPolygonStipple`: `None` (off) by default. Filled polygons
    /// only; keys the pipeline by its pattern.
    pub polygon_stipple: Option<PolygonStipple>,
}

/// `glPolygonMode`'s two modes, `FILL`, `LINE` or `POINT` each.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct PolygonModes {
    /// `GL_FRONT`'s mode.
    pub front: vk::PolygonMode,
    /// `GL_BACK`'s mode.
    pub back: vk::PolygonMode,
}

impl PolygonModes {
    /// `glPolygonMode(GL_FRONT_AND_BACK, mode)`.
    pub const fn both(mode: vk::PolygonMode) -> Self {
        PolygonModes {
            front: mode,
            back: mode,
        }
    }

    /// GL's default: both faces filled.
    pub const FILL: PolygonModes = PolygonModes::both(vk::PolygonMode::FILL);
}

impl Default for PolygonModes {
    fn default() -> Self {
        PolygonModes::FILL
    }
}

/// One face's stencil state (GL 2.1 §4.1.5): the test `(reference & value_mask) func
/// (stencil & value_mask)`, what each outcome writes, and the bits that may be written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct StencilFace {
    /// `glStencilFunc`'s func: `ALWAYS` by default.
    pub func: vk::CompareOp,
    /// `glStencilFunc`'s ref: 0 by default (GL clamps it to [0, 2^s - 1] when it tests).
    pub reference: u32,
    /// `glStencilFunc`'s mask: all ones by default.
    pub value_mask: u32,
    /// `glStencilOp`'s sfail: `KEEP` by default.
    pub fail: vk::StencilOp,
    /// `glStencilOp`'s dpfail: `KEEP` by default.
    pub depth_fail: vk::StencilOp,
    /// `glStencilOp`'s dppass: `KEEP` by default.
    pub pass: vk::StencilOp,
    /// `glStencilMask`: all ones by default.
    pub write_mask: u32,
}

impl Default for StencilFace {
    fn default() -> Self {
        StencilFace {
            func: vk::CompareOp::ALWAYS,
            reference: 0,
            value_mask: u32::MAX,
            fail: vk::StencilOp::KEEP,
            depth_fail: vk::StencilOp::KEEP,
            pass: vk::StencilOp::KEEP,
            write_mask: u32::MAX,
        }
    }
}

with_fields!(StencilFace {
    /// Sets [`func`](StencilFace::func), [`reference`](StencilFace::reference) and
    /// [`value_mask`](StencilFace::value_mask) at once through [`StencilFace::with_func`].
    with_compare => func: vk::CompareOp,
    /// Sets [`write_mask`](StencilFace::write_mask) (`glStencilMask`).
    with_write_mask => write_mask: u32,
});

impl StencilFace {
    /// `glStencilFunc(func, reference, value_mask)`.
    #[must_use]
    pub fn with_func(mut self, func: vk::CompareOp, reference: u32, value_mask: u32) -> Self {
        (self.func, self.reference, self.value_mask) = (func, reference, value_mask);
        self
    }

    /// `glStencilOp(fail, depth_fail, pass)`.
    #[must_use]
    pub fn with_ops(mut self, fail: vk::StencilOp, depth_fail: vk::StencilOp, pass: vk::StencilOp) -> Self {
        (self.fail, self.depth_fail, self.pass) = (fail, depth_fail, pass);
        self
    }
}

/// The stencil test's state for each face (`glStencilFuncSeparate` and its kin); a polygon's
/// facing picks one, points and lines take the front's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Stencil {
    /// The front faces' (and points' and lines').
    pub front: StencilFace,
    /// The back faces'.
    pub back: StencilFace,
}

impl Stencil {
    /// The same state for both faces (`glStencilFunc`, `glStencilOp`, `glStencilMask`).
    pub const fn both(face: StencilFace) -> Self {
        Stencil {
            front: face,
            back: face,
        }
    }
}

/// `glLineStipple(factor, pattern)`: bit `(c / factor) mod 16` of `pattern` says whether the
/// line's c-th fragment is drawn, c counting from each line's (or strip's) start.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct LineStipple {
    /// The repeat factor, 1 ..= 256 (GL clamps it there).
    pub factor: u32,
    /// The 16-bit pattern, least significant bit first.
    pub pattern: u16,
}

/// `glBlendColor`'s RGBA, compared and hashed by its bits.
#[derive(Debug, Clone, Copy, Default)]
pub struct BlendColor(pub [f32; 4]);

impl PartialEq for BlendColor {
    fn eq(&self, other: &Self) -> bool {
        self.0.map(f32::to_bits) == other.0.map(f32::to_bits)
    }
}

impl Eq for BlendColor {}

impl std::hash::Hash for BlendColor {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.0.map(f32::to_bits).hash(state);
    }
}

/// `glPolygonOffset(factor, units)` with `GL_POLYGON_OFFSET_FILL`, `_LINE` and `_POINT`: a
/// polygon rasterized in an enabled mode ([`RasterState::polygon_mode`]) has its depth moved by
/// o = m · factor + r · units (GL 2.1 §3.5.5), m its depth slope and r the depth format's
/// smallest resolvable step; Vulkan's depth bias with slope factor `factor` and constant factor
/// `units` (and no clamp, as GL 2.1 has none). Points and lines drawn as such are never
/// offset. Compared and hashed by its bits.
#[derive(Debug, Clone, Copy)]
pub struct PolygonOffset {
    /// The slope factor.
    pub factor: f32,
    /// The constant, in units of r.
    pub units: f32,
    /// `GL_POLYGON_OFFSET_FILL`: filled polygons are offset.
    pub fill: bool,
    /// `GL_POLYGON_OFFSET_LINE`: polygons drawn as outlines (`glPolygonMode` `GL_LINE`) are.
    pub line: bool,
    /// `GL_POLYGON_OFFSET_POINT`: polygons drawn as vertices (`GL_POINT`) are.
    pub point: bool,
}

impl PolygonOffset {
    /// `glPolygonOffset(factor, units)` with `GL_POLYGON_OFFSET_FILL` on (and `_LINE`,
    /// `_POINT` off).
    pub const fn fill(factor: f32, units: f32) -> Self {
        PolygonOffset {
            factor,
            units,
            fill: true,
            line: false,
            point: false,
        }
    }

    /// Whether a polygon rasterized in `mode` is offset.
    pub fn offsets(&self, mode: vk::PolygonMode) -> bool {
        match mode {
            vk::PolygonMode::LINE => self.line,
            vk::PolygonMode::POINT => self.point,
            _ => self.fill,
        }
    }

    fn bits(&self) -> (u32, u32, bool, bool, bool) {
        (
            self.factor.to_bits(),
            self.units.to_bits(),
            self.fill,
            self.line,
            self.point,
        )
    }
}

impl PartialEq for PolygonOffset {
    fn eq(&self, other: &Self) -> bool {
        self.bits() == other.bits()
    }
}

impl Eq for PolygonOffset {}

impl std::hash::Hash for PolygonOffset {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.bits().hash(state);
    }
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
            polygon_offset: None,
            color_mask: vk::ColorComponentFlags::RGBA,
            blend_color: BlendColor::default(),
            polygon_mode: PolygonModes::FILL,
            stencil: None,
            logic_op: None,
            line_stipple: None,
            polygon_stipple: None,
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

/// The part of a raster state ffvk sets as dynamic state when it records a draw, rather than
/// baking it into the draw's pipeline (Vulkan 1.3 core: culling, front face, the depth test,
/// the stencil test, the depth bias, line width and blend constants). Draws that differ only
/// here share a pipeline.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct DynamicRaster {
    pub(crate) cull_mode: vk::CullModeFlags,
    pub(crate) front_face: vk::FrontFace,
    pub(crate) depth_test: bool,
    /// Depth writes: `glDepthMask`, only while the depth test is on.
    pub(crate) depth_write: bool,
    pub(crate) depth_compare: vk::CompareOp,
    /// The depth bias (constant, slope), where the polygon offset applies to the pass.
    pub(crate) depth_bias: Option<(f32, f32)>,
    pub(crate) stencil: Option<Stencil>,
    pub(crate) line_width: f32,
    pub(crate) blend_color: [f32; 4],
}

impl RasterState {
    /// The state a pipeline is found by, with every dynamic part at GL's default, and the
    /// dynamic part, set when the draw is recorded. Call on a pass's state
    /// ([`RasterState::face_passes`]): its offset applies as it is.
    pub(crate) fn split_dynamic(&self) -> (RasterState, DynamicRaster) {
        let d = RasterState::default();
        // Polygons drawn as lines or points keep their front face in the key: the geometry
        // stage of GL's edge flags finds their facing itself (glsl/edges.geom).
        let front_face = if self.polygon_mode == PolygonModes::FILL {
            d.front_face
        } else {
            self.front_face
        };
        let keyed = RasterState {
            cull_mode: d.cull_mode,
            front_face,
            depth_test: d.depth_test,
            depth_write: d.depth_write,
            depth_compare: d.depth_compare,
            polygon_offset: d.polygon_offset,
            stencil: d.stencil,
            line_width: d.line_width,
            blend_color: d.blend_color,
            ..*self
        };
        let dynamic = DynamicRaster {
            cull_mode: self.cull_mode,
            front_face: self.front_face,
            depth_test: self.depth_test,
            depth_write: self.depth_test && self.depth_write,
            depth_compare: self.depth_compare,
            depth_bias: self.polygon_offset.map(|o| (o.units, o.factor)),
            stencil: self.stencil,
            line_width: self.line_width.0,
            blend_color: self.blend_color.0,
        };
        (keyed, dynamic)
    }

    /// Whether the state has none of the stencil test, a logic op, a polygon mode other than
    /// fill and a line stipple: what the Renderer's deferred path (which lights a G-buffer's
    /// pixels, not fragments) can take.
    pub(crate) fn only_fills_and_blends(&self) -> bool {
        self.stencil.is_none()
            && self.logic_op.is_none()
            && self.polygon_mode == PolygonModes::FILL
            && self.line_stipple.is_none()
            && self.polygon_stipple.is_none()
    }

    /// The raster state of each pass a draw of `triangles` (or, if not, of points or lines)
    /// takes: one, or two where `glPolygonMode` gives the faces different modes and culling
    /// keeps both (the front faces in their mode with the back ones culled, then the back
    /// faces in theirs). Each has one polygon mode for both faces, and state that cannot
    /// apply is dropped: points and lines have no polygon mode and no offset, and an offset
    /// not enabled for a pass's mode is off in it.
    pub fn face_passes(&self, triangles: bool) -> (RasterState, Option<RasterState>) {
        if !triangles {
            let plain = RasterState {
                polygon_mode: PolygonModes::FILL,
                polygon_offset: None,
                polygon_stipple: None,
                ..*self
            };
            return (plain, None);
        }
        let in_mode = |mode: vk::PolygonMode, cull: vk::CullModeFlags| RasterState {
            polygon_mode: PolygonModes::both(mode),
            polygon_offset: self.polygon_offset.filter(|o| o.offsets(mode)),
            polygon_stipple: self.polygon_stipple.filter(|_| mode == vk::PolygonMode::FILL),
            cull_mode: cull,
            ..*self
        };
        let PolygonModes { front, back } = self.polygon_mode;
        let cull = self.cull_mode;
        if front == back || cull == vk::CullModeFlags::FRONT_AND_BACK {
            return (in_mode(front, cull), None);
        }
        if cull == vk::CullModeFlags::FRONT {
            return (in_mode(back, cull), None);
        }
        if cull == vk::CullModeFlags::BACK {
            return (in_mode(front, cull), None);
        }
        (
            in_mode(front, vk::CullModeFlags::BACK),
            Some(in_mode(back, vk::CullModeFlags::FRONT)),
        )
    }
}

/// Blend factors ffvk passes to Vulkan: `ZERO` (0) .. `SRC_ALPHA_SATURATE` (14), GL 2.1's
/// and `glBlendColor`'s (constant 0, GL's default). The dual-source `SRC1_*` factors (15 ..
/// 18) need a second shader output and a device feature, neither of which ffvk has.
const BLEND_FACTORS: std::ops::RangeInclusive<i32> = 0..=14;
/// Blend equations: `ADD`, `SUBTRACT`, `REVERSE_SUBTRACT`, `MIN`, `MAX` (GL's five).
const BLEND_OPS: std::ops::RangeInclusive<i32> = 0..=4;

impl RasterState {
    /// Checks that every Vulkan enum of the state is one ffvk passes on: `cull_mode` only
    /// `FRONT` and `BACK` bits, `front_face` `COUNTER_CLOCKWISE` or `CLOCKWISE`,
    /// `depth_compare` `NEVER` .. `ALWAYS`, and, when blending, factors `ZERO` ..
    /// `SRC_ALPHA_SATURATE` and equations `ADD` .. `MAX`. Errors name the field and the value.
    /// (Sizes are checked against the device when the draw's pipeline is made.)
    pub fn validate(&self) -> Result<(), LightingError> {
        let refuse = |field, value: String, expected| {
            Err(LightingError::RasterEnum {
                field,
                value,
                expected,
            })
        };
        let cull = self.cull_mode.as_raw();
        if cull & !vk::CullModeFlags::FRONT_AND_BACK.as_raw() != 0 {
            return refuse(
                "cull_mode",
                format!("0x{cull:X}"),
                "VK_CULL_MODE_NONE, FRONT_BIT, BACK_BIT or FRONT_AND_BACK (bits 0x3)",
            );
        }
        if !(0..=1).contains(&self.front_face.as_raw()) {
            return refuse(
                "front_face",
                self.front_face.as_raw().to_string(),
                "VK_FRONT_FACE_COUNTER_CLOCKWISE (0) or VK_FRONT_FACE_CLOCKWISE (1)",
            );
        }
        if !(0..=7).contains(&self.depth_compare.as_raw()) {
            return refuse(
                "depth_compare",
                self.depth_compare.as_raw().to_string(),
                "a VkCompareOp, VK_COMPARE_OP_NEVER (0) .. VK_COMPARE_OP_ALWAYS (7)",
            );
        }
        let mask = self.color_mask.as_raw();
        if mask & !vk::ColorComponentFlags::RGBA.as_raw() != 0 {
            return refuse(
                "color_mask",
                format!("0x{mask:X}"),
                "VK_COLOR_COMPONENT_R_BIT, G, B and A_BIT (bits 0xF)",
            );
        }
        if let Some(o) = self.polygon_offset {
            if !(o.factor.is_finite() && o.units.is_finite()) {
                return refuse(
                    "polygon_offset",
                    format!("factor {}, units {}", o.factor, o.units),
                    "finite numbers",
                );
            }
        }
        if !self.blend_color.0.iter().all(|c| (0.0..=1.0).contains(c)) {
            return refuse(
                "blend_color",
                format!("{:?}", self.blend_color.0),
                "four values in [0, 1] (glBlendColor clamps them there)",
            );
        }
        for (face, mode) in [
            ("polygon_mode.front", self.polygon_mode.front),
            ("polygon_mode.back", self.polygon_mode.back),
        ] {
            if !(0..=2).contains(&mode.as_raw()) {
                return refuse(
                    face,
                    mode.as_raw().to_string(),
                    "VK_POLYGON_MODE_FILL (0), LINE (1) or POINT (2)",
                );
            }
        }
        if let Some(s) = self.stencil {
            for (field, f) in [("stencil.front", s.front), ("stencil.back", s.back)] {
                if !(0..=7).contains(&f.func.as_raw()) {
                    return refuse(
                        field,
                        format!("func {}", f.func.as_raw()),
                        "a VkCompareOp, VK_COMPARE_OP_NEVER (0) .. VK_COMPARE_OP_ALWAYS (7)",
                    );
                }
                for (what, op) in [("fail", f.fail), ("depth_fail", f.depth_fail), ("pass", f.pass)] {
                    if !(0..=7).contains(&op.as_raw()) {
                        return refuse(
                            field,
                            format!("{what} {}", op.as_raw()),
                            "a VkStencilOp, VK_STENCIL_OP_KEEP (0) .. VK_STENCIL_OP_DECREMENT_AND_WRAP (7)",
                        );
                    }
                }
            }
        }
        if let Some(op) = self.logic_op {
            if !(0..=15).contains(&op.as_raw()) {
                return refuse(
                    "logic_op",
                    op.as_raw().to_string(),
                    "a VkLogicOp, VK_LOGIC_OP_CLEAR (0) .. VK_LOGIC_OP_SET (15)",
                );
            }
        }
        if let Some(l) = self.line_stipple {
            if !(1..=256).contains(&l.factor) {
                return refuse(
                    "line_stipple",
                    format!("factor {}", l.factor),
                    "a factor of 1 to 256 (glLineStipple clamps it there)",
                );
            }
        }
        if let Some(s) = self.polygon_stipple {
            if s.framebuffer_height == 0 {
                return refuse(
                    "polygon_stipple",
                    "framebuffer_height 0".to_owned(),
                    "the framebuffer's height in pixels (GL counts the pattern's rows from its bottom)",
                );
            }
        }
        let Some(b) = self.blend else { return Ok(()) };
        for (field, factor) in [
            ("src_color", b.src_color),
            ("dst_color", b.dst_color),
            ("src_alpha", b.src_alpha),
            ("dst_alpha", b.dst_alpha),
        ] {
            if !BLEND_FACTORS.contains(&factor.as_raw()) {
                return refuse(
                    field,
                    factor.as_raw().to_string(),
                    "a VkBlendFactor, VK_BLEND_FACTOR_ZERO (0) .. VK_BLEND_FACTOR_SRC_ALPHA_SATURATE (14); the dual-source SRC1 factors are not supported",
                );
            }
        }
        for (field, op) in [("color_op", b.color_op), ("alpha_op", b.alpha_op)] {
            if !BLEND_OPS.contains(&op.as_raw()) {
                return refuse(
                    field,
                    op.as_raw().to_string(),
                    "VK_BLEND_OP_ADD (0), SUBTRACT, REVERSE_SUBTRACT, MIN or VK_BLEND_OP_MAX (4)",
                );
            }
        }
        Ok(())
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
    /// Sets [`polygon_offset`](RasterState::polygon_offset) (`GL_POLYGON_OFFSET_FILL` and
    /// `glPolygonOffset`).
    with_polygon_offset => polygon_offset: Option<PolygonOffset>,
    /// Sets [`color_mask`](RasterState::color_mask) (`glColorMask`).
    with_color_mask => color_mask: vk::ColorComponentFlags,
    /// Sets [`blend_color`](RasterState::blend_color) (`glBlendColor`).
    with_blend_color => blend_color: BlendColor,
    /// Sets [`polygon_mode`](RasterState::polygon_mode) (`glPolygonMode`).
    with_polygon_mode => polygon_mode: PolygonModes,
    /// Sets [`stencil`](RasterState::stencil) (`GL_STENCIL_TEST` and its state).
    with_stencil => stencil: Option<Stencil>,
    /// Sets [`logic_op`](RasterState::logic_op) (`GL_COLOR_LOGIC_OP` and `glLogicOp`).
    with_logic_op => logic_op: Option<vk::LogicOp>,
    /// Sets [`line_stipple`](RasterState::line_stipple) (`GL_LINE_STIPPLE` and
    /// `glLineStipple`).
    with_line_stipple => line_stipple: Option<LineStipple>,
    /// Sets [`polygon_stipple`](RasterState::polygon_stipple) (`GL_POLYGON_STIPPLE` and
    /// `glPolygonStipple`).
    with_polygon_stipple => polygon_stipple: Option<PolygonStipple>,
});
