//! The key a draw's state block ([`StateBlock`](super::StateBlock)) is found by ([`StateKey`]): what of a draw its block is made
//! from, compared field by field.

use glam::Mat4;

use crate::gl::state::{ClipPlanes, FixedFunctionState, Light, MAX_LIGHTS};

/// What of a draw its [`StateBlock`](super::StateBlock) is made from: its [`FixedFunctionState`] but the materials,
/// the current color, `GL_RESCALE_NORMAL` and the mode, and its projection. Two draws with
/// equal keys share a block (and a pipeline, for equal raster states and texturing). The block
/// packs the enabled lights only, so keys are equal when every light's enable is and the
/// enabled lights' values are: a disabled light's values never split a block.
#[derive(Debug, Clone, Copy)]
pub(crate) struct StateKey {
    lighting: bool,
    normalize: bool,
    model: crate::gl::state::LightModel,
    color_material: crate::gl::state::ColorMaterial,
    texture: crate::gl::texture::TextureUnit,
    fragment: crate::gl::state::FragmentStages,
    clip: ClipPlanes,
    points: crate::gl::state::PointParameters,
    projection: Mat4,
    lights: [Light; MAX_LIGHTS],
}

impl StateKey {
    /// The key of a draw of `state` under `projection`.
    pub(crate) fn new(state: &FixedFunctionState, projection: Mat4) -> Self {
        StateKey {
            lighting: state.lighting,
            normalize: state.normalize,
            model: state.model,
            color_material: state.color_material,
            texture: state.texture,
            fragment: state.fragment,
            clip: state.clip,
            points: state.points,
            projection,
            lights: state.lights,
        }
    }

    /// Whether a draw of `state` under `projection` has this key: compared in place, without
    /// copying the lights into a key of its own (a draw's check when it shares the state of the
    /// draw before, the common case).
    pub(crate) fn matches(&self, state: &FixedFunctionState, projection: Mat4) -> bool {
        self.lighting == state.lighting
            && self.normalize == state.normalize
            && self.model == state.model
            && self.color_material == state.color_material
            && self.texture == state.texture
            && self.fragment == state.fragment
            && self.clip == state.clip
            && self.points == state.points
            && self.projection == projection
            && same_lights(&self.lights, &state.lights)
    }
}

impl PartialEq for StateKey {
    fn eq(&self, other: &StateKey) -> bool {
        let StateKey {
            lighting,
            normalize,
            model,
            color_material,
            texture,
            fragment,
            clip,
            points,
            projection,
            lights,
        } = self;
        // Every field by name: a field added to the key must be compared here too.
        *lighting == other.lighting
            && *normalize == other.normalize
            && *model == other.model
            && *color_material == other.color_material
            && *texture == other.texture
            && *fragment == other.fragment
            && *clip == other.clip
            && *points == other.points
            && *projection == other.projection
            && same_lights(lights, &other.lights)
    }
}

/// Whether `a` and `b` make the same block under one projection (their [`StateKey`] parts are
/// equal), compared in place.
pub(crate) fn same_block_state(a: &FixedFunctionState, b: &FixedFunctionState) -> bool {
    a.lighting == b.lighting
        && a.normalize == b.normalize
        && a.model == b.model
        && a.color_material == b.color_material
        && a.texture == b.texture
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
