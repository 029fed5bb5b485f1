//! Generates the GL reference's bindings (`OUT_DIR/gl_bindings.rs`) with gl_generator: GL 2.1
//! in the compatibility profile (glLight, glMaterial, client arrays, ...) and the framebuffer
//! objects it renders into. GL_ARB_framebuffer_object names its functions without a suffix, as
//! GL 3.0 does, so they exist in Mesa's and NVIDIA's compatibility contexts (3.0 and later);
//! `Fallbacks::All` also tries the `EXT` names of GL_EXT_framebuffer_object for a driver that
//! has only those. GL_ARB_timer_query (core in 3.3) gives the bench GL's GPU time per frame.
//! Nothing is linked: the entry points are loaded through `eglGetProcAddress` at run time.

use std::fs;
use std::io::{BufWriter, Write};
use std::path::PathBuf;

use gl_generator::{Api, Fallbacks, Profile, Registry, StructGenerator};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let Some(out_dir) = std::env::var_os("OUT_DIR") else {
        eprintln!("OUT_DIR is not set: run this build script through cargo");
        std::process::exit(1);
    };
    let path = PathBuf::from(out_dir).join("gl_bindings.rs");
    if let Err(e) = write_gl_bindings(&path) {
        eprintln!("{}: {e}", path.display());
        std::process::exit(1);
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
