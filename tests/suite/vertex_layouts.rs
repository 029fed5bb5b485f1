//! What an emulation layer hands ffvk per draw: any of GL's vertex layouts (one `Lighting` for
//! all of them), GL's current values where a layout has no array, and materials per vertex
//! (`glMaterial` between `glBegin` and `glEnd`), drawn against Mesa's GL issuing the same calls.

use ash::vk;
use ffvk::gl::state::{Cap, Face, GlState, LightParam, LightingMode, MaterialParam};
use ffvk::{
    Attribute, DrawValues, Geometry, Lighting, LightingOptions, LitDraw, MaterialArray, Target, Topology,
    VertexInput,
};
use ffvk_cli::gl_reference::{raw, render_raw_gl};
use glam::{Mat4, Vec3, Vec4};

use crate::canvas::{binding, max_difference, Canvas, QUAD};
use crate::support::save_for_inspection;

const SIZE: u32 = 48;

fn bytes_of<T: bytemuck::Pod>(values: &[T]) -> Vec<u8> {
    bytemuck::cast_slice(values).to_vec()
}

fn assert_matches_gl(ffvk: &image::RgbaImage, gl: &image::RgbaImage, name: &str) {
    let d = max_difference(ffvk, gl);
    // Kept for a look (tests/output), passing or not.
    save_for_inspection(ffvk, &format!("{name}_ffvk"));
    save_for_inspection(gl, &format!("{name}_mesa"));
    assert!(
        d <= 1,
        "{name}: ffvk and Mesa's GL differ by {d}/255 (images in tests/output)"
    );
}

/// Lighting with one white light (GL_LIGHT0's defaults: directional, toward +z), every
/// material parameter black, flat shading: piglit's `gl-1.0-dlist-materials` set-up.
fn dlist_materials_state() -> GlState {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    gl.enable(Cap::Light(0)).unwrap();
    for param in [
        LightParam::Ambient(Vec4::ONE),
        LightParam::Diffuse(Vec4::ONE),
        LightParam::Specular(Vec4::ONE),
    ] {
        gl.light(0, param).unwrap();
    }
    let black = Vec4::new(0.0, 0.0, 0.0, 1.0);
    for param in [
        MaterialParam::Ambient(black),
        MaterialParam::Diffuse(black),
        MaterialParam::Specular(black),
        MaterialParam::Emission(black),
    ] {
        gl.material(Face::FrontAndBack, param).unwrap();
    }
    gl.lighting.mode = LightingMode::Flat;
    gl.normal(Vec3::Z).unwrap();
    gl
}

/// Piglit's `gl-1.0-dlist-materials` (tests/spec/gl-1.0/dlist-materials.c): a triangle strip of
/// two quads whose vertices set `which` with glMaterial between glBegin and glEnd (red for
/// the left quad, green for the right), every vertex (`set_all`) or only v2 and v4; flat
/// shading, so each triangle takes its last vertex's material. The per-vertex materials a
/// layer hands ffvk are what GL's current material is at each vertex: v0 and v1 keep the
/// black set before the list unless `set_all`.
#[test]
fn materials_set_between_glbegin_and_glend_light_each_vertex_as_mesa_lights_piglits_dlist_materials() {
    let red = [1.0f32, 0.0, 0.0, 1.0];
    let green = [0.0f32, 1.0, 0.0, 1.0];
    let black = [0.0f32, 0.0, 0.0, 1.0];
    let corners: [[f32; 2]; 6] = [
        [-1.0, -1.0],
        [-1.0, 1.0],
        [0.0, -1.0],
        [0.0, 1.0],
        [1.0, -1.0],
        [1.0, 1.0],
    ];
    let mut canvas = Canvas::new(SIZE);
    let device = canvas.ffvk();
    let gl = dlist_materials_state();
    for (which, gl_name) in [
        (MaterialArray::Ambient, raw::AMBIENT),
        (MaterialArray::Diffuse, raw::DIFFUSE),
        (MaterialArray::Specular, raw::SPECULAR),
        (MaterialArray::Emission, raw::EMISSION),
    ] {
        for set_all in [false, true] {
            // x y, then the material: 24 bytes a vertex.
            let early = if set_all { red } else { black };
            let materials = [early, early, red, red, green, green];
            let mut vertices = Vec::new();
            for (xy, m) in corners.iter().zip(materials) {
                vertices.extend_from_slice(xy);
                vertices.extend_from_slice(&m);
            }
            let buffer = canvas.buffer(&bytes_of(&vertices));
            let input = VertexInput::new(
                vec![binding(24)],
                Attribute::new(0, 0, vk::Format::R32G32_SFLOAT),
                Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
            )
            .with_normal(None)
            .with_material(
                Face::FrontAndBack,
                which,
                Some(Attribute::new(0, 8, vk::Format::R32G32B32A32_SFLOAT)),
            );
            let options = LightingOptions::new(
                Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED),
                input,
            );
            let mut lighting = Lighting::new(&device, &options).unwrap();
            let buffers = [(buffer, 0)];
            let draw = LitDraw::new(
                &gl.lighting,
                Mat4::IDENTITY,
                Mat4::IDENTITY,
                &buffers,
                Geometry::vertices(6).with_topology(Topology::TriangleStrip),
            );
            lighting.begin_frame(0).unwrap();
            let mut result = Ok(());
            let ffvk = canvas
                .frame(|_, cmd| {
                    // SAFETY: the canvas's pass is open with viewport and scissor set; the
                    // buffer lives as long as the canvas.
                    result = unsafe { lighting.draw(cmd, 0, &draw) };
                })
                .unwrap();
            result.unwrap();
            drop(lighting);

            let mesa = render_raw_gl(SIZE, SIZE, |g| {
                // SAFETY: a context is current; the calls are piglit's.
                unsafe {
                    g.Enable(raw::LIGHTING);
                    g.Enable(raw::LIGHT0);
                    for pname in [raw::AMBIENT, raw::DIFFUSE, raw::SPECULAR] {
                        g.Lightfv(raw::LIGHT0, pname, [1.0f32; 4].as_ptr());
                    }
                    for pname in [raw::AMBIENT, raw::DIFFUSE, raw::SPECULAR, raw::EMISSION] {
                        g.Materialfv(raw::FRONT_AND_BACK, pname, black.as_ptr());
                    }
                    let list = g.GenLists(1);
                    g.NewList(list, raw::COMPILE);
                    g.ShadeModel(raw::FLAT);
                    g.Begin(raw::TRIANGLE_STRIP);
                    g.Normal3f(0.0, 0.0, 1.0);
                    for (i, xy) in corners.iter().enumerate() {
                        let color = if i < 4 { red } else { green };
                        if set_all || i == 2 || i == 4 {
                            g.Materialfv(raw::FRONT_AND_BACK, gl_name, color.as_ptr());
                        }
                        g.Vertex2f(xy[0], xy[1]);
                    }
                    g.End();
                    g.EndList();
                    g.CallList(list);
                    g.DeleteLists(list, 1);
                }
            })
            .expect("Mesa's GL renders");
            let name = format!("dlist_materials_{}_{set_all}", which.gl_name());
            // Piglit's probes: just left of the middle red, just right green.
            let probe = |x: u32| ffvk.get_pixel(x, SIZE / 2).0;
            assert_eq!(
                probe(SIZE / 2 - 2),
                [255, 0, 0, 255],
                "{name}: left of the middle"
            );
            assert_eq!(
                probe(SIZE / 2 + 2),
                [0, 255, 0, 255],
                "{name}: right of the middle"
            );
            assert_matches_gl(&ffvk, &mesa, &name);
        }
    }
    drop(device);
}

/// One `Lighting`, three layouts in one frame, a viewport of its own for each draw (the
/// caller's command between ffvk's draws): float normals; normals as GL_BYTE (all zero bytes,
/// which GL 2.1 converts to 1/255 each, so a diffuse material of 100 shows them: Vulkan's SNORM
/// would make them 0 and the quad ambient-dark); positions alone with the current normal
/// (glNormal) tilted away from the light.
#[test]
fn one_lighting_draws_three_vertex_layouts_in_one_frame_as_mesa_draws_the_same_calls() {
    let mut canvas = Canvas::new(SIZE);
    let device = canvas.ffvk();
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    gl.enable(Cap::Light(0)).unwrap();

    // Layout 0: x y z and a float normal, 24 bytes.
    let floats: Vec<f32> = QUAD
        .iter()
        .flat_map(|p| [p[0], p[1], p[2], 0.0, 0.0, 1.0])
        .collect();
    let float_buffer = canvas.buffer(&bytes_of(&floats));
    let float_layout = VertexInput::new(
        vec![binding(24)],
        Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
        Attribute::new(0, 12, vk::Format::R32G32B32_SFLOAT),
    );
    // Layout 1: x y z and a GL_BYTE normal padded to four bytes, 16 bytes.
    let mut with_bytes = Vec::new();
    for p in QUAD {
        with_bytes.extend_from_slice(&bytes_of(&p));
        with_bytes.extend_from_slice(&[0u8; 4]);
    }
    let byte_buffer = canvas.buffer(&with_bytes);
    let byte_layout = VertexInput::new(
        vec![binding(16)],
        Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
        Attribute::new(0, 12, vk::Format::R8G8B8A8_SNORM),
    );
    // Layout 2: x y z alone.
    let positions_buffer = canvas.buffer(&bytes_of(&QUAD));
    let position_layout = VertexInput::new(
        vec![binding(12)],
        Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
        Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
    )
    .with_normal(None);

    let options = LightingOptions::new(
        Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED),
        float_layout,
    );
    let mut lighting = Lighting::new(&device, &options).unwrap();
    let bytes = lighting.vertex_layout(byte_layout).unwrap();
    let positions = lighting.vertex_layout(position_layout).unwrap();

    let plain = DrawValues::of(&gl.lighting);
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Diffuse(Vec4::new(100.0, 50.0, 100.0, 1.0)),
    )
    .unwrap();
    let strong = DrawValues::of(&gl.lighting);
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Diffuse(Vec4::new(0.2, 0.8, 0.4, 1.0)),
    )
    .unwrap();
    let tilted_normal = Vec3::new(0.0, 0.6, 0.8);
    gl.normal(tilted_normal).unwrap();
    let tilted = DrawValues::of(&gl.lighting);

    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);
    let buffers = [[(float_buffer, 0)], [(byte_buffer, 0)], [(positions_buffer, 0)]];
    let draws = [
        LitDraw::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &buffers[0], strip)
            .with_values(Some(plain)),
        LitDraw::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &buffers[1], strip)
            .with_values(Some(strong))
            .with_layout(Some(bytes)),
        LitDraw::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &buffers[2], strip)
            .with_values(Some(tilted))
            .with_layout(Some(positions)),
    ];
    let third = SIZE / 3;
    lighting.begin_frame(0).unwrap();
    let mut results = Vec::new();
    let ffvk = canvas
        .frame(|device, cmd| {
            for (i, draw) in draws.iter().enumerate() {
                // GL's glViewport(i * third, 0, third, SIZE): full height, so y needs no flip.
                let viewport = vk::Viewport {
                    x: (i as u32 * third) as f32,
                    y: 0.0,
                    width: third as f32,
                    height: SIZE as f32,
                    min_depth: 0.0,
                    max_depth: 1.0,
                };
                // SAFETY: the canvas's pass is open; the viewport is the caller's own command
                // between ffvk's draws, which binds nothing.
                unsafe { device.cmd_set_viewport(cmd, 0, &[viewport]) };
                // SAFETY: as above; the buffers live as long as the canvas.
                results.push(unsafe { lighting.draw(cmd, 0, draw) });
            }
        })
        .unwrap();
    for r in results {
        r.unwrap();
    }
    drop(lighting);
    drop(device);

    let mesa = render_raw_gl(SIZE, SIZE, |g| {
        // SAFETY: a context is current; the calls are those a GL 1.x program makes.
        unsafe {
            g.Enable(raw::LIGHTING);
            g.Enable(raw::LIGHT0);
            let strip = |g: &raw::Gl, normal: &dyn Fn(&raw::Gl)| {
                g.Begin(raw::TRIANGLE_STRIP);
                for p in QUAD {
                    normal(g);
                    g.Vertex3f(p[0], p[1], p[2]);
                }
                g.End();
            };
            g.Viewport(0, 0, third as i32, SIZE as i32);
            strip(g, &|g| g.Normal3f(0.0, 0.0, 1.0));
            g.Viewport(third as i32, 0, third as i32, SIZE as i32);
            g.Materialfv(
                raw::FRONT_AND_BACK,
                raw::DIFFUSE,
                [100.0f32, 50.0, 100.0, 1.0].as_ptr(),
            );
            // glNormal3b converts as GL 2.1 says (Mesa's BYTE_TO_FLOAT).
            strip(g, &|g| g.Normal3b(0, 0, 0));
            g.Viewport(2 * third as i32, 0, third as i32, SIZE as i32);
            g.Materialfv(
                raw::FRONT_AND_BACK,
                raw::DIFFUSE,
                [0.2f32, 0.8, 0.4, 1.0].as_ptr(),
            );
            g.Normal3f(tilted_normal.x, tilted_normal.y, tilted_normal.z);
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
        }
    })
    .expect("Mesa's GL renders");
    // The byte normals are GL's (1, 1, 1)/255, not 0: the middle quad is lit well above the
    // ambient term's 0.04 (10/255).
    let middle = ffvk.get_pixel(SIZE / 2, SIZE / 2).0;
    assert!(
        middle[0] > 100,
        "GL_BYTE normals of 0 converted as GL converts them: {middle:?}"
    );
    assert_matches_gl(&ffvk, &mesa, "three_layouts");
}

/// Colors as GL's arrays give them and positions with a w: signed bytes (GL 2.1 table 2.9:
/// (2c + 1)/255, so byte 0 is 1/255, not 0), unsigned bytes with three components (alpha 1),
/// and positions (x, y, 0, 2) that GL divides by w, each in a viewport of its own, unlit,
/// against Mesa's GL drawing the same vertices with glColor4b, glColor3ub and glVertex4f.
/// Mesa 22.3 converts glColorPointer(GL_BYTE) arrays as Vulkan's SNORM does (max(c/127, −1)),
/// off the spec: ffvk follows the spec, and this test pins Mesa's deviation.
#[test]
fn byte_colors_and_positions_with_w_draw_as_gl_2_1_converts_them() {
    let mut canvas = Canvas::new(SIZE);
    let device = canvas.ffvk();
    let gl = GlState::new();
    let signed: [i8; 4] = [0, 32, 100, 127];
    let unsigned: [u8; 3] = [10, 128, 250];
    // x y z, then the signed color: 16 bytes; x y z, then the unsigned color padded: 16 bytes.
    let mut signed_vertices = Vec::new();
    let mut unsigned_vertices = Vec::new();
    for p in QUAD {
        signed_vertices.extend_from_slice(&bytes_of(&p));
        signed_vertices.extend_from_slice(&bytes_of(&signed));
        unsigned_vertices.extend_from_slice(&bytes_of(&p));
        unsigned_vertices.extend_from_slice(&unsigned);
        unsigned_vertices.push(0);
    }
    let half_with_w: Vec<f32> = QUAD.iter().flat_map(|p| [p[0], p[1], 0.0, 2.0]).collect();
    let buffers = [
        [(canvas.buffer(&signed_vertices), 0)],
        [(canvas.buffer(&unsigned_vertices), 0)],
        [(canvas.buffer(&bytes_of(&half_with_w)), 0)],
    ];
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let layout = |color: Option<Attribute>| {
        VertexInput::new(vec![binding(16)], position, position)
            .with_normal(None)
            .with_color(color)
    };
    let options = LightingOptions::new(
        Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED),
        layout(Some(Attribute::new(0, 12, vk::Format::R8G8B8A8_SNORM))),
    );
    let mut lighting = Lighting::new(&device, &options).unwrap();
    let unsigned_layout = lighting
        .vertex_layout(layout(Some(Attribute::new(0, 12, vk::Format::R8G8B8_UNORM))))
        .unwrap();
    let with_w = lighting
        .vertex_layout(
            VertexInput::new(
                vec![binding(16)],
                Attribute::new(0, 0, vk::Format::R32G32B32A32_SFLOAT),
                position,
            )
            .with_normal(None),
        )
        .unwrap();
    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);
    let draw = |i: usize| LitDraw::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &buffers[i], strip);
    let draws = [
        draw(0),
        draw(1).with_layout(Some(unsigned_layout)),
        draw(2).with_layout(Some(with_w)),
    ];
    let third = SIZE / 3;
    lighting.begin_frame(0).unwrap();
    let mut results = Vec::new();
    let ffvk = canvas
        .frame(|device, cmd| {
            for (i, draw) in draws.iter().enumerate() {
                let viewport = vk::Viewport {
                    x: (i as u32 * third) as f32,
                    y: 0.0,
                    width: third as f32,
                    height: SIZE as f32,
                    min_depth: 0.0,
                    max_depth: 1.0,
                };
                // SAFETY: the canvas's pass is open; the buffers live as long as the canvas.
                unsafe { device.cmd_set_viewport(cmd, 0, &[viewport]) };
                // SAFETY: as above.
                results.push(unsafe { lighting.draw(cmd, 0, draw) });
            }
        })
        .unwrap();
    for r in results {
        r.unwrap();
    }
    drop(lighting);
    drop(device);

    let quads = |g: &raw::Gl, color: &dyn Fn(&raw::Gl)| {
        // SAFETY: a context is current.
        unsafe {
            g.Viewport(0, 0, third as i32, SIZE as i32);
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                color(g);
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
            g.Viewport(third as i32, 0, third as i32, SIZE as i32);
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                g.Color3ub(unsigned[0], unsigned[1], unsigned[2]);
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
            g.Viewport(2 * third as i32, 0, third as i32, SIZE as i32);
            g.Color4f(1.0, 1.0, 1.0, 1.0);
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                g.Vertex4f(p[0], p[1], 0.0, 2.0);
            }
            g.End();
        }
    };
    let mesa = render_raw_gl(SIZE, SIZE, |g| {
        // SAFETY: a context is current.
        quads(g, &|g| unsafe {
            g.Color4b(signed[0], signed[1], signed[2], signed[3])
        })
    })
    .expect("Mesa's GL renders");
    let centre = |i: u32| ffvk.get_pixel(i * third + third / 2, SIZE / 2).0;
    assert_eq!(
        centre(0),
        [1, 65, 201, 255],
        "GL_BYTE (0, 32, 100, 127) as (2c + 1)/255"
    );
    assert_eq!(
        centre(1),
        [10, 128, 250, 255],
        "GL_UNSIGNED_BYTE (10, 128, 250), alpha 1"
    );
    // w = 2 halves the quad: its corner pixels stay clear, its middle is white.
    assert_eq!(centre(2), [255; 4]);
    assert_eq!(
        ffvk.get_pixel(2 * third + 1, 1).0,
        [0; 4],
        "the w = 2 quad covers half its viewport"
    );
    assert_matches_gl(&ffvk, &mesa, "byte_colors_and_w");

    // Mesa's deviation: the same bytes through glColorPointer(GL_BYTE) and glDrawArrays (its
    // immediate mode, glArrayElement included, converts as the spec says).
    let mesa_array = render_raw_gl(SIZE, SIZE, |g| {
        let colors: Vec<i8> = (0..4).flat_map(|_| signed).collect();
        // SAFETY: a context is current; the arrays outlive the draw, which reads 4 vertices.
        unsafe {
            g.Viewport(0, 0, third as i32, SIZE as i32);
            g.EnableClientState(raw::VERTEX_ARRAY);
            g.EnableClientState(raw::COLOR_ARRAY);
            g.VertexPointer(3, raw::FLOAT, 0, QUAD.as_ptr().cast());
            g.ColorPointer(4, raw::BYTE, 0, colors.as_ptr().cast());
            g.DrawArrays(raw::TRIANGLE_STRIP, 0, 4);
            g.DisableClientState(raw::COLOR_ARRAY);
            g.DisableClientState(raw::VERTEX_ARRAY);
        }
    })
    .expect("Mesa's GL renders");
    let mesa_bytes = mesa_array.get_pixel(third / 2, SIZE / 2).0;
    assert_eq!(
        mesa_bytes,
        [0, 64, 201, 255],
        "Mesa 22.3 converts glColorPointer(GL_BYTE) as max(c/127, -1), not as GL 2.1's (2c + 1)/255"
    );
}

/// A layout with a material array drawn in the fragment mode (whose materials are the
/// draw's), and a layout handle of another `Lighting`, are refused by name, recording nothing.
#[test]
fn material_arrays_in_the_fragment_mode_and_another_lightings_layout_are_refused_by_name() {
    let mut canvas = Canvas::new(8);
    let device = canvas.ffvk();
    let buffer = canvas.buffer(&bytes_of(&[0f32; 4 * 8]));
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let plain = VertexInput::new(vec![binding(32)], position, position);
    let with_material = plain.clone().with_material(
        Face::Back,
        MaterialArray::Specular,
        Some(Attribute::new(0, 12, vk::Format::R32G32B32A32_SFLOAT)),
    );
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, plain.clone())).unwrap();
    let mut other = Lighting::new(&device, &LightingOptions::new(target, plain)).unwrap();
    let materials = lighting.vertex_layout(with_material).unwrap();
    let foreign = other.vertex_layout(VertexInput::interleaved()).unwrap();
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    gl.lighting.mode = LightingMode::Fragment;
    let buffers = [(buffer, 0)];
    let draw = LitDraw::new(
        &gl.lighting,
        Mat4::IDENTITY,
        Mat4::IDENTITY,
        &buffers,
        Geometry::vertices(3),
    );
    lighting.begin_frame(0).unwrap();
    let mut errors = Vec::new();
    canvas
        .frame(|_, cmd| {
            for layout in [materials, foreign] {
                // SAFETY: the canvas's pass is open; the buffer lives as long as the canvas.
                let e = unsafe { lighting.draw(cmd, 0, &draw.with_layout(Some(layout))) };
                errors.push(e.expect_err("refused").to_string());
            }
        })
        .unwrap();
    assert!(
        errors[0].contains("back GL_SPECULAR material per vertex") && errors[0].contains("fragment mode"),
        "{}",
        errors[0]
    );
    assert!(errors[1].contains("made by another Lighting"), "{}", errors[1]);
    drop((lighting, other));
}

/// A textured draw whose layout has no texture coordinate array takes GL's current texture
/// coordinates (glTexCoord2f before the vertices: every fragment samples one texel), and
/// four-component texture coordinates divide by q as GL's do (glTexCoord4f with q = 2), each
/// in half the image, against Mesa's GL; a 2×2 texture, nearest, `GL_REPLACE`.
#[test]
fn current_and_projective_texture_coordinates_sample_as_mesa_samples_them() {
    use ffvk::draw::texture::sampler_info;
    use ffvk::gl::texture::{Sampling, TexEnvMode};
    let texels: [u8; 16] = [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255];
    let mut canvas = Canvas::new(SIZE);
    let device = canvas.ffvk();
    let (view, sampler) = canvas.texture(&texels, (2, 2), &sampler_info(&Sampling::NEAREST, 1));
    let mut gl = GlState::new();
    gl.lighting.texture_units[0].enabled = true;
    gl.lighting.texture_units[0].env_mode = TexEnvMode::Replace;
    gl.tex_coord(Vec4::new(0.75, 0.25, 0.0, 1.0)).unwrap();
    // x y z, then s t r q with q = 2: 28 bytes.
    let corners = [[0.0f32, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]];
    let mut projective = Vec::new();
    for (p, st) in QUAD.iter().zip(corners) {
        projective.extend_from_slice(p);
        projective.extend_from_slice(&[2.0 * st[0], 2.0 * st[1], 0.0, 2.0]);
    }
    let buffers = [
        [(canvas.buffer(&bytes_of(&QUAD)), 0)],
        [(canvas.buffer(&bytes_of(&projective)), 0)],
    ];
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let bare = VertexInput::new(vec![binding(12)], position, position).with_normal(None);
    let with_stq = VertexInput::new(vec![binding(28)], position, position)
        .with_normal(None)
        .with_texcoord(Some(Attribute::new(0, 12, vk::Format::R32G32B32A32_SFLOAT)));
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, bare)).unwrap();
    let stq = lighting.vertex_layout(with_stq).unwrap();
    // SAFETY: the view and sampler are the canvas's, alive until it drops, after `lighting`.
    let texture = unsafe { lighting.bind_texture(view, sampler) }.unwrap();
    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);
    let draws = [
        LitDraw::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &buffers[0], strip)
            .with_texture(Some(&texture)),
        LitDraw::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &buffers[1], strip)
            .with_texture(Some(&texture))
            .with_layout(Some(stq)),
    ];
    let half = SIZE / 2;
    lighting.begin_frame(0).unwrap();
    let mut results = Vec::new();
    let ffvk = canvas
        .frame(|device, cmd| {
            for (i, draw) in draws.iter().enumerate() {
                let viewport = vk::Viewport {
                    x: (i as u32 * half) as f32,
                    y: 0.0,
                    width: half as f32,
                    height: SIZE as f32,
                    min_depth: 0.0,
                    max_depth: 1.0,
                };
                // SAFETY: the canvas's pass is open; buffers and texture outlive the frame.
                unsafe { device.cmd_set_viewport(cmd, 0, &[viewport]) };
                // SAFETY: as above.
                results.push(unsafe { lighting.draw(cmd, 0, draw) });
            }
        })
        .unwrap();
    for r in results {
        r.unwrap();
    }
    drop(lighting);
    drop(device);

    let mesa = render_raw_gl(SIZE, SIZE, |g| {
        // SAFETY: a context is current; the texels outlive glTexImage2D.
        unsafe {
            let mut name = 0;
            g.GenTextures(1, &mut name);
            g.BindTexture(raw::TEXTURE_2D, name);
            g.TexImage2D(
                raw::TEXTURE_2D,
                0,
                raw::RGBA as i32,
                2,
                2,
                0,
                raw::RGBA,
                raw::UNSIGNED_BYTE,
                texels.as_ptr().cast(),
            );
            g.TexParameteri(raw::TEXTURE_2D, raw::TEXTURE_MIN_FILTER, raw::NEAREST as i32);
            g.TexParameteri(raw::TEXTURE_2D, raw::TEXTURE_MAG_FILTER, raw::NEAREST as i32);
            g.TexEnvi(raw::TEXTURE_ENV, raw::TEXTURE_ENV_MODE, raw::REPLACE as i32);
            g.Enable(raw::TEXTURE_2D);
            g.Viewport(0, 0, half as i32, SIZE as i32);
            g.TexCoord2f(0.75, 0.25);
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
            g.Viewport(half as i32, 0, half as i32, SIZE as i32);
            g.Begin(raw::TRIANGLE_STRIP);
            for (p, st) in QUAD.iter().zip(corners) {
                g.TexCoord4f(2.0 * st[0], 2.0 * st[1], 0.0, 2.0);
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
            g.DeleteTextures(1, &name);
        }
    })
    .expect("Mesa's GL renders");
    // The current coordinates (0.75, 0.25) pick texel (1, 0): green, everywhere in the left half.
    assert_eq!(ffvk.get_pixel(2, 2).0, [0, 255, 0, 255]);
    assert_eq!(ffvk.get_pixel(half - 3, SIZE - 3).0, [0, 255, 0, 255]);
    // With q = 2 the right half shows the whole texture: its top-left quarter is t = 1, s = 0.
    assert_eq!(ffvk.get_pixel(half + 3, 3).0, [0, 0, 255, 255]);
    assert_matches_gl(&ffvk, &mesa, "current_and_projective_texcoords");
}
