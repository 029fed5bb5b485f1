//! The scene file's shape, as serde reads it: TOML tables with GL's names, every field
//! optional and unknown fields rejected. Values are checked, and defaults filled in, when
//! the scene is built from it.

use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// A whole scene file.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    #[serde(default)]
    pub(super) image: ImageSpec,
    #[serde(default)]
    pub(super) camera: CameraSpec,
    /// GL_LIGHTING. On unless said otherwise: scene files are about lighting.
    pub(super) lighting: Option<bool>,
    #[serde(default)]
    pub(super) light_model: LightModelSpec,
    #[serde(default)]
    pub(super) lights: Vec<LightSpec>,
    pub(super) material: Option<MaterialSpec>,
    pub(super) back_material: Option<MaterialSpec>,
    pub(super) color_material: Option<ColorMaterialSpec>,
    /// GL_TEXTURE_2D with a texture, for every mesh without its own.
    pub(super) texture: Option<TextureSpec>,
    /// GL_NORMALIZE; off (GL's default), or on under `gltf_defaults`.
    pub(super) normalize: Option<bool>,
    #[serde(default)]
    pub(super) rescale_normal: bool,
    /// How the KHR_lights_punctual lights of the glTF files are added after `lights`:
    /// "off", "gl" or "exact" (true and false as "gl" and "off").
    pub(super) gltf_lights: Option<GltfLightsSpec>,
    /// glTF's meaning for the glTF meshes (see `meaning.rs`) instead of GL's defaults.
    pub(super) gltf_defaults: Option<bool>,
    /// GL light color per glTF light unit (lux, candela), or "auto".
    pub(super) gltf_exposure: Option<ExposureSpec>,
    /// `GL_COLOR_SUM`: off (GL's default).
    pub(super) color_sum: Option<bool>,
    /// GL's current secondary color (glSecondaryColor3f: RGB), added by the color sum with
    /// lighting off; (0, 0, 0) by default.
    pub(super) secondary_color: Option<Vec<f32>>,
    /// `[fog]`: GL_FOG and glFog.
    pub(super) fog: Option<FogSpec>,
    /// `[alpha_test]`: GL_ALPHA_TEST and glAlphaFunc.
    pub(super) alpha_test: Option<AlphaTestSpec>,
    /// `[points]`: glPointSize and glPointParameter, GL_POINT_SPRITE.
    pub(super) points: Option<PointsSpec>,
    /// `[[clip_planes]]`: glClipPlane and GL_CLIP_PLANEi, in world space.
    #[serde(default)]
    pub(super) clip_planes: Vec<ClipPlaneSpec>,
    #[serde(default)]
    pub(super) meshes: Vec<MeshSpec>,
}

/// `[fog]`: GL_FOG (on unless `enabled = false`) and glFog's parameters, GL's defaults for
/// those left out.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FogSpec {
    pub(super) enabled: Option<bool>,
    /// "linear", "exp" (GL's default) or "exp2".
    pub(super) mode: Option<String>,
    pub(super) density: Option<f32>,
    pub(super) start: Option<f32>,
    pub(super) end: Option<f32>,
    pub(super) color: Option<Vec<f32>>,
    /// "fragment_depth" (GL's default) or "fog_coord".
    pub(super) coord_src: Option<String>,
    /// GL's current fog coordinate (glFogCoord), read with `coord_src = "fog_coord"`.
    pub(super) coord: Option<f32>,
    /// GL_FOG_HINT: "dont_care" (GL's default), "fastest" or "nicest".
    pub(super) hint: Option<String>,
}

/// `[points]`: how the meshes drawn as points are drawn, GL's defaults for those left out.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct PointsSpec {
    /// glPointSize, > 0.
    pub(super) size: Option<f32>,
    /// GL_POINT_SIZE_MIN, ≥ 0.
    pub(super) size_min: Option<f32>,
    /// GL_POINT_SIZE_MAX, ≥ 0.
    pub(super) size_max: Option<f32>,
    /// GL_POINT_DISTANCE_ATTENUATION, [a, b, c].
    pub(super) distance_attenuation: Option<[f32; 3]>,
    /// GL_POINT_FADE_THRESHOLD_SIZE, ≥ 0.
    pub(super) fade_threshold_size: Option<f32>,
    /// GL_POINT_SPRITE.
    pub(super) sprite: Option<bool>,
    /// GL_POINT_SPRITE_COORD_ORIGIN: "upper_left" (GL's default) or "lower_left".
    pub(super) sprite_coord_origin: Option<String>,
}

/// `[alpha_test]`: GL_ALPHA_TEST (on unless `enabled = false`) and glAlphaFunc.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct AlphaTestSpec {
    pub(super) enabled: Option<bool>,
    /// "never", "less", "equal", "lequal", "greater", "notequal", "gequal" or "always"
    /// (GL's default).
    pub(super) func: Option<String>,
    /// The reference, clamped to [0, 1] as GL clamps it; 0 by default.
    pub(super) reference: Option<f32>,
}

/// One `[[clip_planes]]` table: glClipPlane(GL_CLIP_PLANEi) in world space (given with the
/// view loaded, as a program sets it after glLoadMatrix(view)), enabled unless said otherwise.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ClipPlaneSpec {
    /// i in 0..6; the table's position by default.
    pub(super) index: Option<usize>,
    #[serde(default, deserialize_with = "exact")]
    pub(super) equation: Option<[f64; 4]>,
    pub(super) enabled: Option<bool>,
}

/// `gltf_lights`: a word, or a boolean as earlier versions wrote.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub(super) enum GltfLightsSpec {
    Bool(bool),
    Word(String),
}

/// `gltf_exposure`: a number, or a word (only "auto" is one).
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub(super) enum ExposureSpec {
    Scale(f64),
    Word(String),
}

/// `[image]`: the picture and how it is drawn.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ImageSpec {
    #[serde(default, deserialize_with = "exact")]
    pub(super) size: Option<[u32; 2]>,
    pub(super) clear_color: Option<Vec<f32>>,
    /// glClearStencil, 0..=255; 0 by default. Read wide, so that a bad value is refused by
    /// name.
    pub(super) clear_stencil: Option<i64>,
    pub(super) lighting_mode: Option<String>,
    pub(super) depth_test: Option<bool>,
    pub(super) fragment_path: Option<String>,
}

/// `[camera]`: gluLookAt and gluPerspective parameters, or the matrices themselves.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CameraSpec {
    #[serde(default, deserialize_with = "exact")]
    pub(super) eye: Option<[f32; 3]>,
    #[serde(default, deserialize_with = "exact")]
    pub(super) target: Option<[f32; 3]>,
    #[serde(default, deserialize_with = "exact")]
    pub(super) up: Option<[f32; 3]>,
    /// Vertical field of view, degrees (gluPerspective's fovy).
    pub(super) fovy: Option<f32>,
    pub(super) near: Option<f32>,
    pub(super) far: Option<f32>,
    /// Column-major, as glLoadMatrixf; replaces eye/target/up.
    #[serde(default, deserialize_with = "exact")]
    pub(super) view: Option<[f32; 16]>,
    /// Column-major GL projection; replaces fovy/near/far.
    #[serde(default, deserialize_with = "exact")]
    pub(super) projection: Option<[f32; 16]>,
}

/// `[light_model]`: glLightModel.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LightModelSpec {
    pub(super) ambient: Option<Vec<f32>>,
    pub(super) local_viewer: Option<bool>,
    pub(super) two_side: Option<bool>,
    pub(super) color_control: Option<String>,
    /// ffvk's extension: "blinn_halfway" (GL's) or "phong_reflect".
    pub(super) specular_model: Option<String>,
}

/// One `[[lights]]` table: glLight for one light.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LightSpec {
    /// GL_LIGHTi; by default the position in the list. Signed, so that a negative index is
    /// reported as out of GL's range rather than as a type mismatch.
    pub(super) index: Option<i64>,
    pub(super) enabled: Option<bool>,
    pub(super) ambient: Option<Vec<f32>>,
    pub(super) diffuse: Option<Vec<f32>>,
    pub(super) specular: Option<Vec<f32>>,
    /// World space, homogeneous: w = 0 is a directional light.
    #[serde(default, deserialize_with = "exact")]
    pub(super) position: Option<[f32; 4]>,
    /// World space.
    #[serde(default, deserialize_with = "exact")]
    pub(super) spot_direction: Option<[f32; 3]>,
    pub(super) spot_exponent: Option<f32>,
    pub(super) spot_cutoff: Option<f32>,
    pub(super) constant_attenuation: Option<f32>,
    pub(super) linear_attenuation: Option<f32>,
    pub(super) quadratic_attenuation: Option<f32>,
    /// ffvk's extension: "gl_exponent" (GL's), "linear_inner_outer" or
    /// "smoothstep_inner_outer".
    pub(super) spot_edge: Option<String>,
    /// The soft edge's inner half-angle, degrees.
    pub(super) spot_inner_cutoff: Option<f32>,
    /// ffvk's extension: "gl_k012" (GL's) or "gltf_inverse_square".
    pub(super) attenuation: Option<String>,
    /// glTF's range for "gltf_inverse_square", > 0.
    pub(super) range: Option<f32>,
}

/// A `material` table: glMaterial for one face, from a preset or from scratch.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MaterialSpec {
    /// A classic GL material (see `presets`); the fields below override it.
    pub(super) preset: Option<String>,
    pub(super) ambient: Option<Vec<f32>>,
    pub(super) diffuse: Option<Vec<f32>>,
    pub(super) specular: Option<Vec<f32>>,
    pub(super) emission: Option<Vec<f32>>,
    pub(super) shininess: Option<f32>,
}

/// `[color_material]`: glColorMaterial and GL_COLOR_MATERIAL.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ColorMaterialSpec {
    pub(super) enabled: Option<bool>,
    pub(super) face: Option<String>,
    pub(super) mode: Option<String>,
}

/// One `[[meshes]]` table: a glTF file (or part of one) or a built-in shape, placed.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MeshSpec {
    /// A .gltf or .glb file, relative to the scene file.
    pub(super) gltf: Option<PathBuf>,
    /// Only what the glTF node with this name places (it and its descendants).
    pub(super) node: Option<String>,
    /// Only primitives of the glTF mesh with this name.
    pub(super) mesh: Option<String>,
    /// A built-in shape instead of a file: "teapot", "sphere" or "plane".
    pub(super) builtin: Option<String>,
    /// Tessellation of a built-in shape (teapot: 1..=64, sphere: slices).
    pub(super) level: Option<u32>,
    /// Vertex color of a built-in shape (feeds COLOR_MATERIAL).
    pub(super) color: Option<Vec<f32>>,
    #[serde(default, deserialize_with = "exact")]
    pub(super) translate: Option<[f32; 3]>,
    /// Degrees about x, then y, then z.
    #[serde(default, deserialize_with = "exact")]
    pub(super) rotate: Option<[f32; 3]>,
    #[serde(default, deserialize_with = "exact")]
    pub(super) scale: Option<[f32; 3]>,
    /// Column-major model matrix; replaces translate/rotate/scale.
    #[serde(default, deserialize_with = "exact")]
    pub(super) matrix: Option<[f32; 16]>,
    /// Front (and back unless `back_material`) material for this mesh only.
    pub(super) material: Option<MaterialSpec>,
    pub(super) back_material: Option<MaterialSpec>,
    /// This mesh's texture (`enabled = false` draws it untextured): unit 0 alone.
    pub(super) texture: Option<TextureSpec>,
    /// This mesh's texture units, `GL_TEXTURE0` first (at most four); not with `texture`.
    pub(super) texture_units: Option<Vec<TextureSpec>>,
    /// GL's primitive mode its index list is drawn with ("triangles" by default): "points",
    /// "lines", "line_strip", "line_loop", "triangles", "triangle_strip", "triangle_fan",
    /// "quads", "quad_strip" or "polygon".
    pub(super) primitive: Option<String>,
    /// GL_CULL_FACE with glCullFace: "front", "back" or "front_and_back"; off by default.
    pub(super) cull_face: Option<String>,
    /// glFrontFace: "ccw" (GL's default) or "cw".
    pub(super) front_face: Option<String>,
    /// glPolygonMode: "fill" (GL's default), "line" or "point" for both faces, or
    /// `{ front = ..., back = ... }`.
    pub(super) polygon_mode: Option<PolygonModeSpec>,
    /// glPolygonOffset with GL_POLYGON_OFFSET_FILL (on with the table), _LINE and _POINT.
    pub(super) polygon_offset: Option<PolygonOffsetSpec>,
    /// glColorMask(r, g, b, a); all true by default.
    #[serde(default, deserialize_with = "exact")]
    pub(super) color_mask: Option<[bool; 4]>,
    /// GL_STENCIL_TEST with the front faces' (and points' and lines') state, and the back
    /// faces' unless `stencil_back` gives theirs.
    pub(super) stencil: Option<StencilSpec>,
    pub(super) stencil_back: Option<StencilSpec>,
    /// GL_COLOR_LOGIC_OP with glLogicOp: GL's names ("copy", "xor", ...).
    pub(super) logic_op: Option<String>,
    /// GL_LINE_STIPPLE with glLineStipple.
    pub(super) line_stipple: Option<LineStippleSpec>,
    /// GL_POLYGON_STIPPLE with glPolygonStipple: 32 rows from the bottom, each a 32-bit
    /// integer whose most significant bit is the leftmost column.
    pub(super) polygon_stipple: Option<Vec<i64>>,
    /// GL_BLEND with glBlendFuncSeparate and glBlendEquationSeparate.
    pub(super) blend: Option<BlendSpec>,
    /// glBlendColor, RGBA in [0, 1]; (0, 0, 0, 0) by default.
    pub(super) blend_color: Option<Vec<f32>>,
    /// glDepthRange(near, far), each clamped to [0, 1] as GL clamps it; [0, 1] by default.
    #[serde(default, deserialize_with = "exact")]
    pub(super) depth_range: Option<[f32; 2]>,
    /// glDepthMask: true (depth writes on) by default.
    pub(super) depth_mask: Option<bool>,
}

/// `polygon_mode`: one word for both faces, or a table with each face's.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub(super) enum PolygonModeSpec {
    Both(String),
    Faces(FacesSpec),
}

/// `polygon_mode = { front = ..., back = ... }`: `"fill"` for a face left out.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FacesSpec {
    pub(super) front: Option<String>,
    pub(super) back: Option<String>,
}

/// `polygon_offset`: glPolygonOffset and the modes it is enabled for.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct PolygonOffsetSpec {
    /// 0 by default.
    pub(super) factor: Option<f32>,
    /// 0 by default.
    pub(super) units: Option<f32>,
    /// GL_POLYGON_OFFSET_FILL: on when the table is given unless this says otherwise.
    pub(super) fill: Option<bool>,
    /// GL_POLYGON_OFFSET_LINE: off by default.
    pub(super) line: Option<bool>,
    /// GL_POLYGON_OFFSET_POINT: off by default.
    pub(super) point: Option<bool>,
}

/// `stencil` and `stencil_back`: glStencilFuncSeparate, glStencilOpSeparate and
/// glStencilMaskSeparate for one face. Integers are read wide, so that an out-of-range value
/// is refused by name rather than as a type mismatch.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct StencilSpec {
    /// "always" by default.
    pub(super) func: Option<String>,
    /// A GLint, 0 by default; GL clamps it to [0, 255] for the 8-bit stencil buffer.
    #[serde(rename = "ref")]
    pub(super) reference: Option<i64>,
    /// A GLuint, all ones by default.
    pub(super) value_mask: Option<i64>,
    /// "keep" by default, as are `depth_fail` and `pass`.
    pub(super) fail: Option<String>,
    pub(super) depth_fail: Option<String>,
    pub(super) pass: Option<String>,
    /// A GLuint, all ones by default.
    pub(super) write_mask: Option<i64>,
}

/// `line_stipple`: glLineStipple.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LineStippleSpec {
    /// 1..=256, 1 by default.
    pub(super) factor: Option<i64>,
    /// A GLushort, 0xFFFF by default.
    pub(super) pattern: Option<i64>,
}

/// `blend`: glBlendFuncSeparate and glBlendEquationSeparate; the alpha ones default to the
/// color ones.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct BlendSpec {
    /// "one" by default.
    pub(super) src: Option<String>,
    /// "zero" by default.
    pub(super) dst: Option<String>,
    /// "func_add" by default.
    pub(super) equation: Option<String>,
    pub(super) src_alpha: Option<String>,
    pub(super) dst_alpha: Option<String>,
    pub(super) equation_alpha: Option<String>,
}

/// A fixed-length array that refuses extra or missing elements (serde's own arrays, read from
/// TOML, ignore extra ones: `size = [64, 64, 64]` would pass).
pub(super) fn exact<'de, D, T, const N: usize>(d: D) -> Result<Option<[T; N]>, D::Error>
where
    D: serde::Deserializer<'de>,
    T: serde::Deserialize<'de> + Copy + Default,
{
    use serde::de::Error as _;
    let Some(values) = Option::<Vec<T>>::deserialize(d)? else {
        return Ok(None);
    };
    if values.len() != N {
        let expected = format!("an array of exactly {N} numbers");
        return Err(D::Error::invalid_length(values.len(), &expected.as_str()));
    }
    let mut out = [T::default(); N];
    out.copy_from_slice(&values);
    Ok(Some(out))
}

/// A `texture` table as serde reads it.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct TextureSpec {
    /// GL_TEXTURE_2D; on when the table is present unless this says otherwise.
    pub(super) enabled: Option<bool>,
    /// A PNG or JPEG file, relative to the scene file.
    pub(super) image: Option<std::path::PathBuf>,
    /// A built-in image: "checker", "leaves", "disc" or "lightmap".
    pub(super) builtin: Option<String>,
    /// `GL_COORD_REPLACE`: point sprites take the sprite's coordinates; off by default.
    pub(super) coord_replace: Option<bool>,
    pub(super) env: Option<String>,
    pub(super) env_color: Option<Vec<f32>>,
    /// `GL_COMBINE`'s parameters, read with `env = "combine"`.
    pub(super) combine: Option<CombineSpec>,
    /// Units 1-3: the mesh's texture coordinates ("mesh") or the unit's current ones
    /// (glMultiTexCoord4f: 4 numbers); (0, 0, 0, 1), GL's, by default. Read as any value, so
    /// that a wrong one is refused naming the field.
    pub(super) coords: Option<toml::Value>,
    pub(super) min_filter: Option<String>,
    pub(super) mag_filter: Option<String>,
    pub(super) wrap_s: Option<String>,
    pub(super) wrap_t: Option<String>,
    /// GL_GENERATE_MIPMAP; off, as in GL.
    pub(super) generate_mipmap: Option<bool>,
    /// GL_SRGB8_ALPHA8 instead of GL_RGBA8.
    pub(super) srgb: Option<bool>,
    /// The base internal format (glTexImage2D's `internalformat`, table 3.15): "rgba" (GL's
    /// `GL_RGBA`, the default), "rgb", "alpha", "luminance", "luminance_alpha" or "intensity".
    pub(super) format: Option<String>,
    /// The GL_TEXTURE matrix, column-major; or scale, rotate (degrees about r) and translate
    /// of (s, t), applied in that order.
    #[serde(default, deserialize_with = "exact")]
    pub(super) matrix: Option<[f32; 16]>,
    #[serde(default, deserialize_with = "exact")]
    pub(super) scale: Option<[f32; 2]>,
    pub(super) rotate: Option<f32>,
    #[serde(default, deserialize_with = "exact")]
    pub(super) translate: Option<[f32; 2]>,
    /// Texture coordinate generation: a table per coordinate generated, `s`, `t`, `r` or `q`.
    /// A map rather than fields, so that an unknown coordinate is refused naming its path.
    pub(super) texgen: Option<BTreeMap<String, TexCoordGenSpec>>,
    /// GL_TEXTURE_CUBE_MAP's texture for the unit, enabled with it (sampled before the 2D
    /// image, GL's precedence).
    pub(super) cube_map: Option<CubeMapSpec>,
}

/// A unit's `cube_map` table: six face files, GL's order (+X, -X, +Y, -Y, +Z, -Z), or a
/// built-in cube ("faces").
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CubeMapSpec {
    /// Six PNG or JPEG files, relative to the scene file, +X first.
    pub(super) faces: Option<Vec<std::path::PathBuf>>,
    /// A built-in cube: "faces" (each face one color of its own).
    pub(super) builtin: Option<String>,
}

/// One coordinate of a `texgen` table: glTexGen for it, GL_TEXTURE_GEN_S (`_T`, `_R`, `_Q`)
/// on unless `enabled = false`.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct TexCoordGenSpec {
    pub(super) enabled: Option<bool>,
    /// GL_TEXTURE_GEN_MODE: "object_linear", "eye_linear" (GL's default), "sphere_map",
    /// "reflection_map" or "normal_map".
    pub(super) mode: Option<String>,
    /// GL_OBJECT_PLANE or GL_EYE_PLANE (the mode's), 4 numbers; an eye plane in world space.
    /// Read as a list, so that a wrong length is refused by name.
    pub(super) plane: Option<Vec<f64>>,
}

/// A unit's `combine` table: glTexEnv's `GL_COMBINE` parameters (table 6.19's defaults for
/// those left out). Lists are read whole, so that a bad entry is refused naming its index.
#[derive(Debug, Default, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CombineSpec {
    /// `GL_COMBINE_RGB`: "modulate" by default.
    pub(super) rgb: Option<String>,
    /// `GL_COMBINE_ALPHA`: "modulate" by default; never a dot product.
    pub(super) alpha: Option<String>,
    /// `GL_SRC0_RGB` .. `GL_SRC2_RGB`, at most three, from Arg0.
    pub(super) rgb_sources: Option<Vec<String>>,
    /// `GL_SRC0_ALPHA` .. `GL_SRC2_ALPHA`.
    pub(super) alpha_sources: Option<Vec<String>>,
    /// `GL_OPERAND0_RGB` .. `GL_OPERAND2_RGB`.
    pub(super) rgb_operands: Option<Vec<String>>,
    /// `GL_OPERAND0_ALPHA` .. `GL_OPERAND2_ALPHA`.
    pub(super) alpha_operands: Option<Vec<String>>,
    /// `GL_RGB_SCALE`: 1, 2 or 4. Read as a float, so that 2 and 2.0 alike are taken.
    pub(super) rgb_scale: Option<f64>,
    /// `GL_ALPHA_SCALE`: 1, 2 or 4.
    pub(super) alpha_scale: Option<f64>,
}
