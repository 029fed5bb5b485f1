//! A texture's base internal format (GL 2.1 tables 3.15 and 3.22) against Mesa's GL: the lit,
//! partly transparent sphere of texture_units.rs with the waves texture (color and alpha
//! varying) as `GL_ALPHA`, `GL_LUMINANCE`, `GL_LUMINANCE_ALPHA`, `GL_INTENSITY`, `GL_RGB` and
//! `GL_RGBA`, under each environment mode table 3.22 defines for it (`GL_DECAL` only for RGB and
//! RGBA) and under `GL_COMBINE`, and a luminance light map on a second unit. The GL reference
//! uploads the same RGBA8 texels with the format as `glTexImage2D`'s internal format, so GL's
//! own conversion (luminance and intensity from R, alpha from A) meets ffvk's. Compared as
//! texture_units.rs compares (2/255 on 99.9 % of the masked pixels), specialized and uber; and
//! table 3.22 by hand against the CPU reference's copy.

use ffvk::gl::state::*;
use ffvk::gl::texture::{BaseFormat, CombineFunc, CombineSource, TexEnvMode, MAX_TEXTURE_UNITS};
use ffvk::Specialize;
use glam::{DVec4, Vec4};

use crate::texture_conformance::waves;
use crate::texture_units::{check, red_green, sampling, unit, units_state, UnitsCase};

fn cases(mode: LightingMode) -> Vec<UnitsCase> {
    let mut all = Vec::new();
    for format in BaseFormat::ALL {
        for env in [
            TexEnvMode::Replace,
            TexEnvMode::Modulate,
            TexEnvMode::Decal,
            TexEnvMode::Blend,
            TexEnvMode::Add,
            TexEnvMode::Combine,
        ] {
            // Table 3.22 leaves GL_DECAL undefined but for RGB and RGBA.
            if env == TexEnvMode::Decal && !matches!(format, BaseFormat::Rgb | BaseFormat::Rgba) {
                continue;
            }
            let state = units_state(mode, |gl| {
                gl.tex_env(TexEnvParam::Mode(env)).unwrap();
                gl.tex_env(TexEnvParam::Color(Vec4::new(0.1, 0.8, 0.3, 0.4)))
                    .unwrap();
                if env == TexEnvMode::Combine {
                    // Interpolate the texture and the constant by the texture's alpha, alpha
                    // added: both of the format's components show.
                    gl.tex_env(TexEnvParam::CombineRgb(CombineFunc::Interpolate))
                        .unwrap();
                    gl.tex_env(TexEnvParam::SourceRgb(1, CombineSource::Constant))
                        .unwrap();
                    gl.tex_env(TexEnvParam::SourceRgb(2, CombineSource::Texture))
                        .unwrap();
                    gl.tex_env(TexEnvParam::CombineAlpha(CombineFunc::Add)).unwrap();
                }
            });
            let name = Box::leak(format!("{}_{}", format.name(), env.name()).into_boxed_str());
            all.push(UnitsCase {
                name,
                state,
                textures: [Some(waves().with_base_format(format)), None, None, None],
                mesh_texcoords: 0,
                cube_maps: Default::default(),
                sampling: sampling(),
            });
        }
    }
    // The light map: an RGB base on unit 0, a luminance map modulating it on unit 1.
    all.push(UnitsCase {
        name: "rgb_base_and_a_luminance_light_map",
        state: units_state(mode, |gl| unit(gl, 1, TexEnvMode::Modulate)),
        textures: [
            Some(red_green().with_base_format(BaseFormat::Rgb)),
            Some(waves().with_base_format(BaseFormat::Luminance)),
            None,
            None,
        ],
        mesh_texcoords: 0b10,
        cube_maps: Default::default(),
        sampling: sampling(),
    });
    all
}

#[test]
fn each_base_format_under_each_environment_matches_mesa_gl() {
    let mut all = cases(LightingMode::Vertex);
    all.extend(cases(LightingMode::Flat));
    check(Specialize::default(), &all);
}

#[test]
fn the_uber_shader_reads_each_base_format_as_the_specialized_pipelines_do() {
    check(Specialize::Never, &cases(LightingMode::Vertex));
}

/// Table 3.22's rows at one fragment, worked by hand: C_p = (0.5, 0.25, 1), A_p = 0.5, the
/// texel's RGBA8 (0.8, 0.2, 0.4, 0.25), C_c = (0, 1, 0), A_c = 1.
#[test]
fn table_3_22_reads_each_format_as_the_spec_says() {
    use ffvk::reference::texture::textured_color;
    let c_f = DVec4::new(0.5, 0.25, 1.0, 0.5);
    let texel = DVec4::new(0.8, 0.2, 0.4, 0.25);
    let at = |format: BaseFormat, env: TexEnvMode| {
        let mut gl = GlState::new();
        gl.enable(Cap::Texture2D).unwrap();
        gl.tex_env(TexEnvParam::Mode(env)).unwrap();
        gl.tex_env(TexEnvParam::Color(Vec4::new(0.0, 1.0, 0.0, 1.0)))
            .unwrap();
        let mut texels = [DVec4::ZERO; MAX_TEXTURE_UNITS];
        texels[0] = format.texel(texel);
        let formats = [format; MAX_TEXTURE_UNITS];
        textured_color(&gl.lighting.texture_units, (1, formats), c_f, texels)
    };
    let close = |a: DVec4, b: DVec4| assert!((a - b).abs().max_element() < 1e-12, "{a} != {b}");
    // GL_ALPHA: the color stays C_p; alpha A_s under REPLACE, A_p A_s otherwise.
    close(
        at(BaseFormat::Alpha, TexEnvMode::Replace),
        DVec4::new(0.5, 0.25, 1.0, 0.25),
    );
    close(
        at(BaseFormat::Alpha, TexEnvMode::Modulate),
        DVec4::new(0.5, 0.25, 1.0, 0.125),
    );
    close(
        at(BaseFormat::Alpha, TexEnvMode::Add),
        DVec4::new(0.5, 0.25, 1.0, 0.125),
    );
    // GL_LUMINANCE: L = R = 0.8 in each channel; alpha stays A_p.
    close(
        at(BaseFormat::Luminance, TexEnvMode::Replace),
        DVec4::new(0.8, 0.8, 0.8, 0.5),
    );
    close(
        at(BaseFormat::Luminance, TexEnvMode::Modulate),
        DVec4::new(0.4, 0.2, 0.8, 0.5),
    );
    close(
        at(BaseFormat::Luminance, TexEnvMode::Add),
        DVec4::new(1.0, 1.0, 1.0, 0.5),
    );
    // BLEND: C_p (1 − C_s) + C_c C_s = (0.1, 0.85, 0.2).
    close(
        at(BaseFormat::Luminance, TexEnvMode::Blend),
        DVec4::new(0.1, 0.85, 0.2, 0.5),
    );
    // GL_LUMINANCE_ALPHA: L and A_s = 0.25.
    close(
        at(BaseFormat::LuminanceAlpha, TexEnvMode::Modulate),
        DVec4::new(0.4, 0.2, 0.8, 0.125),
    );
    // GL_INTENSITY: I = 0.8 everywhere; BLEND's alpha A_p (1 − I) + A_c I = 0.9, ADD's A_p + I.
    close(at(BaseFormat::Intensity, TexEnvMode::Replace), DVec4::splat(0.8));
    close(
        at(BaseFormat::Intensity, TexEnvMode::Blend),
        DVec4::new(0.1, 0.85, 0.2, 0.9),
    );
    close(
        at(BaseFormat::Intensity, TexEnvMode::Add),
        DVec4::new(1.0, 1.0, 1.0, 1.0),
    );
    // GL_RGB: the texel's color, alpha A_p; DECAL with A_s = 1 is the texel's color.
    close(
        at(BaseFormat::Rgb, TexEnvMode::Replace),
        DVec4::new(0.8, 0.2, 0.4, 0.5),
    );
    close(
        at(BaseFormat::Rgb, TexEnvMode::Decal),
        DVec4::new(0.8, 0.2, 0.4, 0.5),
    );
    // GL_RGBA, as before.
    close(
        at(BaseFormat::Rgba, TexEnvMode::Modulate),
        DVec4::new(0.4, 0.05, 0.4, 0.125),
    );
}
