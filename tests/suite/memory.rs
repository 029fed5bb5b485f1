//! Device memory: one allocator for every resource, meshes filled directly or through
//! staging copies with the same pixels, and memory use as the README states it.

use ffvk::gl::state::{Cap, GlState};
use ffvk::mesh::teapot::teapot;
use ffvk::mesh::MeshData;
use ffvk::{Draw, Frame, Pixels, Renderer, RendererOptions, Upload};
use glam::{Mat4, Vec3, Vec4};

use crate::support::*;

/// The teapot, lit with color material, at `size`², drawn by `r`.
fn teapot_frame(r: &mut Renderer, mesh: &MeshData, size: u32) -> Pixels {
    let uploaded = r.upload(mesh).unwrap();
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    gl.enable(Cap::Light(0)).unwrap();
    gl.enable(Cap::ColorMaterial).unwrap();
    let mut frame = Frame::new(size, size);
    frame.draws.push(Draw::new(
        &uploaded,
        Mat4::look_at_rh(Vec3::new(0.0, 1.2, 3.0), Vec3::new(0.0, -0.05, 0.0), Vec3::Y),
        perspective(40.0, 1.0, 0.5, 10.0),
        gl.lighting,
    ));
    r.render(&frame).unwrap()
}

#[test]
fn meshes_copied_through_a_staging_buffer_draw_the_same_pixels_as_meshes_written_directly() {
    let mesh = teapot(6).unwrap();
    let mut direct = renderer();
    let mut staged = renderer_from(RendererOptions::default().with_upload(Upload::Staging));
    let a = teapot_frame(&mut direct, &mesh, 96);
    let b = teapot_frame(&mut staged, &mesh, 96);
    let background = a.pixel(0, 0).unwrap();
    let covered = (0..96 * 96)
        .filter(|i| a.pixel(i % 96, i / 96) != Some(background))
        .count();
    assert!(covered > 96 * 96 / 10, "the teapot covers {covered} pixels only");
    if let Some(i) = (0..96 * 96).find(|i| a.pixel(i % 96, i / 96) != b.pixel(i % 96, i / 96)) {
        save_for_inspection(&b.clone().into_rgba_image(), "memory_staged");
        panic!(
            "pixel ({}, {}) differs: direct {:?}, staged {:?}",
            i % 96,
            i / 96,
            a.pixel(i % 96, i / 96),
            b.pixel(i % 96, i / 96)
        );
    }
    finish(direct);
    finish(staged);
}

#[test]
fn many_meshes_share_a_few_blocks_and_dropping_them_returns_every_allocation() {
    let r = renderer();
    let before = r.memory_usage();
    let quad = quad(-1.0, -1.0, 1.0, 1.0, 0.0, Vec4::ONE);
    let meshes: Vec<_> = (0..50).map(|_| r.upload(&quad).unwrap()).collect();
    let during = r.memory_usage();
    assert_eq!(
        during.live,
        before.live + 100,
        "a vertex and an index buffer per mesh"
    );
    assert!(
        during.blocks <= before.blocks + 1,
        "100 small buffers took {} new blocks of memory",
        during.blocks - before.blocks
    );
    assert_eq!(during.dedicated, 0);
    drop(meshes);
    let after = r.memory_usage();
    assert_eq!(after.live, before.live, "allocations left behind: {after:?}");
    assert_eq!(after.used_bytes, before.used_bytes);
    finish(r);
}

#[test]
fn a_frame_uses_twelve_bytes_a_pixel_and_a_mesh_forty_eight_a_vertex_and_four_an_index() {
    let mut r = renderer();
    let before = r.memory_usage().used_bytes;
    // Large enough for its vertex buffer (48 B a vertex, 9 MB) to take memory of its own.
    let mesh = teapot(60).unwrap();
    let uploaded = r.upload(&mesh).unwrap();
    let usage = r.memory_usage();
    let mesh_bytes = usage.used_bytes - before;
    let expected = 48 * mesh.vertices.len() as u64 + 4 * mesh.indices.len() as u64;
    assert!(
        mesh_bytes >= expected && mesh_bytes <= expected + (128 << 10),
        "the mesh uses {mesh_bytes} bytes, expected {expected} plus alignment"
    );
    assert!(
        usage.dedicated >= 1,
        "a {expected}-byte mesh shares a block: {usage:?}"
    );
    drop(uploaded);

    let before = r.memory_usage().used_bytes;
    r.render(&Frame::new(512, 512)).unwrap();
    let frame_bytes = r.memory_usage().used_bytes - before;
    let pixels = 512 * 512;
    // Color (RGBA8), depth (D32) and the readback copy (RGBA8); alignment and the first
    // block of uniforms on top.
    assert!(
        frame_bytes >= 12 * pixels && frame_bytes <= 12 * pixels + (1 << 20),
        "a 512² frame uses {frame_bytes} bytes"
    );
    finish(r);
}

#[test]
fn frames_measured_back_to_back_write_each_draws_uniforms_once() {
    let mut r = renderer();
    let quad = r.upload(&quad(-1.0, -1.0, 1.0, 1.0, 0.0, Vec4::ONE)).unwrap();
    let mut frame = Frame::new(32, 32);
    for _ in 0..40 {
        frame.draws.push(ndc_draw(&quad));
    }
    r.measure_frames(&frame, 1).unwrap();
    let one = r.memory_usage();
    // 1,000 repeats of 40 draws would need 40,000 blocks (93 MB) if each repeat wrote its own.
    let frames = r.measure_frames(&frame, 1000).unwrap();
    assert_eq!(frames.len(), 1000);
    assert_eq!(r.memory_usage(), one, "uniform memory grew with the repeats");
    drop(frame);
    drop(quad);
    finish(r);
}

#[test]
fn ffvk_info_names_the_memory_type_of_each_use() {
    let out = ffvk_command(&[&"info"]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    for usage in ["Gpu", "Uniforms", "Staging", "Readback"] {
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("memory for {usage}:")))
            .unwrap_or_else(|| panic!("no memory line for {usage}:\n{text}"));
        // lavapipe has one memory type, device-local and host-visible.
        assert!(line.contains("type 0 (DEVICE_LOCAL | HOST_VISIBLE"), "{line}");
    }
}
