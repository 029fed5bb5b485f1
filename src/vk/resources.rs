//! Buffers and images, each owning its memory and an `Arc` of its device.

use std::sync::Arc;

use ash::vk;

use super::device::Device;
use super::objects::{ImageView, Memory, RawBuffer, RawImage};
use crate::error::{vk_error, Result};

/// A host-visible, coherent buffer, persistently mapped. ffvk targets CPU Vulkan (lavapipe),
/// where all memory is host memory, so a staging copy would only add work.
pub struct Buffer {
    // Field order is drop order: the buffer goes before the memory bound to it (which unmaps).
    raw: RawBuffer,
    memory: Memory,
    mapped: *mut u8,
    size: u64,
}

// SAFETY: the mapped pointer is only written through &mut self or read through &self,
// and Vulkan handles may be used from any thread with external synchronisation, which
// Rust's borrow rules provide here.
unsafe impl Send for Buffer {}
// SAFETY: see above; &self methods only read.
unsafe impl Sync for Buffer {}

/// What a buffer of `usage` holds, for messages.
fn buffer_purpose(usage: vk::BufferUsageFlags) -> &'static str {
    if usage.contains(vk::BufferUsageFlags::VERTEX_BUFFER) {
        "vertex buffer"
    } else if usage.contains(vk::BufferUsageFlags::INDEX_BUFFER) {
        "index buffer"
    } else if usage.contains(vk::BufferUsageFlags::UNIFORM_BUFFER) {
        "uniform buffer"
    } else {
        "readback buffer"
    }
}

impl Buffer {
    /// A buffer of `size` bytes (at least 4) for `usage`, mapped for its whole life.
    pub fn new(device: &Arc<Device>, size: u64, usage: vk::BufferUsageFlags) -> Result<Self> {
        let size = size.max(4);
        let info = vk::BufferCreateInfo::default()
            .size(size)
            .usage(usage)
            .sharing_mode(vk::SharingMode::EXCLUSIVE);
        let raw = RawBuffer::new(device, &info)?;
        // SAFETY: raw is a live buffer of this device.
        let req = unsafe { device.raw.get_buffer_memory_requirements(raw.raw()) };
        let type_index = device.memory_type(
            req.memory_type_bits,
            vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
        )?;
        device.check_allocation(buffer_purpose(usage), req.size, type_index)?;
        let memory = Memory::allocate(device, req.size, type_index)?;
        // SAFETY: the memory is fresh, large enough per the requirements, and the buffer unbound.
        unsafe { device.raw.bind_buffer_memory(raw.raw(), memory.raw(), 0) }
            .map_err(vk_error("vkBindBufferMemory"))?;
        // SAFETY: host-visible memory, mapped once for its whole lifetime (freeing unmaps it).
        let mapped = unsafe {
            device
                .raw
                .map_memory(memory.raw(), 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
        }
        .map_err(vk_error("vkMapMemory"))? as *mut u8;
        Ok(Buffer {
            raw,
            memory,
            mapped,
            size,
        })
    }

    /// The Vulkan handle.
    pub fn raw(&self) -> vk::Buffer {
        self.raw.raw()
    }

    /// The size in bytes.
    pub fn size(&self) -> u64 {
        self.size
    }

    /// The device that owns this buffer.
    pub(crate) fn device(&self) -> &Arc<Device> {
        self.memory.device()
    }

    /// Copies `bytes` in at `offset`. Panics only on a caller's bug (out-of-bounds write).
    pub fn write(&mut self, offset: u64, bytes: &[u8]) {
        assert!(
            offset + bytes.len() as u64 <= self.size,
            "buffer write out of bounds"
        );
        // SAFETY: the range is inside the mapping (checked above); &mut self means no
        // host reader, and callers only write between frames (after the fence wait).
        unsafe {
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), self.mapped.add(offset as usize), bytes.len())
        }
    }

    /// The mapped contents.
    pub fn bytes(&self) -> &[u8] {
        // SAFETY: the mapping covers `size` bytes and lives as long as self; coherent
        // memory needs no invalidate.
        unsafe { std::slice::from_raw_parts(self.mapped, self.size as usize) }
    }
}

/// A 2D image with its own memory and a view.
pub struct Image {
    // Field order is drop order: view, then image, then its memory.
    view: ImageView,
    raw: RawImage,
    _memory: Memory,
}

impl Image {
    /// A single-sampled, single-level 2D image of `format` with a view of `aspect`.
    pub fn new(
        device: &Arc<Device>,
        extent: vk::Extent2D,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
    ) -> Result<Self> {
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D {
                width: extent.width,
                height: extent.height,
                depth: 1,
            })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        let raw = RawImage::new(device, &info)?;
        // SAFETY: raw is a live image of this device.
        let req = unsafe { device.raw.get_image_memory_requirements(raw.raw()) };
        let type_index = device.memory_type(req.memory_type_bits, vk::MemoryPropertyFlags::empty())?;
        let what = if usage.contains(vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT) {
            "depth image"
        } else {
            "color image"
        };
        device.check_allocation(what, req.size, type_index)?;
        let memory = Memory::allocate(device, req.size, type_index)?;
        // SAFETY: fresh memory of the required size, image unbound.
        unsafe { device.raw.bind_image_memory(raw.raw(), memory.raw(), 0) }
            .map_err(vk_error("vkBindImageMemory"))?;
        let view_info = vk::ImageViewCreateInfo::default()
            .image(raw.raw())
            .view_type(vk::ImageViewType::TYPE_2D)
            .format(format)
            .subresource_range(vk::ImageSubresourceRange {
                aspect_mask: aspect,
                base_mip_level: 0,
                level_count: 1,
                base_array_layer: 0,
                layer_count: 1,
            });
        let view = ImageView::new(device, &view_info)?;
        Ok(Image {
            view,
            raw,
            _memory: memory,
        })
    }

    /// The Vulkan image.
    pub fn raw(&self) -> vk::Image {
        self.raw.raw()
    }

    /// The view of the whole image.
    pub fn view(&self) -> vk::ImageView {
        self.view.raw()
    }
}
