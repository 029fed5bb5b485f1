//! Buffers and images, each owning its memory and an `Arc` of its device.

use std::sync::Arc;

use ash::vk;

use super::device::Device;
use crate::error::{vk_error, Result};

/// A host-visible, coherent buffer, persistently mapped. ffvk targets CPU Vulkan (lavapipe),
/// where all memory is host memory, so a staging copy would only add work.
pub struct Buffer {
    device: Arc<Device>,
    pub(crate) raw: vk::Buffer,
    memory: vk::DeviceMemory,
    mapped: *mut u8,
    size: u64,
}

// SAFETY: the mapped pointer is only written through &mut self or read through &self,
// and Vulkan handles may be used from any thread with external synchronisation, which
// Rust's borrow rules provide here.
unsafe impl Send for Buffer {}
// SAFETY: see above; &self methods only read.
unsafe impl Sync for Buffer {}

impl Buffer {
    pub fn new(device: &Arc<Device>, size: u64, usage: vk::BufferUsageFlags) -> Result<Self> {
        let size = size.max(4);
        let vkd = &device.raw;
        let info = vk::BufferCreateInfo::default()
            .size(size)
            .usage(usage)
            .sharing_mode(vk::SharingMode::EXCLUSIVE);
        // SAFETY: valid create info on a live device.
        let raw = unsafe { vkd.create_buffer(&info, None) }.map_err(vk_error("vkCreateBuffer"))?;
        // The partially built buffer frees what it holds if a later step fails.
        let mut buffer = Buffer {
            device: device.clone(),
            raw,
            memory: vk::DeviceMemory::null(),
            mapped: std::ptr::null_mut(),
            size,
        };
        // SAFETY: raw is a live buffer of this device.
        let req = unsafe { vkd.get_buffer_memory_requirements(raw) };
        let type_index = device.memory_type(
            req.memory_type_bits,
            vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
        )?;
        let alloc = vk::MemoryAllocateInfo::default()
            .allocation_size(req.size)
            .memory_type_index(type_index);
        // SAFETY: valid allocate info on a live device.
        buffer.memory = unsafe { vkd.allocate_memory(&alloc, None) }.map_err(vk_error("vkAllocateMemory"))?;
        // SAFETY: memory is fresh, large enough per the requirements, and unbound.
        unsafe { vkd.bind_buffer_memory(raw, buffer.memory, 0) }.map_err(vk_error("vkBindBufferMemory"))?;
        // SAFETY: host-visible memory, mapped once for its whole lifetime.
        buffer.mapped =
            unsafe { vkd.map_memory(buffer.memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty()) }
                .map_err(vk_error("vkMapMemory"))? as *mut u8;
        Ok(buffer)
    }

    pub fn size(&self) -> u64 {
        self.size
    }

    /// The device that owns this buffer.
    pub(crate) fn device(&self) -> &Arc<Device> {
        &self.device
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

impl Drop for Buffer {
    fn drop(&mut self) {
        // SAFETY: the renderer waits for its fence before dropping resources a frame used.
        unsafe {
            self.device.raw.destroy_buffer(self.raw, None);
            if self.memory != vk::DeviceMemory::null() {
                self.device.raw.free_memory(self.memory, None);
            }
        }
    }
}

/// A 2D image with its own memory and a view.
pub struct Image {
    device: Arc<Device>,
    pub(crate) raw: vk::Image,
    pub(crate) view: vk::ImageView,
    memory: vk::DeviceMemory,
}

impl Image {
    pub fn new(
        device: &Arc<Device>,
        extent: vk::Extent2D,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
    ) -> Result<Self> {
        let vkd = &device.raw;
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
        // SAFETY: valid create info on a live device.
        let raw = unsafe { vkd.create_image(&info, None) }.map_err(vk_error("vkCreateImage"))?;
        let mut image = Image {
            device: device.clone(),
            raw,
            view: vk::ImageView::null(),
            memory: vk::DeviceMemory::null(),
        };
        // SAFETY: raw is a live image of this device.
        let req = unsafe { vkd.get_image_memory_requirements(raw) };
        let type_index = device.memory_type(req.memory_type_bits, vk::MemoryPropertyFlags::empty())?;
        let alloc = vk::MemoryAllocateInfo::default()
            .allocation_size(req.size)
            .memory_type_index(type_index);
        // SAFETY: valid allocate info on a live device.
        image.memory = unsafe { vkd.allocate_memory(&alloc, None) }.map_err(vk_error("vkAllocateMemory"))?;
        // SAFETY: fresh memory of the required size, image unbound.
        unsafe { vkd.bind_image_memory(raw, image.memory, 0) }.map_err(vk_error("vkBindImageMemory"))?;
        let view_info = vk::ImageViewCreateInfo::default()
            .image(raw)
            .view_type(vk::ImageViewType::TYPE_2D)
            .format(format)
            .subresource_range(vk::ImageSubresourceRange {
                aspect_mask: aspect,
                base_mip_level: 0,
                level_count: 1,
                base_array_layer: 0,
                layer_count: 1,
            });
        // SAFETY: the image is bound to memory and the view matches its format.
        image.view =
            unsafe { vkd.create_image_view(&view_info, None) }.map_err(vk_error("vkCreateImageView"))?;
        Ok(image)
    }
}

impl Drop for Image {
    fn drop(&mut self) {
        // SAFETY: the renderer waits for its fence before dropping images a frame used.
        unsafe {
            if self.view != vk::ImageView::null() {
                self.device.raw.destroy_image_view(self.view, None);
            }
            self.device.raw.destroy_image(self.raw, None);
            if self.memory != vk::DeviceMemory::null() {
                self.device.raw.free_memory(self.memory, None);
            }
        }
    }
}
