//! The floor's frame on the host: the draws sweep's scene (`draws::scene`, vertex mode) as a
//! plain program keeps it: one frame block of GL's derived light state, one 128-byte record
//! per draw, the meshes.

use bytemuck::{Pod, Zeroable};
use glam::{Vec3, Vec4};

use super::super::draws::{scene, DrawShape};
use super::super::sweep::BenchMode;
use crate::{Error, Result};
use ffvk::gl::state::{Attenuation, ColorControl, FixedFunctionState, SpecularModel};
use ffvk::gpu::layout::{normal_matrix, VK_FROM_GL_CLIP};
use ffvk::mesh::MeshData;

/// One draw's values as every path's vertex stage reads them (`glsl/floor/floor.vert`),
/// 128 bytes: what fits in lavapipe's (and Vulkan's guaranteed) 128 bytes of push
/// constants. The modelview's first three rows (its last row is (0, 0, 0, 1): checked), the
/// normal matrix (M⁻¹)ᵀ's columns (w unused), the front diffuse, the front specular (rgb) and
/// shininess (w). The ambient and emission materials are the frame's (the sweep's program sets
/// them once per frame, as GL's does).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub(super) struct Record {
    modelview_rows: [[f32; 4]; 3],
    normal_columns: [[f32; 4]; 3],
    diffuse: [f32; 4],
    specular_shininess: [f32; 4],
}

/// The record's size in bytes.
pub(super) const RECORD_BYTES: u64 = std::mem::size_of::<Record>() as u64;

/// The frame's uniform block, std140 (`Frame` in `floor.vert`): GL's derived state of the two
/// lights, computed on the host once per frame as GL implementations do.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Pod, Zeroable)]
pub(super) struct FrameBlock {
    projection: [f32; 16],
    scene: [f32; 4],
    l0_vp: [f32; 4],
    l0_h: [f32; 4],
    l0_ambient: [f32; 4],
    l0_diffuse: [f32; 4],
    l0_specular: [f32; 4],
    l1_position: [f32; 4],
    l1_ambient: [f32; 4],
    l1_diffuse: [f32; 4],
    l1_specular: [f32; 4],
    l1_k: [f32; 4],
}

/// The sweep's frame of `draws` draws of one shape, as the floor draws it.
pub(super) struct FloorScene {
    pub(super) draws: u32,
    pub(super) mesh: MeshData,
    /// Each draw a mesh of its own (its own buffers), else all draws the one mesh.
    pub(super) mesh_each: bool,
    pub(super) block: FrameBlock,
    pub(super) records: Vec<Record>,
}

/// v / |v|, as the shader's `unit` (zero kept zero).
fn unit(v: Vec3) -> Vec3 {
    let len = v.length();
    if len > 0.0 {
        v / len
    } else {
        Vec3::ZERO
    }
}

fn rgb(v: Vec3) -> [f32; 4] {
    v.extend(0.0).to_array()
}

/// Refuses a draw's state the floor's shader does not draw as GL would: it evaluates the
/// equation for a directional light 0, a point light 1 (no spot), both enabled and no other,
/// one-sided, infinite viewer, no NORMALIZE, no COLOR_MATERIAL, a single color, Blinn's
/// specular; and the first draw's ambient and emission materials for every draw.
fn check(state: &FixedFunctionState, first: &FixedFunctionState) -> Result<()> {
    let [l0, l1] = [&state.lights[0], &state.lights[1]];
    let ok = state.lighting
        && l0.enabled
        && l1.enabled
        && state.lights[2..].iter().all(|l| !l.enabled)
        && l0.position.w == 0.0
        && l1.position.w == 1.0
        && l0.spot_cutoff == 180.0
        && l1.spot_cutoff == 180.0
        && l1.attenuation == Attenuation::GlK012
        && !state.model.local_viewer
        && !state.model.two_side
        && state.model.color_control == ColorControl::SingleColor
        && state.model.specular_model == SpecularModel::BlinnHalfway
        && !state.normalize
        && !state.rescale_normal
        && !state.color_material.enabled
        && state.front.ambient == first.front.ambient
        && state.front.emission == first.front.emission
        && state.model.ambient == first.model.ambient
        && state.lights[..2] == first.lights[..2];
    if ok {
        Ok(())
    } else {
        Err(Error::Bench(
            "the floor draws only the draws sweep's lights and materials (a directional and a point light)"
                .into(),
        ))
    }
}

impl FloorScene {
    /// The draws sweep's frame of `draws` draws of `shape` (vertex mode).
    pub(super) fn new(shape: DrawShape, draws: u32) -> Result<Self> {
        let (objects, projection) = scene(BenchMode::Vertex, draws, shape.fit())?;
        let Some((_, first)) = objects.first() else {
            return Err(Error::Bench("a floor frame of no draws".into()));
        };
        let first = *first;
        let mut records = Vec::with_capacity(objects.len());
        for (modelview, state) in &objects {
            check(state, &first)?;
            if modelview.row(3) != Vec4::W {
                return Err(Error::Bench(
                    "the floor's records hold affine modelviews only".into(),
                ));
            }
            let n = normal_matrix(*modelview);
            let m = &state.front;
            records.push(Record {
                modelview_rows: [0, 1, 2].map(|i| modelview.row(i).to_array()),
                normal_columns: [n.x_axis, n.y_axis, n.z_axis].map(|c| c.extend(0.0).to_array()),
                diffuse: m.diffuse.to_array(),
                specular_shininess: m.specular.truncate().extend(m.shininess).to_array(),
            });
        }
        let m = &first.front;
        let [l0, l1] = [&first.lights[0], &first.lights[1]];
        let a_cm = m.ambient.truncate();
        let vp0 = unit(l0.position.truncate());
        let block = FrameBlock {
            projection: (VK_FROM_GL_CLIP * projection).to_cols_array(),
            scene: rgb(m.emission.truncate() + a_cm * first.model.ambient.truncate()),
            l0_vp: rgb(vp0),
            l0_h: rgb(unit(vp0 + Vec3::Z)),
            l0_ambient: rgb(a_cm * l0.ambient.truncate()),
            l0_diffuse: l0.diffuse.to_array(),
            l0_specular: l0.specular.to_array(),
            l1_position: l1.position.to_array(),
            l1_ambient: rgb(a_cm * l1.ambient.truncate()),
            l1_diffuse: l1.diffuse.to_array(),
            l1_specular: l1.specular.to_array(),
            l1_k: [
                l1.constant_attenuation,
                l1.linear_attenuation,
                l1.quadratic_attenuation,
                0.0,
            ],
        };
        Ok(FloorScene {
            draws,
            mesh: shape.mesh(),
            mesh_each: shape == DrawShape::QuadMeshEach,
            block,
            records,
        })
    }
}
