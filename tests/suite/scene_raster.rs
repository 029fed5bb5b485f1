//! A mesh's raster state in scene files (polygon mode and offset, color mask, stencil, logic
//! op, line stipple, blending, culling; `[image] clear_stencil`): GL's names and defaults, and
//! a bad value refused naming the file, the field, the value and what was expected.

use std::path::PathBuf;

use ffvk::ash::vk;
use ffvk::gl::state::Face;
use ffvk::scene::{MeshRaster, Scene};
use ffvk::{Blend, LineStipple, PolygonModes, PolygonOffset, StencilFace};

/// The scene of `text`, named `name` (parsed, not read: nothing is written).
fn parse(name: &str, text: &str) -> Result<Scene, ffvk::scene::SceneError> {
    Scene::parse(text, &scene_path(name))
}

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(format!("scene_raster/{name}.toml"))
}

/// The raster state of the one sphere of a scene whose `[[meshes]]` table ends with `fields`.
fn raster(fields: &str) -> MeshRaster {
    let text = format!("[[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\n{fields}\n");
    let scene = parse("ok", &text).unwrap();
    scene.meshes[0].raster
}

/// The message of the error a scene with `fields` in its mesh's table (and `image`'s fields)
/// fails with; it names the file first.
fn refused(name: &str, image: &str, fields: &str) -> String {
    let text = format!("[image]\n{image}\n[[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\n{fields}\n");
    let path = scene_path(name);
    let message = parse(name, &text).expect_err("the scene is refused").to_string();
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

#[test]
fn raster_state_left_out_is_gls_initial_state() {
    let r = raster("");
    assert!(r.is_default());
    assert_eq!(r, MeshRaster::default());
    assert_eq!(r.polygon_mode, PolygonModes::FILL);
    assert_eq!(r.color_mask, [true; 4]);
    assert_eq!(
        (
            r.polygon_offset,
            r.stencil,
            r.logic_op,
            r.line_stipple,
            r.blend,
            r.cull_face
        ),
        (None, None, None, None, None, None)
    );
    assert_eq!(
        (r.blend_color, r.depth_range, r.depth_write),
        ([0.0; 4], [0.0, 1.0], true)
    );
    let scene = parse("plain", "[[meshes]]\nbuiltin = \"sphere\"\n").unwrap();
    assert_eq!(scene.clear_stencil, 0);
}

#[test]
fn each_raster_field_parses_with_gls_names() {
    let r = raster("polygon_mode = \"line\"");
    assert_eq!(r.polygon_mode, PolygonModes::both(vk::PolygonMode::LINE));
    let r = raster("polygon_mode = { front = \"fill\", back = \"point\" }");
    assert_eq!(
        (r.polygon_mode.front, r.polygon_mode.back),
        (vk::PolygonMode::FILL, vk::PolygonMode::POINT)
    );
    let r = raster("polygon_mode = { back = \"line\" }");
    assert_eq!(
        (r.polygon_mode.front, r.polygon_mode.back),
        (vk::PolygonMode::FILL, vk::PolygonMode::LINE),
        "a face left out is filled"
    );

    let r = raster("polygon_offset = { factor = -1.0, units = -2.0, fill = false, line = true }");
    let o = r.polygon_offset.unwrap();
    assert_eq!(
        (o.factor, o.units, o.fill, o.line, o.point),
        (-1.0, -2.0, false, true, false)
    );
    let r = raster("polygon_offset = { factor = 1.0, units = 1.0 }");
    assert_eq!(
        r.polygon_offset,
        Some(PolygonOffset::fill(1.0, 1.0)),
        "the table enables FILL"
    );
    let r = raster("polygon_offset = { factor = 1.0, fill = false }");
    assert_eq!(r.polygon_offset, None, "all three modes off: no offset");

    let r = raster("color_mask = [true, false, true, false]");
    assert_eq!(r.color_mask, [true, false, true, false]);

    let r = raster(
        "stencil = { func = \"equal\", ref = 1, value_mask = 255, fail = \"keep\", depth_fail = \"incr_wrap\", pass = \"replace\", write_mask = 0x0F }",
    );
    let s = r.stencil.unwrap();
    let want = StencilFace::default()
        .with_func(vk::CompareOp::EQUAL, 1, 255)
        .with_ops(
            vk::StencilOp::KEEP,
            vk::StencilOp::INCREMENT_AND_WRAP,
            vk::StencilOp::REPLACE,
        )
        .with_write_mask(0x0F);
    assert_eq!(
        (s.front, s.back),
        (want, want),
        "the back faces take the front's without stencil_back"
    );
    let r = raster(
        "stencil = { func = \"lequal\" }\nstencil_back = { func = \"notequal\", ref = 3, pass = \"decr\" }",
    );
    let s = r.stencil.unwrap();
    assert_eq!(
        s.front,
        StencilFace::default().with_func(vk::CompareOp::LESS_OR_EQUAL, 0, u32::MAX)
    );
    assert_eq!(
        s.back,
        StencilFace::default()
            .with_func(vk::CompareOp::NOT_EQUAL, 3, u32::MAX)
            .with_ops(
                vk::StencilOp::KEEP,
                vk::StencilOp::KEEP,
                vk::StencilOp::DECREMENT_AND_CLAMP
            )
    );
    // GL's defaults for the words left out, every word of each list accepted.
    let s = raster("stencil = {}").stencil.unwrap();
    assert_eq!(s.front, StencilFace::default());
    for (word, op) in [
        ("never", vk::CompareOp::NEVER),
        ("less", vk::CompareOp::LESS),
        ("greater", vk::CompareOp::GREATER),
        ("gequal", vk::CompareOp::GREATER_OR_EQUAL),
        ("always", vk::CompareOp::ALWAYS),
    ] {
        let s = raster(&format!("stencil = {{ func = \"{word}\" }}"))
            .stencil
            .unwrap();
        assert_eq!(s.front.func, op, "{word}");
    }
    for (word, op) in [
        ("zero", vk::StencilOp::ZERO),
        ("incr", vk::StencilOp::INCREMENT_AND_CLAMP),
        ("invert", vk::StencilOp::INVERT),
        ("decr_wrap", vk::StencilOp::DECREMENT_AND_WRAP),
    ] {
        let s = raster(&format!("stencil = {{ fail = \"{word}\" }}"))
            .stencil
            .unwrap();
        assert_eq!(s.front.fail, op, "{word}");
    }
    // GL clamps the reference when it tests: below 0 is 0.
    let s = raster("stencil = { ref = -4 }").stencil.unwrap();
    assert_eq!(s.front.reference, 0);

    for (word, op) in [
        ("clear", vk::LogicOp::CLEAR),
        ("and", vk::LogicOp::AND),
        ("and_reverse", vk::LogicOp::AND_REVERSE),
        ("copy", vk::LogicOp::COPY),
        ("and_inverted", vk::LogicOp::AND_INVERTED),
        ("noop", vk::LogicOp::NO_OP),
        ("xor", vk::LogicOp::XOR),
        ("or", vk::LogicOp::OR),
        ("nor", vk::LogicOp::NOR),
        ("equiv", vk::LogicOp::EQUIVALENT),
        ("invert", vk::LogicOp::INVERT),
        ("or_reverse", vk::LogicOp::OR_REVERSE),
        ("copy_inverted", vk::LogicOp::COPY_INVERTED),
        ("or_inverted", vk::LogicOp::OR_INVERTED),
        ("nand", vk::LogicOp::NAND),
        ("set", vk::LogicOp::SET),
    ] {
        assert_eq!(
            raster(&format!("logic_op = \"{word}\"")).logic_op,
            Some(op),
            "{word}"
        );
    }

    let r = raster("line_stipple = { factor = 2, pattern = 0x0F0F }");
    assert_eq!(
        r.line_stipple,
        Some(LineStipple {
            factor: 2,
            pattern: 0x0F0F
        })
    );
    let r = raster("line_stipple = {}");
    assert_eq!(
        r.line_stipple,
        Some(LineStipple {
            factor: 1,
            pattern: 0xFFFF
        })
    );

    let r = raster("blend = { src = \"src_alpha\", dst = \"one_minus_src_alpha\" }");
    assert_eq!(r.blend, Some(Blend::ALPHA));
    let r = raster(
        "blend = { src = \"one\", dst = \"one\", equation = \"func_reverse_subtract\", src_alpha = \"zero\", equation_alpha = \"max\" }\nblend_color = [0.5, 0.25, 1.0, 0.0]",
    );
    assert_eq!(
        r.blend,
        Some(Blend::separate(
            (
                vk::BlendFactor::ONE,
                vk::BlendFactor::ONE,
                vk::BlendOp::REVERSE_SUBTRACT
            ),
            (vk::BlendFactor::ZERO, vk::BlendFactor::ONE, vk::BlendOp::MAX),
        ))
    );
    assert_eq!(r.blend_color, [0.5, 0.25, 1.0, 0.0]);
    let r = raster("blend = {}");
    assert_eq!(
        r.blend,
        Some(Blend::new(
            vk::BlendFactor::ONE,
            vk::BlendFactor::ZERO,
            vk::BlendOp::ADD
        )),
        "GL's initial factors and equation"
    );

    let r = raster("depth_range = [0.25, 2.0]");
    assert_eq!(
        r.depth_range,
        [0.25, 2.0],
        "kept as given: the renderer clamps it as GL does"
    );

    assert!(!raster("depth_mask = false").depth_write, "glDepthMask(GL_FALSE)");
    let rows: Vec<String> = (0..32).map(|i| format!("0x{:08X}", 0x8000_0001u32 | i)).collect();
    let r = raster(&format!("polygon_stipple = [{}]", rows.join(", ")));
    let mask = r.polygon_stipple.expect("the stipple is on");
    assert_eq!(
        mask[..8],
        [0x80, 0, 0, 0x01, 0x80, 0, 0, 0x01 | 1],
        "rows as GL's bytes, MSB first"
    );

    let r = raster("cull_face = \"front\"");
    assert_eq!(r.cull_face, Some(Face::Front));
    let scene = parse(
        "cull",
        "[[meshes]]\nbuiltin = \"sphere\"\ncull_face = \"front_and_back\"\n",
    )
    .unwrap();
    assert_eq!(scene.cull_face(&scene.meshes[0]), Some(Face::FrontAndBack));

    let scene = parse(
        "clear_stencil",
        "[image]\nclear_stencil = 7\n[[meshes]]\nbuiltin = \"sphere\"\n",
    )
    .unwrap();
    assert_eq!(scene.clear_stencil, 7);
}

#[test]
fn bad_raster_values_name_the_file_the_field_the_value_and_what_was_expected() {
    let m = refused("mode", "", "polygon_mode = \"wire\"");
    contains_all(
        &m,
        &[
            "meshes[0].polygon_mode",
            "\"wire\"",
            r#"expected one of "point", "line", "fill""#,
        ],
    );
    let m = refused("mode_back", "", "polygon_mode = { back = \"lines\" }");
    contains_all(&m, &["meshes[0].polygon_mode.back", "\"lines\"", "\"line\""]);
    let m = refused("offset", "", "polygon_offset = { factor = nan }");
    contains_all(&m, &["meshes[0].polygon_offset.factor", "NaN", "finite"]);
    let m = refused("offset_field", "", "polygon_offset = { slope = 1.0 }");
    contains_all(&m, &["unknown field", "slope"]);
    let m = refused("mask_len", "", "color_mask = [true, true, true]");
    contains_all(&m, &["color_mask", "3", "exactly 4"]);
    let m = refused("func", "", "stencil = { func = \"lessequal\" }");
    contains_all(
        &m,
        &[
            "meshes[0].stencil.func",
            "\"lessequal\"",
            "\"lequal\"",
            "\"always\"",
        ],
    );
    let m = refused("op", "", "stencil = { pass = \"increment\" }");
    contains_all(&m, &["meshes[0].stencil.pass", "\"increment\"", "\"incr_wrap\""]);
    let m = refused(
        "back_op",
        "",
        "stencil = {}\nstencil_back = { depth_fail = \"swap\" }",
    );
    contains_all(&m, &["meshes[0].stencil_back.depth_fail", "\"swap\"", "\"keep\""]);
    let m = refused("back_alone", "", "stencil_back = { func = \"equal\" }");
    contains_all(
        &m,
        &[
            "meshes[0].stencil_back",
            "without stencil",
            "expected a stencil table",
        ],
    );
    let m = refused("mask", "", "stencil = { write_mask = -1 }");
    contains_all(&m, &["meshes[0].stencil.write_mask", "-1", "0..=4294967295"]);
    let m = refused("ref", "", "stencil = { ref = 5000000000 }");
    contains_all(&m, &["meshes[0].stencil.ref", "5000000000", "GLint"]);
    let m = refused("logic", "", "logic_op = \"xnor\"");
    contains_all(&m, &["meshes[0].logic_op", "\"xnor\"", "\"equiv\"", "\"set\""]);
    let m = refused("stipple_factor", "", "line_stipple = { factor = 0 }");
    contains_all(&m, &["meshes[0].line_stipple.factor", "0", "1..=256"]);
    let m = refused("stipple_pattern", "", "line_stipple = { pattern = 0x10000 }");
    contains_all(&m, &["meshes[0].line_stipple.pattern", "65536", "0..=65535"]);
    let m = refused("blend_factor", "", "blend = { src = \"alpha\" }");
    contains_all(&m, &["meshes[0].blend.src", "\"alpha\"", "\"src_alpha\""]);
    let m = refused("blend_saturate", "", "blend = { dst = \"src_alpha_saturate\" }");
    contains_all(
        &m,
        &["meshes[0].blend.dst", "src_alpha_saturate", "source factor only"],
    );
    let m = refused("blend_equation", "", "blend = { equation = \"add\" }");
    contains_all(&m, &["meshes[0].blend.equation", "\"add\"", "\"func_add\""]);
    let m = refused("blend_color", "", "blend_color = [0.5, 2.0, 0.0, 1.0]");
    contains_all(&m, &["meshes[0].blend_color", "2", "[0, 1]"]);
    let m = refused("depth_range", "", "depth_range = [0.0, inf]");
    contains_all(&m, &["meshes[0].depth_range", "inf", "finite"]);
    let m = refused("depth_range_len", "", "depth_range = [0.0]");
    contains_all(&m, &["depth_range", "exactly 2"]);
    let m = refused("blend_color_rgb", "", "blend_color = [0.5, 0.5, 0.5]");
    contains_all(&m, &["meshes[0].blend_color", "3 values", "exactly 4"]);
    let m = refused("stipple_rows", "", "polygon_stipple = [1, 2, 3]");
    contains_all(&m, &["meshes[0].polygon_stipple", "3 rows", "exactly 32"]);
    let mut rows = vec!["0".to_owned(); 32];
    rows[5] = "4294967296".to_owned();
    let m = refused(
        "stipple_row",
        "",
        &format!("polygon_stipple = [{}]", rows.join(", ")),
    );
    contains_all(&m, &["meshes[0].polygon_stipple[5]", "4294967296", "32-bit"]);
    let m = refused("depth_mask", "", "depth_mask = 0");
    contains_all(&m, &["depth_mask"]);
    let m = refused("cull", "", "cull_face = \"both\"");
    contains_all(&m, &["meshes[0].cull_face", "\"both\"", "\"front_and_back\""]);
    let m = refused("clear_stencil", "clear_stencil = 256", "");
    contains_all(&m, &["image.clear_stencil", "256", "0..=255"]);
}
