//! [`LightingOptions`]: how to make a [`Lighting`](super::lighting::Lighting): the caller's
//! target and vertex layout, frame slots, descriptor set index, pipeline cache and
//! specialization policy.

use ash::vk;

use super::pipeline::{Specialize, Target, VertexInput};
use crate::error::{LightingError, Result};

/// The most frame slots a [`Lighting`](super::lighting::Lighting) keeps ([`LightingOptions::frames_in_flight`]): a
/// caller waits for a frame long before this many are in flight, and a count past it is
/// refused before anything is allocated for it.
pub const MAX_FRAMES_IN_FLIGHT: u32 = 64;

/// How to make a [`Lighting`](super::lighting::Lighting).
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct LightingOptions {
    /// The caller's attachments.
    pub target: Target,
    /// The caller's vertex layout.
    pub vertex_input: VertexInput,
    /// Frame slots: how many frames the caller records before it waits for the oldest.
    pub frames_in_flight: u32,
    /// The descriptor set index of ffvk's state block in the pipeline layout (0 unless the
    /// caller's shaders share the layout's lower sets). ffvk uses sets `set_index` (the state
    /// block), `set_index + 1` (the texture) and `set_index + 2` (the draw records, read by
    /// the fragment mode), so `set_index + 2` must be below `maxBoundDescriptorSets`.
    pub set_index: u32,
    /// The caller's pipeline cache; `None` makes ffvk's own.
    pub pipeline_cache: Option<vk::PipelineCache>,
    /// Specialized pipelines per lighting state, or the uber-shader.
    pub specialize: Specialize,
}

impl LightingOptions {
    /// Options for `target` and `vertex_input`: one frame slot, set 0, ffvk's own cache,
    /// [`Specialize::Auto`].
    pub fn new(target: Target, vertex_input: VertexInput) -> Self {
        LightingOptions {
            target,
            vertex_input,
            frames_in_flight: 1,
            set_index: 0,
            pipeline_cache: None,
            specialize: Specialize::Auto,
        }
    }
}

impl LightingOptions {
    /// Checks what needs no device: 1 ..= [`MAX_FRAMES_IN_FLIGHT`] frame slots, the target's
    /// formats and samples ([`Target::validate`]) and the vertex layout
    /// ([`VertexInput::validate`]). [`Lighting::new`](super::lighting::Lighting::new) checks this first, then the device.
    pub fn validate(&self) -> Result<()> {
        match self.frames_in_flight {
            0 => return Err(LightingError::NoFrameSlots.into()),
            count if count > MAX_FRAMES_IN_FLIGHT => {
                return Err(LightingError::TooManyFrameSlots {
                    count,
                    max: MAX_FRAMES_IN_FLIGHT,
                }
                .into())
            }
            _ => {}
        }
        self.target.validate()?;
        self.vertex_input.validate()
    }
}

with_fields!(LightingOptions {
    /// Sets [`frames_in_flight`](LightingOptions::frames_in_flight).
    with_frames_in_flight => frames_in_flight: u32,
    /// Sets [`set_index`](LightingOptions::set_index).
    with_set_index => set_index: u32,
    /// Sets [`pipeline_cache`](LightingOptions::pipeline_cache).
    with_pipeline_cache => pipeline_cache: Option<vk::PipelineCache>,
    /// Sets [`specialize`](LightingOptions::specialize).
    with_specialize => specialize: Specialize,
});
