//! Owned Vulkan objects: each value is created whole (never null and filled in later), holds
//! an `Arc` of its device and destroys its handle in `Drop`. Whoever holds one must keep the
//! GPU off it before dropping it (the renderer waits for its fence or the device).

use std::sync::Arc;

use ash::vk;

use super::device::Device;
use crate::error::{vk_error, Result};

/// Declares a wrapper that owns one handle and frees it with `destroy`.
macro_rules! owned {
    ($(#[$doc:meta])* $name:ident($raw:ty) freed by $destroy:ident) => {
        $(#[$doc])*
        pub struct $name {
            device: Arc<Device>,
            raw: $raw,
        }

        impl $name {
            /// The Vulkan handle; valid while `self` lives.
            pub fn raw(&self) -> $raw {
                self.raw
            }

            /// The device this object belongs to.
            pub fn device(&self) -> &Arc<Device> {
                &self.device
            }
        }

        impl Drop for $name {
            fn drop(&mut self) {
                // SAFETY: the handle was created on this device and is destroyed once, here;
                // owners drop it only when no pending command uses it (module docs).
                unsafe { self.device.raw.$destroy(self.raw, None) }
            }
        }
    };
}

owned!(
    /// A shader module; needed only while pipelines are created from it.
    ShaderModule(vk::ShaderModule) freed by destroy_shader_module
);
owned!(
    /// A descriptor set layout.
    DescriptorSetLayout(vk::DescriptorSetLayout) freed by destroy_descriptor_set_layout
);
owned!(
    /// A pipeline layout.
    PipelineLayout(vk::PipelineLayout) freed by destroy_pipeline_layout
);
owned!(
    /// A pipeline cache.
    PipelineCache(vk::PipelineCache) freed by destroy_pipeline_cache
);
owned!(
    /// A graphics pipeline.
    Pipeline(vk::Pipeline) freed by destroy_pipeline
);
owned!(
    /// A fence, created unsignaled.
    Fence(vk::Fence) freed by destroy_fence
);
owned!(
    /// A query pool.
    QueryPool(vk::QueryPool) freed by destroy_query_pool
);
owned!(
    /// A buffer without its memory (see [`super::Buffer`] for one with).
    RawBuffer(vk::Buffer) freed by destroy_buffer
);
owned!(
    /// An image without its memory (see [`super::Image`] for one with).
    RawImage(vk::Image) freed by destroy_image
);
owned!(
    /// An image view.
    ImageView(vk::ImageView) freed by destroy_image_view
);
owned!(
    /// A sampler.
    Sampler(vk::Sampler) freed by destroy_sampler
);
owned!(
    /// A buffer view: a buffer's bytes as texels of one format.
    BufferView(vk::BufferView) freed by destroy_buffer_view
);

impl BufferView {
    /// The whole of `buffer` (its size rounded down to whole texels) as texels of `format`.
    /// `buffer` was made with a texel buffer usage and must outlive every command that
    /// reads through the view.
    pub fn new(device: &Arc<Device>, buffer: vk::Buffer, format: vk::Format) -> Result<Self> {
        let info = vk::BufferViewCreateInfo::default()
            .buffer(buffer)
            .format(format)
            .offset(0)
            .range(vk::WHOLE_SIZE);
        // SAFETY: a valid create info on a live device; the caller's buffer is this device's.
        let raw =
            unsafe { device.raw.create_buffer_view(&info, None) }.map_err(vk_error("vkCreateBufferView"))?;
        Ok(BufferView {
            device: device.clone(),
            raw,
        })
    }
}

impl Sampler {
    /// A sampler of `info`.
    pub fn new(device: &Arc<Device>, info: &vk::SamplerCreateInfo) -> Result<Self> {
        // SAFETY: a valid create info on a live device (anisotropy and compare off).
        let raw = unsafe { device.raw.create_sampler(info, None) }.map_err(vk_error("vkCreateSampler"))?;
        Ok(Sampler {
            device: device.clone(),
            raw,
        })
    }
}

impl ShaderModule {
    /// A module from SPIR-V words.
    pub fn new(device: &Arc<Device>, words: &[u32]) -> Result<Self> {
        let info = vk::ShaderModuleCreateInfo::default().code(words);
        // SAFETY: a valid create info on a live device; the words are glslang's SPIR-V.
        let raw = unsafe { device.raw.create_shader_module(&info, None) }
            .map_err(vk_error("vkCreateShaderModule"))?;
        Ok(ShaderModule {
            device: device.clone(),
            raw,
        })
    }
}

impl DescriptorSetLayout {
    /// A layout of `bindings`.
    pub fn new(device: &Arc<Device>, bindings: &[vk::DescriptorSetLayoutBinding]) -> Result<Self> {
        let info = vk::DescriptorSetLayoutCreateInfo::default().bindings(bindings);
        // SAFETY: a valid create info on a live device.
        let raw = unsafe { device.raw.create_descriptor_set_layout(&info, None) }
            .map_err(vk_error("vkCreateDescriptorSetLayout"))?;
        Ok(DescriptorSetLayout {
            device: device.clone(),
            raw,
        })
    }
}

impl PipelineLayout {
    /// A pipeline layout of `set_layouts` (set i is the i-th) and no push constants.
    pub fn new(device: &Arc<Device>, set_layouts: &[&DescriptorSetLayout]) -> Result<Self> {
        Self::with_push_constants(device, set_layouts, &[])
    }

    /// A pipeline layout of `set_layouts` and the push constant ranges `push_constants`.
    pub fn with_push_constants(
        device: &Arc<Device>,
        set_layouts: &[&DescriptorSetLayout],
        push_constants: &[vk::PushConstantRange],
    ) -> Result<Self> {
        let set_layouts: Vec<vk::DescriptorSetLayout> = set_layouts.iter().map(|l| l.raw).collect();
        let info = vk::PipelineLayoutCreateInfo::default()
            .set_layouts(&set_layouts)
            .push_constant_ranges(push_constants);
        // SAFETY: a valid create info on a live device; the set layouts are alive.
        let raw = unsafe { device.raw.create_pipeline_layout(&info, None) }
            .map_err(vk_error("vkCreatePipelineLayout"))?;
        Ok(PipelineLayout {
            device: device.clone(),
            raw,
        })
    }
}

impl PipelineCache {
    /// An empty pipeline cache.
    pub fn new(device: &Arc<Device>) -> Result<Self> {
        let info = vk::PipelineCacheCreateInfo::default();
        // SAFETY: a valid create info on a live device.
        let raw = unsafe { device.raw.create_pipeline_cache(&info, None) }
            .map_err(vk_error("vkCreatePipelineCache"))?;
        Ok(PipelineCache {
            device: device.clone(),
            raw,
        })
    }
}

impl Pipeline {
    /// One graphics pipeline from `info`.
    pub fn graphics(
        device: &Arc<Device>,
        cache: vk::PipelineCache,
        info: &vk::GraphicsPipelineCreateInfo,
    ) -> Result<Self> {
        // SAFETY: the caller's create info points at data alive for this call; the cache
        // (possibly null) belongs to this device; caches synchronize their own use.
        let created = unsafe {
            device
                .raw
                .create_graphics_pipelines(cache, std::slice::from_ref(info), None)
        };
        let pipelines = created.map_err(|(pipelines, e)| {
            for p in pipelines.into_iter().filter(|&p| p != vk::Pipeline::null()) {
                // SAFETY: a pipeline this failed call still created; nothing uses it.
                unsafe { device.raw.destroy_pipeline(p, None) };
            }
            vk_error("vkCreateGraphicsPipelines")(e)
        })?;
        Ok(Pipeline {
            device: device.clone(),
            raw: pipelines[0],
        })
    }
}

impl Fence {
    /// An unsignaled fence.
    pub fn new(device: &Arc<Device>) -> Result<Self> {
        // SAFETY: a valid create info on a live device.
        let raw = unsafe { device.raw.create_fence(&vk::FenceCreateInfo::default(), None) }
            .map_err(vk_error("vkCreateFence"))?;
        Ok(Fence {
            device: device.clone(),
            raw,
        })
    }
}

impl QueryPool {
    /// A pool of `info`'s queries.
    pub fn new(device: &Arc<Device>, info: &vk::QueryPoolCreateInfo) -> Result<Self> {
        // SAFETY: a valid create info on a live device; the caller enabled what it needs.
        let raw =
            unsafe { device.raw.create_query_pool(info, None) }.map_err(vk_error("vkCreateQueryPool"))?;
        Ok(QueryPool {
            device: device.clone(),
            raw,
        })
    }
}

impl RawBuffer {
    /// A buffer of `info`, not yet bound to memory.
    pub fn new(device: &Arc<Device>, info: &vk::BufferCreateInfo) -> Result<Self> {
        // SAFETY: a valid create info on a live device.
        let raw = unsafe { device.raw.create_buffer(info, None) }.map_err(vk_error("vkCreateBuffer"))?;
        Ok(RawBuffer {
            device: device.clone(),
            raw,
        })
    }
}

impl RawImage {
    /// An image of `info`, not yet bound to memory.
    pub fn new(device: &Arc<Device>, info: &vk::ImageCreateInfo) -> Result<Self> {
        // SAFETY: a valid create info on a live device.
        let raw = unsafe { device.raw.create_image(info, None) }.map_err(vk_error("vkCreateImage"))?;
        Ok(RawImage {
            device: device.clone(),
            raw,
        })
    }
}

impl ImageView {
    /// A view of `info`, whose image is bound to memory.
    pub fn new(device: &Arc<Device>, info: &vk::ImageViewCreateInfo) -> Result<Self> {
        // SAFETY: a valid create info on a live device; the image it names is bound.
        let raw =
            unsafe { device.raw.create_image_view(info, None) }.map_err(vk_error("vkCreateImageView"))?;
        Ok(ImageView {
            device: device.clone(),
            raw,
        })
    }
}

/// A descriptor pool and the one set allocated from it (freed with the pool).
pub struct DescriptorPool {
    device: Arc<Device>,
    raw: vk::DescriptorPool,
    set: vk::DescriptorSet,
}

impl DescriptorPool {
    /// A pool of `sizes` with one set of `layout` allocated from it.
    pub fn with_one_set(
        device: &Arc<Device>,
        sizes: &[vk::DescriptorPoolSize],
        layout: &DescriptorSetLayout,
    ) -> Result<Self> {
        let info = vk::DescriptorPoolCreateInfo::default()
            .max_sets(1)
            .pool_sizes(sizes);
        // SAFETY: a valid create info on a live device.
        let raw = unsafe { device.raw.create_descriptor_pool(&info, None) }
            .map_err(vk_error("vkCreateDescriptorPool"))?;
        let layouts = [layout.raw];
        let alloc = vk::DescriptorSetAllocateInfo::default()
            .descriptor_pool(raw)
            .set_layouts(&layouts);
        // SAFETY: the pool was just created with room for this set.
        match unsafe { device.raw.allocate_descriptor_sets(&alloc) } {
            Ok(sets) => Ok(DescriptorPool {
                device: device.clone(),
                raw,
                set: sets[0],
            }),
            Err(e) => {
                // SAFETY: the pool is unused; nothing was allocated from it.
                unsafe { device.raw.destroy_descriptor_pool(raw, None) };
                Err(vk_error("vkAllocateDescriptorSets")(e))
            }
        }
    }

    /// The set allocated from this pool.
    pub fn set(&self) -> vk::DescriptorSet {
        self.set
    }
}

impl Drop for DescriptorPool {
    fn drop(&mut self) {
        // SAFETY: created on this device, destroyed once; freeing the pool frees its set, which
        // no pending command uses (module docs).
        unsafe { self.device.raw.destroy_descriptor_pool(self.raw, None) }
    }
}

/// A descriptor pool with room for `max_sets` sets of one layout, allocated one at a time
/// ([`SetPool::allocate`]) and all freed together ([`SetPool::reset`]).
pub struct SetPool {
    device: Arc<Device>,
    raw: vk::DescriptorPool,
    layout: vk::DescriptorSetLayout,
    capacity: u32,
    allocated: u32,
}

impl SetPool {
    /// A pool for `max_sets` sets of `layout`, whose bindings take `sizes` per set.
    pub fn new(
        device: &Arc<Device>,
        layout: &DescriptorSetLayout,
        sizes_per_set: &[vk::DescriptorPoolSize],
        max_sets: u32,
    ) -> Result<Self> {
        let sizes: Vec<vk::DescriptorPoolSize> = sizes_per_set
            .iter()
            .map(|s| vk::DescriptorPoolSize {
                ty: s.ty,
                descriptor_count: s.descriptor_count * max_sets,
            })
            .collect();
        let info = vk::DescriptorPoolCreateInfo::default()
            .max_sets(max_sets)
            .pool_sizes(&sizes);
        // SAFETY: a valid create info on a live device.
        let raw = unsafe { device.raw.create_descriptor_pool(&info, None) }
            .map_err(vk_error("vkCreateDescriptorPool"))?;
        Ok(SetPool {
            device: device.clone(),
            raw,
            layout: layout.raw,
            capacity: max_sets,
            allocated: 0,
        })
    }

    /// A new set, or `None` when the pool is full.
    pub fn allocate(&mut self) -> Result<Option<vk::DescriptorSet>> {
        if self.allocated == self.capacity {
            return Ok(None);
        }
        let layouts = [self.layout];
        let alloc = vk::DescriptorSetAllocateInfo::default()
            .descriptor_pool(self.raw)
            .set_layouts(&layouts);
        // SAFETY: the pool has room for one more set of this layout (counted above).
        let sets = unsafe { self.device.raw.allocate_descriptor_sets(&alloc) }
            .map_err(vk_error("vkAllocateDescriptorSets"))?;
        self.allocated += 1;
        Ok(sets.first().copied())
    }

    /// Frees every set; the caller makes sure no pending command uses one.
    pub fn reset(&mut self) -> Result<()> {
        // SAFETY: the pool is this device's; the caller's contract above.
        unsafe {
            self.device
                .raw
                .reset_descriptor_pool(self.raw, vk::DescriptorPoolResetFlags::empty())
        }
        .map_err(vk_error("vkResetDescriptorPool"))?;
        self.allocated = 0;
        Ok(())
    }
}

impl Drop for SetPool {
    fn drop(&mut self) {
        // SAFETY: created on this device, destroyed once; its sets go with it, and no pending
        // command uses them (module docs).
        unsafe { self.device.raw.destroy_descriptor_pool(self.raw, None) }
    }
}

/// A command pool whose buffers may be reset one by one, and one primary buffer from it.
pub struct CommandPool {
    device: Arc<Device>,
    raw: vk::CommandPool,
    buffer: vk::CommandBuffer,
}

impl CommandPool {
    /// A pool for `queue_family` with one primary command buffer.
    pub fn with_one_buffer(device: &Arc<Device>, queue_family: u32) -> Result<Self> {
        let info = vk::CommandPoolCreateInfo::default()
            .queue_family_index(queue_family)
            .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
        // SAFETY: a valid create info on a live device.
        let raw = unsafe { device.raw.create_command_pool(&info, None) }
            .map_err(vk_error("vkCreateCommandPool"))?;
        let alloc = vk::CommandBufferAllocateInfo::default()
            .command_pool(raw)
            .level(vk::CommandBufferLevel::PRIMARY)
            .command_buffer_count(1);
        // SAFETY: the pool was just created on this device.
        match unsafe { device.raw.allocate_command_buffers(&alloc) } {
            Ok(buffers) => Ok(CommandPool {
                device: device.clone(),
                raw,
                buffer: buffers[0],
            }),
            Err(e) => {
                // SAFETY: the pool is unused; nothing was allocated from it.
                unsafe { device.raw.destroy_command_pool(raw, None) };
                Err(vk_error("vkAllocateCommandBuffers")(e))
            }
        }
    }

    /// The command buffer allocated from this pool.
    pub fn buffer(&self) -> vk::CommandBuffer {
        self.buffer
    }

    /// Resets the command buffer and begins recording it for one submission.
    ///
    /// # Safety
    ///
    /// The command buffer is not pending: the submission that last used it has finished.
    pub unsafe fn begin_one_time(&self) -> Result<vk::CommandBuffer> {
        let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
        // SAFETY: the caller's contract; the pool allows individual resets.
        unsafe {
            self.device
                .raw
                .reset_command_buffer(self.buffer, vk::CommandBufferResetFlags::empty())
                .map_err(vk_error("vkResetCommandBuffer"))?;
            self.device
                .raw
                .begin_command_buffer(self.buffer, &begin)
                .map_err(vk_error("vkBeginCommandBuffer"))?;
        }
        Ok(self.buffer)
    }
}

impl Drop for CommandPool {
    fn drop(&mut self) {
        // SAFETY: created on this device, destroyed once; its command buffer is not pending
        // (module docs) and is freed with the pool.
        unsafe { self.device.raw.destroy_command_pool(self.raw, None) }
    }
}
