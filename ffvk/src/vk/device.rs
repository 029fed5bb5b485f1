//! Physical device choice (lavapipe by default) and the logical device with one graphics queue.

use std::sync::Arc;

use ash::{ext, vk};

use super::instance::Instance;
use super::memory::{Books, DeviceAllocator, MemoryUsage, MemoryUse};
use super::supported::Supported;
use crate::error::{vk_error, Error, Result};

/// What `ffvk info` prints and benchmarks record.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct DeviceInfo {
    /// `deviceName`, e.g. `llvmpipe (LLVM …)` for lavapipe; what
    /// [`RendererOptions::device`](crate::RendererOptions::device) is matched against.
    pub name: String,
    /// `VkPhysicalDeviceType` as ash's `Debug` spells it, e.g. `CPU` or `DISCRETE_GPU`.
    pub device_type: String,
    /// `driverName` (`VkPhysicalDeviceDriverProperties`), e.g. `llvmpipe`.
    pub driver_name: String,
    /// `driverInfo`: the driver's own version text (the Mesa version for lavapipe).
    pub driver_info: String,
    /// The device's Vulkan version, `major.minor.patch`; at least 1.3.
    pub api_version: String,
    /// `vendorID`: the PCI vendor ID, or a Khronos-assigned one for non-PCI drivers.
    pub vendor_id: u32,
    /// `deviceID`, vendor-specific.
    pub device_id: u32,
    /// `maxImageDimension2D`: the largest frame width or height, in pixels.
    pub max_image_dimension_2d: u32,
    /// `maxUniformBufferRange`: the largest uniform block a descriptor can see, in bytes.
    pub max_uniform_buffer_range: u32,
    /// `minUniformBufferOffsetAlignment`, in bytes: the state blocks and draw records sit at
    /// multiples of it (and of 16).
    pub min_uniform_buffer_offset_alignment: u64,
    /// `maxVertexOutputComponents`: scalar outputs a vertex shader may pass on; the
    /// per-vertex modes pass up to four colors.
    pub max_vertex_output_components: u32,
    /// `timestampPeriod`: nanoseconds per timestamp tick.
    pub timestamp_period_ns: f32,
    /// Meaningful bits of the graphics queue's timestamps (0: no timestamps).
    pub timestamp_valid_bits: u32,
    /// Whether the graphics queue writes timestamps; without them
    /// [`FrameStats::gpu_ns`](crate::FrameStats::gpu_ns) is `None`.
    pub timestamps_supported: bool,
    /// Whether `pipelineStatisticsQuery` is available (ffvk enables it when it is); without
    /// it [`FrameStats::pipeline`](crate::FrameStats::pipeline) is `None`.
    pub pipeline_statistics_query: bool,
    /// `provokingVertexLast` of `VK_EXT_provoking_vertex`, which GL's flat shading needs:
    /// always true, since [`Device::new`] refuses a device without it.
    pub provoking_vertex_last: bool,
    /// `wideLines`: lines wider than one pixel (`RasterState::line_width`).
    pub wide_lines: bool,
    /// `largePoints`: points larger than one pixel (`RasterState::point_size`).
    pub large_points: bool,
    /// `shaderClipDistance`: GL's user clip planes (`glClipPlane`) through `gl_ClipDistance`.
    pub clip_distance: bool,
    /// `fillModeNonSolid`: `glPolygonMode`'s `GL_LINE` and `GL_POINT`.
    pub fill_mode_non_solid: bool,
    /// `logicOp`: `glLogicOp` (`GL_COLOR_LOGIC_OP`).
    pub logic_op: bool,
    /// `geometryShader` with `shaderTessellationAndGeometryPointSize`: GL's edge flags (polygons
    /// drawn as lines or points without their inner edges,
    /// [`Topology::EdgeFlaggedTriangles`](crate::draw::record::Topology)).
    pub geometry_shader: bool,
    /// `VK_EXT_line_rasterization` with `bresenhamLines` and `stippledBresenhamLines`:
    /// `glLineStipple` (`GL_LINE_STIPPLE`).
    pub stippled_lines: bool,
    /// `VK_EXT_non_seamless_cube_map` with `nonSeamlessCubeMap`: GL 2.1's cube map filtering,
    /// each face on its own (without it, cube maps filter across face edges).
    pub non_seamless_cube_map: bool,
    /// `lineWidthRange` and `pointSizeRange`, in pixels.
    pub line_width_range: [f32; 2],
    /// `pointSizeRange`, in pixels.
    pub point_size_range: [f32; 2],
    /// Whether the validation layer is active on the instance.
    pub validation: bool,
}

/// A logical device and what ffvk knows about it: either ffvk's own (opened by
/// [`Device::new`], with its instance and one graphics queue, destroyed when the last `Arc`
/// goes) or a caller's (wrapped by [`Device::from_caller`], never destroyed by ffvk).
pub struct Device {
    pub(crate) raw: ash::Device,
    pub(crate) memory: vk::PhysicalDeviceMemoryProperties,
    pub(crate) limits: vk::PhysicalDeviceLimits,
    /// Where every buffer and image of this device gets its memory.
    allocator: DeviceAllocator,
    /// ffvk's own allocations in it.
    books: Books,
    /// Vulkan 1.1's maxMemoryAllocationSize (0: unknown).
    pub(crate) max_memory_allocation_size: u64,
    pub(crate) info: DeviceInfo,
    /// What only ffvk's own device has; `None` for a caller's device.
    pub(crate) own: Option<OwnDevice>,
    /// How to ask which features a format has on this device.
    formats: FormatQuery,
    /// Counts the recordings of every [`Lighting`](crate::Lighting) on this device: a
    /// `Lighting` trusts what it remembers having bound only if no other one recorded since
    /// (two `Lighting`s drawing into one command buffer bind over each other).
    pub(crate) recordings: std::sync::atomic::AtomicU64,
}

/// `vkGetPhysicalDeviceFormatProperties` of the device's instance, and its physical device:
/// what a [`Target`](crate::Target) and a vertex layout are checked against.
#[derive(Clone, Copy)]
pub(crate) struct FormatQuery {
    physical: vk::PhysicalDevice,
    get: vk::PFN_vkGetPhysicalDeviceFormatProperties,
}

impl FormatQuery {
    fn new(instance: &ash::Instance, physical: vk::PhysicalDevice) -> Self {
        FormatQuery {
            physical,
            get: instance.fp_v1_0().get_physical_device_format_properties,
        }
    }
}

/// The instance and queue of a device ffvk opened itself.
pub(crate) struct OwnDevice {
    pub(crate) instance: Arc<Instance>,
    pub(crate) queue: vk::Queue,
    pub(crate) queue_family: u32,
}

/// A memory type chosen for a use ([`Device::memory_choices`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct MemoryChoice {
    /// The memory type's index.
    pub index: u32,
    /// Its property flags.
    pub flags: vk::MemoryPropertyFlags,
    /// The size of its heap, in bytes.
    pub heap_bytes: u64,
}

/// The device features a caller enabled on its own device, as it tells
/// [`Device::from_caller`] (Vulkan cannot be asked which features a device was created with).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub struct EnabledFeatures {
    /// `dynamicRendering` (Vulkan 1.3 core): required; ffvk's pipelines render without render
    /// passes.
    pub dynamic_rendering: bool,
    /// `provokingVertexLast` of `VK_EXT_provoking_vertex` (with the extension enabled): needed
    /// for the `flat` lighting mode, whose triangles take their last vertex's color as in GL.
    pub provoking_vertex_last: bool,
    /// `wideLines`: needed for a line width other than 1.
    pub wide_lines: bool,
    /// `largePoints`: needed for a point size other than 1.
    pub large_points: bool,
    /// `shaderClipDistance`: needed for GL's user clip planes.
    pub clip_distance: bool,
    /// `fillModeNonSolid`: needed for `glPolygonMode`'s `GL_LINE` and `GL_POINT`.
    pub fill_mode_non_solid: bool,
    /// `logicOp`: needed for `glLogicOp`.
    pub logic_op: bool,
    /// `geometryShader` and `shaderTessellationAndGeometryPointSize`: needed for GL's edge flags
    /// (`Topology::EdgeFlaggedTriangles`).
    pub geometry_shader: bool,
    /// `VK_EXT_line_rasterization` (enabled) with `bresenhamLines` and
    /// `stippledBresenhamLines`: needed for `glLineStipple`.
    pub stippled_lines: bool,
    /// `VK_EXT_non_seamless_cube_map` (enabled) with `nonSeamlessCubeMap`: lets the samplers
    /// of ffvk's renderer filter each cube map face on its own, as GL 2.1 does (a caller makes
    /// its own samplers).
    pub non_seamless_cube_map: bool,
}

with_fields!(EnabledFeatures {
    /// Sets [`dynamic_rendering`](EnabledFeatures::dynamic_rendering).
    with_dynamic_rendering => dynamic_rendering: bool,
    /// Sets [`provoking_vertex_last`](EnabledFeatures::provoking_vertex_last).
    with_provoking_vertex_last => provoking_vertex_last: bool,
    /// Sets [`wide_lines`](EnabledFeatures::wide_lines).
    with_wide_lines => wide_lines: bool,
    /// Sets [`large_points`](EnabledFeatures::large_points).
    with_large_points => large_points: bool,
    /// Sets [`clip_distance`](EnabledFeatures::clip_distance).
    with_clip_distance => clip_distance: bool,
    /// Sets [`fill_mode_non_solid`](EnabledFeatures::fill_mode_non_solid).
    with_fill_mode_non_solid => fill_mode_non_solid: bool,
    /// Sets [`logic_op`](EnabledFeatures::logic_op).
    with_logic_op => logic_op: bool,
    /// Sets [`geometry_shader`](EnabledFeatures::geometry_shader).
    with_geometry_shader => geometry_shader: bool,
    /// Sets [`stippled_lines`](EnabledFeatures::stippled_lines).
    with_stippled_lines => stippled_lines: bool,
    /// Sets [`non_seamless_cube_map`](EnabledFeatures::non_seamless_cube_map).
    with_non_seamless_cube_map => non_seamless_cube_map: bool,
});

pub(crate) fn device_name(props: &vk::PhysicalDeviceProperties) -> String {
    props
        .device_name_as_c_str()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default()
}

impl DeviceInfo {
    /// Whether the device is a CPU (`VK_PHYSICAL_DEVICE_TYPE_CPU`: lavapipe, SwiftShader):
    /// what [`FragmentPath::Auto`](crate::FragmentPath::Auto)'s rule asks.
    pub fn is_cpu(&self) -> bool {
        // `device_type` is ash's Debug spelling of the type (see `describe`).
        self.device_type == "CPU"
    }
}

impl Device {
    /// Opens the device whose name contains `requested` (case-insensitive), or lavapipe
    /// ("llvmpipe") by default, or else the first device.
    pub fn new(instance: Arc<Instance>, requested: Option<&str>) -> Result<Arc<Self>> {
        let vki = &instance.raw;
        // SAFETY: the instance is alive for the duration of the call.
        let physicals =
            unsafe { vki.enumerate_physical_devices() }.map_err(vk_error("vkEnumeratePhysicalDevices"))?;
        let named: Vec<(vk::PhysicalDevice, String)> = physicals
            .iter()
            // SAFETY: each handle comes from the enumeration above.
            .map(|&p| (p, device_name(&unsafe { vki.get_physical_device_properties(p) })))
            .collect();
        let available = if named.is_empty() {
            "none".to_owned()
        } else {
            named
                .iter()
                .map(|(_, n)| n.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        };
        let wanted = requested.unwrap_or("llvmpipe").to_lowercase();
        let pick = named
            .iter()
            .find(|(_, n)| n.to_lowercase().contains(&wanted))
            .or_else(|| if requested.is_none() { named.first() } else { None });
        let Some(&(physical, _)) = pick else {
            return Err(Error::NoDevice {
                requested: requested.map(|r| format!(" named {r:?}")).unwrap_or_default(),
                available,
            });
        };

        // SAFETY: physical is a valid handle from this instance.
        let (props, memory, families) = unsafe {
            (
                vki.get_physical_device_properties(physical),
                vki.get_physical_device_memory_properties(physical),
                vki.get_physical_device_queue_family_properties(physical),
            )
        };
        require_vulkan_1_3(&props)?;
        let queue_family = families
            .iter()
            .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
            .ok_or_else(|| Error::MissingFeature("a graphics queue".into()))?
            as u32;
        let timestamp_valid_bits = families[queue_family as usize].timestamp_valid_bits;

        // Features: dynamic rendering (1.3), last-vertex provoking convention (GL's flat
        // shading), pipeline statistics (benchmarks).
        // SAFETY: physical comes from this instance's enumeration.
        let supported = unsafe { Supported::query(vki, physical) };
        let pipeline_statistics_query = supported.pipeline_statistics_query;
        if !supported.dynamic_rendering || !supported.synchronization2 {
            return Err(Error::MissingFeature(
                "dynamicRendering and synchronization2".into(),
            ));
        }
        // SAFETY: physical is valid.
        let extensions = unsafe { vki.enumerate_device_extension_properties(physical) }
            .map_err(vk_error("vkEnumerateDeviceExtensionProperties"))?;
        let has_provoking = extensions.iter().any(|e| {
            e.extension_name_as_c_str()
                .is_ok_and(|n| n == ext::provoking_vertex::NAME)
        });
        let provoking_vertex_last = has_provoking && supported.provoking_vertex_last;
        if !provoking_vertex_last {
            return Err(Error::MissingFeature(
                "VK_EXT_provoking_vertex with provokingVertexLast (GL's flat shading takes the last vertex)"
                    .into(),
            ));
        }

        let mut info = describe(
            &props,
            &supported,
            timestamp_valid_bits,
            pipeline_statistics_query,
            provoking_vertex_last,
            instance.validation_enabled(),
        );
        // GL's glLineWidth and glPointSize, where the device has them.
        (info.wide_lines, info.large_points) = (supported.wide_lines, supported.large_points);
        info.clip_distance = supported.clip_distance;
        (info.fill_mode_non_solid, info.logic_op) = (supported.fill_mode_non_solid, supported.logic_op);
        info.geometry_shader = supported.geometry_shader;
        let has_line_rasterization = extensions.iter().any(|e| {
            e.extension_name_as_c_str()
                .is_ok_and(|n| n == ext::line_rasterization::NAME)
        });
        info.stippled_lines = has_line_rasterization && supported.stippled_lines;
        info.non_seamless_cube_map = supported.non_seamless_cube_map;

        let priorities = [1.0f32];
        let queues = [vk::DeviceQueueCreateInfo::default()
            .queue_family_index(queue_family)
            .queue_priorities(&priorities)];
        let mut extension_names = vec![ext::provoking_vertex::NAME.as_ptr()];
        if info.stippled_lines {
            extension_names.push(ext::line_rasterization::NAME.as_ptr());
        }
        if info.non_seamless_cube_map {
            extension_names.push(ext::non_seamless_cube_map::NAME.as_ptr());
        }
        let mut enable_non_seamless =
            vk::PhysicalDeviceNonSeamlessCubeMapFeaturesEXT::default().non_seamless_cube_map(true);
        let mut enable_lines = vk::PhysicalDeviceLineRasterizationFeaturesEXT::default()
            .bresenham_lines(info.stippled_lines)
            .stippled_bresenham_lines(info.stippled_lines);
        let mut enable_v13 = vk::PhysicalDeviceVulkan13Features::default()
            .dynamic_rendering(true)
            .synchronization2(true);
        let mut enable_provoking =
            vk::PhysicalDeviceProvokingVertexFeaturesEXT::default().provoking_vertex_last(true);
        let base = vk::PhysicalDeviceFeatures::default()
            .pipeline_statistics_query(pipeline_statistics_query)
            .wide_lines(supported.wide_lines)
            .large_points(supported.large_points)
            .shader_clip_distance(supported.clip_distance)
            .fill_mode_non_solid(supported.fill_mode_non_solid)
            .logic_op(supported.logic_op)
            .geometry_shader(supported.geometry_shader)
            .shader_tessellation_and_geometry_point_size(supported.geometry_shader);
        let mut create = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_extension_names(&extension_names)
            .enabled_features(&base)
            .push_next(&mut enable_v13)
            .push_next(&mut enable_provoking);
        if info.stippled_lines {
            create = create.push_next(&mut enable_lines);
        }
        if info.non_seamless_cube_map {
            create = create.push_next(&mut enable_non_seamless);
        }
        // SAFETY: the create info and everything it points to live until the call returns.
        let raw =
            unsafe { vki.create_device(physical, &create, None) }.map_err(vk_error("vkCreateDevice"))?;
        // SAFETY: the queue family and index 0 were requested above.
        let queue = unsafe { raw.get_device_queue(queue_family, 0) };

        let allocator = DeviceAllocator::own(vki, &raw, physical);
        let formats = FormatQuery::new(vki, physical);
        let own = OwnDevice {
            instance,
            queue,
            queue_family,
        };
        Device::assemble(
            raw,
            memory,
            &props,
            &supported,
            info,
            (Some(own), formats),
            allocator,
        )
    }

    /// Wraps a device the caller created and keeps: ffvk creates its objects on it and frees
    /// them, and never destroys the device, submits to its queues or waits on it. Fails with
    /// [`Error::NotEnabled`] when `enabled` lacks dynamic rendering, and with
    /// [`Error::MissingFeature`] when the device is older than Vulkan 1.3 or when `enabled`
    /// claims a feature the device does not support. The caller's instance asks for
    /// `apiVersion` 1.3 (ffvk records `vkCmdBeginRendering`'s pipelines and reads their
    /// 1.3 limits); `synchronization2` is the caller's own choice, ffvk records no barriers.
    ///
    /// # Safety
    ///
    /// `device` was created from `physical_device` of `instance` with the features `enabled`
    /// says, and stays alive until every ffvk object made from the returned `Arc` is dropped.
    pub unsafe fn from_caller(
        instance: &ash::Instance,
        physical_device: vk::PhysicalDevice,
        device: ash::Device,
        enabled: EnabledFeatures,
    ) -> Result<Arc<Self>> {
        // SAFETY: the caller's contract, passed on.
        unsafe { Device::wrap(instance, physical_device, device, enabled, None) }
    }

    /// [`Device::from_caller`] with the embedder's own gpu-allocator `Allocator` (made for the
    /// same device), which every ffvk buffer and image then takes its memory from: ffvk's
    /// allocations are named `ffvk: <what>` in its reports and all freed when their owners
    /// drop. Use [`crate::gpu_allocator`], the version ffvk was built with.
    ///
    /// # Safety
    ///
    /// As [`Device::from_caller`]; `allocator` was made for `device`.
    #[cfg(feature = "shared-allocator")]
    pub unsafe fn from_caller_with_allocator(
        instance: &ash::Instance,
        physical_device: vk::PhysicalDevice,
        device: ash::Device,
        enabled: EnabledFeatures,
        allocator: Arc<std::sync::Mutex<gpu_allocator::vulkan::Allocator>>,
    ) -> Result<Arc<Self>> {
        // SAFETY: the caller's contract, passed on.
        unsafe { Device::wrap(instance, physical_device, device, enabled, Some(allocator)) }
    }

    /// Both caller constructors.
    ///
    /// # Safety
    ///
    /// As [`Device::from_caller`].
    unsafe fn wrap(
        instance: &ash::Instance,
        physical_device: vk::PhysicalDevice,
        device: ash::Device,
        enabled: EnabledFeatures,
        shared: Option<Arc<std::sync::Mutex<gpu_allocator::vulkan::Allocator>>>,
    ) -> Result<Arc<Self>> {
        // SAFETY: the caller's contract: physical_device belongs to instance.
        let (props, memory) = unsafe {
            (
                instance.get_physical_device_properties(physical_device),
                instance.get_physical_device_memory_properties(physical_device),
            )
        };
        require_vulkan_1_3(&props)?;
        // SAFETY: the caller's contract: physical_device belongs to instance.
        let supported = unsafe { Supported::query(instance, physical_device) };
        if !enabled.dynamic_rendering {
            return Err(Error::NotEnabled {
                feature: "dynamicRendering",
                flag: "dynamic_rendering",
                needed_for: "every ffvk pipeline needs (they render without render passes)",
            });
        }
        if !supported.dynamic_rendering {
            return Err(Error::MissingFeature("dynamicRendering".into()));
        }
        if enabled.provoking_vertex_last && !supported.provoking_vertex_last {
            return Err(Error::MissingFeature(
                "VK_EXT_provoking_vertex with provokingVertexLast (EnabledFeatures::provoking_vertex_last says it is enabled)"
                    .into(),
            ));
        }
        for (claimed, has, name) in [
            (
                enabled.wide_lines,
                supported.wide_lines,
                "wideLines (EnabledFeatures::wide_lines says it is enabled)",
            ),
            (
                enabled.large_points,
                supported.large_points,
                "largePoints (EnabledFeatures::large_points says it is enabled)",
            ),
            (
                enabled.clip_distance,
                supported.clip_distance,
                "shaderClipDistance (EnabledFeatures::clip_distance says it is enabled)",
            ),
            (
                enabled.fill_mode_non_solid,
                supported.fill_mode_non_solid,
                "fillModeNonSolid (EnabledFeatures::fill_mode_non_solid says it is enabled)",
            ),
            (
                enabled.logic_op,
                supported.logic_op,
                "logicOp (EnabledFeatures::logic_op says it is enabled)",
            ),
            (
                enabled.geometry_shader,
                supported.geometry_shader,
                "geometryShader and shaderTessellationAndGeometryPointSize (EnabledFeatures::geometry_shader says they are enabled)",
            ),
            (
                enabled.stippled_lines,
                supported.stippled_lines,
                "VK_EXT_line_rasterization's bresenhamLines and stippledBresenhamLines (EnabledFeatures::stippled_lines says they are enabled)",
            ),
            (
                enabled.non_seamless_cube_map,
                supported.non_seamless_cube_map,
                "VK_EXT_non_seamless_cube_map's nonSeamlessCubeMap (EnabledFeatures::non_seamless_cube_map says it is enabled)",
            ),
        ] {
            if claimed && !has {
                return Err(Error::MissingFeature(name.into()));
            }
        }
        let mut info = describe(&props, &supported, 0, false, enabled.provoking_vertex_last, false);
        (info.wide_lines, info.large_points) = (enabled.wide_lines, enabled.large_points);
        info.clip_distance = enabled.clip_distance;
        (info.fill_mode_non_solid, info.logic_op, info.stippled_lines) = (
            enabled.fill_mode_non_solid,
            enabled.logic_op,
            enabled.stippled_lines,
        );
        info.geometry_shader = enabled.geometry_shader;
        info.non_seamless_cube_map = enabled.non_seamless_cube_map;
        let allocator = match shared {
            #[cfg(feature = "shared-allocator")]
            Some(shared) => Ok(DeviceAllocator::Shared(shared)),
            _ => DeviceAllocator::own(instance, &device, physical_device),
        };
        let formats = FormatQuery::new(instance, physical_device);
        Device::assemble(
            device,
            memory,
            &props,
            &supported,
            info,
            (None, formats),
            allocator,
        )
    }

    /// The device value of either constructor, with its allocator. A failed allocator
    /// destroys ffvk's own device again.
    fn assemble(
        raw: ash::Device,
        memory: vk::PhysicalDeviceMemoryProperties,
        props: &vk::PhysicalDeviceProperties,
        supported: &Supported,
        info: DeviceInfo,
        (own, formats): (Option<OwnDevice>, FormatQuery),
        allocator: Result<DeviceAllocator>,
    ) -> Result<Arc<Self>> {
        let allocator = match allocator {
            Ok(a) => a,
            Err(e) => {
                if own.is_some() {
                    // SAFETY: the device was just created by ffvk and has no children.
                    unsafe { raw.destroy_device(None) };
                }
                return Err(e);
            }
        };
        Ok(Arc::new(Device {
            raw,
            memory,
            limits: props.limits,
            allocator,
            books: Books::default(),
            max_memory_allocation_size: supported.max_memory_allocation_size,
            info,
            own,
            formats,
            recordings: std::sync::atomic::AtomicU64::new(0),
        }))
    }

    /// The features `format` has on this device (`vkGetPhysicalDeviceFormatProperties`).
    /// Callers pass only formats they have checked are core Vulkan formats, so that no unknown
    /// value reaches Vulkan.
    pub(crate) fn format_properties(&self, format: vk::Format) -> vk::FormatProperties {
        let mut properties = vk::FormatProperties::default();
        let FormatQuery { physical, get } = self.formats;
        // SAFETY: `get` was loaded from the instance `physical` belongs to, which outlives this
        // device (ffvk's own keeps it in `own`; a caller's by from_caller's contract), and
        // `properties` is writable.
        unsafe { get(physical, format, &mut properties) };
        properties
    }

    /// The instance and queue of ffvk's own device. Only the renderer submits, and it
    /// always opens its own device.
    pub(crate) fn own(&self) -> Result<&OwnDevice> {
        self.own.as_ref().ok_or(Error::Internal(
            "a caller's device was asked for ffvk's own queue",
        ))
    }

    /// What ffvk found out about the device when it opened it.
    pub fn info(&self) -> &DeviceInfo {
        &self.info
    }

    /// The allocator every buffer and image of this device takes its memory from.
    pub(crate) fn allocator(&self) -> &DeviceAllocator {
        &self.allocator
    }

    /// ffvk's books of its allocations on this device.
    pub(crate) fn books(&self) -> &Books {
        &self.books
    }

    /// For each use, the memory type gpu-allocator gives a small buffer of it (a probe
    /// allocation, freed at once; `None` where it gave none). What `ffvk info` prints.
    pub fn memory_choices(self: &Arc<Self>) -> Vec<(MemoryUse, Option<MemoryChoice>)> {
        MemoryUse::ALL
            .into_iter()
            .map(|usage| {
                let usages = vk::BufferUsageFlags::TRANSFER_SRC
                    | vk::BufferUsageFlags::TRANSFER_DST
                    | vk::BufferUsageFlags::VERTEX_BUFFER
                    | vk::BufferUsageFlags::UNIFORM_BUFFER;
                let probe = super::Buffer::new(self, "memory probe", 256, usages, usage).ok();
                let chosen = probe.map(|b| {
                    let flags = b.memory_flags();
                    let count = self.memory.memory_type_count.min(vk::MAX_MEMORY_TYPES as u32);
                    let index = (0..count)
                        .find(|&i| self.memory.memory_types[i as usize].property_flags == flags)
                        .unwrap_or(0);
                    let heap = self.memory.memory_types[index as usize].heap_index as usize;
                    MemoryChoice {
                        index,
                        flags,
                        heap_bytes: self.memory.memory_heaps[heap].size,
                    }
                });
                (usage, chosen)
            })
            .collect()
    }

    /// How much device memory ffvk holds on this device, and how much of it is in use.
    pub fn memory_usage(&self) -> MemoryUsage {
        self.allocator.usage(&self.books)
    }

    /// Waits until the device is idle.
    pub(crate) fn wait_idle(&self) -> Result<()> {
        // SAFETY: the device is alive; no other thread submits to its queue (the renderer
        // owns the only queue and takes &mut self to submit).
        unsafe { self.raw.device_wait_idle() }.map_err(vk_error("vkDeviceWaitIdle"))
    }
}

impl Drop for Device {
    fn drop(&mut self) {
        if self.own.is_some() {
            // SAFETY: the device is alive and every child holding an Arc of it is gone; no
            // submitted work may use the memory freed next.
            let _ = unsafe { self.raw.device_wait_idle() };
        }
        // Every allocation holds the device, so none is left, and their owners kept the GPU
        // off them before dropping them (on a caller's device, the caller's contract): the
        // blocks go back first, on the caller's device too.
        self.allocator.release();
        if self.own.is_none() {
            // The caller's device: the caller destroys it.
            return;
        }
        // SAFETY: every child holds an Arc<Device>, so none is left, and the device is idle
        // (waited for above).
        unsafe { self.raw.destroy_device(None) };
    }
}

/// What `ffvk info` shows of a physical device.
fn describe(
    props: &vk::PhysicalDeviceProperties,
    supported: &Supported,
    timestamp_valid_bits: u32,
    pipeline_statistics_query: bool,
    provoking_vertex_last: bool,
    validation: bool,
) -> DeviceInfo {
    DeviceInfo {
        name: device_name(props),
        device_type: format!("{:?}", props.device_type),
        driver_name: supported.driver_name.clone(),
        driver_info: supported.driver_info.clone(),
        api_version: version_string(props.api_version),
        vendor_id: props.vendor_id,
        device_id: props.device_id,
        max_image_dimension_2d: props.limits.max_image_dimension2_d,
        max_uniform_buffer_range: props.limits.max_uniform_buffer_range,
        min_uniform_buffer_offset_alignment: props.limits.min_uniform_buffer_offset_alignment,
        max_vertex_output_components: props.limits.max_vertex_output_components,
        timestamp_period_ns: props.limits.timestamp_period,
        timestamp_valid_bits,
        timestamps_supported: timestamp_valid_bits > 0,
        pipeline_statistics_query,
        provoking_vertex_last,
        wide_lines: false,
        large_points: false,
        clip_distance: false,
        fill_mode_non_solid: false,
        logic_op: false,
        geometry_shader: false,
        stippled_lines: false,
        non_seamless_cube_map: false,
        line_width_range: props.limits.line_width_range,
        point_size_range: props.limits.point_size_range,
        validation,
    }
}

/// ffvk's pipelines need Vulkan 1.3 (dynamic rendering, synchronization2 in core).
fn require_vulkan_1_3(props: &vk::PhysicalDeviceProperties) -> Result<()> {
    if props.api_version < vk::API_VERSION_1_3 {
        return Err(Error::MissingFeature(format!(
            "Vulkan 1.3 (the device offers {})",
            version_string(props.api_version)
        )));
    }
    Ok(())
}

pub(crate) fn version_string(v: u32) -> String {
    format!(
        "{}.{}.{}",
        vk::api_version_major(v),
        vk::api_version_minor(v),
        vk::api_version_patch(v)
    )
}

#[cfg(test)]
mod tests {
    use ash::vk;

    /// `DeviceInfo::is_cpu` compares with the text `describe` writes: ash's Debug spelling.
    #[test]
    fn the_cpu_device_type_is_spelled_as_is_cpu_expects() {
        assert_eq!(format!("{:?}", vk::PhysicalDeviceType::CPU), "CPU");
        assert_ne!(format!("{:?}", vk::PhysicalDeviceType::DISCRETE_GPU), "CPU");
    }
}
