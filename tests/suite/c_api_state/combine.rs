//! `GL_COMBINE`'s sequences of the differential test (GL 2.1 §3.8.13, table 3.24;
//! ARB_texture_env_combine and _dot3): each function for RGB and alpha, each source and
//! operand for each argument, and the scales, through the four forms of glTexEnv, valid and
//! invalid (a dot product as the alpha function, a color operand on an alpha argument, a scale
//! other than 1, 2 or 4, values and names that are none of GL's); the mode switched to
//! `GL_COMBINE` and away. Each case is followed by glGetTexEnv{i,f}v of every name.
//!
//! `GL_TEXTUREn` sources (ARB_texture_env_crossbar, core since GL 1.4) are in `units.rs`,
//! with the texture units they name. Not here either: the extensions' names and values Mesa
//! takes beyond GL 2.1's (NV_texture_env_combine4's fourth argument, `GL_OPERAND3_ALPHA_NV`
//! 0x859B; ATI_texture_env_combine3's functions and `GL_ZERO`/`GL_ONE` sources).

use super::{Call, Query, Step};

const TEXTURE_ENV: u32 = 0x2300;
const TEXTURE_ENV_MODE: u32 = 0x2200;
const COMBINE: u32 = 0x8570;
const COMBINE_RGB: u32 = 0x8571;
const COMBINE_ALPHA: u32 = 0x8572;
const RGB_SCALE: u32 = 0x8573;
const ALPHA_SCALE: u32 = 0x0D1C;
const SRC0_RGB: u32 = 0x8580;
const SRC0_ALPHA: u32 = 0x8588;
const OPERAND0_RGB: u32 = 0x8590;
const OPERAND0_ALPHA: u32 = 0x8598;
const REPLACE: u32 = 0x1E01;
const MODULATE: u32 = 0x2100;
const DECAL: u32 = 0x2101;
const ADD: u32 = 0x0104;
const ADD_SIGNED: u32 = 0x8574;
const INTERPOLATE: u32 = 0x8575;
const SUBTRACT: u32 = 0x84E7;
const DOT3_RGB: u32 = 0x86AE;
const DOT3_RGBA: u32 = 0x86AF;
const TEXTURE: u32 = 0x1702;
const CONSTANT: u32 = 0x8576;
const PRIMARY_COLOR: u32 = 0x8577;
const PREVIOUS: u32 = 0x8578;
const SRC_COLOR: u32 = 0x0300;
const ONE_MINUS_SRC_COLOR: u32 = 0x0301;
const SRC_ALPHA: u32 = 0x0302;
const ONE_MINUS_SRC_ALPHA: u32 = 0x0303;
const POINT_SPRITE: u32 = 0x8861;
const BOGUS: u32 = 0x1234;

const FUNCS: [(u32, &str); 8] = [
    (REPLACE, "GL_REPLACE"),
    (MODULATE, "GL_MODULATE"),
    (ADD, "GL_ADD"),
    (ADD_SIGNED, "GL_ADD_SIGNED"),
    (INTERPOLATE, "GL_INTERPOLATE"),
    (SUBTRACT, "GL_SUBTRACT"),
    (DOT3_RGB, "GL_DOT3_RGB"),
    (DOT3_RGBA, "GL_DOT3_RGBA"),
];
const SOURCES: [(u32, &str); 4] = [
    (TEXTURE, "GL_TEXTURE"),
    (CONSTANT, "GL_CONSTANT"),
    (PRIMARY_COLOR, "GL_PRIMARY_COLOR"),
    (PREVIOUS, "GL_PREVIOUS"),
];
const OPERANDS: [(u32, &str); 4] = [
    (SRC_COLOR, "GL_SRC_COLOR"),
    (ONE_MINUS_SRC_COLOR, "GL_ONE_MINUS_SRC_COLOR"),
    (SRC_ALPHA, "GL_SRC_ALPHA"),
    (ONE_MINUS_SRC_ALPHA, "GL_ONE_MINUS_SRC_ALPHA"),
];

/// Every name glGetTexEnv answers for `GL_TEXTURE_ENV` but the color, with its GL name.
fn pnames() -> Vec<(u32, String)> {
    let mut names = vec![
        (TEXTURE_ENV_MODE, "GL_TEXTURE_ENV_MODE".to_string()),
        (COMBINE_RGB, "GL_COMBINE_RGB".into()),
        (COMBINE_ALPHA, "GL_COMBINE_ALPHA".into()),
    ];
    for n in 0..3 {
        names.push((SRC0_RGB + n, format!("GL_SRC{n}_RGB")));
        names.push((SRC0_ALPHA + n, format!("GL_SRC{n}_ALPHA")));
        names.push((OPERAND0_RGB + n, format!("GL_OPERAND{n}_RGB")));
        names.push((OPERAND0_ALPHA + n, format!("GL_OPERAND{n}_ALPHA")));
    }
    names.push((RGB_SCALE, "GL_RGB_SCALE".into()));
    names.push((ALPHA_SCALE, "GL_ALPHA_SCALE".into()));
    names
}

/// The call that sets `pname` to `v` through `form` (0 i, 1 f, 2 iv, 3 fv); the vector forms
/// pass values after the first that GL does not read.
fn form(form: usize, pname: u32, v: f32) -> Call {
    match form {
        0 => Call::TexEnvi(TEXTURE_ENV, pname, v as i32),
        1 => Call::TexEnvf(TEXTURE_ENV, pname, v),
        2 => Call::TexEnviv(TEXTURE_ENV, pname, vec![v as i32, 7, 7, 7]),
        _ => Call::TexEnvfv(TEXTURE_ENV, pname, vec![v, 7.0, 7.0, 7.0]),
    }
}

const FORMS: usize = 4;

/// glGetTexEnv{i,f}v of every name.
fn readback() -> Vec<Step> {
    let mut steps = Vec::new();
    for (pname, _) in pnames() {
        steps.push(Step::Query(Query::GetTexEnviv(TEXTURE_ENV, pname, 1)));
        steps.push(Step::Query(Query::GetTexEnvfv(TEXTURE_ENV, pname, 1)));
    }
    steps
}

/// Each form of glTexEnv setting `pname` to `value`, the name queried after each and set back
/// to `other` between them, so that each form's effect shows; the last form's value stays.
fn every_form(pname: u32, value: f32, other: u32) -> Vec<Step> {
    let mut steps = Vec::new();
    for f in 0..FORMS {
        steps.push(Step::Call(form(f, pname, value)));
        steps.push(Step::Query(Query::GetTexEnviv(TEXTURE_ENV, pname, 1)));
        steps.push(Step::Query(Query::GetTexEnvfv(TEXTURE_ENV, pname, 1)));
        steps.push(Step::Call(Call::TexEnvi(TEXTURE_ENV, pname, other as i32)));
    }
    steps.push(Step::Call(form(0, pname, value)));
    steps
}

/// The sequences: each case's steps, then [`readback`].
pub(super) fn sequences() -> Vec<(String, Vec<Step>)> {
    use Call::*;
    let c = Step::Call;
    let q = Step::Query;
    let mut cases: Vec<(String, Vec<Step>)> = vec![("GL's initial GL_COMBINE state".into(), vec![])];

    // The mode, and each function for RGB and alpha (the dot products are RGB functions:
    // GL_INVALID_ENUM for GL_COMBINE_ALPHA).
    cases.push((
        "every glTexEnv(GL_TEXTURE_ENV_MODE, GL_COMBINE)".into(),
        every_form(TEXTURE_ENV_MODE, COMBINE as f32, MODULATE),
    ));
    for (pname, pname_name) in [
        (COMBINE_RGB, "GL_COMBINE_RGB"),
        (COMBINE_ALPHA, "GL_COMBINE_ALPHA"),
    ] {
        for (func, func_name) in FUNCS {
            let other = if func == ADD { SUBTRACT } else { ADD };
            cases.push((
                format!("every glTexEnv({pname_name}, {func_name})"),
                every_form(pname, func as f32, other),
            ));
        }
    }
    // Each source for each argument, RGB and alpha.
    for n in 0..3 {
        for (first, kind) in [(SRC0_RGB, "RGB"), (SRC0_ALPHA, "ALPHA")] {
            for (source, source_name) in SOURCES {
                let other = if source == CONSTANT { PREVIOUS } else { CONSTANT };
                cases.push((
                    format!("every glTexEnv(GL_SRC{n}_{kind}, {source_name})"),
                    every_form(first + n, source as f32, other),
                ));
            }
        }
    }
    // Each operand for each argument: a color operand on an alpha argument is
    // GL_INVALID_ENUM.
    for n in 0..3 {
        for (first, kind) in [(OPERAND0_RGB, "RGB"), (OPERAND0_ALPHA, "ALPHA")] {
            for (operand, operand_name) in OPERANDS {
                let other = if operand == ONE_MINUS_SRC_ALPHA {
                    SRC_ALPHA
                } else {
                    ONE_MINUS_SRC_ALPHA
                };
                cases.push((
                    format!("every glTexEnv(GL_OPERAND{n}_{kind}, {operand_name})"),
                    every_form(first + n, operand as f32, other),
                ));
            }
        }
    }
    // The scales: 1, 2 and 4, and values that are none of them (GL_INVALID_VALUE).
    for (pname, pname_name) in [(RGB_SCALE, "GL_RGB_SCALE"), (ALPHA_SCALE, "GL_ALPHA_SCALE")] {
        for scale in [1.0, 2.0, 4.0, 0.0, 3.0, 8.0, -1.0, -2.0, 16.0] {
            let other = if scale == 2.0 { 4 } else { 2 };
            cases.push((
                format!("every glTexEnv({pname_name}, {scale})"),
                every_form(pname, scale, other),
            ));
        }
        for scale in [0.5f32, 2.5, 3.999, 1.0001] {
            cases.push((
                format!("glTexEnvf and glTexEnvfv({pname_name}, {scale})"),
                vec![
                    c(TexEnvi(TEXTURE_ENV, pname, 4)),
                    c(form(1, pname, scale)),
                    c(form(3, pname, scale)),
                ],
            ));
        }
    }

    // Values that are none of a name's, through every form; a float enum is truncated.
    type Named = (u32, &'static str);
    let bad_values: [(u32, &str, &[Named]); 4] = [
        (
            COMBINE_RGB,
            "GL_COMBINE_RGB",
            &[
                (BOGUS, "0x1234"),
                (COMBINE, "GL_COMBINE"),
                (DECAL, "GL_DECAL"),
                (SRC_COLOR, "GL_SRC_COLOR"),
                (TEXTURE, "GL_TEXTURE"),
                (DOT3_RGBA + 1, "GL_DOT3_RGBA + 1"),
            ],
        ),
        (
            COMBINE_ALPHA,
            "GL_COMBINE_ALPHA",
            &[(BOGUS, "0x1234"), (DECAL, "GL_DECAL"), (PREVIOUS, "GL_PREVIOUS")],
        ),
        (
            SRC0_RGB + 1,
            "GL_SRC1_RGB",
            &[
                (BOGUS, "0x1234"),
                (SRC_COLOR, "GL_SRC_COLOR"),
                (MODULATE, "GL_MODULATE"),
                (PREVIOUS + 1, "GL_PREVIOUS + 1"),
                (TEXTURE_ENV, "GL_TEXTURE_ENV"),
            ],
        ),
        (
            OPERAND0_ALPHA + 2,
            "GL_OPERAND2_ALPHA",
            &[
                (BOGUS, "0x1234"),
                (0, "0"),
                (TEXTURE, "GL_TEXTURE"),
                (ONE_MINUS_SRC_ALPHA + 1, "GL_DST_ALPHA"),
            ],
        ),
    ];
    for (pname, pname_name, values) in bad_values {
        for &(value, name) in values {
            let steps = (0..FORMS).map(|f| c(form(f, pname, value as f32))).collect();
            cases.push((format!("every glTexEnv({pname_name}, {name})"), steps));
        }
    }
    for (pname, pname_name) in [
        (SRC0_ALPHA + 2, "GL_SRC2_ALPHA"),
        (OPERAND0_RGB + 1, "GL_OPERAND1_RGB"),
    ] {
        cases.push((
            format!("every glTexEnv({pname_name}, -1) and 0x1234"),
            vec![
                c(form(0, pname, -1.0)),
                c(form(1, pname, -1.0)),
                c(form(2, pname, BOGUS as f32)),
                c(form(3, pname, BOGUS as f32)),
            ],
        ));
    }
    cases.push((
        "glTexEnvf and glTexEnvfv truncate an enum given with a fraction".into(),
        vec![
            c(TexEnvf(TEXTURE_ENV, COMBINE_RGB, DOT3_RGB as f32 + 0.75)),
            c(TexEnvf(TEXTURE_ENV, SRC0_RGB + 2, PRIMARY_COLOR as f32 + 0.5)),
            c(TexEnvfv(
                TEXTURE_ENV,
                OPERAND0_ALPHA,
                vec![ONE_MINUS_SRC_ALPHA as f32 + 0.25],
            )),
            c(TexEnvf(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as f32 + 0.5)),
        ],
    ));
    // Names that are none of glTexEnv's, and GL_COMBINE's names on another target.
    for pname in [BOGUS, COMBINE, SRC0_RGB - 1, OPERAND0_ALPHA - 1, RGB_SCALE + 1] {
        let mut steps: Vec<Step> = (0..FORMS).map(|f| c(form(f, pname, ADD as f32))).collect();
        steps.push(q(Query::GetTexEnviv(TEXTURE_ENV, pname, 1)));
        steps.push(q(Query::GetTexEnvfv(TEXTURE_ENV, pname, 1)));
        cases.push((format!("glTexEnv and glGetTexEnv of pname 0x{pname:04X}"), steps));
    }
    for target in [BOGUS, POINT_SPRITE] {
        cases.push((
            format!("glTexEnv and glGetTexEnv of GL_COMBINE's names on target 0x{target:04X}"),
            vec![
                c(TexEnvi(target, COMBINE_RGB, ADD as i32)),
                c(TexEnvf(target, RGB_SCALE, 2.0)),
                c(TexEnviv(target, SRC0_ALPHA, vec![CONSTANT as i32])),
                q(Query::GetTexEnviv(target, COMBINE_RGB, 1)),
                q(Query::GetTexEnvfv(target, RGB_SCALE, 1)),
            ],
        ));
    }

    // The mode switched: GL_COMBINE's state is set whatever the mode, and kept across it.
    cases.push((
        "GL_COMBINE's state set under GL_MODULATE, then the mode switched to GL_COMBINE".into(),
        vec![
            c(TexEnvi(TEXTURE_ENV, COMBINE_RGB, INTERPOLATE as i32)),
            c(TexEnvi(TEXTURE_ENV, SRC0_RGB + 2, PRIMARY_COLOR as i32)),
            c(TexEnvf(TEXTURE_ENV, ALPHA_SCALE, 4.0)),
            q(Query::GetTexEnviv(TEXTURE_ENV, TEXTURE_ENV_MODE, 1)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32)),
        ],
    ));
    cases.push((
        "GL_COMBINE set, then GL_DECAL: the combine state is kept".into(),
        vec![
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32)),
            c(TexEnvi(TEXTURE_ENV, COMBINE_RGB, DOT3_RGBA as i32)),
            c(TexEnvi(TEXTURE_ENV, COMBINE_ALPHA, SUBTRACT as i32)),
            c(TexEnvi(TEXTURE_ENV, OPERAND0_RGB + 1, ONE_MINUS_SRC_COLOR as i32)),
            c(TexEnvf(TEXTURE_ENV, RGB_SCALE, 2.0)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, DECAL as i32)),
        ],
    ));
    cases.push((
        "GL_COMBINE, GL_ADD, GL_COMBINE again, then a refused mode".into(),
        vec![
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32)),
            c(TexEnvi(TEXTURE_ENV, SRC0_ALPHA + 1, TEXTURE as i32)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, ADD as i32)),
            c(TexEnvfv(TEXTURE_ENV, TEXTURE_ENV_MODE, vec![COMBINE as f32])),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE_RGB as i32)),
        ],
    ));
    cases.push((
        "a refused GL_COMBINE value changes nothing".into(),
        vec![
            c(TexEnvi(TEXTURE_ENV, COMBINE_ALPHA, ADD_SIGNED as i32)),
            c(TexEnvi(TEXTURE_ENV, COMBINE_ALPHA, DOT3_RGB as i32)),
            c(TexEnvi(
                TEXTURE_ENV,
                OPERAND0_ALPHA + 1,
                ONE_MINUS_SRC_ALPHA as i32,
            )),
            c(TexEnvi(TEXTURE_ENV, OPERAND0_ALPHA + 1, SRC_COLOR as i32)),
            c(TexEnvf(TEXTURE_ENV, RGB_SCALE, 4.0)),
            c(TexEnvf(TEXTURE_ENV, RGB_SCALE, 3.0)),
        ],
    ));
    cases.push((
        "the first glTexEnv error sticks until glGetError reads it".into(),
        vec![
            Step::Quiet(TexEnvf(TEXTURE_ENV, ALPHA_SCALE, 3.0)),
            Step::Quiet(TexEnvi(TEXTURE_ENV, COMBINE_ALPHA, DOT3_RGBA as i32)),
            Step::Quiet(TexEnvi(TEXTURE_ENV, SRC0_RGB, BOGUS as i32)),
            q(Query::GetTexEnviv(TEXTURE_ENV, COMBINE_ALPHA, 1)),
            q(Query::GetTexEnviv(TEXTURE_ENV, COMBINE_ALPHA, 1)),
        ],
    ));

    cases
        .into_iter()
        .map(|(name, mut steps)| {
            steps.extend(readback());
            (name, steps)
        })
        .collect()
}
