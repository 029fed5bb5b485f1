//! GL's edge flags (GL 2.1 §2.6.2, §3.5.4) through the Renderer and Mesa's GL: a quad, a quad
//! strip's quads and a polygon drawn with `GL_LINE` show their sides and no inner edge of ffvk's
//! triangles, and with `GL_POINT` only the vertices that start a boundary edge; a vertex's
//! flag (`glEdgeFlagPointer`) hides the edge that starts at it. Mesa's GL draws GL's own modes
//! (`GL_QUADS`, `GL_QUAD_STRIP`, `GL_POLYGON`, `GL_TRIANGLES` with an edge flag array); ffvk
//! draws `Topology::EdgeFlaggedTriangles` from `gl_primitives`' `_edge_flagged` lists.

use ash::vk;
use ffvk::draw::gl_primitives;
use ffvk::gl::state::{Face, GlState, LightingMode};
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, PolygonModes, Renderer, Topology};
use ffvk_cli::gl_reference::{GlCall, GlDraw, GlMode};
use glam::{Mat4, Vec3, Vec4};
use image::RgbaImage;

use crate::support::*;

const SIZE: u32 = 64;
const CLEAR: [f32; 4] = [0.0, 0.0, 0.0, 1.0];

/// A color per vertex, all different and all bright.
fn color(k: usize) -> Vec4 {
    let a = k as f32 * 2.1;
    Vec4::new(
        0.6 + 0.4 * a.cos(),
        0.6 + 0.4 * (a + 2.0).cos(),
        0.6 + 0.4 * (a + 4.0).cos(),
        1.0,
    )
}

/// Vertices at `points` (in [-1, 1]², the window under an identity projection), facing +z.
fn vertices(points: &[(f32, f32)]) -> Vec<Vertex> {
    points
        .iter()
        .enumerate()
        .map(|(k, &(x, y))| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, color(k)))
        .collect()
}

/// Two quads, the left one counter-clockwise (front), the right one clockwise (back).
fn two_quads() -> Vec<(f32, f32)> {
    vec![
        (-0.83, -0.61),
        (-0.12, -0.72),
        (-0.21, 0.67),
        (-0.77, 0.52),
        (0.13, -0.58),
        (0.22, 0.63),
        (0.85, 0.71),
        (0.79, -0.66),
    ]
}

/// A ladder of four quads, above and below alternately (counter-clockwise quads).
fn ladder() -> Vec<(f32, f32)> {
    (0..10)
        .map(|k| {
            let x = -0.87 + 0.41 * (k / 2) as f32 + 0.03 * (k % 2) as f32;
            (x, if k % 2 == 1 { -0.53 } else { 0.47 + 0.02 * k as f32 })
        })
        .collect()
}

/// A convex heptagon, counter-clockwise.
fn heptagon() -> Vec<(f32, f32)> {
    (0..7)
        .map(|k| {
            let a = 0.3 + k as f32 * std::f32::consts::TAU / 7.0;
            (0.81 * a.cos(), 0.77 * a.sin())
        })
        .collect()
}

/// One GL mode's draw: ffvk's edge-flagged list and Mesa's own mode over the same vertices.
struct Shape {
    name: &'static str,
    mode: GlMode,
    points: Vec<(f32, f32)>,
    /// Per-vertex edge flags (GL's edge flag array); `None`: all `GL_TRUE`.
    flags: Option<Vec<u8>>,
}

impl Shape {
    fn ffvk_mesh(&self) -> MeshData {
        let order: Vec<u32> = (0..self.points.len() as u32).collect();
        let flag = |v: u32| self.flags.as_ref().is_none_or(|f| f[v as usize] != 0);
        let indices = match self.mode {
            GlMode::Quads => gl_primitives::quads_edge_flagged(&order, flag),
            GlMode::QuadStrip => gl_primitives::quad_strip_edge_flagged(&order),
            GlMode::Polygon => gl_primitives::polygon_edge_flagged(&order, flag),
            _ => gl_primitives::triangles_edge_flagged(&order, flag),
        };
        MeshData::new(vertices(&self.points), indices).with_topology(Topology::EdgeFlaggedTriangles)
    }

    fn gl_mesh(&self) -> MeshData {
        MeshData::new(vertices(&self.points), (0..self.points.len() as u32).collect())
    }
}

/// How a shape is drawn: its polygon modes, shading, whether lit two-sided (the facing then
/// picks the material), culling and glFrontFace.
#[derive(Debug, Clone, Copy)]
struct Setup {
    modes: PolygonModes,
    shading: LightingMode,
    lit: bool,
    cull: Option<Face>,
    front: vk::FrontFace,
    /// glPointSize (what polygons drawn as points take).
    point_size: f32,
}

/// The shape through ffvk and Mesa's GL as `setup` says.
fn draw_both(r: &mut Renderer, shape: &Shape, setup: Setup) -> (RgbaImage, RgbaImage) {
    let Setup {
        modes,
        shading,
        lit,
        cull,
        front,
        point_size,
    } = setup;
    let mut state = if lit {
        two_sided(shading).lighting
    } else {
        GlState::new().lighting
    };
    state.mode = shading;
    let ours_mesh = shape.ffvk_mesh();
    let gl_mesh = shape.gl_mesh();
    let mesh = r.upload(&ours_mesh).unwrap();
    let mut frame = Frame::new(SIZE, SIZE);
    frame.clear_color = Vec4::from_array(CLEAR);
    frame.depth_test = false;
    let mut draw = Draw::new(&mesh, Mat4::IDENTITY, Mat4::IDENTITY, state).with_polygon_mode(modes);
    let mut calls = vec![GlCall::PolygonMode(modes), GlCall::FrontFace(front)];
    draw = draw.with_front_face(front);
    if let Some(face) = cull {
        draw = draw.with_cull_face(Some(face));
        calls.push(GlCall::CullFace(face));
    }
    draw.point_size = point_size;
    frame.draws.push(draw);
    let ours = r.render(&frame).unwrap().into_rgba_image();
    let mut gl = GlDraw::new(&gl_mesh, Mat4::IDENTITY, Mat4::IDENTITY, state);
    gl.point_size = point_size;
    gl.mode = shape.mode;
    gl.calls = calls;
    gl.edge_flags = shape.flags.as_deref();
    let theirs = mesa_image((SIZE, SIZE), CLEAR, false, vec![gl]);
    (ours, theirs)
}

/// Pixels lit (not black) in one image and not the other, and pixels lit in both whose colors
/// differ by more than 2/255.
fn compare(a: &RgbaImage, b: &RgbaImage) -> (usize, usize) {
    let lit = |p: &image::Rgba<u8>| p.0[..3] != [0, 0, 0];
    let (mut coverage, mut color) = (0, 0);
    for (p, q) in a.pixels().zip(b.pixels()) {
        if lit(p) != lit(q) {
            coverage += 1;
        } else if p.0.iter().zip(q.0).any(|(x, y)| x.abs_diff(y) > 2) {
            color += 1;
        }
    }
    (coverage, color)
}

fn lit_pixels(a: &RgbaImage) -> usize {
    a.pixels().filter(|p| p.0[..3] != [0, 0, 0]).count()
}

fn shapes() -> Vec<Shape> {
    vec![
        Shape {
            name: "quads",
            mode: GlMode::Quads,
            points: two_quads(),
            flags: None,
        },
        Shape {
            name: "quad_strip",
            mode: GlMode::QuadStrip,
            points: ladder(),
            flags: None,
        },
        Shape {
            name: "polygon",
            mode: GlMode::Polygon,
            points: heptagon(),
            flags: None,
        },
        Shape {
            name: "quads_flagged",
            mode: GlMode::Quads,
            points: two_quads(),
            flags: Some(vec![1, 0, 1, 1, 0, 1, 1, 0]),
        },
        Shape {
            name: "polygon_flagged",
            mode: GlMode::Polygon,
            points: heptagon(),
            flags: Some(vec![0, 1, 1, 0, 1, 0, 1]),
        },
        Shape {
            name: "triangles_flagged",
            mode: GlMode::Triangles,
            points: heptagon()[..6].to_vec(),
            flags: Some(vec![1, 0, 1, 0, 1, 1]),
        },
    ]
}

#[test]
fn quads_quad_strips_and_polygons_drawn_as_lines_or_points_show_only_their_boundary_edges_as_mesa_gl_does() {
    let mut r = renderer();
    let (fill, line, point) = (
        vk::PolygonMode::FILL,
        vk::PolygonMode::LINE,
        vk::PolygonMode::POINT,
    );
    let mut report = Vec::new();
    for shape in shapes() {
        let (ccw, cw) = (vk::FrontFace::COUNTER_CLOCKWISE, vk::FrontFace::CLOCKWISE);
        let (vertex, flat, fragment) = (LightingMode::Vertex, LightingMode::Flat, LightingMode::Fragment);
        for (front, back, shading, lit, cull, winding, point_size) in [
            (fill, fill, vertex, false, None, ccw, 1.0),
            (line, line, vertex, false, None, ccw, 1.0),
            (point, point, vertex, false, None, ccw, 1.0),
            (point, point, fragment, true, None, ccw, 3.0),
            (line, fill, flat, false, None, ccw, 1.0),
            (line, line, fragment, true, Some(Face::Back), ccw, 1.0),
            (line, line, fragment, true, None, ccw, 1.0),
            (line, point, vertex, true, None, cw, 4.0),
            (point, line, flat, true, Some(Face::Front), cw, 1.0),
        ] {
            let modes = PolygonModes { front, back };
            let setup = Setup {
                modes,
                shading,
                lit,
                cull,
                front: winding,
                point_size,
            };
            let (ours, theirs) = draw_both(&mut r, &shape, setup);
            let what = format!(
                "{} {front:?}-{back:?} {shading:?} lit {lit} cull {cull:?} {winding:?} size {point_size}",
                shape.name
            );
            let file = what.replace([' ', ':', '(', ')', ','], "_");
            let a = save_for_inspection(&ours, &format!("edge_flags_{file}_ffvk"));
            let b = save_for_inspection(&theirs, &format!("edge_flags_{file}_gl"));
            let (coverage, color) = compare(&ours, &theirs);
            let drawn = lit_pixels(&theirs);
            report.push(format!(
                "{what}: {coverage} pixels covered by one only, {color} colored apart, of {drawn}"
            ));
            assert!(
                drawn >= 3,
                "{what}: Mesa's GL drew {drawn} pixels: the scene is wrong"
            );
            assert!(
                coverage <= 2 && color <= 2,
                "{what}: {coverage} pixels lit by one of ffvk and Mesa's GL only, {color} lit by both in colors more than 2/255 apart: {} vs {}",
                a.display(),
                b.display()
            );
        }
    }
    eprintln!("{}", report.join("\n"));
    finish(r);
}

/// Scene files: a mesh of quads, quad strips or polygons drawn with `polygon_mode = "line"` (or
/// "point") keeps its edge flags; filled, it stays a triangle list. `front_face` is glFrontFace,
/// "ccw" or "cw", and anything else is refused naming the field.
#[test]
fn a_scene_mesh_of_quads_drawn_as_lines_keeps_its_edge_flags_and_takes_its_front_face() {
    let dir = output_dir().join("edge_flags_scene");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let load = |extra: &str| {
        let path = dir.join("s.toml");
        std::fs::write(
            &path,
            format!(
                "[image]\nsize = [64, 64]\n[[lights]]\nindex = 0\nposition = [0.0, 0.0, 1.0, 0.0]\n\
                 [[meshes]]\nbuiltin = \"sphere\"\nlevel = 12\ntranslate = [0.0, 0.0, -3.0]\n{extra}"
            ),
        )
        .unwrap();
        ffvk::scene::Scene::load(&path)
    };
    let mut r = renderer();
    let outlined = load("primitive = \"quads\"\npolygon_mode = \"line\"").unwrap();
    let filled = load("primitive = \"quads\"").unwrap();
    let (o, f) = (&outlined.meshes[0].data, &filled.meshes[0].data);
    assert_eq!(
        (o.topology, f.topology),
        (Topology::EdgeFlaggedTriangles, Topology::TriangleList)
    );
    assert_eq!(o.indices.len(), 2 * f.indices.len(), "six indices a triangle");
    let image = ffvk::scene::render_scene(&mut r, &outlined, None).unwrap();
    // The scene's outlines are the API's: the same vertices through quads_edge_flagged.
    let mesh = r.upload(o).unwrap();
    let mut frame = Frame::new(64, 64);
    frame.clear_color = Vec4::new(0.0, 0.0, 0.0, 1.0);
    let draw = Draw::new(
        &mesh,
        outlined.modelview(&outlined.meshes[0]),
        outlined.projection,
        outlined.draw_state(&outlined.meshes[0]),
    )
    .with_polygon_mode(PolygonModes::both(vk::PolygonMode::LINE));
    frame.draws.push(draw);
    let direct = r.render(&frame).unwrap().into_rgba_image();
    assert!(lit_pixels(&direct) > 100, "{} lit", lit_pixels(&direct));
    assert_eq!(compare(&image, &direct), (0, 0));

    let cw = load("front_face = \"cw\"\ncull_face = \"back\"").unwrap();
    let ccw = load("front_face = \"ccw\"\ncull_face = \"back\"").unwrap();
    assert_eq!(cw.meshes[0].raster.front_face, vk::FrontFace::CLOCKWISE);
    let (a, b) = (
        ffvk::scene::render_scene(&mut r, &cw, None).unwrap(),
        ffvk::scene::render_scene(&mut r, &ccw, None).unwrap(),
    );

    assert_ne!(a, b, "glFrontFace(GL_CW) culls the other faces");
    let e = load("front_face = \"clockwise\"").unwrap_err().to_string();
    assert!(
        e.contains("meshes[0].front_face") && e.contains("\"clockwise\"") && e.contains("ccw"),
        "{e}"
    );
    finish(r);
}
