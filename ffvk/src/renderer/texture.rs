//! Textures on the renderer's device: a [`TextureImage`]'s levels in a sampled image, the
//! sampler its [`Sampling`] asks for, and the descriptor set draws bind.

use ash::vk;

use crate::draw::texture::TextureBinding;
use crate::gl::texture::{Sampling, TextureImage};
use crate::vk::objects::Sampler;
use crate::vk::Image;

/// A texture uploaded to a renderer's device, with its sampling parameters (a GL texture
/// object). Drawing it with another renderer is an error.
pub struct Texture {
    // Field order is drop order: the set that names the view and sampler goes first.
    pub(super) binding: TextureBinding,
    _sampler: Sampler,
    pub(super) image: Image,
    /// GL's completeness (section 3.8.10): false when the min filter reads mipmaps the image
    /// lacks, and then draws are not textured.
    complete: bool,
    width: u32,
    height: u32,
}

impl Texture {
    pub(super) fn new(
        image: Image,
        sampler: Sampler,
        binding: TextureBinding,
        source: &TextureImage,
        sampling: &Sampling,
    ) -> Self {
        Texture {
            binding,
            _sampler: sampler,
            complete: !sampling.min_filter.uses_mipmaps() || source.has_mipmaps(),
            width: source.width(),
            height: source.height(),
            image,
        }
    }

    /// Whether the texture is complete for its min filter (else drawing with it textures
    /// nothing, as in GL).
    pub fn is_complete(&self) -> bool {
        self.complete
    }

    /// Level 0's size in texels.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// How many levels were uploaded.
    pub fn levels(&self) -> u32 {
        self.image.levels()
    }
}

/// The image format of `image`: `R8G8B8A8_UNORM`, or `R8G8B8A8_SRGB` for sRGB textures.
pub(super) fn format(image: &TextureImage) -> vk::Format {
    if image.srgb {
        vk::Format::R8G8B8A8_SRGB
    } else {
        vk::Format::R8G8B8A8_UNORM
    }
}
