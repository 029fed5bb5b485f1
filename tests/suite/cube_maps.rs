//! Cube maps (GL 2.1 §3.8.6, §2.11.4, §3.8.16) against Mesa's GL: texture_units.rs's lit sphere
//! with a cube map whose six faces tell apart (each its own color, shaded across s and t so
//! that a face flipped or turned shows), reached by `GL_REFLECTION_MAP` and `GL_NORMAL_MAP`
//! texgen and by object-linear coordinates; linear filtering at the faces' seams (GL 2.1
//! filters each face on its own: `VK_EXT_non_seamless_cube_map`), mipmaps, a cube map and a 2D
//! texture on two units, and `GL_TEXTURE_CUBE_MAP`'s precedence over `GL_TEXTURE_2D` on one.
//! Compared as texture_units.rs compares (2/255 on 99.9 % of the masked pixels), specialized
//! and uber; and the CPU reference's face selection against the faces ffvk samples.
//!
//! Measured here (lavapipe against llvmpipe, Mesa 22.3.6; 8 830 masked pixels a scene): every
//! reflection-map, object-linear and two-unit scene 100 % within 2/255 (worst 1/255), the seams
//! included (each face filtered on its own on both sides); the two `GL_NORMAL_MAP` scenes
//! 99.989 %: one pixel whose normal lies on a face diagonal, where the face is the
//! implementation's choice (§3.8.6) and the two samplers break the tie apart.

use ffvk::gl::state::*;
use ffvk::gl::texture::{
    cube_face, units_applied, CubeFace, CubeImage, MagFilter, MinFilter, Sampling, TexEnvMode, TexGenMode,
    TextureImage, Wrap,
};
use ffvk::Specialize;
use glam::{DVec3, Vec4};

use crate::support::*;
use crate::texture_units::{check, red_green, sampling, unit, units_state, UnitsCase};

/// Each face's color, in GL's order: +X red, −X cyan, +Y green, −Y magenta, +Z blue, −Z
/// yellow.
const FACE_COLORS: [[u8; 3]; 6] = [
    [230, 40, 40],
    [40, 220, 220],
    [40, 210, 50],
    [220, 50, 220],
    [50, 60, 230],
    [230, 220, 40],
];

/// A cube map of `side`-texel faces: each face's color, its red brightening along s and its
/// blue along t, a darker checker on top, alpha falling along t.
pub(crate) fn faces(side: u32) -> CubeImage {
    let face = |c: [u8; 3]| {
        let mut rgba = Vec::new();
        for j in 0..side {
            for i in 0..side {
                let s = i as f32 / (side - 1) as f32;
                let t = j as f32 / (side - 1) as f32;
                let dark = if (i / 2 + j / 2) % 2 == 0 { 1.0 } else { 0.7 };
                let v = |x: f32| (x * dark).clamp(0.0, 255.0) as u8;
                rgba.extend([
                    v(c[0] as f32 * (0.6 + 0.4 * s)),
                    v(c[1] as f32),
                    v(c[2] as f32 * (0.6 + 0.4 * t)),
                    (255.0 - 128.0 * t) as u8,
                ]);
            }
        }
        TextureImage::new(side, side, rgba).unwrap()
    };
    CubeImage::new(FACE_COLORS.map(face)).unwrap()
}

/// Coordinates S, T and R generated in `mode` on the active unit.
fn generate(gl: &mut GlState, mode: TexGenMode) {
    for coord in 0..3 {
        gl.tex_gen_mode(coord, mode).unwrap();
        gl.enable(Cap::TextureGen(coord)).unwrap();
    }
}

/// Unit 0 with its cube map enabled in `env`, its 2D target off.
fn cube_unit(gl: &mut GlState, env: TexEnvMode) {
    gl.disable(Cap::Texture2D).unwrap();
    gl.enable(Cap::TextureCubeMap).unwrap();
    gl.tex_env(TexEnvParam::Mode(env)).unwrap();
}

fn case(name: &'static str, state: FixedFunctionState, cube: CubeImage, sampling: Sampling) -> UnitsCase {
    UnitsCase {
        name,
        state,
        textures: Default::default(),
        mesh_texcoords: 0,
        cube_maps: [Some(cube), None, None, None],
        sampling,
    }
}

fn cases(mode: LightingMode) -> Vec<UnitsCase> {
    let nearest = Sampling::NEAREST;
    let seams = Sampling::default()
        .with_min_filter(MinFilter::Linear)
        .with_mag_filter(MagFilter::Linear)
        .with_wrap_s(Wrap::ClampToEdge)
        .with_wrap_t(Wrap::ClampToEdge);
    let mipmapped = Sampling::default()
        .with_min_filter(MinFilter::LinearMipmapLinear)
        .with_mag_filter(MagFilter::Linear);
    let reflection = |env| {
        units_state(mode, |gl| {
            cube_unit(gl, env);
            generate(gl, TexGenMode::ReflectionMap);
        })
    };
    let mut all = vec![
        case(
            "reflection_map_replace_nearest",
            reflection(TexEnvMode::Replace),
            faces(8),
            nearest,
        ),
        case(
            "reflection_map_modulate_nearest",
            reflection(TexEnvMode::Modulate),
            faces(8),
            nearest,
        ),
        // 4-texel faces magnified: linear filtering reaches every face's edge, where GL 2.1
        // clamps within the face.
        case(
            "reflection_map_linear_at_the_seams",
            reflection(TexEnvMode::Replace),
            faces(4),
            seams,
        ),
        case(
            "reflection_map_mipmapped",
            reflection(TexEnvMode::Decal),
            faces(64).with_mipmaps(),
            mipmapped,
        ),
        case(
            "normal_map_blend",
            units_state(mode, |gl| {
                cube_unit(gl, TexEnvMode::Blend);
                gl.tex_env(TexEnvParam::Color(Vec4::new(0.9, 0.3, 0.1, 1.0)))
                    .unwrap();
                generate(gl, TexGenMode::NormalMap);
            }),
            faces(8),
            nearest,
        ),
        case(
            "object_linear_directions",
            units_state(mode, |gl| {
                cube_unit(gl, TexEnvMode::Replace);
                for (coord, plane) in [
                    glam::DVec4::new(1.0, 0.0, 0.0, 0.1),
                    glam::DVec4::new(0.0, 1.0, 0.0, -0.2),
                    glam::DVec4::new(0.0, 0.0, 1.0, 0.0),
                ]
                .into_iter()
                .enumerate()
                {
                    gl.tex_gen_mode(coord, TexGenMode::ObjectLinear).unwrap();
                    gl.tex_gen_object_plane(coord, plane).unwrap();
                    gl.enable(Cap::TextureGen(coord)).unwrap();
                }
            }),
            faces(8),
            nearest,
        ),
    ];
    // A 2D texture on unit 0 and the reflection on unit 1, added: a chrome look over a base.
    let mut chrome = case(
        "a_2d_unit_then_a_reflected_cube_map_added",
        units_state(mode, |gl| {
            unit(gl, 1, TexEnvMode::Add);
            gl.disable(Cap::Texture2D).unwrap();
            gl.enable(Cap::TextureCubeMap).unwrap();
            generate(gl, TexGenMode::ReflectionMap);
        }),
        faces(8),
        sampling(),
    );
    chrome.textures[0] = Some(red_green());
    chrome.cube_maps = [None, Some(faces(8)), None, None];
    all.push(chrome);
    // Both targets enabled and both bound on one unit: the cube map is sampled.
    let mut both = case(
        "the_cube_map_takes_precedence_over_the_2d_texture",
        units_state(mode, |gl| {
            gl.enable(Cap::TextureCubeMap).unwrap();
            gl.tex_env(TexEnvParam::Mode(TexEnvMode::Replace)).unwrap();
            generate(gl, TexGenMode::NormalMap);
        }),
        faces(8),
        nearest,
    );
    both.textures[0] = Some(red_green());
    all.push(both);
    all
}

#[test]
fn cube_maps_by_reflection_normal_and_object_coordinates_match_mesa_gl() {
    let mut all = cases(LightingMode::Vertex);
    all.extend(cases(LightingMode::Flat));
    check(Specialize::default(), &all);
}

#[test]
fn the_uber_shader_samples_cube_maps_as_the_specialized_pipelines_do() {
    check(Specialize::Never, &cases(LightingMode::Vertex));
}

/// GL_TEXTURE_CUBE_MAP's precedence (§3.8.16): with it on, a unit samples its cube map, or, with
/// none bound, nothing, whatever its 2D texture (Mesa falls back to the 2D texture there;
/// GL 2.1 disables the unit, as ffvk does).
#[test]
fn a_unit_with_its_cube_map_on_and_none_bound_textures_nothing() {
    let mut gl = GlState::new();
    gl.enable(Cap::Texture2D).unwrap();
    assert_eq!(units_applied(&gl.lighting.texture_units, 0b1, 0), (1, 1, 0));
    gl.enable(Cap::TextureCubeMap).unwrap();
    assert_eq!(units_applied(&gl.lighting.texture_units, 0b1, 0), (0, 0, 0));
    assert_eq!(units_applied(&gl.lighting.texture_units, 0b1, 0b1), (1, 1, 1));
    gl.disable(Cap::Texture2D).unwrap();
    assert_eq!(units_applied(&gl.lighting.texture_units, 0, 0b1), (1, 1, 1));
}

/// The CPU reference's face selection (table 3.19) picks the face whose color ffvk draws in
/// that direction: a cube map of solid faces, read back through `GL_NORMAL_MAP` on a sphere, has
/// at the pixel nearest each axis the color of that axis's face.
#[test]
fn the_face_the_reference_selects_is_the_face_ffvk_samples() {
    let directions = [
        (DVec3::new(0.9, 0.2, 0.3), CubeFace::PositiveX),
        (DVec3::new(-0.9, 0.1, 0.2), CubeFace::NegativeX),
        (DVec3::new(0.1, 0.8, 0.3), CubeFace::PositiveY),
        (DVec3::new(0.2, -0.8, 0.1), CubeFace::NegativeY),
        (DVec3::new(0.1, 0.2, 0.9), CubeFace::PositiveZ),
        (DVec3::new(0.3, -0.1, -0.9), CubeFace::NegativeZ),
    ];
    for (r, face) in directions {
        assert_eq!(cube_face(r).map(|f| f.0), Some(face), "{r}");
    }
    // The sphere's eye-space normals toward the viewer: +Z, with +X on the right and +Y up.
    let solid = CubeImage::solid(2, FACE_COLORS.map(|c| [c[0], c[1], c[2], 255])).unwrap();
    let state = units_state(LightingMode::Vertex, |gl| {
        gl.disable(Cap::Lighting).unwrap();
        cube_unit(gl, TexEnvMode::Replace);
        generate(gl, TexGenMode::NormalMap);
    });
    let mut r = renderer_with(Specialize::default());
    let mesh = ffvk::mesh::MeshData::uv_sphere(48, 32);
    let gpu = r.upload(&mesh).unwrap();
    let cube = r.upload_cube_map(&solid, &Sampling::NEAREST).unwrap();
    let mut frame = ffvk::Frame::new(64, 64);
    let modelview = glam::Mat4::from_translation(glam::Vec3::new(0.0, 0.0, -3.0));
    // Orthographic, so that the normal at 0.9 of the radius from the center is 0.9 along that
    // axis: the sphere's radius is 64 / 2.4 ≈ 26.7 pixels.
    let projection = glam::Mat4::orthographic_rh_gl(-1.2, 1.2, -1.2, 1.2, 1.0, 10.0);
    let mut draw = ffvk::Draw::new(&gpu, modelview, projection, state);
    draw.cube_maps[0] = Some(&cube);
    frame.draws.push(draw);
    let image = r.render(&frame).unwrap().into_rgba_image();
    let rgb = |x: u32, y: u32| {
        let p = image.get_pixel(x, y).0;
        [p[0], p[1], p[2]]
    };
    // The sphere's center faces the viewer (+Z); 24 pixels (0.9 of the radius) to its right
    // +X, to its left −X, above it +Y (row 0 is the top), below −Y.
    for ((x, y), face) in [
        ((32, 32), CubeFace::PositiveZ),
        ((56, 32), CubeFace::PositiveX),
        ((8, 32), CubeFace::NegativeX),
        ((32, 8), CubeFace::PositiveY),
        ((32, 56), CubeFace::NegativeY),
    ] {
        assert_eq!(
            rgb(x, y),
            FACE_COLORS[face.index()],
            "pixel ({x}, {y}): {}",
            face.gl_name()
        );
    }
    finish(r);
}

/// A cube map bound where a 2D texture goes, or the reverse, is refused naming the slot and the
/// unit, and nothing is drawn.
#[test]
fn a_texture_in_the_other_targets_slot_is_refused_naming_the_unit() {
    let mut r = renderer_with(Specialize::default());
    let mesh = ffvk::mesh::MeshData::uv_sphere(8, 6);
    let gpu = r.upload(&mesh).unwrap();
    let cube = r.upload_cube_map(&faces(4), &Sampling::NEAREST).unwrap();
    let flat = r.upload_texture(&red_green(), &Sampling::NEAREST).unwrap();
    let state = units_state(LightingMode::Vertex, |gl| {
        unit(gl, 2, TexEnvMode::Modulate);
        gl.enable(Cap::TextureCubeMap).unwrap();
    });
    let view = glam::Mat4::from_translation(glam::Vec3::new(0.0, 0.0, -3.0));
    let projection = perspective(45.0, 1.0, 1.0, 10.0);
    for (textures, cubes, field) in [
        ([None, None, Some(&cube), None], [None; 4], "textures"),
        ([None; 4], [None, None, Some(&flat), None], "cube_maps"),
    ] {
        let mut frame = ffvk::Frame::new(16, 16);
        frame.draws.push(
            ffvk::Draw::new(&gpu, view, projection, state)
                .with_textures(textures)
                .with_cube_maps(cubes),
        );
        let e = r.render(&frame).expect_err("the wrong target is refused");
        let text = e.to_string();
        assert!(text.contains(field) && text.contains("unit 2"), "{text}");
    }
    // CubeImage itself refuses faces that are not a cube.
    let faces6: [TextureImage; 6] = std::array::from_fn(|i| {
        let side = if i == 4 { 8 } else { 4 };
        TextureImage::new(side, side, vec![0; (side * side * 4) as usize]).unwrap()
    });
    let e = CubeImage::new(faces6).unwrap_err().to_string();
    assert!(e.contains("GL_TEXTURE_CUBE_MAP_POSITIVE_Z"), "{e}");
    finish(r);
}
