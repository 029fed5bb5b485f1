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
    };
    FfvkRendererCreateInfo info;
    FfvkDrawInfo draw;
    FfvkRaster raster;
    info.struct_size = (uint32_t)sizeof info;
    draw.struct_size = (uint32_t)sizeof draw;
    ffvkRasterDefaults(&raster);
    return (int)(sizeof fns / sizeof fns[0]) + (GL_LIGHT0 == 0x4000 ? 0 : 1) + (int)raster.depth_write;
}
"#;

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
