//! The Utah teapot, tessellated from Martin Newell's public-domain bicubic Bézier patches (the
//! classic set of 32 patches over 306 control points: rim, body, handle, spout, lid knob, lid
//! and bottom), as a [`MeshData`] (`crate::scene::gltf::write` writes any mesh as glTF).
//!
//! # Coordinates
//!
//! Newell's data is z-up, spans x ∈ [-3, 3.525] (handle to spout tip), y ∈ [-2, 2] and
//! z ∈ [0, 3.15] (bottom to lid knob). [`teapot`] maps a data point (x, y, z) to
//!
//! ```text
//! x' = (x - 0.2625) / 3.2625
//! y' = (z - 1.575)  / 3.2625
//! z' = -y           / 3.2625
//! ```
//!
//! a rotation of -90° about x (z up becomes y up; a proper rotation, so windings and
//! outward normals are kept) after centering the control points' bounding box on the origin,
//! then a uniform scale that maps the longest side (x, 6.525) to 2. By the convex-hull
//! property of Bézier patches the surface lies within x' ∈ [-1, 1], y' ∈ [-0.483, 0.483],
//! z' ∈ [-0.613, 0.613]; the spout points to +x', the handle to -x', the lid to +y'.

use crate::error::MeshError;
use crate::mesh::{MeshData, Vertex};
use glam::{DVec3, Vec4};

/// Patches in Newell's set.
pub const PATCH_COUNT: usize = 32;

/// The largest tessellation level [`teapot`] accepts (32 × 65² = 135 200 vertices).
pub const MAX_LEVEL: u32 = 64;

/// The center of the control points' bounding box, in the data's z-up coordinates.
const CENTER: DVec3 = DVec3::new(0.2625, 0.0, 1.575);

/// Half the longest side (x) of the control points' bounding box.
const HALF_EXTENT: f64 = 3.2625;

/// Newell's 32 patches: 16 one-based control-point numbers each, row by row (row = u, column = v).
#[rustfmt::skip]
const PATCHES: [[u16; 16]; PATCH_COUNT] = [
    // rim
    [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16],
    [4, 17, 18, 19, 8, 20, 21, 22, 12, 23, 24, 25, 16, 26, 27, 28],
    [19, 29, 30, 31, 22, 32, 33, 34, 25, 35, 36, 37, 28, 38, 39, 40],
    [31, 41, 42, 1, 34, 43, 44, 5, 37, 45, 46, 9, 40, 47, 48, 13],
    // upper body
    [13, 14, 15, 16, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60],
    [16, 26, 27, 28, 52, 61, 62, 63, 56, 64, 65, 66, 60, 67, 68, 69],
    [28, 38, 39, 40, 63, 70, 71, 72, 66, 73, 74, 75, 69, 76, 77, 78],
    [40, 47, 48, 13, 72, 79, 80, 49, 75, 81, 82, 53, 78, 83, 84, 57],
    // lower body
    [57, 58, 59, 60, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96],
    [60, 67, 68, 69, 88, 97, 98, 99, 92, 100, 101, 102, 96, 103, 104, 105],
    [69, 76, 77, 78, 99, 106, 107, 108, 102, 109, 110, 111, 105, 112, 113, 114],
    [78, 83, 84, 57, 108, 115, 116, 85, 111, 117, 118, 89, 114, 119, 120, 93],
    // handle
    [121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136],
    [124, 137, 138, 121, 128, 139, 140, 125, 132, 141, 142, 129, 136, 143, 144, 133],
    [133, 134, 135, 136, 145, 146, 147, 148, 149, 150, 151, 152, 69, 153, 154, 155],
    [136, 143, 144, 133, 148, 156, 157, 145, 152, 158, 159, 149, 155, 160, 161, 69],
    // spout
    [162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177],
    [165, 178, 179, 162, 169, 180, 181, 166, 173, 182, 183, 170, 177, 184, 185, 174],
    [174, 175, 176, 177, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197],
    [177, 184, 185, 174, 189, 198, 199, 186, 193, 200, 201, 190, 197, 202, 203, 194],
    // lid knob
    [204, 204, 204, 204, 207, 208, 209, 210, 211, 211, 211, 211, 212, 213, 214, 215],
    [204, 204, 204, 204, 210, 217, 218, 219, 211, 211, 211, 211, 215, 220, 221, 222],
    [204, 204, 204, 204, 219, 224, 225, 226, 211, 211, 211, 211, 222, 227, 228, 229],
    [204, 204, 204, 204, 226, 230, 231, 207, 211, 211, 211, 211, 229, 232, 233, 212],
    // lid
    [212, 213, 214, 215, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245],
    [215, 220, 221, 222, 237, 246, 247, 248, 241, 249, 250, 251, 245, 252, 253, 254],
    [222, 227, 228, 229, 248, 255, 256, 257, 251, 258, 259, 260, 254, 261, 262, 263],
    [229, 232, 233, 212, 257, 264, 265, 234, 260, 266, 267, 238, 263, 268, 269, 242],
    // bottom
    [270, 270, 270, 270, 279, 280, 281, 282, 275, 276, 277, 278, 271, 272, 273, 274],
    [270, 270, 270, 270, 282, 289, 290, 291, 278, 286, 287, 288, 274, 283, 284, 285],
    [270, 270, 270, 270, 291, 298, 299, 300, 288, 295, 296, 297, 285, 292, 293, 294],
    [270, 270, 270, 270, 300, 305, 306, 279, 297, 303, 304, 275, 294, 301, 302, 271],
];

/// Newell's 306 control points (x, y, z) in the original z-up coordinates.
#[rustfmt::skip]
const CONTROL_POINTS: [[f64; 3]; 306] = [
    [1.4, 0.0, 2.4], [1.4, -0.784, 2.4], [0.784, -1.4, 2.4],
    [0.0, -1.4, 2.4], [1.3375, 0.0, 2.53125], [1.3375, -0.749, 2.53125],
    [0.749, -1.3375, 2.53125], [0.0, -1.3375, 2.53125], [1.4375, 0.0, 2.53125],
    [1.4375, -0.805, 2.53125], [0.805, -1.4375, 2.53125], [0.0, -1.4375, 2.53125],
    [1.5, 0.0, 2.4], [1.5, -0.84, 2.4], [0.84, -1.5, 2.4],
    [0.0, -1.5, 2.4], [-0.784, -1.4, 2.4], [-1.4, -0.784, 2.4],
    [-1.4, 0.0, 2.4], [-0.749, -1.3375, 2.53125], [-1.3375, -0.749, 2.53125],
    [-1.3375, 0.0, 2.53125], [-0.805, -1.4375, 2.53125], [-1.4375, -0.805, 2.53125],
    [-1.4375, 0.0, 2.53125], [-0.84, -1.5, 2.4], [-1.5, -0.84, 2.4],
    [-1.5, 0.0, 2.4], [-1.4, 0.784, 2.4], [-0.784, 1.4, 2.4],
    [0.0, 1.4, 2.4], [-1.3375, 0.749, 2.53125], [-0.749, 1.3375, 2.53125],
    [0.0, 1.3375, 2.53125], [-1.4375, 0.805, 2.53125], [-0.805, 1.4375, 2.53125],
    [0.0, 1.4375, 2.53125], [-1.5, 0.84, 2.4], [-0.84, 1.5, 2.4],
    [0.0, 1.5, 2.4], [0.784, 1.4, 2.4], [1.4, 0.784, 2.4],
    [0.749, 1.3375, 2.53125], [1.3375, 0.749, 2.53125], [0.805, 1.4375, 2.53125],
    [1.4375, 0.805, 2.53125], [0.84, 1.5, 2.4], [1.5, 0.84, 2.4],
    [1.75, 0.0, 1.875], [1.75, -0.98, 1.875], [0.98, -1.75, 1.875],
    [0.0, -1.75, 1.875], [2.0, 0.0, 1.35], [2.0, -1.12, 1.35],
    [1.12, -2.0, 1.35], [0.0, -2.0, 1.35], [2.0, 0.0, 0.9],
    [2.0, -1.12, 0.9], [1.12, -2.0, 0.9], [0.0, -2.0, 0.9],
    [-0.98, -1.75, 1.875], [-1.75, -0.98, 1.875], [-1.75, 0.0, 1.875],
    [-1.12, -2.0, 1.35], [-2.0, -1.12, 1.35], [-2.0, 0.0, 1.35],
    [-1.12, -2.0, 0.9], [-2.0, -1.12, 0.9], [-2.0, 0.0, 0.9],
    [-1.75, 0.98, 1.875], [-0.98, 1.75, 1.875], [0.0, 1.75, 1.875],
    [-2.0, 1.12, 1.35], [-1.12, 2.0, 1.35], [0.0, 2.0, 1.35],
    [-2.0, 1.12, 0.9], [-1.12, 2.0, 0.9], [0.0, 2.0, 0.9],
    [0.98, 1.75, 1.875], [1.75, 0.98, 1.875], [1.12, 2.0, 1.35],
    [2.0, 1.12, 1.35], [1.12, 2.0, 0.9], [2.0, 1.12, 0.9],
    [2.0, 0.0, 0.45], [2.0, -1.12, 0.45], [1.12, -2.0, 0.45],
    [0.0, -2.0, 0.45], [1.5, 0.0, 0.225], [1.5, -0.84, 0.225],
    [0.84, -1.5, 0.225], [0.0, -1.5, 0.225], [1.5, 0.0, 0.15],
    [1.5, -0.84, 0.15], [0.84, -1.5, 0.15], [0.0, -1.5, 0.15],
    [-1.12, -2.0, 0.45], [-2.0, -1.12, 0.45], [-2.0, 0.0, 0.45],
    [-0.84, -1.5, 0.225], [-1.5, -0.84, 0.225], [-1.5, 0.0, 0.225],
    [-0.84, -1.5, 0.15], [-1.5, -0.84, 0.15], [-1.5, 0.0, 0.15],
    [-2.0, 1.12, 0.45], [-1.12, 2.0, 0.45], [0.0, 2.0, 0.45],
    [-1.5, 0.84, 0.225], [-0.84, 1.5, 0.225], [0.0, 1.5, 0.225],
    [-1.5, 0.84, 0.15], [-0.84, 1.5, 0.15], [0.0, 1.5, 0.15],
    [1.12, 2.0, 0.45], [2.0, 1.12, 0.45], [0.84, 1.5, 0.225],
    [1.5, 0.84, 0.225], [0.84, 1.5, 0.15], [1.5, 0.84, 0.15],
    [-1.6, 0.0, 2.025], [-1.6, -0.3, 2.025], [-1.5, -0.3, 2.25],
    [-1.5, 0.0, 2.25], [-2.3, 0.0, 2.025], [-2.3, -0.3, 2.025],
    [-2.5, -0.3, 2.25], [-2.5, 0.0, 2.25], [-2.7, 0.0, 2.025],
    [-2.7, -0.3, 2.025], [-3.0, -0.3, 2.25], [-3.0, 0.0, 2.25],
    [-2.7, 0.0, 1.8], [-2.7, -0.3, 1.8], [-3.0, -0.3, 1.8],
    [-3.0, 0.0, 1.8], [-1.5, 0.3, 2.25], [-1.6, 0.3, 2.025],
    [-2.5, 0.3, 2.25], [-2.3, 0.3, 2.025], [-3.0, 0.3, 2.25],
    [-2.7, 0.3, 2.025], [-3.0, 0.3, 1.8], [-2.7, 0.3, 1.8],
    [-2.7, 0.0, 1.575], [-2.7, -0.3, 1.575], [-3.0, -0.3, 1.35],
    [-3.0, 0.0, 1.35], [-2.5, 0.0, 1.125], [-2.5, -0.3, 1.125],
    [-2.65, -0.3, 0.9375], [-2.65, 0.0, 0.9375], [-2.0, -0.3, 0.9],
    [-1.9, -0.3, 0.6], [-1.9, 0.0, 0.6], [-3.0, 0.3, 1.35],
    [-2.7, 0.3, 1.575], [-2.65, 0.3, 0.9375], [-2.5, 0.3, 1.125],
    [-1.9, 0.3, 0.6], [-2.0, 0.3, 0.9], [1.7, 0.0, 1.425],
    [1.7, -0.66, 1.425], [1.7, -0.66, 0.6], [1.7, 0.0, 0.6],
    [2.6, 0.0, 1.425], [2.6, -0.66, 1.425], [3.1, -0.66, 0.825],
    [3.1, 0.0, 0.825], [2.3, 0.0, 2.1], [2.3, -0.25, 2.1],
    [2.4, -0.25, 2.025], [2.4, 0.0, 2.025], [2.7, 0.0, 2.4],
    [2.7, -0.25, 2.4], [3.3, -0.25, 2.4], [3.3, 0.0, 2.4],
    [1.7, 0.66, 0.6], [1.7, 0.66, 1.425], [3.1, 0.66, 0.825],
    [2.6, 0.66, 1.425], [2.4, 0.25, 2.025], [2.3, 0.25, 2.1],
    [3.3, 0.25, 2.4], [2.7, 0.25, 2.4], [2.8, 0.0, 2.475],
    [2.8, -0.25, 2.475], [3.525, -0.25, 2.49375], [3.525, 0.0, 2.49375],
    [2.9, 0.0, 2.475], [2.9, -0.15, 2.475], [3.45, -0.15, 2.5125],
    [3.45, 0.0, 2.5125], [2.8, 0.0, 2.4], [2.8, -0.15, 2.4],
    [3.2, -0.15, 2.4], [3.2, 0.0, 2.4], [3.525, 0.25, 2.49375],
    [2.8, 0.25, 2.475], [3.45, 0.15, 2.5125], [2.9, 0.15, 2.475],
    [3.2, 0.15, 2.4], [2.8, 0.15, 2.4], [0.0, 0.0, 3.15],
    [0.0, -0.002, 3.15], [0.002, 0.0, 3.15], [0.8, 0.0, 3.15],
    [0.8, -0.45, 3.15], [0.45, -0.8, 3.15], [0.0, -0.8, 3.15],
    [0.0, 0.0, 2.85], [0.2, 0.0, 2.7], [0.2, -0.112, 2.7],
    [0.112, -0.2, 2.7], [0.0, -0.2, 2.7], [-0.002, 0.0, 3.15],
    [-0.45, -0.8, 3.15], [-0.8, -0.45, 3.15], [-0.8, 0.0, 3.15],
    [-0.112, -0.2, 2.7], [-0.2, -0.112, 2.7], [-0.2, 0.0, 2.7],
    [0.0, 0.002, 3.15], [-0.8, 0.45, 3.15], [-0.45, 0.8, 3.15],
    [0.0, 0.8, 3.15], [-0.2, 0.112, 2.7], [-0.112, 0.2, 2.7],
    [0.0, 0.2, 2.7], [0.45, 0.8, 3.15], [0.8, 0.45, 3.15],
    [0.112, 0.2, 2.7], [0.2, 0.112, 2.7], [0.4, 0.0, 2.55],
    [0.4, -0.224, 2.55], [0.224, -0.4, 2.55], [0.0, -0.4, 2.55],
    [1.3, 0.0, 2.55], [1.3, -0.728, 2.55], [0.728, -1.3, 2.55],
    [0.0, -1.3, 2.55], [1.3, 0.0, 2.4], [1.3, -0.728, 2.4],
    [0.728, -1.3, 2.4], [0.0, -1.3, 2.4], [-0.224, -0.4, 2.55],
    [-0.4, -0.224, 2.55], [-0.4, 0.0, 2.55], [-0.728, -1.3, 2.55],
    [-1.3, -0.728, 2.55], [-1.3, 0.0, 2.55], [-0.728, -1.3, 2.4],
    [-1.3, -0.728, 2.4], [-1.3, 0.0, 2.4], [-0.4, 0.224, 2.55],
    [-0.224, 0.4, 2.55], [0.0, 0.4, 2.55], [-1.3, 0.728, 2.55],
    [-0.728, 1.3, 2.55], [0.0, 1.3, 2.55], [-1.3, 0.728, 2.4],
    [-0.728, 1.3, 2.4], [0.0, 1.3, 2.4], [0.224, 0.4, 2.55],
    [0.4, 0.224, 2.55], [0.728, 1.3, 2.55], [1.3, 0.728, 2.55],
    [0.728, 1.3, 2.4], [1.3, 0.728, 2.4], [0.0, 0.0, 0.0],
    [1.5, 0.0, 0.15], [1.5, 0.84, 0.15], [0.84, 1.5, 0.15],
    [0.0, 1.5, 0.15], [1.5, 0.0, 0.075], [1.5, 0.84, 0.075],
    [0.84, 1.5, 0.075], [0.0, 1.5, 0.075], [1.425, 0.0, 0.0],
    [1.425, 0.798, 0.0], [0.798, 1.425, 0.0], [0.0, 1.425, 0.0],
    [-0.84, 1.5, 0.15], [-1.5, 0.84, 0.15], [-1.5, 0.0, 0.15],
    [-0.84, 1.5, 0.075], [-1.5, 0.84, 0.075], [-1.5, 0.0, 0.075],
    [-0.798, 1.425, 0.0], [-1.425, 0.798, 0.0], [-1.425, 0.0, 0.0],
    [-1.5, -0.84, 0.15], [-0.84, -1.5, 0.15], [0.0, -1.5, 0.15],
    [-1.5, -0.84, 0.075], [-0.84, -1.5, 0.075], [0.0, -1.5, 0.075],
    [-1.425, -0.798, 0.0], [-0.798, -1.425, 0.0], [0.0, -1.425, 0.0],
    [0.84, -1.5, 0.15], [1.5, -0.84, 0.15], [0.84, -1.5, 0.075],
    [1.5, -0.84, 0.075], [0.798, -1.425, 0.0], [1.425, -0.798, 0.0],
];

/// The cubic Bernstein polynomials B0..B3 at `t`.
fn bernstein(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
}

/// The derivatives of B0..B3 at `t`.
fn bernstein_derivative(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [
        -3.0 * s * s,
        3.0 * s * s - 6.0 * t * s,
        6.0 * t * s - 3.0 * t * t,
        3.0 * t * t,
    ]
}

/// One bicubic patch: control point `4 * r + c` weighs B_r(u) · B_c(v).
struct Patch {
    control: [DVec3; 16],
}

/// Normals shorter than this (in data units, where |∂P/∂u × ∂P/∂v| is typically 1..10) are
/// taken as a vanishing derivative.
const DEGENERATE_NORMAL: f64 = 1e-7;

impl Patch {
    fn new(index: usize) -> Self {
        let ids = &PATCHES[index];
        Patch {
            control: std::array::from_fn(|k| DVec3::from_array(CONTROL_POINTS[usize::from(ids[k]) - 1])),
        }
    }

    fn combine(&self, bu: [f64; 4], bv: [f64; 4]) -> DVec3 {
        let mut sum = DVec3::ZERO;
        for (r, wu) in bu.iter().enumerate() {
            for (c, wv) in bv.iter().enumerate() {
                sum += self.control[4 * r + c] * (wu * wv);
            }
        }
        sum
    }

    fn point(&self, u: f64, v: f64) -> DVec3 {
        self.combine(bernstein(u), bernstein(v))
    }

    /// -(∂P/∂u × ∂P/∂v), unnormalized: Newell's patches are all parameterized so that this
    /// points out of the teapot (checked by the tests).
    fn raw_normal(&self, u: f64, v: f64) -> DVec3 {
        let du = self.combine(bernstein_derivative(u), bernstein(v));
        let dv = self.combine(bernstein(u), bernstein_derivative(v));
        -du.cross(dv)
    }

    /// The unit outward normal at (u, v). Where a derivative vanishes (the lid knob's tip and
    /// the bottom's center, where a whole row of control points collapses to one point), the
    /// normal is taken a little way into the patch, which converges to the surface's limit
    /// normal there; if even that fails, a fixed axis (up above mid-height, down below).
    fn normal(&self, u: f64, v: f64) -> DVec3 {
        let n = self.raw_normal(u, v);
        if n.length() > DEGENERATE_NORMAL {
            return n.normalize();
        }
        for step in [1e-4, 1e-3, 1e-2, 1e-1] {
            let toward_center = |t: f64| if t < 0.5 { t + step } else { t - step };
            let n = self.raw_normal(toward_center(u), toward_center(v));
            if n.length() > DEGENERATE_NORMAL {
                return n.normalize();
            }
        }
        if self.point(u, v).z >= CENTER.z {
            DVec3::Z
        } else {
            DVec3::NEG_Z
        }
    }

    /// Whether each boundary curve collapses to a point: [u = 0, u = 1, v = 0, v = 1].
    fn collapsed_edges(&self) -> [bool; 4] {
        let all_equal = |ks: [usize; 4]| ks.iter().all(|&k| self.control[k] == self.control[ks[0]]);
        [
            all_equal([0, 1, 2, 3]),
            all_equal([12, 13, 14, 15]),
            all_equal([0, 4, 8, 12]),
            all_equal([3, 7, 11, 15]),
        ]
    }
}

/// Data (z-up) point to ffvk's y-up, centered, scaled frame (see the module docs).
fn to_y_up_point(p: DVec3) -> DVec3 {
    let q = p - CENTER;
    DVec3::new(q.x, q.z, -q.y) / HALF_EXTENT
}

/// Data (z-up) direction to the y-up frame: the same rotation, no translation or scale.
fn to_y_up_direction(n: DVec3) -> DVec3 {
    DVec3::new(n.x, n.z, -n.y)
}

/// The Utah teapot with each of its 32 patches cut into `level` × `level` quads.
///
/// Every patch has its own (level + 1)² vertices (none are shared between patches, so the
/// vertex count is 32 · (level + 1)²), each with the patch's analytic unit normal
/// -(∂P/∂u × ∂P/∂v), pointing out of the teapot, and color white (1, 1, 1, 1). Each quad
/// becomes two triangles, counter-clockwise seen from outside. Where a patch boundary
/// collapses to a point (the lid knob's tip and the bottom's center) the zero-area triangle
/// of each quad along it is left out: 64 · level² − 8 · level triangles in all.
///
/// The frame is y up, centered, scaled into [-1, 1]³ (see the module docs).
///
/// Errors when `level` is 0 or larger than [`MAX_LEVEL`].
pub fn teapot(level: u32) -> Result<MeshData, MeshError> {
    if level == 0 || level > MAX_LEVEL {
        return Err(MeshError::TeapotLevel {
            level,
            max: MAX_LEVEL,
        });
    }
    let n = level as usize;
    let side = n + 1;
    let mut vertices = Vec::with_capacity(PATCH_COUNT * side * side);
    let mut indices = Vec::with_capacity(PATCH_COUNT * n * n * 6);
    let white = Vec4::ONE;
    for index in 0..PATCH_COUNT {
        let patch = Patch::new(index);
        let base = vertices.len();
        for i in 0..side {
            let u = i as f64 / n as f64;
            for j in 0..side {
                let v = j as f64 / n as f64;
                let position = to_y_up_point(patch.point(u, v)).as_vec3();
                let normal = to_y_up_direction(patch.normal(u, v)).as_vec3().normalize();
                // Each patch takes the whole texture, (s, t) = (u, v), as glutSolidTeapot does.
                let st = glam::Vec2::new(u as f32, v as f32);
                vertices.push(Vertex::new(position, normal, white).with_texcoord(st));
            }
        }
        let [u0, u1, v0, v1] = patch.collapsed_edges();
        let id = |i: usize, j: usize| (base + i * side + j) as u32;
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
                // (a, c, b): (c - a) × (b - a) = (∂u + ∂v) × ∂u = -(∂u × ∂v), the outward
                // normal, so the triangle is counter-clockwise seen from outside. Its edges a-b
                // (v = j) and b-c (u = i + 1) vanish on collapsed boundaries.
                let first_vanishes = (j == 0 && v0) || (i + 1 == n && u1);
                if !first_vanishes {
                    indices.extend_from_slice(&[a, c, b]);
                }
                // (a, d, c): (d - a) × (c - a) = ∂v × (∂u + ∂v) = -(∂u × ∂v). Edges a-d
                // (u = i) and d-c (v = j + 1).
                let second_vanishes = (i == 0 && u0) || (j + 1 == n && v1);
                if !second_vanishes {
                    indices.extend_from_slice(&[a, d, c]);
                }
            }
        }
    }
    Ok(MeshData::new(vertices, indices))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;
    use std::collections::HashMap;

    fn pos(v: &Vertex) -> Vec3 {
        Vec3::from_array(v.position)
    }

    fn nrm(v: &Vertex) -> Vec3 {
        Vec3::from_array(v.normal)
    }

    #[test]
    fn data_tables_are_consistent() {
        for (p, ids) in PATCHES.iter().enumerate() {
            for &id in ids {
                assert!((1..=306).contains(&id), "patch {p} names control point {id}");
            }
        }
        // Every control point but the four near-duplicates of the knob tip is used.
        let mut used = [false; 306];
        PATCHES
            .iter()
            .flatten()
            .for_each(|&id| used[usize::from(id) - 1] = true);
        let unused: Vec<usize> = (1..=306).filter(|&k| !used[k - 1]).collect();
        assert_eq!(unused, vec![205, 206, 216, 223]);
    }

    #[test]
    fn vertex_count_is_32_times_level_plus_one_squared() {
        for level in [1, 2, 3, 8, 16] {
            let mesh = teapot(level).unwrap();
            let side = (level + 1) as usize;
            assert_eq!(mesh.vertices.len(), PATCH_COUNT * side * side, "level {level}");
            assert_eq!(mesh.indices.len() % 3, 0);
            // 8 patches (knob and bottom) lose one triangle per quad along their collapsed edge.
            let n = level as usize;
            assert_eq!(
                mesh.triangle_count(),
                PATCH_COUNT * 2 * n * n - 8 * n,
                "level {level}"
            );
            assert!(mesh.indices.iter().all(|&i| (i as usize) < mesh.vertices.len()));
        }
    }

    #[test]
    fn level_out_of_range_is_an_error_naming_the_value_and_range() {
        let e = teapot(0).unwrap_err().to_string();
        assert!(e.contains("level 0") && e.contains("1..=64"), "{e}");
        let e = teapot(65).unwrap_err().to_string();
        assert!(e.contains("level 65") && e.contains("1..=64"), "{e}");
        assert!(teapot(1).is_ok());
        assert!(teapot(MAX_LEVEL).is_ok());
    }

    #[test]
    fn attributes_are_finite_normals_unit_colors_white() {
        for level in [1, 4, 10] {
            let mesh = teapot(level).unwrap();
            for (k, v) in mesh.vertices.iter().enumerate() {
                assert!(
                    pos(v).is_finite(),
                    "level {level} vertex {k}: position {:?}",
                    v.position
                );
                let n = nrm(v);
                assert!(n.is_finite(), "level {level} vertex {k}: normal {n}");
                assert!(
                    (n.length() - 1.0).abs() < 1e-5,
                    "level {level} vertex {k}: |n| = {}",
                    n.length()
                );
                assert_eq!(v.color, [1.0; 4]);
            }
        }
    }

    #[test]
    fn winding_agrees_with_normals() {
        // Level 1 is left out: there each half-tube patch of the handle and spout is a single
        // quad whose four corners lie in the symmetry plane, so its triangles face sideways
        // (perpendicular to the corner normals), and the spout lip's corners are collinear.
        for level in [2, 3, 6, 12] {
            let mesh = teapot(level).unwrap();
            let (mut agree, mut total, mut degenerate) = (0usize, 0usize, 0usize);
            for t in mesh.indices.chunks(3) {
                let [a, b, c] = [0, 1, 2].map(|k| &mesh.vertices[t[k] as usize]);
                let face = (pos(b) - pos(a)).cross(pos(c) - pos(a));
                if face.length() < 1e-12 {
                    degenerate += 1;
                    continue;
                }
                total += 1;
                if face.dot(nrm(a) + nrm(b) + nrm(c)) > 0.0 {
                    agree += 1;
                }
            }
            assert_eq!(
                degenerate, 0,
                "level {level}: collapsed patch edges produce no triangles"
            );
            assert!(
                agree * 100 > total * 99,
                "level {level}: {agree} of {total} triangles agree"
            );
            // From level 3 on, every one does (at level 2, 238 of 240: the spout lip's
            // triangles are still coarser than its curl).
            if level >= 3 {
                assert_eq!(agree, total, "level {level}");
            }
        }
    }

    #[test]
    fn bounding_box_is_centered_y_up_and_unit_sized() {
        let mesh = teapot(16).unwrap();
        let (mut lo, mut hi) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
        for v in &mesh.vertices {
            lo = lo.min(pos(v));
            hi = hi.max(pos(v));
        }
        assert!(
            lo.cmpge(Vec3::splat(-1.0)).all() && hi.cmple(Vec3::splat(1.0)).all(),
            "{lo} {hi}"
        );
        // Bottom at data z = 0 and the knob tip at z = 3.15 lie on the surface.
        let bottom = (0.0 - 1.575) / 3.2625;
        assert!((lo.y - bottom as f32).abs() < 1e-5, "bottom {}", lo.y);
        assert!((hi.y + bottom as f32).abs() < 1e-5, "top {}", hi.y);
        // Handle (-x) to spout (+x) is the long side; the body is symmetric in z.
        assert!(hi.x - lo.x > 1.8 && hi.x > 0.9 && lo.x < -0.8, "{lo} {hi}");
        assert!(
            (lo.z + hi.z).abs() < 1e-5 && hi.z > 0.6 && hi.z < 0.62,
            "{lo} {hi}"
        );
        assert!(hi.y - lo.y < hi.x - lo.x, "y is up, x is the long axis");
    }

    #[test]
    fn normals_point_out_of_the_teapot() {
        let n = 8;
        let mesh = teapot(n).unwrap();
        let per_patch = ((n + 1) * (n + 1)) as usize;
        let patch_vertices = |p: usize| &mesh.vertices[p * per_patch..(p + 1) * per_patch];
        let axis_point = Vec3::new(-0.2625 / 3.2625, 0.0, 0.0);
        // Rim, body, lid and bottom: the normal leans away from the vertical axis (or along
        // it, at the lid and the bottom) wherever the surface is far from the knob.
        for p in (0..12).chain(24..32) {
            let mut outward = 0;
            // The rim (patches 0-3) rolls over from the outer wall (u = 1) to the inside
            // (u = 0), where its outer face faces the axis: check its outer half only.
            let rows = if p < 4 {
                (n / 2 + 1) as usize..(n + 1) as usize
            } else {
                0..(n + 1) as usize
            };
            let checked = rows.len() * (n + 1) as usize;
            for v in patch_vertices(p)[rows.start * (n + 1) as usize..rows.end * (n + 1) as usize].iter() {
                let mut d = pos(v) - axis_point;
                if p >= 12 {
                    d = Vec3::new(d.x, d.y.signum() * 0.5, d.z);
                } else {
                    d.y = 0.0;
                }
                if nrm(v).dot(d) > 0.0 {
                    outward += 1;
                }
            }
            assert_eq!(
                outward, checked,
                "patch {p}: {outward} of {checked} normals point out"
            );
        }
        // Handle and spout tubes: at the middle of the tube, the normal points away from the
        // tube's cross-section center (the midpoint of the patch's two v = 0 and v = 1 edges).
        for p in 12..20 {
            let patch = Patch::new(p);
            for u in [0.1, 0.25, 0.4] {
                let center = (patch.point(u, 0.0) + patch.point(u, 1.0)) / 2.0;
                let d = patch.point(u, 0.5) - center;
                assert!(patch.normal(u, 0.5).dot(d) > 0.0, "patch {p} u {u}");
            }
        }
        // The knob tip points up, the bottom center down.
        let tip = patch_vertices(20)[0];
        assert!(nrm(&tip).dot(Vec3::Y) > 0.999, "knob tip normal {:?}", tip.normal);
        let bottom = patch_vertices(28)[0];
        assert!(
            nrm(&bottom).dot(Vec3::NEG_Y) > 0.999,
            "bottom center normal {:?}",
            bottom.normal
        );
    }

    #[test]
    fn patches_are_consistently_oriented_across_shared_edges() {
        // Weld coincident vertices; a consistently oriented surface walks every shared edge
        // once in each direction, never twice in the same one.
        let mesh = teapot(6).unwrap();
        let mut ids: HashMap<[i64; 3], u32> = HashMap::new();
        let key = |p: Vec3| p.to_array().map(|x| (x as f64 * 1e5).round() as i64);
        let welded: Vec<u32> = mesh
            .vertices
            .iter()
            .map(|v| {
                let next = ids.len() as u32;
                *ids.entry(key(pos(v))).or_insert(next)
            })
            .collect();
        let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
        for t in mesh.indices.chunks(3) {
            for k in 0..3 {
                let (a, b) = (welded[t[k] as usize], welded[t[(k + 1) % 3] as usize]);
                *directed.entry((a, b)).or_default() += 1;
            }
        }
        let twice: Vec<_> = directed.iter().filter(|(_, &c)| c > 1).collect();
        assert!(twice.is_empty(), "edges walked twice the same way: {twice:?}");
        let shared = directed
            .keys()
            .filter(|(a, b)| directed.contains_key(&(*b, *a)))
            .count();
        assert!(
            shared > directed.len() / 2,
            "{shared} of {} edges are shared",
            directed.len()
        );
    }

    #[test]
    fn closed_part_encloses_positive_volume() {
        // Body, lid and bottom: signed volume sum of a·(b×c)/6 > 0 with outward orientation.
        let n = 12u32;
        let mesh = teapot(n).unwrap();
        let per_patch = (n + 1) * (n + 1);
        let mut volume = 0.0f64;
        for t in mesh.indices.chunks(3) {
            let patch = t[0] / per_patch;
            if (12..20).contains(&patch) {
                continue;
            }
            let [a, b, c] = [0, 1, 2].map(|k| pos(&mesh.vertices[t[k] as usize]).as_dvec3());
            volume += a.dot(b.cross(c)) / 6.0;
        }
        // About 0.72: less than the bounding cylinder of the body (radius 2 / 3.2625, height
        // 2.4 / 3.2625: 0.87) plus the lid's, more than the cylinder inscribed in the bulge.
        assert!(volume > 0.5 && volume < 0.95, "volume {volume}");
    }
}
