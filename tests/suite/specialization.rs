//! Pipeline specialization: which pipeline each policy creates for which state, and the key
//! that decides it. (That specialized and uber pipelines draw the same lighting is checked by
//! every lighting and conformance test, which run both.)

use ffvk::draw::pipeline::MAX_AUTO_VARIANTS;
use ffvk::gl::state::*;
use ffvk::gpu::layout::{SpecConstant, SpecKey};
use ffvk::{Draw, Frame, Renderer, Specialize};
use glam::{Mat4, Vec3, Vec4};

use crate::support::*;

/// Lighting on with `lights` directional lights, in `mode`.
fn lit(lights: usize, mode: LightingMode) -> FixedFunctionState {
    with(dark(), |gl| {
        for i in 0..lights {
            gl.enable(Cap::Light(i))?;
            gl.light(i, LightParam::Position(Vec4::new(i as f32, 1.0, 1.0, 0.0)))?;
        }
        gl.lighting_mode(mode);
        Ok(())
    })
    .lighting
}

/// Draws one small frame of a quad with each state, in order.
fn draw_states(r: &mut Renderer, states: &[FixedFunctionState]) {
    let mesh = r.upload(&quad(-1.0, -1.0, 1.0, 1.0, 0.0, Vec4::ONE)).unwrap();
    for &state in states {
        let mut frame = Frame::new(8, 8);
        frame.draws.push(Draw::new(
            &mesh,
            Mat4::from_translation(Vec3::new(0.0, 0.0, -2.0)),
            perspective(45.0, 1.0, 0.5, 10.0),
            state,
        ));
        r.render(&frame).unwrap().into_rgba_image();
    }
}

#[test]
fn always_shares_a_pipeline_between_states_that_light_alike() {
    let mut r = renderer_with(Specialize::Always);
    let a = lit(1, LightingMode::Vertex);
    // Another color and direction, still one directional light: the same key.
    let mut b = a;
    b.lights[0].diffuse = Vec4::new(0.2, 0.4, 0.6, 1.0);
    b.lights[0].position = Vec4::new(0.0, 0.0, 1.0, 0.0);
    draw_states(&mut r, &[a, b]);
    assert_eq!(r.pipeline_counts(), (1, 1));
    // Two lights, then the same in fragment mode: one new pipeline each.
    draw_states(
        &mut r,
        &[lit(2, LightingMode::Vertex), lit(2, LightingMode::Fragment)],
    );
    assert_eq!(r.pipeline_counts(), (3, 3));
    finish(r);
}

#[test]
fn never_uses_one_uber_pipeline_per_mode() {
    let mut r = renderer_with(Specialize::Never);
    draw_states(
        &mut r,
        &[
            lit(1, LightingMode::Vertex),
            lit(5, LightingMode::Vertex),
            unlit(),
            lit(3, LightingMode::Fragment),
        ],
    );
    assert_eq!(r.pipeline_counts(), (2, 0));
    finish(r);
}

#[test]
fn auto_specializes_until_its_budget_then_uses_the_uber_shader() {
    let mut r = renderer_with(Specialize::Auto);
    // Distinct keys: light count × local viewer × two-sided.
    let mut states = Vec::new();
    for lights in 0..=MAX_LIGHTS {
        for (local, two) in [(false, false), (true, false), (false, true), (true, true)] {
            let mut s = lit(lights, LightingMode::Vertex);
            s.model.local_viewer = local;
            s.model.two_side = two;
            states.push(s);
        }
    }
    states.dedup_by_key(|s| SpecKey::for_state(s));
    assert!(states.len() > MAX_AUTO_VARIANTS);
    draw_states(&mut r, &states[..MAX_AUTO_VARIANTS]);
    assert_eq!(r.pipeline_counts(), (MAX_AUTO_VARIANTS, MAX_AUTO_VARIANTS));
    // Past the budget: the uber-shader, shared by every later state of the mode.
    draw_states(&mut r, &states[MAX_AUTO_VARIANTS..]);
    assert_eq!(r.pipeline_counts(), (MAX_AUTO_VARIANTS + 1, MAX_AUTO_VARIANTS));
    // A state specialized before the budget ran out keeps its pipeline.
    draw_states(&mut r, &states[..1]);
    assert_eq!(r.pipeline_counts(), (MAX_AUTO_VARIANTS + 1, MAX_AUTO_VARIANTS));
    finish(r);
}

#[test]
fn the_key_keeps_only_what_changes_the_lighting() {
    let key = |s: &FixedFunctionState| SpecKey::for_state(s);
    // Unlit states share one key whatever their lights and light model.
    let mut unlit_with_lights = lit(3, LightingMode::Vertex);
    unlit_with_lights.lighting = false;
    unlit_with_lights.model.local_viewer = true;
    assert_eq!(key(&unlit_with_lights), key(&unlit()));
    // Every constant 0 but the alpha test's function, GL_ALWAYS (7) with the test off.
    let mut want = [0; ffvk::gpu::layout::SPEC_CONSTANT_COUNT];
    want[ffvk::gpu::layout::SpecConstant::AlphaFunc as usize] = 7;
    assert_eq!(key(&unlit()).values, want);

    // Without lights the viewer and color control cannot matter; two-sided still does (the
    // back material's emission and ambient).
    let none = lit(0, LightingMode::Vertex);
    let mut none_local = none;
    none_local.model.local_viewer = true;
    none_local.model.color_control = ColorControl::SeparateSpecularColor;
    assert_eq!(key(&none), key(&none_local));
    let mut none_two = none;
    none_two.model.two_side = true;
    assert_ne!(key(&none), key(&none_two));

    // Light count and kinds.
    let mut s = lit(3, LightingMode::Vertex);
    let k = key(&s);
    assert_eq!(k.get(SpecConstant::LightCount), 3);
    assert_eq!(k.get(SpecConstant::Lighting), 1);
    assert_eq!(k.get(SpecConstant::AnyLocalLight), 0);
    assert_eq!(k.get(SpecConstant::AnySpotLight), 0);
    s.lights[1].position.w = 1.0;
    assert_eq!(key(&s).get(SpecConstant::AnyLocalLight), 1);
    s.lights[2].spot_cutoff = 30.0;
    assert_eq!(key(&s).get(SpecConstant::AnySpotLight), 1);
    // A disabled spot light is no spot light.
    let mut t = lit(1, LightingMode::Vertex);
    t.lights[5].spot_cutoff = 30.0;
    assert_eq!(key(&t).get(SpecConstant::AnySpotLight), 0);
    // The mode is not part of the key: pipelines are keyed by (mode, key).
    assert_eq!(
        key(&lit(2, LightingMode::Vertex)),
        key(&lit(2, LightingMode::Flat))
    );
}

#[test]
fn gls_own_state_promises_no_lighting_variant_and_a_variant_that_cannot_act_changes_no_key() {
    let key = |s: &FixedFunctionState| SpecKey::for_state(s);
    let variants = |k: SpecKey| {
        [
            SpecConstant::SpecularModel,
            SpecConstant::AnySoftSpot,
            SpecConstant::AnyGltfFalloff,
        ]
        .map(|c| k.get(c))
    };
    // GL's own states, spots and point lights included: every variant compiled out.
    let mut gl = lit(3, LightingMode::Vertex);
    gl.lights[1].position.w = 1.0;
    gl.lights[2].position.w = 1.0;
    gl.lights[2].spot_cutoff = 30.0;
    assert_eq!(variants(key(&gl)), [0, 0, 0]);
    // A soft edge without a cone (cutoff 180) and glTF's falloff on a directional light do
    // nothing: the same key as GL's.
    let mut inert = gl;
    inert.lights[0].spot_edge = SpotEdge::LinearInnerOuter { inner_degrees: 10.0 };
    inert.lights[0].attenuation = Attenuation::GltfInverseSquare { range: None };
    assert_eq!(key(&inert), key(&gl));
    // Each variant that acts sets its own constant, and only it.
    let mut soft = gl;
    soft.lights[2].spot_edge = SpotEdge::SmoothstepInnerOuter { inner_degrees: 10.0 };
    assert_eq!(variants(key(&soft)), [0, 1, 0]);
    let mut falloff = gl;
    falloff.lights[1].attenuation = Attenuation::GltfInverseSquare { range: Some(3.0) };
    assert_eq!(variants(key(&falloff)), [0, 0, 1]);
    let mut phong = gl;
    phong.model.specular_model = SpecularModel::PhongReflect;
    assert_eq!(variants(key(&phong)), [1, 0, 0]);
    // A disabled light's variants count for nothing.
    let mut disabled = gl;
    disabled.lights[7].position.w = 1.0;
    disabled.lights[7].spot_cutoff = 20.0;
    disabled.lights[7].spot_edge = SpotEdge::LinearInnerOuter { inner_degrees: 5.0 };
    disabled.lights[7].attenuation = Attenuation::GltfInverseSquare { range: None };
    assert_eq!(key(&disabled), key(&gl));
}

#[test]
fn one_sided_single_color_states_pass_one_color_between_the_stages() {
    use ffvk::draw::pipeline::variant_name;
    let key = |s: &FixedFunctionState| SpecKey::for_state(s);
    let one_sided = lit(2, LightingMode::Vertex);
    let mut two_sided = one_sided;
    two_sided.model.two_side = true;
    let mut separate = one_sided;
    separate.model.color_control = ColorControl::SeparateSpecularColor;
    let flat = lit(2, LightingMode::Flat);
    assert_eq!(
        variant_name(LightingMode::Vertex, key(&one_sided), false, false),
        "vertex_one_color"
    );
    assert_eq!(
        variant_name(LightingMode::Flat, key(&flat), false, false),
        "flat_one_color"
    );
    assert_eq!(
        variant_name(LightingMode::Vertex, key(&unlit()), false, false),
        "vertex_one_color"
    );
    for s in [two_sided, separate] {
        assert_eq!(
            variant_name(LightingMode::Vertex, key(&s), false, false),
            "vertex"
        );
    }
    // The uber-shader passes every color; fragment mode has one pair of stages.
    assert_eq!(
        variant_name(LightingMode::Vertex, SpecKey::UBER, false, false),
        "vertex"
    );
    assert_eq!(
        variant_name(LightingMode::Fragment, key(&one_sided), false, false),
        "fragment"
    );
    // A small draw of the fragment mode passes its materials as flat varyings; the other
    // modes have no such variant.
    assert_eq!(
        variant_name(LightingMode::Fragment, key(&one_sided), true, true),
        "fragment_small_textured"
    );
    assert_eq!(
        variant_name(LightingMode::Vertex, key(&two_sided), false, true),
        "vertex"
    );
    // A textured draw takes the textured build of the same variant.
    assert_eq!(
        variant_name(LightingMode::Flat, key(&flat), true, false),
        "flat_one_color_textured"
    );
}

/// `SPEC_FINITE_VERTICES` (VP_pli and ĥ_i taken from a directional light's derived state) is
/// promised only where it holds: lit, with at least one directional light, and a draw whose
/// modelview is affine (w = 1 at every vertex); `SPEC_DIRECTIONAL_LIGHTS` and
/// `SPEC_SPOT_LIGHTS` name each enabled light's kind, in packed order, so that a positional
/// light beside directional ones is evaluated in full and the directional ones are not. The
/// uber-shader's key keeps them unset.
#[test]
fn directional_lights_take_their_derived_state_only_at_affine_modelviews() {
    let finite =
        |s: &FixedFunctionState, mv: Mat4| SpecKey::for_draw(s, mv).get(SpecConstant::FiniteVertices);
    let affine = Mat4::from_translation(Vec3::new(0.0, 0.0, -2.0));
    let mut projective = affine;
    projective.w_axis.w = 2.0;
    let directional = lit(2, LightingMode::Vertex);
    assert_eq!(finite(&directional, affine), 1);
    assert_eq!(finite(&directional, projective), 0);
    let mut mixed = directional;
    mixed.lights[1].position.w = 1.0;
    assert_eq!(finite(&mixed, affine), 1, "light 0 is still directional");
    let kinds = |s: &FixedFunctionState| {
        let key = SpecKey::for_draw(s, affine);
        (
            key.get(SpecConstant::DirectionalLights),
            key.get(SpecConstant::SpotLights),
        )
    };
    assert_eq!(kinds(&directional), (0b11, 0));
    assert_eq!(kinds(&mixed), (0b01, 0));
    mixed.lights[1].spot_cutoff = 30.0;
    assert_eq!(kinds(&mixed), (0b01, 0b10));
    // Packed order: with light 0 disabled, light 1 is the first packed light.
    mixed.lights[0].enabled = false;
    assert_eq!(kinds(&mixed), (0b00, 0b01));
    assert_eq!(finite(&mixed, affine), 0, "no directional light left");
    assert_eq!(SpecKey::UBER.get(SpecConstant::DirectionalLights), -1);
    assert_eq!(finite(&lit(0, LightingMode::Vertex), affine), 0);
    assert_eq!(finite(&unlit(), affine), 0);
    assert_eq!(SpecKey::UBER.with_finite_vertices(true), SpecKey::UBER);
}

/// A modelview that is not affine takes the full P1P2 formula in a pipeline of its own; drawn
/// as 2·M (w = 2 at every vertex: the same points, and with NORMALIZE the same normals), it
/// lights as M does, in every mode, within the rounding of the host's derived state.
#[test]
fn a_projective_modelview_lights_as_its_affine_equal_in_a_pipeline_of_its_own() {
    let mut r = renderer_with(Specialize::Always);
    let sphere = r.upload(&ffvk::mesh::MeshData::uv_sphere(24, 12)).unwrap();
    let affine = Mat4::from_translation(Vec3::new(0.2, -0.1, -3.0));
    let projective = affine * 2.0;
    for mode in LightingMode::ALL {
        let state = with(dark(), |gl| {
            for i in 0..3 {
                gl.enable(Cap::Light(i))?;
                gl.light(i, LightParam::Position(Vec4::new(i as f32 - 1.0, 1.0, 0.5, 0.0)))?;
                gl.light(i, LightParam::Diffuse(Vec4::new(0.6, 0.5, 0.4, 1.0)))?;
                gl.light(i, LightParam::Specular(Vec4::ONE))?;
            }
            gl.material(Face::FrontAndBack, MaterialParam::Specular(Vec4::splat(0.8)))?;
            gl.material(Face::FrontAndBack, MaterialParam::Shininess(20.0))?;
            gl.enable(Cap::Normalize)?;
            gl.lighting_mode(mode);
            Ok(())
        })
        .lighting;
        let image = |r: &mut Renderer, mv: Mat4| {
            let mut frame = Frame::new(64, 64);
            frame
                .draws
                .push(Draw::new(&sphere, mv, perspective(45.0, 1.0, 0.5, 10.0), state));
            r.render(&frame).unwrap().into_rgba_image()
        };
        let a = image(&mut r, affine);
        let before = r.pipeline_counts().0;
        let p = image(&mut r, projective);
        assert_eq!(
            r.pipeline_counts().0,
            before + 1,
            "{mode:?}: a pipeline of its own"
        );
        let worst = a
            .pixels()
            .zip(p.pixels())
            .flat_map(|(x, y)| (0..4).map(move |c| x.0[c].abs_diff(y.0[c])))
            .max()
            .unwrap();
        assert!(worst <= 1, "{mode:?}: {worst}/255 apart");
        let lit_pixels = a.pixels().filter(|px| px.0[0] > 40).count();
        assert!(lit_pixels > 400, "{mode:?}: {lit_pixels} lit pixels");
    }
    finish(r);
}
