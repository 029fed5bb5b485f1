//! Determinism, measured: the same scene gives byte-identical pixels across runs, across
//! renderer instances in one process, and with LP_NUM_THREADS set to 1, 2 and 4.

use std::path::PathBuf;
use std::process::Command;

use ffvk::gl::state::LightingMode;
use ffvk::scene::{render_scene, Scene};

use crate::support::*;

fn scenes() -> Vec<PathBuf> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    vec![
        root.join("assets/scenes/eight_lights.toml"),
        root.join("assets/scenes/spot.toml"),
        root.join("tests/golden/states/clamping.toml"),
    ]
}

#[test]
fn identical_across_frames_and_renderer_instances() {
    let mut first = renderer();
    let mut second = renderer();
    for path in scenes() {
        let mut scene = Scene::load(&path).unwrap();
        scene.set_size(160, 120);
        for mode in LightingMode::ALL {
            let a = render_scene(&mut first, &scene, Some(mode)).unwrap();
            let b = render_scene(&mut first, &scene, Some(mode)).unwrap();
            let c = render_scene(&mut second, &scene, Some(mode)).unwrap();
            assert!(
                a == b,
                "{} {}: two frames of one renderer differ",
                path.display(),
                mode.name()
            );
            assert!(
                a == c,
                "{} {}: two renderer instances differ",
                path.display(),
                mode.name()
            );
        }
    }
    finish(first);
    finish(second);
}

#[test]
fn identical_with_1_2_and_4_rasterizer_threads() {
    let dir = output_dir().join("determinism");
    std::fs::create_dir_all(&dir).unwrap();
    for path in scenes() {
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        let mut images = Vec::new();
        for threads in ["1", "2", "4", "4"] {
            for mode in ["vertex", "fragment"] {
                let out = dir.join(format!("{stem}_{mode}_{threads}.png"));
                let status = Command::new(env!("CARGO_BIN_EXE_ffvk"))
                    .args([
                        "render",
                        &path.display().to_string(),
                        "-o",
                        &out.display().to_string(),
                    ])
                    .args(["--lighting", mode, "--size", "300x200"])
                    .env("LP_NUM_THREADS", threads)
                    .env("VK_DRIVER_FILES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json")
                    .status()
                    .unwrap();
                assert!(status.success(), "ffvk render with LP_NUM_THREADS={threads}");
                images.push((threads, mode, image::open(&out).unwrap().to_rgba8()));
            }
        }
        for (threads, mode, image) in &images {
            let (_, _, base) = images.iter().find(|(t, m, _)| *t == "1" && m == mode).unwrap();
            assert!(
                image == base,
                "{stem} {mode}: LP_NUM_THREADS={threads} differs from LP_NUM_THREADS=1"
            );
        }
    }
}
