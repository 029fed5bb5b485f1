//! Hostile input: no stack overflow on deep node chains, no read of a device, pipe or
//! anything outside a glTF asset's folder.

use std::path::{Path, PathBuf};
use std::process::Command;

use ffvk::scene::gltf::{load, LoadErrorKind};
use ffvk::scene::{Limits, Scene};

use crate::support::{ffvk_command, output_dir};

/// Waits for `child` at most `seconds`, then kills it and fails the test naming `what`.
fn finish_within(
    mut child: std::process::Child,
    seconds: u64,
    what: &str,
) -> (std::process::ExitStatus, std::process::Output) {
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > std::time::Duration::from_secs(seconds) {
            child.kill().unwrap();
            panic!("{what} took more than {seconds} s");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    (status, child.wait_with_output().unwrap())
}

fn scratch(name: &str) -> PathBuf {
    let dir = output_dir().join("hostile").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// One triangle (positions and normals, 72 bytes) in buffer 0 at `uri`, under `nodes`.
fn gltf_json(uri: &str, nodes: &str, scene_nodes: &str) -> String {
    format!(
        r#"{{"asset": {{"version": "2.0"}},
  "buffers": [{{"uri": "{uri}", "byteLength": 72}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 36}}, {{"buffer": 0, "byteOffset": 36, "byteLength": 36}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1}}}}]}}],
  "nodes": [{nodes}],
  "scenes": [{{"nodes": [{scene_nodes}]}}], "scene": 0}}"#
    )
}

/// The triangle's 72 bytes as a file next to the glTF.
fn triangle_bin(dir: &Path, name: &str) {
    let floats: [f32; 18] = [
        0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 1., 0., 0., 1.,
    ];
    std::fs::write(dir.join(name), bytemuck::cast_slice::<f32, u8>(&floats)).unwrap();
}

#[test]
fn a_node_chain_8000_deep_loads_without_overflowing_the_stack() {
    let dir = scratch("deep");
    triangle_bin(&dir, "t.bin");
    let depth = 8000;
    let nodes: Vec<String> = (0..depth)
        .map(|i| {
            if i + 1 < depth {
                format!(r#"{{"children": [{}]}}"#, i + 1)
            } else {
                r#"{"mesh": 0}"#.to_string()
            }
        })
        .collect();
    let path = dir.join("deep.gltf");
    std::fs::write(&path, gltf_json("t.bin", &nodes.join(","), "0")).unwrap();
    // On a thread with a 512 KiB stack: recursion over 8000 nodes would overflow it.
    let loaded = std::thread::Builder::new()
        .stack_size(512 << 10)
        .spawn(move || load(&path).map(|l| (l.meshes.len(), l.meshes[0].node_path.len())))
        .unwrap()
        .join()
        .expect("no stack overflow")
        .unwrap();
    assert_eq!(loaded, (1, depth));
}

#[test]
fn buffer_uris_may_not_leave_the_assets_folder() {
    let dir = scratch("outside");
    let asset = dir.join("asset");
    std::fs::create_dir_all(&asset).unwrap();
    triangle_bin(&dir, "outside.bin");
    triangle_bin(&asset, "inside.bin");
    std::os::unix::fs::symlink(dir.join("outside.bin"), asset.join("link.bin")).unwrap();
    let escaping = [
        "../../../../../../etc/passwd",
        "/etc/passwd",
        "file:///etc/passwd",
        "../outside.bin",
        "%2e%2e/outside.bin",
        "link.bin",
        "sub/../../outside.bin",
    ];
    for uri in escaping {
        let path = asset.join("a.gltf");
        std::fs::write(&path, gltf_json(uri, r#"{"mesh": 0}"#, "0")).unwrap();
        let e = load(&path).expect_err(uri);
        assert!(
            matches!(e.kind, LoadErrorKind::BufferOutside { .. }),
            "{uri}: {e}"
        );
        assert!(e.to_string().contains("leaves the asset's folder"), "{e}");
    }
    // A folder the user allows explicitly widens the rule to it, and only to it.
    let allowed = Limits::default().with_asset_roots(vec![dir.clone()]);
    std::fs::write(asset.join("s.toml"), "[[meshes]]\ngltf = \"a.gltf\"\n").unwrap();
    for (uri, loads) in [
        ("../outside.bin", true),
        ("link.bin", true),
        ("/etc/passwd", false),
        ("../../outside.bin", false),
    ] {
        std::fs::write(asset.join("a.gltf"), gltf_json(uri, r#"{"mesh": 0}"#, "0")).unwrap();
        let loaded = Scene::load_with(&asset.join("s.toml"), &allowed);
        assert_eq!(
            loaded.is_ok(),
            loads,
            "{uri}: {:?}",
            loaded.err().map(|e| e.to_string())
        );
        if !loads {
            let e = Scene::load_with(&asset.join("s.toml"), &allowed)
                .unwrap_err()
                .to_string();
            assert!(e.contains("--allow-root"), "{e}");
        }
    }
    // A malformed escape is said to be one.
    for uri in ["%zz.bin", "%e9.bin", "abc%4"] {
        let path = asset.join("c.gltf");
        std::fs::write(&path, gltf_json(uri, r#"{"mesh": 0}"#, "0")).unwrap();
        let e = load(&path).expect_err(uri).to_string();
        assert!(
            e.contains("not valid percent-encoding") && e.contains(uri),
            "{uri}: {e}"
        );
    }
    // Inside the folder, percent-encoded or not, it loads.
    for uri in ["inside.bin", "./inside.bin", "%69nside.bin"] {
        let path = asset.join("b.gltf");
        std::fs::write(&path, gltf_json(uri, r#"{"mesh": 0}"#, "0")).unwrap();
        assert_eq!(
            load(&path).unwrap_or_else(|e| panic!("{uri}: {e}")).meshes.len(),
            1
        );
    }
}

#[test]
fn devices_and_pipes_are_refused_before_they_are_read() {
    let dir = scratch("devices");
    // A buffer that is a pipe inside the folder, and a device as the glTF file itself.
    let fifo = dir.join("pipe.bin");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let path = dir.join("p.gltf");
    std::fs::write(&path, gltf_json("pipe.bin", r#"{"mesh": 0}"#, "0")).unwrap();
    let e = load(&path).unwrap_err().to_string();
    assert!(e.contains("pipe.bin") && e.contains("not a regular file"), "{e}");
    let e = load(Path::new("/dev/zero")).unwrap_err().to_string();
    assert!(e.contains("/dev/zero") && e.contains("not a regular file"), "{e}");
    // As a scene file: a device, a pipe.
    for scene in [Path::new("/dev/zero"), fifo.as_path()] {
        let e = Scene::load(scene).unwrap_err().to_string();
        assert!(e.contains("not a regular file"), "{e}");
    }
    // And as a scene's mesh.
    let scene = dir.join("s.toml");
    std::fs::write(&scene, "[[meshes]]\ngltf = \"/dev/zero\"\n").unwrap();
    let e = Scene::load(&scene).unwrap_err().to_string();
    assert!(
        e.contains("s.toml") && e.contains("/dev/zero") && e.contains("not a regular file"),
        "{e}"
    );
}

#[test]
fn fixed_length_arrays_take_exactly_their_length_and_light_indices_are_unique() {
    let dir = scratch("arrays");
    let cases = [
        ("[image]\nsize = [64, 64, 64]\n", "exactly 2"),
        ("[camera]\neye = [0, 0, 3, 99]\n", "exactly 3"),
        ("[camera]\ntarget = [0, 0]\n", "exactly 3"),
        ("[[lights]]\nposition = [1, 1, 1, 0, 7]\n", "exactly 4"),
        (
            &format!("[camera]\nview = [{}]\n", vec!["0"; 17].join(", ")),
            "exactly 16",
        ),
    ];
    for (k, (text, words)) in cases.iter().enumerate() {
        let path = dir.join(format!("a{k}.toml"));
        std::fs::write(&path, format!("{text}[[meshes]]\nbuiltin = \"sphere\"\n")).unwrap();
        let e = Scene::load(&path).unwrap_err().to_string();
        assert!(e.contains("invalid length") && e.contains(words), "{text}: {e}");
    }
    let path = dir.join("lights.toml");
    std::fs::write(
        &path,
        "[[meshes]]\nbuiltin = \"sphere\"\n[[lights]]\nindex = 2\n[[lights]]\nindex = 2\ndiffuse = [1, 0, 0]\n",
    )
    .unwrap();
    let e = Scene::load(&path).unwrap_err().to_string();
    assert!(
        e.contains("lights[1].index") && e.contains("GL_LIGHT2 is already lights[0]"),
        "{e}"
    );
}

/// The error `Scene::load` gives for `text` (with a sphere appended unless `text` has meshes).
fn scene_error(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(format!("{name}.toml"));
    let text = if text.contains("[[meshes]]") {
        text.to_string()
    } else {
        format!("{text}\n[[meshes]]\nbuiltin = \"sphere\"\n")
    };
    std::fs::write(&path, text).unwrap();
    let e = Scene::load(&path).expect_err(name).to_string();
    assert!(
        e.starts_with(&path.display().to_string()),
        "names the file first: {e}"
    );
    e
}

#[test]
fn what_drawing_would_refuse_is_a_scene_error_naming_the_field() {
    let dir = scratch("drawable");
    triangle_bin(&dir, "t.bin");
    std::fs::write(dir.join("t.gltf"), gltf_json("t.bin", r#"{"mesh": 0}"#, "0")).unwrap();
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "zero_attenuation",
            "[[lights]]\nposition = [0, 0, 2, 1]\nconstant_attenuation = 0.0\n",
            &["lights[0]", "attenuation = 0", "> 0"],
        ),
        (
            "zero_scale",
            "[[lights]]\n[[meshes]]\nbuiltin = \"sphere\"\nscale = [1, 0, 1]\n",
            &["mesh \"sphere\"", "determinant 0", "invertible"],
        ),
        (
            "singular_view",
            &format!(
                "[camera]\nview = [{}]\n",
                ["1", "0", "0", "0"].repeat(4).join(", ")
            ),
            &["camera.view", "determinant", "invertible"],
        ),
        (
            "zero_projection",
            &format!("[camera]\nprojection = [{}]\n", vec!["0"; 16].join(", ")),
            &["camera.projection", "determinant 0", "invertible projection"],
        ),
        (
            "negative_index",
            "[[lights]]\nindex = -1\n",
            &["lights[0].index", "-1", "expected 0..16"],
        ),
        (
            "level_on_gltf",
            "[[meshes]]\ngltf = \"t.gltf\"\nlevel = 3\n",
            &["meshes[0].level", "built-in shapes only"],
        ),
        (
            "color_on_gltf",
            "[[meshes]]\ngltf = \"t.gltf\"\ncolor = [1, 0, 0]\n",
            &["meshes[0].color", "built-in shapes only"],
        ),
    ];
    for (name, text, parts) in cases {
        let e = scene_error(&dir, name, text);
        for part in *parts {
            assert!(e.contains(part), "{name}: {part:?} missing from {e}");
        }
    }
}

#[test]
fn a_megabyte_long_value_is_shortened_in_the_message() {
    let dir = scratch("long");
    let long = "x".repeat(1 << 20);
    for (name, text, field) in [
        (
            "mode",
            format!("[image]\nlighting_mode = \"{long}\"\n"),
            "image.lighting_mode",
        ),
        (
            "preset",
            format!("[material]\npreset = \"{long}\"\n"),
            "material.preset",
        ),
        ("toml", format!("[image]\nsize = \"{long}\"\n"), "size"),
        ("key", format!("[image]\n{long} = 1\n"), "unknown field"),
    ] {
        let e = scene_error(&dir, name, &text);
        assert!(e.contains(field), "{name}: {e}");
        assert!(e.len() < 2000, "{name}: a {} byte message", e.len());
    }
}

/// A glTF of 3 vertices and `index_count` UNSIGNED_BYTE indices (0, 1, 2, 0, 1, 2, ...) and no
/// normals, so that every triangle gets vertices of its own: 48 bytes of mesh per index byte.
fn index_heavy_gltf(dir: &Path, index_count: usize) -> PathBuf {
    let floats: [f32; 9] = [0., 0., 0., 1., 0., 0., 0., 1., 0.];
    let mut bin = bytemuck::cast_slice::<f32, u8>(&floats).to_vec();
    bin.extend((0..index_count).map(|i| (i % 3) as u8));
    std::fs::write(dir.join("heavy.bin"), &bin).unwrap();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}},
  "buffers": [{{"uri": "heavy.bin", "byteLength": {len}}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 36}}, {{"buffer": 0, "byteOffset": 36, "byteLength": {index_count}}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5121, "count": {index_count}, "type": "SCALAR"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1}}]}}],
  "nodes": [{{"mesh": 0}}], "scenes": [{{"nodes": [0]}}], "scene": 0}}"#,
        len = bin.len()
    );
    let path = dir.join("heavy.gltf");
    std::fs::write(&path, json).unwrap();
    path
}

#[test]
fn meshes_past_the_scenes_memory_limit_are_refused_before_they_are_read() {
    let dir = scratch("budget");
    // One triangle placed by 2,000 nodes: 156 bytes each time it is placed.
    triangle_bin(&dir, "t.bin");
    let nodes = vec![r#"{"mesh": 0}"#; 2000].join(",");
    let roots: Vec<String> = (0..2000).map(|i| i.to_string()).collect();
    let many = dir.join("many.gltf");
    std::fs::write(&many, gltf_json("t.bin", &nodes, &roots.join(","))).unwrap();
    std::fs::write(dir.join("many.toml"), "[[meshes]]\ngltf = \"many.gltf\"\n").unwrap();
    let limits = Limits::default().with_mesh_bytes(100_000);
    let e = Scene::load_with(&dir.join("many.toml"), &limits)
        .unwrap_err()
        .to_string();
    for part in [
        "many.toml",
        "meshes[0].gltf",
        "mesh 0 primitive 0",
        "3 vertices and 3 indices take 156 bytes",
        "limit of 100000 bytes",
        "--max-mesh-mib",
    ] {
        assert!(e.contains(part), "{part:?} missing from {e}");
    }
    let scene = Scene::load_with(
        &dir.join("many.toml"),
        &Limits::default().with_mesh_bytes(2000 * 156),
    )
    .unwrap();
    assert_eq!(scene.meshes.len(), 2000, "exactly at the limit loads");
    // Built-in shapes count too.
    std::fs::write(
        dir.join("spheres.toml"),
        "[[meshes]]\nbuiltin = \"sphere\"\nlevel = 1024\n".repeat(3),
    )
    .unwrap();
    let e = Scene::load_with(
        &dir.join("spheres.toml"),
        &Limits::default().with_mesh_bytes(80 << 20),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("meshes[2]") && e.contains("mesh memory limit"), "{e}");

    // From the command line: refused under a low limit, rendered once it is raised.
    index_heavy_gltf(&dir, 300_000);
    std::fs::write(
        dir.join("heavy.toml"),
        "[image]\nsize = [16, 16]\n[[lights]]\n[[meshes]]\ngltf = \"heavy.gltf\"\n",
    )
    .unwrap();
    let scene = dir.join("heavy.toml");
    let out = ffvk_command(&[&"--max-mesh-mib", &"4", &"render", &scene])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("heavy.gltf") && stderr.contains("limit of 4194304 bytes"),
        "{stderr}"
    );
    assert!(!dir.join("heavy.png").exists());
    let out = ffvk_command(&[&"--max-mesh-mib", &"16", &"render", &scene])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(dir.join("heavy.png").exists());
}

#[test]
fn running_out_of_host_memory_while_reading_a_mesh_is_an_error_not_an_abort() {
    let dir = scratch("oom");
    // 10 M indices: 400 MB of vertices, past a 400 MB address-space limit with the rest.
    index_heavy_gltf(&dir, 10_000_002);
    std::fs::write(
        dir.join("s.toml"),
        "[[lights]]\n[[meshes]]\ngltf = \"heavy.gltf\"\n",
    )
    .unwrap();
    let scene = dir.join("s.toml");
    let out = Command::new("prlimit")
        .arg("--as=400000000")
        .arg(env!("CARGO_BIN_EXE_ffvk"))
        .args([
            "--max-mesh-mib",
            "4096",
            "explain",
            scene.to_str().unwrap(),
            "--pixel",
            "1,1",
        ])
        .output()
        .expect("prlimit (util-linux) runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("heavy.gltf")
            && stderr.contains("cannot allocate")
            && stderr.contains("bytes of host memory"),
        "{stderr}"
    );
}

#[test]
fn deeply_nested_toml_and_json_are_errors_not_stack_overflows() {
    let dir = scratch("nesting");
    let deep = 100_000;
    std::fs::write(
        dir.join("deep.gltf"),
        format!(
            r#"{{"asset": {{"version": "2.0"}}, "extras": {}{}}}"#,
            "[".repeat(deep),
            "]".repeat(deep)
        ),
    )
    .unwrap();
    let cases = [
        (
            "arrays",
            format!("x = {}{}\n", "[".repeat(deep), "]".repeat(deep)),
        ),
        ("tables", format!("a{} = 1\n", ".a".repeat(deep / 2))),
        (
            "inline",
            format!("x = {}{}\n", "{ a = ".repeat(deep / 8), "}".repeat(deep / 8)),
        ),
        ("json", "[[meshes]]\ngltf = \"deep.gltf\"\n".to_string()),
    ];
    for (name, text) in cases {
        // On a 512 KiB stack: a parser recursing once per level would overflow it.
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, text).unwrap();
        let e = std::thread::Builder::new()
            .stack_size(512 << 10)
            .spawn(move || Scene::load(&path).map(|_| ()).unwrap_err().to_string())
            .unwrap()
            .join()
            .expect("no stack overflow");
        // Brackets and braces are counted before the TOML parser runs (32 levels); JSON stops
        // at its parser's recursion limit.
        assert!(
            e.contains("recursion limit") || e.contains("expected at most 32"),
            "{name}: {e}"
        );
        assert!(e.len() < 2000, "{name}: a {} byte message", e.len());
    }
}

#[test]
fn glb_headers_with_a_short_length_or_another_version_are_errors() {
    let dir = scratch("glb_header");
    let header = |version: u32, length: u32| {
        let mut bytes = b"glTF".to_vec();
        bytes.extend(version.to_le_bytes());
        bytes.extend(length.to_le_bytes());
        bytes
    };
    // The glTF-Validator's zero_length.glb and invalid_version.glb, and their neighbours.
    let cases = [
        ("zero_length", header(2, 0), "length is 0"),
        ("short_length", header(2, 11), "length is 11"),
        (
            "past_the_end",
            header(2, 400),
            "expected the file's length, 12 bytes",
        ),
        ("version_0", header(0, 12), "GLB version 0: expected 2"),
        ("truncated", b"glTF\x02\x00".to_vec(), "a GLB header of 6 bytes"),
    ];
    for (name, bytes, words) in cases {
        let path = dir.join(format!("{name}.glb"));
        std::fs::write(&path, bytes).unwrap();
        let e = load(&path).expect_err(name).to_string();
        assert!(
            e.contains(&format!("{name}.glb")) && e.contains(words),
            "{name}: {e}"
        );
    }
}

/// An image with no source, or in a bufferView without a mimeType, made the `gltf` crate
/// unwrap a `None` (a panic in `render`, `scene` and `explain`): it is a load error naming the
/// image and what was expected.
#[test]
fn gltf_images_without_a_source_or_a_mime_type_are_errors_not_panics() {
    let dir = scratch("image-sources");
    triangle_bin(&dir, "t.bin");
    let cases = [
        ("none", "{}", "images[0]: neither uri nor bufferView"),
        (
            "mime-only",
            r#"{"mimeType": "image/png"}"#,
            "images[0]: neither uri nor bufferView",
        ),
        (
            "view-without-mime",
            r#"{"bufferView": 0}"#,
            "images[0].mimeType: missing",
        ),
        (
            "both",
            r#"{"uri": "x.png", "bufferView": 0, "mimeType": "image/png"}"#,
            "images[0]: both uri and bufferView",
        ),
    ];
    for (name, image, expected) in cases {
        let json = gltf_json("t.bin", r#"{"mesh": 0}"#, "0");
        // The triangle's material samples texture 0, whose image is the case's.
        let json = json.replacen(
            r#""meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}]}]"#,
            &format!(
                r#""meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1}}, "material": 0}}]}}],
  "materials": [{{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}}}}}}],
  "textures": [{{"source": 0}}], "images": [{image}]"#
            ),
            1,
        );
        assert!(
            json.contains("\"images\""),
            "{name}: the case's JSON was not spliced in"
        );
        let path = dir.join(format!("{name}.gltf"));
        std::fs::write(&path, json).unwrap();
        let out_png = dir.join(format!("{name}.png"));
        let runs: [Vec<&dyn AsRef<std::ffi::OsStr>>; 3] = [
            vec![&"render", &path, &"-o", &out_png],
            vec![&"scene", &path],
            vec![&"explain", &"--pixel", &"1,1", &path],
        ];
        for args in runs {
            let out = ffvk_command(&args).output().unwrap();
            let stderr = String::from_utf8_lossy(&out.stderr);
            // 2: an error (a panic exits with 101).
            assert_eq!(
                out.status.code(),
                Some(2),
                "{name} {:?}: {stderr}",
                args[0].as_ref()
            );
            assert!(!stderr.contains("panicked"), "{name}: {stderr}");
            assert!(
                stderr.contains(expected) && stderr.contains(&format!("{name}.gltf")),
                "{name}: {stderr}"
            );
        }
        assert!(!out_png.exists(), "{name}: no image is written");
    }
}

/// `compare` refuses a pipe or a device as either image, as every other command does, instead
/// of blocking on the pipe until a writer comes.
#[test]
fn compare_refuses_pipes_and_devices_instead_of_blocking() {
    let dir = scratch("compare-fifo");
    let fifo = dir.join("a.png");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let png = dir.join("b.png");
    image::RgbaImage::new(2, 2).save(&png).unwrap();
    for (expected, actual) in [
        (fifo.as_path(), png.as_path()),
        (png.as_path(), fifo.as_path()),
        (Path::new("/dev/zero"), png.as_path()),
    ] {
        let child = ffvk_command(&[&"compare", &expected, &actual])
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        // A blocked child is killed after 20 s, and the test fails.
        let what = format!("compare {} {}", expected.display(), actual.display());
        let (status, out) = finish_within(child, 20, &what);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(status.code(), Some(2), "an error: {stderr}");
        assert!(stderr.contains("not a regular file"), "{stderr}");
    }
}

/// Output piped into a reader that has gone (`ffvk compare a b | head -1`) ends ffvk quietly, as
/// it ends other Unix tools, instead of a panic in `println!` on a broken pipe.
#[test]
fn a_closed_output_pipe_ends_ffvk_without_a_panic() {
    let dir = scratch("broken-pipe");
    let err = dir.join("stderr.txt");
    let ffvk = env!("CARGO_BIN_EXE_ffvk");
    // `true` exits without reading, so ffvk's first line meets a closed pipe.
    let status = Command::new("sh")
        .arg("-c")
        .arg(r#""$1" info 2>"$2" | true"#)
        .arg("sh")
        .arg(ffvk)
        .arg(&err)
        .env("VK_DRIVER_FILES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json")
        .status()
        .unwrap();
    assert!(status.success(), "the pipeline's status is true's");
    let stderr = std::fs::read_to_string(&err).unwrap();
    assert!(!stderr.contains("panicked"), "{stderr}");
}

/// A glTF of 20,000 nodes each placing one quad with vertex colors (a draw each, under glTF's
/// defaults: color material on) renders in well under a second on lavapipe here (100,000 nodes:
/// about 1 s and 770 MB). It once took about 2.3 ms and 245 KB per node, minutes for 100,000
/// nodes, when every draw made lavapipe compile a shader variant; the bound (30 s) catches
/// that, not a few percent.
#[test]
fn twenty_thousand_nodes_render_in_seconds_not_minutes() {
    let dir = scratch("many-nodes");
    // The quad: positions, normals, colors (floats), then six u16 indices.
    let mut bytes = Vec::new();
    for (x, y) in [(-0.5f32, -0.5f32), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)] {
        bytes.extend(bytemuck::cast_slice::<f32, u8>(&[x, y, 0.0]));
    }
    for _ in 0..4 {
        bytes.extend(bytemuck::cast_slice::<f32, u8>(&[0.0, 0.0, 1.0]));
    }
    for _ in 0..4 {
        bytes.extend(bytemuck::cast_slice::<f32, u8>(&[1.0, 0.5, 0.2, 1.0]));
    }
    bytes.extend(bytemuck::cast_slice::<u16, u8>(&[0, 1, 2, 0, 2, 3, 0]));
    std::fs::write(dir.join("quad.bin"), &bytes).unwrap();
    const NODES: usize = 20_000;
    let side = (NODES as f64).sqrt().ceil() as usize;
    let nodes: Vec<String> = (0..NODES)
        .map(|i| {
            format!(
                r#"{{"mesh": 0, "translation": [{}, {}, 0]}}"#,
                (i % side) as f32 * 1.1,
                (i / side) as f32 * 1.1
            )
        })
        .collect();
    let roots: Vec<String> = (0..NODES).map(|i| i.to_string()).collect();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}},
  "buffers": [{{"uri": "quad.bin", "byteLength": {len}}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}}, {{"buffer": 0, "byteOffset": 48, "byteLength": 48}},
    {{"buffer": 0, "byteOffset": 96, "byteLength": 64}}, {{"buffer": 0, "byteOffset": 160, "byteLength": 12}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]}},
    {{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"}},
    {{"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC4"}},
    {{"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1, "COLOR_0": 2}}, "indices": 3}}]}}],
  "nodes": [{nodes}], "scenes": [{{"nodes": [{roots}]}}], "scene": 0}}"#,
        len = bytes.len(),
        nodes = nodes.join(", "),
        roots = roots.join(", "),
    );
    let path = dir.join("nodes.gltf");
    std::fs::write(&path, json).unwrap();
    let png = dir.join("nodes.png");
    let child = ffvk_command(&[&"render", &path, &"-o", &png])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let (status, out) = finish_within(child, 30, &format!("{NODES} nodes"));
    assert!(status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let image = image::open(&png).unwrap().to_rgba8();
    // The grid is drawn: most of the image is the quads' lit orange, not the clear color.
    let orange = image.pixels().filter(|p| p.0[0] > p.0[2] + 40).count();
    assert!(
        orange > (image.width() * image.height() / 4) as usize,
        "{orange} orange pixels"
    );
}

/// What the specification forbids and the `gltf` crate's validator lets through is refused with
/// the field, its value and what was expected: a buffer of 0 bytes, a vertex stride that is not
/// a multiple of 4, a zero rotation quaternion (drawn before as if it were no rotation).
#[test]
fn zero_buffers_odd_strides_and_zero_rotations_are_refused_naming_the_field() {
    let dir = scratch("spec-limits");
    triangle_bin(&dir, "t.bin");
    let base = gltf_json("t.bin", r#"{"mesh": 0}"#, "0");
    let cases = [
        (
            "zero-buffer",
            base.replace(r#""byteLength": 72}"#, r#""byteLength": 0}"#),
            "buffers[0].byteLength: 0: expected at least 1",
        ),
        (
            "odd-stride",
            base.replacen(
                r#"{"buffer": 0, "byteOffset": 0, "byteLength": 36}"#,
                r#"{"buffer": 0, "byteOffset": 0, "byteLength": 36, "byteStride": 14}"#,
                1,
            ),
            "bufferViews[0].byteStride: 14: expected a multiple of 4",
        ),
        (
            "zero-rotation",
            gltf_json("t.bin", r#"{"mesh": 0, "rotation": [0, 0, 0, 0]}"#, "0"),
            "nodes[0].rotation: [0, 0, 0, 0]: expected a unit quaternion",
        ),
    ];
    for (name, json, expected) in cases {
        let path = dir.join(format!("{name}.gltf"));
        std::fs::write(&path, &json).unwrap();
        let e = load(&path).unwrap_err().to_string();
        assert!(
            e.contains(expected) && e.contains(&format!("{name}.gltf")),
            "{name}: {e}"
        );
    }
}

/// A sphere whose unit 1 takes `unit1` (unit 0 the checker), each unit filtered linearly: the
/// filter that reads two texels a side, the second one past the first.
fn units_scene(unit1: &str) -> String {
    format!(
        "[image]\nsize = [48, 48]\n[camera]\neye = [0.0, 0.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\nfovy = 45\n\
         [[lights]]\nposition = [1.0, 1.0, 1.0, 0.0]\n[[meshes]]\nbuiltin = \"sphere\"\nlevel = 4\n\
         texture_units = [{{ builtin = \"checker\", min_filter = \"linear\", mag_filter = \"linear\" }}, {{ {unit1}, min_filter = \"linear\", mag_filter = \"linear\" }}]\n"
    )
}

/// GL lets a program give any finite coordinates, q = 0 among them (glMultiTexCoord4f(…, 0);
/// GL leaves the texel undefined there): `ffvk explain` then samples at s/q = ∞, or at a texel
/// index past any integer's range, and must still print rather than overflow an index
/// (a panic in a build with overflow checks).
#[test]
fn explain_on_a_unit_whose_coordinates_are_infinite_after_the_divide_by_q_does_not_panic() {
    for unit1 in [
        "builtin = \"lightmap\", coords = [1.0, 1.0, 0.0, 0.0]",
        "builtin = \"lightmap\", coords = [3.0e38, -3.0e38, 0.0, 1.0e-30]",
        "builtin = \"lightmap\", wrap_s = \"mirrored_repeat\", wrap_t = \"clamp_to_edge\", coords = [-1.0, 1.0, 0.0, 0.0]",
        "cube_map = { builtin = \"faces\" }, coords = [1.0, -1.0, 1.0, 0.0]",
    ] {
        let scene = Scene::parse(&units_scene(unit1), Path::new("hostile/q0.toml")).unwrap();
        for (x, y) in [(24, 24), (23, 24), (24, 23), (16, 28)] {
            let text = std::panic::catch_unwind(|| {
                ffvk_cli::explain::explain(&scene, x, y, ffvk::gl::state::LightingMode::Vertex)
            })
            .unwrap_or_else(|_| panic!("explain panicked at ({x}, {y}) with unit 1 {unit1}"));
            let text = text.expect("the sphere covers the pixel");
            assert!(text.contains("GL_TEXTURE1"), "{text}");
        }
    }
}

/// `--max-texture-mib` bounds a scene file's own images as it bounds a glTF file's: each
/// unit's `image` and each cube map face is charged (RGBA8 with its mipmaps, from the file's
/// header) before it is decoded, so that a small PNG of a large, flat image named by many
/// units and faces cannot take the host's memory.
#[test]
fn a_scene_files_images_and_cube_faces_count_against_the_texture_memory_limit() {
    let dir = scratch("texture-budget");
    image::RgbaImage::from_pixel(64, 64, image::Rgba([200, 120, 40, 255]))
        .save(dir.join("flat.png"))
        .unwrap();
    let faces = ["\"flat.png\""; 6].join(", ");
    let text = format!(
        "[[meshes]]\nbuiltin = \"sphere\"\nlevel = 4\n\
         texture_units = [{{ image = \"flat.png\" }}, {{ cube_map = {{ faces = [{faces}] }} }}]\n"
    );
    let path = dir.join("budget.toml");
    std::fs::write(&path, &text).unwrap();
    // A 64² image takes 21,844 bytes with its mipmaps: seven of them are the scene's.
    let one = 4 * (64 * 64 + 32 * 32 + 16 * 16 + 8 * 8 + 4 * 4 + 2 * 2 + 1);
    let fits = Limits::default().with_texture_bytes(7 * one);
    Scene::load_with(&path, &fits).expect("seven images within the limit");
    let four = Limits::default().with_texture_bytes(4 * one + 100);
    let e = Scene::load_with(&path, &four)
        .expect_err("the fifth image passes the limit")
        .to_string();
    for part in [
        "budget.toml",
        "meshes[0].texture_units[1].cube_map.faces[3]",
        "flat.png",
        "64x64",
        &format!("{one} bytes"),
        &format!("{} bytes of the textures before", 4 * one),
        "--max-texture-mib",
    ] {
        assert!(e.contains(part), "{e:?} lacks {part:?}");
    }
}
