//! SPIR-V of every shader variant, compiled from `glsl/` by build.rs (glslc) and embedded.

/// One pipeline variant: a lighting mode's vertex and fragment stages, compiled with the
/// macros in `defines`. Each stage's entry point is `main`.
#[derive(Debug, Clone, Copy)]
#[non_exhaustive]
pub struct ShaderVariant {
    /// `vertex`, `flat` or `fragment` (the [`LightingMode`](crate::gl::state::LightingMode)
    /// names), with `_one_color` for the variants that pass only the front primary color.
    pub name: &'static str,
    /// What the variant computes, in one sentence.
    pub doc: &'static str,
    /// The vertex stage's source file under `glsl/`.
    pub vertex_source: &'static str,
    /// The fragment stage's source file under `glsl/`.
    pub fragment_source: &'static str,
    /// The macro definitions both stages were compiled with, as (name, value).
    pub defines: &'static [(&'static str, &'static str)],
    /// Vertex-stage SPIR-V (bytes of 32-bit little-endian words).
    pub vertex: &'static [u8],
    /// Fragment-stage SPIR-V (bytes of 32-bit little-endian words).
    pub fragment: &'static [u8],
    /// Geometry-stage SPIR-V, of `glsl/edges.geom`: the `_edges` builds only (GL's edge
    /// flags, read from a triangle list with adjacency).
    pub geometry: Option<&'static [u8]>,
}

include!(concat!(env!("OUT_DIR"), "/shaders.rs"));

/// The variant called `name`, for example `"vertex_one_color"`.
pub fn variant(name: &str) -> Option<&'static ShaderVariant> {
    VARIANTS.iter().find(|v| v.name == name)
}
