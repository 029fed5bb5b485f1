//! The specialization constants of `glsl/draw.glsl` ([`SpecConstant`]) and one pipeline's
//! values of them ([`SpecKey`]), derived from the state a draw is lit with.

use glam::Mat4;

use super::specular_code;
use crate::gl::state::{Attenuation, ColorControl, FixedFunctionState, FogSource, Light, SpotEdge};

/// The specialization constants of `glsl/draw.glsl`, by `constant_id`. Each is an `int`
/// whose default, -1, makes the shader read the uniform instead (the uber-shader).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u32)]
#[non_exhaustive]
pub enum SpecConstant {
    /// `SPEC_LIGHT_COUNT`: the number of enabled lights, 0..=[`MAX_LIGHTS`](crate::gl::state::MAX_LIGHTS); a constant
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
    /// `SPEC_FINITE_VERTICES`: 1 promises that every vertex lies at a finite point (w ≠ 0: the
    /// draw's modelview is affine, its last row (0, 0, 0, 1)), so that for every light
    /// [`SpecConstant::DirectionalLights`] names, VP_pli and, for the infinite viewer, ĥ_i are
    /// the light's derived state ([`GpuLight::VP_hat_inf`](super::GpuLight::VP_hat_inf), [`GpuLight::h_hat_inf`](super::GpuLight::h_hat_inf)) at every
    /// vertex; 0 promises nothing. Set per draw ([`SpecKey::for_draw`]).
    FiniteVertices = 12,
    /// `SPEC_POINTS`: 1 for a pipeline drawing points, whose vertex stage writes the point
    /// size (one pixel, GL's default); 0 for other topologies. Set from the draw's topology
    /// when the pipeline is made, not by [`SpecKey::for_state`].
    Points = 13,
    /// `SPEC_POINT_SIZE`: a `float`, the point size a points pipeline writes (GL's
    /// `glPointSize`, [`RasterState::point_size`](crate::draw::pipeline::RasterState::point_size));
    /// its bits are the key's entry, set when the pipeline is made.
    PointSize = 14,
    /// `SPEC_DIRECTIONAL_LIGHTS`: a bit per enabled light in packed order, set where the light
    /// is directional (w = 0): its attenuation is compiled out, and at finite vertices its
    /// VP_pli and ĥ_i are its derived state; a clear bit is a positional light. Each light is
    /// specialized for its own kind, as Mesa's fixed-function key does, rather than every
    /// light for the kinds of all.
    DirectionalLights = 15,
    /// `SPEC_SPOT_LIGHTS`: a bit per enabled light in packed order, set where the light is a
    /// spot (cutoff ≠ 180): the cone is compiled in for those lights only.
    SpotLights = 16,
    /// `SPEC_GL_SNORM`: the vertex layout's signed normalized arrays, converted as GL 2.1 does
    /// ((2c + 1) / (2^b − 1)): a byte per attribute (the normal's, then the color's), holding
    /// b (0: none) and bit 7 when the array has a fourth component. Set from the layout when
    /// the pipeline is made, in every pipeline.
    GlSnorm = 17,
    /// `SPEC_RECORD_VEC4S`: `vec4`s from one draw record to the next in the record buffer
    /// ([`record_stride`](super::record_stride) / 16), for the deferred lighting pass; set in every pipeline.
    RecordVec4s = 18,
    /// `SPEC_COLOR_SUM`: `GL_COLOR_SUM` with lighting off, 0 or 1 (lit draws always sum).
    ColorSum = 19,
    /// `SPEC_ALPHA_FUNC`: the alpha test's function as
    /// [`CompareFunc::code`](crate::gl::state::CompareFunc::code), 7 (`GL_ALWAYS`) while off.
    AlphaFunc = 20,
    /// `SPEC_ALPHA_BITS`: the color attachment's alpha bits when it is UNORM (the alpha test
    /// compares at that fixed-point precision, as GL does), 0 for a float compare; set from the
    /// target in every pipeline.
    AlphaBits = 21,
    /// `SPEC_FOG_MODE`: [`Fog::mode_code`](crate::gl::state::Fog::mode_code), 0 with fog off.
    FogMode = 22,
    /// `SPEC_FOG_SOURCE`: 1 for `GL_FOG_COORD`, 0 for `GL_FRAGMENT_DEPTH` (0 with fog off).
    FogSource = 23,
    /// `SPEC_FOG_PER_VERTEX`: 1 for `GL_FOG_HINT` `GL_FASTEST` (0 with fog off).
    FogPerVertex = 24,
    /// `SPEC_CLIP_PLANES`: the enabled user clip planes, a bit each ([`ClipPlanes::mask`](crate::gl::state::ClipPlanes::mask));
    /// read by the `_clipped` variants, which write `gl_ClipDistance`.
    ClipPlanes = 25,
    /// `SPEC_POINT_ATTENUATION`: 1 where a points pipeline's size falls with the distance
    /// (`GL_POINT_DISTANCE_ATTENUATION` ≠ (1, 0, 0)). This and the point constants after it are
    /// the pipeline's own, like [`SpecConstant::PointSize`]: set when a points pipeline is made
    /// (the uber-shader's too), fixed to their "off" values in every other pipeline.
    PointAttenuation = 26,
    /// `SPEC_POINT_ATTENUATION_A`: a `float`, a of `GL_POINT_DISTANCE_ATTENUATION`.
    PointAttenuationA = 27,
    /// `SPEC_POINT_ATTENUATION_B`: a `float`, b.
    PointAttenuationB = 28,
    /// `SPEC_POINT_ATTENUATION_C`: a `float`, c.
    PointAttenuationC = 29,
    /// `SPEC_POINT_SIZE_MIN`: a `float`, `GL_POINT_SIZE_MIN`.
    PointSizeMin = 30,
    /// `SPEC_POINT_SIZE_MAX`: a `float`, `GL_POINT_SIZE_MAX`.
    PointSizeMax = 31,
    /// `SPEC_POINT_SPRITE`: bit 0 `GL_POINT_SPRITE`, bit 1 `GL_COORD_REPLACE` (of a textured
    /// pipeline), bit 2 `GL_POINT_SPRITE_COORD_ORIGIN` `GL_LOWER_LEFT`.
    PointSprite = 32,
    /// `SPEC_TEXGEN`: texture coordinate generation, each coordinate's
    /// [`TexCoordGen::code`](crate::gl::texture::TexCoordGen::code) in 3 bits from S
    /// ([`TextureUnit::texgen_code`](crate::gl::texture::TextureUnit::texgen_code)); read only
    /// by the textured variants' vertex stages.
    TexGen = 33,
    /// `SPEC_COMBINE`: `GL_COMBINE`'s state as
    /// [`Combine::code`](crate::gl::texture::Combine::code) where the environment mode is
    /// `GL_COMBINE`, else 0; read only by the textured variants' fragment stages.
    Combine = 34,
    /// `SPEC_TEXTURE_UNITS`: the units a textured pipeline samples (bits 0-3) and applies (bits
    /// 4-7), as [`units_applied`](crate::gl::texture::units_applied) finds them; the
    /// pipeline's own, set in every textured pipeline (the uber-shader's too).
    TextureUnits = 35,
    /// `SPEC_CROSSBAR`: unit 0's `GL_TEXTUREn` sources as
    /// [`Combine::crossbar_code`](crate::gl::texture::Combine::crossbar_code) where its mode
    /// is `GL_COMBINE`, else 0.
    Crossbar = 36,
    /// `SPEC_TEX_ENV_1`: unit 1's [`SpecConstant::TexEnv`].
    TexEnv1 = 37,
    /// `SPEC_TEX_ENV_2`: unit 2's.
    TexEnv2 = 38,
    /// `SPEC_TEX_ENV_3`: unit 3's.
    TexEnv3 = 39,
    /// `SPEC_TEXGEN_1`: unit 1's [`SpecConstant::TexGen`].
    TexGen1 = 40,
    /// `SPEC_TEXGEN_2`: unit 2's.
    TexGen2 = 41,
    /// `SPEC_TEXGEN_3`: unit 3's.
    TexGen3 = 42,
    /// `SPEC_COMBINE_1`: unit 1's [`SpecConstant::Combine`].
    Combine1 = 43,
    /// `SPEC_COMBINE_2`: unit 2's.
    Combine2 = 44,
    /// `SPEC_COMBINE_3`: unit 3's.
    Combine3 = 45,
    /// `SPEC_CROSSBAR_1`: unit 1's [`SpecConstant::Crossbar`].
    Crossbar1 = 46,
    /// `SPEC_CROSSBAR_2`: unit 2's.
    Crossbar2 = 47,
    /// `SPEC_CROSSBAR_3`: unit 3's.
    Crossbar3 = 48,
}

/// How many specialization constants there are.
pub const SPEC_CONSTANT_COUNT: usize = 49;

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
        SpecConstant::FiniteVertices,
        SpecConstant::Points,
        SpecConstant::PointSize,
        SpecConstant::DirectionalLights,
        SpecConstant::SpotLights,
        SpecConstant::GlSnorm,
        SpecConstant::RecordVec4s,
        SpecConstant::ColorSum,
        SpecConstant::AlphaFunc,
        SpecConstant::AlphaBits,
        SpecConstant::FogMode,
        SpecConstant::FogSource,
        SpecConstant::FogPerVertex,
        SpecConstant::ClipPlanes,
        SpecConstant::PointAttenuation,
        SpecConstant::PointAttenuationA,
        SpecConstant::PointAttenuationB,
        SpecConstant::PointAttenuationC,
        SpecConstant::PointSizeMin,
        SpecConstant::PointSizeMax,
        SpecConstant::PointSprite,
        SpecConstant::TexGen,
        SpecConstant::Combine,
        SpecConstant::TextureUnits,
        SpecConstant::Crossbar,
        SpecConstant::TexEnv1,
        SpecConstant::TexEnv2,
        SpecConstant::TexEnv3,
        SpecConstant::TexGen1,
        SpecConstant::TexGen2,
        SpecConstant::TexGen3,
        SpecConstant::Combine1,
        SpecConstant::Combine2,
        SpecConstant::Combine3,
        SpecConstant::Crossbar1,
        SpecConstant::Crossbar2,
        SpecConstant::Crossbar3,
    ];

    /// Unit `unit`'s `GL_TEXTURE_ENV_MODE`, texgen, `GL_COMBINE` and crossbar constants.
    pub fn of_unit(unit: usize) -> [SpecConstant; 4] {
        use SpecConstant::*;
        match unit {
            0 => [TexEnv, TexGen, Combine, Crossbar],
            1 => [TexEnv1, TexGen1, Combine1, Crossbar1],
            2 => [TexEnv2, TexGen2, Combine2, Crossbar2],
            _ => [TexEnv3, TexGen3, Combine3, Crossbar3],
        }
    }

    /// The `constant_id` in the GLSL.
    pub fn id(self) -> u32 {
        self as u32
    }

    /// Whether the GLSL declares it a `float` (its value's bits in [`SpecKey`]); the others
    /// are `int`s.
    pub fn is_float(self) -> bool {
        matches!(
            self,
            SpecConstant::PointSize
                | SpecConstant::PointAttenuationA
                | SpecConstant::PointAttenuationB
                | SpecConstant::PointAttenuationC
                | SpecConstant::PointSizeMin
                | SpecConstant::PointSizeMax
        )
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
            SpecConstant::FiniteVertices => "SPEC_FINITE_VERTICES",
            SpecConstant::DirectionalLights => "SPEC_DIRECTIONAL_LIGHTS",
            SpecConstant::SpotLights => "SPEC_SPOT_LIGHTS",
            SpecConstant::Points => "SPEC_POINTS",
            SpecConstant::PointSize => "SPEC_POINT_SIZE",
            SpecConstant::GlSnorm => "SPEC_GL_SNORM",
            SpecConstant::RecordVec4s => "SPEC_RECORD_VEC4S",
            SpecConstant::ColorSum => "SPEC_COLOR_SUM",
            SpecConstant::AlphaFunc => "SPEC_ALPHA_FUNC",
            SpecConstant::AlphaBits => "SPEC_ALPHA_BITS",
            SpecConstant::FogMode => "SPEC_FOG_MODE",
            SpecConstant::FogSource => "SPEC_FOG_SOURCE",
            SpecConstant::FogPerVertex => "SPEC_FOG_PER_VERTEX",
            SpecConstant::ClipPlanes => "SPEC_CLIP_PLANES",
            SpecConstant::PointAttenuation => "SPEC_POINT_ATTENUATION",
            SpecConstant::PointAttenuationA => "SPEC_POINT_ATTENUATION_A",
            SpecConstant::PointAttenuationB => "SPEC_POINT_ATTENUATION_B",
            SpecConstant::PointAttenuationC => "SPEC_POINT_ATTENUATION_C",
            SpecConstant::PointSizeMin => "SPEC_POINT_SIZE_MIN",
            SpecConstant::PointSizeMax => "SPEC_POINT_SIZE_MAX",
            SpecConstant::PointSprite => "SPEC_POINT_SPRITE",
            SpecConstant::TexGen => "SPEC_TEXGEN",
            SpecConstant::Combine => "SPEC_COMBINE",
            SpecConstant::TextureUnits => "SPEC_TEXTURE_UNITS",
            SpecConstant::Crossbar => "SPEC_CROSSBAR",
            SpecConstant::TexEnv1 => "SPEC_TEX_ENV_1",
            SpecConstant::TexEnv2 => "SPEC_TEX_ENV_2",
            SpecConstant::TexEnv3 => "SPEC_TEX_ENV_3",
            SpecConstant::TexGen1 => "SPEC_TEXGEN_1",
            SpecConstant::TexGen2 => "SPEC_TEXGEN_2",
            SpecConstant::TexGen3 => "SPEC_TEXGEN_3",
            SpecConstant::Combine1 => "SPEC_COMBINE_1",
            SpecConstant::Combine2 => "SPEC_COMBINE_2",
            SpecConstant::Combine3 => "SPEC_COMBINE_3",
            SpecConstant::Crossbar1 => "SPEC_CROSSBAR_1",
            SpecConstant::Crossbar2 => "SPEC_CROSSBAR_2",
            SpecConstant::Crossbar3 => "SPEC_CROSSBAR_3",
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
    /// model and light kinds without lights). A unit's environment, texgen and combine count
    /// only while one of its targets is enabled; which units a pipeline samples
    /// ([`SpecConstant::TextureUnits`]) is the pipeline's to set.
    pub fn for_state(state: &FixedFunctionState) -> SpecKey {
        let mut values = [0; SPEC_CONSTANT_COUNT];
        for (i, unit) in state
            .texture_units
            .iter()
            .enumerate()
            .filter(|(_, u)| u.is_enabled())
        {
            let [env, texgen, combine, crossbar] = SpecConstant::of_unit(i);
            values[env as usize] = unit.env_mode.code() as i32;
            values[texgen as usize] = unit.texgen_code() as i32;
            if unit.env_mode == crate::gl::texture::TexEnvMode::Combine {
                values[combine as usize] = unit.combine.code() as i32;
                values[crossbar as usize] = unit.combine.crossbar_code() as i32;
            }
        }
        values[SpecConstant::AlphaFunc as usize] = state.fragment.alpha_test.effective_func().code() as i32;
        values[SpecConstant::ClipPlanes as usize] = state.clip.mask() as i32;
        let fog = &state.fragment.fog;
        if fog.enabled {
            values[SpecConstant::FogMode as usize] = fog.mode_code() as i32;
            values[SpecConstant::FogSource as usize] = (fog.source == FogSource::FogCoord) as i32;
            values[SpecConstant::FogPerVertex as usize] = fog.hint.per_vertex() as i32;
        }
        if !state.lighting {
            values[SpecConstant::ColorSum as usize] = state.fragment.color_sum as i32;
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
        let mask = |kind: fn(&Light) -> bool| {
            lights
                .iter()
                .enumerate()
                .filter(|(_, l)| kind(l))
                .fold(0, |mask, (i, _)| mask | 1 << i)
        };
        values[SpecConstant::DirectionalLights as usize] = mask(|l| l.position.w == 0.0);
        values[SpecConstant::SpotLights as usize] = mask(|l| l.spot_cutoff != 180.0);
        values[SpecConstant::LightCount as usize] = lights.len() as i32;
        SpecKey { values }
    }

    /// [`SpecKey::for_state`] for a draw with `modelview`: [`SpecConstant::FiniteVertices`]
    /// set where it can act (lit, with lights, every one directional) and the modelview is
    /// affine, which makes every vertex's w exactly 1. The uber-shader's key stays as it is.
    pub fn for_draw(state: &FixedFunctionState, modelview: Mat4) -> SpecKey {
        SpecKey::for_state(state).with_finite_vertices(modelview.row(3) == glam::Vec4::W)
    }

    /// This key with [`SpecConstant::FiniteVertices`] set to `finite` where it can act (see
    /// [`SpecKey::for_draw`]).
    pub fn with_finite_vertices(mut self, finite: bool) -> SpecKey {
        let can_act = self.get(SpecConstant::Lighting) == 1
            && self.get(SpecConstant::LightCount) > 0
            && self.get(SpecConstant::DirectionalLights) > 0;
        if can_act {
            self.values[SpecConstant::FiniteVertices as usize] = finite as i32;
        }
        self
    }
}
