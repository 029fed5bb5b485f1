//! Compiles every shader stage under `glsl/` to SPIR-V with shaderc (glslang).
//!
//! Stage files are `*.vert` and `*.frag`; `*.glsl` files are only included. `#include "x"`
//! resolves relative to the including file. SPIR-V lands in `OUT_DIR/<name>.spv`, and
//! `OUT_DIR/shaders.rs` lists them for `include_bytes!`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::{env, fs};

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let glsl_dir = manifest.join("glsl");
    let out_dir = PathBuf::from(env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    println!("cargo:rerun-if-changed={}", glsl_dir.display());

    let mut sources: Vec<PathBuf> = match fs::read_dir(&glsl_dir) {
        Ok(dir) => dir.filter_map(|e| e.ok().map(|e| e.path())).collect(),
        Err(e) => fail(&format!(
            "{}: cannot read the shader directory: {e}",
            glsl_dir.display()
        )),
    };
    sources.sort();

    let compiler = shaderc::Compiler::new().unwrap_or_else(|e| fail(&format!("shaderc: {e}")));
    let mut table = String::from(
        "/// Every compiled stage: (file name, SPIR-V bytes).\npub const SHADERS: &[(&str, &[u8])] = &[\n",
    );
    let mut errors = Vec::new();

    for path in &sources {
        println!("cargo:rerun-if-changed={}", path.display());
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        let kind = match ext {
            "vert" => shaderc::ShaderKind::Vertex,
            "frag" => shaderc::ShaderKind::Fragment,
            _ => continue,
        };
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default()
            .to_owned();
        let source = match fs::read_to_string(path) {
            Ok(s) => s,
            Err(e) => fail(&format!("{}: {e}", path.display())),
        };
        let mut options =
            shaderc::CompileOptions::new().unwrap_or_else(|e| fail(&format!("shaderc options: {e}")));
        options.set_target_env(shaderc::TargetEnv::Vulkan, shaderc::EnvVersion::Vulkan1_3 as u32);
        // No spirv-opt: Debian's SPIRV-Tools 2023.1 rejects glslang 12's copies of std140
        // structs into locals ("OpStore Pointer type does not match"). The driver optimizes
        // the SPIR-V itself (Mesa's NIR), so nothing is lost at run time.
        options.set_optimization_level(shaderc::OptimizationLevel::Zero);
        options.set_warnings_as_errors();
        options.set_include_callback(|requested, _ty, requester, _depth| include(requested, requester));

        match compiler.compile_into_spirv(&source, kind, &path.to_string_lossy(), "main", Some(&options)) {
            Ok(artifact) => {
                let spv = out_dir.join(format!("{name}.spv"));
                if let Err(e) = fs::write(&spv, artifact.as_binary_u8()) {
                    fail(&format!("{}: {e}", spv.display()));
                }
                writeln!(
                    table,
                    "    ({name:?}, include_bytes!({:?})),",
                    spv.display().to_string()
                )
                .unwrap();
            }
            Err(e) => errors.push(e.to_string()),
        }
    }
    if !errors.is_empty() {
        // glslang already formats its messages as `file:line: error: ...`.
        fail(&errors.join("\n"));
    }
    table.push_str("];\n");
    if let Err(e) = fs::write(out_dir.join("shaders.rs"), table) {
        fail(&format!("shaders.rs: {e}"));
    }
}

/// Resolves `#include "requested"` relative to the directory of the including file.
fn include(requested: &str, requester: &str) -> Result<shaderc::ResolvedInclude, String> {
    let base = Path::new(requester).parent().unwrap_or(Path::new("."));
    let path = base.join(requested);
    println!("cargo:rerun-if-changed={}", path.display());
    match fs::read_to_string(&path) {
        Ok(content) => Ok(shaderc::ResolvedInclude {
            resolved_name: path.to_string_lossy().into_owned(),
            content,
        }),
        Err(e) => Err(format!("{}: {e}", path.display())),
    }
}

fn fail(message: &str) -> ! {
    for line in message.lines() {
        println!("cargo:warning={line}");
    }
    eprintln!("{message}");
    std::process::exit(1);
}
