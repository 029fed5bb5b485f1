//! What picks a draw's pipeline besides its state and raster state ([`Variant`]), and the
//! policy ([`Specialize`]) that chooses its specialization.

use ash::vk;

use super::super::pipeline::{PointKey, RasterState, Specialize, MAX_AUTO_VARIANTS};
use super::super::record::Topology;
use super::Lighting;
use crate::error::Result;
use crate::gl::state::FixedFunctionState;
use crate::gpu::layout::SpecKey;

/// What besides its state and raster state picks a draw's pipeline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Variant {
    /// The vertex layout's number.
    pub(super) layout: u32,
    /// It samples a texture.
    pub(super) textured: bool,
    /// A fragment-mode draw of fewer than [`SMALL_DRAW_VERTICES`](super::super::pipeline::SMALL_DRAW_VERTICES) vertices.
    pub(super) small: bool,
    /// Every vertex at w = 1 after the modelview (`SpecConstant::FiniteVertices`): an affine
    /// modelview and a layout whose positions have no w.
    pub(super) affine: bool,
    /// Its topology and primitive restart.
    pub(super) assembly: (Topology, bool),
    /// The deferred path's G-buffer pass ([`Lighting::set_gbuffer`]).
    pub(super) gbuffer: bool,
    /// Some user clip plane is enabled: the `_clipped` build.
    pub(super) clipped: bool,
    /// Fog is on: the `_fog` build.
    pub(super) fogged: bool,
    /// Its point constants ([`PointKey::OFF`] but for points).
    pub(super) points: PointKey,
}

impl Lighting {
    /// The pipeline a draw with `state` and `raster`, (textured or not, small or not, with an
    /// affine modelview or not), uses under the [`Specialize`] policy.
    pub(super) fn pipeline_for(
        &mut self,
        state: &FixedFunctionState,
        raster: RasterState,
        variant: Variant,
    ) -> Result<vk::Pipeline> {
        let mode = state.mode;
        let (textured, affine, assembly) = (
            (variant.textured, variant.small),
            variant.affine,
            variant.assembly,
        );
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
                    (assembly.0, assembly.1, variant.points),
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
            (variant.gbuffer, variant.clipped, variant.fogged),
            variant.points,
        )
    }
}
