//! A texture unit's `cube_map` in scene files (GL_TEXTURE_CUBE_MAP, sampled before the unit's
//! 2D image): six face files in GL's order or the built-in "faces", the unit's filters, wraps,
//! `srgb` and `generate_mipmap` applied to each face; a bad cube map refused naming the file,
//! the field, the value and what was expected; and a reflection-mapped sphere drawn by ffvk as
//! Mesa's GL draws it.

use std::path::{Path, PathBuf};

use ffvk::gl::state::LightingMode;
use ffvk::gl::texture::{CubeFace, MinFilter};
use ffvk::scene::{render_scene, Scene};

use crate::stage_scenes::{differing, gl_image};
use crate::support::*;

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(format!("scene_cube/{name}.toml"))
}

/// A sphere whose table ends with `fields`.
fn sphere(fields: &str) -> String {
    format!("[[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\n{fields}\n")
}

/// The message of the error the scene `text` at `path` fails with; it names the file first.
fn refused_at(path: &Path, text: &str) -> String {
    let message = Scene::parse(text, path)
        .expect_err("the scene is refused")
        .to_string();
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

/// A folder of face files: `name` → a square PNG of `size` texels of one color.
fn faces_dir() -> PathBuf {
    let dir = output_dir().join("scene_cube");
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, w: u32, h: u32, c: [u8; 4]| {
        image::RgbaImage::from_pixel(w, h, image::Rgba(c))
            .save(dir.join(name))
            .unwrap();
    };
    for (i, c) in [
        [255, 0, 0, 255],
        [0, 255, 255, 255],
        [0, 255, 0, 255],
        [255, 0, 255, 255],
    ]
    .into_iter()
    .chain([[0, 0, 255, 255], [255, 255, 0, 255]])
    .enumerate()
    {
        write(&format!("face{i}.png"), 8, 8, c);
    }
    write("wide.png", 8, 4, [9; 4]);
    write("small.png", 4, 4, [9; 4]);
    dir
}

/// `texture_units` of the sphere: unit 0 the checker, unit 1 a cube map of `faces`.
fn units_with_faces(faces: &[&str]) -> String {
    let list: Vec<String> = faces.iter().map(|f| format!("{f:?}")).collect();
    sphere(&format!(
        "texture_units = [{{ builtin = \"checker\", min_filter = \"nearest\" }}, {{ cube_map = {{ faces = [{}] }}, min_filter = \"nearest\" }}]",
        list.join(", ")
    ))
}

const SIX: [&str; 6] = [
    "face0.png",
    "face1.png",
    "face2.png",
    "face3.png",
    "face4.png",
    "face5.png",
];

#[test]
fn a_units_cube_map_is_six_face_files_in_gls_order_or_the_builtin_faces() {
    let dir = faces_dir();
    let path = dir.join("six.toml");
    let scene = Scene::parse(&units_with_faces(&SIX), &path).unwrap();
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    let unit = scene.meshes[0].textures[1].as_ref().unwrap();
    let cube = unit.cube_map.as_ref().expect("a cube map");
    assert!(unit.unit.cube_map && unit.unit.enabled && unit.applies());
    assert_eq!((cube.size(), cube.level_count()), (8, 1));
    let texel = |f: CubeFace| cube.face(f).levels()[0].texel(0, 0);
    assert_eq!(texel(CubeFace::PositiveX), [255, 0, 0, 255]);
    assert_eq!(texel(CubeFace::NegativeY), [255, 0, 255, 255]);
    assert_eq!(texel(CubeFace::NegativeZ), [255, 255, 0, 255]);
    // Unit 0 has none: GL_TEXTURE_CUBE_MAP stays off there.
    let zero = scene.meshes[0].textures[0].as_ref().unwrap();
    assert!(zero.cube_map.is_none() && !zero.unit.cube_map);
    // The built-in cube, the one-unit form, with mipmaps made for each face and sRGB faces.
    let m = Scene::parse(
        &sphere("[meshes.texture]\ncube_map = { builtin = \"faces\" }\nmin_filter = \"linear_mipmap_linear\"\ngenerate_mipmap = true\nsrgb = true\n"),
        &scene_path("builtin"),
    )
    .unwrap()
    .meshes
    .remove(0);
    let t = m.texture().unwrap();
    let cube = t.cube_map.as_ref().unwrap();
    assert_eq!(t.sampling.min_filter, MinFilter::LinearMipmapLinear);
    assert!(cube.has_mipmaps() && cube.srgb() && t.applies());
    assert_eq!(cube.size(), 16);
    let colors: Vec<[u8; 4]> = CubeFace::ALL
        .iter()
        .map(|&f| cube.face(f).levels()[0].texel(0, 0))
        .collect();
    for (i, c) in colors.iter().enumerate() {
        assert!(!colors[..i].contains(c), "face {i}'s color {c:?} repeats");
    }
    // Without generate_mipmap a mipmap filter leaves it incomplete, as in GL, and says so.
    let scene = Scene::parse(
        &sphere(
            "[meshes.texture]\ncube_map = { builtin = \"faces\" }\nmin_filter = \"nearest_mipmap_nearest\"\n",
        ),
        &scene_path("incomplete"),
    )
    .unwrap();
    assert!(!scene.meshes[0].texture().unwrap().applies());
    assert_eq!(scene.warnings.len(), 1, "{:?}", scene.warnings);
}

#[test]
fn the_scenes_inputs_list_every_face_file() {
    let dir = faces_dir();
    let path = dir.join("inputs.toml");
    std::fs::write(&path, units_with_faces(&SIX)).unwrap();
    let files = ffvk::scene::inputs(&path, &Default::default());
    let mut expected = vec![path.clone()];
    expected.extend(SIX.iter().map(|f| dir.join(f)));
    assert_eq!(files, expected);
}

#[test]
fn a_bad_cube_map_is_refused_naming_the_file_the_field_the_value_and_the_expectation() {
    let dir = faces_dir();
    let path = dir.join("bad.toml");
    let at = "meshes[0].texture_units[1].cube_map";
    let m = refused_at(&path, &units_with_faces(&SIX[..5]));
    contains_all(
        &m,
        &[&format!("{at}.faces"), "5 files", "expected exactly 6", "+X, -X"],
    );
    let m = refused_at(
        &path,
        &units_with_faces(&[SIX[0], SIX[1], SIX[2], "wide.png", SIX[4], SIX[5]]),
    );
    contains_all(
        &m,
        &[
            &format!("{at}.faces[3]"),
            "wide.png",
            "8x4",
            "expected a square face",
        ],
    );
    let m = refused_at(
        &path,
        &units_with_faces(&[SIX[0], SIX[1], SIX[2], SIX[3], "small.png", SIX[5]]),
    );
    contains_all(
        &m,
        &[
            &format!("{at}.faces[4]"),
            "small.png",
            "4x4",
            "expected 8x8",
            "face0.png",
        ],
    );
    let m = refused_at(
        &path,
        &units_with_faces(&[SIX[0], "missing.png", SIX[2], SIX[3], SIX[4], SIX[5]]),
    );
    contains_all(&m, &[&format!("{at}.faces[1]"), "missing.png", "cannot read"]);
    let m = refused_at(
        &path,
        &sphere("texture_units = [{ builtin = \"checker\" }, { cube_map = { builtin = \"sky\" } }]"),
    );
    contains_all(&m, &[&format!("{at}.builtin"), "\"sky\"", "expected \"faces\""]);
    let m = refused_at(
        &path,
        &sphere(
            "texture_units = [{ builtin = \"checker\" }, { cube_map = { builtin = \"faces\", faces = [] } }]",
        ),
    );
    contains_all(
        &m,
        &[&format!("{at}.faces"), "given with builtin", "expected either"],
    );
    let m = refused_at(&path, &sphere("texture = { cube_map = {} }"));
    contains_all(
        &m,
        &["meshes[0].texture.cube_map", "no faces", "expected faces ="],
    );
    let m = refused_at(&path, &sphere("texture = { cube_map = { side = 3 } }"));
    contains_all(&m, &["side"]);
}

/// A lit sphere over a floor at 128², the sphere's table ending with `sphere`.
fn lit(sphere: &str) -> String {
    format!(
        "[image]\nsize = [128, 128]\nclear_color = [0.1, 0.1, 0.12]\n\
         [camera]\neye = [0.0, 1.2, 3.2]\ntarget = [0.0, -0.1, 0.0]\nfovy = 45\n\
         [light_model]\nambient = [0.3, 0.3, 0.3]\n\
         [[lights]]\nposition = [1.0, 2.0, 1.5, 0.0]\n\
         [material]\npreset = \"white_plastic\"\nambient = [0.8, 0.8, 0.8]\n\
         [[meshes]]\nbuiltin = \"sphere\"\nlevel = 24\nscale = [0.7, 0.7, 0.7]\n{sphere}\n\
         [[meshes]]\nbuiltin = \"plane\"\nlevel = 8\ntranslate = [0.0, -0.7, 0.0]\nrotate = [-90.0, 0.0, 0.0]\nscale = [2.0, 2.0, 1.0]\n\
         texture = {{ builtin = \"checker\", min_filter = \"linear\" }}\n"
    )
}

/// Unit 0 the checker from the mesh's coordinates; unit 1 the built-in cube (or `cube`),
/// GL_MODULATEd, its S, T and R generated in GL_REFLECTION_MAP.
fn reflective(unit1: &str) -> String {
    lit(&format!(
        "[[meshes.texture_units]]\nbuiltin = \"checker\"\nmin_filter = \"linear\"\n\
         [[meshes.texture_units]]\n{unit1}\nmin_filter = \"linear\"\ncoords = \"mesh\"\n\
         texgen = {{ s = {{ mode = \"reflection_map\" }}, t = {{ mode = \"reflection_map\" }}, r = {{ mode = \"reflection_map\" }} }}\n"
    ))
}

#[test]
fn a_reflection_mapped_sphere_draws_as_mesas_gl_draws_it() {
    let cube = "cube_map = { builtin = \"faces\" }";
    let scene = Scene::parse(&reflective(cube), &scene_path("reflect")).unwrap();
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    let mut r = renderer();
    let mut failures = Vec::new();
    let mut vertex = None;
    for mode in [LightingMode::Vertex, LightingMode::Flat] {
        let ours = render_scene(&mut r, &scene, Some(mode)).unwrap();
        let theirs = gl_image(&scene, mode);
        let (n, worst) = differing(&ours, &theirs, 2);
        let share = n as f64 / (ours.width() * ours.height()) as f64;
        let what = format!("scene_cube_reflect_{}", mode.name());
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
    let cubed = vertex.unwrap();
    // The cube map is sampled: without it (the unit's checker alone) the sphere changes.
    let plain = render_scene(
        &mut r,
        &Scene::parse(&reflective("builtin = \"leaves\""), &scene_path("plain")).unwrap(),
        Some(LightingMode::Vertex),
    )
    .unwrap();
    let changed = differing(&cubed, &plain, 8).0 as f64 / (128.0 * 128.0);
    println!("the cube map changes {:.1} % of the pixels", changed * 100.0);
    assert!(
        changed > 0.1,
        "the cube map changes only {:.1} %",
        changed * 100.0
    );
    // GL's precedence: an image given with the cube map is not sampled.
    let both = render_scene(
        &mut r,
        &Scene::parse(
            &reflective(&format!("builtin = \"leaves\"\n{cube}")),
            &scene_path("both"),
        )
        .unwrap(),
        Some(LightingMode::Vertex),
    )
    .unwrap();
    assert_eq!(
        differing(&cubed, &both, 0).0,
        0,
        "the 2D image changed the cube-mapped sphere"
    );
    finish(r);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
