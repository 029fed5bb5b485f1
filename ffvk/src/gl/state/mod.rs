//! GL 2.1 lighting state (tables 2.10-2.12) with GL's defaults, GL's validation and GL's
//! "transform at specification time" rule for light positions and spot directions.
//!
//! [`GlState`] behaves like the fixed-function state machine an emulation layer ports:
//! `glLight`, `glMaterial`, `glLightModel`, `glColorMaterial`, `glShadeModel`, `glEnable`.
//! Values GL would answer with `INVALID_VALUE` (or `INVALID_ENUM`) are rejected with a
//! [`StateError`] naming the parameter, the value and the valid range.
//!
//! Color material is GL's (section 2.14.3): while `COLOR_MATERIAL` is enabled, `glColor`
//! ([`GlState::color`]), `glColorMaterial` and `glEnable(COLOR_MATERIAL)` write the current
//! color into the tracked material parameters, which keep it after
//! `glDisable(COLOR_MATERIAL)`, as in Mesa's GL (a conformance test pins it). A draw with a
//! per-vertex color array applies color material to each vertex's color while drawing and
//! leaves the state's material alone; GL leaves the current color undefined after such a draw
//! (section 2.8), and the state keeps the last `glColor`.
//!
//! ```
//! use ffvk::gl::state::{Cap, ColorMaterialMode, Face, GlState, LightParam, MaterialParam};
//! use ffvk::glam::{Mat4, Vec3, Vec4};
//!
//! let mut gl = GlState::new();
//! gl.enable(Cap::Lighting)?;
//! gl.enable(Cap::Light(0))?;
//! // Set under a view matrix, a light position is stored in eye space, as glLight does.
//! gl.load_modelview(Mat4::from_translation(Vec3::new(0.0, 0.0, -5.0)))?;
//! gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 1.0)))?;
//! assert_eq!(gl.lighting.lights[0].position, Vec4::new(0.0, 0.0, -4.0, 1.0));
//! // GL's INVALID_VALUE is an error naming the parameter; the state is unchanged.
//! let err = gl.light(0, LightParam::SpotCutoff(95.0)).unwrap_err();
//! assert!(err.to_string().starts_with("GL_SPOT_CUTOFF = 95"));
//! // glColor under COLOR_MATERIAL is written into the material, and stays after glDisable.
//! gl.color_material(Face::FrontAndBack, ColorMaterialMode::Diffuse);
//! gl.enable(Cap::ColorMaterial)?;
//! gl.color(Vec4::new(1.0, 0.5, 0.0, 1.0))?;
//! gl.disable(Cap::ColorMaterial)?;
//! assert_eq!(gl.lighting.front.diffuse, Vec4::new(1.0, 0.5, 0.0, 1.0));
//! # let _ = MaterialParam::Shininess(0.0);
//! # Ok::<(), ffvk::gl::state::StateError>(())
//! ```

use glam::{Vec3, Vec4};

use super::texture::{
    AlphaOperand, CombineFunc, CombineSource, RgbOperand, TexEnvMode, TextureUnit, MAX_TEXTURE_UNITS,
};

mod caps;
mod checks;
mod clip;
mod machine;
mod points;
mod raster;
mod stages;
mod values;
pub use caps::Cap;
pub use checks::validate_light;
use checks::validate_lights;
pub use clip::{ClipPlanes, MAX_CLIP_PLANES};
pub use machine::GlState;
pub use points::{PointParam, PointParameters, SpriteOrigin};
pub use raster::{
    BlendEquation, BlendFactor, FrontFace, GlEnum, LogicOp, PolygonMode, RasterGl, StencilGl, StencilOp,
    STENCIL_BITS, STENCIL_ONES,
};
pub use stages::{AlphaTest, CompareFunc, Fog, FogHint, FogMode, FogParam, FogSource, FragmentStages};
pub use values::DrawValues;

/// Lights ffvk evaluates per draw (GL_MAX_LIGHTS). GL requires at least 8.
pub const MAX_LIGHTS: usize = 16;

pub use super::errors::StateError;

/// One light source's state, in eye coordinates as GL stores it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Light {
    /// `GL_LIGHTi` (glEnable); false for every light initially, light 0 included. A disabled
    /// light contributes nothing.
    pub enabled: bool,
    /// a_cli, `GL_AMBIENT`: default (0, 0, 0, 1). Components are unrestricted (negative or
    /// above 1 allowed); only RGB enters the equation.
    pub ambient: Vec4,
    /// d_cli, `GL_DIFFUSE`: default (1, 1, 1, 1) for light 0, (0, 0, 0, 1) for the others.
    pub diffuse: Vec4,
    /// s_cli, `GL_SPECULAR`: default (1, 1, 1, 1) for light 0, (0, 0, 0, 1) for the others.
    pub specular: Vec4,
    /// P_pli, `GL_POSITION`, homogeneous, eye space (already transformed by the modelview at
    /// specification time). w = 0: a directional light from direction (x, y, z), never
    /// attenuated; w ≠ 0: a positional light at (x, y, z) / w. Default (0, 0, 1, 0).
    pub position: Vec4,
    /// s_dli, `GL_SPOT_DIRECTION`, eye space (transformed by the upper 3x3 of the modelview
    /// at specification time); any length, normalized where used. Default (0, 0, -1).
    pub spot_direction: Vec3,
    /// s_rli, `GL_SPOT_EXPONENT`, in [0, 128]; default 0 (uniform cone, with 0^0 = 1).
    pub spot_exponent: f32,
    /// c_rli, `GL_SPOT_CUTOFF`, the cone's half-angle in degrees, in [0, 90] or exactly 180;
    /// default 180, which turns the spot off (spot_i = 1).
    pub spot_cutoff: f32,
    /// k0, `GL_CONSTANT_ATTENUATION`, >= 0; default 1. att_i = 1 / (k0 + k1·d + k2·d²), d
    /// the eye-space distance to the light, applies only when `position.w != 0`; drawing
    /// fails if an enabled positional light has k0 + k1 + k2 = 0.
    pub constant_attenuation: f32,
    /// k1, `GL_LINEAR_ATTENUATION`, the factor of d, >= 0; default 0.
    pub linear_attenuation: f32,
    /// k2, `GL_QUADRATIC_ATTENUATION`, the factor of d², >= 0; default 0.
    pub quadratic_attenuation: f32,
    /// How the cone's edge falls off (ffvk's extension); default [`SpotEdge::GlExponent`],
    /// GL's.
    pub spot_edge: SpotEdge,
    /// How intensity falls off with distance (ffvk's extension); default
    /// [`Attenuation::GlK012`], GL's.
    pub attenuation: Attenuation,
}

/// How a spotlight's intensity falls off towards its cone's edge. cos θ is GL's
/// P_pliV ⊙ ŝ_dli, the outer cone is `GL_SPOT_CUTOFF` (c_rli); with c_rli = 180 there is no
/// cone and every edge gives spot_i = 1.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub enum SpotEdge {
    /// GL's: (cos θ)^s_rli inside the cone, 0 outside (`GL_SPOT_EXPONENT`).
    #[default]
    GlExponent,
    /// 1 inside the inner cone, 0 outside the outer, and between them
    /// clamp((cos θ − cos outer) / (cos inner − cos outer), 0, 1); the exponent is not used.
    /// An inner angle equal to the outer is a hard cutoff at that angle.
    LinearInnerOuter {
        /// The inner cone's half-angle in degrees, in [0, 90] and at most the outer.
        inner_degrees: f32,
    },
    /// As [`SpotEdge::LinearInnerOuter`], with smoothstep(cos outer, cos inner, cos θ)
    /// between the cones (glTF's KHR_lights_punctual cone, as Khronos' sample viewer draws
    /// it).
    SmoothstepInnerOuter {
        /// The inner cone's half-angle in degrees, in [0, 90] and at most the outer.
        inner_degrees: f32,
    },
}

impl SpotEdge {
    /// The name scene files and `ffvk explain` use.
    pub fn name(self) -> &'static str {
        match self {
            SpotEdge::GlExponent => "gl_exponent",
            SpotEdge::LinearInnerOuter { .. } => "linear_inner_outer",
            SpotEdge::SmoothstepInnerOuter { .. } => "smoothstep_inner_outer",
        }
    }

    /// The inner cone's half-angle, for the soft edges.
    pub fn inner_degrees(self) -> Option<f32> {
        match self {
            SpotEdge::GlExponent => None,
            SpotEdge::LinearInnerOuter { inner_degrees }
            | SpotEdge::SmoothstepInnerOuter { inner_degrees } => Some(inner_degrees),
        }
    }
}

/// How a positional light's intensity falls off with the eye-space distance d to it.
/// Directional lights (w = 0) are never attenuated.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub enum Attenuation {
    /// GL's: att_i = 1 / (k0 + k1·d + k2·d²).
    #[default]
    GlK012,
    /// glTF's (KHR_lights_punctual): att_i = 1 / d², times the window
    /// clamp(1 − (d / range)⁴, 0, 1) when the light has a range (as Khronos' sample viewer
    /// draws it); k0, k1 and k2 are not used. Infinite at d = 0, as GL's k2-only falloff is.
    GltfInverseSquare {
        /// Where the light's influence ends, > 0 (eye-space units); `None`: unbounded.
        range: Option<f32>,
    },
}

impl Attenuation {
    /// The name scene files and `ffvk explain` use.
    pub fn name(self) -> &'static str {
        match self {
            Attenuation::GlK012 => "gl_k012",
            Attenuation::GltfInverseSquare { .. } => "gltf_inverse_square",
        }
    }
}

/// Which specular term the equation uses (ffvk's extension to the light model).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum SpecularModel {
    /// GL's: f_i (n ⊙ ĥ_i)^s_rm, ĥ_i the unit halfway vector between VP_pli and the
    /// direction to the viewer (Blinn).
    #[default]
    BlinnHalfway,
    /// Phong's original: f_i (r_i ⊙ v)^s_rm, r_i = 2 (n · VP_pli) n − VP_pli the reflection of
    /// the direction to the light about n, v the direction to the viewer ((0, 0, 1) unless
    /// the viewer is local), with the same clamping of negative products and the same f_i.
    /// For the same exponent its highlight is narrower than GL's: for coplanar vectors the
    /// halfway angle is half of r_i's (larger otherwise), so (n ⊙ ĥ_i)^s_rm falls off more
    /// slowly (about four times the exponent gives GL's term a similar highlight).
    PhongReflect,
}

impl SpecularModel {
    /// The name scene files and `ffvk explain` use.
    pub fn name(self) -> &'static str {
        match self {
            SpecularModel::BlinnHalfway => "blinn_halfway",
            SpecularModel::PhongReflect => "phong_reflect",
        }
    }
}

impl Light {
    /// GL's initial state of light `index`: light 0 has white diffuse and specular, the others black.
    pub fn gl_default(index: usize) -> Self {
        let white_if_first = if index == 0 {
            Vec4::ONE
        } else {
            Vec4::new(0.0, 0.0, 0.0, 1.0)
        };
        Light {
            enabled: false,
            ambient: Vec4::new(0.0, 0.0, 0.0, 1.0),
            diffuse: white_if_first,
            specular: white_if_first,
            position: Vec4::new(0.0, 0.0, 1.0, 0.0),
            spot_direction: Vec3::new(0.0, 0.0, -1.0),
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            constant_attenuation: 1.0,
            linear_attenuation: 0.0,
            quadratic_attenuation: 0.0,
            spot_edge: SpotEdge::GlExponent,
            attenuation: Attenuation::GlK012,
        }
    }
}

/// Material state of one face.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Material {
    /// a_cm, `GL_AMBIENT`: default (0.2, 0.2, 0.2, 1). Components are unrestricted.
    pub ambient: Vec4,
    /// d_cm, `GL_DIFFUSE`: default (0.8, 0.8, 0.8, 1). Its alpha is the lit color's alpha.
    pub diffuse: Vec4,
    /// s_cm, `GL_SPECULAR`: default (0, 0, 0, 1), so no highlight until it is set.
    pub specular: Vec4,
    /// e_cm, `GL_EMISSION`: default (0, 0, 0, 1); added unlit and unattenuated.
    pub emission: Vec4,
    /// s_rm, `GL_SHININESS`, the specular exponent, in [0, 128]; default 0 (with 0^0 = 1).
    pub shininess: f32,
}

impl Default for Material {
    /// GL's initial material (table 2.10).
    fn default() -> Self {
        Material {
            ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            diffuse: Vec4::new(0.8, 0.8, 0.8, 1.0),
            specular: Vec4::new(0.0, 0.0, 0.0, 1.0),
            emission: Vec4::new(0.0, 0.0, 0.0, 1.0),
            shininess: 0.0,
        }
    }
}

impl Material {
    /// Checks the ranges GL checks (shininess in [0, 128]) and that every value is finite.
    pub fn validate(&self) -> Result<(), StateError> {
        for (name, c) in [
            ("GL_AMBIENT", self.ambient),
            ("GL_DIFFUSE", self.diffuse),
            ("GL_SPECULAR", self.specular),
            ("GL_EMISSION", self.emission),
        ] {
            finite_vec(name, c.to_array().as_slice())?;
        }
        in_range("GL_SHININESS", self.shininess, 0.0, 128.0, "a value in [0, 128]")
    }
}

/// c_es, `GL_LIGHT_MODEL_COLOR_CONTROL`: where the specular term goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ColorControl {
    /// `GL_SINGLE_COLOR` (the default): specular is part of c_pri; c_sec is (0, 0, 0, 1).
    #[default]
    SingleColor,
    /// `GL_SEPARATE_SPECULAR_COLOR`: specular goes to c_sec, which GL adds after texturing
    /// (so a texture does not darken the highlight); untextured, only the clamping differs:
    /// each color is clamped before the color sum.
    SeparateSpecularColor,
}

/// Light-model state.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct LightModel {
    /// a_cs, `GL_LIGHT_MODEL_AMBIENT`, scaled by a_cm for every lit point even with no light
    /// enabled; default (0.2, 0.2, 0.2, 1).
    pub ambient: Vec4,
    /// v_bs, `GL_LIGHT_MODEL_LOCAL_VIEWER`; default false: the viewer is at infinity along +z
    /// and h_i uses (0, 0, 1) instead of the direction to the eye.
    pub local_viewer: bool,
    /// t_bs, `GL_LIGHT_MODEL_TWO_SIDE`; default false. When true, back faces are lit with the
    /// back material and the negated normal.
    pub two_side: bool,
    /// c_es, `GL_LIGHT_MODEL_COLOR_CONTROL`; default [`ColorControl::SingleColor`].
    pub color_control: ColorControl,
    /// The specular term (ffvk's extension); default [`SpecularModel::BlinnHalfway`], GL's.
    pub specular_model: SpecularModel,
}

impl Default for LightModel {
    fn default() -> Self {
        LightModel {
            ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            local_viewer: false,
            two_side: false,
            color_control: ColorControl::SingleColor,
            specular_model: SpecularModel::BlinnHalfway,
        }
    }
}

/// A face selector for glMaterial and glColorMaterial.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Face {
    /// `GL_FRONT`.
    Front,
    /// `GL_BACK`: the back material, which lights only with two-sided lighting on.
    Back,
    /// `GL_FRONT_AND_BACK`, glColorMaterial's initial face.
    #[default]
    FrontAndBack,
}

impl Face {
    /// Whether the selector affects the front material (`GL_FRONT` or `GL_FRONT_AND_BACK`).
    pub fn includes_front(self) -> bool {
        matches!(self, Face::Front | Face::FrontAndBack)
    }
    /// Whether the selector affects the back material (`GL_BACK` or `GL_FRONT_AND_BACK`).
    pub fn includes_back(self) -> bool {
        matches!(self, Face::Back | Face::FrontAndBack)
    }
}

/// The material parameter(s) glColorMaterial makes track the current color.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ColorMaterialMode {
    /// `GL_EMISSION`: e_cm.
    Emission,
    /// `GL_AMBIENT`: a_cm.
    Ambient,
    /// `GL_DIFFUSE`: d_cm, and with it the lit alpha.
    Diffuse,
    /// `GL_SPECULAR`: s_cm.
    Specular,
    /// `GL_AMBIENT_AND_DIFFUSE` (the initial mode): a_cm and d_cm.
    #[default]
    AmbientAndDiffuse,
}

/// COLOR_MATERIAL state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub struct ColorMaterial {
    /// glEnable(`GL_COLOR_MATERIAL`); default false.
    pub enabled: bool,
    /// glColorMaterial's face; default [`Face::FrontAndBack`].
    pub face: Face,
    /// glColorMaterial's mode; default [`ColorMaterialMode::AmbientAndDiffuse`].
    pub mode: ColorMaterialMode,
}

impl ColorMaterial {
    /// The material of one face with the tracked parameter(s) replaced by `color`.
    pub fn apply(&self, material: &Material, color: Vec4, back: bool) -> Material {
        let mut m = *material;
        let applies = if back {
            self.face.includes_back()
        } else {
            self.face.includes_front()
        };
        if !self.enabled || !applies {
            return m;
        }
        match self.mode {
            ColorMaterialMode::Emission => m.emission = color,
            ColorMaterialMode::Ambient => m.ambient = color,
            ColorMaterialMode::Diffuse => m.diffuse = color,
            ColorMaterialMode::Specular => m.specular = color,
            ColorMaterialMode::AmbientAndDiffuse => {
                m.ambient = color;
                m.diffuse = color;
            }
        }
        m
    }
}

/// Where the one equation is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum LightingMode {
    /// Lit at each vertex, clamped there, colors interpolated (GL's SMOOTH; Gouraud's method).
    #[default]
    Vertex,
    /// Eye-space position and normal interpolated, lit at each fragment (Phong's
    /// interpolation; the specular term stays GL's halfway-vector one).
    Fragment,
    /// GL's ShadeModel(FLAT): lit per vertex, the triangle takes its last vertex's color.
    Flat,
}

impl LightingMode {
    /// Every mode, in declaration order (for loops over modes in tests and benchmarks).
    pub const ALL: [LightingMode; 3] = [LightingMode::Vertex, LightingMode::Fragment, LightingMode::Flat];

    /// Lowercase name (`vertex`, `fragment`, `flat`), the one [`str::parse`] accepts.
    pub fn name(self) -> &'static str {
        match self {
            LightingMode::Vertex => "vertex",
            LightingMode::Fragment => "fragment",
            LightingMode::Flat => "flat",
        }
    }
}

impl std::str::FromStr for LightingMode {
    type Err = super::errors::UnknownName;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "vertex" => Ok(LightingMode::Vertex),
            "fragment" => Ok(LightingMode::Fragment),
            "flat" => Ok(LightingMode::Flat),
            other => Err(super::errors::UnknownName::new(
                "lighting mode",
                other,
                "vertex, fragment or flat",
            )),
        }
    }
}

/// GL's ShadeModel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShadeModel {
    /// `GL_SMOOTH` (GL's default): selects [`LightingMode::Vertex`].
    Smooth,
    /// `GL_FLAT`: selects [`LightingMode::Flat`].
    Flat,
}

/// Parameters of glTexEnv (target `GL_TEXTURE_ENV`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum TexEnvParam {
    /// `GL_TEXTURE_ENV_MODE`.
    Mode(TexEnvMode),
    /// `GL_TEXTURE_ENV_COLOR`, C_c: clamped to [0, 1] as GL does; NaN or infinity is an error.
    Color(Vec4),
    /// `GL_COMBINE_RGB`.
    CombineRgb(CombineFunc),
    /// `GL_COMBINE_ALPHA`: `GL_DOT3_RGB` and `GL_DOT3_RGBA` are GL's `GL_INVALID_ENUM`.
    CombineAlpha(CombineFunc),
    /// `GL_SRCn_RGB`, n in 0..3.
    SourceRgb(usize, CombineSource),
    /// `GL_SRCn_ALPHA`, n in 0..3.
    SourceAlpha(usize, CombineSource),
    /// `GL_OPERANDn_RGB`, n in 0..3.
    OperandRgb(usize, RgbOperand),
    /// `GL_OPERANDn_ALPHA`, n in 0..3.
    OperandAlpha(usize, AlphaOperand),
    /// `GL_RGB_SCALE`: 1, 2 or 4, else GL's `GL_INVALID_VALUE`.
    RgbScale(f32),
    /// `GL_ALPHA_SCALE`: 1, 2 or 4, else GL's `GL_INVALID_VALUE`.
    AlphaScale(f32),
}

/// Parameters of glLight.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum LightParam {
    /// `GL_AMBIENT`, a_cli: any finite RGBA.
    Ambient(Vec4),
    /// `GL_DIFFUSE`, d_cli: any finite RGBA.
    Diffuse(Vec4),
    /// `GL_SPECULAR`, s_cli: any finite RGBA.
    Specular(Vec4),
    /// `GL_POSITION`, P_pli. Object coordinates: transformed by the modelview in force at
    /// the call.
    Position(Vec4),
    /// `GL_SPOT_DIRECTION`, s_dli. Object coordinates: transformed by the upper 3x3 of the
    /// modelview in force at the call.
    SpotDirection(Vec3),
    /// `GL_SPOT_EXPONENT`, s_rli, in [0, 128].
    SpotExponent(f32),
    /// `GL_SPOT_CUTOFF`, c_rli, in degrees: [0, 90] or exactly 180.
    SpotCutoff(f32),
    /// `GL_CONSTANT_ATTENUATION`, k0, >= 0.
    ConstantAttenuation(f32),
    /// `GL_LINEAR_ATTENUATION`, k1, >= 0.
    LinearAttenuation(f32),
    /// `GL_QUADRATIC_ATTENUATION`, k2, >= 0.
    QuadraticAttenuation(f32),
    /// ffvk's extension: the spot edge; a soft edge's inner angle in [0, 90] (and, when the
    /// light is drawn, at most `GL_SPOT_CUTOFF`).
    SpotEdge(SpotEdge),
    /// ffvk's extension: the distance falloff; a glTF range > 0.
    Attenuation(Attenuation),
}

/// Parameters of glMaterial.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum MaterialParam {
    /// `GL_AMBIENT`, a_cm: any finite RGBA.
    Ambient(Vec4),
    /// `GL_DIFFUSE`, d_cm: any finite RGBA.
    Diffuse(Vec4),
    /// `GL_SPECULAR`, s_cm: any finite RGBA.
    Specular(Vec4),
    /// `GL_EMISSION`, e_cm: any finite RGBA.
    Emission(Vec4),
    /// `GL_SHININESS`, s_rm, in [0, 128].
    Shininess(f32),
    /// `GL_AMBIENT_AND_DIFFUSE`: sets a_cm and d_cm to the same color.
    AmbientAndDiffuse(Vec4),
}

/// Parameters of glLightModel.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum LightModelParam {
    /// `GL_LIGHT_MODEL_AMBIENT`, a_cs: any finite RGBA.
    Ambient(Vec4),
    /// `GL_LIGHT_MODEL_LOCAL_VIEWER`, v_bs.
    LocalViewer(bool),
    /// `GL_LIGHT_MODEL_TWO_SIDE`, t_bs.
    TwoSide(bool),
    /// `GL_LIGHT_MODEL_COLOR_CONTROL`, c_es.
    ColorControl(ColorControl),
    /// ffvk's extension: the specular term.
    SpecularModel(SpecularModel),
}

/// GL's fixed-function state a draw captures, besides its geometry, matrices and raster state:
/// GL's state groups in one struct, read as a whole by one key per pipeline
/// ([`SpecKey`](crate::gpu::layout::SpecKey)). The groups: lighting (`lighting` to
/// `rescale_normal`, and `mode`), texturing (`texture`), the current values (`current_*`), and
/// the fragment stages after texturing (`fragment`: color sum, fog, alpha test) and the user
/// clip planes (`clip`). Earlier versions called it
/// `LightingState`, which stays as a deprecated alias for a release.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct FixedFunctionState {
    /// GL_LIGHTING; off by default, as in GL: the vertex color passes through.
    pub lighting: bool,
    /// `GL_LIGHT0` onwards, [`MAX_LIGHTS`] of them, each starting at [`Light::gl_default`].
    pub lights: [Light; MAX_LIGHTS],
    /// The front material, also used for back faces unless two-sided lighting is on.
    pub front: Material,
    /// The back material: used only when [`LightModel::two_side`] is on.
    pub back: Material,
    /// glLightModel state.
    pub model: LightModel,
    /// glColorMaterial state.
    pub color_material: ColorMaterial,
    /// The texture units (`GL_TEXTURE0` onwards): each one's `GL_TEXTURE_2D`, glTexEnv,
    /// glTexGen and texture matrix, applied in order to the primary color before the color sum
    /// (§3.8.16).
    pub texture_units: [TextureUnit; MAX_TEXTURE_UNITS],
    /// `GL_NORMALIZE`; off by default, so a scaled modelview lights with unnormalized normals.
    pub normalize: bool,
    /// `GL_RESCALE_NORMAL`; off by default.
    pub rescale_normal: bool,
    /// Where the equation is evaluated; [`LightingMode::Vertex`] by default (GL's SMOOTH).
    pub mode: LightingMode,
    /// GL's current color (`GL_CURRENT_COLOR`, set by `glColor`), (1, 1, 1, 1) initially: the
    /// color of every vertex of a draw without a color array. With a color array each vertex
    /// has its own color and this one is not read.
    pub current_color: Vec4,
    /// GL's current normal (`GL_CURRENT_NORMAL`, set by `glNormal`), (0, 0, 1) initially: the
    /// normal of every vertex of a draw whose layout has no normal array.
    pub current_normal: Vec3,
    /// GL's current texture coordinates of each unit (`GL_CURRENT_TEXTURE_COORDS`, set by
    /// `glTexCoord` for unit 0 and `glMultiTexCoord`), (0, 0, 0, 1) initially: those of every
    /// vertex of a draw applying the unit whose layout has no texture coordinate array for it.
    pub current_texcoords: [Vec4; MAX_TEXTURE_UNITS],
    /// GL's current secondary color (`GL_CURRENT_SECONDARY_COLOR`, set by
    /// `glSecondaryColor`), (0, 0, 0, 1) initially: that of every vertex of a draw whose layout
    /// has no secondary color array; summed only with lighting off and `GL_COLOR_SUM` on.
    pub current_secondary_color: Vec4,
    /// GL's current fog coordinate (`GL_CURRENT_FOG_COORD`, set by `glFogCoord`), 0
    /// initially: that of every vertex of a draw whose layout has no fog coordinate array.
    pub current_fog_coord: f32,
    /// The fragment stages after texturing: the color sum, fog and the alpha test.
    pub fragment: FragmentStages,
    /// The user clip planes (a vertex stage, §2.12).
    pub clip: ClipPlanes,
    /// The point parameters and point sprites (§3.3), read by draws of points.
    pub points: PointParameters,
}

/// The old name of [`FixedFunctionState`], from when it held lighting alone.
#[deprecated(
    since = "0.2.0",
    note = "renamed FixedFunctionState: it holds every fixed-function stage, not lighting alone"
)]
pub type LightingState = FixedFunctionState;

impl Default for FixedFunctionState {
    fn default() -> Self {
        FixedFunctionState {
            lighting: false,
            lights: std::array::from_fn(Light::gl_default),
            front: Material::default(),
            back: Material::default(),
            model: LightModel::default(),
            color_material: ColorMaterial::default(),
            texture_units: [TextureUnit::default(); MAX_TEXTURE_UNITS],
            normalize: false,
            rescale_normal: false,
            mode: LightingMode::Vertex,
            current_color: Vec4::ONE,
            current_normal: Vec3::Z,
            current_texcoords: [Vec4::W; MAX_TEXTURE_UNITS],
            current_secondary_color: Vec4::W,
            current_fog_coord: 0.0,
            fragment: FragmentStages::default(),
            clip: ClipPlanes::default(),
            points: PointParameters::default(),
        }
    }
}

impl FixedFunctionState {
    /// Checks every value against GL's ranges; for state built field by field rather than
    /// through [`GlState`]'s setters.
    pub fn validate(&self) -> Result<(), StateError> {
        DrawValues::of(self).validate()?;
        self.validate_shared()
    }

    /// The values of the state every draw under it shares: the light model's ambient, the
    /// texture unit, every light's values and the cones of the enabled ones.
    fn validate_shared(&self) -> Result<(), StateError> {
        finite_vec("GL_LIGHT_MODEL_AMBIENT", self.model.ambient.to_array().as_slice())?;
        for unit in &self.texture_units {
            unit.validate()?;
        }
        for plane in &self.clip.planes {
            finite_vec("GL_CLIP_PLANEi", plane.to_array().as_slice())?;
        }
        let fog = &self.fragment.fog;
        finite_vec("GL_FOG_START", &[fog.start, fog.end])?;
        finite_vec("GL_FOG_COLOR", fog.color.to_array().as_slice())?;
        in_range("GL_FOG_DENSITY", fog.density, 0.0, f32::MAX, "a value >= 0")?;
        let reference = self.fragment.alpha_test.reference;
        if !(0.0..=1.0).contains(&reference) {
            return Err(StateError::OutOfRange {
                parameter: "GL_ALPHA_TEST_REF",
                value: reference,
                valid: "a value in [0, 1] (glAlphaFunc clamps it)",
            });
        }
        validate_lights(&self.lights)
    }

    /// The enabled lights, in index order.
    pub fn enabled_lights(&self) -> impl Iterator<Item = &Light> {
        self.lights.iter().filter(|l| l.enabled)
    }

    /// What makes the state (all but the draw's own values) drawable, GL's rules and ffvk's:
    /// the light model's ambient finite, the texture unit's values, every light's values and
    /// the cones of the enabled ones, and, lighting, no enabled positional light with all
    /// three attenuations 0 (att_i would be 1/0). The one definition: the renderer and the
    /// embedding API check it whenever a draw's state differs from the last draw's, the
    /// scene builder to name a scene's field.
    pub fn check_drawable(&self) -> Result<(), StateError> {
        self.validate_shared()?;
        if self.lighting {
            for (index, l) in self.lights.iter().enumerate() {
                let gl_falloff = l.attenuation == Attenuation::GlK012;
                let sum = l.constant_attenuation + l.linear_attenuation + l.quadratic_attenuation;
                if l.enabled && l.position.w != 0.0 && gl_falloff && sum == 0.0 {
                    return Err(StateError::ZeroAttenuation { light: index });
                }
            }
        }
        Ok(())
    }

    /// What a draw's own values must be under this state: its materials and current values
    /// in range and finite ([`DrawValues::validate`]), and, lighting, its `modelview`
    /// invertible (normals need (M⁻¹)ᵀ). The one per-draw check.
    pub fn check_draw(&self, values: &DrawValues, modelview: glam::Mat4) -> Result<(), StateError> {
        values.validate()?;
        if self.lighting {
            let det = glam::Mat3::from_mat4(modelview).determinant();
            if det == 0.0 || !det.is_finite() {
                return Err(StateError::SingularModelview { determinant: det });
            }
        }
        Ok(())
    }
}

/// cos(c_rli), exact at 90° (where the f64 cosine is 6e-17, not 0): with the spec's
/// `P_pliV ⊙ ŝ_dli ≥ cos(c_rli)` a 90° cone then holds every direction, and points behind the
/// light get (0)^s_rli, which is 1 for s_rli = 0, as the formula says. The one definition:
/// the CPU reference evaluates it, the GPU packer stores it.
pub fn cos_cutoff(cutoff_degrees: f32) -> f64 {
    if cutoff_degrees == 90.0 {
        0.0
    } else {
        (cutoff_degrees as f64).to_radians().cos()
    }
}

pub(crate) fn finite_vec(parameter: &'static str, values: &[f32]) -> Result<(), StateError> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(&value) => Err(StateError::NotFinite {
            parameter,
            value,
            valid: "finite components",
        }),
        None => Ok(()),
    }
}

pub(super) fn in_range(
    parameter: &'static str,
    value: f32,
    lo: f32,
    hi: f32,
    valid: &'static str,
) -> Result<(), StateError> {
    if !value.is_finite() {
        return Err(StateError::NotFinite {
            parameter,
            value,
            valid,
        });
    }
    if value < lo || value > hi {
        return Err(StateError::OutOfRange {
            parameter,
            value,
            valid,
        });
    }
    Ok(())
}

pub(super) fn check_light_scalar(p: &LightParam) -> Result<(), StateError> {
    match *p {
        LightParam::SpotExponent(v) => in_range("GL_SPOT_EXPONENT", v, 0.0, 128.0, "a value in [0, 128]"),
        LightParam::SpotCutoff(v) => {
            const VALID: &str = "a value in [0, 90] or exactly 180";
            if v == 180.0 {
                Ok(())
            } else {
                in_range("GL_SPOT_CUTOFF", v, 0.0, 90.0, VALID)
            }
        }
        LightParam::ConstantAttenuation(v) => {
            in_range("GL_CONSTANT_ATTENUATION", v, 0.0, f32::MAX, "a value >= 0")
        }
        LightParam::LinearAttenuation(v) => {
            in_range("GL_LINEAR_ATTENUATION", v, 0.0, f32::MAX, "a value >= 0")
        }
        LightParam::QuadraticAttenuation(v) => {
            in_range("GL_QUADRATIC_ATTENUATION", v, 0.0, f32::MAX, "a value >= 0")
        }
        LightParam::SpotEdge(edge) => match edge.inner_degrees() {
            Some(inner) => in_range("spot inner angle", inner, 0.0, 90.0, "a value in [0, 90] degrees"),
            None => Ok(()),
        },
        LightParam::Attenuation(Attenuation::GltfInverseSquare { range: Some(r) }) => {
            in_range("range", r, f32::MIN_POSITIVE, f32::MAX, "a value > 0")
        }
        _ => Ok(()),
    }
}
