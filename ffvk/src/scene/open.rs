//! Opening what `ffvk render` takes: a scene file, or a `.gltf`/`.glb` file drawn as
//! [`DirectOptions`] say, at its own size or another; what was chosen and what was warned
//! of handed to the caller, each distinct warning once.

use std::path::Path;

use super::direct::{from_gltf, is_gltf, DirectOptions};
use super::{Limits, Scene, SceneError};

/// What opening a scene tells its caller besides the scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum OpenNote<'a> {
    /// What ffvk chose for a glTF file drawn without a scene file (camera, lights), one line
    /// each.
    Chose {
        /// The choice.
        text: &'a str,
    },
    /// A warning of the scene, once however many nodes repeat it, with how many times it
    /// came.
    Warning {
        /// The warning.
        text: &'a str,
        /// How many times the scene gave it.
        times: usize,
    },
}

impl std::fmt::Display for OpenNote<'_> {
    /// A choice as it is; a warning as `warning: TEXT`, with `(×N)` when it came N > 1 times.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OpenNote::Chose { text } => write!(f, "{text}"),
            OpenNote::Warning { text, times: 1 } => write!(f, "warning: {text}"),
            OpenNote::Warning { text, times } => write!(f, "warning: {text} (×{times})"),
        }
    }
}

/// The scene at `path`: a scene file, or a glTF file drawn as `direct` says; at `size` when
/// given (a glTF file's camera is made for it). `note` hears the choices first, then each
/// distinct warning once.
pub fn open(
    path: &Path,
    size: Option<(u32, u32)>,
    limits: &Limits,
    direct: &DirectOptions,
    note: &mut dyn FnMut(OpenNote),
) -> Result<Scene, SceneError> {
    let (mut scene, size) = if is_gltf(path) {
        let mut options = direct.clone();
        options.size = size;
        let made = from_gltf(path, &path.to_string_lossy(), limits, &options)?;
        for text in &made.choices {
            note(OpenNote::Chose { text });
        }
        (made.scene, None)
    } else {
        (Scene::load_with(path, limits)?, size)
    };
    let mut seen: Vec<(&str, usize)> = Vec::new();
    for w in &scene.warnings {
        match seen.iter_mut().find(|(text, _)| *text == w.as_str()) {
            Some((_, times)) => *times += 1,
            None => seen.push((w, 1)),
        }
    }
    for (text, times) in seen {
        note(OpenNote::Warning { text, times });
    }
    if let Some((w, h)) = size {
        scene.set_size(w, h);
    }
    Ok(scene)
}
