// Scratch probe (not committed): the spheres / quads frame, timed and perf-able.
use ffvk::gl::state::{Cap, Face, GlState, LightParam, LightingMode, MaterialParam};
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, Renderer, RendererOptions};
use ffvk_cli::gl_reference::{time_frames, GlDraw, GlScene};
use glam::{Mat4, Vec3, Vec4};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let what = args.get(1).map(String::as_str).unwrap_or("spheres");
    let mode = match args.get(2).map(String::as_str).unwrap_or("vertex") {
        "fragment" => LightingMode::Fragment,
        "flat" => LightingMode::Flat,
        _ => LightingMode::Vertex,
    };
    let engine = args.get(3).map(String::as_str).unwrap_or("ffvk");
    let frames: u32 = args.get(4).and_then(|s| s.parse().ok()).unwrap_or(30);
    let lit = std::env::var("UNLIT").is_err();
    let (mesh, draws, fit) = match what {
        "spheres" => (MeshData::uv_sphere(12, 11), 1024u32, 0.45f32),
        "dense" => (MeshData::uv_sphere(1024, 512), 1u32, 1.0f32),
        _ => {
            let v = |x, y| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, Vec4::ONE);
            (
                MeshData::new(
                    vec![v(-0.5, -0.5), v(0.5, -0.5), v(0.5, 0.5), v(-0.5, 0.5)],
                    vec![0, 1, 2, 0, 2, 3],
                ),
                10000,
                0.9,
            )
        }
    };
    let mut gl = GlState::new();
    gl.lighting_mode(mode);
    for cap in [Cap::Light(0), Cap::Light(1)] {
        gl.enable(cap).unwrap();
    }
    if lit {
        gl.enable(Cap::Lighting).unwrap();
    }
    gl.light(0, LightParam::Position(Vec4::new(0.3, 0.4, 1.0, 0.0)))
        .unwrap();
    gl.light(0, LightParam::Diffuse(Vec4::splat(0.6))).unwrap();
    if what == "dense" {
        gl.disable(Cap::Light(1)).unwrap();
        for i in 0..4 {
            gl.enable(Cap::Light(i)).unwrap();
            gl.light(i, LightParam::Position(Vec4::new(0.3 * i as f32, 0.4, 1.0, 0.0)))
                .unwrap();
            gl.light(i, LightParam::Diffuse(Vec4::splat(0.2))).unwrap();
        }
    } else if std::env::var("DIRONLY").is_err() {
        gl.light(1, LightParam::Position(Vec4::new(1.0, 1.0, 1.0, 1.0)))
            .unwrap();
    }
    gl.light(1, LightParam::Diffuse(Vec4::splat(0.5))).unwrap();
    gl.light(1, LightParam::Specular(Vec4::splat(0.5))).unwrap();
    gl.light(1, LightParam::LinearAttenuation(0.2)).unwrap();
    gl.material(Face::FrontAndBack, MaterialParam::Specular(Vec4::splat(0.5)))
        .unwrap();
    let side = (f64::from(draws).sqrt().ceil() as u32).max(1);
    let cell = 2.0 / side as f32;
    let mut objects = Vec::new();
    for i in 0..draws {
        let h = i as f32 / draws as f32;
        gl.material(
            Face::FrontAndBack,
            MaterialParam::Diffuse(Vec4::new(h, 1.0 - h, 0.5 + 0.5 * h, 1.0)),
        )
        .unwrap();
        gl.material(Face::FrontAndBack, MaterialParam::Shininess(4.0 + 60.0 * h))
            .unwrap();
        let (x, y) = ((i % side) as f32, (i / side) as f32);
        let at = Vec3::new(-1.0 + cell * (x + 0.5), -1.0 + cell * (y + 0.5), -2.0);
        objects.push((
            Mat4::from_translation(at) * Mat4::from_scale(Vec3::splat(cell * fit)),
            gl.lighting,
        ));
    }
    let projection = Mat4::perspective_rh_gl(53f32.to_radians(), 1.0, 0.5, 10.0);
    let mut times = Vec::new();
    if engine == "gl" {
        let scene = GlScene {
            width: 512,
            height: 512,
            clear_color: [0.1, 0.1, 0.1, 1.0],
            depth_test: true,
            draws: objects
                .iter()
                .map(|(m, s)| GlDraw::new(&mesh, *m, projection, *s))
                .collect(),
        };
        let t = time_frames(&scene, 3, frames).unwrap();
        times = t.frame_ns.iter().map(|n| n / 1e6).collect();
    } else {
        let mut renderer = Renderer::new(&RendererOptions::default()).unwrap();
        let m = renderer.upload(&mesh).unwrap();
        let mut frame = Frame::new(512, 512);
        frame.draws = objects
            .iter()
            .map(|(mv, s)| Draw::new(&m, *mv, projection, *s))
            .collect();
        for i in 0..frames + 3 {
            let start = Instant::now();
            renderer.measure(&frame).unwrap();
            if i >= 3 {
                times.push(start.elapsed().as_secs_f64() * 1e3);
            }
        }
    }
    times.sort_by(f64::total_cmp);
    println!(
        "{what} {mode:?} {engine} lit={lit}: median {:.2} ms (min {:.2})",
        times[times.len() / 2],
        times[0]
    );
}
