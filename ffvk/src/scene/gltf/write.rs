//! A small glTF 2.0 writer for any [`MeshData`]: one `.gltf` JSON file with the buffer
//! embedded as a base64 data URI (what `ffvk teapot` writes).

use std::io;
use std::path::Path;

use crate::mesh::MeshData;

/// Standard base64 (RFC 4648 alphabet, `=` padding).
fn base64_encode(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let group = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[((group >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// `s` as a JSON string literal.
fn json_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if u32::from(c) < 0x20 => out.push_str(&format!("\\u{:04x}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn invalid(message: String) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidInput, message)
}

/// The glTF 2.0 JSON document for `mesh`, named `name`, with its one buffer embedded as a
/// base64 data URI.
fn gltf_document(mesh: &MeshData, name: &str) -> io::Result<String> {
    let vertex_count = mesh.vertices.len();
    let index_count = mesh.indices.len();
    if vertex_count == 0 || index_count == 0 {
        return Err(invalid(format!(
            "cannot write a glTF mesh with {vertex_count} vertices and {index_count} indices: \
             expected at least one triangle"
        )));
    }
    if mesh.topology != crate::Topology::TriangleList {
        return Err(invalid(format!(
            "cannot write a mesh of {} as glTF: the writer writes triangle lists",
            mesh.topology.gl_name()
        )));
    }
    if !index_count.is_multiple_of(3) {
        return Err(invalid(format!(
            "cannot write a glTF triangle list of {index_count} indices: expected a multiple of 3"
        )));
    }
    if let Some((k, &i)) = mesh
        .indices
        .iter()
        .enumerate()
        .find(|(_, &i)| i as usize >= vertex_count)
    {
        return Err(invalid(format!(
            "index {k} is {i}: expected a value < {vertex_count} (the vertex count)"
        )));
    }
    for (k, v) in mesh.vertices.iter().enumerate() {
        let all = v
            .position
            .iter()
            .chain(&v.normal)
            .chain(&v.color)
            .chain(&v.texcoord);
        if let Some(x) = all.copied().find(|x| !x.is_finite()) {
            return Err(invalid(format!(
                "vertex {k} has the non-finite value {x}: glTF (JSON) needs finite numbers"
            )));
        }
    }

    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    let mut bin = Vec::with_capacity(vertex_count * 48 + index_count * 4);
    for v in &mesh.vertices {
        for k in 0..3 {
            min[k] = min[k].min(v.position[k]);
            max[k] = max[k].max(v.position[k]);
        }
        bin.extend(v.position.iter().flat_map(|x| x.to_le_bytes()));
    }
    for v in &mesh.vertices {
        bin.extend(v.normal.iter().flat_map(|x| x.to_le_bytes()));
    }
    for v in &mesh.vertices {
        bin.extend(v.color.iter().flat_map(|x| x.to_le_bytes()));
    }
    for v in &mesh.vertices {
        bin.extend(v.texcoord.iter().flat_map(|x| x.to_le_bytes()));
    }
    bin.extend(mesh.indices.iter().flat_map(|i| i.to_le_bytes()));

    let (pos_len, nrm_len, col_len, tex_len, idx_len) = (
        12 * vertex_count,
        12 * vertex_count,
        16 * vertex_count,
        8 * vertex_count,
        4 * index_count,
    );
    let nrm_off = pos_len;
    let col_off = nrm_off + nrm_len;
    let tex_off = col_off + col_len;
    let idx_off = tex_off + tex_len;
    let vec3 = |a: [f32; 3]| format!("[{}, {}, {}]", a[0], a[1], a[2]);
    let name = json_string(name);
    Ok(format!(
        r#"{{
  "asset": {{ "version": "2.0", "generator": "ffvk::scene::gltf::write::write_gltf" }},
  "scene": 0,
  "scenes": [ {{ "name": {name}, "nodes": [0] }} ],
  "nodes": [ {{ "name": {name}, "mesh": 0 }} ],
  "meshes": [ {{
    "name": {name},
    "primitives": [ {{
      "attributes": {{ "POSITION": 0, "NORMAL": 1, "COLOR_0": 2, "TEXCOORD_0": 4 }},
      "indices": 3,
      "material": 0,
      "mode": 4
    }} ]
  }} ],
  "materials": [ {{
    "name": "default",
    "pbrMetallicRoughness": {{ "baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0.5 }}
  }} ],
  "accessors": [
    {{ "bufferView": 0, "componentType": 5126, "count": {vertex_count}, "type": "VEC3", "min": {min}, "max": {max} }},
    {{ "bufferView": 1, "componentType": 5126, "count": {vertex_count}, "type": "VEC3" }},
    {{ "bufferView": 2, "componentType": 5126, "count": {vertex_count}, "type": "VEC4" }},
    {{ "bufferView": 3, "componentType": 5125, "count": {index_count}, "type": "SCALAR" }},
    {{ "bufferView": 4, "componentType": 5126, "count": {vertex_count}, "type": "VEC2" }}
  ],
  "bufferViews": [
    {{ "buffer": 0, "byteOffset": 0, "byteLength": {pos_len}, "target": 34962 }},
    {{ "buffer": 0, "byteOffset": {nrm_off}, "byteLength": {nrm_len}, "target": 34962 }},
    {{ "buffer": 0, "byteOffset": {col_off}, "byteLength": {col_len}, "target": 34962 }},
    {{ "buffer": 0, "byteOffset": {idx_off}, "byteLength": {idx_len}, "target": 34963 }},
    {{ "buffer": 0, "byteOffset": {tex_off}, "byteLength": {tex_len}, "target": 34962 }}
  ],
  "buffers": [
    {{ "byteLength": {total}, "uri": "data:application/octet-stream;base64,{data}" }}
  ]
}}
"#,
        min = vec3(min),
        max = vec3(max),
        total = bin.len(),
        data = base64_encode(&bin),
    ))
}

/// Writes `mesh` as a glTF 2.0 `.gltf` JSON file with one embedded (base64 data URI) buffer:
/// one scene with one node holding one mesh of one indexed triangle primitive with POSITION
/// (float VEC3, with the min/max glTF requires), NORMAL (float VEC3), COLOR_0 (float VEC4),
/// TEXCOORD_0 (float VEC2)
/// and UNSIGNED_INT indices, using one default PBR material (white, metallic 0, roughness
/// 0.5). The scene, node and mesh are named after the file stem.
///
/// Errors (`InvalidInput`) on a mesh with no triangles, an index count that is not a
/// multiple of 3, an index out of range or a non-finite vertex value; otherwise any error of
/// writing the file.
pub fn write_gltf(mesh: &MeshData, path: &Path) -> io::Result<()> {
    let name = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "mesh".into());
    let document = gltf_document(mesh, &name)?;
    // Atomically: a failed write leaves the old file, never a partial one.
    crate::files::write_bytes(path, document.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::teapot::teapot;
    use crate::mesh::Vertex;
    use glam::{Vec3, Vec4};
    use std::path::PathBuf;

    fn scratch_dir(test: &str) -> PathBuf {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("..")
            .join("target")
            .join("ffvk-test-gltf-write")
            .join(test);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn base64_matches_rfc_4648_vectors() {
        let cases = [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ];
        for (plain, encoded) in cases {
            assert_eq!(base64_encode(plain.as_bytes()), encoded);
        }
        assert_eq!(base64_encode(&[0xfb, 0xff, 0xbf]), "+/+/");
    }

    #[test]
    fn json_strings_are_escaped() {
        assert_eq!(json_string("a\"b\\c\nd\u{1}"), r#""a\"b\\c\nd\u0001""#);
    }

    #[test]
    fn write_gltf_round_trips_through_the_gltf_crate() {
        let mesh = teapot(3).unwrap();
        let path = scratch_dir("round_trip").join("teapot.gltf");
        write_gltf(&mesh, &path).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(
            text.contains("\"version\": \"2.0\"") && text.contains("data:application/octet-stream;base64,")
        );

        let gltf = gltf::Gltf::open(&path).unwrap();
        let buffers = gltf::import_buffers(&gltf, path.parent(), None).unwrap();
        let primitive = gltf.meshes().next().unwrap().primitives().next().unwrap();
        assert_eq!(primitive.mode(), gltf::mesh::Mode::Triangles);
        let position_accessor = primitive.get(&gltf::Semantic::Positions).unwrap();
        assert!(position_accessor.min().is_some() && position_accessor.max().is_some());
        let reader = primitive.reader(|b| Some(&buffers[b.index()]));
        let positions: Vec<[f32; 3]> = reader.read_positions().unwrap().collect();
        let normals: Vec<[f32; 3]> = reader.read_normals().unwrap().collect();
        let colors: Vec<[f32; 4]> = reader.read_colors(0).unwrap().into_rgba_f32().collect();
        let indices: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
        assert_eq!(indices, mesh.indices);
        assert_eq!(positions.len(), mesh.vertices.len());
        for (k, v) in mesh.vertices.iter().enumerate() {
            assert_eq!(positions[k], v.position);
            assert_eq!(normals[k], v.normal);
            assert_eq!(colors[k], v.color);
        }
        let material = primitive.material();
        assert_eq!(material.index(), Some(0));
        assert_eq!(material.pbr_metallic_roughness().base_color_factor(), [1.0; 4]);
        assert_eq!(
            gltf.default_scene()
                .unwrap()
                .nodes()
                .next()
                .unwrap()
                .mesh()
                .unwrap()
                .index(),
            0
        );
    }

    #[test]
    fn write_gltf_rejects_meshes_gltf_cannot_hold() {
        let dir = scratch_dir("rejects");
        let e = write_gltf(&MeshData::default(), &dir.join("empty.gltf")).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::InvalidInput);
        assert!(e.to_string().contains("0 vertices"), "{e}");

        let v = Vertex::new(Vec3::ZERO, Vec3::Y, Vec4::ONE);
        let bad_index = MeshData::new(vec![v; 3], vec![0, 1, 3]);
        let e = write_gltf(&bad_index, &dir.join("bad_index.gltf")).unwrap_err();
        assert!(
            e.to_string().contains("index 2 is 3") && e.to_string().contains("< 3"),
            "{e}"
        );

        let partial = MeshData::new(vec![v; 3], vec![0, 1]);
        let e = write_gltf(&partial, &dir.join("partial.gltf")).unwrap_err();
        assert!(e.to_string().contains("multiple of 3"), "{e}");

        let mut nan = MeshData::new(vec![v; 3], vec![0, 1, 2]);
        nan.vertices[1].normal[0] = f32::NAN;
        let e = write_gltf(&nan, &dir.join("nan.gltf")).unwrap_err();
        assert!(
            e.to_string().contains("vertex 1") && e.to_string().contains("NaN"),
            "{e}"
        );
    }
}
