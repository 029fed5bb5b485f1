//! The host cost of recording lit draws: what an emulation layer pays per draw call.
//!
//! One frame holds [`DRAWS`] draws of a small quad, each with its own lighting state (its own
//! material, so every draw writes a different record) but one specialization key, so
//! every pipeline exists before recording starts: the warm cost. The renderer times the loop
//! checking, packing and recording of the frame's draws ([`FrameStats::record_ns`]); then the
//! same frame with one material, each draw changing only its modelview. Packing a whole draw
//! ([`DrawBlock::new`], its lights included) is timed alone over the same states, so the
//! report can say what staging state only when it changes saves. A new specialization key costs a pipeline: its creation is
//! timed by [`Renderer::prepare`], and the first frame that draws with it is compared with
//! the next one (lavapipe compiles fragment code at the first draw).

use std::time::Instant;

// The embedding example's caller-side renderer (its own instance, device and command buffer
// with plain ash): what an emulation layer records through, measured as it would.
#[path = "../../ffvk/examples/embed.rs"]
#[allow(dead_code, clippy::all)]
mod embed;

use glam::{Mat4, Vec3, Vec4};
use serde::Serialize;

use super::measure::Spread;
use crate::{Error, Result};
use ffvk::gl::state::{Cap, Face, GlState, LightParam, LightingMode, MaterialParam};
use ffvk::gpu::layout::DrawBlock;
use ffvk::mesh::{MeshData, Vertex};
use ffvk::renderer::{Draw, Frame, FrameStats, Renderer};

/// Draws per measured frame in the standard sweeps.
pub const DRAWS: usize = 10_000;

/// What recording draws costs on the host.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DrawCost {
    /// Draws per measured frame, each with its own state.
    pub draws: usize,
    /// Measured frames (after one warm-up frame).
    pub frames: u32,
    /// Recording one warm draw with a state change, in µs: the median over frames of the
    /// frame's recording time divided by its draws.
    pub warm_us_per_draw: Spread,
    /// Recording one warm draw that changes only its modelview (the same material and lights
    /// as the draw before), in µs, as `warm_us_per_draw`.
    pub modelview_only_us_per_draw: Spread,
    /// Packing a whole draw alone, its state block and record ([`DrawBlock::new`]), in µs per
    /// draw: what a draw would cost if every draw changed the lights.
    pub pack_us_per_draw: Spread,
    /// Through `Lighting::draw_run` on a caller's device (the embedding example), each draw a
    /// command of its own: draws sharing one state, each with its own material
    /// (`LitDraw::with_values`) and modelview, µs per draw.
    pub run_own_values_us_per_draw: Spread,
    /// The same, each draw changing only its modelview.
    pub run_modelview_only_us_per_draw: Spread,
    /// The same, each draw with a whole state of its own.
    pub run_state_each_us_per_draw: Spread,
    /// Creating the pipeline of a new specialization key, in ms.
    pub new_key_create_ms: Spread,
    /// The first frame drawing with a new key, less the same frame drawn again, in ms
    /// (driver work deferred to the first draw).
    pub new_key_first_draw_ms: Spread,
}

/// A 2-triangle quad in the z = 0 plane facing +z.
fn quad() -> MeshData {
    let v = |x, y| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, Vec4::ONE);
    MeshData::new(
        vec![v(-0.5, -0.5), v(0.5, -0.5), v(0.5, 0.5), v(-0.5, 0.5)],
        vec![0, 1, 2, 0, 2, 3],
    )
}

/// Draw `k` of `draws`' state: two lights and a material of its own.
fn warm_state(k: usize, draws: usize) -> Result<GlState> {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting)?;
    gl.enable(Cap::Light(0))?;
    gl.enable(Cap::Light(1))?;
    gl.light(1, LightParam::Position(Vec4::new(-1.0, 1.0, 2.0, 1.0)))?;
    let t = k as f32 / draws as f32;
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Diffuse(Vec4::new(t, 1.0 - t, 0.5, 1.0)),
    )?;
    gl.material(Face::FrontAndBack, MaterialParam::Shininess(1.0 + 100.0 * t))?;
    Ok(gl)
}

/// A state whose specialization key no earlier state of this run had: `k + 1` lights, and
/// two-sided lighting on odd `k`.
fn new_key_state(k: usize) -> Result<GlState> {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting)?;
    for i in 0..=k {
        gl.enable(Cap::Light(i))?;
    }
    gl.lighting_mode(LightingMode::Fragment);
    gl.light_model(ffvk::gl::state::LightModelParam::TwoSide(k % 2 == 1))?;
    Ok(gl)
}

/// Measures the recording cost on `renderer` (which should specialize every state): `draws`
/// draws a frame over `frames` frames, and `new_keys` (at most 16) new specialization keys.
pub fn measure_draw_cost(
    renderer: &mut Renderer,
    device: Option<&str>,
    draws: usize,
    frames: u32,
    new_keys: usize,
) -> Result<DrawCost> {
    if frames == 0 || draws == 0 || new_keys == 0 || new_keys > ffvk::gl::state::MAX_LIGHTS {
        return Err(Error::Bench(format!(
            "draw cost with {draws} draws, {frames} frames and {new_keys} new keys: expected at least 1 of each and at most {} keys",
            ffvk::gl::state::MAX_LIGHTS
        )));
    }
    let mesh = renderer.upload(&quad())?;
    let states = (0..draws)
        .map(|k| warm_state(k, draws))
        .collect::<Result<Vec<_>>>()?;
    let projection = Mat4::orthographic_rh_gl(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    let mut frame = Frame::new(64, 64);
    frame.depth_test = false;
    frame.draws = states
        .iter()
        .map(|gl| Draw::new(&mesh, Mat4::IDENTITY, projection, gl.lighting))
        .collect();

    // One warm-up frame makes the pipeline and lets the driver finish compiling it.
    renderer.measure(&frame)?;
    let mut record = Vec::new();
    let mut pack = Vec::new();
    for _ in 0..frames {
        let stats: FrameStats = renderer.measure(&frame)?;
        record.push(stats.record_ns / 1e3 / draws as f64);
        let start = Instant::now();
        for d in &frame.draws {
            std::hint::black_box(DrawBlock::new(&d.state, d.modelview, d.projection)?);
        }
        pack.push(start.elapsed().as_nanos() as f64 / 1e3 / draws as f64);
    }

    // The same draws with one material: each changes only its modelview.
    let same = warm_state(0, draws)?;
    for (k, d) in frame.draws.iter_mut().enumerate() {
        d.state = same.lighting;
        d.modelview = Mat4::from_translation(Vec3::new(0.0, 0.0, -(k as f32) / draws as f32));
    }
    renderer.measure(&frame)?;
    let mut modelview_only = Vec::new();
    for _ in 0..frames {
        modelview_only.push(renderer.measure(&frame)?.record_ns / 1e3 / draws as f64);
    }

    let mut create = Vec::new();
    let mut first_draw = Vec::new();
    for k in 0..new_keys {
        let gl = new_key_state(k)?;
        create.push(renderer.prepare(&gl.lighting, false)? / 1e6);
        let mut one = Frame::new(64, 64);
        one.depth_test = false;
        one.draws
            .push(Draw::new(&mesh, Mat4::IDENTITY, projection, gl.lighting));
        let first = renderer.measure(&one)?.wall_ns;
        let again = renderer.measure(&one)?.wall_ns;
        first_draw.push((first - again) / 1e6);
    }
    let run = embed::record_times(device, draws as u32, frames)
        .map_err(|e| Error::Bench(format!("recording runs on a caller's device: {e}")))?;
    let us = |ns: &[f64]| ns.iter().map(|ns| ns / 1e3).collect::<Vec<_>>();
    let spread = |v: &[f64]| Spread::of(v).expect("at least one sample");
    Ok(DrawCost {
        draws,
        frames,
        warm_us_per_draw: spread(&record),
        modelview_only_us_per_draw: spread(&modelview_only),
        pack_us_per_draw: spread(&pack),
        run_own_values_us_per_draw: spread(&us(&run.shared_state_own_values)),
        run_modelview_only_us_per_draw: spread(&us(&run.modelview_only)),
        run_state_each_us_per_draw: spread(&us(&run.state_each)),
        new_key_create_ms: spread(&create),
        new_key_first_draw_ms: spread(&first_draw),
    })
}
