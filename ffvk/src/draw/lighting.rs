//! [`Lighting`]: GL's lighting inside a caller's own Vulkan device, render targets and
//! command buffers.
//!
//! # What it takes, owns and records
//!
//! The caller keeps its instance, device, queues, command pools and buffers, images, vertex
//! and index buffers, synchronization and submission; ffvk touches none of them beyond
//! recording commands into the command buffer it is given. A [`Lighting`] owns what it
//! creates: one descriptor set layout (binding 0, `UNIFORM_BUFFER_DYNAMIC`, vertex and
//! fragment stages: the state block; empty layouts for the sets below
//! [`LightingOptions::set_index`]), the texture's layout for the set after it (binding 0,
//! `COMBINED_IMAGE_SAMPLER`, fragment stage), the draw records' layout for the set after that
//! (binding 0, `UNIFORM_BUFFER_DYNAMIC`, fragment stage: the fragment mode reads a draw's
//! materials there), one pipeline layout (no push constants), a
//! pipeline cache unless the caller passes one, the pipelines (created on first use per
//! lighting mode, specialization key and [`RasterState`]), and for each frame slot
//! host-visible, coherent memory for the state blocks and the draw records (buffers with
//! their descriptor sets); and the [`TextureBinding`](super::texture::TextureBinding)s the caller asks
//! for (a descriptor set naming the caller's image view and sampler), which the caller holds.
//! Dropping it frees all of that; the caller must first make sure no submitted command buffer
//! still uses it (wait for its fences or the device).
//!
//! The pipelines read the caller's vertex bindings per vertex and ffvk's draw records per
//! instance, at the lowest binding number the caller's [`VertexInput`] leaves free, as
//! attribute locations 4-20 ([`DrawRecord`]), and GL's current values from the record where a
//! layout has no array for them; the device needs `maxVertexInputAttributes` ≥ 21
//! ([`LightingError::VertexInputLimit`] otherwise). Instancing and `firstInstance` are ffvk's.
//! One `Lighting` draws with any number of vertex layouts ([`Lighting::vertex_layout`]).
//!
//! [`Lighting::draw`] records, into the caller's command buffer inside the caller's dynamic
//! rendering pass (`vkCmdBeginRendering`; render passes are not supported): bind pipeline,
//! bind the state block's descriptor set at its dynamic offset (and, textured, the texture's
//! set after it; in the fragment mode, for draws of [`SMALL_DRAW_VERTICES`] or more vertices,
//! the record's set at the record's dynamic offset), bind
//! the caller's vertex buffers and ffvk's record buffer (and the caller's index buffer), draw
//! with `firstInstance` naming the draw's record. The commands read the
//! caller's vertex and index buffers and ffvk's per-frame memory, and write the caller's color
//! attachment (and depth attachment when the draw's [`RasterState`] tests depth), with
//! blending as that state says. They need the viewport and scissor the caller sets (both are
//! dynamic state). The bindings stay bound after the call.
//!
//! # Bindings
//!
//! ffvk remembers what it bound, and in which command buffer: its next draw into the same
//! command buffer ([`Lighting::draw`], [`Lighting::draw_run`] or [`Lighting::record_run`])
//! binds only what differs, so a caller that records one `draw` per GL draw pays no rebinding
//! of the pipeline, the state block, the record buffer or unchanged vertex and index buffers.
//! The caller may record its own commands between ffvk's draws: viewports, scissors, clears,
//! barriers, dynamic state, the end of one rendering pass and the start of another need nothing
//! more; after binding anything of its own (a pipeline, descriptor sets, vertex or index
//! buffers), or resetting a command buffer ffvk drew into, it calls
//! [`Lighting::forget_bindings`] and ffvk binds everything at its next draw.
//! [`Lighting::begin_frame`] forgets too, and so does a `Lighting` when another one on the same
//! device has recorded since its last draw (two layouts' `Lighting`s in one command buffer). Viewport and scissor are the caller's to set (dynamic
//! state in every ffvk pipeline); every other raster state is the draw's [`RasterState`], part
//! of its pipeline.
//!
//! What one `draw` per draw still costs against a run is the instancing a run gives: a run
//! draws consecutive draws of one geometry as instances of one draw command, single draws are
//! a command each (`ffvk bench`'s draws sweep measures both, BENCHMARKS.md "Many draws").
//!
//! # Frame slots
//!
//! Per-draw GL state goes into the memory of the frame slot the caller names. Call
//! [`Lighting::begin_frame`] for a slot before recording its draws, and only once the fence
//! of the submission that last used that slot has signalled: that is when its memory may be
//! rewritten. With `frames_in_flight` slots the caller cycles through them as it cycles
//! through its own per-frame resources.
//!
//! # What a draw costs
//!
//! A draw's GL state is staged in GL's rhythm. Its own values, the ones GL programs change
//! between draws (modelview, materials, current color), are checked and written as its
//! [`DrawRecord`] (304 bytes, with the normal matrix): that is all a draw that changes only
//! those writes, about 0.1 µs on the host on lavapipe in a run whose draws borrow one
//! [`FixedFunctionState`] and carry their own [`DrawValues`] (0.3-0.5 µs when each draw brings a
//! state of its own, which is compared with the one before). The rest ([`StateBlock`]: lights,
//! light model, switches, texture environment and matrix, projection; 2,928 bytes) is checked,
//! packed and written only when it differs from the previous draw's in the same frame slot,
//! and then bound at a new dynamic offset; the pipeline, too, is looked up only then (about
//! 0.7 µs more). [`Lighting::draw_run`] is the recording scope: its draws bind only what
//! changes between them, and consecutive draws of the same geometry, buffers, pipeline, state
//! and texture become instances of one draw command, but for the fragment mode's draws of
//! [`SMALL_DRAW_VERTICES`] or more vertices, whose fragment stage reads the draw's record as a
//! uniform block bound per draw (smaller ones pass their materials as flat varyings, which
//! lavapipe's triangle setup pays per triangle; BENCHMARKS.md, "Many draws"). A
//! pipeline is made per lighting mode, [`RasterState`], texturing and specialization key (the
//! switches and the kinds of the enabled lights, never materials, colors, matrices or light
//! values): about 15 ms on lavapipe, on the first draw that needs it unless
//! [`Lighting::prepare`] made it before the frame. The shaders keep their branches and loop
//! bounds off uniform values alone and read per-draw values as vertex data, so the driver
//! compiles nothing per draw (lavapipe 22.3 would, for every draw whose uniforms changed; a
//! test guards it); the uber-shader ([`Specialize::Never`], or [`Specialize::Auto`] past its
//! budget) is about twice as slow per vertex and fragment as specialized pipelines.
//!
//! # The fragment mode's deferred path
//!
//! [`Lighting`] lights the fragment mode forward, at every fragment of every draw. The
//! once-per-pixel path ([`FragmentPath::Deferred`](crate::FragmentPath::Deferred)) is the
//! [`Renderer`](crate::Renderer)'s: it needs attachments of its own (the G-buffer) and a
//! second pass inside the frame, after the draws, which a caller's single rendering pass does
//! not give; offering it here would mean taking over the caller's pass structure.
//!
//! # Threads
//!
//! `Lighting` is `Send` and `Sync`; recording takes `&mut self`, so one thread records with a
//! given `Lighting` at a time (a renderer that records on several threads makes one per
//! thread).

//!
//! # Example
//!
//! `ffvk/examples/embed.rs` in the repository: its own instance, device, queue, images and
//! buffers with plain `ash`, the teapot in the three modes (`cargo run --release -p ffvk
//! --features images --example embed`):
//!
#![doc = concat!("```rust,ignore\n", include_str!("../../examples/embed.rs"), "\n```")]

use std::sync::Arc;

use ash::vk;

mod bindings;
mod textures;
mod variant;
use bindings::Remembered;
pub(crate) use variant::units_key;
use variant::Variant;

pub use super::lit::{DrawValues, LitDraw, VertexLayout};
pub use super::options::{LightingOptions, MAX_FRAMES_IN_FLIGHT};
use super::pipeline::{
    PipelineConfig, Pipelines, PointKey, RasterState, Specialize, VertexInput, SMALL_DRAW_VERTICES,
};
use super::raster::DynamicRaster;
use super::record::{record_in_run, Bound, RunState, Topology};
use super::ring::{Pushed, Ring, RingUse};
use super::texture::{UnitSets, UnitTextures};
use crate::error::{LightingError, Result};
use crate::gl::state::{FixedFunctionState, LightingMode};
use crate::gl::texture::MAX_TEXTURE_UNITS;
use crate::gpu::layout::{DrawRecord, StateBlock, StateKey};
use crate::vk::Device;

/// A draw's pipeline, state block and record, ready to record ([`Lighting::stage`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Staged {
    /// The pipeline, and a second one for a draw whose faces take different polygon modes.
    pipeline: DrawPipelines,
    /// The vertex layout's number.
    layout: u32,
    /// The state block's set and dynamic offset.
    state: (vk::DescriptorSet, u32),
    /// The record's buffer and index.
    record: (vk::Buffer, u32),
    /// The record chunk's set and the record's offset, for a fragment stage that reads it as a
    /// uniform block (the fragment mode).
    record_block: Option<(vk::DescriptorSet, u32)>,
    /// The texture units' set, for a textured draw.
    texture_set: Option<vk::DescriptorSet>,
}

impl Staged {
    /// The state block's descriptor set and dynamic offset.
    pub(crate) fn state_binding(&self) -> (vk::DescriptorSet, u32) {
        self.state
    }

    /// The buffer holding the draw's record.
    pub(crate) fn record_buffer(&self) -> vk::Buffer {
        self.record.0
    }

    /// The record's index in [`Staged::record_buffer`] (the vertex stages' instance index).
    pub(crate) fn record_index(&self) -> u32 {
        self.record.1
    }
}

/// A draw checked and written into its frame slot by [`Lighting::stage_draw`], waiting for
/// [`Lighting::record_run`].
#[derive(Debug, Clone, Copy)]
pub struct StagedDraw(Staged);

/// The state block the last staged draw used, and the pipelines found for it: the next draw
/// with an equal [`StateKey`] in the same slot reuses both, so that a draw which changes only
/// its own values (materials, color, modelview) writes only its record.
struct LastState {
    slot: u32,
    key: StateKey,
    block: Pushed,
    /// (mode, raster state, variant) and the pipeline such a draw of this state uses.
    pipelines: Vec<(LightingMode, RasterState, Variant, DrawPipelines)>,
}

/// A draw's pipeline and the raster state it sets as dynamic state, and a second pair for a
/// draw whose faces take different polygon modes ([`RasterState::face_passes`]).
pub(super) type DrawPipelines = (
    (vk::Pipeline, DynamicRaster),
    Option<(vk::Pipeline, DynamicRaster)>,
);

/// The next [`Lighting`]'s number (its layouts name it, so another's are refused).
static NEXT_LIGHTING: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

// Recording takes &mut self; the type itself may move between and be shared by threads.
const _: () = {
    const fn send_and_sync<T: Send + Sync>() {}
    send_and_sync::<Lighting>();
};

/// GL 2.1 lighting for a caller's device: pipelines, layouts and per-draw state memory,
/// recorded into the caller's command buffers (see the module docs for what it owns, what
/// it records and when a frame slot may be reused).
pub struct Lighting {
    // Field order is drop order: the per-frame memory and pipelines before the device.
    /// The state blocks of each frame slot.
    states: Ring,
    /// The draw records of each frame slot.
    records: Ring,
    /// The texture units' sets of each frame slot.
    unit_sets: UnitSets,
    pipelines: Pipelines,
    specialize: Specialize,
    last: Option<LastState>,
    /// This `Lighting`'s number among all, which its [`VertexLayout`]s carry.
    id: u64,
    /// Draws are staged for the deferred path's G-buffer pass ([`Lighting::set_gbuffer`]).
    gbuffer: bool,
    /// Draws are staged for the stencil form of the target ([`Lighting::set_stencil_target`]).
    stencil_target: bool,
    /// What the public recording calls last bound, and into which command buffer (module
    /// docs, "Bindings"): the next such call into the same command buffer binds only what
    /// differs. Cleared by [`Lighting::begin_frame`] and [`Lighting::forget_bindings`].
    remembered: std::sync::Mutex<Option<Remembered>>,
    device: Arc<Device>,
}

impl Lighting {
    /// Creates the layouts, the cache (unless the options pass one) and empty frame slots
    /// on `device`, which may be ffvk's own or a caller's
    /// ([`Device::from_caller`](crate::vk::Device::from_caller)). Fails on what
    /// [`LightingOptions::validate`] refuses, on a target or vertex layout the device cannot
    /// take (formats without the features ffvk uses them with, sample counts outside its
    /// framebuffer sample counts, strides and offsets past its limits), or on a set index it
    /// cannot bind.
    pub fn new(device: &Arc<Device>, options: &LightingOptions) -> Result<Self> {
        options.validate()?;
        // The texture's set goes right after the block's, the records' after it.
        let max_sets = device.limits.max_bound_descriptor_sets;
        if options.set_index.checked_add(2).is_none_or(|top| top >= max_sets) {
            return Err(LightingError::SetIndex {
                index: options.set_index,
                max: max_sets.saturating_sub(3),
            }
            .into());
        }
        let pipelines = Pipelines::new(
            device,
            PipelineConfig::new(options.target, options.vertex_input.clone())
                .with_set_index(options.set_index)
                .with_cache(options.pipeline_cache),
        )?;
        let slots = options.frames_in_flight;
        Ok(Lighting {
            states: Ring::new(
                device,
                slots,
                RingUse::Uniforms,
                std::mem::size_of::<StateBlock>(),
            )?,
            records: Ring::new(
                device,
                slots,
                RingUse::InstanceData,
                std::mem::size_of::<DrawRecord>(),
            )?,
            unit_sets: UnitSets::new(device, slots),
            pipelines,
            specialize: options.specialize,
            last: None,
            id: NEXT_LIGHTING.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
            gbuffer: false,
            stencil_target: false,
            remembered: std::sync::Mutex::new(None),
            device: device.clone(),
        })
    }

    /// The device the pipelines live on.
    pub fn device(&self) -> &Arc<Device> {
        &self.device
    }

    /// Adds a vertex layout draws may name ([`LitDraw::with_layout`]), checked as
    /// [`Lighting::new`] checks the options' (formats it takes, offsets within strides, the
    /// device's limits and vertex formats), and returns its handle; a layout equal to one added
    /// before (or to the options') gets that one's handle. Pipelines are made per layout, on
    /// the first draw that needs one; the texture bindings, frame slots and state blocks serve
    /// every layout.
    pub fn vertex_layout(&mut self, input: VertexInput) -> Result<VertexLayout> {
        let index = self.pipelines.add_layout(input)?;
        Ok(VertexLayout {
            index,
            owner: self.id,
        })
    }

    /// The number of `draw`'s layout, refusing another `Lighting`'s.
    fn layout_of(&self, draw: &LitDraw) -> Result<u32> {
        match draw.layout {
            None => Ok(0),
            Some(l) if l.owner == self.id => Ok(l.index),
            Some(l) => Err(LightingError::ForeignLayout { layout: l.index }.into()),
        }
    }

    /// The layout numbered `layout`.
    fn input(&self, layout: u32) -> Result<&VertexInput> {
        self.pipelines
            .vertex_layout(layout)
            .ok_or(crate::Error::Internal("a vertex layout number past those added"))
    }

    /// Starts recording the draws of frame slot `slot`: its earlier draws' state memory is
    /// reused. Call it only when no submitted work still uses that slot (its fence has
    /// signalled).
    pub fn begin_frame(&mut self, slot: u32) -> Result<()> {
        self.states.reset(slot)?;
        self.records.reset(slot)?;
        self.unit_sets.reset(slot)?;
        self.forget_bindings();
        if self.last.as_ref().is_some_and(|last| last.slot == slot) {
            self.last = None;
        }
        Ok(())
    }

    /// How many frame slots there are.
    pub fn frames_in_flight(&self) -> u32 {
        self.states.slots()
    }

    /// Creates the pipeline a draw of `state` with `raster`, textured or not (with a texture
    /// on every unit), would use, so that the first such draw does not pay for it (pipeline
    /// creation is the slow part of a cold start).
    pub fn prepare(&mut self, state: &FixedFunctionState, raster: RasterState, textured: bool) -> Result<()> {
        let all = (1 << MAX_TEXTURE_UNITS) - 1;
        let bound = if textured { (all, all) } else { (0, 0) };
        self.prepare_sized(state, raster, bound, false)?;
        if state.mode == LightingMode::Fragment {
            // Small draws of the fragment mode have a pipeline of their own.
            self.prepare_sized(state, raster, bound, true)?;
        }
        Ok(())
    }

    /// [`Lighting::prepare`] for draws of one size (`small` when they fetch fewer than
    /// [`SMALL_DRAW_VERTICES`] vertices) with a 2D texture bound on the units `bound.0` names
    /// and a cube map on those of `bound.1`.
    pub(crate) fn prepare_sized(
        &mut self,
        state: &FixedFunctionState,
        raster: RasterState,
        bound: (u32, u32),
        small: bool,
    ) -> Result<()> {
        let small = small && state.mode == LightingMode::Fragment;
        // Draws with an affine modelview, as nearly all are.
        let variant = Variant {
            layout: 0,
            units: units_key(&state.texture_units, bound.0, bound.1),
            small,
            affine: !self.input(0)?.positions_have_w(),
            assembly: (Topology::TriangleList, false),
            gbuffer: false,
            stencil_target: self.stencil_target,
            clipped: state.clip.mask() != 0,
            fogged: state.fragment.fog.enabled,
            points: PointKey::OFF,
        };
        self.pipeline_for(state, raster, variant).map(|_| ())
    }

    /// How many pipelines exist, and how many of them are specialized.
    pub fn pipeline_counts(&self) -> (usize, usize) {
        self.pipelines.counts()
    }

    /// Records one lit draw into `cmd` for frame slot `slot`: binds its pipeline (created now
    /// if it is new), writes its state into the slot's memory and binds it, binds the
    /// caller's buffers and draws, binding only what differs from what ffvk remembers having
    /// bound in `cmd` (module docs, "Bindings").
    ///
    /// What it costs against [`Lighting::draw_run`]: the same checks and binds, but each draw
    /// is a draw command of its own, where a run draws consecutive draws of one geometry as
    /// instances of one command. On lavapipe (`ffvk bench`'s draws sweep, BENCHMARKS.md "Many
    /// draws") a frame recorded draw by draw takes within 1.25× of the run's time where draws
    /// have meshes of their own or few share one, and 1.3-1.8× for 10,000 quads sharing one
    /// mesh. A caller that can collect the draws between two commands of its own should pass
    /// them as a run. Fails, recording nothing, when the state is invalid (a
    /// NaN, or a singular modelview while lighting), when the buffers do not match the
    /// vertex layout, or when the pipeline cannot be made.
    ///
    /// # Safety
    ///
    /// `cmd` is a command buffer of this device in the recording state, inside a dynamic
    /// rendering pass whose attachments have the [`Target`](super::pipeline::Target)'s formats and samples, with
    /// viewport and scissor set; the buffers belong to this device, hold what the geometry
    /// reads, and live until the command buffer has finished executing; the slot was begun
    /// with [`Lighting::begin_frame`] after its previous use finished; since ffvk last drew into
    /// `cmd`, the caller bound nothing of its own there and did not reset it, or called
    /// [`Lighting::forget_bindings`] after doing so (module docs, "Bindings").
    pub unsafe fn draw(&mut self, cmd: vk::CommandBuffer, slot: u32, draw: &LitDraw) -> Result<()> {
        let staged = self.stage(slot, draw, false)?;
        let bound = self.bound(&staged, draw);
        // SAFETY: the caller's contract above: what ffvk remembers as bound in `cmd` is bound.
        self.with_remembered(cmd, |run| unsafe {
            record_in_run(&self.device.raw, cmd, &bound, &draw.geometry, run)
        });
        Ok(())
    }

    /// The first half of [`Lighting::draw`]: checks the draw, packs its state into the slot's
    /// uniform memory and finds its pipeline. What it returns may be recorded any number of
    /// times in the slot's frame ([`Lighting::record_staged`]): a frame repeated for
    /// measurement writes its uniforms once. `same_state` says that the draw's state and
    /// projection are those of the draw staged just before in this slot (the same borrowed
    /// state in one run, which cannot have changed in between): its block is reused unchecked.
    pub(crate) fn stage(&mut self, slot: u32, draw: &LitDraw, same_state: bool) -> Result<Staged> {
        let layout = self.layout_of(draw)?;
        let input = self.input(layout)?;
        let positions_have_w = input.positions_have_w();
        let bindings = &input.bindings;
        if draw.vertex_buffers.len() != bindings.len() {
            return Err(LightingError::VertexBuffers {
                given: draw.vertex_buffers.len(),
                expected: bindings.len(),
            }
            .into());
        }
        draw.raster.validate()?;
        draw.geometry.validate()?;
        Self::check_targets(draw)?;
        // The draw's own values, checked for every draw; the state, below, when it changed.
        let values = match &draw.values {
            Some(v) => *v,
            None => DrawValues::of(draw.state),
        };
        draw.state.check_draw(&values, draw.modelview)?;
        let record = DrawRecord::with_values(draw.state, &values, draw.modelview);
        // The state is compared in place with the last one's key; a key is made only for a
        // state that differs, and kept.
        let in_slot = self.last.as_ref().filter(|last| last.slot == slot);
        let changed = match in_slot {
            Some(_) if same_state => false,
            Some(last) => !last.key.matches(draw.state, draw.projection),
            None => true,
        };
        if changed {
            let key = StateKey::new(draw.state, draw.projection);
            draw.state.check_drawable()?;
            let block = StateBlock::new(draw.state, draw.projection);
            let block = self
                .states
                .push(slot, bytemuck::bytes_of(&block), self.pipelines.set_layout())?;
            self.last = Some(LastState {
                slot,
                key,
                block,
                pipelines: Vec::new(),
            });
        }
        let (mode, raster) = (draw.state.mode, draw.raster);
        // A small draw of the fragment mode takes its materials as flat varyings; a larger one
        // reads them from its record, bound for its fragment stage.
        // (The G-buffer pass has no small variant: its draws bind their record like large ones.)
        let small =
            !self.gbuffer && mode == LightingMode::Fragment && draw.geometry.fetched() < SMALL_DRAW_VERTICES;
        // An affine modelview puts every vertex without a w at w = 1
        // (SpecConstant::FiniteVertices).
        let units = Self::units(draw);
        let variant = Variant {
            layout,
            units,
            small,
            affine: draw.modelview.row(3) == glam::Vec4::W && !positions_have_w,
            assembly: draw.geometry.assembly(),
            gbuffer: self.gbuffer && mode == LightingMode::Fragment,
            stencil_target: self.stencil_target,
            clipped: draw.state.clip.mask() != 0,
            fogged: draw.state.fragment.fog.enabled,
            points: PointKey::of(draw.state, draw.geometry.assembly().0, units & 15),
        };
        let found = self.last.as_ref().and_then(|last| {
            last.pipelines
                .iter()
                .find(|p| (p.0, p.1, p.2) == (mode, raster, variant))
                .map(|p| p.3)
        });
        let pipeline = match found {
            Some(pipeline) => pipeline,
            None => {
                let pipeline = self.pipeline_for(draw.state, raster, variant)?;
                if let Some(last) = &mut self.last {
                    last.pipelines.push((mode, raster, variant, pipeline));
                }
                pipeline
            }
        };
        let block = self
            .last
            .as_ref()
            .map(|last| last.block)
            .ok_or(crate::Error::Internal("no state block after one was staged"))?;
        let record = self.records.push(
            slot,
            bytemuck::bytes_of(&record),
            self.pipelines.record_set_layout(),
        )?;
        let texture_set = if units == 0 {
            None
        } else {
            // Unit i samples its cube map (bit 8 + i) or its 2D texture (bit i alone).
            let textures: UnitTextures = std::array::from_fn(|i| {
                let cube = units & 256 << i != 0;
                let texture = if cube { draw.cube_maps[i] } else { draw.textures[i] };
                texture.filter(|_| units & 1 << i != 0).copied()
            });
            // SAFETY: the textures are the caller's live bindings (Lighting::bind_texture's
            // contract covers the command buffers this set is drawn in).
            Some(unsafe {
                self.unit_sets
                    .set_for(self.pipelines.texture_set_layout(), slot, textures)
            }?)
        };
        Ok(Staged {
            pipeline,
            layout,
            state: (block.set, block.offset),
            record: (record.buffer, record.index),
            record_block: (mode == LightingMode::Fragment && !small).then_some((record.set, record.offset)),
            texture_set,
        })
    }

    /// Stages `draws` in order ([`Lighting::stage`]), telling each whether it shares the draw
    /// before's state: the same borrowed [`FixedFunctionState`] (which cannot change while the run
    /// borrows it) and an equal projection.
    /// On failure, the index of the draw that failed and why.
    pub(crate) fn stage_run(
        &mut self,
        slot: u32,
        draws: &[LitDraw],
    ) -> std::result::Result<Vec<Staged>, (usize, crate::Error)> {
        let mut staged = Vec::with_capacity(draws.len());
        for (i, draw) in draws.iter().enumerate() {
            let same = i
                .checked_sub(1)
                .and_then(|before| draws.get(before))
                .is_some_and(|before| {
                    std::ptr::eq(before.state, draw.state) && before.projection == draw.projection
                });
            staged.push(self.stage(slot, draw, same).map_err(|e| (i, e))?);
        }
        Ok(staged)
    }

    /// Checks `draw` and writes its state into slot `slot`'s memory, recording nothing: the
    /// first half of a run recorded draw by draw ([`Lighting::record_run`] is the second), for
    /// a caller that learns of its draws one at a time (an emulation layer's `glDrawElements`)
    /// and wants each bad one refused at once, with the draws before it kept. Fails as
    /// [`Lighting::draw`] does, leaving the draws staged before it valid.
    pub fn stage_draw(&mut self, slot: u32, draw: &LitDraw) -> Result<StagedDraw> {
        self.stage(slot, draw, false).map(StagedDraw)
    }

    /// Records draws staged with [`Lighting::stage_draw`] into `cmd` as one run, binding only
    /// what changes between them, as [`Lighting::draw_run`] does. Fails, recording nothing,
    /// when `staged` and `draws` differ in length.
    ///
    /// # Safety
    ///
    /// As [`Lighting::draw`], for every draw; `staged[i]` came from `stage_draw` with
    /// `draws[i]` (the same state, geometry, buffers and texture) in the slot this command
    /// buffer's frame uses, since the slot was last begun.
    pub unsafe fn record_run(
        &self,
        cmd: vk::CommandBuffer,
        staged: &[StagedDraw],
        draws: &[LitDraw],
    ) -> Result<()> {
        if staged.len() != draws.len() {
            return Err(crate::Error::Internal(
                "record_run: a staged draw for every draw, in the same order",
            ));
        }
        let staged: Vec<Staged> = staged.iter().map(|s| s.0).collect();
        // SAFETY: the caller's contract above: what ffvk remembers as bound in `cmd` is bound.
        self.with_remembered(cmd, |run| unsafe {
            self.record_staged_run_from(cmd, &staged, draws, run)
        });
        Ok(())
    }

    /// Records `draws` one after the other into `cmd` for frame slot `slot`, as
    /// [`Lighting::draw`] records each, but binding only what changes from one draw to the
    /// next: the pipeline when the state's key or the raster state changes, the vertex and
    /// index buffers when they do, the texture's set when it does (each draw's block is bound
    /// at its own offset), starting from what ffvk remembers having bound in `cmd` (module
    /// docs, "Bindings"). This is the recording scope of a run of draws: no command of the
    /// caller's comes between them, which lets ffvk draw consecutive draws of one geometry as
    /// instances of one draw command. Every draw is
    /// checked (and its block written) before anything is recorded, so a bad draw fails the
    /// run with nothing recorded, with [`Error::InRun`](crate::Error::InRun) naming the draw.
    ///
    /// # Safety
    ///
    /// As [`Lighting::draw`], for every draw of the run.
    pub unsafe fn draw_run(&mut self, cmd: vk::CommandBuffer, slot: u32, draws: &[LitDraw]) -> Result<()> {
        let staged = self
            .stage_run(slot, draws)
            .map_err(|(index, e)| crate::Error::InRun {
                index,
                source: Box::new(e),
            })?;
        // SAFETY: the caller's contract above; each staged entry was staged for its draw; what
        // ffvk remembers as bound in `cmd` is bound.
        self.with_remembered(cmd, |run| unsafe {
            self.record_staged_run_from(cmd, &staged, draws, run)
        });
        Ok(())
    }

    /// The second half of [`Lighting::draw_run`]: binds what each of `staged` found, only
    /// where it differs from the draw before, and draws.
    ///
    /// # Safety
    ///
    /// As [`Lighting::record_staged`], for every draw; `staged[i]` came from `draws[i]`.
    pub(crate) unsafe fn record_staged_run(
        &self,
        cmd: vk::CommandBuffer,
        staged: &[Staged],
        draws: &[LitDraw],
    ) {
        // SAFETY: the caller's contract above; nothing is taken as bound.
        unsafe { self.record_staged_run_from(cmd, staged, draws, &mut RunState::default()) }
    }

    /// Records `staged` one draw command each, as [`Lighting::draw`] per draw records them:
    /// each binds what differs from the draw before it.
    ///
    /// # Safety
    ///
    /// As [`Lighting::record_staged_run`].
    pub(crate) unsafe fn record_staged_draw_by_draw(
        &self,
        cmd: vk::CommandBuffer,
        staged: &[Staged],
        draws: &[LitDraw],
    ) {
        let mut run = RunState::default();
        for (staged, draw) in staged.iter().zip(draws) {
            let bound = self.bound(staged, draw);
            // SAFETY: the caller's contract above; `run` holds what the draws before bound.
            unsafe { record_in_run(&self.device.raw, cmd, &bound, &draw.geometry, &mut run) };
        }
    }

    /// [`Lighting::record_staged_run`] with `run` bound in `cmd` already.
    ///
    /// # Safety
    ///
    /// As [`Lighting::record_staged_run`]; what `run` records as bound is bound in `cmd`.
    unsafe fn record_staged_run_from(
        &self,
        cmd: vk::CommandBuffer,
        staged: &[Staged],
        draws: &[LitDraw],
        run: &mut RunState,
    ) {
        let mut at = 0;
        while let (Some(first), Some(draw)) = (staged.get(at), draws.get(at)) {
            // Consecutive draws of the same geometry with everything bound alike and their
            // records one after the other become instances of one draw command.
            let same = |i: usize| match (staged.get(i - 1), staged.get(i), draws.get(i - 1), draws.get(i)) {
                (Some(a), Some(b), Some(da), Some(db)) => {
                    (a.pipeline, a.state, a.record.0) == (b.pipeline, b.state, b.record.0)
                        && a.record.1.checked_add(1) == Some(b.record.1)
                        && a.record_block.is_none()
                        && da.geometry == db.geometry
                        && da.vertex_buffers == db.vertex_buffers
                        && a.texture_set == b.texture_set
                }
                _ => false,
            };
            let count = (at + 1..).take_while(|&i| same(i)).count() + 1;
            let mut bound = self.bound(first, draw);
            bound.draws = count as u32;
            // SAFETY: the caller's contract above; `run` holds what this loop bound in `cmd`,
            // and nothing else is recorded between its draws; the merged draws' records are
            // consecutive in one buffer.
            unsafe { record_in_run(&self.device.raw, cmd, &bound, &draw.geometry, run) };
            at += count;
        }
    }

    /// What `draw` binds, with what staging it found.
    fn bound<'a>(&'a self, staged: &Staged, draw: &LitDraw<'a>) -> Bound<'a> {
        let config = self.pipelines.config();
        // Staging found the layout: it exists.
        let input = self
            .pipelines
            .vertex_layout(staged.layout)
            .unwrap_or(&config.vertex_input);
        Bound {
            pipeline: staged.pipeline.0,
            second_pipeline: staged.pipeline.1,
            layout: self.pipelines.layout(),
            set_index: config.set_index,
            set: staged.state.0,
            uniform_offset: staged.state.1,
            texture_set: staged.texture_set,
            bindings: &input.bindings,
            vertex_buffers: draw.vertex_buffers,
            record_binding: input.record_binding(),
            record_buffer: staged.record.0,
            first_record: staged.record.1,
            draws: 1,
            record_block: staged.record_block,
        }
    }

    /// Draws staged from now on write the deferred path's G-buffer (fragment mode; the
    /// Renderer's deferred frames) instead of lighting.
    pub(crate) fn set_gbuffer(&mut self, on: bool) {
        self.gbuffer = on;
    }

    /// Draws staged from now on render into the target's stencil form
    /// ([`Target::with_stencil`](crate::Target::with_stencil)): the Renderer's frames that
    /// test the stencil buffer.
    pub(crate) fn set_stencil_target(&mut self, on: bool) {
        self.stencil_target = on;
    }

    /// The pipeline cache its pipelines are made through.
    pub(crate) fn pipeline_cache(&self) -> vk::PipelineCache {
        self.pipelines.cache()
    }

    /// Specialized pipelines or the uber-shader.
    pub(crate) fn specialize(&self) -> Specialize {
        self.specialize
    }

    /// The pipeline layout's state block set layout: the deferred lighting pass binds the
    /// same blocks.
    pub(crate) fn state_set_layout(&self) -> &crate::vk::objects::DescriptorSetLayout {
        self.pipelines.set_layout()
    }
}
