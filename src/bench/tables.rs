//! The tables of a bench run's summary: the environment, each sweep's table and the fitted
//! costs, built from the results as [`Table`]s (`report.rs` puts them together).

use super::format::{cell, count, count_or_dash, find, ms, ratio};
use super::measure::Spread;
use super::points::{sphere_counts, GL_MODES};
use super::sweep::{BenchMode, Engine, Group, LightKind, Primitive, Variant};
use super::{BenchReport, BenchResult, DrawCost};
use crate::table::{Align, Table};

pub(super) const COSTS_NOTE: &str = "Least-squares slopes of the sweeps above, in ns: per vertex drawn \
(density sweep, vertices × draws per frame), per pixel drawn (size sweep, pixels × draws), per \
light enabled (light sweep) and per light and evaluation of the equation (that slope over the \
vertices shaded in vertex and flat mode, the fragments shaded in fragment mode); \"fixed\" is \
the density fit's intercept, an estimate of a frame without geometry. Straight lines through \
sweeps whose counts grow geometrically follow the largest points: where time is not linear in \
the count (lavapipe's small frames), read them as rough. Unlit rows show what the pipeline \
costs without lighting.";

/// The fitted costs of each engine and mode.
pub(super) fn costs_table(report: &BenchReport) -> Table {
    let mut t = Table::new([
        ("engine", Align::Left),
        ("mode", Align::Left),
        ("ns / vertex", Align::Right),
        ("ns / pixel", Align::Right),
        ("ns / light", Align::Right),
        ("ns / light / evaluation", Align::Right),
        ("fixed ms", Align::Right),
    ]);
    // Three significant digits or so, whatever the scale (rounded first, so that a fit's
    // 99.9999 reads 100).
    let ns = |v: Option<f64>| match v.map(|v| (v * 1e3).round() / 1e3) {
        None => "—".to_string(),
        Some(v) if v.abs() >= 100.0 => format!("{v:.0}"),
        Some(v) if v.abs() >= 1.0 => format!("{v:.2}"),
        Some(v) => format!("{v:.3}"),
    };
    for c in &report.summary.costs {
        t.row([
            c.engine.name().to_string(),
            c.mode.name().to_string(),
            ns(c.ns_per_vertex),
            ns(c.ns_per_pixel),
            ns(c.ns_per_light),
            ns(c.ns_per_light_evaluation),
            c.fixed_ns.map_or("—".to_string(), |v| format!("{:.3}", v / 1e6)),
        ]);
    }
    t
}

/// The machine, the drivers, the sweep and the build: one row each, then the notes.
/// The recording cost: medians with their interquartile range.
pub(super) fn draw_cost_table(d: &DrawCost) -> Table {
    let mut t = Table::new([
        ("", Align::Left),
        ("median", Align::Right),
        ("25–75%", Align::Right),
    ]);
    let row = |t: &mut Table, what: String, s: &Spread, digits: usize| {
        t.row([
            what,
            format!("{:.*}", digits, s.median),
            format!("{:.*}–{:.*}", digits, s.p25, digits, s.p75),
        ])
    };
    row(
        &mut t,
        format!(
            "one warm draw with a state change, µs ({} draws a frame, {} frames)",
            d.draws, d.frames
        ),
        &d.warm_us_per_draw,
        3,
    );
    row(
        &mut t,
        "one warm draw that changes only its modelview, µs".into(),
        &d.modelview_only_us_per_draw,
        3,
    );
    row(
        &mut t,
        "packing a whole draw alone, its lights included (DrawBlock::new), µs".into(),
        &d.pack_us_per_draw,
        3,
    );
    row(
        &mut t,
        "Lighting::draw_run on a caller's device, one state shared, a material and modelview per draw, µs"
            .into(),
        &d.run_own_values_us_per_draw,
        3,
    );
    row(
        &mut t,
        "Lighting::draw_run, one state shared, only the modelview per draw, µs".into(),
        &d.run_modelview_only_us_per_draw,
        3,
    );
    row(
        &mut t,
        "Lighting::draw_run, a whole state per draw, µs".into(),
        &d.run_state_each_us_per_draw,
        3,
    );
    row(
        &mut t,
        "a new specialization key: creating its pipeline, ms".into(),
        &d.new_key_create_ms,
        2,
    );
    row(
        &mut t,
        "a new specialization key: extra time of its first frame, ms".into(),
        &d.new_key_first_draw_ms,
        2,
    );
    t
}

/// What dominates the warm draw.
pub(super) fn draw_cost_note(d: &DrawCost) -> String {
    let (all, pack) = (d.warm_us_per_draw.median, d.pack_us_per_draw.median);
    let share = if all > 0.0 { 100.0 * pack / all } else { 0.0 };
    format!(
        "Packing a whole draw alone (normal matrix, clip conversion, sixteen lights checked and \
         packed) takes {share:.0}% of a warm draw's time. A draw whose state (lights, light \
         model, switches, projection) equals the draw before's reuses its state block and \
         pipeline (here every draw: each has its own material under the same lights), so it \
         checks and writes only its 304-byte record: materials, current values, modelview and \
         normal matrix. The first two rows go through the Renderer, whose frames hold a whole \
         state per draw (it compares each with the one before); the draw_run rows are what an \
         emulation layer pays recording into its own command buffer, each draw a command of its \
         own (a triangle each, so none merge): with one state borrowed by every draw, the \
         comparison is skipped.\n"
    )
}

pub(super) fn environment(report: &BenchReport) -> Table {
    let e = &report.env;
    let c = &report.sweep;
    let mut rows = vec![
        ("device", format!("{} ({})", e.device, e.driver)),
        (
            "driver",
            // Mesa's driver_info already names its version; other drivers' is their own.
            if e.mesa_version.is_empty() || e.driver_info.contains(&e.mesa_version) {
                e.driver_info.clone()
            } else {
                format!("{} (Mesa {})", e.driver_info, e.mesa_version)
            },
        ),
    ];
    if let (Some(r), Some(v)) = (&e.gl_renderer, &e.gl_version) {
        rows.push(("GL anchor", format!("{r}, GL {v} (EGL)")));
    }
    if let (Some(r), Some(v)) = (&e.zink_renderer, &e.zink_version) {
        rows.push(("zink anchor", format!("{r}, GL {v} (EGL, a process of its own)")));
    }
    let heap = if c.malloc_no_trim {
        "freed memory kept (--malloc-no-trim: glibc M_TRIM_THRESHOLD = max, M_TOP_PAD = 256 MiB)"
    } else {
        "glibc defaults (freed memory trimmed)"
    };
    let load = |l: Option<f64>| l.map_or("?".into(), |l| format!("{l:.2}"));
    let build = if e.optimized_build {
        "optimized"
    } else {
        "debug (numbers not representative)"
    };
    if e.uses_lp_threads() {
        rows.push(("LP_NUM_THREADS", e.lp_num_threads.clone()));
    }
    rows.extend([
        ("heap", heap.into()),
        ("CPU", format!("{} ({} CPUs)", e.cpu, e.cpus)),
        (
            "load average (1 min)",
            format!("{} before, {} after", load(e.load_before), load(e.load_after)),
        ),
        (
            "sweep",
            format!(
                "{} — {} warm-up + {} measured frames per point{}; image {}² but in the size \
                 sweep; {} vertices in the size sweep, {} in the light sweeps{}",
                c.name,
                c.warmup,
                c.frames,
                if c.batch { " (in one submission)" } else { "" },
                c.base_size,
                sphere_counts(c.size_stacks).0,
                sphere_counts(c.base_stacks).0,
                if c.draws > 1 {
                    format!("; {} draws of the mesh per frame, each lit in full", c.draws)
                } else {
                    String::new()
                }
            ),
        ),
        (
            "build",
            format!(
                "ffvk {}, {build}{}",
                e.ffvk_version,
                if e.validation { ", validation layer on" } else { "" }
            ),
        ),
    ]);
    rows.extend(report.notes.iter().map(|n| ("note", n.clone())));

    let mut t = Table::new([("", Align::Left), ("", Align::Left)]);
    for (key, value) in rows {
        t.row([key.to_string(), value]);
    }
    t
}

/// Time against vertex count: ffvk's modes and vertex-shader invocations, then GL's modes and
/// the ratio of ffvk's vertex mode to GL's.
pub(super) fn density_table(report: &BenchReport, has_gl: bool) -> Table {
    let spec = Variant::Specialized;
    let mut t = Table::new(
        ["vertices", "triangles"]
            .into_iter()
            .chain(BenchMode::ALL.map(BenchMode::name))
            .chain(["VS invocations (vertex)"])
            .map(|h| (h, Align::Right)),
    );
    if has_gl {
        for h in ["GL smooth", "GL flat", "GL unlit", "ffvk vertex ÷ GL"] {
            t.column(h, Align::Right);
        }
    }
    let has_zink = report.results.iter().any(|r| r.point.engine == Engine::Zink);
    if has_zink {
        for h in ["zink smooth", "ffvk vertex ÷ zink"] {
            t.column(h, Align::Right);
        }
    }
    for &stacks in &report.sweep.stacks {
        let at = |engine, mode, variant| {
            find(&report.results, |p| {
                p.group == Group::Density
                    && p.stacks == stacks
                    && p.engine == engine
                    && p.mode == mode
                    && p.variant == variant
            })
        };
        let (v, triangles) = sphere_counts(stacks);
        let mut row = vec![count(v as f64), count(triangles as f64)];
        row.extend(BenchMode::ALL.map(|mode| cell(at(Engine::Ffvk, mode, spec))));
        row.push(count_or_dash(
            at(Engine::Ffvk, BenchMode::Vertex, spec).and_then(|r| r.stats.vs_invocations),
        ));
        if has_gl {
            row.extend(GL_MODES.map(|mode| cell(at(Engine::Gl, mode, Variant::FixedFunction))));
            let gl = report
                .summary
                .gl_ratios
                .iter()
                .find(|r| r.group == Group::Density && r.mode == BenchMode::Vertex && r.vertices == v);
            row.push(ratio(gl.map(|r| r.ratio)));
        }
        if has_zink {
            let zink = at(Engine::Zink, BenchMode::Vertex, Variant::FixedFunction);
            row.push(cell(zink));
            let ffvk = at(Engine::Ffvk, BenchMode::Vertex, spec);
            row.push(ratio(
                ffvk.zip(zink)
                    .map(|(f, z)| f.stats.wall_ms.median / z.stats.wall_ms.median),
            ));
        }
        t.row(row);
    }
    t
}

/// Time against pixel count: ffvk's modes and fragment-shader invocations.
pub(super) fn size_table(report: &BenchReport) -> Table {
    let mut t = Table::new(
        ["image", "pixels"]
            .into_iter()
            .chain(BenchMode::ALL.map(BenchMode::name))
            .chain(["FS invocations (fragment)"])
            .map(|h| (h, Align::Right)),
    );
    for &size in &report.sweep.sizes {
        let at = |mode| {
            find(&report.results, |p| {
                p.group == Group::Size
                    && p.width == size
                    && p.engine == Engine::Ffvk
                    && p.mode == mode
                    && p.variant == Variant::Specialized
            })
        };
        let mut row = vec![format!("{size}²"), count(size as f64 * size as f64)];
        row.extend(BenchMode::ALL.map(|mode| cell(at(mode))));
        row.push(count_or_dash(
            at(BenchMode::Fragment).and_then(|r| r.stats.fs_invocations),
        ));
        t.row(row);
    }
    t
}

/// What the fragment sweep's columns mean.
pub(super) const FRAGMENT_NOTE: &str = "Covered pixels: those not at the clear color in a frame read back \
after the measured ones. Equation runs per covered pixel: over the covered pixels, for the \
forward path the fragment stage's pipeline-statistics count, which lavapipe (llvmpipe) makes per \
4×4 block a triangle touches, partly covered blocks included (a GPU counts about one per pixel), \
for every draw of the sphere in a frame (the gpu sweep's 16 each pass the depth test); for the \
deferred path the lighting pass's own count (an atomic add per pixel it lights, once whatever \
the draws), its G-buffer pass not counted.";

/// The fragment mode's paths in the fragment sweep, as its rows name them.
pub(super) const FRAGMENT_PATHS: [(&str, Variant); 3] = [
    ("forward", Variant::Specialized),
    ("deferred", Variant::Deferred),
    ("deferred, uber-shader", Variant::DeferredUber),
];

/// The fragment sweep's ffvk result at image side `size` in `mode` drawn by `variant`.
pub(super) fn fragment_point(
    report: &BenchReport,
    size: u32,
    mode: BenchMode,
    variant: Variant,
) -> Option<&BenchResult> {
    find(&report.results, |p| {
        p.group == Group::Fragment
            && p.width == size
            && p.engine == Engine::Ffvk
            && p.mode == mode
            && p.variant == variant
    })
}

/// How many times a fragment point evaluated the equation, and who counted: the deferred
/// paths' lighting pass itself, or the forward path's fragment-stage statistics.
pub(super) fn equation_runs(r: &BenchResult) -> (Option<u64>, &'static str) {
    match r.point.variant {
        Variant::Deferred | Variant::DeferredUber => (r.stats.evaluations, "the lighting pass's own count"),
        _ => (r.stats.fs_invocations, "pipeline statistics"),
    }
}

/// Fragment lighting on the dense mesh: the three modes' times, the ratios issue 37 sets goals
/// for, and the fragment stage's invocations per covered pixel.
pub(super) fn fragment_table(report: &BenchReport) -> Table {
    let mut t = Table::new([
        ("image", Align::Right),
        ("path", Align::Left),
        ("covered pixels", Align::Right),
        ("fragment", Align::Right),
        ("vertex", Align::Right),
        ("unlit", Align::Right),
        ("fragment ÷ unlit", Align::Right),
        ("fragment ÷ vertex", Align::Right),
        ("equation runs per covered pixel", Align::Right),
        ("counted by", Align::Left),
    ]);
    for &size in &report.sweep.fragment_sizes {
        let at = |mode, variant| fragment_point(report, size, mode, variant);
        let (vertex, unlit) = (
            at(BenchMode::Vertex, Variant::Specialized),
            at(BenchMode::Unlit, Variant::Specialized),
        );
        let time = |r: Option<&BenchResult>| r.map(|r| r.stats.time_ms);
        let over = |a: Option<f64>, b: Option<f64>| ratio(a.zip(b).map(|(a, b)| a / b));
        for (path, variant) in FRAGMENT_PATHS {
            let Some(fragment) = at(BenchMode::Fragment, variant) else {
                continue;
            };
            let covered = fragment.stats.covered_pixels;
            let (runs, counted_by) = equation_runs(fragment);
            t.row([
                format!("{size}²"),
                path.to_string(),
                count_or_dash(covered),
                cell(Some(fragment)),
                cell(vertex),
                cell(unlit),
                over(time(Some(fragment)), time(unlit)),
                over(time(Some(fragment)), time(vertex)),
                over(
                    runs.map(|n| n as f64),
                    covered.filter(|&c| c > 0).map(|c| c as f64),
                ),
                counted_by.to_string(),
            ]);
        }
    }
    t
}

/// The note under the paths table.
pub(super) fn paths_note() -> String {
    format!(
        "Deferred ÷ forward below 1: the deferred path wins. \"G-buffer pass\" and \"lighting pass\": \
         the deferred frame's time split at a timestamp between its two passes (medians frame by \
         frame); the G-buffer pass writes {} bytes a pixel beside the depth ({} with its color, \
         which only color material and unlit draws need), the lighting pass reads them and writes \
         the 4-byte color. \"auto\": what FragmentPath::Auto picks for the frame on \
         this device (its rule, from the frame's vertices, pixels and lights; not from these times); \
         \"agrees\": whether that is the faster path here, or within 5 % of it.",
        ffvk::renderer::GBUFFER_BYTES_PER_PIXEL - 8,
        ffvk::renderer::GBUFFER_BYTES_PER_PIXEL
    )
}

/// The fragment mode's two paths over density, size and lights, with what
/// [`FragmentPath::Auto`](ffvk::FragmentPath::Auto) picks.
pub(super) fn paths_table(report: &BenchReport) -> Table {
    let mut t = Table::new([
        ("vertices", Align::Right),
        ("image", Align::Right),
        ("lights", Align::Right),
        ("vertices / pixel", Align::Right),
        ("forward", Align::Right),
        ("deferred", Align::Right),
        ("G-buffer pass", Align::Right),
        ("lighting pass", Align::Right),
        ("deferred ÷ forward", Align::Right),
        ("auto", Align::Left),
        ("agrees", Align::Left),
    ]);
    // As DeviceInfo::is_cpu decides it for the renderer.
    let cpu = report.env.device_type == "CPU";
    let c = &report.sweep;
    for &stacks in &c.path_stacks {
        for &size in &c.path_sizes {
            for &lights in &c.path_lights {
                let at = |variant| {
                    find(&report.results, |p| {
                        p.group == Group::Paths
                            && p.stacks == stacks
                            && p.width == size
                            && p.lights == lights
                            && p.variant == variant
                    })
                };
                let (forward, deferred) = (at(Variant::Specialized), at(Variant::Deferred));
                let vertices = sphere_counts(stacks).0 * u64::from(c.draws);
                let pixels = u64::from(size) * u64::from(size);
                let picks = ffvk::FragmentPath::auto_picks_deferred(cpu, vertices, pixels, lights);
                let times = forward
                    .zip(deferred)
                    .map(|(f, d)| (f.stats.time_ms, d.stats.time_ms));
                let agrees = times.map(|(f, d)| match picks {
                    true => d <= f * 1.05,
                    false => f <= d * 1.05,
                });
                t.row([
                    count(vertices as f64),
                    format!("{size}²"),
                    lights.to_string(),
                    format!("{:.3}", vertices as f64 / pixels as f64),
                    cell(forward),
                    cell(deferred),
                    deferred
                        .and_then(|d| d.stats.gbuffer_ms)
                        .map_or("–".into(), |s| ms(s.median)),
                    deferred
                        .and_then(|d| d.stats.lighting_ms)
                        .map_or("–".into(), |s| ms(s.median)),
                    ratio(times.map(|(f, d)| d / f)),
                    (if picks { "deferred" } else { "forward" }).to_string(),
                    agrees.map_or("–", |a| if a { "yes" } else { "no" }).to_string(),
                ]);
            }
        }
    }
    t
}

/// The sphere drawn as triangles, lines and points: ffvk's vertex, flat and unlit times, GL's,
/// and ffvk's over GL's for the two lit modes.
pub(super) fn primitives_table(report: &BenchReport, has_gl: bool) -> Table {
    let modes = [BenchMode::Vertex, BenchMode::Flat, BenchMode::Unlit];
    let mut t = Table::new([("drawn as", Align::Left)]);
    for mode in modes {
        t.column(mode.name(), Align::Right);
    }
    if has_gl {
        for h in ["GL smooth", "GL flat", "GL unlit", "vertex ÷ GL", "flat ÷ GL"] {
            t.column(h, Align::Right);
        }
    }
    for primitive in Primitive::ALL {
        let at = |engine, mode| {
            find(&report.results, |p| {
                p.group == Group::Primitives
                    && p.primitive == primitive
                    && p.engine == engine
                    && p.mode == mode
            })
        };
        let mut row = vec![primitive.gl_name().to_string()];
        row.extend(modes.map(|mode| cell(at(Engine::Ffvk, mode))));
        if has_gl {
            row.extend(modes.map(|mode| cell(at(Engine::Gl, mode))));
            for mode in [BenchMode::Vertex, BenchMode::Flat] {
                let pair = at(Engine::Ffvk, mode).zip(at(Engine::Gl, mode));
                row.push(ratio(
                    pair.map(|(f, g)| f.stats.wall_ms.median / g.stats.wall_ms.median),
                ));
            }
        }
        t.row(row);
    }
    t
}

/// Time against light count: vertex and fragment mode, specialized and uber, and GL's smooth
/// shading.
pub(super) fn light_count_table(report: &BenchReport, has_gl: bool) -> Table {
    let mut t = Table::new(
        [
            "lights",
            "vertex specialized",
            "vertex uber",
            "uber ÷ spec.",
            "fragment specialized",
            "fragment uber",
            "uber ÷ spec.",
        ]
        .map(|h| (h, Align::Right)),
    );
    if has_gl {
        for h in ["GL smooth", "ffvk vertex ÷ GL"] {
            t.column(h, Align::Right);
        }
    }
    for &lights in &report.sweep.light_counts {
        let at = |engine, mode, variant| {
            find(&report.results, |p| {
                p.group == Group::Lights
                    && p.lights == lights
                    && p.engine == engine
                    && p.mode == mode
                    && p.variant == variant
            })
        };
        let mut row = vec![lights.to_string()];
        for mode in [BenchMode::Vertex, BenchMode::Fragment] {
            let s = at(Engine::Ffvk, mode, Variant::Specialized);
            let u = at(Engine::Ffvk, mode, Variant::Uber);
            let uber = s.zip(u).map(|(s, u)| u.stats.time_ms / s.stats.time_ms);
            row.extend([cell(s), cell(u), ratio(uber)]);
        }
        if has_gl {
            let g = at(Engine::Gl, BenchMode::Vertex, Variant::FixedFunction);
            let gl = report
                .summary
                .gl_ratios
                .iter()
                .find(|r| r.group == Group::Lights && r.lights == lights);
            row.extend([cell(g), ratio(gl.map(|r| r.ratio))]);
        }
        t.row(row);
    }
    t
}

/// Time against light kind and viewer: vertex and fragment mode, specialized and uber, and
/// GL's smooth shading.
pub(super) fn light_kind_table(report: &BenchReport, has_gl: bool) -> Table {
    let mut t = Table::new([("lights", Align::Left), ("viewer", Align::Left)]);
    for h in [
        "vertex specialized",
        "vertex uber",
        "fragment specialized",
        "fragment uber",
    ] {
        t.column(h, Align::Right);
    }
    if has_gl {
        for h in ["GL smooth", "ffvk vertex ÷ GL"] {
            t.column(h, Align::Right);
        }
    }
    // What a lighting variant costs: its specialized time over its GL form's.
    for h in ["vertex vs GL form", "fragment vs GL form"] {
        t.column(h, Align::Right);
    }
    for &kind in &report.sweep.kinds {
        for local in [false, true] {
            let at = |engine, mode, variant| {
                find(&report.results, |p| {
                    p.group == Group::Kind
                        && p.light_kind == kind
                        && p.local_viewer == local
                        && p.engine == engine
                        && p.mode == mode
                        && p.variant == variant
                })
            };
            let viewer = if local { "local" } else { "infinite" };
            let mut row = vec![kind.name().to_string(), viewer.to_string()];
            for mode in [BenchMode::Vertex, BenchMode::Fragment] {
                for variant in [Variant::Specialized, Variant::Uber] {
                    row.push(cell(at(Engine::Ffvk, mode, variant)));
                }
            }
            if has_gl {
                let g = at(Engine::Gl, BenchMode::Vertex, Variant::FixedFunction);
                let f = at(Engine::Ffvk, BenchMode::Vertex, Variant::Specialized);
                let gl = f
                    .zip(g)
                    .map(|(f, g)| f.stats.wall_ms.median / g.stats.wall_ms.median);
                row.extend([cell(g), ratio(gl)]);
            }
            for mode in [BenchMode::Vertex, BenchMode::Fragment] {
                let time = |kind: LightKind| {
                    find(&report.results, |p| {
                        p.group == Group::Kind
                            && p.light_kind == kind
                            && p.local_viewer == local
                            && p.engine == Engine::Ffvk
                            && p.mode == mode
                            && p.variant == Variant::Specialized
                    })
                    .map(|p| p.stats.wall_ms.median)
                };
                let cost = kind.gl_form().and_then(|form| Some(time(kind)? / time(form)?));
                row.push(ratio(cost));
            }
            t.row(row);
        }
    }
    t
}
