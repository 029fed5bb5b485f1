//! The stages around lighting on the CPU, in double precision and in GL's order: user clip
//! planes (GL 2.1 §2.12), the color sum with lighting off (§3.9), fog (§3.10) and the alpha
//! test (§4.1.4). Where GL leaves room, these take the choices ffvk's shaders take (|z_e| for
//! the fragment depth, f interpolated under `GL_FASTEST`), and where Mesa's GL deviates from
//! the spec they follow the spec (a fog coordinate taken as it is, not its absolute value).

use glam::{DVec3, DVec4};

use crate::gl::state::{AlphaTest, ClipPlanes, CompareFunc, FixedFunctionState, Fog, FogSource};

/// The secondary color GL passes on with lighting off (§2.14.6, §3.9): the current secondary
/// color, clamped, with alpha 1, where `GL_COLOR_SUM` is on; (0, 0, 0, 1), which adds
/// nothing, where it is off.
pub fn unlit_secondary(state: &FixedFunctionState) -> DVec4 {
    if state.fragment.color_sum {
        state
            .current_secondary_color
            .as_dvec4()
            .truncate()
            .clamp(DVec3::ZERO, DVec3::ONE)
            .extend(1.0)
    } else {
        DVec4::new(0.0, 0.0, 0.0, 1.0)
    }
}

/// The fog's distance c at a vertex at eye position `eye` whose fog coordinate is `coord`:
/// |z_e| for `GL_FRAGMENT_DEPTH`, the coordinate as it is for `GL_FOG_COORD`.
pub fn fog_distance(fog: &Fog, eye: DVec4, coord: f64) -> f64 {
    match fog.source {
        FogSource::FragmentDepth => eye.z.abs(),
        FogSource::FogCoord => coord,
    }
}

/// Section 3.10's blend: RGB f · rgb + (1 − f) · fog color, alpha untouched.
pub fn apply_fog(fog: &Fog, color: DVec4, f: f64) -> DVec4 {
    let fog_rgb = fog.color.as_dvec4().truncate();
    (color.truncate() * f + fog_rgb * (1.0 - f)).extend(color.w)
}

/// The fog at one pixel.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct FogTerms {
    /// Each vertex's distance c.
    pub c_vertices: [f64; 3],
    /// c at the pixel, interpolated from the vertices' (what f is computed from per fragment).
    pub c: f64,
    /// Whether f was computed per vertex and interpolated (`GL_FOG_HINT` `GL_FASTEST`).
    pub per_vertex: bool,
    /// The fog factor at the pixel, in [0, 1].
    pub f: f64,
    /// The color before fog (after texturing and the color sum).
    pub before: DVec4,
    /// The color after fog.
    pub after: DVec4,
}

/// Fog over `color` at a pixel whose vertices have eye positions `eyes` and perspective-correct
/// weights `w`; the fog coordinate is the state's current one (the CPU reference's vertices
/// carry none of their own).
pub fn fog_pixel(state: &FixedFunctionState, eyes: [DVec4; 3], w: DVec3, color: DVec4) -> FogTerms {
    let fog = &state.fragment.fog;
    let coord = f64::from(state.current_fog_coord);
    let c_vertices = eyes.map(|e| fog_distance(fog, e, coord));
    let mix = |v: [f64; 3]| v[0] * w.x + v[1] * w.y + v[2] * w.z;
    let c = mix(c_vertices);
    let per_vertex = fog.hint.per_vertex();
    let f = if per_vertex {
        mix(c_vertices.map(|c| fog.factor(c))).clamp(0.0, 1.0)
    } else {
        fog.factor(c)
    };
    FogTerms {
        c_vertices,
        c,
        per_vertex,
        f,
        before: color,
        after: apply_fog(fog, color, f),
    }
}

/// The alpha test's verdict on one fragment.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct AlphaVerdict {
    /// The function compared with (`GL_ALWAYS` while the test is off).
    pub func: CompareFunc,
    /// The fragment's alpha and the reference, as compared: fixed-point values at the target's
    /// precision where it is UNORM, else as they are.
    pub alpha: f64,
    /// See `alpha`.
    pub reference: f64,
    /// Whether the fragment is kept.
    pub passes: bool,
}

/// Section 4.1.4: the alpha test on alpha `a`, compared at `bits` of fixed-point precision
/// (a UNORM target's alpha bits) as GL compares, or as floats where `bits` is `None`.
pub fn alpha_test(test: &AlphaTest, a: f64, bits: Option<u32>) -> AlphaVerdict {
    let func = test.effective_func();
    let reference = f64::from(test.reference);
    let (alpha, reference) = match bits {
        Some(bits) => {
            let scale = f64::from((1u32 << bits) - 1);
            ((a.clamp(0.0, 1.0) * scale).round(), (reference * scale).round())
        }
        None => (a, reference),
    };
    AlphaVerdict {
        func,
        alpha,
        reference,
        passes: func.passes(alpha, reference),
    }
}

/// Section 2.12: each enabled user clip plane's index and its distance p_eye · e at eye
/// position `eye`; the point is kept where every distance is ≥ 0.
pub fn clip_distances(planes: &ClipPlanes, eye: DVec4) -> Vec<(usize, f64)> {
    planes
        .planes
        .iter()
        .zip(planes.enabled)
        .enumerate()
        .filter(|(_, (_, on))| *on)
        .map(|(i, (p, _))| (i, p.as_dvec4().dot(eye)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::state::{FogHint, FogMode, GlState};

    #[test]
    fn a_disabled_alpha_test_keeps_every_fragment_and_an_enabled_one_compares_at_8_bits() {
        let mut test = AlphaTest::default();
        assert!(alpha_test(&test, 0.0, Some(8)).passes);
        test.enabled = true;
        test.func = CompareFunc::Less;
        test.reference = 0.5015;
        // 0.5 and 0.5015 are both 128 of 255: not less.
        let v = alpha_test(&test, 0.5, Some(8));
        assert_eq!((v.alpha, v.reference, v.passes), (128.0, 128.0, false));
        // As floats they differ.
        assert!(alpha_test(&test, 0.5, None).passes);
    }

    #[test]
    fn per_vertex_fog_interpolates_f_and_per_fragment_fog_interpolates_c() {
        let mut gl = GlState::new();
        gl.lighting.fragment.fog.enabled = true;
        gl.lighting.fragment.fog.mode = FogMode::Exp;
        gl.lighting.fragment.fog.density = 0.5;
        let eyes = [
            DVec4::new(0.0, 0.0, -1.0, 1.0),
            DVec4::new(0.0, 0.0, -9.0, 1.0),
            DVec4::new(0.0, 0.0, -9.0, 1.0),
        ];
        let w = DVec3::new(0.5, 0.25, 0.25);
        let nicest = fog_pixel(&gl.lighting, eyes, w, DVec4::ONE);
        assert_eq!(nicest.c, 5.0);
        assert!((nicest.f - (-2.5f64).exp()).abs() < 1e-15);
        gl.lighting.fragment.fog.hint = FogHint::Fastest;
        let fastest = fog_pixel(&gl.lighting, eyes, w, DVec4::ONE);
        let want = 0.5 * (-0.5f64).exp() + 0.5 * (-4.5f64).exp();
        assert!((fastest.f - want).abs() < 1e-15, "{} vs {want}", fastest.f);
        // Alpha is untouched, RGB goes to the fog color (black).
        assert_eq!(fastest.after.w, 1.0);
        assert!((fastest.after.x - want).abs() < 1e-15);
    }
}
