//! What a [`Lighting`] knows of textures: the bindings of a caller's views
//! ([`Lighting::bind_texture`], [`Lighting::bind_cube_map`]), and which units a draw samples
//! and applies, as its pipeline keys them.

use ash::vk;

use super::super::texture::{TextureBinding, TextureTarget};
use super::variant::units_key;
use super::{Lighting, LitDraw};
use crate::error::{LightingError, Result};
use crate::gl::texture::MAX_TEXTURE_UNITS;

impl Lighting {
    /// A texture binding naming the caller's image `view` and `sampler`, for
    /// [`LitDraw::textures`]. The view is a 2D color view the fragment stage samples as floats
    /// (e.g. `R8G8B8A8_UNORM`, or `R8G8B8A8_SRGB` for GL's `GL_SRGB8_ALPHA8`), in
    /// `SHADER_READ_ONLY_OPTIMAL` layout whenever a draw that uses it executes;
    /// [`sampler_info`](crate::draw::texture::sampler_info) makes a sampler that samples as GL's
    /// texture parameters say. The binding holds no reference to either: the caller keeps
    /// both alive as long as the binding may be drawn with.
    ///
    /// # Safety
    ///
    /// `view` and `sampler` are live objects of this device and outlive every command buffer
    /// that draws with the returned binding.
    pub unsafe fn bind_texture(&self, view: vk::ImageView, sampler: vk::Sampler) -> Result<TextureBinding> {
        Ok(TextureBinding::new(view, sampler, TextureTarget::Texture2D))
    }

    /// A cube map binding naming the caller's image `view` (a `CUBE` view of an image with six
    /// array layers in GL's face order, `GL_TEXTURE_CUBE_MAP_POSITIVE_X` first, each face's
    /// row 0 at t = 0; in `SHADER_READ_ONLY_OPTIMAL` layout whenever a draw that uses it
    /// executes) and `sampler`, for [`LitDraw::cube_maps`]. GL 2.1 filters each face on its
    /// own: a sampler made with `VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT`
    /// ([`cube_sampler_info`](crate::draw::texture::cube_sampler_info)) does so where the device
    /// has `VK_EXT_non_seamless_cube_map`. The binding holds no reference to either.
    ///
    /// # Safety
    ///
    /// As [`Lighting::bind_texture`].
    pub unsafe fn bind_cube_map(&self, view: vk::ImageView, sampler: vk::Sampler) -> Result<TextureBinding> {
        Ok(TextureBinding::new(view, sampler, TextureTarget::CubeMap))
    }

    /// The texture units `draw` samples (bits 0-3), applies (bits 4-7) and samples as cube
    /// maps (bits 8-11), and each sampled unit's base format (3 bits from bit 12 + 3 i): 0
    /// when it applies none ([`units_key`]).
    pub(super) fn units(draw: &LitDraw) -> u32 {
        let mask = |bound: &[Option<&TextureBinding>; MAX_TEXTURE_UNITS]| {
            (0..MAX_TEXTURE_UNITS)
                .filter(|&i| bound[i].is_some())
                .fold(0, |mask, i| mask | 1 << i)
        };
        let key = units_key(
            &draw.state.texture_units,
            mask(&draw.textures),
            mask(&draw.cube_maps),
        );
        (0..MAX_TEXTURE_UNITS)
            .filter(|&i| key & 1 << i != 0)
            .filter_map(|i| {
                let bound = if key & 256 << i != 0 {
                    draw.cube_maps[i]
                } else {
                    draw.textures[i]
                };
                bound.map(|t| (i, t.base_format().code()))
            })
            .fold(key, |key, (i, code)| key | code << (12 + 3 * i))
    }

    /// Refuses a draw whose `textures` hold a cube map or whose `cube_maps` hold a 2D
    /// texture.
    pub(super) fn check_targets(draw: &LitDraw) -> Result<()> {
        let slots = [
            (&draw.textures, TextureTarget::Texture2D, "textures"),
            (&draw.cube_maps, TextureTarget::CubeMap, "cube_maps"),
        ];
        for (bound, expected, field) in slots {
            for (unit, t) in bound.iter().enumerate() {
                if let Some(t) = t.filter(|t| t.target() != expected) {
                    return Err(LightingError::TextureTarget {
                        field,
                        unit,
                        given: t.target().gl_name(),
                        expected: expected.gl_name(),
                    }
                    .into());
                }
            }
        }
        Ok(())
    }
}
