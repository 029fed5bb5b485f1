//! Labelled contact sheets: panels in a grid, each with its name drawn in DejaVu Sans.

use ab_glyph::{Font, FontRef, PxScale, ScaleFont};
use image::{Rgba, RgbaImage};

use crate::{Error, Result};

/// DejaVu Sans (Bitstream Vera licence, `assets/fonts/DejaVu-LICENSE.txt`), embedded so that
/// labels never depend on the fonts a machine has installed.
pub const LABEL_FONT: &[u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");

fn load_font() -> Result<FontRef<'static>> {
    FontRef::try_from_slice(LABEL_FONT).map_err(|e| Error::Font {
        message: format!("the embedded DejaVu Sans is not a usable TrueType font: {e}"),
    })
}

/// Draws `text` in white with its top-left corner at (x, y), `size` pixels high.
fn draw_text(image: &mut RgbaImage, font: &FontRef, text: &str, x: f32, y: f32, size: f32) {
    let scaled = font.as_scaled(PxScale::from(size));
    let mut caret = x;
    for ch in text.chars() {
        let id = scaled.glyph_id(ch);
        let glyph =
            id.with_scale_and_position(PxScale::from(size), ab_glyph::point(caret, y + scaled.ascent()));
        caret += scaled.h_advance(id);
        let Some(outline) = font.outline_glyph(glyph) else {
            continue;
        };
        let bounds = outline.px_bounds();
        outline.draw(|gx, gy, coverage| {
            let (px, py) = (bounds.min.x as i64 + gx as i64, bounds.min.y as i64 + gy as i64);
            if px >= 0 && py >= 0 && (px as u32) < image.width() && (py as u32) < image.height() {
                let p = image.get_pixel_mut(px as u32, py as u32);
                for c in 0..3 {
                    let v = p.0[c] as f32 * (1.0 - coverage) + 255.0 * coverage;
                    p.0[c] = v.round() as u8;
                }
            }
        });
    }
}

/// Lays out labelled panels in rows of `columns`, each panel with its label above it.
/// Panels may differ in size; cells take the largest.
pub fn contact_sheet(panels: &[(String, RgbaImage)], columns: usize) -> Result<RgbaImage> {
    let font = load_font()?;
    let columns = columns.max(1);
    let cell_w = panels.iter().map(|(_, p)| p.width()).max().unwrap_or(1);
    let cell_h = panels.iter().map(|(_, p)| p.height()).max().unwrap_or(1);
    let (label_h, gap) = (24u32, 8u32);
    let rows = panels.len().div_ceil(columns) as u32;
    let width = columns as u32 * (cell_w + gap) + gap;
    let height = rows * (cell_h + label_h + gap) + gap;
    let mut sheet = RgbaImage::from_pixel(width, height, Rgba([24, 24, 28, 255]));
    for (i, (label, panel)) in panels.iter().enumerate() {
        let (col, row) = ((i % columns) as u32, (i / columns) as u32);
        let x = gap + col * (cell_w + gap);
        let y = gap + row * (cell_h + label_h + gap);
        draw_text(&mut sheet, &font, label, x as f32 + 2.0, y as f32 + 2.0, 18.0);
        image::imageops::overlay(&mut sheet, panel, x as i64, (y + label_h) as i64);
    }
    Ok(sheet)
}
