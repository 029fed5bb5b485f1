//! The surroundings the chrome teapots reflect, made procedurally, as a sphere map and as a
//! cube map.

use std::f32::consts::TAU;

use glam::{Mat3, Mat4, Vec2, Vec3};

use ffvk::gl::texture::{CubeImage, TextureImage};

use super::common::{hash, texel};

const HORIZON: Vec3 = Vec3::new(0.86, 0.89, 0.94);

/// The sun's direction: where the teapots' GL light comes from, so that its highlight lies on
/// the sun's reflection.
pub(super) const SUN: Vec3 = Vec3::new(1.0, 1.5, 1.2);

/// The surroundings in the world direction `d` (unit length): a sky from a pale horizon to a
/// deep blue zenith with the sun at [`SUN`], a skyline of 28 blocks of four colors
/// around the horizon, and below it a floor of large checker tiles fading into the haze.
fn environment(d: Vec3) -> Vec3 {
    let elevation = d.y.clamp(-1.0, 1.0).asin();
    if d.y >= 0.0 {
        let azimuth = d.x.atan2(d.z);
        let block = (azimuth / TAU * 28.0).floor() as i32;
        let height = 0.04 + 0.16 * hash(block);
        if elevation < height {
            const PALETTE: [Vec3; 4] = [
                Vec3::new(0.62, 0.26, 0.2),
                Vec3::new(0.78, 0.68, 0.46),
                Vec3::new(0.3, 0.36, 0.5),
                Vec3::new(0.22, 0.48, 0.36),
            ];
            let color = PALETTE[(hash(block + 101) * 4.0) as usize % 4];
            // Darker towards the ground: the blocks stand on the floor.
            return color * (0.7 + 0.3 * elevation / height);
        }
        let zenith = Vec3::new(0.12, 0.3, 0.78);
        let sky = HORIZON.lerp(zenith, d.y.sqrt());
        let sun = SUN.normalize();
        let c = d.dot(sun).max(0.0);
        let disc = if c > 0.997 { 1.0 } else { 0.0 };
        let glow = Vec3::new(1.0, 0.8, 0.5) * c.powi(48) * 0.7;
        return (sky + glow + Vec3::new(1.0, 0.95, 0.8) * disc).min(Vec3::ONE);
    }
    // The floor one unit below: tiles of one unit, hazier far away.
    let p = Vec2::new(d.x, d.z) / -d.y;
    let tile = ((p.x.floor() + p.y.floor()) as i64).rem_euclid(2) == 0;
    let floor = if tile {
        Vec3::new(0.74, 0.7, 0.62)
    } else {
        Vec3::new(0.3, 0.26, 0.22)
    };
    let haze = (-p.length() / 9.0).exp();
    HORIZON.lerp(floor, haze)
}

/// The eye-to-world rotation of `view`: the inverse (transpose) of its rotation.
pub(super) fn eye_to_world(view: Mat4) -> Mat3 {
    Mat3::from_mat4(view).transpose()
}

/// A `size`² image whose texel (i, j) averages `color` at 4 × 4 points spread over it, in
/// coordinates from −1 at the image's edge (0) to 1 (`size`): the maps' horizons and far tiles
/// without aliasing.
fn supersampled(size: u32, color: impl Fn(f32, f32) -> Vec3) -> TextureImage {
    const N: u32 = 4;
    let mut rgba = Vec::with_capacity((size * size * 4) as usize);
    for j in 0..size {
        for i in 0..size {
            let mut sum = Vec3::ZERO;
            for k in 0..N * N {
                let at = |texel: u32, sub: u32| {
                    2.0 * (texel as f32 + (sub as f32 + 0.5) / N as f32) / size as f32 - 1.0
                };
                sum += color(at(i, k % N), at(j, k / N));
            }
            rgba.extend(texel(sum / (N * N) as f32));
        }
    }
    TextureImage::new(size, size, rgba).expect("a square RGBA8 image is a valid texture")
}

/// [`environment`] as a sphere map for a viewer whose view is `view`: texel (s, t) is what a
/// mirror ball shows at (x, y) = (2s − 1, 2t − 1), the reflection
/// r = (2 n_z x, 2 n_z y, 2 n_z² − 1) of the eye's −z about the ball's normal n = (x, y, n_z),
/// which GL's `GL_SPHERE_MAP` turns back into (s, t); r is in eye space, turned into the world
/// for the lookup. Outside the disc, the direction straight behind (the ball's rim), so that
/// filtering there blends in nothing else.
pub(super) fn sphere_map(size: u32, view: Mat4) -> TextureImage {
    let to_world = eye_to_world(view);
    supersampled(size, |x, y| {
        let r = if x * x + y * y < 1.0 {
            let nz = (1.0 - x * x - y * y).sqrt();
            Vec3::new(2.0 * nz * x, 2.0 * nz * y, 2.0 * nz * nz - 1.0)
        } else {
            Vec3::NEG_Z
        };
        environment((to_world * r).normalize())
    })
    .with_mipmaps()
}

/// [`environment`] as a cube map in world directions: texel (s, t) of each face looks along
/// the direction table 3.19 maps to it (s_c = 2s − 1, t_c = 2t − 1 on the face's axes).
pub(super) fn cube_map(size: u32) -> CubeImage {
    let face = |k: usize| {
        supersampled(size, |sc, tc| {
            let d = match k {
                0 => Vec3::new(1.0, -tc, -sc),
                1 => Vec3::new(-1.0, -tc, sc),
                2 => Vec3::new(sc, 1.0, tc),
                3 => Vec3::new(sc, -1.0, -tc),
                4 => Vec3::new(sc, -tc, 1.0),
                _ => Vec3::new(-sc, -tc, -1.0),
            };
            environment(d.normalize())
        })
    };
    CubeImage::new(std::array::from_fn(face))
        .expect("six square faces of one size are a cube map")
        .with_mipmaps()
}
