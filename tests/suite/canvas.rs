//! A caller's Vulkan device made with plain ash for tests of the embedding and C APIs: the
//! validation layer on (any message it reports fails the frame), lavapipe, dynamic rendering,
//! the provoking-vertex extension and shaderClipDistance, one color image of `size`² (`R8G8B8A8_UNORM`, no
//! depth) read back after each frame, and host-visible buffers holding what a test writes.

use std::ffi::{c_void, CStr};
use std::sync::{Arc, Mutex};

use ash::{ext, vk};
use ffvk::vk::{Device, EnabledFeatures};

/// What the validation layer said.
type Messages = Mutex<Vec<String>>;

unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _kind: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    let loud = vk::DebugUtilsMessageSeverityFlagsEXT::ERROR | vk::DebugUtilsMessageSeverityFlagsEXT::WARNING;
    if severity.intersects(loud) {
        // SAFETY: the layer passes valid callback data; `user` is the canvas's boxed messages,
        // alive until the messenger is destroyed.
        let (text, sink) = unsafe {
            (
                CStr::from_ptr((*data).p_message).to_string_lossy().into_owned(),
                &*(user as *const Messages),
            )
        };
        if let Ok(mut m) = sink.lock() {
            m.push(text);
        }
    }
    vk::FALSE
}

/// The caller's device, image and buffers; everything is destroyed on drop (ffvk's objects
/// first: tests drop their `Lighting`s before the canvas).
pub(crate) struct Canvas {
    _entry: ash::Entry,
    instance: ash::Instance,
    messenger: (ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT),
    messages: Box<Messages>,
    pub(crate) physical: vk::PhysicalDevice,
    pub(crate) device: ash::Device,
    queue: vk::Queue,
    pool: vk::CommandPool,
    cmd: vk::CommandBuffer,
    fence: vk::Fence,
    color: (vk::Image, vk::ImageView, vk::DeviceMemory),
    readback: (vk::Buffer, vk::DeviceMemory),
    /// Textures: image, view, memory, sampler; laid out for sampling by the next frame.
    textures: Vec<(vk::Image, vk::ImageView, vk::DeviceMemory, vk::Sampler)>,
    /// Textures made since the last frame, which that frame lays out for sampling first.
    fresh: Vec<vk::Image>,
    buffers: Vec<(vk::Buffer, vk::DeviceMemory)>,
    pub(crate) size: u32,
}

impl Canvas {
    /// A device and a `size`² color image.
    pub(crate) fn new(size: u32) -> Canvas {
        // SAFETY: loads the system's Vulkan loader; every create info outlives its call, and
        // every object is made from the ones made before it.
        unsafe {
            let entry = ash::Entry::load().expect("the Vulkan loader");
            let layers = [c"VK_LAYER_KHRONOS_validation".as_ptr()];
            let extensions = [ext::debug_utils::NAME.as_ptr()];
            let app = vk::ApplicationInfo::default().api_version(vk::API_VERSION_1_3);
            let info = vk::InstanceCreateInfo::default()
                .application_info(&app)
                .enabled_layer_names(&layers)
                .enabled_extension_names(&extensions);
            let instance = entry
                .create_instance(&info, None)
                .expect("an instance with validation");
            let messages: Box<Messages> = Box::default();
            let loader = ext::debug_utils::Instance::new(&entry, &instance);
            let info = vk::DebugUtilsMessengerCreateInfoEXT::default()
                .message_severity(
                    vk::DebugUtilsMessageSeverityFlagsEXT::ERROR
                        | vk::DebugUtilsMessageSeverityFlagsEXT::WARNING,
                )
                .message_type(
                    vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                        | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION,
                )
                .pfn_user_callback(Some(on_message))
                .user_data(&*messages as *const Messages as *mut c_void);
            let messenger = loader
                .create_debug_utils_messenger(&info, None)
                .expect("a messenger");
            let physical = instance
                .enumerate_physical_devices()
                .expect("physical devices")
                .into_iter()
                .find(|&p| {
                    instance
                        .get_physical_device_properties(p)
                        .device_name_as_c_str()
                        .is_ok_and(|n| n.to_string_lossy().contains("llvmpipe"))
                })
                .expect("lavapipe");
            let priorities = [1.0];
            let queues = [vk::DeviceQueueCreateInfo::default()
                .queue_family_index(0)
                .queue_priorities(&priorities)];
            let mut v13 = vk::PhysicalDeviceVulkan13Features::default().dynamic_rendering(true);
            let mut provoking =
                vk::PhysicalDeviceProvokingVertexFeaturesEXT::default().provoking_vertex_last(true);
            let device_extensions = [ext::provoking_vertex::NAME.as_ptr()];
            let base = vk::PhysicalDeviceFeatures::default().shader_clip_distance(true);
            let info = vk::DeviceCreateInfo::default()
                .queue_create_infos(&queues)
                .enabled_extension_names(&device_extensions)
                .enabled_features(&base)
                .push_next(&mut v13)
                .push_next(&mut provoking);
            let device = instance.create_device(physical, &info, None).expect("a device");
            let queue = device.get_device_queue(0, 0);
            let pool = device
                .create_command_pool(
                    &vk::CommandPoolCreateInfo::default()
                        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER),
                    None,
                )
                .expect("a command pool");
            let cmd = device
                .allocate_command_buffers(
                    &vk::CommandBufferAllocateInfo::default()
                        .command_pool(pool)
                        .command_buffer_count(1),
                )
                .expect("a command buffer")[0];
            let fence = device
                .create_fence(&vk::FenceCreateInfo::default(), None)
                .expect("a fence");
            let mut canvas = Canvas {
                _entry: entry,
                instance,
                messenger: (loader, messenger),
                messages,
                physical,
                device,
                queue,
                pool,
                cmd,
                fence,
                color: Default::default(),
                readback: Default::default(),
                textures: Vec::new(),
                fresh: Vec::new(),
                buffers: Vec::new(),
                size,
            };
            canvas.color = canvas.color_image();
            let bytes = u64::from(size) * u64::from(size) * 4;
            canvas.readback = canvas.host_buffer(bytes, vk::BufferUsageFlags::TRANSFER_DST);
            canvas
        }
    }

    /// ffvk's view of this device.
    pub(crate) fn ffvk(&self) -> Arc<Device> {
        let enabled = EnabledFeatures::default()
            .with_dynamic_rendering(true)
            .with_provoking_vertex_last(true)
            .with_clip_distance(true);
        // SAFETY: the device comes from this physical device with those features, and lives
        // until the canvas drops, after the tests' ffvk objects.
        unsafe { Device::from_caller(&self.instance, self.physical, self.device.clone(), enabled) }
            .expect("ffvk takes the device")
    }

    /// Memory of a type in `bits` with `flags`.
    fn memory(
        &self,
        requirements: vk::MemoryRequirements,
        flags: vk::MemoryPropertyFlags,
    ) -> vk::DeviceMemory {
        // SAFETY: the physical device and device are alive.
        unsafe {
            let types = self.instance.get_physical_device_memory_properties(self.physical);
            let index = (0..types.memory_type_count)
                .find(|&i| {
                    requirements.memory_type_bits & (1 << i) != 0
                        && types.memory_types[i as usize].property_flags.contains(flags)
                })
                .expect("a memory type");
            let info = vk::MemoryAllocateInfo::default()
                .allocation_size(requirements.size)
                .memory_type_index(index);
            self.device.allocate_memory(&info, None).expect("memory")
        }
    }

    /// A host-visible, coherent buffer of `size` bytes.
    fn host_buffer(&self, size: u64, usage: vk::BufferUsageFlags) -> (vk::Buffer, vk::DeviceMemory) {
        // SAFETY: the device is alive; the memory is bound once, at offset 0.
        unsafe {
            let info = vk::BufferCreateInfo::default().size(size.max(4)).usage(usage);
            let buffer = self.device.create_buffer(&info, None).expect("a buffer");
            let requirements = self.device.get_buffer_memory_requirements(buffer);
            let memory = self.memory(
                requirements,
                vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
            );
            self.device.bind_buffer_memory(buffer, memory, 0).expect("bound");
            (buffer, memory)
        }
    }

    /// A vertex (and index) buffer holding `bytes`, destroyed with the canvas.
    pub(crate) fn buffer(&mut self, bytes: &[u8]) -> vk::Buffer {
        let usage = vk::BufferUsageFlags::VERTEX_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
        let (buffer, memory) = self.host_buffer(bytes.len() as u64, usage);
        // SAFETY: the memory is host-visible, unmapped and at least `bytes.len()` long.
        unsafe {
            let at = self
                .device
                .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .expect("mapped");
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), at.cast::<u8>(), bytes.len());
            self.device.unmap_memory(memory);
        }
        self.buffers.push((buffer, memory));
        buffer
    }

    fn color_image(&self) -> (vk::Image, vk::ImageView, vk::DeviceMemory) {
        // SAFETY: the device is alive; the image's memory is bound once.
        unsafe {
            let info = vk::ImageCreateInfo::default()
                .image_type(vk::ImageType::TYPE_2D)
                .format(vk::Format::R8G8B8A8_UNORM)
                .extent(vk::Extent3D {
                    width: self.size,
                    height: self.size,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC);
            let image = self.device.create_image(&info, None).expect("an image");
            let memory = self.memory(
                self.device.get_image_memory_requirements(image),
                vk::MemoryPropertyFlags::DEVICE_LOCAL,
            );
            self.device.bind_image_memory(image, memory, 0).expect("bound");
            let view = self
                .device
                .create_image_view(
                    &vk::ImageViewCreateInfo::default()
                        .image(image)
                        .view_type(vk::ImageViewType::TYPE_2D)
                        .format(vk::Format::R8G8B8A8_UNORM)
                        .subresource_range(color_range()),
                    None,
                )
                .expect("a view");
            (image, view, memory)
        }
    }

    /// A `width` × `height` RGBA8 texture of `rgba` (rows from GL's first, t = 0), linear
    /// tiling in host-visible memory, with a sampler made from `info`: its view and sampler,
    /// in `SHADER_READ_ONLY_OPTIMAL` from the next frame on.
    pub(crate) fn texture(
        &mut self,
        rgba: &[u8],
        (width, height): (u32, u32),
        info: &vk::SamplerCreateInfo,
    ) -> (vk::ImageView, vk::Sampler) {
        // SAFETY: the device is alive; the image's memory is bound once and written while
        // preinitialized, before any command uses it.
        unsafe {
            let image_info = vk::ImageCreateInfo::default()
                .image_type(vk::ImageType::TYPE_2D)
                .format(vk::Format::R8G8B8A8_UNORM)
                .extent(vk::Extent3D {
                    width,
                    height,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .tiling(vk::ImageTiling::LINEAR)
                .initial_layout(vk::ImageLayout::PREINITIALIZED)
                .usage(vk::ImageUsageFlags::SAMPLED);
            let image = self.device.create_image(&image_info, None).expect("a texture");
            let memory = self.memory(
                self.device.get_image_memory_requirements(image),
                vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
            );
            self.device.bind_image_memory(image, memory, 0).expect("bound");
            let layout = self.device.get_image_subresource_layout(
                image,
                vk::ImageSubresource {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    mip_level: 0,
                    array_layer: 0,
                },
            );
            let at = self
                .device
                .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .expect("mapped")
                .cast::<u8>();
            let row = (width * 4) as usize;
            for (y, texels) in rgba.chunks_exact(row).enumerate() {
                let to = at.add(layout.offset as usize + y * layout.row_pitch as usize);
                std::ptr::copy_nonoverlapping(texels.as_ptr(), to, row);
            }
            self.device.unmap_memory(memory);
            let view = self
                .device
                .create_image_view(
                    &vk::ImageViewCreateInfo::default()
                        .image(image)
                        .view_type(vk::ImageViewType::TYPE_2D)
                        .format(vk::Format::R8G8B8A8_UNORM)
                        .subresource_range(color_range()),
                    None,
                )
                .expect("a view");
            let sampler = self.device.create_sampler(info, None).expect("a sampler");
            self.textures.push((image, view, memory, sampler));
            self.fresh.push(image);
            (view, sampler)
        }
    }

    /// The whole image as a viewport (depth 0..1).
    pub(crate) fn full_viewport(&self) -> vk::Viewport {
        vk::Viewport {
            x: 0.0,
            y: 0.0,
            width: self.size as f32,
            height: self.size as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        }
    }

    /// Records one frame: the image cleared to transparent black, a rendering pass begun with
    /// the full viewport and scissor set, `record` called with the device and the command
    /// buffer, the pass
    /// ended; submits it, waits, and returns the image, row 0 at the top. Fails with what the
    /// validation layer said, if it said anything.
    pub(crate) fn frame(
        &mut self,
        record: impl FnOnce(&ash::Device, vk::CommandBuffer),
    ) -> Result<image::RgbaImage, String> {
        let (device, cmd, size) = (&self.device, self.cmd, self.size);
        let extent = vk::Extent2D {
            width: size,
            height: size,
        };
        // SAFETY: the command buffer is not in use (the last frame was waited for); every
        // handle is alive; the barriers order the clear, the draws and the copy.
        unsafe {
            device
                .reset_command_buffer(cmd, vk::CommandBufferResetFlags::empty())
                .map_err(|e| e.to_string())?;
            device
                .begin_command_buffer(cmd, &vk::CommandBufferBeginInfo::default())
                .map_err(|e| e.to_string())?;
            let to_sampled: Vec<vk::ImageMemoryBarrier> = self
                .fresh
                .drain(..)
                .map(|image| {
                    vk::ImageMemoryBarrier::default()
                        .old_layout(vk::ImageLayout::PREINITIALIZED)
                        .new_layout(vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL)
                        .src_access_mask(vk::AccessFlags::HOST_WRITE)
                        .dst_access_mask(vk::AccessFlags::SHADER_READ)
                        .image(image)
                        .subresource_range(color_range())
                })
                .collect();
            if !to_sampled.is_empty() {
                device.cmd_pipeline_barrier(
                    cmd,
                    vk::PipelineStageFlags::HOST,
                    vk::PipelineStageFlags::FRAGMENT_SHADER,
                    vk::DependencyFlags::empty(),
                    &[],
                    &[],
                    &to_sampled,
                );
            }
            let to_attachment = vk::ImageMemoryBarrier::default()
                .old_layout(vk::ImageLayout::UNDEFINED)
                .new_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                .dst_access_mask(vk::AccessFlags::COLOR_ATTACHMENT_WRITE)
                .image(self.color.0)
                .subresource_range(color_range());
            device.cmd_pipeline_barrier(
                cmd,
                vk::PipelineStageFlags::TOP_OF_PIPE,
                vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &[to_attachment],
            );
            let attachment = [vk::RenderingAttachmentInfo::default()
                .image_view(self.color.1)
                .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::STORE)
                .clear_value(vk::ClearValue::default())];
            let rendering = vk::RenderingInfo::default()
                .render_area(extent.into())
                .layer_count(1)
                .color_attachments(&attachment);
            device.cmd_begin_rendering(cmd, &rendering);
            device.cmd_set_viewport(cmd, 0, &[self.full_viewport()]);
            device.cmd_set_scissor(cmd, 0, &[extent.into()]);
            record(device, cmd);
            device.cmd_end_rendering(cmd);
            let to_copy = vk::ImageMemoryBarrier::default()
                .old_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                .new_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)
                .src_access_mask(vk::AccessFlags::COLOR_ATTACHMENT_WRITE)
                .dst_access_mask(vk::AccessFlags::TRANSFER_READ)
                .image(self.color.0)
                .subresource_range(color_range());
            device.cmd_pipeline_barrier(
                cmd,
                vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
                vk::PipelineStageFlags::TRANSFER,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &[to_copy],
            );
            let region = vk::BufferImageCopy::default()
                .image_subresource(vk::ImageSubresourceLayers {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    mip_level: 0,
                    base_array_layer: 0,
                    layer_count: 1,
                })
                .image_extent(vk::Extent3D {
                    width: size,
                    height: size,
                    depth: 1,
                });
            device.cmd_copy_image_to_buffer(
                cmd,
                self.color.0,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                self.readback.0,
                &[region],
            );
            let to_host = vk::BufferMemoryBarrier::default()
                .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                .dst_access_mask(vk::AccessFlags::HOST_READ)
                .buffer(self.readback.0)
                .size(vk::WHOLE_SIZE);
            device.cmd_pipeline_barrier(
                cmd,
                vk::PipelineStageFlags::TRANSFER,
                vk::PipelineStageFlags::HOST,
                vk::DependencyFlags::empty(),
                &[],
                &[to_host],
                &[],
            );
            device.end_command_buffer(cmd).map_err(|e| e.to_string())?;
            let cmds = [cmd];
            device
                .queue_submit(
                    self.queue,
                    &[vk::SubmitInfo::default().command_buffers(&cmds)],
                    self.fence,
                )
                .map_err(|e| e.to_string())?;
            device
                .wait_for_fences(&[self.fence], true, u64::MAX)
                .map_err(|e| e.to_string())?;
            device.reset_fences(&[self.fence]).map_err(|e| e.to_string())?;
            let bytes = (size * size * 4) as usize;
            let at = device
                .map_memory(self.readback.1, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .map_err(|e| e.to_string())?;
            let pixels = std::slice::from_raw_parts(at.cast::<u8>(), bytes).to_vec();
            device.unmap_memory(self.readback.1);
            self.said()?;
            image::RgbaImage::from_raw(size, size, pixels).ok_or_else(|| "a short readback".to_owned())
        }
    }

    /// Fails with what the validation layer said since the last call, if anything.
    pub(crate) fn said(&self) -> Result<(), String> {
        let messages = std::mem::take(&mut *self.messages.lock().unwrap_or_else(|p| p.into_inner()));
        if messages.is_empty() {
            Ok(())
        } else {
            Err(format!("validation messages:\n{}", messages.join("\n")))
        }
    }
}

fn color_range() -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

impl Drop for Canvas {
    fn drop(&mut self) {
        // SAFETY: nothing is executing (every frame was waited for) and the tests dropped
        // ffvk's objects on this device; each object is destroyed once, children first.
        unsafe {
            let d = &self.device;
            let _ = d.device_wait_idle();
            for (image, view, memory, sampler) in self.textures.drain(..) {
                d.destroy_sampler(sampler, None);
                d.destroy_image_view(view, None);
                d.destroy_image(image, None);
                d.free_memory(memory, None);
            }
            for (buffer, memory) in self.buffers.drain(..).chain([self.readback]) {
                d.destroy_buffer(buffer, None);
                d.free_memory(memory, None);
            }
            d.destroy_image_view(self.color.1, None);
            d.destroy_image(self.color.0, None);
            d.free_memory(self.color.2, None);
            d.destroy_fence(self.fence, None);
            d.destroy_command_pool(self.pool, None);
            d.destroy_device(None);
            self.messenger
                .0
                .destroy_debug_utils_messenger(self.messenger.1, None);
            self.instance.destroy_instance(None);
        }
    }
}

/// A quad over its whole viewport as a triangle strip, z = 0.
pub(crate) const QUAD: [[f32; 3]; 4] = [
    [-1.0, -1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, 1.0, 0.0],
];

/// Vertex binding 0 of `stride` bytes, per vertex.
pub(crate) fn binding(stride: u32) -> vk::VertexInputBindingDescription {
    vk::VertexInputBindingDescription {
        binding: 0,
        stride,
        input_rate: vk::VertexInputRate::VERTEX,
    }
}

/// The largest difference of any channel between two images of one size.
pub(crate) fn max_difference(a: &image::RgbaImage, b: &image::RgbaImage) -> u8 {
    a.pixels()
        .zip(b.pixels())
        .flat_map(|(p, q)| p.0.iter().zip(q.0).map(|(x, y)| x.abs_diff(y)))
        .max()
        .unwrap_or(0)
}
