//! The CPU reference against values worked out by hand from the spec's formulas.

use ffvk::gl::state::*;
use ffvk::reference::{self, light, unit_from_to};
use glam::{DVec3, DVec4, Mat4, Vec3, Vec4};

/// State is f32 (as GL's), so its decimal constants carry f32 rounding.
const EPS: f64 = 1e-6;

fn near(a: f64, b: f64) -> bool {
    (a - b).abs() < EPS
}

fn assert_rgb(got: DVec4, want: [f64; 3], what: &str) {
    assert!(
        near(got.x, want[0]) && near(got.y, want[1]) && near(got.z, want[2]),
        "{what}: got {got:?}, want {want:?}"
    );
}

fn lit_gl() -> GlState {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    gl.enable(Cap::Light(0)).unwrap();
    gl
}

const V: DVec4 = DVec4::new(0.0, 0.0, -1.0, 1.0);
const N: DVec3 = DVec3::Z;

#[test]
fn defaults_facing_light_0() {
    // a_cm*a_cs = 0.2*0.2 = 0.04; diffuse 1 * 0.8 * 1; specular material is black.
    let gl = lit_gl();
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_rgb(lit.c_pri, [0.84; 3], "c_pri");
    assert_eq!(lit.c_pri.w, 1.0);
    assert_eq!(lit.c_sec, DVec4::new(0.0, 0.0, 0.0, 1.0));
}

#[test]
fn shininess_zero_gives_full_specular_and_f_i_removes_it_behind() {
    let mut gl = lit_gl();
    gl.light(0, LightParam::Diffuse(Vec4::ZERO)).unwrap();
    gl.light_model(LightModelParam::Ambient(Vec4::ZERO)).unwrap();
    gl.material(
        Face::Front,
        MaterialParam::Specular(Vec4::new(0.5, 0.25, 1.0, 1.0)),
    )
    .unwrap();
    gl.light(0, LightParam::Position(Vec4::new(1.0, 0.0, 1.0, 0.0)))
        .unwrap();
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_rgb(lit.c_pri, [0.5, 0.25, 1.0], "(n⊙h)^0 = 1");
    // Light behind: n · L < 0, so f_i = 0 even though 0^0 would be 1.
    gl.light(0, LightParam::Position(Vec4::new(1.0, 0.0, -1.0, 0.0)))
        .unwrap();
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_rgb(lit.c_pri, [0.0; 3], "f_i = 0");
    assert_eq!(lit.lights[0].f_i, 0.0);
}

#[test]
fn halfway_vector_infinite_and_local_viewer() {
    let mut gl = lit_gl();
    gl.light(0, LightParam::Diffuse(Vec4::ZERO)).unwrap();
    gl.light_model(LightModelParam::Ambient(Vec4::ZERO)).unwrap();
    gl.material(Face::Front, MaterialParam::Specular(Vec4::ONE))
        .unwrap();
    gl.material(Face::Front, MaterialParam::Shininess(2.0)).unwrap();
    // Light along +x+z at 45°: L = (1,0,1)/√2. Infinite viewer: h = L + (0,0,1);
    // n·ĥ = cos(22.5°), squared = (1 + cos 45°)/2.
    gl.light(0, LightParam::Position(Vec4::new(1.0, 0.0, 1.0, 0.0)))
        .unwrap();
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    let want = (1.0 + std::f64::consts::FRAC_1_SQRT_2) / 2.0;
    assert_rgb(lit.c_pri, [want; 3], "infinite viewer");
    // Local viewer at V = (1, 0, -1): VPe = (-1, 0, 1)/√2, so h = (0, 0, √2) and n·ĥ = 1.
    gl.light_model(LightModelParam::LocalViewer(true)).unwrap();
    let lit = light(
        &gl.lighting,
        DVec4::new(1.0, 0.0, -1.0, 1.0),
        N,
        &gl.lighting.front,
    );
    assert_rgb(lit.c_pri, [1.0; 3], "local viewer");
}

#[test]
fn attenuation_uses_the_distance_and_only_for_positional_lights() {
    let mut gl = lit_gl();
    gl.light_model(LightModelParam::Ambient(Vec4::ZERO)).unwrap();
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 1.0)))
        .unwrap();
    for (k, v) in [(0, 1.0), (1, 1.0), (2, 1.0)] {
        let p = match k {
            0 => LightParam::ConstantAttenuation(v),
            1 => LightParam::LinearAttenuation(v),
            _ => LightParam::QuadraticAttenuation(v),
        };
        gl.light(0, p).unwrap();
    }
    // Distance 2 from (0,0,1) to (0,0,-1): att = 1/(1 + 2 + 4); diffuse 0.8.
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert!(near(lit.lights[0].att_i, 1.0 / 7.0));
    assert_rgb(lit.c_pri, [0.8 / 7.0; 3], "attenuated diffuse");
    // A light position with w = 2 is the point (0, 0, 0.5): distance 1.5.
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 2.0)))
        .unwrap();
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert!(near(lit.lights[0].att_i, 1.0 / (1.0 + 1.5 + 2.25)));
    // Directional: no attenuation whatever the factors.
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 0.0)))
        .unwrap();
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_eq!(lit.lights[0].att_i, 1.0);
}

#[test]
fn spot_cone_exponent_and_cutoff() {
    let mut gl = lit_gl();
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 0.0, 1.0)))
        .unwrap();
    gl.light(0, LightParam::SpotDirection(Vec3::new(0.0, 0.0, -1.0)))
        .unwrap();
    gl.light(0, LightParam::SpotCutoff(45.0)).unwrap();
    gl.light(0, LightParam::SpotExponent(2.0)).unwrap();
    // Vertex 30° off the axis: spot = cos²30° = 0.75.
    let s30 = 30f64.to_radians();
    let v30 = DVec4::new(s30.sin(), 0.0, -s30.cos(), 1.0);
    let lit = light(&gl.lighting, v30, N, &gl.lighting.front);
    assert!(near(lit.lights[0].spot_i, 0.75), "{}", lit.lights[0].spot_i);
    // 50° off the axis: outside the 45° cone.
    let s50 = 50f64.to_radians();
    let lit = light(
        &gl.lighting,
        DVec4::new(s50.sin(), 0.0, -s50.cos(), 1.0),
        N,
        &gl.lighting.front,
    );
    assert_eq!(lit.lights[0].spot_i, 0.0);
    // Exponent 0 inside the cone: 0^0 rule not needed, but x^0 = 1.
    gl.light(0, LightParam::SpotExponent(0.0)).unwrap();
    let lit = light(&gl.lighting, v30, N, &gl.lighting.front);
    assert_eq!(lit.lights[0].spot_i, 1.0);
    // Cutoff 180: spot 1 even behind the light.
    gl.light(0, LightParam::SpotCutoff(180.0)).unwrap();
    gl.light(0, LightParam::SpotExponent(50.0)).unwrap();
    let lit = light(
        &gl.lighting,
        DVec4::new(0.0, 0.0, 1.0, 1.0),
        N,
        &gl.lighting.front,
    );
    assert_eq!(lit.lights[0].spot_i, 1.0);
    // A directional light's cone: P_pliV is minus its direction (0,0,1) -> (0,0,-1), on the axis.
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 0.0)))
        .unwrap();
    gl.light(0, LightParam::SpotCutoff(10.0)).unwrap();
    let lit = light(&gl.lighting, v30, N, &gl.lighting.front);
    assert_eq!(lit.lights[0].spot_i, 1.0);
    gl.light(0, LightParam::SpotDirection(Vec3::new(1.0, 0.0, -1.0)))
        .unwrap();
    let lit = light(&gl.lighting, v30, N, &gl.lighting.front);
    assert_eq!(lit.lights[0].spot_i, 0.0, "45° off a 10° cone");
}

#[test]
fn separate_specular_moves_specular_to_c_sec_and_color_sum_clamps() {
    let mut gl = lit_gl();
    gl.light_model(LightModelParam::ColorControl(ColorControl::SeparateSpecularColor))
        .unwrap();
    gl.material(
        Face::Front,
        MaterialParam::Specular(Vec4::new(0.5, 0.5, 0.5, 1.0)),
    )
    .unwrap();
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_rgb(lit.c_pri, [0.84; 3], "c_pri without specular");
    assert_rgb(lit.c_sec, [0.5; 3], "c_sec");
    assert_eq!(lit.c_sec.w, 1.0);
    assert_rgb(lit.color(), [1.0; 3], "clamp(c_pri + c_sec)");
}

#[test]
fn clamping_alpha_and_negative_colors() {
    let mut gl = lit_gl();
    gl.light(0, LightParam::Diffuse(Vec4::new(3.0, -3.0, 0.5, 1.0)))
        .unwrap();
    gl.material(Face::Front, MaterialParam::Diffuse(Vec4::new(1.0, 1.0, 1.0, 0.3)))
        .unwrap();
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_rgb(lit.c_pri, [1.0, 0.0, 0.54], "clamped per component");
    assert!(near(lit.c_pri.w, 0.3), "alpha is d_cm's");
}

#[test]
fn unit_vector_between_homogeneous_points() {
    let p = DVec4::new(1.0, 2.0, 2.0, 1.0);
    let q = DVec4::new(1.0, 2.0, 5.0, 1.0);
    assert_eq!(unit_from_to(p, q), DVec3::Z);
    assert_eq!(
        unit_from_to(p, DVec4::new(0.0, 3.0, 0.0, 0.0)),
        DVec3::Y,
        "P2 at infinity"
    );
    assert_eq!(
        unit_from_to(DVec4::new(0.0, 0.0, 2.0, 0.0), p),
        -DVec3::Z,
        "P1 at infinity"
    );
    assert_eq!(unit_from_to(p, p), DVec3::ZERO, "zero length stays zero, not NaN");
}

#[test]
fn normals_rescale_and_normalize() {
    let mut state = FixedFunctionState::default();
    let m = Mat4::from_scale(Vec3::splat(0.5));
    // (M⁻¹)ᵀ of a 0.5 scale doubles the normal.
    assert!((reference::eye_normal(&state, m, DVec3::Z) - DVec3::new(0.0, 0.0, 2.0)).length() < 1e-6);
    state.rescale_normal = true;
    assert!((reference::eye_normal(&state, m, DVec3::Z) - DVec3::Z).length() < 1e-6);
    state.rescale_normal = false;
    state.normalize = true;
    assert!((reference::eye_normal(&state, m, DVec3::new(0.0, 3.0, 0.0)) - DVec3::Y).length() < 1e-6);
    assert_eq!(
        reference::eye_normal(&state, m, DVec3::ZERO),
        DVec3::ZERO,
        "zero normal is not NaN"
    );
}

#[test]
fn two_sided_back_face_uses_back_material_and_negated_normal() {
    let mut gl = lit_gl();
    gl.light_model(LightModelParam::TwoSide(true)).unwrap();
    gl.light_model(LightModelParam::Ambient(Vec4::ZERO)).unwrap();
    gl.material(Face::Back, MaterialParam::Diffuse(Vec4::new(0.0, 0.5, 0.0, 1.0)))
        .unwrap();
    // Light from -z; the front normal points +z, so only the back face sees it.
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, -1.0, 0.0)))
        .unwrap();
    let front = reference::light_face(&gl.lighting, V, N, DVec4::ONE, false);
    let back = reference::light_face(&gl.lighting, V, N, DVec4::ONE, true);
    assert_rgb(front.c_pri, [0.0; 3], "front faces away from the light");
    assert_rgb(back.c_pri, [0.0, 0.5, 0.0], "back material with -n");
    gl.light_model(LightModelParam::TwoSide(false)).unwrap();
    let back = reference::light_face(&gl.lighting, V, N, DVec4::ONE, true);
    assert_rgb(back.c_pri, [0.0; 3], "two-sided off: front material and n");
}

#[test]
fn color_material_tracks_the_current_color() {
    let mut gl = lit_gl();
    gl.light_model(LightModelParam::Ambient(Vec4::ZERO)).unwrap();
    // Enabling COLOR_MATERIAL writes the current color into the tracked AMBIENT_AND_DIFFUSE.
    gl.color(Vec4::new(0.5, 0.5, 0.5, 1.0)).unwrap();
    gl.enable(Cap::ColorMaterial).unwrap();
    assert_eq!(gl.lighting.front.diffuse, Vec4::new(0.5, 0.5, 0.5, 1.0));
    let c = DVec4::new(0.25, 0.5, 0.75, 1.0);
    let lit = reference::light_face(&gl.lighting, V, N, c, false);
    assert_rgb(lit.c_pri, [0.25, 0.5, 0.75], "AMBIENT_AND_DIFFUSE replaces d_cm");
    // Tracking EMISSION: the vertex color is e_cm; d_cm keeps the color written at enable.
    gl.color_material(Face::FrontAndBack, ColorMaterialMode::Emission);
    let lit = reference::light_face(&gl.lighting, V, N, c, false);
    assert_rgb(lit.c_pri, [0.75, 1.0, 1.0], "EMISSION");
    // Tracking only BACK: the front keeps the last color written into it, not c.
    gl.color(Vec4::new(0.1, 0.0, 0.0, 1.0)).unwrap();
    gl.color_material(Face::Back, ColorMaterialMode::Emission);
    let lit = reference::light_face(&gl.lighting, V, N, c, false);
    assert_rgb(lit.c_pri, [0.6, 0.5, 0.5], "BACK only leaves the front alone");
}

/// Spec 2.14.1: spot_i is (P_pliV ⊙ ŝ_dli)^s_rli when P_pliV ⊙ ŝ_dli ≥ cos(c_rli): a point
/// exactly on the cone's edge is inside. Mesa 22.3's fixed-function GL uses a strict `>`
/// there (found by the conformance oracle), so this rule is pinned against the spec here.
#[test]
fn a_point_exactly_on_the_cone_edge_is_inside() {
    let mut gl = lit_gl();
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 0.0, 1.0)))
        .unwrap();
    gl.light(0, LightParam::SpotDirection(Vec3::new(0.0, 0.0, -1.0)))
        .unwrap();
    gl.light(0, LightParam::SpotCutoff(0.0)).unwrap();
    // On the axis: P_pliV ⊙ ŝ_dli = 1 = cos 0.
    let lit = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_eq!(lit.lights[0].spot_i, 1.0);
}

/// cos(90°) is exactly 0, so a 90° cone holds every direction: behind the light,
/// P_pliV ⊙ ŝ_dli = 0 ≥ 0 and spot_i = 0^s_rli (1 for exponent 0, 0 otherwise).
#[test]
fn a_90_degree_cone_follows_the_formula_behind_the_light() {
    let mut gl = lit_gl();
    gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 0.0, 1.0)))
        .unwrap();
    gl.light(0, LightParam::SpotDirection(Vec3::new(0.0, 0.0, 1.0)))
        .unwrap();
    gl.light(0, LightParam::SpotCutoff(90.0)).unwrap();
    assert_eq!(reference::cos_cutoff(90.0), 0.0);
    let behind = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_eq!(behind.lights[0].spot_i, 1.0, "0^0 = 1");
    gl.light(0, LightParam::SpotExponent(1.0)).unwrap();
    let behind = light(&gl.lighting, V, N, &gl.lighting.front);
    assert_eq!(behind.lights[0].spot_i, 0.0, "0^1 = 0");
}
