//! glTF files drawn directly (`ffvk render FILE.glb`, no scene file): the scene ffvk makes
//! for the files of `assets/gltf` (each shaped like a public sample that real content trips
//! over), its pixels against the CPU reference, and each image as a whole: lit but not
//! clipped, and framed.

use std::path::PathBuf;

use ffvk::gl::state::{ColorMaterialMode, Face, LightingMode};
use ffvk::scene::direct::{from_gltf, CameraChoice, DirectOptions, LightChoice};
use ffvk::scene::{render_scene, Scene};
use glam::{Vec3, Vec4};
use image::RgbaImage;

use crate::support::*;

fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("assets/gltf")
}

fn direct(name: &str, options: DirectOptions) -> Scene {
    let path = assets().join(name);
    from_gltf(&path, name, &Default::default(), &options)
        .unwrap_or_else(|e| panic!("{e}"))
        .scene
}

fn small() -> DirectOptions {
    DirectOptions::default().with_size(Some((96, 96)))
}

/// The clear color the direct scene uses, as bytes.
const CLEAR: [u8; 4] = [51, 51, 51, 255];

/// What an image shows of its objects: the share of the image they cover, the share of their
/// pixels clipped to white (every channel ≥ 250) and near black (every channel < 13), and
/// whether any touches the image's border.
struct Coverage {
    covered: f64,
    clipped: f64,
    black: f64,
    touches_edge: bool,
}

fn coverage(image: &RgbaImage) -> Coverage {
    let (w, h) = image.dimensions();
    let (mut n, mut clipped, mut black, mut edge) = (0usize, 0usize, 0usize, false);
    for (x, y, p) in image.enumerate_pixels() {
        if p.0 == CLEAR {
            continue;
        }
        n += 1;
        clipped += usize::from(p.0[..3].iter().all(|&c| c >= 250));
        black += usize::from(p.0[..3].iter().all(|&c| c < 13));
        edge |= x == 0 || y == 0 || x == w - 1 || y == h - 1;
    }
    let share = |k: usize| k as f64 / n.max(1) as f64;
    Coverage {
        covered: n as f64 / (w * h) as f64,
        clipped: share(clipped),
        black: share(black),
        touches_edge: edge,
    }
}

/// Checks `image` of `scene` in `mode` against the CPU reference at an 8×8 grid of probe
/// pixels that lie well inside a triangle; returns how many were probed.
fn probe(scene: &Scene, image: &RgbaImage, mode: LightingMode, what: &str) -> usize {
    let mut probed = 0;
    for j in 0..8 {
        for i in 0..8 {
            let (x, y) = (scene.width * (2 * i + 1) / 16, scene.height * (2 * j + 1) / 16);
            let Some((hit, want)) = reference_at(scene, x, y, mode) else {
                continue;
            };
            // Away from edges, where which triangle covers the pixel is a rounding question.
            if hit.coverage.weights.min_element() < 0.05 {
                continue;
            }
            assert_pixel(image, x, y, want, 1.0, &format!("{what} {}", mode.name()));
            probed += 1;
        }
    }
    probed
}

#[test]
fn every_gltf_file_drawn_directly_matches_the_reference_and_is_lit_unclipped_and_framed() {
    let mut r = renderer();
    let mut files: Vec<PathBuf> = std::fs::read_dir(assets())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| ffvk::scene::direct::is_gltf(p))
        .collect();
    files.sort();
    assert!(files.len() >= 6, "{files:?}");
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        let scene = direct(&name, small());
        for mode in LightingMode::ALL {
            let image = render_scene(&mut r, &scene, Some(mode)).unwrap();
            let what = format!("{name} {}", mode.name());
            let probed = probe(&scene, &image, mode, &what);
            assert!(probed >= 4, "{what}: only {probed} probes on a surface");
            let c = coverage(&image);
            let path = save_for_inspection(&image, &format!("gltf_{name}_{}", mode.name()));
            let say = format!(
                "{what} ({}): covers {:.0} %, clipped {:.0} %, near black {:.0} %, touches the edge: {}",
                path.display(),
                c.covered * 100.0,
                c.clipped * 100.0,
                c.black * 100.0,
                c.touches_edge
            );
            assert!(c.covered >= 0.12, "not framed: {say}");
            assert!(c.clipped <= 1.0 / 3.0, "clipped: {say}");
            assert!(c.black <= 1.0 / 3.0, "near black: {say}");
            // Only a file's own camera may cut the scene at the border.
            if name != "camera.gltf" {
                assert!(!c.touches_edge, "not framed: {say}");
            }
        }
    }
    finish(r);
}

/// The checks above can fail: the same files read with GL's defaults (what scene files without
/// `gltf_defaults` keep) wash out exactly as the issue reported.
#[test]
fn with_gl_defaults_scaled_nodes_and_physical_light_units_wash_out() {
    let mut r = renderer();
    for (name, why) in [
        ("scaled_node.gltf", "normals scaled by 100"),
        ("lamp.glb", "120 cd as a GL color"),
    ] {
        let made = from_gltf(&assets().join(name), name, &Default::default(), &small()).unwrap();
        let gl = made
            .toml
            .replace("gltf_defaults = true", "gltf_defaults = false")
            .replace("gltf_exposure = \"auto\"", "");
        let scene = Scene::parse(&gl, &assets().join(name)).unwrap();
        let image = render_scene(&mut r, &scene, Some(LightingMode::Fragment)).unwrap();
        let c = coverage(&image);
        assert!(
            c.clipped > 1.0 / 3.0,
            "{name} ({why}) under GL's defaults clips only {:.0} %",
            c.clipped * 100.0
        );
    }
    finish(r);
}

#[test]
fn gltf_meaning_maps_vertex_colors_double_sided_emissive_and_scaled_nodes_onto_gl_state() {
    // COLOR_0 × baseColorFactor (0.8) through color material, single-sided: back faces culled.
    let scene = direct("vertex_colors.gltf", small());
    let cube = &scene.meshes[0];
    let state = scene.draw_state(cube);
    assert!(state.color_material.enabled);
    assert_eq!(
        (state.color_material.face, state.color_material.mode),
        (Face::FrontAndBack, ColorMaterialMode::AmbientAndDiffuse)
    );
    assert!(Vec4::from_array(cube.data.vertices[0].color).abs_diff_eq(Vec4::new(0.8, 0.16, 0.16, 1.0), 1e-6));
    assert!(!state.model.two_side);
    assert_eq!(scene.cull_face(cube), Some(Face::Back));
    assert!(state.normalize, "GL_NORMALIZE");
    assert_eq!(
        state.model.color_control,
        ffvk::gl::state::ColorControl::SeparateSpecularColor
    );

    let scene = direct("double_sided.gltf", small());
    let pipe = &scene.meshes[0];
    assert!(scene.draw_state(pipe).model.two_side);
    assert_eq!(scene.cull_face(pipe), None);
    assert!(!scene.draw_state(pipe).color_material.enabled, "no COLOR_0");

    // emissiveFactor 1 × the texture's mean: 16 of the 64 texels sRGB (255, 140, 40), the
    // rest (20, 10, 5), averaged in linear light.
    let linear = |c: f32| {
        let c = c / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    let mean = |lit: f32, dark: f32| (16.0 * linear(lit) + 48.0 * linear(dark)) / 64.0;
    let want = Vec3::new(mean(255.0, 20.0), mean(140.0, 10.0), mean(40.0, 5.0));
    let scene = direct("emissive.gltf", small());
    let emission = scene.meshes[0].front.emission.truncate();
    assert!(emission.abs_diff_eq(want, 1e-4), "{emission} vs {want}");
    assert_eq!(scene.meshes[1].front.emission.truncate(), Vec3::ZERO);

    // The small ball sits under scales of 0.01, 100 and 0.5: its model matrix carries them.
    let scene = direct("scaled_node.gltf", small());
    let model = scene.meshes[1].model;
    assert!((glam::Mat3::from_mat4(model).determinant() - 0.125).abs() < 1e-4);
}

#[test]
fn punctual_lights_are_scaled_by_the_documented_auto_exposure() {
    let scene = direct("lamp.glb", small());
    // Bounds: the 4 × 4 floor at y = 0 and the ball up to y = 1: center (0, 0.5, 0), radius
    // √33 / 2. Each light's brightest channel × GL's 1 / (1 + d²) at the center (d at least
    // half the radius), summed, is lit to 0.75.
    let center = Vec3::new(0.0, 0.5, 0.0);
    let radius = 33f32.sqrt() / 2.0;
    let at = |p: Vec3| {
        let d = (p - center).length().max(radius / 2.0);
        1.0 / (1.0 + d * d)
    };
    let total = 120.0 * at(Vec3::new(-0.8, 1.6, 0.8)) + 60.0 * at(Vec3::new(1.2, 2.0, 0.0)) + 2.0;
    let scale = 0.75 / total;
    let bulb = scene
        .state
        .lights
        .iter()
        .find(|l| l.enabled && l.position.w != 0.0)
        .unwrap();
    let want = Vec3::new(1.0, 0.9, 0.7) * 120.0 * scale;
    assert!(
        bulb.diffuse.truncate().abs_diff_eq(want, 1e-4),
        "{} vs {want}",
        bulb.diffuse
    );
    assert!(
        scene.notes.iter().any(|n| n.contains("gltf_exposure auto")),
        "{:?}",
        scene.notes
    );

    // A given exposure replaces it; "headlight" replaces the file's lights.
    let given = direct("lamp.glb", small().with_exposure(Some(0.01)));
    let bulb = given
        .state
        .lights
        .iter()
        .find(|l| l.enabled && l.position.w != 0.0)
        .unwrap();
    assert!(bulb
        .diffuse
        .truncate()
        .abs_diff_eq(Vec3::new(1.2, 1.08, 0.84), 1e-5));
    let headlight = direct("lamp.glb", small().with_lights(LightChoice::Headlight));
    assert_eq!(headlight.state.lights.iter().filter(|l| l.enabled).count(), 1);
}

#[test]
fn a_files_camera_is_used_with_its_aspect_ratio_when_asked_for_and_framing_is_the_default() {
    let scene = direct(
        "camera.gltf",
        DirectOptions::default().with_camera(CameraChoice::FirstInFile),
    );
    assert_eq!((scene.width, scene.height), (768, 512), "aspectRatio 1.5");
    // The camera node at (3, 2, 4): the view takes it to the origin.
    let eye = scene.view.inverse().transform_point3(Vec3::ZERO);
    assert!(eye.abs_diff_eq(Vec3::new(3.0, 2.0, 4.0), 1e-4), "{eye}");
    // GL's projection for yfov 0.6 rad: y scale 1 / tan(0.3).
    assert!((scene.projection.y_axis.y - 1.0 / 0.3f32.tan()).abs() < 1e-4);

    let framed = direct("camera.gltf", DirectOptions::default());
    assert_ne!(framed.view, scene.view);
    assert_eq!(
        (framed.width, framed.height),
        (512, 512),
        "the framing camera's square"
    );
    let named = direct(
        "camera.gltf",
        DirectOptions::default().with_camera(CameraChoice::File("side view".into())),
    );
    assert_eq!(named.view, scene.view);
    let e = from_gltf(
        &assets().join("camera.gltf"),
        "camera.gltf",
        &Default::default(),
        &small().with_camera(CameraChoice::File("top".into())),
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("camera.gltf") && e.contains("\"top\"") && e.contains("0 (\"side view\")"),
        "{e}"
    );
}

fn run(args: &[&dyn AsRef<std::ffi::OsStr>]) -> (i32, String, String) {
    let out = ffvk_command(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn ffvk_render_and_scene_take_a_gltf_file_and_agree() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/output/gltf_cli");
    std::fs::create_dir_all(&dir).unwrap();
    let glb = assets().join("lamp.glb");
    let direct_png = dir.join("lamp.png");
    let (code, _, err) = run(&[&"render", &glb, &"--size", &"64x48", &"-o", &direct_png]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("lights: 3 KHR_lights_punctual lights from the file"),
        "{err}"
    );
    assert!(err.contains("camera: none in the file; framing"), "{err}");

    // The scene `ffvk scene` writes draws the same image.
    let toml = dir.join("lamp.toml");
    let (code, _, err) = run(&[&"scene", &glb, &"--size", &"64x48", &"-o", &toml]);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&toml).unwrap();
    assert!(
        text.contains("gltf_defaults = true") && text.contains("../../../assets/gltf/lamp.glb"),
        "{text}"
    );
    let via_toml = dir.join("lamp_via_toml.png");
    let (code, _, err) = run(&[&"render", &toml, &"-o", &via_toml]);
    assert_eq!(code, 0, "{err}");
    let a = image::open(&direct_png).unwrap().to_rgba8();
    let b = image::open(&via_toml).unwrap().to_rgba8();
    assert_eq!(a.dimensions(), (64, 48));
    assert!(
        a == b,
        "ffvk render FILE.glb and ffvk render of ffvk scene's TOML differ"
    );

    // explain names glTF's meaning; the glTF-only flags are refused for a scene file.
    let (code, out, err) = run(&[&"explain", &glb, &"--size", &"64x48", &"--pixel", &"32,30"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("scene: glTF: normals renormalized") && out.contains("gltf_exposure auto"),
        "{out}"
    );
    let (code, _, err) = run(&[&"render", &toml, &"--camera", &"frame"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("lamp.toml") && err.contains("apply to .gltf and .glb inputs"),
        "{err}"
    );
}

#[test]
fn gltf_lights_exact_draws_gltfs_own_falloff_and_cone_and_gl_stays_the_default() {
    use ffvk::gl::state::{Attenuation, SpotEdge};
    use ffvk::scene::gltf::GltfLights;
    let with = |mapping| direct("lamp.glb", small().with_gltf_lights(mapping));
    let lit = |scene: &Scene| {
        scene
            .state
            .lights
            .iter()
            .filter(|l| l.enabled)
            .copied()
            .collect::<Vec<_>>()
    };
    // GL's mapping, the default: GL's attenuation and edge everywhere.
    let gl = with(GltfLights::Gl);
    assert_eq!(lit(&gl), lit(&direct("lamp.glb", small())));
    assert!(lit(&gl)
        .iter()
        .all(|l| l.attenuation == Attenuation::GlK012 && l.spot_edge == SpotEdge::GlExponent));
    // Exact: the point and the spot fall off as 1 / d² (no range in the file), the spot's
    // edge is smoothstep from its inner cone (0.3 rad) to its outer (0.6 rad = the cutoff).
    let exact = with(GltfLights::Exact);
    let lights = lit(&exact);
    assert_eq!(lights.len(), 3);
    let positional: Vec<_> = lights.iter().filter(|l| l.position.w != 0.0).collect();
    assert_eq!(positional.len(), 2);
    assert!(positional
        .iter()
        .all(|l| l.attenuation == Attenuation::GltfInverseSquare { range: None }));
    let spot = lights.iter().find(|l| l.spot_cutoff != 180.0).unwrap();
    assert!((spot.spot_cutoff - 0.6f32.to_degrees()).abs() < 1e-4);
    match spot.spot_edge {
        SpotEdge::SmoothstepInnerOuter { inner_degrees } => {
            assert!((inner_degrees - 0.3f32.to_degrees()).abs() < 1e-4)
        }
        other => panic!("{other:?}"),
    }
    // GL's colors times one exposure, which "auto" computes with glTF's falloff.
    let scale = lights[0].diffuse.x / lit(&gl)[0].diffuse.x;
    assert!(scale != 1.0);
    for (a, b) in lit(&gl).iter().zip(&lights) {
        assert!((a.diffuse.truncate() * scale).abs_diff_eq(b.diffuse.truncate(), 1e-5));
    }
    assert!(
        exact.notes.iter().any(|n| n.contains("gltf_lights \"exact\"")),
        "{:?}",
        exact.notes
    );
    // Off: the file's lights left out, the headlight instead.
    let off = with(GltfLights::Off);
    assert_eq!(lit(&off).len(), 1);
    assert_eq!(lit(&off)[0].position.w, 0.0);
    // The two images differ.
    let mut r = renderer();
    let (a, b) = (
        render_scene(&mut r, &gl, None).unwrap(),
        render_scene(&mut r, &exact, None).unwrap(),
    );
    finish(r);
    assert!(a != b);
}

/// `twin` drawn in every mode is within the default tolerance of `plain`; the images are
/// saved as `gltf_NAME_MODE`.
fn draws_within_the_default_tolerance(twin: &Scene, plain: &Scene, name: &str) {
    use ffvk::images::compare::{compare, Tolerance};
    let mut r = renderer();
    for mode in LightingMode::ALL {
        let a = render_scene(&mut r, twin, Some(mode)).unwrap();
        let b = render_scene(&mut r, plain, Some(mode)).unwrap();
        let c = compare(&b, &a, &Tolerance::default()).unwrap();
        let path = save_for_inspection(&a, &format!("gltf_{name}_{}", mode.name()));
        assert!(
            c.passes(&Tolerance::default()),
            "{} ({}): {}",
            mode.name(),
            path.display(),
            c.summary()
        );
    }
    finish(r);
}

/// KHR_mesh_quantization (`assets/gltf/quantized.gltf`, from scripts/make_gltf_samples.py):
/// UNSIGNED_SHORT positions under a dequantizing node, normalized BYTE normals, normalized
/// UNSIGNED_SHORT texture coordinates, and a box of normalized SHORT positions and normals with
/// plain BYTE texture coordinates, drawn within the default tolerance of the same model in
/// floats, in every mode; their vertices agree within the quantization step.
#[test]
fn a_quantized_model_draws_within_the_default_tolerance_of_its_plain_version() {
    let options = DirectOptions::default().with_size(Some((256, 256)));
    let quantized = direct("quantized.gltf", options.clone());
    let plain = direct("quantized_plain.gltf", options);
    assert_eq!(quantized.meshes.len(), plain.meshes.len());
    for (q, p) in quantized.meshes.iter().zip(&plain.meshes) {
        assert_eq!(q.data.vertices.len(), p.data.vertices.len(), "{}", q.name);
        for (a, b) in q.data.vertices.iter().zip(&p.data.vertices) {
            let world =
                |m: &ffvk::scene::SceneMesh, v: [f32; 3]| m.model.transform_point3(Vec3::from_array(v));
            let (wa, wb) = (world(q, a.position), world(p, b.position));
            assert!(wa.distance(wb) < 1e-4, "{}: position {wa} against {wb}", q.name);
            let (na, nb) = (Vec3::from_array(a.normal), Vec3::from_array(b.normal));
            assert!(
                na.distance(nb) < 1.0 / 100.0,
                "{}: normal {na} against {nb}",
                q.name
            );
            let (ta, tb) = (
                glam::Vec2::from_array(a.texcoord),
                glam::Vec2::from_array(b.texcoord),
            );
            assert!(ta.distance(tb) < 1e-4, "{}: texcoord {ta} against {tb}", q.name);
        }
    }
    draws_within_the_default_tolerance(&quantized, &plain, "quantized");
}

/// EXT_meshopt_compression (`assets/gltf/meshopt.glb`, from examples/make_meshopt_sample.rs):
/// the plain model with every view compressed (ATTRIBUTES, TRIANGLES and INDICES modes; 16-bit
/// OCTAHEDRAL and EXPONENTIAL filters on the normals), drawn within the default tolerance of
/// the plain model in every mode; positions, texture coordinates and indices decode exactly,
/// normals within the filters' precision.
#[test]
fn a_meshopt_compressed_model_draws_within_the_default_tolerance_of_its_plain_version() {
    let options = DirectOptions::default().with_size(Some((256, 256)));
    let quantized = direct("meshopt.glb", options.clone());
    let plain = direct("quantized_plain.gltf", options);
    assert_eq!(quantized.meshes.len(), plain.meshes.len());
    for (q, p) in quantized.meshes.iter().zip(&plain.meshes) {
        assert_eq!(q.data.vertices.len(), p.data.vertices.len(), "{}", q.name);
        assert_eq!(q.data.indices, p.data.indices, "{}", q.name);
        for (a, b) in q.data.vertices.iter().zip(&p.data.vertices) {
            let world =
                |m: &ffvk::scene::SceneMesh, v: [f32; 3]| m.model.transform_point3(Vec3::from_array(v));
            let (wa, wb) = (world(q, a.position), world(p, b.position));
            assert_eq!(a.position, b.position, "{}: position {wa} against {wb}", q.name);
            let (na, nb) = (Vec3::from_array(a.normal), Vec3::from_array(b.normal));
            assert!(
                na.distance(nb) < 1.0 / 100.0,
                "{}: normal {na} against {nb}",
                q.name
            );
            let (ta, tb) = (
                glam::Vec2::from_array(a.texcoord),
                glam::Vec2::from_array(b.texcoord),
            );
            assert_eq!(ta, tb, "{}: texcoord", q.name);
        }
    }
    draws_within_the_default_tolerance(&quantized, &plain, "meshopt");
}

#[test]
fn a_folder_of_gltf_files_is_a_suite_with_references_junit_and_a_report() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/output/gltf_suite");
    let _ = std::fs::remove_dir_all(&dir);
    let models = dir.join("models");
    std::fs::create_dir_all(models.join("lamps")).unwrap();
    for (from, to) in [
        ("vertex_colors.gltf", "vertex_colors.gltf"),
        ("meshopt.glb", "meshopt.glb"),
        ("lamp.glb", "lamps/lamp.glb"),
    ] {
        std::fs::copy(assets().join(from), models.join(to)).unwrap();
    }
    // Bless references, then check against them with every results file.
    let refs = dir.join("refs");
    let (code, _, err) = run(&[&"render", &models, &"--size", &"64x48", &"-o", &refs]);
    assert_eq!(code, 0, "{err}");
    for name in ["vertex_colors.png", "meshopt.png", "lamps/lamp.png"] {
        assert!(refs.join(name).is_file(), "{name}: {err}");
    }
    let (junit, report) = (dir.join("junit.xml"), dir.join("report"));
    let (code, out, err) = run(&[
        &"render",
        &models,
        &"--size",
        &"64x48",
        &"-o",
        &dir.join("out"),
        &"--check",
        &refs,
        &"--junit",
        &junit,
        &"--report",
        &report,
    ]);
    assert_eq!(code, 0, "{out}\n{err}");
    assert!(out.contains("3 image(s): 3 passed"), "{out}");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("lamps/lamp") && xml.contains("meshopt"), "{xml}");
    assert!(report.join("index.html").is_file());

    // One model in a folder is still a folder's suite: -o is a folder, and a .png name is
    // refused rather than made a folder of.
    let one = dir.join("one");
    std::fs::create_dir_all(&one).unwrap();
    std::fs::copy(assets().join("lamp.glb"), one.join("lamp.glb")).unwrap();
    let (code, _, err) = run(&[&"render", &one, &"--size", &"32x24", &"-o", &dir.join("one_out")]);
    assert_eq!(code, 0, "{err}");
    assert!(dir.join("one_out/lamp.png").is_file());
    let png = dir.join("two_modes.png");
    let (code, _, err) = run(&[
        &"render",
        &one.join("lamp.glb"),
        &"--lighting",
        &"vertex,fragment",
        &"-o",
        &png,
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("two_modes.png") && err.contains("expected a folder for -o"),
        "{err}"
    );
    assert!(!png.exists());

    // Beside scene files, glTF files are their meshes, and a note says so.
    std::fs::write(
        one.join("scene.toml"),
        "[image]\nsize = [32, 24]\n[[meshes]]\nbuiltin = \"sphere\"\n",
    )
    .unwrap();
    let (code, _, err) = run(&[&"render", &one, &"-o", &dir.join("mixed_out")]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("1 .gltf/.glb file(s) are left to them as meshes"),
        "{err}"
    );
    assert!(dir.join("mixed_out/scene.png").is_file() && !dir.join("mixed_out/lamp.png").exists());
}

#[test]
fn the_framing_camera_turns_rises_and_zooms_as_asked_and_the_background_is_the_clear_color() {
    use ffvk::scene::direct::Orbit;
    let eye = |s: &Scene| s.view.inverse().transform_point3(Vec3::ZERO);
    let center = Vec3::new(2.3, 0.0, -2.2); // camera.gltf's bounds
    let at = |orbit: Orbit| direct("camera.gltf", small().with_orbit(orbit));
    let default = at(Orbit::default());
    let d0 = eye(&default) - center;
    // Azimuth 90: on the +X side, level with the center at elevation 0.
    let side = at(Orbit::default()
        .with_azimuth(Some(90.0))
        .with_elevation(Some(0.0)));
    let d = (eye(&side) - center).normalize();
    assert!(d.abs_diff_eq(Vec3::X, 1e-4), "{d}");
    // Straight above, looking down, still a proper view.
    let above = at(Orbit::default().with_elevation(Some(90.0)));
    let d = (eye(&above) - center).normalize();
    assert!(d.abs_diff_eq(Vec3::Y, 1e-4) && above.view.is_finite(), "{d}");
    // Zoom 2: the same direction at half the distance.
    let near = at(Orbit::default().with_zoom(Some(2.0)));
    let d1 = eye(&near) - center;
    assert!(d1.normalize().abs_diff_eq(d0.normalize(), 1e-5));
    assert!(
        (d1.length() * 2.0 - d0.length()).abs() < 1e-3 * d0.length(),
        "{d1} {d0}"
    );
    // The angles the default stands for give the default view (within rounding).
    let (a, e) = Orbit::default().degrees();
    let same = at(Orbit::default().with_azimuth(Some(a)).with_elevation(Some(e)));
    assert!(eye(&same).abs_diff_eq(eye(&default), 1e-3));

    let colored = direct("camera.gltf", small().with_background(Some([0.2, 0.6, 0.8, 1.0])));
    assert_eq!(colored.clear_color, ffvk::glam::Vec4::new(0.2, 0.6, 0.8, 1.0));
    let mut r = renderer();
    let image = render_scene(&mut r, &colored, None).unwrap();
    finish(r);
    assert_eq!(image.get_pixel(0, 0).0, [51, 153, 204, 255]);

    // Out of range, and framing moves with a file's camera, are refused by name.
    let e = from_gltf(
        &assets().join("camera.gltf"),
        "camera.gltf",
        &Default::default(),
        &small().with_orbit(Orbit::default().with_elevation(Some(95.0))),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("elevation 95: expected degrees from -90 to 90"), "{e}");
    let (code, _, err) = run(&[
        &"render",
        &assets().join("camera.gltf"),
        &"--camera",
        &"file",
        &"--zoom",
        &"2",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("move the framing camera: expected --camera frame"),
        "{err}"
    );
}

#[test]
fn an_image_never_lands_on_a_texture_its_model_reads() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/output/gltf_own_texture");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    // A model whose JSON names an image `vc.png` beside it: where `ffvk render vc.gltf` would
    // write its image without -o.
    let text = std::fs::read_to_string(assets().join("vertex_colors.gltf")).unwrap();
    let text = text.replacen('{', r#"{ "images": [ { "uri": "vc.png" } ], "#, 1);
    let model = dir.join("vc.gltf");
    std::fs::write(&model, text).unwrap();
    let texture = dir.join("vc.png");
    std::fs::write(&texture, b"the model's texture").unwrap();
    for args in [vec![], vec!["--lighting", "vertex"]] {
        let mut all: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"render", &model];
        all.extend(args.iter().map(|a| a as &dyn AsRef<std::ffi::OsStr>));
        let (code, _, err) = run(&all);
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains("vc.png") && err.contains("a file this run reads"),
            "{err}"
        );
        assert_eq!(std::fs::read(&texture).unwrap(), b"the model's texture");
    }
    // Elsewhere, it is drawn.
    let (code, _, err) = run(&[&"render", &model, &"-o", &dir.join("drawn.png")]);
    assert_eq!(code, 0, "{err}");
    assert!(dir.join("drawn.png").is_file());
}
