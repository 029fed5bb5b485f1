//! The C API's renderer on a caller's device through its `vkGetInstanceProcAddr`: each
//! `ffvkDraw` is checked when it is added, a refused draw leaves the scope open with the draws
//! before it, and the errors name what to fix in C's terms.

use std::ffi::CStr;

use ffvk::ash::vk::{self, Handle};
use ffvk_c::gl::*;
use ffvk_c::render::*;
use ffvk_c::result::{ffvkResultMessage, FfvkResult};

use crate::embedding::PlainDevice;

const GL_LIGHTING: u32 = 0x0B50;
const GL_LIGHT0: u32 = 0x4000;
const GL_FLAT: u32 = 0x1D00;
const GL_SMOOTH: u32 = 0x1D01;
const GL_LINES: u32 = 0x0001;
const GL_TRIANGLES: u32 = 0x0004;
const GL_QUADS: u32 = 0x0007;
const GL_TRIANGLES_ADJACENCY: u32 = 0x000C;

fn message() -> String {
    // SAFETY: ffvkResultMessage never returns null; the string is valid until the next call.
    unsafe { CStr::from_ptr(ffvkResultMessage()) }
        .to_string_lossy()
        .into_owned()
}

fn attribute(binding: u32, offset: u32, format: vk::Format) -> FfvkAttribute {
    FfvkAttribute {
        binding,
        offset,
        format,
    }
}

/// A renderer on `plain`'s device (dynamic rendering only: no provoking vertex, no wide
/// lines), positions and normals interleaved in one binding.
fn renderer(plain: &PlainDevice, bindings: &[vk::VertexInputBindingDescription]) -> *mut FfvkRenderer {
    let info = FfvkRendererCreateInfo {
        struct_size: std::mem::size_of::<FfvkRendererCreateInfo>() as u32,
        get_instance_proc_addr: Some(plain.entry.static_fn().get_instance_proc_addr),
        instance: plain.instance.handle(),
        physical_device: plain.physical,
        device: plain.device.handle(),
        enabled_features: FFVK_FEATURE_DYNAMIC_RENDERING,
        color_format: vk::Format::R8G8B8A8_UNORM,
        depth_format: vk::Format::D32_SFLOAT,
        samples: vk::SampleCountFlags::TYPE_1,
        bindings: bindings.as_ptr(),
        binding_count: bindings.len() as u32,
        position: attribute(0, 0, vk::Format::R32G32B32_SFLOAT),
        normal: attribute(0, 12, vk::Format::R32G32B32_SFLOAT),
        color: std::ptr::null(),
        texcoord: std::ptr::null(),
        frames_in_flight: 1,
        set_index: 0,
        pipeline_cache: vk::PipelineCache::null(),
    };
    let mut renderer = std::ptr::null_mut();
    // SAFETY: the create info's handles are plain's, alive for the test; out is writable.
    let result = unsafe { ffvkCreateRenderer(&info, &mut renderer) };
    assert_eq!(result, FfvkResult::FFVK_SUCCESS, "{}", message());
    renderer
}

fn draw_info(mode: u32, buffer: &vk::Buffer, raster: FfvkRaster) -> FfvkDrawInfo {
    FfvkDrawInfo {
        struct_size: std::mem::size_of::<FfvkDrawInfo>() as u32,
        mode,
        vertex_buffers: buffer,
        vertex_offsets: std::ptr::null(),
        vertex_buffer_count: 1,
        index_buffer: vk::Buffer::null(),
        index_offset: 0,
        index_type: vk::IndexType::UINT32,
        first: 0,
        count: 6,
        vertex_offset: 0,
        primitive_restart: 0,
        raster,
        texture: std::ptr::null(),
        layout: std::ptr::null(),
        raster_source: FFVK_RASTER_SOURCE_DRAW,
        texture1: std::ptr::null(),
        texture2: std::ptr::null(),
        texture3: std::ptr::null(),
        cube_map: std::ptr::null(),
        cube_map1: std::ptr::null(),
        cube_map2: std::ptr::null(),
        cube_map3: std::ptr::null(),
    }
}

#[test]
fn a_draw_the_device_or_the_state_cannot_take_is_refused_at_ffvk_draw_and_the_scope_stays_open() {
    let plain = PlainDevice::new();
    let bindings = [vk::VertexInputBindingDescription {
        binding: 0,
        stride: 24,
        input_rate: vk::VertexInputRate::VERTEX,
    }];
    let r = renderer(&plain, &bindings);
    let ctx = ffvkCreateContext();
    // A buffer handle that is never dereferenced: nothing here is recorded or submitted
    // (ffvkDraw only checks and stages; ffvkEndDraws of these scopes records nothing or is
    // not reached).
    let buffer = vk::Buffer::null();
    let mut raster = std::mem::MaybeUninit::<FfvkRaster>::uninit();
    // SAFETY: writable; ffvkRasterDefaults fills every field.
    let raster = unsafe {
        ffvkRasterDefaults(raster.as_mut_ptr());
        raster.assume_init()
    };
    // SAFETY: every pointer is live for its call; the command buffer handle is a placeholder
    // that ffvk never records into (the scopes end empty or are dropped with the renderer).
    unsafe {
        ffvkEnable(ctx, GL_LIGHTING);
        ffvkEnable(ctx, GL_LIGHT0);
        assert_eq!(
            ffvkBeginDraws(r, vk::CommandBuffer::null(), 0),
            FfvkResult::FFVK_ERROR_INVALID_ARGUMENT
        );
        let fake_cmd = vk::CommandBuffer::from_raw(0x1000);
        assert_eq!(
            ffvkBeginDraws(r, fake_cmd, 0),
            FfvkResult::FFVK_ERROR_INVALID_ARGUMENT
        );
        assert!(
            message().contains("expected ffvkBeginFrame(renderer, 0) first"),
            "{}",
            message()
        );
        assert_eq!(ffvkBeginFrame(r, 1), FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
        assert_eq!(ffvkBeginFrame(r, 0), FfvkResult::FFVK_SUCCESS, "{}", message());
        assert_eq!(
            ffvkBeginDraws(r, fake_cmd, 0),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );

        // GL_FLAT without VK_EXT_provoking_vertex.
        ffvkShadeModel(ctx, GL_FLAT);
        let flat = ffvkDraw(r, ctx, &draw_info(GL_TRIANGLES, &buffer, raster));
        assert_eq!(flat, FfvkResult::FFVK_ERROR_MISSING_FEATURE, "{}", message());
        assert!(message().starts_with("ffvkDraw: "), "{}", message());
        assert!(
            message().contains("FFVK_FEATURE_PROVOKING_VERTEX_LAST"),
            "{}",
            message()
        );
        ffvkShadeModel(ctx, GL_SMOOTH);

        // A line width of 3 without wideLines.
        let wide = FfvkRaster {
            line_width: 3.0,
            ..raster
        };
        let lines = ffvkDraw(r, ctx, &draw_info(GL_LINES, &buffer, wide));
        assert_ne!(lines, FfvkResult::FFVK_SUCCESS);
        assert!(message().contains("FFVK_FEATURE_WIDE_LINES"), "{}", message());

        // A singular modelview while lighting: GL's normals need its inverse.
        let flat_plane: [f32; 16] = [1., 0., 0., 0., 0., 0., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.];
        ffvkLoadModelview(ctx, flat_plane.as_ptr());
        let singular = ffvkDraw(r, ctx, &draw_info(GL_TRIANGLES, &buffer, raster));
        assert_eq!(singular, FfvkResult::FFVK_ERROR_STATE, "{}", message());
        assert!(message().contains("determinant"), "{}", message());

        // A zeroed raster state (point size 0) and GL_QUADS, refused with what to do.
        let identity: [f32; 16] = [1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.];
        ffvkLoadModelview(ctx, identity.as_ptr());
        let zeroed = ffvkDraw(r, ctx, &draw_info(GL_TRIANGLES, &buffer, std::mem::zeroed()));
        assert_eq!(zeroed, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{}", message());
        let quads = ffvkDraw(r, ctx, &draw_info(GL_QUADS, &buffer, raster));
        assert_eq!(quads, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
        assert!(message().contains("ffvkPrimitiveIndices"), "{}", message());
        // GL's edge flags (GL_TRIANGLES_ADJACENCY, ffvkEdgeFlaggedIndices' lists) without
        // geometryShader.
        let edges = ffvkDraw(r, ctx, &draw_info(GL_TRIANGLES_ADJACENCY, &buffer, raster));
        assert_eq!(edges, FfvkResult::FFVK_ERROR_MISSING_FEATURE, "{}", message());
        assert!(
            message().contains("FFVK_FEATURE_GEOMETRY_SHADER"),
            "{}",
            message()
        );

        // Nothing was added: the scope closes recording nothing, and opens again.
        assert_eq!(ffvkEndDraws(r), FfvkResult::FFVK_SUCCESS, "{}", message());
        assert_eq!(ffvkEndDraws(r), FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
        assert_eq!(ffvkBeginDraws(r, fake_cmd, 0), FfvkResult::FFVK_SUCCESS);
        // A draw the device and the state can take is accepted now (staged, not recorded).
        let good = ffvkDraw(r, ctx, &draw_info(GL_TRIANGLES, &buffer, raster));
        assert_eq!(good, FfvkResult::FFVK_SUCCESS, "{}", message());
        // The frame slot cannot be begun again while its scope is open.
        assert_eq!(ffvkBeginFrame(r, 0), FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);

        // Destroyed with its scope open: nothing was recorded, everything is freed.
        ffvkDestroyRenderer(r);
        ffvkDestroyContext(ctx);
    }
}

/// A version 3 draw with `FFVK_RASTER_SOURCE_CONTEXT` takes the context's GL raster state as it
/// is at `ffvkDraw` (GL's rule: a draw takes the state in force when it is issued), and one with
/// `FFVK_RASTER_SOURCE_DRAW` its own `raster`: the context's stencil test on a target without
/// stencil, and its `GL_LINE` polygon mode on a device without `fillModeNonSolid`, refuse the
/// first and not the second.
#[test]
fn a_version_3_draw_takes_the_contexts_raster_state_as_it_is_when_the_draw_is_issued() {
    const GL_FRONT_AND_BACK: u32 = 0x0408;
    const GL_LINE: u32 = 0x1B01;
    const GL_FILL: u32 = 0x1B02;
    const GL_STENCIL_TEST: u32 = 0x0B90;
    let plain = PlainDevice::new();
    let bindings = [vk::VertexInputBindingDescription {
        binding: 0,
        stride: 24,
        input_rate: vk::VertexInputRate::VERTEX,
    }];
    let r = renderer(&plain, &bindings);
    let ctx = ffvkCreateContext();
    // Never dereferenced: the draws are checked and staged, never recorded.
    let buffer = vk::Buffer::null();
    let mut raster = std::mem::MaybeUninit::<FfvkRaster>::uninit();
    // SAFETY: writable; ffvkRasterDefaults fills every field.
    let raster = unsafe {
        ffvkRasterDefaults(raster.as_mut_ptr());
        raster.assume_init()
    };
    let own = draw_info(GL_TRIANGLES, &buffer, raster);
    let mut from_context = draw_info(GL_TRIANGLES, &buffer, raster);
    from_context.raster_source = FFVK_RASTER_SOURCE_CONTEXT;
    // SAFETY: every pointer is live for its call; the command buffer handle is a placeholder
    // ffvk never records into (the renderer is destroyed with its scope open).
    unsafe {
        assert_eq!(ffvkBeginFrame(r, 0), FfvkResult::FFVK_SUCCESS, "{}", message());
        let fake_cmd = vk::CommandBuffer::from_raw(0x1000);
        assert_eq!(ffvkBeginDraws(r, fake_cmd, 0), FfvkResult::FFVK_SUCCESS);
        // GL's initial raster state draws.
        assert_eq!(
            ffvkDraw(r, ctx, &from_context),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );

        ffvkEnable(ctx, GL_STENCIL_TEST);
        let stencil = ffvkDraw(r, ctx, &from_context);
        assert_ne!(
            stencil,
            FfvkResult::FFVK_SUCCESS,
            "the context's stencil test on D32_SFLOAT"
        );
        assert!(message().to_lowercase().contains("stencil"), "{}", message());
        assert_eq!(
            ffvkDraw(r, ctx, &own),
            FfvkResult::FFVK_SUCCESS,
            "a draw with its own raster state does not read the context's: {}",
            message()
        );
        ffvkDisable(ctx, GL_STENCIL_TEST);

        ffvkPolygonMode(ctx, GL_FRONT_AND_BACK, GL_LINE);
        assert_ne!(ffvkDraw(r, ctx, &from_context), FfvkResult::FFVK_SUCCESS);
        assert!(message().contains("fillModeNonSolid"), "{}", message());
        assert_eq!(ffvkDraw(r, ctx, &own), FfvkResult::FFVK_SUCCESS, "{}", message());
        ffvkPolygonMode(ctx, GL_FRONT_AND_BACK, GL_FILL);

        // GL_POLYGON_STIPPLE counts its rows from the framebuffer's bottom: without the
        // framebuffer's height the draw is refused, naming the call that gives it.
        const GL_POLYGON_STIPPLE: u32 = 0x0B42;
        let checks = [0xAAu8; 128];
        ffvkPolygonStipple(ctx, checks.as_ptr());
        ffvkEnable(ctx, GL_POLYGON_STIPPLE);
        assert_eq!(ffvkDraw(r, ctx, &from_context), FfvkResult::FFVK_ERROR_STATE);
        assert!(message().contains("ffvkFramebufferHeight"), "{}", message());
        // GL stipples fills only: lines, and polygons drawn as lines, need no height.
        let mut lines = draw_info(GL_LINES, &buffer, raster);
        lines.raster_source = FFVK_RASTER_SOURCE_CONTEXT;
        assert_eq!(
            ffvkDraw(r, ctx, &lines),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );
        ffvkFramebufferHeight(ctx, 0);
        assert_eq!(ffvkGetError(ctx), 0x0501, "GL_INVALID_VALUE for a height of 0");
        ffvkFramebufferHeight(ctx, 64);
        assert_eq!(
            ffvkDraw(r, ctx, &from_context),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );
        ffvkDisable(ctx, GL_POLYGON_STIPPLE);

        // The state at this ffvkDraw, not at the scope's start: drawable again.
        ffvkColorMask(ctx, 0, 1, 1, 1);
        assert_eq!(
            ffvkDraw(r, ctx, &from_context),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );
        assert_eq!(ffvkGetError(ctx), 0);

        from_context.raster_source = 2;
        assert_eq!(
            ffvkDraw(r, ctx, &from_context),
            FfvkResult::FFVK_ERROR_INVALID_ARGUMENT
        );
        assert!(
            message().contains("raster_source 2 is not accepted: expected FFVK_RASTER_SOURCE_DRAW (0) or FFVK_RASTER_SOURCE_CONTEXT (1)"),
            "{}",
            message()
        );
        ffvkDestroyRenderer(r);
        ffvkDestroyContext(ctx);
    }
}
