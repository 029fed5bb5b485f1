//! The C API's boundary, probed as a hostile C caller probes it: every entry point called
//! through its `extern "C"` function with null, misaligned, unknown, non-finite and
//! out-of-range arguments. The promise under test (ffvk.h): nothing crosses the boundary
//! unsafely. No panic unwinds into C, a null or misaligned pointer is refused rather than
//! followed, a call GL would refuse sets GL's error and changes nothing, and every refusal
//! leaves a message naming the function, the parameter, the value and what was expected.
//!
//! No Vulkan device is used: the renderer's entry points are probed up to the checks that
//! come before Vulkan is touched (the loader given here counts its calls and must never be
//! called).

use std::ffi::{c_char, CStr};
use std::mem::size_of;
use std::ptr::{null, null_mut, NonNull};
use std::sync::atomic::{AtomicUsize, Ordering};

use ffvk::ash::vk::{self, Handle};
use ffvk_c::gl::*;
use ffvk_c::mesh::*;
use ffvk_c::query::*;
use ffvk_c::render::*;
use ffvk_c::result::{ffvkResultMessage, FfvkResult};
use ffvk_c::viewport::{ffvkScissor, ffvkViewport};

// GL's enums, as <GL/gl.h> spells them (checked against the header's list below).
const NO_ERROR: u32 = 0;
const INVALID_ENUM: u32 = 0x0500;
const INVALID_VALUE: u32 = 0x0501;
const LIGHTING: u32 = 0x0B50;
const LIGHT0: u32 = 0x4000;
const COLOR_MATERIAL: u32 = 0x0B57;
const NORMALIZE: u32 = 0x0BA1;
const RESCALE_NORMAL: u32 = 0x803A;
const TEXTURE_2D: u32 = 0x0DE1;
/// Base internal formats (glTexImage2D's internalformat).
const ALPHA: u32 = 0x1906;
const RGBA: u32 = 0x1908;
const LUMINANCE: u32 = 0x1909;
const INTENSITY: u32 = 0x8049;
const BLEND: u32 = 0x0BE2;
/// GL_DITHER: a cap ffvk does not keep.
const DITHER: u32 = 0x0BD0;
const AMBIENT: u32 = 0x1200;
const DIFFUSE: u32 = 0x1201;
const SPECULAR: u32 = 0x1202;
const POSITION: u32 = 0x1203;
const SPOT_DIRECTION: u32 = 0x1204;
const SPOT_EXPONENT: u32 = 0x1205;
const SPOT_CUTOFF: u32 = 0x1206;
const CONSTANT_ATTENUATION: u32 = 0x1207;
const LINEAR_ATTENUATION: u32 = 0x1208;
const QUADRATIC_ATTENUATION: u32 = 0x1209;
const EMISSION: u32 = 0x1600;
const SHININESS: u32 = 0x1601;
const AMBIENT_AND_DIFFUSE: u32 = 0x1602;
const COLOR_INDEXES: u32 = 0x1603;
const FRONT: u32 = 0x0404;
const BACK: u32 = 0x0405;
const FRONT_AND_BACK: u32 = 0x0408;
const LIGHT_MODEL_LOCAL_VIEWER: u32 = 0x0B51;
const LIGHT_MODEL_TWO_SIDE: u32 = 0x0B52;
const LIGHT_MODEL_AMBIENT: u32 = 0x0B53;
const LIGHT_MODEL_COLOR_CONTROL: u32 = 0x81F8;
const SINGLE_COLOR: u32 = 0x81F9;
const SEPARATE_SPECULAR_COLOR: u32 = 0x81FA;
const SHADE_MODEL: u32 = 0x0B54;
const FLAT: u32 = 0x1D00;
const SMOOTH: u32 = 0x1D01;
const COLOR_MATERIAL_FACE: u32 = 0x0B55;
const COLOR_MATERIAL_PARAMETER: u32 = 0x0B56;
const CURRENT_COLOR: u32 = 0x0B00;
const CURRENT_NORMAL: u32 = 0x0B02;
const CURRENT_TEXTURE_COORDS: u32 = 0x0B03;
const MAX_LIGHTS: u32 = 0x0D31;
const MODELVIEW_MATRIX: u32 = 0x0BA6;
const PROJECTION_MATRIX: u32 = 0x0BA7;
const TEXTURE_MATRIX: u32 = 0x0BA8;
const TEXTURE_ENV: u32 = 0x2300;
const TEXTURE_ENV_MODE: u32 = 0x2200;
const TEXTURE_ENV_COLOR: u32 = 0x2201;
const MODULATE: u32 = 0x2100;
const REPLACE: u32 = 0x1E01;
const POINTS: u32 = 0x0000;
const LINES: u32 = 0x0001;
const LINE_LOOP: u32 = 0x0002;
const LINE_STRIP: u32 = 0x0003;
const TRIANGLES: u32 = 0x0004;
const TRIANGLE_STRIP: u32 = 0x0005;
const TRIANGLE_FAN: u32 = 0x0006;
const QUADS: u32 = 0x0007;
const QUAD_STRIP: u32 = 0x0008;
const POLYGON: u32 = 0x0009;
/// Not in GL 2.1's <GL/gl.h> for any lighting entry point (nor any enum at all).
const BOGUS: u32 = 0x1234;
/// GL_LEFT: a real GL enum, but not a material face.
const LEFT: u32 = 0x0406;
const COMBINE_RGB: u32 = 0x8571;
const COMBINE_ALPHA: u32 = 0x8572;
const RGB_SCALE: u32 = 0x8573;
const ALPHA_SCALE: u32 = 0x0D1C;
const SRC0_RGB: u32 = 0x8580;
const SRC0_ALPHA: u32 = 0x8588;
const OPERAND0_RGB: u32 = 0x8590;
const OPERAND0_ALPHA: u32 = 0x8598;
const DOT3_RGB: u32 = 0x86AE;
const DOT3_RGBA: u32 = 0x86AF;
const TEXTURE: u32 = 0x1702;
const SRC_COLOR: u32 = 0x0300;
const ONE_MINUS_SRC_COLOR: u32 = 0x0301;
/// GL_TEXTURE0: the first texture unit (glActiveTexture, glMultiTexCoord), and unit 0's texel
/// as a `GL_COMBINE` source (ARB_texture_env_crossbar); ffvk has four units.
const TEXTURE0: u32 = 0x84C0;
const ACTIVE_TEXTURE: u32 = 0x84E0;
const MAX_TEXTURE_UNITS: u32 = 0x84E2;
const MAX_TEXTURE_COORDS: u32 = 0x8871;
const POINT_SPRITE: u32 = 0x8861;
const COORD_REPLACE: u32 = 0x8862;
const S: u32 = 0x2000;
const T: u32 = 0x2001;
const R: u32 = 0x2002;
const Q: u32 = 0x2003;
const TEXTURE_GEN_MODE: u32 = 0x2500;
const OBJECT_PLANE: u32 = 0x2501;
const EYE_PLANE: u32 = 0x2502;
const EYE_LINEAR: u32 = 0x2400;
const OBJECT_LINEAR: u32 = 0x2401;
const SPHERE_MAP: u32 = 0x2402;
const NORMAL_MAP: u32 = 0x8511;
const REFLECTION_MAP: u32 = 0x8512;
const TEXTURE_GEN_S: u32 = 0x0C60;
const TEXTURE_GEN_R: u32 = 0x0C62;
const TEXTURE_GEN_Q: u32 = 0x0C63;

/// What a query buffer holds before the call: a query that answers overwrites it.
const SENTINEL_F: f32 = -12345.5;
const SENTINEL_I: i32 = -0x5A5A5A5A;
const SENTINEL_B: u8 = 0xA5;

/// This thread's last message (`ffvkResultMessage`), never null.
fn message() -> String {
    let text = ffvkResultMessage();
    assert!(!text.is_null(), "ffvkResultMessage returned null");
    // SAFETY: ffvkResultMessage returns a NUL-terminated string, valid until the next ffvk
    // call on this thread; it is copied at once.
    unsafe { CStr::from_ptr(text) }.to_string_lossy().into_owned()
}

/// Asserts that `text` contains each of `words`.
#[track_caller]
fn assert_names(text: &str, words: &[&str]) {
    for word in words {
        assert!(text.contains(word), "the message {text:?} does not name {word:?}");
    }
}

/// `0x1234`: how messages show a value GL has no name for (and the value after a name).
fn hex(value: u32) -> String {
    format!("0x{value:04X}")
}

/// `GL_QUADS (0x0007)`: how messages show a primitive mode.
fn mode_named(mode: u32) -> String {
    let names = [
        "GL_POINTS",
        "GL_LINES",
        "GL_LINE_LOOP",
        "GL_LINE_STRIP",
        "GL_TRIANGLES",
        "GL_TRIANGLE_STRIP",
        "GL_TRIANGLE_FAN",
        "GL_QUADS",
        "GL_QUAD_STRIP",
        "GL_POLYGON",
    ];
    format!("{} ({})", names[mode as usize], hex(mode))
}

/// Makes each call as C writes it, then asserts on the context `$c` that it was refused with
/// `$error` (and then `GL_NO_ERROR`), that the message names the function called and each
/// of the words, and that nothing changed since the snapshot `$before`.
macro_rules! assert_each_refused {
    ($c:expr, $before:expr, $error:expr, $words:expr, {
        $($f:ident($($arg:expr),* $(,)?);)*
    }) => {{
        let words: &[&str] = &$words;
        $(
            $f($($arg),*);
            $c.assert_refused(&$before, $error, &[&[stringify!($f)], words].concat());
        )*
    }};
}

/// Makes each call as C writes it and asserts it returned `FFVK_ERROR_INVALID_ARGUMENT` with
/// a message naming the function called and each of the words.
macro_rules! assert_each_invalid_argument {
    ($words:expr, {
        $($f:ident($($arg:expr),* $(,)?);)*
    }) => {{
        let words: &[&str] = &$words;
        $(
            let result = $f($($arg),*);
            let text = message();
            assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{}: {text}", stringify!($f));
            assert_names(&text, &[&[stringify!($f)], words].concat());
        )*
    }};
}

/// A pointer one byte past `p`: the address a C caller gets from a packed struct or a byte
/// buffer's odd offset, never aligned for a 4-byte type.
fn misaligned<T>(p: *const T) -> *const T {
    p.cast::<u8>().wrapping_add(1).cast()
}

/// One answered query, every value's bits (so -0, NaN and sentinels compare exactly).
type Snapshot = Vec<(String, Vec<u32>)>;

/// A context of `ffvkCreateContext`, destroyed on drop.
struct Ctx(*mut FfvkContext);

impl Drop for Ctx {
    fn drop(&mut self) {
        // SAFETY: the context came from ffvkCreateContext and is not used after this.
        unsafe { ffvkDestroyContext(self.0) };
    }
}

/// The names `ffvkGetFloatv` answers (GL_LIGHTi added by [`Ctx::snapshot`]).
const GET_NAMES: &[u32] = &[
    0x0B40, // GL_POLYGON_MODE
    0x8038, // GL_POLYGON_OFFSET_FACTOR
    0x2A00, // GL_POLYGON_OFFSET_UNITS
    0x8037, // GL_POLYGON_OFFSET_FILL
    0x0B43, // GL_EDGE_FLAG
    0x0B24, // GL_LINE_STIPPLE
    0x0B25, // GL_LINE_STIPPLE_PATTERN
    0x0B26, // GL_LINE_STIPPLE_REPEAT
    0x0B70, // GL_DEPTH_RANGE
    0x0B71, // GL_DEPTH_TEST
    0x0B72, // GL_DEPTH_WRITEMASK
    0x0B74, // GL_DEPTH_FUNC
    0x0B90, // GL_STENCIL_TEST
    0x0B91, // GL_STENCIL_CLEAR_VALUE
    0x0B92, // GL_STENCIL_FUNC
    0x0B93, // GL_STENCIL_VALUE_MASK
    0x0B94, // GL_STENCIL_FAIL
    0x0B96, // GL_STENCIL_PASS_DEPTH_PASS
    0x0B97, // GL_STENCIL_REF
    0x0B98, // GL_STENCIL_WRITEMASK
    0x8800, // GL_STENCIL_BACK_FUNC
    0x8802, // GL_STENCIL_BACK_PASS_DEPTH_FAIL
    0x8CA3, // GL_STENCIL_BACK_REF
    0x8CA5, // GL_STENCIL_BACK_WRITEMASK
    0x0C23, // GL_COLOR_WRITEMASK
    BLEND,
    0x80C9, // GL_BLEND_SRC_RGB
    0x80C8, // GL_BLEND_DST_RGB
    0x80CB, // GL_BLEND_SRC_ALPHA
    0x80CA, // GL_BLEND_DST_ALPHA
    0x8009, // GL_BLEND_EQUATION_RGB
    0x883D, // GL_BLEND_EQUATION_ALPHA
    0x8005, // GL_BLEND_COLOR
    0x0BF2, // GL_COLOR_LOGIC_OP
    0x0BF0, // GL_LOGIC_OP_MODE
    0x0B44, // GL_CULL_FACE
    0x0B45, // GL_CULL_FACE_MODE
    0x0B46, // GL_FRONT_FACE
    0x0B11, // GL_POINT_SIZE
    0x0B21, // GL_LINE_WIDTH
    0x0B60, // GL_FOG
    0x0B62, // GL_FOG_DENSITY
    0x0B63, // GL_FOG_START
    0x0B64, // GL_FOG_END
    0x0B65, // GL_FOG_MODE
    0x0B66, // GL_FOG_COLOR
    0x8450, // GL_FOG_COORD_SRC
    0x8453, // GL_CURRENT_FOG_COORD
    0x8459, // GL_CURRENT_SECONDARY_COLOR
    0x0BC0, // GL_ALPHA_TEST
    0x0BC1, // GL_ALPHA_TEST_FUNC
    0x0BC2, // GL_ALPHA_TEST_REF
    0x8458, // GL_COLOR_SUM
    CURRENT_NORMAL,
    CURRENT_TEXTURE_COORDS,
    LIGHTING,
    COLOR_MATERIAL,
    NORMALIZE,
    RESCALE_NORMAL,
    TEXTURE_2D,
    LIGHT_MODEL_AMBIENT,
    LIGHT_MODEL_LOCAL_VIEWER,
    LIGHT_MODEL_TWO_SIDE,
    LIGHT_MODEL_COLOR_CONTROL,
    SHADE_MODEL,
    COLOR_MATERIAL_FACE,
    COLOR_MATERIAL_PARAMETER,
    CURRENT_COLOR,
    MAX_LIGHTS,
    MODELVIEW_MATRIX,
    PROJECTION_MATRIX,
    TEXTURE_MATRIX,
    ACTIVE_TEXTURE,
    MAX_TEXTURE_UNITS,
    MAX_TEXTURE_COORDS,
];
const LIGHT_PNAMES: [u32; 10] = [
    AMBIENT,
    DIFFUSE,
    SPECULAR,
    POSITION,
    SPOT_DIRECTION,
    SPOT_EXPONENT,
    SPOT_CUTOFF,
    CONSTANT_ATTENUATION,
    LINEAR_ATTENUATION,
    QUADRATIC_ATTENUATION,
];
const MATERIAL_PNAMES: [u32; 6] = [AMBIENT, DIFFUSE, SPECULAR, EMISSION, SHININESS, COLOR_INDEXES];

impl Ctx {
    /// A context in GL's initial state.
    fn new() -> Ctx {
        let ctx = ffvkCreateContext();
        assert!(!ctx.is_null(), "ffvkCreateContext: {}", message());
        Ctx(ctx)
    }

    /// A context with every queryable value away from GL's default, so a refused call that
    /// reset anything to a default would show in a snapshot.
    fn busy() -> Ctx {
        let c = Ctx::new();
        let x = c.0;
        let scale: [f32; 16] = [2., 0., 0., 0., 0., 3., 0., 0., 0., 0., 4., 0., 1., 2., 3., 1.];
        let shear: [f32; 16] = [1., 0.5, 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., 0., -2., 1.];
        // SAFETY: a live context; every pointer points at as many values as its name takes.
        unsafe {
            ffvkEnable(x, LIGHTING);
            ffvkEnable(x, LIGHT0 + 1);
            ffvkEnable(x, LIGHT0 + 15);
            ffvkEnable(x, NORMALIZE);
            ffvkEnable(x, TEXTURE_2D);
            for (i, l) in [0u32, 1, 15].into_iter().enumerate() {
                let k = i as f32 + 1.0;
                ffvkLightfv(x, LIGHT0 + l, AMBIENT, [0.1 * k, 0.2, 0.3, 0.4].as_ptr());
                ffvkLightfv(x, LIGHT0 + l, DIFFUSE, [0.5, 0.6 * k, 0.7, 0.8].as_ptr());
                ffvkLightfv(x, LIGHT0 + l, SPECULAR, [0.9, 0.8, 0.7 * k, 0.6].as_ptr());
                ffvkLightfv(x, LIGHT0 + l, POSITION, [1.0, 2.0 * k, 3.0, 1.0].as_ptr());
                ffvkLightfv(x, LIGHT0 + l, SPOT_DIRECTION, [0.0, -1.0, 0.5 * k].as_ptr());
                ffvkLightf(x, LIGHT0 + l, SPOT_EXPONENT, 5.0 * k);
                ffvkLightf(x, LIGHT0 + l, SPOT_CUTOFF, 40.0 + k);
                ffvkLightf(x, LIGHT0 + l, CONSTANT_ATTENUATION, 2.0 * k);
                ffvkLightf(x, LIGHT0 + l, LINEAR_ATTENUATION, 0.5 * k);
                ffvkLightf(x, LIGHT0 + l, QUADRATIC_ATTENUATION, 0.25 * k);
            }
            ffvkMaterialfv(x, FRONT, AMBIENT, [0.3, 0.2, 0.1, 0.9].as_ptr());
            ffvkMaterialfv(x, FRONT, DIFFUSE, [0.4, 0.5, 0.6, 0.7].as_ptr());
            ffvkMaterialfv(x, BACK, SPECULAR, [0.7, 0.6, 0.5, 0.4].as_ptr());
            ffvkMaterialfv(x, FRONT_AND_BACK, EMISSION, [0.05, 0.1, 0.15, 1.0].as_ptr());
            ffvkMaterialf(x, FRONT, SHININESS, 17.0);
            ffvkMaterialf(x, BACK, SHININESS, 33.0);
            ffvkMaterialfv(x, FRONT, COLOR_INDEXES, [1.0, 2.0, 3.0].as_ptr());
            ffvkMaterialfv(x, BACK, COLOR_INDEXES, [4.0, 5.0, 6.0].as_ptr());
            ffvkLightModelfv(x, LIGHT_MODEL_AMBIENT, [0.3, 0.3, 0.4, 1.0].as_ptr());
            ffvkLightModeli(x, LIGHT_MODEL_LOCAL_VIEWER, 1);
            ffvkLightModeli(x, LIGHT_MODEL_TWO_SIDE, 1);
            ffvkLightModeli(x, LIGHT_MODEL_COLOR_CONTROL, SEPARATE_SPECULAR_COLOR as i32);
            ffvkTexEnvi(x, TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32);
            ffvkTexEnvfv(x, TEXTURE_ENV, TEXTURE_ENV_COLOR, [0.25, 0.5, 0.75, 1.0].as_ptr());
            ffvkTexEnvi(x, TEXTURE_ENV, COMBINE_RGB, DOT3_RGBA as i32);
            ffvkTexEnvi(x, TEXTURE_ENV, COMBINE_ALPHA, REPLACE as i32);
            ffvkTexEnvi(x, TEXTURE_ENV, SRC0_RGB + 1, TEXTURE as i32);
            ffvkTexEnvi(x, TEXTURE_ENV, OPERAND0_RGB, ONE_MINUS_SRC_COLOR as i32);
            ffvkTexEnvf(x, TEXTURE_ENV, RGB_SCALE, 2.0);
            ffvkTexEnvf(x, TEXTURE_ENV, ALPHA_SCALE, 4.0);
            ffvkColorMaterial(x, BACK, SPECULAR);
            ffvkColor4f(x, 0.3, 0.6, 0.9, 0.5);
            ffvkShadeModel(x, FLAT);
            ffvkLoadModelview(x, scale.as_ptr());
            ffvkLoadProjection(x, shear.as_ptr());
            ffvkLoadTextureMatrix(x, scale.as_ptr());
            ffvkEnable(x, TEXTURE_GEN_S);
            ffvkEnable(x, TEXTURE_GEN_R);
            ffvkTexGeni(x, S, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32);
            ffvkTexGeni(x, T, TEXTURE_GEN_MODE, SPHERE_MAP as i32);
            ffvkTexGeni(x, R, TEXTURE_GEN_MODE, REFLECTION_MAP as i32);
            ffvkTexGenfv(x, S, OBJECT_PLANE, [0.5, -1.0, 2.0, 0.25].as_ptr());
            ffvkTexGenfv(x, Q, OBJECT_PLANE, [1.0, 2.0, 3.0, 4.0].as_ptr());
            ffvkTexGendv(x, T, EYE_PLANE, [0.0, 1.5, -0.5, 3.0].as_ptr());
            ffvkTexGeniv(x, R, EYE_PLANE, [4, 0, -2, 1].as_ptr());
            for cap in [0x8037, 0x0B24, 0x0B71, 0x0B90, BLEND, 0x0BF2, 0x0B44] {
                ffvkEnable(x, cap);
            }
            ffvkPolygonMode(x, BACK, 0x1B01);
            ffvkPolygonOffset(x, 1.5, -2.0);
            ffvkEdgeFlag(x, 0);
            ffvkLineStipple(x, 3, 0x0F0F);
            ffvkDepthRange(x, 0.25, 0.75);
            ffvkDepthMask(x, 0);
            ffvkDepthFunc(x, 0x0203);
            ffvkStencilFuncSeparate(x, FRONT, 0x0202, 7, 0x3F);
            ffvkStencilFuncSeparate(x, BACK, 0x0205, 9, 0x1F);
            ffvkStencilOpSeparate(x, FRONT, 0x1E01, 0x1E02, 0x150A);
            ffvkStencilOpSeparate(x, BACK, 0, 0x8507, 0x8508);
            ffvkStencilMaskSeparate(x, BACK, 0x0F);
            ffvkClearStencil(x, 5);
            ffvkColorMask(x, 1, 0, 1, 0);
            ffvkBlendFuncSeparate(x, 0x0302, 0x0303, 0x8001, 0x8004);
            ffvkBlendEquationSeparate(x, 0x800A, 0x8008);
            ffvkBlendColor(x, 0.25, 0.5, 0.75, 1.0);
            ffvkLogicOp(x, 0x1506);
            ffvkCullFace(x, FRONT_AND_BACK);
            ffvkFrontFace(x, 0x0900);
            ffvkPointSize(x, 3.0);
            ffvkLineWidth(x, 2.0);
            // Units 1 to 3 away from their defaults too, each its own way; unit 0 active again.
            for unit in 1..4u32 {
                let k = unit as f32;
                ffvkActiveTexture(x, TEXTURE0 + unit);
                ffvkTexEnvi(
                    x,
                    TEXTURE_ENV,
                    TEXTURE_ENV_MODE,
                    [0, 0x0104, 0x8570, 0x0BE2][unit as usize],
                );
                ffvkTexEnvfv(
                    x,
                    TEXTURE_ENV,
                    TEXTURE_ENV_COLOR,
                    [0.1 * k, 0.2, 0.3, 0.4].as_ptr(),
                );
                ffvkTexEnvi(x, TEXTURE_ENV, SRC0_RGB + unit - 1, (TEXTURE0 + 3 - unit) as i32);
                ffvkTexEnvf(x, TEXTURE_ENV, ALPHA_SCALE, [1.0, 2.0, 4.0, 2.0][unit as usize]);
                ffvkEnable(x, if unit == 2 { TEXTURE_GEN_Q } else { TEXTURE_2D });
                ffvkTexGeni(
                    x,
                    S,
                    TEXTURE_GEN_MODE,
                    [0, SPHERE_MAP, NORMAL_MAP, EYE_LINEAR][unit as usize] as i32,
                );
                ffvkTexGenfv(x, T, OBJECT_PLANE, [k, 0.5, -k, 2.0].as_ptr());
                ffvkLoadTextureMatrix(x, if unit == 1 { shear.as_ptr() } else { scale.as_ptr() });
                ffvkTexEnvi(x, POINT_SPRITE, COORD_REPLACE, (unit % 2) as i32);
                ffvkMultiTexCoord4f(x, TEXTURE0 + unit, k, -k, 0.5 * k, 2.0);
            }
            ffvkActiveTexture(x, TEXTURE0);
            ffvkTexCoord4f(x, 0.25, 0.75, -1.0, 1.0);
            assert_eq!(
                ffvkGetError(x),
                NO_ERROR,
                "the busy state's set-up: {}",
                message()
            );
        }
        c
    }

    fn error(&self) -> u32 {
        // SAFETY: a live context.
        unsafe { ffvkGetError(self.0) }
    }

    /// Every value the context answers for, through the float queries.
    fn snapshot(&self) -> Snapshot {
        let x = self.0;
        let mut out = Vec::new();
        let mut take = |name: String, query: &dyn Fn(*mut f32)| {
            let mut buf = [SENTINEL_F; 16];
            query(buf.as_mut_ptr());
            assert_ne!(buf[0], SENTINEL_F, "{name} was not answered");
            out.push((name, buf.iter().map(|v| v.to_bits()).collect()));
        };
        // SAFETY: a live context; each buffer has room for 16 values, the most any name has.
        unsafe {
            let names = GET_NAMES.iter().copied().chain((0..16).map(|i| LIGHT0 + i));
            for p in names {
                take(format!("GetFloatv(0x{p:04X})"), &|b| ffvkGetFloatv(x, p, b));
            }
            for l in 0..16 {
                for p in LIGHT_PNAMES {
                    take(format!("GetLightfv(LIGHT{l}, 0x{p:04X})"), &|b| {
                        ffvkGetLightfv(x, LIGHT0 + l, p, b)
                    });
                }
            }
            for face in [FRONT, BACK] {
                for p in MATERIAL_PNAMES {
                    take(format!("GetMaterialfv(0x{face:04X}, 0x{p:04X})"), &|b| {
                        ffvkGetMaterialfv(x, face, p, b)
                    });
                }
            }
            let combine = [COMBINE_RGB, COMBINE_ALPHA, RGB_SCALE, ALPHA_SCALE];
            let arguments = [SRC0_RGB, SRC0_ALPHA, OPERAND0_RGB, OPERAND0_ALPHA];
            let arguments = arguments.into_iter().flat_map(|p| [p, p + 1, p + 2]);
            for p in [TEXTURE_ENV_MODE, TEXTURE_ENV_COLOR]
                .into_iter()
                .chain(combine)
                .chain(arguments)
            {
                take(format!("GetTexEnvfv(0x{p:04X})"), &|b| {
                    ffvkGetTexEnvfv(x, TEXTURE_ENV, p, b)
                });
            }
            let caps = [LIGHTING, COLOR_MATERIAL, NORMALIZE, RESCALE_NORMAL, TEXTURE_2D];
            for coord in [S, T, R, Q] {
                for p in [TEXTURE_GEN_MODE, OBJECT_PLANE, EYE_PLANE] {
                    take(format!("GetTexGenfv(0x{coord:04X}, 0x{p:04X})"), &|b| {
                        ffvkGetTexGenfv(x, coord, p, b)
                    });
                }
            }
            for p in 0..6 {
                take(format!("GetClipPlane({p})"), &|b| {
                    let mut d = [0.0f64; 4];
                    ffvkGetClipPlane(x, 0x3000 + p, d.as_mut_ptr());
                    for (k, v) in d.iter().enumerate() {
                        b.add(k).write(*v as f32);
                    }
                });
            }
            for cap in caps
                .into_iter()
                .chain((0..16).map(|i| LIGHT0 + i))
                .chain((0..6).map(|i| 0x3000 + i))
                .chain(TEXTURE_GEN_S..=TEXTURE_GEN_Q)
            {
                let on = ffvkIsEnabled(x, cap) as f32;
                take(format!("IsEnabled(0x{cap:04X})"), &|b| b.write(on));
            }
            // Every unit's state, each made active in turn, then the active unit as it was.
            let mut active = 0;
            ffvkGetIntegerv(x, ACTIVE_TEXTURE, &mut active);
            for unit in 0..4 {
                ffvkActiveTexture(x, TEXTURE0 + unit);
                for p in [TEXTURE_MATRIX, CURRENT_TEXTURE_COORDS, TEXTURE_2D] {
                    take(format!("unit {unit}: GetFloatv(0x{p:04X})"), &|b| {
                        ffvkGetFloatv(x, p, b)
                    });
                }
                let env = [TEXTURE_ENV_MODE, TEXTURE_ENV_COLOR, COMBINE_RGB, ALPHA_SCALE];
                for p in env.into_iter().chain(SRC0_RGB..SRC0_RGB + 3) {
                    take(format!("unit {unit}: GetTexEnvfv(0x{p:04X})"), &|b| {
                        ffvkGetTexEnvfv(x, TEXTURE_ENV, p, b)
                    });
                }
                take(format!("unit {unit}: GL_COORD_REPLACE"), &|b| {
                    ffvkGetTexEnvfv(x, POINT_SPRITE, COORD_REPLACE, b)
                });
                for coord in [S, T, Q] {
                    for p in [TEXTURE_GEN_MODE, OBJECT_PLANE] {
                        take(
                            format!("unit {unit}: GetTexGenfv(0x{coord:04X}, 0x{p:04X})"),
                            &|b| ffvkGetTexGenfv(x, coord, p, b),
                        );
                    }
                }
                for cap in TEXTURE_GEN_S..=TEXTURE_GEN_Q {
                    let on = ffvkIsEnabled(x, cap) as f32;
                    take(format!("unit {unit}: IsEnabled(0x{cap:04X})"), &|b| b.write(on));
                }
            }
            ffvkActiveTexture(x, active as u32);
        }
        out
    }

    /// Asserts the last call was refused with `error` (then `GL_NO_ERROR`), that the message
    /// names each of `words`, and that nothing changed since `before`.
    #[track_caller]
    fn assert_refused(&self, before: &Snapshot, error: u32, words: &[&str]) {
        let text = message();
        let got = self.error();
        assert_eq!(
            got, error,
            "GetError after a refused call (0x{got:04X}); message {text:?}"
        );
        assert_eq!(self.error(), NO_ERROR, "the error is cleared by reading it");
        assert_names(&text, words);
        assert_unchanged(before, &self.snapshot(), &text);
    }
}

#[track_caller]
fn assert_unchanged(before: &Snapshot, after: &Snapshot, context: &str) {
    assert_eq!(before.len(), after.len());
    for ((name, a), (_, b)) in before.iter().zip(after) {
        let fa: Vec<f32> = a.iter().map(|&v| f32::from_bits(v)).collect();
        let fb: Vec<f32> = b.iter().map(|&v| f32::from_bits(v)).collect();
        assert_eq!(
            a, b,
            "{name} changed from {fa:?} to {fb:?} by a refused call ({context})"
        );
    }
}

// ---------------------------------------------------------------------------------------
// Null and misaligned contexts.

/// One entry point called on the context given, its other arguments valid.
type ContextCall = fn(*mut FfvkContext);

/// Every entry point that takes a context, called with valid other arguments on `ctx`.
fn context_calls() -> Vec<(&'static str, ContextCall)> {
    const F4: [f32; 4] = [0.5, 0.5, 0.5, 1.0];
    const I4: [i32; 4] = [1, 1, 1, 1];
    const M: [f32; 16] = [1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.];
    fn e(name: &'static str, call: ContextCall) -> (&'static str, ContextCall) {
        (name, call)
    }
    // SAFETY: each closure is called with a null or misaligned context only (which the
    // entry points must refuse before using it); every other pointer is a valid constant of
    // as many values as its name takes, and query buffers are fresh 16-value arrays.
    unsafe {
        vec![
            e("ffvkGetError", |c| {
                assert_eq!(ffvkGetError(c), NO_ERROR);
            }),
            e("ffvkEnable", |c| ffvkEnable(c, LIGHTING)),
            e("ffvkDisable", |c| ffvkDisable(c, LIGHTING)),
            e("ffvkIsEnabled", |c| {
                assert_eq!(ffvkIsEnabled(c, LIGHTING), 0);
            }),
            e("ffvkLightfv", |c| ffvkLightfv(c, LIGHT0, AMBIENT, F4.as_ptr())),
            e("ffvkLightiv", |c| ffvkLightiv(c, LIGHT0, AMBIENT, I4.as_ptr())),
            e("ffvkLightf", |c| ffvkLightf(c, LIGHT0, SPOT_CUTOFF, 45.0)),
            e("ffvkLighti", |c| ffvkLighti(c, LIGHT0, SPOT_CUTOFF, 45)),
            e("ffvkMaterialfv", |c| {
                ffvkMaterialfv(c, FRONT, AMBIENT, F4.as_ptr())
            }),
            e("ffvkMaterialiv", |c| {
                ffvkMaterialiv(c, FRONT, AMBIENT, I4.as_ptr())
            }),
            e("ffvkMaterialf", |c| ffvkMaterialf(c, FRONT, SHININESS, 10.0)),
            e("ffvkMateriali", |c| ffvkMateriali(c, FRONT, SHININESS, 10)),
            e("ffvkLightModelfv", |c| {
                ffvkLightModelfv(c, LIGHT_MODEL_AMBIENT, F4.as_ptr())
            }),
            e("ffvkLightModeliv", |c| {
                ffvkLightModeliv(c, LIGHT_MODEL_AMBIENT, I4.as_ptr())
            }),
            e("ffvkLightModelf", |c| {
                ffvkLightModelf(c, LIGHT_MODEL_TWO_SIDE, 1.0)
            }),
            e("ffvkLightModeli", |c| ffvkLightModeli(c, LIGHT_MODEL_TWO_SIDE, 1)),
            e("ffvkTexEnvfv", |c| {
                ffvkTexEnvfv(c, TEXTURE_ENV, TEXTURE_ENV_COLOR, F4.as_ptr())
            }),
            e("ffvkTexEnviv", |c| {
                ffvkTexEnviv(c, TEXTURE_ENV, TEXTURE_ENV_COLOR, I4.as_ptr())
            }),
            e("ffvkTexEnvf", |c| {
                ffvkTexEnvf(c, TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as f32)
            }),
            e("ffvkTexEnvi", |c| {
                ffvkTexEnvi(c, TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32)
            }),
            e("ffvkColorMaterial", |c| ffvkColorMaterial(c, FRONT, DIFFUSE)),
            e("ffvkColor4f", |c| ffvkColor4f(c, 0.1, 0.2, 0.3, 0.4)),
            e("ffvkColor3f", |c| ffvkColor3f(c, 0.1, 0.2, 0.3)),
            e("ffvkColor4ub", |c| ffvkColor4ub(c, 1, 2, 3, 4)),
            e("ffvkColor3ub", |c| ffvkColor3ub(c, 1, 2, 3)),
            e("ffvkNormal3f", |c| ffvkNormal3f(c, 0.0, 1.0, 0.0)),
            e("ffvkNormal3b", |c| ffvkNormal3b(c, 0, 127, 0)),
            e("ffvkTexCoord4f", |c| ffvkTexCoord4f(c, 0.5, 0.5, 0.0, 1.0)),
            e("ffvkTexCoord2f", |c| ffvkTexCoord2f(c, 0.5, 0.5)),
            e("ffvkActiveTexture", |c| ffvkActiveTexture(c, TEXTURE0 + 1)),
            e("ffvkMultiTexCoord4f", |c| {
                ffvkMultiTexCoord4f(c, TEXTURE0 + 2, 0.5, 0.5, 0.0, 1.0)
            }),
            e("ffvkMultiTexCoord2f", |c| {
                ffvkMultiTexCoord2f(c, TEXTURE0 + 3, 0.5, 0.5)
            }),
            e("ffvkMultiTexCoord4fv", |c| {
                ffvkMultiTexCoord4fv(c, TEXTURE0 + 1, F4.as_ptr())
            }),
            e("ffvkSecondaryColor3f", |c| ffvkSecondaryColor3f(c, 0.1, 0.2, 0.3)),
            e("ffvkAlphaFunc", |c| ffvkAlphaFunc(c, 0x0201, 0.5)),
            e("ffvkFogf", |c| ffvkFogf(c, 0x0B62, 0.5)),
            e("ffvkFogi", |c| ffvkFogi(c, 0x0B65, 0x0800)),
            e("ffvkFogfv", |c| ffvkFogfv(c, 0x0B66, [0.5f32; 4].as_ptr())),
            e("ffvkFogiv", |c| ffvkFogiv(c, 0x0B65, [0x0801i32].as_ptr())),
            e("ffvkFogCoordf", |c| ffvkFogCoordf(c, 2.0)),
            e("ffvkPointParameterf", |c| ffvkPointParameterf(c, 0x8126, 2.0)),
            e("ffvkPointParameteri", |c| ffvkPointParameteri(c, 0x8127, 9)),
            e("ffvkPointParameterfv", |c| {
                ffvkPointParameterfv(c, 0x8129, [0.5f32, 0.25, 0.125].as_ptr())
            }),
            e("ffvkPointParameteriv", |c| {
                ffvkPointParameteriv(c, 0x8128, [3i32].as_ptr())
            }),
            e("ffvkHint", |c| ffvkHint(c, 0x0C54, 0x1101)),
            e("ffvkClipPlane", |c| {
                ffvkClipPlane(c, 0x3000, [1.0f64, 0.0, 0.0, 0.5].as_ptr())
            }),
            e("ffvkGetClipPlane", |c| {
                let mut b = [f64::from(SENTINEL_F); 4];
                ffvkGetClipPlane(c, 0x3000, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == f64::from(SENTINEL_F)), "{b:?}");
            }),
            e("ffvkTexGeni", |c| {
                ffvkTexGeni(c, S, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32)
            }),
            e("ffvkTexGenf", |c| {
                ffvkTexGenf(c, T, TEXTURE_GEN_MODE, SPHERE_MAP as f32)
            }),
            e("ffvkTexGend", |c| {
                ffvkTexGend(c, R, TEXTURE_GEN_MODE, f64::from(NORMAL_MAP))
            }),
            e("ffvkTexGeniv", |c| ffvkTexGeniv(c, S, OBJECT_PLANE, I4.as_ptr())),
            e("ffvkTexGenfv", |c| ffvkTexGenfv(c, T, EYE_PLANE, F4.as_ptr())),
            e("ffvkTexGendv", |c| {
                ffvkTexGendv(c, Q, OBJECT_PLANE, [1.0f64, 0.0, 0.0, 0.5].as_ptr())
            }),
            e("ffvkGetTexGeniv", |c| {
                let mut b = [SENTINEL_I; 16];
                ffvkGetTexGeniv(c, S, TEXTURE_GEN_MODE, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_I), "{b:?}");
            }),
            e("ffvkGetTexGenfv", |c| {
                let mut b = [SENTINEL_F; 16];
                ffvkGetTexGenfv(c, T, OBJECT_PLANE, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_F), "{b:?}");
            }),
            e("ffvkGetTexGendv", |c| {
                let mut b = [f64::from(SENTINEL_F); 16];
                ffvkGetTexGendv(c, Q, EYE_PLANE, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == f64::from(SENTINEL_F)), "{b:?}");
            }),
            e("ffvkShadeModel", |c| ffvkShadeModel(c, FLAT)),
            e("ffvkPolygonMode", |c| ffvkPolygonMode(c, FRONT, 0x1B01)),
            e("ffvkPolygonOffset", |c| ffvkPolygonOffset(c, 1.0, 1.0)),
            e("ffvkEdgeFlag", |c| ffvkEdgeFlag(c, 0)),
            e("ffvkPolygonStipple", |c| {
                ffvkPolygonStipple(c, [0x55u8; 128].as_ptr())
            }),
            e("ffvkFramebufferHeight", |c| ffvkFramebufferHeight(c, 480)),
            e("ffvkGetPolygonStipple", |c| {
                let mut b = [0xA5u8; 128];
                ffvkGetPolygonStipple(c, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == 0xA5), "{b:?}");
            }),
            e("ffvkLineStipple", |c| ffvkLineStipple(c, 2, 0x00FF)),
            e("ffvkDepthRange", |c| ffvkDepthRange(c, 0.0, 0.5)),
            e("ffvkStencilFunc", |c| ffvkStencilFunc(c, 0x0202, 1, 0xFF)),
            e("ffvkStencilFuncSeparate", |c| {
                ffvkStencilFuncSeparate(c, BACK, 0x0202, 1, 0xFF)
            }),
            e("ffvkStencilOp", |c| ffvkStencilOp(c, 0x1E00, 0x1E00, 0x1E01)),
            e("ffvkStencilOpSeparate", |c| {
                ffvkStencilOpSeparate(c, FRONT, 0x1E00, 0x1E00, 0x1E01)
            }),
            e("ffvkStencilMask", |c| ffvkStencilMask(c, 0x0F)),
            e("ffvkStencilMaskSeparate", |c| {
                ffvkStencilMaskSeparate(c, BACK, 0x0F)
            }),
            e("ffvkClearStencil", |c| ffvkClearStencil(c, 1)),
            e("ffvkColorMask", |c| ffvkColorMask(c, 0, 1, 1, 1)),
            e("ffvkDepthMask", |c| ffvkDepthMask(c, 0)),
            e("ffvkDepthFunc", |c| ffvkDepthFunc(c, 0x0203)),
            e("ffvkBlendFunc", |c| ffvkBlendFunc(c, 0x0302, 0x0303)),
            e("ffvkBlendFuncSeparate", |c| {
                ffvkBlendFuncSeparate(c, 0x0302, 0x0303, 1, 0)
            }),
            e("ffvkBlendEquation", |c| ffvkBlendEquation(c, 0x800A)),
            e("ffvkBlendEquationSeparate", |c| {
                ffvkBlendEquationSeparate(c, 0x800A, 0x8006)
            }),
            e("ffvkBlendColor", |c| ffvkBlendColor(c, 0.5, 0.5, 0.5, 0.5)),
            e("ffvkLogicOp", |c| ffvkLogicOp(c, 0x1506)),
            e("ffvkCullFace", |c| ffvkCullFace(c, FRONT)),
            e("ffvkFrontFace", |c| ffvkFrontFace(c, 0x0900)),
            e("ffvkPointSize", |c| ffvkPointSize(c, 2.0)),
            e("ffvkLineWidth", |c| ffvkLineWidth(c, 2.0)),
            e("ffvkPerFragmentLighting", |c| ffvkPerFragmentLighting(c, 1)),
            e("ffvkLoadModelview", |c| ffvkLoadModelview(c, M.as_ptr())),
            e("ffvkLoadProjection", |c| ffvkLoadProjection(c, M.as_ptr())),
            e("ffvkLoadTextureMatrix", |c| ffvkLoadTextureMatrix(c, M.as_ptr())),
            e("ffvkGetLightfv", |c| {
                let mut b = [SENTINEL_F; 16];
                ffvkGetLightfv(c, LIGHT0, AMBIENT, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_F), "{b:?}");
            }),
            e("ffvkGetLightiv", |c| {
                let mut b = [SENTINEL_I; 16];
                ffvkGetLightiv(c, LIGHT0, AMBIENT, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_I), "{b:?}");
            }),
            e("ffvkGetMaterialfv", |c| {
                let mut b = [SENTINEL_F; 16];
                ffvkGetMaterialfv(c, FRONT, AMBIENT, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_F), "{b:?}");
            }),
            e("ffvkGetMaterialiv", |c| {
                let mut b = [SENTINEL_I; 16];
                ffvkGetMaterialiv(c, FRONT, AMBIENT, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_I), "{b:?}");
            }),
            e("ffvkGetTexEnvfv", |c| {
                let mut b = [SENTINEL_F; 16];
                ffvkGetTexEnvfv(c, TEXTURE_ENV, TEXTURE_ENV_COLOR, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_F), "{b:?}");
            }),
            e("ffvkGetTexEnviv", |c| {
                let mut b = [SENTINEL_I; 16];
                ffvkGetTexEnviv(c, TEXTURE_ENV, TEXTURE_ENV_COLOR, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_I), "{b:?}");
            }),
            e("ffvkGetFloatv", |c| {
                let mut b = [SENTINEL_F; 16];
                ffvkGetFloatv(c, MODELVIEW_MATRIX, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_F), "{b:?}");
            }),
            e("ffvkGetIntegerv", |c| {
                let mut b = [SENTINEL_I; 16];
                ffvkGetIntegerv(c, MODELVIEW_MATRIX, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_I), "{b:?}");
            }),
            e("ffvkGetBooleanv", |c| {
                let mut b = [SENTINEL_B; 16];
                ffvkGetBooleanv(c, MODELVIEW_MATRIX, b.as_mut_ptr());
                assert!(b.iter().all(|&v| v == SENTINEL_B), "{b:?}");
            }),
        ]
    }
}

#[test]
fn the_table_of_context_entry_points_covers_every_function_of_the_header_that_takes_a_context() {
    let header = include_str!("../include/ffvk.h");
    let covered: Vec<&str> = context_calls().iter().map(|(name, _)| *name).collect();
    let mut missing = Vec::new();
    for line in header.lines() {
        let Some(open) = line.find("(struct FfvkContext *ctx") else {
            continue;
        };
        let name = line[..open].rsplit([' ', '*']).next().unwrap();
        if name != "ffvkDestroyContext" && !covered.contains(&name) {
            missing.push(name.to_string());
        }
    }
    assert!(
        missing.is_empty(),
        "entry points not probed with a null context: {missing:?}"
    );
    assert!(
        covered.len() >= 39,
        "the header parse found too little: {covered:?}"
    );
}

#[test]
fn every_context_entry_point_with_a_null_context_does_nothing_and_names_itself() {
    // A live context beside it must not be touched either.
    let other = Ctx::busy();
    let before = other.snapshot();
    for (name, call) in context_calls() {
        call(null_mut());
        assert_names(&message(), &[name, "context", "null"]);
    }
    assert_eq!(other.error(), NO_ERROR);
    assert_unchanged(&before, &other.snapshot(), "null-context calls");
}

#[test]
fn every_context_entry_point_with_a_misaligned_context_does_nothing_and_names_itself() {
    let real = Ctx::busy();
    let before = real.snapshot();
    let bad = misaligned(real.0.cast_const()).cast_mut();
    for (name, call) in context_calls() {
        call(bad);
        assert_names(&message(), &[name, "context", "not aligned"]);
    }
    assert_eq!(real.error(), NO_ERROR);
    assert_unchanged(&before, &real.snapshot(), "misaligned-context calls");
}

#[test]
fn destroying_a_null_context_mesh_renderer_or_texture_does_nothing() {
    // SAFETY: null is documented as ignored by every destroy function.
    unsafe {
        ffvkDestroyContext(null_mut());
        ffvkDestroyMesh(null_mut());
        ffvkDestroyRenderer(null_mut());
        ffvkDestroyTexture(null_mut());
    }
}

// ---------------------------------------------------------------------------------------
// Null and misaligned parameter arrays.

#[test]
fn a_null_params_sets_invalid_value_names_the_function_and_changes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    // SAFETY: a live context; the null pointers are what is probed.
    unsafe {
        assert_each_refused!(
            c,
            before,
            INVALID_VALUE,
            ["params is a null pointer", "expected"],
            {
                ffvkLightfv(x, LIGHT0, AMBIENT, null());
                ffvkLightiv(x, LIGHT0, SPOT_CUTOFF, null());
                ffvkMaterialfv(x, FRONT, SHININESS, null());
                ffvkMaterialiv(x, BACK, DIFFUSE, null());
                ffvkLightModelfv(x, LIGHT_MODEL_AMBIENT, null());
                ffvkLightModeliv(x, LIGHT_MODEL_TWO_SIDE, null());
                ffvkTexEnvfv(x, TEXTURE_ENV, TEXTURE_ENV_COLOR, null());
                ffvkTexEnviv(x, TEXTURE_ENV, TEXTURE_ENV_MODE, null());
                ffvkTexGenfv(x, S, OBJECT_PLANE, null());
                ffvkTexGeniv(x, T, TEXTURE_GEN_MODE, null());
                ffvkTexGendv(x, R, EYE_PLANE, null());
            }
        );
        // The matrix entry points' parameter is `m` (ffvk.h).
        assert_each_refused!(c, before, INVALID_VALUE, ["m is a null pointer", "16"], {
            ffvkLoadModelview(x, null());
            ffvkLoadProjection(x, null());
            ffvkLoadTextureMatrix(x, null());
        });
        // glMultiTexCoord4fv's is `v`.
        assert_each_refused!(c, before, INVALID_VALUE, ["v is a null pointer", "4 value(s)"], {
            ffvkMultiTexCoord4fv(x, TEXTURE0 + 1, null());
        });
    }
}

#[test]
fn a_query_with_a_null_params_sets_invalid_value_and_names_the_function() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    // SAFETY: a live context; the null pointers are what is probed.
    unsafe {
        assert_each_refused!(
            c,
            before,
            INVALID_VALUE,
            ["params is a null pointer", "expected"],
            {
                ffvkGetLightfv(x, LIGHT0, AMBIENT, null_mut());
                ffvkGetLightiv(x, LIGHT0, SPOT_CUTOFF, null_mut());
                ffvkGetMaterialfv(x, FRONT, SHININESS, null_mut());
                ffvkGetMaterialiv(x, BACK, EMISSION, null_mut());
                ffvkGetTexEnvfv(x, TEXTURE_ENV, TEXTURE_ENV_COLOR, null_mut());
                ffvkGetTexEnviv(x, TEXTURE_ENV, TEXTURE_ENV_MODE, null_mut());
                ffvkGetTexGenfv(x, S, OBJECT_PLANE, null_mut());
                ffvkGetTexGeniv(x, T, TEXTURE_GEN_MODE, null_mut());
                ffvkGetTexGendv(x, Q, EYE_PLANE, null_mut());
                ffvkGetFloatv(x, MODELVIEW_MATRIX, null_mut());
                ffvkGetIntegerv(x, MAX_LIGHTS, null_mut());
                ffvkGetBooleanv(x, LIGHTING, null_mut());
            }
        );
    }
}

#[test]
fn a_misaligned_params_sets_invalid_value_and_is_neither_read_nor_written() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    // Room for 16 values after the odd byte, in a pattern that would show a write.
    let mut bytes = [0x5Au8; 80];
    let f = misaligned(bytes.as_mut_ptr().cast::<f32>().cast_const());
    let i = misaligned(bytes.as_mut_ptr().cast::<i32>().cast_const());
    let (fm, im) = (f.cast_mut(), i.cast_mut());
    // SAFETY: a live context; the misaligned pointers point into `bytes` with room for 16
    // values, and must be refused for their alignment before they are read or written.
    unsafe {
        assert_each_refused!(
            c,
            before,
            INVALID_VALUE,
            ["params 0x", "not aligned to 4 bytes"],
            {
                ffvkLightfv(x, LIGHT0, AMBIENT, f);
                ffvkLightiv(x, LIGHT0, AMBIENT, i);
                ffvkMaterialfv(x, FRONT, AMBIENT, f);
                ffvkMaterialiv(x, FRONT, SHININESS, i);
                ffvkLightModelfv(x, LIGHT_MODEL_TWO_SIDE, f);
                ffvkLightModeliv(x, LIGHT_MODEL_AMBIENT, i);
                ffvkTexEnvfv(x, TEXTURE_ENV, TEXTURE_ENV_COLOR, f);
                ffvkTexEnviv(x, TEXTURE_ENV, TEXTURE_ENV_MODE, i);
                ffvkGetLightfv(x, LIGHT0, AMBIENT, fm);
                ffvkGetLightiv(x, LIGHT0, POSITION, im);
                ffvkGetMaterialfv(x, BACK, EMISSION, fm);
                ffvkGetMaterialiv(x, FRONT, AMBIENT, im);
                ffvkGetTexEnvfv(x, TEXTURE_ENV, TEXTURE_ENV_COLOR, fm);
                ffvkGetTexEnviv(x, TEXTURE_ENV, TEXTURE_ENV_MODE, im);
                ffvkTexGenfv(x, S, OBJECT_PLANE, f);
                ffvkTexGeniv(x, T, EYE_PLANE, i);
                ffvkGetTexGenfv(x, R, EYE_PLANE, fm);
                ffvkGetTexGeniv(x, Q, OBJECT_PLANE, im);
                ffvkGetFloatv(x, MODELVIEW_MATRIX, fm);
                ffvkGetIntegerv(x, MODELVIEW_MATRIX, im);
            }
        );
        assert_each_refused!(c, before, INVALID_VALUE, ["m 0x", "not aligned to 4 bytes"], {
            ffvkLoadModelview(x, f);
            ffvkLoadProjection(x, f);
            ffvkLoadTextureMatrix(x, f);
        });
        assert_each_refused!(c, before, INVALID_VALUE, ["v 0x", "not aligned to 4 bytes"], {
            ffvkMultiTexCoord4fv(x, TEXTURE0 + 3, f);
        });
    }
    assert!(
        bytes.iter().all(|&b| b == 0x5A),
        "written through a misaligned pointer: {bytes:?}"
    );
    // A boolean has no alignment to miss: ffvkGetBooleanv writes at any address.
    let mut bools = [SENTINEL_B; 17];
    // SAFETY: a live context; room for the 16 values of the matrix after the first byte.
    unsafe { ffvkGetBooleanv(x, MODELVIEW_MATRIX, bools.as_mut_ptr().add(1)) };
    assert_eq!(c.error(), NO_ERROR, "{}", message());
    assert_eq!(bools[0], SENTINEL_B);
    assert_eq!(bools[1], 1, "the modelview's first component is 2: GL_TRUE");
}

// ---------------------------------------------------------------------------------------
// Unknown enums: GL_INVALID_ENUM, nothing changed, the value named.

#[test]
fn enable_disable_and_is_enabled_refuse_an_unknown_cap_with_invalid_enum() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for cap in [
        BOGUS,
        0,
        u32::MAX,
        DITHER,
        LIGHT0 - 1,
        LIGHT0 + 16,
        LIGHT0 + 0x1000,
    ] {
        // SAFETY: a live context.
        unsafe {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["cap", &hex(cap), "expected GL_LIGHTING"],
                {
                    ffvkEnable(x, cap);
                    ffvkDisable(x, cap);
                    ffvkIsEnabled(x, cap);
                }
            );
            assert_eq!(ffvkIsEnabled(x, cap), 0, "GL_FALSE for an unknown cap");
            assert_eq!(c.error(), INVALID_ENUM);
        }
    }
}

#[test]
fn the_raster_entry_points_refuse_what_gl_refuses_naming_the_parameter_and_change_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    // SAFETY: a live context.
    unsafe {
        assert_each_refused!(c, before, INVALID_ENUM, ["face", &hex(BOGUS), "GL_FRONT"], {
            ffvkPolygonMode(x, BOGUS, 0x1B01);
            ffvkStencilFuncSeparate(x, BOGUS, 0x0202, 0, 0);
            ffvkStencilOpSeparate(x, BOGUS, 0x1E00, 0x1E00, 0x1E00);
            ffvkStencilMaskSeparate(x, BOGUS, 0);
        });
        assert_each_refused!(c, before, INVALID_ENUM, ["mode", &hex(BOGUS), "expected GL_"], {
            ffvkPolygonMode(x, FRONT, BOGUS);
            ffvkCullFace(x, BOGUS);
            ffvkFrontFace(x, BOGUS);
            ffvkBlendEquation(x, BOGUS);
        });
        assert_each_refused!(c, before, INVALID_ENUM, ["func", &hex(BOGUS), "GL_NEVER"], {
            ffvkStencilFunc(x, BOGUS, 0, 0);
            ffvkDepthFunc(x, BOGUS);
        });
        assert_each_refused!(c, before, INVALID_ENUM, ["dppass", &hex(BOGUS), "GL_KEEP"], {
            ffvkStencilOp(x, 0x1E00, 0x1E00, BOGUS);
        });
        assert_each_refused!(
            c,
            before,
            INVALID_ENUM,
            ["dfactor", "GL_SRC_ALPHA_SATURATE", "source factor only"],
            {
                ffvkBlendFunc(x, 1, 0x0308);
            }
        );
        assert_each_refused!(
            c,
            before,
            INVALID_ENUM,
            ["sfactorAlpha", &hex(BOGUS), "GL_ZERO"],
            {
                ffvkBlendFuncSeparate(x, 1, 0, BOGUS, 0);
            }
        );
        assert_each_refused!(c, before, INVALID_ENUM, ["opcode", &hex(BOGUS), "GL_CLEAR"], {
            ffvkLogicOp(x, BOGUS);
        });
        for size in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            assert_each_refused!(c, before, INVALID_VALUE, [&size.to_string()], {
                ffvkPointSize(x, size);
                ffvkLineWidth(x, size);
            });
        }
        assert_each_refused!(c, before, INVALID_VALUE, ["GL_POLYGON_OFFSET_UNITS", "NaN"], {
            ffvkPolygonOffset(x, 1.0, f32::NAN);
        });
        assert_each_refused!(c, before, INVALID_VALUE, ["GL_BLEND_COLOR", "inf"], {
            ffvkBlendColor(x, 0.0, f32::INFINITY, 0.0, 0.0);
        });
        assert_each_refused!(c, before, INVALID_VALUE, ["GL_DEPTH_RANGE", "NaN"], {
            ffvkDepthRange(x, f64::NAN, 1.0);
        });
    }
}

#[test]
fn gl_light_refuses_a_light_past_gl_max_lights_or_an_unknown_pname_with_invalid_enum() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let (f4, i4) = ([0.5f32; 4], [1i32; 4]);
    let (f, i) = (f4.as_ptr(), i4.as_ptr());
    let (mut f16, mut i16) = ([SENTINEL_F; 16], [SENTINEL_I; 16]);
    let (fo, io) = (f16.as_mut_ptr(), i16.as_mut_ptr());
    // SAFETY: a live context for every call below; params point at 4 values, query buffers
    // at 16.
    unsafe {
        for light in [LIGHT0 + 16, LIGHT0 - 1, 0, BOGUS, u32::MAX] {
            assert_each_refused!(c, before, INVALID_ENUM, ["light", &hex(light), "GL_LIGHT0"], {
                ffvkLightfv(x, light, AMBIENT, f);
                ffvkLightiv(x, light, DIFFUSE, i);
                ffvkLightf(x, light, SPOT_CUTOFF, 45.0);
                ffvkLighti(x, light, SPOT_EXPONENT, 2);
                ffvkGetLightfv(x, light, AMBIENT, fo);
                ffvkGetLightiv(x, light, AMBIENT, io);
            });
        }
        // Material, light model and texture names are not light names.
        for pname in [
            BOGUS,
            0,
            SHININESS,
            EMISSION,
            LIGHT_MODEL_AMBIENT,
            TEXTURE_ENV_COLOR,
        ] {
            assert_each_refused!(c, before, INVALID_ENUM, ["pname", &hex(pname), "expected"], {
                ffvkLightfv(x, LIGHT0, pname, f);
                ffvkLightiv(x, LIGHT0 + 3, pname, i);
                ffvkLightf(x, LIGHT0, pname, 1.0);
                ffvkLighti(x, LIGHT0 + 15, pname, 1);
                ffvkGetLightfv(x, LIGHT0, pname, fo);
                ffvkGetLightiv(x, LIGHT0 + 1, pname, io);
            });
        }
        // glLightf and glLighti take the single-valued names only (GL 2.1 section 2.14.2).
        for pname in [AMBIENT, DIFFUSE, SPECULAR, POSITION, SPOT_DIRECTION] {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["pname", &hex(pname), "single-valued"],
                {
                    ffvkLightf(x, LIGHT0, pname, 1.0);
                    ffvkLighti(x, LIGHT0, pname, 1);
                }
            );
        }
    }
    assert_eq!(f16, [SENTINEL_F; 16], "a refused query wrote");
    assert_eq!(i16, [SENTINEL_I; 16], "a refused query wrote");
}

#[test]
fn gl_material_refuses_an_unknown_face_or_pname_with_invalid_enum() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let (f4, i4) = ([0.5f32; 4], [1i32; 4]);
    let (f, i) = (f4.as_ptr(), i4.as_ptr());
    // SAFETY: a live context for every call below; params point at 4 values.
    unsafe {
        for face in [LEFT, 0, BOGUS, u32::MAX, LIGHT0] {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["face", &hex(face), "GL_FRONT_AND_BACK"],
                {
                    ffvkMaterialfv(x, face, AMBIENT, f);
                    ffvkMaterialiv(x, face, DIFFUSE, i);
                    ffvkMaterialf(x, face, SHININESS, 2.0);
                    ffvkMateriali(x, face, SHININESS, 2);
                    ffvkColorMaterial(x, face, DIFFUSE);
                }
            );
        }
        // Light names that are not material names, and nonsense.
        for pname in [POSITION, SPOT_CUTOFF, CONSTANT_ATTENUATION, BOGUS, 0] {
            assert_each_refused!(c, before, INVALID_ENUM, ["pname", &hex(pname), "expected"], {
                ffvkMaterialfv(x, FRONT, pname, f);
                ffvkMaterialiv(x, FRONT_AND_BACK, pname, i);
                ffvkMaterialf(x, BACK, pname, 1.0);
                ffvkMateriali(x, FRONT, pname, 1);
            });
        }
        // glMaterialf and glMateriali take GL_SHININESS only.
        for pname in [
            AMBIENT,
            DIFFUSE,
            SPECULAR,
            EMISSION,
            AMBIENT_AND_DIFFUSE,
            COLOR_INDEXES,
        ] {
            assert_each_refused!(c, before, INVALID_ENUM, ["pname", &hex(pname), "GL_SHININESS"], {
                ffvkMaterialf(x, FRONT, pname, 1.0);
                ffvkMateriali(x, BACK, pname, 1);
            });
        }
        // glColorMaterial's mode is a color of the material.
        for mode in [SHININESS, COLOR_INDEXES, POSITION, BOGUS, 0] {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["mode", &hex(mode), "GL_AMBIENT_AND_DIFFUSE"],
                {
                    ffvkColorMaterial(x, FRONT_AND_BACK, mode);
                }
            );
        }
    }
}

#[test]
fn gl_get_material_refuses_front_and_back_ambient_and_diffuse_and_unknown_names_and_writes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for (face, pname, parameter) in [
        (FRONT_AND_BACK, AMBIENT, "face"),
        (LEFT, AMBIENT, "face"),
        (0, SHININESS, "face"),
        (FRONT, AMBIENT_AND_DIFFUSE, "pname"),
        (BACK, POSITION, "pname"),
        (FRONT, BOGUS, "pname"),
    ] {
        let value = hex(if parameter == "face" { face } else { pname });
        let mut f = [SENTINEL_F; 16];
        let mut i = [SENTINEL_I; 16];
        // SAFETY: a live context; 16 values of room.
        unsafe {
            assert_each_refused!(c, before, INVALID_ENUM, [parameter, &value, "expected"], {
                ffvkGetMaterialfv(x, face, pname, f.as_mut_ptr());
                ffvkGetMaterialiv(x, face, pname, i.as_mut_ptr());
            });
        }
        assert!(f.iter().all(|&v| v == SENTINEL_F), "{f:?}");
        assert!(i.iter().all(|&v| v == SENTINEL_I), "{i:?}");
    }
}

#[test]
fn gl_get_light_refuses_an_unknown_light_or_pname_and_writes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for (light, pname) in [(LIGHT0 + 16, AMBIENT), (LIGHT0, BOGUS), (LIGHT0 + 2, SHININESS)] {
        let mut f = [SENTINEL_F; 16];
        let mut i = [SENTINEL_I; 16];
        // SAFETY: a live context; 16 values of room.
        unsafe {
            assert_each_refused!(c, before, INVALID_ENUM, ["expected"], {
                ffvkGetLightfv(x, light, pname, f.as_mut_ptr());
                ffvkGetLightiv(x, light, pname, i.as_mut_ptr());
            });
        }
        assert!(f.iter().all(|&v| v == SENTINEL_F), "{f:?}");
        assert!(i.iter().all(|&v| v == SENTINEL_I), "{i:?}");
    }
}

#[test]
fn gl_light_model_refuses_an_unknown_pname_or_color_control_with_invalid_enum() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let (f4, i4) = ([0.5f32; 4], [1i32; 4]);
    let (f, i) = (f4.as_ptr(), i4.as_ptr());
    // SAFETY: a live context for every call below; params point at 4 values.
    unsafe {
        for pname in [BOGUS, 0, AMBIENT, SHADE_MODEL, LIGHT_MODEL_COLOR_CONTROL + 3] {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["pname", &hex(pname), "GL_LIGHT_MODEL_"],
                {
                    ffvkLightModelfv(x, pname, f);
                    ffvkLightModeliv(x, pname, i);
                    ffvkLightModelf(x, pname, 1.0);
                    ffvkLightModeli(x, pname, 1);
                }
            );
        }
        // GL_LIGHT_MODEL_AMBIENT has 4 values: not for the scalar entry points.
        assert_each_refused!(c, before, INVALID_ENUM, ["pname", "0x0B53", "single-valued"], {
            ffvkLightModelf(x, LIGHT_MODEL_AMBIENT, 1.0);
            ffvkLightModeli(x, LIGHT_MODEL_AMBIENT, 1);
        });
        let pname = LIGHT_MODEL_COLOR_CONTROL;
        for value in [BOGUS, 0, 1, SINGLE_COLOR - 1, SEPARATE_SPECULAR_COLOR + 1] {
            let (fv, iv) = ([value as f32; 4], [value as i32; 4]);
            let words = [
                "GL_LIGHT_MODEL_COLOR_CONTROL",
                &hex(value),
                "GL_SEPARATE_SPECULAR_COLOR",
            ];
            assert_each_refused!(c, before, INVALID_ENUM, words, {
                ffvkLightModelfv(x, pname, fv.as_ptr());
                ffvkLightModeliv(x, pname, iv.as_ptr());
                ffvkLightModelf(x, pname, value as f32);
                ffvkLightModeli(x, pname, value as i32);
            });
        }
    }
}

#[test]
fn gl_tex_env_refuses_an_unknown_target_pname_or_mode_with_invalid_enum() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let (f4, i4) = ([0.5f32; 4], [MODULATE as i32; 4]);
    let (f, i) = (f4.as_ptr(), i4.as_ptr());
    let (mut f16, mut i16) = ([SENTINEL_F; 16], [SENTINEL_I; 16]);
    let (fo, io) = (f16.as_mut_ptr(), i16.as_mut_ptr());
    let (env, mode, color) = (TEXTURE_ENV, TEXTURE_ENV_MODE, TEXTURE_ENV_COLOR);
    // SAFETY: a live context for every call below; params point at 4 values, query buffers
    // at 16.
    unsafe {
        for target in [TEXTURE_2D, BOGUS, 0, TEXTURE_ENV + 1] {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["target", &hex(target), "GL_TEXTURE_ENV"],
                {
                    ffvkTexEnvfv(x, target, color, f);
                    ffvkTexEnviv(x, target, mode, i);
                    ffvkTexEnvf(x, target, mode, MODULATE as f32);
                    ffvkTexEnvi(x, target, mode, MODULATE as i32);
                    ffvkGetTexEnvfv(x, target, mode, fo);
                    ffvkGetTexEnviv(x, target, color, io);
                }
            );
        }
        for pname in [BOGUS, 0, AMBIENT, TEXTURE_ENV] {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["pname", &hex(pname), "GL_TEXTURE_ENV_MODE"],
                {
                    ffvkTexEnvfv(x, env, pname, f);
                    ffvkTexEnviv(x, env, pname, i);
                    ffvkTexEnvf(x, env, pname, 1.0);
                    ffvkTexEnvi(x, env, pname, 1);
                    ffvkGetTexEnvfv(x, env, pname, fo);
                    ffvkGetTexEnviv(x, env, pname, io);
                }
            );
        }
        // GL_TEXTURE_ENV_COLOR has 4 values: not for the scalar entry points.
        assert_each_refused!(c, before, INVALID_ENUM, ["pname", "0x2201", "single-valued"], {
            ffvkTexEnvf(x, env, color, 1.0);
            ffvkTexEnvi(x, env, color, 1);
        });
        for value in [COMBINE_RGB, BOGUS, 0, SMOOTH] {
            let (fv, iv) = ([value as f32; 4], [value as i32; 4]);
            let words = ["GL_TEXTURE_ENV_MODE", &hex(value), "GL_MODULATE"];
            assert_each_refused!(c, before, INVALID_ENUM, words, {
                ffvkTexEnvfv(x, env, mode, fv.as_ptr());
                ffvkTexEnviv(x, env, mode, iv.as_ptr());
                ffvkTexEnvf(x, env, mode, value as f32);
                ffvkTexEnvi(x, env, mode, value as i32);
            });
        }
    }
    assert_eq!(f16, [SENTINEL_F; 16], "a refused query wrote");
    assert_eq!(i16, [SENTINEL_I; 16], "a refused query wrote");
    let mut got = [SENTINEL_F; 16];
    // SAFETY: a live context; 16 values of room.
    unsafe { ffvkGetTexEnvfv(x, env, mode, got.as_mut_ptr()) };
    assert_eq!(got[0], REPLACE as f32, "the busy context's mode survived");
}

#[test]
fn gl_tex_env_refuses_a_combine_value_gl_does_not_take_or_a_unit_past_the_last() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let env = TEXTURE_ENV;
    // SAFETY: a live context for every call below; params point at 4 values.
    unsafe {
        // GL_TEXTUREn (ARB_texture_env_crossbar) names unit n's texel: ffvk has four units, so
        // GL_TEXTURE4 .. GL_TEXTURE31 name none (GL_INVALID_ENUM, as Mesa refuses one past its
        // own units).
        for pname in [SRC0_RGB, SRC0_RGB + 2, SRC0_ALPHA, SRC0_ALPHA + 1] {
            for value in [TEXTURE0 + 4, TEXTURE0 + 7, TEXTURE0 + 31] {
                let (fv, iv) = ([value as f32; 4], [value as i32; 4]);
                let words = [
                    &format!("GL_TEXTURE{} ({})", value - TEXTURE0, hex(value)),
                    "GL_TEXTURE, GL_CONSTANT",
                    "GL_TEXTURE0 .. GL_TEXTURE3",
                    "GL_MAX_TEXTURE_UNITS, 4",
                ];
                assert_each_refused!(c, before, INVALID_ENUM, words, {
                    ffvkTexEnvfv(x, env, pname, fv.as_ptr());
                    ffvkTexEnviv(x, env, pname, iv.as_ptr());
                    ffvkTexEnvf(x, env, pname, value as f32);
                    ffvkTexEnvi(x, env, pname, value as i32);
                });
            }
        }
        // The dot products are RGB functions (§3.8.13).
        for value in [DOT3_RGB, DOT3_RGBA] {
            assert_each_refused!(c, before, INVALID_ENUM, ["GL_COMBINE_ALPHA", "GL_DOT3_RGB"], {
                ffvkTexEnvi(x, env, COMBINE_ALPHA, value as i32);
                ffvkTexEnvf(x, env, COMBINE_ALPHA, value as f32);
            });
        }
        // An alpha argument takes the source's alpha, or one minus it.
        for pname in [OPERAND0_ALPHA, OPERAND0_ALPHA + 1, OPERAND0_ALPHA + 2] {
            for value in [SRC_COLOR, ONE_MINUS_SRC_COLOR] {
                let words = [
                    "GL_OPERAND",
                    &hex(value),
                    "GL_SRC_ALPHA or GL_ONE_MINUS_SRC_ALPHA",
                ];
                assert_each_refused!(c, before, INVALID_ENUM, words, {
                    ffvkTexEnvi(x, env, pname, value as i32);
                    ffvkTexEnvf(x, env, pname, value as f32);
                });
            }
        }
        // A value for another argument's kind: a source as an operand, an operand as a source.
        assert_each_refused!(c, before, INVALID_ENUM, ["GL_OPERAND0_RGB", "0x8580"], {
            ffvkTexEnvi(x, env, OPERAND0_RGB, SRC0_RGB as i32);
        });
        assert_each_refused!(c, before, INVALID_ENUM, ["GL_SRC1_ALPHA", "0x0300"], {
            ffvkTexEnvi(x, env, SRC0_ALPHA + 1, SRC_COLOR as i32);
        });
        // The scales are 1, 2 or 4.
        for pname in [RGB_SCALE, ALPHA_SCALE] {
            for scale in [0.0f32, 3.0, 8.0, -1.0, 2.5, 1.0001, f32::NAN, f32::INFINITY] {
                let (fv, iv) = ([scale; 4], [scale as i32; 4]);
                assert_each_refused!(c, before, INVALID_VALUE, ["_SCALE", "1.0, 2.0 or 4.0"], {
                    ffvkTexEnvfv(x, env, pname, fv.as_ptr());
                    ffvkTexEnvf(x, env, pname, scale);
                });
                if scale.fract() == 0.0 {
                    assert_each_refused!(c, before, INVALID_VALUE, ["_SCALE", "1.0, 2.0 or 4.0"], {
                        ffvkTexEnviv(x, env, pname, iv.as_ptr());
                        ffvkTexEnvi(x, env, pname, scale as i32);
                    });
                }
            }
        }
    }
}

#[test]
fn gl_active_texture_and_multi_tex_coord_refuse_a_unit_past_the_last_and_change_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    // SAFETY: a live context for every call below; v points at 4 values.
    unsafe {
        // GL_TEXTURE0 + i for i below GL_MAX_TEXTURE_UNITS (4); GL_TEXTURE0 - 1 and 0 wrap
        // around below it, GL_ACTIVE_TEXTURE is GL_TEXTURE0 + 32.
        for texture in [
            TEXTURE0 + 4,
            TEXTURE0 + 31,
            ACTIVE_TEXTURE,
            TEXTURE0 - 1,
            0,
            BOGUS,
            TEXTURE_2D,
        ] {
            let words = [
                &hex(texture) as &str,
                "texture",
                "GL_TEXTURE0 .. GL_TEXTURE3",
                "GL_INVALID_ENUM",
            ];
            assert_each_refused!(c, before, INVALID_ENUM, words, {
                ffvkActiveTexture(x, texture);
            });
            let words = [&hex(texture) as &str, "target", "GL_MAX_TEXTURE_COORDS is 4"];
            assert_each_refused!(c, before, INVALID_ENUM, words, {
                ffvkMultiTexCoord4f(x, texture, 1.0, 2.0, 3.0, 4.0);
                ffvkMultiTexCoord2f(x, texture, 1.0, 2.0);
                ffvkMultiTexCoord4fv(x, texture, [1.0f32; 4].as_ptr());
                // The target is checked first: a null v with a bad target is GL_INVALID_ENUM.
                ffvkMultiTexCoord4fv(x, texture, null());
            });
        }
        for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            assert_each_refused!(
                c,
                before,
                INVALID_VALUE,
                ["GL_CURRENT_TEXTURE_COORDS", "finite"],
                {
                    ffvkMultiTexCoord4f(x, TEXTURE0 + 2, 0.0, 0.0, bad, 1.0);
                    ffvkMultiTexCoord2f(x, TEXTURE0, bad, 0.0);
                    ffvkMultiTexCoord4fv(x, TEXTURE0 + 3, [0.0, 0.0, 0.0, bad].as_ptr());
                }
            );
        }
    }
}

/// The value of `pname` on the active unit through `ffvkGetFloatv`, `count` values.
fn floats(x: *mut FfvkContext, pname: u32, count: usize) -> Vec<f32> {
    let mut b = [SENTINEL_F; 16];
    // SAFETY: a live context; room for 16 values.
    unsafe { ffvkGetFloatv(x, pname, b.as_mut_ptr()) };
    b[..count].to_vec()
}

#[test]
fn each_units_state_is_set_and_answered_through_the_active_unit() {
    let c = Ctx::new();
    let x = c.0;
    let scale = |k: f32| -> [f32; 16] { [k, 0., 0., 0., 0., k, 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.] };
    let tex_env = |p: u32| {
        let mut v = SENTINEL_I;
        // SAFETY: a live context; one value written.
        unsafe { ffvkGetTexEnviv(x, TEXTURE_ENV, p, &mut v) };
        v
    };
    // SAFETY: a live context; every pointer points at as many values as its name takes.
    unsafe {
        assert_eq!(floats(x, MAX_TEXTURE_UNITS, 1), [4.0]);
        let mut n = [SENTINEL_I; 2];
        ffvkGetIntegerv(x, MAX_TEXTURE_COORDS, n.as_mut_ptr());
        assert_eq!(n, [4, SENTINEL_I]);
        assert_eq!(
            floats(x, ACTIVE_TEXTURE, 1),
            [TEXTURE0 as f32],
            "GL_TEXTURE0 initially"
        );
        // Each unit its own way, set while it is the active one; glTexCoord is unit 0's
        // whatever the active unit, glMultiTexCoord the unit its target names.
        for unit in 0..4u32 {
            let k = unit as f32 + 1.0;
            ffvkActiveTexture(x, TEXTURE0 + unit);
            ffvkLoadTextureMatrix(x, scale(k).as_ptr());
            ffvkTexEnvi(
                x,
                TEXTURE_ENV,
                TEXTURE_ENV_MODE,
                [MODULATE, REPLACE, 0x8570, 0x0104][unit as usize] as i32,
            );
            ffvkTexEnvi(x, TEXTURE_ENV, SRC0_RGB + 1, (TEXTURE0 + 3 - unit) as i32);
            ffvkTexEnvf(x, TEXTURE_ENV, SRC0_ALPHA, (TEXTURE0 + unit) as f32);
            ffvkTexGenfv(x, T, OBJECT_PLANE, [k, 0.0, 0.0, 1.0].as_ptr());
            ffvkTexEnvi(x, POINT_SPRITE, COORD_REPLACE, (unit == 2) as i32);
            if unit % 2 == 1 {
                ffvkEnable(x, TEXTURE_2D);
                ffvkEnable(x, TEXTURE_GEN_R);
            }
            ffvkMultiTexCoord4fv(x, TEXTURE0 + 3 - unit, [k, 2.0 * k, 0.0, 1.0].as_ptr());
        }
        ffvkMultiTexCoord2f(x, TEXTURE0 + 2, 0.5, -0.5);
        ffvkTexCoord4f(x, 9.0, 8.0, 7.0, 6.0);
        assert_eq!(c.error(), NO_ERROR, "{}", message());
        assert_eq!(floats(x, ACTIVE_TEXTURE, 1), [(TEXTURE0 + 3) as f32]);
        let coords = [
            [9.0, 8.0, 7.0, 6.0],
            [3.0, 6.0, 0.0, 1.0],
            [0.5, -0.5, 0.0, 1.0],
            [1.0, 2.0, 0.0, 1.0],
        ];
        for unit in 0..4u32 {
            let k = unit as f32 + 1.0;
            ffvkActiveTexture(x, TEXTURE0 + unit);
            let mut active = [SENTINEL_I; 1];
            ffvkGetIntegerv(x, ACTIVE_TEXTURE, active.as_mut_ptr());
            assert_eq!(active, [(TEXTURE0 + unit) as i32]);
            assert_eq!(
                floats(x, TEXTURE_MATRIX, 16),
                scale(k),
                "unit {unit}'s texture matrix"
            );
            assert_eq!(
                floats(x, CURRENT_TEXTURE_COORDS, 4),
                coords[unit as usize],
                "unit {unit}"
            );
            let on = unit % 2 == 1;
            assert_eq!(
                ffvkIsEnabled(x, TEXTURE_2D) != 0,
                on,
                "unit {unit}'s GL_TEXTURE_2D"
            );
            assert_eq!(
                ffvkIsEnabled(x, TEXTURE_GEN_R) != 0,
                on,
                "unit {unit}'s GL_TEXTURE_GEN_R"
            );
            assert_eq!(floats(x, TEXTURE_2D, 1), [on as u8 as f32]);
            assert_eq!(
                tex_env(TEXTURE_ENV_MODE),
                [MODULATE, REPLACE, 0x8570, 0x0104][unit as usize] as i32
            );
            assert_eq!(
                tex_env(SRC0_RGB + 1),
                (TEXTURE0 + 3 - unit) as i32,
                "GL_TEXTUREn answered"
            );
            assert_eq!(tex_env(SRC0_ALPHA), (TEXTURE0 + unit) as i32);
            assert_eq!(tex_env(SRC0_RGB), TEXTURE as i32, "untouched: GL_TEXTURE");
            let mut plane = [SENTINEL_F; 4];
            ffvkGetTexGenfv(x, T, OBJECT_PLANE, plane.as_mut_ptr());
            assert_eq!(plane, [k, 0.0, 0.0, 1.0]);
            let mut replace = SENTINEL_I;
            ffvkGetTexEnviv(x, POINT_SPRITE, COORD_REPLACE, &mut replace);
            assert_eq!(replace, (unit == 2) as i32);
        }
        // A refused unit leaves the active one.
        ffvkActiveTexture(x, TEXTURE0 + 4);
        assert_eq!(c.error(), INVALID_ENUM);
        assert_eq!(floats(x, ACTIVE_TEXTURE, 1), [(TEXTURE0 + 3) as f32]);
        assert_eq!(c.error(), NO_ERROR);
    }
}

#[test]
fn gl_tex_gen_refuses_an_unknown_coord_pname_or_mode_and_a_mode_the_coordinate_does_not_take() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let (f4, i4, d4) = ([0.5f32; 4], [1i32; 4], [0.5f64; 4]);
    let (f, i, d) = (f4.as_ptr(), i4.as_ptr(), d4.as_ptr());
    let (mut f16, mut i16, mut d16) = ([SENTINEL_F; 16], [SENTINEL_I; 16], [f64::from(SENTINEL_F); 16]);
    let (fo, io, dout) = (f16.as_mut_ptr(), i16.as_mut_ptr(), d16.as_mut_ptr());
    let mode = TEXTURE_GEN_MODE;
    // SAFETY: a live context for every call below; params point at 4 values, query buffers
    // at 16.
    unsafe {
        for coord in [BOGUS, 0, S - 1, Q + 1, TEXTURE_GEN_S] {
            let words = ["coord", &hex(coord), "GL_S, GL_T, GL_R or GL_Q"];
            assert_each_refused!(c, before, INVALID_ENUM, words, {
                ffvkTexGeni(x, coord, mode, OBJECT_LINEAR as i32);
                ffvkTexGenf(x, coord, mode, OBJECT_LINEAR as f32);
                ffvkTexGend(x, coord, mode, f64::from(OBJECT_LINEAR));
                ffvkTexGeniv(x, coord, OBJECT_PLANE, i);
                ffvkTexGenfv(x, coord, EYE_PLANE, f);
                ffvkTexGendv(x, coord, OBJECT_PLANE, d);
                ffvkGetTexGeniv(x, coord, mode, io);
                ffvkGetTexGenfv(x, coord, OBJECT_PLANE, fo);
                ffvkGetTexGendv(x, coord, EYE_PLANE, dout);
            });
        }
        for pname in [BOGUS, 0, TEXTURE_GEN_S, TEXTURE_ENV_MODE, EYE_PLANE + 1] {
            let words = [
                "pname",
                &hex(pname),
                "GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE or GL_EYE_PLANE",
            ];
            assert_each_refused!(c, before, INVALID_ENUM, words, {
                ffvkTexGeni(x, S, pname, OBJECT_LINEAR as i32);
                ffvkTexGenf(x, T, pname, OBJECT_LINEAR as f32);
                ffvkTexGend(x, R, pname, f64::from(OBJECT_LINEAR));
                ffvkTexGeniv(x, Q, pname, i);
                ffvkTexGenfv(x, S, pname, f);
                ffvkTexGendv(x, T, pname, d);
                ffvkGetTexGeniv(x, R, pname, io);
                ffvkGetTexGenfv(x, Q, pname, fo);
                ffvkGetTexGendv(x, S, pname, dout);
            });
        }
        // A plane has 4 values: not for the scalar entry points (§2.11.4).
        for pname in [OBJECT_PLANE, EYE_PLANE] {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["pname", &hex(pname), "single-valued"],
                {
                    ffvkTexGeni(x, S, pname, 1);
                    ffvkTexGenf(x, T, pname, 1.0);
                    ffvkTexGend(x, Q, pname, 1.0);
                }
            );
        }
        for value in [BOGUS, 0, OBJECT_PLANE, TEXTURE_GEN_S, EYE_LINEAR - 1] {
            let (fv, iv, dv) = ([value as f32; 4], [value as i32; 4], [f64::from(value); 4]);
            let words = ["GL_T's GL_TEXTURE_GEN_MODE", &hex(value), "GL_OBJECT_LINEAR"];
            assert_each_refused!(c, before, INVALID_ENUM, words, {
                ffvkTexGeni(x, T, mode, value as i32);
                ffvkTexGenf(x, T, mode, value as f32);
                ffvkTexGend(x, T, mode, f64::from(value));
                ffvkTexGeniv(x, T, mode, iv.as_ptr());
                ffvkTexGenfv(x, T, mode, fv.as_ptr());
                ffvkTexGendv(x, T, mode, dv.as_ptr());
            });
        }
        // GL_SPHERE_MAP is for S and T, GL_REFLECTION_MAP and GL_NORMAL_MAP for S, T and R.
        for (coord, name, value, why) in [
            (R, "GL_R", SPHERE_MAP, "for S and T only"),
            (Q, "GL_Q", SPHERE_MAP, "for S and T only"),
            (Q, "GL_Q", REFLECTION_MAP, "for S, T and R"),
            (Q, "GL_Q", NORMAL_MAP, "for S, T and R"),
        ] {
            let words = [name, "GL_TEXTURE_GEN_MODE", &hex(value), why];
            assert_each_refused!(c, before, INVALID_ENUM, words, {
                ffvkTexGeni(x, coord, mode, value as i32);
                ffvkTexGenf(x, coord, mode, value as f32);
                ffvkTexGendv(x, coord, mode, [f64::from(value)].as_ptr());
            });
        }
        // An enum is checked before the values are looked at.
        assert_each_refused!(c, before, INVALID_ENUM, ["0x1234"], {
            ffvkTexGenfv(x, BOGUS, OBJECT_PLANE, null());
            ffvkTexGendv(x, S, BOGUS, null());
            ffvkGetTexGeniv(x, BOGUS, OBJECT_PLANE, null_mut());
        });
        // A double's alignment is 8 bytes.
        let mut bytes = [0x5Au8; 160];
        let dm = misaligned(bytes.as_mut_ptr().cast::<f64>().cast_const());
        assert_each_refused!(
            c,
            before,
            INVALID_VALUE,
            ["params 0x", "not aligned to 8 bytes"],
            {
                ffvkTexGendv(x, S, OBJECT_PLANE, dm);
                ffvkGetTexGendv(x, T, EYE_PLANE, dm.cast_mut());
            }
        );
        assert!(
            bytes.iter().all(|&b| b == 0x5A),
            "written through a misaligned pointer"
        );
    }
    assert_eq!(f16, [SENTINEL_F; 16], "a refused query wrote");
    assert_eq!(i16, [SENTINEL_I; 16], "a refused query wrote");
    assert_eq!(d16, [f64::from(SENTINEL_F); 16], "a refused query wrote");
}

#[test]
fn a_non_finite_plane_value_or_a_singular_modelview_sets_invalid_value_and_keeps_the_planes() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for bad in NON_FINITE {
        let shown = bad.to_string();
        for at in 0..4 {
            let bad_d = with_bad(at, bad).map(f64::from);
            // SAFETY: a live context; 16 values.
            unsafe {
                assert_each_refused!(c, before, INVALID_VALUE, [&shown, "not a finite number"], {
                    ffvkTexGenfv(x, S, OBJECT_PLANE, with_bad(at, bad).as_ptr());
                    ffvkTexGenfv(x, T, EYE_PLANE, with_bad(at, bad).as_ptr());
                    ffvkTexGendv(x, Q, OBJECT_PLANE, bad_d.as_ptr());
                    ffvkTexGendv(x, R, EYE_PLANE, bad_d.as_ptr());
                });
            }
        }
        // A mode given as a float that is not finite is no enum: ffvk's GL_INVALID_VALUE.
        // SAFETY: a live context.
        unsafe {
            assert_each_refused!(c, before, INVALID_VALUE, [&shown, "not a finite number"], {
                ffvkTexGenf(x, S, TEXTURE_GEN_MODE, bad);
                ffvkTexGend(x, T, TEXTURE_GEN_MODE, f64::from(bad));
            });
        }
    }
    // A double past a float's range is not finite once stored.
    // SAFETY: a live context; 4 values.
    unsafe {
        assert_each_refused!(c, before, INVALID_VALUE, ["not a finite number"], {
            ffvkTexGendv(x, S, OBJECT_PLANE, [1e300, 0.0, 0.0, 0.0].as_ptr());
        });
    }
    // The eye plane is p · M⁻¹: a modelview without an inverse is refused.
    let singular: [f32; 16] = [1., 0., 0., 0., 0., 0., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.];
    // SAFETY: a live context; 16 and 4 values.
    unsafe {
        ffvkLoadModelview(x, singular.as_ptr());
        assert_eq!(c.error(), NO_ERROR);
        let before = c.snapshot();
        assert_each_refused!(
            c,
            before,
            INVALID_VALUE,
            ["determinant of the modelview", "invertible"],
            {
                ffvkTexGenfv(x, T, EYE_PLANE, [0.0f32, 1.0, 0.0, 0.0].as_ptr());
            }
        );
        // The object plane takes no matrix.
        ffvkTexGenfv(x, T, OBJECT_PLANE, [0.0f32, 1.0, 0.0, 0.0].as_ptr());
        assert_eq!(c.error(), NO_ERROR, "{}", message());
    }
}

#[test]
fn gl_shade_model_refuses_anything_but_flat_and_smooth_with_invalid_enum() {
    let c = Ctx::busy();
    let before = c.snapshot();
    for mode in [0, BOGUS, FLAT - 1, SMOOTH + 1, u32::MAX] {
        // SAFETY: a live context.
        unsafe {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["mode", &hex(mode), "GL_FLAT or GL_SMOOTH"],
                {
                    ffvkShadeModel(c.0, mode);
                }
            );
        }
    }
}

#[test]
fn gl_get_refuses_a_name_outside_the_state_ffvk_keeps_and_writes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for pname in [BOGUS, 0, DITHER, LIGHT0 + 16, AMBIENT, TEXTURE_ENV_MODE, u32::MAX] {
        let mut f = [SENTINEL_F; 16];
        let mut i = [SENTINEL_I; 16];
        let mut b = [SENTINEL_B; 16];
        // SAFETY: a live context; 16 values of room in each buffer.
        unsafe {
            assert_each_refused!(
                c,
                before,
                INVALID_ENUM,
                ["pname", &hex(pname), "a state name: GL_LIGHTING"],
                {
                    ffvkGetFloatv(x, pname, f.as_mut_ptr());
                    ffvkGetIntegerv(x, pname, i.as_mut_ptr());
                    ffvkGetBooleanv(x, pname, b.as_mut_ptr());
                }
            );
        }
        assert!(
            f.iter().all(|&v| v == SENTINEL_F),
            "GetFloatv({}) wrote {f:?}",
            hex(pname)
        );
        assert!(
            i.iter().all(|&v| v == SENTINEL_I),
            "GetIntegerv({}) wrote {i:?}",
            hex(pname)
        );
        assert!(
            b.iter().all(|&v| v == SENTINEL_B),
            "GetBooleanv({}) wrote {b:?}",
            hex(pname)
        );
    }
}

#[test]
fn an_invalid_enum_is_refused_before_a_null_params_is_looked_at() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    // SAFETY: a live context; params is null, which the enum checks come before.
    unsafe {
        assert_each_refused!(c, before, INVALID_ENUM, ["0x4010"], {
            ffvkLightfv(x, LIGHT0 + 16, AMBIENT, null());
            ffvkGetLightiv(x, LIGHT0 + 16, AMBIENT, null_mut());
        });
        assert_each_refused!(c, before, INVALID_ENUM, ["0x1234"], {
            ffvkMaterialiv(x, FRONT, BOGUS, null());
            ffvkGetFloatv(x, BOGUS, null_mut());
        });
    }
}

// ---------------------------------------------------------------------------------------
// Non-finite and out-of-range values: GL_INVALID_VALUE, nothing changed.

const NON_FINITE: [f32; 3] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];

/// `values` with `bad` at index `at`.
fn with_bad(at: usize, bad: f32) -> [f32; 16] {
    let mut v = [0.5f32; 16];
    v[at] = bad;
    v
}

#[test]
fn a_non_finite_light_value_sets_invalid_value_and_changes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for (pname, len) in LIGHT_PNAMES.into_iter().zip([4, 4, 4, 4, 3, 1, 1, 1, 1, 1]) {
        for bad in NON_FINITE {
            let shown = bad.to_string();
            for at in 0..len {
                // SAFETY: a live context; 16 values.
                unsafe {
                    assert_each_refused!(c, before, INVALID_VALUE, [&shown, "not a finite number"], {
                        ffvkLightfv(x, LIGHT0 + 1, pname, with_bad(at, bad).as_ptr());
                    });
                }
            }
            if len == 1 {
                // SAFETY: a live context.
                unsafe {
                    assert_each_refused!(c, before, INVALID_VALUE, [&shown, "not a finite number"], {
                        ffvkLightf(x, LIGHT0 + 15, pname, bad);
                    });
                }
            }
        }
    }
}

#[test]
fn a_non_finite_material_value_sets_invalid_value_and_changes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let pnames = [
        AMBIENT,
        DIFFUSE,
        SPECULAR,
        EMISSION,
        AMBIENT_AND_DIFFUSE,
        SHININESS,
        COLOR_INDEXES,
    ];
    for (pname, len) in pnames.into_iter().zip([4, 4, 4, 4, 4, 1, 3]) {
        for face in [FRONT, BACK, FRONT_AND_BACK] {
            for bad in NON_FINITE {
                for at in 0..len {
                    // SAFETY: a live context; 16 values.
                    unsafe {
                        assert_each_refused!(c, before, INVALID_VALUE, [&bad.to_string(), "not a finite"], {
                            ffvkMaterialfv(x, face, pname, with_bad(at, bad).as_ptr());
                        });
                    }
                }
            }
        }
    }
    for bad in NON_FINITE {
        // SAFETY: a live context.
        unsafe {
            assert_each_refused!(c, before, INVALID_VALUE, ["GL_SHININESS", &bad.to_string()], {
                ffvkMaterialf(x, FRONT_AND_BACK, SHININESS, bad);
            });
        }
    }
}

#[test]
fn a_non_finite_light_model_value_sets_invalid_value_and_changes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for bad in NON_FINITE {
        let shown = bad.to_string();
        for at in 0..4 {
            // SAFETY: a live context; 16 values.
            unsafe {
                assert_each_refused!(c, before, INVALID_VALUE, ["GL_LIGHT_MODEL_AMBIENT", &shown], {
                    ffvkLightModelfv(x, LIGHT_MODEL_AMBIENT, with_bad(at, bad).as_ptr());
                });
            }
        }
        // A boolean or an enum given as a float that is not a number is no value at all: not
        // true (as non-zero would be), not an enum (as some truncated integer would be).
        for (pname, name) in [
            (LIGHT_MODEL_LOCAL_VIEWER, "GL_LIGHT_MODEL_LOCAL_VIEWER"),
            (LIGHT_MODEL_TWO_SIDE, "GL_LIGHT_MODEL_TWO_SIDE"),
            (LIGHT_MODEL_COLOR_CONTROL, "GL_LIGHT_MODEL_COLOR_CONTROL"),
        ] {
            // SAFETY: a live context; 16 values.
            unsafe {
                assert_each_refused!(c, before, INVALID_VALUE, [name, &shown, "not a finite number"], {
                    ffvkLightModelf(x, pname, bad);
                    ffvkLightModelfv(x, pname, with_bad(0, bad).as_ptr());
                });
            }
        }
    }
    // The busy context's booleans are true: a refused NaN must not have left them so by
    // chance. From GL's initial state (false), NaN must not make them true either.
    let fresh = Ctx::new();
    // SAFETY: a live context.
    unsafe {
        ffvkLightModelf(fresh.0, LIGHT_MODEL_TWO_SIDE, f32::NAN);
        ffvkLightModelf(fresh.0, LIGHT_MODEL_LOCAL_VIEWER, f32::NAN);
    }
    let mut got = [SENTINEL_B; 2];
    // SAFETY: a live context; one value each.
    unsafe {
        ffvkGetBooleanv(fresh.0, LIGHT_MODEL_TWO_SIDE, got.as_mut_ptr());
        ffvkGetBooleanv(fresh.0, LIGHT_MODEL_LOCAL_VIEWER, got.as_mut_ptr().add(1));
    }
    assert_eq!(got, [0, 0], "NaN made a light model boolean true");
}

#[test]
fn a_non_finite_texture_environment_value_sets_invalid_value_and_changes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let (env, mode, color) = (TEXTURE_ENV, TEXTURE_ENV_MODE, TEXTURE_ENV_COLOR);
    for bad in NON_FINITE {
        let shown = bad.to_string();
        for at in 0..4 {
            // SAFETY: a live context; 16 values.
            unsafe {
                assert_each_refused!(c, before, INVALID_VALUE, ["GL_TEXTURE_ENV_COLOR", &shown], {
                    ffvkTexEnvfv(x, env, color, with_bad(at, bad).as_ptr());
                });
            }
        }
        // SAFETY: a live context; 16 values.
        unsafe {
            assert_each_refused!(
                c,
                before,
                INVALID_VALUE,
                ["GL_TEXTURE_ENV_MODE", &shown, "not a finite"],
                {
                    ffvkTexEnvf(x, env, mode, bad);
                    ffvkTexEnvfv(x, env, mode, with_bad(0, bad).as_ptr());
                }
            );
        }
    }
}

#[test]
fn a_non_finite_normal_or_texture_coordinate_sets_invalid_value_and_keeps_the_current_ones() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for bad in NON_FINITE {
        let shown = bad.to_string();
        for at in 0..4 {
            let v = with_bad(at, bad);
            // SAFETY: a live context.
            unsafe {
                if at < 3 {
                    assert_each_refused!(c, before, INVALID_VALUE, ["GL_CURRENT_NORMAL", &shown], {
                        ffvkNormal3f(x, v[0], v[1], v[2]);
                    });
                }
                assert_each_refused!(c, before, INVALID_VALUE, ["GL_CURRENT_TEXTURE_COORDS", &shown], {
                    ffvkTexCoord4f(x, v[0], v[1], v[2], v[3]);
                });
                if at < 2 {
                    assert_each_refused!(c, before, INVALID_VALUE, ["GL_CURRENT_TEXTURE_COORDS", &shown], {
                        ffvkTexCoord2f(x, v[0], v[1]);
                    });
                }
            }
        }
    }
    // The byte form converts as GL 2.1 does: (2c + 1)/255.
    // SAFETY: a live context; room for the 4 values asked.
    unsafe {
        ffvkNormal3b(x, -128, 0, 127);
        let mut n = [0.0f32; 4];
        ffvkGetFloatv(x, CURRENT_NORMAL, n.as_mut_ptr());
        assert_eq!(&n[..3], &[-1.0, 1.0 / 255.0, 1.0]);
    }
}

#[test]
fn a_non_finite_color_sets_invalid_value_and_keeps_the_current_color_and_the_materials() {
    let c = Ctx::busy();
    let x = c.0;
    // SAFETY: a live context.
    unsafe { ffvkEnable(x, COLOR_MATERIAL) };
    assert_eq!(c.error(), NO_ERROR);
    let before = c.snapshot();
    for bad in NON_FINITE {
        let shown = bad.to_string();
        for at in 0..4 {
            let v = with_bad(at, bad);
            // SAFETY: a live context.
            unsafe {
                assert_each_refused!(c, before, INVALID_VALUE, ["GL_CURRENT_COLOR", &shown], {
                    ffvkColor4f(x, v[0], v[1], v[2], v[3]);
                });
                if at < 3 {
                    assert_each_refused!(c, before, INVALID_VALUE, ["GL_CURRENT_COLOR", &shown], {
                        ffvkColor3f(x, v[0], v[1], v[2]);
                    });
                }
            }
        }
    }
}

#[test]
fn a_non_finite_matrix_component_sets_invalid_value_and_keeps_the_matrix() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    for bad in NON_FINITE {
        let shown = bad.to_string();
        for at in 0..16 {
            let m = with_bad(at, bad);
            // SAFETY: a live context; 16 floats.
            unsafe {
                assert_each_refused!(c, before, INVALID_VALUE, [&shown, "not a finite number"], {
                    ffvkLoadModelview(x, m.as_ptr());
                    ffvkLoadProjection(x, m.as_ptr());
                    ffvkLoadTextureMatrix(x, m.as_ptr());
                });
            }
        }
    }
}

#[test]
fn a_value_outside_gls_range_sets_invalid_value_and_changes_nothing() {
    let c = Ctx::busy();
    let x = c.0;
    let before = c.snapshot();
    let cutoff = "[0, 90] or exactly 180";
    for (pname, value, name, expected) in [
        (SPOT_EXPONENT, 128.5, "GL_SPOT_EXPONENT", "[0, 128]"),
        (SPOT_EXPONENT, -1.0, "GL_SPOT_EXPONENT", "[0, 128]"),
        (SPOT_EXPONENT, f32::MAX, "GL_SPOT_EXPONENT", "[0, 128]"),
        (SPOT_CUTOFF, 91.0, "GL_SPOT_CUTOFF", cutoff),
        (SPOT_CUTOFF, -0.5, "GL_SPOT_CUTOFF", cutoff),
        (SPOT_CUTOFF, 179.0, "GL_SPOT_CUTOFF", cutoff),
        (SPOT_CUTOFF, 181.0, "GL_SPOT_CUTOFF", cutoff),
        (CONSTANT_ATTENUATION, -1.0, "GL_CONSTANT_ATTENUATION", ">= 0"),
        (CONSTANT_ATTENUATION, f32::MIN, "GL_CONSTANT_ATTENUATION", ">= 0"),
        (LINEAR_ATTENUATION, -0.001, "GL_LINEAR_ATTENUATION", ">= 0"),
        (QUADRATIC_ATTENUATION, -5.0, "GL_QUADRATIC_ATTENUATION", ">= 0"),
    ] {
        let shown = value.to_string();
        // SAFETY: a live context; 4 values.
        unsafe {
            assert_each_refused!(c, before, INVALID_VALUE, [name, &shown, expected], {
                ffvkLightf(x, LIGHT0 + 1, pname, value);
                ffvkLightfv(x, LIGHT0, pname, [value; 4].as_ptr());
            });
            if value.fract() == 0.0 && value.abs() < 1e9 {
                assert_each_refused!(c, before, INVALID_VALUE, [name, &shown, expected], {
                    ffvkLighti(x, LIGHT0 + 15, pname, value as i32);
                    ffvkLightiv(x, LIGHT0 + 2, pname, [value as i32; 4].as_ptr());
                });
            }
        }
    }
    // SAFETY: a live context.
    unsafe {
        assert_each_refused!(c, before, INVALID_VALUE, ["GL_SHININESS", "[0, 128]"], {
            ffvkMaterialf(x, FRONT, SHININESS, 128.5);
            ffvkMaterialf(x, BACK, SHININESS, -0.25);
            ffvkMaterialf(x, FRONT_AND_BACK, SHININESS, 1000.0);
            ffvkMateriali(x, FRONT_AND_BACK, SHININESS, 129);
            ffvkMaterialfv(x, FRONT, SHININESS, [-1.0f32; 4].as_ptr());
        });
    }
}

#[test]
fn the_ends_of_gls_ranges_are_accepted() {
    let c = Ctx::new();
    // SAFETY: a live context; 16 values of room.
    unsafe {
        for (pname, value) in [
            (SPOT_EXPONENT, 0.0),
            (SPOT_EXPONENT, 128.0),
            (SPOT_CUTOFF, 0.0),
            (SPOT_CUTOFF, 90.0),
            (SPOT_CUTOFF, 180.0),
            (CONSTANT_ATTENUATION, 0.0),
            (LINEAR_ATTENUATION, 0.0),
            (QUADRATIC_ATTENUATION, f32::MAX),
        ] {
            ffvkLightf(c.0, LIGHT0, pname, value);
            assert_eq!(c.error(), NO_ERROR, "{} = {value}: {}", hex(pname), message());
            let mut got = [SENTINEL_F; 16];
            ffvkGetLightfv(c.0, LIGHT0, pname, got.as_mut_ptr());
            assert_eq!(got[0], value);
        }
        ffvkMaterialf(c.0, FRONT_AND_BACK, SHININESS, 128.0);
        assert_eq!(c.error(), NO_ERROR);
    }
}

// ---------------------------------------------------------------------------------------
// GL's error flag and the messages.

#[test]
fn the_first_error_sticks_until_get_error_reads_it_and_then_there_is_none() {
    let c = Ctx::busy();
    let before = c.snapshot();
    // SAFETY: a live context.
    unsafe {
        ffvkEnable(c.0, BOGUS); // GL_INVALID_ENUM
        ffvkLightf(c.0, LIGHT0, SPOT_CUTOFF, 91.0); // GL_INVALID_VALUE, dropped
        ffvkEnable(c.0, LIGHTING); // valid: the flag stays
    }
    let text = message();
    assert_eq!(c.error(), INVALID_ENUM, "{text}");
    assert_eq!(c.error(), NO_ERROR);
    assert_eq!(c.error(), NO_ERROR);
    assert_names(&text, &["ffvkEnable", "0x1234"]);
    assert!(
        !text.contains("GL_SPOT_CUTOFF"),
        "the message follows the kept error: {text}"
    );

    // The other order: GL_INVALID_VALUE kept, GL_INVALID_ENUM dropped.
    // SAFETY: a live context; 16 values of room.
    unsafe {
        ffvkMaterialf(c.0, FRONT, SHININESS, -1.0);
        ffvkShadeModel(c.0, BOGUS);
        ffvkGetFloatv(c.0, BOGUS, [0.0; 16].as_mut_ptr());
    }
    let text = message();
    assert_eq!(c.error(), INVALID_VALUE, "{text}");
    assert_eq!(c.error(), NO_ERROR);
    assert_names(&text, &["ffvkMaterialf", "GL_SHININESS", "-1"]);
    assert_unchanged(&before, &c.snapshot(), "three refused calls");
}

#[test]
fn errors_on_one_context_do_not_show_on_another() {
    let a = Ctx::busy();
    let b = Ctx::new();
    let b_before = b.snapshot();
    // SAFETY: live contexts.
    unsafe {
        ffvkEnable(a.0, BOGUS);
        ffvkLightf(a.0, LIGHT0, SPOT_EXPONENT, 3.0);
    }
    assert_eq!(b.error(), NO_ERROR);
    assert_unchanged(&b_before, &b.snapshot(), "calls on another context");
    assert_eq!(a.error(), INVALID_ENUM);
}

#[test]
fn messages_name_the_function_the_parameter_the_value_and_what_was_expected() {
    let c = Ctx::new();
    let x = c.0;
    let expect = |words: &[&str]| {
        let text = message();
        assert_ne!(c.error(), NO_ERROR, "{text}");
        assert_names(&text, words);
    };
    // SAFETY: a live context; params point at 4 values (16 for the query) or are null.
    unsafe {
        ffvkLightf(x, LIGHT0, SPOT_CUTOFF, 91.0);
        expect(&[
            "ffvkLightf: GL_SPOT_CUTOFF = 91",
            "expected a value in [0, 90] or exactly 180",
        ]);
        ffvkEnable(x, LIGHT0 + 16);
        expect(&[
            "ffvkEnable: cap 0x4010",
            "expected",
            "GL_LIGHT0 .. GL_LIGHT0 + 15",
            "GL_INVALID_ENUM",
        ]);
        ffvkLightfv(x, LIGHT0 + 20, AMBIENT, [0.0f32; 4].as_ptr());
        expect(&[
            "ffvkLightfv: light 0x4014",
            "GL_MAX_LIGHTS is 16",
            "GL_INVALID_ENUM",
        ]);
        ffvkMaterialfv(x, FRONT, SHININESS, [200.0f32; 4].as_ptr());
        expect(&[
            "ffvkMaterialfv: GL_SHININESS = 200",
            "expected a value in [0, 128]",
            "GL_INVALID_VALUE",
        ]);
        ffvkMaterialf(x, FRONT, AMBIENT, 1.0);
        expect(&[
            "ffvkMaterialf: pname GL_AMBIENT (0x1200)",
            "expected GL_SHININESS",
            "GL_INVALID_ENUM",
        ]);
        ffvkTexEnvi(x, TEXTURE_ENV, SRC0_RGB, (TEXTURE0 + 4) as i32);
        expect(&[
            "ffvkTexEnvi: GL_SRC0_RGB value GL_TEXTURE4 (0x84C4) is not accepted",
            "expected GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS or GL_TEXTURE0 .. GL_TEXTURE3",
            "GL_INVALID_ENUM",
        ]);
        ffvkActiveTexture(x, TEXTURE0 + 4);
        expect(&[
            "ffvkActiveTexture: texture GL_TEXTURE4 (0x84C4) is not accepted",
            "expected GL_TEXTURE0 .. GL_TEXTURE3 (GL_MAX_TEXTURE_UNITS is 4)",
            "GL_INVALID_ENUM",
        ]);
        ffvkMultiTexCoord2f(x, 0x1234, 0.0, 0.0);
        expect(&[
            "ffvkMultiTexCoord2f: target 0x1234 is not accepted",
            "expected GL_TEXTURE0 .. GL_TEXTURE3 (GL_MAX_TEXTURE_COORDS is 4)",
            "GL_INVALID_ENUM",
        ]);
        ffvkMultiTexCoord4f(x, TEXTURE0 + 1, 0.0, f32::NAN, 0.0, 1.0);
        expect(&["ffvkMultiTexCoord4f", "NaN", "GL_INVALID_VALUE"]);
        ffvkColorMaterial(x, FRONT, SHININESS);
        expect(&[
            "ffvkColorMaterial: mode GL_SHININESS (0x1601)",
            "expected GL_EMISSION",
            "GL_AMBIENT_AND_DIFFUSE",
        ]);
        ffvkLightiv(x, LIGHT0, POSITION, null());
        expect(&[
            "ffvkLightiv: params is a null pointer",
            "expected the parameter's 4 value(s)",
        ]);
        ffvkLightModelf(x, LIGHT_MODEL_TWO_SIDE, f32::NAN);
        expect(&[
            "ffvkLightModelf: GL_LIGHT_MODEL_TWO_SIDE = NaN is not a finite number",
            "expected",
        ]);
        ffvkGetMaterialfv(x, FRONT_AND_BACK, AMBIENT, [0.0f32; 16].as_mut_ptr());
        expect(&[
            "ffvkGetMaterialfv: face GL_FRONT_AND_BACK (0x0408)",
            "expected GL_FRONT or GL_BACK",
            "GL_INVALID_ENUM",
        ]);
        ffvkLoadProjection(x, with_bad(7, f32::INFINITY).as_ptr());
        expect(&[
            "ffvkLoadProjection",
            "inf is not a finite number",
            "expected 16 finite floats",
        ]);
    }
}

#[test]
fn messages_name_a_gl_enum_by_its_gl_name_and_a_value_gl_has_no_name_for_in_hex() {
    const SCISSOR_TEST: u32 = 0x0C11;
    const VERTEX_ARRAY: u32 = 0x8074;
    let c = Ctx::new();
    let x = c.0;
    let expect = |words: &[&str]| {
        let text = message();
        assert_eq!(c.error(), INVALID_ENUM, "{text}");
        assert_names(&text, words);
    };
    // SAFETY: a live context; params point at 4 values.
    unsafe {
        // Names the API refuses, as a layer forwarding every glEnable passes them.
        ffvkEnable(x, SCISSOR_TEST);
        expect(&["ffvkEnable: cap GL_SCISSOR_TEST (0x0C11) is not accepted"]);
        ffvkDisable(x, VERTEX_ARRAY);
        expect(&["ffvkDisable: cap GL_VERTEX_ARRAY (0x8074) is not accepted"]);
        ffvkTexEnvi(x, TEXTURE_ENV, SRC0_ALPHA, (TEXTURE0 + 9) as i32);
        expect(&["GL_SRC0_ALPHA value GL_TEXTURE9 (0x84C9) is not accepted"]);
        ffvkGetFloatv(x, 0x84E1, [0.0f32; 16].as_mut_ptr());
        expect(&["ffvkGetFloatv: pname GL_CLIENT_ACTIVE_TEXTURE (0x84E1) is not accepted"]);
        // Names the API takes, where they do not belong.
        ffvkLightfv(x, LIGHT0, SHININESS, [0.0f32; 4].as_ptr());
        expect(&["ffvkLightfv: pname GL_SHININESS (0x1601) is not accepted"]);
        ffvkGetMaterialfv(x, FRONT_AND_BACK, AMBIENT, [0.0f32; 16].as_mut_ptr());
        expect(&["ffvkGetMaterialfv: face GL_FRONT_AND_BACK (0x0408) is not accepted"]);
        // Values GL has no name for, and values below 0x0100 (booleans and primitive modes
        // share them), stay hex.
        ffvkEnable(x, LIGHT0 + 16);
        expect(&["ffvkEnable: cap 0x4010 is not accepted"]);
        ffvkShadeModel(x, TRIANGLES);
        expect(&["ffvkShadeModel: mode 0x0004 is not accepted"]);
    }
}

#[test]
fn every_gl_name_a_message_prints_has_the_value_gl_h_gives_it() {
    let mut headers = String::new();
    for path in ["/usr/include/GL/gl.h", "/usr/include/GL/glext.h"] {
        headers += &std::fs::read_to_string(path)
            .unwrap_or_else(|e| panic!("{path}: {e} (install the Debian package libgl-dev)"));
    }
    let names: Vec<(&str, u32)> = ffvk_c::enums::message_names().collect();
    for (i, (name, _)) in names.iter().enumerate() {
        assert!(
            !names[..i].iter().any(|(n, _)| n == name),
            "{name} is listed twice"
        );
    }
    for (name, value) in names {
        let defined = headers.lines().find_map(|line| {
            let mut words = line.split_whitespace();
            (words.next() == Some("#define") && words.next() == Some(name))
                .then(|| words.next())
                .flatten()
        });
        let defined = defined.unwrap_or_else(|| panic!("<GL/gl.h> does not define {name}"));
        let parsed = u32::from_str_radix(defined.trim_start_matches("0x"), 16)
            .unwrap_or_else(|e| panic!("{name} is {defined} in <GL/gl.h>: {e}"));
        assert_eq!(parsed, value, "{name}: <GL/gl.h> says {defined}");
    }
}

#[test]
fn the_message_is_never_null_and_empty_on_a_thread_that_had_no_failure() {
    std::thread::spawn(|| {
        assert_eq!(message(), "");
        let c = Ctx::new();
        // SAFETY: a live context; valid calls leave no message.
        unsafe {
            ffvkEnable(c.0, LIGHTING);
            ffvkLightf(c.0, LIGHT0, SPOT_CUTOFF, 30.0);
        }
        assert_eq!(c.error(), NO_ERROR);
        assert_eq!(message(), "");
    })
    .join()
    .unwrap();
}

#[test]
fn the_enums_this_test_spells_are_the_headers() {
    let table = ffvk_c::enums::gl_enums();
    let value = |name: &str| {
        let found = table.iter().find(|(n, _)| *n == name);
        found.unwrap_or_else(|| panic!("{name} is not in the header")).1
    };
    for (name, ours) in [
        ("GL_INVALID_ENUM", INVALID_ENUM),
        ("GL_INVALID_VALUE", INVALID_VALUE),
        ("GL_LIGHTING", LIGHTING),
        ("GL_LIGHT0", LIGHT0),
        ("GL_COLOR_MATERIAL", COLOR_MATERIAL),
        ("GL_RESCALE_NORMAL", RESCALE_NORMAL),
        ("GL_TEXTURE_2D", TEXTURE_2D),
        ("GL_SPOT_CUTOFF", SPOT_CUTOFF),
        ("GL_QUADRATIC_ATTENUATION", QUADRATIC_ATTENUATION),
        ("GL_COLOR_INDEXES", COLOR_INDEXES),
        ("GL_FRONT_AND_BACK", FRONT_AND_BACK),
        ("GL_LIGHT_MODEL_COLOR_CONTROL", LIGHT_MODEL_COLOR_CONTROL),
        ("GL_SEPARATE_SPECULAR_COLOR", SEPARATE_SPECULAR_COLOR),
        ("GL_COLOR_MATERIAL_PARAMETER", COLOR_MATERIAL_PARAMETER),
        ("GL_TEXTURE_MATRIX", TEXTURE_MATRIX),
        ("GL_TEXTURE_ENV_COLOR", TEXTURE_ENV_COLOR),
        ("GL_REPLACE", REPLACE),
        ("GL_LINE_LOOP", LINE_LOOP),
        ("GL_QUAD_STRIP", QUAD_STRIP),
        ("GL_POLYGON", POLYGON),
    ] {
        assert_eq!(value(name), ours, "{name}");
    }
}

// ---------------------------------------------------------------------------------------
// Threads.

#[test]
fn contexts_on_different_threads_are_independent() {
    const THREADS: u32 = 4;
    const ROUNDS: u32 = 2000;
    std::thread::scope(|s| {
        for t in 0..THREADS {
            s.spawn(move || {
                let c = Ctx::new();
                let light = LIGHT0 + t;
                let bogus = 0x7000 + t;
                for round in 0..ROUNDS {
                    let v = [t as f32, round as f32, 0.25, 1.0];
                    let exponent = (round % 128) as f32;
                    let mut got = [SENTINEL_F; 16];
                    // SAFETY: this thread's own live context; 4 values in, 16 of room out.
                    unsafe {
                        ffvkLightfv(c.0, light, DIFFUSE, v.as_ptr());
                        ffvkLightf(c.0, light, SPOT_EXPONENT, exponent);
                        ffvkEnable(c.0, bogus);
                    }
                    // The message is this thread's: it names this thread's bogus cap.
                    assert_names(&message(), &["ffvkEnable", &hex(bogus)]);
                    assert_eq!(c.error(), INVALID_ENUM);
                    assert_eq!(c.error(), NO_ERROR);
                    // SAFETY: as above.
                    unsafe { ffvkGetLightfv(c.0, light, DIFFUSE, got.as_mut_ptr()) };
                    assert_eq!(got[..4], v, "thread {t} round {round}");
                    // SAFETY: as above.
                    unsafe { ffvkGetLightfv(c.0, light, SPOT_EXPONENT, got.as_mut_ptr()) };
                    assert_eq!(got[0], exponent);
                    // Other threads' lights are not this context's: still GL's defaults.
                    let other = LIGHT0 + (t + 1) % THREADS;
                    // SAFETY: as above.
                    unsafe { ffvkGetLightfv(c.0, other, SPOT_EXPONENT, got.as_mut_ptr()) };
                    assert_eq!(got[0], 0.0, "thread {t} sees another thread's light");
                }
            });
        }
    });
}

// ---------------------------------------------------------------------------------------
// The renderer, up to what is checked before Vulkan is touched.

static LOADER_CALLS: AtomicUsize = AtomicUsize::new(0);

/// A `vkGetInstanceProcAddr` that must never be called: every create info here is refused
/// before ffvk loads anything.
unsafe extern "system" fn loader_never_called(_: vk::Instance, _: *const c_char) -> vk::PFN_vkVoidFunction {
    LOADER_CALLS.fetch_add(1, Ordering::SeqCst);
    None
}

static BINDINGS: [vk::VertexInputBindingDescription; 1] = [vk::VertexInputBindingDescription {
    binding: 0,
    stride: 24,
    input_rate: vk::VertexInputRate::VERTEX,
}];

static COLOR: FfvkAttribute = FfvkAttribute {
    binding: 0,
    offset: 0,
    format: vk::Format::R8G8B8A8_UNORM,
};

/// A create info that is valid up to Vulkan, with non-null handles that are never used: each
/// test breaks one field, so that creation stops before the loader.
fn create_info() -> FfvkRendererCreateInfo {
    let float3 = vk::Format::R32G32B32_SFLOAT;
    FfvkRendererCreateInfo {
        struct_size: size_of::<FfvkRendererCreateInfo>() as u32,
        get_instance_proc_addr: Some(loader_never_called),
        instance: vk::Instance::from_raw(0x1000),
        physical_device: vk::PhysicalDevice::from_raw(0x2000),
        device: vk::Device::from_raw(0x3000),
        enabled_features: FFVK_FEATURE_DYNAMIC_RENDERING,
        color_format: vk::Format::R8G8B8A8_UNORM,
        depth_format: vk::Format::D32_SFLOAT,
        samples: vk::SampleCountFlags::TYPE_1,
        bindings: BINDINGS.as_ptr(),
        binding_count: 1,
        position: FfvkAttribute {
            binding: 0,
            offset: 0,
            format: float3,
        },
        normal: FfvkAttribute {
            binding: 0,
            offset: 12,
            format: float3,
        },
        color: null(),
        texcoord: null(),
        frames_in_flight: 2,
        set_index: 0,
        pipeline_cache: vk::PipelineCache::null(),
    }
}

/// Creates a renderer from `info` into an out pointer that starts dangling, and asserts it
/// was refused with `FFVK_ERROR_INVALID_ARGUMENT`, the out pointer null, the loader not
/// called and a message naming each of `words`.
#[track_caller]
fn assert_create_refused(info: *const FfvkRendererCreateInfo, words: &[&str]) {
    let mut out: *mut FfvkRenderer = NonNull::dangling().as_ptr();
    // SAFETY: info is null, misaligned or a create info whose handles are never used (it is
    // refused before the loader); out is writable.
    let result = unsafe { ffvkCreateRenderer(info, &mut out) };
    let text = message();
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{text}");
    assert!(out.is_null(), "the out pointer is left {out:?} after an error");
    assert_eq!(LOADER_CALLS.load(Ordering::SeqCst), 0, "the loader was called");
    assert_names(&text, &["ffvkCreateRenderer: "]);
    assert_names(&text, words);
}

#[test]
fn create_renderer_with_a_null_or_misaligned_out_pointer_is_invalid_argument() {
    let info = create_info();
    let mut slot = [0u64; 2];
    let bad = misaligned(slot.as_mut_ptr().cast::<*mut FfvkRenderer>().cast_const()).cast_mut();
    // SAFETY: the null and misaligned out pointers are what is probed; info is refused before
    // Vulkan is touched.
    unsafe {
        assert_each_invalid_argument!(["renderer is a null pointer", "expected where to write"], {
            ffvkCreateRenderer(&info, null_mut());
            ffvkCreateRenderer(null(), null_mut());
        });
        assert_each_invalid_argument!(["renderer 0x", "not aligned to 8 bytes"], {
            ffvkCreateRenderer(&info, bad);
        });
    }
    assert_eq!(slot, [0, 0], "written through a misaligned out pointer");
    assert_eq!(LOADER_CALLS.load(Ordering::SeqCst), 0);
}

#[test]
fn create_renderer_with_a_null_info_is_invalid_argument_and_nulls_the_out_pointer() {
    assert_create_refused(
        null(),
        &["info is a null pointer", "expected an FfvkRendererCreateInfo"],
    );
}

#[test]
fn create_renderer_refuses_a_struct_size_that_no_published_header_declares_naming_the_sizes_accepted() {
    let v1 = size_of::<FfvkRendererCreateInfo>() as u32;
    let accepted = format!(
        "expected sizeof(FfvkRendererCreateInfo) as a published ffvk.h declares it, {v1} (version 1)"
    );
    for (size, why) in [
        (0u32, "smaller than version 1"),
        (4, "smaller than version 1"),
        (v1 - 8, "smaller than version 1"),
        (v1 - 1, "smaller than version 1"),
        (
            v1 + 1,
            "larger than any version this library (ffvk-c 0.1.0) knows",
        ),
        (v1 + 8, "a newer ffvk.h than the library it runs with"),
        (u32::MAX, "larger than any version"),
    ] {
        let mut info = create_info();
        info.struct_size = size;
        let given = format!("FfvkRendererCreateInfo.struct_size is {size}: ");
        assert_create_refused(&info, &[&given, why, &accepted]);
    }
}

#[test]
fn create_renderer_with_a_null_loader_is_invalid_argument() {
    let mut info = create_info();
    info.get_instance_proc_addr = None;
    assert_create_refused(
        &info,
        &["get_instance_proc_addr is null", "vkGetInstanceProcAddr"],
    );
}

#[test]
fn create_renderer_with_a_null_handle_is_invalid_argument_naming_it() {
    let mut info = create_info();
    info.instance = vk::Instance::null();
    assert_create_refused(
        &info,
        &["instance is VK_NULL_HANDLE", "expected the caller's instance"],
    );
    let mut info = create_info();
    info.physical_device = vk::PhysicalDevice::null();
    assert_create_refused(&info, &["physical_device is VK_NULL_HANDLE"]);
    let mut info = create_info();
    info.device = vk::Device::null();
    assert_create_refused(
        &info,
        &["device is VK_NULL_HANDLE", "expected the caller's device"],
    );
}

#[test]
fn create_renderer_with_no_frames_in_flight_is_invalid_argument() {
    let mut info = create_info();
    info.frames_in_flight = 0;
    assert_create_refused(&info, &["frames_in_flight is 0", "expected at least 1"]);
}

#[test]
fn create_renderer_with_unknown_feature_bits_is_invalid_argument() {
    for bits in [
        0x400u32,
        0x8000_0000,
        u32::MAX,
        FFVK_FEATURE_DYNAMIC_RENDERING | 0x400,
        FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP | 0x800,
    ] {
        let mut info = create_info();
        info.enabled_features = bits;
        let shown = format!("enabled_features 0x{bits:X} has unknown bits");
        assert_create_refused(&info, &[&shown, "expected FFVK_FEATURE_* flags (0x3FF)"]);
    }
}

#[test]
fn create_renderer_with_null_or_misaligned_bindings_is_invalid_argument() {
    let mut info = create_info();
    info.bindings = null();
    info.binding_count = 2;
    assert_create_refused(&info, &["bindings is null with a count of 2"]);
    let mut info = create_info();
    info.bindings = misaligned(BINDINGS.as_ptr());
    assert_create_refused(&info, &["bindings 0x", "not aligned to 4 bytes"]);
}

#[test]
fn create_renderer_refuses_frames_in_flight_past_the_limit_before_allocating_anything() {
    // Issue 46: a billion frame slots were allocated infallibly and aborted the host.
    for frames in [FFVK_MAX_FRAMES_IN_FLIGHT + 1, 1_000_000_000, u32::MAX] {
        let mut info = create_info();
        info.frames_in_flight = frames;
        let given = format!("frames_in_flight is {frames}");
        let expected = format!("expected 1..={FFVK_MAX_FRAMES_IN_FLIGHT}");
        assert_create_refused(&info, &[&given, &expected]);
    }
}

#[test]
fn create_renderer_refuses_a_binding_count_past_the_limit_before_reading_the_bindings() {
    // Only one binding lies at `bindings`: the count must be refused, never read or copied.
    for count in [FFVK_MAX_VERTEX_BINDINGS + 1, 1 << 30, u32::MAX] {
        let mut info = create_info();
        info.binding_count = count;
        let given = format!("binding_count is {count}");
        let expected = format!("expected at most {FFVK_MAX_VERTEX_BINDINGS}");
        assert_create_refused(&info, &[&given, &expected]);
    }
}

#[test]
fn create_renderer_refuses_a_color_format_that_is_not_a_float_color_format_naming_it() {
    for (raw, name) in [
        (0, "UNDEFINED"),
        (126, "D32_SFLOAT"),
        (130, "D32_SFLOAT_S8_UINT"),
        (41, "R8G8B8A8_UINT"),
        (107, "R32G32B32A32_UINT"),
        (131, "BC1_RGB_UNORM_BLOCK"),
        (99_999, "99999"),
        (-1, "-1"),
    ] {
        let mut info = create_info();
        info.color_format = vk::Format::from_raw(raw);
        let given = format!("color_format {name} ({raw}) is not a color format");
        assert_create_refused(&info, &[&given, "expected an uncompressed color format"]);
    }
}

#[test]
fn create_renderer_refuses_a_depth_format_without_depth_naming_it() {
    for (raw, name) in [
        (37, "R8G8B8A8_UNORM"),
        (127, "S8_UINT"),
        (100, "R32_SFLOAT"),
        (99_999, "99999"),
    ] {
        let mut info = create_info();
        info.depth_format = vk::Format::from_raw(raw);
        let given = format!("depth_format {name} ({raw}) is not a depth format");
        assert_create_refused(&info, &[&given, "expected UNDEFINED (no depth attachment)"]);
    }
}

#[test]
fn create_renderer_refuses_samples_that_are_not_one_sample_count_bit() {
    for raw in [0u32, 3, 5, 6, 12, 128, 0x41, u32::MAX] {
        let mut info = create_info();
        info.samples = vk::SampleCountFlags::from_raw(raw);
        let given = format!("samples {raw} (0x{raw:X}) is not one VkSampleCountFlagBits bit");
        assert_create_refused(&info, &[&given, "expected 1, 2, 4, 8, 16, 32 or 64"]);
    }
}

#[test]
fn create_renderer_refuses_an_attribute_that_ends_past_its_bindings_stride() {
    // BINDINGS' stride is 24: a 12-byte normal at 13 ends at 25; u32::MAX overflows.
    for offset in [13u32, 24, 4096, u32::MAX] {
        let mut info = create_info();
        info.normal.offset = offset;
        let given = format!("the normal attribute at offset {offset} (12 bytes of R32G32B32_SFLOAT)");
        assert_create_refused(&info, &[&given, "past the stride 24 of binding 0"]);
    }
    let mut info = create_info();
    let color = FfvkAttribute {
        binding: 0,
        offset: 21,
        format: vk::Format::R8G8B8A8_UNORM,
    };
    info.color = &color;
    assert_create_refused(
        &info,
        &[
            "the color attribute at offset 21 (4 bytes",
            "expected offset + 4 <= stride",
        ],
    );
}

#[test]
fn create_renderer_with_a_misaligned_info_or_attribute_is_invalid_argument() {
    // A create info one byte into a buffer: reading through it would be undefined.
    let mut bytes = vec![0u8; size_of::<FfvkRendererCreateInfo>() + 16];
    let info = misaligned(bytes.as_mut_ptr().cast::<FfvkRendererCreateInfo>().cast_const());
    assert_create_refused(info, &["info 0x", "not aligned to 8 bytes"]);
    let mut info = create_info();
    info.color = misaligned(&COLOR);
    assert_create_refused(&info, &["color 0x", "not aligned"]);
    let mut info = create_info();
    info.texcoord = misaligned(&COLOR);
    assert_create_refused(&info, &["texcoord 0x", "not aligned"]);
}

#[test]
fn the_renderer_entry_points_refuse_a_null_or_misaligned_renderer_naming_themselves() {
    let c = Ctx::new();
    // SAFETY: all zeros is a valid FfvkDrawInfo (integers, null pointers, null handles, and
    // Vulkan enums and flags that are plain integers).
    let draw: FfvkDrawInfo = unsafe { std::mem::zeroed() };
    let cmd = vk::CommandBuffer::from_raw(0x4000);
    let (view, sampler) = (vk::ImageView::from_raw(0x10), vk::Sampler::from_raw(0x20));
    let mut texture: *mut FfvkTexture = null_mut();
    let mut bytes = [0u64; 8];
    let bad = misaligned(bytes.as_mut_ptr().cast::<FfvkRenderer>().cast_const()).cast_mut();
    // SAFETY: null and misaligned renderers, refused before anything else is looked at.
    unsafe {
        assert_each_invalid_argument!(["renderer is a null pointer", "expected a renderer"], {
            ffvkBeginFrame(null_mut(), 0);
            ffvkBeginDraws(null_mut(), cmd, 0);
            ffvkBeginDraws(null_mut(), vk::CommandBuffer::null(), 7);
            ffvkDraw(null_mut(), c.0, &draw);
            ffvkDraw(null_mut(), null(), null());
            ffvkEndDraws(null_mut());
            ffvkCreateTexture(null_mut(), view, sampler, &mut texture);
            ffvkCreateCubeMap(null_mut(), view, sampler, &mut texture);
            ffvkCreateTextureWithFormat(null_mut(), view, sampler, LUMINANCE, &mut texture);
            ffvkCreateCubeMapWithFormat(null_mut(), view, sampler, LUMINANCE, &mut texture);
            ffvkCreateTextureWithFormat(null_mut(), view, sampler, 0xFFFF, &mut texture);
        });
        assert_each_invalid_argument!(["renderer 0x", "not aligned"], {
            ffvkBeginFrame(bad, 0);
            ffvkBeginDraws(bad, cmd, 0);
            ffvkDraw(bad, c.0, &draw);
            ffvkEndDraws(bad);
            ffvkCreateTexture(bad, view, sampler, &mut texture);
            ffvkCreateCubeMap(bad, view, sampler, &mut texture);
            ffvkCreateTextureWithFormat(bad, view, sampler, ALPHA, &mut texture);
            ffvkCreateCubeMapWithFormat(bad, view, sampler, INTENSITY, &mut texture);
        });
    }
    assert_eq!(bytes, [0; 8], "written through a misaligned renderer");
    assert_eq!(
        c.error(),
        NO_ERROR,
        "a refused draw sets no GL error on its context"
    );
}

#[test]
fn create_texture_nulls_its_out_pointer_when_it_fails() {
    let mut out: *mut FfvkTexture = NonNull::dangling().as_ptr();
    let view = vk::ImageView::from_raw(0x10);
    let sampler = vk::Sampler::from_raw(0x20);
    // SAFETY: a null renderer, refused before the handles are used; out is writable.
    let result = unsafe { ffvkCreateTexture(null_mut(), view, sampler, &mut out) };
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert!(out.is_null(), "the out pointer is left {out:?} after an error");
    // SAFETY: as above, with a null out pointer too.
    let result = unsafe { ffvkCreateTexture(null_mut(), view, sampler, null_mut()) };
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
}

#[test]
fn create_cube_map_names_itself_and_nulls_its_out_pointer_when_it_fails() {
    let mut out: *mut FfvkTexture = NonNull::dangling().as_ptr();
    let view = vk::ImageView::from_raw(0x10);
    let sampler = vk::Sampler::from_raw(0x20);
    // SAFETY: a null renderer, refused before the handles are used; out is writable.
    let result = unsafe { ffvkCreateCubeMap(null_mut(), view, sampler, &mut out) };
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert!(out.is_null(), "the out pointer is left {out:?} after an error");
    let text = message();
    assert!(
        text.starts_with("ffvkCreateCubeMap: renderer is a null pointer"),
        "{text}"
    );
    // SAFETY: as above, with a null out pointer too.
    let result = unsafe { ffvkCreateCubeMap(null_mut(), view, sampler, null_mut()) };
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    // A misaligned out pointer is neither written nor taken.
    let mut bytes = [0u64; 2];
    let bad = misaligned(bytes.as_mut_ptr().cast::<*mut FfvkTexture>().cast_const()).cast_mut();
    // SAFETY: as above; the misaligned out pointer is refused, never written.
    let result = unsafe { ffvkCreateCubeMap(null_mut(), view, sampler, bad) };
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert_eq!(bytes, [0; 2], "written through a misaligned out pointer");
    // A null cube map is destroyed as a null texture is: nothing happens.
    // SAFETY: null is documented as ignored.
    unsafe { ffvkDestroyTexture(null_mut()) };
}

#[test]
fn the_with_format_entry_points_name_themselves_and_null_their_out_pointer_when_they_fail() {
    let view = vk::ImageView::from_raw(0x10);
    let sampler = vk::Sampler::from_raw(0x20);
    type Create = unsafe extern "C" fn(
        *mut FfvkRenderer,
        vk::ImageView,
        vk::Sampler,
        u32,
        *mut *mut FfvkTexture,
    ) -> FfvkResult;
    let entries: [(&str, Create); 2] = [
        ("ffvkCreateTextureWithFormat", ffvkCreateTextureWithFormat),
        ("ffvkCreateCubeMapWithFormat", ffvkCreateCubeMapWithFormat),
    ];
    for (name, create) in entries {
        // A bad enum with a null renderer: the renderer is named, the out pointer nulled.
        for format in [LUMINANCE, 0x8040, 0] {
            let mut out: *mut FfvkTexture = NonNull::dangling().as_ptr();
            // SAFETY: a null renderer, refused before the handles are used; out is writable.
            let result = unsafe { create(null_mut(), view, sampler, format, &mut out) };
            assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{name}");
            assert!(
                out.is_null(),
                "{name}: the out pointer is left {out:?} after an error"
            );
            let text = message();
            assert!(
                text.starts_with(&format!("{name}: renderer is a null pointer")),
                "{text}"
            );
        }
        // SAFETY: as above, with a null out pointer too.
        let result = unsafe { create(null_mut(), view, sampler, RGBA, null_mut()) };
        assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{name}");
        let mut bytes = [0u64; 2];
        let bad = misaligned(bytes.as_mut_ptr().cast::<*mut FfvkTexture>().cast_const()).cast_mut();
        // SAFETY: as above; the misaligned out pointer is refused, never written.
        let result = unsafe { create(null_mut(), view, sampler, RGBA, bad) };
        assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{name}");
        assert_eq!(bytes, [0; 2], "{name}: written through a misaligned out pointer");
    }
}

#[test]
fn raster_defaults_are_gls_initial_state_and_a_null_or_misaligned_raster_is_ignored() {
    let mut bytes = [0u8; size_of::<FfvkRaster>() + 8];
    // SAFETY: null and misaligned are documented as ignored.
    unsafe {
        ffvkRasterDefaults(null_mut());
        ffvkRasterDefaults(misaligned(bytes.as_mut_ptr().cast::<FfvkRaster>().cast_const()).cast_mut());
    }
    assert!(
        bytes.iter().all(|&b| b == 0),
        "written through a misaligned pointer"
    );
    let mut raster = std::mem::MaybeUninit::<FfvkRaster>::uninit();
    // SAFETY: writable; ffvkRasterDefaults writes every field.
    let r = unsafe {
        ffvkRasterDefaults(raster.as_mut_ptr());
        raster.assume_init()
    };
    assert_eq!(r.cull_mode, vk::CullModeFlags::NONE);
    assert_eq!(r.front_face, vk::FrontFace::COUNTER_CLOCKWISE);
    assert_eq!((r.depth_test, r.depth_write, r.blend), (0, 1, 0));
    assert_eq!(r.depth_compare, vk::CompareOp::LESS);
    assert_eq!(
        (r.src_color, r.dst_color),
        (vk::BlendFactor::ONE, vk::BlendFactor::ZERO)
    );
    assert_eq!(
        (r.src_alpha, r.dst_alpha),
        (vk::BlendFactor::ONE, vk::BlendFactor::ZERO)
    );
    assert_eq!((r.color_op, r.alpha_op), (vk::BlendOp::ADD, vk::BlendOp::ADD));
    assert_eq!((r.point_size, r.line_width), (1.0, 1.0));
}

// ---------------------------------------------------------------------------------------
// GL's primitive modes as indices.

/// `ffvkPrimitiveIndices` asked for its size, then filled: (indices, the mode to draw them).
fn primitive_indices(mode: u32, vertices: &[u32]) -> (Vec<u32>, u32) {
    let count = vertices.len() as u32;
    let (mut written, mut draw_mode) = (u32::MAX, u32::MAX);
    // SAFETY: vertices points at count values; out is null (asking the size).
    let r = unsafe {
        ffvkPrimitiveIndices(
            mode,
            vertices.as_ptr(),
            count,
            null_mut(),
            0,
            &mut written,
            &mut draw_mode,
        )
    };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    let mut out = vec![u32::MAX; written as usize + 2];
    let (mut written2, mut draw_mode2) = (u32::MAX, u32::MAX);
    // SAFETY: out has room for `written` values (and two more, which must stay untouched).
    let r = unsafe {
        let o = out.as_mut_ptr();
        ffvkPrimitiveIndices(
            mode,
            vertices.as_ptr(),
            count,
            o,
            written,
            &mut written2,
            &mut draw_mode2,
        )
    };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    assert_eq!((written2, draw_mode2), (written, draw_mode));
    assert_eq!(out[written as usize..], [u32::MAX; 2], "written past the count");
    out.truncate(written as usize);
    (out, draw_mode)
}

/// The triangles of a list, each kept in its vertex order, sorted: the order of the
/// triangles in the list is the API's choice; the order within each is GL's winding and
/// provoking vertex.
fn triangles(list: &[u32]) -> Vec<[u32; 3]> {
    assert_eq!(list.len() % 3, 0, "{list:?} is not a triangle list");
    let mut t: Vec<[u32; 3]> = list.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
    t.sort();
    t
}

/// The segments of a line list, each kept in its vertex order, sorted.
fn segments(list: &[u32]) -> Vec<[u32; 2]> {
    assert_eq!(list.len() % 2, 0, "{list:?} is not a line list");
    let mut s: Vec<[u32; 2]> = list.chunks(2).map(|c| [c[0], c[1]]).collect();
    s.sort();
    s
}

#[test]
fn the_six_modes_vulkan_has_are_copied_unchanged() {
    let v = [10, 11, 12, 13, 14, 15, 16];
    for mode in [POINTS, LINES, LINE_STRIP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN] {
        assert_eq!(primitive_indices(mode, &v), (v.to_vec(), mode), "mode {mode}");
    }
}

#[test]
fn quads_become_two_triangles_each_ending_with_the_quads_fourth_vertex_in_its_winding() {
    // GL 2.1 section 2.6.1: quad i is vertices 4i+1 .. 4i+4 (from 1), its boundary in that
    // order; table 2.12: its provoking vertex is 4i+4, the fourth. Two triangles that both
    // end with it, in the quad's winding, share the diagonal from the second vertex to the
    // fourth: (v1, v2, v4) and (v2, v3, v4). The 9th vertex makes no quad.
    let (list, mode) = primitive_indices(QUADS, &[10, 11, 12, 13, 20, 21, 22, 23, 99]);
    assert_eq!(mode, TRIANGLES);
    assert_eq!(
        triangles(&list),
        [[10, 11, 13], [11, 12, 13], [20, 21, 23], [21, 22, 23]]
    );
    assert!(
        primitive_indices(QUADS, &[1, 2, 3]).0.is_empty(),
        "three vertices make no quad"
    );
}

#[test]
fn a_quad_strip_becomes_triangles_ending_with_vertex_2i_plus_2_in_the_quads_winding() {
    // GL 2.1 section 2.6.1: quad i (from 1) of a strip has the boundary 2i-1, 2i, 2i+2,
    // 2i+1; table 2.12: its provoking vertex is 2i+2. For vertices a b c d (the boundary
    // a, b, d, c) both triangles end with d: (a, b, d) and (c, a, d), the boundary rotated.
    // The 7th vertex is unpaired and dropped.
    let (list, mode) = primitive_indices(QUAD_STRIP, &[10, 11, 12, 13, 14, 15, 16]);
    assert_eq!(mode, TRIANGLES);
    assert_eq!(
        triangles(&list),
        [[10, 11, 13], [12, 10, 13], [12, 13, 15], [14, 12, 15]]
    );
    assert!(
        primitive_indices(QUAD_STRIP, &[1, 2, 3]).0.is_empty(),
        "fewer than 4 make no quad"
    );
}

#[test]
fn a_polygon_becomes_a_fan_of_triangles_ending_with_its_first_vertex() {
    // GL 2.1 table 2.12: a polygon's provoking vertex is its first. Triangles that all end
    // with it and keep the polygon's winding: (v(i), v(i+1), v1) for i = 2 .. n-1.
    let (list, mode) = primitive_indices(POLYGON, &[10, 11, 12, 13, 14]);
    assert_eq!(mode, TRIANGLES);
    assert_eq!(triangles(&list), [[11, 12, 10], [12, 13, 10], [13, 14, 10]]);
    assert_eq!(triangles(&primitive_indices(POLYGON, &[1, 2, 3]).0), [[2, 3, 1]]);
    assert!(
        primitive_indices(POLYGON, &[1, 2]).0.is_empty(),
        "two vertices make no polygon"
    );
}

#[test]
fn a_line_loop_becomes_segments_ending_with_each_segments_provoking_vertex() {
    // GL 2.1 section 2.6.1 and table 2.12: segment i joins vertices i and i+1, i+1 provoking;
    // the closing segment joins the last vertex to the first, the first provoking. As a line
    // list whose second vertex provokes: (vi, vi+1) and (vn, v1).
    let (list, mode) = primitive_indices(LINE_LOOP, &[10, 11, 12, 13]);
    assert_eq!(mode, LINES);
    assert_eq!(segments(&list), [[10, 11], [11, 12], [12, 13], [13, 10]]);
    assert_eq!(
        segments(&primitive_indices(LINE_LOOP, &[5, 6]).0),
        [[5, 6], [6, 5]]
    );
    assert!(
        primitive_indices(LINE_LOOP, &[5]).0.is_empty(),
        "one vertex makes no line"
    );
}

#[test]
fn no_vertices_make_no_indices_in_every_mode() {
    for mode in POINTS..=POLYGON {
        let (mut written, mut draw_mode) = (u32::MAX, u32::MAX);
        // SAFETY: a count of 0 with null vertices; out null.
        let r = unsafe { ffvkPrimitiveIndices(mode, null(), 0, null_mut(), 0, &mut written, &mut draw_mode) };
        assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
        assert_eq!(written, 0, "mode {mode}");
    }
}

#[test]
fn primitive_indices_refuses_an_unknown_mode_and_writes_nothing() {
    let v = [0u32, 1, 2, 3];
    for (mode, shown) in [
        (POLYGON + 1, "0x000A"),
        (LIGHTING, "GL_LIGHTING (0x0B50)"),
        (u32::MAX, "0xFFFFFFFF"),
    ] {
        let mut out = [u32::MAX; 16];
        let (mut written, mut draw_mode) = (7u32, 7u32);
        // SAFETY: 4 vertices; out has room for 16.
        let r = unsafe {
            ffvkPrimitiveIndices(
                mode,
                v.as_ptr(),
                4,
                out.as_mut_ptr(),
                16,
                &mut written,
                &mut draw_mode,
            )
        };
        assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
        let words = [
            &format!("ffvkPrimitiveIndices: mode {shown} is not one of GL's ten primitive modes"),
            "expected GL_POINTS",
        ];
        assert_names(&message(), &words);
        assert_eq!((written, draw_mode), (7, 7));
        assert_eq!(out, [u32::MAX; 16]);
    }
}

#[test]
fn primitive_indices_with_too_small_a_capacity_writes_no_index_and_says_how_many() {
    let v = [0u32, 1, 2, 3, 4, 5, 6, 7];
    let mut out = [u32::MAX; 16];
    let (mut written, mut draw_mode) = (0u32, 0u32);
    // SAFETY: 8 vertices; out has room for 16, of which 11 are offered (two quads need 12).
    let r = unsafe {
        ffvkPrimitiveIndices(
            QUADS,
            v.as_ptr(),
            8,
            out.as_mut_ptr(),
            11,
            &mut written,
            &mut draw_mode,
        )
    };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert_names(
        &message(),
        &[
            "ffvkPrimitiveIndices: capacity 11 is too small",
            "expected at least 12",
        ],
    );
    assert_eq!(
        out,
        [u32::MAX; 16],
        "an index was written past a refused capacity"
    );
    assert_eq!(
        (written, draw_mode),
        (12, TRIANGLES),
        "the needed count is still given"
    );
}

#[test]
fn primitive_indices_refuses_null_and_misaligned_pointers_naming_each() {
    let v = [0u32, 1, 2, 3];
    let mut out = [0u32; 16];
    let mut bytes = [0u32; 4];
    let (mut w, mut m) = (0u32, 0u32);
    let (o, vp, w_, m_) = (out.as_mut_ptr(), v.as_ptr(), &raw mut w, &raw mut m);
    let bad = misaligned(bytes.as_mut_ptr().cast_const()).cast_mut();
    // SAFETY: every non-null, aligned pointer is valid for its count; the null and misaligned
    // ones are what is probed.
    unsafe {
        assert_each_invalid_argument!(["vertices is a null pointer", "expected the 4 vertex numbers"], {
            ffvkPrimitiveIndices(QUADS, null(), 4, o, 16, w_, m_);
        });
        assert_each_invalid_argument!(["written is a null pointer", "expected where to write"], {
            ffvkPrimitiveIndices(QUADS, vp, 4, o, 16, null_mut(), m_);
        });
        assert_each_invalid_argument!(["draw_mode is a null pointer", "expected where to write"], {
            ffvkPrimitiveIndices(QUADS, vp, 4, o, 16, w_, null_mut());
        });
        assert_each_invalid_argument!(["vertices 0x", "not aligned to 4 bytes"], {
            ffvkPrimitiveIndices(QUADS, bad, 3, o, 16, w_, m_);
        });
        assert_each_invalid_argument!(["out 0x", "not aligned to 4 bytes"], {
            ffvkPrimitiveIndices(QUADS, vp, 4, bad, 3, w_, m_);
        });
        assert_each_invalid_argument!(["written 0x", "not aligned to 4 bytes"], {
            ffvkPrimitiveIndices(QUADS, vp, 4, o, 16, bad, m_);
        });
        assert_each_invalid_argument!(["draw_mode 0x", "not aligned to 4 bytes"], {
            ffvkPrimitiveIndices(QUADS, vp, 4, o, 16, w_, bad);
        });
    }
    assert_eq!(out, [0; 16]);
    assert_eq!((w, m), (0, 0));
    assert_eq!(bytes, [0; 4], "written through a misaligned pointer");
}

#[test]
fn a_size_query_of_any_count_reads_and_allocates_nothing() {
    // Issue 46: asking the size for 3e9 vertex numbers (12 GB) or 0xFFFFFFFF of them copied or
    // expanded them first, which aborted the host. The query needs the count alone: the one
    // vertex here is never read.
    let one = [7u32];
    for (mode, count, needed) in [
        (TRIANGLES, u32::MAX, u32::MAX),
        (POINTS, 3_000_000_000, 3_000_000_000),
        (QUADS, 2_000_000_000, 3_000_000_000),
        (QUAD_STRIP, 1_000_000_000, 2_999_999_994),
        (POLYGON, 1_431_655_767, u32::MAX),
        (LINE_LOOP, 2_000_000_000, 4_000_000_000),
    ] {
        let (mut written, mut draw_mode) = (0u32, u32::MAX);
        // SAFETY: a size query (out null) reads nothing from vertices, as the header says.
        let r = unsafe {
            ffvkPrimitiveIndices(
                mode,
                one.as_ptr(),
                count,
                null_mut(),
                0,
                &mut written,
                &mut draw_mode,
            )
        };
        assert_eq!(
            r,
            FfvkResult::FFVK_SUCCESS,
            "mode {mode}, count {count}: {}",
            message()
        );
        assert_eq!(written, needed, "mode {mode}, count {count}");
    }
}

#[test]
fn primitive_indices_refuses_a_count_whose_indices_a_uint32_count_cannot_hold() {
    let one = [7u32];
    for (mode, count, needed) in [
        (QUADS, 3_000_000_000u32, 4_500_000_000u64),
        (QUADS, u32::MAX, 6_442_450_938),
        (QUAD_STRIP, u32::MAX, 12_884_901_876),
        (POLYGON, 1_431_655_768, 4_294_967_298),
        (POLYGON, u32::MAX, 12_884_901_879),
        (LINE_LOOP, u32::MAX, 8_589_934_590),
    ] {
        let mut out = [u32::MAX; 4];
        let (mut written, mut draw_mode) = (5u32, 5u32);
        for o in [null_mut(), out.as_mut_ptr()] {
            // SAFETY: refused from the count alone: neither vertices nor out is touched.
            let r = unsafe {
                ffvkPrimitiveIndices(mode, one.as_ptr(), count, o, 4, &mut written, &mut draw_mode)
            };
            assert_eq!(
                r,
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                "mode {mode}, count {count}"
            );
            let words = [
                &format!("ffvkPrimitiveIndices: count {count} of mode {}", mode_named(mode)),
                &format!("makes {needed} indices"),
                "expected a count whose indices number at most 4294967295",
            ];
            assert_names(&message(), &words);
        }
        assert_eq!((written, draw_mode), (5, 5), "written on a refusal");
        assert_eq!(out, [u32::MAX; 4]);
    }
}

/// `ffvkPrimitiveIndicesRange(mode, first, count)`: the size query, then the indices into
/// room for exactly that many (and two more, which must stay untouched).
fn primitive_indices_range(mode: u32, first: u32, count: u32) -> (Vec<u32>, u32) {
    let (mut written, mut draw_mode) = (u32::MAX, u32::MAX);
    // SAFETY: out is null (asking the size).
    let r =
        unsafe { ffvkPrimitiveIndicesRange(mode, first, count, null_mut(), 0, &mut written, &mut draw_mode) };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    let mut out = vec![u32::MAX; written as usize + 2];
    let (mut written2, mut draw_mode2) = (u32::MAX, u32::MAX);
    // SAFETY: out has room for `written` values.
    let r = unsafe {
        ffvkPrimitiveIndicesRange(
            mode,
            first,
            count,
            out.as_mut_ptr(),
            written,
            &mut written2,
            &mut draw_mode2,
        )
    };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    assert_eq!((written2, draw_mode2), (written, draw_mode));
    assert_eq!(out[written as usize..], [u32::MAX; 2], "written past the count");
    out.truncate(written as usize);
    (out, draw_mode)
}

#[test]
fn the_range_form_makes_the_indices_of_the_consecutive_vertices_first_to_first_plus_count() {
    for mode in POINTS..=POLYGON {
        for (first, count) in [
            (0u32, 0u32),
            (0, 1),
            (0, 12),
            (5, 11),
            (1000, 9),
            (u32::MAX - 7, 8),
        ] {
            let listed: Vec<u32> = (0..count).map(|i| first + i).collect();
            assert_eq!(
                primitive_indices_range(mode, first, count),
                primitive_indices(mode, &listed),
                "{} of vertices {first} .. {first} + {count}",
                mode_named(mode)
            );
        }
    }
}

#[test]
fn the_range_form_refuses_a_last_vertex_past_the_uint32_range_naming_first_and_count() {
    let mut out = [u32::MAX; 8];
    let (mut written, mut draw_mode) = (5u32, 5u32);
    for (first, count) in [(u32::MAX, 2u32), (2, u32::MAX), (u32::MAX, u32::MAX)] {
        for o in [null_mut(), out.as_mut_ptr()] {
            // SAFETY: out is null or has room for 8; refused before it is looked at.
            let r = unsafe {
                ffvkPrimitiveIndicesRange(TRIANGLES, first, count, o, 8, &mut written, &mut draw_mode)
            };
            assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
            let words = [
                &format!("ffvkPrimitiveIndicesRange: first {first} + count {count} passes 2^32"),
                "expected first + count <= 4294967296",
            ];
            assert_names(&message(), &words);
        }
    }
    assert_eq!((written, draw_mode), (5, 5), "written on a refusal");
    assert_eq!(out, [u32::MAX; 8]);
    // The last vertex number may be 0xFFFFFFFF itself.
    let (indices, _) = primitive_indices_range(LINE_LOOP, u32::MAX - 1, 2);
    assert_eq!(indices, [u32::MAX - 1, u32::MAX, u32::MAX, u32::MAX - 1]);
}

#[test]
fn the_range_forms_size_query_and_refusals_are_those_of_the_listed_form() {
    let (mut written, mut draw_mode) = (0u32, u32::MAX);
    // SAFETY: a size query writes the count and mode only.
    let r = unsafe {
        ffvkPrimitiveIndicesRange(
            QUADS,
            0,
            2_000_000_000,
            null_mut(),
            0,
            &mut written,
            &mut draw_mode,
        )
    };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    assert_eq!((written, draw_mode), (3_000_000_000, TRIANGLES));
    let mut out = [u32::MAX; 16];
    let (o, w_, m_) = (out.as_mut_ptr(), &raw mut written, &raw mut draw_mode);
    // SAFETY: each call is refused before out (room for 16) is written.
    unsafe {
        assert_each_invalid_argument!(
            ["count 3000000000 of mode GL_QUADS (0x0007) makes 4500000000 indices"],
            {
                ffvkPrimitiveIndicesRange(QUADS, 0, 3_000_000_000, o, 16, w_, m_);
            }
        );
        assert_each_invalid_argument!(
            ["mode GL_LIGHTING (0x0B50) is not one of GL's ten primitive modes"],
            {
                ffvkPrimitiveIndicesRange(LIGHTING, 0, 4, o, 16, w_, m_);
            }
        );
        assert_each_invalid_argument!(["capacity 11 is too small", "expected at least 12"], {
            ffvkPrimitiveIndicesRange(QUADS, 0, 8, o, 11, w_, m_);
        });
        assert_each_invalid_argument!(["written is a null pointer"], {
            ffvkPrimitiveIndicesRange(QUADS, 0, 4, o, 16, null_mut(), m_);
        });
        assert_each_invalid_argument!(["draw_mode is a null pointer"], {
            ffvkPrimitiveIndicesRange(QUADS, 0, 4, o, 16, w_, null_mut());
        });
    }
    assert_eq!(out, [u32::MAX; 16]);
}

// ---------------------------------------------------------------------------------------
// GL's viewport and scissor box as Vulkan's.

#[test]
fn viewport_and_scissor_refuse_what_gl_refuses_naming_the_function_and_the_value_and_write_nothing() {
    let kept = vk::Viewport {
        x: 7.0,
        y: 7.0,
        width: 7.0,
        height: 7.0,
        min_depth: 0.7,
        max_depth: 0.7,
    };
    let mut v = kept;
    let kept_rect = vk::Rect2D {
        offset: vk::Offset2D { x: 7, y: 7 },
        extent: vk::Extent2D { width: 7, height: 7 },
    };
    let mut s = kept_rect;
    let (vp, sp) = (&raw mut v, &raw mut s);
    // SAFETY: each out pointer is writable, null or misaligned (what is probed).
    unsafe {
        assert_each_invalid_argument!(
            [
                "width is -1: expected 0 or more",
                "GL_INVALID_VALUE in glViewport"
            ],
            {
                ffvkViewport(0, 0, -1, 10, 48, 0.0, 1.0, vp);
            }
        );
        assert_each_invalid_argument!(["height is 0: expected at least 1", "skip the draws instead"], {
            ffvkViewport(0, 0, 10, 0, 48, 0.0, 1.0, vp);
        });
        assert_each_invalid_argument!(["depth_range [NaN, 1] holds NaN"], {
            ffvkViewport(0, 0, 10, 10, 48, f64::NAN, 1.0, vp);
        });
        assert_each_invalid_argument!(["target height is 4294967295: expected at most 2147483647"], {
            ffvkViewport(0, 0, 10, 10, u32::MAX, 0.0, 1.0, vp);
        });
        assert_each_invalid_argument!(["viewport is a null pointer"], {
            ffvkViewport(0, 0, 10, 10, 48, 0.0, 1.0, null_mut());
        });
        assert_each_invalid_argument!(
            [
                "height is -3: expected 0 or more",
                "GL_INVALID_VALUE in glScissor"
            ],
            {
                ffvkScissor(0, 0, 10, -3, 64, 48, sp);
            }
        );
        assert_each_invalid_argument!(["target width is 2147483648"], {
            ffvkScissor(0, 0, 10, 10, 1 << 31, 48, sp);
        });
        assert_each_invalid_argument!(["scissor is a null pointer"], {
            ffvkScissor(0, 0, 10, 10, 64, 48, null_mut());
        });
        let bytes = [0u64; 4];
        let bad = bytes
            .as_ptr()
            .cast::<u8>()
            .wrapping_add(1)
            .cast::<vk::Rect2D>()
            .cast_mut();
        assert_each_invalid_argument!(["scissor 0x", "not aligned to 4 bytes"], {
            ffvkScissor(0, 0, 10, 10, 64, 48, bad);
        });
        assert_eq!(bytes, [0; 4], "written through a misaligned pointer");
    }
    let fields = |v: vk::Viewport| [v.x, v.y, v.width, v.height, v.min_depth, v.max_depth];
    assert_eq!(fields(v), fields(kept), "a refused viewport was written");
    assert_eq!(s, kept_rect, "a refused scissor was written");
}

#[test]
fn viewport_counts_rows_from_the_top_and_scissor_clips_gls_box_to_the_target() {
    let mut v = vk::Viewport::default();
    let mut s = vk::Rect2D::default();
    // SAFETY: writable out pointers.
    unsafe {
        assert_eq!(
            ffvkViewport(8, 6, 32, 24, 48, 0.25, 2.0, &mut v),
            FfvkResult::FFVK_SUCCESS
        );
        assert_eq!(
            ffvkScissor(-4, 40, 20, 20, 64, 48, &mut s),
            FfvkResult::FFVK_SUCCESS
        );
    }
    assert_eq!((v.x, v.y, v.width, v.height), (8.0, 18.0, 32.0, 24.0));
    assert_eq!(
        (v.min_depth, v.max_depth),
        (0.25, 1.0),
        "glDepthRange's values clamp to [0, 1]"
    );
    assert_eq!(
        (s.offset.x, s.offset.y, s.extent.width, s.extent.height),
        (0, 0, 16, 8)
    );
}

// ---------------------------------------------------------------------------------------
// The teapot.

#[test]
fn create_teapot_refuses_level_0_and_65_naming_the_level_and_nulls_the_mesh() {
    for level in [0u32, 65, u32::MAX] {
        let mut mesh: *mut FfvkMesh = NonNull::dangling().as_ptr();
        // SAFETY: mesh is writable.
        let r = unsafe { ffvkCreateTeapot(level, &mut mesh) };
        assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
        assert!(mesh.is_null());
        let words = [
            &format!("ffvkCreateTeapot: teapot tessellation level {level}"),
            "expected 1..=64",
        ];
        assert_names(&message(), &words);
    }
    let mut bytes = [0u64; 2];
    let bad = misaligned(bytes.as_mut_ptr().cast::<*mut FfvkMesh>().cast_const()).cast_mut();
    // SAFETY: the null and misaligned out pointers are what is probed.
    unsafe {
        assert_each_invalid_argument!(["mesh is a null pointer", "expected where to write the mesh"], {
            ffvkCreateTeapot(1, null_mut());
        });
        assert_each_invalid_argument!(["mesh 0x", "not aligned to 8 bytes"], {
            ffvkCreateTeapot(1, bad);
        });
    }
    assert_eq!(bytes, [0; 2]);
}

#[test]
fn a_level_1_teapot_has_triangles_whose_indices_are_all_in_range() {
    let mut mesh: *mut FfvkMesh = null_mut();
    // SAFETY: mesh is writable.
    let r = unsafe { ffvkCreateTeapot(1, &mut mesh) };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    assert!(!mesh.is_null());
    let mut arrays = std::mem::MaybeUninit::<FfvkMeshArrays>::uninit();
    // SAFETY: a live mesh; arrays is writable.
    let r = unsafe { ffvkGetMeshArrays(mesh, arrays.as_mut_ptr()) };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS);
    // SAFETY: written by the successful call.
    let a = unsafe { arrays.assume_init() };
    let n = a.vertex_count as usize;
    let indices = a.index_count as usize;
    assert!(
        n > 0 && indices > 0 && indices.is_multiple_of(3),
        "{n} vertices, {indices} indices"
    );
    // SAFETY: the arrays' documented lengths, valid until ffvkDestroyMesh.
    let (positions, normals, colors, indices) = unsafe {
        (
            std::slice::from_raw_parts(a.positions, 3 * n),
            std::slice::from_raw_parts(a.normals, 3 * n),
            std::slice::from_raw_parts(a.colors, 4 * n),
            std::slice::from_raw_parts(a.indices, indices),
        )
    };
    assert!(indices.iter().all(|&i| (i as usize) < n), "an index past {n}");
    assert!(positions.iter().all(|v| v.is_finite()));
    for normal in normals.chunks(3) {
        let length = normal.iter().map(|c| c * c).sum::<f32>().sqrt();
        assert!((length - 1.0).abs() < 1e-3, "normal {normal:?}");
    }
    assert!(colors.iter().all(|c| (0.0..=1.0).contains(c)));
    // SAFETY: the mesh is live and not used after this.
    unsafe { ffvkDestroyMesh(mesh) };
}

#[test]
fn get_mesh_arrays_refuses_a_null_or_misaligned_mesh_or_arrays_naming_which() {
    let mut mesh: *mut FfvkMesh = null_mut();
    // SAFETY: mesh is writable.
    let r = unsafe { ffvkCreateTeapot(1, &mut mesh) };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    let mut arrays = std::mem::MaybeUninit::<FfvkMeshArrays>::uninit();
    let a = arrays.as_mut_ptr();
    let mut bytes = [0u64; 8];
    let bad_arrays = misaligned(bytes.as_mut_ptr().cast::<FfvkMeshArrays>().cast_const()).cast_mut();
    let bad_mesh = misaligned(mesh.cast_const());
    // SAFETY: the null and misaligned pointers are what is probed; the others are valid.
    unsafe {
        assert_each_invalid_argument!(
            ["mesh is a null pointer", "expected a mesh from ffvkCreateTeapot"],
            {
                ffvkGetMeshArrays(null(), a);
            }
        );
        assert_each_invalid_argument!(["arrays is a null pointer", "expected where to write"], {
            ffvkGetMeshArrays(mesh, null_mut());
        });
        assert_each_invalid_argument!(["mesh 0x", "not aligned"], {
            ffvkGetMeshArrays(bad_mesh, a);
        });
        assert_each_invalid_argument!(["arrays 0x", "not aligned to 8 bytes"], {
            ffvkGetMeshArrays(mesh, bad_arrays);
        });
        ffvkDestroyMesh(mesh);
    }
    assert_eq!(bytes, [0; 8]);
}

// ---------------------------------------------------------------------------------------
// GL's polygons with their edge flags.

/// `ffvkEdgeFlaggedIndices` asked for its size, then filled.
fn edge_flagged_indices(mode: u32, vertices: &[u32], flags: Option<&[u8]>) -> Vec<u32> {
    let count = vertices.len() as u32;
    let (flag_ptr, flag_count) = flags.map_or((null(), 0), |f| (f.as_ptr(), f.len() as u32));
    let mut written = u32::MAX;
    // SAFETY: vertices points at count values, the flags at flag_count; out is null (the size).
    let r = unsafe {
        ffvkEdgeFlaggedIndices(
            mode,
            vertices.as_ptr(),
            count,
            flag_ptr,
            flag_count,
            null_mut(),
            0,
            &mut written,
        )
    };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    let mut out = vec![u32::MAX; written as usize + 2];
    let mut again = u32::MAX;
    // SAFETY: out has room for `written` values (and two more, which must stay untouched).
    let r = unsafe {
        ffvkEdgeFlaggedIndices(
            mode,
            vertices.as_ptr(),
            count,
            flag_ptr,
            flag_count,
            out.as_mut_ptr(),
            written,
            &mut again,
        )
    };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    assert_eq!(again, written);
    assert_eq!(out[written as usize..], [u32::MAX; 2], "written past the count");
    out.truncate(written as usize);
    out
}

#[test]
fn edge_flagged_indices_are_the_primitive_indices_triangles_with_their_boundary_edges_marked() {
    const TRIANGLES: u32 = 0x0004;
    const QUAD_STRIP: u32 = 0x0008;
    const POLYGON: u32 = 0x0009;
    let v: Vec<u32> = (20..29).collect();
    for mode in [TRIANGLES, QUADS, QUAD_STRIP, POLYGON] {
        let flagged = edge_flagged_indices(mode, &v, None);
        let (triangles, draw_mode) = primitive_indices(mode, &v);
        assert_eq!(draw_mode, TRIANGLES);
        let corners: Vec<u32> = flagged.chunks(2).map(|p| p[0]).collect();
        assert_eq!(corners, triangles, "mode {mode}: the same triangles");
    }
    // Two quads: each with its four sides and no diagonal; a flag of zero hides the side
    // that starts at its vertex (here 21, then 24).
    let quads: Vec<u32> = (20..28).collect();
    let mut flags = vec![1u8; 28];
    flags[21] = 0;
    flags[24] = 0;
    assert_eq!(
        edge_flagged_indices(QUADS, &quads, Some(&flags))[..12],
        [20, 20, 21, 23, 23, 23, 21, 22, 22, 22, 23, 21],
        "quad 20-23: 20-21, 23-20 from the first triangle; 22-23 from the second; 21-22 hidden"
    );
    assert_eq!(
        edge_flagged_indices(QUADS, &quads, None),
        ffvk::draw::gl_primitives::quads_edge_flagged(&quads, |_| true)
    );
}

#[test]
fn edge_flagged_indices_refuse_other_modes_missing_flags_and_small_rooms_writing_nothing() {
    let v = [0u32, 1, 2, 3, 4, 5, 6, 7];
    let mut out = [u32::MAX; 32];
    let mut written = 0u32;
    let mut call = |mode: u32, flags: &[u8], capacity: u32, out: &mut [u32; 32]| {
        // SAFETY: 8 vertex numbers; the flags as given; out has room for 32.
        unsafe {
            ffvkEdgeFlaggedIndices(
                mode,
                v.as_ptr(),
                8,
                if flags.is_empty() { null() } else { flags.as_ptr() },
                flags.len() as u32,
                out.as_mut_ptr(),
                capacity,
                &mut written,
            )
        }
    };
    assert_eq!(
        call(0x0005, &[], 32, &mut out),
        FfvkResult::FFVK_ERROR_INVALID_ARGUMENT
    );
    assert_names(
        &message(),
        &[
            "ffvkEdgeFlaggedIndices: mode GL_TRIANGLE_STRIP (0x0005) has no edge flags",
            "GL_QUADS",
        ],
    );
    assert_eq!(
        call(QUADS, &[1; 6], 32, &mut out),
        FfvkResult::FFVK_ERROR_INVALID_ARGUMENT
    );
    assert_names(
        &message(),
        &["vertex number 6 has no edge flag", "below flag_count 6"],
    );
    assert_eq!(
        call(QUADS, &[], 23, &mut out),
        FfvkResult::FFVK_ERROR_INVALID_ARGUMENT
    );
    assert_names(&message(), &["capacity 23 is too small", "expected at least 24"]);
    assert_eq!(out, [u32::MAX; 32], "nothing written on a refusal");
    assert_eq!(call(QUADS, &[], 24, &mut out), FfvkResult::FFVK_SUCCESS);
    assert_eq!(written, 24);
}

/// The shader library's files from C: each name gives the text ffvk::shaders holds; a null or
/// misaligned pointer, a null name and an unknown name are refused with the output cleared and
/// a message naming the function and the value.
#[test]
fn the_shader_library_hands_out_each_file_and_refuses_bad_names_and_pointers() {
    use ffvk_c::shaders::{ffvkShaderLibraryFile, ffvkShaderLibraryVersion};
    assert_eq!(ffvkShaderLibraryVersion(), ffvk::shaders::LIBRARY_VERSION);
    for file in ffvk::shaders::FILES {
        let name = std::ffi::CString::new(file.name).unwrap();
        let (mut source, mut length) = (std::ptr::null::<std::ffi::c_char>(), 0usize);
        // SAFETY: a NUL-terminated name and writable outputs.
        let r = unsafe { ffvkShaderLibraryFile(name.as_ptr(), &mut source, &mut length) };
        assert_eq!(r, FfvkResult::FFVK_SUCCESS);
        // SAFETY: the library's static text of `length` bytes.
        let text = unsafe { std::slice::from_raw_parts(source.cast::<u8>(), length) };
        assert_eq!(text, file.source.as_bytes(), "{}", file.name);
    }
    let unknown = c"ffvk/lights.glsl";
    let (mut source, mut length) = (c"stale".as_ptr(), 7usize);
    // SAFETY: as above.
    let r = unsafe { ffvkShaderLibraryFile(unknown.as_ptr(), &mut source, &mut length) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert!(source.is_null() && length == 0);
    let message = message();
    assert!(
        message.contains("ffvkShaderLibraryFile")
            && message.contains("ffvk/lights.glsl")
            && message.contains("ffvk/lighting.glsl"),
        "{message}"
    );
    // SAFETY: null pointers are refused before any is followed.
    let r = unsafe { ffvkShaderLibraryFile(std::ptr::null(), &mut source, &mut length) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    // SAFETY: as above.
    let r = unsafe { ffvkShaderLibraryFile(unknown.as_ptr(), std::ptr::null_mut(), &mut length) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    let misaligned = (&mut length as *mut usize)
        .cast::<u8>()
        .wrapping_add(1)
        .cast::<usize>();
    // SAFETY: a misaligned pointer is refused before it is written.
    let r = unsafe { ffvkShaderLibraryFile(unknown.as_ptr(), &mut source, misaligned) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
}

/// The packers write what the shader library reads from a context's state, as the Rust
/// packers lay it out: the state block's switches and lights, the draw record's modelview (the
/// context's own, as `ffvkGetFloatv` answers it) and the specialization constants; a short
/// buffer, a null or misaligned pointer and a state GL cannot draw are refused by name.
#[test]
fn the_packers_write_the_librarys_block_record_and_constants_from_a_context() {
    use bytemuck::Zeroable;
    use ffvk::gpu::layout::{DrawRecord, SpecConstant, SpecKey, StateBlock};
    use ffvk_c::shaders::{ffvkPackDrawRecord, ffvkPackSpecKey, ffvkPackStateBlock};
    let c = Ctx::busy();
    let mut block = StateBlock::zeroed();
    let mut record = DrawRecord::zeroed();
    let mut key = SpecKey::UBER;
    // SAFETY: a live context and buffers of the sizes given.
    unsafe {
        let r = ffvkPackStateBlock(
            c.0,
            (&mut block as *mut StateBlock).cast(),
            size_of::<StateBlock>(),
        );
        assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
        let r = ffvkPackDrawRecord(
            c.0,
            (&mut record as *mut DrawRecord).cast(),
            size_of::<DrawRecord>(),
        );
        assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
        let r = ffvkPackSpecKey(c.0, (&mut key as *mut SpecKey).cast(), size_of::<SpecKey>());
        assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    }
    // Ctx::busy: LIGHTING and NORMALIZE on, lights 1 and 15 enabled, light 1's diffuse
    // (0.5, 1.2, 0.7, 0.8), packed first.
    assert_eq!((block.lighting, block.normalize, block.light_count), (1, 1, 2));
    assert_eq!(block.lights[0].d_cli, [0.5, 1.2, 0.7, 0.8]);
    assert_eq!(key.get(SpecConstant::LightCount), 2);
    assert_eq!(key.get(SpecConstant::Lighting), 1);
    let mut modelview = [0f32; 16];
    // SAFETY: 16 floats.
    unsafe { ffvkGetFloatv(c.0, MODELVIEW_MATRIX, modelview.as_mut_ptr()) };
    assert_eq!(record.modelview, modelview);

    // Refusals, each naming the function.
    let mut small = [0u32; 4];
    // SAFETY: 16 writable bytes, fewer than the block.
    let r = unsafe { ffvkPackStateBlock(c.0, small.as_mut_ptr().cast(), 16) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    let m = message();
    assert!(
        m.contains("ffvkPackStateBlock") && m.contains("size 16") && m.contains("3488"),
        "{m}"
    );
    // SAFETY: null pointers are refused before any is followed.
    let r = unsafe { ffvkPackSpecKey(null(), (&mut key as *mut SpecKey).cast(), size_of::<SpecKey>()) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    // SAFETY: as above.
    let r = unsafe { ffvkPackDrawRecord(c.0, null_mut(), 1 << 20) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    let odd = (small.as_mut_ptr() as *mut u8)
        .wrapping_add(1)
        .cast::<std::ffi::c_void>();
    // SAFETY: a misaligned pointer is refused before it is written.
    let r = unsafe { ffvkPackSpecKey(c.0, odd, 1 << 20) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    // A positional light with all-zero attenuation: GL could not draw it.
    let zero = Ctx::new();
    // SAFETY: a live context; four floats each.
    unsafe {
        ffvkEnable(zero.0, LIGHTING);
        ffvkEnable(zero.0, LIGHT0);
        ffvkLightfv(zero.0, LIGHT0, POSITION, [0.0, 0.0, 1.0, 1.0].as_ptr());
        ffvkLightf(zero.0, LIGHT0, CONSTANT_ATTENUATION, 0.0);
    }
    // SAFETY: a buffer of the block's size.
    let r = unsafe {
        ffvkPackStateBlock(
            zero.0,
            (&mut block as *mut StateBlock).cast(),
            size_of::<StateBlock>(),
        )
    };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert!(message().contains("ffvkPackStateBlock"), "{}", message());
}

/// A pipeline's own constants from C: points take the context's `glPointSize`, an RGBA8
/// target's alpha test compares 8-bit values, a bound and enabled unit is sampled and applied;
/// the state's constants are `ffvkPackSpecKey`'s; a mode beyond GL's ten is refused by name.
#[test]
fn the_pipeline_packer_sets_the_points_target_and_units_a_pipeline_fixes() {
    use ffvk::gpu::layout::{SpecConstant, SpecKey};
    use ffvk_c::shaders::{ffvkPackSpecKey, ffvkPackSpecKeyForPipeline};
    let c = Ctx::busy();
    // SAFETY: a live context.
    unsafe { ffvkPointSize(c.0, 4.0) };
    let (mut state_key, mut key) = (SpecKey::UBER, SpecKey::UBER);
    let rgba8 = ffvk::ash::vk::Format::R8G8B8A8_UNORM;
    // SAFETY: a live context and keys of the size given.
    unsafe {
        let r = ffvkPackSpecKey(c.0, (&mut state_key as *mut SpecKey).cast(), size_of::<SpecKey>());
        assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
        let r = ffvkPackSpecKeyForPipeline(
            c.0,
            POINTS,
            rgba8,
            0,
            0,
            (&mut key as *mut SpecKey).cast(),
            size_of::<SpecKey>(),
        );
        assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    }
    assert_eq!(key.get(SpecConstant::Points), 1);
    assert_eq!(key.get(SpecConstant::PointSize), 4.0f32.to_bits() as i32);
    assert_eq!(key.get(SpecConstant::AlphaBits), 8);
    assert_eq!(
        key.get(SpecConstant::LightCount),
        state_key.get(SpecConstant::LightCount)
    );
    assert_eq!(
        key.get(SpecConstant::Lighting),
        state_key.get(SpecConstant::Lighting)
    );
    // SAFETY: as above.
    let r = unsafe {
        ffvkPackSpecKeyForPipeline(
            c.0,
            0x000A,
            rgba8,
            0,
            0,
            (&mut key as *mut SpecKey).cast(),
            size_of::<SpecKey>(),
        )
    };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    let m = message();
    assert!(
        m.contains("ffvkPackSpecKeyForPipeline") && m.contains("0x000A"),
        "{m}"
    );
    // A unit past the last: refused by name.
    // SAFETY: as above.
    let r = unsafe {
        ffvkPackSpecKeyForPipeline(
            c.0,
            POINTS,
            rgba8,
            0x10,
            0,
            (&mut key as *mut SpecKey).cast(),
            size_of::<SpecKey>(),
        )
    };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    let m = message();
    assert!(m.contains("bound2d 0x10"), "{m}");
}

/// The resolver from C: the library's includes inlined, the size asked first with a null
/// buffer, a buffer one byte short refused with nothing written, an unknown file named.
#[test]
fn the_resolver_inlines_the_librarys_includes_for_a_c_caller() {
    use ffvk_c::shaders::ffvkShaderLibraryResolve;
    let source =
        std::ffi::CString::new("#version 300 es\n#include \"ffvk/es.glsl\"\nvoid main() {}\n").unwrap();
    let mut length = 0usize;
    // SAFETY: a NUL-terminated source, a null buffer of capacity 0, a writable length.
    let r = unsafe { ffvkShaderLibraryResolve(source.as_ptr(), null_mut(), 0, &mut length) };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    let expected = ffvk::shaders::resolve(source.to_str().unwrap()).unwrap();
    assert_eq!(length, expected.len());
    let mut short = vec![b'x' as std::ffi::c_char; length];
    // SAFETY: `length` writable bytes, one fewer than the text and its NUL need.
    let r = unsafe { ffvkShaderLibraryResolve(source.as_ptr(), short.as_mut_ptr(), length, &mut length) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert!(
        short.iter().all(|&c| c == b'x' as std::ffi::c_char),
        "nothing written"
    );
    let mut text = vec![0 as std::ffi::c_char; length + 1];
    // SAFETY: `length + 1` writable bytes.
    let r = unsafe { ffvkShaderLibraryResolve(source.as_ptr(), text.as_mut_ptr(), length + 1, &mut length) };
    assert_eq!(r, FfvkResult::FFVK_SUCCESS, "{}", message());
    // SAFETY: NUL-terminated by the call.
    let got = unsafe { std::ffi::CStr::from_ptr(text.as_ptr()) }
        .to_str()
        .unwrap();
    assert_eq!(got, expected);
    assert!(
        got.contains("precision highp float;")
            && !got.lines().any(|l| l.trim_start().starts_with("#include")),
        "{got}"
    );
    let unknown = std::ffi::CString::new("#include \"ffvk/lights.glsl\"\n").unwrap();
    // SAFETY: as above.
    let r = unsafe { ffvkShaderLibraryResolve(unknown.as_ptr(), null_mut(), 0, &mut length) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    let m = message();
    assert!(
        m.contains("ffvkShaderLibraryResolve") && m.contains("ffvk/lights.glsl") && m.contains("line 1"),
        "{m}"
    );
    // SAFETY: a null source is refused before it is read.
    let r = unsafe { ffvkShaderLibraryResolve(std::ptr::null(), null_mut(), 0, &mut length) };
    assert_eq!(r, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
}
