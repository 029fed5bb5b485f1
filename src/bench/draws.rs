//! The draws sweep: frames of many small draws, each with its own material and modelview, as a
//! fixed-function emulation layer records them (a `glMaterial` and a `glLoadMatrix` before each
//! `glDrawElements`), under a directional and a point light; the GL anchor draws the same
//! calls. What it reports per point: the frame's host time (handed over to fence), the
//! host recording time and the device time per draw, and how much the process grew per frame.

use std::time::Instant;

use glam::{Mat4, Vec3, Vec4};
use indicatif::ProgressBar;
use serde::{Deserialize, Serialize};

use super::measure::{GlAnchor, Spread};
use super::points::CLEAR;
pub use super::sweep::MAX_DRAW_COUNT;
use super::sweep::{BenchMode, Engine, SweepConfig};
use crate::gl_reference::{time_frames_with, GlDraw, GlScene};
use crate::Result;
use ffvk::gl::state::{Cap, Face, FixedFunctionState, GlState, LightParam, MaterialParam};
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, Recording, Renderer};

/// The image side of the sweep's frames (the emulation frame of the issue that asked for it).
pub const SIZE: u32 = 512;

/// The modes the sweep draws.
pub const DRAW_MODES: [BenchMode; 3] = [BenchMode::Vertex, BenchMode::Fragment, BenchMode::Flat];

/// What the sweep's draws draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DrawShape {
    /// Every draw the same quad mesh: ffvk may draw consecutive draws as instances of one
    /// draw command (GL draws each, from its own buffer object).
    OneQuadMesh,
    /// Every draw a quad mesh of its own (its own vertex and index buffers): nothing merges,
    /// each draw is a draw command.
    QuadMeshEach,
    /// 1,024 spheres of 240 triangles sharing one mesh: the emulation frame whose cost is
    /// also its lit vertices.
    Spheres,
    /// One sphere of 131,841 vertices (the light sweeps' mesh) under the same two lights:
    /// dense vertex lighting, where the cost is the lit vertices alone.
    DenseSphere,
}

impl DrawShape {
    /// Every shape, in the order the sweep runs them.
    pub const ALL: [DrawShape; 4] = [
        DrawShape::OneQuadMesh,
        DrawShape::QuadMeshEach,
        DrawShape::Spheres,
        DrawShape::DenseSphere,
    ];

    /// How the report names it.
    pub fn name(self) -> &'static str {
        match self {
            DrawShape::OneQuadMesh => "quads, one mesh",
            DrawShape::QuadMeshEach => "quads, a mesh each",
            DrawShape::Spheres => "spheres, one mesh",
            DrawShape::DenseSphere => "one dense sphere",
        }
    }

    /// The draw counts of this shape in a sweep whose quad counts are `counts`: the spheres'
    /// frame has 1,024 draws, the dense sphere's one.
    pub fn counts(self, counts: &[u32]) -> Vec<u32> {
        match self {
            DrawShape::Spheres => vec![SPHERES],
            DrawShape::DenseSphere => vec![1],
            _ => counts.to_vec(),
        }
    }

    /// The mesh each draw draws.
    pub fn mesh(self) -> MeshData {
        match self {
            DrawShape::Spheres => MeshData::uv_sphere(12, 11),
            DrawShape::DenseSphere => MeshData::uv_sphere(512, 256),
            _ => quad(),
        }
    }

    /// The scale that fits the mesh in a grid cell of side 1.
    pub(crate) fn fit(self) -> f32 {
        match self {
            DrawShape::Spheres => 0.45,
            _ => 0.9,
        }
    }
}

/// The draws of the spheres' frame.
pub const SPHERES: u32 = 1_024;

/// One point of the draws sweep.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DrawsResult {
    /// Who drew it.
    pub engine: Engine,
    /// What the draws draw.
    pub shape: DrawShape,
    /// Where the equation is evaluated.
    pub mode: BenchMode,
    /// Draws per frame, each with its own material and modelview.
    pub draws: u32,
    /// The first frame (pipeline creation, GL's program build).
    pub first_frame_ms: f64,
    /// Each measured frame's host time, from the frame handed over to the fence signalled: for
    /// ffvk the whole `Renderer::measure` call (checking the draws, recording, submission, wait),
    /// for GL its calls and `glFinish`.
    pub frame_ms: Spread,
    /// ffvk: the same frame recorded one `Lighting::draw` per draw ([`Recording::DrawByDraw`]),
    /// host time per frame as `frame_ms`; `None` for GL and zink.
    pub draw_by_draw_ms: Option<Spread>,
    /// ffvk: each measured frame's time from submission to fence alone; `None` for GL.
    pub submit_ms: Option<Spread>,
    /// ffvk: the median host time to record one draw (checking its state, writing its block,
    /// binding and drawing), in µs; `None` for GL.
    pub record_us_per_draw: Option<f64>,
    /// The median device time of a frame (timestamps around the pass) divided by the draws,
    /// in µs, where the device has timestamps; `None` for GL.
    pub device_us_per_draw: Option<f64>,
    /// The process's resident memory after the measured frames less before them, per frame,
    /// in KiB (after the warm-up: what every further frame costs).
    pub rss_kib_per_frame: f64,
}

/// A quad of side 1 facing the viewer, each vertex white (the material gives the color).
fn quad() -> MeshData {
    let v = |x, y| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, Vec4::ONE);
    MeshData::new(
        vec![v(-0.5, -0.5), v(0.5, -0.5), v(0.5, 0.5), v(-0.5, 0.5)],
        vec![0, 1, 2, 0, 2, 3],
    )
}

/// The frame of `draws` quads: a grid filling the view, draw `i` with its own diffuse color and
/// shininess; a directional and a point light (the point light's attenuation is a per-light
/// term the shaders must evaluate for every draw).
pub(crate) fn scene(
    mode: BenchMode,
    draws: u32,
    fit: f32,
) -> Result<(Vec<(Mat4, FixedFunctionState)>, Mat4)> {
    let mut gl = GlState::new();
    gl.lighting_mode(mode.lighting_mode());
    for cap in [Cap::Lighting, Cap::Light(0), Cap::Light(1)] {
        gl.enable(cap)?;
    }
    gl.light(0, LightParam::Position(Vec4::new(0.3, 0.4, 1.0, 0.0)))?;
    gl.light(0, LightParam::Diffuse(Vec4::splat(0.6)))?;
    gl.light(1, LightParam::Position(Vec4::new(1.0, 1.0, 1.0, 1.0)))?;
    gl.light(1, LightParam::Diffuse(Vec4::splat(0.5)))?;
    gl.light(1, LightParam::Specular(Vec4::splat(0.5)))?;
    gl.light(1, LightParam::LinearAttenuation(0.2))?;
    gl.material(Face::FrontAndBack, MaterialParam::Specular(Vec4::splat(0.5)))?;
    let side = (f64::from(draws).sqrt().ceil() as u32).max(1);
    let cell = 2.0 / side as f32;
    let mut out = Vec::with_capacity(draws as usize);
    for i in 0..draws {
        let h = i as f32 / draws as f32;
        gl.material(
            Face::FrontAndBack,
            MaterialParam::Diffuse(Vec4::new(h, 1.0 - h, 0.5 + 0.5 * h, 1.0)),
        )?;
        gl.material(Face::FrontAndBack, MaterialParam::Shininess(4.0 + 60.0 * h))?;
        let (x, y) = ((i % side) as f32, (i / side) as f32);
        let at = Vec3::new(-1.0 + cell * (x + 0.5), -1.0 + cell * (y + 0.5), -2.0);
        let modelview = Mat4::from_translation(at) * Mat4::from_scale(Vec3::splat(cell * fit));
        out.push((modelview, gl.lighting));
    }
    // 2 units away, a 53° field of view shows the 2 × 2 grid whole.
    Ok((out, Mat4::perspective_rh_gl(53f32.to_radians(), 1.0, 0.5, 10.0)))
}

/// The process's resident memory in KiB (VmRSS); `None` where /proc does not say.
pub fn resident_kib() -> Option<u64> {
    std::fs::read_to_string("/proc/self/status").ok().and_then(|s| {
        s.lines()
            .find_map(|l| l.strip_prefix("VmRSS:"))
            .and_then(|v| v.split_whitespace().next())
            .and_then(|v| v.parse().ok())
    })
}

/// How much the process grew since `before` (KiB), per one of `frames`; 0 without /proc.
fn grown_per_frame(before: Option<u64>, frames: u32) -> f64 {
    match (before, resident_kib()) {
        (Some(before), Some(now)) => now.saturating_sub(before) as f64 / f64::from(frames),
        _ => 0.0,
    }
}

fn median(values: &[f64]) -> Option<f64> {
    Spread::of(values).map(|s| s.median)
}

/// One frame timed as an application draws it: timestamps around the pass, no pipeline
/// statistics query (lavapipe counts its statistics in every draw and every fragment shader
/// invocation while one is active, which no application frame pays).
fn frame_stats(renderer: &mut Renderer, frame: &Frame) -> Result<ffvk::FrameStats> {
    renderer
        .measure_frames(frame, 1)?
        .into_iter()
        .next()
        .ok_or_else(|| crate::Error::Bench("a timed frame returned no stats".into()))
}

/// Runs the draws sweep of `config` with `renderer` (and the GL anchor, when there is one).
pub(super) fn run_draws(
    config: &SweepConfig,
    renderer: &mut Renderer,
    gl: Option<&GlAnchor>,
    progress: &ProgressBar,
) -> Result<Vec<DrawsResult>> {
    let mut out = Vec::new();
    for shape in DrawShape::ALL {
        let mesh = shape.mesh();
        let counts = shape.counts(&config.draw_counts);
        let most = counts.iter().copied().max().unwrap_or(1);
        let meshes = match shape {
            DrawShape::QuadMeshEach => (0..most)
                .map(|_| renderer.upload(&mesh))
                .collect::<ffvk::Result<Vec<_>>>()?,
            _ => vec![renderer.upload(&mesh)?],
        };
        for &draws in &counts {
            for mode in DRAW_MODES {
                progress.set_message(format!("draws: {} {draws} {}", shape.name(), mode.name()));
                out.extend(run_point(
                    config,
                    renderer,
                    gl,
                    (shape, &mesh, &meshes),
                    draws,
                    mode,
                )?);
                progress.inc(1 + u64::from(gl.is_some()));
            }
        }
    }
    Ok(out)
}

/// The sweep's frame of `draws` draws of `shape` in `mode` at `size`², drawing `meshes` in
/// turn (uploads of [`DrawShape::mesh`]; one, or one per draw): what ffvk draws at a point,
/// and what the floor ([`super::floor`]) is checked against at any size.
pub fn draws_frame(
    shape: DrawShape,
    draws: u32,
    mode: BenchMode,
    size: u32,
    meshes: &[ffvk::Mesh],
) -> Result<Frame<'_>> {
    let (objects, projection) = scene(mode, draws, shape.fit())?;
    let mut frame = Frame::new(size, size);
    frame.clear_color = CLEAR;
    frame.draws = objects
        .iter()
        .zip(meshes.iter().cycle())
        .map(|((modelview, state), mesh)| Draw::new(mesh, *modelview, projection, *state))
        .collect();
    Ok(frame)
}

/// One point of the sweep: ffvk's frame of `draws` draws of `shape` in `mode` (drawing `meshes`
/// in turn, the uploads of `mesh`) and GL's of the same calls.
fn run_point(
    config: &SweepConfig,
    renderer: &mut Renderer,
    gl: Option<&GlAnchor>,
    (shape, mesh, meshes): (DrawShape, &MeshData, &[ffvk::Mesh]),
    draws: u32,
    mode: BenchMode,
) -> Result<Vec<DrawsResult>> {
    let mut out = Vec::new();
    let mut frame = draws_frame(shape, draws, mode, SIZE, meshes)?;
    let start = Instant::now();
    frame_stats(renderer, &frame)?;
    let first_frame_ms = start.elapsed().as_secs_f64() * 1e3;
    for _ in 1..config.warmup {
        frame_stats(renderer, &frame)?;
    }
    let before = resident_kib();
    let mut wall = Vec::new();
    let mut samples = Vec::new();
    for _ in 0..config.frames {
        let start = Instant::now();
        samples.push(frame_stats(renderer, &frame)?);
        wall.push(start.elapsed().as_secs_f64() * 1e3);
    }
    let grown = grown_per_frame(before, config.frames);
    // The same frame recorded as one `Lighting::draw` per draw records it.
    frame.recording = Recording::DrawByDraw;
    for _ in 0..config.warmup {
        frame_stats(renderer, &frame)?;
    }
    let mut by_draw = Vec::new();
    for _ in 0..config.frames {
        let start = Instant::now();
        frame_stats(renderer, &frame)?;
        by_draw.push(start.elapsed().as_secs_f64() * 1e3);
    }
    let per_draw = |ns: &[f64]| median(ns).map(|m| m / 1e3 / f64::from(draws));
    let submit: Vec<f64> = samples.iter().map(|s| s.wall_ns / 1e6).collect();
    let record: Vec<f64> = samples.iter().map(|s| s.record_ns).collect();
    let device: Vec<f64> = samples.iter().filter_map(|s| s.gpu_ns).collect();
    out.push(DrawsResult {
        engine: Engine::Ffvk,
        shape,
        mode,
        draws,
        first_frame_ms,
        frame_ms: Spread::of(&wall).unwrap_or_default(),
        draw_by_draw_ms: Spread::of(&by_draw),
        submit_ms: Spread::of(&submit),
        record_us_per_draw: per_draw(&record),
        device_us_per_draw: per_draw(&device),
        rss_kib_per_frame: grown,
    });

    if let Some(gl) = gl {
        out.push(gl_point(gl, Engine::Gl, config, (shape, mesh), draws, mode)?);
    }
    Ok(out)
}

/// The GL side of the draws sweep alone, every point in the order [`run_draws`] draws them,
/// labelled `engine`: what the zink anchor's process times ([`super::zink`]).
pub(super) fn gl_draws(config: &SweepConfig, gl: &GlAnchor, engine: Engine) -> Result<Vec<DrawsResult>> {
    let mut out = Vec::new();
    for shape in DrawShape::ALL {
        let mesh = shape.mesh();
        for draws in shape.counts(&config.draw_counts) {
            for mode in DRAW_MODES {
                out.push(gl_point(gl, engine, config, (shape, &mesh), draws, mode)?);
            }
        }
    }
    Ok(out)
}

/// One point of the sweep drawn by the GL anchor `gl` (reported as `engine`): the calls an
/// application issues for the frame ([`crate::gl_reference::time_frames`]), each draw from
/// its own buffer objects.
fn gl_point(
    gl: &GlAnchor,
    engine: Engine,
    config: &SweepConfig,
    (shape, mesh): (DrawShape, &MeshData),
    draws: u32,
    mode: BenchMode,
) -> Result<DrawsResult> {
    let (objects, projection) = scene(mode, draws, shape.fit())?;
    let scene = GlScene {
        width: SIZE,
        height: SIZE,
        clear_color: CLEAR.to_array(),
        depth_test: true,
        draws: objects
            .iter()
            .map(|(modelview, state)| GlDraw::new(mesh, *modelview, projection, *state))
            .collect(),
    };
    let before = resident_kib();
    let timing = time_frames_with(&scene, config.warmup, config.frames, gl.options())?;
    // The context (and its memory) lives for this call only: what it kept is counted
    // over all its frames, warm-up included.
    let grown = grown_per_frame(before, config.warmup + config.frames);
    let wall: Vec<f64> = timing.frame_ns.iter().map(|ns| ns / 1e6).collect();
    Ok(DrawsResult {
        engine,
        shape,
        mode,
        draws,
        first_frame_ms: timing.first_frame_ns / 1e6,
        frame_ms: Spread::of(&wall).unwrap_or_default(),
        draw_by_draw_ms: None,
        submit_ms: None,
        record_us_per_draw: None,
        device_us_per_draw: None,
        rss_kib_per_frame: grown,
    })
}

/// The draws sweep as a Markdown table: per draw count and mode, ffvk against GL and zink.
pub fn draws_markdown(results: &[DrawsResult]) -> String {
    if results.is_empty() {
        return String::new();
    }
    let mut md = String::from(
        "### Many draws, each with its own material\n\n\
         Frames of quads (or 1,024 spheres of 240 triangles) in a grid at 512², each draw with its \
         own diffuse color, shininess and modelview, under a directional light and a point light \
         with linear attenuation, both with specular; host time per frame, medians: ffvk from \
         the frame handed to the renderer (checking the draws, recording, submission) to the \
         fence, GL and zink from their first call to glFinish's return. The GL programs issue \
         what an application issues: the lights, light model and switches once per frame, then \
         per draw only what changed (a glMaterial per changed parameter, glLoadMatrix) and \
         glDrawElements, binding a draw's buffer objects when they differ from the draw \
         before's. GL is Mesa's llvmpipe in this process; zink is Mesa's GL on the same Vulkan \
         driver, in a process of its own. ffvk records the frame as one run \
         (`Lighting::draw_run`: with one mesh, consecutive draws become instances of one draw \
         command; with a mesh each, every draw is a command of its own), and again one \
         `Lighting::draw` per draw (\"by draw\": a command each, binding only what changed).\n\n\
         | meshes | draws | mode | ffvk ms | ffvk by draw ms | by draw ÷ run | GL ms | zink ms | ffvk ÷ GL | ffvk ÷ zink | ffvk record µs/draw | ffvk device µs/draw | ffvk RSS KiB/frame |\n\
         | --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    );
    let fmt = |v: Option<f64>, digits: usize| v.map_or("—".into(), |v| format!("{v:.digits$}"));
    for r in results.iter().filter(|r| r.engine == Engine::Ffvk) {
        let anchor = |engine: Engine| {
            results
                .iter()
                .find(|g| g.engine == engine && g.shape == r.shape && g.mode == r.mode && g.draws == r.draws)
                .map(|g| g.frame_ms.median)
        };
        let (gl, zink) = (anchor(Engine::Gl), anchor(Engine::Zink));
        md.push_str(&format!(
            "| {} | {} | {} | {:.2} | {} | {} | {} | {} | {} | {} | {} | {} | {:.0} |\n",
            r.shape.name(),
            r.draws,
            r.mode.name(),
            r.frame_ms.median,
            fmt(r.draw_by_draw_ms.map(|s| s.median), 2),
            fmt(r.draw_by_draw_ms.map(|s| s.median / r.frame_ms.median), 2),
            fmt(gl, 2),
            fmt(zink, 2),
            fmt(gl.map(|g| r.frame_ms.median / g), 2),
            fmt(zink.map(|z| r.frame_ms.median / z), 2),
            fmt(r.record_us_per_draw, 2),
            fmt(r.device_us_per_draw, 2),
            r.rss_kib_per_frame,
        ));
    }
    md
}
