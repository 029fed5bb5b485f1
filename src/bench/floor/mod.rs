//! The floor: the draws sweep's frames ([`super::draws`], vertex mode) drawn by a small plain
//! Vulkan program, without ffvk's pipelines, renderer or lighting: what lavapipe can do at
//! best on the same frame, and so where ffvk cannot reach GL's speed.
//!
//! The program has its own device ([`context`]), its own shaders (`glsl/floor/`: GL 2.1's
//! equation for exactly the sweep's directional and point light, no branch on a uniform
//! value), and draws each frame through one of five data paths for the draws' own values
//! (a 128-byte record per draw: the modelview's affine rows, the normal matrix, the front
//! diffuse, specular and shininess; [`scene::Record`]):
//!
//! - `instance_attributes`: per-instance vertex attributes from one buffer, one
//!   `vkCmdDrawIndexed` per draw whose `firstInstance` names its record;
//! - `instance_attributes_instanced` (one mesh only): the same, every draw an instance of one
//!   draw command;
//! - `storage_draw_id`: a storage buffer indexed by `gl_DrawID`, the draws in
//!   `vkCmdDrawMultiIndexedEXT` batches of `maxMultiDrawCount` (VK_EXT_multi_draw); for a
//!   mesh each, the meshes packed into one vertex and index buffer, each draw's place its
//!   firstIndex and vertexOffset;
//! - `uniform_offsets`: a uniform buffer, the descriptor set bound again at the draw's dynamic
//!   offset before each draw;
//! - `push_constants`: the record pushed before each draw.
//!
//! The per-draw paths draw a mesh each from its own buffers, bound before each draw, as the
//! sweep's frame has it. A frame's time runs from writing the draws' records (the buffer
//! paths' per-frame upload; push constants are written while recording) through recording
//! the command buffer anew, submission and the fence: what `run_point` times of ffvk.

mod context;
mod pipelines;
mod render;
mod scene;

use std::time::Instant;

use indicatif::ProgressBar;
use serde::{Deserialize, Serialize};

use super::draws::{DrawShape, DrawsResult, SIZE, SPHERES};
use super::measure::Spread;
use super::sweep::{BenchMode, Engine, SweepConfig};
use crate::Result;
use ffvk::RendererOptions;
use render::Floor;
use scene::FloorScene;

/// How the floor hands the draws' own values to its vertex stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FloorPath {
    /// Per-instance vertex attributes, a draw command per draw.
    InstanceAttributes,
    /// Per-instance vertex attributes, all draws one instanced command (one mesh only).
    InstanceAttributesInstanced,
    /// A storage buffer indexed by `gl_DrawID`, in multi-draws (VK_EXT_multi_draw).
    StorageDrawId,
    /// A uniform buffer at a dynamic offset per draw.
    UniformOffsets,
    /// Push constants per draw.
    PushConstants,
}

impl FloorPath {
    /// Every path, in the order the floor runs them.
    pub const ALL: [FloorPath; 5] = [
        FloorPath::InstanceAttributes,
        FloorPath::InstanceAttributesInstanced,
        FloorPath::StorageDrawId,
        FloorPath::UniformOffsets,
        FloorPath::PushConstants,
    ];

    /// How reports name it.
    pub fn name(self) -> &'static str {
        match self {
            FloorPath::InstanceAttributes => "instance_attributes",
            FloorPath::InstanceAttributesInstanced => "instance_attributes_instanced",
            FloorPath::StorageDrawId => "storage_draw_id",
            FloorPath::UniformOffsets => "uniform_offsets",
            FloorPath::PushConstants => "push_constants",
        }
    }

    /// Whether it draws frames of `shape` (the instanced path needs one mesh).
    pub fn draws_shape(self, shape: DrawShape) -> bool {
        self != FloorPath::InstanceAttributesInstanced || shape != DrawShape::QuadMeshEach
    }

    fn kind(self) -> pipelines::Kind {
        match self {
            FloorPath::InstanceAttributes | FloorPath::InstanceAttributesInstanced => {
                pipelines::Kind::Instance
            }
            FloorPath::StorageDrawId => pipelines::Kind::Storage,
            FloorPath::UniformOffsets => pipelines::Kind::Uniform,
            FloorPath::PushConstants => pipelines::Kind::Push,
        }
    }
}

/// One frame class through one path.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FloorResult {
    /// The data path.
    pub path: FloorPath,
    /// What the draws draw.
    pub shape: DrawShape,
    /// Draws per frame.
    pub draws: u32,
    /// Each measured frame's host time, ms: writing the records, recording, submission and
    /// the fence.
    pub frame_ms: Spread,
}

/// The floor's frame classes in a sweep of `draw_counts`: the spheres' frame, and both quad
/// shapes at the largest count; none without counts.
pub fn frame_classes(draw_counts: &[u32]) -> Vec<(DrawShape, u32)> {
    let Some(&most) = draw_counts.iter().max() else {
        return Vec::new();
    };
    vec![
        (DrawShape::Spheres, SPHERES),
        (DrawShape::OneQuadMesh, most),
        (DrawShape::QuadMeshEach, most),
        (DrawShape::DenseSphere, 1),
    ]
}

/// Times the floor's frame classes of `config` through every path the device has (at the
/// sweep's 512²), on the device and with the validation `options` ask for. Paths the device
/// cannot draw are left out with a note in `notes`.
pub(super) fn run_floor(
    config: &SweepConfig,
    options: &RendererOptions,
    progress: &ProgressBar,
    notes: &mut Vec<String>,
) -> Result<Vec<FloorResult>> {
    let classes = frame_classes(&config.draw_counts);
    if classes.is_empty() {
        return Ok(Vec::new());
    }
    let mut floor = Floor::new(options.device.as_deref(), options.validation, SIZE)?;
    for path in FloorPath::ALL.into_iter().filter(|&p| !floor.can(p)) {
        notes.push(format!(
            "the floor's {} path is left out: the device has no VK_EXT_multi_draw (with shaderDrawParameters)",
            path.name()
        ));
    }
    let mut out = Vec::new();
    for (shape, draws) in classes {
        floor.load(FloorScene::new(shape, draws)?)?;
        for path in FloorPath::ALL {
            if !floor.can(path) || !path.draws_shape(shape) {
                continue;
            }
            progress.set_message(format!("floor: {} {draws} {}", shape.name(), path.name()));
            for _ in 0..config.warmup {
                floor.frame(path, false)?;
            }
            let mut wall = Vec::with_capacity(config.frames as usize);
            for _ in 0..config.frames {
                let start = Instant::now();
                floor.frame(path, false)?;
                wall.push(start.elapsed().as_secs_f64() * 1e3);
            }
            out.push(FloorResult {
                path,
                shape,
                draws,
                frame_ms: Spread::of(&wall).unwrap_or_default(),
            });
        }
    }
    floor.close()?;
    Ok(out)
}

/// The floor's image of the draws sweep's frame of `draws` draws of `shape` at `size`²,
/// through each path the device can draw it through (RGBA, row 0 at the top, as
/// [`ffvk::Pixels::rgba`]): what the tests compare with ffvk's image of
/// [`super::draws::draws_frame`]. The validation layer's messages are errors.
pub fn floor_images(
    options: &RendererOptions,
    shape: DrawShape,
    draws: u32,
    size: u32,
) -> Result<Vec<(FloorPath, Vec<u8>)>> {
    let mut floor = Floor::new(options.device.as_deref(), options.validation, size)?;
    floor.load(FloorScene::new(shape, draws)?)?;
    let mut out = Vec::new();
    for path in FloorPath::ALL {
        if floor.can(path) && path.draws_shape(shape) {
            if let Some(image) = floor.frame(path, true)? {
                out.push((path, image));
            }
        }
    }
    floor.close()?;
    Ok(out)
}

/// The floor as a Markdown table, each frame against GL's and zink's of the same frame class
/// in vertex mode (from the draws sweep's `draws`).
pub fn floor_markdown(floor: &[FloorResult], draws: &[DrawsResult]) -> String {
    if floor.is_empty() {
        return String::new();
    }
    let mut md = String::from(
        "### Floor: the same frames in plain Vulkan\n\n\
         The draws sweep's vertex-mode frames drawn by a small Vulkan program of its own on the \
         same device, without ffvk: its own two shaders (GL's equation for exactly these two \
         lights, no branch on a uniform value) and one 128-byte record per draw (modelview, \
         normal matrix, diffuse, specular, shininess), handed over through each data path; \
         host time per frame from writing the records through recording, submission and the \
         fence, medians. ÷ GL and ÷ zink: the floor's time over theirs on the same frame; \
         where it is above 1, no Vulkan program on this driver reaches their speed.\n\n\
         | path | frame | draws | ms | ÷ GL | ÷ zink |\n\
         | --- | --- | ---: | ---: | ---: | ---: |\n",
    );
    for r in floor {
        let anchor = |engine: Engine| {
            draws
                .iter()
                .find(|d| {
                    d.engine == engine
                        && d.shape == r.shape
                        && d.mode == BenchMode::Vertex
                        && d.draws == r.draws
                })
                .map(|d| r.frame_ms.median / d.frame_ms.median)
        };
        let fmt = |v: Option<f64>| v.map_or("—".into(), |v| format!("{v:.2}"));
        md.push_str(&format!(
            "| {} | {} | {} | {:.2} | {} | {} |\n",
            r.path.name(),
            r.shape.name(),
            r.draws,
            r.frame_ms.median,
            fmt(anchor(Engine::Gl)),
            fmt(anchor(Engine::Zink)),
        ));
    }
    md
}
