//! The texture units' sequences of the differential test (GL 2.1 §2.7, §3.8.13, §3.8.17,
//! ARB_texture_env_crossbar): glActiveTexture on each unit and past the last (the first error
//! sticking), glMultiTexCoord on each unit through each form, glTexCoord after another unit was
//! made active, the `GL_TEXTURE_2D` and `GL_TEXTURE_GEN_*` enables, glTexEnv, glTexGen, the
//! texture matrix and `GL_COORD_REPLACE` set on several units, `GL_TEXTUREn` as a `GL_COMBINE`
//! source through every form (and past the last unit). Each case is followed by every unit's
//! state, queried with each unit made active in turn.
//!
//! Units at and past ffvk's four are named through the sentinels of `c_api_state.rs`, which
//! each implementation resolves with its own limits (Mesa has 8 units): `UNIT_LAST` is each
//! one's last unit, compared with the other's (and then not queried as `GL_ACTIVE_TEXTURE`,
//! whose value differs by design, nor as a source).

use super::{Call, Query, Step, COORDS_PAST_LAST, TEXTURE0, UNIT_LAST, UNIT_PAST_ACTIVE, UNIT_PAST_LAST};

const ACTIVE_TEXTURE: u32 = 0x84E0;
const CURRENT_TEXTURE_COORDS: u32 = 0x0B03;
const TEXTURE_MATRIX: u32 = 0x0BA8;
const MODELVIEW_MATRIX: u32 = 0x0BA6;
const TEXTURE_2D: u32 = 0x0DE1;
const TEXTURE_CUBE_MAP: u32 = 0x8513;
const TEXTURE_GEN_S: u32 = 0x0C60;
const TEXTURE_ENV: u32 = 0x2300;
const TEXTURE_ENV_MODE: u32 = 0x2200;
const TEXTURE_ENV_COLOR: u32 = 0x2201;
const COMBINE: u32 = 0x8570;
const COMBINE_RGB: u32 = 0x8571;
const COMBINE_ALPHA: u32 = 0x8572;
const RGB_SCALE: u32 = 0x8573;
const SRC0_RGB: u32 = 0x8580;
const SRC0_ALPHA: u32 = 0x8588;
const OPERAND0_RGB: u32 = 0x8590;
const MODULATE: u32 = 0x2100;
const DECAL: u32 = 0x2101;
const BLEND: u32 = 0x0BE2;
const ADD: u32 = 0x0104;
const REPLACE: u32 = 0x1E01;
const INTERPOLATE: u32 = 0x8575;
const SUBTRACT: u32 = 0x84E7;
const CONSTANT: u32 = 0x8576;
const PRIMARY_COLOR: u32 = 0x8577;
const PREVIOUS: u32 = 0x8578;
const ONE_MINUS_SRC_COLOR: u32 = 0x0301;
const POINT_SPRITE: u32 = 0x8861;
const COORD_REPLACE: u32 = 0x8862;
const S: u32 = 0x2000;
const T: u32 = 0x2001;
const R: u32 = 0x2002;
const Q: u32 = 0x2003;
const TEXTURE_GEN_MODE: u32 = 0x2500;
const OBJECT_PLANE: u32 = 0x2501;
const EYE_PLANE: u32 = 0x2502;
const OBJECT_LINEAR: u32 = 0x2401;
const SPHERE_MAP: u32 = 0x2402;
const REFLECTION_MAP: u32 = 0x8512;
const BOGUS: u32 = 0x1234;

/// ffvk's four units, `GL_TEXTURE0` first.
const UNITS: [u32; 4] = [TEXTURE0, TEXTURE0 + 1, TEXTURE0 + 2, TEXTURE0 + 3];

/// Column-major matrices, each exact in floats: a scale with a translation, a shear, a quarter
/// turn about z, a projective one.
const MATRICES: [[f32; 16]; 4] = [
    [
        2.0, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.5, -0.25, 0.0, 1.0,
    ],
    [
        1.0, 0.5, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.25, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ],
    [
        0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0,
    ],
    [
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0,
    ],
];

/// The state of each of `units`, each made active in turn (its `GL_ACTIVE_TEXTURE` queried
/// but for `UNIT_LAST`), then `GL_TEXTURE0` active again.
fn readback(units: &[u32]) -> Vec<Step> {
    use Query::*;
    let c = Step::Call;
    let q = Step::Query;
    let mut steps = Vec::new();
    for &unit in units {
        steps.push(c(Call::ActiveTexture(unit)));
        if unit != UNIT_LAST {
            steps.push(q(GetIntegerv(ACTIVE_TEXTURE, 1)));
        }
        steps.push(q(GetFloatv(CURRENT_TEXTURE_COORDS, 4)));
        steps.push(q(GetIntegerv(CURRENT_TEXTURE_COORDS, 4)));
        steps.push(q(GetFloatv(TEXTURE_MATRIX, 16)));
        steps.push(q(IsEnabled(TEXTURE_2D)));
        steps.push(q(GetBooleanv(TEXTURE_2D, 1)));
        steps.push(q(IsEnabled(TEXTURE_CUBE_MAP)));
        steps.push(q(GetIntegerv(TEXTURE_CUBE_MAP, 1)));
        for cap in TEXTURE_GEN_S..TEXTURE_GEN_S + 4 {
            steps.push(q(IsEnabled(cap)));
        }
        steps.push(q(GetTexEnviv(TEXTURE_ENV, TEXTURE_ENV_MODE, 1)));
        steps.push(q(GetTexEnvfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, 4)));
        steps.push(q(GetTexEnviv(TEXTURE_ENV, COMBINE_RGB, 1)));
        steps.push(q(GetTexEnviv(TEXTURE_ENV, COMBINE_ALPHA, 1)));
        for n in 0..3 {
            steps.push(q(GetTexEnviv(TEXTURE_ENV, SRC0_RGB + n, 1)));
            steps.push(q(GetTexEnvfv(TEXTURE_ENV, SRC0_ALPHA + n, 1)));
        }
        steps.push(q(GetTexEnvfv(TEXTURE_ENV, RGB_SCALE, 1)));
        steps.push(q(GetTexEnviv(POINT_SPRITE, COORD_REPLACE, 1)));
        for coord in [S, T, R, Q] {
            steps.push(q(GetTexGeniv(coord, TEXTURE_GEN_MODE, 1)));
        }
        steps.push(q(GetTexGenfv(S, OBJECT_PLANE, 4)));
        steps.push(q(GetTexGenfv(T, EYE_PLANE, 4)));
    }
    steps.push(c(Call::ActiveTexture(TEXTURE0)));
    steps.push(q(GetIntegerv(ACTIVE_TEXTURE, 1)));
    steps
}

/// The call that sets `pname` to `v` through `form` (0 i, 1 f, 2 iv, 3 fv), as combine.rs's.
fn form(form: usize, pname: u32, v: u32) -> Call {
    match form {
        0 => Call::TexEnvi(TEXTURE_ENV, pname, v as i32),
        1 => Call::TexEnvf(TEXTURE_ENV, pname, v as f32),
        2 => Call::TexEnviv(TEXTURE_ENV, pname, vec![v as i32, 7, 7, 7]),
        _ => Call::TexEnvfv(TEXTURE_ENV, pname, vec![v as f32, 7.0, 7.0, 7.0]),
    }
}

/// The sequences: each case's steps, then [`readback`] of ffvk's four units (or of units 0 to
/// 2 and the last unit, for a case that names `UNIT_LAST`).
pub(super) fn sequences() -> Vec<(String, Vec<Step>)> {
    use Call::*;
    let c = Step::Call;
    let q = Step::Query;
    let mut cases: Vec<(String, Vec<Step>)> = vec![("GL's initial texture units".into(), vec![])];

    // glActiveTexture: each unit, the value answered through every query form.
    for (i, unit) in UNITS.into_iter().enumerate() {
        cases.push((
            format!("glActiveTexture(GL_TEXTURE{i})"),
            vec![
                c(ActiveTexture(unit)),
                q(Query::GetIntegerv(ACTIVE_TEXTURE, 1)),
                q(Query::GetFloatv(ACTIVE_TEXTURE, 1)),
                q(Query::GetBooleanv(ACTIVE_TEXTURE, 1)),
                c(ActiveTexture(unit)),
                q(Query::GetIntegerv(ACTIVE_TEXTURE, 1)),
            ],
        ));
    }
    // Past the last unit glActiveTexture takes, and values that are no GL_TEXTUREi (below
    // GL_TEXTURE0 they wrap around in GL's unsigned arithmetic): GL_INVALID_ENUM, the active
    // unit kept.
    for (texture, name) in [
        (UNIT_PAST_ACTIVE, "the first unit past the last"),
        (BOGUS, "0x1234"),
        (0, "0"),
        (TEXTURE0 - 1, "GL_TEXTURE0 - 1"),
        (u32::MAX, "0xFFFFFFFF"),
        (TEXTURE_2D, "GL_TEXTURE_2D"),
    ] {
        cases.push((
            format!("glActiveTexture({name}) after GL_TEXTURE2"),
            vec![
                c(ActiveTexture(TEXTURE0 + 2)),
                c(ActiveTexture(texture)),
                q(Query::GetIntegerv(ACTIVE_TEXTURE, 1)),
                c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, ADD as i32)),
            ],
        ));
    }
    cases.push((
        "the first glActiveTexture error sticks until glGetError reads it".into(),
        vec![
            Step::Quiet(ActiveTexture(UNIT_PAST_ACTIVE)),
            Step::Quiet(ActiveTexture(TEXTURE0 + 1)),
            Step::Quiet(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, BOGUS as i32)),
            Step::Quiet(ActiveTexture(BOGUS)),
            q(Query::GetIntegerv(ACTIVE_TEXTURE, 1)),
            q(Query::GetIntegerv(ACTIVE_TEXTURE, 1)),
        ],
    ));
    cases.push((
        "the last unit: glActiveTexture, glTexEnv and the texture matrix on it".into(),
        vec![
            c(ActiveTexture(UNIT_LAST)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, DECAL as i32)),
            c(TexEnvfv(
                TEXTURE_ENV,
                TEXTURE_ENV_COLOR,
                vec![0.25, 0.5, 0.75, 1.0],
            )),
            c(LoadTextureMatrix(MATRICES[1])),
            c(Enable(TEXTURE_2D)),
            c(MultiTexCoord4f(UNIT_LAST, [0.25, -2.0, 3.0, 0.5])),
            q(Query::GetFloatv(TEXTURE_MATRIX, 16)),
        ],
    ));

    // glMultiTexCoord on each unit through each form, whatever the active unit; glTexCoord is
    // unit 0's.
    for (i, unit) in UNITS.into_iter().enumerate() {
        let v = [0.25 + i as f32, -1.75, 2.0 * i as f32, 0.75];
        for (name, call) in [
            ("glMultiTexCoord4f", MultiTexCoord4f(unit, v)),
            ("glMultiTexCoord2f", MultiTexCoord2f(unit, [v[0], v[1]])),
            ("glMultiTexCoord4fv", MultiTexCoord4fv(unit, v.to_vec())),
        ] {
            cases.push((
                format!("{name}(GL_TEXTURE{i}) with GL_TEXTURE{} active", 3 - i),
                vec![c(ActiveTexture(UNITS[3 - i])), c(call)],
            ));
        }
    }
    cases.push((
        "glTexCoord4f with GL_TEXTURE2 active sets unit 0's coordinates".into(),
        vec![
            c(MultiTexCoord4f(TEXTURE0 + 2, [1.0, 2.0, 3.0, 4.0])),
            c(ActiveTexture(TEXTURE0 + 2)),
            c(TexCoord4f([-0.75, 0.25, 1.5, 1.0])),
            q(Query::GetFloatv(CURRENT_TEXTURE_COORDS, 4)),
        ],
    ));
    cases.push((
        "glMultiTexCoord on every unit, then again on two".into(),
        vec![
            c(MultiTexCoord4f(TEXTURE0, [1.0, 0.0, 0.0, 1.0])),
            c(MultiTexCoord2f(TEXTURE0 + 1, [2.0, 0.0])),
            c(MultiTexCoord4fv(TEXTURE0 + 2, vec![3.0, 0.0, -1.0, 1.0])),
            c(MultiTexCoord4f(TEXTURE0 + 3, [4.0, 0.0, 0.0, 2.0])),
            c(MultiTexCoord2f(TEXTURE0 + 3, [5.0, -5.0])),
            c(MultiTexCoord4fv(TEXTURE0, vec![6.0, 6.0, 6.0, 6.0])),
        ],
    ));
    cases.push((
        "glMultiTexCoord on the last unit".into(),
        vec![
            c(MultiTexCoord4f(UNIT_LAST, [0.5, 1.5, 2.5, 3.5])),
            c(MultiTexCoord4f(TEXTURE0 + 2, [-1.0, -2.0, -3.0, 1.0])),
        ],
    ));
    // Targets that name no coordinate set: GL 2.1 leaves them undefined, ffvk refuses them,
    // Mesa writes set (target & 7) (a listed deviation).
    for (target, name) in [
        (COORDS_PAST_LAST, "the first set past the last"),
        (BOGUS, "0x1234"),
        (TEXTURE0 - 1, "GL_TEXTURE0 - 1"),
        (ACTIVE_TEXTURE, "GL_ACTIVE_TEXTURE"),
    ] {
        cases.push((
            format!("glMultiTexCoord({name}) through each form"),
            vec![
                c(MultiTexCoord4f(target, [9.0, 8.0, 7.0, 6.0])),
                c(MultiTexCoord2f(target, [5.0, 4.0])),
                c(MultiTexCoord4fv(target, vec![3.0, 2.0, 1.0, 0.5])),
            ],
        ));
    }

    // The enables of each unit.
    for (i, unit) in UNITS.into_iter().enumerate() {
        cases.push((
            format!("glEnable(GL_TEXTURE_2D) and glEnable(GL_TEXTURE_GEN_*) on GL_TEXTURE{i}"),
            vec![
                c(ActiveTexture(unit)),
                c(Enable(TEXTURE_2D)),
                c(Enable(TEXTURE_GEN_S + i as u32)),
                c(Enable(TEXTURE_GEN_S + (i as u32 + 1) % 4)),
                q(Query::IsEnabled(TEXTURE_2D)),
                c(Disable(TEXTURE_GEN_S + (i as u32 + 1) % 4)),
            ],
        ));
    }
    cases.push((
        "GL_TEXTURE_2D enabled on units 1 and 3, disabled on 3 again, with unit 0 active between".into(),
        vec![
            c(ActiveTexture(TEXTURE0 + 1)),
            c(Enable(TEXTURE_2D)),
            c(ActiveTexture(TEXTURE0 + 3)),
            c(Enable(TEXTURE_2D)),
            c(ActiveTexture(TEXTURE0)),
            q(Query::IsEnabled(TEXTURE_2D)),
            c(ActiveTexture(TEXTURE0 + 3)),
            c(Disable(TEXTURE_2D)),
        ],
    ));

    // GL_TEXTURE_CUBE_MAP (GL 2.1 §3.8.15), the active unit's: enabled and disabled on several
    // units, beside and without GL_TEXTURE_2D, queried through glIsEnabled and every glGet form.
    for (i, unit) in UNITS.into_iter().enumerate() {
        cases.push((
            format!("glEnable(GL_TEXTURE_CUBE_MAP) with and without GL_TEXTURE_2D on GL_TEXTURE{i}"),
            vec![
                c(ActiveTexture(unit)),
                c(Enable(TEXTURE_CUBE_MAP)),
                q(Query::IsEnabled(TEXTURE_CUBE_MAP)),
                q(Query::IsEnabled(TEXTURE_2D)),
                q(Query::GetBooleanv(TEXTURE_CUBE_MAP, 1)),
                q(Query::GetFloatv(TEXTURE_CUBE_MAP, 1)),
                c(Enable(TEXTURE_2D)),
                c(ActiveTexture(UNITS[(i + 1) % 4])),
                q(Query::IsEnabled(TEXTURE_CUBE_MAP)),
                c(ActiveTexture(unit)),
                c(Disable(TEXTURE_2D)),
                q(Query::IsEnabled(TEXTURE_CUBE_MAP)),
            ],
        ));
    }
    cases.push((
        "GL_TEXTURE_CUBE_MAP on units 0, 2 and 3, disabled on 2 again and twice on 3".into(),
        vec![
            c(Enable(TEXTURE_CUBE_MAP)),
            c(ActiveTexture(TEXTURE0 + 2)),
            c(Enable(TEXTURE_CUBE_MAP)),
            c(ActiveTexture(TEXTURE0 + 3)),
            c(Enable(TEXTURE_CUBE_MAP)),
            c(Enable(TEXTURE_CUBE_MAP)),
            c(ActiveTexture(TEXTURE0 + 2)),
            c(Disable(TEXTURE_CUBE_MAP)),
            q(Query::IsEnabled(TEXTURE_CUBE_MAP)),
            c(ActiveTexture(TEXTURE0 + 3)),
            c(Disable(TEXTURE_CUBE_MAP)),
            c(Disable(TEXTURE_CUBE_MAP)),
            c(ActiveTexture(TEXTURE0 + 1)),
            c(Disable(TEXTURE_CUBE_MAP)),
        ],
    ));
    cases.push((
        "GL_TEXTURE_CUBE_MAP on the last unit, and a glActiveTexture error leaving it on unit 1".into(),
        vec![
            c(ActiveTexture(UNIT_LAST)),
            c(Enable(TEXTURE_CUBE_MAP)),
            q(Query::IsEnabled(TEXTURE_CUBE_MAP)),
            c(ActiveTexture(TEXTURE0 + 1)),
            c(ActiveTexture(UNIT_PAST_ACTIVE)),
            c(Enable(TEXTURE_CUBE_MAP)),
            q(Query::IsEnabled(TEXTURE_CUBE_MAP)),
        ],
    ));

    // glTexEnv on several units.
    cases.push((
        "a texture environment per unit: GL_DECAL, GL_ADD, GL_COMBINE, GL_BLEND".into(),
        vec![
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, DECAL as i32)),
            c(ActiveTexture(TEXTURE0 + 1)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, ADD as i32)),
            c(TexEnvfv(TEXTURE_ENV, TEXTURE_ENV_COLOR, vec![0.1, 0.2, 0.3, 0.4])),
            c(ActiveTexture(TEXTURE0 + 2)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32)),
            c(TexEnvi(TEXTURE_ENV, COMBINE_RGB, INTERPOLATE as i32)),
            c(TexEnvi(TEXTURE_ENV, COMBINE_ALPHA, SUBTRACT as i32)),
            c(TexEnvi(TEXTURE_ENV, SRC0_RGB + 2, PRIMARY_COLOR as i32)),
            c(TexEnvi(TEXTURE_ENV, OPERAND0_RGB, ONE_MINUS_SRC_COLOR as i32)),
            c(TexEnvf(TEXTURE_ENV, RGB_SCALE, 4.0)),
            c(ActiveTexture(TEXTURE0 + 3)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, BLEND as i32)),
            c(TexEnviv(
                TEXTURE_ENV,
                TEXTURE_ENV_COLOR,
                vec![1 << 30, 0, i32::MAX, -5],
            )),
        ],
    ));
    cases.push((
        "a refused glTexEnv on unit 2 leaves it, unit 0's untouched".into(),
        vec![
            c(ActiveTexture(TEXTURE0 + 2)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, REPLACE as i32)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, BOGUS as i32)),
            c(TexEnvf(TEXTURE_ENV, RGB_SCALE, 3.0)),
        ],
    ));

    // glTexGen on several units, eye planes under a modelview (each stored in eye space).
    let translate: [f32; 16] = [
        1.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 3.0, -4.0, 5.0, 1.0,
    ];
    cases.push((
        "texture coordinate generation per unit, eye planes under a modelview".into(),
        vec![
            c(ActiveTexture(TEXTURE0 + 1)),
            c(LoadModelview(translate)),
            c(TexGenfv(T, EYE_PLANE, vec![1.0, 2.0, -0.5, 3.0])),
            c(Enable(TEXTURE_GEN_S + 1)),
            c(LoadModelview(MATRICES[0])),
            c(ActiveTexture(TEXTURE0 + 2)),
            c(TexGeni(S, TEXTURE_GEN_MODE, SPHERE_MAP as i32)),
            c(TexGeni(T, TEXTURE_GEN_MODE, SPHERE_MAP as i32)),
            c(TexGenfv(T, EYE_PLANE, vec![0.0, 1.0, 0.0, -1.0])),
            c(ActiveTexture(TEXTURE0 + 3)),
            c(TexGeni(Q, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32)),
            c(TexGenfv(S, OBJECT_PLANE, vec![0.5, 0.0, 0.25, 1.0])),
            c(TexGeni(R, TEXTURE_GEN_MODE, REFLECTION_MAP as i32)),
            c(Enable(TEXTURE_GEN_S + 3)),
            c(ActiveTexture(TEXTURE0)),
            c(TexGendv(S, OBJECT_PLANE, vec![-1.0, 0.0, 0.0, 2.0])),
            q(Query::GetFloatv(MODELVIEW_MATRIX, 16)),
        ],
    ));

    // The texture matrix of each unit.
    cases.push((
        "a texture matrix per unit: units 0, 2 and 3 loaded, unit 1 left".into(),
        vec![
            c(LoadTextureMatrix(MATRICES[0])),
            c(ActiveTexture(TEXTURE0 + 2)),
            c(LoadTextureMatrix(MATRICES[2])),
            c(ActiveTexture(TEXTURE0 + 3)),
            c(LoadTextureMatrix(MATRICES[3])),
            c(LoadTextureMatrix(MATRICES[1])),
            q(Query::GetFloatv(TEXTURE_MATRIX, 16)),
            q(Query::GetIntegerv(TEXTURE_MATRIX, 16)),
            q(Query::GetFloatv(MODELVIEW_MATRIX, 16)),
        ],
    ));
    cases.push((
        "a texture matrix loaded after a refused glActiveTexture goes to the unit still active".into(),
        vec![
            c(ActiveTexture(TEXTURE0 + 1)),
            c(ActiveTexture(UNIT_PAST_ACTIVE)),
            c(LoadTextureMatrix(MATRICES[3])),
        ],
    ));

    // GL_COORD_REPLACE is a unit's.
    cases.push((
        "GL_COORD_REPLACE on unit 2, then off on unit 0".into(),
        vec![
            c(ActiveTexture(TEXTURE0 + 2)),
            c(TexEnvi(POINT_SPRITE, COORD_REPLACE, 1)),
            c(ActiveTexture(TEXTURE0)),
            c(TexEnvi(POINT_SPRITE, COORD_REPLACE, 0)),
        ],
    ));

    // GL_TEXTUREn sources (ARB_texture_env_crossbar, GL 1.4): each unit's texel as each
    // argument through every form, the name queried after each and set back between them.
    for (n, source) in UNITS.into_iter().enumerate() {
        for (first, kind) in [(SRC0_RGB, "RGB"), (SRC0_ALPHA, "ALPHA")] {
            for argument in 0..3 {
                let pname = first + argument;
                let mut steps = vec![c(ActiveTexture(UNITS[(n + argument as usize) % 4]))];
                for f in 0..4 {
                    steps.push(c(form(f, pname, source)));
                    steps.push(q(Query::GetTexEnviv(TEXTURE_ENV, pname, 1)));
                    steps.push(q(Query::GetTexEnvfv(TEXTURE_ENV, pname, 1)));
                    steps.push(c(TexEnvi(TEXTURE_ENV, pname, CONSTANT as i32)));
                }
                steps.push(c(form(0, pname, source)));
                cases.push((
                    format!(
                        "every glTexEnv(GL_SRC{argument}_{kind}, GL_TEXTURE{n}) on unit {}",
                        (n + argument as usize) % 4
                    ),
                    steps,
                ));
            }
        }
    }
    // Past the last unit, and GL_TEXTUREn enums past any unit: GL_INVALID_ENUM, unchanged.
    for (value, name) in [
        (UNIT_PAST_LAST, "the first unit past the last"),
        (TEXTURE0 + 31, "GL_TEXTURE31"),
        (ACTIVE_TEXTURE, "GL_ACTIVE_TEXTURE (GL_TEXTURE0 + 32)"),
        (TEXTURE0 - 1, "GL_TEXTURE0 - 1"),
    ] {
        for pname in [SRC0_RGB + 1, SRC0_ALPHA + 2] {
            let mut steps = vec![
                c(ActiveTexture(TEXTURE0 + 1)),
                c(TexEnvi(TEXTURE_ENV, pname, (TEXTURE0 + 2) as i32)),
            ];
            steps.extend((0..4).map(|f| c(form(f, pname, value))));
            cases.push((format!("every glTexEnv(0x{pname:04X}, {name}) on unit 1"), steps));
        }
    }
    cases.push((
        "a GL_COMBINE chain: unit 1 reads GL_TEXTURE0, unit 3 GL_TEXTURE2 and GL_PREVIOUS".into(),
        vec![
            c(ActiveTexture(TEXTURE0 + 1)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32)),
            c(TexEnvi(TEXTURE_ENV, COMBINE_RGB, MODULATE as i32)),
            c(TexEnvi(TEXTURE_ENV, SRC0_RGB, TEXTURE0 as i32)),
            c(TexEnvi(TEXTURE_ENV, SRC0_RGB + 1, PREVIOUS as i32)),
            c(ActiveTexture(TEXTURE0 + 3)),
            c(TexEnvi(TEXTURE_ENV, TEXTURE_ENV_MODE, COMBINE as i32)),
            c(TexEnvi(TEXTURE_ENV, COMBINE_ALPHA, REPLACE as i32)),
            c(TexEnvf(TEXTURE_ENV, SRC0_ALPHA, (TEXTURE0 + 2) as f32)),
            c(TexEnviv(TEXTURE_ENV, SRC0_RGB + 2, vec![(TEXTURE0 + 2) as i32])),
            c(ActiveTexture(TEXTURE0 + 2)),
            q(Query::GetTexEnviv(TEXTURE_ENV, SRC0_RGB + 2, 1)),
        ],
    ));

    cases
        .into_iter()
        .map(|(name, mut steps)| {
            let last = steps.iter().any(|s| match s {
                Step::Call(c) | Step::Quiet(c) => names_last_unit(c),
                Step::Query(_) => false,
            });
            if last {
                steps.extend(readback(&[TEXTURE0, TEXTURE0 + 1, TEXTURE0 + 2, UNIT_LAST]));
            } else {
                steps.extend(readback(&UNITS));
            }
            (name, steps)
        })
        .collect()
}

/// Whether `call` names the last unit's sentinel (whose state each implementation keeps on its
/// own last unit).
fn names_last_unit(call: &Call) -> bool {
    match call {
        Call::ActiveTexture(t)
        | Call::MultiTexCoord4f(t, _)
        | Call::MultiTexCoord2f(t, _)
        | Call::MultiTexCoord4fv(t, _) => *t == UNIT_LAST,
        _ => false,
    }
}
