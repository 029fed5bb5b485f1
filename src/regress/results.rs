//! The results of regression runs as data: what each run (or shard) was, its rows, the counts
//! and the exit code; written as JSON (`--json`), read back and merged across shards
//! (`ffvk results merge`).

use std::fmt;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::{Partition, Row, Status};
use crate::{Error, Result};
use ffvk::images::compare::Tolerance;

/// The `format` field of a results file this version writes and reads.
pub const FORMAT: &str = "ffvk-results/1";

/// The largest results file read: a suite of about a million images.
const MAX_RESULTS_BYTES: u64 = 1 << 30;

/// The device the images were rendered on, as a worker reports it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct DeviceSummary {
    /// `deviceName`.
    pub device: String,
    /// `VkPhysicalDeviceType`, e.g. `CPU`.
    pub device_type: String,
    /// `driverName`, e.g. `llvmpipe`.
    pub driver: String,
    /// `driverInfo`: the Mesa version for lavapipe.
    pub driver_info: String,
    /// The device's Vulkan version.
    pub api_version: String,
}

impl DeviceSummary {
    /// The summary of `info`.
    pub fn of(info: &ffvk::vk::DeviceInfo) -> DeviceSummary {
        DeviceSummary {
            device: info.name.clone(),
            device_type: info.device_type.clone(),
            driver: info.driver_name.clone(),
            driver_info: info.driver_info.clone(),
            api_version: info.api_version.clone(),
        }
    }
}

/// What one run (one shard, when partitioned) was.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct RunInfo {
    /// ffvk's version.
    pub ffvk: String,
    /// The device, when a worker started.
    pub device: Option<DeviceSummary>,
    /// Worker processes.
    pub jobs: usize,
    /// LP_NUM_THREADS in each worker (lavapipe's rasterizer threads), when set.
    pub lp_num_threads: Option<String>,
    /// The shard, when partitioned.
    pub partition: Option<Partition>,
    /// Scenes in the whole suite.
    pub suite_scenes: usize,
    /// Scenes this run rendered (its shard's).
    pub scenes: usize,
    /// Lighting modes asked for (empty: each scene's own).
    pub modes: Vec<String>,
    /// The reference folder, when checking.
    pub references: Option<PathBuf>,
    /// Whether references were blessed.
    pub bless: bool,
    /// The tolerance images were checked with.
    pub tolerance: Tolerance,
    /// When the run started: UTC, `YYYY-MM-DDThh:mm:ss`.
    pub timestamp: String,
    /// The machine's host name.
    pub hostname: String,
    /// Wall-clock seconds of the run.
    pub seconds: f64,
}

/// One run and its rows.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Run {
    /// What the run was.
    pub info: RunInfo,
    /// Its rows, in suite order.
    pub rows: Vec<Row>,
}

/// A results file: one run, or the shards of one suite merged.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Results {
    /// [`FORMAT`].
    pub format: String,
    /// The runs, shards in partition order.
    pub runs: Vec<Run>,
}

/// How many rows ended how.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Counts {
    /// Rows.
    pub images: usize,
    /// Within tolerance.
    pub passed: usize,
    /// Beyond tolerance or of another size.
    pub failed: usize,
    /// Without a reference.
    pub missing: usize,
    /// References written.
    pub blessed: usize,
    /// Rendered with nothing to check against.
    pub rendered: usize,
    /// Errors (load, render, write, worker crash or timeout).
    pub errors: usize,
}

impl Counts {
    /// The counts of `rows`.
    pub fn of(rows: &[Row]) -> Counts {
        let mut c = Counts {
            images: rows.len(),
            ..Counts::default()
        };
        for r in rows {
            match r.status {
                Status::Pass => c.passed += 1,
                Status::Fail => c.failed += 1,
                Status::Missing => c.missing += 1,
                Status::Blessed => c.blessed += 1,
                Status::Rendered => c.rendered += 1,
                Status::Error => c.errors += 1,
            }
        }
        c
    }

    /// The documented exit code: 2 when any row is an error (errors win), else 1 when any
    /// image differs or lacks its reference, else 0.
    pub fn exit_code(&self) -> u8 {
        if self.errors > 0 {
            2
        } else if self.failed + self.missing > 0 {
            1
        } else {
            0
        }
    }
}

impl fmt::Display for Counts {
    /// `N image(s): P passed, F failed, …`, leaving out the kinds that did not happen.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} image(s)", self.images)?;
        let parts = [
            (self.passed, "passed"),
            (self.failed, "failed"),
            (self.missing, "missing"),
            (self.blessed, "blessed"),
            (self.rendered, "rendered"),
            (self.errors, "error(s)"),
        ];
        let mut first = true;
        for (n, word) in parts.into_iter().filter(|(n, _)| *n > 0) {
            write!(f, "{}{n} {word}", if first { ": " } else { ", " })?;
            first = false;
        }
        Ok(())
    }
}

impl Results {
    /// One run's results.
    pub fn single(info: RunInfo, rows: Vec<Row>) -> Results {
        Results {
            format: FORMAT.into(),
            runs: vec![Run { info, rows }],
        }
    }

    /// Every row of every run, in suite order.
    pub fn rows(&self) -> Vec<Row> {
        let mut rows: Vec<Row> = self.runs.iter().flat_map(|r| r.rows.iter().cloned()).collect();
        // Stable: the modes of one scene keep their order.
        rows.sort_by_key(|r| r.index);
        rows
    }

    /// The counts over every run.
    pub fn counts(&self) -> Counts {
        Counts::of(&self.rows())
    }

    /// Writes the results as JSON, atomically.
    pub fn write_json(&self, path: &Path) -> Result<()> {
        let text = serde_json::to_string_pretty(self).map_err(|source| Error::Json {
            path: path.to_path_buf(),
            source,
        })?;
        crate::write_file(path, text.as_bytes())
    }

    /// Reads a results file written by [`Results::write_json`].
    pub fn read_json(path: &Path) -> Result<Results> {
        let read = |source| Error::Read {
            path: path.to_path_buf(),
            source,
        };
        // A regular file of bounded size: a pipe or /dev/zero given by mistake must not
        // hang the command or fill memory.
        let bytes = ffvk::files::read_regular(path, MAX_RESULTS_BYTES).map_err(read)?;
        let text = String::from_utf8(bytes).map_err(|e| MergeError::Parse {
            path: path.to_path_buf(),
            message: format!("not UTF-8 text: {e}"),
        })?;
        // Broken JSON (a download cut short) says where, before the format is looked at.
        let value = serde_json::from_str::<serde_json::Value>(&text).map_err(|e| MergeError::Parse {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        let format = value.get("format").map(|f| match f.as_str() {
            Some(s) => s.to_owned(),
            None => f.to_string(),
        });
        if format.as_deref() != Some(FORMAT) {
            return Err(MergeError::Format {
                path: path.to_path_buf(),
                found: format.unwrap_or_else(|| "no format field".into()),
            }
            .into());
        }
        let results: Results = serde_json::from_str(&text).map_err(|e| MergeError::Parse {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        results.check(path)?;
        Ok(results)
    }

    /// Refuses what no run of ffvk writes, naming the file (`path`) and the JSON field: a
    /// partition outside 1..=count, more scenes than the suite, a row at an index past the
    /// suite's scenes or of a scene of another shard (by [`Partition::contains`]), rows that
    /// do not cover the run's scenes once in each mode, two rows of one scene in one mode.
    pub fn check(&self, path: &Path) -> Result<(), MergeError> {
        for (at, run) in self.runs.iter().enumerate() {
            check_run(path, at, run)?;
        }
        Ok(())
    }

    /// Joins the results of the shards of one suite, checking that together they are every
    /// shard exactly once and cover every scene exactly once.
    pub fn merge(parts: Vec<(PathBuf, Results)>) -> Result<Results> {
        let mut runs: Vec<(PathBuf, Run)> = Vec::new();
        for (path, results) in parts {
            results.check(&path)?;
            runs.extend(results.runs.into_iter().map(|r| (path.clone(), r)));
        }
        let Some((first_path, first)) = runs.first() else {
            return Err(MergeError::Nothing.into());
        };
        let count = first.info.partition.map_or(1, |p| p.count);
        let suite = first.info.suite_scenes;
        let mut seen: Vec<Option<&Path>> = vec![None; count as usize];
        for (path, run) in &runs {
            let p = run.info.partition.unwrap_or(Partition { index: 1, count: 1 });
            if p.count != count || run.info.suite_scenes != suite {
                return Err(MergeError::OtherSuite {
                    first: first_path.clone(),
                    first_shards: count,
                    first_scenes: suite,
                    other: path.clone(),
                    other_shards: p.count,
                    other_scenes: run.info.suite_scenes,
                }
                .into());
            }
            if let Some(earlier) = seen[p.index as usize - 1] {
                return Err(MergeError::SameShard {
                    shard: p,
                    first: earlier.to_path_buf(),
                    second: path.clone(),
                }
                .into());
            }
            seen[p.index as usize - 1] = Some(path);
        }
        let missing: Vec<String> = seen
            .iter()
            .enumerate()
            .filter(|(_, s)| s.is_none())
            .map(|(i, _)| format!("{}/{count}", i + 1))
            .collect();
        if !missing.is_empty() {
            return Err(MergeError::MissingShards { missing, count }.into());
        }
        // Each scene of the suite in one shard: no index in two.
        let mut indices: Vec<(usize, &Path, &str)> = runs
            .iter()
            .flat_map(|(path, r)| {
                r.rows
                    .iter()
                    .map(move |row| (row.index, path.as_path(), row.scene.as_str()))
            })
            .collect();
        indices.sort_by_key(|&(index, ..)| index);
        indices.dedup_by(|a, b| a.0 == b.0 && a.1 == b.1);
        if let Some(w) = indices.windows(2).find(|w| w[0].0 == w[1].0) {
            return Err(MergeError::SameIndex {
                index: w[0].0,
                first: w[0].1.to_path_buf(),
                first_scene: w[0].2.to_owned(),
                second: w[1].1.to_path_buf(),
                second_scene: w[1].2.to_owned(),
            }
            .into());
        }
        let scenes: usize = runs.iter().map(|(_, r)| r.info.scenes).sum();
        if scenes != suite {
            return Err(MergeError::Coverage { scenes, suite }.into());
        }
        let mut names: Vec<(&str, &Path)> = runs
            .iter()
            .flat_map(|(path, r)| r.rows.iter().map(move |row| (row.name.as_str(), path.as_path())))
            .collect();
        names.sort();
        if let Some(w) = names.windows(2).find(|w| w[0].0 == w[1].0) {
            return Err(MergeError::SameImage {
                name: w[0].0.to_owned(),
                first: w[0].1.to_path_buf(),
                second: w[1].1.to_path_buf(),
            }
            .into());
        }
        runs.sort_by_key(|(_, r)| r.info.partition.map_or(1, |p| p.index));
        Ok(Results {
            format: FORMAT.into(),
            runs: runs.into_iter().map(|(_, r)| r).collect(),
        })
    }
}

/// What no run writes in a row, if the row has it: a mode that is not a lighting mode, a name
/// that leaves the suite's folder (`..`, an absolute path), a comparison of an image no run
/// draws (a side of 0 or past 16384) or whose pixels lie outside it. The field (below
/// `rows[k].`), the value and what was expected.
fn row_problem(row: &crate::regress::Row) -> Option<(String, String, String)> {
    if let Some(mode) = &row.mode {
        if !["vertex", "fragment", "flat"].contains(&mode.as_str()) {
            return Some((
                "mode".into(),
                format!("{mode:?}"),
                "\"vertex\", \"fragment\" or \"flat\"".into(),
            ));
        }
    }
    let name = Path::new(&row.name);
    if name.is_absolute()
        || name
            .components()
            .any(|c| matches!(c, std::path::Component::ParentDir))
    {
        return Some((
            "name".into(),
            format!("{:?}", row.name),
            "a scene's path below the suite's folder, without \"..\"".into(),
        ));
    }
    let c = row.comparison.as_ref()?;
    if !(1..=16384).contains(&c.width) || !(1..=16384).contains(&c.height) {
        return Some((
            "comparison".into(),
            format!("{}x{}", c.width, c.height),
            "an image of 1 to 16384 pixels a side".into(),
        ));
    }
    if c.over as u64 > u64::from(c.width) * u64::from(c.height) {
        return Some((
            "comparison.over".into(),
            c.over.to_string(),
            format!(
                "at most the image's {} pixels",
                u64::from(c.width) * u64::from(c.height)
            ),
        ));
    }
    for (what, pixel) in [("worst", &c.worst), ("first_over", &c.first_over)] {
        if let Some(p) = pixel.as_ref().filter(|p| p.x >= c.width || p.y >= c.height) {
            return Some((
                format!("comparison.{what}"),
                format!("({}, {})", p.x, p.y),
                format!("a pixel of the {}x{} image", c.width, c.height),
            ));
        }
    }
    None
}

/// The checks of [`Results::check`] on run `at` of the file at `path`.
fn check_run(path: &Path, at: usize, run: &Run) -> Result<(), MergeError> {
    let info = &run.info;
    let field = |field: String, value: String, expected: String| MergeError::Field {
        path: path.to_path_buf(),
        field: format!("runs[{at}].{field}"),
        value,
        expected,
    };
    if let Some(p) = info.partition {
        if p.count == 0 {
            return Err(field(
                "info.partition.count".into(),
                "0".into(),
                "1 or more shards".into(),
            ));
        }
        if !(1..=p.count).contains(&p.index) {
            return Err(field(
                "info.partition.index".into(),
                p.index.to_string(),
                format!("a shard in 1..={} (partition.count)", p.count),
            ));
        }
    }
    let suite = info.suite_scenes;
    if info.scenes > suite {
        return Err(field(
            "info.scenes".into(),
            info.scenes.to_string(),
            format!("at most the suite's {suite} (info.suite_scenes)"),
        ));
    }
    for (k, row) in run.rows.iter().enumerate() {
        if row.index >= suite {
            return Err(field(
                format!("rows[{k}].index"),
                row.index.to_string(),
                format!("a scene's place in the suite of {suite}, 0..{suite} (info.suite_scenes)"),
            ));
        }
        if let Some(p) = info.partition.filter(|p| !p.contains(&row.scene)) {
            return Err(field(
                format!("rows[{k}].scene"),
                format!("{:?}", row.scene),
                format!("a scene of shard {p}: this name hashes to another shard (--partition)"),
            ));
        }
        if let Some(problem) = row_problem(row) {
            let (name, value, expected) = problem;
            return Err(field(format!("rows[{k}].{name}"), value, expected));
        }
        if !info.modes.is_empty() && !row.mode.as_ref().is_some_and(|m| info.modes.contains(m)) {
            return Err(field(
                format!("rows[{k}].mode"),
                format!("{:?}", row.mode),
                format!("one of the run's modes {:?} (info.modes)", info.modes),
            ));
        }
    }
    let mut indices: Vec<usize> = run.rows.iter().map(|r| r.index).collect();
    indices.sort_unstable();
    indices.dedup();
    if indices.len() != info.scenes {
        return Err(MergeError::Rows {
            path: path.to_path_buf(),
            scenes: info.scenes,
            found: indices.len(),
        });
    }
    let modes = info.modes.len().max(1);
    if run.rows.len() != info.scenes * modes {
        return Err(field(
            "rows".into(),
            format!("{} rows", run.rows.len()),
            format!(
                "one row per scene and mode: {} scene(s) (info.scenes) x {modes} mode(s) = {}",
                info.scenes,
                info.scenes * modes
            ),
        ));
    }
    let mut keys: Vec<(usize, Option<&str>, usize)> = run
        .rows
        .iter()
        .enumerate()
        .map(|(k, r)| (r.index, r.mode.as_deref(), k))
        .collect();
    keys.sort_unstable();
    if let Some(w) = keys.windows(2).find(|w| (w[0].0, w[0].1) == (w[1].0, w[1].1)) {
        return Err(field(
            format!("rows[{}]", w[1].2),
            format!("a second row at index {} in mode {:?}", w[1].0, w[1].1),
            format!("one row per scene and mode (the first is rows[{}])", w[0].2),
        ));
    }
    let mut scenes: Vec<(usize, &str, usize)> = run
        .rows
        .iter()
        .enumerate()
        .map(|(k, r)| (r.index, r.scene.as_str(), k))
        .collect();
    scenes.sort_unstable();
    if let Some(w) = scenes.windows(2).find(|w| w[0].0 == w[1].0 && w[0].1 != w[1].1) {
        return Err(field(
            format!("rows[{}].scene", w[1].2),
            format!("{:?} at index {}", w[1].1, w[1].0),
            format!("one scene at each index: rows[{}] has {:?} there", w[0].2, w[0].1),
        ));
    }
    Ok(())
}

/// Results files that cannot be read or merged.
#[allow(missing_docs)] // each variant's text names its fields
#[derive(Debug, thiserror::Error)]
pub enum MergeError {
    /// No results were given.
    #[error("no results to merge: expected one or more results files written by --json")]
    Nothing,
    /// Not a results file of this version.
    #[error("{}: format is {found:?}: expected {FORMAT:?} (a file written by ffvk render --json)", .path.display())]
    Format { path: PathBuf, found: String },
    /// A results file that does not parse.
    #[error("{}: not a results file: {message}", .path.display())]
    Parse { path: PathBuf, message: String },
    /// Shards of different suites or partition counts.
    #[error("{} is one of {other_shards} shard(s) of a suite of {other_scenes} scenes, but {} is one of {first_shards} of {first_scenes}: expected the shards of one suite", .other.display(), .first.display())]
    OtherSuite {
        first: PathBuf,
        first_shards: u32,
        first_scenes: usize,
        other: PathBuf,
        other_shards: u32,
        other_scenes: usize,
    },
    /// One shard given twice.
    #[error("{} and {} are both shard {shard}: expected each shard once", .first.display(), .second.display())]
    SameShard {
        shard: Partition,
        first: PathBuf,
        second: PathBuf,
    },
    /// Shards missing.
    #[error("shard(s) {} of {count} missing: expected every shard's results", .missing.join(", "))]
    MissingShards { missing: Vec<String>, count: u32 },
    /// The shards' scenes do not add up to the suite.
    #[error("the shards rendered {scenes} scenes, the suite has {suite}: expected every scene exactly once (did the suite change between shards?)")]
    Coverage { scenes: usize, suite: usize },
    /// A run whose rows do not cover the scenes it says it rendered.
    #[error("{}: the run says it rendered {scenes} scene(s) but its rows cover {found}: expected a row for every scene (was the file edited or cut short?)", .path.display())]
    Rows {
        path: PathBuf,
        scenes: usize,
        found: usize,
    },
    /// A field of a results file that no run of ffvk writes.
    #[error("{}: {field} is {value}: expected {expected}", .path.display())]
    Field {
        path: PathBuf,
        field: String,
        value: String,
        expected: String,
    },
    /// One scene index in two shards.
    #[error("{} and {} both have rows at index {index} (scenes {first_scene:?} and {second_scene:?}): expected each scene of the suite in one shard", .first.display(), .second.display())]
    SameIndex {
        index: usize,
        first: PathBuf,
        first_scene: String,
        second: PathBuf,
        second_scene: String,
    },
    /// One image in two shards.
    #[error("{} and {} both have the image {name}: expected each image in one shard", .first.display(), .second.display())]
    SameImage {
        name: String,
        first: PathBuf,
        second: PathBuf,
    },
}

/// The current time, UTC, as `YYYY-MM-DDThh:mm:ss` (the form JUnit's `timestamp` takes).
pub fn utc_timestamp(time: std::time::SystemTime) -> String {
    let secs = time
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs()) as i64;
    let (days, rest) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    let (y, m, d) = civil_from_days(days);
    format!(
        "{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}",
        rest / 3600,
        rest / 60 % 60,
        rest % 60
    )
}

/// The proleptic Gregorian date of a count of days since 1970-01-01 (Howard Hinnant's
/// `civil_from_days`: eras of 400 years, years starting in March).
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

/// This machine's host name (Linux's `/proc/sys/kernel/hostname`, else `$HOSTNAME`, else
/// `localhost`).
pub fn hostname() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .ok()
        .or_else(|| std::env::var("HOSTNAME").ok())
        .map(|h| h.trim().to_owned())
        .filter(|h| !h.is_empty())
        .unwrap_or_else(|| "localhost".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, UNIX_EPOCH};

    #[test]
    fn timestamps_are_utc_calendar_dates() {
        let at = |s| utc_timestamp(UNIX_EPOCH + Duration::from_secs(s));
        assert_eq!(at(0), "1970-01-01T00:00:00");
        // 2000-02-29 (a leap day of a century divisible by 400), 12:34:56.
        assert_eq!(at(951_827_696), "2000-02-29T12:34:56");
        // 2026-11-23T00:00:00 and the second before it.
        assert_eq!(at(1_795_392_000), "2026-11-23T00:00:00");
        assert_eq!(at(1_795_391_999), "2026-11-22T23:59:59");
    }

    #[test]
    fn a_cut_short_results_file_says_where_and_a_pipe_is_refused_unread() {
        let dir = std::env::temp_dir().join(format!("ffvk-results-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let cut = dir.join("cut.json");
        std::fs::write(&cut, "{\"format\": \"ffvk-results/1\", \"runs\": [").unwrap();
        let e = Results::read_json(&cut).unwrap_err().to_string();
        assert!(
            e.contains("cut.json") && e.contains("EOF") && e.contains("line 1"),
            "{e}"
        );
        let fifo = dir.join("fifo.json");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status().unwrap();
        assert!(made.success());
        let e = Results::read_json(&fifo).unwrap_err().to_string();
        assert!(e.contains("not a regular file"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_run_whose_rows_miss_scenes_is_refused() {
        let text = format!(
            r#"{{"format": "{FORMAT}", "runs": [{{"info": {{"ffvk": "x", "device": null, "jobs": 1,
              "lp_num_threads": null, "partition": null, "suite_scenes": 7, "scenes": 7, "modes": [],
              "references": null, "bless": false, "tolerance": {{"threshold": 2, "max_share": 0.001,
              "max_flip": 0.005, "flip_all_pixels": false}}, "timestamp": "t", "hostname": "h",
              "seconds": 1.0}}, "rows": []}}]}}"#
        );
        let results: Results = serde_json::from_str(&text).unwrap();
        let e = Results::merge(vec![("norows.json".into(), results)])
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("norows.json") && e.contains("7 scene(s)") && e.contains("cover 0"),
            "{e}"
        );
    }

    #[test]
    fn errors_win_over_differences_in_the_exit_code() {
        let c = |failed, missing, errors| Counts {
            images: 10,
            failed,
            missing,
            errors,
            ..Counts::default()
        };
        assert_eq!(c(0, 0, 0).exit_code(), 0);
        assert_eq!(c(1, 0, 0).exit_code(), 1);
        assert_eq!(c(0, 1, 0).exit_code(), 1);
        assert_eq!(c(3, 2, 1).exit_code(), 2);
    }
}
