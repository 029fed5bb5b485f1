//! Texture coordinate generation's sequences of the differential test (GL 2.1 §2.11.4): each
//! mode on each coordinate through every form of glTexGen, valid and invalid; the object and
//! eye planes through every form; eye planes set under modelviews other than the identity
//! (stored as p · M⁻¹, which Mesa's answers check, and not moved by later modelviews); bad
//! coordinates and names; `GL_TEXTURE_GEN_S` .. `_Q` through glEnable. Each case is followed by
//! glGetTexGen{i,f,d}v of every name of every coordinate, and by every query of the four caps.

use super::{Call, Query, Step};

const S: u32 = 0x2000;
const T: u32 = 0x2001;
const R: u32 = 0x2002;
const Q: u32 = 0x2003;
const TEXTURE_GEN_MODE: u32 = 0x2500;
const OBJECT_PLANE: u32 = 0x2501;
const EYE_PLANE: u32 = 0x2502;
const EYE_LINEAR: u32 = 0x2400;
const OBJECT_LINEAR: u32 = 0x2401;
const SPHERE_MAP: u32 = 0x2402;
const NORMAL_MAP: u32 = 0x8511;
const REFLECTION_MAP: u32 = 0x8512;
const TEXTURE_GEN_S: u32 = 0x0C60;
const TEXTURE_GEN_T: u32 = 0x0C61;
const TEXTURE_GEN_R: u32 = 0x0C62;
const TEXTURE_GEN_Q: u32 = 0x0C63;
const TEXTURE_ENV_MODE: u32 = 0x2200;
const BOGUS: u32 = 0x1234;

const COORDS: [(u32, &str); 4] = [(S, "GL_S"), (T, "GL_T"), (R, "GL_R"), (Q, "GL_Q")];
const MODES: [(u32, &str); 5] = [
    (OBJECT_LINEAR, "GL_OBJECT_LINEAR"),
    (EYE_LINEAR, "GL_EYE_LINEAR"),
    (SPHERE_MAP, "GL_SPHERE_MAP"),
    (REFLECTION_MAP, "GL_REFLECTION_MAP"),
    (NORMAL_MAP, "GL_NORMAL_MAP"),
];
const CAPS: [u32; 4] = [TEXTURE_GEN_S, TEXTURE_GEN_T, TEXTURE_GEN_R, TEXTURE_GEN_Q];
const PLANES: [(u32, &str); 2] = [(OBJECT_PLANE, "GL_OBJECT_PLANE"), (EYE_PLANE, "GL_EYE_PLANE")];

/// Modelviews, column-major as glLoadMatrixf takes them, each invertible: a scale with a
/// translation, a quarter turn about z with a translation (both inverted exactly in floats),
/// a turn of 30° about (1, 2, 3) with an unequal scale and a translation, and one whose last
/// row is not (0, 0, 0, 1).
const MODELVIEWS: [(&str, [f32; 16]); 4] = [
    (
        "scale (2, 4, 0.5), translate (1, -3, 2)",
        [
            2.0, 0.0, 0.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 1.0, -3.0, 2.0, 1.0,
        ],
    ),
    (
        "a quarter turn about z, translate (0.5, 0.25, -4)",
        [
            0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.5, 0.25, -4.0, 1.0,
        ],
    ),
    (
        "30° about (1, 2, 3), scale (1.5, 0.75, 2), translate (0.3, -1.2, 2.5)",
        [
            1.313393, 0.630047, -0.357829, 0.0, -0.286314, 0.678228, 0.143286, 0.0, 0.59194, -0.152426,
            1.904304, 0.0, 0.3, -1.2, 2.5, 1.0,
        ],
    ),
    (
        "a projective modelview (last row (0, 0, -0.5, 1.5))",
        [
            1.0, 0.0, 0.0, 0.0, 0.5, 2.0, 0.0, 0.0, 0.0, 0.25, 1.0, -0.5, 0.0, 1.0, -2.0, 1.5,
        ],
    ),
];

fn identity() -> [f32; 16] {
    let mut m = [0.0; 16];
    for i in 0..4 {
        m[i * 5] = 1.0;
    }
    m
}

/// The call that sets `pname` of `coord` through `form` (0 i, 1 f, 2 d, 3 iv, 4 fv, 5 dv) with
/// the value `v` (the mode's enum, or a plane's first value for the scalar forms) or the
/// plane `p`.
fn form(form: usize, coord: u32, pname: u32, v: f64, p: [f64; 4]) -> Call {
    let values = if pname == TEXTURE_GEN_MODE {
        vec![v]
    } else {
        p.to_vec()
    };
    match form {
        0 => Call::TexGeni(coord, pname, v as i32),
        1 => Call::TexGenf(coord, pname, v as f32),
        2 => Call::TexGend(coord, pname, v),
        3 => Call::TexGeniv(coord, pname, values.iter().map(|&x| x as i32).collect()),
        4 => Call::TexGenfv(coord, pname, values.iter().map(|&x| x as f32).collect()),
        _ => Call::TexGendv(coord, pname, values),
    }
}

const FORMS: [&str; 6] = [
    "glTexGeni",
    "glTexGenf",
    "glTexGend",
    "glTexGeniv",
    "glTexGenfv",
    "glTexGendv",
];

/// Every glGetTexGen answer (each name of each coordinate through the three forms), and every
/// query of the four caps.
fn readback() -> Vec<Step> {
    use Query::*;
    let mut steps = Vec::new();
    for (coord, _) in COORDS {
        for (pname, n) in [(TEXTURE_GEN_MODE, 1), (OBJECT_PLANE, 4), (EYE_PLANE, 4)] {
            steps.push(Step::Query(GetTexGeniv(coord, pname, n)));
            steps.push(Step::Query(GetTexGenfv(coord, pname, n)));
            steps.push(Step::Query(GetTexGendv(coord, pname, n)));
        }
    }
    for cap in CAPS {
        steps.push(Step::Query(IsEnabled(cap)));
        steps.push(Step::Query(GetBooleanv(cap, 1)));
        steps.push(Step::Query(GetIntegerv(cap, 1)));
        steps.push(Step::Query(GetFloatv(cap, 1)));
    }
    steps
}

/// The sequences: each case's steps, then [`readback`].
pub(super) fn sequences() -> Vec<(String, Vec<Step>)> {
    use Call::*;
    let c = Step::Call;
    let q = Step::Query;
    let mut cases: Vec<(String, Vec<Step>)> =
        vec![("GL's initial texture coordinate generation".into(), vec![])];

    // Each mode on each coordinate through the six forms, the mode queried after each; a
    // different mode is set between them so that each form's effect shows. GL_SPHERE_MAP on
    // R or Q and GL_REFLECTION_MAP or GL_NORMAL_MAP on Q are GL_INVALID_ENUM.
    for (coord, coord_name) in COORDS {
        for (mode, mode_name) in MODES {
            let other = if mode == OBJECT_LINEAR {
                EYE_LINEAR
            } else {
                OBJECT_LINEAR
            };
            let mut steps = Vec::new();
            for f in 0..FORMS.len() {
                steps.push(c(form(f, coord, TEXTURE_GEN_MODE, f64::from(mode), [0.0; 4])));
                steps.push(q(Query::GetTexGeniv(coord, TEXTURE_GEN_MODE, 1)));
                steps.push(c(TexGeni(coord, TEXTURE_GEN_MODE, other as i32)));
            }
            steps.push(c(form(0, coord, TEXTURE_GEN_MODE, f64::from(mode), [0.0; 4])));
            cases.push((
                format!("every glTexGen({coord_name}, GL_TEXTURE_GEN_MODE, {mode_name})"),
                steps,
            ));
        }
    }
    // Values that are no mode, through every form; a float or double mode is truncated.
    for (value, name) in [
        (f64::from(BOGUS), "0x1234"),
        (0.0, "0"),
        (f64::from(TEXTURE_GEN_MODE), "GL_TEXTURE_GEN_MODE"),
        (f64::from(OBJECT_PLANE), "GL_OBJECT_PLANE"),
        (f64::from(TEXTURE_GEN_S), "GL_TEXTURE_GEN_S"),
        (-1.0, "-1"),
    ] {
        for (coord, coord_name) in [(S, "GL_S"), (Q, "GL_Q")] {
            let steps = (0..FORMS.len())
                .map(|f| c(form(f, coord, TEXTURE_GEN_MODE, value, [0.0; 4])))
                .collect();
            cases.push((
                format!("every glTexGen({coord_name}, GL_TEXTURE_GEN_MODE, {name})"),
                steps,
            ));
        }
    }
    cases.push((
        "glTexGenf, glTexGend and glTexGenfv truncate a mode given with a fraction".into(),
        vec![
            c(TexGenf(T, TEXTURE_GEN_MODE, OBJECT_LINEAR as f32 + 0.75)),
            c(TexGend(R, TEXTURE_GEN_MODE, f64::from(OBJECT_LINEAR) + 0.75)),
            c(TexGenfv(Q, TEXTURE_GEN_MODE, vec![OBJECT_LINEAR as f32 + 0.5])),
        ],
    ));
    cases.push((
        "a mode set twice, then one the coordinate does not take".into(),
        vec![
            c(TexGeni(R, TEXTURE_GEN_MODE, NORMAL_MAP as i32)),
            c(TexGeni(R, TEXTURE_GEN_MODE, NORMAL_MAP as i32)),
            c(TexGeni(R, TEXTURE_GEN_MODE, SPHERE_MAP as i32)),
        ],
    ));

    // The planes through every vector form, on each coordinate; ints convert to floats.
    let plane = [1.0, 2.0, -0.5, 3.0];
    for (coord, coord_name) in COORDS {
        for (pname, pname_name) in PLANES {
            for (f, name) in FORMS.iter().enumerate().skip(3) {
                let p = if f == 3 { [3.0, -2.0, 1.0, 5.0] } else { plane };
                cases.push((
                    format!("{name}({coord_name}, {pname_name})"),
                    vec![c(form(f, coord, pname, 0.0, p))],
                ));
            }
        }
    }
    cases.push((
        "glTexGeniv planes of large integers, glTexGendv planes of fractions".into(),
        vec![
            c(TexGeniv(
                S,
                OBJECT_PLANE,
                vec![1 << 30, -(1 << 29), 123_456_789, -7],
            )),
            c(TexGeniv(
                T,
                EYE_PLANE,
                vec![-(1 << 30), 1 << 24, (1 << 24) + 1, 0],
            )),
            c(TexGendv(R, OBJECT_PLANE, vec![0.1, 0.2, 0.3, 0.4])),
            c(TexGendv(Q, EYE_PLANE, vec![-0.75, 0.25, 1e-3, 2.5])),
        ],
    ));
    // The scalar forms take the mode alone: a plane there is GL_INVALID_ENUM (§2.11.4).
    for (pname, pname_name) in PLANES {
        for (f, name) in FORMS.iter().enumerate().take(3) {
            cases.push((
                format!("{name}(GL_T, {pname_name}, 2) (a plane has four values)"),
                vec![c(form(f, T, pname, 2.0, [0.0; 4]))],
            ));
        }
    }

    // Eye planes under modelviews: stored as p · M⁻¹ at the call, kept when the modelview
    // changes; object planes are not transformed.
    for (name, m) in MODELVIEWS {
        let steps = vec![
            c(LoadModelview(m)),
            c(TexGenfv(S, EYE_PLANE, vec![1.0, 2.0, -0.5, 3.0])),
            c(TexGendv(T, EYE_PLANE, vec![0.25, -1.0, 2.0, -4.5])),
            c(TexGeniv(R, EYE_PLANE, vec![3, -2, 1, 5])),
            c(TexGenfv(Q, EYE_PLANE, vec![0.1, 0.2, 0.3, 0.4])),
            c(TexGenfv(Q, OBJECT_PLANE, vec![0.1, 0.2, 0.3, 0.4])),
            q(Query::GetTexGenfv(S, EYE_PLANE, 4)),
            q(Query::GetTexGendv(T, EYE_PLANE, 4)),
            c(LoadModelview(identity())),
        ];
        cases.push((format!("eye planes set under {name}"), steps));
    }
    cases.push((
        "an eye plane set again under a second modelview, the first left in place".into(),
        vec![
            c(LoadModelview(MODELVIEWS[0].1)),
            c(TexGenfv(S, EYE_PLANE, vec![1.0, 2.0, -0.5, 3.0])),
            c(TexGenfv(T, EYE_PLANE, vec![1.0, 2.0, -0.5, 3.0])),
            c(LoadModelview(MODELVIEWS[2].1)),
            c(TexGenfv(T, EYE_PLANE, vec![1.0, 2.0, -0.5, 3.0])),
        ],
    ));

    // Bad coordinates and names, through every entry point and query.
    for coord in [BOGUS, 0, S - 1, Q + 1, TEXTURE_GEN_S] {
        let mut steps: Vec<Step> = (0..FORMS.len())
            .map(|f| {
                c(form(
                    f,
                    coord,
                    TEXTURE_GEN_MODE,
                    f64::from(OBJECT_LINEAR),
                    [0.0; 4],
                ))
            })
            .collect();
        steps.push(c(TexGenfv(coord, EYE_PLANE, vec![1.0; 4])));
        for (pname, n) in [(TEXTURE_GEN_MODE, 1), (OBJECT_PLANE, 4), (EYE_PLANE, 4)] {
            steps.push(q(Query::GetTexGeniv(coord, pname, n)));
            steps.push(q(Query::GetTexGenfv(coord, pname, n)));
            steps.push(q(Query::GetTexGendv(coord, pname, n)));
        }
        cases.push((
            format!("glTexGen and glGetTexGen of coordinate 0x{coord:04X}"),
            steps,
        ));
    }
    for pname in [BOGUS, 0, TEXTURE_GEN_S, TEXTURE_ENV_MODE, EYE_PLANE + 1] {
        let mut steps: Vec<Step> = (0..FORMS.len())
            .map(|f| c(form(f, S, pname, f64::from(OBJECT_LINEAR), [1.0; 4])))
            .collect();
        for coord in [S, Q] {
            steps.push(q(Query::GetTexGeniv(coord, pname, 4)));
            steps.push(q(Query::GetTexGenfv(coord, pname, 4)));
            steps.push(q(Query::GetTexGendv(coord, pname, 4)));
        }
        cases.push((format!("glTexGen and glGetTexGen of pname 0x{pname:04X}"), steps));
    }

    // GL_TEXTURE_GEN_S .. _Q.
    for cap in CAPS {
        cases.push((
            format!("glEnable(0x{cap:04X})"),
            vec![q(Query::IsEnabled(cap)), c(Enable(cap))],
        ));
        cases.push((
            format!("glEnable(0x{cap:04X}), glDisable"),
            vec![c(Enable(cap)), q(Query::IsEnabled(cap)), c(Disable(cap))],
        ));
    }
    cases.push((
        "every GL_TEXTURE_GEN_* enabled, each coordinate generated its own way".into(),
        vec![
            c(Enable(TEXTURE_GEN_S)),
            c(Enable(TEXTURE_GEN_T)),
            c(Enable(TEXTURE_GEN_R)),
            c(Enable(TEXTURE_GEN_Q)),
            c(TexGeni(S, TEXTURE_GEN_MODE, SPHERE_MAP as i32)),
            c(TexGeni(T, TEXTURE_GEN_MODE, SPHERE_MAP as i32)),
            c(TexGeni(R, TEXTURE_GEN_MODE, REFLECTION_MAP as i32)),
            c(TexGeni(Q, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32)),
            c(Disable(TEXTURE_GEN_T)),
        ],
    ));
    cases.push((
        "the first glTexGen error sticks until glGetError reads it".into(),
        vec![
            Step::Quiet(TexGeni(R, TEXTURE_GEN_MODE, SPHERE_MAP as i32)),
            Step::Quiet(TexGeni(BOGUS, TEXTURE_GEN_MODE, OBJECT_LINEAR as i32)),
            Step::Quiet(TexGenfv(S, OBJECT_PLANE, vec![1.0, 1.0, 1.0, 1.0])),
            q(Query::IsEnabled(TEXTURE_GEN_S)),
            q(Query::IsEnabled(TEXTURE_GEN_S)),
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
