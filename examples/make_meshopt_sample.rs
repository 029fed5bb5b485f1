//! Writes `assets/gltf/meshopt.glb`: `assets/gltf/quantized_plain.gltf` (from
//! scripts/make_gltf_samples.py) with every bufferView compressed by meshoptimizer's encoder
//! as EXT_meshopt_compression asks, the way gltfpack's `-c` does: the compressed bytes in the
//! GLB's binary chunk, the views pointing into a fallback buffer with no data. It covers the
//! extension's three modes and three of its filters:
//!
//! - positions and texture coordinates: ATTRIBUTES, no filter (floats, vertex codec version 0);
//! - the ball's normals: ATTRIBUTES with the OCTAHEDRAL filter, 16-bit (normalized SHORT, four
//!   components with a stride of 8, so the file requires KHR_mesh_quantization);
//! - the box's normals: ATTRIBUTES with the EXPONENTIAL filter (floats again once decoded);
//! - the ball's indices: TRIANGLES; the box's: INDICES.
//!
//! `cargo run --example make_meshopt_sample` rewrites the file; the test
//! `a_meshopt_compressed_model_draws_within_the_default_tolerance_of_its_plain_version` draws
//! it against the plain model.

use serde_json::{json, Value};
use std::error::Error;
use std::path::Path;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

fn main() -> Result<()> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/gltf");
    let plain: Value = serde_json::from_slice(&std::fs::read(root.join("quantized_plain.gltf"))?)?;
    let uri = plain["buffers"][0]["uri"]
        .as_str()
        .ok_or("buffers[0].uri: missing")?;
    let data = base64_decode(uri.split_once(',').ok_or("buffers[0].uri: not a data URI")?.1)?;
    let mut doc = plain.clone();
    doc["asset"]["generator"] = json!("ffvk examples/make_meshopt_sample.rs");

    // Which accessor reads each view, and in which role.
    let views = plain["bufferViews"].as_array().ok_or("bufferViews: missing")?;
    let accessors = plain["accessors"].as_array().ok_or("accessors: missing")?;
    let mut role = vec![String::new(); views.len()];
    for (m, mesh) in plain["meshes"]
        .as_array()
        .ok_or("meshes: missing")?
        .iter()
        .enumerate()
    {
        let primitive = &mesh["primitives"][0];
        for (name, a) in primitive["attributes"].as_object().ok_or("attributes: missing")? {
            let view = accessors[a.as_u64().ok_or("attribute: not an index")? as usize]["bufferView"]
                .as_u64()
                .ok_or("accessor without a view")?;
            role[view as usize] = format!("{m}:{name}");
        }
        let i = primitive["indices"].as_u64().ok_or("indices: missing")? as usize;
        role[accessors[i]["bufferView"]
            .as_u64()
            .ok_or("accessor without a view")? as usize] = format!("{m}:indices");
    }

    let mut bin = Vec::new();
    let mut fallback = 0usize;
    let mut new_views = Vec::new();
    for (v, view) in views.iter().enumerate() {
        let offset = view["byteOffset"].as_u64().unwrap_or(0) as usize;
        let length = view["byteLength"].as_u64().ok_or("byteLength: missing")? as usize;
        let bytes = &data[offset..offset + length];
        let floats: Vec<f32> = bytes
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect();
        let (encoded, count, stride, mode, filter) = match role[v].as_str() {
            "0:NORMAL" => {
                // Octahedral 16-bit: the accessor becomes normalized SHORT VEC3 in a stride of 8.
                let n: Vec<[f32; 4]> = floats.chunks_exact(3).map(|c| [c[0], c[1], c[2], 0.0]).collect();
                let oct: Vec<[i16; 4]> = meshopt::encoding::encode_filter_oct(&n, 16);
                for a in doc["accessors"].as_array_mut().ok_or("accessors")? {
                    if a["bufferView"] == json!(v) {
                        a["componentType"] = json!(5122);
                        a["normalized"] = json!(true);
                    }
                }
                (encode(&oct)?, n.len(), 8, "ATTRIBUTES", Some("OCTAHEDRAL"))
            }
            "1:NORMAL" => {
                let n: Vec<[f32; 3]> = floats.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
                let exp = meshopt::encoding::encode_filter_exp(
                    &n,
                    15,
                    meshopt::encoding::EncodeExpMode::SharedVector,
                );
                (encode(&exp)?, n.len(), 12, "ATTRIBUTES", Some("EXPONENTIAL"))
            }
            r if r.ends_with(":indices") => {
                let i: Vec<u32> = bytes
                    .chunks_exact(2)
                    .map(|c| u32::from(u16::from_le_bytes([c[0], c[1]])))
                    .collect();
                let vertices = i.iter().max().map_or(0, |&m| m as usize + 1);
                if r == "0:indices" {
                    (
                        meshopt::encoding::encode_index_buffer(&i, vertices)?,
                        i.len(),
                        2,
                        "TRIANGLES",
                        None,
                    )
                } else {
                    (
                        meshopt::encoding::encode_index_sequence(&i, vertices)?,
                        i.len(),
                        2,
                        "INDICES",
                        None,
                    )
                }
            }
            r if r.ends_with(":POSITION") => {
                let p: Vec<[f32; 3]> = floats.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
                (encode(&p)?, p.len(), 12, "ATTRIBUTES", None)
            }
            r if r.ends_with(":TEXCOORD_0") => {
                let t: Vec<[f32; 2]> = floats.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
                (encode(&t)?, t.len(), 8, "ATTRIBUTES", None)
            }
            other => {
                return Err(format!(
                    "bufferViews[{v}]: read as {other:?}, which this generator does not know"
                )
                .into())
            }
        };
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        let mut ext = json!({ "buffer": 0, "byteOffset": bin.len(), "byteLength": encoded.len(),
                              "byteStride": stride, "count": count, "mode": mode });
        if let Some(f) = filter {
            ext["filter"] = json!(f);
        }
        bin.extend_from_slice(&encoded);
        let mut new = json!({ "buffer": 1, "byteOffset": fallback, "byteLength": count * stride,
                              "extensions": { "EXT_meshopt_compression": ext } });
        if mode == "ATTRIBUTES" {
            new["byteStride"] = json!(stride);
            new["target"] = json!(34962);
        } else {
            new["target"] = json!(34963);
        }
        fallback += (count * stride).next_multiple_of(4);
        new_views.push(new);
    }
    doc["bufferViews"] = json!(new_views);
    doc["buffers"] = json!([
        { "byteLength": bin.len() },
        { "byteLength": fallback, "extensions": { "EXT_meshopt_compression": { "fallback": true } } }
    ]);
    doc["extensionsUsed"] = json!(["EXT_meshopt_compression", "KHR_mesh_quantization"]);
    doc["extensionsRequired"] = json!(["EXT_meshopt_compression", "KHR_mesh_quantization"]);

    let out = root.join("meshopt.glb");
    std::fs::write(&out, glb(&serde_json::to_vec(&doc)?, &bin))?;
    println!(
        "wrote {} ({} bytes of compressed geometry for {} plain)",
        out.display(),
        bin.len(),
        data.len()
    );
    Ok(())
}

/// Vertex codec version 0, the one EXT_meshopt_compression allows (version 1 is
/// KHR_meshopt_compression's).
fn encode<T>(v: &[T]) -> Result<Vec<u8>> {
    Ok(meshopt::encoding::encode_vertex_buffer_level(v, 2, Some(0))?)
}

/// A GLB container: the JSON chunk (padded with spaces) and the binary chunk (with zeros).
fn glb(json: &[u8], bin: &[u8]) -> Vec<u8> {
    let pad = |b: &[u8], with: u8| {
        let mut v = b.to_vec();
        v.resize(b.len().next_multiple_of(4), with);
        v
    };
    let (json, bin) = (pad(json, b' '), pad(bin, 0));
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    for word in [0x4654_6C67, 2, total as u32, json.len() as u32, 0x4E4F_534A] {
        out.extend_from_slice(&u32::to_le_bytes(word));
    }
    out.extend_from_slice(&json);
    for word in [bin.len() as u32, 0x004E_4942] {
        out.extend_from_slice(&u32::to_le_bytes(word));
    }
    out.extend_from_slice(&bin);
    out
}

/// Standard base64 (RFC 4648, with padding), as the generator writes data URIs.
fn base64_decode(text: &str) -> Result<Vec<u8>> {
    let value = |c: u8| -> Result<u32> {
        Ok(match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return Err(format!("base64: {:?}: expected A-Z, a-z, 0-9, + or /", c as char).into()),
        } as u32)
    };
    let text = text.trim_end_matches('=').as_bytes();
    let mut out = Vec::with_capacity(text.len() * 3 / 4);
    for chunk in text.chunks(4) {
        let mut n = 0u32;
        for (i, &c) in chunk.iter().enumerate() {
            n |= value(c)? << (18 - 6 * i);
        }
        out.extend_from_slice(&n.to_be_bytes()[1..chunk.len()]);
    }
    Ok(out)
}
