//! The zink anchor: Mesa's GL on Vulkan (zink), fixed function included, on the Vulkan driver
//! ffvk runs on: the peer that does ffvk's job by another road. It draws the GL anchor's
//! points (the same scenes, the same calls) in a process of its own, since Mesa picks its GL
//! driver from the environment once per process (`LIBGL_ALWAYS_SOFTWARE=1
//! GALLIUM_DRIVER=zink` for a CPU device such as lavapipe, `MESA_LOADER_DRIVER_OVERRIDE=zink`
//! for a GPU), and the llvmpipe anchor lives in this one.
//!
//! The parent runs `ffvk bench --anchor-worker` from its own executable, writes an
//! [`AnchorRequest`] (the sweep's configuration and the Vulkan device's name) as JSON to the
//! child's stdin, and reads an [`AnchorAnswer`] as JSON from its stdout. A child that cannot
//! start, whose GL is not zink, or that fails, leaves zink out with a note saying why.

use std::io::{Read, Write};
use std::path::Path;
use std::process::{Command, Stdio};

use serde::{Deserialize, Serialize};

use super::draws::{gl_draws, DrawsResult};
use super::measure::{GlAnchor, PointStats};
use super::points::points;
use super::sweep::{Engine, Point, SweepConfig};
use crate::{Error, Result};
use ffvk::mesh::MeshData;

/// What the parent asks of the anchor's process.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct AnchorRequest {
    /// The sweep whose GL points (and draws sweep) the child draws.
    pub config: SweepConfig,
    /// The Vulkan device's name: the child's GL must be on it.
    pub vulkan_device: String,
}

/// What the anchor's process answers.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct AnchorAnswer {
    /// GL_RENDERER ("zink (llvmpipe (LLVM 15.0.6, 256 bits))").
    pub renderer: String,
    /// GL_VERSION.
    pub version: String,
    /// One entry per GL point of the sweep ([`points`] with engine GL, in order); `None` for a
    /// point with more lights than the context has.
    pub points: Vec<Option<PointStats>>,
    /// The draws sweep's points, labelled [`Engine::Zink`].
    pub draws: Vec<DrawsResult>,
}

/// What the zink anchor measured, merged into a run.
pub(super) struct ZinkRun {
    /// GL_RENDERER.
    pub renderer: String,
    /// GL_VERSION.
    pub version: String,
    /// The GL points of the sweep, relabelled [`Engine::Zink`], with what zink measured.
    pub points: Vec<(Point, PointStats)>,
    /// The draws sweep's zink points.
    pub draws: Vec<DrawsResult>,
}

/// The environment that makes Mesa's GL zink on the device of type `device_type`
/// (`VkPhysicalDeviceType` as ffvk spells it), and the variables to remove.
fn zink_environment(device_type: &str) -> (Vec<(&'static str, &'static str)>, Vec<&'static str>) {
    if super::is_gpu(device_type) {
        (
            vec![("MESA_LOADER_DRIVER_OVERRIDE", "zink")],
            vec!["LIBGL_ALWAYS_SOFTWARE", "GALLIUM_DRIVER"],
        )
    } else {
        (
            vec![("LIBGL_ALWAYS_SOFTWARE", "1"), ("GALLIUM_DRIVER", "zink")],
            vec!["MESA_LOADER_DRIVER_OVERRIDE"],
        )
    }
}

/// Runs the zink anchor for `config` in a child process of `program` (ffvk's executable),
/// on the Vulkan device `vulkan_device` of type `device_type`; `None` with a note when zink
/// cannot be had.
pub(super) fn run_zink(
    program: &Path,
    config: &SweepConfig,
    (vulkan_device, device_type): (&str, &str),
    notes: &mut Vec<String>,
) -> Option<ZinkRun> {
    match ask(program, config, vulkan_device, device_type) {
        Ok(answer) => merge(config, answer, notes),
        Err(e) => {
            notes.push(format!("zink anchor left out: {e}"));
            None
        }
    }
}

fn ask(program: &Path, config: &SweepConfig, vulkan_device: &str, device_type: &str) -> Result<AnchorAnswer> {
    let request = AnchorRequest {
        config: config.clone(),
        vulkan_device: vulkan_device.to_string(),
    };
    let json = serde_json::to_vec(&request).map_err(|e| Error::Bench(format!("the zink request: {e}")))?;
    let (set, remove) = zink_environment(device_type);
    let mut command = Command::new(program);
    command
        .args(["bench", "--anchor-worker"])
        .envs(set)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    for name in remove {
        command.env_remove(name);
    }
    let mut child = command
        .spawn()
        .map_err(|e| Error::Bench(format!("{} could not start: {e}", program.display())))?;
    let written = child.stdin.take().map(|mut stdin| stdin.write_all(&json));
    let output = child
        .wait_with_output()
        .map_err(|e| Error::Bench(format!("its process: {e}")))?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    let said = stderr.trim();
    if !output.status.success() {
        return Err(Error::Bench(format!(
            "its process failed ({}): {}",
            output.status,
            if said.is_empty() { "no message" } else { said }
        )));
    }
    if let Some(Err(e)) = written {
        return Err(Error::Bench(format!("writing its request: {e}")));
    }
    let answer: AnchorAnswer = serde_json::from_slice(&output.stdout)
        .map_err(|e| Error::Bench(format!("its process answered out of protocol: {e}")))?;
    if !answer.renderer.to_ascii_lowercase().contains("zink") {
        return Err(Error::Bench(format!(
            "the GL driver loaded {:?}, not zink (Mesa's zink driver missing?)",
            answer.renderer
        )));
    }
    Ok(answer)
}

/// The answer's points next to the sweep's GL points, relabelled zink.
fn merge(config: &SweepConfig, answer: AnchorAnswer, notes: &mut Vec<String>) -> Option<ZinkRun> {
    let gl_points: Vec<Point> = points(config)
        .into_iter()
        .filter(|p| p.engine == Engine::Gl)
        .collect();
    if gl_points.len() != answer.points.len() {
        notes.push(format!(
            "zink anchor left out: it answered {} points for the sweep's {}",
            answer.points.len(),
            gl_points.len()
        ));
        return None;
    }
    let mut left_out = 0;
    let mut merged = Vec::new();
    for (mut point, stats) in gl_points.into_iter().zip(answer.points) {
        match stats {
            Some(stats) => {
                point.engine = Engine::Zink;
                merged.push((point, stats));
            }
            None => left_out += 1,
        }
    }
    if left_out > 0 {
        notes.push(format!(
            "{left_out} zink points with more lights than its GL_MAX_LIGHTS are left out"
        ));
    }
    Some(ZinkRun {
        renderer: answer.renderer,
        version: answer.version,
        points: merged,
        draws: answer.draws,
    })
}

/// `ffvk bench --anchor-worker`: reads an [`AnchorRequest`] from stdin, draws the sweep's GL
/// points and draws sweep with this process's GL (zink, as the parent set the environment),
/// and writes the [`AnchorAnswer`] to stdout.
pub fn answer_request() -> Result<()> {
    let mut input = Vec::new();
    std::io::stdin()
        .read_to_end(&mut input)
        .map_err(|e| Error::Bench(format!("reading the anchor request: {e}")))?;
    let request: AnchorRequest =
        serde_json::from_slice(&input).map_err(|e| Error::Bench(format!("the anchor request: {e}")))?;
    let config = &request.config;
    config.validate()?;
    if config.malloc_no_trim && !super::keep_freed_memory() {
        return Err(Error::Bench(
            "glibc's mallopt refused --malloc-no-trim's settings".into(),
        ));
    }
    let mut notes = Vec::new();
    let Some(gl) = GlAnchor::open(true, &request.vulkan_device, &mut notes) else {
        return Err(Error::Bench(notes.join("; ")));
    };
    let mut stats = Vec::new();
    let mut mesh: Option<(u32, MeshData)> = None;
    for point in points(config).iter().filter(|p| p.engine == Engine::Gl) {
        if point.lights > gl.max_lights {
            stats.push(None);
            continue;
        }
        if mesh.as_ref().is_none_or(|(stacks, _)| *stacks != point.stacks) {
            mesh = Some((point.stacks, MeshData::uv_sphere(2 * point.stacks, point.stacks)));
        }
        let (_, data) = mesh.as_ref().expect("made above");
        stats.push(Some(gl.measure(&point.primitive.mesh(data), point, config)?));
    }
    let draws = gl_draws(config, &gl, Engine::Zink)?;
    let answer = AnchorAnswer {
        renderer: gl.renderer.clone(),
        version: gl.version.clone(),
        points: stats,
        draws,
    };
    let json = serde_json::to_string(&answer).map_err(|e| Error::Bench(format!("the anchor answer: {e}")))?;
    crate::outln!("{json}")?;
    Ok(())
}
