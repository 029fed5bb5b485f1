//! The key a draw's state block ([`StateBlock`](super::StateBlock)) is found by ([`StateKey`]): what of a draw its block is made
//! from, compared field by field.

use glam::Mat4;

use crate::gl::state::{FixedFunctionState, Light, MAX_LIGHTS};

/// What of a draw its [`StateBlock`](super::StateBlock) is made from: its [`FixedFunctionState`] but the materials,
/// the current color, `GL_RESCALE_NORMAL` and the mode, and its projection. Two draws with
/// equal keys share a block (and a pipeline, for equal raster states and texturing). The block
/// packs the enabled lights only, so keys are equal when every light's enable is and the
/// enabled lights' values are: a disabled light's values never split a block.
#[derive(Debug, Clone, Copy)]
pub(crate) struct StateKey {
    /// The draw's state; only what [`same_block_state`] compares counts.
    state: FixedFunctionState,
    projection: Mat4,
}

impl StateKey {
    /// The key of a draw of `state` under `projection`.
    pub(crate) fn new(state: &FixedFunctionState, projection: Mat4) -> Self {
        StateKey {
            state: *state,
            projection,
        }
    }

    /// Whether a draw of `state` under `projection` has this key, compared in place (a draw's
    /// check when it shares the state of the draw before, the common case).
    pub(crate) fn matches(&self, state: &FixedFunctionState, projection: Mat4) -> bool {
        self.projection == projection && same_block_state(&self.state, state)
    }
}

impl PartialEq for StateKey {
    fn eq(&self, other: &StateKey) -> bool {
        self.matches(&other.state, other.projection)
    }
}

/// Whether `a` and `b` make the same block under one projection (their [`StateKey`] parts are
/// equal), compared in place: the one list of what a block is made from. A field added to the
/// state that the block or the pipeline reads must be compared here.
pub(crate) fn same_block_state(a: &FixedFunctionState, b: &FixedFunctionState) -> bool {
    a.lighting == b.lighting
        && a.normalize == b.normalize
        && a.model == b.model
        && a.color_material == b.color_material
        && a.texture_units == b.texture_units
        && a.fragment == b.fragment
        && a.clip == b.clip
        && a.points == b.points
        && same_lights(&a.lights, &b.lights)
}

/// Lights that pack into the same block: the same enables, and equal values where enabled.
fn same_lights(a: &[Light; MAX_LIGHTS], b: &[Light; MAX_LIGHTS]) -> bool {
    a.iter()
        .zip(b)
        .all(|(a, b)| a.enabled == b.enabled && (!a.enabled || a == b))
}
