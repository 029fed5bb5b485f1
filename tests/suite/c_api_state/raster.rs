//! The raster state's sequences of the differential test (issue 50): every raster entry point
//! valid and invalid, each followed by every raster query through glGetFloatv, glGetIntegerv
//! and glGetBooleanv, and glIsEnabled of every raster cap.

use super::{Call, Query, Step};

const FRONT: u32 = 0x0404;
const BACK: u32 = 0x0405;
const FRONT_AND_BACK: u32 = 0x0408;
/// GL_LEFT: a GL enum, but no face.
const LEFT: u32 = 0x0406;
const BOGUS: u32 = 0x1234;
const POINT: u32 = 0x1B00;
const LINE: u32 = 0x1B01;
const FILL: u32 = 0x1B02;
const LESS: u32 = 0x0201;
const EQUAL: u32 = 0x0202;
const GREATER: u32 = 0x0204;
const GEQUAL: u32 = 0x0206;
const ZERO: u32 = 0;
const ONE: u32 = 1;
const KEEP: u32 = 0x1E00;
const REPLACE: u32 = 0x1E01;
const INCR: u32 = 0x1E02;
const INVERT: u32 = 0x150A;
const INCR_WRAP: u32 = 0x8507;
const DECR_WRAP: u32 = 0x8508;
const SRC_ALPHA: u32 = 0x0302;
const ONE_MINUS_SRC_ALPHA: u32 = 0x0303;
const DST_COLOR: u32 = 0x0306;
const SRC_ALPHA_SATURATE: u32 = 0x0308;
const CONSTANT_COLOR: u32 = 0x8001;
const ONE_MINUS_CONSTANT_ALPHA: u32 = 0x8004;
const FUNC_SUBTRACT: u32 = 0x800A;
const FUNC_REVERSE_SUBTRACT: u32 = 0x800B;
const MIN: u32 = 0x8007;
const MAX: u32 = 0x8008;
const XOR: u32 = 0x1506;
const NAND: u32 = 0x150E;
const CW: u32 = 0x0900;

/// The raster caps.
pub(super) const CAPS: [u32; 10] = [
    0x8037, // GL_POLYGON_OFFSET_FILL
    0x2A02, // GL_POLYGON_OFFSET_LINE
    0x2A01, // GL_POLYGON_OFFSET_POINT
    0x0B24, // GL_LINE_STIPPLE
    0x0B42, // GL_POLYGON_STIPPLE
    0x0B90, // GL_STENCIL_TEST
    0x0BF2, // GL_COLOR_LOGIC_OP
    0x0BE2, // GL_BLEND
    0x0B71, // GL_DEPTH_TEST
    0x0B44, // GL_CULL_FACE
];

/// Every raster state name with its value count.
const NAMES: [(u32, usize); 41] = [
    (0x0B40, 2), // GL_POLYGON_MODE
    (0x8038, 1), // GL_POLYGON_OFFSET_FACTOR
    (0x2A00, 1), // GL_POLYGON_OFFSET_UNITS
    (0x0B43, 1), // GL_EDGE_FLAG
    (0x0B25, 1), // GL_LINE_STIPPLE_PATTERN
    (0x0B26, 1), // GL_LINE_STIPPLE_REPEAT
    (0x0B70, 2), // GL_DEPTH_RANGE
    (0x0B72, 1), // GL_DEPTH_WRITEMASK
    (0x0B74, 1), // GL_DEPTH_FUNC
    (0x0B91, 1), // GL_STENCIL_CLEAR_VALUE
    (0x0B92, 1), // GL_STENCIL_FUNC
    (0x0B93, 1), // GL_STENCIL_VALUE_MASK
    (0x0B94, 1), // GL_STENCIL_FAIL
    (0x0B95, 1), // GL_STENCIL_PASS_DEPTH_FAIL
    (0x0B96, 1), // GL_STENCIL_PASS_DEPTH_PASS
    (0x0B97, 1), // GL_STENCIL_REF
    (0x0B98, 1), // GL_STENCIL_WRITEMASK
    (0x8800, 1), // GL_STENCIL_BACK_FUNC
    (0x8801, 1), // GL_STENCIL_BACK_FAIL
    (0x8802, 1), // GL_STENCIL_BACK_PASS_DEPTH_FAIL
    (0x8803, 1), // GL_STENCIL_BACK_PASS_DEPTH_PASS
    (0x8CA3, 1), // GL_STENCIL_BACK_REF
    (0x8CA4, 1), // GL_STENCIL_BACK_VALUE_MASK
    (0x8CA5, 1), // GL_STENCIL_BACK_WRITEMASK
    (0x0C23, 4), // GL_COLOR_WRITEMASK
    (0x0BE1, 1), // GL_BLEND_SRC
    (0x0BE0, 1), // GL_BLEND_DST
    (0x80C9, 1), // GL_BLEND_SRC_RGB
    (0x80C8, 1), // GL_BLEND_DST_RGB
    (0x80CB, 1), // GL_BLEND_SRC_ALPHA
    (0x80CA, 1), // GL_BLEND_DST_ALPHA
    (0x8009, 1), // GL_BLEND_EQUATION_RGB
    (0x883D, 1), // GL_BLEND_EQUATION_ALPHA
    (0x8005, 4), // GL_BLEND_COLOR
    (0x0BF0, 1), // GL_LOGIC_OP_MODE
    (0x0B45, 1), // GL_CULL_FACE_MODE
    (0x0B46, 1), // GL_FRONT_FACE
    (0x0B11, 1), // GL_POINT_SIZE
    (0x0B21, 1), // GL_LINE_WIDTH
    (0x0B71, 1), // GL_DEPTH_TEST
    (0x0B90, 1), // GL_STENCIL_TEST
];

/// The sequences: each case's calls, then every name through every query form.
pub(super) fn sequences() -> Vec<(String, Vec<Step>)> {
    use Call::*;
    let cases: Vec<(&str, Vec<Call>)> = vec![
        ("GL's initial raster state", vec![]),
        ("glPolygonMode(GL_FRONT, GL_LINE)", vec![PolygonMode(FRONT, LINE)]),
        ("glPolygonMode(GL_BACK, GL_POINT)", vec![PolygonMode(BACK, POINT)]),
        (
            "glPolygonMode(GL_FRONT_AND_BACK, GL_POINT), then GL_FILL for the front",
            vec![PolygonMode(FRONT_AND_BACK, POINT), PolygonMode(FRONT, FILL)],
        ),
        ("glPolygonMode(GL_LEFT, GL_LINE)", vec![PolygonMode(LEFT, LINE)]),
        ("glPolygonMode(GL_FRONT, bad)", vec![PolygonMode(FRONT, BOGUS)]),
        ("glPolygonOffset(2.5, -1.5)", vec![PolygonOffset(2.5, -1.5)]),
        ("glEdgeFlag(GL_FALSE)", vec![EdgeFlag(0)]),
        ("glLineStipple(3, 0xAAAA)", vec![LineStipple(3, 0xAAAA)]),
        (
            "glLineStipple(0, ..) (clamped to 1)",
            vec![LineStipple(0, 0x1234)],
        ),
        (
            "glLineStipple(1000, ..) (clamped to 256)",
            vec![LineStipple(1000, 0x00FF)],
        ),
        (
            "glLineStipple(-5, ..) (clamped to 1)",
            vec![LineStipple(-5, 0x0F0F)],
        ),
        (
            "glPolygonStipple(a pattern of every byte value)",
            vec![PolygonStipple(
                (0..128u8).map(|b| b.wrapping_mul(37) ^ 0xA5).collect(),
            )],
        ),
        ("glDepthRange(0.25, 0.75)", vec![DepthRange(0.25, 0.75)]),
        ("glDepthRange(-1, 2) (clamped)", vec![DepthRange(-1.0, 2.0)]),
        ("glDepthRange(0.8, 0.2) (reversed)", vec![DepthRange(0.8, 0.2)]),
        (
            "glStencilFunc(GL_EQUAL, 5, 0x0F)",
            vec![StencilFunc(EQUAL, 5, 0x0F)],
        ),
        (
            "glStencilFunc(GL_LESS, 300, ~0) (ref clamped when queried)",
            vec![StencilFunc(LESS, 300, !0)],
        ),
        (
            "glStencilFunc(GL_LESS, -3, 0xFF)",
            vec![StencilFunc(LESS, -3, 0xFF)],
        ),
        ("glStencilFunc(bad)", vec![StencilFunc(BOGUS, 1, 1)]),
        (
            "glStencilFuncSeparate(GL_BACK, GL_GREATER, 2, 7)",
            vec![StencilFuncSeparate(BACK, GREATER, 2, 7)],
        ),
        (
            "glStencilFuncSeparate(GL_LEFT, ..)",
            vec![StencilFuncSeparate(LEFT, GREATER, 2, 7)],
        ),
        (
            "glStencilFuncSeparate(GL_FRONT, bad)",
            vec![StencilFuncSeparate(FRONT, BOGUS, 2, 7)],
        ),
        (
            "glStencilOp(GL_REPLACE, GL_INCR, GL_DECR_WRAP)",
            vec![StencilOp(REPLACE, INCR, DECR_WRAP)],
        ),
        (
            "glStencilOp(GL_KEEP, bad, GL_KEEP)",
            vec![StencilOp(KEEP, BOGUS, KEEP)],
        ),
        (
            "glStencilOpSeparate(GL_FRONT, GL_ZERO, GL_INVERT, GL_INCR_WRAP)",
            vec![StencilOpSeparate(FRONT, ZERO, INVERT, INCR_WRAP)],
        ),
        (
            "glStencilOpSeparate(bad face)",
            vec![StencilOpSeparate(BOGUS, ZERO, INVERT, INCR_WRAP)],
        ),
        ("glStencilMask(0x0F)", vec![StencilMask(0x0F)]),
        (
            "glStencilMaskSeparate(GL_BACK, 3)",
            vec![StencilMaskSeparate(BACK, 3)],
        ),
        (
            "glStencilMaskSeparate(bad face)",
            vec![StencilMaskSeparate(LEFT, 3)],
        ),
        ("glClearStencil(7)", vec![ClearStencil(7)]),
        ("glColorMask(1, 0, 1, 0)", vec![ColorMask([1, 0, 1, 0])]),
        (
            "glColorMask(2, 0, 0, 255) (non-zero is true)",
            vec![ColorMask([2, 0, 0, 255])],
        ),
        ("glDepthMask(GL_FALSE)", vec![DepthMask(0)]),
        ("glDepthFunc(GL_GEQUAL)", vec![DepthFunc(GEQUAL)]),
        ("glDepthFunc(bad)", vec![DepthFunc(BOGUS)]),
        (
            "glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)",
            vec![BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA)],
        ),
        ("glBlendFunc(bad, GL_ONE)", vec![BlendFunc(BOGUS, ONE)]),
        (
            "glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE)",
            vec![BlendFunc(SRC_ALPHA_SATURATE, ONE)],
        ),
        (
            "glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE)",
            vec![BlendFunc(ONE, SRC_ALPHA_SATURATE)],
        ),
        (
            "glBlendFuncSeparate(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_DST_COLOR, GL_ZERO)",
            vec![BlendFuncSeparate([
                CONSTANT_COLOR,
                ONE_MINUS_CONSTANT_ALPHA,
                DST_COLOR,
                ZERO,
            ])],
        ),
        (
            "glBlendFuncSeparate(.., bad alpha)",
            vec![BlendFuncSeparate([ONE, ONE, BOGUS, ONE])],
        ),
        (
            "glBlendEquation(GL_FUNC_SUBTRACT)",
            vec![BlendEquation(FUNC_SUBTRACT)],
        ),
        ("glBlendEquation(GL_MIN)", vec![BlendEquation(MIN)]),
        ("glBlendEquation(bad)", vec![BlendEquation(BOGUS)]),
        (
            "glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX)",
            vec![BlendEquationSeparate(FUNC_REVERSE_SUBTRACT, MAX)],
        ),
        (
            "glBlendEquationSeparate(GL_MAX, bad)",
            vec![BlendEquationSeparate(MAX, BOGUS)],
        ),
        (
            "glBlendColor(0.25, 0.5, 0.75, 1)",
            vec![BlendColor([0.25, 0.5, 0.75, 1.0])],
        ),
        (
            "glBlendColor(-1, 2, 0.5, 0.5) (clamped)",
            vec![BlendColor([-1.0, 2.0, 0.5, 0.5])],
        ),
        ("glLogicOp(GL_XOR)", vec![LogicOp(XOR)]),
        ("glLogicOp(GL_NAND)", vec![LogicOp(NAND)]),
        ("glLogicOp(bad)", vec![LogicOp(BOGUS)]),
        ("glCullFace(GL_FRONT)", vec![CullFace(FRONT)]),
        ("glCullFace(GL_FRONT_AND_BACK)", vec![CullFace(FRONT_AND_BACK)]),
        ("glCullFace(bad)", vec![CullFace(LEFT)]),
        ("glFrontFace(GL_CW)", vec![FrontFace(CW)]),
        ("glFrontFace(bad)", vec![FrontFace(FRONT)]),
        ("glPointSize(4.5)", vec![PointSize(4.5)]),
        ("glPointSize(0) (GL_INVALID_VALUE)", vec![PointSize(0.0)]),
        ("glPointSize(-1) (GL_INVALID_VALUE)", vec![PointSize(-1.0)]),
        ("glLineWidth(2.5)", vec![LineWidth(2.5)]),
        ("glLineWidth(0) (GL_INVALID_VALUE)", vec![LineWidth(0.0)]),
        ("glLineWidth(-2) (GL_INVALID_VALUE)", vec![LineWidth(-2.0)]),
        (
            "every raster cap enabled",
            CAPS.iter().map(|&cap| Enable(cap)).collect(),
        ),
        (
            "every raster cap enabled, then disabled",
            CAPS.iter()
                .map(|&cap| Enable(cap))
                .chain(CAPS.iter().map(|&cap| Disable(cap)))
                .collect(),
        ),
    ];
    cases
        .into_iter()
        .map(|(name, calls)| {
            let mut steps: Vec<Step> = calls.into_iter().map(Step::Call).collect();
            for (pname, n) in NAMES {
                steps.push(Step::Query(Query::GetFloatv(pname, n)));
                steps.push(Step::Query(Query::GetIntegerv(pname, n)));
                steps.push(Step::Query(Query::GetBooleanv(pname, n)));
            }
            steps.extend(CAPS.map(|cap| Step::Query(Query::IsEnabled(cap))));
            steps.push(Step::Query(Query::GetPolygonStipple));
            (name.to_string(), steps)
        })
        .collect()
}
