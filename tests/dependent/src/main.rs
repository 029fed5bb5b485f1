//! Uses ffvk's core the way a dependent crate does: GL state through GL's entry points, one
//! lit quad rendered offscreen on lavapipe, and its center pixel checked against the CPU
//! reference of the same equation. Exits non-zero, with the reason, on any difference.

use std::process::ExitCode;

use ffvk::gl::state::{Cap, GlState, LightParam, MaterialParam, Face};
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, Renderer, RendererOptions};
use glam::{DVec3, DVec4, Mat4, Vec3, Vec4};

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("ffvk-dependent: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<(), String> {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).map_err(|e| e.to_string())?;
    gl.enable(Cap::Light(0)).map_err(|e| e.to_string())?;
    // A directional light from over the viewer's right shoulder and a reddish material.
    gl.light(0, LightParam::Position(Vec4::new(1.0, 1.0, 2.0, 0.0)))
        .map_err(|e| e.to_string())?;
    gl.material(Face::FrontAndBack, MaterialParam::Diffuse(Vec4::new(0.9, 0.3, 0.2, 1.0)))
        .map_err(|e| e.to_string())?;

    let normal = Vec3::Z;
    let v = |x, y| Vertex::new(Vec3::new(x, y, 0.0), normal, Vec4::ONE);
    let quad = MeshData {
        vertices: vec![v(-1.0, -1.0), v(1.0, -1.0), v(1.0, 1.0), v(-1.0, 1.0)],
        indices: vec![0, 1, 2, 0, 2, 3],
    };

    let mut renderer = Renderer::new(&RendererOptions::default()).map_err(|e| e.to_string())?;
    let mesh = renderer.upload(&quad).map_err(|e| e.to_string())?;
    let mut frame = Frame::new(8, 8);
    frame.draws.push(Draw::new(&mesh, Mat4::IDENTITY, Mat4::IDENTITY, gl.lighting));
    let pixels = renderer.render(&frame).map_err(|e| e.to_string())?;
    let got = pixels.pixel(4, 4).ok_or("the image has no pixel (4, 4)")?;

    let lit = ffvk::reference::light(
        &gl.lighting,
        DVec4::new(0.0, 0.0, 0.0, 1.0),
        DVec3::Z,
        &gl.lighting.front,
    );
    let want = lit.color().to_array().map(|c| (c * 255.0).round() as i32);
    let off = got.iter().zip(want).map(|(&g, w)| (g as i32 - w).abs()).max().unwrap_or(0);
    println!(
        "ffvk as a dependency on {}: pixel (4, 4) = {got:?}, the CPU reference says {want:?}",
        renderer.device_info().name
    );
    if off > 1 {
        return Err(format!("pixel (4, 4) is {got:?}: expected {want:?} within 1/255"));
    }
    Ok(())
}
