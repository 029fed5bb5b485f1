//! Measuring: the frames of one point (warm-up, then timed frames) through ffvk or the GL
//! anchor, their spread, and what the results of a sweep show (crossovers, speedups, ratios).

use std::collections::BTreeMap;
use std::time::Instant;

use serde::{Deserialize, Serialize};

use super::points::{matrices, point_state, CLEAR};
use super::stage_textures::{StageTextures, UploadedTextures};
use super::sweep::{BenchMode, Engine, Group, Point, SweepConfig, Variant};
use super::BenchResult;
use crate::gl_reference::{gl_info_with, time_frames_with, GlDraw, GlOptions, GlScene};
use crate::Result;
use ffvk::draw::pipeline::Specialize;
use ffvk::mesh::MeshData;
use ffvk::renderer::{Draw, Frame, FrameStats, Mesh, Renderer};

/// Median, quartiles and extremes of a point's frames.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub struct Spread {
    /// The median (the figure a point reports).
    pub median: f64,
    /// The fastest frame.
    pub min: f64,
    /// The first quartile.
    pub p25: f64,
    /// The third quartile.
    pub p75: f64,
    /// The slowest frame.
    pub max: f64,
}

impl Spread {
    /// The spread of `samples` (linear interpolation between order statistics); `None`
    /// when there are none.
    pub fn of(samples: &[f64]) -> Option<Spread> {
        let mut s: Vec<f64> = samples.iter().copied().filter(|v| v.is_finite()).collect();
        if s.is_empty() {
            return None;
        }
        s.sort_by(f64::total_cmp);
        let at = |q: f64| {
            let pos = q * (s.len() - 1) as f64;
            let (lo, hi) = (pos.floor() as usize, pos.ceil() as usize);
            s[lo] + (s[hi] - s[lo]) * (pos - lo as f64)
        };
        Some(Spread {
            median: at(0.5),
            min: s[0],
            p25: at(0.25),
            p75: at(0.75),
            max: s[s.len() - 1],
        })
    }
}

/// What a point measured.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PointStats {
    /// Unmeasured frames before the measured ones.
    pub warmup: u32,
    /// Measured frames.
    pub frames: u32,
    /// Host time of the first warm-up frame, ms: it includes creating the pipeline and
    /// lavapipe's lazy fragment-shader compile when the point is the first to need them.
    pub first_frame_ms: f64,
    /// Timestamps around the rendering pass (ffvk only), ms.
    pub gpu_ms: Option<Spread>,
    /// Host time per frame, ms: submit to fence for ffvk; draw calls to glFinish for GL.
    pub wall_ms: Spread,
    /// The figure the tables and plots use: `gpu_ms` for ffvk, `wall_ms` for GL (medians).
    pub time_ms: f64,
    /// Vertex-shader invocations of the last frame (ffvk only; the same every frame).
    pub vs_invocations: Option<u64>,
    /// Fragment-shader invocations of the last frame (ffvk only).
    pub fs_invocations: Option<u64>,
    /// Primitives out of the clipper in the last frame (ffvk only).
    pub clipping_primitives: Option<u64>,
    /// Pixels the drawing covers (those not left at the clear color), counted in a frame read
    /// back after the measured ones (ffvk's fragment sweep only).
    pub covered_pixels: Option<u64>,
    /// The deferred path's own count of the pixels its lighting pass evaluated the equation at
    /// (deferred points only).
    pub evaluations: Option<u64>,
    /// A deferred frame's G-buffer pass alone, from a timestamp between its two passes, ms
    /// (deferred points only).
    pub gbuffer_ms: Option<Spread>,
    /// A deferred frame's lighting pass alone (the frame's time less its G-buffer pass's,
    /// frame by frame), ms (deferred points only).
    pub lighting_ms: Option<Spread>,
}

/// ffvk against GL on one scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GlRatio {
    /// The sweep of the scene.
    pub group: Group,
    /// The lighting mode of both.
    pub mode: BenchMode,
    /// The sphere's vertices.
    pub vertices: u64,
    /// The image's pixels.
    pub pixels: u64,
    /// Enabled lights.
    pub lights: usize,
    /// ffvk's host time per frame (submit to fence), specialized pipelines, ms.
    pub ffvk_wall_ms: f64,
    /// ffvk's timestamps, ms.
    pub ffvk_gpu_ms: Option<f64>,
    /// GL's host time per frame (draw to glFinish), ms.
    pub gl_wall_ms: f64,
    /// GL's GL_TIME_ELAPSED per frame, ms (batched sweeps, where the driver has timer
    /// queries).
    pub gl_gpu_ms: Option<f64>,
    /// ffvk's time over GL's: GPU time over GPU time where GL's was measured (batched
    /// sweeps), else host time over host time. Below 1, ffvk is faster.
    pub ratio: f64,
}

/// What one more vertex, pixel or light costs in one mode, fitted to the sweeps by least
/// squares (time against the count, the other counts fixed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Costs {
    /// Who drew it.
    pub engine: Engine,
    /// The lighting mode.
    pub mode: BenchMode,
    /// The density sweep's slope against vertices drawn (vertices × draws per frame), ns.
    pub ns_per_vertex: Option<f64>,
    /// The density sweep's intercept: the frame's cost without geometry (clears, layout
    /// changes, the fixed cost of a frame and of its draws), ns.
    pub fixed_ns: Option<f64>,
    /// The size sweep's slope against pixels drawn (pixels × draws per frame), ns.
    pub ns_per_pixel: Option<f64>,
    /// The light sweep's slope against enabled lights: one more light in a frame, ns.
    pub ns_per_light: Option<f64>,
    /// That slope per evaluation of the equation: per vertex shaded in vertex and flat
    /// mode, per fragment shaded in fragment mode (from the pipeline statistics), ns.
    pub ns_per_light_evaluation: Option<f64>,
}

/// What the sweep shows, computed from its results.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// Vertices (at the base image size) where vertex and fragment mode cost the same.
    pub crossover_vertices: Option<f64>,
    /// Pixels (with the base mesh) where vertex and fragment mode cost the same.
    pub crossover_pixels: Option<f64>,
    /// Per mode: geometric mean over the light sweeps of uber time / specialized time.
    pub specialization_speedup: BTreeMap<String, f64>,
    /// What ffvk uses by default, after this measurement.
    pub default_specialize: String,
    /// ffvk's specialized pipelines against GL on every scene that both drew.
    pub gl_ratios: Vec<GlRatio>,
    /// Geometric mean of the vertex-mode ratios.
    pub gl_vertex_ratio_geomean: Option<f64>,
    /// Per engine and mode: the cost of a vertex, a pixel and a light.
    pub costs: Vec<Costs>,
}

// ---------------------------------------------------------------------------------------------
// Running.

pub(super) fn measure_ffvk(
    renderer: &mut Renderer,
    mesh: &Mesh,
    point: &Point,
    config: &SweepConfig,
) -> Result<PointStats> {
    // The stage's textures, uploaded before the frames are timed (as a program loads them).
    let textures = StageTextures::of(point.stage)?.upload(renderer)?;
    let frame = ffvk_frame(mesh, point, &textures)?;
    let deferred = matches!(point.variant, Variant::Deferred | Variant::DeferredUber);
    let start = Instant::now();
    renderer.measure(&frame)?;
    let first_frame_ms = start.elapsed().as_secs_f64() * 1e3;
    let samples = if config.batch {
        if config.warmup > 1 {
            renderer.measure_frames(&frame, config.warmup - 1)?;
        }
        let mut samples = renderer.measure_frames(&frame, config.frames)?;
        // The counters come from a frame of their own: the statistics query costs GPU time
        // on some devices, so the timed frames go without it.
        let counted = renderer.measure(&frame)?;
        if let Some(last) = samples.last_mut() {
            last.pipeline = counted.pipeline;
            last.evaluations = counted.evaluations;
            last.deferred = counted.deferred;
        }
        samples
    } else {
        for _ in 1..config.warmup {
            renderer.measure(&frame)?;
        }
        (0..config.frames)
            .map(|_| renderer.measure(&frame))
            .collect::<ffvk::Result<Vec<FrameStats>>>()?
    };
    let gpu: Vec<f64> = samples
        .iter()
        .filter_map(|s| s.gpu_ns)
        .map(|ns| ns / 1e6)
        .collect();
    let wall: Vec<f64> = samples.iter().map(|s| s.wall_ns / 1e6).collect();
    let gpu_ms = Spread::of(&gpu);
    // A deferred frame's two passes, from the timestamp between them.
    let split: Vec<(f64, f64)> = samples
        .iter()
        .filter_map(|s| Some((s.gbuffer_ns? / 1e6, (s.gpu_ns? - s.gbuffer_ns?) / 1e6)))
        .collect();
    let gbuffer_ms = Spread::of(&split.iter().map(|s| s.0).collect::<Vec<_>>());
    let lighting_ms = Spread::of(&split.iter().map(|s| s.1).collect::<Vec<_>>());
    let wall_ms = Spread::of(&wall).expect("at least one frame");
    if deferred && !samples.last().is_some_and(|s| s.deferred) {
        return Err(crate::Error::Bench(format!(
            "{}: the frame was drawn forward, not deferred",
            point.label()
        )));
    }
    let evaluations = samples.last().and_then(|s| s.evaluations);
    let last = samples.last().and_then(|s| s.pipeline);
    let covered_pixels = if matches!(point.group, Group::Fragment | Group::Paths) {
        Some(covered(&renderer.render(&frame)?))
    } else {
        None
    };
    Ok(PointStats {
        warmup: config.warmup,
        frames: config.frames,
        first_frame_ms,
        time_ms: gpu_ms.map_or(wall_ms.median, |g| g.median),
        gpu_ms,
        wall_ms,
        vs_invocations: last.map(|p| p.vertex_shader_invocations),
        fs_invocations: last.map(|p| p.fragment_shader_invocations),
        clipping_primitives: last.map(|p| p.clipping_primitives),
        covered_pixels,
        evaluations,
        gbuffer_ms,
        lighting_ms,
    })
}

/// The frame ffvk draws at `point`: its draws of `mesh` with the stage's `textures` (uploaded
/// by [`StageTextures::upload`]).
pub fn ffvk_frame<'a>(mesh: &'a Mesh, point: &Point, textures: &'a UploadedTextures) -> Result<Frame<'a>> {
    let (modelviews, projection) = matrices(point);
    let state = point_state(point)?;
    let mut frame = Frame::new(point.width, point.height);
    frame.clear_color = CLEAR;
    if matches!(point.variant, Variant::Deferred | Variant::DeferredUber) {
        frame.fragment_path = ffvk::FragmentPath::Deferred;
    }
    frame.draws = modelviews
        .into_iter()
        .map(|modelview| textures.bind(Draw::new(mesh, modelview, projection, state)))
        .collect();
    Ok(frame)
}

/// The GL scene the anchor draws at `point`: the same draws of `mesh` with the stage's
/// textures.
pub fn gl_scene<'a>(mesh: &'a MeshData, point: &Point, textures: &'a StageTextures) -> Result<GlScene<'a>> {
    let (modelviews, projection) = matrices(point);
    let state = point_state(point)?;
    Ok(GlScene {
        width: point.width,
        height: point.height,
        clear_color: CLEAR.to_array(),
        depth_test: true,
        draws: modelviews
            .into_iter()
            .map(|modelview| textures.bind_gl(GlDraw::new(mesh, modelview, projection, state)))
            .collect(),
    })
}

/// The pixels of `image` not at the clear color, read at its top-left corner (the sphere
/// lies in the middle of the view and never reaches it).
fn covered(image: &ffvk::Pixels) -> u64 {
    let rgba = image.rgba();
    let clear = rgba.get(..4).unwrap_or_default();
    rgba.chunks_exact(4).filter(|p| *p != clear).count() as u64
}

/// Fixed-function GL through the GL reference renderer, on the device that runs ffvk.
pub(super) struct GlAnchor {
    pub(super) renderer: String,
    pub(super) version: String,
    pub(super) max_lights: usize,
    /// The device the anchor was found on, kept for every measurement.
    options: GlOptions,
}

impl GlAnchor {
    /// The GL context on the Vulkan device named `vulkan_device` (the same rasterizer as
    /// ffvk's: llvmpipe for lavapipe), or `None` with a note saying why not.
    pub(super) fn open(wanted: bool, vulkan_device: &str, notes: &mut Vec<String>) -> Option<GlAnchor> {
        if !wanted {
            notes.push("GL anchor not requested".into());
            return None;
        }
        let options = GlOptions {
            vulkan_name: Some(vulkan_device.to_string()),
            ..GlOptions::default()
        };
        match gl_info_with(&options) {
            Ok(info) => Some(GlAnchor {
                renderer: info.renderer,
                version: info.version,
                max_lights: usize::try_from(info.max_lights).unwrap_or(0),
                options,
            }),
            Err(e) => {
                notes.push(format!("GL anchor left out: {e}"));
                None
            }
        }
    }

    /// The device the anchor draws on.
    pub(super) fn options(&self) -> &GlOptions {
        &self.options
    }

    pub(super) fn measure(&self, mesh: &MeshData, point: &Point, config: &SweepConfig) -> Result<PointStats> {
        let textures = StageTextures::of(point.stage)?;
        let scene = gl_scene(mesh, point, &textures)?;
        let timing = time_frames_with(&scene, config.warmup, config.frames, &self.options)?;
        let wall: Vec<f64> = timing.frame_ns.iter().map(|ns| ns / 1e6).collect();
        let wall_ms = Spread::of(&wall).expect("at least one frame");
        // GL's GPU time only in batched sweeps, where ffvk's is taken the same way; the
        // lavapipe sweeps compare with llvmpipe's host time as before.
        let gpu_ms = timing
            .gpu_ns
            .filter(|_| config.batch)
            .and_then(|ns| Spread::of(&ns.iter().map(|ns| ns / 1e6).collect::<Vec<_>>()));
        Ok(PointStats {
            warmup: config.warmup,
            frames: config.frames,
            first_frame_ms: timing.first_frame_ns / 1e6,
            gpu_ms,
            wall_ms,
            time_ms: gpu_ms.map_or(wall_ms.median, |g| g.median),
            vs_invocations: None,
            fs_invocations: None,
            clipping_primitives: None,
            covered_pixels: None,
            evaluations: None,
            gbuffer_ms: None,
            lighting_ms: None,
        })
    }
}

// ---------------------------------------------------------------------------------------------
// What the results show.

/// (x, time) of one series, sorted by x.
pub(super) fn series(
    results: &[BenchResult],
    keep: impl Fn(&Point) -> bool,
    x: impl Fn(&Point) -> f64,
) -> Vec<(f64, &BenchResult)> {
    let mut s: Vec<(f64, &BenchResult)> = results
        .iter()
        .filter(|r| keep(&r.point))
        .map(|r| (x(&r.point), r))
        .collect();
    s.sort_by(|a, b| a.0.total_cmp(&b.0));
    s
}

/// Where `a` and `b` (times at the same x values) cost the same: the first sign change of
/// ln a − ln b, interpolated in log-log. `None` when one stays below the other.
pub fn crossover(a: &[(f64, f64)], b: &[(f64, f64)]) -> Option<f64> {
    let mut d: Vec<(f64, f64)> = Vec::new();
    for &(x, ta) in a {
        if let Some(&(_, tb)) = b.iter().find(|(xb, _)| *xb == x) {
            if x > 0.0 && ta > 0.0 && tb > 0.0 {
                d.push((x.ln(), ta.ln() - tb.ln()));
            }
        }
    }
    d.windows(2).find_map(|w| {
        let ((x0, d0), (x1, d1)) = (w[0], w[1]);
        if d0 == 0.0 {
            return Some(x0.exp());
        }
        if (d0 < 0.0) != (d1 < 0.0) || d1 == 0.0 {
            let t = d0 / (d0 - d1);
            Some((x0 + t * (x1 - x0)).exp())
        } else {
            None
        }
    })
}

fn geomean(values: impl IntoIterator<Item = f64>) -> Option<f64> {
    let (sum, n) = values
        .into_iter()
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((0.0, 0usize), |(s, n), v| (s + v.ln(), n + 1));
    (n > 0).then(|| (sum / n as f64).exp())
}

fn times(s: &[(f64, &BenchResult)]) -> Vec<(f64, f64)> {
    s.iter().map(|(x, r)| (*x, r.stats.time_ms)).collect()
}

pub(super) fn is(group: Group, engine: Engine, mode: BenchMode, variant: Variant) -> impl Fn(&Point) -> bool {
    move |p: &Point| p.group == group && p.engine == engine && p.mode == mode && p.variant == variant
}

/// The crossovers, the specialization speedups and the GL ratios of `results`.
pub fn summarize(results: &[BenchResult]) -> Summary {
    let spec = Variant::Specialized;
    let by_vertices = |mode| {
        times(&series(
            results,
            is(Group::Density, Engine::Ffvk, mode, spec),
            |p| p.vertices as f64,
        ))
    };
    let by_pixels = |mode| {
        times(&series(results, is(Group::Size, Engine::Ffvk, mode, spec), |p| {
            p.pixels as f64
        }))
    };
    let crossover_vertices = crossover(&by_vertices(BenchMode::Vertex), &by_vertices(BenchMode::Fragment));
    let crossover_pixels = crossover(&by_pixels(BenchMode::Vertex), &by_pixels(BenchMode::Fragment));

    // Uber / specialized over every point that ran both but the stages sweep's (its table has
    // them), so that the summary reads as before the stages.
    let mut speedups: BTreeMap<String, Vec<f64>> = BTreeMap::new();
    for r in results
        .iter()
        .filter(|r| r.point.variant == Variant::Uber && r.point.group != Group::Stages)
    {
        let twin = results.iter().find(|s| {
            s.point
                == Point {
                    variant: Variant::Specialized,
                    ..r.point.clone()
                }
        });
        if let Some(s) = twin {
            speedups
                .entry(r.point.mode.name().to_string())
                .or_default()
                .push(r.stats.time_ms / s.stats.time_ms);
        }
    }
    let specialization_speedup: BTreeMap<String, f64> = speedups
        .into_iter()
        .filter_map(|(mode, v)| geomean(v).map(|g| (mode, g)))
        .collect();
    let default_specialize = match geomean(specialization_speedup.values().copied()) {
        Some(g) if g < 1.0 => format!(
            "{} (the uber-shader measured faster here: consider Specialize::Never)",
            Specialize::default().name()
        ),
        _ => format!("{} (specialized pipelines)", Specialize::default().name()),
    };

    let mut gl_ratios = Vec::new();
    // The primitives and stages sweeps have tables of their own; the summary's ratios stay
    // those of lit triangles without stages.
    for g in results.iter().filter(|r| {
        r.point.engine == Engine::Gl && !matches!(r.point.group, Group::Primitives | Group::Stages)
    }) {
        let twin = results.iter().find(|s| {
            s.point
                == Point {
                    engine: Engine::Ffvk,
                    variant: spec,
                    ..g.point.clone()
                }
        });
        if let Some(f) = twin {
            let gl_gpu_ms = g.stats.gpu_ms.map(|s| s.median);
            let ratio = match gl_gpu_ms {
                Some(gl) => f.stats.time_ms / gl,
                None => f.stats.wall_ms.median / g.stats.wall_ms.median,
            };
            gl_ratios.push(GlRatio {
                group: g.point.group,
                mode: g.point.mode,
                vertices: g.point.vertices,
                pixels: g.point.pixels,
                lights: g.point.lights,
                ffvk_wall_ms: f.stats.wall_ms.median,
                ffvk_gpu_ms: f.stats.gpu_ms.map(|s| s.median),
                gl_wall_ms: g.stats.wall_ms.median,
                gl_gpu_ms,
                ratio,
            });
        }
    }
    let gl_vertex_ratio_geomean = geomean(
        gl_ratios
            .iter()
            .filter(|r| r.mode == BenchMode::Vertex)
            .map(|r| r.ratio),
    );
    Summary {
        crossover_vertices,
        crossover_pixels,
        specialization_speedup,
        default_specialize,
        gl_ratios,
        gl_vertex_ratio_geomean,
        costs: costs(results),
    }
}

/// Least-squares line through `points`: (slope, intercept), or `None` with fewer than two
/// distinct x.
pub fn fit_line(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let n = points.len() as f64;
    let mean_x = points.iter().map(|p| p.0).sum::<f64>() / n;
    let mean_y = points.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = points.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
    (points.len() >= 2 && sxx > 0.0).then(|| {
        let slope = sxy / sxx;
        (slope, mean_y - slope * mean_x)
    })
}

/// The costs of every engine and mode that ran the density, size or light sweep
/// (specialized pipelines for ffvk).
fn costs(results: &[BenchResult]) -> Vec<Costs> {
    let mut out = Vec::new();
    for (engine, variant) in [
        (Engine::Ffvk, Variant::Specialized),
        (Engine::Gl, Variant::FixedFunction),
    ] {
        for mode in BenchMode::ALL {
            let ns = |group, x: fn(&Point) -> f64| -> Vec<(f64, f64)> {
                series(results, is(group, engine, mode, variant), x)
                    .iter()
                    .map(|(x, r)| (*x, r.stats.time_ms * 1e6))
                    .collect()
            };
            let density = fit_line(&ns(Group::Density, |p| (p.vertices * u64::from(p.draws)) as f64));
            let size = fit_line(&ns(Group::Size, |p| (p.pixels * u64::from(p.draws)) as f64));
            let lights = fit_line(&ns(Group::Lights, |p| p.lights as f64));
            if density.is_none() && size.is_none() && lights.is_none() {
                continue;
            }
            // Evaluations per frame at the light sweep's points (the same mesh and image).
            let evaluations = results
                .iter()
                .filter(|r| is(Group::Lights, engine, mode, variant)(&r.point))
                .find_map(|r| match mode {
                    BenchMode::Fragment => r.stats.fs_invocations,
                    _ => r.stats.vs_invocations,
                })
                .filter(|&n| n > 0);
            let ns_per_light = lights.map(|(slope, _)| slope);
            out.push(Costs {
                engine,
                mode,
                ns_per_vertex: density.map(|(slope, _)| slope),
                fixed_ns: density.map(|(_, intercept)| intercept),
                ns_per_pixel: size.map(|(slope, _)| slope),
                ns_per_light,
                ns_per_light_evaluation: ns_per_light.zip(evaluations).map(|(ns, n)| ns / n as f64),
            });
        }
    }
    out
}
