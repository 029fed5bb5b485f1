//! Shared test helpers: a validated renderer, meshes, and pixel comparisons that report
//! the failing pixel with its coordinates and values and save the image.

use std::path::PathBuf;

use ffvk::gl::state::{
    Cap, ColorControl, Face, FixedFunctionState, GlState, LightModelParam, LightParam, LightingMode,
    MaterialParam, StateError, TexEnvParam,
};
use ffvk::gl::texture::{TexEnvMode, TextureImage};
use ffvk::mesh::{MeshData, Vertex};
use ffvk::vk::{Validation, ValidationSink};
use ffvk::{Renderer, RendererOptions, Specialize};
use ffvk_cli::gl_reference::GlOptions;
use glam::{DVec4, Mat4, Vec3, Vec4};
use image::RgbaImage;

/// A renderer with the validation layer required: its errors fail the frame that caused them.
pub fn renderer() -> Renderer {
    renderer_with(Specialize::default())
}

/// [`renderer`] with a given pipeline specialization policy.
pub fn renderer_with(specialize: Specialize) -> Renderer {
    renderer_from(RendererOptions::default().with_specialize(specialize))
}

/// A renderer of `options` with the validation layer required.
pub fn renderer_from(options: RendererOptions) -> Renderer {
    Renderer::new(&options.clone().with_validation(Validation::Required))
        .expect("a renderer on lavapipe with VK_LAYER_KHRONOS_validation")
}

/// The GL the oracle tests compare with: a software device (Mesa's llvmpipe, whose results
/// the tolerances were measured on) where EGL has one, even on a machine whose GPU driver
/// lists its devices first; otherwise the first device that works. To compare with another
/// driver, leave EGL only that driver (docs/conformance.md, "The GL reference").
/// Mesa's image of `draws` on a `size`² image cleared to `clear`, with GL_DEPTH_TEST
/// (`GL_LESS`) as `depth_test` says, through the oracle's device ([`gl_options`]).
pub fn mesa_image(
    size: (u32, u32),
    clear: [f32; 4],
    depth_test: bool,
    draws: Vec<ffvk_cli::gl_reference::GlDraw>,
) -> RgbaImage {
    let scene = ffvk_cli::gl_reference::GlScene {
        width: size.0,
        height: size.1,
        clear_color: clear,
        depth_test,
        draws,
    };
    ffvk_cli::gl_reference::render_gl_with(&scene, &gl_options()).expect("Mesa's GL renders")
}

pub fn gl_options() -> GlOptions {
    GlOptions {
        prefer_software: true,
        ..GlOptions::default()
    }
}

/// The two pipeline variants every lighting result must hold for: specialized pipelines
/// and the uber-shader.
pub const VARIANTS: [Specialize; 2] = [Specialize::Always, Specialize::Never];

/// Drops the renderer and fails on any validation error reported at teardown
/// (objects still alive when the device is destroyed, for example).
pub fn finish(renderer: Renderer) {
    let sink: ValidationSink = renderer.validation_sink();
    drop(renderer);
    let errors = sink.take_errors();
    assert!(
        errors.is_empty(),
        "validation errors at teardown:\n{}",
        errors.join("\n")
    );
}

/// Where failing tests write their images.
pub fn output_dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/output");
    std::fs::create_dir_all(&dir).expect("tests/output is writable");
    dir
}

pub fn save_for_inspection(image: &RgbaImage, name: &str) -> PathBuf {
    let path = output_dir().join(format!("{name}.png"));
    image.save(&path).expect("tests/output is writable");
    path
}

/// A lit GL state: lighting on, light 0 on, everything else GL's defaults.
pub fn lit_state() -> GlState {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    gl.enable(Cap::Light(0)).unwrap();
    gl
}

/// A quad in the z = `z` plane covering [x0, x1] × [y0, y1], normal +z, counter-clockwise
/// seen from +z, one color.
pub fn quad(x0: f32, y0: f32, x1: f32, y1: f32, z: f32, color: Vec4) -> MeshData {
    let n = Vec3::Z;
    let v = |x, y| Vertex::new(Vec3::new(x, y, z), n, color);
    MeshData::new(
        vec![v(x0, y0), v(x1, y0), v(x1, y1), v(x0, y1)],
        vec![0, 1, 2, 0, 2, 3],
    )
}

/// A regular grid over [-1, 1]² in the z = 0 plane with `n`×`n` cells, normals from `normal`,
/// colors from `color`, counter-clockwise seen from +z.
pub fn grid(n: u32, normal: impl Fn(f32, f32) -> Vec3, color: impl Fn(f32, f32) -> Vec4) -> MeshData {
    let mut vertices = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let x = -1.0 + 2.0 * i as f32 / n as f32;
            let y = -1.0 + 2.0 * j as f32 / n as f32;
            vertices.push(Vertex::new(Vec3::new(x, y, 0.0), normal(x, y), color(x, y)));
        }
    }
    let mut indices = Vec::new();
    let at = |i: u32, j: u32| j * (n + 1) + i;
    for j in 0..n {
        for i in 0..n {
            indices.extend([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            indices.extend([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    MeshData::new(vertices, indices)
}

/// A GL perspective projection (gluPerspective).
pub fn perspective(fovy_deg: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    Mat4::perspective_rh_gl(fovy_deg.to_radians(), aspect, near, far)
}

/// The pixel as 0..=255 values.
pub fn px(image: &RgbaImage, x: u32, y: u32) -> [u8; 4] {
    image.get_pixel(x, y).0
}

/// A reference color in 0..=255 (unrounded).
pub fn to_255(c: DVec4) -> [f64; 4] {
    [c.x * 255.0, c.y * 255.0, c.z * 255.0, c.w * 255.0]
}

/// Asserts pixel (x, y) is within `tol` (in 1/255 units) of `expected` (0..=1 per channel);
/// on failure saves the image and names the pixel, both values and the image's path.
pub fn assert_pixel(image: &RgbaImage, x: u32, y: u32, expected: DVec4, tol: f64, what: &str) {
    let got = px(image, x, y);
    let want = to_255(expected);
    let worst = (0..4)
        .map(|c| (got[c] as f64 - want[c]).abs())
        .fold(0.0, f64::max);
    if worst > tol {
        let path = save_for_inspection(image, &what.replace([' ', '/', ':', ','], "_"));
        panic!(
            "{what}: pixel ({x}, {y}) is {got:?}, expected {:?} (±{tol}/255, off by {worst:.2}); image at {}",
            want.map(|v| (v * 100.0).round() / 100.0),
            path.display()
        );
    }
}

/// The state with lighting disabled: vertex colors pass through.
pub fn unlit() -> FixedFunctionState {
    FixedFunctionState::default()
}

pub fn rgba(r: f32, g: f32, b: f32, a: f32) -> Vec4 {
    Vec4::new(r, g, b, a)
}

/// GL state with lighting on and every light off: each scene enables what it tests.
pub fn dark() -> GlState {
    let mut gl = GlState::new();
    gl.enable(Cap::Lighting).unwrap();
    gl
}

/// `gl` after `f`, which sets state through GL's entry points.
pub fn with(mut gl: GlState, f: impl FnOnce(&mut GlState) -> Result<(), StateError>) -> GlState {
    f(&mut gl).unwrap();
    gl
}

/// An unlit draw with identity matrices: object coordinates are GL's normalized device
/// coordinates.
pub fn ndc_draw(mesh: &ffvk::Mesh) -> ffvk::Draw<'_> {
    ffvk::Draw::new(mesh, Mat4::IDENTITY, Mat4::IDENTITY, unlit())
}

/// The ffvk binary on lavapipe with `args`.
pub fn ffvk_command(args: &[&dyn AsRef<std::ffi::OsStr>]) -> std::process::Command {
    let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_ffvk"));
    c.args(args.iter().map(|a| a.as_ref()))
        .env("VK_DRIVER_FILES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json");
    c
}

/// What the CPU reference predicts at pixel (x, y) of `scene` drawn in `mode`: the surface
/// there and its color, or `None` where no surface covers the pixel's center.
pub fn reference_at(
    scene: &ffvk::scene::Scene,
    x: u32,
    y: u32,
    mode: ffvk::gl::state::LightingMode,
) -> Option<(ffvk_cli::explain::Hit, DVec4)> {
    let hit = ffvk_cli::explain::find_surface(scene, x, y, mode)?;
    let mesh = &scene.meshes[hit.mesh];
    let mut state = scene.draw_state(mesh);
    state.mode = mode;
    let tri = hit.vertices.map(|i| &mesh.data.vertices[i]);
    let color = ffvk::reference::pixel_color(
        &state,
        scene.modelview(mesh),
        scene.projection,
        tri,
        hit.coverage,
        mesh.draw_textures().for_triangle(&mesh.data, hit.vertices),
    );
    Some((hit, color))
}

/// The lit, textured state of the texturing tests: light 0 from the upper right with a white
/// highlight on an orange, partly transparent material; the texture environment `env` with color (0.2, 0.4, 1, 0.5) and `matrix`.
pub fn textured_state(
    env: TexEnvMode,
    control: ColorControl,
    mode: LightingMode,
    matrix: Mat4,
) -> FixedFunctionState {
    let mut gl = lit_state();
    gl.light(0, LightParam::Position(Vec4::new(1.0, 1.0, 2.0, 0.0)))
        .unwrap();
    gl.material(
        Face::FrontAndBack,
        MaterialParam::AmbientAndDiffuse(rgba(0.9, 0.6, 0.3, 0.7)),
    )
    .unwrap();
    gl.material(
        Face::FrontAndBack,
        MaterialParam::Specular(rgba(0.8, 0.8, 0.8, 1.0)),
    )
    .unwrap();
    gl.material(Face::FrontAndBack, MaterialParam::Shininess(20.0))
        .unwrap();
    gl.light_model(LightModelParam::ColorControl(control)).unwrap();
    gl.enable(Cap::Texture2D).unwrap();
    gl.tex_env(TexEnvParam::Mode(env)).unwrap();
    gl.tex_env(TexEnvParam::Color(rgba(0.2, 0.4, 1.0, 0.5))).unwrap();
    gl.load_texture_matrix(matrix).unwrap();
    gl.lighting_mode(mode);
    gl.lighting
}

/// The nearest triangle of `mesh` (depth test LESS) whose interior holds the center of pixel
/// (px, py) of a `size`² image, `clips` its vertices' GL clip positions: the triangle's
/// vertex indices and the pixel's coverage.
pub fn nearest_covering(
    mesh: &MeshData,
    clips: &[DVec4],
    size: u32,
    px: u32,
    py: u32,
) -> Option<([usize; 3], ffvk::reference::Coverage)> {
    let mut best: Option<(f64, [usize; 3], ffvk::reference::Coverage)> = None;
    for t in mesh.indices.chunks(3) {
        let idx = [t[0] as usize, t[1] as usize, t[2] as usize];
        let clip = idx.map(|i| clips[i]);
        let Some(cov) = ffvk::reference::coverage(clip, size, size, px, py) else {
            continue;
        };
        let w = cov.weights;
        let z = (0..3).map(|k| clip[k].z / clip[k].w * w[k]).sum::<f64>();
        if best.as_ref().is_none_or(|b| z < b.0) {
            best = Some((z, idx, cov));
        }
    }
    best.map(|(_, idx, cov)| (idx, cov))
}

/// A `side`×`side` texture (`side` a power of two up to 16) whose every texel differs: colors
/// from a hash of its position, blue rising along the rows, alpha from 64 down the rows in
/// steps of 192 / `side`; so that the wrong texel, a blend where nearest was asked for, or
/// alpha used wrongly (DECAL, MODULATE) shows.
pub fn hashed_texels(side: u32) -> TextureImage {
    let mut rgba = Vec::new();
    for j in 0..side {
        for i in 0..side {
            let h = (i * 73 + j * 151 + i * j * 37) % 256;
            rgba.extend([
                h as u8,
                (255 - h) as u8,
                ((i * (256 / side)) % 256) as u8,
                (64 + j * (192 / side)) as u8,
            ]);
        }
    }
    TextureImage::new(side, side, rgba).unwrap()
}

/// Two-sided lighting with a light from the upper right, a warm front and a blue back
/// material, so that a wrong face or a wrong vertex shows.
pub fn two_sided(mode: LightingMode) -> GlState {
    with(dark(), |gl| {
        gl.enable(Cap::Light(0))?;
        gl.light(0, LightParam::Position(Vec4::new(0.6, 0.5, 1.0, 0.0)))?;
        gl.light(0, LightParam::Specular(Vec4::new(0.5, 0.5, 0.5, 1.0)))?;
        gl.light_model(LightModelParam::TwoSide(true))?;
        gl.material(Face::Front, MaterialParam::Diffuse(Vec4::new(0.9, 0.5, 0.2, 1.0)))?;
        gl.material(Face::Front, MaterialParam::Ambient(Vec4::new(0.3, 0.1, 0.0, 1.0)))?;
        gl.material(Face::Back, MaterialParam::Diffuse(Vec4::new(0.1, 0.3, 0.9, 1.0)))?;
        gl.material(Face::Back, MaterialParam::Ambient(Vec4::new(0.0, 0.1, 0.4, 1.0)))?;
        gl.material(Face::FrontAndBack, MaterialParam::Specular(Vec4::splat(0.6)))?;
        gl.material(Face::FrontAndBack, MaterialParam::Shininess(10.0))?;
        gl.lighting_mode(mode);
        Ok(())
    })
}
