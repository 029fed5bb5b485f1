//! The plots of a run (PNG): time against vertices, pixels and light count.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::format::{count, lights_text};
use super::measure::{is, series};
use super::points::{sphere_counts, GL_MODES};
use super::sweep::{BenchMode, Engine, Group, Point, Variant};
use super::{BenchReport, BenchResult};
use crate::{Error, Result};

/// Tick labels: "20 k", "1.5 M", "0.5", "12".
fn axis_number(v: f64) -> String {
    let a = v.abs();
    if a >= 1e6 {
        format!("{} M", trim(v / 1e6))
    } else if a >= 1e4 {
        format!("{} k", trim(v / 1e3))
    } else {
        trim(v)
    }
}

fn trim(v: f64) -> String {
    let s = if v.abs() >= 100.0 || v.fract() == 0.0 {
        format!("{v:.0}")
    } else if v.abs() >= 1.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    };
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

const WIDTH: u32 = 1000;
const HEIGHT: u32 = 640;

/// Registers the embedded DejaVu Sans as plotters' "sans-serif" (once per process).
fn ensure_font() -> Result<()> {
    static FONT: OnceLock<bool> = OnceLock::new();
    let registered = *FONT.get_or_init(|| {
        plotters::style::register_font("sans-serif", FontStyle::Normal, crate::sheet::LABEL_FONT).is_ok()
    });
    if registered {
        Ok(())
    } else {
        Err(Error::Font {
            message: "the embedded DejaVu Sans is not a usable TrueType font".into(),
        })
    }
}

fn color(mode: BenchMode) -> RGBColor {
    match mode {
        BenchMode::Vertex => RGBColor(31, 119, 180),
        BenchMode::Fragment => RGBColor(214, 39, 40),
        BenchMode::Flat => RGBColor(44, 160, 44),
        BenchMode::Unlit => RGBColor(127, 127, 127),
    }
}

/// One line of a plot.
struct Line {
    label: String,
    color: RGBColor,
    dashed: bool,
    /// (x, median, low, high).
    points: Vec<(f64, f64, f64, f64)>,
}

/// The lines of one sweep against `x`: ffvk's specialized modes, then GL's.
fn mode_lines(res: &[BenchResult], group: Group, x: fn(&Point) -> f64) -> Vec<Line> {
    let mut lines = Vec::new();
    for mode in BenchMode::ALL {
        let ser = series(res, is(group, Engine::Ffvk, mode, Variant::Specialized), x);
        lines.extend(line(format!("ffvk {}", mode.name()), color(mode), false, &ser));
    }
    // GL's lines dashed in the modes' colors, zink's dashed in darker ones.
    for (engine, shade) in [(Engine::Gl, 1), (Engine::Zink, 2)] {
        for mode in GL_MODES {
            let ser = series(res, is(group, engine, mode, Variant::FixedFunction), x);
            let name = if mode == BenchMode::Vertex {
                "smooth"
            } else {
                mode.name()
            };
            let RGBColor(r, g, b) = color(mode);
            let c = RGBColor(r / shade, g / shade, b / shade);
            lines.extend(line(format!("{} {name}", engine.name()), c, true, &ser));
        }
    }
    lines
}

fn line(label: String, color: RGBColor, dashed: bool, s: &[(f64, &BenchResult)]) -> Option<Line> {
    let points: Vec<(f64, f64, f64, f64)> = s
        .iter()
        .map(|(x, r)| {
            let sp = r.stats.gpu_ms.unwrap_or(r.stats.wall_ms);
            (*x, r.stats.time_ms, sp.min, sp.max)
        })
        .collect();
    (!points.is_empty()).then_some(Line {
        label,
        color,
        dashed,
        points,
    })
}

/// A log-log (or lin-log) chart of `lines` with min–max whiskers and vertical markers.
fn chart(
    path: &Path,
    title: &str,
    x_label: &str,
    x_log: bool,
    lines: &[Line],
    markers: &[(f64, String)],
) -> Result<()> {
    let err = |message: String| Error::Plot {
        path: path.to_path_buf(),
        message,
    };
    let plot_err = |e: &dyn std::fmt::Display| err(e.to_string());
    let mut buffer = vec![0u8; (WIDTH * HEIGHT * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| plot_err(&e))?;
        let all: Vec<&(f64, f64, f64, f64)> = lines.iter().flat_map(|l| &l.points).collect();
        if all.is_empty() {
            return Err(err("no points to plot".into()));
        }
        let (mut x0, mut x1) = (f64::MAX, f64::MIN);
        let (mut y0, mut y1) = (f64::MAX, f64::MIN);
        for &&(x, y, lo, hi) in &all {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(lo.min(y));
            y1 = y1.max(hi.max(y));
        }
        let (y0, y1) = ((y0 * 0.8).max(1e-3), y1 * 1.25);
        // Crossover labels sit left of their line in the right half of the plot.
        let markers: Vec<(f64, String, bool)> = markers
            .iter()
            .map(|(x, t)| {
                let f = if x_log {
                    (x.ln() - x0.ln()) / (x1.ln() - x0.ln()).max(1e-9)
                } else {
                    (x - x0) / (x1 - x0).max(1e-9)
                };
                (*x, t.clone(), f > 0.5)
            })
            .collect();
        let markers = &markers[..];
        if x_log {
            let (x0, x1) = (x0 / 1.3, x1 * 1.3);
            let c = builder(&root, title)
                .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
                .map_err(|e| plot_err(&e))?;
            draw(c, x_label, lines, markers, (y0, y1)).map_err(|e| plot_err(&e))?;
        } else {
            // A linear x (light counts) gets a linear time axis from zero.
            let pad = ((x1 - x0) * 0.05).max(0.5);
            let c = builder(&root, title)
                .build_cartesian_2d((x0 - pad)..(x1 + pad), 0.0..y1)
                .map_err(|e| plot_err(&e))?;
            draw(c, x_label, lines, markers, (0.0, y1)).map_err(|e| plot_err(&e))?;
        }
        root.present().map_err(|e| plot_err(&e))?;
    }
    let rgb =
        image::RgbImage::from_raw(WIDTH, HEIGHT, buffer).ok_or_else(|| err("plot buffer size".into()))?;
    Ok(ffvk::images::save_png(
        &image::DynamicImage::ImageRgb8(rgb).to_rgba8(),
        path,
    )?)
}

type Chart<'a, X, Y> = ChartContext<'a, BitMapBackend<'a>, Cartesian2d<X, Y>>;
type DrawResult<'a> =
    std::result::Result<(), DrawingAreaErrorKind<<BitMapBackend<'a> as DrawingBackend>::ErrorType>>;

fn builder<'a, 'b>(
    root: &'a DrawingArea<BitMapBackend<'b>, Shift>,
    title: &str,
) -> ChartBuilder<'a, 'b, BitMapBackend<'b>> {
    let mut b = ChartBuilder::on(root);
    b.caption(title, ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(64);
    b
}

fn draw<'a, X, Y>(
    mut c: Chart<'a, X, Y>,
    x_label: &str,
    lines: &[Line],
    markers: &[(f64, String, bool)],
    (y0, y1): (f64, f64),
) -> DrawResult<'a>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    c.configure_mesh()
        .x_desc(x_label)
        .y_desc("time per frame, ms (median; whiskers: min–max)")
        .x_label_formatter(&|v| axis_number(*v))
        .y_label_formatter(&|v| axis_number(*v))
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 16))
        .draw()?;
    for (x, text, left_of_line) in markers {
        let style = ShapeStyle::from(&BLACK.mix(0.6)).stroke_width(1);
        c.draw_series(DashedLineSeries::new(vec![(*x, y0), (*x, y1)], 6, 4, style))?;
        let anchor = if *left_of_line { HPos::Right } else { HPos::Left };
        let font = ("sans-serif", 15)
            .into_font()
            .color(&BLACK)
            .pos(Pos::new(anchor, VPos::Top));
        let text = if *left_of_line {
            format!("{text} ")
        } else {
            format!(" {text}")
        };
        c.draw_series(std::iter::once(Text::new(text, (*x, y1 / 1.1), font)))?;
    }
    for l in lines {
        let style = ShapeStyle::from(&l.color).stroke_width(2);
        let pts: Vec<(f64, f64)> = l.points.iter().map(|p| (p.0, p.1)).collect();
        let anno = if l.dashed {
            c.draw_series(DashedLineSeries::new(pts.clone(), 8, 5, style))?
        } else {
            c.draw_series(LineSeries::new(pts.clone(), style))?
        };
        let legend_color = l.color;
        let dashed = l.dashed;
        anno.label(l.label.clone()).legend(move |(x, y)| {
            let s = ShapeStyle::from(&legend_color).stroke_width(if dashed { 1 } else { 3 });
            PathElement::new(vec![(x, y), (x + 22, y)], s)
        });
        c.draw_series(
            pts.iter()
                .map(|&(x, y)| Circle::new((x, y), 3, ShapeStyle::from(&l.color).filled())),
        )?;
        c.draw_series(l.points.iter().map(|&(x, _, lo, hi)| {
            PathElement::new(vec![(x, lo), (x, hi)], ShapeStyle::from(&l.color.mix(0.7)))
        }))?;
    }
    c.configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .label_font(("sans-serif", 15))
        .draw()?;
    Ok(())
}

/// Writes every plot the report has data for; returns the paths.
pub(super) fn write_all(report: &BenchReport, dir: &Path) -> Result<Vec<PathBuf>> {
    ensure_font()?;
    let res = &report.results;
    let c = &report.sweep;
    let s = &report.summary;
    let spec = Variant::Specialized;
    let mut written = Vec::new();

    // Time against vertices, per mode (+ GL).
    let lines = mode_lines(res, Group::Density, |p| p.vertices as f64);
    if !lines.is_empty() {
        let markers: Vec<(f64, String)> = s
            .crossover_vertices
            .map(|v| (v, format!("vertex = fragment at {} vertices", count(v))))
            .into_iter()
            .collect();
        let path = dir.join("time_vs_vertices.png");
        chart(
            &path,
            &format!(
                "Time against vertex count ({}² image, {})",
                c.base_size,
                lights_text(c.base_lights)
            ),
            "vertices (log)",
            true,
            &lines,
            &markers,
        )?;
        written.push(path);
    }

    // Time against pixels, per mode (+ GL).
    let lines = mode_lines(res, Group::Size, |p| p.pixels as f64);
    if !lines.is_empty() {
        let markers: Vec<(f64, String)> = s
            .crossover_pixels
            .map(|p| (p, format!("vertex = fragment at {} pixels", count(p))))
            .into_iter()
            .collect();
        let path = dir.join("time_vs_pixels.png");
        chart(
            &path,
            &format!(
                "Time against pixel count ({} vertices, {})",
                sphere_counts(c.size_stacks).0,
                lights_text(c.base_lights)
            ),
            "pixels (log)",
            true,
            &lines,
            &markers,
        )?;
        written.push(path);
    }

    // Time against light count: specialized against uber (+ GL).
    let mut lines = Vec::new();
    for mode in [BenchMode::Vertex, BenchMode::Fragment] {
        for variant in [spec, Variant::Uber] {
            let ser = series(res, is(Group::Lights, Engine::Ffvk, mode, variant), |p| {
                p.lights as f64
            });
            lines.extend(line(
                format!("ffvk {} {}", mode.name(), variant.name()),
                color(mode),
                variant == Variant::Uber,
                &ser,
            ));
        }
    }
    for (engine, c) in [
        (Engine::Gl, RGBColor(0, 0, 0)),
        (Engine::Zink, RGBColor(127, 127, 127)),
    ] {
        let ser = series(
            res,
            is(Group::Lights, engine, BenchMode::Vertex, Variant::FixedFunction),
            |p| p.lights as f64,
        );
        lines.extend(line(format!("{} smooth", engine.name()), c, true, &ser));
    }
    if !lines.is_empty() {
        let path = dir.join("time_vs_lights.png");
        chart(
            &path,
            &format!(
                "Time against light count: specialized and uber pipelines ({} vertices, {}²)",
                sphere_counts(c.base_stacks).0,
                c.base_size
            ),
            "directional lights",
            false,
            &lines,
            &[],
        )?;
        written.push(path);
    }
    Ok(written)
}
