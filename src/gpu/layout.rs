//! The GPU layout of GL state: std140 mirrors of `glsl/draw.glsl`'s `Draw` block.
//! Field names are the GLSL member names; a test compares their offsets with the ones
//! glslang wrote into the SPIR-V.

#![allow(non_snake_case)]

use glam::{Mat3, Mat4};

use crate::gl::state::{
    ColorControl, ColorMaterialMode, Light, LightingState, Material, StateError, MAX_LIGHTS,
};

/// GL clip space (z in [-w, w], y up) to Vulkan clip space (z in [0, w], y down), applied
/// after the GL projection so the image's top row is the top of the view, as on a GL screen.
/// The y flip mirrors window-space winding, which the pipeline's front face accounts for.
pub const VK_FROM_GL_CLIP: Mat4 = Mat4::from_cols_array(&[
    1.0, 0.0, 0.0, 0.0, //
    0.0, -1.0, 0.0, 0.0, //
    0.0, 0.0, 0.5, 0.0, //
    0.0, 0.0, 0.5, 1.0,
]);

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMaterial {
    pub a_cm: [f32; 4],
    pub d_cm: [f32; 4],
    pub s_cm: [f32; 4],
    pub e_cm: [f32; 4],
    pub s_rm: f32,
    pub _pad: [f32; 3],
}

impl From<&Material> for GpuMaterial {
    fn from(m: &Material) -> Self {
        GpuMaterial {
            a_cm: m.ambient.to_array(),
            d_cm: m.diffuse.to_array(),
            s_cm: m.specular.to_array(),
            e_cm: m.emission.to_array(),
            s_rm: m.shininess,
            _pad: [0.0; 3],
        }
    }
}

#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuLight {
    pub a_cli: [f32; 4],
    pub d_cli: [f32; 4],
    pub s_cli: [f32; 4],
    pub P_pli: [f32; 4],
    pub s_dli: [f32; 3],
    pub s_rli: f32,
    pub c_rli: f32,
    pub cos_c_rli: f32,
    pub k0: f32,
    pub k1: f32,
    pub k2: f32,
    pub _pad: [f32; 3],
}

impl From<&Light> for GpuLight {
    fn from(l: &Light) -> Self {
        GpuLight {
            a_cli: l.ambient.to_array(),
            d_cli: l.diffuse.to_array(),
            s_cli: l.specular.to_array(),
            P_pli: l.position.to_array(),
            s_dli: l.spot_direction.to_array(),
            s_rli: l.spot_exponent,
            c_rli: l.spot_cutoff,
            // The same cosine as the CPU reference: double precision, exactly 0 at 90°.
            cos_c_rli: crate::reference::cos_cutoff(l.spot_cutoff) as f32,
            k0: l.constant_attenuation,
            k1: l.linear_attenuation,
            k2: l.quadratic_attenuation,
            _pad: [0.0; 3],
        }
    }
}

/// The `Draw` uniform block.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct DrawBlock {
    pub modelview: [f32; 16],
    pub projection: [f32; 16],
    pub normal_matrix: [f32; 16],
    pub front: GpuMaterial,
    pub back: GpuMaterial,
    pub a_cs: [f32; 4],
    pub light_count: u32,
    pub lighting: u32,
    pub v_bs: u32,
    pub t_bs: u32,
    pub separate_specular: u32,
    pub color_material: u32,
    pub color_material_front: u32,
    pub color_material_back: u32,
    pub color_material_mode: u32,
    pub normalize: u32,
    pub rescale: f32,
    pub _pad: u32,
    pub lights: [GpuLight; MAX_LIGHTS],
}

/// The specialization constants of `glsl/draw.glsl`, by `constant_id`. Each is an `int`
/// whose default, -1, makes the shader read the uniform instead (the uber-shader).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u32)]
pub enum SpecConstant {
    LightCount = 0,
    Lighting = 1,
    LocalViewer = 2,
    TwoSide = 3,
    SeparateSpecular = 4,
    ColorMaterial = 5,
    AnyLocalLight = 6,
    AnySpotLight = 7,
}

/// How many specialization constants there are.
pub const SPEC_CONSTANT_COUNT: usize = 8;

impl SpecConstant {
    /// Every constant, in `constant_id` order.
    pub const ALL: [SpecConstant; SPEC_CONSTANT_COUNT] = [
        SpecConstant::LightCount,
        SpecConstant::Lighting,
        SpecConstant::LocalViewer,
        SpecConstant::TwoSide,
        SpecConstant::SeparateSpecular,
        SpecConstant::ColorMaterial,
        SpecConstant::AnyLocalLight,
        SpecConstant::AnySpotLight,
    ];

    /// The `constant_id` in the GLSL.
    pub fn id(self) -> u32 {
        self as u32
    }

    /// The constant's name in the GLSL.
    pub fn glsl_name(self) -> &'static str {
        match self {
            SpecConstant::LightCount => "SPEC_LIGHT_COUNT",
            SpecConstant::Lighting => "SPEC_LIGHTING",
            SpecConstant::LocalViewer => "SPEC_LOCAL_VIEWER",
            SpecConstant::TwoSide => "SPEC_TWO_SIDE",
            SpecConstant::SeparateSpecular => "SPEC_SEPARATE_SPECULAR",
            SpecConstant::ColorMaterial => "SPEC_COLOR_MATERIAL",
            SpecConstant::AnyLocalLight => "SPEC_ANY_LOCAL_LIGHT",
            SpecConstant::AnySpotLight => "SPEC_ANY_SPOT_LIGHT",
        }
    }
}

/// The values of every specialization constant for one pipeline, indexed by `constant_id`;
/// -1 leaves the state to the uniform. The bytes are the `VkSpecializationInfo` data.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, bytemuck::Pod, bytemuck::Zeroable)]
pub struct SpecKey {
    pub values: [i32; SPEC_CONSTANT_COUNT],
}

impl SpecKey {
    /// Every constant at -1: one pipeline per mode that branches on the uniforms.
    pub const UBER: SpecKey = SpecKey {
        values: [-1; SPEC_CONSTANT_COUNT],
    };

    /// The value of one constant.
    pub fn get(&self, c: SpecConstant) -> i32 {
        self.values[c as usize]
    }

    /// A key with every constant fixed to `state`'s values. States that light the same way
    /// share a key: unlit states have one key, and what cannot matter is zeroed (the light
    /// model and light kinds without lights).
    pub fn for_state(state: &LightingState) -> SpecKey {
        let mut values = [0; SPEC_CONSTANT_COUNT];
        if !state.lighting {
            return SpecKey { values };
        }
        let lights: Vec<&Light> = state.enabled_lights().collect();
        let mut set = |c: SpecConstant, on: bool| values[c as usize] = on as i32;
        set(SpecConstant::Lighting, true);
        set(SpecConstant::TwoSide, state.model.two_side);
        set(SpecConstant::ColorMaterial, state.color_material.enabled);
        if !lights.is_empty() {
            set(SpecConstant::LocalViewer, state.model.local_viewer);
            set(
                SpecConstant::SeparateSpecular,
                state.model.color_control == ColorControl::SeparateSpecularColor,
            );
            set(
                SpecConstant::AnyLocalLight,
                lights.iter().any(|l| l.position.w != 0.0),
            );
            set(
                SpecConstant::AnySpotLight,
                lights.iter().any(|l| l.spot_cutoff != 180.0),
            );
        }
        values[SpecConstant::LightCount as usize] = lights.len() as i32;
        SpecKey { values }
    }
}

/// (M⁻¹)ᵀ of the upper 3x3 of the modelview: the matrix normals are transformed by.
pub fn normal_matrix(modelview: Mat4) -> Mat3 {
    Mat3::from_mat4(modelview).inverse().transpose()
}

/// RESCALE_NORMAL's factor 1 / sqrt(m31² + m32² + m33²), from the third row of M⁻¹.
pub fn rescale_factor(modelview: Mat4) -> f32 {
    let inv = Mat3::from_mat4(modelview).inverse();
    1.0 / inv.row(2).length()
}

impl DrawBlock {
    /// Packs one draw's state. `projection` is GL's; the Vulkan clip conversion is applied here.
    pub fn new(state: &LightingState, modelview: Mat4, projection: Mat4) -> Result<Self, StateError> {
        state.validate()?;
        if state.lighting {
            // Normals need (M⁻¹)ᵀ; a singular modelview would light with NaN normals.
            let det = Mat3::from_mat4(modelview).determinant();
            if det == 0.0 || !det.is_finite() {
                return Err(StateError::OutOfRange {
                    parameter: "determinant of the modelview's upper 3x3",
                    value: det,
                    valid: "a finite non-zero value (an invertible modelview, for the normal matrix)",
                });
            }
            // att_i = 1 / (k0 + k1 d + k2 d²) is infinite when all three are 0.
            for l in state.enabled_lights().filter(|l| l.position.w != 0.0) {
                let sum = l.constant_attenuation + l.linear_attenuation + l.quadratic_attenuation;
                if sum == 0.0 {
                    return Err(StateError::OutOfRange {
                        parameter:
                            "GL_CONSTANT_ATTENUATION + GL_LINEAR_ATTENUATION + GL_QUADRATIC_ATTENUATION",
                        value: sum,
                        valid: "> 0 for an enabled positional light (else att_i = 1/0)",
                    });
                }
            }
        }
        let mut lights = [GpuLight::zeroed(); MAX_LIGHTS];
        let mut light_count = 0;
        for (slot, light) in lights.iter_mut().zip(state.enabled_lights()) {
            *slot = GpuLight::from(light);
            light_count += 1;
        }
        let cm = &state.color_material;
        Ok(DrawBlock {
            modelview: modelview.to_cols_array(),
            projection: (VK_FROM_GL_CLIP * projection).to_cols_array(),
            normal_matrix: Mat4::from_mat3(normal_matrix(modelview)).to_cols_array(),
            front: GpuMaterial::from(&state.front),
            back: GpuMaterial::from(&state.back),
            a_cs: state.model.ambient.to_array(),
            light_count,
            lighting: state.lighting as u32,
            v_bs: state.model.local_viewer as u32,
            t_bs: state.model.two_side as u32,
            separate_specular: (state.model.color_control == ColorControl::SeparateSpecularColor) as u32,
            color_material: cm.enabled as u32,
            color_material_front: cm.face.includes_front() as u32,
            color_material_back: cm.face.includes_back() as u32,
            color_material_mode: match cm.mode {
                ColorMaterialMode::Emission => 0,
                ColorMaterialMode::Ambient => 1,
                ColorMaterialMode::Diffuse => 2,
                ColorMaterialMode::Specular => 3,
                ColorMaterialMode::AmbientAndDiffuse => 4,
            },
            normalize: state.normalize as u32,
            rescale: if state.rescale_normal {
                rescale_factor(modelview)
            } else {
                1.0
            },
            _pad: 0,
            lights,
        })
    }
}

use bytemuck::Zeroable as _;
