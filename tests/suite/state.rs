//! GL's state semantics: defaults (table 2.10), validation, and light positions and spot
//! directions transformed by the modelview in force when they are set.

use ffvk::gl::state::*;
use ffvk::gpu::layout::DrawBlock;
use glam::{Mat4, Vec3, Vec4};

fn close(a: Vec4, b: Vec4) -> bool {
    (a - b).abs().max_element() < 1e-6
}

#[test]
fn defaults_are_gls() {
    let gl = GlState::new();
    let s = &gl.lighting;
    assert!(!s.lighting, "LIGHTING starts disabled");
    assert_eq!(s.front, s.back);
    assert_eq!(s.front.ambient, Vec4::new(0.2, 0.2, 0.2, 1.0));
    assert_eq!(s.front.diffuse, Vec4::new(0.8, 0.8, 0.8, 1.0));
    assert_eq!(s.front.specular, Vec4::new(0.0, 0.0, 0.0, 1.0));
    assert_eq!(s.front.emission, Vec4::new(0.0, 0.0, 0.0, 1.0));
    assert_eq!(s.front.shininess, 0.0);
    for (i, l) in s.lights.iter().enumerate() {
        assert!(!l.enabled, "light {i} starts disabled");
        assert_eq!(l.ambient, Vec4::new(0.0, 0.0, 0.0, 1.0));
        let white_or_black = if i == 0 {
            Vec4::ONE
        } else {
            Vec4::new(0.0, 0.0, 0.0, 1.0)
        };
        assert_eq!(l.diffuse, white_or_black, "light {i} diffuse");
        assert_eq!(l.specular, white_or_black, "light {i} specular");
        assert_eq!(l.position, Vec4::new(0.0, 0.0, 1.0, 0.0));
        assert_eq!(l.spot_direction, Vec3::new(0.0, 0.0, -1.0));
        assert_eq!((l.spot_exponent, l.spot_cutoff), (0.0, 180.0));
        assert_eq!(
            (
                l.constant_attenuation,
                l.linear_attenuation,
                l.quadratic_attenuation
            ),
            (1.0, 0.0, 0.0)
        );
    }
    const { assert!(MAX_LIGHTS >= 8) };
    assert_eq!(s.model.ambient, Vec4::new(0.2, 0.2, 0.2, 1.0));
    assert!(!s.model.local_viewer && !s.model.two_side);
    assert_eq!(s.model.color_control, ColorControl::SingleColor);
    assert!(!s.color_material.enabled);
    assert_eq!(s.color_material.face, Face::FrontAndBack);
    assert_eq!(s.color_material.mode, ColorMaterialMode::AmbientAndDiffuse);
    assert!(!s.normalize && !s.rescale_normal);
    assert_eq!(s.mode, LightingMode::Vertex);
    assert_eq!(gl.modelview, Mat4::IDENTITY);
}

#[test]
fn light_position_takes_the_modelview_at_specification_time() {
    let mut gl = GlState::new();
    let view =
        Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0)) * Mat4::from_rotation_y(std::f32::consts::FRAC_PI_2);
    gl.load_modelview(view).unwrap();
    gl.light(1, LightParam::Position(Vec4::new(1.0, 0.0, 0.0, 1.0)))
        .unwrap();
    gl.light(2, LightParam::Position(Vec4::new(1.0, 0.0, 0.0, 0.0)))
        .unwrap();
    gl.light(1, LightParam::SpotDirection(Vec3::new(1.0, 0.0, 0.0)))
        .unwrap();
    // Rotating +x by 90° about y gives -z; the point then moves by the translation.
    let l = gl.lighting.lights[1];
    assert!(
        close(l.position, Vec4::new(1.0, 2.0, 2.0, 1.0)),
        "{:?}",
        l.position
    );
    assert!(
        close(gl.lighting.lights[2].position, Vec4::new(0.0, 0.0, -1.0, 0.0)),
        "directions ignore translation"
    );
    assert!(
        close(l.spot_direction.extend(0.0), Vec4::new(0.0, 0.0, -1.0, 0.0)),
        "{:?}",
        l.spot_direction
    );
    // A later modelview does not move lights already set.
    gl.load_modelview(Mat4::from_scale(Vec3::splat(5.0))).unwrap();
    assert_eq!(gl.lighting.lights[1], l);
    // mult_modelview composes like glMultMatrix.
    gl.mult_modelview(Mat4::from_translation(Vec3::X)).unwrap();
    gl.light(3, LightParam::Position(Vec4::new(0.0, 0.0, 0.0, 1.0)))
        .unwrap();
    assert!(close(
        gl.lighting.lights[3].position,
        Vec4::new(5.0, 0.0, 0.0, 1.0)
    ));
}

fn rejected(result: Result<(), StateError>, parameter: &str, value: &str, valid: &str) {
    let err = result.expect_err("GL rejects this value");
    let text = err.to_string();
    for part in [parameter, value, valid] {
        assert!(text.contains(part), "{text:?} should mention {part:?}");
    }
}

#[test]
fn out_of_range_values_are_rejected_with_parameter_value_and_range() {
    let mut gl = GlState::new();
    let before = gl.clone();
    for bad in [-1.0, 90.5, 179.9, 180.1, 360.0] {
        rejected(
            gl.light(0, LightParam::SpotCutoff(bad)),
            "GL_SPOT_CUTOFF",
            &bad.to_string(),
            "[0, 90] or exactly 180",
        );
    }
    for bad in [-0.5, 128.5] {
        rejected(
            gl.light(0, LightParam::SpotExponent(bad)),
            "GL_SPOT_EXPONENT",
            &bad.to_string(),
            "[0, 128]",
        );
    }
    rejected(
        gl.light(0, LightParam::ConstantAttenuation(-1.0)),
        "GL_CONSTANT_ATTENUATION",
        "-1",
        ">= 0",
    );
    rejected(
        gl.light(0, LightParam::LinearAttenuation(-0.1)),
        "GL_LINEAR_ATTENUATION",
        "-0.1",
        ">= 0",
    );
    rejected(
        gl.light(0, LightParam::QuadraticAttenuation(-2.0)),
        "GL_QUADRATIC_ATTENUATION",
        "-2",
        ">= 0",
    );
    rejected(
        gl.material(Face::Front, MaterialParam::Shininess(128.5)),
        "GL_SHININESS",
        "128.5",
        "[0, 128]",
    );
    rejected(
        gl.material(Face::Back, MaterialParam::Shininess(-1.0)),
        "GL_SHININESS",
        "-1",
        "[0, 128]",
    );
    rejected(
        gl.light(MAX_LIGHTS, LightParam::Ambient(Vec4::ONE)),
        "light index 16",
        "16",
        "0..16",
    );
    rejected(gl.enable(Cap::Light(99)), "light index 99", "99", "GL_MAX_LIGHTS");
    rejected(
        gl.light(0, LightParam::SpotExponent(f32::NAN)),
        "GL_SPOT_EXPONENT",
        "NaN",
        "[0, 128]",
    );
    rejected(
        gl.light(0, LightParam::Diffuse(Vec4::new(1.0, f32::INFINITY, 0.0, 1.0))),
        "GL_DIFFUSE",
        "inf",
        "finite",
    );
    rejected(
        gl.light(0, LightParam::Position(Vec4::new(f32::NAN, 0.0, 0.0, 1.0))),
        "GL_POSITION",
        "NaN",
        "finite",
    );
    rejected(
        gl.light(
            0,
            LightParam::SpotDirection(Vec3::new(0.0, f32::NEG_INFINITY, 0.0)),
        ),
        "GL_SPOT_DIRECTION",
        "-inf",
        "finite",
    );
    rejected(
        gl.material(Face::FrontAndBack, MaterialParam::Emission(Vec4::splat(f32::NAN))),
        "GL_EMISSION",
        "NaN",
        "finite",
    );
    rejected(
        gl.light_model(LightModelParam::Ambient(Vec4::splat(f32::INFINITY))),
        "GL_LIGHT_MODEL_AMBIENT",
        "inf",
        "finite",
    );
    rejected(
        gl.load_modelview(Mat4::from_scale(Vec3::splat(f32::NAN))),
        "modelview",
        "NaN",
        "finite",
    );
    assert_eq!(gl, before, "rejected calls leave the state unchanged");
}

#[test]
fn boundary_values_are_accepted() {
    let mut gl = GlState::new();
    for ok in [0.0, 45.0, 90.0, 180.0] {
        gl.light(0, LightParam::SpotCutoff(ok)).unwrap();
    }
    for ok in [0.0, 128.0] {
        gl.light(7, LightParam::SpotExponent(ok)).unwrap();
        gl.material(Face::Front, MaterialParam::Shininess(ok)).unwrap();
    }
    gl.light(MAX_LIGHTS - 1, LightParam::LinearAttenuation(0.0))
        .unwrap();
    // Colors are unrestricted: negative and above 1 are legal.
    gl.light(0, LightParam::Diffuse(Vec4::new(-2.0, 5.0, 0.0, 1.0)))
        .unwrap();
    gl.material(
        Face::Back,
        MaterialParam::AmbientAndDiffuse(Vec4::new(3.0, -1.0, 0.5, 0.5)),
    )
    .unwrap();
    assert_eq!(gl.lighting.back.ambient, gl.lighting.back.diffuse);
    assert_eq!(
        gl.lighting.front.diffuse,
        Vec4::new(0.8, 0.8, 0.8, 1.0),
        "FRONT untouched by BACK"
    );
}

#[test]
fn state_built_by_hand_is_validated_before_it_reaches_the_gpu() {
    let mut state = FixedFunctionState::default();
    state.lights[4].spot_cutoff = 100.0;
    let err = DrawBlock::new(&state, Mat4::IDENTITY, Mat4::IDENTITY).unwrap_err();
    assert!(err.to_string().contains("GL_SPOT_CUTOFF = 100"), "{err}");
    let mut state = FixedFunctionState::default();
    state.front.shininess = f32::NAN;
    assert!(DrawBlock::new(&state, Mat4::IDENTITY, Mat4::IDENTITY).is_err());
}

#[test]
fn enabled_lights_pack_in_index_order() {
    let mut gl = GlState::new();
    for i in [5, 1, 9] {
        gl.enable(Cap::Light(i)).unwrap();
        gl.light(i, LightParam::Ambient(Vec4::new(i as f32, 0.0, 0.0, 1.0)))
            .unwrap();
    }
    let block = DrawBlock::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY).unwrap();
    assert_eq!(block.state.light_count, 3);
    let order: Vec<f32> = block.state.lights[..3].iter().map(|l| l.a_cli[0]).collect();
    assert_eq!(order, [1.0, 5.0, 9.0]);
}

#[test]
fn shade_model_and_lighting_mode() {
    let mut gl = GlState::new();
    gl.shade_model(ShadeModel::Flat);
    assert_eq!(gl.lighting.mode, LightingMode::Flat);
    gl.shade_model(ShadeModel::Smooth);
    assert_eq!(gl.lighting.mode, LightingMode::Vertex);
    gl.lighting_mode(LightingMode::Fragment);
    assert_eq!(gl.lighting.mode, LightingMode::Fragment);
    assert_eq!("fragment".parse::<LightingMode>(), Ok(LightingMode::Fragment));
    let err = "phong".parse::<LightingMode>().unwrap_err();
    assert_eq!((err.what, err.value.as_str()), ("lighting mode", "phong"));
    assert_eq!(
        err.to_string(),
        r#"unknown lighting mode "phong": expected vertex, fragment or flat"#
    );
}

#[test]
fn states_that_would_light_with_nan_are_rejected_at_draw_time() {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    let flat = Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0));
    let err = DrawBlock::new(&gl.lighting, flat, Mat4::IDENTITY)
        .unwrap_err()
        .to_string();
    assert!(err.contains("modelview") && err.contains("= 0"), "{err}");
    // Unlit drawing needs no normal matrix: a flattening modelview is fine.
    gl.disable(Cap::Lighting).unwrap();
    DrawBlock::new(&gl.lighting, flat, Mat4::IDENTITY).unwrap();

    gl.enable(Cap::Lighting).unwrap();
    gl.enable(Cap::Light(2)).unwrap();
    gl.light(2, LightParam::Position(Vec4::new(0.0, 1.0, 0.0, 1.0)))
        .unwrap();
    gl.light(2, LightParam::ConstantAttenuation(0.0)).unwrap();
    let err = DrawBlock::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("GL_CONSTANT_ATTENUATION + GL_LINEAR_ATTENUATION") && err.contains("> 0"),
        "{err}"
    );
    // Directional lights are never attenuated: all-zero factors are harmless there.
    gl.light(2, LightParam::Position(Vec4::new(0.0, 1.0, 0.0, 0.0)))
        .unwrap();
    DrawBlock::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY).unwrap();
}

#[test]
fn the_lighting_variants_default_to_gls_and_refuse_impossible_cones_and_ranges() {
    let gl = GlState::new();
    assert_eq!(gl.lighting.model.specular_model, SpecularModel::BlinnHalfway);
    for l in &gl.lighting.lights {
        assert_eq!(
            (l.spot_edge, l.attenuation),
            (SpotEdge::GlExponent, Attenuation::GlK012)
        );
    }
    let mut gl = GlState::new();
    // An inner angle past 90°, or a range that is not positive, is refused at once and
    // changes nothing.
    let e = gl
        .light(
            2,
            LightParam::SpotEdge(SpotEdge::LinearInnerOuter { inner_degrees: 95.0 }),
        )
        .unwrap_err();
    assert!(
        e.to_string().contains("95") && e.to_string().contains("[0, 90]"),
        "{e}"
    );
    for range in [-1.0, 0.0, f32::NAN] {
        let e = gl
            .light(
                2,
                LightParam::Attenuation(Attenuation::GltfInverseSquare { range: Some(range) }),
            )
            .unwrap_err();
        assert!(e.to_string().contains("range"), "{e}");
    }
    assert_eq!(gl.lighting.lights[2].spot_edge, SpotEdge::GlExponent);
    assert_eq!(gl.lighting.lights[2].attenuation, Attenuation::GlK012);
    // An inner cone wider than the outer may be set in either order; drawing refuses it,
    // naming the light and both angles.
    gl.light(
        2,
        LightParam::SpotEdge(SpotEdge::SmoothstepInnerOuter { inner_degrees: 30.0 }),
    )
    .unwrap();
    gl.light(2, LightParam::SpotCutoff(20.0)).unwrap();
    // Disabled, the light may stay half set up; enabled, it is drawn and refused.
    assert!(gl.lighting.validate().is_ok());
    gl.enable(Cap::Light(2)).unwrap();
    let e = gl.lighting.validate().unwrap_err();
    assert_eq!(
        e,
        StateError::SpotCone {
            light: 2,
            inner: 30.0,
            outer: 20.0
        }
    );
    assert!(
        e.to_string().starts_with(
            "light 2: the spot edge's inner angle 30° is wider than its outer angle (GL_SPOT_CUTOFF) 20°"
        ),
        "{e}"
    );
    gl.light(2, LightParam::SpotCutoff(30.0)).unwrap();
    assert!(gl.lighting.validate().is_ok());
}
