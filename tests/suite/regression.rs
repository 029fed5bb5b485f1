//! Regression runs at CI scale: worker processes (`--jobs`), shards (`--partition`), results
//! for CI systems (`--json`, `--junit`, `ffvk results merge`), and runs that survive a bad
//! scene, a crashed worker and a hung one. Every run goes through the `ffvk` binary with the
//! validation layer on in each worker; the JUnit files are validated with `xmllint` against
//! the two schemas CI tools use, Jenkins' junit-4.xsd and Ant's JUnit.xsd (as shipped in the
//! `junit-report` crate's package, a dev-dependency for that reason).

use std::path::{Path, PathBuf};
use std::process::Output;

use ffvk_cli::bench::generate_scenes;
use ffvk_cli::regress::{self, Partition};
use serde_json::Value;

use crate::support::{ffvk_command, output_dir};

fn scratch(name: &str) -> PathBuf {
    let dir = output_dir().join("regression").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `count` generated scenes of 32² in `dir/scenes`, the last one moved into `sub/`.
fn suite(dir: &Path, count: usize) -> PathBuf {
    let scenes = dir.join("scenes");
    let files = generate_scenes(&scenes, count, 32).unwrap();
    let last = files.last().unwrap();
    std::fs::create_dir_all(scenes.join("sub")).unwrap();
    std::fs::rename(last, scenes.join("sub").join(last.file_name().unwrap())).unwrap();
    scenes
}

/// `ffvk ARGS` with the validation layer on in every worker and `env` set.
fn ffvk(args: &[&dyn AsRef<std::ffi::OsStr>], env: &[(&str, &str)]) -> Output {
    let mut c = ffvk_command(args);
    c.env("FFVK_VALIDATION", "1").env_remove(regress::pool::FAULT_VAR);
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().expect("the ffvk binary runs")
}

fn text(out: &Output) -> String {
    format!(
        "exit {:?}\nstdout:\n{}\nstderr:\n{}",
        out.status.code(),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

fn assert_exit(out: &Output, code: i32) {
    assert_eq!(out.status.code(), Some(code), "{}", text(out));
}

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The rows of a results file, in suite order (a merged file keeps each shard's rows with
/// its run; `index` is the scene's place in the suite).
fn rows(results: &Value) -> Vec<Value> {
    let mut rows: Vec<Value> = results["runs"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|r| r["rows"].as_array().unwrap().clone())
        .collect();
    rows.sort_by_key(|r| r["index"].as_u64().unwrap());
    rows
}

/// (name, status) of every row.
fn outcomes(results: &Value) -> Vec<(String, String)> {
    rows(results)
        .iter()
        .map(|r| {
            (
                r["name"].as_str().unwrap().to_owned(),
                r["status"].as_str().unwrap().to_owned(),
            )
        })
        .collect()
}

/// Every file below `dir`, relative to it, sorted.
fn files_below(dir: &Path) -> Vec<PathBuf> {
    fn walk(root: &Path, dir: &Path, found: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(root, &p, found);
            } else {
                found.push(p.strip_prefix(root).unwrap().to_path_buf());
            }
        }
    }
    let mut found = Vec::new();
    walk(dir, dir, &mut found);
    found.sort();
    found
}

/// The two JUnit schemas, from the junit-report crate's package: the version Cargo.lock
/// pins, unpacked in Cargo's registry when the dev-dependencies were built.
fn junit_schemas() -> [PathBuf; 2] {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lock = std::fs::read_to_string(root.join("Cargo.lock")).unwrap();
    let version = lock
        .split("[[package]]")
        .find(|p| p.contains("name = \"junit-report\""))
        .and_then(|p| p.lines().find_map(|l| l.strip_prefix("version = ")))
        .expect("junit-report is in Cargo.lock")
        .trim_matches('"')
        .to_owned();
    let cargo_home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(std::env::var_os("HOME").unwrap()).join(".cargo"));
    let registries = cargo_home.join("registry/src");
    let package = std::fs::read_dir(&registries)
        .unwrap_or_else(|e| panic!("{}: {e}", registries.display()))
        .map(|e| e.unwrap().path().join(format!("junit-report-{version}")))
        .find(|p| p.is_dir())
        .unwrap_or_else(|| {
            panic!(
                "junit-report-{version} is not unpacked below {}",
                registries.display()
            )
        });
    // JUnit.xsd there is Jenkins' junit-4.xsd; JUnit-alternative.xsd is Windy Road's schema
    // of Ant's JUnit task output.
    let schemas = [
        package.join("tests/JUnit.xsd"),
        package.join("tests/JUnit-alternative.xsd"),
    ];
    for s in &schemas {
        assert!(
            s.is_file(),
            "{} is missing from the junit-report package",
            s.display()
        );
    }
    schemas
}

/// Validates `xml` against both schemas with xmllint; the error names the schema and
/// xmllint's complaint.
fn validate_junit(xml: &Path) -> Result<(), String> {
    for schema in junit_schemas() {
        let out = std::process::Command::new("xmllint")
            .args(["--noout", "--schema"])
            .arg(&schema)
            .arg(xml)
            .output()
            .expect("xmllint runs (libxml2-utils; make test installs it)");
        if !out.status.success() {
            return Err(format!(
                "{} is not valid against {}:\n{}",
                xml.display(),
                schema.display(),
                String::from_utf8_lossy(&out.stderr)
            ));
        }
    }
    Ok(())
}

/// The number an XPath expression gives on `xml` (xmllint --xpath).
fn xpath_number(xml: &Path, expression: &str) -> usize {
    let out = std::process::Command::new("xmllint")
        .args(["--xpath", expression])
        .arg(xml)
        .output()
        .expect("xmllint runs");
    let s = String::from_utf8_lossy(&out.stdout);
    s.trim()
        .parse()
        .unwrap_or_else(|_| panic!("{expression} on {}: {s}", xml.display()))
}

fn xpath_text(xml: &Path, expression: &str) -> String {
    let out = std::process::Command::new("xmllint")
        .args(["--xpath", expression])
        .arg(xml)
        .output()
        .expect("xmllint runs");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn the_schema_check_refuses_a_file_that_breaks_either_schema() {
    let dir = scratch("schema_check");
    let valid = dir.join("valid.xml");
    std::fs::write(
        &valid,
        "<testsuites><testsuite name=\"s\" package=\"p\" id=\"0\" timestamp=\"2026-11-23T00:00:00\" \
         hostname=\"h\" tests=\"1\" failures=\"0\" errors=\"0\" time=\"0.1\"><properties>\
         <property name=\"a\" value=\"b\"/></properties><testcase name=\"t\" classname=\"c\" \
         time=\"0.1\"/><system-out/><system-err/></testsuite></testsuites>",
    )
    .unwrap();
    validate_junit(&valid).unwrap();
    // A test case without a name breaks both; a suite without a host name breaks Ant's.
    for (file, broken) in [
        ("no_name.xml", ("<testcase name=\"t\"", "<testcase")),
        ("no_host.xml", ("hostname=\"h\" ", "")),
    ] {
        let path = dir.join(file);
        let text = std::fs::read_to_string(&valid)
            .unwrap()
            .replace(broken.0, broken.1);
        std::fs::write(&path, text).unwrap();
        assert!(validate_junit(&path).is_err(), "{file} passed the schema check");
    }
}

#[test]
fn images_and_the_summary_do_not_depend_on_the_number_of_workers() {
    let dir = scratch("jobs");
    let scenes = suite(&dir, 12);
    let mut runs = Vec::new();
    for jobs in ["1", "3"] {
        let out_dir = dir.join(format!("out_{jobs}"));
        let results = dir.join(format!("results_{jobs}.json"));
        let out = ffvk(
            &[
                &"render",
                &scenes,
                &"--lighting",
                &"vertex,fragment",
                &"--out",
                &out_dir,
                &"--jobs",
                &jobs,
                &"--json",
                &results,
            ],
            &[],
        );
        assert_exit(&out, 0);
        let stdout = String::from_utf8_lossy(&out.stdout).replace(&out_dir.display().to_string(), "OUT");
        runs.push((out_dir, json(&results), stdout));
    }
    let (a, b) = (&runs[0], &runs[1]);
    assert_eq!(a.2, b.2, "the printed lines differ between 1 and 3 workers");
    assert_eq!(outcomes(&a.1), outcomes(&b.1));
    assert_eq!(rows(&a.1).len(), 24);
    let files = files_below(&a.0);
    assert_eq!(files, files_below(&b.0));
    assert!(
        files.contains(&PathBuf::from("sub/scene_011_vertex.png")),
        "{files:?}"
    );
    for f in &files {
        assert_eq!(
            std::fs::read(a.0.join(f)).unwrap(),
            std::fs::read(b.0.join(f)).unwrap(),
            "{} differs between 1 and 3 workers",
            f.display()
        );
    }
    for (run, jobs) in [(&a.1, 1), (&b.1, 3)] {
        let info = &run["runs"][0]["info"];
        assert_eq!(info["jobs"], jobs);
        assert!(
            info["lp_num_threads"]
                .as_str()
                .is_some_and(|t| t.parse::<u32>().is_ok()),
            "{info}"
        );
        assert_eq!(info["device"]["driver"], "llvmpipe");
    }
}

#[test]
fn a_worker_that_crashes_costs_only_the_scene_it_was_rendering() {
    let dir = scratch("crash");
    let scenes = suite(&dir, 8);
    let out_dir = dir.join("out");
    let results = dir.join("results.json");
    let out = ffvk(
        &[
            &"render", &scenes, &"--out", &out_dir, &"--jobs", &"2", &"--json", &results,
        ],
        &[(regress::pool::FAULT_VAR, "abort:scene_003")],
    );
    assert_exit(&out, 2);
    let results = json(&results);
    for row in rows(&results) {
        let name = row["name"].as_str().unwrap();
        if name == "scene_003" {
            assert_eq!(row["status"], "error");
            let message = row["message"].as_str().unwrap();
            assert!(message.contains("signal 6 (SIGABRT)"), "{message}");
            assert!(!out_dir.join("scene_003.png").exists());
        } else {
            assert_eq!(row["status"], "rendered", "{row}");
            assert!(out_dir.join(format!("{name}.png")).is_file(), "{name}");
        }
    }
    assert_eq!(rows(&results).len(), 8);
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("scene_003: its worker process was killed by signal 6")
    );
}

#[test]
fn a_scene_over_the_timeout_has_its_worker_killed_and_is_an_error_row() {
    let dir = scratch("timeout");
    let scenes = suite(&dir, 5);
    let results = dir.join("results.json");
    let started = std::time::Instant::now();
    let out = ffvk(
        &[
            &"render",
            &scenes,
            &"--out",
            &dir.join("out"),
            &"--jobs",
            &"2",
            &"--timeout",
            &"3",
            &"--json",
            &results,
        ],
        &[(regress::pool::FAULT_VAR, "hang:scene_001")],
    );
    assert_exit(&out, 2);
    assert!(
        started.elapsed().as_secs() < 120,
        "the run waited {:?}",
        started.elapsed()
    );
    let outcomes = outcomes(&json(&results));
    let expected: Vec<(String, String)> = [
        "scene_000",
        "scene_001",
        "scene_002",
        "scene_003",
        "sub/scene_004",
    ]
    .iter()
    .map(|n| {
        (
            n.to_string(),
            if *n == "scene_001" { "error" } else { "rendered" }.to_string(),
        )
    })
    .collect();
    assert_eq!(outcomes, expected);
    assert!(
        text(&out).contains("no result within the timeout of 3 s"),
        "{}",
        text(&out)
    );
}

/// A glTF file that needs Draco, which ffvk does not decode (as in the issue's suite).
fn draco_scene(scenes: &Path) {
    std::fs::write(
        scenes.join("draco.gltf"),
        r#"{"asset":{"version":"2.0"},"extensionsUsed":["KHR_draco_mesh_compression"],
            "extensionsRequired":["KHR_draco_mesh_compression"],"scenes":[{"nodes":[]}],"scene":0}"#,
    )
    .unwrap();
    std::fs::write(
        scenes.join("needs_draco.toml"),
        "[[lights]]\n[[meshes]]\ngltf = \"draco.gltf\"\n",
    )
    .unwrap();
}

#[test]
fn bad_scenes_are_error_rows_the_run_goes_on_and_errors_win_over_differences() {
    let dir = scratch("bad_scenes");
    let scenes = suite(&dir, 4);
    let refs = dir.join("refs");
    let out_dir = dir.join("out");
    let check = |extra: &[&dyn AsRef<std::ffi::OsStr>], name: &str| {
        let results = dir.join(format!("{name}.json"));
        let junit = dir.join(format!("{name}.xml"));
        let mut args: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![
            &"render", &scenes, &"--out", &out_dir, &"--check", &refs, &"--jobs", &"2",
        ];
        args.extend_from_slice(extra);
        let (r, j) = (results.clone(), junit.clone());
        let mut all = args.clone();
        all.extend_from_slice(&[&"--json" as &dyn AsRef<std::ffi::OsStr>, &r, &"--junit", &j]);
        (ffvk(&all, &[]), results, junit)
    };
    // Blessed: the references are written, exit 0.
    let (out, _, _) = check(&[&"--bless"], "bless");
    assert_exit(&out, 0);
    let (out, _, junit) = check(&[], "pass");
    assert_exit(&out, 0);
    validate_junit(&junit).unwrap();

    // One reference changed: exit 1, a failure with its figures and paths.
    let changed = refs.join("scene_002.png");
    let mut image = image::open(&changed).unwrap().to_rgba8();
    for (x, y) in (5..9).flat_map(|x| (7..11).map(move |y| (x, y))) {
        image.put_pixel(x, y, image::Rgba([255, 0, 255, 255]));
    }
    image.save(&changed).unwrap();
    let (out, _, junit) = check(&[], "differs");
    assert_exit(&out, 1);
    validate_junit(&junit).unwrap();
    assert_eq!(xpath_number(&junit, "count(//testcase/failure)"), 1);
    let failure = xpath_text(&junit, "string(//testcase[@classname='scene_002']/failure)");
    assert!(
        failure.contains("worst pixel (") && failure.contains(&changed.display().to_string()),
        "{failure}"
    );
    assert!(
        failure.contains("diff: ") && failure.contains("actual: "),
        "{failure}"
    );

    // Plus a scene that does not parse and one that needs Draco: both error rows, every
    // other scene still checked, and exit 2 (errors win over the difference).
    std::fs::write(scenes.join("broken.toml"), "[image\nsize = 3").unwrap();
    draco_scene(&scenes);
    let (out, results, junit) = check(&[], "errors");
    assert_exit(&out, 2);
    let outcomes = outcomes(&json(&results));
    let status = |name: &str| outcomes.iter().find(|(n, _)| n == name).map(|(_, s)| s.clone());
    assert_eq!(outcomes.len(), 6, "{outcomes:?}");
    assert_eq!(status("broken").as_deref(), Some("error"));
    assert_eq!(status("needs_draco").as_deref(), Some("error"));
    assert_eq!(status("scene_002").as_deref(), Some("fail"));
    for pass in ["scene_000", "scene_001", "sub/scene_003"] {
        assert_eq!(status(pass).as_deref(), Some("pass"), "{pass}: {outcomes:?}");
    }
    validate_junit(&junit).unwrap();
    assert_eq!(xpath_number(&junit, "count(//testcase)"), 6);
    assert_eq!(xpath_number(&junit, "count(//testcase/error)"), 2);
    assert_eq!(xpath_number(&junit, "number(//testsuite/@errors)"), 2);
    assert_eq!(xpath_number(&junit, "number(//testsuite/@failures)"), 1);
    let draco = xpath_text(
        &junit,
        "string(//testcase[@classname='needs_draco']/error/@message)",
    );
    assert!(draco.contains("KHR_draco_mesh_compression"), "{draco}");
    let broken = xpath_text(&junit, "string(//testcase[@classname='broken']/error/@message)");
    assert!(broken.contains("broken.toml"), "{broken}");
    let summary = String::from_utf8_lossy(&out.stdout);
    assert!(
        summary.contains("6 image(s): 3 passed, 1 failed, 2 error(s)"),
        "{summary}"
    );
}

#[test]
fn shards_render_every_scene_exactly_once_and_merge_into_the_whole_run() {
    let dir = scratch("shards");
    let scenes = suite(&dir, 10);
    let refs = dir.join("refs");
    let whole = dir.join("whole.json");
    let out_dir = dir.join("out");
    // The suite checked against refs/, with `extra` arguments.
    let check = |extra: &[&dyn AsRef<std::ffi::OsStr>]| {
        let mut args: Vec<&dyn AsRef<std::ffi::OsStr>> =
            vec![&"render", &scenes, &"--out", &out_dir, &"--check", &refs];
        args.extend_from_slice(extra);
        ffvk(&args, &[])
    };
    assert_exit(&check(&[&"--bless", &"--json", &whole]), 0);
    // Check the whole suite once more, so that every row passes as the shards' will.
    assert_exit(&check(&[&"--json", &whole]), 0);
    let whole = json(&whole);

    let mut shard_files = Vec::new();
    let mut seen: Vec<String> = Vec::new();
    for k in 1..=3 {
        let results = dir.join(format!("shard_{k}.json"));
        let partition = format!("{k}/3");
        let out = check(&[&"--partition", &partition, &"--json", &results]);
        assert_exit(&out, 0);
        let shard = json(&results);
        let p: Partition = partition.parse().unwrap();
        for (name, status) in outcomes(&shard) {
            assert!(p.contains(&name), "{name} is not in shard {p}");
            assert_eq!(status, "pass");
            seen.push(name);
        }
        assert_eq!(shard["runs"][0]["info"]["suite_scenes"], 10);
        shard_files.push(results);
    }
    let mut whole_names: Vec<String> = outcomes(&whole).into_iter().map(|(n, _)| n).collect();
    whole_names.sort();
    seen.sort();
    assert_eq!(
        seen, whole_names,
        "the shards together are not the suite, each scene once"
    );

    // Merged in any order: the whole run's rows, in its order; one JUnit file of 3 suites.
    let merged = dir.join("merged.json");
    let junit = dir.join("merged.xml");
    let out = ffvk(
        &[
            &"results",
            &"merge",
            &shard_files[2],
            &shard_files[0],
            &shard_files[1],
            &"--json",
            &merged,
            &"--junit",
            &junit,
        ],
        &[],
    );
    assert_exit(&out, 0);
    assert_eq!(outcomes(&json(&merged)), outcomes(&whole));
    validate_junit(&junit).unwrap();
    assert_eq!(xpath_number(&junit, "count(//testsuite)"), 3);
    assert_eq!(xpath_number(&junit, "count(//testcase)"), 10);
    assert!(String::from_utf8_lossy(&out.stdout).contains("10 image(s): 10 passed"));

    // A missing shard, a shard twice and a file that is not results are refused.
    let refused = |files: &[&dyn AsRef<std::ffi::OsStr>], words: &str| {
        let mut args: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"results", &"merge"];
        args.extend_from_slice(files);
        let out = ffvk(&args, &[]);
        assert_exit(&out, 2);
        assert!(text(&out).contains(words), "{words:?} not in {}", text(&out));
    };
    refused(&[&shard_files[0], &shard_files[1]], "shard(s) 3/3 of 3 missing");
    refused(
        &[&shard_files[0], &shard_files[0], &shard_files[1], &shard_files[2]],
        "are both shard 1/3",
    );
    let scene_file = scenes.join("scene_000.toml");
    refused(&[&shard_files[0], &scene_file], "scene_000.toml");
}

#[test]
fn adding_a_scene_moves_no_other_scene_between_shards() {
    let dir = scratch("stable_shards");
    let scenes = suite(&dir, 30);
    let shards = |scenes: &Path| -> Vec<(String, u32)> {
        let mut found = Vec::new();
        for index in 1..=4 {
            let job = regress::Job {
                scenes: vec![scenes.to_path_buf()],
                partition: Some(Partition { index, count: 4 }),
                ..Default::default()
            };
            let (files, suite) = regress::job_files(&job).unwrap();
            assert!(suite >= 30);
            found.extend(files.into_iter().map(|f| (f.name, index)));
        }
        found.sort();
        found
    };
    let before = shards(&scenes);
    assert_eq!(before.len(), 30);
    assert!(
        (1..=4).all(|k| before.iter().any(|(_, s)| *s == k)),
        "an empty shard: {before:?}"
    );
    std::fs::copy(scenes.join("scene_000.toml"), scenes.join("a_new_scene.toml")).unwrap();
    let after = shards(&scenes);
    assert_eq!(after.len(), 31);
    let kept: Vec<(String, u32)> = after.into_iter().filter(|(n, _)| n != "a_new_scene").collect();
    assert_eq!(kept, before);
}

/// The one rule for what a run writes (`regress::refuse_overlaps`): results files go neither
/// over a reference, a scene file, one of the run's own images nor each other, and a reference
/// folder nested inside `--out` keeps its images; `results merge` follows it too. Every case is
/// refused before anything is written, and the references are byte for byte as blessed.
#[test]
fn results_files_and_images_never_land_on_references_scenes_or_each_other() {
    let dir = scratch("overlaps");
    let scenes = suite(&dir, 2);
    let refs = dir.join("refs");
    let out_dir = dir.join("out");
    let bless = ffvk(
        &[
            &"render", &scenes, &"--out", &out_dir, &"--check", &refs, &"--bless",
        ],
        &[],
    );
    assert_exit(&bless, 0);
    let reference = refs.join("scene_000.png");
    let blessed = std::fs::read(&reference).unwrap();
    let scene = scenes.join("scene_000.toml");
    let scene_text = std::fs::read(&scene).unwrap();
    let image = out_dir.join("scene_000.png");
    let both = dir.join("both.xml");
    let cases: [(&str, Vec<&dyn AsRef<std::ffi::OsStr>>, &str); 5] = [
        (
            "--json over a reference",
            vec![&"--json", &reference],
            "inside the reference folder",
        ),
        (
            "--junit over a reference",
            vec![&"--junit", &reference],
            "inside the reference folder",
        ),
        (
            "--junit over a scene file",
            vec![&"--junit", &scene],
            "a file this run reads",
        ),
        (
            "--json over the run's image",
            vec![&"--json", &image],
            "the run's images",
        ),
        (
            "--json and --junit on one file",
            vec![&"--json", &both, &"--junit", &both],
            "--junit and --json both name",
        ),
    ];
    for (what, extra, expected) in cases {
        let mut args: Vec<&dyn AsRef<std::ffi::OsStr>> =
            vec![&"render", &scenes, &"--out", &out_dir, &"--check", &refs];
        args.extend(extra);
        let out = ffvk(&args, &[]);
        assert_exit(&out, 2);
        assert!(text(&out).contains(expected), "{what}: {}", text(&out));
        assert_eq!(
            std::fs::read(&reference).unwrap(),
            blessed,
            "{what}: the reference"
        );
        assert_eq!(
            std::fs::read(&scene).unwrap(),
            scene_text,
            "{what}: the scene file"
        );
    }
    assert!(!both.exists(), "nothing written");

    // A reference folder nested the other way: references in X/refs, --out X, and a suite that
    // holds refs/NAME.toml, whose image would be X/refs/NAME.png.
    let x = dir.join("x");
    let nested_refs = x.join("refs");
    std::fs::create_dir_all(&nested_refs).unwrap();
    let nested_suite = dir.join("nested");
    std::fs::create_dir_all(nested_suite.join("refs")).unwrap();
    std::fs::copy(&scene, nested_suite.join("refs").join("r.toml")).unwrap();
    std::fs::write(nested_refs.join("r.png"), &blessed).unwrap();
    let out = ffvk(
        &[&"render", &nested_suite, &"--out", &x, &"--check", &nested_refs],
        &[],
    );
    assert_exit(&out, 2);
    assert!(
        text(&out).contains("the run's images outside it"),
        "{}",
        text(&out)
    );
    assert_eq!(
        std::fs::read(nested_refs.join("r.png")).unwrap(),
        blessed,
        "the nested reference"
    );

    // results merge writes neither over its inputs nor into the references its runs checked.
    let results = dir.join("results.json");
    assert_exit(
        &ffvk(
            &[
                &"render", &scenes, &"--out", &out_dir, &"--check", &refs, &"--json", &results,
            ],
            &[],
        ),
        0,
    );
    let out = ffvk(&[&"results", &"merge", &results, &"--junit", &reference], &[]);
    assert_exit(&out, 2);
    assert!(
        text(&out).contains("inside the reference folder"),
        "{}",
        text(&out)
    );
    assert_eq!(
        std::fs::read(&reference).unwrap(),
        blessed,
        "merge: the reference"
    );
    let out = ffvk(&[&"results", &"merge", &results, &"--json", &results], &[]);
    assert_exit(&out, 2);
}
