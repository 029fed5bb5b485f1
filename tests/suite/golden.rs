//! ffvk's own golden images: the asset scenes and hard states in every lighting mode, and
//! the demo's panels, against references in tests/golden/<area>/. The references were made on
//! lavapipe, so there the comparison is exact (any changed pixel fails); on another driver the
//! user-facing tolerance policy (ffvk::images::compare::Tolerance::default()) applies. A failure
//! writes the actual image and a diff heat map to tests/output/golden/<area>/ and says how to
//! bless.

use std::path::PathBuf;

use ffvk::gl::state::LightingMode;
use ffvk::images::compare::{compare, heat_map, load_image, Tolerance};
use ffvk::images::save_png;
use ffvk_cli::regress::{self, Job, Status};

use crate::support::*;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

const HOW_TO_BLESS: &str = "to accept the new images: FFVK_BLESS=1 cargo test --test suite golden";

/// Exact on lavapipe, where the references come from; the cross-driver policy elsewhere.
fn golden_tolerance(r: &ffvk::Renderer) -> Tolerance {
    if r.device_info().name.contains("llvmpipe") {
        Tolerance::EXACT
    } else {
        Tolerance::default()
    }
}

fn check_scenes(area: &str, scenes: PathBuf) {
    check_scenes_on(area, scenes, None)
}

/// [`check_scenes`] with the fragment mode drawn on `path` (the other modes, and frames the
/// deferred path cannot draw, stay forward): the same references, every pixel within 1/255 on
/// the deferred path (its G-buffer keeps the normal's direction in 16-bit octahedral form and
/// the color in 16-bit floats, and the lighting pass rebuilds the position from the depth).
fn check_scenes_on(area: &str, scenes: PathBuf, path: Option<ffvk::FragmentPath>) {
    // Every state specialized, however many the area's scenes make: under the default policy
    // the states first seen past MAX_AUTO_VARIANTS take the uber-shader, whose rounding may
    // differ by 1/255, so that a scene added early in the folder changed a later one's image.
    let mut r = renderer_with(ffvk::Specialize::Always);
    let exact = golden_tolerance(&r) == Tolerance::EXACT;
    let tolerance = match path {
        Some(_) if exact => Tolerance::EXACT.with_threshold(1).with_flip_all_pixels(false),
        _ => golden_tolerance(&r),
    };
    let out = if path.is_some() {
        "tests/output/golden_deferred"
    } else {
        "tests/output/golden"
    };
    let job = Job {
        scenes: vec![scenes],
        out_dir: Some(root().join(out).join(area)),
        modes: LightingMode::ALL.to_vec(),
        size: Some((128, 128)),
        fragment_path: path,
        references: Some(root().join("tests/golden").join(area)),
        bless: regress::bless_from_env(),
        tolerance,
        limits: Default::default(),
        direct: Default::default(),
        driver_family: Some(regress::driver_family(r.device_info())),
        partition: None,
    };
    let rows = regress::run(&mut r, &job, &mut |_| {}).unwrap();
    finish(r);
    assert!(
        rows.iter()
            .all(|r| matches!(r.status, Status::Pass | Status::Blessed)),
        "golden images differ:\n{}\n{HOW_TO_BLESS}",
        regress::summary(&rows, true),
    );
}

#[test]
fn golden_asset_scenes_in_every_mode() {
    check_scenes("scenes", root().join("assets/scenes"));
}

#[test]
fn golden_hard_states_in_every_mode() {
    check_scenes("states", root().join("tests/golden/states"));
}

/// The fragment mode's deferred path draws every golden scene (asset scenes, hard states,
/// lighting variants) within the golden tolerance of the references the forward path made.
#[test]
fn golden_scenes_on_the_deferred_path_match_the_forward_references() {
    check_scenes_on(
        "scenes",
        root().join("assets/scenes"),
        Some(ffvk::FragmentPath::Deferred),
    );
    check_scenes_on(
        "states",
        root().join("tests/golden/states"),
        Some(ffvk::FragmentPath::Deferred),
    );
    check_scenes_on(
        "variants",
        root().join("tests/golden/variants"),
        Some(ffvk::FragmentPath::Deferred),
    );
}

/// ffvk's lighting variants (Phong's specular, soft spot edges, glTF's falloff): pinned the
/// same way, once their images matched the CPU reference (tests/suite/lighting.rs).
#[test]
fn golden_lighting_variants_in_every_mode() {
    check_scenes("variants", root().join("tests/golden/variants"));
}

#[test]
fn golden_demo_panels() {
    let mut r = renderer();
    let tolerance = golden_tolerance(&r);
    let mut panels = ffvk_cli::demo::panels(&mut r, 128).unwrap();
    panels.extend(ffvk_cli::demo::model_panels(&mut r, 128).unwrap());
    panels.extend(ffvk_cli::demo::stages::stage_panels(&mut r, 128).unwrap());
    panels.extend(ffvk_cli::demo::raster::raster_panels(&mut r, 128).unwrap());
    panels.extend(ffvk_cli::demo::multitexture::multitexture_panels(&mut r, 128).unwrap());
    finish(r);
    let refs = root().join("tests/golden/demo");
    let out = root().join("tests/output/golden/demo");
    let bless = regress::bless_from_env();
    let mut failures = Vec::new();
    for p in &panels {
        let reference = refs.join(format!("{}.png", p.name));
        let actual = out.join(format!("{}.png", p.name));
        save_png(&p.image, &actual).unwrap();
        if !reference.exists() {
            if bless {
                save_png(&p.image, &reference).unwrap();
            } else {
                failures.push(format!(
                    "{}: no reference {}; actual {}",
                    p.name,
                    reference.display(),
                    actual.display()
                ));
            }
            continue;
        }
        let expected = load_image(&reference).unwrap();
        let c = compare(&expected, &p.image, &tolerance).unwrap();
        if !c.identical() && bless {
            save_png(&p.image, &reference).unwrap();
        } else if !c.passes(&tolerance) {
            let diff = out.join(format!("{}.diff.png", p.name));
            save_png(
                &heat_map(&expected, &p.image, tolerance.threshold).unwrap(),
                &diff,
            )
            .unwrap();
            failures.push(format!(
                "{}: {}; actual {}, diff {}",
                p.name,
                c.summary(),
                actual.display(),
                diff.display()
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "demo panels differ:\n{}\n{HOW_TO_BLESS}",
        failures.join("\n")
    );
}

#[test]
fn references_of_the_drivers_own_family_take_precedence_over_the_shared_ones() {
    let area = root().join("tests/output/golden_family");
    let _ = std::fs::remove_dir_all(&area);
    let (scenes, out, refs) = (area.join("scenes"), area.join("out"), area.join("refs"));
    std::fs::create_dir_all(&scenes).unwrap();
    std::fs::write(
        scenes.join("ball.toml"),
        "[image]\nsize = [32, 32]\n[[lights]]\n[[meshes]]\nbuiltin = \"sphere\"\nlevel = 12\n",
    )
    .unwrap();
    let mut r = renderer();
    let family = regress::driver_family(r.device_info());
    let mut job = Job {
        fragment_path: None,
        scenes: vec![scenes.clone()],
        out_dir: Some(out.clone()),
        modes: Vec::new(),
        size: None,
        references: None,
        bless: false,
        tolerance: Tolerance::EXACT,
        limits: Default::default(),
        direct: Default::default(),
        driver_family: Some(family.clone()),
        partition: None,
    };
    regress::run(&mut r, &job, &mut |_| {}).unwrap();
    // The shared reference is wrong; the family's own is this driver's image.
    let image = load_image(&out.join("ball.png")).unwrap();
    save_png(&image::RgbaImage::new(32, 32), &refs.join("ball.png")).unwrap();
    save_png(&image, &refs.join(&family).join("ball.png")).unwrap();
    job.references = Some(refs.clone());
    let rows = regress::run(&mut r, &job, &mut |_| {}).unwrap();
    assert_eq!(rows[0].status, Status::Pass, "{}", regress::table(&rows));
    assert_eq!(
        rows[0].reference.as_deref(),
        Some(refs.join(&family).join("ball.png").as_path())
    );
    // Another family falls back to the shared reference, which fails.
    job.driver_family = Some("some-other-driver".into());
    let rows = regress::run(&mut r, &job, &mut |_| {}).unwrap();
    assert_eq!(rows[0].status, Status::Fail);
    assert_eq!(
        rows[0].reference.as_deref(),
        Some(refs.join("ball.png").as_path())
    );
    finish(r);
}

#[test]
fn compare_passes_a_shift_within_the_threshold_and_fails_one_beyond_it() {
    let dir = root().join("tests/output/golden_shift");
    std::fs::create_dir_all(&dir).unwrap();
    // A dark image like the golden scenes' background (0.1 → 26), and shifted copies.
    let base = image::RgbaImage::from_fn(64, 64, |x, y| {
        if (16..48).contains(&x) && (16..48).contains(&y) {
            image::Rgba([60 + x as u8, 120, 40 + y as u8, 255])
        } else {
            image::Rgba([26, 26, 26, 255])
        }
    });
    let shifted = |by: u8| {
        let mut s = base.clone();
        s.pixels_mut().for_each(|p| (0..3).for_each(|c| p.0[c] -= by));
        s
    };
    save_png(&base, &dir.join("base.png")).unwrap();
    for (by, passes) in [(1u8, true), (2, true), (3, false)] {
        let path = dir.join(format!("shift{by}.png"));
        save_png(&shifted(by), &path).unwrap();
        let out = ffvk_command(&[&"compare", &dir.join("base.png"), &path])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
        assert_eq!(
            out.status.code(),
            Some(if passes { 0 } else { 1 }),
            "shift {by}: {text}"
        );
        if by == 1 {
            // FLIP over every pixel, on request, still sees the shift.
            let all = ffvk_command(&[&"compare", &dir.join("base.png"), &path, &"--flip-all-pixels"])
                .output()
                .unwrap();
            assert_eq!(
                all.status.code(),
                Some(1),
                "{}",
                String::from_utf8_lossy(&all.stdout)
            );
        }
    }
}

#[test]
fn a_checked_run_prints_each_warning_once_on_stderr_apart_from_the_results() {
    let dir = output_dir().join("warnings_once");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("refs")).unwrap();
    let floats: [f32; 18] = [
        0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 1., 0., 0., 1.,
    ];
    std::fs::write(dir.join("tri.bin"), bytemuck::cast_slice::<f32, u8>(&floats)).unwrap();
    std::fs::write(
        dir.join("tri.gltf"),
        r#"{"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_fancy_thing"],
  "buffers": [{"uri": "tri.bin", "byteLength": 72}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0}"#,
    )
    .unwrap();
    // The same file twice: the same warning twice.
    std::fs::write(
        dir.join("two.toml"),
        "[image]\nsize = [16, 16]\n[[meshes]]\ngltf = \"tri.gltf\"\n[[meshes]]\ngltf = \"tri.gltf\"\n",
    )
    .unwrap();
    let out = ffvk_command(&[
        &"render",
        &dir.join("two.toml"),
        &"--check",
        &dir.join("refs"),
        &"--out",
        &dir.join("out"),
    ])
    .output()
    .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert_eq!(
        out.status.code(),
        Some(1),
        "a missing reference: {stdout}\n{stderr}"
    );
    assert!(
        !stdout.contains("EXT_fancy_thing"),
        "warnings among the results:\n{stdout}"
    );
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("EXT_fancy_thing")).collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].starts_with("warning: ") && warnings[0].ends_with("(×2)"),
        "{stderr}"
    );
}
