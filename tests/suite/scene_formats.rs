//! A texture's base internal format in scene files (a `texture` table's, or a unit's of
//! `texture_units`, `format`): GL's names in lowercase without `GL_`, `"rgba"` by default, for
//! a 2D image and a cube map's faces alike; a bad value refused naming the file, the field,
//! the value and the names accepted; and scenes of luminance, alpha and intensity units drawn
//! by ffvk as Mesa's GL draws them (the GL reference uploads each image with its format as
//! glTexImage2D's internal format).

use std::path::PathBuf;

use ffvk::gl::texture::{BaseFormat, TexEnvMode};
use ffvk::scene::Scene;

use crate::scene_units::{changed_share, draws_as_mesa_does, ffvk_image, lit};

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(format!("scene_formats/{name}.toml"))
}

fn parse(name: &str, text: &str) -> Result<Scene, ffvk::scene::SceneError> {
    Scene::parse(text, &scene_path(name))
}

/// A sphere whose table ends with `fields`.
fn sphere(fields: &str) -> String {
    format!("[[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\n{fields}\n")
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

fn contains_all(message: &str, parts: &[&str]) {
    for p in parts {
        assert!(message.contains(p), "{message:?} should mention {p:?}");
    }
}

/// The base format of each unit of the one sphere of a scene whose table ends with `fields`
/// (a unit's cube map's faces must share it).
fn formats(fields: &str) -> Vec<Option<BaseFormat>> {
    let scene = parse("ok", &sphere(fields)).unwrap();
    scene.meshes[0]
        .textures
        .iter()
        .map(|t| {
            let t = t.as_ref()?;
            if let Some(cube) = &t.cube_map {
                for face in cube.faces() {
                    assert_eq!(face.base_format, t.image.base_format, "{fields}");
                }
            }
            Some(t.image.base_format)
        })
        .collect()
}

#[test]
fn a_textures_format_is_gls_base_internal_format_by_its_lowercase_name_rgba_by_default() {
    let names = [
        ("rgba", BaseFormat::Rgba),
        ("rgb", BaseFormat::Rgb),
        ("alpha", BaseFormat::Alpha),
        ("luminance", BaseFormat::Luminance),
        ("luminance_alpha", BaseFormat::LuminanceAlpha),
        ("intensity", BaseFormat::Intensity),
    ];
    for (name, format) in names {
        let one = format!("texture = {{ builtin = \"checker\", format = \"{name}\" }}");
        assert_eq!(formats(&one)[0], Some(format), "{name}");
    }
    // GL_RGBA, as glTexImage2D's internal format of a legacy program's RGBA image.
    assert_eq!(
        formats("texture = { builtin = \"checker\" }")[0],
        Some(BaseFormat::Rgba)
    );
    // Each unit its own; the scene's [texture] takes it as a mesh's does.
    assert_eq!(
        formats(
            "texture_units = [{ builtin = \"checker\", format = \"rgb\" }, { builtin = \"lightmap\", format = \"luminance\" }, \
             { builtin = \"leaves\", format = \"alpha\" }, { builtin = \"lightmap\" }]"
        ),
        [
            Some(BaseFormat::Rgb),
            Some(BaseFormat::Luminance),
            Some(BaseFormat::Alpha),
            Some(BaseFormat::Rgba)
        ]
    );
    let scene = parse(
        "scene_texture",
        &format!(
            "[texture]\nbuiltin = \"lightmap\"\nformat = \"intensity\"\n{}",
            sphere("")
        ),
    )
    .unwrap();
    let t = scene.meshes[0].texture().unwrap();
    assert_eq!(t.image.base_format, BaseFormat::Intensity);
    // A cube map's faces take the unit's format, with its image or alone.
    let cube = "cube_map = { builtin = \"faces\" }";
    assert_eq!(
        formats(&format!(
            "texture_units = [{{ builtin = \"checker\" }}, {{ {cube}, format = \"luminance_alpha\" }}]"
        )),
        [
            Some(BaseFormat::Rgba),
            Some(BaseFormat::LuminanceAlpha),
            None,
            None
        ]
    );
    assert_eq!(
        formats(&format!(
            "texture = {{ builtin = \"checker\", {cube}, format = \"intensity\" }}"
        ))[0],
        Some(BaseFormat::Intensity)
    );
    // sRGB where GL 2.1 has it: GL_SRGB8, GL_SLUMINANCE8, GL_SLUMINANCE8_ALPHA8.
    for name in ["rgb", "luminance", "luminance_alpha"] {
        let scene = parse(
            "srgb",
            &sphere(&format!(
                "texture = {{ builtin = \"lightmap\", srgb = true, format = \"{name}\" }}"
            )),
        )
        .unwrap();
        let image = &scene.meshes[0].texture().unwrap().image;
        assert!(image.srgb && image.base_format.name() == name, "{name}");
    }
}

#[test]
fn bad_formats_are_refused_naming_the_file_the_field_the_value_and_the_names_accepted() {
    let accepted =
        "expected one of \"rgba\", \"rgb\", \"alpha\", \"luminance\", \"luminance_alpha\", \"intensity\"";
    // GL's spelling, C's enum, another base format GL 2.1 has but textures do not take, a
    // sized internal format, a typo: each refused by name.
    for (name, value) in [
        ("gl_name", "GL_LUMINANCE"),
        ("upper", "LUMINANCE"),
        ("depth", "depth_component"),
        ("sized", "luminance8"),
        ("typo", "luminence"),
    ] {
        let text = sphere(&format!(
            "texture_units = [{{ builtin = \"checker\" }}, {{ builtin = \"lightmap\", format = \"{value}\" }}]"
        ));
        let m = refused(name, &text);
        contains_all(
            &m,
            &[&format!(
                "meshes[0].texture_units[1].format: \"{value}\": {accepted}"
            )],
        );
    }
    // Under every path a texture table has: a mesh's texture, the scene's, a cube map's unit,
    // the third mesh's.
    let m = refused(
        "texture",
        &sphere("texture = { builtin = \"checker\", format = \"rgba8\" }"),
    );
    contains_all(&m, &["meshes[0].texture.format: \"rgba8\"", accepted]);
    let m = refused(
        "scene",
        &format!(
            "[texture]\nbuiltin = \"checker\"\nformat = \"bgra\"\n{}",
            sphere("")
        ),
    );
    contains_all(&m, &["texture.format: \"bgra\"", accepted]);
    let m = refused(
        "cube",
        &sphere("texture_units = [{ builtin = \"checker\" }, { cube_map = { builtin = \"faces\" }, format = \"red\" }]"),
    );
    contains_all(&m, &["meshes[0].texture_units[1].format: \"red\"", accepted]);
    let m = refused(
        "third",
        &format!(
            "{}{}{}",
            sphere(""),
            sphere(""),
            sphere("texture_units = [{ builtin = \"checker\" }, { builtin = \"disc\", format = \"alpha\" }, { builtin = \"lightmap\", format = \"Intensity\" }]")
        ),
    );
    contains_all(
        &m,
        &["meshes[2].texture_units[2].format: \"Intensity\"", accepted],
    );
    // Not a word: TOML's type error names the field.
    let m = refused(
        "number",
        &sphere("texture = { builtin = \"checker\", format = 0x1909 }"),
    );
    contains_all(&m, &["format"]);
    // GL 2.1 has no sRGB alpha or intensity format.
    for value in ["alpha", "intensity"] {
        let m = refused(
            "srgb",
            &sphere(&format!(
                "texture = {{ builtin = \"leaves\", srgb = true, format = \"{value}\" }}"
            )),
        );
        contains_all(
            &m,
            &[
                &format!(
                    "meshes[0].texture.srgb: true with format \"{value}\": GL 2.1 has no sRGB {value} format"
                ),
                "GL_SLUMINANCE8_ALPHA8",
                "expected srgb = false, or format \"rgba\", \"rgb\", \"luminance\" or \"luminance_alpha\"",
            ],
        );
    }
}

/// The sphere: an RGB checker on unit 0 and the light map as `GL_LUMINANCE` on unit 1 through
/// `GL_COMBINE`'s `MODULATE` scaled by 2 (a gray light map: the pools' tints gone). The floor:
/// a checker, the light map as `GL_INTENSITY` on unit 1 in `GL_BLEND` towards a warm
/// constant, and the leaves as `GL_ALPHA` on unit 2 (`GL_MODULATE`: the color kept, the alpha
/// the leaves'), cut by the alpha test.
fn formatted(sphere: [&str; 2], floor: [&str; 3]) -> String {
    let text = lit(
        &format!(
            "texture_units = [{{ builtin = \"checker\", min_filter = \"linear\", scale = [2.0, 2.0]{} }}, \
             {{ builtin = \"lightmap\", min_filter = \"linear\", coords = \"mesh\", env = \"combine\", \
             combine = {{ rgb = \"modulate\", rgb_scale = 2 }}{} }}]",
            sphere[0], sphere[1]
        ),
        &format!(
            "texture_units = [{{ builtin = \"checker\", min_filter = \"linear\", scale = [2.0, 2.0]{} }}, \
             {{ builtin = \"lightmap\", min_filter = \"linear\", coords = \"mesh\", env = \"blend\", \
             env_color = [1.0, 0.6, 0.2, 1.0]{} }}, \
             {{ builtin = \"leaves\", min_filter = \"linear\", coords = \"mesh\", scale = [3.0, 3.0]{} }}]",
            floor[0], floor[1], floor[2]
        ),
    );
    format!("[alpha_test]\nfunc = \"greater\"\nreference = 0.5\n{text}")
}

#[test]
fn luminance_intensity_and_alpha_units_draw_as_mesas_gl_draws_them() {
    let rgb = ", format = \"rgb\"";
    let text = formatted(
        [rgb, ", format = \"luminance\""],
        [rgb, ", format = \"intensity\"", ", format = \"alpha\""],
    );
    let scene = parse("units", &text).unwrap();
    let unit = |mesh: usize, i: usize| scene.meshes[mesh].textures[i].as_ref().unwrap();
    assert_eq!(unit(0, 1).image.base_format, BaseFormat::Luminance);
    assert_eq!(unit(0, 1).unit.env_mode, TexEnvMode::Combine);
    assert_eq!(unit(1, 1).image.base_format, BaseFormat::Intensity);
    assert_eq!(unit(1, 2).image.base_format, BaseFormat::Alpha);
    let ours = draws_as_mesa_does("formats", &text);
    // The formats are drawn: the same scene in GL_RGBA throughout draws another image.
    let rgba = ffvk_image("formats_rgba", &formatted(["", ""], ["", "", ""]));
    let share = changed_share(&ours, &rgba);
    println!(
        "the base formats change {:.1} % of the pixels by more than 8/255",
        share * 100.0
    );
    assert!(
        share > 0.1,
        "the base formats change only {:.1} % of the pixels",
        share * 100.0
    );
}

/// A reflection-mapped sphere whose unit 1 is the built-in cube map as `GL_INTENSITY`: each
/// face's red as its gray and its alpha, `GL_MODULATE`d.
#[test]
fn an_intensity_cube_map_draws_as_mesas_gl_draws_it() {
    let reflective = |format: &str| {
        lit(
            &format!(
                "[[meshes.texture_units]]\nbuiltin = \"checker\"\nmin_filter = \"linear\"\n\
                 [[meshes.texture_units]]\ncube_map = {{ builtin = \"faces\" }}\n{format}\nmin_filter = \"linear\"\n\
                 coords = \"mesh\"\ntexgen = {{ s = {{ mode = \"reflection_map\" }}, t = {{ mode = \"reflection_map\" }}, \
                 r = {{ mode = \"reflection_map\" }} }}\n"
            ),
            "",
        )
    };
    let text = reflective("format = \"intensity\"");
    let scene = parse("cube", &text).unwrap();
    let cube = scene.meshes[0].textures[1]
        .as_ref()
        .unwrap()
        .cube_map
        .as_ref()
        .unwrap();
    assert!(cube
        .faces()
        .iter()
        .all(|f| f.base_format == BaseFormat::Intensity));
    let ours = draws_as_mesa_does("cube_intensity", &text);
    let rgba = ffvk_image("cube_rgba", &reflective(""));
    let share = changed_share(&ours, &rgba);
    println!(
        "GL_INTENSITY changes {:.1} % of the pixels by more than 8/255",
        share * 100.0
    );
    assert!(
        share > 0.1,
        "GL_INTENSITY changes only {:.1} % of the pixels",
        share * 100.0
    );
}
