//! The fuzz harness at the C boundary (issue 46): generated create infos (formats, sample
//! counts, attribute offsets, frame counts, raw values Vulkan does not define among them) and
//! generated raster states, passed to `ffvkCreateRenderer` and `ffvkDraw` on lavapipe. Each
//! is accepted exactly when an oracle written from Vulkan's rules and the device's answers
//! says it is valid, and otherwise refused with `FFVK_ERROR_INVALID_ARGUMENT` and a message
//! naming the function and the field: never a crash, never an unknown value passed on.
//! `FFVK_FUZZ_SCALE` multiplies the case counts, as for the other fuzz tests.

use ffvk::ash::vk::{self, Handle};
use ffvk_c::gl::*;
use ffvk_c::render::*;
use ffvk_c::result::FfvkResult;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

use crate::c_api_boundary::{create, create_info, message, BINDINGS};
use crate::embedding::PlainDevice;
use crate::fuzz::runner;

/// A raw value: mostly near the valid ones, sometimes anything.
fn raw_i32(near: std::ops::Range<i32>) -> BoxedStrategy<i32> {
    prop_oneof![4 => near, 1 => any::<i32>()].boxed()
}

/// What the device says about `format` for `feature`; unknown values are never asked about.
fn has(plain: &PlainDevice, format: vk::Format, feature: vk::FormatFeatureFlags) -> bool {
    if !(1..=184).contains(&format.as_raw()) {
        return false;
    }
    // SAFETY: a live physical device and a core format.
    let p = unsafe {
        plain
            .instance
            .get_physical_device_format_properties(plain.physical, format)
    };
    (p.optimal_tiling_features | p.linear_tiling_features).contains(feature)
}

/// Whether a create info with these values may make a renderer, by Vulkan's rules: a color
/// format the shaders write as floats (not integer, depth or compressed) that the device
/// renders into, no depth or a depth format it has, one sample-count bit among its
/// framebuffer counts, the normal within the 24-byte element, 1..=64 frames.
fn valid(plain: &PlainDevice, info: &FfvkRendererCreateInfo) -> bool {
    // SAFETY: the physical device is live.
    let limits = unsafe { plain.instance.get_physical_device_properties(plain.physical) }.limits;
    let name = format!("{:?}", info.color_format);
    let float_color = (1..=123).contains(&info.color_format.as_raw())
        && !name.contains("_UINT")
        && !name.contains("_SINT")
        && !["D16", "D24", "D32", "S8_"].iter().any(|d| name.contains(d));
    let color = float_color && has(plain, info.color_format, vk::FormatFeatureFlags::COLOR_ATTACHMENT);
    let depth_name = format!("{:?}", info.depth_format);
    let (depth, mut counts) = if info.depth_format == vk::Format::UNDEFINED {
        (true, limits.framebuffer_color_sample_counts)
    } else {
        let is_depth = ["D16", "D24", "D32"].iter().any(|d| depth_name.contains(d));
        let mut counts = limits.framebuffer_color_sample_counts & limits.framebuffer_depth_sample_counts;
        if depth_name.contains("S8") {
            counts &= limits.framebuffer_stencil_sample_counts;
        }
        (
            is_depth
                && has(
                    plain,
                    info.depth_format,
                    vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT,
                ),
            counts,
        )
    };
    counts &= vk::SampleCountFlags::from_raw(0x7F);
    let samples = info.samples.as_raw().count_ones() == 1 && counts.contains(info.samples);
    let normal = info.normal.offset.checked_add(12).is_some_and(|end| end <= 24);
    color && depth && samples && normal && (1..=64).contains(&info.frames_in_flight)
}

#[test]
fn generated_create_infos_make_a_renderer_exactly_when_every_value_is_valid() {
    let plain = PlainDevice::new();
    // Each value mostly one a device renders (so that whole create infos are often valid),
    // otherwise anything.
    let values = (
        prop_oneof![3 => prop::sample::select(vec![37, 44, 43, 97]), 1 => raw_i32(0..200)],
        prop_oneof![2 => Just(0), 2 => prop::sample::select(vec![124, 126, 129, 130]), 1 => raw_i32(0..200)],
        prop_oneof![3 => prop::sample::select(vec![1u32, 4]), 1 => (0..8u32).prop_map(|b| 1u32 << b), 1 => any::<u32>()],
        prop_oneof![3 => 0..=12u32, 1 => 0..30u32, 1 => any::<u32>()],
        prop_oneof![3 => 1..=64u32, 1 => 0..70u32, 1 => any::<u32>()],
    );
    let accepted = std::cell::Cell::new(0u32);
    runner(128)
        .run(&values, |(color, depth, samples, offset, frames)| {
            let info = FfvkRendererCreateInfo {
                color_format: vk::Format::from_raw(color),
                depth_format: vk::Format::from_raw(depth),
                samples: vk::SampleCountFlags::from_raw(samples),
                normal: FfvkAttribute {
                    offset,
                    ..create_info(&plain).normal
                },
                frames_in_flight: frames,
                ..create_info(&plain)
            };
            let (result, text) = create(&info);
            let expected = valid(&plain, &info);
            if expected {
                accepted.set(accepted.get() + 1);
                prop_assert_eq!(
                    result,
                    FfvkResult::FFVK_SUCCESS,
                    "refused a valid create info: {}",
                    text
                );
            } else {
                prop_assert_eq!(
                    result,
                    FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                    "accepted: {}",
                    text
                );
                let named = [
                    "color_format",
                    "depth_format",
                    "samples",
                    "normal attribute",
                    "frames_in_flight",
                ]
                .iter()
                .any(|field| text.contains(field));
                prop_assert!(text.starts_with("ffvkCreateRenderer: ") && named, "{}", text);
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        accepted.get() > 0,
        "no generated create info was valid: the oracle or the generator is off"
    );
    assert_eq!(BINDINGS[0].stride, 24, "the oracle's element size");
}

/// Whether ffvk may pass a raster state on: Vulkan's core enums (GL's blend factors and
/// equations, no dual-source factors), the blend values only while blending.
fn valid_raster(r: &FfvkRaster) -> bool {
    let blend_ok = r.blend == 0
        || [r.src_color, r.dst_color, r.src_alpha, r.dst_alpha]
            .iter()
            .all(|f| (0..=14).contains(&f.as_raw()))
            && [r.color_op, r.alpha_op]
                .iter()
                .all(|op| (0..=4).contains(&op.as_raw()));
    r.cull_mode.as_raw() <= 3
        && (0..=1).contains(&r.front_face.as_raw())
        && (0..=7).contains(&r.depth_compare.as_raw())
        && blend_ok
}

#[test]
fn generated_raster_states_are_drawn_exactly_when_every_enum_is_one_vulkan_defines() {
    let plain = PlainDevice::new();
    let mut r = std::ptr::null_mut();
    // SAFETY: a valid create info on a live device; out is writable.
    let made = unsafe { ffvkCreateRenderer(&create_info(&plain), &mut r) };
    assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
    let ctx = ffvkCreateContext();
    let buffer = vk::Buffer::null();
    // SAFETY: a live renderer; the command buffer is a placeholder that is never recorded
    // into (the renderer is destroyed with its scope open).
    unsafe {
        assert_eq!(ffvkBeginFrame(r, 0), FfvkResult::FFVK_SUCCESS);
        assert_eq!(
            ffvkBeginDraws(r, vk::CommandBuffer::from_raw(0x1000), 0),
            FfvkResult::FFVK_SUCCESS
        );
    }
    let factor = || raw_i32(-1..20);
    let op = || raw_i32(-1..7);
    let values = (
        (
            prop_oneof![4 => 0..6u32, 1 => any::<u32>()],
            raw_i32(-1..3),
            raw_i32(-1..10),
            any::<bool>(),
        ),
        (factor(), factor(), op(), factor(), factor(), op()),
    );
    let (drawn, refused) = (std::cell::Cell::new(0u32), std::cell::Cell::new(0u32));
    let outcome = runner(96).run(
        &values,
        |((cull, front, compare, blend), (sc, dc, co, sa, da, ao))| {
            let raster = FfvkRaster {
                cull_mode: vk::CullModeFlags::from_raw(cull),
                front_face: vk::FrontFace::from_raw(front),
                depth_test: 1,
                depth_write: 1,
                depth_compare: vk::CompareOp::from_raw(compare),
                blend: blend as u8,
                src_color: vk::BlendFactor::from_raw(sc),
                dst_color: vk::BlendFactor::from_raw(dc),
                color_op: vk::BlendOp::from_raw(co),
                src_alpha: vk::BlendFactor::from_raw(sa),
                dst_alpha: vk::BlendFactor::from_raw(da),
                alpha_op: vk::BlendOp::from_raw(ao),
                point_size: 1.0,
                line_width: 1.0,
            };
            let draw = crate::c_api_boundary::draw_info(&buffer, raster);
            // SAFETY: live renderer and context, an open scope; the draw is only staged.
            let result = unsafe { ffvkDraw(r, ctx, &draw) };
            let text = message();
            if valid_raster(&raster) {
                drawn.set(drawn.get() + 1);
                prop_assert_eq!(result, FfvkResult::FFVK_SUCCESS, "refused {:?}: {}", raster, text);
            } else {
                refused.set(refused.get() + 1);
                prop_assert_eq!(
                    result,
                    FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                    "drew {:?}",
                    raster
                );
                prop_assert!(
                    text.starts_with("ffvkDraw: ") && text.contains("is not accepted: expected"),
                    "{}",
                    text
                );
            }
            Ok::<(), TestCaseError>(())
        },
    );
    // SAFETY: the renderer and context are live and not used after this.
    unsafe {
        ffvkDestroyRenderer(r);
        ffvkDestroyContext(ctx);
    }
    outcome.unwrap_or_else(|e| panic!("{e}"));
    let (drawn, refused) = (drawn.get(), refused.get());
    assert!(
        drawn > 0 && refused > 0,
        "{drawn} drawn, {refused} refused: the generator is off"
    );
}
