//! Image comparison for regression renders: per-channel differences, the share of pixels over
//! a threshold, and FLIP (NVIDIA's perceptual difference, through the `nv-flip` crate that
//! wgpu's own image tests use), with a heat map of where images differ.
//!
//! The tolerance policy (README, "Golden images"): on the same Mesa and CPU, ffvk's images
//! are byte-identical; across Mesa versions and CPUs, LLVM may order or fuse float operations
//! differently and rasterization rules may settle silhouette pixels differently, so a
//! reference passes when every channel is within `threshold` except on at most `max_share`
//! of the pixels, and the mean FLIP error stays under `max_flip`.

use image::{Rgba, RgbaImage};

pub use super::load_image;

/// Two images that cannot be compared because their sizes differ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("the images differ in size: expected {}x{}, actual {}x{}", .expected.0, .expected.1, .actual.0, .actual.1)]
pub struct SizeMismatch {
    /// Width and height of the expected image.
    pub expected: (u32, u32),
    /// Width and height of the actual image.
    pub actual: (u32, u32),
}

/// When a comparison passes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// Largest per-channel difference (of 255) a pixel may have without counting as over.
    pub threshold: u8,
    /// Largest share (0..=1) of pixels allowed over `threshold`.
    pub max_share: f64,
    /// Largest mean FLIP error (0..=1).
    pub max_flip: f32,
}

impl Default for Tolerance {
    /// The policy for references made on another Mesa version or CPU.
    fn default() -> Self {
        Tolerance {
            threshold: 2,
            max_share: 0.001,
            max_flip: 0.005,
        }
    }
}

impl Tolerance {
    /// Byte-identical images only.
    pub const EXACT: Tolerance = Tolerance {
        threshold: 0,
        max_share: 0.0,
        max_flip: 0.0,
    };
}

/// One pixel where the images differ most.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorstPixel {
    pub x: u32,
    pub y: u32,
    pub expected: [u8; 4],
    pub actual: [u8; 4],
}

/// What a comparison found.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    pub width: u32,
    pub height: u32,
    /// Largest difference per channel (R, G, B, A).
    pub max_diff: [u8; 4],
    /// Pixels with some channel over the threshold.
    pub over: usize,
    /// `over` as a share of all pixels.
    pub share_over: f64,
    /// Mean FLIP error over the image (RGB), 0 for identical images.
    pub flip_mean: f32,
    pub worst: Option<WorstPixel>,
    pub threshold: u8,
}

impl Comparison {
    pub fn passes(&self, tolerance: &Tolerance) -> bool {
        self.share_over <= tolerance.max_share && self.flip_mean <= tolerance.max_flip
    }

    pub fn identical(&self) -> bool {
        self.max_diff == [0; 4]
    }

    /// A one-line report: the figures and the worst pixel with both values.
    pub fn summary(&self) -> String {
        let worst = match self.worst {
            Some(w) => format!(
                "; worst pixel ({}, {}): expected {:?}, actual {:?}",
                w.x, w.y, w.expected, w.actual
            ),
            None => String::new(),
        };
        format!(
            "max diff RGBA {:?}, {} pixel(s) ({:.4}%) over {}/255, FLIP mean {:.5}{worst}",
            self.max_diff,
            self.over,
            self.share_over * 100.0,
            self.threshold,
            self.flip_mean
        )
    }
}

/// Compares two images of the same size; `threshold` is the per-channel difference a pixel
/// may have before it counts as over.
pub fn compare(expected: &RgbaImage, actual: &RgbaImage, threshold: u8) -> Result<Comparison, SizeMismatch> {
    if expected.dimensions() != actual.dimensions() {
        return Err(SizeMismatch {
            expected: expected.dimensions(),
            actual: actual.dimensions(),
        });
    }
    let (width, height) = expected.dimensions();
    let mut max_diff = [0u8; 4];
    let mut over = 0;
    let mut worst: Option<(u8, WorstPixel)> = None;
    for (x, y, e) in expected.enumerate_pixels() {
        let a = actual.get_pixel(x, y);
        let mut pixel_max = 0;
        for (c, m) in max_diff.iter_mut().enumerate() {
            let d = e.0[c].abs_diff(a.0[c]);
            *m = (*m).max(d);
            pixel_max = pixel_max.max(d);
        }
        if pixel_max > threshold {
            over += 1;
        }
        if pixel_max > 0 && worst.is_none_or(|(d, _)| pixel_max > d) {
            worst = Some((
                pixel_max,
                WorstPixel {
                    x,
                    y,
                    expected: e.0,
                    actual: a.0,
                },
            ));
        }
    }
    let flip_mean = if max_diff[..3] == [0, 0, 0] {
        0.0
    } else {
        flip_pool(expected, actual).mean()
    };
    Ok(Comparison {
        width,
        height,
        max_diff,
        over,
        share_over: over as f64 / (width as f64 * height as f64),
        flip_mean,
        worst: worst.map(|(_, w)| w),
        threshold,
    })
}

fn rgb_bytes(image: &RgbaImage) -> Vec<u8> {
    image.pixels().flat_map(|p| [p.0[0], p.0[1], p.0[2]]).collect()
}

fn flip_map(expected: &RgbaImage, actual: &RgbaImage) -> nv_flip::FlipImageFloat {
    let (w, h) = expected.dimensions();
    let reference = nv_flip::FlipImageRgb8::with_data(w, h, &rgb_bytes(expected));
    let test = nv_flip::FlipImageRgb8::with_data(w, h, &rgb_bytes(actual));
    nv_flip::flip(reference, test, nv_flip::DEFAULT_PIXELS_PER_DEGREE)
}

fn flip_pool(expected: &RgbaImage, actual: &RgbaImage) -> nv_flip::FlipPool {
    nv_flip::FlipPool::from_image(&flip_map(expected, actual))
}

/// A heat map of where the images differ: FLIP's error through the magma color map; pixels
/// over `threshold` that FLIP rates dim are painted red, so that a change of a few levels past
/// the threshold cannot hide in the dark end of the map.
pub fn heat_map(expected: &RgbaImage, actual: &RgbaImage, threshold: u8) -> Result<RgbaImage, SizeMismatch> {
    compare(expected, actual, threshold)?; // size check
    let (w, h) = expected.dimensions();
    let colored = flip_map(expected, actual)
        .apply_color_lut(&nv_flip::magma_lut())
        .to_vec();
    Ok(RgbaImage::from_fn(w, h, |x, y| {
        let i = ((y * w + x) * 3) as usize;
        let (e, a) = (expected.get_pixel(x, y), actual.get_pixel(x, y));
        let over = (0..4).any(|c| e.0[c].abs_diff(a.0[c]) > threshold);
        if over && colored[i] < 160 {
            Rgba([255, 40, 40, 255])
        } else {
            Rgba([colored[i], colored[i + 1], colored[i + 2], 255])
        }
    }))
}
