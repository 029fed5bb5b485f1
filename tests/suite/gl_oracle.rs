//! Checks the GL reference renderer (fixed-function OpenGL through EGL) itself against values
//! worked out by hand from the GL 2.1 lighting equation (not from ffvk), so that it can serve
//! as the oracle; and how it chooses, and fails to find, a GL driver and device.

use ffvk::gl::state::{FixedFunctionState, LightingMode};
use ffvk::mesh::{MeshData, Vertex};
use ffvk_cli::gl_reference::{
    gl_info, gl_info_with, render_gl, render_gl_with, time_frames_with, GlDraw, GlError, GlOptions, GlScene,
    NoDriver,
};
use glam::{Mat4, Vec3, Vec4};

use crate::support::gl_options;

const SIZE: u32 = 16;

/// Two counter-clockwise triangles covering the whole view under identity matrices.
fn full_screen_quad(normal: Vec3, color: Vec4) -> MeshData {
    let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    MeshData::new(
        corners
            .iter()
            .map(|&(x, y)| Vertex::new(Vec3::new(x, y, 0.0), normal, color))
            .collect(),
        vec![0, 1, 2, 0, 2, 3],
    )
}

fn scene<'a>(mesh: &'a MeshData, state: FixedFunctionState) -> GlScene<'a> {
    GlScene {
        width: SIZE,
        height: SIZE,
        clear_color: [0.0, 0.0, 0.0, 1.0],
        depth_test: true,
        draws: vec![GlDraw {
            mesh,
            modelview: Mat4::IDENTITY,
            projection: Mat4::IDENTITY,
            state,
            color_array: true,
            calls: Vec::new(),
            textures: Default::default(),
            cube_maps: Default::default(),
            mesh_texcoords: 0,
            second_texcoords: 0,
            mode: Default::default(),
            point_size: 1.0,
            line_width: 1.0,
            edge_flags: None,
        }],
    }
}

/// The oracle's render (see [`gl_options`]).
fn render(scene: &GlScene) -> ffvk_cli::Result<image::RgbaImage> {
    render_gl_with(scene, &gl_options())
}

fn assert_every_pixel(img: &image::RgbaImage, expected: [u8; 4], tolerance: u8) {
    for (x, y, p) in img.enumerate_pixels() {
        let close =
            p.0.iter()
                .zip(expected)
                .all(|(&got, want)| got.abs_diff(want) <= tolerance);
        assert!(
            close,
            "pixel ({x}, {y}) is {:?}, expected {expected:?} ±{tolerance}",
            p.0
        );
    }
}

fn lit_default_light0() -> FixedFunctionState {
    let mut state = FixedFunctionState::default();
    state.lighting = true;
    state.lights[0].enabled = true;
    state
}

#[test]
fn reports_a_fixed_function_context() {
    let info = gl_info_with(&gl_options()).expect("a GL context");
    println!("{info:?}");
    assert!(info.max_lights >= 8, "GL_MAX_LIGHTS = {}", info.max_lights);
    assert!(!info.version.is_empty() && !info.renderer.is_empty());
}

#[test]
fn unlit_color_passes_through() {
    // 0.25, 0.5, 0.75 of 255 are 63.75, 127.5 and 191.25.
    let mesh = full_screen_quad(Vec3::Z, Vec4::new(0.25, 0.5, 0.75, 1.0));
    let img = render(&scene(&mesh, FixedFunctionState::default())).expect("render");
    assert_eq!(img.dimensions(), (SIZE, SIZE));
    assert_every_pixel(&img, [64, 128, 191, 255], 1);
}

#[test]
fn default_light0_on_a_facing_quad() {
    // Light 0 is directional along +z with white diffuse; the default material has
    // diffuse 0.8, ambient 0.2 (times the scene ambient 0.2) and no specular:
    // 0.2 * 0.2 + 0.8 * (n . L = 1) = 0.84, and 0.84 * 255 = 214.2. Alpha is d_cm's, 1.
    let mesh = full_screen_quad(Vec3::Z, Vec4::new(1.0, 0.0, 0.0, 1.0));
    let img = render(&scene(&mesh, lit_default_light0())).expect("render");
    assert_every_pixel(&img, [214, 214, 214, 255], 1);
}

#[test]
fn row_zero_is_the_top_of_the_view() {
    // A counter-clockwise red triangle in the top part of the view only (y from 0.2 to 1).
    let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
    let mesh = MeshData::new(
        [(-1.0, 0.2), (1.0, 0.2), (0.0, 1.0)]
            .iter()
            .map(|&(x, y)| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, red))
            .collect(),
        vec![0, 1, 2],
    );
    let img = render(&scene(&mesh, FixedFunctionState::default())).expect("render");
    let mid = SIZE / 2;
    // Row 2 at the center column lies near y = +0.75 in NDC: inside the triangle.
    assert_eq!(img.get_pixel(mid, 2).0, [255, 0, 0, 255]);
    // The bottom half of the image is all clear color.
    for y in SIZE / 2..SIZE {
        for x in 0..SIZE {
            assert_eq!(img.get_pixel(x, y).0, [0, 0, 0, 255], "pixel ({x}, {y})");
        }
    }
}

#[test]
fn flat_shading_takes_the_last_vertex() {
    // One triangle covering the view, vertices red, green, blue: GL's provoking vertex is the
    // last one, so every pixel is blue.
    let colors = [
        Vec4::new(1.0, 0.0, 0.0, 1.0),
        Vec4::new(0.0, 1.0, 0.0, 1.0),
        Vec4::new(0.0, 0.0, 1.0, 1.0),
    ];
    let positions = [(-1.0, -1.0), (3.0, -1.0), (-1.0, 3.0)];
    let mesh = MeshData::new(
        positions
            .iter()
            .zip(colors)
            .map(|(&(x, y), c)| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, c))
            .collect(),
        vec![0, 1, 2],
    );
    let mut state = FixedFunctionState::default();
    state.mode = LightingMode::Flat;
    let img = render(&scene(&mesh, state)).expect("render");
    assert_every_pixel(&img, [0, 0, 255, 255], 0);
}

#[test]
fn two_sided_lighting_uses_the_back_material_and_negated_normal() {
    // The quad wound clockwise shows its back. Its normal (0, 0, -1) negated is (0, 0, 1),
    // which faces light 0. Back material diffuse (0, 1, 0, 0.5), ambient default 0.2:
    // rgb = 0.2 * 0.2 + (0, 1, 0) * 1 = (0.04, 1.04 -> 1, 0.04); alpha = 0.5.
    let mut mesh = full_screen_quad(Vec3::NEG_Z, Vec4::ONE);
    mesh.indices = vec![0, 2, 1, 0, 3, 2];
    let mut state = lit_default_light0();
    state.model.two_side = true;
    state.back.diffuse = Vec4::new(0.0, 1.0, 0.0, 0.5);
    let img = render(&scene(&mesh, state)).expect("render");
    assert_every_pixel(&img, [10, 255, 10, 128], 1);

    // One-sided: the front material with the normal as given, pointing away from the light:
    // only the ambient term, 0.04 -> 10.
    state.model.two_side = false;
    let img = render(&scene(&mesh, state)).expect("render");
    assert_every_pixel(&img, [10, 10, 10, 255], 1);
}

#[test]
fn a_light_beyond_gl_max_lights_is_an_error() {
    let info = gl_info_with(&gl_options()).expect("a GL context");
    let index = info.max_lights as usize;
    let mesh = full_screen_quad(Vec3::Z, Vec4::ONE);
    let mut state = lit_default_light0();
    if index >= state.lights.len() {
        return; // this GL evaluates every light ffvk has
    }
    state.lights[index].enabled = true;
    let err = render(&scene(&mesh, state))
        .expect_err("light beyond GL_MAX_LIGHTS")
        .to_string();
    assert!(err.contains("GL_MAX_LIGHTS"), "{err}");
}

#[test]
fn an_invalid_value_is_reported_as_a_gl_error() {
    // SPOT_CUTOFF 120 is outside [0, 90] and not 180: GL raises INVALID_VALUE (0x0501).
    let mesh = full_screen_quad(Vec3::Z, Vec4::ONE);
    let mut state = lit_default_light0();
    state.lights[0].spot_cutoff = 120.0;
    let err = render(&scene(&mesh, state))
        .expect_err("invalid spot cutoff")
        .to_string();
    assert!(err.contains("0x0501"), "{err}");
}

#[test]
fn a_missing_egl_library_is_no_gl_driver() {
    let options = GlOptions {
        egl_library: Some("/nonexistent/libEGL.so.1".into()),
        ..GlOptions::default()
    };
    let err = gl_info_with(&options).expect_err("no EGL library there");
    assert!(
        matches!(
            &err,
            ffvk_cli::Error::Gl(GlError::NoDriver(NoDriver::Library { library, .. }))
                if library == "/nonexistent/libEGL.so.1"
        ),
        "{err:?}"
    );
    let message = err.to_string();
    assert!(message.starts_with("no GL driver: "), "{message}");
    assert!(message.contains("/nonexistent/libEGL.so.1"), "{message}");
    assert!(message.contains("libegl-mesa0"), "{message}");

    // Every entry point says the same.
    let mesh = full_screen_quad(Vec3::Z, Vec4::ONE);
    let scene = scene(&mesh, FixedFunctionState::default());
    for message in [
        render_gl_with(&scene, &options).map(drop),
        time_frames_with(&scene, 1, 1, &options).map(drop),
    ]
    .map(|r| r.expect_err("no EGL library there").to_string())
    {
        assert!(message.starts_with("no GL driver: "), "{message}");
    }
}

#[test]
fn the_device_named_like_the_default_one_renders_the_same() {
    let info = gl_info().expect("a GL context");
    let options = GlOptions {
        vulkan_name: Some(info.renderer.to_uppercase()),
        ..GlOptions::default()
    };
    let named = gl_info_with(&options).expect("the device by its name");
    assert_eq!(named.renderer, info.renderer);
    let mesh = full_screen_quad(Vec3::Z, Vec4::new(1.0, 0.0, 0.0, 1.0));
    let img = render_gl_with(&scene(&mesh, lit_default_light0()), &options).expect("render");
    assert_every_pixel(&img, [214, 214, 214, 255], 1);
}

#[test]
fn a_device_that_is_not_there_is_a_clear_error() {
    gl_info().expect("a GL context");
    for options in [
        GlOptions {
            vulkan_name: Some("No Such GPU 9000".into()),
            ..GlOptions::default()
        },
        GlOptions {
            vulkan_uuid: Some([0xAB; 16]),
            ..GlOptions::default()
        },
    ] {
        let err = gl_info_with(&options).expect_err("no such device");
        assert!(
            matches!(err, ffvk_cli::Error::Gl(GlError::NoMatchingDevice { .. })),
            "{err:?}"
        );
        let message = err.to_string();
        assert!(
            message.starts_with("GL reference: no EGL device matches"),
            "{message}"
        );
        // Each display tried is named, with why it is not the one.
        assert!(message.contains("EGL_"), "{message}");
    }
}

#[test]
fn framebuffer_sizes_gl_cannot_make_are_errors() {
    let mesh = full_screen_quad(Vec3::Z, Vec4::ONE);
    for (width, height, expected) in [
        (0, 16, "empty"),
        (16, 0, "empty"),
        (1 << 20, 16, "GL_MAX_RENDERBUFFER_SIZE"),
    ] {
        let scene = GlScene {
            width,
            height,
            ..scene(&mesh, FixedFunctionState::default())
        };
        let message = render_gl(&scene).expect_err("no framebuffer").to_string();
        assert!(message.contains(expected), "{width}x{height}: {message}");
    }
}
