//! Generates the GL reference's bindings (`OUT_DIR/gl_bindings.rs`) with gl_generator: GL 2.1
//! in the compatibility profile (glLight, glMaterial, client arrays, ...) and the framebuffer
//! objects it renders into. GL_ARB_framebuffer_object names its functions without a suffix, as
//! GL 3.0 does, so they exist in Mesa's and NVIDIA's compatibility contexts (3.0 and later);
//! `Fallbacks::All` also tries the `EXT` names of GL_EXT_framebuffer_object for a driver that
//! has only those. GL_ARB_timer_query (core in 3.3) gives the bench GL's GPU time per frame.
//! Nothing is linked: the entry points are loaded through `eglGetProcAddress` at run time.
//!
//! It also compiles the bench floor's shaders (`glsl/floor/`, see `src/bench/floor/`) to
//! SPIR-V with shaderc's `glslc`, as ffvk's build script compiles ffvk's: one vertex stage per
//! data path (`PATH_<NAME>` defined) and the one fragment stage, into
//! `OUT_DIR/floor_<path>.vert.spv` and `OUT_DIR/floor.frag.spv`.

use std::fs;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::Command;

use gl_generator::{Api, Fallbacks, Profile, Registry, StructGenerator};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let Some(out_dir) = std::env::var_os("OUT_DIR") else {
        eprintln!("OUT_DIR is not set: run this build script through cargo");
        std::process::exit(1);
    };
    let out_dir = PathBuf::from(out_dir);
    let path = out_dir.join("gl_bindings.rs");
    if let Err(e) = write_gl_bindings(&path) {
        eprintln!("{}: {e}", path.display());
        std::process::exit(1);
    }
    if let Err(e) = compile_floor_shaders(&out_dir) {
        for line in e.lines() {
            println!("cargo:warning={line}");
        }
        eprintln!("{e}");
        std::process::exit(1);
    }
}

/// The floor's data paths: each a vertex stage compiled with `PATH_<NAME>=1`.
const FLOOR_PATHS: [&str; 4] = ["instance", "storage", "uniform", "push"];

/// Compiles `glsl/floor/floor.vert` once per data path and `glsl/floor/floor.frag` once.
fn compile_floor_shaders(out_dir: &Path) -> Result<(), String> {
    let Some(root) = std::env::var_os("CARGO_MANIFEST_DIR") else {
        return Err("CARGO_MANIFEST_DIR is not set: run this build script through cargo".into());
    };
    let dir = PathBuf::from(root).join("glsl").join("floor");
    // A directory is scanned recursively: any change to a source reruns this.
    println!("cargo:rerun-if-changed={}", dir.display());
    println!("cargo:rerun-if-env-changed=GLSLC");
    let glslc = std::env::var_os("GLSLC").map_or_else(|| PathBuf::from("glslc"), PathBuf::from);
    let mut errors = Vec::new();
    for path in FLOOR_PATHS {
        let define = format!("-DPATH_{}=1", path.to_uppercase());
        let spv = out_dir.join(format!("floor_{path}.vert.spv"));
        if let Err(e) = glsl(&glslc, &dir.join("floor.vert"), "vert", Some(&define), &spv) {
            errors.push(format!("floor path {path}: {e}"));
        }
    }
    if let Err(e) = glsl(
        &glslc,
        &dir.join("floor.frag"),
        "frag",
        None,
        &out_dir.join("floor.frag.spv"),
    ) {
        errors.push(format!("floor fragment stage: {e}"));
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors.join("\n"))
    }
}

/// Runs glslc on one stage source (its messages are already `file:line: error: text`).
fn glsl(glslc: &Path, source: &Path, stage: &str, define: Option<&str>, spv: &Path) -> Result<(), String> {
    let mut command = Command::new(glslc);
    command
        .arg(format!("-fshader-stage={stage}"))
        .arg("--target-env=vulkan1.3")
        .arg("-Werror");
    command.args(define);
    command.arg("-o").arg(spv).arg(source);
    let output = command.output().map_err(|e| {
        format!(
            "cannot run {}: {e}; install the Debian package glslc (shaderc's compiler) or set GLSLC",
            glslc.display()
        )
    })?;
    if output.status.success() {
        Ok(())
    } else {
        Err(format!(
            "{} ({}): {}",
            source.display(),
            output.status,
            String::from_utf8_lossy(&output.stderr).trim_end()
        ))
    }
}

fn write_gl_bindings(path: &std::path::Path) -> std::io::Result<()> {
    let registry = Registry::new(
        Api::Gl,
        (2, 1),
        Profile::Compatibility,
        Fallbacks::All,
        ["GL_ARB_framebuffer_object", "GL_ARB_timer_query"],
    );
    let mut file = BufWriter::new(fs::File::create(path)?);
    registry.write_bindings(StructGenerator, &mut file)?;
    file.flush()
}
