//! Image comparison for regression renders: per-channel differences, the share of pixels over
//! a threshold, and FLIP (NVIDIA's perceptual difference, through the `nv-flip` crate that
//! wgpu's own image tests use), with a heat map of where images differ.
//!
//! The tolerance policy (docs/regression.md, "Tolerance policy"): on the same Mesa and CPU, ffvk's images
//! are byte-identical; across drivers, Mesa versions and CPUs, float operations may be
//! ordered or fused differently (a clear color of 0.1 is 26 on one driver and 25 on another)
//! and rasterization rules may settle silhouette pixels differently, so a reference passes
//! when every channel is within `threshold` except on at most `max_share` of the pixels, and
//! the FLIP error of the pixels over the threshold, averaged over the image, stays under
//! `max_flip`. An image whose every pixel is within the threshold therefore always passes;
//! [`Tolerance::flip_all_pixels`] opts into FLIP over every pixel instead.

use image::{Rgba, RgbaImage};

pub use super::load_image;

/// Two images that cannot be compared because their sizes differ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("the images differ in size: expected {}x{}, actual {}x{}", .expected.0, .expected.1, .actual.0, .actual.1)]
#[non_exhaustive]
pub struct SizeMismatch {
    /// Width and height of the expected image.
    pub expected: (u32, u32),
    /// Width and height of the actual image.
    pub actual: (u32, u32),
}

/// When a comparison passes.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Tolerance {
    /// Largest per-channel difference (of 255) a pixel may have without counting as over.
    pub threshold: u8,
    /// Largest share (0..=1) of pixels allowed over `threshold`.
    pub max_share: f64,
    /// Largest mean FLIP error (0..=1): FLIP's per-pixel error, counted at the pixels over
    /// `threshold` (0 elsewhere), averaged over the image.
    pub max_flip: f32,
    /// Count FLIP at every pixel, those within `threshold` included, so that a uniform shift
    /// within the threshold can fail a dark image (off by default: across drivers such shifts
    /// are rounding, not regressions).
    pub flip_all_pixels: bool,
}

impl Default for Tolerance {
    /// The policy for references made on another Mesa version or CPU.
    fn default() -> Self {
        Tolerance {
            threshold: 2,
            max_share: 0.001,
            max_flip: 0.005,
            flip_all_pixels: false,
        }
    }
}

with_fields!(Tolerance {
    /// Sets [`threshold`](Tolerance::threshold).
    with_threshold => threshold: u8,
    /// Sets [`max_share`](Tolerance::max_share).
    with_max_share => max_share: f64,
    /// Sets [`max_flip`](Tolerance::max_flip).
    with_max_flip => max_flip: f32,
    /// Sets [`flip_all_pixels`](Tolerance::flip_all_pixels).
    with_flip_all_pixels => flip_all_pixels: bool,
});

/// A tolerance value out of its range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{name} = {value} is out of range: expected a number in [0, 1]")]
#[non_exhaustive]
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
        flip_all_pixels: true,
    };
}

/// One pixel where the images differ, with both values.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PixelDiff {
    /// Column, in pixels from the left.
    pub x: u32,
    /// Row, in pixels from the top.
    pub y: u32,
    /// The expected image's RGBA bytes at the pixel.
    pub expected: [u8; 4],
    /// The actual image's RGBA bytes at the pixel.
    pub actual: [u8; 4],
}

/// What a comparison found. `Default` is the comparison of two empty images.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Comparison {
    /// Width of both images, in pixels.
    pub width: u32,
    /// Height of both images, in pixels.
    pub height: u32,
    /// Largest difference per channel (R, G, B, A).
    pub max_diff: [u8; 4],
    /// Pixels with some channel over the threshold.
    pub over: usize,
    /// `over` as a share of all pixels.
    pub share_over: f64,
    /// Mean FLIP error over the image (RGB), counted at the pixels over the threshold unless
    /// `flip_all_pixels`: 0 when no pixel counts, `None` when it was not needed (the share
    /// over the threshold already fails the tolerance compared with).
    pub flip_mean: Option<f32>,
    /// Whether `flip_mean` counted every pixel ([`Tolerance::flip_all_pixels`]).
    pub flip_all_pixels: bool,
    /// The pixel whose largest channel difference is the largest (the first such, row by
    /// row).
    pub worst: Option<PixelDiff>,
    /// The first pixel, row by row from the top left, with a channel over the threshold.
    #[cfg_attr(feature = "serde", serde(default))]
    pub first_over: Option<PixelDiff>,
    /// The [`Tolerance::threshold`] `over` was counted with (of 255).
    pub threshold: u8,
}

impl Comparison {
    /// Whether the images pass `tolerance` (the one they were compared with: without FLIP,
    /// an image never passes).
    pub fn passes(&self, tolerance: &Tolerance) -> bool {
        self.share_over <= tolerance.max_share && self.flip_mean.is_some_and(|f| f <= tolerance.max_flip)
    }

    /// Whether the images are byte-identical, alpha included.
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
        let scope = if self.flip_all_pixels {
            "all pixels"
        } else {
            "pixels over the threshold"
        };
        let flip = match self.flip_mean {
            Some(f) => format!("FLIP mean {f:.5} ({scope})"),
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
#[non_exhaustive]
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
    c.flip_all_pixels = tolerance.flip_all_pixels;
    // Only pixels over the threshold count, unless every pixel does.
    let counted = (!tolerance.flip_all_pixels).then_some(tolerance.threshold);
    c.flip_mean = if c.max_diff[..3] == [0, 0, 0] || (counted.is_some() && c.over == 0) {
        Some(0.0)
    } else if flip == Flip::WhenNeeded && c.share_over > tolerance.max_share {
        None
    } else {
        Some(flip_mean(expected, actual, counted))
    };
    Ok(c)
}

/// The per-channel part of a comparison (no FLIP yet).
fn channels(expected: &RgbaImage, actual: &RgbaImage, threshold: u8) -> Result<Comparison, SizeMismatch> {
    same_size(expected, actual)?;
    let (width, height) = expected.dimensions();
    let mut max_diff = [0u8; 4];
    let mut over = 0;
    let mut worst: Option<(u8, PixelDiff)> = None;
    let mut first_over = None;
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
        let here = PixelDiff {
            x,
            y,
            expected: [e[0], e[1], e[2], e[3]],
            actual: [a[0], a[1], a[2], a[3]],
        };
        if pixel_max > threshold {
            over += 1;
            first_over.get_or_insert(here);
        }
        if pixel_max > 0 && worst.is_none_or(|(d, _)| pixel_max > d) {
            worst = Some((pixel_max, here));
        }
    }
    Ok(Comparison {
        width,
        height,
        max_diff,
        over,
        share_over: over as f64 / (width as f64 * height as f64),
        flip_mean: None,
        flip_all_pixels: false,
        worst: worst.map(|(_, w)| w),
        first_over,
        threshold,
    })
}

/// Images up to this many pixels get FLIP in one piece; larger ones in regions around their
/// differences.
const FLIP_WHOLE_PIXELS: u64 = 2048 * 2048;
/// The side of the blocks FLIP's regions are made of.
const BLOCK: u32 = 32;
/// The most block rows one region spans (bounding its memory: 512 rows of the image).
const REGION_BLOCK_ROWS: u32 = 16;
/// Pixels of context around a region: more than the reach of FLIP's filters at its default
/// 67 pixels per degree (about 13), so that region values equal whole-image values. FLIP is
/// exactly 0 wherever both images agree within that reach, so regions cover only the blocks
/// within that reach of a difference.
const FLIP_MARGIN: u32 = 24;

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

/// Which blocks lie within [`FLIP_MARGIN`] of an RGB difference, row-major, `columns` per
/// block row.
fn needed_blocks(expected: &RgbaImage, actual: &RgbaImage) -> (Vec<bool>, u32, u32) {
    let (w, h) = expected.dimensions();
    let (columns, rows) = (w.div_ceil(BLOCK), h.div_ceil(BLOCK));
    let mut needed = vec![false; (columns * rows) as usize];
    let stride = w as usize * 4;
    for y in 0..h {
        let (e, a) = (
            &expected.as_raw()[y as usize * stride..][..stride],
            &actual.as_raw()[y as usize * stride..][..stride],
        );
        if e == a {
            continue;
        }
        let (r0, r1) = (
            y.saturating_sub(FLIP_MARGIN) / BLOCK,
            (y + FLIP_MARGIN).min(h - 1) / BLOCK,
        );
        for (i, (pe, pa)) in e.chunks_exact(4).zip(a.chunks_exact(4)).enumerate() {
            if pe[..3] == pa[..3] {
                continue;
            }
            let x = i as u32;
            let (c0, c1) = (
                x.saturating_sub(FLIP_MARGIN) / BLOCK,
                (x + FLIP_MARGIN).min(w - 1) / BLOCK,
            );
            for r in r0..=r1 {
                for c in c0..=c1 {
                    needed[(r * columns + c) as usize] = true;
                }
            }
        }
    }
    (needed, columns, rows)
}

/// The regions FLIP is computed on, as (first column, end column, first row, end row) in
/// blocks: each block row's runs of needed blocks, a run merged with the same run in the rows
/// below, up to [`REGION_BLOCK_ROWS`] rows.
fn regions(needed: &[bool], columns: u32, rows: u32) -> Vec<(u32, u32, u32, u32)> {
    let runs = |r: u32| {
        let mut out = Vec::new();
        let mut c = 0;
        while c < columns {
            if needed[(r * columns + c) as usize] {
                let start = c;
                while c < columns && needed[(r * columns + c) as usize] {
                    c += 1;
                }
                out.push((start, c));
            } else {
                c += 1;
            }
        }
        out
    };
    let mut done = Vec::new();
    // Regions still growing downwards: (start, end, first row).
    let mut open: Vec<(u32, u32, u32)> = Vec::new();
    for r in 0..rows {
        let row_runs = runs(r);
        let mut still_open = Vec::new();
        for (start, end, first) in open {
            if row_runs.contains(&(start, end)) && r - first < REGION_BLOCK_ROWS {
                still_open.push((start, end, first));
            } else {
                done.push((start, end, first, r));
            }
        }
        for run in row_runs {
            if !still_open.iter().any(|&(s, e, _)| (s, e) == run) {
                still_open.push((run.0, run.1, r));
            }
        }
        open = still_open;
    }
    done.extend(open.into_iter().map(|(s, e, first)| (s, e, first, rows)));
    done
}

/// Calls `visit` with regions (x, y, width, height) of the image and their FLIP values,
/// covering every pixel whose FLIP value may be non-zero; every other pixel's value is 0.
/// Memory stays bounded by one region.
fn flip_tiles(expected: &RgbaImage, actual: &RgbaImage, mut visit: impl FnMut(u32, u32, u32, u32, &[f32])) {
    let (w, h) = expected.dimensions();
    if u64::from(w) * u64::from(h) <= FLIP_WHOLE_PIXELS {
        visit(0, 0, w, h, &flip_region(expected, actual, 0, 0, w, h).to_vec());
        return;
    }
    let (needed, columns, rows) = needed_blocks(expected, actual);
    for (c0, c1, r0, r1) in regions(&needed, columns, rows) {
        let (tx, ty) = (c0 * BLOCK, r0 * BLOCK);
        let (iw, ih) = ((c1 * BLOCK).min(w) - tx, (r1 * BLOCK).min(h) - ty);
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

/// Whether some channel of the two pixels is more than `threshold` apart.
fn over_threshold(e: &Rgba<u8>, a: &Rgba<u8>, threshold: u8) -> bool {
    (0..4).any(|c| e.0[c].abs_diff(a.0[c]) > threshold)
}

/// The FLIP error averaged over the whole image, counting every pixel, or with
/// `over: Some(threshold)` only the pixels with a channel more than `threshold` apart (the
/// others count as 0).
fn flip_mean(expected: &RgbaImage, actual: &RgbaImage, over: Option<u8>) -> f32 {
    let (w, h) = expected.dimensions();
    if over.is_none() && u64::from(w) * u64::from(h) <= FLIP_WHOLE_PIXELS {
        // In one piece, FLIP's own pool gives the mean (as earlier versions reported).
        return nv_flip::FlipPool::from_image(&flip_region(expected, actual, 0, 0, w, h)).mean();
    }
    let mut sum = 0.0f64;
    flip_tiles(expected, actual, |tx, ty, tw, _, values| {
        for (i, &v) in values.iter().enumerate().filter(|&(_, &v)| v != 0.0) {
            let counts = over.is_none_or(|threshold| {
                let (x, y) = (tx + i as u32 % tw, ty + i as u32 / tw);
                over_threshold(expected.get_pixel(x, y), actual.get_pixel(x, y), threshold)
            });
            if counts {
                sum += f64::from(v);
            }
        }
    });
    (sum / (f64::from(w) * f64::from(h))) as f32
}

/// A heat map of where the images differ: FLIP's error through the magma color map; pixels
/// over `threshold` that FLIP rates dim are painted red, so that a change of a few levels past
/// the threshold cannot hide in the dark end of the map.
pub fn heat_map(expected: &RgbaImage, actual: &RgbaImage, threshold: u8) -> Result<RgbaImage, SizeMismatch> {
    Ok(heat_map_and_flip(expected, actual, threshold, false)?.0)
}

/// [`heat_map`] and, from the same FLIP values, the FLIP mean as [`compare`] counts it under
/// `tolerance` (at the pixels over its threshold, or at every pixel).
pub fn heat_map_with_flip(
    expected: &RgbaImage,
    actual: &RgbaImage,
    tolerance: &Tolerance,
) -> Result<(RgbaImage, f32), SizeMismatch> {
    heat_map_and_flip(expected, actual, tolerance.threshold, tolerance.flip_all_pixels)
}

fn heat_map_and_flip(
    expected: &RgbaImage,
    actual: &RgbaImage,
    threshold: u8,
    all_pixels: bool,
) -> Result<(RgbaImage, f32), SizeMismatch> {
    same_size(expected, actual)?;
    let (w, h) = expected.dimensions();
    let lut = nv_flip::magma_lut().to_vec();
    // Pixels no region covers have FLIP 0.
    let mut map = RgbaImage::from_pixel(w, h, Rgba([lut[0], lut[1], lut[2], 255]));
    let mut sum = 0.0f64;
    flip_tiles(expected, actual, |tx, ty, tw, _th, values| {
        for (i, &v) in values.iter().enumerate() {
            let (x, y) = (tx + i as u32 % tw, ty + i as u32 / tw);
            let (e, a) = (expected.get_pixel(x, y), actual.get_pixel(x, y));
            let over = over_threshold(e, a, threshold);
            if over || all_pixels {
                sum += f64::from(v);
            }
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
    Ok((map, (sum / (f64::from(w) * f64::from(h))) as f32))
}

/// A map of the per-channel differences: each pixel's red, green and blue are |actual −
/// expected| of that channel, scaled so that the largest difference of any channel in the
/// image is 255 (identical pixels are black; a difference in alpha lights all three, gray).
/// [`channel_gain`] is the scale.
pub fn channel_map(expected: &RgbaImage, actual: &RgbaImage) -> Result<RgbaImage, SizeMismatch> {
    same_size(expected, actual)?;
    let (w, h) = expected.dimensions();
    let diff = |e: &[u8], a: &[u8]| -> [u8; 4] { std::array::from_fn(|c| e[c].abs_diff(a[c])) };
    let largest = expected
        .as_raw()
        .chunks_exact(4)
        .zip(actual.as_raw().chunks_exact(4))
        .map(|(e, a)| diff(e, a).into_iter().max().unwrap_or(0))
        .max()
        .unwrap_or(0);
    let gain = channel_gain(largest);
    let mut map = RgbaImage::new(w, h);
    for ((out, e), a) in map
        .as_mut()
        .chunks_exact_mut(4)
        .zip(expected.as_raw().chunks_exact(4))
        .zip(actual.as_raw().chunks_exact(4))
    {
        let d = diff(e, a);
        for c in 0..3 {
            out[c] = (f32::from(d[c].max(d[3])) * gain).round().min(255.0) as u8;
        }
        out[3] = 255;
    }
    Ok(map)
}

/// The factor [`channel_map`] multiplies differences by when the largest difference of any
/// channel is `largest` (1 when the images are identical).
pub fn channel_gain(largest: u8) -> f32 {
    255.0 / f32::from(largest.max(1))
}

fn same_size(expected: &RgbaImage, actual: &RgbaImage) -> Result<(), SizeMismatch> {
    if expected.dimensions() != actual.dimensions() {
        return Err(SizeMismatch {
            expected: expected.dimensions(),
            actual: actual.dimensions(),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Over FLIP_WHOLE_PIXELS, FLIP is computed in regions around the differences; the mean
    /// must equal the whole image's (FLIP is 0 wherever both images agree within its reach).
    #[test]
    fn flip_in_regions_equals_flip_of_the_whole_image() {
        let (w, h) = (2100u32, 2050u32);
        let expected = RgbaImage::from_fn(w, h, |x, y| {
            Rgba([(x % 251) as u8, (y % 241) as u8, ((x ^ y) & 0x7f) as u8, 255])
        });
        let mut actual = expected.clone();
        for k in 0..40u32 {
            let (x, y) = ((k * 7919) % w, (k * 104_729) % h);
            actual.put_pixel(x, y, Rgba([0, 255, 0, 255]));
        }
        for y in 700..760 {
            for x in 1500..1620 {
                actual.put_pixel(x, y, Rgba([200, 10, 10, 255]));
            }
        }
        let whole = nv_flip::FlipPool::from_image(&flip_region(&expected, &actual, 0, 0, w, h)).mean();
        let regions = flip_mean(&expected, &actual, None);
        assert!(
            (whole - regions).abs() <= 1e-5 * whole,
            "whole image {whole}, regions {regions}"
        );
        // And the heat map covers the differences.
        let map = heat_map(&expected, &actual, 2).unwrap();
        assert_ne!(map.get_pixel(1550, 730), map.get_pixel(10, 10));
    }

    /// A dark image (the clear color of the golden scenes, 0.1 → 26) and the same image one
    /// or three levels lower everywhere.
    fn dark_and_shifted(shift: u8) -> (RgbaImage, RgbaImage) {
        let mut expected = RgbaImage::from_pixel(64, 64, Rgba([26, 26, 26, 255]));
        for y in 20..40 {
            for x in 20..40 {
                expected.put_pixel(x, y, Rgba([40 + x as u8, 90, 30 + y as u8, 255]));
            }
        }
        let mut actual = expected.clone();
        for p in actual.pixels_mut() {
            for c in 0..3 {
                p.0[c] -= shift;
            }
        }
        (expected, actual)
    }

    #[test]
    fn a_shift_within_the_threshold_passes_and_one_beyond_it_fails() {
        let (expected, one_lower) = dark_and_shifted(1);
        let c = compare(&expected, &one_lower, &Tolerance::default()).unwrap();
        assert!(c.passes(&Tolerance::default()), "{}", c.summary());
        assert_eq!((c.over, c.flip_mean), (0, Some(0.0)));
        // FLIP over every pixel, as before the cross-driver policy, fails the same images.
        let all = Tolerance {
            flip_all_pixels: true,
            ..Tolerance::default()
        };
        let c = compare(&expected, &one_lower, &all).unwrap();
        assert!(
            c.flip_mean.unwrap() > 0.0 && c.summary().contains("all pixels"),
            "{}",
            c.summary()
        );

        let (expected, three_lower) = dark_and_shifted(3);
        let c = compare(&expected, &three_lower, &Tolerance::default()).unwrap();
        assert!(!c.passes(&Tolerance::default()), "{}", c.summary());
        assert_eq!(c.over, 64 * 64);
    }

    #[test]
    fn flip_counts_only_the_pixels_over_the_threshold() {
        let (expected, mut actual) = dark_and_shifted(1);
        // One pixel far off, on top of the uniform shift within the threshold.
        actual.put_pixel(30, 30, Rgba([255, 0, 0, 255]));
        let c = compare(&expected, &actual, &Tolerance::default()).unwrap();
        let all = flip_mean(&expected, &actual, None);
        let over = c.flip_mean.unwrap();
        assert!(over > 0.0 && over < all, "over {over}, all {all}");
        // The one pixel's own FLIP value over the image's 4096 pixels.
        let map = flip_region(&expected, &actual, 0, 0, 64, 64).to_vec();
        let expected_mean = map[30 * 64 + 30] / 4096.0;
        assert!((over - expected_mean).abs() < 1e-7, "{over} vs {expected_mean}");
    }

    #[test]
    fn the_first_pixel_over_the_threshold_is_the_first_row_by_row() {
        let expected = RgbaImage::from_pixel(8, 8, Rgba([10, 20, 30, 255]));
        let mut actual = expected.clone();
        // Within the threshold earlier, over it later, and the worst last.
        actual.put_pixel(0, 0, Rgba([11, 20, 30, 255]));
        actual.put_pixel(6, 2, Rgba([10, 25, 30, 255]));
        actual.put_pixel(1, 3, Rgba([10, 20, 30, 200]));
        actual.put_pixel(7, 7, Rgba([90, 20, 30, 255]));
        let c = compare(&expected, &actual, &Tolerance::default()).unwrap();
        let first = c.first_over.unwrap();
        assert_eq!(
            (first.x, first.y, first.expected, first.actual),
            (6, 2, [10, 20, 30, 255], [10, 25, 30, 255])
        );
        assert_eq!((c.worst.unwrap().x, c.worst.unwrap().y), (7, 7));
        assert_eq!((c.over, c.max_diff), (3, [80, 5, 0, 55]));
        let same = compare(&expected, &expected, &Tolerance::default()).unwrap();
        assert_eq!((same.first_over, same.worst), (None, None));
    }

    #[test]
    fn the_channel_map_scales_each_channel_by_the_largest_difference() {
        let expected = RgbaImage::from_pixel(4, 2, Rgba([100, 100, 100, 255]));
        let mut actual = expected.clone();
        actual.put_pixel(1, 0, Rgba([110, 100, 95, 255]));
        actual.put_pixel(2, 1, Rgba([100, 102, 100, 250]));
        let map = channel_map(&expected, &actual).unwrap();
        // The largest difference, 10, is 255: gain 25.5.
        assert_eq!(map.get_pixel(1, 0).0, [255, 0, 128, 255]);
        // Alpha's 5 lights every channel; green's own 2 is below it.
        assert_eq!(map.get_pixel(2, 1).0, [128, 128, 128, 255]);
        assert_eq!(map.get_pixel(0, 0).0, [0, 0, 0, 255]);
        assert_eq!(channel_gain(10), 25.5);
        assert!(channel_map(&expected, &RgbaImage::new(2, 2)).is_err());
    }

    #[test]
    fn the_heat_map_gives_the_flip_mean_compare_gives() {
        let (expected, mut actual) = dark_and_shifted(1);
        actual.put_pixel(30, 30, Rgba([255, 0, 0, 255]));
        actual.put_pixel(5, 50, Rgba([0, 200, 0, 255]));
        for tolerance in [
            Tolerance::default(),
            Tolerance {
                flip_all_pixels: true,
                ..Tolerance::default()
            },
        ] {
            let c = compare_with(&expected, &actual, &tolerance, Flip::Always).unwrap();
            let (_, mean) = heat_map_with_flip(&expected, &actual, &tolerance).unwrap();
            // Over every pixel of a small image, compare takes FLIP's own pool, which sums
            // in f32.
            let want = c.flip_mean.unwrap();
            assert!((mean - want).abs() <= 1e-4 * want, "{mean} vs {want}");
        }
    }

    #[test]
    fn tolerances_out_of_range_are_refused() {
        for (share, flip) in [
            (f64::NAN, 0.0),
            (0.0, f32::NAN),
            (f64::INFINITY, 0.0),
            (-0.1, 0.0),
            (0.0, 1.5),
        ] {
            let t = Tolerance {
                threshold: 2,
                max_share: share,
                max_flip: flip,
                flip_all_pixels: false,
            };
            assert!(t.validate().is_err(), "{t:?}");
        }
        assert!(Tolerance::default().validate().is_ok() && Tolerance::EXACT.validate().is_ok());
    }
}
