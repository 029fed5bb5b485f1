//! What one lit draw is: GL's state for it ([`LitDraw`]) and the values a draw may carry of
//! its own ([`DrawValues`]), as [`Lighting`](super::lighting::Lighting) records them.

use ash::vk;
use glam::{Mat4, Vec4};

use super::pipeline::RasterState;
use super::record::Geometry;
use super::texture::TextureBinding;
use crate::gl::state::{LightingState, Material};

#[cfg(doc)]
use super::pipeline::VertexInput;

/// A draw's own values, the GL state programs change between draws without touching lights or
/// switches: the two materials (`glMaterial`, or `COLOR_MATERIAL`'s tracking) and the current
/// color (`glColor`). A [`LitDraw`] with its own values ([`LitDraw::with_values`]) takes them
/// instead of its state's, so that draws which differ only in these can share one
/// [`LightingState`]: an emulation layer keeps a state per change of lights or switches and
/// these per draw (176 bytes instead of a 2.5 KB state).
///
/// ```
/// use ffvk::gl::state::{Face, GlState, MaterialParam};
/// use ffvk::glam::Vec4;
/// use ffvk::DrawValues;
///
/// let mut gl = GlState::new();
/// gl.material(Face::Front, MaterialParam::Diffuse(Vec4::new(1.0, 0.0, 0.0, 1.0))).unwrap();
/// let red = DrawValues::of(&gl.lighting);
/// assert_eq!(red.front.diffuse, Vec4::new(1.0, 0.0, 0.0, 1.0));
/// assert_eq!(red.current_color, Vec4::ONE);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct DrawValues {
    /// The front material (also the back's, unless two-sided lighting is on).
    pub front: Material,
    /// The back material.
    pub back: Material,
    /// GL's current color: every vertex's color when the mesh has no color array.
    pub current_color: Vec4,
}

impl DrawValues {
    /// The values `state` holds now: after a program's `glMaterial`, `glColor` and
    /// `glColorMaterial` calls on a [`GlState`](crate::gl::state::GlState), its materials
    /// already carry what color-material tracking wrote into them.
    pub fn of(state: &LightingState) -> Self {
        DrawValues {
            front: state.front,
            back: state.back,
            current_color: state.current_color,
        }
    }

    /// These materials and current color.
    pub fn new(front: Material, back: Material, current_color: Vec4) -> Self {
        DrawValues {
            front,
            back,
            current_color,
        }
    }
}

/// One lit draw: GL's state for it, its matrices, its raster state and the caller's buffers.
#[derive(Debug, Clone, Copy)]
#[non_exhaustive]
pub struct LitDraw<'a> {
    /// The lighting state the draw captures (from [`GlState`](crate::gl::state::GlState)).
    pub state: &'a LightingState,
    /// Object to eye space (GL conventions: column vectors, viewer looking down −z).
    pub modelview: Mat4,
    /// GL's projection (clip z in [−w, w]); ffvk converts it to Vulkan's clip space.
    pub projection: Mat4,
    /// Culling, winding, depth and blending.
    pub raster: RasterState,
    /// One (buffer, byte offset) per entry of [`VertexInput::bindings`], in that order.
    pub vertex_buffers: &'a [(vk::Buffer, u64)],
    /// Which vertices to draw.
    pub geometry: Geometry,
    /// The texture bound to `GL_TEXTURE_2D` ([`Lighting::bind_texture`](crate::Lighting::bind_texture)); it is sampled when
    /// [`TextureUnit::enabled`](crate::gl::texture::TextureUnit::enabled) is on too. `None` is
    /// GL's texture object 0, which textures nothing. Whether the texture is complete for its
    /// sampler (mipmaps where the min filter reads them) is the caller's to ensure, as GL's
    /// completeness rule is about the caller's image.
    pub texture: Option<&'a TextureBinding>,
    /// The draw's own materials and current color, in place of `state`'s; `None` takes
    /// `state`'s.
    pub values: Option<DrawValues>,
}

impl<'a> LitDraw<'a> {
    /// A draw of `geometry` from `vertex_buffers` (one `(buffer, byte offset)` per entry of
    /// [`VertexInput::bindings`]) under `state`, with these matrices, GL's initial
    /// [`RasterState`] (no depth test, no culling, no blending) and no texture. The `with_*`
    /// methods set the rest.
    pub fn new(
        state: &'a LightingState,
        modelview: Mat4,
        projection: Mat4,
        vertex_buffers: &'a [(vk::Buffer, u64)],
        geometry: Geometry,
    ) -> Self {
        LitDraw {
            state,
            modelview,
            projection,
            raster: RasterState::default(),
            vertex_buffers,
            geometry,
            texture: None,
            values: None,
        }
    }

    /// This draw with `raster` (culling, winding, depth and blending).
    #[must_use]
    pub fn with_raster(mut self, raster: RasterState) -> Self {
        self.raster = raster;
        self
    }

    /// This draw with `texture` bound to `GL_TEXTURE_2D` (`None`: texture object 0).
    #[must_use]
    pub fn with_texture(mut self, texture: Option<&'a TextureBinding>) -> Self {
        self.texture = texture;
        self
    }

    /// This draw with its own materials and current color (`None`: its state's).
    #[must_use]
    pub fn with_values(mut self, values: Option<DrawValues>) -> Self {
        self.values = values;
        self
    }
}
