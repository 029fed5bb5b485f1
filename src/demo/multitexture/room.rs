//! The light-mapped room corner: a floor and two walls with a crate in the corner, unlit, each
//! surface's base texture (tiles, bricks, planks) tiled by unit 0's texture matrix, and on unit
//! 1 a light map baked here for that surface (two area lights, the crate's soft shadows),
//! stretched once over it from the mesh's own coordinates, combined by `GL_COMBINE`'s
//! `MODULATE` with `GL_RGB_SCALE` 2: a light map of 0.5 leaves the base as it is, brighter
//! texels light it past its own color.

use glam::{Mat4, Vec2, Vec3, Vec4};

use ffvk::gl::state::{Cap, GlState, TexEnvParam};
use ffvk::gl::texture::{
    CombineFunc, CombineSource, MagFilter, MinFilter, Sampling, TexEnvMode, TextureImage, Wrap,
};
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Renderer};

use super::common::{hash, projection, render, texel, trilinear};
use crate::Result;

/// The crate: an axis-aligned box standing on the floor in the far left quarter.
const CRATE_MIN: Vec3 = Vec3::new(-0.62, 0.0, -0.62);
const CRATE_MAX: Vec3 = Vec3::new(-0.12, 0.5, -0.12);

/// The lights the maps are baked from: a warm lamp at the back right, low, and a dimmer cool
/// one at the left front, each a disc of radius 0.1 (soft shadows), and the ambient light.
const LIGHTS: [(Vec3, Vec3); 2] = [
    (Vec3::new(0.45, 1.05, -0.45), Vec3::new(0.95, 0.75, 0.48)),
    (Vec3::new(-0.5, 1.1, 0.9), Vec3::new(0.35, 0.45, 0.75)),
];
const AMBIENT: Vec3 = Vec3::new(0.08, 0.08, 0.1);

/// The base textures.
#[derive(Clone, Copy)]
enum Base {
    Tiles,
    Bricks,
    Planks,
}

/// A rectangle: corner `origin`, edges `u` (s) and `v` (t), facing u × v; its base texture
/// repeated `tiles` times along each edge.
struct Surface {
    origin: Vec3,
    u: Vec3,
    v: Vec3,
    base: Base,
    tiles: Vec2,
}

impl Surface {
    fn normal(&self) -> Vec3 {
        self.u.cross(self.v).normalize()
    }

    fn at(&self, st: Vec2) -> Vec3 {
        self.origin + st.x * self.u + st.y * self.v
    }

    fn mesh(&self) -> MeshData {
        let corner = |s: f32, t: f32| {
            Vertex::new(self.at(Vec2::new(s, t)), self.normal(), Vec4::ONE).with_texcoord(Vec2::new(s, t))
        };
        MeshData::new(
            vec![
                corner(0.0, 0.0),
                corner(1.0, 0.0),
                corner(1.0, 1.0),
                corner(0.0, 1.0),
            ],
            vec![0, 1, 2, 0, 2, 3],
        )
    }

    /// The surface's light map, `size`² texels, each the irradiance at its centre halved (the
    /// combiner doubles it): the ambient light plus each light's N·L over 0.3 + d², averaged
    /// over 16 points of its disc that the crate does not hide.
    fn lightmap(&self, size: u32) -> TextureImage {
        let n = self.normal();
        let mut rgba = Vec::with_capacity((size * size * 4) as usize);
        for j in 0..size {
            for i in 0..size {
                let st = (Vec2::new(i as f32, j as f32) + 0.5) / size as f32;
                let p = self.at(st) + n * 1e-3;
                let mut e = AMBIENT;
                for (centre, color) in LIGHTS {
                    for k in 0..16 {
                        // A golden-angle spiral over the disc, in the plane y = const.
                        let r = 0.1 * ((k as f32 + 0.5) / 16.0).sqrt();
                        let a = k as f32 * 2.399_963;
                        let q = centre + Vec3::new(r * a.cos(), 0.0, r * a.sin());
                        let to = q - p;
                        let cos = n.dot(to.normalize()).max(0.0);
                        if cos > 0.0 && !hidden(p, q) {
                            e += color * cos / (0.3 + to.length_squared()) / 16.0;
                        }
                    }
                }
                rgba.extend(texel(e * 0.5));
            }
        }
        TextureImage::new(size, size, rgba).expect("a square RGBA8 image is a valid texture")
    }
}

/// Whether the crate stands between `p` and `q` (the slab test on the segment).
fn hidden(p: Vec3, q: Vec3) -> bool {
    let d = q - p;
    let (mut near, mut far) = (0.0f32, 1.0f32);
    for a in 0..3 {
        if d[a].abs() < 1e-7 {
            if p[a] < CRATE_MIN[a] || p[a] > CRATE_MAX[a] {
                return false;
            }
            continue;
        }
        let (t0, t1) = ((CRATE_MIN[a] - p[a]) / d[a], (CRATE_MAX[a] - p[a]) / d[a]);
        near = near.max(t0.min(t1));
        far = far.min(t0.max(t1));
        if near > far {
            return false;
        }
    }
    true
}

/// The room: the floor (x, z in [−1, 1]), the back wall (z = −1) and the left wall (x = −1),
/// 1.4 high, and the crate's five visible faces.
fn surfaces() -> Vec<Surface> {
    let (lo, hi) = (CRATE_MIN, CRATE_MAX);
    let (w, h, d) = (hi.x - lo.x, hi.y - lo.y, hi.z - lo.z);
    let s = |origin: Vec3, u: Vec3, v: Vec3, base: Base, tiles: Vec2| Surface {
        origin,
        u,
        v,
        base,
        tiles,
    };
    let one = Vec2::ONE;
    vec![
        s(
            Vec3::new(-1.0, 0.0, 1.0),
            Vec3::X * 2.0,
            Vec3::Z * -2.0,
            Base::Tiles,
            Vec2::splat(4.0),
        ),
        s(
            Vec3::new(-1.0, 0.0, -1.0),
            Vec3::X * 2.0,
            Vec3::Y * 1.4,
            Base::Bricks,
            Vec2::new(4.0, 3.0),
        ),
        s(
            Vec3::new(-1.0, 0.0, 1.0),
            Vec3::Z * -2.0,
            Vec3::Y * 1.4,
            Base::Bricks,
            Vec2::new(4.0, 3.0),
        ),
        s(
            Vec3::new(lo.x, hi.y, hi.z),
            Vec3::X * w,
            Vec3::Z * -d,
            Base::Planks,
            one,
        ),
        s(
            Vec3::new(lo.x, lo.y, hi.z),
            Vec3::X * w,
            Vec3::Y * h,
            Base::Planks,
            one,
        ),
        s(
            Vec3::new(hi.x, lo.y, lo.z),
            Vec3::X * -w,
            Vec3::Y * h,
            Base::Planks,
            one,
        ),
        s(
            Vec3::new(hi.x, lo.y, hi.z),
            Vec3::Z * -d,
            Vec3::Y * h,
            Base::Planks,
            one,
        ),
        s(
            Vec3::new(lo.x, lo.y, lo.z),
            Vec3::Z * d,
            Vec3::Y * h,
            Base::Planks,
            one,
        ),
    ]
}

/// A 64² base texture.
fn base_texture(base: Base) -> TextureImage {
    const SIZE: u32 = 64;
    let mut rgba = Vec::with_capacity((SIZE * SIZE * 4) as usize);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let c = match base {
                // 2 × 2 tiles, cream and terracotta, in grey grout.
                Base::Tiles => {
                    let (x, y) = (i % 32, j % 32);
                    if x < 2 || y < 2 {
                        Vec3::splat(0.45)
                    } else if (i / 32 + j / 32) % 2 == 0 {
                        Vec3::new(0.86, 0.8, 0.68)
                    } else {
                        Vec3::new(0.7, 0.36, 0.24)
                    }
                }
                // Four courses of bricks 32 × 16, every other one shifted half a brick.
                Base::Bricks => {
                    let course = j / 16;
                    let x = i + (course % 2) * 16;
                    let brick = (course * 4 + (x / 32) % 2) as i32;
                    if j % 16 < 2 || x % 32 < 2 {
                        Vec3::new(0.72, 0.7, 0.66)
                    } else {
                        Vec3::new(0.66, 0.3, 0.2) * (0.8 + 0.3 * hash(brick))
                    }
                }
                // Four planks with dark seams, in a darker frame.
                Base::Planks => {
                    let frame = !(5..SIZE - 5).contains(&i) || !(5..SIZE - 5).contains(&j);
                    let grain = 0.9 + 0.1 * ((i as f32 * 0.7 + (j / 16) as f32 * 3.0).sin());
                    if frame {
                        Vec3::new(0.42, 0.27, 0.14)
                    } else if j % 16 < 1 {
                        Vec3::new(0.25, 0.16, 0.08)
                    } else {
                        Vec3::new(0.72, 0.52, 0.3) * grain
                    }
                }
            };
            rgba.extend(texel(c));
        }
    }
    TextureImage::new(SIZE, SIZE, rgba)
        .expect("a square RGBA8 image is a valid texture")
        .with_mipmaps()
}

/// The corner seen from the front right, `size` pixels square.
pub(super) fn lightmapped_corner(renderer: &mut Renderer, size: u32) -> Result<image::RgbaImage> {
    let view = Mat4::look_at_rh(Vec3::new(0.95, 1.15, 2.2), Vec3::new(-0.3, 0.35, -0.45), Vec3::Y);
    let bases = [Base::Tiles, Base::Bricks, Base::Planks]
        .map(|b| renderer.upload_texture(&base_texture(b), &trilinear(Wrap::Repeat)));
    let [tiles, bricks, planks] = bases;
    let (tiles, bricks, planks) = (tiles?, bricks?, planks?);
    let clamp = Sampling::default()
        .with_min_filter(MinFilter::Linear)
        .with_mag_filter(MagFilter::Linear)
        .with_wrap_s(Wrap::ClampToEdge)
        .with_wrap_t(Wrap::ClampToEdge);
    let surfaces = surfaces();
    let mut uploaded = Vec::new();
    for s in &surfaces {
        let map = renderer.upload_texture(&s.lightmap(48), &clamp)?;
        uploaded.push((renderer.upload(&s.mesh())?, map));
    }
    let mut draws = Vec::new();
    for (s, (mesh, map)) in surfaces.iter().zip(&uploaded) {
        // Unlit: the primary color is the vertices' white.
        let mut gl = GlState::new();
        gl.enable(Cap::Texture2D)?;
        gl.tex_env(TexEnvParam::Mode(TexEnvMode::Modulate))?;
        gl.load_texture_matrix(Mat4::from_scale(s.tiles.extend(1.0)))?;
        gl.active_texture(1)?;
        gl.enable(Cap::Texture2D)?;
        gl.tex_env(TexEnvParam::Mode(TexEnvMode::Combine))?;
        gl.tex_env(TexEnvParam::CombineRgb(CombineFunc::Modulate))?;
        gl.tex_env(TexEnvParam::SourceRgb(0, CombineSource::Texture))?;
        gl.tex_env(TexEnvParam::SourceRgb(1, CombineSource::Previous))?;
        gl.tex_env(TexEnvParam::RgbScale(2.0))?;
        let base = match s.base {
            Base::Tiles => &tiles,
            Base::Bricks => &bricks,
            Base::Planks => &planks,
        };
        draws.push(
            Draw::new(mesh, view, projection(), gl.lighting)
                .with_textures([Some(base), Some(map), None, None])
                .with_mesh_texcoords(0b10),
        );
    }
    render(renderer, size, draws)
}
