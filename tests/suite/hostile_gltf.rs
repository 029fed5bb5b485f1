//! Hostile glTF, second round: what the specification forbids and the `gltf` crate lets
//! through (sparse indices out of range, unsorted or repeated; a GLB whose header length is
//! not the file's; numbers past float32's range), what it allows and ffvk refused (GLB chunks
//! of unknown type), and messages that name the field that caused them.

use std::path::{Path, PathBuf};

use ffvk::scene::gltf::load;

use crate::support::output_dir;

fn scratch(name: &str) -> PathBuf {
    let dir = output_dir().join("hostile_gltf").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A quad's four corners (48 bytes) then its six u16 indices (12 bytes) then `extra`, as one
/// buffer.
fn quad_buffer(extra: &[u8]) -> Vec<u8> {
    let corners: [f32; 12] = [-1., -1., 0., 1., -1., 0., 1., 1., 0., -1., 1., 0.];
    let mut bytes = bytemuck::cast_slice::<f32, u8>(&corners).to_vec();
    bytes.extend(bytemuck::cast_slice::<u16, u8>(&[0, 1, 2, 0, 2, 3]));
    bytes.extend(extra);
    bytes
}

/// The quad in buffer 0 (`buffer` is its JSON object), with `more_views` after the two views
/// of the quad, `accessor_extra` inside the POSITION accessor and `node` as node 0.
fn quad_json(buffer: &str, more_views: &str, accessor_extra: &str, node: &str) -> String {
    format!(
        r#"{{"asset": {{"version": "2.0"}},
  "buffers": [{buffer}],
  "bufferViews": [{{"buffer": 0, "byteLength": 48}}, {{"buffer": 0, "byteOffset": 48, "byteLength": 12}}{more_views}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 1]{accessor_extra}}},
    {{"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1}}]}}],
  "nodes": [{node}],
  "scenes": [{{"nodes": [0]}}], "scene": 0}}"#
    )
}

/// Writes `json` with `bin` beside it as `name.gltf` / `name.bin`.
fn write_gltf(dir: &Path, name: &str, json: &str, bin: &[u8]) -> PathBuf {
    std::fs::write(dir.join(format!("{name}.bin")), bin).unwrap();
    let path = dir.join(format!("{name}.gltf"));
    std::fs::write(&path, json).unwrap();
    path
}

/// A GLB of `chunks` (type, data), each padded to 4 bytes, with the header's length `length`
/// (the file's own where `None`).
fn glb(chunks: &[(&[u8; 4], &[u8])], length: Option<u32>) -> Vec<u8> {
    let mut body = Vec::new();
    for (kind, data) in chunks {
        let padded = data.len().next_multiple_of(4);
        body.extend((padded as u32).to_le_bytes());
        body.extend(*kind);
        body.extend(*data);
        let pad = if *kind == b"JSON" { b' ' } else { 0 };
        body.resize(body.len() + padded - data.len(), pad);
    }
    let mut bytes = b"glTF".to_vec();
    bytes.extend(2u32.to_le_bytes());
    bytes.extend(length.unwrap_or(12 + body.len() as u32).to_le_bytes());
    bytes.extend(body);
    bytes
}

/// glTF 2.0: sparse indices "MUST strictly increase" and each names an element of the
/// accessor. The `gltf` crate's reader dropped the substitutions that broke this without a word.
#[test]
fn sparse_indices_out_of_range_unsorted_or_repeated_are_refused_naming_the_index() {
    let dir = scratch("sparse");
    // Two substitutions: u8 indices at byte 60 (padded to 64), two VEC3 values at 64.
    let sparse = r#", "sparse": {"count": 2, "indices": {"bufferView": 2, "componentType": 5121},
                    "values": {"bufferView": 3}}"#;
    let views = r#", {"buffer": 0, "byteOffset": 60, "byteLength": 2}, {"buffer": 0, "byteOffset": 64, "byteLength": 24}"#;
    let cases = [
        ("in-order", [1u8, 2], None),
        (
            "out-of-range",
            [1, 9],
            Some("sparse index 1 is 9: expected less than 4 (the accessor's count)"),
        ),
        (
            "unsorted",
            [2, 1],
            Some("sparse index 1 is 1, after 2: expected strictly increasing indices"),
        ),
        (
            "repeated",
            [1, 1],
            Some("sparse index 1 is 1, after 1: expected strictly increasing indices"),
        ),
    ];
    for (name, indices, expected) in cases {
        let mut extra = indices.to_vec();
        extra.extend([0, 0]);
        extra.extend(bytemuck::cast_slice::<f32, u8>(&[0.5f32; 6]));
        let bin = quad_buffer(&extra);
        let buffer = format!(r#"{{"uri": "{name}.bin", "byteLength": {}}}"#, bin.len());
        let json = quad_json(&buffer, views, sparse, r#"{"mesh": 0}"#);
        let path = write_gltf(&dir, name, &json, &bin);
        match (load(&path), expected) {
            (Ok(loaded), None) => {
                // Corners 1 and 2 moved to z = 0.5: three of the six unshared vertices.
                let zs: Vec<f32> = loaded.meshes[0]
                    .data
                    .vertices
                    .iter()
                    .map(|v| v.position[2])
                    .collect();
                assert_eq!(zs.iter().filter(|&&z| z == 0.5).count(), 3, "{zs:?}");
            }
            (Err(e), Some(words)) => {
                let e = e.to_string();
                assert!(
                    e.contains(&format!("{name}.gltf")) && e.contains("accessor 0") && e.contains(words),
                    "{name}: {e}"
                );
            }
            (Ok(_), Some(words)) => panic!("{name}: loaded, expected an error saying {words:?}"),
            (Err(e), None) => panic!("{name}: {e}"),
        }
    }
}

/// A GLB's header states the file's length; a header that says less (the rest ignored) or
/// more is refused. Chunks of a type other than JSON and BIN are skipped, as glTF 2.0 asks
/// (they were an error without the type's value); a first chunk that is not JSON is refused
/// naming its type.
#[test]
fn glb_chunks_of_unknown_type_are_skipped_and_a_header_length_not_the_files_is_refused() {
    let dir = scratch("glb");
    let bin = quad_buffer(&[]);
    let json = quad_json(
        &format!(r#"{{"byteLength": {}}}"#, bin.len()),
        "",
        "",
        r#"{"mesh": 0}"#,
    );
    let json = json.as_bytes();
    let write = |name: &str, bytes: Vec<u8>| {
        let path = dir.join(format!("{name}.glb"));
        std::fs::write(&path, bytes).unwrap();
        path
    };

    let good = glb(&[(b"JSON", json), (b"BIN\0", &bin)], None);
    let loaded = load(&write("good", good.clone())).unwrap();
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);

    let extra = glb(&[(b"JSON", json), (b"BIN\0", &bin), (b"XTRA", b"abcd")], None);
    let loaded = load(&write("extra-chunk", extra)).unwrap();
    assert_eq!(loaded.meshes.len(), 1);
    assert!(
        loaded
            .warnings
            .iter()
            .any(|w| w.contains("GLB chunk 2 has type \"XTRA\"") && w.contains("skipped")),
        "{:?}",
        loaded.warnings
    );

    let refused = [
        (
            "short-length",
            glb(&[(b"JSON", json), (b"BIN\0", &bin)], Some(good.len() as u32 - 8)),
            format!(
                "the GLB header's length is {}: expected the file's length, {} bytes",
                good.len() - 8,
                good.len()
            ),
        ),
        (
            "unknown-first",
            glb(&[(b"XTRA", b"abcd"), (b"JSON", json)], None),
            "chunk 0 has type \"XTRA\" (0x41525458): expected \"JSON\"".to_owned(),
        ),
        (
            "bin-third",
            glb(&[(b"JSON", json), (b"XTRA", b"abcd"), (b"BIN\0", &bin)], None),
            "chunk 2 has type \"BIN\\0\"".to_owned(),
        ),
    ];
    for (name, bytes, words) in refused {
        let e = load(&write(name, bytes)).expect_err(name).to_string();
        assert!(
            e.contains(&format!("{name}.glb")) && e.contains(&words),
            "{name}: {e}"
        );
    }

    // A chunk whose length runs past the file.
    let mut overrun = good.clone();
    let json_padded = json.len().next_multiple_of(4);
    let bin_length_at = 12 + 8 + json_padded;
    overrun[bin_length_at..bin_length_at + 4].copy_from_slice(&1000u32.to_le_bytes());
    let e = load(&write("overrun", overrun)).unwrap_err().to_string();
    assert!(
        e.contains("chunk 1 (\"BIN\\0\" (0x004E4942)): its length is 1000: expected at most the"),
        "{e}"
    );
}

/// glTF's numbers are float32: one past its range became an infinity that failed later without
/// its field (a node's transform emptied the scene: "no triangle meshes"; a texture transform
/// reached the GL state's check). Each is now refused naming its JSON path; a product of
/// finite transforms that overflows is refused naming the node, and so is an index or enum
/// past 32 bits.
#[test]
fn numbers_past_float32_or_u32_and_transforms_that_overflow_are_refused_naming_the_field() {
    let dir = scratch("float-range");
    let bin = quad_buffer(&[]);
    let buffer = |name: &str| format!(r#"{{"uri": "{name}.bin", "byteLength": {}}}"#, bin.len());
    let texture = r#""materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
          "extensions": {"KHR_texture_transform": {"scale": [1, 5e38]}}}}}],
        "textures": [{"source": 0}], "images": [{"uri": "t.png"}],
        "extensionsUsed": ["KHR_texture_transform"],"#;
    let cases = [
        ("translation", r#"{"mesh": 0, "translation": [1e39, 0, 0]}"#, "", "nodes[0].translation[0]: 1e+39: expected a number float32 holds"),
        ("matrix", r#"{"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,-4e38,1]}"#, "", "nodes[0].matrix[14]: -4e+38"),
        // Indices and enums are 32-bit: the gltf crate wrapped 2³² to 0 and drew mesh 0.
        ("wrapped-index", r#"{"mesh": 4294967296}"#, "", "nodes[0].mesh: 4294967296: expected an integer from 0 to 4294967295"),
        (
            "wrapped-enum",
            r#"{"mesh": 0}"#,
            r#""samplers": [{"magFilter": 4294977025}],"#,
            "samplers[0].magFilter: 4294977025: expected an integer",
        ),
        (
            "texture-transform",
            r#"{"mesh": 0}"#,
            texture,
            "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.scale[1]: 5e+38",
        ),
        (
            "overflowing-product",
            r#"{"scale": [1e30, 1, 1], "children": [1]}, {"name": "leaf", "mesh": 0, "scale": [1e30, 1, 1]}"#,
            "",
            "nodes[1] (\"leaf\", 2 deep): its world transform (its ancestors' transforms times its own) overflows float32",
        ),
    ];
    for (name, node, top, words) in cases {
        let json = quad_json(&buffer(name), "", "", node)
            .replacen(r#""indices": 1}"#, r#""indices": 1, "material": 0}"#, 1)
            .replacen("{\"asset\"", &format!("{{{top} \"asset\""), 1);
        let json = if top.is_empty() {
            json.replacen(r#""meshes""#, r#""materials": [{}], "meshes""#, 1)
        } else {
            json
        };
        let path = write_gltf(&dir, name, &json, &bin);
        let e = load(&path).expect_err(name).to_string();
        assert!(
            e.contains(&format!("{name}.gltf")) && e.contains(words),
            "{name}: {e}"
        );
    }
    // Numbers in extras and in extensions ffvk does not read are other readers' business.
    let json = quad_json(
        &buffer("extras"),
        "",
        r#", "extras": {"big": 1e300}"#,
        r#"{"mesh": 0, "extensions": {"X_other": {"far": 1e300}}}"#,
    );
    load(&write_gltf(&dir, "extras", &json, &bin)).unwrap();
}

/// An accessor that overruns its view because of the view's byteStride says so, and the
/// largest stride that would fit; a packed one says where it ends.
#[test]
fn an_accessor_overrunning_its_view_names_the_byte_stride_that_spaces_it() {
    let dir = scratch("stride");
    let bin = quad_buffer(&[]);
    let buffer = |name: &str| format!(r#"{{"uri": "{name}.bin", "byteLength": {}}}"#, bin.len());
    let strided = quad_json(&buffer("strided"), "", "", r#"{"mesh": 0}"#).replacen(
        r#"{"buffer": 0, "byteLength": 48}"#,
        r#"{"buffer": 0, "byteLength": 48, "byteStride": 16}"#,
        1,
    );
    let e = load(&write_gltf(&dir, "strided", &strided, &bin))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains(
            "accessor 0: 4 elements of 12 bytes, 16 apart (buffer view 0's byteStride), from byte 0 \
             end at byte 60 and overrun buffer view 0 (48 bytes): expected a byteStride of at most 12"
        ),
        "{e}"
    );
    let packed = quad_json(&buffer("packed"), "", r#", "byteOffset": 4"#, r#"{"mesh": 0}"#);
    let e = load(&write_gltf(&dir, "packed", &packed, &bin))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("accessor 0: 4 elements of 12 bytes from byte 4 end at byte 52 and overrun buffer view 0 (48 bytes)"),
        "{e}"
    );
}

/// Values longer than 120 characters are shortened in every message and warning, as the
/// README promises: URIs, extension names, JSON keys in a path.
#[test]
fn values_past_120_characters_are_shortened_in_errors_and_warnings() {
    let dir = scratch("long");
    let bin = quad_buffer(&[]);
    let long = "x".repeat(300);
    let buffer = |name: &str| format!(r#"{{"uri": "{name}.bin", "byteLength": {}}}"#, bin.len());
    let base = quad_json(&buffer("base"), "", "", r#"{"mesh": 0}"#);
    let cases = [
        (
            "required",
            base.replacen(
                "{\"asset\"",
                &format!(
                    "{{\"extensionsRequired\": [\"{long}\"], \"extensionsUsed\": [\"{long}\"], \"asset\""
                ),
                1,
            ),
        ),
        (
            "outside",
            base.replacen("\"uri\": \"base.bin\"", &format!("\"uri\": \"../{long}.bin\""), 1),
        ),
        (
            "missing-file",
            base.replacen("\"uri\": \"base.bin\"", &format!("\"uri\": \"{long}.bin\""), 1),
        ),
        (
            "bad-data-uri",
            base.replacen(
                "\"uri\": \"base.bin\"",
                &format!("\"uri\": \"data:application/octet-stream;base64,{long}!\""),
                1,
            ),
        ),
        (
            "long-key",
            base.replacen(
                "\"version\": \"2.0\"",
                &format!("\"version\": \"2.0\", \"{long}\": 1e39"),
                1,
            ),
        ),
    ];
    for (name, json) in cases {
        let path = write_gltf(&dir, name, &json, &bin);
        let e = load(&path).expect_err(name).to_string();
        assert!(e.contains(&format!("{name}.gltf")), "{name}: {e}");
        assert!(!e.contains(&"x".repeat(121)), "{name}: not shortened: {e}");
        // (A bad data URI's message quotes the decoder, not the URI.)
        assert!(
            name == "bad-data-uri" || e.contains("bytes in all"),
            "{name}: {e}"
        );
    }
    // A used (not required) extension of that name is a warning, shortened too.
    write_gltf(&dir, "base", &base, &bin);
    let used = base.replacen(
        "{\"asset\"",
        &format!("{{\"extensionsUsed\": [\"{long}\"], \"asset\""),
        1,
    );
    let loaded = load(&write_gltf(&dir, "used", &used, &bin)).unwrap();
    assert!(
        loaded.warnings.iter().all(|w| !w.contains(&"x".repeat(121))) && !loaded.warnings.is_empty(),
        "{:?}",
        loaded.warnings
    );
}

/// An accessor (or a sparse substitution) of count 0 made the `gltf` crate's reader compute
/// `count - 1` before ffvk's check ran: a panic with overflow checks (found by the fuzz
/// harness). Now the check runs first and names the accessor.
#[test]
fn accessors_and_sparse_substitutions_of_count_0_are_errors_not_panics() {
    let dir = scratch("count-0");
    let bin = quad_buffer(&[0, 1, 2, 3]);
    let buffer = |name: &str| format!(r#"{{"uri": "{name}.bin", "byteLength": {}}}"#, bin.len());
    let views = r#", {"buffer": 0, "byteOffset": 60, "byteLength": 4}"#;
    let cases = [
        ("count-0", "", "accessor 0: count is 0: expected at least 1"),
        (
            "sparse-count-0",
            r#", "sparse": {"count": 0, "indices": {"bufferView": 2, "componentType": 5121}, "values": {"bufferView": 0}}"#,
            "accessor 0: sparse count is 0: expected 1..=4",
        ),
    ];
    for (name, sparse, words) in cases {
        let mut json = quad_json(&buffer(name), views, sparse, r#"{"mesh": 0}"#);
        if name == "count-0" {
            json = json.replacen(r#""count": 4"#, r#""count": 0"#, 1);
        }
        let path = write_gltf(&dir, name, &json, &bin);
        let e = std::thread::spawn(move || load(&path).map(|_| ()).unwrap_err().to_string())
            .join()
            .expect("no panic");
        assert!(
            e.contains(&format!("{name}.gltf")) && e.contains(words),
            "{name}: {e}"
        );
    }
}

/// glTF allows `extras` of any JSON type; the `gltf` crate reads only objects there and
/// refused the file ("expected struct Void"). ffvk reads no extras: the file loads.
#[test]
fn extras_of_any_json_type_are_allowed() {
    let dir = scratch("extras");
    let bin = quad_buffer(&[]);
    for (name, extras) in [
        ("number", "1e300"),
        ("string", "\"hi\""),
        ("array", "[1, [2], {}]"),
        ("null", "null"),
    ] {
        let buffer = format!(
            r#"{{"uri": "{name}.bin", "byteLength": {}, "extras": {extras}}}"#,
            bin.len()
        );
        let json = quad_json(
            &buffer,
            "",
            &format!(r#", "extras": {extras}"#),
            &format!(r#"{{"mesh": 0, "extras": {extras}}}"#),
        )
        .replacen("{\"asset\"", &format!("{{\"extras\": {extras}, \"asset\""), 1);
        let loaded = load(&write_gltf(&dir, name, &json, &bin));
        assert!(loaded.is_ok(), "{name}: {}", loaded.unwrap_err());
    }
    // What else the crate refuses is still reported with its line and column.
    let json = quad_json(
        r#"{"uri": "x.bin", "byteLength": "sixty"}"#,
        "",
        r#", "extras": 5"#,
        r#"{"mesh": 0}"#,
    );
    let e = load(&write_gltf(&dir, "bad", &json, &bin))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("bad.gltf") && e.contains("line") && e.contains("column"),
        "{e}"
    );
}
