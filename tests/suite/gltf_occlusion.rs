//! glTF occlusion textures under glTF's meaning (`gltf_defaults = true`): on `GL_TEXTURE1`
//! through `GL_MODULATE` as a `GL_LUMINANCE` image of the R channel, from `TEXCOORD_0` or the
//! mesh's second set (`TEXCOORD_1`, a vertex buffer of its own), drawn as Mesa's GL draws the
//! same units; a set the primitive lacks is a warning naming the file, the material, the field
//! and the value; and the renderer's checks of a second set.

use std::path::{Path, PathBuf};

use ffvk::gl::state::LightingMode;
use ffvk::gl::texture::{BaseFormat, TexEnvMode};
use ffvk::scene::{render_scene, Scene, TexCoords};
use glam::{Mat4, Vec4};

use crate::stage_scenes::{differing, gl_image};
use crate::support::*;

/// A folder of its own for the files of scene `name` (tests run at once: no two write the same
/// image).
fn dir(name: &str) -> PathBuf {
    let dir = output_dir().join("gltf_occlusion").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The quad's buffer: positions, normals, both texture coordinate sets, indices; and the
/// bufferViews and accessors over it, as JSON.
fn quad_buffer() -> (Vec<u8>, String, String) {
    let positions = [
        [-1.0f32, -1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
    ];
    let normals = [[0.0f32, 0.0, 1.0]; 4];
    // TEXCOORD_0 maps the image upright (glTF's v runs down); TEXCOORD_1 turns it a quarter.
    let st0 = [[0.0f32, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]];
    let st1 = [[1.0f32, 1.0], [1.0, 0.0], [0.0, 0.0], [0.0, 1.0]];
    let floats = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let parts: [Vec<u8>; 5] = [
        floats(positions.as_flattened()),
        floats(normals.as_flattened()),
        floats(st0.as_flattened()),
        floats(st1.as_flattened()),
        [0u16, 1, 2, 0, 2, 3]
            .iter()
            .flat_map(|i| i.to_le_bytes())
            .collect(),
    ];
    let mut bin = Vec::new();
    let mut views = Vec::new();
    for p in &parts {
        views.push(format!(
            r#"{{ "buffer": 0, "byteOffset": {}, "byteLength": {} }}"#,
            bin.len(),
            p.len()
        ));
        bin.extend_from_slice(p);
    }
    let accessors = r#"
        { "bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0] },
        { "bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3" },
        { "bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2" },
        { "bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC2" },
        { "bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR" }"#;
    (bin, views.join(", "), accessors.to_owned())
}

/// The images: an 8×8 checker of two colors for the base color; for occlusion an ORM-packed
/// 8×8 image, R a ramp from dark at the left to white at the right, G and B what the occlusion
/// must not read.
fn write_images(dir: &Path) {
    let base = image::RgbaImage::from_fn(8, 8, |x, y| {
        if (x / 2 + y / 2) % 2 == 0 {
            image::Rgba([235, 190, 120, 255])
        } else {
            image::Rgba([130, 170, 230, 255])
        }
    });
    base.save(dir.join("base.png")).unwrap();
    let orm = image::RgbaImage::from_fn(8, 8, |x, _| {
        let r = (30 + 225 * x / 7) as u8;
        image::Rgba([r, 255 - r, 90, 255])
    });
    orm.save(dir.join("orm.png")).unwrap();
}

/// `NAME.gltf` (and `NAME.bin`): the quad with both coordinate sets, its material a base
/// color texture and, unless `occlusion` is empty, `"occlusionTexture": {occlusion}`; the
/// primitive's attributes without TEXCOORD_1 when `second_set` is false.
fn write_gltf(dir: &Path, name: &str, occlusion: &str, second_set: bool) -> PathBuf {
    write_images(dir);
    let (bin, views, accessors) = quad_buffer();
    std::fs::write(dir.join(format!("{name}.bin")), &bin).unwrap();
    let occlusion = match occlusion {
        "" => String::new(),
        o => format!(r#", "occlusionTexture": {o}"#),
    };
    let second = if second_set { r#", "TEXCOORD_1": 3"# } else { "" };
    let json = format!(
        r#"{{ "asset": {{ "version": "2.0" }}, "extensionsUsed": ["KHR_texture_transform"],
           "scene": 0, "scenes": [ {{ "nodes": [0] }} ],
           "nodes": [ {{ "mesh": 0 }} ],
           "meshes": [ {{ "name": "quad", "primitives": [ {{ "attributes": {{ "POSITION": 0,
               "NORMAL": 1, "TEXCOORD_0": 2{second} }}, "indices": 4, "material": 0 }} ] }} ],
           "materials": [ {{ "name": "stone", "pbrMetallicRoughness": {{ "baseColorTexture": {{ "index": 0 }},
               "metallicFactor": 0.0, "roughnessFactor": 0.5 }}{occlusion} }} ],
           "samplers": [ {{ "magFilter": 9729, "minFilter": 9729, "wrapS": 33071, "wrapT": 33071 }} ],
           "textures": [ {{ "source": 0, "sampler": 0 }}, {{ "source": 1, "sampler": 0 }} ],
           "images": [ {{ "uri": "base.png" }}, {{ "uri": "orm.png" }} ],
           "accessors": [ {accessors} ], "bufferViews": [ {views} ],
           "buffers": [ {{ "byteLength": {}, "uri": "{name}.bin" }} ] }}"#,
        bin.len()
    );
    let path = dir.join(format!("{name}.gltf"));
    std::fs::write(&path, json).unwrap();
    path
}

/// A lit scene under glTF's meaning drawing `gltf` (beside it), 128².
fn write_scene(dir: &Path, name: &str, gltf: &Path) -> PathBuf {
    let text = format!(
        "gltf_defaults = true\n\
         [image]\nsize = [128, 128]\nclear_color = [0.1, 0.1, 0.12]\n\
         [camera]\neye = [0.4, 0.5, 3.2]\ntarget = [0.0, 0.0, 0.0]\nfovy = 45\n\
         [light_model]\nambient = [0.3, 0.3, 0.3]\n\
         [[lights]]\nposition = [1.0, 2.0, 1.5, 0.0]\n\
         [[meshes]]\ngltf = \"{}\"\n",
        gltf.file_name().unwrap().to_str().unwrap()
    );
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

/// The scene of a quad whose occlusion texture is `occlusion` (JSON), with TEXCOORD_1 or not.
fn scene(name: &str, occlusion: &str, second_set: bool) -> Scene {
    let dir = dir(name);
    let gltf = write_gltf(&dir, name, occlusion, second_set);
    Scene::load(&write_scene(&dir, name, &gltf)).unwrap()
}

#[test]
fn a_gltf_occlusion_texture_is_unit_1_modulating_a_luminance_image_from_its_texcoord_set() {
    // texCoord 0, strength 1: unit 1 reads the mesh's coordinates.
    let first = scene("set0", r#"{ "index": 1 }"#, true);
    assert!(first.warnings.is_empty(), "{:?}", first.warnings);
    let mesh = &first.meshes[0];
    let (base, occlusion) = (
        mesh.textures[0].as_ref().unwrap(),
        mesh.textures[1].as_ref().unwrap(),
    );
    assert_eq!(base.image.base_format, BaseFormat::Rgba);
    assert_eq!(occlusion.image.base_format, BaseFormat::Luminance);
    assert_eq!(occlusion.unit.env_mode, TexEnvMode::Modulate);
    assert!(occlusion.unit.enabled && occlusion.applies());
    assert_eq!(occlusion.coords, TexCoords::Mesh);
    assert_eq!((mesh.mesh_texcoords(), mesh.second_texcoords()), (0b10, 0));
    assert!(
        mesh.data.second_texcoords.is_empty(),
        "no second set read for texCoord 0"
    );
    // The R ramp as luminance: the left column dark, the right one white.
    let level = &occlusion.image.levels()[0];
    assert_eq!(level.texel(0, 3), [30, 30, 30, 255]);
    assert_eq!(level.texel(7, 3), [255, 255, 255, 255]);
    assert!(
        first
            .notes
            .iter()
            .any(|n| n.contains("GL_TEXTURE1") && n.contains("whole lit color") && n.contains("ambient")),
        "{:?}",
        first.notes
    );
    assert!(
        !first.notes.iter().any(|n| n.contains("strength")),
        "{:?}",
        first.notes
    );

    // texCoord 1, strength 0.5 and a texture transform: the second set, the strength baked.
    let second = scene(
        "set1",
        r#"{ "index": 1, "texCoord": 1, "strength": 0.5,
             "extensions": { "KHR_texture_transform": { "offset": [0.25, 0] } } }"#,
        true,
    );
    assert!(second.warnings.is_empty(), "{:?}", second.warnings);
    let mesh = &second.meshes[0];
    let occlusion = mesh.textures[1].as_ref().unwrap();
    assert_eq!(occlusion.coords, TexCoords::MeshSecond);
    assert_eq!((mesh.mesh_texcoords(), mesh.second_texcoords()), (0, 0b10));
    assert_eq!(
        mesh.data.second_texcoords,
        [[1.0, 1.0], [1.0, 0.0], [0.0, 0.0], [0.0, 1.0]]
    );
    // 1 + 0.5 × (30/255 − 1) = 142.5/255: bytes 255 − 0.5 × (255 − 30).
    let texel = occlusion.image.levels()[0].texel(0, 0)[0];
    assert!((142..=143).contains(&texel), "{texel}");
    assert_eq!(
        occlusion.unit.matrix,
        Mat4::from_translation(glam::Vec3::new(0.25, 0.0, 0.0))
    );
    assert!(
        second
            .notes
            .iter()
            .any(|n| n.contains("material 0 (\"stone\")") && n.contains("strength 0.5")),
        "{:?}",
        second.notes
    );
}

/// `scene` drawn by ffvk and by Mesa's GL in the vertex and flat modes, held to the stage
/// scenes' tolerance (at most 1.5 % of the pixels beyond 2/255); ffvk's vertex-mode image.
fn draws_as_mesa_does(name: &str, scene: &Scene) -> image::RgbaImage {
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    let mut r = renderer();
    let mut failures = Vec::new();
    let mut vertex = None;
    for mode in [LightingMode::Vertex, LightingMode::Flat] {
        let ours = render_scene(&mut r, scene, Some(mode)).unwrap();
        let theirs = gl_image(scene, mode);
        let (n, worst) = differing(&ours, &theirs, 2);
        let share = n as f64 / (ours.width() * ours.height()) as f64;
        let what = format!("gltf_occlusion_{name}_{}", mode.name());
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
    let image = vertex.unwrap();
    // The CPU reference predicts both units, from either set, on a grid of probes (two
    // linearly filtered texels multiplied: 2/255).
    let mut probed = 0;
    for j in 0..8 {
        for i in 0..8 {
            let (x, y) = (scene.width * (2 * i + 1) / 16, scene.height * (2 * j + 1) / 16);
            if let Some((_, want)) = crate::support::reference_at(scene, x, y, LightingMode::Vertex) {
                crate::support::assert_pixel(
                    &image,
                    x,
                    y,
                    want,
                    2.0,
                    &format!("gltf_occlusion_{name} probe"),
                );
                probed += 1;
            }
        }
    }
    assert!(probed >= 16, "only {probed} probes hit the scene");
    image
}

/// The share of pixels of `a` and `b` more than 8/255 apart.
fn changed_share(a: &image::RgbaImage, b: &image::RgbaImage) -> f64 {
    differing(a, b, 8).0 as f64 / (a.width() * a.height()) as f64
}

#[test]
fn a_gltf_scene_with_occlusion_from_either_set_draws_as_mesas_gl_draws_it() {
    let set0 = draws_as_mesa_does("set0", &scene("drawn_set0", r#"{ "index": 1 }"#, true));
    let set1 = draws_as_mesa_does(
        "set1",
        &scene(
            "drawn_set1",
            r#"{ "index": 1, "texCoord": 1, "strength": 0.8 }"#,
            true,
        ),
    );
    // The occlusion is drawn, and each set maps it its own way.
    let plain = scene("drawn_plain", "", true);
    assert!(plain.warnings.is_empty(), "{:?}", plain.warnings);
    let mut r = renderer();
    let without = render_scene(&mut r, &plain, Some(LightingMode::Vertex)).unwrap();
    finish(r);
    for (what, a, b, least) in [
        ("occlusion from TEXCOORD_0", &set0, &without, 0.15),
        ("occlusion from TEXCOORD_1", &set1, &without, 0.15),
        ("TEXCOORD_1 for TEXCOORD_0", &set1, &set0, 0.1),
    ] {
        let share = changed_share(a, b);
        println!(
            "{what} changes {:.1} % of the pixels by more than 8/255",
            share * 100.0
        );
        assert!(
            share > least,
            "{what} changes only {:.1} % of the pixels",
            share * 100.0
        );
    }
}

#[test]
fn an_occlusion_texcoord_the_primitive_lacks_is_a_warning_naming_file_material_field_and_value() {
    for (name, occlusion, second_set, set) in [
        ("lacks_set1", r#"{ "index": 1, "texCoord": 1 }"#, false, "1"),
        ("set2", r#"{ "index": 1, "texCoord": 2 }"#, true, "2"),
    ] {
        let scene = scene(name, occlusion, second_set);
        let file = dir(name).join(format!("{name}.gltf")).display().to_string();
        let field = format!("occlusionTexture.texCoord = {set}");
        assert!(
            scene.warnings.iter().any(|w| w.starts_with(&file)
                && w.contains("material 0 (\"stone\")")
                && w.contains(&field)
                && w.contains("without its occlusion")),
            "{name}: {:?}",
            scene.warnings
        );
        let mesh = &scene.meshes[0];
        assert!(mesh.textures[1].is_none(), "{name}: the occlusion is left out");
        assert!(mesh.textures[0].is_some(), "{name}: the base color stays");
        // Drawn, without a panic.
        let mut r = renderer();
        render_scene(&mut r, &scene, Some(LightingMode::Vertex)).unwrap();
        finish(r);
    }
}

#[test]
fn a_second_texcoord_set_of_another_length_or_a_draw_reading_one_its_mesh_lacks_is_refused() {
    let mut r = renderer();
    let plain = quad(-0.5, -0.5, 0.5, 0.5, 0.0, Vec4::ONE);
    let short = plain.clone().with_second_texcoords(vec![[0.0, 0.0]; 3]);
    let e = r
        .upload(&short)
        .err()
        .expect("three coordinates for four vertices");
    let text = e.to_string();
    assert!(
        text.contains("3 second texture coordinates for 4 vertices"),
        "{text}"
    );
    let mesh = r.upload(&plain).unwrap();
    let mut frame = ffvk::Frame::new(16, 16);
    frame.draws.push(ndc_draw(&mesh).with_second_texcoords(0b10));
    let text = r.render(&frame).expect_err("no second set").to_string();
    assert!(
        text.contains("draw 0") && text.contains("second texture coordinates"),
        "{text}"
    );
    // Bit 0 is not a unit that reads it: the draw is fine.
    let mut frame = ffvk::Frame::new(16, 16);
    frame.draws.push(ndc_draw(&mesh).with_second_texcoords(1));
    r.render(&frame).unwrap();
    drop(mesh);
    finish(r);
}
