//! Which compiled shader variant (build.rs, [`shaders`](crate::gpu::shaders)) a pipeline
//! uses: the lighting mode's, with the suffixes of the stages and varyings its draws need.

use crate::gl::state::LightingMode;
use crate::gpu::layout::{SpecConstant, SpecKey};

/// Whether a pipeline specialized by `key` needs only the front primary color between the
/// per-vertex stages: unlit, or one-sided with a single color (the back colors then equal the
/// front ones and the secondary color is (0, 0, 0, 1)). Fewer vertex outputs make lavapipe's
/// vertex pipeline cheaper (BENCHMARKS.md); the uber-shader always passes all four colors.
pub fn one_color(key: SpecKey) -> bool {
    key != SpecKey::UBER
        && if key.get(SpecConstant::Lighting) == 0 {
            // Unlit: a secondary color reaches the fragment stage only under COLOR_SUM.
            key.get(SpecConstant::ColorSum) == 0
        } else {
            key.get(SpecConstant::TwoSide) == 0 && key.get(SpecConstant::SeparateSpecular) == 0
        }
}

/// Draws of fewer indices (or, not indexed, vertices) than this are small: in the fragment mode
/// they pass their materials from the vertex stage as flat varyings (the `fragment_small`
/// variants), so that consecutive small draws bind nothing of their own; larger draws read them
/// from their record as a uniform block bound per draw. On lavapipe a flat varying costs its
/// triangle setup per triangle (about 70 ns for the materials) and a draw's own block about
/// 5 µs: the two meet near 80 triangles.
pub const SMALL_DRAW_VERTICES: u32 = 256;

/// The name of the shader variant a mode's pipeline specialized by `key` uses: the mode's
/// name, with `_small` for a small draw of the fragment mode ([`SMALL_DRAW_VERTICES`]), with
/// `_one_color` when [`one_color`] holds for a per-vertex mode, and with `_textured` when the
/// draw samples a texture. (Layouts without a color, normal or texture coordinate array share
/// the variants: the pipeline's vertex input reads GL's current value from the draw record.)
pub fn variant_name(mode: LightingMode, key: SpecKey, textured: bool, small: bool) -> String {
    variant_name_staged(mode, key, (textured, small), (false, false))
}

/// [`variant_name`], with `_fog` for a fogged draw (the build that passes the fog varying) and
/// `_clipped` for a draw with user clip planes (the build that writes `gl_ClipDistance`), in
/// that order, before `_textured`.
pub fn variant_name_staged(
    mode: LightingMode,
    key: SpecKey,
    (textured, small): (bool, bool),
    (fogged, clipped): (bool, bool),
) -> String {
    let one = one_color(key) && mode != LightingMode::Fragment;
    format!(
        "{}{}{}{}{}{}",
        mode.name(),
        if small && mode == LightingMode::Fragment {
            "_small"
        } else {
            ""
        },
        if one { "_one_color" } else { "" },
        if fogged { "_fog" } else { "" },
        if clipped { "_clipped" } else { "" },
        if textured { "_textured" } else { "" },
    )
}

/// The `_edges` build a pipeline of GL's edge flags uses (a polygon mode of `GL_LINE` or
/// `GL_POINT` over [`Topology::EdgeFlaggedTriangles`](crate::draw::record::Topology)):
/// [`variant_name_staged`]'s name for a pipeline that passes all four colors (the per-vertex
/// modes' `_one_color` builds have no `_edges` build), with `_edges` last.
pub fn edges_variant_name(
    mode: LightingMode,
    (textured, small): (bool, bool),
    (fogged, clipped): (bool, bool),
) -> String {
    let name = variant_name_staged(mode, SpecKey::UBER, (textured, small), (fogged, clipped));
    format!("{name}_edges")
}
