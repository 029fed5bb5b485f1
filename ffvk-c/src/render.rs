//! The renderer: ffvk's pipelines on the caller's Vulkan device, recording a context's GL state
//! as draws into the caller's command buffer (`ffvk::Lighting` behind C).
//!
//! It loads Vulkan through the caller's `vkGetInstanceProcAddr` (no Vulkan library of its
//! own), never submits, never waits, and owns only what it creates: the descriptor set
//! layouts, the pipeline layout, the pipelines, a pipeline cache unless the caller passes one,
//! and per frame slot host-visible memory for the state blocks and draw records. Dropping it
//! (`ffvkDestroyRenderer`) frees those; the caller first waits until no submitted command
//! buffer uses them.

use std::sync::Arc;

use ffvk::ash::{self, vk};
use ffvk::gl::state::FixedFunctionState;
use ffvk::glam::Mat4;
use ffvk::{
    Attribute, Geometry, Lighting, LightingOptions, LitDraw, RasterState, StagedDraw, Target, VertexInput,
};

mod base_format;
mod features;
pub mod layout;
mod raster;
mod texture;
mod topology;
mod versions;

use features::{enabled_features, KNOWN_FEATURES};
pub use features::{
    FFVK_FEATURE_CLIP_DISTANCE, FFVK_FEATURE_DYNAMIC_RENDERING, FFVK_FEATURE_FILL_MODE_NON_SOLID,
    FFVK_FEATURE_GEOMETRY_SHADER, FFVK_FEATURE_LARGE_POINTS, FFVK_FEATURE_LOGIC_OP,
    FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP, FFVK_FEATURE_PROVOKING_VERTEX_LAST, FFVK_FEATURE_STIPPLED_LINES,
    FFVK_FEATURE_WIDE_LINES,
};
pub(crate) use raster::raster_defaults;
pub use raster::{ffvkRasterDefaults, FfvkRaster, FFVK_RASTER_SOURCE_CONTEXT, FFVK_RASTER_SOURCE_DRAW};
pub use texture::{
    ffvkCreateCubeMap, ffvkCreateCubeMapWithFormat, ffvkCreateTexture, ffvkCreateTextureWithFormat,
    ffvkDestroyTexture, FfvkTexture,
};
use topology::topology;

use crate::gl::FfvkContext;
use crate::result::{check_ptr, fail, from_error, guard, misaligned, FfvkResult};
use crate::vk_types::*;
use layout::FfvkVertexLayout;

/// The most `frames_in_flight` a renderer takes (`ffvk::MAX_FRAMES_IN_FLIGHT`).
pub const FFVK_MAX_FRAMES_IN_FLIGHT: u32 = 64;
/// The most vertex `bindings` a renderer takes (`ffvk::MAX_VERTEX_BINDINGS`).
pub const FFVK_MAX_VERTEX_BINDINGS: u32 = 32;
const _: () = assert!(FFVK_MAX_FRAMES_IN_FLIGHT == ffvk::MAX_FRAMES_IN_FLIGHT);
const _: () = assert!(FFVK_MAX_VERTEX_BINDINGS == ffvk::MAX_VERTEX_BINDINGS);

/// Where one vertex attribute lives: a binding of the create info's `bindings`, the byte
/// offset within one element, the format (any the shaders read as floats, e.g.
/// `VK_FORMAT_R32G32B32_SFLOAT`, `VK_FORMAT_R8G8B8A8_UNORM`, that the device reads from
/// vertex buffers). The attribute lies within one element: offset + the format's size <= the
/// binding's stride.
///
/// It never changes (it has no `struct_size`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct FfvkAttribute {
    /// The vertex buffer binding it is read from.
    pub binding: u32,
    /// Byte offset within one element of that binding.
    pub offset: u32,
    /// The attribute's format.
    pub format: VkFormat,
}

/// What `ffvkCreateRenderer` takes. Set `struct_size` to `sizeof(FfvkRendererCreateInfo)`.
///
/// How it grows (the rule of every struct with a `struct_size`): a later `ffvk.h` only appends
/// fields, each documented with its default. The library accepts the `sizeof` of every
/// published version of the struct (this header's is version 1), reads only the bytes
/// `struct_size` covers and gives the fields beyond them their defaults, so a program built
/// against an older header runs unchanged with a newer library. Any other size (0, between
/// two versions, or a newer header's than the library knows) is refused with
/// `FFVK_ERROR_INVALID_ARGUMENT`, the message naming the size given and the sizes accepted.
#[repr(C)]
pub struct FfvkRendererCreateInfo {
    /// `sizeof(FfvkRendererCreateInfo)`.
    pub struct_size: u32,
    /// The caller's loader entry point: ffvk loads every Vulkan function through it.
    pub get_instance_proc_addr: PFN_vkGetInstanceProcAddr,
    /// The caller's instance, created with `apiVersion` 1.3 or later.
    pub instance: VkInstance,
    /// The physical device `device` was made from.
    pub physical_device: VkPhysicalDevice,
    /// The caller's device: ffvk creates its objects on it and never destroys it.
    pub device: VkDevice,
    /// `FFVK_FEATURE_*` bits: the features the caller enabled on `device` (Vulkan cannot be
    /// asked). `FFVK_FEATURE_DYNAMIC_RENDERING` is required: `VkPhysicalDeviceVulkan13Features::
    /// dynamicRendering`. `FFVK_FEATURE_PROVOKING_VERTEX_LAST` is the extension
    /// `VK_EXT_provoking_vertex` enabled with `VkPhysicalDeviceProvokingVertexFeaturesEXT::
    /// provokingVertexLast`; without it `GL_FLAT` draws are refused. `FFVK_FEATURE_WIDE_LINES`
    /// and `FFVK_FEATURE_LARGE_POINTS` are `VkPhysicalDeviceFeatures::wideLines` and
    /// `largePoints`; `FFVK_FEATURE_CLIP_DISTANCE` is `shaderClipDistance` (draws with a user
    /// clip plane enabled); `FFVK_FEATURE_FILL_MODE_NON_SOLID` is `fillModeNonSolid` (polygon
    /// modes `GL_LINE` and `GL_POINT`); `FFVK_FEATURE_LOGIC_OP` is `logicOp`
    /// (`GL_COLOR_LOGIC_OP`); `FFVK_FEATURE_STIPPLED_LINES` is the extension
    /// `VK_EXT_line_rasterization` enabled with `VkPhysicalDeviceLineRasterizationFeaturesEXT::
    /// bresenhamLines` and `stippledBresenhamLines` (`GL_LINE_STIPPLE`; every line then drawn
    /// as GL's aliased lines); `FFVK_FEATURE_GEOMETRY_SHADER` is `geometryShader` (GL's edge
    /// flags: draws of mode `GL_TRIANGLES_ADJACENCY`); `FFVK_FEATURE_NON_SEAMLESS_CUBE_MAP` is the
    /// extension `VK_EXT_non_seamless_cube_map` enabled with `nonSeamlessCubeMap` (the caller's
    /// cube map samplers may then filter each face on its own, as GL 2.1). A draw needing a
    /// feature not declared is refused, naming its bit.
    /// `ffvkDeviceRequirements` says which bits a device will have.
    pub enabled_features: u32,
    /// The color attachment's format: an uncompressed core format the shaders write as floats
    /// (UNORM, SNORM, SRGB or FLOAT; not UNDEFINED, a depth or an integer format) that the
    /// device supports as `VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT`.
    pub color_format: VkFormat,
    /// The depth attachment's format, or `VK_FORMAT_UNDEFINED` for none: one of the six `D*`
    /// formats, supported by the device as `VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT`.
    pub depth_format: VkFormat,
    /// Samples per pixel of both attachments: one `VK_SAMPLE_COUNT_*_BIT`, among the device's
    /// `framebufferColorSampleCounts` (and `framebufferDepthSampleCounts` with a depth format,
    /// `framebufferStencilSampleCounts` with a stencil one).
    pub samples: VkSampleCountFlagBits,
    /// The caller's vertex buffer bindings (per-vertex rate), in the order draws pass their
    /// buffers.
    pub bindings: *const VkVertexInputBindingDescription,
    /// How many `bindings`, at most `FFVK_MAX_VERTEX_BINDINGS`.
    pub binding_count: u32,
    /// Object-space position (`glVertexPointer`).
    pub position: FfvkAttribute,
    /// Object-space normal (`glNormalPointer`).
    pub normal: FfvkAttribute,
    /// Per-vertex color (`glColorPointer`), or null: every vertex takes the context's current
    /// color (`ffvkColor4f`).
    pub color: *const FfvkAttribute,
    /// Texture coordinates (`glTexCoordPointer`), or null: every vertex of a textured draw takes
    /// the context's current texture coordinates (`ffvkTexCoord4f`).
    pub texcoord: *const FfvkAttribute,
    /// Frame slots, 1 to `FFVK_MAX_FRAMES_IN_FLIGHT`: how many frames the caller records
    /// before it waits for the oldest.
    pub frames_in_flight: u32,
    /// The descriptor set index of ffvk's state block (ffvk uses it and the next two).
    pub set_index: u32,
    /// The caller's pipeline cache, or `VK_NULL_HANDLE` for ffvk's own.
    pub pipeline_cache: VkPipelineCache,
}

/// One draw: `glDrawArrays` (no index buffer) or `glDrawElementsBaseVertex`. Set
/// `struct_size` to `sizeof(FfvkDrawInfo)`.
///
/// It grows as `FfvkRendererCreateInfo` does: later headers append fields (each with its
/// default), the library accepts every published version's size (this header's is version 5:
/// version 2 appended `layout`, version 3 `raster_source`, version 4 `texture1` ..
/// `texture3`, version 5 `cube_map` .. `cube_map3`) and reads only what `struct_size` covers. `raster` never grows (`FfvkRaster`
/// keeps its size): the rest of GL's raster state comes from the context (`raster_source`).
#[repr(C)]
pub struct FfvkDrawInfo {
    /// `sizeof(FfvkDrawInfo)`.
    pub struct_size: u32,
    /// `GL_POINTS`, `GL_LINES`, `GL_LINE_STRIP`, `GL_TRIANGLES`, `GL_TRIANGLE_STRIP` or
    /// `GL_TRIANGLE_FAN`; `ffvkPrimitiveIndices` turns `GL_LINE_LOOP`, `GL_QUADS`,
    /// `GL_QUAD_STRIP` and `GL_POLYGON` into lists of these. `GL_TRIANGLES_ADJACENCY` draws
    /// GL's polygons with their edge flags as `ffvkEdgeFlaggedIndices` makes them (six indices
    /// a triangle: `first` and `count` multiples of 6; `FFVK_FEATURE_GEOMETRY_SHADER`).
    pub mode: u32,
    /// The vertex buffers, one per binding of the create info, in its order.
    pub vertex_buffers: *const VkBuffer,
    /// Their byte offsets, or null for all 0.
    pub vertex_offsets: *const VkDeviceSize,
    /// How many `vertex_buffers`: the create info's `binding_count`.
    pub vertex_buffer_count: u32,
    /// The index buffer, or `VK_NULL_HANDLE` to draw `count` consecutive vertices.
    pub index_buffer: VkBuffer,
    /// Byte offset of index 0 in `index_buffer`.
    pub index_offset: VkDeviceSize,
    /// `VK_INDEX_TYPE_UINT16` or `VK_INDEX_TYPE_UINT32`.
    pub index_type: VkIndexType,
    /// The first index (indexed) or vertex (glDrawArrays' `first`).
    pub first: u32,
    /// How many indices or vertices.
    pub count: u32,
    /// Added to every index before its vertex is fetched (indexed only).
    pub vertex_offset: i32,
    /// Indexed strips and fans: the index of all ones starts a new primitive.
    pub primitive_restart: u8,
    /// The raster state.
    pub raster: FfvkRaster,
    /// Texture unit 0's texture (`GL_TEXTURE0`'s glBindTexture), sampled while unit 0's
    /// `GL_TEXTURE_2D` is enabled, or null (GL's texture object 0: the unit textures nothing).
    pub texture: *const FfvkTexture,
    /// Version 2: the vertex layout the buffers follow (`ffvkCreateVertexLayout`), or null
    /// (the default, and what a version 1 caller gets): the create info's.
    pub layout: *const FfvkVertexLayout,
    /// Version 3: where the draw's raster state comes from. `FFVK_RASTER_SOURCE_DRAW` (0, the
    /// default, and what version 1 and 2 callers get): `raster`. `FFVK_RASTER_SOURCE_CONTEXT`
    /// (1): the whole of the context's GL raster state as it is at this `ffvkDraw` (polygon
    /// modes and offset, line stipple, point size, line width, culling, front face, the
    /// stencil and depth tests, blending, blend color, logic op, color and depth masks);
    /// `raster` is not read.
    pub raster_source: u32,
    /// Version 4: texture unit 1's texture (`GL_TEXTURE1`'s glBindTexture), sampled while unit
    /// 1's `GL_TEXTURE_2D` is enabled (`ffvkActiveTexture(ctx, GL_TEXTURE1)`, `ffvkEnable`), or
    /// null (the default, and what version 1 to 3 callers get): unit 1 textures nothing, as
    /// GL's texture object 0. Its coordinates are the layout's `texcoord1`, or unit 1's current
    /// ones. The units apply in order, each to the result of the one before it; a
    /// `GL_COMBINE` source `GL_TEXTUREn` reads unit n's texel.
    pub texture1: *const FfvkTexture,
    /// Version 4: unit 2's texture, as `texture1` (null by default).
    pub texture2: *const FfvkTexture,
    /// Version 4: unit 3's texture, as `texture1` (null by default).
    pub texture3: *const FfvkTexture,
    /// Version 5: unit 0's cube map (`GL_TEXTURE0`'s glBindTexture(GL_TEXTURE_CUBE_MAP, …)),
    /// from `ffvkCreateCubeMap`, or null (the default, and what version 1 to 4 callers get).
    /// While the unit's `GL_TEXTURE_CUBE_MAP` is enabled it takes precedence over
    /// `GL_TEXTURE_2D` (GL 2.1 §3.8.15): the unit samples this cube map at its (s, t, r), or
    /// with none textures nothing, whatever `texture` holds. A 2D texture here, or a cube map in
    /// a `texture*` field, is `FFVK_ERROR_INVALID_ARGUMENT` naming the field and the unit.
    pub cube_map: *const FfvkTexture,
    /// Version 5: unit 1's cube map, as `cube_map` (null by default).
    pub cube_map1: *const FfvkTexture,
    /// Version 5: unit 2's cube map, as `cube_map` (null by default).
    pub cube_map2: *const FfvkTexture,
    /// Version 5: unit 3's cube map, as `cube_map` (null by default).
    pub cube_map3: *const FfvkTexture,
}

/// One draw waiting for `ffvkEndDraws`.
struct Pending {
    state: usize,
    layout: Option<ffvk::VertexLayout>,
    modelview: Mat4,
    projection: Mat4,
    raster: RasterState,
    buffers: Vec<(vk::Buffer, u64)>,
    geometry: Geometry,
    /// Copies of the draw's 2D textures and cube maps, unit 0 first, taken at `ffvkDraw`: the
    /// record `ffvkEndDraws` makes is the one `ffvkDraw` checked and staged, whatever becomes
    /// of the caller's `FfvkTexture` objects in between.
    textures: [Option<ffvk::TextureBinding>; ffvk::gl::texture::MAX_TEXTURE_UNITS],
    cube_maps: [Option<ffvk::TextureBinding>; ffvk::gl::texture::MAX_TEXTURE_UNITS],
}

/// What `ffvkBeginDraws` opened.
pub(crate) struct Recording {
    cmd: vk::CommandBuffer,
    slot: u32,
    states: Vec<FixedFunctionState>,
    draws: Vec<Pending>,
    /// Each draw as `ffvkDraw` checked it and wrote it into the slot.
    staged: Vec<StagedDraw>,
}

/// ffvk on the caller's device (`ffvkCreateRenderer`).
pub struct FfvkRenderer {
    // Fields drop in order: the lighting's objects before the device wrapper.
    pub(crate) lighting: Lighting,
    _device: Arc<ffvk::vk::Device>,
    pub(crate) recording: Option<Recording>,
    binding_count: u32,
    /// Which frame slots `ffvkBeginFrame` has begun (a scope may only open on one of them).
    begun: Vec<bool>,
}

pub(crate) fn invalid(message: impl Into<String>) -> FfvkResult {
    fail(FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, message)
}

/// Reads `count` values at `ptr` (empty for a count of 0).
///
/// # Safety
///
/// `ptr` points at `count` values when `count` is not 0 and it is not null.
pub(crate) unsafe fn slice<'a, T>(
    function: &str,
    what: &str,
    ptr: *const T,
    count: u32,
) -> Result<&'a [T], FfvkResult> {
    if count == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(invalid(format!(
            "{function}: {what} is null with a count of {count}"
        )));
    }
    if misaligned(ptr) {
        return Err(invalid(format!(
            "{function}: {what} {ptr:p} is not aligned to {} bytes: expected {count} values",
            std::mem::align_of::<T>()
        )));
    }
    // SAFETY: the caller's contract: count values at a non-null ptr.
    Ok(unsafe { std::slice::from_raw_parts(ptr, count as usize) })
}

pub(crate) fn attribute(a: &FfvkAttribute) -> Attribute {
    Attribute::new(a.binding, a.offset, a.format)
}

/// The renderer's options and device wrapper from a create info.
///
/// # Safety
///
/// The create info's contract (`ffvkCreateRenderer`).
unsafe fn create(info: &FfvkRendererCreateInfo) -> Result<FfvkRenderer, FfvkResult> {
    const F: &str = "ffvkCreateRenderer";
    let Some(get_instance_proc_addr) = info.get_instance_proc_addr else {
        return Err(invalid(format!(
            "{F}: get_instance_proc_addr is null: expected the caller's vkGetInstanceProcAddr"
        )));
    };
    for (what, null) in [
        ("instance", info.instance == vk::Instance::null()),
        (
            "physical_device",
            info.physical_device == vk::PhysicalDevice::null(),
        ),
        ("device", info.device == vk::Device::null()),
    ] {
        if null {
            return Err(invalid(format!(
                "{F}: {what} is VK_NULL_HANDLE: expected the caller's {what}"
            )));
        }
    }
    let known = KNOWN_FEATURES;
    if info.enabled_features & !known != 0 {
        return Err(invalid(format!(
            "{F}: enabled_features 0x{:X} has unknown bits: expected FFVK_FEATURE_* flags (0x{known:X})",
            info.enabled_features
        )));
    }
    if info.binding_count > FFVK_MAX_VERTEX_BINDINGS {
        return Err(invalid(format!(
            "{F}: binding_count is {}: expected at most {FFVK_MAX_VERTEX_BINDINGS} (FFVK_MAX_VERTEX_BINDINGS)",
            info.binding_count
        )));
    }
    // SAFETY: the caller's contract: binding_count descriptions at bindings (checked bounded).
    let bindings = unsafe { slice(F, "bindings", info.bindings, info.binding_count) }?.to_vec();
    let mut vertex_input = VertexInput::new(bindings, attribute(&info.position), attribute(&info.normal));
    for (what, ptr) in [("color", info.color), ("texcoord", info.texcoord)] {
        if misaligned(ptr) {
            return Err(invalid(format!(
                "{F}: {what} {ptr:p} is not aligned: expected an FfvkAttribute or null"
            )));
        }
    }
    // SAFETY: the caller's contract: color and texcoord are null or point at an attribute.
    let (color, texcoord) = unsafe { (info.color.as_ref(), info.texcoord.as_ref()) };
    vertex_input = vertex_input
        .with_color(color.map(attribute))
        .with_texcoord(texcoord.map(attribute));
    let mut target = Target::new(info.color_format, info.depth_format);
    target.samples = info.samples;
    let options = LightingOptions::new(target, vertex_input)
        .with_frames_in_flight(info.frames_in_flight)
        .with_set_index(info.set_index)
        .with_pipeline_cache(Some(info.pipeline_cache).filter(|c| *c != vk::PipelineCache::null()));
    // Every value that needs no device is checked before Vulkan is touched; Lighting::new
    // checks them again (the one check the Rust API has too), then the device.
    options.validate().map_err(|e| from_error(F, &e))?;

    let static_fn = ash::StaticFn {
        get_instance_proc_addr,
    };
    // SAFETY: the caller's contract: get_instance_proc_addr is its loader's and instance is
    // live; ash only loads function pointers here.
    let instance = unsafe { ash::Instance::load(&static_fn, info.instance) };
    // SAFETY: as above, for the device of that instance.
    let device = unsafe { ash::Device::load(instance.fp_v1_0(), info.device) };
    let features = enabled_features(info.enabled_features);
    // SAFETY: the caller's contract: device was made from physical_device of instance with
    // these features and outlives the renderer.
    let ffvk_device =
        unsafe { ffvk::vk::Device::from_caller(&instance, info.physical_device, device, features) }
            .map_err(|e| from_error(F, &e))?;
    let lighting = Lighting::new(&ffvk_device, &options).map_err(|e| from_error(F, &e))?;
    Ok(FfvkRenderer {
        lighting,
        _device: ffvk_device,
        recording: None,
        binding_count: info.binding_count,
        begun: vec![false; info.frames_in_flight as usize],
    })
}

/// Makes a renderer on the caller's device: checks every value of `info` before Vulkan is
/// touched, then the device (Vulkan 1.3, dynamic rendering, the features `enabled_features`
/// claims, the formats' features and sample counts, vertex limits), and makes the pipeline
/// layout; pipelines are made on the first draw that needs each (about 15 ms on lavapipe).
/// Returns `FFVK_SUCCESS` with `*renderer` set, or an error code with `*renderer` null:
/// `FFVK_ERROR_INVALID_ARGUMENT` (a null pointer or handle, a `struct_size` that is not a
/// published version's, 0 or more than `FFVK_MAX_FRAMES_IN_FLIGHT` frames, more than
/// `FFVK_MAX_VERTEX_BINDINGS` bindings, unknown feature bits, a format, sample count or
/// vertex layout that is invalid or that the device does not support; the message names the
/// field, its value and what was expected),
/// `FFVK_ERROR_MISSING_FEATURE`, `FFVK_ERROR_OUT_OF_MEMORY`, `FFVK_ERROR_VULKAN`. Records
/// nothing.
///
/// # Safety
///
/// `renderer` is null or writable; `info` is null or points at the `struct_size` bytes of a
/// create info as the caller's header declares it; the handles in `info` are live, `device`
/// was created from `physical_device` of `instance` with the features `enabled_features` names,
/// and all of them outlive the renderer.
#[no_mangle]
pub unsafe extern "C" fn ffvkCreateRenderer(
    info: *const FfvkRendererCreateInfo,
    renderer: *mut *mut FfvkRenderer,
) -> FfvkResult {
    guard(|| {
        const F: &str = "ffvkCreateRenderer";
        if let Err(code) = check_ptr(F, "renderer", renderer, "where to write the renderer") {
            return code;
        }
        // SAFETY: checked non-null and aligned; the caller's contract makes it writable.
        unsafe { *renderer = std::ptr::null_mut() };
        if let Err(code) = check_ptr(F, "info", info, "an FfvkRendererCreateInfo") {
            return code;
        }
        // SAFETY: checked non-null and aligned; the caller's contract: struct_size bytes of a
        // create info.
        let info = match unsafe { crate::abi::read(F, info) } {
            Ok(info) => info,
            Err(code) => return code,
        };
        // SAFETY: the caller's contract on the create info.
        match unsafe { create(&info) } {
            Ok(r) => {
                // SAFETY: checked non-null above.
                unsafe { *renderer = Box::into_raw(Box::new(r)) };
                FfvkResult::FFVK_SUCCESS
            }
            Err(code) => code,
        }
    })
}

/// Frees the renderer and everything it created; null is ignored. Records nothing. The
/// caller first makes sure no submitted command buffer still uses it (waits on its fences).
///
/// # Safety
///
/// `renderer` is null or a renderer from `ffvkCreateRenderer` not yet destroyed, whose
/// device is still alive.
#[no_mangle]
pub unsafe extern "C" fn ffvkDestroyRenderer(renderer: *mut FfvkRenderer) {
    // SAFETY: the caller's contract: made by this API, destroyed once.
    unsafe { crate::result::free(renderer) }
}

/// Runs `f` on a renderer behind the panic barrier.
pub(crate) fn with_renderer(
    renderer: *mut FfvkRenderer,
    function: &str,
    f: impl FnOnce(&mut FfvkRenderer) -> FfvkResult,
) -> FfvkResult {
    guard(|| {
        if let Err(code) = check_ptr(
            function,
            "renderer",
            renderer,
            "a renderer from ffvkCreateRenderer",
        ) {
            return code;
        }
        // SAFETY: checked non-null and aligned; the caller's contract: a live renderer used by
        // one thread at a time.
        f(unsafe { &mut *renderer })
    })
}

/// Starts a frame slot (0 .. frames_in_flight - 1): its memory will be rewritten by the draws
/// recorded next. Call it once the fence of the submission that last used this slot has
/// signalled. Records nothing.
///
/// # Safety
///
/// `renderer` is null or live and used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkBeginFrame(renderer: *mut FfvkRenderer, slot: u32) -> FfvkResult {
    with_renderer(renderer, "ffvkBeginFrame", |r| {
        if r.recording.is_some() {
            return invalid("ffvkBeginFrame: called between ffvkBeginDraws and ffvkEndDraws");
        }
        match r.lighting.begin_frame(slot) {
            Ok(()) => {
                r.begun[slot as usize] = true;
                FfvkResult::FFVK_SUCCESS
            }
            Err(e) => from_error("ffvkBeginFrame", &e),
        }
    })
}

/// Opens a recording scope on `cmd` for frame slot `slot`, which `ffvkBeginFrame` has begun
/// (several scopes may follow one `ffvkBeginFrame`; their draws share the slot's memory).
/// `cmd` is in the recording state inside the caller's `vkCmdBeginRendering` on attachments of
/// the create info's formats, with viewport and scissor set (both dynamic state). Between this
/// call and `ffvkEndDraws` the caller records nothing of its own into `cmd`; between scopes it
/// may (viewports, scissors, clears, barriers, rendering passes), and after binding anything of
/// its own (a pipeline, descriptor sets, vertex or index buffers) or resetting `cmd` it calls
/// `ffvkForgetBindings` before the next scope. Records nothing itself.
///
/// # Safety
///
/// `renderer` is null or live and used by one thread at a time; `cmd` is a command buffer of
/// the renderer's device.
#[no_mangle]
pub unsafe extern "C" fn ffvkBeginDraws(
    renderer: *mut FfvkRenderer,
    cmd: VkCommandBuffer,
    slot: u32,
) -> FfvkResult {
    with_renderer(renderer, "ffvkBeginDraws", |r| {
        if r.recording.is_some() {
            return invalid("ffvkBeginDraws: a recording scope is already open: expected ffvkEndDraws first");
        }
        if cmd == vk::CommandBuffer::null() {
            return invalid("ffvkBeginDraws: cmd is VK_NULL_HANDLE: expected the caller's command buffer");
        }
        if slot >= r.lighting.frames_in_flight() {
            return invalid(format!(
                "ffvkBeginDraws: slot {slot} is out of range: expected 0 to {} (frames_in_flight - 1)",
                r.lighting.frames_in_flight() - 1
            ));
        }
        if !r.begun[slot as usize] {
            return invalid(format!(
                "ffvkBeginDraws: slot {slot} was not begun: expected ffvkBeginFrame(renderer, {slot}) first"
            ));
        }
        r.recording = Some(Recording {
            cmd,
            slot,
            states: Vec::new(),
            draws: Vec::new(),
            staged: Vec::new(),
        });
        FfvkResult::FFVK_SUCCESS
    })
}

/// Adds a draw to the open scope: the context's state now (lights, materials, switches, its
/// modelview and projection) is captured, so the caller may change the context right after.
/// The draw is checked and its state written into the slot's memory now (its pipeline is made
/// now if it is new: about 15 ms on lavapipe); `ffvkEndDraws` records it. A refused draw is
/// not added and the scope stays open with the draws before it. Errors:
/// `FFVK_ERROR_INVALID_ARGUMENT` (no open scope, a null pointer, a `struct_size` that is not a
/// published version's, a mode ffvk does not draw directly, a buffer count other than the
/// layout's bindings, a raster enum that is not one ffvk passes to Vulkan (see `FfvkRaster`), a `raster_source`
/// other than `FFVK_RASTER_SOURCE_DRAW` and `FFVK_RASTER_SOURCE_CONTEXT`,
/// blending into a color
/// format the device cannot blend, a point size or line width out of the device's range, a
/// textured draw without texture coordinates, a cube map from `ffvkCreateCubeMap` in a
/// `texture*` field or a 2D texture in a `cube_map*` one: the message names the field and unit),
/// `FFVK_ERROR_STATE` (the context's state cannot be drawn: a soft spot cone wider than its
/// cutoff, a modelview that cannot be inverted while lighting, a fill with `GL_POLYGON_STIPPLE`
/// on and no `ffvkFramebufferHeight`), `FFVK_ERROR_MISSING_FEATURE` (`GL_FLAT`, a point size or
/// a line width, a `GL_CLIP_PLANEi` enabled, a polygon mode, logic op or line stipple, or a
/// `GL_TRIANGLES_ADJACENCY` draw, that the create info's `enabled_features` did not declare), `FFVK_ERROR_OUT_OF_MEMORY`, `FFVK_ERROR_VULKAN` (making the pipeline).
///
/// # Safety
///
/// `renderer` and `ctx` are null or live and used by this thread only; `draw` is null or
/// points at the `struct_size` bytes of a draw info as the caller's header declares it; its
/// buffers are the caller's live buffers of the renderer's device, and its textures are null
/// or live during this call. `ffvkDraw` copies what each texture names, so a texture may be
/// destroyed as soon as it returns (`ffvkEndDraws` records the copy); the view and sampler it
/// names stay alive until the command buffer has executed.
#[no_mangle]
pub unsafe extern "C" fn ffvkDraw(
    renderer: *mut FfvkRenderer,
    ctx: *const FfvkContext,
    draw: *const FfvkDrawInfo,
) -> FfvkResult {
    const F: &str = "ffvkDraw";
    with_renderer(renderer, F, |r| {
        let binding_count = r.binding_count;
        let lighting = &mut r.lighting;
        let Some(recording) = r.recording.as_mut() else {
            return invalid("ffvkDraw: no recording scope is open: expected ffvkBeginDraws first");
        };
        let checked = check_ptr(F, "ctx", ctx, "the context whose state is drawn")
            .and_then(|()| check_ptr(F, "draw", draw, "an FfvkDrawInfo"));
        if let Err(code) = checked {
            return code;
        }
        // SAFETY: checked non-null and aligned; the caller's contract: a live context.
        let ctx = unsafe { &*ctx };
        let result = (|| {
            // SAFETY: checked non-null and aligned; the caller's contract: struct_size bytes of
            // a draw info.
            let draw = unsafe { crate::abi::read(F, draw) }?;
            let topology = topology(draw.mode)?;
            // SAFETY: the caller's contract: null or live textures (misaligned ones refused).
            let units = unsafe { texture::of_draw(F, &draw) }?;
            // SAFETY: the caller's contract: the layout is null or live.
            let (layout, binding_count) = unsafe { layout::of_draw(F, draw.layout, binding_count) }?;
            if draw.vertex_buffer_count != binding_count {
                let whose = if layout.is_some() {
                    "the draw's layout"
                } else {
                    "the renderer's layout"
                };
                return Err(invalid(format!(
                    "{F}: vertex_buffer_count is {}: expected {binding_count}, one buffer per binding of {whose}",
                    draw.vertex_buffer_count
                )));
            }
            // SAFETY: the caller's contract: vertex_buffer_count buffers (and offsets unless null).
            let buffers =
                unsafe { slice(F, "vertex_buffers", draw.vertex_buffers, draw.vertex_buffer_count) }?;
            let offsets = if draw.vertex_offsets.is_null() {
                vec![0; buffers.len()]
            } else {
                // SAFETY: as above.
                unsafe { slice(F, "vertex_offsets", draw.vertex_offsets, draw.vertex_buffer_count) }?.to_vec()
            };
            let geometry = if draw.index_buffer == vk::Buffer::null() {
                Geometry::vertices(draw.count).with_first(draw.first)
            } else {
                if draw.index_type != vk::IndexType::UINT16 && draw.index_type != vk::IndexType::UINT32 {
                    return Err(invalid(format!(
                        "{F}: index_type {} is not accepted: expected VK_INDEX_TYPE_UINT16 or VK_INDEX_TYPE_UINT32",
                        draw.index_type.as_raw()
                    )));
                }
                Geometry::indexed(draw.index_buffer, draw.index_type, draw.count)
                    .with_first(draw.first)
                    .with_buffer_offset(draw.index_offset)
                    .with_vertex_offset(draw.vertex_offset)
                    .with_primitive_restart(draw.primitive_restart != 0)
            }
            .with_topology(topology);
            let buffers: Vec<(vk::Buffer, u64)> = buffers.iter().copied().zip(offsets).collect();
            let raster = raster::of_draw(F, &draw, ctx)?;
            // SAFETY: checked aligned above; the caller's contract: null or live textures.
            let (bound, cubes) = unsafe {
                (
                    texture::bindings(&units.textures),
                    texture::bindings(&units.cube_maps),
                )
            };
            let lit = LitDraw::new(
                &ctx.gl.lighting,
                ctx.gl.modelview,
                ctx.projection,
                &buffers,
                geometry,
            )
            .with_raster(raster)
            .with_textures(bound)
            .with_cube_maps(cubes)
            .with_layout(layout);
            // Checked and written into the slot now, so that a bad draw is refused alone.
            let staged = lighting
                .stage_draw(recording.slot, &lit)
                .map_err(|e| from_error(F, &e))?;
            let state = match recording.states.last() {
                Some(last) if *last == ctx.gl.lighting => recording.states.len() - 1,
                _ => {
                    recording.states.push(ctx.gl.lighting);
                    recording.states.len() - 1
                }
            };
            recording.draws.push(Pending {
                state,
                layout,
                modelview: ctx.gl.modelview,
                projection: ctx.projection,
                raster,
                buffers,
                geometry,
                textures: bound.map(|t| t.copied()),
                cube_maps: cubes.map(|t| t.copied()),
            });
            recording.staged.push(staged);
            Ok(())
        })();
        match result {
            Ok(()) => FfvkResult::FFVK_SUCCESS,
            Err(code) => code,
        }
    })
}

/// Closes the scope: records every draw `ffvkDraw` added since `ffvkBeginDraws` into its
/// command buffer as one run (binding only what changes between draws; consecutive draws of
/// one geometry become instances). Records: bind pipeline, bind ffvk's descriptor sets at
/// their dynamic offsets, bind the caller's vertex and index buffers and ffvk's record
/// buffer, draw, each bind only where it differs from what ffvk last bound in the same command
/// buffer (since `ffvkBeginFrame` or `ffvkForgetBindings`): a scope per draw, as a GL layer
/// records `glDrawElements` by `glDrawElements`, rebinds nothing that did not change. They
/// stay bound afterwards. A scope without draws records nothing. Errors:
/// `FFVK_ERROR_INVALID_ARGUMENT` when no scope is open; the draws were checked when added.
///
/// # Safety
///
/// `renderer` is null or live and used by one thread at a time; the scope's command buffer is
/// recording as `ffvkBeginDraws` requires; the draws' buffers, and the image views and samplers
/// their textures name, are live and stay so until the command buffer has executed (the
/// `FfvkTexture` objects themselves are not read again: `ffvkDraw` copied them).
#[no_mangle]
pub unsafe extern "C" fn ffvkEndDraws(renderer: *mut FfvkRenderer) -> FfvkResult {
    with_renderer(renderer, "ffvkEndDraws", |r| {
        let Some(recording) = r.recording.take() else {
            return invalid("ffvkEndDraws: no recording scope is open: expected ffvkBeginDraws first");
        };
        let mut draws = Vec::with_capacity(recording.draws.len());
        for d in &recording.draws {
            // The bindings ffvkDraw copied: the caller's textures are not read again.
            let (bound, cubes) = (
                d.textures.each_ref().map(Option::as_ref),
                d.cube_maps.each_ref().map(Option::as_ref),
            );
            draws.push(
                LitDraw::new(
                    &recording.states[d.state],
                    d.modelview,
                    d.projection,
                    &d.buffers,
                    d.geometry,
                )
                .with_raster(d.raster)
                .with_textures(bound)
                .with_cube_maps(cubes)
                .with_layout(d.layout),
            );
        }
        // SAFETY: the caller's contract: cmd records inside a rendering pass of the target's
        // formats with viewport and scissor set; the slot was begun; the buffers live on;
        // staged[i] was staged by ffvkDraw from draws[i]'s values in this scope's slot.
        match unsafe { r.lighting.record_run(recording.cmd, &recording.staged, &draws) } {
            Ok(()) => FfvkResult::FFVK_SUCCESS,
            Err(e) => from_error("ffvkEndDraws", &e),
        }
    })
}

/// Forgets what ffvk bound: the next scope binds everything its draws need. Call it after
/// recording commands of your own that bind a pipeline, descriptor sets, vertex buffers or an
/// index buffer into a command buffer ffvk draws into, or after resetting such a command
/// buffer (`ffvkBeginFrame` forgets too). Records nothing. Errors:
/// `FFVK_ERROR_INVALID_ARGUMENT` for a null renderer or while a scope is open.
///
/// # Safety
///
/// `renderer` is null or live and used by one thread at a time.
#[no_mangle]
pub unsafe extern "C" fn ffvkForgetBindings(renderer: *mut FfvkRenderer) -> FfvkResult {
    with_renderer(renderer, "ffvkForgetBindings", |r| {
        if r.recording.is_some() {
            return invalid("ffvkForgetBindings: called between ffvkBeginDraws and ffvkEndDraws: expected ffvkEndDraws first");
        }
        r.lighting.forget_bindings();
        FfvkResult::FFVK_SUCCESS
    })
}
