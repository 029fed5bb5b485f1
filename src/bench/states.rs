//! Frames of several lighting states on the fragment mode's two paths (issue 53): the draws
//! sweep's frames in the fragment mode, their draws split among a number of lighting states
//! (each state's point light elsewhere), drawn forward and deferred. The deferred path lights
//! them with a lighting pass per state, each scissored to its draws; how the states lie on
//! screen decides how much of the target each pass covers, so both layouts are measured:
//! states in bands of consecutive draws (an emulation layer changing lights between groups
//! of objects), and states interleaved draw by draw (every pass's rectangle the whole grid).

use glam::Vec4;
use indicatif::ProgressBar;
use serde::{Deserialize, Serialize};

use super::draws::{draws_frame, DrawShape, SIZE};
use super::format::{ms, ratio};
use super::measure::Spread;
use super::sweep::{BenchMode, SweepConfig};
use crate::table::{Align, Table};
use crate::Result;
use ffvk::{FragmentPath, Renderer};

/// The frames' shapes and draw counts: the draws sweep's 1,000 quads and 1,024 spheres.
pub const STATE_FRAMES: [(DrawShape, u32); 2] =
    [(DrawShape::OneQuadMesh, 1_000), (DrawShape::Spheres, 1_024)];

/// The numbers of lighting states a frame's draws are split among.
pub const STATE_COUNTS: [u32; 4] = [1, 4, 16, 64];

/// How a frame's draws are given their states.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StateLayout {
    /// Consecutive draws share a state: each state a band of the grid.
    Bands,
    /// Draw i under state i mod the count: every state all over the grid.
    Interleaved,
}

impl StateLayout {
    /// How the report names it.
    pub fn name(self) -> &'static str {
        match self {
            StateLayout::Bands => "bands",
            StateLayout::Interleaved => "interleaved",
        }
    }

    /// The state of draw `i` of `draws` under `states` states.
    fn state_of(self, i: u32, draws: u32, states: u32) -> u32 {
        match self {
            StateLayout::Bands => (u64::from(i) * u64::from(states) / u64::from(draws.max(1))) as u32,
            StateLayout::Interleaved => i % states.max(1),
        }
    }
}

/// One frame of several states on one path.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StatesResult {
    /// What the draws draw.
    pub shape: DrawShape,
    /// Draws per frame.
    pub draws: u32,
    /// Lighting states the draws are split among.
    pub states: u32,
    /// How the draws are given their states.
    pub layout: StateLayout,
    /// Whether the deferred path was asked for (else forward).
    pub deferred_asked: bool,
    /// Whether the frame took the deferred path.
    pub deferred: bool,
    /// The frame's device time (timestamps around its passes), ms.
    pub device_ms: Option<Spread>,
    /// A deferred frame's G-buffer pass alone, ms.
    pub gbuffer_ms: Option<Spread>,
}

/// Runs the frames of several states with `renderer` (fragment mode, [`SIZE`]²).
pub(super) fn run_states(
    config: &SweepConfig,
    renderer: &mut Renderer,
    progress: &ProgressBar,
) -> Result<Vec<StatesResult>> {
    let mut out = Vec::new();
    for (shape, draws) in STATE_FRAMES {
        let mesh = renderer.upload(&shape.mesh())?;
        let meshes = [mesh];
        for states in STATE_COUNTS {
            for layout in [StateLayout::Bands, StateLayout::Interleaved] {
                // One state has one layout.
                if states == 1 && layout == StateLayout::Interleaved {
                    continue;
                }
                for deferred_asked in [false, true] {
                    progress.set_message(format!(
                        "states: {} {draws}, {states} states {}",
                        shape.name(),
                        layout.name()
                    ));
                    let mut frame = draws_frame(shape, draws, BenchMode::Fragment, SIZE, &meshes)?;
                    for (i, d) in frame.draws.iter_mut().enumerate() {
                        // State s: the point light (light 1) moved s steps along x.
                        let s = layout.state_of(i as u32, draws, states);
                        let x = 1.0 - 2.0 * s as f32 / states as f32;
                        d.state.lights[1].position = Vec4::new(x, 1.0, 1.0, 1.0);
                    }
                    frame.fragment_path = match deferred_asked {
                        true => FragmentPath::Deferred,
                        false => FragmentPath::Forward,
                    };
                    for _ in 0..config.warmup.max(1) {
                        renderer.measure_frames(&frame, 1)?;
                    }
                    let mut samples = Vec::new();
                    for _ in 0..config.frames.max(1) {
                        samples.extend(renderer.measure_frames(&frame, 1)?);
                    }
                    let spread = |f: &dyn Fn(&ffvk::FrameStats) -> Option<f64>| {
                        Spread::of(
                            &samples
                                .iter()
                                .filter_map(f)
                                .map(|ns| ns / 1e6)
                                .collect::<Vec<_>>(),
                        )
                    };
                    out.push(StatesResult {
                        shape,
                        draws,
                        states,
                        layout,
                        deferred_asked,
                        deferred: samples.iter().all(|s| s.deferred),
                        device_ms: spread(&|s| s.gpu_ns),
                        gbuffer_ms: spread(&|s| s.gbuffer_ns),
                    });
                }
            }
        }
    }
    Ok(out)
}

/// The frames of several states: per frame, forward and deferred device times, the deferred
/// frame's split, and whether it was drawn deferred.
pub(super) fn states_table(results: &[StatesResult]) -> Table {
    let mut t = Table::new([
        ("draws", Align::Left),
        ("states", Align::Right),
        ("layout", Align::Left),
        ("forward", Align::Right),
        ("deferred", Align::Right),
        ("G-buffer pass", Align::Right),
        ("lighting passes", Align::Right),
        ("deferred ÷ forward", Align::Right),
        ("drawn deferred", Align::Left),
    ]);
    let median = |s: &Option<Spread>| s.as_ref().map(|s| s.median);
    let text = |v: Option<f64>| v.map_or("–".into(), ms);
    for forward in results.iter().filter(|r| !r.deferred_asked) {
        let Some(deferred) = results.iter().find(|r| {
            r.deferred_asked
                && (r.shape, r.draws, r.states, r.layout)
                    == (forward.shape, forward.draws, forward.states, forward.layout)
        }) else {
            continue;
        };
        let (f, d, g) = (
            median(&forward.device_ms),
            median(&deferred.device_ms),
            median(&deferred.gbuffer_ms),
        );
        t.row([
            format!("{} {}", forward.draws, forward.shape.name()),
            forward.states.to_string(),
            forward.layout.name().to_string(),
            text(f),
            text(d),
            text(g),
            text(d.zip(g).map(|(d, g)| d - g)),
            ratio(d.zip(f).map(|(d, f)| d / f)),
            if deferred.deferred { "yes" } else { "no" }.to_string(),
        ]);
    }
    t
}

/// The note under the states table.
pub(super) fn states_note() -> String {
    format!(
        "The draws sweep's frames at {SIZE}² in the fragment mode (a directional and a point \
         light, each draw its own material), their draws split among the lighting states, each \
         state's point light elsewhere. Device time medians. \"lighting passes\": the deferred \
         frame less its G-buffer pass, a full-screen triangle per state scissored to the \
         rectangle its draws project to. Bands: consecutive draws share a state; interleaved: \
         draw i takes state i mod the count, so every state's rectangle is the whole grid. \
         Up to {} states take the deferred path.",
        ffvk::MAX_DEFERRED_STATES
    )
}
