//! The GPU layout of GL state: the std140 mirror of `glsl/draw.glsl`'s `State` block and the
//! per-draw record `glsl/record.glsl` reads as vertex attributes. Field names are the GLSL
//! member names; tests compare their offsets and locations with the ones glslang wrote into
//! the SPIR-V.

#![allow(non_snake_case)]

use glam::{Mat3, Mat4};

mod key;
mod spec;
pub(crate) use key::{same_block_state, StateKey};
pub use spec::{SpecConstant, SpecKey, SPEC_CONSTANT_COUNT};

use crate::gl::state::{
    Attenuation, ColorControl, ColorMaterialMode, DrawValues, FixedFunctionState, FogSource, Light, Material,
    SpecularModel, SpotEdge, StateError, MAX_CLIP_PLANES, MAX_LIGHTS,
};
use crate::gl::texture::{TextureUnit, MAX_TEXTURE_UNITS};

/// GL clip space (z in [-w, w], y up) to Vulkan clip space (z in [0, w], y down), applied
/// after the GL projection so the image's top row is the top of the view, as on a GL screen.
/// The y flip mirrors window-space winding, which the pipeline's front face accounts for.
pub const VK_FROM_GL_CLIP: Mat4 = Mat4::from_cols_array(&[
    1.0, 0.0, 0.0, 0.0, //
    0.0, -1.0, 0.0, 0.0, //
    0.0, 0.0, 0.5, 0.0, //
    0.0, 0.0, 0.5, 1.0,
]);

/// One enabled [`Light`] as the GLSL `Light` struct (std140, 160 bytes), eye space.
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
    /// cos(c_rli) from [`crate::gl::state::cos_cutoff`] (double precision, exactly 0 at
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
    /// Fills the 16-byte slot of `range` (std140 starts a `vec3` on 16 bytes); always zero.
    pub _pad: [f32; 3],
    /// For a directional light (w = 0): the unit vector toward it, VP_pli of every finite
    /// vertex. GL's derived state, computed here when the state changes (in double precision,
    /// rounded once) so the vertex stage does not normalize it per vertex; zero for a
    /// positional light.
    pub VP_hat_inf: [f32; 3],
    /// Always zero.
    pub _pad_VP: f32,
    /// For a directional light: the unit halfway vector ĥ_i of `VP_hat_inf` and the infinite
    /// viewer's (0, 0, 1), GLSL 1.20's `gl_LightSource[i].halfVector`; zero for a positional
    /// light.
    pub h_hat_inf: [f32; 3],
    /// Rounds the struct up to std140's 16-byte struct alignment; always zero.
    pub _pad_h: f32,
}

/// For a directional light at `position` (w = 0): the unit vector toward it and the unit
/// halfway vector of it and (0, 0, 1), in double precision and rounded once; zero vectors for
/// a positional light (or a zero direction).
fn directional_derived(position: glam::Vec4) -> ([f32; 3], [f32; 3]) {
    if position.w != 0.0 {
        return ([0.0; 3], [0.0; 3]);
    }
    let unit = |v: glam::DVec3| {
        let len = v.length();
        if len > 0.0 {
            v / len
        } else {
            glam::DVec3::ZERO
        }
    };
    let VP = unit(position.truncate().as_dvec3());
    let h = unit(VP + glam::DVec3::Z);
    (VP.as_vec3().to_array(), h.as_vec3().to_array())
}

impl From<&Light> for GpuLight {
    fn from(l: &Light) -> Self {
        let (VP_hat_inf, h_hat_inf) = directional_derived(l.position);
        GpuLight {
            a_cli: l.ambient.to_array(),
            d_cli: l.diffuse.to_array(),
            s_cli: l.specular.to_array(),
            P_pli: l.position.to_array(),
            s_dli: l.spot_direction.to_array(),
            s_rli: l.spot_exponent,
            c_rli: l.spot_cutoff,
            // The same cosine as the CPU reference: double precision, exactly 0 at 90°.
            cos_c_rli: crate::gl::state::cos_cutoff(l.spot_cutoff) as f32,
            k0: l.constant_attenuation,
            k1: l.linear_attenuation,
            k2: l.quadratic_attenuation,
            spot_edge: spot_edge_code(l.spot_edge),
            cos_inner: l
                .spot_edge
                .inner_degrees()
                .map_or(1.0, |inner| crate::gl::state::cos_cutoff(inner) as f32),
            falloff: falloff_code(l.attenuation),
            range: match l.attenuation {
                Attenuation::GltfInverseSquare { range: Some(r) } => r,
                _ => 0.0,
            },
            _pad: [0.0; 3],
            VP_hat_inf,
            _pad_VP: 0.0,
            h_hat_inf,
            _pad_h: 0.0,
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

/// The `State` uniform block: GL's lighting state but the draw's own values (those are its
/// [`DrawRecord`]), written when a draw's state differs from the draw before and bound at a
/// dynamic offset. Matrices are column-major; the `u32` flags are 0 or 1.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct StateBlock {
    /// GL's projection premultiplied by [`VK_FROM_GL_CLIP`].
    pub projection: [f32; 16],
    /// `GL_LIGHT_MODEL_AMBIENT`, RGBA.
    pub a_cs: [f32; 4],
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
    /// The specular term, the GLSL `SPECULAR_*` values: 0 GL's (Blinn's halfway vector),
    /// 1 Phong's reflection vector.
    pub specular_model: u32,
    /// `GL_COLOR_SUM` (read by the uber-shader with lighting off).
    pub color_sum: u32,
    /// The alpha test's function as [`CompareFunc::code`](crate::gl::state::CompareFunc::code),
    /// `GL_ALWAYS` (7) while the test is off.
    pub alpha_func: u32,
    /// `GL_ALPHA_TEST_REF`, in [0, 1].
    pub alpha_ref: f32,
    /// Unused: keeps `fog_color` on a 16-byte boundary.
    pub pad_0: u32,
    /// Unused.
    pub pad_1: u32,
    /// `GL_FOG_COLOR`, RGBA in [0, 1].
    pub fog_color: [f32; 4],
    /// `GL_FOG_START`.
    pub fog_start: f32,
    /// `GL_FOG_END`.
    pub fog_end: f32,
    /// `GL_FOG_DENSITY`.
    pub fog_density: f32,
    /// 1 / (end − start) for `GL_LINEAR`, 0 where end = start (f is then 1: GL leaves it
    /// undefined).
    pub fog_scale: f32,
    /// The fog's mode as [`Fog::mode_code`](crate::gl::state::Fog::mode_code): 0 off.
    pub fog_mode: u32,
    /// 1 for `GL_FOG_COORD_SRC` `GL_FOG_COORD`, 0 for `GL_FRAGMENT_DEPTH`.
    pub fog_source: u32,
    /// 1 for `GL_FOG_HINT` `GL_FASTEST` (f per vertex).
    pub fog_per_vertex: u32,
    /// The enabled user clip planes, a bit each ([`ClipPlanes::mask`](crate::gl::state::ClipPlanes::mask)).
    pub clip_mask: u32,
    /// The user clip planes in eye space (`glClipPlane`, §2.12).
    pub clip_planes: [[f32; 4]; MAX_CLIP_PLANES],
    /// The texture units, `GL_TEXTURE0` onwards (read by the textured variants for the units
    /// they sample).
    pub units: [GpuTextureUnit; MAX_TEXTURE_UNITS],
    /// The enabled lights packed in index order, so entry i is not necessarily `GL_LIGHTi`;
    /// entries from `light_count` on are zeroed.
    pub lights: [GpuLight; MAX_LIGHTS],
}

/// One texture unit's state as the shaders read it (`TextureUnitState` in `glsl/draw.glsl`),
/// 160 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuTextureUnit {
    /// The unit's `GL_TEXTURE` matrix, column-major.
    pub matrix: [f32; 16],
    /// `GL_TEXTURE_ENV_COLOR`, RGBA in [0, 1].
    pub c_c: [f32; 4],
    /// Each coordinate's plane as its mode reads it: the object plane (`GL_OBJECT_LINEAR`), the
    /// eye plane in eye space (`GL_EYE_LINEAR`), else zero.
    pub texgen_planes: [[f32; 4]; 4],
    /// `GL_TEXTURE_ENV_MODE` as [`TexEnvMode::code`](crate::gl::texture::TexEnvMode::code).
    pub env_mode: u32,
    /// `GL_COMBINE`'s state as [`Combine::code`](crate::gl::texture::Combine::code) (read
    /// under `GL_TEXTURE_ENV_MODE` `GL_COMBINE`).
    pub combine: u32,
    /// `GL_COMBINE`'s `GL_TEXTUREn` sources as
    /// [`Combine::crossbar_code`](crate::gl::texture::Combine::crossbar_code).
    pub crossbar: u32,
    /// Texture coordinate generation while the unit's `GL_TEXTURE_2D` is on
    /// ([`TextureUnit::texgen_code`](crate::gl::texture::TextureUnit::texgen_code)), else 0.
    pub texgen: u32,
}

impl GpuTextureUnit {
    /// `unit` packed.
    pub fn new(unit: &TextureUnit) -> Self {
        GpuTextureUnit {
            matrix: unit.matrix.to_cols_array(),
            c_c: unit.env_color.to_array(),
            texgen_planes: unit.texgen.map(|g| g.plane().to_array()),
            env_mode: unit.env_mode.code(),
            combine: unit.combine.code(),
            crossbar: unit.combine.crossbar_code(),
            texgen: if unit.is_enabled() { unit.texgen_code() } else { 0 },
        }
    }
}

/// One draw's own values, as the vertex stages read them: per-instance vertex attributes at
/// locations 4-20 (`glsl/record.glsl`), one record per draw in ffvk's record buffer, the draw's
/// `firstInstance` naming its record, and the current values a layout without an array for them
/// reads at locations 1-3, 21-25 instead. 352 bytes, 22 `vec4`s; in the buffer, records lie the
/// device's uniform offset alignment apart ([`record_stride`]).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct DrawRecord {
    /// M: object to eye space (locations 4-7, one column each).
    pub modelview: [f32; 16],
    /// [`normal_matrix`] of the modelview, one column per location (8-10), each with a fourth
    /// value: the front material's `GL_SHININESS`, the back's, and what eye-space normals are
    /// multiplied by ([`rescale_factor`] with `GL_RESCALE_NORMAL` on, else 1).
    pub normal_matrix: [[f32; 4]; 3],
    /// The front material's ambient, diffuse, specular and emission, RGBA (locations 11-14).
    pub front: [[f32; 4]; 4],
    /// The back material's, as `front` (locations 15-18; read only when `t_bs` is 1).
    pub back: [[f32; 4]; 4],
    /// GL's current color (`glColor`), RGBA: every vertex's color (location 2) where the
    /// layout has no color array.
    pub current_color: [f32; 4],
    /// GL's current normal (`glNormal`), x y z: every vertex's normal (location 1) where the
    /// layout has no normal array; w: GL's current fog coordinate (`glFogCoord`, location 22
    /// where the layout has no fog coordinate array).
    pub current_normal: [f32; 4],
    /// GL's current texture coordinates (`glTexCoord`), s t r q: every vertex's (location 3)
    /// where a textured draw's layout has no texture coordinate array.
    pub current_texcoord: [f32; 4],
    /// GL's current secondary color (`glSecondaryColor`), RGBA: every vertex's (location 21)
    /// where the layout has no secondary color array.
    pub current_secondary_color: [f32; 4],
    /// GL's current texture coordinates of units 1-3 (`glMultiTexCoord`): every vertex's
    /// (locations 23-25) where a draw sampling the unit has no texture coordinate array for it.
    pub current_unit_texcoords: [[f32; 4]; MAX_TEXTURE_UNITS - 1],
}

/// The first vertex-attribute location of a [`DrawRecord`].
pub const RECORD_FIRST_LOCATION: u32 = 4;
/// How many vertex-attribute locations the record's per-draw values take: the modelview,
/// normal matrix and materials (4-18, a `vec4` each) and the two shininesses (19, 20).
pub const RECORD_LOCATIONS: u32 = 17;

/// Bytes from one [`DrawRecord`] to the next in ffvk's record buffer on a device whose
/// `minUniformBufferOffsetAlignment` is `alignment`: the record's size rounded up to it (the
/// fragment mode binds a record as a uniform block at its own dynamic offset).
pub fn record_stride(alignment: u64) -> u64 {
    let align = alignment.max(16);
    (std::mem::size_of::<DrawRecord>() as u64).div_ceil(align) * align
}

/// One draw packed: its GL state's block and its own record. [`DrawBlock::new`] checks
/// everything a draw is checked for.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct DrawBlock {
    /// The state block (shared with every following draw of the same state).
    pub state: StateBlock,
    /// The draw's own record.
    pub record: DrawRecord,
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

/// Packs the enabled lights in index order; returns them and their count.
fn pack_lights(lights: &[Light; MAX_LIGHTS]) -> ([GpuLight; MAX_LIGHTS], u32) {
    let mut packed = [GpuLight::zeroed(); MAX_LIGHTS];
    let mut count = 0;
    for (slot, light) in packed.iter_mut().zip(lights.iter().filter(|l| l.enabled)) {
        *slot = GpuLight::from(light);
        count += 1;
    }
    (packed, count)
}

impl StateBlock {
    /// Checks and packs the state part of a draw of `state` under GL's `projection` (the
    /// Vulkan clip conversion is applied here): the light model, the lights (and, lighting,
    /// that no enabled positional light has all-zero attenuation), the texture unit.
    pub fn new(state: &FixedFunctionState, projection: Mat4) -> Self {
        let (lights, light_count) = pack_lights(&state.lights);
        let cm = &state.color_material;
        let fog = &state.fragment.fog;
        StateBlock {
            projection: (VK_FROM_GL_CLIP * projection).to_cols_array(),
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
            specular_model: specular_code(state.model.specular_model),
            color_sum: state.fragment.color_sum as u32,
            alpha_func: state.fragment.alpha_test.effective_func().code(),
            alpha_ref: state.fragment.alpha_test.reference,
            pad_0: 0,
            pad_1: 0,
            fog_color: fog.color.to_array(),
            fog_start: fog.start,
            fog_end: fog.end,
            fog_density: fog.density,
            fog_scale: if fog.end == fog.start {
                0.0
            } else {
                1.0 / (fog.end - fog.start)
            },
            fog_mode: fog.mode_code(),
            fog_source: (fog.source == FogSource::FogCoord) as u32,
            fog_per_vertex: fog.hint.per_vertex() as u32,
            clip_mask: state.clip.mask(),
            clip_planes: state.clip.planes.map(|p| p.to_array()),
            units: state.texture_units.each_ref().map(GpuTextureUnit::new),
            lights,
        }
    }
}

impl DrawRecord {
    /// Checks and packs a draw's own values: the materials and current color of `state` and
    /// the `modelview` (invertible, while lighting: normals need (M⁻¹)ᵀ).
    pub fn new(state: &FixedFunctionState, modelview: Mat4) -> Self {
        Self::with_values(state, &DrawValues::of(state), modelview)
    }

    /// [`DrawRecord::new`] with the draw's own materials and current values given apart
    /// from `state`, whose switches (`GL_LIGHTING`, `GL_RESCALE_NORMAL`) still apply.
    pub fn with_values(state: &FixedFunctionState, values: &DrawValues, modelview: Mat4) -> Self {
        let (front, back) = (&values.front, &values.back);
        let n = normal_matrix(modelview);
        let rescale = if state.rescale_normal {
            rescale_factor(modelview)
        } else {
            1.0
        };
        let with_w = |column: glam::Vec3, w: f32| [column.x, column.y, column.z, w];
        let face = |m: &Material| {
            [
                m.ambient.to_array(),
                m.diffuse.to_array(),
                m.specular.to_array(),
                m.emission.to_array(),
            ]
        };
        DrawRecord {
            modelview: modelview.to_cols_array(),
            normal_matrix: [
                with_w(n.x_axis, front.shininess),
                with_w(n.y_axis, back.shininess),
                with_w(n.z_axis, rescale),
            ],
            front: face(front),
            back: face(back),
            current_color: values.current_color.to_array(),
            current_normal: values.current_normal.extend(values.current_fog_coord).to_array(),
            current_texcoord: values.current_texcoords[0].to_array(),
            current_secondary_color: values.current_secondary_color.to_array(),
            current_unit_texcoords: [1, 2, 3].map(|i| values.current_texcoords[i].to_array()),
        }
    }
}

impl DrawBlock {
    /// Checks one draw as drawing does ([`FixedFunctionState::check_drawable`] and
    /// [`FixedFunctionState::check_draw`]) and packs it: its [`DrawRecord`] and [`StateBlock`].
    /// `projection` is GL's; the Vulkan clip conversion is applied here.
    pub fn new(state: &FixedFunctionState, modelview: Mat4, projection: Mat4) -> Result<Self, StateError> {
        state.check_drawable()?;
        state.check_draw(&DrawValues::of(state), modelview)?;
        Ok(DrawBlock {
            state: StateBlock::new(state, projection),
            record: DrawRecord::new(state, modelview),
        })
    }
}

use bytemuck::Zeroable as _;

#[cfg(test)]
mod tests {
    use glam::{Mat4, Vec3, Vec4};

    use super::*;
    use crate::gl::state::{Cap, Face, GlState, LightParam, MaterialParam};

    #[test]
    fn the_state_key_ignores_what_the_record_carries_and_disabled_lights_and_sees_the_rest() {
        let mut gl = GlState::new();
        gl.enable(Cap::Lighting).unwrap();
        let key = StateKey::new(&gl.lighting, Mat4::IDENTITY);
        gl.material(Face::Back, MaterialParam::Shininess(7.0)).unwrap();
        gl.color(Vec4::new(0.5, 0.5, 0.5, 1.0)).unwrap();
        gl.enable(Cap::RescaleNormal).unwrap();
        assert_eq!(StateKey::new(&gl.lighting, Mat4::IDENTITY), key);
        assert_ne!(StateKey::new(&gl.lighting, Mat4::from_translation(Vec3::X)), key);
        // The block packs the enabled lights only: a disabled light's values do not split it,
        // its enable and an enabled light's values do.
        gl.light(3, LightParam::Diffuse(Vec4::ONE)).unwrap();
        assert_eq!(
            StateKey::new(&gl.lighting, Mat4::IDENTITY),
            key,
            "a disabled light's values"
        );
        assert!(key.matches(&gl.lighting, Mat4::IDENTITY));
        gl.enable(Cap::Light(3)).unwrap();
        let with_light = StateKey::new(&gl.lighting, Mat4::IDENTITY);
        assert_ne!(with_light, key, "a light's enable");
        assert!(!key.matches(&gl.lighting, Mat4::IDENTITY));
        gl.light(3, LightParam::Diffuse(Vec4::splat(0.5))).unwrap();
        assert_ne!(
            StateKey::new(&gl.lighting, Mat4::IDENTITY),
            with_light,
            "an enabled light's values"
        );
        assert!(!with_light.matches(&gl.lighting, Mat4::IDENTITY));
    }

    #[test]
    fn the_record_carries_both_shininesses_and_the_rescale_factor_in_the_normal_columns() {
        let mut gl = GlState::new();
        gl.enable(Cap::Lighting).unwrap();
        gl.enable(Cap::RescaleNormal).unwrap();
        gl.material(Face::Front, MaterialParam::Shininess(5.0)).unwrap();
        gl.material(Face::Back, MaterialParam::Shininess(9.0)).unwrap();
        let mv = Mat4::from_scale(Vec3::splat(2.0));
        let r = DrawRecord::new(&gl.lighting, mv);
        assert_eq!([r.normal_matrix[0][3], r.normal_matrix[1][3]], [5.0, 9.0]);
        // (M⁻¹)ᵀ of 2I is I/2, and RESCALE_NORMAL's factor brings its normals back to length 1.
        assert_eq!(r.normal_matrix[0][0], 0.5);
        assert_eq!(r.normal_matrix[2][3], 2.0);
        assert_eq!(RECORD_LOCATIONS, 17);
    }
}
