//! Geometry on the host: independent triangles with GL's per-vertex attributes.

use glam::{Vec3, Vec4};

/// One vertex as the vertex stage reads it (locations 0, 1, 2).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    /// Object-space position.
    pub position: [f32; 3],
    /// Object-space normal (GL's current normal); not normalized by ffvk.
    pub normal: [f32; 3],
    /// GL's current color, RGBA; feeds COLOR_MATERIAL and unlit drawing.
    pub color: [f32; 4],
}

impl Vertex {
    pub fn new(position: Vec3, normal: Vec3, color: Vec4) -> Self {
        Vertex {
            position: position.to_array(),
            normal: normal.to_array(),
            color: color.to_array(),
        }
    }
}

/// A triangle list: every three indices make one triangle, counter-clockwise is front.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MeshData {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

impl MeshData {
    /// The number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }
}
