//! A draw's own values ([`DrawValues`]): what GL programs change between draws without
//! touching lights or switches, and the per-draw check of them.

use glam::{Vec3, Vec4};

use super::{finite_vec, FixedFunctionState, Material, StateError};
use crate::gl::texture::MAX_TEXTURE_UNITS;

/// A draw's own values, the GL state programs change between draws without touching lights or
/// switches: the two materials (`glMaterial`, or `COLOR_MATERIAL`'s tracking) and GL's
/// current values (`glColor`, `glNormal`, `glTexCoord`). A [`LitDraw`](crate::LitDraw) with its
/// own values ([`LitDraw::with_values`](crate::LitDraw::with_values)) takes them instead of
/// its state's, so that draws which differ only in these can share one [`FixedFunctionState`]: an
/// emulation layer keeps a state per change of lights or switches and these per draw (about
/// 200 bytes instead of a 2.5 KB state).
///
/// ```
/// use ffvk::gl::state::{Face, GlState, MaterialParam};
/// use ffvk::glam::{Vec3, Vec4};
/// use ffvk::DrawValues;
///
/// let mut gl = GlState::new();
/// gl.material(Face::Front, MaterialParam::Diffuse(Vec4::new(1.0, 0.0, 0.0, 1.0))).unwrap();
/// gl.normal(Vec3::new(0.0, 1.0, 0.0)).unwrap();
/// let red = DrawValues::of(&gl.lighting);
/// assert_eq!(red.front.diffuse, Vec4::new(1.0, 0.0, 0.0, 1.0));
/// assert_eq!(red.current_color, Vec4::ONE);
/// assert_eq!(red.current_normal, Vec3::Y);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct DrawValues {
    /// The front material (also the back's, unless two-sided lighting is on).
    pub front: Material,
    /// The back material.
    pub back: Material,
    /// GL's current color: every vertex's color when the layout has no color array.
    pub current_color: Vec4,
    /// GL's current normal: every vertex's normal when the layout has no normal array.
    pub current_normal: Vec3,
    /// GL's current texture coordinates (s, t, r, q) of each unit: every vertex's when a draw
    /// applying the unit has no texture coordinate array for it.
    pub current_texcoords: [Vec4; MAX_TEXTURE_UNITS],
    /// GL's current secondary color: every vertex's when the layout has no secondary color
    /// array (summed with lighting off under `GL_COLOR_SUM`).
    pub current_secondary_color: Vec4,
    /// GL's current fog coordinate: every vertex's when the layout has no fog coordinate
    /// array (read with `GL_FOG_COORD_SRC` `GL_FOG_COORD`).
    pub current_fog_coord: f32,
}

impl DrawValues {
    /// The values `state` holds now: after a program's `glMaterial`, `glColor`, `glNormal`,
    /// `glTexCoord` and `glColorMaterial` calls on a [`GlState`](super::GlState), its
    /// materials already carry what color-material tracking wrote into them.
    pub fn of(state: &FixedFunctionState) -> Self {
        DrawValues {
            front: state.front,
            back: state.back,
            current_color: state.current_color,
            current_normal: state.current_normal,
            current_texcoords: state.current_texcoords,
            current_secondary_color: state.current_secondary_color,
            current_fog_coord: state.current_fog_coord,
        }
    }

    /// These materials and current color, with GL's initial current normal (0, 0, 1), texture
    /// coordinates (0, 0, 0, 1) and secondary color (0, 0, 0, 1).
    pub fn new(front: Material, back: Material, current_color: Vec4) -> Self {
        DrawValues {
            front,
            back,
            current_color,
            current_normal: Vec3::Z,
            current_texcoords: [Vec4::W; MAX_TEXTURE_UNITS],
            current_secondary_color: Vec4::W,
            current_fog_coord: 0.0,
        }
    }

    /// These values with `normal` as the current normal.
    #[must_use]
    pub fn with_normal(mut self, normal: Vec3) -> Self {
        self.current_normal = normal;
        self
    }

    /// These values with `texcoord` as unit 0's current texture coordinates.
    #[must_use]
    pub fn with_texcoord(mut self, texcoord: Vec4) -> Self {
        self.current_texcoords[0] = texcoord;
        self
    }

    /// Checks the values a draw carries: the materials in GL's ranges and every current value
    /// finite. The one per-draw check of them ([`FixedFunctionState::check_draw`]).
    pub fn validate(&self) -> Result<(), StateError> {
        self.front.validate()?;
        self.back.validate()?;
        finite_vec("GL_CURRENT_COLOR", self.current_color.to_array().as_slice())?;
        finite_vec("GL_CURRENT_NORMAL", self.current_normal.to_array().as_slice())?;
        for texcoord in &self.current_texcoords {
            finite_vec("GL_CURRENT_TEXTURE_COORDS", texcoord.to_array().as_slice())?;
        }
        finite_vec(
            "GL_CURRENT_SECONDARY_COLOR",
            self.current_secondary_color.to_array().as_slice(),
        )?;
        finite_vec("GL_CURRENT_FOG_COORD", &[self.current_fog_coord])
    }
}
