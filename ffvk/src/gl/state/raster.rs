//! GL's raster and per-fragment operations state beside lighting ([`RasterGl`], GL 2.1 tables
//! 6.12-6.21 with their initial values): polygon modes and offset, line stipple, point size,
//! line width, culling, the stencil and depth tests, blending, the logic op, the color and
//! depth masks, the depth range and the current edge flag; `GlState`'s entry points for them
//! with GL's errors; and [`RasterGl::to_raster_state`], the one place each of them becomes a
//! draw's [`RasterState`].
//!
//! ```
//! use ffvk::gl::state::{Cap, CompareFunc, Face, GlState, PolygonMode, StencilOp};
//!
//! let mut gl = GlState::new();
//! gl.polygon_mode(Face::Back, PolygonMode::Line);
//! gl.enable(Cap::StencilTest)?;
//! gl.stencil_func(CompareFunc::Equal, 300, 0xFF);
//! gl.stencil_op(StencilOp::Keep, StencilOp::Keep, StencilOp::Incr);
//! gl.color_mask(false, true, true, true);
//! let raster = gl.raster_state()?;
//! let stencil = raster.stencil.expect("the stencil test is on");
//! // GL clamps the reference to the 8-bit stencil buffer's range when it tests.
//! assert_eq!(stencil.front.reference, 255);
//! assert_eq!(raster.polygon_mode.back, ffvk::ash::vk::PolygonMode::LINE);
//! assert!(raster.blend.is_none(), "GL_BLEND is off");
//! // GL_INVALID_VALUE: the size is refused and nothing changes.
//! assert!(gl.point_size(0.0).is_err());
//! assert_eq!(gl.raster.point_size, 1.0);
//! # Ok::<(), ffvk::gl::state::StateError>(())
//! ```

use ash::vk;
use glam::Vec4;

use super::{finite_vec, Cap, CompareFunc, Face, GlState, StateError};
use crate::draw::pipeline::PolygonStipple;
use crate::{Blend, BlendColor, LineStipple, PolygonModes, PolygonOffset, RasterState, Stencil, StencilFace};

/// A GL enum type: its values as `<GL/gl.h>` spells them, for the C API's parameters and queries.
pub trait GlEnum: Sized + Copy + 'static {
    /// The values GL accepts, in words, for messages (`"GL_POINT, GL_LINE or GL_FILL"`).
    const EXPECTED: &'static str;
    /// The value GL names `value`, if any.
    fn from_gl(value: u32) -> Option<Self>;
    /// GL's value (`GL_LINE` is 0x1B01).
    fn gl(self) -> u32;
    /// GL's name (`"GL_LINE"`).
    fn gl_name(self) -> &'static str;
}

/// Declares a GL enum with its GL value and name and the Vulkan value it becomes.
macro_rules! gl_enum {
    ($(#[$doc:meta])* $name:ident => $vk:ty, $expected:literal {
        $($(#[$vdoc:meta])* $variant:ident = $gl:literal $gl_name:literal => $vkv:expr),* $(,)?
    }) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum $name {
            $($(#[$vdoc])* $variant),*
        }

        impl GlEnum for $name {
            const EXPECTED: &'static str = $expected;
            fn from_gl(value: u32) -> Option<Self> {
                match value {
                    $($gl => Some($name::$variant),)*
                    _ => None,
                }
            }
            fn gl(self) -> u32 {
                match self {
                    $($name::$variant => $gl),*
                }
            }
            fn gl_name(self) -> &'static str {
                match self {
                    $($name::$variant => $gl_name),*
                }
            }
        }

        impl $name {
            /// The Vulkan value a draw's [`RasterState`] takes.
            pub fn vk(self) -> $vk {
                match self {
                    $($name::$variant => $vkv),*
                }
            }
        }
    };
}

gl_enum! {
    /// `glPolygonMode`'s mode: how a polygon is rasterized.
    PolygonMode => vk::PolygonMode, "GL_POINT, GL_LINE or GL_FILL" {
        /// `GL_POINT`: its vertices, as points.
        Point = 0x1B00 "GL_POINT" => vk::PolygonMode::POINT,
        /// `GL_LINE`: its edges, as lines.
        Line = 0x1B01 "GL_LINE" => vk::PolygonMode::LINE,
        /// `GL_FILL` (the default): its interior.
        Fill = 0x1B02 "GL_FILL" => vk::PolygonMode::FILL,
    }
}

gl_enum! {
    /// `glStencilOp`'s actions.
    StencilOp => vk::StencilOp,
        "GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP or GL_DECR_WRAP" {
        /// `GL_KEEP` (the default of all three).
        Keep = 0x1E00 "GL_KEEP" => vk::StencilOp::KEEP,
        /// `GL_ZERO`.
        Zero = 0x0000 "GL_ZERO" => vk::StencilOp::ZERO,
        /// `GL_REPLACE`: the reference.
        Replace = 0x1E01 "GL_REPLACE" => vk::StencilOp::REPLACE,
        /// `GL_INCR`, saturating.
        Incr = 0x1E02 "GL_INCR" => vk::StencilOp::INCREMENT_AND_CLAMP,
        /// `GL_DECR`, saturating.
        Decr = 0x1E03 "GL_DECR" => vk::StencilOp::DECREMENT_AND_CLAMP,
        /// `GL_INVERT`: bitwise.
        Invert = 0x150A "GL_INVERT" => vk::StencilOp::INVERT,
        /// `GL_INCR_WRAP`.
        IncrWrap = 0x8507 "GL_INCR_WRAP" => vk::StencilOp::INCREMENT_AND_WRAP,
        /// `GL_DECR_WRAP`.
        DecrWrap = 0x8508 "GL_DECR_WRAP" => vk::StencilOp::DECREMENT_AND_WRAP,
    }
}

gl_enum! {
    /// A blend factor of `glBlendFuncSeparate` (GL 2.1 table 4.2).
    BlendFactor => vk::BlendFactor,
        "GL_ZERO, GL_ONE, GL_[ONE_MINUS_]SRC_COLOR, GL_[ONE_MINUS_]DST_COLOR, GL_[ONE_MINUS_]SRC_ALPHA, \
         GL_[ONE_MINUS_]DST_ALPHA, GL_[ONE_MINUS_]CONSTANT_COLOR, GL_[ONE_MINUS_]CONSTANT_ALPHA or \
         (source only) GL_SRC_ALPHA_SATURATE" {
        /// `GL_ZERO` (the destination's default).
        Zero = 0x0000 "GL_ZERO" => vk::BlendFactor::ZERO,
        /// `GL_ONE` (the source's default).
        One = 0x0001 "GL_ONE" => vk::BlendFactor::ONE,
        /// `GL_SRC_COLOR`.
        SrcColor = 0x0300 "GL_SRC_COLOR" => vk::BlendFactor::SRC_COLOR,
        /// `GL_ONE_MINUS_SRC_COLOR`.
        OneMinusSrcColor = 0x0301 "GL_ONE_MINUS_SRC_COLOR" => vk::BlendFactor::ONE_MINUS_SRC_COLOR,
        /// `GL_SRC_ALPHA`.
        SrcAlpha = 0x0302 "GL_SRC_ALPHA" => vk::BlendFactor::SRC_ALPHA,
        /// `GL_ONE_MINUS_SRC_ALPHA`.
        OneMinusSrcAlpha = 0x0303 "GL_ONE_MINUS_SRC_ALPHA" => vk::BlendFactor::ONE_MINUS_SRC_ALPHA,
        /// `GL_DST_ALPHA`.
        DstAlpha = 0x0304 "GL_DST_ALPHA" => vk::BlendFactor::DST_ALPHA,
        /// `GL_ONE_MINUS_DST_ALPHA`.
        OneMinusDstAlpha = 0x0305 "GL_ONE_MINUS_DST_ALPHA" => vk::BlendFactor::ONE_MINUS_DST_ALPHA,
        /// `GL_DST_COLOR`.
        DstColor = 0x0306 "GL_DST_COLOR" => vk::BlendFactor::DST_COLOR,
        /// `GL_ONE_MINUS_DST_COLOR`.
        OneMinusDstColor = 0x0307 "GL_ONE_MINUS_DST_COLOR" => vk::BlendFactor::ONE_MINUS_DST_COLOR,
        /// `GL_SRC_ALPHA_SATURATE`: a source factor only.
        SrcAlphaSaturate = 0x0308 "GL_SRC_ALPHA_SATURATE" => vk::BlendFactor::SRC_ALPHA_SATURATE,
        /// `GL_CONSTANT_COLOR`: `glBlendColor`'s.
        ConstantColor = 0x8001 "GL_CONSTANT_COLOR" => vk::BlendFactor::CONSTANT_COLOR,
        /// `GL_ONE_MINUS_CONSTANT_COLOR`.
        OneMinusConstantColor = 0x8002 "GL_ONE_MINUS_CONSTANT_COLOR" => vk::BlendFactor::ONE_MINUS_CONSTANT_COLOR,
        /// `GL_CONSTANT_ALPHA`.
        ConstantAlpha = 0x8003 "GL_CONSTANT_ALPHA" => vk::BlendFactor::CONSTANT_ALPHA,
        /// `GL_ONE_MINUS_CONSTANT_ALPHA`.
        OneMinusConstantAlpha = 0x8004 "GL_ONE_MINUS_CONSTANT_ALPHA" => vk::BlendFactor::ONE_MINUS_CONSTANT_ALPHA,
    }
}

gl_enum! {
    /// A blend equation of `glBlendEquationSeparate`.
    BlendEquation => vk::BlendOp,
        "GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN or GL_MAX" {
        /// `GL_FUNC_ADD` (the default).
        FuncAdd = 0x8006 "GL_FUNC_ADD" => vk::BlendOp::ADD,
        /// `GL_FUNC_SUBTRACT`.
        FuncSubtract = 0x800A "GL_FUNC_SUBTRACT" => vk::BlendOp::SUBTRACT,
        /// `GL_FUNC_REVERSE_SUBTRACT`.
        FuncReverseSubtract = 0x800B "GL_FUNC_REVERSE_SUBTRACT" => vk::BlendOp::REVERSE_SUBTRACT,
        /// `GL_MIN`: the factors are not used.
        Min = 0x8007 "GL_MIN" => vk::BlendOp::MIN,
        /// `GL_MAX`: the factors are not used.
        Max = 0x8008 "GL_MAX" => vk::BlendOp::MAX,
    }
}

gl_enum! {
    /// `glLogicOp`'s op (GL 2.1 table 4.3).
    LogicOp => vk::LogicOp, "GL_CLEAR .. GL_SET (0x1500 .. 0x150F)" {
        /// `GL_CLEAR`: 0.
        Clear = 0x1500 "GL_CLEAR" => vk::LogicOp::CLEAR,
        /// `GL_AND`: s ∧ d.
        And = 0x1501 "GL_AND" => vk::LogicOp::AND,
        /// `GL_AND_REVERSE`: s ∧ ¬d.
        AndReverse = 0x1502 "GL_AND_REVERSE" => vk::LogicOp::AND_REVERSE,
        /// `GL_COPY` (the default): s.
        Copy = 0x1503 "GL_COPY" => vk::LogicOp::COPY,
        /// `GL_AND_INVERTED`: ¬s ∧ d.
        AndInverted = 0x1504 "GL_AND_INVERTED" => vk::LogicOp::AND_INVERTED,
        /// `GL_NOOP`: d.
        Noop = 0x1505 "GL_NOOP" => vk::LogicOp::NO_OP,
        /// `GL_XOR`.
        Xor = 0x1506 "GL_XOR" => vk::LogicOp::XOR,
        /// `GL_OR`.
        Or = 0x1507 "GL_OR" => vk::LogicOp::OR,
        /// `GL_NOR`.
        Nor = 0x1508 "GL_NOR" => vk::LogicOp::NOR,
        /// `GL_EQUIV`.
        Equiv = 0x1509 "GL_EQUIV" => vk::LogicOp::EQUIVALENT,
        /// `GL_INVERT`: ¬d.
        Invert = 0x150A "GL_INVERT" => vk::LogicOp::INVERT,
        /// `GL_OR_REVERSE`: s ∨ ¬d.
        OrReverse = 0x150B "GL_OR_REVERSE" => vk::LogicOp::OR_REVERSE,
        /// `GL_COPY_INVERTED`: ¬s.
        CopyInverted = 0x150C "GL_COPY_INVERTED" => vk::LogicOp::COPY_INVERTED,
        /// `GL_OR_INVERTED`: ¬s ∨ d.
        OrInverted = 0x150D "GL_OR_INVERTED" => vk::LogicOp::OR_INVERTED,
        /// `GL_NAND`.
        Nand = 0x150E "GL_NAND" => vk::LogicOp::NAND,
        /// `GL_SET`: all ones.
        Set = 0x150F "GL_SET" => vk::LogicOp::SET,
    }
}

gl_enum! {
    /// `glFrontFace`'s winding of front-facing polygons.
    FrontFace => vk::FrontFace, "GL_CW or GL_CCW" {
        /// `GL_CW`.
        Cw = 0x0900 "GL_CW" => vk::FrontFace::CLOCKWISE,
        /// `GL_CCW` (the default): ffvk's clip-space flip keeps GL's winding.
        Ccw = 0x0901 "GL_CCW" => vk::FrontFace::COUNTER_CLOCKWISE,
    }
}

impl GlEnum for CompareFunc {
    const EXPECTED: &'static str =
        "GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL or GL_ALWAYS";
    fn from_gl(value: u32) -> Option<Self> {
        value
            .checked_sub(0x0200)
            .and_then(|i| CompareFunc::ALL.get(i as usize).copied())
    }
    fn gl(self) -> u32 {
        0x0200 + self.code()
    }
    fn gl_name(self) -> &'static str {
        CompareFunc::gl_name(self)
    }
}

/// The bits of ffvk's stencil buffers (`D32_SFLOAT_S8_UINT`, `D24_UNORM_S8_UINT`): s in GL's
/// [0, 2^s - 1], the range the reference is clamped to.
pub const STENCIL_BITS: u32 = 8;

/// GL's initial stencil masks, "1's" (table 6.20) in the [`STENCIL_BITS`] of the buffer.
pub const STENCIL_ONES: u32 = (1 << STENCIL_BITS) - 1;

/// One face's stencil state (GL 2.1 §4.1.5, table 6.20), GL's initial values by default.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct StencilGl {
    /// `GL_STENCIL_FUNC`; `GL_ALWAYS` by default.
    pub func: CompareFunc,
    /// `GL_STENCIL_REF` as given (0 by default); [`StencilGl::clamped_reference`] is the
    /// value tested and queried.
    pub reference: i32,
    /// `GL_STENCIL_VALUE_MASK` as given; by default [`STENCIL_ONES`], table 6.20's "1's" in
    /// the stencil buffer's bits (as Mesa answers it).
    pub value_mask: u32,
    /// `GL_STENCIL_FAIL` (sfail); `GL_KEEP` by default.
    pub fail: StencilOp,
    /// `GL_STENCIL_PASS_DEPTH_FAIL` (dpfail); `GL_KEEP` by default.
    pub pass_depth_fail: StencilOp,
    /// `GL_STENCIL_PASS_DEPTH_PASS` (dppass); `GL_KEEP` by default.
    pub pass_depth_pass: StencilOp,
    /// `GL_STENCIL_WRITEMASK` as given; [`STENCIL_ONES`] by default.
    pub write_mask: u32,
}

impl Default for StencilGl {
    fn default() -> Self {
        StencilGl {
            func: CompareFunc::Always,
            reference: 0,
            value_mask: STENCIL_ONES,
            fail: StencilOp::Keep,
            pass_depth_fail: StencilOp::Keep,
            pass_depth_pass: StencilOp::Keep,
            write_mask: STENCIL_ONES,
        }
    }
}

impl StencilGl {
    /// The reference GL tests with: clamped to [0, 2^s - 1] (§4.1.5), s = [`STENCIL_BITS`].
    /// The one rule: the draw's stencil state and the `GL_STENCIL_REF` query both take it.
    pub fn clamped_reference(&self) -> u32 {
        self.reference.clamp(0, (1 << STENCIL_BITS) - 1) as u32
    }

    /// This face as a draw's [`StencilFace`].
    pub fn to_face(&self) -> StencilFace {
        StencilFace::default()
            .with_func(
                vk::CompareOp::from_raw(self.func.code() as i32),
                self.clamped_reference(),
                self.value_mask,
            )
            .with_ops(
                self.fail.vk(),
                self.pass_depth_fail.vk(),
                self.pass_depth_pass.vk(),
            )
            .with_write_mask(self.write_mask)
    }
}

/// GL's raster and per-fragment state beside lighting, with GL 2.1's initial values
/// (`Default`): what `glPolygonMode`, `glPolygonOffset`, `glLineStipple`, `glPointSize`,
/// `glLineWidth`, `glCullFace`, `glFrontFace`, the stencil, depth, blend and logic op
/// functions, the masks, `glDepthRange`, `glClearStencil`, `glEdgeFlag` and their caps set.
/// [`RasterGl::to_raster_state`] turns it into a draw's [`RasterState`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct RasterGl {
    /// `GL_POLYGON_MODE`'s front mode; `GL_FILL` by default.
    pub polygon_front: PolygonMode,
    /// `GL_POLYGON_MODE`'s back mode; `GL_FILL` by default.
    pub polygon_back: PolygonMode,
    /// `GL_POLYGON_OFFSET_FACTOR`; 0 by default.
    pub polygon_offset_factor: f32,
    /// `GL_POLYGON_OFFSET_UNITS`; 0 by default.
    pub polygon_offset_units: f32,
    /// `GL_POLYGON_OFFSET_FILL`; off by default.
    pub polygon_offset_fill: bool,
    /// `GL_POLYGON_OFFSET_LINE`; off by default.
    pub polygon_offset_line: bool,
    /// `GL_POLYGON_OFFSET_POINT`; off by default.
    pub polygon_offset_point: bool,
    /// `GL_LINE_STIPPLE`; off by default.
    pub line_stipple: bool,
    /// `GL_LINE_STIPPLE_REPEAT`, in [1, 256] (glLineStipple clamps it); 1 by default.
    pub line_stipple_repeat: u32,
    /// `GL_LINE_STIPPLE_PATTERN`; all ones (0xFFFF) by default.
    pub line_stipple_pattern: u16,
    /// `GL_POLYGON_STIPPLE`; off by default.
    pub polygon_stipple: bool,
    /// glPolygonStipple's pattern as GL unpacks it (default pixel storage: rows of 4 bytes from
    /// the bottom row up, the most significant bit of each byte leftmost); all ones by default.
    pub polygon_stipple_mask: [u8; 128],
    /// The height of the framebuffer draws render into, in pixels (ffvk's; GL knows its
    /// window's): GL counts the polygon stipple's rows from the framebuffer's bottom. `None`
    /// until set; a draw with `GL_POLYGON_STIPPLE` on needs it.
    pub framebuffer_height: Option<u32>,
    /// `GL_STENCIL_TEST`; off by default.
    pub stencil_test: bool,
    /// The front faces' stencil state (also points' and lines').
    pub stencil_front: StencilGl,
    /// The back faces' (`GL_STENCIL_BACK_*`).
    pub stencil_back: StencilGl,
    /// `GL_STENCIL_CLEAR_VALUE` as given; 0 by default.
    pub stencil_clear: i32,
    /// `GL_COLOR_WRITEMASK` (R, G, B, A); all true by default.
    pub color_mask: [bool; 4],
    /// `GL_DEPTH_TEST`; off by default.
    pub depth_test: bool,
    /// `GL_DEPTH_WRITEMASK`; true by default.
    pub depth_mask: bool,
    /// `GL_DEPTH_FUNC`; `GL_LESS` by default.
    pub depth_func: CompareFunc,
    /// `GL_DEPTH_RANGE` (near, far), each clamped to [0, 1] by glDepthRange; (0, 1) by
    /// default. Kept for queries: a draw's depth range is its viewport's (`gl_viewport`).
    pub depth_range: [f64; 2],
    /// `GL_BLEND`; off by default.
    pub blend: bool,
    /// `GL_BLEND_SRC_RGB`; `GL_ONE` by default.
    pub blend_src_rgb: BlendFactor,
    /// `GL_BLEND_DST_RGB`; `GL_ZERO` by default.
    pub blend_dst_rgb: BlendFactor,
    /// `GL_BLEND_SRC_ALPHA`; `GL_ONE` by default.
    pub blend_src_alpha: BlendFactor,
    /// `GL_BLEND_DST_ALPHA`; `GL_ZERO` by default.
    pub blend_dst_alpha: BlendFactor,
    /// `GL_BLEND_EQUATION_RGB`; `GL_FUNC_ADD` by default.
    pub blend_equation_rgb: BlendEquation,
    /// `GL_BLEND_EQUATION_ALPHA`; `GL_FUNC_ADD` by default.
    pub blend_equation_alpha: BlendEquation,
    /// `GL_BLEND_COLOR`, each component clamped to [0, 1] by glBlendColor (GL 2.1); (0, 0,
    /// 0, 0) by default.
    pub blend_color: Vec4,
    /// `GL_COLOR_LOGIC_OP`; off by default.
    pub color_logic_op: bool,
    /// `GL_LOGIC_OP_MODE`; `GL_COPY` by default.
    pub logic_op: LogicOp,
    /// `GL_CULL_FACE`; off by default.
    pub cull_face: bool,
    /// `GL_CULL_FACE_MODE`; `GL_BACK` by default.
    pub cull_face_mode: Face,
    /// `GL_FRONT_FACE`; `GL_CCW` by default.
    pub front_face: FrontFace,
    /// `GL_POINT_SIZE`, > 0; 1 by default.
    pub point_size: f32,
    /// `GL_LINE_WIDTH`, > 0; 1 by default.
    pub line_width: f32,
    /// `GL_EDGE_FLAG`, the current edge flag (glEdgeFlag); true by default. Kept for queries:
    /// a draw's flags are in its indices (`Topology::EdgeFlaggedTriangles`, made from each
    /// vertex's flag by `gl_primitives`' `_edge_flagged` functions).
    pub edge_flag: bool,
}

impl Default for RasterGl {
    fn default() -> Self {
        RasterGl {
            polygon_front: PolygonMode::Fill,
            polygon_back: PolygonMode::Fill,
            polygon_offset_factor: 0.0,
            polygon_offset_units: 0.0,
            polygon_offset_fill: false,
            polygon_offset_line: false,
            polygon_offset_point: false,
            line_stipple: false,
            line_stipple_repeat: 1,
            line_stipple_pattern: 0xFFFF,
            polygon_stipple: false,
            polygon_stipple_mask: [0xFF; 128],
            framebuffer_height: None,
            stencil_test: false,
            stencil_front: StencilGl::default(),
            stencil_back: StencilGl::default(),
            stencil_clear: 0,
            color_mask: [true; 4],
            depth_test: false,
            depth_mask: true,
            depth_func: CompareFunc::Less,
            depth_range: [0.0, 1.0],
            blend: false,
            blend_src_rgb: BlendFactor::One,
            blend_dst_rgb: BlendFactor::Zero,
            blend_src_alpha: BlendFactor::One,
            blend_dst_alpha: BlendFactor::Zero,
            blend_equation_rgb: BlendEquation::FuncAdd,
            blend_equation_alpha: BlendEquation::FuncAdd,
            blend_color: Vec4::ZERO,
            color_logic_op: false,
            logic_op: LogicOp::Copy,
            cull_face: false,
            cull_face_mode: Face::Back,
            front_face: FrontFace::Ccw,
            point_size: 1.0,
            line_width: 1.0,
            edge_flag: true,
        }
    }
}

impl RasterGl {
    /// The enable of a raster cap; `None` for a cap of the lighting state.
    pub fn enabled_mut(&mut self, cap: Cap) -> Option<&mut bool> {
        Some(match cap {
            Cap::PolygonOffsetFill => &mut self.polygon_offset_fill,
            Cap::PolygonOffsetLine => &mut self.polygon_offset_line,
            Cap::PolygonOffsetPoint => &mut self.polygon_offset_point,
            Cap::LineStipple => &mut self.line_stipple,
            Cap::PolygonStipple => &mut self.polygon_stipple,
            Cap::StencilTest => &mut self.stencil_test,
            Cap::ColorLogicOp => &mut self.color_logic_op,
            Cap::Blend => &mut self.blend,
            Cap::DepthTest => &mut self.depth_test,
            Cap::CullFace => &mut self.cull_face,
            _ => return None,
        })
    }

    /// Whether a raster cap is enabled; `None` for a cap of the lighting state.
    pub fn enabled(&self, cap: Cap) -> Option<bool> {
        let mut copy = *self;
        copy.enabled_mut(cap).map(|on| *on)
    }

    /// The draw's raster state under this GL state: each disabled test, blend, logic op,
    /// offset or stipple `None`, culling `NONE` unless `GL_CULL_FACE` is on, the stencil
    /// reference clamped ([`StencilGl::clamped_reference`]). The one place each GL value
    /// becomes Vulkan's. Errors: `GL_POLYGON_STIPPLE` on without the framebuffer's height.
    pub fn to_raster_state(&self) -> Result<RasterState, StateError> {
        let mut r = RasterState::default()
            .with_point_size(self.point_size)
            .with_line_width(self.line_width);
        r.cull_mode = match (self.cull_face, self.cull_face_mode) {
            (false, _) => vk::CullModeFlags::NONE,
            (true, Face::Front) => vk::CullModeFlags::FRONT,
            (true, Face::Back) => vk::CullModeFlags::BACK,
            (true, Face::FrontAndBack) => vk::CullModeFlags::FRONT_AND_BACK,
        };
        r.front_face = self.front_face.vk();
        r.depth_test = self.depth_test;
        r.depth_write = self.depth_mask;
        r.depth_compare = vk::CompareOp::from_raw(self.depth_func.code() as i32);
        r.blend = self.blend.then(|| {
            Blend::separate(
                (
                    self.blend_src_rgb.vk(),
                    self.blend_dst_rgb.vk(),
                    self.blend_equation_rgb.vk(),
                ),
                (
                    self.blend_src_alpha.vk(),
                    self.blend_dst_alpha.vk(),
                    self.blend_equation_alpha.vk(),
                ),
            )
        });
        let offset = [
            self.polygon_offset_fill,
            self.polygon_offset_line,
            self.polygon_offset_point,
        ];
        r.polygon_offset = offset.contains(&true).then_some(PolygonOffset {
            factor: self.polygon_offset_factor,
            units: self.polygon_offset_units,
            fill: self.polygon_offset_fill,
            line: self.polygon_offset_line,
            point: self.polygon_offset_point,
        });
        let channels = [
            vk::ColorComponentFlags::R,
            vk::ColorComponentFlags::G,
            vk::ColorComponentFlags::B,
            vk::ColorComponentFlags::A,
        ];
        r.color_mask = channels
            .into_iter()
            .zip(self.color_mask)
            .filter(|(_, on)| *on)
            .fold(vk::ColorComponentFlags::empty(), |mask, (bit, _)| mask | bit);
        r.blend_color = BlendColor(self.blend_color.to_array());
        r.polygon_mode = PolygonModes {
            front: self.polygon_front.vk(),
            back: self.polygon_back.vk(),
        };
        r.stencil = self.stencil_test.then(|| Stencil {
            front: self.stencil_front.to_face(),
            back: self.stencil_back.to_face(),
        });
        r.logic_op = self.color_logic_op.then(|| self.logic_op.vk());
        r.line_stipple = self.line_stipple.then_some(LineStipple {
            factor: self.line_stipple_repeat,
            pattern: self.line_stipple_pattern,
        });
        if self.polygon_stipple {
            let height = self.framebuffer_height.ok_or(StateError::NoFramebufferHeight)?;
            r.polygon_stipple = Some(PolygonStipple::from_gl_mask(&self.polygon_stipple_mask, height));
        }
        Ok(r)
    }

    /// The stencil faces `face` selects.
    fn stencil_faces(&mut self, face: Face) -> impl Iterator<Item = &mut StencilGl> {
        let (front, back) = (face.includes_front(), face.includes_back());
        [(&mut self.stencil_front, front), (&mut self.stencil_back, back)]
            .into_iter()
            .filter_map(|(s, on)| on.then_some(s))
    }
}

/// A size of glPointSize or glLineWidth: GL's `INVALID_VALUE` at or below 0; a NaN or
/// infinity is refused too (ffvk's choice).
fn positive(parameter: &'static str, value: f32) -> Result<f32, StateError> {
    finite_vec(parameter, &[value])?;
    if value <= 0.0 {
        return Err(StateError::OutOfRange {
            parameter,
            value,
            valid: "a size > 0",
        });
    }
    Ok(value)
}

impl GlState {
    /// GL's raster state as a draw takes it: [`RasterGl::to_raster_state`]. Errors: a polygon
    /// stipple without the framebuffer's height ([`GlState::framebuffer_height`]).
    pub fn raster_state(&self) -> Result<RasterState, StateError> {
        self.raster.to_raster_state()
    }

    /// glPolygonMode: `face`'s polygons are rasterized as `mode`.
    pub fn polygon_mode(&mut self, face: Face, mode: PolygonMode) {
        if face.includes_front() {
            self.raster.polygon_front = mode;
        }
        if face.includes_back() {
            self.raster.polygon_back = mode;
        }
    }

    /// glPolygonOffset: any finite factor and units (a NaN or infinity is refused: ffvk's
    /// choice where GL leaves it undefined).
    pub fn polygon_offset(&mut self, factor: f32, units: f32) -> Result<(), StateError> {
        finite_vec("GL_POLYGON_OFFSET_FACTOR", &[factor])?;
        finite_vec("GL_POLYGON_OFFSET_UNITS", &[units])?;
        self.raster.polygon_offset_factor = factor;
        self.raster.polygon_offset_units = units;
        Ok(())
    }

    /// glPolygonStipple: the 32 × 32 pattern of filled polygons, as GL unpacks `mask` with the
    /// default pixel storage (rows of 4 bytes from the bottom row up, the most significant bit
    /// of each byte leftmost).
    pub fn polygon_stipple(&mut self, mask: &[u8; 128]) {
        self.raster.polygon_stipple_mask = *mask;
    }

    /// The height in pixels of the framebuffer the draws render into (GL knows its window's):
    /// GL counts the polygon stipple's rows from its bottom. Errors: a height of 0.
    pub fn framebuffer_height(&mut self, height: u32) -> Result<(), StateError> {
        if height == 0 {
            return Err(StateError::OutOfRange {
                parameter: "framebuffer height",
                value: 0.0,
                valid: "a height of at least 1 pixel",
            });
        }
        self.raster.framebuffer_height = Some(height);
        Ok(())
    }

    /// glLineStipple: the repeat factor clamped to [1, 256] as GL clamps it, and the pattern.
    pub fn line_stipple(&mut self, factor: i32, pattern: u16) {
        self.raster.line_stipple_repeat = factor.clamp(1, 256) as u32;
        self.raster.line_stipple_pattern = pattern;
    }

    /// glStencilFuncSeparate: `face`'s test, reference (kept as given) and value mask.
    pub fn stencil_func_separate(&mut self, face: Face, func: CompareFunc, reference: i32, mask: u32) {
        for s in self.raster.stencil_faces(face) {
            (s.func, s.reference, s.value_mask) = (func, reference, mask);
        }
    }

    /// glStencilFunc: [`GlState::stencil_func_separate`] for both faces.
    pub fn stencil_func(&mut self, func: CompareFunc, reference: i32, mask: u32) {
        self.stencil_func_separate(Face::FrontAndBack, func, reference, mask);
    }

    /// glStencilOpSeparate: `face`'s actions on a stencil fail, a depth fail and a pass.
    pub fn stencil_op_separate(
        &mut self,
        face: Face,
        fail: StencilOp,
        depth_fail: StencilOp,
        pass: StencilOp,
    ) {
        for s in self.raster.stencil_faces(face) {
            (s.fail, s.pass_depth_fail, s.pass_depth_pass) = (fail, depth_fail, pass);
        }
    }

    /// glStencilOp: [`GlState::stencil_op_separate`] for both faces.
    pub fn stencil_op(&mut self, fail: StencilOp, depth_fail: StencilOp, pass: StencilOp) {
        self.stencil_op_separate(Face::FrontAndBack, fail, depth_fail, pass);
    }

    /// glStencilMaskSeparate: the bits `face`'s fragments may write.
    pub fn stencil_mask_separate(&mut self, face: Face, mask: u32) {
        for s in self.raster.stencil_faces(face) {
            s.write_mask = mask;
        }
    }

    /// glStencilMask: [`GlState::stencil_mask_separate`] for both faces.
    pub fn stencil_mask(&mut self, mask: u32) {
        self.stencil_mask_separate(Face::FrontAndBack, mask);
    }

    /// glClearStencil: the value a stencil clear writes, kept as given (GL masks it to the
    /// buffer's bits when it clears).
    pub fn clear_stencil(&mut self, s: i32) {
        self.raster.stencil_clear = s;
    }

    /// glColorMask: which channels fragments write.
    pub fn color_mask(&mut self, r: bool, g: bool, b: bool, a: bool) {
        self.raster.color_mask = [r, g, b, a];
    }

    /// glDepthMask: whether fragments write depth (while the depth test is on).
    pub fn depth_mask(&mut self, on: bool) {
        self.raster.depth_mask = on;
    }

    /// glDepthFunc.
    pub fn depth_func(&mut self, func: CompareFunc) {
        self.raster.depth_func = func;
    }

    /// glDepthRange: near and far, each clamped to [0, 1] as GL clamps them (near may exceed
    /// far); a NaN is refused (ffvk's choice).
    pub fn depth_range(&mut self, near: f64, far: f64) -> Result<(), StateError> {
        if let Some(&nan) = [near, far].iter().find(|v| v.is_nan()) {
            return Err(StateError::NotFinite {
                parameter: "GL_DEPTH_RANGE",
                value: nan as f32,
                valid: "numbers (clamped to [0, 1])",
            });
        }
        self.raster.depth_range = [near.clamp(0.0, 1.0), far.clamp(0.0, 1.0)];
        Ok(())
    }

    /// glBlendFuncSeparate. `GL_SRC_ALPHA_SATURATE` is a source factor only (GL 2.1 table
    /// 4.2): as a destination it is GL's `INVALID_ENUM` ([`StateError::NotAccepted`]).
    pub fn blend_func_separate(
        &mut self,
        (src_rgb, dst_rgb): (BlendFactor, BlendFactor),
        (src_alpha, dst_alpha): (BlendFactor, BlendFactor),
    ) -> Result<(), StateError> {
        for (parameter, dst) in [("dfactorRGB", dst_rgb), ("dfactorAlpha", dst_alpha)] {
            if dst == BlendFactor::SrcAlphaSaturate {
                return Err(StateError::NotAccepted {
                    parameter,
                    value: dst.gl_name(),
                    valid: "a destination factor (GL_SRC_ALPHA_SATURATE is a source factor only)",
                });
            }
        }
        let r = &mut self.raster;
        (r.blend_src_rgb, r.blend_dst_rgb) = (src_rgb, dst_rgb);
        (r.blend_src_alpha, r.blend_dst_alpha) = (src_alpha, dst_alpha);
        Ok(())
    }

    /// glBlendFunc: [`GlState::blend_func_separate`] with the same factors for color and alpha.
    pub fn blend_func(&mut self, src: BlendFactor, dst: BlendFactor) -> Result<(), StateError> {
        self.blend_func_separate((src, dst), (src, dst))
    }

    /// glBlendEquationSeparate.
    pub fn blend_equation_separate(&mut self, rgb: BlendEquation, alpha: BlendEquation) {
        self.raster.blend_equation_rgb = rgb;
        self.raster.blend_equation_alpha = alpha;
    }

    /// glBlendEquation: the same equation for color and alpha.
    pub fn blend_equation(&mut self, equation: BlendEquation) {
        self.blend_equation_separate(equation, equation);
    }

    /// glBlendColor: each component clamped to [0, 1] as GL 2.1 clamps it; a NaN or infinity
    /// is refused (ffvk's choice).
    pub fn blend_color(&mut self, color: Vec4) -> Result<(), StateError> {
        finite_vec("GL_BLEND_COLOR", color.to_array().as_slice())?;
        self.raster.blend_color = color.clamp(Vec4::ZERO, Vec4::ONE);
        Ok(())
    }

    /// glLogicOp: the op used while `GL_COLOR_LOGIC_OP` is enabled.
    pub fn logic_op(&mut self, op: LogicOp) {
        self.raster.logic_op = op;
    }

    /// glCullFace: the faces culled while `GL_CULL_FACE` is enabled.
    pub fn cull_face(&mut self, face: Face) {
        self.raster.cull_face_mode = face;
    }

    /// glFrontFace.
    pub fn front_face(&mut self, winding: FrontFace) {
        self.raster.front_face = winding;
    }

    /// glPointSize: GL's `INVALID_VALUE` at or below 0.
    pub fn point_size(&mut self, size: f32) -> Result<(), StateError> {
        self.raster.point_size = positive("GL_POINT_SIZE", size)?;
        Ok(())
    }

    /// glLineWidth: GL's `INVALID_VALUE` at or below 0.
    pub fn line_width(&mut self, width: f32) -> Result<(), StateError> {
        self.raster.line_width = positive("GL_LINE_WIDTH", width)?;
        Ok(())
    }

    /// glEdgeFlag: the current edge flag.
    pub fn edge_flag(&mut self, flag: bool) {
        self.raster.edge_flag = flag;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gls_initial_raster_state_is_ffvks_default_raster_state() {
        assert_eq!(RasterGl::default().to_raster_state(), Ok(RasterState::default()));
        let all = RasterGl {
            stencil_test: true,
            ..RasterGl::default()
        };
        let stencil = all.to_raster_state().unwrap().stencil.unwrap();
        let gl = StencilFace::default().with_write_mask(0xFF);
        assert_eq!(stencil.front, gl.with_func(vk::CompareOp::ALWAYS, 0, 0xFF));
    }

    #[test]
    fn every_gl_enum_round_trips_through_its_gl_value() {
        fn check<T: GlEnum + PartialEq + std::fmt::Debug>(all: &[u32]) {
            for &v in all {
                let e = T::from_gl(v).unwrap_or_else(|| panic!("0x{v:04X}"));
                assert_eq!(e.gl(), v);
                assert!(e.gl_name().starts_with("GL_"));
            }
            assert_eq!(T::from_gl(0x1234), None);
        }
        check::<PolygonMode>(&[0x1B00, 0x1B01, 0x1B02]);
        check::<StencilOp>(&[0x1E00, 0, 0x1E01, 0x1E02, 0x1E03, 0x150A, 0x8507, 0x8508]);
        check::<BlendEquation>(&[0x8006, 0x800A, 0x800B, 0x8007, 0x8008]);
        check::<LogicOp>(&(0x1500..=0x150F).collect::<Vec<_>>());
        check::<FrontFace>(&[0x0900, 0x0901]);
        check::<CompareFunc>(&(0x0200..=0x0207).collect::<Vec<_>>());
        let factors: Vec<u32> = [0, 1]
            .into_iter()
            .chain(0x0300..=0x0308)
            .chain(0x8001..=0x8004)
            .collect();
        check::<BlendFactor>(&factors);
        // Vulkan's orders match GL's where ffvk relies on it.
        for (i, op) in (0x1500..=0x150F).enumerate() {
            assert_eq!(LogicOp::from_gl(op).unwrap().vk().as_raw(), i as i32);
        }
    }

    #[test]
    fn only_enabled_state_reaches_the_draw_and_the_reference_is_clamped_to_the_stencil_bits() {
        let mut gl = GlState::new();
        gl.stencil_func_separate(Face::Back, CompareFunc::Less, -4, 0x0F);
        gl.polygon_offset(2.0, 1.0).unwrap();
        gl.line_stipple(1000, 0x00FF);
        gl.cull_face(Face::Front);
        let off = gl.raster_state().unwrap();
        assert_eq!(
            (off.stencil, off.polygon_offset, off.line_stipple, off.cull_mode),
            (None, None, None, vk::CullModeFlags::NONE)
        );
        for cap in [
            Cap::StencilTest,
            Cap::PolygonOffsetLine,
            Cap::LineStipple,
            Cap::CullFace,
        ] {
            gl.enable(cap).unwrap();
        }
        let on = gl.raster_state().unwrap();
        let stencil = on.stencil.unwrap();
        assert_eq!((stencil.back.reference, stencil.back.value_mask), (0, 0x0F));
        assert_eq!(
            stencil.front.value_mask, 0xFF,
            "the stencil buffer's bits of all ones"
        );
        let offset = on.polygon_offset.unwrap();
        assert_eq!((offset.factor, offset.fill, offset.line), (2.0, false, true));
        assert_eq!(on.line_stipple.unwrap().factor, 256, "clamped by glLineStipple");
        assert_eq!(on.cull_mode, vk::CullModeFlags::FRONT);
        gl.color_mask(false, true, false, true);
        assert_eq!(
            gl.raster_state().unwrap().color_mask,
            vk::ColorComponentFlags::G | vk::ColorComponentFlags::A
        );
        on.validate().unwrap();
    }

    #[test]
    fn sizes_at_or_below_zero_and_a_destination_src_alpha_saturate_are_refused_and_change_nothing() {
        let mut gl = GlState::new();
        for size in [0.0, -1.0, f32::NAN] {
            assert!(gl.point_size(size).is_err());
            assert!(gl.line_width(size).is_err());
        }
        let saturate = BlendFactor::SrcAlphaSaturate;
        let err = gl.blend_func(BlendFactor::One, saturate).unwrap_err();
        assert!(err.to_string().contains("GL_SRC_ALPHA_SATURATE"), "{err}");
        gl.blend_func(saturate, BlendFactor::One).unwrap();
        gl.depth_range(-1.0, 2.0).unwrap();
        gl.blend_color(Vec4::new(-1.0, 0.5, 2.0, 1.0)).unwrap();
        assert_eq!(gl.raster.depth_range, [0.0, 1.0]);
        assert_eq!(gl.raster.blend_color, Vec4::new(0.0, 0.5, 1.0, 1.0));
        assert_eq!((gl.raster.point_size, gl.raster.line_width), (1.0, 1.0));
    }
}
