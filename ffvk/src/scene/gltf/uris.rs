//! Where a glTF file's URIs lead: the file a buffer or image URI names, kept inside the glTF
//! file's folder (or the folders the user allowed), and `%XX` escapes decoded. Read by the
//! buffers (`read.rs`) and the textures (`textures.rs`).

use std::path::Path;

/// The file a URI without a scheme names, inside the glTF file's folder `base` or one of
/// `roots`; `None` where it leaves them (see [`inside_folder`] and [`inside_roots`]).
pub(super) fn asset_file(base: &Path, uri: &str, roots: &[std::path::PathBuf]) -> Option<std::path::PathBuf> {
    inside_folder(base, uri).or_else(|| inside_roots(base, uri, roots))
}

/// The file a relative buffer URI names, when it lies inside `folder`: percent-decoded, not
/// absolute, no scheme, no `..` component, and inside the folder after symbolic links. `None`
/// otherwise.
fn inside_folder(folder: &Path, uri: &str) -> Option<std::path::PathBuf> {
    if uri.contains(':') {
        return None;
    }
    let decoded = percent_decode(uri)?;
    let relative = Path::new(&decoded);
    // `..` can only lead out or back; refused outright, since after a symbolic link it would
    // not mean what it reads as.
    if relative.is_absolute()
        || relative
            .components()
            .any(|c| matches!(c, std::path::Component::ParentDir))
    {
        return None;
    }
    let folder = std::fs::canonicalize(if folder.as_os_str().is_empty() {
        Path::new(".")
    } else {
        folder
    })
    .ok()?;
    let file = folder.join(relative);
    match std::fs::canonicalize(&file) {
        // It exists: after every link it must still be inside.
        Ok(real) => real.starts_with(&folder).then_some(file),
        // It does not (or cannot be resolved): the read reports that.
        Err(_) => Some(file),
    }
}

/// The file a URI without a scheme names, relative to `folder` or absolute, when it exists
/// and lies, after every symbolic link, inside one of `roots` (the folders the user allowed
/// explicitly). `None` otherwise.
fn inside_roots(folder: &Path, uri: &str, roots: &[std::path::PathBuf]) -> Option<std::path::PathBuf> {
    if roots.is_empty() || uri.contains(':') {
        return None;
    }
    let file = folder.join(percent_decode(uri)?);
    let real = std::fs::canonicalize(&file).ok()?;
    roots
        .iter()
        .filter_map(|root| std::fs::canonicalize(root).ok())
        .any(|root| real.starts_with(root))
        .then_some(file)
}

/// `%XX` escapes decoded; `None` when an escape is malformed or the result is not UTF-8.
pub(super) fn percent_decode(uri: &str) -> Option<String> {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = std::str::from_utf8(bytes.get(i + 1..i + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}
