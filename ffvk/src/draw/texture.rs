//! The texture a lit draw samples: a descriptor set naming an image view and a sampler, and
//! the Vulkan sampler that samples as GL's texture parameters say.
//!
//! ffvk's own renderer uploads [`TextureImage`](crate::gl::texture::TextureImage)s into images
//! it owns; an embedding caller keeps its own images and samplers and asks
//! [`Lighting::bind_texture`](super::lighting::Lighting::bind_texture) for a
//! [`TextureBinding`] that names them.

use std::sync::Arc;

use ash::vk;

use crate::error::Result;
use crate::gl::texture::{MagFilter, MinFilter, Sampling, Wrap};
use crate::vk::objects::{DescriptorPool, DescriptorSetLayout};
use crate::vk::Device;

/// The layout of a texture's set: binding 0, one combined image sampler, fragment stage.
pub(crate) fn set_layout(device: &Arc<Device>) -> Result<DescriptorSetLayout> {
    let bindings = [vk::DescriptorSetLayoutBinding::default()
        .binding(0)
        .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
    DescriptorSetLayout::new(device, &bindings)
}

/// A descriptor set (and its pool) that names one image view and one sampler; owned by ffvk,
/// while the view and sampler stay the caller's.
pub struct TextureBinding {
    pool: DescriptorPool,
}

impl std::fmt::Debug for TextureBinding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TextureBinding")
            .field("set", &self.set())
            .finish()
    }
}

impl TextureBinding {
    /// A set of `layout` naming `view` (in `SHADER_READ_ONLY_OPTIMAL` when drawn) and `sampler`.
    ///
    /// # Safety
    ///
    /// `view` and `sampler` are live objects of `device` and outlive every command buffer
    /// that draws with this binding.
    pub(crate) unsafe fn new(
        device: &Arc<Device>,
        layout: &DescriptorSetLayout,
        view: vk::ImageView,
        sampler: vk::Sampler,
    ) -> Result<Self> {
        let sizes = [vk::DescriptorPoolSize {
            ty: vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
            descriptor_count: 1,
        }];
        let pool = DescriptorPool::with_one_set(device, &sizes, layout)?;
        let image = [vk::DescriptorImageInfo {
            sampler,
            image_view: view,
            image_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
        }];
        let write = vk::WriteDescriptorSet::default()
            .dst_set(pool.set())
            .dst_binding(0)
            .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
            .image_info(&image);
        // SAFETY: the set is new and unused; the view and sampler are live (the contract).
        unsafe { device.raw.update_descriptor_sets(&[write], &[]) };
        Ok(TextureBinding { pool })
    }

    /// The set, bound after the state block's.
    pub fn set(&self) -> vk::DescriptorSet {
        self.pool.set()
    }
}

/// A sampler that samples as GL's texture parameters `sampling` say, for an image of
/// `levels` mip levels: filters and wrap modes map one to one; GL's `GL_NEAREST` and
/// `GL_LINEAR` min filters (level 0 only) become a mipmap mode of `NEAREST` with `maxLod`
/// 0.25, the Vulkan specification's way to keep the min/mag switch while sampling level 0
/// only. Vulkan switches between the two filters at λ = 0 exactly; GL 2.1 moves the switch to
/// 0.5 when the mag filter is `LINEAR` and the min filter `*_MIPMAP_NEAREST`/`NEAREST_*`
/// (section 3.8.9), a difference of one band of fragments at that λ.
pub fn sampler_info(sampling: &Sampling, levels: u32) -> vk::SamplerCreateInfo<'static> {
    let filter = |f: MagFilter| match f {
        MagFilter::Nearest => vk::Filter::NEAREST,
        MagFilter::Linear => vk::Filter::LINEAR,
    };
    let address = |w: Wrap| match w {
        Wrap::Repeat => vk::SamplerAddressMode::REPEAT,
        Wrap::ClampToEdge => vk::SamplerAddressMode::CLAMP_TO_EDGE,
        Wrap::MirroredRepeat => vk::SamplerAddressMode::MIRRORED_REPEAT,
    };
    let min = sampling.min_filter;
    let (mipmap_mode, max_lod) = match min {
        MinFilter::Nearest | MinFilter::Linear => (vk::SamplerMipmapMode::NEAREST, 0.25),
        _ if min.between_levels_linear() => (vk::SamplerMipmapMode::LINEAR, (levels.max(1) - 1) as f32),
        _ => (vk::SamplerMipmapMode::NEAREST, (levels.max(1) - 1) as f32),
    };
    vk::SamplerCreateInfo::default()
        .mag_filter(filter(sampling.mag_filter))
        .min_filter(filter(min.within_level()))
        .mipmap_mode(mipmap_mode)
        .address_mode_u(address(sampling.wrap_s))
        .address_mode_v(address(sampling.wrap_t))
        .address_mode_w(vk::SamplerAddressMode::REPEAT)
        .min_lod(0.0)
        .max_lod(max_lod)
        .unnormalized_coordinates(false)
}
