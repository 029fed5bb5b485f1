//! Compiles the shader variants under `glsl/` to SPIR-V with shaderc's compiler, `glslc`
//! (glslang inside; Debian package `glslc`).
//!
//! A variant is a lighting mode's pair of stage sources compiled with its own macro
//! definitions (the table below), so no variant needs a file of its own. `#include "x"`
//! resolves relative to the including file. SPIR-V lands in `OUT_DIR/<variant>.<stage>.spv`,
//! and `OUT_DIR/shaders.rs` lists every variant for `include_bytes!`.
//!
//! glslc runs as a program rather than through shaderc's Rust bindings: Debian's
//! `libshaderc.so.1` is underlinked, and the link override that worked around it lived in this
//! repository's `.cargo/config.toml`, which Cargo ignores when ffvk is another crate's
//! dependency. A program needs no linking, so ffvk builds the same from any workspace.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::{env, fs};

/// One pipeline variant: its name (a lighting mode, optionally with a suffix), the stage
/// sources and the macros both stages are compiled with.
struct Variant {
    name: &'static str,
    vertex: &'static str,
    fragment: &'static str,
    defines: &'static [(&'static str, &'static str)],
    doc: &'static str,
}

/// `INTERP`: the interpolation qualifier of the per-vertex colors. `ONE_COLOR`: only the front
/// primary color passes between the stages (specialized one-sided, single-color states).
/// A layout without a color (normal, texture coordinate) array needs no variant of its own: the
/// pipeline's vertex input reads GL's current value from the draw record at that location.
const VARIANTS: &[Variant] = &[
    Variant {
        name: "vertex",
        vertex: "vertex.vert",
        fragment: "vertex.frag",
        defines: &[("INTERP", "smooth")],
        doc: "Lit at each vertex; four colors interpolated (GL's SMOOTH shading).",
    },
    Variant {
        name: "vertex_one_color",
        vertex: "vertex.vert",
        fragment: "vertex.frag",
        defines: &[("INTERP", "smooth"), ("ONE_COLOR", "1")],
        doc: "`vertex` with only the front primary color between the stages.",
    },
    Variant {
        name: "flat",
        vertex: "vertex.vert",
        fragment: "vertex.frag",
        defines: &[("INTERP", "flat")],
        doc: "Lit at each vertex; the provoking (last) vertex's colors (GL's FLAT shading).",
    },
    Variant {
        name: "flat_one_color",
        vertex: "vertex.vert",
        fragment: "vertex.frag",
        defines: &[("INTERP", "flat"), ("ONE_COLOR", "1")],
        doc: "`flat` with only the front primary color between the stages.",
    },
    Variant {
        name: "fragment",
        vertex: "fragment.vert",
        fragment: "fragment.frag",
        defines: &[],
        doc: "Eye-space position and normal interpolated; lit at each fragment; the materials read from the draw's record as a uniform block.",
    },
    Variant {
        name: "fragment_small",
        vertex: "fragment.vert",
        fragment: "fragment.frag",
        defines: &[("VARYING_MATERIALS", "1")],
        doc: "`fragment` for small draws: the materials pass from the vertex stage as flat varyings, so consecutive draws bind nothing of their own.",
    },
    Variant {
        name: "fragment_gbuffer",
        vertex: "fragment.vert",
        fragment: "fragment.frag",
        defines: &[("GBUFFER", "1")],
        doc: "The deferred path's first pass: what `fragment` lights at each fragment, written to the G-buffer instead.",
    },
    Variant {
        name: "deferred",
        vertex: "deferred.vert",
        fragment: "deferred.frag",
        defines: &[],
        doc: "The deferred path's lighting pass: the equation once per pixel from the G-buffer.",
    },
    Variant {
        name: "deferred_counted",
        vertex: "deferred.vert",
        fragment: "deferred.frag",
        defines: &[("COUNT", "1")],
        doc: "`deferred` counting the pixels it lights in a storage buffer (measured frames).",
    },
];

/// The build with GL's user clip planes of each variant whose vertex stage is a drawing one,
/// named `<variant>_clipped`: `gl_ClipDistance[6]` written (the device's `shaderClipDistance`
/// needed, which pipelines without clip planes do not ask for).
const CLIP_PLANES: (&str, &str) = ("CLIP_PLANES", "1");

/// The build with fog of each of those, named `<variant>_fog` (before `_clipped`): the fog
/// varying passed between the stages, which pipelines without fog do without.
const FOG: (&str, &str) = ("FOG", "1");

/// The variants with `_fog` and `_clipped` builds.
const CLIPPED: [&str; 6] = [
    "vertex",
    "vertex_one_color",
    "flat",
    "flat_one_color",
    "fragment",
    "fragment_small",
];

/// The textured build of each of those, named `<…>_textured`: texture coordinates at
/// location 3, the texture environment before the color sum (`glsl/texture.glsl`).
/// Untextured draws keep the variants without it, unchanged.
const TEXTURE: (&str, &str) = ("TEXTURE", "1");

/// The variants with an `_edges` build of each of their builds (`<…>_edges`, last): GL's edge
/// flags for polygons drawn as lines or points, a geometry stage (`glsl/edges.geom`) between
/// the two, reading the draw's triangles with adjacency (`glsl/edges.glsl`). The per-vertex
/// modes' `_one_color` builds have none: such draws take the build with all four colors.
const EDGES: [&str; 4] = ["vertex", "flat", "fragment", "fragment_small"];
const EDGE_FLAGS: (&str, &str) = ("EDGE_FLAGS", "1");
/// The geometry stage's varyings are the fragment mode's (fragment.vert) rather than the
/// per-vertex modes' (vertex.vert).
const EDGES_OF_FRAGMENT_MODE: (&str, &str) = ("EDGES_OF_FRAGMENT_MODE", "1");

fn main() {
    let cargo_dir = |name: &str| match env::var_os(name) {
        Some(dir) => PathBuf::from(dir),
        None => fail(&format!("{name} is not set: run this build script through cargo")),
    };
    let glsl_dir = cargo_dir("CARGO_MANIFEST_DIR").join("glsl");
    let out_dir = cargo_dir("OUT_DIR");
    // A directory is scanned recursively: any change to a source or an include reruns this.
    println!("cargo:rerun-if-changed={}", glsl_dir.display());
    println!("cargo:rerun-if-env-changed=GLSLC");
    let glslc = env::var_os("GLSLC").map_or_else(|| PathBuf::from("glslc"), PathBuf::from);

    let mut table = String::new();
    let mut errors = Vec::new();
    let builds = VARIANTS.iter().flat_map(|v| {
        let mut bases = vec![(v.name.to_string(), v.doc.to_string(), v.defines.to_vec())];
        if CLIPPED.contains(&v.name) {
            for (fog, clip) in [(true, false), (false, true), (true, true)] {
                let mut defines = v.defines.to_vec();
                let (mut name, mut doc) = (v.name.to_string(), v.doc.to_string());
                if fog {
                    defines.push(FOG);
                    name.push_str("_fog");
                    doc.push_str(" With fog.");
                }
                if clip {
                    defines.push(CLIP_PLANES);
                    name.push_str("_clipped");
                    doc.push_str(" With GL's user clip planes.");
                }
                bases.push((name, doc, defines));
            }
        }
        bases.into_iter().flat_map(move |(name, doc, defines)| {
            let mut textured = defines.clone();
            textured.push(TEXTURE);
            let builds = [
                (name.clone(), doc.clone(), defines),
                (
                    format!("{name}_textured"),
                    format!("{doc} Textured: the texture environment before the color sum."),
                    textured,
                ),
            ];
            builds.into_iter().flat_map(move |(name, doc, defines)| {
                let mut all = vec![(v, name.clone(), doc.clone(), defines.clone(), false)];
                if EDGES.contains(&v.name) {
                    let mut edged = defines;
                    edged.push(EDGE_FLAGS);
                    if v.vertex == "fragment.vert" {
                        edged.push(EDGES_OF_FRAGMENT_MODE);
                    }
                    all.push((
                        v,
                        format!("{name}_edges"),
                        format!("{doc} With GL's edge flags (a geometry stage)."),
                        edged,
                        true,
                    ));
                }
                all
            })
        })
    });
    for (variant, name, doc, defines, edges) in builds {
        let mut stages = Vec::new();
        let mut sources = vec![(variant.vertex, "vert"), (variant.fragment, "frag")];
        if edges {
            sources.push(("edges.geom", "geom"));
        }
        for (source, stage) in sources {
            let spv = out_dir.join(format!("{name}.{stage}.spv"));
            match compile(&glslc, &glsl_dir.join(source), stage, &defines, &spv) {
                Ok(()) => stages.push(spv),
                Err(e) => errors.push(format!("variant {name}: {e}")),
            }
        }
        let (vertex, fragment, geometry) = match stages.as_slice() {
            [v, f] => (v, f, None),
            [v, f, g] => (v, f, Some(g)),
            _ => continue,
        };
        let geometry = match geometry {
            Some(g) => format!("Some(include_bytes!({:?}))", g.display().to_string()),
            None => "None".to_owned(),
        };
        // Writing to a String cannot fail.
        let _ = writeln!(
            table,
            "    ShaderVariant {{\n        name: {:?},\n        doc: {:?},\n        \
             vertex_source: {:?},\n        fragment_source: {:?},\n        \
             defines: &{:?},\n        \
             vertex: include_bytes!({:?}),\n        fragment: include_bytes!({:?}),\n        \
             geometry: {},\n    }},",
            name,
            doc,
            variant.vertex,
            variant.fragment,
            defines,
            vertex.display().to_string(),
            fragment.display().to_string(),
            geometry,
        );
    }
    if !errors.is_empty() {
        fail(&errors.join("\n"));
    }
    let generated = format!(
        "/// Every compiled variant, in build order.\npub const VARIANTS: &[ShaderVariant] = &[\n{table}];\n"
    );
    if let Err(e) = fs::write(out_dir.join("shaders.rs"), generated) {
        fail(&format!("{}: {e}", out_dir.join("shaders.rs").display()));
    }
}

/// Runs glslc on one stage source. Its messages are already `file:line: error: text`.
fn compile(
    glslc: &Path,
    source: &Path,
    stage: &str,
    defines: &[(&str, &str)],
    spv: &Path,
) -> Result<(), String> {
    let mut command = Command::new(glslc);
    command
        .arg(format!("-fshader-stage={stage}"))
        .arg("--target-env=vulkan1.3")
        // No spirv-opt: Debian's SPIRV-Tools 2023.1 rejects glslang 12's copies of std140
        // structs into locals ("OpStore Pointer type does not match"). The driver optimizes
        // the SPIR-V itself (Mesa's NIR), so nothing is lost at run time.
        .arg("-O0")
        .arg("-Werror")
        // The shader library's files (`glsl/lib/ffvk/`), included as "ffvk/....glsl".
        .arg("-I")
        .arg(source.parent().unwrap_or(Path::new(".")).join("lib"));
    for (name, value) in defines {
        command.arg(format!("-D{name}={value}"));
    }
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
        let stderr = String::from_utf8_lossy(&output.stderr);
        Err(format!(
            "{} ({}): {}",
            source.display(),
            output.status,
            stderr.trim_end()
        ))
    }
}

fn fail(message: &str) -> ! {
    for line in message.lines() {
        println!("cargo:warning={line}");
    }
    eprintln!("{message}");
    std::process::exit(1);
}
