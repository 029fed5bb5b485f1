//! Small copies of large images for pages that show many of them (the regression report).
//! Each thumbnail pixel stands for a block of the image: the block's mean for pictures, its
//! largest value per channel for difference maps, so that one differing pixel of a 16384²
//! image still shows in its 512² thumbnail.

use image::RgbaImage;

/// How a block of pixels becomes one thumbnail pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Reduce {
    /// The mean of each channel (for rendered images).
    Mean,
    /// The largest value of each channel (for difference maps).
    Max,
}

/// The size of `(width, height)` fitted within `max_side` on its longer side, keeping the
/// aspect ratio (each side at least 1); sizes that fit already are kept.
pub fn fitted_size(width: u32, height: u32, max_side: u32) -> (u32, u32) {
    let long = width.max(height);
    if long <= max_side {
        return (width, height);
    }
    let scale = |side: u32| {
        ((u64::from(side) * u64::from(max_side) + u64::from(long) / 2) / u64::from(long)).max(1) as u32
    };
    (scale(width), scale(height))
}

/// `image` fitted within `max_side` ([`fitted_size`]), each pixel reduced from its block of
/// the image as `reduce` says; `None` when the image fits already.
pub fn thumbnail(image: &RgbaImage, max_side: u32, reduce: Reduce) -> Option<RgbaImage> {
    let (w, h) = image.dimensions();
    let (tw, th) = fitted_size(w, h, max_side);
    if (tw, th) == (w, h) {
        return None;
    }
    // Block edges: output column/row i covers [edge(i), edge(i + 1)).
    let edge = |i: u32, out: u32, side: u32| (u64::from(i) * u64::from(side) / u64::from(out)) as usize;
    let columns: Vec<usize> = (0..=tw).map(|i| edge(i, tw, w)).collect();
    let stride = w as usize * 4;
    let mut out = RgbaImage::new(tw, th);
    let mut acc = vec![0u64; tw as usize * 4];
    for oy in 0..th {
        let (y0, y1) = (edge(oy, th, h), edge(oy + 1, th, h));
        acc.fill(0);
        for y in y0..y1 {
            let row = &image.as_raw()[y * stride..][..stride];
            for (ox, block) in columns.windows(2).enumerate() {
                let a = &mut acc[ox * 4..][..4];
                for p in row[block[0] * 4..block[1] * 4].chunks_exact(4) {
                    for c in 0..4 {
                        a[c] = match reduce {
                            Reduce::Mean => a[c] + u64::from(p[c]),
                            Reduce::Max => a[c].max(u64::from(p[c])),
                        };
                    }
                }
            }
        }
        for (ox, block) in columns.windows(2).enumerate() {
            let count = ((block[1] - block[0]) * (y1 - y0)) as u64;
            let a = &acc[ox * 4..][..4];
            let pixel = std::array::from_fn(|c| match reduce {
                Reduce::Mean => ((a[c] + count / 2) / count) as u8,
                Reduce::Max => a[c] as u8,
            });
            out.put_pixel(ox as u32, oy, image::Rgba(pixel));
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::Rgba;

    #[test]
    fn sizes_fit_the_longer_side_and_keep_the_aspect_ratio() {
        assert_eq!(fitted_size(16384, 16384, 512), (512, 512));
        assert_eq!(fitted_size(16384, 1, 512), (512, 1));
        assert_eq!(fitted_size(1000, 600, 500), (500, 300));
        assert_eq!(fitted_size(300, 200, 512), (300, 200));
    }

    #[test]
    fn one_differing_pixel_survives_the_max_and_is_averaged_by_the_mean() {
        let mut image = RgbaImage::from_pixel(1024, 768, Rgba([0, 0, 0, 255]));
        image.put_pixel(1000, 700, Rgba([255, 0, 64, 255]));
        let max = thumbnail(&image, 256, Reduce::Max).unwrap();
        assert_eq!(max.dimensions(), (256, 192));
        // Blocks are 4×4: the pixel lands in block (250, 175).
        assert_eq!(max.get_pixel(250, 175).0, [255, 0, 64, 255]);
        assert_eq!(max.pixels().filter(|p| p.0[0] != 0).count(), 1);
        let mean = thumbnail(&image, 256, Reduce::Mean).unwrap();
        assert_eq!(mean.get_pixel(250, 175).0, [16, 0, 4, 255]);
        assert!(thumbnail(&image, 1024, Reduce::Mean).is_none());
    }

    #[test]
    fn blocks_of_uneven_size_cover_every_pixel() {
        // 7 pixels into 3: blocks of 2, 2 and 3 pixels.
        let image = RgbaImage::from_fn(7, 1, |x, _| Rgba([x as u8 * 10, 0, 0, 255]));
        let mean = thumbnail(&image, 3, Reduce::Mean).unwrap();
        let reds: Vec<u8> = mean.pixels().map(|p| p.0[0]).collect();
        assert_eq!(reds, [5, 25, 50]);
        let max = thumbnail(&image, 3, Reduce::Max).unwrap();
        let reds: Vec<u8> = max.pixels().map(|p| p.0[0]).collect();
        assert_eq!(reds, [10, 30, 60]);
    }
}
