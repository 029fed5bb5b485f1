//! The fixed-function stages after texturing (GL 2.1 §3.9 color sum, §4.1.4 alpha test),
//! drawn through the embedding API and against Mesa's GL issuing the same calls, with the
//! spec's own verdicts where they are sharp.

use ash::vk;
use ffvk::gl::state::{Cap, CompareFunc, GlState, LightingMode};
use ffvk::{
    Attribute, DrawValues, Geometry, Lighting, LightingOptions, LitDraw, Target, Topology, VertexInput,
};
use ffvk_cli::gl_reference::{raw, render_raw_gl};
use glam::{Mat4, Vec3, Vec4};

use crate::canvas::Canvas;
use crate::support::save_for_inspection;

/// A quad over its whole viewport as a triangle strip, z = 0.
const QUAD: [[f32; 3]; 4] = [
    [-1.0, -1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, 1.0, 0.0],
];

fn binding(stride: u32) -> vk::VertexInputBindingDescription {
    vk::VertexInputBindingDescription {
        binding: 0,
        stride,
        input_rate: vk::VertexInputRate::VERTEX,
    }
}

fn viewport(x: u32, y: u32, size: u32, canvas: u32) -> vk::Viewport {
    // GL's glViewport(x, y, size, size) on a target `canvas` high: rows from the top.
    vk::Viewport {
        x: x as f32,
        y: (canvas - y - size) as f32,
        width: size as f32,
        height: size as f32,
        min_depth: 0.0,
        max_depth: 1.0,
    }
}

fn max_difference(a: &image::RgbaImage, b: &image::RgbaImage) -> u8 {
    a.pixels()
        .zip(b.pixels())
        .flat_map(|(p, q)| p.0.iter().zip(q.0).map(|(x, y)| x.abs_diff(y)))
        .max()
        .unwrap_or(0)
}

/// (alpha, reference) pairs at the alpha test's edges on an 8-bit target: 0.5 and 0.5015 are
/// both 128 at 8 bits (a float compare would tell them apart); 0.498 is 127; and the ends.
const EDGES: [(f32, f32); 5] = [(0.5, 0.5015), (0.5, 0.498), (0.2, 0.2), (0.0, 0.0), (1.0, 1.0)];

/// Every function of glAlphaFunc at each edge pair, a cell each (8 columns, 5 rows of 8×8
/// pixels), unlit quads of the current color (1, 1, 1, alpha): the cells kept and discarded
/// are GL 2.1's verdicts at 8 bits and Mesa's image, in the vertex and fragment modes.
#[test]
fn the_alpha_test_keeps_what_gl_keeps_comparing_at_the_targets_8_bit_precision() {
    const CELL: u32 = 8;
    let size = 64;
    let mut canvas = Canvas::new(size);
    let device = canvas.ffvk();
    let buffer = canvas.buffer(bytemuck::cast_slice(&QUAD));
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let input = VertexInput::new(vec![binding(12)], position, position).with_normal(None);
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, input)).unwrap();
    let buffers = [(buffer, 0)];
    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);

    let mesa = render_raw_gl(size, size, |g| {
        // SAFETY: a context is current.
        unsafe {
            g.Enable(raw::ALPHA_TEST);
            for (column, func) in CompareFunc::ALL.iter().enumerate() {
                for (row, (alpha, reference)) in EDGES.iter().enumerate() {
                    g.Viewport(
                        (column as u32 * CELL) as i32,
                        (row as u32 * CELL) as i32,
                        CELL as i32,
                        CELL as i32,
                    );
                    g.AlphaFunc(raw::NEVER + func.code(), *reference);
                    g.Color4f(1.0, 1.0, 1.0, *alpha);
                    g.Begin(raw::TRIANGLE_STRIP);
                    for p in QUAD {
                        g.Vertex3f(p[0], p[1], p[2]);
                    }
                    g.End();
                }
            }
        }
    })
    .expect("Mesa's GL renders");
    save_for_inspection(&mesa, "fragment_stages_alpha_test_mesa");

    for mode in [LightingMode::Vertex, LightingMode::Fragment] {
        let mut states = Vec::new();
        for func in CompareFunc::ALL {
            for (alpha, reference) in EDGES {
                let mut gl = GlState::new();
                gl.lighting_mode(mode);
                gl.enable(Cap::AlphaTest).unwrap();
                gl.alpha_func(func, reference).unwrap();
                gl.color(Vec4::new(1.0, 1.0, 1.0, alpha)).unwrap();
                states.push(gl.lighting);
            }
        }
        let draws: Vec<LitDraw> = states
            .iter()
            .map(|s| LitDraw::new(s, Mat4::IDENTITY, Mat4::IDENTITY, &buffers, strip))
            .collect();
        lighting.begin_frame(0).unwrap();
        let mut results = Vec::new();
        let ffvk = canvas
            .frame(|d, cmd| {
                for (i, draw) in draws.iter().enumerate() {
                    let (column, row) = (i as u32 / EDGES.len() as u32, i as u32 % EDGES.len() as u32);
                    // SAFETY: the canvas's pass is open; the buffer lives as long as the canvas.
                    unsafe { d.cmd_set_viewport(cmd, 0, &[viewport(column * CELL, row * CELL, CELL, size)]) };
                    // SAFETY: as above.
                    results.push(unsafe { lighting.draw(cmd, 0, draw) });
                }
            })
            .unwrap();
        for r in results {
            r.unwrap();
        }
        save_for_inspection(&ffvk, &format!("fragment_stages_alpha_test_{}", mode.name()));
        // GL 2.1's verdict for each cell, at 8 bits: round(a × 255) func round(ref × 255).
        let fixed = |v: f32| (v * 255.0 + 0.5).floor() as i32;
        for (column, func) in CompareFunc::ALL.iter().enumerate() {
            for (row, (alpha, reference)) in EDGES.iter().enumerate() {
                let (x, y) = (
                    column as u32 * CELL + CELL / 2,
                    size - 1 - (row as u32 * CELL + CELL / 2),
                );
                let kept = ffvk.get_pixel(x, y).0[3] != 0 || ffvk.get_pixel(x, y).0[0] != 0;
                let spec = func.passes(fixed(*alpha), fixed(*reference));
                assert_eq!(
                    kept,
                    spec,
                    "{}: alpha {alpha} {} reference {reference}: GL 2.1 {} it at 8 bits",
                    mode.name(),
                    func.gl_name(),
                    if spec { "keeps" } else { "discards" }
                );
            }
        }
        let d = max_difference(&ffvk, &mesa);
        assert!(
            d <= 1,
            "{}: ffvk and Mesa's GL differ by {d}/255 (tests/output/fragment_stages_*)",
            mode.name()
        );
    }
    drop(lighting);
    drop(device);
}

/// With lighting off, GL_COLOR_SUM adds the secondary color (a per-vertex array of unsigned
/// bytes, then the current secondary color) to the primary; without it the secondary color
/// changes nothing (§3.9). Four cells: sum off and on, an array and the current value; in the
/// vertex and fragment modes, against Mesa's glSecondaryColor3ub / glSecondaryColor3f.
#[test]
fn the_color_sum_adds_the_secondary_color_with_lighting_off_as_mesa_does() {
    let size = 32;
    let half = size / 2;
    let mut canvas = Canvas::new(size);
    let device = canvas.ffvk();
    let secondaries: [[u8; 4]; 4] = [[200, 0, 0, 0], [0, 200, 0, 0], [0, 0, 200, 0], [100, 100, 100, 0]];
    let mut with_array = Vec::new();
    for (p, s) in QUAD.iter().zip(secondaries) {
        with_array.extend_from_slice(bytemuck::cast_slice(p));
        with_array.extend_from_slice(&s);
    }
    let buffers = [
        [(canvas.buffer(&with_array), 0)],
        [(canvas.buffer(bytemuck::cast_slice(&QUAD)), 0)],
    ];
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let array_layout = VertexInput::new(vec![binding(16)], position, position)
        .with_normal(None)
        .with_secondary_color(Some(Attribute::new(0, 12, vk::Format::R8G8B8A8_UNORM)));
    let bare = VertexInput::new(vec![binding(12)], position, position).with_normal(None);
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, array_layout)).unwrap();
    let current = lighting.vertex_layout(bare).unwrap();
    let primary = Vec4::new(0.2, 0.3, 0.4, 1.0);
    let secondary = Vec3::new(0.5, 0.1, 0.3);
    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);

    let mesa = render_raw_gl(size, size, |g| {
        // SAFETY: a context is current.
        unsafe {
            g.Color4f(primary.x, primary.y, primary.z, primary.w);
            for (cell, sum) in [(0, false), (1, true)] {
                if sum {
                    g.Enable(raw::COLOR_SUM);
                }
                g.Viewport(cell * half as i32, half as i32, half as i32, half as i32);
                g.Begin(raw::TRIANGLE_STRIP);
                for (p, s) in QUAD.iter().zip(secondaries) {
                    g.SecondaryColor3ub(s[0], s[1], s[2]);
                    g.Vertex3f(p[0], p[1], p[2]);
                }
                g.End();
                g.Viewport(cell * half as i32, 0, half as i32, half as i32);
                g.SecondaryColor3f(secondary.x, secondary.y, secondary.z);
                g.Begin(raw::TRIANGLE_STRIP);
                for p in QUAD {
                    g.Vertex3f(p[0], p[1], p[2]);
                }
                g.End();
            }
        }
    })
    .expect("Mesa's GL renders");
    save_for_inspection(&mesa, "fragment_stages_color_sum_mesa");

    for mode in [LightingMode::Vertex, LightingMode::Fragment] {
        let mut states = Vec::new();
        for sum in [false, true] {
            let mut gl = GlState::new();
            gl.lighting_mode(mode);
            gl.color(primary).unwrap();
            gl.secondary_color(secondary).unwrap();
            if sum {
                gl.enable(Cap::ColorSum).unwrap();
            }
            states.push(gl.lighting);
        }
        lighting.begin_frame(0).unwrap();
        let mut results = Vec::new();
        let ffvk = canvas
            .frame(|d, cmd| {
                for (cell, state) in states.iter().enumerate() {
                    let values = DrawValues::of(state);
                    let x = cell as u32 * half;
                    for (y, buffers, layout) in [(half, &buffers[0], None), (0, &buffers[1], Some(current))] {
                        let draw = LitDraw::new(state, Mat4::IDENTITY, Mat4::IDENTITY, buffers, strip)
                            .with_values(Some(values))
                            .with_layout(layout);
                        // SAFETY: the canvas's pass is open; the buffers live as long as it.
                        unsafe { d.cmd_set_viewport(cmd, 0, &[viewport(x, y, half, size)]) };
                        // SAFETY: as above.
                        results.push(unsafe { lighting.draw(cmd, 0, &draw) });
                    }
                }
            })
            .unwrap();
        for r in results {
            r.unwrap();
        }
        save_for_inspection(&ffvk, &format!("fragment_stages_color_sum_{}", mode.name()));
        // The sum off: the primary color alone in both left cells; on: the primary plus the
        // current secondary color in the lower right cell.
        let unorm = |c: f32| (c.clamp(0.0, 1.0) * 255.0).round() as u8;
        // Within one step: lavapipe converts 76.5 (0.3 × 255) down.
        let near = |got: [u8; 4], want: [u8; 4], what: &str| {
            assert!(
                got.iter().zip(want).all(|(a, b)| a.abs_diff(b) <= 1),
                "{}: {what}: {got:?}, expected {want:?}",
                mode.name()
            )
        };
        let plain = [unorm(primary.x), unorm(primary.y), unorm(primary.z), 255];
        near(ffvk.get_pixel(half / 2, half / 2).0, plain, "sum off, array");
        near(ffvk.get_pixel(half / 2, size - 2).0, plain, "sum off, current");
        let summed = primary.truncate() + secondary;
        let want = [unorm(summed.x), unorm(summed.y), unorm(summed.z), 255];
        near(
            ffvk.get_pixel(half + half / 2, size - half / 2).0,
            want,
            "sum on, current",
        );
        let d = max_difference(&ffvk, &mesa);
        assert!(
            d <= 1,
            "{}: ffvk and Mesa's GL differ by {d}/255 (tests/output/fragment_stages_*)",
            mode.name()
        );
    }
    drop(lighting);
    drop(device);
}
