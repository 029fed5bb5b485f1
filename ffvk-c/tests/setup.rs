//! `ffvkDeviceRequirements` against devices made up here: a loader whose
//! `vkGetPhysicalDeviceProperties`, `vkEnumerateDeviceExtensionProperties` and
//! `vkGetPhysicalDeviceFeatures2` answer as the test's device says, so that every answer a
//! real device could give (no Vulkan 1.3, no dynamic rendering, no provoking-vertex or
//! line-rasterization extension, an extension without its features, no wide lines, no polygon
//! modes, no logic ops) is asked. What ffvk fills in, lists and
//! says is checked; nothing is created.

use std::cell::Cell;
use std::ffi::{c_char, CStr};
use std::ptr::{null, null_mut};

use ffvk::ash::vk::{self, Handle};
use ffvk_c::render::*;
use ffvk_c::result::{ffvkResultMessage, FfvkResult};
use ffvk_c::setup::*;

/// What the made-up device supports.
#[derive(Clone, Copy)]
struct Device {
    api_version: u32,
    dynamic_rendering: bool,
    provoking_extension: bool,
    provoking_vertex_last: bool,
    wide_lines: bool,
    large_points: bool,
    clip_distance: bool,
    fill_mode_non_solid: bool,
    logic_op: bool,
    geometry_shader: bool,
    lines_extension: bool,
    bresenham_lines: bool,
    stippled_bresenham_lines: bool,
    non_seamless_extension: bool,
    non_seamless_cube_map: bool,
}

const FULL: Device = Device {
    api_version: vk::API_VERSION_1_3,
    dynamic_rendering: true,
    provoking_extension: true,
    provoking_vertex_last: true,
    wide_lines: true,
    large_points: true,
    clip_distance: true,
    fill_mode_non_solid: true,
    logic_op: true,
    geometry_shader: true,
    lines_extension: true,
    bresenham_lines: true,
    stippled_bresenham_lines: true,
    non_seamless_extension: true,
    non_seamless_cube_map: true,
};

thread_local! {
    /// The device this thread's test asks about (each test runs on a thread of its own).
    static DEVICE: Cell<Device> = const { Cell::new(FULL) };
}

fn bool32(b: bool) -> vk::Bool32 {
    b as vk::Bool32
}

unsafe extern "system" fn get_properties(_: vk::PhysicalDevice, props: *mut vk::PhysicalDeviceProperties) {
    let p = vk::PhysicalDeviceProperties {
        api_version: DEVICE.get().api_version,
        ..Default::default()
    };
    // SAFETY: ffvk passes a writable struct.
    unsafe { props.write(p) };
}

unsafe extern "system" fn enumerate_extensions(
    _: vk::PhysicalDevice,
    _: *const c_char,
    count: *mut u32,
    properties: *mut vk::ExtensionProperties,
) -> vk::Result {
    let d = DEVICE.get();
    let names: Vec<&CStr> = [
        (d.provoking_extension, c"VK_EXT_provoking_vertex"),
        (d.lines_extension, c"VK_EXT_line_rasterization"),
        (d.non_seamless_extension, c"VK_EXT_non_seamless_cube_map"),
    ]
    .into_iter()
    .filter_map(|(has, name)| has.then_some(name))
    .collect();
    // SAFETY: Vulkan's two-call contract, which ash follows: count is writable, properties
    // null or room for *count.
    unsafe {
        if properties.is_null() {
            *count = names.len() as u32;
            return vk::Result::SUCCESS;
        }
        let written = names.len().min(*count as usize);
        for (i, name) in names[..written].iter().enumerate() {
            let mut p = vk::ExtensionProperties::default();
            for (dst, &src) in p.extension_name.iter_mut().zip(name.to_bytes_with_nul()) {
                *dst = src as c_char;
            }
            properties.add(i).write(p);
        }
        *count = written as u32;
        if written < names.len() {
            return vk::Result::INCOMPLETE;
        }
    }
    vk::Result::SUCCESS
}

unsafe extern "system" fn get_features2(_: vk::PhysicalDevice, features: *mut vk::PhysicalDeviceFeatures2) {
    let d = DEVICE.get();
    // SAFETY: ffvk passes a valid chain of writable structs.
    unsafe {
        (*features).features.wide_lines = bool32(d.wide_lines);
        (*features).features.large_points = bool32(d.large_points);
        (*features).features.shader_clip_distance = bool32(d.clip_distance);
        (*features).features.fill_mode_non_solid = bool32(d.fill_mode_non_solid);
        (*features).features.logic_op = bool32(d.logic_op);
        (*features).features.geometry_shader = bool32(d.geometry_shader);
        (*features).features.shader_tessellation_and_geometry_point_size = bool32(d.geometry_shader);
        let mut node = (*features).p_next.cast::<vk::BaseOutStructure>();
        while !node.is_null() {
            match (*node).s_type {
                vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES => {
                    (*node.cast::<vk::PhysicalDeviceVulkan13Features>()).dynamic_rendering =
                        bool32(d.dynamic_rendering)
                }
                vk::StructureType::PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT => {
                    assert!(d.provoking_extension, "the extension's struct chained without it");
                    (*node.cast::<vk::PhysicalDeviceProvokingVertexFeaturesEXT>()).provoking_vertex_last =
                        bool32(d.provoking_vertex_last)
                }
                vk::StructureType::PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT => {
                    assert!(d.lines_extension, "the extension's struct chained without it");
                    let lines = node.cast::<vk::PhysicalDeviceLineRasterizationFeaturesEXT>();
                    (*lines).bresenham_lines = bool32(d.bresenham_lines);
                    (*lines).stippled_bresenham_lines = bool32(d.stippled_bresenham_lines);
                }
                vk::StructureType::PHYSICAL_DEVICE_NON_SEAMLESS_CUBE_MAP_FEATURES_EXT => {
                    assert!(
                        d.non_seamless_extension,
                        "the extension's struct chained without it"
                    );
                    (*node.cast::<vk::PhysicalDeviceNonSeamlessCubeMapFeaturesEXT>()).non_seamless_cube_map =
                        bool32(d.non_seamless_cube_map)
                }
                _ => {}
            }
            node = (*node).p_next;
        }
    }
}

/// The made-up loader: the three functions above, nothing else.
unsafe extern "system" fn loader(_: vk::Instance, name: *const c_char) -> vk::PFN_vkVoidFunction {
    // SAFETY: ash passes NUL-terminated names.
    let name = unsafe { CStr::from_ptr(name) };
    // SAFETY: each is the function Vulkan's loader would return for the name, with its
    // signature; the caller casts it back to that signature.
    unsafe {
        match name.to_bytes() {
            b"vkGetPhysicalDeviceProperties" => Some(std::mem::transmute::<
                unsafe extern "system" fn(vk::PhysicalDevice, *mut vk::PhysicalDeviceProperties),
                unsafe extern "system" fn(),
            >(get_properties)),
            b"vkEnumerateDeviceExtensionProperties" => Some(std::mem::transmute::<
                unsafe extern "system" fn(
                    vk::PhysicalDevice,
                    *const c_char,
                    *mut u32,
                    *mut vk::ExtensionProperties,
                ) -> vk::Result,
                unsafe extern "system" fn(),
            >(enumerate_extensions)),
            b"vkGetPhysicalDeviceFeatures2" => Some(std::mem::transmute::<
                unsafe extern "system" fn(vk::PhysicalDevice, *mut vk::PhysicalDeviceFeatures2),
                unsafe extern "system" fn(),
            >(get_features2)),
            _ => None,
        }
    }
}

fn message() -> String {
    // SAFETY: never null; copied at once.
    unsafe { CStr::from_ptr(ffvkResultMessage()) }
        .to_string_lossy()
        .into_owned()
}

/// A caller's chain: features2 → Vulkan 1.3 → (provoking vertex) → (line rasterization), all
/// features off but the caller's own synchronization2.
struct Chain {
    features: vk::PhysicalDeviceFeatures2<'static>,
    v13: vk::PhysicalDeviceVulkan13Features<'static>,
    provoking: vk::PhysicalDeviceProvokingVertexFeaturesEXT<'static>,
    lines: vk::PhysicalDeviceLineRasterizationFeaturesEXT<'static>,
    /// Chained only by [`Chain::with_non_seamless`].
    non_seamless: vk::PhysicalDeviceNonSeamlessCubeMapFeaturesEXT<'static>,
}

impl Chain {
    /// With both extensions' structs (`extensions`) or neither.
    fn new(extensions: bool) -> Box<Chain> {
        Chain::with(extensions, extensions)
    }

    /// With the provoking-vertex struct when `provoking`, the line-rasterization one when
    /// `lines`.
    fn with(provoking: bool, lines: bool) -> Box<Chain> {
        let mut chain = Box::new(Chain {
            features: vk::PhysicalDeviceFeatures2::default(),
            v13: vk::PhysicalDeviceVulkan13Features::default(),
            provoking: vk::PhysicalDeviceProvokingVertexFeaturesEXT::default(),
            lines: vk::PhysicalDeviceLineRasterizationFeaturesEXT::default(),
            non_seamless: vk::PhysicalDeviceNonSeamlessCubeMapFeaturesEXT::default(),
        });
        chain.v13.synchronization2 = vk::TRUE;
        chain.features.p_next = (&raw mut chain.v13).cast();
        let mut last: *mut *mut std::ffi::c_void = &raw mut chain.v13.p_next;
        if provoking {
            // SAFETY: last points at a pNext field of the boxed chain.
            unsafe { *last = (&raw mut chain.provoking).cast() };
            last = &raw mut chain.provoking.p_next;
        }
        if lines {
            // SAFETY: as above.
            unsafe { *last = (&raw mut chain.lines).cast() };
        }
        chain
    }

    /// The chain with the non-seamless cube map struct appended at its end.
    fn with_non_seamless(mut self: Box<Chain>) -> Box<Chain> {
        let mut last: *mut *mut std::ffi::c_void = &raw mut self.features.p_next;
        // SAFETY: each pNext of the boxed chain is null or points at a struct of it.
        unsafe {
            while !(*last).is_null() {
                last = (&raw mut (*(*last).cast::<vk::BaseOutStructure>()).p_next).cast();
            }
            *last = (&raw mut self.non_seamless).cast();
        }
        self
    }

    /// The sTypes along the chain, from features2's pNext.
    fn types(&self) -> Vec<vk::StructureType> {
        let mut types = Vec::new();
        let mut node = self.features.p_next.cast::<vk::BaseOutStructure>().cast_const();
        while !node.is_null() {
            // SAFETY: the chain's structs live in self.
            unsafe {
                types.push((*node).s_type);
                node = (*node).p_next;
            }
        }
        types
    }

    /// Whether any feature is on besides the caller's synchronization2.
    fn untouched(&self) -> bool {
        self.v13.dynamic_rendering == vk::FALSE
            && self.v13.synchronization2 == vk::TRUE
            && self.provoking.provoking_vertex_last == vk::FALSE
            && self.features.features.wide_lines == vk::FALSE
            && self.features.features.large_points == vk::FALSE
            && self.features.features.shader_clip_distance == vk::FALSE
            && self.features.features.fill_mode_non_solid == vk::FALSE
            && self.features.features.logic_op == vk::FALSE
            && self.features.features.geometry_shader == vk::FALSE
            && self.lines.bresenham_lines == vk::FALSE
            && self.lines.stippled_bresenham_lines == vk::FALSE
            && self.non_seamless.non_seamless_cube_map == vk::FALSE
    }
}

/// What one call returned and wrote.
struct Answer {
    result: FfvkResult,
    names: Vec<String>,
    count: u32,
    bits: u32,
    message: String,
}

/// `ffvkDeviceRequirements` on `device` with room for `room` names (`None`: a size query).
fn ask(device: Device, chain: &mut Chain, room: Option<u32>) -> Answer {
    DEVICE.set(device);
    let mut names = [null::<c_char>(); 8];
    let mut count = room.unwrap_or(0);
    let mut bits = 0xDEAD;
    let names_ptr = if room.is_some() {
        names.as_mut_ptr()
    } else {
        null_mut()
    };
    // SAFETY: the loader answers for any handle; the chain is valid and writable; names has
    // room for 8 >= room.
    let result = unsafe {
        ffvkDeviceRequirements(
            Some(loader),
            vk::Instance::from_raw(0x10),
            vk::PhysicalDevice::from_raw(0x20),
            &mut chain.features,
            &mut count,
            names_ptr,
            &mut bits,
        )
    };
    let listed = names[..count.min(8) as usize]
        .iter()
        .filter(|n| !n.is_null())
        // SAFETY: ffvk writes static NUL-terminated names.
        .map(|&n| unsafe { CStr::from_ptr(n) }.to_string_lossy().into_owned())
        .collect();
    Answer {
        result,
        names: if room.is_some() { listed } else { Vec::new() },
        count,
        bits,
        message: message(),
    }
}

const ALL: u32 = FFVK_FEATURE_DYNAMIC_RENDERING
    | FFVK_FEATURE_PROVOKING_VERTEX_LAST
    | FFVK_FEATURE_WIDE_LINES
    | FFVK_FEATURE_LARGE_POINTS
    | FFVK_FEATURE_CLIP_DISTANCE
    | FFVK_FEATURE_FILL_MODE_NON_SOLID
    | FFVK_FEATURE_LOGIC_OP
    | FFVK_FEATURE_STIPPLED_LINES
    | FFVK_FEATURE_GEOMETRY_SHADER;

#[test]
fn a_device_with_everything_gets_every_feature_set_the_extension_listed_and_every_bit() {
    let mut chain = Chain::new(true).with_non_seamless();
    let a = ask(FULL, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(
        a.names,
        [
            "VK_EXT_provoking_vertex",
            "VK_EXT_line_rasterization",
            "VK_EXT_non_seamless_cube_map"
        ]
    );
    assert_eq!((a.count, a.bits), (3, ALL | FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP));
    assert_eq!(a.message, "", "nothing is missing");
    assert_eq!(chain.non_seamless.non_seamless_cube_map, vk::TRUE);
    assert_eq!(chain.v13.dynamic_rendering, vk::TRUE);
    assert_eq!(
        chain.v13.synchronization2,
        vk::TRUE,
        "the caller's own feature is kept"
    );
    assert_eq!(chain.provoking.provoking_vertex_last, vk::TRUE);
    assert_eq!(chain.features.features.wide_lines, vk::TRUE);
    assert_eq!(chain.features.features.large_points, vk::TRUE);
    assert_eq!(chain.features.features.shader_clip_distance, vk::TRUE);
    assert_eq!(chain.features.features.fill_mode_non_solid, vk::TRUE);
    assert_eq!(chain.features.features.logic_op, vk::TRUE);
    assert_eq!(chain.features.features.geometry_shader, vk::TRUE);
    assert_eq!(
        chain
            .features
            .features
            .shader_tessellation_and_geometry_point_size,
        vk::TRUE
    );
    assert_eq!(
        (chain.lines.bresenham_lines, chain.lines.stippled_bresenham_lines),
        (vk::TRUE, vk::TRUE)
    );
    assert_eq!(
        chain.types(),
        [
            vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT,
            vk::StructureType::PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT,
            vk::StructureType::PHYSICAL_DEVICE_NON_SEAMLESS_CUBE_MAP_FEATURES_EXT,
        ],
        "the extensions' structs stay chained"
    );
}

#[test]
fn a_chain_without_the_non_seamless_struct_gets_no_cube_map_extension_and_is_told_to_chain_one() {
    let mut chain = Chain::new(true);
    let a = ask(FULL, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(a.names, ["VK_EXT_provoking_vertex", "VK_EXT_line_rasterization"]);
    assert_eq!(
        (a.count, a.bits),
        (2, ALL),
        "no FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP"
    );
    assert_eq!(
        a.message,
        "ffvkDeviceRequirements: without FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP (features' pNext chain \
         has no VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT to set it in; cube map samplers \
         filter across the faces' edges, where GL 2.1 filters each face on its own)"
    );
}

#[test]
fn without_the_non_seamless_extension_or_its_feature_its_struct_leaves_the_chain_and_is_named() {
    for (device, why) in [
        (
            Device {
                non_seamless_extension: false,
                non_seamless_cube_map: false,
                ..FULL
            },
            "the device lacks VK_EXT_non_seamless_cube_map",
        ),
        (
            Device {
                non_seamless_cube_map: false,
                ..FULL
            },
            "the device lacks nonSeamlessCubeMap",
        ),
    ] {
        let mut chain = Chain::new(true).with_non_seamless();
        let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
        assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
        assert_eq!(a.names, ["VK_EXT_provoking_vertex", "VK_EXT_line_rasterization"]);
        assert_eq!(a.bits, ALL);
        let words = format!("without FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP ({why};");
        assert!(a.message.contains(&words), "{:?} lacks {words:?}", a.message);
        assert_eq!(chain.non_seamless.non_seamless_cube_map, vk::FALSE);
        assert_eq!(
            chain.types(),
            [
                vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                vk::StructureType::PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT,
                vk::StructureType::PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT,
            ],
            "the cube map struct is still chained, or another was taken out"
        );
    }
}

#[test]
fn a_size_query_says_the_count_and_the_bits_and_changes_no_feature() {
    let mut chain = Chain::new(true);
    let a = ask(FULL, &mut chain, None);
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!((a.count, a.bits), (2, ALL));
    assert!(chain.untouched(), "a size query set a feature");
}

#[test]
fn too_little_room_for_the_names_is_refused_saying_how_many_and_changes_no_feature() {
    let mut chain = Chain::new(true);
    let a = ask(FULL, &mut chain, Some(0));
    assert_eq!(a.result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert_eq!(a.count, 2, "*extension_count says how many are needed");
    assert!(
        a.message
            .contains("ffvkDeviceRequirements: *extension_count is 0: expected room for 2"),
        "{}",
        a.message
    );
    assert!(chain.untouched(), "a refused call set a feature");
}

#[test]
fn without_the_provoking_vertex_extension_its_struct_leaves_the_chain_and_the_message_says_gl_flat_is_refused(
) {
    let device = Device {
        provoking_extension: false,
        provoking_vertex_last: false,
        ..FULL
    };
    let mut chain = Chain::new(true);
    let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(a.names, ["VK_EXT_line_rasterization"]);
    assert_eq!(a.bits, ALL & !FFVK_FEATURE_PROVOKING_VERTEX_LAST);
    for words in [
        "ffvkDeviceRequirements: without FFVK_FEATURE_PROVOKING_VERTEX_LAST",
        "the device lacks VK_EXT_provoking_vertex",
        "GL_FLAT draws are refused",
    ] {
        assert!(
            a.message.contains(words),
            "{:?} does not say {words:?}",
            a.message
        );
    }
    assert_eq!(
        chain.types(),
        [
            vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT,
        ],
        "the extension's struct is still chained, or the line one was taken out"
    );
    assert_eq!(chain.v13.dynamic_rendering, vk::TRUE);
}

#[test]
fn the_extension_without_provoking_vertex_last_is_not_listed_and_its_struct_leaves_the_chain() {
    let device = Device {
        provoking_vertex_last: false,
        ..FULL
    };
    let mut chain = Chain::new(true);
    let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(a.names, ["VK_EXT_line_rasterization"]);
    assert!(
        a.message.contains("the device lacks provokingVertexLast"),
        "{}",
        a.message
    );
    assert_eq!(
        chain.types(),
        [
            vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT,
        ]
    );
}

#[test]
fn a_chain_without_the_provoking_vertex_struct_gets_no_extension_and_is_told_to_chain_one() {
    let mut chain = Chain::with(false, true);
    let a = ask(FULL, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(a.names, ["VK_EXT_line_rasterization"]);
    assert_eq!(a.bits, ALL & !FFVK_FEATURE_PROVOKING_VERTEX_LAST);
    assert!(
        a.message
            .contains("features' pNext chain has no VkPhysicalDeviceProvokingVertexFeaturesEXT"),
        "{}",
        a.message
    );
}

#[test]
fn without_wide_lines_or_large_points_their_bits_are_missing_and_named() {
    let device = Device {
        wide_lines: false,
        large_points: false,
        ..FULL
    };
    let mut chain = Chain::new(true);
    let a = ask(device, &mut chain, Some(2));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(
        a.bits,
        ALL & !(FFVK_FEATURE_WIDE_LINES | FFVK_FEATURE_LARGE_POINTS)
    );
    assert_eq!(chain.features.features.wide_lines, vk::FALSE);
    for words in [
        "without FFVK_FEATURE_WIDE_LINES (the device lacks wideLines",
        "without FFVK_FEATURE_LARGE_POINTS (the device lacks largePoints",
    ] {
        assert!(
            a.message.contains(words),
            "{:?} does not say {words:?}",
            a.message
        );
    }
}

#[test]
fn without_fill_mode_non_solid_or_logic_op_their_bits_are_missing_named_and_their_features_left_off() {
    let device = Device {
        fill_mode_non_solid: false,
        logic_op: false,
        ..FULL
    };
    let mut chain = Chain::new(true).with_non_seamless();
    let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(
        a.bits,
        (ALL | FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP)
            & !(FFVK_FEATURE_FILL_MODE_NON_SOLID | FFVK_FEATURE_LOGIC_OP)
    );
    assert_eq!(
        (
            chain.features.features.fill_mode_non_solid,
            chain.features.features.logic_op
        ),
        (vk::FALSE, vk::FALSE)
    );
    assert_eq!(
        a.message,
        "ffvkDeviceRequirements: without FFVK_FEATURE_FILL_MODE_NON_SOLID (the device lacks fillModeNonSolid; \
         polygon modes GL_LINE and GL_POINT are refused), without FFVK_FEATURE_LOGIC_OP (the device lacks \
         logicOp; draws with GL_COLOR_LOGIC_OP are refused)"
    );
}

#[test]
fn without_geometry_shader_its_bit_is_missing_named_and_its_feature_left_off() {
    let device = Device {
        geometry_shader: false,
        ..FULL
    };
    let mut chain = Chain::new(true).with_non_seamless();
    let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(
        a.bits,
        (ALL | FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP) & !FFVK_FEATURE_GEOMETRY_SHADER
    );
    assert_eq!(chain.features.features.geometry_shader, vk::FALSE);
    assert_eq!(
        a.message,
        "ffvkDeviceRequirements: without FFVK_FEATURE_GEOMETRY_SHADER (the device lacks geometryShader \
         or shaderTessellationAndGeometryPointSize; draws of GL_TRIANGLES_ADJACENCY, GL's edge flags, \
         are refused)"
    );
}

#[test]
fn without_the_line_rasterization_extension_its_struct_leaves_the_chain_and_the_message_says_stipple_is_refused(
) {
    let device = Device {
        lines_extension: false,
        bresenham_lines: false,
        stippled_bresenham_lines: false,
        ..FULL
    };
    let mut chain = Chain::new(true).with_non_seamless();
    let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(
        a.names,
        ["VK_EXT_provoking_vertex", "VK_EXT_non_seamless_cube_map"]
    );
    assert_eq!(
        a.bits,
        (ALL | FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP) & !FFVK_FEATURE_STIPPLED_LINES
    );
    assert_eq!(
        a.message,
        "ffvkDeviceRequirements: without FFVK_FEATURE_STIPPLED_LINES (the device lacks \
         VK_EXT_line_rasterization; draws with GL_LINE_STIPPLE are refused, and lines are the \
         device's own, not GL's aliased lines)"
    );
    assert_eq!(
        chain.types(),
        [
            vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT,
            vk::StructureType::PHYSICAL_DEVICE_NON_SEAMLESS_CUBE_MAP_FEATURES_EXT,
        ]
    );
    assert_eq!(chain.lines.bresenham_lines, vk::FALSE);
}

#[test]
fn the_line_extension_without_a_line_feature_is_not_listed_names_the_feature_and_its_struct_leaves() {
    for (bresenham_lines, stippled_bresenham_lines, lacking) in [
        (true, false, "the device lacks stippledBresenhamLines;"),
        (false, true, "the device lacks bresenhamLines;"),
        (
            false,
            false,
            "the device lacks bresenhamLines and stippledBresenhamLines;",
        ),
    ] {
        let device = Device {
            bresenham_lines,
            stippled_bresenham_lines,
            ..FULL
        };
        let mut chain = Chain::new(true);
        let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
        assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
        assert_eq!(a.names, ["VK_EXT_provoking_vertex"]);
        assert_eq!(a.bits, ALL & !FFVK_FEATURE_STIPPLED_LINES);
        assert!(
            a.message.contains(lacking),
            "{:?} does not say {lacking:?}",
            a.message
        );
        assert_eq!(chain.types().len(), 2, "the line struct is still chained");
        assert_eq!(
            (chain.lines.bresenham_lines, chain.lines.stippled_bresenham_lines),
            (vk::FALSE, vk::FALSE),
            "a feature set in a struct taken out"
        );
    }
}

#[test]
fn without_either_extension_both_structs_leave_the_chain_whatever_their_order() {
    let device = Device {
        provoking_extension: false,
        provoking_vertex_last: false,
        lines_extension: false,
        ..FULL
    };
    let mut chain = Chain::new(true);
    let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert!(a.names.is_empty(), "{:?}", a.names);
    assert_eq!(a.count, 0);
    assert_eq!(
        chain.types(),
        [vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES]
    );
    // The line struct first, the provoking-vertex one after it.
    let mut chain = Chain::with(false, false);
    chain.v13.p_next = (&raw mut chain.lines).cast();
    chain.lines.p_next = (&raw mut chain.provoking).cast();
    let a = ask(device, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(
        chain.types(),
        [vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES]
    );
}

#[test]
fn a_chain_without_the_line_rasterization_struct_gets_no_line_extension_and_is_told_to_chain_one() {
    let mut chain = Chain::with(true, false);
    let a = ask(FULL, &mut chain, Some(FFVK_MAX_DEVICE_EXTENSIONS));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(a.names, ["VK_EXT_provoking_vertex"]);
    assert_eq!(a.bits, ALL & !FFVK_FEATURE_STIPPLED_LINES);
    assert!(
        a.message.contains(
            "without FFVK_FEATURE_STIPPLED_LINES (features' pNext chain has no \
             VkPhysicalDeviceLineRasterizationFeaturesEXT to set them in"
        ),
        "{}",
        a.message
    );
}

#[test]
fn a_device_older_than_vulkan_1_3_or_without_dynamic_rendering_is_a_missing_feature_and_nothing_changes() {
    for (device, words) in [
        (
            Device {
                api_version: vk::API_VERSION_1_2,
                ..FULL
            },
            "the device supports Vulkan 1.2: ffvk needs Vulkan 1.3",
        ),
        (
            Device {
                dynamic_rendering: false,
                ..FULL
            },
            "the device lacks dynamicRendering",
        ),
    ] {
        let mut chain = Chain::new(true);
        let a = ask(device, &mut chain, Some(4));
        assert_eq!(a.result, FfvkResult::FFVK_ERROR_MISSING_FEATURE, "{}", a.message);
        assert!(
            a.message.contains(words),
            "{:?} does not say {words:?}",
            a.message
        );
        assert!(chain.untouched());
        assert_eq!(a.bits, 0xDEAD, "bits written on a refusal");
    }
}

#[test]
fn a_chain_with_no_struct_for_dynamic_rendering_is_refused_naming_the_struct_to_chain() {
    let mut chain = Chain::new(false);
    chain.features.p_next = null_mut();
    let a = ask(FULL, &mut chain, Some(4));
    assert_eq!(a.result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert!(
        a.message
            .contains("features' pNext chain has no VkPhysicalDeviceVulkan13Features"),
        "{}",
        a.message
    );
    // VkPhysicalDeviceDynamicRenderingFeatures serves as well.
    let mut dynamic = vk::PhysicalDeviceDynamicRenderingFeatures::default();
    chain.features.p_next = (&raw mut dynamic).cast();
    let a = ask(FULL, &mut chain, Some(4));
    assert_eq!(a.result, FfvkResult::FFVK_SUCCESS, "{}", a.message);
    assert_eq!(dynamic.dynamic_rendering, vk::TRUE);
}

#[test]
fn a_looping_chain_or_a_wrong_s_type_is_refused_and_nothing_changes() {
    let mut chain = Chain::new(true);
    chain.provoking.p_next = (&raw mut chain.v13).cast();
    let a = ask(FULL, &mut chain, Some(4));
    assert_eq!(a.result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert!(a.message.contains("longer than 64 structs"), "{}", a.message);
    assert!(chain.untouched());

    let mut chain = Chain::new(true);
    chain.features.s_type = vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
    let a = ask(FULL, &mut chain, Some(4));
    assert_eq!(a.result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    assert!(
        a.message.contains(
            "features->sType is 53: expected VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2 (1000059000)"
        ),
        "{}",
        a.message
    );
}

#[test]
fn null_pointers_and_handles_are_refused_naming_each() {
    let mut chain = Chain::new(true);
    let (mut count, mut bits) = (4u32, 0u32);
    let mut names = [null::<c_char>(); 4];
    let (f, c, n, b) = (
        &raw mut chain.features,
        &raw mut count,
        names.as_mut_ptr(),
        &raw mut bits,
    );
    let (i, p) = (vk::Instance::from_raw(0x10), vk::PhysicalDevice::from_raw(0x20));
    let refused = |result: FfvkResult, words: &str| {
        assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{words}");
        let text = message();
        assert!(text.starts_with("ffvkDeviceRequirements: "), "{text}");
        assert!(text.contains(words), "{text:?} does not say {words:?}");
    };
    // SAFETY: the null pointer or handle is what is probed; the rest are valid.
    let r = unsafe { ffvkDeviceRequirements(Some(loader), i, p, null_mut(), c, n, b) };
    refused(r, "features is a null pointer");
    // SAFETY: as above.
    let r = unsafe { ffvkDeviceRequirements(Some(loader), i, p, f, null_mut(), n, b) };
    refused(r, "extension_count is a null pointer");
    // SAFETY: as above.
    let r = unsafe { ffvkDeviceRequirements(Some(loader), i, p, f, c, n, null_mut()) };
    refused(r, "enabled_features is a null pointer");
    // SAFETY: as above.
    let r = unsafe { ffvkDeviceRequirements(None, i, p, f, c, n, b) };
    refused(r, "get_instance_proc_addr is null");
    // SAFETY: as above.
    let r = unsafe { ffvkDeviceRequirements(Some(loader), vk::Instance::null(), p, f, c, n, b) };
    refused(r, "instance or physical_device is VK_NULL_HANDLE");
    assert!(chain.untouched());
}
