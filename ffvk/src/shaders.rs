//! ffvk's shader library: GL 2.1's lighting equation and the fixed-function stages around it
//! (texture environments and `GL_COMBINE`, texgen, fog, the alpha test, points, clip planes) as
//! GLSL include files a caller's own shaders include, the same files ffvk's own pipelines are
//! built from. Each file is `#include "ffvk/<name>"`; [`include()`] resolves those names for a
//! compiler's include callback (shaderc's, glslang's), and [`resolve`] inlines them for
//! compilers without `#include` (GLSL ES).
//!
//! What a caller defines before including the files, the interface of
//! [`LIBRARY_VERSION`]:
//! - the state block, declared with the library's members where the caller chooses and named
//!   by `FFVK_STATE`:
//!   `layout(std140, set = 3, binding = 0) uniform FfvkState { FFVK_STATE_MEMBERS } ffvk_state;`
//!   then `#define FFVK_STATE ffvk_state` (after `ffvk/state.glsl`, before the others); its
//!   bytes are [`StateBlock`](crate::gpu::layout::StateBlock)'s;
//! - `FFVK_SPEC_BASE`, the first of the library's specialization constant IDs (0 by default;
//!   [`SpecConstant::id`](crate::gpu::layout::SpecConstant::id) plus the base), so that they
//!   never collide with the caller's own;
//! - `FFVK_HIDDEN_ZERO`, a `uint` expression that is 0 but that the compiler cannot prove 0
//!   (`uint(gl_VertexIndex < 0)`, `uint(gl_FragCoord.x < 0.0)`): the uber-shader's switches
//!   pass through it, which keeps lavapipe from compiling a shader variant per draw when a
//!   branch would test uniform values alone;
//! - for `ffvk/texture.glsl`, `FFVK_TEXEL_2D(i, st)` and `FFVK_TEXEL_CUBE(i, str)`: unit i's
//!   filtered RGBA texel from the caller's samplers.

use std::collections::HashSet;

/// The library's interface version (`FFVK_LIBRARY_VERSION` in `ffvk/state.glsl`): a change of
/// the state block's layout, of a function's inputs or outputs, of a specialization constant's
/// meaning or ID, or of what the caller must define is a new version.
pub const LIBRARY_VERSION: u32 = 2;

/// One file of the library.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct LibraryFile {
    /// The name a shader includes it by: `ffvk/lighting.glsl`.
    pub name: &'static str,
    /// Its GLSL.
    pub source: &'static str,
    /// What it holds, in one sentence.
    pub doc: &'static str,
}

macro_rules! library_file {
    ($name:literal, $doc:literal) => {
        LibraryFile {
            name: concat!("ffvk/", $name),
            source: include_str!(concat!("../glsl/lib/ffvk/", $name)),
            doc: $doc,
        }
    };
}

/// Every file of the library, each after the files it includes.
pub const FILES: &[LibraryFile] = &[
    library_file!(
        "state.glsl",
        "The state's structs, its enumerated values and FFVK_STATE_MEMBERS; the version."
    ),
    library_file!(
        "spec.glsl",
        "The specialization constants, at FFVK_SPEC_BASE + their IDs."
    ),
    library_file!(
        "switches.glsl",
        "The state's switches: a constant where specialized, else the block's member."
    ),
    library_file!(
        "stages.glsl",
        "The alpha test, fog, the point size and the user clip planes."
    ),
    library_file!(
        "material.glsl",
        "One face's material with COLOR_MATERIAL applied."
    ),
    library_file!("normal.glsl", "The eye-space normal (section 2.11.3)."),
    library_file!(
        "lighting.glsl",
        "The lighting equation (section 2.14.1) and the color sum."
    ),
    library_file!(
        "texgen.glsl",
        "Texture coordinate generation (section 2.11.4) for every unit."
    ),
    library_file!(
        "texture.glsl",
        "The texture environments, GL_COMBINE and the units in order (section 3.8.13-16)."
    ),
    library_file!(
        "es.glsl",
        "The declaration header for GLSL ES 3.00: precision, no loop attributes; included first."
    ),
];

/// The lines that make the library's switches plain constants of `key`'s values, for a
/// shader compiled without specialization constants (GLSL ES, or one compile per state):
/// `#define FFVK_SPEC_AS_DEFINES` and `#define <name> <value>` for each constant (negative
/// values in parentheses),
/// to put before `#include "ffvk/spec.glsl"`. Every value is the key's: the pipeline's own
/// constants (the points', the layout's conversions, the target's alpha bits, the textured
/// units), which [`SpecKey::for_state`](crate::gpu::layout::SpecKey::for_state) leaves at 0,
/// are the caller's to set first, as ffvk sets them for each of its pipelines
/// ([`SpecKey::for_pipeline`](crate::gpu::layout::SpecKey::for_pipeline) sets them).
pub fn spec_defines(key: &crate::gpu::layout::SpecKey) -> String {
    use crate::gpu::layout::SpecConstant;
    let mut out = String::from("#define FFVK_SPEC_AS_DEFINES\n");
    for c in SpecConstant::ALL {
        let value = key.get(c);
        let text = if c.is_float() {
            // `{:?}` writes a float GLSL reads back exactly ("1.0", "3.4028235e38").
            format!("{:?}", f32::from_bits(value as u32))
        } else {
            value.to_string()
        };
        // A negative value in parentheses: `x - SPEC_...` stays a subtraction of it.
        let text = if text.starts_with('-') {
            format!("({text})")
        } else {
            text
        };
        out.push_str(&format!("#define {} {text}\n", c.glsl_name()));
    }
    out
}

/// The library's file `name` (`ffvk/lighting.glsl`), or `None` where there is none.
pub fn file(name: &str) -> Option<&'static LibraryFile> {
    FILES.iter().find(|f| f.name == name)
}

/// An include callback's answer for `requested` (the name in `#include "..."`): the library's
/// file of that name, or `None` for a name outside `ffvk/`, which the caller resolves itself.
pub fn include(requested: &str) -> Option<(&'static str, &'static str)> {
    file(requested).map(|f| (f.name, f.source))
}

/// Why [`resolve`] could not inline a shader's includes.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum LibraryError {
    /// `#include "ffvk/..."` names no file of the library.
    #[error(
        "line {line}: #include \"{name}\": the shader library has no such file (expected one of {expected})"
    )]
    UnknownFile {
        /// The line of the directive, from 1.
        line: usize,
        /// The name it includes.
        name: String,
        /// The library's names, comma-separated.
        expected: String,
    },
    /// An `#include` directive that is not `#include "name"`.
    #[error("line {line}: {directive:?}: expected #include \"ffvk/<file>.glsl\"")]
    Malformed {
        /// The line of the directive, from 1.
        line: usize,
        /// The directive as written.
        directive: String,
    },
}

/// `source` with each `#include "ffvk/..."` replaced by the library file's text (its own
/// includes inlined the same way; each file once, as its include guard would keep it), for
/// compilers without `#include` (GLSL ES). Other `#include` lines are left as they are.
pub fn resolve(source: &str) -> Result<String, LibraryError> {
    let mut out = String::with_capacity(source.len() * 4);
    let mut seen = HashSet::new();
    inline(source, &mut out, &mut seen)?;
    Ok(out)
}

fn inline(source: &str, out: &mut String, seen: &mut HashSet<&'static str>) -> Result<(), LibraryError> {
    for (index, text) in source.lines().enumerate() {
        let line = index + 1;
        let Some(rest) = text.trim_start().strip_prefix("#include") else {
            out.push_str(text);
            out.push('\n');
            continue;
        };
        let malformed = || LibraryError::Malformed {
            line,
            directive: text.trim().to_string(),
        };
        let name = rest
            .trim()
            .strip_prefix('"')
            .and_then(|r| r.split_once('"'))
            .map(|(name, _)| name)
            .ok_or_else(malformed)?;
        if !name.starts_with("ffvk/") {
            out.push_str(text);
            out.push('\n');
            continue;
        }
        let f = file(name).ok_or_else(|| LibraryError::UnknownFile {
            line,
            name: name.to_string(),
            expected: FILES.iter().map(|f| f.name).collect::<Vec<_>>().join(", "),
        })?;
        if seen.insert(f.name) {
            inline(f.source, out, seen)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_library_version_is_the_one_its_glsl_names() {
        let state = file("ffvk/state.glsl").unwrap().source;
        assert!(
            state.contains(&format!("#define FFVK_LIBRARY_VERSION {LIBRARY_VERSION}\n")),
            "ffvk/state.glsl names another version"
        );
        let spec = file("ffvk/spec.glsl").unwrap().source;
        let count = crate::gpu::layout::SPEC_CONSTANT_COUNT;
        assert!(spec.contains(&format!("#define FFVK_SPEC_COUNT {count}\n")));
    }

    #[test]
    fn every_file_includes_only_files_listed_before_it() {
        for (i, f) in FILES.iter().enumerate() {
            for line in f.source.lines().filter(|l| l.starts_with("#include")) {
                let name = line.split('"').nth(1).unwrap();
                let at = FILES.iter().position(|g| g.name == name);
                assert!(at.is_some_and(|at| at < i), "{} includes {name}", f.name);
            }
        }
    }

    #[test]
    fn resolving_inlines_each_library_file_once_and_keeps_other_includes() {
        let text = "#version 310 es\n#include \"ffvk/lighting.glsl\"\n#include \"ffvk/state.glsl\"\n#include \"mine.glsl\"\nvoid main() {}\n";
        let out = resolve(text).unwrap();
        assert!(!out.contains("#include \"ffvk/"), "{out}");
        assert_eq!(out.matches("#define FFVK_STATE_GLSL").count(), 1);
        assert!(out.contains("#define FFVK_LIGHTING_GLSL"));
        assert!(out.contains("#include \"mine.glsl\""));
        assert!(out.starts_with("#version 310 es\n"));
    }

    #[test]
    fn an_unknown_library_file_is_named_with_its_line() {
        let e = resolve("#version 450\n\n#include \"ffvk/lights.glsl\"\n").unwrap_err();
        let text = e.to_string();
        assert!(
            text.contains("line 3")
                && text.contains("ffvk/lights.glsl")
                && text.contains("ffvk/lighting.glsl"),
            "{text}"
        );
        let e = resolve("#include <ffvk/lighting.glsl>\n").unwrap_err();
        assert!(matches!(e, LibraryError::Malformed { line: 1, .. }), "{e}");
    }
}
