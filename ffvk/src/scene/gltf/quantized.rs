//! `KHR_mesh_quantization`: vertex attributes stored as 8- or 16-bit integers, normalized or
//! not, read as the floats they stand for. The node transforms that undo the quantization
//! (a position stored as UNSIGNED_SHORT with a scale and offset in its node) are ordinary
//! node transforms and need nothing here.
//!
//! A normalized integer c of b bits maps as glTF 2.0's table of normalized integers says (the
//! extension points to it): signed, max(c / (2^(b−1) − 1), −1); unsigned, c / (2^b − 1). An
//! integer that is not normalized is its value.

use gltf::accessor::{DataType, Item, Iter};

use super::accessors::read_checked;
use super::{Context, LoadError};

/// The extension's name, as `extensionsUsed` lists it.
pub(super) const NAME: &str = "KHR_mesh_quantization";

/// Whether the file declares the extension in `extensionsUsed` (files that quantize must also
/// require it; ffvk reads them either way once they say they use it).
pub(super) fn declared(cx: &Context) -> bool {
    cx.raw
        .get("extensionsUsed")
        .and_then(|v| v.as_array())
        .is_some_and(|used| used.iter().any(|e| e.as_str() == Some(NAME)))
}

/// An attribute component type and how it becomes a float.
trait Component: Item + Copy {
    fn to_float(self, normalized: bool) -> f32;
}

impl Component for f32 {
    fn to_float(self, _: bool) -> f32 {
        self
    }
}

/// An integer type whose normalized values divide by `$max` (and, signed, stop at −1).
macro_rules! integer_component {
    ($($t:ty => $max:expr),*) => {$(
        impl Component for $t {
            fn to_float(self, normalized: bool) -> f32 {
                if normalized {
                    (self as f32 / $max).max(-1.0)
                } else {
                    self as f32
                }
            }
        }
    )*};
}

integer_component!(i8 => 127.0, u8 => 255.0, i16 => 32767.0, u16 => 65535.0);

/// The component types (and normalization) an attribute may have.
#[derive(Debug, Clone, Copy)]
pub(super) struct Accepted {
    /// FLOAT.
    pub float: bool,
    /// (BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT) when normalized.
    pub normalized: [bool; 4],
    /// The same when not normalized.
    pub plain: [bool; 4],
}

impl Accepted {
    /// Whether an accessor of `data_type`, normalized or not, is one of these.
    pub(super) fn allows(&self, data_type: DataType, normalized: bool) -> bool {
        let slot = match data_type {
            DataType::F32 => return self.float,
            DataType::I8 => 0,
            DataType::U8 => 1,
            DataType::I16 => 2,
            DataType::U16 => 3,
            DataType::U32 => return false,
        };
        if normalized {
            self.normalized[slot]
        } else {
            self.plain[slot]
        }
    }
}

/// POSITION: FLOAT; with the extension any 8- or 16-bit integer, normalized or not.
pub(super) const POSITION: Accepted = Accepted {
    float: true,
    normalized: [true; 4],
    plain: [true; 4],
};
/// NORMAL: FLOAT; with the extension normalized BYTE or SHORT.
pub(super) const NORMAL: Accepted = Accepted {
    float: true,
    normalized: [true, false, true, false],
    plain: [false; 4],
};
/// TEXCOORD_n: FLOAT, normalized UNSIGNED_BYTE or UNSIGNED_SHORT (glTF's core); with the
/// extension any 8- or 16-bit integer, normalized or not.
pub(super) const TEXCOORD: Accepted = Accepted {
    float: true,
    normalized: [true; 4],
    plain: [true; 4],
};
/// FLOAT alone.
pub(super) const FLOAT: Accepted = Accepted {
    float: true,
    normalized: [false; 4],
    plain: [false; 4],
};

/// Reads `accessor`'s `N`-vectors as floats, whatever its (already accepted) component type.
pub(super) fn read_vectors<const N: usize>(
    cx: &Context,
    primitive: &str,
    accessor: &gltf::Accessor,
    buffers: &[gltf::buffer::Data],
) -> Result<Vec<[f32; N]>, LoadError>
where
    [f32; N]: Item,
    [i8; N]: Item,
    [u8; N]: Item,
    [i16; N]: Item,
    [u16; N]: Item,
{
    match accessor.data_type() {
        DataType::I8 => read_as::<i8, N>(cx, primitive, accessor, buffers),
        DataType::U8 => read_as::<u8, N>(cx, primitive, accessor, buffers),
        DataType::I16 => read_as::<i16, N>(cx, primitive, accessor, buffers),
        DataType::U16 => read_as::<u16, N>(cx, primitive, accessor, buffers),
        _ => read_as::<f32, N>(cx, primitive, accessor, buffers),
    }
}

fn read_as<T: Component, const N: usize>(
    cx: &Context,
    primitive: &str,
    accessor: &gltf::Accessor,
    buffers: &[gltf::buffer::Data],
) -> Result<Vec<[f32; N]>, LoadError>
where
    [T; N]: Item,
{
    let normalized = accessor.normalized();
    let data = |b: gltf::Buffer| buffers.get(b.index()).map(|d| &d.0[..]);
    read_checked(cx, primitive, accessor, buffers, || {
        Iter::<[T; N]>::new(accessor.clone(), data)
            .map(|values| values.map(move |v: [T; N]| v.map(|c| c.to_float(normalized))))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalized_integers_map_as_gltf_says_and_plain_ones_keep_their_value() {
        assert_eq!(127i8.to_float(true), 1.0);
        assert_eq!((-127i8).to_float(true), -1.0);
        assert_eq!((-128i8).to_float(true), -1.0);
        assert_eq!(255u8.to_float(true), 1.0);
        assert_eq!(32767i16.to_float(true), 1.0);
        assert_eq!((-32768i16).to_float(true), -1.0);
        assert_eq!(65535u16.to_float(true), 1.0);
        assert_eq!(0u16.to_float(true), 0.0);
        assert_eq!(1000u16.to_float(false), 1000.0);
        assert_eq!((-5i8).to_float(false), -5.0);
        assert!(NORMAL.allows(DataType::I16, true) && !NORMAL.allows(DataType::I16, false));
        assert!(!NORMAL.allows(DataType::U8, true) && !FLOAT.allows(DataType::U16, true));
        assert!(TEXCOORD.allows(DataType::I8, false) && TEXCOORD.allows(DataType::U16, true));
        assert!(POSITION.allows(DataType::U16, false) && !POSITION.allows(DataType::U32, false));
    }
}
