//! The files a scene reads, listed without loading it: the scene file, its texture images
//! (and cube map faces),
//! its glTF files and each glTF file's external buffers and images. A command checks its
//! outputs against them before it writes anything ([`crate::files`] then guards each write).
//! The list is best effort: a part that cannot be read or parsed is left out (loading the
//! scene reports it), and so is what a file names but ffvk would refuse to read.

use std::path::{Path, PathBuf};

use super::direct::is_gltf;
use super::file::SceneFile;
use super::Limits;

/// The files that drawing the scene at `path` (a scene file, or a glTF file drawn directly)
/// reads, `path` first; each once, as it would be opened (not resolved).
pub fn inputs(path: &Path, limits: &Limits) -> Vec<PathBuf> {
    let mut files = vec![path.to_path_buf()];
    if is_gltf(path) {
        files.extend(super::gltf::external_files(path, &limits.asset_roots));
        return dedup(files);
    }
    let Ok(bytes) = crate::files::read_regular(path, super::MAX_SCENE_BYTES) else {
        return files;
    };
    let Ok(text) = String::from_utf8(bytes) else {
        return files;
    };
    if super::nesting_depth(&text) > super::MAX_SCENE_NESTING {
        return files;
    }
    let Ok(scene) = toml::from_str::<SceneFile>(&text) else {
        return files;
    };
    let folder = path.parent().unwrap_or(Path::new(""));
    let textures = scene.texture.iter().chain(
        scene
            .meshes
            .iter()
            .flat_map(|m| m.texture.iter().chain(m.texture_units.iter().flatten())),
    );
    // Each unit's image, then its cube map's faces (GL's order).
    for t in textures {
        let faces = t.cube_map.iter().filter_map(|c| c.faces.as_ref()).flatten();
        files.extend(t.image.iter().chain(faces).map(|image| folder.join(image)));
    }
    for gltf in scene.meshes.iter().filter_map(|m| m.gltf.as_ref()) {
        let gltf = folder.join(gltf);
        files.extend(super::gltf::external_files(&gltf, &limits.asset_roots));
        files.push(gltf);
    }
    dedup(files)
}

/// `files` with repeats removed, the first of each kept.
fn dedup(files: Vec<PathBuf>) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = Vec::with_capacity(files.len());
    for f in files {
        if !out.contains(&f) {
            out.push(f);
        }
    }
    out
}
