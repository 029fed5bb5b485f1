//! Textures on the renderer's device: a [`TextureImage`]'s levels in a sampled image, the
//! sampler its [`Sampling`] asks for, and the descriptor set draws bind.

use ash::vk;

use crate::draw::texture::{TextureBinding, TextureTarget};
use crate::gl::texture::{CubeImage, TextureImage};
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
    /// A texture of `image` (level 0 `size` texels), complete for its min filter or not.
    pub(super) fn new(
        image: Image,
        sampler: Sampler,
        binding: TextureBinding,
        complete: bool,
        size: (u32, u32),
    ) -> Self {
        Texture {
            binding,
            _sampler: sampler,
            complete,
            width: size.0,
            height: size.1,
            image,
        }
    }

    /// `GL_TEXTURE_2D` or `GL_TEXTURE_CUBE_MAP`: which of a draw's slots it goes in
    /// ([`Draw::textures`](crate::Draw::textures) or [`Draw::cube_maps`](crate::Draw::cube_maps)).
    pub fn target(&self) -> TextureTarget {
        self.binding.target()
    }

    /// Whether the texture is complete for its min filter (else drawing with it textures
    /// nothing, as in GL).
    pub fn is_complete(&self) -> bool {
        self.complete
    }

    /// Level 0's size in texels (a cube map's: a face's).
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
    srgb_format(image.srgb)
}

/// The image format of a cube map's faces.
pub(super) fn cube_format(image: &CubeImage) -> vk::Format {
    srgb_format(image.srgb())
}

fn srgb_format(srgb: bool) -> vk::Format {
    if srgb {
        vk::Format::R8G8B8A8_SRGB
    } else {
        vk::Format::R8G8B8A8_UNORM
    }
}
