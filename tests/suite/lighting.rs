//! GPU against the CPU reference: every term alone and in combination, every trap of the
//! spec page, in each lighting mode, at probe pixels, within 1/255 per channel.

use ffvk::gl::state::*;
use ffvk::mesh::MeshData;
use ffvk::reference;
use ffvk::{Draw, Frame, Specialize};
use glam::{DVec4, Mat4, Vec3, Vec4};
use image::RgbaImage;

use crate::support::*;

const SIZE: u32 = 96;
/// Probes stay this many pixels away from every triangle edge, so that rasterization
/// tie-breaking cannot pick a different triangle than the reference.
const EDGE_MARGIN: f64 = 0.75;

/// What a scene draws.
pub struct Scene {
    pub mesh: MeshData,
    pub modelview: Mat4,
    pub projection: Mat4,
    pub gl: GlState,
}

fn sphere_scene(gl: GlState) -> Scene {
    Scene {
        mesh: MeshData::uv_sphere(24, 16),
        modelview: Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0)),
        projection: perspective(45.0, 1.0, 1.0, 10.0),
        gl,
    }
}

/// An open, gently curved sheet, tilted so that its back faces the viewer when `back`.
fn sheet_scene(gl: GlState, back: bool) -> Scene {
    let mesh = grid(
        8,
        |x, y| Vec3::new(0.3 * x, 0.2 * y, 1.0),
        |x, y| Vec4::new(0.5 + 0.5 * x, 0.5 + 0.5 * y, 0.8, 1.0),
    );
    let turn = if back {
        Mat4::from_rotation_y(std::f32::consts::PI)
    } else {
        Mat4::IDENTITY
    };
    Scene {
        mesh,
        modelview: Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0)) * Mat4::from_rotation_x(-0.4) * turn,
        projection: perspective(45.0, 1.0, 1.0, 10.0),
        gl,
    }
}

/// Renders `scene` in `state`'s mode with pipelines of the `specialize` variant.
fn render_variant(scene: &Scene, state: FixedFunctionState, specialize: Specialize) -> RgbaImage {
    let mut r = renderer_with(specialize);
    let mesh = r.upload(&scene.mesh).unwrap();
    let mut frame = Frame::new(SIZE, SIZE);
    frame.clear_color = Vec4::new(0.1, 0.2, 0.3, 1.0);
    frame
        .draws
        .push(Draw::new(&mesh, scene.modelview, scene.projection, state));
    let image = r.render(&frame).unwrap().into_rgba_image();
    // The variant really drew: one pipeline, specialized or not.
    let specialized = usize::from(specialize == Specialize::Always);
    assert_eq!(r.pipeline_counts(), (1, specialized), "{}", specialize.name());
    drop(frame);
    drop(mesh);
    finish(r);
    image
}

/// Renders `scene` in `mode`, with specialized pipelines and with the uber-shader, and
/// compares probe pixels of both images with the CPU reference.
fn check(name: &str, scene: &Scene, mode: LightingMode) {
    let mut state = scene.gl.lighting;
    state.mode = mode;
    let images: Vec<(Specialize, RgbaImage)> = VARIANTS
        .iter()
        .map(|&v| (v, render_variant(scene, state, v)))
        .collect();

    let v = &scene.mesh.vertices;
    let clips: Vec<DVec4> = v
        .iter()
        .map(|v| reference::transform(&state, scene.modelview, scene.projection, v).clip)
        .collect();
    let mut probes = 0;
    for py in (1..SIZE).step_by(2) {
        for px in (1..SIZE).step_by(2) {
            let Some((idx, cov)) = nearest_covering(&scene.mesh, &clips, SIZE, px, py) else {
                continue;
            };
            if !away_from_edges(idx.map(|i| clips[i]), px, py) {
                continue;
            }
            let tri = idx.map(|i| &v[i]);
            let want = reference::pixel_color(&state, scene.modelview, scene.projection, tri, cov, None);
            for (variant, image) in &images {
                let what = format!("{name} {} {}", mode.name(), variant.name());
                assert_pixel(image, px, py, want, 1.0, &what);
            }
            probes += 1;
        }
    }
    assert!(
        probes > 60,
        "{name}: only {probes} probes landed inside triangles"
    );
}

/// Whether the pixel center is at least EDGE_MARGIN pixels inside the triangle.
fn away_from_edges(clip: [DVec4; 3], px: u32, py: u32) -> bool {
    let p = clip.map(|c| reference::window(c, SIZE, SIZE));
    let (x, y) = (px as f64 + 0.5, py as f64 + 0.5);
    (0..3).all(|i| {
        let (a, b) = (p[i], p[(i + 1) % 3]);
        let len = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        let dist = ((b.0 - a.0) * (y - a.1) - (b.1 - a.1) * (x - a.0)).abs() / len;
        dist >= EDGE_MARGIN
    })
}

/// One test per scene, each checking the three modes.
macro_rules! scenes {
    ($($name:ident => $scene:expr;)*) => {
        $(
            #[test]
            fn $name() {
                let scene: Scene = $scene;
                for mode in LightingMode::ALL {
                    check(stringify!($name), &scene, mode);
                }
            }
        )*
    };
}

scenes! {
    lighting_off_passes_the_vertex_color => sheet_scene(GlState::new(), false);
    lighting_off_clamps_out_of_range_colors => {
        // Section 2.14.6: clamped at the vertex whether lighting is on or not, so Gouraud
        // interpolates clamped colors.
        let mut scene = sheet_scene(GlState::new(), false);
        scene.mesh = grid(6, |_, _| Vec3::Z, |x, y| Vec4::new(3.0 * x, -2.0 * y, 1.5, 2.0 - x));
        scene
    };
    spot_cutoff_90_exponent_0_lights_behind_the_light => spot_90(0.0);
    spot_cutoff_90_exponent_1 => spot_90(1.0);
    gl_defaults_with_light_0 => sphere_scene(lit_state());
    emission_only => sphere_scene(with(dark(), |gl| {
        gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
        gl.material(Face::Front, MaterialParam::Emission(rgba(0.3, 0.5, 0.7, 1.0)))
    }));
    scene_ambient_only => sphere_scene(with(dark(), |gl| {
        gl.light_model(LightModelParam::Ambient(rgba(0.4, 0.6, 0.8, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Ambient(rgba(0.9, 0.5, 0.25, 1.0)))
    }));
    light_ambient_only => sphere_scene(with(dark(), |gl| {
        gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
        gl.enable(Cap::Light(3))?;
        gl.light(3, LightParam::Ambient(rgba(0.5, 0.7, 0.9, 1.0)))
    }));
    diffuse_directional => sphere_scene(with(dark(), |gl| {
        gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
        gl.enable(Cap::Light(1))?;
        gl.light(1, LightParam::Diffuse(rgba(0.9, 0.8, 0.6, 1.0)))?;
        gl.light(1, LightParam::Position(Vec4::new(1.0, 1.0, 1.0, 0.0)))
    }));
    specular_shininess_zero_is_one => sphere_scene(with(dark(), |gl| {
        // 0^0 = 1: wherever n · L > 0 the specular term is s_cm * s_cli.
        gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(Vec4::ZERO))?;
        gl.light(0, LightParam::Position(Vec4::new(1.0, 0.0, 0.3, 0.0)))?;
        gl.material(Face::Front, MaterialParam::Specular(rgba(0.6, 0.5, 0.4, 1.0)))
    }));
    specular_infinite_viewer => sphere_scene(with(dark(), |gl| {
        gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(Vec4::ZERO))?;
        gl.light(0, LightParam::Position(Vec4::new(-1.0, 1.0, 1.0, 0.0)))?;
        gl.material(Face::Front, MaterialParam::Specular(rgba(1.0, 0.9, 0.8, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Shininess(20.0))
    }));
    specular_local_viewer => sphere_scene(with(dark(), |gl| {
        gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
        gl.light_model(LightModelParam::LocalViewer(true))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(Vec4::ZERO))?;
        gl.light(0, LightParam::Position(Vec4::new(-1.0, 1.0, 1.0, 0.0)))?;
        gl.material(Face::Front, MaterialParam::Specular(rgba(1.0, 0.9, 0.8, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Shininess(20.0))
    }));
    specular_needs_light_in_front_f_i => sphere_scene(with(dark(), |gl| {
        // The light sits behind the sphere's visible side: f_i must remove the highlight the
        // halfway vector would otherwise put on the rim.
        gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(Vec4::ZERO))?;
        gl.light(0, LightParam::Position(Vec4::new(0.0, 0.2, -1.0, 0.0)))?;
        gl.material(Face::Front, MaterialParam::Specular(Vec4::ONE))?;
        gl.material(Face::Front, MaterialParam::Shininess(1.0))
    }));
    point_light_with_attenuation => sphere_scene(with(dark(), |gl| {
        gl.enable(Cap::Light(2))?;
        gl.light(2, LightParam::Diffuse(rgba(2.0, 1.8, 1.5, 1.0)))?;
        gl.light(2, LightParam::Specular(rgba(1.0, 1.0, 1.0, 1.0)))?;
        gl.light(2, LightParam::Position(Vec4::new(1.5, 1.0, -1.5, 1.0)))?;
        gl.light(2, LightParam::ConstantAttenuation(0.5))?;
        gl.light(2, LightParam::LinearAttenuation(0.3))?;
        gl.light(2, LightParam::QuadraticAttenuation(0.2))?;
        gl.material(Face::Front, MaterialParam::Specular(rgba(0.5, 0.5, 0.5, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Shininess(40.0))
    }));
    spot_exponent_zero_hard_edge => sphere_scene(with(dark(), |gl| {
        gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 0.0, 1.0)))?;
        gl.light(0, LightParam::SpotDirection(Vec3::new(0.1, 0.2, -1.0)))?;
        gl.light(0, LightParam::SpotCutoff(12.0))
    }));
    spot_exponent_soft => sphere_scene(with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(1.0, 1.0, 0.0, 1.0)))?;
        gl.light(0, LightParam::SpotDirection(Vec3::new(-1.0, -1.0, -3.0)))?;
        gl.light(0, LightParam::SpotCutoff(30.0))?;
        gl.light(0, LightParam::SpotExponent(20.0))
    }));
    spot_on_a_directional_light => sphere_scene(with(dark(), |gl| {
        // w = 0: P_pliV is the negated light direction, which the cone still applies to.
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 0.0)))?;
        gl.light(0, LightParam::SpotDirection(Vec3::new(0.0, 0.0, -1.0)))?;
        gl.light(0, LightParam::SpotCutoff(10.0))?;
        gl.light(0, LightParam::SpotExponent(2.0))
    }));
    spot_pointing_away_is_dark => sphere_scene(with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 0.0, 1.0)))?;
        gl.light(0, LightParam::SpotDirection(Vec3::new(0.0, 0.0, 1.0)))?;
        gl.light(0, LightParam::SpotCutoff(60.0))
    }));
    phong_reflect_infinite_viewer => sphere_scene(with(specular_scene(), |gl| {
        gl.light_model(LightModelParam::SpecularModel(SpecularModel::PhongReflect))
    }));
    phong_reflect_local_viewer_separate_specular => sphere_scene(with(specular_scene(), |gl| {
        gl.light_model(LightModelParam::SpecularModel(SpecularModel::PhongReflect))?;
        gl.light_model(LightModelParam::LocalViewer(true))?;
        gl.light_model(LightModelParam::ColorControl(ColorControl::SeparateSpecularColor))
    }));
    phong_reflect_light_behind_keeps_f_i => sphere_scene(with(dark(), |gl| {
        // r_i can point at the viewer while the light is behind the surface: f_i removes it.
        gl.light_model(LightModelParam::SpecularModel(SpecularModel::PhongReflect))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(Vec4::ZERO))?;
        gl.light(0, LightParam::Position(Vec4::new(0.0, 0.2, -1.0, 0.0)))?;
        gl.material(Face::Front, MaterialParam::Specular(Vec4::ONE))?;
        gl.material(Face::Front, MaterialParam::Shininess(1.0))
    }));
    spot_linear_inner_outer => sphere_scene(soft_spot(SpotEdge::LinearInnerOuter { inner_degrees: 10.0 }));
    spot_smoothstep_inner_outer => sphere_scene(soft_spot(SpotEdge::SmoothstepInnerOuter { inner_degrees: 10.0 }));
    spot_soft_edge_with_equal_cones_is_a_hard_cutoff => sphere_scene(with(soft_spot(SpotEdge::LinearInnerOuter { inner_degrees: 12.0 }), |gl| gl.light(0, LightParam::SpotCutoff(12.0))));
    gltf_inverse_square_without_range => sphere_scene(gltf_point(None));
    gltf_inverse_square_with_a_range_across_the_sphere => sphere_scene(gltf_point(Some(3.2)));
    gl_and_variant_lights_in_one_draw => sphere_scene(with(soft_spot(SpotEdge::SmoothstepInnerOuter { inner_degrees: 5.0 }), |gl| {
        // Light 1 keeps GL's edge and falloff beside light 0's soft edge and light 2's glTF
        // falloff: each light reads its own.
        gl.light_model(LightModelParam::SpecularModel(SpecularModel::PhongReflect))?;
        gl.enable(Cap::Light(1))?;
        gl.light(1, LightParam::Diffuse(rgba(0.2, 0.4, 0.1, 1.0)))?;
        gl.light(1, LightParam::Position(Vec4::new(-1.0, 0.5, -1.0, 1.0)))?;
        gl.light(1, LightParam::SpotDirection(Vec3::new(1.0, -0.5, -2.0)))?;
        gl.light(1, LightParam::SpotCutoff(40.0))?;
        gl.light(1, LightParam::SpotExponent(4.0))?;
        gl.light(1, LightParam::QuadraticAttenuation(0.3))?;
        gl.enable(Cap::Light(2))?;
        gl.light(2, LightParam::Diffuse(rgba(1.5, 0.5, 0.5, 1.0)))?;
        gl.light(2, LightParam::Position(Vec4::new(1.2, -1.0, -1.5, 1.0)))?;
        gl.light(2, LightParam::Attenuation(Attenuation::GltfInverseSquare { range: Some(2.5) }))
    }));
    eight_mixed_lights => sphere_scene(eight_lights(dark()));
    sixteen_lights => sphere_scene(with(dark(), |gl| {
        for i in 0..MAX_LIGHTS {
            let a = i as f32 * 0.4;
            gl.enable(Cap::Light(i))?;
            gl.light(i, LightParam::Diffuse(rgba(0.08, 0.06, 0.05, 1.0)))?;
            gl.light(i, LightParam::Position(Vec4::new(a.cos(), a.sin(), 1.0, 0.0)))?;
        }
        Ok(())
    }));
    over_bright_clamps_per_vertex => sphere_scene(with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(rgba(4.0, 2.0, 0.5, 1.0)))?;
        gl.light(0, LightParam::Position(Vec4::new(0.5, 0.5, 1.0, 0.0)))
    }));
    negative_colors_subtract => sphere_scene(with(dark(), |gl| {
        gl.light_model(LightModelParam::Ambient(rgba(1.0, 1.0, 1.0, 1.0)))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(rgba(-0.6, -0.3, 0.0, 1.0)))?;
        gl.light(0, LightParam::Position(Vec4::new(1.0, 0.0, 1.0, 0.0)))
    }));
    separate_specular_color => sphere_scene(with(specular_scene(), |gl| {
        gl.light_model(LightModelParam::ColorControl(ColorControl::SeparateSpecularColor))
    }));
    alpha_comes_from_diffuse => sphere_scene(with(lit_state(), |gl| {
        gl.material(Face::Front, MaterialParam::Diffuse(rgba(0.5, 0.6, 0.7, 0.25)))?;
        gl.material(Face::Front, MaterialParam::Ambient(rgba(0.5, 0.6, 0.7, 0.9)))
    }));
    two_sided_back_uses_back_material_and_minus_n => sheet_scene(two_sided(true), true);
    two_sided_front => sheet_scene(two_sided(true), false);
    one_sided_back_uses_front_material_and_n => sheet_scene(two_sided(false), true);
    color_material_ambient_and_diffuse => sheet_scene(color_material(Face::FrontAndBack, ColorMaterialMode::AmbientAndDiffuse), false);
    color_material_ambient => sheet_scene(color_material(Face::FrontAndBack, ColorMaterialMode::Ambient), false);
    color_material_diffuse => sheet_scene(color_material(Face::Front, ColorMaterialMode::Diffuse), false);
    color_material_specular => sheet_scene(color_material(Face::FrontAndBack, ColorMaterialMode::Specular), false);
    color_material_emission => sheet_scene(color_material(Face::FrontAndBack, ColorMaterialMode::Emission), false);
    color_material_back_only_leaves_front => sheet_scene(color_material(Face::Back, ColorMaterialMode::Diffuse), false);
    color_material_back_face_two_sided => sheet_scene(with(color_material(Face::Back, ColorMaterialMode::Diffuse), |gl| {
        gl.light_model(LightModelParam::TwoSide(true))
    }), true);
    eight_lights_local_viewer_two_sided_color_material_back => sheet_scene(combined(), true);
    eight_lights_local_viewer_two_sided_color_material_front => sheet_scene(combined(), false);
    zero_normals_stay_finite_under_normalize => {
        // Normals vanish at the grid's center column: NORMALIZE must not turn them into NaN.
        let mut scene = sheet_scene(with(specular_scene(), |gl| gl.enable(Cap::Normalize)), false);
        scene.mesh = grid(8, |x, _| Vec3::new(x, 0.0, x.abs()), |_, _| Vec4::ONE);
        scene
    };
    scaled_modelview_neither_normalize_nor_rescale => scaled(|_| Ok(()));
    scaled_modelview_normalize => scaled(|gl| gl.enable(Cap::Normalize));
    scaled_modelview_rescale_normal => scaled(|gl| gl.enable(Cap::RescaleNormal));
    light_position_set_under_a_view_matrix => {
        // The light is given in world space after loading a view that turns the world;
        // glLight stores it in eye space, and later modelview changes don't move it.
        let view = Mat4::look_at_rh(Vec3::new(2.0, 1.0, 3.0), Vec3::ZERO, Vec3::Y);
        let mut gl = dark();
        gl.load_modelview(view).unwrap();
        gl.enable(Cap::Light(0)).unwrap();
        gl.light(0, LightParam::Position(Vec4::new(0.0, 3.0, 0.0, 1.0))).unwrap();
        gl.light(0, LightParam::SpotDirection(Vec3::new(0.0, -1.0, 0.0))).unwrap();
        gl.light(0, LightParam::SpotCutoff(40.0)).unwrap();
        gl.load_modelview(Mat4::IDENTITY).unwrap();
        Scene {
            mesh: MeshData::uv_sphere(24, 16),
            modelview: view,
            projection: perspective(40.0, 1.0, 1.0, 10.0),
            gl,
        }
    };
}

/// A spotlight at the sphere's center aiming at +x with a 90° cone: with the spec's
/// `P_pliV ⊙ ŝ_dli ≥ cos(90°) = 0`, points behind it pass the test with (0)^s_rli.
fn spot_90(exponent: f32) -> Scene {
    let mut scene = sphere_scene(with(dark(), |gl| {
        gl.load_modelview(Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0)))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 0.0, 1.0)))?;
        gl.light(0, LightParam::SpotDirection(Vec3::new(1.0, 0.0, 0.0)))?;
        gl.light(0, LightParam::SpotCutoff(90.0))?;
        gl.light(0, LightParam::SpotExponent(exponent))?;
        gl.light(0, LightParam::Ambient(rgba(0.3, 0.5, 0.7, 1.0)))?;
        gl.load_modelview(Mat4::IDENTITY)
    }));
    scene.gl.lighting.normalize = true;
    scene
}

/// A spotlight at the eye aiming at the sphere, outer cone 25°, with `edge`; specular on so
/// that the edge shapes the highlight too.
fn soft_spot(edge: SpotEdge) -> GlState {
    with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(0.3, 0.2, 0.0, 1.0)))?;
        gl.light(0, LightParam::SpotDirection(Vec3::new(-0.1, -0.05, -1.0)))?;
        gl.light(0, LightParam::SpotCutoff(25.0))?;
        gl.light(0, LightParam::SpotExponent(30.0))?;
        gl.light(0, LightParam::SpotEdge(edge))?;
        gl.material(Face::Front, MaterialParam::Specular(rgba(0.5, 0.5, 0.5, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Shininess(16.0))
    })
}

/// A point light beside the sphere with glTF's inverse-square falloff (k0, k1 and k2 set to
/// values that would change the image if they were read).
fn gltf_point(range: Option<f32>) -> GlState {
    with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(rgba(3.0, 2.5, 2.0, 1.0)))?;
        gl.light(0, LightParam::Position(Vec4::new(1.5, 1.0, -1.2, 1.0)))?;
        gl.light(0, LightParam::ConstantAttenuation(5.0))?;
        gl.light(0, LightParam::LinearAttenuation(2.0))?;
        gl.light(
            0,
            LightParam::Attenuation(Attenuation::GltfInverseSquare { range }),
        )?;
        gl.material(Face::Front, MaterialParam::Specular(rgba(0.5, 0.5, 0.5, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Shininess(30.0))
    })
}

fn specular_scene() -> GlState {
    with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(-1.0, 1.0, 1.0, 0.0)))?;
        gl.material(Face::Front, MaterialParam::Diffuse(rgba(0.2, 0.3, 0.7, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Specular(rgba(0.9, 0.9, 0.9, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Shininess(12.0))
    })
}

fn eight_lights(gl: GlState) -> GlState {
    with(gl, |gl| {
        gl.light_model(LightModelParam::LocalViewer(true))?;
        let colors = [
            rgba(0.4, 0.1, 0.1, 1.0),
            rgba(0.1, 0.4, 0.1, 1.0),
            rgba(0.1, 0.1, 0.4, 1.0),
            rgba(0.3, 0.3, 0.0, 1.0),
        ];
        for i in 0..8 {
            gl.enable(Cap::Light(i))?;
            let a = i as f32 * 0.8;
            gl.light(i, LightParam::Diffuse(colors[i % 4]))?;
            gl.light(i, LightParam::Specular(colors[(i + 1) % 4] * 2.0))?;
            gl.light(i, LightParam::Ambient(rgba(0.02, 0.02, 0.02, 1.0)))?;
            match i % 3 {
                0 => gl.light(i, LightParam::Position(Vec4::new(a.cos(), a.sin(), 0.8, 0.0)))?,
                1 => {
                    gl.light(
                        i,
                        LightParam::Position(Vec4::new(2.0 * a.cos(), 2.0 * a.sin(), -1.0, 1.0)),
                    )?;
                    gl.light(i, LightParam::LinearAttenuation(0.2))?;
                }
                _ => {
                    gl.light(i, LightParam::Position(Vec4::new(a.cos(), a.sin(), 0.0, 1.0)))?;
                    gl.light(i, LightParam::SpotDirection(Vec3::new(-a.cos(), -a.sin(), -3.0)))?;
                    gl.light(i, LightParam::SpotCutoff(25.0))?;
                    gl.light(i, LightParam::SpotExponent(5.0))?;
                }
            }
        }
        gl.material(Face::Front, MaterialParam::Specular(rgba(0.7, 0.7, 0.7, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Shininess(30.0))
    })
}

/// The acceptance scene: 8 mixed lights, local viewer, two-sided, color material.
fn combined() -> GlState {
    with(eight_lights(dark()), |gl| {
        gl.light_model(LightModelParam::TwoSide(true))?;
        gl.material(Face::Back, MaterialParam::Diffuse(rgba(0.3, 0.3, 0.9, 1.0)))?;
        gl.material(Face::Back, MaterialParam::Emission(rgba(0.05, 0.0, 0.1, 1.0)))?;
        gl.color_material(Face::Front, ColorMaterialMode::AmbientAndDiffuse);
        gl.enable(Cap::ColorMaterial)
    })
}

fn two_sided(on: bool) -> GlState {
    with(dark(), |gl| {
        gl.light_model(LightModelParam::TwoSide(on))?;
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(0.3, 0.5, 1.0, 0.0)))?;
        gl.enable(Cap::Light(1))?;
        gl.light(1, LightParam::Diffuse(rgba(0.2, 0.6, 0.3, 1.0)))?;
        gl.light(1, LightParam::Position(Vec4::new(-0.2, 0.1, -1.0, 0.0)))?;
        gl.material(Face::Front, MaterialParam::Diffuse(rgba(0.9, 0.3, 0.2, 1.0)))?;
        gl.material(Face::Back, MaterialParam::Diffuse(rgba(0.2, 0.4, 0.9, 1.0)))?;
        gl.material(Face::Back, MaterialParam::Specular(rgba(0.5, 0.5, 0.5, 1.0)))?;
        gl.material(Face::Back, MaterialParam::Shininess(10.0))
    })
}

fn color_material(face: Face, mode: ColorMaterialMode) -> GlState {
    with(specular_scene(), |gl| {
        gl.color_material(face, mode);
        gl.enable(Cap::ColorMaterial)?;
        gl.light(0, LightParam::Position(Vec4::new(0.2, 0.4, 1.0, 0.0)))?;
        gl.light(0, LightParam::Ambient(rgba(0.3, 0.3, 0.3, 1.0)))
    })
}

fn scaled(f: impl FnOnce(&mut GlState) -> Result<(), StateError>) -> Scene {
    let mut scene = sphere_scene(with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Diffuse(rgba(0.5, 0.5, 0.5, 1.0)))?;
        gl.light(0, LightParam::Position(Vec4::new(0.5, 0.5, 1.0, 0.0)))?;
        f(gl)
    }));
    // Uniform scale 0.6: without NORMALIZE or RESCALE_NORMAL normals grow by 1/0.6.
    scene.modelview *= Mat4::from_scale(Vec3::splat(0.6));
    scene
}

/// Renders `state` on the sphere scene with specialized pipelines, in vertex mode.
fn sphere_image(state: GlState) -> RgbaImage {
    render_variant(&sphere_scene(state.clone()), state.lighting, Specialize::Always)
}

#[test]
fn a_soft_edge_with_equal_cones_draws_gls_hard_cutoff_exactly() {
    for edge in [
        SpotEdge::LinearInnerOuter { inner_degrees: 12.0 },
        SpotEdge::SmoothstepInnerOuter { inner_degrees: 12.0 },
    ] {
        let soft = with(soft_spot(edge), |gl| gl.light(0, LightParam::SpotCutoff(12.0)));
        let hard = with(soft.clone(), |gl| {
            gl.light(0, LightParam::SpotEdge(SpotEdge::GlExponent))?;
            gl.light(0, LightParam::SpotExponent(0.0))
        });
        for mode in LightingMode::ALL {
            for specialize in VARIANTS {
                let image = |gl: &GlState| {
                    let mut state = gl.lighting;
                    state.mode = mode;
                    render_variant(&sphere_scene(gl.clone()), state, specialize)
                };
                let (a, b) = (image(&soft), image(&hard));
                // The cutoff crosses the sphere: lit and unlit pixels both.
                let lit = a.pixels().filter(|p| p.0[0] > 60).count();
                assert!(lit > 200 && lit < 4000, "{} lit pixels", lit);
                assert!(
                    a == b,
                    "{} {} {}: the soft edge with equal cones differs from GL's hard cutoff",
                    edge.name(),
                    mode.name(),
                    specialize.name()
                );
            }
        }
    }
}

#[test]
fn phong_reflect_equals_blinn_halfway_where_light_and_viewer_lie_on_the_normal() {
    // A sheet facing the viewer (n = +z), the light along +z, the viewer at infinity on +z:
    // r_i = ĥ_i = n, both factors are 1, the images are the same.
    let state = |model| {
        with(dark(), |gl| {
            gl.light_model(LightModelParam::SpecularModel(model))?;
            gl.enable(Cap::Light(0))?;
            gl.light(0, LightParam::Position(Vec4::new(0.0, 0.0, 1.0, 0.0)))?;
            gl.material(Face::Front, MaterialParam::Specular(rgba(0.6, 0.5, 0.4, 1.0)))?;
            gl.material(Face::Front, MaterialParam::Shininess(50.0))
        })
    };
    let flat = |gl: GlState| Scene {
        mesh: grid(4, |_, _| Vec3::Z, |_, _| Vec4::ONE),
        modelview: Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0)),
        projection: perspective(45.0, 1.0, 1.0, 10.0),
        gl,
    };
    let [blinn, phong] = [SpecularModel::BlinnHalfway, SpecularModel::PhongReflect].map(|m| {
        let s = flat(state(m));
        render_variant(&s, s.gl.lighting, Specialize::Always)
    });
    assert!(blinn == phong);
    // And on a sphere they differ: for the same exponent GL's halfway highlight is wider
    // (its angle is half of r_i's), Phong's narrower (the specular term alone drawn).
    let [blinn, phong] = [SpecularModel::BlinnHalfway, SpecularModel::PhongReflect].map(|m| {
        sphere_image(with(state(m), |gl| {
            gl.light_model(LightModelParam::Ambient(Vec4::ZERO))?;
            gl.light(0, LightParam::Diffuse(Vec4::ZERO))?;
            gl.light(0, LightParam::Position(Vec4::new(-1.0, 1.0, 1.0, 0.0)))
        }))
    });
    let bright = |i: &RgbaImage| i.pixels().filter(|p| p.0[0] > 60).count();
    assert!(
        bright(&blinn) > 4 * bright(&phong),
        "phong {} blinn {}",
        bright(&phong),
        bright(&blinn)
    );
}
