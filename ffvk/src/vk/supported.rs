//! What a physical device supports of what ffvk uses ([`Supported`]).

use std::ffi::CStr;

use ash::{ext, vk};

/// What a physical device supports of what ffvk uses, and its driver's name and version.
pub(crate) struct Supported {
    pub(crate) dynamic_rendering: bool,
    pub(crate) synchronization2: bool,
    /// The feature bit only; the extension must be listed too.
    pub(crate) provoking_vertex_last: bool,
    pub(crate) pipeline_statistics_query: bool,
    pub(crate) wide_lines: bool,
    pub(crate) large_points: bool,
    pub(crate) clip_distance: bool,
    pub(crate) fill_mode_non_solid: bool,
    pub(crate) logic_op: bool,
    pub(crate) geometry_shader: bool,
    /// `bresenhamLines` and `stippledBresenhamLines` (the extension must be listed too).
    pub(crate) stippled_lines: bool,
    /// `VK_EXT_non_seamless_cube_map` listed, with `nonSeamlessCubeMap`.
    pub(crate) non_seamless_cube_map: bool,
    pub(crate) driver_name: String,
    pub(crate) driver_info: String,
    /// Vulkan 1.1's maxMemoryAllocationSize.
    pub(crate) max_memory_allocation_size: u64,
}

impl Supported {
    /// # Safety
    ///
    /// `physical` belongs to `instance`.
    pub(crate) unsafe fn query(instance: &ash::Instance, physical: vk::PhysicalDevice) -> Supported {
        let mut provoking = vk::PhysicalDeviceProvokingVertexFeaturesEXT::default();
        let mut v13 = vk::PhysicalDeviceVulkan13Features::default();
        let mut lines = vk::PhysicalDeviceLineRasterizationFeaturesEXT::default();
        // An extension's struct is chained only where the device lists the extension.
        // SAFETY: the caller vouches for the handle.
        let listed = unsafe { instance.enumerate_device_extension_properties(physical) }.unwrap_or_default();
        let has = |name: &std::ffi::CStr| listed.iter().any(|e| e.extension_name_as_c_str() == Ok(name));
        let mut non_seamless = vk::PhysicalDeviceNonSeamlessCubeMapFeaturesEXT::default();
        let mut features = vk::PhysicalDeviceFeatures2::default().push_next(&mut v13);
        if has(ext::non_seamless_cube_map::NAME) {
            features = features.push_next(&mut non_seamless);
        }
        if has(ext::provoking_vertex::NAME) {
            features = features.push_next(&mut provoking);
        }
        if has(ext::line_rasterization::NAME) {
            features = features.push_next(&mut lines);
        }
        let mut driver = vk::PhysicalDeviceDriverProperties::default();
        let mut v11 = vk::PhysicalDeviceVulkan11Properties::default();
        let mut props2 = vk::PhysicalDeviceProperties2::default()
            .push_next(&mut driver)
            .push_next(&mut v11);
        // SAFETY: the chained structs live until the calls return; the caller vouches for
        // the handle.
        unsafe {
            instance.get_physical_device_features2(physical, &mut features);
            instance.get_physical_device_properties2(physical, &mut props2);
        }
        let pipeline_statistics_query = features.features.pipeline_statistics_query == vk::TRUE;
        let wide_lines = features.features.wide_lines == vk::TRUE;
        let large_points = features.features.large_points == vk::TRUE;
        let clip_distance = features.features.shader_clip_distance == vk::TRUE;
        let fill_mode_non_solid = features.features.fill_mode_non_solid == vk::TRUE;
        let logic_op = features.features.logic_op == vk::TRUE;
        // Edge flags' geometry stage passes the point size on (polygons drawn as points).
        let geometry_shader = features.features.geometry_shader == vk::TRUE
            && features.features.shader_tessellation_and_geometry_point_size == vk::TRUE;
        let stippled_lines = lines.bresenham_lines == vk::TRUE && lines.stippled_bresenham_lines == vk::TRUE;
        let non_seamless_cube_map = non_seamless.non_seamless_cube_map == vk::TRUE;
        let cstr = |bytes: &[std::ffi::c_char]| {
            // SAFETY: the driver properties hold NUL-terminated strings within their arrays.
            unsafe { CStr::from_ptr(bytes.as_ptr()) }
                .to_string_lossy()
                .into_owned()
        };
        Supported {
            dynamic_rendering: v13.dynamic_rendering == vk::TRUE,
            synchronization2: v13.synchronization2 == vk::TRUE,
            provoking_vertex_last: provoking.provoking_vertex_last == vk::TRUE,
            pipeline_statistics_query,
            wide_lines,
            large_points,
            clip_distance,
            fill_mode_non_solid,
            logic_op,
            geometry_shader,
            stippled_lines,
            non_seamless_cube_map,
            driver_name: cstr(&driver.driver_name),
            driver_info: cstr(&driver.driver_info),
            max_memory_allocation_size: v11.max_memory_allocation_size,
        }
    }
}
