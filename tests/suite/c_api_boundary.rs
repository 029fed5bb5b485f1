//! The C boundary's checks that need a device (issue 46): formats and sample counts the
//! device cannot render, counts that used to be allocated infallibly, and raster enums that
//! used to reach Vulkan unchecked. Each value is refused with `FFVK_ERROR_INVALID_ARGUMENT`
//! and a message naming the function, the field, the value and what was expected; the Rust
//! API refuses the same values through the same checks.

use std::ffi::CStr;

use ffvk::ash::vk::{self, Handle};
use ffvk_c::abi::Versioned;
use ffvk_c::gl::*;
use ffvk_c::render::layout::*;
use ffvk_c::render::*;
use ffvk_c::result::{ffvkResultMessage, FfvkResult};

use crate::embedding::PlainDevice;

const GL_TRIANGLES: u32 = 0x0004;

pub(crate) fn message() -> String {
    // SAFETY: ffvkResultMessage never returns null; the string is valid until the next call.
    unsafe { CStr::from_ptr(ffvkResultMessage()) }
        .to_string_lossy()
        .into_owned()
}

/// Positions and normals interleaved in one binding of 24 bytes.
pub(crate) const BINDINGS: [vk::VertexInputBindingDescription; 1] = [vk::VertexInputBindingDescription {
    binding: 0,
    stride: 24,
    input_rate: vk::VertexInputRate::VERTEX,
}];

/// A valid create info on `plain`'s device (dynamic rendering only), over [`BINDINGS`].
pub(crate) fn create_info(plain: &PlainDevice) -> FfvkRendererCreateInfo {
    let attribute = |offset| FfvkAttribute {
        binding: 0,
        offset,
        format: vk::Format::R32G32B32_SFLOAT,
    };
    FfvkRendererCreateInfo {
        struct_size: std::mem::size_of::<FfvkRendererCreateInfo>() as u32,
        get_instance_proc_addr: Some(plain.entry.static_fn().get_instance_proc_addr),
        instance: plain.instance.handle(),
        physical_device: plain.physical,
        device: plain.device.handle(),
        enabled_features: FFVK_FEATURE_DYNAMIC_RENDERING,
        color_format: vk::Format::R8G8B8A8_UNORM,
        depth_format: vk::Format::D32_SFLOAT,
        samples: vk::SampleCountFlags::TYPE_1,
        bindings: BINDINGS.as_ptr(),
        binding_count: 1,
        position: attribute(0),
        normal: attribute(12),
        color: std::ptr::null(),
        texcoord: std::ptr::null(),
        frames_in_flight: 1,
        set_index: 0,
        pipeline_cache: vk::PipelineCache::null(),
    }
}

/// Creates a renderer from `info`: the result, the message, and the renderer destroyed again
/// when one was made.
pub(crate) fn create(info: &FfvkRendererCreateInfo) -> (FfvkResult, String) {
    let mut renderer = std::ptr::null_mut();
    // SAFETY: the create info's handles are a live PlainDevice's; out is writable.
    let result = unsafe { ffvkCreateRenderer(info, &mut renderer) };
    let text = message();
    assert_eq!(
        renderer.is_null(),
        result != FfvkResult::FFVK_SUCCESS,
        "the out pointer and the result disagree: {result:?} {text}"
    );
    // SAFETY: null or a renderer just made, whose device is alive.
    unsafe { ffvkDestroyRenderer(renderer) };
    (result, text)
}

#[track_caller]
fn assert_refused(info: &FfvkRendererCreateInfo, words: &[&str]) {
    let (result, text) = create(info);
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{text}");
    assert!(text.starts_with("ffvkCreateRenderer: "), "{text}");
    for word in words {
        assert!(text.contains(word), "{text:?} does not name {word:?}");
    }
}

#[test]
fn a_renderer_asked_for_a_billion_frames_in_flight_is_refused_not_an_abort() {
    let plain = PlainDevice::new();
    for frames in [1_000_000_000, FFVK_MAX_FRAMES_IN_FLIGHT + 1] {
        let info = FfvkRendererCreateInfo {
            frames_in_flight: frames,
            ..create_info(&plain)
        };
        assert_refused(
            &info,
            &[&format!("frames_in_flight is {frames}"), "expected 1..=64"],
        );
    }
    let most = FfvkRendererCreateInfo {
        frames_in_flight: FFVK_MAX_FRAMES_IN_FLIGHT,
        ..create_info(&plain)
    };
    let (result, text) = create(&most);
    assert_eq!(result, FfvkResult::FFVK_SUCCESS, "{text}");
}

#[test]
fn samples_the_device_cannot_render_are_refused_at_creation_naming_its_sample_counts() {
    let plain = PlainDevice::new();
    // SAFETY: the physical device is live.
    let limits = unsafe { plain.instance.get_physical_device_properties(plain.physical) }.limits;
    let supported = limits.framebuffer_color_sample_counts & limits.framebuffer_depth_sample_counts;
    let mut refused = 0;
    for bit in (0..7).map(|b| vk::SampleCountFlags::from_raw(1 << b)) {
        let info = FfvkRendererCreateInfo {
            samples: bit,
            ..create_info(&plain)
        };
        if supported.contains(bit) {
            let (result, text) = create(&info);
            assert_eq!(
                result,
                FfvkResult::FFVK_SUCCESS,
                "{} samples: {text}",
                bit.as_raw()
            );
        } else {
            let given = format!("samples {} is not supported by the device", bit.as_raw());
            assert_refused(&info, &[&given, "expected one of 1", "SampleCounts)"]);
            refused += 1;
        }
    }
    assert!(
        refused > 0,
        "the device renders every sample count: 64 is not tested"
    );
}

/// The features the device has for `format`, tilings together.
fn features(plain: &PlainDevice, format: vk::Format) -> vk::FormatFeatureFlags {
    // SAFETY: the physical device is live; format is a core format.
    let p = unsafe {
        plain
            .instance
            .get_physical_device_format_properties(plain.physical, format)
    };
    p.optimal_tiling_features | p.linear_tiling_features
}

#[test]
fn color_formats_the_device_cannot_render_into_are_refused_naming_the_feature() {
    let plain = PlainDevice::new();
    // Float color formats (valid values) that devices commonly cannot render into.
    let candidates = [
        vk::Format::R8G8B8_UNORM,
        vk::Format::R16G16B16_UNORM,
        vk::Format::R64_SFLOAT,
        vk::Format::R8_USCALED,
        vk::Format::E5B9G9R9_UFLOAT_PACK32,
    ];
    let unsupported: Vec<vk::Format> = candidates
        .into_iter()
        .filter(|&f| !features(&plain, f).contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT))
        .collect();
    assert!(
        !unsupported.is_empty(),
        "the device renders into each of {candidates:?}"
    );
    for format in unsupported {
        let info = FfvkRendererCreateInfo {
            color_format: format,
            ..create_info(&plain)
        };
        let given = format!("color_format {format:?} is not supported by the device as COLOR_ATTACHMENT");
        assert_refused(&info, &[&given]);
    }
    let depth_less = ffvk::ash::vk::Format::R8G8B8A8_UNORM;
    assert!(!features(&plain, depth_less).contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT));
}

/// A default raster state (`ffvkRasterDefaults`).
fn defaults() -> FfvkRaster {
    let mut raster = std::mem::MaybeUninit::<FfvkRaster>::uninit();
    // SAFETY: writable; ffvkRasterDefaults fills every field.
    unsafe {
        ffvkRasterDefaults(raster.as_mut_ptr());
        raster.assume_init()
    }
}

/// Raster states with one value Vulkan does not define (or ffvk does not pass on), each with
/// the field and value its refusal names.
pub(crate) fn bad_rasters() -> Vec<(FfvkRaster, &'static str, &'static str)> {
    let d = defaults();
    let blend = FfvkRaster { blend: 1, ..d };
    vec![
        (
            FfvkRaster {
                depth_compare: vk::CompareOp::from_raw(99),
                ..d
            },
            "depth_compare 99",
            "VK_COMPARE_OP_NEVER (0) .. VK_COMPARE_OP_ALWAYS (7)",
        ),
        (
            FfvkRaster {
                cull_mode: vk::CullModeFlags::from_raw(0x77),
                ..d
            },
            "cull_mode 0x77",
            "bits 0x3",
        ),
        (
            FfvkRaster {
                front_face: vk::FrontFace::from_raw(5),
                ..d
            },
            "front_face 5",
            "VK_FRONT_FACE_CLOCKWISE (1)",
        ),
        (
            FfvkRaster {
                src_color: vk::BlendFactor::from_raw(999),
                ..blend
            },
            "src_color 999",
            "VK_BLEND_FACTOR_SRC_ALPHA_SATURATE (14)",
        ),
        (
            FfvkRaster {
                dst_alpha: vk::BlendFactor::SRC1_COLOR,
                ..blend
            },
            "dst_alpha 15",
            "dual-source",
        ),
        (
            FfvkRaster {
                color_op: vk::BlendOp::from_raw(5),
                ..blend
            },
            "color_op 5",
            "VK_BLEND_OP_MAX (4)",
        ),
        (
            FfvkRaster {
                alpha_op: vk::BlendOp::MULTIPLY_EXT,
                ..blend
            },
            "alpha_op 1000148012",
            "VK_BLEND_OP_ADD (0)",
        ),
    ]
}

/// A buffer handle ffvkDraw never dereferences (it only checks and stages).
const PLACEHOLDER: u64 = 0x2000;

/// A non-indexed draw of 3 vertices from `buffer` with `raster`.
pub(crate) fn draw_info(buffer: &vk::Buffer, raster: FfvkRaster) -> FfvkDrawInfo {
    FfvkDrawInfo {
        struct_size: std::mem::size_of::<FfvkDrawInfo>() as u32,
        mode: GL_TRIANGLES,
        vertex_buffers: buffer,
        vertex_offsets: std::ptr::null(),
        vertex_buffer_count: 1,
        index_buffer: vk::Buffer::null(),
        index_offset: 0,
        index_type: vk::IndexType::UINT32,
        first: 0,
        count: 3,
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

/// Calls `f` with a renderer on lavapipe and a context, inside an open recording scope whose
/// command buffer is a placeholder: ffvkDraw only checks and stages, and the renderer is
/// destroyed with its scope open, so nothing is ever recorded.
fn in_draw_scope(f: impl FnOnce(*mut FfvkRenderer, *mut FfvkContext)) {
    let plain = PlainDevice::new();
    let mut r = std::ptr::null_mut();
    // SAFETY: a valid create info on a live device; out is writable.
    let made = unsafe { ffvkCreateRenderer(&create_info(&plain), &mut r) };
    assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
    let ctx = ffvkCreateContext();
    // SAFETY: a live renderer; the command buffer is never recorded into (above).
    unsafe {
        assert_eq!(ffvkBeginFrame(r, 0), FfvkResult::FFVK_SUCCESS);
        assert_eq!(
            ffvkBeginDraws(r, vk::CommandBuffer::from_raw(0x1000), 0),
            FfvkResult::FFVK_SUCCESS
        );
    }
    f(r, ctx);
    // SAFETY: both live, used by this thread only, destroyed once.
    unsafe {
        ffvkDestroyRenderer(r);
        ffvkDestroyContext(ctx);
    }
}

/// `draw` is refused at ffvkDraw with a message naming `given` and `expected`.
#[track_caller]
fn assert_draw_refused(
    r: *mut FfvkRenderer,
    ctx: *mut FfvkContext,
    draw: &FfvkDrawInfo,
    given: &str,
    expected: &str,
) {
    // SAFETY: a live renderer in an open scope and a live context (in_draw_scope).
    let result = unsafe { ffvkDraw(r, ctx, draw) };
    let text = message();
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{given}: {text}");
    assert!(text.starts_with("ffvkDraw: "), "{text}");
    assert!(
        text.contains(given) && text.contains(expected),
        "{text:?} lacks {given:?} or {expected:?}"
    );
}

/// `draw` is staged at ffvkDraw.
#[track_caller]
fn assert_drawn(r: *mut FfvkRenderer, ctx: *mut FfvkContext, draw: &FfvkDrawInfo) {
    // SAFETY: as in assert_draw_refused.
    let result = unsafe { ffvkDraw(r, ctx, draw) };
    assert_eq!(result, FfvkResult::FFVK_SUCCESS, "{}", message());
}

#[test]
fn raster_enums_vulkan_does_not_define_are_refused_at_ffvk_draw_naming_field_and_value() {
    let buffer = vk::Buffer::from_raw(PLACEHOLDER);
    in_draw_scope(|r, ctx| {
        for (raster, given, expected) in bad_rasters() {
            assert_draw_refused(r, ctx, &draw_info(&buffer, raster), given, expected);
        }
        // Blending off: the factors are not used, whatever they hold.
        let unused = FfvkRaster {
            src_color: vk::BlendFactor::from_raw(999),
            ..defaults()
        };
        assert_drawn(r, ctx, &draw_info(&buffer, unused));
    });
}

#[test]
fn the_rust_api_refuses_the_same_targets_layouts_and_raster_states_as_the_c_api() {
    use ffvk::vk::{Device, EnabledFeatures};
    use ffvk::{
        Attribute, Blend, Lighting, LightingError, LightingOptions, RasterState, Target, VertexInput,
    };
    let plain = PlainDevice::new();
    // SAFETY: the device comes from this physical device and outlives every ffvk object here.
    let device = unsafe {
        Device::from_caller(
            &plain.instance,
            plain.physical,
            plain.device.clone(),
            EnabledFeatures::default().with_dynamic_rendering(true),
        )
    }
    .unwrap();
    let input = || {
        VertexInput::new(
            BINDINGS.to_vec(),
            Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
            Attribute::new(0, 12, vk::Format::R32G32B32_SFLOAT),
        )
    };
    let lighting = |target: Target, input: VertexInput, frames: u32| {
        Lighting::new(
            &device,
            &LightingOptions::new(target, input).with_frames_in_flight(frames),
        )
        .err()
        .map(|e| e.to_string())
    };
    let color = Target::new(vk::Format::D32_SFLOAT, vk::Format::UNDEFINED);
    let e = lighting(color, input(), 1).expect("a depth format as color");
    assert!(
        e.contains("color_format D32_SFLOAT (126) is not a color format"),
        "{e}"
    );
    let depth = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::R8G8B8A8_UNORM);
    let e = lighting(depth, input(), 1).expect("a color format as depth");
    assert!(
        e.contains("depth_format R8G8B8A8_UNORM (37) is not a depth format"),
        "{e}"
    );
    let mut samples = Target::OFFSCREEN;
    samples.samples = vk::SampleCountFlags::TYPE_64;
    let e = lighting(samples, input(), 1).expect("64 samples on lavapipe");
    assert!(e.contains("samples 64 is not supported by the device"), "{e}");
    samples.samples = vk::SampleCountFlags::from_raw(3);
    assert_eq!(
        samples.validate(),
        Err(LightingError::Samples {
            samples: vk::SampleCountFlags::from_raw(3)
        })
    );
    let mut past = input();
    past.normal = past.normal.map(|n| Attribute::new(n.binding, 13, n.format));
    let e = lighting(Target::OFFSCREEN, past, 1).expect("a normal past the stride");
    assert!(e.contains("the normal attribute at offset 13"), "{e}");
    let e = lighting(Target::OFFSCREEN, input(), 1_000_000_000).expect("a billion frames");
    assert!(
        e.contains("frames_in_flight is 1000000000: expected 1..=64"),
        "{e}"
    );
    assert!(lighting(Target::OFFSCREEN, input(), 2).is_none());

    let raster = RasterState::default().with_depth_compare(vk::CompareOp::from_raw(99));
    let e = raster.validate().unwrap_err().to_string();
    assert!(e.contains("depth_compare 99 is not accepted"), "{e}");
    let blend = Blend::new(
        vk::BlendFactor::ONE,
        vk::BlendFactor::from_raw(999),
        vk::BlendOp::ADD,
    );
    let e = RasterState::default()
        .with_blend(Some(blend))
        .validate()
        .unwrap_err()
        .to_string();
    assert!(e.contains("dst_color 999"), "{e}");
    assert_eq!(RasterState::default().validate(), Ok(()));
}

/// What Vulkan would not draw as given is refused at `ffvkDraw`, naming the field and value:
/// an index offset that is not a multiple of the index size (VUID-vkCmdBindIndexBuffer-
/// offset-00432 once recorded), a first index or vertex plus the count past 2^32. The Rust API checks the same (`Geometry::validate`, in `Lighting`'s staging).
#[test]
fn geometry_vulkan_would_not_draw_is_refused_at_ffvk_draw_naming_field_and_value() {
    let buffer = vk::Buffer::from_raw(PLACEHOLDER);
    let null = vk::Buffer::null();
    let good = FfvkDrawInfo {
        index_buffer: vk::Buffer::from_raw(0x3000),
        ..draw_info(&buffer, defaults())
    };
    let cases = [
        (
            FfvkDrawInfo {
                index_offset: 0xFFFF_FFFF_FFFF_FFF0,
                first: 8,
                ..good
            },
            "index offset + (first + count) × index size is 18446744073709551600 + (8 + 3) × 4",
            "at most 2^64 - 1 bytes",
        ),
        (
            FfvkDrawInfo {
                index_offset: 3,
                ..good
            },
            "index offset is 3",
            "a multiple of the index size",
        ),
        (
            FfvkDrawInfo {
                index_offset: 2,
                index_type: vk::IndexType::UINT32,
                ..good
            },
            "index offset is 2",
            "4 for UINT32",
        ),
        (
            FfvkDrawInfo {
                first: u32::MAX,
                count: 3,
                ..good
            },
            "first + count is 4294967295 + 3",
            "at most 4294967295",
        ),
        (
            FfvkDrawInfo {
                index_buffer: null,
                first: 10,
                count: u32::MAX - 5,
                ..good
            },
            "first + count is 10 + 4294967290",
            "at most 4294967295",
        ),
    ];
    in_draw_scope(|r, ctx| {
        for (draw, given, expected) in &cases {
            assert_draw_refused(r, ctx, draw, given, expected);
        }
        // An offset of 4 with UINT32, 2 with UINT16: drawn.
        for (offset, index_type) in [(4, vk::IndexType::UINT32), (2, vk::IndexType::UINT16)] {
            let draw = FfvkDrawInfo {
                index_offset: offset,
                index_type,
                ..good
            };
            assert_drawn(r, ctx, &draw);
        }
    });
}

/// ffvkForgetBindings belongs between scopes: inside one it is refused, naming the call to make
/// first, and the scope stays open; a null renderer is refused too.
#[test]
fn forgetting_bindings_inside_an_open_scope_is_refused_naming_ffvk_end_draws() {
    in_draw_scope(|r, _| {
        // SAFETY: a live renderer in an open scope (in_draw_scope).
        let result = unsafe { ffvkForgetBindings(r) };
        let text = message();
        assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{text}");
        assert!(
            text.starts_with("ffvkForgetBindings: ") && text.contains("ffvkEndDraws"),
            "{text}"
        );
        // SAFETY: as above; the scope is still open, so a second one is refused.
        let again = unsafe { ffvkBeginDraws(r, vk::CommandBuffer::from_raw(0x1000), 0) };
        assert_eq!(again, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
    });
    // SAFETY: null is allowed and refused.
    let null = unsafe { ffvkForgetBindings(std::ptr::null_mut()) };
    assert_eq!(null, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
}

#[test]
fn ffvk_draw_takes_every_published_versions_size_and_refuses_any_other_naming_the_sizes_accepted() {
    let versions = <FfvkDrawInfo as Versioned>::VERSIONS;
    let sizes: Vec<u32> = versions.iter().map(|v| v.size as u32).collect();
    let accepted = sizes
        .iter()
        .enumerate()
        .map(|(i, size)| format!("{size} (version {})", i + 1))
        .collect::<Vec<_>>()
        .join(" or ");
    let expected = format!("expected sizeof(FfvkDrawInfo) as a published ffvk.h declares it, {accepted}");
    let newest = *sizes.last().expect("version 1 at least");
    let mut refused = vec![
        (0, "smaller than version 1"),
        (sizes[0] - 8, "smaller than version 1"),
        (newest + 8, "larger than any version this library (ffvk-c 0.1.0) knows, so the program was built against a newer ffvk.h"),
        (newest + 64, "larger than any version this library (ffvk-c 0.1.0) knows"),
    ];
    for pair in sizes.windows(2) {
        refused.push((pair[0] + 4, "between versions"));
    }
    in_draw_scope(|r, ctx| {
        let buffer = vk::Buffer::from_raw(PLACEHOLDER);
        for (size, why) in refused {
            let mut draw = draw_info(&buffer, defaults());
            draw.struct_size = size;
            let given = format!("FfvkDrawInfo.struct_size is {size}: {why}");
            assert_draw_refused(r, ctx, &draw, &given, &expected);
        }
        // Each version's size is drawn, whatever lies past it.
        for size in sizes {
            let mut draw = draw_info(&buffer, defaults());
            draw.struct_size = size;
            assert_drawn(r, ctx, &draw);
        }
    });
}

/// Each unit's texture pointer is checked as unit 0's is, naming its field; a version 3 draw
/// (without `texture1` .. `texture3`) is drawn whatever lies where they would be.
#[test]
fn a_misaligned_texture_of_any_unit_is_refused_naming_its_field_and_an_older_draw_never_reads_them() {
    let bad = 0x1001 as *const FfvkTexture;
    in_draw_scope(|r, ctx| {
        let buffer = vk::Buffer::from_raw(PLACEHOLDER);
        for (field, draw) in [
            (
                "texture",
                FfvkDrawInfo {
                    texture: bad,
                    ..draw_info(&buffer, defaults())
                },
            ),
            (
                "texture1",
                FfvkDrawInfo {
                    texture1: bad,
                    ..draw_info(&buffer, defaults())
                },
            ),
            (
                "texture2",
                FfvkDrawInfo {
                    texture2: bad,
                    ..draw_info(&buffer, defaults())
                },
            ),
            (
                "texture3",
                FfvkDrawInfo {
                    texture3: bad,
                    ..draw_info(&buffer, defaults())
                },
            ),
        ] {
            let given = format!("{field} 0x1001 is not aligned");
            assert_draw_refused(
                r,
                ctx,
                &draw,
                &given,
                "expected a texture from ffvkCreateTexture or null",
            );
        }
        let version_3 = <FfvkDrawInfo as Versioned>::VERSIONS[2].size as u32;
        let draw = FfvkDrawInfo {
            struct_size: version_3,
            texture1: bad,
            texture3: bad,
            ..draw_info(&buffer, defaults())
        };
        assert_drawn(r, ctx, &draw);
    });
}

/// Each unit's cube map pointer (version 5) is checked as its texture is, naming its field; a
/// version 4 draw is drawn whatever lies where they would be; a cube map where a 2D texture
/// goes, or a 2D texture where a cube map goes, is refused naming the field, the unit and the
/// field it belongs in; and `ffvkCreateCubeMap` refuses null handles and out pointers.
#[test]
fn cube_maps_are_checked_per_unit_naming_the_field_and_a_binding_of_the_other_target_is_refused() {
    let bad = 0x1001 as *const FfvkTexture;
    in_draw_scope(|r, ctx| {
        let buffer = vk::Buffer::from_raw(PLACEHOLDER);
        let with = |field: &str, t: *const FfvkTexture| {
            let mut draw = draw_info(&buffer, defaults());
            match field {
                "texture" => draw.texture = t,
                "texture2" => draw.texture2 = t,
                "cube_map" => draw.cube_map = t,
                "cube_map1" => draw.cube_map1 = t,
                "cube_map2" => draw.cube_map2 = t,
                _ => draw.cube_map3 = t,
            }
            draw
        };
        for field in ["cube_map", "cube_map1", "cube_map2", "cube_map3"] {
            let given = format!("{field} 0x1001 is not aligned");
            let draw = with(field, bad);
            assert_draw_refused(
                r,
                ctx,
                &draw,
                &given,
                "expected a cube map from ffvkCreateCubeMap or null",
            );
        }
        let version_4 = <FfvkDrawInfo as Versioned>::VERSIONS[3].size as u32;
        let draw = FfvkDrawInfo {
            struct_size: version_4,
            cube_map: bad,
            cube_map3: bad,
            ..draw_info(&buffer, defaults())
        };
        assert_drawn(r, ctx, &draw);

        let (view, sampler) = (vk::ImageView::from_raw(0x10), vk::Sampler::from_raw(0x20));
        let (mut flat, mut cube) = (std::ptr::null_mut(), std::ptr::null_mut());
        // SAFETY: a live renderer; the handles are never used by a draw that is recorded
        // (every draw below is refused); the outs are writable.
        unsafe {
            assert_eq!(
                ffvkCreateTexture(r, view, sampler, &mut flat),
                FfvkResult::FFVK_SUCCESS
            );
            assert_eq!(
                ffvkCreateCubeMap(r, view, sampler, &mut cube),
                FfvkResult::FFVK_SUCCESS
            );
        }
        for (field, t, unit, words) in [
            ("texture", cube, 0, "is a cube map (GL_TEXTURE_CUBE_MAP): expected a GL_TEXTURE_2D binding from ffvkCreateTexture or null (a cube map goes in cube_map)"),
            ("texture2", cube, 2, "is a cube map (GL_TEXTURE_CUBE_MAP): expected a GL_TEXTURE_2D binding from ffvkCreateTexture or null (a cube map goes in cube_map2)"),
            ("cube_map", flat, 0, "is a 2D texture (GL_TEXTURE_2D): expected a GL_TEXTURE_CUBE_MAP binding from ffvkCreateCubeMap or null (a 2D texture goes in texture)"),
            ("cube_map3", flat, 3, "is a 2D texture (GL_TEXTURE_2D): expected a GL_TEXTURE_CUBE_MAP binding from ffvkCreateCubeMap or null (a 2D texture goes in texture3)"),
        ] {
            let given = format!("{field} (unit {unit}, GL_TEXTURE{unit}) {t:p}");
            assert_draw_refused(r, ctx, &with(field, t), &given, words);
        }
        let mut out = std::ptr::NonNull::<FfvkTexture>::dangling().as_ptr();
        // SAFETY: a live renderer; null handles are refused before use; out is writable.
        unsafe {
            let result = ffvkCreateCubeMap(r, vk::ImageView::null(), sampler, &mut out);
            assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
            assert!(out.is_null(), "the out pointer is left {out:?}");
            assert_eq!(
                message(),
                "ffvkCreateCubeMap: view or sampler is VK_NULL_HANDLE: expected the caller's cube image view and sampler"
            );
            let result = ffvkCreateCubeMap(r, view, sampler, std::ptr::null_mut());
            assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
            assert_eq!(
                message(),
                "ffvkCreateCubeMap: cube_map is a null pointer: expected where to write the cube map"
            );
            ffvkDestroyTexture(flat);
            ffvkDestroyTexture(cube);
        }
    });
}

/// A vertex layout's coordinate arrays of units 1 to 3 (version 2) are checked as the others
/// are, naming their field; a version 1 layout info never reads them.
#[test]
fn a_vertex_layouts_unit_coordinate_arrays_are_checked_and_an_older_info_never_reads_them() {
    let plain = PlainDevice::new();
    let mut r = std::ptr::null_mut();
    // SAFETY: a valid create info on a live device; out is writable.
    let made = unsafe { ffvkCreateRenderer(&create_info(&plain), &mut r) };
    assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
    let binding = vk::VertexInputBindingDescription {
        binding: 0,
        stride: 20,
        input_rate: vk::VertexInputRate::VERTEX,
    };
    let st = FfvkAttribute {
        binding: 0,
        offset: 12,
        format: vk::Format::R32G32_SFLOAT,
    };
    let past = FfvkAttribute { offset: 16, ..st };
    let info = FfvkVertexLayoutInfo {
        struct_size: std::mem::size_of::<FfvkVertexLayoutInfo>() as u32,
        bindings: &binding,
        binding_count: 1,
        position: FfvkAttribute {
            binding: 0,
            offset: 0,
            format: vk::Format::R32G32B32_SFLOAT,
        },
        normal: std::ptr::null(),
        color: std::ptr::null(),
        texcoord: &st,
        secondary_color: std::ptr::null(),
        fog_coord: std::ptr::null(),
        materials: std::ptr::null(),
        material_count: 0,
        texcoord1: std::ptr::null(),
        texcoord2: &st,
        texcoord3: std::ptr::null(),
    };
    let make = |info: &FfvkVertexLayoutInfo| {
        let mut layout = std::ptr::null_mut();
        // SAFETY: a live renderer between scopes; the info's pointers are null, misaligned (and
        // refused before use) or point at live attributes; out is writable.
        let result = unsafe { ffvkCreateVertexLayout(r, info, &mut layout) };
        // SAFETY: null or a layout just made.
        unsafe { ffvkDestroyVertexLayout(layout) };
        (result, message())
    };
    assert_eq!(make(&info).0, FfvkResult::FFVK_SUCCESS, "{}", make(&info).1);
    let misaligned = FfvkVertexLayoutInfo {
        texcoord3: 0x2002 as *const FfvkAttribute,
        ..info
    };
    let (result, text) = make(&misaligned);
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{text}");
    assert!(
        text.starts_with("ffvkCreateVertexLayout: texcoord3 0x2002 is not aligned"),
        "{text}"
    );
    // Past its binding's stride (16 + 8 > 20): named as the core names unit 1's array.
    let (result, text) = make(&FfvkVertexLayoutInfo {
        texcoord1: &past,
        ..info
    });
    assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT, "{text}");
    assert!(text.contains("unit 1 texcoord"), "{text}");
    let version_1 = <FfvkVertexLayoutInfo as Versioned>::VERSIONS[0].size as u32;
    let older = FfvkVertexLayoutInfo {
        struct_size: version_1,
        texcoord1: &past,
        ..misaligned
    };
    let (result, text) = make(&older);
    assert_eq!(
        result,
        FfvkResult::FFVK_SUCCESS,
        "a version 1 info reads no unit array: {text}"
    );
    // SAFETY: live, destroyed once.
    unsafe { ffvkDestroyRenderer(r) };
}

#[test]
fn ffvk_draw_names_a_gl_mode_it_does_not_draw_directly_by_its_gl_name() {
    in_draw_scope(|r, ctx| {
        let buffer = vk::Buffer::from_raw(PLACEHOLDER);
        for (mode, name) in [
            (0x0002, "GL_LINE_LOOP"),
            (0x0008, "GL_QUAD_STRIP"),
            (0x0009, "GL_POLYGON"),
        ] {
            let draw = FfvkDrawInfo {
                mode,
                ..draw_info(&buffer, defaults())
            };
            let given = format!("mode {name} (0x{mode:04X}) is drawn as a list");
            assert_draw_refused(r, ctx, &draw, &given, "ffvkPrimitiveIndicesRange");
        }
        let draw = FfvkDrawInfo {
            mode: 0x0B71,
            ..draw_info(&buffer, defaults())
        };
        assert_draw_refused(
            r,
            ctx,
            &draw,
            "mode GL_DEPTH_TEST (0x0B71) is not a GL primitive",
            "expected GL_POINTS",
        );
        let draw = FfvkDrawInfo {
            mode: 0x000A,
            ..draw_info(&buffer, defaults())
        };
        assert_draw_refused(
            r,
            ctx,
            &draw,
            "mode 0x000A is not a GL primitive",
            "expected GL_POINTS",
        );
    });
}
