//! `GL_COMBINE` (GL 2.1 §3.8.13, table 3.24; ARB_texture_env_combine and _dot3) against Mesa's
//! GL: texture_conformance.rs's lit, textured sphere (the waves texture, whose alpha varies;
//! the lit color's alpha 0.7; the environment color (0.2, 0.4, 1, 0.5)), each function with
//! sources and operands that reach its edges, scaled, compared over the same mask with the same
//! tolerances; and the function's values at edge inputs against the CPU reference's copy.

use ffvk::gl::state::*;
use ffvk::gl::texture::{
    AlphaOperand, CombineFunc, CombineSource, MagFilter, MinFilter, RgbOperand, Sampling, TexEnvMode,
};
use ffvk::Specialize;
use glam::{DVec4, Mat4};

use crate::support::*;
use crate::texture_conformance::{check, waves, Case};

/// GL's state of the texture conformance scenes with `GL_COMBINE` and `params` set.
fn with_combine(mode: LightingMode, params: &[TexEnvParam]) -> FixedFunctionState {
    let base = textured_state(
        TexEnvMode::Modulate,
        ColorControl::SeparateSpecularColor,
        mode,
        Mat4::IDENTITY,
    );
    let mut gl = GlState::new();
    gl.lighting = base;
    gl.tex_env(TexEnvParam::Mode(TexEnvMode::Combine)).unwrap();
    for &p in params {
        gl.tex_env(p).unwrap();
    }
    gl.lighting
}

#[test]
fn each_combine_function_source_and_operand_matches_mesa_gl() {
    use CombineFunc::*;
    use CombineSource::*;
    use TexEnvParam::*;
    let sampling = Sampling::default()
        .with_min_filter(MinFilter::Linear)
        .with_mag_filter(MagFilter::Linear);
    let one_minus = [RgbOperand::OneMinusSrcColor, RgbOperand::OneMinusSrcAlpha];
    let setups: Vec<(&str, Vec<TexEnvParam>)> = vec![
        ("default_modulate", vec![]),
        (
            "replace_constant",
            vec![
                CombineRgb(Replace),
                SourceRgb(0, Constant),
                CombineAlpha(Replace),
                SourceAlpha(0, Texture),
            ],
        ),
        ("add", vec![CombineRgb(Add), CombineAlpha(Add)]),
        (
            "add_signed_one_minus",
            vec![
                CombineRgb(AddSigned),
                OperandRgb(0, one_minus[0]),
                OperandRgb(1, one_minus[1]),
                CombineAlpha(AddSigned),
                OperandAlpha(1, AlphaOperand::OneMinusSrcAlpha),
            ],
        ),
        (
            "interpolate_by_texture_alpha",
            vec![
                CombineRgb(Interpolate),
                SourceRgb(0, Constant),
                SourceRgb(1, PrimaryColor),
                SourceRgb(2, Texture),
                OperandRgb(2, RgbOperand::SrcAlpha),
                CombineAlpha(Interpolate),
                SourceAlpha(2, Texture),
            ],
        ),
        (
            "subtract_scaled_2",
            vec![
                CombineRgb(Subtract),
                RgbScale(2.0),
                CombineAlpha(Subtract),
                AlphaScale(2.0),
            ],
        ),
        ("dot3_rgb", vec![CombineRgb(Dot3Rgb), SourceRgb(1, Constant)]),
        (
            "dot3_rgba_scaled_4",
            vec![CombineRgb(Dot3Rgba), SourceRgb(1, PrimaryColor), RgbScale(4.0)],
        ),
        (
            "alpha_operands_in_rgb",
            vec![
                CombineRgb(Modulate),
                OperandRgb(0, RgbOperand::SrcAlpha),
                OperandRgb(1, RgbOperand::OneMinusSrcAlpha),
                SourceRgb(1, Constant),
                CombineAlpha(Replace),
                SourceAlpha(0, Constant),
                AlphaScale(4.0),
            ],
        ),
    ];
    let mut cases = Vec::new();
    for (name, params) in &setups {
        for mode in [LightingMode::Vertex, LightingMode::Flat] {
            cases.push(Case {
                name: format!("combine_{name}_{}", mode.name()),
                state: with_combine(mode, params),
                image: waves(),
                sampling,
                tol: 2,
                need: 0.999,
            });
        }
    }
    cases.push(Case {
        name: "combine_interpolate_fragment".into(),
        state: with_combine(LightingMode::Fragment, &setups[4].1),
        image: waves(),
        sampling,
        tol: 3,
        need: 0.999,
    });
    check(Specialize::default(), &cases);
    // The uber-shader decodes the same bits from the state block.
    check(Specialize::Never, &cases[..cases.len() - 1]);
}

/// Table 3.24 at edge values, worked by hand, against the CPU reference's copy (the source of
/// the conformance expectations); and GL's errors for `GL_COMBINE`'s parameters.
#[test]
fn the_combine_functions_give_table_3_24s_values_and_bad_parameters_are_refused() {
    use ffvk::reference::texture::combine;
    use CombineFunc::*;
    use TexEnvParam::*;
    let c_f = DVec4::new(1.0, 0.5, 0.0, 0.8);
    let c_s = DVec4::new(0.25, 1.0, 0.5, 0.4);
    let c_c = DVec4::new(0.0, 0.0, 1.0, 0.1);
    let at = |params: &[TexEnvParam]| {
        let mut gl = GlState::new();
        for &p in params {
            gl.tex_env(p).unwrap();
        }
        combine(&gl.lighting.texture_units[0].combine, c_f, c_s, c_c)
    };
    let close = |a: DVec4, b: DVec4| (a - b).abs().max_element() < 1e-12;
    // Defaults: Arg0 = texel, Arg1 = previous (the primary color), MODULATE.
    assert!(close(at(&[]), DVec4::new(0.25, 0.5, 0.0, 0.32)));
    // ADD clamps: (1.25, 1.5, 0.5) -> (1, 1, 0.5); alpha 1.2 -> 1.
    assert!(close(
        at(&[CombineRgb(Add), CombineAlpha(Add)]),
        DVec4::new(1.0, 1.0, 0.5, 1.0)
    ));
    // SUBTRACT clamps below: (-0.75, 0.5, 0.5); alpha 0.4 - 0.8 -> 0.
    assert!(close(
        at(&[CombineRgb(Subtract), CombineAlpha(Subtract)]),
        DVec4::new(0.0, 0.5, 0.5, 0.0)
    ));
    // DOT3_RGBA: 4 ((−0.25)(0.5) + (0.5)(0) + (0)(−0.5)) = −0.5 -> 0 everywhere, alpha too.
    assert!(close(at(&[CombineRgb(Dot3Rgba)]), DVec4::ZERO));
    let d = at(&[
        CombineRgb(Dot3Rgb),
        SourceRgb(0, CombineSource::PrimaryColor),
        SourceRgb(1, CombineSource::PrimaryColor),
    ]);
    // 4 ((0.5)² + 0 + (−0.5)²) = 2 -> 1 in RGB; alpha MODULATE of texel and primary: 0.32.
    assert!(close(d, DVec4::new(1.0, 1.0, 1.0, 0.32)), "{d}");
    // INTERPOLATE by the constant's alpha 0.1: texel 0.1 + primary 0.9.
    let i = at(&[
        CombineRgb(Interpolate),
        OperandRgb(2, RgbOperand::SrcAlpha),
        CombineAlpha(Replace),
        SourceAlpha(0, CombineSource::Constant),
        AlphaScale(4.0),
    ]);
    assert!(
        (i - DVec4::new(0.925, 0.55, 0.05, 0.4)).abs().max_element() < 1e-7,
        "{i}"
    );
    // GL's errors: a dot product as the alpha function, a scale other than 1, 2 or 4, an
    // argument past 2; nothing changes.
    let mut gl = GlState::new();
    assert!(gl.tex_env(CombineAlpha(Dot3Rgb)).is_err());
    assert!(gl.tex_env(RgbScale(3.0)).is_err());
    assert!(gl.tex_env(SourceRgb(3, CombineSource::Texture)).is_err());
    assert_eq!(gl.lighting.texture_units[0].combine, Default::default());
}
