//! The stages sweep's table: what fog, the alpha test, the color sum, user clip planes and
//! texturing (one unit, four) cost in each lighting mode, specialized and uber, against the
//! same frame without them, and GL's own cost of each.

use super::format::{find, ms, ratio};
use super::sweep::{BenchMode, Engine, Group, Stage, Variant};
use super::{BenchReport, BenchResult};
use crate::table::{Align, Table};

pub(super) const STAGES_NOTE: &str = "Each stage alone, then all together, on the light sweeps' \
sphere; \"÷ none\" is the time over the same column's frame without stages. The alpha test \
passes every fragment and the clip planes cut nothing, so each row costs the stage's work and \
draws the pixels of the row \"none\"; lit draws always sum the secondary color, so \
GL_COLOR_SUM changes only the unlit column. The texturing rows bind 64² textures, linear, no \
mipmaps: one unit modulated; then four, the second a light map through GL_COMBINE (MODULATE \
× 2), the third sphere-mapped, the fourth a 16² cube map by GL_REFLECTION_MAP, added.";

/// The stages table (see [`STAGES_NOTE`]).
pub(super) fn stages_table(report: &BenchReport, has_gl: bool) -> Table {
    let columns: Vec<(Engine, BenchMode, Variant, &str)> = {
        let mut c = vec![
            (Engine::Ffvk, BenchMode::Vertex, Variant::Specialized, "vertex"),
            (Engine::Ffvk, BenchMode::Vertex, Variant::Uber, "vertex uber"),
            (
                Engine::Ffvk,
                BenchMode::Fragment,
                Variant::Specialized,
                "fragment",
            ),
            (Engine::Ffvk, BenchMode::Fragment, Variant::Uber, "fragment uber"),
            (Engine::Ffvk, BenchMode::Flat, Variant::Specialized, "flat"),
            (Engine::Ffvk, BenchMode::Unlit, Variant::Specialized, "unlit"),
        ];
        if has_gl {
            c.push((Engine::Gl, BenchMode::Vertex, Variant::FixedFunction, "GL smooth"));
            c.push((Engine::Gl, BenchMode::Unlit, Variant::FixedFunction, "GL unlit"));
        }
        c
    };
    let mut t = Table::new([("stage", Align::Left)]);
    for &(_, _, _, name) in &columns {
        t.column(name, Align::Right);
        t.column("÷ none", Align::Right);
    }
    if has_gl {
        t.column("vertex ÷ GL", Align::Right);
    }
    let at = |stage: Stage, engine: Engine, mode: BenchMode, variant: Variant| -> Option<&BenchResult> {
        find(&report.results, |p| {
            p.group == Group::Stages
                && p.stage == stage
                && p.engine == engine
                && p.mode == mode
                && p.variant == variant
        })
    };
    for stage in Stage::ALL {
        let mut row = vec![stage.label().to_string()];
        for &(engine, mode, variant, _) in &columns {
            let here = at(stage, engine, mode, variant);
            let none = at(Stage::Off, engine, mode, variant);
            row.push(here.map_or("–".into(), |r| ms(r.stats.time_ms)));
            row.push(ratio(
                here.zip(none).map(|(h, n)| h.stats.time_ms / n.stats.time_ms),
            ));
        }
        if has_gl {
            let ours = at(stage, Engine::Ffvk, BenchMode::Vertex, Variant::Specialized);
            let gl = at(stage, Engine::Gl, BenchMode::Vertex, Variant::FixedFunction);
            row.push(ratio(
                ours.zip(gl).map(|(o, g)| o.stats.time_ms / g.stats.time_ms),
            ));
        }
        t.row(row);
    }
    t
}
