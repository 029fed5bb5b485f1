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

use crate::canvas::{binding, max_difference, Canvas, QUAD};
use crate::support::save_for_inspection;

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

/// A quad over the whole viewport whose eye-space depth runs from −1 (left) to −9 (right),
/// with a fog coordinate running from 1 to 9 alongside: x y z, then the coordinate.
const DEEP_QUAD: [[f32; 4]; 4] = [
    [-1.0, -1.0, -1.0, 1.0],
    [1.0, -1.0, -9.0, 9.0],
    [-1.0, 1.0, -1.0, 1.0],
    [1.0, 1.0, -9.0, 9.0],
];

/// The fog set-ups the tests draw: (mode, density, start, end).
const FOGS: [(ffvk::gl::state::FogMode, f32, f32, f32); 3] = [
    (ffvk::gl::state::FogMode::Linear, 1.0, 1.0, 9.0),
    (ffvk::gl::state::FogMode::Exp, 0.2, 0.0, 1.0),
    (ffvk::gl::state::FogMode::Exp2, 0.15, 0.0, 1.0),
];

const FOG_COLOR: Vec4 = Vec4::new(0.1, 0.2, 0.9, 1.0);
const FOGGED: Vec4 = Vec4::new(0.8, 0.6, 0.4, 1.0);

fn gl_fog_mode(mode: ffvk::gl::state::FogMode) -> u32 {
    match mode {
        ffvk::gl::state::FogMode::Linear => raw::LINEAR,
        ffvk::gl::state::FogMode::Exp => raw::EXP,
        _ => raw::EXP2,
    }
}

/// Fog in each mode (GL_LINEAR, GL_EXP, GL_EXP2) from each source (the eye-space depth, and
/// a fog coordinate array), per fragment, on a quad running deep into the view, unlit, in
/// the vertex and fragment modes, against Mesa's GL (glFog, glFogCoord).
#[test]
fn fog_in_each_mode_and_source_fogs_as_mesa_does() {
    use ffvk::gl::state::{FogParam, FogSource};
    let (size, cell) = (48, 16);
    let mut canvas = Canvas::new(size);
    let device = canvas.ffvk();
    let buffer = canvas.buffer(bytemuck::cast_slice(&DEEP_QUAD));
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let input = VertexInput::new(vec![binding(16)], position, position)
        .with_normal(None)
        .with_fog_coord(Some(Attribute::new(0, 12, vk::Format::R32_SFLOAT)));
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, input)).unwrap();
    let buffers = [(buffer, 0)];
    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);
    let projection = Mat4::orthographic_rh_gl(-1.0, 1.0, -1.0, 1.0, 0.0, 10.0);

    let mesa = render_raw_gl(size, size, |g| {
        // SAFETY: a context is current; the arrays outlive the calls that read them.
        unsafe {
            g.MatrixMode(raw::PROJECTION);
            g.Ortho(-1.0, 1.0, -1.0, 1.0, 0.0, 10.0);
            g.MatrixMode(raw::MODELVIEW);
            g.Enable(raw::FOG);
            g.Fogfv(raw::FOG_COLOR, FOG_COLOR.to_array().as_ptr());
            g.Color4f(FOGGED.x, FOGGED.y, FOGGED.z, FOGGED.w);
            for (column, (mode, density, start, end)) in FOGS.iter().enumerate() {
                g.Fogi(raw::FOG_MODE, gl_fog_mode(*mode) as i32);
                g.Fogf(raw::FOG_DENSITY, *density);
                g.Fogf(raw::FOG_START, *start);
                g.Fogf(raw::FOG_END, *end);
                for (row, source) in [raw::FRAGMENT_DEPTH, raw::FOG_COORD].iter().enumerate() {
                    g.Fogi(raw::FOG_COORD_SRC, *source as i32);
                    g.Viewport(
                        (column as u32 * cell) as i32,
                        (row as u32 * cell) as i32,
                        cell as i32,
                        cell as i32,
                    );
                    g.Begin(raw::TRIANGLE_STRIP);
                    for v in DEEP_QUAD {
                        g.FogCoordf(v[3]);
                        g.Vertex3f(v[0], v[1], v[2]);
                    }
                    g.End();
                }
            }
        }
    })
    .expect("Mesa's GL renders");
    save_for_inspection(&mesa, "fragment_stages_fog_mesa");

    for mode in [LightingMode::Vertex, LightingMode::Fragment] {
        let mut states = Vec::new();
        for (fog_mode, density, start, end) in FOGS {
            for source in [FogSource::FragmentDepth, FogSource::FogCoord] {
                let mut gl = GlState::new();
                gl.lighting_mode(mode);
                gl.enable(Cap::Fog).unwrap();
                for param in [
                    FogParam::Mode(fog_mode),
                    FogParam::Density(density),
                    FogParam::Start(start),
                    FogParam::End(end),
                    FogParam::Color(FOG_COLOR),
                    FogParam::CoordSrc(source),
                ] {
                    gl.fog(param).unwrap();
                }
                gl.color(FOGGED).unwrap();
                states.push(gl.lighting);
            }
        }
        lighting.begin_frame(0).unwrap();
        let mut results = Vec::new();
        let ffvk = canvas
            .frame(|d, cmd| {
                for (i, state) in states.iter().enumerate() {
                    let (column, row) = (i as u32 / 2, i as u32 % 2);
                    let draw = LitDraw::new(state, Mat4::IDENTITY, projection, &buffers, strip);
                    // SAFETY: the canvas's pass is open; the buffer lives as long as it.
                    unsafe { d.cmd_set_viewport(cmd, 0, &[viewport(column * cell, row * cell, cell, size)]) };
                    // SAFETY: as above.
                    results.push(unsafe { lighting.draw(cmd, 0, &draw) });
                }
            })
            .unwrap();
        for r in results {
            r.unwrap();
        }
        save_for_inspection(&ffvk, &format!("fragment_stages_fog_{}", mode.name()));
        // Not unfogged: the right edge of the linear cell is nearly the fog color.
        let right = ffvk.get_pixel(cell - 1, size - cell / 2).0;
        assert!(
            right[2] > 200,
            "{}: the far side is fogged: {right:?}",
            mode.name()
        );
        let d = max_difference(&ffvk, &mesa);
        assert!(
            d <= 1,
            "{}: ffvk and Mesa's GL differ by {d}/255 (tests/output/fragment_stages_fog_*)",
            mode.name()
        );
    }
    drop(lighting);
    drop(device);
}

/// GL 2.1 takes the fog coordinate as it is (section 3.10): a coordinate of −2 with
/// GL_LINEAR from 0 to 10 gives f = 1.2, clamped to 1 (no fog), and with GL_EXP of density
/// 0.5 f = e, clamped to 1. Mesa 22.3 takes |c| (f = 0.8 and e^−1): ffvk follows the spec, and
/// this test pins Mesa's deviation. And GL_FOG_HINT GL_FASTEST computes f per vertex (GL 2.1
/// allows it; Mesa ignores the hint): with GL_EXP2 of density 0.5 and coordinates 0 and 4,
/// f is interpolated between 1 and e^−4, not taken at the interpolated coordinate.
#[test]
fn negative_fog_coordinates_and_per_vertex_fog_follow_the_spec_where_mesa_does_not() {
    use ffvk::gl::state::{FogHint, FogMode, FogParam, FogSource};
    let size = 32;
    let mut canvas = Canvas::new(size);
    let device = canvas.ffvk();
    let flat: Vec<f32> = QUAD
        .iter()
        .flat_map(|p| [p[0], p[1], p[2], if p[0] < 0.0 { 0.0 } else { 4.0 }])
        .collect();
    let buffer = canvas.buffer(bytemuck::cast_slice(&flat));
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let bare = VertexInput::new(vec![binding(16)], position, position).with_normal(None);
    let with_coords = bare
        .clone()
        .with_fog_coord(Some(Attribute::new(0, 12, vk::Format::R32_SFLOAT)));
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, bare)).unwrap();
    let coords = lighting.vertex_layout(with_coords).unwrap();
    let buffers = [(buffer, 0)];
    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);
    let fogged_state = |mode: FogMode, density: f32, hint: FogHint| {
        let mut gl = GlState::new();
        gl.enable(Cap::Fog).unwrap();
        for p in [
            FogParam::Mode(mode),
            FogParam::Density(density),
            FogParam::Start(0.0),
            FogParam::End(10.0),
            FogParam::Color(FOG_COLOR),
            FogParam::CoordSrc(FogSource::FogCoord),
        ] {
            gl.fog(p).unwrap();
        }
        gl.fog_hint(hint);
        gl.fog_coord(-2.0).unwrap();
        gl.color(FOGGED).unwrap();
        gl.lighting
    };
    let states = [
        fogged_state(FogMode::Linear, 1.0, FogHint::DontCare),
        fogged_state(FogMode::Exp, 0.5, FogHint::DontCare),
        fogged_state(FogMode::Exp2, 0.5, FogHint::Fastest),
    ];
    let half = size / 2;
    lighting.begin_frame(0).unwrap();
    let mut results = Vec::new();
    let ffvk = canvas
        .frame(|d, cmd| {
            // The negative coordinate (the current one) in the top half, a cell per mode; the
            // per-vertex fog across the bottom half.
            for (i, state) in states.iter().enumerate() {
                let (vp, layout) = match i {
                    2 => (
                        vk::Viewport {
                            x: 0.0,
                            y: half as f32,
                            width: size as f32,
                            height: half as f32,
                            min_depth: 0.0,
                            max_depth: 1.0,
                        },
                        Some(coords),
                    ),
                    _ => (viewport(i as u32 * half, half, half, size), None),
                };
                let draw =
                    LitDraw::new(state, Mat4::IDENTITY, Mat4::IDENTITY, &buffers, strip).with_layout(layout);
                // SAFETY: the canvas's pass is open; the buffer lives as long as it.
                unsafe { d.cmd_set_viewport(cmd, 0, &[vp]) };
                // SAFETY: as above.
                results.push(unsafe { lighting.draw(cmd, 0, &draw) });
            }
        })
        .unwrap();
    for r in results {
        r.unwrap();
    }
    drop(lighting);
    drop(device);
    save_for_inspection(&ffvk, "fragment_stages_fog_spec");
    let unorm = |c: f32| (c * 255.0).round() as i32;
    let close = |got: [u8; 4], want: Vec4, slack: i32, what: &str| {
        let want = [unorm(want.x), unorm(want.y), unorm(want.z)];
        assert!(
            got.iter()
                .zip(want)
                .all(|(&g, w)| (i32::from(g) - w).abs() <= slack),
            "{what}: {got:?}, expected {want:?}"
        );
    };
    let fog = |f: f32| FOG_COLOR.lerp(FOGGED, f).truncate().extend(1.0);
    // The spec: f clamped to 1, the color unfogged, in both top cells.
    close(
        ffvk.get_pixel(half / 2, half / 2).0,
        FOGGED,
        1,
        "GL_LINEAR at c = -2",
    );
    close(
        ffvk.get_pixel(half + half / 2, half / 2).0,
        FOGGED,
        1,
        "GL_EXP at c = -2",
    );
    // Per vertex: at pixel x, f interpolates between 1 (c = 0) and e^-4 (c = 4).
    for x in [4, half, size - 5] {
        let t = (x as f32 + 0.5) / size as f32;
        let per_vertex = (1.0 - t) + t * (-4.0f32).exp();
        close(
            ffvk.get_pixel(x, size - 4).0,
            fog(per_vertex),
            2,
            &format!("GL_FASTEST at x = {x}"),
        );
    }

    // Mesa's GL on the same calls.
    let mesa = render_raw_gl(size, size, |g| {
        // SAFETY: a context is current.
        unsafe {
            g.Enable(raw::FOG);
            g.Fogfv(raw::FOG_COLOR, FOG_COLOR.to_array().as_ptr());
            g.Fogi(raw::FOG_COORD_SRC, raw::FOG_COORD as i32);
            g.Fogf(raw::FOG_START, 0.0);
            g.Fogf(raw::FOG_END, 10.0);
            g.Color4f(FOGGED.x, FOGGED.y, FOGGED.z, FOGGED.w);
            for (i, (mode, density)) in [(raw::LINEAR, 1.0), (raw::EXP, 0.5)].iter().enumerate() {
                g.Fogi(raw::FOG_MODE, *mode as i32);
                g.Fogf(raw::FOG_DENSITY, *density);
                g.Viewport(i as i32 * half as i32, half as i32, half as i32, half as i32);
                g.Begin(raw::TRIANGLE_STRIP);
                for p in QUAD {
                    g.FogCoordf(-2.0);
                    g.Vertex3f(p[0], p[1], p[2]);
                }
                g.End();
            }
            g.Hint(raw::FOG_HINT, raw::FASTEST);
            g.Fogi(raw::FOG_MODE, raw::EXP2 as i32);
            g.Fogf(raw::FOG_DENSITY, 0.5);
            g.Viewport(0, 0, size as i32, half as i32);
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                g.FogCoordf(if p[0] < 0.0 { 0.0 } else { 4.0 });
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
        }
    })
    .expect("Mesa's GL renders");
    save_for_inspection(&mesa, "fragment_stages_fog_spec_mesa");
    // Mesa's deviation: |c|, so f = 0.8 for GL_LINEAR and e^-1 for GL_EXP.
    close(
        mesa.get_pixel(half / 2, half / 2).0,
        fog(0.8),
        1,
        "Mesa's GL_LINEAR at c = -2 (|c|)",
    );
    close(
        mesa.get_pixel(half + half / 2, half / 2).0,
        fog((-1.0f32).exp()),
        1,
        "Mesa's GL_EXP at c = -2 (|c|)",
    );
    // Mesa ignores GL_FASTEST: f at the interpolated coordinate, e^-(2 × 0.5 × c)^2 ... at the
    // middle, c = 2: e^-1.
    let t = (half as f32 + 0.5) / size as f32;
    let c = 4.0 * t;
    close(
        mesa.get_pixel(half, size - 4).0,
        fog((-(0.5 * c) * (0.5 * c)).exp()),
        2,
        "Mesa's GL_FASTEST (per fragment)",
    );
}

/// User clip planes (§2.12) cutting a lit quad: GL_CLIP_PLANE0 = (1, 0, 0, 0) given under a
/// modelview that moves x by 0.5 (stored in eye space as (1, 0, 0, −0.5): x ≥ 0.5 kept), and
/// GL_CLIP_PLANE2 = (0, 1, 1, 0) under the identity; drawn under another modelview, which
/// moves neither plane. In the vertex, flat and fragment modes, against Mesa's GL.
#[test]
fn user_clip_planes_cut_a_lit_quad_where_mesas_gl_cuts_it() {
    use ffvk::gl::state::{GlState, MaterialParam};
    let size = 32;
    let mut canvas = Canvas::new(size);
    let device = canvas.ffvk();
    let quad: Vec<f32> = QUAD
        .iter()
        .flat_map(|p| [p[0] * 0.9, p[1] * 0.9, p[2], 0.0, 0.0, 1.0])
        .collect();
    let buffer = canvas.buffer(bytemuck::cast_slice(&quad));
    let input = VertexInput::new(
        vec![binding(24)],
        Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT),
        Attribute::new(0, 12, vk::Format::R32G32B32_SFLOAT),
    );
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, input)).unwrap();
    let buffers = [(buffer, 0)];
    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);
    let moved = Mat4::from_translation(Vec3::new(0.5, 0.0, 0.0));
    let drawn_under = Mat4::from_rotation_z(0.3);
    let diffuse = Vec4::new(0.9, 0.5, 0.2, 1.0);

    let mesa = render_raw_gl(size, size, |g| {
        // SAFETY: a context is current.
        unsafe {
            g.Enable(raw::LIGHTING);
            g.Enable(raw::LIGHT0);
            g.Materialfv(raw::FRONT_AND_BACK, raw::DIFFUSE, diffuse.to_array().as_ptr());
            g.LoadMatrixf(moved.to_cols_array().as_ptr());
            g.ClipPlane(raw::CLIP_PLANE0, [1.0f64, 0.0, 0.0, 0.0].as_ptr());
            g.LoadIdentity();
            g.ClipPlane(raw::CLIP_PLANE2, [0.0f64, 1.0, 1.0, 0.0].as_ptr());
            g.Enable(raw::CLIP_PLANE0);
            g.Enable(raw::CLIP_PLANE2);
            g.LoadMatrixf(drawn_under.to_cols_array().as_ptr());
            g.Begin(raw::TRIANGLE_STRIP);
            for v in quad.chunks(6) {
                g.Normal3f(v[3], v[4], v[5]);
                g.Vertex3f(v[0], v[1], v[2]);
            }
            g.End();
        }
    })
    .expect("Mesa's GL renders");
    save_for_inspection(&mesa, "fragment_stages_clip_mesa");

    for mode in [LightingMode::Vertex, LightingMode::Flat, LightingMode::Fragment] {
        let mut gl = GlState::new();
        gl.lighting_mode(mode);
        gl.enable(Cap::Lighting).unwrap();
        gl.enable(Cap::Light(0)).unwrap();
        gl.material(
            ffvk::gl::state::Face::FrontAndBack,
            MaterialParam::Diffuse(diffuse),
        )
        .unwrap();
        gl.load_modelview(moved).unwrap();
        gl.clip_plane(0, glam::DVec4::new(1.0, 0.0, 0.0, 0.0)).unwrap();
        gl.load_modelview(Mat4::IDENTITY).unwrap();
        gl.clip_plane(2, glam::DVec4::new(0.0, 1.0, 1.0, 0.0)).unwrap();
        gl.enable(Cap::ClipPlane(0)).unwrap();
        gl.enable(Cap::ClipPlane(2)).unwrap();
        assert_eq!(
            gl.lighting.clip.planes[0],
            Vec4::new(1.0, 0.0, 0.0, -0.5),
            "p M^-1 at the call"
        );
        let draw = LitDraw::new(&gl.lighting, drawn_under, Mat4::IDENTITY, &buffers, strip);
        lighting.begin_frame(0).unwrap();
        let mut result = Ok(());
        let ffvk = canvas
            .frame(|_, cmd| {
                // SAFETY: the canvas's pass is open; the buffer lives as long as it.
                result = unsafe { lighting.draw(cmd, 0, &draw) };
            })
            .unwrap();
        result.unwrap();
        save_for_inspection(&ffvk, &format!("fragment_stages_clip_{}", mode.name()));
        // Kept: right of x = 0.5 and above y = 0 (eye space, here window space: the projection is
        // the identity), e.g. (0.6, 0.3); cut: (−0.5, 0.3) and (0.6, −0.53), inside the quad.
        let (kept, cut) = (ffvk.get_pixel(25, 11).0, ffvk.get_pixel(8, 11).0);
        assert_ne!(kept, [0; 4], "{}: inside both planes", mode.name());
        assert_eq!(cut, [0; 4], "{}: left of x = 0.5", mode.name());
        assert_eq!(ffvk.get_pixel(25, 24).0, [0; 4], "{}: below y = 0", mode.name());
        let d = max_difference(&ffvk, &mesa);
        assert!(
            d <= 1,
            "{}: ffvk and Mesa's GL differ by {d}/255 (tests/output/fragment_stages_clip_*)",
            mode.name()
        );
    }
    drop(lighting);
    drop(device);
}

/// A draw with a user clip plane on a device without shaderClipDistance is refused, naming the
/// feature and `EnabledFeatures::clip_distance`, before anything is recorded.
/// glClipPlane needs M⁻¹ of the whole modelview: one whose 4×4 has no inverse is refused naming
/// glClipPlane's p · M⁻¹, even where its upper 3×3 (the normal matrix's) is the identity; one
/// whose 3×3 alone is singular takes the plane.
#[test]
fn a_clip_plane_under_a_modelview_without_an_inverse_is_refused_naming_glclipplane() {
    let mut gl = GlState::new();
    let singular_4x4 = Mat4::from_diagonal(Vec4::new(1.0, 1.0, 1.0, 0.0));
    gl.load_modelview(singular_4x4).unwrap();
    let e = gl.clip_plane(0, glam::DVec4::X).unwrap_err().to_string();
    assert!(
        e.contains("determinant of the modelview = 0") && e.contains("glClipPlane"),
        "{e}"
    );
    assert_eq!(gl.lighting.clip.planes[0], Vec4::ZERO, "the plane is unchanged");
    let singular_3x3 = Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::W, Vec4::Z);
    assert_ne!(singular_3x3.determinant(), 0.0);
    gl.load_modelview(singular_3x3).unwrap();
    gl.clip_plane(0, glam::DVec4::X).unwrap();
}

#[test]
fn a_clip_plane_on_a_device_without_clip_distances_is_refused_by_name() {
    use crate::embedding::PlainDevice;
    use ffvk::vk::{Device, EnabledFeatures};
    let plain = PlainDevice::new();
    // SAFETY: the device comes from this physical device with dynamic rendering, and outlives
    // every ffvk object here.
    let device = unsafe {
        Device::from_caller(
            &plain.instance,
            plain.physical,
            plain.device.clone(),
            EnabledFeatures::default().with_dynamic_rendering(true),
        )
    }
    .unwrap();
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let input = VertexInput::new(vec![binding(12)], position, position).with_normal(None);
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, input)).unwrap();
    let mut gl = GlState::new();
    gl.clip_plane(0, glam::DVec4::new(1.0, 0.0, 0.0, 0.0)).unwrap();
    gl.enable(Cap::ClipPlane(0)).unwrap();
    let buffers = [(vk::Buffer::null(), 0)];
    let draw = LitDraw::new(
        &gl.lighting,
        Mat4::IDENTITY,
        Mat4::IDENTITY,
        &buffers,
        Geometry::vertices(3),
    );
    lighting.begin_frame(0).unwrap();
    // SAFETY: the draw is refused while staging, before the command buffer is touched.
    let e = unsafe { lighting.draw(vk::CommandBuffer::null(), 0, &draw) }
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("shaderClipDistance") && e.contains("clip_distance"),
        "{e}"
    );
    drop(lighting);
    drop(device);
}

/// Scene files carry the stages with GL's names and defaults: `color_sum`, `[fog]`,
/// `[alpha_test]` and `[[clip_planes]]` (in world space, set with the view loaded, as
/// glClipPlane after glLoadMatrix(view)); a bad word or value is refused naming the field.
#[test]
fn scene_files_set_the_stages_and_refuse_bad_values_naming_the_field() {
    use ffvk::gl::state::{FogHint, FogMode, FogSource};
    use ffvk::scene::Scene;
    use std::path::Path;
    let text = r#"
        color_sum = true
        [camera]
        eye = [0.0, 0.0, 5.0]
        target = [0.0, 0.0, 0.0]
        [fog]
        mode = "linear"
        start = 2.0
        end = 8.0
        color = [0.5, 0.5, 0.5]
        coord_src = "fog_coord"
        coord = 3.0
        hint = "fastest"
        [alpha_test]
        func = "gequal"
        reference = 1.5
        [[clip_planes]]
        equation = [1.0, 0.0, 0.0, 0.0]
        [[meshes]]
        builtin = "sphere"
    "#;
    let scene = Scene::parse(text, Path::new("stages.toml")).unwrap();
    let s = &scene.state;
    assert!(s.fragment.color_sum);
    let fog = &s.fragment.fog;
    assert!(fog.enabled);
    assert_eq!(
        (fog.mode, fog.start, fog.end, fog.source, fog.hint),
        (FogMode::Linear, 2.0, 8.0, FogSource::FogCoord, FogHint::Fastest)
    );
    assert_eq!(fog.color, Vec4::new(0.5, 0.5, 0.5, 1.0));
    assert_eq!(s.current_fog_coord, 3.0);
    let alpha = &s.fragment.alpha_test;
    assert!(alpha.enabled);
    assert_eq!(
        (alpha.func, alpha.reference),
        (CompareFunc::GreaterOrEqual, 1.0),
        "the reference clamped"
    );
    // The world's x >= 0 in eye space: the view looks down -z from (0, 0, 5), so the plane is
    // (1, 0, 0, 0) there too.
    assert!(s.clip.enabled[0]);
    assert!(
        (s.clip.planes[0] - Vec4::X).abs().max_element() < 1e-6,
        "{:?}",
        s.clip.planes[0]
    );

    for (bad, field) in [
        ("[fog]\nmode = \"exp3\"", "fog.mode"),
        ("[fog]\ndensity = -1.0", "fog.density"),
        ("[fog]\nhint = \"slow\"", "fog.hint"),
        ("[alpha_test]\nfunc = \"sometimes\"", "alpha_test.func"),
        (
            "[[clip_planes]]\nindex = 6\nequation = [1.0, 0.0, 0.0, 0.0]",
            "clip_planes[0]",
        ),
        ("[[clip_planes]]\nenabled = true", "clip_planes[0].equation"),
    ] {
        let text = format!("{bad}\n[[meshes]]\nbuiltin = \"sphere\"\n");
        let e = Scene::parse(&text, Path::new("bad.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains(field), "{bad:?}: {e}");
    }
}

/// GL's order (§3.8.13 texturing, §3.9 color sum, §3.10 fog, §4.1.4 alpha test): a textured
/// quad under `GL_REPLACE`, fogged with f = 0.5 everywhere (GL_LINEAR over a constant fog
/// coordinate), alpha-tested after the fog. Fog applied before texturing would be replaced by
/// the texel (an unfogged red); the alpha test before fog would see another alpha. Against
/// Mesa's GL and the spec's value, in the vertex and fragment modes.
#[test]
fn texturing_then_fog_then_the_alpha_test_run_in_gls_order() {
    use ffvk::draw::texture::sampler_info;
    use ffvk::gl::state::{FogMode, FogParam, FogSource};
    use ffvk::gl::texture::{Sampling, TexEnvMode};
    let size = 16;
    let texel: [u8; 4] = [255, 0, 0, 128];
    let mut canvas = Canvas::new(size);
    let device = canvas.ffvk();
    let (view, sampler) = canvas.texture(&texel, (1, 1), &sampler_info(&Sampling::NEAREST, 1));
    let mut with_st = Vec::new();
    for p in QUAD {
        with_st.extend_from_slice(&[p[0], p[1], p[2], 0.5, 0.5]);
    }
    let buffer = canvas.buffer(bytemuck::cast_slice(&with_st));
    let position = Attribute::new(0, 0, vk::Format::R32G32B32_SFLOAT);
    let input = VertexInput::new(vec![binding(20)], position, position)
        .with_normal(None)
        .with_texcoord(Some(Attribute::new(0, 12, vk::Format::R32G32_SFLOAT)));
    let target = Target::new(vk::Format::R8G8B8A8_UNORM, vk::Format::UNDEFINED);
    let mut lighting = Lighting::new(&device, &LightingOptions::new(target, input)).unwrap();
    // SAFETY: the view and sampler are the canvas's, alive until it drops, after `lighting`.
    let texture = unsafe { lighting.bind_texture(view, sampler) }.unwrap();
    let buffers = [(buffer, 0)];
    let strip = Geometry::vertices(4).with_topology(Topology::TriangleStrip);
    let fog_color = Vec4::new(0.0, 0.0, 1.0, 1.0);

    let mesa = render_raw_gl(size, size, |g| {
        // SAFETY: a context is current; the texel outlives glTexImage2D.
        unsafe {
            let mut name = 0;
            g.GenTextures(1, &mut name);
            g.BindTexture(raw::TEXTURE_2D, name);
            g.TexImage2D(
                raw::TEXTURE_2D,
                0,
                raw::RGBA as i32,
                1,
                1,
                0,
                raw::RGBA,
                raw::UNSIGNED_BYTE,
                texel.as_ptr().cast(),
            );
            g.TexParameteri(raw::TEXTURE_2D, raw::TEXTURE_MIN_FILTER, raw::NEAREST as i32);
            g.TexParameteri(raw::TEXTURE_2D, raw::TEXTURE_MAG_FILTER, raw::NEAREST as i32);
            g.TexEnvi(raw::TEXTURE_ENV, raw::TEXTURE_ENV_MODE, raw::REPLACE as i32);
            g.Enable(raw::TEXTURE_2D);
            g.Enable(raw::FOG);
            g.Fogi(raw::FOG_MODE, raw::LINEAR as i32);
            g.Fogf(raw::FOG_START, 0.0);
            g.Fogf(raw::FOG_END, 2.0);
            g.Fogi(raw::FOG_COORD_SRC, raw::FOG_COORD as i32);
            g.Fogfv(raw::FOG_COLOR, fog_color.to_array().as_ptr());
            g.Enable(raw::ALPHA_TEST);
            g.AlphaFunc(raw::GEQUAL, 0.5);
            g.FogCoordf(1.0);
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                g.TexCoord2f(0.5, 0.5);
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
            g.DeleteTextures(1, &name);
        }
    })
    .expect("Mesa's GL renders");
    save_for_inspection(&mesa, "fragment_stages_order_mesa");

    for mode in [LightingMode::Vertex, LightingMode::Fragment] {
        let mut gl = GlState::new();
        gl.lighting_mode(mode);
        gl.lighting.texture_units[0].enabled = true;
        gl.lighting.texture_units[0].env_mode = TexEnvMode::Replace;
        for p in [
            FogParam::Mode(FogMode::Linear),
            FogParam::Start(0.0),
            FogParam::End(2.0),
            FogParam::CoordSrc(FogSource::FogCoord),
            FogParam::Color(fog_color),
        ] {
            gl.fog(p).unwrap();
        }
        gl.enable(Cap::Fog).unwrap();
        gl.enable(Cap::AlphaTest).unwrap();
        gl.alpha_func(CompareFunc::GreaterOrEqual, 0.5).unwrap();
        gl.fog_coord(1.0).unwrap();
        let draw = LitDraw::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &buffers, strip)
            .with_texture(Some(&texture));
        lighting.begin_frame(0).unwrap();
        let mut result = Ok(());
        let ffvk = canvas
            .frame(|_, cmd| {
                // SAFETY: the canvas's pass is open; buffer and texture outlive the frame.
                result = unsafe { lighting.draw(cmd, 0, &draw) };
            })
            .unwrap();
        result.unwrap();
        save_for_inspection(&ffvk, &format!("fragment_stages_order_{}", mode.name()));
        // The texel (1, 0, 0, 128/255) replaces the color, fog mixes half of it with blue
        // (alpha untouched), and 128/255 passes GL_GEQUAL 0.5 (128 >= 128 at 8 bits).
        let got = ffvk.get_pixel(size / 2, size / 2).0;
        let want = [128, 0, 128, 128];
        assert!(
            got.iter().zip(want).all(|(a, b)| a.abs_diff(b) <= 1),
            "{}: {got:?}, expected {want:?}: texturing, then fog, then the alpha test",
            mode.name()
        );
        let d = max_difference(&ffvk, &mesa);
        assert!(d <= 1, "{}: ffvk and Mesa's GL differ by {d}/255", mode.name());
    }
    drop(lighting);
    drop(device);
}
