//! Reading a file: the JSON (from a `.gltf`, or a `.glb`'s JSON chunk), its validation, its
//! buffers (GLB binary chunk, external `.bin` files, data URIs), and the walk over the node
//! hierarchy that places meshes and lights.

use super::cameras::placed_camera;
use super::lights::punctual_light;
use super::materials::pbr_material;
use super::primitives::{draws_triangles, read_primitive};
use super::rules::{
    accessor_problems, hierarchy_problems, node_matrix, node_transform_problem, unlisted_extensions,
};
use super::{Context, LoadError, LoadErrorKind, Loaded, LoadedMesh};
use crate::scene::{Limits, MeshBudget};
use glam::Mat4;
use gltf::json::Value;
use std::path::Path;

/// A file as parsed: the raw JSON (for names), the `gltf` crate's document, the GLB's binary
/// chunk, and what reading the container skipped.
pub(super) struct Parsed {
    pub raw: Value,
    pub document: gltf::Document,
    pub blob: Option<Vec<u8>>,
    pub warnings: Vec<String>,
}

/// Reads and parses `path`, a `.gltf` (JSON) or `.glb` file, without validating it.
pub(super) fn parse(path: &Path) -> Result<Parsed, LoadError> {
    let error = |kind| LoadError {
        path: path.to_path_buf(),
        kind,
    };
    let bytes = crate::files::read_regular(path, super::MAX_FILE_BYTES)
        .map_err(|source| error(LoadErrorKind::Io { source }))?;
    let parse_error = |message: String| error(LoadErrorKind::Parse { message });
    let mut warnings = Vec::new();
    let (json, blob) = if bytes.starts_with(b"glTF") {
        let glb = split_glb(&bytes).map_err(parse_error)?;
        for (index, kind) in glb.skipped {
            warnings.push(format!(
                "GLB chunk {index} has type {}: not JSON or BIN, skipped (as glTF 2.0 asks of unknown chunks)",
                chunk_type_name(kind)
            ));
        }
        (glb.json, glb.bin.map(<[u8]>::to_vec))
    } else {
        (&bytes[..], None)
    };
    let raw: Value = from_json(json).map_err(parse_error)?;
    let root: gltf::json::Root = match from_json(json) {
        Ok(root) => root,
        // glTF allows `extras` of any JSON type; the crate reads only objects there. ffvk reads
        // no extras, so a file the crate refuses is tried again without them (the first error,
        // which has a line and column, is the one reported if that fails too).
        Err(e) => {
            let mut stripped = raw.clone();
            remove_extras(&mut stripped);
            gltf::json::deserialize::from_value(stripped).map_err(|_| parse_error(e))?
        }
    };
    Ok(Parsed {
        raw,
        document: gltf::Document::from_json_without_validation(root),
        blob,
        warnings,
    })
}

/// `json` read as a `T`, or the error with the JSON path of the value refused before the
/// parser's message (`accessors[0].count: invalid value: integer `-4`, expected u32 at line 5
/// column 20`).
fn from_json<T: serde::de::DeserializeOwned>(json: &[u8]) -> Result<T, String> {
    let mut parser = serde_json::Deserializer::from_slice(json);
    let value: T = serde_path_to_error::deserialize(&mut parser).map_err(|e| {
        let path = e.path().to_string();
        let message = e.inner().to_string();
        match path.as_str() {
            "." | "" => message,
            _ => format!("{}: {message}", crate::scene::shorten(&path)),
        }
    })?;
    // Nothing but white space after the document.
    parser.end().map_err(|e| e.to_string())?;
    Ok(value)
}

/// `value` without any `extras` member, at any depth (iterative: the depth is the file's).
fn remove_extras(value: &mut Value) {
    let mut stack = vec![value];
    while let Some(value) = stack.pop() {
        match value {
            Value::Object(members) => {
                members.remove("extras");
                stack.extend(members.values_mut());
            }
            Value::Array(items) => stack.extend(items.iter_mut()),
            _ => {}
        }
    }
}

/// A GLB file's chunks: the JSON chunk, the binary chunk if there is one, and the index and
/// type of each chunk of another type (which readers skip).
struct GlbChunks<'a> {
    json: &'a [u8],
    bin: Option<&'a [u8]>,
    skipped: Vec<(usize, u32)>,
}

const CHUNK_JSON: u32 = u32::from_le_bytes(*b"JSON");
const CHUNK_BIN: u32 = u32::from_le_bytes(*b"BIN\0");

/// A chunk type as its four bytes read (when printable) and its value.
fn chunk_type_name(kind: u32) -> String {
    let bytes = kind.to_le_bytes();
    if bytes
        .iter()
        .all(|b| b.is_ascii_graphic() || *b == b' ' || *b == 0)
    {
        let text: String = bytes
            .iter()
            .map(|&b| {
                if b == 0 {
                    "\\0".to_owned()
                } else {
                    (b as char).to_string()
                }
            })
            .collect();
        format!("\"{text}\" (0x{kind:08X})")
    } else {
        format!("0x{kind:08X}")
    }
}

/// Splits a GLB file (glTF 2.0, "GLB File Format Specification"): a 12-byte header (magic,
/// version 2, the file's length), then chunks of an 8-byte header (length, type) and their
/// data. The first chunk is JSON; a BIN chunk may only be the second; chunks of other types
/// are skipped. Every length is checked here, before the `gltf` crate is given anything (its
/// reader subtracts the header size from the length unchecked, and refuses unknown chunks).
fn split_glb(bytes: &[u8]) -> Result<GlbChunks<'_>, String> {
    let word = |at: usize| {
        bytes
            .get(at..at + 4)
            .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
    };
    let (Some(version), Some(length)) = (word(4), word(8)) else {
        return Err(format!("a GLB header of {} bytes: expected 12", bytes.len()));
    };
    if version != 2 {
        return Err(format!("GLB version {version}: expected 2"));
    }
    if length as usize != bytes.len() {
        return Err(format!(
            "the GLB header's length is {length}: expected the file's length, {} bytes",
            bytes.len()
        ));
    }
    let mut chunks = GlbChunks {
        json: &[],
        bin: None,
        skipped: Vec::new(),
    };
    let (mut at, mut index) = (12usize, 0usize);
    while at < bytes.len() {
        let (Some(chunk_length), Some(kind)) = (word(at), word(at + 4)) else {
            return Err(format!(
                "chunk {index}: its header at byte {at} is cut short by the end of the file ({} bytes)",
                bytes.len()
            ));
        };
        let start = at + 8;
        let end = start
            .checked_add(chunk_length as usize)
            .filter(|&end| end <= bytes.len())
            .ok_or_else(|| {
                format!(
                    "chunk {index} ({}): its length is {chunk_length}: expected at most the {} bytes \
                     left in the file after its header",
                    chunk_type_name(kind),
                    bytes.len() - start
                )
            })?;
        let data = &bytes[start..end];
        match (index, kind) {
            (0, CHUNK_JSON) => chunks.json = data,
            (0, _) => {
                return Err(format!(
                    "chunk 0 has type {}: expected \"JSON\" (0x{CHUNK_JSON:08X}), the JSON chunk first",
                    chunk_type_name(kind)
                ))
            }
            (1, CHUNK_BIN) => chunks.bin = Some(data),
            (_, CHUNK_JSON | CHUNK_BIN) => {
                return Err(format!(
                    "chunk {index} has type {}: expected one JSON chunk, first, and at most one BIN \
                     chunk, second",
                    chunk_type_name(kind)
                ))
            }
            _ => chunks.skipped.push((index, kind)),
        }
        // Chunks start on 4-byte boundaries; a writer that left out the padding of the last
        // chunk still ends at the file's end.
        at = end.next_multiple_of(4);
        index += 1;
    }
    if index == 0 {
        return Err("no JSON chunk after the 12-byte GLB header: expected one".to_owned());
    }
    Ok(chunks)
}

/// Runs the `gltf` crate's validator, then checks what it lets through and glTF 2.0 forbids
/// (see below); what they find makes the error. Extensions used but not listed, which ffvk
/// does not read, are a warning.
pub(super) fn validate(
    cx: &Context,
    document: &gltf::Document,
    warnings: &mut Vec<String>,
) -> Result<(), LoadError> {
    use gltf::json::validation::Validate;
    let root = document.as_json();
    let mut problems = super::values::out_of_range_numbers(cx.raw);
    root.validate(root, gltf::json::Path::new, &mut |path, error| {
        // extensionsRequired was checked before, against what ffvk supports or may ignore
        // (the crate knows only the extensions it parses).
        if error != gltf::json::validation::Error::Unsupported {
            problems.push(format!("{}: {error}", path()));
        }
    });
    // The crate's image accessors unwrap these (gltf 1.4, image.rs): an image must name
    // exactly one source, and an image in a bufferView its mimeType (glTF 2.0, 5.17).
    for (index, image) in root.images.iter().enumerate() {
        match (&image.uri, &image.buffer_view, &image.mime_type) {
            (Some(_), None, _) | (None, Some(_), Some(_)) => {}
            (None, None, _) => problems.push(format!(
                "images[{index}]: neither uri nor bufferView: expected one of them"
            )),
            (Some(_), Some(_), _) => problems.push(format!(
                "images[{index}]: both uri and bufferView: expected one of them"
            )),
            (None, Some(_), None) => problems.push(format!(
                "images[{index}].mimeType: missing: expected \"image/png\" or \"image/jpeg\" for an image in a bufferView"
            )),
        }
    }
    // What the crate's validator lets through and the specification forbids (glTF 2.0: a
    // buffer's byteLength ≥ 1, a vertex bufferView's byteStride a multiple of 4, a node's
    // rotation a unit quaternion; a zero one has no rotation to take).
    for (index, buffer) in root.buffers.iter().enumerate() {
        if buffer.byte_length.0 == 0 {
            problems.push(format!("buffers[{index}].byteLength: 0: expected at least 1"));
        }
    }
    for (index, view) in root.buffer_views.iter().enumerate() {
        if let Some(stride) = view.byte_stride {
            if stride.0 % 4 != 0 {
                problems.push(format!(
                    "bufferViews[{index}].byteStride: {}: expected a multiple of 4",
                    stride.0
                ));
            }
        }
    }
    for (index, node) in root.nodes.iter().enumerate() {
        problems.extend(node_transform_problem(index, node));
    }
    problems.extend(accessor_problems(root));
    let (unlisted, others) = unlisted_extensions(cx.raw);
    problems.extend(unlisted);
    if !others.is_empty() {
        let names: Vec<String> = others.iter().take(8).map(|n| crate::scene::shorten(n)).collect();
        warnings.push(format!(
            "the file uses extension{} {}{} without listing {} in extensionsUsed, as glTF 2.0 \
             asks: ffvk does not read {}, so {} ignored",
            if others.len() == 1 { "" } else { "s" },
            names.join(", "),
            if others.len() > 8 {
                format!(" and {} more", others.len() - 8)
            } else {
                String::new()
            },
            if others.len() == 1 { "it" } else { "them" },
            if others.len() == 1 { "it" } else { "them" },
            if others.len() == 1 { "it is" } else { "they are" },
        ));
    }
    if problems.is_empty() {
        // Only a hierarchy whose indices are all valid can be judged a forest.
        problems.extend(hierarchy_problems(root));
    }
    if problems.is_empty() {
        return Ok(());
    }
    Err(cx.error(LoadErrorKind::Invalid { problems }))
}

/// Loads every buffer (at least its byteLength), external files relative to the glTF file
/// (or inside `limits.asset_roots`), all of them together within `limits.buffer_bytes`.
pub(super) fn read_buffers(
    cx: &Context,
    document: &gltf::Document,
    mut blob: Option<Vec<u8>>,
    limits: &Limits,
) -> Result<Vec<gltf::buffer::Data>, LoadError> {
    let roots = &limits.asset_roots[..];
    let base = cx.path.parent().unwrap_or(Path::new(""));
    let mut buffers = Vec::new();
    let mut used = 0u64;
    // Takes `bytes` for buffer `index` within the limit, or says why not.
    let mut charge = |index: usize, what: &'static str, bytes: u64| {
        let total = used.saturating_add(bytes);
        if total > limits.buffer_bytes {
            return Err(cx.error(LoadErrorKind::BufferBudget {
                buffer: index,
                what,
                bytes,
                used,
                limit: limits.buffer_bytes,
            }));
        }
        used = total;
        Ok(())
    };
    for buffer in document.buffers() {
        let index = buffer.index();
        let message = |message: String| LoadErrorKind::Buffer {
            buffer: index,
            message,
        };
        if let Some(len) = super::meshopt::fallback_len(cx, index) {
            // Zeros, which the compressed views are decoded into (meshopt::decode); no file
            // bounds them, so they are charged before they are allocated, and allocated
            // fallibly.
            charge(index, "a meshopt fallback buffer", len)?;
            let len = usize::try_from(len).unwrap_or(usize::MAX);
            let mut zeros = crate::alloc::try_vec(len, "a meshopt fallback buffer").map_err(|source| {
                cx.error(LoadErrorKind::BufferAlloc {
                    buffer: index,
                    source,
                })
            })?;
            zeros.resize(len, 0);
            buffers.push(gltf::buffer::Data(zeros));
            continue;
        }
        if let gltf::buffer::Source::Uri(uri) = buffer.source() {
            if !uri.starts_with("data:") {
                if super::uris::percent_decode(uri).is_none() {
                    return Err(cx.error(message(format!(
                        "the URI {:?} is not valid percent-encoding: expected %XX escapes that \
                         decode to UTF-8",
                        crate::scene::shorten(uri)
                    ))));
                }
                let file = super::uris::asset_file(base, uri, roots).ok_or_else(|| {
                    cx.error(LoadErrorKind::BufferOutside {
                        buffer: index,
                        uri: crate::scene::shorten(uri),
                        folder: base.to_path_buf(),
                    })
                })?;
                // Charged at the size the file has before it is read (one whose size cannot
                // be had fails to be read, below, with the reason).
                if let Ok(meta) = std::fs::metadata(&file) {
                    charge(index, "its file", meta.len().next_multiple_of(4))?;
                }
                let mut bytes =
                    crate::files::read_regular(&file, super::MAX_FILE_BYTES).map_err(|source| {
                        cx.error(LoadErrorKind::BufferFile {
                            buffer: index,
                            file: file.clone(),
                            source,
                        })
                    })?;
                while bytes.len() % 4 != 0 {
                    bytes.push(0);
                }
                if bytes.len() < buffer.length() {
                    return Err(cx.error(LoadErrorKind::BufferLength {
                        buffer: index,
                        len: bytes.len(),
                        byte_length: buffer.length(),
                    }));
                }
                buffers.push(gltf::buffer::Data(bytes));
                continue;
            }
        }
        // data: URIs and the GLB chunk; no file is read here.
        let data =
            gltf::buffer::Data::from_source_and_blob(buffer.source(), None, &mut blob).map_err(|e| {
                cx.error(match (buffer.source(), e) {
                    (gltf::buffer::Source::Uri(uri), gltf::Error::Io(source)) => LoadErrorKind::BufferFile {
                        buffer: index,
                        file: base.join(uri),
                        source,
                    },
                    (gltf::buffer::Source::Bin, gltf::Error::MissingBlob) => {
                        LoadErrorKind::MissingBinChunk { buffer: index }
                    }
                    (gltf::buffer::Source::Uri(uri), e) if uri.starts_with("data:") => {
                        message(format!("bad data URI: {e}"))
                    }
                    (gltf::buffer::Source::Uri(uri), e) => {
                        message(format!("cannot load {:?}: {e}", crate::scene::shorten(uri)))
                    }
                    (gltf::buffer::Source::Bin, e) => message(e.to_string()),
                })
            })?;
        // Already in memory (a data URI is part of the JSON, the chunk part of the GLB), and
        // counted with the rest.
        let what = match buffer.source() {
            gltf::buffer::Source::Bin => "the GLB binary chunk",
            gltf::buffer::Source::Uri(_) => "its data URI",
        };
        charge(index, what, data.len() as u64)?;
        if data.len() < buffer.length() {
            return Err(cx.error(LoadErrorKind::BufferLength {
                buffer: index,
                len: data.len(),
                byte_length: buffer.length(),
            }));
        }
        buffers.push(data);
    }
    Ok(buffers)
}

/// Walks the default scene (or the first scene; or, in a file with no scene, every root node,
/// with a warning) into `out`.
pub(super) fn walk(
    cx: &Context,
    document: &gltf::Document,
    buffers: &[gltf::buffer::Data],
    (limits, textures): (&Limits, super::Textures),
    budget: &mut MeshBudget,
    out: &mut Loaded,
) -> Result<(), LoadError> {
    let mut roots: Vec<gltf::Node> = Vec::new();
    if let Some(scene) = document.default_scene().or_else(|| document.scenes().next()) {
        roots.extend(scene.nodes());
    } else if document.nodes().len() > 0 {
        let mut is_child = vec![false; document.nodes().len()];
        for node in document.nodes() {
            node.children().for_each(|c| is_child[c.index()] = true);
        }
        roots.extend(document.nodes().filter(|n| !is_child[n.index()]));
        out.warnings
            .push("the file has no scene: loaded every root node".to_owned());
    }
    let mut path = NodePath {
        on_path: vec![false; document.nodes().len()],
        names: Vec::new(),
    };
    for root in roots {
        visit(cx, buffers, root, &mut path, (limits, textures), budget, out)?;
    }
    Ok(())
}

/// The nodes from the walk's root down to the current one: marked in `on_path` (by index),
/// named in `names` (root first).
struct NodePath {
    on_path: Vec<bool>,
    names: Vec<String>,
}

/// One step of the walk: enter a node under its parent's world transform, or leave one.
enum Step<'a> {
    Enter(gltf::Node<'a>, Mat4),
    Leave(usize),
}

/// Places `root`'s meshes and light, then its descendants', depth first in the file's order.
/// `on_path` marks the nodes from the root down to the current one, whose names are in
/// `names`: a node met again on its own path is a cycle. An explicit stack, not recursion, so
/// that a chain of any depth cannot overflow the thread's stack.
fn visit(
    cx: &Context,
    buffers: &[gltf::buffer::Data],
    root: gltf::Node,
    path: &mut NodePath,
    (limits, textures): (&Limits, super::Textures),
    budget: &mut MeshBudget,
    out: &mut Loaded,
) -> Result<(), LoadError> {
    let NodePath { on_path, names } = path;
    let mut stack = vec![Step::Enter(root, Mat4::IDENTITY)];
    while let Some(step) = stack.pop() {
        let (node, parent) = match step {
            Step::Leave(index) => {
                names.pop();
                on_path[index] = false;
                continue;
            }
            Step::Enter(node, parent) => (node, parent),
        };
        let index = node.index();
        if on_path[index] {
            return Err(cx.error(LoadErrorKind::NodeCycle { node: index }));
        }
        on_path[index] = true;
        names.push(cx.name("nodes", index).unwrap_or_else(|| format!("node {index}")));
        let world = parent * node_matrix(&node);
        if !world.is_finite() {
            // Each number is within float32's range (validated); their product is not.
            return Err(cx.error(LoadErrorKind::Invalid {
                problems: vec![format!(
                    "nodes[{index}] ({:?}, {} deep): its world transform (its ancestors' \
                     transforms times its own) overflows float32: expected transforms whose \
                     product is finite",
                    crate::scene::shorten(names.last().map_or("", String::as_str)),
                    names.len()
                )],
            }));
        }

        if let Some(mesh) = node.mesh() {
            let m = mesh.index();
            let base_name = cx.name("meshes", m).unwrap_or_else(|| format!("mesh {m}"));
            let several = mesh.primitives().len() > 1;
            let mirrored = world.determinant() < 0.0;
            for primitive in mesh.primitives() {
                let p = primitive.index();
                // Counted by the nodes on its path, whose names it keeps: on a deep chain of
                // nodes that each place a mesh, those copies grow as the square of the depth.
                let depth = names.len() as u64;
                budget
                    .charge_placement(depth, limits.placements)
                    .map_err(|made| {
                        cx.error(LoadErrorKind::Placements {
                            node: index,
                            primitive: cx.primitive_label(m, p),
                            depth,
                            made,
                            limit: limits.placements,
                        })
                    })?;
                if primitive.morph_targets().len() > 0 {
                    out.warnings
                        .push(format!("{}: morph targets are ignored", cx.primitive_label(m, p)));
                }
                // TEXCOORD_1 is read where an occlusion texture sampled from it needs it.
                let second_set = textures == super::Textures::Means
                    && super::occlusion::coordinate_set(cx, &primitive.material()) == Some(1)
                    && primitive.get(&gltf::Semantic::TexCoords(1)).is_some();
                let data = read_primitive(
                    cx,
                    buffers,
                    m,
                    &primitive,
                    (mirrored, second_set),
                    budget,
                    &mut out.warnings,
                )?;
                let material = pbr_material(cx, primitive.material());
                out.meshes.push(LoadedMesh {
                    name: if several {
                        format!("{base_name}[{p}]")
                    } else {
                        base_name.clone()
                    },
                    data,
                    transform: world,
                    node_path: names.clone(),
                    material,
                    vertex_colors: primitive.get(&gltf::Semantic::Colors(0)).is_some(),
                    texcoords: primitive.get(&gltf::Semantic::TexCoords(0)).is_some(),
                    // glTF: points and lines without normals are drawn unlit.
                    lit: draws_triangles(primitive.mode())
                        || primitive.get(&gltf::Semantic::Normals).is_some(),
                });
            }
        }
        if node.skin().is_some() {
            out.warnings.push(format!("node {index}: skinning is ignored"));
        }
        if let Some(light) = node.light() {
            out.lights.push(punctual_light(cx, light, world));
        }
        if let Some(camera) = node.camera() {
            match placed_camera(cx, camera, world) {
                Ok(camera) => out.cameras.push(camera),
                Err(why) => out.warnings.push(why),
            }
        }
        stack.push(Step::Leave(index));
        let children: Vec<gltf::Node> = node.children().collect();
        stack.extend(children.into_iter().rev().map(|c| Step::Enter(c, world)));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::scene::gltf::testing::{message, one_mesh_body, scratch_dir, Asset, QUAD};
    use crate::scene::gltf::{load, LoadErrorKind};
    use glam::{Mat4, Vec3, Vec4};

    #[test]
    fn glb_with_bin_chunk_loads() {
        let dir = scratch_dir("glb");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD);
        let idx = a.u16s(&[0, 1, 2, 0, 2, 3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "indices": {idx}, "material": 0 }}"#
        )) + r#""materials": [ { "name": "red", "pbrMetallicRoughness": { "baseColorFactor": [1, 0, 0, 0.5],
                "metallicFactor": 0.25, "roughnessFactor": 0.75 }, "emissiveFactor": [0, 1, 0],
                "doubleSided": true } ],"#;
        let loaded = load(&a.write_glb(&dir, "quad", &body)).unwrap();
        let m = &loaded.meshes[0];
        assert_eq!(m.data.triangle_count(), 2);
        assert_eq!(m.data.vertices.len(), 6);
        let material = m.material.as_ref().unwrap();
        assert_eq!(material.name.as_deref(), Some("red"));
        assert_eq!(material.base_color_factor, Vec4::new(1.0, 0.0, 0.0, 0.5));
        assert_eq!(
            (material.metallic_factor, material.roughness_factor),
            (0.25, 0.75)
        );
        assert_eq!(material.emissive_factor, Vec3::Y);
        assert!(material.double_sided);
    }

    #[test]
    fn node_hierarchy_composes_parent_times_local_in_the_default_scene() {
        let dir = scratch_dir("hierarchy");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let s = std::f32::consts::FRAC_1_SQRT_2;
        let body = format!(
            r#""scene": 1,
               "scenes": [ {{ "nodes": [3] }}, {{ "nodes": [0] }} ],
               "nodes": [
                 {{ "name": "parent", "translation": [1, 2, 3], "children": [1] }},
                 {{ "name": "child", "scale": [2, 2, 2], "rotation": [0, {s}, 0, {s}], "children": [2], "mesh": 0 }},
                 {{ "name": "grandchild", "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1], "mesh": 1 }},
                 {{ "name": "other scene", "mesh": 0 }}
               ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }}, {{ "attributes": {{ "POSITION": {pos} }} }} ] }},
                           {{ "name": "leaf", "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],"#
        );
        let loaded = load(&a.write_gltf(&dir, "hierarchy", &body)).unwrap();
        let names: Vec<&str> = loaded.meshes.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["mesh 0[0]", "mesh 0[1]", "leaf"]);
        let parent = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0));
        let child = Mat4::from_scale_rotation_translation(
            Vec3::splat(2.0),
            glam::Quat::from_xyzw(0.0, s, 0.0, s),
            Vec3::ZERO,
        );
        let grandchild = Mat4::from_translation(Vec3::new(0.0, 0.0, 5.0));
        assert!(loaded.meshes[0].transform.abs_diff_eq(parent * child, 1e-6));
        assert!(loaded.meshes[2]
            .transform
            .abs_diff_eq(parent * child * grandchild, 1e-5));
        // (0,0,5) in the child's frame: rotated +90° about y to (5,0,0), scaled by 2, moved.
        let origin = loaded.meshes[2].transform.transform_point3(Vec3::ZERO);
        assert!(origin.abs_diff_eq(Vec3::new(11.0, 2.0, 3.0), 1e-4), "{origin}");
    }

    #[test]
    fn a_file_without_scenes_loads_its_root_nodes_with_a_warning() {
        let dir = scratch_dir("no_scene");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = format!(
            r#""nodes": [ {{ "children": [1] }}, {{ "mesh": 0, "translation": [0, 1, 0] }}, {{ "mesh": 0 }} ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],"#
        );
        let loaded = load(&a.write_gltf(&dir, "no_scene", &body)).unwrap();
        assert_eq!(
            loaded.meshes.len(),
            2,
            "node 1 once, as node 0's child, and node 2"
        );
        assert!(
            loaded.warnings.iter().any(|w| w.contains("no scene")),
            "{:?}",
            loaded.warnings
        );
    }

    #[test]
    fn file_buffer_and_json_errors_name_the_file() {
        let dir = scratch_dir("io");
        let e = message(load(&dir.join("nope.gltf")).unwrap_err());
        assert!(e.contains("nope.gltf") && e.contains("cannot read"), "{e}");

        let bad = dir.join("bad.gltf");
        std::fs::write(&bad, "{ not json").unwrap();
        let e = message(load(&bad).unwrap_err());
        assert!(e.contains("bad.gltf") && e.contains("not a glTF 2.0 file"), "{e}");

        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = one_mesh_body(&format!(r#"{{ "attributes": {{ "POSITION": {pos} }} }}"#));
        let path = a.write_gltf(&dir, "lost_bin", &body);
        std::fs::remove_file(dir.join("lost_bin.bin")).unwrap();
        let e = load(&path).unwrap_err();
        assert!(matches!(e.kind, LoadErrorKind::BufferFile { buffer: 0, .. }));
        let e = message(e);
        assert!(
            e.contains("lost_bin.gltf: buffer 0: cannot read") && e.contains("lost_bin.bin"),
            "{e}"
        );

        // A buffer shorter than its byteLength.
        let short = dir.join("short.gltf");
        std::fs::write(dir.join("short.bin"), [0u8; 8]).unwrap();
        std::fs::write(&short, a.json(&body, Some("short.bin"))).unwrap();
        let e = message(load(&short).unwrap_err());
        assert!(e.contains("buffer 0: holds 8 bytes: expected at least 36"), "{e}");

        // Schema problems go through the gltf crate's validator.
        let invalid = dir.join("invalid.gltf");
        let body = one_mesh_body(r#"{ "attributes": { "POSITION": 9 } }"#);
        std::fs::write(&invalid, a.json(&body, Some("lost_bin.bin"))).unwrap();
        let e = message(load(&invalid).unwrap_err());
        assert!(
            e.contains("invalid.gltf: invalid glTF") && e.contains("POSITION names accessor 9"),
            "{e}"
        );
        let body = one_mesh_body(r#"{ "attributes": { "POSITION": 0, "NORMAL": 9 } }"#);
        std::fs::write(&invalid, a.json(&body, Some("lost_bin.bin"))).unwrap();
        let e = message(load(&invalid).unwrap_err());
        assert!(
            e.contains("invalid.gltf: invalid glTF") && e.contains("NORMAL"),
            "{e}"
        );
    }

    #[test]
    fn node_cycles_are_an_error() {
        let dir = scratch_dir("cycle");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = format!(
            r#""scene": 0, "scenes": [ {{ "nodes": [0] }} ],
               "nodes": [ {{ "children": [1] }}, {{ "children": [0], "mesh": 0 }} ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],"#
        );
        let e = message(load(&a.write_gltf(&dir, "cycle", &body)).unwrap_err());
        assert!(
            e.contains("cycle.gltf") && e.contains("node 0 is its own ancestor"),
            "{e}"
        );
    }
}
