//! GL's polygon stipple (§3.5.2, `glPolygonStipple`): the pattern as a draw carries it
//! ([`PolygonStipple`]) and as the fragment stage reads it, specialization constants 35 .. 67 of
//! `glsl/stipple.glsl`, set for stippled pipelines only (the lighting's [`SpecKey`] stays as it
//! is).
//!
//! [`SpecKey`]: crate::gpu::layout::SpecKey

use ash::vk;

/// The first constant of `glsl/stipple.glsl` (`SPEC_STIPPLE`); the 32 rows follow it.
pub(crate) const FIRST_STIPPLE_CONSTANT: u32 = crate::gpu::layout::SPEC_CONSTANT_COUNT as u32;

/// `GL_POLYGON_STIPPLE` with `glPolygonStipple`: a fragment of a filled polygon at window
/// (x_w, y_w) is drawn only where bit x_w mod 32 of `rows[y_w mod 32]` is set, window rows
/// counted from the bottom of the framebuffer as in GL. Polygons drawn as lines or points,
/// and lines and points, are not stippled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct PolygonStipple {
    /// Row y of the pattern (y = 0 at the bottom), bit x for column x (least significant
    /// first).
    pub rows: [u32; 32],
    /// The framebuffer's height in pixels: GL's rows count from its bottom, Vulkan's from its
    /// top (only the height mod 32 matters).
    pub framebuffer_height: u32,
}

impl PolygonStipple {
    /// The pattern `glPolygonStipple(mask)` sets under GL's initial unpack state
    /// (`GL_UNPACK_LSB_FIRST` false): 32 rows of 4 bytes from the bottom row up, each byte's
    /// most significant bit the leftmost of its 8 columns; for a framebuffer
    /// `framebuffer_height` pixels high.
    pub fn from_gl_mask(mask: &[u8; 128], framebuffer_height: u32) -> Self {
        let mut rows = [0u32; 32];
        for (row, bytes) in rows.iter_mut().zip(mask.chunks_exact(4)) {
            for (i, &byte) in bytes.iter().enumerate() {
                // Column 8 i + b is bit 7 - b of byte i.
                *row |= u32::from(byte.reverse_bits()) << (8 * i);
            }
        }
        PolygonStipple {
            rows,
            framebuffer_height,
        }
    }
}

/// The fragment stage's specialization: the lighting's constants (`entries` over `data`), and
/// where `stipple` is set, the stipple's after them.
pub(crate) fn fragment_specialization(
    entries: &[vk::SpecializationMapEntry],
    data: &[u8],
    stipple: Option<PolygonStipple>,
) -> (Vec<vk::SpecializationMapEntry>, Vec<u8>) {
    let (mut entries, mut data) = (entries.to_vec(), data.to_vec());
    if let Some(s) = stipple {
        let values = std::iter::once((s.framebuffer_height % 32) as i32 as u32).chain(s.rows);
        for (i, value) in values.enumerate() {
            entries.push(vk::SpecializationMapEntry {
                constant_id: FIRST_STIPPLE_CONSTANT + i as u32,
                offset: data.len() as u32,
                size: 4,
            });
            data.extend_from_slice(&value.to_ne_bytes());
        }
    }
    (entries, data)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_gl_mask_byte_is_read_most_significant_bit_first() {
        let mut mask = [0u8; 128];
        mask[0] = 0b1000_0000; // row 0, column 0
        mask[5] = 0b0000_0001; // row 1, column 15
        mask[127] = 0b0000_0001; // row 31, column 31
        let s = PolygonStipple::from_gl_mask(&mask, 64);
        assert_eq!((s.rows[0], s.rows[1], s.rows[31]), (1, 1 << 15, 1 << 31));
        assert!(s.rows[2..31].iter().all(|&r| r == 0));
    }
}
