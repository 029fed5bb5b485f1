//! What the glTF loader's tests share: glTF files written from hand-built buffers.

use super::LoadError;
use std::path::{Path, PathBuf};

/// A folder of its own under `target/` for test `test`'s files.
pub(super) fn scratch_dir(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("target")
        .join("ffvk-test-gltf_load")
        .join(test);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A binary buffer under construction plus the bufferViews and accessors into it.
#[derive(Default)]
pub(super) struct Asset {
    bin: Vec<u8>,
    views: Vec<String>,
    pub(super) accessors: Vec<String>,
}

impl Asset {
    fn view(&mut self, bytes: &[u8]) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        self.views.push(format!(
            r#"{{ "buffer": 0, "byteOffset": {}, "byteLength": {} }}"#,
            self.bin.len(),
            bytes.len()
        ));
        self.bin.extend_from_slice(bytes);
        self.views.len() - 1
    }

    /// An accessor over `bytes`; `extra` is more JSON members (with a leading comma).
    pub(super) fn accessor(
        &mut self,
        bytes: &[u8],
        component: u32,
        count: usize,
        ty: &str,
        extra: &str,
    ) -> usize {
        let view = self.view(bytes);
        self.accessors.push(format!(
            r#"{{ "bufferView": {view}, "componentType": {component}, "count": {count}, "type": "{ty}"{extra} }}"#
        ));
        self.accessors.len() - 1
    }

    /// FLOAT VEC3 positions, with the min and max glTF requires of them.
    pub(super) fn positions(&mut self, p: &[[f32; 3]]) -> usize {
        let mut lo = [f32::INFINITY; 3];
        let mut hi = [f32::NEG_INFINITY; 3];
        for v in p {
            for k in 0..3 {
                lo[k] = lo[k].min(v[k]);
                hi[k] = hi[k].max(v[k]);
            }
        }
        let bytes: Vec<u8> = p.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        let extra = format!(r#", "min": {lo:?}, "max": {hi:?}"#);
        self.accessor(&bytes, 5126, p.len(), "VEC3", &extra)
    }

    pub(super) fn vec3s(&mut self, v: &[[f32; 3]]) -> usize {
        let bytes: Vec<u8> = v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        self.accessor(&bytes, 5126, v.len(), "VEC3", "")
    }

    pub(super) fn u8s(&mut self, v: &[u8]) -> usize {
        self.accessor(v, 5121, v.len(), "SCALAR", "")
    }

    pub(super) fn u16s(&mut self, v: &[u16]) -> usize {
        let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
        self.accessor(&bytes, 5123, v.len(), "SCALAR", "")
    }

    pub(super) fn u32s(&mut self, v: &[u32]) -> usize {
        let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
        self.accessor(&bytes, 5125, v.len(), "SCALAR", "")
    }

    /// The document: `body` holds the remaining top-level members (meshes, nodes, ...,
    /// each followed by a comma); the buffer has `uri` or none (GLB).
    pub(super) fn json(&self, body: &str, uri: Option<&str>) -> String {
        let uri = uri.map(|u| format!(r#", "uri": "{u}""#)).unwrap_or_default();
        format!(
            r#"{{ "asset": {{ "version": "2.0" }}, {body}
               "accessors": [{}], "bufferViews": [{}],
               "buffers": [ {{ "byteLength": {}{uri} }} ] }}"#,
            self.accessors.join(", "),
            self.views.join(", "),
            self.bin.len()
        )
    }

    /// `NAME.gltf` with its buffer in `NAME.bin` beside it.
    pub(super) fn write_gltf(&self, dir: &Path, name: &str, body: &str) -> PathBuf {
        std::fs::write(dir.join(format!("{name}.bin")), &self.bin).unwrap();
        let path = dir.join(format!("{name}.gltf"));
        std::fs::write(&path, self.json(body, Some(&format!("{name}.bin")))).unwrap();
        path
    }

    /// `NAME.glb`: a JSON chunk and a BIN chunk.
    pub(super) fn write_glb(&self, dir: &Path, name: &str, body: &str) -> PathBuf {
        let mut json = self.json(body, None).into_bytes();
        while !json.len().is_multiple_of(4) {
            json.push(b' ');
        }
        let mut bin = self.bin.clone();
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        let total = 12 + 8 + json.len() + 8 + bin.len();
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&(total as u32).to_le_bytes());
        out.extend_from_slice(&(json.len() as u32).to_le_bytes());
        out.extend_from_slice(&0x4E4F_534Au32.to_le_bytes());
        out.extend_from_slice(&json);
        out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        out.extend_from_slice(&0x004E_4942u32.to_le_bytes());
        out.extend_from_slice(&bin);
        let path = dir.join(format!("{name}.glb"));
        std::fs::write(&path, out).unwrap();
        path
    }
}

/// One node holding mesh 0, in scene 0.
pub(super) fn one_mesh_body(primitive: &str) -> String {
    format!(
        r#""scene": 0, "scenes": [ {{ "nodes": [0] }} ], "nodes": [ {{ "mesh": 0 }} ],
           "meshes": [ {{ "name": "thing", "primitives": [ {primitive} ] }} ],"#
    )
}

/// The unit square's corners, counter-clockwise seen from +z.
pub(super) const QUAD: [[f32; 3]; 4] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];

/// The error as users see it.
pub(super) fn message(e: LoadError) -> String {
    e.to_string()
}
