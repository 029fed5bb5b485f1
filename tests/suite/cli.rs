//! The command line against hostile use (issue 46): results files that lie about their shards
//! and rows, a full or closed stdout, output names of the wrong kind, negative option values
//! and a benchmark's output folder that is a file. Every case runs the `ffvk` binary and must
//! end in an error that names what is wrong, never in a panic, a silent write or a long run.

use std::path::{Path, PathBuf};
use std::process::{Child, ExitStatus, Output, Stdio};
use std::time::{Duration, Instant};

use ffvk_cli::regress::Partition;
use serde_json::{json, Value};

use crate::support::{ffvk_command, output_dir};

fn scratch(name: &str) -> PathBuf {
    let dir = output_dir().join("cli").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Waits for `child` at most `seconds`, then kills it and fails the test naming `what`.
fn finish_within(mut child: Child, seconds: u64, what: &str) -> (ExitStatus, Output) {
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > Duration::from_secs(seconds) {
            child.kill().unwrap();
            let _ = child.wait();
            panic!("{what} took more than {seconds} s");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    (status, child.wait_with_output().unwrap())
}

/// `ffvk ARGS`, killed (and the test failed) after `seconds`.
fn run(args: &[&dyn AsRef<std::ffi::OsStr>], seconds: u64) -> Output {
    let what = args
        .iter()
        .map(|a| a.as_ref().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join(" ");
    let child = ffvk_command(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    finish_within(child, seconds, &format!("ffvk {what}")).1
}

fn text(out: &Output) -> String {
    format!(
        "exit {:?}\nstdout:\n{}\nstderr:\n{}",
        out.status.code(),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// Asserts an error exit (2) whose message holds every one of `words`, and no panic.
fn assert_refused(out: &Output, words: &[&str], what: &str) {
    let all = text(out);
    assert!(!all.contains("panicked"), "{what}: a panic\n{all}");
    assert_eq!(out.status.code(), Some(2), "{what}: an error exit\n{all}");
    for w in words {
        assert!(all.contains(w), "{what}: {w:?} not in\n{all}");
    }
}

// ---------------------------------------------------------------------------------------------
// results merge

/// A row of scene `name` at `index` in the suite.
fn row(name: &str, index: usize) -> Value {
    json!({
        "name": name, "scene": name, "file": format!("{name}.toml"), "index": index,
        "mode": "vertex", "status": "rendered", "message": null, "comparison": null,
        "output": null, "diff": null, "reference": null, "seconds": 0.01
    })
}

/// A results file at `dir/name` of one run: shard `partition` of a suite of `suite` scenes,
/// saying it rendered `scenes` of them, with `rows`.
fn results_file(
    dir: &Path,
    name: &str,
    partition: Option<Value>,
    suite: usize,
    scenes: usize,
    rows: Vec<Value>,
) -> PathBuf {
    let results = json!({
        "format": "ffvk-results/1",
        "runs": [{
            "info": {
                "ffvk": "0.1.0", "device": null, "jobs": 1, "lp_num_threads": null,
                "partition": partition, "suite_scenes": suite, "scenes": scenes, "modes": [],
                "references": null, "bless": false,
                "tolerance": {"threshold": 2, "max_share": 0.001, "max_flip": 0.005,
                              "flip_all_pixels": false},
                "timestamp": "2026-01-01T00:00:00", "hostname": "h", "seconds": 1.0
            },
            "rows": rows
        }]
    });
    let path = dir.join(name);
    std::fs::write(&path, serde_json::to_string(&results).unwrap()).unwrap();
    path
}

/// The six scenes `s0` … `s5` of a suite, at their indices.
fn six_rows() -> Vec<Value> {
    (0..6).map(|i| row(&format!("s{i}"), i)).collect()
}

fn merge(files: &[&PathBuf]) -> Output {
    let mut args: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"results", &"merge"];
    args.extend(files.iter().map(|f| *f as &dyn AsRef<std::ffi::OsStr>));
    run(&args, 60)
}

#[test]
fn results_merge_refuses_a_shard_outside_its_partition_count_naming_the_file_and_field() {
    let dir = scratch("merge-partition");
    // The fabricated file itself merges: only its partition is wrong below.
    let whole = results_file(&dir, "whole.json", None, 6, 6, six_rows());
    let out = merge(&[&whole]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    for (name, index, count, words) in [
        (
            "three_of_two.json",
            3,
            2,
            &["three_of_two.json", "partition.index", "3"][..],
        ),
        (
            "zero_of_two.json",
            0,
            2,
            &["zero_of_two.json", "partition.index", "0"][..],
        ),
        (
            "one_of_none.json",
            1,
            0,
            &["one_of_none.json", "partition.count", "0"][..],
        ),
    ] {
        let partition = json!({"index": index, "count": count});
        let shard = results_file(&dir, name, Some(partition), 6, 6, six_rows());
        assert_refused(&merge(&[&shard]), words, name);
    }
}

#[test]
fn results_merge_refuses_rows_that_are_not_the_suites_scenes() {
    let dir = scratch("merge-rows");
    // 10,000 made-up rows beside the six real ones of a 6-scene suite, each at a scene's index.
    let mut padded = six_rows();
    padded.extend((0..10_000).map(|k| row(&format!("fake_{k}"), k % 6)));
    let padded = results_file(&dir, "padded.json", None, 6, 6, padded);
    assert_refused(&merge(&[&padded]), &["padded.json", "rows", "6"], "padded rows");

    // A row whose index is past the suite's last scene.
    let mut beyond = six_rows();
    beyond[5] = row("s5", 9);
    let beyond = results_file(&dir, "beyond.json", None, 6, 6, beyond);
    assert_refused(
        &merge(&[&beyond]),
        &["beyond.json", "rows[5].index", "9"],
        "index past the suite",
    );

    // Two shards that swapped their scenes: each row belongs to the other shard.
    let names: Vec<String> = (0..6).map(|i| format!("s{i}")).collect();
    let shard_of = |name: &str| {
        (1..=2)
            .find(|&index| Partition { index, count: 2 }.contains(name))
            .unwrap()
    };
    let rows_of = |shard: u32| -> Vec<Value> {
        names
            .iter()
            .enumerate()
            .filter(|(_, n)| shard_of(n) == shard)
            .map(|(i, n)| row(n, i))
            .collect()
    };
    let (first, second) = (rows_of(1), rows_of(2));
    assert!(
        !first.is_empty() && !second.is_empty(),
        "both shards hold a scene"
    );
    let shard = |k: u32| Some(json!({"index": k, "count": 2}));
    let swapped_1 = results_file(&dir, "swapped_1.json", shard(1), 6, second.len(), second.clone());
    let swapped_2 = results_file(&dir, "swapped_2.json", shard(2), 6, first.len(), first.clone());
    assert_refused(
        &merge(&[&swapped_1, &swapped_2]),
        &["swapped_", "shard"],
        "rows of the other shard",
    );
    // The same shards unswapped merge.
    let shard_1 = results_file(&dir, "shard_1.json", shard(1), 6, first.len(), first.clone());
    let shard_2 = results_file(&dir, "shard_2.json", shard(2), 6, second.len(), second.clone());
    let out = merge(&[&shard_1, &shard_2]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));

    // One index in both shards (the other's scene at it left out).
    let mut reused = second.clone();
    reused[0]["index"] = first[0]["index"].clone();
    let reused = results_file(&dir, "reused.json", shard(2), 6, second.len(), reused);
    assert_refused(
        &merge(&[&shard_1, &reused]),
        &["reused.json", "index"],
        "an index in two shards",
    );
}
