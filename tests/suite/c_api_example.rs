//! The C API's example (ffvk-c/examples/teapot.c): plain C99 on Vulkan's C API and
//! libffvk_c.so, built with the system's C compiler through its Makefile and run with the
//! validation layer, draws the Rust embedding example's images byte for byte.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::embedding::embed;
use crate::support::{output_dir, save_for_inspection};

pub(crate) const LAVAPIPE_ICD: &str = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";

pub(crate) fn workspace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// What a failed command printed, for the panic message.
pub(crate) fn printed(output: &Output) -> String {
    format!(
        "{}\n--- stdout ---\n{}\n--- stderr ---\n{}",
        output.status,
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    )
}

/// target/<profile>, where cargo puts libffvk_c.so: this binary is target/<profile>/deps/suite-….
pub(crate) fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test binary's path");
    let deps = exe.parent().expect("the test binary's directory");
    assert!(
        deps.file_name().is_some_and(|n| n == "deps"),
        "the test binary {} is not in a cargo deps directory",
        exe.display()
    );
    deps.parent().expect("target/<profile>").to_path_buf()
}

/// Builds libffvk_c.so in this test's profile, as an embedder builds it. `cargo test -p
/// ffvk-cli` builds ffvk-c only as a dependency, whose library stays in deps/ and is not
/// copied up to target/<profile>: without this, the example could link a stale one. A no-op
/// when fresh.
pub(crate) fn build_library(profile: &Path) {
    let mut cargo = Command::new(env!("CARGO"));
    cargo
        .current_dir(workspace())
        .args(["build", "--quiet", "-p", "ffvk-c", "--target-dir"])
        .arg(profile.parent().expect("the target directory"));
    match profile.file_name().and_then(|n| n.to_str()) {
        Some("debug") => {}
        Some(name) => {
            cargo.args(["--profile", name]);
        }
        None => panic!("no profile directory in {}", profile.display()),
    }
    let output = cargo.output().expect("cargo runs");
    assert!(
        output.status.success(),
        "cargo build -p ffvk-c failed: {}",
        printed(&output)
    );
    assert!(
        profile.join("libffvk_c.so").is_file(),
        "cargo build -p ffvk-c made no {}",
        profile.join("libffvk_c.so").display()
    );
}

/// `make -C ffvk-c/examples` against the library in `profile`; returns the program. The
/// binary goes next to the library, not into the source tree.
pub(crate) fn build_example(profile: &Path) -> PathBuf {
    // One make at a time: the tests that need the examples run in parallel, and two makes
    // installing the library into the same prefix at once race (`install: File exists`).
    static MAKE: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _one = MAKE.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let build_dir = profile.join("ffvk-c-examples");
    let output = Command::new("make")
        .arg("-C")
        .arg(workspace().join("ffvk-c/examples"))
        .arg(format!("FFVK_LIB_DIR={}", profile.display()))
        .arg(format!("BUILD_DIR={}", build_dir.display()))
        .output()
        .expect("make runs");
    assert!(
        output.status.success(),
        "make -C ffvk-c/examples failed (the C compiler's output follows): {}",
        printed(&output)
    );
    build_dir.join("teapot")
}

/// The RGB bytes of a binary PPM of `size`² pixels.
pub(crate) fn read_ppm(path: &Path, size: u32) -> Vec<u8> {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let header = format!("P6\n{size} {size}\n255\n");
    assert!(
        bytes.starts_with(header.as_bytes()),
        "{} does not start with the header {header:?}",
        path.display()
    );
    let rgb = bytes[header.len()..].to_vec();
    assert_eq!(
        rgb.len(),
        (size * size * 3) as usize,
        "{}: pixel bytes after the header",
        path.display()
    );
    rgb
}

/// None when equal, else the mode, how many bytes differ and the first differing pixel.
fn difference(mode: &str, rust_rgb: &[u8], c_rgb: &[u8], size: u32) -> Option<String> {
    let differing = rust_rgb.iter().zip(c_rgb).filter(|(a, b)| a != b).count();
    let first = rust_rgb
        .chunks(3)
        .zip(c_rgb.chunks(3))
        .position(|(a, b)| a != b)?;
    let (x, y) = (first as u32 % size, first as u32 / size);
    Some(format!(
        "{mode}: {differing} of {} bytes differ; first at pixel ({x}, {y}): {:?} from the Rust example, {:?} from the C example",
        rust_rgb.len(),
        &rust_rgb[first * 3..first * 3 + 3],
        &c_rgb[first * 3..first * 3 + 3],
    ))
}

#[test]
fn the_c_example_draws_the_teapot_in_every_mode_byte_identical_to_the_rust_example() {
    let profile = profile_dir();
    build_library(&profile);
    let teapot = build_example(&profile);

    let out = output_dir().join("c_api_example");
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).expect("tests/output is writable");
    let mut run = Command::new(&teapot);
    run.arg(&out)
        .env("FFVK_VALIDATION", "1")
        // The Rust example below draws on lavapipe: so must the C one.
        .env_remove("FFVK_DEVICE");
    if std::env::var_os("VK_DRIVER_FILES").is_none() {
        run.env("VK_DRIVER_FILES", LAVAPIPE_ICD);
    }
    let output = run.output().expect("the C example runs");
    assert!(
        output.status.success(),
        "{} failed (validation messages fail it too): {}",
        teapot.display(),
        printed(&output)
    );

    let rust_images =
        embed::render_modes(None, true).expect("the Rust embedding example renders with validation on");
    assert_eq!(rust_images.len(), 3, "the Rust example's modes");
    let size = embed::SIZE;
    let clear = embed::CLEAR.map(|c| (c * 255.0).round() as u8);
    let mut failures = Vec::new();
    for (mode, rgba) in rust_images {
        let rust_rgb: Vec<u8> = rgba.chunks(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
        let c_path = out.join(format!("teapot_{}.ppm", mode.name()));
        let c_rgb = read_ppm(&c_path, size);
        // Two blank images would agree too: the teapot covers the center.
        let center = ((size / 2 * size + size / 2) * 3) as usize;
        assert_ne!(
            c_rgb[center..center + 3],
            clear[..3],
            "{}: no teapot at the center",
            c_path.display()
        );
        if let Some(message) = difference(mode.name(), &rust_rgb, &c_rgb, size) {
            let image = image::RgbaImage::from_raw(size, size, rgba).expect("256 x 256 RGBA8");
            let saved = save_for_inspection(&image, &format!("c_api_example/rust_{}", mode.name()));
            failures.push(format!(
                "{message} (images: {} and {})",
                saved.display(),
                c_path.display()
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "the C example's images differ from the Rust example's:\n{}",
        failures.join("\n")
    );
}
