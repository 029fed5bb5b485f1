//! How the bench's tables and plots write numbers and results: times, counts, ratios, light
//! counts, and the result a table cell shows. A leaf: the summary (`report.rs`), its tables
//! (`tables.rs`) and the plots (`plots.rs`) all use it.

use super::sweep::Point;
use super::BenchResult;

/// "1 directional light", "4 directional lights".
pub(super) fn lights_text(n: usize) -> String {
    format!("{n} directional light{}", if n == 1 { "" } else { "s" })
}

pub(super) fn ms(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
}

/// "median (p25–p75)" of a result's main time.
pub(super) fn cell(r: Option<&BenchResult>) -> String {
    match r {
        None => "–".into(),
        Some(r) => {
            let s = r.stats.gpu_ms.unwrap_or(r.stats.wall_ms);
            format!("{} ({}–{})", ms(r.stats.time_ms), ms(s.p25), ms(s.p75))
        }
    }
}

pub(super) fn find(results: &[BenchResult], keep: impl Fn(&Point) -> bool) -> Option<&BenchResult> {
    results.iter().find(|r| keep(&r.point))
}

pub(super) fn count(n: f64) -> String {
    if n >= 1e6 {
        format!("{:.2} M", n / 1e6)
    } else if n >= 1e3 {
        format!("{:.1} k", n / 1e3)
    } else {
        format!("{n:.0}")
    }
}

/// "–" for nothing, else the ratio to two decimals.
pub(super) fn ratio(r: Option<f64>) -> String {
    r.map_or("–".into(), |r| format!("{r:.2}"))
}

/// "–" for nothing, else the count.
pub(super) fn count_or_dash(n: Option<u64>) -> String {
    n.map_or("–".into(), |n| count(n as f64))
}
