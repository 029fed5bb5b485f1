//! Images after rendering: PNG files written and read with errors that name the path, and
//! their comparison.

pub mod compare;

use std::path::{Path, PathBuf};

use image::RgbaImage;

/// A PNG that could not be read or written, with its path.
#[derive(Debug, thiserror::Error)]
#[error("{}: {kind}", .path.display())]
pub struct ImageError {
    /// The file (or, for [`ImageErrorKind::CreateDir`], the folder).
    pub path: PathBuf,
    /// What went wrong.
    pub kind: ImageErrorKind,
}

/// What went wrong with an image file.
#[derive(Debug, thiserror::Error)]
pub enum ImageErrorKind {
    /// The output folder could not be created.
    #[error("cannot create the folder: {0}")]
    CreateDir(std::io::Error),
    /// Encoding or writing failed.
    #[error("cannot write the image: {0}")]
    Write(image::ImageError),
    /// Reading or decoding failed.
    #[error("cannot read the image: {0}")]
    Read(image::ImageError),
}

/// Saves a PNG, creating the parent directory; errors name the path.
pub fn save_png(image: &RgbaImage, path: &Path) -> Result<(), ImageError> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| ImageError {
            path: dir.to_path_buf(),
            kind: ImageErrorKind::CreateDir(e),
        })?;
    }
    image.save(path).map_err(|e| ImageError {
        path: path.to_path_buf(),
        kind: ImageErrorKind::Write(e),
    })
}

/// Reads a PNG (or any format `image` knows) as RGBA8; errors name the path.
pub fn load_image(path: &Path) -> Result<RgbaImage, ImageError> {
    image::open(path).map(|i| i.to_rgba8()).map_err(|e| ImageError {
        path: path.to_path_buf(),
        kind: ImageErrorKind::Read(e),
    })
}
