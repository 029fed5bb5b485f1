//! The demo's sheet of the raster state a GL draw carries (issue 50): a CAD hidden-line view
//! (the fill pushed back by `glPolygonOffset`, then `GL_LINE`), a wireframe over the lit fill
//! by `GL_POLYGON_OFFSET_LINE`, a teapot cut open with its front faces in `GL_LINE` and its
//! back faces filled, `GL_POINT` mode, a stencil-masked mirror, the teapot's shape stenciled
//! out of a wall, two teapots combined by `GL_XOR`, stippled lines, a teapot drawn into
//! `glDepthRange(0, 0.3)` in front of a wall it stands behind, `GL_FUNC_REVERSE_SUBTRACT`,
//! and particles (the points of `assets/scenes/particles.toml`).

use std::path::Path;

use ash::vk;
use glam::{DVec4, Mat4, Vec3, Vec4};

use ffvk::gl::presets;
use ffvk::gl::state::{Cap, Face, GlState, LightParam, MaterialParam};
use ffvk::mesh::{teapot, MeshData, Vertex};
use ffvk::scene::{render_scene, Scene};
use ffvk::{
    Blend, Draw, Frame, LineStipple, Mesh, PolygonModes, PolygonOffset, Renderer, Stencil, StencilFace,
    Topology,
};

use super::Panel;
use crate::Result;

const PARTICLES: &str = include_str!("../../assets/scenes/particles.toml");
const PAPER: Vec4 = Vec4::new(0.96, 0.95, 0.9, 1.0);
const INK: Vec4 = Vec4::new(0.12, 0.14, 0.22, 1.0);

fn view() -> Mat4 {
    Mat4::look_at_rh(Vec3::new(0.0, 1.0, 3.2), Vec3::new(0.0, 0.0, 0.0), Vec3::Y)
}

fn projection() -> Mat4 {
    Mat4::perspective_rh_gl(40f32.to_radians(), 1.0, 0.5, 10.0)
}

/// A material preset lit by one white directional light from the upper right front, both
/// faces lit (two-sided) so that a cut-open teapot shows its inside.
fn lit(material: &str) -> Result<GlState> {
    let mut gl = GlState::new();
    let m = presets::preset(material).expect("the preset table has the demo's materials");
    gl.lighting.front = m;
    gl.lighting.back = m;
    gl.enable(Cap::Lighting)?;
    gl.enable(Cap::Light(0))?;
    gl.load_modelview(view())?;
    gl.light(0, LightParam::Position(Vec4::new(1.0, 1.5, 1.2, 0.0)))?;
    gl.material(Face::FrontAndBack, MaterialParam::Shininess(m.shininess))?;
    gl.light_model(ffvk::gl::state::LightModelParam::TwoSide(true))?;
    Ok(gl)
}

/// A square of half-size `h` in the plane y = `y` (normal +y, counter-clockwise from above),
/// or, `wall`, in the plane z = `y` facing +z.
fn square(h: f32, y: f32, wall: bool, color: Vec4) -> MeshData {
    let corners = [(-h, -h), (h, -h), (h, h), (-h, h)];
    let vertices = corners
        .iter()
        .map(|&(a, b)| match wall {
            false => Vertex::new(Vec3::new(a, y, -b), Vec3::Y, color),
            true => Vertex::new(Vec3::new(a, b, y), Vec3::Z, color),
        })
        .collect();
    MeshData::new(vertices, vec![0, 1, 2, 0, 2, 3])
}

/// Lines from the centre out, 24 of them, as a `GL_LINES` mesh.
fn star(color: Vec4) -> MeshData {
    let mut mesh = MeshData::default();
    for i in 0..24 {
        let a = i as f32 / 24.0 * std::f32::consts::TAU;
        mesh.vertices.push(Vertex::new(Vec3::ZERO, Vec3::Z, color));
        mesh.vertices.push(Vertex::new(
            Vec3::new(a.cos(), a.sin(), 0.0) * 1.1,
            Vec3::Z,
            color,
        ));
    }
    mesh.indices = (0..48).collect();
    mesh.topology = Topology::LineList;
    mesh
}

/// `mesh` with every vertex's color `color` (its color array: GL's glColorPointer).
fn colored(mut mesh: MeshData, color: Vec4) -> MeshData {
    for v in &mut mesh.vertices {
        v.color = color.to_array();
    }
    mesh
}

/// The meshes the panels share, uploaded once.
struct Meshes {
    teapot: Mesh,
    paper_teapot: Mesh,
    ink_teapot: Mesh,
    pale_teapot: Mesh,
    floor: Mesh,
    wall: Mesh,
    star: Mesh,
}

fn frame<'a>(size: u32, clear: Vec4) -> Frame<'a> {
    let mut f = Frame::new(size, size);
    f.clear_color = clear;
    f
}

fn stencil(func: vk::CompareOp, reference: u32, pass: vk::StencilOp) -> Option<Stencil> {
    let face = StencilFace::default().with_func(func, reference, 0xFF).with_ops(
        vk::StencilOp::KEEP,
        vk::StencilOp::KEEP,
        pass,
    );
    Some(Stencil::both(face))
}

/// The raster sheet's panels, `size` pixels square.
pub fn raster_panels(renderer: &mut Renderer, size: u32) -> Result<Vec<Panel>> {
    let teapot = teapot::teapot(8)?;
    let m = Meshes {
        teapot: renderer.upload(&teapot)?,
        paper_teapot: renderer.upload(&colored(teapot.clone(), PAPER))?,
        ink_teapot: renderer.upload(&colored(teapot.clone(), INK))?,
        pale_teapot: renderer.upload(&colored(teapot, Vec4::new(0.9, 1.0, 0.9, 1.0)))?,
        floor: renderer.upload(&square(1.6, -0.5, false, Vec4::new(0.55, 0.6, 0.7, 0.4)))?,
        wall: renderer.upload(&square(1.2, -0.9, true, Vec4::new(0.8, 0.45, 0.3, 1.0)))?,
        star: renderer.upload(&star(INK))?,
    };
    let mut panels = Vec::new();
    let mut add = |name: &str, label: &str, image: image::RgbaImage| {
        panels.push(Panel {
            name: format!("raster_{name}"),
            label: label.to_owned(),
            image,
        });
    };
    let (v, p) = (view(), projection());
    let line = PolygonModes::both(vk::PolygonMode::LINE);
    // Lighting off: the meshes' color arrays.
    let plain = GlState::new().lighting;
    let dark = Vec4::new(0.1, 0.1, 0.12, 1.0);

    // A CAD hidden-line view: the fill in the paper's color, pushed back, then the edges.
    let mut f = frame(size, PAPER);
    f.draws
        .push(Draw::new(&m.paper_teapot, v, p, plain).with_polygon_offset(1.0, 1.0));
    f.draws
        .push(Draw::new(&m.ink_teapot, v, p, plain).with_polygon_mode(line));
    add("hidden_line", "hidden line", renderer.render(&f)?.into());

    // The wireframe over the lit fill, pulled forward by GL_POLYGON_OFFSET_LINE.
    let mut f = frame(size, dark);
    f.draws.push(Draw::new(&m.teapot, v, p, lit("jade")?.lighting));
    let forward = PolygonOffset {
        line: true,
        fill: false,
        ..PolygonOffset::fill(-1.0, -1.0)
    };
    f.draws.push(
        Draw::new(&m.pale_teapot, v, p, plain)
            .with_polygon_mode(line)
            .with_offset(Some(forward)),
    );
    add(
        "wire_over_fill",
        "GL_POLYGON_OFFSET_LINE",
        renderer.render(&f)?.into(),
    );

    // Cut open by a clip plane: front faces as lines, back faces (the inside) filled.
    let mut cut = lit("ruby")?;
    cut.load_modelview(v)?;
    cut.clip_plane(0, DVec4::new(0.0, -1.0, -0.4, 0.15))?;
    cut.enable(Cap::ClipPlane(0))?;
    let mut f = frame(size, dark);
    let front_line = PolygonModes {
        front: vk::PolygonMode::LINE,
        back: vk::PolygonMode::FILL,
    };
    f.draws
        .push(Draw::new(&m.teapot, v, p, cut.lighting).with_polygon_mode(front_line));
    add(
        "front_line_back_fill",
        "front LINE, back FILL",
        renderer.render(&f)?.into(),
    );

    // GL_POINT: the vertices alone, 2 pixels wide.
    let mut f = frame(size, Vec4::new(0.05, 0.05, 0.08, 1.0));
    f.draws.push(
        Draw::new(&m.teapot, v, p, lit("gold")?.lighting)
            .with_polygon_mode(PolygonModes::both(vk::PolygonMode::POINT))
            .with_point_size(2.0),
    );
    add("points", "GL_POINT, size 2", renderer.render(&f)?.into());

    // The mirror: the floor marks the stencil (color and depth writes off), the teapot
    // mirrored in y = -0.5 draws where it marked, the floor blends over its reflection, the
    // teapot stands on it.
    let gold = lit("gold")?.lighting;
    let mirror =
        Mat4::from_translation(Vec3::new(0.0, -1.0, 0.0)) * Mat4::from_scale(Vec3::new(1.0, -1.0, 1.0));
    let mut reflected = lit("gold")?;
    reflected.load_modelview(v * mirror)?;
    reflected.light(0, LightParam::Position(Vec4::new(1.0, -1.5, 1.2, 0.0)))?;
    let mut f = frame(size, Vec4::new(0.08, 0.08, 0.1, 1.0));
    f.depth_test = true;
    f.draws.push(
        Draw::new(&m.floor, v, p, plain)
            .with_stencil(stencil(vk::CompareOp::ALWAYS, 1, vk::StencilOp::REPLACE))
            .with_color_mask([false; 4])
            .with_depth_write(false),
    );
    // The mirrored modelview turns the winding around: GL programs flip glFrontFace, or as
    // here cull nothing. The mark wrote no depth (glDepthMask(GL_FALSE)).
    f.draws.push(
        Draw::new(&m.teapot, v * mirror, p, reflected.lighting).with_stencil(stencil(
            vk::CompareOp::EQUAL,
            1,
            vk::StencilOp::KEEP,
        )),
    );
    f.draws
        .push(Draw::new(&m.floor, v, p, plain).with_blend(Some(Blend::ALPHA)));
    f.draws.push(Draw::new(&m.teapot, v, p, gold));
    add("mirror", "stencil-masked mirror", renderer.render(&f)?.into());

    // The teapot's silhouette stenciled out of a wall: the teapot marks, the wall draws
    // where it did not.
    let mut f = frame(size, Vec4::new(0.2, 0.3, 0.45, 1.0));
    f.draws.push(
        Draw::new(&m.teapot, v, p, gold)
            .with_stencil(stencil(vk::CompareOp::ALWAYS, 1, vk::StencilOp::REPLACE))
            .with_color_mask([false; 4]),
    );
    f.draws.push(Draw::new(&m.wall, v, p, plain).with_stencil(stencil(
        vk::CompareOp::NOT_EQUAL,
        1,
        vk::StencilOp::KEEP,
    )));
    add(
        "stencil_cutout",
        "stencil GL_NOTEQUAL",
        renderer.render(&f)?.into(),
    );

    // Two teapots combined bitwise.
    let mut f = frame(size, Vec4::new(0.0, 0.0, 0.0, 1.0));
    let left = Mat4::from_translation(Vec3::new(-0.35, 0.0, 0.0));
    let right = Mat4::from_translation(Vec3::new(0.35, 0.1, 0.0));
    let xor = Some(vk::LogicOp::XOR);
    // Alpha masked: XOR of two opaque alphas would be 0, a hole in the sheet.
    let rgb = [true, true, true, false];
    f.draws.push(
        Draw::new(&m.teapot, v * left, p, lit("emerald")?.lighting)
            .with_logic_op(xor)
            .with_color_mask(rgb),
    );
    f.draws.push(
        Draw::new(&m.teapot, v * right, p, lit("ruby")?.lighting)
            .with_logic_op(xor)
            .with_color_mask(rgb),
    );
    add("logic_xor", "glLogicOp(GL_XOR)", renderer.render(&f)?.into());

    // Stippled lines: three patterns on three stars.
    let mut f = frame(size, PAPER);
    for (x, pattern, factor) in [(-0.9, 0x00FF, 1), (0.0, 0x0F0F, 2), (0.9, 0x5555, 3)] {
        let at = Mat4::from_translation(Vec3::new(x, 0.6 - x.abs() * 0.9, -3.0))
            * Mat4::from_scale(Vec3::splat(0.42));
        f.draws
            .push(Draw::new(&m.star, at, p, plain).with_line_stipple(Some(LineStipple { factor, pattern })));
    }
    add("stipple", "glLineStipple", renderer.render(&f)?.into());

    // The teapot stands behind the wall, but its depth range lies in front of the wall's.
    let mut f = frame(size, dark);
    let behind = Mat4::from_translation(Vec3::new(0.3, 0.0, -1.6));
    f.draws
        .push(Draw::new(&m.wall, v, p, plain).with_depth_range(0.3, 1.0));
    f.draws
        .push(Draw::new(&m.teapot, v * behind, p, gold).with_depth_range(0.0, 0.3));
    add("depth_range", "glDepthRange(0, 0.3)", renderer.render(&f)?.into());

    // GL_FUNC_REVERSE_SUBTRACT: the image minus the teapot, its front faces only (each
    // covered layer would subtract again).
    let mut f = frame(size, Vec4::new(0.9, 0.9, 0.9, 1.0));
    // The alpha kept (glBlendFuncSeparate's ZERO, ONE): the image stays opaque.
    let subtract = Blend::separate(
        (
            vk::BlendFactor::ONE,
            vk::BlendFactor::ONE,
            vk::BlendOp::REVERSE_SUBTRACT,
        ),
        (vk::BlendFactor::ZERO, vk::BlendFactor::ONE, vk::BlendOp::ADD),
    );
    f.draws.push(
        Draw::new(&m.teapot, v, p, lit("jade")?.lighting)
            .with_blend(Some(subtract))
            .with_cull_face(Some(Face::Back)),
    );
    add(
        "reverse_subtract",
        "REVERSE_SUBTRACT",
        renderer.render(&f)?.into(),
    );

    // Particles: the points of the stage sheet's scene.
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut scene = Scene::parse(PARTICLES, &assets.join("particles.toml"))?;
    scene.set_size(size, size);
    add(
        "particles",
        "point sprites",
        render_scene(renderer, &scene, None)?,
    );
    Ok(panels)
}
