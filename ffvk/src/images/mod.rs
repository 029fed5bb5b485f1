//! Images after rendering: PNG files written and read with errors that name the path, and
//! their comparison.

pub mod compare;
pub mod thumbnail;

use std::path::{Path, PathBuf};

use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder, ImageReader, Limits, RgbaImage};

/// A PNG that could not be read or written, with its path.
#[derive(Debug, thiserror::Error)]
#[error("{}: {kind}", .path.display())]
#[non_exhaustive]
pub struct ImageError {
    /// The image file read or written.
    pub path: PathBuf,
    /// What went wrong.
    pub kind: ImageErrorKind,
}

/// What went wrong with an image file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ImageErrorKind {
    /// The path does not end in `.png`: ffvk writes PNG only.
    #[error("not a .png path: expected a file name ending in .png (ffvk writes PNG only)")]
    NotPng,
    /// Encoding failed.
    #[error("cannot encode the PNG: {0}")]
    Encode(image::ImageError),
    /// Writing failed (the destination is left as it was).
    #[error("cannot write the image (the file is left as it was): {0}")]
    Write(std::io::Error),
    /// Reading or decoding failed.
    #[error("cannot read the image: {0}")]
    Read(image::ImageError),
    /// The path is not a regular file (a pipe, a device, a folder): reading it could block or
    /// never end.
    #[error("not a regular file: expected an image file (not a device, pipe or folder)")]
    NotAFile,
    /// The image is not 8 bits per channel; comparing it at 8 bits would hide differences.
    #[error("the image has {found:?} pixels: expected 8 bits per channel (RGB or RGBA, as ffvk writes); convert it, or compare it with a 16-bit tool")]
    Not8Bit {
        /// What the file holds.
        found: image::ColorType,
    },
}

/// The largest decoded image accepted: two of ffvk's largest renders (16384² RGBA8).
const MAX_DECODED_BYTES: u64 = 2 * 16384 * 16384 * 4;

/// Saves a PNG atomically ([`crate::files::write_atomically`]), creating the parent folder;
/// errors name the path, and on error the file is left as it was.
pub fn save_png(image: &RgbaImage, path: &Path) -> Result<(), ImageError> {
    let err = |kind| ImageError {
        path: path.to_path_buf(),
        kind,
    };
    if !path.extension().is_some_and(|e| e.eq_ignore_ascii_case("png")) {
        return Err(err(ImageErrorKind::NotPng));
    }
    let mut encode_error = None;
    let written = crate::files::write_atomically(path, |w| {
        let encoder = PngEncoder::new(w);
        encoder
            .write_image(
                image.as_raw(),
                image.width(),
                image.height(),
                ExtendedColorType::Rgba8,
            )
            .map_err(|e| match e {
                image::ImageError::IoError(io) => io,
                other => {
                    encode_error = Some(other);
                    std::io::Error::other("encoding failed")
                }
            })
    });
    match (written, encode_error) {
        (Ok(()), _) => Ok(()),
        (Err(_), Some(e)) => Err(err(ImageErrorKind::Encode(e))),
        (Err(e), None) => Err(err(ImageErrorKind::Write(e))),
    }
}

/// Reads an 8-bit PNG (or any 8-bit format `image` knows) as RGBA8, up to two of ffvk's
/// largest images in memory; errors name the path. 16-bit and float images are refused
/// rather than reduced to 8 bits.
pub fn load_image(path: &Path) -> Result<RgbaImage, ImageError> {
    let err = |kind| ImageError {
        path: path.to_path_buf(),
        kind,
    };
    // Before opening: opening a FIFO blocks until a writer comes, and a device never ends.
    let meta =
        std::fs::metadata(path).map_err(|e| err(ImageErrorKind::Read(image::ImageError::IoError(e))))?;
    if !meta.is_file() {
        return Err(err(ImageErrorKind::NotAFile));
    }
    let mut reader = ImageReader::open(path)
        .map_err(|e| err(ImageErrorKind::Read(image::ImageError::IoError(e))))?
        .with_guessed_format()
        .map_err(|e| err(ImageErrorKind::Read(image::ImageError::IoError(e))))?;
    let mut limits = Limits::default();
    limits.max_alloc = Some(MAX_DECODED_BYTES);
    reader.limits(limits);
    let image = reader.decode().map_err(|e| err(ImageErrorKind::Read(e)))?;
    match image.color() {
        image::ColorType::Rgba8 | image::ColorType::Rgb8 | image::ColorType::L8 | image::ColorType::La8 => {
            Ok(image.into_rgba8())
        }
        found => Err(err(ImageErrorKind::Not8Bit { found })),
    }
}
