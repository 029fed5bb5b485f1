//! What one lit draw is: GL's state for it ([`LitDraw`]) and the values a draw may carry of
//! its own ([`DrawValues`]), as [`Lighting`](super::lighting::Lighting) records them.

use ash::vk;
use glam::Mat4;

use super::pipeline::RasterState;
use super::record::Geometry;
use super::texture::TextureBinding;
pub use crate::gl::state::DrawValues;
use crate::gl::state::FixedFunctionState;
use crate::gl::texture::MAX_TEXTURE_UNITS;

#[cfg(doc)]
use super::pipeline::VertexInput;

/// One lit draw: GL's state for it, its matrices, its raster state and the caller's buffers.
#[derive(Debug, Clone, Copy)]
#[non_exhaustive]
pub struct LitDraw<'a> {
    /// The lighting state the draw captures (from [`GlState`](crate::gl::state::GlState)).
    pub state: &'a FixedFunctionState,
    /// Object to eye space (GL conventions: column vectors, viewer looking down −z).
    pub modelview: Mat4,
    /// GL's projection (clip z in [−w, w]); ffvk converts it to Vulkan's clip space.
    pub projection: Mat4,
    /// Culling, winding, depth and blending.
    pub raster: RasterState,
    /// One (buffer, byte offset) per entry of its layout's [`VertexInput::bindings`], in that
    /// order.
    pub vertex_buffers: &'a [(vk::Buffer, u64)],
    /// Which vertices to draw.
    pub geometry: Geometry,
    /// The texture bound to each unit's `GL_TEXTURE_2D`
    /// ([`Lighting::bind_texture`](crate::Lighting::bind_texture)), `GL_TEXTURE0` first; a
    /// unit's is sampled when its [`TextureUnit::enabled`](crate::gl::texture::TextureUnit::enabled)
    /// is on too. `None` is GL's texture object 0, which textures nothing. Whether a texture is
    /// complete for its sampler (mipmaps where the min filter reads them) is the caller's to
    /// ensure, as GL's completeness rule is about the caller's image: bind `None` for an
    /// incomplete one.
    pub textures: [Option<&'a TextureBinding>; MAX_TEXTURE_UNITS],
    /// The cube map bound to each unit's `GL_TEXTURE_CUBE_MAP`
    /// ([`Lighting::bind_cube_map`](crate::Lighting::bind_cube_map)): sampled, before the
    /// unit's 2D texture, when its
    /// [`TextureUnit::cube_map`](crate::gl::texture::TextureUnit::cube_map) is on. `None`: GL's
    /// cube map object 0, which textures nothing (a unit with `GL_TEXTURE_CUBE_MAP` on and no
    /// cube map passes the color through, whatever its 2D texture).
    pub cube_maps: [Option<&'a TextureBinding>; MAX_TEXTURE_UNITS],
    /// The draw's own materials and current values, in place of `state`'s; `None` takes
    /// `state`'s.
    pub values: Option<DrawValues>,
    /// The vertex layout its buffers follow ([`Lighting::vertex_layout`](crate::Lighting::vertex_layout));
    /// `None`: the one [`LightingOptions::vertex_input`](crate::LightingOptions) gave.
    pub layout: Option<VertexLayout>,
}

/// A vertex layout a [`Lighting`](crate::Lighting) draws with, by number
/// ([`Lighting::vertex_layout`](crate::Lighting::vertex_layout)): a cheap handle a draw names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct VertexLayout {
    /// The layout's number in its `Lighting` (0: the options' layout).
    pub(crate) index: u32,
    /// Which `Lighting` made it.
    pub(crate) owner: u64,
}

impl VertexLayout {
    /// The layout's number in the `Lighting` that made it (0 is the one its options gave).
    pub fn index(self) -> u32 {
        self.index
    }
}

impl<'a> LitDraw<'a> {
    /// A draw of `geometry` from `vertex_buffers` (one `(buffer, byte offset)` per entry of
    /// [`VertexInput::bindings`]) under `state`, with these matrices, GL's initial
    /// [`RasterState`] (no depth test, no culling, no blending) and no texture. The `with_*`
    /// methods set the rest.
    pub fn new(
        state: &'a FixedFunctionState,
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
            textures: [None; MAX_TEXTURE_UNITS],
            cube_maps: [None; MAX_TEXTURE_UNITS],
            values: None,
            layout: None,
        }
    }

    /// This draw with `raster` (culling, winding, depth and blending).
    #[must_use]
    pub fn with_raster(mut self, raster: RasterState) -> Self {
        self.raster = raster;
        self
    }

    /// This draw with `texture` bound to unit 0's `GL_TEXTURE_2D` (`None`: texture object 0).
    #[must_use]
    pub fn with_texture(mut self, texture: Option<&'a TextureBinding>) -> Self {
        self.textures[0] = texture;
        self
    }

    /// This draw with each unit's cube map, `GL_TEXTURE0` first.
    #[must_use]
    pub fn with_cube_maps(mut self, cube_maps: [Option<&'a TextureBinding>; MAX_TEXTURE_UNITS]) -> Self {
        self.cube_maps = cube_maps;
        self
    }

    /// This draw with each unit's texture, `GL_TEXTURE0` first.
    #[must_use]
    pub fn with_textures(mut self, textures: [Option<&'a TextureBinding>; MAX_TEXTURE_UNITS]) -> Self {
        self.textures = textures;
        self
    }

    /// This draw with its own materials and current values (`None`: its state's).
    #[must_use]
    pub fn with_values(mut self, values: Option<DrawValues>) -> Self {
        self.values = values;
        self
    }

    /// This draw with its buffers following vertex layout `layout` (`None`: the options').
    #[must_use]
    pub fn with_layout(mut self, layout: Option<VertexLayout>) -> Self {
        self.layout = layout;
        self
    }
}
