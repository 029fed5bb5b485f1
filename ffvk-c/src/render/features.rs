//! The `FFVK_FEATURE_*` bits of `FfvkRendererCreateInfo::enabled_features`: the device
//! features the caller enabled, as ffvk's `EnabledFeatures`. Each bit is named after the field
//! of `EnabledFeatures` it sets, so that ffvk's "not enabled" errors name the bit.

use ffvk::vk::EnabledFeatures;

/// `dynamicRendering` (Vulkan 1.3): required.
pub const FFVK_FEATURE_DYNAMIC_RENDERING: u32 = 1;
/// `VK_EXT_provoking_vertex` with `provokingVertexLast`: needed for `GL_FLAT`.
pub const FFVK_FEATURE_PROVOKING_VERTEX_LAST: u32 = 2;
/// `wideLines`: needed for a line width other than 1.
pub const FFVK_FEATURE_WIDE_LINES: u32 = 4;
/// `largePoints`: needed for a point size other than 1.
pub const FFVK_FEATURE_LARGE_POINTS: u32 = 8;
/// `shaderClipDistance`: needed for GL's user clip planes (`ffvkClipPlane`).
pub const FFVK_FEATURE_CLIP_DISTANCE: u32 = 16;
/// `VkPhysicalDeviceFeatures::fillModeNonSolid`: needed for `ffvkPolygonMode`'s `GL_LINE` and
/// `GL_POINT`.
pub const FFVK_FEATURE_FILL_MODE_NON_SOLID: u32 = 32;
/// `VkPhysicalDeviceFeatures::logicOp`: needed for `GL_COLOR_LOGIC_OP` (`ffvkLogicOp`).
pub const FFVK_FEATURE_LOGIC_OP: u32 = 64;
/// The extension `VK_EXT_line_rasterization` enabled with
/// `VkPhysicalDeviceLineRasterizationFeaturesEXT::bresenhamLines` and
/// `stippledBresenhamLines`: needed for `GL_LINE_STIPPLE` (`ffvkLineStipple`). With it every
/// line and polygon outline is drawn as GL's aliased (diamond-exit) lines.
pub const FFVK_FEATURE_STIPPLED_LINES: u32 = 128;
/// `VkPhysicalDeviceFeatures::geometryShader` and `shaderTessellationAndGeometryPointSize`:
/// needed for GL's edge flags (draws of mode `GL_TRIANGLES_ADJACENCY` from
/// `ffvkEdgeFlaggedIndices`).
pub const FFVK_FEATURE_GEOMETRY_SHADER: u32 = 256;
/// The extension `VK_EXT_non_seamless_cube_map` enabled with
/// `VkPhysicalDeviceNonSeamlessCubeMapFeaturesEXT::nonSeamlessCubeMap`: lets the caller's cube
/// map samplers (`ffvkCreateCubeMap`) take `VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT`,
/// filtering each face on its own as GL 2.1 does. ffvk makes no sampler of the caller's: the
/// bit says what the device has, and no draw is refused without it.
pub const FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP: u32 = 512;

/// Every bit this version knows.
pub(crate) const KNOWN_FEATURES: u32 = FFVK_FEATURE_DYNAMIC_RENDERING
    | FFVK_FEATURE_PROVOKING_VERTEX_LAST
    | FFVK_FEATURE_WIDE_LINES
    | FFVK_FEATURE_LARGE_POINTS
    | FFVK_FEATURE_CLIP_DISTANCE
    | FFVK_FEATURE_FILL_MODE_NON_SOLID
    | FFVK_FEATURE_LOGIC_OP
    | FFVK_FEATURE_STIPPLED_LINES
    | FFVK_FEATURE_GEOMETRY_SHADER
    | FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP;

/// The features `bits` (checked for unknown bits before) say the caller enabled.
pub(crate) fn enabled_features(bits: u32) -> EnabledFeatures {
    let has = |bit: u32| bits & bit != 0;
    EnabledFeatures::default()
        .with_dynamic_rendering(has(FFVK_FEATURE_DYNAMIC_RENDERING))
        .with_provoking_vertex_last(has(FFVK_FEATURE_PROVOKING_VERTEX_LAST))
        .with_wide_lines(has(FFVK_FEATURE_WIDE_LINES))
        .with_large_points(has(FFVK_FEATURE_LARGE_POINTS))
        .with_clip_distance(has(FFVK_FEATURE_CLIP_DISTANCE))
        .with_fill_mode_non_solid(has(FFVK_FEATURE_FILL_MODE_NON_SOLID))
        .with_logic_op(has(FFVK_FEATURE_LOGIC_OP))
        .with_stippled_lines(has(FFVK_FEATURE_STIPPLED_LINES))
        .with_geometry_shader(has(FFVK_FEATURE_GEOMETRY_SHADER))
        .with_non_seamless_cube_map(has(FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP))
}
