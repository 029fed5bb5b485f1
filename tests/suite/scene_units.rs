//! Several texture units in scene files (a mesh's `texture_units`, `GL_TEXTURE0` first) and
//! `GL_COMBINE` (a unit's `combine`): GL's names and defaults, each unit's coordinates (the
//! mesh's or its current ones), a bad value refused naming the file, the field, the value and
//! what was expected; and scenes of two units, and of a `GL_COMBINE` unit reading
//! `GL_TEXTURE0` through the crossbar, drawn by ffvk as Mesa's GL draws them.

use std::path::PathBuf;

use ffvk::gl::state::LightingMode;
use ffvk::gl::texture::{
    AlphaOperand, Combine, CombineFunc, CombineSource, RgbOperand, TexEnvMode, TexGenMode, TextureUnit,
};
use ffvk::scene::{render_scene, Scene, TexCoords};
use glam::{Mat4, Vec3, Vec4};

use crate::stage_scenes::{differing, gl_image};
use crate::support::*;

/// The scene of `text`, named `name` (parsed, not read: nothing is written).
fn parse(name: &str, text: &str) -> Result<Scene, ffvk::scene::SceneError> {
    Scene::parse(text, &scene_path(name))
}

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(format!("scene_units/{name}.toml"))
}

/// A sphere whose table ends with `fields`.
fn sphere(fields: &str) -> String {
    format!("[[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\n{fields}\n")
}

/// The one sphere of a scene whose table ends with `fields`.
fn mesh(fields: &str) -> ffvk::scene::SceneMesh {
    parse("ok", &sphere(fields)).unwrap().meshes.remove(0)
}

/// The `GL_COMBINE` state of unit 1 of a sphere whose unit 1 has `combine` (unit 0 the checker).
fn combine(combine: &str) -> Combine {
    let m = mesh(&format!(
        "texture_units = [{{ builtin = \"checker\" }}, {{ builtin = \"lightmap\", env = \"combine\", combine = {combine} }}]"
    ));
    let unit = m.textures[1].as_ref().expect("unit 1").unit;
    assert_eq!(unit.env_mode, TexEnvMode::Combine);
    unit.combine
}

/// The message of the error the scene `text` fails with; it names the file first.
fn refused(name: &str, text: &str) -> String {
    let path = scene_path(name);
    let message = parse(name, text).expect_err("the scene is refused").to_string();
    assert!(
        message.starts_with(&path.display().to_string()),
        "{message:?} names the file first"
    );
    message
}

/// [`refused`] for a sphere of two units, the second with `combine`.
fn refused_combine(name: &str, combine: &str) -> String {
    refused(
        name,
        &sphere(&format!(
            "texture_units = [{{ builtin = \"checker\" }}, {{ builtin = \"lightmap\", env = \"combine\", combine = {combine} }}]"
        )),
    )
}

fn contains_all(message: &str, parts: &[&str]) {
    for p in parts {
        assert!(message.contains(p), "{message:?} should mention {p:?}");
    }
}

#[test]
fn a_meshs_texture_units_are_gl_texture0_onwards_with_gls_defaults() {
    let m = mesh(
        "[[meshes.texture_units]]\nbuiltin = \"checker\"\n[[meshes.texture_units]]\nbuiltin = \"lightmap\"\n",
    );
    let (zero, one) = (m.textures[0].as_ref().unwrap(), m.textures[1].as_ref().unwrap());
    assert!(m.textures[2].is_none() && m.textures[3].is_none());
    assert_eq!(zero.source, "builtin checker");
    assert_eq!(one.source, "builtin lightmap");
    assert_eq!(m.texture().map(|t| &t.source), Some(&zero.source));
    // Each unit's glTexEnv, texture matrix and glTexGen are GL's initial ones, enabled.
    for t in [zero, one] {
        let mut expected = TextureUnit::default();
        expected.enabled = true;
        assert_eq!(t.unit, expected);
    }
    // Unit 0 reads the mesh's coordinates; unit 1 its current ones, GL's (0, 0, 0, 1).
    assert_eq!(
        (zero.coords, one.coords),
        (TexCoords::Mesh, TexCoords::Current(Vec4::W))
    );
    assert_eq!(m.mesh_texcoords(), 0);
    // The draw's state holds both units; the others stay off.
    let scene = parse(
        "ok",
        &sphere("texture_units = [{ builtin = \"checker\" }, { builtin = \"lightmap\" }]"),
    )
    .unwrap();
    let state = scene.draw_state(&scene.meshes[0]);
    assert!(state.texture_units[0].enabled && state.texture_units[1].enabled);
    assert!(!state.texture_units[2].enabled && !state.texture_units[3].enabled);
    assert_eq!(state.current_texcoords, [Vec4::W; 4]);
    // Four units, the most GL_MAX_TEXTURE_UNITS allows; one disabled is no unit.
    let m = mesh(
        "texture_units = [{ builtin = \"checker\" }, { builtin = \"disc\", enabled = false }, { builtin = \"leaves\" }, { builtin = \"lightmap\" }]",
    );
    let sources: Vec<Option<&str>> = m
        .textures
        .iter()
        .map(|t| t.as_ref().map(|t| t.source.as_str()))
        .collect();
    assert_eq!(
        sources,
        [
            Some("builtin checker"),
            None,
            Some("builtin leaves"),
            Some("builtin lightmap")
        ]
    );
}

#[test]
fn units_1_to_3_take_the_meshs_coordinates_or_their_current_ones() {
    let text = sphere(
        "texture_units = [{ builtin = \"checker\" }, { builtin = \"lightmap\", coords = \"mesh\" }, \
         { builtin = \"disc\", coords = [0.25, 0.5, 0, 2] }, { builtin = \"leaves\", coords = \"mesh\" }]",
    );
    let scene = parse("coords", &text).unwrap();
    let m = &scene.meshes[0];
    let coords: Vec<TexCoords> = m.textures.iter().map(|t| t.as_ref().unwrap().coords).collect();
    assert_eq!(
        coords,
        [
            TexCoords::Mesh,
            TexCoords::Mesh,
            TexCoords::Current(Vec4::new(0.25, 0.5, 0.0, 2.0)),
            TexCoords::Mesh
        ]
    );
    // Units 1 and 3 read the mesh's coordinates (Draw::mesh_texcoords' bits); unit 2's current
    // coordinates are glMultiTexCoord4f's.
    assert_eq!(m.mesh_texcoords(), 0b1010);
    let state = scene.draw_state(m);
    assert_eq!(state.current_texcoords[2], Vec4::new(0.25, 0.5, 0.0, 2.0));
    assert_eq!(
        [
            state.current_texcoords[0],
            state.current_texcoords[1],
            state.current_texcoords[3]
        ],
        [Vec4::W; 3]
    );
}

/// `texture` stays the one-unit form (unit 0); the scene's `[texture]` serves every mesh
/// without its own, and a mesh's `texture_units` are its own.
#[test]
fn the_one_unit_form_is_unit_0_and_the_scenes_texture_serves_meshes_without_their_own() {
    let text = "[texture]\nbuiltin = \"leaves\"\n\
                [[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\n\
                [[meshes]]\nbuiltin = \"plane\"\ntexture = { builtin = \"checker\", env = \"decal\" }\n\
                [[meshes]]\nbuiltin = \"plane\"\ntexture_units = [{ builtin = \"disc\" }, { builtin = \"lightmap\", coords = \"mesh\" }]\n";
    let scene = parse("precedence", text).unwrap();
    let sources = |i: usize| -> Vec<Option<String>> {
        scene.meshes[i]
            .textures
            .iter()
            .map(|t| t.as_ref().map(|t| t.source.clone()))
            .collect()
    };
    let some = |s: &str| Some(s.to_owned());
    assert_eq!(sources(0), [some("builtin leaves"), None, None, None]);
    assert_eq!(sources(1), [some("builtin checker"), None, None, None]);
    assert_eq!(
        scene.meshes[1].texture().unwrap().unit.env_mode,
        TexEnvMode::Decal
    );
    assert_eq!(
        sources(2),
        [some("builtin disc"), some("builtin lightmap"), None, None]
    );
    assert_eq!(scene.meshes[2].mesh_texcoords(), 0b10);
}

#[test]
fn each_unit_has_its_own_environment_texgen_and_texture_matrix() {
    let m = mesh(
        "[[meshes.texture_units]]\nbuiltin = \"checker\"\nenv = \"decal\"\nscale = [4.0, 2.0]\n\
         [[meshes.texture_units]]\nbuiltin = \"lightmap\"\nenv = \"blend\"\nenv_color = [0.5, 0.25, 1.0, 1.0]\n\
         texgen = { s = { mode = \"object_linear\", plane = [0.5, 0, 0, 0.5] }, t = { mode = \"sphere_map\" } }\n\
         matrix = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.25, 0.5, 0, 1]\n",
    );
    let (zero, one) = (
        m.textures[0].as_ref().unwrap().unit,
        m.textures[1].as_ref().unwrap().unit,
    );
    assert_eq!(zero.env_mode, TexEnvMode::Decal);
    assert_eq!(zero.matrix, Mat4::from_scale(Vec3::new(4.0, 2.0, 1.0)));
    assert_eq!(zero.texgen, TextureUnit::default().texgen);
    assert_eq!(one.env_mode, TexEnvMode::Blend);
    assert_eq!(one.env_color, Vec4::new(0.5, 0.25, 1.0, 1.0));
    assert_eq!(one.matrix, Mat4::from_translation(Vec3::new(0.25, 0.5, 0.0)));
    assert!(one.texgen[0].enabled && one.texgen[0].mode == TexGenMode::ObjectLinear);
    assert_eq!(one.texgen[0].object_plane, Vec4::new(0.5, 0.0, 0.0, 0.5));
    assert!(one.texgen[1].enabled && one.texgen[1].mode == TexGenMode::SphereMap);
    assert!(!one.texgen[2].enabled && !one.texgen[3].enabled);
}

/// `env = "combine"` without a table is GL's initial GL_COMBINE state (table 6.19); each field
/// left out keeps its default, and a list shorter than three keeps the later arguments'.
#[test]
fn combine_takes_gls_names_with_table_6_19s_defaults() {
    let gl = Combine::default();
    assert_eq!(combine("{}"), gl);
    let m = mesh("texture = { builtin = \"checker\", env = \"combine\" }");
    let unit = m.texture().unwrap().unit;
    assert_eq!((unit.env_mode, unit.combine), (TexEnvMode::Combine, gl));
    assert_eq!((gl.rgb, gl.alpha), (CombineFunc::Modulate, CombineFunc::Modulate));
    use CombineSource::*;
    assert_eq!(gl.rgb_sources, [Texture, Previous, Constant]);
    assert_eq!(gl.alpha_sources, [Texture, Previous, Constant]);
    assert_eq!(
        gl.rgb_operands,
        [RgbOperand::SrcColor, RgbOperand::SrcColor, RgbOperand::SrcAlpha]
    );
    assert_eq!(gl.alpha_operands, [AlphaOperand::SrcAlpha; 3]);
    assert_eq!((gl.rgb_scale, gl.alpha_scale), (1.0, 1.0));

    let c = combine(
        "{ rgb = \"interpolate\", alpha = \"add_signed\", rgb_sources = [\"texture0\", \"primary_color\"], \
         alpha_sources = [\"constant\"], rgb_operands = [\"one_minus_src_alpha\"], \
         alpha_operands = [\"src_alpha\", \"one_minus_src_alpha\"], rgb_scale = 2, alpha_scale = 4.0 }",
    );
    assert_eq!(
        (c.rgb, c.alpha),
        (CombineFunc::Interpolate, CombineFunc::AddSigned)
    );
    assert_eq!(c.rgb_sources, [TextureUnit(0), PrimaryColor, Constant]);
    assert_eq!(c.alpha_sources, [Constant, Previous, Constant]);
    assert_eq!(
        c.rgb_operands,
        [
            RgbOperand::OneMinusSrcAlpha,
            RgbOperand::SrcColor,
            RgbOperand::SrcAlpha
        ]
    );
    assert_eq!(
        c.alpha_operands,
        [
            AlphaOperand::SrcAlpha,
            AlphaOperand::OneMinusSrcAlpha,
            AlphaOperand::SrcAlpha
        ]
    );
    assert_eq!((c.rgb_scale, c.alpha_scale), (2.0, 4.0));
}

/// Every function, source and operand by GL's name in lowercase without `GL_`, as `env` and
/// the texgen modes are spelled.
#[test]
fn every_combine_function_source_and_operand_parses_by_gls_name() {
    let functions = [
        ("replace", CombineFunc::Replace),
        ("modulate", CombineFunc::Modulate),
        ("add", CombineFunc::Add),
        ("add_signed", CombineFunc::AddSigned),
        ("interpolate", CombineFunc::Interpolate),
        ("subtract", CombineFunc::Subtract),
        ("dot3_rgb", CombineFunc::Dot3Rgb),
        ("dot3_rgba", CombineFunc::Dot3Rgba),
    ];
    for (word, f) in functions {
        assert_eq!(combine(&format!("{{ rgb = \"{word}\" }}")).rgb, f, "{word}");
        if f.is_alpha_function() {
            assert_eq!(combine(&format!("{{ alpha = \"{word}\" }}")).alpha, f, "{word}");
        }
    }
    // The unit sources up to the mesh's last unit (the sphere has two).
    let sources = [
        ("texture", CombineSource::Texture),
        ("constant", CombineSource::Constant),
        ("primary_color", CombineSource::PrimaryColor),
        ("previous", CombineSource::Previous),
        ("texture0", CombineSource::TextureUnit(0)),
        ("texture1", CombineSource::TextureUnit(1)),
    ];
    for (word, s) in sources {
        let list = format!("[\"previous\", \"previous\", \"{word}\"]");
        let c = combine(&format!("{{ rgb_sources = {list}, alpha_sources = {list} }}"));
        assert_eq!((c.rgb_sources[2], c.alpha_sources[2]), (s, s), "{word}");
    }
    let rgb = [
        ("src_color", RgbOperand::SrcColor),
        ("one_minus_src_color", RgbOperand::OneMinusSrcColor),
        ("src_alpha", RgbOperand::SrcAlpha),
        ("one_minus_src_alpha", RgbOperand::OneMinusSrcAlpha),
    ];
    for (word, o) in rgb {
        let c = combine(&format!(
            "{{ rgb_operands = [\"{word}\", \"{word}\", \"{word}\"] }}"
        ));
        assert_eq!(c.rgb_operands, [o; 3], "{word}");
    }
    for (word, o) in [
        ("src_alpha", AlphaOperand::SrcAlpha),
        ("one_minus_src_alpha", AlphaOperand::OneMinusSrcAlpha),
    ] {
        let c = combine(&format!(
            "{{ alpha_operands = [\"{word}\", \"{word}\", \"{word}\"] }}"
        ));
        assert_eq!(c.alpha_operands, [o; 3], "{word}");
    }
    // "texture3" on a mesh of four units.
    let m = mesh(
        "texture_units = [{ builtin = \"checker\" }, { builtin = \"disc\" }, { builtin = \"leaves\" }, \
         { builtin = \"lightmap\", env = \"combine\", combine = { rgb_sources = [\"texture3\", \"texture2\"] } }]",
    );
    let c = m.textures[3].as_ref().unwrap().unit.combine;
    assert_eq!(
        c.rgb_sources[..2],
        [CombineSource::TextureUnit(3), CombineSource::TextureUnit(2)]
    );
}

#[test]
fn bad_texture_units_are_refused_naming_the_file_the_field_the_value_and_what_was_expected() {
    // Both forms: one would be ignored.
    let m = refused(
        "both",
        &sphere("texture = { builtin = \"checker\" }\ntexture_units = [{ builtin = \"lightmap\" }]"),
    );
    contains_all(
        &m,
        &[
            "meshes[0].texture_units",
            "meshes[0].texture:",
            "either texture (unit 0 alone) or texture_units",
        ],
    );
    let m = refused("none", &sphere("texture_units = []"));
    contains_all(&m, &["meshes[0].texture_units", "0 units", "expected 1 to 4"]);
    let five = ["{ builtin = \"checker\" }"; 5].join(", ");
    let m = refused("five", &sphere(&format!("texture_units = [{five}]")));
    contains_all(
        &m,
        &[
            "meshes[0].texture_units",
            "5 units",
            "expected 1 to 4",
            "GL_MAX_TEXTURE_UNITS",
        ],
    );
    // Unit 0 always takes the mesh's coordinates: coords there is refused, in every form.
    for (name, text, field) in [
        (
            "coords_0",
            sphere("texture_units = [{ builtin = \"checker\", coords = \"mesh\" }]"),
            "meshes[0].texture_units[0].coords",
        ),
        (
            "coords_texture",
            sphere("texture = { builtin = \"checker\", coords = [0, 0, 0, 1] }"),
            "meshes[0].texture.coords",
        ),
        (
            "coords_scene",
            format!(
                "[texture]\nbuiltin = \"checker\"\ncoords = \"mesh\"\n{}",
                sphere("")
            ),
            "texture.coords",
        ),
    ] {
        let m = refused(name, &text);
        contains_all(&m, &[field, "unit 0", "units 1 to 3 only"]);
    }
    let unit1 = |coords: &str| {
        sphere(&format!(
            "texture_units = [{{ builtin = \"checker\" }}, {{ builtin = \"lightmap\", coords = {coords} }}]"
        ))
    };
    let m = refused("coords_word", &unit1("\"vertex\""));
    contains_all(
        &m,
        &[
            "meshes[0].texture_units[1].coords",
            "\"vertex\"",
            "expected \"mesh\"",
            "4 numbers",
        ],
    );
    let m = refused("coords_three", &unit1("[0.5, 0.5, 0]"));
    contains_all(
        &m,
        &[
            "meshes[0].texture_units[1].coords",
            "3 numbers",
            "4 numbers (s, t, r, q, as glMultiTexCoord4f)",
        ],
    );
    let m = refused("coords_nan", &unit1("[0.5, nan, 0, 1]"));
    contains_all(&m, &["meshes[0].texture_units[1].coords", "NaN", "finite"]);
    // Finite as given, past a float's range as GL keeps it.
    let m = refused("coords_huge", &unit1("[0.5, 1e300, 0, 1]"));
    contains_all(&m, &["meshes[0].texture_units[1].coords", "inf", "finite"]);
    for (name, value) in [("coords_bool", "true"), ("coords_mixed", "[0.5, \"t\", 0, 1]")] {
        let m = refused(name, &unit1(value));
        contains_all(
            &m,
            &[
                &format!("meshes[0].texture_units[1].coords: {value}: expected \"mesh\""),
                "4 numbers",
            ],
        );
    }
    // A unit is checked as a texture table is, under its own path.
    let m = refused(
        "unit_env",
        &sphere(
            "texture_units = [{ builtin = \"checker\" }, { builtin = \"lightmap\", env = \"multiply\" }]",
        ),
    );
    contains_all(
        &m,
        &[
            "meshes[0].texture_units[1].env",
            "\"multiply\"",
            "\"modulate\", \"replace\", \"decal\", \"blend\", \"add\", \"combine\"",
        ],
    );
    let m = refused(
        "unit_texgen",
        &sphere("texture_units = [{ builtin = \"checker\" }, { builtin = \"lightmap\", texgen = { q = { mode = \"sphere_map\" } } }]"),
    );
    contains_all(&m, &["meshes[0].texture_units[1].texgen.q.mode", "GL_SPHERE_MAP"]);
    let m = refused(
        "unit_image",
        &sphere("texture_units = [{ builtin = \"checker\" }, { min_filter = \"linear\" }]"),
    );
    contains_all(&m, &["meshes[0].texture_units[1]:", "no image", "\"lightmap\""]);
    let m = refused(
        "unit_field",
        &sphere("texture_units = [{ builtin = \"checker\", coord = \"mesh\" }]"),
    );
    contains_all(&m, &["unknown field", "coord"]);
}

#[test]
fn bad_combine_values_are_refused_naming_the_file_the_field_the_value_and_what_was_expected() {
    let field = "meshes[0].texture_units[1].combine";
    // A combine table another environment would never read.
    let m = refused(
        "unread",
        &sphere("texture_units = [{ builtin = \"checker\" }, { builtin = \"lightmap\", env = \"modulate\", combine = { rgb = \"add\" } }]"),
    );
    contains_all(
        &m,
        &[
            &format!("{field}:"),
            "env \"modulate\"",
            "expected env = \"combine\"",
        ],
    );
    // The dot products are RGB functions (GL_INVALID_ENUM for GL_COMBINE_ALPHA).
    for (word, gl) in [("dot3_rgb", "GL_DOT3_RGB"), ("dot3_rgba", "GL_DOT3_RGBA")] {
        let m = refused_combine("dot3_alpha", &format!("{{ alpha = \"{word}\" }}"));
        contains_all(
            &m,
            &[
                &format!("{field}.alpha:"),
                &format!("\"{word}\" for alpha"),
                "\"replace\", \"modulate\", \"add\", \"add_signed\", \"interpolate\", \"subtract\"",
                gl,
                "GL_INVALID_ENUM",
            ],
        );
    }
    for (scale, value) in [
        ("rgb_scale = 3", "3"),
        ("rgb_scale = 0.5", "0.5"),
        ("alpha_scale = 8", "8"),
    ] {
        let name = scale.split(' ').next().unwrap();
        let m = refused_combine("scale", &format!("{{ {scale} }}"));
        let gl = if name == "rgb_scale" {
            "GL_RGB_SCALE"
        } else {
            "GL_ALPHA_SCALE"
        };
        contains_all(
            &m,
            &[&format!("{field}.{name}: {value}:"), "expected 1, 2 or 4", gl],
        );
    }
    // A GL_TEXTUREn source past the mesh's last unit: the two-unit sphere has no unit 2, the
    // one-unit form no unit 1; "texture4" is none of GL's.
    let m = refused_combine("past", "{ rgb_sources = [\"texture\", \"texture2\"] }");
    contains_all(
        &m,
        &[
            &format!("{field}.rgb_sources[1]:"),
            "\"texture2\" reads unit 2, past the mesh's last texture unit (1)",
            "\"previous\", \"texture0\", \"texture1\"",
        ],
    );
    let m = refused_combine(
        "past_alpha",
        "{ alpha_sources = [\"texture\", \"previous\", \"texture3\"] }",
    );
    contains_all(
        &m,
        &[&format!("{field}.alpha_sources[2]:"), "\"texture3\" reads unit 3"],
    );
    let m = refused(
        "past_one",
        &sphere("texture = { builtin = \"checker\", env = \"combine\", combine = { rgb_sources = [\"texture1\"] } }"),
    );
    contains_all(
        &m,
        &[
            "meshes[0].texture.combine.rgb_sources[0]:",
            "\"texture1\" reads unit 1, past the mesh's last texture unit (0)",
        ],
    );
    let m = refused_combine("texture4", "{ rgb_sources = [\"texture4\"] }");
    contains_all(
        &m,
        &[
            &format!("{field}.rgb_sources[0]:"),
            "\"texture4\": expected one of \"texture\", \"constant\", \"primary_color\", \"previous\", \"texture0\", \"texture1\"",
        ],
    );
    // Unknown names, each by its field and index.
    for (combine, at, value, expected) in [
        ("{ rgb = \"multiply\" }", "rgb", "\"multiply\"", "\"dot3_rgba\""),
        ("{ alpha = \"GL_ADD\" }", "alpha", "\"GL_ADD\"", "\"add\""),
        (
            "{ rgb_sources = [\"texture\", \"primary\"] }",
            "rgb_sources[1]",
            "\"primary\"",
            "\"primary_color\"",
        ),
        (
            "{ rgb_operands = [\"src_color\", \"src_colour\"] }",
            "rgb_operands[1]",
            "\"src_colour\"",
            "\"one_minus_src_color\"",
        ),
        (
            "{ alpha_operands = [\"alpha\"] }",
            "alpha_operands[0]",
            "\"alpha\"",
            "\"src_alpha\", \"one_minus_src_alpha\"",
        ),
    ] {
        let m = refused_combine("name", combine);
        contains_all(
            &m,
            &[&format!("{field}.{at}: {value}: expected one of"), expected],
        );
    }
    // An alpha argument takes a source's alpha (GL_INVALID_ENUM for a color operand).
    let m = refused_combine(
        "alpha_color",
        "{ alpha_operands = [\"src_alpha\", \"one_minus_src_color\"] }",
    );
    contains_all(
        &m,
        &[
            &format!("{field}.alpha_operands[1]:"),
            "\"one_minus_src_color\" for alpha",
            "\"src_alpha\", \"one_minus_src_alpha\"",
            "GL_INVALID_ENUM",
        ],
    );
    let m = refused_combine(
        "four",
        "{ rgb_operands = [\"src_color\", \"src_color\", \"src_color\", \"src_color\"] }",
    );
    contains_all(
        &m,
        &[
            &format!("{field}.rgb_operands:"),
            "4 entries",
            "at most 3",
            "GL_OPERAND0_RGB to GL_OPERAND2_RGB",
        ],
    );
    let m = refused_combine("field", "{ rgb_source = [\"texture\"] }");
    contains_all(&m, &["unknown field", "rgb_source"]);
    let m = refused_combine("type", "{ rgb_scale = \"2\" }");
    contains_all(&m, &["rgb_scale"]);
}

/// The files a scene reads list each unit's image, as they list a `texture`'s.
#[test]
fn the_scenes_inputs_list_every_units_image() {
    let dir = output_dir().join("scene_units");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("inputs.toml");
    std::fs::write(
        &path,
        sphere(
            "texture_units = [{ image = \"base.png\" }, { builtin = \"lightmap\" }, { image = \"light.png\", coords = \"mesh\" }]",
        ),
    )
    .unwrap();
    let files = ffvk::scene::inputs(&path, &Default::default());
    assert_eq!(files, [path.clone(), dir.join("base.png"), dir.join("light.png")]);
}

/// Scene text for the comparisons below: a lit sphere and a floor at 128², the camera a little
/// above, each mesh's table ending with its `sphere` or `floor` fields.
pub(crate) fn lit(sphere: &str, floor: &str) -> String {
    format!(
        "[image]\nsize = [128, 128]\nclear_color = [0.1, 0.1, 0.12]\n\
         [camera]\neye = [0.0, 1.2, 3.2]\ntarget = [0.0, -0.1, 0.0]\nfovy = 45\n\
         [light_model]\nambient = [0.3, 0.3, 0.3]\n\
         [[lights]]\nposition = [1.0, 2.0, 1.5, 0.0]\n\
         [material]\npreset = \"white_plastic\"\nambient = [0.8, 0.8, 0.8]\n\
         [[meshes]]\nbuiltin = \"sphere\"\nlevel = 24\nscale = [0.7, 0.7, 0.7]\n{sphere}\n\
         [[meshes]]\nbuiltin = \"plane\"\nlevel = 8\ntranslate = [0.0, -0.7, 0.0]\nrotate = [-90.0, 0.0, 0.0]\nscale = [2.0, 2.0, 1.0]\n{floor}\n"
    )
}

/// `text` drawn by ffvk and by Mesa's GL in the vertex and flat modes (GL has no per-fragment
/// lighting), held to the stage scenes' tolerance: at most 1.5 % of the pixels beyond 2/255.
/// Returns ffvk's vertex-mode image.
pub(crate) fn draws_as_mesa_does(name: &str, text: &str) -> image::RgbaImage {
    let scene = parse(name, text).unwrap();
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    let mut r = renderer();
    let mut failures = Vec::new();
    let mut vertex = None;
    for mode in [LightingMode::Vertex, LightingMode::Flat] {
        let ours = render_scene(&mut r, &scene, Some(mode)).unwrap();
        let theirs = gl_image(&scene, mode);
        let (n, worst) = differing(&ours, &theirs, 2);
        let share = n as f64 / (ours.width() * ours.height()) as f64;
        let what = format!("scene_units_{name}_{}", mode.name());
        let a = save_for_inspection(&ours, &format!("{what}_ffvk"));
        save_for_inspection(&theirs, &format!("{what}_gl"));
        println!(
            "{what}: {n} pixels ({:.2} %) beyond 2/255 (worst {worst})",
            share * 100.0
        );
        if share > 0.015 {
            failures.push(format!(
                "{what}: {:.2} % of pixels differ from Mesa's GL by more than 2/255 (worst {worst}); images beside {}",
                share * 100.0,
                a.display()
            ));
        }
        vertex.get_or_insert(ours);
    }
    finish(r);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    vertex.unwrap()
}

/// The share of pixels of `a` and `b` (ffvk's images of two scenes) more than 8/255 apart.
pub(crate) fn changed_share(a: &image::RgbaImage, b: &image::RgbaImage) -> f64 {
    differing(a, b, 8).0 as f64 / (a.width() * a.height()) as f64
}

/// ffvk's vertex-mode image of `text`.
pub(crate) fn ffvk_image(name: &str, text: &str) -> image::RgbaImage {
    let scene = parse(name, text).unwrap();
    let mut r = renderer();
    let image = render_scene(&mut r, &scene, Some(LightingMode::Vertex)).unwrap();
    finish(r);
    image
}

/// A checker on unit 0 and the light map GL_MODULATEd on unit 1: on the sphere from the mesh's
/// coordinates through unit 1's own texture matrix, on the floor from unit 1's current
/// coordinates (glMultiTexCoord4f: one texel of the warm pool everywhere).
#[test]
fn a_scene_with_two_units_draws_as_mesas_gl_draws_it() {
    let base = "{ builtin = \"checker\", min_filter = \"linear\", scale = [2.0, 2.0] }";
    let text = lit(
        &format!(
            "texture_units = [{base}, {{ builtin = \"lightmap\", min_filter = \"linear\", coords = \"mesh\", rotate = 30.0 }}]"
        ),
        &format!(
            "texture_units = [{base}, {{ builtin = \"lightmap\", min_filter = \"nearest\", coords = [0.3, 0.35, 0.0, 1.0] }}]"
        ),
    );
    let two = draws_as_mesa_does("two_units", &text);
    // Unit 1 is drawn: without it a good part of the image changes.
    let one = ffvk_image(
        "one_unit",
        &lit(&format!("texture = {base}"), &format!("texture = {base}")),
    );
    let share = changed_share(&two, &one);
    println!(
        "unit 1 changes {:.1} % of the pixels by more than 8/255",
        share * 100.0
    );
    assert!(
        share > 0.2,
        "unit 1 changes only {:.1} % of the pixels",
        share * 100.0
    );
}

/// Unit 0 the light map GL_MODULATEd with the lit color; unit 1 GL_COMBINE's GL_INTERPOLATE of
/// GL_TEXTURE0 (unit 0's texel, read through the crossbar) and GL_PREVIOUS by one minus its own
/// checker texel, alpha GL_TEXTURE0's, its coordinates generated (GL_OBJECT_LINEAR S and T).
#[test]
fn a_combine_unit_reading_gl_texture0_through_the_crossbar_draws_as_mesas_gl_draws_it() {
    let crossbar = |arg0: &str| {
        format!(
            "[[meshes.texture_units]]\nbuiltin = \"lightmap\"\nmin_filter = \"linear\"\n\
             [[meshes.texture_units]]\nbuiltin = \"checker\"\nmin_filter = \"linear\"\nenv = \"combine\"\n\
             texgen = {{ s = {{ mode = \"object_linear\" }}, t = {{ mode = \"object_linear\", plane = [0, 1, 0, 0] }} }}\n\
             combine = {{ rgb = \"interpolate\", rgb_sources = [\"{arg0}\", \"previous\", \"texture\"], \
             rgb_operands = [\"src_color\", \"src_color\", \"one_minus_src_color\"], \
             alpha = \"replace\", alpha_sources = [\"{arg0}\"] }}\n"
        )
    };
    let text = lit(&crossbar("texture0"), &crossbar("texture0"));
    let scene = parse("crossbar", &text).unwrap();
    let unit = scene.meshes[0].textures[1].as_ref().unwrap().unit;
    assert_eq!(unit.combine.rgb_sources[0], CombineSource::TextureUnit(0));
    assert_eq!(unit.combine.units_read(), 0b1);
    let crossed = draws_as_mesa_does("crossbar", &text);
    // GL_TEXTURE0 is read: GL_PREVIOUS in its place (the lit texel) draws another image.
    let previous = ffvk_image(
        "crossbar_previous",
        &lit(&crossbar("previous"), &crossbar("previous")),
    );
    let share = changed_share(&crossed, &previous);
    println!(
        "GL_TEXTURE0 for GL_PREVIOUS changes {:.1} % of the pixels by more than 8/255",
        share * 100.0
    );
    assert!(
        share > 0.1,
        "GL_TEXTURE0 for GL_PREVIOUS changes only {:.1} % of the pixels",
        share * 100.0
    );
}

/// The asset scene: each surface a checker base on unit 0, tiled by its texture matrix, and
/// the light map on unit 1 from the mesh's coordinates; the wall's through GL_COMBINE's
/// MODULATE scaled by 2.
#[test]
fn the_lightmap_asset_scene_lights_a_tiled_base_through_a_second_unit() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/lightmap.toml");
    let scene = Scene::load(&path).unwrap();
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    assert!(!scene.state.lighting);
    assert_eq!(scene.meshes.len(), 2);
    for m in &scene.meshes {
        let (base, light) = (m.textures[0].as_ref().unwrap(), m.textures[1].as_ref().unwrap());
        assert_eq!(
            (base.source.as_str(), light.source.as_str()),
            ("builtin checker", "builtin lightmap")
        );
        assert_ne!(base.unit.matrix, Mat4::IDENTITY);
        assert_eq!(light.unit.matrix, Mat4::IDENTITY);
        assert_eq!(m.mesh_texcoords(), 0b10);
        assert!(base.applies() && light.applies());
    }
    assert_eq!(
        scene.meshes[0].textures[1].as_ref().unwrap().unit.env_mode,
        TexEnvMode::Modulate
    );
    let wall = scene.meshes[1].textures[1].as_ref().unwrap().unit;
    assert_eq!(wall.env_mode, TexEnvMode::Combine);
    assert_eq!(
        (wall.combine.rgb, wall.combine.rgb_scale),
        (CombineFunc::Modulate, 2.0)
    );
}

/// `ffvk explain` on a surface of two units prints each unit's coordinates, texel, previous
/// color and result in unit order, `GL_COMBINE`'s functions with their arguments, and the
/// color texturing leaves; and names the cube map's face a direction selects.
#[test]
fn explain_prints_each_units_inputs_and_result_in_unit_order() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/lightmap.toml");
    let mut scene = Scene::load(&path).unwrap();
    scene.set_size(128, 128);
    let text = ffvk_cli::explain::explain(&scene, 64, 100, LightingMode::Vertex).expect("the floor is there");
    contains_all(
        &text,
        &[
            "GL_TEXTURE0: builtin checker (64x64",
            "GL_TEXTURE1: builtin lightmap (64x64",
            "C_p = C_f (c_pri)",
            "C_p (previous unit)",
            "C_v, A_v (modulate)",
            "after texturing",
        ],
    );
    let zero = text.find("GL_TEXTURE0:").unwrap();
    assert!(zero < text.find("GL_TEXTURE1:").unwrap(), "{text}");
    assert!(!text.contains("not predicted"), "{text}");
    // The wall: GL_COMBINE's MODULATE × 2.
    let wall = ffvk_cli::explain::explain(&scene, 64, 30, LightingMode::Vertex).expect("the wall is there");
    contains_all(
        &wall,
        &["GL_COMBINE: RGB GL_MODULATE(GL_TEXTURE GL_SRC_COLOR, GL_PREVIOUS GL_SRC_COLOR) × 2"],
    );
    // A cube map on unit 1 by GL_REFLECTION_MAP: the face and (s_face, t_face).
    let text = String::from(
        "[image]\nsize = [64, 64]\n[camera]\neye = [0.0, 0.0, 3.0]\n\
         [[meshes]]\nbuiltin = \"sphere\"\nlevel = 16\n\
         [[meshes.texture_units]]\nbuiltin = \"checker\"\nmin_filter = \"linear\"\n\
         [[meshes.texture_units]]\ncube_map = { builtin = \"faces\" }\nmin_filter = \"linear\"\n\
         texgen = { s = { mode = \"reflection_map\" }, t = { mode = \"reflection_map\" }, r = { mode = \"reflection_map\" } }\n"
    );
    let scene = Scene::parse(&text, &PathBuf::from("explain_cube.toml")).unwrap();
    let text = ffvk_cli::explain::explain(&scene, 32, 32, LightingMode::Vertex).expect("the sphere is there");
    contains_all(
        &text,
        &[
            "GL_TEXTURE1: builtin cube map faces (16² cube map faces",
            "R by GL_REFLECTION_MAP generated",
            "selects GL_TEXTURE_CUBE_MAP_POSITIVE_Z, (s_face, t_face) (0.5",
        ],
    );
}
