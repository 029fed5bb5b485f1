//! Several texture units (GL 2.1 §3.8.16, §3.8.13) against Mesa's GL: texture_conformance.rs's
//! lit sphere with two and four units at once, each unit on the previous one's result, in unit
//! order, clamped after each; units on the mesh's coordinates, on their current coordinates
//! (`glMultiTexCoord`) and on generated ones; `GL_COMBINE` reading another unit's texel
//! (`GL_TEXTUREn`), the primary color and the previous unit; a first unit disabled. Compared
//! over conformance.rs's mask with texture_conformance.rs's tolerances (2/255 on 99.9 % of the
//! pixels), in specialized pipelines and the uber-shader. And the comparison can fail: the
//! same scene with two units swapped, or drawn without the clamp after a unit, is far from
//! Mesa's image of it.

use ffvk::gl::state::*;
use ffvk::gl::texture::{
    CombineFunc, CombineSource, CubeImage, MagFilter, MinFilter, RgbOperand, Sampling, TexEnvMode,
    TexGenMode, TextureImage, MAX_TEXTURE_UNITS,
};
use ffvk::mesh::MeshData;
use ffvk::{Draw, Frame, Renderer, Specialize};
use glam::{DVec4, Mat4, Vec3, Vec4};
use image::RgbaImage;

use crate::conformance::{compare, gl_draw_image, mask, save_triplet, SIZE};
use crate::support::*;
use crate::texture_conformance::waves;
use ffvk_cli::gl_reference::GlDraw;

/// One scene of several units: the state (its units set through `GlState`), each unit's
/// texture, and the units 1-3 that read the mesh's coordinates.
pub(crate) struct UnitsCase {
    pub(crate) name: &'static str,
    pub(crate) state: FixedFunctionState,
    pub(crate) textures: [Option<TextureImage>; MAX_TEXTURE_UNITS],
    pub(crate) mesh_texcoords: u32,
    /// Each unit's cube map (cube_maps.rs's cases).
    pub(crate) cube_maps: [Option<CubeImage>; MAX_TEXTURE_UNITS],
    /// The sampling of every texture and cube map.
    pub(crate) sampling: Sampling,
}

struct View {
    mesh: MeshData,
    modelview: Mat4,
    projection: Mat4,
}

fn sphere() -> View {
    View {
        mesh: MeshData::uv_sphere(24, 16),
        modelview: Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0)) * Mat4::from_rotation_x(0.3),
        projection: perspective(45.0, 1.0, 1.0, 10.0),
    }
}

pub(crate) fn sampling() -> Sampling {
    Sampling::default()
        .with_min_filter(MinFilter::Linear)
        .with_mag_filter(MagFilter::Linear)
}

/// texture_conformance.rs's lit state (unit 0 enabled, `GL_MODULATE`) in `mode`, then `setup`.
pub(crate) fn units_state(mode: LightingMode, setup: impl FnOnce(&mut GlState)) -> FixedFunctionState {
    let mut gl = GlState::new();
    gl.lighting = textured_state(
        TexEnvMode::Modulate,
        ColorControl::SeparateSpecularColor,
        mode,
        Mat4::IDENTITY,
    );
    setup(&mut gl);
    gl.lighting
}

/// Unit `unit` active, enabled, in environment mode `env`.
pub(crate) fn unit(gl: &mut GlState, unit: usize, env: TexEnvMode) {
    gl.active_texture(unit).unwrap();
    gl.enable(Cap::Texture2D).unwrap();
    gl.tex_env(TexEnvParam::Mode(env)).unwrap();
}

fn ffvk_image(r: &mut Renderer, view: &View, case: &UnitsCase) -> RgbaImage {
    let gpu = r.upload(&view.mesh).unwrap();
    let uploaded: Vec<Option<ffvk::Texture>> = case
        .textures
        .iter()
        .map(|t| {
            t.as_ref()
                .map(|image| r.upload_texture(image, &case.sampling).unwrap())
        })
        .collect();
    let cubes: Vec<Option<ffvk::Texture>> = case
        .cube_maps
        .iter()
        .map(|c| {
            c.as_ref()
                .map(|image| r.upload_cube_map(image, &case.sampling).unwrap())
        })
        .collect();
    let mut frame = Frame::new(SIZE, SIZE);
    let textures = std::array::from_fn(|i| uploaded[i].as_ref());
    let cube_maps = std::array::from_fn(|i| cubes[i].as_ref());
    frame.draws.push(
        Draw::new(&gpu, view.modelview, view.projection, case.state)
            .with_textures(textures)
            .with_cube_maps(cube_maps)
            .with_mesh_texcoords(case.mesh_texcoords),
    );
    r.render(&frame).unwrap().into_rgba_image()
}

fn gl_image(view: &View, case: &UnitsCase) -> RgbaImage {
    let mut draw = GlDraw::new(&view.mesh, view.modelview, view.projection, case.state);
    draw.textures = std::array::from_fn(|i| case.textures[i].as_ref().map(|t| (t, case.sampling)));
    draw.cube_maps = std::array::from_fn(|i| case.cube_maps[i].as_ref().map(|c| (c, case.sampling)));
    draw.mesh_texcoords = case.mesh_texcoords;
    gl_draw_image(draw, [0.0, 0.0, 0.0, 1.0])
}

/// The share of masked pixels within 2/255, and the worst difference.
fn agreement(ours: &RgbaImage, theirs: &RgbaImage, m: &[bool]) -> (f64, u8, usize) {
    let s = compare(ours, theirs, m, 2);
    (s.within as f64 / s.compared.max(1) as f64, s.worst.4, s.compared)
}

/// A checker of red and green with alpha 1 and 0.25: where it is modulated onto another unit,
/// both its colors and alphas show.
pub(crate) fn red_green() -> TextureImage {
    let mut rgba = Vec::new();
    for j in 0..8u32 {
        for i in 0..8u32 {
            if (i + j) % 2 == 0 {
                rgba.extend([230, 40, 30, 255]);
            } else {
                rgba.extend([40, 200, 60, 64]);
            }
        }
    }
    TextureImage::new(8, 8, rgba).unwrap()
}

fn cases(mode: LightingMode) -> Vec<UnitsCase> {
    use CombineSource::*;
    use TexEnvParam::*;
    let scaled = Mat4::from_scale(Vec3::new(3.0, 2.0, 1.0));
    vec![
        UnitsCase {
            name: "two_units_modulate_then_add_on_the_mesh_coordinates",
            state: units_state(mode, |gl| {
                unit(gl, 1, TexEnvMode::Add);
                gl.load_texture_matrix(scaled).unwrap();
            }),
            textures: [Some(waves()), Some(hashed_texels(16)), None, None],
            mesh_texcoords: 0b10,
            cube_maps: Default::default(),
            sampling: sampling(),
        },
        UnitsCase {
            name: "a_unit_on_its_current_coordinates_blends_one_texel",
            state: units_state(mode, |gl| {
                unit(gl, 1, TexEnvMode::Blend);
                gl.tex_env(Color(Vec4::new(0.1, 0.9, 0.4, 0.6))).unwrap();
                gl.multi_tex_coord(1, Vec4::new(0.3, 0.55, 0.0, 1.0)).unwrap();
            }),
            textures: [Some(waves()), Some(red_green()), None, None],
            mesh_texcoords: 0,
            cube_maps: Default::default(),
            sampling: sampling(),
        },
        UnitsCase {
            name: "four_units_in_order_with_texgen_on_two",
            state: units_state(mode, |gl| {
                unit(gl, 1, TexEnvMode::Modulate);
                gl.load_texture_matrix(scaled).unwrap();
                unit(gl, 2, TexEnvMode::Add);
                for coord in 0..2 {
                    gl.tex_gen_mode(coord, TexGenMode::SphereMap).unwrap();
                    gl.enable(Cap::TextureGen(coord)).unwrap();
                }
                unit(gl, 3, TexEnvMode::Decal);
                for (coord, plane) in [
                    (0, glam::DVec4::new(1.5, 0.0, 0.5, 0.5)),
                    (1, glam::DVec4::new(0.0, 2.0, 0.0, 0.5)),
                ] {
                    gl.tex_gen_mode(coord, TexGenMode::ObjectLinear).unwrap();
                    gl.tex_gen_object_plane(coord, plane).unwrap();
                    gl.enable(Cap::TextureGen(coord)).unwrap();
                }
            }),
            textures: [
                Some(waves()),
                Some(hashed_texels(16)),
                Some(hashed_texels(8)),
                Some(red_green()),
            ],
            mesh_texcoords: 0b10,
            cube_maps: Default::default(),
            sampling: sampling(),
        },
        UnitsCase {
            name: "combine_reads_unit_0s_texel_and_the_primary_color_through_the_crossbar",
            state: units_state(mode, |gl| {
                unit(gl, 1, TexEnvMode::Combine);
                gl.tex_env(CombineRgb(CombineFunc::Interpolate)).unwrap();
                gl.tex_env(SourceRgb(0, TextureUnit(0))).unwrap();
                gl.tex_env(SourceRgb(1, PrimaryColor)).unwrap();
                gl.tex_env(SourceRgb(2, Texture)).unwrap();
                gl.tex_env(OperandRgb(2, RgbOperand::SrcAlpha)).unwrap();
                gl.tex_env(CombineAlpha(CombineFunc::Modulate)).unwrap();
                gl.tex_env(SourceAlpha(0, TextureUnit(0))).unwrap();
                gl.tex_env(SourceAlpha(1, Previous)).unwrap();
            }),
            textures: [Some(waves()), Some(red_green()), None, None],
            mesh_texcoords: 0b10,
            cube_maps: Default::default(),
            sampling: sampling(),
        },
        UnitsCase {
            name: "the_clamp_after_a_unit_holds_a_scaled_sum_at_one_before_the_next_subtracts",
            state: units_state(mode, |gl| {
                gl.tex_env(Mode(TexEnvMode::Combine)).unwrap();
                gl.tex_env(CombineRgb(CombineFunc::Add)).unwrap();
                gl.tex_env(RgbScale(4.0)).unwrap();
                unit(gl, 1, TexEnvMode::Combine);
                gl.tex_env(CombineRgb(CombineFunc::Subtract)).unwrap();
                gl.tex_env(SourceRgb(0, Previous)).unwrap();
                gl.tex_env(SourceRgb(1, Texture)).unwrap();
            }),
            textures: [Some(waves()), Some(red_green()), None, None],
            mesh_texcoords: 0b10,
            cube_maps: Default::default(),
            sampling: sampling(),
        },
        UnitsCase {
            name: "with_unit_0_off_unit_1s_previous_is_the_primary_color",
            state: units_state(mode, |gl| {
                gl.disable(Cap::Texture2D).unwrap();
                unit(gl, 1, TexEnvMode::Combine);
                gl.tex_env(CombineRgb(CombineFunc::AddSigned)).unwrap();
                gl.tex_env(SourceRgb(1, Previous)).unwrap();
            }),
            textures: [Some(waves()), Some(red_green()), None, None],
            mesh_texcoords: 0b10,
            cube_maps: Default::default(),
            sampling: sampling(),
        },
    ]
}

/// Runs `cases` on a renderer of `variant`: one line per case, and the failures.
fn run(variant: Specialize, cases: &[UnitsCase]) -> (Vec<String>, Vec<String>) {
    let mut r = renderer_with(variant);
    let view = sphere();
    let m = mask(&mut r, &view.mesh, view.modelview, view.projection);
    let (mut lines, mut failures) = (Vec::new(), Vec::new());
    for case in cases {
        let ours = ffvk_image(&mut r, &view, case);
        let theirs = gl_image(&view, case);
        let (share, worst, compared) = agreement(&ours, &theirs, &m);
        let name = format!(
            "units_{}_{}_{}",
            case.name,
            case.state.mode.name(),
            variant.name()
        );
        lines.push(format!(
            "{name}: {:.3}% within 2/255, worst {worst}/255",
            share * 100.0
        ));
        if compared < 500 || share < 0.999 {
            let diff = save_triplet(&name, &ours, &theirs, &m);
            failures.push(format!(
                "{name}: {:.2}% of {compared} pixels within 2/255 (need 99.9%), worst {worst}/255; images in {}",
                share * 100.0,
                diff.parent().unwrap().display()
            ));
        }
    }
    finish(r);
    (lines, failures)
}

pub(crate) fn check(variant: Specialize, cases: &[UnitsCase]) {
    let (lines, failures) = run(variant, cases);
    println!("{}", lines.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn two_and_four_units_match_mesa_gl_in_the_vertex_and_flat_modes() {
    let mut all = cases(LightingMode::Vertex);
    all.extend(cases(LightingMode::Flat));
    check(Specialize::default(), &all);
}

#[test]
fn the_uber_shader_applies_the_units_as_the_specialized_pipelines_do() {
    check(Specialize::Never, &cases(LightingMode::Vertex));
}

/// The comparison tells unit order and the clamp apart: ffvk's image of a scene against Mesa's
/// image of the same scene with its two units swapped, and of the clamp scene against Mesa's
/// image of a scene whose first unit does not saturate (what no clamp would give), each has
/// most pixels off.
#[test]
fn swapping_two_units_or_dropping_the_clamp_fails_the_comparison() {
    let mut r = renderer_with(Specialize::default());
    let view = sphere();
    let m = mask(&mut r, &view.mesh, view.modelview, view.projection);
    let all = cases(LightingMode::Vertex);
    let two = &all[0];
    // The same units in the other order: ADD on unit 0, MODULATE on unit 1.
    let swapped = UnitsCase {
        name: "swapped",
        state: units_state(LightingMode::Vertex, |gl| {
            gl.tex_env(TexEnvParam::Mode(TexEnvMode::Add)).unwrap();
            unit(gl, 1, TexEnvMode::Modulate);
            gl.load_texture_matrix(Mat4::from_scale(Vec3::new(3.0, 2.0, 1.0)))
                .unwrap();
        }),
        textures: two.textures.clone(),
        mesh_texcoords: two.mesh_texcoords,
        cube_maps: Default::default(),
        sampling: sampling(),
    };
    let ours = ffvk_image(&mut r, &view, two);
    let (share, ..) = agreement(&ours, &gl_image(&view, &swapped), &m);
    assert!(
        share < 0.5,
        "order: {:.1}% of pixels agree with the swapped scene",
        share * 100.0
    );
    // The clamp scene with unit 0 scaled by 1 instead of 4: its sum mostly stays under one, as
    // an unclamped scaled sum would carry on past it.
    let clamp = &all[4];
    let mut unscaled = clamp.state;
    unscaled.texture_units[0].combine.rgb_scale = 1.0;
    let other = UnitsCase {
        name: "unscaled",
        state: unscaled,
        textures: clamp.textures.clone(),
        mesh_texcoords: clamp.mesh_texcoords,
        cube_maps: Default::default(),
        sampling: sampling(),
    };
    let ours = ffvk_image(&mut r, &view, clamp);
    let (share, ..) = agreement(&ours, &gl_image(&view, &other), &m);
    assert!(
        share < 0.5,
        "clamp: {:.1}% of pixels agree with the unscaled scene",
        share * 100.0
    );
    finish(r);
}

/// §3.8.16 at edge values, worked by hand, against the CPU reference's copy: each unit takes the
/// one before's clamped result.
#[test]
fn each_unit_takes_the_previous_units_clamped_result() {
    use ffvk::reference::texture::textured_color;
    let mut gl = GlState::new();
    gl.enable(Cap::Texture2D).unwrap();
    gl.tex_env(TexEnvParam::Mode(TexEnvMode::Add)).unwrap();
    unit(&mut gl, 1, TexEnvMode::Modulate);
    let units = gl.lighting.texture_units;
    let c_f = DVec4::new(0.75, 0.5, 0.25, 1.0);
    let rgba = [ffvk::gl::texture::BaseFormat::Rgba; MAX_TEXTURE_UNITS];
    let texels = [
        DVec4::new(0.5, 0.75, 0.5, 0.5),
        DVec4::new(0.5, 0.5, 0.5, 1.0),
        DVec4::ZERO,
        DVec4::ZERO,
    ];
    // Unit 0: ADD, (1.25, 1.25, 0.75) clamped to (1, 1, 0.75), alpha 1 × 0.5. Unit 1:
    // MODULATE by 0.5: (0.5, 0.5, 0.375), alpha 0.5.
    let both = textured_color(&units, (0b11, rgba), c_f, texels);
    assert_eq!(both, DVec4::new(0.5, 0.5, 0.375, 0.5));
    // Unit 1 alone: MODULATE of the primary color.
    assert_eq!(
        textured_color(&units, (0b10, rgba), c_f, texels),
        DVec4::new(0.375, 0.25, 0.125, 1.0)
    );
    // In the other order (MODULATE first, then ADD) the result differs.
    let mut swapped = units;
    swapped.swap(0, 1);
    let texels_swapped = [texels[1], texels[0], texels[2], texels[3]];
    assert_eq!(
        textured_color(&swapped, (0b11, rgba), c_f, texels_swapped),
        DVec4::new(0.875, 1.0, 0.625, 0.5)
    );
}

/// The units a draw applies: enabled with a texture bound; a unit whose `GL_COMBINE` reads a
/// unit that is not sampled through `GL_TEXTUREn` is sampled but passes the color through.
#[test]
fn a_unit_reading_a_missing_units_texel_passes_the_color_through() {
    use ffvk::gl::texture::units_applied;
    let mut gl = GlState::new();
    gl.enable(Cap::Texture2D).unwrap();
    unit(&mut gl, 2, TexEnvMode::Combine);
    gl.tex_env(TexEnvParam::SourceRgb(1, CombineSource::TextureUnit(1)))
        .unwrap();
    let units = gl.lighting.texture_units;
    // Units 0 and 2 enabled, all bound: unit 2 reads unit 1, which is disabled.
    assert_eq!(units_applied(&units, 0b1111, 0), (0b101, 0b001, 0));
    gl.active_texture(1).unwrap();
    gl.enable(Cap::Texture2D).unwrap();
    assert_eq!(
        units_applied(&gl.lighting.texture_units, 0b1111, 0),
        (0b111, 0b111, 0)
    );
    // Unit 1 enabled without a texture: as if disabled.
    assert_eq!(
        units_applied(&gl.lighting.texture_units, 0b101, 0),
        (0b101, 0b001, 0)
    );
    // A REPLACE reads Arg0 alone: a crossbar source in Arg1 is not read.
    gl.active_texture(2).unwrap();
    gl.tex_env(TexEnvParam::CombineRgb(CombineFunc::Replace)).unwrap();
    assert_eq!(
        units_applied(&gl.lighting.texture_units, 0b101, 0),
        (0b101, 0b101, 0)
    );
}

/// glActiveTexture and glMultiTexCoord refuse a unit past `GL_MAX_TEXTURE_UNITS`, changing
/// nothing; the per-unit calls act on the active unit only.
#[test]
fn the_active_unit_takes_the_unit_calls_and_a_unit_past_the_last_is_refused() {
    let mut gl = GlState::new();
    assert!(gl.active_texture(MAX_TEXTURE_UNITS).is_err());
    assert_eq!(gl.active_unit, 0);
    assert!(gl.multi_tex_coord(MAX_TEXTURE_UNITS, Vec4::ONE).is_err());
    assert!(gl.multi_tex_coord(1, Vec4::new(f32::NAN, 0.0, 0.0, 1.0)).is_err());
    gl.multi_tex_coord(3, Vec4::new(0.5, 0.25, 0.0, 1.0)).unwrap();
    assert_eq!(gl.lighting.current_texcoords[3], Vec4::new(0.5, 0.25, 0.0, 1.0));
    assert_eq!(gl.lighting.current_texcoords[0], Vec4::W);
    gl.active_texture(2).unwrap();
    gl.enable(Cap::Texture2D).unwrap();
    gl.tex_env(TexEnvParam::Mode(TexEnvMode::Decal)).unwrap();
    gl.load_texture_matrix(Mat4::from_scale(Vec3::splat(2.0)))
        .unwrap();
    let units = gl.lighting.texture_units;
    assert!(units[2].enabled && !units[0].enabled);
    assert_eq!(units[2].env_mode, TexEnvMode::Decal);
    assert_eq!(units[0].env_mode, TexEnvMode::Modulate);
    assert_eq!(units[0].matrix, Mat4::IDENTITY);
    assert!(gl
        .tex_env(TexEnvParam::SourceRgb(
            0,
            CombineSource::TextureUnit(MAX_TEXTURE_UNITS as u8)
        ))
        .is_err());
}
