//! Draco-compressed geometry (KHR_draco_mesh_compression), which ffvk cannot decode: found in
//! the raw JSON before anything is read, so that a file whose triangles exist only compressed
//! is refused with the extension's name rather than with what its missing data looks like to
//! the validator ("bufferView: Missing data").
//!
//! Draco's decoder is C++ with no maintained pure-Rust port (draco-rs binds it and builds it
//! from source, minutes of every clean build). A file that also carries uncompressed data
//! (the extension allows that fallback) loads from that data, with a warning. Meshopt
//! compression is decoded (`meshopt.rs`).

use super::{Context, LoadError, LoadErrorKind};
use gltf::json::Value;

/// The Draco extension's name.
const DRACO: &str = "KHR_draco_mesh_compression";

/// Refuses a file whose drawn geometry exists only in a compressed form.
pub(super) fn check(cx: &Context) -> Result<(), LoadError> {
    let raw = cx.raw;
    let array = |name: &str| {
        raw.get(name)
            .and_then(Value::as_array)
            .map(Vec::as_slice)
            .unwrap_or(&[])
    };
    let accessors = array("accessors");
    let meshes = array("meshes");
    for (m, mesh) in meshes.iter().enumerate() {
        let primitives = mesh.get("primitives").and_then(Value::as_array);
        for (p, primitive) in primitives.into_iter().flatten().enumerate() {
            let draco = primitive.get("extensions").and_then(|e| e.get(DRACO)).is_some();
            let mut needed: Vec<(String, u64)> = primitive
                .get("attributes")
                .and_then(Value::as_object)
                .into_iter()
                .flatten()
                .filter_map(|(name, a)| Some((name.clone(), a.as_u64()?)))
                .collect();
            if let Some(i) = primitive.get("indices").and_then(Value::as_u64) {
                needed.push(("indices".to_owned(), i));
            }
            for (what, accessor) in needed {
                let Some(a) = usize::try_from(accessor).ok().and_then(|a| accessors.get(a)) else {
                    continue; // the validator names it
                };
                if !draco || a.get("bufferView").is_some() {
                    continue;
                }
                let (extension, detail) = (DRACO, "has no bufferView: its data exists only Draco-compressed");
                return Err(cx.error(LoadErrorKind::Compressed {
                    primitive: cx.primitive_label(m, p),
                    attribute: what,
                    accessor,
                    extension,
                    detail,
                }));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::scene::gltf::load;
    use crate::scene::gltf::testing::{message, scratch_dir, Asset, QUAD};

    #[test]
    fn geometry_that_exists_only_compressed_names_its_extension() {
        let dir = scratch_dir("compressed");
        let mut a = Asset::default();
        a.positions(&QUAD[..3]);
        // Draco, listed as used but not required, with POSITION only compressed.
        let body = r#""extensionsUsed": ["KHR_draco_mesh_compression"],
               "meshes": [ { "primitives": [ { "attributes": { "POSITION": 1 },
                 "extensions": { "KHR_draco_mesh_compression": { "bufferView": 0, "attributes": { "POSITION": 0 } } } } ] } ],
               "nodes": [ { "mesh": 0 } ], "scenes": [ { "nodes": [0] } ], "scene": 0,"#;
        a.accessors.push(
            r#"{ "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0] }"#.into(),
        );
        let text = message(load(&a.write_gltf(&dir, "draco", body)).unwrap_err());
        assert!(
            text.contains("mesh 0 primitive 0: POSITION (accessor 1)")
                && text.contains("KHR_draco_mesh_compression")
                && text.contains("cannot decode"),
            "{text}"
        );
        assert!(!text.contains("Missing data"), "{text}");

        // Draco with an uncompressed copy loads from the copy.
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = format!(
            r#""extensionsUsed": ["KHR_draco_mesh_compression"],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }},
                 "extensions": {{ "KHR_draco_mesh_compression": {{ "bufferView": 0, "attributes": {{ "POSITION": 0 }} }} }} }} ] }} ],
               "nodes": [ {{ "mesh": 0 }} ], "scenes": [ {{ "nodes": [0] }} ], "scene": 0,"#
        );
        let loaded = load(&a.write_gltf(&dir, "draco_fallback", &body)).unwrap();
        assert_eq!(loaded.meshes.len(), 1);
        assert!(loaded
            .warnings
            .iter()
            .any(|w| w.contains("KHR_draco_mesh_compression")));
    }
}
