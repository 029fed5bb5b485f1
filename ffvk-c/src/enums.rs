//! GL's values for the enums the C API takes and returns (the GL 2.1 specification's tables,
//! as `<GL/gl.h>` spells them). The header defines each one guarded by `#ifndef`, so it
//! agrees with a caller's own GL headers included before or after it.

macro_rules! gl_enums {
    ($($name:ident = $value:expr),* $(,)?) => {
        $(#[allow(dead_code)] pub(crate) const $name: u32 = $value;)*
        /// Every GL enum the API uses, by name, for the header's guarded definitions.
        pub fn gl_enums() -> &'static [(&'static str, u32)] {
            &[$((stringify!($name), $value)),*]
        }
    };
}

gl_enums! {
    GL_FALSE = 0,
    GL_TRUE = 1,
    GL_NO_ERROR = 0,
    GL_INVALID_ENUM = 0x0500,
    GL_INVALID_VALUE = 0x0501,
    GL_INVALID_OPERATION = 0x0502,
    GL_OUT_OF_MEMORY = 0x0505,
    GL_CURRENT_COLOR = 0x0B00,
    GL_CURRENT_NORMAL = 0x0B02,
    GL_CURRENT_TEXTURE_COORDS = 0x0B03,
    GL_LIGHTING = 0x0B50,
    GL_LIGHT_MODEL_LOCAL_VIEWER = 0x0B51,
    GL_LIGHT_MODEL_TWO_SIDE = 0x0B52,
    GL_LIGHT_MODEL_AMBIENT = 0x0B53,
    GL_SHADE_MODEL = 0x0B54,
    GL_COLOR_MATERIAL_FACE = 0x0B55,
    GL_COLOR_MATERIAL_PARAMETER = 0x0B56,
    GL_COLOR_MATERIAL = 0x0B57,
    GL_NORMALIZE = 0x0BA1,
    GL_MODELVIEW_MATRIX = 0x0BA6,
    GL_PROJECTION_MATRIX = 0x0BA7,
    GL_TEXTURE_MATRIX = 0x0BA8,
    GL_BLEND = 0x0BE2,
    GL_FOG = 0x0B60,
    GL_CLIP_PLANE0 = 0x3000,
    GL_MAX_CLIP_PLANES = 0x0D32,
    GL_FOG_INDEX = 0x0B61,
    GL_FOG_DENSITY = 0x0B62,
    GL_FOG_START = 0x0B63,
    GL_FOG_END = 0x0B64,
    GL_FOG_MODE = 0x0B65,
    GL_FOG_COLOR = 0x0B66,
    GL_EXP = 0x0800,
    GL_EXP2 = 0x0801,
    GL_LINEAR = 0x2601,
    GL_FOG_COORD_SRC = 0x8450,
    GL_FOG_COORD = 0x8451,
    GL_FRAGMENT_DEPTH = 0x8452,
    GL_CURRENT_FOG_COORD = 0x8453,
    GL_PERSPECTIVE_CORRECTION_HINT = 0x0C50,
    GL_POINT_SMOOTH_HINT = 0x0C51,
    GL_LINE_SMOOTH_HINT = 0x0C52,
    GL_POLYGON_SMOOTH_HINT = 0x0C53,
    GL_FOG_HINT = 0x0C54,
    GL_GENERATE_MIPMAP_HINT = 0x8192,
    GL_TEXTURE_COMPRESSION_HINT = 0x84EF,
    GL_FRAGMENT_SHADER_DERIVATIVE_HINT = 0x8B8B,
    GL_POINT_SIZE_MIN = 0x8126,
    GL_POINT_SIZE_MAX = 0x8127,
    GL_POINT_FADE_THRESHOLD_SIZE = 0x8128,
    GL_POINT_DISTANCE_ATTENUATION = 0x8129,
    GL_POINT_SPRITE = 0x8861,
    GL_COORD_REPLACE = 0x8862,
    GL_POINT_SPRITE_COORD_ORIGIN = 0x8CA0,
    GL_LOWER_LEFT = 0x8CA1,
    GL_UPPER_LEFT = 0x8CA2,
    GL_DONT_CARE = 0x1100,
    GL_FASTEST = 0x1101,
    GL_NICEST = 0x1102,
    GL_ALPHA_TEST = 0x0BC0,
    GL_ALPHA_TEST_FUNC = 0x0BC1,
    GL_ALPHA_TEST_REF = 0x0BC2,
    GL_COLOR_SUM = 0x8458,
    GL_CURRENT_SECONDARY_COLOR = 0x8459,
    GL_NEVER = 0x0200,
    GL_LESS = 0x0201,
    GL_EQUAL = 0x0202,
    GL_LEQUAL = 0x0203,
    GL_GREATER = 0x0204,
    GL_NOTEQUAL = 0x0205,
    GL_GEQUAL = 0x0206,
    GL_ALWAYS = 0x0207,
    GL_MAX_LIGHTS = 0x0D31,
    GL_TEXTURE_2D = 0x0DE1,
    GL_FRONT = 0x0404,
    GL_BACK = 0x0405,
    GL_FRONT_AND_BACK = 0x0408,
    GL_ADD = 0x0104,
    GL_AMBIENT = 0x1200,
    GL_DIFFUSE = 0x1201,
    GL_SPECULAR = 0x1202,
    GL_POSITION = 0x1203,
    GL_SPOT_DIRECTION = 0x1204,
    GL_SPOT_EXPONENT = 0x1205,
    GL_SPOT_CUTOFF = 0x1206,
    GL_CONSTANT_ATTENUATION = 0x1207,
    GL_LINEAR_ATTENUATION = 0x1208,
    GL_QUADRATIC_ATTENUATION = 0x1209,
    GL_EMISSION = 0x1600,
    GL_SHININESS = 0x1601,
    GL_AMBIENT_AND_DIFFUSE = 0x1602,
    GL_COLOR_INDEXES = 0x1603,
    GL_FLAT = 0x1D00,
    GL_SMOOTH = 0x1D01,
    GL_REPLACE = 0x1E01,
    GL_MODULATE = 0x2100,
    GL_DECAL = 0x2101,
    GL_TEXTURE_ENV_MODE = 0x2200,
    GL_TEXTURE_ENV_COLOR = 0x2201,
    GL_TEXTURE_ENV = 0x2300,
    GL_LIGHT0 = 0x4000,
    GL_LIGHT1 = 0x4001,
    GL_LIGHT2 = 0x4002,
    GL_LIGHT3 = 0x4003,
    GL_LIGHT4 = 0x4004,
    GL_LIGHT5 = 0x4005,
    GL_LIGHT6 = 0x4006,
    GL_LIGHT7 = 0x4007,
    GL_RESCALE_NORMAL = 0x803A,
    GL_LIGHT_MODEL_COLOR_CONTROL = 0x81F8,
    GL_SINGLE_COLOR = 0x81F9,
    GL_SEPARATE_SPECULAR_COLOR = 0x81FA,
    GL_POINTS = 0x0000,
    GL_LINES = 0x0001,
    GL_LINE_LOOP = 0x0002,
    GL_LINE_STRIP = 0x0003,
    GL_TRIANGLES = 0x0004,
    GL_TRIANGLE_STRIP = 0x0005,
    GL_TRIANGLE_FAN = 0x0006,
    GL_QUADS = 0x0007,
    GL_QUAD_STRIP = 0x0008,
    GL_POLYGON = 0x0009,
}

/// GL's names for values the API refuses but an application may well pass on (a layer
/// forwarding every `glEnable`, a `glTexEnv` of `GL_COMBINE`), as `<GL/gl.h>` spells them:
/// messages name them. The header does not define them.
const MESSAGE_NAMES: &[(&str, u32)] = &[
    ("GL_STACK_OVERFLOW", 0x0503),
    ("GL_POINT_SMOOTH", 0x0B10),
    ("GL_LINE_SMOOTH", 0x0B20),
    ("GL_LINE_STIPPLE", 0x0B24),
    ("GL_POLYGON_SMOOTH", 0x0B41),
    ("GL_POLYGON_STIPPLE", 0x0B42),
    ("GL_CULL_FACE", 0x0B44),
    ("GL_DEPTH_RANGE", 0x0B70),
    ("GL_DEPTH_TEST", 0x0B71),
    ("GL_STENCIL_TEST", 0x0B90),
    ("GL_MATRIX_MODE", 0x0BA0),
    ("GL_VIEWPORT", 0x0BA2),
    ("GL_DITHER", 0x0BD0),
    ("GL_COLOR_LOGIC_OP", 0x0BF2),
    ("GL_SCISSOR_TEST", 0x0C11),
    ("GL_TEXTURE_GEN_S", 0x0C60),
    ("GL_TEXTURE_GEN_T", 0x0C61),
    ("GL_AUTO_NORMAL", 0x0D80),
    ("GL_TEXTURE_1D", 0x0DE0),
    ("GL_MODELVIEW", 0x1700),
    ("GL_PROJECTION", 0x1701),
    ("GL_TEXTURE", 0x1702),
    ("GL_POLYGON_OFFSET_FILL", 0x8037),
    ("GL_TEXTURE_3D", 0x806F),
    ("GL_VERTEX_ARRAY", 0x8074),
    ("GL_NORMAL_ARRAY", 0x8075),
    ("GL_COLOR_ARRAY", 0x8076),
    ("GL_TEXTURE_COORD_ARRAY", 0x8078),
    ("GL_MULTISAMPLE", 0x809D),
    ("GL_TEXTURE_CUBE_MAP", 0x8513),
    ("GL_COMBINE", 0x8570),
];

/// Every GL name a message may print with its value: the API's enums and the names of values
/// it refuses ([`MESSAGE_NAMES`]). The tests check each against `<GL/gl.h>`.
pub fn message_names() -> impl Iterator<Item = (&'static str, u32)> {
    gl_enums().iter().chain(MESSAGE_NAMES).copied()
}

/// GL's primitive modes in value order: `GL_POINTS` (0) .. `GL_POLYGON` (9).
const MODES: [&str; 10] = [
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

/// A GL enum as a message shows it: its name with its value, `GL_DEPTH_TEST (0x0B71)`, or the
/// value alone, `0x4010`, when GL has no name for it here. Values below 0x0100 (which GL's
/// booleans, primitive modes and blend factors share) are never named: a primitive mode is
/// shown by [`mode_name`].
pub(crate) fn enum_name(value: u32) -> String {
    let name = (value >= 0x0100)
        .then(|| message_names().find(|&(_, v)| v == value))
        .flatten();
    match name {
        Some((name, _)) => format!("{name} (0x{value:04X})"),
        None => format!("0x{value:04X}"),
    }
}

/// A primitive mode as a message shows it: `GL_QUAD_STRIP (0x0008)`, or `0x0042` for a value
/// that is none of GL's ten.
pub(crate) fn mode_name(mode: u32) -> String {
    match MODES.get(mode as usize) {
        Some(name) => format!("{name} (0x{mode:04X})"),
        None => format!("0x{mode:04X}"),
    }
}
