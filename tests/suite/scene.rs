//! Scene files and the command line: GL semantics of the format, and one clear error for
//! each kind of bad input, never a panic.

use std::path::{Path, PathBuf};

use ffvk::gl::state::LightingMode;
use ffvk::scene::{render_scene, Scene};
use glam::{Mat4, Vec3, Vec4};

use crate::support::*;

fn scratch(name: &str) -> PathBuf {
    let dir = output_dir().join("scenes").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(dir: &Path, file: &str, text: &str) -> PathBuf {
    let path = dir.join(file);
    std::fs::write(&path, text).unwrap();
    path
}

const MINIMAL: &str = "[[meshes]]\nbuiltin = \"sphere\"\nlevel = 16\n";

fn load_err(name: &str, text: &str) -> String {
    let dir = scratch(name);
    let path = write(&dir, "scene.toml", text);
    let err = Scene::load(&path).expect_err("the scene is rejected");
    let message = err.to_string();
    assert!(
        message.starts_with(&path.display().to_string()),
        "{message:?} names the file first"
    );
    message
}

/// The final bytes `ffvk explain` predicts and the ones it says the GPU drew agree within 1.
fn assert_explain_agrees_with_the_gpu(stdout: &str) {
    let final_line = stdout.lines().find(|l| l.starts_with("final color")).unwrap();
    let drew_line = stdout.lines().find(|l| l.contains(" drew ")).unwrap();
    let nums = |s: &str| -> Vec<i32> {
        let inner = &s[s.rfind('[').unwrap() + 1..s.rfind(']').unwrap()];
        inner.split(',').map(|v| v.trim().parse().unwrap()).collect()
    };
    let (a, b) = (nums(final_line), nums(drew_line));
    assert!(
        a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= 1),
        "reference {a:?} vs GPU {b:?}"
    );
}

fn contains_all(message: &str, parts: &[&str]) {
    for p in parts {
        assert!(message.contains(p), "{message:?} should mention {p:?}");
    }
}

#[test]
fn lights_are_given_in_world_space_and_stored_in_eye_space() {
    let dir = scratch("world_space");
    let path = write(
        &dir,
        "scene.toml",
        r#"
[camera]
eye = [3.0, 1.0, 2.0]
target = [0.0, 0.5, 0.0]
[[lights]]
position = [1.0, 2.0, 3.0, 1.0]
spot_direction = [0.0, -1.0, 0.0]
spot_cutoff = 30.0
[[lights]]
index = 5
position = [0.0, 1.0, 0.0, 0.0]
[[meshes]]
builtin = "sphere"
"#,
    );
    let scene = Scene::load(&path).unwrap();
    let view = Mat4::look_at_rh(Vec3::new(3.0, 1.0, 2.0), Vec3::new(0.0, 0.5, 0.0), Vec3::Y);
    assert!(scene.view.abs_diff_eq(view, 1e-6));
    let l0 = scene.state.lights[0];
    assert!(
        l0.position
            .abs_diff_eq(view * Vec4::new(1.0, 2.0, 3.0, 1.0), 1e-5),
        "{:?}",
        l0.position
    );
    assert!(l0
        .spot_direction
        .abs_diff_eq(view.transform_vector3(-Vec3::Y), 1e-5));
    let l5 = scene.state.lights[5];
    assert!(l5.enabled && !scene.state.lights[1].enabled);
    assert!(l5
        .position
        .abs_diff_eq(view * Vec4::new(0.0, 1.0, 0.0, 0.0), 1e-5));
    // Unspecified parameters keep GL's defaults; light 0's diffuse is white, light 5's black.
    assert_eq!(l0.diffuse, Vec4::ONE);
    assert_eq!(l5.diffuse, Vec4::new(0.0, 0.0, 0.0, 1.0));
    assert!(scene.state.lighting, "scene files turn LIGHTING on");
    assert_eq!(scene.state.mode, LightingMode::Vertex);
    assert_eq!((scene.width, scene.height), (512, 512));
}

#[test]
fn every_asset_scene_renders_and_matches_the_reference_where_probed() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut r = renderer();
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let mut scene = Scene::load(&path).unwrap();
        assert!(
            scene.warnings.is_empty(),
            "{}: {:?}",
            path.display(),
            scene.warnings
        );
        scene.set_size(96, 96);
        for mode in LightingMode::ALL {
            let image = render_scene(&mut r, &scene, Some(mode)).unwrap();
            // The pixel at the center is explained by the CPU reference and drawn the same,
            // where the reference knows how it was drawn: it takes each surface as lit and
            // filled, not through a mesh's raster state (stencil, masks, blending, outlines).
            let (x, y) = (48, 48);
            let plain = scene.meshes.iter().all(|m| m.raster.is_default());
            if let Some((_, want)) = reference_at(&scene, x, y, mode).filter(|_| plain) {
                assert_pixel(
                    &image,
                    x,
                    y,
                    want,
                    1.0,
                    &format!("{} {}", path.display(), mode.name()),
                );
                count += 1;
            }
        }
    }
    assert!(
        count >= 15,
        "only {count} scene/mode pairs had a surface at the center"
    );
    finish(r);
}

#[test]
fn bad_scenes_name_the_file_the_field_the_value_and_what_was_expected() {
    let m = load_err("syntax", "[image\nsize = [1, 2]\n");
    contains_all(&m, &["line 1"]);
    let m = load_err("unknown_field", &format!("[image]\nsise = [64, 64]\n{MINIMAL}"));
    contains_all(&m, &["unknown field", "sise", "size"]);
    let m = load_err("exposure_word", &format!("gltf_exposure = \"bright\"\n{MINIMAL}"));
    contains_all(
        &m,
        &["gltf_exposure", "\"bright\"", "expected \"auto\" or a number > 0"],
    );
    let m = load_err("exposure_negative", &format!("gltf_exposure = -2\n{MINIMAL}"));
    contains_all(&m, &["gltf_exposure", "-2", "a number > 0"]);
    let m = load_err("wrong_type", &format!("[image]\nsize = \"big\"\n{MINIMAL}"));
    contains_all(&m, &["size", "big"]);
    let m = load_err("zero_size", &format!("[image]\nsize = [0, 64]\n{MINIMAL}"));
    contains_all(&m, &["image.size", "[0, 64]", "1..=16384"]);
    let m = load_err("huge_size", &format!("[image]\nsize = [64, 100000]\n{MINIMAL}"));
    contains_all(&m, &["image.size", "100000", "1..=16384"]);
    let m = load_err("cutoff", &format!("[[lights]]\nspot_cutoff = 100.0\n{MINIMAL}"));
    contains_all(
        &m,
        &[
            "lights[0].spot_cutoff",
            "GL_SPOT_CUTOFF = 100",
            "[0, 90] or exactly 180",
        ],
    );
    let m = load_err(
        "attenuation",
        &format!("[[lights]]\n[[lights]]\nlinear_attenuation = -1.0\n{MINIMAL}"),
    );
    contains_all(&m, &["lights[1].linear_attenuation", "-1", ">= 0"]);
    let m = load_err("light_index", &format!("[[lights]]\nindex = 40\n{MINIMAL}"));
    contains_all(&m, &["lights[0].index", "40", "GL_MAX_LIGHTS"]);
    let m = load_err("shininess", &format!("[material]\nshininess = 200.0\n{MINIMAL}"));
    contains_all(&m, &["material", "GL_SHININESS = 200", "[0, 128]"]);
    let m = load_err(
        "color_len",
        &format!("[material]\ndiffuse = [1.0, 0.5]\n{MINIMAL}"),
    );
    contains_all(&m, &["material.diffuse", "[1.0, 0.5]", "3 (RGB) or 4 (RGBA)"]);
    let m = load_err(
        "preset",
        &format!("[material]\npreset = \"unobtainium\"\n{MINIMAL}"),
    );
    contains_all(&m, &["material.preset", "unobtainium", "emerald"]);
    let m = load_err("mode", &format!("[image]\nlighting_mode = \"phong\"\n{MINIMAL}"));
    contains_all(
        &m,
        &[
            "image.lighting_mode",
            "phong",
            r#""vertex", "fragment" or "flat""#,
        ],
    );
    let m = load_err(
        "color_control",
        &format!("[light_model]\ncolor_control = \"separate\"\n{MINIMAL}"),
    );
    contains_all(
        &m,
        &["light_model.color_control", "separate", "separate_specular_color"],
    );
    let m = load_err(
        "cm_mode",
        &format!("[color_material]\nmode = \"shiny\"\n{MINIMAL}"),
    );
    contains_all(&m, &["color_material.mode", "shiny", "ambient_and_diffuse"]);
    let m = load_err("no_meshes", "[image]\nsize = [8, 8]\n");
    contains_all(&m, &["meshes", "at least one"]);
    let m = load_err("builtin", "[[meshes]]\nbuiltin = \"cube\"\n");
    contains_all(&m, &["meshes[0].builtin", "cube", "teapot"]);
    let m = load_err("teapot_level", "[[meshes]]\nbuiltin = \"teapot\"\nlevel = 0\n");
    contains_all(&m, &["meshes[0].level", "0", "1..=64"]);
    let m = load_err("fovy", &format!("[camera]\nfovy = 190.0\n{MINIMAL}"));
    contains_all(&m, &["camera.fovy", "190", "(0, 180)"]);
    let m = load_err("missing_gltf", "[[meshes]]\ngltf = \"nowhere.gltf\"\n");
    contains_all(&m, &["meshes[0].gltf", "nowhere.gltf"]);
}

#[test]
fn bad_gltf_files_are_clear_errors() {
    let dir = scratch("bad_gltf");
    // POSITION missing: a mesh with only a NORMAL accessor.
    let no_positions = r#"{"asset":{"version":"2.0"},
        "buffers":[{"byteLength":12,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAIA/"}],
        "bufferViews":[{"buffer":0,"byteLength":12}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":1,"type":"VEC3"}],
        "meshes":[{"name":"blob","primitives":[{"attributes":{"NORMAL":0}}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}"#;
    write(&dir, "no_positions.gltf", no_positions);
    let scene = write(&dir, "scene.toml", "[[meshes]]\ngltf = \"no_positions.gltf\"\n");
    let m = Scene::load(&scene).unwrap_err().to_string();
    contains_all(
        &m,
        &["scene.toml", "meshes[0].gltf", "no_positions.gltf", "POSITION"],
    );
    write(&dir, "broken.gltf", "{ not json");
    let scene = write(&dir, "scene2.toml", "[[meshes]]\ngltf = \"broken.gltf\"\n");
    let m = Scene::load(&scene).unwrap_err().to_string();
    contains_all(&m, &["scene2.toml", "broken.gltf"]);
}

fn ffvk(args: &[&str]) -> (bool, String, String) {
    let out = crate::support::ffvk_command(&[])
        .args(args)
        .output()
        .expect("the ffvk binary runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn the_command_line_fails_cleanly_on_bad_input() {
    let dir = scratch("cli");
    let good = write(&dir, "good.toml", &format!("[image]\nsize = [32, 32]\n{MINIMAL}"));
    let bad = write(&dir, "bad.toml", "[[lights]]\nspot_exponent = 300.0\n");
    let cases: Vec<(Vec<String>, Vec<&str>)> = vec![
        (
            vec!["render".into(), dir.join("missing.toml").display().to_string()],
            vec!["missing.toml", "cannot read"],
        ),
        (
            vec!["render".into(), bad.display().to_string()],
            vec!["bad.toml", "GL_SPOT_EXPONENT = 300", "[0, 128]"],
        ),
        (
            vec![
                "render".into(),
                good.display().to_string(),
                "--size".into(),
                "0x5".into(),
            ],
            vec!["0x5", "1..=16384"],
        ),
        (
            vec![
                "render".into(),
                good.display().to_string(),
                "--lighting".into(),
                "phong".into(),
            ],
            vec!["phong", "vertex, fragment or flat"],
        ),
        (
            vec![
                "render".into(),
                good.display().to_string(),
                "-o".into(),
                "/proc/forbidden/x.png".into(),
            ],
            vec!["/proc/forbidden"],
        ),
        (
            vec![
                "explain".into(),
                good.display().to_string(),
                "--pixel".into(),
                "40,1".into(),
            ],
            vec!["40,1", "outside the 32x32"],
        ),
        (
            vec!["--device".into(), "voodoo".into(), "info".into()],
            vec!["voodoo", "llvmpipe"],
        ),
    ];
    for (args, parts) in cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (ok, _, stderr) = ffvk(&args);
        assert!(!ok, "ffvk {args:?} should fail");
        assert!(!stderr.contains("panicked"), "ffvk {args:?} panicked: {stderr}");
        contains_all(&stderr, &parts);
    }
}

#[test]
fn render_and_explain_from_the_command_line() {
    let dir = scratch("cli_ok");
    let scene = write(
        &dir,
        "ball.toml",
        &format!("[image]\nsize = [40, 40]\n[[lights]]\nposition = [1.0, 1.0, 1.0, 0.0]\n{MINIMAL}"),
    );
    let out = dir.join("ball.png");
    let (ok, stdout, stderr) = ffvk(&[
        "render",
        &scene.display().to_string(),
        "-o",
        &out.display().to_string(),
        "--lighting",
        "flat",
    ]);
    assert!(ok, "{stderr}");
    assert!(stdout.contains("ball.png"));
    let image = image::open(&out).unwrap().to_rgba8();
    assert_eq!(image.dimensions(), (40, 40));
    let (ok, stdout, stderr) = ffvk(&["explain", &scene.display().to_string(), "--pixel", "20,20"]);
    assert!(ok, "{stderr}");
    contains_all(
        &stdout,
        &[
            "GL_LIGHT0",
            "att_i",
            "spot_i",
            "f_i",
            "c_pri",
            "c_sec",
            "final color",
            "drew",
        ],
    );
    // The reference's final bytes and the GPU's agree within 1 at the center.
    assert_explain_agrees_with_the_gpu(&stdout);
}

#[test]
fn gltf_node_and_mesh_selection_and_hierarchy() {
    let dir = scratch("gltf_nodes");
    let gltf = r#"{"asset":{"version":"2.0"},
        "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
        "bufferViews":[{"buffer":0,"byteLength":36}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
        "meshes":[{"name":"tri","primitives":[{"attributes":{"POSITION":0}}]}],
        "nodes":[{"name":"root","children":[1,2]},
                 {"name":"left","mesh":0,"translation":[-1,0,0]},
                 {"name":"right","mesh":0,"translation":[1,0,0],"children":[3]},
                 {"name":"right_child","mesh":0,"scale":[2,2,2]}],
        "scenes":[{"nodes":[0]}],"scene":0}"#;
    write(&dir, "tris.gltf", gltf);
    let load = |extra: &str| {
        let path = write(
            &dir,
            "scene.toml",
            &format!("[[meshes]]\ngltf = \"tris.gltf\"\ntranslate = [0.0, 0.0, -2.0]\n{extra}"),
        );
        Scene::load(&path)
    };
    let all = load("").unwrap();
    assert_eq!(all.meshes.len(), 3);
    let right = load("node = \"right\"").unwrap();
    assert_eq!(right.meshes.len(), 2, "a node selects itself and its descendants");
    // right_child: scene translate, then right's translation, then its own scale.
    let child = &right.meshes[1].model;
    let want = Mat4::from_translation(Vec3::new(0.0, 0.0, -2.0))
        * Mat4::from_translation(Vec3::new(1.0, 0.0, 0.0))
        * Mat4::from_scale(Vec3::splat(2.0));
    assert!(child.abs_diff_eq(want, 1e-6), "{child:?}");
    // No NORMAL: flat normals (the triangle lies in z = 0, counter-clockwise: +z).
    assert_eq!(right.meshes[0].data.vertices[0].normal, [0.0, 0.0, 1.0]);
    assert_eq!(load("mesh = \"tri\"").unwrap().meshes.len(), 3);
    let m = load("node = \"nowhere\"").unwrap_err().to_string();
    contains_all(&m, &["meshes[0].gltf", "no node named \"nowhere\""]);
    let m = load("mesh = \"square\"").unwrap_err().to_string();
    contains_all(&m, &["no mesh named \"square\""]);
}

#[test]
fn lighting_variants_in_scene_files_name_the_light_field_and_values_when_wrong() {
    let light = |extra: &str| format!("[[lights]]\nposition = [0.0, 0.0, 2.0, 1.0]\n{extra}\n{MINIMAL}");
    let m = load_err(
        "inner_wider",
        &light("spot_cutoff = 20\nspot_edge = \"linear_inner_outer\"\nspot_inner_cutoff = 30"),
    );
    contains_all(
        &m,
        &["lights[0].spot_inner_cutoff", "30", "spot_cutoff = 20", "<= 20"],
    );
    let m = load_err(
        "inner_missing",
        &light("spot_cutoff = 20\nspot_edge = \"smoothstep_inner_outer\""),
    );
    contains_all(
        &m,
        &["lights[0].spot_inner_cutoff", "missing", "smoothstep_inner_outer"],
    );
    let m = load_err(
        "inner_without_edge",
        &light("spot_cutoff = 20\nspot_inner_cutoff = 5"),
    );
    contains_all(&m, &["lights[0].spot_inner_cutoff", "5", "spot_edge"]);
    let m = load_err(
        "inner_past_90",
        &light("spot_edge = \"linear_inner_outer\"\nspot_inner_cutoff = 95"),
    );
    contains_all(&m, &["lights[0].spot_inner_cutoff", "95", "[0, 90]"]);
    let m = load_err("edge_word", &light("spot_edge = \"soft\""));
    contains_all(&m, &["lights[0].spot_edge", "\"soft\"", "linear_inner_outer"]);
    let m = load_err(
        "range_negative",
        &light("attenuation = \"gltf_inverse_square\"\nrange = -1"),
    );
    contains_all(&m, &["lights[0].range", "-1", "> 0"]);
    let m = load_err("range_without_gltf", &light("range = 3"));
    contains_all(&m, &["lights[0].range", "3", "gltf_inverse_square"]);
    let m = load_err("attenuation_word", &light("attenuation = \"physical\""));
    contains_all(&m, &["lights[0].attenuation", "\"physical\"", "gl_k012"]);
    let m = load_err(
        "specular_word",
        &format!("[light_model]\nspecular_model = \"phong\"\n{MINIMAL}"),
    );
    contains_all(&m, &["light_model.specular_model", "\"phong\"", "phong_reflect"]);
    let m = load_err(
        "gltf_lights_word",
        &format!("gltf_lights = \"physical\"\n{MINIMAL}"),
    );
    contains_all(
        &m,
        &[
            "gltf_lights",
            "\"physical\"",
            "\"off\", \"gl\"",
            "\"exact\"",
            "true/false",
        ],
    );
}

#[test]
fn a_light_with_gltfs_falloff_needs_no_gl_attenuation() {
    // k0 = k1 = k2 = 0 would be 1/0 for GL's falloff, which glTF's does not read.
    let dir = scratch("gltf_falloff_k0");
    let path = write(
        &dir,
        "scene.toml",
        &format!(
            "[[lights]]\nposition = [0.0, 0.0, 3.0, 1.0]\nconstant_attenuation = 0.0\n\
             attenuation = \"gltf_inverse_square\"\n{MINIMAL}"
        ),
    );
    let scene = Scene::load(&path).expect("glTF's falloff ignores k0, k1 and k2");
    assert_eq!(scene.state.lights[0].constant_attenuation, 0.0);
    let m = load_err(
        "gl_falloff_k0",
        &format!("[[lights]]\nposition = [0.0, 0.0, 3.0, 1.0]\nconstant_attenuation = 0.0\n{MINIMAL}"),
    );
    contains_all(&m, &["lights[0]", "= 0 for a positional light"]);
}

#[test]
fn explain_names_each_variant_and_its_terms_and_agrees_with_the_gpu() {
    let dir = scratch("variants_explain");
    let scene = write(
        &dir,
        "variants.toml",
        "[image]\nsize = [48, 48]\nlighting_mode = \"fragment\"\n\
         [camera]\neye = [0.0, 0.0, 3.0]\n\
         [light_model]\nspecular_model = \"phong_reflect\"\n\
         [[lights]]\nposition = [0.3, 0.3, 2.0, 1.0]\nspot_direction = [-0.1, -0.1, -1.0]\nspot_cutoff = 20\n\
         spot_edge = \"smoothstep_inner_outer\"\nspot_inner_cutoff = 4\n\
         attenuation = \"gltf_inverse_square\"\nrange = 4.5\ndiffuse = [3.0, 3.0, 3.0]\n\
         [material]\npreset = \"gold\"\n\
         [[meshes]]\nbuiltin = \"sphere\"\nlevel = 24\n",
    );
    let (ok, stdout, stderr) = ffvk(&["explain", &scene.display().to_string(), "--pixel", "22,22"]);
    assert!(ok, "{stderr}");
    contains_all(
        &stdout,
        &[
            "att_i  gltf_inverse_square: clamp(1 − (d / range)⁴, 0, 1) / d²",
            "range 4.5",
            "spot_i smoothstep_inner_outer: smoothstep(cos outer, cos inner, cos θ)",
            "outer 20°, inner 4°",
            "f_i (r_i ⊙ v)^s_rm s_cm * s_cli",
            "(phong_reflect, factor",
        ],
    );
    assert_explain_agrees_with_the_gpu(&stdout);
}

/// A matrix replaces what it is made from (`view` eye/target/up, `projection` fovy/near/far):
/// both given, one would be silently ignored, so the scene is refused naming both.
#[test]
fn a_camera_matrix_given_with_what_it_replaces_is_refused_naming_both() {
    let identity = "[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]";
    let mesh = "\n[[meshes]]\nbuiltin = \"sphere\"\n";
    let e = load_err(
        "view-eye",
        &format!("[camera]\nview = {identity}\neye = [0, 0, 5]\n{mesh}"),
    );
    contains_all(&e, &["camera.view", "camera.eye", "replaces"]);
    let e = load_err(
        "projection-fovy",
        &format!("[camera]\nprojection = {identity}\nfovy = 30\nfar = 9\n{mesh}"),
    );
    contains_all(&e, &["camera.projection", "camera.fovy, camera.far", "replaces"]);
    // Each alone is fine.
    let dir = scratch("camera-alone");
    let path = write(
        &dir,
        "s.toml",
        &format!("[camera]\nview = {identity}\nfovy = 30\n{mesh}"),
    );
    Scene::load(&path).unwrap();
}

/// A zero light direction, or a zero spot direction on a spotlight, is legal GL that lights
/// nothing: warned, not refused.
#[test]
fn zero_light_and_spot_directions_are_warned_not_refused() {
    let dir = scratch("zero-directions");
    let path = write(
        &dir,
        "s.toml",
        "[[lights]]\nposition = [0, 0, 0, 0]\n\n[[lights]]\nposition = [0, 2, 0, 1]\nspot_direction = [0, 0, 0]\nspot_cutoff = 30\n\n\
         [[lights]]\nposition = [0, 2, 0, 1]\nspot_direction = [0, 0, 0]\n\n[[meshes]]\nbuiltin = \"sphere\"\n",
    );
    let scene = Scene::load(&path).unwrap();
    let w = scene.warnings.join("\n");
    contains_all(
        &w,
        &["lights[0].position", "lights[1].spot_direction", "lights nothing"],
    );
    assert!(
        !w.contains("lights[2]"),
        "a zero spot direction with cutoff 180 (no spotlight) is not warned: {w}"
    );
}

/// Arrays nested 100,000 deep once overflowed a 128 KiB stack in the TOML parser; the depth is
/// counted first and refused past 32, naming the file and the depth, on any stack.
#[test]
fn a_scene_nested_past_32_levels_is_refused_before_it_is_parsed() {
    let dir = scratch("nesting");
    let deep = format!("x = {}{}\n", "[".repeat(100_000), "]".repeat(100_000));
    let path = write(&dir, "deep.toml", &deep);
    let e = std::thread::Builder::new()
        .stack_size(128 << 10)
        .spawn(move || Scene::load(&path).unwrap_err().to_string())
        .unwrap()
        .join()
        .expect("no stack overflow");
    contains_all(&e, &["deep.toml", "100000 deep", "at most 32"]);
    // Brackets inside strings and comments are text, not nesting.
    let text = format!(
        "# {}\n[[meshes]]\nbuiltin = \"sphere\"\n[meshes.texture]\nbuiltin = \"checker\"\nenv = \"modulate\"\n# \"[[[[\n",
        "[".repeat(50)
    );
    let path = write(&dir, "text.toml", &text);
    Scene::load(&path).unwrap();
}
