//! The specialization constants a pipeline fixes for itself rather than for the state (its
//! topology's, its point size's, its vertex layout's, its target's, the units it samples), for
//! pipelines of a caller's own built on the shader library (`docs/shader-library.md`).

use ash::vk;
use glam::Mat4;

use super::formats::unorm_alpha_bits;
use super::lighting::units_key;
use super::pipeline::{with_assembly, PointKey};
use super::record::Topology;
use crate::gl::state::FixedFunctionState;
use crate::gpu::layout::{SpecConstant, SpecKey};

/// What one of a caller's pipelines is made for, beside GL's state: what
/// [`SpecKey::for_pipeline`] needs to set the constants that [`SpecKey::for_state`] leaves at
/// 0, as ffvk sets them in its own pipelines.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PipelineConstants {
    /// The primitives drawn: points write GL's point size (`SPEC_POINTS` and the point
    /// constants).
    pub topology: Topology,
    /// `glPointSize`, for pipelines drawing points (1, GL's default).
    pub point_size: f32,
    /// The color attachment's format: the alpha test compares at its alpha precision
    /// (`SPEC_ALPHA_BITS`).
    pub color_format: vk::Format,
    /// The vertex layout's signed normalized arrays, as `SPEC_GL_SNORM` codes them (0: none;
    /// see [`SpecConstant::GlSnorm`]).
    pub gl_snorm: i32,
    /// The units with a complete `GL_TEXTURE_2D` texture bound, a bit each.
    pub bound_2d: u32,
    /// The units with a complete cube map bound, a bit each.
    pub bound_cube: u32,
}

impl PipelineConstants {
    /// A pipeline drawing `topology` into a color attachment of `color_format`, with GL's
    /// point size, no signed normalized arrays and no texture bound.
    pub fn new(topology: Topology, color_format: vk::Format) -> Self {
        PipelineConstants {
            topology,
            point_size: 1.0,
            color_format,
            gl_snorm: 0,
            bound_2d: 0,
            bound_cube: 0,
        }
    }
}

impl SpecKey {
    /// Every constant for a pipeline of `pipeline`'s kind drawing under `state` with
    /// `modelview`: [`SpecKey::for_draw`] with the pipeline's own constants set as ffvk sets them
    /// in its own pipelines (the topology's and the point constants, the layout's GL
    /// conversions, the target's alpha bits, the units sampled and applied). The constants of
    /// ffvk's deferred pass (`SPEC_RECORD_VEC4S`) stay 0.
    pub fn for_pipeline(
        state: &FixedFunctionState,
        modelview: Mat4,
        pipeline: &PipelineConstants,
    ) -> SpecKey {
        let units = units_key(&state.texture_units, pipeline.bound_2d, pipeline.bound_cube);
        let points = pipeline.topology == Topology::PointList;
        let key = with_assembly(
            SpecKey::for_draw(state, modelview),
            points,
            pipeline.point_size,
            PointKey::of(state, pipeline.topology, units & 0xf),
        );
        let mut key = key;
        key.values[SpecConstant::GlSnorm as usize] = pipeline.gl_snorm;
        key.values[SpecConstant::AlphaBits as usize] = unorm_alpha_bits(pipeline.color_format) as i32;
        key.values[SpecConstant::TextureUnits as usize] = units as i32;
        key
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::state::{Cap, GlState, PointParam};

    #[test]
    fn a_callers_key_sets_the_pipelines_own_constants_that_the_states_key_leaves_at_zero() {
        let mut gl = GlState::new();
        gl.enable(Cap::Lighting).unwrap();
        gl.enable(Cap::Light(0)).unwrap();
        gl.enable(Cap::Texture2D).unwrap();
        gl.point_parameter(PointParam::SizeMax(8.0)).unwrap();
        let state = gl.lighting;
        let of_state = SpecKey::for_draw(&state, Mat4::IDENTITY);
        let mut points = PipelineConstants::new(Topology::PointList, vk::Format::R8G8B8A8_UNORM);
        points.point_size = 3.0;
        points.bound_2d = 0b1;
        let key = SpecKey::for_pipeline(&state, Mat4::IDENTITY, &points);
        let get = |c: SpecConstant| key.get(c);
        assert_eq!(get(SpecConstant::Points), 1);
        assert_eq!(get(SpecConstant::PointSize), 3.0f32.to_bits() as i32);
        assert_eq!(get(SpecConstant::PointSizeMax), 8.0f32.to_bits() as i32);
        assert_eq!(get(SpecConstant::AlphaBits), 8, "an 8-bit UNORM target's alpha");
        // Unit 0, bound and enabled, is sampled (bit 0) and applied (bit 4).
        assert_eq!(get(SpecConstant::TextureUnits), 0b1_0001);
        for c in SpecConstant::ALL {
            let own = matches!(
                c,
                SpecConstant::Points
                    | SpecConstant::PointSize
                    | SpecConstant::PointSizeMax
                    | SpecConstant::PointSizeMin
                    | SpecConstant::PointAttenuationA
                    | SpecConstant::AlphaBits
                    | SpecConstant::TextureUnits
            );
            if !own {
                assert_eq!(key.get(c), of_state.get(c), "{c:?} is the state's");
            }
        }
        // Triangles into a float target: no point constants, alpha compared as floats.
        let triangles = PipelineConstants::new(Topology::TriangleList, vk::Format::R32G32B32A32_SFLOAT);
        let key = SpecKey::for_pipeline(&state, Mat4::IDENTITY, &triangles);
        assert_eq!(key.get(SpecConstant::Points), 0);
        assert_eq!(key.get(SpecConstant::AlphaBits), 0);
        assert_eq!(
            key.get(SpecConstant::TextureUnits),
            0,
            "no texture bound: nothing sampled"
        );
    }
}
