//! The raster state of issue 50 beyond offsets and masks, through the Renderer and Mesa's GL
//! (GL 2.1 chapters 3 and 4): the stencil test for each face, glPolygonMode (the same and
//! different modes for the two faces, with GL_POLYGON_OFFSET_LINE), glLogicOp and
//! glLineStipple. Every expectation is Mesa's image, and where the spec fixes a pixel, the
//! spec's value.

use ash::vk;
use ffvk::gl::state::GlState;
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, LineStipple, PolygonModes, PolygonOffset, Renderer, Stencil, StencilFace, Topology};
use ffvk_cli::gl_reference::{GlCall, GlDraw};
use glam::{Mat4, Vec3, Vec4};
use image::RgbaImage;

use crate::support::*;

const SIZE: u32 = 64;
const CLEAR: [f32; 4] = [0.2, 0.4, 0.6, 1.0];
const RED: Vec4 = Vec4::new(1.0, 0.0, 0.0, 1.0);
const GREEN: Vec4 = Vec4::new(0.0, 1.0, 0.0, 1.0);
const BLUE: Vec4 = Vec4::new(0.0, 0.0, 1.0, 1.0);

/// An axis-aligned square of half-size `h` at depth `z` (eye space, under [`view`]), counter-
/// clockwise (front-facing) or, `back`, clockwise.
fn square(h: f32, z: f32, color: Vec4, back: bool) -> MeshData {
    let corners = [(-h, -h), (h, -h), (h, h), (-h, h)];
    let indices = if back {
        vec![0, 2, 1, 0, 3, 2]
    } else {
        vec![0, 1, 2, 0, 2, 3]
    };
    MeshData::new(
        corners
            .iter()
            .map(|&(x, y)| Vertex::new(Vec3::new(x, y, z), Vec3::Z, color))
            .collect(),
        indices,
    )
}

/// A tilted square (its depth has a slope), for polygon modes and offsets.
fn tilted(color: Vec4) -> MeshData {
    let mut m = square(1.0, 0.0, color, false);
    for v in &mut m.vertices {
        let p = Mat4::from_rotation_x(-0.6).transform_point3(Vec3::from_array(v.position));
        v.position = p.to_array();
    }
    m
}

fn view() -> Mat4 {
    Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0))
}

fn projection() -> Mat4 {
    Mat4::perspective_rh_gl(50f32.to_radians(), 1.0, 1.0, 10.0)
}

/// One draw of a test: its mesh, its ffvk raster setters and the GL calls that set the same.
struct Case<'m> {
    mesh: &'m MeshData,
    set: Box<dyn Fn(Draw) -> Draw + 'm>,
    calls: Vec<GlCall>,
}

impl<'m> Case<'m> {
    fn plain(mesh: &'m MeshData) -> Self {
        Case {
            mesh,
            set: Box::new(|d| d),
            calls: Vec::new(),
        }
    }
}

/// The draws through ffvk and through Mesa's GL, unlit, depth test as `depth_test` says.
fn draw_both(r: &mut Renderer, depth_test: bool, cases: &[Case]) -> (RgbaImage, RgbaImage) {
    let state = GlState::new().lighting;
    let meshes: Vec<_> = cases.iter().map(|c| r.upload(c.mesh).unwrap()).collect();
    let mut frame = Frame::new(SIZE, SIZE);
    frame.clear_color = Vec4::from_array(CLEAR);
    frame.depth_test = depth_test;
    for (c, m) in cases.iter().zip(&meshes) {
        frame
            .draws
            .push((c.set)(Draw::new(m, view(), projection(), state)));
    }
    let ours = r.render(&frame).unwrap().into_rgba_image();
    let gl = cases
        .iter()
        .map(|c| {
            let mut d = GlDraw::new(c.mesh, view(), projection(), state);
            d.calls.clone_from(&c.calls);
            d
        })
        .collect();
    let theirs = mesa_image((SIZE, SIZE), CLEAR, depth_test, gl);
    (ours, theirs)
}

/// Pixels that differ by more than 1/255 in some channel.
fn differing(a: &RgbaImage, b: &RgbaImage) -> usize {
    a.pixels()
        .zip(b.pixels())
        .filter(|(p, q)| p.0.iter().zip(q.0).any(|(x, y)| x.abs_diff(y) > 1))
        .count()
}

/// Saves both images and checks they differ in at most `most` pixels.
fn check_like_mesa(what: &str, ours: &RgbaImage, theirs: &RgbaImage, most: usize) {
    let name = what.replace([' ', ':', '(', ')', ',', '/'], "_");
    let a = save_for_inspection(ours, &format!("raster_modes_{name}_ffvk"));
    let b = save_for_inspection(theirs, &format!("raster_modes_{name}_gl"));
    let n = differing(ours, theirs);
    assert!(
        n <= most,
        "{what}: {n} pixels differ from Mesa's GL by more than 1/255 (at most {most}): {} vs {}",
        a.display(),
        b.display()
    );
}

fn rgba(c: Vec4) -> [u8; 4] {
    (c * 255.0).round().to_array().map(|x| x as u8)
}

/// GL 2.1 §4.1.5: a mask drawn with `GL_ALWAYS`/`GL_REPLACE` (its color masked off) limits a
/// later draw with `GL_EQUAL` to the mask's pixels, and `GL_NOTEQUAL` to the others.
#[test]
fn the_stencil_test_limits_a_draw_to_the_pixels_a_mask_wrote() {
    let mut r = renderer();
    let mask = square(0.4, 0.0, RED, false);
    let cover = square(1.5, 0.0, GREEN, false);
    let write = StencilFace::default()
        .with_func(vk::CompareOp::ALWAYS, 1, 0xFF)
        .with_ops(vk::StencilOp::KEEP, vk::StencilOp::KEEP, vk::StencilOp::REPLACE);
    let clear = rgba(Vec4::from_array(CLEAR));
    for func in [vk::CompareOp::EQUAL, vk::CompareOp::NOT_EQUAL] {
        let test = StencilFace::default().with_func(func, 1, 0xFF);
        let cases = [
            Case {
                mesh: &mask,
                set: Box::new(move |d| {
                    d.with_stencil(Some(Stencil::both(write)))
                        .with_color_mask([false; 4])
                }),
                calls: vec![
                    GlCall::Stencil(Stencil::both(write)),
                    GlCall::ColorMask([false; 4]),
                ],
            },
            Case {
                mesh: &cover,
                set: Box::new(move |d| d.with_stencil(Some(Stencil::both(test)))),
                calls: vec![GlCall::Stencil(Stencil::both(test))],
            },
        ];
        let (ours, theirs) = draw_both(&mut r, false, &cases);
        let what = format!("stencil {func:?}");
        check_like_mesa(&what, &ours, &theirs, 0);
        let centre = ours.get_pixel(SIZE / 2, SIZE / 2).0;
        let corner = ours.get_pixel(2, 2).0;
        if func == vk::CompareOp::EQUAL {
            assert_eq!(
                (centre, corner),
                (rgba(GREEN), clear),
                "{what}: only the mask's pixels pass"
            );
        } else {
            assert_eq!(
                (centre, corner),
                (clear, rgba(GREEN)),
                "{what}: only the others pass"
            );
        }
    }
    finish(r);
}

/// GL 2.0's two-sided stencil (§4.1.5, `glStencilOpSeparate`): front faces increment, back
/// faces decrement with wrap from 0 to 255; a later `GL_EQUAL` 1 and `GL_EQUAL` 255 find
/// each. The depth test's failure runs `dpfail`, not `dppass`.
#[test]
fn front_and_back_faces_update_the_stencil_buffer_by_their_own_ops() {
    let mut r = renderer();
    // A front square on the left half, a back (clockwise) square on the right.
    let mut front = square(0.45, 0.0, RED, false);
    let mut back = square(0.45, 0.0, RED, true);
    for v in &mut front.vertices {
        v.position[0] -= 0.5;
    }
    for v in &mut back.vertices {
        v.position[0] += 0.5;
    }
    let faces = Stencil {
        front: StencilFace::default().with_ops(
            vk::StencilOp::KEEP,
            vk::StencilOp::KEEP,
            vk::StencilOp::INCREMENT_AND_CLAMP,
        ),
        back: StencilFace::default().with_ops(
            vk::StencilOp::KEEP,
            vk::StencilOp::KEEP,
            vk::StencilOp::DECREMENT_AND_WRAP,
        ),
    };
    let cover_green = square(1.5, 0.0, GREEN, false);
    let cover_blue = square(1.5, 0.0, BLUE, false);
    let equal =
        |reference| Stencil::both(StencilFace::default().with_func(vk::CompareOp::EQUAL, reference, 0xFF));
    let cases = [
        Case {
            mesh: &front,
            set: Box::new(move |d| d.with_stencil(Some(faces))),
            calls: vec![GlCall::Stencil(faces)],
        },
        Case {
            mesh: &back,
            set: Box::new(move |d| d.with_stencil(Some(faces))),
            calls: vec![GlCall::Stencil(faces)],
        },
        Case {
            mesh: &cover_green,
            set: Box::new(move |d| d.with_stencil(Some(equal(1)))),
            calls: vec![GlCall::Stencil(equal(1))],
        },
        Case {
            mesh: &cover_blue,
            set: Box::new(move |d| d.with_stencil(Some(equal(255)))),
            calls: vec![GlCall::Stencil(equal(255))],
        },
    ];
    let (ours, theirs) = draw_both(&mut r, false, &cases);
    check_like_mesa("two-sided stencil", &ours, &theirs, 0);
    let y = SIZE / 2;
    assert_eq!(ours.get_pixel(SIZE / 4 + 2, y).0, rgba(GREEN), "front: 0 + 1");
    assert_eq!(
        ours.get_pixel(3 * SIZE / 4 - 2, y).0,
        rgba(BLUE),
        "back: 0 - 1 wraps to 255"
    );
    assert_eq!(
        ours.get_pixel(SIZE / 2, 2).0,
        rgba(Vec4::from_array(CLEAR)),
        "neither: 0"
    );
    finish(r);
}

/// GL 2.1 §3.5.4: `GL_LINE` draws a polygon's edges and `GL_POINT` its vertices, and with
/// different front and back modes each polygon takes its own face's mode, culling first.
#[test]
fn polygon_modes_draw_edges_or_vertices_by_each_polygons_facing() {
    let mut r = renderer();
    let mut front = square(0.45, 0.0, RED, false);
    let mut back = square(0.45, 0.0, GREEN, true);
    for v in &mut front.vertices {
        v.position[0] -= 0.5;
    }
    for v in &mut back.vertices {
        v.position[0] += 0.5;
    }
    // Both faces in one mesh, so that one draw has both.
    let mut both = front.clone();
    let base = both.vertices.len() as u32;
    both.vertices.extend(back.vertices.iter().copied());
    both.indices.extend(back.indices.iter().map(|i| i + base));
    let (fill, line, point) = (
        vk::PolygonMode::FILL,
        vk::PolygonMode::LINE,
        vk::PolygonMode::POINT,
    );
    for (front_mode, back_mode) in [
        (line, line),
        (point, point),
        (line, fill),
        (fill, point),
        (point, line),
    ] {
        let modes = PolygonModes {
            front: front_mode,
            back: back_mode,
        };
        let cases = [Case {
            mesh: &both,
            set: Box::new(move |d| d.with_polygon_mode(modes)),
            calls: vec![GlCall::PolygonMode(modes)],
        }];
        let (ours, theirs) = draw_both(&mut r, false, &cases);
        let what = format!("front {front_mode:?} back {back_mode:?}");
        check_like_mesa(&what, &ours, &theirs, 4);
        let centre_of = |x: u32| ours.get_pixel(x, SIZE / 2).0;
        let clear = rgba(Vec4::from_array(CLEAR));
        for (mode, x, color) in [
            (front_mode, SIZE / 4 + 1, RED),
            (back_mode, 3 * SIZE / 4 - 1, GREEN),
        ] {
            let want = if mode == fill { rgba(color) } else { clear };
            assert_eq!(centre_of(x), want, "{what}: a {mode:?} polygon's inside");
        }
    }
    finish(r);
}

/// The hidden-line view of CAD programs (GL 2.1 §3.5.5): the fill, then the same polygons in
/// `GL_LINE` mode with `GL_POLYGON_OFFSET_LINE` pulling the outlines in front; without the
/// offset the coplanar lines lose to the fill in places.
#[test]
fn polygon_offset_line_pulls_outlines_in_front_of_their_own_fill() {
    let mut r = renderer();
    let fill = tilted(RED);
    let lines = tilted(GREEN);
    let mut shown = Vec::new();
    for offset in [
        None,
        Some(PolygonOffset {
            line: true,
            fill: false,
            ..PolygonOffset::fill(-1.0, -1.0)
        }),
    ] {
        let modes = PolygonModes::both(vk::PolygonMode::LINE);
        let mut calls = vec![GlCall::PolygonMode(modes)];
        if let Some(o) = offset {
            calls.push(GlCall::PolygonOffset(o));
        }
        let cases = [
            Case::plain(&fill),
            Case {
                mesh: &lines,
                set: Box::new(move |d| d.with_polygon_mode(modes).with_offset(offset)),
                calls,
            },
        ];
        let (ours, theirs) = draw_both(&mut r, true, &cases);
        let what = format!("outline offset {:?}", offset.map(|o| (o.factor, o.units)));
        check_like_mesa(&what, &ours, &theirs, 6);
        let green = ours.pixels().filter(|p| p.0 == rgba(GREEN)).count();
        shown.push(green);
    }
    assert!(
        shown[1] > shown[0] + 20 && shown[1] > 150,
        "pulled forward, more of the outline shows: {shown:?} pixels without and with the offset"
    );
    finish(r);
}

/// GL 2.1 §4.1.10: with `GL_COLOR_LOGIC_OP` the fragment's color and the image's combine
/// bitwise, blending off: XOR of red over green gives yellow, INVERT ignores the source.
#[test]
fn logic_ops_combine_the_fragment_and_the_image_bitwise() {
    let mut r = renderer();
    let below = square(1.5, 0.0, Vec4::new(0.0, 1.0, 0.0, 1.0), false);
    let above = square(0.5, 0.0, Vec4::new(1.0, 0.6, 0.0, 1.0), false);
    for (op, want) in [
        (vk::LogicOp::XOR, [255, 255 ^ 153, 0, 0]),
        (vk::LogicOp::INVERT, [255, 0, 255, 0]),
        (vk::LogicOp::AND, [0, 153, 0, 255]),
        (vk::LogicOp::COPY_INVERTED, [0, 102, 255, 0]),
    ] {
        let cases = [
            Case::plain(&below),
            Case {
                mesh: &above,
                set: Box::new(move |d| d.with_logic_op(Some(op))),
                calls: vec![GlCall::LogicOp(op)],
            },
        ];
        let (ours, theirs) = draw_both(&mut r, false, &cases);
        let what = format!("logic op {op:?}");
        check_like_mesa(&what, &ours, &theirs, 0);
        assert_eq!(ours.get_pixel(SIZE / 2, SIZE / 2).0, want, "{what}");
    }
    finish(r);
}

/// GL 2.1 §3.4.2: a stippled line draws fragment c where bit (c / factor) mod 16 of the
/// pattern is set, counting from each segment's start in `GL_LINES`.
#[test]
fn line_stipple_draws_the_patterns_bits_along_each_line() {
    let mut r = renderer();
    let mut lines = MeshData::new(
        [(-0.9, -0.5), (0.9, -0.5), (-0.9, 0.2), (0.8, 0.9)]
            .iter()
            .map(|&(x, y)| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, GREEN))
            .collect(),
        vec![0, 1, 2, 3],
    );
    lines.topology = Topology::LineList;
    for stipple in [
        LineStipple {
            factor: 1,
            pattern: 0x0F0F,
        },
        LineStipple {
            factor: 3,
            pattern: 0xAAAA,
        },
    ] {
        let cases = [Case {
            mesh: &lines,
            set: Box::new(move |d| d.with_line_stipple(Some(stipple))),
            calls: vec![GlCall::LineStipple(stipple)],
        }];
        let (ours, theirs) = draw_both(&mut r, false, &cases);
        let what = format!("stipple {} {:#06x}", stipple.factor, stipple.pattern);
        check_like_mesa(&what, &ours, &theirs, 2);
        let drawn = ours.pixels().filter(|p| p.0 == rgba(GREEN)).count();
        assert!(drawn > 20, "{what}: {drawn} pixels drawn");
    }
    finish(r);
}

/// A raster state ffvk cannot draw is refused naming what is missing: stencil ops outside
/// Vulkan's eight, logic ops outside its sixteen, a stipple factor outside [1, 256].
#[test]
fn raster_modes_out_of_range_are_refused_naming_the_field() {
    use ffvk::RasterState;
    let bad_op = StencilFace::default().with_ops(
        vk::StencilOp::KEEP,
        vk::StencilOp::from_raw(9),
        vk::StencilOp::KEEP,
    );
    let e = RasterState::default()
        .with_stencil(Some(Stencil::both(bad_op)))
        .validate()
        .unwrap_err()
        .to_string();
    assert!(e.contains("stencil.front") && e.contains("depth_fail 9"), "{e}");
    let e = RasterState::default()
        .with_logic_op(Some(vk::LogicOp::from_raw(16)))
        .validate()
        .unwrap_err()
        .to_string();
    assert!(e.contains("logic_op") && e.contains("16"), "{e}");
    let e = RasterState::default()
        .with_line_stipple(Some(LineStipple {
            factor: 0,
            pattern: 1,
        }))
        .validate()
        .unwrap_err()
        .to_string();
    assert!(e.contains("line_stipple") && e.contains("factor 0"), "{e}");
    let e = RasterState::default()
        .with_polygon_mode(PolygonModes::both(vk::PolygonMode::from_raw(3)))
        .validate()
        .unwrap_err()
        .to_string();
    assert!(e.contains("polygon_mode.front"), "{e}");
}

/// Culling, the stencil state and the polygon offset's values are dynamic state: draws that
/// differ only there share one pipeline (and still draw as GL does: the other tests); a
/// polygon mode keys a pipeline of its own.
#[test]
fn draws_that_differ_only_in_dynamic_state_share_one_pipeline() {
    use ffvk::gl::state::Face;
    let mut r = renderer();
    let mesh = r.upload(&square(0.5, 0.0, RED, false)).unwrap();
    let state = GlState::new().lighting;
    let before = r.pipeline_counts().0;
    let base = Draw::new(&mesh, view(), projection(), state);
    let mut frame = Frame::new(SIZE, SIZE);
    let equal = StencilFace::default().with_func(vk::CompareOp::EQUAL, 0, 0xF);
    frame.draws = vec![
        base.with_stencil(Some(Stencil::both(StencilFace::default()))),
        base.with_cull_face(Some(Face::Back)),
        base.with_stencil(Some(Stencil::both(equal))),
        base.with_polygon_offset(1.0, 2.0),
        base.with_cull_face(Some(Face::Front))
            .with_polygon_offset(-1.0, 0.0),
    ];
    let image = r.render(&frame).unwrap().into_rgba_image();
    assert_eq!(
        r.pipeline_counts().0 - before,
        1,
        "five draws differing in dynamic state only"
    );
    assert_eq!(image.get_pixel(SIZE / 2, SIZE / 2).0, rgba(RED));
    frame
        .draws
        .push(base.with_polygon_mode(PolygonModes::both(vk::PolygonMode::LINE)));
    r.render(&frame).unwrap();
    assert_eq!(r.pipeline_counts().0 - before, 2, "a polygon mode keys its own");
    finish(r);
}

/// GL 2.1 §2.11.1: glDepthRange maps window z into [near, far], clamped to [0, 1]: a far
/// square drawn into (0, 0.4) covers a near one drawn into (0.5, 1) under `GL_LESS`, as a
/// first-person weapon drawn with glDepthRange(0, 0.1) stays before the world; near may
/// exceed far, turning the depth order around. As Mesa's GL draws it.
#[test]
fn the_depth_range_maps_each_draws_depth_into_its_own_interval() {
    let mut r = renderer();
    let near = square(0.5, 0.5, RED, false);
    let far = square(0.3, -0.5, GREEN, false);
    for (red_range, green_range, want) in [
        ((0.0, 1.0), (0.0, 1.0), RED),
        ((0.5, 1.0), (0.0, 0.4), GREEN),
        ((0.5, 1.5), (-1.0, 0.4), GREEN),
        ((1.0, 0.0), (1.0, 0.0), GREEN),
    ] {
        let cases = [
            Case {
                mesh: &near,
                set: Box::new(move |d| d.with_depth_range(red_range.0, red_range.1)),
                calls: vec![GlCall::DepthRange(red_range.0 as f64, red_range.1 as f64)],
            },
            Case {
                mesh: &far,
                set: Box::new(move |d| d.with_depth_range(green_range.0, green_range.1)),
                calls: vec![GlCall::DepthRange(green_range.0 as f64, green_range.1 as f64)],
            },
        ];
        let (ours, theirs) = draw_both(&mut r, true, &cases);
        let what = format!("depth ranges {red_range:?} and {green_range:?}");
        check_like_mesa(&what, &ours, &theirs, 0);
        assert_eq!(ours.get_pixel(SIZE / 2, SIZE / 2).0, rgba(want), "{what}");
    }
    let mesh = r.upload(&near).unwrap();
    let mut frame = Frame::new(SIZE, SIZE);
    frame.draws.push(
        Draw::new(&mesh, view(), projection(), GlState::new().lighting).with_depth_range(f32::NAN, 1.0),
    );
    let e = r.render(&frame).unwrap_err().to_string();
    assert!(e.contains("depth_range") && e.contains("NaN"), "{e}");
    finish(r);
}

/// GL 2.1 §3.5.2: a filled polygon's fragment at window (x, y) is drawn where bit x mod 32 of
/// row y mod 32 of the pattern is set, rows counted from the framebuffer's bottom (a height
/// that is no multiple of 32 moves them), each mask byte's most significant bit leftmost;
/// polygons drawn as lines are not stippled. As Mesa's GL draws it, pixel for pixel.
#[test]
fn polygon_stipple_draws_the_patterns_bits_in_window_coordinates() {
    let mut r = renderer();
    // 4 × 4 checks, and an asymmetric mark (bottom-left 3 × 2 pixels) that shows a flip.
    let mut mask = [0u8; 128];
    for y in 0..32 {
        for x in 0..32 {
            let on = ((x / 4) + (y / 4)) % 2 == 0 || (x < 3 && y < 2);
            if on {
                mask[y * 4 + x / 8] |= 0x80 >> (x % 8);
            }
        }
    }
    let state = GlState::new().lighting;
    let quad = square(1.5, 0.0, GREEN, false);
    let mesh = r.upload(&quad).unwrap();
    for (height, modes) in [
        (64, PolygonModes::FILL),
        (70, PolygonModes::FILL),
        (64, PolygonModes::both(vk::PolygonMode::LINE)),
    ] {
        let mut frame = Frame::new(SIZE, height);
        frame.clear_color = Vec4::from_array(CLEAR);
        frame.depth_test = false;
        let projection = Mat4::perspective_rh_gl(50f32.to_radians(), SIZE as f32 / height as f32, 1.0, 10.0);
        frame.draws.push(
            Draw::new(&mesh, view(), projection, state)
                .with_polygon_stipple(Some(mask))
                .with_polygon_mode(modes),
        );
        let ours = r.render(&frame).unwrap().into_rgba_image();
        let mut gl = GlDraw::new(&quad, view(), projection, state);
        gl.calls = vec![GlCall::PolygonStipple(mask), GlCall::PolygonMode(modes)];
        let theirs = mesa_image((SIZE, height), CLEAR, false, vec![gl]);
        let what = format!("stipple at height {height}, {:?}", modes.front);
        check_like_mesa(&what, &ours, &theirs, 0);
        let green = ours.pixels().filter(|p| p.0 == rgba(GREEN)).count();
        if modes == PolygonModes::FILL {
            // The quad covers the frame: about half its pixels are drawn.
            let all = (SIZE * height) as usize;
            assert!(
                (all * 2 / 5..all * 3 / 5).contains(&green),
                "{what}: {green} of {all}"
            );
            // The mark: window (0, 0) .. (2, 1) is GL's bottom-left, Vulkan's last rows.
            let bottom = height - 1;
            assert_eq!(ours.get_pixel(2, bottom - 1).0, rgba(GREEN), "{what}: the mark");
        }
    }
    finish(r);
}
