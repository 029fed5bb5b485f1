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

/// A tolerance value out of its range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{name} = {value} is out of range: expected a number in [0, 1]")]
pub struct ToleranceError {
    /// `max_share` or `max_flip`.
    pub name: &'static str,
    /// The value given.
    pub value: f64,
}

impl Tolerance {
    /// Checks that the shares are numbers in [0, 1] (a NaN would fail every image, an
    /// infinity pass every one).
    pub fn validate(&self) -> Result<(), ToleranceError> {
        for (name, value) in [("max_share", self.max_share), ("max_flip", self.max_flip as f64)] {
            if !(0.0..=1.0).contains(&value) {
                return Err(ToleranceError { name, value });
            }
        }
        Ok(())
    }

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
    /// Mean FLIP error over the image (RGB): 0 for identical RGB, `None` when it was not
    /// needed (the share over the threshold already fails the tolerance compared with).
    pub flip_mean: Option<f32>,
    pub worst: Option<WorstPixel>,
    pub threshold: u8,
}

impl Comparison {
    /// Whether the images pass `tolerance` (the one they were compared with: without FLIP,
    /// an image never passes).
    pub fn passes(&self, tolerance: &Tolerance) -> bool {
        self.share_over <= tolerance.max_share && self.flip_mean.is_some_and(|f| f <= tolerance.max_flip)
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
        let flip = match self.flip_mean {
            Some(f) => format!("FLIP mean {f:.5}"),
            None => "FLIP not computed (the share over the threshold decides)".into(),
        };
        format!(
            "max diff RGBA {:?}, {} pixel(s) ({:.4}%) over {}/255, {flip}{worst}",
            self.max_diff,
            self.over,
            self.share_over * 100.0,
            self.threshold,
        )
    }
}

/// When to compute FLIP.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flip {
    /// Only when the per-channel check does not decide: the images differ in RGB and the
    /// share over the threshold is within the tolerance.
    WhenNeeded,
    /// Whenever the images differ in RGB.
    Always,
}

/// Compares two images of the same size under `tolerance`, computing FLIP only when the
/// per-channel check does not decide.
pub fn compare(
    expected: &RgbaImage,
    actual: &RgbaImage,
    tolerance: &Tolerance,
) -> Result<Comparison, SizeMismatch> {
    compare_with(expected, actual, tolerance, Flip::WhenNeeded)
}

/// [`compare`] with the choice of when to compute FLIP.
pub fn compare_with(
    expected: &RgbaImage,
    actual: &RgbaImage,
    tolerance: &Tolerance,
    flip: Flip,
) -> Result<Comparison, SizeMismatch> {
    let mut c = channels(expected, actual, tolerance.threshold)?;
    c.flip_mean = if c.max_diff[..3] == [0, 0, 0] {
        Some(0.0)
    } else if flip == Flip::WhenNeeded && c.share_over > tolerance.max_share {
        None
    } else {
        Some(flip_mean(expected, actual))
    };
    Ok(c)
}

/// The per-channel part of a comparison (no FLIP yet).
fn channels(expected: &RgbaImage, actual: &RgbaImage, threshold: u8) -> Result<Comparison, SizeMismatch> {
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
    for (i, (e, a)) in expected
        .as_raw()
        .chunks_exact(4)
        .zip(actual.as_raw().chunks_exact(4))
        .enumerate()
    {
        if e == a {
            continue;
        }
        let (x, y) = ((i % width as usize) as u32, (i / width as usize) as u32);
        let mut pixel_max = 0;
        for (c, m) in max_diff.iter_mut().enumerate() {
            let d = e[c].abs_diff(a[c]);
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
                    expected: [e[0], e[1], e[2], e[3]],
                    actual: [a[0], a[1], a[2], a[3]],
                },
            ));
        }
    }
    Ok(Comparison {
        width,
        height,
        max_diff,
        over,
        share_over: over as f64 / (width as f64 * height as f64),
        flip_mean: None,
        worst: worst.map(|(_, w)| w),
        threshold,
    })
}

/// Images up to this many pixels get FLIP in one piece; larger ones in tiles.
const FLIP_WHOLE_PIXELS: u64 = 2048 * 2048;
/// The side of a FLIP tile's interior.
const FLIP_TILE: u32 = 1024;
/// Pixels of context around a tile's interior: more than the reach of FLIP's filters at its
/// default 67 pixels per degree, so that interior values match the whole-image ones.
const FLIP_MARGIN: u32 = 48;

/// The RGB bytes of the `w`×`h` region of `image` at (`x0`, `y0`).
fn rgb_region(image: &RgbaImage, x0: u32, y0: u32, w: u32, h: u32) -> Vec<u8> {
    let mut out = Vec::with_capacity((w * h * 3) as usize);
    let stride = image.width() as usize * 4;
    for y in y0..y0 + h {
        let row = &image.as_raw()[y as usize * stride..][..stride];
        for p in row[x0 as usize * 4..(x0 + w) as usize * 4].chunks_exact(4) {
            out.extend_from_slice(&p[..3]);
        }
    }
    out
}

/// FLIP over the `w`×`h` region at (`x0`, `y0`) of both images.
fn flip_region(
    expected: &RgbaImage,
    actual: &RgbaImage,
    x0: u32,
    y0: u32,
    w: u32,
    h: u32,
) -> nv_flip::FlipImageFloat {
    let reference = nv_flip::FlipImageRgb8::with_data(w, h, &rgb_region(expected, x0, y0, w, h));
    let test = nv_flip::FlipImageRgb8::with_data(w, h, &rgb_region(actual, x0, y0, w, h));
    nv_flip::flip(reference, test, nv_flip::DEFAULT_PIXELS_PER_DEGREE)
}

/// Calls `visit` with each tile's interior (x, y, width, height) and the FLIP values of that
/// interior, row by row; memory stays bounded by one tile with its margin.
fn flip_tiles(expected: &RgbaImage, actual: &RgbaImage, mut visit: impl FnMut(u32, u32, u32, u32, &[f32])) {
    let (w, h) = expected.dimensions();
    if u64::from(w) * u64::from(h) <= FLIP_WHOLE_PIXELS {
        visit(0, 0, w, h, &flip_region(expected, actual, 0, 0, w, h).to_vec());
        return;
    }
    for ty in (0..h).step_by(FLIP_TILE as usize) {
        for tx in (0..w).step_by(FLIP_TILE as usize) {
            let (iw, ih) = (FLIP_TILE.min(w - tx), FLIP_TILE.min(h - ty));
            let (x0, y0) = (tx.saturating_sub(FLIP_MARGIN), ty.saturating_sub(FLIP_MARGIN));
            let (x1, y1) = ((tx + iw + FLIP_MARGIN).min(w), (ty + ih + FLIP_MARGIN).min(h));
            let tile = flip_region(expected, actual, x0, y0, x1 - x0, y1 - y0).to_vec();
            let tile_w = (x1 - x0) as usize;
            let mut interior = Vec::with_capacity((iw * ih) as usize);
            for y in ty..ty + ih {
                let row = (y - y0) as usize * tile_w;
                interior.extend_from_slice(&tile[row + (tx - x0) as usize..][..iw as usize]);
            }
            visit(tx, ty, iw, ih, &interior);
        }
    }
}

/// The mean FLIP error over the whole image.
fn flip_mean(expected: &RgbaImage, actual: &RgbaImage) -> f32 {
    let (w, h) = expected.dimensions();
    if u64::from(w) * u64::from(h) <= FLIP_WHOLE_PIXELS {
        // In one piece, FLIP's own pool gives the mean (as earlier versions reported).
        return nv_flip::FlipPool::from_image(&flip_region(expected, actual, 0, 0, w, h)).mean();
    }
    let mut sum = 0.0f64;
    flip_tiles(expected, actual, |_, _, _, _, values| {
        sum += values.iter().map(|&v| f64::from(v)).sum::<f64>();
    });
    (sum / (f64::from(w) * f64::from(h))) as f32
}

/// A heat map of where the images differ: FLIP's error through the magma color map; pixels
/// over `threshold` that FLIP rates dim are painted red, so that a change of a few levels past
/// the threshold cannot hide in the dark end of the map.
pub fn heat_map(expected: &RgbaImage, actual: &RgbaImage, threshold: u8) -> Result<RgbaImage, SizeMismatch> {
    if expected.dimensions() != actual.dimensions() {
        return Err(SizeMismatch {
            expected: expected.dimensions(),
            actual: actual.dimensions(),
        });
    }
    let (w, h) = expected.dimensions();
    let lut = nv_flip::magma_lut().to_vec();
    let mut map = RgbaImage::new(w, h);
    flip_tiles(expected, actual, |tx, ty, tw, _th, values| {
        for (i, &v) in values.iter().enumerate() {
            let (x, y) = (tx + i as u32 % tw, ty + i as u32 / tw);
            let (e, a) = (expected.get_pixel(x, y), actual.get_pixel(x, y));
            let over = (0..4).any(|c| e.0[c].abs_diff(a.0[c]) > threshold);
            let k = (v.clamp(0.0, 1.0) * 255.0).round() as usize * 3;
            let colored = [lut[k], lut[k + 1], lut[k + 2]];
            let pixel = if over && colored[0] < 160 {
                Rgba([255, 40, 40, 255])
            } else {
                Rgba([colored[0], colored[1], colored[2], 255])
            };
            map.put_pixel(x, y, pixel);
        }
    });
    Ok(map)
}
