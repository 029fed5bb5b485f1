//! EXT_meshopt_compression and KHR_meshopt_compression: bufferViews whose bytes are stored
//! compressed in another buffer (gltfpack's `-c`). Each compressed view is decoded with
//! meshoptimizer's own decoder (the `meshopt` crate) into the place the view describes, in
//! the buffer the view names; that buffer is often a *fallback* buffer with no data of its
//! own (its extension says `"fallback": true`), which [`fallback_len`] lets the reader
//! allocate. After decoding, accessors read the views as they would uncompressed ones.
//!
//! Both extensions share the JSON and the codecs; KHR_meshopt_compression adds the vertex
//! codec's version 1 and the COLOR filter, which the decoder reads too.

use super::{Context, LoadError, LoadErrorKind};
use gltf::json::Value;

/// The two extensions' names.
pub(super) const EXTENSIONS: [&str; 2] = ["EXT_meshopt_compression", "KHR_meshopt_compression"];

/// The extension object named `name` in `object`'s `extensions`, with its name.
fn extension(object: &Value) -> Option<(&'static str, &Value)> {
    let extensions = object.get("extensions")?;
    EXTENSIONS
        .into_iter()
        .find_map(|name| Some((name, extensions.get(name)?)))
}

/// Buffer `index`'s byteLength when it is a meshopt fallback buffer that only compressed
/// views read: its bytes are whatever those views decode to, so the reader allocates zeros
/// and reads nothing, not even the file its URI names (gltfpack's `-cf` writes one for
/// loaders without the extension; it need not be there).
pub(super) fn fallback_len(cx: &Context, index: usize) -> Option<u64> {
    let buffer = cx.raw.get("buffers")?.get(index)?;
    let (_, ext) = extension(buffer)?;
    if ext.get("fallback").and_then(Value::as_bool) != Some(true) {
        return None;
    }
    let views = cx.raw.get("bufferViews").and_then(Value::as_array);
    let plain_reader = views.into_iter().flatten().any(|view| {
        view.get("buffer").and_then(Value::as_u64) == Some(index as u64) && extension(view).is_none()
    });
    match plain_reader {
        // A view reads the buffer as it is: its data must be loaded.
        true => None,
        false => buffer.get("byteLength")?.as_u64(),
    }
}

/// How a view's bytes were encoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Attributes,
    Triangles,
    Indices,
}

/// What [`Mode::Attributes`] data goes through after decoding.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Filter {
    None,
    Octahedral,
    Quaternion,
    Exponential,
    Color,
}

/// One compressed view's extension object, checked.
struct Compressed {
    /// The buffer and byte range holding the compressed bytes.
    source: (usize, usize, usize),
    stride: usize,
    count: usize,
    mode: Mode,
    filter: Filter,
}

/// Decodes every compressed bufferView into its place in `buffers`.
pub(super) fn decode(cx: &Context, buffers: &mut [gltf::buffer::Data]) -> Result<(), LoadError> {
    let Some(views) = cx.raw.get("bufferViews").and_then(Value::as_array) else {
        return Ok(());
    };
    for (index, view) in views.iter().enumerate() {
        let Some((name, ext)) = extension(view) else {
            continue;
        };
        let fail = |problem: String| {
            cx.error(LoadErrorKind::Meshopt {
                view: index,
                extension: name,
                problem,
            })
        };
        let c = parse(ext, buffers).map_err(fail)?;
        let bytes = c
            .count
            .checked_mul(c.stride)
            .filter(|&n| n as u64 <= super::MAX_FILE_BYTES);
        let Some(bytes) = bytes else {
            return Err(fail(format!(
                "count {} × byteStride {}: expected at most {} bytes decoded",
                c.count,
                c.stride,
                super::MAX_FILE_BYTES
            )));
        };
        // Where the decoded bytes go: the view's own buffer and range (the validator has
        // checked that range lies in the buffer's byteLength, which the reader has loaded).
        let target = view.get("buffer").and_then(Value::as_u64).unwrap_or(u64::MAX) as usize;
        let offset = view.get("byteOffset").and_then(Value::as_u64).unwrap_or(0) as usize;
        let length = view.get("byteLength").and_then(Value::as_u64).unwrap_or(0) as usize;
        if bytes > length {
            return Err(fail(format!(
                "count {} × byteStride {} = {bytes} bytes: expected at most the view's byteLength {length}",
                c.count, c.stride
            )));
        }
        let (buffer, start, len) = c.source;
        let encoded = &buffers[buffer].0[start..start + len];
        let decoded = run(&c, encoded, bytes).map_err(fail)?;
        let end = offset.saturating_add(bytes);
        let Some(out) = buffers.get_mut(target).and_then(|b| b.0.get_mut(offset..end)) else {
            return Err(fail(format!(
                "the view's byteOffset {offset} + {bytes} decoded bytes: expected a range inside buffer {target}"
            )));
        };
        out.copy_from_slice(&bytemuck::cast_slice(&decoded)[..bytes]);
    }
    Ok(())
}

/// Reads and checks one view's extension object; a problem names the field, the value and
/// what was expected.
fn parse(ext: &Value, buffers: &[gltf::buffer::Data]) -> Result<Compressed, String> {
    let uint = |field: &str, default: Option<u64>| match ext.get(field) {
        None => default.ok_or_else(|| format!("{field}: missing: expected an unsigned integer")),
        Some(v) => v
            .as_u64()
            .ok_or_else(|| format!("{field}: {v}: expected an unsigned integer")),
    };
    let size = |field: &str, default: Option<u64>| {
        uint(field, default).and_then(|n| usize::try_from(n).map_err(|_| format!("{field}: {n}: too large")))
    };
    let word = |field: &str, default: Option<&'static str>| match ext.get(field) {
        None => default.ok_or_else(|| format!("{field}: missing: expected a string")),
        Some(v) => v
            .as_str()
            .ok_or_else(|| format!("{field}: {v}: expected a string")),
    };
    let buffer = size("buffer", None)?;
    let (offset, length) = (size("byteOffset", Some(0))?, size("byteLength", None)?);
    let (stride, count) = (size("byteStride", None)?, size("count", None)?);
    let Some(data) = buffers.get(buffer) else {
        return Err(format!(
            "buffer: {buffer}: expected the index of one of the file's {} buffers",
            buffers.len()
        ));
    };
    if offset.checked_add(length).is_none_or(|end| end > data.0.len()) {
        return Err(format!(
            "byteOffset {offset} + byteLength {length}: expected a range inside buffer {buffer} ({} bytes)",
            data.0.len()
        ));
    }
    let mode = match word("mode", None)? {
        "ATTRIBUTES" => Mode::Attributes,
        "TRIANGLES" => Mode::Triangles,
        "INDICES" => Mode::Indices,
        other => {
            return Err(format!(
                "mode: {:?}: expected \"ATTRIBUTES\", \"TRIANGLES\" or \"INDICES\"",
                crate::scene::shorten(other)
            ))
        }
    };
    let filter = match word("filter", Some("NONE"))? {
        "NONE" => Filter::None,
        "OCTAHEDRAL" => Filter::Octahedral,
        "QUATERNION" => Filter::Quaternion,
        "EXPONENTIAL" => Filter::Exponential,
        "COLOR" => Filter::Color,
        other => {
            return Err(format!(
            "filter: {:?}: expected \"NONE\", \"OCTAHEDRAL\", \"QUATERNION\", \"EXPONENTIAL\" or \"COLOR\"",
            crate::scene::shorten(other)
        ))
        }
    };
    // The strides each mode and filter allow (the extensions' specifications).
    let stride_ok = match (mode, filter) {
        (Mode::Attributes, Filter::None | Filter::Exponential) => {
            stride % 4 == 0 && (4..=256).contains(&stride)
        }
        (Mode::Attributes, Filter::Octahedral | Filter::Color) => stride == 4 || stride == 8,
        (Mode::Attributes, Filter::Quaternion) => stride == 8,
        (_, Filter::None) => stride == 2 || stride == 4,
        (_, _) => {
            return Err(format!(
                "filter: {filter:?} with mode {mode:?}: expected filters only with mode \"ATTRIBUTES\""
            ))
        }
    };
    if !stride_ok {
        let expected = match (mode, filter) {
            (Mode::Attributes, Filter::None | Filter::Exponential) => "a multiple of 4 from 4 to 256",
            (Mode::Attributes, Filter::Quaternion) => "8",
            (Mode::Attributes, _) => "4 or 8",
            _ => "2 or 4 (16- or 32-bit indices)",
        };
        return Err(format!(
            "byteStride: {stride} for mode {mode:?}, filter {filter:?}: expected {expected}"
        ));
    }
    if mode == Mode::Triangles && count % 3 != 0 {
        return Err(format!(
            "count: {count} with mode \"TRIANGLES\": expected a multiple of 3"
        ));
    }
    Ok(Compressed {
        source: (buffer, offset, length),
        stride,
        count,
        mode,
        filter,
    })
}

/// Decodes `encoded` into `bytes` bytes (rounded up to whole words, which the filters read).
fn run(c: &Compressed, encoded: &[u8], bytes: usize) -> Result<Vec<u32>, String> {
    // u32 words: the filters read 16- and 32-bit components, so the bytes are word-aligned.
    // (At most the view's byteLength, inside a buffer charged to the file's buffer limit; the
    // copy is allocated fallibly.)
    let words = bytes.div_ceil(4);
    let mut out = crate::alloc::try_vec::<u32>(words, "meshopt decoded data").map_err(|e| e.to_string())?;
    out.resize(words, 0);
    let dest = out.as_mut_ptr().cast::<std::ffi::c_void>();
    let (count, stride) = (c.count, c.stride);
    // SAFETY: `out` holds at least count × stride bytes, all the decoders write; `encoded` is
    // a live slice read for its length only. meshoptimizer's decoders check their input
    // (they are meant for untrusted data) and return a negative code on malformed bytes.
    let code = unsafe {
        match c.mode {
            Mode::Attributes => {
                meshopt::ffi::meshopt_decodeVertexBuffer(dest, count, stride, encoded.as_ptr(), encoded.len())
            }
            Mode::Triangles => {
                meshopt::ffi::meshopt_decodeIndexBuffer(dest, count, stride, encoded.as_ptr(), encoded.len())
            }
            Mode::Indices => meshopt::ffi::meshopt_decodeIndexSequence(
                dest,
                count,
                stride,
                encoded.as_ptr(),
                encoded.len(),
            ),
        }
    };
    if code != 0 {
        return Err(format!(
            "the {} compressed bytes do not decode as {count} elements of {stride} bytes \
             (meshoptimizer's code {code}): expected data from meshoptimizer's encoder",
            encoded.len()
        ));
    }
    // SAFETY: the filters rewrite count elements of `stride` bytes in place, within `out`
    // (count × stride bytes at least), word-aligned; `parse` allowed only the strides each
    // filter takes.
    unsafe {
        match c.filter {
            Filter::None => {}
            Filter::Octahedral => meshopt::ffi::meshopt_decodeFilterOct(dest, count, stride),
            Filter::Quaternion => meshopt::ffi::meshopt_decodeFilterQuat(dest, count, stride),
            Filter::Exponential => meshopt::ffi::meshopt_decodeFilterExp(dest, count, stride),
            Filter::Color => meshopt::ffi::meshopt_decodeFilterColor(dest, count, stride),
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use crate::scene::gltf::load;
    use crate::scene::gltf::testing::{message, scratch_dir, QUAD};
    use std::path::PathBuf;

    /// Compressed bytes laid out in buffer 0, their views decoding into fallback buffer 1,
    /// whose URI names a file that is never written (as gltfpack's `-cf` files are often
    /// shipped without theirs): loaders that decode do not read it.
    #[derive(Default)]
    struct Packed {
        bin: Vec<u8>,
        views: Vec<String>,
        /// Bytes of the fallback buffer taken so far.
        fallback: usize,
    }

    impl Packed {
        /// A view of `count` elements of `stride` bytes whose compressed bytes are `encoded`;
        /// `ext` is more members of the extension object (with a leading comma), `view` more
        /// of the view's own.
        fn view(&mut self, encoded: &[u8], count: usize, stride: usize, ext: &str, view: &str) -> usize {
            while !self.bin.len().is_multiple_of(4) {
                self.bin.push(0);
            }
            let len = count * stride;
            self.views.push(format!(
                r#"{{ "buffer": 1, "byteOffset": {}, "byteLength": {len}{view},
                     "extensions": {{ "EXT_meshopt_compression": {{ "buffer": 0, "byteOffset": {},
                       "byteLength": {}, "byteStride": {stride}, "count": {count}{ext} }} }} }}"#,
                self.fallback,
                self.bin.len(),
                encoded.len()
            ));
            self.bin.extend_from_slice(encoded);
            self.fallback += len.next_multiple_of(4);
            self.views.len() - 1
        }

        fn write(&self, name: &str, required: &str, accessors: &str) -> PathBuf {
            let dir = scratch_dir("meshopt");
            std::fs::write(dir.join(format!("{name}.bin")), &self.bin).unwrap();
            let path = dir.join(format!("{name}.gltf"));
            let json = format!(
                r#"{{ "asset": {{ "version": "2.0" }},
                     "extensionsUsed": ["EXT_meshopt_compression"{required}],
                     "extensionsRequired": ["EXT_meshopt_compression"{required}],
                     "scene": 0, "scenes": [ {{ "nodes": [0] }} ], "nodes": [ {{ "mesh": 0 }} ],
                     "meshes": [ {{ "name": "packed", "primitives": [ {{ "attributes": {{ "POSITION": 0, "NORMAL": 1 }}, "indices": 2 }} ] }} ],
                     "accessors": [ {accessors} ],
                     "bufferViews": [ {} ],
                     "buffers": [ {{ "byteLength": {}, "uri": "{name}.bin" }},
                                  {{ "byteLength": {}, "uri": "{name}.fallback.bin",
                                     "extensions": {{ "EXT_meshopt_compression": {{ "fallback": true }} }} }} ] }}"#,
                self.views.join(", "),
                self.bin.len(),
                self.fallback.max(4)
            );
            std::fs::write(&path, json).unwrap();
            path
        }
    }

    const QUAD_INDICES: [u32; 6] = [0, 1, 2, 0, 2, 3];

    fn accessors(normal_type: u32, normalized: bool, index_type: u32) -> String {
        format!(
            r#"{{ "bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,0] }},
               {{ "bufferView": 1, "componentType": {normal_type}, "normalized": {normalized}, "count": 4, "type": "VEC3" }},
               {{ "bufferView": 2, "componentType": {index_type}, "count": 6, "type": "SCALAR" }}"#
        )
    }

    /// The quad's positions, normals and indices as loaded.
    fn quad(path: &std::path::Path) -> (Vec<[f32; 3]>, Vec<[f32; 3]>, Vec<u32>) {
        let loaded = load(path).unwrap_or_else(|e| panic!("{}", message(e)));
        assert_eq!(loaded.meshes.len(), 1);
        let data = &loaded.meshes[0].data;
        let positions = data.vertices.iter().map(|v| v.position).collect();
        let normals = data.vertices.iter().map(|v| v.normal).collect();
        (positions, normals, data.indices.clone())
    }

    #[test]
    fn a_quad_compressed_with_each_mode_and_filter_loads_as_its_plain_data() {
        let tilted = [0.0f32, 0.6, 0.8];
        // Vertex codec version 0: what EXT_meshopt_compression allows.
        let encode = |v: &[[f32; 3]]| meshopt::encoding::encode_vertex_buffer_level(v, 2, Some(0)).unwrap();

        // Floats without a filter, octahedral 8-bit normals, triangle-coded 16-bit indices.
        let mut p = Packed::default();
        p.view(&encode(&QUAD), 4, 12, r#", "mode": "ATTRIBUTES""#, "");
        let oct: Vec<[i8; 4]> =
            meshopt::encoding::encode_filter_oct(&[[tilted[0], tilted[1], tilted[2], 0.0]; 4], 8);
        let oct = meshopt::encoding::encode_vertex_buffer_level(&oct, 2, Some(0)).unwrap();
        p.view(
            &oct,
            4,
            4,
            r#", "mode": "ATTRIBUTES", "filter": "OCTAHEDRAL""#,
            r#", "byteStride": 4"#,
        );
        let tri = meshopt::encoding::encode_index_buffer(&QUAD_INDICES, 4).unwrap();
        p.view(&tri, 6, 2, r#", "mode": "TRIANGLES""#, "");
        let path = p.write(
            "oct_triangles",
            r#", "KHR_mesh_quantization""#,
            &accessors(5120, true, 5123),
        );
        let (positions, normals, indices) = quad(&path);
        assert_eq!(positions, QUAD.to_vec());
        for n in &normals {
            let off = (0..3).map(|k| (n[k] - tilted[k]).abs()).fold(0.0, f32::max);
            assert!(off < 0.02, "normal {n:?} against {tilted:?}");
        }
        assert_eq!(indices, QUAD_INDICES.to_vec());

        // Exponent-coded floats and sequence-coded 32-bit indices.
        let mut p = Packed::default();
        let exp = meshopt::encoding::encode_filter_exp(&QUAD, 24, meshopt::encoding::EncodeExpMode::Separate);
        let exp = meshopt::encoding::encode_vertex_buffer_level(&exp, 2, Some(0)).unwrap();
        p.view(
            &exp,
            4,
            12,
            r#", "mode": "ATTRIBUTES", "filter": "EXPONENTIAL""#,
            "",
        );
        let normals = meshopt::encoding::encode_filter_exp(
            &[tilted; 4],
            24,
            meshopt::encoding::EncodeExpMode::Separate,
        );
        let normals = meshopt::encoding::encode_vertex_buffer_level(&normals, 2, Some(0)).unwrap();
        p.view(
            &normals,
            4,
            12,
            r#", "mode": "ATTRIBUTES", "filter": "EXPONENTIAL""#,
            "",
        );
        let seq = meshopt::encoding::encode_index_sequence(&QUAD_INDICES, 4).unwrap();
        p.view(&seq, 6, 4, r#", "mode": "INDICES""#, "");
        let path = p.write("exp_indices", "", &accessors(5126, false, 5125));
        let (positions, normals, indices) = quad(&path);
        assert_eq!(positions, QUAD.to_vec());
        for n in &normals {
            let off = (0..3).map(|k| (n[k] - tilted[k]).abs()).fold(0.0, f32::max);
            assert!(off < 1e-5, "normal {n:?} against {tilted:?}");
        }
        assert_eq!(indices, QUAD_INDICES.to_vec());
    }

    #[test]
    fn a_bad_compressed_view_is_refused_naming_the_view_field_and_value() {
        let encode = |v: &[[f32; 3]]| meshopt::encoding::encode_vertex_buffer_level(v, 2, Some(0)).unwrap();
        let normals = encode(&[[0.0, 0.0, 1.0]; 4]);
        let tri = meshopt::encoding::encode_index_buffer(&QUAD_INDICES, 4).unwrap();
        // Each case: the indices view's extension members, and what the message must say.
        let cases: [(&[u8], usize, usize, &str, &str); 6] = [
            (
                &[0x55; 8],
                6,
                2,
                r#", "mode": "TRIANGLES""#,
                "do not decode as 6 elements of 2 bytes",
            ),
            (
                &tri,
                6,
                2,
                r#", "mode": "STRIPS""#,
                r#"mode: "STRIPS": expected "ATTRIBUTES", "TRIANGLES" or "INDICES""#,
            ),
            (
                &tri,
                6,
                3,
                r#", "mode": "TRIANGLES""#,
                "byteStride: 3 for mode Triangles",
            ),
            (
                &tri,
                6,
                2,
                r#", "mode": "TRIANGLES", "filter": "OCTAHEDRAL""#,
                "expected filters only with mode \"ATTRIBUTES\"",
            ),
            (
                &tri,
                6,
                2,
                r#", "mode": "TRIANGLES", "buffer": 7"#,
                "buffer: 7: expected the index of one of the file's 2 buffers",
            ),
            (
                &tri,
                6,
                2,
                r#", "count": 5, "mode": "TRIANGLES""#,
                "count: 5 with mode \"TRIANGLES\": expected a multiple of 3",
            ),
        ];
        for (i, (encoded, count, stride, ext, expected)) in cases.into_iter().enumerate() {
            let mut p = Packed::default();
            p.view(&encode(&QUAD), 4, 12, r#", "mode": "ATTRIBUTES""#, "");
            p.view(&normals, 4, 12, r#", "mode": "ATTRIBUTES""#, "");
            p.view(encoded, count, stride, ext, "");
            let path = p.write(&format!("bad_{i}"), "", &accessors(5126, false, 5123));
            let text = message(load(&path).unwrap_err());
            assert!(
                text.contains("bufferViews[2].extensions.EXT_meshopt_compression: ")
                    && text.contains(expected),
                "case {i}: {text}"
            );
        }
    }

    #[test]
    fn fallback_buffers_count_together_against_the_buffer_limit() {
        // Two fallback buffers of 600 MB each, declared in a few bytes of JSON: no file backs
        // them, so their sum is what is refused (by the file's buffer limit, 1 GiB), before
        // the second is allocated.
        let path = scratch_dir("meshopt").join("huge_fallbacks.gltf");
        let buffer = r#"{ "byteLength": 600000000, "extensions": { "EXT_meshopt_compression": { "fallback": true } } }"#;
        std::fs::write(
            &path,
            format!(
                r#"{{ "asset": {{ "version": "2.0" }}, "extensionsUsed": ["EXT_meshopt_compression"],
                     "buffers": [ {buffer}, {buffer} ] }}"#
            ),
        )
        .unwrap();
        let text = message(load(&path).unwrap_err());
        assert!(
            text.contains(
                "buffers[1]: a meshopt fallback buffer of 600000000 bytes, with the 600000000 bytes \
                 of the buffers before it, passes the limit of 1073741824 bytes"
            ) && text.contains("--max-buffer-mib"),
            "{text}"
        );
    }
}
