//! Buffers and images, each owning its place in device memory and an `Arc` of its device.

use std::sync::Arc;

use ash::vk;

use super::device::Device;
use super::memory::{Limits, MappedPtr, MemoryUse, Placed, Resource};
use super::objects::{ImageView, RawBuffer, RawImage};
use crate::error::{vk_error, Error, Result};

/// A piece of device memory: the memory object, the offset to bind at and, for host-visible
/// coherent memory, where it is mapped. Returned to the device's allocator when dropped.
struct Allocation {
    device: Arc<Device>,
    /// `None` only while being dropped.
    placed: Option<Placed>,
}

impl Allocation {
    fn new(
        device: &Arc<Device>,
        what: &'static str,
        resource: Resource,
        requirements: &vk::MemoryRequirements,
        usage: MemoryUse,
    ) -> Result<Self> {
        let limits = Limits {
            memory: &device.memory,
            max_allocation: device.max_memory_allocation_size,
        };
        let placed =
            device
                .allocator()
                .allocate(device.books(), &limits, what, resource, requirements, usage)?;
        Ok(Allocation {
            device: device.clone(),
            placed: Some(placed),
        })
    }

    fn placed(&self) -> &Placed {
        // Set from creation until Drop takes it.
        self.placed
            .as_ref()
            .unwrap_or_else(|| unreachable!("an allocation used after its drop"))
    }
    /// The memory object to bind.
    fn memory(&self) -> vk::DeviceMemory {
        // SAFETY: the memory object is alive while the allocation is, and is bound only to
        // this allocation's resource at its offset.
        unsafe { self.placed().inner.memory() }
    }
    /// The offset to bind at.
    fn offset(&self) -> u64 {
        self.placed().inner.offset()
    }
    /// Its memory type's property flags.
    fn flags(&self) -> vk::MemoryPropertyFlags {
        self.placed().inner.memory_properties()
    }
    /// Where the host sees its first byte, when the memory is host-visible and coherent.
    fn mapped(&self) -> Option<MappedPtr> {
        self.placed().mapped
    }
}

impl Drop for Allocation {
    fn drop(&mut self) {
        if let Some(placed) = self.placed.take() {
            self.device.allocator().free(self.device.books(), placed.inner);
        }
    }
}

/// A buffer and its memory, placed by the device's allocator for its [`MemoryUse`]; mapped
/// for its whole life when that memory is host-visible.
pub struct Buffer {
    // Field order is drop order: the buffer goes before its memory.
    raw: RawBuffer,
    memory: Allocation,
    size: u64,
}

impl Buffer {
    /// A buffer of `size` bytes (at least 4) for `usage`, in memory for `memory_use`; `what`
    /// names it in errors (e.g. `"vertex buffer"`).
    pub fn new(
        device: &Arc<Device>,
        what: &'static str,
        size: u64,
        usage: vk::BufferUsageFlags,
        memory_use: MemoryUse,
    ) -> Result<Self> {
        let size = size.max(4);
        let info = vk::BufferCreateInfo::default()
            .size(size)
            .usage(usage)
            .sharing_mode(vk::SharingMode::EXCLUSIVE);
        let raw = RawBuffer::new(device, &info)?;
        // SAFETY: raw is a live buffer of this device.
        let req = unsafe { device.raw.get_buffer_memory_requirements(raw.raw()) };
        let memory = Allocation::new(device, what, Resource::Buffer(raw.raw()), &req, memory_use)?;
        // SAFETY: the allocation is of a type the requirements allow, at an offset aligned as
        // they ask, as large as they ask; the buffer is unbound.
        unsafe {
            device
                .raw
                .bind_buffer_memory(raw.raw(), memory.memory(), memory.offset())
        }
        .map_err(vk_error("vkBindBufferMemory"))?;
        Ok(Buffer { raw, memory, size })
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
        &self.memory.device
    }

    /// The property flags of the memory type gpu-allocator placed it in.
    pub fn memory_flags(&self) -> vk::MemoryPropertyFlags {
        self.memory.flags()
    }

    /// Whether the host sees the buffer's memory ([`Buffer::write`] and [`Buffer::bytes`]
    /// work): always for the mapped uses, and for [`MemoryUse::Gpu`] on devices whose
    /// device-local memory is host-visible.
    pub fn is_mapped(&self) -> bool {
        self.memory.mapped().is_some()
    }

    /// Copies `bytes` in at `offset`. The caller writes only between frames (after the fence
    /// of the last frame that read the buffer).
    pub fn write(&mut self, offset: u64, bytes: &[u8]) -> Result<()> {
        let Some(mapped) = self.memory.mapped() else {
            return Err(Error::NotMapped);
        };
        let end = offset.checked_add(bytes.len() as u64);
        if end.is_none_or(|end| end > self.size) {
            return Err(Error::OutOfBounds {
                offset,
                bytes: bytes.len() as u64,
                size: self.size,
            });
        }
        // SAFETY: the range is inside the buffer (checked above), whose memory is mapped from
        // its first byte; &mut self means no host reader, and the caller keeps the GPU off it.
        unsafe {
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), mapped.get().add(offset as usize), bytes.len())
        }
        Ok(())
    }

    /// The mapped contents; `None` when the host cannot see the memory.
    pub fn bytes(&self) -> Option<&[u8]> {
        let mapped = self.memory.mapped()?;
        // SAFETY: the mapping covers the buffer's `size` bytes and lives as long as self;
        // coherent memory needs no invalidate.
        Some(unsafe { std::slice::from_raw_parts(mapped.get(), self.size as usize) })
    }
}

/// A 2D image (or a cube map's six layers) with its memory and a view of all its levels.
pub struct Image {
    // Field order is drop order: view, then image, then its memory.
    view: ImageView,
    raw: RawImage,
    _memory: Allocation,
    levels: u32,
    layers: u32,
}

impl Image {
    /// A single-sampled, single-level 2D image of `format` with a view of `aspect`, in
    /// device-local memory.
    pub fn new(
        device: &Arc<Device>,
        extent: vk::Extent2D,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
    ) -> Result<Self> {
        Image::with_levels(device, extent, format, usage, aspect, 1)
    }

    /// [`Image::new`] with `levels` mip levels (each half the one above, down to 1×1 at most).
    pub fn with_levels(
        device: &Arc<Device>,
        extent: vk::Extent2D,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
        levels: u32,
    ) -> Result<Self> {
        Image::make(device, (extent, levels, false), format, usage, aspect)
    }

    /// A cube map: six square color layers of `side` texels in GL's face order, `levels` mip
    /// levels each, with a `CUBE` view of them all.
    pub fn cube(
        device: &Arc<Device>,
        side: u32,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        levels: u32,
    ) -> Result<Self> {
        let extent = vk::Extent2D {
            width: side,
            height: side,
        };
        Image::make(
            device,
            (extent, levels, true),
            format,
            usage,
            vk::ImageAspectFlags::COLOR,
        )
    }

    fn make(
        device: &Arc<Device>,
        (extent, levels, cube): (vk::Extent2D, u32, bool),
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
    ) -> Result<Self> {
        let layers = if cube { 6 } else { 1 };
        let flags = if cube {
            vk::ImageCreateFlags::CUBE_COMPATIBLE
        } else {
            vk::ImageCreateFlags::empty()
        };
        let info = vk::ImageCreateInfo::default()
            .flags(flags)
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D {
                width: extent.width,
                height: extent.height,
                depth: 1,
            })
            .mip_levels(levels)
            .array_layers(layers)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        let raw = RawImage::new(device, &info)?;
        // SAFETY: raw is a live image of this device.
        let req = unsafe { device.raw.get_image_memory_requirements(raw.raw()) };
        let what = if usage.contains(vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT) {
            "depth image"
        } else if usage.contains(vk::ImageUsageFlags::SAMPLED) {
            "texture image"
        } else {
            "color image"
        };
        let memory = Allocation::new(device, what, Resource::Image(raw.raw()), &req, MemoryUse::Gpu)?;
        // SAFETY: memory of an allowed type, aligned and as large as required; image unbound.
        unsafe {
            device
                .raw
                .bind_image_memory(raw.raw(), memory.memory(), memory.offset())
        }
        .map_err(vk_error("vkBindImageMemory"))?;
        let view_info = vk::ImageViewCreateInfo::default()
            .image(raw.raw())
            .view_type(if cube {
                vk::ImageViewType::CUBE
            } else {
                vk::ImageViewType::TYPE_2D
            })
            .format(format)
            .subresource_range(vk::ImageSubresourceRange {
                aspect_mask: aspect,
                base_mip_level: 0,
                level_count: levels,
                base_array_layer: 0,
                layer_count: layers,
            });
        let view = ImageView::new(device, &view_info)?;
        Ok(Image {
            view,
            raw,
            _memory: memory,
            levels,
            layers,
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

    /// The device that owns this image.
    pub(crate) fn device(&self) -> &Arc<Device> {
        self.raw.device()
    }

    /// How many mip levels it has.
    pub fn levels(&self) -> u32 {
        self.levels
    }

    /// How many array layers it has: 6 for a cube map, else 1.
    pub fn layers(&self) -> u32 {
        self.layers
    }
}
