//! The outputs of a run: results.csv, results.json and summary.md (the plots are in
//! [`super::plots`]).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Serialize;

use super::format::{count, lights_text};
use super::measure::Spread;
use super::points::sphere_counts;
use super::sweep::{BenchMode, Engine, Group, Variant};
use super::tables::{
    costs_table, density_table, draw_cost_note, draw_cost_table, environment, equation_runs, fragment_point,
    fragment_table, light_count_table, light_kind_table, paths_note, paths_table, primitives_table,
    size_table, COSTS_NOTE, FRAGMENT_NOTE, FRAGMENT_PATHS,
};
use super::{BenchReport, BenchResult};
use crate::{write_file, Error, Result};

// ---------------------------------------------------------------------------------------------
// The files.

/// The CSV columns, in order.
pub const CSV_COLUMNS: [&str; 41] = [
    "group",
    "engine",
    "mode",
    "variant",
    "stacks",
    "vertices",
    "triangles",
    "width",
    "height",
    "pixels",
    "lights",
    "light_kind",
    "local_viewer",
    "draws",
    "primitive",
    "stage",
    "warmup",
    "frames",
    "time_ms",
    "gpu_ms_median",
    "gpu_ms_min",
    "gpu_ms_p25",
    "gpu_ms_p75",
    "gpu_ms_max",
    "wall_ms_median",
    "wall_ms_min",
    "wall_ms_p25",
    "wall_ms_p75",
    "wall_ms_max",
    "first_frame_ms",
    "vs_invocations",
    "fs_invocations",
    "clipping_primitives",
    "covered_pixels",
    "evaluations",
    "lp_num_threads",
    "device",
    "driver_info",
    "mesa_version",
    "optimized_build",
    "malloc_no_trim",
];

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The results as CSV: a header of [`CSV_COLUMNS`] and one row per point.
pub fn csv(report: &BenchReport) -> String {
    let mut out = CSV_COLUMNS.join(",");
    out.push('\n');
    let num = |v: f64| format!("{v:.4}");
    let opt_spread = |s: Option<Spread>| match s {
        Some(s) => [s.median, s.min, s.p25, s.p75, s.max].map(num),
        None => std::array::from_fn(|_| String::new()),
    };
    let opt = |v: Option<u64>| v.map_or(String::new(), |v| v.to_string());
    for r in &report.results {
        let p = &r.point;
        let s = &r.stats;
        let w = s.wall_ms;
        let mut row: Vec<String> = vec![
            serde_name(&p.group),
            serde_name(&p.engine),
            p.mode.name().into(),
            p.variant.name().into(),
            p.stacks.to_string(),
            p.vertices.to_string(),
            p.triangles.to_string(),
            p.width.to_string(),
            p.height.to_string(),
            p.pixels.to_string(),
            p.lights.to_string(),
            p.light_kind.name().into(),
            p.local_viewer.to_string(),
            p.draws.to_string(),
            serde_name(&p.primitive),
            serde_name(&p.stage),
            s.warmup.to_string(),
            s.frames.to_string(),
            num(s.time_ms),
        ];
        row.extend(opt_spread(s.gpu_ms));
        row.extend([w.median, w.min, w.p25, w.p75, w.max].map(num));
        row.extend([
            num(s.first_frame_ms),
            opt(s.vs_invocations),
            opt(s.fs_invocations),
            opt(s.clipping_primitives),
            opt(s.covered_pixels),
            opt(s.evaluations),
            r.lp_num_threads.clone(),
            r.device.clone(),
            r.driver_info.clone(),
            r.mesa_version.clone(),
            report.env.optimized_build.to_string(),
            report.sweep.malloc_no_trim.to_string(),
        ]);
        debug_assert_eq!(row.len(), CSV_COLUMNS.len());
        out.push_str(&row.iter().map(|f| csv_field(f)).collect::<Vec<_>>().join(","));
        out.push('\n');
    }
    out
}

/// The serde name of a unit enum variant ("density", "ffvk").
pub(super) fn serde_name<T: Serialize>(value: &T) -> String {
    match serde_json::to_value(value) {
        Ok(serde_json::Value::String(s)) => s,
        _ => String::new(),
    }
}

/// Writes results.csv, results.json, summary.md and the plots into `dir` (created when
/// missing); returns the paths written.
pub fn write_outputs(report: &BenchReport, dir: &Path) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut written = Vec::new();
    let path = dir.join("results.csv");
    write_file(&path, csv(report).as_bytes())?;
    written.push(path);
    let path = dir.join("results.json");
    let json = serde_json::to_string_pretty(report).map_err(|source| Error::Json {
        path: path.clone(),
        source,
    })?;
    write_file(&path, json.as_bytes())?;
    written.push(path);
    let path = dir.join("summary.md");
    write_file(&path, markdown(report).as_bytes())?;
    written.push(path);
    written.extend(super::plots::write_all(report, dir)?);
    Ok(written)
}

// ---------------------------------------------------------------------------------------------
// summary.md: the environment and one table per sweep, from rows of data.

/// The tables of a run, as Markdown (written to summary.md and quoted in BENCHMARKS.md).
pub fn markdown(report: &BenchReport) -> String {
    let c = &report.sweep;
    let has_gl = report.results.iter().any(|r| r.point.engine == Engine::Gl);
    let mut m = format!("### Environment\n\n{}\n", environment(report).markdown());
    m.push_str(if c.batch {
        "Times are per frame in ms: the median, then the interquartile range; ffvk's from \
         timestamps between frames recorded back to back in one submission, GL's from \
         GL_TIME_ELAPSED around each frame's clear and draws (the host clock around the draws \
         and glFinish where the driver has no timer queries).\n"
    } else {
        "Times are per frame in ms: the median, then the interquartile range; ffvk's from \
         timestamps around the rendering pass, GL's from the host clock around the draw and \
         glFinish.\n"
    });
    let sections = [
        (
            Group::Density,
            format!(
                "Time against vertex count ({}² image, {})",
                c.base_size,
                lights_text(c.base_lights)
            ),
            density_table(report, has_gl),
        ),
        (
            Group::Size,
            format!(
                "Time against pixel count ({} vertices, {})",
                sphere_counts(c.size_stacks).0,
                lights_text(c.base_lights)
            ),
            size_table(report),
        ),
        (
            Group::Lights,
            format!(
                "Light count: specialized pipelines against the uber-shader ({} vertices, {}², \
                 directional lights)",
                sphere_counts(c.base_stacks).0,
                c.base_size
            ),
            light_count_table(report, has_gl),
        ),
        (
            Group::Kind,
            format!(
                "Light kind ({} lights of one kind, {} vertices, {}²)",
                c.kind_lights,
                sphere_counts(c.base_stacks).0,
                c.base_size
            ),
            light_kind_table(report, has_gl),
        ),
        (
            Group::Primitives,
            format!(
                "Points and lines ({} vertices, {}², {}; lines: each triangle's three edges)",
                sphere_counts(c.base_stacks).0,
                c.base_size,
                lights_text(c.base_lights)
            ),
            primitives_table(report, has_gl),
        ),
    ];
    for (group, title, table) in sections {
        if report.results.iter().any(|r| r.point.group == group) {
            let _ = write!(m, "\n### {title}\n\n{}", table.markdown());
        }
    }
    if report.results.iter().any(|r| r.point.group == Group::Stages) {
        let _ = write!(
            m,
            "\n### The stages around lighting ({} vertices, {}², {})\n\n{}\n{}\n",
            sphere_counts(c.base_stacks).0,
            c.base_size,
            lights_text(c.base_lights),
            super::stages::stages_table(report, has_gl).markdown(),
            super::stages::STAGES_NOTE
        );
    }
    if !c.fragment_sizes.is_empty() {
        let _ = write!(
            m,
            "\n### Fragment lighting on a dense mesh ({} vertices, {})\n\n{}\n{}\n",
            sphere_counts(c.fragment_stacks).0,
            lights_text(c.fragment_lights),
            fragment_table(report).markdown(),
            FRAGMENT_NOTE
        );
    }
    if report.results.iter().any(|r| r.point.group == Group::Paths) {
        let _ = write!(
            m,
            "\n### Which fragment path wins (fragment mode, directional lights, {} draw{} a frame)\n\n{}\n{}\n",
            c.draws,
            if c.draws == 1 { "" } else { "s" },
            paths_table(report).markdown(),
            paths_note()
        );
    }
    if !report.states.is_empty() {
        let _ = write!(
            m,
            "\n### Frames of several lighting states (fragment mode, forward and deferred)\n\n{}\n{}\n",
            super::states::states_table(&report.states).markdown(),
            super::states::states_note()
        );
    }
    if !report.summary.costs.is_empty() {
        let _ = write!(
            m,
            "\n### What a vertex, a pixel and a light cost\n\n{}\n{}\n",
            costs_table(report).markdown(),
            COSTS_NOTE
        );
    }
    if let Some(d) = &report.draw_cost {
        let _ = write!(
            m,
            "\n### Recording draws (host)\n\n{}\n{}\n",
            draw_cost_table(d).markdown(),
            draw_cost_note(d)
        );
    }
    if !report.draws.is_empty() {
        let _ = write!(m, "\n{}", super::draws::draws_markdown(&report.draws));
        let floor = super::floor::floor_markdown(&report.floor, &report.draws);
        if !floor.is_empty() {
            let _ = write!(m, "\n{floor}");
        }
    }

    let s = &report.summary;
    let gl_name = report.env.gl_renderer.as_deref();
    let _ = writeln!(m, "\n### Summary\n");
    // The crossings come from the density and size sweeps; sweeps without them (paths) say
    // nothing of them.
    let has = |g: Group| report.results.iter().any(|r| r.point.group == g);
    let _ = has(Group::Density).then(|| {
        writeln!(
            m,
            "- vertex and fragment mode cost the same at about {} ({}² image)",
            s.crossover_vertices
                .map_or("— (no crossing in this sweep)".into(), |v| format!(
                    "{} vertices",
                    count(v)
                )),
            c.base_size
        )
    });
    let _ = has(Group::Size).then(|| {
        writeln!(
            m,
            "- with {} vertices they cost the same at about {}",
            sphere_counts(c.size_stacks).0,
            s.crossover_pixels
                .map_or("— (no crossing in this sweep)".into(), |p| format!(
                    "{} pixels ({:.0}²)",
                    count(p),
                    p.sqrt()
                ))
        )
    });
    for (mode, g) in &s.specialization_speedup {
        let _ = writeln!(
            m,
            "- {mode} mode: the uber-shader takes {g:.2}× the time of specialized pipelines (geometric mean)"
        );
    }
    let _ = writeln!(m, "- ffvk's default: Specialize::{}", s.default_specialize);
    if let Some(g) = s.gl_vertex_ratio_geomean {
        let basis = if s.gl_ratios.iter().any(|r| r.gl_gpu_ms.is_some()) {
            "GPU time"
        } else {
            "host time"
        };
        let _ = writeln!(
            m,
            "- ffvk vertex mode ÷ the GL driver's fixed-function GL{} ({basis} per frame, geometric mean over {} scenes): {g:.2}",
            gl_name.map(|n| format!(" ({n})")).unwrap_or_default(),
            s.gl_ratios.iter().filter(|r| r.mode == BenchMode::Vertex).count()
        );
        let vertex: Vec<f64> = s
            .gl_ratios
            .iter()
            .filter(|r| r.mode == BenchMode::Vertex)
            .map(|r| r.ratio)
            .collect();
        let (lo, hi) = vertex
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &r| {
                (lo.min(r), hi.max(r))
            });
        let _ = writeln!(
            m,
            "- ffvk vertex mode ÷ GL per scene: {lo:.2} to {hi:.2}; {} of {} scenes above 1.0",
            vertex.iter().filter(|&&r| r > 1.0).count(),
            vertex.len()
        );
    }
    // Lighting's own cost per vertex: the lit density fit's slope less the unlit one.
    let slope = |engine: Engine, mode: BenchMode| {
        s.costs
            .iter()
            .find(|c| c.engine == engine && c.mode == mode)
            .and_then(|c| c.ns_per_vertex)
    };
    let added = |engine| Some(slope(engine, BenchMode::Vertex)? - slope(engine, BenchMode::Unlit)?);
    if let Some(ffvk) = added(Engine::Ffvk) {
        let _ = writeln!(
            m,
            "- per-vertex lighting's added cost (vertex-mode minus unlit ns per vertex, from the density fits): ffvk {ffvk:.0} ns{}",
            added(Engine::Gl).map_or(String::new(), |gl| format!(", GL {gl:.0} ns"))
        );
    }
    for &size in &report.sweep.fragment_sizes {
        let at = |mode, variant| fragment_point(report, size, mode, variant);
        let time = |r: Option<&BenchResult>| r.map(|r| r.stats.time_ms);
        let (v, u) = (
            time(at(BenchMode::Vertex, Variant::Specialized)),
            time(at(BenchMode::Unlit, Variant::Specialized)),
        );
        for (path, variant) in FRAGMENT_PATHS {
            let fragment = at(BenchMode::Fragment, variant);
            let runs = fragment.and_then(|r| equation_runs(r).0);
            let per_pixel = runs
                .zip(fragment.and_then(|r| r.stats.covered_pixels))
                .filter(|&(_, covered)| covered > 0)
                .map(|(n, covered)| n as f64 / covered as f64);
            if let (Some(f), Some(v), Some(u)) = (time(fragment), v, u) {
                let _ = writeln!(
                    m,
                    "- fragment lighting at {size}², {path} ({} vertices, {}): {:.2}× unlit, {:.2}× vertex mode; the equation runs {} times per covered pixel",
                    sphere_counts(report.sweep.fragment_stacks).0,
                    lights_text(report.sweep.fragment_lights),
                    f / u,
                    f / v,
                    per_pixel.map_or("–".into(), |p| format!("{p:.2}"))
                );
            }
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::bench::{points, summarize, BenchEnv, LightKind, Point, PointStats, Stage, SweepConfig};

    /// Made-up times that grow with vertices, pixels and lights, the uber-shader and GL slower;
    /// vertex and fragment mode cross in the density and the size sweep.
    fn fake_time(p: &Point) -> f64 {
        let lights = 1.0 + p.lights as f64;
        let (per_vertex, per_pixel) = match p.mode {
            BenchMode::Vertex => (4e-3 * lights, 2e-4),
            BenchMode::Fragment => (1e-4, 1e-3 * lights),
            BenchMode::Flat => (3e-4 * lights, 2e-4),
            BenchMode::Unlit => (1e-4, 2e-4),
        };
        let kind = match p.light_kind.gl_form().unwrap_or(p.light_kind) {
            LightKind::Directional => 1.0,
            LightKind::Point => 1.05,
            _ => 1.1,
        };
        let viewer = if p.local_viewer { 1.02 } else { 1.0 };
        // A lighting variant costs 20 % more than its GL form.
        let variant = if p.light_kind.gl_form().is_some() {
            1.2
        } else {
            1.0
        };
        // A stage costs 10 %, all of them 30 %.
        let stage = match p.stage {
            Stage::Off => 1.0,
            Stage::All => 1.3,
            _ => 1.1,
        };
        let t = (0.05 + per_vertex * p.vertices as f64 + per_pixel * p.pixels as f64)
            * kind
            * viewer
            * variant
            * stage;
        match p.variant {
            Variant::Specialized => t,
            Variant::Uber => t * 1.25,
            Variant::FixedFunction => t * 1.5,
            Variant::Deferred => t * 0.8,
            Variant::DeferredUber => t * 0.9,
        }
    }

    /// A report of the tiny sweep with [`fake_time`]s: no device needed.
    pub(crate) fn synthetic_report() -> BenchReport {
        let sweep = SweepConfig::tiny();
        let env = BenchEnv {
            lp_num_threads: "2".into(),
            device: "llvmpipe (LLVM 15.0.6, 256 bits)".into(),
            device_type: "CPU".into(),
            driver: "llvmpipe".into(),
            driver_info: "Mesa 22.3.6 (LLVM 15.0.6)".into(),
            mesa_version: "22.3.6".into(),
            vulkan_api: "1.3.230".into(),
            gl_renderer: Some("llvmpipe (LLVM 15.0.6, 256 bits)".into()),
            zink_renderer: None,
            zink_version: None,
            gl_version: Some("2.1 Mesa 22.3.6".into()),
            cpu: "Some CPU".into(),
            cpus: 2,
            ffvk_version: "0.1.0".into(),
            optimized_build: true,
            validation: false,
            load_before: Some(0.5),
            load_after: None,
        };
        let results: Vec<BenchResult> = points(&sweep)
            .into_iter()
            .map(|point| {
                let t = fake_time(&point);
                let spread = Spread {
                    median: t,
                    min: t * 0.9,
                    p25: t * 0.95,
                    p75: t * 1.05,
                    max: t * 1.2,
                };
                let ffvk = point.engine == Engine::Ffvk;
                BenchResult {
                    stats: PointStats {
                        warmup: sweep.warmup,
                        frames: sweep.frames,
                        first_frame_ms: 10.0 * t,
                        gpu_ms: ffvk.then_some(spread),
                        wall_ms: Spread {
                            median: t * 1.1,
                            ..spread
                        },
                        time_ms: t,
                        vs_invocations: ffvk.then_some(point.vertices),
                        fs_invocations: ffvk.then_some(point.pixels / 2),
                        clipping_primitives: ffvk.then_some(point.triangles),
                        covered_pixels: ffvk.then_some(point.pixels / 4),
                        evaluations: matches!(point.variant, Variant::Deferred | Variant::DeferredUber)
                            .then_some(point.pixels / 4),
                        gbuffer_ms: matches!(point.variant, Variant::Deferred | Variant::DeferredUber)
                            .then_some(Spread {
                                median: t * 0.6,
                                ..spread
                            }),
                        lighting_ms: matches!(point.variant, Variant::Deferred | Variant::DeferredUber)
                            .then_some(Spread {
                                median: t * 0.4,
                                ..spread
                            }),
                    },
                    point,
                    lp_num_threads: env.lp_num_threads.clone(),
                    device: env.device.clone(),
                    driver_info: env.driver_info.clone(),
                    mesa_version: env.mesa_version.clone(),
                }
            })
            .collect();
        let summary = summarize(&results);
        BenchReport {
            env,
            sweep,
            results,
            summary,
            draw_cost: None,
            draws: Vec::new(),
            floor: Vec::new(),
            states: Vec::new(),
            notes: vec!["a note".into()],
        }
    }

    /// summary.md of [`synthetic_report`], to the character.
    const SYNTHETIC_SUMMARY: &str = r#"### Environment

| | |
| --- | --- |
| device | llvmpipe (LLVM 15.0.6, 256 bits) (llvmpipe) |
| driver | Mesa 22.3.6 (LLVM 15.0.6) |
| GL anchor | llvmpipe (LLVM 15.0.6, 256 bits), GL 2.1 Mesa 22.3.6 (EGL) |
| LP_NUM_THREADS | 2 |
| heap | glibc defaults (freed memory trimmed) |
| CPU | Some CPU (2 CPUs) |
| load average (1 min) | 0.50 before, ? after |
| sweep | tiny — 1 warm-up + 2 measured frames per point; image 24² but in the size sweep; 66 vertices in the size sweep, 91 in the light sweeps |
| build | ffvk 0.1.0, optimized |
| note | a note |

Times are per frame in ms: the median, then the interquartile range; ffvk's from timestamps around the rendering pass, GL's from the host clock around the draw and glFinish.

### Time against vertex count (24² image, 1 directional light)

| vertices | triangles | vertex | fragment | flat | unlit | VS invocations (vertex) | GL smooth | GL flat | GL unlit | ffvk vertex ÷ GL |
| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| 45 | 48 | 0.53 (0.50–0.55) | 1.21 (1.15–1.27) | 0.19 (0.18–0.20) | 0.17 (0.16–0.18) | 45 | 0.79 (0.75–0.83) | 0.29 (0.27–0.30) | 0.25 (0.24–0.27) | 0.67 |
| 153 | 224 | 1.39 (1.32–1.46) | 1.22 (1.16–1.28) | 0.26 (0.24–0.27) | 0.18 (0.17–0.19) | 153 | 2.08 (1.98–2.19) | 0.39 (0.37–0.40) | 0.27 (0.26–0.28) | 0.67 |

### Time against pixel count (66 vertices, 1 directional light)

| image | pixels | vertex | fragment | flat | unlit | FS invocations (fragment) |
| ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| 16² | 256 | 0.63 (0.60–0.66) | 0.57 (0.54–0.60) | 0.14 (0.13–0.15) | 0.11 (0.10–0.11) | 128 |
| 32² | 1.0 k | 0.78 (0.74–0.82) | 2.10 (2.00–2.21) | 0.29 (0.28–0.31) | 0.26 (0.25–0.27) | 512 |

### Light count: specialized pipelines against the uber-shader (91 vertices, 24², directional lights)

| lights | vertex specialized | vertex uber | uber ÷ spec. | fragment specialized | fragment uber | uber ÷ spec. | GL smooth | ffvk vertex ÷ GL |
| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| 1 | 0.89 (0.85–0.94) | 1.12 (1.06–1.17) | 1.25 | 1.21 (1.15–1.27) | 1.51 (1.44–1.59) | 1.25 | 1.34 (1.27–1.41) | 0.67 |
| 2 | 1.26 (1.19–1.32) | 1.57 (1.49–1.65) | 1.25 | 1.79 (1.70–1.88) | 2.23 (2.12–2.35) | 1.25 | 1.89 (1.79–1.98) | 0.67 |

### Light kind (2 lights of one kind, 91 vertices, 24²)

| lights | viewer | vertex specialized | vertex uber | fragment specialized | fragment uber | GL smooth | ffvk vertex ÷ GL | vertex vs GL form | fragment vs GL form |
| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| directional | infinite | 1.26 (1.19–1.32) | 1.57 (1.49–1.65) | 1.79 (1.70–1.88) | 2.23 (2.12–2.35) | 1.89 (1.79–1.98) | 0.67 | – | – |
| directional | local | 1.28 (1.22–1.35) | 1.60 (1.52–1.68) | 1.82 (1.73–1.91) | 2.28 (2.16–2.39) | 1.92 (1.83–2.02) | 0.67 | – | – |
| spot | infinite | 1.38 (1.31–1.45) | 1.73 (1.64–1.82) | 1.97 (1.87–2.06) | 2.46 (2.33–2.58) | 2.07 (1.97–2.18) | 0.67 | – | – |
| spot | local | 1.41 (1.34–1.48) | 1.76 (1.68–1.85) | 2.01 (1.90–2.11) | 2.51 (2.38–2.63) | 2.12 (2.01–2.22) | 0.67 | – | – |
| spot_smoothstep | infinite | 1.66 (1.58–1.74) | 2.07 (1.97–2.18) | 2.36 (2.24–2.48) | 2.95 (2.80–3.10) | – | – | 1.20 | 1.20 |
| spot_smoothstep | local | 1.69 (1.61–1.78) | 2.12 (2.01–2.22) | 2.41 (2.29–2.53) | 3.01 (2.86–3.16) | – | – | 1.20 | 1.20 |

### Points and lines (91 vertices, 24², 1 directional light; lines: each triangle's three edges)

| drawn as | vertex | flat | unlit | GL smooth | GL flat | GL unlit | vertex ÷ GL | flat ÷ GL |
| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| GL_TRIANGLES | 0.89 (0.85–0.94) | 0.22 (0.21–0.23) | 0.17 (0.17–0.18) | 1.34 (1.27–1.41) | 0.33 (0.31–0.35) | 0.26 (0.25–0.27) | 0.67 | 0.67 |
| GL_LINES | 0.89 (0.85–0.94) | 0.22 (0.21–0.23) | 0.17 (0.17–0.18) | 1.34 (1.27–1.41) | 0.33 (0.31–0.35) | 0.26 (0.25–0.27) | 0.67 | 0.67 |
| GL_POINTS | 0.89 (0.85–0.94) | 0.22 (0.21–0.23) | 0.17 (0.17–0.18) | 1.34 (1.27–1.41) | 0.33 (0.31–0.35) | 0.26 (0.25–0.27) | 0.67 | 0.67 |

### The stages around lighting (91 vertices, 24², 1 directional light)

| stage | vertex | ÷ none | vertex uber | ÷ none | fragment | ÷ none | fragment uber | ÷ none | flat | ÷ none | unlit | ÷ none | GL smooth | ÷ none | GL unlit | ÷ none | vertex ÷ GL |
| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |
| none | 0.89 | 1.00 | 1.12 | 1.00 | 1.21 | 1.00 | 1.51 | 1.00 | 0.22 | 1.00 | 0.17 | 1.00 | 1.34 | 1.00 | 0.26 | 1.00 | 0.67 |
| fog GL_LINEAR | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |
| fog GL_EXP2 | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |
| fog GL_EXP2, GL_FASTEST (per vertex) | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |
| alpha test GL_GREATER 0 | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |
| GL_COLOR_SUM | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |
| 1 clip plane | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |
| 6 clip planes | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |
| all of them | 1.16 | 1.30 | 1.45 | 1.30 | 1.57 | 1.30 | 1.97 | 1.30 | 0.29 | 1.30 | 0.23 | 1.30 | 1.74 | 1.30 | 0.34 | 1.30 | 0.67 |
| 1 texture unit, GL_MODULATE | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |
| 4 units: + GL_COMBINE, sphere map, cube map | 0.98 | 1.10 | 1.23 | 1.10 | 1.33 | 1.10 | 1.67 | 1.10 | 0.24 | 1.10 | 0.19 | 1.10 | 1.47 | 1.10 | 0.29 | 1.10 | 0.67 |

Each stage alone, then all together, on the light sweeps' sphere; "÷ none" is the time over the same column's frame without stages. The alpha test passes every fragment and the clip planes cut nothing, so each row costs the stage's work and draws the pixels of the row "none"; lit draws always sum the secondary color, so GL_COLOR_SUM changes only the unlit column. The texturing rows bind 64² textures, linear, no mipmaps: one unit modulated; then four, the second a light map through GL_COMBINE (MODULATE × 2), the third sphere-mapped, the fourth a 16² cube map by GL_REFLECTION_MAP, added.

### Fragment lighting on a dense mesh (91 vertices, 2 directional lights)

| image | path | covered pixels | fragment | vertex | unlit | fragment ÷ unlit | fragment ÷ vertex | equation runs per covered pixel | counted by |
| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |
| 16² | forward | 64 | 0.83 (0.79–0.87) | 1.19 (1.13–1.25) | 0.11 (0.10–0.12) | 7.50 | 0.69 | 2.00 | pipeline statistics |
| 16² | deferred | 64 | 0.66 (0.63–0.69) | 1.19 (1.13–1.25) | 0.11 (0.10–0.12) | 6.00 | 0.55 | 1.00 | the lighting pass's own count |
| 16² | deferred, uber-shader | 64 | 0.74 (0.71–0.78) | 1.19 (1.13–1.25) | 0.11 (0.10–0.12) | 6.75 | 0.62 | 1.00 | the lighting pass's own count |
| 24² | forward | 144 | 1.79 (1.70–1.88) | 1.26 (1.19–1.32) | 0.17 (0.17–0.18) | 10.25 | 1.42 | 2.00 | pipeline statistics |
| 24² | deferred | 144 | 1.43 (1.36–1.50) | 1.26 (1.19–1.32) | 0.17 (0.17–0.18) | 8.20 | 1.14 | 1.00 | the lighting pass's own count |
| 24² | deferred, uber-shader | 144 | 1.61 (1.53–1.69) | 1.26 (1.19–1.32) | 0.17 (0.17–0.18) | 9.23 | 1.28 | 1.00 | the lighting pass's own count |

Covered pixels: those not at the clear color in a frame read back after the measured ones. Equation runs per covered pixel: over the covered pixels, for the forward path the fragment stage's pipeline-statistics count, which lavapipe (llvmpipe) makes per 4×4 block a triangle touches, partly covered blocks included (a GPU counts about one per pixel), for every draw of the sphere in a frame (the gpu sweep's 16 each pass the depth test); for the deferred path the lighting pass's own count (an atomic add per pixel it lights, once whatever the draws), its G-buffer pass not counted.

### Which fragment path wins (fragment mode, directional lights, 1 draw a frame)

| vertices | image | lights | vertices / pixel | forward | deferred | G-buffer pass | lighting pass | deferred ÷ forward | auto | agrees |
| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | --- |
| 45 | 16² | 1 | 0.176 | 0.57 (0.54–0.59) | 0.45 (0.43–0.48) | 0.27 | 0.18 | 0.80 | forward | no |
| 45 | 16² | 2 | 0.176 | 0.82 (0.78–0.86) | 0.66 (0.63–0.69) | 0.39 | 0.26 | 0.80 | forward | no |
| 153 | 16² | 1 | 0.598 | 0.58 (0.55–0.61) | 0.46 (0.44–0.48) | 0.28 | 0.18 | 0.80 | forward | no |
| 153 | 16² | 2 | 0.598 | 0.83 (0.79–0.87) | 0.67 (0.63–0.70) | 0.40 | 0.27 | 0.80 | forward | no |

Deferred ÷ forward below 1: the deferred path wins. "G-buffer pass" and "lighting pass": the deferred frame's time split at a timestamp between its two passes (medians frame by frame); the G-buffer pass writes 16 bytes a pixel beside the depth (24 with its color, which only color material and unlit draws need), the lighting pass reads them and writes the 4-byte color. "auto": what FragmentPath::Auto picks for the frame on this device (its rule, from the frame's vertices, pixels and lights; not from these times); "agrees": whether that is the faster path here, or within 5 % of it.

### What a vertex, a pixel and a light cost

| engine | mode | ns / vertex | ns / pixel | ns / light | ns / light / evaluation | fixed ms |
| --- | --- | ---: | ---: | ---: | ---: | ---: |
| ffvk | vertex | 8000 | 200 | 364000 | 4000 | 0.165 |
| ffvk | fragment | 100 | 2000 | 576000 | 2000 | 1.202 |
| ffvk | flat | 600 | 200 | — | — | 0.165 |
| ffvk | unlit | 100 | 200 | — | — | 0.165 |
| GL | vertex | 12000 | 300 | 546000 | — | 0.248 |
| GL | flat | 900 | 300 | — | — | 0.248 |
| GL | unlit | 150 | 300 | — | — | 0.248 |

Least-squares slopes of the sweeps above, in ns: per vertex drawn (density sweep, vertices × draws per frame), per pixel drawn (size sweep, pixels × draws), per light enabled (light sweep) and per light and evaluation of the equation (that slope over the vertices shaded in vertex and flat mode, the fragments shaded in fragment mode); "fixed" is the density fit's intercept, an estimate of a frame without geometry. Straight lines through sweeps whose counts grow geometrically follow the largest points: where time is not linear in the count (lavapipe's small frames), read them as rough. Unlit rows show what the pipeline costs without lighting.

### Summary

- vertex and fragment mode cost the same at about 129 vertices (24² image)
- with 66 vertices they cost the same at about 291 pixels (17²)
- fragment mode: the uber-shader takes 1.25× the time of specialized pipelines (geometric mean)
- vertex mode: the uber-shader takes 1.25× the time of specialized pipelines (geometric mean)
- ffvk's default: Specialize::auto (specialized pipelines)
- ffvk vertex mode ÷ the GL driver's fixed-function GL (llvmpipe (LLVM 15.0.6, 256 bits)) (host time per frame, geometric mean over 10 scenes): 0.67
- ffvk vertex mode ÷ GL per scene: 0.67 to 0.67; 0 of 10 scenes above 1.0
- per-vertex lighting's added cost (vertex-mode minus unlit ns per vertex, from the density fits): ffvk 7900 ns, GL 11850 ns
- fragment lighting at 16², forward (91 vertices, 2 directional lights): 7.50× unlit, 0.69× vertex mode; the equation runs 2.00 times per covered pixel
- fragment lighting at 16², deferred (91 vertices, 2 directional lights): 6.00× unlit, 0.55× vertex mode; the equation runs 1.00 times per covered pixel
- fragment lighting at 16², deferred, uber-shader (91 vertices, 2 directional lights): 6.75× unlit, 0.62× vertex mode; the equation runs 1.00 times per covered pixel
- fragment lighting at 24², forward (91 vertices, 2 directional lights): 10.25× unlit, 1.42× vertex mode; the equation runs 2.00 times per covered pixel
- fragment lighting at 24², deferred (91 vertices, 2 directional lights): 8.20× unlit, 1.14× vertex mode; the equation runs 1.00 times per covered pixel
- fragment lighting at 24², deferred, uber-shader (91 vertices, 2 directional lights): 9.23× unlit, 1.28× vertex mode; the equation runs 1.00 times per covered pixel
"#;

    #[test]
    fn markdown_of_a_synthetic_report() {
        let m = markdown(&synthetic_report());
        for (line, (actual, expected)) in m.lines().zip(SYNTHETIC_SUMMARY.lines()).enumerate() {
            assert_eq!(actual, expected, "line {}", line + 1);
        }
        assert_eq!(m, SYNTHETIC_SUMMARY);
    }

    #[test]
    fn the_fitted_costs_are_the_slopes_fake_time_was_made_of() {
        // fake_time: ffvk vertex mode costs 4e-3 ms × (1 + lights) per vertex and 2e-4 ms per
        // pixel over 0.05 ms; the density and size sweeps have 1 light, the light sweep 91
        // vertices (6 stacks) at 24² = 576 pixels.
        let report = synthetic_report();
        let c = |engine, mode| {
            report
                .summary
                .costs
                .iter()
                .find(|c| c.engine == engine && c.mode == mode)
                .unwrap()
                .clone()
        };
        let close =
            |a: Option<f64>, b: f64| assert!(a.is_some_and(|a| (a - b).abs() < 1e-6 * b), "{a:?} vs {b}");
        let vertex = c(Engine::Ffvk, BenchMode::Vertex);
        close(vertex.ns_per_vertex, 4e-3 * 2.0 * 1e6);
        close(vertex.ns_per_pixel, 2e-4 * 1e6);
        close(vertex.ns_per_light, 4e-3 * 91.0 * 1e6);
        // Per evaluation: the 91 vertices the pipeline statistics say were shaded.
        close(vertex.ns_per_light_evaluation, 4e-3 * 1e6);
        close(vertex.fixed_ns, (0.05 + 2e-4 * 576.0) * 1e6);
        // Fragment mode: 1e-3 ms × (1 + lights) per pixel, fs_invocations = pixels / 2.
        let fragment = c(Engine::Ffvk, BenchMode::Fragment);
        close(fragment.ns_per_pixel, 1e-3 * 2.0 * 1e6);
        close(fragment.ns_per_light_evaluation, 1e-3 * 576.0 * 1e6 / 288.0);
        // GL: the same times × 1.5, no pipeline statistics.
        let gl = c(Engine::Gl, BenchMode::Vertex);
        close(gl.ns_per_vertex, 1.5 * 4e-3 * 2.0 * 1e6);
        assert_eq!(gl.ns_per_light_evaluation, None);
    }

    #[test]
    fn on_a_driver_that_is_not_mesa_the_environment_names_it_plainly() {
        let mut report = synthetic_report();
        report.env.device = "NVIDIA H100 80GB HBM3".into();
        report.env.driver = "NVIDIA".into();
        report.env.driver_info = "580.159.04".into();
        report.env.mesa_version = String::new();
        report.env.gl_renderer = Some("NVIDIA H100 80GB HBM3/PCIe/SSE2".into());
        report.env.gl_version = Some("4.6.0 NVIDIA 580.159.04".into());
        let m = markdown(&report);
        assert!(m.contains("| driver | 580.159.04 |"), "{m}");
        assert!(!m.contains("Mesa") && !m.contains("LP_NUM_THREADS"), "{m}");
        assert!(
            m.contains("÷ the GL driver's fixed-function GL (NVIDIA H100"),
            "{m}"
        );
        // A Mesa driver whose driver_info does not name the version gets it added.
        report.env.driver_info = "some build".into();
        report.env.mesa_version = "25.1.0".into();
        assert!(markdown(&report).contains("| driver | some build (Mesa 25.1.0) |"));
    }

    #[test]
    fn without_gl_the_tables_have_no_gl_columns() {
        let mut report = synthetic_report();
        report.results.retain(|r| r.point.engine == Engine::Ffvk);
        report.summary = summarize(&report.results);
        let m = markdown(&report);
        assert!(!m.contains("GL smooth") && !m.contains("÷ GL"), "{m}");
        // Every line of a table has as many cells as its headings.
        let tables: Vec<&str> = m.split("\n\n").filter(|b| b.starts_with('|')).collect();
        assert_eq!(tables.len(), 10, "{m}");
        for table in tables {
            let cells: Vec<usize> = table.lines().map(|l| l.matches(" |").count()).collect();
            assert!(cells.iter().all(|&n| n == cells[0]), "{table}");
        }
    }
}
