//! What a command writes never lands on what it reads: the one output rule, by file identity
//! (device and inode after links), checked before anything is written and again at each
//! write, with or without `-o`. Each test spells an output onto an input another way and
//! checks that the run is refused (exit 2, the message naming both) and the input is
//! byte for byte what it was.

use std::path::{Path, PathBuf};
use std::process::Output;

use crate::support::{ffvk_command, output_dir};

fn scratch(name: &str) -> PathBuf {
    let dir = output_dir().join("outputs").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A 4×4 PNG at `path`: the bytes to compare against afterwards.
fn texture(path: &Path) -> Vec<u8> {
    let image = image::RgbaImage::from_fn(4, 4, |x, y| {
        image::Rgba([(x * 60) as u8, (y * 60) as u8, 200, 255])
    });
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    ffvk::images::save_png(&image, path).unwrap();
    std::fs::read(path).unwrap()
}

/// A process id that no process has: one past the kernel's pid_max.
fn dead_pid() -> u64 {
    let max = std::fs::read_to_string("/proc/sys/kernel/pid_max").unwrap();
    max.trim().parse::<u64>().unwrap() + 1
}

/// A scratch folder `name` holding the scene `s.toml`, whose texture is `t.png` beside it.
fn textured_dir(name: &str) -> PathBuf {
    let dir = scratch(name);
    textured_scene(&dir, "s.toml", "t.png");
    texture(&dir.join("t.png"));
    dir
}

/// A scene of one textured plane, its texture at `image` (as the scene file spells it).
fn textured_scene(dir: &Path, name: &str, image: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(
        &path,
        format!(
            "[image]\nsize = [16, 16]\n\n[[meshes]]\nbuiltin = \"plane\"\n\n[meshes.texture]\nimage = \"{image}\"\n"
        ),
    )
    .unwrap();
    path
}

/// One triangle with texture coordinates (96 bytes in `tri.bin`) and a base-color texture
/// whose image URI is `uri`.
fn textured_gltf(dir: &Path, name: &str, uri: &str) -> PathBuf {
    let floats: [f32; 24] = [
        0., 0., 0., 1., 0., 0., 0., 1., 0., // positions
        0., 0., 1., 0., 0., 1., 0., 0., 1., // normals
        0., 0., 1., 0., 0., 1., // texture coordinates
    ];
    std::fs::write(dir.join("tri.bin"), bytemuck::cast_slice::<f32, u8>(&floats)).unwrap();
    let path = dir.join(name);
    std::fs::write(
        &path,
        format!(
            r#"{{"asset": {{"version": "2.0"}},
  "buffers": [{{"uri": "tri.bin", "byteLength": 96}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 36}}, {{"buffer": 0, "byteOffset": 36, "byteLength": 36}},
                  {{"buffer": 0, "byteOffset": 72, "byteLength": 24}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}},
    {{"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}}],
  "images": [{{"uri": "{uri}"}}],
  "textures": [{{"source": 0}}],
  "materials": [{{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}}}}}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}}, "material": 0}}]}}],
  "nodes": [{{"mesh": 0}}],
  "scenes": [{{"nodes": [0]}}], "scene": 0}}"#
        ),
    )
    .unwrap();
    path
}

fn run(dir: &Path, args: &[&dyn AsRef<std::ffi::OsStr>]) -> Output {
    ffvk_command(args).current_dir(dir).output().unwrap()
}

/// `render s.toml --out out --check refs` and `extra`, run in `dir`: the exit code and stderr.
fn render_checked(dir: &Path, extra: &[&str]) -> (Option<i32>, String) {
    let mut args: Vec<&dyn AsRef<std::ffi::OsStr>> =
        vec![&"render", &"s.toml", &"--out", &"out", &"--check", &"refs"];
    args.extend(extra.iter().map(|a| a as &dyn AsRef<std::ffi::OsStr>));
    let o = run(dir, &args);
    (o.status.code(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// The run was refused before writing, naming `input`, and `file` still holds `bytes`.
#[track_caller]
fn refused(out: &Output, input: &str, file: &Path, bytes: &[u8]) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "refused: {stderr}");
    assert!(
        stderr.contains("which this run reads") || stderr.contains("a file this run reads"),
        "{stderr}"
    );
    assert!(stderr.contains(input), "names {input}: {stderr}");
    assert_eq!(
        std::fs::read(file).unwrap(),
        bytes,
        "{} untouched",
        file.display()
    );
}

#[test]
fn render_o_onto_the_scenes_texture_is_refused_however_it_is_spelled() {
    let dir = scratch("render-o");
    let bytes = texture(&dir.join("t.png"));
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::os::unix::fs::symlink("t.png", dir.join("link.png")).unwrap();
    textured_scene(&dir, "s.toml", "t.png");
    // `nodir/../t.png`: through a folder that does not exist yet, which the write would make.
    for out in [
        "t.png",
        "./sub/../t.png",
        "link.png",
        "nodir/../t.png",
        "nodir/deeper/../../t.png",
    ] {
        let o = run(&dir, &[&"render", &"s.toml", &"-o", &out]);
        refused(&o, "t.png", &dir.join("t.png"), &bytes);
    }
    // An absolute spelling and a hard link: the same file.
    std::fs::hard_link(dir.join("t.png"), dir.join("hard.png")).unwrap();
    for out in [dir.join("t.png"), dir.join("hard.png")] {
        let o = run(&dir, &[&"render", &"s.toml", &"-o", &out]);
        refused(&o, "t.png", &dir.join("t.png"), &bytes);
    }
    assert!(std::fs::symlink_metadata(dir.join("link.png"))
        .unwrap()
        .file_type()
        .is_symlink());
}

#[test]
fn a_gltf_drawn_directly_never_writes_onto_its_own_texture() {
    let dir = scratch("gltf-o");
    let bytes = texture(&dir.join("tex.png"));
    textured_gltf(&dir, "m.gltf", "tex.png");
    let o = run(&dir, &[&"render", &"m.gltf", &"-o", &"tex.png"]);
    refused(&o, "tex.png", &dir.join("tex.png"), &bytes);
    // Without -o the image is m.png: an image URI that percent-decodes to it (`%6D` is `m`).
    let dir = scratch("gltf-escaped");
    let bytes = texture(&dir.join("m.png"));
    textured_gltf(&dir, "m.gltf", "%6D.png");
    let o = run(&dir, &[&"render", &"m.gltf"]);
    refused(&o, "m.png", &dir.join("m.png"), &bytes);
}

#[test]
fn without_o_the_image_beside_the_scene_may_not_be_its_texture_by_any_spelling() {
    for (case, spelled) in [
        ("dot", "./s.png"),
        ("parent", "sub/../s.png"),
        ("link", "linked.png"),
    ] {
        let dir = scratch(&format!("no-o-{case}"));
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        let bytes = texture(&dir.join("s.png"));
        std::os::unix::fs::symlink("s.png", dir.join("linked.png")).unwrap();
        textured_scene(&dir, "s.toml", spelled);
        let o = run(&dir, &[&"render", &"s.toml"]);
        refused(&o, "s.png", &dir.join("s.png"), &bytes);
    }
    // A texture of a glTF mesh the scene loads.
    let dir = scratch("no-o-gltf-mesh");
    let bytes = texture(&dir.join("s.png"));
    textured_gltf(&dir, "g.gltf", "s.png");
    std::fs::write(
        dir.join("s.toml"),
        "[image]\nsize = [16, 16]\n\n[[meshes]]\ngltf = \"g.gltf\"\n",
    )
    .unwrap();
    let o = run(&dir, &[&"render", &"s.toml"]);
    refused(&o, "s.png", &dir.join("s.png"), &bytes);
    // The rule is about files, not names: a texture elsewhere called s.png does not stop it.
    let dir = scratch("no-o-other-folder");
    texture(&dir.join("art/s.png"));
    textured_scene(&dir, "s.toml", "art/s.png");
    let o = run(&dir, &[&"render", &"s.toml"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(dir.join("s.png").is_file());
}

#[test]
fn blessing_never_writes_through_a_reference_that_links_to_a_texture() {
    let dir = scratch("bless-link");
    let bytes = texture(&dir.join("t.png"));
    textured_scene(&dir, "s.toml", "t.png");
    std::fs::create_dir_all(dir.join("refs")).unwrap();
    std::os::unix::fs::symlink("../t.png", dir.join("refs/s.png")).unwrap();
    let o = run(
        &dir,
        &[
            &"render", &"s.toml", &"--out", &"out", &"--check", &"refs", &"--bless",
        ],
    );
    refused(&o, "t.png", &dir.join("t.png"), &bytes);
}

#[test]
fn a_diff_map_link_to_a_texture_receives_nothing() {
    let dir = scratch("diff-link");
    let bytes = texture(&dir.join("t.png"));
    textured_scene(&dir, "s.toml", "t.png");
    std::fs::create_dir_all(dir.join("refs")).unwrap();
    std::fs::create_dir_all(dir.join("out")).unwrap();
    // A reference that differs, so a diff map is written, and the diff's name a link.
    let other = image::RgbaImage::from_pixel(16, 16, image::Rgba([255, 0, 255, 255]));
    ffvk::images::save_png(&other, &dir.join("refs/s.png")).unwrap();
    std::os::unix::fs::symlink("../t.png", dir.join("out/s.diff.png")).unwrap();
    let o = run(
        &dir,
        &[&"render", &"s.toml", &"--out", &"out", &"--check", &"refs"],
    );
    let stdout = String::from_utf8_lossy(&o.stdout);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_ne!(o.status.code(), Some(0), "{stdout}{stderr}");
    assert!(
        format!("{stdout}{stderr}").contains("which this run reads"),
        "{stdout}{stderr}"
    );
    assert_eq!(
        std::fs::read(dir.join("t.png")).unwrap(),
        bytes,
        "the texture is untouched"
    );
}

#[test]
fn a_report_replaces_links_in_its_folder_instead_of_writing_through_them() {
    let dir = textured_dir("report-link");
    let o = run(
        &dir,
        &[&"render", &"s.toml", &"--out", &"out", &"--json", &"r.json"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = run(&dir, &[&"results", &"report", &"r.json", &"--out", &"rep"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // An earlier report whose page is now a link to the scene.
    let scene = std::fs::read(dir.join("s.toml")).unwrap();
    std::fs::remove_file(dir.join("rep/index.html")).unwrap();
    std::os::unix::fs::symlink("../s.toml", dir.join("rep/index.html")).unwrap();
    std::fs::remove_file(dir.join("rep/report.css")).unwrap();
    std::os::unix::fs::symlink("../s.toml", dir.join("rep/report.css")).unwrap();
    let o = run(&dir, &[&"results", &"report", &"r.json", &"--out", &"rep"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        std::fs::read(dir.join("s.toml")).unwrap(),
        scene,
        "the scene is untouched"
    );
    let page = std::fs::symlink_metadata(dir.join("rep/index.html")).unwrap();
    assert!(
        page.file_type().is_file(),
        "the page is the report's own file now"
    );
}

#[test]
fn a_results_file_may_not_take_a_name_the_report_writes() {
    let dir = textured_dir("report-json");
    std::fs::create_dir_all(dir.join("refs")).unwrap();
    for json in ["rep/index.html", "rep/report.css", "rep/images/x.json"] {
        let (code, stderr) = render_checked(&dir, &["--report", "rep", "--json", json]);
        assert_eq!(code, Some(2), "{json}: {stderr}");
        assert!(stderr.contains("--report"), "{stderr}");
    }
}

#[test]
fn a_scene_output_may_not_replace_the_gltf_it_was_made_from_or_its_buffer() {
    let dir = scratch("scene-o");
    texture(&dir.join("tex.png"));
    textured_gltf(&dir, "m.gltf", "tex.png");
    let bin = std::fs::read(dir.join("tri.bin")).unwrap();
    // A TOML name (what `scene -o` writes) that links to the buffer.
    std::os::unix::fs::symlink("tri.bin", dir.join("out.toml")).unwrap();
    let o = run(&dir, &[&"scene", &"m.gltf", &"-o", &"out.toml"]);
    refused(&o, "tri.bin", &dir.join("tri.bin"), &bin);
}

/// A write interrupted by SIGINT, SIGTERM or SIGHUP leaves no temporary file behind (the
/// destination keeps its old contents or none).
#[test]
fn an_interrupted_write_leaves_no_temporary_file() {
    for signal in ["INT", "TERM", "HUP"] {
        let dir = scratch(&format!("signal-{signal}"));
        // A large image: its PNG takes long enough to encode for the signal to arrive mid-write.
        std::fs::write(
            dir.join("big.toml"),
            "[image]\nsize = [4096, 4096]\nclear_color = [0.3, 0.2, 0.1]\n\n[[meshes]]\nbuiltin = \"sphere\"\n",
        )
        .unwrap();
        let mut child = ffvk_command(&[&"render", &"big.toml"])
            .current_dir(&dir)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        let temporaries = || -> Vec<String> {
            std::fs::read_dir(&dir)
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .filter(|n| n.ends_with(".tmp"))
                .collect()
        };
        let start = std::time::Instant::now();
        while temporaries().is_empty() {
            assert!(
                child.try_wait().unwrap().is_none(),
                "{signal}: the write ended before it was seen"
            );
            assert!(
                start.elapsed().as_secs() < 120,
                "{signal}: no temporary file appeared"
            );
            std::thread::sleep(std::time::Duration::from_micros(200));
        }
        let killed = std::process::Command::new("kill")
            .arg(format!("-{signal}"))
            .arg(child.id().to_string())
            .status()
            .unwrap();
        assert!(killed.success());
        let status = child.wait().unwrap();
        assert!(!status.success(), "{signal}: the signal ended it");
        assert_eq!(
            temporaries(),
            Vec::<String>::new(),
            "{signal}: no temporary file left"
        );
        assert!(!dir.join("big.png").exists(), "{signal}: no partial image");
    }
}

/// Temporary files that a process killed outright (SIGKILL, a power cut) left are swept by the
/// next write of the same file; a live process's are not.
#[test]
fn stale_temporary_files_of_dead_processes_are_swept_by_the_next_write() {
    let dir = textured_dir("stale");

    let dead = dead_pid();
    let stale = dir.join(format!(".s.png.{dead}-0.tmp"));
    let alive = dir.join(format!(".s.png.{}-0.tmp", std::process::id()));
    std::fs::write(&stale, b"left by a dead writer").unwrap();
    std::fs::write(&alive, b"being written").unwrap();
    let o = run(&dir, &[&"render", &"s.toml"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!stale.exists(), "the dead process's temporary file is swept");
    assert!(alive.exists(), "a live process's is left alone");
}

/// `results merge` reads the runs' results, and through them names the scenes, images and
/// references those runs used: its `--json` and `--junit` may replace none of them, through a
/// link or a folder not made yet (`zz/../p.json`).
#[test]
fn results_merge_never_writes_onto_its_inputs_or_the_files_its_results_name() {
    let dir = textured_dir("merge");
    let o = run(
        &dir,
        &[&"render", &"s.toml", &"--out", &"out", &"--json", &"r.json"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let results = std::fs::read(dir.join("r.json")).unwrap();
    let scene = std::fs::read(dir.join("s.toml")).unwrap();
    let image = std::fs::read(dir.join("out/s.png")).unwrap();
    std::os::unix::fs::symlink("s.toml", dir.join("s.json")).unwrap();
    std::os::unix::fs::symlink("out/s.png", dir.join("o.xml")).unwrap();
    for (flag, path, input, file, bytes) in [
        ("--json", "zz/../r.json", "r.json", "r.json", &results),
        ("--json", "s.json", "s.toml", "s.toml", &scene),
        ("--junit", "o.xml", "s.png", "out/s.png", &image),
    ] {
        let o = run(&dir, &[&"results", &"merge", &"r.json", &flag, &path]);
        refused(&o, input, &dir.join(file), bytes);
    }
}

/// A report replaces its `images/` folder whole: a run that reads a file inside it (a scene or
/// texture kept there) is refused before anything is drawn, and the file stays.
#[test]
fn a_report_folder_whose_images_hold_an_input_is_refused_before_anything_is_written() {
    let dir = scratch("report-images");
    std::fs::create_dir_all(dir.join("rep/images")).unwrap();
    std::fs::create_dir_all(dir.join("refs")).unwrap();
    std::fs::write(dir.join("rep/.ffvk-report"), b"").unwrap();
    let scene = textured_scene(&dir.join("rep/images"), "s.toml", "t.png");
    let bytes = texture(&dir.join("rep/images/t.png"));
    let o = run(
        &dir,
        &[
            &"render",
            &scene,
            &"--out",
            &"out",
            &"--check",
            &"refs",
            &"--report",
            &"rep",
        ],
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("replaces this folder whole"), "{stderr}");
    assert_eq!(std::fs::read(dir.join("rep/images/t.png")).unwrap(), bytes);
    assert!(scene.is_file());
    assert!(!dir.join("out").exists(), "nothing drawn");
}

/// The sweep of stale temporary files never removes a file the run reads, whatever its name.
#[test]
fn the_sweep_of_stale_temporary_files_spares_the_runs_inputs() {
    let dir = scratch("sweep-input");
    let dead = dead_pid();
    let name = format!(".out.png.{dead}-0.tmp");
    let bytes = texture(&dir.join("t.png"));
    std::fs::rename(dir.join("t.png"), dir.join(&name)).unwrap();
    textured_scene(&dir, "s.toml", &name);
    let o = run(&dir, &[&"render", &"s.toml", &"-o", &"out.png"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        std::fs::read(dir.join(&name)).unwrap(),
        bytes,
        "the texture is still there"
    );
}

/// A report path through a folder not made yet names the folder it will name: a folder no
/// report wrote is refused as such, whatever the spelling, and its files stay.
#[test]
fn a_report_spelled_through_a_missing_folder_is_judged_by_the_folder_it_names() {
    let dir = textured_dir("report-missing");
    std::fs::create_dir_all(dir.join("rep/images")).unwrap();
    std::fs::create_dir_all(dir.join("refs")).unwrap();
    std::fs::write(dir.join("rep/images/precious.txt"), b"precious").unwrap();
    for report in ["rep", "nodir/../rep", "a/b/../../rep"] {
        let (code, stderr) = render_checked(&dir, &["--report", report]);
        assert_eq!(code, Some(2), "{report}: {stderr}");
        assert!(
            stderr.contains("holds no earlier ffvk report"),
            "{report}: {stderr}"
        );
        assert_eq!(
            std::fs::read(dir.join("rep/images/precious.txt")).unwrap(),
            b"precious"
        );
        assert!(!dir.join("rep/.ffvk-report").exists(), "{report}: not claimed");
    }
}

/// `--out` spelled through a missing folder and then a link (`nodir/../lnk/..`) names where
/// the link leads: into the reference folder, refused, and no reference is replaced.
#[test]
fn an_output_folder_spelled_through_a_missing_folder_and_a_link_is_judged_by_where_it_leads() {
    let dir = textured_dir("out-missing-link");
    std::fs::create_dir_all(dir.join("refs/sub")).unwrap();
    std::fs::create_dir_all(dir.join("w")).unwrap();
    std::os::unix::fs::symlink(dir.join("refs/sub"), dir.join("w/lnk")).unwrap();
    let other = image::RgbaImage::from_pixel(16, 16, image::Rgba([0, 0, 255, 255]));
    ffvk::images::save_png(&other, &dir.join("refs/s_vertex.png")).unwrap();
    let reference = std::fs::read(dir.join("refs/s_vertex.png")).unwrap();
    let o = run(
        &dir.join("w"),
        &[
            &"render",
            &"../s.toml",
            &"--check",
            &"../refs",
            &"--lighting",
            &"vertex,fragment",
            &"--out",
            &"nodir/../lnk/..",
        ],
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("reference folder"), "{stderr}");
    assert_eq!(std::fs::read(dir.join("refs/s_vertex.png")).unwrap(), reference);
}

/// In a folder run the workers write the images but know only their own scenes' inputs: the
/// stale-temporary sweep is the parent's, which knows every scene's, so a later scene's
/// texture named like a dead writer's temporary file stays.
#[test]
fn the_sweep_in_a_folder_run_spares_every_scenes_inputs() {
    let dir = scratch("sweep-folder");
    let suite = dir.join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    let dead = dead_pid();
    let name = format!(".a.png.{dead}-0.tmp");
    let bytes = texture(&suite.join("t.png"));
    std::fs::copy(suite.join("t.png"), suite.join(&name)).unwrap();
    textured_scene(&suite, "a.toml", "t.png");
    textured_scene(&suite, "b.toml", &name);
    let o = run(&dir, &[&"render", &"suite"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        std::fs::read(suite.join(&name)).unwrap(),
        bytes,
        "b's texture is still there"
    );
    // A dead writer's temporary file that nothing reads is swept.
    let stale = suite.join(format!(".b.png.{dead}-1.tmp"));
    std::fs::write(&stale, b"left by a dead writer").unwrap();
    let o = run(&dir, &[&"render", &"suite"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!stale.exists());
}

/// `results merge` protects what the scenes its rows name read, too: a `--json` that links
/// to a scene's texture is refused.
#[test]
fn results_merge_never_writes_onto_what_the_runs_scenes_read() {
    let dir = scratch("merge-texture");
    textured_scene(&dir, "s.toml", "t.png");
    let bytes = texture(&dir.join("t.png"));
    let o = run(
        &dir,
        &[&"render", &"s.toml", &"--out", &"out", &"--json", &"r.json"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    std::os::unix::fs::symlink("t.png", dir.join("l.json")).unwrap();
    let o = run(&dir, &[&"results", &"merge", &"r.json", &"--json", &"l.json"]);
    refused(&o, "t.png", &dir.join("t.png"), &bytes);
}

/// A folder swapped for a link while a suite runs (after every check before the run) cannot
/// carry an image onto another scene's texture: each worker knows every scene's inputs, and
/// each write is checked in the folder it really lands in. Whatever the timing, the texture
/// stays as it was.
#[test]
fn a_folder_swapped_for_a_link_during_a_suite_never_receives_an_input() {
    let dir = scratch("swapped-folder");
    let scenes = dir.join("scenes");
    std::fs::create_dir_all(&scenes).unwrap();
    std::fs::create_dir_all(dir.join("out")).unwrap();
    let bytes = texture(&dir.join("tex/a.png"));
    // `a` takes long enough to draw for the swap to come first; `b` reads `tex/a.png`, where
    // `a`'s image lands once `out` is a link to `tex`.
    slow_scene(&scenes);
    textured_scene(&scenes, "b.toml", "../tex/a.png");
    render_swapping_out(&dir, "tex", &[]);
    assert_eq!(
        std::fs::read(dir.join("tex/a.png")).unwrap(),
        bytes,
        "the texture is untouched"
    );
}

/// The same swap aimed at the reference folder: a run without `--bless` never writes there,
/// checked as each image, map and replaced reference is written, so a forged reference is
/// never overwritten into a pass.
#[test]
fn an_output_folder_swapped_for_a_link_to_the_references_never_writes_a_reference() {
    let dir = scratch("swapped-refs");
    let scenes = dir.join("scenes");
    std::fs::create_dir_all(&scenes).unwrap();
    std::fs::create_dir_all(dir.join("out")).unwrap();
    std::fs::create_dir_all(dir.join("refs")).unwrap();
    slow_scene(&scenes);
    std::fs::write(
        scenes.join("b.toml"),
        "[image]\nsize = [16, 16]\n\n[[meshes]]\nbuiltin = \"sphere\"\n",
    )
    .unwrap();
    // Forged references: what the scenes do not draw.
    let forged = image::RgbaImage::from_pixel(16, 16, image::Rgba([255, 0, 255, 255]));
    for name in ["a", "b"] {
        ffvk::images::save_png(&forged, &dir.join(format!("refs/{name}.png"))).unwrap();
    }
    let before = |name: &str| std::fs::read(dir.join(format!("refs/{name}.png"))).unwrap();
    let (a, b) = (before("a"), before("b"));
    let status = render_swapping_out(&dir, "refs", &["--check", "refs"]);
    assert!(!status.success(), "the forged references never pass");
    assert_eq!(before("a"), a, "refs/a.png untouched");
    assert_eq!(before("b"), b, "refs/b.png untouched");
}

/// A marker that is a link proves no earlier report: the folder is refused, its files kept.
#[test]
fn a_linked_report_marker_does_not_make_a_folder_a_report() {
    let dir = textured_dir("linked-marker");
    let o = run(
        &dir,
        &[&"render", &"s.toml", &"--out", &"out", &"--json", &"r.json"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::create_dir_all(dir.join("victim/images")).unwrap();
    std::fs::write(dir.join("victim/images/keep.txt"), b"precious").unwrap();
    std::os::unix::fs::symlink("../s.toml", dir.join("victim/.ffvk-report")).unwrap();
    let o = run(&dir, &[&"results", &"report", &"r.json", &"--out", &"victim"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("holds no earlier ffvk report"), "{stderr}");
    assert_eq!(
        std::fs::read(dir.join("victim/images/keep.txt")).unwrap(),
        b"precious"
    );
}

/// `scenes/a.toml`: a scene that takes long enough to draw for a swap to come before its
/// image is written.
fn slow_scene(scenes: &Path) {
    std::fs::write(
        scenes.join("a.toml"),
        "[image]\nsize = [2048, 2048]\n\n[[meshes]]\nbuiltin = \"teapot\"\nlevel = 32\n",
    )
    .unwrap();
}

/// Runs `render scenes --out out --jobs 1` and `extra` in `dir` and, as soon as its worker
/// runs (every check before the run done), swaps the folder `out` for a link to `target`;
/// the run's exit status.
fn render_swapping_out(dir: &Path, target: &str, extra: &[&str]) -> std::process::ExitStatus {
    let mut args: Vec<&dyn AsRef<std::ffi::OsStr>> =
        vec![&"render", &"scenes", &"--out", &"out", &"--jobs", &"1"];
    args.extend(extra.iter().map(|a| a as &dyn AsRef<std::ffi::OsStr>));
    let mut child = ffvk_command(&args)
        .current_dir(dir)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while !has_children(child.id()) && child.try_wait().unwrap().is_none() {
        assert!(start.elapsed().as_secs() < 60, "no worker started");
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    std::fs::rename(dir.join("out"), dir.join("out.real")).unwrap();
    std::os::unix::fs::symlink(target, dir.join("out")).unwrap();
    child.wait().unwrap()
}

/// Whether process `pid` has a child now (from /proc: each process's stat names its parent).
fn has_children(pid: u32) -> bool {
    std::fs::read_dir("/proc").unwrap().flatten().any(|entry| {
        std::fs::read_to_string(entry.path().join("stat")).is_ok_and(|stat| {
            // "PID (COMM) STATE PPID ...": the command may hold spaces and parentheses.
            stat.rsplit_once(')')
                .and_then(|(_, rest)| rest.split_whitespace().nth(1).map(|ppid| ppid == pid.to_string()))
                .unwrap_or(false)
        })
    })
}
