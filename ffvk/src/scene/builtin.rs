//! The shapes a `[[meshes]]` table may name with `builtin` instead of a glTF file: the Utah
//! teapot, a UV sphere and a square.

use super::file::MeshSpec;
use super::{Builder, SceneError};
use crate::mesh::{teapot, MeshData, Vertex};
use glam::{Vec3, Vec4};

impl Builder<'_> {
    /// The built-in shape `name` of the `[[meshes]]` entry `field`, tessellated by its
    /// `level` and with its `color` (white by default) at every vertex.
    pub(super) fn builtin(&self, field: &str, name: &str, spec: &MeshSpec) -> Result<MeshData, SceneError> {
        let mut data = match name {
            "teapot" => teapot::teapot(spec.level.unwrap_or(12))
                .map_err(|e| self.field(format!("{field}.level"), e.to_string()))?,
            "sphere" => {
                let n = spec.level.unwrap_or(32);
                if !(3..=1024).contains(&n) {
                    return Err(
                        self.field(format!("{field}.level"), format!("{n}: expected 3..=1024 slices"))
                    );
                }
                MeshData::uv_sphere(n, n / 2)
            }
            "plane" => {
                let n = spec.level.unwrap_or(1);
                if !(1..=1024).contains(&n) {
                    return Err(self.field(format!("{field}.level"), format!("{n}: expected 1..=1024 cells")));
                }
                plane(n)
            }
            other => {
                return Err(self.field(
                    format!("{field}.builtin"),
                    format!(
                        "{:?}: expected \"teapot\", \"sphere\" or \"plane\"",
                        super::shorten(other)
                    ),
                ))
            }
        };
        if let Some(c) = &spec.color {
            let c = self.color(&format!("{field}.color"), c)?;
            data.vertices.iter_mut().for_each(|v| v.color = c.to_array());
        }
        Ok(data)
    }
}

/// The square [-1, 1]² in the z = 0 plane, facing +z, `n`×`n` cells; texture coordinates
/// put an image upright on it, its first row along the top edge.
fn plane(n: u32) -> MeshData {
    let mut data = MeshData::default();
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (-1.0 + 2.0 * i as f32 / n as f32, -1.0 + 2.0 * j as f32 / n as f32);
            // The image upright: s left to right, t from the top edge (row 0 at t = 0).
            let st = glam::Vec2::new((x + 1.0) / 2.0, (1.0 - y) / 2.0);
            data.vertices
                .push(Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, Vec4::ONE).with_texcoord(st));
        }
    }
    let at = |i: u32, j: u32| j * (n + 1) + i;
    for j in 0..n {
        for i in 0..n {
            data.indices.extend([
                at(i, j),
                at(i + 1, j),
                at(i + 1, j + 1),
                at(i, j),
                at(i + 1, j + 1),
                at(i, j + 1),
            ]);
        }
    }
    data
}
