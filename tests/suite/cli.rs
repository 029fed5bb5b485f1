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

/// What no run writes in a row is refused naming the row's field: a mode that is not a
/// lighting mode, a name leaving the suite's folder, a comparison of an image no run draws or
/// whose worst pixel lies outside it.
#[test]
fn results_rows_no_run_writes_are_refused_naming_the_field() {
    let dir = scratch("merge-row-content");
    let comparison = |width: u32, x: u32| {
        json!({"width": width, "height": 32, "max_diff": [9, 0, 0, 0], "over": 1, "share_over": 0.001,
               "flip_mean": null, "flip_all_pixels": false, "threshold": 2,
               "worst": {"x": x, "y": 0, "expected": [0, 0, 0, 255], "actual": [9, 0, 0, 255]},
               "first_over": null})
    };
    let cases: [(&str, Value, &[&str]); 4] = [
        (
            "mode",
            json!({"mode": "bogus"}),
            &["rows[2].mode", "bogus", "\"vertex\""],
        ),
        (
            "name",
            json!({"name": "../../x"}),
            &["rows[2].name", "../../x", "below the suite's folder"],
        ),
        (
            "size",
            json!({"comparison": comparison(u32::MAX, 0)}),
            &["rows[2].comparison", "4294967295x32"],
        ),
        (
            "pixel",
            json!({"comparison": comparison(32, 99_999)}),
            &["rows[2].comparison.worst", "(99999, 0)", "32x32"],
        ),
    ];
    for (what, change, words) in cases {
        let mut rows = six_rows();
        for (key, value) in change.as_object().unwrap() {
            rows[2][key] = value.clone();
        }
        let file = results_file(&dir, &format!("{what}.json"), None, 6, 6, rows);
        let out = merge(&[&file]);
        let name = format!("{what}.json");
        let mut all = words.to_vec();
        all.push(&name);
        assert_refused(&out, &all, what);
    }
    // The same comparison within its image merges: the checks are about what no run writes.
    let mut rows = six_rows();
    rows[2]["comparison"] = comparison(32, 31);
    let file = results_file(&dir, "fine.json", None, 6, 6, rows);
    let out = merge(&[&file]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
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

// ---------------------------------------------------------------------------------------------
// stdout

#[test]
fn a_full_stdout_is_an_error_naming_stdout_not_a_panic() {
    let dir = scratch("full-stdout");
    let image = dir.join("a.png");
    image::RgbaImage::new(4, 4).save(&image).unwrap();
    let results = results_file(&dir, "whole.json", None, 6, 6, six_rows());
    let scenes = dir.join("scenes");
    let scene = ffvk_cli::bench::generate_scenes(&scenes, 2, 16)
        .unwrap()
        .remove(0);
    let teapot = dir.join("t.gltf");
    let gltf = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/teapot.gltf");
    let one = dir.join("one.png");
    let many = dir.join("many");
    let cases: [Vec<&dyn AsRef<std::ffi::OsStr>>; 10] = [
        vec![&"info"],
        // What clap prints itself.
        vec![&"--help"],
        vec![&"--version"],
        vec![&"render", &"--help"],
        vec![&"teapot", &"--level", &"1", &"-o", &teapot],
        vec![&"compare", &image, &image],
        vec![&"results", &"merge", &results],
        vec![&"scene", &gltf],
        vec![&"render", &scene, &"-o", &one],
        vec![&"render", &scenes, &"--out", &many, &"--jobs", &"1"],
    ];
    for args in cases {
        let what = args
            .iter()
            .map(|a| a.as_ref().to_string_lossy().into_owned())
            .collect::<Vec<_>>()
            .join(" ");
        let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let child = ffvk_command(&args)
            .stdout(Stdio::from(full))
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let (_, out) = finish_within(child, 120, &what);
        assert_refused(&out, &["stdout", "No space left on device"], &what);
    }
}

#[test]
fn a_closed_stdout_pipe_ends_ffvk_with_a_failure_status_and_no_panic() {
    for args in [vec!["info"], vec!["scene", "assets/teapot.gltf"]] {
        // The read end is closed before ffvk starts, so its first write fails whatever the
        // scheduling (closing it after the spawn raced ffvk's output into the pipe's buffer).
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let child = ffvk_command(&args.iter().map(|a| a as _).collect::<Vec<_>>())
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .stdout(Stdio::from(writer))
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let (status, out) = finish_within(child, 60, &args.join(" "));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(!status.success(), "{args:?}: a failure status, not success");
    }
}

// ---------------------------------------------------------------------------------------------
// Output names

#[test]
fn an_output_named_for_another_kind_of_file_is_refused_and_not_written() {
    let dir = scratch("kinds");
    let scenes = dir.join("scenes");
    let scene = ffvk_cli::bench::generate_scenes(&scenes, 1, 16)
        .unwrap()
        .remove(0);
    let gltf = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/teapot.gltf");
    let image = dir.join("a.png");
    image::RgbaImage::new(4, 4).save(&image).unwrap();
    let results = results_file(&dir, "whole.json", None, 6, 6, six_rows());
    let out_dir = dir.join("out");
    let t_png = dir.join("t.png");
    let t_glb = dir.join("t.glb");
    let s_png = dir.join("s.png");
    let r_jpg = dir.join("r.jpg");
    let j_xml = dir.join("j.xml");
    let x_json = dir.join("x.json");
    let m_txt = dir.join("m.txt");
    let d_txt = dir.join("d.txt");
    let cases: [(Vec<&dyn AsRef<std::ffi::OsStr>>, &Path, &str); 9] = [
        (vec![&"teapot", &"-o", &t_png], &t_png, ".gltf"),
        (vec![&"teapot", &"-o", &t_glb], &t_glb, ".gltf"),
        (vec![&"scene", &gltf, &"-o", &s_png], &s_png, ".toml"),
        (vec![&"render", &scene, &"-o", &r_jpg], &r_jpg, ".png"),
        (
            vec![&"render", &scenes, &"--out", &out_dir, &"--json", &j_xml],
            &j_xml,
            ".json",
        ),
        (
            vec![&"render", &scenes, &"--out", &out_dir, &"--junit", &x_json],
            &x_json,
            ".xml",
        ),
        (
            vec![&"results", &"merge", &results, &"--json", &m_txt],
            &m_txt,
            ".json",
        ),
        (
            vec![&"results", &"merge", &results, &"--junit", &m_txt],
            &m_txt,
            ".xml",
        ),
        (
            vec![&"compare", &image, &image, &"--diff", &d_txt],
            &d_txt,
            ".png",
        ),
    ];
    for (args, written, expected) in cases {
        let what = args
            .iter()
            .map(|a| a.as_ref().to_string_lossy().into_owned())
            .collect::<Vec<_>>()
            .join(" ");
        let out = run(&args, 120);
        let name = written.file_name().unwrap().to_string_lossy();
        assert_refused(&out, &[&name, expected], &what);
        assert!(!written.exists(), "{what}: {} was written", written.display());
    }
}

// ---------------------------------------------------------------------------------------------
// Numbers

#[test]
fn a_negative_value_reaches_its_options_own_check() {
    let gltf = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/teapot.gltf");
    let dir = scratch("negative");
    let image = dir.join("a.png");
    image::RgbaImage::new(4, 4).save(&image).unwrap();
    let out = dir.join("out");
    // (command line, the option, the value), each refused before anything is drawn.
    let render = |option: &'static str, value: &'static str| {
        let args: Vec<&dyn AsRef<std::ffi::OsStr>> =
            vec![&"render", &gltf, &"--out", &out, &"--lighting", &"vertex,flat"];
        (args, option, value)
    };
    let mut cases = vec![
        render("--zoom", "-1"),
        // 1e-300 is 0 as a float32: refused as given, not as "--zoom 0".
        render("--zoom", "1e-300"),
        render("--azimuth", "-1e30"),
        render("--camera", "-1"),
        render("--exposure", "-1"),
        render("--elevation", "-91"),
        render("--jobs", "-1"),
        render("--timeout", "-1"),
        render("--size", "-1x5"),
        render("--threshold", "-1"),
        render("--max-share", "-1"),
        render("--max-flip", "-1"),
        render("--max-mesh-mib", "-1"),
        render("--background", "-1,0,0"),
        render("--partition", "-1/2"),
    ];
    let explain: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"explain", &gltf];
    cases.push((explain.clone(), "--pixel", "-1,0"));
    cases.push((vec![&"teapot", &"-o", &"unused.gltf"], "--level", "-1"));
    cases.push((vec![&"compare", &image, &image], "--max-share", "-0.5"));
    for option in [
        "--draws",
        "--warmup",
        "--frames",
        "--lp-threads",
        "--scenes",
        "--jobs",
    ] {
        cases.push((vec![&"bench", &"--out", &out], option, "-1"));
    }
    for (mut args, option, value) in cases {
        args.push(&option);
        args.push(&value);
        let what = format!("{} {option} {value}", args[0].as_ref().to_string_lossy());
        let result = run(&args, 60);
        assert!(
            !text(&result).contains("unexpected argument"),
            "{what}: {}",
            text(&result)
        );
        assert_refused(&result, &[option, value], &what);
    }
    assert!(!out.exists(), "nothing was written");
}

// ---------------------------------------------------------------------------------------------
// bench

#[test]
fn bench_refuses_an_output_folder_that_is_a_file_before_it_measures() {
    let dir = scratch("bench-out");
    let file = dir.join("results.txt");
    std::fs::write(&file, "kept").unwrap();
    for sweep in ["quick", "jobs"] {
        // The quick sweep takes over a minute here: a refusal comes in seconds.
        let out = run(
            &[&"bench", &"--sweep", &sweep, &"--no-progress", &"-o", &file],
            20,
        );
        assert_refused(&out, &["results.txt", "folder"], sweep);
        assert_eq!(std::fs::read_to_string(&file).unwrap(), "kept");
    }
}

// ---------------------------------------------------------------------------------------------
// Modes and warnings

/// A mode named twice would draw one image twice over the same file and give the results two
/// rows for it (which `results merge` then refuses): refused before anything is drawn.
#[test]
fn a_lighting_mode_named_twice_is_refused() {
    let gltf = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/teapot.gltf");
    let dir = scratch("lighting-twice");
    let out = dir.join("out");
    let result = run(
        &[
            &"render",
            &gltf,
            &"--out",
            &out,
            &"--lighting",
            &"vertex,flat,vertex",
        ],
        60,
    );
    assert_refused(&result, &["--lighting", "vertex twice"], "vertex,flat,vertex");
    assert!(!out.exists(), "nothing was written");
}

/// In a folder run the warnings of many scenes interleave: each names its scene file.
#[test]
fn warnings_name_their_scene_file() {
    let dir = scratch("warnings");
    let scene = dir.join("zero.toml");
    std::fs::write(
        &scene,
        "[image]\nsize = [8, 8]\n\n[[lights]]\nposition = [0, 0, 0, 0]\n\n[[meshes]]\nbuiltin = \"sphere\"\n",
    )
    .unwrap();
    let image = dir.join("zero_out.png");
    let folder = dir.join("out");
    let one: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"-o", &image];
    let two: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"--out", &folder, &"--lighting", &"vertex,flat"];
    for args in [one, two] {
        let mut all: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"render", &scene];
        all.extend(args);
        let out = run(&all, 60);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{}", text(&out));
        assert!(
            stderr.contains(&format!("warning: {}: lights[0].position", scene.display())),
            "{stderr}"
        );
    }
}
