//! [`Cap`]: the capabilities glEnable, glDisable and glIsEnabled name.

#[cfg(doc)]
use super::{
    AlphaTest, FixedFunctionState, Fog, PointParameters, RasterGl, StateError, MAX_CLIP_PLANES, MAX_LIGHTS,
};

/// Capabilities toggled by glEnable/glDisable: those of lighting and the fragment stages
/// ([`FixedFunctionState`]) and those of the raster state ([`RasterGl`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Cap {
    /// `GL_LIGHTING`: without it the clamped vertex color is drawn unlit.
    Lighting,
    /// `GL_LIGHTi`, i in 0..[`MAX_LIGHTS`]; a larger i is a [`StateError::LightIndex`].
    Light(usize),
    /// `GL_COLOR_MATERIAL`.
    ColorMaterial,
    /// `GL_NORMALIZE`: eye-space normals are made unit length.
    Normalize,
    /// `GL_RESCALE_NORMAL`: eye-space normals are scaled to undo a uniform scale in the
    /// modelview (the factor comes from the third row of its inverse).
    RescaleNormal,
    /// `GL_TEXTURE_2D`: the active unit textures with its bound 2D texture, when it is
    /// complete.
    Texture2D,
    /// `GL_TEXTURE_CUBE_MAP`: the active unit textures with its bound cube map (before its 2D
    /// texture), when it is complete.
    TextureCubeMap,
    /// `GL_COLOR_SUM`: with lighting off, the secondary color is added after texturing.
    ColorSum,
    /// `GL_ALPHA_TEST`: fragments are kept as [`AlphaTest`] says.
    AlphaTest,
    /// `GL_FOG`: fragments are fogged as [`Fog`] says.
    Fog,
    /// `GL_CLIP_PLANEi`, i in 0..[`MAX_CLIP_PLANES`]; a larger i is a
    /// [`StateError::OutOfRange`].
    ClipPlane(usize),
    /// `GL_POINT_SPRITE`: points are sprites ([`PointParameters::sprite`]).
    PointSprite,
    /// `GL_TEXTURE_GEN_S` (0), `_T` (1), `_R` (2) or `_Q` (3): the coordinate is generated
    /// ([`TexCoordGen::enabled`](crate::gl::texture::TexCoordGen::enabled)); a larger index is
    /// a [`StateError::OutOfRange`].
    TextureGen(usize),
    /// `GL_POLYGON_OFFSET_FILL`: filled polygons are offset ([`RasterGl::polygon_offset_fill`]).
    PolygonOffsetFill,
    /// `GL_POLYGON_OFFSET_LINE`: polygons drawn as outlines are offset.
    PolygonOffsetLine,
    /// `GL_POLYGON_OFFSET_POINT`: polygons drawn as vertices are offset.
    PolygonOffsetPoint,
    /// `GL_LINE_STIPPLE`: lines are stippled ([`RasterGl::line_stipple`]).
    LineStipple,
    /// `GL_POLYGON_STIPPLE`: filled polygons are stippled ([`RasterGl::polygon_stipple`]).
    PolygonStipple,
    /// `GL_STENCIL_TEST`.
    StencilTest,
    /// `GL_COLOR_LOGIC_OP`: the logic op replaces blending.
    ColorLogicOp,
    /// `GL_BLEND`.
    Blend,
    /// `GL_DEPTH_TEST`.
    DepthTest,
    /// `GL_CULL_FACE`.
    CullFace,
}
