//! docs/embedding-rust.md's "Using the library" program, as a dependent crate runs it: GL state through GL's
//! entry points, a lit sphere rendered offscreen on lavapipe, and its nearest point checked
//! against the CPU reference of the same equation. ash and glam come from ffvk's re-exports.
//! Exits non-zero, with the reason, on any difference.

use std::process::ExitCode;

use ffvk::gl::state::{Cap, Face, GlState, LightParam, LightingMode, MaterialParam};
use ffvk::glam::{DVec3, DVec4, Mat4, Vec3, Vec4};
use ffvk::mesh::MeshData;
use ffvk::{Draw, Frame, Renderer, RendererOptions};

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("ffvk-dependent: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let mut renderer = Renderer::new(&RendererOptions::default())?;
    let sphere = renderer.upload(&MeshData::uv_sphere(32, 16))?;

    let view = Mat4::look_at_rh(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, Vec3::Y);
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting)?;
    gl.enable(Cap::Light(0))?;
    gl.load_modelview(view)?;
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 0.0)))?;
    gl.material(Face::FrontAndBack, MaterialParam::Diffuse(Vec4::new(0.9, 0.3, 0.2, 1.0)))?;
    gl.lighting_mode(LightingMode::Fragment);

    let mut frame = Frame::new(256, 256);
    let projection = Mat4::perspective_rh_gl(0.8, 1.0, 0.1, 10.0);
    frame.draws.push(Draw::new(&sphere, view, projection, gl.lighting));
    let pixels = renderer.render(&frame)?;
    let center = pixels.pixel(128, 128).ok_or("no pixel (128, 128)")?;

    let lit = ffvk::reference::light(
        &gl.lighting,
        DVec4::new(0.0, 0.0, -2.0, 1.0),
        DVec3::Z,
        &gl.lighting.front,
    );
    let expected = lit.color().to_array().map(|c| (c * 255.0).round() as u8);
    println!("ffvk as a dependency: pixel (128, 128) = {center:?}, the CPU reference says {expected:?}");
    if !center.iter().zip(expected).all(|(&a, b)| a.abs_diff(b) <= 1) {
        return Err(format!("pixel (128, 128) is {center:?}: expected {expected:?} within 1/255").into());
    }
    Ok(())
}
