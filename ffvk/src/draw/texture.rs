//! The textures a lit draw samples: the texture units' set (binding 0, one combined image
//! sampler per unit, [`MAX_TEXTURE_UNITS`] of them, holding the unit's 2D texture or its cube
//! map; the shaders read the binding as an array of `sampler2D` and, aliased, of
//! `samplerCube`, each unit through the one its target says), the caller's view and sampler
//! each unit names ([`TextureBinding`]), and the Vulkan sampler that samples as GL's texture
//! parameters say.
//!
//! ffvk's own renderer uploads [`TextureImage`](crate::gl::texture::TextureImage)s into images
//! it owns; an embedding caller keeps its own images and samplers and asks
//! [`Lighting::bind_texture`](super::lighting::Lighting::bind_texture) for a
//! [`TextureBinding`] that names them.
//!
//! A draw binds one set for all its units. Sets are made per frame slot, one for each
//! combination of textures the slot's draws sample (`UnitSets`), and freed together when
//! the slot is begun again: the cost is one `vkAllocateDescriptorSets` and one
//! `vkUpdateDescriptorSets` of the sampled units' descriptors per combination per frame, where
//! one set per texture would need a set index per unit (Vulkan guarantees four bound sets in
//! all). The element of a unit a draw does not sample holds another of its textures (every
//! element must be valid; lavapipe 22.3 has no `descriptorBindingPartiallyBound`), which the
//! shader never reads.

use std::collections::HashMap;
use std::sync::Arc;

use ash::vk;

use crate::error::Result;
use crate::gl::texture::{BaseFormat, MagFilter, MinFilter, Sampling, Wrap, MAX_TEXTURE_UNITS};
use crate::vk::objects::{DescriptorSetLayout, SetPool};
use crate::vk::Device;

/// The layout of the units' set: binding 0, one combined image sampler per unit (its 2D
/// texture or its cube map), fragment stage.
pub(crate) fn set_layout(device: &Arc<Device>) -> Result<DescriptorSetLayout> {
    let bindings = [vk::DescriptorSetLayoutBinding::default()
        .binding(0)
        .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
        .descriptor_count(MAX_TEXTURE_UNITS as u32)
        .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
    DescriptorSetLayout::new(device, &bindings)
}

/// What a texture binding is bound to: GL's `GL_TEXTURE_2D` or `GL_TEXTURE_CUBE_MAP` target.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum TextureTarget {
    /// `GL_TEXTURE_2D`: a 2D view.
    Texture2D,
    /// `GL_TEXTURE_CUBE_MAP`: a cube view of six faces.
    CubeMap,
}

impl TextureTarget {
    /// GL's name.
    pub fn gl_name(self) -> &'static str {
        match self {
            TextureTarget::Texture2D => "GL_TEXTURE_2D",
            TextureTarget::CubeMap => "GL_TEXTURE_CUBE_MAP",
        }
    }
}

/// A caller's image view and sampler, as a texture unit samples them: GL's texture object with
/// its parameters, for one target. It holds no reference to either; the caller keeps both
/// alive.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct TextureBinding {
    view: vk::ImageView,
    sampler: vk::Sampler,
    target: TextureTarget,
    base_format: BaseFormat,
}

impl TextureBinding {
    /// A binding of `view` (in `SHADER_READ_ONLY_OPTIMAL` when drawn) and `sampler` for
    /// `target`.
    pub(crate) fn new(view: vk::ImageView, sampler: vk::Sampler, target: TextureTarget) -> Self {
        TextureBinding {
            view,
            sampler,
            target,
            base_format: BaseFormat::Rgba,
        }
    }

    /// The target it binds to.
    pub fn target(&self) -> TextureTarget {
        self.target
    }

    /// This binding with the texture's base internal format (`GL_RGBA` by default): which of
    /// the view's components the texture environment reads (luminance and intensity from R,
    /// alpha from A; table 3.22).
    #[must_use]
    pub fn with_base_format(mut self, format: BaseFormat) -> Self {
        self.base_format = format;
        self
    }

    /// The base internal format.
    pub fn base_format(&self) -> BaseFormat {
        self.base_format
    }

    /// The image view.
    pub fn view(&self) -> vk::ImageView {
        self.view
    }

    /// The sampler.
    pub fn sampler(&self) -> vk::Sampler {
        self.sampler
    }
}

/// Sets a pool holds before another is added.
const SETS_PER_POOL: u32 = 64;

/// The texture each unit of a draw samples (its 2D texture or its cube map), `None` where it
/// samples none.
pub(crate) type UnitTextures = [Option<TextureBinding>; MAX_TEXTURE_UNITS];

/// The units' sets of one frame slot: the pools they come from and the set made for each
/// combination of textures.
#[derive(Default)]
struct SlotSets {
    pools: Vec<SetPool>,
    sets: HashMap<[TextureBinding; MAX_TEXTURE_UNITS], vk::DescriptorSet>,
}

/// The units' sets of every frame slot.
pub(crate) struct UnitSets {
    slots: Vec<SlotSets>,
    device: Arc<Device>,
}

impl UnitSets {
    /// No sets yet, for `slots` frame slots.
    pub(crate) fn new(device: &Arc<Device>, slots: u32) -> Self {
        UnitSets {
            slots: (0..slots).map(|_| SlotSets::default()).collect(),
            device: device.clone(),
        }
    }

    /// Frees slot `slot`'s sets: no submitted work uses them any more (the caller's contract
    /// of [`Lighting::begin_frame`](super::lighting::Lighting::begin_frame)).
    pub(crate) fn reset(&mut self, slot: u32) -> Result<()> {
        if let Some(s) = self.slots.get_mut(slot as usize) {
            s.sets.clear();
            // One pool is kept: a frame like the last one needs no new pool.
            s.pools.truncate(1);
            for pool in &mut s.pools {
                pool.reset()?;
            }
        }
        Ok(())
    }

    /// The set of slot `slot` naming `units` (each unit's texture where the draw samples one;
    /// a unit that samples none names another of the draw's textures), made now if the slot
    /// has none for them. `units` has at least one texture.
    ///
    /// # Safety
    ///
    /// Every view and sampler of `units` is live and outlives the command buffers that draw
    /// with the set (the contract of [`Lighting::bind_texture`](super::lighting::Lighting::bind_texture)).
    pub(crate) unsafe fn set_for(
        &mut self,
        layout: &DescriptorSetLayout,
        slot: u32,
        units: UnitTextures,
    ) -> Result<vk::DescriptorSet> {
        let filler = units
            .iter()
            .flatten()
            .next()
            .copied()
            .ok_or(crate::Error::Internal(
                "a textured draw's set was asked for with no texture",
            ))?;
        let key = units.map(|u| u.unwrap_or(filler));
        let s = self.slots.get_mut(slot as usize).ok_or(crate::Error::Internal(
            "a texture set for a frame slot that does not exist",
        ))?;
        if let Some(&set) = s.sets.get(&key) {
            return Ok(set);
        }
        let mut set = match s.pools.last_mut() {
            Some(pool) => pool.allocate()?,
            None => None,
        };
        if set.is_none() {
            let sizes = [vk::DescriptorPoolSize {
                ty: vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
                descriptor_count: MAX_TEXTURE_UNITS as u32,
            }];
            let mut pool = SetPool::new(&self.device, layout, &sizes, SETS_PER_POOL)?;
            set = pool.allocate()?;
            s.pools.push(pool);
        }
        let set = set.ok_or(crate::Error::Internal("a new descriptor pool had no room"))?;
        let images = key.map(|t| vk::DescriptorImageInfo {
            sampler: t.sampler,
            image_view: t.view,
            image_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
        });
        let write = vk::WriteDescriptorSet::default()
            .dst_set(set)
            .dst_binding(0)
            .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
            .image_info(&images);
        // SAFETY: the set is new and unused; the views and samplers are live (the contract).
        unsafe { self.device.raw.update_descriptor_sets(&[write], &[]) };
        s.sets.insert(key, set);
        Ok(set)
    }
}

/// [`sampler_info`] for a cube map: its faces filtered each on its own
/// (`VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT`) where `non_seamless` (the device has
/// `VK_EXT_non_seamless_cube_map` enabled), as GL 2.1 filters them; the wrap modes of s and t
/// apply within a face (r is the direction's third component and wraps nothing).
pub fn cube_sampler_info(
    sampling: &Sampling,
    levels: u32,
    non_seamless: bool,
) -> vk::SamplerCreateInfo<'static> {
    let info = sampler_info(sampling, levels);
    if non_seamless {
        info.flags(vk::SamplerCreateFlags::NON_SEAMLESS_CUBE_MAP_EXT)
    } else {
        info
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
