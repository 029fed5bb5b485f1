//! The GPU layout of GL state: std140 mirrors of `glsl/draw.glsl`'s `Draw` block.
//! Field names are the GLSL member names; a test compares their offsets with the ones
//! glslang wrote into the SPIR-V.

#![allow(non_snake_case)]

use glam::{Mat3, Mat4};

use crate::gl::state::{
    Attenuation, ColorControl, ColorMaterialMode, Light, LightingState, Material, SpecularModel, SpotEdge,
    StateError, MAX_LIGHTS,
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

/// One face's [`Material`] as the GLSL `Material` struct (std140, 80 bytes).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMaterial {
    /// `GL_AMBIENT`, RGBA.
    pub a_cm: [f32; 4],
    /// `GL_DIFFUSE`, RGBA; its alpha is the lit alpha.
    pub d_cm: [f32; 4],
    /// `GL_SPECULAR`, RGBA.
    pub s_cm: [f32; 4],
    /// `GL_EMISSION`, RGBA.
    pub e_cm: [f32; 4],
    /// `GL_SHININESS`, in [0, 128].
    pub s_rm: f32,
    /// Rounds the struct up to std140's 16-byte struct alignment; always zero.
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

/// One enabled [`Light`] as the GLSL `Light` struct (std140, 128 bytes), eye space.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuLight {
    /// `GL_AMBIENT`, RGBA (the shader uses RGB).
    pub a_cli: [f32; 4],
    /// `GL_DIFFUSE`, RGBA (the shader uses RGB).
    pub d_cli: [f32; 4],
    /// `GL_SPECULAR`, RGBA (the shader uses RGB).
    pub s_cli: [f32; 4],
    /// `GL_POSITION`, homogeneous, eye space; w = 0 for a directional light.
    pub P_pli: [f32; 4],
    /// `GL_SPOT_DIRECTION`, eye space, as stored (the shader normalizes it).
    pub s_dli: [f32; 3],
    /// `GL_SPOT_EXPONENT`, in [0, 128]; packed into the 4th component of `s_dli`'s slot.
    pub s_rli: f32,
    /// `GL_SPOT_CUTOFF` in degrees; exactly 180 means no spot cone.
    pub c_rli: f32,
    /// cos(c_rli) from [`crate::reference::cos_cutoff`] (double precision, exactly 0 at
    /// 90°), so the GPU tests the cone against the same threshold as the CPU reference.
    pub cos_c_rli: f32,
    /// `GL_CONSTANT_ATTENUATION`.
    pub k0: f32,
    /// `GL_LINEAR_ATTENUATION`.
    pub k1: f32,
    /// `GL_QUADRATIC_ATTENUATION`.
    pub k2: f32,
    /// The spot edge, the GLSL `EDGE_*` values: 0 GL's exponent, 1 linear, 2 smoothstep.
    pub spot_edge: u32,
    /// cos of the soft edge's inner angle (double precision, as `cos_c_rli`); 1 for GL's
    /// edge.
    pub cos_inner: f32,
    /// The distance falloff, the GLSL `FALLOFF_*` values: 0 GL's k0, k1, k2; 1 glTF's
    /// inverse square.
    pub falloff: u32,
    /// glTF's range, > 0; 0 for none.
    pub range: f32,
    /// Rounds the struct up to std140's 16-byte struct alignment; always zero.
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
            spot_edge: spot_edge_code(l.spot_edge),
            cos_inner: l
                .spot_edge
                .inner_degrees()
                .map_or(1.0, |inner| crate::reference::cos_cutoff(inner) as f32),
            falloff: falloff_code(l.attenuation),
            range: match l.attenuation {
                Attenuation::GltfInverseSquare { range: Some(r) } => r,
                _ => 0.0,
            },
            _pad: [0.0; 3],
        }
    }
}

/// The GLSL `EDGE_*` value of a spot edge.
pub fn spot_edge_code(edge: SpotEdge) -> u32 {
    match edge {
        SpotEdge::GlExponent => 0,
        SpotEdge::LinearInnerOuter { .. } => 1,
        SpotEdge::SmoothstepInnerOuter { .. } => 2,
    }
}

/// The GLSL `FALLOFF_*` value of an attenuation.
pub fn falloff_code(a: Attenuation) -> u32 {
    match a {
        Attenuation::GlK012 => 0,
        Attenuation::GltfInverseSquare { .. } => 1,
    }
}

/// The GLSL `SPECULAR_*` value of a specular model.
pub fn specular_code(m: SpecularModel) -> u32 {
    match m {
        SpecularModel::BlinnHalfway => 0,
        SpecularModel::PhongReflect => 1,
    }
}

/// The `Draw` uniform block: one per draw, bound at a dynamic offset. Matrices are
/// column-major; the `u32` flags are 0 or 1.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct DrawBlock {
    /// M: object to eye space.
    pub modelview: [f32; 16],
    /// GL's projection premultiplied by [`VK_FROM_GL_CLIP`].
    pub projection: [f32; 16],
    /// [`normal_matrix`] of the modelview in the upper 3x3 of a mat4 (the shader reads only
    /// that part).
    pub normal_matrix: [f32; 16],
    /// The front material.
    pub front: GpuMaterial,
    /// The back material (read only when `t_bs` is 1).
    pub back: GpuMaterial,
    /// `GL_LIGHT_MODEL_AMBIENT`, RGBA.
    pub a_cs: [f32; 4],
    /// GL's current color (`glColor`), RGBA: the vertex color of the variants compiled for
    /// meshes without a color array.
    pub current_color: [f32; 4],
    /// How many entries of `lights` are in use: the enabled lights, 0..=[`MAX_LIGHTS`].
    pub light_count: u32,
    /// `GL_LIGHTING`.
    pub lighting: u32,
    /// `GL_LIGHT_MODEL_LOCAL_VIEWER`.
    pub v_bs: u32,
    /// `GL_LIGHT_MODEL_TWO_SIDE`.
    pub t_bs: u32,
    /// 1 when `GL_LIGHT_MODEL_COLOR_CONTROL` is `GL_SEPARATE_SPECULAR_COLOR`.
    pub separate_specular: u32,
    /// `GL_COLOR_MATERIAL`.
    pub color_material: u32,
    /// 1 when glColorMaterial's face includes `GL_FRONT`.
    pub color_material_front: u32,
    /// 1 when glColorMaterial's face includes `GL_BACK`.
    pub color_material_back: u32,
    /// glColorMaterial's mode as the GLSL `CM_*` values: 0 `GL_EMISSION`, 1 `GL_AMBIENT`,
    /// 2 `GL_DIFFUSE`, 3 `GL_SPECULAR`, 4 `GL_AMBIENT_AND_DIFFUSE`.
    pub color_material_mode: u32,
    /// `GL_NORMALIZE`.
    pub normalize: u32,
    /// What eye-space normals are multiplied by: [`rescale_factor`] with
    /// `GL_RESCALE_NORMAL` on, else 1.
    pub rescale: f32,
    /// The specular term, the GLSL `SPECULAR_*` values: 0 GL's (Blinn's halfway vector),
    /// 1 Phong's reflection vector. (It also starts `lights` on a 16-byte boundary.)
    pub specular_model: u32,
    /// The enabled lights packed in index order, so entry i is not necessarily `GL_LIGHTi`;
    /// entries from `light_count` on are zeroed.
    pub lights: [GpuLight; MAX_LIGHTS],
    /// The `GL_TEXTURE` matrix, column-major (read by the textured variants).
    pub texture_matrix: [f32; 16],
    /// `GL_TEXTURE_ENV_COLOR`, RGBA in [0, 1].
    pub c_c: [f32; 4],
    /// `GL_TEXTURE_ENV_MODE` as [`TexEnvMode::code`](crate::gl::texture::TexEnvMode::code).
    pub tex_env_mode: u32,
    /// Rounds the block up to 16 bytes; always zero.
    pub _pad_end: [u32; 3],
}

/// The specialization constants of `glsl/draw.glsl`, by `constant_id`. Each is an `int`
/// whose default, -1, makes the shader read the uniform instead (the uber-shader).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u32)]
#[non_exhaustive]
pub enum SpecConstant {
    /// `SPEC_LIGHT_COUNT`: the number of enabled lights, 0..=[`MAX_LIGHTS`]; a constant
    /// count lets the light loop unroll.
    LightCount = 0,
    /// `SPEC_LIGHTING`: `GL_LIGHTING`, 0 or 1.
    Lighting = 1,
    /// `SPEC_LOCAL_VIEWER`: `GL_LIGHT_MODEL_LOCAL_VIEWER`, 0 or 1.
    LocalViewer = 2,
    /// `SPEC_TWO_SIDE`: `GL_LIGHT_MODEL_TWO_SIDE`, 0 or 1.
    TwoSide = 3,
    /// `SPEC_SEPARATE_SPECULAR`: 1 for `GL_SEPARATE_SPECULAR_COLOR`, 0 for `GL_SINGLE_COLOR`.
    SeparateSpecular = 4,
    /// `SPEC_COLOR_MATERIAL`: `GL_COLOR_MATERIAL`, 0 or 1.
    ColorMaterial = 5,
    /// `SPEC_ANY_LOCAL_LIGHT`: 0 promises that no enabled light is positional (w ≠ 0), so
    /// the shader skips attenuation; 1 means some may be.
    AnyLocalLight = 6,
    /// `SPEC_ANY_SPOT_LIGHT`: 0 promises that no enabled light is a spot (cutoff ≠ 180), so
    /// the shader skips the cone; 1 means some may be.
    AnySpotLight = 7,
    /// `SPEC_TEX_ENV`: `GL_TEXTURE_ENV_MODE` as
    /// [`TexEnvMode::code`](crate::gl::texture::TexEnvMode::code); read only by the textured
    /// variants.
    TexEnv = 8,
    /// `SPEC_SPECULAR_MODEL`: the specular term as [`specular_code`].
    SpecularModel = 9,
    /// `SPEC_ANY_SOFT_SPOT`: 0 promises that every enabled light has GL's spot edge, so the
    /// soft edges are compiled out; 1 means some light may have another.
    AnySoftSpot = 10,
    /// `SPEC_ANY_GLTF_FALLOFF`: 0 promises that every enabled light has GL's attenuation,
    /// so glTF's falloff is compiled out; 1 means some light may have it.
    AnyGltfFalloff = 11,
}

/// How many specialization constants there are.
pub const SPEC_CONSTANT_COUNT: usize = 12;

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
        SpecConstant::TexEnv,
        SpecConstant::SpecularModel,
        SpecConstant::AnySoftSpot,
        SpecConstant::AnyGltfFalloff,
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
            SpecConstant::TexEnv => "SPEC_TEX_ENV",
            SpecConstant::SpecularModel => "SPEC_SPECULAR_MODEL",
            SpecConstant::AnySoftSpot => "SPEC_ANY_SOFT_SPOT",
            SpecConstant::AnyGltfFalloff => "SPEC_ANY_GLTF_FALLOFF",
        }
    }
}

/// The values of every specialization constant for one pipeline, indexed by `constant_id`;
/// -1 leaves the state to the uniform. The bytes are the `VkSpecializationInfo` data.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, bytemuck::Pod, bytemuck::Zeroable)]
#[non_exhaustive]
pub struct SpecKey {
    /// Entry `constant_id`: -1 (read the uniform), or the value the constant is fixed to.
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
    /// model and light kinds without lights). The environment mode counts only while
    /// `GL_TEXTURE_2D` is enabled.
    pub fn for_state(state: &LightingState) -> SpecKey {
        let mut values = [0; SPEC_CONSTANT_COUNT];
        if state.texture.enabled {
            values[SpecConstant::TexEnv as usize] = state.texture.env_mode.code() as i32;
        }
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
            set(
                SpecConstant::AnySoftSpot,
                lights
                    .iter()
                    .any(|l| l.spot_cutoff != 180.0 && l.spot_edge != SpotEdge::GlExponent),
            );
            set(
                SpecConstant::AnyGltfFalloff,
                lights
                    .iter()
                    .any(|l| l.position.w != 0.0 && l.attenuation != Attenuation::GlK012),
            );
            values[SpecConstant::SpecularModel as usize] = specular_code(state.model.specular_model) as i32;
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

/// att_i = 1 / (k0 + k1 d + k2 d²) is infinite when all three are 0: refused for an enabled
/// positional light with GL's attenuation (drawn with lighting on).
fn check_attenuation_sums(lights: &[Light; MAX_LIGHTS]) -> Result<(), StateError> {
    for l in lights
        .iter()
        .filter(|l| l.enabled && l.position.w != 0.0 && l.attenuation == Attenuation::GlK012)
    {
        let sum = l.constant_attenuation + l.linear_attenuation + l.quadratic_attenuation;
        if sum == 0.0 {
            return Err(StateError::OutOfRange {
                parameter: "GL_CONSTANT_ATTENUATION + GL_LINEAR_ATTENUATION + GL_QUADRATIC_ATTENUATION",
                value: sum,
                valid: "> 0 for an enabled positional light (else att_i = 1/0)",
            });
        }
    }
    Ok(())
}

/// The last lights a [`DrawBlock`] was packed from, checked, and their packed form: draws
/// under unchanged lights (materials and matrices change per draw in a GL program; lights
/// rarely do) copy them instead of checking sixteen lights and computing their cone cosines
/// again. Lights that fail their checks are not kept, so they fail every draw.
#[derive(Debug, Clone, Default)]
pub(crate) struct LightCache {
    last: Option<([Light; MAX_LIGHTS], [GpuLight; MAX_LIGHTS], u32)>,
}

impl LightCache {
    /// The enabled lights of `lights` packed in index order, and how many there are.
    fn packed(&mut self, lights: &[Light; MAX_LIGHTS]) -> Result<([GpuLight; MAX_LIGHTS], u32), StateError> {
        if let Some((source, packed, count)) = &self.last {
            if source == lights {
                return Ok((*packed, *count));
            }
        }
        let (packed, count) = pack_lights(lights)?;
        self.last = Some((*lights, packed, count));
        Ok((packed, count))
    }
}

/// Checks `lights` and packs the enabled ones in index order; returns them and their count.
fn pack_lights(lights: &[Light; MAX_LIGHTS]) -> Result<([GpuLight; MAX_LIGHTS], u32), StateError> {
    crate::gl::state::validate_lights(lights)?;
    let mut packed = [GpuLight::zeroed(); MAX_LIGHTS];
    let mut count = 0;
    for (slot, light) in packed.iter_mut().zip(lights.iter().filter(|l| l.enabled)) {
        *slot = GpuLight::from(light);
        count += 1;
    }
    Ok((packed, count))
}

impl DrawBlock {
    /// Packs one draw's state. `projection` is GL's; the Vulkan clip conversion is applied here.
    pub fn new(state: &LightingState, modelview: Mat4, projection: Mat4) -> Result<Self, StateError> {
        Self::assemble(state, modelview, projection, pack_lights)
    }

    /// [`DrawBlock::new`] with the lights checked and packed through `cache`: a draw under
    /// the same lights as the one before (GL's rhythm: materials and matrices change per draw,
    /// lights between frames) copies them instead.
    pub(crate) fn new_cached(
        state: &LightingState,
        modelview: Mat4,
        projection: Mat4,
        cache: &mut LightCache,
    ) -> Result<Self, StateError> {
        Self::assemble(state, modelview, projection, |lights| cache.packed(lights))
    }

    /// Checks and packs one draw's state, its lights through `pack` (after the rest is checked,
    /// so errors come in the order of [`LightingState::validate`]).
    fn assemble(
        state: &LightingState,
        modelview: Mat4,
        projection: Mat4,
        pack: impl FnOnce(&[Light; MAX_LIGHTS]) -> Result<([GpuLight; MAX_LIGHTS], u32), StateError>,
    ) -> Result<Self, StateError> {
        state.validate_all_but_lights()?;
        let (lights, light_count) = pack(&state.lights)?;
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
            check_attenuation_sums(&state.lights)?;
        }
        let cm = &state.color_material;
        Ok(DrawBlock {
            modelview: modelview.to_cols_array(),
            projection: (VK_FROM_GL_CLIP * projection).to_cols_array(),
            normal_matrix: Mat4::from_mat3(normal_matrix(modelview)).to_cols_array(),
            front: GpuMaterial::from(&state.front),
            back: GpuMaterial::from(&state.back),
            a_cs: state.model.ambient.to_array(),
            current_color: state.current_color.to_array(),
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
            specular_model: specular_code(state.model.specular_model),
            lights,
            texture_matrix: state.texture.matrix.to_cols_array(),
            c_c: state.texture.env_color.to_array(),
            tex_env_mode: state.texture.env_mode.code(),
            _pad_end: [0; 3],
        })
    }
}

use bytemuck::Zeroable as _;

#[cfg(test)]
mod tests {
    use glam::{Mat4, Vec3, Vec4};

    use super::*;
    use crate::gl::state::{Cap, Face, GlState, LightParam, MaterialParam};

    fn lit() -> GlState {
        let mut gl = GlState::new();
        gl.enable(Cap::Lighting).unwrap();
        gl.enable(Cap::Light(0)).unwrap();
        gl.enable(Cap::Light(1)).unwrap();
        gl.light(1, LightParam::Position(Vec4::new(1.0, 2.0, 3.0, 1.0)))
            .unwrap();
        gl.light(1, LightParam::SpotCutoff(30.0)).unwrap();
        gl
    }

    #[test]
    fn draws_packed_through_the_light_cache_equal_draws_packed_alone() {
        let mut cache = LightCache::default();
        let mut gl = lit();
        let mv = Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0));
        for i in 0..4 {
            // A new material every draw, new lights every other draw.
            gl.material(Face::FrontAndBack, MaterialParam::Shininess(10.0 * i as f32))
                .unwrap();
            if i % 2 == 1 {
                gl.light(0, LightParam::Position(Vec4::new(i as f32, 1.0, 1.0, 0.0)))
                    .unwrap();
            }
            let cached = DrawBlock::new_cached(&gl.lighting, mv, Mat4::IDENTITY, &mut cache).unwrap();
            let alone = DrawBlock::new(&gl.lighting, mv, Mat4::IDENTITY).unwrap();
            assert_eq!(cached, alone, "draw {i}");
        }
    }

    #[test]
    fn lights_that_fail_their_checks_fail_every_draw_through_the_cache() {
        let mut cache = LightCache::default();
        let good = lit();
        DrawBlock::new_cached(&good.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &mut cache).unwrap();
        let mut bad = good.lighting;
        bad.lights[1].constant_attenuation = 0.0;
        bad.lights[1].spot_exponent = f32::NAN;
        for _ in 0..2 {
            assert!(DrawBlock::new_cached(&bad, Mat4::IDENTITY, Mat4::IDENTITY, &mut cache).is_err());
        }
        // And the good lights still pack after them.
        let again =
            DrawBlock::new_cached(&good.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &mut cache).unwrap();
        assert_eq!(
            again,
            DrawBlock::new(&good.lighting, Mat4::IDENTITY, Mat4::IDENTITY).unwrap()
        );
    }
}
