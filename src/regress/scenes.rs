//! The scenes of a run: files given, and folders expanded into their scene files (or their
//! glTF files), each named by its path below the folder given.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::{Error, Result};

/// One scene of a run: its file and the name its images take (no extension).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct SceneFile {
    /// Its place in the suite, counting from 0.
    pub index: usize,
    /// The scene file.
    pub path: PathBuf,
    /// Its path relative to the folder given, without its extension (`a/s` for
    /// `DIR/a/s.toml` or `DIR/a/s.glb`), or the file's stem for a file given by itself.
    pub name: String,
}

/// Expands folders into their scenes (below them, in path order) and names every scene; two
/// scenes that would write the same image are an error. A folder's scenes are its *.toml
/// files, or, in a folder without any, its *.gltf and *.glb files, each drawn directly
/// (where a folder has both, the glTF files are the scene files' meshes: [`folder_scenes`]).
pub fn scene_files(inputs: &[PathBuf]) -> Result<Vec<SceneFile>> {
    let mut files = Vec::new();
    for input in inputs {
        if input.is_dir() {
            let found = folder_scenes(input)?.scenes;
            if found.is_empty() {
                return Err(Error::Path {
                    path: input.clone(),
                    problem: "no .toml scene files and no .gltf or .glb files in this directory",
                });
            }
            for path in found {
                let relative = path.strip_prefix(input).unwrap_or(&path).with_extension("");
                let name = relative
                    .components()
                    .map(|c| c.as_os_str().to_string_lossy().into_owned())
                    .collect::<Vec<_>>()
                    .join("/");
                files.push(SceneFile {
                    index: files.len(),
                    path,
                    name,
                });
            }
        } else {
            let name = input
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            files.push(SceneFile {
                index: files.len(),
                path: input.clone(),
                name,
            });
        }
    }
    // Beside its image a scene may write NAME.diff.png, NAME.channels.png and
    // NAME.replaced.png: a scene named NAME.diff would write over the first.
    let writes_over = |a: &str, b: &str| {
        a == b
            || [".diff", ".channels", ".replaced"]
                .iter()
                .any(|suffix| a.strip_suffix(suffix) == Some(b) || b.strip_suffix(suffix) == Some(a))
    };
    for (i, f) in files.iter().enumerate() {
        if let Some(other) = files[..i].iter().find(|o| writes_over(&o.name, &f.name)) {
            return Err(Error::NameClash {
                name: if other.name.len() > f.name.len() {
                    other.name.clone()
                } else {
                    f.name.clone()
                },
                first: other.path.clone(),
                second: f.path.clone(),
            });
        }
    }
    Ok(files)
}

/// What a folder given as a suite holds.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FolderScenes {
    /// Its scenes, in path order: every *.toml file below it, or every *.gltf and *.glb file
    /// where there is no *.toml file.
    pub scenes: Vec<PathBuf>,
    /// The *.gltf and *.glb files below it that are not scenes because scene files are
    /// (the meshes those files name, or files to give by name).
    pub meshes: Vec<PathBuf>,
}

/// The scenes of folder `dir` (see [`FolderScenes`]).
pub fn folder_scenes(dir: &Path) -> Result<FolderScenes> {
    let (mut toml, mut gltf) = (Vec::new(), Vec::new());
    collect(dir, &mut toml, &mut gltf)?;
    toml.sort();
    gltf.sort();
    Ok(match toml.is_empty() {
        true => FolderScenes {
            scenes: gltf,
            meshes: Vec::new(),
        },
        false => FolderScenes {
            scenes: toml,
            meshes: gltf,
        },
    })
}

/// Every *.toml file and every .gltf or .glb file below `dir`.
fn collect(dir: &Path, toml: &mut Vec<PathBuf>, gltf: &mut Vec<PathBuf>) -> Result<()> {
    let entries = std::fs::read_dir(dir).map_err(|source| Error::Read {
        path: dir.to_path_buf(),
        source,
    })?;
    for entry in entries {
        let path = entry
            .map_err(|source| Error::Read {
                path: dir.to_path_buf(),
                source,
            })?
            .path();
        if path.is_dir() {
            collect(&path, toml, gltf)?;
        } else if path.extension().is_some_and(|x| x == "toml") {
            toml.push(path);
        } else if ffvk::scene::direct::is_gltf(&path) {
            gltf.push(path);
        }
    }
    Ok(())
}
