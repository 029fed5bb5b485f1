//! GL's other primitives through the renderer: points, lines, strips and fans lit as GL lights
//! them, each pixel checked against the CPU reference's lit vertex. Points and lines take the
//! front material and the front color even with two-sided lighting (facing is a polygon's
//! property); flat shading takes GL's provoking vertex (GL 2.1 §2.14.7, table 2.12): the last
//! of each line and of each strip or fan triangle.

use ffvk::gl::state::*;
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, Topology};
use glam::{DVec4, Mat4, Vec3, Vec4};

use crate::support::*;

const SIZE: u32 = 16;

/// The center of pixel (x, y) at z = 0 under identity matrices.
fn at_pixel(x: f32, y: f32) -> Vec3 {
    Vec3::new(
        (x + 0.5) / SIZE as f32 * 2.0 - 1.0,
        1.0 - (y + 0.5) / SIZE as f32 * 2.0,
        0.0,
    )
}

/// The reference's lit color of vertex `v` for the front (or back) face, identity matrices.
fn lit(state: &FixedFunctionState, v: &Vertex, back: bool) -> DVec4 {
    let eye = ffvk::reference::transform(state, Mat4::IDENTITY, Mat4::IDENTITY, v);
    let (pri, sec) = ffvk::reference::vertex_color(state, &eye, back);
    ffvk::reference::color_sum(pri, sec)
}

/// Draws `vertices` and `indices` as `topology` in a black SIZE² frame.
fn draw(gl: &GlState, vertices: Vec<Vertex>, indices: Vec<u32>, topology: Topology) -> image::RgbaImage {
    let mut r = renderer();
    let mesh = r.upload(&MeshData::new(vertices, indices)).unwrap();
    let mut frame = Frame::new(SIZE, SIZE);
    frame.clear_color = Vec4::new(0.0, 0.0, 0.0, 1.0);
    frame
        .draws
        .push(Draw::new(&mesh, Mat4::IDENTITY, Mat4::IDENTITY, gl.lighting).with_topology(topology));
    let image = r.render(&frame).unwrap().into_rgba_image();
    drop(mesh);
    finish(r);
    image
}

#[test]
fn points_take_the_front_material_and_color_even_facing_away_with_two_sided_lighting() {
    for mode in LightingMode::ALL {
        let gl = two_sided(mode);
        let normals = [Vec3::Z, Vec3::NEG_Z, Vec3::new(0.6, 0.0, 0.8)];
        let vertices: Vec<Vertex> = normals
            .iter()
            .enumerate()
            .map(|(k, &n)| Vertex::new(at_pixel(3.0 + 4.0 * k as f32, 5.0), n, Vec4::ONE))
            .collect();
        let image = draw(&gl, vertices.clone(), vec![0, 1, 2], Topology::PointList);
        for (k, v) in vertices.iter().enumerate() {
            let (front, back) = (lit(&gl.lighting, v, false), lit(&gl.lighting, v, true));
            assert!(
                (front - back).abs().max_element() > 0.05,
                "the faces must differ for the test to tell them apart"
            );
            let what = format!("{} point {k}", mode.name());
            assert_pixel(&image, 3 + 4 * k as u32, 5, front, 1.0, &what);
        }
        // One pixel each: the rest of the row stays the clear color.
        assert_eq!(px(&image, 4, 5), [0, 0, 0, 255], "{}", mode.name());
    }
}

#[test]
fn flat_lines_take_their_second_vertex_and_smooth_lines_their_ends() {
    // Three horizontal lines, each from a vertex lit from one side to one lit from the other.
    let mut vertices = Vec::new();
    for row in 0..3 {
        let y = 3.0 + 4.0 * row as f32;
        vertices.push(Vertex::new(
            at_pixel(1.0, y),
            Vec3::new(-0.8, 0.0, 0.6),
            Vec4::ONE,
        ));
        vertices.push(Vertex::new(
            at_pixel(14.0, y),
            Vec3::new(0.8, 0.3, 0.5).normalize(),
            Vec4::ONE,
        ));
    }
    let indices: Vec<u32> = (0..6).collect();
    let flat = two_sided(LightingMode::Flat);
    let image = draw(&flat, vertices.clone(), indices.clone(), Topology::LineList);
    for row in 0..3u32 {
        let second = &vertices[2 * row as usize + 1];
        let y = 3 + 4 * row;
        for x in [3, 8, 12] {
            assert_pixel(
                &image,
                x,
                y,
                lit(&flat.lighting, second, false),
                1.0,
                &format!("flat line {row} at x {x}"),
            );
        }
    }
    // Smooth: the line's pixels run from its first vertex's color to its second's.
    let smooth = two_sided(LightingMode::Vertex);
    let image = draw(&smooth, vertices.clone(), indices, Topology::LineList);
    let (a, b) = (
        lit(&smooth.lighting, &vertices[0], false),
        lit(&smooth.lighting, &vertices[1], false),
    );
    let t = |x: f64| (x + 0.5 - 1.5) / 13.0;
    for x in [2u32, 7, 13] {
        let want = a.lerp(b, t(x as f64));
        assert_pixel(&image, x, 3, want, 3.0, &format!("smooth line at x {x}"));
    }
}

#[test]
fn strips_and_fans_in_flat_mode_take_the_last_vertex_of_each_triangle() {
    // A fan around the center and a strip below it; the normals turn so every vertex lights
    // differently.
    let normal = |k: usize| {
        let a = k as f32 * 0.7;
        Vec3::new(0.7 * a.cos(), 0.7 * a.sin(), 0.714).normalize()
    };
    let center = (8.0, 6.0);
    let rim: Vec<(f32, f32)> = (0..5)
        .map(|k| {
            let a = std::f32::consts::PI * k as f32 / 4.0;
            (center.0 + 6.5 * a.cos(), center.1 - 5.5 * a.sin())
        })
        .collect();
    let gl = two_sided(LightingMode::Flat);
    // Fan: vertex 0 the center, 1..=5 the rim from right to left over the top (counter-
    // clockwise on screen: front faces); triangles (0, i, i + 1), provoking vertex i + 1.
    let fan: Vec<Vertex> = std::iter::once(center)
        .chain(rim.iter().copied())
        .enumerate()
        .map(|(k, (x, y))| Vertex::new(at_pixel(x, y), normal(k), Vec4::ONE))
        .collect();
    let image = draw(&gl, fan.clone(), (0..6).collect(), Topology::TriangleFan);
    for i in 1..5 {
        let (x, y) = [center, rim[i - 1], rim[i]]
            .into_iter()
            .fold((0.0f32, 0.0f32), |(sx, sy), (x, y)| (sx + x / 3.0, sy + y / 3.0));
        let want = lit(&gl.lighting, &fan[i + 1], false);
        assert_pixel(
            &image,
            x.round() as u32,
            y.round() as u32,
            want,
            1.0,
            &format!("fan triangle {i}"),
        );
    }
    // Strip: 0 1 2 3 4 5 zigzagging right along rows 9 and 14, the first triangle counter-
    // clockwise; triangle i provokes i + 2.
    let strip: Vec<Vertex> = (0..6)
        .map(|k| {
            let (x, y) = (1.0 + 2.8 * k as f32, if k % 2 == 0 { 9.0 } else { 14.0 });
            Vertex::new(at_pixel(x, y), normal(k + 2), Vec4::ONE)
        })
        .collect();
    let image = draw(&gl, strip.clone(), (0..6).collect(), Topology::TriangleStrip);
    for i in 0..4 {
        let row = |k: usize| if k.is_multiple_of(2) { 9.0 } else { 14.0 };
        let (x, y) = (i..i + 3).fold((0.0f32, 0.0f32), |(sx, sy), k| {
            (sx + (1.0 + 2.8 * k as f32) / 3.0, sy + row(k) / 3.0)
        });
        let want = lit(&gl.lighting, &strip[i + 2], false);
        assert_pixel(
            &image,
            x.round() as u32,
            y.round() as u32,
            want,
            1.0,
            &format!("strip triangle {i}"),
        );
    }
}

#[test]
fn the_gl_modes_vulkan_lacks_draw_through_their_helpers_with_gls_provoking_vertex() {
    use ffvk::draw::gl_primitives;
    // GL_QUADS: one quad whose four corners light differently; both triangles take the fourth.
    let gl = two_sided(LightingMode::Flat);
    let corners = [(2.0, 13.0), (13.0, 13.0), (13.0, 2.0), (2.0, 2.0)];
    let quad: Vec<Vertex> = corners
        .iter()
        .enumerate()
        .map(|(k, &(x, y))| {
            let a = k as f32 * 1.3;
            let n = Vec3::new(0.6 * a.cos(), 0.6 * a.sin(), 0.8);
            Vertex::new(at_pixel(x, y), n, Vec4::ONE)
        })
        .collect();
    let indices = gl_primitives::quads(&[0, 1, 2, 3]);
    let image = draw(&gl, quad.clone(), indices, Topology::TriangleList);
    let want = lit(&gl.lighting, &quad[3], false);
    for (x, y) in [(4, 11), (11, 4), (7, 7)] {
        assert_pixel(&image, x, y, want, 1.0, &format!("quad at ({x}, {y})"));
    }
    // GL_POLYGON: the same corners as a polygon take the first vertex.
    let image = draw(
        &gl,
        quad.clone(),
        gl_primitives::polygon(&[0, 1, 2, 3]),
        Topology::TriangleList,
    );
    let want = lit(&gl.lighting, &quad[0], false);
    for (x, y) in [(4, 11), (11, 4), (7, 7)] {
        assert_pixel(&image, x, y, want, 1.0, &format!("polygon at ({x}, {y})"));
    }
}

// ---------------------------------------------------------------------------------------------
// Against Mesa's GL: the same vertices drawn in each of GL's ten modes by GL itself and by ffvk
// (through a Topology or a gl_primitives helper).

use ffvk::draw::gl_primitives;
use ffvk_cli::gl_reference::{render_gl_with, GlDraw, GlMode, GlScene};

/// GL's side and its size.
const GL_SIZE: u32 = 48;

/// Nine vertices for `mode`: on a circle, counter-clockwise, for the modes that walk around a
/// shape; on a ladder (even vertices below, odd above) for the strips; every normal different.
fn mode_vertices(mode: GlMode) -> Vec<Vertex> {
    let ladder = matches!(mode, GlMode::QuadStrip | GlMode::TriangleStrip);
    (0..9)
        .map(|k| {
            let p = if ladder {
                let x = -0.85 + 0.2 * k as f32;
                Vec3::new(x, if k % 2 == 0 { -0.5 } else { 0.4 }, 0.0)
            } else {
                let a = k as f32 * std::f32::consts::TAU / 9.0;
                Vec3::new(0.8 * a.cos(), 0.8 * a.sin(), 0.0)
            };
            let b = k as f32 * 0.9;
            let n = Vec3::new(0.6 * b.cos(), 0.6 * b.sin(), 0.8);
            Vertex::new(p, n, Vec4::ONE)
        })
        .collect()
}

/// How ffvk draws GL's `mode` over indices 0..9.
fn ffvk_form(mode: GlMode) -> (Vec<u32>, Topology) {
    let all: Vec<u32> = (0..9).collect();
    match mode {
        GlMode::Points => (all, Topology::PointList),
        GlMode::Lines => (all, Topology::LineList),
        GlMode::LineStrip => (all, Topology::LineStrip),
        GlMode::LineLoop => (gl_primitives::line_loop(&all), Topology::LineList),
        GlMode::Triangles => (all, Topology::TriangleList),
        GlMode::TriangleStrip => (all, Topology::TriangleStrip),
        GlMode::TriangleFan => (all, Topology::TriangleFan),
        GlMode::Quads => (gl_primitives::quads(&all), Topology::TriangleList),
        GlMode::QuadStrip => (gl_primitives::quad_strip(&all), Topology::TriangleList),
        GlMode::Polygon => (gl_primitives::polygon(&all), Topology::TriangleList),
    }
}

/// Where two images of the same scene on black agree: of the pixels either lights (not black),
/// leaving out those `skip` names, how many both light, how many either does, the largest
/// channel difference where both do, and how many of those differ by more than 2/255.
struct Overlap {
    both: u32,
    either: u32,
    worst: u8,
    off: u32,
}

fn overlap(ours: &image::RgbaImage, theirs: &image::RgbaImage, skip: impl Fn(u32, u32) -> bool) -> Overlap {
    let lit = |p: &image::Rgba<u8>| p.0[..3] != [0, 0, 0];
    let mut o = Overlap {
        both: 0,
        either: 0,
        worst: 0,
        off: 0,
    };
    for ((x, y, a), b) in ours.enumerate_pixels().zip(theirs.pixels()) {
        if skip(x, y) {
            continue;
        }
        o.either += (lit(a) || lit(b)) as u32;
        if lit(a) && lit(b) {
            o.both += 1;
            let d = (0..3).map(|c| a.0[c].abs_diff(b.0[c])).max().unwrap();
            o.worst = o.worst.max(d);
            o.off += (d > 2) as u32;
        }
    }
    o
}

#[test]
fn every_gl_mode_lights_as_mesa_gl_lights_it_smooth_and_flat_two_sided_or_not() {
    let modes = [
        GlMode::Points,
        GlMode::Lines,
        GlMode::LineStrip,
        GlMode::LineLoop,
        GlMode::Triangles,
        GlMode::TriangleStrip,
        GlMode::TriangleFan,
        GlMode::Quads,
        GlMode::QuadStrip,
        GlMode::Polygon,
    ];
    let mut r = renderer();
    for mode in modes {
        let vertices = mode_vertices(mode);
        let (indices, topology) = ffvk_form(mode);
        let gl_mesh = MeshData::new(vertices.clone(), (0..9).collect());
        let mesh = r.upload(&MeshData::new(vertices, indices)).unwrap();
        for shading in [LightingMode::Vertex, LightingMode::Flat] {
            for two_side in [true, false] {
                let mut gl = two_sided(shading);
                gl.light_model(LightModelParam::TwoSide(two_side)).unwrap();
                let what = format!("{mode:?} {} two-sided {two_side}", shading.name());
                let mut frame = Frame::new(GL_SIZE, GL_SIZE);
                frame.clear_color = Vec4::new(0.0, 0.0, 0.0, 1.0);
                frame.draws.push(
                    Draw::new(&mesh, Mat4::IDENTITY, Mat4::IDENTITY, gl.lighting).with_topology(topology),
                );
                let ours = r.render(&frame).unwrap().into_rgba_image();
                let mut draw = GlDraw::new(&gl_mesh, Mat4::IDENTITY, Mat4::IDENTITY, gl.lighting);
                draw.mode = mode;
                let theirs = render_gl_with(
                    &GlScene {
                        width: GL_SIZE,
                        height: GL_SIZE,
                        clear_color: [0.0, 0.0, 0.0, 1.0],
                        depth_test: false,
                        draws: vec![draw],
                    },
                    &gl_options(),
                )
                .unwrap();
                // Only pixels both cover: GL and Vulkan rasterize lines and points by
                // different rules (GL's diamond exit, Vulkan's rectangles), and smooth lines
                // interpolate at the pixels each covers.
                // Where line segments meet, which one draws the shared pixel differs too (GL's
                // half-open segments, Vulkan's overlapping ones): pixels next to a vertex are
                // left out for the line modes.
                let lines = matches!(mode, GlMode::Lines | GlMode::LineStrip | GlMode::LineLoop);
                let joint = |x: u32, y: u32| {
                    lines
                        && gl_mesh.vertices.iter().any(|v| {
                            let wx = (v.position[0] + 1.0) / 2.0 * GL_SIZE as f32;
                            let wy = (1.0 - v.position[1]) / 2.0 * GL_SIZE as f32;
                            (x as f32 + 0.5 - wx).abs() <= 1.5 && (y as f32 + 0.5 - wy).abs() <= 1.5
                        })
                };
                let Overlap {
                    both, either, worst, ..
                } = overlap(&ours, &theirs, joint);
                let tolerance = if lines && shading == LightingMode::Vertex {
                    12
                } else {
                    3
                };
                if worst > tolerance || both * 10 < either * 7 {
                    let a = save_for_inspection(&ours, &format!("topology_ffvk_{what}"));
                    let b = save_for_inspection(&theirs, &format!("topology_gl_{what}"));
                    panic!(
                        "{what}: {both} pixels both cover of {either} either covers, worst {worst}/255 \
                         (tolerance {tolerance}); images {} and {}",
                        a.display(),
                        b.display()
                    );
                }
            }
        }
    }
    finish(r);
}

// ---------------------------------------------------------------------------------------------
// glTF's seven modes.

/// A glTF file of seven primitives, one per mode, each in a cell of its own; the points and
/// lines without normals and in a pure color each (red POINTS, green LINES, blue LINE_LOOP,
/// yellow LINE_STRIP), the triangles grey (flat normals, lit).
fn seven_modes_gltf(dir: &std::path::Path) -> std::path::PathBuf {
    let mut positions: Vec<f32> = Vec::new();
    let mut colors: Vec<f32> = Vec::new();
    let mut primitives = Vec::new();
    let pure = [
        [1.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0, 1.0],
        [1.0, 1.0, 0.0, 1.0],
    ];
    for mode in 0..7u32 {
        let (cx, cy) = ((mode % 4) as f32 * 2.5, (mode / 4) as f32 * -2.5);
        // Six vertices around the cell's center, counter-clockwise.
        let first = positions.len() / 3;
        for k in 0..6 {
            let a = k as f32 * std::f32::consts::TAU / 6.0;
            positions.extend([cx + a.cos(), cy + a.sin(), 0.0]);
            colors.extend(if mode < 4 {
                pure[mode as usize]
            } else {
                [0.6, 0.6, 0.6, 1.0]
            });
        }
        // glTF's mode numbers: 0 POINTS, 1 LINES, 2 LINE_LOOP, 3 LINE_STRIP, 4 TRIANGLES,
        // 5 TRIANGLE_STRIP, 6 TRIANGLE_FAN. Triangles take vertices (0, 1, 2), (0, 2, 3)…
        let gltf_mode = [0, 1, 2, 3, 4, 5, 6][mode as usize];
        let indices: Vec<u32> = match gltf_mode {
            4 => vec![0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5],
            5 => vec![0, 1, 5, 2, 4, 3],
            _ => (0..6).collect(),
        };
        primitives.push((first, gltf_mode, indices));
    }
    let mut bin: Vec<u8> = bytemuck::cast_slice::<f32, u8>(&positions).to_vec();
    let color_offset = bin.len();
    bin.extend(bytemuck::cast_slice::<f32, u8>(&colors));
    let mut views = vec![
        format!(r#"{{"buffer": 0, "byteOffset": 0, "byteLength": {color_offset}}}"#),
        format!(
            r#"{{"buffer": 0, "byteOffset": {color_offset}, "byteLength": {}}}"#,
            colors.len() * 4
        ),
    ];
    let mut accessors = Vec::new();
    let mut json_primitives = Vec::new();
    for (first, mode, indices) in &primitives {
        let p = accessors.len();
        accessors.push(format!(
            r#"{{"bufferView": 0, "byteOffset": {}, "componentType": 5126, "count": 6, "type": "VEC3", "min": [-10, -10, -1], "max": [10, 10, 1]}}"#,
            first * 12
        ));
        accessors.push(format!(
            r#"{{"bufferView": 1, "byteOffset": {}, "componentType": 5126, "count": 6, "type": "VEC4"}}"#,
            first * 16
        ));
        let index_offset = bin.len();
        bin.extend(bytemuck::cast_slice::<u32, u8>(indices));
        views.push(format!(
            r#"{{"buffer": 0, "byteOffset": {index_offset}, "byteLength": {}}}"#,
            indices.len() * 4
        ));
        accessors.push(format!(
            r#"{{"bufferView": {}, "componentType": 5125, "count": {}, "type": "SCALAR"}}"#,
            views.len() - 1,
            indices.len()
        ));
        json_primitives.push(format!(
            r#"{{"attributes": {{"POSITION": {p}, "COLOR_0": {}}}, "indices": {}, "mode": {mode}}}"#,
            p + 1,
            p + 2
        ));
    }
    std::fs::write(dir.join("seven.bin"), &bin).unwrap();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "buffers": [{{"uri": "seven.bin", "byteLength": {}}}],
  "bufferViews": [{}], "accessors": [{}],
  "meshes": [{{"primitives": [{}]}}], "nodes": [{{"mesh": 0}}], "scenes": [{{"nodes": [0]}}], "scene": 0}}"#,
        bin.len(),
        views.join(", "),
        accessors.join(", "),
        json_primitives.join(", ")
    );
    let path = dir.join("seven.gltf");
    std::fs::write(&path, json).unwrap();
    path
}

#[test]
fn a_gltf_file_draws_each_of_its_seven_modes_points_and_lines_unlit_without_normals() {
    let dir = output_dir().join("topology_gltf");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = seven_modes_gltf(&dir);
    let made = ffvk::scene::direct::from_gltf(
        &path,
        "seven.gltf",
        &Default::default(),
        &ffvk::scene::direct::DirectOptions::default().with_size(Some((200, 120))),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let scene = made.scene;
    assert_eq!(scene.meshes.len(), 7);
    let lit: Vec<bool> = scene.meshes.iter().map(|m| m.lit).collect();
    assert_eq!(lit, [false, false, false, false, true, true, true]);
    let mut r = renderer();
    let image = ffvk::scene::render_scene(&mut r, &scene, None).unwrap();
    save_for_inspection(&image, "topology_gltf_seven_modes");
    // Unlit points and lines show their vertex colors exactly.
    for (name, color) in [
        ("POINTS", [255, 0, 0, 255]),
        ("LINES", [0, 255, 0, 255]),
        ("LINE_LOOP", [0, 0, 255, 255]),
        ("LINE_STRIP", [255, 255, 0, 255]),
    ] {
        let n = image.pixels().filter(|p| p.0 == color).count();
        let least = if name == "POINTS" { 6 } else { 20 };
        assert!(n >= least, "{name}: {n} pixels of {color:?}");
    }
    // The three triangle modes, lit grey, cover their cells.
    let grey = image
        .pixels()
        .filter(|p| p.0[0] == p.0[1] && p.0[1] == p.0[2] && p.0[0] > 60)
        .count();
    assert!(grey > 600, "{grey} lit grey pixels");
    finish(r);
}

// ---------------------------------------------------------------------------------------------
// Scene files.

#[test]
fn a_scene_draws_a_meshs_index_list_in_any_gl_mode_and_refuses_an_unknown_one() {
    let dir = output_dir().join("topology_scene");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = |primitive: &str| {
        format!(
            "[image]\nsize = [64, 64]\n[[lights]]\nindex = 0\nposition = [0.0, 0.0, 1.0, 0.0]\n\
             [[meshes]]\nbuiltin = \"sphere\"\nlevel = 12\ntranslate = [0.0, 0.0, -3.0]\n{primitive}"
        )
    };
    let mut r = renderer();
    let mut drawn = Vec::new();
    for primitive in [
        "",
        "primitive = \"points\"",
        "primitive = \"lines\"",
        "primitive = \"quads\"",
    ] {
        let path = dir.join("s.toml");
        std::fs::write(&path, scene(primitive)).unwrap();
        let s = ffvk::scene::Scene::load(&path).unwrap_or_else(|e| panic!("{primitive}: {e}"));
        let image = ffvk::scene::render_scene(&mut r, &s, None).unwrap();
        let lit = image.pixels().filter(|p| p.0[..3] != [0, 0, 0]).count();
        drawn.push((primitive, s.meshes[0].data.topology, lit));
    }
    let [solid, points, lines, quads] = [drawn[0], drawn[1], drawn[2], drawn[3]];
    assert_eq!(
        [points.1, lines.1, quads.1],
        [Topology::PointList, Topology::LineList, Topology::TriangleList]
    );
    assert!(
        points.2 > 20 && points.2 < lines.2 && lines.2 < solid.2,
        "{drawn:?}"
    );
    assert!(quads.2 > 0 && quads.2 <= solid.2, "{drawn:?}");
    let path = dir.join("bad.toml");
    std::fs::write(&path, scene("primitive = \"tristrip\"")).unwrap();
    let e = ffvk::scene::Scene::load(&path).unwrap_err().to_string();
    assert!(
        e.contains("meshes[0].primitive")
            && e.contains("\"tristrip\"")
            && e.contains("expected points, lines"),
        "{e}"
    );
    finish(r);
}

// ---------------------------------------------------------------------------------------------
// A glxgears-like gear: flat-shaded quad strips and quads, drawn by Mesa's GL with GL's own
// modes and by ffvk through gl_primitives.

/// One part of the gear: its vertices (in GL's order for `mode`) and GL's mode.
struct Part {
    vertices: Vec<Vertex>,
    mode: GlMode,
}

/// A gear of `teeth` teeth between radius 0.3 and 1.0, 0.3 thick: its front ring (a quad strip),
/// the front of its teeth (quads) and the outward faces of its teeth (a quad strip whose quads
/// each take the normal of their face from their provoking vertex, as flat shading reads it).
fn gear(teeth: usize) -> Vec<Part> {
    let (inner, root, tip, half) = (0.3f32, 0.75f32, 1.0f32, 0.15f32);
    let step = std::f32::consts::TAU / teeth as f32 / 4.0;
    let at = |r: f32, a: f32, z: f32| Vec3::new(r * a.cos(), r * a.sin(), z);
    let v = |p: Vec3, n: Vec3| Vertex::new(p, n, Vec4::ONE);
    let mut ring = Vec::new();
    for k in 0..=teeth * 4 {
        let a = k as f32 * step;
        ring.push(v(at(inner, a, half), Vec3::Z));
        ring.push(v(at(root, a, half), Vec3::Z));
    }
    let mut fronts = Vec::new();
    for t in 0..teeth {
        let a = t as f32 * 4.0 * step;
        for (r, k) in [(root, 0.0), (tip, 1.0), (tip, 2.0), (root, 3.0)] {
            fronts.push(v(at(r, a + k * step, half), Vec3::Z));
        }
    }
    // The outline: root, tip, tip, root for each tooth, back to the start.
    let outline: Vec<Vec3> = (0..=teeth * 4)
        .map(|k| {
            let r = if matches!(k % 4, 1 | 2) { tip } else { root };
            at(r, k as f32 * step, 0.0)
        })
        .collect();
    let mut sides = Vec::new();
    for (k, p) in outline.iter().enumerate() {
        // The normal of the face that ends here (for k = 0, the last face's).
        let from = if k == 0 {
            outline[outline.len() - 2]
        } else {
            outline[k - 1]
        };
        let d = *p - from;
        let n = Vec3::new(d.y, -d.x, 0.0).normalize_or(Vec3::X);
        sides.push(v(*p + Vec3::Z * half, n));
        sides.push(v(*p - Vec3::Z * half, n));
    }
    vec![
        Part {
            vertices: ring,
            mode: GlMode::QuadStrip,
        },
        Part {
            vertices: fronts,
            mode: GlMode::Quads,
        },
        Part {
            vertices: sides,
            mode: GlMode::QuadStrip,
        },
    ]
}

#[test]
fn a_flat_shaded_gear_of_quad_strips_and_quads_lights_as_mesa_gl_lights_it() {
    let parts = gear(12);
    let gl = with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(5.0, 5.0, 10.0, 0.0)))?;
        gl.material(
            Face::FrontAndBack,
            MaterialParam::AmbientAndDiffuse(Vec4::new(0.8, 0.1, 0.0, 1.0)),
        )?;
        gl.lighting_mode(LightingMode::Flat);
        Ok(())
    });
    let modelview = Mat4::from_translation(Vec3::new(0.0, 0.0, -4.0))
        * Mat4::from_rotation_x(-0.6)
        * Mat4::from_rotation_y(0.5);
    let projection = Mat4::perspective_rh_gl(0.7, 1.0, 1.0, 10.0);
    let size = 96;
    // GL: each part with its own mode.
    let gl_meshes: Vec<MeshData> = parts
        .iter()
        .map(|p| MeshData::new(p.vertices.clone(), (0..p.vertices.len() as u32).collect()))
        .collect();
    let draws = parts
        .iter()
        .zip(&gl_meshes)
        .map(|(p, mesh)| {
            let mut d = GlDraw::new(mesh, modelview, projection, gl.lighting);
            d.mode = p.mode;
            d
        })
        .collect();
    let theirs = render_gl_with(
        &GlScene {
            width: size,
            height: size,
            clear_color: [0.0, 0.0, 0.0, 1.0],
            depth_test: true,
            draws,
        },
        &gl_options(),
    )
    .unwrap();
    // ffvk: the same parts as triangle lists from gl_primitives.
    let mut r = renderer();
    let meshes: Vec<ffvk::Mesh> = parts
        .iter()
        .map(|p| {
            let order: Vec<u32> = (0..p.vertices.len() as u32).collect();
            let indices = match p.mode {
                GlMode::QuadStrip => gl_primitives::quad_strip(&order),
                _ => gl_primitives::quads(&order),
            };
            r.upload(&MeshData::new(p.vertices.clone(), indices)).unwrap()
        })
        .collect();
    let mut frame = Frame::new(size, size);
    frame.clear_color = Vec4::new(0.0, 0.0, 0.0, 1.0);
    frame.depth_test = true;
    for mesh in &meshes {
        frame
            .draws
            .push(Draw::new(mesh, modelview, projection, gl.lighting));
    }
    let ours = r.render(&frame).unwrap().into_rgba_image();
    drop(frame);
    drop(meshes);
    finish(r);
    let Overlap {
        both,
        either,
        worst,
        off,
    } = overlap(&ours, &theirs, |_, _| false);
    let a = save_for_inspection(&ours, "gear_ffvk");
    let b = save_for_inspection(&theirs, "gear_gl");
    // Where two faces meet at an edge, which one a pixel on it shows is the rasterizer's
    // call; a handful of such pixels may differ, no face may.
    assert!(
        both > 2000 && both * 100 >= either * 97 && off * 100 <= both,
        "{both} pixels both cover of {either}, {off} over 2/255 apart (worst {worst}); images {} and {}",
        a.display(),
        b.display()
    );
}

// ---------------------------------------------------------------------------------------------
// glPointSize and glLineWidth.

#[test]
fn wide_points_and_lines_light_as_mesa_gl_lights_them_and_bad_sizes_are_refused() {
    let mut r = renderer();
    for (mode, topology, size) in [
        (GlMode::Points, Topology::PointList, 4.0f32),
        (GlMode::Lines, Topology::LineList, 3.0),
    ] {
        let vertices = mode_vertices(mode);
        let count = if mode == GlMode::Lines { 8 } else { 9 };
        let mesh_data = MeshData::new(vertices, (0..count).collect());
        let mesh = r.upload(&mesh_data.clone().with_topology(topology)).unwrap();
        for shading in [LightingMode::Vertex, LightingMode::Flat] {
            let gl = two_sided(shading);
            let what = format!("{mode:?} of {size} pixels, {}", shading.name());
            let mut frame = Frame::new(GL_SIZE, GL_SIZE);
            frame.clear_color = Vec4::new(0.0, 0.0, 0.0, 1.0);
            let draw = Draw::new(&mesh, Mat4::IDENTITY, Mat4::IDENTITY, gl.lighting);
            frame.draws.push(if mode == GlMode::Points {
                draw.with_point_size(size)
            } else {
                draw.with_line_width(size)
            });
            let ours = r.render(&frame).unwrap().into_rgba_image();
            let mut d = GlDraw::new(&mesh_data, Mat4::IDENTITY, Mat4::IDENTITY, gl.lighting);
            d.mode = mode;
            (d.point_size, d.line_width) = (size, size);
            let theirs = render_gl_with(
                &GlScene {
                    width: GL_SIZE,
                    height: GL_SIZE,
                    clear_color: [0.0, 0.0, 0.0, 1.0],
                    depth_test: false,
                    draws: vec![d],
                },
                &gl_options(),
            )
            .unwrap();
            let Overlap {
                both, either, worst, ..
            } = overlap(&ours, &theirs, |_, _| false);
            let tolerance = if mode == GlMode::Lines && shading == LightingMode::Vertex {
                12
            } else {
                3
            };
            let thin = ours.pixels().filter(|p| p.0[..3] != [0, 0, 0]).count();
            let a = save_for_inspection(&ours, &format!("wide_ffvk_{what}"));
            let b = save_for_inspection(&theirs, &format!("wide_gl_{what}"));
            assert!(
                worst <= tolerance && both * 10 >= either * 7,
                "{what}: {both} pixels both cover of {either}, worst {worst}/255; images {} and {}",
                a.display(),
                b.display()
            );
            // Wide: nine points of 4 × 4 pixels, four lines of about 13 pixels, three wide.
            let least = if mode == GlMode::Points {
                9 * 12
            } else {
                4 * 3 * 10
            };
            assert!(thin >= least, "{what}: {thin} pixels");
        }
    }
    // A size of 0 is GL's GL_INVALID_VALUE; one past the device's range cannot be drawn.
    let mesh = r
        .upload(
            &MeshData::new(mode_vertices(GlMode::Points), (0..9).collect())
                .with_topology(Topology::PointList),
        )
        .unwrap();
    for (size, words) in [
        (0.0, "point size 0: expected a finite size above 0"),
        (1e6, "point size 1000000: expected"),
    ] {
        let mut frame = Frame::new(8, 8);
        frame.draws.push(
            Draw::new(
                &mesh,
                Mat4::IDENTITY,
                Mat4::IDENTITY,
                two_sided(LightingMode::Vertex).lighting,
            )
            .with_point_size(size),
        );
        let e = r.render(&frame).unwrap_err().to_string();
        assert!(e.contains(words), "{e}");
    }
    drop(mesh);
    finish(r);
}
