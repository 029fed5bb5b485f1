//! What a caller enables on its device for ffvk (`ffvkDeviceRequirements`): the features,
//! filled into the caller's own `VkPhysicalDeviceFeatures2` chain, and the extension names,
//! so that the device it creates and the `enabled_features` it tells the renderer agree.

use std::ffi::c_char;

use ffvk::ash::{self, ext, vk};

use crate::render::{
    FFVK_FEATURE_CLIP_DISTANCE, FFVK_FEATURE_DYNAMIC_RENDERING, FFVK_FEATURE_FILL_MODE_NON_SOLID,
    FFVK_FEATURE_GEOMETRY_SHADER, FFVK_FEATURE_LARGE_POINTS, FFVK_FEATURE_LOGIC_OP,
    FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP, FFVK_FEATURE_PROVOKING_VERTEX_LAST, FFVK_FEATURE_STIPPLED_LINES,
    FFVK_FEATURE_WIDE_LINES,
};
use crate::result::{check_ptr, fail, guard, misaligned, FfvkResult};
use crate::vk_types::*;

/// The most extension names `ffvkDeviceRequirements` ever lists, in this version and later
/// ones: room for this many is always enough.
pub const FFVK_MAX_DEVICE_EXTENSIONS: u32 = 4;

/// The longest `pNext` chain walked: a longer one is taken for a loop.
const MAX_CHAIN: usize = 64;

/// A struct of an extension's features in the caller's chain: the `pNext` field that points
/// at it (to take it out when the extension is not listed), the struct, and its `sType`.
type Linked = (
    *mut *mut vk::BaseOutStructure<'static>,
    *mut vk::BaseOutStructure<'static>,
    vk::StructureType,
);

/// The structs of the caller's chain that ffvk sets.
struct Chain {
    vulkan13: Vec<*mut vk::PhysicalDeviceVulkan13Features<'static>>,
    dynamic_rendering: Vec<*mut vk::PhysicalDeviceDynamicRenderingFeatures<'static>>,
    /// The provoking-vertex, line-rasterization and non-seamless cube map structs, in the
    /// chain's order.
    extension_structs: Vec<Linked>,
}

impl Chain {
    /// The structs of `s_type` among `extension_structs`.
    fn of<T>(&self, s_type: vk::StructureType) -> impl Iterator<Item = *mut T> + '_ {
        self.extension_structs
            .iter()
            .filter(move |e| e.2 == s_type)
            .map(|e| e.1.cast())
    }

    /// Whether the chain holds a struct of `s_type`.
    fn has(&self, s_type: vk::StructureType) -> bool {
        self.extension_structs.iter().any(|e| e.2 == s_type)
    }
}

const PROVOKING: vk::StructureType = vk::StructureType::PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT;
const LINES: vk::StructureType = vk::StructureType::PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT;
const NON_SEAMLESS: vk::StructureType = vk::StructureType::PHYSICAL_DEVICE_NON_SEAMLESS_CUBE_MAP_FEATURES_EXT;

/// Walks `features`' `pNext` chain, reading only `sType` and `pNext` of each struct.
///
/// # Safety
///
/// `features` is a valid `VkPhysicalDeviceFeatures2` whose chain holds valid structs.
unsafe fn walk(
    function: &str,
    features: *mut vk::PhysicalDeviceFeatures2<'static>,
) -> Result<Chain, FfvkResult> {
    let mut chain = Chain {
        vulkan13: Vec::new(),
        dynamic_rendering: Vec::new(),
        extension_structs: Vec::new(),
    };
    // SAFETY: the caller's contract: a valid struct; its p_next is the chain's first link.
    let mut link: *mut *mut vk::BaseOutStructure<'static> = unsafe { (&raw mut (*features).p_next).cast() };
    for depth in 0.. {
        // SAFETY: link points at a pNext field of a struct of the chain.
        let node = unsafe { *link };
        if node.is_null() {
            break;
        }
        if depth == MAX_CHAIN {
            return Err(fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{function}: features' pNext chain is longer than {MAX_CHAIN} structs: expected a chain that ends (does it loop?)"),
            ));
        }
        if misaligned(node) {
            return Err(fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!(
                    "{function}: struct {depth} of features' pNext chain, {node:p}, is not aligned to {} bytes: expected Vulkan structs",
                    std::mem::align_of::<vk::BaseOutStructure>()
                ),
            ));
        }
        // SAFETY: a non-null, aligned struct of the caller's chain, which starts with sType.
        let s_type = unsafe { (*node).s_type };
        match s_type {
            vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES => chain.vulkan13.push(node.cast()),
            vk::StructureType::PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES => {
                chain.dynamic_rendering.push(node.cast())
            }
            PROVOKING | LINES | NON_SEAMLESS => chain.extension_structs.push((link, node, s_type)),
            _ => {}
        }
        // SAFETY: as above; pNext follows sType in every Vulkan struct.
        link = unsafe { &raw mut (*node).p_next };
    }
    Ok(chain)
}

/// What the device supports of what ffvk uses.
struct Support {
    api_version: u32,
    dynamic_rendering: bool,
    /// `VK_EXT_provoking_vertex` listed and `provokingVertexLast` supported.
    provoking_vertex_last: bool,
    /// The extension alone (its feature may still be missing).
    provoking_extension: bool,
    wide_lines: bool,
    large_points: bool,
    clip_distance: bool,
    fill_mode_non_solid: bool,
    logic_op: bool,
    geometry_shader: bool,
    /// `VK_EXT_line_rasterization` listed, with `bresenhamLines` and `stippledBresenhamLines`.
    stippled_lines: bool,
    /// The extension alone.
    lines_extension: bool,
    /// Which of the two line features the device lacks, if it has the extension.
    lines_lacking: &'static str,
    /// `VK_EXT_non_seamless_cube_map` listed, with `nonSeamlessCubeMap`.
    non_seamless_cube_map: bool,
    /// The extension alone.
    non_seamless_extension: bool,
}

/// Asks the device what it supports.
///
/// # Safety
///
/// `physical_device` belongs to `instance`, whose instance API is 1.1 or later.
unsafe fn query(
    function: &str,
    instance: &ash::Instance,
    physical_device: vk::PhysicalDevice,
) -> Result<Support, FfvkResult> {
    // SAFETY: the caller's contract.
    let props = unsafe { instance.get_physical_device_properties(physical_device) };
    // SAFETY: as above.
    let extensions =
        unsafe { instance.enumerate_device_extension_properties(physical_device) }.map_err(|e| {
            fail(
                FfvkResult::FFVK_ERROR_VULKAN,
                format!("{function}: vkEnumerateDeviceExtensionProperties failed: {e}"),
            )
        })?;
    let listed = |name| extensions.iter().any(|e| e.extension_name_as_c_str() == Ok(name));
    let provoking_extension = listed(ext::provoking_vertex::NAME);
    let lines_extension = listed(ext::line_rasterization::NAME);
    let non_seamless_extension = listed(ext::non_seamless_cube_map::NAME);
    let mut v13 = vk::PhysicalDeviceVulkan13Features::default();
    let mut provoking = vk::PhysicalDeviceProvokingVertexFeaturesEXT::default();
    let mut lines = vk::PhysicalDeviceLineRasterizationFeaturesEXT::default();
    let mut non_seamless = vk::PhysicalDeviceNonSeamlessCubeMapFeaturesEXT::default();
    let mut features = vk::PhysicalDeviceFeatures2::default().push_next(&mut v13);
    // Each extension's struct chained only when the device has the extension, as Vulkan
    // requires.
    if provoking_extension {
        features = features.push_next(&mut provoking);
    }
    if lines_extension {
        features = features.push_next(&mut lines);
    }
    if non_seamless_extension {
        features = features.push_next(&mut non_seamless);
    }
    // SAFETY: the chained structs live until the call returns; the caller's contract.
    unsafe { instance.get_physical_device_features2(physical_device, &mut features) };
    let base = features.features;
    let (wide_lines, large_points) = (base.wide_lines, base.large_points);
    let clip_distance = base.shader_clip_distance == vk::TRUE;
    let (bresenham, stippled) = (
        lines.bresenham_lines == vk::TRUE,
        lines.stippled_bresenham_lines == vk::TRUE,
    );
    let lines_lacking = match (bresenham, stippled) {
        (false, false) => "bresenhamLines and stippledBresenhamLines",
        (false, true) => "bresenhamLines",
        (true, false) => "stippledBresenhamLines",
        (true, true) => "",
    };
    Ok(Support {
        api_version: props.api_version,
        dynamic_rendering: v13.dynamic_rendering == vk::TRUE,
        provoking_vertex_last: provoking_extension && provoking.provoking_vertex_last == vk::TRUE,
        provoking_extension,
        wide_lines: wide_lines == vk::TRUE,
        large_points: large_points == vk::TRUE,
        clip_distance,
        fill_mode_non_solid: base.fill_mode_non_solid == vk::TRUE,
        logic_op: base.logic_op == vk::TRUE,
        geometry_shader: base.geometry_shader == vk::TRUE
            && base.shader_tessellation_and_geometry_point_size == vk::TRUE,
        stippled_lines: lines_extension && bresenham && stippled,
        lines_extension,
        lines_lacking,
        non_seamless_cube_map: non_seamless_extension && non_seamless.non_seamless_cube_map == vk::TRUE,
        non_seamless_extension,
    })
}

/// Tells the caller what to enable on the device it is about to create for ffvk, and fills it
/// in: call it after choosing `physical_device` and before `vkCreateDevice`, with the
/// `VkPhysicalDeviceFeatures2` (sType `VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2`) whose
/// chain the caller then passes as `VkDeviceCreateInfo::pNext` (with `pEnabledFeatures` null),
/// and its own features already set in it. ffvk only sets features to `VK_TRUE`, never clears
/// one:
///
/// - `dynamicRendering` (required) in the chain's `VkPhysicalDeviceVulkan13Features` (or
///   `VkPhysicalDeviceDynamicRenderingFeatures`): the chain must hold one of them;
/// - `provokingVertexLast` in a `VkPhysicalDeviceProvokingVertexFeaturesEXT` of the chain, when
///   the device supports it (`GL_FLAT` needs it), with `VK_EXT_provoking_vertex` listed. Chain
///   one whatever the device: where the device lacks the extension or the feature, ffvk takes
///   the struct out of the chain (Vulkan forbids the struct of an extension not enabled);
/// - `wideLines` and `largePoints` in `features->features`, where supported (line widths and
///   point sizes other than 1);
/// - `shaderClipDistance` in `features->features`, where supported (draws with a user clip
///   plane enabled);
/// - `fillModeNonSolid`, `logicOp`, and `geometryShader` with
///   `shaderTessellationAndGeometryPointSize`, in `features->features`, where supported (polygon
///   modes `GL_LINE` and `GL_POINT`; `GL_COLOR_LOGIC_OP`; GL's edge flags, draws of
///   `GL_TRIANGLES_ADJACENCY`);
/// - `bresenhamLines` and `stippledBresenhamLines` in a `VkPhysicalDeviceLineRasterizationFeaturesEXT`
///   of the chain, when the device supports both (`GL_LINE_STIPPLE` needs them, and with them
///   every line is GL's aliased line), with `VK_EXT_line_rasterization` listed. As with the
///   provoking-vertex struct, chain one whatever the device: ffvk takes it out of the chain
///   where the device lacks the extension or either feature;
/// - `nonSeamlessCubeMap` in a `VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT` of the chain,
///   when the device supports it, with `VK_EXT_non_seamless_cube_map` listed
///   (`FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP`: the caller's cube map samplers may then take
///   `VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT`, filtering each face on its own as GL 2.1
///   does). Chain one whatever the device, as above: ffvk takes it out of the chain where the
///   device lacks the extension or the feature.
///
/// `extension_names` receives the extensions to enable (static strings, valid for the life of
/// the program), to be appended to the caller's own: `*extension_count` is, on the way in, the
/// room at `extension_names`, and on the way out how many names ffvk needs (never more than
/// `FFVK_MAX_DEVICE_EXTENSIONS`). With `extension_names` null, only the counts and
/// `*enabled_features` are written (nothing else changes). `*enabled_features` receives the
/// `FFVK_FEATURE_*` bits the created device will have: what `FfvkRendererCreateInfo::
/// enabled_features` then says. On success, `ffvkResultMessage()` says which optional features
/// are missing, why, and what ffvk refuses without them (`""` when none is).
///
/// Errors: `FFVK_ERROR_INVALID_ARGUMENT` (a null or misaligned pointer or handle, `features`
/// not a `VkPhysicalDeviceFeatures2`, a chain without a struct for `dynamicRendering`, a chain
/// of more than 64 structs, room for fewer names than needed: `*extension_count` then says how
/// many, and nothing else changes); `FFVK_ERROR_MISSING_FEATURE` (a device older than Vulkan
/// 1.3 or without `dynamicRendering`: nothing changes); `FFVK_ERROR_VULKAN` (listing the
/// device's extensions failed).
///
/// # Safety
///
/// `get_instance_proc_addr` is the caller's loader entry point, `instance` a live instance
/// created with `apiVersion` 1.3 or later and `physical_device` one of its devices; `features`
/// is null or a valid, writable `VkPhysicalDeviceFeatures2` whose `pNext` chain holds valid,
/// writable Vulkan structs; `extension_count` and `enabled_features` are null or writable;
/// `extension_names` is null or has room for `*extension_count` pointers.
#[no_mangle]
pub unsafe extern "C" fn ffvkDeviceRequirements(
    get_instance_proc_addr: PFN_vkGetInstanceProcAddr,
    instance: VkInstance,
    physical_device: VkPhysicalDevice,
    features: *mut VkPhysicalDeviceFeatures2,
    extension_count: *mut u32,
    extension_names: *mut *const c_char,
    enabled_features: *mut u32,
) -> FfvkResult {
    const F: &str = "ffvkDeviceRequirements";
    guard(|| {
        let checked = check_ptr(F, "features", features, "the VkPhysicalDeviceFeatures2 to fill")
            .and_then(|()| {
                check_ptr(
                    F,
                    "extension_count",
                    extension_count,
                    "the room at extension_names",
                )
            })
            .and_then(|()| {
                check_ptr(
                    F,
                    "enabled_features",
                    enabled_features,
                    "where to write FFVK_FEATURE_* bits",
                )
            });
        let checked = if extension_names.is_null() {
            checked
        } else {
            checked.and_then(|()| {
                check_ptr(
                    F,
                    "extension_names",
                    extension_names,
                    "room for *extension_count names, or null",
                )
            })
        };
        if let Err(code) = checked {
            return code;
        }
        let Some(get_instance_proc_addr) = get_instance_proc_addr else {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{F}: get_instance_proc_addr is null: expected the caller's vkGetInstanceProcAddr"),
            );
        };
        if instance == vk::Instance::null() || physical_device == vk::PhysicalDevice::null() {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{F}: instance or physical_device is VK_NULL_HANDLE: expected the caller's instance and the device it chose"),
            );
        }
        // SAFETY: checked non-null and aligned; the caller's contract: a valid struct.
        let s_type = unsafe { (*features).s_type };
        if s_type != vk::StructureType::PHYSICAL_DEVICE_FEATURES_2 {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!(
                    "{F}: features->sType is {}: expected VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2 ({})",
                    s_type.as_raw(),
                    vk::StructureType::PHYSICAL_DEVICE_FEATURES_2.as_raw()
                ),
            );
        }
        // SAFETY: the caller's contract: a valid chain.
        let chain = match unsafe { walk(F, features.cast()) } {
            Ok(chain) => chain,
            Err(code) => return code,
        };
        if chain.vulkan13.is_empty() && chain.dynamic_rendering.is_empty() {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{F}: features' pNext chain has no VkPhysicalDeviceVulkan13Features (nor VkPhysicalDeviceDynamicRenderingFeatures): expected one, where ffvk sets dynamicRendering"),
            );
        }

        let static_fn = ash::StaticFn {
            get_instance_proc_addr,
        };
        // SAFETY: the caller's contract: its loader and a live instance; this loads pointers only.
        let loaded = unsafe { ash::Instance::load(&static_fn, instance) };
        // SAFETY: the caller's contract: physical_device is the instance's, API 1.3.
        let support = match unsafe { query(F, &loaded, physical_device) } {
            Ok(support) => support,
            Err(code) => return code,
        };
        let (major, minor) = (
            vk::api_version_major(support.api_version),
            vk::api_version_minor(support.api_version),
        );
        if (major, minor) < (1, 3) {
            return fail(
                FfvkResult::FFVK_ERROR_MISSING_FEATURE,
                format!("{F}: the device supports Vulkan {major}.{minor}: ffvk needs Vulkan 1.3 (dynamic rendering)"),
            );
        }
        if !support.dynamic_rendering {
            return fail(
                FfvkResult::FFVK_ERROR_MISSING_FEATURE,
                format!("{F}: the device lacks dynamicRendering, which every ffvk pipeline needs"),
            );
        }

        let mut bits = FFVK_FEATURE_DYNAMIC_RENDERING;
        let mut missing = Vec::new();
        let provoking = support.provoking_vertex_last && chain.has(PROVOKING);
        if provoking {
            bits |= FFVK_FEATURE_PROVOKING_VERTEX_LAST;
        } else {
            let why = if !support.provoking_extension {
                "the device lacks VK_EXT_provoking_vertex"
            } else if !support.provoking_vertex_last {
                "the device lacks provokingVertexLast"
            } else {
                "features' pNext chain has no VkPhysicalDeviceProvokingVertexFeaturesEXT to set it in"
            };
            missing.push(format!(
                "FFVK_FEATURE_PROVOKING_VERTEX_LAST ({why}; GL_FLAT draws are refused)"
            ));
        }
        if support.wide_lines {
            bits |= FFVK_FEATURE_WIDE_LINES;
        } else {
            missing.push(
                "FFVK_FEATURE_WIDE_LINES (the device lacks wideLines; line widths other than 1 are refused)"
                    .into(),
            );
        }
        if support.large_points {
            bits |= FFVK_FEATURE_LARGE_POINTS;
        } else {
            missing.push("FFVK_FEATURE_LARGE_POINTS (the device lacks largePoints; point sizes other than 1 are refused)".into());
        }
        if support.clip_distance {
            bits |= FFVK_FEATURE_CLIP_DISTANCE;
        } else {
            missing.push(
                "FFVK_FEATURE_CLIP_DISTANCE (the device lacks shaderClipDistance; draws with user clip planes are refused)"
                    .into(),
            );
        }
        if support.fill_mode_non_solid {
            bits |= FFVK_FEATURE_FILL_MODE_NON_SOLID;
        } else {
            missing.push("FFVK_FEATURE_FILL_MODE_NON_SOLID (the device lacks fillModeNonSolid; polygon modes GL_LINE and GL_POINT are refused)".into());
        }
        if support.geometry_shader {
            bits |= FFVK_FEATURE_GEOMETRY_SHADER;
        } else {
            missing.push("FFVK_FEATURE_GEOMETRY_SHADER (the device lacks geometryShader or shaderTessellationAndGeometryPointSize; draws of GL_TRIANGLES_ADJACENCY, GL's edge flags, are refused)".into());
        }
        if support.logic_op {
            bits |= FFVK_FEATURE_LOGIC_OP;
        } else {
            missing.push(
                "FFVK_FEATURE_LOGIC_OP (the device lacks logicOp; draws with GL_COLOR_LOGIC_OP are refused)"
                    .into(),
            );
        }
        let stippled = support.stippled_lines && chain.has(LINES);
        if stippled {
            bits |= FFVK_FEATURE_STIPPLED_LINES;
        } else {
            let why = if !support.lines_extension {
                "the device lacks VK_EXT_line_rasterization".to_owned()
            } else if !support.stippled_lines {
                format!("the device lacks {}", support.lines_lacking)
            } else {
                "features' pNext chain has no VkPhysicalDeviceLineRasterizationFeaturesEXT to set them in"
                    .to_owned()
            };
            missing.push(format!("FFVK_FEATURE_STIPPLED_LINES ({why}; draws with GL_LINE_STIPPLE are refused, and lines are the device's own, not GL's aliased lines)"));
        }
        let non_seamless = support.non_seamless_cube_map && chain.has(NON_SEAMLESS);
        if non_seamless {
            bits |= FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP;
        } else {
            let why = if !support.non_seamless_extension {
                "the device lacks VK_EXT_non_seamless_cube_map"
            } else if !support.non_seamless_cube_map {
                "the device lacks nonSeamlessCubeMap"
            } else {
                "features' pNext chain has no VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT to set it in"
            };
            missing.push(format!("FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP ({why}; cube map samplers filter across the faces' edges, where GL 2.1 filters each face on its own)"));
        }
        let mut names: Vec<&'static std::ffi::CStr> = Vec::new();
        if provoking {
            names.push(ext::provoking_vertex::NAME);
        }
        if stippled {
            names.push(ext::line_rasterization::NAME);
        }
        if non_seamless {
            names.push(ext::non_seamless_cube_map::NAME);
        }
        debug_assert!(names.len() <= FFVK_MAX_DEVICE_EXTENSIONS as usize);
        let needed = names.len() as u32;
        let message = if missing.is_empty() {
            String::new()
        } else {
            format!("{F}: without {}", missing.join(", without "))
        };

        // SAFETY: checked non-null and aligned; readable and writable by the caller's contract.
        let room = unsafe { extension_count.replace(needed) };
        // SAFETY: as above.
        unsafe { enabled_features.write(bits) };
        if extension_names.is_null() {
            return fail(FfvkResult::FFVK_SUCCESS, message);
        }
        if room < needed {
            return fail(
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                format!("{F}: *extension_count is {room}: expected room for {needed} extension name(s) (*extension_count now says how many)"),
            );
        }
        for (i, name) in names.iter().enumerate() {
            // SAFETY: room for `room` >= needed pointers (the caller's contract).
            unsafe { extension_names.add(i).write(name.as_ptr()) };
        }
        // SAFETY: each pointer came from the walk of the caller's writable chain.
        unsafe {
            for &s in &chain.vulkan13 {
                (*s).dynamic_rendering = vk::TRUE;
            }
            for &s in &chain.dynamic_rendering {
                (*s).dynamic_rendering = vk::TRUE;
            }
            if provoking {
                for s in chain.of::<vk::PhysicalDeviceProvokingVertexFeaturesEXT>(PROVOKING) {
                    (*s).provoking_vertex_last = vk::TRUE;
                }
            }
            if stippled {
                for s in chain.of::<vk::PhysicalDeviceLineRasterizationFeaturesEXT>(LINES) {
                    (*s).bresenham_lines = vk::TRUE;
                    (*s).stippled_bresenham_lines = vk::TRUE;
                }
            }
            if non_seamless {
                for s in chain.of::<vk::PhysicalDeviceNonSeamlessCubeMapFeaturesEXT>(NON_SEAMLESS) {
                    (*s).non_seamless_cube_map = vk::TRUE;
                }
            }
            // The struct of an extension not listed may not be chained. Unlinked last first
            // (of every kind together), so that each link still points at its struct.
            for &(link, s, s_type) in chain.extension_structs.iter().rev() {
                let listed = match s_type {
                    PROVOKING => provoking,
                    LINES => stippled,
                    _ => non_seamless,
                };
                if !listed {
                    *link = (*s).p_next;
                }
            }
            if support.wide_lines {
                (*features).features.wide_lines = vk::TRUE;
            }
            if support.large_points {
                (*features).features.large_points = vk::TRUE;
            }
            if support.clip_distance {
                (*features).features.shader_clip_distance = vk::TRUE;
            }
            if support.fill_mode_non_solid {
                (*features).features.fill_mode_non_solid = vk::TRUE;
            }
            if support.logic_op {
                (*features).features.logic_op = vk::TRUE;
            }
            if support.geometry_shader {
                (*features).features.geometry_shader = vk::TRUE;
                (*features).features.shader_tessellation_and_geometry_point_size = vk::TRUE;
            }
        }
        fail(FfvkResult::FFVK_SUCCESS, message)
    })
}
