//! The C library installs as a system library (`make install-c`): libffvk_c.so.<version> with
//! the SONAME libffvk_c.so.<major> and its links, libffvk_c.a, ffvk.h and ffvk.pc; a C program
//! built with `pkg-config --cflags --libs ffvk` against a prefix the loader does not search
//! starts without LD_LIBRARY_PATH, and one linked with the static library and pkg-config's
//! `--static` libraries runs too.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::c_api_example::{build_library, printed, profile_dir, workspace};

/// A program of the C API that needs no device: GL's error and message for a cutoff of 91,
/// and the viewport of GL's lower-left quadrant.
const PROGRAM: &str = r#"
#include <ffvk.h>
#include <stdio.h>
#include <string.h>
int main(void) {
    FfvkContext *ctx = ffvkCreateContext();
    VkViewport viewport;
    if (!ctx) return 100;
    ffvkLightf(ctx, GL_LIGHT0, GL_SPOT_CUTOFF, 91.0f);
    if (ffvkGetError(ctx) != GL_INVALID_VALUE) { puts("cutoff 91 is not GL_INVALID_VALUE"); return 1; }
    if (!strstr(ffvkResultMessage(), "GL_SPOT_CUTOFF")) { puts(ffvkResultMessage()); return 2; }
    ffvkDestroyContext(ctx);
    if (ffvkViewport(0, 0, 32, 24, 48, 0.0, 1.0, &viewport) != FFVK_SUCCESS) { puts(ffvkResultMessage()); return 3; }
    printf("viewport %g %g %g %g\n", viewport.x, viewport.y, viewport.width, viewport.height);
    return 0;
}
"#;

/// ffvk-c's version, from its Cargo.toml.
fn ffvk_c_version() -> String {
    let manifest = std::fs::read_to_string(workspace().join("ffvk-c/Cargo.toml")).expect("ffvk-c/Cargo.toml");
    manifest
        .lines()
        .find_map(|l| l.strip_prefix("version = \""))
        .and_then(|v| v.strip_suffix('"'))
        .expect("a version line in ffvk-c/Cargo.toml")
        .to_string()
}

/// Runs `command` and returns its stdout, failing with everything it printed otherwise.
fn run(command: &mut Command, what: &str) -> String {
    let output = command.output().unwrap_or_else(|e| panic!("{what}: {e}"));
    assert!(output.status.success(), "{what} failed: {}", printed(&output));
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// `pkg-config ARGS ffvk` with `prefix`'s ffvk.pc first on the path, split into arguments.
fn pkg_config(prefix: &Path, args: &[&str]) -> Vec<String> {
    let out = run(
        Command::new("pkg-config")
            .env("PKG_CONFIG_PATH", prefix.join("lib/pkgconfig"))
            .args(args)
            .arg("ffvk"),
        &format!(
            "pkg-config {} ffvk (the Debian package pkg-config)",
            args.join(" ")
        ),
    );
    out.split_whitespace().map(String::from).collect()
}

/// `readelf -d`'s lines naming `tag` (SONAME, NEEDED, RUNPATH), their values in brackets.
fn dynamic(file: &Path, tag: &str) -> Vec<String> {
    let out = run(
        Command::new("readelf").arg("-d").arg(file),
        &format!("readelf -d {} (binutils)", file.display()),
    );
    out.lines()
        .filter(|l| l.contains(&format!("({tag})")))
        .filter_map(|l| Some(l.split_once('[')?.1.split_once(']')?.0.to_string()))
        .collect()
}

fn link_target(path: &Path) -> PathBuf {
    std::fs::read_link(path).unwrap_or_else(|e| panic!("{} is not a link: {e}", path.display()))
}

#[test]
fn the_installed_library_carries_its_major_version_and_a_pkg_config_program_starts_without_ld_library_path() {
    let profile = profile_dir();
    build_library(&profile);
    let prefix = profile.join("ffvk-c-install-test");
    let _ = std::fs::remove_dir_all(&prefix);
    run(
        Command::new("make")
            .arg("-C")
            .arg(workspace())
            .arg("--no-print-directory")
            .arg("install-c")
            .arg(format!("PREFIX={}", prefix.display()))
            .arg(format!("FFVK_C_LIB_DIR={}", profile.display())),
        "make install-c",
    );

    // The files and links of a versioned shared library.
    let version = ffvk_c_version();
    let major = version.split('.').next().expect("a major version");
    let lib = prefix.join("lib");
    let real = format!("libffvk_c.so.{version}");
    let soname = format!("libffvk_c.so.{major}");
    assert!(lib.join(&real).is_file(), "no {}", lib.join(&real).display());
    assert_eq!(link_target(&lib.join(&soname)), PathBuf::from(&real));
    assert_eq!(link_target(&lib.join("libffvk_c.so")), PathBuf::from(&soname));
    assert!(lib.join("libffvk_c.a").is_file(), "no static library");
    assert_eq!(
        std::fs::read(prefix.join("include/ffvk.h")).expect("the installed header"),
        std::fs::read(workspace().join("ffvk-c/include/ffvk.h")).expect("the header"),
        "the installed header is not ffvk-c/include/ffvk.h"
    );
    // The shader library beside it, each file as ffvk::shaders holds it.
    for file in ffvk::shaders::FILES {
        let installed = prefix.join("include").join(file.name);
        assert_eq!(
            std::fs::read_to_string(&installed).unwrap_or_else(|e| panic!("{}: {e}", installed.display())),
            file.source,
            "the installed {} is not the library's",
            file.name
        );
    }
    assert_eq!(dynamic(&lib.join(&real), "SONAME"), std::slice::from_ref(&soname));
    assert_eq!(
        pkg_config(&prefix, &["--modversion"]),
        std::slice::from_ref(&version)
    );

    // A program built as docs/c-api.md builds one: pkg-config's flags alone, no environment.
    let dir = profile.join("ffvk-c-install-program");
    std::fs::create_dir_all(&dir).expect("a directory for the program");
    let source = dir.join("program.c");
    std::fs::write(&source, PROGRAM).expect("the program's source");
    let shared = dir.join("program-shared");
    run(
        Command::new("cc")
            .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-o"])
            .arg(&shared)
            .arg(&source)
            .args(pkg_config(&prefix, &["--cflags", "--libs"])),
        "cc program.c $(pkg-config --cflags --libs ffvk)",
    );
    assert!(
        dynamic(&shared, "NEEDED").contains(&soname),
        "the program does not ask for {soname}"
    );
    assert_eq!(
        dynamic(&shared, "RUNPATH"),
        [lib.display().to_string()],
        "ffvk.pc gives a prefix the loader does not search an rpath"
    );
    let out = run(
        Command::new(&shared).env_remove("LD_LIBRARY_PATH"),
        "the program linked with the shared library",
    );
    assert_eq!(out.trim(), "viewport 0 24 32 24");

    // The static library with pkg-config's --static libraries: no libffvk_c.so needed.
    let libs: Vec<String> = pkg_config(&prefix, &["--static", "--libs-only-l"])
        .into_iter()
        .filter(|l| l != "-lffvk_c")
        .collect();
    let fixed = dir.join("program-static");
    run(
        Command::new("cc")
            .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-o"])
            .arg(&fixed)
            .arg(&source)
            .args(pkg_config(&prefix, &["--cflags"]))
            .arg(lib.join("libffvk_c.a"))
            .args(&libs),
        "cc program.c libffvk_c.a $(pkg-config --static --libs-only-l ffvk)",
    );
    assert!(
        !dynamic(&fixed, "NEEDED")
            .iter()
            .any(|n| n.starts_with("libffvk_c")),
        "the statically linked program still needs libffvk_c.so"
    );
    let out = run(
        Command::new(&fixed).env_remove("LD_LIBRARY_PATH"),
        "the program linked with the static library",
    );
    assert_eq!(out.trim(), "viewport 0 24 32 24");
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&prefix);
}
