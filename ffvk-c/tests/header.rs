//! `include/ffvk.h` is generated from this crate's source by cbindgen: this test generates it
//! and fails when the checked-in copy differs (run with `FFVK_BLESS_HEADER=1` to rewrite it),
//! then compiles it as C99 and as C++ with `-Wall -Wextra -Werror -pedantic`.

use std::path::{Path, PathBuf};
use std::process::Command;

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The header as cbindgen makes it now.
fn generate() -> String {
    let dir = crate_dir();
    let mut config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut enums = String::from("\n/* GL's values for the enums this API takes and returns. */\n");
    for (name, value) in ffvk_c::enums::gl_enums() {
        enums.push_str(&format!("#ifndef {name}\n#define {name} 0x{value:04X}\n#endif\n"));
    }
    config.after_includes = Some(enums);
    let mut out = Vec::new();
    cbindgen::Builder::new()
        .with_crate(&dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header")
        .write(&mut out);
    String::from_utf8(out).expect("UTF-8 header")
}

#[test]
fn the_checked_in_header_is_what_cbindgen_generates_from_the_source() {
    let path = crate_dir().join("include/ffvk.h");
    let fresh = generate();
    if std::env::var_os("FFVK_BLESS_HEADER").is_some() {
        std::fs::write(&path, &fresh).expect("write include/ffvk.h");
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        checked_in == fresh,
        "{} is stale: regenerate it with `FFVK_BLESS_HEADER=1 cargo test -p ffvk-c --test header` and commit it",
        path.display()
    );
}

fn compile(compiler: &str, args: &[&str], source: &Path) {
    let include = crate_dir().join("include");
    let out = std::env::temp_dir().join(format!("ffvk-header-{}-{compiler}.o", std::process::id()));
    let output = Command::new(compiler)
        .args(args)
        .args(["-Wall", "-Wextra", "-Werror", "-pedantic", "-c", "-o"])
        .arg(&out)
        .arg("-I")
        .arg(&include)
        .arg(source)
        .output()
        .unwrap_or_else(|e| panic!("{compiler}: {e}"));
    let _ = std::fs::remove_file(&out);
    assert!(
        output.status.success(),
        "{compiler} {args:?} failed on ffvk.h:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// Every function of the header taken by address, and its types used, so that a declaration
/// the compiler rejects cannot hide.
const USE_HEADER: &str = r#"
#include <ffvk.h>
#include <GL/gl.h>
int main(void) {
    typedef void (*fn)(void);
    fn fns[] = {
        (fn)&ffvkCreateContext, (fn)&ffvkDestroyContext, (fn)&ffvkGetError,
        (fn)&ffvkEnable, (fn)&ffvkLightfv, (fn)&ffvkGetMaterialfv, (fn)&ffvkGetBooleanv,
        (fn)&ffvkCreateRenderer, (fn)&ffvkDraw, (fn)&ffvkEndDraws, (fn)&ffvkCreateTexture,
        (fn)&ffvkResultMessage, (fn)&ffvkPrimitiveIndices, (fn)&ffvkCreateTeapot,
        (fn)&ffvkPrimitiveIndicesRange, (fn)&ffvkViewport, (fn)&ffvkScissor,
        (fn)&ffvkDeviceRequirements, (fn)&ffvkActiveTexture, (fn)&ffvkMultiTexCoord4fv,
    };
    FfvkRendererCreateInfo info;
    FfvkDrawInfo draw;
    FfvkRaster raster;
    info.struct_size = (uint32_t)sizeof info;
    draw.struct_size = (uint32_t)sizeof draw;
    draw.texture1 = NULL;
    ffvkRasterDefaults(&raster);
    return (int)(sizeof fns / sizeof fns[0]) + (GL_LIGHT0 == 0x4000 ? 0 : 1) + (int)raster.depth_write;
}
"#;

/// A C program of the state API alone: GL's error for a cutoff of 91, the position in eye
/// space after a translated modelview, the first error sticking.
const STATE_PROGRAM: &str = r#"
#include <ffvk.h>
#include <stdio.h>
int main(void) {
    static const float translate[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1};
    const float position[4] = {0, 0, 1, 1};
    float eye[4] = {0, 0, 0, 0};
    int failures = 0;
    FfvkContext *ctx = ffvkCreateContext();
    if (!ctx) return 100;
    ffvkLightf(ctx, GL_LIGHT0, GL_SPOT_CUTOFF, 91.0f);
    ffvkEnable(ctx, 0x1234);
    if (ffvkGetError(ctx) != GL_INVALID_VALUE) { puts("cutoff 91 is not GL_INVALID_VALUE"); failures++; }
    if (ffvkGetError(ctx) != GL_NO_ERROR) { puts("the second error stuck"); failures++; }
    ffvkLoadModelview(ctx, translate);
    ffvkLightfv(ctx, GL_LIGHT0, GL_POSITION, position);
    ffvkGetLightfv(ctx, GL_LIGHT0, GL_POSITION, eye);
    if (eye[0] != 1 || eye[1] != 2 || eye[2] != 4 || eye[3] != 1) { puts("position not in eye space"); failures++; }
    ffvkDestroyContext(ctx);
    return failures;
}
"#;

/// target/<profile> with the library an embedder gets: `cargo build -p ffvk-c` there. The
/// workspace's own build of this crate unifies ffvk's features with the command's (images,
/// scene: C++ objects that need libstdc++), so the test builds the lean library itself (a no-op
/// when it is fresh).
fn lean_library_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test's path");
    // target/<profile>/deps/header-<hash>
    let profile = exe
        .parent()
        .and_then(Path::parent)
        .expect("target/<profile>")
        .to_path_buf();
    let mut cargo = Command::new(env!("CARGO"));
    cargo
        .current_dir(crate_dir())
        .args(["build", "--quiet", "-p", "ffvk-c", "--target-dir"])
        .arg(profile.parent().expect("the target directory"));
    match profile.file_name().and_then(|n| n.to_str()) {
        Some("debug") | None => {}
        Some(name) => {
            cargo.args(["--profile", name]);
        }
    }
    let output = cargo.output().expect("cargo runs");
    assert!(
        output.status.success(),
        "cargo build -p ffvk-c failed:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    profile
}

#[test]
fn a_c_program_links_the_static_and_the_shared_library_and_gets_gls_errors_and_eye_space() {
    let dir = std::env::temp_dir().join(format!("ffvk-link-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let source = dir.join("state.c");
    std::fs::write(&source, STATE_PROGRAM).unwrap();
    let lib = lean_library_dir();
    // The shared library's SONAME is libffvk_c.so.<major>, the name an installed copy has
    // (`make install-c`): the program finds it here, a link to cargo's libffvk_c.so.
    let runtime = dir.join("runtime");
    std::fs::create_dir_all(&runtime).unwrap();
    let soname = format!("libffvk_c.so.{}", env!("CARGO_PKG_VERSION_MAJOR"));
    let _ = std::fs::remove_file(runtime.join(&soname));
    std::os::unix::fs::symlink(lib.join("libffvk_c.so"), runtime.join(&soname)).unwrap();
    for (kind, link) in [
        (
            "static",
            vec![
                lib.join("libffvk_c.a").display().to_string(),
                "-lm".into(),
                "-ldl".into(),
                "-lpthread".into(),
            ],
        ),
        (
            "shared",
            vec![
                format!("-L{}", lib.display()),
                format!("-Wl,-rpath,{}", runtime.display()),
                "-lffvk_c".into(),
            ],
        ),
    ] {
        let exe = dir.join(format!("state-{kind}"));
        let output = Command::new("cc")
            .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-o"])
            .arg(&exe)
            .arg("-I")
            .arg(crate_dir().join("include"))
            .arg(&source)
            .args(&link)
            .output()
            .expect("cc");
        assert!(
            output.status.success(),
            "linking the {kind} library failed:\n{}",
            String::from_utf8_lossy(&output.stderr)
        );
        let run = Command::new(&exe)
            .env_remove("LD_LIBRARY_PATH")
            .output()
            .expect("the C program runs");
        assert!(
            run.status.success(),
            "the C program linked with the {kind} library failed ({}):\n{}",
            run.status,
            String::from_utf8_lossy(&run.stdout)
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_header_compiles_as_c99_and_as_cpp_with_every_warning_an_error() {
    let dir = std::env::temp_dir().join(format!("ffvk-header-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let c = dir.join("use.c");
    let cpp = dir.join("use.cpp");
    std::fs::write(&c, USE_HEADER).unwrap();
    std::fs::write(&cpp, USE_HEADER).unwrap();
    compile("cc", &["-std=c99"], &c);
    compile("c++", &["-std=c++11"], &cpp);
    let _ = std::fs::remove_dir_all(&dir);
}
