//! The errors of GL state and of names read from text: values GL would reject
//! ([`StateError`], also at `gl::state::StateError`) and names that exist in no list
//! ([`UnknownName`], also at `ffvk::UnknownName`). A leaf: the GL state, the texture unit and
//! the crate's error type all use it, and it uses none of them.

/// A value GL would reject. A [`GlState`](super::state::GlState) entry point that returns it changes nothing.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum StateError {
    /// `GL_POLYGON_STIPPLE` on while the framebuffer's height is unknown: GL counts the
    /// stipple's rows from the framebuffer's bottom, and Vulkan's fragments count from its top.
    #[error("GL_POLYGON_STIPPLE is enabled but the framebuffer's height is unknown: expected GlState::framebuffer_height (ffvkFramebufferHeight) first, since GL counts the stipple's rows from the framebuffer's bottom")]
    NoFramebufferHeight,
    /// GL's `INVALID_VALUE`: a finite value outside the parameter's range. Also used for a
    /// state that is in range but cannot be drawn (see [`DrawBlock::new`]).
    ///
    /// [`DrawBlock::new`]: crate::gpu::layout::DrawBlock::new
    #[error("{parameter} = {value} is out of range: expected {valid}")]
    OutOfRange {
        /// The GL name of the parameter, e.g. `"GL_SPOT_CUTOFF"`.
        parameter: &'static str,
        /// The rejected value.
        value: f32,
        /// The valid range, in words, e.g. `"a value in [0, 90] or exactly 180"`.
        valid: &'static str,
    },
    /// A NaN or infinite component. GL leaves their effect unspecified; ffvk refuses them so
    /// they cannot spread NaN through the lighting.
    #[error("{parameter} = {value} is not a finite number: expected {valid}")]
    NotFinite {
        /// The GL name of the parameter (or `"modelview matrix"`).
        parameter: &'static str,
        /// The first non-finite component found.
        value: f32,
        /// What would have been accepted, in words.
        valid: &'static str,
    },
    /// A soft spot edge whose inner cone is wider than its outer cone (`GL_SPOT_CUTOFF`):
    /// ffvk's extension, checked when the light is drawn, since GL's order of calls lets
    /// either angle be set first.
    #[error("light {light}: the spot edge's inner angle {inner}° is wider than its outer angle (GL_SPOT_CUTOFF) {outer}°: expected inner <= outer")]
    SpotCone {
        /// The light's index (`GL_LIGHTi`).
        light: usize,
        /// The inner cone's half-angle, degrees.
        inner: f32,
        /// The outer cone's half-angle (`GL_SPOT_CUTOFF`), degrees.
        outer: f32,
    },
    /// An enabled positional light with GL's attenuation and all three attenuations 0,
    /// drawn with lighting on: att_i = 1 / (k0 + k1 d + k2 d²) would be 1/0.
    #[error(
        "light {light}: GL_CONSTANT_ATTENUATION + GL_LINEAR_ATTENUATION + GL_QUADRATIC_ATTENUATION = 0: \
         expected a sum > 0 for an enabled positional light (else att_i = 1/0)"
    )]
    ZeroAttenuation {
        /// The light's index (`GL_LIGHTi`).
        light: usize,
    },
    /// A draw's modelview whose upper 3×3 has no inverse, drawn with lighting on: GL's normal
    /// matrix (M⁻¹)ᵀ would be undefined and the normals NaN.
    #[error(
        "determinant of the modelview's upper 3x3 = {determinant}: expected a finite non-zero value \
         (an invertible modelview, for the normal matrix)"
    )]
    SingularModelview {
        /// The determinant found.
        determinant: f32,
    },
    /// glClipPlane under a modelview with no inverse: p · M⁻¹ is undefined (GL leaves the plane
    /// undefined; ffvk refuses it).
    #[error(
        "determinant of the modelview = {determinant}: expected an invertible modelview \
         (glClipPlane and glTexGen's GL_EYE_PLANE store p · M⁻¹)"
    )]
    SingularClipModelview {
        /// The determinant of the whole 4×4 modelview.
        determinant: f64,
    },
    /// GL's `INVALID_ENUM` for a value of the right type that the parameter does not take
    /// here: `GL_SRC_ALPHA_SATURATE` as a destination blend factor (GL 2.1 table 4.2: "valid
    /// only for source RGB and alpha").
    #[error("{parameter} = {value} is not accepted: expected {valid}")]
    NotAccepted {
        /// The GL name of the parameter, e.g. `"dfactorRGB"`.
        parameter: &'static str,
        /// The GL name of the value refused.
        value: &'static str,
        /// What would have been accepted, in words.
        valid: &'static str,
    },
    /// A light index at or past [`MAX_LIGHTS`](super::state::MAX_LIGHTS) (GL's `INVALID_ENUM` for `GL_LIGHTi`).
    #[error("light index {index} is out of range: expected 0..{max} (GL_MAX_LIGHTS = {max})")]
    LightIndex {
        /// The index given.
        index: usize,
        /// [`MAX_LIGHTS`](super::state::MAX_LIGHTS); valid indices are below it.
        max: usize,
    },
}

/// A name that [`FromStr`](std::str::FromStr) does not know: `"phong"` for a
/// [`LightingMode`](crate::gl::state::LightingMode), say. Its message names what was being
/// read, the value and the names that exist.
///
/// ```
/// use ffvk::gl::state::LightingMode;
///
/// assert_eq!("flat".parse::<LightingMode>(), Ok(LightingMode::Flat));
/// let err = "phong".parse::<LightingMode>().unwrap_err();
/// assert_eq!(err.to_string(), r#"unknown lighting mode "phong": expected vertex, fragment or flat"#);
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown {what} {value:?}: expected {expected}")]
#[non_exhaustive]
pub struct UnknownName {
    /// What the name was for, e.g. `"lighting mode"`.
    pub what: &'static str,
    /// The text given.
    pub value: String,
    /// The names that exist, e.g. `"vertex, fragment or flat"`.
    pub expected: &'static str,
}

impl UnknownName {
    /// `value` is not one of the names of `what`, which are `expected`.
    pub fn new(what: &'static str, value: &str, expected: &'static str) -> Self {
        UnknownName {
            what,
            value: value.to_owned(),
            expected,
        }
    }
}
