//! DOT3 bump mapping: a square of 4 × 4 tiles, each with a dome in its middle, set in grooves.
//! Unit 0 holds the bumps as a normal map (RGB = n · 0.5 + 0.5, n in the square's tangent
//! space: x along s, y along t, z out of it) and computes `GL_DOT3_RGB` of its texel and the
//! light's direction, encoded the same way, from the constant color (one direction) or from the
//! primary color (per vertex, interpolated); unit 1 modulates the tiles' colors by it.

use glam::{Vec2, Vec3, Vec4};

use ffvk::gl::state::{Cap, GlState, TexEnvParam};
use ffvk::gl::texture::{CombineFunc, CombineSource, TexEnvMode, TextureImage, Wrap};
use ffvk::{Draw, Mesh, Renderer, Texture};

use super::common::{flat_view, plane, projection, render, texel, trilinear};
use crate::Result;

const SIZE: u32 = 128;
const TILES: f32 = 4.0;

/// Where the light's direction comes from.
pub(super) enum LightIn {
    /// `GL_CONSTANT`: a direction, the same everywhere (a directional light).
    Constant(Vec3),
    /// `GL_PRIMARY_COLOR`: the direction to a point light at this position, at each vertex.
    PrimaryColor(Vec3),
}

/// The height of the surface at (s, t), in units of the square's side: a dome of radius 0.34
/// tile and height 0.035 in each tile, and grooves 0.008 deep along the tiles' edges.
fn height(st: Vec2) -> f32 {
    let cell = (st * TILES).fract() - 0.5;
    let r = cell.length() / 0.34;
    let dome = if r < 1.0 {
        0.035 * (1.0 - r * r).powi(2)
    } else {
        0.0
    };
    let edge = 0.5 - cell.abs().max_element();
    let groove = if edge < 0.06 {
        -0.008 * (1.0 - (edge / 0.06).powi(2))
    } else {
        0.0
    };
    dome + groove
}

/// The normal map: each texel's normal from the height's central differences.
fn normal_map() -> TextureImage {
    let delta = 0.5 / SIZE as f32;
    let mut rgba = Vec::with_capacity((SIZE * SIZE * 4) as usize);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let st = (Vec2::new(i as f32, j as f32) + 0.5) / SIZE as f32;
            let ds = (height(st + Vec2::X * delta) - height(st - Vec2::X * delta)) / (2.0 * delta);
            let dt = (height(st + Vec2::Y * delta) - height(st - Vec2::Y * delta)) / (2.0 * delta);
            let n = Vec3::new(-ds, -dt, 1.0).normalize();
            rgba.extend(texel(n * 0.5 + 0.5));
        }
    }
    TextureImage::new(SIZE, SIZE, rgba)
        .expect("a square RGBA8 image is a valid texture")
        .with_mipmaps()
}

/// The tiles' colors: terracotta and ivory in turn, the grooves grey.
fn base() -> TextureImage {
    let mut rgba = Vec::with_capacity((SIZE * SIZE * 4) as usize);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let st = (Vec2::new(i as f32, j as f32) + 0.5) / SIZE as f32;
            let cell = (st * TILES).floor();
            let c = if height(st) < 0.0 {
                Vec3::splat(0.55)
            } else if (cell.x + cell.y) as i32 % 2 == 0 {
                Vec3::new(0.85, 0.45, 0.3)
            } else {
                Vec3::new(0.92, 0.88, 0.78)
            };
            rgba.extend(texel(c));
        }
    }
    TextureImage::new(SIZE, SIZE, rgba)
        .expect("a square RGBA8 image is a valid texture")
        .with_mipmaps()
}

/// The bump panels' square and textures, uploaded once.
pub(super) struct Bumps {
    square: Mesh,
    normals: Texture,
    base: Texture,
}

const HALF: f32 = 0.9;

impl Bumps {
    pub(super) fn upload(renderer: &mut Renderer) -> Result<Bumps> {
        let sampling = trilinear(Wrap::ClampToEdge);
        Ok(Bumps {
            square: renderer.upload(&plane(HALF, 1, |_| Vec4::ONE))?,
            normals: renderer.upload_texture(&normal_map(), &sampling)?,
            base: renderer.upload_texture(&base(), &sampling)?,
        })
    }

    /// The square face on, lit from `light`, `size` pixels square. The square lies in z = 0
    /// with s along x and t along y, so that its object space is the normal map's tangent
    /// space and directions need no turning.
    pub(super) fn draw(
        &self,
        renderer: &mut Renderer,
        size: u32,
        light: LightIn,
    ) -> Result<image::RgbaImage> {
        // Unlit: the primary color is the vertex color.
        let mut gl = GlState::new();
        gl.enable(Cap::Texture2D)?;
        gl.tex_env(TexEnvParam::Mode(TexEnvMode::Combine))?;
        gl.tex_env(TexEnvParam::CombineRgb(CombineFunc::Dot3Rgb))?;
        gl.tex_env(TexEnvParam::SourceRgb(0, CombineSource::Texture))?;
        let per_vertex;
        let mesh = match light {
            LightIn::Constant(direction) => {
                gl.tex_env(TexEnvParam::SourceRgb(1, CombineSource::Constant))?;
                gl.tex_env(TexEnvParam::Color((direction * 0.5 + 0.5).extend(1.0)))?;
                &self.square
            }
            LightIn::PrimaryColor(lamp) => {
                gl.tex_env(TexEnvParam::SourceRgb(1, CombineSource::PrimaryColor))?;
                // Fine enough that the interpolated directions stay close to the true ones.
                per_vertex = renderer.upload(&plane(HALF, 24, |p| {
                    ((lamp - p).normalize() * 0.5 + 0.5).extend(1.0)
                }))?;
                &per_vertex
            }
        };
        gl.active_texture(1)?;
        gl.enable(Cap::Texture2D)?;
        gl.tex_env(TexEnvParam::Mode(TexEnvMode::Modulate))?;
        let draw = Draw::new(mesh, flat_view(), projection(), gl.lighting)
            .with_textures([Some(&self.normals), Some(&self.base), None, None])
            .with_mesh_texcoords(0b10);
        render(renderer, size, vec![draw])
    }
}
