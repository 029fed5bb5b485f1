//! What the sheet's panels share: cameras, a subdivided square, sampling, drawing a frame.

use glam::{Mat4, Vec2, Vec3, Vec4};

use ffvk::gl::texture::{MagFilter, MinFilter, Sampling, Wrap};
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, Renderer};

use crate::Result;

pub(super) const BACKGROUND: Vec4 = Vec4::new(0.08, 0.08, 0.1, 1.0);

pub(super) fn projection() -> Mat4 {
    Mat4::perspective_rh_gl(40f32.to_radians(), 1.0, 0.5, 10.0)
}

/// The flat panels' camera: straight at the plane z = 0 from 2.6 in front.
pub(super) fn flat_view() -> Mat4 {
    Mat4::look_at_rh(Vec3::new(0.0, 0.0, 2.6), Vec3::ZERO, Vec3::Y)
}

/// A number in [0, 1) for an integer: the procedural textures' variation.
pub(super) fn hash(i: i32) -> f32 {
    let mut x = (i as u32).wrapping_mul(0x9E37_79B9) ^ 0x85EB_CA6B;
    x ^= x >> 15;
    x = x.wrapping_mul(0x2C1B_3C6D);
    x ^= x >> 12;
    (x & 0xFFFF) as f32 / 65536.0
}

/// An opaque RGBA8 texel of a color, clamped to [0, 1].
pub(super) fn texel(c: Vec3) -> [u8; 4] {
    let [r, g, b] = c
        .clamp(Vec3::ZERO, Vec3::ONE)
        .to_array()
        .map(|v| (v * 255.0).round() as u8);
    [r, g, b, 255]
}

pub(super) fn trilinear(wrap: Wrap) -> Sampling {
    Sampling::default()
        .with_min_filter(MinFilter::LinearMipmapLinear)
        .with_mag_filter(MagFilter::Linear)
        .with_wrap_s(wrap)
        .with_wrap_t(wrap)
}

/// A square of half-size `h` in the plane z = 0 facing +z, `n` × `n` quads, (s, t) from 0 at
/// the lower left to 1 at the upper right; each vertex's color from its position.
pub(super) fn plane(h: f32, n: u32, color: impl Fn(Vec3) -> Vec4) -> MeshData {
    let mut mesh = MeshData::default();
    for j in 0..=n {
        for i in 0..=n {
            let st = Vec2::new(i as f32, j as f32) / n as f32;
            let p = Vec3::new((2.0 * st.x - 1.0) * h, (2.0 * st.y - 1.0) * h, 0.0);
            mesh.vertices
                .push(Vertex::new(p, Vec3::Z, color(p)).with_texcoord(st));
        }
    }
    let at = |i: u32, j: u32| j * (n + 1) + i;
    for j in 0..n {
        for i in 0..n {
            mesh.indices.extend([
                at(i, j),
                at(i + 1, j),
                at(i + 1, j + 1),
                at(i, j),
                at(i + 1, j + 1),
                at(i, j + 1),
            ]);
        }
    }
    mesh
}

pub(super) fn render(renderer: &mut Renderer, size: u32, draws: Vec<Draw>) -> Result<image::RgbaImage> {
    let mut frame = Frame::new(size, size);
    frame.clear_color = BACKGROUND;
    frame.draws = draws;
    Ok(renderer.render(&frame)?.into())
}
