//! glTF's samplers and KHR_texture_transform as GL's texture parameters and texture matrix,
//! and a texture ready to sample with them ([`SampledTexture`]).

use crate::gl::texture::{MagFilter, MinFilter, Sampling, TextureImage, Wrap};
use glam::Mat4;
use std::sync::Arc;

/// A texture ready to sample: its image (a base color texture's as stored, GL_RGBA8, no sRGB
/// decode, as a legacy GL program loads it; an occlusion texture's as a GL_LUMINANCE copy, see
/// [`OcclusionTexture`](super::OcclusionTexture); mipmaps generated, as glGenerateMipmap), the
/// sampler mapped from glTF's, and KHR_texture_transform as the GL_TEXTURE matrix.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct SampledTexture {
    /// The decoded image with its mipmaps; shared by every material that uses the image (an
    /// occlusion texture's copy by those of the same strength).
    pub image: Arc<TextureImage>,
    /// glTF's sampler as glTexParameter values; without one, linear and trilinear with repeat.
    pub sampling: Sampling,
    /// KHR_texture_transform's offset, rotation and scale as a matrix of (s, t); identity
    /// without it.
    pub matrix: Mat4,
    /// The glTF image's index, for messages.
    pub image_index: usize,
}

/// glTF's sampler as GL's texture parameters (glTF uses GL's enums). Without a filter glTF
/// leaves the choice to the renderer: ffvk takes linear magnification and trilinear
/// minification (the mipmaps are generated).
pub fn sampling(sampler: &gltf::texture::Sampler) -> Sampling {
    use gltf::texture::{MagFilter as GMag, MinFilter as GMin, WrappingMode};
    let wrap = |w: WrappingMode| match w {
        WrappingMode::ClampToEdge => Wrap::ClampToEdge,
        WrappingMode::MirroredRepeat => Wrap::MirroredRepeat,
        WrappingMode::Repeat => Wrap::Repeat,
    };
    Sampling {
        mag_filter: match sampler.mag_filter() {
            Some(GMag::Nearest) => MagFilter::Nearest,
            Some(GMag::Linear) | None => MagFilter::Linear,
        },
        min_filter: match sampler.min_filter() {
            Some(GMin::Nearest) => MinFilter::Nearest,
            Some(GMin::Linear) => MinFilter::Linear,
            Some(GMin::NearestMipmapNearest) => MinFilter::NearestMipmapNearest,
            Some(GMin::LinearMipmapNearest) => MinFilter::LinearMipmapNearest,
            Some(GMin::NearestMipmapLinear) => MinFilter::NearestMipmapLinear,
            Some(GMin::LinearMipmapLinear) | None => MinFilter::LinearMipmapLinear,
        },
        wrap_s: wrap(sampler.wrap_s()),
        wrap_t: wrap(sampler.wrap_t()),
    }
}

/// KHR_texture_transform's matrix: translation × rotation × scale of (u, v), the rotation
/// turning UVs counter-clockwise in the image (whose v runs down), as the extension's example
/// says (offset [0, 1], rotation π/2 and scale ½ pick the lower left quadrant).
pub fn transform_matrix(offset: [f32; 2], rotation: f32, scale: [f32; 2]) -> Mat4 {
    let (sin, cos) = rotation.sin_cos();
    let rotate = Mat4::from_cols(
        glam::Vec4::new(cos, -sin, 0.0, 0.0),
        glam::Vec4::new(sin, cos, 0.0, 0.0),
        glam::Vec4::Z,
        glam::Vec4::W,
    );
    Mat4::from_translation(glam::Vec3::new(offset[0], offset[1], 0.0))
        * rotate
        * Mat4::from_scale(glam::Vec3::new(scale[0], scale[1], 1.0))
}
