//! Geometry on the host: independent triangles with GL's per-vertex attributes.

pub mod teapot;

use glam::{Vec2, Vec3, Vec4};

/// One vertex as the vertex stage reads it (locations 0, 1, 2, and 3 when textured).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    /// Object-space position.
    pub position: [f32; 3],
    /// Object-space normal (GL's current normal); not normalized by ffvk.
    pub normal: [f32; 3],
    /// GL's current color, RGBA; feeds COLOR_MATERIAL and unlit drawing.
    pub color: [f32; 4],
    /// Texture coordinates (s, t); r = 0 and q = 1, as glTexCoord2f sets them.
    pub texcoord: [f32; 2],
}

impl Vertex {
    /// A vertex from glam vectors; the normal and color are stored as given.
    pub fn new(position: Vec3, normal: Vec3, color: Vec4) -> Self {
        Vertex {
            position: position.to_array(),
            normal: normal.to_array(),
            color: color.to_array(),
            texcoord: [0.0; 2],
        }
    }

    /// The same vertex with texture coordinates (s, t).
    pub fn with_texcoord(self, st: Vec2) -> Self {
        Vertex {
            texcoord: st.to_array(),
            ..self
        }
    }
}

/// Vertices and the indices that make its primitives: a triangle list unless `topology` says
/// otherwise (every three indices a triangle, counter-clockwise front).
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct MeshData {
    /// The vertices the indices refer to; a vertex may be shared by several triangles.
    pub vertices: Vec<Vertex>,
    /// Each below `vertices.len()`; a multiple of 3 for a triangle list, of 2 for a line
    /// list. [`Renderer::upload`] rejects anything else with a
    /// [`MeshError`](crate::error::MeshError).
    ///
    /// [`Renderer::upload`]: crate::Renderer::upload
    pub indices: Vec<u32>,
    /// How the indices make primitives (`TriangleList` by default); a draw of the mesh takes
    /// it ([`Draw::new`](crate::Draw::new)).
    pub topology: crate::Topology,
    /// A second set of texture coordinates (s, t), one per vertex, or none (empty, the
    /// default): glTF's `TEXCOORD_1`. [`Renderer::upload`] puts it in a vertex buffer of its
    /// own, so that [`Vertex`]'s layout stays as it is; units 1-3 read it where a draw's
    /// [`Draw::second_texcoords`](crate::Draw::second_texcoords) names them. A set of
    /// another length than `vertices` is refused with a
    /// [`MeshError`](crate::error::MeshError).
    ///
    /// [`Renderer::upload`]: crate::Renderer::upload
    pub second_texcoords: Vec<[f32; 2]>,
}

impl MeshData {
    /// A triangle list of `vertices` and `indices` (checked when it is uploaded).
    pub fn new(vertices: Vec<Vertex>, indices: Vec<u32>) -> Self {
        MeshData {
            vertices,
            indices,
            topology: crate::Topology::TriangleList,
            second_texcoords: Vec::new(),
        }
    }

    /// This mesh with a second set of texture coordinates, one (s, t) per vertex (see
    /// [`MeshData::second_texcoords`]).
    #[must_use]
    pub fn with_second_texcoords(mut self, st: Vec<[f32; 2]>) -> Self {
        self.second_texcoords = st;
        self
    }

    /// This mesh with its indices read as `topology`.
    #[must_use]
    pub fn with_topology(mut self, topology: crate::Topology) -> Self {
        self.topology = topology;
        self
    }

    /// The number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }
}

impl MeshData {
    /// A unit sphere centered at the origin, `slices` around the y axis and `stacks` from
    /// pole to pole, with unit outward normals, counter-clockwise seen from outside, white;
    /// texture coordinates s = longitude / 360°, t = colatitude / 180°.
    pub fn uv_sphere(slices: u32, stacks: u32) -> MeshData {
        let (slices, stacks) = (slices.max(3), stacks.max(2));
        let mut vertices = Vec::with_capacity(((slices + 1) * (stacks + 1)) as usize);
        for j in 0..=stacks {
            let theta = std::f32::consts::PI * j as f32 / stacks as f32; // from +y down
            for i in 0..=slices {
                let phi = std::f32::consts::TAU * i as f32 / slices as f32;
                let n = Vec3::new(theta.sin() * phi.sin(), theta.cos(), theta.sin() * phi.cos());
                // s around from the seam, t from the top pole: an image's first row is at the top.
                let st = Vec2::new(i as f32 / slices as f32, j as f32 / stacks as f32);
                vertices.push(Vertex::new(n, n, Vec4::ONE).with_texcoord(st));
            }
        }
        let at = |i: u32, j: u32| j * (slices + 1) + i;
        let mut indices = Vec::with_capacity((slices * stacks * 6) as usize);
        for j in 0..stacks {
            for i in 0..slices {
                let (a, b, c, d) = (at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
                if j > 0 {
                    indices.extend([a, b, d]);
                }
                if j + 1 < stacks {
                    indices.extend([d, b, c]);
                }
            }
        }
        MeshData::new(vertices, indices)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_winding_is_counter_clockwise_from_outside() {
        let m = MeshData::uv_sphere(12, 8);
        for t in m.indices.chunks(3) {
            let p: [Vec3; 3] = std::array::from_fn(|k| Vec3::from(m.vertices[t[k] as usize].position));
            let face = (p[1] - p[0]).cross(p[2] - p[0]);
            let center = (p[0] + p[1] + p[2]) / 3.0;
            assert!(face.dot(center) > 0.0, "triangle {t:?} faces inward");
        }
    }
}
