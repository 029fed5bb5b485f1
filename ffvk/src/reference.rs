//! The CPU reference: GL 2.1's lighting equation (section 2.14.1) in double precision,
//! written from the spec page independently of the GLSL, plus the vertex transform and the
//! interpolation tests need to predict a pixel, and texturing ([`texture`]) with the color
//! sum after it. Tests and `ffvk explain` use it.

pub mod stages;
pub mod texture;
pub mod units;

use glam::{DMat3, DVec3, DVec4, Mat4};

use crate::gl::state::{
    Attenuation, ColorControl, FixedFunctionState, Light, LightingMode, Material, SpecularModel, SpotEdge,
};
use crate::gl::texture::{Sampling, TextureImage, MAX_TEXTURE_UNITS};
use crate::mesh::Vertex;

/// One light's share of the sum, before clamping (what `ffvk explain` prints).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct LightTerms {
    /// Distance attenuation: 1 / (k0 + k1·d + k2·d²) for a positional light (d the eye-space
    /// distance), 1 for a directional one. Not clamped, as in GL. With glTF's falloff
    /// ([`Attenuation::GltfInverseSquare`]): window / d².
    pub att_i: f64,
    /// The eye-space distance d to a positional light (`None` for a directional one).
    pub distance: Option<f64>,
    /// The attenuation this light uses.
    pub attenuation: Attenuation,
    /// Spotlight factor: (P_pliV ⊙ ŝ_dli)^s_rli inside the cone, 0 outside it, 1 when
    /// c_rli = 180; with a soft edge ([`SpotEdge`]), its ramp between the cones instead.
    pub spot_i: f64,
    /// cos θ = P_pliV ⊙ ŝ_dli, for a spot (`None` when c_rli = 180).
    pub cos_spot: Option<f64>,
    /// The spot edge this light uses.
    pub spot_edge: SpotEdge,
    /// The specular factor before f_i and the colors: (n ⊙ ĥ_i)^s_rm (GL's) or
    /// (r_i ⊙ v)^s_rm (Phong's), as the light model says.
    pub specular_factor: f64,
    /// 1 when n · VP_pli > 0, else 0: a light behind the surface leaves no highlight.
    pub f_i: f64,
    /// a_cm * a_cli
    pub ambient: DVec3,
    /// (n ⊙ VP_pli) d_cm * d_cli
    pub diffuse: DVec3,
    /// f_i (n ⊙ ĥ_i)^s_rm s_cm * s_cli (or Phong's (r_i ⊙ v)^s_rm in place of the power)
    pub specular: DVec3,
}

/// The equation's result at one point, with every term.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Lit {
    /// The specular term's model.
    pub specular_model: SpecularModel,
    /// e_cm
    pub emission: DVec3,
    /// a_cm * a_cs
    pub scene_ambient: DVec3,
    /// One entry per enabled light, in index order.
    pub lights: Vec<LightTerms>,
    /// Clamped to [0, 1].
    pub c_pri: DVec4,
    /// Clamped to [0, 1]; alpha 1.
    pub c_sec: DVec4,
}

impl Lit {
    /// Color sum: RGB clamp(c_pri + c_sec), alpha from c_pri.
    pub fn color(&self) -> DVec4 {
        color_sum(self.c_pri, self.c_sec)
    }
}

/// GL's color sum (section 3.9): RGB clamp(c_pri + c_sec) to [0, 1], alpha from c_pri.
pub fn color_sum(c_pri: DVec4, c_sec: DVec4) -> DVec4 {
    (c_pri.truncate() + c_sec.truncate())
        .clamp(DVec3::ZERO, DVec3::ONE)
        .extend(c_pri.w)
}

fn d4(v: glam::Vec4) -> DVec4 {
    v.as_dvec4()
}

/// d1 ⊙ d2 = max(d1 · d2, 0).
fn odot(a: DVec3, b: DVec3) -> f64 {
    a.dot(b).max(0.0)
}

/// x^y with 0^0 = 1 (section 2.1.1).
fn pow_gl(x: f64, y: f64) -> f64 {
    if y == 0.0 {
        1.0
    } else {
        x.powf(y)
    }
}

fn unit(v: DVec3) -> DVec3 {
    let len = v.length();
    if len > 0.0 {
        v / len
    } else {
        DVec3::ZERO
    }
}

/// The unit vector from homogeneous point p1 to p2 (the spec's P1P2 with a hat).
pub fn unit_from_to(p1: DVec4, p2: DVec4) -> DVec3 {
    match (p1.w == 0.0, p2.w == 0.0) {
        (false, true) => unit(p2.truncate()),
        (true, false) => -unit(p1.truncate()),
        (true, true) => unit(p2.truncate() - p1.truncate()),
        (false, false) => unit(p2.truncate() / p2.w - p1.truncate() / p1.w),
    }
}

/// cos(c_rli), exact at 90°: the GL state's own function, re-exported.
pub use crate::gl::state::cos_cutoff;

/// Lights eye-space point `v` with eye-space normal `n` and material `m` under `state`'s
/// enabled lights and light model.
pub fn light(state: &FixedFunctionState, v: DVec4, n: DVec3, m: &Material) -> Lit {
    let (e_cm, a_cm, d_cm, s_cm) = (d4(m.emission), d4(m.ambient), d4(m.diffuse), d4(m.specular));
    let s_rm = m.shininess as f64;
    let a_cs = d4(state.model.ambient);
    let p_e = DVec4::new(0.0, 0.0, 0.0, 1.0);

    let emission = e_cm.truncate();
    let scene_ambient = a_cm.truncate() * a_cs.truncate();
    let mut c_pri = emission + scene_ambient;
    let mut c_sec = DVec3::ZERO;
    let mut lights = Vec::new();

    for l in state.enabled_lights() {
        let t = light_terms(state, l, v, n, a_cm, d_cm, s_cm, s_rm, p_e);
        let scale = t.att_i * t.spot_i;
        match state.model.color_control {
            ColorControl::SingleColor => c_pri += scale * (t.ambient + t.diffuse + t.specular),
            ColorControl::SeparateSpecularColor => {
                c_pri += scale * (t.ambient + t.diffuse);
                c_sec += scale * t.specular;
            }
        }
        lights.push(t);
    }
    Lit {
        specular_model: state.model.specular_model,
        emission,
        scene_ambient,
        lights,
        c_pri: c_pri.extend(d_cm.w).clamp(DVec4::ZERO, DVec4::ONE),
        c_sec: c_sec.clamp(DVec3::ZERO, DVec3::ONE).extend(1.0),
    }
}

#[allow(clippy::too_many_arguments)]
fn light_terms(
    state: &FixedFunctionState,
    l: &Light,
    v: DVec4,
    n: DVec3,
    a_cm: DVec4,
    d_cm: DVec4,
    s_cm: DVec4,
    s_rm: f64,
    p_e: DVec4,
) -> LightTerms {
    let p_pli = d4(l.position);
    let vp_pli = unit_from_to(v, p_pli);

    let distance = (p_pli.w != 0.0).then(|| (p_pli.truncate() / p_pli.w - v.truncate() / v.w).length());
    let att_i = match (distance, l.attenuation) {
        (None, _) => 1.0,
        (Some(d), Attenuation::GlK012) => {
            1.0 / (l.constant_attenuation as f64
                + l.linear_attenuation as f64 * d
                + l.quadratic_attenuation as f64 * d * d)
        }
        (Some(d), Attenuation::GltfInverseSquare { range }) => gltf_inverse_square(d, range.map(f64::from)),
    };

    let cos_spot =
        (l.spot_cutoff != 180.0).then(|| odot(unit_from_to(p_pli, v), unit(l.spot_direction.as_dvec3())));
    let spot_i = match cos_spot {
        None => 1.0,
        Some(c) => {
            let cos_outer = cos_cutoff(l.spot_cutoff);
            match l.spot_edge {
                SpotEdge::GlExponent if c >= cos_outer => pow_gl(c, l.spot_exponent as f64),
                SpotEdge::GlExponent => 0.0,
                SpotEdge::LinearInnerOuter { inner_degrees } => {
                    soft_edge(c, cos_outer, cos_cutoff(inner_degrees), |t| t)
                }
                SpotEdge::SmoothstepInnerOuter { inner_degrees } => {
                    soft_edge(c, cos_outer, cos_cutoff(inner_degrees), |t| {
                        t * t * (3.0 - 2.0 * t)
                    })
                }
            }
        }
    };

    let n_vp = odot(n, vp_pli);
    let f_i = if n_vp != 0.0 { 1.0 } else { 0.0 };
    // The direction to the viewer: to the eye, or +z for a viewer at infinity.
    let to_viewer = if state.model.local_viewer {
        unit_from_to(v, p_e)
    } else {
        DVec3::Z
    };
    let specular_factor = match state.model.specular_model {
        SpecularModel::BlinnHalfway => pow_gl(odot(n, unit(vp_pli + to_viewer)), s_rm),
        SpecularModel::PhongReflect => {
            // r_i, the reflection of VP_pli about n (n as given, as the halfway term takes it).
            let r_i = 2.0 * n.dot(vp_pli) * n - vp_pli;
            pow_gl(odot(r_i, to_viewer), s_rm)
        }
    };
    LightTerms {
        att_i,
        distance,
        attenuation: l.attenuation,
        spot_i,
        cos_spot,
        spot_edge: l.spot_edge,
        specular_factor,
        f_i,
        ambient: a_cm.truncate() * d4(l.ambient).truncate(),
        diffuse: n_vp * d_cm.truncate() * d4(l.diffuse).truncate(),
        specular: f_i * specular_factor * s_cm.truncate() * d4(l.specular).truncate(),
    }
}

/// glTF's falloff (KHR_lights_punctual, as Khronos' sample viewer draws it): 1 / d², times
/// clamp(1 − (d / range)⁴, 0, 1) with a range.
pub fn gltf_inverse_square(d: f64, range: Option<f64>) -> f64 {
    let window = range.map_or(1.0, |r| (1.0 - (d / r).powi(4)).clamp(0.0, 1.0));
    window / (d * d)
}

/// A soft spot edge: 1 at or inside the inner cone, 0 outside the outer, `ramp` of the
/// position between them (0 at the outer cone, 1 at the inner); equal cones are a hard cutoff.
fn soft_edge(cos_angle: f64, cos_outer: f64, cos_inner: f64, ramp: impl Fn(f64) -> f64) -> f64 {
    if cos_inner <= cos_outer {
        return if cos_angle >= cos_outer { 1.0 } else { 0.0 };
    }
    ramp(((cos_angle - cos_outer) / (cos_inner - cos_outer)).clamp(0.0, 1.0))
}

/// Section 2.11.3: the eye-space normal, with RESCALE_NORMAL and NORMALIZE as enabled.
pub fn eye_normal(state: &FixedFunctionState, modelview: Mat4, n_object: DVec3) -> DVec3 {
    let m3 = DMat3::from_mat4(modelview.as_dmat4());
    let inv = m3.inverse();
    let mut n = inv.transpose() * n_object;
    if state.rescale_normal {
        n /= inv.row(2).length();
    }
    if state.normalize {
        n = unit(n);
    }
    n
}

/// A vertex after the vertex stage: eye position, clip position (GL), normal and color.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct EyeVertex {
    /// Eye-space position: the modelview times (x, y, z, 1).
    pub eye: DVec4,
    /// GL clip coordinates (z in [-w, w]), before ffvk's conversion to Vulkan's.
    pub clip: DVec4,
    /// Eye-space normal from [`eye_normal`]; renormalized only when NORMALIZE is on, so a
    /// scaled modelview shows in its length, as in GL.
    pub normal: DVec3,
    /// The vertex's color (GL's current color), not yet clamped.
    pub color: DVec4,
    /// Each unit's (s, t, r, q) from [`units::unit_texcoords`]: the source coordinates, the
    /// generated ones replaced (§2.11.4), through the unit's texture matrix; not yet divided
    /// by q.
    pub texcoords: [DVec4; MAX_TEXTURE_UNITS],
}

/// Runs the vertex stage on the CPU for object-space vertex `v`, in double precision, units
/// 1-3 taking their current texture coordinates: [`transform_with`] of no mesh coordinates.
pub fn transform(state: &FixedFunctionState, modelview: Mat4, projection: Mat4, v: &Vertex) -> EyeVertex {
    transform_with(state, modelview, projection, v, units::CoordSources::default())
}

/// [`transform`] with units 1-3 reading the vertex's coordinates or its second set as
/// `sources` says ([`Draw::mesh_texcoords`](crate::Draw::mesh_texcoords),
/// [`Draw::second_texcoords`](crate::Draw::second_texcoords)).
pub fn transform_with(
    state: &FixedFunctionState,
    modelview: Mat4,
    projection: Mat4,
    v: &Vertex,
    sources: units::CoordSources,
) -> EyeVertex {
    let object = DVec3::from(v.position.map(f64::from)).extend(1.0);
    let eye = modelview.as_dmat4() * object;
    let normal = eye_normal(state, modelview, DVec3::from(v.normal.map(f64::from)));
    EyeVertex {
        eye,
        clip: projection.as_dmat4() * eye,
        normal,
        color: DVec4::from(v.color.map(f64::from)),
        texcoords: units::unit_texcoords(state, sources, v.texcoord, (object, eye, normal)),
    }
}

/// The lit colors of one face at one point: two-sided lighting takes the back material
/// and −n for the back face; COLOR_MATERIAL applies the current color.
pub fn light_face(state: &FixedFunctionState, eye: DVec4, normal: DVec3, color: DVec4, back: bool) -> Lit {
    let two_sided_back = back && state.model.two_side;
    let material = if two_sided_back { &state.back } else { &state.front };
    let material = state
        .color_material
        .apply(material, color.as_vec4(), two_sided_back);
    let n = if two_sided_back { -normal } else { normal };
    light(state, eye, n, &material)
}

/// The color GL produces at one vertex for one face (lighting off: the current color).
pub fn vertex_color(state: &FixedFunctionState, v: &EyeVertex, back: bool) -> (DVec4, DVec4) {
    if !state.lighting {
        // Section 2.14.6: colors are clamped "after lighting, whether enabled or not".
        return (
            v.color.clamp(DVec4::ZERO, DVec4::ONE),
            stages::unlit_secondary(state),
        );
    }
    let lit = light_face(state, v.eye, v.normal, v.color, back);
    (lit.c_pri, lit.c_sec)
}

/// A pixel's position within one triangle, from the rasterizer's point of view.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Coverage {
    /// Perspective-correct barycentric weights of the three vertices.
    pub weights: DVec3,
    /// The same weights one pixel to the right and one pixel down (outside the triangle
    /// possibly): the screen-space derivatives that texturing's level of detail needs.
    pub weights_dx: DVec3,
    /// See `weights_dx`.
    pub weights_dy: DVec3,
    /// Whether the window-space winding is counter-clockwise (GL's front under FrontFace(CCW)).
    pub front: bool,
}

/// Window-space position (x right, y down from the image's top row, in pixels) of a GL clip position.
pub fn window(clip: DVec4, width: u32, height: u32) -> (f64, f64) {
    let ndc = clip.truncate() / clip.w;
    (
        (ndc.x + 1.0) * 0.5 * width as f64,
        (1.0 - ndc.y) * 0.5 * height as f64,
    )
}

/// The perspective-correct weights at the center of pixel (px, py) (row 0 at the top), or
/// `None` when the center is outside the triangle.
pub fn coverage(clip: [DVec4; 3], width: u32, height: u32, px: u32, py: u32) -> Option<Coverage> {
    let p: Vec<(f64, f64)> = clip.iter().map(|c| window(*c, width, height)).collect();
    let (x, y) = (px as f64 + 0.5, py as f64 + 0.5);
    let edge =
        |a: (f64, f64), b: (f64, f64), c: (f64, f64)| (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
    let area = edge(p[0], p[1], p[2]);
    if area == 0.0 {
        return None;
    }
    let screen = |x: f64, y: f64| {
        DVec3::new(
            edge(p[1], p[2], (x, y)) / area,
            edge(p[2], p[0], (x, y)) / area,
            edge(p[0], p[1], (x, y)) / area,
        )
    };
    // Perspective correction: weight by 1/w and renormalize.
    let correct = |b: DVec3| {
        let w = b / DVec3::new(clip[0].w, clip[1].w, clip[2].w);
        w / (w.x + w.y + w.z)
    };
    let b = screen(x, y);
    if b.x < 0.0 || b.y < 0.0 || b.z < 0.0 {
        return None;
    }
    // With y pointing down, a GL counter-clockwise triangle has negative `area` here.
    Some(Coverage {
        weights: correct(b),
        weights_dx: correct(screen(x + 1.0, y)),
        weights_dy: correct(screen(x, y + 1.0)),
        front: area < 0.0,
    })
}

/// A texture bound to a draw: its image and its sampling parameters.
pub type Bound<'a> = (&'a TextureImage, &'a Sampling);

/// Everything the CPU predicts at one pixel.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct PixelTerms {
    /// The primary color reaching the fragment (interpolated, provoking or lit there).
    pub c_pri: DVec4,
    /// The secondary color reaching the fragment.
    pub c_sec: DVec4,
    /// What each texture unit that samples did, in unit order.
    pub units: [Option<units::Textured>; MAX_TEXTURE_UNITS],
    /// The primary color after texturing: the last applied unit's result, `c_pri` where none
    /// applies.
    pub textured: DVec4,
    /// The color sum of the textured primary and the secondary color.
    pub summed: DVec4,
    /// What fog did, where it is on.
    pub fog: Option<stages::FogTerms>,
    /// The final color: `summed`, fogged where fog is on.
    pub color: DVec4,
    /// The alpha test's verdict on `color`'s alpha at an 8-bit UNORM target's precision (the
    /// format ffvk's renderer draws to); `GL_ALWAYS` while the test is off.
    pub alpha_test: stages::AlphaVerdict,
    /// Each enabled user clip plane's index and its distance at the pixel (kept where ≥ 0).
    pub clip_distances: Vec<(usize, f64)>,
    /// Whether the fragment survives the clip planes and the alpha test: where it does not,
    /// the pixel keeps what was drawn before.
    pub kept: bool,
}

/// What ffvk should draw at a pixel covered by triangle `tri` (object-space vertices, in
/// order), in `state.mode`, with `textures` bound (an `Option<Bound>`: unit 0's texture alone;
/// or a [`units::DrawTextures`]): the CPU prediction tests compare the GPU with. A fragment the
/// clip planes or the alpha test discard draws nothing: see [`pixel_terms`]' `kept`.
pub fn pixel_color<'a>(
    state: &FixedFunctionState,
    modelview: Mat4,
    projection: Mat4,
    tri: [&Vertex; 3],
    cov: Coverage,
    textures: impl Into<units::DrawTextures<'a>>,
) -> DVec4 {
    pixel_terms(state, modelview, projection, tri, cov, textures).color
}

/// [`pixel_color`] with the colors before the color sum and the texturing terms.
pub fn pixel_terms<'a>(
    state: &FixedFunctionState,
    modelview: Mat4,
    projection: Mat4,
    tri: [&Vertex; 3],
    cov: Coverage,
    textures: impl Into<units::DrawTextures<'a>>,
) -> PixelTerms {
    let textures = textures.into();
    let v: [EyeVertex; 3] = std::array::from_fn(|k| {
        let sources = units::CoordSources {
            mesh: textures.mesh_texcoords,
            second: textures.second_texcoords,
            second_st: textures.triangle_second[k],
        };
        transform_with(state, modelview, projection, tri[k], sources)
    });
    let back = !cov.front;
    let at = |w: DVec3, f: &dyn Fn(&EyeVertex) -> DVec4| f(&v[0]) * w.x + f(&v[1]) * w.y + f(&v[2]) * w.z;
    let w = cov.weights;
    let (c_pri, c_sec) = match state.mode {
        LightingMode::Vertex => {
            let c = v.map(|e| vertex_color(state, &e, back));
            (
                c[0].0 * w.x + c[1].0 * w.y + c[2].0 * w.z,
                c[0].1 * w.x + c[1].1 * w.y + c[2].1 * w.z,
            )
        }
        LightingMode::Flat => vertex_color(state, &v[2], back),
        LightingMode::Fragment if !state.lighting => {
            // Unlit: the clamped vertex colors, interpolated, as in vertex mode.
            let c = v.map(|e| vertex_color(state, &e, back).0);
            (
                c[0] * w.x + c[1] * w.y + c[2] * w.z,
                stages::unlit_secondary(state),
            )
        }
        LightingMode::Fragment => {
            let eye = at(w, &|e| e.eye);
            let color = at(w, &|e| e.color);
            let dirs = v.map(|e| unit(e.normal));
            let lens = v.map(|e| e.normal.length());
            let dir = dirs[0] * w.x + dirs[1] * w.y + dirs[2] * w.z;
            let len = lens[0] * w.x + lens[1] * w.y + lens[2] * w.z;
            let lit = light_face(state, eye, unit(dir) * len, color, back);
            (lit.c_pri, lit.c_sec)
        }
    };
    let stq = std::array::from_fn(|i| {
        [cov.weights, cov.weights_dx, cov.weights_dy].map(|w| at(w, &|e| e.texcoords[i]))
    });
    let (units, textured) = units::texture_units(state, &textures, stq, c_pri);
    let summed = color_sum(textured, c_sec);
    let fog = state
        .fragment
        .fog
        .enabled
        .then(|| stages::fog_pixel(state, v.map(|e| e.eye), w, summed));
    let color = fog.map_or(summed, |f| f.after);
    let alpha_test = stages::alpha_test(&state.fragment.alpha_test, color.w, Some(8));
    let clip_distances = stages::clip_distances(&state.clip, at(w, &|e| e.eye));
    let kept = alpha_test.passes && clip_distances.iter().all(|&(_, d)| d >= 0.0);
    PixelTerms {
        c_pri,
        c_sec,
        units,
        textured,
        summed,
        fog,
        color,
        alpha_test,
        clip_distances,
        kept,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::state::GlState;

    /// Unit vectors in the upper half space, from a small deterministic generator.
    fn directions(count: usize) -> Vec<DVec3> {
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..count)
            .map(|_| unit(DVec3::new(next() * 2.0 - 1.0, next() * 2.0 - 1.0, next() + 0.05)))
            .collect()
    }

    /// The angles of r_i (Phong) and ĥ_i (GL) for light `l`, viewer `v`, normal `n`.
    fn angles(n: DVec3, l: DVec3, v: DVec3) -> (f64, f64) {
        let r = 2.0 * n.dot(l) * n - l;
        (
            r.dot(v).clamp(-1.0, 1.0).acos(),
            n.dot(unit(l + v)).clamp(-1.0, 1.0).acos(),
        )
    }

    #[test]
    fn the_halfway_angle_is_half_the_reflection_angle_for_coplanar_vectors_and_more_otherwise() {
        let n = DVec3::Z;
        for (i, l) in directions(200).into_iter().enumerate() {
            // A viewer in the plane of n and l, and one out of it.
            let in_plane = unit(DVec3::new(-l.x * 0.3, -l.y * 0.3, 1.0));
            let (reflect, halfway) = angles(n, l, in_plane);
            assert!(
                (reflect - 2.0 * halfway).abs() < 1e-9,
                "{i}: {reflect} vs 2 × {halfway}"
            );
            let out = unit(DVec3::new(l.y, -l.x, 0.5));
            let (reflect, halfway) = angles(n, l, out);
            assert!(halfway >= reflect / 2.0 - 1e-12, "{i}: {halfway} < {reflect} / 2");
        }
    }

    #[test]
    fn a_soft_edge_tends_to_the_hard_cutoff_as_the_inner_cone_meets_the_outer() {
        let outer = 20.0f32;
        let cos_outer = cos_cutoff(outer);
        for k in 0..=60 {
            // Angles from 15° to 25°, across the outer cone.
            let theta = 15.0 + k as f64 / 6.0;
            let c = theta.to_radians().cos();
            let hard = if c >= cos_outer { 1.0 } else { 0.0 };
            for inner in [outer, outer - 1e-4] {
                let cos_inner = cos_cutoff(inner);
                let linear = soft_edge(c, cos_outer, cos_inner, |t| t);
                let smooth = soft_edge(c, cos_outer, cos_inner, |t| t * t * (3.0 - 2.0 * t));
                // Within 0.01° of the outer cone the ramp is still a ramp.
                if (theta - outer as f64).abs() > 0.01 || inner == outer {
                    assert_eq!((linear, smooth), (hard, hard), "θ {theta}, inner {inner}");
                }
            }
        }
    }

    #[test]
    fn the_gltf_falloff_is_the_inverse_square_windowed_to_zero_at_the_range() {
        assert_eq!(gltf_inverse_square(2.0, None), 0.25);
        assert_eq!(gltf_inverse_square(2.0, Some(4.0)), (1.0 - 1.0 / 16.0) / 4.0);
        assert_eq!(gltf_inverse_square(4.0, Some(4.0)), 0.0);
        assert_eq!(gltf_inverse_square(5.0, Some(4.0)), 0.0);
        // Through the equation: a light at distance 2 with range 4.
        let mut gl = GlState::new();
        gl.lighting.lights[0].enabled = true;
        gl.lighting.lights[0].position = glam::Vec4::new(0.0, 0.0, 2.0, 1.0);
        gl.lighting.lights[0].attenuation = Attenuation::GltfInverseSquare { range: Some(4.0) };
        let lit = light(
            &gl.lighting,
            DVec4::new(0.0, 0.0, 0.0, 1.0),
            DVec3::Z,
            &Material::default(),
        );
        assert_eq!(lit.lights[0].distance, Some(2.0));
        assert!((lit.lights[0].att_i - 15.0 / 64.0).abs() < 1e-15);
    }
}
