//! The render path end to end: clear, coverage, orientation, winding, depth, many frames,
//! errors.

use ffvk::gl::state::{Cap, Face, GlState, LightModelParam, MaterialParam};
use ffvk::{Draw, Error, Frame};
use glam::{DVec4, Mat4, Vec4};

use crate::support::*;

#[test]
fn clear_color_fills_the_image() {
    let mut r = renderer();
    let mut frame = Frame::new(32, 16);
    frame.clear_color = Vec4::new(0.25, 0.5, 0.75, 1.0);
    let image = r.render(&frame).unwrap().into_rgba_image();
    assert_eq!(image.dimensions(), (32, 16));
    for (x, y, _) in image.enumerate_pixels() {
        assert_pixel(&image, x, y, DVec4::new(0.25, 0.5, 0.75, 1.0), 0.5, "clear");
    }
    finish(r);
}

#[test]
fn top_of_the_view_is_the_top_row_and_x_points_right() {
    let mut r = renderer();
    // Unlit, identity matrices: NDC directly. A red quad in the top-left quarter.
    let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
    let mesh = r.upload(&quad(-1.0, 0.0, 0.0, 1.0, 0.0, red)).unwrap();
    let mut frame = Frame::new(64, 64);
    frame.draws.push(ndc_draw(&mesh));
    let image = r.render(&frame).unwrap().into_rgba_image();
    let black = DVec4::new(0.0, 0.0, 0.0, 1.0);
    assert_pixel(
        &image,
        10,
        10,
        DVec4::new(1.0, 0.0, 0.0, 1.0),
        0.0,
        "top-left is red",
    );
    assert_pixel(&image, 50, 10, black, 0.0, "top-right is clear");
    assert_pixel(&image, 10, 50, black, 0.0, "bottom-left is clear");
    // Coverage: exactly the 32×32 top-left pixels (edges at pixel boundaries).
    let covered = image.pixels().filter(|p| p.0[0] == 255).count();
    assert_eq!(covered, 32 * 32, "covered pixels");
    drop(frame);
    drop(mesh);
    finish(r);
}

/// Two-sided lighting with a red front emission and a blue back emission shows which face
/// the rasterizer took: counter-clockwise in GL window coordinates must be the front.
#[test]
fn counter_clockwise_is_front() {
    let mut r = renderer();
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    gl.light_model(LightModelParam::TwoSide(true)).unwrap();
    gl.light_model(LightModelParam::Ambient(Vec4::ZERO)).unwrap();
    gl.material(
        Face::Front,
        MaterialParam::Emission(Vec4::new(1.0, 0.0, 0.0, 1.0)),
    )
    .unwrap();
    gl.material(Face::Back, MaterialParam::Emission(Vec4::new(0.0, 0.0, 1.0, 1.0)))
        .unwrap();
    // Left quad counter-clockwise; right quad the same geometry mirrored in x, so clockwise.
    let ccw = r.upload(&quad(-1.0, -1.0, 0.0, 1.0, 0.0, Vec4::ONE)).unwrap();
    let mirror = Mat4::from_scale(glam::Vec3::new(-1.0, 1.0, 1.0));
    let mut frame = Frame::new(64, 64);
    for (modelview, _) in [(Mat4::IDENTITY, "ccw"), (mirror, "cw")] {
        frame
            .draws
            .push(Draw::new(&ccw, modelview, Mat4::IDENTITY, gl.lighting));
    }
    let image = r.render(&frame).unwrap().into_rgba_image();
    assert_pixel(
        &image,
        16,
        32,
        DVec4::new(1.0, 0.0, 0.0, 1.0),
        0.0,
        "ccw quad shows the front",
    );
    assert_pixel(
        &image,
        48,
        32,
        DVec4::new(0.0, 0.0, 1.0, 1.0),
        0.0,
        "cw quad shows the back",
    );
    drop(frame);
    drop(ccw);
    finish(r);
}

/// glCullFace: with GL_CULL_FACE and GL_BACK the clockwise (back-facing) copy is dropped and
/// the counter-clockwise one kept; GL_FRONT the other way round; GL_FRONT_AND_BACK drops both.
#[test]
fn cull_face_drops_the_faces_it_names() {
    let mut r = renderer();
    let white = Vec4::ONE;
    let ccw = r.upload(&quad(-1.0, -1.0, 0.0, 1.0, 0.0, white)).unwrap();
    let mirror = Mat4::from_scale(glam::Vec3::new(-1.0, 1.0, 1.0));
    let black = DVec4::new(0.0, 0.0, 0.0, 1.0);
    let lit = DVec4::ONE;
    for (cull, left, right) in [
        (None, lit, lit),
        (Some(Face::Back), lit, black),
        (Some(Face::Front), black, lit),
        (Some(Face::FrontAndBack), black, black),
    ] {
        let mut frame = Frame::new(64, 64);
        for modelview in [Mat4::IDENTITY, mirror] {
            let mut draw = ndc_draw(&ccw).with_cull_face(cull);
            draw.modelview = modelview;
            frame.draws.push(draw);
        }
        let image = r.render(&frame).unwrap().into_rgba_image();
        assert_pixel(
            &image,
            16,
            32,
            left,
            0.0,
            &format!("{cull:?}: the ccw quad (left)"),
        );
        assert_pixel(
            &image,
            48,
            32,
            right,
            0.0,
            &format!("{cull:?}: the cw quad (right)"),
        );
    }
    drop(ccw);
    finish(r);
}

#[test]
fn depth_test_keeps_the_nearest_surface() {
    let mut r = renderer();
    let near = r
        .upload(&quad(-1.0, -1.0, 1.0, 1.0, -0.5, Vec4::new(0.0, 1.0, 0.0, 1.0)))
        .unwrap();
    let far = r
        .upload(&quad(-1.0, -1.0, 1.0, 1.0, 0.5, Vec4::new(1.0, 0.0, 1.0, 1.0)))
        .unwrap();
    // GL's identity projection keeps z: -0.5 is nearer than 0.5. Draw near first.
    let mut frame = Frame::new(16, 16);
    frame.draws = vec![ndc_draw(&near), ndc_draw(&far)];
    let image = r.render(&frame).unwrap().into_rgba_image();
    assert_pixel(
        &image,
        8,
        8,
        DVec4::new(0.0, 1.0, 0.0, 1.0),
        0.0,
        "depth test on: near wins",
    );
    frame.depth_test = false;
    let image = r.render(&frame).unwrap().into_rgba_image();
    assert_pixel(
        &image,
        8,
        8,
        DVec4::new(1.0, 0.0, 1.0, 1.0),
        0.0,
        "depth test off: last wins",
    );
    drop(frame);
    drop((near, far));
    finish(r);
}

#[test]
fn one_renderer_draws_many_frames_and_sizes() {
    let mut r = renderer();
    let mesh = r.upload(&quad(-0.5, -0.5, 0.5, 0.5, 0.0, Vec4::ONE)).unwrap();
    for i in 0..60u32 {
        let size = 8 + (i % 5) * 12;
        let mut frame = Frame::new(size, size + 3);
        let g = i as f32 / 60.0;
        frame.clear_color = Vec4::new(0.0, g, 0.0, 1.0);
        // A growing number of draws exercises the uniform buffer's growth.
        for _ in 0..=i {
            frame.draws.push(ndc_draw(&mesh));
        }
        let image = r.render(&frame).unwrap().into_rgba_image();
        assert_eq!(image.dimensions(), (size, size + 3));
        assert_pixel(
            &image,
            0,
            0,
            DVec4::new(0.0, g as f64, 0.0, 1.0),
            0.51,
            &format!("frame {i} clear"),
        );
        assert_pixel(
            &image,
            size / 2,
            (size + 3) / 2,
            DVec4::ONE,
            0.0,
            &format!("frame {i} quad"),
        );
    }
    drop(mesh);
    finish(r);
}

#[test]
fn bad_sizes_and_meshes_are_errors() {
    let mut r = renderer();
    let max = r.device_info().max_image_dimension_2d;
    for (w, h) in [(0, 16), (16, 0), (max + 1, 4)] {
        match r.render(&Frame::new(w, h)) {
            Err(Error::InvalidSize { width, height, .. }) => assert_eq!((width, height), (w, h)),
            other => panic!("size {w}x{h}: expected InvalidSize, got {:?}", other.map(|_| ())),
        }
    }
    let mut bad = quad(-1.0, -1.0, 1.0, 1.0, 0.0, Vec4::ONE);
    bad.indices[4] = 9;
    let err = r.upload(&bad).err().expect("index 9 of 4 vertices is rejected");
    assert!(err.to_string().contains("index 4 is 9"), "{err}");
    bad.indices.pop();
    let err = r.upload(&bad).err().expect("5 indices are rejected");
    assert!(err.to_string().contains("multiple of 3"), "{err}");
    // The renderer still works after errors.
    let image = r.render(&Frame::new(4, 4)).unwrap().into_rgba_image();
    assert_eq!(image.dimensions(), (4, 4));
    finish(r);
}

#[test]
fn an_unknown_device_name_is_a_clear_error() {
    let err = ffvk::Renderer::new(
        &ffvk::RendererOptions::default()
            .with_device(Some("no-such-gpu".into()))
            .with_validation(ffvk::vk::Validation::Off),
    )
    .err()
    .expect("no device named no-such-gpu");
    let text = err.to_string();
    assert!(
        text.contains("no-such-gpu") && text.contains("llvmpipe"),
        "{text}"
    );
}

#[test]
fn measured_frames_report_timestamps_and_pipeline_statistics() {
    let mut r = renderer();
    let info = r.device_info().clone();
    assert!(
        info.timestamps_supported && info.pipeline_statistics_query,
        "lavapipe has timestamps and pipeline statistics: {info:?}"
    );
    // Unlit, identity matrices: a quad over the top-left 32×32 pixels, 4 vertices, 2 triangles.
    let mesh = r
        .upload(&quad(-1.0, 0.0, 0.0, 1.0, 0.0, Vec4::new(1.0, 0.0, 0.0, 1.0)))
        .unwrap();
    let mut frame = Frame::new(64, 64);
    frame.draws.push(ndc_draw(&mesh));
    let plain = r.render(&frame).unwrap().into_rgba_image();
    let (image, stats) = r.render_measured(&frame).unwrap();
    let image = image.into_rgba_image();
    assert_eq!(plain, image, "measuring does not change the image");
    let gpu = stats.gpu_ns.expect("timestamps");
    assert!(gpu > 0.0 && stats.wall_ns > 0.0, "{stats:?}");
    let p = stats.pipeline.expect("pipeline statistics");
    assert_eq!(p.input_assembly_vertices, 6, "{p:?}");
    assert_eq!(p.input_assembly_primitives, 2, "{p:?}");
    assert!((4..=6).contains(&p.vertex_shader_invocations), "{p:?}");
    assert_eq!(p.clipping_invocations, 2, "{p:?}");
    assert!(p.fragment_shader_invocations >= 32 * 32, "{p:?}");

    // Without readback: the same counters, and the image buffer is not needed.
    let again = r.measure(&frame).unwrap();
    assert_eq!(again.pipeline, Some(p));
    assert!(again.gpu_ns.is_some_and(|ns| ns > 0.0));

    // Repeated in one submission: one GPU time per frame, no statistics, the same image.
    let frames = r.measure_frames(&frame, 5).unwrap();
    assert_eq!(frames.len(), 5);
    assert!(
        frames
            .iter()
            .all(|s| s.gpu_ns.is_some_and(|ns| ns > 0.0) && s.pipeline.is_none()),
        "{frames:?}"
    );
    assert_eq!(r.render(&frame).unwrap().into_rgba_image(), plain);
    assert!(matches!(
        r.measure_frames(&frame, ffvk::renderer::MAX_REPEAT + 1),
        Err(Error::TooManyFrames {
            count: 4097,
            max: 4096
        })
    ));

    // No draws: nothing is shaded.
    let empty = Frame::new(64, 64);
    let none = r.measure(&empty).unwrap().pipeline.unwrap();
    assert_eq!(none.vertex_shader_invocations, 0);
    assert_eq!(none.fragment_shader_invocations, 0);
    drop(frame);
    drop(mesh);
    finish(r);
}

#[test]
fn a_mesh_from_another_renderer_is_an_error() {
    let mut a = renderer();
    let b = renderer();
    let foreign = b.upload(&quad(-1.0, -1.0, 1.0, 1.0, 0.0, Vec4::ONE)).unwrap();
    let mut frame = Frame::new(8, 8);
    frame.draws.push(ndc_draw(&foreign));
    let err = a.render(&frame).expect_err("a foreign mesh is refused");
    assert!(err.to_string().contains("another renderer"), "{err}");
    drop(frame);
    drop(foreign);
    finish(a);
    finish(b);
}
