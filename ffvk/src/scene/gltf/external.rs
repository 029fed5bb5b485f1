//! The files outside a glTF file that reading it opens (its buffers' and images' URIs), read
//! from its JSON alone, so that a command can check its outputs against them before it
//! writes anything (see [`crate::scene::inputs`]).

use std::path::{Path, PathBuf};

use gltf::json::Value;

/// The external buffer and image files of the glTF or GLB file at `path`, each as the loader
/// would open it (inside the file's folder or `roots`); data URIs and what the loader would
/// refuse are left out, and so is everything when the JSON cannot be read.
pub fn external_files(path: &Path, roots: &[PathBuf]) -> Vec<PathBuf> {
    let Some(json) = json_of(path) else {
        return Vec::new();
    };
    let Ok(root) = gltf::json::deserialize::from_slice::<Value>(&json) else {
        return Vec::new();
    };
    let base = path.parent().unwrap_or(Path::new(""));
    ["buffers", "images"]
        .iter()
        .filter_map(|list| root.get(list)?.as_array())
        .flatten()
        .filter_map(|item| item.get("uri")?.as_str())
        .filter(|uri| !uri.starts_with("data:"))
        .filter_map(|uri| super::uris::asset_file(base, uri, roots))
        .collect()
}

/// The JSON of a `.gltf` file, or of a GLB's first chunk (read without its binary chunk).
fn json_of(path: &Path) -> Option<Vec<u8>> {
    use std::io::Read;
    let meta = std::fs::metadata(path).ok()?;
    if !meta.is_file() {
        return None;
    }
    let mut file = std::fs::File::open(path).ok()?;
    let mut header = [0u8; 20];
    let read = file.read(&mut header).ok()?;
    if read < 20 || &header[..4] != b"glTF" {
        return crate::files::read_regular(path, super::MAX_FILE_BYTES).ok();
    }
    crate::files::note_input(path);
    let length = u32::from_le_bytes([header[12], header[13], header[14], header[15]]) as u64;
    if &header[16..20] != b"JSON" || length > meta.len() {
        return None;
    }
    let mut json = Vec::new();
    json.try_reserve_exact(length as usize).ok()?;
    file.take(length).read_to_end(&mut json).ok()?;
    Some(json)
}
