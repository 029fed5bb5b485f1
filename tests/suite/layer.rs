//! A pipeline ffvk does not own: the layer example (`ffvk/examples/layer.rs`) draws with its
//! own shaders, which include the shader library, its own uniform block, descriptor set,
//! specialization constants and pipelines, and a stage of its own (a vignette).

// It brings its own copy of the embedding example, which crate::embedding also includes.
#[path = "../../ffvk/examples/layer.rs"]
#[allow(dead_code, clippy::duplicate_mod)]
mod example;

use ffvk::gl::state::{FixedFunctionState, LightingMode};
use ffvk::{Draw, Frame};
use ffvk_cli::gl_reference::GlDraw;
use glam::Vec4;
use image::RgbaImage;

use crate::conformance::{check_against_gl, gl_draw_image, SIZE};
use crate::embedding::assert_same_bytes;
use crate::support::*;

/// The teapot under `state`, drawn by ffvk's own pipelines at `SIZE`.
fn ffvk_frame(r: &mut ffvk::Renderer, mesh: &ffvk::Mesh, state: &FixedFunctionState) -> ffvk::Pixels {
    let mut frame = Frame::new(SIZE, SIZE);
    frame.clear_color = Vec4::from_array(example::CLEAR);
    frame
        .draws
        .push(Draw::new(mesh, example::view(), example::projection(), *state));
    r.render(&frame).unwrap()
}

/// The layer's images of `frames` at `SIZE`, with the validation layer on.
fn layer_images(frames: &[example::LayerFrame]) -> Vec<Vec<u8>> {
    example::render(None, true, SIZE, frames).unwrap_or_else(|e| panic!("the layer example renders: {e}"))
}

/// With nothing of its own added, the layer's pipelines draw the bytes ffvk's own draw: the
/// teapot lit per vertex, per fragment and flat, and with fog and the alpha test in the vertex
/// and fragment modes (the library's lighting, color sum, fog and alpha test, in the caller's
/// shaders, at the caller's bindings and constant IDs).
#[test]
fn a_layers_own_pipelines_built_on_the_library_draw_ffvks_bytes_in_every_mode() {
    let frames: Vec<(String, example::LayerFrame)> = example::frames()
        .unwrap()
        .into_iter()
        .filter(|(_, f)| !f.vignette)
        .collect();
    assert_eq!(frames.len(), 5, "three modes, then fog and alpha in two");
    let only: Vec<example::LayerFrame> = frames.iter().map(|(_, f)| *f).collect();
    let images = layer_images(&only);
    let mut r = renderer();
    let mesh = r.upload(&example::teapot().unwrap()).unwrap();
    for ((name, frame), bytes) in frames.iter().zip(images) {
        let ours = ffvk_frame(&mut r, &mesh, &frame.state);
        assert_same_bytes(&ours, &bytes, &format!("layer_{name}"));
        let clear = example::CLEAR.map(|c| (c * 255.0).round() as u8);
        assert_ne!(
            ours.pixel(SIZE / 2, SIZE / 2),
            Some(clear),
            "{name}: the teapot covers the centre"
        );
    }
    // The alpha test drops something: the teapot's inside, seen through its openings.
    let fogged = example::fogged_state(LightingMode::Vertex).unwrap();
    let mut untested = fogged;
    untested.fragment.alpha_test.enabled = false;
    let (with, without) = (
        ffvk_frame(&mut r, &mesh, &fogged),
        ffvk_frame(&mut r, &mesh, &untested),
    );
    let dropped = with
        .rgba()
        .chunks(4)
        .zip(without.rgba().chunks(4))
        .filter(|(a, b)| a != b)
        .count();
    assert!(dropped > 0, "the alpha test drops the back faces");
    finish(r);
}

/// The layer's fog and alpha test, in its own pipeline, against Mesa's GL given the same state
/// through GL's entry points (per vertex: GL has no per-fragment lighting).
#[test]
fn the_layers_fog_and_alpha_test_match_mesa_gl() {
    let state = example::fogged_state(LightingMode::Vertex).unwrap();
    let frame = example::LayerFrame {
        state,
        vignette: false,
    };
    let bytes = layer_images(&[frame]).remove(0);
    let ours = RgbaImage::from_raw(SIZE, SIZE, bytes).unwrap();
    let teapot = example::teapot().unwrap();
    let (view, projection) = (example::view(), example::projection());
    let theirs = gl_draw_image(GlDraw::new(&teapot, view, projection, state), example::CLEAR);
    let mut r = renderer();
    let checked = check_against_gl(
        &mut r,
        "layer_fog_alpha",
        &ours,
        &theirs,
        &teapot,
        view,
        projection,
    );
    finish(r);
    checked.unwrap();
    // Fogged: the teapot's centre is nearer the fog colour than the unfogged teapot's.
    let mut clear_air = state;
    clear_air.fragment.fog.enabled = false;
    let unfogged = layer_images(&[example::LayerFrame {
        state: clear_air,
        vignette: false,
    }])
    .remove(0);
    let at = ((SIZE / 2 * SIZE + SIZE / 2) * 4) as usize;
    assert_ne!(
        &unfogged[at..at + 4],
        ours.get_pixel(SIZE / 2, SIZE / 2).0.as_slice(),
        "fog changes the centre"
    );
}

/// The layer's own stage: each pixel of the vignetted image is the plain image's pixel times
/// the layer's factor at the pixel's centre, computed here in double precision (within the
/// 1/255 of rounding twice); undrawn pixels keep the clear colour.
#[test]
fn the_layers_vignette_darkens_each_pixel_by_its_own_factor() {
    for mode in [LightingMode::Vertex, LightingMode::Fragment] {
        let state = example::fogged_state(mode).unwrap();
        let images = layer_images(&[false, true].map(|vignette| example::LayerFrame { state, vignette }));
        let (plain, vignetted) = (&images[0], &images[1]);
        let clear = example::CLEAR.map(|c| (c * 255.0).round() as u8);
        let mut darkened = 0;
        for (i, (p, v)) in plain.chunks(4).zip(vignetted.chunks(4)).enumerate() {
            let (x, y) = ((i as u32 % SIZE) as f64 + 0.5, (i as u32 / SIZE) as f64 + 0.5);
            if p == clear && v == clear {
                continue;
            }
            let f = example::vignette(x, y, SIZE);
            for c in 0..3 {
                let expected = p[c] as f64 * f;
                assert!(
                    (v[c] as f64 - expected).abs() <= 1.0,
                    "{}: pixel ({x}, {y}) channel {c}: {} after the vignette, expected {expected:.2} ({} × {f:.4})",
                    mode.name(),
                    v[c],
                    p[c]
                );
            }
            assert_eq!(
                v[3],
                p[3],
                "{}: the vignette leaves alpha alone at ({x}, {y})",
                mode.name()
            );
            darkened += usize::from(v != p);
        }
        assert!(
            darkened > 1000,
            "{}: the vignette darkens the teapot's edges ({darkened} pixels)",
            mode.name()
        );
    }
}

/// Builds the layer's OpenGL ES 3 program (`ffvk/examples/gles/layer_gles.c`) with the
/// system's C compiler against EGL and GLES 2/3 (libegl-dev, libgles-dev).
fn gles_program() -> std::path::PathBuf {
    let source = concat!(env!("CARGO_MANIFEST_DIR"), "/ffvk/examples/gles/layer_gles.c");
    let dir = output_dir().join("layer_gles");
    std::fs::create_dir_all(&dir).unwrap();
    let program = dir.join("layer_gles");
    let out = std::process::Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-O1", source, "-o"])
        .arg(&program)
        .args(["-lEGL", "-lGLESv2"])
        .output()
        .expect("cc runs (the C API's tests need it too)");
    assert!(
        out.status.success(),
        "cc layer_gles.c:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    program
}

/// The layer's frame drawn by its ES program on Mesa's OpenGL ES 3 (llvmpipe, through EGL
/// without a surface): its shaders as GLSL ES 3.00 with the library's ES header, the switches
/// as defines, its blocks from uniform buffers, GL's own projection. Returns the image, top row
/// first, and what GL_RENDERER and GL_VERSION said.
fn gles_image(program: &std::path::Path, name: &str, frame: &example::LayerFrame) -> (Vec<u8>, String) {
    use ffvk::gpu::layout::{DrawBlock, SpecKey};
    let dir = output_dir().join("layer_gles").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let state = &frame.state;
    let (modelview, projection) = (example::view(), example::projection());
    let key = SpecKey::for_pipeline(
        state,
        modelview,
        &ffvk::PipelineConstants::new(
            ffvk::Topology::TriangleList,
            ffvk::ash::vk::Format::R8G8B8A8_UNORM,
        ),
    );
    let target = example::ShaderTarget::Es {
        key: &key,
        vignette: frame.vignette,
        size: SIZE,
    };
    for stage in ["vert", "frag"] {
        let text = example::source(stage, state.mode, &target).unwrap();
        std::fs::write(dir.join(format!("{stage}.glsl")), text).unwrap();
    }
    let mut block = DrawBlock::new(state, modelview, projection).unwrap();
    // The block's projection is Vulkan's clip space (y flipped, z in [0, w]); GL's is GL's own.
    block.state.projection = projection.to_cols_array();
    std::fs::write(dir.join("draw.bin"), bytemuck::bytes_of(&block.record)).unwrap();
    std::fs::write(dir.join("state.bin"), bytemuck::bytes_of(&block.state)).unwrap();
    // The teapot as the Vulkan side's buffers hold it (the embedding example's `scene`).
    let mesh = example::teapot().unwrap();
    let positions: Vec<[f32; 3]> = mesh.vertices.iter().map(|v| v.position).collect();
    let mut attributes = Vec::with_capacity(mesh.vertices.len() * 16);
    for v in &mesh.vertices {
        attributes.extend_from_slice(bytemuck::cast_slice(&v.normal));
        attributes.extend(v.color.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8));
    }
    std::fs::write(dir.join("positions.bin"), bytemuck::cast_slice(&positions)).unwrap();
    std::fs::write(dir.join("attributes.bin"), &attributes).unwrap();
    std::fs::write(dir.join("indices.bin"), bytemuck::cast_slice(&mesh.indices)).unwrap();
    let out = std::process::Command::new(program)
        .arg(&dir)
        .arg(SIZE.to_string())
        .args(example::CLEAR.map(|c| c.to_string()))
        // Mesa's software rasterizer, whatever GPU the machine has.
        .env("LIBGL_ALWAYS_SOFTWARE", "1")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{name}: the ES program failed (shaders in {}):\n{}",
        dir.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    let rgba = std::fs::read(dir.join("image.rgba")).unwrap();
    (rgba, String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// The library as GLSL ES 3.00: the layer's shaders, the library's functions unchanged behind
/// its ES header, in an OpenGL ES 3 context on Mesa, draw the images ffvk's Vulkan pipelines
/// draw within 1/255 at every pixel but those along silhouettes, where GL's and Vulkan's
/// rasterization of the mirrored (y-flipped) triangles may cover a pixel differently.
#[test]
fn the_library_compiled_as_glsl_es_draws_ffvks_images_on_mesas_gles() {
    let program = gles_program();
    let mut frames: Vec<(String, example::LayerFrame)> = example::frames().unwrap();
    frames.retain(|(name, _)| name.starts_with("teapot") || name.ends_with("vignette"));
    assert_eq!(
        frames.len(),
        5,
        "three modes, fog and alpha with the vignette in two"
    );
    let only: Vec<example::LayerFrame> = frames.iter().map(|(_, f)| *f).collect();
    let vulkan = layer_images(&only);
    let mut report = Vec::new();
    for ((name, frame), ours) in frames.iter().zip(&vulkan) {
        let (es, renderer) = gles_image(&program, name, frame);
        assert!(renderer.contains("OpenGL ES 3"), "{name}: {renderer}");
        let (mut compared, mut beyond, mut worst) = (0, 0, 0u8);
        let at = |x: i64, y: i64| ((y * SIZE as i64 + x) * 4) as usize;
        let clear = example::CLEAR.map(|c| (c * 255.0).round() as u8);
        for y in 1..SIZE as i64 - 1 {
            for x in 1..SIZE as i64 - 1 {
                // Covered in both images, as are its eight neighbours: not on a silhouette.
                let covered = |img: &[u8], x: i64, y: i64| img[at(x, y)..at(x, y) + 4] != clear;
                let inside = (-1..=1).all(|dy| {
                    (-1..=1).all(|dx| covered(ours, x + dx, y + dy) && covered(&es, x + dx, y + dy))
                });
                if !inside {
                    continue;
                }
                compared += 1;
                let d = (0..4)
                    .map(|c| ours[at(x, y) + c].abs_diff(es[at(x, y) + c]))
                    .max()
                    .unwrap();
                worst = worst.max(d);
                beyond += usize::from(d > 1);
            }
        }
        report.push(format!(
            "{name}: {compared} pixels compared, {beyond} beyond 1/255, worst {worst}/255"
        ));
        let es_image = RgbaImage::from_raw(SIZE, SIZE, es.clone()).unwrap();
        save_for_inspection(&es_image, &format!("layer_gles_{name}"));
        assert!(
            compared > 2000,
            "{name}: the teapot covers the image ({compared} pixels)"
        );
        assert!(
            beyond == 0,
            "{name}: ES and Vulkan differ beyond 1/255 at {beyond} of {compared} pixels (worst {worst}/255; tests/output/layer_gles_{name}.png)\n{renderer}"
        );
    }
    eprintln!("{}", report.join("\n"));
}

/// The guide's GLSL ES snippet (docs/shader-library.md, "GLSL ES 3.00"), completed as its
/// comments say (the defines of a state in place of the comment line, a `main`) and its
/// includes resolved, compiles in Mesa's OpenGL ES 3 as a vertex shader.
#[test]
fn the_guides_glsl_es_snippet_compiles_on_mesas_gles() {
    let program = gles_program();
    let guide =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/shader-library.md")).unwrap();
    let snippet = guide
        .split("```glsl\n")
        .skip(1)
        .map(|s| s.split("```").next().unwrap())
        .find(|s| s.starts_with("#version 300 es"))
        .expect("docs/shader-library.md has a GLSL ES snippet");
    let state = example::fogged_state(LightingMode::Vertex).unwrap();
    let key = ffvk::gpu::layout::SpecKey::for_pipeline(
        &state,
        example::view(),
        &ffvk::PipelineConstants::new(
            ffvk::Topology::TriangleList,
            ffvk::ash::vk::Format::R8G8B8A8_UNORM,
        ),
    );
    let defines_line = snippet
        .lines()
        .find(|l| l.contains("spec_defines"))
        .expect("the snippet says where the defines go");
    let completed = snippet.replace(defines_line, ffvk::shaders::spec_defines(&key).trim_end())
        + "void main() { gl_Position = vec4(float(lighting_enabled())); }\n";
    let resolved = ffvk::shaders::resolve(&completed).unwrap();
    let path = output_dir().join("layer_gles").join("guide_snippet.vert");
    std::fs::write(&path, resolved).unwrap();
    let out = std::process::Command::new(program)
        .args(["--compile", "vert"])
        .arg(&path)
        .env("LIBGL_ALWAYS_SOFTWARE", "1")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "the guide's ES snippet ({}):\n{}",
        path.display(),
        String::from_utf8_lossy(&out.stderr)
    );
}
