//! What picks a draw's pipeline besides its state and raster state ([`Variant`]), and the
//! policy ([`Specialize`]) that chooses its specialization.

use ash::vk;

use super::super::pipeline::{PointKey, RasterState, Specialize, MAX_AUTO_VARIANTS};
use super::super::record::Topology;
use super::{DrawPipelines, Lighting};
use crate::error::Result;
use crate::gl::state::FixedFunctionState;
use crate::gl::texture::{units_applied, TextureUnit, MAX_TEXTURE_UNITS};
use crate::gpu::layout::SpecKey;

/// What besides its state and raster state picks a draw's pipeline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Variant {
    /// The vertex layout's number.
    pub(super) layout: u32,
    /// The texture units it samples (bits 0-3) and applies (bits 4-7); 0 untextured.
    pub(super) units: u32,
    /// A fragment-mode draw of fewer than [`SMALL_DRAW_VERTICES`](super::super::pipeline::SMALL_DRAW_VERTICES) vertices.
    pub(super) small: bool,
    /// Every vertex at w = 1 after the modelview (`SpecConstant::FiniteVertices`): an affine
    /// modelview and a layout whose positions have no w.
    pub(super) affine: bool,
    /// Its topology and primitive restart.
    pub(super) assembly: (Topology, bool),
    /// The deferred path's G-buffer pass ([`Lighting::set_gbuffer`]).
    pub(super) gbuffer: bool,
    /// Renders into the stencil form of the target ([`Lighting::set_stencil_target`]).
    pub(super) stencil_target: bool,
    /// Some user clip plane is enabled: the `_clipped` build.
    pub(super) clipped: bool,
    /// Fog is on: the `_fog` build.
    pub(super) fogged: bool,
    /// Its point constants ([`PointKey::OFF`] but for points).
    pub(super) points: PointKey,
}

/// The texture units a draw samples (bits 0-3), applies (bits 4-7) and samples as cube maps
/// (bits 8-11), as the pipeline keys them (`SPEC_TEXTURE_UNITS`), for `units` with a complete
/// 2D texture on the units `bound` names and a complete cube map on those of `bound_cube`
/// ([`units_applied`]): 0, the untextured pipeline, when no unit applies.
pub(crate) fn units_key(units: &[TextureUnit; MAX_TEXTURE_UNITS], bound: u32, bound_cube: u32) -> u32 {
    match units_applied(units, bound, bound_cube) {
        (_, 0, _) => 0,
        (sampled, applied, cube) => sampled | applied << 4 | cube << 8,
    }
}

impl Lighting {
    /// The pipelines a draw with `state` and `raster`, (textured or not, small or not, with an
    /// affine modelview or not), uses under the [`Specialize`] policy: one, or two where its
    /// faces are rasterized in different polygon modes ([`RasterState::face_passes`]).
    pub(super) fn pipeline_for(
        &mut self,
        state: &FixedFunctionState,
        raster: RasterState,
        variant: Variant,
    ) -> Result<DrawPipelines> {
        // The whole state is checked once here: the pipelines see only its keyed part.
        self.pipelines
            .check_raster(&raster, (variant.stencil_target, variant.gbuffer))?;
        let (first, second) = raster.face_passes(variant.assembly.0.is_triangles());
        let (keyed, dynamic) = first.split_dynamic();
        let first = (self.pipeline_of_pass(state, keyed, variant)?, dynamic);
        let second = match second.map(|pass| pass.split_dynamic()) {
            Some((keyed, dynamic)) => Some((self.pipeline_of_pass(state, keyed, variant)?, dynamic)),
            None => None,
        };
        Ok((first, second))
    }

    /// The pipeline of one of a draw's passes.
    fn pipeline_of_pass(
        &mut self,
        state: &FixedFunctionState,
        raster: RasterState,
        variant: Variant,
    ) -> Result<vk::Pipeline> {
        let mode = state.mode;
        let (textured, affine, assembly) = ((variant.units, variant.small), variant.affine, variant.assembly);
        let key = match self.specialize {
            Specialize::Never => SpecKey::UBER,
            Specialize::Always => SpecKey::for_state(state).with_finite_vertices(affine),
            Specialize::Auto => {
                let key = SpecKey::for_state(state).with_finite_vertices(affine);
                if self.pipelines.contains(
                    variant.layout,
                    mode,
                    key,
                    raster,
                    textured,
                    (assembly.0, assembly.1, variant.points, variant.stencil_target),
                ) || self.pipelines.counts().1 < MAX_AUTO_VARIANTS
                {
                    key
                } else {
                    SpecKey::UBER
                }
            }
        };
        self.pipelines.get_for(
            variant.layout,
            (mode, key, raster),
            textured,
            assembly,
            (
                variant.gbuffer,
                variant.clipped,
                variant.fogged,
                variant.stencil_target,
            ),
            variant.points,
        )
    }
}
