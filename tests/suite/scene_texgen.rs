//! Texture coordinate generation in scene files (a texture's `texgen`): GL's names and
//! defaults per coordinate, eye planes given in world space and stored as glTexGen stores them
//! with the view loaded, the scene's `[texture]` and a mesh's alike, and a bad value refused
//! naming the file, the field, the value and what was expected.

use std::path::PathBuf;

use ffvk::gl::texture::{TexCoordGen, TexGenMode, TextureUnit};
use ffvk::scene::Scene;
use glam::Vec4;

/// The scene of `text`, named `name` (parsed, not read: nothing is written).
fn parse(name: &str, text: &str) -> Result<Scene, ffvk::scene::SceneError> {
    Scene::parse(text, &scene_path(name))
}

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(format!("scene_texgen/{name}.toml"))
}

/// The camera of these scenes: at (5, 0, 0) looking at the origin, y up. Its view takes a
/// world point (x, y, z) to (−z, y, x − 5) in eye space.
const CAMERA: &str = "[camera]\neye = [5.0, 0.0, 0.0]\ntarget = [0.0, 0.0, 0.0]\nup = [0.0, 1.0, 0.0]\n";

/// The texture coordinate generation of the one sphere of a scene whose texture has `texgen`.
fn texgen(texgen: &str) -> [TexCoordGen; 4] {
    let text = format!(
        "{CAMERA}[[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\ntexture = {{ builtin = \"checker\", texgen = {texgen} }}\n"
    );
    let scene = parse("ok", &text).unwrap();
    scene.meshes[0].texture().expect("textured").unit.texgen
}

/// The message of the error a scene whose sphere's texture has `texgen` fails with; it names
/// the file first.
fn refused(name: &str, texgen: &str) -> String {
    let text = format!(
        "{CAMERA}[[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\ntexture = {{ builtin = \"checker\", texgen = {texgen} }}\n"
    );
    refused_scene(name, &text)
}

fn refused_scene(name: &str, text: &str) -> String {
    let path = scene_path(name);
    let message = parse(name, text).expect_err("the scene is refused").to_string();
    assert!(
        message.starts_with(&path.display().to_string()),
        "{message:?} names the file first"
    );
    message
}

fn contains_all(message: &str, parts: &[&str]) {
    for p in parts {
        assert!(message.contains(p), "{message:?} should mention {p:?}");
    }
}

fn assert_close(a: Vec4, b: Vec4, what: &str) {
    assert!((a - b).abs().max_element() < 1e-5, "{what}: {a} should be {b}");
}

#[test]
fn texgen_left_out_is_gls_initial_generation() {
    let text = format!("{CAMERA}[[meshes]]\nbuiltin = \"sphere\"\ntexture = {{ builtin = \"checker\" }}\n");
    let scene = parse("plain", &text).unwrap();
    let unit = scene.meshes[0].texture().unwrap().unit;
    assert_eq!(unit.texgen, TextureUnit::default().texgen);
    assert!(unit.texgen.iter().all(|g| !g.enabled));
    assert_eq!(unit.texgen_code(), 0);
    // An empty table generates nothing either.
    assert_eq!(texgen("{}"), TextureUnit::default().texgen);
}

#[test]
fn each_texgen_mode_parses_with_gls_names_and_defaults() {
    // A coordinate given is generated, GL_EYE_LINEAR from GL's initial planes by default.
    let g = texgen("{ s = {}, r = {} }");
    for coord in [0, 2] {
        let initial = TexCoordGen::initial(coord);
        assert!(g[coord].enabled, "coordinate {coord} is generated");
        assert_eq!(g[coord].mode, TexGenMode::EyeLinear);
        assert_eq!(
            (g[coord].object_plane, g[coord].eye_plane),
            (initial.object_plane, initial.eye_plane)
        );
    }
    assert_eq!((g[1], g[3]), (TexCoordGen::initial(1), TexCoordGen::initial(3)));
    assert_eq!((g[0].eye_plane, g[2].eye_plane), (Vec4::X, Vec4::ZERO));

    // Each mode by GL's name, on every coordinate GL takes it for.
    let modes = [
        ("object_linear", TexGenMode::ObjectLinear, 4),
        ("eye_linear", TexGenMode::EyeLinear, 4),
        ("sphere_map", TexGenMode::SphereMap, 2),
        ("reflection_map", TexGenMode::ReflectionMap, 3),
        ("normal_map", TexGenMode::NormalMap, 3),
    ];
    for (name, mode, coords) in modes {
        assert_eq!(mode.name(), name);
        let table: Vec<String> = ["s", "t", "r", "q"][..coords]
            .iter()
            .map(|c| format!("{c} = {{ mode = \"{name}\" }}"))
            .collect();
        let g = texgen(&format!("{{ {} }}", table.join(", ")));
        for (coord, gen) in g.iter().enumerate() {
            if coord < coords {
                assert!(gen.enabled && gen.mode == mode, "{name} on {coord}: {gen:?}");
            } else {
                assert_eq!(*gen, TexCoordGen::initial(coord), "{name}: {coord} left alone");
            }
        }
    }

    // An object plane is kept as given; the eye plane keeps GL's initial value.
    let g = texgen("{ q = { mode = \"object_linear\", plane = [0, 0, 0.2, 1] } }");
    assert!(g[3].enabled);
    assert_eq!(g[3].mode, TexGenMode::ObjectLinear);
    assert_eq!(g[3].object_plane, Vec4::new(0.0, 0.0, 0.2, 1.0));
    assert_eq!(g[3].eye_plane, Vec4::ZERO);
    assert_eq!(g[3].plane(), Vec4::new(0.0, 0.0, 0.2, 1.0));

    // enabled = false sets the mode and plane with GL_TEXTURE_GEN_T off.
    let g = texgen("{ t = { enabled = false, mode = \"object_linear\", plane = [0, 2, 0, 0] } }");
    assert!(!g[1].enabled);
    assert_eq!(
        (g[1].mode, g[1].object_plane),
        (TexGenMode::ObjectLinear, Vec4::new(0.0, 2.0, 0.0, 0.0))
    );
    assert_eq!(g[1].code(), 0);
}

/// An eye plane is given in world space: set with the view loaded, GL stores p · V⁻¹. The
/// camera's view takes (x, y, z) to (−z, y, x − 5), so V⁻¹ takes (x_e, y_e, z_e) to
/// (z_e + 5, y_e, −x_e) and a x_w + b y_w + c z_w + d = −c x_e + b y_e + a z_e + (5a + d):
/// the world plane (1, 0.5, 0.25, 2) is (−0.25, 0.5, 1, 7) in eye space.
#[test]
fn an_eye_plane_is_given_in_world_space_and_stored_in_eye_space() {
    let g = texgen(
        "{ s = { mode = \"eye_linear\", plane = [1.0, 0.5, 0.25, 2.0] }, t = { plane = [0, 0, 1, 0] } }",
    );
    assert_eq!(
        (g[0].mode, g[1].mode),
        (TexGenMode::EyeLinear, TexGenMode::EyeLinear)
    );
    assert_close(g[0].eye_plane, Vec4::new(-0.25, 0.5, 1.0, 7.0), "s's eye plane");
    // z_w = −x_e: the world's z plane is the eye's −x plane.
    assert_close(g[1].eye_plane, Vec4::new(-1.0, 0.0, 0.0, 0.0), "t's eye plane");
    // The object planes keep GL's initial values.
    assert_eq!((g[0].object_plane, g[1].object_plane), (Vec4::X, Vec4::Y));

    // The same plane value at a world point and at its eye-space image.
    let text = format!(
        "{CAMERA}[[meshes]]\nbuiltin = \"sphere\"\ntexture = {{ builtin = \"checker\", texgen = {{ s = {{ plane = [1.0, 0.5, 0.25, 2.0] }} }} }}\n"
    );
    let scene = parse("eye", &text).unwrap();
    let world = Vec4::new(0.3, -1.2, 2.5, 1.0);
    let eye = scene.view * world;
    assert_close(
        eye,
        Vec4::new(-2.5, -1.2, -4.7, 1.0),
        "the view's image of the point",
    );
    let plane = scene.meshes[0].texture().unwrap().unit.texgen[0].eye_plane;
    let given = Vec4::new(1.0, 0.5, 0.25, 2.0);
    assert!((plane.dot(eye) - given.dot(world)).abs() < 1e-5);
}

/// The scene's `[texture]` generates the same coordinates on every mesh without a texture of
/// its own; a mesh's own `texture` takes its own.
#[test]
fn the_scenes_texture_and_a_meshs_take_texgen_alike() {
    let text = format!(
        "{CAMERA}\n[texture]\nbuiltin = \"checker\"\ntexgen = {{ s = {{ mode = \"sphere_map\" }}, t = {{ mode = \"sphere_map\" }} }}\n\
         [[meshes]]\nbuiltin = \"sphere\"\n\
         [[meshes]]\nbuiltin = \"plane\"\n\
         [[meshes]]\nbuiltin = \"teapot\"\nlevel = 2\ntexture = {{ builtin = \"checker\", texgen = {{ r = {{ mode = \"normal_map\" }} }} }}\n"
    );
    let scene = parse("shared", &text).unwrap();
    let units: Vec<TextureUnit> = scene.meshes.iter().map(|m| m.texture().unwrap().unit).collect();
    for unit in &units[..2] {
        assert!(unit.texgen[..2]
            .iter()
            .all(|g| g.enabled && g.mode == TexGenMode::SphereMap));
        assert!(!unit.texgen[2].enabled && !unit.texgen[3].enabled);
    }
    let own = units[2].texgen;
    assert!(!own[0].enabled && !own[1].enabled && !own[3].enabled);
    assert!(own[2].enabled && own[2].mode == TexGenMode::NormalMap);
    // The scene's [texture] is checked as a mesh's is, under its own path.
    let m = refused_scene(
        "scene_mode",
        &format!(
            "{CAMERA}[texture]\nbuiltin = \"checker\"\ntexgen = {{ q = {{ mode = \"normal_map\" }} }}\n[[meshes]]\nbuiltin = \"sphere\"\n"
        ),
    );
    contains_all(
        &m,
        &[": texture.texgen.q.mode", "\"normal_map\"", "GL_NORMAL_MAP"],
    );
}

#[test]
fn bad_texgen_values_name_the_file_the_field_the_value_and_what_was_expected() {
    let m = refused("coord", "{ u = { mode = \"sphere_map\" } }");
    contains_all(
        &m,
        &[
            "meshes[0].texture.texgen.u",
            "not a texture coordinate",
            "s, t, r or q",
        ],
    );
    let m = refused("word", "{ s = { mode = \"cube_map\" } }");
    contains_all(
        &m,
        &[
            "meshes[0].texture.texgen.s.mode",
            "\"cube_map\"",
            r#"expected one of "object_linear", "eye_linear", "sphere_map", "reflection_map", "normal_map""#,
        ],
    );
    // The modes GL refuses for a coordinate (GL_INVALID_ENUM), each saying which it takes.
    for (coord, mode, gl, takes) in [
        ("r", "sphere_map", "GL_SPHERE_MAP", "S and T only"),
        ("q", "sphere_map", "GL_SPHERE_MAP", "S and T only"),
        ("q", "reflection_map", "GL_REFLECTION_MAP", "S, T and R only"),
        ("q", "normal_map", "GL_NORMAL_MAP", "S, T and R only"),
    ] {
        let m = refused("coord_mode", &format!("{{ {coord} = {{ mode = \"{mode}\" }} }}"));
        let field = format!("meshes[0].texture.texgen.{coord}.mode");
        let value = format!("\"{mode}\" for {coord}");
        contains_all(
            &m,
            &[&field, &value, gl, takes, "\"object_linear\", \"eye_linear\""],
        );
    }
    let m = refused(
        "plane_len",
        "{ s = { mode = \"object_linear\", plane = [1, 0, 0] } }",
    );
    contains_all(&m, &["meshes[0].texture.texgen.s.plane", "3 values", "exactly 4"]);
    let m = refused("plane_nan", "{ t = { plane = [0, nan, 0, 0] } }");
    contains_all(&m, &["meshes[0].texture.texgen.t.plane", "NaN", "finite"]);
    let m = refused(
        "plane_inf",
        "{ r = { mode = \"object_linear\", plane = [0, 0, -inf, 0] } }",
    );
    contains_all(&m, &["meshes[0].texture.texgen.r.plane", "-inf", "finite"]);
    // Finite as given, past a float's range as GL keeps it.
    let m = refused(
        "plane_huge",
        "{ s = { mode = \"object_linear\", plane = [1e300, 0, 0, 0] } }",
    );
    contains_all(&m, &["meshes[0].texture.texgen.s.plane", "GL_OBJECT_PLANE"]);
    let m = refused(
        "plane_unread",
        "{ s = { mode = \"sphere_map\", plane = [1, 0, 0, 0] } }",
    );
    contains_all(
        &m,
        &[
            "meshes[0].texture.texgen.s.plane",
            "\"sphere_map\"",
            "reads no plane",
        ],
    );
    let m = refused("field", "{ s = { mode = \"eye_linear\", plan = [1, 0, 0, 0] } }");
    contains_all(&m, &["unknown field", "plan"]);
    let m = refused("enabled", "{ s = { enabled = 1 } }");
    contains_all(&m, &["enabled"]);
}

/// The asset scene: a lit teapot whose S and T come from GL_SPHERE_MAP.
#[test]
fn the_chrome_asset_scene_is_sphere_mapped() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/chrome.toml");
    let scene = Scene::load(&path).unwrap();
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    assert!(scene.state.lighting);
    let teapot = scene.meshes.iter().find(|m| m.name == "teapot").unwrap();
    let g = teapot.texture().unwrap().unit.texgen;
    assert!(g[..2]
        .iter()
        .all(|g| g.enabled && g.mode == TexGenMode::SphereMap));
    assert!(!g[2].enabled && !g[3].enabled);
}
