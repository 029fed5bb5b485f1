//! The fragment mode's deferred path against its forward path: the same images (at most
//! 1/255 apart, byte-identical where the arithmetic allows), the equation evaluated once per
//! pixel the lighting pass lights, and the frames the deferred path cannot draw drawn forward.

use ffvk::gl::state::{
    Cap, ColorControl, ColorMaterialMode, Face, GlState, LightModelParam, LightParam, LightingMode,
    MaterialParam,
};
use ffvk::glam::{Mat4, Vec3, Vec4};
use ffvk::mesh::MeshData;
use ffvk::{Draw, FragmentPath, Frame, Renderer};
use image::RgbaImage;

use crate::support::*;

const SIZE: u32 = 160;

/// A lit state in the fragment mode: a directional, a point and a spot light, specular.
fn state(two_side: bool, local_viewer: bool, separate: bool, color_material: bool) -> GlState {
    let mut gl = GlState::new();
    gl.lighting_mode(LightingMode::Fragment);
    let setup = |gl: &mut GlState| -> Result<(), ffvk::gl::state::StateError> {
        gl.enable(Cap::Lighting)?;
        for i in 0..3 {
            gl.enable(Cap::Light(i))?;
        }
        gl.light(0, LightParam::Position(Vec4::new(0.5, 1.0, 1.0, 0.0)))?;
        gl.light(1, LightParam::Position(Vec4::new(-1.5, 0.5, 0.5, 1.0)))?;
        gl.light(1, LightParam::Diffuse(Vec4::new(0.6, 0.4, 0.3, 1.0)))?;
        gl.light(1, LightParam::LinearAttenuation(0.4))?;
        gl.light(2, LightParam::Position(Vec4::new(0.0, 2.0, 0.0, 1.0)))?;
        gl.light(2, LightParam::SpotDirection(Vec3::new(0.0, -1.0, -0.6)))?;
        gl.light(2, LightParam::SpotCutoff(35.0))?;
        gl.light(2, LightParam::SpotExponent(6.0))?;
        gl.light(2, LightParam::Diffuse(Vec4::new(0.3, 0.5, 0.9, 1.0)))?;
        gl.material(
            Face::FrontAndBack,
            MaterialParam::Specular(Vec4::new(0.8, 0.8, 0.8, 1.0)),
        )?;
        gl.material(Face::FrontAndBack, MaterialParam::Shininess(40.0))?;
        gl.material(Face::Back, MaterialParam::Diffuse(Vec4::new(0.9, 0.2, 0.2, 1.0)))?;
        gl.light_model(LightModelParam::TwoSide(two_side))?;
        gl.light_model(LightModelParam::LocalViewer(local_viewer))?;
        if separate {
            gl.light_model(LightModelParam::ColorControl(ColorControl::SeparateSpecularColor))?;
        }
        if color_material {
            gl.color_material(Face::FrontAndBack, ColorMaterialMode::AmbientAndDiffuse);
            gl.enable(Cap::ColorMaterial)?;
        }
        Ok(())
    };
    setup(&mut gl).unwrap();
    gl
}

fn view(at: Vec3) -> Mat4 {
    Mat4::from_translation(Vec3::new(0.0, 0.0, -3.2)) * Mat4::from_translation(at)
}

/// A mesh, its modelview and its front diffuse color.
type Placed<'m> = (&'m ffvk::Mesh, Mat4, Vec4);

/// `meshes` drawn under `gl`, each with its own material, along `path`.
fn render(
    r: &mut Renderer,
    meshes: &[Placed],
    gl: &GlState,
    path: FragmentPath,
) -> (RgbaImage, ffvk::FrameStats) {
    let mut frame = Frame::new(SIZE, SIZE);
    frame.clear_color = Vec4::new(0.1, 0.1, 0.12, 1.0);
    frame.fragment_path = path;
    for (mesh, modelview, diffuse) in meshes {
        let mut state = gl.lighting;
        state.front.diffuse = *diffuse;
        frame.draws.push(Draw::new(
            mesh,
            *modelview,
            perspective(45.0, 1.0, 0.5, 20.0),
            state,
        ));
    }
    let (pixels, stats) = r.render_measured(&frame).unwrap();
    (pixels.into_rgba_image(), stats)
}

/// The largest channel difference, and how many bytes differ.
fn difference(a: &RgbaImage, b: &RgbaImage) -> (u8, usize) {
    let max = a
        .as_raw()
        .iter()
        .zip(b.as_raw())
        .map(|(x, y)| x.abs_diff(*y))
        .max()
        .unwrap_or(0);
    let count = a.as_raw().iter().zip(b.as_raw()).filter(|(x, y)| x != y).count();
    (max, count)
}

#[test]
fn the_deferred_path_draws_the_forward_paths_image_within_1_255_lighting_each_pixel_once() {
    let mut r = renderer();
    let sphere = r.upload(&MeshData::uv_sphere(48, 24)).unwrap();
    let teapot = r.upload(&ffvk::mesh::teapot::teapot(6).unwrap()).unwrap();
    let plane = r
        .upload(&quad(-0.8, -0.8, 0.8, 0.8, 0.0, Vec4::new(0.7, 0.7, 0.2, 1.0)))
        .unwrap();
    let at = |p: Vec3| view(p);
    // Turned away past 90° about y: the quad shows its back face.
    let turned = view(Vec3::ZERO) * Mat4::from_rotation_y(2.5) * Mat4::from_rotation_x(0.3);
    let scenes: Vec<(&str, Vec<Placed>, GlState)> = vec![
        (
            "sphere",
            vec![(&sphere, at(Vec3::ZERO), Vec4::new(0.2, 0.5, 0.8, 1.0))],
            state(false, false, false, false),
        ),
        (
            "teapot, local viewer, separate specular",
            vec![(&teapot, at(Vec3::ZERO), Vec4::new(0.8, 0.6, 0.2, 1.0))],
            state(false, true, true, false),
        ),
        (
            "color material",
            vec![(&teapot, at(Vec3::ZERO), Vec4::ONE)],
            state(false, false, false, true),
        ),
        // Two-sided lighting: the back face lit with the back material and the negated normal.
        (
            "two-sided back face",
            vec![(&plane, turned, Vec4::ONE)],
            state(true, false, false, false),
        ),
        (
            "many draws, each its own material",
            (0..9)
                .map(|i| {
                    let at = Vec3::new((i % 3) as f32 - 1.0, (i / 3) as f32 - 1.0, -0.5 * (i % 2) as f32);
                    (
                        &sphere,
                        view(at * 0.9) * Mat4::from_scale(Vec3::splat(0.4)),
                        Vec4::new(0.1 * i as f32, 0.9 - 0.1 * i as f32, 0.5, 1.0),
                    )
                })
                .collect(),
            state(false, false, false, false),
        ),
    ];
    for (name, meshes, gl) in &scenes {
        let (forward, fstats) = render(&mut r, meshes, gl, FragmentPath::Forward);
        let (deferred, dstats) = render(&mut r, meshes, gl, FragmentPath::Deferred);
        assert!(
            !fstats.deferred && dstats.deferred,
            "{name}: the deferred frame was drawn forward"
        );
        save_for_inspection(
            &forward,
            &format!("deferred_{}_forward", name.replace([' ', ','], "_")),
        );
        let path = save_for_inspection(
            &deferred,
            &format!("deferred_{}_deferred", name.replace([' ', ','], "_")),
        );
        let (max, count) = difference(&forward, &deferred);
        eprintln!("{name}: {count} bytes differ, at most {max}/255");
        assert!(
            max <= 1,
            "{name}: the paths differ by {max}/255 ({count} bytes; {})",
            path.display()
        );
        // The lighting pass runs once per pixel of the target at most (a full-screen triangle;
        // lavapipe counts whole 4×4 blocks).
        // The lighting pass evaluates the equation once per pixel the draws cover, by its own
        // count: exactly the pixels that are not the clear color (every drawn pixel is lit
        // here, and none is lit to the clear color).
        let covered = forward.pixels().filter(|p| p.0 != [26, 26, 31, 255]).count() as u64;
        assert_eq!(
            dstats.evaluations,
            Some(covered),
            "{name}: evaluations against covered pixels"
        );
        assert_eq!(fstats.evaluations, None, "{name}");
        if let (Some(f), Some(d)) = (fstats.pipeline, dstats.pipeline) {
            eprintln!(
                "{name}: {covered} pixels covered; fragment invocations forward {}, deferred lighting pass {} (blocks)",
                f.fragment_shader_invocations, d.fragment_shader_invocations
            );
        }
    }
    finish(r);
}

#[test]
fn frames_the_deferred_path_cannot_draw_are_drawn_forward_with_the_same_image() {
    let mut r = renderer();
    let sphere = r.upload(&MeshData::uv_sphere(24, 12)).unwrap();
    let lit = state(false, false, false, false);
    let mut other = lit.clone();
    other
        .light(0, LightParam::Diffuse(Vec4::new(0.2, 0.9, 0.2, 1.0)))
        .unwrap();
    let mut vertex_mode = lit.clone();
    vertex_mode.lighting_mode(LightingMode::Vertex);
    let frame_of = |states: &[&GlState], depth_test: bool, path| {
        let mut frame = Frame::new(64, 64);
        frame.depth_test = depth_test;
        frame.fragment_path = path;
        for (i, gl) in states.iter().enumerate() {
            let draw = Draw::new(
                &sphere,
                view(Vec3::new(0.6 * i as f32 - 0.3, 0.0, 0.0)),
                perspective(45.0, 1.0, 0.5, 20.0),
                gl.lighting,
            );
            frame.draws.push(draw);
        }
        frame
    };
    // A draw in the vertex mode; no depth test.
    for (what, states, depth_test) in [
        ("a vertex-mode draw", vec![&lit, &vertex_mode], true),
        ("no depth test", vec![&lit], false),
    ] {
        let forward = r
            .render_measured(&frame_of(&states, depth_test, FragmentPath::Forward))
            .unwrap();
        let deferred = r
            .render_measured(&frame_of(&states, depth_test, FragmentPath::Deferred))
            .unwrap();
        assert!(!deferred.1.deferred, "{what}: drawn deferred");
        assert_eq!(forward.0, deferred.0, "{what}: the images differ");
    }
    // One state, depth tested: deferred; two states too.
    for states in [vec![&lit], vec![&lit, &other]] {
        let frame = frame_of(&states, true, FragmentPath::Deferred);
        assert!(r.render_measured(&frame).unwrap().1.deferred);
    }
    // More states than the lighting pass takes: forward, the same image.
    let many: Vec<GlState> = (0..=ffvk::MAX_DEFERRED_STATES)
        .map(|i| {
            let mut gl = lit.clone();
            let g = i as f32 / ffvk::MAX_DEFERRED_STATES as f32;
            gl.light(0, LightParam::Diffuse(Vec4::new(g, 1.0 - g, 0.5, 1.0)))
                .unwrap();
            gl
        })
        .collect();
    let many: Vec<&GlState> = many.iter().collect();
    let forward = r
        .render_measured(&frame_of(&many, true, FragmentPath::Forward))
        .unwrap();
    let deferred = r
        .render_measured(&frame_of(&many, true, FragmentPath::Deferred))
        .unwrap();
    assert!(!deferred.1.deferred, "{} states: drawn deferred", many.len());
    assert_eq!(forward.0, deferred.0, "{} states: the images differ", many.len());
    finish(r);
}

/// One draw of a frame of several lighting states: its mesh, modelview, projection and state.
type StateDraw<'m> = (&'m ffvk::Mesh, Mat4, Mat4, ffvk::gl::state::FixedFunctionState);

#[test]
fn a_frame_of_several_lighting_states_is_lit_by_a_pass_per_state_within_1_255_of_forward() {
    let mut r = renderer();
    let sphere = r.upload(&MeshData::uv_sphere(32, 16)).unwrap();
    let plane = r
        .upload(&quad(-1.0, -1.0, 1.0, 1.0, 0.0, Vec4::new(0.3, 0.8, 0.4, 1.0)))
        .unwrap();
    let lit = state(false, false, false, false);
    // Another light color; two-sided with local viewer; color material; lighting off.
    let mut green = lit.clone();
    green
        .light(0, LightParam::Diffuse(Vec4::new(0.1, 0.9, 0.2, 1.0)))
        .unwrap();
    let two_sided = state(true, true, false, false);
    let colored = state(false, false, true, true);
    let mut unlit = lit.clone();
    unlit.disable(Cap::Lighting).unwrap();
    let projection = perspective(45.0, 1.0, 0.5, 20.0);
    let ortho = Mat4::orthographic_rh_gl(-2.0, 2.0, -2.0, 2.0, 0.5, 20.0);
    let small = |at: Vec3| view(at) * Mat4::from_scale(Vec3::splat(0.45));
    let draws: Vec<StateDraw> = vec![
        (
            &sphere,
            small(Vec3::new(-0.8, 0.7, 0.0)),
            projection,
            lit.lighting,
        ),
        (
            &sphere,
            small(Vec3::new(0.8, 0.7, 0.0)),
            projection,
            green.lighting,
        ),
        // Overlapping the first two, behind and in front of them, in other states.
        (
            &sphere,
            small(Vec3::new(0.0, 0.7, -0.3)),
            projection,
            colored.lighting,
        ),
        (
            &sphere,
            small(Vec3::new(-0.4, 0.5, 0.4)),
            projection,
            unlit.lighting,
        ),
        // Another projection: a state of its own.
        (&sphere, small(Vec3::new(0.9, -0.9, 0.0)), ortho, lit.lighting),
        // Back to the first state after others: its pass lights both of its draws.
        (
            &sphere,
            small(Vec3::new(-0.9, -0.8, 0.0)),
            projection,
            lit.lighting,
        ),
        // A plane through the eye's plane (its bounds' corners behind the eye: the whole
        // target is its pass's), turned to show its back face.
        (
            &plane,
            Mat4::from_translation(Vec3::new(0.0, -1.2, -1.0))
                * Mat4::from_rotation_x(1.9)
                * Mat4::from_scale(Vec3::splat(3.0)),
            projection,
            two_sided.lighting,
        ),
        // Half off the target.
        (
            &sphere,
            small(Vec3::new(1.6, 0.0, 0.0)),
            projection,
            green.lighting,
        ),
    ];
    let frame_of = |path| {
        let mut frame = Frame::new(SIZE, SIZE);
        frame.clear_color = Vec4::new(0.1, 0.1, 0.12, 1.0);
        frame.fragment_path = path;
        for (i, &(mesh, modelview, projection, mut state)) in draws.iter().enumerate() {
            let h = i as f32 / draws.len() as f32;
            state.front.diffuse = Vec4::new(h, 0.8 - 0.6 * h, 0.3 + 0.5 * h, 1.0);
            frame.draws.push(Draw::new(mesh, modelview, projection, state));
        }
        frame
    };
    let (forward, fstats) = r.render_measured(&frame_of(FragmentPath::Forward)).unwrap();
    let (deferred, dstats) = r.render_measured(&frame_of(FragmentPath::Deferred)).unwrap();
    let (forward, deferred) = (forward.into_rgba_image(), deferred.into_rgba_image());
    assert!(!fstats.deferred && dstats.deferred, "the frame was drawn forward");
    save_for_inspection(&forward, "deferred_states_forward");
    let path = save_for_inspection(&deferred, "deferred_states_deferred");
    let (max, count) = difference(&forward, &deferred);
    assert!(
        max <= 1,
        "the paths differ by {max}/255 ({count} bytes; {})",
        path.display()
    );
    // Each covered pixel lit once, by its own state's pass: none twice where the states'
    // rectangles overlap, none missed where a rectangle were too small.
    let covered = forward.pixels().filter(|p| p.0 != [26, 26, 31, 255]).count() as u64;
    assert_eq!(
        dstats.evaluations,
        Some(covered),
        "evaluations against covered pixels"
    );
    finish(r);
}

#[test]
fn auto_draws_deferred_on_a_cpu_only_where_lights_are_many_and_triangles_small() {
    let mut r = renderer();
    assert_eq!(r.device_info().device_type, "CPU", "the suite runs on lavapipe");
    // 0.19, 0.048, 0.0075 and 0.0018 vertices per pixel at 160².
    let denser = r.upload(&MeshData::uv_sphere(96, 48)).unwrap();
    let dense = r.upload(&MeshData::uv_sphere(48, 24)).unwrap();
    let coarse = r.upload(&MeshData::uv_sphere(16, 11)).unwrap();
    let sparse = r.upload(&MeshData::uv_sphere(8, 4)).unwrap();
    let three = state(false, false, false, false);
    let mut two = three.clone();
    two.disable(Cap::Light(2)).unwrap();
    let mut eight = three.clone();
    for i in 3..8 {
        eight.enable(Cap::Light(i)).unwrap();
        let d = 0.1 * i as f32;
        eight
            .light(i, LightParam::Position(Vec4::new(d - 0.5, 0.5 - d, 1.0, 0.0)))
            .unwrap();
    }
    let mut four = three.clone();
    four.enable(Cap::Light(3)).unwrap();
    four.light(3, LightParam::Position(Vec4::new(-0.2, 0.2, 1.0, 0.0)))
        .unwrap();
    let pixels = u64::from(SIZE * SIZE);
    let cases = [
        ("dense mesh, 8 lights", &dense, &eight, true),
        ("dense mesh, 4 lights", &dense, &four, true),
        ("dense mesh, 3 lights", &dense, &three, false),
        ("denser mesh, 2 lights", &denser, &two, false),
        ("denser mesh, 4 lights", &denser, &four, true),
        ("coarse mesh, 4 lights", &coarse, &four, false),
        ("coarse mesh, 8 lights", &coarse, &eight, true),
        ("sparse mesh, 8 lights", &sparse, &eight, false),
    ];
    for (name, mesh, gl, deferred) in cases {
        // The rule's own answer for the frame, and the path the renderer took.
        let vertices = u64::from(mesh.vertex_count());
        let lights = gl.lighting.enabled_lights().count();
        assert_eq!(
            FragmentPath::auto_picks_deferred(true, vertices, pixels, lights),
            deferred,
            "{name}: {vertices} vertices over {pixels} pixels, {lights} lights"
        );
        assert!(
            !FragmentPath::auto_picks_deferred(false, vertices, pixels, lights),
            "{name}: a GPU draws forward"
        );
        let meshes = [(mesh, view(Vec3::ZERO), Vec4::new(0.2, 0.5, 0.8, 1.0))];
        let (forward, _) = render(&mut r, &meshes, gl, FragmentPath::Forward);
        let (auto, stats) = render(&mut r, &meshes, gl, FragmentPath::Auto);
        assert_eq!(stats.deferred, deferred, "{name}: the path auto took");
        let (max, count) = difference(&forward, &auto);
        assert!(
            max <= 1,
            "{name}: auto differs from forward by {max}/255 ({count} bytes)"
        );
    }
    finish(r);
}
